//! The rigid part of a deforming section's history ([`RigidDeflection`]):
//! how far the section is carried and turned as a whole, and how much its
//! shape changes beyond that.
//!
//! The aerodynamic discipline's section deforms as the wing's system
//! analysis found: the mid-span section of the built-in FWAV heaves
//! ±0.13 chords with the wing's bending and pitches about ±1.4° with its
//! twist, and its mid-line bends from a straight line by at most 0.1 % of
//! the chord (`tests/data/fwav_cycle1_section.json`). A rigid motion is
//! the solver's moving frame, exact and free ([`fwav_ns2d::Motion`]); only
//! the change of shape needs the grid moved at every step
//! ([`fwav_ns2d::Flow::deforming`]), which costs half again a rigid step.
//! Its change of shape, small as it is, moves CT by 3.7 %, so the
//! default leaves nothing out and keeps the whole deformation on the
//! moving grid (`ns2d/README.md`, "The deformation's rigid part";
//! [`super::ViscousSection::run_deflecting`]). There too the rigid part
//! is taken apart: each sample's map is the map of its change of shape
//! moved rigidly by this fit (`ViscousSection::deformation`), which is
//! what makes the two ways agree (0.07 % in the first stroke's CT).
//!
//! Each sample's rigid part is the least-squares fit of its mid-line
//! points to the undeformed straight mid-line, point by point (the `i`-th
//! point of every sample is the same material point): the rotation and
//! translation of the 2D Procrustes problem (Kabsch), the undeformed point
//! at its arc length along the sample from the leading edge. The
//! samples' translations and angles are interpolated in time by the
//! trigonometric polynomial through them, as [`fwav_ns2d::Deformation`]
//! interpolates the maps' coefficients, so the frame's velocity and
//! acceleration are continuous.

use fwav_ns2d::{trigonometric_terms, Complex64};

/// Most samples a [`RigidDeflection`] holds (its spectrum is a fixed
/// array: a plain value, evaluated every step without allocating). A
/// history of more samples is not fitted (it runs on the moving grid).
pub const MAX_DEFLECTION_SAMPLES: usize = 64;

/// The rigid part of a periodic deformation history (module docs), in the
/// body frame of the section's path: the frame's origin at the pivot, the
/// undeformed chord along `+x`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidDeflection {
    period: f64,
    samples: usize,
    /// `spectrum[h]`: the discrete Fourier transform over the samples of
    /// the translation (complex) and the angle (real part), divided by
    /// the number of samples.
    spectrum: [[Complex64; 2]; MAX_DEFLECTION_SAMPLES],
    shape_change: f64,
}

/// The rigid deflection at one instant: the body axes carried by
/// `translation` and turned counter-clockwise by `angle` (radians), with
/// their rates.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DeflectionState {
    /// Displacement of the frame's origin, chords (`x + i y`).
    pub translation: Complex64,
    /// Its velocity.
    pub velocity: Complex64,
    /// Its acceleration.
    pub acceleration: Complex64,
    /// Counter-clockwise turn of the body axes, radians.
    pub angle: f64,
    /// Its rate.
    pub rate: f64,
    /// Its acceleration.
    pub angular_acceleration: f64,
}

impl RigidDeflection {
    /// The rigid part of `samples` (mid-line points from the leading edge,
    /// chords, in the path's axes with the undeformed leading edge at the
    /// origin; sample `i` at `i · period / n`, as
    /// [`super::ViscousSection::run_deforming`] takes them), the frame's
    /// origin `pivot` chords along the chord from the leading edge. None
    /// for a history this cannot hold: no samples or more than
    /// [`MAX_DEFLECTION_SAMPLES`], a sample of fewer than two points or
    /// of another number than the first's, or of no length. Cost
    /// `O(n²)` for `n` samples, and `O(n p)` for their `p` points.
    pub fn fit(samples: &[Vec<(f64, f64)>], pivot: f64, period: f64) -> Option<Self> {
        let n = samples.len();
        let points = samples.first()?.len();
        if n > MAX_DEFLECTION_SAMPLES || points < 2 || !(period.is_finite() && period > 0.0) {
            return None;
        }
        let mut fits = Vec::with_capacity(n);
        let mut shape_change: f64 = 0.0;
        for sample in samples {
            if sample.len() != points {
                return None;
            }
            let (translation, angle, change) = fit_sample(sample, pivot)?;
            shape_change = shape_change.max(change);
            fits.push((translation, angle));
        }
        // Angles taken continuously from sample to sample.
        for i in 1..n {
            let step = (fits[i].1 - fits[i - 1].1 + std::f64::consts::PI)
                .rem_euclid(std::f64::consts::TAU)
                - std::f64::consts::PI;
            fits[i].1 = fits[i - 1].1 + step;
        }
        let zero = Complex64::new(0.0, 0.0);
        let mut spectrum = [[zero; 2]; MAX_DEFLECTION_SAMPLES];
        for (h, row) in spectrum.iter_mut().take(n).enumerate() {
            for (i, &(translation, angle)) in fits.iter().enumerate() {
                let phase = -std::f64::consts::TAU * ((h * i) % n) as f64 / n as f64;
                let e = Complex64::from_polar(1.0 / n as f64, phase);
                row[0] += e * translation;
                row[1] += e * angle;
            }
        }
        Some(Self {
            period,
            samples: n,
            spectrum,
            shape_change,
        })
    }

