//! The discrete-vortex thin-plate solver (LDVM class, Ramesh et al. 2014,
//! without leading-edge shedding yet), in units of chord, freestream speed
//! and air density (`c = U = rho = 1`).
//!
//! - Bound vorticity as a Glauert series
//!   `gamma(theta) = 2 U [A0 (1 + cos theta)/sin theta + sum An sin n theta]`,
//!   `x = c (1 - cos theta) / 2`, with `A0 = 1/pi int W dtheta`,
//!   `An = -2/pi int W cos(n theta) dtheta`, `W` the normal velocity of the
//!   flow relative to the plate without the bound vorticity (wake-induced
//!   velocity, freestream, plunge and pitch motion).
//! - One trailing-edge vortex shed per step, placed a third of the way from
//!   the trailing edge to the previous one (Ramesh et al.), its strength set
//!   by Kelvin's theorem; since `W` is linear in it, solved exactly.
//! - Free vortices with a Vatistas (n = 2) core of radius `1.3 U dt`,
//!   convected by forward Euler with the velocity induced by the bound and
//!   free vortices plus the freestream.
//! - Loads from the pressure jump of unsteady Bernoulli,
//!   `dp = rho (V_t gamma + d/dt int_0^x gamma)`, integrated over the bound
//!   vortices: normal force `sum V_t Gamma_j + d/dt sum Gamma_j (c - x_j)`
//!   (for the Glauert series this is the LDVM's
//!   `2 pi (A0 + A1/2) + 2 pi c/U (3/4 A0' + 1/4 A1' + 1/8 A2')` plus the
//!   wake term), moment likewise, and the leading-edge suction
//!   `rho pi c U^2 A0^2` along the chord, which is the thrust of a plunging
//!   plate. Time derivatives are backward differences, so all loads and the
//!   kinematics that multiply them are taken at the half step.
//!
//! Cost per step is O(M N_w + N_w^2) for `M` chord points and `N_w` wake
//! vortices.

use std::f64::consts::PI;

use super::camber::CamberHistory;

/// Prescribed motion of the section (all amplitudes in chords / radians).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Reduced frequency `k = omega c / (2 U)`; 0 for a steady (impulsively
    /// started) motion.
    pub reduced_frequency: f64,
    /// Plunge `h = h0 sin(omega t)`, positive up, chords.
    pub plunge_amplitude: f64,
    /// Mean pitch angle (nose up), rad.
    pub mean_pitch: f64,
    /// Pitch amplitude, rad: `alpha = mean + a sin(omega t + phase)`.
    pub pitch_amplitude: f64,
    /// Phase by which pitch leads plunge, rad.
    pub pitch_phase: f64,
    /// Pitch axis, chords from the leading edge.
    pub pivot: f64,
}

impl Motion {
    /// Pure plunge `h = h0 sin(omega t)` at reduced frequency `k`, no pitch.
    pub fn plunge(reduced_frequency: f64, plunge_amplitude: f64) -> Self {
        Self {
            reduced_frequency,
            plunge_amplitude,
            mean_pitch: 0.0,
            pitch_amplitude: 0.0,
            pitch_phase: 0.0,
            pivot: 0.25,
        }
    }

    /// A steady plate at `alpha` (rad), started impulsively at t = 0.
    pub fn steady(alpha: f64) -> Self {
        Self {
            mean_pitch: alpha,
            ..Self::plunge(0.0, 0.0)
        }
    }

    /// `(h, h', alpha, alpha')` at time `t`.
    fn at(&self, t: f64) -> (f64, f64, f64, f64) {
        let w = 2.0 * self.reduced_frequency;
        let (s, c) = (w * t).sin_cos();
        let (sp, cp) = (w * t + self.pitch_phase).sin_cos();
        (
            self.plunge_amplitude * s,
            self.plunge_amplitude * w * c,
            self.mean_pitch + self.pitch_amplitude * sp,
            self.pitch_amplitude * w * cp,
        )
    }
}

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
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            chord_points: 80,
            fourier_terms: 40,
            dt: 0.015,
            duration: 10.0,
            far_wake: 1.5,
        }
    }
}

/// A free vortex (counter-clockwise circulation positive).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FreeVortex {
    /// Position, chords.
    pub x: f64,
    /// Position, chords.
    pub y: f64,
    /// Circulation, U c.
    pub gamma: f64,
}

