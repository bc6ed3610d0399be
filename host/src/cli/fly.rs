//! The link commands of the `fwav` program: `ports`, `upload`, `fc`,
//! `monitor`. Printing happens here; the work is in the library.

use std::io::Write as _;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use anyhow::{Context, Result};
use fwav::device::Device;
use fwav::link::Link;
use fwav::port;
use fwav::profile_file::ProfileFile;
use fwav_protocol::{Command, Status, TelemetrySample};
use serialport::SerialPort;

type Port = Box<dyn SerialPort>;

/// Set by Ctrl-C.
fn interrupted() -> Result<Arc<AtomicBool>> {
    let flag = Arc::new(AtomicBool::new(false));
    let f = flag.clone();
    ctrlc::set_handler(move || f.store(true, Ordering::SeqCst))
        .context("cannot install the Ctrl-C handler")?;
    Ok(flag)
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
    if json {
        println!("{report:#}");
    } else {
        println!(
            "{}: {} accepted {} ({} segment(s), {:.2} s per pass){}",
            path,
            device.hello.firmware,
            file.display(),
            loaded.profile.segments.len(),
            loaded.profile.duration_s(),
            if save { ", saved to flash" } else { "" }
        );
    }
    if start {
        fly(&mut device, duration)?;
    }
    Ok(())
}

/// Arms, starts and keeps the link alive (the device's link failsafe stops
/// the wing within the link timeout otherwise) until Ctrl-C or `duration`;
/// then stops, waits for rest and disarms.
fn fly(device: &mut Device<Port>, duration: Option<f64>) -> Result<()> {
    let stop = interrupted()?;
    device.command(Command::ClearFaults)?;
    device.command(Command::Arm)?;
    device.command(Command::Start)?;
    device.telemetry(true, 100)?; // 100 Hz at a 10 kHz control rate
    eprintln!("flying; Ctrl-C stops the wing and disarms");
    let started = Instant::now();
    let mut last_print = Instant::now();
    while !stop.load(Ordering::SeqCst)
        && duration.is_none_or(|d| started.elapsed().as_secs_f64() < d)
    {
        let status = device.status()?; // also the heartbeat
        device.link.listen(Duration::from_millis(100))?;
        let samples = device.link.take_telemetry();
        if last_print.elapsed() >= Duration::from_millis(500) {
            last_print = Instant::now();
            match samples.last() {
                Some(t) => println!(
                    "{}  amplitude {:.2} deg  frequency {:.3} Hz  current {:.3} A",
                    status_line(&status),
                    t.amplitude_est_rad.to_degrees(),
                    t.frequency_est_hz,
                    t.current_a
                ),
                None => println!("{}", status_line(&status)),
            }
            if !status.armed {
                anyhow::bail!("the device disarmed: {}", status_line(&status));
            }
        }
    }
    device.command(Command::Stop)?;
    let deadline = Instant::now() + Duration::from_secs(5);
    while device.status()?.running && Instant::now() < deadline {
        device.link.listen(Duration::from_millis(100))?;
    }
    device.telemetry(false, 1)?;
    device.command(Command::Disarm)?;
    eprintln!("stopped and disarmed");
    Ok(())
}

/// `fwav fc ACTION`.
pub fn fc(path: &str, action: &str, sets: &[String], json: bool) -> Result<()> {
    let mut device = connect(path)?;
    let simple = match action {
        "arm" => Some(Command::Arm),
        "disarm" => Some(Command::Disarm),
        "start" => Some(Command::Start),
        "stop" => Some(Command::Stop),
        "clear-faults" => Some(Command::ClearFaults),
        "save" => Some(Command::SaveProfile),
        _ => None,
    };
    if let Some(command) = simple {
        device.command(command)?;
        if action == "arm" || action == "start" {
            eprintln!("note: the device disarms after its link timeout without a heartbeat; use `fwav upload --start` or `fwav monitor` to keep the link");
        }
    } else if action == "params" {
        for set in sets {
            let (name, value) = set
                .split_once('=')
                .with_context(|| format!("--set {set:?}: expected name=value"))?;
            let value: f32 = value
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
                    i.name, p.value, i.unit, i.default, i.min, i.max
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

/// `fwav monitor`.
pub fn monitor(
    path: &str,
    csv: Option<&Path>,
    decimation: u16,
    duration: Option<f64>,
) -> Result<()> {
    let stop = interrupted()?;
    let mut device = connect(path)?;
    let mut csv = match csv {
        Some(p) => {
            let mut f = std::io::BufWriter::new(
                std::fs::File::create(p)
                    .with_context(|| format!("cannot create {}", p.display()))?,
            );
            writeln!(f, "time_s,seq,commanded_deg,measured_deg,duty,current_a,amplitude_est_deg,frequency_est_hz")?;
            Some(f)
        }
        None => None,
    };
    device.telemetry(true, decimation.max(1))?;
    eprintln!(
        "monitoring {path} ({}); Ctrl-C stops",
        device.hello.firmware
    );
    let started = Instant::now();
    let mut last_print = Instant::now();
    let mut latest: Option<TelemetrySample> = None;
    while !stop.load(Ordering::SeqCst)
        && duration.is_none_or(|d| started.elapsed().as_secs_f64() < d)
    {
        let status = device.status()?; // heartbeat
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
            match latest {
                Some(t) => println!(
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
                None => println!("{} (no telemetry yet)", status_line(&status)),
            }
        }
    }
    device.telemetry(false, 1)?;
    if let Some(mut f) = csv {
        f.flush()?;
    }
    eprintln!("monitor stopped");
    Ok(())
}
