//! The flight controller: the link handler state machine and the control
//! step, in one object that the STM32 binary and hil-sim both drive.
//!
//! - [`FlightController::handle`] takes a decoded request from one of the
//!   links and returns the answer (or asks the caller to save to flash).
//! - [`FlightController::step`] runs one control period: failsafes,
//!   reference, controller, telemetry; it returns the H-bridge duty.
//!
//! States: disarmed (bridge off) → armed (bridge on, holding rest) → running
//! (following the profile). Arming needs a handshake on the link, no latched
//! fault and no save in progress; starting needs armed and a valid profile.
//! Every disarm records its [`DisarmReason`]; every fault stays latched until
//! [`Command::ClearFaults`].
//!
//! The link failsafe: arming opens a session (a number returned in
//! [`Reply::Armed`]) and only [`Command::Heartbeat`]s carrying that number
//! keep the device armed. Any client on any link may still query (status,
//! ping, parameters, profile, limits) and stop or disarm, but none of that
//! feeds the failsafe, so a wing whose controlling client died is brought to
//! rest within the link timeout and one wingbeat whoever else keeps asking.

use fwav_protocol::{
    Command, DeviceMessage, DisarmReason, FaultFlags, Limits, LinkStats, NackReason, ParamId,
    Profile, Reply, Request, Response, Status, TelemetrySample,
};

use crate::controller::{ControlOutput, FlappingController, Measurement};
use crate::monitor::FaultMonitor;
use crate::params::ParamSet;
use crate::reference::{Mode, ReferenceGenerator};
use crate::session::{Dispatch, Session};
use crate::storage::{StorageError, StoredState};

/// The links a flight controller serves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinkId {
    /// USB CDC-ACM (what a user plugs in).
    Usb,
    /// UART (a radio, or hil-sim's pseudo-terminal).
    Uart,
}

impl LinkId {
    const fn index(self) -> usize {
        match self {
            LinkId::Usb => 0,
            LinkId::Uart => 1,
        }
    }
}

/// The answer to a request.
#[derive(Clone, Debug, PartialEq)]
#[allow(
    clippy::large_enum_variant,
    reason = "no allocator on the device: answers are values"
)]
pub enum Handled {
    /// Send this back on the link the request came from.
    Reply(DeviceMessage),
    /// Write `record` to flash, then answer with
    /// [`FlightController::save_finished`].
    Save {
        /// The request's sequence number.
        seq: u16,
        /// What to store.
        record: StoredState,
    },
}

/// The result of one control step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Actuation {
    /// H-bridge duty in [-1, 1] (0 when disabled).
    pub duty: f32,
    /// Bridge outputs enabled (armed). When false the binary switches the
    /// bridge off in hardware, not just to zero duty.
    pub bridge_enabled: bool,
    /// A telemetry sample to send, and on which link.
    pub telemetry: Option<(LinkId, TelemetrySample)>,
}

/// Why a stored record was not restored at boot.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum RestoreError {
    /// The record could not be read.
    #[error("{0}")]
    Storage(#[from] StorageError),
    /// The stored profile violates this device's limits: not loaded.
    #[error("stored profile refused: {0}")]
    Profile(fwav_protocol::ProfileError),
}

/// The flight controller.
#[derive(Clone, Debug)]
pub struct FlightController {
    limits: Limits,
    params: ParamSet,
    sessions: [Session; 2],
    /// Per link, the last request's sequence number and answer: a retry
    /// (same seq) gets the same answer without being executed twice.
    last_reply: [Option<(u16, DeviceMessage)>; 2],
    profile: Option<Profile>,
    generator: ReferenceGenerator,
    controller: FlappingController,
    monitor: FaultMonitor,
    armed: bool,
    /// The session of the last arming: only its heartbeats feed the link
    /// failsafe.
    session: u32,
    saving: bool,
    /// The link failsafe is ramping down; disarm when at rest.
    link_lost: bool,
    faults: FaultFlags,
    last_disarm: Option<DisarmReason>,
    telemetry: Option<(LinkId, u16)>,
    telemetry_countdown: u16,
    telemetry_seq: u32,
    /// When the controlling session last armed or sent a heartbeat, µs.
    last_heartbeat_us: u64,
    now_us: u64,
    last_duty: f32,
    last_output: Option<ControlOutput>,
}

