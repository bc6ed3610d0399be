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
//! formula returns of itself (below). Lagged by a step instead, the wall condition
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
//! diffusion.
//!
//! Time: the advection's first-order upwind part by the θ-method, with a
//! weight per face from its Courant number (Crank–Nicolson's ½ up to a
//! Courant number of 0.56, more implicit beyond, stable at any), and its
//! correction to the third-order values by second-order Adams–Bashforth
//! (deferred correction: `advection`); the diffusion by Crank–Nicolson
//! (backward Euler for the first few steps, whose impulsive start it
//! would keep ringing). Douglas's ADI splits the implicit operators into a
//! ring sweep and then a radial sweep, whose systems stay tridiagonal.
//! The step is thus limited by accuracy, not stability: a thin section's
//! edges crowd cells so small that the explicit scheme of before needed
//! 242,533 steps (Courant number 0.35) for four strokes of the default
//! FWAV section; [`Flow::stable_dt`] gives the step of a chosen largest
//! Courant number.
//!
//! The velocity that carries the vorticity through a step is the one of
//! the step's middle, the relative streamfunction extrapolated from the
//! step's start and the last one's (`flow/advection.rs`, as it forms the
//! corners' streamfunction; a
//! deforming grid's swept fluxes likewise). With the start's velocity,
//! as until 2026-12-03, the step was first order in the velocity's
//! change: the default FWAV section's first-stroke thrust kept falling
//! as the step was refined (CT 0.0791, 0.0785, 0.0777, 0.0767, 0.0749
//! at Courant numbers 1.5, 1, 0.75, 0.5, 0.25 on 384 × 160) where it now
//! settles (0.0753, 0.0739, 0.0733, 0.0729, 0.0727, 0.0728, 0.0727 at 6,
//! 4, 3, 2, 1.5, 0.5, 0.25: second order).
//! Ruled out first: the θ-weighted part (below a Courant number of 0.5
//! no face is more implicit than Crank–Nicolson, and the thrust still
//! moved 2.3 % from 0.5 to 0.25) and the wall pressure's flux (the
//! one-sided and the first cell's estimates moved by the same 0.0025
//! from 1.5 to 0.5). The extrapolated velocity is the step's only
//! change: it costs two `O(N)` passes and lets the default step double
//! (Courant number 3; `fwav::aero2d::viscous::ViscousSection`).
//!
//! The wall vorticity enters the step in the radial sweep, the last one,
//! through the radial diffusion (no advective flux crosses the wall's
//! face, and the normal velocity vanishes at the wall): the wall's
//! influence matrix of the radial diffusion alone (constant for a given
//! step) corrects a first pass with the current wall vorticity, and a
//! second radial sweep takes the correction. What the radial advection
//! near the wall adds is left out ([`Flow::wall_residual`]: 1e-5 to 1e-6
//! of the wall vorticity on the impulsively started cylinder past its
//! first steps).
//!
//! Forces: the wall pressure from the momentum equation along the no-slip
//! wall, `∂p/∂s = -a_wall·s + ν ∂ω/∂n` (the flux `∂ω/∂n` compact, from
//! the vorticity equation at the wall: `Flow::wall_vorticity_flux`),
//! integrated round the section (its
//! trip round is not exactly zero; the mismatch is spread linearly and
//! reported as [`WallLoads::closure`]), and the friction `ν (ω - 2Ω)`.

mod advection;
mod deforming;
mod loads;
mod pressure_level;
mod regrid;
mod sweeps;
mod wall_influence;

pub use loads::WallLoads;

use rayon::prelude::*;

use crate::error::NsError;
use crate::grid::{GridSpec, OGrid};
use crate::motion::{FrameState, Motion};
use crate::section_map::SectionMap;
use crate::stream::StreamSolver;
use wall_influence::WallInfluence;

