//! A 2D run's load histories as CSV, for a spreadsheet or a plotting
//! script: `time, cl, ct, cp` (time in chords travelled, coefficients on
//! `1/2 rho U^2 c`, `U^3` for the power), one row a sample.

use std::fmt::Write as _;
use std::path::Path;

use crate::aero2d::history::History;
use crate::files::{write_new, WriteError};

/// Writes `history` to `path`, a new file: an existing one is refused
/// ([`WriteError::Exists`]), never overwritten, and the file appears
/// whole ([`write_new`]).
///
/// # Errors
/// [`WriteError`]: the name is taken, or the file system refused.
pub fn write_history_csv(history: &History, path: &Path) -> Result<(), WriteError> {
    let mut text = String::from("time,cl,ct,cp\n");
    for (((t, cl), ct), cp) in history
        .time
        .iter()
        .zip(&history.cl)
        .zip(&history.ct)
        .zip(&history.cp)
    {
        let _ = writeln!(text, "{t},{cl},{ct},{cp}");
    }
    write_new(path, text)
}
