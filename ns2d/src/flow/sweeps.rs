//! The implicit and explicit sweeps of a step: the explicit advection and
//! ring diffusion (third-order upwind, rings in parallel), the radial
//! Crank–Nicolson sweep with the wall vorticity at the step's end, and
//! the ring sweep of Douglas's ADI (periodic tridiagonal systems).

use rayon::prelude::*;

use super::Flow;
use crate::motion::Motion;

impl<M: Motion> Flow<M> {
    /// The explicit parts of `dω/dt` at the interior nodes: advection into
    /// `self.rate`, diffusion round the section into
    /// `self.theta_diffusion` (wall and outer rows zero), and the
    /// circulation advected out through the outer face per unit time into
    /// `self.outflow_rate`; rows in parallel.
    pub(super) fn explicit_rate(&mut self) {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        for (i, r) in self.relative.iter_mut().enumerate() {
            *r = self.psi[i] - self.frame_psi[i];
        }
        let widths = &self.widths;
        let rows = RateRows {
            nt,
            nr,
            d_theta: g.d_theta,
            viscosity: self.viscosity,
            w: &self.omega,
            rel: &self.relative,
            widths,
        };
        self.rate
            .par_chunks_mut(nt)
            .zip(self.theta_diffusion.par_chunks_mut(nt))
            .enumerate()
            .for_each_init(
                || vec![0.0; 5 * nt],
                |scratch, (j, (out, diffusion))| {
                    if j == 0 || j == nr - 1 {
                        out.fill(0.0);
                        diffusion.fill(0.0);
                    } else {
                        let inv_jac = &g.inv_jac[j * nt..(j + 1) * nt];
                        rows.row(j, inv_jac, scratch, (out, diffusion));
                    }
                },
            );
        // What leaves through the outer face (rings nr - 2 and nr - 1).
        let mut corners = std::mem::take(&mut self.outer_corners);
        let mut fluxes = std::mem::take(&mut self.outer_fluxes);
        rows.corners(nr - 2, &mut corners);
        rows.radial_fluxes(nr - 2, &corners, &mut fluxes);
        self.outflow_rate = fluxes.iter().sum();
        self.outer_corners = corners;
        self.outer_fluxes = fluxes;
    }

    /// The second ADI sweep: `(1 - dt/2 D_θ) ω = ω* - dt/2 D_θ ω_old` on
    /// every interior ring (periodic tridiagonal systems, rings in
    /// parallel), `D_θ ω_old` being `self.theta_diffusion`.
    pub(super) fn ring_implicit(&mut self, dt: f64) {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        let factor = 0.5 * dt * self.viscosity / (g.d_theta * g.d_theta);
        self.omega
            .par_chunks_mut(nt)
            .zip(self.theta_diffusion.par_chunks(nt))
            .zip(g.inv_jac.par_chunks(nt))
            .enumerate()
            .filter(|(j, _)| *j > 0 && *j < nr - 1)
            .for_each_init(
                || vec![0.0; 3 * nt],
                |scratch, (_, ((ring, old), inv_jac))| {
                    let (sigma, rest) = scratch.split_at_mut(nt);
                    let (upper, corner) = rest.split_at_mut(nt);
                    for ((s, w), (d, i)) in sigma
                        .iter_mut()
                        .zip(ring.iter_mut())
                        .zip(old.iter().zip(inv_jac))
                    {
                        *s = factor * i;
                        *w -= 0.5 * dt * d;
                    }
                    solve_periodic(sigma, ring, upper, corner);
                },
            );
    }

    /// `ω ← (1 - dt/2 D)⁻¹ [(1 + dt/2 D) ω + dt E]` along each radial
    /// line, `D` the radial diffusion `ν/(J g'²)(∂ηη - β ∂η)` and `E` the
    /// explicit rate in `self.rate`, with the wall vorticity `new_wall` at
    /// the end of the step (the current one at its start) and the outer
    /// value held. The Thomas sweeps run ring by ring over all
    /// lines at once (contiguous memory).
    // Stencil code: the ring index k addresses several arrays at once.
    #[allow(clippy::needless_range_loop)]
    pub(super) fn radial_crank_nicolson(&mut self, dt: f64, new_wall: &[f64]) {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        let h2 = 1.0 / (g.d_eta * g.d_eta);
        let half = g.curvature / (2.0 * g.d_eta);
        let (a, c) = (h2 + half, h2 - half);
        let w = &mut self.omega;
        let (upper_mod, solved) = (&mut self.sweep_upper, &mut self.sweep_rhs);
        // Forward sweep, rings 1..nr-1; the old ring j-1 is kept aside
        // because ring j's right-hand side needs it.
        self.previous_ring.copy_from_slice(&w[..nt]);
        for j in 1..nr - 1 {
            let factor = 0.5 * dt * self.viscosity / (g.slope[j] * g.slope[j]);
            let row = j * nt;
            for k in 0..nt {
                let i = row + k;
                let kappa = factor * g.inv_jac[i];
                let (lower, diag, mut upper) = (-kappa * a, 1.0 + 2.0 * kappa * h2, -kappa * c);
                let old_below = self.previous_ring[k];
                let mut rhs = w[i]
                    + kappa * (a * old_below - 2.0 * h2 * w[i] + c * w[i + nt])
                    + dt * self.rate[i];
                if j == nr - 2 {
                    rhs -= upper * w[i + nt];
                    upper = 0.0;
                }
                let (prev_upper, prev_rhs) = if j == 1 {
                    rhs -= lower * new_wall[k];
                    (0.0, 0.0)
                } else {
                    (upper_mod[i - nt], solved[i - nt])
                };
                let lower = if j == 1 { 0.0 } else { lower };
                let inv = 1.0 / (diag - lower * prev_upper);
                upper_mod[i] = upper * inv;
                solved[i] = (rhs - lower * prev_rhs) * inv;
                self.previous_ring[k] = w[i];
            }
        }
        // Back substitution.
        for j in (1..nr - 1).rev() {
            for k in 0..nt {
                let i = j * nt + k;
                w[i] = if j == nr - 2 {
                    solved[i]
                } else {
                    solved[i] - upper_mod[i] * w[i + nt]
                };
            }
        }
    }
}

