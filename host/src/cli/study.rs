//! `fwav study run|resume|status|report`: many design runs of one base
//! configuration, on a local pool or a Slurm job array.

use std::collections::BTreeMap;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use anyhow::{bail, Context, Result};
use fwav::study::file::{check_slurm, LocalSettings, SlurmSettings};
use fwav::study::output::table::cell;
use fwav::study::output::{self, ReportFiles};
use fwav::study::{
    directory, execute, prepare, reclaim, CaseStatus, Executor, ExecutorKind, Launch, SlurmOptions,
    StudyDir, StudyState,
};
use indicatif::ProgressBar;

/// `fwav study`'s subcommands.
#[derive(clap::Subcommand)]
pub enum StudyCommand {
    /// Make the study's cases in DIR and run them: each case is an
    /// ordinary, resumable `fwav design --config DIR/cases/NNN/config.toml
    /// --out DIR/cases/NNN`. Ends with results.csv, plots and report.md.
    Run(RunArgs),
    /// Run the study's unfinished cases again (each goes on from its own
    /// state.json), on the executor used last unless told.
    Resume(ResumeArgs),
    /// The table of the study's cases.
    Status(StatusArgs),
    /// Write results.csv, the plots and report.md of the finished cases.
    Report(ReportArgs),
}

/// Where and how the cases run.
#[derive(clap::Args)]
pub struct ExecutorArgs {
    /// Where the cases run: child processes here (local) or one Slurm
    /// job array (slurm). Default: local for run, the last one used for
    /// resume.
    #[arg(long, value_enum)]
    pub executor: Option<ExecutorChoice>,
    /// Local: cases at a time (default 1, or [local] jobs). Slurm: at
    /// most this many array tasks at once (the array's %N).
    #[arg(long, allow_negative_numbers = true)]
    pub jobs: Option<usize>,
    /// Slurm: the partition (default: the study file's [slurm] partition,
    /// else the cluster's default).
    #[arg(long)]
    pub partition: Option<String>,
    /// Slurm: a case's time limit (e.g. 2:00:00).
    #[arg(long)]
    pub time: Option<String>,
    /// Slurm: CPUs of each task (default 2).
    #[arg(long, allow_negative_numbers = true)]
    pub cpus_per_task: Option<u32>,
    /// Slurm: memory of each task (e.g. 4G).
    #[arg(long)]
    pub mem: Option<String>,
    /// Slurm: seconds between two looks at the queue (default 10).
    #[arg(long, value_name = "SECONDS", allow_negative_numbers = true)]
    pub poll: Option<f64>,
    /// Run cases far beyond the built-in design's cost.
    #[arg(long)]
    pub yes: bool,
    /// No progress display (the cases' ends are still printed).
    #[arg(long)]
    pub quiet: bool,
}

/// The executors.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ExecutorChoice {
    /// Child processes on this host.
    Local,
    /// One Slurm job array.
    Slurm,
}

/// `fwav study run`'s options.
#[derive(clap::Args)]
pub struct RunArgs {
    /// The study file (TOML).
    pub study: PathBuf,
    /// The study's directory: new, empty, or holding this same study
    /// (continued).
    #[arg(long)]
    pub out: PathBuf,
    #[command(flatten)]
    pub executor: ExecutorArgs,
}

/// `fwav study resume`'s options.
#[derive(clap::Args)]
pub struct ResumeArgs {
    /// The study's directory.
    pub dir: PathBuf,
    #[command(flatten)]
    pub executor: ExecutorArgs,
}

/// `fwav study status`'s options.
#[derive(clap::Args)]
pub struct StatusArgs {
    /// The study's directory.
    pub dir: PathBuf,
    /// The state (study.json, settled from the cases' files) as JSON.
    #[arg(long)]
    pub json: bool,
}

/// `fwav study report`'s options.
#[derive(clap::Args)]
pub struct ReportArgs {
    /// The study's directory.
    pub dir: PathBuf,
}

/// Runs `fwav study ...`.
pub fn run_command(command: &StudyCommand) -> Result<()> {
    match command {
        StudyCommand::Run(a) => run(a),
        StudyCommand::Resume(a) => resume(a),
        StudyCommand::Status(a) => status(&a.dir, a.json),
        StudyCommand::Report(a) => {
            let files = output::write(&a.dir)?;
            print_report(&files);
            Ok(())
        }
    }
}

