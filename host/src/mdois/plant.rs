//! The designed vehicle as hil-sim's plant file: `plant.toml` beside
//! `kinematics.json` ([`fwav_actuator::params::PlantParams`], read by
//! `hil-sim run --plant` and `hil-sim serve --plant`). The wing is the
//! final design's: its inertia about the flapping axis from the shell
//! model at the final cycle's layout, its aerodynamic damping calibrated
//! on the final cycle's system analysis (the drive's work per cycle at
//! the analysed kinematics, [`crate::vehicle::aero_damping`]); the
//! actuator is the design file's `[actuator]`, its spring (when tuned)
//! tuned to the frequency `kinematics.json` flies. The file is checked to
//! parse back ([`PlantParams::from_toml`]) before it is written; a plant
//! whose controller model the device refuses ([`checked_controller_model`])
//! says so at its head.

use std::path::{Path, PathBuf};

use fwav_actuator::controller_model::checked_controller_model;
use fwav_actuator::params::PlantParams;
use fwav_protocol::ParamValue;

use crate::config::SystemConfig;
use crate::files::write_atomic;
use crate::profile_file::ProfileFile;
use crate::vehicle::Vehicle;

use super::error::DesignError;
use super::profile::KINEMATICS_FILE;
use super::records::load_topology;
use super::records::system::load_system;
use super::stage::layout_densities;

/// The plant file's name in the run's directory.
pub const PLANT_FILE: &str = "plant.toml";

/// The vehicle of `cycle`, the one its aerodynamic discipline and (for
/// the final cycle) `kinematics.json` are judged on: the wing with the
/// layout the cycle analysed (the uniform starting design in cycle 1, the
/// previous cycle's structural proposal after), damped as the cycle's
/// system analysis says.
pub fn cycle_vehicle(
    dir: &Path,
    config: &SystemConfig,
    cycle: usize,
) -> Result<Vehicle, DesignError> {
    let densities = if cycle <= 1 {
        config.wing_model()?.densities
    } else {
        layout_densities(&load_topology(dir, cycle - 1)?.result.layout)
    };
    designed_vehicle(dir, config, cycle, &densities)
}

/// The vehicle of `cycle`: the wing at the carbon `densities` the cycle's
/// system analysis had, damped as that analysis says.
pub fn designed_vehicle(
    dir: &Path,
    config: &SystemConfig,
    cycle: usize,
    densities: &[f64],
) -> Result<Vehicle, DesignError> {
    let record = load_system(dir, cycle)?;
    let model = config.wing_model_with(Some(densities))?;
    Vehicle::from_analysis(
        &model,
        &record.kinematics,
        &config.flight(),
        &record.steps,
        record.steps_per_cycle,
        config.actuator.actuator(),
    )
    .map_err(|source| DesignError::Vehicle { cycle, source })
}

/// The flight controller's `model` of a plant
/// ([`fwav_actuator::controller_model::controller_model`]) as
/// the command that sets it on a board (hil-sim sets the same values
/// itself).
pub fn controller_params_note(model: &[ParamValue]) -> String {
    let sets: Vec<String> = model
        .iter()
        .map(|v| format!("--set {}={:e}", v.id.info().name, v.value))
        .collect();
    format!(
        "Flight controller's model of this plant (its feedforward; hil-sim sets it itself):\n  fwav fc params {}",
        sets.join(" ")
    )
}

/// The plant text of `vehicle` flying at `frequency_hz`, with a header
/// saying where it came from and the controller's parameters of the
/// plant ([`controller_params_note`]); checked to parse back.
pub fn plant_toml(
    vehicle: &Vehicle,
    frequency_hz: f64,
    header: &str,
) -> Result<String, DesignError> {
    let plant = vehicle.plant(frequency_hz);
    let body = toml::to_string(&plant).map_err(|e| DesignError::output(PLANT_FILE, e))?;
    let mut text = String::new();
    // A model a board cannot be set to is said at the head of the file
    // (hil-sim refuses it naming the key): the design's results are
    // written already, and the run is not lost for it. The initial
    // vehicle's model is checked after the first analysis
    // (`Context::check_flyable`); a later cycle's (another layout, a
    // spring tuned to another frequency) may still leave the range.
    let note = match checked_controller_model(&plant) {
        Ok(model) => controller_params_note(&model),
        Err(beyond) => format!("NOT FLYABLE by the flight controller as it is: {beyond}"),
    };
    for line in header.lines().chain(note.lines()) {
        text.push_str("# ");
        text.push_str(line);
        text.push('\n');
    }
    text.push('\n');
    text.push_str(&body);
    PlantParams::from_toml(&text).map_err(|e| DesignError::output(PLANT_FILE, e))?;
    Ok(text)
}

