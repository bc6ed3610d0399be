//! Cubic splines of plane curves, parametrised by the polygon's arc
//! (cumulative chord) length: a closed curve (periodic, `C²` all round)
//! through a [`crate::Contour`]'s points for the conformal fit, and an open
//! one (natural ends) through a membrane's mid-line samples.
//!
//! Points are complex numbers `x + iy`; the second derivatives come from
//! one (cyclic) tridiagonal solve, `O(n)`. Evaluation finds the knot
//! interval by bisection, `O(log n)`.

use realfft::num_complex::Complex64;

/// A cubic spline `P(s)` of a plane curve (module docs).
#[derive(Debug, Clone)]
pub(crate) struct CurveSpline {
    /// Knots `s_i` (cumulative chord length from point 0).
    knots: Vec<f64>,
    /// Values at the knots (the closed curve repeats point 0 at its end).
    values: Vec<Complex64>,
    /// Second derivatives at the knots.
    second: Vec<Complex64>,
    /// Whether `s` is taken modulo the length.
    closed: bool,
}

impl CurveSpline {
    /// The closed spline through `points` (distinct consecutive points,
    /// no closing duplicate), period = the polygon's perimeter.
    pub(crate) fn closed(points: &[Complex64]) -> Self {
        let n = points.len();
        let mut values = points.to_vec();
        values.push(points[0]);
        let knots = chord_knots(&values);
        let h: Vec<f64> = knots.windows(2).map(|w| w[1] - w[0]).collect();
        // Row i: h[i-1] M[i-1] + 2(h[i-1] + h[i]) M[i] + h[i] M[i+1] = r[i].
        let prev = |i: usize| if i == 0 { n - 1 } else { i - 1 };
        let lower: Vec<f64> = (0..n).map(|i| h[prev(i)]).collect();
        let diag: Vec<f64> = (0..n).map(|i| 2.0 * (h[prev(i)] + h[i])).collect();
        let upper: Vec<f64> = h.clone();
        let rhs: Vec<Complex64> = (0..n)
            .map(|i| {
                let ip = prev(i);
                6.0 * ((values[i + 1] - values[i]) / h[i] - (values[i] - values[ip]) / h[ip])
            })
            .collect();
        let mut second = solve_cyclic(&lower, &diag, &upper, &rhs);
        second.push(second[0]);
        Self {
            knots,
            values,
            second,
            closed: true,
        }
    }

    /// The open spline through `points` with zero curvature at both ends.
    pub(crate) fn open(points: &[Complex64]) -> Self {
        let n = points.len();
        let values = points.to_vec();
        let knots = chord_knots(&values);
        let h: Vec<f64> = knots.windows(2).map(|w| w[1] - w[0]).collect();
        let mut second = vec![Complex64::new(0.0, 0.0); n];
        if n > 2 {
            let m = n - 2;
            let lower: Vec<f64> = (1..=m).map(|i| h[i - 1]).collect();
            let diag: Vec<f64> = (1..=m).map(|i| 2.0 * (h[i - 1] + h[i])).collect();
            let upper: Vec<f64> = (1..=m).map(|i| h[i]).collect();
            let rhs: Vec<Complex64> = (1..=m)
                .map(|i| {
                    6.0 * ((values[i + 1] - values[i]) / h[i]
                        - (values[i] - values[i - 1]) / h[i - 1])
                })
                .collect();
            let inner = solve_tridiagonal(&lower, &diag, &upper, &rhs);
            second[1..=m].copy_from_slice(&inner);
        }
        Self {
            knots,
            values,
            second,
            closed: false,
        }
    }

    /// The curve's parameter length (the polygon's perimeter or length).
    pub(crate) fn length(&self) -> f64 {
        self.knots[self.knots.len() - 1]
    }

    /// The knots: the cumulative chord length at each point (a closed
    /// spline's last knot, the period, is point 0 again).
    pub(crate) fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// `P(s)` and `dP/ds` (`s` modulo the length on a closed curve,
    /// clamped to the ends on an open one).
    pub(crate) fn eval(&self, s: f64) -> (Complex64, Complex64) {
        let len = self.length();
        let s = if self.closed {
            s.rem_euclid(len)
        } else {
            s.clamp(0.0, len)
        };
        let last = self.knots.len() - 2;
        let i = self
            .knots
            .partition_point(|&k| k <= s)
            .saturating_sub(1)
            .min(last);
        let (s0, s1) = (self.knots[i], self.knots[i + 1]);
        let h = s1 - s0;
        let (a, b) = (s1 - s, s - s0);
        let (m0, m1) = (self.second[i], self.second[i + 1]);
        let c0 = self.values[i] / h - m0 * (h / 6.0);
        let c1 = self.values[i + 1] / h - m1 * (h / 6.0);
        let p = m0 * (a * a * a / (6.0 * h)) + m1 * (b * b * b / (6.0 * h)) + c0 * a + c1 * b;
        let dp = -m0 * (a * a / (2.0 * h)) + m1 * (b * b / (2.0 * h)) - c0 + c1;
        (p, dp)
    }
}

