//! The implicit sweeps of a step, Douglas's ADI: the ring sweep first
//! (periodic tridiagonal systems), then the radial sweep with the wall
//! vorticity at the step's end (so that the wall's influence on the step
//! is the radial sweep's alone: see [`super::Flow::step`]); both with
//! Crank–Nicolson diffusion and θ-weighted first-order advection.

use rayon::prelude::*;

use super::Flow;
use crate::motion::Motion;

impl<M: Motion> Flow<M> {
    /// The first ADI sweep: `ω* = (1 - dt Θ_θ)⁻¹ (ω + dt E)` on every
    /// interior ring, `Θ_θ` the implicit part of the ring diffusion (half, but
    /// at the start: [`super::Flow::step`]) and the `θ` part of
    /// the first-order ring advection (`self.ring_speed`), `E` the
    /// explicit rate in `self.rate` (periodic tridiagonal systems, rings
    /// in parallel).
    pub(super) fn ring_implicit(&mut self, dt: f64) {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        let factor = self.diffusion_weight * dt * self.viscosity / (g.d_theta * g.d_theta);
        let widths = &self.widths;
        self.omega
            .par_chunks_mut(nt)
            .zip(self.rate.par_chunks(nt))
            .zip(self.ring_speed.par_chunks(nt))
            .zip(g.inv_jac.par_chunks(nt))
            .enumerate()
            .filter(|(j, _)| *j > 0 && *j < nr - 1)
            .for_each_init(
                || vec![0.0; 5 * nt],
                |scratch, (j, (((ring, rate), speed), inv_jac))| {
                    let (lower, rest) = scratch.split_at_mut(nt);
                    let (diag, rest) = rest.split_at_mut(nt);
                    let (upper, rest) = rest.split_at_mut(nt);
                    let (work, z) = rest.split_at_mut(nt);
                    let inv_width = dt / (widths[j] * g.d_theta);
                    for k in 0..nt {
                        let km = if k == 0 { nt - 1 } else { k - 1 };
                        let sigma = factor * inv_jac[k];
                        let s = inv_width * inv_jac[k];
                        let (q, p) = (speed[k], speed[km]);
                        lower[k] = -sigma - s * p.max(0.0);
                        diag[k] = 1.0 + 2.0 * sigma + s * (q.max(0.0) - p.min(0.0));
                        upper[k] = -sigma + s * q.min(0.0);
                        ring[k] += dt * rate[k];
                    }
                    solve_periodic(lower, diag, upper, ring, work, z);
                },
            );
    }

