//! The two links, USB CDC-ACM and UART, served by the same code: bytes in →
//! frame decoder → flight controller → outbox → frames out. Every byte
//! sequence is handled without panicking (the decoder and the flight
//! controller are property-tested on the host).

use embassy_stm32::usart::{BufferedUartRx, BufferedUartTx};
use embassy_stm32::usb::Driver;
use embassy_sync::blocking_mutex::raw::CriticalSectionRawMutex;
use embassy_sync::mutex::Mutex;
use embassy_usb::class::cdc_acm::{Receiver, Sender};
use embedded_io_async::{Read, Write};
use fwav_fc_core::flight::{Handled, LinkId};
use fwav_fc_core::storage::MAX_RECORD_LEN;
use fwav_protocol::{encode_frame, FrameDecoder, Request, MAX_FRAME_LEN};

use crate::shared::{now_us, outbox, with_fc};
use crate::storage::Store;
use crate::watchdog;

/// The flash store, shared by the links' save requests.
pub static STORE: Mutex<CriticalSectionRawMutex, Option<Store>> = Mutex::new(None);

/// The link has gone away (USB unplugged).
pub struct LinkDown;

/// Bytes in.
pub trait ByteRx {
    /// Waits for bytes; `Err` when the link is down.
    async fn read(&mut self, buf: &mut [u8]) -> Result<usize, LinkDown>;
}

/// Bytes out.
pub trait ByteTx {
    /// Sends all of `bytes`; `Err` when the link is down.
    async fn write_all(&mut self, bytes: &[u8]) -> Result<(), LinkDown>;
}

/// Reads and handles requests until the link goes down.
pub async fn receive(link: LinkId, rx: &mut impl ByteRx) {
    let mut decoder = FrameDecoder::new();
    let mut chunk = [0u8; 64];
    loop {
        let Ok(n) = rx.read(&mut chunk).await else {
            with_fc(|fc| fc.link_closed(link));
            return;
        };
        for &byte in &chunk[..n] {
            // Dropped frames are counted in the decoder's stats.
            if let Some(Ok(request)) = decoder.push::<Request>(byte) {
                serve(link, request, &decoder).await;
            }
        }
    }
}

async fn serve(link: LinkId, request: Request, decoder: &FrameDecoder) {
    let stats = decoder.stats();
    let Some(handled) = with_fc(|fc| fc.handle(link, request, now_us(), stats)) else {
        return;
    };
    let answer = match handled {
        Handled::Reply(message) => message,
        Handled::Save { seq, record } => {
            let mut bytes = [0u8; MAX_RECORD_LEN];
            let ok = match record.encode(&mut bytes) {
                Ok(n) => save(&bytes[..n]).await,
                Err(_) => false,
            };
            match with_fc(|fc| fc.save_finished(seq, ok)) {
                Some(message) => message,
                None => return,
            }
        }
    };
    outbox(link).send(answer).await;
}

/// Writes a record to flash with the watchdog stretched over the erase.
async fn save(record: &[u8]) -> bool {
    let mut store = STORE.lock().await;
    let Some(store) = store.as_mut() else {
        return false;
    };
    watchdog::set_reload(watchdog::SAVING_COUNTS);
    let ok = store.save(record).await;
    watchdog::set_reload(watchdog::RUNNING_COUNTS);
    ok
}

/// Frames and sends the outbox of `link` for ever.
pub async fn transmit(link: LinkId, tx: &mut impl ByteTx) -> ! {
    let mut frame = [0u8; MAX_FRAME_LEN];
    loop {
        let message = outbox(link).receive().await;
        match encode_frame(&message, &mut frame) {
            // A message for a link that is down is dropped.
            Ok(n) => {
                let _ = tx.write_all(&frame[..n]).await;
            }
            Err(_) => defmt::error!("message does not fit a frame"),
        }
    }
}

/// UART receive half.
pub struct UartRx(pub BufferedUartRx<'static>);
/// UART transmit half.
pub struct UartTx(pub BufferedUartTx<'static>);

impl ByteRx for UartRx {
    async fn read(&mut self, buf: &mut [u8]) -> Result<usize, LinkDown> {
        loop {
            match self.0.read(buf).await {
                Ok(n) => return Ok(n),
                // Framing, noise, overrun: the decoder resynchronizes.
                Err(e) => defmt::warn!("UART: {}", e),
            }
        }
    }
}

impl ByteTx for UartTx {
    async fn write_all(&mut self, bytes: &[u8]) -> Result<(), LinkDown> {
        self.0.write_all(bytes).await.map_err(|_| LinkDown)
    }
}

type UsbDriver = Driver<'static, crate::board::UsbPeripheral>;

/// USB CDC-ACM receive side.
pub struct UsbRx(pub Receiver<'static, UsbDriver>);
/// USB CDC-ACM transmit side.
pub struct UsbTx(pub Sender<'static, UsbDriver>);

impl ByteRx for UsbRx {
    async fn read(&mut self, buf: &mut [u8]) -> Result<usize, LinkDown> {
        self.0.read_packet(buf).await.map_err(|_| LinkDown)
    }
}

impl ByteTx for UsbTx {
    async fn write_all(&mut self, bytes: &[u8]) -> Result<(), LinkDown> {
        let size = usize::from(self.0.max_packet_size());
        for packet in bytes.chunks(size) {
            self.0.write_packet(packet).await.map_err(|_| LinkDown)?;
        }
        if bytes.len() % size == 0 {
            // A full last packet needs a zero-length one to end the transfer.
            self.0.write_packet(&[]).await.map_err(|_| LinkDown)?;
        }
        Ok(())
    }
}

/// Serves the UART link.
#[embassy_executor::task]
pub async fn uart_rx(mut rx: UartRx) {
    loop {
        receive(LinkId::Uart, &mut rx).await;
    }
}

/// Sends the UART outbox.
#[embassy_executor::task]
pub async fn uart_tx(mut tx: UartTx) {
    transmit(LinkId::Uart, &mut tx).await
}

/// Serves the USB link, once per connection.
#[embassy_executor::task]
pub async fn usb_rx(mut rx: UsbRx) {
    loop {
        rx.0.wait_connection().await;
        defmt::info!("USB connected");
        receive(LinkId::Usb, &mut rx).await;
        defmt::info!("USB disconnected");
    }
}

/// Sends the USB outbox.
#[embassy_executor::task]
pub async fn usb_tx(mut tx: UsbTx) {
    transmit(LinkId::Usb, &mut tx).await
}

/// Runs the USB device stack.
#[embassy_executor::task]
pub async fn usb_device(mut device: embassy_usb::UsbDevice<'static, UsbDriver>) {
    device.run().await
}
