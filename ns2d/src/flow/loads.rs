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
    /// Power the section gives the fluid, `-∮ f·u_wall ds`.
    pub power: f64,
    /// Wall pressure round the section (mean zero).
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
        let de = g.d_eta;
        let i = Complex64::new(0.0, 1.0);
        // dp/dθ = ν/g'0 ω_η - a_wall · z_θ (the momentum equation at the
        // no-slip wall, along it).
        let deformation: Vec<_> = (0..nt).map(|k| self.wall_deformation(k)).collect();
        let mut dp = vec![0.0; nt];
        for (k, d) in dp.iter_mut().enumerate() {
            let w = &self.omega;
            let w_eta = (-3.0 * w[k] + 4.0 * w[nt + k] - w[2 * nt + k]) / (2.0 * de);
            let z_theta = i * g.dz_dxi[k];
            let accel = frame.point_acceleration(g.z[k]) + deformation[k].0;
            *d = nu / g.slope[0] * w_eta - (accel.conj() * z_theta).re;
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
}
