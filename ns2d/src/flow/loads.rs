//! The wall's loads: pressure from the momentum equation along the
//! no-slip wall, friction, and their resultants (module docs of
//! [`crate::Flow`]).

use realfft::num_complex::Complex64;

use super::Flow;
use crate::motion::Motion;

/// Pressure and friction on the wall and their resultants at one instant
/// (fluid density 1; body axes for the distributions, fixed axes for the
/// resultants).
#[derive(Debug, Clone, PartialEq)]
pub struct WallLoads {
    /// Time.
    pub time: f64,
    /// Force on the section by the fluid, fixed axes (`Fx + i Fy`).
    pub force: Complex64,
    /// Moment about the frame origin, counter-clockwise positive.
    pub moment: f64,
    /// Power the section gives the fluid, `-∮ f·u_wall ds`, with `u_wall`
    /// the wall's velocity relative to the far fluid: the frame's whole
    /// motion, its steady translation included (a body towed at rest in
    /// its frame gives the fluid its drag times the speed).
    pub power: f64,
    /// Wall pressure round the section, less its mean over the nodes:
    /// add [`Flow::wall_pressure_mean`] for the pressure relative to the
    /// far fluid's.
    pub pressure: Vec<f64>,
    /// The pressure jump a trip round the wall gave before it was spread
    /// (zero for the exact solution: a measure of the discrete no-slip
    /// condition's consistency).
    pub closure: f64,
    /// Wall vorticity relative to the section's rotation, `ω - 2Ω` (and,
    /// for a deforming wall, `+ 2 n·∂w/∂s`: `flow/deforming.rs`); the
    /// skin friction is `ν` times it, along the counter-clockwise tangent.
    pub wall_vorticity: Vec<f64>,
}

impl<M: Motion> Flow<M> {
    /// Wall pressure, friction and their resultants at the current time.
    #[must_use]
    pub fn loads(&self) -> WallLoads {
        let g = &self.grid;
        let nt = g.nt;
        let frame = self.frame;
        let nu = self.viscosity;
        let i = Complex64::new(0.0, 1.0);
        // dp/dθ = ν ω_ξ - a_wall · z_θ (the momentum equation at the
        // no-slip wall, along it).
        let deformation: Vec<_> = (0..nt).map(|k| self.wall_deformation(k)).collect();
        let flux = self.wall_vorticity_flux();
        let mut dp = vec![0.0; nt];
        for (k, d) in dp.iter_mut().enumerate() {
            let z_theta = i * g.dz_dxi[k];
            let accel = frame.point_acceleration(g.z[k]) + deformation[k].0;
            *d = nu * flux[k] - (accel.conj() * z_theta).re;
        }
        // Integrate round the wall (trapezoid); spread the closure error.
        let mut pressure = vec![0.0; nt];
        for k in 1..nt {
            pressure[k] = pressure[k - 1] + 0.5 * (dp[k - 1] + dp[k]) * g.d_theta;
        }
        let closure = pressure[nt - 1] + 0.5 * (dp[nt - 1] + dp[0]) * g.d_theta;
        for (k, p) in pressure.iter_mut().enumerate() {
            *p -= closure * k as f64 / nt as f64;
        }
        let mean = pressure.iter().sum::<f64>() / nt as f64;
        for p in &mut pressure {
            *p -= mean;
        }
        let wall_vorticity: Vec<f64> = (0..nt)
            .map(|k| self.omega[k] - 2.0 * frame.rate + deformation[k].2)
            .collect();
        let mut force = Complex64::new(0.0, 0.0);
        let mut moment = 0.0;
        let mut power = 0.0;
        for k in 0..nt {
            let z_theta = i * g.dz_dxi[k];
            let f = (i * pressure[k] + nu * wall_vorticity[k]) * z_theta * g.d_theta;
            force += f;
            moment += (g.z[k].conj() * f).im;
            let velocity = frame.point_velocity(g.z[k]) + deformation[k].1;
            power -= (f.conj() * velocity).re;
        }
        WallLoads {
            time: self.time,
            force: force * Complex64::from_polar(1.0, frame.angle),
            moment,
            power,
            pressure,
            closure,
            wall_vorticity,
        }
    }

