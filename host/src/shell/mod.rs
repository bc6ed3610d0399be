//! Shell finite elements for the two-layer flapping wing: the structural
//! core of the system analysis and of the topology optimization.
//!
//! - [`material`]: the carbon design layer and mylar skin sharing nodes,
//!   SIMP-scaled.
//! - [`mesh`]: quadrilateral meshes and generators.
//! - [`element`]: the flat MITC4 + QM6 shell element (six DOFs a node).
//! - [`assembly`]: DOF maps, mass, loads, element energies.
//! - [`structure`]: the sparse pattern and symbolic factorization of a
//!   mesh, reused for every new stiffness on it.
//! - [`linear`]: linear statics, one factorization for many load cases.
//! - [`modal`]: lowest natural frequencies and shapes.
//! - [`dynamics`]: linear transient response (generalized-alpha).
//! - [`corotational`], [`nonlinear`]: large displacements and rotations
//!   (co-rotational elements, Newton with load steps), and in time
//!   ([`nonlinear_dynamics`], generalized-alpha with Newton).
//! - [`wing`]: the planform, its mesh, spar and root attachment.
//! - [`import`]: NASTRAN bulk data and Gmsh meshes.
//!
//! SI units throughout (m, N, Pa, kg, s).

pub mod assembly;
pub mod corotational;
pub mod dynamics;
pub mod element;
pub mod import;
pub mod linear;
pub mod material;
pub mod mesh;
pub mod modal;
pub mod nonlinear;
pub mod nonlinear_dynamics;
pub mod ordering;
pub mod structure;
pub mod wing;
