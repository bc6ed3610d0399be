//! The vorticity–streamfunction time stepper.
//!
//! In the body frame on the conformal grid of [`crate::OGrid`] the absolute
//! vorticity obeys
//!
//! ```text
//! ∂ω/∂t + (1/J)(ψr_θ ω_ξ - ψr_ξ ω_θ) = (ν/J)(ω_ξξ + ω_θθ),   ψ_ξξ + ψ_θθ = -J ω
//! ```
//!
//! where `ψ` is the streamfunction of the absolute velocity and
//! `ψr = ψ - ψ_frame` that of the velocity relative to the moving grid
//! (the rigid motion has a streamfunction, [`crate::FrameState`]). The
//! wall condition is no-slip: `ψ` equals the wall's streamfunction, and
//! the wall vorticity is Thom's,
//! `ω_0 = -(2(ψ_1 - ψ_0 - ξ_1 ψ_ξ,wall)/ξ_1² + ψ_θθ)/J` (Roache, *Fundamentals of Computational Fluid Dynamics*,
//! 1998, §3.3; second-order accurate in the flow, Huang & Wetton 1996),
//! satisfied implicitly at the end of each step: the step is linear in
//! the wall vorticity, so the wall's influence matrix (one column per wall
//! node, LU once per time step) gives the wall vorticity that Thom's
//! formula returns of itself. Lagged by a step instead, the wall condition
//! limited the wall cell's diffusion number to about 0.5 (7e-6 c/U at the
//! tips of Wang's 12% ellipse). The mean of the wall vorticity is not
//! Thom's (the streamfunction's mean no-slip row already holds the
//! section's circulation) but Kelvin's theorem: the fluid's circulation
//! is minus the section's own (`2ΩA`) and minus what the flow has carried
//! out through the far boundary (the advective flux through the face
//! between the last two rings). Far away `ψ = 0`, and the vorticity is
//! zero where the flow enters and extrapolated where it leaves.
//!
//! Space: the advection in conservative form,
//! `J ∂ω/∂t = -∂ξ(ψr_θ ω) + ∂θ(ψr_ξ ω) + …`, by finite volumes round the
//! nodes: the flux through a cell face is the difference of `ψr` at its
//! two corners (so the fluxes round a cell sum to zero exactly and none
//! crosses the wall) times the third-order upwind-biased face value
//! `(-ω_{-1} + 5ω_0 + 2ω_1)/6` (the flux form of the fourth-order central
//! difference with a fourth-difference dissipation of weight `|U|/12`, as
//! in Kawamura & Kuwahara 1984). Advection then changes the fluid's
//! circulation only by what crosses the outer face, which is what Kelvin's
//! bookkeeping counts as exited: in the advective form it did not, and
//! the wall made up the difference (the pressure's trip round the wall,
//! [`WallLoads::closure`], was 3–5% of the pressure range on Wang's
//! hovering ellipse; 0.1% now). Second-order central differences for
//! diffusion; time:
//! second-order Adams–Bashforth for the advection, Crank–Nicolson for the
//! diffusion split by Douglas's ADI into a radial and a ring sweep, so
//! the step is limited by the advective Courant number only
//! ([`Flow::stable_dt`]).
//!
//! Forces: the wall pressure from the momentum equation along the no-slip
//! wall, `∂p/∂s = -a_wall·s + ν ∂ω/∂n`, integrated round the section (its
//! trip round is not exactly zero; the mismatch is spread linearly and
//! reported as [`WallLoads::closure`]), and the friction `ν (ω - 2Ω)`.

mod loads;
mod sweeps;

pub use loads::WallLoads;

use crate::error::NsError;
use crate::grid::{GridSpec, OGrid};
use crate::motion::{FrameState, Motion};
use crate::section_map::SectionMap;
use crate::stream::StreamSolver;

