//! Tests of the flight controller: refusals, failsafes, telemetry, storage.

use super::*;
use fwav_protocol::{EndAction, Hello, ParamValue, ProfileError, Segment, TelemetryConfig};
use proptest::prelude::*;

const DT: f32 = 1e-4;
const DT_US: u64 = 100;
const DEG: f32 = core::f32::consts::PI / 180.0;
const L: Limits = Limits::REFERENCE_FWAV;

/// A flight controller with a clock and a perfect plant (the wing follows
/// the command exactly), for testing the state machine.
struct Bench {
    fc: FlightController,
    now_us: u64,
    seq: u16,
    /// The session of the last arming.
    session: u32,
    angle: f32,
    current: f32,
}

impl Bench {
    fn new() -> Self {
        Self {
            fc: FlightController::new(L),
            now_us: 0,
            seq: 0,
            session: 0,
            angle: 0.0,
            current: 0.1,
        }
    }

    fn send(&mut self, link: LinkId, command: Command) -> Handled {
        self.seq = self.seq.wrapping_add(1);
        let request = Request {
            seq: self.seq,
            command,
        };
        self.fc
            .handle(link, request, self.now_us, LinkStats::default())
    }

    fn ask(&mut self, command: Command) -> Reply {
        match self.send(LinkId::Uart, command) {
            Handled::Reply(DeviceMessage::Response(r)) => {
                assert_eq!(r.seq, self.seq, "the answer echoes the sequence number");
                r.reply
            }
            other => panic!("unexpected {other:?}"),
        }
    }

    fn connect(&mut self) {
        match self.send(LinkId::Uart, Command::Handshake(Hello::THIS)) {
            Handled::Reply(DeviceMessage::Hello(h)) => assert!(h.accepted),
            other => panic!("{other:?}"),
        }
    }

    /// Runs `seconds` of control steps; returns the actuations.
    fn run(&mut self, seconds: f32) -> Vec<Actuation> {
        (0..(seconds / DT) as usize)
            .map(|_| {
                self.now_us += DT_US;
                let m = Measurement {
                    angle_rad: self.angle,
                    current_a: self.current,
                    supply_v: None,
                };
                let a = self.fc.step(self.now_us, DT, &m);
                if let Some(out) = self.fc.last_output {
                    self.angle = out.command.angle;
                }
                a
            })
            .collect()
    }

    /// Arms; keeps the session for the heartbeats.
    fn arm(&mut self) {
        match self.ask(Command::Arm) {
            Reply::Armed { session } => self.session = session,
            other => panic!("arming refused: {other:?}"),
        }
    }

    /// The controlling session's heartbeat.
    fn heartbeat(&mut self) -> Reply {
        self.ask(Command::Heartbeat {
            session: self.session,
        })
    }

    /// Runs with a heartbeat every 0.1 s (while the device is armed).
    fn run_with_heartbeat(&mut self, seconds: f32) -> Vec<Actuation> {
        let mut out = Vec::new();
        for _ in 0..(seconds / 0.1) as usize {
            let expected = if self.fc.is_armed() {
                Reply::Ack
            } else {
                Reply::Nack(NackReason::NotArmed)
            };
            assert_eq!(self.heartbeat(), expected);
            out.extend(self.run(0.1));
        }
        out
    }

    fn status(&mut self) -> Status {
        match self.ask(Command::GetStatus) {
            Reply::Status(s) => s,
            other => panic!("{other:?}"),
        }
    }
}

fn cruise() -> Profile {
    Profile::from_segments(
        &[Segment::symmetric(11.0, 30.0 * DEG, 0.0, 100.0, 0.75)],
        EndAction::Hold,
    )
    .unwrap()
}

/// Handshake, upload, arm, start.
fn flying() -> Bench {
    let mut b = Bench::new();
    b.connect();
    assert_eq!(b.ask(Command::UploadProfile(cruise())), Reply::Ack);
    b.arm();
    assert_eq!(b.ask(Command::Start), Reply::Ack);
    b
}

fn nack(r: Reply) -> NackReason {
    match r {
        Reply::Nack(reason) => reason,
        other => panic!("expected a nack, got {other:?}"),
    }
}