    /// The largest distance, chords, of a sample's mid-line point from
    /// its undeformed place carried by the sample's rigid fit: how much
    /// the shape itself changes.
    #[must_use]
    pub fn shape_change(&self) -> f64 {
        self.shape_change
    }

    /// The period, chords travelled.
    #[must_use]
    pub fn period(&self) -> f64 {
        self.period
    }

    /// The deflection at time `t` (the trigonometric interpolation; a
    /// Nyquist harmonic of an even number of samples taken as its
    /// cosine). Cost `O(n)`.
    #[must_use]
    pub fn state(&self, t: f64) -> DeflectionState {
        let n = self.samples;
        let omega = std::f64::consts::TAU / self.period;
        let phase = omega * t;
        let mut s = DeflectionState::default();
        for (h, row) in self.spectrum.iter().take(n).enumerate() {
            let (terms, count) = trigonometric_terms(h, n);
            for &(weight, f) in &terms[..count] {
                let e = Complex64::from_polar(weight, f * phase);
                let d = Complex64::new(0.0, f * omega);
                let (e1, e2) = (e * d, e * d * d);
                s.translation += e * row[0];
                s.velocity += e1 * row[0];
                s.acceleration += e2 * row[0];
                s.angle += (e * row[1]).re;
                s.rate += (e1 * row[1]).re;
                s.angular_acceleration += (e2 * row[1]).re;
            }
        }
        s
    }

    /// `samples` (as [`Self::fit`] took them) with each one's rigid part
    /// taken out: its points carried back by the deflection at the
    /// sample's time, the change of shape alone.
    #[must_use]
    pub fn residual(&self, samples: &[Vec<(f64, f64)>], pivot: f64) -> Vec<Vec<(f64, f64)>> {
        let n = samples.len();
        samples
            .iter()
            .enumerate()
            .map(|(i, sample)| {
                let s = self.state(self.period * i as f64 / n as f64);
                let back = Complex64::from_polar(1.0, -s.angle);
                sample
                    .iter()
                    .map(|&(x, y)| {
                        let z = back * (Complex64::new(x - pivot, y) - s.translation);
                        (z.re + pivot, z.im)
                    })
                    .collect()
            })
            .collect()
    }

    /// The largest speed of a point of the section, chords from the
    /// origin at most `arm`, from the deflection alone, over `4n`
    /// instants of a period.
    pub(super) fn peak_speed(&self, arm: f64) -> f64 {
        let checks = 4 * self.samples;
        (0..checks)
            .map(|i| {
                let s = self.state(self.period * i as f64 / checks as f64);
                s.velocity.norm() + s.rate.abs() * arm
            })
            .fold(0.0, f64::max)
    }
}

