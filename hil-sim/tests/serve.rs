//! `hil-sim serve` end to end: a serial-port client on the pseudo-terminal
//! handshakes with the virtual flight controller and gets answers.

use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use fwav_actuator::params::PlantParams;
use fwav_hil_sim::serve::Server;
use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::{Command, DeviceMessage, FrameDecoder, Hello, Reply, Request, Response};

fn read_until(
    port: &mut dyn serialport::SerialPort,
    decoder: &mut FrameDecoder,
    want: usize,
) -> Vec<DeviceMessage> {
    let mut out = Vec::new();
    let mut buf = [0u8; 256];
    let deadline = Instant::now() + Duration::from_secs(5);
    while out.len() < want && Instant::now() < deadline {
        if let Ok(n) = port.read(&mut buf) {
            out.extend(
                decoder
                    .feed::<DeviceMessage>(&buf[..n])
                    .filter_map(Result::ok),
            );
        }
    }
    out
}

#[test]
fn a_serial_client_talks_to_the_virtual_flight_controller() {
    let mut server = Server::new(&PlantParams::default(), 1.0).expect("a pty pair");
    let path = server.path().to_owned();
    assert!(path.starts_with("/dev/"), "{path}");
    let stop = Arc::new(AtomicBool::new(false));
    let flag = stop.clone();
    let thread = std::thread::spawn(move || server.run(|| flag.load(Ordering::Relaxed)));

    let mut port = serialport::new(&path, 460_800)
        .timeout(Duration::from_millis(50))
        .open()
        .expect("the pty opens");
    let mut decoder = FrameDecoder::new();
    // Garbage first: the device must still answer afterwards.
    port.write_all(&[0x55, 0x00, 0x17, 0x99, 0x00]).unwrap();
    for (seq, command) in [
        (1u16, Command::Handshake(Hello::THIS)),
        (2, Command::Ping { nonce: 77 }),
    ] {
        port.write_all(&encode_frame_vec(&Request { seq, command }).unwrap())
            .unwrap();
    }
    let replies = read_until(port.as_mut(), &mut decoder, 2);
    stop.store(true, Ordering::Relaxed);
    thread.join().unwrap().unwrap();

    assert!(
        matches!(&replies[0], DeviceMessage::Hello(h) if h.accepted && h.seq == 1),
        "{replies:?}"
    );
    assert_eq!(
        replies[1],
        DeviceMessage::Response(Response {
            seq: 2,
            reply: Reply::Pong { nonce: 77 }
        })
    );
}
