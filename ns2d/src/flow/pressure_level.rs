//! The level of the wall pressure: its mean round the wall relative to
//! the pressure of the fluid far away.
//!
//! [`super::WallLoads::pressure`] is integrated along the wall from the
//! momentum equation there, which gives its differences, not its level.
//! The level comes from the momentum equation along the grid's radial
//! lines, from the outer ring in to the wall, averaged over the lines.
//!
//! In the frame of the far fluid (at rest; density 1) the momentum
//! equation in Lamb's form is
//!
//! ```text
//! ∇H = -∂u/∂t - ω ẑ×u - ν ∇×(ω ẑ),   H = p + |u|²/2.
//! ```
//!
//! Integrate it along the radial line `C` of a node `k` round the wall,
//! from the outer ring to the wall. The line moves with the grid, at the
//! nodes' velocity `v` (the frame's `V + Ω×z` and a deforming grid's
//! own). By the transport of a line integral along a moving curve,
//! `∫_C ∂u/∂t·dl = d/dt ∫_C u·dl + ∫_C (v×ω ẑ)·dl - [u·v]`, the ends'
//! term taken from the outer ring to the wall. So
//!
//! ```text
//! H_wall - H_outer = -d/dt ∫_C u·dl + [u·v] - ∫_C ω (ẑ×(u - v))·dl - ν ∫_C ∇×(ω ẑ)·dl.
//! ```
//!
//! On the conformal grid (`z = F(ξ + iθ)`) a radial line's `u·dl` is
//! `∂ψ/∂θ dξ` and its `∇×(ω ẑ)·dl` is `∂ω/∂θ dξ`: both are derivatives
//! round the rings, so their means over the lines vanish (`ψ` and `ω` are
//! periodic in `θ`), and with them the unsteady and the viscous terms.
//! The wall moves with its nodes (no slip: `u = v` there), and the mean
//! of `H` over the outer ring is the far fluid's, 0: outside the
//! vorticity, `H = -∂φ/∂t` (Bernoulli), and the potential of a flow whose
//! circulation does not change (none has left through the ring) is a
//! series in `1/ζ` without a constant term there, of mean zero round a
//! ring. What is left is, averaged over the lines `k`,
//!
//! ```text
//! mean p_wall = mean_k [ |v_wall|²/2 - u_outer·v_outer + ∫_wall^outer ω (ẑ×(u - v))·dl ].
//! ```
//!
//! The integral is the vorticity's flux across the line relative to it:
//! `(ẑ×w)·dl = dψr - Re(i w_g conj(z_ξ)) dξ` with `ψr = ψ - ψ_frame - ψ_g`
//! and `w_g` a deforming grid's own velocity less its rigid part, whose
//! streamfunction is `ψ_g` (`flow/deforming.rs`). Across a boundary layer it is
//! the loss of `|u - v|²/2` to the wall, Bernoulli's jump the layer does
//! not make in the pressure.
//!
//! Approximations: the outer ring's own conditions (`ψ = 0` there, where
//! the unbounded flow's potential is `O(a²/R)` for a section of size `a`:
//! the level is off by `O(a²/R²)`, 3e-4 for a chord at 30 chords), and
//! the vorticity at or just past the outer ring, where the ring is not in
//! irrotational flow. Bernoulli fails only over the arc a vortex crosses
//! (a fraction `core/(2πR)` of the mean), and the unsteady potential of
//! a vortex `γ` carried at speed `U` just outside the ring has a mean
//! round it of `O(γU/(2πR))`, fading as it goes on: a percent of the
//! dynamic pressure for `γ ~ 1` at 30 chords, while a wake leaves. On
//! the cylinder shedding at Re 100 the wall's mean `C_p` is -0.4901
//! before its wake reaches the outer ring and -0.4929 as it leaves
//! (`tests/wall_pressure_level.rs`, with the exact and independent
//! checks).

use realfft::num_complex::Complex64;

use super::Flow;
use crate::motion::Motion;

