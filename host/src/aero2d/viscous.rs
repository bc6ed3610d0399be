//! The viscous section model: laminar Navier–Stokes ([`fwav_ns2d`]) of a
//! plunging and pitching section, behind the same [`super::case::Case`] as
//! the inviscid models, in the same units (chords, `U = 1`, time in chords
//! travelled) and with the same [`History`].
//!
//! The section is set in the solver's body frame with the pitch axis at
//! the origin, the chord along `+x` from the leading edge at `x = -pivot`;
//! the stream is along `+x`. Thrust is the force upstream (`-Fx`), lift
//! the force across (`Fy`), the input power the work rate of the wall on
//! the fluid, all on `1/2 rho U^2 c` (`U^3` for the power). The forces
//! include the wall's friction: the thrust is net of it, and the run's
//! friction history is zero (the inviscid models' estimate is not added).
//!
//! Sections: `flat` is a thin plate of a chosen thickness with elliptic
//! ends (the conformal map is exact); other contours wait for the
//! solver's numerical map (issue 23 goes on).
//!
//! The time step is the largest the explicit advection allows
//! ([`fwav_ns2d::Flow::stable_dt`]), checked as the flow develops and
//! halved when it falls below; a change of step costs one build of the
//! wall's influence matrix (`N_θ` implicit sweeps). The loads are sampled
//! at a fixed interval by linear interpolation between steps, so the
//! cycle means of [`super::history`] see uniform samples.

use fwav_ns2d::{Flow, GridSpec, NsError, PlungePitch, SectionMap};

use super::history::History;
use super::ldvm::FreeVortex;
use super::motion::Motion;

/// Largest Courant number of the explicit advection the step is chosen
/// for (AB2 with third-order upwind is stable to about 0.5).
const COURANT: f64 = 0.35;

/// Steps between checks of the stable time step.
const CHECK_EVERY: usize = 10;

/// Fewest load samples a period.
const SAMPLES_PER_PERIOD: f64 = 200.0;

/// Most grid cells drawn in the vorticity picture.
const PICTURE_CELLS: usize = 20_000;

/// Radius, chords about the pivot, of the vorticity picture.
const PICTURE_RADIUS: f64 = 6.0;

/// Steps a run may take before it is refused as beyond this machine.
pub const MAX_VISCOUS_STEPS: usize = 2_000_000;

/// The viscous model's section and resolution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViscousSection {
    /// Thickness of the plate modelling the thin section, chords.
    pub thickness: f64,
    /// Nodes round the section.
    pub around: usize,
    /// Nodes from the wall to the outer boundary.
    pub radial: usize,
    /// Outer boundary, chords from the pivot.
    pub outer_chords: f64,
    /// First cell at the wall at mid-chord, in boundary-layer thicknesses
    /// `c / sqrt(Re)`.
    pub first_cell_layers: f64,
}

impl ViscousSection {
    /// Default thickness of the thin plate, chords.
    pub const DEFAULT_THICKNESS: f64 = 0.04;

    /// The default resolution round a plate of `thickness` chords: 256
    /// nodes round, 160 out to 30 chords, first cell a tenth of the
    /// boundary layer's thickness.
    pub fn plate(thickness: f64) -> Self {
        Self {
            thickness,
            around: 256,
            radial: 160,
            outer_chords: 30.0,
            first_cell_layers: 0.1,
        }
    }

    /// The conformal map of the section, the pitch axis `pivot` (chords
    /// from the leading edge) at the origin.
    fn map(&self, pivot: f64) -> Result<SectionMap, NsError> {
        SectionMap::ellipse(0.5, 0.5 * self.thickness, (0.5 - pivot, 0.0))
    }

    /// The grid of this resolution for the map `map` at `reynolds`.
    fn grid(&self, map: &SectionMap, reynolds: f64) -> GridSpec {
        // Physical height of the first cell at mid-chord over its height
        // in ξ is |∂z/∂ξ| there, |a| + |b_1| = 0.5 for the plate.
        let first = self.first_cell_layers / reynolds.sqrt() / 0.5;
        GridSpec {
            around: self.around,
            radial: self.radial,
            outer_radius: self.outer_chords / map.scale(),
            first_cell: first.min(0.05),
        }
    }
}

