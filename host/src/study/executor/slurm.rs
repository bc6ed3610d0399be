//! The Slurm executor: the cases go to the cluster as one job array —
//! a batch script (`slurm/array-S.sh`, S the submission) whose task `N`
//! runs case `N`'s design run, submitted with `sbatch --parsable` — and
//! are followed with `squeue` (every task's state, finished ones too while
//! Slurm keeps them, `MinJobAge`) and `sacct` where accounting is on,
//! until no task is pending or running. Nothing of a case runs on the
//! submitting host.
//!
//! Slurm's word is not the last: a case is finished when its own run
//! directory says so ([`crate::study::state::progress`]), and a task
//! Slurm no longer knows is settled from those files. A task that ended
//! otherwise (cancelled, timed out, out of memory, failed) leaves its
//! case failed with the reason, and `fwav study resume` submits it again;
//! its run goes on from its last finished stage.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use crate::files::write_atomic;
use crate::study::cases::width;
use crate::study::directory::StudyDir;
use crate::study::error::StudyError;
use crate::study::file::SlurmSettings;
use crate::study::state::{now_unix_s, progress, CaseProgress, CaseStatus, ExecutorKind};

use super::{error_in_log, Launch, Observer};

/// CPUs a task asks for unless told: the design's two disciplines run
/// side by side.
pub const DEFAULT_CPUS: u32 = 2;

/// Seconds between two looks at the queue unless told.
pub const DEFAULT_POLL_S: f64 = 10.0;

/// Failed `squeue` calls in a row before the follower gives up (the
/// controller can be briefly unreachable).
const QUEUE_TRIES: usize = 10;

/// How the job array is asked for and followed.
#[derive(Clone, Debug, PartialEq)]
pub struct SlurmOptions {
    /// The `#SBATCH` settings (the study file's, overridden by flags).
    pub settings: SlurmSettings,
}

impl SlurmOptions {
    /// The time between two looks at the queue.
    pub fn poll(&self) -> Duration {
        Duration::from_secs_f64(self.settings.poll_s.unwrap_or(DEFAULT_POLL_S))
    }
}

/// A task's state as Slurm names it, and what that means for its case.
fn case_status(state: &str) -> Option<CaseStatus> {
    match state {
        "PENDING" | "CONFIGURING" | "REQUEUED" | "REQUEUE_HOLD" | "REQUEUE_FED"
        | "RESV_DEL_HOLD" => Some(CaseStatus::Queued),
        "RUNNING" | "COMPLETING" | "STAGE_OUT" | "SIGNALING" | "RESIZING" | "SUSPENDED" => {
            Some(CaseStatus::Running)
        }
        // Ended: the case's files decide.
        _ => None,
    }
}

/// `'text'` for bash.
fn quoted(text: &str) -> String {
    format!("'{}'", text.replace('\'', r"'\''"))
}

/// A path the script and `#SBATCH` lines can hold.
fn plain(path: &Path) -> Result<String, StudyError> {
    let text = path.display().to_string();
    if text
        .chars()
        .any(|c| c.is_whitespace() || c == '\'' || c == '"')
    {
        return Err(StudyError::SlurmPath {
            path: path.to_path_buf(),
        });
    }
    Ok(text)
}

/// The array's index list, `1,3,4` (with `%N` to cap the tasks at once).
fn array_spec(cases: &[usize], max_parallel: Option<usize>) -> String {
    let list: Vec<String> = cases.iter().map(ToString::to_string).collect();
    match max_parallel {
        Some(n) => format!("{}%{n}", list.join(",")),
        None => list.join(","),
    }
}

