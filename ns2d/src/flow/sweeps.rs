//! The implicit sweeps of a step, Douglas's ADI: the ring sweep first
//! (periodic tridiagonal systems), then the radial sweep with the wall
//! vorticity at the step's end (so that the wall's influence on the step
//! is the radial sweep's alone: see [`super::Flow::step`]); both with
//! Crank–Nicolson diffusion and θ-weighted first-order advection.

use rayon::prelude::*;

use super::Flow;
use crate::blocks;
use crate::motion::Motion;

impl<M: Motion> Flow<M> {
    /// The first ADI sweep: `ω* = (1 - dt Θ_θ)⁻¹ (ω + dt E)` on every
    /// interior ring, `Θ_θ` the implicit part of the ring diffusion (half, but
    /// at the start: [`super::Flow::step`]) and the `θ` part of
    /// the first-order ring advection (`self.ring_speed`), `E` the
    /// explicit rate in `self.rate` (periodic tridiagonal systems, blocks
    /// of [`LANES`] rings in parallel, each block's rings eliminated side
    /// by side).
    pub(super) fn ring_implicit(&mut self, dt: f64) {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        let factor = self.diffusion_weight * dt * self.viscosity / (g.d_theta * g.d_theta);
        let widths = &self.widths;
        let span = LANES * nt;
        self.omega
            .par_chunks_mut(span)
            .zip(self.rate.par_chunks(span))
            .zip(self.ring_speed.par_chunks(span))
            .zip(g.inv_jac.par_chunks(span))
            .enumerate()
            .for_each_init(
                || vec![0.0; 6 * span],
                |scratch, (block, (((rings, rate), speed), inv_jac))| {
                    let (lower, rest) = scratch.split_at_mut(span);
                    let (diag, rest) = rest.split_at_mut(span);
                    let (upper, rest) = rest.split_at_mut(span);
                    let (b, rest) = rest.split_at_mut(span);
                    let (work, z) = rest.split_at_mut(span);
                    let count = rings.len() / nt;
                    // Per lane (ring of the block): whether it is an
                    // interior ring (the others get an identity system and
                    // are not written) and its `dt / (w_j Δθ)`.
                    let mut live = [false; LANES];
                    let mut inv_width = [0.0; LANES];
                    for l in 0..LANES {
                        let j = block * LANES + l;
                        live[l] = l < count && j > 0 && j < nr - 1;
                        if live[l] {
                            inv_width[l] = dt / (widths[j] * g.d_theta);
                        }
                    }
                    // Node by node, the lanes inner: the interleaved
                    // systems are written in order (lane by lane, each
                    // write touched another cache line).
                    for k in 0..nt {
                        let km = if k == 0 { nt - 1 } else { k - 1 };
                        for l in 0..LANES {
                            let i = k * LANES + l;
                            if !live[l] {
                                (lower[i], diag[i], upper[i], b[i]) = (0.0, 1.0, 0.0, 0.0);
                                continue;
                            }
                            let at = l * nt;
                            let sigma = factor * inv_jac[at + k];
                            let s = inv_width[l] * inv_jac[at + k];
                            let (q, p) = (speed[at + k], speed[at + km]);
                            lower[i] = -sigma - s * p.max(0.0);
                            diag[i] = 1.0 + 2.0 * sigma + s * (q.max(0.0) - p.min(0.0));
                            upper[i] = -sigma + s * q.min(0.0);
                            b[i] = rings[at + k] + dt * rate[at + k];
                        }
                    }
                    solve_periodic(lower, diag, upper, b, work, z);
                    for (k, solved) in b.chunks_exact(LANES).enumerate() {
                        for (l, x) in solved.iter().enumerate() {
                            if live[l] {
                                rings[l * nt + k] = *x;
                            }
                        }
                    }
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
        let (speed, radial_old, widths) = (&self.radial_speed, &self.radial_old, &self.widths);
        let weight = self.diffusion_weight * dt * self.viscosity;
        let lines = line_blocks(
            &mut self.omega,
            &mut self.sweep_upper,
            &mut self.sweep_rhs,
            &mut self.sweep_gain,
            nt,
        );
        lines
            .into_par_iter()
            .for_each(|((((mut w, mut upper_mod), mut solved), mut gain), k0)| {
                let width = w[0].len();
                let zeros = vec![0.0; width];
                let new_wall = &new_wall[k0..k0 + width];
                for j in 1..nr - 1 {
                    let (a, c) = g.radial_neighbours(j);
                    let factor = weight / (g.slope[j] * g.slope[j]);
                    let inv_width = dt / (widths[j] * g.d_theta);
                    // The ring's slices of the block (no index arithmetic
                    // in the loop: it vectorizes).
                    let r = j * nt + k0..j * nt + k0 + width;
                    let (q_row, inv_jac, old) = (
                        &speed[r.clone()],
                        &g.inv_jac[r.clone()],
                        &radial_old[r.clone()],
                    );
                    let (first, last) = (j == 1, j == nr - 2);
                    // Ring 1's lower neighbour is the wall, known: no
                    // advection through the wall's face, no elimination.
                    let p_row = if first {
                        &zeros[..]
                    } else {
                        &speed[r.start - nt..r.end - nt]
                    };
                    let (w_lo, w_hi) = w.split_at_mut(j + 1);
                    let (ring, above) = (&*w_lo[j], &*w_hi[0]);
                    let (s_lo, s_hi) = solved.split_at_mut(j);
                    let (u_lo, u_hi) = upper_mod.split_at_mut(j);
                    let (prev_upper, prev_rhs) = if first {
                        (&zeros[..], &zeros[..])
                    } else {
                        (&*u_lo[j - 1], &*s_lo[j - 1])
                    };
                    let (u_out, s_out, gain_row) = (&mut *u_hi[0], &mut *s_hi[0], &mut *gain[j]);
                    for kk in 0..width {
                        let kappa = factor * inv_jac[kk];
                        let s = inv_width * inv_jac[kk];
                        let (q, p) = (q_row[kk], p_row[kk]);
                        let lower = -kappa * a - s * p.max(0.0);
                        let diag = 1.0 + 2.0 * kappa * h2 + s * (q.max(0.0) - p.min(0.0));
                        let full_upper = -kappa * c + s * q.min(0.0);
                        let mut rhs = ring[kk] - dt * old[kk];
                        // The outer ring's value is held: it moves to the
                        // right-hand side.
                        rhs -= if last { full_upper * above[kk] } else { 0.0 };
                        let upper = if last { 0.0 } else { full_upper };
                        rhs -= if first { lower * new_wall[kk] } else { 0.0 };
                        let coupled = if first { 0.0 } else { lower };
                        let inv = 1.0 / (diag - coupled * prev_upper[kk]);
                        u_out[kk] = upper * inv;
                        s_out[kk] = (rhs - coupled * prev_rhs[kk]) * inv;
                        gain_row[kk] = -lower * inv;
                    }
                }
                let top = w.len() - 2;
                back_substitute(&mut w, &upper_mod, &solved, top);
            });
    }

    /// The radial sweep of [`Self::radial_crank_nicolson`] again with the
    /// wall vorticity changed by `change`: the same elimination, the
    /// change carried through it (linear), and the back substitution.
    /// Returns the rings from the wall out that it may have changed (the
    /// wall ring, whose value the caller sets, included): the others keep
    /// the first pass's values bit for bit.
    pub(super) fn radial_wall_change(&mut self, change: &[f64]) -> usize {
        let nt = self.grid.nt;
        let lines = line_blocks(
            &mut self.omega,
            &mut self.sweep_upper,
            &mut self.sweep_rhs,
            &mut self.sweep_gain,
            nt,
        );
        // A line's carried change stops where it falls to the rounding of
        // the largest change of all lines (1e-17 of it; 1e-16 by ring 27
        // to 41 of 160 on the default FWAV section): the line's rings
        // above keep the first pass's values. Each line stops on its own,
        // whatever block it is in, so the flow does not depend on how
        // many threads share the lines (`tests/thread_count.rs`).
        let rounding = 1e-17 * change.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
        let top = lines
            .into_par_iter()
            .map(|((((mut w, upper_mod), mut solved), gain), k0)| {
                let rings = solved.len();
                // Ring by ring, the block's lines side by side (the rings
                // are contiguous, the lines are not), until every line's
                // carried change has stopped (is zeroed: it then adds
                // nothing, and the back substitution of its rings above
                // its stop gives the first pass's values again).
                let mut carried = change[k0..k0 + solved[1].len()].to_vec();
                let mut top = 0;
                for j in 1..rings - 1 {
                    let mut live = false;
                    for c in carried.iter_mut() {
                        if c.abs() <= rounding {
                            *c = 0.0;
                        } else {
                            live = true;
                        }
                    }
                    if !live {
                        break;
                    }
                    for ((c, s), g) in carried
                        .iter_mut()
                        .zip(solved[j].iter_mut())
                        .zip(gain[j].iter())
                    {
                        *c *= g;
                        *s += *c;
                    }
                    top = j;
                }
                back_substitute(&mut w, &upper_mod, &solved, top);
                top
            })
            .max()
            .unwrap_or(0);
        top + 1
    }
}

/// One block's pieces of every ring of a field ([`blocks::pieces`]).
type Pieces<'a> = Vec<&'a mut [f64]>;

/// A block of radial lines: its pieces of the vorticity and of the kept
/// elimination (modified upper diagonal, right-hand side, gains), and its
/// first line.
type LineBlock<'a> = ((((Pieces<'a>, Pieces<'a>), Pieces<'a>), Pieces<'a>), usize);

/// The radial sweeps' blocks of lines, one per worker thread, over the
/// vorticity and the elimination's `upper`, `rhs` and `gain` (rings of
/// `nt`).
fn line_blocks<'a>(
    omega: &'a mut [f64],
    upper: &'a mut [f64],
    rhs: &'a mut [f64],
    gain: &'a mut [f64],
    nt: usize,
) -> Vec<LineBlock<'a>> {
    let bounds = blocks::bounds(0, nt);
    blocks::pieces(omega, nt, &bounds)
        .into_iter()
        .zip(blocks::pieces(upper, nt, &bounds))
        .zip(blocks::pieces(rhs, nt, &bounds))
        .zip(blocks::pieces(gain, nt, &bounds))
        .zip(bounds.iter().copied())
        .collect()
}

