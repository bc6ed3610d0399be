//! The `[actuator]` table: the flapping drive the design must be flown
//! by — DC motor, gearbox, battery, spring about the flapping axis, and
//! the flight controller's current limit and the reserve kept for its
//! feedback. One conversion, [`ActuatorConfig::actuator`], maps it to the
//! actuator crate's parameter types ([`crate::vehicle::Actuator`]); with
//! the designed wing ([`crate::vehicle::Vehicle`]) that is the plant the
//! feasibility check judges and hil-sim flies.
//!
//! ## Defaults: where the numbers come from
//! The motor is a FAULHABER 1331 T 006 SR coreless DC micromotor (13 mm
//! diameter, 31 mm long, 19 g; precious-metal commutation), from the
//! maker's datasheet "DC-Micromotors Series 1331 ... SR" (values at 22 °C,
//! 6 V winding): terminal resistance 2.83 ohm, rotor inductance 70 uH,
//! torque constant 5.35 mN m/A, rotor inertia 0.71 g cm^2, friction
//! torque 0.12 mN m (Coulomb). Its no-load current, 0.022 A at 10 600
//! rpm, times the torque constant is 0.118 mN m, the friction torque
//! itself: the datasheet leaves no viscous share, so the viscous friction
//! is 0. The battery is a 2S lithium-polymer pack, 7.4 V nominal, with
//! 0.15 ohm internal resistance (the actuator crate's default plant's
//! value for a small pack; not from a datasheet). The gearbox ratio 20 at
//! 0.9 efficiency is a one-stage spur reduction's class (assumed, no
//! gearhead datasheet consulted; 20 keeps the back-EMF at 11 Hz, ±30°,
//! `K_t N A w` = 3.9 V, well inside the battery). The current limit is
//! the flight controller's default (`ParamId::CurrentLimit`, 1.5 A) and
//! the reserve the check's default (10%,
//! [`fwav_actuator::feasibility::DEFAULT_RESERVE`]).
//!
//! The spring is tuned to resonance by default (`spring = "tuned"`, `k =
//! J omega^2` at the flapping frequency flown): the built-in wing (10.3 g,
//! 6.74e-5 kg m^2 about the flapping axis) at 11 Hz, ±30° needs 0.17 N m
//! of inertial torque at the stroke's ends; through the best gear ratio
//! for this rotor (`N = sqrt(J_wing / J_rotor)` = 31) that is 2.0 A of
//! this motor's current for the inertia alone, above the 1.5 A limit. The
//! tuned spring takes it, leaving the motor the aerodynamic and friction
//! torques (`fwav actuator --frequency-hz 11 --amplitude-deg 30` prints
//! the margins and the current the spring saves).

use fwav_actuator::feasibility::{ActuatorLimits, DEFAULT_RESERVE};
use fwav_actuator::params::{device_range, Motor, PlantParams, Supply};
use fwav_protocol::ParamId;
use fwav_settings::{Allowed, Bound, Interval, Setting, Table, Value};
use serde::{Deserialize, Serialize};

use crate::vehicle::{Actuator, Spring};

/// How the spring's stiffness is given.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SpringChoice {
    /// `spring_nm_per_rad` as given (0: no spring).
    Fixed,
    /// Tuned to resonance at the flapping frequency flown (`k = J
    /// omega^2`, `J` the wing's and the reflected rotor's inertia);
    /// `spring_nm_per_rad` is then not used.
    #[default]
    Tuned,
}

