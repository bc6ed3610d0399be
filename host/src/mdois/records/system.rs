//! `cycle-N/system.json`: the system analysis of a cycle's design, as the
//! summary, the plots and a resumed run read it back. Versioned
//! ([`FORMAT`]).

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::aeroelastic::analysis::SystemSettings;
use crate::aeroelastic::last_cycle::{self, Doubt};
use crate::aeroelastic::{CycleMeans, StepRecord, SystemResult};
use crate::file_format::{FileFormat, FormatError};

use super::super::error::DesignError;
use super::cycle_path;
use crate::aeroelastic::kinematics::FlappingKinematics;

/// The kind of file and the version this build reads and writes.
pub const FORMAT: FileFormat = FileFormat {
    file: "system.json",
    format: "fwav-system-analysis",
    version: 1,
};

/// `cycle-N/system.json`: the system analysis of the cycle's design.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SystemRecord {
    /// Always [`FORMAT`]'s `format`.
    pub format: String,
    /// [`FORMAT`]'s `version`.
    pub format_version: u32,
    /// The kinematics analysed.
    pub kinematics: FlappingKinematics,
    /// Means over the last simulated cycle (3D thrust, lift, power,
    /// efficiency).
    pub means: CycleMeans,
    /// Every time step.
    pub steps: Vec<StepRecord>,
    /// Time steps a flapping cycle.
    pub steps_per_cycle: usize,
    /// Half of the tip's peak-to-peak flapwise deflection over the last
    /// cycle, m.
    pub tip_deflection_amplitude_m: f64,
    /// Mass of the half wing, kg.
    pub wing_mass_kg: f64,
    /// Reference area (half-wing planform), m².
    pub reference_area_m2: f64,
    /// Time step, s.
    pub dt_s: f64,
}

impl SystemRecord {
    /// The record of `result`, the analysis of `kinematics` with
    /// `steps_per_cycle` steps a cycle.
    pub fn of(
        kinematics: FlappingKinematics,
        result: &SystemResult,
        steps_per_cycle: usize,
    ) -> Self {
        Self {
            format: FORMAT.format.to_string(),
            format_version: FORMAT.version,
            kinematics,
            means: result.means,
            steps: result.steps.clone(),
            steps_per_cycle,
            tip_deflection_amplitude_m: result.tip_deflection_amplitude_m(steps_per_cycle),
            wing_mass_kg: result.wing_mass_kg,
            reference_area_m2: result.reference_area_m2,
            dt_s: result.dt_s,
        }
    }

    /// Why this analysis's numbers are not to be trusted, if at all
    /// ([`SystemResult::doubts`], asked of the steps read back), for a wing
    /// of `semi_span_m` analysed with `settings` (the record's own steps a
    /// cycle).
    pub fn doubts(&self, settings: &SystemSettings, semi_span_m: f64) -> Vec<Doubt> {
        let settings = SystemSettings {
            steps_per_cycle: self.steps_per_cycle,
            ..*settings
        };
        last_cycle::doubts(&self.steps, &settings, semi_span_m)
    }

    /// The file's text.
    pub fn to_json(&self) -> Result<String, FormatError> {
        FORMAT.to_json(self, false)
    }
}

/// The system analysis record of `cycle` in the run's `dir`.
pub fn load_system(dir: &Path, cycle: usize) -> Result<SystemRecord, DesignError> {
    Ok(FORMAT.read(&cycle_path(dir, cycle, FORMAT.file))?)
}
