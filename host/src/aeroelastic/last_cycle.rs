//! What a system analysis's result says about its last flapping cycle
//! beyond the cycle means: the tip's deflection amplitude, the drive's mean
//! power, the coupling effort, and why its numbers may not be trusted
//! ([`Doubt`]). Methods on [`SystemResult`], used by `fwav
//! system-analysis` and by the MDOIS records alike, and the same as
//! functions of an analysis's steps, for a record read back.
//!
//! May import: [`super::analysis`], [`super::kinematics`] and
//! [`crate::periodicity`].

use fwav_settings::Shown;

use super::analysis::{StepRecord, SystemResult, SystemSettings};
use super::kinematics::FlappingKinematics;
use crate::periodicity::{change_of_swing, PERIODIC_CHANGE};

/// Why a system analysis's numbers are not to be trusted. The numbers are
/// still shown, with the doubt beside them.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum Doubt {
    /// The last two cycles disagree ([`PERIODIC_CHANGE`] of
    /// [`crate::periodicity`]).
    #[error(
        "the result is not periodic: the mean CT changed by {:.0}% of its size or swing between \
         the last two cycles (more than {:.0}%); run more cycles ([analysis] cycles, {cycles} \
         now), or the motion is more than this wing takes",
        100.0 * change,
        100.0 * PERIODIC_CHANGE
    )]
    NotPeriodic {
        /// The change, relative to the larger of the mean CT and its swing.
        change: f64,
        /// The cycles simulated.
        cycles: usize,
    },
    /// The coupling stopped at its cap of sub-iterations with the
    /// interface residual above its tolerance in some of the last cycle's
    /// steps: there the lattice and the shell were not solved together.
    #[error(
        "the coupling did not converge in {steps} of the last cycle's {total} steps: it \
         stopped at its cap of {cap} sub-iteration{} with the interface residual up to {:.3} \
         (tolerance {}); raise [analysis] max_subiterations, or take more steps a cycle \
         ([analysis] steps_per_cycle)",
        if *cap == 1 { "" } else { "s" },
        Shown(*worst_residual),
        Shown(*tolerance)
    )]
    CouplingNotConverged {
        /// The last cycle's steps whose final residual is above the
        /// tolerance.
        steps: usize,
        /// The last cycle's steps.
        total: usize,
        /// The largest final residual.
        worst_residual: f64,
        /// The coupling tolerance.
        tolerance: f64,
        /// The sub-iterations allowed a step.
        cap: usize,
    },
    /// The tip's flapwise deflection amplitude is larger than the
    /// semi-span: no wing that does not stretch reaches that far from its
    /// undeformed place, so the shell has left the range of its model.
    #[error(
        "the wing tip swung {:.0} mm either way on a {:.0} mm semi-span, farther than a wing \
         that does not stretch can reach: the structure has left its model's range; lower the \
         frequency or the amplitude, or stiffen the wing",
        1e3 * amplitude_m,
        1e3 * semi_span_m
    )]
    TipBeyondSpan {
        /// The tip's deflection amplitude, m.
        amplitude_m: f64,
        /// The wing's semi-span, m.
        semi_span_m: f64,
    },
}

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
        last_cycle(&self.steps, steps_per_cycle)
    }

    /// Half of the tip's peak-to-peak flapwise deflection over the last
    /// cycle, m (0 without steps).
    pub fn tip_deflection_amplitude_m(&self, steps_per_cycle: usize) -> f64 {
        tip_deflection_amplitude_m(&self.steps, steps_per_cycle)
    }

    /// The change of the mean CT from the cycle before the last to the
    /// last, relative to the larger of the last cycle's mean CT and its CT
    /// swing; `None` with fewer than two cycles of `steps_per_cycle`.
    pub fn ct_change_of_swing(&self, steps_per_cycle: usize) -> Option<f64> {
        ct_change_of_swing(&self.steps, steps_per_cycle)
    }

    /// Why this result's numbers are not to be trusted, if at all: an
    /// analysis with `settings`, of a wing of `semi_span_m`.
    pub fn doubts(&self, settings: &SystemSettings, semi_span_m: f64) -> Vec<Doubt> {
        doubts(&self.steps, settings, semi_span_m)
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

/// The steps of the last cycle of `steps_per_cycle` steps (all of them if
/// fewer were taken).
fn last_cycle(steps: &[StepRecord], steps_per_cycle: usize) -> &[StepRecord] {
    &steps[steps.len().saturating_sub(steps_per_cycle)..]
}

/// [`SystemResult::tip_deflection_amplitude_m`] of an analysis's `steps`
/// (a result's, or a design record's read back).
pub fn tip_deflection_amplitude_m(steps: &[StepRecord], steps_per_cycle: usize) -> f64 {
    let last = last_cycle(steps, steps_per_cycle);
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

/// [`SystemResult::ct_change_of_swing`] of an analysis's `steps`.
pub fn ct_change_of_swing(steps: &[StepRecord], steps_per_cycle: usize) -> Option<f64> {
    let n = steps_per_cycle;
    let total = steps.len();
    if n == 0 || total < 2 * n {
        return None;
    }
    let ct = |cycle: &[StepRecord]| cycle.iter().map(|s| s.ct).collect::<Vec<f64>>();
    let mean = |values: &[f64]| values.iter().sum::<f64>() / n as f64;
    let last = ct(&steps[total - n..]);
    let previous = ct(&steps[total - 2 * n..total - n]);
    Some(change_of_swing(mean(&last), mean(&previous), &last))
}

/// [`SystemResult::doubts`] of an analysis's `steps`: a design resumed
/// from records asks them of its `system.json` as a new analysis is asked.
pub fn doubts(steps: &[StepRecord], settings: &SystemSettings, semi_span_m: f64) -> Vec<Doubt> {
    let steps_per_cycle = settings.steps_per_cycle;
    let mut doubts = Vec::new();
    if let Some(change) = ct_change_of_swing(steps, steps_per_cycle) {
        if change > PERIODIC_CHANGE || change.is_nan() {
            doubts.push(Doubt::NotPeriodic {
                change,
                cycles: settings.cycles,
            });
        }
    }
    // The last cycle's steps, whose numbers are reported, as the other
    // doubts judge (a step of the start's transient at the cap is not
    // held against the answer). A rigid wing has no coupling (one pass a
    // step, residual 0).
    let last = last_cycle(steps, steps_per_cycle);
    let unconverged: Vec<f64> = last
        .iter()
        .map(|s| s.residual)
        .filter(|r| r.is_nan() || *r > settings.coupling_tolerance)
        .collect();
    if !unconverged.is_empty() {
        doubts.push(Doubt::CouplingNotConverged {
            steps: unconverged.len(),
            total: last.len(),
            worst_residual: unconverged.iter().copied().fold(f64::NAN, f64::max),
            tolerance: settings.coupling_tolerance,
            cap: settings.max_subiterations,
        });
    }
    let amplitude_m = tip_deflection_amplitude_m(steps, steps_per_cycle);
    if amplitude_m >= semi_span_m || amplitude_m.is_nan() {
        doubts.push(Doubt::TipBeyondSpan {
            amplitude_m,
            semi_span_m,
        });
    }
    doubts
}
