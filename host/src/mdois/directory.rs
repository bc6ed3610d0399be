//! Where a design run may write. A new run goes only into a new or empty
//! directory, or into a run of the same configuration, which it
//! continues; a directory holding anything else — a person's files, a run
//! of another configuration, a state file this build cannot read — is
//! refused before anything is written, naming the ways out: another
//! `--out`, or `--force` to delete its contents and start over (a run of
//! the same configuration too). `--force` never deletes an input of the
//! run (the configuration file read) or the directory the program runs
//! in. A directory holding only `config.toml`, the very file the run
//! reads as its configuration (`--config DIR/config.toml --out DIR`, as
//! `fwav study` prepares each case), counts as empty: the run writes its
//! resolved configuration, the same one, over it. Every check of the
//! configuration runs before the directory is made, and the directory is locked
//! ([`super::lock`]) before anything is written or deleted in it.

use std::path::{Path, PathBuf};

use crate::config::SystemConfig;

use super::error::DesignError;
use super::lock::{LockHolder, RunLock, LOCK_FILE};
use super::state::{RunState, STATE_FILE};

/// What a new run may do to an output directory that holds something
/// else.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Replace {
    /// Delete its contents and start over (`--force`).
    pub force: bool,
    /// The files the run reads (its configuration): `--force` never
    /// deletes them.
    pub inputs: Vec<PathBuf>,
}

/// What an output directory holds.
enum Contents {
    /// Nothing there yet.
    Missing,
    /// An empty directory (or one holding only a lock file).
    Empty,
    /// A design run (its `state.json`).
    Run,
    /// Other files: their names, sorted.
    Other(Vec<String>),
}

/// What is in `dir` (the lock file does not count).
fn contents(dir: &Path) -> Result<Contents, DesignError> {
    match std::fs::metadata(dir) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Contents::Missing),
        Err(e) => return Err(DesignError::io(dir)(e)),
        Ok(m) if !m.is_dir() => {
            return Err(DesignError::NotADirectory {
                path: dir.to_path_buf(),
            })
        }
        Ok(_) => {}
    }
    let mut names = Vec::new();
    for entry in std::fs::read_dir(dir).map_err(DesignError::io(dir))? {
        let entry = entry.map_err(DesignError::io(dir))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if name != LOCK_FILE {
            names.push(name);
        }
    }
    names.sort();
    Ok(if names.iter().any(|n| n == STATE_FILE) {
        Contents::Run
    } else if names.is_empty() {
        Contents::Empty
    } else {
        Contents::Other(names)
    })
}

/// What a claimed directory is for.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Plan {
    /// A new run of this configuration (the directory is empty).
    New(SystemConfig),
    /// The run there goes on; with a configuration, it must be the
    /// run's.
    Continue(Option<SystemConfig>),
}

/// A run directory claimed by this process: checked, made and locked,
/// with what is to be done in it ([`RunDir::run`]).
#[derive(Debug)]
pub struct RunDir {
    pub(crate) dir: PathBuf,
    pub(crate) plan: Plan,
    pub(crate) replaced: bool,
    pub(crate) lock: RunLock,
}

impl RunDir {
    /// Claims `dir` for a new run of `config` (module docs): the
    /// configuration is checked, the directory made if missing and
    /// locked; a run of the same configuration there is continued.
    pub fn for_start(
        config: &SystemConfig,
        dir: &Path,
        replace: &Replace,
    ) -> Result<Self, DesignError> {
        config.check()?;
        // The run's first step: the mesh must build.
        config.wing_model()?;
        // Some(why not): the directory holds something; None in it: a
        // run of this configuration.
        let occupied = match contents(dir)? {
            Contents::Missing | Contents::Empty => None,
            Contents::Run => Some(same_configuration(config, dir).err()),
            Contents::Other(names) if holds_only_its_configuration(dir, &names, replace) => None,
            Contents::Other(names) => Some(Some(DesignError::NotARun {
                dir: dir.to_path_buf(),
                names,
            })),
        };
        let replaced = match occupied {
            None => false,
            Some(_) if replace.force => {
                deletable(dir, &replace.inputs)?;
                true
            }
            Some(None) => return Self::claim(dir, Plan::Continue(Some(config.clone())), false),
            Some(Some(refusal)) => return Err(refusal),
        };
        std::fs::create_dir_all(dir).map_err(DesignError::io(dir))?;
        Self::claim(dir, Plan::New(config.clone()), replaced)
    }

