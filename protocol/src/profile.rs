//! The flapping kinematics the host uploads: a [`Profile`] of [`Segment`]s.
//!
//! The wing angle the flight controller follows within a segment is
//! `phi(t) = mean + amplitude * sin(theta(p))`, where the cycle phase `p`
//! advances at `frequency` and `theta` sweeps the downstroke (top to bottom)
//! in [`Segment::downstroke_fraction`] of the period and the upstroke in the
//! rest (0.5: the plain sinusoid). At the start of each segment the frequency,
//! amplitude, mean and split cycle move from the previous segment's values
//! (from rest, amplitude 0 and mean 0, for the first segment) to the new ones
//! over [`Segment::ramp_s`] along a cubic smoothstep `3x^2 - 2x^3`, so neither
//! the angle nor its rate jumps at a segment change; the phase stays
//! continuous. A smoothstep's peak rate is [`RAMP_PEAK_RATE_FACTOR`] times the
//! average change `delta / ramp_s`; validation checks that peak against the
//! slew limits. This is the harmonic leading-edge motion of the paper's
//! flapping kinematics (seed paper, "flapping motion ... harmonic"), with the
//! split-cycle ratio of direct-drive flapping controllers added as an option.

use heapless::Vec;
use postcard_schema::Schema;
use serde::{Deserialize, Serialize};

/// Peak rate of the cubic smoothstep ramp relative to its average rate
/// (`d/dx (3x^2 - 2x^3)` is 1.5 at `x = 1/2`).
pub const RAMP_PEAK_RATE_FACTOR: f32 = 1.5;

/// Maximum number of segments in one [`Profile`].
///
/// Part of the schema hash: a device built with another capacity refuses the
/// handshake rather than failing on a long profile later.
pub const MAX_SEGMENTS: usize = 16;

/// One piece of flapping kinematics, held for [`Segment::duration_s`].
///
/// All angles in radians, about the flapping axis, positive up.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, Schema)]
pub struct Segment {
    /// Flapping frequency, Hz (paper's initial design: 11 Hz).
    pub frequency_hz: f32,
    /// Peak flapping amplitude (half the stroke), rad.
    pub amplitude_rad: f32,
    /// Mean flapping angle (front view), rad.
    pub mean_rad: f32,
    /// Time the segment lasts, including its ramp, s.
    pub duration_s: f32,
    /// Time over which frequency, amplitude, mean and split cycle move
    /// (smoothstep) from the previous segment's values to this segment's, s.
    pub ramp_s: f32,
    /// Fraction of the period spent on the downstroke (split cycle); 0.5 is
    /// the symmetric sinusoid.
    pub downstroke_fraction: f32,
}

impl Segment {
    /// A symmetric segment (downstroke fraction 0.5).
    pub const fn symmetric(
        frequency_hz: f32,
        amplitude_rad: f32,
        mean_rad: f32,
        duration_s: f32,
        ramp_s: f32,
    ) -> Self {
        Self {
            frequency_hz,
            amplitude_rad,
            mean_rad,
            duration_s,
            ramp_s,
            downstroke_fraction: 0.5,
        }
    }
}

/// What the device does when the last segment's duration has elapsed.
///
/// In the JSON profile document it is written in snake case (`"hold"`); on the
/// wire it is the variant index, as for every enum.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize, Schema)]
#[serde(rename_all = "snake_case")]
pub enum EndAction {
    /// Keep flapping with the last segment's kinematics until stopped.
    #[default]
    Hold,
    /// Start again at the first segment (ramping from the last one).
    Repeat,
    /// Ramp the amplitude to zero at the slew limit and stop.
    Stop,
}

impl core::fmt::Display for EndAction {
    /// The name the JSON profile document uses (`hold`, `repeat`, `stop`).
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            EndAction::Hold => "hold",
            EndAction::Repeat => "repeat",
            EndAction::Stop => "stop",
        })
    }
}

/// The kinematic program uploaded to the flight controller.
///
/// Construct it freely; check it with [`Profile::validate`] against the
/// device's [`crate::Limits`] before use (the device does the same and refuses
/// an invalid profile with the [`crate::ProfileError`]).
#[derive(Clone, Debug, PartialEq, Default, Serialize, Deserialize, Schema)]
pub struct Profile {
    /// The segments, flown in order.
    pub segments: Vec<Segment, MAX_SEGMENTS>,
    /// What happens after the last segment.
    pub on_end: EndAction,
}

impl Profile {
    /// A profile from a slice of segments; `None` if there are more than
    /// [`MAX_SEGMENTS`].
    pub fn from_segments(segments: &[Segment], on_end: EndAction) -> Option<Self> {
        Some(Self {
            segments: Vec::from_slice(segments).ok()?,
            on_end,
        })
    }

    /// Total duration of one pass through the segments, s.
    pub fn duration_s(&self) -> f32 {
        self.segments.iter().map(|s| s.duration_s).sum()
    }
}
