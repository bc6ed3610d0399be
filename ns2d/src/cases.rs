//! The published reference flows the solver is validated on, set up once
//! for the tests, the benchmarks and `fwav validate`.
//!
//! Each case fixes the body, the motion and the Reynolds number of its
//! reference; the resolution (grid and time step) is the caller's, with
//! the validated one as `validated()`. Lengths are in diameters (cylinder)
//! or chords (ellipse), speeds in the reference speed.

use crate::error::NsError;
use crate::flow::Flow;
use crate::grid::GridSpec;
use crate::history::{ForceHistory, WakeStatistics};
use crate::motion::{FrameState, Motion, SteadyStream};
use crate::section_map::SectionMap;
use realfft::num_complex::Complex64;

/// A resolution: grid and time step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolution {
    /// The grid.
    pub grid: GridSpec,
    /// The time step, in reference lengths over the reference speed.
    pub dt: f64,
}

/// A cylinder of diameter 1 at rest in a unit stream at Reynolds number
/// `reynolds` on `resolution`'s grid, turned at the start with peak rate
/// `kick_rate` over `kick_period` (0: not turned; [`SteadyStream`]).
fn cylinder_in_stream(
    reynolds: f64,
    resolution: Resolution,
    kick_rate: f64,
    kick_period: f64,
) -> Result<Flow<SteadyStream>, NsError> {
    let map = SectionMap::circle(0.5)?;
    let motion = SteadyStream {
        speed: 1.0,
        kick_rate,
        kick_period,
    };
    Flow::new(&map, resolution.grid, motion, 1.0 / reynolds)
}

/// The periodic wake of a circular cylinder (diameter 1) at rest in a unit
/// stream: mean drag, lift amplitude and Strouhal number of the shedding
/// (Liu, Zheng & Sung 1998; Park, Kwon & Choi 1998; Braza, Chassaing &
/// Ha Minh 1986). The symmetry is broken by one period of rotation at
/// the start.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderWake {
    /// `U D / ν`.
    pub reynolds: f64,
    /// Time simulated, `U t / D`.
    pub duration: f64,
    /// The statistics are taken over the last `averaged` of the run.
    pub averaged: f64,
}

impl CylinderWake {
    /// The grid and step validated for the wake at Re 100–200: 256 nodes
    /// round, 192 out to 50 diameters, first cell 0.005 D, dt = 0.005 D/U.
    #[must_use]
    pub fn validated() -> Resolution {
        Resolution {
            grid: GridSpec {
                around: 256,
                radial: 192,
                outer_radius: 100.0,
                first_cell: 0.01,
                far: None,
            },
            dt: 0.005,
        }
    }

    /// Run the case at `resolution`.
    ///
    /// # Errors
    /// The solver's.
    pub fn run(&self, resolution: Resolution) -> Result<WakeStatistics, NsError> {
        let mut flow = self.flow(resolution)?;
        let mut history = ForceHistory::default();
        while flow.time() < self.duration {
            flow.step(resolution.dt)?;
            let loads = flow.loads();
            history.push(flow.time(), loads.force * 2.0);
        }
        Ok(history.wake_statistics(self.duration * (1.0 - self.averaged)))
    }

    /// The case's flow at rest on `resolution`'s grid, before its first
    /// step: the cylinder in the stream, with the start-up turn.
    ///
    /// # Errors
    /// The solver's.
    pub fn flow(&self, resolution: Resolution) -> Result<Flow<SteadyStream>, NsError> {
        cylinder_in_stream(self.reynolds, resolution, 0.5, 2.0)
    }
}

/// The impulsively started circular cylinder (diameter 1): the drag
/// history against `U t / R` (Koumoutsakos & Leonard 1995).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpulsiveCylinder {
    /// `U D / ν`.
    pub reynolds: f64,
    /// The run ends at this `U t / R`.
    pub until: f64,
}

impl ImpulsiveCylinder {
    /// The resolution validated at Re 550: 256 nodes round, 192 out to 50
    /// diameters, first cell 0.001 D, step 0.004 D/U.
    #[must_use]
    pub fn validated() -> Resolution {
        Resolution {
            grid: GridSpec {
                around: 256,
                radial: 192,
                outer_radius: 100.0,
                first_cell: 0.002,
                far: None,
            },
            dt: 0.004,
        }
    }

    /// The finest resolution tried at Re 3000, validated there: 512 nodes
    /// round, 320 out to 50 diameters, first cell 0.00035 D, step
    /// 0.0007 D/U.
    #[must_use]
    pub fn validated_re_3000() -> Resolution {
        Resolution {
            grid: GridSpec {
                around: 512,
                radial: 320,
                outer_radius: 100.0,
                first_cell: 0.0007,
                far: None,
            },
            dt: 0.0007,
        }
    }

