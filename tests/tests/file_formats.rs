//! Fuzzing every file format the programs read (issue 22): random bytes,
//! and valid files with a few random edits (bytes changed, cut or
//! repeated, numbers replaced by extreme ones, TOML/JSON tokens put in),
//! through each reader and what its command does right after reading.
//! Nothing may panic; every refusal is the reader's typed error, whose
//! text is not empty.
//!
//! The formats: the design configuration (TOML, `fwav design --config`),
//! the kinematics profile (JSON, `fwav profile check`, `fwav upload`), the
//! section and pressure histories (JSON, `fwav aero2d --deformation`,
//! `fwav topology --pressure`), a design run's `state.json` (`fwav design
//! --resume`), a section's point file (`fwav aero2d --section FILE`), Gmsh
//! and NASTRAN meshes (`fwav::shell::import`), hil-sim's scenario and plant
//! files (TOML).
//!
//! Bounded for CI by the case counts below: 16 000 cases of each text
//! reader, 4 000 of each file reader; the whole file took 62 s here (28 s
//! of CPU, on two cores shared with other builds) in the workspace's test
//! build. `PROPTEST_CASES=N` runs N cases of each instead, for a longer
//! search (20 000 each found the two regressions kept below).

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use fwav::aero2d::camber::CamberHistory;
use fwav::aero2d::case::SectionModel;
use fwav::aeroelastic::handoff::{PressureFile, SectionFile};
use fwav::config::SystemConfig;
use fwav::mdois::state::{RunRecord, RunState, Stage, StageRecord, STATE_FILE};
use fwav::profile_file::ProfileFile;
use fwav::shell::import;
use fwav::shell::material::{Layer, Section};
use fwav::topology::pressure::PressureHistory;
use fwav_actuator::params::{PlantParams, DEFAULT_PLANT_TOML};
use fwav_hil_sim::scenario::Scenario;
use fwav_protocol::document::ProfileDocument;
use fwav_protocol::Limits;
use proptest::prelude::*;
use proptest::sample::Index;
use proptest::test_runner::{Config, TestError, TestRunner};

/// `cases` cases, or `PROPTEST_CASES` when set; no failure files written
/// (a finding is kept as a named regression test instead).
fn config(cases: u32) -> Config {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(cases);
    Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    }
}

/// What readers trip on: extreme and special numbers, the words and
/// delimiters of TOML and JSON, a byte-order mark, non-ASCII text.
const TOKENS: &[&str] = &[
    "0",
    "-0",
    "-1",
    "0.5",
    "1e308",
    "-1e308",
    "1e-320",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "18446744073709551615",
    "18446744073709551616",
    "-9223372036854775809",
    "4294967296",
    "65536",
    "100000000",
    "1e15",
    "1e19",
    "\"\"",
    "\"x\"",
    "[]",
    "{}",
    "[[",
    "]]",
    "null",
    "true",
    ",",
    ":",
    "=",
    "\n",
    "[",
    "]",
    "{",
    "}",
    "\"",
    "#",
    "$",
    "*",
    "+",
    "\u{feff}",
    "\u{e9}",
    "\0",
];

/// One random edit of a file's bytes.
#[derive(Clone, Debug)]
enum Edit {
    /// This byte becomes that one.
    Replace(Index, u8),
    /// Up to this many bytes from here are cut.
    Cut(Index, usize),
    /// A token goes in here.
    Insert(Index, Index),
    /// A number of the file (a run of digits, `.`, `e`, `+`, `-`) becomes
    /// a token.
    Number(Index, Index),
    /// A line is written twice.
    RepeatLine(Index),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (any::<Index>(), any::<u8>()).prop_map(|(i, b)| Edit::Replace(i, b)),
        (any::<Index>(), 1usize..40).prop_map(|(i, n)| Edit::Cut(i, n)),
        (any::<Index>(), any::<Index>()).prop_map(|(i, t)| Edit::Insert(i, t)),
        (any::<Index>(), any::<Index>()).prop_map(|(i, t)| Edit::Number(i, t)),
        (any::<Index>(), any::<Index>()).prop_map(|(i, t)| Edit::Number(i, t)),
        any::<Index>().prop_map(Edit::RepeatLine),
    ]
}

