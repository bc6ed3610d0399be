//! State shared between the control loop (high-priority executor) and the
//! link tasks: the flight controller behind a critical-section mutex (held
//! for microseconds), and one outbox of messages per link.

use core::cell::RefCell;

use embassy_sync::blocking_mutex::raw::CriticalSectionRawMutex;
use embassy_sync::blocking_mutex::Mutex;
use embassy_sync::channel::Channel;
use fwav_fc_core::flight::{FlightController, LinkId};
use fwav_protocol::DeviceMessage;

/// The flight controller; `None` only before `main` installs it.
pub static FC: Mutex<CriticalSectionRawMutex, RefCell<Option<FlightController>>> =
    Mutex::new(RefCell::new(None));

/// Messages waiting to be framed and sent, per link (responses and telemetry).
pub type Outbox = Channel<CriticalSectionRawMutex, DeviceMessage, 4>;

/// USB outbox.
pub static USB_OUT: Outbox = Channel::new();
/// UART outbox.
pub static UART_OUT: Outbox = Channel::new();

/// The outbox of `link`.
pub fn outbox(link: LinkId) -> &'static Outbox {
    match link {
        LinkId::Usb => &USB_OUT,
        LinkId::Uart => &UART_OUT,
    }
}

/// Runs `f` on the flight controller (None before it is installed).
pub fn with_fc<R>(f: impl FnOnce(&mut FlightController) -> R) -> Option<R> {
    FC.lock(|cell| cell.borrow_mut().as_mut().map(f))
}

/// Microseconds since boot.
pub fn now_us() -> u64 {
    embassy_time::Instant::now().as_micros()
}
