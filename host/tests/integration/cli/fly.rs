//! The link commands (`fwav upload --start`, `fwav fc`, `fwav monitor`) as
//! real processes against the virtual flight controller of `hil-sim serve`
//! (its library server, on a real pseudo-terminal, in real time): the link
//! failsafe with an orphaned wing, signals, and arguments refused before the
//! link is touched.

use std::io::{BufRead, BufReader};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use fwav_actuator::params::PlantParams;
use fwav_hil_sim::serve::Server;

const PROFILE: &str = "host/profiles/initial-design.json";

/// `hil-sim serve`'s virtual flight controller on a pseudo-terminal, in
/// real time, until dropped.
struct VirtualBoard {
    path: String,
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl VirtualBoard {
    fn start() -> Self {
        let mut server = Server::new(&PlantParams::default(), 1.0).expect("a pty pair");
        let path = server.path().to_owned();
        let stop = Arc::new(AtomicBool::new(false));
        let flag = stop.clone();
        let thread = std::thread::spawn(move || {
            server
                .run(|| flag.load(Ordering::Relaxed))
                .expect("the server runs");
        });
        Self {
            path,
            stop,
            thread: Some(thread),
        }
    }

    /// `fwav fc --port PTY status --json`, parsed; `None` if it failed (the
    /// port still held by a dying client, say).
    fn status(&self) -> Option<serde_json::Value> {
        let out = super::fwav(&["fc", "--port", &self.path, "status", "--json"]);
        if !out.status.success() {
            return None;
        }
        serde_json::from_slice(&out.stdout).ok()
    }
}

impl Drop for VirtualBoard {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

/// A running `fwav` process whose stdout lines arrive on a channel and
/// whose stderr is collected.
struct Running {
    child: Child,
    lines: Receiver<String>,
    stderr: JoinHandle<String>,
}

impl Running {
    fn spawn(args: &[&str]) -> Self {
        let mut child = Command::new(env!("CARGO_BIN_EXE_fwav"))
            .args(args)
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("the fwav binary runs");
        let stdout = child.stdout.take().expect("piped");
        let (send, lines) = mpsc::channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines().map_while(Result::ok) {
                let _ = send.send(line);
            }
        });
        let mut pipe = child.stderr.take().expect("piped");
        let stderr = std::thread::spawn(move || {
            let mut text = String::new();
            let _ = std::io::Read::read_to_string(&mut pipe, &mut text);
            text
        });
        Self {
            child,
            lines,
            stderr,
        }
    }

