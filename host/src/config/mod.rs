//! The design file (TOML): the wing, its kinematics, the flight
//! condition, the system analysis and the two disciplines' and the cycle
//! loop's settings — every table's type, every key declared once with its
//! unit, range and doc ([`fwav_settings`]), the checks those declarations
//! drive, the conversions to the solvers' own settings, and `fwav init`'s
//! commented template. Every key is optional with the built-in FWAV's
//! value as default; units are in the key names, angles in degrees
//! (people type them).
//!
//! ```toml
//! [wing]
//! semi_span_m = 0.15
//! carbon_fraction = 0.3
//! [kinematics]
//! frequency_hz = 11.0
//! amplitude_deg = 30.0
//! [analysis]
//! cycles = 4
//! [topology]
//! mass_fraction = 0.3
//! [mdois]
//! max_cycles = 5
//! ```
//!
//! - [`wing`], [`kinematics`], [`flight`], [`analysis`], [`design`],
//!   [`topology`], [`mdois`], [`actuator`]: one table each, its type and
//!   declarations.
//! - [`template`]: the commented file (`fwav init`, a run's
//!   `config.toml`).
//! - [`cost`]: a design run's memory and time, estimated before it starts.
//! - [`keys`]: every declared key by its qualified name (`wing.semi_span_m`),
//!   for files that name design keys from outside (a study's variations).
//!
//! This room sits above the solvers: it may import [`crate::aeroelastic`],
//! [`crate::shell`], [`crate::discipline`], [`crate::topology`] and
//! [`crate::vehicle`] (their settings types), and only [`crate::mdois`],
//! [`crate::study`] and the program import it;
//! no solver module imports from here.

pub mod actuator;
pub mod analysis;
pub mod cost;
pub mod design;
pub mod flight;
pub mod keys;
pub mod kinematics;
pub mod mdois;
pub mod template;
pub mod topology;
pub mod wing;

use fwav_settings::{SettingError, Shown};
use serde::{Deserialize, Serialize};

use crate::aero2d::viscous::{ViscousError, TRAILING_EDGE_LAYER};
use crate::aeroelastic::analysis::SystemSettings;
use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::aeroelastic::model::{FlightCondition, WingModel, WingModelError};
use crate::discipline::kinematic::DesignSpace;
use crate::discipline::section::{EvaluationError, SectionCase};
use crate::shell::material::Layer;
use crate::shell::wing::Planform;

pub use actuator::ActuatorConfig;
pub use design::DesignConfig;
pub use flight::FlightConfig;
pub use mdois::MdoisConfig;
pub use topology::TopologyConfig;
pub use wing::WingConfig;