/// The flow round one moving section (module docs).
pub struct Flow<M: Motion> {
    grid: OGrid,
    motion: M,
    viscosity: f64,
    time: f64,
    steps: usize,
    omega: Vec<f64>,
    psi: Vec<f64>,
    stream: StreamSolver,
    /// Work arrays: the rigid streamfunction at the nodes, the source
    /// `J ω`, the explicit rate.
    frame_psi: Vec<f64>,
    source: Vec<f64>,
    rate: Vec<f64>,
    relative: Vec<f64>,
    theta_diffusion: Vec<f64>,
    wall_shape: Vec<f64>,
    wall_slope: Vec<f64>,
    wall_curvature: Vec<f64>,
    outer: Vec<f64>,
    /// The vorticity at the step's start, a wall ring, and the wall's
    /// factored influence matrix of the current time step.
    start: Vec<f64>,
    wall_scratch: Vec<f64>,
    /// A ring of zeros (the first pass's wall) and the first pass's outer
    /// ring, kept for the second.
    zero_ring: Vec<f64>,
    outer_ring: Vec<f64>,
    influence: Option<WallInfluence>,
    /// The section's area (for its own circulation `2ΩA`) and the
    /// circulation carried out through the far boundary so far.
    area: f64,
    exited: f64,
    /// The circulation advected out through the outer face per unit time
    /// (this step's and the previous one's, for Adams–Bashforth), and the
    /// outer face's corners and fluxes.
    outflow_rate: f64,
    previous_outflow: f64,
    outer_corners: Vec<f64>,
    outer_fluxes: Vec<f64>,
    /// The width in `ξ` of each ring's cell (trapezoid: half the distance
    /// between its neighbours; the wall's and the outer ring's half cells).
    widths: Vec<f64>,
    frame: FrameState,
    /// The explicit rate of the previous step (Adams–Bashforth) and its
    /// time step.
    previous_rate: Vec<f64>,
    last_dt: f64,
    /// The radial Thomas sweeps' modified upper diagonal and right-hand
    /// side (all lines), and the ring the sweep has just replaced.
    sweep_upper: Vec<f64>,
    sweep_rhs: Vec<f64>,
    previous_ring: Vec<f64>,
}

impl<M: Motion> std::fmt::Debug for Flow<M> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Flow")
            .field("time", &self.time)
            .field("steps", &self.steps)
            .finish_non_exhaustive()
    }
}

impl<M: Motion> Flow<M> {
    /// A flow at rest round the section of `map` moving by `motion`, with
    /// kinematic viscosity `viscosity` (`1/Re` in units of the reference
    /// length and speed).
    ///
    /// # Errors
    /// The grid's errors; [`NsError::BadReynolds`] for a viscosity that is
    /// not positive.
    pub fn new(
        map: &SectionMap,
        spec: GridSpec,
        motion: M,
        viscosity: f64,
    ) -> Result<Self, NsError> {
        if !(viscosity.is_finite() && viscosity > 0.0) {
            return Err(NsError::BadReynolds(1.0 / viscosity));
        }
        let grid = OGrid::new(map, spec)?;
        let stream = StreamSolver::new(&grid);
        let (n, nt, nr) = (grid.len(), grid.nt, grid.nr);
        let frame = motion.state(0.0);
        let widths = (0..nr)
            .map(|j| {
                let below = if j == 0 { grid.xi[0] } else { grid.xi[j - 1] };
                let above = if j + 1 == nr {
                    grid.xi[j]
                } else {
                    grid.xi[j + 1]
                };
                0.5 * (above - below)
            })
            .collect();
        let mut flow = Self {
            grid,
            motion,
            viscosity,
            time: 0.0,
            steps: 0,
            omega: vec![0.0; n],
            psi: vec![0.0; n],
            stream,
            frame_psi: vec![0.0; n],
            source: vec![0.0; n],
            rate: vec![0.0; n],
            relative: vec![0.0; n],
            theta_diffusion: vec![0.0; n],
            start: vec![0.0; n],
            wall_scratch: vec![0.0; nt],
            zero_ring: vec![0.0; nt],
            outer_ring: vec![0.0; nt],
            influence: None,
            area: map.area(),
            exited: 0.0,
            outflow_rate: 0.0,
            previous_outflow: 0.0,
            outer_corners: vec![0.0; nt],
            outer_fluxes: vec![0.0; nt],
            widths,
            previous_rate: vec![0.0; n],
            last_dt: 0.0,
            sweep_upper: vec![0.0; n],
            sweep_rhs: vec![0.0; n],
            previous_ring: vec![0.0; nt],
            wall_shape: vec![0.0; nt],
            wall_slope: vec![0.0; nt],
            wall_curvature: vec![0.0; nt],
            outer: vec![0.0; nt],
            frame,
        };
        flow.evaluate(0.0);
        Ok(flow)
    }