/// Why a viscous run cannot be done.
#[derive(Debug, thiserror::Error)]
pub enum ViscousError {
    /// The solver refused the case or diverged.
    #[error(transparent)]
    Solver(#[from] NsError),
    /// A plate thickness out of range.
    #[error(
        "plate thickness {0} chords: the Navier–Stokes model takes 0.005 to 0.3 chords \
         (thinner plates crowd the grid at the edges beyond any usable time step)"
    )]
    Thickness(f64),
    /// A deforming section (not yet in the viscous model).
    #[error(
        "the Navier–Stokes model does not take a deformation history yet: run it rigid, or \
         use the inviscid model for the deforming section"
    )]
    Deforming,
    /// The stable time step keeps falling: the run would take too long.
    #[error(
        "the stable time step fell to {dt:.2e} chords travelled at t = {time:.3} \
         ({steps} steps for the run at that step, more than {max}): the motion is too fast for \
         this grid's cells at the section's edges; choose a thicker plate (--ns-thickness), \
         fewer nodes round the section, or a gentler motion"
    )]
    TooManySteps {
        /// The time step reached.
        dt: f64,
        /// When.
        time: f64,
        /// The steps the run would take at that step.
        steps: usize,
        /// The most allowed ([`MAX_VISCOUS_STEPS`]).
        max: usize,
    },
}

/// What a viscous run leaves.
#[derive(Clone, Debug, PartialEq)]
pub struct ViscousRun {
    /// Loads sampled every `sample` chords travelled; no friction
    /// estimate (the forces include the friction).
    pub history: History,
    /// The sampling interval, chords travelled.
    pub sample: f64,
    /// The smallest time step taken, chords travelled.
    pub dt: f64,
    /// Time steps taken.
    pub steps: usize,
    /// The grid's cells near the section as point vortices (their
    /// circulation), global frame, for a picture.
    pub vorticity: Vec<FreeVortex>,
    /// The section's outline at the end, global frame.
    pub body: Vec<(f64, f64)>,
}

/// The loads at one instant: `(CL, CT, CP)`.
fn coefficients<M: fwav_ns2d::Motion>(flow: &Flow<M>) -> [f64; 3] {
    let loads = flow.loads();
    [
        2.0 * loads.force.im,
        -2.0 * loads.force.re,
        2.0 * loads.power,
    ]
}

