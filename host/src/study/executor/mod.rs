//! The executors that run a study's cases: [`local`] (child processes on
//! this host, N at a time) and [`slurm`] (one Slurm job array, followed
//! until it ends; nothing runs on the submitting host). Either way a case
//! is the ordinary, resumable design run
//! `fwav design --config DIR/cases/NNN/config.toml --out DIR/cases/NNN`
//! of the `fwav` program itself ([`Launch`]): a case stopped anywhere goes
//! on from its own `state.json`, losing at most the stage it was in.

pub mod local;
pub mod slurm;

use std::ffi::OsString;
use std::path::{Path, PathBuf};

use crate::mdois::driver::CONFIG_FILE;

use super::state::StudyState;

/// How a case is run: the `fwav` program and whether it may run a case
/// far beyond the built-in design's cost.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Launch {
    /// The `fwav` executable (on a cluster, on a file system every node
    /// sees).
    pub program: PathBuf,
    /// Pass `--yes` to each design run.
    pub yes: bool,
}

impl Launch {
    /// The arguments of the design run of the case in `case_dir`.
    pub fn arguments(&self, case_dir: &Path) -> Vec<OsString> {
        let mut args: Vec<OsString> = vec!["design".into(), "--quiet".into()];
        if self.yes {
            args.push("--yes".into());
        }
        args.push("--config".into());
        args.push(case_dir.join(CONFIG_FILE).into_os_string());
        args.push("--out".into());
        args.push(case_dir.as_os_str().to_owned());
        args
    }
}

/// Called with the study's state whenever it changes (a progress
/// display).
pub type Observer<'a> = &'a dyn Fn(&StudyState);

/// The error a design run printed last (`error: ...`) in its log,
/// without the `design run in DIR: ` it starts with (the case is known;
/// its directory's path depends on how the study was started).
pub fn error_in_log(log: &Path) -> Option<String> {
    let text = std::fs::read_to_string(log).ok()?;
    let error = text.lines().rev().find_map(|l| l.strip_prefix("error: "))?;
    let error = error
        .strip_prefix("design run in ")
        .and_then(|rest| rest.split_once(": ").map(|(_, e)| e))
        .unwrap_or(error);
    Some(error.trim().to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The last error line, without the run directory's context.
    #[test]
    fn the_last_error_is_read_from_a_log() {
        let dir = std::env::temp_dir().join(format!("fwav-study-log-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let log = dir.join("001.log");
        std::fs::write(
            &log,
            "warning: x\nerror: design run in /s/cases/001: the initial design cannot be \
             flown\n",
        )
        .unwrap();
        assert_eq!(
            error_in_log(&log).as_deref(),
            Some("the initial design cannot be flown")
        );
        std::fs::write(&log, "error: cannot read x\n").unwrap();
        assert_eq!(error_in_log(&log).as_deref(), Some("cannot read x"));
        std::fs::write(&log, "all well\n").unwrap();
        assert_eq!(error_in_log(&log), None);
        std::fs::remove_dir_all(&dir).ok();
    }
}
