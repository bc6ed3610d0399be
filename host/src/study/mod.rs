//! Design studies: many `fwav design` runs of one base configuration
//! with some keys varied — a full grid, a Latin hypercube or a list of
//! cases — run on a local pool or as one Slurm job array, followed,
//! resumed, and reported as `results.csv`, plots and `report.md`.
//!
//! - [`file`](mod@file): the study file (TOML) and its checks.
//! - [`cases`]: the cases it makes, each configuration checked whole
//!   before anything is written or submitted.
//! - [`directory`]: the study's directory (`study.json`, `cases/NNN/`,
//!   logs, scripts) and its lock.
//! - [`state`]: `study.json`, and what a case's own run directory says.
//! - [`executor`]: the local pool and the Slurm job array; a case is the
//!   ordinary, resumable design run of the `fwav` program.
//! - [`results`]: each case's final design from its `summary.json`.
//! - [`output`]: `results.csv`, the plots, `report.md`.
//! - [`error`]: why a study stopped.
//!
//! Imports: [`crate::config`] (the key table and the design file's
//! check), [`crate::mdois`] (a run's state, summary and lock, read from
//! the cases' directories; never its driver: each case is a process of
//! its own), [`crate::output`]'s drawing tools. Only the program imports
//! this room.

pub mod cases;
pub mod directory;
pub mod error;
pub mod executor;
pub mod file;
pub mod output;
pub mod results;
pub mod state;

use std::path::Path;

use crate::config::cost::CostEstimate;

pub use cases::PreparedCase;
pub use directory::StudyDir;
pub use error::StudyError;
pub use executor::slurm::SlurmOptions;
pub use executor::Launch;
pub use file::StudyFile;
pub use state::{CaseStatus, ExecutorKind, StudyState};

/// A study file read and every case checked: ready to claim a
/// directory.
#[derive(Clone, Debug)]
pub struct Prepared {
    /// The study file.
    pub file: StudyFile,
    /// Every case with its configuration.
    pub cases: Vec<PreparedCase>,
}

/// Reads the study file at `path` and checks every case
/// ([`cases::prepare`]); nothing is written.
pub fn prepare(path: &Path) -> Result<Prepared, StudyError> {
    let file = StudyFile::read(path)?;
    let cases = cases::prepare(&file)?;
    Ok(Prepared { file, cases })
}

impl Prepared {
    /// The cases far beyond the built-in design's cost: how many, and
    /// the costliest with its estimate.
    pub fn costly(&self) -> Option<(usize, String, CostEstimate)> {
        let total = self.cases.len();
        let far: Vec<(usize, CostEstimate)> = self
            .cases
            .iter()
            .map(|c| (c.case.number, CostEstimate::of(&c.config)))
            .filter(|(_, e)| e.is_far_beyond_default())
            .collect();
        let (number, estimate) = far
            .iter()
            .max_by(|a, b| a.1.time_ratio.total_cmp(&b.1.time_ratio))?;
        Some((far.len(), cases::case_name(*number, total), *estimate))
    }

    /// Refuses cases far beyond the built-in design's cost unless `yes`.
    pub fn check_cost(&self, yes: bool) -> Result<(), StudyError> {
        match self.costly() {
            Some((count, case, estimate)) if !yes => Err(StudyError::Cost {
                count,
                case,
                estimate,
            }),
            _ => Ok(()),
        }
    }
}

/// Where the cases run.
#[derive(Clone, Debug, PartialEq)]
pub enum Executor {
    /// Child processes here, `jobs` at a time.
    Local {
        /// Cases at a time.
        jobs: usize,
    },
    /// One Slurm job array.
    Slurm(SlurmOptions),
}

impl Executor {
    /// Its kind.
    pub fn kind(&self) -> ExecutorKind {
        match self {
            Executor::Local { .. } => ExecutorKind::Local,
            Executor::Slurm(_) => ExecutorKind::Slurm,
        }
    }
}

/// Runs `cases` of the claimed `study` on `executor` until each has
/// ended; `observe` sees the state at every change.
pub fn execute(
    study: &mut StudyDir,
    cases: &[usize],
    executor: &Executor,
    launch: &Launch,
    observe: executor::Observer<'_>,
) -> Result<(), StudyError> {
    if cases.is_empty() {
        return Ok(());
    }
    match executor {
        Executor::Local { jobs } => executor::local::run(study, cases, launch, *jobs, observe),
        Executor::Slurm(options) => executor::slurm::run(study, cases, launch, options, observe),
    }
}

/// Before resubmitting: refuses while a Slurm job of an earlier
/// submission still holds cases of the study (pending or running), then
/// settles every case from its files (cases left queued or running by a
/// follower that stopped are pending again).
pub fn reclaim(study: &mut StudyDir) -> Result<(), StudyError> {
    let open: Vec<(usize, String)> = study
        .state
        .submissions
        .iter()
        .filter(|s| s.executor == ExecutorKind::Slurm && s.ended_unix_s.is_none())
        .filter_map(|s| Some((s.number, s.job_id.clone()?)))
        .collect();
    for (number, job) in open {
        let cases = executor::slurm::active_cases(&job)?;
        if !cases.is_empty() {
            return Err(StudyError::StillQueued {
                dir: study.path().to_path_buf(),
                job,
                cases,
            });
        }
        if let Some(s) = study.state.submission_mut(number) {
            s.ended_unix_s = Some(state::now_unix_s());
        }
    }
    let dir = study.path().to_path_buf();
    study.state.settle(&dir, true);
    study.save()
}
