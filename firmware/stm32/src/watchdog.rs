//! The independent watchdog (IWDG), driven through its registers so that
//! the timeout can change at run time: short while flying, long across a
//! flash erase (which stalls the CPU for 1.3–2.6 s on the F405).
//!
//! The IWDG counts the LSI oscillator, which the datasheet gives as
//! 17–47 kHz (32 kHz typical). With the /64 prescaler one count is 2 ms
//! nominal (1.4–3.8 ms): [`RUNNING_COUNTS`] = 50 is 100 ms nominal and at
//! least 68 ms, far above the 100 µs control period; [`SAVING_COUNTS`] =
//! 4000 is 8 s nominal and at least 5.4 s, above the worst erase.

use embassy_stm32::pac::iwdg::vals::{Key, Pr};
use embassy_stm32::pac::IWDG;

/// Reload value while flying (≈ 100 ms).
pub const RUNNING_COUNTS: u16 = 50;
/// Reload value across a flash save (≈ 8 s).
pub const SAVING_COUNTS: u16 = 4000;

/// Starts the watchdog with the running timeout. Once started it cannot be
/// stopped (hardware rule); only reset.
pub fn start() {
    IWDG.kr().write(|w| w.set_key(Key::START));
    set_reload(RUNNING_COUNTS);
}

/// Changes the timeout; takes effect after the register update completes.
///
/// Runs in a critical section: a pet from the control loop (a higher
/// priority) between the unlock and the writes would re-lock PR/RLR and the
/// new timeout would be silently lost, so a flash erase would then outlast
/// the short timeout. It only runs around a save, while disarmed.
pub fn set_reload(counts: u16) {
    critical_section::with(|_| {
        IWDG.kr().write(|w| w.set_key(Key::ENABLE));
        // A previous update must finish before PR/RLR accept a new value.
        while IWDG.sr().read().pvu() || IWDG.sr().read().rvu() {}
        IWDG.pr().write(|w| w.set_pr(Pr::DIVIDE_BY64));
        IWDG.rlr().write(|w| w.set_rl(counts));
        while IWDG.sr().read().pvu() || IWDG.sr().read().rvu() {}
        pet();
    });
}

/// Reloads the counter (called by the control loop every period).
pub fn pet() {
    IWDG.kr().write(|w| w.set_key(Key::RESET));
}
