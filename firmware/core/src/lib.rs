//! # fwav-fc-core — the portable core of the fwav flight controller
//!
//! `no_std`, no embassy, no PAC: this crate is the controller logic that runs
//! on the STM32 (`firmware/stm32` binds it to timers, UART, ADC and flash) and,
//! unchanged, inside hil-sim in simulated time. There is no second copy of it
//! anywhere: hil-sim testing this crate *is* testing the firmware.
//!
//! Today it holds the link [`session`]: the handshake gate that every command
//! passes through. The reference generator, the flapping controller, the full
//! link handler and the failsafes build on it (firmware issue).

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

/// Firmware name and version reported in the handshake.
pub const FIRMWARE_NAME: &str = concat!("fwav-fc ", env!("CARGO_PKG_VERSION"));
