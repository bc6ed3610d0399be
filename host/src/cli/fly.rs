//! The link commands of the `fwav` program: `ports`, `upload`, `fc`,
//! `monitor`. Printing happens here; the work is in the library.

use std::io::Write as _;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use anyhow::{Context, Result};
use fwav::device::{Device, DeviceError};
use fwav::link::{Link, LinkError};
use fwav::port;
use fwav::profile_file::ProfileFile;
use fwav_protocol::{Command, NackReason, Status, TelemetrySample};
use fwav_settings::Shown;
use serialport::SerialPort;

type Port = Box<dyn SerialPort>;

/// Why a `--duration` is refused.
#[derive(Debug, thiserror::Error)]
pub enum DurationError {
    /// Not a number at all.
    #[error("{text:?} is not a number of seconds")]
    NotANumber {
        /// What was given.
        text: String,
    },
    /// NaN, infinite, zero or negative.
    #[error("{} is not a positive number of seconds (a finite one; leave --duration out to run until Ctrl-C)", Shown(*.seconds))]
    NotPositive {
        /// The value given.
        seconds: f64,
    },
}

/// Parses `--duration` of `upload --start` and `monitor`: a positive,
/// finite number of seconds. The argument parser calls it, so a bad value is
/// refused before any port is opened.
pub fn duration_seconds(text: &str) -> Result<f64, DurationError> {
    let seconds: f64 = text.trim().parse().map_err(|_| DurationError::NotANumber {
        text: text.to_owned(),
    })?;
    if seconds > 0.0 && seconds.is_finite() {
        Ok(seconds)
    } else {
        Err(DurationError::NotPositive { seconds })
    }
}

/// Set by Ctrl-C (SIGINT), SIGTERM or SIGHUP: the flight or the monitor then
/// ends through its own shutdown, which stops the wing first.
fn stop_signals() -> Result<Arc<AtomicBool>> {
    let flag = Arc::new(AtomicBool::new(false));
    let f = flag.clone();
    ctrlc::set_handler(move || f.store(true, Ordering::SeqCst))
        .context("cannot install the handler of SIGINT, SIGTERM and SIGHUP")?;
    Ok(flag)
}

/// A line for the user on stderr. A failed write (a hung-up terminal after
/// SIGHUP) is ignored: it must not keep the program from stopping the wing.
fn tell(line: &str) {
    let _ = writeln!(std::io::stderr(), "{line}");
}

/// How a flight or a monitor loop ended when the link did not fail.
enum Ended {
    /// A stop signal or the end of `--duration`.
    Asked,
    /// Its output could not be written (a closed pipe, a hung-up terminal).
    Output(std::io::Error),
}

impl Ended {
    fn into_result(self) -> Result<()> {
        match self {
            Ended::Asked => Ok(()),
            Ended::Output(e) => {
                Err(e).context("cannot write the output (the wing was stopped first)")
            }
        }
    }
}

fn connect(path: &str) -> Result<Device<Port>> {
    let port = port::open(path)?;
    let device = Device::connect(port).with_context(|| path.to_owned())?;
    Ok(device)
}

fn status_json(s: &Status) -> serde_json::Value {
    serde_json::json!({
        "uptime_s": s.uptime_ms as f64 / 1000.0,
        "armed": s.armed,
        "running": s.running,
        "profile_loaded": s.profile_loaded,
        "active_segment": s.active_segment,
        "faults": s.faults.to_string(),
        "last_disarm": s.last_disarm.map(|r| format!("{r:?}")),
        "link": {
            "frames_ok": s.link.frames_ok,
            "dropped": s.link.dropped(),
            "crc_errors": s.link.crc_errors,
            "overlong": s.link.overlong,
            "malformed": s.link.malformed,
            "decode_errors": s.link.decode_errors,
        },
    })
}

fn status_line(s: &Status) -> String {
    format!(
        "armed {} running {} segment {} faults {} last disarm {} | link ok {} dropped {}",
        s.armed,
        s.running,
        s.active_segment.map_or("-".to_owned(), |i| i.to_string()),
        s.faults,
        s.last_disarm.map_or("-".to_owned(), |r| r.to_string()),
        s.link.frames_ok,
        s.link.dropped()
    )
}