/// Writes `plant.toml` of the final `cycle` into `dir`, for the frequency
/// of the `kinematics.json` already written there.
pub fn write_plant(
    dir: &Path,
    config: &SystemConfig,
    cycle: usize,
    densities: &[f64],
) -> Result<PathBuf, DesignError> {
    let vehicle = designed_vehicle(dir, config, cycle, densities)?;
    let profile = ProfileFile::load(dir.join(KINEMATICS_FILE))
        .map_err(|e| DesignError::output(PLANT_FILE, e))?;
    let frequency_hz = profile
        .document
        .segments
        .first()
        .map(|s| s.frequency_hz)
        .ok_or_else(|| DesignError::output(PLANT_FILE, "kinematics.json has no segment"))?;
    let header = format!(
        "fwav design: the designed vehicle (cycle {cycle}) for hil-sim --plant.\n\
         Wing: {:.2} g, inertia {:.4e} kg m^2 about the flapping axis (shell model, final layout);\n\
         aerodynamic damping c_a = {:.4e} N m s^2 (written as the drag coefficient that gives it on\n\
         the planform), calibrated on the final system analysis's drive work per cycle.\n\
         Actuator: the design file's [actuator]; spring {:.5} N m/rad at {frequency_hz} Hz (kinematics.json).",
        1e3 * vehicle.wing_mass_kg,
        vehicle.wing_inertia_kg_m2,
        vehicle.aero_damping_nms2,
        vehicle.spring_nm_per_rad(frequency_hz),
    );
    let text = plant_toml(&vehicle, frequency_hz, &header)?;
    Ok(write_atomic(dir, PLANT_FILE, text)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use fwav_actuator::controller_model::controller_model;
    use fwav_protocol::ParamId;

    /// The note is a command a user can paste: eight `--set name=value`
    /// with names the firmware knows and values that read back as the
    /// controller's model of the plant.
    #[test]
    fn the_note_sets_the_controllers_model() {
        let plant = PlantParams::default();
        let note = controller_params_note(&controller_model(&plant));
        let sets: Vec<&str> = note
            .split_whitespace()
            .filter(|w| w.contains('='))
            .collect();
        let model = controller_model(&plant);
        assert_eq!(sets.len(), model.len(), "{note}");
        for (set, v) in sets.iter().zip(&model) {
            let (name, value) = set.split_once('=').unwrap();
            assert_eq!(ParamId::from_name(name), Some(v.id), "{set}");
            assert_eq!(value.parse::<f32>().unwrap(), v.value, "{set}");
        }
    }

    /// A designed vehicle whose model a board cannot be set to (a wing of
    /// 1 kg m^2; the device's inertia goes to 0.01) is written with that
    /// said at the file's head, in place of the `fwav fc params` line: the
    /// design's results are written before it, and the run is not lost.
    #[test]
    fn a_plant_the_device_cannot_model_says_so() {
        // A fixed spring, so that the inertia is the model's one value
        // beyond the device (tuned to so heavy a wing, the spring would be
        // 4777 N m/rad, past the device's 10, too).
        let mut actuator = crate::config::ActuatorConfig::default();
        actuator.spring = crate::config::actuator::SpringChoice::Fixed;
        actuator.spring_nm_per_rad = 0.45;
        let mut vehicle = Vehicle {
            wing_mass_kg: 0.0103,
            wing_inertia_kg_m2: 6.737e-5,
            aero_damping_nms2: 2.25e-5,
            aero_source: crate::vehicle::AeroSource::QuasiSteady {
                drag_coefficient: 3.0,
            },
            span_m: 0.15,
            root_chord_m: 0.075,
            tip_chord_m: 0.0375,
            air_density_kg_m3: 1.225,
            actuator: actuator.actuator(),
        };
        let flyable = plant_toml(&vehicle, 11.0, "test").unwrap();
        assert!(flyable.contains("fwav fc params --set"), "{flyable}");
        vehicle.wing_inertia_kg_m2 = 1.0;
        let text = plant_toml(&vehicle, 11.0, "test").unwrap();
        assert!(
            text.contains(
                "# NOT FLYABLE by the flight controller as it is: the plant gives the \
                 controller's wing_inertia = 1.00003 kg m^2"
            ) && !text.contains("fwav fc params --set"),
            "{text}"
        );
    }
}
