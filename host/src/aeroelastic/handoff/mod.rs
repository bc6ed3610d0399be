//! What a system analysis hands to the two disciplines, as files: the
//! mid-span section history (`section.json`, [`SectionFile`], the
//! aerodynamic discipline's input and `fwav aero2d --deformation`'s) and
//! the pressure history (`pressure.json`, [`PressureFile`], the structural
//! discipline's, read by
//! [`crate::topology::pressure::PressureHistory::from_json`]), plus the
//! step records as CSV (`steps.csv`). Each JSON file is one serde type used
//! for writing and reading, with a format name and version
//! ([`crate::file_format`]). `fwav system-analysis --out` and the MDOIS
//! driver write the same files ([`write()`]).
//!
//! May import: [`super::analysis`] (the result it hands on),
//! [`crate::file_format`] and [`crate::files`].

pub mod pressure;
pub mod section;

use std::path::Path;

use super::analysis::SystemResult;
use crate::file_format::FormatError;
use crate::files::{write_to, Existing, WriteError};

pub use pressure::PressureFile;
pub use section::SectionFile;

/// The files [`write()`] writes, in its order.
pub const FILES: [&str; 3] = ["section.json", "pressure.json", "steps.csv"];

/// Why the handoff files could not be written.
#[derive(Debug, thiserror::Error)]
pub enum HandoffError {
    /// A file's text could not be made.
    #[error(transparent)]
    Format(#[from] FormatError),
    /// A file could not be written.
    #[error(transparent)]
    Write(#[from] WriteError),
}

/// Writes `section.json`, `pressure.json` and `steps.csv` of `result` into
/// `dir` (which must exist), each atomically, over files there or not as
/// `existing` says.
pub fn write(dir: &Path, result: &SystemResult, existing: Existing) -> Result<(), HandoffError> {
    write_to(
        &dir.join(FILES[0]),
        SectionFile::of(result).to_json()?,
        existing,
    )?;
    write_to(
        &dir.join(FILES[1]),
        PressureFile::of(result).to_json()?,
        existing,
    )?;
    write_to(&dir.join(FILES[2]), steps_csv(result), existing)?;
    Ok(())
}

/// The `steps.csv` text: one row a time step.
pub fn steps_csv(result: &SystemResult) -> String {
    let mut csv = String::from(
        "time_s,fx_n,fy_n,fz_n,power_w,ct,cl,cp,drive_torque_nm,tip_dx_m,tip_dy_m,tip_dz_m,subiterations,residual\n",
    );
    for s in &result.steps {
        csv.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            s.time_s,
            s.force_n[0],
            s.force_n[1],
            s.force_n[2],
            s.power_w,
            s.ct,
            s.cl,
            s.cp,
            s.drive_torque_nm,
            s.tip_displacement_m[0],
            s.tip_displacement_m[1],
            s.tip_displacement_m[2],
            s.subiterations,
            s.residual
        ));
    }
    csv
}
