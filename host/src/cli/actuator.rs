//! `fwav actuator`: can the actuator fly a flapping demand? The margins
//! of motor torque, current and terminal voltage, the limiting one and the
//! verdict, on a hil-sim plant file or on the design file's actuator and
//! wing, and exits with status 1 when the verdict is infeasible. Parses
//! and prints; the library ([`fwav::vehicle`],
//! [`fwav_actuator::feasibility`]) computes.

use std::path::PathBuf;

use anyhow::{Context, Result};
use fwav::vehicle::{AeroSource, TunedSpring, Vehicle};
use fwav_actuator::feasibility::{check, ActuatorLimits, Feasibility, FlappingDemand};
use fwav_actuator::params::PlantParams;
use serde_json::json;

use super::system::read_config;

/// The command's options.
#[derive(clap::Args)]
pub struct ActuatorArgs {
    /// Design configuration (TOML): its `[actuator]` and the wing at its
    /// initial layout; the built-in FWAV's when neither this nor --plant is
    /// given.
    #[arg(long, conflicts_with = "plant")]
    pub config: Option<PathBuf>,
    /// A hil-sim plant file (TOML, `actuator/plant.toml` format), judged
    /// with the firmware's default current limit and reserve.
    #[arg(long)]
    pub plant: Option<PathBuf>,
    /// Flapping frequency, Hz.
    #[arg(long, allow_negative_numbers = true)]
    pub frequency_hz: f64,
    /// Flapping amplitude (half the stroke), deg.
    #[arg(long, allow_negative_numbers = true)]
    pub amplitude_deg: f64,
    /// Mean flapping angle, deg.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub mean_deg: f64,
    /// Machine-readable output.
    #[arg(long)]
    pub json: bool,
}

/// Runs the command.
pub fn run_command(a: &ActuatorArgs) -> Result<()> {
    let demand = FlappingDemand {
        frequency_hz: a.frequency_hz,
        amplitude_deg: a.amplitude_deg,
        mean_deg: a.mean_deg,
    };
    let (verdict, source, vehicle, spring) = match &a.plant {
        Some(path) => {
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("reading {}", path.display()))?;
            let plant =
                PlantParams::from_toml(&text).with_context(|| format!("{}", path.display()))?;
            let verdict = check(&plant, &ActuatorLimits::firmware_default(), &demand)?;
            (
                verdict,
                format!("plant file {}", path.display()),
                None,
                None,
            )
        }
        None => {
            let config = read_config(a.config.as_deref())?;
            let model = config.wing_model()?;
            let vehicle = Vehicle::quasi_steady(
                &model,
                &config.kinematics(),
                &config.flight(),
                config.actuator.actuator(),
            )?;
            let verdict = vehicle.check(&demand)?;
            let spring = vehicle.tuned_spring(&demand)?;
            let source = match &a.config {
                Some(p) => format!("design file {}", p.display()),
                None => "the built-in FWAV's design file".to_string(),
            };
            (verdict, source, Some(vehicle), Some(spring))
        }
    };
    if a.json {
        let report = json!({
            "source": source,
            "verdict": verdict,
            "vehicle": vehicle,
            "tuned_spring": spring,
        });
        println!("{report:#}");
    } else {
        print_text(&verdict, &source, vehicle.as_ref(), spring.as_ref());
    }
    if verdict.feasible {
        Ok(())
    } else {
        Err(CannotFly(verdict).into())
    }
}

/// The verdict is printed, and it is no: the command ends with status 1,
/// as `fwav profile check` does on an invalid profile, so that a script
/// that runs `fwav upload` after it stops here.
#[derive(Debug, thiserror::Error)]
#[error(
    "the actuator cannot fly {}: its {} is below the reserve of {:.1}%; fly a gentler demand or \
     give the drive more reach (the plant file, or the design file's [actuator])",
    .0.demand,
    .0.limiting,
    100.0 * .0.reserve
)]
struct CannotFly(Feasibility);

fn print_text(
    v: &Feasibility,
    source: &str,
    vehicle: Option<&Vehicle>,
    spring: Option<&TunedSpring>,
) {
    println!("actuator: {source}");
    if let Some(vehicle) = vehicle {
        println!(
            "  wing {:.2} g, inertia {:.4e} kg m^2 about the flapping axis (shell model, initial layout)",
            1e3 * vehicle.wing_mass_kg,
            vehicle.wing_inertia_kg_m2
        );
        let how = match vehicle.aero_source {
            AeroSource::QuasiSteady { drag_coefficient } => format!(
                "the quasi-steady blade-element model (C_D = {drag_coefficient}; no system analysis at hand)"
            ),
            AeroSource::SystemAnalysis {
                work_per_cycle_j, ..
            } => format!("the system analysis ({work_per_cycle_j:.4e} J per cycle)"),
        };
        println!(
            "  aerodynamic moment c_a w|w|, c_a = {:.4e} N m s^2 from {how}",
            vehicle.aero_damping_nms2
        );
        println!(
            "  spring {:.4} N m/rad at {:.3} Hz",
            vehicle.spring_nm_per_rad(v.demand.frequency_hz),
            v.demand.frequency_hz
        );
    }
    if let Some(s) = spring {
        println!(
            "  a spring tuned to {:.3} Hz (k = J w^2 = {:.4} N m/rad, J = {:.4e} kg m^2) saves {:.3} A of peak current ({:.3} A RMS) against none",
            s.frequency_hz,
            s.stiffness_nm_per_rad,
            s.inertia_kg_m2,
            s.peak_current_saved_a,
            s.rms_current_saved_a
        );
    }
    println!("demand: {}", v.demand);
    for m in v.margins() {
        println!("  {m}");
    }
    println!("limiting: {}", v.limiting);
    println!(
        "verdict: {} (every margin must be at least the reserve, {:.1}%)",
        if v.feasible { "feasible" } else { "infeasible" },
        100.0 * v.reserve
    );
}
