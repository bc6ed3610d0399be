//! Geometrically nonlinear transient dynamics: the co-rotational shell
//! ([`super::corotational`]) advanced by the generalized-alpha method in
//! the form of Arnold & Brüls (2007, Multibody Syst. Dyn. 18) for
//! configurations with rotations, Newton iterations every step:
//!
//! - equilibrium at `t_{n+1}`: `M acc_{n+1} + f_int(q_{n+1}) = f_ext(t_{n+1})`;
//! - an algorithmic acceleration `a`:
//!   `(1 - alpha_m) a_{n+1} + alpha_m a_n = (1 - alpha_f) acc_{n+1} + alpha_f acc_n`;
//! - `q_{n+1} = q_n (+) [h v_n + h^2 (1/2 - beta) a_n + h^2 beta a_{n+1}]`,
//!   `v_{n+1} = v_n + h (1 - gamma) a_n + h gamma a_{n+1}`
//!   (`(+)`: translations add, rotations compose with the spin);
//! - the parameters of [`super::dynamics::GeneralizedAlpha`] (second order,
//!   `rho_inf` sets the high-frequency dissipation).
//!
//! Newton's matrix is `K_T + (1 - alpha_m) / ((1 - alpha_f) beta h^2) M`
//! (lumped mass; rotational inertia, `rho t^3 / 12`, treated as for small
//! rotation rates). Prescribed DOFs (a driven root) follow given
//! translations and rotations; the loads may change every step (pressure
//! histories).

use std::sync::Arc;

use nalgebra::{Rotation3, Vector3};

use super::assembly::{self, AssemblyError};
use super::corotational::{Configuration, Corotational};
use super::dynamics::GeneralizedAlpha;
use super::element::NODE_DOFS;
use super::material::Section;
use super::mesh::ShellMesh;
use super::nonlinear::{internal_force, norm, summed_forces, NonlinearError, TangentWorkspace};
use super::structure::Structure;

/// The largest nodal rotation a Newton correction may make, rad.
const MAX_TURN: f64 = 0.2;

/// The fraction of the last residual a kept-factor iteration must reach
/// for the next to keep it too (else the tangent is made afresh there).
const CHORD_RATE: f64 = 0.25;

/// Where the prescribed nodes are at a time: translation from the initial
/// position and rotation, per prescribed node.
pub type Prescribed = Vec<(usize, Vector3<f64>, Rotation3<f64>)>;

/// The state of a nonlinear transient.
#[derive(Clone, Debug)]
pub struct DynamicState {
    /// Time, s.
    pub time: f64,
    /// Configuration.
    pub configuration: Configuration,
    /// Velocities (translational and angular) over all global DOFs.
    pub velocity: Vec<f64>,
    /// True accelerations over all global DOFs.
    pub acceleration: Vec<f64>,
    /// Algorithmic accelerations over all global DOFs.
    pub algorithmic: Vec<f64>,
}

/// A nonlinear transient model.
pub struct NonlinearTransient<'a> {
    mesh: &'a ShellMesh,
    elements: Corotational,
    structure: Arc<Structure>,
    mass: Vec<f64>,
    settings: GeneralizedAlpha,
    /// Newton tolerance: residual norm relative to the largest of the
    /// external, inertial and internal force norms (the frame spin is a
    /// central difference, which puts a floor near 1e-6 under it).
    pub tolerance: f64,
    /// Newton iterations allowed a step.
    pub max_iterations: usize,
    /// A force norm, N, below which the balance's scale does not fall
    /// (0 by default): the largest load of a load history, so that steps
    /// where every force is small (a load brought in from zero) are not
    /// asked for a residual below the internal forces' round-off.
    pub reference_force: f64,
    /// Where Newton starts each step (constant acceleration by default).
    pub predictor: Predictor,
    /// Modified Newton: the relative residual below which the next
    /// iteration keeps the last factorization instead of a fresh tangent,
    /// as long as each such iteration cuts the residual to a quarter of
    /// the last (else the tangent is made afresh at that iterate); when
    /// positive, a step's first iteration also keeps the last step's
    /// factorization (same step length), since the configuration it
    /// starts from is where that factorization was made, to the Newton
    /// tolerance. 0 (default): a fresh tangent every iteration. Used
    /// with [`Self::step_in`], whose workspace carries the factorization
    /// from step to step.
    pub keep_factor_below: f64,
}

