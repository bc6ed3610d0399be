//! The design's configuration file (TOML): the wing, its kinematics, the
//! flight condition, the solver settings and the two disciplines', every field
//! optional with the built-in FWAV's value as default, units in the key
//! names, angles in degrees (people type them).
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

use serde::{Deserialize, Serialize};

use crate::shell::material::Layer;
use crate::shell::wing::Planform;

use super::analysis::SystemSettings;
use super::kinematics::FlappingKinematics;
use super::model::{FlightCondition, WingModel, WingModelError};

/// Why a configuration was refused.
#[derive(Debug, thiserror::Error)]
pub enum ConfigError {
    /// Not TOML or an unknown/mistyped field (the message names it).
    #[error("{0}")]
    Parse(String),
    /// A value out of range.
    #[error("{field} = {value} is outside {range}")]
    Range {
        /// The field, as `table.key`.
        field: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range.
        range: &'static str,
    },
    /// The wing could not be built.
    #[error(transparent)]
    Wing(#[from] WingModelError),
}

/// A key's value, its allowed range (inclusive) and how the error names
/// that range.
pub(crate) type RangeCheck = (&'static str, f64, f64, f64, &'static str);

/// Checks `(key, value, low, high, range text)` entries: the first value
/// outside its range, or not finite, is the error.
pub(crate) fn check_ranges(ranges: &[RangeCheck]) -> Result<(), ConfigError> {
    for &(field, value, low, high, range) in ranges {
        if !(value.is_finite() && (low..=high).contains(&value)) {
            return Err(ConfigError::Range {
                field,
                value,
                range,
            });
        }
    }
    Ok(())
}

/// The `[wing]` table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WingConfig {
    /// Semi-span, m.
    pub semi_span_m: f64,
    /// Root chord, m.
    pub root_chord_m: f64,
    /// Tip chord, m.
    pub tip_chord_m: f64,
    /// Leading-edge spar width, m.
    pub spar_width_m: f64,
    /// Root attachment length from the leading edge, m.
    pub root_attachment_m: f64,
    /// Shell elements along the span.
    pub span_elements: usize,
    /// Shell elements along the chord.
    pub chord_elements: usize,
    /// Uniform carbon density of the design layer, in [0, 1]. Default 1, the
    /// full carbon layer (first bending mode 26 Hz on the built-in wing);
    /// the topology's uniform starting density of 0.3 would put it at
    /// 16.8 Hz, so near the 11 Hz flapping that the wing's tip swings by
    /// more than its span in the small-deflection floating frame.
    pub carbon_fraction: f64,
}

impl Default for WingConfig {
    fn default() -> Self {
        let p = Planform::FWAV;
        Self {
            semi_span_m: p.semi_span,
            root_chord_m: p.root_chord,
            tip_chord_m: p.tip_chord,
            spar_width_m: p.spar_width,
            root_attachment_m: p.root_attachment,
            span_elements: p.span_elements,
            chord_elements: p.chord_elements,
            carbon_fraction: 1.0,
        }
    }
}

/// The `[kinematics]` table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct KinematicsConfig {
    /// Flapping frequency, Hz.
    pub frequency_hz: f64,
    /// Flapping amplitude, degrees.
    pub amplitude_deg: f64,
    /// Mean flapping angle, degrees.
    pub mean_angle_deg: f64,
    /// Stroke-plane inclination, degrees.
    pub stroke_plane_deg: f64,
}

impl Default for KinematicsConfig {
    /// [`FlappingKinematics::INITIAL`] in degrees as a person types them
    /// (11 Hz, ±30°, 0°, 90°; `to_degrees` of the radians would give
    /// 29.999999999999996°, which `fwav init` would then write).
    fn default() -> Self {
        Self {
            frequency_hz: FlappingKinematics::INITIAL.frequency,
            amplitude_deg: 30.0,
            mean_angle_deg: 0.0,
            stroke_plane_deg: 90.0,
        }
    }
}

/// The `[flight]` table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FlightConfig {
    /// Flight speed, m/s.
    pub speed_m_s: f64,
    /// Air density, kg/m³.
    pub density_kg_m3: f64,
}

impl Default for FlightConfig {
    fn default() -> Self {
        Self {
            speed_m_s: FlightCondition::FWAV.speed,
            density_kg_m3: FlightCondition::FWAV.density,
        }
    }
}

