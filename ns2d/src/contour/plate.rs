//! A thin plate or membrane modelled with a small finite thickness.
//!
//! The section is the band of thickness `t` round a mid-line: the two
//! surfaces are the mid-line offset by `±t/2` along its normal, closed at
//! each end by the semicircle of radius `t/2` centred on the mid-line's end
//! (tangent to both surfaces, so the contour has a continuous tangent; its
//! curvature jumps from the mid-line's to `2/t` there). The mid-line is
//! the natural cubic spline through the given samples, parametrised by
//! their chord length (a membrane's deformation comes as mid-line
//! samples). The offset is a simple curve only while the mid-line's
//! radius of curvature exceeds `t/2` everywhere; a tighter bend makes the
//! surfaces cross, which [`Contour::from_points`] reports.
//!
//! Points: cosine spacing along the mid-line's length on each surface
//! (fine towards the ends, where the conformal map crowds), one eighth of
//! them on each end.

use realfft::num_complex::Complex64;

use super::Contour;
use crate::error::NsError;
use crate::spline::CurveSpline;

impl Contour {
    /// The flat plate from `(0, 0)` to `(chord, 0)`, thickness
    /// `thickness`, semicircular ends, on `points` points (module docs of
    /// `contour/plate.rs`). Cost `O(points)`.
    ///
    /// # Errors
    /// As [`Contour::membrane`].
    pub fn flat_plate(chord: f64, thickness: f64, points: usize) -> Result<Self, NsError> {
        if !(chord.is_finite() && chord > 0.0) {
            return Err(NsError::BadSection {
                what: "plate chord",
                value: chord,
            });
        }
        Self::membrane(&[(0.0, 0.0), (chord, 0.0)], thickness, points)
    }

    /// The membrane of thickness `thickness` round the mid-line through
    /// `midline` `(x, y)` samples (from the leading to the trailing end, at
    /// least two), semicircular ends, on `points` points (module docs of
    /// `contour/plate.rs`). Cost `O(points log samples)`.
    ///
    /// # Errors
    /// [`NsError::BadSection`] for a thickness that is not positive or
    /// not below the mid-line's length, fewer than 32 points, fewer than
    /// two samples or repeated/non-finite ones; the [`Contour::from_points`]
    /// checks (a mid-line bent tighter than `t/2` crosses itself).
    pub fn membrane(
        midline: &[(f64, f64)],
        thickness: f64,
        points: usize,
    ) -> Result<Self, NsError> {
        if midline.len() < 2 {
            return Err(NsError::BadSection {
                what: "membrane's number of mid-line samples (at least 2)",
                value: midline.len() as f64,
            });
        }
        for (i, &(x, y)) in midline.iter().enumerate() {
            let repeated = i > 0 && (x, y) == midline[i - 1];
            if !(x.is_finite() && y.is_finite()) || repeated {
                return Err(NsError::BadSection {
                    what: "membrane mid-line sample (finite, distinct from the previous one)",
                    value: i as f64,
                });
            }
        }
        let mid: Vec<Complex64> = midline.iter().map(|&(x, y)| Complex64::new(x, y)).collect();
        let spline = CurveSpline::open(&mid);
        let length = spline.length();
        if !(thickness.is_finite() && thickness > 0.0 && thickness < length) {
            return Err(NsError::BadSection {
                what: "membrane thickness (0 < t < mid-line length)",
                value: thickness,
            });
        }
        if points < 32 {
            return Err(NsError::BadSection {
                what: "membrane's number of points (at least 32)",
                value: points as f64,
            });
        }
        let end = (points / 8).max(6);
        let per_side = (points - 2 * end) / 2 - 1;
        let half = 0.5 * thickness;
        // Point at mid-line parameter s offset by `side · t/2` along the
        // left normal (up for a mid-line running in +x).
        let offset = |s: f64, side: f64| {
            let (p, dp) = spline.eval(s);
            p + Complex64::i() * dp / dp.norm() * (side * half)
        };
        let cosine = |i: usize| {
            length * 0.5 * (1.0 - (std::f64::consts::PI * i as f64 / per_side as f64).cos())
        };
        let mut z = Vec::with_capacity(points);
        // Upper surface from the trailing end to the leading end, round
        // the leading end, lower surface back, round the trailing end:
        // counterclockwise for a mid-line running in +x.
        for i in (0..=per_side).rev() {
            z.push(offset(cosine(i), 1.0));
        }
        let (lead, lead_dir) = spline.eval(0.0);
        push_semicircle(
            &mut z,
            lead,
            Complex64::i() * lead_dir / lead_dir.norm(),
            half,
            end,
        );
        for i in 0..=per_side {
            z.push(offset(cosine(i), -1.0));
        }
        let (trail, trail_dir) = spline.eval(length);
        push_semicircle(
            &mut z,
            trail,
            -Complex64::i() * trail_dir / trail_dir.norm(),
            half,
            end,
        );
        let xy: Vec<(f64, f64)> = z.iter().map(|p| (p.re, p.im)).collect();
        Contour::from_points(&xy)
    }
}

/// The `count` interior points of the counterclockwise half circle of
/// radius `radius` round `centre` that starts in the unit direction
/// `start`.
fn push_semicircle(
    z: &mut Vec<Complex64>,
    centre: Complex64,
    start: Complex64,
    radius: f64,
    count: usize,
) {
    for i in 1..=count {
        let phi = std::f64::consts::PI * i as f64 / (count + 1) as f64;
        z.push(centre + start * Complex64::from_polar(radius, phi));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flat plate's area is the band's plus the two half discs,
    /// `c t + π t²/4`, to the polygon's inscribed error.
    #[test]
    fn the_flat_plate_has_its_area() {
        let (c, t) = (1.0, 0.02);
        let plate = Contour::flat_plate(c, t, 512).unwrap();
        let exact = c * t + std::f64::consts::PI * t * t / 4.0;
        assert!(
            (plate.area() - exact).abs() < 1e-4 * exact,
            "{} {exact}",
            plate.area()
        );
        assert_eq!(plate.len(), 512);
    }

    /// A mid-line bent tighter than half the thickness makes the lower
    /// surface fold over: refused as a crossing.
    #[test]
    fn a_too_tight_bend_crosses() {
        let midline: Vec<(f64, f64)> = (0..=40)
            .map(|k| {
                let phi = std::f64::consts::PI * f64::from(k) / 40.0;
                (0.05 * phi.cos(), 0.05 * phi.sin())
            })
            .collect();
        let r = Contour::membrane(&midline, 0.15, 256);
        assert!(matches!(r, Err(NsError::ContourCrossing { .. })), "{r:?}");
    }
}
