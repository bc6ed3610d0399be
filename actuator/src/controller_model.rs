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

use crate::params::PlantParams;

/// The controller's model parameters of `plant`, in wire-id order.
pub fn controller_model(plant: &PlantParams) -> [ParamValue; 8] {
    let n = plant.transmission.gear_ratio;
    let m = &plant.motor;
    let value = |id, v: f64| ParamValue {
        id,
        value: v as f32,
    };
    [
        value(
            ParamId::WingInertia,
            plant.wing.inertia_kg_m2 + n * n * m.rotor_inertia_kg_m2,
        ),
        value(
            ParamId::SpringStiffness,
            plant.transmission.spring_nm_per_rad,
        ),
        value(
            ParamId::ViscousDamping,
            n * n * m.viscous_friction_nms_per_rad,
        ),
        value(ParamId::AeroDamping, plant.wing.aero_damping()),
        value(ParamId::TorqueConstant, m.torque_constant_nm_per_a),
        value(ParamId::WindingResistance, m.resistance_ohm),
        value(ParamId::GearRatio, n),
        value(ParamId::SupplyVoltage, plant.supply.battery_v),
    ]
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
    }
}