/// The `[design]` table: the kinematic optimization's levels (low,
/// initial, high) and the weights of its combined objective.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct DesignConfig {
    /// Flapping frequency levels, Hz.
    pub frequency_hz: [f64; 3],
    /// Flapping amplitude levels, degrees.
    pub amplitude_deg: [f64; 3],
    /// Mean flapping angle levels, degrees.
    pub mean_angle_deg: [f64; 3],
    /// Stroke-plane inclination levels, degrees.
    pub stroke_plane_deg: [f64; 3],
    /// Weight of the relative thrust gain in the combined objective.
    pub thrust_weight: f64,
    /// Weight of the relative efficiency gain.
    pub efficiency_weight: f64,
    /// Seed of the genetic algorithm.
    pub seed: u64,
}

impl Default for DesignConfig {
    fn default() -> Self {
        let s = crate::discipline::kinematic::DesignSpace::fwav();
        Self {
            frequency_hz: s.frequency_hz,
            amplitude_deg: s.amplitude_deg,
            mean_angle_deg: s.mean_angle_deg,
            stroke_plane_deg: s.stroke_plane_deg,
            thrust_weight: 1.0,
            efficiency_weight: 1.0,
            seed: 1,
        }
    }
}

/// The whole file.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SystemConfig {
    /// The wing.
    pub wing: WingConfig,
    /// Its flapping kinematics.
    pub kinematics: KinematicsConfig,
    /// The flight condition.
    pub flight: FlightConfig,
    /// Solver settings.
    pub analysis: SystemSettings,
    /// The kinematic optimization.
    pub design: DesignConfig,
    /// The structural discipline (ESLSO).
    pub topology: crate::topology::config::TopologyConfig,
    /// The MDOIS cycle loop (cycle cap, "unchanged" tolerances).
    pub mdois: crate::mdois::config::MdoisConfig,
}

impl SystemConfig {
    /// Parses and checks a TOML text.
    pub fn from_toml(text: &str) -> Result<Self, ConfigError> {
        let config: Self = toml::from_str(text).map_err(|e| ConfigError::Parse(e.to_string()))?;
        config.check()?;
        Ok(config)
    }

    /// Checks the ranges of every field: wing, kinematics, flight,
    /// analysis, design, topology and mdois.
    pub fn check(&self) -> Result<(), ConfigError> {
        let w = &self.wing;
        let k = &self.kinematics;
        let f = &self.flight;
        let ranges: [RangeCheck; 13] = [
            ("wing.semi_span_m", w.semi_span_m, 0.01, 2.0, "[0.01, 2] m"),
            (
                "wing.root_chord_m",
                w.root_chord_m,
                0.005,
                1.0,
                "[0.005, 1] m",
            ),
            (
                "wing.tip_chord_m",
                w.tip_chord_m,
                0.005,
                1.0,
                "[0.005, 1] m",
            ),
            (
                "wing.spar_width_m",
                w.spar_width_m,
                1e-4,
                0.1,
                "[0.0001, 0.1] m",
            ),
            (
                "wing.root_attachment_m",
                w.root_attachment_m,
                1e-4,
                1.0,
                "[0.0001, 1] m",
            ),
            (
                "wing.span_elements",
                w.span_elements as f64,
                2.0,
                400.0,
                "2..=400",
            ),
            (
                "wing.chord_elements",
                w.chord_elements as f64,
                2.0,
                200.0,
                "2..=200",
            ),
            (
                "wing.carbon_fraction",
                w.carbon_fraction,
                0.0,
                1.0,
                "[0, 1]",
            ),
            (
                "kinematics.frequency_hz",
                k.frequency_hz,
                0.1,
                200.0,
                "[0.1, 200] Hz",
            ),
            (
                "kinematics.amplitude_deg",
                k.amplitude_deg,
                0.0,
                80.0,
                "[0, 80] deg",
            ),
            (
                "kinematics.mean_angle_deg",
                k.mean_angle_deg,
                -60.0,
                60.0,
                "[-60, 60] deg",
            ),
            (
                "kinematics.stroke_plane_deg",
                k.stroke_plane_deg,
                0.0,
                180.0,
                "[0, 180] deg",
            ),
            ("flight.speed_m_s", f.speed_m_s, 0.1, 50.0, "[0.1, 50] m/s"),
        ];
        check_ranges(&ranges)?;
        self.check_analysis()?;
        let d = &self.design;
        let level_sets: [(&'static str, [f64; 3], f64, f64, &'static str); 4] = [
            (
                "design.frequency_hz",
                d.frequency_hz,
                0.1,
                200.0,
                "increasing, in [0.1, 200] Hz",
            ),
            (
                "design.amplitude_deg",
                d.amplitude_deg,
                0.0,
                80.0,
                "increasing, in [0, 80] deg",
            ),
            (
                "design.mean_angle_deg",
                d.mean_angle_deg,
                -60.0,
                60.0,
                "increasing, in [-60, 60] deg",
            ),
            (
                "design.stroke_plane_deg",
                d.stroke_plane_deg,
                0.0,
                180.0,
                "increasing, in [0, 180] deg",
            ),
        ];
        for (field, levels, low, high, range) in level_sets {
            let inside = levels
                .iter()
                .all(|v| v.is_finite() && (low..=high).contains(v));
            if !(inside && levels[0] < levels[1] && levels[1] < levels[2]) {
                return Err(ConfigError::Range {
                    field,
                    value: levels[0],
                    range,
                });
            }
        }
        for (field, w) in [
            ("design.thrust_weight", d.thrust_weight),
            ("design.efficiency_weight", d.efficiency_weight),
        ] {
            if !(w.is_finite() && (0.0..=100.0).contains(&w)) {
                return Err(ConfigError::Range {
                    field,
                    value: w,
                    range: "[0, 100]",
                });
            }
        }
        let rho = f.density_kg_m3;
        if !(rho.is_finite() && (0.01..=2000.0).contains(&rho)) {
            return Err(ConfigError::Range {
                field: "flight.density_kg_m3",
                value: rho,
                range: "[0.01, 2000] kg/m^3",
            });
        }
        self.topology.check()?;
        self.mdois.check()
    }

