//! The boundary correspondence of a section's exterior conformal map, by
//! Wegmann's Newton method.
//!
//! ## What
//! The exterior map `F(ζ) = a ζ + z0 + Σ b_k ζ^(-k)` puts the unit circle
//! on the section: `F(e^{it}) = η(S(t))`, with `η(s)` the contour's
//! closed cubic spline (arc-length parameter) and `S` the unknown
//! boundary correspondence. Once `S` is known at `N` equally spaced `t`,
//! one FFT of `η(S(t_j))` gives the coefficients (`a` the mode 1, `z0`
//! mode 0, `b_k` mode `-k`); a wrong `S` shows as modes `k ≥ 2`.
//!
//! ## How, and why this method
//! Wegmann's method (R. Wegmann, "An iterative method for conformal
//! mapping", J. Comput. Appl. Math. 14 (1986) 7–18; and his chapter
//! "Methods for numerical conformal mapping", Handbook of Complex
//! Analysis 2, 2005, §3.3) is Newton's method for `S`: linearising
//! `η(S + U) ≈ η + η' U`, the correction `U` (real) and the function `g`
//! analytic outside the disk with `g(∞) = a > 0` solve
//!
//! ```text
//! η(S) + η'(S) U = e^{it} g(e^{it})
//! ⇔  Re( conj(A) g ) = γ,   conj(A) = -i e^{it}/η',  γ = Im(η/η')
//! ```
//!
//! a Riemann–Hilbert problem of index zero (the tangent turns once),
//! solved in closed form with two conjugations (each an FFT pair):
//! `conj(A) = ρ e^{-iα}`, `G = -Kα + iα` (analytic outside), then
//! `H = e^{-G} g` has the known real part `γ/(ρ e^{-Kα})`, so
//! `H = γ₁ + iKγ₁ + ic` with the constant `c` fixing `Im g(∞) = 0` (here
//! `K` is the exterior conjugation: `+i sign(k)` on Fourier mode `k`).
//! Each step costs `O(N log N)` and convergence is quadratic, so the
//! whole fit is a few FFT sweeps — the method for a map recomputed every
//! time step. Theodorsen–Garrick would need a near-circle (a Joukowski
//! pre-map whose critical points a general contour does not give) and
//! converges linearly; Fornberg's method needs a linear solve per step.
//!
//! A full Newton step can overshoot where the correspondence crowds (the
//! ends of a thin section); the step is halved until `S` stays increasing
//! (the correspondence of a one-to-one map is monotone), and each
//! correction is low-pass filtered (`exp(-36 (k/(N/2))⁸)`), without which
//! the discrete iteration's high modes grow (measured: by 3.5× a step on
//! a 4:1 ellipse). Thin sections: on the raw contour Newton did not
//! converge for flat plates of 1–8 % thickness, so it runs on the contour
//! opened by a Joukowski pre-map (`Premap`, a Theodorsen–Garrick-like
//! step): critical points at the centres of curvature of the two tips, the
//! circle through them raised by half the mid-chord camber, so a thin
//! cambered plate becomes a near-circle; the correspondence is the same
//! function of the arc length, and the start is the pre-image's polar
//! angle. The samples `N` grow with the start's crowding (64 per unit of
//! largest/smallest step) and double while Newton fails.
//!
//! ## Slits that leave the section
//! The pre-map's slit is a circular arc through the critical points, of
//! the height of the mid-chord camber. Where the camber line is far from
//! a circular arc, that arc leaves a thin section near an edge, the
//! contour crosses it, and its pre-image is no closed curve (NACA 4706,
//! 4 % camber at 70 % of the chord, 6 % thick: the camber line's slope at
//! the trailing edge is −0.27 where the arc's is about −0.15). Newton then
//! failed: on the contours `fwav aero2d --model ns --section nacaXXXX`
//! fits (401 points, the trailing edge opened to 0.005 chords), on 35 of
//! 104 NACA 4-digit sections scanned (camber 0, 2, 4, 6, 8, 9 % at 10 to
//! 90 % of the chord, 6 to 30 % thick; those that failed: camber 2 to 9 %
//! at 10 % or 70 to 90 %) and on NACA 0090 and 0099 (the scan:
//! 2026-12-07). When the first pre-map fails, the fit tries
//! pre-maps whose slits lie inside the section ([`Premap::inside`]):
//! critical points at the tips' centres of curvature, or one moved to the
//! mid-line 98 % of the way out (a leading edge whose camber turns fast),
//! each with the arc height, of 81 from a semicircle one way to one the
//! other, whose slit lies inside and leaves the pre-image roundest. That
//! maps 12 of the 37: NACA 0090, 2912, 4106, 4706, 4920, 4930, 6706, 6930,
//! 8112, 8712, 9112 and 9712. The unit tests below check, on 4706, 4106
//! and 6930 as the command fits them, that the first slit leaves the
//! section, Newton fails after it, and a fallback fits;
//! `tests/section_maps.rs` that the boundaries of 4106, 9712 and 6930
//! (from `Contour::naca4`'s 256 points, where the first pre-map fails
//! too) converge with the terms, to 2.0e-5, 8.3e-6 and 1.2e-4 chords with
//! 128. 9112's leading edge, which turns fastest, is about 1e-3 chords
//! off with 128 terms. The other 25 (NACA 2906, 4906, 4912, 6106, 6130,
//! 6906, 6912, 6920, 8106, 8120, 8130, 8706, 8906, 8912, 8920, 8930,
//! 9106, 9120, 9130, 9706, 9906, 9912, 9920, 9930, and 0099) still fail:
//! no one arc fits inside them, and critical points moved farther in
//! (tried to 90 % of the way) leave a thin tongue Newton does not
//! converge on. Such a section needs a slit that follows its mid-line (a
//! composition of elementary maps, as the zipper algorithm's: Marshall &
//! Rohde 2007, *SIAM J. Numer. Anal.* 45), not built. Sections the first
//! pre-map fits are fitted as before, to the bit.
//!
//! Accuracy: that of the contour's cubic spline, `O(h⁴)` on smooth
//! contours (4:1 ellipse from 1024 points: 4e-11), and of the truncation
//! (`terms⁻²` for the rounded plates and NACA sections, whose curvature
//! jumps): tables in `tests/section_maps.rs`. Cost: 2–4 ms for 256 points,
//! 5–6 ms for 1024 (release, this 2-core machine under load,
//! `examples/fit_timing.rs`).

use realfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

use crate::contour::Contour;
use crate::error::NsError;
use crate::spline::CurveSpline;

/// A closed curve round a section, counterclockwise, by a periodic
/// parameter `s` (the conformal fit's input; a [`Contour`]'s is its
/// closed cubic spline by arc length).
pub(crate) trait ClosedCurve {
    /// The parameter's period.
    fn period(&self) -> f64;
    /// The point and its derivative by the parameter at `s`.
    fn eval(&self, s: f64) -> (Complex64, Complex64);
    /// The section's point at `s` (the physical one, where `eval` is a
    /// pre-mapped curve's).
    fn boundary(&self, s: f64) -> Complex64 {
        self.eval(s).0
    }
}

impl ClosedCurve for CurveSpline {
    fn period(&self) -> f64 {
        self.length()
    }
    fn eval(&self, s: f64) -> (Complex64, Complex64) {
        CurveSpline::eval(self, s)
    }
}

/// The most samples round the circle (doubled from the first guess while
/// Newton fails).
const MAX_SAMPLES: usize = 1 << 15;
/// The fitted pre-maps' critical points: how far from the section's
/// middle to each tip (1: the tip's centre of curvature; module docs,
/// "Slits that leave the section").
const REACHES: [(f64, f64); 3] = [(1.0, 1.0), (0.98, 1.0), (1.0, 0.98)];
/// The fitted pre-maps' arc heights tried, evenly from a semicircle one
/// way (`κ = -f`) to one the other (`κ = f`).
const SLIT_HEIGHTS: usize = 81;
/// Points round the pre-map's circle at which a slit is tested inside
/// the section (the slit is covered twice: 128 distinct points along it).
const SLIT_SAMPLES: usize = 256;
/// The most Newton steps.
const MAX_STEPS: usize = 60;
/// Converged when the largest correction is below this fraction of the
/// perimeter.
const TOLERANCE: f64 = 1e-13;
/// Accepted (at the discretisation's floor) when the steps stop shrinking
/// below this.
const STALL: f64 = 1e-7;
/// The order of the low-pass filter on each correction.
const FILTER_ORDER: i32 = 8;

