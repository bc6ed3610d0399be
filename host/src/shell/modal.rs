//! Natural frequencies and mode shapes: the lowest eigenpairs of
//! `K phi = omega^2 M phi` by subspace iteration (Bathe, Finite Element
//! Procedures, 1996, section 11.6) on the factorized stiffness, with the
//! lumped mass. Each iteration costs one multi-right-hand-side solve with
//! `q = max(2p, p + 8)` vectors and a `q x q` dense eigenproblem.

use faer::linalg::solvers::Solve;
use faer::Mat;
use nalgebra::DMatrix;

use super::assembly::{self, AssemblyError};
use super::linear::LinearStatic;
use super::material::Section;
use super::mesh::ShellMesh;

/// One mode.
#[derive(Clone, Debug, PartialEq)]
pub struct Mode {
    /// Natural frequency, Hz.
    pub frequency: f64,
    /// Mass-normalized shape over all global DOFs (`phi^T M phi = 1`).
    pub shape: Vec<f64>,
}

/// Why a modal analysis failed.
#[derive(Debug, thiserror::Error)]
pub enum ModalError {
    /// Assembly or factorization.
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// More modes asked than free DOFs, or none.
    #[error("{asked} modes asked of a model with {free} free DOFs")]
    Count {
        /// Modes asked.
        asked: usize,
        /// Free DOFs.
        free: usize,
    },
    /// No convergence within the iteration cap.
    #[error("subspace iteration did not converge in {0} iterations")]
    NoConvergence(usize),
    /// A massless DOF (e.g. a node no element touches).
    #[error("free DOF {0} has no mass")]
    Massless(usize),
}

/// The `count` lowest modes of `mesh` with `sections` and the global DOFs
/// in `fixed` held.
pub fn modes(
    mesh: &ShellMesh,
    sections: &[Section],
    fixed: &[usize],
    count: usize,
) -> Result<Vec<Mode>, ModalError> {
    let model = LinearStatic::new(mesh, sections, fixed)?;
    let map = model.map();
    let n = map.free_count();
    if count == 0 || count > n {
        return Err(ModalError::Count {
            asked: count,
            free: n,
        });
    }
    let mass = map.restrict(&assembly::lumped_mass(mesh, sections)?);
    if let Some(i) = mass.iter().position(|&m| m <= 0.0) {
        return Err(ModalError::Massless(i));
    }
    let q = (2 * count).max(count + 8).min(n);
    // Start: the mass diagonal and pseudo-random vectors (a fixed LCG, so
    // runs repeat exactly).
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut x = Mat::from_fn(n, q, |i, j| {
        if j == 0 {
            mass[i]
        } else {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            mass[i] * ((seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5)
        }
    });
    let mut previous = vec![0.0; count];
    const CAP: usize = 200;
    for _ in 0..CAP {
        let mx = Mat::from_fn(n, q, |i, j| mass[i] * x[(i, j)]);
        let y = model.factor_solve(&mx);
        // Reduced matrices: K_r = Y^T K Y = Y^T M X, M_r = Y^T M Y.
        let kr: DMatrix<f64> =
            DMatrix::from_fn(q, q, |a, b| (0..n).map(|i| y[(i, a)] * mx[(i, b)]).sum());
        let mr: DMatrix<f64> = DMatrix::from_fn(q, q, |a, b| {
            (0..n).map(|i| y[(i, a)] * mass[i] * y[(i, b)]).sum()
        });
        let kr = (&kr + kr.transpose()) * 0.5;
        let mr = (&mr + mr.transpose()) * 0.5;
        let l: DMatrix<f64> = nalgebra::Cholesky::new(mr)
            .ok_or(ModalError::NoConvergence(0))?
            .l();
        let l_inv: DMatrix<f64> = l.try_inverse().ok_or(ModalError::NoConvergence(0))?;
        let c = &l_inv * kr * l_inv.transpose();
        let eig = nalgebra::SymmetricEigen::new((&c + c.transpose()) * 0.5);
        let mut order: Vec<usize> = (0..q).collect();
        order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
        let z = l_inv.transpose() * &eig.eigenvectors;
        x = Mat::from_fn(n, q, |i, j| {
            (0..q).map(|a| y[(i, a)] * z[(a, order[j])]).sum()
        });
        let lambda: Vec<f64> = order.iter().map(|&j| eig.eigenvalues[j]).collect();
        let converged = lambda[..count]
            .iter()
            .zip(&previous)
            .all(|(a, b)| (a - b).abs() <= 1e-10 * a.abs());
        previous = lambda[..count].to_vec();
        if converged {
            return Ok((0..count)
                .map(|j| {
                    let free: Vec<f64> = (0..n).map(|i| x[(i, j)]).collect();
                    Mode {
                        frequency: lambda[j].max(0.0).sqrt() / (2.0 * std::f64::consts::PI),
                        shape: map.expand(&free),
                    }
                })
                .collect());
        }
    }
    Err(ModalError::NoConvergence(CAP))
}

impl LinearStatic {
    /// `K^-1 B` over the free DOFs.
    pub(crate) fn factor_solve(&self, b: &Mat<f64>) -> Mat<f64> {
        self.factor().solve(b)
    }
}
