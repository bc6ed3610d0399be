//! One 2D analysis as `fwav aero2d` runs it: a [`Case`] (the section, its
//! motion and deformation, how many cycles) chooses the solver — the
//! thin-line LDVM ([`super::ldvm`]) for a flat section, the panel method
//! ([`super::panel`]) for a thick one — and runs it to a [`CaseRun`], whose
//! [`CaseRun::means`] are the last cycle's means and how periodic they are.
//!
//! May import the other modules of [`crate::aero2d`] only; a deformation
//! comes in as points (the `section.json` type that carries them lives
//! with the system analysis that writes it).

use std::f64::consts::PI;
use std::path::Path;

use super::camber::{CamberError, CamberHistory};
use super::friction::friction_history;
use super::history::{cycle_mean_of, cycle_means, cycle_means_until, History};
use super::ldvm::{FreeVortex, Ldvm, Settings};
use super::motion::Motion;
use super::naca::{read_points, Naca4, NacaError, PointsError, TrailingEdge};
use super::panel::DEFAULT_PANELS;
use super::panel::{
    PanelError, PanelSettings, PanelSolver, SectionShape, ShapeError, ShapeHistory,
};
use super::theory::garrick_plunge;

/// Fewest chord stations a thin section's deformation is resampled onto.
const MIN_CAMBER_STATIONS: usize = 21;

/// Fewest time steps a cycle: the default step is shortened to this at
/// high reduced frequencies.
const MIN_STEPS_PER_CYCLE: f64 = 100.0;

/// The section and, with it, the solver.
#[derive(Clone, Debug, PartialEq)]
pub enum SectionModel {
    /// A thin line (flat plate, or the deforming mid-line): LDVM.
    Flat,
    /// A closed contour: the panel method.
    Thick(SectionShape),
}

