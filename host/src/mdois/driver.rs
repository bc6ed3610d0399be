//! The MDOIS cycle loop (seed paper, Figs. 3 and 4): the system analysis
//! of the current design, then the two disciplines independently and at
//! the same time — the aerodynamic discipline on the mid-span section's
//! deformation, the structural discipline on the pressure history — then
//! the next cycle's system analysis with both proposals, until a cycle's
//! disciplines leave every design variable unchanged
//! ([`crate::config::MdoisConfig`] says within what). At the cycle cap the
//! last proposal is analysed once more and the run ends as "cycle cap
//! reached", never as converged. A later cycle's structural discipline
//! starts SIMP from the last cycle's design variables: started cold, the
//! default wing's layout kept moving 1.5–2.6% a cycle and the design ran
//! to its cap in 11.1 min; warm, it converges in cycle 2 in 2.8 min.
//!
//! A run lives in a directory: `config.toml` (the resolved configuration;
//! a resume refuses it edited since the start, [`super::state`] keeps the
//! original), `state.json` ([`super::state`]), each stage's files
//! under `cycle-N/` ([`super::stage`]), and the result files
//! ([`super::output`]). [`start`] begins a run, [`resume`] continues one
//! without redoing its finished stages; both claim the directory first
//! ([`super::directory`]: what may be written there, and its lock).

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};
use std::time::{Instant, SystemTime, UNIX_EPOCH};

use crate::config::SystemConfig;
use crate::discipline::cache::EvaluationCache;
use crate::files::write_atomic;
use crate::shell::material::Layer;
use crate::topology::eslso::DesignProblem;

use super::directory::{Plan, RunDir};
use super::error::DesignError;
use super::output::files::{write_final, write_summary};
use super::plant::write_plant;
use super::progress::Progress;
use super::records::{load_kinematics, load_topology};
use super::stage::{Context, CACHE_FILE};
use super::state::{Outcome, RunRecord, RunState, Stage, StageRecord};
use super::summary::{self, Summary};
use crate::config::template::commented_toml;

/// The resolved configuration's file name in the run's directory.
pub const CONFIG_FILE: &str = "config.toml";

/// How to drive a run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RunOptions {
    /// Stop before starting a stage once this many stages have been
    /// computed in this invocation (the two disciplines of a cycle start
    /// together and count as two). `None`: run to the end. For tests of
    /// resuming, and for running a design a piece at a time.
    pub stage_limit: Option<usize>,
}

/// What an invocation of the driver did.
#[derive(Clone, Debug, PartialEq)]
pub struct DesignRun {
    /// The run's directory.
    pub dir: PathBuf,
    /// How the run ended; `None`: it stopped at the stage limit and can
    /// be resumed.
    pub outcome: Option<Outcome>,
    /// The summary (also in `summary.json`).
    pub summary: Summary,
    /// Stages computed by this invocation.
    pub stages_computed: usize,
    /// Stages reused from earlier invocations.
    pub stages_reused: usize,
    /// The run had ended before this invocation, which computed and
    /// wrote nothing.
    pub finished_before: bool,
    /// A finished run's configuration has a value this fwav refuses (an
    /// earlier one accepted it): the refusal's message (a
    /// [`crate::config::ConfigError`]'s, which is neither `Clone` nor
    /// `PartialEq`), said beside the results it reports as they were
    /// computed. (An unfinished run is refused instead,
    /// [`DesignError::RefusedNow`].)
    pub refused_now: Option<String>,
}

/// Starts a new run of `config` in `dir` (created if missing), or
/// continues the run of the same configuration there; any other content
/// is refused ([`RunDir::for_start`]; `--force` is
/// [`RunDir::for_start`] with [`Replace`](super::directory::Replace)).
pub fn start(
    config: &SystemConfig,
    dir: &Path,
    options: &RunOptions,
    progress: &(dyn Fn(&Progress) + Sync),
) -> Result<DesignRun, DesignError> {
    RunDir::for_start(config, dir, &super::directory::Replace::default())?.run(options, progress)
}

/// Continues the run in `dir`: its finished stages are reused, the rest
/// computed. With `config`, it must equal the run's configuration (the
/// error names the first differing field).
pub fn resume(
    dir: &Path,
    config: Option<&SystemConfig>,
    options: &RunOptions,
    progress: &(dyn Fn(&Progress) + Sync),
) -> Result<DesignRun, DesignError> {
    RunDir::for_resume(dir, config)?.run(options, progress)
}