/// Cumulative chord lengths of a polyline, from 0.
fn chord_knots(values: &[Complex64]) -> Vec<f64> {
    let mut knots = Vec::with_capacity(values.len());
    let mut s = 0.0;
    knots.push(s);
    for w in values.windows(2) {
        s += (w[1] - w[0]).norm();
        knots.push(s);
    }
    knots
}

/// Thomas' algorithm for a diagonally dominant tridiagonal system
/// (`lower[0]` and `upper[n-1]` unused).
fn solve_tridiagonal(
    lower: &[f64],
    diag: &[f64],
    upper: &[f64],
    rhs: &[Complex64],
) -> Vec<Complex64> {
    let n = diag.len();
    let mut c = vec![0.0; n];
    let mut d = vec![Complex64::new(0.0, 0.0); n];
    c[0] = upper[0] / diag[0];
    d[0] = rhs[0] / diag[0];
    for i in 1..n {
        let m = diag[i] - lower[i] * c[i - 1];
        c[i] = upper[i] / m;
        d[i] = (rhs[i] - d[i - 1] * lower[i]) / m;
    }
    for i in (0..n - 1).rev() {
        let next = d[i + 1];
        d[i] -= next * c[i];
    }
    d
}

/// A cyclic tridiagonal system (`lower[0]` couples row 0 to row n-1,
/// `upper[n-1]` row n-1 to row 0), by Sherman–Morrison on Thomas.
fn solve_cyclic(lower: &[f64], diag: &[f64], upper: &[f64], rhs: &[Complex64]) -> Vec<Complex64> {
    let n = diag.len();
    let (alpha, beta) = (upper[n - 1], lower[0]);
    let gamma = -diag[0];
    let mut d = diag.to_vec();
    d[0] -= gamma;
    d[n - 1] -= alpha * beta / gamma;
    let x = solve_tridiagonal(lower, &d, upper, rhs);
    let mut u = vec![Complex64::new(0.0, 0.0); n];
    u[0] = Complex64::new(gamma, 0.0);
    u[n - 1] = Complex64::new(alpha, 0.0);
    let z = solve_tridiagonal(lower, &d, upper, &u);
    let factor = (x[0] + x[n - 1] * (beta / gamma)) / (1.0 + z[0].re + z[n - 1].re * beta / gamma);
    x.iter().zip(&z).map(|(xi, zi)| xi - zi * factor).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Through the points, and a circle's tangent has the circle's
    /// direction and unit speed (to the chord-length parametrisation's
    /// accuracy).
    #[test]
    fn the_closed_spline_interpolates_a_circle() {
        let n = 64;
        let points: Vec<Complex64> = (0..n)
            .map(|k| Complex64::from_polar(2.0, std::f64::consts::TAU * k as f64 / n as f64))
            .collect();
        let spline = CurveSpline::closed(&points);
        for (i, p) in points.iter().enumerate() {
            let (q, _) = spline.eval(spline.knots[i]);
            assert!((q - p).norm() < 1e-12);
        }
        for k in 0..200 {
            let s = spline.length() * (k as f64 + 0.37) / 200.0;
            let (p, dp) = spline.eval(s);
            assert!((p.norm() - 2.0).abs() < 1e-6, "{}", p.norm());
            let tangent = Complex64::i() * p / p.norm();
            assert!((dp - tangent).norm() < 1e-3, "{dp} {tangent}");
        }
    }

    /// A straight open line stays straight, and its ends are reached.
    #[test]
    fn the_open_spline_keeps_a_line() {
        let points: Vec<Complex64> = (0..5).map(|k| Complex64::new(f64::from(k), 0.5)).collect();
        let spline = CurveSpline::open(&points);
        let (p, dp) = spline.eval(2.7);
        assert!((p - Complex64::new(2.7, 0.5)).norm() < 1e-12);
        assert!((dp - 1.0).norm() < 1e-12);
        assert!((spline.eval(10.0).0 - Complex64::new(4.0, 0.5)).norm() < 1e-12);
    }
}