    /// The grid.
    #[must_use]
    pub fn grid(&self) -> &OGrid {
        &self.grid
    }

    /// The time reached.
    #[must_use]
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The vorticity at the nodes (row-major, radial index outer).
    #[must_use]
    pub fn vorticity(&self) -> &[f64] {
        &self.omega
    }

    /// The streamfunction at the nodes.
    #[must_use]
    pub fn streamfunction(&self) -> &[f64] {
        &self.psi
    }

    /// Solve the streamfunction of the current vorticity at time `t`, set
    /// the wall vorticity from it (Thom's), and leave the frame state of
    /// `t`.
    fn evaluate(&mut self, t: f64) {
        self.solve_stream(t, false);
        let mut wall = std::mem::take(&mut self.wall_scratch);
        self.thom(false, &mut wall);
        self.omega[..self.grid.nt].copy_from_slice(&wall);
        self.wall_scratch = wall;
    }

    /// The streamfunction of the current vorticity: with the wall's and
    /// far field's conditions at time `t` (and the frame state of `t`
    /// left), or with homogeneous ones (`homogeneous`, for the wall's
    /// influence matrix).
    fn solve_stream(&mut self, t: f64, homogeneous: bool) {
        let g = &self.grid;
        let nt = g.nt;
        for (i, s) in self.source.iter_mut().enumerate() {
            *s = g.jac[i] * self.omega[i];
        }
        if homogeneous {
            self.wall_shape.fill(0.0);
            self.wall_slope.fill(0.0);
        } else {
            self.frame = self.motion.state(t);
            let frame = self.frame;
            let rigid = frame.rigid_field();
            for (i, z) in g.z.iter().enumerate() {
                self.frame_psi[i] = rigid.streamfunction(*z);
            }
            for k in 0..nt {
                self.wall_shape[k] = self.frame_psi[k];
                let grad = frame.streamfunction_gradient(g.z[k]);
                self.wall_slope[k] = (grad.conj() * g.dz_dxi[k]).re;
            }
        }
        // Far away the fluid is at rest: ψ = 0.
        self.outer.fill(0.0);
        let slope_mean = self.wall_slope.iter().sum::<f64>() / nt as f64;
        self.stream.solve(
            &self.source,
            &self.wall_shape,
            slope_mean,
            &self.outer,
            &mut self.psi,
        );
    }

    /// Thom's wall vorticity (module docs) of the current streamfunction
    /// into `out` (`homogeneous`: with the homogeneous wall conditions of
    /// the last [`Self::solve_stream`]).
    fn thom(&mut self, homogeneous: bool, out: &mut [f64]) {
        let g = &self.grid;
        let xi1 = g.xi[1];
        if homogeneous {
            self.wall_curvature.fill(0.0);
        } else {
            let shape = std::mem::take(&mut self.wall_shape);
            self.stream
                .ring_second_derivative(&shape, &mut self.wall_curvature);
            self.wall_shape = shape;
        }
        for (k, o) in out.iter_mut().enumerate() {
            let psi_w = self.psi[k];
            let d1 = self.psi[g.at(1, k)] - psi_w - self.wall_slope[k] * xi1;
            let psi_xixi = 2.0 * d1 / (xi1 * xi1);
            *o = -(psi_xixi + self.wall_curvature[k]) * g.inv_jac[k];
        }
    }

    /// Outer ring: zero vorticity where the relative flow enters, the
    /// neighbour's where it leaves.
    fn outer_condition(&mut self) {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        let j = nr - 1;
        for k in 0..nt {
            let kp = if k + 1 == nt { 0 } else { k + 1 };
            let km = if k == 0 { nt - 1 } else { k - 1 };
            // ψr_θ > 0 means outward relative flow (U^ξ = ψr_θ / J).
            let rel = |kk: usize| self.psi[j * nt + kk] - self.frame_psi[j * nt + kk];
            let outward = rel(kp) - rel(km) > 0.0;
            self.omega[j * nt + k] = if outward {
                self.omega[(j - 1) * nt + k]
            } else {
                0.0
            };
        }
    }