/// Time histories of a run (coefficients on `1/2 rho U^2 c`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct History {
    /// Time, chords travelled.
    pub time: Vec<f64>,
    /// Lift coefficient (force up).
    pub cl: Vec<f64>,
    /// Thrust coefficient (force upstream).
    pub ct: Vec<f64>,
    /// Input power coefficient (on `1/2 rho U^3 c`).
    pub cp: Vec<f64>,
    /// Leading-edge suction parameter A0.
    pub lesp: Vec<f64>,
    /// Bound circulation (clockwise positive), U c.
    pub bound_circulation: Vec<f64>,
}

/// Far-wake vortices lumped together for induction.
const FAR_GROUP: usize = 8;

/// The pressure-jump integrals of one step (c = U = rho = 1).
#[derive(Clone, Copy, Debug)]
struct LoadIntegrals {
    /// sum V_t Gamma_j: the quasi-steady normal force.
    normal: f64,
    /// sum V_t Gamma_j x_j.
    moment: f64,
    /// Leading-edge suction pi A0^2.
    suction: f64,
    /// sum Gamma_j (1 - x_j), whose rate is the unsteady normal force.
    q_normal: f64,
    /// sum Gamma_j (1 - x_j^2) / 2, whose rate is the unsteady moment.
    q_moment: f64,
    /// Quasi-steady work rate against the camber motion, sum V_t Gamma_j eta_t,j.
    deform_quasi: f64,
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

/// Velocity induced at `(x, y)` by a ccw vortex with a Vatistas (n = 2)
/// core of squared radius `core2`. Beyond ten core radii the core changes
/// the kernel by less than 5e-5 relative, and the plain `1/r^2` kernel
/// (no square root) is used.
#[inline]
fn induced(v: &FreeVortex, x: f64, y: f64, core2: f64) -> (f64, f64) {
    let (dx, dy) = (x - v.x, y - v.y);
    let r2 = dx * dx + dy * dy;
    let denominator = if r2 > 100.0 * core2 {
        r2
    } else {
        (r2 * r2 + core2 * core2).sqrt()
    };
    let k = v.gamma / (2.0 * PI * denominator);
    (-dy * k, dx * k)
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

    /// The free vortices.
    pub fn wake(&self) -> &[FreeVortex] {
        &self.wake
    }

    /// The far wake for induction: groups of [`FAR_GROUP`] consecutive
    /// vortices as one, at their |Gamma|-weighted centroid with their total
    /// circulation (their spread is small against their distance).
    fn far_proxies(&self, near_from: usize) -> Vec<FreeVortex> {
        self.wake[..near_from]
            .chunks(FAR_GROUP)
            .map(|group| {
                let weight: f64 = group
                    .iter()
                    .map(|v| v.gamma.abs())
                    .sum::<f64>()
                    .max(f64::MIN_POSITIVE);
                let x = group.iter().map(|v| v.x * v.gamma.abs()).sum::<f64>() / weight;
                let y = group.iter().map(|v| v.y * v.gamma.abs()).sum::<f64>() / weight;
                FreeVortex {
                    x,
                    y,
                    gamma: group.iter().map(|v| v.gamma).sum(),
                }
            })
            .collect()
    }

    /// Index of the first vortex of the near wake. The wake is kept in
    /// shedding order and drifts downstream, so the far wake is a prefix.
    fn near_wake_start(&self, x_te: f64) -> usize {
        let limit = x_te + self.settings.far_wake;
        self.wake
            .iter()
            .position(|v| v.x <= limit)
            .unwrap_or(self.wake.len())
    }

    /// Global position of chordwise station `xb` (chords from the LE).
    fn body_point(&self, xb: f64, h: f64, alpha: f64) -> (f64, f64) {
        let p = self.motion.pivot;
        let s = xb - p;
        (p + s * alpha.cos(), h - s * alpha.sin())
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

    /// One time step.
    fn step(&mut self, history: &mut History) {
        let dt = self.settings.dt;
        self.time += dt;
        let t = self.time;
        let (h, h_dot, alpha, alpha_dot) = self.motion.at(t);
        let (sa, ca) = alpha.sin_cos();
        let pivot = self.motion.pivot;
        let shape = |xb: f64| {
            self.camber
                .as_ref()
                .map_or((0.0, 0.0, 0.0), |c| c.at(xb, t))
        };
        let mut slopes = Vec::with_capacity(self.theta.len());
        let stations: Vec<(f64, f64, f64)> = self
            .theta
            .iter()
            .map(|&th| {
                let xb = 0.5 * (1.0 - th.cos());
                let (eta, slope, rate) = shape(xb);
                slopes.push((slope, rate));
                let (x, y) = self.body_point(xb, h, alpha);
                // Offset along the normal (sin alpha, cos alpha).
                (xb, x + eta * sa, y + eta * ca)
            })
            .collect();

        // The new trailing-edge vortex.
        let te = {
            let (x, y) = self.body_point(1.0, h, alpha);
            let eta = shape(1.0).0;
            (x + eta * sa, y + eta * ca)
        };
        let (nx, ny) = match self.wake.last() {
            Some(last) => (te.0 + (last.x - te.0) / 3.0, te.1 + (last.y - te.1) / 3.0),
            None => (te.0 + 0.5 * dt, te.1),
        };
        // Normal velocities without and with a unit new vortex.
        let unit = FreeVortex {
            x: nx,
            y: ny,
            gamma: 1.0,
        };
        let mut w0 = Vec::with_capacity(stations.len());
        let mut w1 = Vec::with_capacity(stations.len());
        // Tangential flow relative to the plate (without bound vorticity),
        // split into the part known now and the part per unit new vortex.
        let mut vt0 = Vec::with_capacity(stations.len());
        let mut vt1 = Vec::with_capacity(stations.len());
        let near_from = self.near_wake_start(te.0);
        let proxies = self.far_proxies(near_from);
        for (&(xb, x, y), &(slope, rate)) in stations.iter().zip(&slopes) {
            let (mut u, mut v) = (1.0, 0.0);
            for fv in self.wake[near_from..].iter().chain(&proxies) {
                let (du, dv) = induced(fv, x, y, self.core2);
                u += du;
                v += dv;
            }
            let relative = u * sa + v * ca - h_dot * ca + (xb - pivot) * alpha_dot;
            let tangential = u * ca - v * sa + h_dot * sa;
            // Camber: the normal tilts by -slope and moves at `rate`.
            w0.push(relative - slope * tangential - rate);
            vt0.push(tangential);
            let (du, dv) = induced(&unit, x, y, self.core2);
            let unit_tangential = du * ca - dv * sa;
            w1.push(du * sa + dv * ca - slope * unit_tangential);
            vt1.push(unit_tangential);
        }
        let a0 = self.coefficients(&w0);
        let a1 = self.coefficients(&w1);
        let circulation = |a: &[f64]| PI * (a[0] + 0.5 * a[1]);
        let shed_so_far: f64 = self.wake.iter().map(|v| v.gamma).sum();
        // Kelvin: sum of wake (ccw) = bound (clockwise), linear in the new one.
        let m = circulation(&a1);
        let gamma_new = (circulation(&a0) - shed_so_far) / (1.0 - m);
        let a: Vec<f64> = a0.iter().zip(&a1).map(|(p, q)| p + gamma_new * q).collect();
        self.wake.push(FreeVortex {
            x: nx,
            y: ny,
            gamma: gamma_new,
        });

        // Bound vortices: the analytic integral of gamma over each panel.
        let m_points = self.theta.len();
        let mut panel_gamma = vec![0.0; m_points];
        for (an, row) in a.iter().zip(self.panel_table.chunks_exact(m_points)) {
            for (g, p) in panel_gamma.iter_mut().zip(row) {
                *g += an * p;
            }
        }
        self.bound = panel_gamma
            .iter()
            .zip(&stations)
            .map(|(&g, &(_, x, y))| FreeVortex { x, y, gamma: -g })
            .collect();

        // Loads from the pressure jump (unsteady Bernoulli) on the bound
        // vortices: N = sum V_t Gamma_j + d/dt sum Gamma_j (1 - x_j),
        // M_LE = -(sum V_t Gamma_j x_j + d/dt sum Gamma_j (1 - x_j^2) / 2),
        // plus the leading-edge suction pi A0^2 along the chord.
        let mut now = LoadIntegrals {
            normal: 0.0,
            moment: 0.0,
            suction: PI * a[0] * a[0],
            q_normal: 0.0,
            q_moment: 0.0,
            deform_quasi: 0.0,
        };
        for (j, (v, &(xb, _, _))) in self.bound.iter().zip(&stations).enumerate() {
            let g = -v.gamma; // clockwise
            let vt = vt0[j] + gamma_new * vt1[j];
            now.normal += vt * g;
            now.moment += vt * g * xb;
            now.q_normal += g * (1.0 - xb);
            now.q_moment += g * 0.5 * (1.0 - xb * xb);
            now.deform_quasi += vt * g * slopes[j].1;
        }
        // Deformation work: -int dp eta_t dx, with the unsteady part of the
        // pressure jump per station, dx_j dPhi_j/dt (Phi: running bound
        // circulation to the station's centre).
        let mut running = Vec::with_capacity(self.bound.len());
        let mut sum = 0.0;
        for v in &self.bound {
            let g = -v.gamma;
            running.push(sum + 0.5 * g);
            sum += g;
        }
        let unsteady_deform: f64 = if self.running_previous.len() == running.len() {
            let dtheta = PI / self.theta.len() as f64;
            running
                .iter()
                .zip(&self.running_previous)
                .zip(self.theta.iter().zip(&slopes))
                .map(|((p, q), (th, &(_, rate)))| 0.5 * th.sin() * dtheta * (p - q) / dt * rate)
                .sum()
        } else {
            0.0
        };
        self.running_previous = running;
        if let Some(prev) = self.loads.replace(now) {
            // The backward differences are the loads at the half step: take
            // the kinematics there too, or the added-mass force (large at
            // high k, in quadrature with the velocity) leaks into the mean
            // power through an O(omega dt) phase error.
            let tm = t - 0.5 * dt;
            let (_, h_dot_m, alpha_m, alpha_dot_m) = self.motion.at(tm);
            let normal = 0.5 * (now.normal + prev.normal) + (now.q_normal - prev.q_normal) / dt;
            let moment_le =
                -(0.5 * (now.moment + prev.moment) + (now.q_moment - prev.q_moment) / dt);
            let suction = 0.5 * (now.suction + prev.suction);
            let (sm, cm) = alpha_m.sin_cos();
            let fx = normal * sm - suction * cm;
            let fy = normal * cm + suction * sm;
            let m_pivot_nose_up = moment_le + pivot * normal;
            let deformation = 0.5 * (now.deform_quasi + prev.deform_quasi) + unsteady_deform;
            let power = -fy * h_dot_m - m_pivot_nose_up * alpha_dot_m - deformation;
            history.time.push(tm);
            history.cl.push(2.0 * fy);
            history.ct.push(-2.0 * fx);
            history.cp.push(2.0 * power);
            history.lesp.push(a[0]);
            history.bound_circulation.push(circulation(&a));
        }

        // Convect the free vortices: the near wake with the velocity induced
        // by everything (the far wake as proxies), the far wake with the
        // freestream. (The new vortex joined the near wake.)
        let velocities: Vec<(f64, f64)> = self.wake[near_from..]
            .iter()
            .map(|p| {
                let (mut u, mut v) = (1.0, 0.0);
                for q in self
                    .bound
                    .iter()
                    .chain(&self.wake[near_from..])
                    .chain(&proxies)
                {
                    let (du, dv) = induced(q, p.x, p.y, self.core2);
                    u += du;
                    v += dv;
                }
                (u, v)
            })
            .collect();
        for p in &mut self.wake[..near_from] {
            p.x += dt;
        }
        for (p, (u, v)) in self.wake[near_from..].iter_mut().zip(velocities) {
            p.x += u * dt;
            p.y += v * dt;
        }
    }
}

/// Cycle means over the last `cycles` whole periods of a periodic history:
/// `(CT, CP, efficiency)`.
pub fn cycle_means(history: &History, period: f64, cycles: usize) -> (f64, f64, f64) {
    cycle_means_until(
        history,
        period,
        cycles,
        *history.time.last().unwrap_or(&0.0),
    )
}

/// [`cycle_means`] over the `cycles` periods ending at time `end` (e.g. one
/// period before the last sample, for a periodicity check).
pub fn cycle_means_until(
    history: &History,
    period: f64,
    cycles: usize,
    end: f64,
) -> (f64, f64, f64) {
    let start = end - period * cycles as f64;
    let (mut ct, mut cp, mut n) = (0.0, 0.0, 0usize);
    for ((t, a), b) in history.time.iter().zip(&history.ct).zip(&history.cp) {
        if *t > start && *t <= end {
            ct += a;
            cp += b;
            n += 1;
        }
    }
    let n = n.max(1) as f64;
    (ct / n, cp / n, ct / cp)
}
