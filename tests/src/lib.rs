//! # fwav-e2e — end-to-end tests across the fwav crates
//!
//! The tests in `tests/tests/` drive the real code paths of several crates
//! together: the host's profile file → protocol frames → the flight
//! controller's portable core (`fwav-fc-core`) → reply frames → the host.
//! This library holds what those tests share.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

use fwav_fc_core::flight::{FlightController, Handled, LinkId};
use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::{FrameDecoder, Limits, LinkStats, Request};

/// The device end of an in-process byte link: a frame decoder in front of the
/// firmware core's [`FlightController`], wired as the STM32 binary wires its
/// UART. Saves to flash succeed at once into [`DeviceEnd::flash`].
pub struct DeviceEnd {
    decoder: FrameDecoder,
    /// The flight controller under test.
    pub fc: FlightController,
    /// The last record saved.
    pub flash: Vec<u8>,
}

impl Default for DeviceEnd {
    fn default() -> Self {
        Self {
            decoder: FrameDecoder::new(),
            fc: FlightController::new(Limits::REFERENCE_FWAV),
            flash: Vec::new(),
        }
    }
}

impl DeviceEnd {
    /// Takes bytes from the wire at `now_us`, returns the bytes the device
    /// sends back.
    pub fn exchange(&mut self, bytes: &[u8], now_us: u64) -> Vec<u8> {
        let mut out = Vec::new();
        let requests: Vec<Request> = self.decoder.feed(bytes).filter_map(Result::ok).collect();
        for request in requests {
            let answer = match self
                .fc
                .handle(LinkId::Uart, request, now_us, self.decoder.stats())
            {
                Handled::Reply(message) => message,
                Handled::Save { seq, record } => {
                    let mut buf = vec![0u8; fwav_fc_core::storage::MAX_RECORD_LEN];
                    let ok = match record.encode(&mut buf) {
                        Ok(n) => {
                            self.flash = buf[..n].to_vec();
                            true
                        }
                        Err(_) => false,
                    };
                    self.fc.save_finished(seq, ok)
                }
            };
            out.extend(encode_frame_vec(&answer).expect("device replies fit a frame"));
        }
        out
    }

    /// The device decoder's counters.
    pub fn link_stats(&self) -> LinkStats {
        self.decoder.stats()
    }
}