/// Steps at the start whose diffusion is backward Euler instead of
/// Crank–Nicolson: a flow started from rest has a wall vorticity that
/// jumps at the start, whose stiff near-wall modes Crank–Nicolson keeps
/// ringing (each step's drag of the impulsively started cylinder at Re
/// 550 alternated in sign, ±14,000 at the first step, ±2,000 after 25
/// steps of 0.004 D/U, and into the compared window at 0.008); a few
/// implicit Euler steps damp them (Rannacher 1984, *Numer. Math.* 43).
const DAMPED_START_STEPS: usize = 4;

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
    /// Work arrays: the rigid streamfunction at the nodes, the explicit
    /// rate of the first sweep.
    frame_psi: Vec<f64>,
    rate: Vec<f64>,
    /// The first sweep's explicit rate but the correction, the radial
    /// sweep's implicit operator applied to the step's start, and the
    /// `θ q` of the radial and ring faces ([`advection`]).
    explicit: Vec<f64>,
    radial_old: Vec<f64>,
    radial_speed: Vec<f64>,
    ring_speed: Vec<f64>,
    wall_shape: Vec<f64>,
    wall_slope: Vec<f64>,
    wall_curvature: Vec<f64>,
    outer: Vec<f64>,
    /// The outer ring's vorticity at the step's start, two wall rings (the
    /// wall vorticity and its mismatch), and the wall's factored influence
    /// matrix of the current time step.
    start_outer: Vec<f64>,
    wall_scratch: Vec<f64>,
    residual_scratch: Vec<f64>,
    /// The first pass's outer ring, kept for the second.
    outer_ring: Vec<f64>,
    influences: Vec<WallInfluence>,
    /// The streamfunction solver's responses at the wall's rings to a
    /// unit source on each ring (`Self::wall_influence`), once computed.
    stream_responses: Option<Vec<f64>>,
    /// The section's area (for its own circulation `2ΩA`) and the
    /// circulation carried out through the far boundary so far.
    area: f64,
    exited: f64,
    /// The circulation advected out through the outer face per unit time
    /// by the correction (this step's and the previous one's, for
    /// Adams–Bashforth) and by the explicit part of the first-order flux;
    /// the step's radial faces.
    outflow_rate: f64,
    previous_outflow: f64,
    outflow_explicit: f64,
    radial_faces: advection::RadialFaces,
    /// How far the last step's wall vorticity was from the one Thom's
    /// formula gives back for it, relative to its largest value.
    wall_residual: f64,
    /// The width in `ξ` of each ring's cell (trapezoid: half the distance
    /// between its neighbours; the wall's and the outer ring's half cells).
    widths: Vec<f64>,
    /// `1/(w_j Δθ)` per ring (the cell areas are `J` times its inverse).
    inv_cell: Vec<f64>,
    /// A deforming section's grid (`flow/deforming.rs`); `None`: rigid.
    deforming: Option<deforming::DeformingGrid>,
    frame: FrameState,
    /// The time of `frame` and `frame_psi`.
    frame_time: Option<f64>,
    /// The relative streamfunction `ψ - ψ_frame` at the current step's
    /// start (written by the advection, which carries the vorticity by
    /// its extrapolation to the step's middle) and at the last one's
    /// (swapped after the advection).
    relative_start: Vec<f64>,
    previous_relative: Vec<f64>,
    /// The explicit rate of the previous step (Adams–Bashforth) and its
    /// time step; the diffusion's implicit weight of the current step.
    previous_rate: Vec<f64>,
    last_dt: f64,
    /// The wall vorticity at the last step's start (its time derivative
    /// enters the wall pressure, `loads.rs`).
    previous_wall: Vec<f64>,
    diffusion_weight: f64,
    /// The radial Thomas sweeps' modified upper diagonal and right-hand
    /// side (all lines), and how each eliminated row depends on the one
    /// below (ring 1's: on the wall).
    sweep_upper: Vec<f64>,
    sweep_rhs: Vec<f64>,
    sweep_gain: Vec<f64>,
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
        let widths: Vec<f64> = (0..nr)
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
        let inv_cell: Vec<f64> = widths.iter().map(|w| 1.0 / (w * grid.d_theta)).collect();
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
            rate: vec![0.0; n],
            explicit: vec![0.0; n],
            radial_old: vec![0.0; n],
            radial_speed: vec![0.0; n],
            ring_speed: vec![0.0; n],
            start_outer: vec![0.0; nt],
            wall_scratch: vec![0.0; nt],
            residual_scratch: vec![0.0; nt],
            outer_ring: vec![0.0; nt],
            influences: Vec::new(),
            stream_responses: None,
            area: map.area(),
            exited: 0.0,
            outflow_rate: 0.0,
            previous_outflow: 0.0,
            outflow_explicit: 0.0,
            radial_faces: advection::RadialFaces::new(nt, nr),
            wall_residual: 0.0,
            widths,
            inv_cell,
            deforming: None,
            relative_start: vec![0.0; n],
            previous_relative: vec![0.0; n],
            previous_rate: vec![0.0; n],
            last_dt: 0.0,
            previous_wall: vec![0.0; nt],
            diffusion_weight: 0.5,
            sweep_upper: vec![0.0; n],
            sweep_rhs: vec![0.0; n],
            sweep_gain: vec![0.0; n],
            wall_shape: vec![0.0; nt],
            wall_slope: vec![0.0; nt],
            wall_curvature: vec![0.0; nt],
            outer: vec![0.0; nt],
            frame,
            frame_time: None,
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
        self.solve_stream(t, false, Extent::All);
        let mut wall = std::mem::take(&mut self.wall_scratch);
        self.thom(false, &mut wall);
        self.omega[..self.grid.nt].copy_from_slice(&wall);
        self.wall_scratch = wall;
    }

    /// The streamfunction of the current vorticity: with the wall's and
    /// far field's conditions at time `t` (and the frame state of `t`
    /// left), or with homogeneous ones (`homogeneous`, for the wall's
    /// influence matrix); at every node, or (`Extent::Wall`) at the
    /// wall's two rings only, which are all that Thom's formula reads
    /// (the rest of `psi` is left as it was).
    fn solve_stream(&mut self, t: f64, homogeneous: bool, extent: Extent) {
        let all = self.grid.nr;
        self.solve_stream_changed(t, homogeneous, extent, all);
    }

    /// [`Self::solve_stream`] when the vorticity has changed since the
    /// last solve on its first `changed` rings only, at the same time and
    /// on the same grid (the step's second solve: [`Self::step`]).
    fn solve_stream_changed(&mut self, t: f64, homogeneous: bool, extent: Extent, changed: usize) {
        let g = &self.grid;
        let nt = g.nt;
        if homogeneous {
            self.wall_shape.fill(0.0);
            self.wall_slope.fill(0.0);
        } else {
            // The rigid field is the time's: computed once for the two
            // solves of a step.
            if self.frame_time != Some(t) {
                self.frame = self.motion.state(t);
                let rigid = self.frame.rigid_field();
                self.frame_psi
                    .par_iter_mut()
                    .zip(g.z.par_iter())
                    .for_each(|(p, z)| *p = rigid.streamfunction(*z));
                self.frame_time = Some(t);
            }
            let frame = self.frame;
            for k in 0..nt {
                self.wall_shape[k] = self.frame_psi[k];
                let grad = frame.streamfunction_gradient(g.z[k]);
                self.wall_slope[k] = (grad.conj() * g.dz_dxi[k]).re;
            }
            // A deforming wall's own normal flux and tangential velocity.
            if let Some(d) = &self.deforming {
                for k in 0..nt {
                    self.wall_shape[k] += d.wall_psi[k];
                    self.wall_slope[k] += d.wall_slope[k];
                }
            }
        }
        // Far away the fluid is at rest: ψ = 0.
        self.outer.fill(0.0);
        let slope_mean = self.wall_slope.iter().sum::<f64>() / nt as f64;
        self.stream.solve_vorticity(
            &g.jac,
            &self.omega,
            &self.wall_shape,
            slope_mean,
            &self.outer,
            &mut self.psi,
            match extent {
                Extent::All => g.nr,
                Extent::Wall => 2,
            },
            changed,
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
            // ψr_θ > 0 means outward relative flow (U^ξ = ψr_θ / J), ψr
            // the step start's (`previous_relative` since the advection's
            // rates: relative to the frame and to a deforming grid's
            // rigid part, the part that reaches the outer ring).
            let rel = |kk: usize| self.previous_relative[j * nt + kk];
            let outward = rel(kp) - rel(km) > 0.0;
            self.omega[j * nt + k] = if outward {
                self.omega[(j - 1) * nt + k]
            } else {
                0.0
            };
        }
    }

    /// The time step at which the current flow's largest advective Courant
    /// number (of a node, both directions summed) is `courant`. Any is
    /// stable (module docs); the larger, the more of the advection near
    /// the section is first order in time. Cost `O(N)`.
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
                let rel = |n: usize| self.relative_at(n).0;
                let jac = g.jac[i];
                // Less the grid's own motion where the section deforms
                // (its rigid part is in `rel`).
                let swept = self.relative_at(i).1;
                let psi_t = (rel(j * nt + kp) - rel(j * nt + km)) / (2.0 * dt) - swept.re;
                let psi_e = (rel(i + nt) - rel(i - nt)) / (2.0 * de) + swept.im * gp;
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

    /// Advance one step of `dt` (module docs): the advection, by the
    /// velocity of the step's middle (extrapolated from the last two
    /// steps' starts), its first-order part by the θ-method with per-face
    /// weights and its third-order correction by second-order
    /// Adams–Bashforth (Euler on the first step; its variable-step form
    /// after a change of `dt`), Crank–Nicolson
    /// diffusion, split by Douglas's ADI into radial and ring sweeps, and
    /// the wall vorticity implicit: the one that Thom's formula gives back
    /// for the step's own streamfunction. The wall's influence matrix of
    /// the diffusion alone (built once for each `dt` used, kept for the
    /// eight latest) corrects the current
    /// wall vorticity once; the advection's share in the wall cells is
    /// what is left ([`Self::wall_residual`]). Two implicit sweeps and two
    /// streamfunction solves (the first needs the wall's rings only).
    ///
    /// The step runs on a worker of rayon's pool (in place when called
    /// from one): its parallel regions are then joins among the pool's
    /// threads. Called from an outside thread, each region was handed to
    /// the pool while the caller slept until a worker woke it: the default
    /// FWAV section's four strokes took 40.1 s instead of 34.4 s. Called
    /// from outside, the pool's other workers are also kept awake through
    /// the step (`awake_pool.rs`: about 5–9 % sooner on two cores).
    ///
    /// # Errors
    /// [`NsError::Diverged`] when the flow is no longer finite.
    pub fn step(&mut self, dt: f64) -> Result<(), NsError>
    where
        M: Send,
    {
        crate::awake_pool::on_awake_pool(|| self.step_in_pool(dt))
    }

    /// [`Self::step`], on the calling thread.
    fn step_in_pool(&mut self, dt: f64) -> Result<(), NsError> {
        let nt = self.grid.nt;
        self.diffusion_weight = if self.steps < DAMPED_START_STEPS {
            1.0
        } else {
            0.5
        };
        let influence = self.influence_for(dt)?;
        self.previous_wall.copy_from_slice(&self.omega[..nt]);
        // Adams–Bashforth of variable step (`r` the ratio of this step to
        // the last); Euler at the start.
        let (now, before) = if self.steps == 0 {
            (1.0, 0.0)
        } else {
            let r = dt / self.last_dt;
            (1.0 + 0.5 * r, -0.5 * r)
        };
        self.advection_rates(dt, now, before);
        let explicit_outflow =
            now * self.outflow_rate + before * self.previous_outflow + self.outflow_explicit;
        self.previous_outflow = self.outflow_rate;
        let t = self.time + dt;
        // The explicit part was the step start's grid; the rest is the
        // end's (`flow/deforming.rs`).
        if let Some(d) = self.deforming.as_mut() {
            d.keep_swept_as_previous();
        }
        self.move_grid(t);
        self.start_outer
            .copy_from_slice(&self.omega[(self.grid.nr - 1) * nt..]);
        self.ring_implicit(dt);
        // The step with the current wall vorticity, and Thom's of it.
        let mut wall = std::mem::take(&mut self.wall_scratch);
        wall.copy_from_slice(&self.omega[..nt]);
        self.radial_crank_nicolson(dt, &wall);
        self.outer_condition();
        let mut outer_ring = std::mem::take(&mut self.outer_ring);
        outer_ring.copy_from_slice(&self.omega[(self.grid.nr - 1) * nt..]);
        self.solve_stream(t, false, Extent::Wall);
        let mut residual = std::mem::take(&mut self.residual_scratch);
        self.wall_mismatch(&wall, &mut residual);
        self.influences[influence].solve(&mut residual);
        for (w, r) in wall.iter_mut().zip(&residual) {
            *w += r;
        }
        // The radial sweep again with the corrected wall vorticity.
        let changed = self.radial_wall_change(&residual);
        self.omega[..nt].copy_from_slice(&wall);
        let outer_start = (self.grid.nr - 1) * nt;
        self.omega[outer_start..].copy_from_slice(&outer_ring);
        self.outer_ring = outer_ring;
        self.exited += dt * (explicit_outflow + self.outer_implicit_flux());
        self.time = t;
        self.steps += 1;
        self.last_dt = dt;
        // The vorticity changed on the wall's `changed` rings only since
        // the first solve (the outer ring is back to its value then).
        self.solve_stream_changed(t, false, Extent::All, changed);
        self.wall_mismatch(&wall, &mut residual);
        let largest = wall.iter().fold(0.0_f64, |m, w| m.max(w.abs()));
        self.wall_residual =
            residual.iter().fold(0.0_f64, |m, r| m.max(r.abs())) / largest.max(f64::MIN_POSITIVE);
        self.wall_scratch = wall;
        self.residual_scratch = residual;
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

    /// How far the last step's wall vorticity was from the one Thom's
    /// formula (and Kelvin's theorem, for its mean) gives back for the
    /// step's streamfunction, relative to its largest value: zero but for
    /// the advection's share in the wall cells, which the diffusion's
    /// influence matrix leaves out.
    #[must_use]
    pub fn wall_residual(&self) -> f64 {
        self.wall_residual
    }

    /// How far `wall`, the wall ring of the current flow, is from the
    /// wall vorticity the step wants, into `out`: the variation round the
    /// wall of Thom's for the current streamfunction, less `wall`'s; and
    /// for the mean, the fluid's circulation short of Kelvin's (minus the
    /// section's own `2ΩA` and minus what has left through the far
    /// boundary), per wall node. The mean of Thom's is not used: the
    /// streamfunction's mean no-slip row already holds the section's
    /// circulation. Linear in `wall` with the matrix `-(I - M)` of
    /// [`Self::wall_influence`].
    fn wall_mismatch(&mut self, wall: &[f64], out: &mut [f64]) {
        let nt = self.grid.nt;
        self.thom(false, out);
        let own = self.deforming.as_ref().map_or(0.0, |d| d.circulation);
        let target = -2.0 * self.frame.rate * self.area - own - self.exited;
        let free = self.circulation();
        let mean = out.iter().sum::<f64>() / nt as f64;
        let wall_mean = wall.iter().sum::<f64>() / nt as f64;
        for (o, w) in out.iter_mut().zip(wall) {
            *o += (target - free) / nt as f64 - mean - (w - wall_mean);
        }
    }

    /// The fluid's circulation, `∫ ω dA` over the grid inside the outer
    /// face (trapezoidal in `ξ`, the wall ring included; the outer ring's
    /// half cell lies beyond the face the outflow is counted through).
    /// Cost `O(N)`.
    #[must_use]
    pub fn circulation(&self) -> f64 {
        let g = &self.grid;
        let (nt, nr) = (g.nt, g.nr);
        // Each ring's sum on its own thread, the rings' sums added in
        // order: the same to the bit whatever the threads.
        let rings: Vec<f64> = g.jac[..(nr - 1) * nt]
            .par_chunks(nt)
            .zip(self.omega.par_chunks(nt))
            .zip(self.widths.par_iter())
            .map(|((jac, omega), width)| {
                let ring: f64 = jac.iter().zip(omega).map(|(j, w)| j * w).sum();
                width * g.d_theta * ring
            })
            .collect();
        rings.iter().sum()
    }

    /// The circulation carried out through the far boundary so far.
    #[must_use]
    pub fn exited_circulation(&self) -> f64 {
        self.exited
    }
}

