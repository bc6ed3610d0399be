//! Where a study lives: `DIR/study.json` ([`super::state`]), a copy of
//! the study file (`study.toml`), one design run directory a case
//! (`cases/NNN/`, holding at first only its `config.toml`), the logs
//! (`logs/`), Slurm's batch scripts (`slurm/`) and the report's files.
//!
//! A study starts only in a new or empty directory, or in a directory
//! holding a study of the same definition (every case's values and
//! configuration), which it continues; anything else is refused before
//! anything is written. While a process runs or follows the study it
//! holds `DIR/fwav.lock` (the design run's lock, [`crate::mdois::lock`]),
//! so two followers never write `study.json` at once; reading the state
//! (`fwav study status`, `report`) needs no lock.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use sha2::{Digest, Sha256};

use crate::config::template::commented_toml;
use crate::files::write_atomic;
use crate::mdois::driver::CONFIG_FILE;
use crate::mdois::lock::{RunLock, LOCK_FILE};

use super::cases::{dir_name, PreparedCase};
use super::error::StudyError;
use super::file::StudyFile;
use super::state::{CaseRecord, CaseStatus, StudyState, STUDY};

/// The copy of the study file in the study's directory.
pub const STUDY_COPY: &str = "study.toml";

/// A study directory claimed by this process (locked), with its state.
#[derive(Debug)]
pub struct StudyDir {
    dir: PathBuf,
    _lock: RunLock,
    /// The study's state, written by [`StudyDir::save`].
    pub state: StudyState,
    /// Whether a study already there was continued.
    pub continued: bool,
}

/// SHA-256 (hex) of the cases' numbers, values and configurations.
fn definition_hash(cases: &[PreparedCase]) -> String {
    let mut hash = Sha256::new();
    for c in cases {
        let values: Vec<String> = c
            .case
            .values
            .iter()
            .map(|(k, v)| format!("{k}={v}"))
            .collect();
        let config = toml::to_string(&c.config).unwrap_or_default();
        hash.update(format!(
            "{}\n{}\n{config}\n",
            c.case.number,
            values.join(",")
        ));
    }
    hash.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

/// The names in `dir` other than its lock file, sorted; `None`: no such
/// directory.
fn contents(dir: &Path) -> Result<Option<Vec<String>>, StudyError> {
    let entries = match std::fs::read_dir(dir) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(StudyError::io(dir)(e)),
        Ok(entries) => entries,
    };
    let mut names = Vec::new();
    for entry in entries {
        let name = entry
            .map_err(StudyError::io(dir))?
            .file_name()
            .to_string_lossy()
            .into_owned();
        if name != LOCK_FILE {
            names.push(name);
        }
    }
    names.sort();
    Ok(Some(names))
}

/// Reads `dir/study.json` (no lock taken).
pub fn read(dir: &Path) -> Result<StudyState, StudyError> {
    let path = dir.join(STUDY.file);
    if !path.is_file() {
        return Err(StudyError::NoStudy {
            dir: dir.to_path_buf(),
        });
    }
    Ok(STUDY.read(&path)?)
}

impl StudyDir {
    /// Claims `dir` for the study of `study` and its checked `cases`
    /// (module docs): a new study is written there (its state, then each
    /// case's `config.toml`), or the study of the same definition there
    /// is continued.
    pub fn create(
        study: &StudyFile,
        cases: &[PreparedCase],
        dir: &Path,
    ) -> Result<Self, StudyError> {
        let hash = definition_hash(cases);
        match contents(dir)? {
            None => std::fs::create_dir_all(dir).map_err(StudyError::io(dir))?,
            Some(names) if names.is_empty() => {}
            Some(names) if names.iter().any(|n| n == STUDY.file) => {
                let state = read(dir)?;
                if state.definition_sha256 != hash {
                    return Err(StudyError::OtherStudy {
                        dir: dir.to_path_buf(),
                        name: state.name,
                    });
                }
                let mut claimed = Self::open(dir)?;
                claimed.continued = true;
                claimed.write_configurations(cases)?;
                return Ok(claimed);
            }
            Some(names) => {
                return Err(StudyError::NotAStudy {
                    dir: dir.to_path_buf(),
                    names,
                })
            }
        }
        let lock = RunLock::acquire(dir)?;
        let total = cases.len();
        let state = StudyState {
            format: STUDY.format.to_string(),
            format_version: STUDY.version,
            name: study.name.clone(),
            study_file: study.path.display().to_string(),
            definition_sha256: hash,
            keys: study.keys().iter().map(ToString::to_string).collect(),
            outputs: study.outputs.iter().map(|o| o.name().to_string()).collect(),
            slurm: study.slurm.clone(),
            local: study.local.clone(),
            cases: cases
                .iter()
                .map(|c| CaseRecord {
                    case: c.case.number,
                    dir: format!("cases/{}", dir_name(c.case.number, total)),
                    values: c
                        .case
                        .values
                        .iter()
                        .map(|(k, v)| (k.to_string(), v.clone()))
                        .collect::<BTreeMap<_, _>>(),
                    status: CaseStatus::Pending,
                    error: None,
                    log: None,
                    submission: None,
                    slurm_task: None,
                    slurm_state: None,
                    stages_done: 0,
                })
                .collect(),
            submissions: Vec::new(),
        };
        let claimed = Self {
            dir: dir.to_path_buf(),
            _lock: lock,
            state,
            continued: false,
        };
        claimed.save()?;
        if let Ok(text) = std::fs::read(&study.path) {
            write_atomic(dir, STUDY_COPY, text)?;
        }
        claimed.write_configurations(cases)?;
        Ok(claimed)
    }

    /// Claims the study in `dir` to resume it.
    pub fn open(dir: &Path) -> Result<Self, StudyError> {
        read(dir)?;
        let lock = RunLock::acquire(dir)?;
        // Read again under the lock: the last holder may have written.
        let state = read(dir)?;
        Ok(Self {
            dir: dir.to_path_buf(),
            _lock: lock,
            state,
            continued: true,
        })
    }

    /// Writes each case's `config.toml` where its directory holds no
    /// design run yet (a study continued writes the ones a killed start
    /// left out).
    fn write_configurations(&self, cases: &[PreparedCase]) -> Result<(), StudyError> {
        for c in cases {
            let Some(record) = self.state.case(c.case.number) else {
                continue;
            };
            let case_dir = self.dir.join(&record.dir);
            if case_dir.join(CONFIG_FILE).is_file() {
                continue;
            }
            std::fs::create_dir_all(&case_dir).map_err(StudyError::io(&case_dir))?;
            write_atomic(&case_dir, CONFIG_FILE, commented_toml(&c.config)?)?;
        }
        Ok(())
    }

    /// The study's directory.
    pub fn path(&self) -> &Path {
        &self.dir
    }

    /// A case's design run directory.
    pub fn case_dir(&self, record: &CaseRecord) -> PathBuf {
        self.dir.join(&record.dir)
    }

    /// Writes `study.json` atomically.
    pub fn save(&self) -> Result<(), StudyError> {
        let text = STUDY
            .to_json(&self.state, true)
            .map_err(|e| StudyError::io(self.dir.join(STUDY.file))(std::io::Error::other(e)))?;
        write_atomic(&self.dir, STUDY.file, text)?;
        Ok(())
    }

    /// Makes `DIR/NAME` (a subdirectory for logs or scripts) and returns
    /// it.
    pub fn subdirectory(&self, name: &str) -> Result<PathBuf, StudyError> {
        let path = self.dir.join(name);
        std::fs::create_dir_all(&path).map_err(StudyError::io(&path))?;
        Ok(path)
    }
}
