//! Linear transient dynamics by the generalized-alpha method (Chung &
//! Hulbert 1993, J. Appl. Mech. 60): `M a + C v + K u = f(t)` with the
//! lumped mass, Rayleigh damping `C = a_M M + a_K K` and the spectral
//! radius at infinite frequency `rho_inf` choosing the numerical
//! dissipation of unresolved modes (1: none, second order throughout).
//!
//! Chung & Hulbert's convention: the balance holds at `n + 1 - alpha`,
//! `x_{n+1-alpha} = (1 - alpha) x_{n+1} + alpha x_n`, with
//! `alpha_m = (2 rho - 1)/(rho + 1)`, `alpha_f = rho/(rho + 1)`,
//! `gamma = 1/2 - alpha_m + alpha_f`, `beta = (1 - alpha_m + alpha_f)^2 / 4`
//! (`alpha_m = alpha_f = 0` is Newmark's average acceleration). The
//! effective matrix is constant: one factorization, one solve a step.

use std::sync::Arc;

use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::Llt;
use faer::Mat;
use fwav_settings::Shown;

use super::assembly::{self, AssemblyError};
use super::linear::LinearStatic;
use super::material::Section;
use super::mesh::ShellMesh;
use super::structure::Structure;

/// Integration settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GeneralizedAlpha {
    /// Time step, s.
    pub dt: f64,
    /// Spectral radius at infinite frequency, in [0, 1].
    pub rho_inf: f64,
    /// Mass-proportional damping `a_M`, 1/s.
    pub mass_damping: f64,
    /// Stiffness-proportional damping `a_K`, s.
    pub stiffness_damping: f64,
}

impl GeneralizedAlpha {
    /// `(alpha_m, alpha_f, gamma, beta)`.
    pub fn parameters(&self) -> (f64, f64, f64, f64) {
        let r = self.rho_inf;
        let am = (2.0 * r - 1.0) / (r + 1.0);
        let af = r / (r + 1.0);
        let gamma = 0.5 - am + af;
        let beta = 0.25 * (1.0 - am + af).powi(2);
        (am, af, gamma, beta)
    }
}

/// The state at one time.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    /// Time, s.
    pub time: f64,
    /// Displacements over the free DOFs.
    pub u: Vec<f64>,
    /// Velocities over the free DOFs.
    pub v: Vec<f64>,
    /// Accelerations over the free DOFs.
    pub a: Vec<f64>,
}

/// A linear transient model ready to step.
pub struct Transient {
    model: LinearStatic,
    mass: Vec<f64>,
    settings: GeneralizedAlpha,
    effective: Llt<usize, f64>,
}

/// Why the transient model could not be built.
#[derive(Debug, thiserror::Error)]
pub enum DynamicsError {
    /// Assembly or factorization.
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// Bad settings.
    #[error(
        "time step must be positive and rho_inf in [0, 1] (got dt {}, rho_inf {})",
        Shown(*.dt),
        Shown(*.rho)
    )]
    Settings {
        /// Step.
        dt: f64,
        /// Spectral radius.
        rho: f64,
    },
}

impl Transient {
    /// Builds and factorizes `(1 - alpha_m) M + (1 - alpha_f)(gamma dt C + beta dt^2 K)`.
    pub fn new(
        mesh: &ShellMesh,
        sections: &[Section],
        fixed: &[usize],
        settings: GeneralizedAlpha,
    ) -> Result<Self, DynamicsError> {
        let ok = settings.dt > 0.0 && (0.0..=1.0).contains(&settings.rho_inf);
        if !ok {
            return Err(DynamicsError::Settings {
                dt: settings.dt,
                rho: settings.rho_inf,
            });
        }
        let structure = Arc::new(Structure::new(mesh, fixed)?);
        let model = LinearStatic::with_structure(structure.clone(), mesh, sections)?;
        let mass = model
            .map()
            .restrict(&assembly::lumped_mass(mesh, sections)?);
        let (am, af, gamma, beta) = settings.parameters();
        let h = settings.dt;
        let c_k = (1.0 - af) * (beta * h * h + gamma * h * settings.stiffness_damping);
        let c_m = (1.0 - am) + (1.0 - af) * gamma * h * settings.mass_damping;
        let mut k = model.stiffness().clone();
        for v in k.val_mut() {
            *v *= c_k;
        }
        add_diagonal(&mut k, &mass.iter().map(|m| c_m * m).collect::<Vec<_>>());
        let effective = structure.factorize(&k)?;
        Ok(Self {
            model,
            mass,
            settings,
            effective,
        })
    }

