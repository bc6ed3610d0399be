//! The header of fwav's versioned JSON files: every file one stage hands
//! to another (`section.json`, `pressure.json`, `system.json`,
//! `summary.json`) begins with a `format` name and a `format_version`,
//! like the profile file of [`fwav_protocol::document`]. A [`FileFormat`]
//! names one kind of file and the version this build reads and writes;
//! reading checks the header before the body, so a file of another kind or
//! version is refused with a [`FormatError`] that says which, instead of a
//! message about a missing key.
//!
//! This module imports nothing of the crate; the file types beside their
//! producers use it.

use std::path::{Path, PathBuf};

use serde::de::{DeserializeOwned, IgnoredAny};
use serde::Deserialize;

/// One kind of versioned file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FileFormat {
    /// The file's usual name, for messages (`"section.json"`).
    pub file: &'static str,
    /// The value of its `format` key.
    pub format: &'static str,
    /// The `format_version` this build reads and writes.
    pub version: u32,
}

/// Why a text is not a readable file of a [`FileFormat`].
#[derive(Debug, thiserror::Error)]
pub enum FormatError {
    /// Not JSON, or a key is missing, unknown or of the wrong type (the
    /// message has the line and column).
    #[error("{file}: {}{error}", not_json(error))]
    Json {
        /// The kind of file, by its usual name.
        file: &'static str,
        /// The parser's complaint.
        error: serde_json::Error,
    },
    /// The `format` key is missing or names another kind of file.
    #[error("{file}: \"format\" is {}, expected {expected:?}: not a {file} of fwav", shown(.found.as_deref()))]
    WrongFormat {
        /// The kind of file expected.
        file: &'static str,
        /// The `format` found (`None`: no such key).
        found: Option<String>,
        /// The `format` expected.
        expected: &'static str,
    },
    /// A `format_version` this build does not read.
    #[error("{file}: \"format_version\" is {}, this build reads version {expected}", .found.map_or_else(|| "missing or not a number".to_string(), |v| v.to_string()))]
    UnsupportedVersion {
        /// The kind of file.
        file: &'static str,
        /// The version found (`None`: no such key).
        found: Option<u64>,
        /// The version this build reads.
        expected: u32,
    },
}

/// Why a versioned file could not be read.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    /// The file could not be read.
    #[error("reading {}: {error}", .path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        error: std::io::Error,
    },
    /// Its text is not a file of the format (or not of this version).
    #[error("{}: {error}", .path.display())]
    Format {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        error: FormatError,
    },
}

/// "not JSON: " before a parser's complaint about the syntax (a CSV or a
/// picture given for a JSON file), nothing before one about the data.
fn not_json(error: &serde_json::Error) -> &'static str {
    match error.classify() {
        serde_json::error::Category::Syntax | serde_json::error::Category::Eof => "not JSON: ",
        _ => "",
    }
}

/// A header value as a message shows it.
fn shown(value: Option<&str>) -> String {
    value.map_or_else(
        || "missing or not of its type".to_string(),
        |v| format!("{v:?}"),
    )
}

/// The header alone; every other key is skipped.
#[derive(Deserialize)]
struct Header {
    format: Option<IgnoredOr<String>>,
    format_version: Option<IgnoredOr<u64>>,
}

/// A header value, or something else in its place (reported as such).
#[derive(Deserialize)]
#[serde(untagged)]
enum IgnoredOr<T> {
    Value(T),
    Other(IgnoredAny),
}

impl<T> IgnoredOr<T> {
    fn value(self) -> Option<T> {
        match self {
            IgnoredOr::Value(v) => Some(v),
            IgnoredOr::Other(_) => None,
        }
    }
}

impl FileFormat {
    /// Checks the header of `text`: its `format` and `format_version`.
    pub fn check(&self, text: &str) -> Result<(), FormatError> {
        let header: Header = serde_json::from_str(text).map_err(|error| FormatError::Json {
            file: self.file,
            error,
        })?;
        let format = header.format.and_then(IgnoredOr::value);
        if format.as_deref() != Some(self.format) {
            return Err(FormatError::WrongFormat {
                file: self.file,
                found: format,
                expected: self.format,
            });
        }
        let version = header.format_version.and_then(IgnoredOr::value);
        if version != Some(u64::from(self.version)) {
            return Err(FormatError::UnsupportedVersion {
                file: self.file,
                found: version,
                expected: self.version,
            });
        }
        Ok(())
    }

