//! # fwav-link — the host end of the fwav link
//!
//! Requests with sequence numbers, answers matched by sequence number,
//! timeouts, retries of lost frames (the device answers a retried sequence
//! number from its cache, so nothing runs twice), and unsolicited telemetry
//! buffered while waiting: [`Link`], over any byte port that implements
//! [`Read`] and [`Write`].
//!
//! It is the one client of the link. The `fwav` program uses it on a serial
//! port (re-exported as `fwav::link`); hil-sim's scenarios use it on the
//! simulated flight controller itself (its `Simulator` is such a byte port,
//! answering each request as it is written), so both talk to the firmware
//! core through the same code. It may import `fwav-protocol` only.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

use std::collections::VecDeque;
use std::io::{ErrorKind, Read, Write};
use std::time::{Duration, Instant};

use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::{
    Command, DeviceHello, DeviceMessage, EncodeError, FrameDecoder, Hello, NackReason, Reply,
    Request, Response, TelemetrySample, VersionMismatch,
};

/// Why talking to a device failed.
#[derive(Debug, thiserror::Error)]
pub enum LinkError {
    /// Nothing came back.
    #[error("no answer from the device after {attempts} attempts of {timeout_ms} ms: is it powered, on this port, and running fwav firmware?")]
    NoAnswer {
        /// Attempts made.
        attempts: u32,
        /// Timeout of each, ms.
        timeout_ms: u64,
    },
    /// Bytes came back, but never a valid fwav frame.
    #[error("the device answers, but not in the fwav protocol ({bytes} bytes, no valid frame): wrong device or baud rate?")]
    WrongDevice {
        /// Bytes received.
        bytes: usize,
    },
    /// The device speaks another protocol version.
    #[error("{0}")]
    VersionMismatch(VersionMismatch),
    /// The device refused a command.
    #[error("the device refused {command}: {reason}")]
    Refused {
        /// What was asked.
        command: &'static str,
        /// Its reason.
        reason: NackReason,
    },
    /// An answer of the wrong kind.
    #[error("unexpected answer to {command}: {answer}")]
    Unexpected {
        /// What was asked.
        command: &'static str,
        /// What came back.
        answer: String,
    },
    /// The request could not be framed.
    #[error("cannot frame the request: {0}")]
    Encode(#[from] EncodeError),
    /// Reading or writing the port failed.
    #[error("port I/O: {0}")]
    Io(#[from] std::io::Error),
}

/// A name for a command, for messages.
pub fn command_name(c: &Command) -> &'static str {
    match c {
        Command::Handshake(_) => "handshake",
        Command::Ping { .. } => "ping",
        Command::UploadProfile(_) => "upload",
        Command::ReadProfile => "read-back",
        Command::Arm => "arm",
        Command::Disarm => "disarm",
        Command::Start => "start",
        Command::Stop => "stop",
        Command::SaveProfile => "save",
        Command::GetParams => "get parameters",
        Command::SetParam(_) => "set parameter",
        Command::GetStatus => "status",
        Command::SetTelemetry(_) => "telemetry",
        Command::ClearFaults => "clear faults",
        Command::GetLimits => "limits",
        Command::Heartbeat { .. } => "heartbeat",
    }
}

/// A connection to a flight controller (or hil-sim) over any byte port
/// whose reads time out (a serial port opened with a timeout) or return at
/// once (an in-process device; [`ErrorKind::WouldBlock`], `TimedOut` or
/// `Interrupted` mean "nothing yet").
pub struct Link<P> {
    port: P,
    decoder: FrameDecoder,
    seq: u16,
    /// Wait for an answer this long before resending.
    pub timeout: Duration,
    /// Resend a request this many times before giving up.
    pub retries: u32,
    telemetry: VecDeque<TelemetrySample>,
    bytes_seen: usize,
}

/// Telemetry samples kept while nobody reads them.
const TELEMETRY_BUFFER: usize = 10_000;

impl<P: Read + Write> Link<P> {
    /// A link on `port` (no handshake yet).
    pub fn new(port: P) -> Self {
        Self {
            port,
            decoder: FrameDecoder::new(),
            seq: 0,
            timeout: Duration::from_millis(300),
            retries: 3,
            telemetry: VecDeque::new(),
            bytes_seen: 0,
        }
    }

