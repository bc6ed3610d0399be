//! An unsteady 2D panel method for a thick section of arbitrary, optionally
//! time-varying shape, in the units and conventions of [`super::ldvm`]
//! (`c = U = rho = 1`, time in chords travelled, plunge `h` up, pitch
//! `alpha` nose up about [`Motion::pivot`], freestream along +x).
//!
//! Method: constant-strength source/doublet panels with the internal
//! Dirichlet condition (Katz & Plotkin, *Low-Speed Aerodynamics*, 2nd ed.,
//! 2001: section 11.4.2 for the steady 2D method, section 13.13 for its
//! time-stepping form; the Morino formulation):
//! - the perturbation potential inside the section is zero, so on the
//!   surface the doublet strength is the outer potential, `mu = phi`, and
//!   the source strength is its normal derivative,
//!   `sigma = (V_body - U_inf) . n`; at every collocation point (panel
//!   midpoints, just inside) `sum_j C_ij mu_j + sum_j B_ij sigma_j +
//!   phi_wake = 0` (module `influence` for `C`, `B`);
//! - Kutta condition: the wake's doublet at the trailing edge is the jump
//!   of the surface potential there, `mu_W = mu_upper - mu_lower` (Katz &
//!   Plotkin section 11.4.2), each side extrapolated linearly to the edge
//!   from its two panels nearest it; `mu_W` is the bound circulation
//!   (clockwise);
//! - wake: a doublet panel of strength `mu_W` from the trailing edge (the
//!   middle of a blunt edge's base) to the point `E` where this
//!   step's vortex is shed, then the free vortices as a chain of doublet
//!   segments (a doublet panel of strength `mu` is a vortex pair `-mu`,
//!   `+mu` at its ends), so the shed vortex is `Gamma = mu_W - sum Gamma_old`
//!   and Kelvin's theorem holds to round-off. `E` lies a third of the way
//!   from the trailing edge to the last shed vortex (Ramesh et al. 2014),
//!   the first one half a step down the trailing-edge bisector. (The
//!   LDVM, whose newest wake element is a point vortex where this one is
//!   a panel reaching the edge, places it otherwise: [`super::ldvm`], "The
//!   wake next to the edge". This wake's loads converge at first order:
//!   NACA 0006 in Garrick's plunge at k = 1, h = 0.01 c, 160 panels, CT
//!   +1.76 %, +1.00 %, +0.49 % and CP +2.98 %, +1.71 %, +0.84 % against
//!   his at dt 0.015, 0.0075, 0.00375, 2026-12-07, a scratch run.) The influence matrix `C` is constant in the body frame
//!   (factored once, dense LU from `faer`, re-factored each step only for a
//!   [`ShapeHistory`]); the wake panel's changing column enters by
//!   Sherman–Morrison;
//! - free vortices with a Vatistas (n = 2) core of radius `1.3 U dt`
//!   (`ldvm::induced`), convected by forward Euler with the local
//!   velocity (freestream, source panels, the doublet panels as vortices at
//!   the vertices, the wake); beyond [`PanelSettings::far_wake`] chords
//!   behind the trailing edge they drift with the freestream and induce as
//!   groups of eight, as in [`super::ldvm`]. Their potential on the section
//!   (the doublet sheet's, with its cut along the wake) is summed exactly
//!   close to it and by local (Taylor) expansions farther away (module
//!   `expansion`), and the section's velocity on the wake by a multipole
//!   expansion beyond twice its radius, so a step costs about
//!   `O(N^2 + N N_near + N_w)` for `N` panels and `N_w` free vortices;
//! - loads from the unsteady Bernoulli equation in the body frame (Katz &
//!   Plotkin section 13.13):
//!   `Cp = |U_inf - V_body|^2 - |v_rel|^2 - 2 d(phi)/dt|_body`, with the
//!   relative surface velocity tangential,
//!   `v_rel = d(mu)/ds + (U_inf - V_body) . t` (three-point differences of
//!   `mu` along the surface, one-sided at the trailing edge) and
//!   `d(phi)/dt = d(mu)/dt` at the moving collocation point (backward
//!   difference, so loads are reported at the half step with the
//!   quasi-steady part averaged, like [`super::ldvm`]). Force
//!   `-sum Cp n L`; lift `CL` up, thrust `CT = -Cx`; input power
//!   `CP = sum Cp (V_surface . n) L`, which for rigid motion is
//!   `-(F_y h' + M_pivot alpha')` and for a [`ShapeHistory`] adds the
//!   deformation power (the work of the surface's own motion against the
//!   pressure).
//!
//! [`History::cl_impulse`] is the lift from the rate of the vertical
//! impulse of all the vorticity (Wu 1981, AIAA J. 19, 432: the wake, plus
//! the surface sheet `-u . t` that brings the flow inside the section to
//! rest), an independent check of the pressure integral.
//! [`History::lesp`] and [`History::cd_friction`] stay empty (the
//! leading-edge suction is in the pressure of a thick section).
//!
//! Validation (`tests/aero2d_panel.rs`): exact Kármán–Trefftz flow (lift
//! -0.8%, surface pressure within 0.015 at 160 panels), the NACA 0012
//! potential lift slope, Wagner, Garrick, Kelvin, pressure against impulse
//! lift, a rotating shape history against pitch.

