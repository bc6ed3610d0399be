//! # fwav-fc-stm32 — the fwav flight controller on an STM32F405RG
//!
//! Thin embassy glue around `fwav_fc_core`: clocks, the link UART, and (in
//! the firmware issue) the PWM H-bridge, encoder, current ADC, flash storage
//! and watchdog. All decisions live in the portable core, which hil-sim runs
//! unchanged.
//!
//! Build from the workspace root with `cargo fw` (an alias for
//! `cargo build -p fwav-fc-stm32 --target thumbv7em-none-eabihf --profile fw`);
//! flash with `probe-rs run --chip STM32F405RGTx target/thumbv7em-none-eabihf/fw/fwav-fc-stm32`.
//!
//! On the host this file compiles to a stub that says how to build it, so
//! that `cargo clippy --workspace` covers the package.

#![cfg_attr(target_os = "none", no_std)]
#![cfg_attr(target_os = "none", no_main)]

#[cfg(target_os = "none")]
mod board;
#[cfg(target_os = "none")]
mod link;

#[cfg(not(target_os = "none"))]
fn main() {
    eprintln!(
        "fwav-fc-stm32 is firmware for the STM32F405RG; build it with `cargo fw` \
         (target thumbv7em-none-eabihf)."
    );
}

#[cfg(target_os = "none")]
#[embassy_executor::main]
async fn main(_spawner: embassy_executor::Spawner) {
    use defmt_rtt as _;
    use panic_probe as _;

    let p = embassy_stm32::init(board::clocks());
    defmt::info!(
        "{} up, protocol v{}",
        fwav_fc_core::FIRMWARE_NAME,
        fwav_protocol::PROTOCOL_VERSION
    );
    link::serve(p.USART2, p.PA3, p.PA2).await
}
