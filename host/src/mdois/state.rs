//! The run state of a design run, kept as `state.json` in the run's
//! directory: which stages of which cycle are finished, by which
//! invocation of the driver (a fresh start is run 1, each resume the next
//! number), in how many seconds and with which files, and the outcome once
//! the run is over; and the configuration the run started with, with its
//! SHA-256, so that a resume refuses a `config.toml` edited since.
//!
//! A stage's files are written (atomically) before the state marks it
//! finished, and the state itself is written atomically, so a run killed
//! at any moment loses at most the stage in progress. On resume the state
//! is cut back to its consistent prefix: a stage whose files are missing
//! is unfinished, and every stage after an unfinished one is dropped (it
//! took that stage's output as input).

use std::path::Path;

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};

use crate::config::SystemConfig;
use crate::file_format::{FileFormat, FormatError};
use crate::files::write_atomic;

use super::error::DesignError;

/// The state file's name in the run's directory.
pub const STATE_FILE: &str = "state.json";

/// The state file's format. Version 2 holds the configuration the run
/// started with and its hash; version 1 (`"format": "fwav-mdois-state-1"`,
/// no `format_version`) did not, and is refused.
pub const STATE: FileFormat = FileFormat {
    file: STATE_FILE,
    format: "fwav-mdois-state",
    version: 2,
};

/// The `format` of the state files of earlier builds (version 1).
const EARLIER_FORMAT: &str = "fwav-mdois-state-1";

/// Why a state file cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum StateProblem {
    /// Not a state file of this build's format (corrupt, cut short, or of
    /// another kind or version).
    #[error(transparent)]
    Format(#[from] FormatError),
    /// A state file of an earlier build, without the configuration's
    /// hash.
    #[error(
        "it was written by an earlier fwav (format {EARLIER_FORMAT:?}, without the configuration's hash); \
         this build reads {:?} version {}", STATE.format, STATE.version
    )]
    Earlier,
    /// The configuration it holds does not parse.
    #[error("its configuration does not parse: {0}")]
    Configuration(toml::de::Error),
    /// A run is numbered otherwise than the driver numbers them (1, 2,
    /// ... in order).
    #[error("run {run} is numbered {number}: the driver numbers its runs 1, 2, ... in order")]
    RunNumber {
        /// The run's position in `runs`, from 1.
        run: usize,
        /// The number it has.
        number: usize,
    },
}

/// The stages of a design cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Stage {
    /// The coupled 3D aeroelastic system analysis of the cycle's design.
    System,
    /// The aerodynamic discipline (kinematic optimization).
    Kinematics,
    /// The structural discipline (ESLSO topology optimization).
    Topology,
}

impl Stage {
    /// The stage's name as a person reads it.
    pub fn name(self) -> &'static str {
        match self {
            Stage::System => "system analysis",
            Stage::Kinematics => "aerodynamic discipline",
            Stage::Topology => "structural discipline",
        }
    }
}

impl std::fmt::Display for Stage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// A finished stage.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StageRecord {
    /// The driver invocation that computed it (1: the first start).
    pub run: usize,
    /// Wall time of the stage, s.
    pub seconds: f64,
    /// Its files, relative to the run's directory.
    pub files: Vec<String>,
}

/// One design cycle's finished stages.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct CycleState {
    /// Cycle number from 1.
    pub cycle: usize,
    /// The system analysis.
    pub system: Option<StageRecord>,
    /// The aerodynamic discipline.
    pub kinematics: Option<StageRecord>,
    /// The structural discipline.
    pub topology: Option<StageRecord>,
}

impl CycleState {
    fn slot(&mut self, stage: Stage) -> &mut Option<StageRecord> {
        match stage {
            Stage::System => &mut self.system,
            Stage::Kinematics => &mut self.kinematics,
            Stage::Topology => &mut self.topology,
        }
    }

    /// The record of `stage`, if finished.
    pub fn get(&self, stage: Stage) -> Option<&StageRecord> {
        match stage {
            Stage::System => self.system.as_ref(),
            Stage::Kinematics => self.kinematics.as_ref(),
            Stage::Topology => self.topology.as_ref(),
        }
    }
}

