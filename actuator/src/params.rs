//! The plant's parameters, read from TOML (`actuator/plant.toml` documents
//! every default): the actuator's physics (motor, supply, transmission,
//! wing) and what a simulation of it adds (sensors, time stepping). SI
//! units; every field is checked with an error that names it. Imports
//! nothing of this crate.

use fwav_protocol::ParamId;
use fwav_settings::{Allowed, Integers, Interval, Setting, SettingError, Table, Value};
use serde::{Deserialize, Serialize};

/// Why a parameter file was refused.
#[derive(Debug, thiserror::Error)]
pub enum ConfigError {
    /// Not TOML, or an unknown or mistyped key (with line and column).
    #[error("{0}")]
    Toml(#[from] toml::de::Error),
    /// A value outside its declared range (the error names the key,
    /// e.g. `motor.resistance_ohm`, the value and the range).
    #[error(transparent)]
    OutOfRange(#[from] SettingError),
}

/// The H-bridge model (declared with the equations that use it).
pub use fwav_plant::PwmModel;

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
        MOTOR.check(&self.motor)?;
        SUPPLY.check(&self.supply)?;
        TRANSMISSION.check(&self.transmission)?;
        WING.check(&self.wing)?;
        SENSORS.check(&self.sensors)?;
        SIMULATION.check(&self.simulation)?;
        Ok(())
    }

    /// Control period, s.
    pub fn control_dt(&self) -> f64 {
        1.0 / self.simulation.control_hz
    }
}

/// The range of a plant value that the flight controller's model takes as
/// it is ([`crate::controller_model`]): its parameter's, as the device
/// declares it. A plant file the check allows then has values a board
/// (or hil-sim's) can be set to; the values the model combines (the
/// inertia, the damping) and the spring (tuned to a demand, it is
/// computed) are checked by
/// [`crate::controller_model::checked_controller_model`]. The design's
/// `[actuator]` table, the same vehicle, takes these ranges too.
pub const fn device_range(id: ParamId) -> Interval {
    let [low, high] = id.info().bounds;
    Interval::closed(low, high)
}

/// The `[motor]` table's settings.
pub const MOTOR: Table<Motor> = Table {
    name: "motor",
    doc: "DC motor.",
    settings: &[
        Setting::real(
            "resistance_ohm",
            "ohm",
            device_range(ParamId::WindingResistance),
            "Winding resistance (the flight controller's winding_resistance: its range)",
            |m| Value::Real(m.resistance_ohm),
        ),
        Setting::real(
            "inductance_h",
            "H",
            Interval::positive(),
            "Winding inductance",
            |m| Value::Real(m.inductance_h),
        ),
        Setting::real(
            "torque_constant_nm_per_a",
            "N m/A",
            device_range(ParamId::TorqueConstant),
            "Torque constant (= back-EMF constant; the flight controller's torque_constant: its range)",
            |m| Value::Real(m.torque_constant_nm_per_a),
        ),
        Setting::real(
            "rotor_inertia_kg_m2",
            "kg m^2",
            Interval::at_least(0.0),
            "Rotor inertia",
            |m| Value::Real(m.rotor_inertia_kg_m2),
        ),
        Setting::real(
            "coulomb_friction_nm",
            "N m",
            Interval::at_least(0.0),
            "Coulomb friction at the motor shaft",
            |m| Value::Real(m.coulomb_friction_nm),
        ),
        Setting::real(
            "viscous_friction_nms_per_rad",
            "N m s/rad",
            Interval::at_least(0.0),
            "Viscous friction at the motor shaft",
            |m| Value::Real(m.viscous_friction_nms_per_rad),
        ),
    ],
};

/// The `[supply]` table's settings.
pub const SUPPLY: Table<Supply> = Table {
    name: "supply",
    doc: "Battery and H-bridge.",
    settings: &[
        Setting {
            key: "pwm",
            unit: "",
            allowed: Allowed::Choice(&["averaged", "switching"]),
            doc: "Bridge model: the average voltage over a PWM period, or each period's switching",
            value: |s| {
                Value::Choice(match s.pwm {
                    PwmModel::Averaged => "averaged",
                    PwmModel::Switching => "switching",
                })
            },
        },
        Setting::real(
            "battery_v",
            "V",
            device_range(ParamId::SupplyVoltage),
            "Open-circuit battery voltage (the flight controller's supply_voltage: its range)",
            |s| Value::Real(s.battery_v),
        ),
        Setting::real(
            "internal_resistance_ohm",
            "ohm",
            Interval::at_least(0.0),
            "Battery internal resistance",
            |s| Value::Real(s.internal_resistance_ohm),
        ),
        Setting::real(
            "pwm_hz",
            "Hz",
            Interval::positive(),
            "PWM frequency of the switching bridge model",
            |s| Value::Real(s.pwm_hz),
        ),
    ],
};

