//! The streamfunction from the vorticity: `ψ_ξξ + ψ_θθ = -J ω`.
//!
//! In the conformal coordinates of [`crate::OGrid`] the Poisson operator
//! does not depend on the section at all (the section only enters through
//! `J` on the right-hand side), so it is the same matrix for a rigid, a
//! moving or a deforming section. It is separable: a real FFT around each
//! ring, then one tridiagonal system along the radius per Fourier mode
//! (second-order differences in the stretched `η`), factored once when the
//! solver is built. A solve costs `O(N_θ N_r log N_θ)`.
//!
//! Boundary conditions: Dirichlet at the wall (the wall's motion; its
//! constant is a gauge, zero) and at the outer ring for every mode but
//! the mean, whose outer condition is Kelvin's: no circulation round the
//! far boundary (`ψ_ξ = 0` there, second-order one-sided). The circulation
//! round the section then follows from the vorticity, and the no-slip
//! condition (which sets the section's circulation) is the wall
//! vorticity's job ([`crate::Flow`]).

use std::sync::Arc;

use realfft::num_complex::Complex64;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};

use crate::grid::OGrid;

/// One mode's tridiagonal factors (Thomas algorithm): sub-diagonal, the
/// reciprocal pivots and the modified super-diagonal.
#[derive(Debug, Clone)]
struct ModeFactors {
    lower: Vec<f64>,
    inv_pivot: Vec<f64>,
    upper_mod: Vec<f64>,
}

impl ModeFactors {
    /// Factor the system with diagonals `(lower, diag, upper)`.
    fn new(lower: Vec<f64>, diag: &[f64], upper: &[f64]) -> Self {
        let n = diag.len();
        let mut inv_pivot = vec![0.0; n];
        let mut upper_mod = vec![0.0; n];
        let mut prev = 0.0;
        for i in 0..n {
            let pivot = diag[i] - lower[i] * prev;
            inv_pivot[i] = 1.0 / pivot;
            upper_mod[i] = upper[i] * inv_pivot[i];
            prev = upper_mod[i];
        }
        Self {
            lower,
            inv_pivot,
            upper_mod,
        }
    }

    /// Solve in place (the right-hand side becomes the solution).
    fn solve(&self, x: &mut [Complex64]) {
        let n = x.len();
        let mut prev = Complex64::new(0.0, 0.0);
        for ((xi, lower), inv_pivot) in x.iter_mut().zip(&self.lower).zip(&self.inv_pivot) {
            *xi = (*xi - prev * lower) * inv_pivot;
            prev = *xi;
        }
        for i in (0..n - 1).rev() {
            let next = x[i + 1];
            x[i] -= next * self.upper_mod[i];
        }
    }
}

/// The factored Poisson solver of one grid (module docs).
pub struct StreamSolver {
    nt: usize,
    nr: usize,
    modes: usize,
    forward: Arc<dyn RealToComplex<f64>>,
    inverse: Arc<dyn ComplexToReal<f64>>,
    factors: Vec<ModeFactors>,
    /// The radial coefficients of `ψ_{j-1}` and `ψ_{j+1}` in every row
    /// (the same in all rows: the stretching is exponential).
    lower_coefficient: f64,
    upper_coefficient: f64,
    /// `g'²` per radial node.
    slope2: Vec<f64>,
    spectrum: Vec<Complex64>,
    column: Vec<Complex64>,
    ring: Vec<f64>,
    ring_spec: Vec<Complex64>,
    fft_scratch: Vec<Complex64>,
}

impl std::fmt::Debug for StreamSolver {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("StreamSolver")
            .field("nt", &self.nt)
            .field("nr", &self.nr)
            .finish_non_exhaustive()
    }
}

