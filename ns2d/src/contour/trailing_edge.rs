//! A point contour's sharp trailing edge, made blunt.
//!
//! A corner has no conformal map (the map's derivative vanishes there, and
//! Wegmann's iteration does not converge for a wedge of a few degrees,
//! such as the trailing edge of an airfoil's coordinate file). The
//! sharpest vertex (the one the contour turns most at) is taken as the
//! trailing edge and the point farthest from it as the leading edge; the
//! section is opened there to a thickness `δ` by a thickness growing
//! linearly along the chord (`± δ x / 2c` across the chord on the upper
//! and lower sides, `x` from the leading edge), and closed round the back
//! by a curve that leaves one side and meets the other along its tangent
//! (the cubic of the circular arc tangent to both, [`tangent_back`]):
//!
//! - the chord is kept (it grows by about `δ/2`: by `(δ/2)(1/cos φ - tan φ)`
//!   for sides that meet the edge at `±φ`). Rounding the wedge itself
//!   by the circle tangent to both sides instead moves the trailing edge
//!   forward by `r / sin(β/2) - r` for a wedge `β`: 8.4% of the chord for
//!   the SD7003 (a 3.6° edge) at `r = 0.005`, and its lift with it;
//! - the sides change by at most `δ/2` (at the trailing edge), the
//!   leading edge not at all;
//! - the joins do not turn: the contour has no corner. Until 2026-12-07
//!   the back was the semicircle of diameter `δ` about the old edge, whose
//!   ends run along the chord, so the joins turned by the sides' angle
//!   `φ`; at 26° (NACA 0040) the map's Newton method no longer converged
//!   ("too thin or too sharp"), at 20° (NACA 0030) it did. NACA 0040 to
//!   0080 now map; NACA 0012's back moved by at most 3.3e-4 c (at its end).
//!
//! The contour is opened at the corner and a cubic spline (natural ends)
//! is fitted through it by arc length; it is resampled with each of the
//! input's segments in equal pieces (so the file's own clustering at the
//! edges is kept), and the back gets one sixteenth of the points
//! (at least 6). Cost `O(n log n)` for `n` points.

use realfft::num_complex::Complex64;

use super::Contour;
use crate::error::NsError;
use crate::spline::CurveSpline;

/// Largest trailing-edge thickness, as a fraction of the chord.
const THICKEST_EDGE: f64 = 0.05;

impl Contour {
    /// The vertex the contour turns most at and its turning angle
    /// (radians, in `[0, π)`; a straight run turns 0, a thin airfoil's
    /// sharp trailing edge nearly π).
    #[must_use]
    pub fn sharpest_vertex(&self) -> (usize, f64) {
        let n = self.points.len();
        (0..n)
            .map(|i| {
                let before = self.points[i] - self.points[(i + n - 1) % n];
                let after = self.points[(i + 1) % n] - self.points[i];
                (i, (after * before.conj()).arg().abs())
            })
            .fold((0, -1.0), |best, v| if v.1 > best.1 { v } else { best })
    }

