//! NACA 4-digit sections with a rounded trailing edge.
//!
//! Thickness and camber are those of Abbott & von Doenhoff, *Theory of
//! Wing Sections* (1959), §6.4, on a unit chord, with the closed
//! trailing-edge thickness coefficient (`-0.1036 x⁴`, the surfaces meet
//! at `x = 1`):
//!
//! ```text
//! y_t = 5t (0.2969 √x - 0.1260 x - 0.3516 x² + 0.2843 x³ - 0.1036 x⁴)
//! y_c = m/p² (2px - x²)                 x < p
//!     = m/(1-p)² ((1 - 2p) + 2px - x²)  x ≥ p
//! upper/lower = (x, y_c) ± y_t (-sin φ, cos φ),  tan φ = dy_c/dx
//! ```
//!
//! The sharp trailing edge (a corner, where a conformal map's derivative
//! vanishes) is rounded by the circle of radius `r` tangent to both
//! surfaces: the surfaces end at their tangent points (found by Newton on
//! the two camber-x positions whose inward normals, `r` long, reach the
//! same centre) and the arc round the back joins them; the section then
//! ends a little ahead of `x = 1` (the circle sits inside the wedge).
//!
//! Points: cosine spacing along each surface (fine at both edges), one
//! sixteenth of them (at least 6) on the arc.

use realfft::num_complex::Complex64;

use super::Contour;
use crate::error::NsError;

/// The NACA 4-digit parameters, fractions of the chord.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Naca4 {
    camber: f64,
    position: f64,
    thickness: f64,
}

impl Naca4 {
    pub(crate) fn parse(code: &str) -> Result<Self, NsError> {
        let bad = || NsError::BadNaca {
            code: code.to_owned(),
        };
        let code_trim = code.trim();
        let code_trim = code_trim
            .strip_prefix("NACA")
            .or_else(|| code_trim.strip_prefix("naca"))
            .unwrap_or(code_trim)
            .trim();
        let digits: Vec<u32> = code_trim
            .chars()
            .map(|c| c.to_digit(10))
            .collect::<Option<_>>()
            .ok_or_else(bad)?;
        let [m, p, t1, t2] = digits[..] else {
            return Err(bad());
        };
        let thickness = f64::from(10 * t1 + t2) / 100.0;
        if thickness == 0.0 || (m > 0 && p == 0) {
            return Err(bad());
        }
        Ok(Self {
            camber: f64::from(m) / 100.0,
            position: f64::from(p) / 10.0,
            thickness,
        })
    }

    fn half_thickness(&self, x: f64) -> f64 {
        let x = x.max(0.0);
        5.0 * self.thickness
            * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                - 0.1036 * x.powi(4))
    }

    /// Camber `y_c` and its slope at `x`.
    fn camber_line(&self, x: f64) -> (f64, f64) {
        let (m, p) = (self.camber, self.position);
        if m == 0.0 {
            (0.0, 0.0)
        } else if x < p {
            (
                m / (p * p) * (2.0 * p * x - x * x),
                2.0 * m / (p * p) * (p - x),
            )
        } else {
            let q = (1.0 - p) * (1.0 - p);
            (
                m / q * ((1.0 - 2.0 * p) + 2.0 * p * x - x * x),
                2.0 * m / q * (p - x),
            )
        }
    }

    /// The surface point at camber position `x`; `side` +1 upper, -1 lower.
    pub(crate) fn surface(&self, x: f64, side: f64) -> Complex64 {
        let (yc, slope) = self.camber_line(x);
        let normal = Complex64::new(-slope, 1.0) / slope.hypot(1.0);
        Complex64::new(x, yc) + normal * (side * self.half_thickness(x))
    }

    /// The centre a distance `r` inside the surface at `x` (along its
    /// inward normal).
    fn inward_centre(&self, x: f64, side: f64, r: f64) -> Complex64 {
        let h = 1e-5;
        let tangent = self.surface(x + h, side) - self.surface(x - h, side);
        let tangent = tangent / tangent.norm();
        // Upper surface (x increasing): inward is clockwise of the
        // tangent; lower: counterclockwise.
        let inward = Complex64::new(0.0, -side) * tangent;
        self.surface(x, side) + inward * r
    }

    /// The camber positions of the upper and lower tangent points of the
    /// trailing-edge circle of radius `r`, and its centre.
    fn trailing_edge_circle(&self, r: f64) -> Option<(f64, f64, Complex64)> {
        let mut x = [1.0 - 4.0 * r, 1.0 - 4.0 * r];
        let residual =
            |x: [f64; 2]| self.inward_centre(x[0], 1.0, r) - self.inward_centre(x[1], -1.0, r);
        for _ in 0..50 {
            let f = residual(x);
            if f.norm() < 1e-11 {
                let centre = self.inward_centre(x[0], 1.0, r);
                return Some((x[0], x[1], centre));
            }
            let h = 1e-6;
            let du = (residual([x[0] + h, x[1]]) - residual([x[0] - h, x[1]])) / (2.0 * h);
            let dl = (residual([x[0], x[1] + h]) - residual([x[0], x[1] - h])) / (2.0 * h);
            let det = du.re * dl.im - du.im * dl.re;
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let step0 = (f.re * dl.im - f.im * dl.re) / det;
            let step1 = (du.re * f.im - du.im * f.re) / det;
            x = [
                (x[0] - step0).clamp(0.3, 1.0),
                (x[1] - step1).clamp(0.3, 1.0),
            ];
        }
        None
    }
}

