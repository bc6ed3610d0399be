//! The emulated board's constants (`firmware/qemu/src/shipped.rs`) are what
//! the host side ships: the plant of `actuator/plant.toml` as the equations'
//! `Physics` (read and checked by `fwav-actuator`), its sensors, the
//! controller's model of it (`fwav_actuator::controller_model`, what hil-sim
//! sets), and the upload request of `host/profiles/initial-design.json` as
//! a frame. The file is generated here rather than by a build script, so
//! the firmware's build needs no host crates; this test fails when it is
//! stale, and `FWAV_REGENERATE=1` rewrites it:
//!
//! `FWAV_REGENERATE=1 cargo test -p fwav-e2e --test firmware_constants`

use std::fmt::Write as _;

use fwav_actuator::controller_model::controller_model;
use fwav_actuator::params::PlantParams;
use fwav_actuator::plant::Physics;
use fwav_e2e::emulator::workspace;
use fwav_protocol::document::ProfileDocument;
use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::{Command, Request};

const GENERATED: &str = "firmware/qemu/src/shipped.rs";
const PROFILE: &str = "host/profiles/initial-design.json";

/// The file's text. `{:?}` of a float is its shortest exact decimal form,
/// so the constants are bit for bit the parsed values.
fn render() -> String {
    let p = PlantParams::default();
    let x = Physics::from(&p);
    let mut s = String::from(
        "//! What the host side ships, as constants for the emulated board: the\n\
         //! plant of `actuator/plant.toml`, the controller's model of it and the\n\
         //! upload request of `host/profiles/initial-design.json`.\n\
         //!\n\
         //! Generated: do not edit. `cargo test -p fwav-e2e --test firmware_constants`\n\
         //! fails when this is stale; `FWAV_REGENERATE=1` in front of it rewrites it.\n\n\
         use fwav_plant::{Physics, PwmModel};\n\
         use fwav_protocol::{ParamId, ParamValue};\n\n\
         /// The shipped plant's physics.\n\
         pub const PHYSICS: Physics = Physics {\n",
    );
    let fields = [
        ("resistance_ohm", x.resistance_ohm),
        ("inductance_h", x.inductance_h),
        ("torque_constant_nm_per_a", x.torque_constant_nm_per_a),
        ("rotor_inertia_kg_m2", x.rotor_inertia_kg_m2),
        ("coulomb_friction_nm", x.coulomb_friction_nm),
        (
            "viscous_friction_nms_per_rad",
            x.viscous_friction_nms_per_rad,
        ),
        ("battery_v", x.battery_v),
        ("internal_resistance_ohm", x.internal_resistance_ohm),
        ("pwm_hz", x.pwm_hz),
        ("gear_ratio", x.gear_ratio),
        ("gear_efficiency", x.gear_efficiency),
        ("spring_nm_per_rad", x.spring_nm_per_rad),
        ("wing_inertia_kg_m2", x.wing_inertia_kg_m2),
        ("aero_damping_nms2", x.aero_damping_nms2),
    ];
    for (name, value) in fields {
        writeln!(s, "    {name}: {value:?},").expect("a String takes writes");
    }
    writeln!(s, "    pwm: PwmModel::{:?},\n}};\n", x.pwm).expect("a String takes writes");
    writeln!(
        s,
        "/// Control rate the plant file is stepped at, Hz.\n\
         pub const PLANT_CONTROL_HZ: f64 = {:?};\n\
         /// Encoder counts per revolution of the flapping axis.\n\
         pub const ENCODER_COUNTS_PER_REV: u32 = {};\n\
         /// Offset of the current sensor, A.\n\
         pub const CURRENT_OFFSET_A: f64 = {:?};\n",
        p.simulation.control_hz, p.sensors.encoder_counts_per_rev, p.sensors.current_offset_a
    )
    .expect("a String takes writes");
    let model = controller_model(&p);
    writeln!(
        s,
        "/// The controller's model of the plant.\n\
         pub const CONTROLLER_MODEL: [ParamValue; {}] = [",
        model.len()
    )
    .expect("a String takes writes");
    for v in model {
        writeln!(
            s,
            "    ParamValue {{ id: ParamId::{:?}, value: {:?} }},",
            v.id, v.value
        )
        .expect("a String takes writes");
    }
    s.push_str("];\n\n");
    let text = std::fs::read_to_string(workspace().join(PROFILE)).expect("the shipped profile");
    let profile = ProfileDocument::from_json(&text)
        .and_then(|d| d.to_profile())
        .expect("the shipped initial design is a valid profile");
    let frame = encode_frame_vec(&Request {
        seq: 1,
        command: Command::UploadProfile(profile),
    })
    .expect("one profile fits a frame");
    writeln!(
        s,
        "/// `UploadProfile` (sequence number 1) of the shipped initial design, as\n\
         /// a frame.\n\
         pub const UPLOAD_INITIAL_DESIGN: [u8; {}] = [",
        frame.len()
    )
    .expect("a String takes writes");
    for row in frame.chunks(16) {
        let bytes: Vec<String> = row.iter().map(|b| format!("0x{b:02x}")).collect();
        writeln!(s, "    {},", bytes.join(", ")).expect("a String takes writes");
    }
    s.push_str("];\n");
    s
}

#[test]
fn the_emulated_boards_constants_are_the_shipped_plant_and_profile() {
    let path = workspace().join(GENERATED);
    let wanted = render();
    if std::env::var("FWAV_REGENERATE").is_ok_and(|v| v == "1") {
        std::fs::write(&path, &wanted).expect("the file is writable");
    }
    let found = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        found == wanted,
        "{GENERATED} is not what actuator/plant.toml and {PROFILE} give: regenerate it with \
         FWAV_REGENERATE=1 cargo test -p fwav-e2e --test firmware_constants"
    );
}
