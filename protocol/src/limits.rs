//! What a flight controller can fly ([`Limits`]) and why a [`Profile`] is
//! refused ([`ProfileError`]).
//!
//! Every comparison is written so that a NaN on either side *fails* the check
//! (`!(value <= max)`), so a corrupted limit can never let a profile through.
#![allow(
    clippy::neg_cmp_op_on_partial_ord,
    reason = "negated comparisons are the NaN-rejecting form, on purpose"
)]

use postcard_schema::Schema;
use serde::{Deserialize, Serialize};

use crate::profile::{EndAction, Profile, Segment, MAX_SEGMENTS, RAMP_PEAK_RATE_FACTOR};

/// The envelope of kinematics a flight controller accepts.
///
/// Angles in rad, rates in rad/s, frequencies in Hz. The device reports its
/// own limits ([`crate::Command::GetLimits`]); the host checks a profile
/// against them before sending it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, Schema)]
pub struct Limits {
    /// Lowest flapping frequency, Hz (> 0: the phase must advance).
    pub min_frequency_hz: f32,
    /// Highest flapping frequency, Hz.
    pub max_frequency_hz: f32,
    /// Largest peak amplitude, rad.
    pub max_amplitude_rad: f32,
    /// Largest |mean angle|, rad.
    pub max_mean_rad: f32,
    /// Largest |mean| + amplitude (the mechanical stop), rad.
    pub max_excursion_rad: f32,
    /// Fastest change of amplitude or mean during a ramp (peak of the
    /// smoothstep), rad/s.
    pub max_angle_slew_rad_s: f32,
    /// Fastest change of frequency during a ramp (peak), Hz/s.
    pub max_frequency_slew_hz_s: f32,
    /// Largest |downstroke fraction - 0.5| (split-cycle asymmetry).
    pub max_split_asymmetry: f32,
}

impl Limits {
    /// Limits for the fwav reference vehicle: a ~15 cm FWAV flapping at about
    /// 11 Hz with a +-30 deg stroke (seed paper's initial design), with margin:
    /// 1–20 Hz, amplitude <= 45 deg, |mean| <= 20 deg, excursion <= 60 deg,
    /// 60 deg/s angle slew, 10 Hz/s frequency slew, split cycle 0.3–0.7.
    pub const REFERENCE_FWAV: Limits = Limits {
        min_frequency_hz: 1.0,
        max_frequency_hz: 20.0,
        max_amplitude_rad: 45.0 * DEG,
        max_mean_rad: 20.0 * DEG,
        max_excursion_rad: 60.0 * DEG,
        max_angle_slew_rad_s: 60.0 * DEG,
        max_frequency_slew_hz_s: 10.0,
        max_split_asymmetry: 0.2,
    };
}

impl Default for Limits {
    fn default() -> Self {
        Self::REFERENCE_FWAV
    }
}

const DEG: f32 = core::f32::consts::PI / 180.0;

/// A field of a [`Segment`], named in errors.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Schema)]
pub enum SegmentField {
    /// [`Segment::frequency_hz`]
    Frequency,
    /// [`Segment::amplitude_rad`]
    Amplitude,
    /// [`Segment::mean_rad`]
    Mean,
    /// [`Segment::duration_s`]
    Duration,
    /// [`Segment::ramp_s`]
    Ramp,
    /// [`Segment::downstroke_fraction`]
    DownstrokeFraction,
}

impl core::fmt::Display for SegmentField {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Self::Frequency => "frequency",
            Self::Amplitude => "amplitude",
            Self::Mean => "mean angle",
            Self::Duration => "duration",
            Self::Ramp => "ramp time",
            Self::DownstrokeFraction => "downstroke fraction",
        })
    }
}

/// A quantity whose rate of change is limited during a ramp.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Schema)]
pub enum SlewQuantity {
    /// Amplitude, rad/s.
    Amplitude,
    /// Mean angle, rad/s.
    Mean,
    /// Frequency, Hz/s.
    Frequency,
}

