//! One evaluation of the aerodynamic discipline: the mid-span section of
//! the wing flapping with given kinematics, deforming as the system
//! analysis found (held fixed within the cycle, as the seed paper's
//! discipline holds it), analysed in 2D by the LDVM of [`crate::aero2d`].
//!
//! Physical to non-dimensional: the section of chord `c` at `r` from the
//! flapping axis in a flight at `U` flaps at the reduced frequency `k = pi f
//! c / U` and sweeps `r / c` chords about the axis ([`SectionFlapping`]:
//! plunge, and the surge of an inclined stroke plane). The deformation
//! samples cover one cycle of the system analysis; a changed frequency
//! stretches them over the new cycle (the shape history is kept in phase
//! with the stroke).

use serde::{Deserialize, Serialize};

use crate::aero2d::camber::{CamberError, CamberHistory};
use crate::aero2d::ldvm::{
    cycle_mean_of, cycle_means, cycle_means_until, History, Ldvm, Motion, SectionFlapping, Settings,
};
use crate::aeroelastic::kinematics::{FlappingKinematics, KinematicsError};
use crate::aeroelastic::model::FlightCondition;

/// Kinematic viscosity of sea-level air, m²/s (for the chord Reynolds
/// number of the friction estimate).
pub const AIR_KINEMATIC_VISCOSITY: f64 = 1.46e-5;

/// The section and how to analyse it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SectionCase {
    /// Section chord, m.
    pub chord: f64,
    /// Distance of the section from the flapping axis, m.
    pub radius: f64,
    /// Flight condition.
    pub flight: FlightCondition,
    /// Mid-line samples over one cycle, chords, in the section's flapping
    /// frame, sample `k` at `(k + 1) dt` after a cycle start (the system
    /// analysis's `section_history`); empty: a rigid flat section.
    pub deformation: Vec<Vec<[f64; 2]>>,
    /// Cycles simulated; the last two are averaged.
    pub cycles: usize,
    /// Time steps per cycle (at least; the step is also at most 0.015
    /// chords travelled).
    pub steps_per_cycle: usize,
}

/// The cycle-mean results of one evaluation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SectionResult {
    /// Reduced frequency `k = pi f c / U`.
    pub reduced_frequency: f64,
    /// Mean thrust coefficient (inviscid), on `1/2 rho U^2 c`.
    pub ct: f64,
    /// Mean thrust coefficient less the laminar friction estimate.
    pub ct_net: f64,
    /// Mean power coefficient, on `1/2 rho U^3 c`.
    pub cp: f64,
    /// Propulsive efficiency `CT / CP` (inviscid).
    pub efficiency: f64,
    /// Change of the mean CT between the last two cycles (periodicity).
    pub ct_change: f64,
}

/// Why an evaluation failed.
#[derive(Debug, thiserror::Error)]
pub enum EvaluationError {
    /// Kinematics out of range.
    #[error(transparent)]
    Kinematics(#[from] KinematicsError),
    /// The deformation samples are unusable.
    #[error("section deformation: {0}")]
    Deformation(#[from] CamberError),
    /// A case value out of range.
    #[error("section case: {0}")]
    Case(String),
    /// The solution is not finite (the solver diverged).
    #[error("the 2D analysis diverged (non-finite {0})")]
    Diverged(&'static str),
}

impl SectionCase {
    /// The built-in FWAV's mid-span section: chord 0.06 m at 0.075 m from
    /// the axis, 3 m/s at sea level, rigid, 4 cycles of at least 100 steps.
    pub fn fwav_mid_span() -> Self {
        Self {
            chord: 0.06,
            radius: 0.075,
            flight: FlightCondition::FWAV,
            deformation: Vec::new(),
            cycles: 4,
            steps_per_cycle: 100,
        }
    }

    /// Runs the 2D analysis for `kinematics`.
    pub fn evaluate(
        &self,
        kinematics: &FlappingKinematics,
    ) -> Result<SectionResult, EvaluationError> {
        kinematics.validate()?;
        let positive = |v: f64| v.is_finite() && v > 0.0;
        if !(positive(self.chord) && positive(self.radius) && positive(self.flight.speed)) {
            return Err(EvaluationError::Case(format!(
                "chord {} m, radius {} m and speed {} m/s must be positive",
                self.chord, self.radius, self.flight.speed
            )));
        }
        if self.cycles < 3 || self.steps_per_cycle < 20 {
            return Err(EvaluationError::Case(format!(
                "at least 3 cycles of 20 steps (got {} of {})",
                self.cycles, self.steps_per_cycle
            )));
        }
        let k = std::f64::consts::PI * kinematics.frequency * self.chord / self.flight.speed;
        let period = std::f64::consts::PI / k;
        let settings = Settings {
            dt: (period / self.steps_per_cycle as f64).min(Settings::default().dt),
            duration: self.cycles as f64 * period,
            reynolds: Some(self.flight.speed * self.chord / AIR_KINEMATIC_VISCOSITY),
            ..Settings::default()
        };
        let flapping = SectionFlapping {
            reduced_frequency: k,
            radius: self.radius / self.chord,
            amplitude: kinematics.amplitude,
            mean_angle: kinematics.mean_angle,
            stroke_plane: kinematics.stroke_plane,
        };
        let mut solver = Ldvm::new(Motion::plunge(k, 0.0), settings).with_flapping(flapping);
        if !self.deformation.is_empty() {
            // Sample k is at (k + 1) dt: the last one is the cycle's start.
            let n = self.deformation.len();
            let samples: Vec<Vec<(f64, f64)>> = (0..n)
                .map(|i| {
                    self.deformation[(i + n - 1) % n]
                        .iter()
                        .map(|p| (p[0], p[1]))
                        .collect()
                })
                .collect();
            let stations = samples.iter().map(Vec::len).max().unwrap_or(0).max(21);
            solver = solver.with_camber(CamberHistory::from_section_points(
                &samples, period, stations,
            )?);
        }
        let history = solver.run();
        summarize(&history, period, k)
    }
}

fn summarize(history: &History, period: f64, k: f64) -> Result<SectionResult, EvaluationError> {
    let (ct, cp, efficiency) = cycle_means(history, period, 2);
    let end = history.time.last().copied().unwrap_or(0.0);
    let (ct_before, _, _) = cycle_means_until(history, period, 1, end - period);
    let (ct_last, _, _) = cycle_means(history, period, 1);
    let friction = cycle_mean_of(history, &history.cd_friction, period, 2);
    let result = SectionResult {
        reduced_frequency: k,
        ct,
        ct_net: ct - friction,
        cp,
        efficiency,
        ct_change: if ct_before.abs() > 0.0 {
            ct_last / ct_before - 1.0
        } else {
            0.0
        },
    };
    for (name, v) in [("CT", result.ct), ("CP", result.cp), ("friction", friction)] {
        if !v.is_finite() {
            return Err(EvaluationError::Diverged(name));
        }
    }
    Ok(result)
}
