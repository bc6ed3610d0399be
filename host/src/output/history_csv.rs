//! A 2D run's load histories as CSV, for a spreadsheet or a plotting
//! script: `time, cl, ct, cp` (time in chords travelled, coefficients on
//! `1/2 rho U^2 c`, `U^3` for the power), one row a sample.

use std::io::Write;
use std::path::Path;

use crate::aero2d::history::History;

/// Writes `history` to `path`, a new file: an existing one is refused
/// (`ErrorKind::AlreadyExists`), never overwritten.
///
/// # Errors
/// The file system's.
pub fn write_history_csv(history: &History, path: &Path) -> std::io::Result<()> {
    let file = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)?;
    let mut out = std::io::BufWriter::new(file);
    writeln!(out, "time,cl,ct,cp")?;
    for (((t, cl), ct), cp) in history
        .time
        .iter()
        .zip(&history.cl)
        .zip(&history.ct)
        .zip(&history.cp)
    {
        writeln!(out, "{t},{cl},{ct},{cp}")?;
    }
    out.flush()
}
