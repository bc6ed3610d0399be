//! 2D unsteady aerodynamics of a wing section (the aerodynamic discipline's
//! analysis): an LDVM-class discrete-vortex method (Ramesh, Gopalarathnam,
//! Granlund, Ol & Edwards 2014, J. Fluid Mech. 751) and the classical
//! results it is validated against.
//!
//! Status: the thin-plate solver with a free trailing-edge wake, plunge and
//! pitch, and impulse-based loads ([`ldvm`]), validated against
//! Theodorsen–Garrick and Wagner ([`theory`]). Leading-edge vortex shedding,
//! deforming and thick sections, skin friction, wake amalgamation and the
//! `fwav aero2d` command are the rest of the aero2d issue.

pub mod ldvm;
pub mod theory;
