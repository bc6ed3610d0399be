//! The shipped plant file and the checks of a parameter file.

use fwav_actuator::params::{
    PlantParams, DEFAULT_PLANT_TOML, MOTOR, SENSORS, SIMULATION, SUPPLY, TRANSMISSION, WING,
};
use fwav_actuator::plant::Plant;
use fwav_settings::Template;

#[test]
fn the_shipped_plant_parses_and_is_the_controllers_model() {
    let plant = PlantParams::from_toml(DEFAULT_PLANT_TOML).unwrap();
    // The controller's default model is this plant (fwav-protocol ParamId).
    let plant = Plant::new(&plant);
    let inertia = plant.inertia();
    assert!((inertia - 7.5e-6).abs() < 1e-9, "{inertia}");
    assert!(
        (plant.aero_damping() - 1.0465e-5).abs() < 1e-8,
        "{}",
        plant.aero_damping()
    );
}

#[test]
fn bad_parameters_name_the_field() {
    let text = DEFAULT_PLANT_TOML.replace("resistance_ohm = 5.0", "resistance_ohm = -5.0");
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
