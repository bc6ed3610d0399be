//! `pressure.json`: the pressure jump per shell element over the last
//! flapping cycle, the structural discipline's load (read into
//! [`crate::topology::pressure::PressureHistory`]). One type for writing
//! and reading.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::aeroelastic::analysis::SystemResult;
use crate::file_format::{FileFormat, FormatError, ReadError};

/// The kind of file and the version this build reads and writes.
pub const FORMAT: FileFormat = FileFormat {
    file: "pressure.json",
    format: "fwav-pressure-history",
    version: 1,
};

/// What a system analysis writes as the description.
const DESCRIPTION: &str =
    "pressure jump (lower minus upper) per shell element over the last cycle, Pa";

/// A `pressure.json`: `{"format": "fwav-pressure-history",
/// "format_version": 1, "description": ..., "dt_s": 0.00227, "samples":
/// [[p_0, p_1, ...], ...]}`, one sample a step, sample `k` at `(k + 1) dt`
/// after the start of a period, pressures in Pa (lower minus upper
/// surface, positive along the element normal). Unknown keys are refused;
/// `description` may be left out.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PressureFile {
    /// Always [`FORMAT`]'s `format`.
    pub format: String,
    /// [`FORMAT`]'s `version`.
    pub format_version: u32,
    /// Free text: what the samples are.
    #[serde(default)]
    pub description: String,
    /// Time between samples, s.
    pub dt_s: f64,
    /// Pressure jump per element, one sample a step over one period, Pa.
    pub samples: Vec<Vec<f64>>,
}

impl PressureFile {
    /// The pressure history of a system analysis.
    pub fn of(result: &SystemResult) -> Self {
        Self::new(result.dt_s, result.pressure_history.clone())
    }

    /// A file of `samples` every `dt_s`.
    pub fn new(dt_s: f64, samples: Vec<Vec<f64>>) -> Self {
        Self {
            format: FORMAT.format.to_string(),
            format_version: FORMAT.version,
            description: DESCRIPTION.to_string(),
            dt_s,
            samples,
        }
    }

    /// The file's text.
    pub fn to_json(&self) -> Result<String, FormatError> {
        FORMAT.to_json(self, false)
    }

    /// Parses the text of a `pressure.json` (its header first).
    pub fn from_json(text: &str) -> Result<Self, FormatError> {
        FORMAT.parse(text)
    }

    /// Reads the `pressure.json` at `path`.
    pub fn read(path: &Path) -> Result<Self, ReadError> {
        FORMAT.read(path)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What is written reads back the same; another version is refused.
    #[test]
    fn round_trip_and_version() {
        let file = PressureFile::new(0.5, vec![vec![1.0, -2.0]]);
        let text = file.to_json().unwrap();
        assert_eq!(PressureFile::from_json(&text).unwrap(), file);
        let future = text.replace("\"format_version\":1", "\"format_version\":2");
        assert!(matches!(
            PressureFile::from_json(&future),
            Err(FormatError::UnsupportedVersion {
                found: Some(2),
                expected: 1,
                ..
            })
        ));
    }
}
