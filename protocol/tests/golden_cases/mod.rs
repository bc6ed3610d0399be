//! The messages whose frames are pinned in golden.rs (one of each kind).
#![allow(dead_code)]

use fwav_protocol::*;

const DEG: f32 = core::f32::consts::PI / 180.0;

fn example_profile() -> Profile {
    Profile::from_segments(
        &[
            Segment::symmetric(11.0, 30.0 * DEG, 0.0, 10.0, 1.0),
            Segment {
                frequency_hz: 12.5,
                amplitude_rad: 25.0 * DEG,
                mean_rad: 5.0 * DEG,
                duration_s: 4.0,
                ramp_s: 0.5,
                downstroke_fraction: 0.6,
            },
        ],
        EndAction::Stop,
    )
    .unwrap()
}

/// A hello with a fixed hash, so the frozen handshake layout is pinned
/// independently of the current schema.
pub const FIXED_HELLO: Hello = Hello {
    protocol_version: 1,
    schema_hash: 0x0123_4567_89ab_cdef,
};

pub fn requests() -> Vec<(&'static str, Request)> {
    let r = |seq, command| Request { seq, command };
    vec![
        ("handshake", r(1, Command::Handshake(FIXED_HELLO))),
        ("ping", r(7, Command::Ping { nonce: 0x1234_5678 })),
        (
            "upload_profile",
            r(2, Command::UploadProfile(example_profile())),
        ),
        ("read_profile", r(3, Command::ReadProfile)),
        ("arm", r(4, Command::Arm)),
        ("disarm", r(5, Command::Disarm)),
        ("start", r(6, Command::Start)),
        ("stop", r(300, Command::Stop)),
        ("save_profile", r(8, Command::SaveProfile)),
        ("get_params", r(9, Command::GetParams)),
        (
            "set_param",
            r(
                10,
                Command::SetParam(ParamValue {
                    id: ParamId::CurrentLimit,
                    value: 1.25,
                }),
            ),
        ),
        ("get_status", r(11, Command::GetStatus)),
        (
            "set_telemetry",
            r(
                12,
                Command::SetTelemetry(TelemetryConfig {
                    enabled: true,
                    decimation: 10,
                }),
            ),
        ),
        ("clear_faults", r(13, Command::ClearFaults)),
        ("get_limits", r(u16::MAX, Command::GetLimits)),
        (
            "heartbeat",
            r(
                14,
                Command::Heartbeat {
                    session: 0x0001_e240,
                },
            ),
        ),
    ]
}

pub fn device_messages() -> Vec<(&'static str, DeviceMessage)> {
    let resp = |seq, reply| DeviceMessage::Response(Response { seq, reply });
    let firmware = heapless::String::try_from("fwav-fc 0.1.0").unwrap();
    let mut params = heapless::Vec::new();
    params
        .push(ParamValue {
            id: ParamId::WingInertia,
            value: 7.5e-6,
        })
        .unwrap();
    params
        .push(ParamValue {
            id: ParamId::LinkTimeout,
            value: 0.5,
        })
        .unwrap();
    vec![
        (
            "hello",
            DeviceMessage::Hello(DeviceHello {
                seq: 1,
                hello: FIXED_HELLO,
                accepted: true,
                firmware,
            }),
        ),
        ("ack", resp(4, Reply::Ack)),
        (
            "nack_invalid_profile",
            resp(
                2,
                Reply::Nack(NackReason::InvalidProfile(
                    ProfileError::AmplitudeOutOfRange {
                        segment: 1,
                        amplitude_rad: 50.0 * DEG,
                        max_rad: 45.0 * DEG,
                    },
                )),
            ),
        ),
        (
            "nack_faulted",
            resp(
                6,
                Reply::Nack(NackReason::Faulted(
                    FaultFlags::LINK_LOSS.union(FaultFlags::OVER_CURRENT),
                )),
            ),
        ),
        ("pong", resp(7, Reply::Pong { nonce: 0x1234_5678 })),
        ("profile", resp(3, Reply::Profile(Some(example_profile())))),
        ("no_profile", resp(3, Reply::Profile(None))),
        (
            "status",
            resp(
                11,
                Reply::Status(Status {
                    uptime_ms: 123_456,
                    armed: true,
                    running: true,
                    profile_loaded: true,
                    active_segment: Some(1),
                    faults: FaultFlags::NONE,
                    last_disarm: Some(DisarmReason::Command),
                    link: LinkStats {
                        frames_ok: 1000,
                        overlong: 1,
                        malformed: 2,
                        crc_errors: 3,
                        decode_errors: 0,
                    },
                }),
            ),
        ),
        ("params", resp(9, Reply::Params(params))),
        (
            "limits",
            resp(u16::MAX, Reply::Limits(Limits::REFERENCE_FWAV)),
        ),
        (
            "telemetry",
            DeviceMessage::Telemetry(TelemetrySample {
                seq: 77,
                time_us: 1_000_000,
                commanded_rad: 0.5,
                measured_rad: 0.49,
                duty: -0.25,
                current_a: 0.8,
                amplitude_est_rad: 0.52,
                frequency_est_hz: 11.0,
            }),
        ),
        (
            "armed",
            resp(
                4,
                Reply::Armed {
                    session: 0x0001_e240,
                },
            ),
        ),
        (
            "nack_other_session",
            resp(14, Reply::Nack(NackReason::OtherSession)),
        ),
    ]
}
