//! A design run's directory is safe (issue 22): `fwav design` writes only
//! into a new or empty directory or a run of its own configuration,
//! never over a user's files or its own input; a run directory is locked
//! while a process computes in it, and a lock left by a killed process is
//! taken over; a resume refuses a `config.toml` edited since the start,
//! and a run an earlier fwav started with a value this one refuses;
//! every configuration check (cross-field ones too) runs before anything
//! is written; a corrupt `state.json` is named with the way out; the
//! progress line fits the terminal. Each test runs the real `fwav` binary
//! on real files; a command that should be refused at once but is still
//! running after its time limit is killed and reported as a failure.

use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Child, ExitStatus, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use fwav::config::SystemConfig;
use fwav::mdois::state::RunState;
use fwav::mdois::{start, RunOptions};

use crate::program::{fwav_command, terminal};

/// The coarse design of the tests and the README (documented in the file).
const COARSE: &str = include_str!("../../../configs/coarse.toml");

/// How long a command that must be refused at once may take.
const REFUSAL: Duration = Duration::from_secs(30);

fn temp(name: &str) -> PathBuf {
    crate::program::scratch(&format!("safety-{name}"))
}

fn text(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A finished (or killed) `fwav` invocation.
struct Ran {
    /// `None`: still running at the time limit (then killed).
    status: Option<ExitStatus>,
    stdout: String,
    stderr: String,
}

impl Ran {
    /// Asserts the command was refused: it ended, unsuccessfully.
    fn refused(&self, what: &str) -> &str {
        match self.status {
            None => panic!(
                "{what}: still running after {} s instead of being refused; stderr: {}",
                REFUSAL.as_secs(),
                self.stderr
            ),
            Some(s) => assert!(!s.success(), "{what}: succeeded; stdout: {}", self.stdout),
        }
        &self.stderr
    }
}

/// Runs `fwav args`, killed after `limit`.
fn fwav_within(args: &[&str], limit: Duration) -> Ran {
    let mut child = fwav_command(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the fwav binary runs");
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut text = String::new();
            if let Some(mut p) = pipe {
                p.read_to_string(&mut text).ok();
            }
            text
        })
    };
    let out = drain(child.stdout.take().map(|p| Box::new(p) as _));
    let err = drain(child.stderr.take().map(|p| Box::new(p) as _));
    let clock = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break Some(status);
        }
        if clock.elapsed() > limit {
            child.kill().ok();
            child.wait().ok();
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    Ran {
        status,
        stdout: out.join().unwrap(),
        stderr: err.join().unwrap(),
    }
}

