//! `hil-sim`: the virtual flight controller on a pseudo-terminal, or
//! scripted scenarios run as fast as possible. Only this file prints.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::{Parser, Subcommand};
use fwav_actuator::params::{PlantParams, DEFAULT_PLANT_TOML};
use fwav_hil_sim::metrics::Report;
use fwav_hil_sim::scenario::{self, Scenario};
use fwav_hil_sim::serve::{ServeError, Server};
use fwav_settings::Shown;

#[derive(Parser)]
#[command(
    name = "hil-sim",
    version,
    about = "Software-in-the-loop flapping actuator running the fwav flight-controller core"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Serve the virtual flight controller on a pseudo-terminal until stopped.
    Serve {
        /// Plant parameters (TOML); default: the shipped reference plant.
        #[arg(long)]
        plant: Option<PathBuf>,
        /// Simulated seconds per wall-clock second.
        #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
        speed: f64,
    },
    /// Run a scenario headless in simulated time and print its metrics.
    Run {
        /// The scenario (TOML).
        scenario: PathBuf,
        /// Plant parameters (TOML); default: the shipped reference plant.
        #[arg(long)]
        plant: Option<PathBuf>,
        /// Print the report as JSON.
        #[arg(long)]
        json: bool,
        /// Draw commanded vs measured angle, current and duty to this PNG
        /// (a file that exists is refused).
        #[arg(long)]
        plot: Option<PathBuf>,
    },
    /// Print the default plant parameters (a commented TOML to start from).
    Plant,
}

fn load_plant(path: Option<&Path>) -> Result<PlantParams> {
    match path {
        None => Ok(PlantParams::default()),
        Some(p) => {
            let text = std::fs::read_to_string(p)
                .with_context(|| format!("cannot read {}", p.display()))?;
            PlantParams::from_toml(&text).with_context(|| format!("{}", p.display()))
        }
    }
}

fn main() -> ExitCode {
    end_quietly_on_a_closed_pipe();
    match run(Cli::parse()) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {}", error_text(&e));
            ExitCode::FAILURE
        }
    }
}

