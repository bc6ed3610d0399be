//! The messages: [`Request`] from host to device, [`DeviceMessage`] from
//! device to host.
//!
//! Every request carries a sequence number that the device echoes in its
//! [`Response`], so the host can match answers, retry a lost frame and drop a
//! late duplicate. The handshake ([`Hello`] → [`DeviceHello`]) sits at a
//! frozen position of both enums; see the crate docs for the rules.

use heapless::{String, Vec};
use postcard_schema::Schema;
use serde::{Deserialize, Serialize};

use crate::limits::{Limits, ProfileError};
use crate::params::{ParamId, ParamValue, MAX_PARAMS};
use crate::profile::Profile;
use crate::status::{FaultFlags, Status, TelemetryConfig, TelemetrySample};
use crate::{PROTOCOL_VERSION, SCHEMA_HASH};

/// Capacity of [`DeviceHello::firmware`], bytes.
pub const FIRMWARE_NAME_LEN: usize = 32;

/// The type of [`DeviceHello::firmware`].
pub type DeviceHelloName = String<FIRMWARE_NAME_LEN>;

/// Host → device: one command with its sequence number. **Frozen layout.**
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, Schema)]
pub struct Request {
    /// Chosen by the host, echoed by the device; wraps.
    pub seq: u16,
    /// What to do.
    pub command: Command,
}

/// The handshake payload of both sides' versions. **Frozen layout.**
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Schema)]
pub struct Hello {
    /// Sender's [`PROTOCOL_VERSION`].
    pub protocol_version: u16,
    /// Sender's [`SCHEMA_HASH`].
    pub schema_hash: u64,
}

impl Hello {
    /// The hello of this build.
    pub const THIS: Hello = Hello {
        protocol_version: PROTOCOL_VERSION,
        schema_hash: SCHEMA_HASH,
    };

    /// Ok if `peer` speaks exactly this build's protocol.
    pub fn check_peer(peer: &Hello) -> Result<(), VersionMismatch> {
        if *peer == Self::THIS {
            Ok(())
        } else {
            Err(VersionMismatch {
                ours: Self::THIS,
                theirs: *peer,
            })
        }
    }
}

/// Two peers speak different protocols.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "protocol mismatch: this side speaks version {} (schema {:016x}), the peer version {} (schema {:016x}); update the older of the two",
    ours.protocol_version, ours.schema_hash, theirs.protocol_version, theirs.schema_hash
)]
pub struct VersionMismatch {
    /// This side.
    pub ours: Hello,
    /// The other side.
    pub theirs: Hello,
}

/// A host command. Variant 0 ([`Command::Handshake`]) is frozen; append new
/// commands at the end.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, Schema)]
#[allow(
    clippy::large_enum_variant,
    reason = "no allocator on the device: messages are fixed-size values"
)]
pub enum Command {
    /// Open a session: the device answers [`DeviceMessage::Hello`] and, if the
    /// versions differ, refuses every other command.
    Handshake(Hello),
    /// Liveness check. It does not feed the link failsafe: only the arming
    /// session's [`Command::Heartbeat`] does.
    Ping {
        /// Echoed in [`Reply::Pong`].
        nonce: u32,
    },
    /// Replace the device's profile (validated by the device).
    UploadProfile(Profile),
    /// Read back the active profile: [`Reply::Profile`].
    ReadProfile,
    /// Enable the motor output (preconditions in the firmware). Answered
    /// with [`Reply::Armed`]: the session that now controls the device, whose
    /// heartbeats alone keep it armed. Arming an armed device at rest starts
    /// a new session; the previous one's heartbeats are then refused.
    Arm,
    /// Disable the motor output now.
    Disarm,
    /// Start flying the profile (requires armed and a valid profile).
    Start,
    /// Ramp the amplitude to zero and stop.
    Stop,
    /// Store the active profile and parameters in flash (requires disarmed).
    SaveProfile,
    /// Read all controller parameters: [`Reply::Params`].
    GetParams,
    /// Set one controller parameter.
    SetParam(ParamValue),
    /// Read the status: [`Reply::Status`].
    GetStatus,
    /// Start or stop the telemetry stream.
    SetTelemetry(TelemetryConfig),
    /// Clear latched faults whose cause is gone.
    ClearFaults,
    /// Read the device's kinematic limits: [`Reply::Limits`].
    GetLimits,
    /// The controlling session's heartbeat, the only traffic that feeds the
    /// link failsafe (with the [`Command::Arm`] that opened the session):
    /// acked for the session of the last arming, refused with
    /// [`NackReason::NotArmed`] while disarmed and
    /// [`NackReason::OtherSession`] for any other session. Read-only
    /// queries (status, ping, parameters, profile, limits) from any client
    /// never keep the device armed.
    Heartbeat {
        /// The session [`Reply::Armed`] returned.
        session: u32,
    },
}

/// Device → host. Variant 0 ([`DeviceMessage::Hello`]) is frozen.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, Schema)]
#[allow(
    clippy::large_enum_variant,
    reason = "no allocator on the device: messages are fixed-size values"
)]
pub enum DeviceMessage {
    /// Answer to [`Command::Handshake`].
    Hello(DeviceHello),
    /// Answer to any other command.
    Response(Response),
    /// Unsolicited telemetry.
    Telemetry(TelemetrySample),
}