/// Solve `-σ_k x_{k-1} + (1 + 2σ_k) x_k - σ_k x_{k+1} = b_k` round a ring
/// (periodic), in place, by the Thomas algorithm with the Sherman–Morrison
/// correction for the corners. The matrix is diagonally dominant.
/// `upper` and `z` are work rings of the same length (no allocation: the
/// step calls this for every ring).
fn solve_periodic(sigma: &[f64], b: &mut [f64], upper: &mut [f64], z: &mut [f64]) {
    let n = b.len();
    // A = T + u vᵀ with u = (γ, 0, …, 0, -σ_{n-1}), v = (1, 0, …, 0, -σ_0/γ).
    let gamma = -(1.0 + 2.0 * sigma[0]);
    let diag = |k: usize| {
        let d = 1.0 + 2.0 * sigma[k];
        if k == 0 {
            d - gamma
        } else if k == n - 1 {
            d - sigma[n - 1] * sigma[0] / gamma
        } else {
            d
        }
    };
    z.fill(0.0);
    z[0] = gamma;
    z[n - 1] = -sigma[n - 1];
    // Forward elimination of T for both right-hand sides.
    let mut prev_upper = 0.0;
    for k in 0..n {
        let lower = if k == 0 { 0.0 } else { -sigma[k] };
        let inv = 1.0 / (diag(k) - lower * prev_upper);
        upper[k] = if k + 1 < n { -sigma[k] * inv } else { 0.0 };
        if k > 0 {
            b[k] -= lower * b[k - 1];
            z[k] -= lower * z[k - 1];
        }
        b[k] *= inv;
        z[k] *= inv;
        prev_upper = upper[k];
    }
    for k in (0..n - 1).rev() {
        b[k] -= upper[k] * b[k + 1];
        z[k] -= upper[k] * z[k + 1];
    }
    let v_last = -sigma[0] / gamma;
    let factor = (b[0] + v_last * b[n - 1]) / (1.0 + z[0] + v_last * z[n - 1]);
    for k in 0..n {
        b[k] -= factor * z[k];
    }
}

/// The explicit rates of one ring: advection in conservative form, by
/// third-order upwind-biased face values and face fluxes that are
/// differences of the relative streamfunction at the cell corners (so the
/// fluxes round every cell sum to zero exactly, none crosses the wall, and
/// the fluid's circulation changes by advection only through the outer
/// face); diffusion round the section by central differences (apart: the
/// step treats it implicitly).
pub(super) struct RateRows<'a> {
    pub(super) nt: usize,
    pub(super) nr: usize,
    pub(super) d_theta: f64,
    pub(super) viscosity: f64,
    /// The vorticity and the relative streamfunction at all nodes.
    pub(super) w: &'a [f64],
    pub(super) rel: &'a [f64],
    /// The cell widths in `ξ` of [`Flow::circulation`]'s trapezoid.
    pub(super) widths: &'a [f64],
}