mod expansion;
mod influence;
mod shape;
mod wake;

use std::f64::consts::PI;

pub use shape::{SectionShape, ShapeError, ShapeHistory};

use super::ldvm::{FreeVortex, History, Motion};
use super::motion::SectionFlapping;
use expansion::{chain_potential, clusters};
use influence::{doublet_potential, Matrices, Outline};
use shape::V2;
use wake::BodyField;

/// Panels of the default resolution: 160, where the NACA 0012 lift slope
/// is within 0.6% of its converged value and the Kármán–Trefftz lift of
/// the tests within 0.8% of exact; one 4-cycle plunge run at k = 1 and the
/// default time step takes about 0.15 s.
pub const DEFAULT_PANELS: usize = 160;

/// Clusters of collocation points for the wake potential's expansion.
const CLUSTERS: usize = 3;

/// Numerical settings of the unsteady run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PanelSettings {
    /// Time step, chords travelled (`U dt / c`).
    pub dt: f64,
    /// Simulated time, chords travelled.
    pub duration: f64,
    /// Free vortices farther than this downstream of the trailing edge,
    /// chords, drift with the freestream (as in [`super::ldvm::Settings`]).
    pub far_wake: f64,
}

impl Default for PanelSettings {
    fn default() -> Self {
        Self {
            dt: 0.015,
            duration: 10.0,
            far_wake: 1.5,
        }
    }
}

