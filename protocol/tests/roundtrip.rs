//! Every message survives encode → frame → decode unchanged.

mod strategies;

use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::*;
use proptest::prelude::*;
use serde::{de::DeserializeOwned, Serialize};
use strategies::*;

/// Sends `message` through one frame and one fresh decoder.
fn through_the_wire<T: Serialize + DeserializeOwned>(message: &T) -> T {
    let frame = encode_frame_vec(message).expect("every message fits a frame");
    assert!(frame.len() <= MAX_FRAME_LEN);
    assert_eq!(frame[0], 0, "frames open with a delimiter");
    assert_eq!(*frame.last().unwrap(), 0, "frames close with a delimiter");
    assert!(
        !frame[1..frame.len() - 1].contains(&0),
        "COBS leaves no zero inside"
    );
    let mut decoder = FrameDecoder::new();
    let mut out: Vec<T> = decoder
        .feed(&frame)
        .map(|r| r.expect("valid frame"))
        .collect();
    assert_eq!(out.len(), 1);
    assert_eq!(decoder.stats().frames_ok, 1);
    assert_eq!(decoder.stats().dropped(), 0);
    out.remove(0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn requests_round_trip(req in request(true)) {
        prop_assert_eq!(through_the_wire(&req), req);
    }

    #[test]
    fn device_messages_round_trip(msg in device_message(true)) {
        prop_assert_eq!(through_the_wire(&msg), msg);
    }

    /// With NaN payloads `==` cannot compare, so compare the bytes of a second
    /// encoding: postcard writes f32 bit patterns verbatim.
    #[test]
    fn any_float_bits_round_trip(req in request(false), msg in device_message(false)) {
        let again = encode_frame_vec(&through_the_wire(&req)).unwrap();
        prop_assert_eq!(again, encode_frame_vec(&req).unwrap());
        let again = encode_frame_vec(&through_the_wire(&msg)).unwrap();
        prop_assert_eq!(again, encode_frame_vec(&msg).unwrap());
    }
}

/// The largest message of each kind fits in one frame.
#[test]
fn largest_messages_fit() {
    let seg = Segment::symmetric(f32::MAX, f32::MAX, f32::MIN, f32::MAX, f32::MAX);
    let full = Profile::from_segments(&[seg; MAX_SEGMENTS], EndAction::Repeat).unwrap();
    let req = Request {
        seq: u16::MAX,
        command: Command::UploadProfile(full.clone()),
    };
    assert_eq!(through_the_wire(&req), req);

    let reply = Reply::Profile(Some(full));
    let msg = DeviceMessage::Response(Response {
        seq: u16::MAX,
        reply,
    });
    assert_eq!(through_the_wire(&msg), msg);

    let params = (0..MAX_PARAMS)
        .map(|i| ParamValue {
            id: PARAMS[i % PARAMS.len()].id,
            value: f32::MAX,
        })
        .collect::<heapless::Vec<_, MAX_PARAMS>>();
    let msg = DeviceMessage::Response(Response {
        seq: u16::MAX,
        reply: Reply::Params(params),
    });
    assert_eq!(through_the_wire(&msg), msg);

    let firmware = heapless::String::try_from("x".repeat(FIRMWARE_NAME_LEN).as_str()).unwrap();
    let hello = Hello {
        protocol_version: u16::MAX,
        schema_hash: u64::MAX,
    };
    let msg = DeviceMessage::Hello(DeviceHello {
        seq: u16::MAX,
        hello,
        accepted: true,
        firmware,
    });
    assert_eq!(through_the_wire(&msg), msg);

    let status = Status {
        uptime_ms: u64::MAX,
        armed: true,
        running: true,
        profile_loaded: true,
        active_segment: Some(u8::MAX),
        faults: FaultFlags(u16::MAX),
        last_disarm: Some(DisarmReason::Reset),
        link: LinkStats {
            frames_ok: u32::MAX,
            overlong: u32::MAX,
            malformed: u32::MAX,
            crc_errors: u32::MAX,
            decode_errors: u32::MAX,
        },
    };
    let msg = DeviceMessage::Response(Response {
        seq: 1,
        reply: Reply::Status(status),
    });
    assert_eq!(through_the_wire(&msg), msg);
}

/// A message that cannot fit is an error, not a panic or a truncated frame.
#[test]
fn oversize_and_short_buffers_are_errors() {
    let big = [0xa5u8; MAX_PAYLOAD_LEN + 1];
    let mut out = [0u8; 2 * MAX_FRAME_LEN];
    // postcard writes a length prefix before the bytes: certainly too large.
    assert_eq!(
        encode_frame(&big.as_slice(), &mut out),
        Err(EncodeError::TooLarge)
    );

    let ping = Request {
        seq: 1,
        command: Command::Ping { nonce: 7 },
    };
    for len in 0..8 {
        let mut small = vec![0u8; len];
        assert!(
            matches!(
                encode_frame(&ping, &mut small),
                Err(EncodeError::BufferTooSmall { .. })
            ),
            "len {len}"
        );
    }
}
