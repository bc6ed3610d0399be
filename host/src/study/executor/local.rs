//! The local executor: the cases' design runs as child processes of this
//! one, `jobs` at a time, each with its share of the cores (its
//! `RAYON_NUM_THREADS`, unless set already), its standard output and
//! error in `logs/NNN-local-S.log` (S the submission). A case whose run
//! ends with its outcome written is finished; any other end is a failure
//! with the run's last `error:` line (or its exit status).

use std::collections::VecDeque;
use std::fs::File;
use std::path::PathBuf;
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

use crate::study::directory::StudyDir;
use crate::study::error::StudyError;
use crate::study::state::{now_unix_s, progress, CaseProgress, CaseStatus, ExecutorKind};

use super::{error_in_log, Launch, Observer};

/// How often the children are looked at.
const POLL: Duration = Duration::from_millis(100);

/// How often the running cases' stage counts are refreshed.
const REFRESH: Duration = Duration::from_secs(1);

/// A case's child process.
struct Running {
    case: usize,
    child: Child,
    log: PathBuf,
}

/// Threads for each of `jobs` concurrent cases: the cores shared out.
fn threads_per_case(jobs: usize) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    (cores / jobs.max(1)).max(1)
}

/// Why a run that ended unfinished failed: its last error line, else its
/// exit status.
fn failure(log: &std::path::Path, status: ExitStatus) -> String {
    error_in_log(log).unwrap_or_else(|| match status.code() {
        Some(code) => format!("fwav design ended with exit status {code} (see its log)"),
        None => format!("fwav design was stopped ({status}; see its log)"),
    })
}

/// Runs `cases` of `study` here, `jobs` at a time; returns when every
/// one has ended (finished or failed), with `study.json` up to date.
pub fn run(
    study: &mut StudyDir,
    cases: &[usize],
    launch: &Launch,
    jobs: usize,
    observe: Observer<'_>,
) -> Result<(), StudyError> {
    let jobs = jobs.max(1);
    let submission = study.state.begin_submission(ExecutorKind::Local, cases);
    if let Some(s) = study.state.submission_mut(submission) {
        s.jobs = Some(jobs);
    }
    let logs = study.subdirectory("logs")?;
    let threads = threads_per_case(jobs).to_string();
    let mut waiting: VecDeque<usize> = cases.iter().copied().collect();
    let mut running: Vec<Running> = Vec::new();
    let mut refreshed = Instant::now();
    study.save()?;
    observe(&study.state);
    loop {
        while running.len() < jobs {
            let Some(case) = waiting.pop_front() else {
                break;
            };
            let Some(record) = study.state.case(case).cloned() else {
                continue;
            };
            let name = record
                .dir
                .rsplit('/')
                .next()
                .unwrap_or(&record.dir)
                .to_string();
            let log = logs.join(format!("{name}-local-{submission}.log"));
            let out = File::create(&log).map_err(StudyError::io(&log))?;
            let err = out.try_clone().map_err(StudyError::io(&log))?;
            let mut command = Command::new(&launch.program);
            command
                .args(launch.arguments(&study.case_dir(&record)))
                .stdin(Stdio::null())
                .stdout(out)
                .stderr(err);
            if std::env::var_os("RAYON_NUM_THREADS").is_none() {
                command.env("RAYON_NUM_THREADS", &threads);
            }
            let child = command.spawn().map_err(|source| StudyError::Spawn {
                command: launch.program.display().to_string(),
                source,
            })?;
            let relative = log
                .strip_prefix(study.path())
                .ok()
                .map(|p| p.display().to_string());
            if let Some(r) = study.state.case_mut(case) {
                r.status = CaseStatus::Running;
                r.error = None;
                r.submission = Some(submission);
                r.log = relative;
                r.slurm_task = None;
                r.slurm_state = None;
            }
            running.push(Running { case, child, log });
            study.save()?;
            observe(&study.state);
        }
        if running.is_empty() {
            break;
        }
        std::thread::sleep(POLL);
        let mut changed = false;
        let mut still = Vec::new();
        for mut r in running {
            match r
                .child
                .try_wait()
                .map_err(StudyError::io(&launch.program))?
            {
                None => still.push(r),
                Some(status) => {
                    settle(study, r.case, &r.log, status);
                    changed = true;
                }
            }
        }
        running = still;
        if refreshed.elapsed() >= REFRESH {
            refreshed = Instant::now();
            for r in &running {
                let Some(record) = study.state.case(r.case).cloned() else {
                    continue;
                };
                if let CaseProgress::Unfinished { stages } = progress(&study.case_dir(&record)) {
                    if let Some(c) = study.state.case_mut(r.case) {
                        changed |= c.stages_done != stages;
                        c.stages_done = stages;
                    }
                }
            }
        }
        if changed {
            study.save()?;
            observe(&study.state);
        }
    }
    if let Some(s) = study.state.submission_mut(submission) {
        s.ended_unix_s = Some(now_unix_s());
    }
    study.save()
}

/// Records how the run of `case` ended.
fn settle(study: &mut StudyDir, case: usize, log: &std::path::Path, status: ExitStatus) {
    let Some(record) = study.state.case(case).cloned() else {
        return;
    };
    let outcome = progress(&study.case_dir(&record));
    let Some(c) = study.state.case_mut(case) else {
        return;
    };
    c.settle(outcome, || failure(log, status));
}
