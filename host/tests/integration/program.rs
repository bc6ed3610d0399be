//! Not a test group: the `fwav` program run as a user runs it, from the
//! workspace root (where the README's commands run, and its relative
//! paths, `configs/coarse.toml` say, resolve), for every group that
//! drives the program as a process.

use std::process::{Command, Output};

/// Runs `fwav args` from the workspace root and waits for it: its exit
/// status and everything it printed.
pub fn fwav(args: &[&str]) -> Output {
    fwav_command(args).output().expect("the fwav binary runs")
}

/// `fwav args` to be run from the workspace root, for a test that starts
/// it and acts while it runs.
pub fn fwav_command(args: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_fwav"));
    command
        .args(args)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    command
}
