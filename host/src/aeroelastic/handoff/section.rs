//! `section.json`: the mid-span section's mid-line over the last flapping
//! cycle, the aerodynamic discipline's input (and `fwav aero2d
//! --deformation`'s). One type for writing and reading.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::aeroelastic::analysis::SystemResult;
use crate::file_format::{FileFormat, FormatError, ReadError};

/// The kind of file and the version this build reads and writes.
pub const FORMAT: FileFormat = FileFormat {
    file: "section.json",
    format: "fwav-section-history",
    version: 1,
};

/// What a system analysis writes as the description.
const DESCRIPTION: &str = "mid-span section (mid-line x, y in chords, flapping frame, leading edge undeformed at (0, 0)) over the last cycle; sample k at (k + 1) dt after a cycle start, where the flapping angle is mean + amplitude cos(2 pi f t)";

/// A `section.json`: `{"format": "fwav-section-history", "format_version":
/// 1, "description": ..., "period_s": ..., "samples": [[[x, y], ...], ...]}`.
/// Unknown keys are refused; `description` may be left out, and so may
/// `period_s` (a deformation written by hand for `fwav aero2d` has no
/// period in seconds: the reader spreads the samples over its own period).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SectionFile {
    /// Always [`FORMAT`]'s `format`.
    pub format: String,
    /// [`FORMAT`]'s `version`.
    pub format_version: u32,
    /// Free text: what the samples are.
    #[serde(default)]
    pub description: String,
    /// The period the samples cover, s.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub period_s: Option<f64>,
    /// Mid-line samples over one cycle, equally spaced in time, chords
    /// (see [`SystemResult::section_history`]).
    pub samples: Vec<Vec<[f64; 2]>>,
}

impl SectionFile {
    /// The section history of a system analysis.
    pub fn of(result: &SystemResult) -> Self {
        Self {
            format: FORMAT.format.to_string(),
            format_version: FORMAT.version,
            description: DESCRIPTION.to_string(),
            period_s: Some(result.dt_s * result.section_history.len() as f64),
            samples: result.section_history.clone(),
        }
    }

    /// The file's text.
    pub fn to_json(&self) -> Result<String, FormatError> {
        FORMAT.to_json(self, false)
    }

    /// Parses the text of a `section.json` (its header first).
    pub fn from_json(text: &str) -> Result<Self, FormatError> {
        FORMAT.parse(text)
    }

    /// Reads the `section.json` at `path`.
    pub fn read(path: &Path) -> Result<Self, ReadError> {
        FORMAT.read(path)
    }

    /// The samples as `(x, y)` points, as the 2D solvers take them.
    pub fn points(&self) -> Vec<Vec<(f64, f64)>> {
        self.samples
            .iter()
            .map(|s| s.iter().map(|&[x, y]| (x, y)).collect())
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What is written reads back the same; the header is checked and an
    /// unknown key is refused.
    #[test]
    fn round_trip_and_header() {
        let file = SectionFile {
            format: FORMAT.format.into(),
            format_version: FORMAT.version,
            description: "d".into(),
            period_s: Some(0.1),
            samples: vec![vec![[0.0, 0.0], [1.0, 0.01]]],
        };
        let text = file.to_json().unwrap();
        assert_eq!(SectionFile::from_json(&text).unwrap(), file);
        let old = r#"{"description": "d", "period_s": 0.1, "samples": [[[0, 0], [1, 0]]]}"#;
        assert!(matches!(
            SectionFile::from_json(old),
            Err(FormatError::WrongFormat { found: None, .. })
        ));
        let typo = text.replace("\"samples\"", "\"sample\"");
        assert!(matches!(
            SectionFile::from_json(&typo),
            Err(FormatError::Json { .. })
        ));
    }
}