    /// The port.
    pub fn get_ref(&self) -> &P {
        &self.port
    }

    /// The port, to act on the device between requests (an in-process
    /// device's simulated time, say). Bytes written or read here bypass the
    /// link's sequence numbers and decoder.
    pub fn get_mut(&mut self) -> &mut P {
        &mut self.port
    }

    /// Opens the session: the device's hello, or a clear error if it speaks
    /// another version (both versions named).
    pub fn handshake(&mut self) -> Result<DeviceHello, LinkError> {
        // A lone delimiter flushes whatever half frame the device holds.
        self.port.write_all(&[0])?;
        let command = Command::Handshake(Hello::THIS);
        match self.exchange(command)? {
            DeviceMessage::Hello(h) if h.accepted => Ok(h),
            DeviceMessage::Hello(h) => Err(LinkError::VersionMismatch(VersionMismatch {
                ours: Hello::THIS,
                theirs: h.hello,
            })),
            other => Err(LinkError::Unexpected {
                command: "handshake",
                answer: format!("{other:?}"),
            }),
        }
    }

    /// Sends `command` and returns the device's reply (a nack is a reply,
    /// not an error, here).
    pub fn request(&mut self, command: Command) -> Result<Reply, LinkError> {
        let name = command_name(&command);
        match self.exchange(command)? {
            DeviceMessage::Response(Response { reply, .. }) => Ok(reply),
            other => Err(LinkError::Unexpected {
                command: name,
                answer: format!("{other:?}"),
            }),
        }
    }

    /// Sends `command`; Ok on an ack, [`LinkError::Refused`] on a nack.
    pub fn command(&mut self, command: Command) -> Result<(), LinkError> {
        let name = command_name(&command);
        match self.request(command)? {
            Reply::Ack => Ok(()),
            Reply::Nack(reason) => Err(LinkError::Refused {
                command: name,
                reason,
            }),
            other => Err(LinkError::Unexpected {
                command: name,
                answer: format!("{other:?}"),
            }),
        }
    }

    /// Arms the device; returns the session whose heartbeats
    /// ([`Link::heartbeat`]) alone keep it armed.
    pub fn arm(&mut self) -> Result<u32, LinkError> {
        match self.request(Command::Arm)? {
            Reply::Armed { session } => Ok(session),
            Reply::Nack(reason) => Err(LinkError::Refused {
                command: "arm",
                reason,
            }),
            other => Err(LinkError::Unexpected {
                command: "arm",
                answer: format!("{other:?}"),
            }),
        }
    }

    /// The heartbeat of `session` (from [`Link::arm`]): keeps the device
    /// armed for another link timeout. Refused if the device disarmed
    /// ([`NackReason::NotArmed`]) or another client armed it since
    /// ([`NackReason::OtherSession`]).
    pub fn heartbeat(&mut self, session: u32) -> Result<(), LinkError> {
        self.command(Command::Heartbeat { session })
    }

    /// Takes the telemetry received so far.
    pub fn take_telemetry(&mut self) -> Vec<TelemetrySample> {
        self.telemetry.drain(..).collect()
    }

    /// Reads for `wait` and buffers any telemetry that arrives.
    pub fn listen(&mut self, wait: Duration) -> Result<(), LinkError> {
        let deadline = Instant::now() + wait;
        while Instant::now() < deadline {
            self.receive_some(None)?;
        }
        Ok(())
    }

    /// Sends with a new sequence number; resends the same sequence number
    /// on timeout; returns the matching answer.
    fn exchange(&mut self, command: Command) -> Result<DeviceMessage, LinkError> {
        self.seq = self.seq.wrapping_add(1);
        let frame = encode_frame_vec(&Request {
            seq: self.seq,
            command,
        })?;
        let bytes_before = self.bytes_seen;
        for _ in 0..=self.retries {
            self.port.write_all(&frame)?;
            self.port.flush()?;
            let deadline = Instant::now() + self.timeout;
            // At least one read per attempt, however late: a device that
            // answers at once (in process) is never resent to.
            loop {
                if let Some(answer) = self.receive_some(Some(self.seq))? {
                    return Ok(answer);
                }
                if Instant::now() >= deadline {
                    break;
                }
            }
        }
        let bytes = self.bytes_seen - bytes_before;
        if bytes > 0 && self.decoder.stats().frames_ok == 0 {
            Err(LinkError::WrongDevice { bytes })
        } else {
            Err(LinkError::NoAnswer {
                attempts: self.retries + 1,
                timeout_ms: self.timeout.as_millis() as u64,
            })
        }
    }

