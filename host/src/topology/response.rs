//! Step 1 of an ESLSO cycle: the nonlinear dynamic response of the current
//! wing design, root held, under the periodic pressure history (seed
//! paper, Fig. 17 and "Nonlinear dynamic topology optimization using
//! ESLSO"; the paper runs LS-DYNA, here the co-rotational shell of
//! [`crate::shell::nonlinear_dynamics`] with generalized-α).
//!
//! The pressure is a follower load: each step's element pressures act
//! along the element normals of the configuration at the step's start
//! (explicit in the load, so no load stiffness in Newton's matrix; the
//! step is a fraction of a period and the rotation per step small).
//!
//! The run starts at rest, undeformed, and brings the load in over the
//! first period (factor `(1 - cos(pi t / T)) / 2`), then runs `periods - 1`
//! more periods and samples the last. (A static start under the first
//! load fails on the thin mylar-only regions of a 0/1 layout: without the
//! inertia shift their compressed membranes make the tangent indefinite.)
//! A step where Newton fails is halved (pressure interpolated), up to
//! three times. The samples are displacements (translations, m, and
//! rotation vectors, rad, per node, the form of a linear displacement
//! vector) and the strain energies of the co-rotational elements.

use fwav_settings::Shown;
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

use crate::shell::assembly::DofMap;
use crate::shell::corotational::Configuration;
use crate::shell::dynamics::GeneralizedAlpha;
use crate::shell::material::Section;
use crate::shell::mesh::ShellMesh;
use crate::shell::nonlinear::{norm, NonlinearError, TangentWorkspace};
use crate::shell::nonlinear_dynamics::{
    follower_pressure_loads, DynamicState, NonlinearTransient, Predictor,
};

use super::pressure::{PressureError, PressureHistory};

/// How the response is computed and sampled.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ResponseSettings {
    /// Periods run, the first bringing the load in; the last is sampled
    /// (at least 2).
    pub periods: usize,
    /// Sample every this many steps of the last period (the number of ESL
    /// load cases is the steps a period over this).
    pub sample_every: usize,
    /// Generalized-α high-frequency spectral radius. 0.5 by default: with
    /// 0.8 the nonlinear analysis of a layout the second MDOIS cycle
    /// proposed (default wing, 13 Hz and 40° pressure, first mode 20.4
    /// Hz) stopped near the end of its second period, Newton stuck at a
    /// relative residual of 0.92 even with steps down to 1/64 of the
    /// sample step; the mylar-only regions' poorly resolved high modes
    /// need the stronger dissipation. At 0.5 it runs (558 iterations,
    /// peak 18.1 mm); the algorithmic damping of the wing's first modes
    /// (20–30 Hz, 40 steps a 13 Hz period) stays small (Chung & Hulbert
    /// 1993, J. Appl. Mech. 60, 371).
    pub rho_inf: f64,
    /// Newton tolerance, relative to the largest force in balance. Not
    /// below about 1e-4 for aerodynamic loads on a carbon wing: the
    /// co-rotational internal forces carry a round-off floor near 1.5e-5
    /// of those light loads (stiff membranes, forces found as small
    /// differences).
    pub tolerance: f64,
}

impl Default for ResponseSettings {
    /// Two periods, every second step sampled (20 load cases from the
    /// system analysis's 40 steps), ρ∞ = 0.5, Newton to 1e-4.
    fn default() -> Self {
        Self {
            periods: 2,
            sample_every: 2,
            rho_inf: 0.5,
            tolerance: 1e-4,
        }
    }
}

/// The sampled response.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SampledResponse {
    /// Sample times from the start of the sampled period, s.
    pub times: Vec<f64>,
    /// Global 6-DOF displacement vectors per sample (translations m,
    /// rotation vectors rad).
    pub displacements: Vec<Vec<f64>>,
    /// Strain energy of the co-rotational model per sample, J.
    pub strain_energy: Vec<f64>,
    /// Largest nodal translation per sample, m.
    pub peak_displacement: Vec<f64>,
    /// The dynamic loads per sample, `f_ext - M a` (global, N and N·m):
    /// the pressure on the deformed surface less the inertia forces, the
    /// loads the structure carries at that instant (d'Alembert).
    pub dynamic_loads: Vec<Vec<f64>>,
    /// Newton iterations over the whole run (failed tries of halved
    /// steps included).
    pub newton_iterations: usize,
}

impl SampledResponse {
    /// The sum of the sampled strain energies, J: the objective the paper
    /// minimizes ("the summation of the strain energy").
    pub fn total_strain_energy(&self) -> f64 {
        self.strain_energy.iter().sum()
    }
}

