//! The Joukowski pre-map that opens a section into a near-circle before
//! Wegmann's Newton method fits its correspondence (the parent module's
//! docs, "How, and why this method" and "Slits that leave the section"):
//! the first, through the tips' centres of curvature with the arc of the
//! mid-chord camber ([`Premap::new`]), and the fallbacks whose slits lie
//! inside the section ([`Premap::inside`]).

use realfft::num_complex::Complex64;
use std::f64::consts::TAU;

use super::{start_at_angles, wrap, ClosedCurve};
use crate::contour::Contour;
use crate::spline::CurveSpline;

/// The fitted pre-maps' critical points: how far from the section's
/// middle to each tip (1: the tip's centre of curvature; module docs,
/// "Slits that leave the section").
const REACHES: [(f64, f64); 3] = [(1.0, 1.0), (0.98, 1.0), (1.0, 0.98)];
/// The fitted pre-maps' arc heights tried, evenly from a semicircle one
/// way (`κ = -f`) to one the other (`κ = f`).
const SLIT_HEIGHTS: usize = 81;
/// Points round the pre-map's circle at which a slit is tested inside
/// the section (the slit is covered twice: 128 distinct points along it).
pub(super) const SLIT_SAMPLES: usize = 256;

/// The Joukowski pre-map `z = m + e^{iβ} (w + f²/w)` whose critical
/// points `m ± 2f e^{iβ}` are ([`Premap::new`]) the centres of curvature
/// at the contour's two tips along its principal axis, or ([`Premap::inside`])
/// points chosen so that its slit lies inside the section: it opens a
/// thin section into a near-circle in `w`, where Newton converges from
/// the polar angle (module docs). A near-circle gets `f = 0` (no
/// pre-map).
pub(super) struct Premap<'a> {
    spline: &'a CurveSpline,
    centre: Complex64,
    /// `e^{-iβ}`.
    unrotate: Complex64,
    pub(super) beta: f64,
    f2: f64,
    /// The pre-map's circle centre `iκ` in `w` (the arc `J` opens, of
    /// height `2κ`: a cambered section's).
    kappa: f64,
}

impl<'a> Premap<'a> {
    pub(super) fn new(
        spline: &'a CurveSpline,
        points: &[Complex64],
        frame: &PrincipalFrame,
    ) -> Self {
        let (centroid, axis) = (frame.centroid, frame.axis);
        let circle = Self {
            spline,
            centre: centroid,
            unrotate: Complex64::new(1.0, 0.0),
            beta: 0.0,
            f2: 0.0,
            kappa: 0.0,
        };
        if frame.anisotropy < 0.05 {
            return circle;
        }
        let (far, near) = (frame.far, frame.near);
        let x = |i: usize| ((points[i] - centroid) * axis).re;
        let (Some(plus), Some(minus)) = (
            curvature_centre(points, far),
            curvature_centre(points, near),
        ) else {
            return circle;
        };
        let span = plus - minus;
        // Both critical points well inside, on the tips' side of the centre.
        let inside = ((plus - centroid) * axis).re > 0.0 && ((minus - centroid) * axis).re < 0.0;
        if !inside || span.norm() < 0.1 * (x(far) - x(near)) {
            return circle;
        }
        let beta = span.arg();
        let (centre, unrotate) = (0.5 * (plus + minus), Complex64::from_polar(1.0, -beta));
        let f = 0.25 * span.norm();
        // Camber: the middle of the section's height at mid-chord.
        let (mut top, mut bottom) = (f64::NEG_INFINITY, f64::INFINITY);
        for p in points {
            let q = (p - centre) * unrotate;
            if q.re.abs() < 0.2 * f {
                top = top.max(q.im);
                bottom = bottom.min(q.im);
            }
        }
        let kappa = if top > bottom {
            0.25 * (top + bottom)
        } else {
            0.0
        };
        Self {
            spline,
            centre,
            unrotate,
            beta,
            f2: f * f,
            kappa,
        }
    }

    /// The pre-map whose critical points are `minus` and `plus` and whose
    /// slit (the arc they span, of height `2 kappa` over their chord) is
    /// the image of the circle through `±f` round `iκ`.
    fn through(spline: &'a CurveSpline, minus: Complex64, plus: Complex64, kappa: f64) -> Self {
        let span = plus - minus;
        let beta = span.arg();
        let f = 0.25 * span.norm();
        Self {
            spline,
            centre: 0.5 * (plus + minus),
            unrotate: Complex64::from_polar(1.0, -beta),
            beta,
            f2: f * f,
            kappa,
        }
    }

