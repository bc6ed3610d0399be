//! `fwav validate`: runs the solvers' validation cases
//! ([`fwav::validation`]) and prints value, reference, error, tolerance
//! and pass for each; fails (exit 1) if any case fails.

use std::io::IsTerminal;
use std::time::Instant;

use anyhow::{bail, Result};
use fwav::validation::{self, Case, ErrorKind};

/// The command's options.
#[derive(clap::Args)]
pub struct ValidateArgs {
    /// Run only the cases whose name contains this text (e.g. `shell/`,
    /// `garrick`, `uvlm/katz-plotkin-steady`).
    #[arg(long)]
    pub only: Option<String>,
    /// List the cases (name and reference) without running them.
    #[arg(long)]
    pub list: bool,
    /// Machine-readable output: a JSON array of the cases.
    #[arg(long)]
    pub json: bool,
}

/// Runs the command.
pub fn run_command(a: &ValidateArgs) -> Result<()> {
    if a.only.as_deref().is_some_and(|f| f.trim().is_empty()) {
        // Every name contains the empty text: it would run all the cases
        // (an hour), surely not what an empty argument meant.
        bail!(
            "--only {:?}: give part of a case's name (`fwav validate --list` lists them), \
             or leave --only out to run every case",
            a.only.as_deref().unwrap_or_default()
        );
    }
    let selected = validation::matching(a.only.as_deref());
    if selected.is_empty() {
        bail!(
            "--only {:?} matches no validation case (`fwav validate --list` lists them)",
            a.only.as_deref().unwrap_or_default()
        );
    }
    if a.list {
        for v in &selected {
            println!("{:<40} {}", v.spec.name, v.spec.reference);
        }
        return Ok(());
    }
    let show = std::io::stderr().is_terminal();
    let started = Instant::now();
    let total = selected.len();
    let cases: Vec<Case> = selected
        .iter()
        .enumerate()
        .map(|(i, v)| {
            if show {
                eprint!("\r\x1b[K[{}/{total}] {} ...", i + 1, v.spec.name);
            }
            v.run()
        })
        .collect();
    if show {
        eprint!("\r\x1b[K");
    }
    let seconds = started.elapsed().as_secs_f64();
    let failed = cases.iter().filter(|c| !c.pass).count();
    if a.json {
        println!("{}", serde_json::to_string_pretty(&cases)?);
    } else {
        print_table(&cases);
        println!(
            "{} of {total} cases passed in {seconds:.1} s",
            total - failed
        );
    }
    if failed > 0 {
        let names: Vec<&str> = cases.iter().filter(|c| !c.pass).map(|c| c.name).collect();
        bail!("{failed} validation case(s) failed: {}", names.join(", "));
    }
    Ok(())
}

/// A number to 5 significant digits, trailing zeros dropped.
fn number(v: f64) -> String {
    let trim = |s: String| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    };
    if v == 0.0 || !v.is_finite() {
        format!("{v}")
    } else if (1e-3..1e5).contains(&v.abs()) {
        let decimals = (4 - v.abs().log10().floor() as i32).max(0) as usize;
        trim(format!("{v:.decimals$}"))
    } else {
        let text = format!("{v:.4e}");
        match text.split_once('e') {
            Some((mantissa, exponent)) => format!("{}e{exponent}", trim(mantissa.to_string())),
            None => text,
        }
    }
}

/// An error or tolerance: per cent when relative, in the case's units when
/// absolute.
fn deviation(v: f64, kind: ErrorKind) -> String {
    match kind {
        ErrorKind::Relative => format!("{:+.2}%", 100.0 * v),
        ErrorKind::Absolute => number(v),
    }
}

fn print_table(cases: &[Case]) {
    let width = cases.iter().map(|c| c.name.len()).max().unwrap_or(4).max(4);
    println!(
        "{:<width$}  {:>12}  {:>12}  {:>10}  {:>10}  result  units",
        "case", "value", "reference", "error", "tolerance"
    );
    for c in cases {
        let (value, error) = match (c.value, c.error) {
            (Some(v), Some(e)) => (number(v), deviation(e, c.error_kind)),
            _ => ("-".into(), "-".into()),
        };
        let tolerance = match c.error_kind {
            ErrorKind::Relative => format!("{:.2}%", 100.0 * c.tolerance),
            ErrorKind::Absolute => format!("±{}", number(c.tolerance)),
        };
        println!(
            "{:<width$}  {value:>12}  {:>12}  {error:>10}  {tolerance:>10}  {:<6}  {}",
            c.name,
            number(c.reference_value),
            if c.pass { "PASS" } else { "FAIL" },
            c.units
        );
        if let Some(failure) = &c.failure {
            println!("{:<width$}    solver failed: {failure}", "");
        }
    }
}
