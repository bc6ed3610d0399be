//! `summary.json`: per cycle the design analysed, its 3D thrust, power and
//! efficiency (system analysis), the aerodynamic discipline's proposal and
//! its 2D values, the structural discipline's strain energy, mass fraction
//! and elements changed, whether the design changed, and the stage times;
//! then the initial design against the final one. Built from the run's
//! state and stage files, so a resumed run's summary is the same as an
//! uninterrupted one's (stage times and invocation numbers aside).

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::file_format::{FileFormat, FormatError, ReadError};

use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::config::SystemConfig;
use crate::discipline::section::SectionResult;
use crate::discipline::section_model::ModelledSection;

use super::error::DesignError;
use super::plant::cycle_vehicle;
use super::profile::{actuator_check, ActuatorCheck};
use super::records::{
    load_kinematics, load_system, load_topology, KinematicRecord, SystemRecord, TopologyRecord,
};
use super::state::{Outcome, RunState, Stage, StageRecord};

/// The kind of file and the version this build reads and writes.
pub const FORMAT: FileFormat = FileFormat {
    file: "summary.json",
    format: "fwav-design-summary",
    version: 1,
};

/// How much the design changed in a cycle's disciplines, and whether that
/// counts as unchanged ([`crate::config::MdoisConfig`]).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct CycleChange {
    /// Largest move of a kinematic variable, as a fraction of its level
    /// range.
    pub kinematics_change_of_range: f64,
    /// Every kinematic variable within the tolerance.
    pub kinematics_unchanged: bool,
    /// Design-domain elements whose carbon changed.
    pub elements_changed: usize,
    /// The same as a fraction of the design domain.
    pub elements_changed_fraction: f64,
    /// The layout within the tolerance.
    pub layout_unchanged: bool,
    /// Both: the seed paper's stopping rule.
    pub design_unchanged: bool,
}

/// The change of a cycle from its two discipline records.
pub fn change(
    config: &SystemConfig,
    kinematics: &KinematicRecord,
    topology: &TopologyRecord,
) -> CycleChange {
    let space = config.design_space();
    let ranges = [
        space.frequency_hz,
        space.amplitude_deg,
        space.mean_angle_deg,
        space.stroke_plane_deg,
    ]
    .map(|l| (l[2] - l[0]).abs().max(f64::MIN_POSITIVE));
    let (a, p) = (kinematics.analysed.degrees(), kinematics.proposed.degrees());
    let kinematics_change_of_range = (0..4)
        .map(|i| (p[i] - a[i]).abs() / ranges[i])
        .fold(0.0f64, f64::max);
    let tolerance = &config.mdois;
    let kinematics_unchanged = kinematics_change_of_range <= tolerance.kinematics_tolerance;
    let fraction = topology.elements_changed as f64 / topology.design_elements.max(1) as f64;
    let layout_unchanged = topology.elements_changed == 0 || fraction <= tolerance.layout_tolerance;
    CycleChange {
        kinematics_change_of_range,
        kinematics_unchanged,
        elements_changed: topology.elements_changed,
        elements_changed_fraction: fraction,
        layout_unchanged,
        design_unchanged: kinematics_unchanged && layout_unchanged,
    }
}

/// The 3D system analysis of a cycle's design.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SystemSummary {
    /// Mean thrust coefficient over the last flapping cycle.
    pub ct: f64,
    /// Mean lift coefficient.
    pub cl: f64,
    /// Mean power coefficient.
    pub cp: f64,
    /// Propulsive efficiency CT / CP.
    pub efficiency: f64,
    /// Relative change of the mean CT over the last two flapping cycles.
    pub ct_change_last_two_cycles: f64,
    /// Half of the tip's peak-to-peak deflection, m.
    pub tip_deflection_amplitude_m: f64,
    /// Mass of the half wing, kg.
    pub wing_mass_kg: f64,
    /// Wall time, s.
    pub seconds: f64,
    /// The driver invocation that computed it.
    pub run: usize,
}

