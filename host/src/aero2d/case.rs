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

use super::camber::CamberHistory;
use super::friction::friction_history;
use super::history::{cycle_mean_of, cycle_means, cycle_means_until, History};
use super::ldvm::{FreeVortex, Ldvm, Settings};
use super::motion::Motion;
use super::panel::{PanelSettings, PanelSolver, SectionShape, ShapeHistory};
use super::theory::garrick_plunge;
use super::viscous::{
    load_interval, FlowField, FrameSink, NoFrames, SectionPath, SurfaceLoads, ViscousSection,
    STILL_KICK_RATE,
};
use super::window::WindowStatistics;
use crate::periodicity::change_of_swing;

mod error;
mod section_model;
pub use error::CaseError;
pub use section_model::{check_contour_history, SectionModel};

/// Fewest chord stations a thin section's deformation is resampled onto.
const MIN_CAMBER_STATIONS: usize = 21;

/// Points on each side of a NACA section given to the viscous model (cosine
/// spacing; its contour is resampled from them).
const NACA_SIDE_POINTS: usize = 200;

/// Fewest time steps a cycle: the default step is shortened to this at
/// high reduced frequencies.
const MIN_STEPS_PER_CYCLE: f64 = 100.0;

/// Most time steps a case may take. The cost of a step grows with the
/// wake, so a run's time grows faster than its steps: 1,047 steps (the
/// default 5 cycles at k = 1) took 0.7 s and 10,472 (k = 0.1) 32 s in
/// the dev profile on two busy cores; k = 0.001 (a period of 3,142
/// chords) would take a million steps and hours.
pub const MAX_STEPS: usize = 20_000;

/// The highest reduced frequency `k = omega c / (2 U)` the 2D models take.
/// They scale the flow by the flight speed `U`; past this the section
/// flaps nearly in hover, where that scale fails: a thin-line plunge of
/// 0.01 c already takes 83 % more power than Garrick's theory at k = 20
/// (+13 % at k = 2, where the thrust is within 5 %), and at 0.1 m/s the
/// default section (k = 20.7) gave CP -1.56e7 on its analysed deformation.
pub const MAX_REDUCED_FREQUENCY: f64 = 20.0;

/// The longest run without a period ([`Case::duration`]), chords
/// travelled: a cylinder's wake settles to its periodic shedding within
/// about 100 diameters at Re 100 (`fwav_ns2d::cases::CylinderWake` runs
/// 150).
pub const MAX_DURATION_CHORDS: f64 = 1000.0;

/// The shortest run without a period, in load sample intervals: two,
/// so that its second half, which is reported (from half the last
/// sample's time), holds two samples.
const SHORTEST_DURATION_SAMPLES: f64 = 2.0;

/// Thickest NACA section the panel method takes, chords. Measured on
/// NACA 00TT plunging at h = 0.05, k = 1 (5 cycles, 160 panels): up to
/// 0052 the mean CT falls smoothly with thickness (0.0092 at 0012, 0.0047
/// at 0050, 0.0043 at 0052) and the pressure lift agrees with the
/// vortex-impulse lift to 0.005; at 0055 they differ by 7 (CT swings to
/// -2.3 within the cycle) and from 0058 on the solution blows up (CL
/// 1e6 to 1e9, the wake scattered hundreds of chords).
pub const MAX_NACA_THICKNESS: f64 = 0.5;

/// Fewest points a section file must give the panel method. NACA 0012
/// plunging at h = 0.05, k = 1: mean CT -0.027 with 4 panels (the wrong
/// sign), 39% below the 160-panel value with 10, 9% with 20, 4% with 40;
/// three points (a triangle) blew up (CL -9e6).
pub const MIN_SECTION_POINTS: usize = 20;

/// How far a free vortex may be from the region the section sweeps, in
/// chords per chord of (1 + plunge amplitude), before the solution is
/// taken as blown up. In the converged cases of the validation and of
/// `fwav aero2d`'s range the wake stays within 11 chords of the path (h
/// = 2, k = 2 with leading-edge shedding: 26 chords upstream, within 60);
/// in the blown-up ones it scattered 150 to 2,200 chords.
pub const WAKE_REACH_CHORDS: f64 = 20.0;

