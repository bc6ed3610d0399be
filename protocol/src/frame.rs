//! Framing: `0x00 ‖ COBS(postcard(message) ‖ CRC-32C(le)) ‖ 0x00`.
//!
//! COBS removes every zero byte from the frame body, so `0x00` marks frame
//! boundaries unambiguously: after line noise, a reset or a half-sent frame the
//! receiver loses at most the frame in progress and picks up at the next
//! delimiter. The *leading* delimiter costs one byte and guarantees that
//! garbage before a frame is never glued to it. Consecutive delimiters
//! (empty frames) are ignored, so a sender may also send a lone `0x00` to
//! flush the receiver.
//!
//! CRC-32C (Castagnoli, `crc::CRC_32_ISCSI`) over the postcard bytes catches
//! what COBS cannot: flipped bits inside a body. The CRC is computed before
//! COBS encoding and checked after decoding.

use serde::{de::DeserializeOwned, Serialize};

use crate::status::LinkStats;

/// Largest frame on the wire, both delimiters included, bytes.
///
/// Fits a 16-segment profile with room to spare; small enough for a
/// statically allocated buffer on the microcontroller.
pub const MAX_FRAME_LEN: usize = 512;

/// Largest serialized message (before CRC and COBS), bytes.
pub const MAX_PAYLOAD_LEN: usize = 504;

const CRC_LEN: usize = 4;

/// Bytes between the two delimiters at most.
const MAX_BODY_LEN: usize = MAX_FRAME_LEN - 2;

const _: () = assert!(cobs::max_encoding_length(MAX_PAYLOAD_LEN + CRC_LEN) <= MAX_BODY_LEN);

/// CRC-32C: check value 0xe3069283 for "123456789" (Castagnoli 1993; the
/// `crc` catalogue's CRC_32_ISCSI).
pub(crate) const CRC32C: crc::Crc<u32> = crc::Crc::<u32>::new(&crc::CRC_32_ISCSI);

/// Why a message could not be framed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum EncodeError {
    /// The serialized message is longer than [`MAX_PAYLOAD_LEN`].
    #[error("message longer than the {MAX_PAYLOAD_LEN}-byte frame payload")]
    TooLarge,
    /// The output buffer cannot hold the frame.
    #[error("output buffer of {available} bytes is too small for the frame")]
    BufferTooSmall {
        /// Size of the buffer given, bytes.
        available: usize,
    },
}

/// Why a received frame was dropped (each is counted in [`LinkStats`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum FrameError {
    /// More than [`MAX_FRAME_LEN`] bytes before the next delimiter.
    #[error("frame longer than {MAX_FRAME_LEN} bytes")]
    Overlong,
    /// Not valid COBS, or too short to hold a CRC.
    #[error("malformed frame (bad COBS or shorter than its CRC)")]
    Malformed,
    /// The CRC does not match the content.
    #[error("CRC mismatch")]
    Crc,
    /// CRC good but the bytes are not a message of the expected type (or
    /// have bytes left over).
    #[error("frame content is not a valid message")]
    Decode,
}

/// Writes `message` as one frame into `out`; returns the frame's length.
///
/// Never panics: an over-long message or a short buffer is an error.
pub fn encode_frame<T: Serialize>(message: &T, out: &mut [u8]) -> Result<usize, EncodeError> {
    let mut raw = [0u8; MAX_PAYLOAD_LEN];
    let payload = postcard::to_slice(message, &mut raw).map_err(|_| EncodeError::TooLarge)?;
    frame_payload(payload, out)
}

/// Frames already-serialized bytes (CRC, COBS, delimiters) into `out`;
/// returns the frame's length. [`encode_frame`] is this after postcard; on its
/// own it serves fault injection (a well-framed message of wrong content).
pub fn frame_payload(payload: &[u8], out: &mut [u8]) -> Result<usize, EncodeError> {
    let n = payload.len();
    if n > MAX_PAYLOAD_LEN {
        return Err(EncodeError::TooLarge);
    }
    let mut raw = [0u8; MAX_PAYLOAD_LEN + CRC_LEN];
    raw[..n].copy_from_slice(payload);
    raw[n..n + CRC_LEN].copy_from_slice(&CRC32C.checksum(payload).to_le_bytes());

    let available = out.len();
    let too_small = EncodeError::BufferTooSmall { available };
    if available < 2 {
        return Err(too_small);
    }
    out[0] = 0;
    let body =
        cobs::try_encode(&raw[..n + CRC_LEN], &mut out[1..available - 1]).map_err(|_| too_small)?;
    out[1 + body] = 0;
    Ok(body + 2)
}