impl FlightController {
    /// A disarmed controller with default parameters and no profile, for a
    /// device with `limits`.
    pub fn new(limits: Limits) -> Self {
        Self {
            limits,
            params: ParamSet::DEFAULT,
            sessions: [Session::new(); 2],
            last_reply: [None, None],
            profile: None,
            generator: ReferenceGenerator::new(),
            controller: FlappingController::new(),
            monitor: FaultMonitor::new(),
            armed: false,
            session: 0,
            saving: false,
            link_lost: false,
            faults: FaultFlags::NONE,
            last_disarm: Some(DisarmReason::Reset),
            telemetry: None,
            telemetry_countdown: 0,
            telemetry_seq: 0,
            last_heartbeat_us: 0,
            now_us: 0,
            last_duty: 0.0,
            last_output: None,
        }
    }

    /// Loads a record read from flash at boot. A damaged or foreign record,
    /// or a profile that fails validation, is refused (the STORAGE fault is
    /// latched so the user sees it) and the defaults stay.
    pub fn restore(&mut self, bytes: &[u8]) -> Result<(), RestoreError> {
        let result = self.try_restore(bytes);
        if result.is_err() {
            self.faults = self.faults.union(FaultFlags::STORAGE);
        }
        result
    }

    fn try_restore(&mut self, bytes: &[u8]) -> Result<(), RestoreError> {
        let record = StoredState::decode(bytes)?;
        if let Some(profile) = &record.profile {
            profile
                .validate(&self.limits)
                .map_err(RestoreError::Profile)?;
        }
        let (params, _refused) = ParamSet::from_list(&record.params);
        self.params = params;
        self.profile = record.profile;
        Ok(())
    }

    /// The parameters in force.
    pub fn params(&self) -> &ParamSet {
        &self.params
    }

    /// Bridge enabled.
    pub fn is_armed(&self) -> bool {
        self.armed
    }

    /// Following (or ramping out of) the profile.
    pub fn is_running(&self) -> bool {
        self.armed && self.generator.is_active()
    }

    /// Latched faults.
    pub fn faults(&self) -> FaultFlags {
        self.faults
    }

    /// The controller's per-stroke state (for diagnostics and tests).
    pub fn flapping(&self) -> &FlappingController {
        &self.controller
    }

    /// The link on which telemetry streams, if any.
    pub fn telemetry_link(&self) -> Option<LinkId> {
        self.telemetry.map(|(link, _)| link)
    }

    /// The status as the device reports it, with `link` the counters of the
    /// asking link's decoder.
    pub fn status(&self, link: LinkStats) -> Status {
        Status {
            uptime_ms: self.now_us / 1000,
            armed: self.armed,
            running: self.is_running(),
            profile_loaded: self.profile.is_some(),
            active_segment: self
                .generator
                .active_segment()
                .filter(|_| self.armed)
                .map(|i| i.min(u8::MAX as usize) as u8),
            faults: self.faults,
            last_disarm: self.last_disarm,
            link,
        }
    }

    /// Handles one request from `link` at time `now_us` (µs since boot).
    /// `stats` are that link decoder's counters (for the status reply).
    ///
    /// A request with the same sequence number as the previous one on the
    /// link is a retry (its answer was lost): it gets the cached answer and
    /// is not executed again. A handshake starts afresh. Only an arming and
    /// the controlling session's heartbeats feed the link failsafe; other
    /// traffic, from whichever client, does not.
    pub fn handle(
        &mut self,
        link: LinkId,
        request: Request,
        now_us: u64,
        stats: LinkStats,
    ) -> Handled {
        let index = link.index();
        let handshake = matches!(request.command, Command::Handshake(_));
        if handshake {
            self.last_reply[index] = None;
        } else if let Some((seq, answer)) = &self.last_reply[index] {
            if *seq == request.seq && self.sessions[index].is_open() {
                return Handled::Reply(answer.clone());
            }
        }
        let seq = request.seq;
        let handled = match self.sessions[index].receive(request) {
            Dispatch::Reply(message) => Handled::Reply(message),
            Dispatch::Forward { seq, command } => {
                if let Command::SaveProfile = command {
                    return self.begin_save(seq);
                }
                let reply = self.command(link, command, stats, now_us);
                Handled::Reply(DeviceMessage::Response(Response { seq, reply }))
            }
        };
        if let (Handled::Reply(answer), false) = (&handled, handshake) {
            self.last_reply[index] = Some((seq, answer.clone()));
        }
        handled
    }

