//! 2D unsteady aerodynamics of a wing section (the aerodynamic discipline's
//! analysis): an LDVM-class discrete-vortex method (Ramesh, Gopalarathnam,
//! Granlund, Ol & Edwards 2014, J. Fluid Mech. 751) and the classical
//! results it is validated against.
//!
//! - [`ldvm`]: thin, cambered or deforming sections ([`camber`]) with
//!   leading-edge vortex shedding by the critical LESP, plunge, pitch and
//!   pitch ramps ([`motion`]).
//! - [`panel`]: thick sections (NACA 4-digit or point files, [`naca`]),
//!   rigid or deforming, by an unsteady source/doublet panel method.
//! - [`history`]: load histories and cycle means; [`friction`]: the laminar
//!   skin-friction estimate for net thrust.
//! - [`theory`]: Theodorsen, Garrick and Wagner, the references.
//! - [`viscous`]: laminar Navier–Stokes of the section (`fwav-ns2d`),
//!   the viscous model behind the same case.
//! - [`case`]: one analysis as `fwav aero2d` runs it: the solver chosen by
//!   the section, the last cycle's means and periodicity; or, for a run
//!   without a period, the loads over its second half ([`window`]).
//!
//! Imports: no other room of the crate (a solver room: the 2D models stand
//! alone; pictures of their results are drawn in [`crate::output`]).

pub mod camber;
pub mod case;
pub mod friction;
pub mod history;
pub mod ldvm;
pub mod motion;
pub mod naca;
pub mod panel;
pub mod theory;
pub mod viscous;
pub mod window;
