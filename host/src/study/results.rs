//! A study's results: each case's final design as its own `summary.json`
//! says (the final kinematics, 3D CT, CP and efficiency, wing mass,
//! carbon fraction, actuator margins, converged or not, time), beside
//! the values of the varied keys its `config.toml` holds; and the outputs
//! a study can plot ([`Output`]). Reads files; writes nothing (the files
//! people read are drawn by [`super::output`]).

use std::path::Path;

use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::mdois::profile::ActuatorCheck;
use crate::mdois::summary::Summary;

use super::state::{CaseRecord, CaseStatus, StudyState};

/// A number a finished case gives, to tabulate and plot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// Final flapping frequency, Hz.
    FrequencyHz,
    /// Final amplitude, deg.
    AmplitudeDeg,
    /// Final mean angle, deg.
    MeanAngleDeg,
    /// Final stroke plane, deg.
    StrokePlaneDeg,
    /// 3D mean thrust coefficient of the final design.
    Ct,
    /// 3D mean power coefficient.
    Cp,
    /// 3D propulsive efficiency.
    Efficiency,
    /// Half-wing mass, kg.
    WingMassKg,
    /// Carbon mass fraction of the final layout.
    CarbonMassFraction,
    /// Motor torque margin (fraction of the stall torque).
    TorqueMargin,
    /// Motor current margin (fraction of the current limit).
    CurrentMargin,
    /// Terminal voltage margin (fraction of the bridge's reach).
    VoltageMargin,
    /// Summed wall time of the design's stages, s.
    Seconds,
}

impl Output {
    /// Every output, in `results.csv`'s order.
    pub const ALL: [Output; 13] = [
        Output::FrequencyHz,
        Output::AmplitudeDeg,
        Output::MeanAngleDeg,
        Output::StrokePlaneDeg,
        Output::Ct,
        Output::Cp,
        Output::Efficiency,
        Output::WingMassKg,
        Output::CarbonMassFraction,
        Output::TorqueMargin,
        Output::CurrentMargin,
        Output::VoltageMargin,
        Output::Seconds,
    ];

    /// The outputs plotted when the study file names none.
    pub const DEFAULT: [Output; 4] = [
        Output::Ct,
        Output::Efficiency,
        Output::WingMassKg,
        Output::FrequencyHz,
    ];

    /// Its column name in `results.csv` and in the study file.
    pub fn name(self) -> &'static str {
        match self {
            Output::FrequencyHz => "frequency_hz",
            Output::AmplitudeDeg => "amplitude_deg",
            Output::MeanAngleDeg => "mean_angle_deg",
            Output::StrokePlaneDeg => "stroke_plane_deg",
            Output::Ct => "ct",
            Output::Cp => "cp",
            Output::Efficiency => "efficiency",
            Output::WingMassKg => "wing_mass_kg",
            Output::CarbonMassFraction => "carbon_mass_fraction",
            Output::TorqueMargin => "torque_margin",
            Output::CurrentMargin => "current_margin",
            Output::VoltageMargin => "voltage_margin",
            Output::Seconds => "seconds",
        }
    }

    /// What it is, for a plot's axis.
    pub fn label(self) -> &'static str {
        match self {
            Output::FrequencyHz => "final frequency, Hz",
            Output::AmplitudeDeg => "final amplitude, deg",
            Output::MeanAngleDeg => "final mean angle, deg",
            Output::StrokePlaneDeg => "final stroke plane, deg",
            Output::Ct => "3D thrust coefficient CT",
            Output::Cp => "3D power coefficient CP",
            Output::Efficiency => "3D propulsive efficiency",
            Output::WingMassKg => "half-wing mass, kg",
            Output::CarbonMassFraction => "carbon mass fraction",
            Output::TorqueMargin => "motor torque margin",
            Output::CurrentMargin => "motor current margin",
            Output::VoltageMargin => "terminal voltage margin",
            Output::Seconds => "design time (stages summed), s",
        }
    }

    /// The output of this name.
    pub fn named(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|o| o.name() == name)
    }

    /// Every output's name.
    pub fn names() -> Vec<&'static str> {
        Self::ALL.iter().map(|o| o.name()).collect()
    }

    /// Its value for a final design (`None`: not known, as a margin
    /// without the actuator's verdict).
    pub fn of(self, d: &FinalDesign) -> Option<f64> {
        let margin = |quantity: &str| {
            d.actuator.as_ref().and_then(|a| {
                a.margins
                    .iter()
                    .find(|m| m.quantity == quantity)
                    .map(|m| m.margin)
            })
        };
        match self {
            Output::FrequencyHz => Some(d.kinematics.frequency),
            Output::AmplitudeDeg => Some(d.kinematics.amplitude_deg()),
            Output::MeanAngleDeg => Some(d.kinematics.mean_angle_deg()),
            Output::StrokePlaneDeg => Some(d.kinematics.stroke_plane_deg()),
            Output::Ct => Some(d.ct),
            Output::Cp => Some(d.cp),
            Output::Efficiency => Some(d.efficiency),
            Output::WingMassKg => Some(d.wing_mass_kg),
            Output::CarbonMassFraction => Some(d.carbon_mass_fraction),
            Output::TorqueMargin => margin("motor torque"),
            Output::CurrentMargin => margin("motor current"),
            Output::VoltageMargin => margin("terminal voltage"),
            Output::Seconds => Some(d.seconds),
        }
    }
}

