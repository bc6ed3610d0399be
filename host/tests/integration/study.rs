//! `fwav study` end to end, as real processes: a small study of the
//! coarse design (3 cases) on the local pool, then the same study as one
//! job array of a real single-node Slurm cluster started here
//! (`study/cluster.rs`), one of its array tasks cancelled mid-run with
//! `scancel` and the study resumed — its `results.csv` must equal the
//! local one; and studies with a bad key refused before anything is
//! written or submitted, naming the case and the key.
//!
//! The cases are the coarse design (`configs/coarse.toml`) made smaller
//! so that the test stays within CI's budget, but still whole design
//! runs: one MDOIS cycle (`mdois.max_cycles = 1`: the system analysis,
//! both disciplines, the analysis of their proposal), one ESLSO cycle of
//! 15 SIMP iterations, attached flow in the section analyses
//! (`design.lesp_critical = 0`, which halves the aerodynamic
//! discipline's time). About 12 s of CPU a case in the test profile.
//!
//! Three cases, not more: one more than the local pool's 2 jobs and,
//! on CI's 2 cores, than the tasks the test cluster runs at once, so the
//! pool queues a case and an array task waits pending, as with the
//! former 2 x 2 grid, at three quarters of its cost.

mod cluster;

use std::path::{Path, PathBuf};
use std::process::{Output, Stdio};
use std::time::{Duration, Instant};

use fwav::mdois::state::{RunState, Stage};

use cluster::Cluster;

use crate::program::fwav_command;

/// The coarse design of the tests and the README.
const COARSE: &str = include_str!("../../../configs/coarse.toml");

/// The study: semi-span by flight speed, 3 x 1 (two varied keys, each a
/// column of `results.csv` and a plot).
const STUDY: &str = "[study]\nname = \"span-speed\"\nbase = \"small.toml\"\n\
    outputs = [\"ct\", \"efficiency\"]\n\
    [grid]\nwing.semi_span_m = [0.14, 0.15, 0.16]\nflight.speed_m_s = [3.0]\n";

fn temp(name: &str) -> PathBuf {
    crate::program::scratch(&format!("study-{name}"))
}

/// The small variant of the coarse design (module docs).
fn small() -> String {
    let mut t: toml::Table = toml::from_str(COARSE).unwrap();
    let mut set = |table: &str, key: &str, value: toml::Value| {
        t.entry(table)
            .or_insert_with(|| toml::Value::Table(toml::Table::new()))
            .as_table_mut()
            .unwrap()
            .insert(key.to_string(), value);
    };
    set("mdois", "max_cycles", toml::Value::Integer(1));
    set("topology", "max_cycles", toml::Value::Integer(1));
    set("topology", "simp_iterations", toml::Value::Integer(15));
    set("design", "lesp_critical", toml::Value::Float(0.0));
    toml::to_string(&t).unwrap()
}

/// A directory with the small base and the study file(s).
fn study_files(name: &str, studies: &[(&str, &str)]) -> PathBuf {
    let dir = temp(name);
    std::fs::write(dir.join("small.toml"), small()).unwrap();
    for (file, text) in studies {
        std::fs::write(dir.join(file), text).unwrap();
    }
    dir
}

fn fwav(args: &[&str], conf: Option<&Path>) -> Output {
    let mut c = fwav_command(args);
    if let Some(conf) = conf {
        c.env("SLURM_CONF", conf);
    }
    c.output().expect("the fwav program runs")
}

