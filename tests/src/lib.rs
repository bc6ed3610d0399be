//! # fwav-e2e — end-to-end tests across the fwav crates
//!
//! The tests in `tests/tests/` drive the real code paths of several crates
//! together: the host's profile file → protocol frames → the flight
//! controller's portable core (`fwav-fc-core`) → reply frames → the host.
//! This library holds what those tests share.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

use fwav_fc_core::session::{Dispatch, Session};
use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::{Command, DeviceMessage, FrameDecoder, LinkStats, Request};

/// The device end of an in-process byte link: the firmware core's frame
/// decoder and session, exactly as the STM32 binary wires them. Forwarded
/// commands are kept for the test to inspect.
#[derive(Default)]
pub struct DeviceEnd {
    decoder: FrameDecoder,
    session: Session,
    /// Commands the session let through to the controller, in order.
    pub forwarded: Vec<(u16, Command)>,
}

impl DeviceEnd {
    /// Takes bytes from the wire, returns the bytes the device sends back.
    /// A forwarded command is answered by `controller`.
    pub fn exchange(
        &mut self,
        bytes: &[u8],
        mut controller: impl FnMut(u16, &Command) -> DeviceMessage,
    ) -> Vec<u8> {
        let mut out = Vec::new();
        let requests: Vec<Request> = self.decoder.feed(bytes).filter_map(Result::ok).collect();
        for request in requests {
            let answer = match self.session.receive(request) {
                Dispatch::Reply(message) => message,
                Dispatch::Forward { seq, command } => {
                    let answer = controller(seq, &command);
                    self.forwarded.push((seq, command));
                    answer
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