/// A finished case's final design, from its `summary.json`.
#[derive(Clone, Debug, PartialEq)]
pub struct FinalDesign {
    /// The final kinematics.
    pub kinematics: FlappingKinematics,
    /// 3D mean thrust coefficient.
    pub ct: f64,
    /// 3D mean power coefficient.
    pub cp: f64,
    /// 3D propulsive efficiency.
    pub efficiency: f64,
    /// Half-wing mass, kg.
    pub wing_mass_kg: f64,
    /// Carbon mass fraction.
    pub carbon_mass_fraction: f64,
    /// Whether the design converged (else it reached its cycle cap).
    pub converged: bool,
    /// The cycle whose analysis is the final design.
    pub final_cycle: usize,
    /// The actuator's verdict on the final kinematics.
    pub actuator: Option<ActuatorCheck>,
    /// Summed wall time of the stages, s.
    pub seconds: f64,
}

impl FinalDesign {
    /// The final design of a finished run's summary (`None`: unfinished).
    pub fn of(summary: &Summary) -> Option<Self> {
        let f = summary.final_design.as_ref().filter(|_| summary.finished)?;
        Some(Self {
            kinematics: f.kinematics,
            ct: f.ct,
            cp: f.cp,
            efficiency: f.efficiency,
            wing_mass_kg: f.wing_mass_kg,
            carbon_mass_fraction: f.carbon_mass_fraction,
            converged: summary.converged_cycle.is_some(),
            final_cycle: f.cycle,
            actuator: summary.actuator.clone(),
            seconds: summary.stage_seconds,
        })
    }
}

/// One case's row.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseResult {
    /// Its number.
    pub number: usize,
    /// Its directory name (`003`).
    pub name: String,
    /// Its status in the study.
    pub status: CaseStatus,
    /// The varied keys' values in its configuration, in the study's key
    /// order (a key a listed case does not set holds the base's value).
    pub values: Vec<(String, toml::Value)>,
    /// The final design, if finished.
    pub design: Option<FinalDesign>,
    /// Why it failed, if it did.
    pub error: Option<String>,
}

/// The value of `table.key` in a TOML table.
fn lookup(table: &toml::Table, qualified: &str) -> Option<toml::Value> {
    let (t, k) = qualified.split_once('.')?;
    table.get(t)?.as_table()?.get(k).cloned()
}

/// One case's result: its `summary.json` (if finished) and its
/// configuration's values of the `keys`.
pub fn case_result(dir: &Path, record: &CaseRecord, keys: &[String]) -> CaseResult {
    let case_dir = dir.join(&record.dir);
    let config: Option<toml::Table> = std::fs::read_to_string(case_dir.join("config.toml"))
        .ok()
        .and_then(|t| toml::from_str(&t).ok());
    let values = keys
        .iter()
        .filter_map(|k| {
            config
                .as_ref()
                .and_then(|c| lookup(c, k))
                .or_else(|| record.values.get(k).cloned())
                .map(|v| (k.clone(), v))
        })
        .collect();
    let design = Summary::read(&case_dir.join("summary.json"))
        .ok()
        .and_then(|s| FinalDesign::of(&s));
    CaseResult {
        number: record.case,
        name: record
            .dir
            .rsplit('/')
            .next()
            .unwrap_or(&record.dir)
            .to_string(),
        status: record.status,
        values,
        design,
        error: record.error.clone(),
    }
}

/// Every case's result, in case order.
pub fn collect(dir: &Path, state: &StudyState) -> Vec<CaseResult> {
    state
        .cases
        .iter()
        .map(|r| case_result(dir, r, &state.keys))
        .collect()
}
