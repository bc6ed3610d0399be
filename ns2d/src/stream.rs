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
//! Boundary conditions: Dirichlet at the outer ring; at the wall,
//! Dirichlet on the wall's motion for every Fourier mode but the mean,
//! whose condition is the mean no-slip one: the wall's mean `ψ_ξ` (the
//! circulation round the section, `2ΩA` for a rigid one) with the wall's
//! free constant as the unknown (second-order one-sided `ψ_ξ`). The
//! fluid's total circulation is then the wall vorticity's business
//! (Kelvin's theorem, [`crate::Flow`]).

use std::sync::Arc;

use rayon::prelude::*;
use realfft::num_complex::Complex64;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};

use crate::blocks;
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

/// Weights of `ψ(0), ψ(ξ1), ψ(ξ2)` in the second-order one-sided `ψ_ξ(0)`
/// (the derivative of the quadratic through the three).
fn wall_slope_weights(xi1: f64, xi2: f64) -> [f64; 3] {
    [
        -(xi1 + xi2) / (xi1 * xi2),
        xi2 / (xi1 * (xi2 - xi1)),
        -xi1 / (xi2 * (xi2 - xi1)),
    ]
}

/// The factored Poisson solver of one grid (module docs).
pub struct StreamSolver {
    nt: usize,
    nr: usize,
    modes: usize,
    forward: Arc<dyn RealToComplex<f64>>,
    inverse: Arc<dyn ComplexToReal<f64>>,
    /// Mode 0's factors (its wall row is the mean no-slip one).
    mean_factors: ModeFactors,
    /// The other modes' factors laid out like the spectrum (entry
    /// `j * modes + m` for the row of ring `j`, `1 <= j <= nr - 2`), so
    /// that their eliminations run side by side along the rings.
    mode_lower: Vec<f64>,
    mode_inv_pivot: Vec<f64>,
    mode_upper: Vec<f64>,
    /// The radial coefficients of `ψ_0` and `ψ_2` in row 1 (the wall's
    /// given value moves to the right-hand side by the first; mode 0's
    /// wall row eliminates `ψ_2` by the second).
    lower_coefficient: f64,
    /// The wall-slope weights of `ψ0, ψ1, ψ2` (mode 0's wall row).
    wall_weights: [f64; 3],
    upper_coefficient: f64,
    /// The radial coefficient of the outer ring's `ψ` in row `nr - 2`
    /// (the outer ring's given value moves to the right-hand side by
    /// it).
    outer_coefficient: f64,
    /// `g'²` per radial node.
    slope2: Vec<f64>,
    /// Each ring's transformed right-hand side `-g'_j² ŝ_j` of the last
    /// solve (kept: a later solve whose source changed on its first rings
    /// only transforms those again, [`Self::solve_vorticity`]),
    /// and the solution's modes.
    source_spectrum: Vec<Complex64>,
    spectrum: Vec<Complex64>,
    /// Mode 0's column.
    mean_column: Vec<Complex64>,
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
        // Row j's coefficients of ψ_{j-1} and ψ_{j+1}.
        let a_at = |j: usize| grid.radial_neighbours(j).0;
        let c_at = |j: usize| grid.radial_neighbours(j).1;
        let (a, c) = grid.radial_neighbours(1);
        let slope2: Vec<f64> = grid.slope.iter().map(|s| s * s).collect();
        let mut factors = Vec::with_capacity(modes);
        for m in 0..modes {
            let k2 = (m * m) as f64;
            if m == 0 {
                // Unknowns j = 0..nr-2: the wall row is the mean no-slip
                // condition, the second-order one-sided ψ_ξ at the wall
                // (a quadratic through ψ0, ψ1, ψ2) equal to the wall's,
                // with ψ2 eliminated by row 1 to stay tridiagonal.
                let n = nr - 1;
                let mut lower: Vec<f64> = (0..n).map(a_at).collect();
                let mut diag = vec![-2.0 * h2; n];
                let mut upper: Vec<f64> = (0..n).map(c_at).collect();
                let w = wall_slope_weights(grid.xi[1], grid.xi[2]);
                lower[0] = 0.0;
                diag[0] = w[0] - w[2] * a / c;
                upper[0] = w[1] - w[2] * diag[1] / c;
                upper[n - 1] = 0.0;
                factors.push(ModeFactors::new(lower, &diag, &upper));
            } else {
                // Unknowns j = 1..nr-2.
                let n = nr - 2;
                let mut lower: Vec<f64> = (1..=n).map(a_at).collect();
                let diag: Vec<f64> = (1..=n).map(|j| -2.0 * h2 - k2 * slope2[j]).collect();
                let mut upper: Vec<f64> = (1..=n).map(c_at).collect();
                lower[0] = 0.0;
                upper[n - 1] = 0.0;
                factors.push(ModeFactors::new(lower, &diag, &upper));
            }
        }
        let mean_factors = factors.remove(0);
        let mut mode_lower = vec![0.0; nr * modes];
        let mut mode_inv_pivot = vec![0.0; nr * modes];
        let mut mode_upper = vec![0.0; nr * modes];
        for (i, f) in factors.iter().enumerate() {
            let m = i + 1;
            for r in 0..nr - 2 {
                let at = (r + 1) * modes + m;
                mode_lower[at] = f.lower[r];
                mode_inv_pivot[at] = f.inv_pivot[r];
                mode_upper[at] = f.upper_mod[r];
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
            mean_factors,
            mode_lower,
            mode_inv_pivot,
            mode_upper,
            lower_coefficient: a,
            wall_weights: wall_slope_weights(grid.xi[1], grid.xi[2]),
            upper_coefficient: c,
            outer_coefficient: c_at(nr - 2),
            slope2,
            source_spectrum: vec![Complex64::new(0.0, 0.0); modes * nr],
            spectrum: vec![Complex64::new(0.0, 0.0); modes * nr],
            mean_column: vec![Complex64::new(0.0, 0.0); nr],
            ring: vec![0.0; nt],
            ring_spec: vec![Complex64::new(0.0, 0.0); modes],
            fft_scratch,
        }
    }