/// Why the response could not be computed.
#[derive(Debug, thiserror::Error)]
pub enum ResponseError {
    /// The pressure history does not fit the mesh.
    #[error(transparent)]
    Pressure(#[from] PressureError),
    /// The shell model failed (assembly, singular tangent, no Newton
    /// convergence).
    #[error("nonlinear dynamic analysis")]
    Shell(#[from] NonlinearError),
    /// A setting out of range.
    #[error("response setting {name} = {} is outside {allowed}", Shown(*.value))]
    Setting {
        /// The setting's name (`sample_every`).
        name: &'static str,
        /// Its value.
        value: f64,
        /// The values allowed for this pressure history.
        allowed: String,
    },
}

/// The nonlinear dynamic response of `mesh` with `sections` and the global
/// DOFs `fixed` held, under `pressure` repeated periodically; `progress`
/// is told each step and the total.
///
/// Cost: per step, a few Newton iterations, each an element pass and,
/// away from the solution, a sparse Cholesky factorization of the tangent
/// (near it and at the step's start the last one is kept).
pub fn nonlinear_response(
    mesh: &ShellMesh,
    sections: &[Section],
    fixed: &[usize],
    pressure: &PressureHistory,
    settings: &ResponseSettings,
    mut progress: impl FnMut(usize, usize),
) -> Result<SampledResponse, ResponseError> {
    pressure.check(mesh.elements.len())?;
    let steps = pressure.samples.len();
    let s = settings;
    // (name, value, inside, allowed)
    let checks = [
        (
            "periods",
            s.periods as f64,
            s.periods >= 2,
            ">= 2".to_owned(),
        ),
        (
            "sample_every",
            s.sample_every as f64,
            (1..=steps).contains(&s.sample_every),
            format!("1..={steps}, the {steps} steps of a period of the pressure history"),
        ),
        (
            "rho_inf",
            s.rho_inf,
            (0.0..=1.0).contains(&s.rho_inf),
            "[0, 1]".to_owned(),
        ),
        (
            "tolerance",
            s.tolerance,
            s.tolerance.is_finite() && s.tolerance > 0.0,
            "(0, inf)".to_owned(),
        ),
    ];
    if let Some((name, value, _, allowed)) = checks.into_iter().find(|c| !c.2) {
        return Err(ResponseError::Setting {
            name,
            value,
            allowed,
        });
    }
    let dt = pressure.dt;
    let mut iterations = 0;
    // The largest load of the history sets the force scale of Newton's
    // tolerance where the ramped-in load is still small.
    let initial = Configuration::initial(mesh.nodes.len());
    let map = DofMap::new(mesh.dofs(), fixed).map_err(NonlinearError::from)?;
    let mut reference_force = 0.0f64;
    for sample in &pressure.samples {
        let free = map.restrict(&follower_pressure_loads(mesh, &initial, sample)?);
        reference_force = reference_force.max(norm(&free));
    }
    let stepper = Stepper::new(mesh, sections, fixed, s, reference_force, dt)?;
    let transient = &stepper.transient;
    let mut workspace = transient.workspace();
    let mut state = transient.rest();
    let mut out = SampledResponse {
        times: Vec::new(),
        displacements: Vec::new(),
        strain_energy: Vec::new(),
        peak_displacement: Vec::new(),
        dynamic_loads: Vec::new(),
        newton_iterations: 0,
    };
    let total = s.periods * steps;
    for period in 0..s.periods {
        for (k, sample) in pressure.samples.iter().enumerate() {
            let before = &pressure.samples[(k + steps - 1) % steps];
            // The first period brings the load in smoothly from rest.
            let ramp = |j: usize| {
                if period == 0 {
                    0.5 * (1.0 - (std::f64::consts::PI * j as f64 / steps as f64).cos())
                } else {
                    1.0
                }
            };
            let scaled = |p: &[f64], f: f64| p.iter().map(|v| f * v).collect::<Vec<f64>>();
            iterations += stepper.advance(
                0,
                &mut workspace,
                &mut state,
                &scaled(before, ramp(k)),
                &scaled(sample, ramp(k + 1)),
            )?;
            progress(period * steps + k + 1, total);
            if period + 1 == s.periods && (k + 1) % s.sample_every == 0 {
                let c = &state.configuration;
                let mut u = vec![0.0; mesh.dofs()];
                let mut peak = 0.0f64;
                for (n, (d, r)) in c.displacement.iter().zip(&c.rotation).enumerate() {
                    let w: Vector3<f64> = r.scaled_axis();
                    for a in 0..3 {
                        u[6 * n + a] = d[a];
                        u[6 * n + 3 + a] = w[a];
                    }
                    peak = peak.max(d.norm());
                }
                out.times.push((k + 1) as f64 * dt);
                out.displacements.push(u);
                out.strain_energy.push(transient.energy(&state).1);
                out.peak_displacement.push(peak);
                let mut f = follower_pressure_loads(mesh, c, sample)?;
                for ((f, m), a) in f.iter_mut().zip(transient.mass()).zip(&state.acceleration) {
                    *f -= m * a;
                }
                out.dynamic_loads.push(f);
            }
        }
    }
    out.newton_iterations = iterations;
    Ok(out)
}

/// Steps that halve themselves where Newton fails: a step that does not
/// converge is retried as two steps of half the length with the pressure
/// interpolated linearly, down to `MAX_HALVINGS` halvings, all on one
/// transient model.
struct Stepper<'a> {
    mesh: &'a ShellMesh,
    transient: NonlinearTransient<'a>,
    dt: f64,
}

/// The relative residual below which Newton keeps the last factorization
/// (see [`NonlinearTransient::keep_factor_below`]).
const KEEP_FACTOR_BELOW: f64 = 0.05;

/// The deepest halving: a step of 1/8 of the sample step.
const MAX_HALVINGS: usize = 3;

/// Newton iterations a step before it is halved (at the deepest level,
/// [`ITERATIONS_AT_THE_DEEPEST`]).
const ITERATIONS_BEFORE_HALVING: usize = 15;

/// Newton iterations allowed a step that can no longer be halved.
const ITERATIONS_AT_THE_DEEPEST: usize = 40;

impl<'a> Stepper<'a> {
    fn new(
        mesh: &'a ShellMesh,
        sections: &[Section],
        fixed: &[usize],
        settings: &ResponseSettings,
        reference_force: f64,
        dt: f64,
    ) -> Result<Self, ResponseError> {
        let mut transient = NonlinearTransient::new(
            mesh,
            sections,
            fixed,
            GeneralizedAlpha {
                dt,
                rho_inf: settings.rho_inf,
                mass_damping: 0.0,
                stiffness_damping: 0.0,
            },
        )?;
        transient.tolerance = settings.tolerance;
        transient.reference_force = reference_force;
        // Every iteration with the full tangent (the transient's default):
        // on the default wing's first 0/1 layout, starting each step with
        // the material tangent (switching when an iteration stalls) cost
        // 546 Newton iterations and 69 s against 503 and 65 s, because the
        // first material correction always overshoots into membrane
        // stretch; on the full carbon wing 277 against 275 iterations,
        // 31.8 s against 33.2 s. Each step starts from the last
        // configuration: on the default wing's first 0/1 layout the
        // constant-acceleration start cost about 30 Newton iterations a
        // step (halvings included), this one about 6.
        transient.predictor = Predictor::ConstantDisplacement;
        // Modified Newton near the solution and at each step's start: on
        // the default wing's first 0/1 layout 56.2 s -> 43.5 s (504
        // iterations against 503, same peak and energy), full carbon
        // 33.2 s -> 20.9 s (298 against 275 iterations). Always keeping
        // the factor (a bound of 2) took 668 iterations and 42.4 s; 0.2
        // 505 and 46.2 s.
        transient.keep_factor_below = KEEP_FACTOR_BELOW;
        Ok(Self {
            mesh,
            transient,
            dt,
        })
    }

