//! Shell finite elements for the two-layer flapping wing: the structural
//! core of the system analysis and of the topology optimization.
//!
//! - [`material`]: the carbon design layer and mylar skin sharing nodes,
//!   SIMP-scaled.
//! - [`mesh`]: quadrilateral meshes and generators.
//! - [`element`]: the flat MITC4 + QM6 shell element (six DOFs a node).
//! - [`assembly`]: global sparse matrices (rayon, faer), DOF maps, loads.
//! - [`linear`]: linear statics, one factorization for many load cases.
//! - [`modal`]: lowest natural frequencies and shapes.
//!
//! SI units throughout (m, N, Pa, kg, s).

pub mod assembly;
pub mod element;
pub mod linear;
pub mod material;
pub mod mesh;
pub mod modal;
