//! The MDOIS disciplines (seed paper): the aerodynamic discipline, which
//! chooses the flapping kinematics on 2D unsteady analyses of the deforming
//! mid-span section, and (to come) the structural discipline.
//!
//! - [`kinematic`]: the discipline: L18, ANOM, RSM + NSGA-II candidates.
//! - [`design_space`]: its variables' levels, the L18 designs over them
//!   and the coded values.
//! - [`cache`]: evaluations keyed by their inputs, reused on a rerun.
//! - [`section`]: one evaluation of the aerodynamic discipline: given
//!   flapping kinematics, the mid-span section's flapping motion and its
//!   deformation from the system analysis, an [`crate::aero2d`] run and its
//!   cycle-mean thrust, power and efficiency.
//! - [`section_model`]: the evaluations' flow model (LDVM or laminar
//!   Navier–Stokes) and what it leaves out of the section.
//!
//! Imports: [`crate::aero2d`] (each evaluation), [`crate::optimize`] (the DOE
//! and optimizers) and the kinematics type of [`crate::aeroelastic`]; never
//! the configuration, the design driver or [`crate::output`].

pub mod cache;
pub mod design_space;
pub mod kinematic;
pub mod section;
pub mod section_model;