/// The fitted map's Fourier modes on the unit circle (module docs).
#[derive(Debug, Clone)]
pub(crate) struct Correspondence {
    /// `c_k` of `F(e^{it}) = Σ c_k e^{ikt}`, FFT order (`c_{-k}` at `N - k`).
    pub(crate) modes: Vec<Complex64>,
    /// The correspondence `S(t_j)` at `t_j = 2πj/N` (increasing by the
    /// curve's period over the circle).
    parameters: Vec<f64>,
    /// The curve's parameter period.
    period: f64,
}

impl Correspondence {
    /// The angles `t` on the unit circle the curve's parameters `s` map
    /// from (inverse of the monotone `S`, linear between samples).
    pub(crate) fn angles(&self, s: &[f64]) -> Vec<f64> {
        let n = self.parameters.len();
        let start = self.parameters[0];
        let end = start + self.period;
        s.iter()
            .map(|&x| {
                let x = start + (x - start).rem_euclid(self.period);
                let i = self.parameters.partition_point(|&p| p <= x).clamp(1, n);
                let (below, above) = (
                    self.parameters[i - 1],
                    self.parameters.get(i).copied().unwrap_or(end),
                );
                let frac = if above > below {
                    (x - below) / (above - below)
                } else {
                    0.0
                };
                TAU * (i as f64 - 1.0 + frac) / n as f64
            })
            .collect()
    }
}

/// The conjugations and transforms of one size.
struct Transforms {
    forward: Arc<dyn Fft<f64>>,
    inverse: Arc<dyn Fft<f64>>,
    buffer: Vec<Complex64>,
    scratch: Vec<Complex64>,
}

impl Transforms {
    fn new(n: usize) -> Self {
        let mut planner = FftPlanner::new();
        let forward = planner.plan_fft_forward(n);
        let inverse = planner.plan_fft_inverse(n);
        let scratch_len = forward
            .get_inplace_scratch_len()
            .max(inverse.get_inplace_scratch_len());
        Self {
            forward,
            inverse,
            buffer: vec![Complex64::new(0.0, 0.0); n],
            scratch: vec![Complex64::new(0.0, 0.0); scratch_len],
        }
    }

    /// The exterior conjugate `K u` of the real sequence `u` into `out`.
    fn conjugate(&mut self, u: &[f64], out: &mut [f64]) {
        let n = u.len();
        for (b, &x) in self.buffer.iter_mut().zip(u) {
            *b = Complex64::new(x, 0.0);
        }
        self.forward
            .process_with_scratch(&mut self.buffer, &mut self.scratch);
        self.buffer[0] = Complex64::new(0.0, 0.0);
        self.buffer[n / 2] = Complex64::new(0.0, 0.0);
        let scale = 1.0 / n as f64;
        for (k, b) in self.buffer.iter_mut().enumerate().skip(1) {
            let sign = if k < n / 2 { 1.0 } else { -1.0 };
            *b *= Complex64::new(0.0, sign * scale);
        }
        self.inverse
            .process_with_scratch(&mut self.buffer, &mut self.scratch);
        for (o, b) in out.iter_mut().zip(&self.buffer) {
            *o = b.re;
        }
    }

