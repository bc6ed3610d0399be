//! The shipped plant file and the checks of a parameter file.

use fwav_actuator::params::{PlantParams, DEFAULT_PLANT_TOML};
use fwav_actuator::plant::Plant;

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
