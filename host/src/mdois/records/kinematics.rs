//! `cycle-N/kinematics.json`: the aerodynamic discipline's run of a cycle,
//! with the proposal the next cycle analyses.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::discipline::kinematic::KinematicResult;
use crate::discipline::section::SectionResult;

use super::super::error::DesignError;
use super::{cycle_file, load_json};

/// The file's name in `cycle-N/`.
pub const FILE: &str = "kinematics.json";

/// The initial design's evaluation, asked for by every discipline run.
const INITIAL_DESIGN: usize = 1;

/// The ANOM and RSM confirmation runs (the best L18 row's candidate is its
/// array run, not a new evaluation).
const CONFIRMATIONS: usize = 2;

/// `cycle-N/kinematics.json`: the aerodynamic discipline's run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct KinematicRecord {
    /// The kinematics of the cycle's design (the discipline's initial
    /// design and reference).
    pub analysed: FlappingKinematics,
    /// What the discipline proposes: the chosen candidate, or the
    /// analysed design when no candidate beats it.
    pub proposed: FlappingKinematics,
    /// The chosen candidate's method, if one was chosen.
    pub chosen: Option<String>,
    /// The proposed design's 2D result (None if it failed).
    pub proposed_2d: Option<SectionResult>,
    /// 2D evaluations found in the cache.
    pub evaluations_reused: usize,
    /// The whole discipline run (array, ANOM, surfaces, Pareto front,
    /// candidates).
    pub result: KinematicResult,
}

/// The 2D evaluations a discipline run asks for: the initial design, each
/// array row and the confirmations.
pub fn evaluations_asked(result: &KinematicResult) -> usize {
    INITIAL_DESIGN + result.runs.len() + CONFIRMATIONS
}

/// The evaluations of a discipline run that failed (a failure is not
/// cached, so each was computed).
pub fn evaluations_failed(result: &KinematicResult) -> usize {
    std::iter::once(&result.initial)
        .chain(&result.runs)
        .chain(result.candidates.iter().skip(1).map(|c| &c.confirmation))
        .filter(|e| e.result.is_err())
        .count()
}

impl KinematicRecord {
    /// The record of a discipline run from `analysed` that computed
    /// `computed` of its evaluations (the rest came from the cache).
    pub fn of(analysed: FlappingKinematics, result: KinematicResult, computed: usize) -> Self {
        let (proposed, chosen, proposed_2d) = match result.chosen {
            Some(i) => {
                let c = &result.candidates[i];
                (
                    c.confirmation.design,
                    Some(c.method.clone()),
                    c.confirmation.result.clone().ok(),
                )
            }
            None => (analysed, None, result.initial.result.clone().ok()),
        };
        Self {
            analysed,
            proposed,
            chosen,
            proposed_2d,
            evaluations_reused: evaluations_asked(&result).saturating_sub(computed),
            result,
        }
    }
}

/// The aerodynamic discipline's record of `cycle` in the run's `dir`.
pub fn load_kinematics(dir: &Path, cycle: usize) -> Result<KinematicRecord, DesignError> {
    load_json(dir, &cycle_file(cycle, FILE))
}
