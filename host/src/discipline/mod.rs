//! The MDOIS disciplines (seed paper): the aerodynamic discipline, which
//! chooses the flapping kinematics on 2D unsteady analyses of the deforming
//! mid-span section, and (to come) the structural discipline.
//!
//! - [`section`]: one evaluation of the aerodynamic discipline: given
//!   flapping kinematics, the mid-span section's flapping motion and its
//!   deformation from the system analysis, an [`crate::aero2d`] run and its
//!   cycle-mean thrust, power and efficiency.

pub mod kinematic;
pub mod section;