/// The `[transmission]` table's settings.
pub const TRANSMISSION: Table<Transmission> = Table {
    name: "transmission",
    doc: "Gearbox and spring.",
    settings: &[
        Setting::real(
            "gear_ratio",
            "",
            device_range(ParamId::GearRatio),
            "Motor turns per flapping-axis turn (the flight controller's gear_ratio: its range)",
            |t| Value::Real(t.gear_ratio),
        ),
        Setting::real(
            "efficiency",
            "",
            Interval::above_up_to(0.0, 1.0),
            "Gearbox efficiency",
            |t| Value::Real(t.efficiency),
        ),
        Setting::real(
            "spring_nm_per_rad",
            "N m/rad",
            // Not the device's range (0 to 10): a spring tuned to the
            // demand (k = J omega^2) passes 10 N m/rad at 51 Hz on the
            // designed vehicle, and the feasibility check validates the
            // plant it tunes; a board's model is checked apart
            // (`checked_controller_model`).
            Interval::at_least(0.0),
            "Torsional spring about the flapping axis",
            |t| Value::Real(t.spring_nm_per_rad),
        ),
    ],
};

/// The `[wing]` table's settings.
pub const WING: Table<Wing> = Table {
    name: "wing",
    doc: "The wing as the actuator sees it.",
    settings: &[
        Setting::real(
            "inertia_kg_m2",
            "kg m^2",
            Interval::positive(),
            "Inertia of the wing (and linkage) about the flapping axis",
            |w| Value::Real(w.inertia_kg_m2),
        ),
        Setting::real(
            "span_m",
            "m",
            Interval::positive(),
            "Span from the flapping axis to the tip",
            |w| Value::Real(w.span_m),
        ),
        Setting::real(
            "root_chord_m",
            "m",
            Interval::positive(),
            "Chord at the root",
            |w| Value::Real(w.root_chord_m),
        ),
        Setting::real(
            "tip_chord_m",
            "m",
            Interval::at_least(0.0),
            "Chord at the tip (linear taper)",
            |w| Value::Real(w.tip_chord_m),
        ),
        Setting::real(
            "air_density_kg_m3",
            "kg/m^3",
            Interval::at_least(0.0),
            "Air density",
            |w| Value::Real(w.air_density_kg_m3),
        ),
        Setting::real(
            "drag_coefficient",
            "",
            Interval::at_least(0.0),
            "Drag coefficient of the wing normal to the flow",
            |w| Value::Real(w.drag_coefficient),
        ),
    ],
};

/// The `[sensors]` table's settings.
pub const SENSORS: Table<Sensors> = Table {
    name: "sensors",
    doc: "Sensors.",
    settings: &[
        Setting {
            key: "encoder_counts_per_rev",
            unit: "",
            allowed: Allowed::Integer(Integers::at_least(4)),
            doc: "Encoder counts per revolution of the flapping axis",
            value: |s| Value::unsigned(s.encoder_counts_per_rev),
        },
        Setting::real(
            "current_noise_a",
            "A",
            Interval::at_least(0.0),
            "Standard deviation of the current sensor's noise",
            |s| Value::Real(s.current_noise_a),
        ),
        Setting::real(
            "current_offset_a",
            "A",
            Interval::finite(),
            "Offset of the current sensor",
            |s| Value::Real(s.current_offset_a),
        ),
        Setting {
            key: "seed",
            unit: "",
            allowed: Allowed::Integer(Integers::at_least(0)),
            doc: "Seed of the sensor noise (recorded in results)",
            value: |s| Value::unsigned(s.seed),
        },
    ],
};

/// The `[simulation]` table's settings.
pub const SIMULATION: Table<Simulation> = Table {
    name: "simulation",
    doc: "Time stepping.",
    settings: &[
        Setting::real(
            "control_hz",
            "Hz",
            Interval::closed(100.0, 100_000.0),
            "Control rate of the flight controller",
            |s| Value::Real(s.control_hz),
        ),
        Setting {
            key: "substeps",
            unit: "",
            allowed: Allowed::Integer(Integers::at_least(10)),
            doc: "Plant RK4 steps per control period (RK4 at least 10x finer than control)",
            value: |s| Value::unsigned(s.substeps),
        },
    ],
};