/// The executor the flags ask for, over the study's own settings.
fn executor(
    a: &ExecutorArgs,
    slurm: &SlurmSettings,
    local: &LocalSettings,
    default: ExecutorKind,
) -> Result<Executor> {
    let kind = match a.executor {
        Some(ExecutorChoice::Local) => ExecutorKind::Local,
        Some(ExecutorChoice::Slurm) => ExecutorKind::Slurm,
        None => default,
    };
    if a.jobs == Some(0) {
        bail!("--jobs 0: at least 1");
    }
    Ok(match kind {
        ExecutorKind::Local => Executor::Local {
            jobs: a.jobs.or(local.jobs).unwrap_or(1),
        },
        ExecutorKind::Slurm => {
            let s = slurm;
            let settings = SlurmSettings {
                partition: a.partition.clone().or_else(|| s.partition.clone()),
                time: a.time.clone().or_else(|| s.time.clone()),
                cpus_per_task: a.cpus_per_task.or(s.cpus_per_task),
                mem: a.mem.clone().or_else(|| s.mem.clone()),
                max_parallel: a.jobs.or(s.max_parallel),
                options: s.options.clone(),
                poll_s: a.poll.or(s.poll_s),
            };
            check_slurm(&settings).context("the Slurm options (flags over [slurm])")?;
            Executor::Slurm(SlurmOptions { settings })
        }
    })
}

/// This program, which each case runs.
fn launch(yes: bool) -> Result<Launch> {
    let program = std::env::current_exe().context("where is the fwav program itself?")?;
    Ok(Launch { program, yes })
}

fn run(a: &RunArgs) -> Result<()> {
    let prepared = prepare(&a.study).with_context(|| format!("study {}", a.study.display()))?;
    prepared.check_cost(a.executor.yes)?;
    if let Some((count, case, estimate)) = prepared.costly() {
        eprintln!("{count} case(s) far beyond the built-in design's cost; {case} needs {estimate}");
    }
    // The executor's settings are checked before the directory is made.
    let file = &prepared.file;
    let executor = executor(&a.executor, &file.slurm, &file.local, ExecutorKind::Local)?;
    let mut study = StudyDir::create(file, &prepared.cases, &a.out)
        .with_context(|| format!("study directory {}", a.out.display()))?;
    if study.continued {
        eprintln!(
            "{} holds this study: going on with its unfinished cases",
            a.out.display()
        );
        reclaim(&mut study)?;
    }
    go(&mut study, &executor, &a.executor)
}

fn resume(a: &ResumeArgs) -> Result<()> {
    let mut study = StudyDir::open(&a.dir)?;
    reclaim(&mut study)?;
    let last = study
        .state
        .submissions
        .last()
        .map_or(ExecutorKind::Local, |s| s.executor);
    let executor = executor(&a.executor, &study.state.slurm, &study.state.local, last)?;
    go(&mut study, &executor, &a.executor)
}

/// Runs the study's unfinished cases, reports, and fails if any case
/// failed.
fn go(study: &mut StudyDir, executor: &Executor, a: &ExecutorArgs) -> Result<()> {
    let cases = study.state.unfinished();
    let dir = study.path().to_path_buf();
    if cases.is_empty() {
        eprintln!(
            "every case of {} has finished: nothing to run",
            dir.display()
        );
    } else {
        let where_ = match executor {
            Executor::Local { jobs } => format!("here, {jobs} at a time"),
            Executor::Slurm(_) => "as one Slurm job array".to_string(),
        };
        eprintln!(
            "{} case(s) of {} to run {where_}",
            cases.len(),
            study.state.cases.len()
        );
        let display = Display::new(cases.len(), !a.quiet && std::io::stderr().is_terminal());
        let observe = |state: &StudyState| display.update(state, &cases);
        execute(study, &cases, executor, &launch(a.yes)?, &observe)?;
        display.finish();
    }
    let files = output::write(&dir)?;
    print_report(&files);
    let failed: Vec<String> = study
        .state
        .cases
        .iter()
        .filter(|c| c.status == CaseStatus::Failed)
        .map(|c| c.dir.rsplit('/').next().unwrap_or(&c.dir).to_string())
        .collect();
    if !failed.is_empty() {
        bail!(
            "{} of {} cases failed (case {}); `fwav study status {}` shows why, `fwav study \
             resume {}` runs them again from their last finished stage",
            failed.len(),
            study.state.cases.len(),
            failed.join(", "),
            dir.display(),
            dir.display()
        );
    }
    Ok(())
}

