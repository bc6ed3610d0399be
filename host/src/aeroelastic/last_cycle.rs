//! What a system analysis's result says about its last flapping cycle
//! beyond the cycle means: the tip's deflection amplitude, the drive's mean
//! power, the coupling effort. Methods on [`SystemResult`], used by `fwav
//! system-analysis` and by the MDOIS records alike.
//!
//! May import: [`super::analysis`] and [`super::kinematics`].

use super::analysis::{StepRecord, SystemResult};
use super::kinematics::FlappingKinematics;

/// Coupling sub-iterations over a whole analysis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CouplingEffort {
    /// Mean sub-iterations a step.
    pub mean: f64,
    /// Most sub-iterations of a step.
    pub max: usize,
}

impl SystemResult {
    /// The steps of the last cycle of `steps_per_cycle` steps (all of them
    /// if fewer were taken).
    pub fn last_cycle(&self, steps_per_cycle: usize) -> &[StepRecord] {
        &self.steps[self.steps.len().saturating_sub(steps_per_cycle)..]
    }

    /// Half of the tip's peak-to-peak flapwise deflection over the last
    /// cycle, m (0 without steps).
    pub fn tip_deflection_amplitude_m(&self, steps_per_cycle: usize) -> f64 {
        let last = self.last_cycle(steps_per_cycle);
        if last.is_empty() {
            return 0.0;
        }
        let (low, high) = last
            .iter()
            .map(|s| s.tip_displacement_m[2])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), z| {
                (l.min(z), h.max(z))
            });
        0.5 * (high - low)
    }

    /// Mean power the drive puts in over the last cycle (drive torque
    /// times the flapping rate of `kinematics`), W.
    pub fn mean_drive_power_w(
        &self,
        kinematics: &FlappingKinematics,
        steps_per_cycle: usize,
    ) -> f64 {
        let last = self.last_cycle(steps_per_cycle);
        last.iter()
            .map(|s| s.drive_torque_nm * kinematics.angle(s.time_s).1)
            .sum::<f64>()
            / last.len() as f64
    }

    /// The coupling sub-iterations of every step: mean and most.
    pub fn coupling_effort(&self) -> CouplingEffort {
        let steps = &self.steps;
        CouplingEffort {
            mean: steps.iter().map(|s| s.subiterations as f64).sum::<f64>()
                / steps.len().max(1) as f64,
            max: steps.iter().map(|s| s.subiterations).max().unwrap_or(0),
        }
    }
}