    /// This contour with its sharpest vertex ([`Self::sharpest_vertex`])
    /// made a blunt trailing edge `thickness` thick (chords of the section
    /// from that vertex to the point farthest from it), on about `points`
    /// points (module docs of `contour/trailing_edge.rs`).
    ///
    /// # Errors
    /// [`NsError::BadSection`] for a thickness that is not positive or
    /// above 5% of the chord, or fewer than 32 points; the
    /// [`Contour::from_points`] checks of the result.
    pub fn with_blunt_trailing_edge(&self, thickness: f64, points: usize) -> Result<Self, NsError> {
        if !(thickness > 0.0 && thickness <= THICKEST_EDGE) {
            return Err(NsError::BadSection {
                what: "trailing-edge thickness (0 < t <= 0.05 chord)",
                value: thickness,
            });
        }
        if points < 32 {
            return Err(NsError::BadSection {
                what: "blunt contour's number of points (at least 32)",
                value: points as f64,
            });
        }
        let n = self.points.len();
        let (corner, _) = self.sharpest_vertex();
        let edge = self.points[corner];
        // Opened at the corner: the trailing edge, the upper side to the
        // leading edge (counterclockwise), the lower side, the edge again.
        let path: Vec<Complex64> = (0..=n).map(|i| self.points[(corner + i) % n]).collect();
        let (nose_index, nose) = path
            .iter()
            .copied()
            .enumerate()
            .max_by(|a, b| (a.1 - edge).norm().total_cmp(&(b.1 - edge).norm()))
            .unwrap_or((0, edge));
        let chord = (edge - nose).norm();
        let along = (edge - nose) / chord;
        let across = Complex64::new(0.0, 1.0) * along;
        let half = 0.5 * thickness * chord;
        let spline = CurveSpline::open(&path);
        let knots = spline.knots();
        let nose_s = knots[nose_index];
        let arc = (points / 16).max(6);
        let pieces = ((points - arc) as f64 / n as f64).round().max(1.0) as usize;
        let mut z: Vec<Complex64> = Vec::with_capacity(pieces * n + arc + 1);
        let mut place = |s: f64| {
            let p = spline.eval(s).0;
            let x = (((p - nose) * along.conj()).re / chord).clamp(0.0, 1.0);
            let side = if s < nose_s { 1.0 } else { -1.0 };
            z.push(p + across * (side * half * x));
        };
        for w in knots.windows(2) {
            for p in 0..pieces {
                place(w[0] + (w[1] - w[0]) * p as f64 / pieces as f64);
            }
        }
        place(spline.length());
        // The back, from the lower side's end round to the upper side's
        // start (counterclockwise), along each side's tangent where it
        // meets it (the sides' headings there, opened as they are).
        let heading = |s: f64, side: f64| {
            let d = spline.eval(s).1;
            d + across * (side * half * (d * along.conj()).re / chord)
        };
        let (lower_end, upper_start) = (z[z.len() - 1], z[0]);
        match tangent_back(
            (lower_end, heading(spline.length(), -1.0)),
            (upper_start, heading(0.0, 1.0)),
            arc,
        ) {
            Some(back) => z.extend(back),
            None => {
                // The semicircle about the old edge.
                let start = (-across).arg();
                z.extend((1..arc).map(|i| {
                    let phi = start + std::f64::consts::PI * i as f64 / arc as f64;
                    edge + Complex64::from_polar(half, phi)
                }));
            }
        }
        let xy: Vec<(f64, f64)> = z.iter().map(|p| (p.re, p.im)).collect();
        Contour::from_points(&xy)
    }
}

