//! A flow carried over to another grid of the same section: a coarse
//! grid's flow continued on a finer one (grid sequencing: the strokes
//! that only bring a periodic flow to its state run on the coarse grid,
//! the ones that are measured on the fine one). Whether the measured
//! strokes then are the fine grid's depends on the flow: an attached,
//! periodic one forgets its start; one that carries its start's memory
//! for strokes does not (`fwav::aero2d::viscous`'s module docs).
//!
//! The vorticity is interpolated node by node, bilinearly in `(ξ, θ)` of
//! the two polar grids of the same conformal map (so in the physical
//! plane too, to second order). The fine grid's own wall layer is not in
//! the coarse flow: the wall vorticity is Thom's of the interpolated
//! flow, and the step that follows builds the layer in a few of the first
//! cell's diffusion times, `Δn²/ν` (the default FWAV section's: about
//! 0.01 chords travelled, a fifth of a percent of a stroke). The step restarts as at the start (Euler for
//! the advection's correction, backward Euler for the diffusion's first
//! steps: [`super::DAMPED_START_STEPS`]); the circulation carried out
//! through the far boundary carries over, so Kelvin's bookkeeping goes on
//! from the coarse flow's (what the interpolation changes of the fluid's
//! circulation the first step's wall vorticity makes up, as it does every
//! step's).

use realfft::num_complex::Complex64;

use super::Flow;
use crate::error::NsError;
use crate::motion::Motion;

/// How far apart the two grids' wall and outer nodes may be, over the
/// section's length (between its wall nodes at `θ = 0` and `θ = π`), for
/// the grids to count as the same section's: the maps of one section
/// fitted with different numbers of terms (a coarser grid has fewer)
/// differ by far less (4e-5 chords at the ends of a 12 % plate, 21 terms
/// against 32; 1.3e-7 of the default FWAV plate, 96 against 192), a
/// wrong time or outer radius by far more.
const SAME_SECTION: f64 = 1e-3;

/// The coarse node bracket of one fine coordinate and the weight of the
/// upper node.
#[derive(Clone, Copy)]
struct Bracket {
    lower: usize,
    upper: usize,
    weight: f64,
}

impl<M: Motion> Flow<M> {
    /// Continue `coarse`, the flow round the same section moving by the
    /// same motion (on any grid), on this flow's grid (module docs): this
    /// flow takes `coarse`'s time, its vorticity interpolated, and the
    /// circulation it has carried out through the far boundary; a
    /// deforming section's grid moves to the map of that time; the step
    /// restarts. Cost: one pass over the nodes and a streamfunction
    /// solve.
    ///
    /// # Errors
    /// [`NsError::OtherSection`] when the two grids' walls or outer
    /// boundaries are not the same curves (another section, another
    /// outer radius, or a deforming section not at the same time).
    pub fn continue_from(&mut self, coarse: &Flow<M>) -> Result<(), NsError> {
        let t = coarse.time;
        self.time = t;
        self.move_grid(t);
        self.check_same_section(coarse)?;
        let radial: Vec<Bracket> = self
            .grid
            .xi
            .iter()
            .map(|&xi| bracket_in(&coarse.grid.xi, xi))
            .collect();
        let (nt, ntc) = (self.grid.nt, coarse.grid.nt);
        let around: Vec<Bracket> = (0..nt)
            .map(|k| {
                let s = k as f64 * ntc as f64 / nt as f64;
                let lower = (s.floor() as usize).min(ntc - 1);
                Bracket {
                    lower,
                    upper: (lower + 1) % ntc,
                    weight: s - lower as f64,
                }
            })
            .collect();
        for (ring, r) in self.omega.chunks_mut(nt).zip(&radial).skip(1) {
            let (below, above) = (r.lower * ntc, r.upper * ntc);
            for (w, a) in ring.iter_mut().zip(&around) {
                let at = |row: usize| {
                    (1.0 - a.weight) * coarse.omega[row + a.lower]
                        + a.weight * coarse.omega[row + a.upper]
                };
                *w = (1.0 - r.weight) * at(below) + r.weight * at(above);
            }
        }
        self.exited = coarse.exited;
        self.steps = 0;
        self.last_dt = 0.0;
        self.previous_outflow = 0.0;
        self.outflow_rate = 0.0;
        self.outflow_explicit = 0.0;
        self.frame_time = None;
        self.evaluate(t);
        Ok(())
    }

