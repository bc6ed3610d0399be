//! The LESP-modulated discrete-vortex method (LDVM, Ramesh, Gopalarathnam,
//! Granlund, Ol & Edwards 2014, J. Fluid Mech. 751) for a thin, possibly
//! cambered and deforming section, in units of chord, freestream speed and
//! air density (`c = U = rho = 1`).
//!
//! - Bound vorticity as a Glauert series
//!   `gamma(theta) = 2 U [A0 (1 + cos theta)/sin theta + sum An sin n theta]`,
//!   `x = c (1 - cos theta) / 2`, with `A0 = 1/pi int W dtheta`,
//!   `An = -2/pi int W cos(n theta) dtheta`, `W` the normal velocity of the
//!   flow relative to the plate without the bound vorticity (wake-induced
//!   velocity, freestream, plunge and pitch motion).
//! - One trailing-edge vortex shed per step, placed [`EDGE_PLACEMENT`]
//!   (0.232) of the way from the trailing edge to the previous one, its
//!   strength set by Kelvin's theorem; since `W` is linear in it, solved
//!   exactly. Ramesh et al. place it a third of the way; see "The wake
//!   next to the edge" below for why not.
//! - Leading-edge vortices (switched on by [`Settings::lesp_critical`]): when
//!   the leading-edge suction parameter `|A0|` would exceed its critical
//!   value, a vortex is also shed at the leading edge (half a step
//!   downstream with the relative flow, or a third of the way to the last
//!   one while shedding continues) and both new strengths follow from
//!   Kelvin and `A0 = +-LESP_crit`, two linear equations.
//! - Free vortices with a Vatistas (n = 2) core of radius `1.3 U dt`
//!   among themselves (Ramesh et al.), convected by forward Euler with the
//!   velocity induced by the bound and free vortices plus the freestream.
//!   On the chord's stations a free vortex's core is the width of the
//!   chord's panel at its foot (`Chord::core2`), not `1.3 U dt`.
//! - Loads from the pressure jump of unsteady Bernoulli,
//!   `dp = rho (V_t gamma + d/dt int_0^x gamma)`, integrated over the bound
//!   vortices: normal force `sum V_t Gamma_j + d/dt sum Gamma_j (c - x_j)`
//!   (for the Glauert series this is the LDVM's
//!   `2 pi (A0 + A1/2) + 2 pi c/U (3/4 A0' + 1/4 A1' + 1/8 A2')` plus the
//!   wake term), moment likewise, and the leading-edge suction
//!   `rho pi c U^2 A0^2` along the chord, which is the thrust of a plunging
//!   plate. The leading-edge vortices are fed through a sheet from the
//!   leading edge, so the potential jump along the plate starts from their
//!   total circulation. Time derivatives are backward differences, so all loads and the
//!   kinematics that multiply them are taken at the half step.
//!
//! ## The wake next to the edge
//! The chord answers a wake vortex at a distance `s` behind its trailing
//! edge as `s^(-1/2)` (the bound circulation a vortex induces on a plate,
//! `Γ (sqrt((1 + s)/s) - 1)`, the kernel of the wake integrals of Wagner's
//! and Theodorsen's problems: von Kármán & Sears 1938, *J. Aeronaut. Sci.*
//! 5). The shed vortices are a point-by-point sum of the continuous
//! wake sheet against that kernel, one point a step, the newest at `a`
//! steps' travel from the edge; such a sum's leading error is
//! `ζ(1/2, a) sqrt(U dt)` (the Hurwitz zeta function: Navot 1961, *J.
//! Math. Phys.* 40, the Euler–Maclaurin expansion for an integrand with
//! an algebraic end singularity; Lyness & Ninham 1967, *Math. Comp.*
//! 21). Placed a fraction `f` of the way to the previous vortex, which
//! has travelled a step since it was placed, the newest settles at
//! `a = f / (1 - f)`: Ramesh et al.'s third is `a = 1/2`, `ζ = -0.605`,
//! and the loads converged only as `sqrt(dt)` (Garrick's plunge at k = 1,
//! h = 0.01 c, the power +10.3 %, +7.4 %, +5.4 % high at dt, dt/2,
//! dt/4). [`EDGE_PLACEMENT`] puts the newest at the zero of `ζ(1/2, a)`,
//! `a* = 0.30272`, so that term vanishes. The free vortices' core of
//! `1.3 U dt` also smoothed this kernel over the newest dozen vortices,
//! another `sqrt(dt)` term of about half the error; on the chord's
//! stations a vortex's core is instead the chord's own resolution at
//! its foot, the width of the panel there, `(c/2)(π/M) sin θ`, which
//! vanishes towards the edges as the stations crowd there and keeps the
//! downwash resolved by the stations where a vortex passes over the
//! chord (with no core there, a wake vortex swept back over the plate
//! took a flapping section's power to 29 times its value). Measured
//! (`fwav validate --only aero2d/ldvm`, before and after): Garrick's
//! plunge at k = 1, h = 0.05 c, thrust +6.18 % and efficiency -4.15 %
//! against theory, now +0.12 % and -0.57 %; Wagner's lift at 1 and 5
//! semichords +1.95 % (at dt 0.00125) and +1.53 % (at 0.01), now +0.32 %
//! and +0.04 % (+0.26 % at s = 1 with dt 0.01); the LDVM paper's case 1
//! mean and peak lift +14.1 % and +9.5 % against its CFD, now +6.9 % and
//! +2.1 %. Garrick's plunge at k = 2, h = 0.05 c (`fwav aero2d`'s step,
//! 0.015): the power +16.6 % and efficiency -9.9 % from theory (the
//! figures issue 23 quotes), now +4.1 % and -3.1 %, the plunge's own
//! nonlinearity (the same at half and a quarter of the step).
//!
//! ## The leading-edge vortices
//! A flapping section that sheds leading-edge vortices does not
//! converge with the step; its loads scatter. On the discipline's 18 L18
//! rows of the built-in design (the built-in mid-span case, rigid, LESP
//! 0.11) the power changes by 4.5 % on average (9.8 % at most) from the
//! step 0.015 to its half, and the (gross) thrust by 0.9 %; row 1 (9 Hz,
//! ±20°, −10°, plane 70°) gives 0.3928, 0.3542, 0.3710 at 0.015,
//! 0.0075, 0.00375 (a scratch build that placed the leading-edge vortex
//! by `x (1/3)` for the code's `x / 3`; the code's own gives 0.3941 at
//! 0.015, the last bit's difference grown to 0.3 %).
//! The first shedding of the first stroke agrees at all three steps;
//! the runs part when its vortices pass over the plate and leave by the
//! trailing edge, and each later shedding starts from where the last
//! left its vortices. Tried on that row (2026-12-07, power at the three
//! steps), none converges:
//!
//! - the leading-edge vortices placed by [`EDGE_PLACEMENT`]: 0.3806,
//!   0.3512, 0.3743. The chord answers a vortex near its leading edge as
//!   `s^(-1/2)` too (through `A0`); on the LDVM paper's case 1 this took
//!   the mean and peak lift to +4.7 % and −0.5 % of its CFD, but the lift
//!   from the vortex impulse hardly moved (2.431 to 2.415) and parted
//!   from the pressure lift by 3.3 % (1.8 % with the third), past the 3 %
//!   the two must agree within (`aero2d::ldvm_case_1_lift_within_15_percent_of_cfd`);
//! - the vortices' core fixed in chords instead of `1.3 U dt` (Krasny's
//!   regularization, which a vortex sheet's roll-up converges under):
//!   0.3928, 0.3850, 0.4055 with the default step's 0.0195 c; 0.4461,
//!   0.3936, 0.4333 with 0.04 c;
//! - the free vortices moved by the second-order Adams–Bashforth rule
//!   instead of Euler's: row 1 0.4434, 0.4302, 0.4030, and over the 18
//!   rows the power moved by 15.7 % on average from Euler's at the same
//!   step, and the net efficiency by 9.5 % RMS between its own step and
//!   half step (Euler's: 5.3 %);
//! - the bound vortices seen by the free ones with the width of their own
//!   panel as core (the continuous sheet at the chord's resolution, where
//!   the free vortices' `1.3 U dt` makes the stations ever sharper as the
//!   step shrinks): 0.3977, 0.3570, 0.3813 with that core alone, 0.3865,
//!   0.3516, 0.3705 with the larger of it and `1.3 U dt`; without either,
//!   the same build gives 0.3941, 0.3486, 0.3696 (the code's own
//!   placement; these and the next, the code of `8f458c0`, 2026-12-07,
//!   with environment knobs);
//! - a finer bound sheet: 160 chord points and 80 Fourier terms, 0.4022,
//!   0.3561, 0.3609; 320 and 160, 0.4269, 0.3596, 0.3600, and 0.3878 at
//!   an eighth of the step (the half and quarter steps' agreement a
//!   coincidence).
//!
//! Free vortices cross the plate's chord line between its edges, which
//! no vortex of the continuous flow can, and more often the smaller the
//! step: 195, 550, 1,702 times in row 1's run at the three steps (more
//! than the steps' count grows), and with 320 chord points 164, 403, 843
//! and 1,664 at an eighth. Their core `1.3 U dt` shrinks with the step,
//! and a new leading-edge vortex is placed half a step's travel from the
//! edge, ever nearer the plate. Mirroring a crossing vortex back (a
//! first try) made thousands of crossings and a negative power.
//!
//! At one step the flow nearly repeats: over strokes 3 to 12, each row's
//! five two-stroke windows differ by 0.9 % (net thrust) and 1.2 % (net
//! efficiency) RMS. On a deforming section the step moves the scores far
//! more: the vortices' pressure pushes on the camber's slope, and the
//! net thrust of the same rows on the default design's first deformation
//! fell by 14.6 % on average (18.2 % RMS, 35 % at most) from the step to
//! its half, where the attached flow on that section moves by 0.23 %. So
//! the discipline's scores carry the step's scatter as the Navier–Stokes
//! model's carry theirs
//! ([`crate::discipline::section_model::LDVM_SHEDDING_SCATTER`],
//! [`crate::discipline::section_model::LDVM_SHEDDING_DEFORMING_SCATTER`]),
//! and Ramesh et al.'s third stays for the leading edge.
//!
//! Cost per step is O(M N_w + N_w^2) for `M` chord points and `N_w` wake
//! vortices.

