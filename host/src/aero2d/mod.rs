//! 2D unsteady aerodynamics of a wing section (the aerodynamic discipline's
//! analysis): an LDVM-class discrete-vortex method (Ramesh, Gopalarathnam,
//! Granlund, Ol & Edwards 2014, J. Fluid Mech. 751) and the classical
//! results it is validated against.
//!
//! Status: the thin-plate solver with a free trailing-edge wake, plunge and
//! pitch, pressure-jump loads with leading-edge suction and a lumped,
//! freely drifting far wake ([`ldvm`]), validated against
//! Theodorsen–Garrick and Wagner ([`theory`]), behind `fwav aero2d`.
//! Leading-edge vortex shedding (LESP), deforming and thick sections, skin
//! friction and plots are the rest of the aero2d issue.

pub mod camber;
pub mod friction;
pub mod history;
pub mod ldvm;
pub mod motion;
pub mod plot;
pub mod theory;