/// Why a case cannot be set up or run.
#[derive(Debug, thiserror::Error)]
pub enum CaseError {
    /// A section name that is neither `flat`, a NACA 4-digit name nor an
    /// existing point file.
    #[error("{name:?}: neither `flat`, a NACA 4-digit name ({naca}), nor an existing point file")]
    SectionName {
        /// The name given.
        name: String,
        /// Why it is not a NACA name.
        naca: NacaError,
    },
    /// A NACA section whose points cannot be made.
    #[error(transparent)]
    Naca(#[from] NacaError),
    /// A point file that cannot be read.
    #[error(transparent)]
    Points(#[from] PointsError),
    /// A contour the panel method cannot take.
    #[error(transparent)]
    Shape(#[from] ShapeError),
    /// A thin section's deformation that is not a camber history.
    #[error(transparent)]
    Camber(#[from] CamberError),
    /// The panel solver refused the section, settings or deformation.
    #[error(transparent)]
    Panel(#[from] PanelError),
    /// Leading-edge vortex shedding asked of the panel method.
    #[error("leading-edge vortex shedding (a critical LESP) applies to the thin-line model only")]
    LespOnThick,
}

impl SectionModel {
    /// The section a name means: `flat`, a NACA 4-digit name (closed
    /// trailing edge, [`DEFAULT_PANELS`] panels), or a point file (Selig
    /// order or clockwise from the trailing edge, chords).
    pub fn named(name: &str) -> Result<Self, CaseError> {
        if name == "flat" {
            return Ok(Self::Flat);
        }
        let points = match name.parse::<Naca4>() {
            Ok(naca) => naca.points(DEFAULT_PANELS, TrailingEdge::Closed)?,
            Err(naca) => {
                let path = Path::new(name);
                if !path.exists() {
                    return Err(CaseError::SectionName {
                        name: name.to_string(),
                        naca,
                    });
                }
                read_points(path)?.points
            }
        };
        Ok(Self::Thick(SectionShape::new(&points)?))
    }

    /// Whether it is the thin line.
    pub fn is_flat(&self) -> bool {
        matches!(self, Self::Flat)
    }
}

/// One 2D analysis.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// The section (and so the solver).
    pub section: SectionModel,
    /// The rigid motion.
    pub motion: Motion,
    /// Periods to simulate.
    pub cycles: u32,
    /// Critical LESP for leading-edge vortex shedding (thin line only).
    pub lesp_critical: Option<f64>,
    /// Chord Reynolds number of the skin-friction estimate.
    pub reynolds: f64,
    /// The section's deformation over one period, samples equally spaced
    /// in time in the section's kinematic frame (chords, leading edge at
    /// (0, 0), trailing edge at (1, 0)): for the thin line the mid-line
    /// points from the leading to the trailing edge, for a thick section
    /// the whole contour in its order. `None`: rigid.
    pub deformation: Option<Vec<Vec<(f64, f64)>>>,
}

/// Means over the last period of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaseMeans {
    /// Mean thrust coefficient (inviscid).
    pub ct: f64,
    /// Mean input power coefficient.
    pub cp: f64,
    /// Propulsive efficiency `CT / CP`.
    pub efficiency: f64,
    /// Mean skin-friction drag coefficient.
    pub cd_friction: f64,
    /// Mean lift coefficient.
    pub cl: f64,
    /// Change of the mean CT from the period before, relative to the last
    /// period's (how periodic the answer is).
    pub periodicity: f64,
}

impl CaseMeans {
    /// Thrust net of the skin-friction estimate.
    pub fn net_ct(&self) -> f64 {
        self.ct - self.cd_friction
    }

    /// Net thrust over input power.
    pub fn net_efficiency(&self) -> f64 {
        self.net_ct() / self.cp
    }
}

/// What a run of a [`Case`] leaves.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseRun {
    /// The load histories.
    pub history: History,
    /// The period, chords travelled.
    pub period: f64,
    /// The time step, chords travelled.
    pub dt: f64,
    /// Trailing-edge (thin line) or wake (panel) vortices shed.
    pub wake_vortices: usize,
    /// Leading-edge vortices shed (thin line only).
    pub leading_edge_vortices: usize,
    /// Every free vortex at the end, for a picture.
    pub vortices: Vec<FreeVortex>,
    /// The section's points at the end (global frame, chords), for a
    /// picture.
    pub body: Vec<(f64, f64)>,
}

impl Case {
    /// The period of the motion, chords travelled (`pi / k`).
    pub fn period(&self) -> f64 {
        PI / self.motion.reduced_frequency
    }

    /// The solver settings: the default time step, shortened to give at
    /// least 100 steps a period, for `cycles` periods.
    pub fn settings(&self) -> Settings {
        let period = self.period();
        let defaults = Settings::default();
        Settings {
            dt: defaults.dt.min(period / MIN_STEPS_PER_CYCLE),
            duration: f64::from(self.cycles) * period,
            lesp_critical: self.lesp_critical,
            reynolds: Some(self.reynolds),
            ..defaults
        }
    }

    /// Garrick's (1936) mean CT, CP and efficiency, when the case is the
    /// one his theory describes: a rigid section in pure plunge without
    /// leading-edge vortices.
    pub fn garrick(&self) -> Option<(f64, f64, f64)> {
        let m = &self.motion;
        let rigid_plunge = m.pitch_amplitude == 0.0
            && m.mean_pitch == 0.0
            && self.deformation.is_none()
            && self.lesp_critical.is_none();
        rigid_plunge.then(|| garrick_plunge(m.reduced_frequency, m.plunge_amplitude))
    }

    /// Runs the case with the solver its section chooses.
    pub fn run(&self) -> Result<CaseRun, CaseError> {
        match &self.section {
            SectionModel::Flat => self.run_thin(),
            SectionModel::Thick(shape) => self.run_thick(shape),
        }
    }

    fn run_thin(&self) -> Result<CaseRun, CaseError> {
        let (period, settings) = (self.period(), self.settings());
        let mut solver = Ldvm::new(self.motion, settings);
        if let Some(samples) = &self.deformation {
            let stations = samples
                .iter()
                .map(Vec::len)
                .max()
                .unwrap_or(0)
                .max(MIN_CAMBER_STATIONS);
            solver = solver.with_camber(CamberHistory::from_section_points(
                samples, period, stations,
            )?);
        }
        let history = solver.run();
        Ok(CaseRun {
            history,
            period,
            dt: settings.dt,
            wake_vortices: solver.wake().len(),
            leading_edge_vortices: solver.leading_edge_vortices().len(),
            vortices: solver
                .wake()
                .iter()
                .chain(solver.leading_edge_vortices())
                .copied()
                .collect(),
            body: solver.section_points(),
        })
    }

    fn run_thick(&self, shape: &SectionShape) -> Result<CaseRun, CaseError> {
        if self.lesp_critical.is_some() {
            return Err(CaseError::LespOnThick);
        }
        let (period, settings) = (self.period(), self.settings());
        let panel_settings = PanelSettings {
            dt: settings.dt,
            duration: settings.duration,
            far_wake: settings.far_wake,
        };
        let mut solver = PanelSolver::new(shape, self.motion, panel_settings)?;
        if let Some(samples) = &self.deformation {
            solver = solver.with_shape_history(ShapeHistory::new(samples, period)?)?;
        }
        let mut history = solver.run();
        history.cd_friction = friction_history(&self.motion, &history.time, self.reynolds);
        Ok(CaseRun {
            history,
            period,
            dt: settings.dt,
            wake_vortices: solver.wake().len(),
            leading_edge_vortices: 0,
            vortices: solver.wake().to_vec(),
            body: self.body_at(settings.duration, solver.surface_pressure().0),
        })
    }

    /// Body-frame points of the section in the global frame at time `t`:
    /// pitched about the pivot and plunged.
    fn body_at(&self, t: f64, points: &[[f64; 2]]) -> Vec<(f64, f64)> {
        let (h, _, alpha, _) = self.motion.at(t);
        let (s, c) = alpha.sin_cos();
        let p = self.motion.pivot;
        points
            .iter()
            .map(|&[x, y]| (p + (x - p) * c + y * s, h - (x - p) * s + y * c))
            .collect()
    }
}

impl CaseRun {
    /// The last period's means, and the change of the mean CT from the
    /// period before (the window ending one period's worth of steps before
    /// the last sample).
    pub fn means(&self) -> CaseMeans {
        let (history, period) = (&self.history, self.period);
        let (ct, cp, efficiency) = cycle_means(history, period, 1);
        let steps_per_period = (period / self.dt).round() as usize;
        let end_previous = history
            .time
            .len()
            .checked_sub(steps_per_period + 1)
            .map_or(0.0, |i| history.time[i]);
        let (ct_prev, _, _) = cycle_means_until(history, period, 1, end_previous);
        CaseMeans {
            ct,
            cp,
            efficiency,
            cd_friction: cycle_mean_of(history, &history.cd_friction, period, 1),
            cl: cycle_mean_of(history, &history.cl, period, 1),
            periodicity: (ct - ct_prev) / ct.abs().max(1e-12),
        }
    }
}