/// Why a configuration was refused.
#[derive(Debug, thiserror::Error)]
pub enum ConfigError {
    /// Not TOML or an unknown/mistyped field (the message names it).
    #[error("{0}")]
    Parse(#[from] toml::de::Error),
    /// A key no table declares (in the tables the TOML parser cannot
    /// check itself, see [`design`]).
    #[error("unknown field `{table}.{key}`, expected one of {expected}")]
    Unknown {
        /// The table.
        table: &'static str,
        /// The key given.
        key: String,
        /// The table's keys, listed.
        expected: String,
    },
    /// A value outside its declared range (the message names the field as
    /// `table.key`, its value and the range).
    #[error(transparent)]
    Range(#[from] SettingError),
    /// A word that is not one of a choice's (checked before serde, which
    /// names no key inside a flattened table).
    #[error("{table}.{key} = {value} is not one of {allowed}")]
    Choice {
        /// The table.
        table: &'static str,
        /// The key.
        key: &'static str,
        /// The value given, as TOML.
        value: String,
        /// The words allowed.
        allowed: String,
    },
    /// The wing could not be built.
    #[error(transparent)]
    Wing(#[from] WingModelError),
    /// Planform keys that do not fit together.
    #[error(transparent)]
    Planform(#[from] wing::PlanformConflict),
    /// A level key of `[design]` without three levels.
    #[error(
        "design.{key} has {found} levels; the L18 array takes exactly three (low, initial, high)"
    )]
    Levels {
        /// The key.
        key: &'static str,
        /// The levels given.
        found: usize,
    },
    /// Both weights of the combined objective are 0.
    #[error(
        "design.thrust_weight and design.efficiency_weight are both 0: the combined objective \
         would be 0 for every design; give at least one a positive weight"
    )]
    NoObjective,
    /// The structural discipline would sample its load cases less often
    /// than once a period of the system analysis's pressure history.
    #[error(
        "topology.sample_every = {sample_every} is more than analysis.steps_per_cycle = \
         {steps_per_cycle}: the structural discipline takes one load case every sample_every \
         steps of the last pressure period, which has steps_per_cycle steps; set \
         topology.sample_every to at most {steps_per_cycle} (a divisor of it spaces the load \
         cases evenly) or raise analysis.steps_per_cycle"
    )]
    SampleEvery {
        /// `topology.sample_every`.
        sample_every: usize,
        /// `analysis.steps_per_cycle`.
        steps_per_cycle: usize,
    },
    /// A flapping frequency so low for the flight speed and the mid-span
    /// chord that each 2D analysis of the aerodynamic discipline would
    /// take too many steps (a period of hundreds of chords).
    #[error(
        "{key} = {frequency_hz} Hz at flight.speed_m_s = {speed_m_s}: the mid-span section \
         ({chord_m} m chord) flaps at reduced frequency {reduced_frequency:.4}, a period of \
         {period_chords:.0} chords, so each 2D analysis of the aerodynamic discipline would \
         take {steps} time steps (at most {max}); set {key} to at least \
         {min_frequency_hz} Hz or lower flight.speed_m_s"
    )]
    SectionWork {
        /// The key of the lowest frequency analysed
        /// (`kinematics.frequency_hz` or `design.frequency_hz`).
        key: &'static str,
        /// That frequency, Hz.
        frequency_hz: f64,
        /// `flight.speed_m_s`.
        speed_m_s: f64,
        /// The mid-span chord, m.
        chord_m: f64,
        /// The reduced frequency `pi f c / U`.
        reduced_frequency: f64,
        /// The period, chords travelled.
        period_chords: f64,
        /// Steps an analysis would take.
        steps: usize,
        /// The most allowed.
        max: usize,
        /// The lowest frequency that fits, Hz, rounded up to 0.01
        /// ([`Shown::at_least`]: it passes as printed).
        min_frequency_hz: f64,
    },
    /// A flapping frequency so high for the flight speed and the
    /// mid-span chord that its reduced frequency is past the 2D section
    /// models' range ([`crate::aero2d::case::MAX_REDUCED_FREQUENCY`]).
    #[error(
        "{key} = {frequency_hz} Hz at flight.speed_m_s = {speed_m_s}: the mid-span section \
         ({chord_m} m chord) flaps at reduced frequency {reduced_frequency:.4} (k = pi f c / U), \
         past the 2D section models' {max}: the flight is nearly hover for this flapping, and \
         the aerodynamic discipline's models scale the flow by the flight speed; set {key} to at \
         most {max_frequency_hz} Hz or flight.speed_m_s to at least {min_speed_m_s} m/s"
    )]
    SectionBeyondModels {
        /// The key of the highest frequency analysed
        /// (`kinematics.frequency_hz` or `design.frequency_hz`).
        key: &'static str,
        /// That frequency, Hz.
        frequency_hz: f64,
        /// `flight.speed_m_s`.
        speed_m_s: f64,
        /// The mid-span chord, m.
        chord_m: f64,
        /// The reduced frequency `pi f c / U`.
        reduced_frequency: f64,
        /// The most the models take.
        max: f64,
        /// The highest frequency that fits, Hz, rounded down to 0.01
        /// ([`Shown::at_most`]: it passes as printed).
        max_frequency_hz: f64,
        /// The lowest flight speed that fits, m/s, rounded up to 0.001.
        min_speed_m_s: f64,
    },
    /// `design.section_model = "ns"` at a mid-span Reynolds number its
    /// grid cannot resolve ([`crate::aero2d::viscous::TRAILING_EDGE_LAYER`]).
    #[error(
        "design.section_model = \"ns\" at flight.speed_m_s = {speed_m_s}: the mid-span section \
         ({chord_m} m chord) flies at Re {reynolds:.0}, and the Navier–Stokes model's grid has \
         wall cells of {cell:.2e} chords, longer than the laminar boundary layer is thick at the \
         trailing edge ({layer:.2e}): it cannot resolve that flow (it can up to Re \
         {max_reynolds:.0}); lower flight.speed_m_s or the chord, or set design.section_model = \
         \"ldvm\""
    )]
    SectionUnresolved {
        /// `flight.speed_m_s`.
        speed_m_s: f64,
        /// The mid-span chord, m.
        chord_m: f64,
        /// The section's Reynolds number.
        reynolds: f64,
        /// The grid's longest wall cell, chords.
        cell: f64,
        /// The boundary layer's thickness at the trailing edge, chords.
        layer: f64,
        /// The highest Reynolds number the grid resolves.
        max_reynolds: f64,
    },
}