/// Why a panel solver cannot be built.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum PanelError {
    /// The section's contour is invalid.
    #[error("section: {0}")]
    Shape(#[from] ShapeError),
    /// The shape history does not fit the section.
    #[error("the shape history has {history} vertices per sample but the section has {section}")]
    HistoryMismatch {
        /// Vertices of the section.
        section: usize,
        /// Vertices of each history sample.
        history: usize,
    },
    /// A setting or motion parameter is out of range.
    #[error("{0}")]
    Settings(&'static str),
    /// The influence matrix of the contour is singular (degenerate
    /// geometry).
    #[error("the contour's influence matrix is singular")]
    Singular,
}

/// The steady solution at one angle of attack (a wake panel of strength
/// `mu_W` from the trailing edge to infinity along the freestream; the
/// same influence code as the unsteady run).
#[derive(Clone, Debug, PartialEq)]
pub struct SteadySolution {
    /// Angle of attack, rad (nose up, relative to the body x axis).
    pub alpha: f64,
    /// Lift coefficient (normal to the freestream).
    pub cl: f64,
    /// Pressure drag coefficient (zero in exact potential flow: a check).
    pub cd: f64,
    /// Moment coefficient about the quarter chord (body (0.25, 0)), nose up.
    pub cm_quarter_chord: f64,
    /// Bound circulation `mu_W` (clockwise), U c; `CL = 2 Gamma` exactly in
    /// potential flow (Kutta–Joukowski).
    pub circulation: f64,
    /// Collocation points (panel midpoints), body frame, chords.
    pub points: Vec<[f64; 2]>,
    /// Pressure coefficient at the collocation points.
    pub cp: Vec<f64>,
}

#[inline]
fn dot(a: V2, b: V2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

/// The rigid-body transform of [`super::ldvm`]: body point `X` sits at
/// `(p + x, h) + R (X - (p, 0))`, `R` the clockwise rotation by `alpha`,
/// `x` the surge downstream (a flapping section's; zero otherwise).
#[derive(Clone, Copy, Debug)]
struct Frame {
    pivot: f64,
    x: f64,
    x_dot: f64,
    h: f64,
    h_dot: f64,
    sin: f64,
    cos: f64,
    alpha_dot: f64,
}

impl Frame {
    /// The frame at `t`: the motion's plunge and pitch, or a flapping
    /// section's surge and plunge with the motion's pitch.
    fn at(motion: &Motion, flapping: Option<&SectionFlapping>, t: f64) -> Self {
        let (mut h, mut h_dot, alpha, alpha_dot) = motion.at(t);
        let (mut x, mut x_dot) = (0.0, 0.0);
        if let Some(f) = flapping {
            (x, x_dot, h, h_dot) = f.at(t);
        }
        let (sin, cos) = alpha.sin_cos();
        Self {
            pivot: motion.pivot,
            x,
            x_dot,
            h,
            h_dot,
            sin,
            cos,
            alpha_dot,
        }
    }

    /// Body vector to global.
    fn rotate(&self, v: V2) -> V2 {
        [
            self.cos * v[0] + self.sin * v[1],
            -self.sin * v[0] + self.cos * v[1],
        ]
    }

    fn to_global(self, x: V2) -> V2 {
        let r = self.rotate([x[0] - self.pivot, x[1]]);
        [self.pivot + self.x + r[0], self.h + r[1]]
    }

    fn to_body(self, r: V2) -> V2 {
        let (dx, dy) = (r[0] - self.pivot - self.x, r[1] - self.h);
        [
            self.pivot + self.cos * dx - self.sin * dy,
            self.sin * dx + self.cos * dy,
        ]
    }

    /// Velocity of the rigid body at body point `x`, body axes: the
    /// pivot's `(x', h')` turned into the body axes, and the rotation.
    fn body_velocity(&self, x: V2) -> V2 {
        [
            self.cos * self.x_dot - self.sin * self.h_dot + self.alpha_dot * x[1],
            self.sin * self.x_dot + self.cos * self.h_dot - self.alpha_dot * (x[0] - self.pivot),
        ]
    }

    /// Freestream in body axes.
    fn freestream(&self) -> V2 {
        [self.cos, self.sin]
    }
}

/// Quasi-steady pressure `|v_kin|^2 - v_t^2` at each collocation point from
/// the doublets and the kinematic velocity `v_kin = U_inf - V_surface`.
/// Also returns the relative tangential (clockwise) surface velocity, the
/// slip.
fn quasi_steady(outline: &Outline, mu: &[f64], kinematic: &[V2]) -> (Vec<f64>, Vec<f64>) {
    outline
        .derivative_stencils()
        .iter()
        .enumerate()
        .map(|(i, (idx, w))| {
            let dmu: f64 = idx.iter().zip(w).map(|(&j, w)| w * mu[j]).sum();
            let vt = dmu + dot(kinematic[i], outline.tangent[i]);
            (dot(kinematic[i], kinematic[i]) - vt * vt, vt)
        })
        .unzip()
}

/// Force `-sum Cp n L` (body axes) and moment (ccw) about `about`.
fn pressure_force(outline: &Outline, cp: &[f64], about: V2) -> (V2, f64) {
    let mut f = [0.0, 0.0];
    let mut moment = 0.0;
    for (i, ((p, n), l)) in cp
        .iter()
        .zip(&outline.normal)
        .zip(&outline.length)
        .enumerate()
    {
        let df = [-p * n[0] * l, -p * n[1] * l];
        f[0] += df[0];
        f[1] += df[1];
        let r = [outline.mid[i][0] - about[0], outline.mid[i][1] - about[1]];
        moment += r[0] * df[1] - r[1] * df[0];
    }
    (f, moment)
}

/// The wake's doublet at the trailing edge from the Kutta condition.
fn kutta_jump(outline: &Outline, mu: &[f64]) -> f64 {
    outline.kutta().iter().map(|&(k, c)| c * mu[k]).sum()
}

/// The steady solution of `section` at angle of attack `alpha` (rad).
pub fn solve_steady(section: &SectionShape, alpha: f64) -> SteadySolution {
    let outline = Outline::new(section.vertices().to_vec());
    let matrices = Matrices::new(&outline);
    let m = outline.len();
    let (s, c) = alpha.sin_cos();
    let kinematic = vec![[c, s]; m];
    let sigma: Vec<f64> = (0..m)
        .map(|j| -dot(kinematic[j], outline.normal[j]))
        .collect();
    let rhs: Vec<f64> = matrices
        .source
        .chunks_exact(m)
        .map(|row| -row.iter().zip(&sigma).map(|(b, s)| b * s).sum::<f64>())
        .collect();
    // Semi-infinite wake panel along the freestream.
    let w: Vec<f64> = outline
        .mid
        .iter()
        .map(|p| {
            let a = [outline.root[0] - p[0], outline.root[1] - p[1]];
            (a[0] * s - a[1] * c).atan2(dot(a, [c, s])) / (2.0 * PI)
        })
        .collect();
    let mu = matrices.solve(&rhs, &w, &outline.kutta());
    let (cp, _) = quasi_steady(&outline, &mu, &kinematic);
    let (f, moment) = pressure_force(&outline, &cp, [0.25, 0.0]);
    SteadySolution {
        alpha,
        cl: -f[0] * s + f[1] * c,
        cd: f[0] * c + f[1] * s,
        cm_quarter_chord: -moment,
        circulation: kutta_jump(&outline, &mu),
        points: outline.mid.clone(),
        cp,
    }
}

/// What the loads at the next half step need from a step.
struct Step {
    /// Doublets.
    mu: Vec<f64>,
    /// Quasi-steady pressures.
    q: Vec<f64>,
    /// Vertical impulse `sum Gamma x` of all the vorticity (/ rho).
    impulse: f64,
}

/// The unsteady panel solver (see the module documentation): a section in
/// prescribed plunge and pitch ([`Motion`], as in [`super::ldvm`]),
/// optionally deforming ([`ShapeHistory`]), started impulsively from rest.
pub struct PanelSolver {
    motion: Motion,
    /// A flapping section's surge and plunge replacing the harmonic plunge.
    flapping: Option<SectionFlapping>,
    settings: PanelSettings,
    shape: Option<ShapeHistory>,
    /// The contour now (body frame) and its factored system.
    outline: Outline,
    matrices: Matrices,
    wake: Vec<FreeVortex>,
    /// The previous step.
    previous: Option<Step>,
    bound: f64,
    last_cp: Vec<f64>,
    time: f64,
    core2: f64,
}

impl PanelSolver {
    /// A section at rest in the freestream, about to move with `motion`.
    pub fn new(
        section: &SectionShape,
        motion: Motion,
        settings: PanelSettings,
    ) -> Result<Self, PanelError> {
        let positive = |v: f64| v > 0.0 && v.is_finite();
        if !(positive(settings.dt) && settings.duration >= 0.0 && settings.duration.is_finite()) {
            return Err(PanelError::Settings(
                "dt must be positive and duration non-negative, both finite",
            ));
        }
        if settings.far_wake.is_nan() || settings.far_wake <= 0.0 {
            return Err(PanelError::Settings("far_wake must be positive"));
        }
        let finite = [
            motion.reduced_frequency,
            motion.plunge_amplitude,
            motion.mean_pitch,
            motion.pitch_amplitude,
            motion.pitch_phase,
            motion.pivot,
        ];
        if !finite.iter().all(|v| v.is_finite()) {
            return Err(PanelError::Settings("motion parameters must be finite"));
        }
        let outline = Outline::new(section.vertices().to_vec());
        let matrices = Matrices::new(&outline);
        if !matrices.is_regular() {
            return Err(PanelError::Singular);
        }
        let core = 1.3 * settings.dt;
        Ok(Self {
            motion,
            flapping: None,
            settings,
            shape: None,
            outline,
            matrices,
            wake: Vec::new(),
            previous: None,
            bound: 0.0,
            last_cp: Vec::new(),
            time: 0.0,
            core2: core * core,
        })
    }

    /// Surge and plunge of a flapping wing's section instead of the
    /// harmonic plunge (pitch and pivot still from the motion), as
    /// [`super::ldvm::Ldvm::with_flapping`]: the surge velocity `x'`
    /// changes the air's speed over the section to `1 - x'`; coefficients
    /// stay referred to the flight speed.
    pub fn with_flapping(mut self, flapping: SectionFlapping) -> Self {
        self.flapping = Some(flapping);
        self
    }

    /// A deforming section: the contour follows `history` (same vertex
    /// count as the section given to [`Self::new`], whose shape it
    /// replaces), with the rigid motion on top. The influence matrix is
    /// rebuilt and factored every step (and the geometry evaluated again at
    /// each half step for the loads).
    pub fn with_shape_history(mut self, history: ShapeHistory) -> Result<Self, PanelError> {
        if history.vertex_count() != self.outline.len() {
            return Err(PanelError::HistoryMismatch {
                section: self.outline.len(),
                history: history.vertex_count(),
            });
        }
        self.shape = Some(history);
        Ok(self)
    }

    /// The free vortices, in shedding order (global frame).
    pub fn wake(&self) -> &[FreeVortex] {
        &self.wake
    }

    /// The bound circulation `mu_W` (clockwise) of the last step, U c.
    pub fn bound_circulation(&self) -> f64 {
        self.bound
    }

    /// The pressure coefficient at the collocation points (body frame, as
    /// of the last step) at the last reported half step.
    pub fn surface_pressure(&self) -> (&[[f64; 2]], &[f64]) {
        (&self.outline.mid, &self.last_cp)
    }

    /// Runs to the end of [`PanelSettings::duration`]; returns the
    /// histories (loads from the second step, at half steps).
    pub fn run(&mut self) -> History {
        let steps = (self.settings.duration / self.settings.dt).round() as usize;
        let mut history = History::default();
        for _ in 0..steps {
            self.step(&mut history);
        }
        history
    }

    /// Contour (body frame) and its vertex velocities at time `t`.
    fn contour_at(&self, t: f64) -> Option<(Outline, Vec<V2>)> {
        self.shape.as_ref().map(|h| {
            let (vertices, velocities) = h.at(t);
            let m = vertices.len();
            let mid_velocity = (0..m)
                .map(|i| {
                    let (a, b) = (velocities[i], velocities[(i + 1) % m]);
                    [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
                })
                .collect();
            (Outline::new(vertices), mid_velocity)
        })
    }

    /// One time step.
    fn step(&mut self, history: &mut History) {
        let dt = self.settings.dt;
        self.time += dt;
        let t = self.time;
        let frame = Frame::at(&self.motion, self.flapping.as_ref(), t);
        let m = self.outline.len();
        let deformation = match self.contour_at(t) {
            Some((outline, velocity)) => {
                self.matrices = Matrices::new(&outline);
                self.outline = outline;
                velocity
            }
            None => vec![[0.0; 2]; m],
        };
        let outline = &self.outline;
        let kinematic: Vec<V2> = (0..m)
            .map(|i| {
                let (u, b) = (frame.freestream(), frame.body_velocity(outline.mid[i]));
                [
                    u[0] - b[0] - deformation[i][0],
                    u[1] - b[1] - deformation[i][1],
                ]
            })
            .collect();
        let sigma: Vec<f64> = (0..m)
            .map(|j| -dot(kinematic[j], outline.normal[j]))
            .collect();
        let mut rhs: Vec<f64> = self
            .matrices
            .source
            .chunks_exact(m)
            .map(|row| -row.iter().zip(&sigma).map(|(b, s)| b * s).sum::<f64>())
            .collect();

        // Where this step's vortex is shed (global frame).
        let root = frame.to_global(outline.root);
        let e = match self.wake.last() {
            Some(last) => [
                root[0] + (last.x - root[0]) / 3.0,
                root[1] + (last.y - root[1]) / 3.0,
            ],
            None => {
                let b = frame.rotate(outline.bisector);
                [root[0] + 0.5 * dt * b[0], root[1] + 0.5 * dt * b[1]]
            }
        };
        // The wake's doublet sheet beyond E: segments from E through the
        // free vortices, newest first; the segment ending at vortex k - 1
        // carries the circulation of the vortices older than k.
        let e_body = frame.to_body(e);
        let n = self.wake.len();
        let mut prefix = Vec::with_capacity(n + 1);
        let mut sum = 0.0;
        prefix.push(0.0);
        for v in &self.wake {
            sum += v.gamma;
            prefix.push(sum);
        }
        let chain: Vec<V2> = std::iter::once(e_body)
            .chain(self.wake.iter().rev().map(|v| frame.to_body([v.x, v.y])))
            .collect();
        let strengths: Vec<f64> = (1..=n).rev().map(|k| prefix[k]).collect();
        let mut phi = vec![0.0; m];
        let groups = clusters(&outline.mid, CLUSTERS);
        chain_potential(&chain, &strengths, &outline.mid, &groups, &mut phi);
        for (r, p) in rhs.iter_mut().zip(&phi) {
            *r -= p;
        }
        let w: Vec<f64> = outline
            .mid
            .iter()
            .map(|p| doublet_potential(outline.root, e_body, *p))
            .collect();
        let mu = self.matrices.solve(&rhs, &w, &outline.kutta());
        let mu_w = kutta_jump(outline, &mu);
        self.bound = mu_w;
        self.wake.push(FreeVortex {
            x: e[0],
            y: e[1],
            gamma: mu_w - sum,
        });

        let (q, slip) = quasi_steady(outline, &mu, &kinematic);
        // Impulse of all the vorticity (Wu 1981, AIAA J. 19, with the
        // section's interior taken as fluid at rest): the wake and the
        // surface sheet that stops the flow inside, of ccw strength
        // `-u . t` (t clockwise, u the absolute fluid velocity there).
        let mut impulse: f64 = self.wake.iter().map(|v| v.gamma * v.x).sum();
        for i in 0..m {
            let x = frame.to_global(outline.mid[i])[0];
            let b = frame.body_velocity(outline.mid[i]);
            let v = [b[0] + deformation[i][0], b[1] + deformation[i][1]];
            impulse -= x * (slip[i] + dot(v, outline.tangent[i])) * outline.length[i];
        }
        let now = Step { mu, q, impulse };
        if let Some(previous) = self.previous.take() {
            self.loads(history, t - 0.5 * dt, &now, &previous);
        }
        let body = self.body_field(&frame, &now.mu, &sigma);
        let limit = root[0] + self.settings.far_wake;
        wake::convect(&mut self.wake, &body, limit, dt, self.core2);
        self.previous = Some(now);
    }

    /// The section's singularities in the global frame, for the wake.
    fn body_field(&self, frame: &Frame, mu: &[f64], sigma: &[f64]) -> BodyField {
        let outline = &self.outline;
        let m = outline.len();
        let vertices: Vec<V2> = outline
            .vertices
            .iter()
            .map(|v| frame.to_global(*v))
            .collect();
        // The doublet panels as vortices at the vertices; at a sharp edge
        // the trailing-edge vertex's `mu_W` cancels the wake panel's end.
        let vortices: Vec<FreeVortex> = (1..m)
            .map(|k| FreeVortex {
                x: vertices[k][0],
                y: vertices[k][1],
                gamma: mu[(k + m - 1) % m] - mu[k],
            })
            .collect();
        let panels = (0..m)
            .map(|j| (vertices[j], vertices[(j + 1) % m], sigma[j]))
            .collect();
        BodyField::new(panels, vortices)
    }

    /// Loads at the half step `tm` from the doublets and quasi-steady
    /// pressures of the two steps around it.
    fn loads(&mut self, history: &mut History, tm: f64, now: &Step, previous: &Step) {
        let dt = self.settings.dt;
        let (mu, mu_prev, q, q_prev) = (&now.mu, &previous.mu, &now.q, &previous.q);
        let m = mu.len();
        let frame = Frame::at(&self.motion, self.flapping.as_ref(), tm);
        let deformed = self.contour_at(tm);
        let rigid = vec![[0.0; 2]; m];
        let (outline, deformation) = match &deformed {
            Some((o, v)) => (o, v),
            None => (&self.outline, &rigid),
        };
        let cp: Vec<f64> = (0..m)
            .map(|i| 0.5 * (q[i] + q_prev[i]) - 2.0 * (mu[i] - mu_prev[i]) / dt)
            .collect();
        let (f, _) = pressure_force(outline, &cp, [frame.pivot, 0.0]);
        let power: f64 = (0..m)
            .map(|i| {
                let b = frame.body_velocity(outline.mid[i]);
                let v = [b[0] + deformation[i][0], b[1] + deformation[i][1]];
                cp[i] * dot(v, outline.normal[i]) * outline.length[i]
            })
            .sum();
        let fg = frame.rotate(f);
        history.time.push(tm);
        history.cl.push(fg[1]);
        history.ct.push(-fg[0]);
        history.cp.push(power);
        history.bound_circulation.push(self.bound);
        history
            .cl_impulse
            .push(2.0 * (now.impulse - previous.impulse) / dt);
        self.last_cp = cp;
    }
}