/// One invocation of the driver on the run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunRecord {
    /// Its number from 1.
    pub run: usize,
    /// When it started, seconds since the Unix epoch.
    pub started_unix_s: u64,
}

/// How a finished run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Outcome {
    /// No design variable changed in this cycle's disciplines: the design
    /// analysed in this cycle is the answer.
    Converged {
        /// The cycle.
        cycle: usize,
    },
    /// The design still changed in cycle `max_cycles`; cycle
    /// `max_cycles + 1` analysed that last proposal.
    CycleCap {
        /// The cap.
        max_cycles: usize,
    },
}

/// The whole state file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunState {
    /// [`STATE`]'s format.
    pub format: String,
    /// [`STATE`]'s version.
    pub format_version: u32,
    /// SHA-256 (hex) of `configuration`: a resume compares the run's
    /// `config.toml` with it.
    pub configuration_sha256: String,
    /// The configuration the run started with: every key, as TOML.
    pub configuration: String,
    /// Every invocation of the driver.
    pub runs: Vec<RunRecord>,
    /// The cycles begun, in order.
    pub cycles: Vec<CycleState>,
    /// Set when the run is over (its final outputs written).
    pub outcome: Option<Outcome>,
}

/// A configuration as the state keeps it (every key, no comments) and its
/// hash.
fn canonical(config: &SystemConfig) -> Result<(String, String), DesignError> {
    let text = toml::to_string(config).map_err(|e| DesignError::output(STATE_FILE, e))?;
    let hash = Sha256::digest(text.as_bytes())
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    Ok((text, hash))
}

impl RunState {
    /// The state of a new run of `config`: nothing done yet.
    pub fn new(config: &SystemConfig) -> Result<Self, DesignError> {
        let (configuration, configuration_sha256) = canonical(config)?;
        Ok(Self {
            format: STATE.format.to_string(),
            format_version: STATE.version,
            configuration_sha256,
            configuration,
            runs: Vec::new(),
            cycles: Vec::new(),
            outcome: None,
        })
    }

    /// Reads `dir/state.json`.
    pub fn load(dir: &Path) -> Result<Self, DesignError> {
        let path = dir.join(STATE_FILE);
        let text = std::fs::read_to_string(&path).map_err(|source| {
            if source.kind() == std::io::ErrorKind::NotFound {
                DesignError::NoRun {
                    dir: dir.to_path_buf(),
                }
            } else {
                DesignError::Io {
                    path: path.clone(),
                    source,
                }
            }
        })?;
        let state: Self = STATE.parse(&text).map_err(|error| {
            let problem = match error {
                FormatError::WrongFormat {
                    found: Some(ref f), ..
                } if f == EARLIER_FORMAT => StateProblem::Earlier,
                other => StateProblem::Format(other),
            };
            DesignError::StateUnreadable {
                path: path.clone(),
                problem,
            }
        })?;
        // The driver numbers its invocations 1, 2, ... in order; another
        // number is not one it wrote (and usize::MAX overflowed the next).
        if let Some((run, r)) = (1..).zip(&state.runs).find(|(i, r)| r.run != *i) {
            return Err(DesignError::StateUnreadable {
                path,
                problem: StateProblem::RunNumber { run, number: r.run },
            });
        }
        Ok(state)
    }

    /// Writes `dir/state.json` atomically.
    pub fn save(&self, dir: &Path) -> Result<(), DesignError> {
        write_atomic(dir, STATE_FILE, STATE.to_json(self, true)?)?;
        Ok(())
    }

    /// Whether `config` is the configuration the run started with.
    pub fn is_of(&self, config: &SystemConfig) -> Result<bool, DesignError> {
        Ok(canonical(config)?.1 == self.configuration_sha256)
    }

