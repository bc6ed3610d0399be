//! `fwav topology`: the structural discipline alone — the carbon
//! reinforcement layout by ESLSO under the flapping pressure history.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result};
use fwav::aeroelastic::handoff::PressureFile;
use fwav::aeroelastic::run;
use fwav::files::{create_new, write_new, Existing};
use fwav::output::layout_picture;
use fwav::output::vtu::{self, Field};
use fwav::topology::eslso::{optimize, DesignProblem, EslsoProgress, EslsoResult};
use fwav::topology::pressure::PressureHistory;

use super::new_files::refuse_taken_in;

/// The command's options.
#[derive(clap::Args)]
pub struct TopologyArgs {
    /// Configuration (TOML; [wing] (the starting design), [topology] and,
    /// without --pressure, [kinematics], [flight] and [analysis]); the
    /// built-in FWAV when not given.
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// The pressure history (`pressure.json` of `fwav system-analysis
    /// --out`); without it the system analysis is run first.
    #[arg(long)]
    pub pressure: Option<PathBuf>,
    /// Write `layout.vtu`, `layout.png`, `cycles.csv` and `topology.json`
    /// here (created if missing; a directory that holds any of them is
    /// refused: they are never overwritten).
    #[arg(long, default_value = "topology")]
    pub out: PathBuf,
    /// Machine-readable summary on standard output.
    #[arg(long)]
    pub json: bool,
    /// No progress lines.
    #[arg(long)]
    pub quiet: bool,
}

/// Runs the command.
pub fn run_command(a: &TopologyArgs) -> Result<()> {
    let config = super::system::read_config(a.config.as_deref())?;
    let wing = config.wing_model()?;
    let elements = wing.wing.mesh.elements.len();
    // The inputs are checked before the outputs' names.
    let given = match &a.pressure {
        Some(path) => Some(
            PressureHistory::from_file(PressureFile::read(path)?, elements)
                .with_context(|| format!("{}", path.display()))?,
        ),
        None => None,
    };
    refuse_taken_in("--out", &a.out, &WRITTEN, &[])?;
    let show = !a.quiet && std::io::stderr().is_terminal();
    let started = Instant::now();
    let pressure = match given {
        Some(pressure) => pressure,
        None => {
            let result = run(
                &wing,
                &config.kinematics(),
                &config.flight(),
                &config.analysis,
                0,
                |done, total| {
                    if show && (done % 10 == 0 || done == total) {
                        eprint!("\rsystem analysis: step {done}/{total}");
                        if done == total {
                            eprintln!();
                        }
                    }
                },
            )?;
            // As `fwav design` does: no layout on an analysis that is not
            // to be trusted (`fwav system-analysis` prints its numbers).
            let doubts = result.doubts(&config.analysis, config.wing.semi_span_m);
            if let Some(doubt) = doubts.first() {
                anyhow::bail!(
                    "the system analysis run for the pressure history cannot be trusted: {doubt}; \
                     the topology stops rather than lay out on it"
                );
            }
            PressureHistory::new(result.dt_s, result.pressure_history, elements)?
        }
    };
    let problem = DesignProblem::wing(
        &wing.wing,
        fwav::shell::material::Layer::CARBON,
        fwav::shell::material::Layer::MYLAR,
    );
    let settings = config.topology.settings();
    let result = optimize(&problem, &pressure, &wing.densities, &settings, |p| {
        if !show {
            return;
        }
        if let EslsoProgress::Step { cycle, done, total } = p {
            if done % 5 == 0 {
                eprint!("\rESLSO cycle {cycle}: dynamic analysis step {done}/{total}");
            }
        }
        if let EslsoProgress::Cycle(c) = p {
            eprintln!(
                "\r
ESLSO cycle {}: strain energy {:.4e} J, mass fraction {:.3}, peak displacement {:.1} mm, {} elements changed ({:.0} s)",
                c.cycle,
                c.strain_energy_j,
                c.mass_fraction,
                1e3 * c.peak_displacement_m,
                c.changed,
                c.analysis_s + c.optimization_s
            );
        }
    })?;
    let seconds = started.elapsed().as_secs_f64();
    write_outputs(a, &problem, &result)?;
    let mass = problem.mass_fraction(&result.layout_densities());
    if a.json {
        let summary = serde_json::json!({
            "converged": result.converged,
            "cycles": result.cycles,
            "layout_mass_fraction": mass,
            "carbon_elements": result.carbon_elements(),
            "elements": elements,
            "seconds": seconds,
            "out": a.out,
        });
        println!("{summary:#}");
    } else {
        for c in &result.cycles {
            println!(
                "cycle {}: strain energy {:.4e} J, mass fraction {:.3}, {} elements changed",
                c.cycle, c.strain_energy_j, c.mass_fraction, c.changed
            );
        }
        let outcome = if result.converged {
            format!(
                "converged (the last cycle flipped at most {}% of the design elements)",
                100.0 * settings.layout_tolerance
            )
        } else {
            "NOT converged (the layout still changed at the cycle cap)".to_string()
        };
        println!(
            "{outcome} after {} cycles: carbon mass fraction {mass:.3}; results in {} ({seconds:.0} s)",
            result.cycles.len(),
            a.out.display()
        );
    }
    Ok(())
}

/// The files `--out` gets.
const WRITTEN: [&str; 4] = ["layout.vtu", "layout.png", "cycles.csv", "topology.json"];

/// Writes the results into `--out`, whose files were refused before the
/// run if taken, and are not replaced if taken since.
fn write_outputs(a: &TopologyArgs, problem: &DesignProblem, result: &EslsoResult) -> Result<()> {
    let dir = &a.out;
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let layout = result.layout_densities();
    let design: Vec<f64> = problem
        .design
        .iter()
        .map(|&d| f64::from(u8::from(d)))
        .collect();
    vtu::write(
        &dir.join("layout.vtu"),
        &problem.mesh,
        &[
            Field::CellScalar("carbon", &layout),
            Field::CellScalar("simp_density", &result.densities),
            Field::CellScalar("design_domain", &design),
        ],
        Existing::Keep,
    )?;
    let title = format!(
        "carbon layout after {} ESLSO cycles{}",
        result.cycles.len(),
        if result.converged {
            ""
        } else {
            " (not converged)"
        }
    );
    create_new(&dir.join("layout.png"), |png| {
        layout_picture::planform(&problem.mesh, &result.layout, &title, 1200, png)
    })?;
    let mut csv = String::from(
        "cycle,strain_energy_j,mass_fraction,peak_displacement_m,newton_iterations,simp_iterations,simp_converged,simp_objective_j,changed,flip_margin,analysis_s,optimization_s\n",
    );
    for c in &result.cycles {
        csv.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{},{}\n",
            c.cycle,
            c.strain_energy_j,
            c.mass_fraction,
            c.peak_displacement_m,
            c.newton_iterations,
            c.simp_iterations,
            c.simp_converged,
            c.simp_objective_j,
            c.changed,
            c.flip_margin,
            c.analysis_s,
            c.optimization_s
        ));
    }
    write_new(&dir.join("cycles.csv"), csv)?;
    let text = serde_json::json!({
        "description": "ESLSO result: carbon (1) or mylar only (0) per shell element, the last SIMP densities, every cycle",
        "converged": result.converged,
        "carbon": layout,
        "simp_density": result.densities,
        "cycles": result.cycles,
    })
    .to_string();
    write_new(&dir.join("topology.json"), text)?;
    Ok(())
}