use std::f64::consts::PI;

use super::camber::CamberHistory;
pub use super::history::{cycle_mean_of, cycle_means, cycle_means_until, History};
pub use super::motion::{Motion, PitchRamp, SectionFlapping};

mod loads;
mod vortex;

use loads::LoadIntegrals;
pub(crate) use vortex::induced;
pub use vortex::FreeVortex;
use vortex::{far_proxies, Sources};

/// How far from the trailing edge towards the last shed vortex the new
/// one is placed: `a* / (1 + a*)`, with `a* = 0.302721828598366` the zero
/// of the Hurwitz zeta function `ζ(1/2, a)` (module docs, "The wake next
/// to the edge"; Ramesh et al. 2014 take 1/3).
pub const EDGE_PLACEMENT: f64 = 0.302_721_828_598_366 / 1.302_721_828_598_366;

/// Numerical settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Chord collocation points (and bound vortices).
    pub chord_points: usize,
    /// Fourier terms beyond A0.
    pub fourier_terms: usize,
    /// Time step, chords travelled (U dt / c).
    pub dt: f64,
    /// Simulated time, chords travelled (U t / c).
    pub duration: f64,
    /// Free vortices farther than this downstream of the trailing edge,
    /// chords, drift with the freestream instead of being convected by the
    /// induced velocity (they still induce velocity on the section and the
    /// near wake, and count in Kelvin's sum): the far wake's self-induced
    /// roll-up no longer affects the section, and the O(N^2) cost of
    /// convecting it goes away.
    pub far_wake: f64,
    /// Critical leading-edge suction parameter (LESP, `|A0|`) beyond which
    /// a leading-edge vortex is shed each step so that `|A0|` stays at the
    /// critical value (Ramesh et al. 2014); `None` switches shedding off
    /// (the attached-flow, Garrick limit).
    pub lesp_critical: Option<f64>,
    /// Chord Reynolds number `U c / nu` for the laminar skin-friction
    /// estimate ([`super::friction`]); `None` leaves it out.
    pub reynolds: Option<f64>,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            chord_points: 80,
            fourier_terms: 40,
            dt: 0.015,
            duration: 10.0,
            far_wake: 1.5,
            lesp_critical: None,
            reynolds: None,
        }
    }
}

