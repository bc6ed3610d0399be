//! The links' UARTs: CMSDK APB UARTs (ARM DDI0479C; QEMU's
//! `hw/char/cmsdk-apb-uart.c`). One byte of receive buffer and one of
//! transmit buffer; QEMU hands over the next received byte only once the
//! last one has been read, so with the receive interrupt serving it no
//! byte is lost (the host's writes wait in the pty instead).
//!
//! Registers: DATA `0x00`; STATE `0x04` (bit 0 TX full, bit 1 RX full);
//! CTRL `0x08` (bit 0 TX enable, 1 RX enable, 2 TX interrupt, 3 RX
//! interrupt); INTSTATUS/INTCLEAR `0x0C` (bit 0 TX, bit 1 RX; write 1 to
//! clear); BAUDDIV `0x10`.

use crate::board;

const DATA: usize = 0x00;
const STATE: usize = 0x04;
const CTRL: usize = 0x08;
const INTCLEAR: usize = 0x0C;
const BAUDDIV: usize = 0x10;

const STATE_TX_FULL: u32 = 1 << 0;
const STATE_RX_FULL: u32 = 1 << 1;
const CTRL_TX_EN: u32 = 1 << 0;
const CTRL_RX_EN: u32 = 1 << 1;
const CTRL_TX_INTEN: u32 = 1 << 2;
const CTRL_RX_INTEN: u32 = 1 << 3;
const INT_TX: u32 = 1 << 0;
const INT_RX: u32 = 1 << 1;

/// One UART. Its registers are shared between the main loop (sending) and
/// the interrupts (receiving, waking the sender): every method is a single
/// register access or runs with interrupts masked by the caller.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Uart {
    base: usize,
}

/// UART0 (the radio link).
pub const UART0: Uart = Uart {
    base: board::UART0_BASE,
};
/// UART1 (the USB link's stand-in).
pub const UART1: Uart = Uart {
    base: board::UART1_BASE,
};

impl Uart {
    /// Enables transmit and receive with the receive interrupt on.
    pub fn start(&self) {
        self.write(BAUDDIV, board::UART_BAUD_DIVIDER);
        self.write(CTRL, CTRL_TX_EN | CTRL_RX_EN | CTRL_RX_INTEN);
    }

    /// The received byte, if one is waiting (reading it lets QEMU deliver
    /// the next), clearing the receive interrupt.
    pub fn receive(&self) -> Option<u8> {
        self.write(INTCLEAR, INT_RX);
        if self.read(STATE) & STATE_RX_FULL == 0 {
            return None;
        }
        Some(self.read(DATA) as u8)
    }

    /// Sends `byte` if the transmit buffer is free; false if it is full
    /// (the host is not reading and the pty is full).
    pub fn try_send(&self, byte: u8) -> bool {
        if !self.can_send() {
            return false;
        }
        self.write(DATA, u32::from(byte));
        true
    }

    /// The transmit buffer is free.
    pub fn can_send(&self) -> bool {
        self.read(STATE) & STATE_TX_FULL == 0
    }

    /// Asks for the transmit interrupt when the buffer frees (to wake the
    /// sender), or stops asking.
    pub fn wake_when_sendable(&self, on: bool) {
        let enabled = CTRL_TX_EN | CTRL_RX_EN | CTRL_RX_INTEN;
        self.write(CTRL, if on { enabled | CTRL_TX_INTEN } else { enabled });
        self.write(INTCLEAR, INT_TX);
    }

    /// Reads the register at `offset`.
    fn read(&self, offset: usize) -> u32 {
        // SAFETY: an aligned 32-bit register of a UART of the machine
        // (`UART0`, `UART1`). Reading DATA takes the received byte, which
        // only `receive` does.
        unsafe { core::ptr::read_volatile((self.base + offset) as *const u32) }
    }

    /// Writes the register at `offset`.
    fn write(&self, offset: usize, value: u32) {
        // SAFETY: an aligned 32-bit register of a UART of the machine,
        // which only this module touches.
        unsafe { core::ptr::write_volatile((self.base + offset) as *mut u32, value) }
    }
}