    /// How far the pre-image of the contour is from a circle round `iκ`:
    /// the largest over the smallest distance of its knots' pre-images
    /// from `iκ` (1 for a circle).
    fn roundness(&self) -> f64 {
        let knots = self.spline.knots();
        let centre = Complex64::new(0.0, self.kappa);
        let (near, far) = knots[..knots.len() - 1]
            .iter()
            .map(|&s| (self.eval(s).0 - centre).norm())
            .fold((f64::INFINITY, 0.0_f64), |(lo, hi), r| {
                (lo.min(r), hi.max(r))
            });
        far / near
    }

    /// `samples` points along the slit, global: the images of points
    /// evenly round the circle through `±f` (`J` covers the slit twice).
    pub(super) fn slit(&self, samples: usize) -> impl Iterator<Item = Complex64> + '_ {
        let f = self.f2.sqrt();
        let radius = (self.f2 + self.kappa * self.kappa).sqrt();
        let turn = self.unrotate.conj();
        (0..samples).map(move |j| {
            let phi = TAU * (j as f64 + 0.5) / samples as f64;
            let w = Complex64::new(0.0, self.kappa) + Complex64::from_polar(radius, phi);
            let z = if f == 0.0 { w } else { w + self.f2 / w };
            self.centre + z * turn
        })
    }

    /// Pre-maps whose slits lie inside `contour`, for a section whose
    /// camber line is too far from a circular arc for [`Self::new`]'s
    /// (module docs, "Slits that leave the section"): critical points at
    /// the [`REACHES`] (the tips' centres of curvature, or the mid-line's
    /// points 98 % of the way from the middle to one tip), each with the
    /// arc height whose slit lies inside and leaves the pre-image
    /// roundest, when one lies inside.
    pub(super) fn inside(
        spline: &'a CurveSpline,
        contour: &'a Contour,
        frame: PrincipalFrame,
    ) -> impl Iterator<Item = Self> + 'a {
        // A near-circle has no pre-map to fall back from.
        let reaches = if frame.anisotropy < 0.05 {
            &REACHES[..0]
        } else {
            &REACHES[..]
        };
        reaches.iter().filter_map(move |&reach| {
            let (minus, plus) = frame.critical_points(contour, reach)?;
            Self::roundest_inside(spline, contour, minus, plus)
        })
    }

    /// Of the [`SLIT_HEIGHTS`] slits through `minus` and `plus`, from a
    /// semicircle one way to one the other, that which lies inside
    /// `contour` (each of its [`SLIT_SAMPLES`] points enclosed, and no
    /// segment between consecutive ones crossing an edge of the contour)
    /// and leaves the contour's pre-image roundest ([`Self::roundness`]).
    /// Cost: `O(SLIT_HEIGHTS SLIT_SAMPLES N)` for `N` contour points (a
    /// few milliseconds for 432).
    fn roundest_inside(
        spline: &'a CurveSpline,
        contour: &Contour,
        minus: Complex64,
        plus: Complex64,
    ) -> Option<Self> {
        let f = 0.25 * (plus - minus).norm();
        if f == 0.0 {
            return None;
        }
        (0..SLIT_HEIGHTS)
            .filter_map(|i| {
                let kappa = f * (2.0 * i as f64 / (SLIT_HEIGHTS - 1) as f64 - 1.0);
                let premap = Self::through(spline, minus, plus, kappa);
                let slit: Vec<Complex64> = premap.slit(SLIT_SAMPLES).collect();
                if !slit.iter().all(|&z| contour.encloses(z)) || contour.crossed_by(&slit) {
                    return None;
                }
                Some((-premap.roundness(), premap))
            })
            .max_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, premap)| premap)
    }

    /// The start `S(t)`: the arc length where the polar angle of `w` is
    /// `t - β` (made increasing: a running maximum blended with 2 % of
    /// the arc length), so that `a` comes out real.
    pub(super) fn start(&self, n: usize) -> Vec<f64> {
        let knots = self.spline.knots();
        let m = knots.len() - 1;
        let length = knots[m];
        let ik = Complex64::new(0.0, self.kappa);
        let w0 = self.eval(0.0).0 - ik;
        let mut phi = Vec::with_capacity(m + 1);
        let (mut previous, mut unwrapped, mut running) = (w0.arg(), 0.0_f64, 0.0_f64);
        for &s in &knots[..m] {
            let a = (self.eval(s).0 - ik).arg();
            unwrapped += wrap(a - previous);
            previous = a;
            running = running.max(unwrapped);
            phi.push(0.98 * running + 0.02 * TAU * s / length);
        }
        phi.push(TAU);
        start_at_angles(&phi, knots, (self.beta, w0.arg()), n)
    }
}