impl core::fmt::Display for SlewQuantity {
    /// The quantity as a person names it (`amplitude`, `mean angle`,
    /// `frequency`).
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            SlewQuantity::Amplitude => "amplitude",
            SlewQuantity::Mean => "mean angle",
            SlewQuantity::Frequency => "frequency",
        })
    }
}

/// Why a profile cannot be flown. Segment indices count from 0.
///
/// Values are carried in the units of the wire (rad, Hz, s); the `Display`
/// text converts angles to degrees because a person reads it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, Schema, thiserror::Error)]
pub enum ProfileError {
    /// The profile has no segment.
    #[error("the profile has no segment")]
    Empty,
    /// More segments than the device holds.
    #[error("the profile has {count} segments, the device holds at most {max}")]
    TooManySegments {
        /// Segments in the profile.
        count: u32,
        /// [`MAX_SEGMENTS`].
        max: u32,
    },
    /// A field is NaN or infinite as the wire's `f32` holds it (a
    /// profile file's 1e300 is finite in the file but not on the wire).
    #[error("segment {segment}: {field} is not a finite number (NaN, infinite, or beyond the link's 32-bit range of +-3.4e38)")]
    NotFinite {
        /// Segment index.
        segment: u8,
        /// The field.
        field: SegmentField,
    },
    /// Duration is zero or negative.
    #[error("segment {segment}: duration {duration_s} s must be positive")]
    NonPositiveDuration {
        /// Segment index.
        segment: u8,
        /// The duration, s.
        duration_s: f32,
    },
    /// Ramp time is negative or longer than the segment.
    #[error(
        "segment {segment}: ramp time {ramp_s} s must be between 0 and the duration {duration_s} s"
    )]
    RampOutOfRange {
        /// Segment index.
        segment: u8,
        /// The ramp time, s.
        ramp_s: f32,
        /// The segment's duration, s.
        duration_s: f32,
    },
    /// Frequency outside the device's range.
    #[error("segment {segment}: frequency {frequency_hz} Hz is outside the device range {min_hz}..={max_hz} Hz")]
    FrequencyOutOfRange {
        /// Segment index.
        segment: u8,
        /// The frequency, Hz.
        frequency_hz: f32,
        /// [`Limits::min_frequency_hz`].
        min_hz: f32,
        /// [`Limits::max_frequency_hz`].
        max_hz: f32,
    },
    /// Amplitude negative or over the limit.
    #[error("segment {segment}: amplitude {:.2} deg is outside 0..={:.2} deg", amplitude_rad.to_degrees(), max_rad.to_degrees())]
    AmplitudeOutOfRange {
        /// Segment index.
        segment: u8,
        /// The amplitude, rad.
        amplitude_rad: f32,
        /// [`Limits::max_amplitude_rad`].
        max_rad: f32,
    },
    /// |Mean angle| over the limit.
    #[error("segment {segment}: mean angle {:.2} deg exceeds +-{:.2} deg", mean_rad.to_degrees(), max_rad.to_degrees())]
    MeanOutOfRange {
        /// Segment index.
        segment: u8,
        /// The mean angle, rad.
        mean_rad: f32,
        /// [`Limits::max_mean_rad`].
        max_rad: f32,
    },
    /// |Mean| + amplitude beyond the mechanical stop.
    #[error("segment {segment}: |mean| + amplitude = {:.2} deg exceeds the stop at {:.2} deg", excursion_rad.to_degrees(), max_rad.to_degrees())]
    ExcursionOutOfRange {
        /// Segment index.
        segment: u8,
        /// |mean| + amplitude, rad.
        excursion_rad: f32,
        /// [`Limits::max_excursion_rad`].
        max_rad: f32,
    },
    /// Split cycle too asymmetric (or outside (0, 1)).
    #[error("segment {segment}: downstroke fraction {downstroke_fraction} is outside 0.5 +- {max_asymmetry}")]
    SplitCycleOutOfRange {
        /// Segment index.
        segment: u8,
        /// The downstroke fraction.
        downstroke_fraction: f32,
        /// [`Limits::max_split_asymmetry`].
        max_asymmetry: f32,
    },
    /// A ramp changes a quantity faster than the slew limit at its peak
    /// (`RAMP_PEAK_RATE_FACTOR * |change| / ramp_s`; a ramp time of zero with
    /// any change is infinitely fast).
    #[error("segment {segment}: the ramp changes the {quantity} at {} per s, the limit is {}", slew_display(*quantity, *rate), slew_display(*quantity, *max_rate))]
    SlewTooFast {
        /// Segment index (the segment whose ramp is too short).
        segment: u8,
        /// What changes too fast.
        quantity: SlewQuantity,
        /// The required rate (rad/s or Hz/s).
        rate: f32,
        /// The limit (rad/s or Hz/s).
        max_rate: f32,
    },
}