    /// The configuration the run started with (the run is in `dir`).
    pub fn started_with(&self, dir: &Path) -> Result<SystemConfig, DesignError> {
        toml::from_str(&self.configuration).map_err(|e| DesignError::StateUnreadable {
            path: dir.join(STATE_FILE),
            problem: StateProblem::Configuration(e),
        })
    }

    /// The record of `stage` of `cycle`, if finished.
    pub fn stage(&self, cycle: usize, stage: Stage) -> Option<&StageRecord> {
        self.cycles
            .iter()
            .find(|c| c.cycle == cycle)
            .and_then(|c| c.get(stage))
    }

    /// Marks `stage` of `cycle` finished with `record`.
    pub fn finish(&mut self, cycle: usize, stage: Stage, record: StageRecord) {
        while self.cycles.len() < cycle {
            let next = self.cycles.len() + 1;
            self.cycles.push(CycleState {
                cycle: next,
                ..CycleState::default()
            });
        }
        if let Some(c) = self.cycles.iter_mut().find(|c| c.cycle == cycle) {
            *c.slot(stage) = Some(record);
        }
    }

    /// The number of the next driver invocation.
    pub fn next_run(&self) -> usize {
        self.runs.iter().map(|r| r.run).max().unwrap_or(0) + 1
    }

    /// Cuts the state back to its consistent prefix (module docs): a stage
    /// any of whose files is missing from `dir` is unfinished; a cycle's
    /// disciplines need its system analysis, and a cycle needs both
    /// disciplines of the cycle before. Returns the stages dropped.
    pub fn consistent_prefix(&mut self, dir: &Path) -> Vec<(usize, Stage)> {
        let mut dropped = Vec::new();
        let mut broken = false;
        for (i, c) in self.cycles.iter_mut().enumerate() {
            c.cycle = i + 1;
            for stage in [Stage::System, Stage::Kinematics, Stage::Topology] {
                let slot = c.slot(stage);
                let present = slot
                    .as_ref()
                    .is_some_and(|r| r.files.iter().all(|f| dir.join(f).is_file()));
                let allowed = match stage {
                    Stage::System => !broken,
                    _ => !broken && c.system.is_some(),
                };
                let slot = c.slot(stage);
                if slot.is_some() && !(present && allowed) {
                    *slot = None;
                    dropped.push((i + 1, stage));
                }
            }
            if c.system.is_none() || c.kinematics.is_none() || c.topology.is_none() {
                broken = true;
            }
        }
        while self.cycles.last().is_some_and(|c| c.system.is_none()) {
            self.cycles.pop();
        }
        if !dropped.is_empty() {
            self.outcome = None;
        }
        dropped
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(files: &[&str]) -> StageRecord {
        StageRecord {
            run: 1,
            seconds: 1.0,
            files: files.iter().map(|f| f.to_string()).collect(),
        }
    }

    /// A stage whose file is gone is unfinished, and so is everything
    /// that took its output.
    #[test]
    fn missing_files_cut_the_state_back() {
        let dir = std::env::temp_dir().join(format!("fwav-state-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for f in ["s1", "k1", "t1", "s2"] {
            std::fs::write(dir.join(f), "x").unwrap();
        }
        let mut state = RunState::new(&SystemConfig::default()).unwrap();
        state.finish(1, Stage::System, record(&["s1"]));
        state.finish(1, Stage::Kinematics, record(&["k1"]));
        state.finish(1, Stage::Topology, record(&["t1"]));
        state.finish(2, Stage::System, record(&["s2"]));
        let mut kept = state.clone();
        assert!(kept.consistent_prefix(&dir).is_empty());
        assert_eq!(kept, state);
        std::fs::remove_file(dir.join("t1")).unwrap();
        let dropped = state.consistent_prefix(&dir);
        assert_eq!(dropped, vec![(1, Stage::Topology), (2, Stage::System)]);
        assert_eq!(state.cycles.len(), 1);
        assert!(state.stage(1, Stage::Kinematics).is_some());
        state.save(&dir).unwrap();
        assert_eq!(RunState::load(&dir).unwrap(), state);
        std::fs::remove_dir_all(&dir).ok();
    }
}
