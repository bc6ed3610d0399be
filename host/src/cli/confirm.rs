//! A run far beyond the default's cost goes ahead only when its user
//! says so: `--yes`, or a "y" typed on a terminal. The estimate is printed
//! either way, and without a terminal (a script, CI) the run is refused
//! with the way out.

use std::fmt::Display;
use std::io::IsTerminal as _;

use anyhow::{bail, Result};

/// Prints "this `run` needs `estimate`" and lets the run go ahead only
/// with `yes` or a "y" typed on a terminal; refuses it otherwise, saying
/// to pass `--yes` or `instead`.
pub fn confirm_cost(run: &str, estimate: &impl Display, yes: bool, instead: &str) -> Result<()> {
    eprintln!("this {run} needs {estimate}");
    if yes {
        return Ok(());
    }
    let stdin = std::io::stdin();
    if stdin.is_terminal() {
        eprint!("run it? [y/N] ");
        let mut answer = String::new();
        stdin.read_line(&mut answer)?;
        if matches!(answer.trim(), "y" | "Y" | "yes") {
            return Ok(());
        }
    }
    bail!("not started: the {run} is far beyond the default's cost; pass --yes to run it anyway, or {instead}")
}
