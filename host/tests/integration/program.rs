//! Not a test group: the `fwav` program run as a user runs it, from the
//! workspace root (where the README's commands run, and its relative
//! paths, `configs/coarse.toml` say, resolve), for every group that
//! drives the program as a process and waits for it.

use std::process::{Command, Output};

/// Runs `fwav args` from the workspace root and waits for it: its exit
/// status and everything it printed.
pub fn fwav(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_fwav"))
        .args(args)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .output()
        .expect("the fwav binary runs")
}
