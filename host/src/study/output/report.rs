//! `report.md`: the study for a person — how many cases finished, failed
//! or wait, a table of every case (varied keys, status, the final
//! design's 3D CT, CP, efficiency, wing mass, kinematics, convergence,
//! time), the finished case with the highest value of each plotted
//! output, the pictures,
//! and each failed case's error and log.

use std::fmt::Write as _;

use crate::study::results::{CaseResult, Output};
use crate::study::state::{CaseStatus, StudyState};

use super::table::cell;

/// A number with `digits` decimals, or "–".
fn num(value: Option<f64>, digits: usize) -> String {
    match value {
        Some(v) if v.is_finite() => format!("{v:.digits$}"),
        _ => "–".to_string(),
    }
}

/// The report of `state` and its `results`; `plots` are the pictures
/// written (key, file name relative to the study's directory).
pub fn markdown(state: &StudyState, results: &[CaseResult], plots: &[(String, String)]) -> String {
    let mut s = String::new();
    let count = |status| state.count(status);
    let _ = writeln!(s, "# fwav study: {}\n", state.name);
    let _ = writeln!(
        s,
        "{} cases from `{}`, varying {}: **{} finished**, {} failed, {} not run or unfinished. \
         Each case is a whole `fwav design` run in `cases/NNN/` (its own `report.md` there); \
         every number here is its final design's. `results.csv` holds every column.\n",
        state.cases.len(),
        state.study_file,
        state
            .keys
            .iter()
            .map(|k| format!("`{k}`"))
            .collect::<Vec<_>>()
            .join(", "),
        count(CaseStatus::Finished),
        count(CaseStatus::Failed),
        state.cases.len() - count(CaseStatus::Finished) - count(CaseStatus::Failed),
    );
    table(&mut s, &state.keys, results);
    best(&mut s, state, results);
    if !plots.is_empty() {
        let _ = writeln!(s, "## Plots\n");
        for (key, file) in plots {
            let _ = writeln!(s, "Against `{key}`:\n\n![{key}]({file})\n");
        }
    }
    let failed: Vec<&CaseResult> = results
        .iter()
        .filter(|r| r.status == CaseStatus::Failed)
        .collect();
    if !failed.is_empty() {
        let _ = writeln!(
            s,
            "## Failed cases\n\n`fwav study resume DIR` runs them again, each from its last \
             finished stage.\n"
        );
        for r in failed {
            let log = state
                .case(r.number)
                .and_then(|c| c.log.clone())
                .map_or_else(String::new, |l| format!(" (log: `{l}`)"));
            let _ = writeln!(
                s,
                "- case {}: {}{log}",
                r.name,
                r.error.as_deref().unwrap_or("no error recorded")
            );
        }
        s.push('\n');
    }
    s
}

/// The table of every case.
fn table(s: &mut String, keys: &[String], results: &[CaseResult]) {
    let mut head = vec!["case".to_string()];
    head.extend(keys.iter().map(|k| format!("`{k}`")));
    head.extend(
        [
            "status",
            "CT",
            "CP",
            "efficiency",
            "wing mass, g",
            "f, Hz",
            "amplitude, deg",
            "converged",
            "time, s",
        ]
        .map(String::from),
    );
    let _ = writeln!(s, "| {} |", head.join(" | "));
    let _ = writeln!(s, "|{}", " --- |".repeat(head.len()));
    for r in results {
        let mut cells = vec![r.name.clone()];
        for key in keys {
            let v = r.values.iter().find(|(k, _)| k == key).map(|(_, v)| v);
            cells.push(v.map_or_else(|| "–".to_string(), cell));
        }
        let d = r.design.as_ref();
        let out = |o: Output, digits| num(d.and_then(|d| o.of(d)), digits);
        cells.push(r.status.word().to_string());
        cells.push(out(Output::Ct, 4));
        cells.push(out(Output::Cp, 4));
        cells.push(out(Output::Efficiency, 3));
        cells.push(num(d.map(|d| 1e3 * d.wing_mass_kg), 3));
        cells.push(out(Output::FrequencyHz, 2));
        cells.push(out(Output::AmplitudeDeg, 1));
        cells.push(d.map_or_else(
            || "–".to_string(),
            |d| {
                if d.converged {
                    "yes".into()
                } else {
                    "no (cycle cap)".into()
                }
            },
        ));
        cells.push(out(Output::Seconds, 1));
        let _ = writeln!(s, "| {} |", cells.join(" | "));
    }
    s.push('\n');
}

/// The finished case with the highest value of each plotted output.
fn best(s: &mut String, state: &StudyState, results: &[CaseResult]) {
    let outputs: Vec<Output> = state
        .outputs
        .iter()
        .filter_map(|o| Output::named(o))
        .filter(|o| *o != Output::Seconds)
        .collect();
    let mut lines = Vec::new();
    for o in outputs {
        let top = results
            .iter()
            .filter_map(|r| Some((r, o.of(r.design.as_ref()?)?)))
            .filter(|(_, v)| v.is_finite())
            .max_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((r, v)) = top {
            let values: Vec<String> = r
                .values
                .iter()
                .map(|(k, v)| format!("{k} = {}", cell(v)))
                .collect();
            lines.push(format!(
                "- {}: {v:.4}, case {} ({})",
                o.name(),
                r.name,
                values.join(", ")
            ));
        }
    }
    if !lines.is_empty() {
        let _ = writeln!(
            s,
            "## Highest value of each plotted output\n\n{}\n",
            lines.join("\n")
        );
    }
}
