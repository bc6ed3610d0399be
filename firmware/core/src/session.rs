//! The link session: nothing but a handshake is served until the host has
//! shown that it speaks exactly this build's protocol.
//!
//! A host of another version gets `DeviceHello { accepted: false }` (whose
//! layout every version can read) and then `Nack(HandshakeRequired)` for every
//! command, so it can never drive the motor by misread bytes.

use fwav_protocol::{
    Command, DeviceHello, DeviceMessage, Hello, NackReason, Reply, Request, Response,
};

use crate::FIRMWARE_NAME;

/// What to do with a received request.
#[derive(Clone, Debug, PartialEq)]
pub enum Dispatch {
    /// Answer with this message; nothing else to do.
    Reply(DeviceMessage),
    /// An accepted command for the controller; answer with `seq`.
    Forward {
        /// The request's sequence number, to echo.
        seq: u16,
        /// The command.
        command: Command,
    },
}

/// Handshake state of one link.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Session {
    open: bool,
}

impl Session {
    /// A session that has not shaken hands yet.
    pub const fn new() -> Self {
        Self { open: false }
    }

    /// True after a handshake with a matching version.
    pub const fn is_open(&self) -> bool {
        self.open
    }

    /// Forgets the handshake (link lost, port reopened): the next host must
    /// shake hands again.
    pub fn close(&mut self) {
        self.open = false;
    }

    /// Handles the session part of `request`: answers handshakes and pings,
    /// refuses everything before a matching handshake, forwards the rest.
    pub fn receive(&mut self, request: Request) -> Dispatch {
        let seq = request.seq;
        let reply = |reply| Dispatch::Reply(DeviceMessage::Response(Response { seq, reply }));
        match request.command {
            Command::Handshake(peer) => {
                self.open = Hello::check_peer(&peer).is_ok();
                let mut firmware = heapless::String::new();
                // FIRMWARE_NAME is shorter than FIRMWARE_NAME_LEN (tested).
                let _ = firmware.push_str(FIRMWARE_NAME);
                Dispatch::Reply(DeviceMessage::Hello(DeviceHello {
                    seq,
                    hello: Hello::THIS,
                    accepted: self.open,
                    firmware,
                }))
            }
            _ if !self.open => reply(Reply::Nack(NackReason::HandshakeRequired)),
            Command::Ping { nonce } => reply(Reply::Pong { nonce }),
            command => Dispatch::Forward { seq, command },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fwav_protocol::{FIRMWARE_NAME_LEN, PROTOCOL_VERSION, SCHEMA_HASH};

    fn req(seq: u16, command: Command) -> Request {
        Request { seq, command }
    }

    fn hello_reply(d: Dispatch) -> DeviceHello {
        match d {
            Dispatch::Reply(DeviceMessage::Hello(h)) => h,
            other => panic!("expected a hello, got {other:?}"),
        }
    }

    #[test]
    fn matching_host_is_accepted_and_served() {
        let mut s = Session::new();
        let h = hello_reply(s.receive(req(1, Command::Handshake(Hello::THIS))));
        assert!(h.accepted && s.is_open());
        assert_eq!((h.seq, h.hello), (1, Hello::THIS));
        assert_eq!(h.firmware.as_str(), FIRMWARE_NAME);
        assert!(FIRMWARE_NAME.len() <= FIRMWARE_NAME_LEN);
        assert_eq!(
            s.receive(req(2, Command::Ping { nonce: 5 })),
            Dispatch::Reply(DeviceMessage::Response(Response {
                seq: 2,
                reply: Reply::Pong { nonce: 5 }
            }))
        );
        assert_eq!(
            s.receive(req(3, Command::Arm)),
            Dispatch::Forward {
                seq: 3,
                command: Command::Arm
            }
        );
    }

    #[test]
    fn other_versions_are_refused_and_locked_out() {
        let mut s = Session::new();
        for peer in [
            Hello {
                protocol_version: PROTOCOL_VERSION + 1,
                schema_hash: SCHEMA_HASH,
            },
            Hello {
                protocol_version: PROTOCOL_VERSION,
                schema_hash: SCHEMA_HASH.wrapping_add(1),
            },
        ] {
            let h = hello_reply(s.receive(req(7, Command::Handshake(peer))));
            assert!(!h.accepted && !s.is_open());
            assert_eq!(h.hello, Hello::THIS, "the device tells its own version");
            for cmd in [
                Command::Ping { nonce: 1 },
                Command::Arm,
                Command::Start,
                Command::GetStatus,
            ] {
                assert_eq!(
                    s.receive(req(8, cmd)),
                    Dispatch::Reply(DeviceMessage::Response(Response {
                        seq: 8,
                        reply: Reply::Nack(NackReason::HandshakeRequired)
                    }))
                );
            }
        }
    }

    #[test]
    fn a_failed_handshake_closes_an_open_session() {
        let mut s = Session::new();
        s.receive(req(1, Command::Handshake(Hello::THIS)));
        assert!(s.is_open());
        s.receive(req(
            2,
            Command::Handshake(Hello {
                protocol_version: 0,
                schema_hash: 0,
            }),
        ));
        assert!(!s.is_open());
        s.receive(req(3, Command::Handshake(Hello::THIS)));
        s.close();
        assert!(!s.is_open());
    }
}