/// The `[actuator]` table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ActuatorConfig {
    /// Winding (terminal) resistance, ohm.
    pub resistance_ohm: f64,
    /// Winding inductance, H.
    pub inductance_h: f64,
    /// Torque constant (= back-EMF constant), N m/A.
    pub torque_constant_nm_per_a: f64,
    /// Rotor inertia, kg m^2.
    pub rotor_inertia_kg_m2: f64,
    /// Coulomb friction at the motor shaft, N m.
    pub coulomb_friction_nm: f64,
    /// Viscous friction at the motor shaft, N m s/rad.
    pub viscous_friction_nms_per_rad: f64,
    /// Motor turns per flapping-axis turn.
    pub gear_ratio: f64,
    /// Gearbox efficiency in (0, 1].
    pub gear_efficiency: f64,
    /// Open-circuit battery voltage, V.
    pub battery_v: f64,
    /// Battery internal resistance, ohm.
    pub battery_resistance_ohm: f64,
    /// `"tuned"` or `"fixed"` (then `spring_nm_per_rad`).
    pub spring: SpringChoice,
    /// Stiffness of a fixed spring about the flapping axis, N m/rad.
    pub spring_nm_per_rad: f64,
    /// The flight controller's current limit, A.
    pub current_limit_a: f64,
    /// Fraction of every limit kept for the feedback loop.
    pub reserve: f64,
}

impl Default for ActuatorConfig {
    fn default() -> Self {
        Self {
            resistance_ohm: 2.83,
            inductance_h: 70e-6,
            torque_constant_nm_per_a: 5.35e-3,
            rotor_inertia_kg_m2: 0.71e-7,
            coulomb_friction_nm: 0.12e-3,
            viscous_friction_nms_per_rad: 0.0,
            gear_ratio: 20.0,
            gear_efficiency: 0.9,
            battery_v: 7.4,
            battery_resistance_ohm: 0.15,
            spring: SpringChoice::Tuned,
            spring_nm_per_rad: 0.0,
            current_limit_a: f64::from(fwav_protocol::ParamId::CurrentLimit.info().default),
            reserve: DEFAULT_RESERVE,
        }
    }
}

impl ActuatorConfig {
    /// The actuator crate's types of this table (the one conversion): the
    /// motor, the supply (bridge model and PWM frequency of the actuator
    /// crate's default plant), the gearbox, the spring and the limits.
    pub fn actuator(&self) -> Actuator {
        let defaults = PlantParams::default();
        Actuator {
            motor: Motor {
                resistance_ohm: self.resistance_ohm,
                inductance_h: self.inductance_h,
                torque_constant_nm_per_a: self.torque_constant_nm_per_a,
                rotor_inertia_kg_m2: self.rotor_inertia_kg_m2,
                coulomb_friction_nm: self.coulomb_friction_nm,
                viscous_friction_nms_per_rad: self.viscous_friction_nms_per_rad,
            },
            supply: Supply {
                battery_v: self.battery_v,
                internal_resistance_ohm: self.battery_resistance_ohm,
                ..defaults.supply
            },
            gear_ratio: self.gear_ratio,
            gear_efficiency: self.gear_efficiency,
            spring: match self.spring {
                SpringChoice::Fixed => Spring::Fixed(self.spring_nm_per_rad),
                SpringChoice::Tuned => Spring::Tuned,
            },
            limits: ActuatorLimits {
                current_a: self.current_limit_a,
                reserve: self.reserve,
            },
        }
    }
}

