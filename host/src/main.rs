//! `fwav`: the command-line program. Parses arguments, calls the library,
//! prints. Exit status: 0 success, 1 the input is refused, 2 usage error.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use fwav::profile_file::ProfileFile;
use fwav_protocol::document::ProfileDocument;
use fwav_protocol::{Limits, MAX_FRAME_LEN, MAX_SEGMENTS, PROTOCOL_VERSION, SCHEMA_HASH};

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
    let cli = Cli::parse();
    match cli.command {
        Command::Profile(ProfileCommand::Check { file, json }) => check_profile(&file, json),
        Command::Protocol { json } => {
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
                println!(
                    "frames up to {MAX_FRAME_LEN} bytes, profiles up to {MAX_SEGMENTS} segments"
                );
            }
            ExitCode::SUCCESS
        }
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
    println!(
        "  {} segment(s), {:.2} s per pass, then {:?}",
        doc.segments.len(),
        loaded.profile.duration_s(),
        doc.on_end
    );
    println!("  #  frequency_hz  amplitude_deg  mean_deg  duration_s  ramp_s  downstroke");
    for (i, s) in doc.segments.iter().enumerate() {
        println!(
            "  {i:<2} {:>12.3} {:>14.2} {:>9.2} {:>11.3} {:>7.3} {:>11.3}",
            s.frequency_hz,
            s.amplitude_deg,
            s.mean_deg,
            s.duration_s,
            s.ramp_s,
            s.downstroke_fraction
        );
    }
}