/// A closed output pipe (`hil-sim run S | head -1`) ends the program as it
/// ends `cat`: killed by SIGPIPE, status 141 in a shell, nothing printed.
/// Rust starts a program with SIGPIPE ignored, so a write to a closed
/// pipe fails and `println!` panics (exit 101); the default action,
/// restored first thing, covers every print at once. `serve` writes to
/// its pseudo-terminal, where a vanished client is an I/O error, not
/// SIGPIPE.
#[cfg(unix)]
fn end_quietly_on_a_closed_pipe() {
    // SAFETY: SIG_DFL installs no handler (no code runs in the signal's
    // context); called first in main, before any other thread exists.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

#[cfg(not(unix))]
fn end_quietly_on_a_closed_pipe() {}

/// An error as one line: its message, then each cause in order that the
/// text so far does not already hold (the errors of the scenario, the
/// plant and the link read whole and also hand their cause on as
/// `source()`, which anyhow's `{:#}` printed a second time).
fn error_text(e: &anyhow::Error) -> String {
    let mut text = String::new();
    for cause in e.chain() {
        let part = cause.to_string();
        let part = part.trim_end();
        if text.contains(part) {
            continue;
        }
        if !text.is_empty() {
            text.push_str(": ");
        }
        text.push_str(part);
    }
    text
}

fn run(cli: Cli) -> Result<ExitCode> {
    match cli.command {
        Command::Plant => {
            print!("{DEFAULT_PLANT_TOML}");
        }
        Command::Serve { plant, speed } => {
            let plant = load_plant(plant.as_deref())?;
            let mut server = Server::new(&plant, speed).map_err(|e| match e {
                ServeError::Speed { .. } => anyhow::Error::new(e).context("--speed"),
                e => e.into(),
            })?;
            println!("{}", server.path());
            eprintln!(
                "hil-sim: virtual flight controller on {} ({}x real time); Ctrl-C stops",
                server.path(),
                Shown(speed)
            );
            server.run(|| false)?;
        }
        Command::Run {
            scenario: path,
            plant,
            json,
            plot,
        } => {
            if let Some(png) = &plot {
                // Before the run: the picture is drawn at its end.
                fwav_hil_sim::plot::check_new(png)
                    .with_context(|| format!("--plot {}", png.display()))?;
            }
            let plant = load_plant(plant.as_deref())?;
            let text = std::fs::read_to_string(&path)
                .with_context(|| format!("cannot read {}", path.display()))?;
            let scenario =
                Scenario::from_toml(&text).with_context(|| format!("{}", path.display()))?;
            let (report, trace) = scenario::run_with_trace(&scenario, &plant)?;
            if let Some(png) = plot {
                fwav_hil_sim::plot::draw(&trace, &png)
                    .with_context(|| format!("cannot draw {}", png.display()))?;
            }
            if json {
                println!("{}", serde_json::to_string_pretty(&report)?);
            } else {
                println!(
                    "{}: {} s simulated",
                    path.display(),
                    Shown(report.duration_s)
                );
                print_steady(&report, &scenario);
                println!(
                    "  energy balance residual {:.2e} %",
                    report.energy_balance_residual_pct
                );
                if !report.settle_cycles.is_empty() {
                    let cycles: Vec<String> = report
                        .settle_cycles
                        .iter()
                        .map(|c| c.map_or("not settled".to_owned(), |n| n.to_string()))
                        .collect();
                    println!(
                        "  settling after segment changes (cycles): {}",
                        cycles.join(", ")
                    );
                }
                if let Some(t) = report.time_to_rest_after_link_silence_s {
                    println!("  link silence -> wing at rest: {t:.3} s");
                }
                if let Some(t) = report.time_to_disarm_after_fault_s {
                    println!("  fault -> disarmed: {:.1} ms", t * 1e3);
                }
                println!(
                    "  at the end: armed {}, faults {}",
                    report.armed_at_end, report.faults_at_end
                );
            }
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// The steady-state lines of a report: its window, the tracking, the
/// current and the battery, or why the run has none.
fn print_steady(report: &Report, scenario: &Scenario) {
    let before = match scenario.first_fault_s() {
        Some(t) => format!("before its end and its first fault at {t:.3} s"),
        None => "before its end".to_owned(),
    };
    let Some(steady) = &report.steady else {
        println!("  no steady-state numbers: the run holds no whole reference cycle {before}");
        println!(
            "  current peak {:.3} A (limit {:.2} A)",
            report.peak_current_a, report.current_limit_a
        );
        return;
    };
    let window = if report.measured_cycles < report.cycles_asked {
        format!(
            "the last {} cycles ({} asked; the run holds no more whole ones {before})",
            report.measured_cycles, report.cycles_asked
        )
    } else {
        format!("the last {} cycles", report.measured_cycles)
    };
    println!(
        "  target {:.2} Hz, {:.2} deg; over {window}:",
        steady.target_frequency_hz, steady.target_amplitude_deg
    );
    let frequency = steady.frequency_error_pct.map_or(
        "frequency error not measured (fewer than two upward crossings of the mean)".to_owned(),
        |e| format!("frequency error {e:+.4} %"),
    );
    if steady.target_amplitude_deg > 0.0 {
        println!(
            "  amplitude error {:+.3} %, {frequency}, phase lag {:+.2} deg, RMS tracking error {:.2} %",
            steady.amplitude_error_pct, steady.phase_lag_deg, steady.rms_tracking_error_pct
        );
    } else {
        println!("  the target does not move (amplitude 0): no tracking errors to measure");
    }
    println!(
        "  current peak {:.3} A (limit {:.2} A), RMS {:.3} A; battery {:.3} W, {:.4} J per cycle",
        report.peak_current_a,
        report.current_limit_a,
        steady.rms_current_a,
        steady.battery_power_w,
        steady.energy_per_cycle_j
    );
    println!(
        "  steady state: current peak {:.3} A, terminal voltage peak {:.3} V, duty saturated {:.1} % of the time",
        steady.steady_peak_current_a, steady.steady_peak_voltage_v, steady.duty_saturated_pct
    );
    if steady.duty_saturated_pct > 0.0 {
        println!(
            "  the drive is out of voltage: the profile is not followed at every instant (only its fundamental may be); this demand is beyond the actuator"
        );
    }
}