    /// Solve for `psi` (all nodes) given the source `s = J ω` at all
    /// nodes, the wall's streamfunction up to a constant, the wall's mean
    /// `ψ_ξ` and the outer ring's streamfunction (module docs). The
    /// rings' transforms and the modes' radial systems run in parallel
    /// (the modes side by side along the rings, in blocks).
    pub fn solve(
        &mut self,
        source: &[f64],
        wall_shape: &[f64],
        wall_slope_mean: f64,
        outer: &[f64],
        psi: &mut [f64],
    ) {
        let nt = self.nt;
        let ring = |j: usize, out: &mut [f64]| out.copy_from_slice(&source[j * nt..(j + 1) * nt]);
        let rings = self.nr;
        self.solve_rings(ring, wall_shape, wall_slope_mean, outer, psi, rings, rings);
    }

    /// [`Self::solve`] with the source `J ω` of the Jacobian `jac` and the
    /// vorticity `omega` at all nodes (formed ring by ring as it is
    /// transformed), for the first `rings` rings from the wall out only:
    /// the rest of `psi` is left as it was (the wall vorticity needs two;
    /// the inverse transforms are about a third of a solve's cost).
    ///
    /// Only the first `changed` rings of the source are transformed; the
    /// others' transforms are the last solve's (`N_r` for all: the
    /// caller promises that the source differs from the last solve's on
    /// those rings only, and the result is then bit for bit the same as
    /// transforming them all). [`crate::Flow::step`]'s second solve: the
    /// wall's correction reaches the first few dozen rings of 320 on the
    /// default FWAV section, and the rest's forward transforms are about
    /// a quarter of a solve's cost.
    #[allow(clippy::too_many_arguments)]
    pub fn solve_vorticity(
        &mut self,
        jac: &[f64],
        omega: &[f64],
        wall_shape: &[f64],
        wall_slope_mean: f64,
        outer: &[f64],
        psi: &mut [f64],
        rings: usize,
        changed: usize,
    ) {
        let nt = self.nt;
        let ring = |j: usize, out: &mut [f64]| {
            let r = j * nt..(j + 1) * nt;
            for ((o, a), w) in out.iter_mut().zip(&jac[r.clone()]).zip(&omega[r]) {
                *o = a * w;
            }
        };
        self.solve_rings(
            ring,
            wall_shape,
            wall_slope_mean,
            outer,
            psi,
            rings,
            changed,
        );
    }

