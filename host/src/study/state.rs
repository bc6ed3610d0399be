//! `study.json`: the state of a study — its cases (values, directory,
//! status, the error of a failed one, its latest log, its Slurm task),
//! the submissions made (which executor, which cases, the Slurm job), and
//! the study's definition (varied keys, outputs, executors' settings, the
//! hash of every case's configuration).
//!
//! The executors write it as cases start and end; but what counts is
//! each case's own run directory: a case is finished when its design
//! run's `state.json` has an outcome and its `summary.json` is written
//! ([`progress`]), whatever the executor or Slurm said, so a study whose
//! follower was killed, or whose jobs ended while nobody watched, is
//! settled from the files ([`StudyState::settle`]).

use std::collections::BTreeMap;
use std::path::Path;
use std::time::{SystemTime, UNIX_EPOCH};

use serde::{Deserialize, Serialize};

use crate::file_format::FileFormat;
use crate::mdois::state::RunState;
use crate::mdois::DesignError;

use super::file::{LocalSettings, SlurmSettings};

/// The state file's format.
pub const STUDY: FileFormat = FileFormat {
    file: "study.json",
    format: "fwav-study",
    version: 1,
};

/// Where a case stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum CaseStatus {
    /// Not run yet, or stopped unfinished with no error known (a resume
    /// runs it).
    Pending,
    /// Submitted to Slurm, waiting for a node.
    Queued,
    /// Its design run is computing.
    Running,
    /// Its design run is over (converged or at its cycle cap).
    Finished,
    /// Its last attempt ended unfinished, with the error.
    Failed,
}

impl CaseStatus {
    /// The word of `fwav study status`.
    pub fn word(self) -> &'static str {
        match self {
            CaseStatus::Pending => "pending",
            CaseStatus::Queued => "queued",
            CaseStatus::Running => "running",
            CaseStatus::Finished => "finished",
            CaseStatus::Failed => "failed",
        }
    }
}

impl std::fmt::Display for CaseStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.word())
    }
}

/// Which executor ran a submission.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ExecutorKind {
    /// Child processes on this host, N at a time.
    Local,
    /// One Slurm job array.
    Slurm,
}

impl std::fmt::Display for ExecutorKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            ExecutorKind::Local => "local",
            ExecutorKind::Slurm => "slurm",
        })
    }
}

/// One case of the study.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CaseRecord {
    /// Its number, from 1.
    pub case: usize,
    /// Its design run's directory, relative to the study's
    /// (`cases/003`).
    pub dir: String,
    /// The values the study sets in it.
    pub values: BTreeMap<String, toml::Value>,
    /// Where it stands.
    pub status: CaseStatus,
    /// Why its last attempt failed.
    pub error: Option<String>,
    /// Its latest log (standard output and error of `fwav design`),
    /// relative to the study's directory.
    pub log: Option<String>,
    /// The submission that ran it last.
    pub submission: Option<usize>,
    /// Its Slurm array task (`JOB_TASK`), if Slurm ran it.
    pub slurm_task: Option<String>,
    /// Slurm's last word on that task (`PENDING`, `COMPLETED`,
    /// `CANCELLED`, ...).
    pub slurm_state: Option<String>,
    /// Stages its design run has finished.
    pub stages_done: usize,
}

impl CaseRecord {
    /// Records what the case's own files say of its ended run
    /// (`outcome`, from [`progress`]): finished, or failed with the
    /// executor's account of why (`failure`, asked only then); a state
    /// that cannot be read says so.
    pub fn settle(&mut self, outcome: CaseProgress, failure: impl FnOnce() -> String) {
        match outcome {
            CaseProgress::Finished { stages } => {
                self.status = CaseStatus::Finished;
                self.error = None;
                self.stages_done = stages;
            }
            CaseProgress::Unfinished { stages } => {
                self.status = CaseStatus::Failed;
                self.error = Some(failure());
                self.stages_done = stages;
            }
            CaseProgress::NotStarted => {
                self.status = CaseStatus::Failed;
                self.error = Some(failure());
                self.stages_done = 0;
            }
            CaseProgress::Unreadable(why) => {
                self.status = CaseStatus::Failed;
                self.error = Some(format!("its run's state cannot be read: {why}"));
            }
        }
    }
}