/// A slew value the way a person reads it: degrees for angles, Hz otherwise.
struct SlewDisplay(SlewQuantity, f32);

fn slew_display(quantity: SlewQuantity, value: f32) -> SlewDisplay {
    SlewDisplay(quantity, value)
}

impl core::fmt::Display for SlewDisplay {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.0 {
            SlewQuantity::Frequency => write!(f, "{:.3} Hz", self.1),
            SlewQuantity::Amplitude | SlewQuantity::Mean => {
                write!(f, "{:.2} deg", self.1.to_degrees())
            }
        }
    }
}

/// `value <= max`, false if either is NaN.
fn within(value: f32, max: f32) -> bool {
    value <= max
}

impl Profile {
    /// Checks the profile against `limits`; the first violation found, in
    /// segment order, is the error. See [`Profile::for_each_violation`] to see
    /// all of them.
    pub fn validate(&self, limits: &Limits) -> Result<(), ProfileError> {
        let mut first = None;
        self.for_each_violation(limits, |e| {
            if first.is_none() {
                first = Some(e);
            }
        });
        first.map_or(Ok(()), Err)
    }

    /// Calls `report` for every violation of `limits`, in segment order.
    pub fn for_each_violation(&self, limits: &Limits, mut report: impl FnMut(ProfileError)) {
        let n = self.segments.len();
        if n == 0 {
            report(ProfileError::Empty);
            return;
        }
        if n > MAX_SEGMENTS {
            report(ProfileError::TooManySegments {
                count: n as u32,
                max: MAX_SEGMENTS as u32,
            });
        }
        // The first segment ramps up from rest at its own frequency.
        let rest = Segment {
            amplitude_rad: 0.0,
            mean_rad: 0.0,
            ..self.segments[0]
        };
        let mut previous = rest;
        let mut all_finite = true;
        for (i, seg) in self.segments.iter().enumerate() {
            let index = i.min(u8::MAX as usize) as u8;
            let finite = check_segment(index, seg, limits, &mut report);
            // A slew computed from a NaN would only repeat the NotFinite error.
            if finite && is_finite(&previous) {
                check_slew(index, &previous, seg, limits, &mut report);
            }
            all_finite &= finite;
            previous = *seg;
        }
        if self.on_end == EndAction::Repeat && n > 1 && all_finite {
            // Wrapping around: the first segment now ramps from the last.
            check_slew(0, &previous, &self.segments[0], limits, &mut report);
        }
    }
}

fn fields(s: &Segment) -> [(SegmentField, f32); 6] {
    [
        (SegmentField::Frequency, s.frequency_hz),
        (SegmentField::Amplitude, s.amplitude_rad),
        (SegmentField::Mean, s.mean_rad),
        (SegmentField::Duration, s.duration_s),
        (SegmentField::Ramp, s.ramp_s),
        (SegmentField::DownstrokeFraction, s.downstroke_fraction),
    ]
}