/// The batch script of a submission: `#SBATCH` lines, then the design
/// run of the task's case.
pub fn batch_script(
    name: &str,
    dir: &Path,
    cases: &[usize],
    total: usize,
    launch: &Launch,
    s: &SlurmSettings,
) -> Result<String, StudyError> {
    let dir_text = plain(dir)?;
    let program = plain(&launch.program)?;
    let w = width(total);
    let job_name: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_.".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect();
    let mut lines = vec![
        "#!/bin/bash".to_string(),
        format!("# fwav study {name:?}: one array task a case; task N runs case N's design run,"),
        "# resumable (a task stopped anywhere goes on from the case's state.json).".into(),
        format!("#SBATCH --job-name=fwav-{job_name}"),
        format!("#SBATCH --array={}", array_spec(cases, s.max_parallel)),
        format!("#SBATCH --output={dir_text}/logs/%{w}a-slurm-%A.out"),
        format!(
            "#SBATCH --cpus-per-task={}",
            s.cpus_per_task.unwrap_or(DEFAULT_CPUS)
        ),
    ];
    if let Some(p) = &s.partition {
        lines.push(format!("#SBATCH --partition={p}"));
    }
    if let Some(t) = &s.time {
        lines.push(format!("#SBATCH --time={t}"));
    }
    if let Some(m) = &s.mem {
        lines.push(format!("#SBATCH --mem={m}"));
    }
    for o in &s.options {
        lines.push(format!("#SBATCH {o}"));
    }
    let yes = if launch.yes { " --yes" } else { "" };
    lines.extend([
        String::new(),
        format!("case=$(printf '%0{w}d' \"$SLURM_ARRAY_TASK_ID\")"),
        "export RAYON_NUM_THREADS=\"${SLURM_CPUS_PER_TASK:-1}\"".into(),
        format!(
            "exec {} design --quiet{yes} --config {}/cases/\"$case\"/config.toml --out {}/cases/\"$case\"",
            quoted(&program),
            quoted(&dir_text),
            quoted(&dir_text)
        ),
        String::new(),
    ]);
    Ok(lines.join("\n"))
}

/// Runs `command` with `args`, returning (success, stdout, stderr).
fn call(command: &str, args: &[&str]) -> Result<(bool, String, String), StudyError> {
    let out = Command::new(command)
        .args(args)
        .output()
        .map_err(|source| StudyError::Spawn {
            command: command.to_string(),
            source,
        })?;
    Ok((
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).trim().to_string(),
    ))
}

/// Submits `script`; returns the job id.
fn submit(script: &Path) -> Result<String, StudyError> {
    let path = script.display().to_string();
    let out = Command::new("sbatch")
        .args(["--parsable", &path])
        .output()
        .map_err(|source| StudyError::Spawn {
            command: "sbatch".into(),
            source,
        })?;
    if !out.status.success() {
        return Err(StudyError::Submit {
            status: out.status.to_string(),
            stderr: String::from_utf8_lossy(&out.stderr).trim().to_string(),
            script: script.to_path_buf(),
        });
    }
    // `--parsable` prints `jobid` or `jobid;cluster`.
    let answer = String::from_utf8_lossy(&out.stdout).trim().to_string();
    let id = answer.split(';').next().unwrap_or("").to_string();
    if id.is_empty() || !id.chars().all(|c| c.is_ascii_digit()) {
        return Err(StudyError::JobId { answer });
    }
    Ok(id)
}

/// Each task's state as `squeue` lists it (ended tasks too, while Slurm
/// keeps them); `None`: Slurm no longer knows the job.
pub fn queue_states(job: &str) -> Result<Option<BTreeMap<usize, String>>, String> {
    let args = [
        "--noheader",
        "--array",
        "--states=all",
        "--jobs",
        job,
        "--format=%K|%T",
    ];
    let (ok, stdout, stderr) = call("squeue", &args).map_err(|e| e.to_string())?;
    if !ok {
        return if stderr.contains("Invalid job id") {
            Ok(None)
        } else {
            Err(stderr)
        };
    }
    let states: BTreeMap<usize, String> = stdout
        .lines()
        .filter_map(|l| {
            let (task, state) = l.trim().split_once('|')?;
            Some((task.parse().ok()?, state.to_string()))
        })
        .collect();
    Ok((!states.is_empty()).then_some(states))
}

/// Each task's final state as `sacct` records it, if accounting is on.
fn accounted_states(job: &str) -> BTreeMap<usize, String> {
    let args = [
        "--noheader",
        "--parsable2",
        "--jobs",
        job,
        "--format=JobID,State",
    ];
    let Ok((true, stdout, _)) = call("sacct", &args) else {
        return BTreeMap::new();
    };
    stdout
        .lines()
        .filter_map(|l| {
            let (id, state) = l.split_once('|')?;
            let (j, task) = id.split_once('_')?;
            if j != job || task.contains('.') {
                return None;
            }
            let state = state.split_whitespace().next()?;
            Some((task.parse().ok()?, state.to_string()))
        })
        .collect()
}