#[test]
fn every_refusal_reason() {
    let mut b = Bench::new();
    // Before any handshake.
    assert_eq!(nack(b.ask(Command::Arm)), NackReason::HandshakeRequired);
    b.connect();
    // Start: not armed, then no profile.
    assert_eq!(nack(b.ask(Command::Start)), NackReason::NotArmed);
    b.arm();
    assert_eq!(nack(b.ask(Command::Start)), NackReason::NoProfile);
    // An invalid profile, with its reason.
    let mut bad = cruise();
    bad.segments[0].amplitude_rad = 50.0 * DEG;
    assert!(matches!(
        nack(b.ask(Command::UploadProfile(bad))),
        NackReason::InvalidProfile(ProfileError::AmplitudeOutOfRange { segment: 0, .. })
    ));
    assert_eq!(
        b.ask(Command::ReadProfile),
        Reply::Profile(None),
        "a refused profile is not kept"
    );
    assert_eq!(b.ask(Command::UploadProfile(cruise())), Reply::Ack);
    // Save needs disarmed.
    assert_eq!(nack(b.ask(Command::SaveProfile)), NackReason::Armed);
    assert_eq!(b.ask(Command::Start), Reply::Ack);
    b.run_with_heartbeat(0.2);
    // While running: no upload, no second start, no re-arm.
    assert_eq!(
        nack(b.ask(Command::UploadProfile(cruise()))),
        NackReason::Running
    );
    assert_eq!(nack(b.ask(Command::Start)), NackReason::Running);
    assert_eq!(nack(b.ask(Command::Arm)), NackReason::NotAtRest);
    // Parameters out of range.
    let too_big = ParamValue {
        id: ParamId::CurrentLimit,
        value: 1e9,
    };
    assert!(matches!(
        nack(b.ask(Command::SetParam(too_big))),
        NackReason::ParamOutOfRange {
            id: ParamId::CurrentLimit,
            ..
        }
    ));
    // Disarm, then a save in progress blocks arming and a second save.
    assert_eq!(b.ask(Command::Disarm), Reply::Ack);
    assert!(matches!(
        b.send(LinkId::Uart, Command::SaveProfile),
        Handled::Save { .. }
    ));
    assert_eq!(nack(b.ask(Command::Arm)), NackReason::Busy);
    assert_eq!(nack(b.ask(Command::SaveProfile)), NackReason::Busy);
    // A failed save is a Storage nack and a latched fault, which blocks arming.
    let seq = b.seq;
    let answer = b.fc.save_finished(seq, false);
    assert_eq!(
        answer,
        DeviceMessage::Response(Response {
            seq,
            reply: Reply::Nack(NackReason::Storage)
        })
    );
    assert_eq!(
        nack(b.ask(Command::Arm)),
        NackReason::Faulted(FaultFlags::STORAGE)
    );
    assert_eq!(b.ask(Command::ClearFaults), Reply::Ack);
    b.arm();
}

#[test]
fn a_flight_follows_the_profile_and_reports_it() {
    let mut b = flying();
    let acts = b.run_with_heartbeat(2.0);
    assert!(acts
        .iter()
        .all(|a| a.bridge_enabled && (-1.0..=1.0).contains(&a.duty)));
    let s = b.status();
    assert!(s.armed && s.running && s.profile_loaded);
    assert_eq!(s.active_segment, Some(0));
    assert!(s.faults.is_empty());
    // The perfect plant reached the commanded amplitude.
    let stroke = b.fc.flapping().last_stroke().unwrap();
    assert!(
        (stroke.measured_amplitude - 30.0 * DEG).abs() < 1e-3,
        "{stroke:?}"
    );
    assert!((b.fc.flapping().frequency_estimate() - 11.0).abs() < 0.05);
    // Stop ramps to rest, stays armed.
    assert_eq!(b.ask(Command::Stop), Reply::Ack);
    b.run_with_heartbeat(1.0);
    let s = b.status();
    assert!(s.armed && !s.running);
    assert!(b.angle.abs() < 1e-3);
    assert_eq!(b.ask(Command::Disarm), Reply::Ack);
    assert_eq!(b.status().last_disarm, Some(DisarmReason::Command));
    assert!(!b
        .run(0.01)
        .iter()
        .any(|a| a.bridge_enabled || a.duty != 0.0));
}

