//! The JSON records a design cycle's stages leave under `cycle-N/`, and
//! their reading back: what the next stage, the summary, the final outputs
//! and a resumed run take from the files (never from memory), so a fresh
//! run and a resumed one compute from the same numbers.
//!
//! - [`system`]: `system.json` ([`SystemRecord`], versioned); the
//!   stage also leaves the handoff files of
//!   [`crate::aeroelastic::handoff`] beside it.
//! - [`kinematics`]: `kinematics.json` ([`KinematicRecord`]).
//! - [`topology`]: `topology.json` ([`TopologyRecord`]).
//!
//! May import: the result types of the analyses and disciplines, the file
//! formats ([`crate::file_format`], [`crate::aeroelastic::handoff`]),
//! [`super::stage`]'s design values and [`super::error`].

pub mod kinematics;
pub mod system;
pub mod topology;

use std::path::{Path, PathBuf};

use serde::de::DeserializeOwned;
use serde::Serialize;

use super::error::DesignError;

pub use kinematics::{load_kinematics, KinematicRecord};
pub use system::{load_system, SystemRecord};
pub use topology::{load_topology, TopologyRecord};

/// The directory of a cycle's stage files, relative to the run's.
pub fn cycle_dir(cycle: usize) -> String {
    format!("cycle-{cycle}")
}

/// A file of `cycle`'s stage files, relative to the run's directory.
pub fn cycle_file(cycle: usize, name: &str) -> String {
    format!("{}/{name}", cycle_dir(cycle))
}

/// The path of `name` among `cycle`'s stage files in the run's `dir`.
pub fn cycle_path(dir: &Path, cycle: usize, name: &str) -> PathBuf {
    dir.join(cycle_file(cycle, name))
}

/// Reads a JSON file of the run (`relative` to `dir`).
pub fn load_json<T: DeserializeOwned>(dir: &Path, relative: &str) -> Result<T, DesignError> {
    let path = dir.join(relative);
    let text = std::fs::read_to_string(&path).map_err(DesignError::io(&path))?;
    serde_json::from_str(&text).map_err(|e| DesignError::State {
        path,
        message: e.to_string(),
    })
}

/// The compact JSON text of a record, for the file `file`.
pub(crate) fn to_json<T: Serialize>(value: &T, file: &str) -> Result<String, DesignError> {
    serde_json::to_string(value).map_err(|e| DesignError::output(file, e))
}
