//! `fwav system-analysis`: the coupled 3D aeroelastic analysis of the
//! flapping wing (UVLM + shell), writing what the two disciplines take.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result};
use fwav::aeroelastic::handoff;
use fwav::aeroelastic::{run, SystemResult};
use fwav::config::SystemConfig;
use fwav::files::Existing;
use fwav::output::wing_series::write_series;
use fwav::periodicity::PERIODIC_CHANGE;

use super::doubtful::Doubtful;
use super::new_files::refuse_taken_in;

/// The command's options.
#[derive(clap::Args)]
pub struct SystemArgs {
    /// Configuration (TOML: [wing], [kinematics], [flight], [analysis]);
    /// the built-in FWAV when not given.
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// Rigid wing: the lattice follows the flapping, no structure.
    #[arg(long)]
    pub rigid: bool,
    /// Write the results here: `section.json` (the mid-span section
    /// history, `fwav aero2d --deformation` format), `pressure.json` (the
    /// pressure jump per shell element over the last cycle), `steps.csv`,
    /// and `wing.pvd`/`wake.pvd` with their `.vtu` files (created if
    /// missing; a directory that holds any of these files is refused:
    /// they are never overwritten).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Machine-readable summary on standard output.
    #[arg(long)]
    pub json: bool,
    /// No progress line.
    #[arg(long)]
    pub quiet: bool,
}

/// The configuration file at `path`, checked, or the built-in FWAV's.
pub fn read_config(path: Option<&Path>) -> Result<SystemConfig> {
    let Some(path) = path else {
        return Ok(SystemConfig::default());
    };
    let text =
        std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
    SystemConfig::from_toml(&text).with_context(|| format!("{}", path.display()))
}

/// The configuration file at `path`, its keys and types checked, its
/// values not ([`SystemConfig::parse_unchecked`]): the one `fwav design
/// --resume DIR --config FILE` compares with the run's own.
pub fn read_config_unchecked(path: &Path) -> Result<SystemConfig> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
    SystemConfig::parse_unchecked(&text).with_context(|| format!("{}", path.display()))
}

/// Runs the command.
pub fn run_command(a: &SystemArgs) -> Result<()> {
    let mut config = read_config(a.config.as_deref())?;
    if a.rigid {
        config.analysis.rigid = true;
    }
    let wing = config.wing_model()?;
    if let Some(dir) = &a.out {
        refuse_taken_in("--out", dir, &WRITTEN, &SERIES)?;
    }
    let show = !a.quiet && std::io::stderr().is_terminal();
    let started = Instant::now();
    let snapshot_every = if a.out.is_some() { 2 } else { 0 };
    let result = run(
        &wing,
        &config.kinematics(),
        &config.flight(),
        &config.analysis,
        snapshot_every,
        |done, total| {
            if show && (done % 10 == 0 || done == total) {
                eprint!(
                    "\rsystem analysis: step {done}/{total}, {:.1} s",
                    started.elapsed().as_secs_f64()
                );
                if done == total {
                    eprintln!();
                }
            }
        },
    )?;
    let seconds = started.elapsed().as_secs_f64();
    if let Some(dir) = &a.out {
        write_outputs(dir, &wing.wing.mesh.elements, &result)?;
    }
    let steps = result.steps.len();
    let steps_per_cycle = config.analysis.steps_per_cycle;
    let coupling = result.coupling_effort();
    let (mean_sub, max_sub) = (coupling.mean, coupling.max);
    let tip_amplitude = result.tip_deflection_amplitude_m(steps_per_cycle);
    let drive_power = result.mean_drive_power_w(&config.kinematics(), steps_per_cycle);
    let doubts: Vec<String> = result
        .doubts(&config.analysis, config.wing.semi_span_m)
        .iter()
        .map(ToString::to_string)
        .collect();
    if a.json {
        let summary = serde_json::json!({
            "model": if config.analysis.rigid { "uvlm, rigid wing" } else { "uvlm + shell (floating frame), strongly coupled" },
            "mean_ct": result.means.ct,
            "mean_cl": result.means.cl,
            "mean_cp": result.means.cp,
            "efficiency": result.means.efficiency,
            "ct_change_last_two_cycles": result.means.ct_change_last_two_cycles,
            "ct_change_of_swing": result.ct_change_of_swing(steps_per_cycle),
            "mean_drive_power_w": drive_power,
            "tip_deflection_amplitude_m": tip_amplitude,
            "wing_mass_kg": result.wing_mass_kg,
            "reference_area_m2": result.reference_area_m2,
            "dt_s": result.dt_s,
            "steps": steps,
            "mean_subiterations": mean_sub,
            "max_subiterations": max_sub,
            "seconds": seconds,
            "seconds_per_cycle": seconds / config.analysis.cycles as f64,
            "seconds_per_step": seconds / steps as f64,
            "out": a.out.as_ref().map(|p| p.display().to_string()),
            "doubts": doubts,
        });
        println!("{summary:#}");
    } else {
        println!(
            "last cycle: CT {:.4}  CL {:.4}  CP {:.4}  efficiency {:.3}",
            result.means.ct, result.means.cl, result.means.cp, result.means.efficiency
        );
        let periodic = result
            .ct_change_of_swing(steps_per_cycle)
            .map_or(String::new(), |c| {
                format!(
                    " ({:.1}% of its size or swing; periodic within {:.0}%)",
                    100.0 * c,
                    100.0 * PERIODIC_CHANGE
                )
            });
        println!(
            "mean CT change over the last cycle {:+.2}%{periodic}, mean drive power {:.4} W",
            100.0 * result.means.ct_change_last_two_cycles,
            drive_power
        );
        println!(
            "tip deflection amplitude {:.3} mm, wing mass {:.2} g, coupling {:.1} sub-iterations a step (max {max_sub})",
            1e3 * tip_amplitude,
            1e3 * result.wing_mass_kg,
            mean_sub
        );
        println!(
            "{steps} steps in {seconds:.1} s ({:.2} s a cycle, {:.1} ms a step)",
            seconds / config.analysis.cycles as f64,
            1e3 * seconds / steps as f64
        );
        if let Some(dir) = &a.out {
            println!("results in {}", dir.display());
        }
    }
    if doubts.is_empty() {
        Ok(())
    } else {
        Err(Doubtful(doubts).into())
    }
}

/// The files `--out` gets besides [`SERIES`]: the handoff's and the
/// series' collections.
const WRITTEN: [&str; 5] = [
    handoff::FILES[0],
    handoff::FILES[1],
    handoff::FILES[2],
    "wing.pvd",
    "wake.pvd",
];

/// The numbered files `--out` gets (start, end of the name).
const SERIES: [(&str, &str); 2] = [("wing-", ".vtu"), ("wake-", ".vtu")];

/// Writes the results into `dir`, whose files were refused before the
/// run if taken, and are not replaced if taken since.
fn write_outputs(dir: &Path, elements: &[[usize; 4]], result: &SystemResult) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    handoff::write(dir, result, Existing::Keep)?;
    write_series(dir, elements, &result.snapshots, Existing::Keep)?;
    Ok(())
}