/// The solver state.
pub struct Ldvm {
    motion: Motion,
    camber: Option<CamberHistory>,
    settings: Settings,
    theta: Vec<f64>,
    wake: Vec<FreeVortex>,
    /// Bound vortices of the last step: global positions and ccw circulation.
    bound: Vec<FreeVortex>,
    /// Load integrals of the previous step.
    loads: Option<LoadIntegrals>,
    /// Leading-edge vortices, in shedding order.
    leading: Vec<FreeVortex>,
    /// Whether the last step shed a leading-edge vortex (the next one is
    /// then placed a third of the way towards it).
    shedding: bool,
    /// A pitch ramp replacing the harmonic pitch of `motion`.
    ramp: Option<PitchRamp>,
    /// A flapping section's surge and plunge replacing the harmonic plunge.
    flapping: Option<SectionFlapping>,
    /// The vertical vortex impulse of the previous step.
    impulse_prev: f64,
    /// Running bound circulation from the leading edge to each station, of
    /// the previous step (for the unsteady pressure on a deforming section).
    running_previous: Vec<f64>,
    /// `cos(n theta_k)`, row n (0..=N), column k: the Fourier projection.
    cos_table: Vec<f64>,
    /// Row n, column j: the integral of term n of the Glauert series over
    /// bound panel j (so panel circulations are a matrix-vector product).
    panel_table: Vec<f64>,
    time: f64,
    core2: f64,
}

