//! The discipline's combined objective (module docs of
//! [`super`]): the net thrust and net efficiency relative to a reference
//! design's, weighted, with the actuator's constraint.

use serde::{Deserialize, Serialize};

use super::{Evaluated, KinematicError, Violation};
use crate::discipline::section::SectionResult;

/// The combined objective's reference: the net thrust coefficient and net
/// efficiency the design's objectives are divided by (the first cycle's
/// initial design's: see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ObjectiveReference {
    /// `CT_0`, net.
    pub ct_net: f64,
    /// `eta_0`, net.
    pub efficiency_net: f64,
}

impl ObjectiveReference {
    /// The reference a run's result gives: refused unless both are
    /// positive (the ratios would flip sign). A result's power is positive
    /// (an evaluation without is refused as
    /// [`crate::discipline::section::EvaluationError::NoInputPower`]), so
    /// its net efficiency has the net thrust's sign.
    ///
    /// # Errors
    /// [`KinematicError::NoNetThrust`].
    pub fn of(result: &SectionResult) -> Result<Self, KinematicError> {
        if !(result.ct_net > 0.0 && result.efficiency_net > 0.0) {
            return Err(KinematicError::NoNetThrust {
                ct_net: result.ct_net,
                ct: result.ct,
            });
        }
        Ok(Self {
            ct_net: result.ct_net,
            efficiency_net: result.efficiency_net,
        })
    }
}

/// Weights of the combined objective.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Weights {
    /// Weight of `CT / CT_0`.
    pub thrust: f64,
    /// Weight of `eta / eta_0`.
    pub efficiency: f64,
}

/// The combined objective, relative to the initial design's results, and
/// the actuator's constraint.
pub(super) struct Objective<'a> {
    pub(super) weights: Weights,
    pub(super) reference: ObjectiveReference,
    pub(super) violation: Violation<'a>,
}

impl Objective<'_> {
    /// The combined objective of a result, on the net thrust and net
    /// efficiency.
    pub(super) fn combined(&self, r: &SectionResult) -> f64 {
        self.weights.thrust * r.ct_net / self.reference.ct_net
            + self.weights.efficiency * r.efficiency_net / self.reference.efficiency_net
    }

    /// The margin by which one evaluation's combined objective must
    /// exceed another's, near `result`, to be better beyond the
    /// evaluations' `scatter` (relative standard deviations of the net
    /// thrust and efficiency, the flow model's [`window_scatter`]): one
    /// standard deviation of the difference of two independent runs,
    /// `√2 (w_ct s_ct CT/CT_0 + w_eta s_eta eta/eta_0)` (the two scatters
    /// added as if fully correlated, the larger bound).
    ///
    /// [`window_scatter`]: crate::discipline::section_model::SectionFlowModel::window_scatter
    pub(super) fn margin(&self, result: &SectionResult, scatter: (f64, f64)) -> f64 {
        let spread = self.weights.thrust * scatter.0 * result.ct_net / self.reference.ct_net
            + self.weights.efficiency * scatter.1 * result.efficiency_net
                / self.reference.efficiency_net;
        std::f64::consts::SQRT_2 * spread.abs()
    }

    /// The combined objective of a run, None if it failed.
    pub(super) fn score(&self, e: &Evaluated) -> Option<f64> {
        e.result.as_ref().ok().map(|r| self.combined(r))
    }

    /// The combined objective of the surfaces' objectives `[-CT_net,
    /// -eta_net]`.
    pub(super) fn predicted(&self, o: &[f64]) -> f64 {
        self.weights.thrust * -o[0] / self.reference.ct_net
            + self.weights.efficiency * -o[1] / self.reference.efficiency_net
    }
}
