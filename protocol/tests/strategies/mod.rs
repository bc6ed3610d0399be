//! proptest strategies for every wire type, shared by the protocol tests.
#![allow(dead_code)]

use fwav_protocol::*;
use proptest::collection::vec;
use proptest::prelude::*;

/// Any f32 bit pattern (NaN, infinities, subnormals) or, half the time, a
/// finite one.
pub fn float(finite_only: bool) -> BoxedStrategy<f32> {
    if finite_only {
        (-1e6f32..1e6).boxed()
    } else {
        prop_oneof![any::<f32>(), -1e6f32..1e6].boxed()
    }
}

pub fn segment(f: bool) -> impl Strategy<Value = Segment> {
    (float(f), float(f), float(f), float(f), float(f), float(f)).prop_map(
        |(frequency_hz, amplitude_rad, mean_rad, duration_s, ramp_s, downstroke_fraction)| {
            Segment {
                frequency_hz,
                amplitude_rad,
                mean_rad,
                duration_s,
                ramp_s,
                downstroke_fraction,
            }
        },
    )
}

pub fn end_action() -> impl Strategy<Value = EndAction> {
    prop_oneof![
        Just(EndAction::Hold),
        Just(EndAction::Repeat),
        Just(EndAction::Stop)
    ]
}

pub fn profile(f: bool) -> impl Strategy<Value = Profile> {
    (vec(segment(f), 0..=MAX_SEGMENTS), end_action()).prop_map(|(segs, on_end)| {
        Profile::from_segments(&segs, on_end).expect("at most MAX_SEGMENTS")
    })
}

pub fn limits(f: bool) -> impl Strategy<Value = Limits> {
    vec(float(f), 8).prop_map(|v| Limits {
        min_frequency_hz: v[0],
        max_frequency_hz: v[1],
        max_amplitude_rad: v[2],
        max_mean_rad: v[3],
        max_excursion_rad: v[4],
        max_angle_slew_rad_s: v[5],
        max_frequency_slew_hz_s: v[6],
        max_split_asymmetry: v[7],
    })
}

pub fn hello() -> impl Strategy<Value = Hello> {
    (any::<u16>(), any::<u64>()).prop_map(|(protocol_version, schema_hash)| Hello {
        protocol_version,
        schema_hash,
    })
}

pub fn param_id() -> impl Strategy<Value = ParamId> {
    (0..PARAMS.len()).prop_map(|i| PARAMS[i].id)
}

pub fn param_value(f: bool) -> impl Strategy<Value = ParamValue> {
    (param_id(), float(f)).prop_map(|(id, value)| ParamValue { id, value })
}

