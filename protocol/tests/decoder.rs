//! The frame decoder never panics, drops and counts bad frames, and
//! resynchronizes so that every valid frame is received.

mod strategies;

use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::*;
use proptest::collection::vec;
use proptest::prelude::*;
use strategies::*;

/// Feeds `bytes` in chunks of `chunk` (the UART/USB driver decides chunking,
/// not us) and collects the decoded requests.
fn decode_all(
    decoder: &mut FrameDecoder,
    bytes: &[u8],
    chunk: usize,
) -> Vec<Result<Request, FrameError>> {
    bytes
        .chunks(chunk.max(1))
        .flat_map(|c| decoder.feed(c).collect::<Vec<_>>())
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1024))]

    /// Arbitrary bytes: no panic, and no frame is ever accepted by accident
    /// that then fails to re-encode (a 32-bit CRC makes accidental acceptance
    /// astronomically rare; if it happens the message must still be valid).
    #[test]
    fn arbitrary_bytes_never_panic(bytes in vec(any::<u8>(), 0..4096), chunk in 1usize..600) {
        let mut decoder = FrameDecoder::new();
        for req in decode_all(&mut decoder, &bytes, chunk).into_iter().flatten() {
            prop_assert!(encode_frame_vec(&req).is_ok());
        }
        let s = decoder.stats();
        let zeros = bytes.iter().filter(|&&b| b == 0).count() as u32;
        prop_assert!(s.frames_ok + s.dropped() <= zeros, "at most one verdict per delimiter");
    }

    /// Valid frames spliced into random garbage (with or without zeros, with
    /// truncated copies of other frames) all come through, in order.
    #[test]
    fn valid_frames_survive_garbage(
        pieces in vec((vec(any::<u8>(), 0..700), request(true), 0usize..3), 1..12),
        chunk in 1usize..700,
    ) {
        let mut stream = Vec::new();
        let mut sent = Vec::new();
        for (garbage, req, mode) in &pieces {
            let frame = encode_frame_vec(req).unwrap();
            stream.extend_from_slice(garbage);
            if *mode == 1 {
                // A truncated copy (cut before its closing delimiter) just before.
                let cut = garbage.len() % frame.len().max(2);
                stream.extend_from_slice(&frame[..cut.max(1)]);
            }
            stream.extend_from_slice(&frame);
            sent.push(req.clone());
        }
        let mut decoder = FrameDecoder::new();
        let received: Vec<Request> = decode_all(&mut decoder, &stream, chunk)
            .into_iter()
            .filter_map(Result::ok)
            .collect();
        // Garbage may, with probability ~2^-32 per frame, decode as an extra
        // message; every sent one must be there, in order.
        let mut it = received.iter();
        for req in &sent {
            prop_assert!(it.any(|r| r == req), "lost a valid frame: {:?}", req);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4096))]

    /// Random bytes inside *valid* frames (good COBS and CRC) reach postcard's
    /// deserializer, which random frames almost never do: whatever the
    /// content, both receivers answer without panicking, and anything they
    /// accept is a well-formed message (e.g. a segment count over 16, a bad
    /// UTF-8 firmware name or an unknown variant is a Decode error).
    /// postcard accepts non-canonical varints (`81 00` for 1), so an accepted
    /// payload need not equal the canonical encoding; it is never shorter.
    #[test]
    fn any_payload_in_a_valid_frame_is_handled(payload in vec(any::<u8>(), 0..=MAX_PAYLOAD_LEN)) {
        let mut frame = vec![0u8; MAX_FRAME_LEN];
        let n = frame_payload(&payload, &mut frame).unwrap();
        let mut device = FrameDecoder::new();
        let got: Vec<Result<Request, FrameError>> = device.feed(&frame[..n]).collect();
        match got.as_slice() {
            [] => prop_assert!(payload.is_empty() || n == 0),
            [Ok(req)] => prop_assert!(well_formed(req, &payload)),
            [Err(e)] => prop_assert!(matches!(e, FrameError::Decode | FrameError::Malformed)),
            more => prop_assert!(false, "one frame, {} verdicts", more.len()),
        }
        let mut host = FrameDecoder::new();
        let got: Vec<Result<DeviceMessage, FrameError>> = host.feed(&frame[..n]).collect();
        if let [Ok(msg)] = got.as_slice() {
            prop_assert!(well_formed(msg, &payload));
        }
    }
}

/// `message`'s canonical encoding is no longer than what it was decoded from,
/// and survives encode → decode → encode unchanged (bytes, so NaNs compare).
fn well_formed<T: serde::Serialize + serde::de::DeserializeOwned>(
    message: &T,
    payload: &[u8],
) -> bool {
    let canonical = postcard::to_allocvec(message).unwrap();
    let again: T = postcard::from_bytes(&canonical).unwrap();
    canonical.len() <= payload.len() && postcard::to_allocvec(&again).unwrap() == canonical
}

