//! The wing's structure in the flapping (floating) frame: small elastic
//! displacements of the shell measured in axes that turn with the root,
//! under the aerodynamic loads and the frame's inertial loads.
//!
//! In the body frame a material point at `p = X + u` accelerates, seen from
//! the ground, by `R (u'' + alpha x p + Omega x (Omega x p) + 2 Omega x
//! u')`; moving the frame terms to the right gives the linear shell
//! equations of [`crate::shell::dynamics`] with the inertial body forces
//! `-m (alpha x p + Omega x (Omega x p) + 2 Omega x u')` on every node
//! (lumped translational masses). The terms that depend on `u` and `u'`
//! are evaluated at the current coupling iterate, so they converge with
//! the fluid–structure sub-iterations. This is the standard floating-frame
//! model of flexible multibody dynamics (Shabana, *Dynamics of Multibody
//! Systems*, ch. 5) for a wing whose elastic displacements stay small
//! against its size while the rigid flapping rotation is large; unlike the
//! co-rotational solver of [`crate::shell::nonlinear_dynamics`] it keeps one
//! factorization for the whole run, which is what makes a coupled analysis
//! of the paper's 2 x 6760-element mesh take seconds per cycle. The
//! geometric stiffening of the rotation (centrifugal stiffening, of order
//! `(Omega / omega_1)^2` of the stiffness) is left out.

use nalgebra::Vector3;

use crate::shell::assembly::{self, DofMap};
use faer::linalg::solvers::Solve;
use faer::Mat;

use crate::shell::dynamics::{add_diagonal, DynamicsError, GeneralizedAlpha, State, Transient};
use crate::shell::material::Section;
use crate::shell::mesh::ShellMesh;

use super::kinematics::RootMotion;

/// A linear shell model of the wing in the flapping frame.
pub struct FloatingFrameWing {
    transient: Transient,
    nodes: Vec<Vector3<f64>>,
    node_mass: Vec<f64>,
    map: DofMap,
    alpha_f: f64,
}

impl FloatingFrameWing {
    /// Builds and factorizes the model: `fixed` are the held DOFs (the
    /// root attachment, fixed in the flapping frame).
    pub fn new(
        mesh: &ShellMesh,
        sections: &[Section],
        fixed: &[usize],
        settings: GeneralizedAlpha,
    ) -> Result<Self, DynamicsError> {
        let transient = Transient::new(mesh, sections, fixed, settings)?;
        let lumped = assembly::lumped_mass(mesh, sections)?;
        let node_mass = (0..mesh.nodes.len()).map(|n| lumped[6 * n]).collect();
        let map = transient.model().map().clone();
        Ok(Self {
            transient,
            nodes: mesh.nodes.clone(),
            node_mass,
            map,
            alpha_f: settings.parameters().1,
        })
    }

    /// The DOF map (global 6-DOF vectors ↔ free DOFs).
    pub fn map(&self) -> &DofMap {
        &self.map
    }

    /// Mass of the wing, kg.
    pub fn mass(&self) -> f64 {
        self.node_mass.iter().sum()
    }

    /// The state at rest, undeformed, with the initial acceleration that
    /// balances `load` (global 6-DOF vector, N) at t = 0.
    pub fn start(&self, load: &[f64]) -> State {
        let f = self.map.restrict(load);
        self.transient.start(vec![0.0; f.len()], &f)
    }

