//! Profile files on disk: read, convert to the wire form, check against a
//! flight controller's limits; and the profile of optimized harmonic
//! kinematics ([`ProfileFile::from_kinematics`]), as `kinematics.json` is
//! written for `fwav upload`.
//!
//! The JSON schema is defined once, in [`fwav_protocol::document`].

use std::path::{Path, PathBuf};

use fwav_protocol::document::{
    DocumentError, ProfileDocument, SegmentDocument, FORMAT, FORMAT_VERSION,
};
use fwav_protocol::{EndAction, Limits, Profile, ProfileError, RAMP_PEAK_RATE_FACTOR};

/// Duration of the single segment of a kinematics profile, s: long enough
/// for any test flight; after it the profile holds (`on_end = "hold"`).
pub const KINEMATICS_DURATION_S: f64 = 60.0;
/// Shortest ramp from rest of a kinematics profile, s (the seed paper's
/// initial design ramps over 1 s too).
pub const KINEMATICS_MIN_RAMP_S: f64 = 1.0;

/// Why a profile file could not be used.
#[derive(Debug, thiserror::Error)]
pub enum ProfileFileError {
    /// The file could not be read.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The file is not a valid profile document.
    #[error("{path}: {source}")]
    Document {
        /// The file.
        path: PathBuf,
        /// What is wrong, with line and column where it applies.
        source: DocumentError,
    },
    /// The file could not be written.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The kinematics are outside the flight controller's limits; every
    /// violation is listed.
    #[error(
        "{path}: the profile violates the flight controller's limits: {}",
        list(violations)
    )]
    OutOfLimits {
        /// The file it was meant for.
        path: PathBuf,
        /// Every violation.
        violations: Vec<ProfileError>,
    },
}

fn list(violations: &[ProfileError]) -> String {
    violations
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join("; ")
}

/// A profile file, read and converted.
#[derive(Clone, Debug)]
pub struct ProfileFile {
    /// Where it came from.
    pub path: PathBuf,
    /// The document as written (degrees).
    pub document: ProfileDocument,
    /// The wire form (radians).
    pub profile: Profile,
}

impl ProfileFile {
    /// Reads and converts `path`. Limits are not checked here; see
    /// [`ProfileFile::violations`].
    pub fn load(path: impl AsRef<Path>) -> Result<Self, ProfileFileError> {
        let path = path.as_ref().to_path_buf();
        let text = std::fs::read_to_string(&path).map_err(|source| ProfileFileError::Read {
            path: path.clone(),
            source,
        })?;
        let document_error = |source| ProfileFileError::Document {
            path: path.clone(),
            source,
        };
        let document = ProfileDocument::from_json(&text).map_err(document_error)?;
        let profile = document.to_profile().map_err(document_error)?;
        Ok(Self {
            path,
            document,
            profile,
        })
    }

    /// Every way the profile violates `limits` (empty if it can be flown).
    pub fn violations(&self, limits: &Limits) -> Vec<ProfileError> {
        let mut all = Vec::new();
        self.profile.for_each_violation(limits, |e| all.push(e));
        all
    }
}

/// Ramp time from rest to `amplitude_deg` and `mean_deg` within the angle
/// slew limit of `limits`: the smoothstep's peak rate
/// `RAMP_PEAK_RATE_FACTOR * max(|A|, |mean|) / ramp` at most 90% of
/// `max_angle_slew_rad_s`, at least [`KINEMATICS_MIN_RAMP_S`], rounded up to
/// 0.1 s. A limit that is zero or not a number gives the minimum ramp (the
/// violation is then reported by the limit check).
pub fn ramp_from_rest_s(amplitude_deg: f64, mean_deg: f64, limits: &Limits) -> f64 {
    let slew_deg_s = f64::from(limits.max_angle_slew_rad_s).to_degrees();
    let change = amplitude_deg.abs().max(mean_deg.abs());
    let needed = f64::from(RAMP_PEAK_RATE_FACTOR) * change / (0.9 * slew_deg_s);
    let ramp = if needed.is_finite() {
        needed.max(KINEMATICS_MIN_RAMP_S)
    } else {
        KINEMATICS_MIN_RAMP_S
    };
    (ramp * 10.0).ceil() / 10.0
}

impl ProfileFile {
    /// The profile of harmonic kinematics `phi(t) = mean + A sin(2 pi f t)`
    /// (frequency in Hz, amplitude and mean angle in degrees), meant for
    /// `path`: one symmetric segment (downstroke fraction 0.5) of
    /// [`KINEMATICS_DURATION_S`], ramped up from rest over
    /// [`ramp_from_rest_s`], then held. `source` says where the kinematics
    /// come from (e.g. "MDOIS cycle 3, RSM + NSGA-II candidate"); the
    /// description adds the numbers. Refused with every violation of
    /// `limits` ([`ProfileFileError::OutOfLimits`]).
    pub fn from_kinematics(
        path: impl AsRef<Path>,
        frequency_hz: f64,
        amplitude_deg: f64,
        mean_deg: f64,
        source: &str,
        limits: &Limits,
    ) -> Result<Self, ProfileFileError> {
        let path = path.as_ref().to_path_buf();
        let ramp_s = ramp_from_rest_s(amplitude_deg, mean_deg, limits);
        let document = ProfileDocument {
            format: FORMAT.to_owned(),
            format_version: FORMAT_VERSION,
            description: format!(
                "{source}: {frequency_hz} Hz, +-{amplitude_deg} deg harmonic flapping about a \
                 mean of {mean_deg} deg, ramped up from rest over the first {ramp_s} s of a \
                 {KINEMATICS_DURATION_S} s segment, then held."
            ),
            on_end: EndAction::Hold,
            segments: vec![SegmentDocument {
                frequency_hz,
                amplitude_deg,
                mean_deg,
                duration_s: KINEMATICS_DURATION_S,
                ramp_s,
                downstroke_fraction: 0.5,
            }],
        };
        let profile = document
            .to_profile()
            .map_err(|source| ProfileFileError::Document {
                path: path.clone(),
                source,
            })?;
        let file = Self {
            path,
            document,
            profile,
        };
        let violations = file.violations(limits);
        if violations.is_empty() {
            Ok(file)
        } else {
            Err(ProfileFileError::OutOfLimits {
                path: file.path,
                violations,
            })
        }
    }

    /// Writes the document as pretty JSON to [`ProfileFile::path`], through
    /// a temporary file beside it and a rename, so a reader never sees half
    /// a file.
    pub fn save(&self) -> Result<(), ProfileFileError> {
        let write_error = |source| ProfileFileError::Write {
            path: self.path.clone(),
            source,
        };
        let mut temporary = self.path.clone().into_os_string();
        temporary.push(".tmp");
        let temporary = PathBuf::from(temporary);
        let mut text = self.document.to_json_pretty();
        text.push('\n');
        std::fs::write(&temporary, text).map_err(write_error)?;
        std::fs::rename(&temporary, &self.path).map_err(write_error)
    }
}