/// [`encode_frame`] into a new `Vec`.
#[cfg(feature = "std")]
pub fn encode_frame_vec<T: Serialize>(message: &T) -> Result<Vec<u8>, EncodeError> {
    let mut out = vec![0u8; MAX_FRAME_LEN];
    let n = encode_frame(message, &mut out)?;
    out.truncate(n);
    Ok(out)
}

/// Streaming frame receiver: push bytes as they arrive, get messages out.
///
/// Memory is one [`MAX_FRAME_LEN`] buffer; no allocation; every input byte
/// sequence is handled without panicking (property-tested).
pub struct FrameDecoder {
    buf: [u8; MAX_BODY_LEN],
    len: usize,
    /// Dropping an over-long frame until its end.
    overflowed: bool,
    stats: LinkStats,
}

impl Default for FrameDecoder {
    fn default() -> Self {
        Self::new()
    }
}

impl FrameDecoder {
    /// An empty decoder.
    pub const fn new() -> Self {
        Self {
            buf: [0; MAX_BODY_LEN],
            len: 0,
            overflowed: false,
            stats: LinkStats {
                frames_ok: 0,
                overlong: 0,
                malformed: 0,
                crc_errors: 0,
                decode_errors: 0,
            },
        }
    }

    /// Counters of received and dropped frames.
    pub fn stats(&self) -> LinkStats {
        self.stats
    }

    /// Forgets a partly received frame (e.g. when the port is reopened).
    pub fn reset(&mut self) {
        self.len = 0;
        self.overflowed = false;
    }

    /// Takes one byte; at a frame's closing delimiter returns the message or
    /// why the frame was dropped.
    pub fn push<T: DeserializeOwned>(&mut self, byte: u8) -> Option<Result<T, FrameError>> {
        if byte != 0 {
            if self.overflowed {
                return None;
            }
            if self.len == self.buf.len() {
                self.overflowed = true;
                self.len = 0;
                return None;
            }
            self.buf[self.len] = byte;
            self.len += 1;
            return None;
        }
        if self.overflowed {
            self.overflowed = false;
            self.stats.overlong = self.stats.overlong.wrapping_add(1);
            return Some(Err(FrameError::Overlong));
        }
        if self.len == 0 {
            return None;
        }
        let len = core::mem::take(&mut self.len);
        let result = decode_body(&mut self.buf[..len]);
        let counter = match result {
            Ok(_) => &mut self.stats.frames_ok,
            Err(FrameError::Overlong) => &mut self.stats.overlong,
            Err(FrameError::Malformed) => &mut self.stats.malformed,
            Err(FrameError::Crc) => &mut self.stats.crc_errors,
            Err(FrameError::Decode) => &mut self.stats.decode_errors,
        };
        *counter = counter.wrapping_add(1);
        Some(result)
    }

    /// Takes a chunk of bytes; iterates over the frames it completes.
    ///
    /// Bytes after the last delimiter stay buffered for the next call. Bytes
    /// not consumed because the iterator was dropped early are lost, so drain
    /// it.
    pub fn feed<'d, 'b, T: DeserializeOwned>(&'d mut self, bytes: &'b [u8]) -> Frames<'d, 'b, T> {
        Frames {
            decoder: self,
            bytes,
            _message: core::marker::PhantomData,
        }
    }
}

/// Iterator returned by [`FrameDecoder::feed`].
pub struct Frames<'d, 'b, T> {
    decoder: &'d mut FrameDecoder,
    bytes: &'b [u8],
    _message: core::marker::PhantomData<fn() -> T>,
}

impl<T: DeserializeOwned> Iterator for Frames<'_, '_, T> {
    type Item = Result<T, FrameError>;

    fn next(&mut self) -> Option<Self::Item> {
        while let Some((&byte, rest)) = self.bytes.split_first() {
            self.bytes = rest;
            if let Some(result) = self.decoder.push(byte) {
                return Some(result);
            }
        }
        None
    }
}

/// COBS-decodes `body` in place, checks the CRC, deserializes.
fn decode_body<T: DeserializeOwned>(body: &mut [u8]) -> Result<T, FrameError> {
    let n = cobs::decode_in_place(body).map_err(|_| FrameError::Malformed)?;
    if n <= CRC_LEN {
        return Err(FrameError::Malformed);
    }
    let (payload, crc) = body[..n].split_at(n - CRC_LEN);
    let mut crc_bytes = [0u8; CRC_LEN];
    crc_bytes.copy_from_slice(crc);
    if CRC32C.checksum(payload) != u32::from_le_bytes(crc_bytes) {
        return Err(FrameError::Crc);
    }
    match postcard::take_from_bytes::<T>(payload) {
        Ok((message, [])) => Ok(message),
        _ => Err(FrameError::Decode),
    }
}
