//! A file the user names is never overwritten, by any command (the
//! mission's reliability: "no user file overwritten"; issue 22 made a
//! design run's directory safe). Each command that writes under a name
//! given on its command line refuses a name that is taken before it runs,
//! naming the flag and the file, and leaves the file as it was; a new
//! name gets the whole file, readable as any file the user makes, with no
//! temporary file left beside it. `fwav aero2d`'s data files (`--history`,
//! `--surface`, `--field`) are tested in `viscous_field` and
//! `input_checks`; here are the pictures, the output directories and
//! the monitor's log. Until 2026-12-07 `aero2d --plot`, `system-analysis
//! --out`, `topology --out` and `kinematics --plot` each replaced a file
//! called "mine" (tried by hand), and `monitor --csv` opened its log with
//! `File::create`, which empties a file there, once the link was open (read
//! in the code: these tests have no device, so they show that the
//! refusal now comes before the link is opened).

use std::path::Path;

use crate::program::{fwav, scratch};

/// A file of the user's, which no command may change.
const MINE: &str = "mine: not to be overwritten";

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Runs `fwav args` and asserts that it is refused (exit 1), that its one
/// error names `flag` and `taken`, that `taken` still holds [`MINE`] and
/// that the scratch directory `dir` holds only `left` afterwards: nothing
/// was run and written before the refusal.
fn refused(args: &[&str], flag: &str, taken: &Path, dir: &Path, left: &[&str]) {
    let out = fwav(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "{args:?} printed results");
    let name = taken.file_name().unwrap().to_string_lossy();
    assert!(
        stderr.contains(flag) && stderr.contains(name.as_ref()),
        "{args:?}: {stderr}"
    );
    assert!(stderr.contains("never overwritten"), "{stderr}");
    assert_eq!(std::fs::read_to_string(taken).unwrap(), MINE, "{args:?}");
    assert_eq!(names(dir), left, "{args:?}");
}

/// Every command that writes under a name the user gives refuses one
/// that is taken, before its run (no other output is written), and leaves
/// the file as it was.
#[test]
fn every_command_refuses_a_name_that_is_taken_before_it_runs() {
    let dir = scratch("user-files-taken");
    let arg = |p: &Path| p.to_str().unwrap().to_owned();
    let coarse = concat!(env!("CARGO_MANIFEST_DIR"), "/../configs/coarse.toml");

    // A picture: with --history beside it, which is not written either.
    let plot = dir.join("plot.png");
    std::fs::write(&plot, MINE).unwrap();
    let history = dir.join("history.csv");
    refused(
        &["aero2d", "--plot", &arg(&plot), "--history", &arg(&history)],
        "--plot",
        &plot,
        &dir,
        &["plot.png"],
    );

    // A picture whose directory is missing: refused before the run too.
    let nowhere = dir.join("missing").join("plot.png");
    let out = fwav(&["aero2d", "--plot", &arg(&nowhere)]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        out.stdout.is_empty() && stderr.contains("No such file or directory"),
        "{stderr}"
    );

    // An output directory, by a fixed name and by a numbered series'.
    for (command, flag, file) in [
        ("system-analysis", "--out", "section.json"),
        ("system-analysis", "--out", "wake-0003.vtu"),
        ("topology", "--out", "layout.png"),
        ("kinematics", "--plot", "pareto.png"),
    ] {
        let out = dir.join(format!("{command}-{}", file.replace('.', "-")));
        std::fs::create_dir_all(&out).unwrap();
        let taken = out.join(file);
        std::fs::write(&taken, MINE).unwrap();
        let args = [command, "--config", coarse, flag, &arg(&out)];
        refused(&args, flag, &taken, &out, &[file]);
    }

    // The monitor's log, refused before the link is opened (the port
    // does not exist: the refusal must come first).
    let logs = dir.join("monitor");
    std::fs::create_dir_all(&logs).unwrap();
    let log = logs.join("monitor.csv");
    std::fs::write(&log, MINE).unwrap();
    let args = [
        "monitor",
        "--port",
        "/dev/fwav-no-such-port",
        "--csv",
        &arg(&log),
    ];
    refused(&args, "--csv", &log, &logs, &["monitor.csv"]);
    // A new log with a port that cannot open is not left behind empty.
    let new_log = logs.join("new.csv");
    let args = [
        "monitor",
        "--port",
        "/dev/fwav-no-such-port",
        "--csv",
        &arg(&new_log),
    ];
    let out = fwav(&args);
    assert_eq!(out.status.code(), Some(1));
    assert!(!new_log.exists(), "an empty log was left behind");
    std::fs::remove_dir_all(&dir).ok();
}

/// A new name gets the whole file, with the permissions of any file the
/// user makes (not a temporary file's owner-only ones), and no temporary
/// file is left beside it; the same command run again is then refused.
#[test]
fn a_new_name_gets_the_whole_file_once() {
    let dir = scratch("user-files-new");
    let plot = dir.join("plot.png");
    let args = ["aero2d", "--cycles", "2", "--plot", plot.to_str().unwrap()];
    let out = fwav(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(&plot).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "not a PNG");
    assert_eq!(names(&dir), ["plot.png"], "a temporary file was left");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        let written = std::fs::metadata(&plot).unwrap().permissions().mode() & 0o777;
        let reference = dir.join("reference");
        std::fs::write(&reference, "").unwrap();
        let made = std::fs::metadata(&reference).unwrap().permissions().mode() & 0o777;
        std::fs::remove_file(&reference).unwrap();
        assert_eq!(
            written, made,
            "{written:o} against a user's file's {made:o}"
        );
    }
    let again = fwav(&args);
    assert_eq!(again.status.code(), Some(1));
    assert_eq!(std::fs::read(&plot).unwrap(), bytes);
    std::fs::remove_dir_all(&dir).ok();
}
