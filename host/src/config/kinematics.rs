//! The `[kinematics]` table: the initial flapping kinematics (the first
//! system analysis flies them), in Hz and degrees.

use fwav_settings::{Allowed, Interval, Setting, Table, Value};
use serde::{Deserialize, Serialize};

use crate::aeroelastic::kinematics::FlappingKinematics;

/// The `[kinematics]` table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct KinematicsConfig {
    /// Flapping frequency, Hz.
    pub frequency_hz: f64,
    /// Flapping amplitude, degrees.
    pub amplitude_deg: f64,
    /// Mean flapping angle, degrees.
    pub mean_angle_deg: f64,
    /// Stroke-plane inclination, degrees.
    pub stroke_plane_deg: f64,
}

impl Default for KinematicsConfig {
    /// [`FlappingKinematics::INITIAL`] in degrees as a person types them
    /// (11 Hz, ±30°, 0°, 90°; `to_degrees` of the radians would give
    /// 29.999999999999996°, which `fwav init` would then write).
    fn default() -> Self {
        Self {
            frequency_hz: FlappingKinematics::INITIAL.frequency,
            amplitude_deg: 30.0,
            mean_angle_deg: 0.0,
            stroke_plane_deg: 90.0,
        }
    }
}

impl KinematicsConfig {
    /// The kinematics in SI.
    pub fn si(&self) -> FlappingKinematics {
        FlappingKinematics {
            frequency: self.frequency_hz,
            amplitude: self.amplitude_deg.to_radians(),
            mean_angle: self.mean_angle_deg.to_radians(),
            stroke_plane: self.stroke_plane_deg.to_radians(),
        }
    }
}

/// The `[kinematics]` table's settings.
pub const KINEMATICS: Table<KinematicsConfig> = Table {
    name: "kinematics",
    doc: "The initial flapping kinematics (the first system analysis flies them).",
    settings: &[
        Setting {
            key: "frequency_hz",
            unit: "Hz",
            allowed: Allowed::Real(Interval::closed(0.1, 200.0)),
            doc: "Flapping frequency",
            value: |k| Value::Real(k.frequency_hz),
        },
        Setting {
            key: "amplitude_deg",
            unit: "deg",
            allowed: Allowed::Real(Interval::closed(0.0, 80.0)),
            doc: "Flapping amplitude (half the stroke)",
            value: |k| Value::Real(k.amplitude_deg),
        },
        Setting {
            key: "mean_angle_deg",
            unit: "deg",
            allowed: Allowed::Real(Interval::closed(-60.0, 60.0)),
            doc: "Mean flapping angle",
            value: |k| Value::Real(k.mean_angle_deg),
        },
        Setting {
            key: "stroke_plane_deg",
            unit: "deg",
            allowed: Allowed::Real(Interval::closed(0.0, 180.0)),
            doc: "Stroke-plane inclination (90: flapping across the flight direction)",
            value: |k| Value::Real(k.stroke_plane_deg),
        },
    ],
};
