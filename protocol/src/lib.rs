//! # fwav-protocol — the wire contract of the fwav link
//!
//! Everything that crosses the serial link between the `fwav` host program,
//! the flight controller and hil-sim is defined here, once, and compiled into
//! all three (the crate is `no_std`; the `std` feature adds the JSON profile
//! document and `Vec` helpers for the host).
//!
//! ## Layers
//! 1. **Messages** ([`message`]): a host sends a [`Request`] (sequence number +
//!    [`Command`]); the device answers with a [`DeviceMessage`]: a
//!    [`DeviceHello`] to a handshake, a [`Response`] (same sequence number,
//!    [`Reply`]: ack, typed nack, data) to anything else, and unsolicited
//!    [`TelemetrySample`]s while the stream is on.
//! 2. **Serialization**: [postcard](https://docs.rs/postcard) (compact, varint
//!    integers, `f32` little-endian, no allocation).
//! 3. **Framing** ([`frame`]): `0x00 ‖ COBS(postcard ‖ CRC-32C) ‖ 0x00`, at most
//!    [`MAX_FRAME_LEN`] bytes. A corrupt, truncated or over-long frame is
//!    dropped and counted in [`LinkStats`]; the decoder resynchronizes at the
//!    next `0x00`.
//! 4. **Handshake** ([`Hello`], [`DeviceHello`]): [`PROTOCOL_VERSION`] and
//!    [`SCHEMA_HASH`], a hash of the whole message schema computed at compile
//!    time from the types themselves, so a mismatched host and device refuse
//!    each other with a clear error instead of misreading bytes.
//!
//! ## Why a hand-written postcard protocol and not postcard-rpc
//! postcard-rpc 0.12 is the obvious candidate, but it pins
//! embassy-executor 0.9 / embassy-sync 0.7 and a tokio host, while the
//! firmware is on embassy-executor 0.10 / embassy-sync 0.8 and the host and
//! hil-sim are synchronous programs. The protocol here is small (one request
//! type, one response type), so we keep postcard and take postcard-rpc's good
//! ideas: a schema hash in the handshake, sequence numbers, typed errors and
//! in-process test channels. CRC and COBS come from the `crc` and `cobs`
//! crates that postcard itself uses, composed explicitly so that the decoder
//! can count *why* a frame was dropped (a user debugging a noisy radio link
//! wants to know whether it is CRC errors or over-long frames).
//!
//! ## Compatibility rules (postcard is not self-describing)
//! - The envelope ([`Request`] = `seq`, then [`Command`];
//!   [`DeviceMessage`] variant 0 = [`DeviceHello`]) and the handshake payloads
//!   [`Hello`] / [`DeviceHello`] are **frozen forever**: every version of
//!   fwav can read another version's handshake and report the mismatch.
//! - Everything else may change, but then [`SCHEMA_HASH`] changes with it
//!   (automatically) and the handshake refuses the peer. Only append enum
//!   variants; never reorder; never use `skip_serializing_if`.
//! - A wire change shows up as a change of the golden vectors in
//!   `tests/golden.rs`.
//!
//! ## Units
//! SI and radians on the wire and in code; degrees only in the JSON profile
//! document a person writes ([`document`], keys named `*_deg`).

#![cfg_attr(not(feature = "std"), no_std)]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

#[cfg(feature = "std")]
pub mod document;
pub mod frame;
pub mod limits;
pub mod message;
pub mod params;
pub mod profile;
pub mod schema;
pub mod status;

pub use frame::{
    encode_frame, frame_payload, EncodeError, FrameDecoder, FrameError, MAX_FRAME_LEN,
    MAX_PAYLOAD_LEN,
};
pub use limits::{Limits, ProfileError, SegmentField, SlewQuantity};
pub use message::{
    Command, DeviceHello, DeviceMessage, Hello, NackReason, Reply, Request, Response,
    VersionMismatch, FIRMWARE_NAME_LEN,
};
pub use params::{ParamId, ParamInfo, ParamValue, MAX_PARAMS, PARAMS};
pub use profile::{EndAction, Profile, Segment, MAX_SEGMENTS, RAMP_PEAK_RATE_FACTOR};
pub use schema::SCHEMA_HASH;
pub use status::{DisarmReason, FaultFlags, LinkStats, Status, TelemetryConfig, TelemetrySample};

/// Version of the fwav link protocol. Bumped by hand on a deliberate change of
/// meaning that the schema hash cannot see (e.g. a unit change of a field).
///
/// Version 2: only the arming session's [`Command::Heartbeat`] feeds the link
/// failsafe; in version 1 any frame (a status query from any client) did.
pub const PROTOCOL_VERSION: u16 = 2;
