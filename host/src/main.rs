//! `fwav`: the command-line program. Parses arguments, calls the library,
//! prints. Exit status: 0 success, 1 the input is refused, 2 usage error
//! or results printed with a warning (`warning: ...` on standard error).

#![warn(clippy::too_many_lines)]

use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod cli {
    pub mod actuator;
    pub mod aero;
    pub mod confirm;
    pub mod design;
    pub mod doubtful;
    pub mod fly;
    pub mod kinematics;
    pub mod new_files;
    pub mod progress;
    pub mod study;
    pub mod system;
    pub mod topology;
    pub mod validate;
}
use fwav::profile_file::ProfileFile;
use fwav_protocol::document::ProfileDocument;
use fwav_protocol::{Limits, MAX_FRAME_LEN, MAX_SEGMENTS, PROTOCOL_VERSION, SCHEMA_HASH};
use fwav_settings::Shown;

#[derive(Parser)]
#[command(
    name = "fwav",
    version,
    about = "Design and fly the flapping wing of a flapping-wing air vehicle"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// The whole design (MDOIS): system analysis, then the aerodynamic and
    /// structural disciplines side by side, repeated until no design
    /// variable changes; resumable with --resume.
    Design(cli::design::DesignArgs),
    /// Write the built-in FWAV's configuration as a commented TOML file to
    /// start from.
    Init(cli::design::InitArgs),
    /// Design studies: many design runs of one base configuration with
    /// keys varied (grid, Latin hypercube, list), on a local pool or a
    /// Slurm job array; results.csv, plots and report.md.
    #[command(subcommand)]
    Study(cli::study::StudyCommand),
    /// Kinematics profiles: the file `fwav design` writes and the flight
    /// controller flies.
    #[command(subcommand)]
    Profile(ProfileCommand),
    /// Print the link protocol version, schema hash and frame limits.
    Protocol {
        /// Machine-readable output.
        #[arg(long)]
        json: bool,
    },
    /// 2D unsteady aerodynamics of a plunging/pitching section (cycle-mean
    /// thrust, power, efficiency; Garrick's values for pure plunge).
    Aero2d(cli::aero::Aero2dArgs),
    /// The coupled 3D aeroelastic analysis of the flapping wing (unsteady
    /// vortex lattice + shell): thrust, power, efficiency, and the section
    /// and pressure histories the design disciplines take.
    SystemAnalysis(cli::system::SystemArgs),
    /// The aerodynamic discipline: choose the flapping kinematics (L18,
    /// ANOM, response surfaces + NSGA-II, confirmation runs) on 2D analyses
    /// of the deforming mid-span section. Alone it is unconstrained: no
    /// analysed vehicle, so no actuator check (`fwav design` judges every
    /// candidate on the designed vehicle; ask `fwav actuator` of a result).
    Kinematics(cli::kinematics::KinematicsArgs),
    /// The structural discipline: the carbon reinforcement layout by
    /// nonlinear dynamic topology optimization with equivalent static
    /// loads (ESLSO) under the flapping pressure history.
    Topology(cli::topology::TopologyArgs),
    /// Run the solvers' validation cases (aero2d, shell FE, UVLM,
    /// optimizers) against published and analytic references: value,
    /// reference, error, tolerance and pass for each; exit 1 if any fails.
    Validate(cli::validate::ValidateArgs),
    /// Can the actuator fly a flapping demand? The margins of motor
    /// torque, current and terminal voltage, the limiting one and the
    /// verdict, on a hil-sim plant file or the design file's actuator and
    /// wing; exit 1 if it is infeasible.
    Actuator(cli::actuator::ActuatorArgs),
    /// List serial ports, marking those where an fwav device answers.
    Ports {
        /// Machine-readable output.
        #[arg(long)]
        json: bool,
    },
    /// Upload a profile to a flight controller (or hil-sim): handshake, check
    /// against the device's limits, send, read back and compare.
    Upload {
        /// Serial port (e.g. /dev/ttyACM0, or the path hil-sim serve prints).
        #[arg(long)]
        port: String,
        /// The profile file (JSON).
        file: PathBuf,
        /// Then arm, start and fly, sending the heartbeat, until Ctrl-C,
        /// SIGTERM or SIGHUP (the wing is stopped and disarmed first).
        #[arg(long)]
        start: bool,
        /// Store the profile in the device's flash.
        #[arg(long)]
        save: bool,
        /// With --start: fly this many seconds, then stop.
        #[arg(long, value_parser = cli::fly::duration_seconds, allow_negative_numbers = true)]
        duration: Option<f64>,
        /// Machine-readable output.
        #[arg(long)]
        json: bool,
    },
    /// Flight-controller commands: status, arm, disarm, start, stop,
    /// clear-faults, save, params [--set name=value ...].
    Fc {
        /// Serial port.
        #[arg(long)]
        port: String,
        /// What to do.
        action: String,
        /// With params: set name=value (repeatable).
        #[arg(long = "set")]
        sets: Vec<String>,
        /// Machine-readable output.
        #[arg(long)]
        json: bool,
    },
    /// Live telemetry until Ctrl-C, SIGTERM or SIGHUP (which stop a running
    /// wing first), optionally logged to CSV.
    Monitor {
        /// Serial port.
        #[arg(long)]
        port: String,
        /// Log every sample to this CSV file (a file that exists is refused).
        #[arg(long)]
        csv: Option<PathBuf>,
        /// One sample every N control steps (100 = 100 Hz at 10 kHz), 1 to
        /// 65535.
        #[arg(
            long,
            default_value_t = 100,
            value_parser = clap::value_parser!(u16).range(1..),
            allow_negative_numbers = true
        )]
        decimation: u16,
        /// Stop after this many seconds.
        #[arg(long, value_parser = cli::fly::duration_seconds, allow_negative_numbers = true)]
        duration: Option<f64>,
    },
}