fn print_report(files: &ReportFiles) {
    println!(
        "{} of {} cases finished; results in {} and {}",
        files.finished,
        files.cases,
        files.results.display(),
        files.report.display()
    );
    for p in &files.plots {
        println!("plot: {}", p.display());
    }
}

/// The progress of the cases submitted: a bar on a terminal, and a line
/// for each case that ends.
struct Display {
    bar: Option<ProgressBar>,
    seen: Mutex<BTreeMap<usize, CaseStatus>>,
}

impl Display {
    fn new(total: usize, live: bool) -> Self {
        let bar = live.then(|| {
            super::progress::bar(
                total as u64,
                "[{elapsed_precise}] {bar:30} {pos}/{len} ended  {wide_msg}",
            )
        });
        Self {
            bar,
            seen: Mutex::new(BTreeMap::new()),
        }
    }

    fn line(&self, text: String) {
        match &self.bar {
            Some(bar) => bar.println(text),
            None => eprintln!("{text}"),
        }
    }

    fn update(&self, state: &StudyState, cases: &[usize]) {
        let mut seen = self.seen.lock().unwrap_or_else(|e| e.into_inner());
        let mut running = Vec::new();
        let mut queued = 0;
        let mut ended = 0;
        for c in state.cases.iter().filter(|c| cases.contains(&c.case)) {
            let name = c.dir.rsplit('/').next().unwrap_or(&c.dir);
            let before = seen.insert(c.case, c.status);
            match c.status {
                CaseStatus::Running => running.push(format!("{name} ({} stages)", c.stages_done)),
                CaseStatus::Queued => queued += 1,
                CaseStatus::Finished | CaseStatus::Failed => ended += 1,
                CaseStatus::Pending => {}
            }
            if before != Some(c.status) {
                match c.status {
                    CaseStatus::Finished => self.line(format!("case {name} finished")),
                    CaseStatus::Failed => self.line(format!(
                        "case {name} failed: {}",
                        c.error.as_deref().unwrap_or("no error recorded")
                    )),
                    _ => {}
                }
            }
        }
        if let Some(bar) = &self.bar {
            bar.set_position(ended);
            let mut msg = String::new();
            if !running.is_empty() {
                msg.push_str(&format!("running: {}", running.join(", ")));
            }
            if queued > 0 {
                msg.push_str(&format!(
                    "{}queued: {queued}",
                    if msg.is_empty() { "" } else { "; " }
                ));
            }
            bar.set_message(msg);
        }
    }

    fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

/// Prints the table of the study's cases.
fn status(dir: &Path, json: bool) -> Result<()> {
    let mut state = directory::read(dir)?;
    state.settle(dir, false);
    if json {
        println!("{}", serde_json::to_string_pretty(&state)?);
        return Ok(());
    }
    let count = |s| state.count(s);
    println!(
        "study {} in {}: {} cases, {} finished, {} failed, {} running, {} queued, {} pending",
        state.name,
        dir.display(),
        state.cases.len(),
        count(CaseStatus::Finished),
        count(CaseStatus::Failed),
        count(CaseStatus::Running),
        count(CaseStatus::Queued),
        count(CaseStatus::Pending),
    );
    let mut rows = vec![{
        let mut h = vec!["case".to_string()];
        h.extend(state.keys.iter().cloned());
        h.extend(["status", "stages", "slurm", "error or log"].map(String::from));
        h
    }];
    for c in &state.cases {
        let mut row = vec![c.dir.rsplit('/').next().unwrap_or(&c.dir).to_string()];
        for k in &state.keys {
            row.push(c.values.get(k).map_or_else(|| "-".into(), cell));
        }
        row.push(c.status.to_string());
        row.push(c.stages_done.to_string());
        row.push(match (&c.slurm_task, &c.slurm_state) {
            (Some(t), Some(s)) => format!("{t} {s}"),
            (Some(t), None) => t.clone(),
            _ => "-".into(),
        });
        row.push(match (&c.error, &c.log) {
            (Some(e), _) => e.clone(),
            (None, Some(l)) => l.clone(),
            _ => String::new(),
        });
        rows.push(row);
    }
    let widths: Vec<usize> = (0..rows[0].len())
        .map(|i| rows.iter().map(|r| r[i].chars().count()).max().unwrap_or(0))
        .collect();
    for r in rows {
        let cells: Vec<String> = r
            .iter()
            .zip(&widths)
            .map(|(c, w)| format!("{c:<w$}"))
            .collect();
        println!("{}", cells.join("  ").trim_end());
    }
    Ok(())
}
