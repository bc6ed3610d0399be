//! A section that changes its shape: a periodic history of conformal maps.
//!
//! A deforming section is given as its shape at `n` instants equally
//! spaced over a period (a membrane's mid-line samples from the system
//! analysis, made into contours, each with its map,
//! [`SectionMap::from_contour`]). Each coefficient of the map
//! `F(ζ, t) = a ζ + z0 + Σ b_k ζ^(-k)` is interpolated in time by the
//! trigonometric polynomial through its `n` samples (a discrete Fourier
//! series: smooth, periodic, exact for a history with fewer than `n/2`
//! harmonics), so the grid's velocity `∂z/∂t` and the wall's acceleration
//! `∂²z/∂t²` at fixed `ζ` are continuous. The sum of univalent maps need
//! not be univalent: every interpolated map is checked at `4n` instants
//! when the history is built ([`Deformation::periodic`]).
//!
//! The normalisation of [`SectionMap::from_contour`] (`a` real and
//! positive) fixes each sample's correspondence, so that nearby shapes
//! have nearby coefficients and the interpolation is meaningful; maps
//! built otherwise (a rotated map, [`SectionMap::moved`]) are interpolated
//! as given.

use realfft::num_complex::Complex64;

use crate::error::NsError;
use crate::section_map::SectionMap;

/// Interpolated maps checked for univalence per sample of the history.
const CHECKS_PER_SAMPLE: usize = 4;

/// The map's coefficients `[a, z0, b_1, …, b_m]` and their first and
/// second time derivatives at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct MapState {
    /// `[a, z0, b_1, …]`.
    pub coefficients: Vec<Complex64>,
    /// Their rates `d/dt`.
    pub rate: Vec<Complex64>,
    /// Their accelerations `d²/dt²`.
    pub acceleration: Vec<Complex64>,
}

impl MapState {
    /// The map of the coefficients.
    #[must_use]
    pub fn map(&self) -> SectionMap {
        SectionMap::from_coefficients(&self.coefficients)
    }
}

/// A periodic history of a section's conformal map (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Deformation {
    period: f64,
    /// `spectrum[h][p]`: the discrete Fourier transform over the samples
    /// of coefficient `p`, divided by the number of samples.
    spectrum: Vec<Vec<Complex64>>,
}

impl Deformation {
    /// The history through `maps`, sample `i` at time `i · period / n`
    /// (module docs). Maps with fewer Laurent terms than the longest are
    /// padded with zeros. Cost `O(n² m)` for `n` samples of `m` terms, and
    /// `4n` univalence checks.
    ///
    /// # Errors
    /// [`NsError::BadSection`] for no maps or a period that is not a
    /// positive number; [`NsError::MapNotUnivalent`] when an interpolated
    /// map between samples folds (samples too far apart for their shapes'
    /// change: give more).
    pub fn periodic(maps: &[SectionMap], period: f64) -> Result<Self, NsError> {
        if maps.is_empty() {
            return Err(NsError::BadSection {
                what: "number of shapes in a deformation history (at least 1)",
                value: 0.0,
            });
        }
        if !(period.is_finite() && period > 0.0) {
            return Err(NsError::BadSection {
                what: "deformation period",
                value: period,
            });
        }
        let terms = maps
            .iter()
            .map(|m| m.coefficients().2.len())
            .max()
            .unwrap_or(0);
        let samples: Vec<Vec<Complex64>> = maps
            .iter()
            .map(|m| {
                let (a, z0, b) = m.coefficients();
                let mut c = Vec::with_capacity(terms + 2);
                c.push(a);
                c.push(z0);
                c.extend_from_slice(b);
                c.resize(terms + 2, Complex64::new(0.0, 0.0));
                c
            })
            .collect();
        let n = samples.len();
        let spectrum = (0..n)
            .map(|h| {
                let mut row = vec![Complex64::new(0.0, 0.0); terms + 2];
                for (i, sample) in samples.iter().enumerate() {
                    let phase = -std::f64::consts::TAU * ((h * i) % n) as f64 / n as f64;
                    let e = Complex64::from_polar(1.0 / n as f64, phase);
                    for (r, c) in row.iter_mut().zip(sample) {
                        *r += e * c;
                    }
                }
                row
            })
            .collect();
        let deformation = Self { period, spectrum };
        let checks = CHECKS_PER_SAMPLE * n;
        for i in 0..checks {
            let map = deformation.state(period * i as f64 / checks as f64).map();
            let zeros = map.derivative_zeros_outside();
            if zeros != 0 {
                return Err(NsError::MapNotUnivalent { terms, zeros });
            }
        }
        Ok(deformation)
    }

