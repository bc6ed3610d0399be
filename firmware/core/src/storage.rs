//! What the flight controller keeps in flash: the active profile and the
//! parameters, as one record with a format version, the schema hash of the
//! build that wrote it and a CRC (the record is stored as one link frame, so
//! it reuses the link's COBS + CRC-32C and its decoder).
//!
//! A record written by another build (different schema hash) or damaged is
//! refused rather than misread; the controller then boots with defaults.

use fwav_protocol::{
    encode_frame, EncodeError, FrameDecoder, ParamValue, Profile, MAX_PARAMS, SCHEMA_HASH,
};
use serde::{Deserialize, Serialize};

/// Version of the record layout.
pub const RECORD_VERSION: u16 = 1;

/// Largest encoded record, bytes (one frame).
pub const MAX_RECORD_LEN: usize = fwav_protocol::MAX_FRAME_LEN;

/// The stored state.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StoredState {
    /// [`RECORD_VERSION`] of the writer.
    pub version: u16,
    /// [`SCHEMA_HASH`] of the writer.
    pub schema_hash: u64,
    /// The active profile, if any.
    pub profile: Option<Profile>,
    /// Parameter values.
    pub params: heapless::Vec<ParamValue, MAX_PARAMS>,
}

/// Why a stored record was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum StorageError {
    /// Damaged: bad framing, CRC or content.
    #[error("stored record is damaged")]
    Damaged,
    /// Written by another firmware version.
    #[error("stored record is from another firmware version (record v{version}, schema {schema_hash:016x})")]
    OtherVersion {
        /// Its record version.
        version: u16,
        /// Its schema hash.
        schema_hash: u64,
    },
}

impl StoredState {
    /// A record of this build.
    pub fn new(profile: Option<Profile>, params: heapless::Vec<ParamValue, MAX_PARAMS>) -> Self {
        Self {
            version: RECORD_VERSION,
            schema_hash: SCHEMA_HASH,
            profile,
            params,
        }
    }

    /// Encodes into `buf`; returns the length.
    pub fn encode(&self, buf: &mut [u8]) -> Result<usize, EncodeError> {
        encode_frame(self, buf)
    }

    /// Decodes and checks a record read from flash.
    pub fn decode(bytes: &[u8]) -> Result<Self, StorageError> {
        let mut decoder = FrameDecoder::new();
        let mut found = None;
        for frame in decoder.feed::<StoredState>(bytes) {
            found = Some(frame.map_err(|_| StorageError::Damaged)?);
        }
        let record = found.ok_or(StorageError::Damaged)?;
        if record.version != RECORD_VERSION || record.schema_hash != SCHEMA_HASH {
            return Err(StorageError::OtherVersion {
                version: record.version,
                schema_hash: record.schema_hash,
            });
        }
        Ok(record)
    }
}
