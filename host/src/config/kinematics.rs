//! The `[kinematics]` table: the initial flapping kinematics (the first
//! system analysis flies them), in Hz and degrees. Its type is
//! [`FlappingKinematics`] itself (SI inside, degrees in the file through
//! its serde); the declarations here check the degrees the file holds.

use crate::aeroelastic::kinematics::FlappingKinematics;
use fwav_settings::{Allowed, Interval, Setting, Table, Value};

/// The `[kinematics]` table's settings.
pub const KINEMATICS: Table<FlappingKinematics> = Table {
    name: "kinematics",
    doc: "The initial flapping kinematics (the first system analysis flies them).",
    settings: &[
        Setting {
            key: "frequency_hz",
            unit: "Hz",
            allowed: Allowed::Real(Interval::closed(0.1, 200.0)),
            doc: "Flapping frequency",
            value: |k| Value::Real(k.frequency),
        },
        Setting {
            key: "amplitude_deg",
            unit: "deg",
            allowed: Allowed::Real(Interval::above_up_to(0.0, 80.0)),
            doc: "Flapping amplitude (half the stroke), above 0: a wing that does not flap \
                  has no thrust, drive power or efficiency to design with (the run also \
                  stops at its first aerodynamic discipline if the initial kinematics give no \
                  net thrust)",
            value: |k| Value::Real(k.amplitude_deg()),
        },
        Setting {
            key: "mean_angle_deg",
            unit: "deg",
            allowed: Allowed::Real(Interval::closed(-60.0, 60.0)),
            doc: "Mean flapping angle",
            value: |k| Value::Real(k.mean_angle_deg()),
        },
        Setting {
            key: "stroke_plane_deg",
            unit: "deg",
            // Open: at 0 or 180 deg the wing sweeps in its own plane,
            // moves no air, and has no thrust, power or efficiency.
            allowed: Allowed::Real(Interval::open(0.0, 180.0)),
            doc: "Stroke-plane inclination (90: flapping across the flight direction; at 0 or 180 the wing would sweep in its own plane)",
            value: |k| Value::Real(k.stroke_plane_deg()),
        },
    ],
};