/// The device's handshake answer. **Frozen layout.**
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize, Schema)]
pub struct DeviceHello {
    /// Sequence number of the handshake request.
    pub seq: u16,
    /// The device's version.
    pub hello: Hello,
    /// True if the device accepted the host's version.
    pub accepted: bool,
    /// Firmware name and version, for people.
    pub firmware: DeviceHelloName,
}

/// Answer to a command other than the handshake.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, Schema)]
pub struct Response {
    /// The request's sequence number.
    pub seq: u16,
    /// The answer.
    pub reply: Reply,
}

/// The content of a [`Response`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, Schema)]
pub enum Reply {
    /// Done.
    Ack,
    /// Refused, with the reason.
    Nack(NackReason),
    /// Answer to [`Command::Ping`].
    Pong {
        /// The ping's nonce.
        nonce: u32,
    },
    /// Answer to [`Command::ReadProfile`]; `None` if no profile is loaded.
    Profile(Option<Profile>),
    /// Answer to [`Command::GetStatus`].
    Status(Status),
    /// Answer to [`Command::GetParams`].
    Params(Vec<ParamValue, MAX_PARAMS>),
    /// Answer to [`Command::GetLimits`].
    Limits(Limits),
    /// Answer to [`Command::Arm`]: armed, controlled by this session.
    Armed {
        /// Send it in every [`Command::Heartbeat`].
        session: u32,
    },
}

/// Why the device refused a command.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, Schema, thiserror::Error)]
pub enum NackReason {
    /// No successful handshake on this link yet.
    #[error("no handshake yet: the device answers only after a matching handshake")]
    HandshakeRequired,
    /// The uploaded profile violates the device's limits.
    #[error("profile refused: {0}")]
    InvalidProfile(ProfileError),
    /// Start or read-back without a loaded profile.
    #[error("no profile is loaded")]
    NoProfile,
    /// Start while disarmed.
    #[error("the motor is not armed")]
    NotArmed,
    /// The command needs the motor disarmed (e.g. save to flash).
    #[error("the motor is armed: disarm first")]
    Armed,
    /// The command is not allowed while the profile runs.
    #[error("not allowed while running: stop first")]
    Running,
    /// Arm or start refused because of latched faults.
    #[error("faults are latched: {0}")]
    Faulted(FaultFlags),
    /// Arm refused because the amplitude command is not zero.
    #[error("arming needs the amplitude at zero")]
    NotAtRest,
    /// Parameter value outside its range.
    #[error(
        "parameter {} = {} is outside {}..={} {}",
        id.info().name,
        ShownValue(*value),
        ShownValue(*min),
        ShownValue(*max),
        id.info().unit
    )]
    ParamOutOfRange {
        /// Which parameter.
        id: ParamId,
        /// The refused value.
        value: f32,
        /// Smallest allowed value.
        min: f32,
        /// Largest allowed value.
        max: f32,
    },
    /// Flash storage failed.
    #[error("flash storage failed")]
    Storage,
    /// The device is busy (e.g. a flash write in progress).
    #[error("busy: try again")]
    Busy,
    /// This device does not implement the command.
    #[error("not supported by this device")]
    Unsupported,
    /// A heartbeat of a session that does not control the device (another
    /// client armed it since).
    #[error("another session armed the device: only the heartbeats of the client that armed it last keep it armed")]
    OtherSession,
}

/// A parameter's value as the messages show it: in plain decimals when
/// its magnitude is in `[1e-3, 1e6)` (or it is 0, infinite or NaN), in
/// powers of ten otherwise. `{}` of an `f32` writes the device's least
/// inertia, `1e-9`, as `0.000000001`. The host's messages follow the same
/// rule (`fwav_settings::Shown`, which allocates; this crate is `no_std`
/// without an allocator).
struct ShownValue(f32);

impl core::fmt::Display for ShownValue {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let x = self.0;
        if x == 0.0 || !x.is_finite() || (1e-3..1e6).contains(&x.abs()) {
            write!(f, "{x}")
        } else {
            write!(f, "{x:e}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A refused parameter is shown with its range in short form, as the
    /// host shows a declared range (`1e-9..=0.01`, not `0.000000001..=0.01`).
    #[test]
    fn a_refused_parameter_shows_its_range_in_short_form() {
        extern crate std;
        use std::string::ToString as _;
        let info = ParamId::WingInertia.info();
        let refused = NackReason::ParamOutOfRange {
            id: ParamId::WingInertia,
            value: 0.5,
            min: info.min(),
            max: info.max(),
        };
        assert_eq!(
            refused.to_string(),
            "parameter wing_inertia = 0.5 is outside 1e-9..=0.01 kg m^2"
        );
        let tiny = NackReason::ParamOutOfRange {
            id: ParamId::WingInertia,
            value: -2.5e-12,
            min: info.min(),
            max: info.max(),
        };
        assert!(tiny.to_string().contains("= -2.5e-12 is"), "{tiny}");
    }
}