    /// [`Self::solve`] with the source's ring `j` written by `source(j,
    /// ring)` for the first `fresh` rings (the others' transforms kept
    /// from the last solve), the first `rings` rings of `psi` written.
    #[allow(clippy::too_many_arguments)]
    fn solve_rings(
        &mut self,
        source: impl Fn(usize, &mut [f64]) + Sync,
        wall_shape: &[f64],
        wall_slope_mean: f64,
        outer: &[f64],
        psi: &mut [f64],
        rings: usize,
        fresh: usize,
    ) {
        self.transform_sources(source, fresh);
        self.solve_modes(wall_shape, wall_slope_mean, outer);
        self.transform_back(psi, rings);
    }

    /// The first `fresh` rings' sources, each ring's modes scaled into the
    /// right-hand side `-g'_j² ŝ_j` (into `source_spectrum`; rings in
    /// parallel).
    fn transform_sources(&mut self, source: impl Fn(usize, &mut [f64]) + Sync, fresh: usize) {
        let (nt, nr, modes) = (self.nt, self.nr, self.modes);
        let scratch_len = self.fft_scratch.len();
        let forward = &self.forward;
        let slope2 = &self.slope2;
        self.source_spectrum[..fresh.min(nr) * modes]
            .par_chunks_mut(modes)
            .enumerate()
            .for_each_init(
                || (vec![0.0; nt], vec![Complex64::new(0.0, 0.0); scratch_len]),
                |(ring, scratch), (j, row)| {
                    source(j, ring);
                    // The lengths match by construction.
                    let _ = forward.process_with_scratch(ring, row, scratch);
                    let s2 = -slope2[j];
                    for v in row.iter_mut() {
                        *v *= s2;
                    }
                },
            );
    }

    /// Every mode's radial system from the transformed sources, with the
    /// wall's and the outer ring's conditions (into `spectrum`).
    fn solve_modes(&mut self, wall_shape: &[f64], wall_slope_mean: f64, outer: &[f64]) {
        let (nt, nr, modes) = (self.nt, self.nr, self.modes);
        let wall = self.modes_of(wall_shape);
        let outer_modes = self.modes_of(outer);
        let (lower_c, upper_c, outer_c, w2) = (
            self.lower_coefficient,
            self.upper_coefficient,
            self.outer_coefficient,
            self.wall_weights[2],
        );
        // Mode 0: the wall row (see `new`) less row 1's right-hand side
        // times the eliminated weight; rows 1..nr-2; the outer value
        // given.
        let column = &mut self.mean_column;
        for (j, c) in column.iter_mut().enumerate() {
            *c = self.source_spectrum[j * modes];
        }
        let n = nr - 1;
        column[0] = Complex64::new(wall_slope_mean * nt as f64, 0.0) - column[1] * (w2 / upper_c);
        column[n - 1] -= outer_modes[0] * outer_c;
        self.mean_factors.solve(&mut column[..n]);
        column[nr - 1] = outer_modes[0];
        for (j, c) in column.iter().enumerate() {
            self.spectrum[j * modes] = *c;
        }
        // The other modes' radial systems side by side along the rings,
        // blocks of modes in parallel: wall and outer values given.
        let (lower, inv_pivot, upper) = (&self.mode_lower, &self.mode_inv_pivot, &self.mode_upper);
        let sources = &self.source_spectrum;
        let bounds = blocks::bounds(1, modes);
        blocks::pieces(&mut self.spectrum, modes, &bounds)
            .into_par_iter()
            .zip(bounds[..bounds.len() - 1].par_iter())
            .for_each(|(mut rows, &m0)| {
                let width = rows[0].len();
                let (wall, outer) = (&wall[m0..m0 + width], &outer_modes[m0..m0 + width]);
                // The right-hand sides (the wall's and the outer ring's
                // given values moved to rows 1 and nr - 2), eliminated
                // outward; row 1's lower coefficient is zero (the wall is
                // given).
                for j in 1..=nr - 2 {
                    let (done, rest) = rows.split_at_mut(j);
                    let (prev, row) = (&*done[j - 1], &mut *rest[0]);
                    let at = j * modes + m0;
                    let source = &sources[at..at + width];
                    let (lo, inv) = (&lower[at..at + width], &inv_pivot[at..at + width]);
                    for i in 0..width {
                        let mut v = source[i];
                        if j == 1 {
                            v -= wall[i] * lower_c;
                        }
                        if j == nr - 2 {
                            v -= outer[i] * outer_c;
                        }
                        row[i] = (v - prev[i] * lo[i]) * inv[i];
                    }
                }
                for j in (1..nr - 2).rev() {
                    let (lo, hi) = rows.split_at_mut(j + 1);
                    let (row, next) = (&mut *lo[j], &*hi[0]);
                    let at = j * modes + m0;
                    let up = &upper[at..at + width];
                    for i in 0..width {
                        row[i] -= next[i] * up[i];
                    }
                }
                rows[0].copy_from_slice(wall);
                rows[nr - 1].copy_from_slice(outer);
            });
    }