    /// The largest stable time step of the current flow: the advective
    /// Courant number `courant` (the diffusion and the wall vorticity are
    /// implicit; second-order Adams–Bashforth with third-order upwind
    /// advection is stable to a Courant number of about 0.5).
    #[must_use]
    pub fn stable_dt(&self, courant: f64) -> f64 {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        let (de, dt) = (g.d_eta, g.d_theta);
        let mut worst_adv: f64 = 0.0;
        for j in 1..nr - 1 {
            let gp = g.slope[j];
            for k in 0..nt {
                let kp = if k + 1 == nt { 0 } else { k + 1 };
                let km = if k == 0 { nt - 1 } else { k - 1 };
                let i = j * nt + k;
                let rel = |n: usize| self.psi[n] - self.frame_psi[n];
                let jac = g.jac[i];
                let psi_t = (rel(j * nt + kp) - rel(j * nt + km)) / (2.0 * dt);
                let psi_e = (rel(i + nt) - rel(i - nt)) / (2.0 * de);
                let adv = (psi_t / (jac * gp)).abs() / de + (psi_e / (gp * jac)).abs() / dt;
                worst_adv = worst_adv.max(adv);
            }
        }
        if worst_adv > 0.0 {
            courant / worst_adv
        } else {
            f64::INFINITY
        }
    }

    /// Advance one step of `dt`: second-order Adams–Bashforth advection
    /// (Euler on the first step and after a change of `dt`), Crank–Nicolson
    /// diffusion split by Douglas's ADI into radial and ring sweeps, and
    /// the wall vorticity implicit: the one that Thom's formula gives back
    /// for the step's own streamfunction, from the wall's influence matrix
    /// (built for each new `dt`). Two implicit sweeps and two
    /// streamfunction solves.
    ///
    /// # Errors
    /// [`NsError::Diverged`] when the flow is no longer finite.
    pub fn step(&mut self, dt: f64) -> Result<(), NsError> {
        let nt = self.grid.nt;
        if self.influence.as_ref().is_none_or(|w| w.dt != dt) {
            self.influence = Some(self.wall_influence(dt)?);
        }
        self.explicit_rate();
        let restart = self.steps == 0 || (dt - self.last_dt).abs() > 1e-12 * dt;
        let (now, before) = if restart { (1.0, 0.0) } else { (1.5, -0.5) };
        for (r, p) in self.rate.iter_mut().zip(self.previous_rate.iter_mut()) {
            let current = *r;
            *r = now * current + before * *p;
            *p = current;
        }
        let outflow = now * self.outflow_rate + before * self.previous_outflow;
        self.previous_outflow = self.outflow_rate;
        // Douglas's ADI: the first sweep carries the whole explicit
        // diffusion round the section, the second takes half of it back
        // implicitly.
        for (r, d) in self.rate.iter_mut().zip(&self.theta_diffusion) {
            *r += d;
        }
        let t = self.time + dt;
        // The step with a zero new wall vorticity, and Thom's of it.
        self.start.copy_from_slice(&self.omega);
        let zero = std::mem::take(&mut self.zero_ring);
        self.radial_crank_nicolson(dt, &zero);
        self.zero_ring = zero;
        self.ring_implicit(dt);
        self.omega[..nt].fill(0.0);
        self.outer_condition();
        let mut outer_ring = std::mem::take(&mut self.outer_ring);
        outer_ring.copy_from_slice(&self.omega[(self.grid.nr - 1) * nt..]);
        self.solve_stream(t, false);
        let mut wall = std::mem::take(&mut self.wall_scratch);
        self.thom(false, &mut wall);
        // The wall vorticity that Thom's formula gives back of itself,
        // (I - M) ω0 = Thom(zero wall), in all but the mean; the mean
        // keeps the fluid's circulation what Kelvin's theorem says:
        // minus the section's own (2ΩA of its rotation) and minus what
        // has left through the far boundary.
        let target = -2.0 * self.frame.rate * self.area - self.exited;
        let free = self.circulation();
        let mean = wall.iter().sum::<f64>() / nt as f64;
        for w in wall.iter_mut() {
            *w += (target - free) / nt as f64 - mean;
        }
        if let Some(influence) = &self.influence {
            influence.solve(&mut wall);
        }
        // The step again with that wall vorticity.
        self.omega.copy_from_slice(&self.start);
        self.radial_crank_nicolson(dt, &wall);
        self.ring_implicit(dt);
        self.omega[..nt].copy_from_slice(&wall);
        let outer_start = (self.grid.nr - 1) * nt;
        self.omega[outer_start..].copy_from_slice(&outer_ring);
        self.outer_ring = outer_ring;
        self.wall_scratch = wall;
        self.exited += dt * outflow;
        self.time = t;
        self.steps += 1;
        self.last_dt = dt;
        self.solve_stream(t, false);
        // Every node's vorticity reaches the wall ring through the
        // streamfunction solve: a non-finite value anywhere shows there.
        if self.omega[..nt].iter().any(|w| !w.is_finite())
            || self.psi[nt..2 * nt].iter().any(|p| !p.is_finite())
        {
            return Err(NsError::Diverged {
                time: self.time,
                step: self.steps,
                dt,
            });
        }
        Ok(())
    }

