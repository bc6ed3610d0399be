//! `fwav design`: the whole MDOIS design run (system analysis, both
//! disciplines, repeated until no design variable changes), resumable; and
//! `fwav init`: the default configuration as a commented TOML file.

use std::collections::BTreeMap;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use anyhow::{bail, Context, Result};
use fwav::config::cost::CostEstimate;
use fwav::config::template::commented_toml;
use fwav::config::SystemConfig;
use fwav::mdois::summary::Summary;
use fwav::mdois::{resume, start, Event, Outcome, Progress, RunOptions, Stage};

/// `fwav design`'s options.
#[derive(clap::Args)]
pub struct DesignArgs {
    /// Configuration (TOML; `fwav init` writes the default to start from);
    /// the built-in FWAV when not given. With --resume it must equal the
    /// run's own `config.toml`.
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// Write the run here: `summary.json`, `report.md`, the plots,
    /// `topology.vtu`/`.png`, `wing-cycle-N.vtu`, `kinematics.json`, and
    /// every stage's files under `cycle-N/` with `state.json`.
    #[arg(long, default_value = "design", conflicts_with = "resume")]
    pub out: PathBuf,
    /// Continue the interrupted run in this directory without redoing its
    /// finished stages.
    #[arg(long, value_name = "DIR")]
    pub resume: Option<PathBuf>,
    /// No progress display.
    #[arg(long)]
    pub quiet: bool,
    /// The summary as JSON on standard output.
    #[arg(long)]
    pub json: bool,
    /// Run even if the estimated memory or time is far beyond the
    /// built-in design's (without it such a run asks on a terminal and is
    /// refused otherwise).
    #[arg(long)]
    pub yes: bool,
}

/// `fwav init`'s options.
#[derive(clap::Args)]
pub struct InitArgs {
    /// The file to write.
    #[arg(long, default_value = "fwav.toml")]
    pub out: PathBuf,
    /// Overwrite the file if it exists.
    #[arg(long)]
    pub force: bool,
}

/// Runs `fwav init`.
pub fn init(a: &InitArgs) -> Result<()> {
    if a.out.exists() && !a.force {
        bail!("{} exists; use --force to overwrite it", a.out.display());
    }
    let text = commented_toml(&SystemConfig::default())?;
    let dir = match a.out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let name = a
        .out
        .file_name()
        .with_context(|| format!("{} is not a file name", a.out.display()))?
        .to_string_lossy()
        .into_owned();
    fwav::files::write_atomic(&dir, &name, text)?;
    println!(
        "wrote {}: the built-in FWAV's configuration; edit it and run `fwav design --config {}`",
        a.out.display(),
        a.out.display()
    );
    Ok(())
}

/// The live progress line on a terminal: the latest report of each stage
/// running, redrawn at most every 0.2 s; stage ends on their own lines.
struct Display {
    live: Mutex<(BTreeMap<u8, String>, Option<Instant>)>,
}

fn stage_key(stage: Stage) -> u8 {
    match stage {
        Stage::System => 0,
        Stage::Kinematics => 1,
        Stage::Topology => 2,
    }
}