/// The curve round a blunt trailing edge from `from`'s point, leaving it
/// along its heading, to `to`'s, meeting it along its heading, turning
/// counterclockwise by the angle `θ` between the headings: the cubic
/// Bézier of the circular arc of that turn through the two points
/// (control arms `4/3 tan(θ/4) R`, `R` the arc's radius; the arc itself
/// when the headings are symmetric about the chord between the points,
/// to the cubic's 1 % of `R` at `θ = 164°`). Its `points - 1` inner points, equally
/// spaced in the curve's parameter; `None` when the turn is not in
/// `(0, 3π/2)` (the sides do not close round a back), where the
/// semicircle serves.
fn tangent_back(
    from: (Complex64, Complex64),
    to: (Complex64, Complex64),
    points: usize,
) -> Option<Vec<Complex64>> {
    let (start, end) = (from.0, to.0);
    let (d0, d1) = (from.1 / from.1.norm(), to.1 / to.1.norm());
    let mut turn = (d1 * d0.conj()).arg();
    if turn <= 0.0 {
        turn += std::f64::consts::TAU;
    }
    if !(turn > 0.0 && turn < 1.5 * std::f64::consts::PI) {
        return None;
    }
    let radius = (end - start).norm() / (2.0 * (0.5 * turn).sin());
    let arm = 4.0 / 3.0 * (0.25 * turn).tan() * radius;
    let (b1, b2) = (start + d0 * arm, end - d1 * arm);
    Some(
        (1..points)
            .map(|i| {
                let t = i as f64 / points as f64;
                let u = 1.0 - t;
                start * (u * u * u)
                    + b1 * (3.0 * u * u * t)
                    + b2 * (3.0 * u * t * t)
                    + end * (t * t * t)
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// NACA 0012's half thickness, closed trailing edge (Abbott & von
    /// Doenhoff 1959, §6.4).
    fn half_0012(x: f64) -> f64 {
        0.6 * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
            - 0.1036 * x.powi(4))
    }

    /// A NACA 0012 given as 199 cosine-spaced points with its sharp
    /// trailing edge, made 0.5% thick: every point of the sides lies on the
    /// analytic section thickened by `δ x / 2` (within 2e-5 chords, the
    /// spline's error between the file's points); the back is the arc
    /// tangent to both opened sides, of radius `R = (δ/2) / cos φ` about
    /// `(1 - (δ/2) tan φ, 0)`, `tan φ` the opened side's slope at the edge
    /// (the section's closed-edge slope 0.6 × 0.24225, Abbott & von
    /// Doenhoff 1959, §6.4, less `δ/2`), to the cubic's own deviation
    /// from a circular arc: 2.7e-4 `R` at a quarter turn (Goldapp 1991,
    /// Comput. Aided Geom. Des. 8, 227–238), growing as the turn's sixth
    /// power, about 1 % at this back's 164° (measured: 1.02 %);
    /// the chord runs from 0 to the arc's end; and the contour turns at
    /// the joins no more than between the back's own points (it turned
    /// there by `φ`, 8.1°, a corner, before 2026-12-07).
    #[test]
    fn a_sharp_naca_point_file_is_opened_by_a_linear_thickness() {
        let m = 100;
        let x = |i: usize| 0.5 * (1.0 - (std::f64::consts::PI * i as f64 / m as f64).cos());
        let mut xy: Vec<(f64, f64)> = (0..=m).rev().map(|i| (x(i), half_0012(x(i)))).collect();
        xy.extend((1..m).map(|i| (x(i), -half_0012(x(i)))));
        let sharp = Contour::from_points(&xy).unwrap();
        let (i, turning) = sharp.sharpest_vertex();
        assert!((sharp.points()[i] - Complex64::new(1.0, 0.0)).norm() < 1e-15);
        assert!(turning > 2.8, "{turning}");
        let delta = 0.005;
        let h = 0.5 * delta;
        let slope: f64 = 0.6 * 0.24225 - h;
        let phi = slope.atan();
        let (centre, radius) = (Complex64::new(1.0 - h * slope, 0.0), h / phi.cos());
        let blunt = sharp.with_blunt_trailing_edge(delta, 512).unwrap();
        let mut on_arc = 0;
        for z in blunt.points() {
            if z.re > 1.0 + 1e-12 {
                let off = (z - centre).norm() - radius;
                assert!(off.abs() < 0.015 * radius, "{z}: {off:.2e}");
                on_arc += 1;
            } else if z.re > 0.02 {
                let expected = half_0012(z.re) + h * z.re;
                assert!((z.im.abs() - expected).abs() < 2e-5, "{z}: {expected}");
            }
        }
        assert!(on_arc >= 6, "{on_arc}");
        let (low, high) = blunt
            .points()
            .iter()
            .fold((f64::MAX, f64::MIN), |(l, h), z| (l.min(z.re), h.max(z.re)));
        assert!(
            low.abs() < 1e-6 && (high - (centre.re + radius)).abs() < 0.005 * radius,
            "{low} {high}"
        );
        // The turn at each vertex of the back and of the joins.
        let points = blunt.points();
        let n = points.len();
        let turn = |i: usize| {
            let before = points[i] - points[(i + n - 1) % n];
            let after = points[(i + 1) % n] - points[i];
            (after * before.conj()).arg().abs()
        };
        let back: Vec<usize> = (0..n).filter(|&i| points[i].re > 1.0 + 1e-12).collect();
        let inner = back.iter().map(|&i| turn(i)).fold(0.0, f64::max);
        let joins = [back[0] - 1, back[back.len() - 1] + 1].map(|i| turn(i % n));
        assert!(
            joins.iter().all(|&j| j <= 1.05 * inner && j < 0.5 * phi),
            "joins turn {joins:?}, the back's points {inner}, phi {phi}"
        );
    }

    #[test]
    fn bad_thicknesses_are_refused() {
        let xy: Vec<(f64, f64)> = (0..16)
            .map(|i| {
                let t = std::f64::consts::TAU * f64::from(i) / 16.0;
                (t.cos(), 0.3 * t.sin())
            })
            .collect();
        let c = Contour::from_points(&xy).unwrap();
        for t in [0.0, -1.0, f64::NAN, 0.06] {
            assert!(matches!(
                c.with_blunt_trailing_edge(t, 64),
                Err(NsError::BadSection { .. })
            ));
        }
        assert!(matches!(
            c.with_blunt_trailing_edge(0.01, 16),
            Err(NsError::BadSection { .. })
        ));
    }
}
