//! Controller parameters, settable over the link: typed ids ([`ParamId`]) with
//! a name, unit, default and allowed range each ([`ParamInfo`]).
//!
//! The plant parameters describe the flapping actuator referred to the
//! flapping axis (`J phi'' + c phi' + c_a phi'|phi'| + k phi = tau`); the
//! controller uses them for feedforward. The defaults are for the fwav
//! reference vehicle (~15 cm span, ~1 g wing, resonance near 11 Hz):
//! wing inertia ~ m L^2 / 3 = 1e-3 * 0.15^2 / 3 = 7.5e-6 kg m^2, spring
//! k = J (2 pi 11)^2 = 3.6e-2 N m/rad, blade-element quadratic damping
//! 0.5 rho C_D int c(r) r^3 dr = 1.05e-5 N m s^2 (rho 1.225 kg/m^3,
//! C_D 3.0, 0.15 m span, chord 0.075 m tapering to half at the tip): the
//! values of the plant hil-sim flew until issue 21. hil-sim's default plant
//! is now the designed vehicle (`actuator/plant.toml`, 9.58e-5 kg m^2 at
//! the flapping axis), and hil-sim sets these parameters from the plant it
//! flies (`fwav_actuator::controller_model`) as a user sets a board's with
//! `fwav fc params --set`; the defaults stay those of a board nobody has
//! configured (changing them would change no behaviour hil-sim tests).

use postcard_schema::Schema;
use serde::{Deserialize, Serialize};

/// Maximum number of parameters in one [`crate::Reply::Params`].
pub const MAX_PARAMS: usize = 32;

/// A controller parameter. Only append variants (the index is the wire id).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize, Schema)]
pub enum ParamId {
    /// Inertia about the flapping axis: wing + transmission + motor rotor
    /// times the gear ratio squared, kg m^2.
    WingInertia,
    /// Torsional spring about the flapping axis, N m/rad.
    SpringStiffness,
    /// Linear (viscous) damping, N m s/rad.
    ViscousDamping,
    /// Quadratic (aerodynamic) damping, N m s^2/rad^2.
    AeroDamping,
    /// Motor torque constant, N m/A (= back-EMF constant, V s/rad).
    TorqueConstant,
    /// Motor winding resistance, ohm.
    WindingResistance,
    /// Gear ratio motor : flapping axis.
    GearRatio,
    /// Nominal supply voltage, V.
    SupplyVoltage,
    /// Proportional gain on the angle error, duty/rad.
    AngleGain,
    /// Derivative gain on the rate error, duty s/rad.
    RateGain,
    /// Integral gain of the per-stroke amplitude correction, 1/s.
    AmplitudeGain,
    /// Integral gain of the per-stroke phase correction, 1/s.
    PhaseGain,
    /// Motor current limit, A.
    CurrentLimit,
    /// Time without a heartbeat of the arming session that triggers the
    /// link failsafe while armed, s.
    LinkTimeout,
    /// Measured current that disarms at once (over-current fault), A.
    OverCurrentTrip,
    /// Bandwidth of the angle/rate observer behind the encoder, Hz.
    ObserverBandwidth,
}

/// Description of one parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParamInfo {
    /// The id.
    pub id: ParamId,
    /// Name used on the command line (`--set name=value`).
    pub name: &'static str,
    /// SI unit.
    pub unit: &'static str,
    /// Value after a reset to defaults.
    pub default: f32,
    /// The allowed range as declared, `[min, max]` in `f64`
    /// ([`Self::min`] and [`Self::max`] are these as the wire's `f32`).
    /// For checking a value before it is sent, where it is an `f64` (a
    /// plant file's, say): `1e-3` as an `f64` is below `1e-3f32` widened,
    /// so the `f32` bounds would refuse the very value declared.
    pub bounds: [f64; 2],
}

impl ParamInfo {
    /// Smallest allowed value, as the wire's `f32`.
    pub const fn min(&self) -> f32 {
        self.bounds[0] as f32
    }

    /// Largest allowed value, as the wire's `f32`.
    pub const fn max(&self) -> f32 {
        self.bounds[1] as f32
    }
}

const fn info(
    id: ParamId,
    name: &'static str,
    unit: &'static str,
    default: f32,
    min: f64,
    max: f64,
) -> ParamInfo {
    ParamInfo {
        id,
        name,
        unit,
        default,
        bounds: [min, max],
    }
}

/// Every parameter, in wire-id order (`PARAMS[id as usize].id == id`).
pub const PARAMS: [ParamInfo; 16] = [
    info(
        ParamId::WingInertia,
        "wing_inertia",
        "kg m^2",
        7.5e-6,
        1e-9,
        1e-2,
    ),
    info(
        ParamId::SpringStiffness,
        "spring_stiffness",
        "N m/rad",
        3.6e-2,
        0.0,
        10.0,
    ),
    info(
        ParamId::ViscousDamping,
        "viscous_damping",
        "N m s/rad",
        1e-5,
        0.0,
        1.0,
    ),
    info(
        ParamId::AeroDamping,
        "aero_damping",
        "N m s^2/rad^2",
        1.05e-5,
        0.0,
        1.0,
    ),
    info(
        ParamId::TorqueConstant,
        "torque_constant",
        "N m/A",
        1.5e-3,
        1e-5,
        1.0,
    ),
    info(
        ParamId::WindingResistance,
        "winding_resistance",
        "ohm",
        5.0,
        1e-3,
        1e3,
    ),
    info(ParamId::GearRatio, "gear_ratio", "-", 20.0, 1.0, 1e3),
    info(
        ParamId::SupplyVoltage,
        "supply_voltage",
        "V",
        7.4,
        1.0,
        60.0,
    ),
    info(ParamId::AngleGain, "angle_gain", "1/rad", 10.0, 0.0, 1e3),
    info(ParamId::RateGain, "rate_gain", "s/rad", 0.03, 0.0, 10.0),
    info(
        ParamId::AmplitudeGain,
        "amplitude_gain",
        "1/s",
        2.0,
        0.0,
        100.0,
    ),
    info(ParamId::PhaseGain, "phase_gain", "1/s", 1.0, 0.0, 100.0),
    info(ParamId::CurrentLimit, "current_limit", "A", 1.5, 0.0, 50.0),
    info(ParamId::LinkTimeout, "link_timeout", "s", 0.3, 0.05, 60.0),
    info(
        ParamId::OverCurrentTrip,
        "over_current_trip",
        "A",
        3.0,
        0.0,
        100.0,
    ),
    info(
        ParamId::ObserverBandwidth,
        "observer_bandwidth",
        "Hz",
        200.0,
        10.0,
        2000.0,
    ),
];

impl ParamId {
    /// Name, unit, default and range of the parameter.
    pub const fn info(self) -> &'static ParamInfo {
        &PARAMS[self as usize]
    }

    /// The id with this command-line name.
    pub fn from_name(name: &str) -> Option<Self> {
        PARAMS.iter().find(|i| i.name == name).map(|i| i.id)
    }

    /// True if `value` is finite and within the allowed range.
    pub fn accepts(self, value: f32) -> bool {
        let i = self.info();
        value >= i.min() && value <= i.max()
    }
}

/// A parameter and its value (in the parameter's SI unit).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, Schema)]
pub struct ParamValue {
    /// Which parameter.
    pub id: ParamId,
    /// Its value.
    pub value: f32,
}