#[test]
fn link_silence_ramps_to_rest_within_a_wingbeat_then_disarms() {
    let mut b = flying();
    b.run_with_heartbeat(2.0);
    let timeout = b.fc.params().get(ParamId::LinkTimeout);
    // The last heartbeat; then silence.
    assert_eq!(b.heartbeat(), Reply::Ack);
    let silence = b.run(timeout + 1.0 / 11.0 + 0.01);
    // Still driving until the timeout...
    let detect = (timeout / DT) as usize;
    assert!(silence[..detect - 1].iter().all(|a| a.bridge_enabled));
    // ...then at most one wingbeat (+2 steps) of ramp, then off.
    let off = silence
        .iter()
        .position(|a| !a.bridge_enabled)
        .expect("disarmed");
    let ramp_s = (off - detect) as f32 * DT;
    assert!(ramp_s <= 1.0 / 11.0 + 2.0 * DT, "ramp took {ramp_s} s");
    assert!(b.angle.abs() < 1e-3, "at rest: {}", b.angle);
    let s = b.status();
    assert!(!s.armed && s.faults.contains(FaultFlags::LINK_LOSS));
    assert_eq!(s.last_disarm, Some(DisarmReason::LinkLoss));
    // A fresh arm is needed, and the latched fault must be cleared first.
    assert_eq!(
        nack(b.ask(Command::Arm)),
        NackReason::Faulted(FaultFlags::LINK_LOSS)
    );
    assert_eq!(b.ask(Command::ClearFaults), Reply::Ack);
    b.arm();
}

#[test]
fn heartbeat_keeps_the_link_alive_and_silence_while_idle_disarms_at_once() {
    let mut b = flying();
    b.run_with_heartbeat(3.0);
    assert!(b.status().faults.is_empty());
    assert_eq!(b.ask(Command::Stop), Reply::Ack);
    b.run_with_heartbeat(1.0);
    let timeout = b.fc.params().get(ParamId::LinkTimeout);
    assert_eq!(b.heartbeat(), Reply::Ack);
    let acts = b.run(timeout + 0.01);
    let off = acts.iter().position(|a| !a.bridge_enabled).unwrap();
    assert!((off as f32 * DT - timeout).abs() < 2.0 * DT);
}

#[test]
fn a_dead_encoder_disarms_within_50_ms() {
    let mut b = flying();
    b.run_with_heartbeat(1.0);
    // The encoder stops counting; the controller drives harder and harder.
    let frozen = b.angle;
    let mut t_off = None;
    for i in 0..1000 {
        b.now_us += DT_US;
        let m = Measurement {
            angle_rad: frozen,
            current_a: 0.1,
            supply_v: None,
        };
        if !b.fc.step(b.now_us, DT, &m).bridge_enabled {
            t_off = Some(i as f32 * DT);
            break;
        }
    }
    let t = t_off.expect("disarmed");
    assert!(t < 0.05, "disarmed after {t} s");
    let s = b.status();
    assert!(s.faults.contains(FaultFlags::ENCODER));
    assert_eq!(s.last_disarm, Some(DisarmReason::EncoderFault));
}

#[test]
fn over_current_disarms() {
    let mut b = flying();
    b.run_with_heartbeat(0.5);
    b.current = 10.0;
    let acts = b.run(0.01);
    let off = acts.iter().position(|a| !a.bridge_enabled).unwrap();
    assert!(off < 5, "tripped after {off} samples");
    assert_eq!(b.status().last_disarm, Some(DisarmReason::OverCurrent));
    assert!(b.status().faults.contains(FaultFlags::OVER_CURRENT));
}

#[test]
fn profile_ending_in_stop_disarms() {
    let mut b = Bench::new();
    b.connect();
    let seg = Segment::symmetric(11.0, 20.0 * DEG, 0.0, 1.0, 0.5);
    let p = Profile::from_segments(&[seg], EndAction::Stop).unwrap();
    assert_eq!(b.ask(Command::UploadProfile(p)), Reply::Ack);
    b.arm();
    assert_eq!(b.ask(Command::Start), Reply::Ack);
    b.run_with_heartbeat(2.0);
    let s = b.status();
    assert!(!s.armed);
    assert_eq!(s.last_disarm, Some(DisarmReason::ProfileEnded));
    assert!(s.faults.is_empty());
    b.arm(); // re-arming works
    b.run_with_heartbeat(0.2);
    assert!(b.fc.is_armed(), "and does not disarm again by itself");
}