impl StreamSolver {
    /// Factor the operator of `grid` (`N_θ/2 + 1` tridiagonal systems of
    /// `N_r` rows; cost `O(N_θ N_r)`).
    #[must_use]
    pub fn new(grid: &OGrid) -> Self {
        let (nt, nr) = (grid.nt, grid.nr);
        let modes = nt / 2 + 1;
        let mut planner = RealFftPlanner::<f64>::new();
        let forward = planner.plan_fft_forward(nt);
        let inverse = planner.plan_fft_inverse(nt);
        let h2 = 1.0 / (grid.d_eta * grid.d_eta);
        let half = grid.curvature / (2.0 * grid.d_eta);
        let (a, c) = (h2 + half, h2 - half);
        let slope2: Vec<f64> = grid.slope.iter().map(|s| s * s).collect();
        let mut factors = Vec::with_capacity(modes);
        for m in 0..modes {
            let k2 = (m * m) as f64;
            if m == 0 {
                // Unknowns j = 1..nr-1: the outer row is Kelvin's
                // condition, no circulation round the far boundary
                // (3ψ_N - 4ψ_{N-1} + ψ_{N-2} = 0), with ψ_{N-2} eliminated
                // by row N-1 to stay tridiagonal.
                let n = nr - 1;
                let mut lower = vec![a; n];
                let mut diag = vec![-2.0 * h2; n];
                let mut upper = vec![c; n];
                lower[0] = 0.0;
                lower[n - 1] = -4.0 - diag[n - 2] / a;
                diag[n - 1] = 3.0 - c / a;
                upper[n - 1] = 0.0;
                factors.push(ModeFactors::new(lower, &diag, &upper));
            } else {
                // Unknowns j = 1..nr-2.
                let n = nr - 2;
                let mut lower = vec![a; n];
                let diag: Vec<f64> = (1..=n).map(|j| -2.0 * h2 - k2 * slope2[j]).collect();
                let mut upper = vec![c; n];
                lower[0] = 0.0;
                upper[n - 1] = 0.0;
                factors.push(ModeFactors::new(lower, &diag, &upper));
            }
        }
        let fft_scratch = forward.make_scratch_vec();
        let fft_scratch = if fft_scratch.len() < inverse.get_scratch_len() {
            inverse.make_scratch_vec()
        } else {
            fft_scratch
        };
        Self {
            nt,
            nr,
            modes,
            forward,
            inverse,
            factors,
            lower_coefficient: a,
            upper_coefficient: c,
            slope2,
            spectrum: vec![Complex64::new(0.0, 0.0); modes * nr],
            column: vec![Complex64::new(0.0, 0.0); nr],
            ring: vec![0.0; nt],
            ring_spec: vec![Complex64::new(0.0, 0.0); modes],
            fft_scratch,
        }
    }

    /// Fourier modes of one ring into `out` (unnormalized).
    fn ring_modes(&mut self, values: &[f64], out_row: usize) {
        self.ring.copy_from_slice(values);
        let dst = &mut self.spectrum[out_row * self.modes..(out_row + 1) * self.modes];
        // The lengths match by construction.
        let _ = self
            .forward
            .process_with_scratch(&mut self.ring, dst, &mut self.fft_scratch);
    }

    /// Solve for `psi` (all nodes) given the source `s = J ω` at all
    /// nodes, the wall's streamfunction and the outer ring's (its mean
    /// replaced by Kelvin's condition, module docs).
    pub fn solve(&mut self, source: &[f64], wall_shape: &[f64], outer: &[f64], psi: &mut [f64]) {
        let (nt, nr, modes) = (self.nt, self.nr, self.modes);
        for j in 0..nr {
            self.ring_modes(&source[j * nt..(j + 1) * nt], j);
        }
        // Scale the source rows: rhs_j = -g'_j² ŝ_j.
        for j in 0..nr {
            let s2 = self.slope2[j];
            for v in &mut self.spectrum[j * modes..(j + 1) * modes] {
                *v *= -s2;
            }
        }
        let wall = self.modes_of(wall_shape);
        let outer_modes = self.modes_of(outer);
        for m in 0..modes {
            if m == 0 {
                // Rows j = 1..nr-2, then Kelvin's row (see `new`) less row
                // N-1's right-hand side over its eliminated coefficient.
                let n = nr - 1;
                for i in 0..n - 1 {
                    self.column[i] = self.spectrum[(i + 1) * modes];
                }
                self.column[0] -= wall[0] * self.lower_coefficient;
                self.column[n - 1] = -self.column[n - 2] / self.lower_coefficient;
                self.factors[0].solve(&mut self.column[..n]);
                for i in 0..n {
                    self.spectrum[(i + 1) * modes] = self.column[i];
                }
                self.spectrum[0] = wall[0];
            } else {
                let n = nr - 2;
                for j in 0..n {
                    self.column[j] = self.spectrum[(j + 1) * modes + m];
                }
                self.column[0] -= wall[m] * self.lower_coefficient;
                self.column[n - 1] -= outer_modes[m] * self.upper_coefficient;
                self.factors[m].solve(&mut self.column[..n]);
                for j in 0..n {
                    self.spectrum[(j + 1) * modes + m] = self.column[j];
                }
                self.spectrum[m] = wall[m];
                self.spectrum[(nr - 1) * modes + m] = outer_modes[m];
            }
        }
        let scale = 1.0 / nt as f64;
        for j in 0..nr {
            let row = &mut self.spectrum[j * modes..(j + 1) * modes];
            row[0].im = 0.0;
            row[modes - 1].im = 0.0;
            let _ = self.inverse.process_with_scratch(
                row,
                &mut psi[j * nt..(j + 1) * nt],
                &mut self.fft_scratch,
            );
            for v in &mut psi[j * nt..(j + 1) * nt] {
                *v *= scale;
            }
        }
    }

