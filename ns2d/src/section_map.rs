//! The conformal map from the exterior of the unit circle to the exterior
//! of the section.
//!
//! The section is the image of the unit circle `|ζ| = 1` under the Laurent
//! map
//!
//! ```text
//! z = F(ζ) = a ζ + z0 + Σ_{k=1..m} b_k ζ^(-k)
//! ```
//!
//! which is analytic and one-to-one outside the unit circle when the
//! section is a simple closed curve (Riemann's mapping theorem; the
//! coefficients of a general contour come from a numerical fit, those of a
//! circle and an ellipse are exact). A circle of radius `R` is `a = R`;
//! an ellipse of semi-axes `A` (along x) and `B` is Joukowski's map
//! `a = (A + B)/2`, `b_1 = (A - B)/2` (Milne-Thomson, *Theoretical
//! Hydrodynamics*, §6.31). Any other simple closed contour
//! ([`crate::Contour`]) gets its coefficients from Wegmann's Newton method
//! for the boundary correspondence ([`SectionMap::from_contour`]; accuracy
//! and cost in `correspondence.rs` and `tests/section_maps.rs`). The grid of [`crate::OGrid`] is the image of
//! the polar grid `ζ = exp(ξ + iθ)`; the map is conformal, so the
//! Laplacian in `(ξ, θ)` is the physical one times `J = |ζ F'(ζ)|²`.

use realfft::num_complex::Complex64;

use crate::contour::Contour;
use crate::correspondence;
use crate::error::NsError;

/// A section as the conformal image of the unit circle (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct SectionMap {
    /// Coefficient `a` of `ζ` (scale and rotation of the far field).
    a: Complex64,
    /// The constant `z0` (the centre of the far field).
    z0: Complex64,
    /// `b_k` of `ζ^(-k)`, `k = 1..`.
    b: Vec<Complex64>,
}

impl SectionMap {
    /// A circle of radius `radius` centred at the origin.
    ///
    /// # Errors
    /// [`NsError::BadSection`] when the radius is not a positive number.
    pub fn circle(radius: f64) -> Result<Self, NsError> {
        if !(radius.is_finite() && radius > 0.0) {
            return Err(NsError::BadSection {
                what: "circle radius",
                value: radius,
            });
        }
        Ok(Self {
            a: Complex64::new(radius, 0.0),
            z0: Complex64::new(0.0, 0.0),
            b: Vec::new(),
        })
    }

