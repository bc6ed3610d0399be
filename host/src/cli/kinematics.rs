//! `fwav kinematics`: the aerodynamic discipline alone — the flapping
//! kinematics chosen on 2D analyses of the mid-span section.

use std::collections::HashSet;
use std::io::IsTerminal as _;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result};
use fwav::aeroelastic::handoff::SectionFile;
use fwav::aeroelastic::kinematics::FlappingKinematics;
use fwav::discipline::cache::{key, EvaluationCache};
use fwav::discipline::kinematic::{
    optimize_reporting, unconstrained, KinematicResult, Weights, EVALUATIONS,
};
use fwav::discipline::section::SectionCase;
use fwav::files::create_new;
use fwav::optimize::nsga2::Nsga2Config;
use fwav::output::discipline_plot;
use indicatif::ProgressBar;

use super::new_files::refuse_taken_in;

/// The command's options.
#[derive(clap::Args)]
pub struct KinematicsArgs {
    /// Configuration (TOML; [wing], [kinematics] (the initial design),
    /// [flight] and [design] (levels, weights, section model) are used); the built-in
    /// FWAV when not given.
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// The mid-span section's deformation over a cycle (`section.json` of
    /// `fwav system-analysis --out`); a rigid flat section when not given.
    #[arg(long)]
    pub section: Option<PathBuf>,
    /// Keep evaluations in this file and reuse them on a rerun.
    #[arg(long)]
    pub cache: Option<PathBuf>,
    /// Draw `main-effects.png` and `pareto.png` into this directory
    /// (created if missing; one that holds either is refused: they are
    /// never overwritten).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Everything (runs, level means, surfaces, Pareto front, candidates)
    /// as JSON on standard output.
    #[arg(long)]
    pub json: bool,
}

/// The pictures `--plot` gets.
const PICTURES: [&str; 2] = ["main-effects.png", "pareto.png"];

/// Runs the command.
pub fn run_command(a: &KinematicsArgs) -> Result<()> {
    let config = super::system::read_config(a.config.as_deref())?;
    let mut case = config.section_case();
    if let Some(path) = &a.section {
        case.deformation = SectionFile::read(path)?.samples;
    }
    if let Some(dir) = &a.plot {
        refuse_taken_in("--plot", dir, &PICTURES, &[])?;
    }
    let cache = match &a.cache {
        Some(path) => EvaluationCache::kept_in(path)?,
        None => EvaluationCache::new(),
    };
    // What the file held before the run: the evaluations the run reuses
    // are counted against it (the file may also hold other runs' results,
    // and other runs may add to it as this one goes).
    let held = cache.keys();
    let initial = config.kinematics();
    let weights = Weights {
        thrust: config.design.thrust_weight,
        efficiency: config.design.efficiency_weight,
    };
    let nsga = Nsga2Config {
        seed: config.design.seed,
        ..Nsga2Config::default()
    };
    let started = Instant::now();
    let bar = evaluation_bar(std::io::stderr().is_terminal());
    let result = optimize_reporting(
        &case,
        &config.design_space(),
        initial,
        weights,
        &nsga,
        None,
        &cache,
        &unconstrained,
        // The total is EVALUATIONS, the bar's length.
        &|done, _| {
            if let Some(bar) = &bar {
                bar.set_position(done as u64);
            }
        },
    );
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let result = result?;
    let seconds = started.elapsed().as_secs_f64();
    let reused = reused(&result, &case, &held);
    if let Some(path) = &a.cache {
        cache.save(path)?;
    }
    if let Some(dir) = &a.plot {
        std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
        let space = config.design_space();
        create_new(&dir.join(PICTURES[0]), |png| {
            discipline_plot::main_effects(&result, &space, png)
        })?;
        create_new(&dir.join(PICTURES[1]), |png| {
            discipline_plot::pareto(&result, png)
        })?;
    }
    if a.json {
        let out = serde_json::json!({
            "section": {
                "chord_m": case.chord,
                "radius_m": case.radius,
                "deforming": !case.deformation.is_empty(),
                "model": case.model.name(),
                "note": result.section.as_ref().map(|m| m.note.as_str()),
            },
            "design_variables": ["frequency_hz", "amplitude_deg", "mean_angle_deg", "stroke_plane_deg"],
            "seed": config.design.seed,
            "seconds": seconds,
            "evaluations_reused": reused,
            "result": result,
        });
        println!("{out:#}");
        return Ok(());
    }
    print_result(&result);
    println!("{seconds:.1} s, {reused} evaluations reused");
    Ok(())
}