    /// The history of a section's shapes, each a map with the angles on
    /// the unit circle of the same material points (the `i`-th point of
    /// every shape is the same point of the section:
    /// [`SectionMap::from_contour_with_angles`] of contours with their
    /// points in step), sample `i` at `i · period / n`. Each map's circle
    /// is first turned ([`SectionMap::turned_circle`]) to put the points,
    /// on the mean, at the first shape's angles: the exterior map is
    /// fixed only up to that turn, and [`SectionMap::from_contour`]'s
    /// choice (`a` real) would make the wall's grid points slide round a
    /// section that merely pitches, by the pitch angle. Turned, a pitch
    /// given as shapes is the pitched map ([`SectionMap::moved`]), and the
    /// wall's grid points slide only as far as the shape's change moves
    /// the map's correspondence.
    ///
    /// # Errors
    /// As [`Self::periodic`]; [`NsError::BadSection`] when the shapes do
    /// not have the same number of points.
    pub fn of_shapes(shapes: &[(SectionMap, Vec<f64>)], period: f64) -> Result<Self, NsError> {
        Self::periodic(&Self::followed(shapes)?, period)
    }

    /// The maps of [`Self::of_shapes`]: each shape's map with its circle
    /// turned to put its points, on the mean, at the first shape's
    /// angles.
    ///
    /// # Errors
    /// [`NsError::BadSection`] when the shapes do not have the same
    /// number of points.
    pub fn followed(shapes: &[(SectionMap, Vec<f64>)]) -> Result<Vec<SectionMap>, NsError> {
        let Some((_, reference)) = shapes.first() else {
            return Ok(Vec::new());
        };
        shapes
            .iter()
            .map(|(map, angles)| {
                if angles.len() != reference.len() {
                    return Err(NsError::BadSection {
                        what: "points of a deformation's shape (as many as the first shape's)",
                        value: angles.len() as f64,
                    });
                }
                // The circular mean of the angles' differences.
                let mean: Complex64 = angles
                    .iter()
                    .zip(reference)
                    .map(|(a, r)| Complex64::from_polar(1.0, a - r))
                    .sum();
                Ok(map.turned_circle(mean.arg()))
            })
            .collect()
    }

    /// The period.
    #[must_use]
    pub fn period(&self) -> f64 {
        self.period
    }

    /// The number of Laurent terms `b_k` of the maps.
    #[must_use]
    pub fn terms(&self) -> usize {
        self.spectrum[0].len() - 2
    }

    /// The map's coefficients and their rates at time `t` (the
    /// trigonometric interpolation of module docs; a Nyquist harmonic of
    /// an even number of samples taken as its cosine). Cost `O(n m)`.
    #[must_use]
    pub fn state(&self, t: f64) -> MapState {
        let n = self.spectrum.len();
        let len = self.spectrum[0].len();
        let zero = Complex64::new(0.0, 0.0);
        let mut state = MapState {
            coefficients: vec![zero; len],
            rate: vec![zero; len],
            acceleration: vec![zero; len],
        };
        let omega = std::f64::consts::TAU / self.period;
        let phase = omega * t;
        for (h, row) in self.spectrum.iter().enumerate() {
            let (terms, count) = trigonometric_terms(h, n);
            for &(weight, f) in &terms[..count] {
                let e = Complex64::from_polar(weight, f * phase);
                let d = Complex64::new(0.0, f * omega);
                let (e1, e2) = (e * d, e * d * d);
                for (p, c) in row.iter().enumerate() {
                    state.coefficients[p] += e * c;
                    state.rate[p] += e1 * c;
                    state.acceleration[p] += e2 * c;
                }
            }
        }
        state
    }

    /// The map at time `t`.
    #[must_use]
    pub fn map_at(&self, t: f64) -> SectionMap {
        self.state(t).map()
    }
}

