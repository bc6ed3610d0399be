//! The flight-controller core on QEMU's emulated Cortex-M4F
//! (`firmware/qemu`): finding `qemu-system-arm`, building the firmware,
//! running it with its UARTs on pseudo-terminals, reading what it reports
//! over semihosting, and stopping it (also when a test fails: [`Emulator`]
//! kills QEMU when dropped).
//!
//! QEMU runs `-machine mps2-an386 -cpu cortex-m4` with `-icount shift=0`:
//! its virtual clock advances one nanosecond per executed instruction, so
//! the firmware's timer counts instructions, and idle time passes at the
//! host's pace (`sleep=on`, QEMU's default), so the host's heartbeats are
//! never late in the device's time while the host keeps the test's
//! threads running. On a host with more runnable threads than cores the
//! heartbeat thread can be held off while the firmware idles, and the
//! link-loss failsafe then fires, as it should. CI on this 2-core
//! machine with a 2-thread benchmark beside it failed
//! `the_core_flies_on_the_emulated_cortex_m4_through_fwav_and_survives_garbage`
//! on that failsafe (2026-12-05), most likely so (not traced); alone it
//! passes.

use std::collections::BTreeMap;
use std::fs::File;
use std::io::{BufRead, BufReader, Write};
use std::os::unix::fs::OpenOptionsExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// The QEMU program the firmware runs on.
pub const QEMU: &str = "qemu-system-arm";

/// The workspace root.
pub fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ is inside the workspace")
        .to_path_buf()
}

/// `qemu-system-arm` on the `PATH`, or why there is none. On CI
/// (`CI=true`, where `.ci/run` installs it) a missing QEMU is an error,
/// not a reason to skip.
pub fn find_qemu() -> Result<PathBuf, String> {
    let found = std::env::var_os("PATH").and_then(|path| {
        std::env::split_paths(&path)
            .map(|dir| dir.join(QEMU))
            .find(|p| p.is_file())
    });
    match found {
        Some(p) => Ok(p),
        None if std::env::var("CI").is_ok_and(|v| v == "true") => {
            panic!("{QEMU} is not installed on CI: .ci/run installs it (apt-get install -y qemu-system-arm)")
        }
        None => Err(format!(
            "skipped: {QEMU} not found on PATH; install it (Debian: apt-get install qemu-system-arm) to run the emulated flight controller"
        )),
    }
}

fn cargo() -> Command {
    let mut cargo = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    cargo.current_dir(workspace());
    cargo
}

fn target_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| workspace().join("target"), PathBuf::from)
}

/// Builds the emulated board's program `bin` (`fwav-fc-qemu` or
/// `step-cost`) as `cargo fw-qemu` does (cached: a second of cargo when
/// nothing changed) and returns its ELF.
pub fn firmware(bin: &str) -> PathBuf {
    let out = cargo()
        .args([
            "build",
            "-p",
            "fwav-fc-qemu",
            "--target",
            "thumbv7em-none-eabihf",
            "--profile",
            "fw",
            "--bin",
            bin,
        ])
        .output()
        .expect("cargo runs");
    assert!(
        out.status.success(),
        "building the emulated firmware failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    target_dir().join("thumbv7em-none-eabihf/fw").join(bin)
}

/// The `fwav` program of this build: next to the test's own build
/// (`cargo test --workspace` builds it with the tests), built if missing.
pub fn fwav_program() -> PathBuf {
    let exe = std::env::current_exe().expect("the test knows its path");
    // target/<profile>/deps/<test> -> target/<profile>/fwav
    let dir = exe
        .parent()
        .and_then(Path::parent)
        .expect("a test runs from target/<profile>/deps");
    let fwav = dir.join("fwav");
    if !fwav.is_file() {
        let status = cargo()
            .args(["build", "-p", "fwav", "--bin", "fwav"])
            .status()
            .expect("cargo runs");
        assert!(status.success(), "building fwav failed");
    }
    fwav
}

/// One report line of the firmware (`fwav-fc-qemu <kind>: key=value ...`,
/// see `firmware/qemu/src/report.rs`).
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// `running`, `cost`, `value`, `stack` or `hard fault`.
    pub kind: String,
    /// Its values.
    pub values: BTreeMap<String, String>,
}

impl Report {
    /// The report of `line`, if it is one.
    pub fn parse(line: &str) -> Option<Report> {
        let rest = line.trim().strip_prefix("fwav-fc-qemu ")?;
        let (kind, values) = rest.split_once(':')?;
        let values = values
            .split_whitespace()
            .filter_map(|kv| kv.split_once('='))
            .map(|(k, v)| (k.to_owned(), v.to_owned()))
            .collect();
        Some(Report {
            kind: kind.to_owned(),
            values,
        })
    }

    /// The value of `key` as a number.
    pub fn number(&self, key: &str) -> f64 {
        let text = self
            .values
            .get(key)
            .unwrap_or_else(|| panic!("report {self:?} has no {key}"));
        text.parse()
            .unwrap_or_else(|_| panic!("report {self:?}: {key}={text} is not a number"))
    }
}

/// QEMU running the firmware, killed when dropped.
pub struct Emulator {
    child: Child,
    ports: Vec<String>,
    /// Each pty kept open here, so QEMU always sees it connected: when the
    /// last client closes a pty QEMU polls it only once a second, and the
    /// next client's first request would wait for that. Also how raw bytes
    /// are written ([`Emulator::write`]) while `fwav`, which opens a port
    /// for itself alone, holds it.
    holders: Vec<File>,
    output: Arc<Mutex<Vec<String>>>,
    reader: Option<JoinHandle<()>>,
}

