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
    /// `self.theta_diffusion` (wall and outer rows zero); rows in parallel.
    pub(super) fn explicit_rate(&mut self) {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        for (i, r) in self.relative.iter_mut().enumerate() {
            *r = self.psi[i] - self.frame_psi[i];
        }
        let w = &self.omega;
        let rel = &self.relative;
        let rows = RateRows {
            nt,
            nr,
            d_eta: g.d_eta,
            d_theta: g.d_theta,
            viscosity: self.viscosity,
        };
        self.rate
            .par_chunks_mut(nt)
            .zip(self.theta_diffusion.par_chunks_mut(nt))
            .enumerate()
            .for_each(|(j, (out, diffusion))| {
                if j == 0 || j == nr - 1 {
                    out.fill(0.0);
                    diffusion.fill(0.0);
                } else {
                    let inv_jac = &g.inv_jac[j * nt..(j + 1) * nt];
                    rows.row(j, w, rel, inv_jac, g.slope[j], (out, diffusion));
                }
            });
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

/// The explicit rates of one ring: advection by third-order upwind
/// differences, and diffusion round the section by central differences
/// (apart: the step treats it implicitly).
struct RateRows {
    nt: usize,
    nr: usize,
    d_eta: f64,
    d_theta: f64,
    viscosity: f64,
}

impl RateRows {
    /// Ring `j` (`1 <= j < nr - 1`) of `dω/dt` into `out`, from the
    /// vorticity `w`, the relative streamfunction `rel` and the ring's
    /// `1/J` and `g'`.
    fn row(
        &self,
        j: usize,
        w: &[f64],
        rel: &[f64],
        inv_jac: &[f64],
        slope: f64,
        (out, diffusion): (&mut [f64], &mut [f64]),
    ) {
        let nt = self.nt;
        let ring = |jj: usize| &w[jj * nt..(jj + 1) * nt];
        let (w0, wm, wp) = (ring(j), ring(j - 1), ring(j + 1));
        let far = (j >= 2 && j + 2 < self.nr).then(|| (ring(j - 2), ring(j + 2)));
        let (r0, rm, rp) = (
            &rel[j * nt..(j + 1) * nt],
            &rel[(j - 1) * nt..j * nt],
            &rel[(j + 1) * nt..(j + 2) * nt],
        );
        let (half_de, half_dt) = (0.5 / self.d_eta, 0.5 / self.d_theta);
        let (inv_de, inv_dt, inv_dt2) = (
            1.0 / self.d_eta,
            1.0 / self.d_theta,
            1.0 / (self.d_theta * self.d_theta),
        );
        let inv_slope = 1.0 / slope;
        for k in 0..nt {
            let kp = if k + 1 == nt { 0 } else { k + 1 };
            let km = if k == 0 { nt - 1 } else { k - 1 };
            let kpp = if kp + 1 == nt { 0 } else { kp + 1 };
            let kmm = if km == 0 { nt - 1 } else { km - 1 };
            let scale = inv_jac[k] * inv_slope;
            let u_eta = (r0[kp] - r0[km]) * half_dt * scale;
            let u_theta = -(rp[k] - rm[k]) * half_de * scale;
            let th = [w0[kmm], w0[km], w0[k], w0[kp], w0[kpp]];
            let adv_t = u_theta * upwind3(th, u_theta) * inv_dt;
            let adv_e = match far {
                Some((wmm, wpp)) => {
                    u_eta * upwind3([wmm[k], wm[k], w0[k], wp[k], wpp[k]], u_eta) * inv_de
                }
                None => u_eta * (wp[k] - wm[k]) * half_de,
            };
            let w_tt = (th[3] - 2.0 * th[2] + th[1]) * inv_dt2;
            diffusion[k] = self.viscosity * inv_jac[k] * w_tt;
            out[k] = -adv_t - adv_e;
        }
    }
}

/// `Δ·∂f/∂x` by third-order upwind differences on five equispaced values
/// `[f_{-2}, f_{-1}, f_0, f_1, f_2]` for the advection speed `u`.
fn upwind3(f: [f64; 5], u: f64) -> f64 {
    let central = (-f[4] + 8.0 * f[3] - 8.0 * f[1] + f[0]) / 12.0;
    let dissipation = (f[4] - 4.0 * f[3] + 6.0 * f[2] - 4.0 * f[1] + f[0]) / 12.0;
    central + u.signum() * dissipation
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