/// The cases of `job` that Slurm still holds pending or running.
pub fn active_cases(job: &str) -> Result<Vec<usize>, StudyError> {
    match queue_states(job) {
        Ok(None) => Ok(Vec::new()),
        Ok(Some(states)) => Ok(states
            .into_iter()
            .filter(|(_, s)| case_status(s).is_some())
            .map(|(task, _)| task)
            .collect()),
        Err(stderr) => Err(StudyError::Queue {
            job: job.to_string(),
            tries: 1,
            stderr,
        }),
    }
}

/// Submits `cases` of `study` as one job array and follows it until no
/// task is pending or running; `study.json` is kept up to date.
pub fn run(
    study: &mut StudyDir,
    cases: &[usize],
    launch: &Launch,
    options: &SlurmOptions,
    observe: Observer<'_>,
) -> Result<(), StudyError> {
    let dir = std::fs::canonicalize(study.path()).map_err(StudyError::io(study.path()))?;
    let total = study.state.cases.len();
    let script_text = batch_script(
        &study.state.name,
        &dir,
        cases,
        total,
        launch,
        &options.settings,
    )?;
    study.subdirectory("logs")?;
    let scripts = study.subdirectory("slurm")?;
    let submission = study.state.begin_submission(ExecutorKind::Slurm, cases);
    let script = write_atomic(&scripts, &format!("array-{submission}.sh"), script_text)?;
    let job = match submit(&script) {
        Ok(job) => job,
        Err(e) => {
            study.state.submissions.pop();
            return Err(e);
        }
    };
    if let Some(s) = study.state.submission_mut(submission) {
        s.job_id = Some(job.clone());
        s.script = Some(format!("slurm/array-{submission}.sh"));
    }
    let w = width(total);
    for &case in cases {
        if let Some(r) = study.state.case_mut(case) {
            r.status = CaseStatus::Queued;
            r.error = None;
            r.submission = Some(submission);
            r.slurm_task = Some(format!("{job}_{case}"));
            r.slurm_state = Some("PENDING".into());
            r.log = Some(format!("logs/{case:0w$}-slurm-{job}.out"));
        }
    }
    study.save()?;
    observe(&study.state);
    follow(study, submission, &job, options.poll(), observe)
}

/// Follows `job` (submission `submission`) until no task is pending or
/// running, then settles its cases.
pub fn follow(
    study: &mut StudyDir,
    submission: usize,
    job: &str,
    poll: Duration,
    observe: Observer<'_>,
) -> Result<(), StudyError> {
    let cases: Vec<usize> = study
        .state
        .submissions
        .iter()
        .find(|s| s.number == submission)
        .map(|s| s.cases.clone())
        .unwrap_or_default();
    let mut failures = 0;
    let mut last: BTreeMap<usize, String> = BTreeMap::new();
    loop {
        let started = Instant::now();
        let states = match queue_states(job) {
            Ok(Some(states)) => states,
            Ok(None) => break,
            Err(stderr) => {
                failures += 1;
                if failures >= QUEUE_TRIES {
                    return Err(StudyError::Queue {
                        job: job.to_string(),
                        tries: failures,
                        stderr,
                    });
                }
                std::thread::sleep(poll);
                continue;
            }
        };
        failures = 0;
        let mut changed = false;
        for &case in &cases {
            let Some(state) = states.get(&case) else {
                continue;
            };
            last.insert(case, state.clone());
            changed |= note(study, case, state);
        }
        if changed {
            study.save()?;
            observe(&study.state);
        }
        let active = cases
            .iter()
            .any(|c| last.get(c).is_none_or(|s| case_status(s).is_some()));
        if !active {
            break;
        }
        std::thread::sleep(poll.saturating_sub(started.elapsed()));
    }
    // Tasks squeue no longer lists: sacct's record, if accounting is on.
    for (task, state) in accounted_states(job) {
        if cases.contains(&task) && last.get(&task).is_none_or(|s| case_status(s).is_some()) {
            last.insert(task, state);
        }
    }
    for &case in &cases {
        settle(study, case, last.get(&case).map(String::as_str));
    }
    if let Some(s) = study.state.submission_mut(submission) {
        s.ended_unix_s = Some(now_unix_s());
    }
    study.save()?;
    observe(&study.state);
    Ok(())
}

