//! A study's files for people: `results.csv` ([`table`]), a PNG of the
//! chosen outputs against each varied key ([`plot`]) and `report.md`
//! ([`report`]). They render [`super::results`]; nothing here computes or
//! runs a case.
//!
//! May import: [`crate::output`]'s drawing tools, [`crate::files`], the
//! study's state and results.

pub mod plot;
pub mod report;
pub mod table;

use std::path::{Path, PathBuf};

use crate::files::write_atomic;

use super::directory::read;
use super::error::StudyError;
use super::results::{collect, Output};

/// The report's file name in the study's directory.
pub const REPORT_FILE: &str = "report.md";

/// The pictures' directory in the study's directory.
pub const PLOTS_DIR: &str = "plots";

/// The files a report wrote.
#[derive(Clone, Debug, PartialEq)]
pub struct ReportFiles {
    /// `results.csv`.
    pub results: PathBuf,
    /// `report.md`.
    pub report: PathBuf,
    /// Each varied key's picture.
    pub plots: Vec<PathBuf>,
    /// Cases finished, of all.
    pub finished: usize,
    /// All cases.
    pub cases: usize,
}

/// A key as a file name (`wing.semi_span_m` stays as it is; anything but
/// letters, digits, `.`, `-` and `_` becomes `_`).
fn file_stem(key: &str) -> String {
    key.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "._-".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// Writes the report of the study in `dir` from its `study.json` and its
/// cases' files: `results.csv`, `plots/KEY.png` for each numeric varied
/// key (when a case has finished), `report.md`. Reads and writes no
/// case's files; takes no lock.
pub fn write(dir: &Path) -> Result<ReportFiles, StudyError> {
    let mut state = read(dir)?;
    state.settle(dir, false);
    let results = collect(dir, &state);
    let results_path = dir.join(table::RESULTS_FILE);
    table::write(&results_path, &state.keys, &results)?;
    let outputs: Vec<Output> = state
        .outputs
        .iter()
        .filter_map(|o| Output::named(o))
        .collect();
    let finished = results.iter().filter(|r| r.design.is_some()).count();
    let mut plots = Vec::new();
    let mut listed = Vec::new();
    if finished > 0 && !outputs.is_empty() {
        let plot_dir = dir.join(PLOTS_DIR);
        std::fs::create_dir_all(&plot_dir).map_err(StudyError::io(&plot_dir))?;
        for key in state.keys.iter().filter(|k| plot::plottable(k, &results)) {
            let name = format!("{}.png", file_stem(key));
            let png = plot_dir.join(&name);
            plot::against(key, &outputs, &results, &png)?;
            listed.push((key.clone(), format!("{PLOTS_DIR}/{name}")));
            plots.push(png);
        }
    }
    let text = report::markdown(&state, &results, &listed);
    let report_path = write_atomic(dir, REPORT_FILE, text)?;
    Ok(ReportFiles {
        results: results_path,
        report: report_path,
        plots,
        finished,
        cases: results.len(),
    })
}