    /// Run the case at `resolution`: `(U t / R, CD)` after every step.
    ///
    /// # Errors
    /// The solver's.
    pub fn run(&self, resolution: Resolution) -> Result<Vec<(f64, f64)>, NsError> {
        let mut flow = self.flow(resolution)?;
        let mut drag = Vec::new();
        // t in D/U; U t / R = 2 t.
        while 2.0 * flow.time() < self.until {
            flow.step(resolution.dt)?;
            drag.push((2.0 * flow.time(), 2.0 * flow.loads().force.re));
        }
        Ok(drag)
    }

    /// The case's flow at rest on `resolution`'s grid, before its first
    /// step: the cylinder in the stream, started at the first step.
    ///
    /// # Errors
    /// The solver's.
    pub fn flow(&self, resolution: Resolution) -> Result<Flow<SteadyStream>, NsError> {
        cylinder_in_stream(self.reynolds, resolution, 0.0, 1.0)
    }
}

/// The hovering ellipse of Wang, Birch & Dickinson (2004): chord 1,
/// thickness 0.12, centre `x = A0/2 cos(2πft)` with `A0 = 2.8`, angle to
/// the stroke line `π/2 + π/4 sin(2πft)`, `f = 0.25`; `Re = U_max c / ν`
/// with `U_max = π f A0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoveringEllipse {
    /// `U_max c / ν` (75 in the reference).
    pub reynolds: f64,
    /// Periods simulated.
    pub periods: f64,
}

/// The stroke of [`HoveringEllipse`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoveringStroke {
    /// Stroke amplitude (peak to peak), chords.
    pub stroke: f64,
    /// Frequency, reference speed over chord.
    pub frequency: f64,
    /// Pitch amplitude, radians.
    pub pitch: f64,
    /// Mean angle of the chord to the stroke line, radians.
    pub mean_angle: f64,
}

impl HoveringStroke {
    /// Wang et al.'s stroke.
    #[must_use]
    pub fn wang_2004() -> Self {
        Self {
            stroke: 2.8,
            frequency: 0.25,
            pitch: std::f64::consts::FRAC_PI_4,
            mean_angle: std::f64::consts::FRAC_PI_2,
        }
    }

    /// The peak speed `π f A0`.
    #[must_use]
    pub fn peak_speed(&self) -> f64 {
        std::f64::consts::PI * self.frequency * self.stroke
    }
}

impl Motion for HoveringStroke {
    fn state(&self, t: f64) -> FrameState {
        let w = std::f64::consts::TAU * self.frequency;
        let (s, c) = (w * t).sin_cos();
        let half = 0.5 * self.stroke;
        FrameState {
            velocity: Complex64::new(-half * w * s, 0.0),
            acceleration: Complex64::new(-half * w * w * c, 0.0),
            angle: self.mean_angle + self.pitch * s,
            rate: self.pitch * w * c,
            angular_acceleration: -self.pitch * w * w * s,
        }
    }
}

impl HoveringEllipse {
    /// The resolution validated for the hovering ellipse: 192 nodes round,
    /// 128 out to 28 chords, first cell 0.01 in ξ, step 0.00025 c/U.
    #[must_use]
    pub fn validated() -> Resolution {
        Resolution {
            grid: GridSpec {
                around: 192,
                radial: 128,
                outer_radius: 100.0,
                first_cell: 0.01,
                far: None,
            },
            dt: 0.00025,
        }
    }

    /// The peak of the quasi-steady lift the published curves are
    /// normalized by, over `½ ρ U_max² c`: Dickinson's fit
    /// `CL = 1.2 sin 2α` at `α = 45°` and `U_max`, which is mid-stroke
    /// (Wang, Birch & Dickinson 2004; the normalization of the curves of
    /// Eldredge 2007 and Li et al. 2015 as distributed with PetIBM).
    pub const QUASI_STEADY_PEAK_LIFT: f64 = 1.2;

    /// Run the case at `resolution`: `(t / T, CL)` after every step, the
    /// lift being the force across the stroke over the quasi-steady peak
    /// lift `1.2 · ½ ρ U_max² c` ([`Self::QUASI_STEADY_PEAK_LIFT`]), as in
    /// the published curves.
    ///
    /// # Errors
    /// The solver's.
    pub fn run(&self, resolution: Resolution) -> Result<Vec<(f64, f64)>, NsError> {
        let map = SectionMap::ellipse(0.5, 0.06, (0.0, 0.0))?;
        let stroke = HoveringStroke::wang_2004();
        let speed = stroke.peak_speed();
        let mut flow = Flow::new(&map, resolution.grid, stroke, speed / self.reynolds)?;
        let period = 1.0 / stroke.frequency;
        let scale = 2.0 / (speed * speed * Self::QUASI_STEADY_PEAK_LIFT);
        let mut lift = Vec::new();
        while flow.time() < self.periods * period {
            flow.step(resolution.dt)?;
            lift.push((flow.time() / period, scale * flow.loads().force.im));
        }
        Ok(lift)
    }
}