impl RunDir {
    /// Runs the design in the claimed directory (a new run, or the one
    /// there continued); the lock is let go at the end.
    pub fn run(
        self,
        options: &RunOptions,
        progress: &(dyn Fn(&Progress) + Sync),
    ) -> Result<DesignRun, DesignError> {
        let dir = self.dir.as_path();
        match &self.plan {
            Plan::New(config) => {
                let text =
                    commented_toml(config).map_err(|e| DesignError::output(CONFIG_FILE, e))?;
                write_atomic(dir, CONFIG_FILE, text)?;
                let state = RunState::new(config)?;
                state.save(dir)?;
                drive(config.clone(), dir, state, options, progress)
            }
            Plan::Continue(given) => continue_run(dir, given.as_ref(), options, progress),
        }
    }
}

/// Goes on with the run in `dir`: its `config.toml` must be the
/// configuration it started with (and `given`, if any); a finished run is
/// reported as it is, nothing written (with the value this fwav refuses,
/// if any, in [`DesignRun::refused_now`]); an unfinished one with a value
/// this fwav refuses is refused ([`DesignError::RefusedNow`]).
fn continue_run(
    dir: &Path,
    given: Option<&SystemConfig>,
    options: &RunOptions,
    progress: &(dyn Fn(&Progress) + Sync),
) -> Result<DesignRun, DesignError> {
    let mut state = RunState::load(dir)?;
    let started = state.started_with(dir)?;
    let path = dir.join(CONFIG_FILE);
    let text = std::fs::read_to_string(&path).map_err(DesignError::io(&path))?;
    let file = SystemConfig::parse_unchecked(&text).map_err(|source| DesignError::RunConfig {
        path: path.clone(),
        source: Box::new(source),
    })?;
    if !state.is_of(&file)? {
        let (field, now, then) = first_difference(&file, &started)
            .unwrap_or_else(|| ("configuration".into(), "?".into(), "?".into()));
        return Err(DesignError::ConfigEdited {
            path,
            field,
            now,
            then,
        });
    }
    if let Some(given) = given {
        if let Some((field, given, stored)) = first_difference(given, &started) {
            return Err(DesignError::ConfigMismatch {
                dir: dir.to_path_buf(),
                field,
                given,
                stored,
            });
        }
    }
    state.consistent_prefix(dir);
    // The values are checked against this fwav's ranges, which may be
    // narrower than those of the fwav that started the run.
    let refused_now = started.check().err();
    if state.outcome.is_some() {
        let summary = summary::build(&started, dir, &state)?;
        return Ok(DesignRun {
            dir: dir.to_path_buf(),
            outcome: state.outcome,
            summary,
            stages_computed: 0,
            stages_reused: 0,
            finished_before: true,
            refused_now: refused_now.map(|e| e.to_string()),
        });
    }
    if let Some(source) = refused_now {
        return Err(DesignError::RefusedNow {
            dir: dir.to_path_buf(),
            source: Box::new(source),
        });
    }
    drive(started, dir, state, options, progress)
}

/// The first `table.key` whose value differs between two configurations,
/// with both values.
pub(crate) fn first_difference(
    a: &SystemConfig,
    b: &SystemConfig,
) -> Option<(String, String, String)> {
    let value = |c: &SystemConfig| toml::Value::try_from(c).ok();
    let (Some(toml::Value::Table(a)), Some(toml::Value::Table(b))) = (value(a), value(b)) else {
        return (a != b).then(|| ("configuration".into(), "?".into(), "?".into()));
    };
    for (table, x) in &a {
        let y = b.get(table);
        match (x, y) {
            (toml::Value::Table(x), Some(toml::Value::Table(y))) => {
                for (key, v) in x {
                    if y.get(key) != Some(v) {
                        let w = y.get(key).map_or("nothing".into(), |w| w.to_string());
                        return Some((format!("{table}.{key}"), v.to_string(), w));
                    }
                }
            }
            _ if y != Some(x) => {
                let w = y.map_or("nothing".into(), |w| w.to_string());
                return Some((table.clone(), x.to_string(), w));
            }
            _ => {}
        }
    }
    None
}

fn lock(state: &Mutex<RunState>) -> MutexGuard<'_, RunState> {
    // Every change to the state is one assignment: a panic elsewhere
    // cannot leave it half changed.
    state.lock().unwrap_or_else(|e| e.into_inner())
}

/// Marks a stage finished (its files are written), saves the state and
/// the summary so far.
fn record(
    ctx: &Context<'_>,
    state: &Mutex<RunState>,
    cycle: usize,
    stage: Stage,
    finished: StageRecord,
) -> Result<(), DesignError> {
    let mut s = lock(state);
    s.finish(cycle, stage, finished);
    s.save(&ctx.dir)?;
    write_summary(&ctx.dir, &summary::build(&ctx.config, &ctx.dir, &s)?)
}