impl Contour {
    /// The NACA 4-digit section `code` (e.g. `"0012"`, `"NACA 2412"`) of
    /// unit chord from `x = 0`, its trailing edge rounded by a circle of
    /// radius `te_radius` (chords) tangent to both surfaces, on `points`
    /// points (module docs of `contour/naca.rs`). Cost `O(points)`.
    ///
    /// # Errors
    /// [`NsError::BadNaca`] for a bad designation, [`NsError::BadSection`]
    /// for a radius outside `(0, 0.05]` or fewer than 32 points or when no
    /// tangent circle of that radius fits, and the [`Contour::from_points`]
    /// checks.
    pub fn naca4(code: &str, points: usize, te_radius: f64) -> Result<Self, NsError> {
        let naca = Naca4::parse(code)?;
        if !(te_radius > 0.0 && te_radius <= 0.05) {
            return Err(NsError::BadSection {
                what: "NACA trailing-edge radius (0 < r <= 0.05 chord)",
                value: te_radius,
            });
        }
        if points < 32 {
            return Err(NsError::BadSection {
                what: "NACA section's number of points (at least 32)",
                value: points as f64,
            });
        }
        let (x_upper, x_lower, centre) =
            naca.trailing_edge_circle(te_radius)
                .ok_or(NsError::BadSection {
                    what: "NACA trailing-edge radius (no circle of it touches both surfaces)",
                    value: te_radius,
                })?;
        let arc = (points / 16).max(6);
        let per_side = (points - arc) / 2;
        let mut z = Vec::with_capacity(points);
        let cosine = |i: usize, end: f64| {
            let beta = std::f64::consts::PI * i as f64 / per_side as f64;
            end * 0.5 * (1.0 - beta.cos())
        };
        for i in (0..=per_side).rev() {
            z.push(naca.surface(cosine(i, x_upper), 1.0));
        }
        for i in 1..=per_side {
            z.push(naca.surface(cosine(i, x_lower), -1.0));
        }
        let from = (z[z.len() - 1] - centre).arg();
        let mut to = (z[0] - centre).arg();
        if to <= from {
            to += std::f64::consts::TAU;
        }
        let remaining = points - z.len();
        for i in 1..=remaining {
            let phi = from + (to - from) * i as f64 / (remaining + 1) as f64;
            z.push(centre + Complex64::from_polar(te_radius, phi));
        }
        let xy: Vec<(f64, f64)> = z.iter().map(|p| (p.re, p.im)).collect();
        Contour::from_points(&xy)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// NACA 0012's thickness at 30 % chord is 12 % (Abbott & von
    /// Doenhoff's tables: y_t(0.3) = 0.06002 for the open edge; the closed
    /// coefficient changes it by 5t·0.0021·0.3⁴ = 1e-5).
    #[test]
    fn the_0012_is_12_percent_thick() {
        let naca = Naca4::parse("NACA 0012").unwrap();
        assert!((naca.half_thickness(0.3) - 0.06002).abs() < 2e-5);
        assert!(naca.half_thickness(1.0).abs() < 1e-12);
    }

    /// The trailing-edge circle touches both surfaces: its centre is `r`
    /// from each tangent point, and for a symmetric section on the chord.
    #[test]
    fn the_trailing_edge_circle_is_tangent() {
        for code in ["0012", "2412", "4415"] {
            let naca = Naca4::parse(code).unwrap();
            let r = 0.005;
            let (xu, xl, c) = naca.trailing_edge_circle(r).unwrap();
            assert!(((naca.surface(xu, 1.0) - c).norm() - r).abs() < 1e-8);
            assert!(((naca.surface(xl, -1.0) - c).norm() - r).abs() < 1e-8);
            assert!(xu > 0.9 && xl > 0.9, "{code}: {xu} {xl}");
            if code == "0012" {
                assert!(c.im.abs() < 1e-10 && (xu - xl).abs() < 1e-8);
            }
        }
    }

    #[test]
    fn bad_designations_are_refused() {
        for code in ["001", "00120", "2412x", "a012", "0000", "2012"] {
            let r = Contour::naca4(code, 128, 0.005);
            assert!(matches!(r, Err(NsError::BadNaca { .. })), "{code}: {r:?}");
        }
    }
}
