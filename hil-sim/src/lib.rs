//! # fwav-hil-sim — the flight controller without hardware
//!
//! hil-sim integrates the flapping actuator of `fwav-actuator` (its
//! `plant`: DC motor, H-bridge, battery, gearbox, spring, wing inertia,
//! blade-element aerodynamic torque, with the parameters of its `params`)
//! behind a quantized encoder and a noisy current sensor, and runs the
//! firmware's portable core, `fwav-fc-core`, unchanged, at its control rate
//! in simulated time ([`sim`]). A host reaches it over the same framed link
//! as a board: in process, through the host's own link client (`fwav-link`,
//! in [`scenario`]), or through a pseudo-terminal ([`serve`]), so `fwav
//! upload --port <pty>` talks to it exactly as to a flight controller.
//! [`metrics`] judges a run and [`plot`] draws it.
//!
//! It may import `fwav-actuator`, `fwav-link`, `fwav-protocol` and
//! `fwav-fc-core`; nothing imports it but its program and the end-to-end
//! tests (the design library uses `fwav-actuator` directly).
//!
//! The invariant it exists to keep: **the code hil-sim runs is the code the
//! microcontroller runs.** There is no second copy of the controller or of
//! the link handler here.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod metrics;
pub mod plot;
pub mod scenario;
pub mod serve;
pub mod sim;