/// The aerodynamic discipline of a cycle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct KinematicsSummary {
    /// The analysed design's 2D result on the cycle's section.
    pub analysed_2d: Option<SectionResult>,
    /// The chosen candidate's method (None: the analysed design stays).
    pub chosen: Option<String>,
    /// The proposal.
    pub proposed: FlappingKinematics,
    /// The proposal's 2D result.
    pub proposed_2d: Option<SectionResult>,
    /// 2D evaluations reused from the cache.
    pub evaluations_reused: usize,
    /// How far a candidate's combined objective had to exceed the
    /// analysed design's to be chosen (the evaluations' scatter; 0 for
    /// the attached LDVM and in runs recorded before it was).
    #[serde(default)]
    pub adoption_margin: f64,
    /// The 2D evaluations' flow model and what it left out of the section
    /// (None in runs recorded before it was: the LDVM).
    #[serde(default)]
    pub section: Option<ModelledSection>,
    /// Wall time, s.
    pub seconds: f64,
    /// The driver invocation that computed it.
    pub run: usize,
}

/// The structural discipline of a cycle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TopologySummary {
    /// Summed strain energy of the analysed design under the cycle's
    /// pressure history (first ESLSO cycle's nonlinear analysis), J.
    pub strain_energy_j: f64,
    /// The same for the design of ESLSO's last cycle, J.
    pub final_strain_energy_j: f64,
    /// Carbon mass fraction of the new layout.
    pub mass_fraction: f64,
    /// Carbon elements of the new layout (spar included).
    pub carbon_elements: usize,
    /// Design-domain elements whose carbon changed.
    pub elements_changed: usize,
    /// ESLSO cycles run.
    pub eslso_cycles: usize,
    /// Whether ESLSO's layout stopped changing.
    pub eslso_converged: bool,
    /// Wall time, s.
    pub seconds: f64,
    /// The driver invocation that computed it.
    pub run: usize,
}

/// One design cycle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CycleSummary {
    /// Cycle number from 1.
    pub cycle: usize,
    /// The kinematics analysed.
    pub kinematics: FlappingKinematics,
    /// Carbon mass fraction of the design analysed.
    pub carbon_mass_fraction: f64,
    /// The system analysis (None: not finished).
    pub system: Option<SystemSummary>,
    /// The aerodynamic discipline.
    pub aerodynamic: Option<KinematicsSummary>,
    /// The structural discipline.
    pub structural: Option<TopologySummary>,
    /// The change, once both disciplines are done.
    pub change: Option<CycleChange>,
    /// Wall time of the finished stages, s (the disciplines ran side by
    /// side, so the cycle took less).
    pub seconds: f64,
}

/// A design and its 3D performance.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DesignPoint {
    /// The cycle that analysed it.
    pub cycle: usize,
    /// Its kinematics.
    pub kinematics: FlappingKinematics,
    /// Its carbon mass fraction.
    pub carbon_mass_fraction: f64,
    /// Mean thrust coefficient (3D).
    pub ct: f64,
    /// Mean power coefficient (3D).
    pub cp: f64,
    /// Propulsive efficiency (3D).
    pub efficiency: f64,
    /// Mass of the half wing, kg.
    pub wing_mass_kg: f64,
}

/// The final design against the initial one, relative changes.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Comparison {
    /// `CT_final / CT_initial - 1`.
    pub ct_relative_change: f64,
    /// `CP_final / CP_initial - 1`.
    pub cp_relative_change: f64,
    /// `eta_final / eta_initial - 1`.
    pub efficiency_relative_change: f64,
    /// `m_final / m_initial - 1`.
    pub wing_mass_relative_change: f64,
}