/// The spans of the numbers in `bytes`.
fn numbers(bytes: &[u8]) -> Vec<(usize, usize)> {
    let mut spans = Vec::new();
    let mut start = None;
    for (i, b) in bytes.iter().enumerate() {
        let inside = b.is_ascii_digit() || (start.is_some() && b".eE+-".contains(b));
        match (inside, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                spans.push((s, i));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        spans.push((s, bytes.len()));
    }
    spans
}

fn apply(valid: &str, edits: &[Edit]) -> Vec<u8> {
    let mut bytes = valid.as_bytes().to_vec();
    for e in edits {
        let at = |i: &Index, len: usize| if len == 0 { 0 } else { i.index(len) };
        match e {
            Edit::Replace(i, b) if !bytes.is_empty() => {
                let k = at(i, bytes.len());
                bytes[k] = *b;
            }
            Edit::Cut(i, n) if !bytes.is_empty() => {
                let k = at(i, bytes.len());
                let end = (k + n).min(bytes.len());
                bytes.drain(k..end);
            }
            Edit::Insert(i, t) => {
                let k = at(i, bytes.len() + 1);
                let token = TOKENS[t.index(TOKENS.len())].as_bytes();
                bytes.splice(k..k, token.iter().copied());
            }
            Edit::Number(i, t) => {
                let spans = numbers(&bytes);
                if !spans.is_empty() {
                    let (s, end) = spans[i.index(spans.len())];
                    let token = TOKENS[t.index(TOKENS.len())].as_bytes();
                    bytes.splice(s..end, token.iter().copied());
                }
            }
            Edit::RepeatLine(i) => {
                let lines: Vec<&[u8]> = bytes.split_inclusive(|&b| b == b'\n').collect();
                if !lines.is_empty() {
                    let k = i.index(lines.len());
                    let mut out = Vec::with_capacity(bytes.len() + lines[k].len());
                    for (j, line) in lines.iter().enumerate() {
                        out.extend_from_slice(line);
                        if j == k {
                            out.extend_from_slice(line);
                        }
                    }
                    bytes = out;
                }
            }
            _ => {}
        }
    }
    bytes
}

/// A valid file with one to five random edits.
fn mutated(valid: String) -> impl Strategy<Value = Vec<u8>> {
    proptest::collection::vec(edit(), 1..6).prop_map(move |edits| apply(&valid, &edits))
}

/// Random bytes, up to 600 of them.
fn random_bytes() -> impl Strategy<Value = Vec<u8>> {
    proptest::collection::vec(any::<u8>(), 0..600)
}

/// A refusal reads as text.
fn refused<E: std::fmt::Display>(e: &E) {
    assert!(!e.to_string().trim().is_empty());
}

/// A scratch directory of this test binary, one per reader.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("fwav-fuzz-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

// --- the readers, each with what its command does right after ---

/// `fwav design --config F` (and every command's `--config`).
fn design_toml(bytes: &[u8]) {
    match SystemConfig::from_toml(&String::from_utf8_lossy(bytes)) {
        Ok(config) => {
            let _ = (config.planform(), config.kinematics(), config.flight());
        }
        Err(e) => refused(&e),
    }
}

/// `fwav profile check F` and `fwav upload F`: read, convert, check
/// against the limits, print.
fn profile_json(dir: &Path, bytes: &[u8]) {
    let path = dir.join("profile.json");
    std::fs::write(&path, bytes).unwrap();
    match ProfileFile::load(&path) {
        Ok(loaded) => {
            for v in loaded.violations(&Limits::REFERENCE_FWAV) {
                refused(&v);
            }
            let document = ProfileDocument::from_profile(&loaded.profile, "");
            let _ = (document.to_json_pretty(), loaded.profile.duration_s());
        }
        Err(e) => refused(&e),
    }
}

/// `fwav aero2d --deformation F`: read, then the camber history the
/// solver takes.
fn section_json(bytes: &[u8]) {
    match SectionFile::from_json(&String::from_utf8_lossy(bytes)) {
        Ok(file) => {
            if let Err(e) = CamberHistory::from_section_points(&file.points(), 1.0, 21) {
                refused(&e);
            }
        }
        Err(e) => refused(&e),
    }
}

/// `fwav topology --pressure F`: read, then the history on a mesh of 3
/// elements.
fn pressure_json(bytes: &[u8]) {
    match PressureFile::from_json(&String::from_utf8_lossy(bytes)) {
        Ok(file) => {
            if let Err(e) = PressureHistory::from_file(file, 3) {
                refused(&e);
            }
        }
        Err(e) => refused(&e),
    }
}

/// `fwav design --resume DIR`: read the state and the configuration the
/// run started with, compare it with the run's, cut the state back to
/// what the directory holds, number the next run.
fn state_json(dir: &Path, bytes: &[u8]) {
    std::fs::write(dir.join(STATE_FILE), bytes).unwrap();
    let mut state = match RunState::load(dir) {
        Ok(state) => state,
        Err(e) => return refused(&e),
    };
    match state.started_with(dir) {
        Ok(started) => {
            if let Err(e) = state.is_of(&started) {
                refused(&e);
            }
        }
        Err(e) => refused(&e),
    }
    state.consistent_prefix(dir);
    let _ = state.next_run();
}

/// `fwav aero2d --section FILE`: the point file, then the panel shape.
fn points_file(dir: &Path, bytes: &[u8]) {
    let path = dir.join("section.dat");
    std::fs::write(&path, bytes).unwrap();
    if let Err(e) = SectionModel::named(path.to_str().unwrap()) {
        refused(&e);
    }
}

fn gmsh(bytes: &[u8]) {
    let default = Section::single(&Layer::MYLAR);
    if let Err(e) = import::gmsh(&String::from_utf8_lossy(bytes), default) {
        refused(&e);
    }
}

fn nastran(bytes: &[u8]) {
    if let Err(e) = import::nastran(&String::from_utf8_lossy(bytes)) {
        refused(&e);
    }
}

/// `hil-sim run S`: the scenario and the profile it uploads.
fn scenario_toml(bytes: &[u8]) {
    match Scenario::from_toml(&String::from_utf8_lossy(bytes)) {
        Ok(scenario) => {
            if let Err(e) = scenario.profile() {
                refused(&e);
            }
        }
        Err(e) => refused(&e),
    }
}

/// `hil-sim --plant F`.
fn plant_toml(bytes: &[u8]) {
    if let Err(e) = PlantParams::from_toml(&String::from_utf8_lossy(bytes)) {
        refused(&e);
    }
}

// --- the valid files the edits start from ---

const COARSE: &str = include_str!("../../configs/coarse.toml");
const PROFILE: &str = include_str!("../../host/profiles/initial-design.json");
const SECTION: &str = r#"{"format": "fwav-section-history", "format_version": 1, "period_s": 0.09,
 "samples": [[[0.0, 0.0], [0.5, 0.01], [1.0, 0.02]], [[0.0, 0.0], [0.5, -0.01], [1.0, -0.02]]]}"#;