/// The first guess of a step's Newton iterations.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Predictor {
    /// The true acceleration of the last step is kept: the textbook
    /// choice, good where the motion is smooth on the step's scale.
    #[default]
    ConstantAcceleration,
    /// The configuration of the last step is kept (velocities and
    /// accelerations then follow from the integrator). The choice for
    /// stiff structures driven slowly against their membrane modes: the
    /// extrapolated motion of a thin shell carries the barely damped
    /// high-frequency part of the last step's velocities and puts internal
    /// forces thousands of times the loads into the first iterate. On the
    /// ESLSO wing's 0/1 layouts (mylar-only regions between carbon) it
    /// took Newton from about 30 iterations a step, halvings included, to
    /// about 6 (the module's tests and the topology response).
    ConstantDisplacement,
}

impl<'a> NonlinearTransient<'a> {
    /// The model; `held` lists the global DOFs that are fixed or
    /// prescribed (every DOF of a prescribed node must be in it).
    pub fn new(
        mesh: &'a ShellMesh,
        sections: &[Section],
        held: &[usize],
        settings: GeneralizedAlpha,
    ) -> Result<Self, NonlinearError> {
        Ok(Self {
            mesh,
            elements: Corotational::new(mesh, sections)?,
            structure: Arc::new(Structure::new(mesh, held)?),
            mass: assembly::lumped_mass(mesh, sections)?,
            settings,
            tolerance: 1e-5,
            max_iterations: 25,
            reference_force: 0.0,
            predictor: Predictor::default(),
            keep_factor_below: 0.0,
        })
    }

    /// At rest, undeformed, at t = 0.
    pub fn rest(&self) -> DynamicState {
        let n = self.mesh.dofs();
        DynamicState {
            time: 0.0,
            configuration: Configuration::initial(self.mesh.nodes.len()),
            velocity: vec![0.0; n],
            acceleration: vec![0.0; n],
            algorithmic: vec![0.0; n],
        }
    }

    /// The lumped mass over the global DOFs (kg, and kg·m² on the
    /// rotations).
    pub fn mass(&self) -> &[f64] {
        &self.mass
    }

    /// Kinetic and strain energy, J.
    pub fn energy(&self, state: &DynamicState) -> (f64, f64) {
        let kinetic = 0.5
            * state
                .velocity
                .iter()
                .zip(&self.mass)
                .map(|(v, m)| m * v * v)
                .sum::<f64>();
        // The energy needs no stress-dependent tangent.
        let strain = self
            .elements
            .material_responses(self.mesh, &state.configuration)
            .iter()
            .map(|r| r.energy)
            .sum();
        (kinetic, strain)
    }

    /// Advances by one step under `load` (global, at the new time) with
    /// the prescribed nodes at `prescribed` (at the new time).
    pub fn step(
        &self,
        state: &mut DynamicState,
        load: &[f64],
        prescribed: &Prescribed,
    ) -> Result<usize, NonlinearError> {
        self.step_with(
            state,
            load,
            prescribed,
            self.settings.dt,
            self.max_iterations,
        )
    }

    /// [`Self::step`] with a step of `h` seconds instead of the settings'
    /// and at most `max_iterations` Newton iterations (the generalized-α
    /// parameters do not depend on the step, so one model serves steps of
    /// any length, e.g. a step retried as two halves). `state` is left as
    /// it was if Newton does not converge.
    pub fn step_with(
        &self,
        state: &mut DynamicState,
        load: &[f64],
        prescribed: &Prescribed,
        h: f64,
        max_iterations: usize,
    ) -> Result<usize, NonlinearError> {
        let mut workspace = self.workspace();
        self.step_in(&mut workspace, state, load, prescribed, h, max_iterations)
    }

