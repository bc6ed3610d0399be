//! Golden frames: one frame of every message kind, byte for byte.
//!
//! A change to the wire format makes this test fail: that is its purpose. If
//! the change is intended, the schema hash has changed too (the handshake will
//! refuse old peers); update the vectors *and* say so in the commit message.
//!
//! Provenance: `handshake`, `ping` and `hello` were derived independently of
//! this crate, from the postcard wire specification (varint integers, enum =
//! varint variant index, string = varint length + UTF-8) with a bit-by-bit
//! CRC-32C (reflected polynomial 0x82F63B78) and a COBS encoder written
//! separately (Cheshire & Baker, IEEE/ACM ToN 7(2), 1999). The others are
//! regression vectors produced by the encoder when the schema was fixed.
//! `handshake` and `hello` are FROZEN: every fwav version must read them.

mod golden_cases;

use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::*;

const REQUESTS: &[(&str, &str)] = &[
("handshake", "0002010f01ef9bafcdf8acd1910105ae401200"),
("ping", "000c0701f8acd19101d95678f500"),
("upload_profile", "000402020201073041920a063f01010101010320410103803f0101023f010b4841f366df3ec2b8b23d0103804001010b3f9a99193f022413baa900"),
("read_profile", "00070303bf2cd6d600"),
("arm", "000704041181717800"),
("disarm", "00070505659ab89900"),
("start", "0007060608c10fbe00"),
("stop", "0008ac0207f7e1075f00"),
("save_profile", "00070808a5ecace600"),
("get_params", "00070909d1f7650700"),
("set_param", "00040a0a0c0107a03f3daf055100"),
("get_status", "00070b0bc8b71bc100"),
("set_telemetry", "00090c0c010a4233ce1b00"),
("clear_faults", "00070d0d1201758e00"),
("get_limits", "0009ffff030e939ffe6900"),
("heartbeat", "000a0e0fc0c4073009e02d00"),
];

const DEVICE_MESSAGES: &[(&str, &str)] = &[
("hello", "00011f0101ef9bafcdf8acd19101010d667761762d666320302e312e3095bbb76600"),
("ack", "0003010405d850af8b00"),
("nack_invalid_profile", "0013010201010601f3665f3fdb0f493f929ccae900"),
("nack_faulted", "000a0106010605bbdc594000"),
("pong", "000d010702f8acd19101c338eebf00"),
("profile", "0006010303010201073041920a063f01010101010320410103803f0101023f010b4841f366df3ec2b8b23d0103804001010b3f9a99193f0277372ddf00"),
("no_profile", "0004010303059589eb4b00"),
("status", "000c010b04c0c4070101010101020106e807010203058cc464c100"),
("params", "0005010905020682a8fb360d0101063fa43c0af900"),
("limits", "000601ffff03060103803f0113a041db0f493fc2b8b23e920a863f920a863f010b2041cdcc4c3eb19b0c5c00"),
("telemetry", "0006024dc0843d0101063f48e1fa3e010b80becdcc4c3fb81e053f01073041cf5c506f00"),
("armed", "000b010407c0c407b9df899300"),
("nack_other_session", "0009010e010c0a7e232200"),
];

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

fn unhex(s: &str) -> Vec<u8> {
    (0..s.len())
        .step_by(2)
        .map(|i| u8::from_str_radix(&s[i..i + 2], 16).unwrap())
        .collect()
}

fn check<T>(cases: Vec<(&'static str, T)>, golden: &[(&str, &str)])
where
    T: serde::Serialize + serde::de::DeserializeOwned + PartialEq + std::fmt::Debug,
{
    assert_eq!(cases.len(), golden.len());
    for ((name, message), (golden_name, golden_hex)) in cases.into_iter().zip(golden) {
        assert_eq!(name, *golden_name);
        let frame = encode_frame_vec(&message).unwrap();
        assert_eq!(hex(&frame), *golden_hex, "wire format of `{name}` changed");
        // And the golden bytes decode to the message.
        let mut d = FrameDecoder::new();
        let decoded: Vec<T> = d.feed(&unhex(golden_hex)).map(|r| r.unwrap()).collect();
        assert_eq!(decoded, vec![message], "`{name}` does not decode");
    }
}

#[test]
fn request_frames_are_golden() {
    check(golden_cases::requests(), REQUESTS);
}

#[test]
fn device_message_frames_are_golden() {
    check(golden_cases::device_messages(), DEVICE_MESSAGES);
}

/// Every command and reply variant is covered above (a new variant must get
/// a golden vector).
#[test]
fn golden_vectors_cover_every_variant() {
    let commands: std::collections::BTreeSet<u8> = golden_cases::requests()
        .iter()
        .map(|(_, r)| postcard::to_allocvec(&r.command).unwrap()[0])
        .collect();
    // Command has 16 variants, indices 0..=15 (one byte of varint each).
    assert_eq!(commands, (0..16).collect());
    let replies: std::collections::BTreeSet<u8> = golden_cases::device_messages()
        .iter()
        .filter_map(|(_, m)| match m {
            DeviceMessage::Response(r) => Some(postcard::to_allocvec(&r.reply).unwrap()[0]),
            _ => None,
        })
        .collect();
    assert_eq!(replies, (0..8).collect());
}

/// CRC-32C check value (catalogue of parametrised CRC algorithms, "CRC-32/ISCSI").
#[test]
fn crc_is_crc32c() {
    let crc = crc::Crc::<u32>::new(&crc::CRC_32_ISCSI);
    assert_eq!(crc.checksum(b"123456789"), 0xe306_9283);
    // The ping frame's CRC, derived by hand in the module docs' provenance.
    assert_eq!(
        crc.checksum(&[0x07, 0x01, 0xf8, 0xac, 0xd1, 0x91, 0x01]),
        0xf578_56d9
    );
}
