//! The profile as a JSON document: what `fwav design` writes, what a person
//! edits and what `fwav upload` sends. One schema, defined here.
//!
//! Angles are in degrees and every key names its unit; the conversion to the
//! wire [`Profile`] (radians, `f32`) happens in [`ProfileDocument::to_profile`].
//!
//! ```json
//! {
//!   "format": "fwav-profile",
//!   "format_version": 1,
//!   "description": "initial design of the seed paper: 11 Hz, +-30 deg",
//!   "on_end": "hold",
//!   "segments": [
//!     { "frequency_hz": 11.0, "amplitude_deg": 30.0, "mean_deg": 0.0,
//!       "duration_s": 10.0, "ramp_s": 1.0, "downstroke_fraction": 0.5 }
//!   ]
//! }
//! ```
//! `mean_deg` and `ramp_s` default to 0, `downstroke_fraction` to 0.5,
//! `on_end` to `"hold"`, `description` to empty. Unknown keys are an error, so a
//! typo never passes silently.

use serde::{Deserialize, Serialize};

use crate::profile::{EndAction, Profile, Segment, MAX_SEGMENTS};

/// Value of the `format` key.
pub const FORMAT: &str = "fwav-profile";
/// Value of the `format_version` key this build reads and writes.
pub const FORMAT_VERSION: u32 = 1;

/// A profile file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProfileDocument {
    /// Always [`FORMAT`].
    pub format: String,
    /// [`FORMAT_VERSION`].
    pub format_version: u32,
    /// Free text: where the profile comes from.
    #[serde(default)]
    pub description: String,
    /// What happens after the last segment.
    #[serde(default)]
    pub on_end: EndAction,
    /// The segments, in order.
    pub segments: Vec<SegmentDocument>,
}

/// One segment of a [`ProfileDocument`]; see [`Segment`] for the meaning.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SegmentDocument {
    /// Flapping frequency, Hz.
    pub frequency_hz: f64,
    /// Peak amplitude, degrees.
    pub amplitude_deg: f64,
    /// Mean flapping angle, degrees.
    #[serde(default)]
    pub mean_deg: f64,
    /// Duration, s.
    pub duration_s: f64,
    /// Ramp time, s.
    #[serde(default)]
    pub ramp_s: f64,
    /// Fraction of the period on the downstroke.
    #[serde(default = "symmetric")]
    pub downstroke_fraction: f64,
}

fn symmetric() -> f64 {
    0.5
}

/// Why a JSON text is not a usable profile document.
#[derive(Debug, thiserror::Error)]
pub enum DocumentError {
    /// Not JSON, or a key is missing, unknown or of the wrong type; the
    /// message has the line and column.
    #[error("{0}")]
    Json(#[from] serde_json::Error),
    /// The `format` key is not [`FORMAT`].
    #[error("\"format\" is {found:?}, expected {FORMAT:?}: this is not an fwav profile")]
    WrongFormat {
        /// The value found.
        found: String,
    },
    /// A `format_version` this build does not read.
    #[error("\"format_version\" is {found}, this build reads version {FORMAT_VERSION}")]
    UnsupportedVersion {
        /// The value found.
        found: u32,
    },
    /// More segments than a device holds.
    #[error("{count} segments: a profile holds at most {MAX_SEGMENTS}")]
    TooManySegments {
        /// Segments in the document.
        count: usize,
    },
}

impl ProfileDocument {
    /// Parses and checks the header (format, version). Kinematic limits are
    /// checked separately, by [`Profile::validate`] on the converted profile.
    pub fn from_json(text: &str) -> Result<Self, DocumentError> {
        let doc: Self = serde_json::from_str(text)?;
        if doc.format != FORMAT {
            return Err(DocumentError::WrongFormat { found: doc.format });
        }
        if doc.format_version != FORMAT_VERSION {
            return Err(DocumentError::UnsupportedVersion {
                found: doc.format_version,
            });
        }
        Ok(doc)
    }

    /// Pretty-printed JSON.
    pub fn to_json_pretty(&self) -> String {
        // Serializing plain structs of numbers and strings cannot fail.
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// The wire form (radians, `f32`).
    pub fn to_profile(&self) -> Result<Profile, DocumentError> {
        let mut profile = Profile {
            segments: heapless::Vec::new(),
            on_end: self.on_end,
        };
        for s in &self.segments {
            let segment = Segment {
                frequency_hz: s.frequency_hz as f32,
                amplitude_rad: s.amplitude_deg.to_radians() as f32,
                mean_rad: s.mean_deg.to_radians() as f32,
                duration_s: s.duration_s as f32,
                ramp_s: s.ramp_s as f32,
                downstroke_fraction: s.downstroke_fraction as f32,
            };
            profile
                .segments
                .push(segment)
                .map_err(|_| DocumentError::TooManySegments {
                    count: self.segments.len(),
                })?;
        }
        Ok(profile)
    }

    /// The document of a wire profile (e.g. one read back from a device).
    /// Values are rounded to 7 significant digits, the precision of the `f32`
    /// they came from, so that `30 deg` does not print as `30.000001` after
    /// the round trip through `f32` radians.
    pub fn from_profile(profile: &Profile, description: impl Into<String>) -> Self {
        let round = |x: f64| round_significant(x, 7);
        Self {
            format: FORMAT.to_owned(),
            format_version: FORMAT_VERSION,
            description: description.into(),
            on_end: profile.on_end,
            segments: profile
                .segments
                .iter()
                .map(|s| SegmentDocument {
                    frequency_hz: round(f64::from(s.frequency_hz)),
                    amplitude_deg: round(f64::from(s.amplitude_rad).to_degrees()),
                    mean_deg: round(f64::from(s.mean_rad).to_degrees()),
                    duration_s: round(f64::from(s.duration_s)),
                    ramp_s: round(f64::from(s.ramp_s)),
                    downstroke_fraction: round(f64::from(s.downstroke_fraction)),
                })
                .collect(),
        }
    }
}

/// `x` rounded to `digits` significant decimal digits.
fn round_significant(x: f64, digits: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let scale = 10f64.powi(digits - 1 - x.abs().log10().floor() as i32);
    (x * scale).round() / scale
}