#[derive(Subcommand)]
enum ProfileCommand {
    /// Check a profile file against the flight controller's limits
    /// (the fwav reference vehicle's until a device is connected).
    Check {
        /// The profile file (JSON).
        file: PathBuf,
        /// Machine-readable output.
        #[arg(long)]
        json: bool,
    },
}

fn main() -> ExitCode {
    end_quietly_on_a_closed_pipe();
    let command = Cli::parse().command;
    if holds_the_wing(&command) {
        stop_the_wing_on_a_closed_pipe();
    }
    let result = match command {
        Command::Profile(ProfileCommand::Check { file, json }) => {
            return check_profile(&file, json)
        }
        Command::Protocol { json } => {
            protocol_info(json);
            Ok(())
        }
        Command::Design(args) => cli::design::run_command(&args),
        Command::Init(args) => cli::design::init(&args),
        Command::Study(command) => cli::study::run_command(&command),
        Command::Aero2d(args) => cli::aero::run(&args),
        Command::SystemAnalysis(args) => cli::system::run_command(&args),
        Command::Kinematics(args) => cli::kinematics::run_command(&args),
        Command::Topology(args) => cli::topology::run_command(&args),
        Command::Validate(args) => cli::validate::run_command(&args),
        Command::Actuator(args) => cli::actuator::run_command(&args),
        Command::Ports { json } => cli::fly::ports(json),
        Command::Upload {
            port,
            file,
            start,
            save,
            duration,
            json,
        } => cli::fly::upload(&port, &file, start, save, duration, json),
        Command::Fc {
            port,
            action,
            sets,
            json,
        } => cli::fly::fc(&port, &action, &sets, json),
        Command::Monitor {
            port,
            csv,
            decimation,
            duration,
        } => cli::fly::monitor(&port, csv.as_deref(), decimation, duration),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.is::<cli::doubtful::Doubtful>() => {
            eprintln!("warning: {e}");
            ExitCode::from(2)
        }
        Err(e) => {
            // Never a panic, even with standard error gone too.
            let _ = writeln!(std::io::stderr(), "error: {}", error_text(&e));
            ExitCode::from(1)
        }
    }
}

/// Whether the command keeps a wing flapping while it prints: `upload
/// --start` and `monitor`. Their loops write their lines fallibly and, on
/// a closed output, stop the wing first and then end with the error.
fn holds_the_wing(command: &Command) -> bool {
    matches!(
        command,
        Command::Upload { start: true, .. } | Command::Monitor { .. }
    )
}

