//! What the device reports about itself: [`Status`], [`FaultFlags`],
//! [`LinkStats`] and the [`TelemetrySample`] stream.

use postcard_schema::Schema;
use serde::{Deserialize, Serialize};

/// Latched fault bits. A fault stays set until the host sends
/// [`crate::Command::ClearFaults`] and its cause is gone.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize, Schema)]
pub struct FaultFlags(pub u16);

impl FaultFlags {
    /// No heartbeat of the arming session within the link timeout while
    /// armed.
    pub const LINK_LOSS: Self = Self(1 << 0);
    /// Encoder silent while driven, or an impossible jump.
    pub const ENCODER: Self = Self(1 << 1);
    /// Motor current above the limit.
    pub const OVER_CURRENT: Self = Self(1 << 2);
    /// Supply voltage below the minimum.
    pub const UNDER_VOLTAGE: Self = Self(1 << 3);
    /// The watchdog reset the controller.
    pub const WATCHDOG_RESET: Self = Self(1 << 4);
    /// Reading or writing the stored profile or parameters failed.
    pub const STORAGE: Self = Self(1 << 5);
    /// The measured amplitude stayed far from the commanded one.
    pub const TRACKING: Self = Self(1 << 6);

    /// Every named fault with its name, for display.
    pub const NAMED: [(Self, &'static str); 7] = [
        (Self::LINK_LOSS, "link-loss"),
        (Self::ENCODER, "encoder"),
        (Self::OVER_CURRENT, "over-current"),
        (Self::UNDER_VOLTAGE, "under-voltage"),
        (Self::WATCHDOG_RESET, "watchdog-reset"),
        (Self::STORAGE, "storage"),
        (Self::TRACKING, "tracking"),
    ];

    /// No fault.
    pub const NONE: Self = Self(0);

    /// True if no bit is set.
    pub const fn is_empty(self) -> bool {
        self.0 == 0
    }
    /// True if every bit of `other` is set in `self`.
    pub const fn contains(self, other: Self) -> bool {
        self.0 & other.0 == other.0
    }
    /// `self` with the bits of `other` set.
    pub const fn union(self, other: Self) -> Self {
        Self(self.0 | other.0)
    }
    /// `self` with the bits of `other` cleared.
    pub const fn without(self, other: Self) -> Self {
        Self(self.0 & !other.0)
    }
}

impl core::fmt::Display for FaultFlags {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        if self.is_empty() {
            return f.write_str("none");
        }
        let mut rest = *self;
        let mut first = true;
        for (flag, name) in Self::NAMED {
            if self.contains(flag) {
                if !first {
                    f.write_str(",")?;
                }
                f.write_str(name)?;
                first = false;
                rest = rest.without(flag);
            }
        }
        if !rest.is_empty() {
            if !first {
                f.write_str(",")?;
            }
            write!(f, "unknown(0x{:04x})", rest.0)?;
        }
        Ok(())
    }
}

/// Why the motor was last disarmed; every disarm reports one.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Schema)]
pub enum DisarmReason {
    /// The host sent [`crate::Command::Disarm`].
    Command,
    /// No heartbeat of the arming session for longer than the link timeout.
    LinkLoss,
    /// Encoder fault.
    EncoderFault,
    /// Over-current.
    OverCurrent,
    /// Supply under-voltage.
    UnderVoltage,
    /// The profile ended with [`crate::EndAction::Stop`].
    ProfileEnded,
    /// The controller restarted (power-up or reset).
    Reset,
}

impl core::fmt::Display for DisarmReason {
    /// The reason as a person reads it (`link loss`, `over-current`).
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            DisarmReason::Command => "command",
            DisarmReason::LinkLoss => "link loss",
            DisarmReason::EncoderFault => "encoder fault",
            DisarmReason::OverCurrent => "over-current",
            DisarmReason::UnderVoltage => "under-voltage",
            DisarmReason::ProfileEnded => "profile ended",
            DisarmReason::Reset => "reset",
        })
    }
}

/// Counters of the frame decoder, wrapping at `u32::MAX`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize, Schema)]
pub struct LinkStats {
    /// Frames received and decoded.
    pub frames_ok: u32,
    /// Frames dropped for exceeding [`crate::MAX_FRAME_LEN`].
    pub overlong: u32,
    /// Frames dropped for invalid COBS or shorter than the CRC.
    pub malformed: u32,
    /// Frames dropped for a CRC mismatch.
    pub crc_errors: u32,
    /// Frames whose CRC matched but whose content is not a valid message.
    pub decode_errors: u32,
}

impl LinkStats {
    /// All dropped frames.
    pub fn dropped(&self) -> u32 {
        self.overlong
            .wrapping_add(self.malformed)
            .wrapping_add(self.crc_errors)
            .wrapping_add(self.decode_errors)
    }
}

/// The device's state, answer to [`crate::Command::GetStatus`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, Schema)]
pub struct Status {
    /// Time since the controller started, ms.
    pub uptime_ms: u64,
    /// Motor output enabled.
    pub armed: bool,
    /// Following the profile.
    pub running: bool,
    /// A valid profile is loaded.
    pub profile_loaded: bool,
    /// Index of the segment being flown, if running.
    pub active_segment: Option<u8>,
    /// Latched faults.
    pub faults: FaultFlags,
    /// Why the motor was last disarmed.
    pub last_disarm: Option<DisarmReason>,
    /// Frame decoder counters of the device's receiver.
    pub link: LinkStats,
}

/// Turns the telemetry stream on or off.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Schema)]
pub struct TelemetryConfig {
    /// Stream on.
    pub enabled: bool,
    /// Send one sample every `decimation` control steps (>= 1).
    pub decimation: u16,
}

/// One sample of the controller, sent unsolicited while telemetry is on.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, Schema)]
pub struct TelemetrySample {
    /// Sample counter (gaps show lost samples).
    pub seq: u32,
    /// Device time, us.
    pub time_us: u64,
    /// Reference flapping angle, rad.
    pub commanded_rad: f32,
    /// Measured flapping angle, rad.
    pub measured_rad: f32,
    /// H-bridge duty in [-1, 1].
    pub duty: f32,
    /// Motor current, A.
    pub current_a: f32,
    /// Flapping amplitude estimated over the last stroke, rad.
    pub amplitude_est_rad: f32,
    /// Flapping frequency estimated over the last stroke, Hz.
    pub frequency_est_hz: f32,
}
