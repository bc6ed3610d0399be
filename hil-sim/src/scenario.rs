//! Scripted runs: a host that handshakes, uploads a profile, arms, starts
//! and keeps a heartbeat, over the framed link (the host's own client,
//! `fwav_link::Link`, on the in-process [`Simulator`]), while faults are
//! injected at given times; the trace goes to [`crate::metrics`].
//!
//! ```toml
//! duration_s = 4.0
//! on_end = "hold"
//! [[segments]]
//! frequency_hz = 11.0
//! amplitude_deg = 30.0
//! duration_s = 100.0
//! ramp_s = 1.0
//! [[faults]]
//! at_s = 3.0
//! kind = "link_silence"     # or encoder_loss, stall, supply_drop (with battery_v)
//! ```

use fwav_actuator::controller_model::{checked_controller_model, BeyondDevice};
use fwav_actuator::params::PlantParams;
use fwav_fc_core::reference::ReferenceGenerator;
use fwav_link::{Link, LinkError};
use fwav_protocol::document::{ProfileDocument, SegmentDocument, FORMAT, FORMAT_VERSION};
use fwav_protocol::{Command, EndAction, Limits, Profile};
use fwav_settings::Shown;
use serde::{Deserialize, Serialize};

use crate::metrics::{Report, TracePoint};
use crate::sim::{InjectedFaults, Simulator};

/// A fault injected at a time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FaultEvent {
    /// When, s from the start of the run.
    pub at_s: f64,
    /// What.
    pub kind: FaultKind,
    /// New battery voltage for `supply_drop`, V.
    #[serde(default)]
    pub battery_v: Option<f64>,
}

/// Kinds of injected faults.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FaultKind {
    /// The host stops sending (no heartbeat).
    LinkSilence,
    /// The encoder stops counting.
    EncoderLoss,
    /// The rotor locks.
    Stall,
    /// The battery voltage drops to `battery_v`.
    SupplyDrop,
}

impl FaultKind {
    /// The name in a scenario file.
    pub const fn name(self) -> &'static str {
        match self {
            FaultKind::LinkSilence => "link_silence",
            FaultKind::EncoderLoss => "encoder_loss",
            FaultKind::Stall => "stall",
            FaultKind::SupplyDrop => "supply_drop",
        }
    }
}

impl std::fmt::Display for FaultKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// A scripted run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// Simulated time, s.
    pub duration_s: f64,
    /// Host heartbeat period, s.
    #[serde(default = "default_heartbeat")]
    pub heartbeat_s: f64,
    /// Steady-state metrics over this many final reference cycles (at
    /// least 1; fewer are measured when the run holds fewer whole cycles
    /// before its end and its first fault, and the report says so).
    #[serde(default = "default_cycles")]
    pub measure_cycles: u32,
    /// Profile end action.
    #[serde(default)]
    pub on_end: EndAction,
    /// The profile's segments (same keys as the JSON profile file).
    pub segments: Vec<SegmentDocument>,
    /// Injected faults.
    #[serde(default)]
    pub faults: Vec<FaultEvent>,
}

fn default_heartbeat() -> f64 {
    0.1
}
fn default_cycles() -> u32 {
    10
}