/// A closed output pipe (`fwav validate --list | head -1`) ends the
/// program as it ends `cat`: killed by SIGPIPE, status 141 in a shell,
/// nothing printed. Rust starts a program with SIGPIPE ignored, so a
/// write to a closed pipe fails and `println!` panics (exit 101, "failed
/// printing to stdout"); the default action, restored first thing, covers
/// every print of the program (both streams, every command) at once,
/// rather than a fallible writer threaded through each of them. A run
/// ended this way is one killed at any moment, which the design run
/// survives (its files are written atomically, `--resume` goes on). The
/// two commands that keep a wing flapping go back to ignoring it
/// ([`stop_the_wing_on_a_closed_pipe`]).
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

/// For the commands that hold the wing ([`holds_the_wing`]): SIGPIPE
/// ignored again (as Rust starts a program), so that a closed output is
/// a write error their loops handle by stopping the wing, not the end of
/// the program with the wing left flying to the device's link failsafe.
#[cfg(unix)]
fn stop_the_wing_on_a_closed_pipe() {
    // SAFETY: SIG_IGN installs no handler; no other thread exists yet.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_IGN);
    }
}

#[cfg(not(unix))]
fn stop_the_wing_on_a_closed_pipe() {}

/// An error as one line a person reads: its message, then each cause in
/// order that the text so far does not already hold. The library's errors
/// read whole (`cannot read F: <the OS's reason>`) and also hand their
/// cause on as `source()`, which anyhow's `{:#}` prints again, once per
/// level: "No such file or directory" came out twice, serde's message
/// three times.
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

fn protocol_info(json: bool) {
    if json {
        let info = serde_json::json!({
            "protocol_version": PROTOCOL_VERSION,
            "schema_hash": format!("{SCHEMA_HASH:016x}"),
            "max_frame_len_bytes": MAX_FRAME_LEN,
            "max_segments": MAX_SEGMENTS,
        });
        println!("{info:#}");
    } else {
        println!("fwav link protocol v{PROTOCOL_VERSION}, schema {SCHEMA_HASH:016x}");
        println!("frames up to {MAX_FRAME_LEN} bytes, profiles up to {MAX_SEGMENTS} segments");
    }
}

fn check_profile(file: &std::path::Path, json: bool) -> ExitCode {
    let limits = Limits::REFERENCE_FWAV;
    let loaded = match ProfileFile::load(file) {
        Ok(loaded) => loaded,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(1);
        }
    };
    let violations = loaded.violations(&limits);
    if json {
        let report = serde_json::json!({
            "file": file.display().to_string(),
            "valid": violations.is_empty(),
            "errors": violations.iter().map(ToString::to_string).collect::<Vec<_>>(),
            "profile": ProfileDocument::from_profile(&loaded.profile, loaded.document.description.clone()),
            "duration_s": loaded.profile.duration_s(),
        });
        println!("{report:#}");
    } else {
        print_profile(&loaded);
        if violations.is_empty() {
            println!("valid: within the reference FWAV limits");
        } else {
            for v in &violations {
                eprintln!("error: {}: {v}", file.display());
            }
        }
    }
    if violations.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

fn print_profile(loaded: &ProfileFile) {
    let doc = &loaded.document;
    println!("{}", loaded.path.display());
    if !doc.description.is_empty() {
        println!("  {}", doc.description);
    }
    // The file's own numbers, in powers of ten where long: a mistyped
    // 1e300 is shown as written, not as 301 digits or the wire's `inf`.
    println!(
        "  {} segment(s), {:.2} s per pass, then {}",
        doc.segments.len(),
        Shown(doc.segments.iter().map(|s| s.duration_s).sum()),
        doc.on_end
    );
    println!("  #  frequency_hz  amplitude_deg  mean_deg  duration_s  ramp_s  downstroke");
    for (i, s) in doc.segments.iter().enumerate() {
        println!(
            "  {i:<2} {:>12.3} {:>14.2} {:>9.2} {:>11.3} {:>7.3} {:>11.3}",
            Shown(s.frequency_hz),
            Shown(s.amplitude_deg),
            Shown(s.mean_deg),
            Shown(s.duration_s),
            Shown(s.ramp_s),
            Shown(s.downstroke_fraction)
        );
    }
}
