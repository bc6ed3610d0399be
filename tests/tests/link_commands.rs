//! The `fwav` link code path against `hil-sim serve` on a pseudo-terminal
//! (the library server the `hil-sim serve` command runs), and the messages a
//! user gets when something is wrong.

use std::io::{Read, Write};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use fwav::device::{Device, DeviceError};
use fwav::link::LinkError;
use fwav::port;
use fwav::profile_file::ProfileFile;
use fwav_e2e::Served;
use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::{Command, DeviceHello, DeviceMessage, FrameDecoder, Hello, Request};
use serialport::{SerialPort, TTYPort};

fn initial_design() -> ProfileFile {
    ProfileFile::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../host/profiles/initial-design.json"
    ))
    .unwrap()
}

/// Upload the shipped profile, start, and watch the telemetry: the wing's
/// measured amplitude reaches the commanded 30 deg within 2%.
#[test]
fn upload_start_and_telemetry_reach_the_commanded_amplitude() {
    let served = Served::start();
    let mut device =
        Device::connect(port::open(&served.path).unwrap()).expect("handshake with hil-sim");
    assert!(device.hello.firmware.starts_with("fwav-fc "));
    let profile = initial_design().profile;
    device.upload(&profile).expect("accepted and read back");
    let session = device.arm().unwrap();
    device.command(Command::Start).unwrap();
    device.telemetry(true, 100).unwrap();
    // 1 s ramp + 1.5 s settling, with a heartbeat every 0.1 s (status
    // queries alone would not keep the device armed).
    let started = Instant::now();
    let mut samples = Vec::new();
    while started.elapsed() < Duration::from_secs_f64(2.5) {
        device.heartbeat(session).unwrap();
        let status = device.status().unwrap();
        assert!(status.armed && status.running, "{status:?}");
        device.link.listen(Duration::from_millis(100)).unwrap();
        samples.extend(device.link.take_telemetry());
    }
    assert!(samples.len() > 150, "{} samples", samples.len());
    let last = samples.last().unwrap();
    let amplitude = last.amplitude_est_rad.to_degrees();
    assert!(
        (amplitude - 30.0).abs() < 0.02 * 30.0,
        "amplitude {amplitude} deg"
    );
    assert!(
        (last.frequency_est_hz - 11.0).abs() < 0.05,
        "frequency {}",
        last.frequency_est_hz
    );
    assert!(samples.windows(2).all(|w| w[1].seq > w[0].seq), "in order");
    device.command(Command::Stop).unwrap();
    device.command(Command::Disarm).unwrap();
}

/// Garbage and truncated frames on the line first; the link still works.
#[test]
fn the_link_survives_garbage_and_truncated_frames() {
    let served = Served::start();
    let mut raw = port::open(&served.path).unwrap();
    let mut junk = vec![0x13, 0x37, 0x00, 0xff, 0xfe, 0x00, 0x42];
    let frame = encode_frame_vec(&Request {
        seq: 9,
        command: Command::Handshake(Hello::THIS),
    })
    .unwrap();
    junk.extend(&frame[..frame.len() / 2]); // cut off
    junk.extend(std::iter::repeat_n(0xa5, 700)); // longer than any frame
    junk.extend(&frame[..3]);
    raw.write_all(&junk).unwrap();
    let mut device = Device::connect(raw).expect("the link recovers");
    let status = device.status().unwrap();
    assert!(status.link.dropped() >= 2, "{:?}", status.link);
    assert!(status.link.overlong >= 1, "{:?}", status.link);
    device.upload(&initial_design().profile).unwrap();
}

/// A pty pair where the far end is a scripted fake device.
fn fake_device(answer: impl Fn(Request) -> Vec<u8> + Send + 'static) -> (String, Arc<AtomicBool>) {
    let (mut master, slave) = TTYPort::pair().unwrap();
    master.set_timeout(Duration::from_millis(10)).unwrap();
    let path = slave.name().unwrap();
    let stop = Arc::new(AtomicBool::new(false));
    let flag = stop.clone();
    std::thread::spawn(move || {
        let _keep = slave;
        let mut decoder = FrameDecoder::new();
        let mut buf = [0u8; 256];
        while !flag.load(Ordering::Relaxed) {
            if let Ok(n) = master.read(&mut buf) {
                let requests: Vec<Request> =
                    decoder.feed(&buf[..n]).filter_map(Result::ok).collect();
                for r in requests {
                    let _ = master.write_all(&answer(r));
                }
            }
        }
    });
    (path, stop)
}

#[test]
fn a_silent_device_is_no_answer() {
    let (path, stop) = fake_device(|_| Vec::new());
    let e = Device::connect(port::open(&path).unwrap()).err().unwrap();
    stop.store(true, Ordering::Relaxed);
    assert!(
        matches!(e, DeviceError::Link(LinkError::NoAnswer { .. })),
        "{e}"
    );
    assert!(e.to_string().contains("no answer"), "{e}");
}

#[test]
fn a_device_speaking_something_else_is_the_wrong_device() {
    let (path, stop) = fake_device(|_| b"AT OK\r\n".to_vec());
    let e = Device::connect(port::open(&path).unwrap()).err().unwrap();
    stop.store(true, Ordering::Relaxed);
    assert!(
        matches!(e, DeviceError::Link(LinkError::WrongDevice { .. })),
        "{e}"
    );
    assert!(e.to_string().contains("wrong device"), "{e}");
}

#[test]
fn another_protocol_version_is_refused_with_both_versions() {
    let theirs = Hello {
        protocol_version: 99,
        schema_hash: 0x1234,
    };
    let (path, stop) = fake_device(move |r| {
        let hello = DeviceHello {
            seq: r.seq,
            hello: theirs,
            accepted: false,
            firmware: heapless_name(),
        };
        encode_frame_vec(&DeviceMessage::Hello(hello)).unwrap()
    });
    let e = Device::connect(port::open(&path).unwrap()).err().unwrap();
    stop.store(true, Ordering::Relaxed);
    let text = e.to_string();
    assert!(
        text.contains("version 99")
            && text.contains(&format!("version {}", fwav_protocol::PROTOCOL_VERSION)),
        "{text}"
    );
}

fn heapless_name() -> fwav_protocol::message::DeviceHelloName {
    fwav_protocol::message::DeviceHelloName::try_from("fwav-fc 9.9.9").unwrap()
}

#[test]
fn a_missing_port_says_so() {
    let e = port::open("/dev/fwav-no-such-port").err().unwrap();
    assert!(e.to_string().contains("no such port"), "{e}");
}

#[test]
fn a_port_held_by_another_program_is_busy() {
    let served = Served::start();
    let _first = port::open(&served.path).unwrap();
    let Err(e) = port::open(&served.path) else {
        panic!("the second open must fail");
    };
    assert!(e.to_string().contains("busy"), "{e}");
}
