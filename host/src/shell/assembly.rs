//! Global matrices: element matrices computed in parallel (rayon), summed
//! into a sparse matrix over the free degrees of freedom (faer), and the
//! map between global and free DOFs.

use rayon::prelude::*;

use super::element::{self, DOFS, NODE_DOFS};
use super::material::Section;
use super::mesh::ShellMesh;

/// Why an assembly or a solve failed.
#[derive(Debug, thiserror::Error)]
pub enum AssemblyError {
    /// One section per element is needed.
    #[error("{sections} sections for {elements} elements")]
    Sections {
        /// Sections given.
        sections: usize,
        /// Elements in the mesh.
        elements: usize,
    },
    /// A constrained DOF index beyond the mesh.
    #[error("constrained DOF {dof} is beyond the mesh's {dofs} DOFs")]
    Dof {
        /// The bad index.
        dof: usize,
        /// DOFs in the mesh.
        dofs: usize,
    },
    /// A load or displacement vector of the wrong length.
    #[error("vector of length {got}, the model has {expected} DOFs")]
    Length {
        /// Length given.
        got: usize,
        /// DOFs expected.
        expected: usize,
    },
    /// The stiffness is not positive definite: the structure is not held
    /// against some rigid-body motion (or a density is zero everywhere).
    #[error("the stiffness matrix is singular or indefinite: check the supports ({0})")]
    Singular(String),
    /// faer could not build the matrix.
    #[error("sparse matrix: {0}")]
    Sparse(String),
}

/// Which global DOFs are free, and their index among the free ones.
#[derive(Clone, Debug, PartialEq)]
pub struct DofMap {
    free: Vec<Option<usize>>,
    count: usize,
}

impl DofMap {
    /// `fixed` lists the constrained global DOFs (`6 node + component`).
    pub fn new(dofs: usize, fixed: &[usize]) -> Result<Self, AssemblyError> {
        let mut is_fixed = vec![false; dofs];
        for &d in fixed {
            *is_fixed
                .get_mut(d)
                .ok_or(AssemblyError::Dof { dof: d, dofs })? = true;
        }
        let mut count = 0;
        let free = is_fixed
            .iter()
            .map(|&f| {
                (!f).then(|| {
                    count += 1;
                    count - 1
                })
            })
            .collect();
        Ok(Self { free, count })
    }

    /// Free index of global DOF `d`, if free.
    pub fn free(&self, d: usize) -> Option<usize> {
        self.free[d]
    }

    /// Number of free DOFs.
    pub fn free_count(&self) -> usize {
        self.count
    }

    /// Number of global DOFs.
    pub fn dofs(&self) -> usize {
        self.free.len()
    }

    /// The free part of a global vector.
    pub fn restrict(&self, global: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.count];
        for (g, f) in self.free.iter().enumerate() {
            if let Some(f) = f {
                out[*f] = global[g];
            }
        }
        out
    }

    /// A global vector from its free part (fixed DOFs zero).
    pub fn expand(&self, free: &[f64]) -> Vec<f64> {
        self.free
            .iter()
            .map(|f| f.map_or(0.0, |i| free[i]))
            .collect()
    }
}

/// Global DOF indices of element `e`'s 24 local DOFs.
pub fn element_dofs(mesh: &ShellMesh, e: usize) -> [usize; DOFS] {
    let mut d = [0; DOFS];
    for (i, &n) in mesh.elements[e].iter().enumerate() {
        for c in 0..NODE_DOFS {
            d[NODE_DOFS * i + c] = NODE_DOFS * n + c;
        }
    }
    d
}

pub(crate) fn check_sections(mesh: &ShellMesh, sections: &[Section]) -> Result<(), AssemblyError> {
    if sections.len() != mesh.elements.len() {
        return Err(AssemblyError::Sections {
            sections: sections.len(),
            elements: mesh.elements.len(),
        });
    }
    Ok(())
}

/// The lumped (diagonal) mass over all global DOFs, kg and kg m^2.
pub fn lumped_mass(mesh: &ShellMesh, sections: &[Section]) -> Result<Vec<f64>, AssemblyError> {
    check_sections(mesh, sections)?;
    let mut m = vec![0.0; mesh.dofs()];
    for (e, section) in sections.iter().enumerate() {
        let me = element::lumped_mass(&mesh.corners(e), section);
        for (local, g) in element_dofs(mesh, e).into_iter().enumerate() {
            m[g] += me[local];
        }
    }
    Ok(m)
}

/// Consistent nodal forces of a pressure per element (Pa, along each
/// element's normal), global, N.
pub fn pressure_loads(mesh: &ShellMesh, pressure: &[f64]) -> Result<Vec<f64>, AssemblyError> {
    if pressure.len() != mesh.elements.len() {
        return Err(AssemblyError::Length {
            got: pressure.len(),
            expected: mesh.elements.len(),
        });
    }
    let mut f = vec![0.0; mesh.dofs()];
    for (e, &p) in pressure.iter().enumerate() {
        let fe = element::pressure_load(&mesh.corners(e), p);
        for (local, g) in element_dofs(mesh, e).into_iter().enumerate() {
            f[g] += fe[local];
        }
    }
    Ok(f)
}

/// Strain energy of each element for global displacements `u`, J.
pub fn element_strain_energy(
    mesh: &ShellMesh,
    sections: &[Section],
    u: &[f64],
) -> Result<Vec<f64>, AssemblyError> {
    check_sections(mesh, sections)?;
    if u.len() != mesh.dofs() {
        return Err(AssemblyError::Length {
            got: u.len(),
            expected: mesh.dofs(),
        });
    }
    Ok((0..mesh.elements.len())
        .into_par_iter()
        .map(|e| {
            let k = element::stiffness(&mesh.corners(e), &sections[e]);
            let ue = element::ElementVector::from_iterator(element_dofs(mesh, e).map(|g| u[g]));
            0.5 * (ue.transpose() * k * ue)[0]
        })
        .collect())
}
