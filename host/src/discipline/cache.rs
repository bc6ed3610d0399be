//! Evaluations keyed by their inputs, so a rerun (or a resumed design
//! run) reuses every 2D analysis already done. The key is a 64-bit FNV-1a
//! hash of the evaluation's inputs serialized as JSON (the section case and
//! the design, in Hz and degrees as [`FlappingKinematics`] writes them), stable across runs and platforms; the file is JSON,
//! written atomically.
//!
//! The case is keyed as its model reads it ([`SectionCase::modelled`]):
//! the flow model and its plate and grid are part of the key (an LDVM
//! result is never served for a Navier–Stokes request, nor one grid's for
//! another's, nor one deformation's for another's). An LDVM case is written as
//! before the model was chosen, so older cache files still match; a
//! Navier–Stokes case carries the revision of that model's results
//! ([`NS_RESULTS_REVISION`]), so results it no longer gives are not served.

use std::collections::HashMap;
use std::path::Path;
use std::sync::Mutex;

use serde::{Deserialize, Serialize};

use crate::aeroelastic::kinematics::FlappingKinematics;

use super::section::{SectionCase, SectionResult};
use super::section_model::SectionFlowModel;

/// Why the cache file could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum CacheError {
    /// Reading or writing the file.
    #[error("evaluation cache {path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// Cause.
        source: std::io::Error,
    },
    /// Not a cache file.
    #[error("evaluation cache {path}: {message}")]
    Format {
        /// The file.
        path: String,
        /// What is wrong.
        message: String,
    },
}

/// Finished evaluations by key.
#[derive(Debug, Default)]
pub struct EvaluationCache {
    entries: Mutex<HashMap<String, SectionResult>>,
}

#[derive(Serialize, Deserialize)]
struct CacheFile {
    format: String,
    entries: HashMap<String, SectionResult>,
}

const FORMAT: &str = "fwav-evaluations-2";

impl EvaluationCache {
    /// An empty cache.
    pub fn new() -> Self {
        Self::default()
    }

    /// Loads `path`; a missing file is an empty cache.
    pub fn load(path: &Path) -> Result<Self, CacheError> {
        let text = match std::fs::read_to_string(path) {
            Ok(t) => t,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Self::new()),
            Err(source) => {
                return Err(CacheError::Io {
                    path: path.display().to_string(),
                    source,
                })
            }
        };
        let file: CacheFile = serde_json::from_str(&text).map_err(|e| CacheError::Format {
            path: path.display().to_string(),
            message: e.to_string(),
        })?;
        if file.format != FORMAT {
            return Err(CacheError::Format {
                path: path.display().to_string(),
                message: format!(
                    "format {:?}, expected {FORMAT:?} (results of an older version: delete the file to recompute)",
                    file.format
                ),
            });
        }
        Ok(Self {
            entries: Mutex::new(file.entries),
        })
    }

    /// Writes the cache to `path` atomically.
    pub fn save(&self, path: &Path) -> Result<(), CacheError> {
        let io = |source| CacheError::Io {
            path: path.display().to_string(),
            source,
        };
        let entries = self.lock().clone();
        let text = serde_json::to_string(&CacheFile {
            format: FORMAT.to_string(),
            entries,
        })
        .map_err(|e| CacheError::Format {
            path: path.display().to_string(),
            message: e.to_string(),
        })?;
        let temporary = path.with_extension("partial");
        std::fs::write(&temporary, text).map_err(io)?;
        std::fs::rename(&temporary, path).map_err(io)
    }

    /// Number of stored evaluations.
    pub fn len(&self) -> usize {
        self.lock().len()
    }

    /// Whether nothing is stored.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The stored result for these inputs, if any.
    pub fn get(&self, case: &SectionCase, design: &FlappingKinematics) -> Option<SectionResult> {
        self.lock().get(&key(case, design)).copied()
    }

    /// Stores a result.
    pub fn insert(&self, case: &SectionCase, design: &FlappingKinematics, result: SectionResult) {
        self.lock().insert(key(case, design), result);
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<String, SectionResult>> {
        // A panic while holding the lock cannot leave the map half
        // written (single inserts), so a poisoned lock is still usable.
        self.entries.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// The revision of the Navier–Stokes model's results, part of its keys:
/// raised when the same inputs give other results, so that a cache file
/// never serves the former ones. 2 (2026-12-04): the input power counts
/// the section's motion relative to steady flight only (before, the
/// flight's `-T U` too: `aero2d/viscous/march.rs`).
pub const NS_RESULTS_REVISION: u32 = 2;

/// The key of an evaluation: FNV-1a of its inputs' JSON (the case as its
/// model reads it; a Navier–Stokes case with [`NS_RESULTS_REVISION`]),
/// hex.
pub fn key(case: &SectionCase, design: &FlappingKinematics) -> String {
    let mut inputs = serde_json::json!({ "case": case.modelled(), "design": design });
    if matches!(case.model, SectionFlowModel::Ns(_)) {
        inputs["ns_results"] = NS_RESULTS_REVISION.into();
    }
    fnv1a(&inputs.to_string())
}

/// The 64-bit FNV-1a hash of `text`, hex.
fn fnv1a(text: &str) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in text.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    format!("{h:016x}")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An LDVM case keeps the key it had before the results' revision
    /// (older cache files still serve it); a Navier–Stokes case's key
    /// changes with the revision, so a result of the former input power
    /// is not served.
    #[test]
    fn only_navier_stokes_keys_carry_the_results_revision() {
        let design = FlappingKinematics::from_degrees([11.0, 30.0, 0.0, 90.0]);
        let ldvm = SectionCase::fwav_mid_span();
        let ns = SectionCase {
            model: SectionFlowModel::ns(0.04),
            ..SectionCase::fwav_mid_span()
        };
        let unrevised = |case: &SectionCase| {
            fnv1a(&serde_json::json!({ "case": case.modelled(), "design": design }).to_string())
        };
        assert_eq!(key(&ldvm, &design), unrevised(&ldvm));
        assert_ne!(key(&ns, &design), unrevised(&ns));
    }
}