    /// Storage for [`Self::step_in`]: element responses, the iteration
    /// matrix and its factorization, kept from one step to the next.
    pub fn workspace(&self) -> TangentWorkspace<'_> {
        TangentWorkspace::new(&self.structure)
    }

    /// [`Self::step_with`] in `workspace` (from [`Self::workspace`] of
    /// this model), which keeps the storage, and with
    /// [`Self::keep_factor_below`] the factorization, for the next step.
    pub fn step_in<'w>(
        &'w self,
        workspace: &mut TangentWorkspace<'w>,
        state: &mut DynamicState,
        load: &[f64],
        prescribed: &Prescribed,
        h: f64,
        max_iterations: usize,
    ) -> Result<usize, NonlinearError> {
        let n = self.mesh.dofs();
        if load.len() != n {
            return Err(AssemblyError::Length {
                got: load.len(),
                expected: n,
            }
            .into());
        }
        let step = AlphaStep::new(&self.settings, h, state.clone());
        let mut iterate = self.predict(&step, prescribed);
        let mut last_relative = f64::NAN;
        let mut last_norm = f64::INFINITY;
        let mut keep =
            self.keep_factor_below > 0.0 && workspace.factor_with_shift(step.shift).is_some();
        for iteration in 1..=max_iterations {
            let acc = step.acceleration(&iterate.algorithmic);
            let balance = self.balance(workspace, &iterate.configuration, &acc, load, keep);
            last_relative = balance.norm / balance.scale;
            if balance.norm <= self.tolerance * balance.scale {
                step.accept(state, iterate, acc);
                return Ok(iteration);
            }
            // A kept factorization that did not cut the residual enough
            // (the step's first iteration always goes on it): a fresh
            // tangent at this iterate.
            if keep && iteration > 1 && balance.norm > CHORD_RATE * last_norm {
                keep = false;
                self.elements.responses_into(
                    self.mesh,
                    &iterate.configuration,
                    &mut workspace.responses,
                );
            }
            last_norm = balance.norm;
            self.correct(workspace, &step, keep, &balance.free, &mut iterate)?;
            // Near the solution the next iteration keeps this factor.
            keep = last_relative < self.keep_factor_below;
        }
        Err(NonlinearError::StepNoConvergence {
            step: (state.time / h).round() as usize + 1,
            time: state.time + h,
            iterations: max_iterations,
            residual: last_relative,
        })
    }

    /// Where Newton starts the step: the predictor's algorithmic
    /// accelerations, with the prescribed nodes' the ones that reach their
    /// prescribed places, and the configuration they give.
    fn predict(&self, step: &AlphaStep, prescribed: &Prescribed) -> Iterate {
        let (am, af, beta, h) = (step.am, step.af, step.beta, step.h);
        let old = &step.old;
        let n = self.mesh.dofs();
        let mut a_new: Vec<f64> = match self.predictor {
            // a_{n+1} from acc_n (acc_{n+1} = acc_n).
            Predictor::ConstantAcceleration => (0..n)
                .map(|i| {
                    ((1.0 - af) * old.acceleration[i] + af * old.acceleration[i]
                        - am * old.algorithmic[i])
                        / (1.0 - am)
                })
                .collect(),
            // The a_{n+1} that makes the increment vanish.
            Predictor::ConstantDisplacement => (0..n)
                .map(|i| -(old.velocity[i] + h * (0.5 - beta) * old.algorithmic[i]) / (h * beta))
                .collect(),
        };
        // Prescribed nodes: their algorithmic acceleration is the one that
        // reaches the prescribed place.
        for &(node, translation, rotation) in prescribed {
            let step_translation = translation - old.configuration.displacement[node];
            let step_rotation =
                (rotation * old.configuration.rotation[node].inverse()).scaled_axis();
            for c in 0..3 {
                for (dof, moved) in [
                    (NODE_DOFS * node + c, step_translation[c]),
                    (NODE_DOFS * node + 3 + c, step_rotation[c]),
                ] {
                    a_new[dof] = (moved
                        - h * old.velocity[dof]
                        - h * h * (0.5 - beta) * old.algorithmic[dof])
                        / (beta * h * h);
                }
            }
        }
        let mut configuration = old.configuration.clone();
        configuration.update(&step.increment(&a_new));
        for &(node, translation, rotation) in prescribed {
            configuration.displacement[node] = translation;
            configuration.rotation[node] = rotation;
        }
        Iterate {
            configuration,
            algorithmic: a_new,
        }
    }

    /// The out-of-balance force of `configuration` moving with the true
    /// accelerations `acc` under `load`, over the free DOFs, its norm and
    /// the scale it is measured against. With a `kept` factorization only
    /// the element forces are computed, else the full element responses
    /// (into `workspace`).
    fn balance(
        &self,
        workspace: &mut TangentWorkspace<'_>,
        configuration: &Configuration,
        acc: &[f64],
        load: &[f64],
        kept: bool,
    ) -> Balance {
        let n = self.mesh.dofs();
        let map = self.structure.map();
        let internal = if kept {
            self.elements
                .forces_into(self.mesh, configuration, &mut workspace.forces);
            summed_forces(self.mesh, workspace.forces.iter())
        } else {
            self.elements
                .responses_into(self.mesh, configuration, &mut workspace.responses);
            internal_force(self.mesh, &workspace.responses)
        };
        let inertia: Vec<f64> = (0..n).map(|i| self.mass[i] * acc[i]).collect();
        let residual: Vec<f64> = (0..n).map(|i| load[i] - inertia[i] - internal[i]).collect();
        let free = map.restrict(&residual);
        let out_of_balance = norm(&free);
        // Relative to the largest of the forces in balance.
        let scale = norm(&map.restrict(load))
            .max(norm(&map.restrict(&inertia)))
            .max(norm(&map.restrict(&internal)))
            .max(self.reference_force)
            .max(f64::MIN_POSITIVE);
        Balance {
            free,
            norm: out_of_balance,
            scale,
        }
    }

    /// A Newton correction of `iterate` against the out-of-balance force
    /// `free`: on the `keep`-t factorization of the iteration matrix, or a
    /// fresh one.
    fn correct<'w>(
        &'w self,
        workspace: &mut TangentWorkspace<'w>,
        step: &AlphaStep,
        keep: bool,
        free: &[f64],
        iterate: &mut Iterate,
    ) -> Result<(), NonlinearError> {
        let (shift, beta, h) = (step.shift, step.beta, step.h);
        let map = self.structure.map();
        let factor = match workspace.factor_with_shift(shift).filter(|_| keep) {
            Some(factor) => factor,
            None => {
                let inertia_diagonal: Vec<f64> =
                    map.restrict(&self.mass).iter().map(|m| shift * m).collect();
                workspace.factor_shifted(shift, &inertia_diagonal, || {
                    self.elements
                        .material_responses(self.mesh, &iterate.configuration)
                })?
            }
        };
        let mut dq_global = factor.solve(&[map.expand(free)])?;
        // A Newton correction that turns some node by more than
        // MAX_TURN is shortened to it: far from the solution (a thin
        // flap snapping) the full correction overshoots into
        // configurations the co-rotational frames cannot follow.
        let turn = dq_global
            .chunks_exact(NODE_DOFS)
            .map(|d| Vector3::new(d[3], d[4], d[5]).norm())
            .fold(0.0f64, f64::max);
        if turn > MAX_TURN {
            let cut = MAX_TURN / turn;
            dq_global.iter_mut().for_each(|d| *d *= cut);
        }
        iterate.configuration.update(&dq_global);
        for (i, (a, dq)) in iterate.algorithmic.iter_mut().zip(&dq_global).enumerate() {
            if map.free(i).is_some() {
                *a += dq / (beta * h * h);
            }
        }
        Ok(())
    }
}

