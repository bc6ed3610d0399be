//! The serial link: bytes from the UART → frame decoder → session → reply
//! frames back. Every byte sequence is handled without panicking (the decoder
//! and session are property-tested on the host).

use embassy_stm32::usart::{self, BufferedUart};
use embassy_stm32::{bind_interrupts, peripherals, Peri};
use embedded_io_async::{Read, Write};
use fwav_fc_core::session::{Dispatch, Session};
use fwav_protocol::{
    encode_frame, DeviceMessage, FrameDecoder, NackReason, Reply, Request, Response, MAX_FRAME_LEN,
};

bind_interrupts!(struct Irqs {
    USART2 => usart::BufferedInterruptHandler<peripherals::USART2>;
});

/// Link baud rate: fast enough for the telemetry stream, slow enough for
/// common USB-serial adapters and radios.
pub const BAUD: u32 = 460_800;

/// Serves the link forever.
pub async fn serve(
    uart: Peri<'static, peripherals::USART2>,
    rx_pin: Peri<'static, peripherals::PA3>,
    tx_pin: Peri<'static, peripherals::PA2>,
) -> ! {
    let mut tx_buf = [0u8; 1024];
    let mut rx_buf = [0u8; 1024];
    let mut config = usart::Config::default();
    config.baudrate = BAUD;
    let mut uart =
        match BufferedUart::new(uart, rx_pin, tx_pin, &mut tx_buf, &mut rx_buf, Irqs, config) {
            Ok(uart) => uart,
            // A baud rate the clock tree cannot make is a build-time mistake.
            Err(e) => defmt::panic!("link UART configuration: {}", e),
        };

    let mut decoder = FrameDecoder::new();
    let mut session = Session::new();
    let mut chunk = [0u8; 64];
    let mut frame = [0u8; MAX_FRAME_LEN];
    loop {
        let n = match uart.read(&mut chunk).await {
            Ok(n) => n,
            Err(e) => {
                // Framing/noise/overrun: the decoder resynchronizes by itself.
                defmt::warn!("link UART: {}", e);
                continue;
            }
        };
        for received in decoder.feed::<Request>(&chunk[..n]) {
            // A dropped frame is counted in the decoder's LinkStats.
            let Ok(request) = received else { continue };
            let answer = match session.receive(request) {
                Dispatch::Reply(message) => message,
                // The controller proper arrives with the firmware issue.
                Dispatch::Forward { seq, .. } => DeviceMessage::Response(Response {
                    seq,
                    reply: Reply::Nack(NackReason::Unsupported),
                }),
            };
            match encode_frame(&answer, &mut frame) {
                Ok(len) => {
                    if let Err(e) = uart.write_all(&frame[..len]).await {
                        defmt::warn!("link UART write: {}", e);
                    }
                }
                Err(_) => defmt::error!("reply does not fit a frame"),
            }
        }
    }
}
