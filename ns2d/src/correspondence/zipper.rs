//! The geodesic zipper: a start for Wegmann's Newton method on a section
//! that no Joukowski pre-map opens (the parent module's docs, "Sections
//! no slit fits").
//!
//! ## What
//! For the contour's points `z_0 … z_{n-1}` (counterclockwise), the angles
//! `t_k` on the unit circle at which the exterior map `F(ζ) = a ζ + …`
//! (`a` real and positive) puts them: `F(e^{i t_k}) ≈ z_k`, the
//! correspondence Newton then refines on the contour itself.
//!
//! ## How
//! D. E. Marshall & S. Rohde, "Convergence of a variant of the zipper
//! algorithm for conformal mapping", *SIAM J. Numer. Anal.* 45 (2007)
//! 2577–2609, §2, the "geodesic algorithm": the map is a composition of
//! one elementary map per point, each of which opens the boundary up to
//! that point onto the real line.
//! - `φ_1(z) = i √((z − z_1)/(z − z_0))` takes the plane less the segment
//!   `z_0 z_1` onto the upper half-plane `H` (`z_1 → 0`, `z_0 → ∞`); the
//!   rest of the contour is a curve in `H` from `0` to `∞`, and the
//!   section's exterior (right of the counterclockwise contour) is the
//!   part of `H` to its right.
//! - For each next point, whose image is `a ∈ H`, `f_a` opens the
//!   circular arc from `0` to `a` orthogonal to the real axis (a
//!   hyperbolic geodesic of `H`) onto the real axis: the real Möbius map
//!   `m(z) = z / (1 − q z)`, `q = Re a/|a|²`, takes the arc to the
//!   segment `[0, i s]`, `s = |a|²/Im a`; `√(m² + s²)` opens that
//!   segment (`a → 0`; its right side, the exterior's, to the positive
//!   reals); and a third, real Möbius map `w/(1 − w/r)`, `r` the image
//!   of infinity, sends infinity back there, so that `z_0` stays at
//!   infinity throughout (Marshall & Rohde's normalisation).
//! - Last, the rest of the contour, from `z_{n−1}` (at `0`) to `z_0` (at
//!   infinity), is to the algorithm the geodesic between them, the
//!   imaginary half-axis, and the exterior the first quadrant, which
//!   squaring opens onto `H`; the Möbius map of `H` onto the disk that
//!   sends the image `c` of the point at infinity to the centre,
//!   inverted, is the exterior of the unit circle (`z_0` at 1), turned
//!   so that `a` is real (the far field's points' arguments, averaged).
//!
//! The contour between the points is, to the algorithm, the pre-image of
//! the geodesics it opens: on a contour sampled finely enough for its
//! spline, the angles are a start, not the fit: their error falls by 4
//! a halving of the spacing on a 4:1 ellipse, and approaches that on a
//! 25:1 one (by 3.4 and 3.9: the test below), from 4.9e-4 and 2.4e-3
//! radians on 256 points. `O(n²)` complex square roots for `n`
//! points: about 4 ms for the 432 of a NACA section as `fwav aero2d`
//! fits it (release, this 2-core machine).

use realfft::num_complex::Complex64;
use std::f64::consts::{PI, TAU};

use super::{start_at_angles, wrap};

/// Directions round the far field in which the map's rotation is read.
const FAR_DIRECTIONS: usize = 16;
/// Their distance from the contour's middle, in its largest radius.
const FAR_RADIUS: f64 = 20.0;

/// The angles `t_k` of `points` on the unit circle (module docs), each
/// unwrapped from `t_0 ∈ (−π, π]` and increasing; `None` when the zipper
/// finds the points no simple counterclockwise curve (a point on the
/// wrong side of the curve so far, a correspondence that turns back).
pub(super) fn exterior_angles(points: &[Complex64]) -> Option<Vec<f64>> {
    let n = points.len();
    if n < 3 {
        return None;
    }
    // Scaled to the unit disk round the points' mean (angles are
    // unchanged by similarity).
    let mean = points.iter().sum::<Complex64>() / n as f64;
    let size = points.iter().fold(0.0_f64, |r, z| r.max((z - mean).norm()));
    let scaled: Vec<Complex64> = points.iter().map(|z| (z - mean) / size).collect();
    let far: Vec<Complex64> = (0..FAR_DIRECTIONS)
        .map(|j| Complex64::from_polar(FAR_RADIUS, TAU * j as f64 / FAR_DIRECTIONS as f64))
        .collect();
    let mut zipped = Zipped::start(&scaled, &far);
    for k in 2..n {
        zipped.open_through(k)?;
    }
    zipped.angles(&far)
}

/// The point at infinity.
const INFINITY: Complex64 = Complex64::new(f64::INFINITY, 0.0);