fn is_finite(s: &Segment) -> bool {
    fields(s).iter().all(|(_, v)| v.is_finite())
}

/// Reports the violations of one segment's own fields; false if a field is
/// not finite (then nothing else about the segment is checked).
fn check_segment(
    segment: u8,
    s: &Segment,
    limits: &Limits,
    report: &mut impl FnMut(ProfileError),
) -> bool {
    let mut finite = true;
    for (field, value) in fields(s) {
        if !value.is_finite() {
            report(ProfileError::NotFinite { segment, field });
            finite = false;
        }
    }
    if !finite {
        return false;
    }
    if !(s.duration_s > 0.0) {
        report(ProfileError::NonPositiveDuration {
            segment,
            duration_s: s.duration_s,
        });
    }
    // Against a non-positive duration any ramp is "too long": said above once.
    if s.duration_s > 0.0 && !(s.ramp_s >= 0.0 && within(s.ramp_s, s.duration_s)) {
        report(ProfileError::RampOutOfRange {
            segment,
            ramp_s: s.ramp_s,
            duration_s: s.duration_s,
        });
    }
    if !(s.frequency_hz >= limits.min_frequency_hz
        && within(s.frequency_hz, limits.max_frequency_hz)
        && s.frequency_hz > 0.0)
    {
        report(ProfileError::FrequencyOutOfRange {
            segment,
            frequency_hz: s.frequency_hz,
            min_hz: limits.min_frequency_hz,
            max_hz: limits.max_frequency_hz,
        });
    }
    if !(s.amplitude_rad >= 0.0 && within(s.amplitude_rad, limits.max_amplitude_rad)) {
        report(ProfileError::AmplitudeOutOfRange {
            segment,
            amplitude_rad: s.amplitude_rad,
            max_rad: limits.max_amplitude_rad,
        });
    }
    if !within(s.mean_rad.abs(), limits.max_mean_rad) {
        report(ProfileError::MeanOutOfRange {
            segment,
            mean_rad: s.mean_rad,
            max_rad: limits.max_mean_rad,
        });
    }
    let excursion = s.mean_rad.abs() + s.amplitude_rad.abs();
    if !within(excursion, limits.max_excursion_rad) {
        report(ProfileError::ExcursionOutOfRange {
            segment,
            excursion_rad: excursion,
            max_rad: limits.max_excursion_rad,
        });
    }
    let asymmetry = (s.downstroke_fraction - 0.5).abs();
    // The fraction must stay strictly inside (0, 1) whatever the limit says.
    if !(within(asymmetry, limits.max_split_asymmetry) && asymmetry < 0.5) {
        report(ProfileError::SplitCycleOutOfRange {
            segment,
            downstroke_fraction: s.downstroke_fraction,
            max_asymmetry: limits.max_split_asymmetry,
        });
    }
    true
}

fn check_slew(
    segment: u8,
    from: &Segment,
    to: &Segment,
    limits: &Limits,
    report: &mut impl FnMut(ProfileError),
) {
    let changes = [
        (
            SlewQuantity::Amplitude,
            to.amplitude_rad - from.amplitude_rad,
            limits.max_angle_slew_rad_s,
        ),
        (
            SlewQuantity::Mean,
            to.mean_rad - from.mean_rad,
            limits.max_angle_slew_rad_s,
        ),
        (
            SlewQuantity::Frequency,
            to.frequency_hz - from.frequency_hz,
            limits.max_frequency_slew_hz_s,
        ),
    ];
    for (quantity, change, max_rate) in changes {
        if change == 0.0 {
            continue;
        }
        // Peak rate of the smoothstep; +inf for an instant step.
        let rate = RAMP_PEAK_RATE_FACTOR * change.abs() / to.ramp_s;
        if !within(rate, max_rate) {
            report(ProfileError::SlewTooFast {
                segment,
                quantity,
                rate,
                max_rate,
            });
        }
    }
}