/// The rigid motion at one time (chords, radians, chords travelled).
#[derive(Clone, Copy, Debug)]
struct Kinematics {
    x: f64,
    x_dot: f64,
    h: f64,
    h_dot: f64,
    alpha: f64,
    alpha_dot: f64,
}

/// The section at one step: its rigid motion, the sine and cosine of its
/// pitch, and the time (for the camber line's shape).
#[derive(Clone, Copy, Debug)]
struct Pose {
    kinematics: Kinematics,
    sa: f64,
    ca: f64,
    t: f64,
}

/// The chord stations of one step.
struct Chord {
    /// `(x_b, x, y)`: chordwise station (chords from the leading edge) and
    /// global position on the camber line.
    stations: Vec<(f64, f64, f64)>,
    /// `(d eta/dx, d eta/dt)` at each station.
    slopes: Vec<(f64, f64)>,
    /// The camber line's leading edge, and the vector from it to the
    /// trailing edge.
    leading_edge: (f64, f64),
    along: (f64, f64),
    /// The stations' spacing in `theta`, `pi / M`.
    spacing: f64,
}

impl Chord {
    /// The squared core radius with which the stations see a free vortex:
    /// the width of the chord's panel at the vortex's foot on the chord
    /// line, `(c/2) (pi/M) sin(theta)`, `theta` held within the end
    /// stations' (module docs, "The wake next to the edge").
    fn core2(&self, v: &FreeVortex) -> f64 {
        let (ax, ay) = self.along;
        let length2 = ax * ax + ay * ay;
        let foot = ((v.x - self.leading_edge.0) * ax + (v.y - self.leading_edge.1) * ay) / length2;
        // sin(theta) at x = (1 - cos theta)/2 is 2 sqrt(x (1 - x)); the
        // end stations sit half a spacing from the edges.
        let end = (0.5 * self.spacing).sin();
        let sin_theta = (2.0 * (foot * (1.0 - foot)).max(0.0).sqrt()).max(end);
        let radius = 0.5 * self.spacing * sin_theta;
        radius * radius * length2
    }
}

/// Normal (`w`) and tangential (`vt`) flow relative to the plate, without
/// the bound vorticity, at the chord stations: row 0 the part known now,
/// row `k + 1` per unit strength of new vortex `k`.
struct Influence {
    w: Vec<Vec<f64>>,
    vt: Vec<Vec<f64>>,
}

impl Ldvm {
    /// A plate at rest in the freestream, about to move.
    pub fn new(motion: Motion, settings: Settings) -> Self {
        let m = settings.chord_points;
        let theta: Vec<f64> = (0..m).map(|k| (k as f64 + 0.5) * PI / m as f64).collect();
        let core = 1.3 * settings.dt;
        let terms = settings.fourier_terms + 1;
        let cos_table = (0..terms)
            .flat_map(|n| theta.iter().map(move |t| (n as f64 * t).cos()))
            .collect();
        // Antiderivatives in theta of gamma dx for each series term (c = U = 1).
        let g = |n: usize, th: f64| -> f64 {
            match n {
                0 => th + th.sin(),
                1 => 0.5 * th - 0.25 * (2.0 * th).sin(),
                _ => {
                    let n = n as f64;
                    ((n - 1.0) * th).sin() / (2.0 * (n - 1.0))
                        - ((n + 1.0) * th).sin() / (2.0 * (n + 1.0))
                }
            }
        };
        let half = 0.5 * PI / m as f64;
        let panel_table = (0..terms)
            .flat_map(|n| theta.iter().map(move |&t| g(n, t + half) - g(n, t - half)))
            .collect();
        Self {
            cos_table,
            panel_table,
            camber: None,
            running_previous: Vec::new(),
            motion,
            settings,
            theta,
            wake: Vec::new(),
            bound: Vec::new(),
            loads: None,
            leading: Vec::new(),
            shedding: false,
            ramp: None,
            flapping: None,
            impulse_prev: 0.0,
            time: 0.0,
            core2: core * core,
        }
    }