    /// The second ADI sweep, `ω ← (1 - dt Θ_r)⁻¹ (ω* - dt Θ_r ω_old)`
    /// along each radial line, `Θ_r` the implicit part of the radial
    /// diffusion `D = ν/(J g'²)(∂ηη - β ∂η)` and the `θ` part of the
    /// first-order radial advection (`self.radial_speed`, none through
    /// the wall's face), `Θ_r ω_old` being `self.radial_old`; with the
    /// wall vorticity `new_wall` at the end of the step and the outer
    /// ring's value held. The Thomas sweeps run ring by ring over blocks
    /// of lines in parallel; the elimination is kept for
    /// [`Self::radial_wall_change`].
    pub(super) fn radial_crank_nicolson(&mut self, dt: f64, new_wall: &[f64]) {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        let h2 = 1.0 / (g.d_eta * g.d_eta);
        let half = g.curvature / (2.0 * g.d_eta);
        let (a, c) = (h2 + half, h2 - half);
        let bounds = line_blocks(nt);
        let (speed, radial_old, widths) = (&self.radial_speed, &self.radial_old, &self.widths);
        let weight = self.diffusion_weight * dt * self.viscosity;
        let blocks: Vec<_> = column_blocks(&mut self.omega, nt, &bounds)
            .into_iter()
            .zip(column_blocks(&mut self.sweep_upper, nt, &bounds))
            .zip(column_blocks(&mut self.sweep_rhs, nt, &bounds))
            .zip(column_blocks(&mut self.sweep_gain, nt, &bounds))
            .zip(bounds.iter().copied())
            .collect();
        blocks.into_par_iter().for_each(
            |((((mut w, mut upper_mod), mut solved), mut gain), k0)| {
                for j in 1..nr - 1 {
                    let factor = weight / (g.slope[j] * g.slope[j]);
                    let inv_width = dt / (widths[j] * g.d_theta);
                    let (w_lo, w_hi) = w.split_at_mut(j + 1);
                    let (ring, above) = (&*w_lo[j], &*w_hi[0]);
                    let (s_lo, s_hi) = solved.split_at_mut(j);
                    let (u_lo, u_hi) = upper_mod.split_at_mut(j);
                    let gain_row = &mut *gain[j];
                    for kk in 0..ring.len() {
                        let i = j * nt + k0 + kk;
                        let kappa = factor * g.inv_jac[i];
                        let s = inv_width * g.inv_jac[i];
                        let q = speed[i];
                        let p = if j == 1 { 0.0 } else { speed[i - nt] };
                        let lower = -kappa * a - s * p.max(0.0);
                        let diag = 1.0 + 2.0 * kappa * h2 + s * (q.max(0.0) - p.min(0.0));
                        let mut upper = -kappa * c + s * q.min(0.0);
                        let mut rhs = ring[kk] - dt * radial_old[i];
                        if j == nr - 2 {
                            rhs -= upper * above[kk];
                            upper = 0.0;
                        }
                        // Ring 1's lower neighbour is the wall, known.
                        let (coupled, prev_upper, prev_rhs) = if j == 1 {
                            rhs -= lower * new_wall[k0 + kk];
                            (0.0, 0.0, 0.0)
                        } else {
                            (lower, u_lo[j - 1][kk], s_lo[j - 1][kk])
                        };
                        let inv = 1.0 / (diag - coupled * prev_upper);
                        u_hi[0][kk] = upper * inv;
                        s_hi[0][kk] = (rhs - coupled * prev_rhs) * inv;
                        gain_row[kk] = -lower * inv;
                    }
                }
                back_substitute(&mut w, &upper_mod, &solved);
            },
        );
    }

    /// The radial sweep of [`Self::radial_crank_nicolson`] again with the
    /// wall vorticity changed by `change`: the same elimination, the
    /// change carried through it (linear), and the back substitution.
    pub(super) fn radial_wall_change(&mut self, change: &[f64]) {
        let nt = self.grid.nt;
        let bounds = line_blocks(nt);
        let blocks: Vec<_> = column_blocks(&mut self.omega, nt, &bounds)
            .into_iter()
            .zip(column_blocks(&mut self.sweep_upper, nt, &bounds))
            .zip(column_blocks(&mut self.sweep_rhs, nt, &bounds))
            .zip(column_blocks(&mut self.sweep_gain, nt, &bounds))
            .zip(bounds.iter().copied())
            .collect();
        blocks
            .into_par_iter()
            .for_each(|((((mut w, upper_mod), mut solved), gain), k0)| {
                let rings = solved.len();
                for kk in 0..solved[1].len() {
                    let mut carried = change[k0 + kk];
                    for j in 1..rings - 1 {
                        carried *= gain[j][kk];
                        solved[j][kk] += carried;
                    }
                }
                back_substitute(&mut w, &upper_mod, &solved);
            });
    }
}

/// The bounds of the blocks of radial lines the sweeps run in parallel:
/// one per worker thread.
fn line_blocks(nt: usize) -> Vec<usize> {
    let blocks = rayon::current_num_threads().clamp(1, nt);
    (0..=blocks).map(|b| b * nt / blocks).collect()
}

/// Each ring of `data` (rings of `nt`) cut at the columns `bounds`: per
/// block, its pieces of every ring.
fn column_blocks<'a>(data: &'a mut [f64], nt: usize, bounds: &[usize]) -> Vec<Vec<&'a mut [f64]>> {
    let blocks = bounds.len() - 1;
    let mut out: Vec<Vec<&mut [f64]>> = (0..blocks)
        .map(|_| Vec::with_capacity(data.len() / nt))
        .collect();
    for ring in data.chunks_mut(nt) {
        let mut rest = ring;
        for (b, block) in out.iter_mut().enumerate() {
            let (piece, tail) = rest.split_at_mut(bounds[b + 1] - bounds[b]);
            block.push(piece);
            rest = tail;
        }
    }
    out
}