    /// [`NsError::OtherSection`] unless this grid's wall and outer ring
    /// lie on `coarse`'s: compared where both have nodes (`θ = 0` and
    /// `θ = π`; both grids have an even number round).
    fn check_same_section(&self, coarse: &Flow<M>) -> Result<(), NsError> {
        let (fine, other) = (&self.grid, &coarse.grid);
        let pairs = [
            (fine.z[0], other.z[0]),
            (fine.z[fine.nt / 2], other.z[other.nt / 2]),
            (
                fine.z[fine.at(fine.nr - 1, 0)],
                other.z[other.at(other.nr - 1, 0)],
            ),
        ];
        let distance = pairs
            .iter()
            .map(|(a, b): &(Complex64, Complex64)| (a - b).norm())
            .fold(0.0, f64::max);
        let scale = (fine.z[0] - fine.z[fine.nt / 2]).norm();
        if distance.is_nan() || distance > SAME_SECTION * scale {
            return Err(NsError::OtherSection { distance });
        }
        Ok(())
    }
}

/// Where `x` falls among the increasing `nodes` (clamped to their ends).
fn bracket_in(nodes: &[f64], x: f64) -> Bracket {
    let last = nodes.len() - 1;
    let upper = nodes.partition_point(|&n| n < x).clamp(1, last);
    let lower = upper - 1;
    let span = nodes[upper] - nodes[lower];
    Bracket {
        lower,
        upper,
        weight: ((x - nodes[lower]) / span).clamp(0.0, 1.0),
    }
}

#[cfg(test)]
mod tests {
    use super::super::ellipse_flow;
    use super::*;

    /// A vorticity field that is bilinear in `(ξ, cos θ, sin θ)` is
    /// carried over as it is where the fine nodes fall on the coarse ones
    /// (every other node round), and the fine flow takes the coarse one's
    /// time and exited circulation; the wall ring is Thom's of the result.
    #[test]
    fn the_vorticity_carries_over_to_the_finer_grid() {
        let mut coarse = ellipse_flow(0.1, 32, 24, 0.01);
        let field = |xi: f64, theta: f64| (1.0 + xi) * theta.cos() * (-xi).exp();
        let g = coarse.grid.clone();
        for j in 1..g.nr {
            for k in 0..g.nt {
                coarse.omega[g.at(j, k)] = field(g.xi[j], k as f64 * g.d_theta);
            }
        }
        coarse.time = 0.7;
        coarse.exited = 0.125;
        let mut fine = ellipse_flow(0.1, 64, 24, 0.01);
        fine.continue_from(&coarse).unwrap();
        assert_eq!(fine.time(), 0.7);
        assert_eq!(fine.exited_circulation(), 0.125);
        let f = fine.grid.clone();
        for j in 1..f.nr {
            for k in (0..f.nt).step_by(2) {
                let want = coarse.omega[g.at(j, k / 2)];
                assert!((fine.omega[f.at(j, k)] - want).abs() < 1e-12, "({j}, {k})");
            }
            // Between the coarse nodes: their mean.
            let between = 0.5 * (coarse.omega[g.at(j, 0)] + coarse.omega[g.at(j, 1)]);
            assert!((fine.omega[f.at(j, 1)] - between).abs() < 1e-12);
        }
    }

    /// A flow on another section is refused with the distance between
    /// the walls.
    #[test]
    fn another_section_is_refused() {
        let coarse = ellipse_flow(0.1, 32, 24, 0.01);
        let mut other = ellipse_flow(0.2, 64, 24, 0.01);
        assert!(matches!(
            other.continue_from(&coarse),
            Err(NsError::OtherSection { distance }) if distance > 0.01
        ));
    }

    #[test]
    fn a_bracket_clamps_to_the_ends() {
        let nodes = [0.0, 1.0, 3.0];
        let b = bracket_in(&nodes, 2.0);
        assert_eq!((b.lower, b.upper, b.weight), (1, 2, 0.5));
        assert_eq!(bracket_in(&nodes, -1.0).weight, 0.0);
        let end = bracket_in(&nodes, 5.0);
        assert_eq!((end.lower, end.upper, end.weight), (1, 2, 1.0));
    }
}
