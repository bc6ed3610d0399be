//! The flight-controller core compiled for the microcontroller and run on
//! QEMU's emulated Cortex-M4F (`firmware/qemu`: the unchanged
//! `FlightController` on two emulated UARTs, its control step on a 10 kHz
//! SysTick flying the shared plant model), driven by the ordinary `fwav`
//! commands as processes over the UARTs' pseudo-terminals: handshake and
//! schema hash, upload and read-back, `upload --start` flying on the radio
//! link while 64 KiB of random bytes and truncated frames go into the other
//! (the USB link's stand-in), which answers after them, `fwav monitor` there
//! showing the commanded frequency and amplitude, stop; no panic or fault
//! handler ran. Reports the step cost the firmware measured and
//! its stack high-water mark against the STM32 binary's stack.
//!
//! Skipped, saying so, only where `qemu-system-arm` is not installed (on CI
//! `.ci/run` installs it, and there a missing QEMU fails the test). About
//! 10-20 s.

use std::io::{BufRead, BufReader};
use std::process::{Child, Command, Output, Stdio};
use std::sync::mpsc::{self, Receiver};
use std::time::{Duration, Instant};

use fwav::device::Device;
use fwav::port;
use fwav_e2e::emulator::{find_qemu, firmware, fwav_program, workspace, Emulator, Report};
use fwav_e2e::step_cost::{Measured, BUDGET_SHARE_LIMIT, CYCLES_PER_INSTRUCTION};
use fwav_protocol::frame::encode_frame_vec;
use fwav_protocol::{Command as Cmd, Hello, Request};
use rand::{RngCore, SeedableRng};

const PROFILE: &str = "host/profiles/initial-design.json";