    /// Claims the run in `dir` to resume it; with `config`, that must be
    /// the run's configuration. `config`'s values are not checked here:
    /// equal to the run's, they are the run's, which an earlier fwav may
    /// have accepted with a value this one refuses (the run then goes as
    /// without `config`: [`DesignError::RefusedNow`], or a finished run
    /// reported with the refusal); unequal, the first difference is the
    /// error ([`DesignError::ConfigMismatch`]).
    pub fn for_resume(dir: &Path, config: Option<&SystemConfig>) -> Result<Self, DesignError> {
        match contents(dir) {
            Ok(Contents::Run) => Self::claim(dir, Plan::Continue(config.cloned()), false),
            Ok(_) | Err(DesignError::NotADirectory { .. }) => Err(DesignError::NoRun {
                dir: dir.to_path_buf(),
            }),
            Err(e) => Err(e),
        }
    }

    /// Locks `dir`; with `replaced`, then deletes what it holds.
    fn claim(dir: &Path, plan: Plan, replaced: bool) -> Result<Self, DesignError> {
        let lock = RunLock::acquire(dir)?;
        if replaced {
            empty(dir)?;
        }
        Ok(Self {
            dir: dir.to_path_buf(),
            plan,
            replaced,
            lock,
        })
    }

    /// The run's directory.
    pub fn path(&self) -> &Path {
        &self.dir
    }

    /// Whether a run already there goes on (a resume, or a start of the
    /// same configuration).
    pub fn continues(&self) -> bool {
        matches!(self.plan, Plan::Continue(_))
    }

    /// Whether the directory's contents were deleted (`--force`).
    pub fn replaced(&self) -> bool {
        self.replaced
    }

    /// The holder of a lock left behind by a killed process, taken over.
    pub fn stale_lock(&self) -> Option<&LockHolder> {
        self.lock.stale()
    }
}

/// Whether the run in `dir` is of `config` (its state's configuration
/// hash); if not, the error names the first differing key.
fn same_configuration(config: &SystemConfig, dir: &Path) -> Result<(), DesignError> {
    let state = RunState::load(dir)?;
    if state.is_of(config)? {
        return Ok(());
    }
    let stored = state.started_with(dir)?;
    let (field, given, stored) = super::driver::first_difference(config, &stored)
        .unwrap_or_else(|| ("configuration".into(), "?".into(), "?".into()));
    Err(DesignError::Exists {
        dir: dir.to_path_buf(),
        field,
        given,
        stored,
    })
}

/// Whether `dir` holds nothing but `config.toml` and that file is the
/// configuration this run reads (`--config DIR/config.toml --out DIR`,
/// as `fwav study` prepares each case): the run starts there and writes
/// its resolved configuration, the same one, over it.
fn holds_only_its_configuration(dir: &Path, names: &[String], replace: &Replace) -> bool {
    let [name] = names else { return false };
    if name != super::driver::CONFIG_FILE {
        return false;
    }
    let Ok(own) = std::fs::canonicalize(dir.join(name)) else {
        return false;
    };
    replace
        .inputs
        .iter()
        .any(|input| std::fs::canonicalize(input).is_ok_and(|i| i == own))
}

/// Refuses to delete `dir` if it holds one of the `inputs` or the working
/// directory.
fn deletable(dir: &Path, inputs: &[PathBuf]) -> Result<(), DesignError> {
    let canonical = std::fs::canonicalize(dir).map_err(DesignError::io(dir))?;
    for input in inputs {
        let inside = std::fs::canonicalize(input).is_ok_and(|i| i.starts_with(&canonical));
        if inside {
            return Err(DesignError::InputInside {
                dir: dir.to_path_buf(),
                input: input.clone(),
            });
        }
    }
    let here = std::env::current_dir().and_then(std::fs::canonicalize);
    if here.is_ok_and(|h| h.starts_with(&canonical)) {
        return Err(DesignError::WorkingDirectoryInside {
            dir: dir.to_path_buf(),
        });
    }
    Ok(())
}

/// Deletes everything in `dir` but its lock file.
fn empty(dir: &Path) -> Result<(), DesignError> {
    for entry in std::fs::read_dir(dir).map_err(DesignError::io(dir))? {
        let entry = entry.map_err(DesignError::io(dir))?;
        if entry.file_name() == LOCK_FILE {
            continue;
        }
        let path = entry.path();
        let is_dir = entry.file_type().is_ok_and(|t| t.is_dir());
        let removed = if is_dir {
            std::fs::remove_dir_all(&path)
        } else {
            std::fs::remove_file(&path)
        };
        removed.map_err(DesignError::io(&path))?;
    }
    Ok(())
}