    /// A deforming section: the camber line follows `camber` (small-camber
    /// thin-airfoil treatment: the normal tilts by `-d eta/dx` and moves
    /// with `d eta/dt`; loads are integrated along the chord, and the input
    /// power includes the work of the deformation, `-int dp eta_t dx`).
    pub fn with_camber(mut self, camber: CamberHistory) -> Self {
        self.camber = Some(camber);
        self
    }

    /// Surge and plunge of a flapping wing's section instead of the
    /// harmonic plunge (pitch and pivot still from the motion). The surge
    /// velocity `x'` changes the air's speed over the section to `1 - x'`;
    /// coefficients stay referred to the flight speed.
    pub fn with_flapping(mut self, flapping: SectionFlapping) -> Self {
        self.flapping = Some(flapping);
        self
    }

    /// Pitch by Eldredge's ramp instead of the harmonic pitch of the motion
    /// (plunge and pivot still from the motion).
    pub fn with_pitch_ramp(mut self, ramp: PitchRamp) -> Self {
        self.ramp = Some(ramp);
        self
    }

    /// The trailing-edge vortices, in shedding order.
    pub fn wake(&self) -> &[FreeVortex] {
        &self.wake
    }

    /// The section's chord stations at the last step, chords (global).
    pub fn section_points(&self) -> Vec<(f64, f64)> {
        self.bound.iter().map(|v| (v.x, v.y)).collect()
    }

    /// The leading-edge vortices, in shedding order.
    pub fn leading_edge_vortices(&self) -> &[FreeVortex] {
        &self.leading
    }

    /// `(x, x', h, h', alpha, alpha')` at time `t`: surge (downstream),
    /// plunge, pitch and their rates.
    fn kinematics(&self, t: f64) -> Kinematics {
        let (mut h, mut h_dot, mut alpha, mut alpha_dot) = self.motion.at(t);
        if let Some(r) = &self.ramp {
            (alpha, alpha_dot) = r.at(t);
        }
        let (mut x, mut x_dot) = (0.0, 0.0);
        if let Some(f) = &self.flapping {
            (x, x_dot, h, h_dot) = f.at(t);
        }
        Kinematics {
            x,
            x_dot,
            h,
            h_dot,
            alpha,
            alpha_dot,
        }
    }

    /// Global position of chordwise station `xb` (chords from the LE).
    fn body_point(&self, xb: f64, k: &Kinematics) -> (f64, f64) {
        let p = self.motion.pivot;
        let s = xb - p;
        (k.x + p + s * k.alpha.cos(), k.h - s * k.alpha.sin())
    }

    /// Fourier coefficients from normal velocities at the chord points:
    /// `A0 = mean(W)`, `An = -2 mean(W cos n theta)` (midpoint rule).
    fn coefficients(&self, w: &[f64]) -> Vec<f64> {
        let m = w.len();
        self.cos_table
            .chunks_exact(m)
            .enumerate()
            .map(|(n, row)| {
                let mean = row.iter().zip(w).map(|(c, w)| c * w).sum::<f64>() / m as f64;
                if n == 0 {
                    mean
                } else {
                    -2.0 * mean
                }
            })
            .collect()
    }

    /// Runs to the end; returns the histories.
    pub fn run(&mut self) -> History {
        let steps = (self.settings.duration / self.settings.dt).round() as usize;
        let mut history = History::default();
        for _ in 0..steps {
            self.step(&mut history);
        }
        history
    }

    /// One time step: the section's pose and chord stations, the flow at
    /// them (known part and per unit new vortex), the new vortices'
    /// strengths from Kelvin (and the LESP), shedding, the bound vortices,
    /// the loads at the half step, and convection of the free vortices.
    fn step(&mut self, history: &mut History) {
        self.time += self.settings.dt;
        let pose = self.pose(self.time);
        let chord = self.chord(&pose);
        let te = self.edge(1.0, &pose);
        let sources = Sources::split(&self.wake, &self.leading, te.0 + self.settings.far_wake);
        let news = self.new_vortices(&pose, te, &sources);
        let influence = self.influence(&pose, &chord, &sources, &news);
        let coefficients: Vec<Vec<f64>> =
            influence.w.iter().map(|w| self.coefficients(w)).collect();
        let strengths = self.strengths(&coefficients);
        let a = superpose(&coefficients[0], &strengths, &coefficients[1..]);
        let tangential = superpose(&influence.vt[0], &strengths, &influence.vt[1..]);
        self.shed(&strengths, &news);
        self.bind(&a, &chord);
        // The leading-edge vortices are fed through a sheet from the
        // leading edge, across which the potential jumps by their (clockwise)
        // circulation: the jump along the plate starts from that value at
        // x = 0 instead of 0. Without it, each shed vortex would take its
        // circulation out of the bound sheet in one step and the unsteady
        // term would read that as a large, spurious loss of normal force.
        let edge_jump = -self.leading.iter().map(|v| v.gamma).sum::<f64>();
        let now = self.load_integrals(&a, &tangential, &chord, edge_jump);
        let unsteady_camber = self.unsteady_camber(edge_jump);
        let impulse_now = self.impulse();
        if let Some(prev) = self.loads.replace(now) {
            self.record(history, &now, &prev, &a, unsteady_camber, impulse_now);
        }
        self.impulse_prev = impulse_now;
        self.convect(&sources);
    }

