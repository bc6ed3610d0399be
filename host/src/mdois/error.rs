//! Why a design run stopped: each error names the cycle and stage, the
//! file, or the configuration field concerned.

use std::path::PathBuf;

use fwav_actuator::controller_model::BeyondDevice;
use fwav_settings::Shown;

use crate::aeroelastic::handoff::HandoffError;
use crate::aeroelastic::last_cycle::Doubt;
use crate::aeroelastic::SystemError;
use crate::config::ConfigError;
use crate::discipline::cache::CacheError;
use crate::discipline::kinematic::KinematicError;
use crate::file_format::{FormatError, ReadError};
use crate::files::WriteError;
use crate::output::vtu::VtuError;
use crate::output::DrawingError;
use crate::topology::eslso::EslsoError;
use crate::topology::pressure::PressureError;
use crate::vehicle::VehicleError;

use super::lock::LockError;
use super::state::{Stage, StateProblem};

/// Why a design run stopped.
#[derive(Debug, thiserror::Error)]
pub enum DesignError {
    /// The configuration was refused (the message names the field).
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// A file could not be read or a directory made.
    #[error("{path}: {source}")]
    Io {
        /// The file or directory.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A file could not be written.
    #[error(transparent)]
    Write(#[from] WriteError),
    /// A versioned file of the run (`system.json`, `section.json`,
    /// `pressure.json`) could not be read, or is of another kind or
    /// version.
    #[error(transparent)]
    Read(#[from] ReadError),
    /// A versioned file's text could not be made.
    #[error(transparent)]
    Format(#[from] FormatError),
    /// The handoff files of a system analysis could not be written.
    #[error(transparent)]
    Handoff(#[from] HandoffError),
    /// A file of the run is not what the driver wrote.
    #[error("{path}: {message}")]
    State {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// A new run was asked for in a directory that holds a run of another
    /// configuration.
    #[error(
        "{d} holds a design run of another configuration ({field}: {given} here, {stored} in that run); \
         continue that run with --resume {d}, replace it with --force, or choose another --out",
        d = .dir.display()
    )]
    Exists {
        /// The directory.
        dir: PathBuf,
        /// The first differing field, `table.key`.
        field: String,
        /// Its value in the configuration given.
        given: String,
        /// Its value in the run's.
        stored: String,
    },
    /// A new run was asked for in a directory that holds other files.
    #[error(
        "{d} holds files that are not a design run ({}); fwav design writes only into a new or \
         empty directory or a run of its own: choose another --out, or add --force to delete \
         what {d} holds and start there",
        listed(.names),
        d = .dir.display()
    )]
    NotARun {
        /// The directory.
        dir: PathBuf,
        /// What it holds, sorted.
        names: Vec<String>,
    },
    /// The output path is a file.
    #[error("{} is not a directory: choose another --out", .path.display())]
    NotADirectory {
        /// The path.
        path: PathBuf,
    },
    /// `--force` would delete an input of the run.
    #[error(
        "--force would delete {}, which this run reads, with the rest of {}: keep the \
         configuration outside the output directory, or choose another --out",
        .input.display(),
        .dir.display()
    )]
    InputInside {
        /// The output directory.
        dir: PathBuf,
        /// The input, as given.
        input: PathBuf,
    },
    /// `--force` would delete the working directory.
    #[error(
        "--force would delete {d}, which holds the current directory: run fwav from elsewhere, \
         or choose another --out",
        d = .dir.display()
    )]
    WorkingDirectoryInside {
        /// The output directory.
        dir: PathBuf,
    },
    /// Another process computes in the run's directory.
    #[error(transparent)]
    Lock(#[from] LockError),
    /// The run's state file cannot be used.
    #[error(
        "{p} cannot be used: {problem}. The run cannot be resumed from it: start the design \
         again with --force (deletes what the directory holds), or with another --out",
        p = .path.display()
    )]
    StateUnreadable {
        /// The state file.
        path: PathBuf,
        /// What is wrong with it.
        problem: StateProblem,
    },
    /// The run's `config.toml` does not parse, or has a key this fwav
    /// does not know (a value outside its range is [`Self::RefusedNow`]).
    #[error("{}: {source}", .path.display())]
    RunConfig {
        /// The run's `config.toml`.
        path: PathBuf,
        /// The cause.
        source: Box<ConfigError>,
    },
    /// The run's configuration has a value this fwav refuses (an earlier
    /// one accepted it): its stages stay as they are, but it cannot go on.
    #[error(
        "{d} was started with a configuration this fwav refuses: {source}. Its finished stages \
         and files are kept as they are, but it cannot be continued with that value: copy its \
         config.toml, change the value, and start a new run (fwav design --config COPY --out \
         ANOTHER_DIRECTORY)",
        d = .dir.display()
    )]
    RefusedNow {
        /// The run's directory.
        dir: PathBuf,
        /// The first value refused.
        source: Box<ConfigError>,
    },
    /// The run's `config.toml` was edited after the run started.
    #[error(
        "{p} was edited after the run started ({field}: {now} in the file, {then} when the run \
         started); a run goes on only with the configuration it started with, so that no cycle \
         mixes the two: undo the edit to resume, or start a new run of the edited file (another \
         --out, or --force)",
        p = .path.display()
    )]
    ConfigEdited {
        /// The run's `config.toml`.
        path: PathBuf,
        /// The first differing field, `table.key`.
        field: String,
        /// Its value in the file now.
        now: String,
        /// Its value when the run started.
        then: String,
    },
    /// A resume was asked for where there is no run.
    #[error("{d} holds no design run to resume (no state.json)", d = .dir.display())]
    NoRun {
        /// The directory.
        dir: PathBuf,
    },
    /// The configuration given to a resume differs from the run's.
    #[error("the configuration differs from the one {d}/config.toml was started with ({field}: {given} here, {stored} there); resume without a configuration, or start a new run", d = .dir.display())]
    ConfigMismatch {
        /// The run's directory.
        dir: PathBuf,
        /// The first differing field, `table.key`.
        field: String,
        /// Its value in the configuration given.
        given: String,
        /// Its value in the run's `config.toml`.
        stored: String,
    },
    /// The system analysis failed.
    #[error("cycle {cycle}, system analysis: {source}")]
    System {
        /// The design cycle.
        cycle: usize,
        /// The cause.
        source: SystemError,
    },
    /// The system analysis ran, but its result is not to be trusted (the
    /// first doubt; `fwav system-analysis` of the cycle's design prints
    /// them all): the disciplines are not given it.
    #[error(
        "cycle {cycle}, system analysis: {doubt}; the design stops rather than choose on this \
         analysis"
    )]
    Doubtful {
        /// The design cycle.
        cycle: usize,
        /// Why the result is not to be trusted.
        doubt: Doubt,
    },
    /// A resumed design's reused system analysis (its `system.json`,
    /// written before the doubts were asked of it) is not to be trusted.
    /// The configuration of a run cannot change on a resume, so the
    /// doubt's own levers are for a new run.
    #[error(
        "cycle {cycle}, system analysis (cycle-{cycle}/system.json, reused on this resume): \
         {doubt}; the design stops rather than choose on this analysis: start the design again \
         in a new --out directory, with the configuration changed as said"
    )]
    DoubtfulRecord {
        /// The design cycle.
        cycle: usize,
        /// Why the result is not to be trusted.
        doubt: Doubt,
    },
    /// The aerodynamic discipline failed.
    #[error("cycle {cycle}, aerodynamic discipline: {source}")]
    Kinematics {
        /// The design cycle.
        cycle: usize,
        /// The cause.
        source: KinematicError,
    },
    /// The structural discipline failed.
    #[error("cycle {cycle}, structural discipline: {source}")]
    Topology {
        /// The design cycle.
        cycle: usize,
        /// The cause.
        source: EslsoError,
    },
    /// A pressure history file did not fit the wing.
    #[error("cycle {cycle}, pressure history: {source}")]
    Pressure {
        /// The design cycle.
        cycle: usize,
        /// The cause.
        source: PressureError,
    },
    /// The evaluation cache could not be read or written.
    #[error(transparent)]
    Cache(#[from] CacheError),
    /// A picture could not be drawn.
    #[error("{file}: {source}")]
    Picture {
        /// The picture's file.
        file: String,
        /// The cause.
        source: DrawingError,
    },
    /// A ParaView file could not be written.
    #[error("{file}: {source}")]
    ParaView {
        /// The ParaView file.
        file: String,
        /// The cause.
        source: VtuError,
    },
    /// Another result file could not be made (serialized or rendered).
    #[error("{file}: {message}")]
    Output {
        /// The output file.
        file: String,
        /// What went wrong.
        message: String,
    },
    /// The designed vehicle (wing on the design's actuator) could not be
    /// built or judged.
    #[error("cycle {cycle}, the vehicle (wing on the [actuator]): {source}")]
    Vehicle {
        /// The design cycle whose wing and analysis it is.
        cycle: usize,
        /// The cause.
        source: VehicleError,
    },
    /// The initial design cannot be flown by the design's actuator: the
    /// disciplines would have no feasible design to start from.
    #[error(
        "the initial design ({frequency_hz} Hz, ±{amplitude_deg} deg, mean {mean_deg} deg) cannot be flown \
         by the [actuator]: {limiting} is short of the {reserve_percent:.0}% reserve (its margin {margin_percent:.1}%), \
         judged with the aerodynamic damping of the first system analysis. Levers: the gear ratio \
         ([actuator] gear_ratio), the spring (spring = \"tuned\" cancels the inertial torque at the \
         flapping frequency), the battery (battery_v, battery_resistance_ohm), the current limit \
         (current_limit_a), or gentler initial kinematics ([kinematics])"
    )]
    InitialInfeasible {
        /// Initial frequency, Hz.
        frequency_hz: f64,
        /// Initial amplitude, deg.
        amplitude_deg: f64,
        /// Initial mean angle, deg.
        mean_deg: f64,
        /// The limiting quantity against its limit, e.g. `terminal
        /// voltage 9.58 V of 7.35 V (margin -30.3%)`.
        limiting: String,
        /// Its margin, percent of the limit.
        margin_percent: f64,
        /// The reserve asked of every margin, percent.
        reserve_percent: f64,
    },
    /// The flight controller cannot be set to the initial vehicle's
    /// model (judged after the first system analysis, on its wing and
    /// damping): a board would feed forward another plant than this one.
    #[error(
        "cycle {cycle}: the designed vehicle gives the flight controller's {} = {} {}, outside \
         the device's {}..={} {}: a board cannot be set to this vehicle's model; change the \
         [actuator] (rotor_inertia_kg_m2, gear_ratio, the spring) or the [wing], or fly \
         gentler initial kinematics ([kinematics])",
        .model.id.info().name,
        Shown::rounded(.model.value, 6),
        .model.id.info().unit,
        Shown(.model.id.info().bounds[0]),
        Shown(.model.id.info().bounds[1]),
        .model.id.info().unit
    )]
    BeyondDevice {
        /// The design cycle.
        cycle: usize,
        /// The model parameter and the value the vehicle gives it (not a
        /// `source`: its own text names the plant file's keys, which a
        /// design's user does not edit).
        model: BeyondDevice,
    },
    /// A discipline's thread panicked (a bug).
    #[error("cycle {cycle}, {stage}: the stage panicked")]
    Panicked {
        /// The design cycle.
        cycle: usize,
        /// The stage.
        stage: Stage,
    },
}

/// A directory's first few names, for a message.
fn listed(names: &[String]) -> String {
    const SHOWN: usize = 4;
    let mut text = names
        .iter()
        .take(SHOWN)
        .map(String::as_str)
        .collect::<Vec<_>>()
        .join(", ");
    if names.len() > SHOWN {
        text.push_str(&format!(" and {} more", names.len() - SHOWN));
    }
    text
}

impl DesignError {
    /// An I/O error on `path`.
    pub(crate) fn io(path: impl Into<PathBuf>) -> impl FnOnce(std::io::Error) -> Self {
        let path = path.into();
        move |source| Self::Io { path, source }
    }

    /// An output error on `file`.
    pub(crate) fn output(file: &str, message: impl std::fmt::Display) -> Self {
        Self::Output {
            file: file.to_string(),
            message: message.to_string(),
        }
    }
}