impl RateRows<'_> {
    /// Ring `j` of the nodes' values `f`.
    fn ring<'b>(&self, f: &'b [f64], j: usize) -> &'b [f64] {
        &f[j * self.nt..(j + 1) * self.nt]
    }

    /// The relative streamfunction at the corners `(j + ½, k + ½)` of ring
    /// `j` (`j + 1` is a ring; the wall's corners for `j` = `usize::MAX`
    /// are the wall's own values, so no flux crosses it) into `out`.
    fn corners(&self, j: usize, out: &mut [f64]) {
        let nt = self.nt;
        if j == usize::MAX {
            let wall = self.ring(self.rel, 0);
            for (k, c) in out.iter_mut().enumerate() {
                *c = 0.5 * (wall[k] + wall[(k + 1) % nt]);
            }
            return;
        }
        let (a, b) = (self.ring(self.rel, j), self.ring(self.rel, j + 1));
        for (k, c) in out.iter_mut().enumerate() {
            let kp = if k + 1 == nt { 0 } else { k + 1 };
            *c = 0.25 * (a[k] + a[kp] + b[k] + b[kp]);
        }
    }

    /// The outward advective flux of circulation through the face between
    /// rings `j` and `j + 1` at each `k` (`corners` those of [`Self::corners`]
    /// for `j`), into `out`.
    pub(super) fn radial_fluxes(&self, j: usize, corners: &[f64], out: &mut [f64]) {
        let nt = self.nt;
        let w = self.w;
        for (k, f) in out.iter_mut().enumerate() {
            let km = if k == 0 { nt - 1 } else { k - 1 };
            let q = corners[k] - corners[km];
            let at = |jj: usize| w[jj * nt + k];
            let value = if q >= 0.0 {
                match j.checked_sub(1) {
                    Some(jm) => upwind_face(at(jm), at(j), at(j + 1)),
                    None => at(j),
                }
            } else if j + 2 < self.nr {
                upwind_face(at(j + 2), at(j + 1), at(j))
            } else {
                at(j + 1)
            };
            *f = q * value;
        }
    }

    /// Ring `j` (`1 <= j < nr - 1`) of `dω/dt` into `out` and of the
    /// diffusion round the section into `diffusion`; `inv_jac` the ring's
    /// `1/J`, `scratch` five work rings.
    pub(super) fn row(
        &self,
        j: usize,
        inv_jac: &[f64],
        scratch: &mut [f64],
        (out, diffusion): (&mut [f64], &mut [f64]),
    ) {
        let nt = self.nt;
        let (lower, rest) = scratch.split_at_mut(nt);
        let (upper, rest) = rest.split_at_mut(nt);
        let (flux_in, rest) = rest.split_at_mut(nt);
        let (flux_out, flux_theta) = rest.split_at_mut(nt);
        self.corners(j, upper);
        if j == 1 {
            self.corners(usize::MAX, lower);
            flux_in.fill(0.0);
        } else {
            self.corners(j - 1, lower);
            self.radial_fluxes(j - 1, lower, flux_in);
        }
        self.radial_fluxes(j, upper, flux_out);
        let w0 = self.ring(self.w, j);
        // Round the ring: the face k + ½ between nodes k and k + 1.
        for (k, f) in flux_theta.iter_mut().enumerate() {
            let km = if k == 0 { nt - 1 } else { k - 1 };
            let kp = if k + 1 == nt { 0 } else { k + 1 };
            let kpp = if kp + 1 == nt { 0 } else { kp + 1 };
            let q = lower[k] - upper[k];
            let value = if q >= 0.0 {
                upwind_face(w0[km], w0[k], w0[kp])
            } else {
                upwind_face(w0[kpp], w0[kp], w0[k])
            };
            *f = q * value;
        }
        let inv_area = 1.0 / (self.widths[j] * self.d_theta);
        let inv_dt2 = 1.0 / (self.d_theta * self.d_theta);
        for k in 0..nt {
            let km = if k == 0 { nt - 1 } else { k - 1 };
            let kp = if k + 1 == nt { 0 } else { k + 1 };
            let divergence = flux_out[k] - flux_in[k] + flux_theta[k] - flux_theta[km];
            out[k] = -divergence * inv_area * inv_jac[k];
            let w_tt = (w0[kp] - 2.0 * w0[k] + w0[km]) * inv_dt2;
            diffusion[k] = self.viscosity * inv_jac[k] * w_tt;
        }
    }
}

/// The third-order upwind-biased value at the face between `near` and
/// `far`, the flow going from `near` to `far` and `behind` the node
/// upstream of `near`: `(-behind + 5 near + 2 far)/6`.
fn upwind_face(behind: f64, near: f64, far: f64) -> f64 {
    (-behind + 5.0 * near + 2.0 * far) / 6.0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The periodic solver against the dense system it stands for.
    #[test]
    fn the_periodic_tridiagonal_solve_satisfies_its_system() {
        let sigma: Vec<f64> = (0..9)
            .map(|k| 0.3 + 0.7 * f64::from(k).sin().abs())
            .collect();
        let b: Vec<f64> = (0..9).map(|k| f64::from(k).cos()).collect();
        let mut x = b.clone();
        solve_periodic(&sigma, &mut x, &mut [0.0; 9], &mut [0.0; 9]);
        let n = 9;
        for k in 0..n {
            let (km, kp) = ((k + n - 1) % n, (k + 1) % n);
            let lhs = -sigma[k] * x[km] + (1.0 + 2.0 * sigma[k]) * x[k] - sigma[k] * x[kp];
            assert!((lhs - b[k]).abs() < 1e-13, "row {k}: {lhs} vs {}", b[k]);
        }
    }
}
