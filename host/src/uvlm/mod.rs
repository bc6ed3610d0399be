//! Unsteady vortex-lattice method (UVLM) with vortex rings, for thin
//! deforming lifting surfaces in incompressible potential flow.
//!
//! Method (Katz & Plotkin, *Low-Speed Aerodynamics*, 2nd ed., 2001, §12.3
//! for the vortex-ring lattice, §13.12 for its time stepping):
//!
//! 1. The surface is a quadrilateral lattice ([`lattice`]); every panel
//!    carries a vortex ring whose leading segment lies on the panel's
//!    quarter chord, and the collocation point sits at its three-quarter
//!    chord (the private `rings` module). The last ring row ends a little
//!    behind the trailing edge, at the shed line.
//! 2. Each step, the zero-normal-flow condition at the collocation points
//!    of the (possibly deformed, moving) surface gives a dense linear
//!    system for the ring circulations; the influence matrix is rebuilt
//!    and LU-factored (faer) every solve ([`solver`]).
//! 3. The Kutta condition sheds a wake row carrying the trailing-edge
//!    circulation; the wake rings keep their circulation and their corners
//!    convect with the local velocity (free wake) or the freestream
//!    (frozen, older rows) ([`wake`]).
//! 4. Loads: Kutta–Joukowski forces on the bound segments plus the
//!    unsteady `ρ ∂Φ/∂t` term, reported as normal panel pressures and a
//!    leading-edge suction force per spanwise strip, so that thrust on a
//!    flapping or heaving plate is right ([`loads`]; Simpson, Palacios &
//!    Murua 2013, AIAA J. 51(7)).
//!
//! Induced velocities use the Biot–Savart law of straight segments with a
//! regularised core ([`vortex`]), summed in parallel (rayon). A symmetric
//! pair of wings is modelled by one half and its mirror image about y = 0.
//!
//! Axes: x chordwise (the freestream direction), y spanwise (root to tip),
//! z up. SI units.
//!
//! Validation (tests/integration/uvlm.rs): the sudden start of rectangular wings
//! against Katz & Plotkin's Program 16 (their Fig. 13.34), a heaving
//! large-aspect-ratio plate against Garrick's thrust and Theodorsen's
//! lift, the cost of wake truncation and partial rollup, and convergence
//! in time step and lattice size.
//!
//! Imports: no other room of the crate.

pub mod error;
pub mod lattice;
pub mod loads;
mod rings;
pub mod settings;
pub mod solver;
pub mod vortex;
pub mod wake;

pub use error::UvlmError;
pub use lattice::Lattice;
pub use loads::Solution;
pub use settings::{PotentialRate, TimeDerivative, UvlmSettings};
pub use solver::Uvlm;
pub use wake::WakeSheet;