/// The whole file.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SystemConfig {
    /// The wing.
    pub wing: WingConfig,
    /// Its flapping kinematics.
    pub kinematics: FlappingKinematics,
    /// The flight condition.
    pub flight: FlightConfig,
    /// Solver settings.
    pub analysis: SystemSettings,
    /// The kinematic optimization.
    pub design: DesignConfig,
    /// The structural discipline (ESLSO).
    pub topology: TopologyConfig,
    /// The MDOIS cycle loop (cycle cap, "unchanged" tolerances).
    pub mdois: MdoisConfig,
    /// The flapping drive (motor, gearbox, battery, spring, limits).
    pub actuator: ActuatorConfig,
}

impl SystemConfig {
    /// Parses and checks a TOML text.
    pub fn from_toml(text: &str) -> Result<Self, ConfigError> {
        let config = Self::parse_unchecked(text)?;
        config.check()?;
        Ok(config)
    }

    /// Parses a TOML text, its keys and types, without checking the
    /// values against their ranges ([`Self::check`]): for a run's own
    /// `config.toml`, which an earlier fwav may have accepted with a
    /// value this one refuses.
    pub fn parse_unchecked(text: &str) -> Result<Self, ConfigError> {
        // The [design] table's keys first: its levels are flattened, and
        // serde's own complaint about them names no key.
        design::check_keys(&toml::from_str(text)?)?;
        Ok(toml::from_str(text)?)
    }

    /// Checks every key against its declared range, table by table in
    /// the file's order (the first key outside is the error), then the
    /// keys that must fit together (the planform, the objective's weights,
    /// `topology.sample_every` within `analysis.steps_per_cycle`, the
    /// section analysis's work at the lowest frequency and its reach at
    /// the highest, the section's Reynolds number for the viscous model).
    pub fn check(&self) -> Result<(), ConfigError> {
        wing::WING.check(&self.wing)?;
        kinematics::KINEMATICS.check(&self.kinematics)?;
        flight::FLIGHT.check(&self.flight)?;
        analysis::ANALYSIS.check(&self.analysis)?;
        design::DESIGN.check(&self.design)?;
        topology::TOPOLOGY.check(&self.topology)?;
        topology::check_sampling(&self.topology, &self.analysis)?;
        mdois::MDOIS.check(&self.mdois)?;
        actuator::ACTUATOR.check(&self.actuator)?;
        wing::check_planform(&self.wing)?;
        design::check_weights(&self.design)?;
        self.check_section_frequencies()?;
        self.check_section_resolution()?;
        Ok(())
    }

