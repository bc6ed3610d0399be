//! The run's result files: `summary.json` (rewritten after every stage,
//! `"finished": false` until the end), each structural discipline's
//! `wing-cycle-N.vtu`, and at the end `topology.vtu` and `topology.png`
//! (the final layout), the plots (`convergence.png`, `pareto.png`,
//! `main-effects.png`, `thrust-history.png`), `kinematics.json` and
//! `report.md`. Every file is written atomically. Nothing here computes a
//! stage: it draws and writes what the records hold.

use std::path::Path;

use crate::files::{write_atomic, Existing};
use crate::mdois::error::DesignError;
use crate::mdois::plant::designed_vehicle;
use crate::mdois::profile::write_kinematics;
use crate::mdois::records::{load_kinematics, load_system, load_topology};
use crate::mdois::stage::{layout_densities, Context};
use crate::mdois::state::{Outcome, RunState, Stage};
use crate::mdois::summary::{Summary, FORMAT};
use crate::output::vtu::{self, Field};
use crate::output::DrawingError;
use crate::output::{discipline_plot, layout_picture};
use crate::topology::eslso::{transform, DesignProblem, EslsoResult};
use crate::topology::pressure::PressureHistory;

use super::{plot, report};

/// The summary's file name.
pub const SUMMARY_FILE: &str = FORMAT.file;

/// Writes `summary.json`.
pub fn write_summary(dir: &Path, summary: &Summary) -> Result<(), DesignError> {
    write_atomic(dir, SUMMARY_FILE, summary.to_json()?)?;
    Ok(())
}

/// Writes `wing-cycle-N.vtu`: the wing of `cycle`'s structural discipline
/// with the new layout (`result`), the `analysed` densities, the last SIMP
/// densities, the design domain and the cycle-mean pressure jump. Returns
/// the file's name (relative to `dir`).
pub(crate) fn write_cycle_wing(
    dir: &Path,
    cycle: usize,
    problem: &DesignProblem,
    analysed: &[f64],
    result: &EslsoResult,
    pressure: &PressureHistory,
) -> Result<String, DesignError> {
    let vtu_name = format!("wing-cycle-{cycle}.vtu");
    let layout = layout_densities(&result.layout);
    let mean_pressure: Vec<f64> = (0..problem.mesh.elements.len())
        .map(|e| pressure.samples.iter().map(|s| s[e]).sum::<f64>() / pressure.samples.len() as f64)
        .collect();
    let domain = layout_densities(&problem.design);
    vtu::write(
        &dir.join(&vtu_name),
        &problem.mesh,
        &[
            Field::CellScalar("carbon", &layout),
            Field::CellScalar("carbon_analysed", analysed),
            Field::CellScalar("simp_density", &result.densities),
            Field::CellScalar("design_domain", &domain),
            Field::CellScalar("mean_pressure_jump_pa", &mean_pressure),
        ],
        Existing::Replace,
    )
    .map_err(|source| DesignError::ParaView {
        file: vtu_name.clone(),
        source,
    })?;
    Ok(vtu_name)
}

/// A temporary name for a picture, renamed into place once drawn (the
/// plotting backend writes the file itself).
fn draw_atomic(
    dir: &Path,
    name: &str,
    draw: impl FnOnce(&Path) -> Result<(), DrawingError>,
) -> Result<(), DesignError> {
    let temporary = dir.join(format!("partial-{name}"));
    draw(&temporary).map_err(|source| DesignError::Picture {
        file: name.to_string(),
        source,
    })?;
    let path = dir.join(name);
    std::fs::rename(&temporary, &path).map_err(DesignError::io(&path))
}