/// `fwav ports`.
pub fn ports(json: bool) -> Result<()> {
    let list = port::list();
    let mut rows = Vec::new();
    for p in &list {
        // Probe with one short handshake: does an fwav device answer?
        let answer = port::open(&p.path).ok().and_then(|port| {
            let mut link = Link::new(port);
            link.timeout = Duration::from_millis(150);
            link.retries = 0;
            link.handshake().ok()
        });
        rows.push((p, answer.map(|h| h.firmware.to_string())));
    }
    if json {
        let v: Vec<_> = rows
            .iter()
            .map(|(p, fw)| serde_json::json!({"path": p.path, "usb_id": p.usb_id, "description": p.description, "fwav": fw}))
            .collect();
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else if rows.is_empty() {
        println!("no serial ports found (a hil-sim pseudo-terminal is not listed: use the path it prints)");
    } else {
        for (p, fw) in rows {
            println!(
                "{:<20} {:<10} {:<40} {}",
                p.path,
                p.usb_id.as_deref().unwrap_or("-"),
                p.description.as_deref().unwrap_or(""),
                fw.map_or(String::new(), |f| format!("<- fwav: {f}"))
            );
        }
    }
    Ok(())
}

/// `fwav upload`.
pub fn upload(
    path: &str,
    file: &Path,
    start: bool,
    save: bool,
    duration: Option<f64>,
    json: bool,
) -> Result<()> {
    let loaded = ProfileFile::load(file)?;
    let mut device = connect(path)?;
    device
        .upload(&loaded.profile)
        .with_context(|| format!("uploading {}", file.display()))?;
    if save {
        device
            .command(Command::SaveProfile)
            .context("saving to flash")?;
    }
    let report = serde_json::json!({
        "port": path,
        "device": device.hello.firmware.as_str(),
        "profile": file.display().to_string(),
        "segments": loaded.profile.segments.len(),
        "duration_s": loaded.profile.duration_s(),
        "accepted": true,
        "saved": save,
    });
    // Written fallibly: with --start a closed pipe is an error here, not
    // SIGPIPE (main), and nothing flies yet.
    if json {
        writeln!(std::io::stdout(), "{report:#}")?;
    } else {
        writeln!(
            std::io::stdout(),
            "{}: {} accepted {} ({} segment(s), {:.2} s per pass){}",
            path,
            device.hello.firmware,
            file.display(),
            loaded.profile.segments.len(),
            loaded.profile.duration_s(),
            if save { ", saved to flash" } else { "" }
        )?;
    }
    if start {
        fly(&mut device, duration)?;
    }
    Ok(())
}

/// Arms, starts and sends this session's heartbeat (the device's link
/// failsafe stops the wing within the link timeout otherwise) until a stop
/// signal, `duration` or an output failure; then stops, waits for rest and
/// disarms.
fn fly(device: &mut Device<Port>, duration: Option<f64>) -> Result<()> {
    let stop = stop_signals()?;
    device.command(Command::ClearFaults)?;
    let session = device.arm()?;
    device.command(Command::Start)?;
    device.telemetry(true, 100)?; // 100 Hz at a 10 kHz control rate
    tell("flying; Ctrl-C (or SIGTERM, SIGHUP) stops the wing and disarms");
    let ended = keep_flying(device, session, duration, &stop)?;
    land(device, session)?;
    tell("stopped and disarmed");
    ended.into_result()
}

/// The heartbeat every ~0.1 s and a progress line every 0.5 s, until a stop
/// signal, `duration` or an output failure. An error if the device disarmed
/// by itself or another client armed it since.
fn keep_flying(
    device: &mut Device<Port>,
    session: u32,
    duration: Option<f64>,
    stop: &AtomicBool,
) -> Result<Ended> {
    let started = Instant::now();
    let mut last_print = Instant::now();
    while !stop.load(Ordering::SeqCst)
        && duration.is_none_or(|d| started.elapsed().as_secs_f64() < d)
    {
        match device.heartbeat(session) {
            Err(e) if refused_for(&e, NackReason::NotArmed) => {
                let status = device.status()?;
                anyhow::bail!("the device disarmed: {}", status_line(&status));
            }
            other => other?,
        }
        device.link.listen(Duration::from_millis(100))?;
        let samples = device.link.take_telemetry();
        if last_print.elapsed() >= Duration::from_millis(500) {
            last_print = Instant::now();
            let status = device.status()?;
            let line = match samples.last() {
                Some(t) => format!(
                    "{}  amplitude {:.2} deg  frequency {:.3} Hz  current {:.3} A",
                    status_line(&status),
                    t.amplitude_est_rad.to_degrees(),
                    t.frequency_est_hz,
                    t.current_a
                ),
                None => status_line(&status),
            };
            if let Err(e) = writeln!(std::io::stdout(), "{line}") {
                return Ok(Ended::Output(e));
            }
        }
    }
    Ok(Ended::Asked)
}

/// Stops the wing, keeps the heartbeat while it ramps to rest (at most 5 s),
/// turns the telemetry off and disarms.
fn land(device: &mut Device<Port>, session: u32) -> Result<()> {
    device.command(Command::Stop)?;
    let deadline = Instant::now() + Duration::from_secs(5);
    while Instant::now() < deadline {
        match device.heartbeat(session) {
            // Already at rest and disarmed (a profile ending in stop).
            Err(e) if refused_for(&e, NackReason::NotArmed) => break,
            other => other?,
        }
        if !device.status()?.running {
            break;
        }
        device.link.listen(Duration::from_millis(100))?;
    }
    device.telemetry(false, 1)?;
    device.command(Command::Disarm)?;
    Ok(())
}

/// True if the device refused with `reason`.
fn refused_for(e: &DeviceError, reason: NackReason) -> bool {
    matches!(e, DeviceError::Link(LinkError::Refused { reason: r, .. }) if *r == reason)
}

/// `fwav fc ACTION`.
pub fn fc(path: &str, action: &str, sets: &[String], json: bool) -> Result<()> {
    let mut device = connect(path)?;
    let simple = match action {
        "disarm" => Some(Command::Disarm),
        "start" => Some(Command::Start),
        "stop" => Some(Command::Stop),
        "clear-faults" => Some(Command::ClearFaults),
        "save" => Some(Command::SaveProfile),
        _ => None,
    };
    if action == "arm" {
        let session = device.arm()?;
        tell(&format!("armed, session {session}; note: the device disarms after its link timeout without this session's heartbeats: `fwav upload --start` arms, flies and keeps them"));
    } else if let Some(command) = simple {
        device.command(command)?;
        if action == "start" {
            tell("note: the device disarms after its link timeout without the heartbeats of the session that armed it: `fwav upload --start` arms, flies and keeps them");
        }
    } else if action == "params" {
        for set in sets {
            let (name, value) = set
                .split_once('=')
                .with_context(|| format!("--set {set:?}: expected name=value"))?;
            let value: f64 = value
                .trim()
                .parse()
                .with_context(|| format!("--set {set:?}: {value:?} is not a number"))?;
            device.set_param(name.trim(), value)?;
        }
        let params = device.params()?;
        if json {
            let map: serde_json::Map<String, serde_json::Value> = params
                .iter()
                .map(|p| {
                    (
                        format!("{} [{}]", p.id.info().name, p.id.info().unit),
                        serde_json::json!(p.value),
                    )
                })
                .collect();
            println!("{}", serde_json::Value::Object(map));
        } else {
            for p in params {
                let i = p.id.info();
                println!(
                    "{:<20} {:>12} {:<14} (default {}, range {}..={})",
                    i.name,
                    p.value,
                    i.unit,
                    i.default,
                    Shown(i.bounds[0]),
                    Shown(i.bounds[1])
                );
            }
        }
        return Ok(());
    } else if action != "status" {
        anyhow::bail!("unknown action {action:?}: status, arm, disarm, start, stop, clear-faults, save or params");
    }
    let status = device.status()?;
    if json {
        println!("{:#}", status_json(&status));
    } else {
        println!("{}: {}", path, device.hello.firmware);
        println!("{}", status_line(&status));
    }
    Ok(())
}

/// `fwav monitor`: live telemetry until a stop signal or `duration`. On
/// Ctrl-C, SIGTERM or SIGHUP a running wing is stopped (it ramps to rest)
/// before the monitor ends. Its status queries never keep a wing armed: only
/// the heartbeats of the client that armed it do.
pub fn monitor(
    path: &str,
    csv: Option<&Path>,
    decimation: u16,
    duration: Option<f64>,
) -> Result<()> {
    let stop = stop_signals()?;
    // The log's name is checked before the link is opened: a file that
    // exists is never overwritten.
    let csv_file = match csv {
        Some(p) => {
            super::new_files::refuse_taken([("--csv", p)])?;
            // New only: one made since the check is refused too.
            let file = std::fs::OpenOptions::new()
                .write(true)
                .create_new(true)
                .open(p)
                .with_context(|| format!("--csv {}: cannot create it", p.display()))?;
            Some(file)
        }
        None => None,
    };
    let mut device = connect(path).inspect_err(|_| {
        // The log was made above, empty: it goes with the run that failed.
        if let Some(p) = csv {
            let _ = std::fs::remove_file(p);
        }
    })?;
    let mut csv = match csv_file {
        Some(file) => {
            let mut f = std::io::BufWriter::new(file);
            writeln!(f, "time_s,seq,commanded_deg,measured_deg,duty,current_a,amplitude_est_deg,frequency_est_hz")?;
            Some(f)
        }
        None => None,
    };
    device.telemetry(true, decimation)?;
    tell(&format!(
        "monitoring {path} ({}); Ctrl-C (or SIGTERM, SIGHUP) stops the wing and the monitor",
        device.hello.firmware
    ));
    let ended = watch(&mut device, csv.as_mut(), duration, &stop)?;
    if stop.load(Ordering::SeqCst) && device.status()?.running {
        device.command(Command::Stop)?;
        tell("stopped the wing");
    }
    device.telemetry(false, 1)?;
    if let Some(mut f) = csv {
        f.flush()?;
    }
    tell("monitor stopped");
    ended.into_result()
}

/// The monitor's loop: telemetry to the CSV file, a line every 0.25 s.
fn watch(
    device: &mut Device<Port>,
    mut csv: Option<&mut std::io::BufWriter<std::fs::File>>,
    duration: Option<f64>,
    stop: &AtomicBool,
) -> Result<Ended> {
    let started = Instant::now();
    let mut last_print = Instant::now();
    let mut latest: Option<TelemetrySample> = None;
    while !stop.load(Ordering::SeqCst)
        && duration.is_none_or(|d| started.elapsed().as_secs_f64() < d)
    {
        device.link.listen(Duration::from_millis(100))?;
        for t in device.link.take_telemetry() {
            if let Some(f) = csv.as_mut() {
                writeln!(
                    f,
                    "{:.6},{},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4}",
                    t.time_us as f64 * 1e-6,
                    t.seq,
                    t.commanded_rad.to_degrees(),
                    t.measured_rad.to_degrees(),
                    t.duty,
                    t.current_a,
                    t.amplitude_est_rad.to_degrees(),
                    t.frequency_est_hz
                )?;
            }
            latest = Some(t);
        }
        if last_print.elapsed() >= Duration::from_millis(250) {
            last_print = Instant::now();
            let status = device.status()?;
            let line = match latest {
                Some(t) => format!(
                    "t {:9.3} s  cmd {:+7.2} deg  meas {:+7.2} deg  amp {:6.2} deg  f {:6.3} Hz  I {:+6.3} A  duty {:+5.2}  faults {}",
                    t.time_us as f64 * 1e-6,
                    t.commanded_rad.to_degrees(),
                    t.measured_rad.to_degrees(),
                    t.amplitude_est_rad.to_degrees(),
                    t.frequency_est_hz,
                    t.current_a,
                    t.duty,
                    status.faults
                ),
                None => format!("{} (no telemetry yet)", status_line(&status)),
            };
            if let Err(e) = writeln!(std::io::stdout(), "{line}") {
                return Ok(Ended::Output(e));
            }
        }
    }
    Ok(Ended::Asked)
}
