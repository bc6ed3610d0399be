//! The flight commands (`fwav upload --start`, `fwav monitor`, signals)
//! against the simulated board on a pty, in a test binary of their own.
//! They keep the link's heartbeat (the device's failsafe fires after
//! 0.3 s without one); inside the integration binary they ran beside the
//! design tests' computation on a 2-core machine, and a SIGINT run once saw
//! the link-loss failsafe instead of the commanded disarm. Cargo runs test
//! binaries one after another, so nothing of the other tests runs beside
//! these.

use std::process::Command;

#[path = "integration/cli/fly.rs"]
mod fly;

fn fwav(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_fwav"))
        .args(args)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .output()
        .expect("the fwav binary runs")
}
