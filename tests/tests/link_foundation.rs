//! Host profile file → frames → flight-controller core (in hil-sim's virtual
//! flight controller) → frames → host, over a noisy in-process byte link.
//! (The pseudo-terminal version with the `fwav` link commands belongs to the
//! link-commands issue.)

use fwav::profile_file::ProfileFile;
use fwav_actuator::params::PlantParams;
use fwav_fc_core::flight::FlightController;
use fwav_hil_sim::sim::Simulator;
use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::*;

fn initial_design() -> ProfileFile {
    ProfileFile::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../host/profiles/initial-design.json"
    ))
    .expect("the shipped example profile loads")
}

fn frames(requests: &[(u16, Command)]) -> Vec<u8> {
    requests
        .iter()
        .flat_map(|(seq, command)| {
            encode_frame_vec(&Request {
                seq: *seq,
                command: command.clone(),
            })
            .unwrap()
        })
        .collect()
}

fn host_receive(decoder: &mut FrameDecoder, bytes: &[u8]) -> Vec<DeviceMessage> {
    decoder
        .feed(bytes)
        .map(|r| r.expect("device frames are valid"))
        .collect()
}

fn reply(message: &DeviceMessage) -> (u16, Reply) {
    match message {
        DeviceMessage::Response(Response { seq, reply }) => (*seq, reply.clone()),
        other => panic!("expected a response, got {other:?}"),
    }
}

#[test]
fn profile_file_reaches_the_flight_controller_through_noise() {
    let file = initial_design();
    let mut device = Simulator::new(&PlantParams::default());
    let mut host = FrameDecoder::new();

    // Line noise before the session, with zeros and a half frame in it.
    let mut wire = vec![0x13, 0x00, 0xff, 0x42, 0x00, 0x07];
    wire.extend(frames(&[(1, Command::Handshake(Hello::THIS))]));
    let upload = frames(&[(2, Command::UploadProfile(file.profile.clone()))]);
    wire.extend(&upload[..upload.len() / 2]); // cut by a glitch
    wire.extend(&upload); // the host's retry with the same seq
    wire.extend(frames(&[
        (3, Command::ReadProfile),
        (4, Command::SaveProfile),
    ]));

    // The UART delivers whatever chunk sizes it likes.
    let mut replies = Vec::new();
    for chunk in wire.chunks(7) {
        device.receive(chunk);
        let back = device.take_output();
        replies.extend(host_receive(&mut host, &back));
    }

    match &replies[0] {
        DeviceMessage::Hello(h) => {
            assert!(h.accepted);
            assert_eq!((h.seq, h.hello), (1, Hello::THIS));
            assert!(h.firmware.starts_with("fwav-fc "));
        }
        other => panic!("expected the handshake answer, got {other:?}"),
    }
    assert_eq!(reply(&replies[1]), (2, Reply::Ack));
    // Read back: exactly the file's profile, in radians.
    assert_eq!(
        reply(&replies[2]),
        (3, Reply::Profile(Some(file.profile.clone())))
    );
    assert_eq!(reply(&replies[3]), (4, Reply::Ack));
    assert_eq!(replies.len(), 4);
    let seg = file.profile.segments[0];
    assert_eq!(seg.frequency_hz, 11.0);
    assert!((seg.amplitude_rad - 30f32.to_radians()).abs() < 1e-6);

    // What was saved restores on a rebooted controller.
    let mut rebooted = FlightController::new(Limits::REFERENCE_FWAV);
    assert_eq!(rebooted.restore(&device.flash), Ok(()));

    // The noise and the cut frame were dropped and counted, nothing else.
    let stats = device.link_stats();
    assert_eq!(stats.frames_ok, 4); // handshake, upload (the retry), read-back, save
    assert!(stats.dropped() >= 2, "{stats:?}");
    assert_eq!(host.stats().dropped(), 0);
}

#[test]
fn a_host_of_another_version_cannot_drive_the_motor() {
    let mut device = Simulator::new(&PlantParams::default());
    let mut host = FrameDecoder::new();
    let stranger = Hello {
        protocol_version: PROTOCOL_VERSION + 1,
        schema_hash: 0xdead_beef,
    };
    let wire = frames(&[
        (1, Command::Handshake(stranger)),
        (2, Command::Arm),
        (3, Command::Start),
    ]);

    device.receive(&wire);
    let replies = host_receive(&mut host, &device.take_output());
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
            && mismatch.contains("00000000deadbeef")
    );
    for (i, seq) in [2u16, 3].into_iter().enumerate() {
        assert_eq!(
            reply(&replies[i + 1]),
            (seq, Reply::Nack(NackReason::HandshakeRequired))
        );
    }
    assert!(!device.fc.is_armed(), "nothing reached the controller");
}

#[test]
fn an_invalid_profile_is_refused_with_the_reason() {
    let mut device = Simulator::new(&PlantParams::default());
    let mut host = FrameDecoder::new();
    let mut profile = initial_design().profile;
    profile.segments[0].amplitude_rad = 50f32.to_radians();
    let wire = frames(&[
        (1, Command::Handshake(Hello::THIS)),
        (9, Command::UploadProfile(profile)),
    ]);
    device.receive(&wire);
    let replies = host_receive(&mut host, &device.take_output());
    match reply(&replies[1]) {
        (9, Reply::Nack(NackReason::InvalidProfile(e))) => {
            assert!(matches!(
                e,
                ProfileError::AmplitudeOutOfRange { segment: 0, .. }
            ));
            assert!(e.to_string().contains("50.00 deg"));
        }
        other => panic!("{other:?}"),
    }
}