/// Writes the final outputs of a run that ended with `outcome`.
pub(crate) fn write_final(
    ctx: &Context<'_>,
    state: &RunState,
    outcome: Outcome,
    summary: &Summary,
) -> Result<(), DesignError> {
    let dir = ctx.dir.as_path();
    let final_cycle = match outcome {
        Outcome::Converged { cycle } => cycle,
        Outcome::CycleCap { max_cycles } => max_cycles + 1,
    };
    let design = ctx.design(final_cycle)?;
    let problem = &ctx.problem;
    let layout = transform(
        &design.densities,
        &problem.design,
        ctx.config.topology.threshold,
    );
    let simp = if final_cycle > 1 {
        load_topology(dir, final_cycle - 1)?.result.densities
    } else {
        design.densities.clone()
    };
    let carbon = layout_densities(&layout);
    let domain = layout_densities(&problem.design);
    vtu::write(
        &dir.join("topology.vtu"),
        &problem.mesh,
        &[
            Field::CellScalar("carbon", &carbon),
            Field::CellScalar("simp_density", &simp),
            Field::CellScalar("design_domain", &domain),
        ],
        Existing::Replace,
    )
    .map_err(|source| DesignError::ParaView {
        file: "topology.vtu".to_string(),
        source,
    })?;
    let converged = matches!(outcome, Outcome::Converged { .. });
    let title = format!(
        "carbon layout of the final design (cycle {final_cycle}{})",
        if converged { "" } else { ", not converged" }
    );
    draw_atomic(dir, "topology.png", |p| {
        layout_picture::planform(&problem.mesh, &layout, &title, 1200, p)
    })?;
    let mut pictures = vec![
        ("convergence.png", "MDOIS convergence: 3D thrust and efficiency, kinematics analysed, layout changes per cycle."),
        ("thrust-history.png", "Thrust coefficient over the last flapping cycle, initial and final design."),
        ("topology.png", "Carbon layout of the final design (black carbon, white mylar only)."),
    ];
    draw_atomic(dir, "convergence.png", |p| {
        plot::convergence(summary, &ctx.config.design_space(), p)
    })?;
    let first = load_system(dir, 1)?;
    let last = load_system(dir, final_cycle)?;
    let curves = [
        ("initial design (cycle 1)".to_string(), &first),
        (format!("final design (cycle {final_cycle})"), &last),
    ];
    draw_atomic(dir, "thrust-history.png", |p| {
        plot::thrust_history(&curves, p)
    })?;
    let last_kinematics = state
        .cycles
        .iter()
        .rev()
        .find(|c| c.get(Stage::Kinematics).is_some())
        .map(|c| c.cycle);
    if let Some(cycle) = last_kinematics {
        let record = load_kinematics(dir, cycle)?;
        draw_atomic(dir, "pareto.png", |p| {
            discipline_plot::pareto(&record.result, p)
        })?;
        draw_atomic(dir, "main-effects.png", |p| {
            discipline_plot::main_effects(&record.result, &ctx.config.design_space(), p)
        })?;
        pictures.push(("pareto.png", "Aerodynamic discipline of the last cycle: net CT and net efficiency of the L18 runs, the response surfaces' Pareto front, the analysed design (the discipline's start) and the three candidates."));
        pictures.push(("main-effects.png", "Aerodynamic discipline of the last cycle: main effects (ANOM level means of the combined objective)."));
    }
    let vehicle = designed_vehicle(dir, &ctx.config, final_cycle, &design.densities)?;
    write_kinematics(
        dir,
        &vehicle,
        &design.kinematics,
        &format!(
            "fwav design: final kinematics of cycle {final_cycle} ({}).",
            if converged {
                "converged"
            } else {
                "cycle cap reached, not converged"
            }
        ),
    )?;
    write_summary(dir, summary)?;
    let cycle_files: Vec<String> = state
        .cycles
        .iter()
        .filter(|c| c.get(Stage::Topology).is_some())
        .map(|c| format!("wing-cycle-{}.vtu", c.cycle))
        .collect();
    write_atomic(
        dir,
        "report.md",
        report::markdown(summary, &pictures, &cycle_files),
    )?;
    Ok(())
}