/// Why a scenario could not run.
#[derive(Debug, thiserror::Error)]
pub enum ScenarioError {
    /// Not TOML or unknown keys.
    #[error("{0}")]
    Toml(#[from] toml::de::Error),
    /// The profile is not a valid document.
    #[error("profile: {0}")]
    Document(#[from] fwav_protocol::document::DocumentError),
    /// The simulated device refused a command, gave an unexpected answer or
    /// none.
    #[error("the simulated flight controller: {0}")]
    Link(#[from] LinkError),
    /// The plant's controller model has a value the device refuses.
    #[error("{0}")]
    Plant(#[from] BeyondDevice),
    /// The run's length is not a positive number of seconds below the cap.
    #[error("duration_s = {} is outside 0 < duration_s < {} s", Shown(*duration_s), Shown(*max))]
    Duration {
        /// The value given.
        duration_s: f64,
        /// The cap, s.
        max: f64,
    },
    /// No cycle to measure the steady state over.
    #[error("measure_cycles = 0: the steady-state numbers are measured over whole reference cycles; give 1 or more (the default is {})", default_cycles())]
    MeasureCycles,
    /// The heartbeat period is not a positive, finite number of seconds.
    #[error("heartbeat_s = {} is not a positive, finite number of seconds", Shown(*heartbeat_s))]
    Heartbeat {
        /// The value given.
        heartbeat_s: f64,
    },
    /// A fault whose time is not inside the run never fires.
    #[error("faults[{index}] ({kind}): at_s = {} is outside the run: a fault fires at 0 <= at_s < duration_s = {} s", Shown(*at_s), Shown(*duration_s))]
    FaultTime {
        /// Its position in `faults`, from 0.
        index: usize,
        /// Its kind.
        kind: FaultKind,
        /// The time given, s.
        at_s: f64,
        /// The run's length, s.
        duration_s: f64,
    },
    /// A supply drop without the voltage it drops to, or with one that is
    /// not a positive number of volts.
    #[error("faults[{index}] (supply_drop): battery_v = {} must be given as the battery's voltage after the drop, a positive number of volts", battery_v.map_or("(missing)".to_owned(), |v| Shown(v).to_string()))]
    Battery {
        /// Its position in `faults`, from 0.
        index: usize,
        /// The voltage given, if any, V.
        battery_v: Option<f64>,
    },
}

/// The longest run a scenario may ask for, s.
pub const MAX_DURATION_S: f64 = 1e5;

impl Scenario {
    /// Parses a TOML text and checks its values.
    pub fn from_toml(text: &str) -> Result<Self, ScenarioError> {
        let s: Self = toml::from_str(text)?;
        s.check()?;
        Ok(s)
    }

    /// Checks the values: the run's length, the heartbeat period, at least
    /// one cycle to measure, and that every fault fires inside the run (a
    /// supply drop with its voltage).
    pub fn check(&self) -> Result<(), ScenarioError> {
        // Written so that NaN fails.
        if !(self.duration_s > 0.0 && self.duration_s < MAX_DURATION_S) {
            return Err(ScenarioError::Duration {
                duration_s: self.duration_s,
                max: MAX_DURATION_S,
            });
        }
        if !(self.heartbeat_s > 0.0 && self.heartbeat_s.is_finite()) {
            return Err(ScenarioError::Heartbeat {
                heartbeat_s: self.heartbeat_s,
            });
        }
        if self.measure_cycles == 0 {
            return Err(ScenarioError::MeasureCycles);
        }
        for (index, fault) in self.faults.iter().enumerate() {
            if !(0.0..self.duration_s).contains(&fault.at_s) {
                return Err(ScenarioError::FaultTime {
                    index,
                    kind: fault.kind,
                    at_s: fault.at_s,
                    duration_s: self.duration_s,
                });
            }
            let volts = fault.battery_v.filter(|v| *v > 0.0 && v.is_finite());
            if fault.kind == FaultKind::SupplyDrop && volts.is_none() {
                return Err(ScenarioError::Battery {
                    index,
                    battery_v: fault.battery_v,
                });
            }
        }
        Ok(())
    }

    /// When the first fault fires, s; `None` without faults. The
    /// steady-state numbers are measured before it.
    pub fn first_fault_s(&self) -> Option<f64> {
        self.faults.iter().map(|f| f.at_s).reduce(f64::min)
    }

    /// The profile in wire form.
    pub fn profile(&self) -> Result<Profile, ScenarioError> {
        let doc = ProfileDocument {
            format: FORMAT.to_owned(),
            format_version: FORMAT_VERSION,
            description: String::new(),
            on_end: self.on_end,
            segments: self.segments.clone(),
        };
        Ok(doc.to_profile()?)
    }
}

/// Runs `scenario` on a plant; returns the metrics report (a scenario
/// that fails [`Scenario::check`] is refused).
pub fn run(scenario: &Scenario, plant: &PlantParams) -> Result<Report, ScenarioError> {
    let (report, _) = run_with_trace(scenario, plant)?;
    Ok(report)
}

/// Runs `scenario`; returns the report and the trace (one point per control
/// period from the start command on).
pub fn run_with_trace(
    scenario: &Scenario,
    plant: &PlantParams,
) -> Result<(Report, Vec<TracePoint>), ScenarioError> {
    scenario.check()?;
    let model = checked_controller_model(plant)?;
    let profile = scenario.profile()?;
    let mut host = Link::new(Simulator::new(plant));
    host.handshake()?;
    // The controller feeds forward the plant it flies, set as a user sets
    // a board's (`fwav fc params --set`), not the protocol's defaults.
    for value in model {
        host.command(Command::SetParam(value))?;
    }
    host.command(Command::UploadProfile(profile.clone()))?;
    let session = host.arm()?;
    host.command(Command::Start)?;
    let mut reference = ReferenceGenerator::new();
    reference.start(&profile, &Limits::REFERENCE_FWAV);

    let dt = plant.control_dt();
    let steps = (scenario.duration_s / dt).round() as usize;
    let heartbeat_every = ((scenario.heartbeat_s / dt).round() as usize).max(1);
    let mut faults = InjectedFaults::default();
    let mut silent = false;
    let mut trace = Vec::with_capacity(steps);
    let start_ledger = host.get_ref().plant.ledger;
    let start_stored = host.get_ref().plant.stored_energy();
    for k in 0..steps {
        let t = k as f64 * dt;
        for f in scenario
            .faults
            .iter()
            .filter(|f| f.at_s <= t && f.at_s > t - dt)
        {
            match f.kind {
                FaultKind::LinkSilence => silent = true,
                FaultKind::EncoderLoss => faults.encoder_lost = true,
                FaultKind::Stall => faults.stalled = true,
                FaultKind::SupplyDrop => faults.battery_v = f.battery_v,
            }
            host.get_mut().set_faults(faults);
        }
        if !silent && k % heartbeat_every == 0 && k > 0 {
            // Refused once the device disarmed (a fault): the host keeps
            // sending, as a real one does until it notices.
            host.request(Command::Heartbeat { session })?;
        }
        let target = reference.waveform();
        let segment = reference.active_segment();
        let sample = host.get_mut().step();
        reference.advance(dt as f32);
        trace.push(TracePoint::new(&sample, &target, segment));
    }
    let sim = host.get_ref();
    let report = Report::from_trace(scenario, plant, &trace, sim, &start_ledger, start_stored);
    Ok((report, trace))
}