const PRESSURE: &str = r#"{"format": "fwav-pressure-history", "format_version": 1, "dt_s": 0.005,
 "samples": [[1.0, 2.0, 3.0], [-1.0, -2.0, -3.0]]}"#;
const POINTS: &str = "ellipse, 6% thick (24 panels: the reader takes 20 points or more)\n\
                      1.0000 0.0000\n0.9830 0.0155\n0.9330 0.0300\n0.8536 0.0424\n0.7500 0.0520\n\
                      0.6294 0.0580\n0.5000 0.0600\n0.3706 0.0580\n0.2500 0.0520\n0.1464 0.0424\n\
                      0.0670 0.0300\n0.0170 0.0155\n0.0000 0.0000\n0.0170 -0.0155\n0.0670 -0.0300\n\
                      0.1464 -0.0424\n0.2500 -0.0520\n0.3706 -0.0580\n0.5000 -0.0600\n0.6294 -0.0580\n\
                      0.7500 -0.0520\n0.8536 -0.0424\n0.9330 -0.0300\n0.9830 -0.0155\n1.0000 -0.0000\n";
/// One block of nodes, and a quadrangle, a triangle and a line element
/// (skipped: not a shell) in three blocks.
const GMSH: &str = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 5 1 5\n2 1 0 5\n\
                    1\n2\n3\n4\n5\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0.5 0\n$EndNodes\n\
                    $Elements\n3 3 1 3\n2 1 3 1\n1 1 2 3 4\n2 1 2 1\n2 2 5 3\n\
                    1 1 1 1\n3 1 2\n$EndElements\n";
