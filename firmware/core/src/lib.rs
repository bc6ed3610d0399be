//! # fwav-fc-core — the portable core of the fwav flight controller
//!
//! `no_std`, no embassy, no PAC: this crate is the controller logic that runs
//! on the STM32 (`firmware/stm32` binds it to timers, UART, ADC and flash) and,
//! unchanged, inside hil-sim in simulated time. There is no second copy of it
//! anywhere: hil-sim testing this crate *is* testing the firmware.
//!
//! What lives here: the link [`session`] (the handshake gate every command
//! passes through), the [`flight`] controller that owns the link handler,
//! the arm/start state machine and the failsafes (link loss, encoder,
//! over-current); the profile's [`reference`](mod@reference) generator; the flapping
//! [`controller`] (angle and current loops) and the rate [`estimator`];
//! telemetry summaries ([`monitor`]); the device [`params`]; and the
//! [`storage`] record of profile and parameters; single-precision
//! [`trig`] for the control step. It may import only
//! `fwav-protocol` and no_std crates: no embassy, no PAC, no std.

#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod controller;
pub mod estimator;
pub mod flight;
pub mod monitor;
pub mod params;
pub mod reference;
pub mod session;
pub mod storage;
pub mod trig;

/// Firmware name and version reported in the handshake.
pub const FIRMWARE_NAME: &str = concat!("fwav-fc ", env!("CARGO_PKG_VERSION"));
