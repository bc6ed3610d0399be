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
use fwav::files::Existing;
use fwav::mdois::lock::LOCK_FILE;
use fwav::mdois::summary::Summary;
use fwav::mdois::{Event, Outcome, Progress, Replace, RunDir, RunOptions, Stage};

use super::confirm::confirm_cost;

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
    /// every stage's files under `cycle-N/` with `state.json`. A new or
    /// empty directory, or a run of the same configuration (continued);
    /// anything else is refused (see --force).
    #[arg(long, default_value = "design", conflicts_with = "resume")]
    pub out: PathBuf,
    /// Delete what the --out directory holds and start the run there
    /// (never the --config file itself: that is refused).
    #[arg(long, conflicts_with = "resume")]
    pub force: bool,
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
    if a.out.file_name().is_none() {
        bail!("{} is not a file name", a.out.display());
    }
    if a.out.symlink_metadata().is_ok() && !a.force {
        bail!("{} exists; use --force to overwrite it", a.out.display());
    }
    let text = commented_toml(&SystemConfig::default())?;
    // Without --force a file made meanwhile is kept too.
    let existing = if a.force {
        Existing::Replace
    } else {
        Existing::Keep
    };
    fwav::files::write_to(&a.out, text, existing)?;
    println!(
        "wrote {}: the built-in FWAV's configuration; edit it and run `fwav design --config {}`",
        a.out.display(),
        a.out.display()
    );
    Ok(())
}

/// The stages running, by their order on the line: each one's latest
/// report.
type Running = BTreeMap<u8, (Stage, String)>;

/// The live progress line on a terminal: the latest report of each stage
/// running, redrawn in place at most every 0.2 s and fitted to the
/// terminal's width (short stage names, then cut); stage ends on their own
/// lines.
struct Display {
    live: Mutex<(Running, Option<Instant>)>,
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

/// A stage's name in a narrow progress line.
fn short_name(stage: Stage) -> &'static str {
    match stage {
        Stage::System => "system",
        Stage::Kinematics => "aero",
        Stage::Topology => "structure",
    }
}

/// Columns the live line may take: the terminal's width less one (a line
/// that reaches the last column wraps on some terminals, and a wrapped
/// line is not redrawn in place); 80 if the terminal does not say.
fn columns() -> usize {
    terminal_size::terminal_size_of(std::io::stderr())
        .map_or(80, |(width, _)| usize::from(width.0))
        .saturating_sub(1)
        .max(1)
}

/// `head` then `tail` in at most `width` characters: `head` is cut (and
/// ends in "…") to keep `tail`, the clock.
fn fitted(head: &str, tail: &str, width: usize) -> String {
    let (h, t) = (head.chars().count(), tail.chars().count());
    if h + t <= width {
        format!("{head}{tail}")
    } else if t + 1 >= width {
        head.chars().chain(tail.chars()).take(width).collect()
    } else {
        let kept: String = head.chars().take(width - t - 1).collect();
        format!("{kept}…{tail}")
    }
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
                live.insert(key, (p.stage, "starting".to_string()));
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
                live.insert(key, (p.stage, what));
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
            let width = columns();
            let tail = format!(" [{}]", clock(p.elapsed));
            let head = |name: fn(Stage) -> &'static str| {
                let text: Vec<String> = live
                    .values()
                    .map(|(stage, what)| format!("{}: {what}", name(*stage)))
                    .collect();
                format!("cycle {}: {}", p.cycle, text.join(" | "))
            };
            let full = head(Stage::name);
            let head = if full.chars().count() + tail.chars().count() <= width {
                full
            } else {
                head(short_name)
            };
            let line = fitted(&head, &tail, width);
            eprint!("\r\x1b[2K{line}");
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
    let (claimed, what) = match &a.resume {
        Some(dir) => {
            // Compared with the run's own configuration, not checked: an
            // earlier fwav may have started the run with a value this one
            // refuses (RunDir::for_resume).
            let config = match &a.config {
                Some(path) => Some(super::system::read_config_unchecked(path)?),
                None => None,
            };
            let what = format!("resuming the design run in {}", dir.display());
            (
                RunDir::for_resume(dir, config.as_ref()).context(what.clone())?,
                what,
            )
        }
        None => {
            let config = super::system::read_config(a.config.as_deref())?;
            let estimate = CostEstimate::of(&config);
            if estimate.is_far_beyond_default() {
                confirm_cost(
                    "design run",
                    &estimate,
                    a.yes,
                    "choose a coarser mesh ([wing] span_elements, chord_elements) or the LDVM \
                     section model ([design] section_model = \"ldvm\")",
                )?;
            }
            let replace = Replace {
                force: a.force,
                inputs: a.config.iter().cloned().collect(),
            };
            let what = format!("design run in {}", a.out.display());
            (
                RunDir::for_start(&config, &a.out, &replace).context(what.clone())?,
                what,
            )
        }
    };
    let dir = claimed.path().display().to_string();
    if let Some(holder) = claimed.stale_lock() {
        eprintln!(
            "warning: {dir}/{LOCK_FILE} is a stale lock: {holder} ended without letting go of it; taking the run over"
        );
    }
    if claimed.replaced() {
        eprintln!("--force: deleted what {dir} held; starting the run there");
    } else if a.resume.is_none() && claimed.continues() {
        eprintln!("{dir} holds a run of this configuration: continuing it");
    }
    let run = claimed.run(&options, &progress).context(what)?;
    if show {
        eprint!("\r\x1b[2K");
    }
    if let Some(refusal) = &run.refused_now {
        eprintln!(
            "warning: {dir} was run with a configuration this fwav refuses ({refusal}); its \
             results are reported as they were computed, and a new run needs a configuration \
             this fwav accepts"
        );
    }
    if a.json {
        println!("{}", serde_json::to_string_pretty(&run.summary)?);
    } else {
        print_summary(&run.summary, &run.dir);
        if run.finished_before {
            println!("the run had already finished: nothing computed");
        } else {
            println!(
                "{} stage(s) computed, {} reused",
                run.stages_computed, run.stages_reused
            );
        }
    }
    match run.outcome {
        Some(Outcome::Converged { .. }) | Some(Outcome::CycleCap { .. }) => Ok(()),
        None => bail!("the run stopped before its end"),
    }
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
        // A structural layout taken at ESLSO's cycle cap is said, not
        // silent (the report marks it "(cap)").
        if let Some(t) = c.structural.as_ref().filter(|t| !t.eslso_converged) {
            println!(
                "  structural discipline: ESLSO NOT converged: the layout still changed after \
                 {} cycle{}, its cap ([topology] max_cycles); the layout is the last one's",
                t.eslso_cycles,
                if t.eslso_cycles == 1 { "" } else { "s" }
            );
        }
        // What the 2D model left out is said, not silent.
        if let Some(m) = c.aerodynamic.as_ref().and_then(|a| a.section.as_ref()) {
            if m.deformation_given && !m.deformation_modelled {
                println!("  2D section model: {}", m.note);
            }
        }
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
