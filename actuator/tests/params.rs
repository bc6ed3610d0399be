//! The shipped plant file and the checks of a parameter file.

use fwav_actuator::controller_model::{checked_controller_model, controller_model};
use fwav_actuator::params::{
    PlantParams, DEFAULT_PLANT_TOML, MOTOR, SENSORS, SIMULATION, SUPPLY, TRANSMISSION, WING,
};
use fwav_actuator::plant::Plant;
use fwav_protocol::ParamId;
use fwav_settings::Template;

/// The shipped plant is the built-in FWAV's initial design, and the
/// controller's model of it (what hil-sim sets over the link) refers it to
/// the flapping axis: `J = J_wing + N^2 J_rotor = 6.737023e-5 + 20^2 *
/// 7.1e-8 = 9.577023e-5 kg m^2` (by hand from the file's values), the
/// aerodynamic damping the file's provenance states, 2.2523e-5 N m s^2.
#[test]
fn the_shipped_plant_parses_and_is_the_controllers_model() {
    let params = PlantParams::from_toml(DEFAULT_PLANT_TOML).unwrap();
    let plant = Plant::new(&params);
    let inertia = plant.inertia();
    assert!((inertia / 9.577023e-5 - 1.0).abs() < 1e-9, "{inertia}");
    assert!(
        (plant.aero_damping() / 2.2523e-5 - 1.0).abs() < 1e-6,
        "{}",
        plant.aero_damping()
    );
    let model = controller_model(&params);
    assert_eq!(model[0].id, ParamId::WingInertia);
    assert!((f64::from(model[0].value) / inertia - 1.0).abs() < 1e-6);
    assert_eq!(model[3].id, ParamId::AeroDamping);
    assert!((f64::from(model[3].value) / 2.2523e-5 - 1.0).abs() < 1e-6);
}

#[test]
fn bad_parameters_name_the_field() {
    let text = DEFAULT_PLANT_TOML.replace("resistance_ohm = 2.83", "resistance_ohm = -5.0");
    let e = PlantParams::from_toml(&text).unwrap_err().to_string();
    assert!(
        e.contains("motor.resistance_ohm") && e.contains("-5"),
        "{e}"
    );
    let text = DEFAULT_PLANT_TOML.replace("gear_ratio", "gear_ration");
    let e = PlantParams::from_toml(&text).unwrap_err().to_string();
    assert!(e.contains("gear_ration"), "{e}");
    let text = DEFAULT_PLANT_TOML.replace("substeps = 10", "substeps = 4");
    let e = PlantParams::from_toml(&text).unwrap_err().to_string();
    assert!(e.contains("simulation.substeps"), "{e}");
}

/// The range in an error is the declared one (fwav-settings generates its
/// text), and a non-finite value never passes.
#[test]
fn errors_carry_the_declared_range() {
    let text = DEFAULT_PLANT_TOML.replace("efficiency = ", "efficiency = 1.5 #");
    let e = PlantParams::from_toml(&text).unwrap_err().to_string();
    assert!(
        e.contains("transmission.efficiency = 1.5") && e.contains("(0, 1]"),
        "{e}"
    );
    let text = DEFAULT_PLANT_TOML.replace("current_offset_a = ", "current_offset_a = nan #");
    let e = PlantParams::from_toml(&text).unwrap_err().to_string();
    assert!(e.contains("sensors.current_offset_a"), "{e}");
}

/// Every key of the plant file is declared in the tables the check walks,
/// and every declared key is in the file (the template renderer refuses
/// either gap).
#[test]
fn every_plant_key_is_declared() {
    let plain = toml::to_string(&PlantParams::default()).unwrap();
    Template::new("plant")
        .table(&MOTOR)
        .table(&SUPPLY)
        .table(&TRANSMISSION)
        .table(&WING)
        .table(&SENSORS)
        .table(&SIMULATION)
        .render(&plain)
        .unwrap();
}

/// A plant value the controller's model takes as it is has the device's
/// range ([`fwav_protocol::ParamInfo::bounds`]), so a plant file the check
/// allows has values a board can be set to (the spring, which a tuned
/// plant computes, is checked with the model's combined values). At each
/// bound the plant passes and its model is accepted (the device compares
/// the wire's `f32`); just beyond it the file is refused, naming its key.
/// The plant's ranges were `(0, inf)` until 2026-12-07, and a winding of
/// 1e300 ohm was refused only at the upload.
#[test]
fn a_value_the_controller_models_as_it_is_has_the_devices_range() {
    type Field = fn(&mut PlantParams) -> &mut f64;
    let cases: [(&str, ParamId, Field); 4] = [
        ("motor.resistance_ohm", ParamId::WindingResistance, |p| {
            &mut p.motor.resistance_ohm
        }),
        (
            "motor.torque_constant_nm_per_a",
            ParamId::TorqueConstant,
            |p| &mut p.motor.torque_constant_nm_per_a,
        ),
        ("supply.battery_v", ParamId::SupplyVoltage, |p| {
            &mut p.supply.battery_v
        }),
        ("transmission.gear_ratio", ParamId::GearRatio, |p| {
            &mut p.transmission.gear_ratio
        }),
    ];
    for (key, id, field) in cases {
        let [low, high] = id.info().bounds;
        // Just beyond each bound (each is positive): a thousandth.
        for (bound, beyond) in [(low, low * 0.999), (high, high * 1.001)] {
            let mut plant = PlantParams::default();
            *field(&mut plant) = bound;
            // The gear ratio scales the reflected inertia past the
            // device's at 1000: keep the rotor's share as at 20.
            if id == ParamId::GearRatio {
                plant.motor.rotor_inertia_kg_m2 *= (20.0 / bound) * (20.0 / bound);
            }
            plant
                .validate()
                .unwrap_or_else(|e| panic!("{key} = {bound}: {e}"));
            checked_controller_model(&plant).unwrap_or_else(|e| panic!("{key} = {bound}: {e}"));
            *field(&mut plant) = beyond;
            let e = plant.validate().unwrap_err().to_string();
            assert!(e.contains(key), "{key} = {beyond}: {e}");
        }
    }
}