pub fn command(f: bool) -> impl Strategy<Value = Command> {
    prop_oneof![
        hello().prop_map(Command::Handshake),
        any::<u32>().prop_map(|nonce| Command::Ping { nonce }),
        profile(f).prop_map(Command::UploadProfile),
        Just(Command::ReadProfile),
        Just(Command::Arm),
        Just(Command::Disarm),
        Just(Command::Start),
        Just(Command::Stop),
        Just(Command::SaveProfile),
        Just(Command::GetParams),
        param_value(f).prop_map(Command::SetParam),
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

pub fn request(f: bool) -> impl Strategy<Value = Request> {
    (any::<u16>(), command(f)).prop_map(|(seq, command)| Request { seq, command })
}

pub fn link_stats() -> impl Strategy<Value = LinkStats> {
    vec(any::<u32>(), 5).prop_map(|v| LinkStats {
        frames_ok: v[0],
        overlong: v[1],
        malformed: v[2],
        crc_errors: v[3],
        decode_errors: v[4],
    })
}

pub fn disarm_reason() -> impl Strategy<Value = DisarmReason> {
    prop_oneof![
        Just(DisarmReason::Command),
        Just(DisarmReason::LinkLoss),
        Just(DisarmReason::EncoderFault),
        Just(DisarmReason::OverCurrent),
        Just(DisarmReason::UnderVoltage),
        Just(DisarmReason::ProfileEnded),
        Just(DisarmReason::Reset),
    ]
}

pub fn status() -> impl Strategy<Value = Status> {
    (
        any::<u64>(),
        any::<[bool; 3]>(),
        proptest::option::of(any::<u8>()),
        any::<u16>(),
        proptest::option::of(disarm_reason()),
        link_stats(),
    )
        .prop_map(
            |(uptime_ms, b, active_segment, faults, last_disarm, link)| Status {
                uptime_ms,
                armed: b[0],
                running: b[1],
                profile_loaded: b[2],
                active_segment,
                faults: FaultFlags(faults),
                last_disarm,
                link,
            },
        )
}

pub fn segment_field() -> impl Strategy<Value = SegmentField> {
    prop_oneof![
        Just(SegmentField::Frequency),
        Just(SegmentField::Amplitude),
        Just(SegmentField::Mean),
        Just(SegmentField::Duration),
        Just(SegmentField::Ramp),
        Just(SegmentField::DownstrokeFraction),
    ]
}

pub fn slew_quantity() -> impl Strategy<Value = SlewQuantity> {
    prop_oneof![
        Just(SlewQuantity::Amplitude),
        Just(SlewQuantity::Mean),
        Just(SlewQuantity::Frequency)
    ]
}

pub fn profile_error(f: bool) -> impl Strategy<Value = ProfileError> {
    let s = any::<u8>();
    prop_oneof![
        Just(ProfileError::Empty),
        (any::<u32>(), any::<u32>())
            .prop_map(|(count, max)| ProfileError::TooManySegments { count, max }),
        (s, segment_field())
            .prop_map(|(segment, field)| ProfileError::NotFinite { segment, field }),
        (s, float(f)).prop_map(|(segment, duration_s)| ProfileError::NonPositiveDuration {
            segment,
            duration_s
        }),
        (s, float(f), float(f)).prop_map(|(segment, ramp_s, duration_s)| {
            ProfileError::RampOutOfRange {
                segment,
                ramp_s,
                duration_s,
            }
        }),
        (s, float(f), float(f), float(f)).prop_map(|(segment, frequency_hz, min_hz, max_hz)| {
            ProfileError::FrequencyOutOfRange {
                segment,
                frequency_hz,
                min_hz,
                max_hz,
            }
        }),
        (s, float(f), float(f)).prop_map(|(segment, amplitude_rad, max_rad)| {
            ProfileError::AmplitudeOutOfRange {
                segment,
                amplitude_rad,
                max_rad,
            }
        }),
        (s, float(f), float(f)).prop_map(|(segment, mean_rad, max_rad)| {
            ProfileError::MeanOutOfRange {
                segment,
                mean_rad,
                max_rad,
            }
        }),
        (s, float(f), float(f)).prop_map(|(segment, excursion_rad, max_rad)| {
            ProfileError::ExcursionOutOfRange {
                segment,
                excursion_rad,
                max_rad,
            }
        }),
        (s, float(f), float(f)).prop_map(|(segment, downstroke_fraction, max_asymmetry)| {
            ProfileError::SplitCycleOutOfRange {
                segment,
                downstroke_fraction,
                max_asymmetry,
            }
        }),
        (s, slew_quantity(), float(f), float(f)).prop_map(|(segment, quantity, rate, max_rate)| {
            ProfileError::SlewTooFast {
                segment,
                quantity,
                rate,
                max_rate,
            }
        }),
    ]
}

pub fn nack(f: bool) -> impl Strategy<Value = NackReason> {
    prop_oneof![
        Just(NackReason::HandshakeRequired),
        profile_error(f).prop_map(NackReason::InvalidProfile),
        Just(NackReason::NoProfile),
        Just(NackReason::NotArmed),
        Just(NackReason::Armed),
        Just(NackReason::Running),
        any::<u16>().prop_map(|b| NackReason::Faulted(FaultFlags(b))),
        Just(NackReason::NotAtRest),
        (param_id(), float(f), float(f), float(f)).prop_map(|(id, value, min, max)| {
            NackReason::ParamOutOfRange {
                id,
                value,
                min,
                max,
            }
        }),
        Just(NackReason::Storage),
        Just(NackReason::Busy),
        Just(NackReason::Unsupported),
        Just(NackReason::OtherSession),
    ]
}

pub fn reply(f: bool) -> impl Strategy<Value = Reply> {
    prop_oneof![
        Just(Reply::Ack),
        nack(f).prop_map(Reply::Nack),
        any::<u32>().prop_map(|nonce| Reply::Pong { nonce }),
        proptest::option::of(profile(f)).prop_map(Reply::Profile),
        status().prop_map(Reply::Status),
        vec(param_value(f), 0..=MAX_PARAMS).prop_map(|v| Reply::Params(
            heapless::Vec::from_slice(&v).expect("at most MAX_PARAMS")
        )),
        limits(f).prop_map(Reply::Limits),
        any::<u32>().prop_map(|session| Reply::Armed { session }),
    ]
}

pub fn telemetry(f: bool) -> impl Strategy<Value = TelemetrySample> {
    (any::<u32>(), any::<u64>(), vec(float(f), 6)).prop_map(|(seq, time_us, v)| TelemetrySample {
        seq,
        time_us,
        commanded_rad: v[0],
        measured_rad: v[1],
        duty: v[2],
        current_a: v[3],
        amplitude_est_rad: v[4],
        frequency_est_hz: v[5],
    })
}

pub fn device_hello() -> impl Strategy<Value = DeviceHello> {
    (any::<u16>(), hello(), any::<bool>(), "[ -~]{0,32}").prop_map(
        |(seq, hello, accepted, name)| {
            let mut firmware = heapless::String::new();
            for c in name.chars() {
                let _ = firmware.push(c);
            }
            DeviceHello {
                seq,
                hello,
                accepted,
                firmware,
            }
        },
    )
}

pub fn device_message(f: bool) -> impl Strategy<Value = DeviceMessage> {
    prop_oneof![
        device_hello().prop_map(DeviceMessage::Hello),
        (any::<u16>(), reply(f))
            .prop_map(|(seq, reply)| DeviceMessage::Response(Response { seq, reply })),
        telemetry(f).prop_map(DeviceMessage::Telemetry),
    ]
}