    /// Checks the header of `text`, then reads the whole file.
    pub fn parse<T: DeserializeOwned>(&self, text: &str) -> Result<T, FormatError> {
        self.check(text)?;
        serde_json::from_str(text).map_err(|error| FormatError::Json {
            file: self.file,
            error,
        })
    }

    /// Reads the file at `path` (its header first).
    pub fn read<T: DeserializeOwned>(&self, path: &Path) -> Result<T, ReadError> {
        let text = std::fs::read_to_string(path).map_err(|error| ReadError::Io {
            path: path.to_path_buf(),
            error,
        })?;
        self.parse(&text).map_err(|error| ReadError::Format {
            path: path.to_path_buf(),
            error,
        })
    }

    /// The text of `value` (compact, or pretty-printed for files a person
    /// reads).
    pub fn to_json<T: serde::Serialize>(
        &self,
        value: &T,
        pretty: bool,
    ) -> Result<String, FormatError> {
        let text = if pretty {
            serde_json::to_string_pretty(value)
        } else {
            serde_json::to_string(value)
        };
        text.map_err(|error| FormatError::Json {
            file: self.file,
            error,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const KIND: FileFormat = FileFormat {
        file: "thing.json",
        format: "fwav-thing",
        version: 2,
    };

    #[derive(Debug, Deserialize)]
    #[allow(dead_code)]
    struct Thing {
        format: String,
        format_version: u32,
        value: f64,
    }

    /// A file of the kind and version reads; another kind, another
    /// version, a missing header and bad JSON are each their own error,
    /// naming the file kind and what was found and expected.
    #[test]
    fn reads_its_own_and_names_the_rest() {
        let ok: Thing = KIND
            .parse(r#"{"format": "fwav-thing", "format_version": 2, "value": 1.5}"#)
            .unwrap();
        assert_eq!(ok.value, 1.5);
        let e = KIND
            .parse::<Thing>(r#"{"format": "fwav-other", "format_version": 2}"#)
            .unwrap_err();
        assert!(
            matches!(e, FormatError::WrongFormat { found: Some(ref f), .. } if f == "fwav-other")
        );
        assert!(e.to_string().contains("thing.json"), "{e}");
        let e = KIND
            .parse::<Thing>(r#"{"format": "fwav-thing", "format_version": 3, "value": 1}"#)
            .unwrap_err();
        assert!(matches!(
            e,
            FormatError::UnsupportedVersion {
                found: Some(3),
                expected: 2,
                ..
            }
        ));
        assert!(
            e.to_string().contains("is 3, this build reads version 2"),
            "{e}"
        );
        let e = KIND.parse::<Thing>(r#"{"value": 1}"#).unwrap_err();
        assert!(matches!(e, FormatError::WrongFormat { found: None, .. }));
        assert!(e.to_string().contains("missing"), "{e}");
        let e = KIND
            .parse::<Thing>(r#"{"format": "fwav-thing", "format_version": "2"}"#)
            .unwrap_err();
        assert!(matches!(
            e,
            FormatError::UnsupportedVersion { found: None, .. }
        ));
        assert!(matches!(
            KIND.parse::<Thing>("{").unwrap_err(),
            FormatError::Json { .. }
        ));
        // A CSV given for the JSON file is called what it is not; a JSON
        // file with a key of the wrong type is not.
        let e = KIND.parse::<Thing>("time_s,fx_n\n0,1\n").unwrap_err();
        assert!(e.to_string().starts_with("thing.json: not JSON: "), "{e}");
        let e = KIND
            .parse::<Thing>(r#"{"format": "fwav-thing", "format_version": 2, "value": []}"#)
            .unwrap_err();
        assert!(!e.to_string().contains("not JSON"), "{e}");
    }
}
