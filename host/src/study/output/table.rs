//! `results.csv`: one row a case — its number and status, the varied
//! keys' values, the final kinematics, 3D CT, CP and efficiency, wing
//! mass, carbon fraction, the actuator's verdict and margins, whether the
//! design converged, its final cycle, its time, and the error of a failed
//! case. Numbers in Rust's shortest round-trip form (the same run gives
//! the same text); an unfinished case's outputs are empty.

use std::path::Path;

use crate::study::error::StudyError;
use crate::study::results::{CaseResult, Output};

/// The file's name in the study's directory.
pub const RESULTS_FILE: &str = "results.csv";

/// A varied key's value as a cell: numbers and lists as TOML writes
/// them, words without quotes.
pub fn cell(value: &toml::Value) -> String {
    match value {
        toml::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// A number as a cell (empty when unknown or not finite).
fn number(value: Option<f64>) -> String {
    value
        .filter(|v| v.is_finite())
        .map_or_else(String::new, |v| v.to_string())
}

/// The header: `case, status`, the keys, the outputs and the verdict.
fn header(keys: &[String]) -> Vec<String> {
    let mut h: Vec<String> = vec!["case".into(), "status".into()];
    h.extend(keys.iter().cloned());
    let outputs = Output::ALL.iter().filter(|o| **o != Output::Seconds);
    h.extend(outputs.map(|o| o.name().to_string()));
    h.extend(
        [
            "feasible",
            "limiting",
            "converged",
            "final_cycle",
            "seconds",
            "error",
        ]
        .iter()
        .map(ToString::to_string),
    );
    h
}

/// One case's row.
fn row(keys: &[String], r: &CaseResult) -> Vec<String> {
    let mut cells = vec![r.name.clone(), r.status.word().to_string()];
    for key in keys {
        let value = r.values.iter().find(|(k, _)| k == key).map(|(_, v)| v);
        cells.push(value.map_or_else(String::new, cell));
    }
    let d = r.design.as_ref();
    for o in Output::ALL.iter().filter(|o| **o != Output::Seconds) {
        cells.push(number(d.and_then(|d| o.of(d))));
    }
    let actuator = d.and_then(|d| d.actuator.as_ref());
    cells.push(actuator.map_or_else(String::new, |a| a.feasible.to_string()));
    cells.push(actuator.map_or_else(String::new, |a| a.limiting.quantity.clone()));
    cells.push(d.map_or_else(String::new, |d| d.converged.to_string()));
    cells.push(d.map_or_else(String::new, |d| d.final_cycle.to_string()));
    cells.push(d.map_or_else(String::new, |d| format!("{:.1}", d.seconds)));
    cells.push(r.error.clone().unwrap_or_default());
    cells
}

/// Writes `results.csv` of `results` (the varied `keys` as columns) to
/// `path`.
pub fn write(path: &Path, keys: &[String], results: &[CaseResult]) -> Result<(), StudyError> {
    let partial = path.with_extension("csv.partial");
    let mut w = csv::Writer::from_path(&partial)?;
    w.write_record(header(keys))?;
    for r in results {
        w.write_record(row(keys, r))?;
    }
    w.flush().map_err(StudyError::io(&partial))?;
    drop(w);
    std::fs::rename(&partial, path).map_err(StudyError::io(path))?;
    Ok(())
}