/// One submission of cases to an executor.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Submission {
    /// Its number, from 1.
    pub number: usize,
    /// The executor.
    pub executor: ExecutorKind,
    /// When it started, seconds since the Unix epoch.
    pub started_unix_s: u64,
    /// When its last case ended (`None`: still going, or its follower
    /// was stopped).
    pub ended_unix_s: Option<u64>,
    /// The cases submitted.
    pub cases: Vec<usize>,
    /// Local: cases at a time.
    pub jobs: Option<usize>,
    /// Slurm: the array job's id.
    pub job_id: Option<String>,
    /// Slurm: the batch script, relative to the study's directory.
    pub script: Option<String>,
}

/// The whole `study.json`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StudyState {
    /// [`STUDY`]'s format.
    pub format: String,
    /// [`STUDY`]'s version.
    pub format_version: u32,
    /// The study's name.
    pub name: String,
    /// The study file it was made from.
    pub study_file: String,
    /// SHA-256 (hex) of every case's number, values and whole
    /// configuration: `fwav study run` continues a study only of the
    /// same definition.
    pub definition_sha256: String,
    /// The varied keys, in the design file's order.
    pub keys: Vec<String>,
    /// The outputs plotted.
    pub outputs: Vec<String>,
    /// The study file's `[slurm]` settings.
    pub slurm: SlurmSettings,
    /// The study file's `[local]` settings.
    pub local: LocalSettings,
    /// Every case.
    pub cases: Vec<CaseRecord>,
    /// Every submission, in order.
    pub submissions: Vec<Submission>,
}

/// What a case's own run directory says.
#[derive(Clone, Debug, PartialEq)]
pub enum CaseProgress {
    /// No design run there yet.
    NotStarted,
    /// A run with this many stages finished, not over.
    Unfinished {
        /// Finished stages.
        stages: usize,
    },
    /// The run is over and its summary written.
    Finished {
        /// Finished stages.
        stages: usize,
    },
    /// Its `state.json` cannot be read (the reason).
    Unreadable(String),
}

/// What the design run in `case_dir` says of itself (module docs).
pub fn progress(case_dir: &Path) -> CaseProgress {
    match RunState::load(case_dir) {
        Err(DesignError::NoRun { .. }) => CaseProgress::NotStarted,
        Err(e) => CaseProgress::Unreadable(e.to_string()),
        Ok(state) => {
            let stages = state
                .cycles
                .iter()
                .map(|c| {
                    [
                        c.system.is_some(),
                        c.kinematics.is_some(),
                        c.topology.is_some(),
                    ]
                    .iter()
                    .filter(|&&done| done)
                    .count()
                })
                .sum();
            if state.outcome.is_some() && case_dir.join("summary.json").is_file() {
                CaseProgress::Finished { stages }
            } else {
                CaseProgress::Unfinished { stages }
            }
        }
    }
}

/// Seconds since the Unix epoch.
pub fn now_unix_s() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs())
}

impl StudyState {
    /// The case numbered `case`.
    pub fn case_mut(&mut self, case: usize) -> Option<&mut CaseRecord> {
        self.cases.iter_mut().find(|c| c.case == case)
    }

    /// The case numbered `case`.
    pub fn case(&self, case: usize) -> Option<&CaseRecord> {
        self.cases.iter().find(|c| c.case == case)
    }

    /// The cases not finished, in order.
    pub fn unfinished(&self) -> Vec<usize> {
        self.cases
            .iter()
            .filter(|c| c.status != CaseStatus::Finished)
            .map(|c| c.case)
            .collect()
    }