/// The radial sweep's back substitution on one block of lines: rings
/// `nr - 2` down to 1 of `w` from the eliminated system (the outer ring's
/// value, held, enters with a zero coefficient).
fn back_substitute(w: &mut [&mut [f64]], upper_mod: &[&mut [f64]], solved: &[&mut [f64]]) {
    let rings = w.len();
    for j in (1..rings - 1).rev() {
        let (lo, hi) = w.split_at_mut(j + 1);
        let (ring, above) = (&mut *lo[j], &*hi[0]);
        for (kk, v) in ring.iter_mut().enumerate() {
            *v = solved[j][kk] - upper_mod[j][kk] * above[kk];
        }
    }
}

/// Solve `l_k x_{k-1} + d_k x_k + u_k x_{k+1} = b_k` round a ring
/// (periodic: `x_{-1} = x_{n-1}`, `x_n = x_0`), in place, by the Thomas
/// algorithm with the Sherman–Morrison correction for the corners
/// (Press et al., *Numerical Recipes*, 3rd ed., §2.7.2). Without pivoting:
/// the sweeps' matrices are diagonally dominant (diffusion and upwind
/// advection). `work` and `z` are rings of the same length (no
/// allocation: the step calls this for every ring); `diag` is modified.
fn solve_periodic(
    lower: &[f64],
    diag: &mut [f64],
    upper: &[f64],
    b: &mut [f64],
    work: &mut [f64],
    z: &mut [f64],
) {
    let n = b.len();
    // A = T + u vᵀ, u = (γ, 0, …, 0, u_{n-1}), v = (1, 0, …, 0, l_0/γ).
    let gamma = -diag[0];
    diag[0] -= gamma;
    diag[n - 1] -= lower[0] * upper[n - 1] / gamma;
    z.fill(0.0);
    z[0] = gamma;
    z[n - 1] = upper[n - 1];
    // Forward elimination of T for both right-hand sides.
    let mut prev_upper = 0.0;
    for k in 0..n {
        let l = if k == 0 { 0.0 } else { lower[k] };
        let inv = 1.0 / (diag[k] - l * prev_upper);
        work[k] = if k + 1 < n { upper[k] * inv } else { 0.0 };
        if k > 0 {
            b[k] -= l * b[k - 1];
            z[k] -= l * z[k - 1];
        }
        b[k] *= inv;
        z[k] *= inv;
        prev_upper = work[k];
    }
    for k in (0..n - 1).rev() {
        b[k] -= work[k] * b[k + 1];
        z[k] -= work[k] * z[k + 1];
    }
    let v_last = lower[0] / gamma;
    let factor = (b[0] + v_last * b[n - 1]) / (1.0 + z[0] + v_last * z[n - 1]);
    for k in 0..n {
        b[k] -= factor * z[k];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The periodic solver against the dense, unsymmetric system it
    /// stands for (diffusion plus upwind advection of either sign).
    #[test]
    fn the_periodic_tridiagonal_solve_satisfies_its_system() {
        let n = 9;
        let sigma: Vec<f64> = (0..n)
            .map(|k| 0.3 + 0.7 * f64::from(k as u8).sin().abs())
            .collect();
        let speed: Vec<f64> = (0..n).map(|k| 2.0 * f64::from(k as u8).cos()).collect();
        let lower: Vec<f64> = (0..n)
            .map(|k| -sigma[k] - speed[(k + n - 1) % n].max(0.0))
            .collect();
        let upper: Vec<f64> = (0..n).map(|k| -sigma[k] + speed[k].min(0.0)).collect();
        let diag: Vec<f64> = (0..n)
            .map(|k| 1.0 + 2.0 * sigma[k] + speed[k].max(0.0) - speed[(k + n - 1) % n].min(0.0))
            .collect();
        let b: Vec<f64> = (0..n).map(|k| f64::from(k as u8).cos()).collect();
        let mut x = b.clone();
        solve_periodic(
            &lower,
            &mut diag.clone(),
            &upper,
            &mut x,
            &mut [0.0; 9],
            &mut [0.0; 9],
        );
        for k in 0..n {
            let (km, kp) = ((k + n - 1) % n, (k + 1) % n);
            let lhs = lower[k] * x[km] + diag[k] * x[k] + upper[k] * x[kp];
            assert!((lhs - b[k]).abs() < 1e-13, "row {k}: {lhs} vs {}", b[k]);
        }
    }
}