    /// The `[analysis]` ranges (those [`super::analysis::run`] accepts,
    /// named as `analysis.key`, so a design run is refused before it
    /// starts).
    fn check_analysis(&self) -> Result<(), ConfigError> {
        let a = &self.analysis;
        let ranges: [RangeCheck; 10] = [
            ("analysis.cycles", a.cycles as f64, 1.0, 100.0, "1..=100"),
            (
                "analysis.steps_per_cycle",
                a.steps_per_cycle as f64,
                8.0,
                2000.0,
                "8..=2000",
            ),
            (
                "analysis.chordwise_panels",
                a.chordwise_panels as f64,
                1.0,
                64.0,
                "1..=64",
            ),
            (
                "analysis.spanwise_panels",
                a.spanwise_panels as f64,
                1.0,
                200.0,
                "1..=200",
            ),
            (
                "analysis.coupling_tolerance",
                a.coupling_tolerance,
                1e-12,
                0.5,
                "[1e-12, 0.5]",
            ),
            (
                "analysis.max_subiterations",
                a.max_subiterations as f64,
                1.0,
                1000.0,
                "1..=1000",
            ),
            ("analysis.rho_inf", a.rho_inf, 0.0, 1.0, "[0, 1]"),
            (
                "analysis.free_wake_cycles",
                a.free_wake_cycles,
                0.0,
                100.0,
                "[0, 100] cycles",
            ),
            (
                "analysis.wake_cycles",
                a.wake_cycles,
                0.01,
                100.0,
                "[0.01, 100] cycles",
            ),
            (
                "analysis.core_radius_chords",
                a.core_radius_chords,
                1e-6,
                0.49,
                "[1e-6, 0.49] root chords",
            ),
        ];
        check_ranges(&ranges)
    }

    /// The planform.
    pub fn planform(&self) -> Planform {
        let w = &self.wing;
        Planform {
            semi_span: w.semi_span_m,
            root_chord: w.root_chord_m,
            tip_chord: w.tip_chord_m,
            spar_width: w.spar_width_m,
            root_attachment: w.root_attachment_m,
            span_elements: w.span_elements,
            chord_elements: w.chord_elements,
        }
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

    /// The kinematics in SI.
    pub fn kinematics(&self) -> FlappingKinematics {
        let k = &self.kinematics;
        FlappingKinematics {
            frequency: k.frequency_hz,
            amplitude: k.amplitude_deg.to_radians(),
            mean_angle: k.mean_angle_deg.to_radians(),
            stroke_plane: k.stroke_plane_deg.to_radians(),
        }
    }

    /// The kinematic design space.
    pub fn design_space(&self) -> crate::discipline::kinematic::DesignSpace {
        let d = &self.design;
        crate::discipline::kinematic::DesignSpace {
            frequency_hz: d.frequency_hz,
            amplitude_deg: d.amplitude_deg,
            mean_angle_deg: d.mean_angle_deg,
            stroke_plane_deg: d.stroke_plane_deg,
        }
    }

    /// The flight condition in SI.
    pub fn flight(&self) -> FlightCondition {
        FlightCondition {
            speed: self.flight.speed_m_s,
            density: self.flight.density_kg_m3,
        }
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
        assert!(e.to_string().contains("kinematics.frequency_hz"), "{e}");
        let e = SystemConfig::from_toml("[wing]\nspan = 3\n").unwrap_err();
        assert!(e.to_string().contains("span"), "{e}");
        let e = SystemConfig::from_toml("[analysis]\ncycles = \"four\"\n").unwrap_err();
        assert!(e.to_string().contains("cycles"), "{e}");
    }
}