fn wait_for(what: &str, limit: Duration, mut ready: impl FnMut() -> bool) {
    let clock = Instant::now();
    while !ready() {
        assert!(clock.elapsed() < limit, "{what}: not within {limit:?}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Starts `fwav design --quiet --config config --out out` in the
/// background and waits until the run's state file exists.
fn started_design(config: &Path, out: &Path) -> Child {
    let child = fwav_command(&[
        "design",
        "--quiet",
        "--config",
        config.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
    .stdout(Stdio::null())
    .stderr(Stdio::null())
    .spawn()
    .unwrap();
    wait_for("the run's state.json", Duration::from_secs(60), || {
        out.join("state.json").is_file()
    });
    child
}

fn kill(mut child: Child) {
    child.kill().ok();
    child.wait().ok();
}

/// Item 1: `fwav design --config DIR/config.toml --out DIR` into a
/// directory holding a user's files is refused before anything is
/// written, naming the directory and the ways out; with `--force` it is
/// still refused, because the configuration read is inside the
/// directory `--force` would empty; a configuration elsewhere and
/// `--force` replace the directory's contents; an empty directory and a
/// file are told apart.
#[test]
fn a_directory_of_other_files_is_never_overwritten() {
    let dir = temp("foreign");
    let mine = [
        ("config.toml", format!("{COARSE}# my own notes\n")),
        ("report.md", "# my report\n".to_string()),
        ("kinematics.json", "{\"mine\": true}\n".to_string()),
    ];
    for (name, content) in &mine {
        std::fs::write(dir.join(name), content).unwrap();
    }
    let untouched = || {
        for (name, content) in &mine {
            assert_eq!(&text(&dir.join(name)), content, "{name} was overwritten");
        }
        let names: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        assert_eq!(names.len(), mine.len(), "files added: {names:?}");
    };
    let config = dir.join("config.toml");
    let (c, d) = (config.to_str().unwrap(), dir.to_str().unwrap());
    let ran = fwav_within(&["design", "--quiet", "--config", c, "--out", d], REFUSAL);
    untouched();
    let stderr = ran.refused("a directory of other files");
    println!("{stderr}");
    for part in [d, "--force", "--out", "report.md"] {
        assert!(stderr.contains(part), "{part}: {stderr}");
    }
    untouched();
    let ran = fwav_within(
        &["design", "--quiet", "--config", c, "--out", d, "--force"],
        REFUSAL,
    );
    let stderr = ran.refused("--force over the configuration's own directory");
    println!("{stderr}");
    assert!(stderr.contains(c), "{stderr}");
    untouched();

    // A file is not a directory.
    let file = dir.join("report.md");
    let ran = fwav_within(
        &[
            "design",
            "--quiet",
            "--config",
            c,
            "--out",
            file.to_str().unwrap(),
        ],
        REFUSAL,
    );
    let stderr = ran.refused("a file as --out");
    assert!(stderr.contains("not a directory"), "{stderr}");
    untouched();

    // --force with the configuration elsewhere replaces the contents; an
    // empty directory is used as it is.
    let elsewhere = temp("foreign-config").join("coarse.toml");
    std::fs::write(&elsewhere, COARSE).unwrap();
    let child = fwav_command(&[
        "design",
        "--quiet",
        "--config",
        elsewhere.to_str().unwrap(),
        "--out",
        d,
        "--force",
    ])
    .stdout(Stdio::null())
    .stderr(Stdio::null())
    .spawn()
    .unwrap();
    wait_for(
        "the replaced run's state.json",
        Duration::from_secs(60),
        || dir.join("state.json").is_file(),
    );
    kill(child);
    assert!(!dir.join("report.md").exists());
    assert_ne!(text(&dir.join("config.toml")), mine[0].1);
    let empty = temp("empty");
    kill(started_design(&elsewhere, &empty));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::remove_dir_all(&empty).ok();
    std::fs::remove_dir_all(elsewhere.parent().unwrap()).ok();
}

/// Item 3: a run's `config.toml` edited after the start (cycle 1 would
/// have run with one mass fraction, the rest with another) is refused by
/// `--resume`, naming the key and both values; nothing is recorded.
#[test]
fn a_resume_refuses_an_edited_configuration() {
    let (dir, run) = a_coarse_run_not_begun("edited");
    let before = RunState::load(&run).unwrap();
    let path = run.join("config.toml");
    let original = text(&path);
    let edited = original.replace("mass_fraction = 0.7\n", "mass_fraction = 0.5\n");
    assert_ne!(edited, original, "no mass_fraction line in {original}");
    std::fs::write(&path, &edited).unwrap();
    let ran = fwav_within(
        &["design", "--quiet", "--resume", run.to_str().unwrap()],
        REFUSAL,
    );
    let stderr = ran.refused("a resume with an edited config.toml");
    println!("{stderr}");
    for part in ["topology.mass_fraction", "0.5", "0.7", "config.toml"] {
        assert!(stderr.contains(part), "{part}: {stderr}");
    }
    assert_eq!(RunState::load(&run).unwrap(), before, "the state changed");
    // Undone, the edit is forgotten.
    std::fs::write(&path, &original).unwrap();
    let ran = fwav_within(
        &["design", "--quiet", "--resume", run.to_str().unwrap()],
        Duration::from_secs(2),
    );
    assert!(
        ran.status.is_none_or(|s| s.success()),
        "the restored configuration: {}",
        ran.stderr
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A run of the coarse design in `temp(name)/run`, its state written and
/// no stage begun; `(temp(name), the run)`.
fn a_coarse_run_not_begun(name: &str) -> (PathBuf, PathBuf) {
    let dir = temp(name);
    let run = dir.join("run");
    let config = SystemConfig::from_toml(COARSE).unwrap();
    start(
        &config,
        &run,
        &RunOptions {
            stage_limit: Some(0),
        },
        &|_| {},
    )
    .unwrap();
    (dir, run)
}

/// Makes the run in `run` one an earlier fwav started with `edit.1`
/// where its `config.toml` has `edit.0`, a value that fwav accepted and
/// this one may refuse: the file and the state's configuration (and its
/// hash) both say it, as that fwav would have written them.
pub(crate) fn as_started_by_an_earlier_fwav(run: &Path, edit: (&str, &str)) {
    let path = run.join("config.toml");
    let original = text(&path);
    let edited = original.replace(edit.0, edit.1);
    assert_ne!(edited, original, "no {:?} in {original}", edit.0);
    std::fs::write(&path, &edited).unwrap();
    let earlier = SystemConfig::parse_unchecked(&edited).unwrap();
    let stored = RunState::new(&earlier).unwrap();
    let mut state = RunState::load(run).unwrap();
    state.configuration = stored.configuration;
    state.configuration_sha256 = stored.configuration_sha256;
    state.save(run).unwrap();
}

/// The two resumes of the run in `run` that must behave alike: `fwav
/// design --resume RUN`, and the same with `--config COPY`, its
/// configuration given again (copied here to `copy`).
pub(crate) fn resumes(run: &Path, copy: &Path) -> [Vec<String>; 2] {
    std::fs::copy(run.join("config.toml"), copy).unwrap();
    let resume = ["design", "--quiet", "--resume", run.to_str().unwrap()].map(String::from);
    let mut with_config = resume.to_vec();
    with_config.extend(["--config".to_string(), copy.display().to_string()]);
    [resume.to_vec(), with_config]
}

/// A run an earlier fwav started with a value this one refuses (a carbon
/// mass fraction of 0.1, which the range's floor of 0.2 now refuses
/// because the nonlinear analysis fails there) is not continued: the
/// resume names the directory, the key, its value and the range, keeps
/// the state as it was, and says how to go on, with or without the
/// run's configuration given again by --config. (A finished one is
/// reported with a warning: `design::coarse_design_converges_writes_everything_and_resumes`.)
#[test]
fn a_run_with_a_value_now_refused_is_not_continued() {
    let (dir, run) = a_coarse_run_not_begun("refused-now");
    as_started_by_an_earlier_fwav(&run, ("mass_fraction = 0.7\n", "mass_fraction = 0.1\n"));
    let before = RunState::load(&run).unwrap();
    let listing = |dir: &Path| {
        let mut names: Vec<_> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        names.sort();
        names
    };
    let (files, config_text) = (listing(&run), text(&run.join("config.toml")));
    // The same with the run's configuration given again (--config, a
    // copy of it): compared with the run's, not refused for its range
    // before the resume can say what to do.
    let r = run.to_str().unwrap();
    for args in resumes(&run, &dir.join("copy.toml")) {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let ran = fwav_within(&args, REFUSAL);
        let stderr = ran.refused("a resume of a run with a value now refused");
        println!("{stderr}");
        for part in [
            r,
            "topology.mass_fraction = 0.1 is outside [0.2, 1]",
            "this fwav refuses",
            "start a new run",
        ] {
            assert!(stderr.contains(part), "{args:?}: {part}: {stderr}");
        }
        assert_eq!(RunState::load(&run).unwrap(), before, "the state changed");
        assert_eq!(listing(&run), files, "the directory's files changed");
        assert_eq!(text(&run.join("config.toml")), config_text);
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Item 4: while `fwav design` computes in a directory, a resume of it
/// and a second start of the same configuration are refused, naming the
/// process that holds the lock; once that process is killed (SIGKILL: no
/// chance to clean up), a resume takes its lock over and says so.
#[test]
fn a_second_writer_is_refused_and_a_dead_ones_lock_taken_over() {
    let dir = temp("lock");
    let config = dir.join("coarse.toml");
    std::fs::write(&config, COARSE).unwrap();
    let out = dir.join("run");
    let first = started_design(&config, &out);
    let pid = first.id().to_string();
    let o = out.to_str().unwrap();
    for args in [
        vec!["design", "--quiet", "--resume", o],
        vec![
            "design",
            "--quiet",
            "--config",
            config.to_str().unwrap(),
            "--out",
            o,
        ],
    ] {
        let ran = fwav_within(&args, REFUSAL);
        let stderr = ran.refused("a second writer");
        println!("{stderr}");
        assert!(stderr.contains(&pid), "pid {pid}: {stderr}");
    }
    let lock: serde_json::Value = serde_json::from_str(&text(&out.join("fwav.lock"))).unwrap();
    assert_eq!(lock["pid"].as_u64(), Some(u64::from(first.id())), "{lock}");
    assert!(
        lock["host"].as_str().is_some_and(|h| !h.is_empty()),
        "{lock}"
    );
    kill(first);

    let mut second = fwav_command(&["design", "--quiet", "--resume", o])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let (send, lines) = mpsc::channel();
    let stderr = second.stderr.take().unwrap();
    std::thread::spawn(move || {
        for line in BufReader::new(stderr).lines().map_while(Result::ok) {
            if send.send(line).is_err() {
                break;
            }
        }
    });
    let warning = lines.recv_timeout(REFUSAL);
    let holder = text(&out.join("fwav.lock"));
    kill(second);
    let warning = warning.expect("a warning about the stale lock");
    println!("{warning}");
    assert!(
        warning.contains(&pid) && warning.contains("stale"),
        "{warning}"
    );
    let holder: serde_json::Value = serde_json::from_str(&holder).unwrap();
    assert_ne!(
        holder["pid"].to_string(),
        pid,
        "the lock was not taken over"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A configuration whose keys are each in range but which cannot run
/// (coarse.toml with `edit`) is refused naming the `keys` before the run
/// directory is made, so the same command says the same thing again.
fn refused_before_the_directory_is_made(name: &str, edit: (&str, &str), keys: &[&str]) {
    let dir = temp(name);
    let bad = dir.join("bad.toml");
    let config = COARSE.replace(edit.0, edit.1);
    assert_ne!(config, COARSE);
    std::fs::write(&bad, config).unwrap();
    let out = dir.join("run");
    let args = [
        "design",
        "--quiet",
        "--config",
        bad.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    let first = fwav_within(&args, REFUSAL);
    let stderr = first.refused(name);
    println!("{name}: {stderr}");
    for key in keys {
        assert!(stderr.contains(key), "{name}: {key}: {stderr}");
    }
    assert!(stderr.contains("bad.toml"), "{name}: {stderr}");
    assert!(!out.exists(), "{name}: the run directory was made");
    let again = fwav_within(&args, REFUSAL);
    assert_eq!(again.refused(name), stderr, "{name}: the second time");
    std::fs::remove_dir_all(&dir).ok();
}

/// Item 9: a root attachment longer than the root chord.
#[test]
fn a_root_attachment_longer_than_the_chord_is_refused_first() {
    refused_before_the_directory_is_made(
        "attachment",
        ("[wing]\n", "[wing]\nroot_attachment_m = 0.08\n"),
        &["wing.root_attachment_m", "wing.root_chord_m"],
    );
}

/// Item 8: a fourth level (the L18 array takes three).
#[test]
fn a_fourth_level_is_refused() {
    refused_before_the_directory_is_made(
        "levels",
        (
            "frequency_hz = [10.0, 11.0, 12.0]",
            "frequency_hz = [9.0, 10.0, 11.0, 12.0]",
        ),
        &["design.frequency_hz", "4"],
    );
}

/// Item 8: both objective weights 0 (every design scores 0).
#[test]
fn both_objective_weights_zero_are_refused() {
    refused_before_the_directory_is_made(
        "weights",
        (
            "[design]\n",
            "[design]\nthrust_weight = 0.0\nefficiency_weight = 0.0\n",
        ),
        &["design.thrust_weight", "design.efficiency_weight"],
    );
}

/// Item 10: a corrupt `state.json` is named, with what to do about it.
#[test]
fn a_corrupt_state_file_is_named_with_the_way_out() {
    let (dir, run) = a_coarse_run_not_begun("corrupt");
    let state = text(&run.join("state.json"));
    std::fs::write(run.join("state.json"), &state[..state.len() / 2]).unwrap();
    let ran = fwav_within(
        &["design", "--quiet", "--resume", run.to_str().unwrap()],
        REFUSAL,
    );
    let stderr = ran.refused("a corrupt state.json");
    println!("{stderr}");
    for part in ["state.json", "--force", "--out"] {
        assert!(stderr.contains(part), "{part}: {stderr}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Item 10: on a terminal the live progress line is redrawn in place
/// (`\r`, clear line); a line wider than the terminal wraps, and each
/// redraw then leaves a new line. On a 40-column terminal every redraw
/// fits in 40 columns.
#[test]
fn the_progress_line_fits_the_terminal() {
    const COLUMNS: usize = 40;
    let dir = temp("width");
    let config = dir.join("coarse.toml");
    std::fs::write(&config, COARSE).unwrap();
    let (mut master, slave) = terminal(COLUMNS as u16);
    let child = fwav_command(&[
        "design",
        "--config",
        config.to_str().unwrap(),
        "--out",
        dir.join("run").to_str().unwrap(),
    ])
    .stdout(Stdio::null())
    .stderr(Stdio::from(slave))
    .spawn()
    .unwrap();
    let (send, chunks) = mpsc::channel();
    std::thread::spawn(move || {
        let mut buffer = [0u8; 4096];
        while let Ok(n) = master.read(&mut buffer) {
            if n == 0 || send.send(buffer[..n].to_vec()).is_err() {
                break;
            }
        }
    });
    const REDRAW: &str = "\r\x1b[2K";
    // The live redraws in `text`: the pieces between two redraws that
    // start a cycle's line and end without a newline (a stage's end is a
    // line of its own, printed once). The last piece is left out: the
    // reading may have cut it mid-line (a stage's end line read up to
    // "done in 0.5 s [" is no redraw).
    fn redraws(text: &str) -> Vec<&str> {
        let pieces: Vec<&str> = text.split(REDRAW).collect();
        pieces[..pieces.len().saturating_sub(1)]
            .iter()
            .copied()
            .filter(|s| s.starts_with("cycle") && !s.contains('\n'))
            .collect()
    }
    let mut seen = Vec::new();
    let clock = Instant::now();
    let live = |seen: &[u8]| redraws(&String::from_utf8_lossy(seen)).len();
    while live(&seen) < 4 && clock.elapsed() < Duration::from_secs(60) {
        if let Ok(chunk) = chunks.recv_timeout(Duration::from_millis(100)) {
            seen.extend(chunk);
        }
    }
    kill(child);
    let text = String::from_utf8_lossy(&seen).into_owned();
    let redraws = redraws(&text);
    assert!(redraws.len() >= 3, "too few redraws: {text:?}");
    for line in &redraws {
        let width = line.chars().count();
        assert!(width <= COLUMNS, "{width} columns: {line:?}");
    }
    println!("{redraws:?}");
    std::fs::remove_dir_all(&dir).ok();
}
