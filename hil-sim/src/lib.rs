//! # fwav-hil-sim — the flight controller without hardware
//!
//! hil-sim simulates the flapping actuator ([`plant`]: DC motor, H-bridge,
//! battery, gearbox, spring, wing inertia, blade-element aerodynamic torque)
//! and its sensors, and runs the firmware's portable core, `fwav-fc-core`,
//! unchanged, at its control rate in simulated time ([`sim`]). A host reaches
//! it over the same framed link as a board: in process ([`scenario`]) or
//! through a pseudo-terminal ([`serve`]), so `fwav upload --port <pty>`
//! talks to it exactly as to a flight controller. [`feasibility`] runs the
//! plant's equations backwards: can the actuator fly a given frequency and
//! amplitude, and if not, what nearest kinematics it can.
//!
//! The invariant it exists to keep: **the code hil-sim runs is the code the
//! microcontroller runs.** There is no second copy of the controller or of
//! the link handler here.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod config;
pub mod feasibility;
pub mod metrics;
pub mod plant;
pub mod plot;
pub mod scenario;
pub mod serve;
pub mod sim;