impl<M: Motion> Flow<M> {
    /// The mean round the wall (over its nodes, equally spaced in `θ`) of
    /// the wall pressure relative to the far fluid's, density 1 (module
    /// docs): add it to [`super::WallLoads::pressure`], whose mean is
    /// zero, for the pressure itself. Cost: one pass over the grid.
    #[must_use]
    pub fn wall_pressure_mean(&self) -> f64 {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        let frame = self.frame;
        let rigid = frame.rigid_field();
        // At node `k` of the wall's ring or the outer ring's.
        let node_velocity = |outer: bool, k: usize| {
            let i = if outer { g.at(nr - 1, k) } else { k };
            frame.point_velocity(g.z[i]) + self.grid_velocity(outer, k)
        };
        // Relative to a deforming grid's rigid part too, and the rest of
        // its velocity across a radial line, per unit ξ.
        let relative =
            |i: usize| self.psi[i] - rigid.streamfunction(g.z[i]) - self.grid_rigid_psi(i);
        let i_unit = Complex64::new(0.0, 1.0);
        let swept = |i: usize| (i_unit * self.swept_rest(i)).re;
        let outer_velocity = self.outer_ring_velocity();
        let sum: f64 = (0..nt)
            .map(|k| {
                let wall = 0.5 * node_velocity(false, k).norm_sqr();
                let outer = (outer_velocity[k] * node_velocity(true, k).conj()).re;
                let mut flux = 0.0;
                for j in 0..nr - 1 {
                    let (a, b) = (g.at(j, k), g.at(j + 1, k));
                    let omega = 0.5 * (self.omega[a] + self.omega[b]);
                    let sweep = 0.5 * (swept(a) + swept(b)) * (g.xi[j + 1] - g.xi[j]);
                    flux += omega * (relative(b) - relative(a) - sweep);
                }
                wall - outer + flux
            })
            .sum();
        sum / nt as f64
    }

    /// The fluid's velocity at the outer ring's nodes (body axes;
    /// [`crate::OGrid::velocity`], `ψ_ξ` one-sided there).
    fn outer_ring_velocity(&self) -> Vec<Complex64> {
        let g = &self.grid;
        (0..g.nt)
            .map(|k| g.velocity(&self.psi, g.nr - 1, k))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::GridSpec;
    use crate::motion::FrameState;
    use crate::section_map::SectionMap;

    /// A circle of radius `R` turning at a steady `Ω` in the fluid it has
    /// set turning as a potential vortex, `u_θ = ΩR²/r`: an exact steady
    /// solution of the Navier–Stokes equations with no slip (Batchelor,
    /// *An Introduction to Fluid Dynamics*, 1967, §4.5), whose pressure
    /// `-(ΩR²/r)²/2` is `-Ω²R²/2` at the wall. The vorticity is zero; the
    /// level comes from the wall's and the outer ring's terms, where the
    /// frame's velocity is `Ω` times 20 radii. Measured: 2.4e-6 of it off
    /// on 64 × 192 nodes (1.8e-4 on 64 × 96: the outer ring's one-sided
    /// `ψ_ξ`).
    #[test]
    fn a_turning_circle_has_the_potential_vortexs_wall_pressure() {
        struct Turning(f64);
        impl Motion for Turning {
            fn state(&self, _t: f64) -> FrameState {
                FrameState {
                    rate: self.0,
                    ..FrameState::default()
                }
            }
        }
        let (radius, rate) = (0.5, 2.0);
        let map = SectionMap::circle(radius).unwrap();
        let spec = GridSpec {
            around: 64,
            radial: 192,
            outer_radius: 10.0,
            first_cell: 0.01,
            far: None,
        };
        let mut flow = Flow::new(&map, spec, Turning(rate), 1e-3).unwrap();
        let circulation = rate * radius * radius;
        for (i, z) in flow.grid.z.iter().enumerate() {
            flow.psi[i] = -circulation * z.norm().ln();
        }
        flow.omega.fill(0.0);
        let exact = -0.5 * (rate * radius).powi(2);
        let level = flow.wall_pressure_mean();
        println!("wall pressure {level:.9}, exact {exact:.9}");
        assert!((level - exact).abs() < 1e-5 * exact.abs(), "{level}");
    }
}
