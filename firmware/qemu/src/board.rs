//! The emulated board: QEMU's `mps2-an386` as QEMU 7.2 models it
//! (`hw/arm/mps2.c`; ARM Application Note AN386): where the peripherals
//! the firmware uses are, their interrupt numbers and clocks.
//!
//! | function | peripheral | address | interrupt |
//! | --- | --- | --- | --- |
//! | the radio link (QEMU's first `-serial`) | CMSDK APB UART0 | `0x4000_4000` | RX 0, TX 1 |
//! | the USB link of the STM32 board (QEMU's second `-serial`) | CMSDK APB UART1 | `0x4000_5000` | RX 2, TX 3 |
//! | free-running counter for cost measurements | CMSDK APB timer 0 | `0x4000_0000` | (8, unused) |
//! | control tick, 10 kHz | SysTick (core clock) | — | exception 15 |
//!
//! Every peripheral is clocked at the board's 25 MHz SYSCLK. QEMU derives
//! these clocks from its virtual clock; under `-icount shift=0` that clock
//! advances one nanosecond per executed instruction, so one count of a
//! 25 MHz clock is 40 instructions.

use cortex_m::interrupt::InterruptNumber;

/// SYSCLK of the MPS2 FPGA images (QEMU's `SYSCLK_FRQ`), Hz: the clock of
/// the core's SysTick, the UARTs and the timers.
pub const SYSCLK_HZ: u32 = 25_000_000;

/// Control rate of the flight controller, Hz: the STM32 binary's
/// (`firmware/stm32/src/board.rs`, `CONTROL_HZ`).
pub const CONTROL_HZ: u32 = 10_000;

/// Control period, µs.
pub const CONTROL_PERIOD_US: u64 = 1_000_000 / CONTROL_HZ as u64;

/// SysTick reload for [`CONTROL_HZ`] on the core clock.
pub const SYSTICK_RELOAD: u32 = SYSCLK_HZ / CONTROL_HZ - 1;

/// Base address of CMSDK APB UART0 (the radio link, `LinkId::Uart`).
pub const UART0_BASE: usize = 0x4000_4000;

/// Base address of CMSDK APB UART1, standing in for the STM32 board's USB
/// CDC-ACM link (`LinkId::Usb`): the core serves two links, and a second
/// client (`fwav monitor`) can watch while another flies.
pub const UART1_BASE: usize = 0x4000_5000;

/// Base address of CMSDK APB timer 0.
pub const TIMER0_BASE: usize = 0x4000_0000;

/// UART baud divider: QEMU ignores the rate (a pty has none) but refuses
/// to transmit with a divider below 16; 25 MHz / 54 ≈ 460 800 baud, the
/// STM32 link's rate.
pub const UART_BAUD_DIVIDER: u32 = 54;

/// The external interrupts the firmware enables (NVIC numbers).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u16)]
pub enum Irq {
    /// UART0 received a byte.
    Uart0Rx = 0,
    /// UART0 can take the next byte to send.
    Uart0Tx = 1,
    /// UART1 received a byte.
    Uart1Rx = 2,
    /// UART1 can take the next byte to send.
    Uart1Tx = 3,
}

// SAFETY: the numbers are the machine's (`hw/arm/mps2.c`: UART0's RX
// interrupt is 0, UART1's 2, TX is RX + 1), below its 32 external
// interrupts.
unsafe impl InterruptNumber for Irq {
    fn number(self) -> u16 {
        self as u16
    }
}

impl Irq {
    /// The interrupt of NVIC number `irqn` (as `DefaultHandler` receives
    /// it), if the firmware uses it.
    pub fn from_number(irqn: i16) -> Option<Irq> {
        match irqn {
            0 => Some(Irq::Uart0Rx),
            1 => Some(Irq::Uart0Tx),
            2 => Some(Irq::Uart1Rx),
            3 => Some(Irq::Uart1Tx),
            _ => None,
        }
    }
}