    /// The rigid motion at time `t` with the sine and cosine of its pitch.
    fn pose(&self, t: f64) -> Pose {
        let kinematics = self.kinematics(t);
        let (sa, ca) = kinematics.alpha.sin_cos();
        Pose {
            kinematics,
            sa,
            ca,
            t,
        }
    }

    /// The camber line's `(eta, d eta/dx, d eta/dt)` at station `xb` and
    /// time `t` (zero for a rigid section).
    fn shape(&self, xb: f64, t: f64) -> (f64, f64, f64) {
        self.camber
            .as_ref()
            .map_or((0.0, 0.0, 0.0), |c| c.at(xb, t))
    }

    /// The chord stations in `pose`, on the camber line.
    fn chord(&self, pose: &Pose) -> Chord {
        let mut slopes = Vec::with_capacity(self.theta.len());
        let stations: Vec<(f64, f64, f64)> = self
            .theta
            .iter()
            .map(|&th| {
                let xb = 0.5 * (1.0 - th.cos());
                let (eta, slope, rate) = self.shape(xb, pose.t);
                slopes.push((slope, rate));
                let (x, y) = self.body_point(xb, &pose.kinematics);
                // Offset along the normal (sin alpha, cos alpha).
                (xb, x + eta * pose.sa, y + eta * pose.ca)
            })
            .collect();
        let leading_edge = self.edge(0.0, pose);
        let trailing_edge = self.edge(1.0, pose);
        Chord {
            stations,
            slopes,
            leading_edge,
            along: (
                trailing_edge.0 - leading_edge.0,
                trailing_edge.1 - leading_edge.1,
            ),
            spacing: PI / self.theta.len() as f64,
        }
    }

    /// Global position of the camber line's point at station `xb` (0: the
    /// leading edge, 1: the trailing edge) in `pose`.
    fn edge(&self, xb: f64, pose: &Pose) -> (f64, f64) {
        let (x, y) = self.body_point(xb, &pose.kinematics);
        let eta = self.shape(xb, pose.t).0;
        (x + eta * pose.sa, y + eta * pose.ca)
    }

    /// The new vortices of unit strength: the trailing-edge one,
    /// [`EDGE_PLACEMENT`] of the way from the trailing edge `te` to the
    /// last one, and with LESP
    /// shedding on a candidate leading-edge one: a third of the way to the
    /// last one while shedding goes on, else half a step downstream of the
    /// leading edge with the flow relative to it (Ramesh et al. 2014).
    fn new_vortices(&self, pose: &Pose, te: (f64, f64), sources: &Sources) -> Vec<FreeVortex> {
        let dt = self.settings.dt;
        let Kinematics {
            x_dot,
            h_dot,
            alpha_dot,
            ..
        } = pose.kinematics;
        let (sa, ca, pivot) = (pose.sa, pose.ca, self.motion.pivot);
        let (nx, ny) = match self.wake.last() {
            Some(last) => (
                te.0 + (last.x - te.0) * EDGE_PLACEMENT,
                te.1 + (last.y - te.1) * EDGE_PLACEMENT,
            ),
            None => (te.0 + 0.5 * dt, te.1),
        };
        let lev_at = self.settings.lesp_critical.map(|_| {
            let le = self.edge(0.0, pose);
            match (self.shedding, self.leading.last()) {
                (true, Some(last)) => (le.0 + (last.x - le.0) / 3.0, le.1 + (last.y - le.1) / 3.0),
                _ => {
                    // The flow that carries the new vortex off the edge,
                    // with the vortices' own core (as `convect` moves
                    // them), not the chord's stations' (`Chord::core2`).
                    let (u, v) = sources.induced_at(le.0, le.1, std::iter::repeat(self.core2));
                    let relative = (
                        1.0 + u - x_dot - pivot * sa * alpha_dot,
                        v - h_dot - pivot * ca * alpha_dot,
                    );
                    (le.0 + 0.5 * dt * relative.0, le.1 + 0.5 * dt * relative.1)
                }
            }
        });
        let unit = |(x, y): (f64, f64)| FreeVortex { x, y, gamma: 1.0 };
        std::iter::once(unit((nx, ny)))
            .chain(lev_at.map(unit))
            .collect()
    }