    /// How many cases stand at `status`.
    pub fn count(&self, status: CaseStatus) -> usize {
        self.cases.iter().filter(|c| c.status == status).count()
    }

    /// Opens a new submission of `cases` to `executor` and returns its
    /// number.
    pub fn begin_submission(&mut self, executor: ExecutorKind, cases: &[usize]) -> usize {
        let number = self.submissions.len() + 1;
        self.submissions.push(Submission {
            number,
            executor,
            started_unix_s: now_unix_s(),
            ended_unix_s: None,
            cases: cases.to_vec(),
            jobs: None,
            job_id: None,
            script: None,
        });
        number
    }

    /// The submission numbered `number`.
    pub fn submission_mut(&mut self, number: usize) -> Option<&mut Submission> {
        self.submissions.iter_mut().find(|s| s.number == number)
    }

    /// Brings every case's status and stage count in line with its run
    /// directory: a case whose run is over is finished; a case recorded
    /// finished whose run is not is pending again; a case recorded queued
    /// or running, when nothing follows it any more (`stale`), is pending.
    /// Returns whether anything changed.
    pub fn settle(&mut self, dir: &Path, stale: bool) -> bool {
        let mut changed = false;
        for c in &mut self.cases {
            let before = (c.status, c.stages_done, c.error.clone());
            match progress(&dir.join(&c.dir)) {
                CaseProgress::Finished { stages } => {
                    c.status = CaseStatus::Finished;
                    c.error = None;
                    c.stages_done = stages;
                }
                CaseProgress::Unfinished { stages } => {
                    c.stages_done = stages;
                    if c.status == CaseStatus::Finished {
                        c.status = CaseStatus::Pending;
                    }
                }
                CaseProgress::NotStarted => {
                    c.stages_done = 0;
                    if c.status == CaseStatus::Finished {
                        c.status = CaseStatus::Pending;
                    }
                }
                CaseProgress::Unreadable(why) => {
                    c.status = CaseStatus::Failed;
                    c.error = Some(format!("its run's state cannot be read: {why}"));
                }
            }
            if stale && matches!(c.status, CaseStatus::Queued | CaseStatus::Running) {
                c.status = CaseStatus::Pending;
            }
            changed |= before != (c.status, c.stages_done, c.error.clone());
        }
        changed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `study.json` reads back as written, values of every kind
    /// included.
    #[test]
    fn state_round_trips() {
        let values = BTreeMap::from([
            ("wing.semi_span_m".to_string(), toml::Value::Float(0.15)),
            ("wing.span_elements".to_string(), toml::Value::Integer(16)),
            (
                "actuator.spring".to_string(),
                toml::Value::String("tuned".into()),
            ),
            ("analysis.rigid".to_string(), toml::Value::Boolean(true)),
            (
                "design.frequency_hz".to_string(),
                toml::Value::Array(vec![toml::Value::Float(10.0), toml::Value::Float(12.0)]),
            ),
        ]);
        let state = StudyState {
            format: STUDY.format.into(),
            format_version: STUDY.version,
            name: "s".into(),
            study_file: "s.toml".into(),
            definition_sha256: "00".into(),
            keys: values.keys().cloned().collect(),
            outputs: vec!["ct".into()],
            slurm: SlurmSettings::default(),
            local: LocalSettings::default(),
            cases: vec![CaseRecord {
                case: 1,
                dir: "cases/001".into(),
                values,
                status: CaseStatus::Failed,
                error: Some("x".into()),
                log: None,
                submission: Some(1),
                slurm_task: Some("12_1".into()),
                slurm_state: Some("CANCELLED".into()),
                stages_done: 1,
            }],
            submissions: Vec::new(),
        };
        let text = STUDY.to_json(&state, true).unwrap();
        let back: StudyState = STUDY.parse(&text).unwrap();
        assert_eq!(back, state);
    }
}
