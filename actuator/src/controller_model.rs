//! The flight controller's model of a plant: the values of the firmware's
//! model parameters ([`fwav_protocol::ParamId`], the feedforward's `J
//! phi'' + c phi' + c_a phi'|phi'| + k phi = tau` and the motor's
//! `V = R i + K_t N phi'`) that describe [`PlantParams`], so the controller flying
//! a plant (hil-sim, or a board after `fwav fc params --set`) feeds
//! forward that plant and not the protocol's defaults.
//!
//! Referred to the flapping axis as [`crate::plant`] writes its equations:
//! `J = J_wing + N^2 J_rotor`, viscous damping `N^2 b`, aerodynamic
//! damping `c_a = 1/2 rho C_D int c r^3 dr` ([`crate::params::Wing::aero_damping`]);
//! the winding resistance is the motor's and the supply the battery's
//! open-circuit voltage. Coulomb friction, the gearbox loss and the
//! battery's internal resistance have no parameter and are left to the
//! feedback.

use fwav_protocol::{ParamId, ParamValue};
use fwav_settings::Shown;

use crate::params::PlantParams;

/// The controller's model parameters of `plant`, in wire-id order (as
/// the wire's `f32`; [`checked_controller_model`] first asks whether the
/// device takes them).
pub fn controller_model(plant: &PlantParams) -> [ParamValue; 8] {
    model_values(plant).map(on_the_wire)
}

/// [`controller_model`], or the first value the device's parameter range
/// refuses ([`ParamId::accepts`]): a board set to it would keep that
/// parameter's old value and feed forward another plant than this one.
pub fn checked_controller_model(plant: &PlantParams) -> Result<[ParamValue; 8], BeyondDevice> {
    let values = model_values(plant);
    match values.iter().find(|&&(id, v)| !id.accepts(v as f32)) {
        Some(&(id, value)) => Err(BeyondDevice { id, value }),
        None => Ok(values.map(on_the_wire)),
    }
}

/// A model value as the wire carries it, an `f32`.
fn on_the_wire((id, value): (ParamId, f64)) -> ParamValue {
    ParamValue {
        id,
        value: value as f32,
    }
}

/// The model's values in `f64`, as the plant gives them.
fn model_values(plant: &PlantParams) -> [(ParamId, f64); 8] {
    let n = plant.transmission.gear_ratio;
    let m = &plant.motor;
    [
        (
            ParamId::WingInertia,
            plant.wing.inertia_kg_m2 + n * n * m.rotor_inertia_kg_m2,
        ),
        (
            ParamId::SpringStiffness,
            plant.transmission.spring_nm_per_rad,
        ),
        (
            ParamId::ViscousDamping,
            n * n * m.viscous_friction_nms_per_rad,
        ),
        (ParamId::AeroDamping, plant.wing.aero_damping()),
        (ParamId::TorqueConstant, m.torque_constant_nm_per_a),
        (ParamId::WindingResistance, m.resistance_ohm),
        (ParamId::GearRatio, n),
        (ParamId::SupplyVoltage, plant.supply.battery_v),
    ]
}

/// A plant whose controller model the device cannot take: one of the
/// model's values is outside its parameter's range.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[error(
    "the plant gives the controller's {} = {} {}, outside the device's {}..={} {}: a board \
     cannot fly this plant's model; check {}",
    .id.info().name,
    Shown::rounded(*.value, 6),
    .id.info().unit,
    Shown(.id.info().bounds[0]),
    Shown(.id.info().bounds[1]),
    .id.info().unit,
    plant_keys(*.id)
)]
pub struct BeyondDevice {
    /// The parameter.
    pub id: ParamId,
    /// The value the plant gives it (computed: shown to six significant
    /// digits).
    pub value: f64,
}

/// The plant file's keys a model parameter is made of.
fn plant_keys(id: ParamId) -> &'static str {
    match id {
        ParamId::WingInertia => {
            "wing.inertia_kg_m2, motor.rotor_inertia_kg_m2 and transmission.gear_ratio"
        }
        ParamId::SpringStiffness => "transmission.spring_nm_per_rad",
        ParamId::ViscousDamping => "motor.viscous_friction_nms_per_rad and transmission.gear_ratio",
        ParamId::AeroDamping => "the [wing] table",
        ParamId::TorqueConstant => "motor.torque_constant_nm_per_a",
        ParamId::WindingResistance => "motor.resistance_ohm",
        ParamId::GearRatio => "transmission.gear_ratio",
        ParamId::SupplyVoltage => "supply.battery_v",
        _ => "the plant file",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every value is one the firmware accepts, and the reflected terms
    /// are the plant's: `J = J_wing + N^2 J_rotor`, `c = N^2 b`.
    #[test]
    fn model_of_a_plant_is_accepted_and_reflected_to_the_flapping_axis() {
        let mut p = PlantParams::default();
        p.motor.viscous_friction_nms_per_rad = 2.5e-8;
        let model = controller_model(&p);
        for v in &model {
            assert!(v.id.accepts(v.value), "{v:?}");
        }
        let n = p.transmission.gear_ratio;
        let j = p.wing.inertia_kg_m2 + n * n * p.motor.rotor_inertia_kg_m2;
        assert!((f64::from(model[0].value) / j - 1.0).abs() < 1e-6);
        assert!((f64::from(model[2].value) / (n * n * 2.5e-8) - 1.0).abs() < 1e-6);
        let ids: Vec<_> = model.iter().map(|v| v.id as usize).collect();
        assert_eq!(ids, (0..8).collect::<Vec<_>>());
        assert_eq!(checked_controller_model(&p), Ok(model));
    }

    /// A value the device refuses is named with the plant's key, as given
    /// (1e300 ohm was sent as `inf` and refused by the device as that).
    #[test]
    fn a_model_beyond_the_device_is_named_with_the_plant_key() {
        let mut p = PlantParams::default();
        p.motor.resistance_ohm = 1e300;
        let e = checked_controller_model(&p).unwrap_err();
        assert_eq!(e.id, ParamId::WindingResistance);
        assert_eq!(
            e.to_string(),
            "the plant gives the controller's winding_resistance = 1e300 ohm, outside the \
             device's 0.001..=1000 ohm: a board cannot fly this plant's model; check \
             motor.resistance_ohm"
        );
    }
}