    /// Low-pass filter the real sequence `u` in place: mode `k` times
    /// `exp(-36 (|k|/(N/2))^order)`.
    fn filter(&mut self, u: &mut [f64], order: i32) {
        let n = u.len();
        for (b, &x) in self.buffer.iter_mut().zip(u.iter()) {
            *b = Complex64::new(x, 0.0);
        }
        self.forward
            .process_with_scratch(&mut self.buffer, &mut self.scratch);
        let scale = 1.0 / n as f64;
        for (k, b) in self.buffer.iter_mut().enumerate() {
            let m = k.min(n - k) as f64 / (n / 2) as f64;
            *b *= scale * (-36.0 * m.powi(order)).exp();
        }
        self.inverse
            .process_with_scratch(&mut self.buffer, &mut self.scratch);
        for (o, b) in u.iter_mut().zip(&self.buffer) {
            *o = b.re;
        }
    }

    /// The Fourier modes `c_k` of `values` (divided by `N`).
    fn modes(&mut self, values: &[Complex64]) -> Vec<Complex64> {
        self.buffer.copy_from_slice(values);
        self.forward
            .process_with_scratch(&mut self.buffer, &mut self.scratch);
        let scale = 1.0 / values.len() as f64;
        self.buffer.iter().map(|c| c * scale).collect()
    }
}

/// Wrap an angle to `(-π, π]`.
fn wrap(x: f64) -> f64 {
    x - TAU * ((x + PI) / TAU).ceil() + TAU
}

/// The correspondence of `contour` on `samples` points (a power of two,
/// at least 16), from `S = arc length` (module docs). Cost: about ten
/// Newton steps of 5 FFTs and `samples` spline evaluations. When Newton
/// fails after [`Premap::new`], up to three more pre-maps are tried
/// ([`Premap::inside`]), each with its samples doubled up to
/// [`MAX_SAMPLES`] while it fails: a contour none fits costs up to about
/// a second.
///
/// # Errors
/// [`NsError::MapNotConverged`] when Newton converges after no pre-map
/// (the correction it carries is the first pre-map's last).
pub(crate) fn solve(contour: &Contour, samples: usize) -> Result<Correspondence, NsError> {
    let spline = CurveSpline::closed(contour.points());
    let premap = Premap::new(&spline, contour.points());
    let first = match solve_premapped(&premap, samples) {
        Ok(fit) => return Ok(fit),
        Err(last) => last,
    };
    // The slit of the pre-map above crosses the contour where the
    // section's camber line is no circular arc (module docs, "Slits
    // that leave the section"): slits kept inside it instead.
    for fitted in Premap::inside(&spline, contour) {
        if let Ok(fit) = solve_premapped(&fitted, samples) {
            return Ok(fit);
        }
    }
    Err(NsError::MapNotConverged {
        iterations: MAX_STEPS,
        correction: first,
        points: contour.len(),
    })
}

/// Newton on the pre-mapped curve from at least `samples` samples (more
/// where the start crowds), doubled while it fails up to
/// [`MAX_SAMPLES`]; `Err` the last correction.
fn solve_premapped(premap: &Premap, samples: usize) -> Result<Correspondence, f64> {
    // The start's crowding (largest over smallest step in S) asks for
    // about 64 samples per factor of it: a thin section's ends. (Capped
    // so that an infinite crowding cannot overflow.)
    let probe = premap.start(samples);
    let steps = probe.windows(2).map(|w| w[1] - w[0]);
    let crowding = steps.clone().fold(0.0, f64::max) / steps.fold(f64::INFINITY, f64::min);
    let wanted = (64.0 * crowding).min((1_u64 << 40) as f64) as usize;
    let mut n = samples.max(wanted.next_power_of_two());
    loop {
        match solve_curve(premap, premap.start(n), -premap.beta) {
            Ok(fit) => return Ok(fit),
            Err(last) if n >= MAX_SAMPLES => return Err(last),
            Err(_) => n *= 2,
        }
    }
}