/// Largest change of the mean CT between the last two cycles, relative
/// to the larger of the mean and the CT's swing over the last cycle, for
/// which a result is reported as periodic (the cases above change by at
/// most 5%): [`crate::periodicity`].
pub use crate::periodicity::PERIODIC_CHANGE;

/// Input power coefficient below which a section is taken as doing no
/// work (its efficiency is undefined): a section that does not move has
/// exactly zero; a plunge of 1e-4 chords at k = 1 still has about 1e-8.
const NO_INPUT_POWER: f64 = 1e-12;

/// One 2D analysis.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// The section (and so the solver).
    pub section: SectionModel,
    /// The rigid motion.
    pub motion: Motion,
    /// Periods to simulate.
    pub cycles: u32,
    /// Chords travelled to run instead of `cycles` periods: a run without
    /// a period (a body at rest in a stream, a sudden start), for the
    /// Navier–Stokes model only ([`CaseError::DurationNeedsNs`]), read by
    /// [`CaseRun::second_half`]. `None`: `cycles` periods.
    pub duration: Option<f64>,
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
    /// Mean skin-friction drag coefficient.
    pub cd_friction: f64,
    /// Mean lift coefficient.
    pub cl: f64,
    /// Change of the mean CT from the period before, relative to the last
    /// period's (how periodic the answer is).
    pub periodicity: f64,
    /// The same change relative to the larger of the mean CT's size and
    /// the CT's swing over the last period (a near-zero mean CT does not
    /// magnify it); above [`PERIODIC_CHANGE`] the result is not periodic.
    pub change_of_swing: f64,
}

impl CaseMeans {
    /// Propulsive efficiency `CT / CP`; `None` (undefined) when the
    /// section does no work (no input power).
    pub fn efficiency(&self) -> Option<f64> {
        (self.cp.abs() > NO_INPUT_POWER).then(|| self.ct / self.cp)
    }

    /// Thrust net of the skin-friction estimate.
    pub fn net_ct(&self) -> f64 {
        self.ct - self.cd_friction
    }

    /// Net thrust over input power; `None` without input power.
    pub fn net_efficiency(&self) -> Option<f64> {
        (self.cp.abs() > NO_INPUT_POWER).then(|| self.net_ct() / self.cp)
    }

    /// Whether the last two periods agree ([`PERIODIC_CHANGE`]).
    pub fn is_periodic(&self) -> bool {
        self.change_of_swing <= PERIODIC_CHANGE
    }
}