impl ClosedCurve for Premap<'_> {
    fn period(&self) -> f64 {
        self.spline.length()
    }
    fn boundary(&self, s: f64) -> Complex64 {
        self.spline.eval(s).0
    }
    fn eval(&self, s: f64) -> (Complex64, Complex64) {
        let (z, dz) = self.spline.eval(s);
        let (z, dz) = ((z - self.centre) * self.unrotate, dz * self.unrotate);
        if self.f2 == 0.0 {
            return (z, dz);
        }
        let root = (z * z - 4.0 * self.f2).sqrt();
        let (w1, w2) = (0.5 * (z + root), 0.5 * (z - root));
        let ik = Complex64::new(0.0, self.kappa);
        // The root outside the circle through ±f round iκ (J maps its
        // outside one-to-one onto the plane less the arc).
        let outside = (w1 - ik).norm_sqr() >= self.f2 + self.kappa * self.kappa;
        let w = if outside { w1 } else { w2 };
        (w, dz / (1.0 - self.f2 / (w * w)))
    }
}

/// A section's principal axes through its centroid, and the contour's
/// points at either end along the major one (the frame of [`Premap::new`]
/// and of the fallback pre-maps' critical points).
pub(super) struct PrincipalFrame {
    centroid: Complex64,
    /// Multiplies a point's offset from the centroid into the frame.
    axis: Complex64,
    /// How far from round: `|I_xx - I_yy, 2 I_xy| / (I_xx + I_yy)` of
    /// the points' second moments (0 for a circle); below 0.05 the
    /// section is taken as a near-circle, with no pre-map.
    anisotropy: f64,
    /// The points farthest along the axis either way (indices).
    near: usize,
    far: usize,
}

impl PrincipalFrame {
    /// The frame of `points` (weighted by the arc length each point
    /// stands for).
    pub(super) fn of(spline: &CurveSpline, points: &[Complex64]) -> Self {
        let knots = spline.knots();
        let m = points.len();
        let length = knots[m];
        let weight = |i: usize| 0.5 * (knots[i + 1] - knots[(i + m - 1) % m]).rem_euclid(length);
        let centroid = (0..m).map(|i| points[i] * weight(i)).sum::<Complex64>() / length;
        let (mut ixx, mut iyy, mut ixy) = (0.0, 0.0, 0.0);
        for (i, p) in points.iter().enumerate() {
            let d = p - centroid;
            ixx += weight(i) * d.re * d.re;
            iyy += weight(i) * d.im * d.im;
            ixy += weight(i) * d.re * d.im;
        }
        let anisotropy = (ixx - iyy).hypot(2.0 * ixy) / (ixx + iyy);
        let axis = Complex64::from_polar(1.0, -0.5 * (2.0 * ixy).atan2(ixx - iyy));
        let x: Vec<f64> = points.iter().map(|p| ((p - centroid) * axis).re).collect();
        let pick = |better: fn(f64, f64) -> bool| {
            (0..m).fold(0, |b, i| if better(x[i], x[b]) { i } else { b })
        };
        Self {
            centroid,
            axis,
            anisotropy,
            far: pick(|a, b| a > b),
            near: pick(|a, b| a < b),
        }
    }

