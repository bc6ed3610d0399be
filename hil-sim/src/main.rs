//! `hil-sim`: the virtual flight controller on a pseudo-terminal, or
//! scripted scenarios run as fast as possible. Only this file prints.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::{Parser, Subcommand};
use fwav_actuator::params::{PlantParams, DEFAULT_PLANT_TOML};
use fwav_hil_sim::scenario::{self, Scenario};
use fwav_hil_sim::serve::Server;

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
        #[arg(long, default_value_t = 1.0)]
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
        /// Draw commanded vs measured angle, current and duty to this PNG.
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
    match run(Cli::parse()) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: Cli) -> Result<ExitCode> {
    match cli.command {
        Command::Plant => {
            print!("{DEFAULT_PLANT_TOML}");
        }
        Command::Serve { plant, speed } => {
            let plant = load_plant(plant.as_deref())?;
            let mut server = Server::new(&plant, speed)?;
            println!("{}", server.path());
            eprintln!(
                "hil-sim: virtual flight controller on {} ({}x real time); Ctrl-C stops",
                server.path(),
                speed
            );
            server.run(|| false)?;
        }
        Command::Run {
            scenario: path,
            plant,
            json,
            plot,
        } => {
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
                println!("{}: {:.1} s simulated", path.display(), report.duration_s);
                println!(
                    "  target {:.2} Hz, {:.2} deg; over the last {} cycles:",
                    report.target_frequency_hz, report.target_amplitude_deg, report.measured_cycles
                );
                println!(
                    "  amplitude error {:+.3} %, frequency error {:+.4} %, phase lag {:+.2} deg, RMS tracking error {:.2} %",
                    report.amplitude_error_pct,
                    report.frequency_error_pct,
                    report.phase_lag_deg,
                    report.rms_tracking_error_pct
                );
                println!(
                    "  current peak {:.3} A (limit {:.2} A), RMS {:.3} A; battery {:.3} W, {:.4} J per cycle",
                    report.peak_current_a,
                    report.current_limit_a,
                    report.rms_current_a,
                    report.battery_power_w,
                    report.energy_per_cycle_j
                );
                println!(
                    "  steady state: current peak {:.3} A, terminal voltage peak {:.3} V, duty saturated {:.1} % of the time",
                    report.steady_peak_current_a,
                    report.steady_peak_voltage_v,
                    report.duty_saturated_pct
                );
                if report.duty_saturated_pct > 0.0 {
                    println!(
                        "  the drive is out of voltage: the profile is not followed at every instant (only its fundamental may be); this demand is beyond the actuator"
                    );
                }
                println!(
                    "  energy balance residual {:.2e} %",
                    report.energy_balance_residual_pct
                );
                if !report.settle_cycles.is_empty() {
                    println!(
                        "  settling after segment changes (cycles): {:?}",
                        report.settle_cycles
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