/// What a run of a [`Case`] leaves.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseRun {
    /// The load histories.
    pub history: History,
    /// The period, chords travelled.
    pub period: f64,
    /// The interval of the history's samples, chords travelled: the time
    /// step of the inviscid models; the viscous model samples its loads
    /// at this interval between its own (smaller, varying) steps.
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
    /// The wall's pressure and skin friction at the end (the viscous
    /// model's; `None` for the inviscid ones).
    pub surface: Option<SurfaceLoads>,
    /// The flow at the end on every node of the grid (the viscous
    /// model's; `None` for the inviscid ones).
    pub field: Option<FlowField>,
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
            duration: self.duration.unwrap_or(f64::from(self.cycles) * period),
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

    /// Whether the case is a rigid section at rest in the stream run for a
    /// [`Self::duration`] (no plunge or pitch amplitude): a body in a
    /// steady stream, started impulsively, without a period (its loads are
    /// then sampled over the duration, not a period of the motion).
    pub fn is_still(&self) -> bool {
        let m = &self.motion;
        self.duration.is_some()
            && m.plunge_amplitude == 0.0
            && m.pitch_amplitude == 0.0
            && self.deformation.is_none()
    }

    /// The time steps the case takes.
    pub fn steps(&self) -> usize {
        let s = self.settings();
        // Saturates: an endless case (k = 0) counts usize::MAX steps.
        (s.duration / s.dt).round() as usize
    }

    /// Runs the case with the solver its section chooses, after checking
    /// its work is bounded ([`MAX_STEPS`]); a run whose loads are not
    /// finite or whose wake left the domain of validity
    /// ([`WAKE_REACH_CHORDS`]) is an error, never a result.
    pub fn run(&self) -> Result<CaseRun, CaseError> {
        self.run_into(&mut NoFrames)
    }

    /// [`Self::run`], handing `frames` the viscous model's flows as the
    /// run reaches them ([`ViscousSection::field_frames`]; the inviscid
    /// models hand on none).
    ///
    /// # Errors
    /// As [`Self::run`], and [`CaseError::Viscous`] with
    /// [`crate::aero2d::viscous::ViscousError::Frame`] when `frames` fails
    /// (the run stops at that frame).
    pub fn run_into(&self, frames: &mut dyn FrameSink) -> Result<CaseRun, CaseError> {
        self.check_work()?;
        let run = match &self.section {
            SectionModel::Flat => self.run_thin(),
            SectionModel::Thick(shape) => self.run_thick(shape),
            SectionModel::Viscous(section) => self.run_viscous(section, frames),
        }?;
        self.check_result(&run)?;
        Ok(run)
    }

    /// Refuses a case of more than [`MAX_STEPS`] steps (a reduced
    /// frequency so small that a period is thousands of chords), with the
    /// smallest reduced frequency that fits; for the Navier–Stokes model,
    /// which chooses its own steps and bounds them
    /// (`ViscousError::TooManySteps`), a run longer than
    /// [`MAX_DURATION_CHORDS`], as for a `duration`. And a deformation
    /// history without a sample ([`CaseError::NoDeformationSamples`]):
    /// all this before anything is run or written.
    pub fn check_work(&self) -> Result<(), CaseError> {
        if self.deformation.as_ref().is_some_and(Vec::is_empty) {
            return Err(CaseError::NoDeformationSamples);
        }
        if let Some(duration) = self.duration {
            // The viscous model bounds its own steps
            // (`ViscousError::TooManySteps`).
            if !matches!(self.section, SectionModel::Viscous(_)) {
                return Err(CaseError::DurationNeedsNs);
            }
            if !(duration > 0.0 && duration <= MAX_DURATION_CHORDS) {
                return Err(CaseError::Duration {
                    duration,
                    max: MAX_DURATION_CHORDS,
                });
            }
            // Its report is of the second half: two samples at least.
            let k = if self.is_still() {
                0.0
            } else {
                self.motion.reduced_frequency
            };
            let interval = load_interval(k, duration);
            // The samples' times are sums of the interval: rounding's room.
            if duration < SHORTEST_DURATION_SAMPLES * interval * (1.0 - 1e-9) {
                return Err(CaseError::DurationTooShort {
                    duration,
                    interval,
                    min: SHORTEST_DURATION_SAMPLES * interval,
                });
            }
            return Ok(());
        }
        if matches!(self.section, SectionModel::Viscous(_)) {
            let chords = f64::from(self.cycles) * self.period();
            if chords <= MAX_DURATION_CHORDS {
                return Ok(());
            }
            return Err(CaseError::TooLong {
                reduced_frequency: self.motion.reduced_frequency,
                period: self.period(),
                cycles: self.cycles,
                chords,
                max: MAX_DURATION_CHORDS,
                min_reduced_frequency: f64::from(self.cycles) * PI / MAX_DURATION_CHORDS,
            });
        }
        let steps = self.steps();
        if steps <= MAX_STEPS {
            return Ok(());
        }
        let default_dt = Settings::default().dt;
        let settings = self.settings();
        Err(CaseError::TooManySteps {
            reduced_frequency: self.motion.reduced_frequency,
            period: self.period(),
            cycles: self.cycles,
            dt: settings.dt,
            steps: (settings.duration / settings.dt).round(),
            max: MAX_STEPS,
            min_reduced_frequency: f64::from(self.cycles) * PI / (MAX_STEPS as f64 * default_dt),
        })
    }

    /// Refuses a run whose loads are not finite, or one with a free vortex
    /// farther than the reach from the region the section sweeps (the
    /// wake travels from the section, `x` in [0, 1], to one chord past the
    /// distance flown; plunge within `+-h0`).
    fn check_result(&self, run: &CaseRun) -> Result<(), CaseError> {
        let h = &run.history;
        for (quantity, values) in [("CL", &h.cl), ("CT", &h.ct), ("CP", &h.cp)] {
            if let Some(i) = values.iter().position(|v| !v.is_finite()) {
                let time = h.time.get(i).copied().unwrap_or(f64::NAN);
                return Err(CaseError::NonFinite { quantity, time });
            }
        }
        let m = run.means();
        for (quantity, value) in [
            ("the mean CL", m.cl),
            ("the mean CT", m.ct),
            ("the mean CP", m.cp),
        ] {
            if !value.is_finite() {
                let time = h.time.last().copied().unwrap_or(0.0);
                return Err(CaseError::NonFinite { quantity, time });
            }
        }
        let h0 = self.motion.plunge_amplitude.abs();
        let reach = WAKE_REACH_CHORDS * (1.0 + h0);
        let downstream = self.settings().duration + 1.0;
        let distance = |v: &FreeVortex| {
            let dx = (-v.x).max(v.x - downstream).max(0.0);
            let dy = (v.y.abs() - h0).max(0.0);
            // A vortex at NaN is infinitely far.
            let d = dx.hypot(dy);
            if d.is_nan() {
                f64::INFINITY
            } else {
                d
            }
        };
        let farthest = run
            .vortices
            .iter()
            .map(|v| (distance(v), v))
            .max_by(|a, b| a.0.total_cmp(&b.0));
        match farthest {
            Some((d, v)) if d > reach => Err(CaseError::WakeLeftDomain {
                x: v.x,
                y: v.y,
                distance: d,
                reach,
            }),
            _ => Ok(()),
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
            surface: None,
            field: None,
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
            surface: None,
            field: None,
        })
    }

    fn run_viscous(
        &self,
        section: &ViscousSection,
        frames: &mut dyn FrameSink,
    ) -> Result<CaseRun, CaseError> {
        if self.lesp_critical.is_some() {
            return Err(CaseError::LespOnThick);
        }
        let duration = self.settings().duration;
        let path = if self.is_still() {
            // Only a mirror symmetric flow needs the start-up turn.
            let symmetric = self.motion.mean_pitch == 0.0 && section.shape.is_mirror_symmetric();
            SectionPath::Still {
                pivot: self.motion.pivot,
                pitch: self.motion.mean_pitch,
                kick_rate: if symmetric { STILL_KICK_RATE } else { 0.0 },
            }
        } else {
            SectionPath::Harmonic(self.motion)
        };
        let run = match &self.deformation {
            Some(samples) => {
                section.run_deforming_into(path, self.reynolds, duration, samples, frames)?
            }
            None => section.run_into(path, self.reynolds, duration, frames)?,
        };
        Ok(CaseRun {
            history: run.history,
            period: self.period(),
            dt: run.sample,
            wake_vortices: 0,
            leading_edge_vortices: 0,
            vortices: run.vorticity,
            body: run.body,
            surface: Some(run.surface),
            field: Some(run.field),
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
    /// The loads over the second half of a run without a period (a
    /// [`Case::duration`]); `None` when it holds fewer than two samples.
    pub fn second_half(&self) -> Option<WindowStatistics> {
        let end = *self.history.time.last()?;
        WindowStatistics::of(&self.history, 0.5 * end)
    }

    /// The last period's means, and the change of the mean CT from the
    /// period before (the window ending one period's worth of steps before
    /// the last sample).
    pub fn means(&self) -> CaseMeans {
        let (history, period) = (&self.history, self.period);
        let (ct, cp, _) = cycle_means(history, period, 1);
        let steps_per_period = (period / self.dt).round() as usize;
        let end_previous = history
            .time
            .len()
            .checked_sub(steps_per_period + 1)
            .map_or(0.0, |i| history.time[i]);
        let (ct_prev, _, _) = cycle_means_until(history, period, 1, end_previous);
        let last = &history.ct[history.ct.len().saturating_sub(steps_per_period)..];
        CaseMeans {
            ct,
            cp,
            cd_friction: cycle_mean_of(history, &history.cd_friction, period, 1),
            cl: cycle_mean_of(history, &history.cl, period, 1),
            periodicity: (ct - ct_prev) / ct.abs().max(1e-12),
            change_of_swing: change_of_swing(ct, ct_prev, last),
        }
    }

    /// The largest leading-edge suction parameter `|A0|` over the last
    /// period: the thin-line model's (`None` for the others, which keep
    /// none). Above the section's critical value the leading edge would
    /// shed a vortex (Ramesh et al. 2014); a run without
    /// [`Case::lesp_critical`] keeps the flow attached there regardless.
    pub fn peak_lesp(&self) -> Option<f64> {
        let lesp = &self.history.lesp;
        let steps_per_period = (self.period / self.dt).round() as usize;
        lesp[lesp.len().saturating_sub(steps_per_period)..]
            .iter()
            .map(|a| a.abs())
            .reduce(f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aero2d::naca::{Naca4, TrailingEdge};
    use crate::aero2d::panel::DEFAULT_PANELS;
    use crate::aero2d::viscous::ViscousShape;

    /// A deformation history without a sample is refused by every model
    /// alike, before a step (the LDVM's message spoke of a period, the
    /// Navier–Stokes model's of "a positive, finite number").
    #[test]
    fn a_deformation_without_samples_is_refused_by_every_model() {
        for section in [
            SectionModel::Flat,
            SectionModel::named("naca0012").unwrap(),
            SectionModel::Viscous(ViscousSection::new(ViscousShape::Plate(0.04))),
        ] {
            let case = Case {
                deformation: Some(Vec::new()),
                ..plunge(section, 0.05, 1.0)
            };
            let err = case.run().unwrap_err();
            assert!(matches!(err, CaseError::NoDeformationSamples), "{err:?}");
        }
    }

    /// A run without a period too short for its report (two load samples
    /// over its second half) is refused before it runs, with the shortest
    /// that reports: until 2026-12-07 `fwav aero2d --model ns --duration
    /// 0.02` ran, then said only "give a longer --duration". A body at
    /// rest samples by its duration, so any duration reports.
    #[test]
    fn a_duration_too_short_to_report_is_refused_before_the_run() {
        let viscous = || SectionModel::Viscous(ViscousSection::new(ViscousShape::Plate(0.04)));
        let with = |h0: f64, duration: f64| Case {
            duration: Some(duration),
            ..plunge(viscous(), h0, 1.0)
        };
        let interval = std::f64::consts::PI / 200.0; // a 200th of the period pi / k
        match with(0.05, 0.02).check_work() {
            Err(e @ CaseError::DurationTooShort { .. }) => {
                let CaseError::DurationTooShort {
                    interval: i, min, ..
                } = e
                else {
                    unreachable!()
                };
                assert!((i - interval).abs() < 1e-15);
                assert!((min - 2.0 * interval).abs() < 1e-15);
                // The shortest that reports, rounded up: 0.031416 shown
                // as 0.0315, not as a 0.031 that is refused again.
                assert!(e.to_string().contains("give at least 0.0315"), "{e}");
            }
            other => panic!("{other:?}"),
        }
        assert!(with(0.05, 2.0 * interval).check_work().is_ok());
        assert!(with(0.05, 0.0315).check_work().is_ok());
        assert!(with(0.0, 1e-3).check_work().is_ok());
    }

    fn plunge(section: SectionModel, h0: f64, k: f64) -> Case {
        Case {
            section,
            motion: Motion {
                reduced_frequency: k,
                plunge_amplitude: h0,
                mean_pitch: 0.0,
                pitch_amplitude: 0.0,
                pitch_phase: 0.0,
                pivot: 0.25,
            },
            cycles: 5,
            duration: None,
            lesp_critical: None,
            reynolds: 15_000.0,
            deformation: None,
        }
    }

    /// Sections the panel method cannot take are refused before any
    /// step, saying why; the thickest allowed NACA section is taken.
    #[test]
    fn impossible_sections_are_refused_up_front() {
        assert!(matches!(
            SectionModel::named("naca9999"),
            Err(CaseError::TooThick { thickness_percent, .. }) if thickness_percent == 99.0
        ));
        assert!(matches!(
            SectionModel::named("naca0051"),
            Err(CaseError::TooThick { .. })
        ));
        assert!(SectionModel::named("naca0050").is_ok());
        let path = std::env::temp_dir().join(format!("fwav-case-{}.dat", std::process::id()));
        let contour = |n: usize| -> String {
            (0..n)
                .map(|i| {
                    let t = 2.0 * PI * i as f64 / n as f64;
                    format!("{} {}\n", 0.5 + 0.5 * t.cos(), 0.06 * t.sin())
                })
                .collect()
        };
        std::fs::write(&path, contour(MIN_SECTION_POINTS - 1)).unwrap();
        let e = SectionModel::named(path.to_str().unwrap()).unwrap_err();
        assert!(
            matches!(
                e,
                CaseError::TooFewPoints {
                    got: 19,
                    min: 20,
                    ..
                }
            ),
            "{e}"
        );
        std::fs::write(&path, contour(MIN_SECTION_POINTS)).unwrap();
        assert!(SectionModel::named(path.to_str().unwrap()).is_ok());
        std::fs::remove_file(&path).ok();
    }

    /// A reduced frequency so low that a period is thousands of chords is
    /// refused with the smallest one that fits, before any step.
    #[test]
    fn endless_cases_are_refused_with_the_reduced_frequency_that_fits() {
        let e = plunge(SectionModel::Flat, 0.05, 1e-3).run().unwrap_err();
        let text = e.to_string();
        let CaseError::TooManySteps {
            steps,
            min_reduced_frequency,
            ..
        } = e
        else {
            panic!("{e}")
        };
        assert!(steps > 1e6, "{steps}");
        // The count as a person reads it, in powers of ten past a million.
        assert!(text.contains("take 1.047198e6 time steps"), "{text}");
        let fits = plunge(SectionModel::Flat, 0.05, min_reduced_frequency * 1.001);
        assert!(fits.steps() <= MAX_STEPS && fits.check_work().is_ok());
        let zero = plunge(SectionModel::Flat, 0.05, 0.0);
        assert!(matches!(
            zero.check_work(),
            Err(CaseError::TooManySteps { .. })
        ));
    }

    /// The Navier–Stokes model, which takes its own steps, is bounded by
    /// the chords its cycles travel, as a run of a given duration is: 10
    /// cycles at k = 0.05 (628 chords; the LDVM's 41,888 steps are
    /// refused) run, 10 at k = 0.03 (1,047 chords) are refused with the
    /// smallest reduced frequency that fits, before any step.
    #[test]
    fn navier_stokes_cycles_are_bounded_by_the_chords_they_travel() {
        let ns = |k: f64| Case {
            cycles: 10,
            ..plunge(SectionModel::Viscous(ViscousSection::plate(0.04)), 0.05, k)
        };
        assert!(ns(0.05).check_work().is_ok());
        assert!(matches!(
            Case {
                section: SectionModel::Flat,
                ..ns(0.05)
            }
            .check_work(),
            Err(CaseError::TooManySteps { .. })
        ));
        let e = ns(0.03).check_work().unwrap_err();
        let CaseError::TooLong {
            chords,
            min_reduced_frequency,
            ..
        } = e
        else {
            panic!("{e}")
        };
        assert!((chords - 10.0 * PI / 0.03).abs() < 1e-9, "{chords}");
        assert!(ns(min_reduced_frequency * 1.001).check_work().is_ok());
        assert!(e.to_string().contains("fewer cycles"), "{e}");
    }

    /// A thick section beyond the panel method's reach (NACA 0060, built
    /// without the name's check) blows up; the run is an error naming the
    /// wake's escape, not a result.
    #[test]
    fn a_blown_up_solution_is_an_error() {
        let shape = SectionShape::new(
            &"0060"
                .parse::<Naca4>()
                .unwrap()
                .points(DEFAULT_PANELS, TrailingEdge::Closed)
                .unwrap(),
        )
        .unwrap();
        let e = plunge(SectionModel::Thick(shape), 0.05, 1.0)
            .run()
            .unwrap_err();
        assert!(
            matches!(e, CaseError::WakeLeftDomain { distance, reach, .. } if distance > reach),
            "{e}"
        );
        assert!(e.to_string().contains("blew up"), "{e}");
    }

    /// Non-finite loads are an error naming the load and the time.
    #[test]
    fn non_finite_loads_are_an_error() {
        let case = plunge(SectionModel::Flat, 0.05, 1.0);
        let mut run = case.run().unwrap();
        run.history.cl[7] = f64::NAN;
        let e = case.check_result(&run).unwrap_err();
        assert!(
            matches!(e, CaseError::NonFinite { quantity: "CL", time } if time == run.history.time[7]),
            "{e}"
        );
    }

    /// A section that does not move has no input power: its efficiency
    /// is undefined, not NaN; a plunging one has one, and is periodic.
    #[test]
    fn efficiency_without_input_power_is_undefined() {
        let still = plunge(SectionModel::Flat, 0.0, 1.0).run().unwrap().means();
        assert_eq!((still.efficiency(), still.net_efficiency()), (None, None));
        let moving = plunge(SectionModel::Flat, 0.05, 1.0).run().unwrap().means();
        assert!(moving.efficiency().is_some_and(|e| e > 0.0 && e < 1.0));
        assert!(moving.is_periodic(), "{moving:?}");
    }
}
