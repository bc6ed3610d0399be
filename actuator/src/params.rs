//! The plant's parameters, read from TOML (`actuator/plant.toml` documents
//! every default): the actuator's physics (motor, supply, transmission,
//! wing) and what a simulation of it adds (sensors, time stepping). SI
//! units; every field is checked with an error that names it. Imports
//! nothing of this crate.

use serde::{Deserialize, Serialize};

/// Why a parameter file was refused.
#[derive(Debug, thiserror::Error)]
pub enum ConfigError {
    /// Not TOML, or an unknown or mistyped key (with line and column).
    #[error("{0}")]
    Toml(#[from] toml::de::Error),
    /// A value outside its allowed range.
    #[error("{field} = {value} is outside {range}")]
    OutOfRange {
        /// The key, e.g. `motor.resistance_ohm`.
        field: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range, for people.
        range: &'static str,
    },
}

/// The H-bridge model.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PwmModel {
    /// Average voltage over a PWM period (fast).
    #[default]
    Averaged,
    /// Resolve each PWM period's switching (needs substeps well below the
    /// PWM period).
    Switching,
}

/// DC motor.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Motor {
    /// Winding resistance, ohm.
    pub resistance_ohm: f64,
    /// Winding inductance, H.
    pub inductance_h: f64,
    /// Torque constant = back-EMF constant, N m/A.
    pub torque_constant_nm_per_a: f64,
    /// Rotor inertia, kg m^2.
    pub rotor_inertia_kg_m2: f64,
    /// Coulomb friction at the motor shaft, N m.
    pub coulomb_friction_nm: f64,
    /// Viscous friction at the motor shaft, N m s/rad.
    pub viscous_friction_nms_per_rad: f64,
}

/// Battery and bridge.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Supply {
    /// Open-circuit battery voltage, V.
    pub battery_v: f64,
    /// Battery internal resistance, ohm.
    pub internal_resistance_ohm: f64,
    /// Bridge model.
    #[serde(default)]
    pub pwm: PwmModel,
    /// PWM frequency for the switching model, Hz.
    pub pwm_hz: f64,
}

/// Gearbox and spring.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Transmission {
    /// Motor turns per flapping-axis turn.
    pub gear_ratio: f64,
    /// Gearbox efficiency in (0, 1].
    pub efficiency: f64,
    /// Torsional spring about the flapping axis, N m/rad.
    pub spring_nm_per_rad: f64,
}

/// The wing.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Wing {
    /// Inertia of the wing (and linkage) about the flapping axis, kg m^2.
    pub inertia_kg_m2: f64,
    /// Span from the flapping axis to the tip, m.
    pub span_m: f64,
    /// Chord at the root, m.
    pub root_chord_m: f64,
    /// Chord at the tip (linear taper), m.
    pub tip_chord_m: f64,
    /// Air density, kg/m^3.
    pub air_density_kg_m3: f64,
    /// Drag coefficient of the wing normal to the flow.
    pub drag_coefficient: f64,
}

impl Wing {
    /// Number of blade elements of the aerodynamic integral.
    pub const BLADE_ELEMENTS: usize = 200;

    /// `c_a = 1/2 rho C_D int_0^R c(r) r^3 dr` by the midpoint rule over
    /// [`Wing::BLADE_ELEMENTS`] strips, N m s^2.
    pub fn aero_damping(&self) -> f64 {
        let n = Self::BLADE_ELEMENTS;
        let dr = self.span_m / n as f64;
        let integral: f64 = (0..n)
            .map(|k| {
                let r = (k as f64 + 0.5) * dr;
                let chord =
                    self.root_chord_m + (self.tip_chord_m - self.root_chord_m) * r / self.span_m;
                chord * r * r * r * dr
            })
            .sum();
        0.5 * self.air_density_kg_m3 * self.drag_coefficient * integral
    }
}

/// Sensors.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sensors {
    /// Encoder counts per revolution of the flapping axis.
    pub encoder_counts_per_rev: u32,
    /// Standard deviation of the current sensor's noise, A.
    pub current_noise_a: f64,
    /// Offset of the current sensor, A.
    pub current_offset_a: f64,
    /// Seed of the noise (recorded in results).
    pub seed: u64,
}

/// Time stepping.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Simulation {
    /// Control rate of the flight controller, Hz.
    pub control_hz: f64,
    /// Plant RK4 steps per control period (>= 10).
    pub substeps: u32,
}

/// Everything about the simulated actuator.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlantParams {
    /// DC motor.
    pub motor: Motor,
    /// Battery and bridge.
    pub supply: Supply,
    /// Gearbox and spring.
    pub transmission: Transmission,
    /// Wing.
    pub wing: Wing,
    /// Sensors.
    pub sensors: Sensors,
    /// Time stepping.
    pub simulation: Simulation,
}

/// The documented default plant (the file shipped as `actuator/plant.toml`).
pub const DEFAULT_PLANT_TOML: &str = include_str!("../plant.toml");

impl Default for PlantParams {
    fn default() -> Self {
        // The shipped file is tested to parse and validate.
        Self::from_toml(DEFAULT_PLANT_TOML).unwrap_or_else(|e| panic!("actuator/plant.toml: {e}"))
    }
}