    /// The first `rings` rings' inverse transforms into `psi` (rings in
    /// parallel).
    fn transform_back(&mut self, psi: &mut [f64], rings: usize) {
        let (nt, nr, modes) = (self.nt, self.nr, self.modes);
        let scratch_len = self.fft_scratch.len();
        let inverse = &self.inverse;
        let scale = 1.0 / nt as f64;
        let rings = rings.min(nr);
        self.spectrum[..rings * modes]
            .par_chunks_mut(modes)
            .zip(psi[..rings * nt].par_chunks_mut(nt))
            .for_each_init(
                || vec![Complex64::new(0.0, 0.0); scratch_len],
                |scratch, (row, out)| {
                    row[0].im = 0.0;
                    row[modes - 1].im = 0.0;
                    let _ = inverse.process_with_scratch(row, out, scratch);
                    for v in out.iter_mut() {
                        *v *= scale;
                    }
                },
            );
    }

    /// The homogeneous solve's streamfunction at the wall's two rings
    /// (zero wall shape, zero mean wall slope, zero outer ring) for a unit
    /// source `J ω` at the node of ring `j` and angle index 0, for every
    /// ring `j` below the outer one: `out[(2 j + r) N_θ + k]` is ring
    /// `r`'s value at angle index `k`. The operator's coefficients depend
    /// on the ring only, so a source at angle index `k0` answers with the
    /// same values turned by `k0`. Cost: `N_r` solves.
    #[must_use]
    pub fn wall_responses(&mut self) -> Vec<f64> {
        let (nt, nr) = (self.nt, self.nr);
        let zeros = vec![0.0; nt];
        let mut psi = vec![0.0; nt * nr];
        let mut out = vec![0.0; 2 * nt * (nr - 1)];
        for j in 0..nr - 1 {
            let source = |ring: usize, values: &mut [f64]| {
                values.fill(0.0);
                if ring == j {
                    values[0] = 1.0;
                }
            };
            self.solve_rings(source, &zeros, 0.0, &zeros, &mut psi, 2, nr);
            out[2 * j * nt..2 * (j + 1) * nt].copy_from_slice(&psi[..2 * nt]);
        }
        out
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
                    far: None,
                };
                let grid = OGrid::new(&map, spec).unwrap();
                let mut solver = StreamSolver::new(&grid);
                let wall: Vec<f64> = grid.z[..32].iter().map(|z| v * z.im).collect();
                let mut psi = vec![0.0; grid.len()];
                solver.solve(&vec![0.0; grid.len()], &wall, 0.0, &[0.0; 32], &mut psi);
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

    /// The mean no-slip row: with a vortex patch in the flow, the mean
    /// of `ψ_ξ` at the wall (second-order one-sided) is the one asked for,
    /// and the outer ring keeps its value.
    #[test]
    fn the_mean_wall_slope_is_the_one_asked_for() {
        let map = SectionMap::circle(0.5).unwrap();
        let spec = GridSpec {
            around: 32,
            radial: 96,
            outer_radius: 40.0,
            first_cell: 0.01,
            far: None,
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
        let slope = 0.37;
        solver.solve(&source, &[0.0; 32], slope, &[0.0; 32], &mut psi);
        let ring = |j: usize| psi[j * 32..(j + 1) * 32].iter().sum::<f64>() / 32.0;
        let w = wall_slope_weights(grid.xi[1], grid.xi[2]);
        let wall_slope = w[0] * ring(0) + w[1] * ring(1) + w[2] * ring(2);
        assert!((wall_slope - slope).abs() < 1e-10, "{wall_slope}");
        assert!(ring(grid.nr - 1).abs() < 1e-14);
    }
}