    /// The wall's vorticity flux `∂ω/∂ξ` at each wall node, compact
    /// (second order in the first cell `h = ξ_1 - ξ_0`): the first cell's
    /// difference less half a cell of the curvature `ω_ξξ`, which the
    /// vorticity equation gives at the wall, where the fluid moves with
    /// it and only diffusion is left: `J ω_t = ν (ω_ξξ + ω_θθ)`, so
    ///
    /// `ω_ξ(0) = (ω_1 - ω_0)/h - (h/2)(J ω_t/ν - ω_θθ)`,
    ///
    /// with `ω_t` the wall vorticity's change over the last step (zero
    /// before the first) and `ω_θθ` central round the wall.
    ///
    /// Why not the one-sided `(-3ω_0 + 4ω_1 - ω_2)/2Δη`: it reads the
    /// curvature from rings 1 and 2, where a wall layer a few cells thick
    /// is not yet parabolic, and the default FWAV section's thrust moved
    /// 6 % when the first cell was halved; with this estimate 2.0 %
    /// (`ns2d/README.md`, "The wall's first cell"). Cost: `O(N_θ)`.
    fn wall_vorticity_flux(&self) -> Vec<f64> {
        let g = &self.grid;
        let nt = g.nt;
        let w = &self.omega;
        let h = g.xi[1] - g.xi[0];
        let rate_scale = if self.steps == 0 {
            0.0
        } else {
            1.0 / self.last_dt
        };
        let inv_dtheta2 = 1.0 / (g.d_theta * g.d_theta);
        (0..nt)
            .map(|k| {
                let (before, after) = (w[(k + nt - 1) % nt], w[(k + 1) % nt]);
                let w_thetatheta = (before - 2.0 * w[k] + after) * inv_dtheta2;
                let w_t = (w[k] - self.previous_wall[k]) * rate_scale;
                let w_xixi = g.jac[k] * w_t / self.viscosity - w_thetatheta;
                (w[nt + k] - w[k]) / h - 0.5 * h * w_xixi
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use crate::flow::small_ellipse_flow;

    /// The compact flux is exact for a wall layer parabolic in `ξ` whose
    /// curvature the vorticity equation at the wall gives: `ω = a_k + b_k
    /// (ξ - ξ_0) + c_k (ξ - ξ_0)²` round an ellipse, with `J ω_t / ν =
    /// 2 c_k + ω_θθ` over the last step, has `ω_ξ(0) = b_k` (to
    /// rounding), where the one-sided difference it replaced is not exact
    /// on the stretched grid's unequal rings (`ξ_2 - ξ_1 ≠ ξ_1 - ξ_0`).
    /// Measured: 8.5e-14 off, against 1.3 (of `b_k` about 40) one-sided.
    #[test]
    fn the_compact_wall_flux_is_exact_for_a_parabolic_layer() {
        let viscosity = 1.0 / 500.0;
        let mut flow = small_ellipse_flow(viscosity);
        let (nt, dt) = (flow.grid.nt, 1e-3);
        let theta = |k: usize| k as f64 * flow.grid.d_theta;
        let a = |k: usize| 3.0 + (2.0 * theta(k)).cos();
        let b = |k: usize| -40.0 + 7.0 * theta(k).sin();
        let c = |k: usize| 900.0 + 50.0 * (3.0 * theta(k)).cos();
        let xi0 = flow.grid.xi[0];
        for j in 0..flow.grid.nr {
            let x = flow.grid.xi[j] - xi0;
            for k in 0..nt {
                flow.omega[j * nt + k] = a(k) + b(k) * x + c(k) * x * x;
            }
        }
        let inv_dtheta2 = 1.0 / (flow.grid.d_theta * flow.grid.d_theta);
        for k in 0..nt {
            let around = (a((k + nt - 1) % nt) - 2.0 * a(k) + a((k + 1) % nt)) * inv_dtheta2;
            let rate = viscosity * (2.0 * c(k) + around) / flow.grid.jac[k];
            flow.previous_wall[k] = a(k) - dt * rate;
        }
        flow.steps = 1;
        flow.last_dt = dt;
        let flux = flow.wall_vorticity_flux();
        let worst = (0..nt)
            .map(|k| (flux[k] - b(k)).abs())
            .fold(0.0_f64, f64::max);
        assert!(worst < 1e-8, "worst {worst:e}");
        let w = &flow.omega;
        let one_sided = (0..nt)
            .map(|k| {
                let w_eta =
                    (-3.0 * w[k] + 4.0 * w[nt + k] - w[2 * nt + k]) / (2.0 * flow.grid.d_eta);
                (w_eta / flow.grid.slope[0] - b(k)).abs()
            })
            .fold(0.0_f64, f64::max);
        println!("compact: worst {worst:.1e}; one-sided: {one_sided:.1e} (of b about 40)");
        assert!(
            one_sided > 1e3 * worst.max(1e-12),
            "one-sided {one_sided:e}"
        );
    }
}
