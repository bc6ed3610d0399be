//! What the host side ships, as constants for the emulated board: the
//! plant of `actuator/plant.toml`, the controller's model of it and the
//! upload request of `host/profiles/initial-design.json`.
//!
//! Generated: do not edit. `cargo test -p fwav-e2e --test firmware_constants`
//! fails when this is stale; `FWAV_REGENERATE=1` in front of it rewrites it.

use fwav_plant::{Physics, PwmModel};
use fwav_protocol::{ParamId, ParamValue};

/// The shipped plant's physics.
pub const PHYSICS: Physics = Physics {
    resistance_ohm: 2.83,
    inductance_h: 7e-5,
    torque_constant_nm_per_a: 0.00535,
    rotor_inertia_kg_m2: 7.1e-8,
    coulomb_friction_nm: 0.00012,
    viscous_friction_nms_per_rad: 0.0,
    battery_v: 7.4,
    internal_resistance_ohm: 0.15,
    pwm_hz: 25000.0,
    gear_ratio: 20.0,
    gear_efficiency: 0.9,
    spring_nm_per_rad: 0.45748372,
    wing_inertia_kg_m2: 6.737023e-5,
    aero_damping_nms2: 2.252300014798452e-5,
    pwm: PwmModel::Averaged,
};

/// Control rate the plant file is stepped at, Hz.
pub const PLANT_CONTROL_HZ: f64 = 10000.0;
/// Encoder counts per revolution of the flapping axis.
pub const ENCODER_COUNTS_PER_REV: u32 = 4096;
/// Offset of the current sensor, A.
pub const CURRENT_OFFSET_A: f64 = 0.005;

/// The controller's model of the plant.
pub const CONTROLLER_MODEL: [ParamValue; 8] = [
    ParamValue { id: ParamId::WingInertia, value: 9.577023e-5 },
    ParamValue { id: ParamId::SpringStiffness, value: 0.4574837 },
    ParamValue { id: ParamId::ViscousDamping, value: 0.0 },
    ParamValue { id: ParamId::AeroDamping, value: 2.2523e-5 },
    ParamValue { id: ParamId::TorqueConstant, value: 0.00535 },
    ParamValue { id: ParamId::WindingResistance, value: 2.83 },
    ParamValue { id: ParamId::GearRatio, value: 20.0 },
    ParamValue { id: ParamId::SupplyVoltage, value: 7.4 },
];

/// `UploadProfile` (sequence number 1) of the shipped initial design, as
/// a frame.
pub const UPLOAD_INITIAL_DESIGN: [u8; 35] = [
    0x00, 0x04, 0x01, 0x02, 0x01, 0x01, 0x07, 0x30, 0x41, 0x92, 0x0a, 0x06, 0x3f, 0x01, 0x01, 0x01,
    0x01, 0x01, 0x03, 0xa0, 0x41, 0x01, 0x03, 0x80, 0x3f, 0x01, 0x01, 0x02, 0x3f, 0x05, 0x7a, 0xdc,
    0x12, 0x1f, 0x00,
];
