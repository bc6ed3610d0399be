//! Why a 2D case cannot be set up or run ([`CaseError`]): each variant
//! carries what was found and says what to change.

use fwav_settings::Shown;

use crate::aero2d::camber::CamberError;
use crate::aero2d::naca::{NacaError, PointsError};
use crate::aero2d::panel::{PanelError, ShapeError};
use crate::aero2d::viscous::ViscousError;

/// Why a case cannot be set up or run.
#[derive(Debug, thiserror::Error)]
pub enum CaseError {
    /// A section name that is neither `flat`, a NACA 4-digit name nor an
    /// existing point file.
    #[error("{name:?}: neither `flat`, a NACA 4-digit name ({naca}), nor an existing point file")]
    SectionName {
        /// The name given.
        name: String,
        /// Why it is not a NACA name.
        naca: NacaError,
    },
    /// A NACA section whose points cannot be made.
    #[error(transparent)]
    Naca(#[from] NacaError),
    /// A point file that cannot be read.
    #[error(transparent)]
    Points(#[from] PointsError),
    /// A contour the panel method cannot take.
    #[error(transparent)]
    Shape(#[from] ShapeError),
    /// A thin section's deformation that is not a camber history.
    #[error(transparent)]
    Camber(#[from] CamberError),
    /// The panel solver refused the section, settings or deformation.
    #[error(transparent)]
    Panel(#[from] PanelError),
    /// A deformation history without a sample.
    #[error(
        "the deformation history has no samples: give at least one (for `flat` the mid-lines \
         `fwav system-analysis --out` writes in section.json; for a thick section its whole \
         contour)"
    )]
    NoDeformationSamples,
    /// A thick section's deformation sample that is not the section's
    /// whole contour, point for point: the Navier–Stokes model would run
    /// the sample's shape, whatever `--section` said.
    #[error(
        "the deformation's sample {sample} has {found} points, but the section has {expected}: a \
         thick section's deformation gives its whole contour at each sample, point for point in \
         the section's order (a last point repeating the first is not counted); give the \
         samples' shape at rest as a point file to --section"
    )]
    ContourPoints {
        /// The sample, from 0.
        sample: usize,
        /// Its points.
        found: usize,
        /// The section's.
        expected: usize,
    },
    /// Leading-edge vortex shedding asked of the panel method or the
    /// viscous model.
    #[error("leading-edge vortex shedding (a critical LESP) applies to the thin-line model only")]
    LespOnThick,
    /// A run of a given duration asked of an inviscid model.
    #[error(
        "a run of a given duration (a body at rest in a stream, a sudden start) is the \
         Navier–Stokes model's; the inviscid models run whole periods of a motion: give cycles \
         instead, or choose the Navier–Stokes model"
    )]
    DurationNeedsNs,
    /// A duration out of range.
    #[error(
        "a duration of {} chords travelled: give more than 0 and at most {max} (a \
         cylinder's wake settles within about 100 diameters)",
        Shown(*.duration)
    )]
    Duration {
        /// The duration asked, chords travelled.
        duration: f64,
        /// The longest allowed ([`super::MAX_DURATION_CHORDS`]).
        max: f64,
    },
    /// A duration whose second half, which the report is of, would hold
    /// fewer than two load samples.
    #[error(
        "a duration of {} chords travelled leaves fewer than two load samples over its \
         second half, which is reported (a sample every {:.4} chords, a 200th of the motion's \
         period): give at least {}",
        Shown(*.duration),
        Shown(*.interval),
        rounded_up(*.min)
    )]
    DurationTooShort {
        /// The duration asked, chords travelled.
        duration: f64,
        /// The load samples' interval, chords travelled.
        interval: f64,
        /// The shortest duration that reports, chords travelled.
        min: f64,
    },
    /// The viscous model refused the case or failed.
    #[error(transparent)]
    Viscous(#[from] ViscousError),
    /// A NACA section thicker than the panel method can take (the
    /// message leaves the name to the caller, who gave it).
    #[error(
        "{thickness_percent}% thick; the panel method takes NACA sections up to \
         {max_percent}% (thicker ones blow up); choose a thinner section"
    )]
    TooThick {
        /// The name given.
        name: String,
        /// Its thickness, per cent of the chord.
        thickness_percent: f64,
        /// The thickest allowed, per cent of the chord.
        max_percent: f64,
    },
    /// A section file with too few points to resolve the section (the
    /// message leaves the file to the caller, who gave it).
    #[error(
        "{got} points; the panel method needs at least {min} to resolve a section \
         (with fewer its thrust is wrong, with 3 it blows up): give more points"
    )]
    TooFewPoints {
        /// The file.
        path: String,
        /// Points in it.
        got: usize,
        /// The fewest allowed.
        min: usize,
    },
    /// A case whose periods are so long that it would take too many steps.
    #[error(
        "reduced frequency {}: a period is {} chords travelled, so {cycles} cycles take \
         {} time steps of {dt} chords (at most {max} are allowed, a run's time growing \
         faster than its steps); use a reduced frequency of at least \
         {min_reduced_frequency:.3} or fewer cycles",
        Shown(*.reduced_frequency),
        Shown(.period.round()),
        Shown(*.steps)
    )]
    TooManySteps {
        /// The reduced frequency.
        reduced_frequency: f64,
        /// The period, chords travelled.
        period: f64,
        /// Cycles asked.
        cycles: u32,
        /// The time step, chords travelled.
        dt: f64,
        /// Steps the case would take (a real number: a reduced frequency
        /// of 1e-300 asks for some 1e303, beyond any integer type).
        steps: f64,
        /// The most allowed ([`super::MAX_STEPS`]).
        max: usize,
        /// The smallest reduced frequency that fits for these cycles.
        min_reduced_frequency: f64,
    },
    /// A Navier–Stokes case whose cycles travel farther than the model
    /// runs ([`super::MAX_DURATION_CHORDS`], as for a duration).
    #[error(
        "reduced frequency {}: a period is {} chords travelled, so {cycles} cycles are {} \
         chords, more than the Navier–Stokes model runs ({max}, as for --duration); use a \
         reduced frequency of at least {min_reduced_frequency:.3} or fewer cycles",
        Shown(*.reduced_frequency),
        Shown(.period.round()),
        Shown(.chords.round())
    )]
    TooLong {
        /// The reduced frequency.
        reduced_frequency: f64,
        /// The period, chords travelled.
        period: f64,
        /// Cycles asked.
        cycles: u32,
        /// Chords the cycles travel.
        chords: f64,
        /// The most allowed, chords travelled.
        max: f64,
        /// The smallest reduced frequency that fits for these cycles.
        min_reduced_frequency: f64,
    },
    /// The solution stopped being finite.
    #[error(
        "the solution diverged: {quantity} is not finite at t = {time:.3} chords travelled; \
         the section or its motion is beyond what the model can take (try a smaller \
         amplitude, a thinner or smoother section, or more section points)"
    )]
    NonFinite {
        /// The load that went non-finite.
        quantity: &'static str,
        /// When, chords travelled.
        time: f64,
    },
    /// A wake vortex far outside the region the flow can reach: the
    /// solution blew up.
    #[error(
        "the solution blew up: a wake vortex reached ({x:.0}, {y:.0}) chords, {distance:.0} \
         chords from the region the section sweeps (the domain of validity reaches \
         {reach:.0}); its loads are not reported. The section or its motion is beyond what \
         the model can take: try a smaller amplitude, a thinner or smoother section, or more \
         section points"
    )]
    WakeLeftDomain {
        /// The vortex's position, chords.
        x: f64,
        /// The vortex's position, chords.
        y: f64,
        /// Its distance from the swept region, chords.
        distance: f64,
        /// How far a vortex may be, chords.
        reach: f64,
    },
}