/// Where a streamfunction solve is wanted ([`Flow::solve_stream`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Extent {
    /// At every node.
    All,
    /// At the wall's two rings.
    Wall,
}

/// The small flow the module's unit tests build: an ellipse (chord 1,
/// 20 % thick) in a steady stream, 64 × 48 nodes out to 20 map radii,
/// first cell 0.01 in `ξ`, at kinematic viscosity `viscosity`.
#[cfg(test)]
fn small_ellipse_flow(viscosity: f64) -> Flow<crate::motion::SteadyStream> {
    ellipse_flow(0.1, 64, 48, viscosity)
}

/// An ellipse of chord 1 and semi-axis `semi_y` across it in a steady
/// stream, on `around` × `radial` nodes as [`small_ellipse_flow`]'s.
#[cfg(test)]
fn ellipse_flow(
    semi_y: f64,
    around: usize,
    radial: usize,
    viscosity: f64,
) -> Flow<crate::motion::SteadyStream> {
    let map = SectionMap::ellipse(0.5, semi_y, (0.0, 0.0)).unwrap();
    let spec = GridSpec {
        around,
        radial,
        outer_radius: 20.0,
        first_cell: 0.01,
        far: None,
    };
    let stream = crate::motion::SteadyStream {
        speed: 1.0,
        kick_rate: 0.0,
        kick_period: 1.0,
    };
    Flow::new(&map, spec, stream, viscosity).unwrap()
}