/// `fwav ARGS`, run to its end from the workspace root.
fn fwav(args: &[&str]) -> Output {
    let out = Command::new(fwav_program())
        .args(args)
        .current_dir(workspace())
        .output()
        .expect("fwav runs");
    assert!(
        out.status.success(),
        "fwav {args:?} failed: {}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// `fwav fc --port PORT status --json`, parsed.
fn status(port: &str) -> serde_json::Value {
    let out = fwav(&["fc", "--port", port, "status", "--json"]);
    serde_json::from_slice(&out.stdout).expect("status --json is JSON")
}

/// `fwav fc --port PORT status --json`, parsed, asked again (at most
/// `within`) while the device does not answer or the pty is still too
/// full of earlier bytes to take the request (a write timeout).
fn answered_status(port: &str, within: Duration) -> serde_json::Value {
    let deadline = Instant::now() + within;
    loop {
        let out = Command::new(fwav_program())
            .args(["fc", "--port", port, "status", "--json"])
            .output()
            .expect("fwav runs");
        if out.status.success() {
            return serde_json::from_slice(&out.stdout).expect("status --json is JSON");
        }
        let said = String::from_utf8_lossy(&out.stderr);
        assert!(
            said.contains("no answer") || said.contains("timed out"),
            "{said}"
        );
        assert!(
            Instant::now() < deadline,
            "no answer within {within:?}: {said}"
        );
    }
}

/// A running `fwav` process whose stdout lines arrive on a channel.
struct Running {
    child: Child,
    lines: Receiver<String>,
    seen: Vec<String>,
}

impl Running {
    fn spawn(args: &[&str]) -> Running {
        let mut child = Command::new(fwav_program())
            .args(args)
            .current_dir(workspace())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("fwav runs");
        let stdout = child.stdout.take().expect("piped");
        let (send, lines) = mpsc::channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines().map_while(Result::ok) {
                let _ = send.send(line);
            }
        });
        Running {
            child,
            lines,
            seen: Vec::new(),
        }
    }

    /// Waits (at most `within`) for `count` consecutive stdout lines
    /// satisfying `ok`; the last of them.
    fn wait_for(&mut self, count: usize, within: Duration, ok: impl Fn(&str) -> bool) -> String {
        let deadline = Instant::now() + within;
        let mut run = 0;
        while let Some(left) = deadline.checked_duration_since(Instant::now()) {
            let Ok(line) = self.lines.recv_timeout(left) else {
                break;
            };
            run = if ok(&line) { run + 1 } else { 0 };
            self.seen.push(line.clone());
            if run == count {
                return line;
            }
        }
        let _ = self.child.kill();
        panic!(
            "no {count} such lines within {within:?}; stdout: {:?}",
            self.seen
        );
    }

    /// SIGTERM, then the exit (at most `within`): stdout lines and stderr.
    fn terminate(mut self, within: Duration) -> (Vec<String>, String) {
        let pid = self.child.id().to_string();
        let sent = Command::new("kill").args(["-s", "TERM", &pid]).status();
        assert!(sent.is_ok_and(|s| s.success()), "kill -s TERM {pid}");
        let deadline = Instant::now() + within;
        loop {
            if let Some(status) = self.child.try_wait().expect("waits") {
                let mut stderr = String::new();
                if let Some(mut e) = self.child.stderr.take() {
                    let _ = std::io::Read::read_to_string(&mut e, &mut stderr);
                }
                assert!(status.success(), "fwav ended with {status}: {stderr}");
                self.seen.extend(self.lines.try_iter());
                return (self.seen, stderr);
            }
            assert!(
                Instant::now() < deadline,
                "fwav still running {within:?} after SIGTERM"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
    }
}

/// The `amp X deg  f Y Hz` of a `fwav monitor` line, if it has them.
fn amplitude_and_frequency(line: &str) -> Option<(f64, f64)> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let after = |key: &str| {
        let i = words.iter().position(|w| *w == key)?;
        words.get(i + 1)?.parse::<f64>().ok()
    };
    Some((after("amp")?, after("f")?))
}

/// The STM32 binary's stack (its `_stack_start - _stack_end`) if `cargo fw`
/// has built it, else the least it can be: 128 KiB of RAM less the 48 KiB
/// static-RAM budget `.ci/firmware-size` enforces.
fn stm32_stack_bytes() -> (u64, &'static str) {
    use object::{Object, ObjectSymbol};
    let elf = workspace().join("target/thumbv7em-none-eabihf/fw/fwav-fc-stm32");
    let symbols = std::fs::read(&elf).ok().and_then(|data| {
        let file = object::File::parse(&*data).ok()?;
        let address = |name: &str| {
            file.symbols()
                .find(|s| s.name() == Ok(name))
                .map(|s| s.address())
        };
        Some(address("_stack_start")? - address("_stack_end")?)
    });
    match symbols {
        Some(size) => (size, "from its ELF"),
        None => (
            (128 - 48) * 1024,
            "at least, by the static-RAM budget (no ELF built)",
        ),
    }
}

#[test]
fn the_core_flies_on_the_emulated_cortex_m4_through_fwav_and_survives_garbage() {
    let qemu = match find_qemu() {
        Ok(qemu) => qemu,
        Err(why) => return eprintln!("{why}"),
    };
    let elf = firmware("fwav-fc-qemu");
    let fwav_built = fwav_program();
    assert!(fwav_built.is_file());
    let started = Instant::now();
    let mut board = Emulator::start(&qemu, &elf, 2, None);
    let (radio, usb) = (board.port(0).to_owned(), board.port(1).to_owned());

    // Handshake and schema hash (what every fwav command opens with).
    let device = Device::connect(port::open(&radio).expect("the pty opens")).expect("handshake");
    assert!(device.hello.accepted, "{:?}", device.hello);
    assert_eq!(
        device.hello.hello,
        Hello::THIS,
        "protocol version and schema hash"
    );
    assert!(
        device.hello.firmware.starts_with("fwav-fc "),
        "{:?}",
        device.hello
    );
    drop(device);
    let text = String::from_utf8(fwav(&["fc", "--port", &radio, "status"]).stdout).expect("UTF-8");
    assert!(
        text.contains("fwav-fc ") && text.contains("armed false"),
        "{text}"
    );

    // Upload and read-back (fwav upload compares what it reads back).
    let text =
        String::from_utf8(fwav(&["upload", "--port", &radio, PROFILE]).stdout).expect("UTF-8");
    assert!(text.contains("accepted"), "{text}");
    assert_eq!(status(&usb)["profile_loaded"], true);

    // Start: the pilot flies on the radio link.
    let mut pilot = Running::spawn(&["upload", "--port", &radio, PROFILE, "--start"]);
    pilot.wait_for(1, Duration::from_secs(30), |l| l.contains("running true"));

    // While it flies, garbage into the USB link: 64 KiB of random bytes,
    // then truncated frames. The wing flies on, and the link answers after.
    let reports_before = board.reports().len();
    let mut junk = vec![0u8; 64 * 1024];
    rand::rngs::StdRng::seed_from_u64(24).fill_bytes(&mut junk);
    let handshake = encode_frame_vec(&Request {
        seq: 7,
        command: Cmd::Handshake(Hello::THIS),
    })
    .expect("a frame");
    let upload = std::fs::read(workspace().join(PROFILE)).expect("the profile");
    junk.extend(&handshake[..handshake.len() / 2]);
    junk.extend(&upload[..100]); // JSON, not a frame at all
    junk.push(0);
    junk.extend(&handshake[1..handshake.len() - 1]); // no delimiters
    let garbage_started = Instant::now();
    board.write(1, &junk);
    // The pty holds what QEMU has not taken yet (it takes a byte at a time):
    // a status request waits behind it, so ask until answered.
    let after_garbage = answered_status(&usb, Duration::from_secs(60));
    let garbage_s = garbage_started.elapsed().as_secs_f64();
    assert_eq!(after_garbage["running"], true, "flying on: {after_garbage}");
    let dropped = after_garbage["link"]["dropped"].as_u64().expect("a count");
    assert!(
        dropped > 100,
        "the garbage's frames were counted as dropped: {after_garbage}"
    );

    // Telemetry: `fwav monitor` on the USB link until it shows the
    // commanded 11 Hz and +-30 deg (within 0.05 Hz and 2%) on two lines in
    // a row.
    let csv = std::env::temp_dir().join(format!("fwav-emulated-{}.csv", std::process::id()));
    // A leftover of an earlier run would be refused: never written over.
    std::fs::remove_file(&csv).ok();
    let csv_arg = csv.to_str().expect("UTF-8 temp path");
    let mut monitor = Running::spawn(&["monitor", "--port", &usb, "--csv", csv_arg]);
    let flying = monitor.wait_for(2, Duration::from_secs(60), |l| {
        amplitude_and_frequency(l)
            .is_some_and(|(a, f)| (a - 30.0).abs() < 0.02 * 30.0 && (f - 11.0).abs() < 0.05)
    });
    // Stop: the pilot stops the wing, waits for rest and disarms.
    let (_, told) = pilot.terminate(Duration::from_secs(30));
    assert!(told.contains("stopped and disarmed"), "{told}");
    let (_, _) = monitor.terminate(Duration::from_secs(10));
    let logged = std::fs::read_to_string(&csv).expect("the monitor's CSV");
    std::fs::remove_file(&csv).ok();
    assert!(
        logged.lines().count() > 20,
        "{} CSV rows",
        logged.lines().count()
    );
    for port in [&radio, &usb] {
        let landed = status(port);
        assert_eq!(landed["armed"], false, "{landed}");
        assert_eq!(landed["running"], false, "{landed}");
        assert_eq!(landed["last_disarm"], "Command", "{landed}");
        assert_eq!(landed["faults"], "none", "{landed}");
    }

    // No panic, no fault: QEMU still runs (a panic or fault ends it), none
    // was reported, and the firmware reports on after the garbage.
    let reports = board.wait_for_report("running", reports_before, Duration::from_secs(30));
    assert!(board.is_running(), "QEMU ended: {:?}", board.lines());
    let lines = board.lines();
    assert!(
        !lines
            .iter()
            .any(|l| l.contains("panicked") || l.contains("hard fault")),
        "{lines:?}"
    );

    // The firmware's own measurements: step cost and stack.
    let last: &Report = reports
        .iter()
        .rev()
        .find(|r| r.kind == "running")
        .expect("a report");
    let steps = last.number("steps");
    let step_mean = last.number("step_mean_ns");
    let step_max = last.number("step_max_ns");
    let used = last.number("stack_used_bytes");
    let size = last.number("stack_size_bytes");
    let loop_depth = last.number("loop_depth_bytes");
    let (stm32, source) = stm32_stack_bytes();
    println!(
        "emulated board: {steps} control steps, {step_mean:.0} instructions a step on average ({:.1}% of 16,800 cycles at {CYCLES_PER_INSTRUCTION} cycles per instruction), {step_max:.0} at most; \
         stack high-water mark {used} of {size} bytes here ({:.0} below the main loop's frames: the core's handle and step calls and the interrupts), against the STM32 binary's {stm32} bytes ({source}); \
         64 KiB of garbage into the other link while flying, status answered after {garbage_s:.1} s ({dropped} frames dropped); test wall time {:.1} s; telemetry: {flying}",
        100.0 * Measured::budget_share(step_mean, CYCLES_PER_INSTRUCTION),
        used - loop_depth,
        started.elapsed().as_secs_f64()
    );
    assert!(
        used < stm32 as f64,
        "the stack reached {used} bytes, the STM32 binary has {stm32}"
    );
    // Disarmed steps are cheaper: the mean over this test is below the
    // benchmark's; the longest step is the benchmark's flying one.
    assert!(
        Measured::budget_share(step_max, CYCLES_PER_INSTRUCTION) <= BUDGET_SHARE_LIMIT,
        "longest step {step_max} instructions"
    );
}
