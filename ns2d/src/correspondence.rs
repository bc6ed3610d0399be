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
//! 128. 9112 is about 1e-3 chords off with 128 terms: its lower surface
//! has a corner (below, "Sections no slit fits").
//!
//! ## Sections no slit fits
//! The other 25 (NACA 2906, 4906, 4912, 6106, 6130, 6906, 6912, 6920,
//! 8106, 8120, 8130, 8706, 8906, 8912, 8920, 8930, 9106, 9120, 9130,
//! 9706, 9906, 9912, 9920, 9930, and 0099) have no one arc inside them on
//! which Newton converges (critical points moved farther in, tried to
//! 90 % of the way, leave a thin tongue Newton does not converge on).
//! For them Newton runs on the contour itself, without pre-map, from the
//! correspondence of the geodesic zipper (Marshall & Rohde 2007, *SIAM J.
//! Numer. Anal.* 45: a composition of one elementary map per contour
//! point, `zipper.rs`, its angles' error falling as the points' spacing
//! squared), whose
//! crowding sets the samples as the pre-map's start does. On the raw
//! contour the arc-length start had failed even for plates of 1–8 %
//! thickness; from the zipper's, Newton converges on all 25 with their
//! trailing edges opened as the command opens a sharp one (the unit
//! tests' `sharp_naca`; the whole fit 0.05 to 0.9 s each, on 4,096 to
//! 32,768 samples), and `tests/section_maps.rs` shows 6106, 8912 and
//! 9912 (from 256 points, where no pre-map fits them either) converging
//! with the terms, to 3.8e-5 to 6.1e-5 chords with 128. The same path
//! maps membranes whose mid-line is no arc, which no pre-map had: an S
//! (`y = 0.02 sin 2πx`, 0.02 chords thick) to 1.7e-6 chords with 256
//! terms, a dragonfly-like corrugation of three waves of 0.04 chords to
//! 9.1e-6 (`tests/section_maps.rs`); five waves of 0.03 converge slowly
//! (8.1e-4 with 256), and of 0.05 Newton stalls at 4e-7 of the perimeter,
//! above its tolerance (an error). (`fwav aero2d
//! --model ns` keeps NACA 0099's trailing-edge corner, which turns by
//! 82°, under the 90° at which the command rounds one; on the corner
//! Newton's corrections stall at 1.7e-5 of the perimeter,
//! above its tolerance, and the fit fails.)
//!
//! The NACA 4-digit lower surface has a corner at the camber's position
//! `x = p`: the thickness is laid off normal to a camber line whose
//! curvature jumps there (from `−2m/p²` to `−2m/(1−p)²`), and the
//! surface's tangent turns at once by an angle that grows with the
//! camber and thickness and as `p` falls: 1.1° on 4106, 24° on 8112, 37°
//! on 9112, 61° on 6120, and past 90° on 6130, 8120, 8130, 9120 and 9130
//! (111° to 136°: the surface folds back on itself). A corner has no
//! smooth map, and the series converges slowly there: 9112 is 1.0e-3
//! chords off with 128 terms and 5.6e-4 with 256, and the five folded
//! miss the fold by 1.4e-3 to 5.9e-3 chords with 128; 8130's and 9130's
//! maps are not one-to-one even with 256 ([`NsError::MapNotUnivalent`]).
//! Nor does Newton converge, from the polar angle's start or the
//! zipper's, on a six-lobed star `r = 1 + cos(6θ)/2` (its corrections
//! stall at 1e-2 of the perimeter): [`NsError::MapNotConverged`],
//! carrying the closest any try came. Sections a pre-map fits are fitted
//! as before, to the bit.
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

mod premap;
mod zipper;

use premap::{Premap, PrincipalFrame};

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
    /// The largest distance, at the `N` samples, between the fitted
    /// boundary `η(S(t_j))` (on the contour) and the boundary of the map
    /// kept to `a`, `z0` and `terms` coefficients `b_k`: the modes left out,
    /// summed by one inverse FFT ([`crate::SectionMap::from_contour_with_deviation`]).
    pub(crate) fn truncation_deviation(&self, terms: usize) -> f64 {
        let n = self.modes.len();
        let mut left = self.modes.clone();
        left[0] = Complex64::new(0.0, 0.0);
        left[1] = Complex64::new(0.0, 0.0);
        for k in 1..=terms.min(n - 2) {
            left[n - k] = Complex64::new(0.0, 0.0);
        }
        FftPlanner::new().plan_fft_inverse(n).process(&mut left);
        left.iter().fold(0.0, |worst, e| worst.max(e.norm()))
    }

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
/// ([`Premap::inside`]), then the contour itself from the zipper's start
/// (module docs, "Sections no slit fits"), each with its samples doubled
/// up to [`MAX_SAMPLES`] while it fails: a contour none fits costs up to
/// about a second.
///
/// # Errors
/// [`NsError::MapNotConverged`] when Newton converges after no pre-map
/// nor from the zipper's start (the correction it carries is the
/// smallest of the tries' last).
pub(crate) fn solve(contour: &Contour, samples: usize) -> Result<Correspondence, NsError> {
    let spline = CurveSpline::closed(contour.points());
    let frame = PrincipalFrame::of(&spline, contour.points());
    let premap = Premap::new(&spline, contour.points(), &frame);
    let first = match solve_premapped(&premap, samples) {
        Ok(fit) => return Ok(fit),
        Err(last) => last,
    };
    // The slit of the pre-map above crosses the contour where the
    // section's camber line is no circular arc (module docs, "Slits
    // that leave the section"): slits kept inside it instead, and then
    // no pre-map, from the zipper's correspondence.
    let mut closest = first;
    for fitted in Premap::inside(&spline, contour, frame) {
        match solve_premapped(&fitted, samples) {
            Ok(fit) => return Ok(fit),
            Err(last) => closest = closest.min(last),
        }
    }
    if let Some(angles) = zipper::exterior_angles(contour.points()) {
        let knots = spline.knots();
        let start = |n: usize| zipper::start(&angles, knots, n);
        match solve_from(&spline, start, 0.0, samples) {
            Ok(fit) => return Ok(fit),
            Err(last) => closest = closest.min(last),
        }
    }
    Err(NsError::MapNotConverged {
        iterations: MAX_STEPS,
        correction: closest,
        points: contour.len(),
    })
}

