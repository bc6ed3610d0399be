//! How the `fwav` program prints (issue 22): a closed output pipe ends it
//! quietly, as it ends `cat`, instead of a panic; an error is printed
//! once, its causes in order, without Rust's debug formatting, and names
//! the file, key or value concerned.

#![cfg(unix)]

use std::os::unix::process::ExitStatusExt as _;
use std::path::PathBuf;
use std::process::{ExitStatus, Output, Stdio};

use crate::program::{fwav, fwav_command};

/// Runs fwav with its standard output (and, with `stderr_too`, its
/// standard error) a pipe whose reading end is already closed, as in
/// `fwav ... | head -1` once `head` has gone; returns how it ended and,
/// unless it went into the pipe too, its standard error.
fn into_closed_pipe(args: &[&str], stderr_too: bool) -> (ExitStatus, String) {
    let (reader, writer) = os_pipe::pipe().unwrap();
    drop(reader);
    let mut command = fwav_command(args);
    command.stdout(writer.try_clone().unwrap());
    if stderr_too {
        command.stderr(writer);
    } else {
        command.stderr(Stdio::piped());
    }
    let out = command.output().expect("the fwav binary runs");
    (
        out.status,
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The conventional end of a program whose reader went away: killed by
/// SIGPIPE (a shell shows status 141), never a panic (status 101).
fn assert_ended_by_closed_pipe(status: ExitStatus, stderr: &str) {
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_ne!(status.code(), Some(101), "{status}: {stderr}");
    assert_eq!(status.signal(), Some(libc::SIGPIPE), "{status}: {stderr}");
}

/// A scratch directory removed at the end.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("fwav-msg-{name}-{}", std::process::id()));
        std::fs::remove_dir_all(&dir).ok();
        std::fs::create_dir_all(&dir).unwrap();
        Self(dir)
    }

    fn file(&self, name: &str, text: &str) -> String {
        let path = self.0.join(name);
        std::fs::write(&path, text).unwrap();
        path.to_str().unwrap().to_owned()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        std::fs::remove_dir_all(&self.0).ok();
    }
}

/// What every printed error must be: one `error:` line of text a person
/// reads, no Rust debug formatting of structures or OS errors.
fn assert_plain_error(out: &Output) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert_eq!(stderr.matches("error:").count(), 1, "{stderr}");
    for debug in ["{", "Os {", "kind:", "Error(", "panicked"] {
        assert!(!stderr.contains(debug), "{debug:?} in {stderr}");
    }
    stderr
}

#[test]
fn validate_list_into_a_closed_pipe_ends_quietly() {
    let (status, stderr) = into_closed_pipe(&["validate", "--list"], false);
    assert_ended_by_closed_pipe(status, &stderr);
}

/// `fwav profile check F 2>&1 | head -1`: both streams in the pipe.
#[test]
fn profile_check_into_a_closed_pipe_ends_quietly() {
    let (status, _) = into_closed_pipe(
        &["profile", "check", "host/profiles/initial-design.json"],
        true,
    );
    assert_ended_by_closed_pipe(status, "");
}

/// An OS error (the file is missing) is printed once, after the file.
#[test]
fn a_missing_profile_is_reported_once() {
    let scratch = Scratch::new("missing");
    let missing = scratch.0.join("no-such-profile.json");
    let out = fwav(&[
        "upload",
        "--port",
        "/dev/no-such-port",
        missing.to_str().unwrap(),
    ]);
    let stderr = assert_plain_error(&out);
    assert!(
        stderr.contains(&format!("cannot read {}", missing.display())),
        "{stderr}"
    );
    assert_eq!(
        stderr.matches("No such file or directory").count(),
        1,
        "{stderr}"
    );
}

/// A file that is not JSON: its reason once (it was printed three times:
/// by the file's error, the document's and serde's).
#[test]
fn a_malformed_profile_is_reported_once() {
    let scratch = Scratch::new("malformed");
    let path = scratch.file("notjson.json", "duration_s = 1.0\n");
    let out = fwav(&["upload", "--port", "/dev/no-such-port", &path]);
    let stderr = assert_plain_error(&out);
    assert!(stderr.contains("notjson.json"), "{stderr}");
    assert_eq!(stderr.matches("line 1 column 1").count(), 1, "{stderr}");
}

