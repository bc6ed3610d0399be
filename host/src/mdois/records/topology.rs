//! `cycle-N/topology.json`: the structural discipline's run of a cycle,
//! with the layout the next cycle analyses.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::topology::eslso::{DesignProblem, EslsoResult};

use super::super::error::DesignError;
use super::super::stage::layout_densities;
use super::{cycle_file, load_json};

/// The file's name in `cycle-N/`.
pub const FILE: &str = "topology.json";

/// `cycle-N/topology.json`: the structural discipline's run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TopologyRecord {
    /// Design-domain elements whose carbon density differs between the
    /// analysed design and the new layout.
    pub elements_changed: usize,
    /// Elements of the design domain.
    pub design_elements: usize,
    /// Carbon mass fraction of the analysed design.
    pub analysed_mass_fraction: f64,
    /// Carbon mass fraction of the new layout.
    pub mass_fraction: f64,
    /// The ESLSO run (cycles, layout, last SIMP densities).
    pub result: EslsoResult,
}

impl TopologyRecord {
    /// The record of an ESLSO run of `problem` from the `analysed`
    /// densities.
    pub fn of(problem: &DesignProblem, analysed: &[f64], result: EslsoResult) -> Self {
        let layout = layout_densities(&result.layout);
        let design_flags = &problem.design;
        let elements_changed = analysed
            .iter()
            .zip(&layout)
            .zip(design_flags)
            .filter(|((a, b), &d)| d && a != b)
            .count();
        Self {
            elements_changed,
            design_elements: design_flags.iter().filter(|&&d| d).count(),
            analysed_mass_fraction: problem.mass_fraction(analysed),
            mass_fraction: problem.mass_fraction(&layout),
            result,
        }
    }
}

/// The structural discipline's record of `cycle` in the run's `dir`.
pub fn load_topology(dir: &Path, cycle: usize) -> Result<TopologyRecord, DesignError> {
    load_json(dir, &cycle_file(cycle, FILE))
}