impl PlantParams {
    /// Parses and checks a TOML text.
    pub fn from_toml(text: &str) -> Result<Self, ConfigError> {
        let p: Self = toml::from_str(text)?;
        p.validate()?;
        Ok(p)
    }

    /// Checks every value's range.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let positive = "(0, inf)";
        let checks: [(&'static str, f64, bool, &'static str); 20] = [
            (
                "motor.resistance_ohm",
                self.motor.resistance_ohm,
                self.motor.resistance_ohm > 0.0,
                positive,
            ),
            (
                "motor.inductance_h",
                self.motor.inductance_h,
                self.motor.inductance_h > 0.0,
                positive,
            ),
            (
                "motor.torque_constant_nm_per_a",
                self.motor.torque_constant_nm_per_a,
                self.motor.torque_constant_nm_per_a > 0.0,
                positive,
            ),
            (
                "motor.rotor_inertia_kg_m2",
                self.motor.rotor_inertia_kg_m2,
                self.motor.rotor_inertia_kg_m2 >= 0.0,
                "[0, inf)",
            ),
            (
                "motor.coulomb_friction_nm",
                self.motor.coulomb_friction_nm,
                self.motor.coulomb_friction_nm >= 0.0,
                "[0, inf)",
            ),
            (
                "motor.viscous_friction_nms_per_rad",
                self.motor.viscous_friction_nms_per_rad,
                self.motor.viscous_friction_nms_per_rad >= 0.0,
                "[0, inf)",
            ),
            (
                "supply.battery_v",
                self.supply.battery_v,
                self.supply.battery_v > 0.0,
                positive,
            ),
            (
                "supply.internal_resistance_ohm",
                self.supply.internal_resistance_ohm,
                self.supply.internal_resistance_ohm >= 0.0,
                "[0, inf)",
            ),
            (
                "supply.pwm_hz",
                self.supply.pwm_hz,
                self.supply.pwm_hz > 0.0,
                positive,
            ),
            (
                "transmission.gear_ratio",
                self.transmission.gear_ratio,
                self.transmission.gear_ratio > 0.0,
                positive,
            ),
            (
                "transmission.efficiency",
                self.transmission.efficiency,
                self.transmission.efficiency > 0.0 && self.transmission.efficiency <= 1.0,
                "(0, 1]",
            ),
            (
                "transmission.spring_nm_per_rad",
                self.transmission.spring_nm_per_rad,
                self.transmission.spring_nm_per_rad >= 0.0,
                "[0, inf)",
            ),
            (
                "wing.inertia_kg_m2",
                self.wing.inertia_kg_m2,
                self.wing.inertia_kg_m2 > 0.0,
                positive,
            ),
            (
                "wing.span_m",
                self.wing.span_m,
                self.wing.span_m > 0.0,
                positive,
            ),
            (
                "wing.root_chord_m",
                self.wing.root_chord_m,
                self.wing.root_chord_m > 0.0,
                positive,
            ),
            (
                "wing.tip_chord_m",
                self.wing.tip_chord_m,
                self.wing.tip_chord_m >= 0.0,
                "[0, inf)",
            ),
            (
                "wing.air_density_kg_m3",
                self.wing.air_density_kg_m3,
                self.wing.air_density_kg_m3 >= 0.0,
                "[0, inf)",
            ),
            (
                "wing.drag_coefficient",
                self.wing.drag_coefficient,
                self.wing.drag_coefficient >= 0.0,
                "[0, inf)",
            ),
            (
                "simulation.control_hz",
                self.simulation.control_hz,
                self.simulation.control_hz >= 100.0 && self.simulation.control_hz <= 100_000.0,
                "[100, 100000]",
            ),
            (
                "simulation.substeps",
                f64::from(self.simulation.substeps),
                self.simulation.substeps >= 10,
                "[10, inf) (RK4 at least 10x finer than control)",
            ),
        ];
        for (field, value, ok, range) in checks {
            // `ok` is false for NaN, since every comparison with NaN is.
            if !ok || !value.is_finite() {
                return Err(ConfigError::OutOfRange {
                    field,
                    value,
                    range,
                });
            }
        }
        if self.sensors.encoder_counts_per_rev < 4 {
            return Err(ConfigError::OutOfRange {
                field: "sensors.encoder_counts_per_rev",
                value: f64::from(self.sensors.encoder_counts_per_rev),
                range: "[4, inf)",
            });
        }
        // Written so that NaN fails.
        let noise_ok =
            self.sensors.current_noise_a >= 0.0 && self.sensors.current_noise_a.is_finite();
        if !noise_ok || !self.sensors.current_offset_a.is_finite() {
            return Err(ConfigError::OutOfRange {
                field: "sensors.current_noise_a",
                value: self.sensors.current_noise_a,
                range: "[0, inf)",
            });
        }
        Ok(())
    }

    /// Control period, s.
    pub fn control_dt(&self) -> f64 {
        1.0 / self.simulation.control_hz
    }
}
