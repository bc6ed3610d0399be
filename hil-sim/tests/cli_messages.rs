//! How the `hil-sim` program prints (issue 22): a closed output pipe ends
//! it quietly, as it ends `cat`, instead of a panic; an error is printed
//! once, without Rust's debug formatting, and names the file, key and
//! value concerned.

#![cfg(unix)]

use std::os::unix::process::ExitStatusExt as _;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

const SCENARIO: &str = "duration_s = 0.5\nmeasure_cycles = 2\n\
                        [[segments]]\nfrequency_hz = 11.0\namplitude_deg = 30.0\n\
                        duration_s = 100.0\nramp_s = 1.0\n";

fn hil_sim(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hil-sim"))
        .args(args)
        .output()
        .expect("the hil-sim binary runs")
}

/// A scratch directory removed at the end.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("hil-sim-msg-{name}-{}", std::process::id()));
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

/// One `error:` line of text a person reads, no debug formatting.
fn assert_plain_error(out: &Output) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert_eq!(stderr.matches("error:").count(), 1, "{stderr}");
    for debug in ["{", "Os {", "kind:", "Error(", "panicked"] {
        assert!(!stderr.contains(debug), "{debug:?} in {stderr}");
    }
    stderr
}

/// `hil-sim run S | head -1` once `head` has gone: the reading end of the
/// pipe is closed before hil-sim prints; it ends by SIGPIPE as `cat`
/// does (a shell shows 141), never with a panic (101).
#[test]
fn run_into_a_closed_pipe_ends_quietly() {
    let scratch = Scratch::new("pipe");
    let scenario = scratch.file("short.toml", SCENARIO);
    let (reader, writer) = os_pipe::pipe().unwrap();
    drop(reader);
    let out = Command::new(env!("CARGO_BIN_EXE_hil-sim"))
        .args(["run", &scenario])
        .stdout(writer)
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_ne!(out.status.code(), Some(101), "{}: {stderr}", out.status);
    assert_eq!(
        out.status.signal(),
        Some(libc::SIGPIPE),
        "{}: {stderr}",
        out.status
    );
}

/// A TOML error in a scenario or a plant file: the file, then the
/// parser's message once (it was printed twice).
#[test]
fn toml_errors_are_reported_once() {
    let scratch = Scratch::new("toml");
    let scenario = scratch.file("typo.toml", &format!("heartbeat_z = 0.1\n{SCENARIO}"));
    let stderr = assert_plain_error(&hil_sim(&["run", &scenario]));
    assert!(stderr.contains("typo.toml"), "{stderr}");
    assert_eq!(
        stderr.matches("unknown field `heartbeat_z`").count(),
        1,
        "{stderr}"
    );

    let good = scratch.file("good.toml", SCENARIO);
    let plant = scratch.file("plant.toml", "[motor]\nresistance = 2.0\n");
    let stderr = assert_plain_error(&hil_sim(&["run", &good, "--plant", &plant]));
    assert!(stderr.contains("plant.toml"), "{stderr}");
    assert_eq!(
        stderr.matches("unknown field `resistance`").count(),
        1,
        "{stderr}"
    );
}

/// A missing file: the path, then the OS's reason once.
#[test]
fn a_missing_scenario_is_reported_once() {
    let scratch = Scratch::new("missing");
    let missing = scratch.0.join("none.toml");
    let stderr = assert_plain_error(&hil_sim(&["run", missing.to_str().unwrap()]));
    assert!(stderr.contains(missing.to_str().unwrap()), "{stderr}");
    assert_eq!(
        stderr.matches("No such file or directory").count(),
        1,
        "{stderr}"
    );
}

/// A duration too long is called too long, with its key, value and
/// range (it said "must be positive"); a mistyped exponent is shown as
/// written (1e300 was a line of 301 digits).
#[test]
fn a_too_long_duration_is_named_with_its_range() {
    let scratch = Scratch::new("long");
    for (value, shown) in [
        ("1e6", "duration_s = 1e6 "),
        ("1e300", "duration_s = 1e300 "),
    ] {
        let scenario = scratch.file("long.toml", &SCENARIO.replace("0.5", value));
        let stderr = assert_plain_error(&hil_sim(&["run", &scenario]));
        assert!(stderr.contains(shown), "{stderr}");
        assert!(stderr.contains("< 100000 s"), "{stderr}");
        assert!(!stderr.contains("positive"), "{stderr}");
    }
}

/// A picture that cannot be written names the file and the OS's reason,
/// not the backend's debug text (`ImageError(IoError(Os { code: 2 ...`).
#[test]
fn a_picture_that_cannot_be_written_is_named_without_debug_text() {
    let scratch = Scratch::new("plot");
    let scenario = scratch.file("short.toml", SCENARIO);
    let png = scratch.0.join("no-such-dir").join("run.png");
    let stderr = assert_plain_error(&hil_sim(&[
        "run",
        &scenario,
        "--plot",
        png.to_str().unwrap(),
    ]));
    assert!(stderr.contains(png.to_str().unwrap()), "{stderr}");
    assert_eq!(
        stderr.matches("No such file or directory").count(),
        1,
        "{stderr}"
    );
}