/// The radial sweep's back substitution on one block of lines: rings
/// `top` down to 1 of `w` from the eliminated system (the ring above
/// `top` given; the outer ring's value, held, enters with a zero
/// coefficient).
fn back_substitute(
    w: &mut [&mut [f64]],
    upper_mod: &[&mut [f64]],
    solved: &[&mut [f64]],
    top: usize,
) {
    for j in (1..=top).rev() {
        let (lo, hi) = w.split_at_mut(j + 1);
        let (ring, above) = (&mut *lo[j], &*hi[0]);
        for (kk, v) in ring.iter_mut().enumerate() {
            *v = solved[j][kk] - upper_mod[j][kk] * above[kk];
        }
    }
}

/// The rings the ring sweep eliminates side by side: the Thomas
/// algorithm is a chain of dependent divisions, and independent chains
/// interleaved keep the processor busy (the ring sweep of the default
/// FWAV section's 256 × 160 grid took 0.32 ms a step one ring at a time,
/// 0.21 ms in blocks of 8, on two cores).
pub(super) const LANES: usize = 8;

/// Solve [`LANES`] systems `l_k x_{k-1} + d_k x_k + u_k x_{k+1} = b_k`
/// round a ring (periodic: `x_{-1} = x_{n-1}`, `x_n = x_0`), in place,
/// by the Thomas algorithm with the Sherman–Morrison correction for the
/// corners (Press et al., *Numerical Recipes*, 3rd ed., §2.7.2); the
/// systems interleaved, entry `k` of system `l` at `k * LANES + l`.
/// Without pivoting: the sweeps' matrices are diagonally dominant
/// (diffusion and upwind advection). `work` and `z` have the same length
/// (no allocation: the step calls this for every block); `diag` is
/// modified.
fn solve_periodic(
    lower: &[f64],
    diag: &mut [f64],
    upper: &[f64],
    b: &mut [f64],
    work: &mut [f64],
    z: &mut [f64],
) {
    const L: usize = LANES;
    let n = b.len() / L;
    let last = (n - 1) * L;
    // A = T + u vᵀ, u = (γ, 0, …, 0, u_{n-1}), v = (1, 0, …, 0, l_0/γ).
    let mut gamma = [0.0; L];
    z.fill(0.0);
    for l in 0..L {
        gamma[l] = -diag[l];
        diag[l] -= gamma[l];
        diag[last + l] -= lower[l] * upper[last + l] / gamma[l];
        z[l] = gamma[l];
        z[last + l] = upper[last + l];
    }
    // Forward elimination of T for both right-hand sides.
    for l in 0..L {
        let inv = 1.0 / diag[l];
        work[l] = upper[l] * inv;
        b[l] *= inv;
        z[l] *= inv;
    }
    for k in 1..n {
        let (done, row) = ((k - 1) * L, k * L);
        let (bp, br) = b.split_at_mut(row);
        let (zp, zr) = z.split_at_mut(row);
        let (wp, wr) = work.split_at_mut(row);
        let keep = if k + 1 < n { 1.0 } else { 0.0 };
        for l in 0..L {
            let lo = lower[row + l];
            let inv = 1.0 / (diag[row + l] - lo * wp[done + l]);
            wr[l] = keep * upper[row + l] * inv;
            br[l] = (br[l] - lo * bp[done + l]) * inv;
            zr[l] = (zr[l] - lo * zp[done + l]) * inv;
        }
    }
    for k in (0..n - 1).rev() {
        let (row, below) = b.split_at_mut((k + 1) * L);
        let (zrow, zbelow) = z.split_at_mut((k + 1) * L);
        for l in 0..L {
            let w = work[k * L + l];
            row[k * L + l] -= w * below[l];
            zrow[k * L + l] -= w * zbelow[l];
        }
    }
    let mut factor = [0.0; L];
    for l in 0..L {
        let v_last = lower[l] / gamma[l];
        factor[l] = (b[l] + v_last * b[last + l]) / (1.0 + z[l] + v_last * z[last + l]);
    }
    for (row, zrow) in b.chunks_exact_mut(L).zip(z.chunks_exact(L)) {
        for l in 0..L {
            row[l] -= factor[l] * zrow[l];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The periodic solver against the dense, unsymmetric systems it
    /// stands for (diffusion plus upwind advection of either sign), a
    /// different one in each lane.
    #[test]
    fn the_periodic_tridiagonal_solve_satisfies_its_system() {
        /// Lower, diagonal, upper, right-hand side.
        type System = (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>);
        let n = 9;
        let lane = |l: usize| {
            let f = |k: usize, a: f64| ((k as f64) * a + l as f64).sin();
            let sigma: Vec<f64> = (0..n).map(|k| 0.3 + 0.7 * f(k, 1.0).abs()).collect();
            let speed: Vec<f64> = (0..n).map(|k| 2.0 * f(k, 0.7)).collect();
            let lower: Vec<f64> = (0..n)
                .map(|k| -sigma[k] - speed[(k + n - 1) % n].max(0.0))
                .collect();
            let upper: Vec<f64> = (0..n).map(|k| -sigma[k] + speed[k].min(0.0)).collect();
            let diag: Vec<f64> = (0..n)
                .map(|k| 1.0 + 2.0 * sigma[k] + speed[k].max(0.0) - speed[(k + n - 1) % n].min(0.0))
                .collect();
            let b: Vec<f64> = (0..n).map(|k| f(k, 1.3).cos()).collect();
            (lower, diag, upper, b)
        };
        let systems: Vec<_> = (0..LANES).map(lane).collect();
        let interleave = |pick: &dyn Fn(&System) -> &Vec<f64>| {
            let mut out = vec![0.0; n * LANES];
            for (l, s) in systems.iter().enumerate() {
                for k in 0..n {
                    out[k * LANES + l] = pick(s)[k];
                }
            }
            out
        };
        let (lower, diag, upper, b) = (
            interleave(&|s| &s.0),
            interleave(&|s| &s.1),
            interleave(&|s| &s.2),
            interleave(&|s| &s.3),
        );
        let mut x = b.clone();
        solve_periodic(
            &lower,
            &mut diag.clone(),
            &upper,
            &mut x,
            &mut vec![0.0; n * LANES],
            &mut vec![0.0; n * LANES],
        );
        for (l, (lo, d, up, rhs)) in systems.iter().enumerate() {
            for k in 0..n {
                let (km, kp) = ((k + n - 1) % n, (k + 1) % n);
                let xs = |kk: usize| x[kk * LANES + l];
                let lhs = lo[k] * xs(km) + d[k] * xs(k) + up[k] * xs(kp);
                assert!(
                    (lhs - rhs[k]).abs() < 1e-13,
                    "system {l}, row {k}: {lhs} vs {}",
                    rhs[k]
                );
            }
        }
    }
}
