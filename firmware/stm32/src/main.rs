//! # fwav-fc-stm32 — the fwav flight controller on an STM32F405RG
//!
//! Thin embassy glue around `fwav_fc_core` (the portable controller that
//! hil-sim runs unchanged): the 10 kHz control loop on a high-priority
//! interrupt executor (`control`), the USB CDC-ACM and UART links feeding
//! the same handler (`link`), the H-bridge (`bridge`), sensors
//! (`sensors`), flash storage (`storage`) and the watchdog
//! (`watchdog`). Pins and board constants: `board`.
//!
//! Build from the workspace root with `cargo fw`; flash and watch the defmt
//! log with `cargo fw-run` (probe-rs). On the host this file compiles to a
//! stub that says how to build it, so `cargo clippy --workspace` covers the
//! package.

#![cfg_attr(target_os = "none", no_std)]
#![cfg_attr(target_os = "none", no_main)]

#[cfg(target_os = "none")]
mod board;
#[cfg(target_os = "none")]
mod bridge;
#[cfg(target_os = "none")]
mod control;
#[cfg(target_os = "none")]
mod link;
#[cfg(target_os = "none")]
mod sensors;
#[cfg(target_os = "none")]
mod shared;
#[cfg(target_os = "none")]
mod storage;
#[cfg(target_os = "none")]
mod watchdog;

#[cfg(not(target_os = "none"))]
fn main() {
    eprintln!(
        "fwav-fc-stm32 is firmware for the STM32F405RG; build it with `cargo fw` \
         (target thumbv7em-none-eabihf)."
    );
}

#[cfg(target_os = "none")]
mod firmware {
    use defmt::unwrap;
    use defmt_rtt as _;
    use embassy_executor::{InterruptExecutor, Spawner};
    use embassy_stm32::flash::Flash;
    use embassy_stm32::interrupt::{InterruptExt, Priority};
    use embassy_stm32::pac::interrupt;
    use embassy_stm32::usart::{self, BufferedUart};
    use embassy_stm32::usb;
    use embassy_usb::class::cdc_acm::{CdcAcmClass, State};
    use fwav_fc_core::flight::{FlightController, RestoreError};
    use fwav_fc_core::storage::MAX_RECORD_LEN;
    use fwav_protocol::Limits;
    use panic_probe as _;
    use static_cell::StaticCell;

    use crate::board::{self, Board, Irqs};
    use crate::bridge::HBridge;
    use crate::link::{self, UartRx, UartTx, UsbRx, UsbTx};
    use crate::sensors::{Analog, Encoder};
    use crate::storage::Store;
    use crate::{control, shared, watchdog};

    /// Runs the control loop above everything else but the drivers' own
    /// interrupts; UART5 is unused on this board and serves as its trigger.
    static CONTROL_EXECUTOR: InterruptExecutor = InterruptExecutor::new();

    #[interrupt]
    unsafe fn UART5() {
        // SAFETY: the executor is started on this interrupt in `main` and
        // only ever polled from it.
        unsafe { CONTROL_EXECUTOR.on_interrupt() }
    }

    /// Link UART baud rate: fast enough for the telemetry stream, slow enough
    /// for common USB-serial adapters and radios.
    const BAUD: u32 = 460_800;

    #[embassy_executor::main]
    async fn main(spawner: Spawner) {
        let board = Board::take(embassy_stm32::init(board::clocks()));
        defmt::info!(
            "{} up, protocol v{}",
            fwav_fc_core::FIRMWARE_NAME,
            fwav_protocol::PROTOCOL_VERSION
        );

        // The flight controller, with what flash holds (refused if invalid).
        let mut fc = FlightController::new(Limits::REFERENCE_FWAV);
        let mut store = Store::new(Flash::new(board.flash, Irqs));
        let mut record = [0u8; MAX_RECORD_LEN];
        if let Some(n) = store.load(&mut record).await {
            match fc.restore(&record[..n]) {
                Ok(()) => defmt::info!("restored profile and parameters from flash"),
                // core::fmt would cost ~10 KiB of flash; name the cause instead.
                Err(RestoreError::Storage(_)) => {
                    defmt::warn!("stored state unreadable or from another firmware")
                }
                Err(RestoreError::Profile(_)) => {
                    defmt::warn!("stored profile violates the limits: refused")
                }
            }
        }
        shared::FC.lock(|cell| cell.replace(Some(fc)));
        *link::STORE.lock().await = Some(store);

        // Control loop, bridge off until armed.
        let bridge = HBridge::new(board.bridge);
        let encoder = Encoder::new(board.encoder);
        let analog = Analog::new(board.analog);
        watchdog::start();
        interrupt::UART5.set_priority(Priority::P6);
        let high = CONTROL_EXECUTOR.start(interrupt::UART5);
        high.spawn(unwrap!(control::run(bridge, encoder, analog)));

        // UART link.
        static UART_TX: StaticCell<[u8; 1024]> = StaticCell::new();
        static UART_RX: StaticCell<[u8; 1024]> = StaticCell::new();
        let mut config = usart::Config::default();
        config.baudrate = BAUD;
        let uart = unwrap!(BufferedUart::new(
            board.uart.uart,
            board.uart.rx,
            board.uart.tx,
            UART_TX.init([0; 1024]),
            UART_RX.init([0; 1024]),
            Irqs,
            config,
        ));
        let (tx, rx) = uart.split();
        spawner.spawn(unwrap!(link::uart_rx(UartRx(rx))));
        spawner.spawn(unwrap!(link::uart_tx(UartTx(tx))));

        // USB CDC-ACM link.
        static EP_OUT: StaticCell<[u8; 256]> = StaticCell::new();
        static CONFIG_DESC: StaticCell<[u8; 256]> = StaticCell::new();
        static BOS_DESC: StaticCell<[u8; 256]> = StaticCell::new();
        static CONTROL_BUF: StaticCell<[u8; 64]> = StaticCell::new();
        static CDC_STATE: StaticCell<State> = StaticCell::new();
        let mut otg = usb::Config::default();
        otg.vbus_detection = true; // battery powered: VBUS sensed (board docs)
        let driver = usb::Driver::new_fs(
            board.usb.usb,
            Irqs,
            board.usb.dp,
            board.usb.dm,
            EP_OUT.init([0; 256]),
            otg,
        );
        let mut desc = embassy_usb::Config::new(0x1209, 0x0001);
        desc.manufacturer = Some("fwav");
        desc.product = Some("fwav flight controller");
        desc.serial_number = Some("fwav-fc");
        desc.max_power = 100;
        desc.max_packet_size_0 = 64;
        let mut builder = embassy_usb::Builder::new(
            driver,
            desc,
            CONFIG_DESC.init([0; 256]),
            BOS_DESC.init([0; 256]),
            &mut [],
            CONTROL_BUF.init([0; 64]),
        );
        let class = CdcAcmClass::new(&mut builder, CDC_STATE.init(State::new()), 64);
        let (sender, receiver) = class.split();
        spawner.spawn(unwrap!(link::usb_device(builder.build())));
        spawner.spawn(unwrap!(link::usb_rx(UsbRx(receiver))));
        spawner.spawn(unwrap!(link::usb_tx(UsbTx(sender))));
    }
}