    fn command(&mut self, link: LinkId, command: Command, stats: LinkStats, now_us: u64) -> Reply {
        let refuse = Reply::Nack;
        match command {
            // Answered by the session; listed so a new command is a compile error here.
            Command::Handshake(_) | Command::Ping { .. } | Command::SaveProfile => {
                refuse(NackReason::Unsupported)
            }
            Command::UploadProfile(profile) => {
                if self.is_running() {
                    return refuse(NackReason::Running);
                }
                match profile.validate(&self.limits) {
                    Ok(()) => {
                        self.profile = Some(profile);
                        Reply::Ack
                    }
                    Err(e) => refuse(NackReason::InvalidProfile(e)),
                }
            }
            Command::ReadProfile => Reply::Profile(self.profile.clone()),
            Command::Arm => {
                if !self.faults.is_empty() {
                    refuse(NackReason::Faulted(self.faults))
                } else if self.saving {
                    refuse(NackReason::Busy)
                } else if self.generator.is_active() {
                    refuse(NackReason::NotAtRest)
                } else {
                    self.arm(now_us)
                }
            }
            Command::Heartbeat { session } => {
                if !self.armed {
                    refuse(NackReason::NotArmed)
                } else if session != self.session {
                    refuse(NackReason::OtherSession)
                } else {
                    self.last_heartbeat_us = self.now_us.max(now_us);
                    Reply::Ack
                }
            }
            Command::Disarm => {
                self.disarm(DisarmReason::Command);
                Reply::Ack
            }
            Command::Start => {
                if !self.armed {
                    refuse(NackReason::NotArmed)
                } else if !self.faults.is_empty() {
                    refuse(NackReason::Faulted(self.faults))
                } else if self.generator.is_active() {
                    refuse(NackReason::Running)
                } else {
                    match &self.profile {
                        None => refuse(NackReason::NoProfile),
                        Some(profile) => {
                            self.generator.start(profile, &self.limits);
                            Reply::Ack
                        }
                    }
                }
            }
            Command::Stop => {
                self.generator.stop();
                Reply::Ack
            }
            Command::GetParams => Reply::Params(self.params.to_list()),
            Command::SetParam(p) => match self.params.set(p.id, p.value) {
                Ok(()) => Reply::Ack,
                Err(reason) => refuse(reason),
            },
            Command::GetStatus => Reply::Status(self.status(stats)),
            Command::SetTelemetry(config) => {
                self.telemetry = config.enabled.then_some((link, config.decimation.max(1)));
                self.telemetry_countdown = 0;
                Reply::Ack
            }
            Command::ClearFaults => {
                self.faults = FaultFlags::NONE;
                Reply::Ack
            }
            Command::GetLimits => Reply::Limits(self.limits),
        }
    }

    /// Arms (if not armed yet) and opens a new controlling session, numbered
    /// above the previous one and at least the uptime in ms (so a host left
    /// over from before a reset is unlikely to hold the new number).
    fn arm(&mut self, now_us: u64) -> Reply {
        if !self.armed {
            self.armed = true;
            self.controller.reset();
            self.monitor = FaultMonitor::new();
            self.link_lost = false;
        }
        let uptime_ms = (self.now_us.max(now_us) / 1000) as u32;
        self.session = self.session.wrapping_add(1).max(uptime_ms);
        self.last_heartbeat_us = self.now_us.max(now_us);
        Reply::Armed {
            session: self.session,
        }
    }

    fn begin_save(&mut self, seq: u16) -> Handled {
        let reply = |reason| {
            Handled::Reply(DeviceMessage::Response(Response {
                seq,
                reply: Reply::Nack(reason),
            }))
        };
        if self.armed {
            // A flash erase stalls the CPU for seconds: never while driving.
            return reply(NackReason::Armed);
        }
        if self.saving {
            return reply(NackReason::Busy);
        }
        self.saving = true;
        Handled::Save {
            seq,
            record: StoredState::new(self.profile.clone(), self.params.to_list()),
        }
    }

