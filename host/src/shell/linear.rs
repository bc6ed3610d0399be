//! Linear statics: one sparse Cholesky factorization of the stiffness over
//! the free DOFs (faer's supernodal `LL^T` with its fill-reducing
//! ordering), then any number of load vectors solved against it.

use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::Llt;
use faer::sparse::SparseColMat;
use faer::Mat;

use std::sync::Arc;

use super::assembly::{AssemblyError, DofMap};
use super::material::Section;
use super::mesh::ShellMesh;
use super::structure::Structure;

/// A factorized linear model.
pub struct LinearStatic {
    structure: Arc<Structure>,
    stiffness: SparseColMat<usize, f64>,
    factor: Llt<usize, f64>,
}

impl LinearStatic {
    /// Assembles and factorizes the stiffness of `mesh` with one section
    /// per element and the global DOFs in `fixed` held at zero.
    pub fn new(
        mesh: &ShellMesh,
        sections: &[Section],
        fixed: &[usize],
    ) -> Result<Self, AssemblyError> {
        Self::with_structure(Arc::new(Structure::new(mesh, fixed)?), mesh, sections)
    }

    /// Assembles and factorizes on an existing structure (same mesh and
    /// supports, new sections): value-only work, the symbolic analysis is
    /// reused.
    pub fn with_structure(
        structure: Arc<Structure>,
        mesh: &ShellMesh,
        sections: &[Section],
    ) -> Result<Self, AssemblyError> {
        let stiffness = structure.stiffness(mesh, sections)?;
        let factor = structure.factorize(&stiffness)?;
        Ok(Self {
            structure,
            stiffness,
            factor,
        })
    }

    /// Assembles element matrices (global axes, one per element) and
    /// factorizes, on an existing structure: for callers that build the
    /// element stiffnesses themselves (topology optimization combines two
    /// kept layer matrices instead of integrating each iteration).
    pub fn from_element_matrices(
        structure: Arc<Structure>,
        matrices: &[super::element::ElementMatrix],
    ) -> Result<Self, AssemblyError> {
        let stiffness = structure.assemble(matrices)?;
        let factor = structure.factorize(&stiffness)?;
        Ok(Self {
            structure,
            stiffness,
            factor,
        })
    }

    /// The structure (pattern and symbolic factorization).
    pub fn structure(&self) -> &Arc<Structure> {
        &self.structure
    }

    /// The DOF map.
    pub fn map(&self) -> &DofMap {
        self.structure.map()
    }

    /// The Cholesky factor of the free stiffness.
    pub(crate) fn factor(&self) -> &Llt<usize, f64> {
        &self.factor
    }

    /// The stiffness over the free DOFs.
    pub fn stiffness(&self) -> &SparseColMat<usize, f64> {
        &self.stiffness
    }

    /// Displacements (global, fixed DOFs zero) under global loads, one
    /// vector per load case, all solved together.
    pub fn solve(&self, loads: &[Vec<f64>]) -> Result<Vec<Vec<f64>>, AssemblyError> {
        let n = self.map().free_count();
        for f in loads {
            if f.len() != self.map().dofs() {
                return Err(AssemblyError::Length {
                    got: f.len(),
                    expected: self.map().dofs(),
                });
            }
        }
        let restricted: Vec<Vec<f64>> = loads.iter().map(|f| self.map().restrict(f)).collect();
        let rhs = Mat::from_fn(n, loads.len(), |i, j| restricted[j][i]);
        let x = self.factor.solve(&rhs);
        Ok((0..loads.len())
            .map(|j| {
                let free: Vec<f64> = (0..n).map(|i| x[(i, j)]).collect();
                self.map().expand(&free)
            })
            .collect())
    }

    /// `K u` over the free DOFs for a free-DOF vector.
    pub fn apply(&self, free: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; free.len()];
        let k = self.stiffness.as_ref();
        for (j, &xj) in free.iter().enumerate() {
            for (i, v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
                out[i] += v * xj;
            }
        }
        out
    }
}