/// The Joukowski pre-map `z = m + e^{iβ} (w + f²/w)` whose critical
/// points `m ± 2f e^{iβ}` are ([`Premap::new`]) the centres of curvature
/// at the contour's two tips along its principal axis, or ([`Premap::inside`])
/// points chosen so that its slit lies inside the section: it opens a
/// thin section into a near-circle in `w`, where Newton converges from
/// the polar angle (module docs). A near-circle gets `f = 0` (no
/// pre-map).
struct Premap<'a> {
    spline: &'a CurveSpline,
    centre: Complex64,
    /// `e^{-iβ}`.
    unrotate: Complex64,
    beta: f64,
    f2: f64,
    /// The pre-map's circle centre `iκ` in `w` (the arc `J` opens, of
    /// height `2κ`: a cambered section's).
    kappa: f64,
}

impl<'a> Premap<'a> {
    fn new(spline: &'a CurveSpline, points: &[Complex64]) -> Self {
        let m = points.len();
        let frame = PrincipalFrame::of(spline, points);
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
        let curvature_centre =
            |i: usize| circumcentre(points[(i + m - 1) % m], points[i], points[(i + 1) % m]);
        let (Some(plus), Some(minus)) = (curvature_centre(far), curvature_centre(near)) else {
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
    fn slit(&self, samples: usize) -> impl Iterator<Item = Complex64> + '_ {
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
    fn inside(spline: &'a CurveSpline, contour: &'a Contour) -> impl Iterator<Item = Self> + 'a {
        let points = contour.points();
        let frame = PrincipalFrame::of(spline, points);
        // A near-circle has no pre-map to fall back from.
        let reaches = if frame.anisotropy < 0.05 {
            &REACHES[..0]
        } else {
            &REACHES[..]
        };
        reaches.iter().filter_map(move |&reach| {
            let (minus, plus) = frame.critical_points(points, reach)?;
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
        let points = contour.points();
        (0..SLIT_HEIGHTS)
            .filter_map(|i| {
                let kappa = f * (2.0 * i as f64 / (SLIT_HEIGHTS - 1) as f64 - 1.0);
                let premap = Self::through(spline, minus, plus, kappa);
                let slit: Vec<Complex64> = premap.slit(SLIT_SAMPLES).collect();
                if !slit.iter().all(|&z| encloses(points, z)) || crosses(&slit, points) {
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
    fn start(&self, n: usize) -> Vec<f64> {
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
        let offset = w0.arg();
        (0..n)
            .map(|j| {
                let target = TAU * j as f64 / n as f64 - self.beta - offset;
                let turns = (target / TAU).floor();
                let f = target - turns * TAU;
                let k = phi.partition_point(|&p| p <= f).clamp(1, m) - 1;
                let w = ((f - phi[k]) / (phi[k + 1] - phi[k])).clamp(0.0, 1.0);
                knots[k] + w * (knots[k + 1] - knots[k]) + turns * length
            })
            .collect()
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
struct PrincipalFrame {
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
    fn of(spline: &CurveSpline, points: &[Complex64]) -> Self {
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
        points: &[Complex64],
        reach: (f64, f64),
    ) -> Option<(Complex64, Complex64)> {
        let m = points.len();
        let curvature_centre =
            |i: usize| circumcentre(points[(i + m - 1) % m], points[i], points[(i + 1) % m]);
        let frame = |p: Complex64| (p - self.centroid) * self.axis;
        let (x_near, x_far) = (frame(points[self.near]).re, frame(points[self.far]).re);
        let middle = 0.5 * (x_near + x_far);
        let at = |tip: usize, x_tip: f64, reach: f64| -> Option<Complex64> {
            if reach >= 1.0 {
                return curvature_centre(tip);
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
        (encloses(points, minus) && encloses(points, plus)).then_some((minus, plus))
    }
}

/// Whether the polygon `points` encloses `z` (its winding number round
/// `z` is not zero; crossings of the ray to the right counted with their
/// direction).
fn encloses(points: &[Complex64], z: Complex64) -> bool {
    let m = points.len();
    let mut winding = 0_i32;
    for i in 0..m {
        let (p, q) = (points[i], points[(i + 1) % m]);
        let side = (q.re - p.re) * (z.im - p.im) - (z.re - p.re) * (q.im - p.im);
        if p.im <= z.im && q.im > z.im && side > 0.0 {
            winding += 1;
        } else if p.im > z.im && q.im <= z.im && side < 0.0 {
            winding -= 1;
        }
    }
    winding != 0
}

/// Whether the polyline `path` (open) crosses an edge of the closed
/// polygon `points`.
fn crosses(path: &[Complex64], points: &[Complex64]) -> bool {
    let m = points.len();
    let side = |p: Complex64, q: Complex64, r: Complex64| {
        (q.re - p.re) * (r.im - p.im) - (r.re - p.re) * (q.im - p.im)
    };
    path.windows(2).any(|w| {
        (0..m).any(|i| {
            let (p, q) = (points[i], points[(i + 1) % m]);
            side(w[0], w[1], p) * side(w[0], w[1], q) < 0.0
                && side(p, q, w[0]) * side(p, q, w[1]) < 0.0
        })
    })
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

/// Newton from `start` (module docs); `Err` carries the last correction
/// over the period when it does not converge.
fn solve_curve(
    spline: &impl ClosedCurve,
    start: Vec<f64>,
    rotation: f64,
) -> Result<Correspondence, f64> {
    let n = start.len();
    let length = spline.period();
    let mut fft = Transforms::new(n);
    let unit: Vec<Complex64> = (0..n)
        .map(|j| Complex64::from_polar(1.0, TAU * j as f64 / n as f64))
        .collect();
    let mut s = start;
    let mut step = NewtonStep::new(n);
    let mut last = f64::INFINITY;
    let mut best = f64::INFINITY;
    for _ in 0..MAX_STEPS {
        step.correction(spline, &s, &unit, &mut fft, rotation);
        fft.filter(&mut step.u, FILTER_ORDER);
        let correction = step.u.iter().fold(0.0_f64, |m, u| m.max(u.abs())) / length;
        if correction.is_nan() {
            break;
        }
        // Damped: halve until the correspondence stays increasing.
        let mut lambda = 1.0;
        let next = loop {
            let next: Vec<f64> = s.iter().zip(&step.u).map(|(s, u)| s + lambda * u).collect();
            if increasing(&next, length) {
                break Some(next);
            }
            lambda *= 0.5;
            if lambda < 1e-3 {
                break None;
            }
        };
        let Some(next) = next else { break };
        if correction > 10.0 * best {
            break;
        }
        best = best.min(correction);
        s = next;
        let stalled = correction < STALL && correction > 0.7 * last;
        if correction < TOLERANCE || stalled {
            let values: Vec<Complex64> = s.iter().map(|&x| spline.boundary(x)).collect();
            return Ok(Correspondence {
                modes: fft.modes(&values),
                parameters: s,
                period: length,
            });
        }
        last = correction;
    }
    Err(last)
}

/// Whether `s` increases all round (within one period).
fn increasing(s: &[f64], length: f64) -> bool {
    s.windows(2).all(|w| w[1] > w[0]) && s[0] + length > s[s.len() - 1]
}

/// The work arrays of a Newton step.
struct NewtonStep {
    eta: Vec<Complex64>,
    tangent: Vec<Complex64>,
    alpha: Vec<f64>,
    k_alpha: Vec<f64>,
    gamma: Vec<f64>,
    k_gamma: Vec<f64>,
    /// The correction `U`.
    u: Vec<f64>,
}

impl NewtonStep {
    fn new(n: usize) -> Self {
        let z = Complex64::new(0.0, 0.0);
        Self {
            eta: vec![z; n],
            tangent: vec![z; n],
            alpha: vec![0.0; n],
            k_alpha: vec![0.0; n],
            gamma: vec![0.0; n],
            k_gamma: vec![0.0; n],
            u: vec![0.0; n],
        }
    }

    /// Fill `u` with Newton's correction at `s`; returns `max |u|` (NaN
    /// when `η'` does not turn exactly once, i.e. `S` is not a
    /// correspondence).
    #[allow(clippy::needless_range_loop)] // six arrays indexed alike
    fn correction(
        &mut self,
        spline: &impl ClosedCurve,
        s: &[f64],
        unit: &[Complex64],
        fft: &mut Transforms,
        rotation: f64,
    ) -> f64 {
        let n = s.len();
        for ((eta, tangent), &x) in self.eta.iter_mut().zip(&mut self.tangent).zip(s) {
            (*eta, *tangent) = spline.eval(x);
        }
        // conj(A) = -i e^{it}/η' = ρ e^{-iα}: α unwrapped, shifted by a
        // multiple of π to a mean in (-π/2, π/2] (ρ takes the sign).
        let arg = |j: usize| -(Complex64::new(0.0, -1.0) * unit[j] / self.tangent[j]).arg();
        self.alpha[0] = arg(0);
        for j in 1..n {
            self.alpha[j] = self.alpha[j - 1] + wrap(arg(j) - arg(j - 1));
        }
        let turn = self.alpha[n - 1] + wrap(arg(0) - arg(n - 1)) - self.alpha[0];
        if turn.abs() > PI {
            return f64::NAN;
        }
        let mean = self.alpha.iter().sum::<f64>() / n as f64;
        let shift = (mean / PI).round();
        let sign = if shift as i64 % 2 == 0 { 1.0 } else { -1.0 };
        for a in &mut self.alpha {
            *a -= shift * PI;
        }
        let mean_alpha = mean - shift * PI;
        fft.conjugate(&self.alpha, &mut self.k_alpha);
        for j in 0..n {
            let rho = sign / self.tangent[j].norm();
            let gamma = (self.eta[j] / self.tangent[j]).im;
            self.gamma[j] = gamma / (rho * (-self.k_alpha[j]).exp());
        }
        fft.conjugate(&self.gamma, &mut self.k_gamma);
        let mean_gamma = self.gamma.iter().sum::<f64>() / n as f64;
        let c = -mean_gamma * (mean_alpha - rotation).tan();
        let mut largest: f64 = 0.0;
        for j in 0..n {
            let h = Complex64::new(self.gamma[j], self.k_gamma[j] + c);
            let g = Complex64::new(-self.k_alpha[j], self.alpha[j]).exp() * h;
            let w = (unit[j] * g - self.eta[j]) / self.tangent[j];
            let u = w.re;
            self.u[j] = u;
            largest = largest.max(u.abs());
        }
        largest
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `K cos kt = -sin kt` outside the disk (`ζ^{-k} = cos kt - i sin kt`).
    #[test]
    fn the_exterior_conjugate_of_a_cosine() {
        let n = 32;
        let mut fft = Transforms::new(n);
        let u: Vec<f64> = (0..n)
            .map(|j| (3.0 * TAU * j as f64 / n as f64).cos())
            .collect();
        let mut ku = vec![0.0; n];
        fft.conjugate(&u, &mut ku);
        for (j, k) in ku.iter().enumerate() {
            let exact = -(3.0 * TAU * j as f64 / n as f64).sin();
            assert!((k - exact).abs() < 1e-14, "{j}: {k} {exact}");
        }
    }

    /// NACA 4706, 4106 and 6930 as `fwav aero2d --model ns` fits them
    /// ([`sharp_naca`]; module docs, "Slits that leave the section"): the
    /// first pre-map's slit leaves the section and Newton fails after it;
    /// a fallback's slit lies inside, and the fit converges. NACA 9906
    /// fits none: an error, not a panic.
    #[test]
    fn a_slit_inside_the_section_fits_where_the_first_fails() {
        for code in ["4706", "4106", "6930"] {
            let contour = sharp_naca(code);
            let points = contour.points();
            let spline = CurveSpline::closed(points);
            let first = Premap::new(&spline, points);
            let slit: Vec<Complex64> = first.slit(SLIT_SAMPLES).collect();
            let leaves = crosses(&slit, points) || !slit.iter().all(|&z| encloses(points, z));
            assert!(leaves, "NACA {code}: the first pre-map's slit stays inside");
            assert!(
                solve_premapped(&first, 1024).is_err(),
                "NACA {code}: the first fits"
            );
            let fitted = Premap::inside(&spline, &contour).next();
            let fitted = fitted.unwrap_or_else(|| panic!("NACA {code}: no slit inside"));
            let slit: Vec<Complex64> = fitted.slit(SLIT_SAMPLES).collect();
            assert!(!crosses(&slit, points) && slit.iter().all(|&z| encloses(points, z)));
            assert!(solve(&contour, 1024).is_ok(), "NACA {code}: not fitted");
        }
        let fit = solve(&sharp_naca("9906"), 1024);
        assert!(
            matches!(fit, Err(NsError::MapNotConverged { .. })),
            "NACA 9906: {:?}",
            fit.map(|_| ())
        );
    }

    /// [`Premap::through`] the critical points of [`Premap::new`], with
    /// its `κ`, is that pre-map; its slit spans the critical points and
    /// rises `2κ` above their chord (`J(i(κ + r)) = 2iκ`, `r² = f² + κ²`).
    #[test]
    fn a_pre_map_through_its_critical_points() {
        let contour = Contour::naca4("2412", 256, 0.005).unwrap();
        let spline = CurveSpline::closed(contour.points());
        let first = Premap::new(&spline, contour.points());
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

    /// A unit square encloses its middle, not a point beside it; a path
    /// across one side crosses it, one inside does not.
    #[test]
    fn inside_a_square() {
        let square = [
            Complex64::new(0.0, 0.0),
            Complex64::new(1.0, 0.0),
            Complex64::new(1.0, 1.0),
            Complex64::new(0.0, 1.0),
        ];
        assert!(encloses(&square, Complex64::new(0.5, 0.5)));
        assert!(!encloses(&square, Complex64::new(1.5, 0.5)));
        let across = [Complex64::new(0.5, 0.5), Complex64::new(1.5, 0.5)];
        let within = [Complex64::new(0.2, 0.5), Complex64::new(0.8, 0.5)];
        assert!(crosses(&across, &square));
        assert!(!crosses(&within, &square));
    }

    /// The contour `fwav aero2d --model ns --section naca<code>` fits: the
    /// NACA 4-digit section's surfaces (`contour::naca`'s, with the
    /// closed trailing edge) through 401 points by the cosine rule, its
    /// sharp trailing edge opened to 0.005 chords and closed by an arc on
    /// 512 points ([`Contour::with_blunt_trailing_edge`]).
    fn sharp_naca(code: &str) -> Contour {
        let naca = crate::contour::naca::Naca4::parse(code).unwrap();
        let surface = |x: f64, side: f64| {
            let z = naca.surface(x, side);
            (z.re, z.im)
        };
        let n = 200;
        let x = |i: usize| 0.5 * (1.0 - (PI * i as f64 / n as f64).cos());
        let mut points: Vec<(f64, f64)> = (0..=n).rev().map(|i| surface(x(i), 1.0)).collect();
        points.extend((1..n).map(|i| surface(x(i), -1.0)));
        let sharp = Contour::from_points(&points).unwrap();
        sharp.with_blunt_trailing_edge(0.005, 512).unwrap()
    }

    #[test]
    fn wrap_keeps_angles_in_range() {
        for x in [-7.0, -PI, -1.0, 0.0, 1.0, PI, 4.0, 10.0] {
            let w = wrap(x);
            assert!(w > -PI - 1e-15 && w <= PI + 1e-15, "{x} -> {w}");
            assert!(((x - w) / TAU - ((x - w) / TAU).round()).abs() < 1e-12);
        }
    }
}