/// Newton on the pre-mapped curve ([`solve_from`]).
fn solve_premapped(premap: &Premap, samples: usize) -> Result<Correspondence, f64> {
    solve_from(premap, |n| premap.start(n), -premap.beta, samples)
}

/// Newton on `curve` from `start(n)` on at least `samples` samples (more
/// where the start crowds), doubled while it fails up to
/// [`MAX_SAMPLES`]; `Err` the last correction.
fn solve_from(
    curve: &impl ClosedCurve,
    start: impl Fn(usize) -> Vec<f64>,
    rotation: f64,
    samples: usize,
) -> Result<Correspondence, f64> {
    // The start's crowding (largest over smallest step in S) asks for
    // about 64 samples per factor of it: a thin section's ends. (Capped
    // at MAX_SAMPLES: the zipper's start, unlike the pre-maps', is not
    // blended with the arc length, and a deep notch's crowding could ask
    // for gigabytes.)
    let probe = start(samples);
    let steps = probe.windows(2).map(|w| w[1] - w[0]);
    let crowding = steps.clone().fold(0.0, f64::max) / steps.fold(f64::INFINITY, f64::min);
    let wanted = (64.0 * crowding).min(MAX_SAMPLES as f64) as usize;
    let mut n = samples.max(wanted.next_power_of_two());
    loop {
        match solve_curve(curve, start(n), rotation) {
            Ok(fit) => return Ok(fit),
            Err(last) if n >= MAX_SAMPLES => return Err(last),
            Err(_) => n *= 2,
        }
    }
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

/// The start `S(t_j)` at `t_j = 2πj/n` of a correspondence known at the
/// curve's knots: knot `k` (parameter `knots[k]`, the period at
/// `knots[m]`) at the angle `phi[k] + shift.0 + shift.1`, `phi` increasing
/// from 0 at the first knot to `2π` at the last; linear between knots, by
/// whole turns beyond (the pre-map's start and the zipper's).
fn start_at_angles(phi: &[f64], knots: &[f64], shift: (f64, f64), n: usize) -> Vec<f64> {
    let m = phi.len() - 1;
    let length = knots[m];
    (0..n)
        .map(|j| {
            let target = TAU * j as f64 / n as f64 - shift.0 - shift.1;
            let turns = (target / TAU).floor();
            let f = target - turns * TAU;
            let k = phi.partition_point(|&p| p <= f).clamp(1, m) - 1;
            let w = ((f - phi[k]) / (phi[k + 1] - phi[k])).clamp(0.0, 1.0);
            knots[k] + w * (knots[k + 1] - knots[k]) + turns * length
        })
        .collect()
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
    use super::premap::SLIT_SAMPLES;
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
    /// a fallback's slit lies inside, and the fit converges.
    #[test]
    fn a_slit_inside_the_section_fits_where_the_first_fails() {
        for code in ["4706", "4106", "6930"] {
            let contour = sharp_naca(code);
            let points = contour.points();
            let spline = CurveSpline::closed(points);
            let frame = PrincipalFrame::of(&spline, points);
            let first = Premap::new(&spline, points, &frame);
            let slit: Vec<Complex64> = first.slit(SLIT_SAMPLES).collect();
            let leaves = contour.crossed_by(&slit) || !slit.iter().all(|&z| contour.encloses(z));
            assert!(leaves, "NACA {code}: the first pre-map's slit stays inside");
            assert!(
                solve_premapped(&first, 1024).is_err(),
                "NACA {code}: the first fits"
            );
            let fitted = Premap::inside(&spline, &contour, frame).next();
            let fitted = fitted.unwrap_or_else(|| panic!("NACA {code}: no slit inside"));
            let slit: Vec<Complex64> = fitted.slit(SLIT_SAMPLES).collect();
            assert!(!contour.crossed_by(&slit) && slit.iter().all(|&z| contour.encloses(z)));
            assert!(solve(&contour, 1024).is_ok(), "NACA {code}: not fitted");
        }
    }

    /// NACA 9906, 2906 and 6106 as the command fits them, and 6106, 8912
    /// and 9912 as `tests/section_maps.rs` builds them
    /// (`Contour::naca4`, 256 points), and its two corrugated membranes
    /// (an S and three waves): no pre-map's Newton converges (the
    /// first's slit leaves the section, and no slit the fallbacks try
    /// lies inside, or Newton fails after it), and Newton on the contour
    /// itself does from the zipper's start (module docs, "Sections no
    /// slit fits"; how close the maps come: `tests/section_maps.rs`). The
    /// start is within 2e-4 of the perimeter of the fitted correspondence
    /// (measured: 1.7e-5 to 1.0e-4). A six-lobed star
    /// `r = 1 + cos(6θ)/2`, where Newton stalls from the polar angle's
    /// start and the zipper's, is an error carrying the closest of the
    /// two, not a panic.
    #[test]
    fn the_zipper_starts_newton_where_no_slit_fits() {
        let command = ["9906", "2906", "6106"].map(|c| (format!("NACA {c}, sharp"), sharp_naca(c)));
        let tested = ["6106", "8912", "9912"]
            .map(|c| (format!("NACA {c}"), Contour::naca4(c, 256, 0.005).unwrap()));
        // And the corrugated membranes of `tests/section_maps.rs`.
        let corrugated = [(1.0, 0.02), (3.0, 0.04)].map(|(waves, amplitude): (f64, f64)| {
            let midline: Vec<(f64, f64)> = (0..=200)
                .map(|i| {
                    let x = i as f64 / 200.0;
                    (x, amplitude * (TAU * waves * x).sin())
                })
                .collect();
            let contour = Contour::membrane(&midline, 0.02, 512).unwrap();
            (format!("{waves} waves of {amplitude}"), contour)
        });
        for (code, contour) in command.iter().chain(&tested).chain(&corrugated) {
            let points = contour.points();
            let spline = CurveSpline::closed(points);
            let frame = PrincipalFrame::of(&spline, points);
            let first = Premap::new(&spline, points, &frame);
            assert!(solve_premapped(&first, 1024).is_err(), "{code}");
            for fitted in Premap::inside(&spline, contour, frame) {
                assert!(solve_premapped(&fitted, 1024).is_err(), "{code}");
            }
            let angles = zipper::exterior_angles(points).expect("the zipper's angles");
            let start = |n: usize| zipper::start(&angles, spline.knots(), n);
            let fit = solve_from(&spline, start, 0.0, 1024);
            let fit = fit.unwrap_or_else(|e| panic!("{code}: Newton from the zipper: {e}"));
            let away = start(fit.parameters.len())
                .iter()
                .zip(&fit.parameters)
                .map(|(s, fitted)| (s - fitted).abs())
                .fold(0.0, f64::max)
                / fit.period;
            println!("{code}: the zipper's start within {away:.2e} of the perimeter");
            assert!(away < 2e-4, "{code}: the start {away:.2e} off");
            assert!(solve(contour, 1024).is_ok(), "{code}: not fitted");
        }
        let star: Vec<(f64, f64)> = (0..512)
            .map(|k| {
                let t = TAU * k as f64 / 512.0;
                let r = 1.0 + 0.5 * (6.0 * t).cos();
                (r * t.cos(), r * t.sin())
            })
            .collect();
        let star = Contour::from_points(&star).unwrap();
        let spline = CurveSpline::closed(star.points());
        let frame = PrincipalFrame::of(&spline, star.points());
        let first = Premap::new(&spline, star.points(), &frame);
        assert_eq!(Premap::inside(&spline, &star, frame).count(), 0);
        let polar = solve_premapped(&first, 1024).map(|_| ()).unwrap_err();
        let angles = zipper::exterior_angles(star.points()).expect("the zipper's angles");
        let start = |n: usize| zipper::start(&angles, spline.knots(), n);
        let zipped = solve_from(&spline, start, 0.0, 1024)
            .map(|_| ())
            .unwrap_err();
        let fit = solve(&star, 1024);
        let Err(NsError::MapNotConverged { correction, .. }) = fit else {
            panic!("the star: {:?}", fit.map(|_| ()));
        };
        assert_eq!(correction, polar.min(zipped));
        assert!(correction.is_finite() && correction > 1e-3, "{correction}");
    }

    /// The contour `fwav aero2d --model ns --section naca<code>` fits: the
    /// NACA 4-digit section's surfaces (`contour::naca`'s, with the
    /// closed trailing edge) through 401 points by the cosine rule, its
    /// sharp trailing edge opened to 0.005 chords and closed by an arc on
    /// 512 points ([`Contour::with_blunt_trailing_edge`]).
    pub(super) fn sharp_naca(code: &str) -> Contour {
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
