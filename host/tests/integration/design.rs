//! The MDOIS design run end to end on a coarse wing: it converges, writes
//! every output, resumes after an interruption or a kill without redoing
//! finished stages and with the same answer, and refuses bad
//! configurations naming the field.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use fwav::aeroelastic::last_cycle::Doubt;
use fwav::config::SystemConfig;
use fwav::file_format::{FormatError, ReadError};
use fwav::mdois::state::RunState;
use fwav::mdois::summary::Summary;
use fwav::mdois::{resume, start, DesignError, DesignRun, Outcome, RunOptions, Stage};

use crate::program::{fwav, fwav_command};

/// The coarse design of the tests and the README (documented in the file).
const COARSE: &str = include_str!("../../../configs/coarse.toml");

fn coarse() -> SystemConfig {
    SystemConfig::from_toml(COARSE).unwrap()
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("fwav-design-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    dir
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The numbers of a run that do not depend on how it was run (stage
/// times and invocation numbers left out): per cycle the design analysed,
/// its 3D means, the proposals and their 2D values, the structural
/// results; and the final layout.
fn answer(dir: &Path) -> Vec<f64> {
    let summary = json(&dir.join("summary.json"));
    let mut values = Vec::new();
    for c in summary["cycles"].as_array().unwrap() {
        for key in [
            "frequency_hz",
            "amplitude_deg",
            "mean_angle_deg",
            "stroke_plane_deg",
        ] {
            values.push(c["kinematics"][key].as_f64().unwrap());
            values.push(c["aerodynamic"]["proposed"][key].as_f64().unwrap_or(-1.0));
        }
        values.push(c["carbon_mass_fraction"].as_f64().unwrap());
        for key in ["ct", "cp", "efficiency", "wing_mass_kg"] {
            values.push(c["system"][key].as_f64().unwrap());
        }
        for key in ["ct", "efficiency"] {
            values.push(
                c["aerodynamic"]["proposed_2d"][key]
                    .as_f64()
                    .unwrap_or(-1.0),
            );
        }
        for key in ["strain_energy_j", "mass_fraction", "elements_changed"] {
            values.push(c["structural"][key].as_f64().unwrap_or(-1.0));
        }
    }
    let topology = std::fs::read_to_string(dir.join("topology.vtu")).unwrap();
    values.extend(
        topology
            .split("Name=\"carbon\"")
            .nth(1)
            .unwrap()
            .split('>')
            .nth(1)
            .unwrap()
            .split('<')
            .next()
            .unwrap()
            .split_whitespace()
            .map(|v| v.parse::<f64>().unwrap()),
    );
    values
}

fn assert_same(a: &[f64], b: &[f64]) {
    assert_eq!(a.len(), b.len());
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        assert!(
            (x - y).abs() <= 1e-9 * x.abs().max(1e-12),
            "value {i}: {x} != {y}"
        );
    }
}

/// `plant.toml` parses as hil-sim's plant; its tuned spring is `k = (J_wing
/// + N^2 J_rotor) (2 pi f)^2` at the frequency `kinematics.json` flies;
/// its aerodynamic damping is the final analysis's drive work per cycle
/// over `int |rate|^3 dt`, computed here from `cycle-N/system.json`'s
/// last cycle (drive torque times the prescribed rate `-A w sin(w t)`).
fn designed_plant_is_the_final_analysis(dir: &Path, cycle: usize, flown_hz: f64) {
    let text = std::fs::read_to_string(dir.join("plant.toml")).unwrap();
    let plant = fwav_actuator::params::PlantParams::from_toml(&text).unwrap();
    let n = plant.transmission.gear_ratio;
    let j = plant.wing.inertia_kg_m2 + n * n * plant.motor.rotor_inertia_kg_m2;
    let w = 2.0 * std::f64::consts::PI * flown_hz;
    let k = plant.transmission.spring_nm_per_rad;
    assert!((k / (j * w * w) - 1.0).abs() < 1e-9, "{k} vs {}", j * w * w);
    let record = json(&dir.join(format!("cycle-{cycle}/system.json")));
    let kin = &record["kinematics"];
    let f = kin["frequency_hz"].as_f64().unwrap();
    let a = kin["amplitude_deg"].as_f64().unwrap().to_radians();
    let per_cycle = record["steps_per_cycle"].as_u64().unwrap() as usize;
    let steps = record["steps"].as_array().unwrap();
    let (mut work, mut cube) = (0.0, 0.0);
    for s in &steps[steps.len() - per_cycle..] {
        let t = s["time_s"].as_f64().unwrap();
        let wf = 2.0 * std::f64::consts::PI * f;
        let rate = -a * wf * (wf * t).sin();
        work += s["drive_torque_nm"].as_f64().unwrap() * rate;
        cube += rate.abs().powi(3);
    }
    let c_a = plant.wing.aero_damping();
    assert!(
        (c_a / (work / cube) - 1.0).abs() < 1e-9,
        "{c_a} vs {}",
        work / cube
    );
}

fn run_of(state: &RunState, cycle: usize, stage: Stage) -> Option<usize> {
    state.stage(cycle, stage).map(|r| r.run)
}

/// Had an earlier fwav run the finished coarse run in `dir` with a value
/// this one refuses (a carbon mass fraction of 0.1, below today's floor
/// of 0.2), a resume still reports it as computed (`done`'s summary),
/// computing nothing, with the refusal beside it (and `fwav design
/// --resume`, with or without `--config` giving the run's configuration
/// again, prints it as a warning); the run's files are put back after.
fn a_finished_run_now_refused_is_reported(dir: &Path, done: &DesignRun) {
    let kept: Vec<(&str, Vec<u8>)> = ["config.toml", "state.json"]
        .into_iter()
        .map(|f| (f, std::fs::read(dir.join(f)).unwrap()))
        .collect();
    crate::design_safety::as_started_by_an_earlier_fwav(
        dir,
        ("mass_fraction = 0.7\n", "mass_fraction = 0.1\n"),
    );
    let earlier = resume(dir, None, &RunOptions::default(), &|_| {}).unwrap();
    assert!(earlier.finished_before && earlier.stages_computed == 0);
    assert_eq!(earlier.outcome, done.outcome);
    let refusal = earlier.refused_now.expect("the value now refused, said");
    assert!(
        refusal.contains("topology.mass_fraction = 0.1 is outside [0.2, 1]"),
        "{refusal}"
    );
    assert_eq!(earlier.summary, done.summary);
    // The command says so on its warning line, and reports the run; the
    // same with the run's configuration given again (--config, a copy).
    let copy = dir.with_extension("config-copy.toml");
    let d = dir.to_str().unwrap();
    for args in crate::design_safety::resumes(dir, &copy) {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = fwav(&args);
        let (stdout, stderr) = (
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr),
        );
        assert!(out.status.success(), "{args:?}: {stderr}");
        for part in [
            "warning: ",
            d,
            "was run with a configuration this fwav refuses (topology.mass_fraction = 0.1 is \
             outside [0.2, 1])",
            "reported as they were computed",
        ] {
            assert!(stderr.contains(part), "{args:?}: {part}: {stderr}");
        }
        assert!(
            stdout.contains("the run had already finished: nothing computed"),
            "{args:?}: {stdout}"
        );
    }
    std::fs::remove_file(&copy).ok();
    for (file, bytes) in kept {
        std::fs::write(dir.join(file), bytes).unwrap();
    }
}

/// The coarse design converges (the documented case: cycle 2) and writes
/// every output; summary.json has every number the issue asks for; the
/// kinematics file is a valid profile document. A finished run is not
/// started over. Then the same design killed mid-run and resumed gives
/// the same answer (`killed_design_resumes_with_the_same_answer`).
#[test]
fn coarse_design_converges_writes_everything_and_resumes() {
    let clock = Instant::now();
    let dir = temp("full");
    let run = start(&coarse(), &dir, &RunOptions::default(), &|_| {}).unwrap();
    println!("uninterrupted run: {:.1} s", clock.elapsed().as_secs_f64());
    // Converges in cycle 2 (6 stages). With leading-edge shedding the
    // section's thrust is capped near 2 pi LESP_c^2 (issue 21, deliver 9)
    // and the net efficiency decides: cycle 1 takes the best L18 row (10
    // Hz, +-25 deg, -5 deg, 80 deg; combined objective 2.544421) over
    // the RSM's design, the same point to 1e-8 Hz and 1e-7 deg, whose
    // confirmation scored 2.523094 (the leading-edge shedding is that
    // sensitive), and ANOM's (+5 deg, a plane of 100 deg: 2.513369);
    // cycle 2, on that design's deformation, keeps it. (Until 2026-12-07 the LDVM
    // placed its newest wake vortex a third of the way to the last and
    // gave the chord the vortices' 1.3 U dt core, so its loads converged
    // as sqrt(dt) (`fwav::aero2d::ldvm`, "The wake next to the edge";
    // `aero2d::garrick_loads_within_1_percent_at_every_step`):
    // cycle 1 took the RSM's +5 deg (2.673968) and cycle 2 went back to
    // the row, converging in cycle 3. Earlier on 2026-12-07 the LDVM's
    // deformation work was taken at the step's end, not the half step
    // (`aero2d::camber_that_is_a_rotation_lifts_like_pitch`): cycle 1
    // took that L18 row and the run converged in cycle 2 on the same
    // final kinematics. Until 2026-12-05 the cycle means' windows took
    // one sample more than their periods about half the time
    // (`fwav::aero2d::history::window`); the L18 row and the RSM's
    // design then tied to 7e-6 and the run converged in cycle 3, or in
    // cycle 2 while serde_json's float parser was an ulp off.)
    assert_eq!(run.outcome, Some(Outcome::Converged { cycle: 2 }));
    assert_eq!(run.stages_computed, 6);
    for file in [
        "summary.json",
        "report.md",
        "config.toml",
        "state.json",
        "topology.vtu",
        "topology.png",
        "convergence.png",
        "pareto.png",
        "main-effects.png",
        "thrust-history.png",
        "kinematics.json",
        "wing-cycle-1.vtu",
        "wing-cycle-2.vtu",
        "cycle-1/system.json",
        "cycle-1/section.json",
        "cycle-1/pressure.json",
        "cycle-1/kinematics.json",
        "cycle-1/topology.json",
        "cycle-2/system.json",
    ] {
        let size = std::fs::metadata(dir.join(file)).map_or(0, |m| m.len());
        assert!(size > 100, "{file}: {size} bytes");
    }
    let summary = json(&dir.join("summary.json"));
    assert_eq!(summary["finished"], true);
    assert_eq!(summary["outcome"], "converged");
    let cycles = summary["cycles"].as_array().unwrap();
    assert_eq!(cycles.len(), 2);
    for c in cycles {
        for key in ["ct", "cp", "efficiency", "seconds"] {
            assert!(c["system"][key].is_f64(), "system.{key}: {c}");
        }
        for key in [
            "frequency_hz",
            "amplitude_deg",
            "mean_angle_deg",
            "stroke_plane_deg",
        ] {
            assert!(c["kinematics"][key].is_f64(), "{key}");
        }
        assert!(c["aerodynamic"]["proposed_2d"]["efficiency"].is_f64());
        assert!(c["aerodynamic"]["proposed_2d"]["ct"].is_f64());
        assert!(c["structural"]["strain_energy_j"].as_f64().unwrap() > 0.0);
        assert!(c["structural"]["mass_fraction"].is_f64());
        assert!(c["structural"]["elements_changed"].is_u64());
        assert!(c["structural"]["seconds"].is_f64());
        assert!(c["change"]["design_unchanged"].is_boolean());
    }
    assert_eq!(cycles[1]["change"]["design_unchanged"], true);
    assert_eq!(cycles[0]["change"]["design_unchanged"], false);
    // One objective for the whole design: cycle 2's aerodynamic
    // discipline divides by cycle 1's initial design's net CT and
    // efficiency, not by its own design's.
    let first = json(&dir.join("cycle-1/kinematics.json"));
    let second = json(&dir.join("cycle-2/kinematics.json"));
    let initial = &first["result"]["initial"]["result"]["Ok"];
    let reference = &first["result"]["reference"];
    assert_eq!(reference["ct_net"], initial["ct_net"], "{reference}");
    assert_eq!(reference["efficiency_net"], initial["efficiency_net"]);
    assert_eq!(&second["result"]["reference"], reference);
    assert_ne!(
        second["result"]["initial"]["result"]["Ok"]["ct_net"], initial["ct_net"],
        "cycle 2 analyses another design (or section) than cycle 1"
    );
    for key in ["initial", "final"] {
        assert!(summary[key]["ct"].is_f64(), "{key}");
    }
    assert_eq!(summary["final"]["cycle"], 2);
    assert!(summary["comparison"]["ct_relative_change"].is_f64());
    let report = std::fs::read_to_string(dir.join("report.md")).unwrap();
    assert!(report.contains("Converged in cycle 2") && report.contains("convergence.png"));
    let profile = fwav::profile_file::ProfileFile::load(dir.join("kinematics.json")).unwrap();
    let f = summary["final"]["kinematics"]["frequency_hz"]
        .as_f64()
        .unwrap();
    assert!((profile.document.segments[0].frequency_hz - f).abs() < 1e-4 * f);
    designed_plant_is_the_final_analysis(&dir, 2, profile.document.segments[0].frequency_hz);
    // The flown kinematics are the final analysed ones (no derating) and
    // the actuator flies them with the reserve: judged here on plant.toml
    // by the actuator crate's check, under the design file's limits.
    let segment = profile.document.segments[0];
    for (file, key) in [
        (segment.amplitude_deg, "amplitude_deg"),
        (segment.mean_deg, "mean_angle_deg"),
    ] {
        let analysed = summary["final"]["kinematics"][key].as_f64().unwrap();
        assert!(
            (file - analysed).abs() < 1e-4 * analysed.abs().max(1.0),
            "{key}"
        );
    }
    let plant = fwav_actuator::params::PlantParams::from_toml(
        &std::fs::read_to_string(dir.join("plant.toml")).unwrap(),
    )
    .unwrap();
    let limits = coarse().actuator.actuator().limits;
    let verdict = fwav_actuator::feasibility::check(
        &plant,
        &limits,
        &fwav_actuator::feasibility::FlappingDemand {
            frequency_hz: segment.frequency_hz,
            amplitude_deg: segment.amplitude_deg,
            mean_deg: segment.mean_deg,
        },
    )
    .unwrap();
    println!("final design on its vehicle: limiting {}", verdict.limiting);
    assert!(verdict.feasible, "{verdict:?}");
    assert!(verdict.limiting.margin >= limits.reserve);
    assert_eq!(summary["actuator"]["feasible"], true);
    let reference = answer(&dir);

    // A finished run is not started over: started again with the same
    // configuration or resumed, it computes nothing and says it had
    // finished; started with another configuration, it is refused naming
    // the first differing key.
    let again = start(&coarse(), &dir, &RunOptions::default(), &|_| {}).unwrap();
    assert!(again.finished_before && again.stages_computed == 0);
    let mut other = coarse();
    other.design.seed = 2;
    let e = start(&other, &dir, &RunOptions::default(), &|_| {}).unwrap_err();
    assert!(
        matches!(e, DesignError::Exists { ref field, .. } if field == "design.seed"),
        "{e}"
    );
    let done = resume(&dir, None, &RunOptions::default(), &|_| {}).unwrap();
    assert_eq!(done.stages_computed, 0);
    assert!(done.finished_before);
    assert_eq!(done.outcome, run.outcome);
    assert_eq!(done.refused_now, None);
    a_finished_run_now_refused_is_reported(&dir, &done);

    killed_design_resumes_with_the_same_answer(&reference);

    // The summary reads back through its own type (its numbers to the
    // parser's last bit); a stage file of another format version is
    // refused, naming the file and both versions.
    let read = Summary::read(&dir.join("summary.json")).unwrap();
    assert_eq!(
        (read.outcome, read.converged_cycle, read.cycles.len()),
        (done.summary.outcome.clone(), Some(2), 2)
    );
    let system = dir.join("cycle-1/system.json");
    let text = std::fs::read_to_string(&system)
        .unwrap()
        .replace("\"format_version\":1,", "\"format_version\":2,");
    std::fs::write(&system, text).unwrap();
    let e = resume(&dir, None, &RunOptions::default(), &|_| {}).unwrap_err();
    assert!(
        matches!(
            &e,
            DesignError::Read(ReadError::Format {
                error: FormatError::UnsupportedVersion {
                    found: Some(2),
                    expected: 1,
                    ..
                },
                ..
            })
        ),
        "{e}"
    );
    assert!(e.to_string().contains("system.json"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
    println!("whole test: {:.1} s", clock.elapsed().as_secs_f64());
}

/// `fwav design` killed (SIGKILL) in cycle 1's aerodynamic discipline,
/// once its system analysis is finished and the discipline has evaluated
/// a row, a stage file of the interrupted stage left half-written and an
/// unrecorded one left complete-looking, then `fwav design --resume`: the
/// finished stage is not redone (invocation 1 computed it), the
/// discipline's evaluations done before the kill are reused from
/// `evaluations.json` (written at each result, not at the stage's end),
/// the rest is computed, and the answer is the uninterrupted run's
/// (`reference`, from the caller's run: one coarse design fewer in CI
/// than a run of its own).
fn killed_design_resumes_with_the_same_answer(reference: &[f64]) {
    let dir = temp("killed");
    std::fs::create_dir_all(&dir).unwrap();
    let config = dir.join("coarse.toml");
    std::fs::write(&config, COARSE).unwrap();
    let out = dir.join("run");
    let mut child = fwav_command(&["design", "--quiet", "--config"])
        .arg(&config)
        .arg("--out")
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let clock = Instant::now();
    // The cache file appears at the discipline's first result (about 0.6 s
    // an evaluation here, some twenty in the stage).
    let evaluations = out.join("evaluations.json");
    loop {
        let finished = RunState::load(&out)
            .ok()
            .is_some_and(|s| s.stage(1, Stage::System).is_some());
        if finished && evaluations.exists() {
            break;
        }
        assert!(clock.elapsed() < Duration::from_secs(120), "no progress");
        std::thread::sleep(Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let before = RunState::load(&out).unwrap();
    assert_eq!(before.outcome, None, "killed after the end");
    assert!(
        before.stage(1, Stage::Kinematics).is_none(),
        "the kill came after the discipline's end: no mid-stage evaluations to reuse"
    );
    let kept = json(&evaluations)["entries"].as_object().unwrap().len();
    assert!(kept >= 1, "no evaluation kept");
    // What a kill mid-stage leaves: the interrupted stage's file half
    // written beside its final name, and (had the kill come between a
    // stage's files and the state) a finished-looking file the state does
    // not record. The resume must recompute and replace both.
    if before.stage(1, Stage::Kinematics).is_none() {
        std::fs::write(out.join("cycle-1/kinematics.json.partial"), "{\"ste").unwrap();
        std::fs::write(out.join("cycle-1/kinematics.json"), "{\"stale\": true}").unwrap();
    }
    let resumed = fwav(&[
        "design",
        "--quiet",
        "--json",
        "--resume",
        out.to_str().unwrap(),
    ]);
    assert!(
        resumed.status.success(),
        "{}",
        String::from_utf8_lossy(&resumed.stderr)
    );
    let summary: serde_json::Value = serde_json::from_slice(&resumed.stdout).unwrap();
    assert_eq!(summary["outcome"], "converged");
    let reused = summary["cycles"][0]["aerodynamic"]["evaluations_reused"]
        .as_u64()
        .unwrap();
    assert!(
        reused >= kept as u64,
        "{kept} evaluations were on disk at the kill, {reused} reused"
    );
    // Resumed again, the finished run says so instead of "0 stage(s)
    // computed, 0 reused", and its lock is gone.
    let finished = fwav(&["design", "--resume", out.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&finished.stdout);
    assert!(
        finished.status.success(),
        "{}",
        String::from_utf8_lossy(&finished.stderr)
    );
    assert!(
        stdout.contains("converged in cycle")
            && stdout.contains("the run had already finished: nothing computed")
            && !stdout.contains("0 stage(s) computed"),
        "{stdout}"
    );
    assert!(!out.join("fwav.lock").exists());
    let after = RunState::load(&out).unwrap();
    assert_eq!(run_of(&after, 1, Stage::System), Some(1));
    for c in &before.cycles {
        for stage in [Stage::System, Stage::Kinematics, Stage::Topology] {
            if c.get(stage).is_some() {
                assert_eq!(run_of(&after, c.cycle, stage), Some(1), "{stage}");
            }
        }
    }
    assert_eq!(run_of(&after, 2, Stage::System), Some(2));

    assert_same(reference, &answer(&out));
    std::fs::remove_dir_all(&dir).ok();
}

/// `fwav init` writes the default configuration, which parses back to
/// the built-in FWAV's, and refuses to overwrite it without --force.
#[test]
fn init_writes_the_default_configuration() {
    let dir = temp("init");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("fwav.toml");
    let path = file.to_str().unwrap();
    let out = fwav(&["init", "--out", path]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&file).unwrap();
    assert_eq!(
        SystemConfig::from_toml(&text).unwrap(),
        SystemConfig::default()
    );
    for table in ["[wing]", "[analysis]", "[design]", "[topology]", "[mdois]"] {
        assert!(text.contains(table), "{table}");
    }
    assert!(
        text.contains("max_cycles = 5")
            && text.contains("# Design cycles allowed")
            && text.contains("1..=50.")
    );
    let again = fwav(&["init", "--out", path]);
    assert!(!again.status.success());
    assert!(String::from_utf8_lossy(&again.stderr).contains("--force"));
    assert!(fwav(&["init", "--out", path, "--force"]).status.success());
    std::fs::remove_dir_all(&dir).ok();
}

/// Bad configurations are refused before anything runs, the error naming
/// the field and its range; a resume with another configuration names
/// the first differing field.
#[test]
fn configuration_errors_name_the_field() {
    let dir = temp("errors");
    std::fs::create_dir_all(&dir).unwrap();
    let config = dir.join("bad.toml");
    for (text, field, range) in [
        ("[mdois]\nmax_cycles = 0\n", "mdois.max_cycles", "1..=50"),
        (
            "[mdois]\nkinematics_tolerance = 2\n",
            "mdois.kinematics_tolerance",
            "[0, 0.5]",
        ),
        (
            "[analysis]\nsteps_per_cycle = 3\n",
            "analysis.steps_per_cycle",
            "8..=2000",
        ),
        // One cycle has no cycle before it to be compared with: its
        // periodicity was printed as "+0.00%" (until 2026-12-07).
        ("[analysis]\ncycles = 1\n", "analysis.cycles", "2..=100"),
        // At 0 or 180 deg the wing sweeps in its own plane: the design's
        // 2D run failed as "diverged (non-finite net efficiency)".
        (
            "[kinematics]\nstroke_plane_deg = 0.0\n",
            "kinematics.stroke_plane_deg",
            "(0, 180) deg",
        ),
        (
            "[design]\nstroke_plane_deg = [90.0, 135.0, 180.0]\n",
            "design.stroke_plane_deg",
            "(0, 180) deg",
        ),
        (
            "[topology]\nthreshold = 2.0\n",
            "topology.threshold",
            "[0.01, 0.99]",
        ),
        (
            "[kinematics]\namplitude_deg = 100.0\n",
            "kinematics.amplitude_deg",
            "(0, 80]",
        ),
        ("[mdois]\ntolerance = 1\n", "tolerance", "unknown field"),
        // Nearly hover for this flapping: the section's reduced frequency
        // is past the 2D models' 20 (k = pi f c / U = 24.5 at the top level
        // of 13 Hz). Until 2026-12-07 the design ran its first analysis,
        // and its discipline refused the initial design's LDVM power of
        // -1.56e7 as "the flow does work on the section".
        (
            "[flight]\nspeed_m_s = 0.1\n",
            "design.frequency_hz (highest level) = 13 Hz",
            "past the 2D section models' 20",
        ),
        (
            "[flight]\nspeed_m_s = 0.1\n[kinematics]\nfrequency_hz = 14.0\n",
            "kinematics.frequency_hz = 14 Hz",
            "or flight.speed_m_s to at least",
        ),
    ] {
        std::fs::write(&config, text).unwrap();
        let out_dir = dir.join("never");
        let out = fwav(&[
            "design",
            "--config",
            config.to_str().unwrap(),
            "--out",
            out_dir.to_str().unwrap(),
        ]);
        assert!(!out.status.success(), "{text}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            stderr.contains(field) && stderr.contains(range) && stderr.contains("bad.toml"),
            "{text}: {stderr}"
        );
        assert!(!out_dir.exists(), "{text}");
    }
    // A run directory with nothing computed yet (stage limit 0).
    let run = dir.join("run");
    let empty = start(
        &coarse(),
        &run,
        &RunOptions {
            stage_limit: Some(0),
        },
        &|_| {},
    )
    .unwrap();
    assert_eq!((empty.outcome, empty.stages_computed), (None, 0));
    let mut other = coarse();
    other.topology.mass_fraction = 0.6;
    let e = resume(
        &run,
        Some(&other),
        &RunOptions {
            stage_limit: Some(0),
        },
        &|_| {},
    )
    .unwrap_err();
    let message = e.to_string();
    assert!(
        message.contains("topology.mass_fraction") && message.contains("0.6"),
        "{message}"
    );
    let nothing = resume(&dir.join("nothing"), None, &RunOptions::default(), &|_| {}).unwrap_err();
    assert!(matches!(nothing, DesignError::NoRun { .. }), "{nothing}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A design whose system analysis cannot be trusted stops there, before
/// the disciplines choose on it: the coarse wing at 20 Hz, +-40 deg, whose
/// tip swings farther than its span and whose two cycles disagree (it was
/// judged by the actuator check on that analysis's damping, or, on a
/// larger battery, handed to the disciplines).
#[test]
fn a_system_analysis_beyond_the_wing_stops_the_design() {
    let mut config = coarse();
    config.kinematics.frequency = 20.0;
    config.kinematics.amplitude = 40f64.to_radians();
    let dir = temp("beyond-the-wing");
    let error = start(&config, &dir, &RunOptions::default(), &|_| {}).unwrap_err();
    let text = error.to_string();
    assert!(
        matches!(error, DesignError::Doubtful { cycle: 1, .. }),
        "{text}"
    );
    assert!(
        text.contains("cycle 1, system analysis: the result is not periodic")
            && text.contains("the design stops rather than choose on this analysis"),
        "{text}"
    );
    assert!(!dir.join("cycle-1/kinematics.json").exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// A resumed design asks its reused system analyses what it asks a new
/// one: a `system.json` that holds a doubt (one written before the doubts
/// were asked, 2026-12-07; made here by scaling a coarse run's tip
/// deflection past the span) stops the resume before the disciplines,
/// where it used to hand that analysis to them.
#[test]
fn a_resumed_design_stops_at_a_reused_analysis_it_cannot_trust() {
    let dir = temp("resumed-doubt");
    let one = RunOptions {
        stage_limit: Some(1),
    };
    let first = start(&coarse(), &dir, &one, &|_| {}).unwrap();
    assert_eq!((first.outcome, first.stages_computed), (None, 1));
    let path = dir.join("cycle-1/system.json");
    let mut record = json(&path);
    for step in record["steps"].as_array_mut().unwrap() {
        let z = &mut step["tip_displacement_m"][2];
        *z = serde_json::json!(z.as_f64().unwrap() * 1e4);
    }
    std::fs::write(&path, serde_json::to_string(&record).unwrap()).unwrap();
    let error = resume(&dir, None, &one, &|_| {}).unwrap_err();
    let text = error.to_string();
    assert!(
        matches!(
            error,
            DesignError::DoubtfulRecord {
                cycle: 1,
                doubt: Doubt::TipBeyondSpan { .. }
            }
        ),
        "{text}"
    );
    assert!(
        text.contains("farther than a wing that does not stretch")
            && text.contains("(cycle-1/system.json, reused on this resume)")
            && text.contains("start the design again in a new --out directory"),
        "{text}"
    );
    assert!(!dir.join("cycle-1/kinematics.json").exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// A design whose vehicle the flight controller cannot be set to stops
/// after the first system analysis (the model takes that analysis's
/// damping), naming the parameter and the design's keys: a rotor of 3e-5
/// kg m^2 through the gear of 20 reflects 0.012 kg m^2 to the flapping
/// axis, past the device's 0.01. Before, such a design ran to its end and
/// wrote a `plant.toml` that hil-sim refuses.
#[test]
fn a_vehicle_the_controller_cannot_model_stops_the_design() {
    let mut config = coarse();
    config.actuator.rotor_inertia_kg_m2 = 3e-5;
    let dir = temp("beyond-device");
    let error = start(&config, &dir, &RunOptions::default(), &|_| {}).unwrap_err();
    let text = error.to_string();
    assert!(
        matches!(error, DesignError::BeyondDevice { cycle: 1, .. }),
        "{text}"
    );
    assert!(
        text.contains("the flight controller's wing_inertia = 0.0120674 kg m^2")
            && text.contains("outside the device's 1e-9..=0.01 kg m^2")
            && text.contains("rotor_inertia_kg_m2, gear_ratio"),
        "{text}"
    );
    // Said once: the plant file's wording (its keys) is not a cause the
    // program prints after it (it was, as the field was called `source`).
    assert!(std::error::Error::source(&error).is_none(), "{text}");
    assert!(!dir.join("cycle-1/kinematics.json").exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// A design whose initial kinematics the actuator cannot fly stops after
/// the first system analysis (whose damping the discipline would judge
/// on) and before the disciplines, naming the limiting quantity and its
/// margin and the levers: the coarse design on a 1 V battery, where the
/// bridge cannot reach the terminal voltage the stroke needs.
#[test]
fn an_initial_design_the_actuator_cannot_fly_stops_before_the_disciplines() {
    let mut config = coarse();
    config.actuator.battery_v = 1.0;
    let dir = temp("tiny-battery");
    let error = start(&config, &dir, &RunOptions::default(), &|_| {}).unwrap_err();
    let text = error.to_string();
    println!("{text}");
    match &error {
        DesignError::InitialInfeasible {
            limiting,
            margin_percent,
            ..
        } => {
            assert!(limiting.starts_with("terminal voltage"), "{limiting}");
            assert!(*margin_percent < 10.0, "{margin_percent}");
        }
        other => panic!("{other}"),
    }
    for lever in ["gear_ratio", "spring", "battery_v"] {
        assert!(text.contains(lever), "{lever}: {text}");
    }
    assert!(dir.join("cycle-1/system.json").exists());
    assert!(!dir.join("cycle-1/kinematics.json").exists());
    assert!(!dir.join("cycle-1/topology.json").exists());
    std::fs::remove_dir_all(&dir).ok();
}