/// Notes a task's current state in its case; returns whether the case
/// changed.
fn note(study: &mut StudyDir, case: usize, state: &str) -> bool {
    let Some(record) = study.state.case(case).cloned() else {
        return false;
    };
    let stages = match progress(&study.case_dir(&record)) {
        CaseProgress::Finished { stages } | CaseProgress::Unfinished { stages } => stages,
        _ => 0,
    };
    let status = case_status(state).unwrap_or(record.status);
    let Some(c) = study.state.case_mut(case) else {
        return false;
    };
    let before = (c.status, c.stages_done, c.slurm_state.clone());
    c.status = status;
    c.stages_done = stages;
    c.slurm_state = Some(state.to_string());
    before != (c.status, c.stages_done, c.slurm_state.clone())
}

/// Why a task that ended left its case unfinished.
fn failure(state: Option<&str>, log: Option<String>) -> String {
    let said = log
        .map(|e| format!("; its last error: {e}"))
        .unwrap_or_default();
    match state {
        Some("CANCELLED") => format!("cancelled in Slurm (CANCELLED){said}"),
        Some("TIMEOUT") => {
            format!("reached its Slurm time limit (TIMEOUT; raise [slurm] time){said}")
        }
        Some("OUT_OF_MEMORY") => {
            format!("ran out of memory in Slurm (OUT_OF_MEMORY; raise [slurm] mem){said}")
        }
        Some("PREEMPTED") => format!("preempted by Slurm (PREEMPTED){said}"),
        Some("NODE_FAIL") => format!("its node failed (NODE_FAIL){said}"),
        Some("COMPLETED") => format!("its task completed but its design run is unfinished{said}"),
        Some(other) => format!("ended in Slurm as {other}{said}"),
        None => format!(
            "its task ended (Slurm no longer lists it) with its design run unfinished{said}"
        ),
    }
}

/// Settles a case whose task ended as `state` (`None`: unknown): its
/// files decide whether it finished.
fn settle(study: &mut StudyDir, case: usize, state: Option<&str>) {
    let Some(record) = study.state.case(case).cloned() else {
        return;
    };
    let outcome = progress(&study.case_dir(&record));
    let log: Option<PathBuf> = record.log.as_ref().map(|l| study.path().join(l));
    let said = log.as_deref().and_then(error_in_log);
    let Some(c) = study.state.case_mut(case) else {
        return;
    };
    if let Some(s) = state {
        c.slurm_state = Some(s.to_string());
    }
    c.settle(outcome, || match (state, said) {
        (Some("FAILED"), Some(e)) => e,
        (state, said) => failure(state, said),
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The batch script asks for the array of the cases with the
    /// settings given and runs the task's case's design run.
    #[test]
    fn batch_script_runs_the_tasks_case() {
        let launch = Launch {
            program: PathBuf::from("/opt/fwav/bin/fwav"),
            yes: true,
        };
        let settings = SlurmSettings {
            partition: Some("compute".into()),
            time: Some("2:00:00".into()),
            cpus_per_task: Some(4),
            mem: Some("8G".into()),
            max_parallel: Some(3),
            options: vec!["--account=wings".into()],
            poll_s: None,
        };
        let s = batch_script(
            "span speed",
            Path::new("/scratch/s"),
            &[2, 5, 7],
            9,
            &launch,
            &settings,
        )
        .unwrap();
        for line in [
            "#SBATCH --job-name=fwav-span_speed",
            "#SBATCH --array=2,5,7%3",
            "#SBATCH --output=/scratch/s/logs/%3a-slurm-%A.out",
            "#SBATCH --cpus-per-task=4",
            "#SBATCH --partition=compute",
            "#SBATCH --time=2:00:00",
            "#SBATCH --mem=8G",
            "#SBATCH --account=wings",
            "case=$(printf '%03d' \"$SLURM_ARRAY_TASK_ID\")",
            "exec '/opt/fwav/bin/fwav' design --quiet --yes --config '/scratch/s'/cases/\"$case\"/config.toml --out '/scratch/s'/cases/\"$case\"",
        ] {
            assert!(s.lines().any(|l| l == line), "{line}\n{s}");
        }
        // Every #SBATCH line comes before the first command.
        let first_command = s
            .lines()
            .position(|l| !l.is_empty() && !l.starts_with('#'))
            .unwrap();
        assert!(s
            .lines()
            .skip(first_command)
            .all(|l| !l.starts_with("#SBATCH")));
        let e = batch_script("s", Path::new("/a b"), &[1], 1, &launch, &settings).unwrap_err();
        assert!(e.to_string().contains("without white space"), "{e}");
    }
}
