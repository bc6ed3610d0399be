//! Profile files on disk: read, convert to the wire form, check against a
//! flight controller's limits.
//!
//! The JSON schema is defined once, in [`fwav_protocol::document`].

use std::path::{Path, PathBuf};

use fwav_protocol::document::{DocumentError, ProfileDocument};
use fwav_protocol::{Limits, Profile, ProfileError};

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