impl ViscousSection {
    /// Runs `motion` at `reynolds` for `duration` chords travelled,
    /// sampling the loads every `period / 200` (or `duration / 2000`
    /// without a period).
    ///
    /// Cost: about 30 ns per cell per step on one core; the steps are
    /// set by the edge cells of the plate (see [`ViscousError::TooManySteps`]).
    ///
    /// # Errors
    /// [`ViscousError`]: a bad thickness, the solver's, a time step that
    /// keeps falling.
    pub fn run(
        &self,
        motion: &Motion,
        reynolds: f64,
        duration: f64,
    ) -> Result<ViscousRun, ViscousError> {
        if !(0.005..=0.3).contains(&self.thickness) {
            return Err(ViscousError::Thickness(self.thickness));
        }
        let map = self.map(motion.pivot)?;
        let spec = self.grid(&map, reynolds);
        let frame = PlungePitch {
            speed: 1.0,
            omega: 2.0 * motion.reduced_frequency,
            plunge: motion.plunge_amplitude,
            mean_pitch: motion.mean_pitch,
            pitch: motion.pitch_amplitude,
            phase: motion.pitch_phase,
        };
        let mut flow = Flow::new(&map, spec, frame, 1.0 / reynolds)?;
        let sample = if motion.reduced_frequency > 0.0 {
            std::f64::consts::PI / motion.reduced_frequency / SAMPLES_PER_PERIOD
        } else {
            duration / 2000.0
        };
        let mut dt = (COURANT * flow.stable_dt(1.0) / peak_speed_ratio(motion)).min(sample);
        let mut history = History::default();
        let mut before = (0.0, coefficients(&flow));
        let mut steps = 0;
        let mut next = sample;
        while next <= duration + 1e-9 * sample {
            if steps % CHECK_EVERY == 0 && steps > 0 {
                let stable = COURANT * flow.stable_dt(1.0);
                if dt > stable {
                    dt = 0.5 * dt.min(2.0 * stable);
                    let left = ((duration - flow.time()) / dt).ceil() as usize;
                    if steps + left > MAX_VISCOUS_STEPS {
                        return Err(ViscousError::TooManySteps {
                            dt,
                            time: flow.time(),
                            steps: steps + left,
                            max: MAX_VISCOUS_STEPS,
                        });
                    }
                }
            }
            flow.step(dt)?;
            steps += 1;
            let now = (flow.time(), coefficients(&flow));
            while next <= now.0 + 1e-12 && next <= duration + 1e-9 * sample {
                let w = (next - before.0) / (now.0 - before.0);
                let at = |i: usize| before.1[i] + w * (now.1[i] - before.1[i]);
                history.time.push(next);
                history.cl.push(at(0));
                history.ct.push(at(1));
                history.cp.push(at(2));
                history.cd_friction.push(0.0);
                next += sample;
            }
            before = now;
        }
        let (vorticity, body) = picture(&flow, motion);
        Ok(ViscousRun {
            history,
            sample,
            dt,
            steps,
            vorticity,
            body,
        })
    }
}

/// The largest speed of the section's motion relative to the stream
/// over the one at the start (the first step is chosen at the start).
fn peak_speed_ratio(motion: &Motion) -> f64 {
    let w = 2.0 * motion.reduced_frequency;
    let plunge = motion.plunge_amplitude.abs() * w;
    // The edges' speed from the pitch rate, about the farther end.
    let pivot = motion.pivot.max(1.0 - motion.pivot);
    let pitch = motion.pitch_amplitude.abs() * w * pivot;
    let start = motion.at(0.0).1.abs() + 1.0;
    (1.0 + plunge + pitch) / start
}

/// The cells within [`PICTURE_RADIUS`] as point vortices and the wall,
/// in the global frame of [`super::case`] (pivot at `x = pivot`,
/// plunged by `h`).
fn picture<M: fwav_ns2d::Motion>(
    flow: &Flow<M>,
    motion: &Motion,
) -> (Vec<FreeVortex>, Vec<(f64, f64)>) {
    let g = flow.grid();
    let (h, _, alpha, _) = motion.at(flow.time());
    // The body axes are turned by -alpha (a nose-up pitch is clockwise).
    let (s, c) = alpha.sin_cos();
    let place = |x: f64, y: f64| (motion.pivot + x * c + y * s, h - x * s + y * c);
    let omega = flow.vorticity();
    let mut cells: Vec<FreeVortex> = (1..g.nr - 1)
        .flat_map(|j| (0..g.nt).map(move |k| (j, k)))
        .filter_map(|(j, k)| {
            let i = g.at(j, k);
            let z = g.z[i];
            (z.re.hypot(z.im) < PICTURE_RADIUS).then(|| {
                let (x, y) = place(z.re, z.im);
                let area = g.jac[i] * g.slope[j] * g.d_eta * g.d_theta;
                FreeVortex {
                    x,
                    y,
                    gamma: omega[i] * area,
                }
            })
        })
        .collect();
    if cells.len() > PICTURE_CELLS {
        cells.sort_by(|a, b| b.gamma.abs().total_cmp(&a.gamma.abs()));
        cells.truncate(PICTURE_CELLS);
    }
    let body = (0..g.nt)
        .map(|k| {
            let z = g.z[g.at(0, k)];
            place(z.re, z.im)
        })
        .collect();
    (cells, body)
}