    /// Normal and tangential flow relative to the plate (without bound
    /// vorticity) at the chord stations: the part known now, and per unit
    /// new vortex.
    fn influence(
        &self,
        pose: &Pose,
        chord: &Chord,
        sources: &Sources,
        news: &[FreeVortex],
    ) -> Influence {
        let Kinematics {
            x_dot,
            h_dot,
            alpha_dot,
            ..
        } = pose.kinematics;
        let (sa, ca, pivot) = (pose.sa, pose.ca, self.motion.pivot);
        let m = chord.stations.len();
        let mut w = vec![Vec::with_capacity(m); 1 + news.len()];
        let mut vt = vec![Vec::with_capacity(m); 1 + news.len()];
        let cores2: Vec<f64> = sources.vortices.iter().map(|v| chord.core2(v)).collect();
        let new_cores2: Vec<f64> = news.iter().map(|v| chord.core2(v)).collect();
        for (&(xb, x, y), &(slope, rate)) in chord.stations.iter().zip(&chord.slopes) {
            let (du, dv) = sources.induced_at(x, y, cores2.iter().copied());
            // The air relative to the surging section.
            let (u, v) = (1.0 + du - x_dot, dv);
            let relative = u * sa + v * ca - h_dot * ca + (xb - pivot) * alpha_dot;
            let tangential = u * ca - v * sa + h_dot * sa;
            // Camber: the normal tilts by -slope and moves at `rate`.
            w[0].push(relative - slope * tangential - rate);
            vt[0].push(tangential);
            for (k, (new, &core2)) in news.iter().zip(&new_cores2).enumerate() {
                let (du, dv) = induced(new, x, y, core2);
                let unit_tangential = du * ca - dv * sa;
                w[k + 1].push(du * sa + dv * ca - slope * unit_tangential);
                vt[k + 1].push(unit_tangential);
            }
        }
        Influence { w, vt }
    }

    /// The new vortices' strengths from the Fourier coefficients of the
    /// known flow and per unit new vortex. Kelvin: the shed (ccw)
    /// circulation equals the bound (clockwise) one; both are linear in the
    /// new vortices. When the trailing-edge vortex alone would leave `|A0|`
    /// above the critical LESP, a leading-edge vortex is shed as well.
    fn strengths(&self, coefficients: &[Vec<f64>]) -> Vec<f64> {
        let shed_so_far: f64 = self.wake.iter().chain(&self.leading).map(|v| v.gamma).sum();
        let [known, per_te] = [&coefficients[0], &coefficients[1]];
        let kelvin_te = 1.0 - circulation(per_te);
        let mut strengths = vec![(circulation(known) - shed_so_far) / kelvin_te];
        if let (Some(critical), Some(per_le)) = (self.settings.lesp_critical, coefficients.get(2)) {
            let a0 = known[0] + strengths[0] * per_te[0];
            if a0.abs() > critical {
                // Kelvin and A0 = +-critical, two linear equations.
                let kelvin_le = 1.0 - circulation(per_le);
                let rhs = [
                    circulation(known) - shed_so_far,
                    critical.copysign(a0) - known[0],
                ];
                let det = kelvin_te * per_le[0] - kelvin_le * per_te[0];
                strengths = vec![
                    (rhs[0] * per_le[0] - kelvin_le * rhs[1]) / det,
                    (kelvin_te * rhs[1] - per_te[0] * rhs[0]) / det,
                ];
            }
        }
        strengths
    }

    /// Sheds the new vortices with their `strengths` (the leading-edge one
    /// only if it has a strength).
    fn shed(&mut self, strengths: &[f64], news: &[FreeVortex]) {
        self.shedding = strengths.len() == 2;
        self.wake.push(FreeVortex {
            gamma: strengths[0],
            ..news[0]
        });
        if let (Some(&gamma), Some(new)) = (strengths.get(1), news.get(1)) {
            self.leading.push(FreeVortex { gamma, ..*new });
        }
    }