    /// An ellipse of semi-axes `semi_x` (along x) and `semi_y`, centred at
    /// `centre` (Joukowski's map; exact).
    ///
    /// # Errors
    /// [`NsError::BadSection`] when an axis is not a positive number.
    pub fn ellipse(semi_x: f64, semi_y: f64, centre: (f64, f64)) -> Result<Self, NsError> {
        for (what, value) in [
            ("ellipse semi-axis x", semi_x),
            ("ellipse semi-axis y", semi_y),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(NsError::BadSection { what, value });
            }
        }
        Ok(Self {
            a: Complex64::new(0.5 * (semi_x + semi_y), 0.0),
            z0: Complex64::new(centre.0, centre.1),
            b: vec![Complex64::new(0.5 * (semi_x - semi_y), 0.0)],
        })
    }

    /// The exterior map of `contour` with `terms` coefficients `b_k`
    /// (module docs): Wegmann's Newton method on `N` points round the
    /// circle (`N` the power of two at least twice the contour's points and
    /// `2 terms + 2`, at least 64), the coefficients the FFT modes of the
    /// converged boundary values, then checked one-to-one. `a` is real and
    /// positive (`θ = 0` maps to the contour's point where the correspondence
    /// puts it). Cost: 2–4 ms for 256 points (release, measured by
    /// `examples/fit_timing.rs` on this loaded machine), `O(N log N)` a
    /// Newton step.
    ///
    /// # Errors
    /// [`NsError::BadSection`] for `terms` outside `1..=4096`,
    /// [`NsError::MapNotConverged`] when Newton fails (a contour too thin
    /// or sharp for its points), [`NsError::MapNotUnivalent`] when the
    /// truncated series is not one-to-one outside the circle.
    pub fn from_contour(contour: &Contour, terms: usize) -> Result<Self, NsError> {
        Ok(Self::fitted(contour, terms)?.0)
    }

    /// [`Self::from_contour`], and the angle `θ` on the unit circle of each
    /// of the contour's points (where the map puts it: `F(e^{iθ})` is the
    /// point, to the fit's accuracy), for following the points of a
    /// deforming section ([`crate::Deformation::of_shapes`]).
    ///
    /// # Errors
    /// As [`Self::from_contour`].
    pub fn from_contour_with_angles(
        contour: &Contour,
        terms: usize,
    ) -> Result<(Self, Vec<f64>), NsError> {
        let (map, fit) = Self::fitted(contour, terms)?;
        let knots = crate::spline::CurveSpline::closed(contour.points())
            .knots()
            .to_vec();
        let angles = fit.angles(&knots[..contour.len()]);
        Ok((map, angles))
    }

    /// [`Self::from_contour`], and how far the map's boundary departs from
    /// the contour (the contour's units): the largest, over the fit's `N`
    /// samples, of the distance from the fitted point (on the spline
    /// through the contour's points) to the truncated series' boundary
    /// point, which is the sum of the modes the series leaves out. Between
    /// samples, and from a finer contour, the boundary may lie a little
    /// farther (NACA 6106: 3.3e-5 against 4.7e-5 measured). Where the
    /// contour has a corner or a fold, the series converges slowly and the
    /// grid's section is the contour smoothed: NACA 9112 from 256 points,
    /// 1.4e-3 chords with 128 terms (1.0e-3 measured from a finer
    /// contour); NACA 0012, 1.7e-5 (`tests/section_maps.rs`). One FFT of
    /// `N` more than the fit.
    ///
    /// # Errors
    /// As [`Self::from_contour`].
    pub fn from_contour_with_deviation(
        contour: &Contour,
        terms: usize,
    ) -> Result<(Self, f64), NsError> {
        let (map, fit) = Self::fitted(contour, terms)?;
        Ok((map, fit.truncation_deviation(terms)))
    }

    /// The fit behind [`Self::from_contour`]: the map, checked one-to-one,
    /// and the correspondence it came from.
    fn fitted(
        contour: &Contour,
        terms: usize,
    ) -> Result<(Self, correspondence::Correspondence), NsError> {
        if !(1..=4096).contains(&terms) {
            return Err(NsError::BadSection {
                what: "number of Laurent terms (1 to 4096)",
                value: terms as f64,
            });
        }
        let samples = (2 * contour.len())
            .max(2 * terms + 2)
            .next_power_of_two()
            .max(64);
        let fit = correspondence::solve(contour, samples)?;
        let modes = &fit.modes;
        let samples = modes.len();
        let map = Self {
            a: modes[1],
            z0: modes[0],
            b: (1..=terms)
                .map(|k| modes.get(samples - k).copied().unwrap_or_default())
                .collect(),
        };
        let zeros = map.derivative_zeros_outside();
        if zeros != 0 {
            return Err(NsError::MapNotUnivalent { terms, zeros });
        }
        Ok((map, fit))
    }

    /// The same section with its circle turned: `F(e^{iφ} ζ)` (the one
    /// freedom of the exterior map; the point at angle `θ` moves to
    /// `θ - φ`).
    #[must_use]
    pub fn turned_circle(&self, phi: f64) -> Self {
        Self {
            a: self.a * Complex64::from_polar(1.0, phi),
            z0: self.z0,
            b: self
                .b
                .iter()
                .enumerate()
                .map(|(k, b)| b * Complex64::from_polar(1.0, -(k as f64 + 1.0) * phi))
                .collect(),
        }
    }

    /// The map of the coefficients `[a, z0, b_1, …]` (at least two;
    /// not checked for univalence: [`Self::derivative_zeros_outside`]).
    pub(crate) fn from_coefficients(c: &[Complex64]) -> Self {
        Self {
            a: c[0],
            z0: c[1],
            b: c[2..].to_vec(),
        }
    }

    /// This section turned counter-clockwise by `angle` (radians) about
    /// the origin and then moved by `offset`: the map `e^{i angle} F + offset`.
    #[must_use]
    pub fn moved(&self, angle: f64, offset: Complex64) -> Self {
        let turn = Complex64::from_polar(1.0, angle);
        Self {
            a: turn * self.a,
            z0: turn * self.z0 + offset,
            b: self.b.iter().map(|b| turn * b).collect(),
        }
    }

    /// The coefficients `(a, z0, [b_1, b_2, ...])`.
    #[must_use]
    pub fn coefficients(&self) -> (Complex64, Complex64, &[Complex64]) {
        (self.a, self.z0, &self.b)
    }

    /// The number of zeros of `F'` in `|ζ| > 1` (0 for a one-to-one map),
    /// by the argument principle: `ζF'(ζ) ~ aζ` turns once round a large
    /// circle, so it turns `1 - zeros` times round the unit circle, sampled
    /// at 8 points per Laurent term (an FFT). A zero on the circle itself
    /// (a corner) counts as one.
    #[must_use]
    pub fn derivative_zeros_outside(&self) -> i64 {
        let m = (8 * (self.b.len() + 1)).next_power_of_two().max(64);
        let mut values = vec![Complex64::new(0.0, 0.0); m];
        values[1] = self.a;
        for (k, bk) in self.b.iter().enumerate() {
            values[m - k - 1] = -bk * (k as f64 + 1.0);
        }
        rustfft::FftPlanner::new()
            .plan_fft_inverse(m)
            .process(&mut values);
        if values.iter().any(|v| v.norm() == 0.0 || !v.is_finite()) {
            return 1;
        }
        let mut turn = 0.0;
        for j in 0..m {
            let (p, q) = (values[j], values[(j + 1) % m]);
            turn += (q / p).arg();
        }
        1 - (turn / std::f64::consts::TAU).round() as i64
    }

    /// The physical point `F(ζ)`.
    #[must_use]
    pub fn point(&self, zeta: Complex64) -> Complex64 {
        let inv = zeta.inv();
        let mut power = inv;
        let mut z = self.a * zeta + self.z0;
        for bk in &self.b {
            z += bk * power;
            power *= inv;
        }
        z
    }

    /// `ζ F'(ζ) = ∂z/∂ξ` at `ζ = exp(ξ + iθ)`; `∂z/∂θ` is `i` times it.
    #[must_use]
    pub fn radial_derivative(&self, zeta: Complex64) -> Complex64 {
        let inv = zeta.inv();
        let mut power = inv;
        let mut d = self.a * zeta;
        for (k, bk) in self.b.iter().enumerate() {
            d -= bk * power * (k as f64 + 1.0);
            power *= inv;
        }
        d
    }

    /// The area enclosed by the section, `π(|a|² - Σ k |b_k|²)` (the area
    /// theorem of univalent functions).
    #[must_use]
    pub fn area(&self) -> f64 {
        let tail: f64 = self
            .b
            .iter()
            .enumerate()
            .map(|(k, bk)| (k as f64 + 1.0) * bk.norm_sqr())
            .sum();
        std::f64::consts::PI * (self.a.norm_sqr() - tail)
    }

    /// `|a|`, the radius the far field sees.
    #[must_use]
    pub fn scale(&self) -> f64 {
        self.a.norm()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Joukowski's map puts the unit circle on the ellipse: every image
    /// point satisfies `x²/A² + y²/B² = 1`, and the area is `πAB`.
    #[test]
    fn the_joukowski_map_draws_the_ellipse() {
        let map = SectionMap::ellipse(0.5, 0.0625, (0.0, 0.0)).unwrap();
        for k in 0..64 {
            let theta = f64::from(k) * std::f64::consts::TAU / 64.0;
            let z = map.point(Complex64::from_polar(1.0, theta));
            let r = (z.re / 0.5).powi(2) + (z.im / 0.0625).powi(2);
            assert!((r - 1.0).abs() < 1e-12, "{r}");
        }
        let exact = std::f64::consts::PI * 0.5 * 0.0625;
        assert!((map.area() - exact).abs() < 1e-12 * exact);
    }

    /// `F = ζ + 0.6 ζ⁻²` has `F' = 1 - 1.2 ζ⁻³`, zero at the three cube
    /// roots of 1.2 (`|ζ| = 1.063 > 1`): not one-to-one, three zeros
    /// counted; the ellipse's `F'` vanishes only inside (`|ζ|² = b/a`).
    #[test]
    fn the_zeros_of_the_derivative_outside_are_counted() {
        let folded = SectionMap {
            a: Complex64::new(1.0, 0.0),
            z0: Complex64::new(0.0, 0.0),
            b: vec![Complex64::new(0.0, 0.0), Complex64::new(0.6, 0.0)],
        };
        assert_eq!(folded.derivative_zeros_outside(), 3);
        let ellipse = SectionMap::ellipse(1.0, 0.01, (0.0, 0.0)).unwrap();
        assert_eq!(ellipse.derivative_zeros_outside(), 0);
    }

    /// The derivative is the map's, by central differences.
    #[test]
    fn the_radial_derivative_is_the_maps() {
        let map = SectionMap::ellipse(0.5, 0.2, (0.1, 0.0)).unwrap();
        let (xi, theta, h) = (0.3, 1.1, 1e-6);
        let z = |x: f64| map.point(Complex64::from_polar(x.exp(), theta));
        let numeric = (z(xi + h) - z(xi - h)) / (2.0 * h);
        let exact = map.radial_derivative(Complex64::from_polar(xi.exp(), theta));
        assert!((numeric - exact).norm() < 1e-8);
    }
}