/// One sample's rigid fit: the translation of the frame's origin, the
/// turn, and the largest distance of a point from its fitted place. None
/// for a sample of no length.
fn fit_sample(sample: &[(f64, f64)], pivot: f64) -> Option<(Complex64, f64, f64)> {
    let placed: Vec<Complex64> = sample
        .iter()
        .map(|&(x, y)| Complex64::new(x - pivot, y))
        .collect();
    // The undeformed places: arc length from the leading edge, less the pivot.
    let mut along = Vec::with_capacity(placed.len());
    let mut s = 0.0;
    for (i, p) in placed.iter().enumerate() {
        if i > 0 {
            s += (p - placed[i - 1]).norm();
        }
        along.push(s - pivot);
    }
    if !(s.is_finite() && s > 0.0) {
        return None;
    }
    let count = placed.len() as f64;
    let centre: Complex64 = placed.iter().sum::<Complex64>() / count;
    let middle: f64 = along.iter().sum::<f64>() / count;
    // Kabsch in 2D: the turn is the argument of the cross-covariance.
    let covariance: Complex64 = placed
        .iter()
        .zip(&along)
        .map(|(p, q)| (p - centre) * (q - middle))
        .sum();
    let angle = covariance.arg();
    let turn = Complex64::from_polar(1.0, angle);
    let translation = centre - turn * middle;
    let change = placed
        .iter()
        .zip(&along)
        .map(|(p, q)| (p - translation - turn * q).norm())
        .fold(0.0, f64::max);
    Some((translation, angle, change))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A straight mid-line heaved by `0.13 sin` and turned by `0.025 cos`
    /// about mid-chord: each sample's fit is its motion, the shape change
    /// is rounding, and the interpolation gives the history's rates: its
    /// heave is one harmonic (exact from 40 samples), its turn's
    /// displacement of the points holds the Bessel harmonics of `e^{iα}`
    /// (`J_2(0.025) ≈ 8e-5`), fitted here as the angle itself (exact).
    #[test]
    fn a_rigidly_moved_mid_line_is_its_motion() {
        let (n, period) = (40, 4.5);
        let omega = std::f64::consts::TAU / period;
        let motion = |t: f64| (0.13 * (omega * t).sin(), 0.025 * (omega * t).cos());
        let samples: Vec<Vec<(f64, f64)>> = (0..n)
            .map(|i| {
                let (h, a) = motion(period * i as f64 / n as f64);
                let turn = Complex64::from_polar(1.0, a);
                (0..=52)
                    .map(|k| {
                        let z = Complex64::new(0.5, h) + turn * (k as f64 / 52.0 - 0.5);
                        (z.re, z.im)
                    })
                    .collect()
            })
            .collect();
        let d = RigidDeflection::fit(&samples, 0.5, period).unwrap();
        assert!(d.shape_change() < 1e-12, "{}", d.shape_change());
        for t in [0.0, 0.37, 1.9, 3.3] {
            let s = d.state(t);
            let (h, a) = motion(t);
            let (c, si) = ((omega * t).cos(), (omega * t).sin());
            assert!((s.translation - Complex64::new(0.0, h)).norm() < 1e-12);
            assert!((s.velocity - Complex64::new(0.0, 0.13 * omega * c)).norm() < 1e-12);
            assert!((s.acceleration + Complex64::new(0.0, h * omega * omega)).norm() < 1e-12);
            assert!((s.angle - a).abs() < 1e-12);
            assert!((s.rate + 0.025 * omega * si).abs() < 1e-12);
            assert!((s.angular_acceleration + a * omega * omega).abs() < 1e-12);
        }
    }

    /// A mid-line bent into an arc of height `b` has no rigid fit that
    /// takes the bend out: the shape change is of the order of `b`.
    #[test]
    fn a_bent_mid_line_keeps_its_bend_as_shape_change() {
        let b = 1e-3;
        let arc: Vec<(f64, f64)> = (0..=52)
            .map(|k| {
                let x = k as f64 / 52.0;
                (x, 4.0 * b * x * (1.0 - x))
            })
            .collect();
        let d = RigidDeflection::fit(&[arc.clone(), arc], 0.5, 1.0).unwrap();
        // The least-squares line through a parabola of height b leaves
        // between b/3 (the middle) and 2b/3 (the ends).
        assert!(d.shape_change() > 0.3 * b && d.shape_change() < 0.7 * b);
    }

    /// A bent mid-line heaved and turned: the residual of each sample is
    /// the same bent line wherever the motion took it (the rigid part
    /// taken out is the motion's, about the pivot).
    #[test]
    fn the_residual_is_the_shape_without_its_motion() {
        let (n, period, b) = (8, 2.0, 1e-3);
        let bent: Vec<(f64, f64)> = (0..=20)
            .map(|k| {
                let x = k as f64 / 20.0;
                (x, 4.0 * b * x * (1.0 - x))
            })
            .collect();
        let samples: Vec<Vec<(f64, f64)>> = (0..n)
            .map(|i| {
                let phase = std::f64::consts::TAU * i as f64 / n as f64;
                let turn = Complex64::from_polar(1.0, 0.03 * phase.sin());
                let lift = Complex64::new(0.01 * phase.cos(), 0.13 * phase.sin());
                bent.iter()
                    .map(|&(x, y)| {
                        let z = Complex64::new(0.5, 0.0) + lift + turn * Complex64::new(x - 0.5, y);
                        (z.re, z.im)
                    })
                    .collect()
            })
            .collect();
        let d = RigidDeflection::fit(&samples, 0.5, period).unwrap();
        let residual = d.residual(&samples, 0.5);
        for shape in &residual[1..] {
            for (p, q) in shape.iter().zip(&residual[0]) {
                assert!((p.0 - q.0).hypot(p.1 - q.1) < 1e-12, "{p:?} {q:?}");
            }
        }
        // Its own fit is no motion.
        let again = RigidDeflection::fit(&residual, 0.5, period).unwrap();
        for i in 0..n {
            let s = again.state(period * i as f64 / n as f64);
            assert!(
                s.translation.norm() < 1e-12 && s.angle.abs() < 1e-12,
                "{s:?}"
            );
        }
    }

    #[test]
    fn a_history_it_cannot_hold_is_none() {
        let line = vec![(0.0, 0.0), (1.0, 0.0)];
        assert!(RigidDeflection::fit(&[], 0.5, 1.0).is_none());
        assert!(RigidDeflection::fit(&[vec![(0.0, 0.0)]], 0.5, 1.0).is_none());
        assert!(RigidDeflection::fit(&[vec![(0.0, 0.0), (0.0, 0.0)]], 0.5, 1.0).is_none());
        assert!(RigidDeflection::fit(&vec![line.clone(); 65], 0.5, 1.0).is_none());
        assert!(RigidDeflection::fit(&[line.clone(), vec![(0.0, 0.0)]], 0.5, 1.0).is_none());
        assert!(RigidDeflection::fit(&[line], 0.5, 0.0).is_none());
    }
}