    /// Bound vortices at the chord stations: the analytic integral of
    /// gamma (the Glauert series with coefficients `a`) over each panel.
    fn bind(&mut self, a: &[f64], chord: &Chord) {
        let m_points = self.theta.len();
        let mut panel_gamma = vec![0.0; m_points];
        for (an, row) in a.iter().zip(self.panel_table.chunks_exact(m_points)) {
            for (g, p) in panel_gamma.iter_mut().zip(row) {
                *g += an * p;
            }
        }
        self.bound = panel_gamma
            .iter()
            .zip(&chord.stations)
            .map(|(&g, &(_, x, y))| FreeVortex { x, y, gamma: -g })
            .collect();
    }

    /// Convects the free vortices: the near wakes (as split in `sources`)
    /// with the velocity induced by everything (the far wakes as proxies),
    /// the far wakes with the freestream. (The new vortices joined the near
    /// wakes.)
    fn convect(&mut self, sources: &Sources) {
        let dt = self.settings.dt;
        let (near_from, lev_near_from) = (sources.near_from, sources.lev_near_from);
        let proxies: Vec<FreeVortex> = far_proxies(&self.wake[..near_from])
            .chain(far_proxies(&self.leading[..lev_near_from]))
            .collect();
        let near: Vec<FreeVortex> = self.wake[near_from..]
            .iter()
            .chain(&self.leading[lev_near_from..])
            .copied()
            .collect();
        let velocities: Vec<(f64, f64)> = near
            .iter()
            .map(|p| {
                let (mut u, mut v) = (1.0, 0.0);
                for q in self.bound.iter().chain(&near).chain(&proxies) {
                    let (du, dv) = induced(q, p.x, p.y, self.core2);
                    u += du;
                    v += dv;
                }
                (u, v)
            })
            .collect();
        for p in self.wake[..near_from]
            .iter_mut()
            .chain(&mut self.leading[..lev_near_from])
        {
            p.x += dt;
        }
        for (p, (u, v)) in self.wake[near_from..]
            .iter_mut()
            .chain(&mut self.leading[lev_near_from..])
            .zip(velocities)
        {
            p.x += u * dt;
            p.y += v * dt;
        }
    }
}

/// The bound circulation `pi (A0 + A1/2)` of the Glauert series `a`.
fn circulation(a: &[f64]) -> f64 {
    PI * (a[0] + 0.5 * a[1])
}

/// `known + sum_k strengths[k] per_unit[k]`, entry by entry: the flow (or
/// its coefficients) once the new vortices' strengths are known.
fn superpose(known: &[f64], strengths: &[f64], per_unit: &[Vec<f64>]) -> Vec<f64> {
    (0..known.len())
        .map(|n| {
            known[n]
                + strengths
                    .iter()
                    .zip(per_unit)
                    .map(|(g, c)| g * c[n])
                    .sum::<f64>()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::EDGE_PLACEMENT;

    /// The Hurwitz zeta function `ζ(1/2, a)` by its Euler–Maclaurin
    /// tail: the sum of `(j + a)^(-1/2)` to `n - 1`, less the tail's
    /// integral `2 sqrt(n + a)`, plus its first two corrections (error
    /// `O(n^(-7/2))`).
    fn hurwitz_zeta_half(a: f64) -> f64 {
        let n = 10_000;
        let head: f64 = (0..n).map(|j| (j as f64 + a).powf(-0.5)).sum();
        let x = n as f64 + a;
        head - 2.0 * x.sqrt() + 0.5 * x.powf(-0.5) + x.powf(-1.5) / 24.0
    }

    /// The newest wake vortex settles at `a = f / (1 - f)` steps' travel
    /// from the edge, where `ζ(1/2, a) = 0` (module docs, "The wake next
    /// to the edge"). The sum is checked first on `ζ(1/2, 1) = ζ(1/2) =
    /// -1.4603545088095868...` (DLMF 25.11.2 and Riemann's zeta at 1/2)
    /// and `ζ(1/2, 1/2) = (sqrt(2) - 1) ζ(1/2)` (DLMF 25.11.11).
    #[test]
    fn the_newest_vortex_sits_at_the_zero_of_the_hurwitz_zeta() {
        let riemann = -1.460_354_508_809_586_8;
        assert!((hurwitz_zeta_half(1.0) - riemann).abs() < 1e-10);
        let half = (2f64.sqrt() - 1.0) * riemann;
        assert!((hurwitz_zeta_half(0.5) - half).abs() < 1e-10);
        let a = EDGE_PLACEMENT / (1.0 - EDGE_PLACEMENT);
        assert!(
            hurwitz_zeta_half(a).abs() < 1e-10,
            "{}",
            hurwitz_zeta_half(a)
        );
        // Ramesh et al.'s third leaves the sqrt(dt) term of -0.605.
        assert!((hurwitz_zeta_half(0.5) + 0.6049).abs() < 1e-4);
    }
}