/// One step of the generalized-alpha integrator: its parameters, length
/// and the state it starts from.
struct AlphaStep {
    am: f64,
    af: f64,
    gamma: f64,
    beta: f64,
    /// Step length, s.
    h: f64,
    /// The iteration matrix's inertia shift, d acc / d a over
    /// `beta h^2`, s^-2.
    shift: f64,
    /// The state at the step's start.
    old: DynamicState,
}

impl AlphaStep {
    /// A step of length `h` from `old`.
    fn new(settings: &GeneralizedAlpha, h: f64, old: DynamicState) -> Self {
        let (am, af, gamma, beta) = settings.parameters();
        // d acc / d a and d q / d a.
        let acc_per_a = (1.0 - am) / (1.0 - af);
        let shift = acc_per_a / (beta * h * h);
        Self {
            am,
            af,
            gamma,
            beta,
            h,
            shift,
            old,
        }
    }

    /// The configuration increment over the step for the algorithmic
    /// accelerations `a_new`.
    fn increment(&self, a_new: &[f64]) -> Vec<f64> {
        let (beta, h, old) = (self.beta, self.h, &self.old);
        (0..a_new.len())
            .map(|i| {
                h * old.velocity[i] + h * h * ((0.5 - beta) * old.algorithmic[i] + beta * a_new[i])
            })
            .collect()
    }