    /// The underlying static model (DOF map, stiffness).
    pub fn model(&self) -> &LinearStatic {
        &self.model
    }

    /// Lumped mass over the free DOFs.
    pub fn mass(&self) -> &[f64] {
        &self.mass
    }

    /// A state at rest at `u0` (free DOFs) with the consistent initial
    /// acceleration `M a0 = f(0) - K u0`.
    pub fn start(&self, u0: Vec<f64>, force0: &[f64]) -> State {
        let ku = self.model.apply(&u0);
        let a = force0
            .iter()
            .zip(&ku)
            .zip(&self.mass)
            .map(|((f, k), m)| (f - k) / m)
            .collect();
        State {
            time: 0.0,
            v: vec![0.0; u0.len()],
            u: u0,
            a,
        }
    }

    /// Advances `state` by one step; `force` is the load over the free
    /// DOFs at `t_{n+1-alpha_f}`.
    pub fn step(&self, state: &mut State, force: &[f64]) {
        let (am, af, gamma, beta) = self.settings.parameters();
        let h = self.settings.dt;
        let (a_m, a_k) = (self.settings.mass_damping, self.settings.stiffness_damping);
        let n = state.u.len();
        // Predictors (the parts of u_{n+1}, v_{n+1} known before a_{n+1}).
        let u_pred: Vec<f64> = (0..n)
            .map(|i| state.u[i] + h * state.v[i] + h * h * (0.5 - beta) * state.a[i])
            .collect();
        let v_pred: Vec<f64> = (0..n)
            .map(|i| state.v[i] + h * (1.0 - gamma) * state.a[i])
            .collect();
        let u_mid: Vec<f64> = (0..n)
            .map(|i| (1.0 - af) * u_pred[i] + af * state.u[i])
            .collect();
        let v_mid: Vec<f64> = (0..n)
            .map(|i| (1.0 - af) * v_pred[i] + af * state.v[i])
            .collect();
        // K (u_mid + a_K v_mid) and the mass terms.
        let combined: Vec<f64> = (0..n).map(|i| u_mid[i] + a_k * v_mid[i]).collect();
        let k_terms = self.model.apply(&combined);
        let rhs = Mat::from_fn(n, 1, |i, _| {
            force[i] - k_terms[i] - self.mass[i] * (am * state.a[i] + a_m * v_mid[i])
        });
        let a_new = self.effective.solve(&rhs);
        for i in 0..n {
            let a1 = a_new[(i, 0)];
            state.u[i] = u_pred[i] + h * h * beta * a1;
            state.v[i] = v_pred[i] + h * gamma * a1;
            state.a[i] = a1;
        }
        state.time += h;
    }

    /// Kinetic plus strain energy of a state, J.
    pub fn energy(&self, state: &State) -> f64 {
        let ku = self.model.apply(&state.u);
        let strain: f64 = state.u.iter().zip(&ku).map(|(u, k)| u * k).sum();
        let kinetic: f64 = state.v.iter().zip(&self.mass).map(|(v, m)| m * v * v).sum();
        0.5 * (strain + kinetic)
    }
}

/// Adds `d` to the diagonal of a square sparse matrix whose pattern holds
/// every diagonal entry (a stiffness does).
pub(crate) fn add_diagonal(k: &mut faer::sparse::SparseColMat<usize, f64>, d: &[f64]) {
    let positions: Vec<Option<usize>> = (0..d.len())
        .map(|j| {
            let range = k.as_ref().col_range(j);
            let rows = k.as_ref().row_idx_of_col_raw(j);
            rows.binary_search(&j).ok().map(|p| range.start + p)
        })
        .collect();
    let values = k.val_mut();
    for (j, p) in positions.into_iter().enumerate() {
        if let Some(p) = p {
            values[p] += d[j];
        }
    }
}