const NASTRAN: &str = "$ a two-element plate\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n\
                       GRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\nGRID,5,,2.,0.5,0.\n\
                       CQUAD4,10,7,1,2,3,4\nCTRIA3,11,7,2,5,3\nPSHELL,7,3,1.-3\n\
                       MAT1,3,70.+9,,0.3,2700.\n\
                       GRID           6              3.      0.      0.\n";
const SCENARIO: &str = include_str!("../../hil-sim/scenarios/encoder-loss.toml");

/// A state of a run with two cycles begun, whose files are in `dir`.
fn state(dir: &Path) -> String {
    let mut state = RunState::new(&SystemConfig::from_toml(COARSE).unwrap()).unwrap();
    for run in 1..=2 {
        state.runs.push(RunRecord {
            run,
            started_unix_s: 1_700_000_000 + 60 * run as u64,
        });
    }
    for (cycle, stage, file) in [
        (1, Stage::System, "cycle-1/system.json"),
        (1, Stage::Kinematics, "cycle-1/kinematics.json"),
        (1, Stage::Topology, "cycle-1/topology.json"),
        (2, Stage::System, "cycle-2/system.json"),
    ] {
        let path = dir.join(file);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, "{}").unwrap();
        state.finish(
            cycle,
            stage,
            StageRecord {
                run: 1,
                seconds: 2.5,
                files: vec![file.to_owned()],
            },
        );
    }
    serde_json::to_string_pretty(&state).unwrap()
}

/// The seeds are valid: the edits start from files every reader takes.
#[test]
fn the_seeds_are_read() {
    SystemConfig::from_toml(COARSE).unwrap();
    SectionFile::from_json(SECTION).unwrap();
    PressureHistory::from_file(PressureFile::from_json(PRESSURE).unwrap(), 3).unwrap();
    import::gmsh(GMSH, Section::single(&Layer::MYLAR)).unwrap();
    import::nastran(NASTRAN).unwrap();
    Scenario::from_toml(SCENARIO).unwrap().profile().unwrap();
    PlantParams::from_toml(DEFAULT_PLANT_TOML).unwrap();
    let dir = scratch("seeds");
    std::fs::write(dir.join("profile.json"), PROFILE).unwrap();
    ProfileFile::load(dir.join("profile.json")).unwrap();
    let text = state(&dir);
    std::fs::write(dir.join(STATE_FILE), text).unwrap();
    let mut loaded = RunState::load(&dir).unwrap();
    assert!(loaded.consistent_prefix(&dir).is_empty());
    std::fs::write(dir.join("section.dat"), POINTS).unwrap();
    SectionModel::named(dir.join("section.dat").to_str().unwrap()).unwrap();
    std::fs::remove_dir_all(&dir).ok();
}

/// How long one input may take before its reader is taken to hang.
const HANG: Duration = Duration::from_secs(20);

/// Runs `read` on `cases` inputs, random bytes and edits of `valid`; a
/// panic is shrunk to a small input and reported with it as text. A
/// watchdog ends the test binary, printing the input, when one input
/// takes longer than [`HANG`] (a reader walking a count read as 1e19).
fn fuzz(cases: u32, valid: String, read: impl Fn(&[u8])) {
    let current = Arc::new(Mutex::new((Instant::now(), Vec::new())));
    let done = Arc::new(AtomicBool::new(false));
    let watchdog = {
        let (current, done) = (current.clone(), done.clone());
        std::thread::spawn(move || {
            while !done.load(Ordering::Relaxed) {
                std::thread::sleep(Duration::from_millis(100));
                let (started, bytes) = &*current.lock().unwrap();
                if started.elapsed() > HANG {
                    eprintln!(
                        "a reader hangs (over {HANG:?}) on input: {:?}",
                        String::from_utf8_lossy(bytes)
                    );
                    std::process::exit(1);
                }
            }
        })
    };
    let mut runner = TestRunner::new(config(cases));
    let inputs = prop_oneof![random_bytes(), mutated(valid)];
    let result = runner.run(&inputs, |bytes| {
        *current.lock().unwrap() = (Instant::now(), bytes.clone());
        read(&bytes);
        Ok(())
    });
    done.store(true, Ordering::Relaxed);
    watchdog.join().unwrap();
    match result {
        Ok(()) => {}
        Err(TestError::Fail(why, bytes)) => {
            panic!("{why}\ninput: {:?}", String::from_utf8_lossy(&bytes))
        }
        Err(TestError::Abort(why)) => panic!("{why}"),
    }
}