/// Specific hostile payloads that a CRC-valid frame could carry.
#[test]
fn hostile_payloads_are_decode_errors() {
    // UploadProfile (seq 1, variant 2) claiming 17 segments.
    let mut too_many = vec![0x01, 0x02, 17];
    too_many.extend(std::iter::repeat_n(0x01, 17 * 24 + 1));
    // Handshake answer with a 200-byte firmware name (capacity 32).
    let mut long_name = vec![0x00, 0x01, 0x01, 0x01, 0x01, 200];
    long_name.extend(std::iter::repeat_n(b'a', 200));
    // Handshake answer with invalid UTF-8 in the firmware name.
    let bad_utf8 = vec![0x00, 0x01, 0x01, 0x01, 0x01, 0x02, 0xc3, 0x28];
    // A command index past the last variant.
    let unknown_command = vec![0x01, 0x7f];
    // A varint seq longer than u16.
    let huge_seq = vec![0xff, 0xff, 0xff, 0x7f, 0x01];

    let mut frame = vec![0u8; MAX_FRAME_LEN];
    for (name, payload) in [
        ("too_many", &too_many),
        ("unknown_command", &unknown_command),
        ("huge_seq", &huge_seq),
    ] {
        let n = frame_payload(payload, &mut frame).unwrap();
        let got: Vec<Result<Request, _>> = FrameDecoder::new().feed(&frame[..n]).collect();
        assert_eq!(got, vec![Err(FrameError::Decode)], "{name}");
    }
    for (name, payload) in [("long_name", &long_name), ("bad_utf8", &bad_utf8)] {
        let n = frame_payload(payload, &mut frame).unwrap();
        let got: Vec<Result<DeviceMessage, _>> = FrameDecoder::new().feed(&frame[..n]).collect();
        assert_eq!(got, vec![Err(FrameError::Decode)], "{name}");
    }
}

/// A frame of MAX_FRAME_LEN non-zero bytes and more is dropped as over-long,
/// counted once, and the next frame is received.
#[test]
fn overlong_frame_is_dropped_and_counted() {
    let ping = Request {
        seq: 9,
        command: Command::Ping { nonce: 42 },
    };
    let frame = encode_frame_vec(&ping).unwrap();
    for extra in [0usize, 1, 2, 1000] {
        let mut stream = vec![0u8];
        stream.extend(std::iter::repeat_n(0x55, MAX_FRAME_LEN - 2 + extra));
        stream.extend_from_slice(&frame);
        let mut d = FrameDecoder::new();
        let out = decode_all(&mut d, &stream, 64);
        let stats = d.stats();
        if extra == 0 {
            // Exactly a full body: not over-long, just not a valid frame.
            assert_eq!(stats.overlong, 0);
            assert_eq!(stats.dropped(), 1);
        } else {
            assert_eq!(stats.overlong, 1, "extra {extra}");
            assert_eq!(out[0], Err(FrameError::Overlong));
        }
        assert_eq!(out.last(), Some(&Ok(ping.clone())), "extra {extra}");
        assert_eq!(stats.frames_ok, 1);
    }
}

/// Each kind of damage is told apart in the counters.
#[test]
fn damage_is_classified() {
    let ping = Request {
        seq: 3,
        command: Command::Ping { nonce: 0xdead_beef },
    };
    let good = encode_frame_vec(&ping).unwrap();

    // A bit flip inside the body that keeps it zero-free: CRC error.
    let mut flipped = good.clone();
    let i = good.len() / 2;
    flipped[i] ^= if flipped[i] == 0x01 { 0x02 } else { 0x01 };
    assert!(!flipped[1..flipped.len() - 1].contains(&0));

    // A COBS code byte pointing past the end: malformed.
    let malformed = [0u8, 0x09, 1, 2, 0];
    // Too short to hold a CRC: malformed.
    let short = [0u8, 0x03, 1, 2, 0];
    // Valid framing and CRC around bytes that are not a Request: decode error.
    let not_a_request = encode_frame_vec(&(250u8, 250u8, 250u8)).unwrap();
    // A message followed by bytes it does not use: decode error too.
    let trailing = encode_frame_vec(&(ping.clone(), 7u8)).unwrap();

    let mut d = FrameDecoder::new();
    let mut stream = Vec::new();
    for part in [
        &flipped[..],
        &malformed,
        &short,
        &not_a_request,
        &trailing,
        &good,
    ] {
        stream.extend_from_slice(part);
    }
    let out = decode_all(&mut d, &stream, 5);
    assert_eq!(
        out,
        vec![
            Err(FrameError::Crc),
            Err(FrameError::Malformed),
            Err(FrameError::Malformed),
            Err(FrameError::Decode),
            Err(FrameError::Decode),
            Ok(ping)
        ]
    );
    let s = d.stats();
    assert_eq!(
        (
            s.crc_errors,
            s.malformed,
            s.decode_errors,
            s.frames_ok,
            s.overlong
        ),
        (1, 2, 2, 1, 0)
    );
}

/// A frame cut off mid-way by a reset, followed by a fresh frame.
#[test]
fn truncated_frame_then_valid_frame() {
    let a = Request {
        seq: 1,
        command: Command::GetStatus,
    };
    let b = Request {
        seq: 2,
        command: Command::Arm,
    };
    let fa = encode_frame_vec(&a).unwrap();
    let fb = encode_frame_vec(&b).unwrap();
    for cut in 1..fa.len() - 1 {
        let mut d = FrameDecoder::new();
        let mut stream = fa[..cut].to_vec();
        stream.extend_from_slice(&fb);
        let ok: Vec<Request> = decode_all(&mut d, &stream, 3)
            .into_iter()
            .filter_map(Result::ok)
            .collect();
        assert_eq!(ok, vec![b.clone()], "cut at {cut}");
    }
}

/// `reset` forgets a partial frame.
#[test]
fn reset_forgets_partial_frame() {
    let a = Request {
        seq: 1,
        command: Command::Start,
    };
    let fa = encode_frame_vec(&a).unwrap();
    let mut d = FrameDecoder::new();
    assert_eq!(d.feed::<Request>(&fa[..fa.len() - 1]).count(), 0);
    d.reset();
    assert_eq!(
        d.feed::<Request>(&[0]).count(),
        0,
        "nothing pending after reset"
    );
    assert_eq!(d.feed::<Request>(&fa).collect::<Vec<_>>(), vec![Ok(a)]);
}
