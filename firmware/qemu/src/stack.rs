//! The stack's high-water mark. cortex-m-rt's `paint-stack` feature fills
//! the whole stack region (`_stack_end` up to `_stack_start`, everything
//! in RAM above the statics) with `0xCCCC_CCCC` before `main`; the deepest
//! word no longer holding the paint marks the most stack ever used.
//! (A word the program wrote with exactly the paint value would hide, at
//! most, that word.)

use cortex_m_rt::STACK_PAINT_VALUE;

extern "C" {
    /// Lowest address of the stack region (cortex-m-rt's linker script).
    static _stack_end: u32;
    /// Top of the stack (the initial stack pointer).
    static _stack_start: u32;
}

/// The stack region's size and deepest use, bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StackUse {
    /// Bytes from the top of the stack to the deepest word written.
    pub used: u32,
    /// Size of the stack region, bytes.
    pub size: u32,
}

/// Bytes of stack in use now (from the top to the stack pointer).
pub fn depth() -> u32 {
    let (_, high) = bounds();
    (high - cortex_m::register::msp::read() as usize) as u32
}

/// Scans the painted region from its low end (cost: one read per unused
/// word, about 30 000 reads for a 128 KiB region).
pub fn high_water() -> StackUse {
    let (low, high) = bounds();
    let mut address = low;
    while address < high {
        // SAFETY: an aligned word inside the stack region cortex-m-rt's
        // linker script reserves (between `_stack_end` and
        // `_stack_start`); volatile, as the program writes it through the
        // stack pointer.
        let word = unsafe { core::ptr::read_volatile(address as *const u32) };
        if word != STACK_PAINT_VALUE {
            break;
        }
        address += 4;
    }
    StackUse {
        used: (high - address) as u32,
        size: (high - low) as u32,
    }
}

/// The stack region's low and high addresses (the linker's symbols'
/// addresses; their contents are never read).
fn bounds() -> (usize, usize) {
    (
        core::ptr::addr_of!(_stack_end) as usize,
        core::ptr::addr_of!(_stack_start) as usize,
    )
}