/// `read()`'s result, or a panic when it takes longer than [`HANG`].
fn finishes<T: Send + 'static>(read: impl FnOnce() -> T + Send + 'static) -> T {
    let (send, receive) = std::sync::mpsc::channel();
    std::thread::spawn(move || send.send(read()));
    receive
        .recv_timeout(HANG)
        .unwrap_or_else(|_| panic!("the reader did not finish within {HANG:?}"))
}

// --- what the fuzzing found, kept ---

/// A Gmsh block of a skipped element type (here lines) whose count reads
/// 1e19 was walked entry by entry for hours (found by
/// `gmsh_never_panics`); now refused at once as running past the end of
/// the file, and so is a block of nodes.
#[test]
fn a_gmsh_block_count_beyond_the_file_is_refused_at_once() {
    for (block, huge) in [
        ("1 1 1 1\n3 1 2", "1 1 1 1e19\n3 1 2"),
        ("2 1 0 5\n", "2 1 0 18446744073709551615\n"),
    ] {
        let msh = GMSH.replace(block, huge);
        let e = finishes(move || import::gmsh(&msh, Section::single(&Layer::MYLAR)))
            .expect_err("refused");
        assert!(e.to_string().contains("past the end of the file"), "{e}");
    }
}

/// A run number of usize::MAX in `state.json` overflowed the number of
/// the next run, a panic on `--resume` (found by
/// `state_json_never_panics`); the reader now refuses run numbers other
/// than the driver's 1, 2, ... in order.
#[test]
fn a_state_with_a_run_number_the_driver_never_wrote_is_refused() {
    let dir = scratch("state-run");
    let text = state(&dir).replacen("\"run\": 1,", "\"run\": 18446744073709551615,", 1);
    assert!(text.contains("18446744073709551615"));
    std::fs::write(dir.join(STATE_FILE), text).unwrap();
    let e = RunState::load(&dir).expect_err("refused");
    assert!(
        e.to_string()
            .contains("run 1 is numbered 18446744073709551615"),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Cases of each reader of a text in CI (0.3 to 0.6 ms a case here).
const CASES: u32 = 16_000;

/// Cases of each reader of a file, one written a case (2 to 3 ms a case).
const FILE_CASES: u32 = 4_000;

#[test]
fn design_toml_never_panics() {
    fuzz(CASES, COARSE.into(), design_toml);
}

#[test]
fn profile_json_never_panics() {
    let dir = scratch("profile");
    fuzz(FILE_CASES, PROFILE.into(), |bytes| {
        profile_json(&dir, bytes)
    });
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn section_json_never_panics() {
    fuzz(CASES, SECTION.into(), section_json);
}

#[test]
fn pressure_json_never_panics() {
    fuzz(CASES, PRESSURE.into(), pressure_json);
}

#[test]
fn state_json_never_panics() {
    let dir = scratch("state");
    fuzz(FILE_CASES, state(&dir), |bytes| state_json(&dir, bytes));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn points_file_never_panics() {
    let dir = scratch("points");
    fuzz(FILE_CASES, POINTS.into(), |bytes| points_file(&dir, bytes));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn gmsh_never_panics() {
    fuzz(CASES, GMSH.into(), gmsh);
}

#[test]
fn nastran_never_panics() {
    fuzz(CASES, NASTRAN.into(), nastran);
}

#[test]
fn scenario_toml_never_panics() {
    fuzz(CASES, SCENARIO.into(), scenario_toml);
}

#[test]
fn plant_toml_never_panics() {
    fuzz(CASES, DEFAULT_PLANT_TOML.into(), plant_toml);
}