impl Emulator {
    /// Starts `elf` on QEMU with `serial_ports` UARTs on pseudo-terminals
    /// and `append` as the program's command line; waits for the ports.
    pub fn start(qemu: &Path, elf: &Path, serial_ports: usize, append: Option<&str>) -> Emulator {
        let mut command = Command::new(qemu);
        command.args([
            "-machine",
            "mps2-an386",
            "-cpu",
            "cortex-m4",
            "-display",
            "none",
            "-monitor",
            "none",
            "-semihosting-config",
            "enable=on,target=native",
            "-icount",
            "shift=0",
        ]);
        for _ in 0..serial_ports {
            command.args(["-serial", "pty"]);
        }
        if serial_ports == 0 {
            command.args(["-serial", "none"]);
        }
        if let Some(line) = append {
            command.args(["-append", line]);
        }
        command.arg("-kernel").arg(elf);
        let mut child = command
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap_or_else(|e| panic!("{} does not start: {e}", qemu.display()));
        let output = Arc::new(Mutex::new(Vec::new()));
        let reader = Some(collect_lines(&mut child, &output));
        let mut emulator = Emulator {
            child,
            ports: Vec::new(),
            holders: Vec::new(),
            output,
            reader,
        };
        emulator.ports = emulator.wait_for_ports(serial_ports);
        emulator.holders = emulator.ports.iter().map(|p| hold(p)).collect();
        emulator
    }

    /// QEMU prints `char device redirected to /dev/pts/N (label serialK)`.
    fn wait_for_ports(&mut self, count: usize) -> Vec<String> {
        let deadline = Instant::now() + Duration::from_secs(20);
        loop {
            let ports: Vec<String> = (0..count)
                .filter_map(|k| {
                    let label = format!("(label serial{k})");
                    self.lines().iter().find_map(|l| {
                        l.contains(&label)
                            .then(|| l.split_whitespace().find(|w| w.starts_with("/dev/")))
                            .flatten()
                            .map(str::to_owned)
                    })
                })
                .collect();
            if ports.len() == count {
                return ports;
            }
            if !self.is_running() || Instant::now() > deadline {
                panic!(
                    "QEMU gave no pty for its {count} serial port(s); its output: {:?}",
                    self.lines()
                );
            }
            std::thread::sleep(Duration::from_millis(20));
        }
    }

    /// The pty of UART `k`.
    pub fn port(&self, k: usize) -> &str {
        &self.ports[k]
    }

    /// Writes `bytes` into UART `k`'s pty as a client would, blocking while
    /// QEMU takes them (a byte at a time: 5-15 KB/s measured).
    pub fn write(&mut self, k: usize, bytes: &[u8]) {
        let pty = &self.ports[k];
        self.holders[k]
            .write_all(bytes)
            .unwrap_or_else(|e| panic!("writing {pty}: {e}"));
    }

    /// Everything QEMU and the firmware printed so far (both streams).
    pub fn lines(&self) -> Vec<String> {
        self.output.lock().expect("no reader panics").clone()
    }

    /// The firmware's reports so far.
    pub fn reports(&self) -> Vec<Report> {
        self.lines()
            .iter()
            .filter_map(|l| Report::parse(l))
            .collect()
    }

    /// QEMU has not exited.
    pub fn is_running(&mut self) -> bool {
        matches!(self.child.try_wait(), Ok(None))
    }

    /// Waits (at most `within`) for a report of `kind` after the first
    /// `after` reports; the reports then.
    pub fn wait_for_report(&mut self, kind: &str, after: usize, within: Duration) -> Vec<Report> {
        let deadline = Instant::now() + within;
        loop {
            let reports = self.reports();
            if reports.iter().skip(after).any(|r| r.kind == kind) {
                return reports;
            }
            if !self.is_running() || Instant::now() > deadline {
                panic!(
                    "no `{kind}` report within {within:?}; output: {:?}",
                    self.lines()
                );
            }
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    /// Waits (at most `within`) for QEMU to exit (a program that ends over
    /// semihosting); its status and output.
    pub fn wait(mut self, within: Duration) -> (ExitStatus, Vec<String>) {
        let deadline = Instant::now() + within;
        loop {
            if let Ok(Some(status)) = self.child.try_wait() {
                if let Some(reader) = self.reader.take() {
                    let _ = reader.join();
                }
                return (status, self.lines());
            }
            if Instant::now() > deadline {
                panic!(
                    "QEMU still running after {within:?}; output: {:?}",
                    self.lines()
                );
            }
            std::thread::sleep(Duration::from_millis(20));
        }
    }
}

impl Drop for Emulator {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Collects the child's stdout and stderr lines into `output`.
fn collect_lines(child: &mut Child, output: &Arc<Mutex<Vec<String>>>) -> JoinHandle<()> {
    let stderr = child.stderr.take().expect("piped");
    let sink = output.clone();
    std::thread::spawn(move || {
        for line in BufReader::new(stderr).lines().map_while(Result::ok) {
            sink.lock().expect("no reader panics").push(line);
        }
    });
    let stdout = child.stdout.take().expect("piped");
    let sink = output.clone();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            sink.lock().expect("no reader panics").push(line);
        }
    })
}

/// Opens `pty` without taking it as a controlling terminal and without the
/// exclusive mode `fwav` sets, so `fwav` can still open it.
fn hold(pty: &str) -> File {
    std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .custom_flags(libc::O_NOCTTY)
        .open(pty)
        .unwrap_or_else(|e| panic!("{pty}: {e}"))
}