/// How harmonic `h` of the discrete Fourier transform of `n` equally
/// spaced samples enters their trigonometric interpolation: its first
/// `count` terms `(weight, frequency)`, the frequency in cycles a period
/// and signed (`h` below `n/2`, `h - n` above), the Nyquist harmonic of
/// an even `n` split half and half between `±n/2` (taken as its cosine,
/// so a real history stays real between its samples).
#[must_use]
pub fn trigonometric_terms(h: usize, n: usize) -> ([(f64, f64); 2], usize) {
    let f = h as f64;
    if 2 * h == n {
        ([(0.5, f), (0.5, -f)], 2)
    } else if 2 * h < n {
        ([(1.0, f), (0.0, 0.0)], 1)
    } else {
        ([(1.0, f - n as f64), (0.0, 0.0)], 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An ellipse moved by `z0(t) = 0.3 i sin(2πt/T)` and turned by
    /// `0.2 sin`: the centre's history is one harmonic, interpolated
    /// exactly with its rate and acceleration from 8 samples; the turn's
    /// `e^{iα}` has Bessel harmonics, `J_4(0.2) ≈ 3e-6` beyond 8 samples'
    /// reach, so its coefficient is within 1e-5.
    #[test]
    fn a_harmonic_history_is_interpolated_with_its_derivatives() {
        let period = 2.0;
        let w = std::f64::consts::TAU / period;
        let ellipse = SectionMap::ellipse(0.5, 0.1, (0.0, 0.0)).unwrap();
        let at = |t: f64| {
            ellipse.moved(
                0.2 * (w * t).sin(),
                Complex64::new(0.0, 0.3 * (w * t).sin()),
            )
        };
        let maps: Vec<SectionMap> = (0..8).map(|i| at(period * f64::from(i) / 8.0)).collect();
        let history = Deformation::periodic(&maps, period).unwrap();
        for t in [0.1, 0.77, 1.3] {
            let s = history.state(t);
            let exact = 0.3 * (w * t).sin();
            assert!((s.coefficients[1] - Complex64::new(0.0, exact)).norm() < 1e-12);
            let rate = 0.3 * w * (w * t).cos();
            assert!((s.rate[1] - Complex64::new(0.0, rate)).norm() < 1e-12);
            let accel = -0.3 * w * w * (w * t).sin();
            assert!((s.acceleration[1] - Complex64::new(0.0, accel)).norm() < 1e-11);
            let a = at(t).coefficients().0;
            assert!(
                (s.coefficients[0] - a).norm() < 1e-5,
                "{}",
                (s.coefficients[0] - a).norm()
            );
        }
    }

    /// A membrane pitched by 0.1 rad, fitted afresh (`a` real, so its
    /// circle turned by the pitch), becomes the first shape's map turned
    /// by the pitch once its points are followed: the pitched map.
    #[test]
    fn a_pitched_shape_is_the_turned_map_once_its_points_are_followed() {
        let midline = [(-0.5, 0.0), (0.0, 0.02), (0.5, 0.0)];
        let pitch = 0.1;
        let turn = Complex64::from_polar(1.0, pitch);
        let turned: Vec<(f64, f64)> = midline
            .iter()
            .map(|&(x, y)| {
                let z = turn * Complex64::new(x, y);
                (z.re, z.im)
            })
            .collect();
        let fit = |m: &[(f64, f64)]| {
            let contour = crate::Contour::membrane(m, 0.04, 256).unwrap();
            SectionMap::from_contour_with_angles(&contour, 64).unwrap()
        };
        let shapes = [fit(&midline), fit(&turned)];
        let a = shapes[1].0.coefficients().0;
        assert!(a.im.abs() < 1e-6 * a.re, "a real as fitted: {a}");
        let history = Deformation::of_shapes(&shapes, 1.0).unwrap();
        let expected = shapes[0].0.moved(pitch, Complex64::new(0.0, 0.0));
        let got = history.map_at(0.5);
        let (a, z0, b) = expected.coefficients();
        let (ga, gz0, gb) = got.coefficients();
        let error = (a - ga).norm()
            + (z0 - gz0).norm()
            + b.iter()
                .zip(gb)
                .map(|(x, y)| (x - y).norm())
                .fold(0.0, f64::max);
        assert!(error < 1e-4, "{error:.3e}");
    }

    #[test]
    fn an_empty_history_or_a_bad_period_is_refused() {
        assert!(Deformation::periodic(&[], 1.0).is_err());
        let circle = SectionMap::circle(1.0).unwrap();
        assert!(Deformation::periodic(&[circle], f64::NAN).is_err());
    }
}
