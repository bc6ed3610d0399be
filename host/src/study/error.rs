//! Why a study could not be made, run, followed or reported.

use std::path::PathBuf;

use crate::config::cost::CostEstimate;
use crate::config::template::CommentedTomlError;
use crate::file_format::ReadError;
use crate::files::WriteError;
use crate::mdois::lock::LockError;
use crate::output::drawing::DrawingError;

use super::cases::CasesRefused;
use super::file::StudyFileError;

/// Why a study stopped.
#[derive(Debug, thiserror::Error)]
pub enum StudyError {
    /// The study file was refused.
    #[error(transparent)]
    File(#[from] StudyFileError),
    /// Cases were refused (each named with its key).
    #[error(transparent)]
    Cases(#[from] CasesRefused),
    /// Cases far beyond the built-in design's cost, without `--yes`.
    #[error(
        "{count} case(s) far beyond the built-in design's cost, {case} the largest: it needs \
         {estimate}; nothing was written or submitted. Pass --yes to run them anyway, or choose \
         a coarser mesh ([wing] span_elements, chord_elements)"
    )]
    Cost {
        /// How many cases.
        count: usize,
        /// The costliest case (`case 003`).
        case: String,
        /// Its estimate.
        estimate: CostEstimate,
    },
    /// A file or directory could not be read or made.
    #[error("{}: {source}", .path.display())]
    Io {
        /// The path.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A file could not be written.
    #[error(transparent)]
    Write(#[from] WriteError),
    /// `study.json` could not be read.
    #[error("{0}")]
    State(#[from] ReadError),
    /// A case's configuration could not be written (a bug).
    #[error(transparent)]
    Template(#[from] CommentedTomlError),
    /// The output directory holds something that is not this study.
    #[error(
        "{} holds {}, not a study: choose another --out (or empty it)",
        .dir.display(),
        .names.iter().take(5).cloned().collect::<Vec<_>>().join(", ")
    )]
    NotAStudy {
        /// The directory.
        dir: PathBuf,
        /// What it holds.
        names: Vec<String>,
    },
    /// The output directory holds a study of another definition.
    #[error(
        "{} holds another study ({name}: other cases or configurations): choose another --out, \
         or `fwav study resume {}` to go on with that one",
        .dir.display(), .dir.display()
    )]
    OtherStudy {
        /// The directory.
        dir: PathBuf,
        /// Its study's name.
        name: String,
    },
    /// No study in the directory.
    #[error("{} holds no study (no study.json): start one with `fwav study run STUDY.toml --out {}`", .dir.display(), .dir.display())]
    NoStudy {
        /// The directory.
        dir: PathBuf,
    },
    /// Another process follows the study.
    #[error(transparent)]
    Lock(#[from] LockError),
    /// A command could not be started.
    #[error(
        "cannot run `{command}`: {source}{}",
        if .command.starts_with('s') {
            "; the Slurm executor needs Slurm's client commands (sbatch, squeue) on PATH, \
             as on a cluster's login node"
        } else { "" }
    )]
    Spawn {
        /// The command.
        command: String,
        /// The cause.
        source: std::io::Error,
    },
    /// sbatch refused the job.
    #[error("sbatch refused the job array ({status}): {stderr}; the script is {}", .script.display())]
    Submit {
        /// Its exit status.
        status: String,
        /// What it said.
        stderr: String,
        /// The batch script.
        script: PathBuf,
    },
    /// sbatch answered something that is not a job id.
    #[error("sbatch --parsable answered {answer:?}, not a job id")]
    JobId {
        /// Its answer.
        answer: String,
    },
    /// squeue kept failing.
    #[error("squeue failed {tries} times in a row following job {job}: {stderr}")]
    Queue {
        /// The job.
        job: String,
        /// How many tries.
        tries: usize,
        /// Its last complaint.
        stderr: String,
    },
    /// A job of an earlier submission is still in Slurm's queue.
    #[error(
        "Slurm job {job} still holds case(s) {} (pending or running): wait for it \
         (`fwav study status {}`), or cancel it (`scancel {job}`) and resume then",
        .cases.iter().map(ToString::to_string).collect::<Vec<_>>().join(", "), .dir.display()
    )]
    StillQueued {
        /// The study's directory.
        dir: PathBuf,
        /// The job.
        job: String,
        /// Its cases still queued or running.
        cases: Vec<usize>,
    },
    /// A path Slurm's `#SBATCH` lines and the batch script cannot hold.
    #[error("{}: the Slurm executor needs a study directory path without white space or quotes", .path.display())]
    SlurmPath {
        /// The path.
        path: PathBuf,
    },
    /// A picture could not be drawn.
    #[error(transparent)]
    Drawing(#[from] DrawingError),
    /// `results.csv` could not be written.
    #[error("results.csv: {0}")]
    Csv(#[from] csv::Error),
}

impl StudyError {
    /// The I/O error at `path`.
    pub fn io(path: impl Into<PathBuf>) -> impl FnOnce(std::io::Error) -> Self {
        let path = path.into();
        move |source| Self::Io { path, source }
    }
}