fn text(out: &Output) -> String {
    format!(
        "status {}\nstdout:\n{}\nstderr:\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// `results.csv` as rows of cells, the `seconds` column (wall times)
/// left out.
fn results(dir: &Path) -> Vec<Vec<String>> {
    let mut reader = csv::Reader::from_path(dir.join("results.csv")).unwrap();
    let header: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    let seconds = header.iter().position(|h| h == "seconds").unwrap();
    let mut rows = vec![header];
    for record in reader.records() {
        rows.push(record.unwrap().iter().map(String::from).collect());
    }
    for row in &mut rows {
        row.remove(seconds);
    }
    rows
}

/// A study whose cases have a bad key or value fails before anything is
/// written (no directory is made), naming the case and the key; so does
/// one with a case far beyond the built-in design's cost, without
/// `--yes`.
#[test]
fn bad_keys_are_refused_before_anything_is_written() {
    let dir = study_files(
        "bad",
        &[
            (
                "range.toml",
                "[study]\nbase = \"small.toml\"\n[grid]\nwing.semi_span_m = [0.14, 5.0]\n\
                 flight.speed_m_s = [2.5, 3.0]\n",
            ),
            (
                "unknown.toml",
                "[[case]]\nwing.semi_span_m = 0.14\n[[case]]\nflight.speed = 3.0\n",
            ),
            ("cross.toml", "[[case]]\ntopology.sample_every = 400\n"),
            (
                "costly.toml",
                "[[case]]\nwing.semi_span_m = 0.15\n[[case]]\nwing.span_elements = 400\n\
                 wing.chord_elements = 100\n",
            ),
        ],
    );
    let out_dir = dir.join("out");
    let run = |file: &str| {
        let out = fwav(
            &[
                "study",
                "run",
                dir.join(file).to_str().unwrap(),
                "--out",
                out_dir.to_str().unwrap(),
            ],
            None,
        );
        assert_eq!(out.status.code(), Some(1), "{}", text(&out));
        assert!(!out_dir.exists(), "{file}: the study directory was made");
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    let e = run("range.toml");
    assert!(
        e.contains("2 of 4 cases refused; nothing was written or submitted")
            && e.contains(
                "case 003 (wing.semi_span_m = 5.0, flight.speed_m_s = 2.5): \
                 wing.semi_span_m = 5 is outside [0.01, 2] m"
            )
            && e.contains("case 004 (wing.semi_span_m = 5.0, flight.speed_m_s = 3.0)"),
        "{e}"
    );
    let e = run("unknown.toml");
    assert!(
        e.contains("case 002: `flight.speed` is not a key of the design file: did you mean `flight.speed_m_s`?"),
        "{e}"
    );
    let e = run("cross.toml");
    assert!(
        e.contains("case 001 (topology.sample_every = 400): topology.sample_every = 400 is more than analysis.steps_per_cycle"),
        "{e}"
    );
    // A case far beyond the built-in design's cost needs --yes, as `fwav
    // design` does.
    let e = run("costly.toml");
    assert!(
        e.contains(
            "1 case(s) far beyond the built-in design's cost, case 002 the largest: it needs about"
        ) && e.contains("40000 shell elements")
            && e.contains("Pass --yes"),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Waits until `ready` or fails after `limit`.
fn wait_until(what: &str, limit: Duration, mut ready: impl FnMut() -> bool) {
    let clock = Instant::now();
    while !ready() {
        assert!(clock.elapsed() < limit, "{what}: not within {limit:?}");
        std::thread::sleep(Duration::from_millis(200));
    }
}

/// The driver invocation that computed `stage` of `cycle` of a run.
fn run_of(dir: &Path, cycle: usize, stage: Stage) -> Option<usize> {
    RunState::load(dir).ok()?.stage(cycle, stage).map(|r| r.run)
}

/// The local study: 3 finished cases, 2 at a time, with `results.csv`,
/// a plot a varied key and `report.md`; run again, it has nothing to do.
fn local_study(dir: &Path) -> PathBuf {
    let out = dir.join("local");
    let study = dir.join("study.toml");
    let args = [
        "study",
        "run",
        study.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--jobs",
        "2",
    ];
    let clock = Instant::now();
    let run = fwav(&args, None);
    assert!(run.status.success(), "{}", text(&run));
    println!("local study: {:.1} s", clock.elapsed().as_secs_f64());
    let rows = results(&out);
    assert_eq!(rows.len(), 4, "{rows:?}");
    assert_eq!(
        rows[0][..4],
        ["case", "status", "wing.semi_span_m", "flight.speed_m_s"]
    );
    let ct = rows[0].iter().position(|h| h == "ct").unwrap();
    for (row, (span, speed)) in
        rows[1..]
            .iter()
            .zip([("0.14", "3.0"), ("0.15", "3.0"), ("0.16", "3.0")])
    {
        assert_eq!(row[1..4], ["finished", span, speed], "{row:?}");
        assert!(row[ct].parse::<f64>().unwrap() > 0.0, "{row:?}");
    }
    // Each case is an ordinary design run with the study's values.
    let config = std::fs::read_to_string(out.join("cases/003/config.toml")).unwrap();
    let config = fwav::config::SystemConfig::from_toml(&config).unwrap();
    assert_eq!(
        (config.wing.semi_span_m, config.flight.speed_m_s),
        (0.16, 3.0)
    );
    assert_eq!(
        json(&out.join("cases/003/summary.json"))["outcome"],
        "cycle cap reached"
    );
    for file in [
        "report.md",
        "plots/wing.semi_span_m.png",
        "plots/flight.speed_m_s.png",
    ] {
        assert!(out.join(file).is_file(), "{file}");
    }
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("**3 finished**, 0 failed"), "{report}");
    let again = fwav(&args, None);
    assert!(again.status.success(), "{}", text(&again));
    assert!(
        String::from_utf8_lossy(&again.stderr).contains("nothing to run"),
        "{}",
        text(&again)
    );
    out
}

/// The same study as a Slurm job array: case 2's task is cancelled
/// (`scancel`) once its run has finished its first stage; the follower
/// ends with that case failed, `fwav study resume` submits it alone, and
/// the case goes on from its own `state.json` (its first stage is not
/// redone). The resume's follower is killed after submitting: a resume
/// meanwhile is refused naming the job, and one after the job has ended
/// settles the study from the case's files. Returns the study's
/// directory.
fn slurm_study(dir: &Path, cluster: &Cluster) -> PathBuf {
    let out = dir.join("slurm");
    let conf = cluster.conf();
    let clock = Instant::now();
    let follower = fwav_command(&["study", "run"])
        .arg(dir.join("study.toml"))
        .arg("--out")
        .arg(&out)
        .args(["--executor", "slurm", "--cpus-per-task", "1", "--poll", "1"])
        .env("SLURM_CONF", conf)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let case2 = out.join("cases/002");
    wait_until("case 002's first stage", Duration::from_secs(120), || {
        RunState::load(&case2).is_ok_and(|s| s.stage(1, Stage::System).is_some())
    });
    let state = json(&out.join("study.json"));
    let job = state["submissions"][0]["job_id"]
        .as_str()
        .unwrap()
        .to_string();
    let cancelled = cluster
        .command("scancel")
        .arg(format!("{job}_2"))
        .status()
        .unwrap();
    assert!(cancelled.success());
    // While the follower runs, the study is its own: a resume is refused
    // (its lock), the status is read.
    let busy = fwav(&["study", "resume", out.to_str().unwrap()], Some(conf));
    assert_eq!(busy.status.code(), Some(1), "{}", text(&busy));
    assert!(
        String::from_utf8_lossy(&busy.stderr).contains("is in use"),
        "{}",
        text(&busy)
    );
    let running = fwav(&["study", "status", out.to_str().unwrap()], Some(conf));
    assert!(running.status.success(), "{}", text(&running));
    let ended = follower.wait_with_output().unwrap();
    println!(
        "slurm study until the cancelled case: {:.1} s",
        clock.elapsed().as_secs_f64()
    );
    assert_eq!(ended.status.code(), Some(1), "{}", text(&ended));
    let stderr = String::from_utf8_lossy(&ended.stderr);
    assert!(
        stderr.contains("1 of 3 cases failed (case 002)"),
        "{stderr}"
    );
    assert!(
        RunState::load(&case2).unwrap().outcome.is_none(),
        "case 002 finished anyway"
    );
    let state = json(&out.join("study.json"));
    let cases = state["cases"].as_array().unwrap();
    for (i, c) in cases.iter().enumerate() {
        let (status, slurm) = if i == 1 {
            ("failed", "CANCELLED")
        } else {
            ("finished", "COMPLETED")
        };
        assert_eq!(
            (c["status"].as_str(), c["slurm_state"].as_str()),
            (Some(status), Some(slurm)),
            "{c}"
        );
        assert_eq!(c["slurm_task"], format!("{job}_{}", i + 1));
    }
    assert!(
        cases[1]["error"]
            .as_str()
            .unwrap()
            .contains("cancelled in Slurm"),
        "{}",
        cases[1]
    );
    // Slurm ran the cases: its logs, none of the local executor's.
    let logs: Vec<String> = std::fs::read_dir(out.join("logs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(logs.iter().all(|l| l.contains("-slurm-")), "{logs:?}");
    let status = fwav(&["study", "status", out.to_str().unwrap()], Some(conf));
    let listing = String::from_utf8_lossy(&status.stdout);
    assert!(
        listing.contains("3 cases, 2 finished, 1 failed")
            && listing.lines().any(|l| l.starts_with("002")
                && l.contains("failed")
                && l.contains("cancelled in Slurm")),
        "{listing}"
    );

    // The resume's follower is killed once it has submitted: its job
    // runs on, a second resume is refused while the job holds the case,
    // and once the job has ended a resume settles the study from the
    // case's files alone.
    let mut follower = fwav_command(&["study", "resume"])
        .arg(&out)
        .args(["--poll", "1"])
        .env("SLURM_CONF", conf)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    wait_until("the resume's submission", Duration::from_secs(60), || {
        std::fs::read_to_string(out.join("study.json"))
            .ok()
            .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
            .is_some_and(|s| s["submissions"][1]["job_id"].is_string())
    });
    follower.kill().unwrap();
    follower.wait().unwrap();
    let state = json(&out.join("study.json"));
    let second = &state["submissions"][1];
    assert_eq!(second["executor"], "slurm");
    assert_eq!(second["cases"], serde_json::json!([2]));
    let job2 = second["job_id"].as_str().unwrap().to_string();
    assert_ne!(job2, job);
    let refused = fwav(&["study", "resume", out.to_str().unwrap()], Some(conf));
    assert_eq!(refused.status.code(), Some(1), "{}", text(&refused));
    let refusal = String::from_utf8_lossy(&refused.stderr);
    assert!(
        refusal.contains(&format!(
            "Slurm job {job2} still holds case(s) 2 (pending or running)"
        )),
        "{refusal}"
    );
    wait_until("the resumed case's task", Duration::from_secs(180), || {
        let active = cluster
            .command("squeue")
            .args([
                "--noheader",
                "--jobs",
                &job2,
                "--states=PENDING,RUNNING,COMPLETING",
            ])
            .output()
            .unwrap();
        active.status.success() && active.stdout.is_empty()
    });
    let settled = fwav(&["study", "resume", out.to_str().unwrap()], Some(conf));
    assert!(settled.status.success(), "{}", text(&settled));
    assert!(
        String::from_utf8_lossy(&settled.stderr).contains("nothing to run"),
        "{}",
        text(&settled)
    );
    println!(
        "slurm study with its resume: {:.1} s",
        clock.elapsed().as_secs_f64()
    );
    let state = json(&out.join("study.json"));
    assert_eq!(state["submissions"].as_array().unwrap().len(), 2);
    assert_eq!(state["cases"][1]["status"], "finished");
    // The resumed case kept the stage it had finished before the cancel.
    assert_eq!(run_of(&case2, 1, Stage::System), Some(1));
    assert_eq!(run_of(&case2, 2, Stage::System), Some(2));
    out
}

/// The study on the local pool, then on a real single-node Slurm
/// cluster with a cancelled task resumed: the same `results.csv` (every
/// column but the wall times, to the last digit). Without Slurm (not
/// installable or not startable here) the Slurm part is skipped, saying
/// why.
#[test]
fn slurm_study_equals_the_local_one_after_a_cancelled_task_is_resumed() {
    let clock = Instant::now();
    let dir = study_files("runs", &[("study.toml", STUDY)]);
    let local = local_study(&dir);
    let cluster = match Cluster::start() {
        Ok(cluster) => cluster,
        Err(why) => {
            eprintln!("SKIPPED the Slurm part of this test: {why}");
            std::fs::remove_dir_all(&dir).ok();
            return;
        }
    };
    // A bad case is refused before anything is submitted: the fresh
    // controller holds no job at all afterwards.
    std::fs::write(
        dir.join("bad.toml"),
        STUDY.replace("[0.14, 0.15, 0.16]", "[0.14, 0.15, 0.16, -1.0]"),
    )
    .unwrap();
    let bad_out = dir.join("bad");
    let bad = fwav(
        &[
            "study",
            "run",
            dir.join("bad.toml").to_str().unwrap(),
            "--out",
            bad_out.to_str().unwrap(),
            "--executor",
            "slurm",
        ],
        Some(cluster.conf()),
    );
    assert_eq!(bad.status.code(), Some(1), "{}", text(&bad));
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert!(
        stderr.contains("case 004 (wing.semi_span_m = -1.0, flight.speed_m_s = 3.0): wing.semi_span_m = -1 is outside"),
        "{stderr}"
    );
    assert!(!bad_out.exists());
    assert_eq!(cluster.jobs(), Vec::<String>::new());

    let slurm = slurm_study(&dir, &cluster);
    drop(cluster);
    assert_eq!(results(&slurm), results(&local));
    assert!(slurm.join("plots/wing.semi_span_m.png").is_file());
    std::fs::remove_dir_all(&dir).ok();
    println!("whole test: {:.1} s", clock.elapsed().as_secs_f64());
}