/// The map `f_a` (module docs) that opens the geodesic from `0` to `a ∈ H`
/// onto the real axis, `a → 0`, infinity kept there.
struct Elementary {
    /// `Re a / |a|²`: the geodesic's circle meets the real axis again at
    /// `1/q`.
    q: f64,
    /// The height of the segment `m` takes the geodesic to, `|a|²/Im a`.
    s: f64,
    /// Where the opening puts infinity, `m(∞) = −1/q` opened; the last
    /// Möbius map sends it back (`None`: `q = 0`, infinity stays).
    infinity: Option<f64>,
}

impl Elementary {
    /// `None` when `a` is not in `H` (the points are no simple curve
    /// traversed with the exterior on their right, or rounding lost it).
    fn new(a: Complex64) -> Option<Self> {
        if !(a.im > 0.0 && a.is_finite()) {
            return None;
        }
        let q = a.re / a.norm_sqr();
        let s = a.norm_sqr() / a.im;
        let infinity = (q != 0.0).then(|| -(1.0 / (q * q) + s * s).sqrt() * q.signum());
        Some(Self { q, s, infinity })
    }

    /// `f_a(z)`: `m = z/(1 − q z)`, then `√(m² + s²)`, taken as
    /// `m √(1 + (s/m)²)` (which is `m` at infinity, has the sign of `m` on
    /// the reals, and does not overflow for large `m` as `m²` would), the
    /// slit's foot `m = 0` to its right side `s`, as is an `m` so small
    /// that `(s/m)²` could overflow (`√(m² + s²)` is `±s` to rounding
    /// there, `−s` on the negative reals); then `w/(1 − w/r)`, `r` the
    /// image of infinity, which sends it back there (a real Möbius map,
    /// `H` onto itself, `0` kept).
    fn apply(&self, z: Complex64) -> Complex64 {
        if z.is_infinite() {
            return INFINITY;
        }
        let m = z / (1.0 - self.q * z);
        let w = if !m.is_finite() {
            INFINITY
        } else if m.norm() < 1e-100 * self.s {
            // The foot, or a real beside it, whose side its sign keeps.
            let left = m.im == 0.0 && m.re < 0.0;
            Complex64::new(if left { -self.s } else { self.s }, 0.0)
        } else {
            let ratio = self.s / m;
            m * (1.0 + ratio * ratio).sqrt()
        };
        match self.infinity {
            None => w,
            Some(r) if w.is_infinite() => Complex64::new(-r, 0.0),
            Some(r) => w / (1.0 - w / r),
        }
    }
}

/// The images of the points, of the far-field points and of infinity
/// through the maps so far (`z_0` stays at infinity).
struct Zipped {
    /// Points `0 … n−1` (`z_0`'s is infinity).
    images: Vec<Complex64>,
    far: Vec<Complex64>,
    /// The image of the plane's point at infinity, in the exterior.
    infinity: Complex64,
}

impl Zipped {
    /// After `φ_1` (module docs).
    fn start(z: &[Complex64], far: &[Complex64]) -> Self {
        let i = Complex64::new(0.0, 1.0);
        let phi = |w: Complex64| i * ((w - z[1]) / (w - z[0])).sqrt();
        let mut images: Vec<Complex64> = z.iter().map(|&w| phi(w)).collect();
        images[0] = INFINITY;
        images[1] = Complex64::new(0.0, 0.0);
        Self {
            images,
            far: far.iter().map(|&w| phi(w)).collect(),
            infinity: i,
        }
    }

    /// Apply the map that opens the boundary up to point `k` (module
    /// docs: `f_a`, `a` its image); `None` when `a` is not in `H`.
    fn open_through(&mut self, k: usize) -> Option<()> {
        let map = Elementary::new(self.images[k])?;
        for z in self.images.iter_mut().chain(&mut self.far) {
            *z = map.apply(*z);
        }
        self.images[k] = Complex64::new(0.0, 0.0);
        self.infinity = map.apply(self.infinity);
        Some(())
    }