    /// Ends a save started by [`Handled::Save`]; returns the answer to send.
    pub fn save_finished(&mut self, seq: u16, ok: bool) -> DeviceMessage {
        self.saving = false;
        let reply = if ok {
            Reply::Ack
        } else {
            self.faults = self.faults.union(FaultFlags::STORAGE);
            Reply::Nack(NackReason::Storage)
        };
        DeviceMessage::Response(Response { seq, reply })
    }

    /// Forgets the handshake of `link` (cable unplugged, port closed).
    pub fn link_closed(&mut self, link: LinkId) {
        self.sessions[link.index()].close();
        if self.telemetry_link() == Some(link) {
            self.telemetry = None;
        }
    }

    fn disarm(&mut self, reason: DisarmReason) {
        if self.armed {
            self.last_disarm = Some(reason);
        }
        self.armed = false;
        self.link_lost = false;
        self.generator.halt();
    }

    fn latch(&mut self, faults: FaultFlags) {
        self.faults = self.faults.union(faults);
    }

    /// One control period of `dt` seconds ending at `now_us`: failsafes,
    /// reference, control law, telemetry.
    pub fn step(&mut self, now_us: u64, dt: f32, m: &Measurement) -> Actuation {
        self.now_us = now_us;
        if self.armed {
            self.check_failsafes(m, dt);
        }
        let duty = if self.armed {
            let target = self.generator.waveform();
            let correcting = matches!(self.generator.mode(), Mode::Segment(_));
            let out = self
                .controller
                .step(&target, m, &self.params, dt, correcting);
            self.generator.advance(dt);
            self.last_output = Some(out);
            self.finish_ramps();
            if self.armed {
                out.duty
            } else {
                0.0
            }
        } else {
            self.last_output = None;
            0.0
        };
        self.last_duty = duty;
        Actuation {
            duty,
            bridge_enabled: self.armed,
            telemetry: self.telemetry_sample(m),
        }
    }

    fn check_failsafes(&mut self, m: &Measurement, dt: f32) {
        let sensed = self.monitor.check(m, self.last_duty, &self.params, dt);
        if sensed.contains(FaultFlags::ENCODER) {
            self.latch(sensed);
            self.disarm(DisarmReason::EncoderFault);
            return;
        }
        if sensed.contains(FaultFlags::OVER_CURRENT) {
            self.latch(sensed);
            self.disarm(DisarmReason::OverCurrent);
            return;
        }
        let timeout_us = (self.params.get(ParamId::LinkTimeout) * 1e6) as u64;
        let silent = self.now_us.saturating_sub(self.last_heartbeat_us) > timeout_us;
        if silent && !self.link_lost {
            self.latch(FaultFlags::LINK_LOSS);
            self.link_lost = true;
            if self.generator.is_active() {
                self.generator.stop_within_one_wingbeat();
            } else {
                self.disarm(DisarmReason::LinkLoss);
            }
        }
    }

    /// Disarms when a failsafe ramp or a profile ending in Stop has come to rest.
    fn finish_ramps(&mut self) {
        if self.generator.is_active() {
            return;
        }
        if self.link_lost {
            self.disarm(DisarmReason::LinkLoss);
        } else if self.generator.profile_ended() {
            self.disarm(DisarmReason::ProfileEnded);
        }
    }

    fn telemetry_sample(&mut self, m: &Measurement) -> Option<(LinkId, TelemetrySample)> {
        let (link, decimation) = self.telemetry?;
        if self.telemetry_countdown > 0 {
            self.telemetry_countdown -= 1;
            return None;
        }
        self.telemetry_countdown = decimation - 1;
        let seq = self.telemetry_seq;
        self.telemetry_seq = seq.wrapping_add(1);
        let commanded = self.last_output.map_or(0.0, |out| out.command.angle);
        // Estimates describe flapping; at rest there is none to report.
        let (amplitude, frequency) = if self.is_running() {
            (
                self.controller
                    .last_stroke()
                    .map_or(0.0, |s| s.measured_amplitude),
                self.controller.frequency_estimate(),
            )
        } else {
            (0.0, 0.0)
        };
        Some((
            link,
            TelemetrySample {
                seq,
                time_us: self.now_us,
                commanded_rad: commanded,
                measured_rad: m.angle_rad,
                duty: self.last_duty,
                current_a: m.current_a,
                amplitude_est_rad: amplitude,
                frequency_est_hz: frequency,
            },
        ))
    }
}

#[cfg(test)]
mod tests;