    /// Refuses `section_model = "ns"` at a Reynolds number its grid
    /// cannot resolve ([`SectionCase::check_resolution`]).
    fn check_section_resolution(&self) -> Result<(), ConfigError> {
        let case = self.section_case();
        match case.check_resolution() {
            Err(EvaluationError::Viscous(ViscousError::Unresolved {
                reynolds,
                cell,
                layer,
                ..
            })) => Err(ConfigError::SectionUnresolved {
                speed_m_s: case.flight.speed,
                chord_m: case.chord,
                reynolds,
                cell,
                layer,
                max_reynolds: (TRAILING_EDGE_LAYER / cell).powi(2),
            }),
            // A plate the map refuses is out of `design.ns_thickness`'s
            // range, which the settings table has refused above.
            _ => Ok(()),
        }
    }

    /// Refuses frequencies the aerodynamic discipline's 2D analyses cannot
    /// take. The discipline analyses the initial frequency and its
    /// candidates, which lie between the lowest and the highest level: at
    /// the lower of the initial frequency and the lowest level an analysis
    /// must end (a period of hundreds of chords would not), and at the
    /// higher of it and the highest level the section's reduced frequency
    /// must stay within the 2D models' reach.
    fn check_section_frequencies(&self) -> Result<(), ConfigError> {
        let case = self.section_case();
        let levels = &self.design.space.frequency_hz;
        let initial = ("kinematics.frequency_hz", self.kinematics.frequency);
        let lowest = levels[0];
        let (key, frequency_hz) = if initial.1 <= lowest {
            initial
        } else {
            ("design.frequency_hz (lowest level)", lowest)
        };
        if let Err(EvaluationError::TooManySteps {
            reduced_frequency,
            steps,
            max,
            min_frequency_hz,
            ..
        }) = case.check_work(frequency_hz)
        {
            return Err(ConfigError::SectionWork {
                key,
                frequency_hz,
                speed_m_s: case.flight.speed,
                chord_m: case.chord,
                reduced_frequency,
                period_chords: std::f64::consts::PI / reduced_frequency,
                steps,
                max,
                min_frequency_hz: Shown::at_least(min_frequency_hz, 2).0,
            });
        }
        let highest = levels[levels.len() - 1];
        let (key, frequency_hz) = if initial.1 >= highest {
            initial
        } else {
            ("design.frequency_hz (highest level)", highest)
        };
        if let Err(EvaluationError::BeyondModels {
            reduced_frequency,
            max,
            max_frequency_hz,
            ..
        }) = case.check_work(frequency_hz)
        {
            return Err(ConfigError::SectionBeyondModels {
                key,
                frequency_hz,
                speed_m_s: case.flight.speed,
                chord_m: case.chord,
                reduced_frequency,
                max,
                max_frequency_hz: Shown::at_most(max_frequency_hz, 2).0,
                min_speed_m_s: Shown::at_least(case.flight.speed * reduced_frequency / max, 3).0,
            });
        }
        Ok(())
    }

    /// The mid-span section the aerodynamic discipline analyses (chord
    /// and radius at half the semi-span, the flight condition, the
    /// critical LESP, the flow model; rigid until a system analysis gives
    /// its deformation).
    pub fn section_case(&self) -> SectionCase {
        let planform = self.planform();
        let radius = 0.5 * planform.semi_span;
        SectionCase {
            chord: planform.chord(radius),
            radius,
            flight: self.flight(),
            lesp_critical: self.design.lesp(),
            model: self.design.flow_model(),
            cycles: self.design.section_cycles,
            ..SectionCase::fwav_mid_span()
        }
    }

    /// The planform.
    pub fn planform(&self) -> Planform {
        self.wing.planform()
    }

    /// The wing model at the uniform starting design (paper's materials).
    pub fn wing_model(&self) -> Result<WingModel, ConfigError> {
        self.wing_model_with(None)
    }

    /// The wing model with carbon `densities` per element (a layout of the
    /// structural discipline), or the uniform starting design for `None`.
    pub fn wing_model_with(&self, densities: Option<&[f64]>) -> Result<WingModel, ConfigError> {
        Ok(WingModel::new(
            self.planform(),
            &Layer::CARBON,
            &Layer::MYLAR,
            densities,
            self.wing.carbon_fraction,
        )?)
    }