/// A TOML error in a configuration: the file, then the parser's message
/// (with its line) once.
#[test]
fn a_configuration_toml_error_is_reported_once() {
    let scratch = Scratch::new("toml");
    let path = scratch.file("wing.toml", "[wing]\nspan_elementz = 12\n");
    let out = fwav(&["system-analysis", "--config", &path]);
    let stderr = assert_plain_error(&out);
    assert!(stderr.contains("wing.toml"), "{stderr}");
    assert_eq!(
        stderr.matches("unknown field `span_elementz`").count(),
        1,
        "{stderr}"
    );
}

/// A picture that cannot be written names the file and the OS's reason,
/// not the backend's debug text (`ImageError(IoError(Os { code: 2 ...`).
#[test]
fn a_picture_that_cannot_be_written_is_named_without_debug_text() {
    let scratch = Scratch::new("plot");
    let png = scratch.0.join("no-such-dir").join("run.png");
    let out = fwav(&[
        "aero2d",
        "--plunge-amplitude",
        "0.05",
        "--reduced-frequency",
        "1.0",
        "--cycles",
        "2",
        "--plot",
        png.to_str().unwrap(),
    ]);
    let stderr = assert_plain_error(&out);
    assert!(stderr.contains(png.to_str().unwrap()), "{stderr}");
    assert_eq!(
        stderr.matches("No such file or directory").count(),
        1,
        "{stderr}"
    );
}

/// A level set that is not increasing says so (it said "is outside
/// increasing, each in ...").
#[test]
fn a_decreasing_level_set_is_called_not_increasing() {
    let scratch = Scratch::new("levels");
    let path = scratch.file("levels.toml", "[design]\namplitude_deg = [40, 30, 20]\n");
    let out = fwav(&["system-analysis", "--config", &path]);
    let stderr = assert_plain_error(&out);
    assert!(
        stderr.contains("design.amplitude_deg = [40, 30, 20] must be increasing"),
        "{stderr}"
    );
    assert!(!stderr.contains("outside increasing"), "{stderr}");
}

/// A response setting the structural discipline cannot use is named with
/// its value and range, not as `ResponseSettings { periods: 2, ... }`.
#[test]
fn a_response_setting_out_of_range_is_named() {
    let scratch = Scratch::new("response");
    let config = scratch.file(
        "wing.toml",
        "[wing]\nspan_elements = 4\nchord_elements = 5\n[topology]\nsample_every = 20\n",
    );
    // 16 steps of zero pressure on the 20 elements of that wing.
    let samples = vec![vec![0.0; 20]; 16];
    let pressure = scratch.file(
        "pressure.json",
        &serde_json::json!({
            "format": "fwav-pressure-history",
            "format_version": 1,
            "dt_s": 0.005,
            "samples": samples,
        })
        .to_string(),
    );
    let out_dir = scratch.0.join("topology");
    let out = fwav(&[
        "topology",
        "--config",
        &config,
        "--pressure",
        &pressure,
        "--out",
        out_dir.to_str().unwrap(),
        "--quiet",
    ]);
    let stderr = assert_plain_error(&out);
    assert!(stderr.contains("sample_every = 20"), "{stderr}");
    assert!(stderr.contains("16 steps"), "{stderr}");
    assert!(!stderr.contains("ResponseSettings"), "{stderr}");
}

/// The reasons a profile is refused read as words (`the ramp changes the
/// Amplitude` was the enum's debug name), and its end action too.
#[test]
fn profile_reasons_and_end_action_read_as_words() {
    let scratch = Scratch::new("profile");
    let path = scratch.file(
        "steep.json",
        r#"{"format":"fwav-profile","format_version":1,"on_end":"stop","segments":[
            {"frequency_hz": 11.0, "amplitude_deg": 40.0, "duration_s": 5.0, "ramp_s": 0.1}]}"#,
    );
    let out = fwav(&["profile", "check", &path]);
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert_eq!(out.status.code(), Some(1), "{stdout}{stderr}");
    assert!(
        stderr.contains("the ramp changes the amplitude at"),
        "{stderr}"
    );
    assert!(stdout.contains("then stop"), "{stdout}");
}

/// A telemetry decimation of 0 (no sample ever, by its meaning: one sample
/// every N control steps) is refused with its range before any port is
/// opened. Until 2026-12-07 `fwav monitor` took it and quietly sent 1.
#[test]
fn a_decimation_of_zero_is_refused_with_its_range() {
    for bad in ["0", "70000", "-1"] {
        let out = fwav(&[
            "monitor",
            "--port",
            "/dev/no-such-fwav-port",
            "--decimation",
            bad,
        ]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{bad}: {stderr}");
        assert!(stderr.contains("--decimation"), "{bad}: {stderr}");
        assert!(!stderr.contains("no such port"), "{bad}: {stderr}");
    }
}