    /// Advances `state` by one step of level `k` from the pressure `from`
    /// to `to`; returns the Newton iterations spent (failed tries
    /// included).
    fn advance(
        &'a self,
        k: usize,
        workspace: &mut TangentWorkspace<'a>,
        state: &mut DynamicState,
        from: &[f64],
        to: &[f64],
    ) -> Result<usize, ResponseError> {
        let load = follower_pressure_loads(self.mesh, &state.configuration, to)?;
        let cap = if k == MAX_HALVINGS {
            ITERATIONS_AT_THE_DEEPEST
        } else {
            ITERATIONS_BEFORE_HALVING
        };
        let h = self.dt / f64::from(1u32 << k);
        match self
            .transient
            .step_in(workspace, state, &load, &Vec::new(), h, cap)
        {
            Ok(iterations) => Ok(iterations),
            Err(NonlinearError::StepNoConvergence { .. }) if k < MAX_HALVINGS => {
                let middle: Vec<f64> = from.iter().zip(to).map(|(a, b)| 0.5 * (a + b)).collect();
                let first = self.advance(k + 1, workspace, state, from, &middle)?;
                let second = self.advance(k + 1, workspace, state, &middle, to)?;
                Ok(cap + first + second)
            }
            Err(e) => Err(e.into()),
        }
    }
}