/// The `[actuator]` table's settings.
pub const ACTUATOR: Table<ActuatorConfig> = Table {
    name: "actuator",
    doc: "The flapping drive: DC motor (default: FAULHABER 1331 T 006 SR datasheet), gearbox, 2S battery, spring, the controller's current limit.",
    settings: &[
        Setting::real("resistance_ohm", "ohm", device_range(ParamId::WindingResistance), "Motor winding resistance (the flight controller's winding_resistance: its range)", |a| {
            Value::Real(a.resistance_ohm)
        }),
        Setting::real("inductance_h", "H", Interval::positive(), "Motor winding inductance", |a| {
            Value::Real(a.inductance_h)
        }),
        Setting::real(
            "torque_constant_nm_per_a",
            "N m/A",
            device_range(ParamId::TorqueConstant),
            "Motor torque constant (= back-EMF constant, V s/rad; the flight controller's torque_constant: its range)",
            |a| Value::Real(a.torque_constant_nm_per_a),
        ),
        Setting::real(
            "rotor_inertia_kg_m2",
            "kg m^2",
            Interval::at_least(0.0),
            "Motor rotor inertia",
            |a| Value::Real(a.rotor_inertia_kg_m2),
        ),
        Setting::real(
            "coulomb_friction_nm",
            "N m",
            Interval::at_least(0.0),
            "Coulomb friction at the motor shaft",
            |a| Value::Real(a.coulomb_friction_nm),
        ),
        Setting::real(
            "viscous_friction_nms_per_rad",
            "N m s/rad",
            Interval::at_least(0.0),
            "Viscous friction at the motor shaft",
            |a| Value::Real(a.viscous_friction_nms_per_rad),
        ),
        Setting::real("gear_ratio", "", device_range(ParamId::GearRatio), "Motor turns per flapping-axis turn (the flight controller's gear_ratio: its range)", |a| {
            Value::Real(a.gear_ratio)
        }),
        Setting::real(
            "gear_efficiency",
            "",
            Interval::above_up_to(0.0, 1.0),
            "Gearbox efficiency",
            |a| Value::Real(a.gear_efficiency),
        ),
        Setting::real("battery_v", "V", device_range(ParamId::SupplyVoltage), "Open-circuit battery voltage (the flight controller's supply_voltage: its range)", |a| {
            Value::Real(a.battery_v)
        }),
        Setting::real(
            "battery_resistance_ohm",
            "ohm",
            Interval::at_least(0.0),
            "Battery internal resistance",
            |a| Value::Real(a.battery_resistance_ohm),
        ),
        Setting {
            key: "spring",
            unit: "",
            allowed: Allowed::Choice(&["tuned", "fixed"]),
            doc: "Spring about the flapping axis: tuned to resonance at the flapping frequency (k = J omega^2), or fixed at spring_nm_per_rad",
            value: |a| {
                Value::Choice(match a.spring {
                    SpringChoice::Tuned => "tuned",
                    SpringChoice::Fixed => "fixed",
                })
            },
        },
        Setting::real(
            "spring_nm_per_rad",
            "N m/rad",
            device_range(ParamId::SpringStiffness),
            "Stiffness of the fixed spring (spring = \"fixed\"; 0: no spring; the flight controller's spring_stiffness: its range)",
            |a| Value::Real(a.spring_nm_per_rad),
        ),
        Setting::real(
            "current_limit_a",
            "A",
            Interval::above_up_to(0.0, ParamId::CurrentLimit.info().bounds[1]),
            "The flight controller's current limit (its current_limit, above 0)",
            |a| Value::Real(a.current_limit_a),
        ),
        Setting::real(
            "reserve",
            "",
            Interval {
                low: Bound::Closed(0.0),
                high: Bound::Open(1.0),
            },
            "Fraction of every limit (torque, current, voltage) kept for the feedback loop",
            |a| Value::Real(a.reserve),
        ),
    ],
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::SystemConfig;

    /// The conversion carries every key to its place; a fixed spring keeps
    /// its stiffness.
    #[test]
    fn conversion_carries_every_key() {
        let text = "[actuator]\nresistance_ohm = 1.1\ninductance_h = 2.2e-4\ntorque_constant_nm_per_a = 3.3e-3\nrotor_inertia_kg_m2 = 4.4e-8\ncoulomb_friction_nm = 5.5e-5\nviscous_friction_nms_per_rad = 6.6e-9\ngear_ratio = 7.7\ngear_efficiency = 0.88\nbattery_v = 9.9\nbattery_resistance_ohm = 0.11\nspring = \"fixed\"\nspring_nm_per_rad = 0.12\ncurrent_limit_a = 1.3\nreserve = 0.14\n";
        let a = SystemConfig::from_toml(text).unwrap().actuator.actuator();
        let m = &a.motor;
        assert_eq!(
            [
                m.resistance_ohm,
                m.inductance_h,
                m.torque_constant_nm_per_a,
                m.rotor_inertia_kg_m2,
                m.coulomb_friction_nm,
                m.viscous_friction_nms_per_rad
            ],
            [1.1, 2.2e-4, 3.3e-3, 4.4e-8, 5.5e-5, 6.6e-9]
        );
        assert_eq!([a.gear_ratio, a.gear_efficiency], [7.7, 0.88]);
        assert_eq!(
            [a.supply.battery_v, a.supply.internal_resistance_ohm],
            [9.9, 0.11]
        );
        assert_eq!(a.spring, Spring::Fixed(0.12));
        assert_eq!([a.limits.current_a, a.limits.reserve], [1.3, 0.14]);
        let d = ActuatorConfig::default().actuator();
        assert_eq!(d.spring, Spring::Tuned);
        assert_eq!(d.limits, ActuatorLimits::firmware_default());
    }

    /// The defaults fly the built-in FWAV's initial design (11 Hz, ±30°,
    /// mean 0) with every margin above the reserve: on the quasi-steady
    /// damping (C_D = 3) and on the damping the full-size system analysis
    /// gives at that point (c_a = 2.2523e-5 N m s^2: 0.0412 J per cycle,
    /// 0.453 W of mean drive power, measured with `fwav system-analysis`
    /// on this commit's defaults). Without the spring they cannot: the
    /// inertial torque alone, `J_wing A w^2`, needs more than the current
    /// limit even at the gear ratio that minimizes it, `N =
    /// sqrt(J_wing / J_rotor)`, where the motor's share is `2 sqrt(J_wing
    /// J_rotor) A w^2 / K_t`.
    #[test]
    fn the_defaults_fly_the_initial_design_only_with_the_spring() {
        use crate::vehicle::Vehicle;
        use fwav_actuator::feasibility::FlappingDemand;
        let config = SystemConfig::default();
        let model = config.wing_model().unwrap();
        let k = config.kinematics();
        let mut v = Vehicle::quasi_steady(&model, &k, &config.flight(), config.actuator.actuator())
            .unwrap();
        let demand = FlappingDemand {
            frequency_hz: 11.0,
            amplitude_deg: 30.0,
            mean_deg: 0.0,
        };
        let quasi = v.check(&demand).unwrap();
        assert!(quasi.feasible, "{quasi:?}");
        v.aero_damping_nms2 = crate::vehicle::INITIAL_DESIGN_AERO_DAMPING;
        let analysed = v.check(&demand).unwrap();
        assert!(analysed.feasible, "{analysed:?}");
        assert!(analysed.peaks.peak_current_a > quasi.peaks.peak_current_a);
        let a = &config.actuator;
        let w = 2.0 * std::f64::consts::PI * 11.0;
        let best = 2.0
            * (v.wing_inertia_kg_m2 * a.rotor_inertia_kg_m2).sqrt()
            * 30f64.to_radians()
            * w
            * w
            / a.torque_constant_nm_per_a;
        assert!(best > a.current_limit_a, "{best} A");
        v.actuator.spring = Spring::Fixed(0.0);
        assert!(!v.check(&demand).unwrap().feasible);
    }

    #[test]
    fn errors_name_the_key() {
        let e = SystemConfig::from_toml("[actuator]\nreserve = 1\n").unwrap_err();
        assert_eq!(e.to_string(), "actuator.reserve = 1 is outside [0, 1)");
        let e = SystemConfig::from_toml("[actuator]\nspring = \"soft\"\n").unwrap_err();
        assert!(e.to_string().contains("spring"), "{e}");
        let e = SystemConfig::from_toml("[actuator]\nmotor = 3\n").unwrap_err();
        assert!(e.to_string().contains("motor"), "{e}");
    }
}
