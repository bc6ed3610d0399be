//! Host profile file → frames → flight-controller core → frames → host, over
//! a noisy in-process byte link. (The pseudo-terminal version against hil-sim
//! belongs to the link-commands issue.)

use fwav::profile_file::ProfileFile;
use fwav_e2e::DeviceEnd;
use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::*;

fn initial_design() -> ProfileFile {
    ProfileFile::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../host/profiles/initial-design.json"
    ))
    .expect("the shipped example profile loads")
}

/// A stand-in controller: validates uploads against the reference limits, as
/// the firmware will, and acks.
fn controller(seq: u16, command: &Command) -> DeviceMessage {
    let reply = match command {
        Command::UploadProfile(p) => match p.validate(&Limits::REFERENCE_FWAV) {
            Ok(()) => Reply::Ack,
            Err(e) => Reply::Nack(NackReason::InvalidProfile(e)),
        },
        _ => Reply::Nack(NackReason::Unsupported),
    };
    DeviceMessage::Response(Response { seq, reply })
}

fn host_receive(decoder: &mut FrameDecoder, bytes: &[u8]) -> Vec<DeviceMessage> {
    decoder
        .feed(bytes)
        .map(|r| r.expect("device frames are valid"))
        .collect()
}

#[test]
fn profile_file_reaches_the_flight_controller_core_through_noise() {
    let file = initial_design();
    let mut device = DeviceEnd::default();
    let mut host = FrameDecoder::new();

    // Line noise before the session, with zeros and a half frame in it.
    let mut wire = vec![0x13, 0x00, 0xff, 0x42, 0x00, 0x07];
    let handshake = Request {
        seq: 1,
        command: Command::Handshake(Hello::THIS),
    };
    wire.extend(encode_frame_vec(&handshake).unwrap());
    let upload = Request {
        seq: 2,
        command: Command::UploadProfile(file.profile.clone()),
    };
    let upload_frame = encode_frame_vec(&upload).unwrap();
    wire.extend(&upload_frame[..upload_frame.len() / 2]); // cut by a glitch
    wire.extend(&upload_frame); // the host's retry with the same seq

    // The UART delivers whatever chunk sizes it likes.
    let mut replies = Vec::new();
    for chunk in wire.chunks(7) {
        let back = device.exchange(chunk, controller);
        replies.extend(host_receive(&mut host, &back));
    }

    match &replies[0] {
        DeviceMessage::Hello(h) => {
            assert!(h.accepted);
            assert_eq!(h.seq, 1);
            assert_eq!(h.hello, Hello::THIS);
            assert!(h.firmware.starts_with("fwav-fc "));
        }
        other => panic!("expected the handshake answer, got {other:?}"),
    }
    assert_eq!(
        replies[1],
        DeviceMessage::Response(Response {
            seq: 2,
            reply: Reply::Ack
        })
    );
    assert_eq!(replies.len(), 2);

    // The controller saw exactly the file's profile, in radians.
    assert_eq!(
        device.forwarded,
        vec![(2, Command::UploadProfile(file.profile.clone()))]
    );
    let seg = file.profile.segments[0];
    assert_eq!(seg.frequency_hz, 11.0);
    assert!((seg.amplitude_rad - 30f32.to_radians()).abs() < 1e-6);

    // The noise and the cut frame were dropped and counted, nothing else.
    let stats = device.link_stats();
    assert_eq!(stats.frames_ok, 2);
    assert!(stats.dropped() >= 2, "{stats:?}");
    assert_eq!(host.stats().dropped(), 0);
}

#[test]
fn a_host_of_another_version_cannot_drive_the_motor() {
    let mut device = DeviceEnd::default();
    let mut host = FrameDecoder::new();
    let stranger = Hello {
        protocol_version: PROTOCOL_VERSION + 1,
        schema_hash: 0xdead_beef,
    };
    let mut wire = encode_frame_vec(&Request {
        seq: 1,
        command: Command::Handshake(stranger),
    })
    .unwrap();
    wire.extend(
        encode_frame_vec(&Request {
            seq: 2,
            command: Command::Arm,
        })
        .unwrap(),
    );
    wire.extend(
        encode_frame_vec(&Request {
            seq: 3,
            command: Command::Start,
        })
        .unwrap(),
    );

    let replies = host_receive(&mut host, &device.exchange(&wire, controller));
    let DeviceMessage::Hello(h) = &replies[0] else {
        panic!("{:?}", replies[0])
    };
    assert!(!h.accepted);
    assert_eq!(h.hello, Hello::THIS, "the device tells its own version");
    // What the stranger reports to its user names both versions.
    let mismatch = VersionMismatch {
        ours: stranger,
        theirs: h.hello,
    }
    .to_string();
    assert!(
        mismatch.contains(&format!("{:016x}", SCHEMA_HASH))
            && mismatch.contains("00000000deadbeef"),
        "{mismatch}"
    );
    for (i, seq) in [2u16, 3].into_iter().enumerate() {
        assert_eq!(
            replies[i + 1],
            DeviceMessage::Response(Response {
                seq,
                reply: Reply::Nack(NackReason::HandshakeRequired)
            })
        );
    }
    assert!(
        device.forwarded.is_empty(),
        "nothing reached the controller"
    );
}

#[test]
fn an_invalid_profile_is_refused_with_the_reason() {
    let mut device = DeviceEnd::default();
    let mut host = FrameDecoder::new();
    let mut profile = initial_design().profile;
    profile.segments[0].amplitude_rad = 50f32.to_radians();
    let mut wire = encode_frame_vec(&Request {
        seq: 1,
        command: Command::Handshake(Hello::THIS),
    })
    .unwrap();
    wire.extend(
        encode_frame_vec(&Request {
            seq: 9,
            command: Command::UploadProfile(profile),
        })
        .unwrap(),
    );
    let replies = host_receive(&mut host, &device.exchange(&wire, controller));
    match &replies[1] {
        DeviceMessage::Response(Response {
            seq: 9,
            reply: Reply::Nack(NackReason::InvalidProfile(e)),
        }) => {
            assert!(matches!(
                e,
                ProfileError::AmplitudeOutOfRange { segment: 0, .. }
            ));
            assert!(e.to_string().contains("50.00 deg"));
        }
        other => panic!("{other:?}"),
    }
}