fn drive(
    config: SystemConfig,
    dir: &Path,
    mut state: RunState,
    options: &RunOptions,
    progress: &(dyn Fn(&Progress) + Sync),
) -> Result<DesignRun, DesignError> {
    let run = state.next_run();
    state.runs.push(RunRecord {
        run,
        started_unix_s: SystemTime::now()
            .duration_since(UNIX_EPOCH)
            .map_or(0, |d| d.as_secs()),
    });
    state.save(dir)?;
    let base = config.wing_model()?;
    let problem = DesignProblem::wing(&base.wing, Layer::CARBON, Layer::MYLAR);
    let cache = EvaluationCache::kept_in(&dir.join(CACHE_FILE))?;
    let ctx = Context {
        dir: dir.to_path_buf(),
        config,
        base,
        problem,
        cache,
        run,
        started: Instant::now(),
        progress,
    };
    let state = Mutex::new(state);
    let (mut computed, mut reused) = (0usize, 0usize);
    let limit_reached = |computed: usize| options.stage_limit.is_some_and(|l| computed >= l);
    let max_cycles = ctx.config.mdois.max_cycles;
    let existing = lock(&state).outcome;
    let outcome = match existing {
        Some(outcome) => Some(outcome),
        None => 'cycles: {
            let mut cycle = 1;
            loop {
                if lock(&state).stage(cycle, Stage::System).is_some() {
                    ctx.check_trusted(cycle)?;
                    ctx.reused(cycle, Stage::System);
                    reused += 1;
                } else {
                    if limit_reached(computed) {
                        break 'cycles None;
                    }
                    let finished = ctx.system(cycle)?;
                    record(&ctx, &state, cycle, Stage::System, finished)?;
                    computed += 1;
                }
                if cycle > max_cycles {
                    break 'cycles Some(Outcome::CycleCap { max_cycles });
                }
                if cycle == 1 {
                    // Stop before the disciplines if the actuator cannot
                    // fly the initial design (after the first analysis:
                    // its damping is what the discipline judges on).
                    ctx.check_flyable(cycle)?;
                }
                let mut needed = Vec::new();
                for stage in [Stage::Kinematics, Stage::Topology] {
                    if lock(&state).stage(cycle, stage).is_some() {
                        ctx.reused(cycle, stage);
                        reused += 1;
                    } else {
                        needed.push(stage);
                    }
                }
                if !needed.is_empty() && limit_reached(computed) {
                    break 'cycles None;
                }
                computed += needed.len();
                disciplines(&ctx, &state, cycle, &needed)?;
                let change = summary::change(
                    &ctx.config,
                    &load_kinematics(dir, cycle)?,
                    &load_topology(dir, cycle)?,
                );
                if change.design_unchanged {
                    break 'cycles Some(Outcome::Converged { cycle });
                }
                cycle += 1;
            }
        }
    };
    let mut s = lock(&state);
    if let Some(outcome) = outcome {
        let mut done = s.clone();
        done.outcome = Some(outcome);
        let summary = summary::build(&ctx.config, dir, &done)?;
        // The result files before the state says the run is over: a run
        // killed while writing them is resumed and writes them again.
        write_final(&ctx, &done, outcome, &summary)?;
        // The designed vehicle for hil-sim, beside the kinematics.json
        // just written: the final cycle's wing and analysis.
        let final_cycle = match outcome {
            Outcome::Converged { cycle } => cycle,
            Outcome::CycleCap { max_cycles } => max_cycles + 1,
        };
        let design = ctx.design(final_cycle)?;
        write_plant(dir, &ctx.config, final_cycle, &design.densities)?;
        done.save(dir)?;
        *s = done;
    }
    let summary = summary::build(&ctx.config, dir, &s)?;
    write_summary(dir, &summary)?;
    Ok(DesignRun {
        dir: dir.to_path_buf(),
        outcome: s.outcome,
        summary,
        stages_computed: computed,
        stages_reused: reused,
        finished_before: false,
        refused_now: None,
    })
}

/// Runs the `needed` disciplines of `cycle` side by side, each recorded as
/// it finishes; the first error is returned after both have ended (the
/// other one's work is kept).
fn disciplines(
    ctx: &Context<'_>,
    state: &Mutex<RunState>,
    cycle: usize,
    needed: &[Stage],
) -> Result<(), DesignError> {
    let results: Vec<Result<(), DesignError>> = std::thread::scope(|scope| {
        let handles: Vec<_> = needed
            .iter()
            .map(|&stage| {
                let handle = scope.spawn(move || {
                    let finished = match stage {
                        Stage::Kinematics => ctx.kinematics(cycle)?,
                        _ => ctx.topology(cycle)?,
                    };
                    record(ctx, state, cycle, stage, finished)
                });
                (stage, handle)
            })
            .collect();
        handles
            .into_iter()
            .map(|(stage, handle)| {
                handle
                    .join()
                    .unwrap_or(Err(DesignError::Panicked { cycle, stage }))
            })
            .collect()
    });
    results.into_iter().collect()
}