/// The whole `summary.json`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Summary {
    /// Always [`FORMAT`]'s `format`.
    pub format: String,
    /// [`FORMAT`]'s `version`.
    pub format_version: u32,
    /// Whether the run is over.
    pub finished: bool,
    /// `"converged"`, `"cycle cap reached"` or `"unfinished"`.
    pub outcome: String,
    /// The cycle whose disciplines left the design unchanged.
    pub converged_cycle: Option<usize>,
    /// The cycle cap (`[mdois] max_cycles`).
    pub max_cycles: usize,
    /// `[mdois] kinematics_tolerance`.
    pub kinematics_tolerance_of_range: f64,
    /// `[mdois] layout_tolerance`.
    pub layout_tolerance: f64,
    /// Every cycle begun.
    pub cycles: Vec<CycleSummary>,
    /// The initial design (cycle 1's analysis).
    pub initial: Option<DesignPoint>,
    /// The final design: the converged cycle's, or at the cap the last
    /// proposal's analysis.
    #[serde(rename = "final")]
    pub final_design: Option<DesignPoint>,
    /// Final against initial.
    pub comparison: Option<Comparison>,
    /// Wall time of every stage computed, s.
    pub stage_seconds: f64,
    /// Invocations of the driver (1 + resumes).
    pub runs: usize,
    /// The actuator verdict on the final kinematics and what
    /// `kinematics.json` flies (once the run is over).
    #[serde(default)]
    pub actuator: Option<ActuatorCheck>,
}

impl Summary {
    /// The file's text (pretty-printed: a person reads it).
    pub fn to_json(&self) -> Result<String, FormatError> {
        FORMAT.to_json(self, true)
    }

    /// Parses the text of a `summary.json` (its header first).
    pub fn from_json(text: &str) -> Result<Self, FormatError> {
        FORMAT.parse(text)
    }

    /// Reads the `summary.json` at `path`.
    pub fn read(path: &Path) -> Result<Self, ReadError> {
        FORMAT.read(path)
    }
}

impl SystemSummary {
    /// The summary of a system analysis record and its stage record.
    fn of(s: &SystemRecord, r: &StageRecord) -> Self {
        Self {
            ct: s.means.ct,
            cl: s.means.cl,
            cp: s.means.cp,
            efficiency: s.means.efficiency,
            ct_change_last_two_cycles: s.means.ct_change_last_two_cycles,
            tip_deflection_amplitude_m: s.tip_deflection_amplitude_m,
            wing_mass_kg: s.wing_mass_kg,
            seconds: r.seconds,
            run: r.run,
        }
    }
}

impl KinematicsSummary {
    /// The summary of an aerodynamic discipline record and its stage
    /// record.
    fn of(k: &KinematicRecord, r: &StageRecord) -> Self {
        Self {
            analysed_2d: k.result.initial.result.clone().ok(),
            chosen: k.chosen.clone(),
            proposed: k.proposed,
            proposed_2d: k.proposed_2d,
            evaluations_reused: k.evaluations_reused,
            adoption_margin: k.result.adoption_margin,
            section: k.result.section.clone(),
            seconds: r.seconds,
            run: r.run,
        }
    }
}

impl TopologySummary {
    /// The summary of a structural discipline record and its stage
    /// record.
    fn of(t: &TopologyRecord, r: &StageRecord) -> Self {
        Self {
            strain_energy_j: t
                .result
                .cycles
                .first()
                .map_or(f64::NAN, |c| c.strain_energy_j),
            final_strain_energy_j: t
                .result
                .cycles
                .last()
                .map_or(f64::NAN, |c| c.strain_energy_j),
            mass_fraction: t.mass_fraction,
            carbon_elements: t.result.carbon_elements(),
            elements_changed: t.elements_changed,
            eslso_cycles: t.result.cycles.len(),
            eslso_converged: t.result.converged,
            seconds: r.seconds,
            run: r.run,
        }
    }
}

