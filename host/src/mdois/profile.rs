//! The final kinematics as the flight controller's profile file
//! (`kinematics.json`, the `fwav-profile` format of
//! [`fwav_protocol::document`], read by `fwav profile check` and sent by
//! `fwav upload`).
//!
//! HOOK: [`write_kinematics`] is a stand-in. The conversion with the
//! actuator feasibility check (can the motor, gearbox and spring fly these
//! kinematics?) is built elsewhere and replaces this function's body; the
//! driver calls only this function, once, with the final design.

use std::path::{Path, PathBuf};

use fwav_protocol::document::{ProfileDocument, SegmentDocument, FORMAT, FORMAT_VERSION};
use fwav_protocol::EndAction;

use crate::files::write_atomic;

use super::error::DesignError;
use super::stage::KinematicValues;

/// The profile file's name in the run's directory.
pub const KINEMATICS_FILE: &str = "kinematics.json";

/// Seconds of the one segment the stand-in writes (held at its end).
const SEGMENT_S: f64 = 20.0;
/// Seconds of its ramp from rest.
const RAMP_S: f64 = 1.0;

/// `x` to 6 significant digits (the optimizer's last digits are noise,
/// and the flight controller flies `f32`).
fn round(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let scale = 10f64.powi(5 - x.abs().log10().floor() as i32);
    (x * scale).round() / scale
}

/// HOOK (to be replaced, see the module docs): writes `kinematics` to
/// `dir/kinematics.json` as one harmonic segment (values to 6
/// significant digits, ramped from rest over 1 s, 20 s long, then held),
/// without any actuator feasibility check.
/// The stroke plane is a mounting angle, not a motor command: it goes into
/// the description only. Returns the file's path.
pub fn write_kinematics(
    dir: &Path,
    kinematics: &KinematicValues,
    description: &str,
) -> Result<PathBuf, DesignError> {
    let document = ProfileDocument {
        format: FORMAT.to_string(),
        format_version: FORMAT_VERSION,
        description: format!(
            "{description} Stroke plane {:.1} deg (set by the mounting). Written without the actuator feasibility check.",
            kinematics.stroke_plane_deg
        ),
        on_end: EndAction::Hold,
        segments: vec![SegmentDocument {
            frequency_hz: round(kinematics.frequency_hz),
            amplitude_deg: round(kinematics.amplitude_deg),
            mean_deg: round(kinematics.mean_angle_deg),
            duration_s: SEGMENT_S,
            ramp_s: RAMP_S,
            downstroke_fraction: 0.5,
        }],
    };
    Ok(write_atomic(
        dir,
        KINEMATICS_FILE,
        document.to_json_pretty(),
    )?)
}
