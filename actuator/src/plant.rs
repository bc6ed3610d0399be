//! The flapping actuator and wing in motion: the equations and their RK4
//! integration with an energy ledger live in the `no_std` crate
//! [`fwav_plant`] (so the emulated microcontroller integrates the same
//! code); this module re-exports them and converts the checked
//! [`PlantParams`] into their [`Physics`]. The equations are in
//! [`fwav_plant`]'s docs.

pub use fwav_plant::{balance_residual, Drive, EnergyLedger, Physics, Plant, State};

pub(crate) use fwav_plant::FRICTION_SLOPE;

use crate::params::PlantParams;

impl From<&PlantParams> for Physics {
    /// The values the equations use; the aerodynamic damping is the wing's
    /// blade-element integral ([`crate::params::Wing::aero_damping`]).
    fn from(p: &PlantParams) -> Self {
        Physics {
            resistance_ohm: p.motor.resistance_ohm,
            inductance_h: p.motor.inductance_h,
            torque_constant_nm_per_a: p.motor.torque_constant_nm_per_a,
            rotor_inertia_kg_m2: p.motor.rotor_inertia_kg_m2,
            coulomb_friction_nm: p.motor.coulomb_friction_nm,
            viscous_friction_nms_per_rad: p.motor.viscous_friction_nms_per_rad,
            battery_v: p.supply.battery_v,
            internal_resistance_ohm: p.supply.internal_resistance_ohm,
            pwm: p.supply.pwm,
            pwm_hz: p.supply.pwm_hz,
            gear_ratio: p.transmission.gear_ratio,
            gear_efficiency: p.transmission.efficiency,
            spring_nm_per_rad: p.transmission.spring_nm_per_rad,
            wing_inertia_kg_m2: p.wing.inertia_kg_m2,
            aero_damping_nms2: p.wing.aero_damping(),
        }
    }
}