    /// The critical points `reach` (towards the near tip, towards the far
    /// one) of the way from the section's middle to its tips: at 1 the
    /// tips' centres of curvature, else the mid-line's points there
    /// (halfway between the contour's lowest and highest crossing of the
    /// line across the axis). `None` when a point is missing or outside.
    /// Unlike [`Premap::new`]'s, the two may lie on one side of the
    /// middle, even crossed (a blunt tip's centre of curvature may lie
    /// beyond it, as NACA 0090's leading edge's does, its radius
    /// `1.1019 t² = 0.89` chords): any two points inside give a slit to
    /// test.
    fn critical_points(
        &self,
        contour: &Contour,
        reach: (f64, f64),
    ) -> Option<(Complex64, Complex64)> {
        let points = contour.points();
        let m = points.len();
        let frame = |p: Complex64| (p - self.centroid) * self.axis;
        let (x_near, x_far) = (frame(points[self.near]).re, frame(points[self.far]).re);
        let middle = 0.5 * (x_near + x_far);
        let at = |tip: usize, x_tip: f64, reach: f64| -> Option<Complex64> {
            if reach >= 1.0 {
                return curvature_centre(points, tip);
            }
            let x = middle + reach * (x_tip - middle);
            let (mut low, mut high) = (f64::INFINITY, f64::NEG_INFINITY);
            for i in 0..m {
                let (p, q) = (frame(points[i]), frame(points[(i + 1) % m]));
                if (p.re - x) * (q.re - x) <= 0.0 && p.re != q.re {
                    let y = p.im + (q.im - p.im) * (x - p.re) / (q.re - p.re);
                    low = low.min(y);
                    high = high.max(y);
                }
            }
            (low < high).then(|| self.centroid + Complex64::new(x, 0.5 * (low + high)) / self.axis)
        };
        let (minus, plus) = (
            at(self.near, x_near, reach.0)?,
            at(self.far, x_far, reach.1)?,
        );
        (contour.encloses(minus) && contour.encloses(plus)).then_some((minus, plus))
    }
}

/// The centre of curvature of the polygon `points` at vertex `i`: of the
/// circle through it and its neighbours (`None` when they are collinear).
fn curvature_centre(points: &[Complex64], i: usize) -> Option<Complex64> {
    let m = points.len();
    circumcentre(points[(i + m - 1) % m], points[i], points[(i + 1) % m])
}

/// The centre of the circle through three points (`None` when collinear).
fn circumcentre(a: Complex64, b: Complex64, c: Complex64) -> Option<Complex64> {
    let (ab, ac) = (b - a, c - a);
    let d = 2.0 * (ab.re * ac.im - ab.im * ac.re);
    if d == 0.0 {
        return None;
    }
    let (nb, nc) = (ab.norm_sqr(), ac.norm_sqr());
    Some(a + Complex64::new(ac.im * nb - ab.im * nc, ab.re * nc - ac.re * nb) / d)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`Premap::through`] the critical points of [`Premap::new`], with
    /// its `κ`, is that pre-map; its slit spans the critical points and
    /// rises `2κ` above their chord (`J(i(κ + r)) = 2iκ`, `r² = f² + κ²`).
    #[test]
    fn a_pre_map_through_its_critical_points() {
        let contour = Contour::naca4("2412", 256, 0.005).unwrap();
        let spline = CurveSpline::closed(contour.points());
        let frame = PrincipalFrame::of(&spline, contour.points());
        let first = Premap::new(&spline, contour.points(), &frame);
        let half_span = 2.0 * first.f2.sqrt() * first.unrotate.conj();
        let (minus, plus) = (first.centre - half_span, first.centre + half_span);
        let again = Premap::through(&spline, minus, plus, first.kappa);
        assert!((again.centre - first.centre).norm() < 1e-14);
        assert!((again.beta - first.beta).abs() < 1e-14);
        assert!((again.f2 - first.f2).abs() < 1e-14 * first.f2);
        let slit = Premap::through(
            &spline,
            Complex64::new(-2.0, 0.0),
            Complex64::new(2.0, 0.0),
            0.3,
        );
        let points: Vec<Complex64> = slit.slit(4096).collect();
        let widest = points.iter().fold(0.0_f64, |m, z| m.max(z.re.abs()));
        let highest = points.iter().fold(f64::NEG_INFINITY, |m, z| m.max(z.im));
        let lowest = points.iter().fold(f64::INFINITY, |m, z| m.min(z.im));
        assert!((widest - 2.0).abs() < 1e-5, "{widest}");
        assert!((highest - 0.6).abs() < 1e-5, "{highest}");
        assert!(lowest > -1e-12, "{lowest}");
    }
}
