//! The MDOIS system analysis: the flexible flapping wing in its flight
//! condition, an unsteady vortex lattice ([`crate::uvlm`]) strongly coupled
//! to the two-layer shell model ([`crate::shell`]) of the wing.
//!
//! The paper's system analysis is a 3D Navier–Stokes fluid–structure
//! simulation (ADINA); fwav replaces it with a potential-flow lattice on
//! the deforming mid-surface and the shell in the flapping frame, and hands
//! on what the disciplines need: the mid-span section's deformation history
//! (aerodynamic discipline, [`crate::aero2d`]), the pressure history on the
//! shell elements (structural discipline), and the wing's thrust, power and
//! efficiency.
//!
//! - [`kinematics`]: the flapping motion of the root (the design variables).
//! - [`model`]: the wing (planform, mesh, two-layer sections) and the
//!   flight condition.
//! - [`interface`]: the lattice on the shell mesh, conservative transfer.
//! - [`floating_frame`]: the shell's elastic dynamics in the flapping frame.
//! - [`analysis`]: the coupled time stepping, results.
//! - [`last_cycle`]: what the result says about its last cycle (tip
//!   deflection, drive power, coupling effort).
//! - [`handoff`]: the section and pressure histories as the disciplines'
//!   input files, one versioned type each.
//!
//! Imports: [`crate::uvlm`] and [`crate::shell`] (the two halves it couples)
//! and the file helpers (`files`, `file_format`); never the configuration,
//! the disciplines, the design driver or [`crate::output`].

pub mod analysis;
pub mod floating_frame;
pub mod handoff;
pub mod interface;
pub mod kinematics;
pub mod last_cycle;
pub mod model;
mod relaxation;

pub use analysis::{
    run, CycleMeans, Snapshot, StepRecord, SystemError, SystemResult, SystemSettings,
};
pub use kinematics::{FlappingKinematics, RootMotion};
pub use model::{FlightCondition, WingModel};