/// Builds the summary of the run in `dir` from its `state`.
pub fn build(config: &SystemConfig, dir: &Path, state: &RunState) -> Result<Summary, DesignError> {
    let mut cycles = Vec::new();
    let mut previous_topology: Option<TopologyRecord> = None;
    for c in &state.cycles {
        let cycle = c.cycle;
        let system = match c.get(Stage::System) {
            Some(record) => Some((load_system(dir, cycle)?, record)),
            None => None,
        };
        let kinematics = match c.get(Stage::Kinematics) {
            Some(record) => Some((load_kinematics(dir, cycle)?, record)),
            None => None,
        };
        let topology = match c.get(Stage::Topology) {
            Some(record) => Some((load_topology(dir, cycle)?, record)),
            None => None,
        };
        let carbon_mass_fraction = match (&previous_topology, &topology) {
            (_, Some((t, _))) => t.analysed_mass_fraction,
            (Some(p), None) => p.mass_fraction,
            (None, None) => config.wing.carbon_fraction,
        };
        let analysed = system
            .as_ref()
            .map(|(s, _)| s.kinematics)
            .unwrap_or_else(|| config.kinematics());
        let seconds = [
            c.get(Stage::System),
            c.get(Stage::Kinematics),
            c.get(Stage::Topology),
        ]
        .iter()
        .flatten()
        .map(|r| r.seconds)
        .sum();
        cycles.push(CycleSummary {
            cycle,
            kinematics: analysed,
            carbon_mass_fraction,
            system: system.as_ref().map(|(s, r)| SystemSummary::of(s, r)),
            aerodynamic: kinematics
                .as_ref()
                .map(|(k, r)| KinematicsSummary::of(k, r)),
            structural: topology.as_ref().map(|(t, r)| TopologySummary::of(t, r)),
            change: match (&kinematics, &topology) {
                (Some((k, _)), Some((t, _))) => Some(change(config, k, t)),
                _ => None,
            },
            seconds,
        });
        previous_topology = topology.map(|(t, _)| t);
    }
    let point = |cycle: usize| -> Option<DesignPoint> {
        let c = cycles.iter().find(|c| c.cycle == cycle)?;
        let s = c.system.as_ref()?;
        Some(DesignPoint {
            cycle,
            kinematics: c.kinematics,
            carbon_mass_fraction: c.carbon_mass_fraction,
            ct: s.ct,
            cp: s.cp,
            efficiency: s.efficiency,
            wing_mass_kg: s.wing_mass_kg,
        })
    };
    let (outcome, converged_cycle, final_cycle) = match state.outcome {
        Some(Outcome::Converged { cycle }) => ("converged", Some(cycle), Some(cycle)),
        Some(Outcome::CycleCap { max_cycles }) => ("cycle cap reached", None, Some(max_cycles + 1)),
        None => ("unfinished", None, None),
    };
    let initial = point(1);
    let final_design = final_cycle.and_then(point);
    let actuator = match &final_design {
        Some(f) => Some(actuator_check(
            &cycle_vehicle(dir, config, f.cycle)?,
            &f.kinematics,
        )?),
        None => None,
    };
    let relative = |a: f64, b: f64| if a != 0.0 { b / a - 1.0 } else { f64::NAN };
    let comparison = match (&initial, &final_design) {
        (Some(i), Some(f)) => Some(Comparison {
            ct_relative_change: relative(i.ct, f.ct),
            cp_relative_change: relative(i.cp, f.cp),
            efficiency_relative_change: relative(i.efficiency, f.efficiency),
            wing_mass_relative_change: relative(i.wing_mass_kg, f.wing_mass_kg),
        }),
        _ => None,
    };
    Ok(Summary {
        format: FORMAT.format.to_string(),
        format_version: FORMAT.version,
        finished: state.outcome.is_some(),
        outcome: outcome.to_string(),
        converged_cycle,
        max_cycles: config.mdois.max_cycles,
        kinematics_tolerance_of_range: config.mdois.kinematics_tolerance,
        layout_tolerance: config.mdois.layout_tolerance,
        stage_seconds: cycles.iter().map(|c| c.seconds).sum(),
        cycles,
        initial,
        final_design,
        comparison,
        runs: state.runs.len(),
        actuator,
    })
}