#[test]
fn telemetry_is_decimated_on_the_asking_link() {
    let mut b = flying();
    let on = TelemetryConfig {
        enabled: true,
        decimation: 50,
    };
    assert_eq!(b.ask(Command::SetTelemetry(on)), Reply::Ack);
    let acts = b.run_with_heartbeat(1.0);
    let samples: Vec<_> = acts.iter().filter_map(|a| a.telemetry).collect();
    assert_eq!(samples.len(), 10_000 / 50);
    assert!(samples.iter().all(|(link, _)| *link == LinkId::Uart));
    assert!(samples.windows(2).all(|w| w[1].1.seq == w[0].1.seq + 1));
    assert!(samples
        .windows(2)
        .all(|w| w[1].1.time_us - w[0].1.time_us == 50 * DT_US));
    assert!((samples.last().unwrap().1.frequency_est_hz - 11.0).abs() < 0.05);
    // At rest (stopped, still armed) there is no flapping to estimate.
    assert_eq!(b.ask(Command::Stop), Reply::Ack);
    let rest: Vec<_> = b
        .run_with_heartbeat(1.0)
        .iter()
        .filter_map(|a| a.telemetry)
        .collect();
    let last = rest.last().unwrap().1;
    assert_eq!((last.amplitude_est_rad, last.frequency_est_hz), (0.0, 0.0));
    let off = TelemetryConfig {
        enabled: false,
        decimation: 1,
    };
    assert_eq!(b.ask(Command::SetTelemetry(off)), Reply::Ack);
    assert!(b
        .run_with_heartbeat(0.2)
        .iter()
        .all(|a| a.telemetry.is_none()));
    // Closing the link stops its stream.
    assert_eq!(b.ask(Command::SetTelemetry(on)), Reply::Ack);
    b.fc.link_closed(LinkId::Uart);
    assert!(b.run(0.01).iter().all(|a| a.telemetry.is_none()));
}

#[test]
fn saved_state_restores_and_bad_records_are_refused() {
    let mut b = Bench::new();
    b.connect();
    assert_eq!(b.ask(Command::UploadProfile(cruise())), Reply::Ack);
    let gain = ParamValue {
        id: ParamId::AngleGain,
        value: 12.5,
    };
    assert_eq!(b.ask(Command::SetParam(gain)), Reply::Ack);
    let Handled::Save { seq, record } = b.send(LinkId::Uart, Command::SaveProfile) else {
        panic!()
    };
    let mut flash = [0xffu8; crate::storage::MAX_RECORD_LEN];
    let n = record.encode(&mut flash).unwrap();
    assert_eq!(
        b.fc.save_finished(seq, true),
        DeviceMessage::Response(Response {
            seq,
            reply: Reply::Ack
        })
    );

    let mut rebooted = FlightController::new(L);
    assert_eq!(rebooted.restore(&flash[..n]), Ok(()));
    assert_eq!(rebooted.profile, Some(cruise()));
    assert_eq!(rebooted.params().get(ParamId::AngleGain), 12.5);
    assert!(rebooted.faults().is_empty());

    // Damaged in flash.
    let mut damaged = flash;
    damaged[n / 2] ^= 0x40;
    let mut fc = FlightController::new(L);
    assert_eq!(
        fc.restore(&damaged[..n]),
        Err(RestoreError::Storage(StorageError::Damaged))
    );
    assert!(fc.faults().contains(FaultFlags::STORAGE));
    assert_eq!(fc.profile, None);
    // Erased flash.
    assert!(FlightController::new(L).restore(&[0xff; 64]).is_err());
    // A profile this device's limits refuse (e.g. a board with a smaller stop).
    let narrow = Limits {
        max_amplitude_rad: 20.0 * DEG,
        ..L
    };
    let mut fc = FlightController::new(narrow);
    assert!(matches!(
        fc.restore(&flash[..n]),
        Err(RestoreError::Profile(
            ProfileError::AmplitudeOutOfRange { .. }
        ))
    ));
    assert_eq!(fc.profile, None, "refused at boot");
}