    /// The true accelerations at the step's end for the algorithmic
    /// accelerations `a_new`.
    fn acceleration(&self, a_new: &[f64]) -> Vec<f64> {
        let (am, af, old) = (self.am, self.af, &self.old);
        (0..a_new.len())
            .map(|i| {
                (((1.0 - am) * a_new[i] + am * old.algorithmic[i]) - af * old.acceleration[i])
                    / (1.0 - af)
            })
            .collect()
    }

    /// Ends the step in `state` at the converged `iterate` with the true
    /// accelerations `acc`.
    fn accept(&self, state: &mut DynamicState, iterate: Iterate, acc: Vec<f64>) {
        let (gamma, h, old) = (self.gamma, self.h, &self.old);
        let a_new = iterate.algorithmic;
        state.time += h;
        state.velocity = (0..a_new.len())
            .map(|i| old.velocity[i] + h * ((1.0 - gamma) * old.algorithmic[i] + gamma * a_new[i]))
            .collect();
        state.acceleration = acc;
        state.algorithmic = a_new;
        state.configuration = iterate.configuration;
    }
}

/// A Newton iterate of a step: the configuration and the algorithmic
/// accelerations over all global DOFs.
struct Iterate {
    configuration: Configuration,
    algorithmic: Vec<f64>,
}

/// The out-of-balance force of an iterate.
struct Balance {
    /// Over the free DOFs, N (N m for rotations).
    free: Vec<f64>,
    /// Its norm.
    norm: f64,
    /// The norm it is measured against: the largest of the forces in
    /// balance.
    scale: f64,
}

/// Nodal forces of a pressure per element acting on the deformed surface
/// (a follower load: along each element's current normal, over its
/// current area), global, N.
pub fn follower_pressure_loads(
    mesh: &ShellMesh,
    configuration: &Configuration,
    pressure: &[f64],
) -> Result<Vec<f64>, NonlinearError> {
    let moved = ShellMesh {
        nodes: mesh
            .nodes
            .iter()
            .zip(&configuration.displacement)
            .map(|(x, u)| x + u)
            .collect(),
        elements: mesh.elements.clone(),
    };
    Ok(assembly::pressure_loads(&moved, pressure)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pressure on a plate turned by 90 degrees acts along the turned
    /// normal with the same resultant.
    #[test]
    fn follower_pressure_turns_with_the_surface() {
        let mesh = ShellMesh::rectangle(1.0, 0.5, 2, 1).unwrap();
        let mut c = Configuration::initial(mesh.nodes.len());
        let q = Rotation3::from_axis_angle(&Vector3::y_axis(), std::f64::consts::FRAC_PI_2);
        for (n, x) in mesh.nodes.iter().enumerate() {
            c.displacement[n] = q * x - x;
        }
        let f = follower_pressure_loads(&mesh, &c, &[2.0, 2.0]).unwrap();
        let total = f
            .chunks_exact(6)
            .fold(Vector3::zeros(), |s, d| s + Vector3::new(d[0], d[1], d[2]));
        let expected = q * Vector3::new(0.0, 0.0, 2.0 * 0.5);
        assert!((total - expected).norm() < 1e-12, "{total}");
    }
}
