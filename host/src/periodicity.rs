//! When a cyclic result is periodic: the change of a cycle mean from the
//! cycle before, judged against the larger of the mean's size and the
//! quantity's swing over the last cycle, so that a near-zero mean does not
//! magnify it. The 2D cases of [`crate::aero2d`] and the 3D system
//! analysis of [`crate::aeroelastic`] are judged alike, on their CT.

/// Largest [`change_of_swing`] for which a result is periodic.
///
/// Measured: the 2D cases of `aero2d`'s tests change by at most 5 % (h = 2,
/// k = 2 with leading-edge shedding; a NACA 9912 with its large steady
/// lift 3.8 %); the 3D system analysis (2026-12-07) of the built-in FWAV
/// by 0.4 %, of the coarse test wing (`configs/coarse.toml`) by 1.6 %, and
/// of the coarse wing at 20 Hz, +-40 deg, whose tip swung farther than its
/// span, by 20 %.
pub const PERIODIC_CHANGE: f64 = 0.1;

/// The change from `previous_mean` to `mean`, relative to the larger of
/// `|mean|` and the swing (largest less smallest) of `last`, the last
/// cycle's samples; 0 when the mean did not change.
pub fn change_of_swing(mean: f64, previous_mean: f64, last: &[f64]) -> f64 {
    let change = (mean - previous_mean).abs();
    if change == 0.0 {
        return 0.0;
    }
    let (low, high) = last
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| {
            (l.min(x), h.max(x))
        });
    change / mean.abs().max(high - low)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against the mean's size, or against the swing where the mean is
    /// near zero.
    #[test]
    fn the_change_is_judged_against_the_larger_of_size_and_swing() {
        assert_eq!(change_of_swing(1.0, 1.0, &[0.0, 2.0]), 0.0);
        assert!((change_of_swing(10.0, 9.0, &[9.0, 11.0]) - 0.1).abs() < 1e-15);
        assert!((change_of_swing(0.01, -0.01, &[-1.0, 1.0]) - 0.01).abs() < 1e-15);
    }
}
