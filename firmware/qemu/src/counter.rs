//! A free-running clock for cost measurements: CMSDK APB timer 0 counting
//! down from `u32::MAX` at [`board::SYSCLK_HZ`], read as counts since it
//! was started (wraps after 171 s, so differences of [`now`] over
//! shorter spans are exact with wrapping arithmetic).
//! Timer 0 is used by nothing else.
//!
//! Under `-icount shift=0` QEMU's virtual clock is the instruction count in
//! nanoseconds, so [`nanoseconds`] of a span is the number of
//! instructions executed in it, to one count (40 instructions).
//!
//! Registers (ARM DDI0479C, CMSDK APB timer): CTRL `0x00` (bit 0 enable),
//! VALUE `0x04` (current count), RELOAD `0x08`.

use crate::board;

const CTRL: usize = 0x00;
const VALUE: usize = 0x04;
const RELOAD: usize = 0x08;
const CTRL_ENABLE: u32 = 1;

/// Nanoseconds per count.
pub const NS_PER_COUNT: u32 = 1_000_000_000 / board::SYSCLK_HZ;

/// Starts timer 0 free-running from `u32::MAX` (at boot, before any
/// [`now`]).
pub fn start() {
    write(RELOAD, u32::MAX);
    write(VALUE, u32::MAX);
    write(CTRL, CTRL_ENABLE);
}

/// Counts since [`start`] (wrapping).
#[inline(always)]
pub fn now() -> u32 {
    u32::MAX - read(VALUE)
}

/// Nanoseconds of virtual time in `counts`.
pub fn nanoseconds(counts: u64) -> u64 {
    counts * u64::from(NS_PER_COUNT)
}

/// Reads timer 0's register at `offset`.
#[inline(always)]
fn read(offset: usize) -> u32 {
    // SAFETY: an aligned 32-bit register of the machine's timer 0
    // (`board::TIMER0_BASE`); reading it has no side effect.
    unsafe { core::ptr::read_volatile((board::TIMER0_BASE + offset) as *const u32) }
}

/// Writes timer 0's register at `offset`.
fn write(offset: usize, value: u32) {
    // SAFETY: an aligned 32-bit register of timer 0, which only this
    // module touches.
    unsafe { core::ptr::write_volatile((board::TIMER0_BASE + offset) as *mut u32, value) }
}