#[test]
fn largest_record_fits() {
    let seg = Segment::symmetric(f32::MAX, f32::MAX, f32::MIN, f32::MAX, f32::MAX);
    let full =
        Profile::from_segments(&[seg; fwav_protocol::MAX_SEGMENTS], EndAction::Repeat).unwrap();
    let record = StoredState::new(Some(full), ParamSet::DEFAULT.to_list());
    let mut buf = [0u8; crate::storage::MAX_RECORD_LEN];
    let n = record.encode(&mut buf).unwrap();
    assert_eq!(StoredState::decode(&buf[..n]), Ok(record));
}

fn any_command() -> impl Strategy<Value = Command> {
    prop_oneof![
        Just(Command::Handshake(Hello::THIS)),
        any::<u32>().prop_map(|nonce| Command::Ping { nonce }),
        (
            0.5f32..25.0,
            0.0f32..1.0,
            -0.5f32..0.5,
            0.01f32..5.0,
            0.0f32..2.0
        )
            .prop_map(|(f, a, m, d, r)| {
                Command::UploadProfile(
                    Profile::from_segments(&[Segment::symmetric(f, a, m, d, r)], EndAction::Repeat)
                        .unwrap(),
                )
            }),
        Just(Command::UploadProfile(cruise())),
        Just(Command::ReadProfile),
        Just(Command::Arm),
        Just(Command::Arm),
        Just(Command::Disarm),
        Just(Command::Start),
        Just(Command::Start),
        Just(Command::Stop),
        Just(Command::SaveProfile),
        Just(Command::GetParams),
        (0..fwav_protocol::PARAMS.len(), any::<f32>()).prop_map(|(i, value)| Command::SetParam(
            ParamValue {
                id: fwav_protocol::PARAMS[i].id,
                value
            }
        )),
        Just(Command::GetStatus),
        (any::<bool>(), any::<u16>()).prop_map(|(enabled, decimation)| Command::SetTelemetry(
            TelemetryConfig {
                enabled,
                decimation
            }
        )),
        Just(Command::ClearFaults),
        Just(Command::GetLimits),
        any::<u32>().prop_map(|session| Command::Heartbeat { session }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// Any sequence of requests, on either link, interleaved with control
    /// steps fed arbitrary sensor values: no panic, duty always in [-1, 1],
    /// zero whenever the bridge is off.
    #[test]
    fn no_request_or_sensor_value_panics(
        script in proptest::collection::vec(
            (any::<bool>(), any_command(), 0usize..300, any::<f32>(), any::<f32>(), proptest::option::of(any::<f32>())),
            1..40,
        ),
    ) {
        let mut fc = FlightController::new(L);
        let mut now = 0u64;
        for (seq, (usb, command, steps, angle, current, supply)) in script.into_iter().enumerate() {
            let link = if usb { LinkId::Usb } else { LinkId::Uart };
            if let Handled::Save { seq, .. } = fc.handle(link, Request { seq: seq as u16, command }, now, LinkStats::default()) {
                fc.save_finished(seq, seq % 2 == 0);
            }
            for k in 0..steps {
                now += DT_US;
                // Mostly plausible readings, sometimes the arbitrary ones.
                let angle = if k % 7 == 0 { angle } else { 0.3 * libm::sinf(now as f32 * 1e-4) };
                let m = Measurement { angle_rad: angle, current_a: if k % 5 == 0 { current } else { 0.2 }, supply_v: supply };
                let a = fc.step(now, DT, &m);
                prop_assert!((-1.0..=1.0).contains(&a.duty), "duty {}", a.duty);
                prop_assert!(a.bridge_enabled || a.duty == 0.0);
            }
        }
    }
}

/// A retried request (same seq, its answer lost) is answered from the cache
/// and not executed twice: a second Start would otherwise be refused.
#[test]
fn retries_by_sequence_number_are_not_executed_twice() {
    let mut b = Bench::new();
    b.connect();
    assert_eq!(b.ask(Command::UploadProfile(cruise())), Reply::Ack);
    b.arm();
    assert_eq!(b.ask(Command::Start), Reply::Ack);
    let seq = b.seq;
    let again = b.fc.handle(
        LinkId::Uart,
        Request {
            seq,
            command: Command::Start,
        },
        b.now_us,
        LinkStats::default(),
    );
    assert_eq!(
        again,
        Handled::Reply(DeviceMessage::Response(Response {
            seq,
            reply: Reply::Ack
        }))
    );
    // A new request with a new seq is executed.
    assert_eq!(nack(b.ask(Command::Start)), NackReason::Running);
    // After a handshake the same seq is a new request again.
    b.connect();
    let fresh = b.fc.handle(
        LinkId::Uart,
        Request {
            seq: b.seq,
            command: Command::GetLimits,
        },
        b.now_us,
        LinkStats::default(),
    );
    assert!(matches!(
        fresh,
        Handled::Reply(DeviceMessage::Response(Response {
            reply: Reply::Limits(_),
            ..
        }))
    ));
}

/// The controlling client dies; a second client keeps reading (handshake,
/// limits, status, parameters, profile, ping) every 50 ms. Read-only traffic
/// does not feed the link failsafe: the wing is at rest and disarmed within
/// the link timeout and one wingbeat of the last heartbeat.
#[test]
fn read_only_traffic_from_another_client_does_not_keep_an_orphaned_wing_flying() {
    let mut b = flying();
    b.run_with_heartbeat(1.0);
    let timeout = b.fc.params().get(ParamId::LinkTimeout);
    let mut off_after = None;
    for k in 0..40u32 {
        b.connect();
        for command in [
            Command::GetLimits,
            Command::GetStatus,
            Command::GetParams,
            Command::ReadProfile,
            Command::Ping { nonce: k },
        ] {
            assert!(!matches!(b.ask(command), Reply::Nack(_)));
        }
        if !b.fc.is_armed() {
            off_after = Some(k as f32 * 0.05);
            break;
        }
        b.run(0.05);
    }
    let t = off_after.expect("still armed after 2 s of read-only polling");
    assert!(t <= timeout + 1.0 / 11.0 + 0.05, "disarmed after {t} s");
    assert!(b.angle.abs() < 1e-3, "at rest: {}", b.angle);
    let s = b.status();
    assert!(s.faults.contains(FaultFlags::LINK_LOSS), "{s:?}");
    assert_eq!(s.last_disarm, Some(DisarmReason::LinkLoss));
}

/// Only the session of the last arming feeds the failsafe: heartbeats with
/// another number are refused and do not keep the device armed; heartbeats
/// while disarmed are refused; a new arming at rest opens a new session and
/// the old one's heartbeats are refused from then on.
#[test]
fn only_the_arming_sessions_heartbeats_keep_the_device_armed() {
    let mut b = Bench::new();
    b.connect();
    assert_eq!(nack(b.heartbeat()), NackReason::NotArmed);
    b.arm();
    let first = b.session;
    let foreign = Command::Heartbeat {
        session: first.wrapping_add(1),
    };
    assert_eq!(nack(b.ask(foreign.clone())), NackReason::OtherSession);
    let mut acts = Vec::new();
    for _ in 0..5 {
        b.ask(foreign.clone());
        acts.extend(b.run(0.1));
    }
    let timeout = b.fc.params().get(ParamId::LinkTimeout);
    let off = acts
        .iter()
        .position(|a| !a.bridge_enabled)
        .expect("disarmed");
    assert!((off as f32 * DT - timeout).abs() < 2.0 * DT, "off at {off}");
    assert_eq!(b.status().last_disarm, Some(DisarmReason::LinkLoss));

    assert_eq!(b.ask(Command::ClearFaults), Reply::Ack);
    b.arm();
    let second = b.session;
    assert_ne!(second, first);
    b.arm();
    assert_ne!(b.session, second, "re-arming at rest opens a new session");
    assert_eq!(
        nack(b.ask(Command::Heartbeat { session: second })),
        NackReason::OtherSession
    );
    assert_eq!(b.heartbeat(), Reply::Ack);
    b.run_with_heartbeat(1.0);
    assert!(b.fc.is_armed());
}