/// A picture is never drawn over a file (the mission's "no user file
/// overwritten"; until 2026-12-07 `--plot` replaced whatever had the
/// name): a taken name is refused before the run, the file left as it
/// was; a new name gets the picture, with no temporary file beside it,
/// and the same run again is refused.
#[test]
fn a_picture_is_never_drawn_over_a_file() {
    let scratch = Scratch::new("taken");
    let scenario = scratch.file("short.toml", SCENARIO);
    let mine = scratch.file("mine.png", "mine");
    let out = hil_sim(&["run", &scenario, "--plot", &mine]);
    let stderr = assert_plain_error(&out);
    assert!(
        stderr.contains("--plot") && stderr.contains(&mine),
        "{stderr}"
    );
    assert!(stderr.contains("never overwritten"), "{stderr}");
    assert!(out.stdout.is_empty(), "the run went on");
    assert_eq!(std::fs::read_to_string(&mine).unwrap(), "mine");

    let png = scratch.0.join("run.png");
    let png = png.to_str().unwrap();
    let out = hil_sim(&["run", &scenario, "--plot", png]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(png).unwrap();
    assert_eq!(&bytes[..4], b"\x89PNG");
    let mut names: Vec<_> = std::fs::read_dir(&scratch.0)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(names, ["mine.png", "run.png", "short.toml"]);
    assert_plain_error(&hil_sim(&["run", &scenario, "--plot", png]));
    assert_eq!(std::fs::read(png).unwrap(), bytes);
}

/// A run too short to hold a whole reference cycle prints that it has no
/// steady-state numbers, not numbers over none (it printed "over the last
/// 0 cycles" and a frequency error of -100 %).
#[test]
fn a_run_without_a_whole_cycle_prints_no_steady_numbers() {
    let dir = Scratch::new("short-run");
    let scenario = dir.file(
        "short.toml",
        &SCENARIO.replace("duration_s = 0.5", "duration_s = 0.05"),
    );
    let out = hil_sim(&["run", &scenario]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    assert!(
        stdout.contains(
            "no steady-state numbers: the run holds no whole reference cycle before its end"
        ),
        "{stdout}"
    );
    for nonsense in [
        "0 cycles",
        "amplitude error",
        "frequency error",
        "J per cycle",
    ] {
        assert!(!stdout.contains(nonsense), "{nonsense:?} in {stdout}");
    }
}

/// `hil-sim serve --speed -1` (or 0, NaN) ran at real time while saying
/// "-1x real time", and 1e-30 overflowed the wait (a panic); a pace outside
/// a thousandth to a thousand times real time is now refused, naming the
/// flag and the value as written.
#[test]
fn a_bad_pace_is_refused() {
    for speed in ["-1", "0", "nan", "inf", "1e-30", "1e300"] {
        let out = hil_sim(&["serve", "--speed", speed]);
        let stderr = assert_plain_error(&out);
        let shown = match speed {
            "nan" => "NaN",
            other => other,
        };
        assert!(
            stderr.contains(&format!("--speed: a pace of {shown} simulated seconds"))
                && stderr.contains("give one from 0.001 to 1000"),
            "{speed}: {stderr}"
        );
        assert!(out.stdout.is_empty(), "{speed}: the pty was made");
    }
}

/// A plant whose controller model the device refuses (a wing of 1 kg m^2,
/// beyond the device's inertia) was refused at the upload, naming the
/// device's parameter in its `f32`; `serve` took it without a word and kept
/// the controller's default. Both now refuse it before the run, naming the
/// plant's keys and the value as computed, to six digits (1 + 20^2 *
/// 7.1e-8 of the rotor = 1.0000284). A value the model takes as it is (a winding of 1e300 ohm) is
/// refused by the plant file's own check, whose range is the device's
/// (since 2026-12-07).
#[test]
fn a_plant_beyond_the_device_is_refused_naming_its_key() {
    let plant = String::from_utf8(hil_sim(&["plant"]).stdout).unwrap();
    let dir = Scratch::new("plant-beyond");
    let scenario = dir.file("cruise.toml", SCENARIO);
    for (key, value, expected) in [
        (
            "inertia_kg_m2 = ",
            "inertia_kg_m2 = 1",
            "the plant gives the controller's wing_inertia = 1.00003 kg m^2, outside the \
             device's 1e-9..=0.01 kg m^2: a board cannot fly this plant's model; check \
             wing.inertia_kg_m2, motor.rotor_inertia_kg_m2 and transmission.gear_ratio",
        ),
        (
            "resistance_ohm = ",
            "resistance_ohm = 1e300",
            "motor.resistance_ohm = 1e300 is outside [0.001, 1000] ohm",
        ),
    ] {
        let line = plant
            .lines()
            .find(|l| l.starts_with(key))
            .expect("the plant's key");
        let plant = dir.file("plant.toml", &plant.replace(line, value));
        for args in [
            &["run", "--plant", &plant, &scenario][..],
            &["serve", "--plant", &plant][..],
        ] {
            let out = hil_sim(args);
            let stderr = assert_plain_error(&out);
            assert!(stderr.contains(expected), "{args:?}: {stderr}");
            assert!(out.stdout.is_empty(), "{args:?}");
        }
    }
}