    /// A starting state close to the periodic response, so the start-up
    /// vibration the analysis must outlast is small: at rest relative to
    /// the frame and deflected by `(K - omega^2 M)^-1 f0`, the steady
    /// harmonic response at the flapping frequency `omega` (rad/s) to the
    /// load `f0` (global 6-DOF vector, N, body axes: the inertial loads at
    /// t = 0, the top of the stroke, where the harmonic response has zero
    /// velocity). When `omega` is above the wing's first natural frequency
    /// that matrix is indefinite; the static deflection `K^-1 f0` is used
    /// instead.
    pub fn start_deflected(&self, load: &[f64], omega: f64) -> Result<State, DynamicsError> {
        let f = self.map.restrict(load);
        let model = self.transient.model();
        let mut k = model.stiffness().clone();
        let shift: Vec<f64> = self
            .transient
            .mass()
            .iter()
            .map(|m| -omega * omega * m)
            .collect();
        add_diagonal(&mut k, &shift);
        let u0 = match model.structure().factorize(&k) {
            Ok(factor) => {
                let x = factor.solve(&Mat::from_fn(f.len(), 1, |i, _| f[i]));
                (0..f.len()).map(|i| x[(i, 0)]).collect()
            }
            Err(_) => self
                .map
                .restrict(&model.solve(std::slice::from_ref(&load.to_vec()))?.remove(0)),
        };
        Ok(self.transient.start(u0, &f))
    }

    /// The frame's inertial loads on the nodes (global 6-DOF vector, N,
    /// body axes) for the body-frame translations `u` and velocities `v`
    /// of every node.
    pub fn inertial_loads(
        &self,
        motion: &RootMotion,
        u: &[Vector3<f64>],
        v: &[Vector3<f64>],
    ) -> Vec<f64> {
        let mut f = vec![0.0; 6 * self.nodes.len()];
        for (n, x) in self.nodes.iter().enumerate() {
            let a = motion.frame_acceleration(&(x + u[n]), &v[n]);
            for c in 0..3 {
                f[6 * n + c] = -self.node_mass[n] * a[c];
            }
        }
        f
    }

    /// One step from `state` under the loads `previous` (at `t_n`) and
    /// `next` (at `t_{n+1}`), global 6-DOF vectors in body axes; `state` is
    /// left as it was (the coupling repeats a step).
    pub fn step(&self, state: &State, previous: &[f64], next: &[f64]) -> State {
        let af = self.alpha_f;
        let mixed: Vec<f64> = previous
            .iter()
            .zip(next)
            .map(|(p, q)| af * p + (1.0 - af) * q)
            .collect();
        let mut trial = state.clone();
        self.transient.step(&mut trial, &self.map.restrict(&mixed));
        trial
    }

    /// Node translations of a state, body axes, m.
    pub fn translations(&self, state: &State) -> Vec<Vector3<f64>> {
        nodal(&self.map.expand(&state.u))
    }

    /// Node velocities of a state relative to the frame, body axes, m/s.
    pub fn velocities(&self, state: &State) -> Vec<Vector3<f64>> {
        nodal(&self.map.expand(&state.v))
    }

    /// The torque about `axis` (unit, through the root) that the wing's
    /// inertia asks of the drive, N m: `axis . sum m_i p_i x a_i` with the
    /// absolute acceleration `a_i = u_i'' + alpha x p_i + Omega x (Omega x
    /// p_i) + 2 Omega x u_i'` of each node in body axes (the rotation
    /// leaves the axis and the triple product unchanged; the nodes' rotary
    /// inertia is left out).
    pub fn inertial_torque(&self, motion: &RootMotion, state: &State, axis: &Vector3<f64>) -> f64 {
        let u = self.translations(state);
        let v = self.velocities(state);
        let a = nodal(&self.map.expand(&state.a));
        self.nodes
            .iter()
            .enumerate()
            .map(|(n, x)| {
                let p = x + u[n];
                let absolute = a[n] + motion.frame_acceleration(&p, &v[n]);
                self.node_mass[n] * axis.dot(&p.cross(&absolute))
            })
            .sum()
    }

    /// Kinetic (relative to the frame) plus strain energy, J.
    pub fn energy(&self, state: &State) -> f64 {
        self.transient.energy(state)
    }
}

fn nodal(global: &[f64]) -> Vec<Vector3<f64>> {
    global
        .chunks_exact(6)
        .map(|c| Vector3::new(c[0], c[1], c[2]))
        .collect()
}