    /// Fourier modes of a ring (unnormalized), into a fresh vector.
    fn modes_of(&mut self, values: &[f64]) -> Vec<Complex64> {
        self.ring.copy_from_slice(values);
        let _ = self.forward.process_with_scratch(
            &mut self.ring,
            &mut self.ring_spec,
            &mut self.fft_scratch,
        );
        self.ring_spec.clone()
    }

    /// `∂²f/∂θ²` of a periodic ring, spectrally (into `out`).
    pub fn ring_second_derivative(&mut self, values: &[f64], out: &mut [f64]) {
        let mut spec = self.modes_of(values);
        let nt = self.nt;
        for (m, v) in spec.iter_mut().enumerate() {
            *v *= -((m * m) as f64) / nt as f64;
        }
        let last = spec.len() - 1;
        spec[0].im = 0.0;
        spec[last].im = 0.0;
        let _ = self
            .inverse
            .process_with_scratch(&mut spec, out, &mut self.fft_scratch);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::GridSpec;
    use crate::section_map::SectionMap;

    /// Potential flow of a cylinder (radius a) moving at V along x in
    /// fluid at rest inside a circle of radius R: ψ = (c1 r + c2/r) sin θ
    /// with ψ(a) = V a sin θ, ψ(R) = 0 (Milne-Thomson §6.21, with the outer
    /// wall): c2 = V a² / (1 - a²/R²), c1 = -c2/R². The solver reproduces
    /// it to second order in the radial step.
    #[test]
    fn the_translating_cylinders_potential_flow_is_reproduced() {
        let (a, r_out, v) = (0.5, 10.0, 1.0);
        let map = SectionMap::circle(a).unwrap();
        let errors: Vec<f64> = [64, 128]
            .iter()
            .map(|&radial| {
                let spec = GridSpec {
                    around: 32,
                    radial,
                    outer_radius: r_out / a,
                    first_cell: 0.01,
                };
                let grid = OGrid::new(&map, spec).unwrap();
                let mut solver = StreamSolver::new(&grid);
                let wall: Vec<f64> = grid.z[..32].iter().map(|z| v * z.im).collect();
                let mut psi = vec![0.0; grid.len()];
                solver.solve(&vec![0.0; grid.len()], &wall, &[0.0; 32], &mut psi);
                let c2 = v * a * a / (1.0 - a * a / (r_out * r_out));
                let c1 = -c2 / (r_out * r_out);
                grid.z
                    .iter()
                    .zip(&psi)
                    .map(|(z, p)| {
                        let (r, s) = (z.norm(), z.im / z.norm());
                        (p - (c1 * r + c2 / r) * s).abs()
                    })
                    .fold(0.0, f64::max)
            })
            .collect();
        assert!(errors[1] < 2e-3 * v * a, "{errors:?}");
        assert!(errors[0] / errors[1] > 3.0, "not second order: {errors:?}");
    }

    /// Kelvin's condition: a vortex patch's streamfunction has no
    /// circulation round the outer ring (its outer slope is zero) while the
    /// wall keeps its value.
    #[test]
    fn a_vortex_patch_leaves_no_circulation_round_the_far_boundary() {
        let map = SectionMap::circle(0.5).unwrap();
        let spec = GridSpec {
            around: 32,
            radial: 96,
            outer_radius: 40.0,
            first_cell: 0.01,
        };
        let grid = OGrid::new(&map, spec).unwrap();
        let mut solver = StreamSolver::new(&grid);
        let source: Vec<f64> = grid
            .z
            .iter()
            .zip(&grid.jac)
            .map(|(z, j)| j * (-((z - Complex64::new(2.0, 0.5)).norm_sqr()) / 0.1).exp())
            .collect();
        let mut psi = vec![0.0; grid.len()];
        solver.solve(&source, &[0.0; 32], &[0.0; 32], &mut psi);
        let ring = |j: usize| psi[j * 32..(j + 1) * 32].iter().sum::<f64>() / 32.0;
        let n = grid.nr - 1;
        let outer_slope = (3.0 * ring(n) - 4.0 * ring(n - 1) + ring(n - 2)) / (2.0 * grid.d_eta);
        let inner_slope = (ring(2) - ring(0)) / (2.0 * grid.d_eta);
        assert!(ring(0).abs() < 1e-14, "wall value {}", ring(0));
        assert!(
            outer_slope.abs() < 1e-9 * inner_slope.abs(),
            "{outer_slope} vs {inner_slope}"
        );
    }
}