/// `x` rounded up to three significant digits, as a refusal shows a
/// least value: shown rounded down it would be refused again. In powers
/// of ten outside [1e-3, 1e6), as [`Shown`] writes (`3.15e298`, not 299
/// digits).
fn rounded_up(x: f64) -> String {
    if !(x.is_finite() && x > 0.0) {
        return Shown(x).to_string();
    }
    let exponent = x.log10().floor() as i32;
    let digits = 2 - exponent;
    if Shown(x).is_plain() {
        let scale = 10f64.powi(digits);
        let up = (x * scale).ceil() / scale;
        format!("{up:.*}", digits.max(0) as usize)
    } else {
        let mantissa = x / 10f64.powi(exponent);
        let up = (mantissa * 100.0).ceil() / 100.0;
        // 9.999e298 rounds up to 1.00e299, not 10.00e298.
        let (up, exponent) = if up >= 10.0 {
            (up / 10.0, exponent + 1)
        } else {
            (up, exponent)
        };
        format!("{up:.2}e{exponent}")
    }
}

#[cfg(test)]
mod tests {
    use super::rounded_up;

    /// Three significant digits, never below the value, and in powers of
    /// ten where plain decimals would be a line of digits.
    #[test]
    fn a_least_value_is_rounded_up_to_three_digits() {
        for (x, shown) in [
            (0.031416, "0.0315"),
            (157.08, "158"),
            (1570.8, "1580"),
            (1.5708e298, "1.58e298"),
            (9.9991e298, "1.00e299"),
            (2.5e-7, "2.50e-7"),
        ] {
            assert_eq!(rounded_up(x), shown, "{x:e}");
        }
    }
}