    /// The last map, the disk's and the rotation that makes `a` real
    /// (module docs); `None` when the correspondence is not increasing
    /// (crowding beyond rounding, or no simple counterclockwise curve).
    fn angles(&self, far: &[Complex64]) -> Option<Vec<f64>> {
        // The last arc, from z_{n-1} at 0 to z_0 at infinity, is the
        // imaginary half-axis to the algorithm, and the exterior the first
        // quadrant, which squaring opens onto H.
        let c = self.infinity;
        if !(c.re > 0.0 && c.im > 0.0) {
            return None;
        }
        let centre = c * c;
        // H onto the exterior of the unit circle, the image of infinity
        // to infinity (z_0, at infinity in H, to 1).
        let exterior = |w: Complex64| {
            let u = w * w;
            if u.is_finite() {
                (u - centre.conj()) / (u - centre)
            } else {
                Complex64::new(1.0, 0.0)
            }
        };
        let rotation: Complex64 = self
            .far
            .iter()
            .zip(far)
            .map(|(&w, &z)| {
                let ratio = z / exterior(w);
                ratio.unscale(ratio.norm())
            })
            .sum();
        let rotation = rotation.arg();
        let n = self.images.len();
        let mut t = Vec::with_capacity(n);
        t.push(wrap(rotation));
        for &w in &self.images[1..] {
            let step = wrap(exterior(w).arg() + rotation - t[t.len() - 1]);
            if step.is_nan() || step <= 0.0 {
                return None;
            }
            t.push(t[t.len() - 1] + step);
        }
        // The step back to z_0, as the others, forward and under a half
        // turn: the whole correspondence one turn.
        (t[n - 1] < t[0] + TAU && t[n - 1] > t[0] + TAU - PI).then_some(t)
    }
}

/// The start `S(t_j)` at `t_j = 2πj/n` from the points' `angles`
/// ([`exterior_angles`]) and their spline parameters `knots` (one more
/// than the points: the period at the end), linear between points
/// ([`start_at_angles`], the angles taken from the first point's).
pub(super) fn start(angles: &[f64], knots: &[f64], n: usize) -> Vec<f64> {
    let mut phi: Vec<f64> = angles.iter().map(|t| t - angles[0]).collect();
    phi.push(TAU);
    start_at_angles(&phi, knots, (angles[0], 0.0), n)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ellipse `(A cos t, B sin t)`'s exterior map is Joukowski's,
    /// `F(ζ) = (A+B)/2 ζ + (A−B)/2 ζ⁻¹` (Milne-Thomson, *Theoretical
    /// Hydrodynamics*, §6.31), with `a` real: the point at parameter `t`
    /// is at angle `t`, and on the ellipse turned by `β`, at `t + β` (the
    /// map `e^{iβ} F(e^{-iβ} ζ)`, whose `a` is real again). From points
    /// unevenly spaced in `t` (`t = u + 0.3 sin u`, `u` even: sparsest at
    /// the sharp end `t = 0`), on the ellipse turned by 0.7 and moved off
    /// the origin, the zipper's worst angle error falls with the spacing
    /// (measured, radians; with the sparse points moved to the flat side,
    /// `t = u + 0.3 sin u + 2`, 4.6e-5 and 9.0e-4 on 256 points):
    ///
    /// | points | 4:1 ellipse | 25:1 |
    /// |-------:|--------:|--------:|
    /// |  256   | 4.91e-4 | 2.44e-3 |
    /// |  512   | 1.23e-4 | 7.23e-4 |
    /// |  1024  | 3.07e-5 | 1.87e-4 |
    ///
    /// A start for Newton, not the fit (which the spline's `O(h⁴)` and
    /// the series' truncation bound: `tests/section_maps.rs`).
    #[test]
    fn an_ellipse_points_at_their_parameter() {
        let turn = 0.7;
        for (semi_y, bound) in [(0.25, 4e-5), (0.04, 2.5e-4)] {
            let mut previous = f64::INFINITY;
            for n in [256, 512, 1024] {
                let t: Vec<f64> = (0..n)
                    .map(|k| {
                        let u = TAU * k as f64 / n as f64;
                        u + 0.3 * u.sin()
                    })
                    .collect();
                let centre = Complex64::new(0.3, -0.1);
                let points: Vec<Complex64> = t
                    .iter()
                    .map(|&t| {
                        let local = Complex64::new(t.cos(), semi_y * t.sin());
                        centre + local * Complex64::from_polar(1.0, turn)
                    })
                    .collect();
                let angles = exterior_angles(&points).unwrap();
                let worst = angles
                    .iter()
                    .zip(&t)
                    .map(|(a, t)| wrap(a - t - turn).abs())
                    .fold(0.0, f64::max);
                println!("1:{semi_y}, {n} points: worst angle error {worst:.2e}");
                assert!(worst < previous / 3.0, "1:{semi_y}, {n}: {worst:.2e}");
                previous = worst;
            }
            assert!(previous < bound, "1:{semi_y}: {previous:.2e}");
        }
    }

    /// A clockwise polygon's right is its inside: no exterior map.
    #[test]
    fn a_clockwise_polygon_is_refused() {
        let points: Vec<Complex64> = (0..64)
            .map(|k| Complex64::from_polar(1.0, -TAU * k as f64 / 64.0))
            .collect();
        assert!(exterior_angles(&points).is_none());
        let mut ccw = points;
        ccw.reverse();
        assert!(exterior_angles(&ccw).is_some());
    }
}
