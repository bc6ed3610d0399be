//! The ZDT bi-objective test problems and their analytic Pareto fronts, to
//! validate multi-objective optimizers (test problems, not wing physics).
//!
//! Reference: Zitzler, Deb & Thiele (2000), "Comparison of multiobjective
//! evolutionary algorithms: empirical results", Evolutionary Computation
//! 8(2), 173–195, section 4 (functions T1, T2, T3, T4, T6). All have
//! f1 = f1(x_1), f2 = g(x_2..x_n) · h(f1, g), both minimized; the Pareto
//! front is g = 1. ZDT5 is binary-coded and left out.

use std::f64::consts::PI;

/// The five real-coded ZDT problems.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Zdt {
    /// Convex front f2 = 1 − √f1; n = 30, x ∈ [0, 1].
    Zdt1,
    /// Concave front f2 = 1 − f1²; n = 30, x ∈ [0, 1].
    Zdt2,
    /// Five disconnected pieces of f2 = 1 − √f1 − f1 sin(10π f1); n = 30,
    /// x ∈ [0, 1].
    Zdt3,
    /// Multimodal (21⁹ local fronts), front f2 = 1 − √f1; n = 10,
    /// x_1 ∈ [0, 1], x_2..x_10 ∈ [−5, 5].
    Zdt4,
    /// Non-uniform density, front f2 = 1 − f1² with f1 ∈ [0.2807753191, 1];
    /// n = 10, x ∈ [0, 1].
    Zdt6,
}

/// The smallest f1 on the ZDT6 front: 1 − exp(−4x) sin⁶(6πx) has its
/// minimum over [0, 1] there (REFERENCES.md).
pub const ZDT6_F1_MIN: f64 = 0.280_775_319_1;

/// Errors of evaluating a ZDT problem.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ZdtError {
    /// The decision vector has the wrong length.
    #[error("{problem} takes {expected} variables, got {found}")]
    Dimension {
        /// Problem name.
        problem: &'static str,
        /// Variables expected.
        expected: usize,
        /// Variables given.
        found: usize,
    },
}

impl Zdt {
    /// All five problems, in order.
    pub const ALL: [Zdt; 5] = [Zdt::Zdt1, Zdt::Zdt2, Zdt::Zdt3, Zdt::Zdt4, Zdt::Zdt6];

    /// The problem's name, e.g. `"ZDT1"`.
    pub fn name(self) -> &'static str {
        match self {
            Zdt::Zdt1 => "ZDT1",
            Zdt::Zdt2 => "ZDT2",
            Zdt::Zdt3 => "ZDT3",
            Zdt::Zdt4 => "ZDT4",
            Zdt::Zdt6 => "ZDT6",
        }
    }

    /// The standard number of decision variables (30 or 10).
    pub fn n_variables(self) -> usize {
        match self {
            Zdt::Zdt1 | Zdt::Zdt2 | Zdt::Zdt3 => 30,
            Zdt::Zdt4 | Zdt::Zdt6 => 10,
        }
    }

    /// Lower and upper bounds of every decision variable.
    pub fn bounds(self) -> (Vec<f64>, Vec<f64>) {
        let n = self.n_variables();
        match self {
            Zdt::Zdt4 => {
                let mut lower = vec![-5.0; n];
                let mut upper = vec![5.0; n];
                lower[0] = 0.0;
                upper[0] = 1.0;
                (lower, upper)
            }
            _ => (vec![0.0; n], vec![1.0; n]),
        }
    }

    /// The two objectives [f1, f2] at `x` (ZDT 2000, section 4).
    pub fn evaluate(self, x: &[f64]) -> Result<[f64; 2], ZdtError> {
        let n = self.n_variables();
        if x.len() != n {
            return Err(ZdtError::Dimension {
                problem: self.name(),
                expected: n,
                found: x.len(),
            });
        }
        let tail = &x[1..];
        let mean_tail = tail.iter().sum::<f64>() / (n - 1) as f64;
        let f = match self {
            Zdt::Zdt1 => {
                let f1 = x[0];
                let g = 1.0 + 9.0 * mean_tail;
                [f1, g * (1.0 - (f1 / g).sqrt())]
            }
            Zdt::Zdt2 => {
                let f1 = x[0];
                let g = 1.0 + 9.0 * mean_tail;
                [f1, g * (1.0 - (f1 / g).powi(2))]
            }
            Zdt::Zdt3 => {
                let f1 = x[0];
                let g = 1.0 + 9.0 * mean_tail;
                let r = f1 / g;
                [f1, g * (1.0 - r.sqrt() - r * (10.0 * PI * f1).sin())]
            }
            Zdt::Zdt4 => {
                let f1 = x[0];
                let g = 1.0
                    + 10.0 * (n - 1) as f64
                    + tail
                        .iter()
                        .map(|v| v * v - 10.0 * (4.0 * PI * v).cos())
                        .sum::<f64>();
                [f1, g * (1.0 - (f1 / g).sqrt())]
            }
            Zdt::Zdt6 => {
                let f1 = 1.0 - (-4.0 * x[0]).exp() * (6.0 * PI * x[0]).sin().powi(6);
                let g = 1.0 + 9.0 * mean_tail.powf(0.25);
                [f1, g * (1.0 - (f1 / g).powi(2))]
            }
        };
        Ok(f)
    }

    /// The analytic Pareto front (g = 1) sampled at `n_points` values of f1
    /// equally spaced over the front's f1 range: [0, 1] for ZDT1, 2 and 4,
    /// [[`ZDT6_F1_MIN`], 1] for ZDT6. For ZDT3 the `n_points` samples span
    /// f1 ∈ [0, 1] and only the non-dominated ones are kept (the five
    /// pieces, about 27 % of the samples), so fewer points are returned.
    pub fn pareto_front(self, n_points: usize) -> Vec<[f64; 2]> {
        let (lo, hi) = match self {
            Zdt::Zdt6 => (ZDT6_F1_MIN, 1.0),
            _ => (0.0, 1.0),
        };
        let f1s = (0..n_points).map(move |i| {
            if n_points < 2 {
                lo
            } else {
                lo + (hi - lo) * i as f64 / (n_points - 1) as f64
            }
        });
        match self {
            Zdt::Zdt1 | Zdt::Zdt4 => f1s.map(|f1| [f1, 1.0 - f1.sqrt()]).collect(),
            Zdt::Zdt2 | Zdt::Zdt6 => f1s.map(|f1| [f1, 1.0 - f1 * f1]).collect(),
            Zdt::Zdt3 => {
                // Samples come in increasing f1, so a sample is
                // non-dominated exactly when its f2 is below every f2
                // before it.
                let mut best = f64::INFINITY;
                let mut front = Vec::new();
                for f1 in f1s {
                    let f2 = 1.0 - f1.sqrt() - f1 * (10.0 * PI * f1).sin();
                    if f2 < best {
                        best = f2;
                        front.push([f1, f2]);
                    }
                }
                front
            }
        }
    }
}