    /// One read; returns the answer with sequence number `want` if it came.
    fn receive_some(&mut self, want: Option<u16>) -> Result<Option<DeviceMessage>, LinkError> {
        let mut buf = [0u8; 512];
        let n = match self.port.read(&mut buf) {
            Ok(n) => n,
            Err(e)
                if matches!(
                    e.kind(),
                    ErrorKind::TimedOut | ErrorKind::WouldBlock | ErrorKind::Interrupted
                ) =>
            {
                return Ok(None)
            }
            Err(e) => return Err(e.into()),
        };
        self.bytes_seen += n;
        let mut found = None;
        for message in self
            .decoder
            .feed::<DeviceMessage>(&buf[..n])
            .filter_map(Result::ok)
        {
            match message {
                DeviceMessage::Telemetry(sample) => {
                    if self.telemetry.len() == TELEMETRY_BUFFER {
                        self.telemetry.pop_front();
                    }
                    self.telemetry.push_back(sample);
                }
                DeviceMessage::Response(ref r) if Some(r.seq) == want => found = Some(message),
                DeviceMessage::Hello(ref h) if Some(h.seq) == want => found = Some(message),
                // A late answer to an earlier attempt: already handled.
                _ => {}
            }
        }
        Ok(found)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A device in memory that acks every request it receives, except the
    /// first `lost` (their answers are lost on the wire).
    struct Acking {
        decoder: FrameDecoder,
        out: Vec<u8>,
        seqs: Vec<u16>,
        lost: usize,
    }

    impl Acking {
        fn new(lost: usize) -> Self {
            Self {
                decoder: FrameDecoder::new(),
                out: Vec::new(),
                seqs: Vec::new(),
                lost,
            }
        }
    }

    impl Write for Acking {
        fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
            let requests: Vec<Request> = self.decoder.feed(bytes).filter_map(Result::ok).collect();
            for r in requests {
                self.seqs.push(r.seq);
                if self.seqs.len() > self.lost {
                    let answer = DeviceMessage::Response(Response {
                        seq: r.seq,
                        reply: Reply::Ack,
                    });
                    self.out.extend(encode_frame_vec(&answer).expect("frames"));
                }
            }
            Ok(bytes.len())
        }

        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    impl Read for Acking {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            if self.out.is_empty() {
                return Err(ErrorKind::WouldBlock.into());
            }
            let n = buf.len().min(self.out.len());
            buf[..n].copy_from_slice(&self.out[..n]);
            self.out.drain(..n);
            Ok(n)
        }
    }

    /// With no time to wait, an answer that is already there is still read:
    /// one send per request, sequence numbers counting up.
    #[test]
    fn a_device_that_answers_at_once_needs_no_timeout() {
        let mut link = Link::new(Acking::new(0));
        link.timeout = Duration::ZERO;
        link.retries = 0;
        link.command(Command::Arm).unwrap();
        link.command(Command::Start).unwrap();
        assert_eq!(link.get_ref().seqs, [1, 2]);
    }

    /// A lost answer is asked for again with the same sequence number; with
    /// every answer lost the error counts the attempts.
    #[test]
    fn lost_answers_are_retried_with_the_same_sequence_number() {
        let mut link = Link::new(Acking::new(1));
        link.timeout = Duration::ZERO;
        link.retries = 1;
        link.command(Command::Arm).unwrap();
        assert_eq!(link.get_ref().seqs, [1, 1]);

        let mut link = Link::new(Acking::new(usize::MAX));
        link.timeout = Duration::ZERO;
        link.retries = 2;
        let e = link.command(Command::Arm).unwrap_err();
        assert!(matches!(e, LinkError::NoAnswer { attempts: 3, .. }), "{e}");
        assert_eq!(link.get_ref().seqs, [1, 1, 1]);
    }
}
