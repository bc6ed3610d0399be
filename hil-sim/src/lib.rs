//! # fwav-hil-sim — the flight controller without hardware
//!
//! hil-sim will simulate the flapping actuator (DC motor, H-bridge, gearbox,
//! torsional spring, wing inertia, blade-element aerodynamic torque, encoder,
//! current sensor) and run the firmware's portable core, `fwav-fc-core`,
//! unchanged, in simulated time behind a pseudo-terminal, so that
//! `fwav upload --port <pty>` talks to it exactly as to a board (hil-sim issue).
//!
//! The invariant it exists to keep: **the code hil-sim runs is the code the
//! microcontroller runs.** It depends on `fwav-fc-core` and never carries a
//! second copy of the controller or of the link handler.
//!
//! Nothing is implemented yet: this crate only fixes the workspace layout.

#![forbid(unsafe_code)]
#![warn(missing_docs)]