    /// Waits for a stdout line containing `text` (at most `within`).
    fn wait_for_line(&mut self, text: &str, within: Duration) -> String {
        let deadline = Instant::now() + within;
        let mut seen = Vec::new();
        while let Some(left) = deadline.checked_duration_since(Instant::now()) {
            match self.lines.recv_timeout(left) {
                Ok(line) if line.contains(text) => return line,
                Ok(line) => seen.push(line),
                Err(_) => break,
            }
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
        panic!("no line with {text:?} within {within:?}; stdout: {seen:?}");
    }

    /// Sends `signal` (a name for kill(1): TERM, HUP, INT) to the process.
    fn signal(&self, signal: &str) {
        let ok = Command::new("kill")
            .args(["-s", signal, &self.child.id().to_string()])
            .status()
            .expect("kill(1) runs")
            .success();
        assert!(ok, "kill -s {signal} failed");
    }

    /// Waits for the exit (at most `within`); the status and stderr.
    fn finish(mut self, within: Duration) -> (ExitStatus, String) {
        let deadline = Instant::now() + within;
        loop {
            if let Some(status) = self.child.try_wait().expect("waits") {
                let stderr = self.stderr.join().expect("stderr read");
                return (status, stderr);
            }
            if Instant::now() > deadline {
                let _ = self.child.kill();
                let _ = self.child.wait();
                panic!("still running {within:?} later");
            }
            std::thread::sleep(Duration::from_millis(10));
        }
    }
}

/// The client that started a flight is killed (SIGKILL: no chance to stop
/// anything); another client then polls `fwav fc status` every 50 ms.
/// Those read-only queries must not keep the orphaned wing flapping: it is
/// at rest and disarmed (by the link failsafe) within 0.5 s of the death.
#[test]
fn an_orphaned_wing_stops_while_another_client_polls_status() {
    let board = VirtualBoard::start();
    let mut pilot = Running::spawn(&["upload", "--port", &board.path, PROFILE, "--start"]);
    pilot.wait_for_line("running true", Duration::from_secs(20));
    pilot.child.kill().expect("SIGKILL");
    let died = Instant::now();
    pilot.child.wait().expect("reaped");

    let mut polls = 0;
    let mut last = None;
    let at_rest = loop {
        let asked = Instant::now();
        if let Some(s) = board.status() {
            polls += 1;
            if s["armed"] == false && s["running"] == false {
                break Some((died.elapsed(), s));
            }
            last = Some(s);
        }
        if died.elapsed() > Duration::from_secs(5) {
            break None;
        }
        std::thread::sleep(Duration::from_millis(50).saturating_sub(asked.elapsed()));
    };
    let Some((after, status)) = at_rest else {
        panic!("still flying 5 s after the controlling client's death, {polls} status polls; last: {last:?}");
    };
    eprintln!(
        "orphaned wing at rest {:.3} s after the controlling client's death ({polls} status polls)",
        after.as_secs_f64()
    );
    assert!(polls >= 2, "the wing was polled while orphaned: {polls}");
    assert!(
        after < Duration::from_millis(500),
        "at rest after {after:?}"
    );
    assert_eq!(status["last_disarm"], "LinkLoss", "{status}");
    assert!(
        status["faults"].as_str().unwrap().contains("link-loss"),
        "{status}"
    );
}

/// SIGTERM, SIGHUP and SIGINT to `fwav upload --start` stop the wing, wait
/// for rest and disarm before the program exits (the device reports a
/// commanded disarm, not the link failsafe).
#[test]
fn upload_start_stops_the_wing_on_sigterm_sighup_and_sigint() {
    for signal in ["TERM", "HUP", "INT"] {
        let board = VirtualBoard::start();
        let mut pilot = Running::spawn(&["upload", "--port", &board.path, PROFILE, "--start"]);
        pilot.wait_for_line("running true", Duration::from_secs(20));
        pilot.signal(signal);
        let (exit, stderr) = pilot.finish(Duration::from_secs(10));
        assert!(exit.success(), "SIG{signal}: {exit:?}\n{stderr}");
        assert!(
            stderr.contains("stopped and disarmed"),
            "SIG{signal}: {stderr}"
        );
        let status = board.status().expect("status after the flight");
        assert_eq!(status["armed"], false, "SIG{signal}: {status}");
        assert_eq!(status["last_disarm"], "Command", "SIG{signal}: {status}");
        assert_eq!(status["faults"], "none", "SIG{signal}: {status}");
    }
}

/// `fwav monitor` ends through its own shutdown (telemetry off, "monitor
/// stopped", exit 0) on SIGTERM and SIGHUP, as on Ctrl-C.
#[test]
fn monitor_ends_cleanly_on_sigterm_and_sighup() {
    for signal in ["TERM", "HUP"] {
        let board = VirtualBoard::start();
        let mut monitor = Running::spawn(&["monitor", "--port", &board.path]);
        monitor.wait_for_line("faults", Duration::from_secs(20));
        monitor.signal(signal);
        let (exit, stderr) = monitor.finish(Duration::from_secs(10));
        assert!(exit.success(), "SIG{signal}: {exit:?}\n{stderr}");
        assert!(stderr.contains("monitor stopped"), "SIG{signal}: {stderr}");
    }
}

/// `--duration nan`, `-1`, `0`, `inf`, `-0.5` or `-1e300` is refused before the link is
/// touched: a usage error naming the option and the value, and the device
/// was never armed (nor even given the profile).
#[test]
fn upload_refuses_a_duration_that_is_not_a_positive_number_of_seconds() {
    let board = VirtualBoard::start();
    // -1e300 is named as written, not as 301 digits.
    for value in ["nan", "-1", "0", "inf", "-0.5", "-1e300"] {
        let out = super::fwav(&[
            "upload",
            "--port",
            &board.path,
            PROFILE,
            "--start",
            "--duration",
            value,
        ]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{value}: {stderr}");
        assert!(
            stderr.contains("--duration") && stderr.contains(value),
            "{value}: {stderr}"
        );
        assert!(stderr.contains("positive number of seconds"), "{stderr}");
        let status = board.status().expect("status");
        assert_eq!(status["last_disarm"], "Reset", "{value}: {status}");
        assert_eq!(status["profile_loaded"], false, "{value}: {status}");
    }
}

/// `fwav fc params --set current_limit=1e300` named the value `inf` (the
/// `f32` the wire carries); the error shows it as typed, and the device
/// keeps its limit.
#[test]
fn a_parameter_beyond_the_wire_is_named_as_typed() {
    let board = VirtualBoard::start();
    // 1e300 is inf on the wire. Just past the declared top, 1000 ohm: its
    // f32 rounds to 1000, which the device would take; the declared f64
    // range, a plant file's, is asked (since 2026-12-07), and the range is
    // shown as declared.
    for (set, expected) in [
        (
            "current_limit=1e300",
            "current_limit = 1e300 is outside 0..=50 A",
        ),
        (
            "winding_resistance=1000.00001",
            "winding_resistance = 1000.00001 is outside 0.001..=1000 ohm",
        ),
    ] {
        let out = super::fwav(&["fc", "--port", &board.path, "params", "--set", set]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{set}: {stderr}");
        assert!(stderr.contains(expected), "{set}: {stderr}");
    }
    let out = super::fwav(&["fc", "--port", &board.path, "params", "--json"]);
    let params: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(params["current_limit [A]"], 1.5, "{params}");
    assert_eq!(params["winding_resistance [ohm]"], 5.0, "{params}");
}

/// `fwav upload --start | head -1`: once the reader has gone, the pilot's
/// next status line cannot be written; it stops the wing first and then
/// ends with that error (exit 1), instead of being killed by SIGPIPE with
/// the wing left flying to the device's failsafe, or panicking (issue 22).
#[test]
fn upload_start_stops_the_wing_when_its_output_pipe_closes() {
    use std::io::Read as _;
    use std::os::unix::process::ExitStatusExt as _;

    let board = VirtualBoard::start();
    let mut child = Command::new(env!("CARGO_BIN_EXE_fwav"))
        .args(["upload", "--port", &board.path, PROFILE, "--start"])
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the fwav binary runs");
    let mut stdout = BufReader::new(child.stdout.take().expect("piped"));
    let deadline = Instant::now() + Duration::from_secs(20);
    let mut line = String::new();
    while !line.contains("running true") {
        line.clear();
        let read = stdout.read_line(&mut line).expect("stdout");
        assert!(read > 0 && Instant::now() < deadline, "not flying: {line}");
    }
    drop(stdout); // the reader goes, as `head` does after its line
    let deadline = Instant::now() + Duration::from_secs(15);
    let exit = loop {
        if let Some(exit) = child.try_wait().expect("wait") {
            break exit;
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            panic!("the pilot did not end after its reader went");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut stderr = String::new();
    child
        .stderr
        .take()
        .expect("piped")
        .read_to_string(&mut stderr)
        .expect("stderr");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_eq!(exit.signal(), None, "{exit:?}: {stderr}");
    assert_eq!(exit.code(), Some(1), "{stderr}");
    assert!(stderr.contains("the wing was stopped first"), "{stderr}");
    let status = board.status().expect("status after the flight");
    assert_eq!(status["armed"], false, "{status}");
    assert_eq!(status["running"], false, "{status}");
    assert_eq!(status["last_disarm"], "Command", "{status}");
}