/// How many of the distinct designs `result` evaluated `held` (the
/// cache's keys as the run found them) already had.
fn reused(result: &KinematicResult, case: &SectionCase, held: &HashSet<String>) -> usize {
    result
        .evaluations()
        .map(|e| key(case, &e.design))
        .filter(|k| held.contains(k))
        .collect::<HashSet<_>>()
        .len()
}

/// The discipline's progress on a terminal (`live`): a bar of the 2D
/// evaluations done (those the cache served count) and the time since the
/// start, redrawn every half second. With `section_model = "ns"` a run is
/// some twenty evaluations of two to three minutes each, and printed
/// nothing until its end.
fn evaluation_bar(live: bool) -> Option<ProgressBar> {
    live.then(|| {
        super::progress::bar(
            EVALUATIONS as u64,
            "[{elapsed_precise}] {bar:30} 2D evaluation {pos}/{len}",
        )
    })
}

/// The discipline's run as a person reads it: the initial design, each
/// candidate, the surfaces' quality and the choice.
fn print_result(result: &KinematicResult) {
    let show = |d: &FlappingKinematics| {
        format!(
            "{:.2} Hz, ±{:.1}°, mean {:+.1}°, stroke plane {:.1}°",
            d.frequency,
            d.amplitude_deg(),
            d.mean_angle_deg(),
            d.stroke_plane_deg()
        )
    };
    if let Some(m) = &result.section {
        println!("section model: {}", m.note);
    }
    if let Ok(r) = &result.initial.result {
        // The Navier–Stokes model's forces include the friction (no
        // estimate subtracted): no inviscid values beside the net ones.
        let inviscid = |text: String| {
            if r.ct == r.ct_net {
                String::new()
            } else {
                text
            }
        };
        println!(
            "initial   {}: net CT {:.4}{}, net efficiency {:.4}{}",
            show(&result.initial.design),
            r.ct_net,
            inviscid(format!(" (inviscid {:.4})", r.ct)),
            r.efficiency_net,
            inviscid(format!(" (inviscid {:.3})", r.efficiency))
        );
    }
    for c in &result.candidates {
        match &c.confirmation.result {
            Ok(r) => println!(
                "{:<13} {}: net CT {:.4}, net efficiency {:.4}, combined {:.3}{}",
                c.method,
                show(&c.confirmation.design),
                r.ct_net,
                r.efficiency_net,
                c.combined.unwrap_or(f64::NAN),
                c.predicted
                    .map(|p| format!(" (predicted {p:.3})"))
                    .unwrap_or_default()
            ),
            Err(e) => println!(
                "{:<13} {}: failed: {e}",
                c.method,
                show(&c.confirmation.design)
            ),
        }
    }
    let failed = result.runs.iter().filter(|r| r.result.is_err()).count();
    println!(
        "surfaces: R² net CT {:.3}, net efficiency {:.3}; {} Pareto points; {} of 18 array runs failed",
        result.surface_quality[0].0,
        result.surface_quality[1].0,
        result.pareto.len(),
        failed
    );
    match result.chosen {
        Some(i) => println!(
            "chosen: {} ({})",
            result.candidates[i].method,
            show(&result.candidates[i].confirmation.design)
        ),
        None => println!("chosen: the initial design (no candidate beats it)"),
    }
    if result.adoption_margin > 0.0 {
        println!(
            "a candidate had to beat the initial design's combined objective by {:.3}: the \
             scatter of two runs of this flow model, whose scores move with its time step (a \
             flow that sheds leading-edge vortices) or from stroke to stroke",
            result.adoption_margin
        );
    }
    println!(
        "unconstrained (no actuator check without an analysed vehicle): `fwav actuator` judges a choice, `fwav design` constrains every candidate"
    );
}
