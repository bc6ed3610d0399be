//! The sparsity structure of a mesh's stiffness over its free DOFs, built
//! once per mesh and support: the compressed-column pattern (6 x 6 blocks
//! of every pair of nodes sharing an element), where each element entry
//! lands in it, and faer's symbolic Cholesky analysis (fill-reducing
//! ordering and elimination tree). Assembling and factorizing a new
//! stiffness on it (new densities, a new tangent) is then value-only work.

use std::collections::BTreeSet;

use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use faer::Side;
use rayon::prelude::*;

use super::assembly::{element_dofs, AssemblyError, DofMap};
use super::element::{self, ElementMatrix};
use super::material::Section;
use super::mesh::ShellMesh;

/// Marks an element entry on a fixed DOF.
const FIXED: u32 = u32::MAX;

/// Pattern, scatter map and symbolic factorization of one mesh + support.
pub struct Structure {
    map: DofMap,
    pattern: SymbolicSparseColMat<usize>,
    /// For element `e`, entry `(a, b)` goes to value `scatter[576 e + 24 a + b]`.
    scatter: Vec<u32>,
    symbolic: SymbolicLlt<usize>,
    elements: usize,
}

impl Structure {
    /// Builds the structure of `mesh` with the global DOFs in `fixed` held.
    /// Cost: `O(nnz log(row length))` plus faer's ordering.
    pub fn new(mesh: &ShellMesh, fixed: &[usize]) -> Result<Self, AssemblyError> {
        let map = DofMap::new(mesh.dofs(), fixed)?;
        let mut neighbours = vec![BTreeSet::new(); mesh.nodes.len()];
        for corners in &mesh.elements {
            for &a in corners {
                neighbours[a].extend(corners.iter().copied());
            }
        }
        let n = map.free_count();
        let mut col_ptr = Vec::with_capacity(n + 1);
        let mut row_idx = Vec::new();
        col_ptr.push(0);
        for (node, near) in neighbours.iter().enumerate() {
            for c in 0..6 {
                if map.free(6 * node + c).is_none() {
                    continue;
                }
                for &m in near {
                    row_idx.extend((0..6).filter_map(|d| map.free(6 * m + d)));
                }
                col_ptr.push(row_idx.len());
            }
        }
        let mut scatter = vec![FIXED; 576 * mesh.elements.len()];
        scatter
            .par_chunks_mut(576)
            .enumerate()
            .for_each(|(e, out)| {
                let free = element_dofs(mesh, e).map(|g| map.free(g));
                for (b, fb) in free.iter().enumerate() {
                    let Some(fb) = fb else { continue };
                    let rows = &row_idx[col_ptr[*fb]..col_ptr[fb + 1]];
                    for (a, fa) in free.iter().enumerate() {
                        if let Some(fa) = fa {
                            // Present by construction (a and b share this element).
                            if let Ok(k) = rows.binary_search(fa) {
                                out[24 * a + b] = (col_ptr[*fb] + k) as u32;
                            }
                        }
                    }
                }
            });
        if row_idx.len() >= FIXED as usize {
            return Err(AssemblyError::Sparse(format!(
                "{} stiffness entries exceed the 32-bit scatter map",
                row_idx.len()
            )));
        }
        let pattern = SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx);
        let symbolic = SymbolicLlt::try_new(pattern.as_ref(), Side::Lower)
            .map_err(|e| AssemblyError::Sparse(format!("{e:?}")))?;
        Ok(Self {
            map,
            pattern,
            scatter,
            symbolic,
            elements: mesh.elements.len(),
        })
    }

    /// The DOF map.
    pub fn map(&self) -> &DofMap {
        &self.map
    }

    /// Sums element matrices (one per element, global axes) into the
    /// pattern.
    pub fn assemble(
        &self,
        matrices: &[ElementMatrix],
    ) -> Result<SparseColMat<usize, f64>, AssemblyError> {
        if matrices.len() != self.elements {
            return Err(AssemblyError::Sections {
                sections: matrices.len(),
                elements: self.elements,
            });
        }
        let mut values = vec![0.0; self.pattern.row_idx().len()];
        for (k, positions) in matrices.iter().zip(self.scatter.chunks_exact(576)) {
            for a in 0..24 {
                for b in 0..24 {
                    let p = positions[24 * a + b];
                    if p != FIXED {
                        values[p as usize] += k[(a, b)];
                    }
                }
            }
        }
        Ok(SparseColMat::new(self.pattern.clone(), values))
    }

    /// The linear stiffness of `mesh` with one section per element.
    pub fn stiffness(
        &self,
        mesh: &ShellMesh,
        sections: &[Section],
    ) -> Result<SparseColMat<usize, f64>, AssemblyError> {
        if sections.len() != mesh.elements.len() {
            return Err(AssemblyError::Sections {
                sections: sections.len(),
                elements: mesh.elements.len(),
            });
        }
        let matrices: Vec<ElementMatrix> = (0..mesh.elements.len())
            .into_par_iter()
            .map(|e| element::stiffness(&mesh.corners(e), &sections[e]))
            .collect();
        self.assemble(&matrices)
    }

    /// Numeric Cholesky factorization of a matrix on this structure.
    pub fn factorize(
        &self,
        k: &SparseColMat<usize, f64>,
    ) -> Result<Llt<usize, f64>, AssemblyError> {
        Llt::try_new_with_symbolic(self.symbolic.clone(), k.as_ref(), Side::Lower)
            .map_err(|e| AssemblyError::Singular(format!("{e:?}")))
    }
}
