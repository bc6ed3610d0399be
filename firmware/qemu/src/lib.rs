//! # fwav-fc-qemu — the flight-controller core on an emulated Cortex-M4F
//!
//! QEMU's `mps2-an386` machine (ARM AN386: a Cortex-M4 with FPU, CMSDK
//! UARTs and timers) runs the code the STM32 runs: `fwav-fc-core`'s
//! `FlightController`, unchanged, compiled for `thumbv7em-none-eabihf`
//! (hardware single-precision floats, `libm`, the no_std panic path), with
//! its link handler on two emulated UARTs (the radio link, and a stand-in
//! for the board's USB link) and its control step on a 10 kHz SysTick
//! interrupt, closing its loop on the plant hil-sim integrates
//! (`fwav-plant`: the same equations and the shipped `actuator/plant.toml`).
//!
//! Two programs:
//! - `fwav-fc-qemu` (`src/main.rs`): the served controller; with
//!   `-serial pty -serial pty` the ordinary `fwav fc`, `fwav upload` and
//!   `fwav monitor` commands talk to it. It reports its measured step cost
//!   and stack high-water mark over semihosting once a simulated second.
//! - `step-cost` (`src/bin/step-cost.rs`): the benchmark: instructions per
//!   control step and per link frame under `-icount shift=0`, printed over
//!   semihosting; QEMU then exits.
//!
//! Modules (built for the microcontroller only): `board` (the machine's
//! memory map, interrupts and clocks), `uart` and `counter` (the CMSDK UART
//! and timer), `vehicle` (the plant and its sensors), `shipped` (the
//! shipped plant and profile as constants), `flash` (the
//! parameter store), `cost` (timing statistics), `stack` (painted-stack
//! high-water mark), `report` and `command_line` (semihosting output and
//! input).
//!
//! Build from the workspace root with `cargo fw-qemu`; run as the README's
//! "Emulated microcontroller" section says. On the host this crate is empty
//! and its programs are stubs that say how to build them.

#![cfg_attr(target_os = "none", no_std)]
#![warn(missing_docs)]

#[cfg(target_os = "none")]
pub mod board;
#[cfg(target_os = "none")]
pub mod command_line;
#[cfg(target_os = "none")]
pub mod cost;
#[cfg(target_os = "none")]
pub mod counter;
#[cfg(target_os = "none")]
pub mod flash;
#[cfg(target_os = "none")]
pub mod report;
#[cfg(target_os = "none")]
#[rustfmt::skip] // generated (tests/tests/firmware_constants.rs)
pub mod shipped;
#[cfg(target_os = "none")]
pub mod stack;
#[cfg(target_os = "none")]
pub mod uart;
#[cfg(target_os = "none")]
pub mod vehicle;

/// What a host build of the programs prints.
pub const HOST_STUB_MESSAGE: &str = "fwav-fc-qemu is firmware for QEMU's mps2-an386 (Cortex-M4F); \
build it with `cargo fw-qemu` (target thumbv7em-none-eabihf) and run it with qemu-system-arm \
(README: \"Emulated microcontroller\").";