    /// The fluid's circulation, `∫ ω dA` over the grid inside the outer
    /// face (trapezoidal in `ξ`, the wall ring included; the outer ring's
    /// half cell lies beyond the face the outflow is counted through).
    /// Cost `O(N)`.
    #[must_use]
    pub fn circulation(&self) -> f64 {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        let mut total = 0.0;
        for j in 0..nr - 1 {
            let ring: f64 = (0..nt)
                .map(|k| g.jac[j * nt + k] * self.omega[j * nt + k])
                .sum();
            total += self.widths[j] * g.d_theta * ring;
        }
        total
    }

    /// The circulation carried out through the far boundary so far.
    #[must_use]
    pub fn exited_circulation(&self) -> f64 {
        self.exited
    }

    /// The wall's influence matrix for steps of `dt`: column `k` is Thom's
    /// wall vorticity of the step's response to a unit wall vorticity at
    /// node `k` (homogeneous conditions, no explicit rate); factored as
    /// `I - M`. Costs `N_θ` implicit sweeps and streamfunction solves.
    fn wall_influence(&mut self, dt: f64) -> Result<WallInfluence, NsError> {
        let nt = self.grid.nt;
        let saved = (self.omega.clone(), self.psi.clone(), self.rate.clone());
        let theta = std::mem::replace(&mut self.theta_diffusion, vec![0.0; self.grid.len()]);
        self.rate.fill(0.0);
        let mut matrix = nalgebra::DMatrix::<f64>::identity(nt, nt);
        let mut unit = vec![0.0; nt];
        let mut column = vec![0.0; nt];
        let inv_n = 1.0 / nt as f64;
        for k in 0..nt {
            unit.fill(0.0);
            unit[k] = 1.0;
            self.omega.fill(0.0);
            self.radial_crank_nicolson(dt, &unit);
            self.ring_implicit(dt);
            self.omega[..nt].copy_from_slice(&unit);
            let circulation = self.circulation();
            self.solve_stream(0.0, true);
            self.thom(true, &mut column);
            for (i, c) in column.iter().enumerate() {
                matrix[(i, k)] -= c;
            }
            // Thom's equations less their mean (the streamfunction's mean
            // no-slip row already holds it), plus Kelvin's: the step's
            // circulation (see `step`).
            let mean = (0..nt).map(|i| matrix[(i, k)]).sum::<f64>() * inv_n;
            for i in 0..nt {
                matrix[(i, k)] += circulation * inv_n - mean;
            }
        }
        let (omega, psi, rate) = saved;
        self.theta_diffusion = theta;
        self.omega = omega;
        self.psi = psi;
        self.rate = rate;
        let lu = matrix.lu();
        if !lu.is_invertible() {
            return Err(NsError::SingularWall { dt });
        }
        Ok(WallInfluence { dt, lu })
    }
}

/// The factored `I - M` of the implicit wall vorticity (see
/// `Flow::wall_influence`), for one time step.
struct WallInfluence {
    dt: f64,
    lu: nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
}

impl WallInfluence {
    /// Solve `(I - M) x = b` in place.
    fn solve(&self, b: &mut [f64]) {
        let rhs = nalgebra::DVector::from_column_slice(b);
        if let Some(x) = self.lu.solve(&rhs) {
            b.copy_from_slice(x.as_slice());
        }
    }
}