    /// The initial kinematics (SI).
    pub fn kinematics(&self) -> FlappingKinematics {
        self.kinematics
    }

    /// The kinematic design space (a copy of `design.space`).
    pub fn design_space(&self) -> DesignSpace {
        self.design.space.clone()
    }

    /// The flight condition in SI.
    pub fn flight(&self) -> FlightCondition {
        self.flight.condition()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_and_errors_name_the_field() {
        let c = SystemConfig::from_toml("").unwrap();
        assert_eq!(c.planform(), Planform::FWAV);
        let (k, i) = (c.kinematics(), FlappingKinematics::INITIAL);
        assert!((k.amplitude - i.amplitude).abs() < 1e-15 && k.frequency == i.frequency);
        let e = SystemConfig::from_toml("[kinematics]\nfrequency_hz = -3\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "kinematics.frequency_hz = -3 is outside [0.1, 200] Hz"
        );
        let e = SystemConfig::from_toml("[wing]\nspan = 3\n").unwrap_err();
        assert!(e.to_string().contains("span"), "{e}");
        let e = SystemConfig::from_toml("[analysis]\ncycles = \"four\"\n").unwrap_err();
        assert!(e.to_string().contains("cycles"), "{e}");
        let e = SystemConfig::from_toml("[design]\nfrequency = [1, 2, 3]\n").unwrap_err();
        assert!(
            e.to_string()
                .starts_with("unknown field `design.frequency`, expected one of"),
            "{e}"
        );
        let e = SystemConfig::from_toml("[design]\namplitude_deg = [40, 30, 20]\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "design.amplitude_deg = [40, 30, 20] must be increasing, each in (0, 80] deg"
        );
        // A level that does not flap: its six L18 rows have no efficiency.
        let e = SystemConfig::from_toml("[design]\namplitude_deg = [0, 1, 2]\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "design.amplitude_deg = [0, 1, 2] must be increasing, each in (0, 80] deg"
        );
    }

    /// A flight nearly in hover for its flapping is refused naming two
    /// levers, each of which passes as printed (rounded toward the
    /// allowed side: 0.1225 m/s is suggested as 0.123, not 0.122).
    #[test]
    fn a_flight_nearly_in_hover_names_levers_that_pass() {
        let e = SystemConfig::from_toml("[flight]\nspeed_m_s = 0.1\n").unwrap_err();
        let ConfigError::SectionBeyondModels {
            max_frequency_hz,
            min_speed_m_s,
            ..
        } = e
        else {
            panic!("{e}")
        };
        let text = e.to_string();
        assert!(
            text.contains(&format!("at most {max_frequency_hz} Hz"))
                && text.contains(&format!("at least {min_speed_m_s} m/s")),
            "{text}"
        );
        SystemConfig::from_toml(&format!("[flight]\nspeed_m_s = {min_speed_m_s}\n")).unwrap();
        SystemConfig::from_toml(&format!(
            "[flight]\nspeed_m_s = 0.1\n[kinematics]\nfrequency_hz = 9.0\n\
             [design]\nfrequency_hz = [8.0, 9.0, {max_frequency_hz}]\n"
        ))
        .unwrap();
    }

    /// A partial `[design]` table keeps the other levels and weights.
    #[test]
    fn a_partial_design_table_keeps_the_defaults() {
        let c =
            SystemConfig::from_toml("[design]\nfrequency_hz = [10, 11, 12]\nseed = 7\n").unwrap();
        let d = DesignConfig::default();
        assert_eq!(c.design.space.frequency_hz, [10.0, 11.0, 12.0]);
        assert_eq!(c.design.space.amplitude_deg, d.space.amplitude_deg);
        assert_eq!((c.design.seed, c.design.thrust_weight), (7, 1.0));
    }
}