fn clock(d: Duration) -> String {
    let s = d.as_secs();
    format!("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60)
}

impl Display {
    fn update(&self, p: &Progress) {
        let mut guard = self.live.lock().unwrap_or_else(|e| e.into_inner());
        let (live, drawn) = &mut *guard;
        let key = stage_key(p.stage);
        let permanent = match p.event {
            Event::Reused => Some(format!(
                "cycle {}, {}: finished earlier, reused",
                p.cycle, p.stage
            )),
            Event::Started => {
                live.insert(key, format!("{}: starting", p.stage));
                None
            }
            Event::Advanced { done, total, inner } => {
                let what = match (p.stage, inner) {
                    (Stage::System, _) => format!("step {done}/{total}"),
                    (Stage::Kinematics, _) => format!("2D evaluation {done}/{total}"),
                    (Stage::Topology, Some(i)) => {
                        format!("ESLSO cycle {i}, dynamic step {done}/{total}")
                    }
                    (Stage::Topology, None) => format!("{done}/{total}"),
                };
                live.insert(key, format!("{}: {what}", p.stage));
                None
            }
            Event::InnerCycle {
                inner,
                elements_changed,
            } => Some(format!(
                "cycle {}, {}: ESLSO cycle {inner} changed {elements_changed} elements",
                p.cycle, p.stage
            )),
            Event::Finished { seconds } => {
                live.remove(&key);
                Some(format!(
                    "cycle {}, {}: done in {seconds:.1} s",
                    p.cycle, p.stage
                ))
            }
        };
        if let Some(line) = permanent {
            eprintln!("\r\x1b[2K{line} [{}]", clock(p.elapsed));
            *drawn = None;
        }
        let due = drawn.is_none_or(|t| t.elapsed() >= Duration::from_millis(200));
        if due && !live.is_empty() {
            let text: Vec<&str> = live.values().map(String::as_str).collect();
            eprint!(
                "\r\x1b[2Kcycle {}: {} [{}]",
                p.cycle,
                text.join(" | "),
                clock(p.elapsed)
            );
            *drawn = Some(Instant::now());
        }
    }
}

/// Runs `fwav design`.
pub fn run_command(a: &DesignArgs) -> Result<()> {
    let show = !a.quiet && std::io::stderr().is_terminal();
    let display = Display {
        live: Mutex::new((BTreeMap::new(), None)),
    };
    let progress = |p: &Progress| {
        if show {
            display.update(p);
        }
    };
    let options = RunOptions::default();
    let run = match &a.resume {
        Some(dir) => {
            let config = match &a.config {
                Some(path) => Some(super::system::read_config(Some(path))?),
                None => None,
            };
            resume(dir, config.as_ref(), &options, &progress)
                .with_context(|| format!("resuming the design run in {}", dir.display()))?
        }
        None => {
            let config = super::system::read_config(a.config.as_deref())?;
            confirm_cost(&CostEstimate::of(&config), a.yes)?;
            start(&config, &a.out, &options, &progress)
                .with_context(|| format!("design run in {}", a.out.display()))?
        }
    };
    if show {
        eprint!("\r\x1b[2K");
    }
    if a.json {
        println!("{}", serde_json::to_string_pretty(&run.summary)?);
    } else {
        print_summary(&run.summary, &run.dir);
        println!(
            "{} stage(s) computed, {} reused",
            run.stages_computed, run.stages_reused
        );
    }
    match run.outcome {
        Some(Outcome::Converged { .. }) | Some(Outcome::CycleCap { .. }) => Ok(()),
        None => bail!("the run stopped before its end"),
    }
}

/// Lets a run far beyond the built-in design's cost go ahead only with
/// `--yes` or a "y" typed on a terminal; prints the estimate either way.
fn confirm_cost(estimate: &CostEstimate, yes: bool) -> Result<()> {
    if !estimate.is_far_beyond_default() {
        return Ok(());
    }
    eprintln!("this design run needs {estimate}");
    if yes {
        return Ok(());
    }
    let stdin = std::io::stdin();
    if stdin.is_terminal() {
        eprint!("run it? [y/N] ");
        let mut answer = String::new();
        stdin.read_line(&mut answer)?;
        if matches!(answer.trim(), "y" | "Y" | "yes") {
            return Ok(());
        }
    }
    bail!(
        "not started: the run is far beyond the built-in design's cost; pass --yes to run it \
         anyway, or choose a coarser mesh ([wing] span_elements, chord_elements)"
    )
}

fn print_summary(s: &Summary, dir: &Path) {
    for c in &s.cycles {
        let k = &c.kinematics;
        let mut line = format!(
            "cycle {}: {:.2} Hz, ±{:.1}°, mean {:+.1}°, stroke plane {:.1}°, carbon {:.3}",
            c.cycle,
            k.frequency,
            k.amplitude_deg(),
            k.mean_angle_deg(),
            k.stroke_plane_deg(),
            c.carbon_mass_fraction
        );
        if let Some(sys) = &c.system {
            line.push_str(&format!(
                ": CT {:.4}, CP {:.4}, efficiency {:.3}",
                sys.ct, sys.cp, sys.efficiency
            ));
        }
        if let Some(d) = &c.change {
            line.push_str(&format!(
                "; kinematics moved {:.1}% of range, {} elements changed{}",
                100.0 * d.kinematics_change_of_range,
                d.elements_changed,
                if d.design_unchanged {
                    " (unchanged)"
                } else {
                    ""
                }
            ));
        }
        println!("{line}");
    }
    match (s.outcome.as_str(), s.converged_cycle) {
        ("converged", Some(c)) => println!("converged in cycle {c}: no design variable changed"),
        ("cycle cap reached", _) => println!(
            "NOT converged: the cycle cap of {} was reached with the design still changing",
            s.max_cycles
        ),
        _ => println!("unfinished"),
    }
    if let (Some(i), Some(f), Some(c)) = (&s.initial, &s.final_design, &s.comparison) {
        println!(
            "initial (cycle {}) → final (cycle {}): CT {:.4} → {:.4} ({:+.1}%), efficiency {:.3} → {:.3} ({:+.1}%)",
            i.cycle,
            f.cycle,
            i.ct,
            f.ct,
            100.0 * c.ct_relative_change,
            i.efficiency,
            f.efficiency,
            100.0 * c.efficiency_relative_change
        );
    }
    println!("results in {} (report.md)", dir.display());
}
