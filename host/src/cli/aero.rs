//! `fwav aero2d`: one 2D unsteady analysis of a plunging/pitching,
//! optionally deforming section.

use std::io::IsTerminal as _;
use std::path::PathBuf;

use anyhow::{bail, Context, Result};
use fwav::aero2d::case::{
    Case, CaseError, CaseRun, SectionModel, MAX_DURATION_CHORDS, MAX_REDUCED_FREQUENCY,
    PERIODIC_CHANGE,
};
use fwav::aero2d::friction::FWAV_REYNOLDS;
use fwav::aero2d::motion::Motion;
use fwav::aero2d::viscous::{
    FlowField, FrameSink, ViscousCost, ViscousError, ViscousSection, MAP_DEVIATION_WARNING,
};
use fwav::aero2d::window::MIN_SHEDDING_PERIODS;
use fwav::aeroelastic::handoff::SectionFile;
use fwav::discipline::section::FWAV_LESP_CRITICAL;
use fwav::files::create_new;
use fwav::output::flow_field_vtu::{write_flow_field, FlowSeries};
use fwav::output::history_csv::write_history_csv;
use fwav::output::section_plot::draw;
use fwav::output::surface_csv::write_surface_csv;
use fwav_ns2d::{AROUND, RADIAL};
use fwav_settings::Shown;
use indicatif::ProgressBar;

use super::confirm::confirm_cost;
use super::doubtful::Doubtful;
use super::new_files::refuse_taken;

/// The command's options.
#[derive(clap::Args)]
pub struct Aero2dArgs {
    /// The flow model: `inviscid` (the section chooses: LDVM for `flat`,
    /// the panel method for a contour) or `ns` (laminar Navier–Stokes at
    /// `--reynolds`; `flat` is a thin plate of `--ns-thickness`, a NACA
    /// section or a point file any closed contour, a sharp trailing edge
    /// opened to 0.005 chords).
    #[arg(long, value_enum, default_value_t = FlowModel::Inviscid)]
    pub model: FlowModel,
    /// Thickness of the plate that models a `flat` section in the
    /// Navier–Stokes model, chords (semicircular edges).
    #[arg(long, default_value_t = ViscousSection::DEFAULT_THICKNESS, allow_negative_numbers = true)]
    pub ns_thickness: f64,
    /// Grid nodes round the section in the Navier–Stokes model (even, 16
    /// to 8192; default 384).
    #[arg(long, allow_negative_numbers = true)]
    pub ns_around: Option<usize>,
    /// Grid nodes from the wall to the outer boundary in the Navier–Stokes
    /// model (default 256, the far field coarsened: the grid is refined or
    /// coarsened as a whole, its near rings and far growth scaled with
    /// these; 8 to 8192, and at most 1.5 growth a far cell: 29 or
    /// more).
    #[arg(long, allow_negative_numbers = true)]
    pub ns_radial: Option<usize>,
    /// Largest Courant number of a time step in the Navier–Stokes model
    /// (0.1 to 10; default 3, chosen on the FWAV plate's thrust; a bluff
    /// body's wake needs a shorter step: a cylinder's lift swing at Re 100
    /// is 0.289 at 3 and 0.314 at 1 on the default grid).
    #[arg(long, allow_negative_numbers = true)]
    pub ns_courant: Option<f64>,
    /// Section: `flat` (thin line, LDVM), a NACA 4-digit name such as
    /// `naca0012` (thick section, panel method), or a file of x y points
    /// (Selig order or clockwise from the trailing edge, chords).
    #[arg(long, default_value = "flat")]
    pub section: String,
    /// Plunge amplitude, chords.
    #[arg(long, default_value_t = 0.05, allow_negative_numbers = true)]
    pub plunge_amplitude: f64,
    /// Reduced frequency k = omega c / (2 U).
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    pub reduced_frequency: f64,
    /// Pitch amplitude, degrees.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub pitch_amplitude_deg: f64,
    /// Phase by which pitch leads plunge, degrees.
    #[arg(long, default_value_t = 90.0, allow_negative_numbers = true)]
    pub pitch_phase_deg: f64,
    /// Mean pitch angle, degrees.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub mean_pitch_deg: f64,
    /// Pitch axis, chords from the leading edge.
    #[arg(long, default_value_t = 0.25, allow_negative_numbers = true)]
    pub pivot: f64,
    /// Cycles to simulate (or `--duration`, for `--model ns`).
    #[arg(long, default_value_t = 5, allow_negative_numbers = true)]
    pub cycles: u32,
    /// Chords travelled to run instead of `--cycles`, for `--model ns`: a
    /// run without a period, such as a body at rest in a stream (no plunge
    /// or pitch amplitude) or a sudden start (the flow starts from rest).
    /// Reports the loads over the run's second half (means, swings, the
    /// lift's Strouhal number `f c / U` when it oscillates) and at its end;
    /// at most 1000.
    #[arg(long, conflicts_with = "cycles", allow_negative_numbers = true)]
    pub duration: Option<f64>,
    /// Critical leading-edge suction parameter: shed leading-edge vortices
    /// beyond it (LDVM). Off when not given: the flow stays attached (the
    /// theory Garrick's is), and a run whose suction parameter passes the
    /// flat plate's 0.11 is marked doubtful (exit status 2).
    #[arg(long, allow_negative_numbers = true)]
    pub lesp_critical: Option<f64>,
    /// Chord Reynolds number: of the laminar skin-friction estimate of the
    /// inviscid models, of the flow in the Navier–Stokes model (default:
    /// the built-in FWAV, 3 m/s, 0.075 m chord, sea-level air).
    #[arg(long, default_value_t = FWAV_REYNOLDS, allow_negative_numbers = true)]
    pub reynolds: f64,
    /// Deformation history of the section over one period: a
    /// `section.json` (`fwav system-analysis --out` writes one;
    /// `{"format": "fwav-section-history", "format_version": 1, "samples":
    /// [[[x, y], ...], ...]}`), samples equally spaced in time,
    /// in the section's kinematic frame (chords, leading edge at (0, 0),
    /// trailing edge at (1, 0)): for `flat` the mid-line points from the
    /// leading to the trailing edge; for a thick section the whole contour,
    /// as many points as the section has, in its order (a point file's;
    /// a NACA name's 160 for the panel method, 400 for `ns`).
    #[arg(long)]
    pub deformation: Option<PathBuf>,
    /// Draw the wake (the vorticity, for `ns`) and the force histories to
    /// this PNG (a file that exists is refused).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Write the load histories to this CSV (time in chords travelled,
    /// CL, CT, CP; a file that exists is refused).
    #[arg(long)]
    pub history: Option<PathBuf>,
    /// Write the wall's pressure and skin friction at the run's end to
    /// this CSV (`--model ns` only): arc length, position, the pressure
    /// coefficient `(p - p∞) / (1/2 rho U^2)`, the wall shear stress's x
    /// and y (a file that exists is refused).
    #[arg(long)]
    pub surface: Option<PathBuf>,
    /// Write the flow at the run's end to this ParaView file (`.vtu`;
    /// `--model ns` only): the grid's cells, the vorticity, the
    /// streamfunction and the velocity at its nodes, in the frame of
    /// `--plot`'s picture (a file that exists is refused).
    #[arg(long)]
    pub field: Option<PathBuf>,
    /// Write the flow through the run to this directory (`--model ns`
    /// only; it must be new or empty): `--field-frames` binary `.vtu`s
    /// (`flow-0000.vtu`, ...; the grid, the vorticity, the streamfunction
    /// and the velocity in single precision) and `flow.pvd`, the series
    /// ParaView plays, each frame at its time in chords travelled.
    #[arg(long)]
    pub field_series: Option<PathBuf>,
    /// Frames of `--field-series`, evenly spaced in time over the run, the
    /// last at its end, each written as the run reaches it: 1 to 500
    /// (default 50; 5.2 MB each on the default 384 × 256 grid).
    #[arg(long, allow_negative_numbers = true)]
    pub field_frames: Option<usize>,
    /// Run a Navier–Stokes case whose memory, grid or field series is far
    /// beyond the default's (without it such a run prints its estimate,
    /// asks on a terminal and is refused otherwise).
    #[arg(long)]
    pub yes: bool,
    /// Machine-readable output.
    #[arg(long)]
    pub json: bool,
}

/// The flow model of `--model`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum FlowModel {
    /// LDVM for a thin section, the panel method for a contour.
    Inviscid,
    /// Laminar Navier–Stokes.
    Ns,
}

/// Frames of `--field-series` when `--field-frames` is not given.
const DEFAULT_FIELD_FRAMES: usize = 50;

/// The most frames `--field-frames` takes: 2.6 GB of files on the
/// default grid (a slip of the keyboard should not fill the disk).
const MAX_FIELD_FRAMES: usize = 500;

/// The efficiency of a section that does no work.
const UNDEFINED_EFFICIENCY: &str = "undefined (no input power)";

fn check(a: &Aero2dArgs) -> Result<()> {
    if (a.section != "flat" || a.model == FlowModel::Ns) && a.lesp_critical.is_some() {
        bail!("--lesp-critical applies to the inviscid thin-line model (`--section flat`) only");
    }
    let ns_options = a.ns_around.is_some()
        || a.ns_radial.is_some()
        || a.ns_courant.is_some()
        || a.surface.is_some()
        || a.field.is_some()
        || a.field_series.is_some()
        || a.ns_thickness != ViscousSection::DEFAULT_THICKNESS;
    if a.model != FlowModel::Ns && ns_options {
        bail!(
            "--ns-thickness, --ns-around, --ns-radial, --ns-courant, --surface, --field and \
             --field-series apply to --model ns only"
        );
    }
    if let Some(n) = a.field_frames {
        if a.field_series.is_none() {
            bail!("--field-frames {n} sets the frames of --field-series DIR: give that too");
        }
        if !(1..=MAX_FIELD_FRAMES).contains(&n) {
            bail!("--field-frames {n} must be between 1 and {MAX_FIELD_FRAMES}");
        }
    }
    if let Some(n) = a.ns_around {
        if !(AROUND.contains(&n) && n % 2 == 0) {
            bail!(
                "--ns-around {n} must be even and in [{}, {}]",
                AROUND.start(),
                AROUND.end()
            );
        }
    }
    if let Some(n) = a.ns_radial {
        if !RADIAL.contains(&n) {
            bail!(
                "--ns-radial {n} must be in [{}, {}]",
                RADIAL.start(),
                RADIAL.end()
            );
        }
    }
    if let Some(c) = a.ns_courant {
        if !(0.1..=10.0).contains(&c) {
            bail!("--ns-courant {} must be in [0.1, 10]", Shown(c));
        }
    }
    if a.model == FlowModel::Ns
        && a.section != "flat"
        && a.ns_thickness != ViscousSection::DEFAULT_THICKNESS
    {
        bail!(
            "--ns-thickness is the thickness of `--section flat`'s plate; {} has its own",
            a.section
        );
    }
    if !(a.reduced_frequency > 0.0 && a.reduced_frequency <= MAX_REDUCED_FREQUENCY) {
        bail!(
            "--reduced-frequency {} must be in (0, {MAX_REDUCED_FREQUENCY}]",
            Shown(a.reduced_frequency)
        );
    }
    if !(-2.0..=2.0).contains(&a.plunge_amplitude) {
        bail!(
            "--plunge-amplitude {} must be within +-2 chords",
            Shown(a.plunge_amplitude)
        );
    }
    if !((-60.0..=60.0).contains(&a.pitch_amplitude_deg)
        && (-60.0..=60.0).contains(&a.mean_pitch_deg))
    {
        bail!("--pitch-amplitude-deg and --mean-pitch-deg must be within +-60 degrees");
    }
    if !(a.pitch_phase_deg.is_finite() && (0.0..=1.0).contains(&a.pivot)) {
        bail!(
            "--pivot {} must be in [0, 1] chords and --pitch-phase-deg finite",
            Shown(a.pivot)
        );
    }
    if let Some(d) = a.duration {
        if a.model != FlowModel::Ns {
            bail!(
                "--duration applies to --model ns (a body at rest in a stream, a sudden start); \
                 the inviscid models run whole periods: give --cycles"
            );
        }
        if !(d > 0.0 && d <= MAX_DURATION_CHORDS) {
            bail!(
                "--duration {} must be in (0, {MAX_DURATION_CHORDS}] chords travelled",
                Shown(d)
            );
        }
    }
    if a.cycles < 2 || a.cycles > 50 {
        bail!("--cycles {} must be between 2 and 50", a.cycles);
    }
    if let Some(l) = a.lesp_critical {
        if !(l > 0.0 && l < 10.0) {
            bail!("--lesp-critical {} must be in (0, 10)", Shown(l));
        }
    }
    if !(100.0..=1e8).contains(&a.reynolds) {
        bail!("--reynolds {} must be in [100, 1e8]", Shown(a.reynolds));
    }
    Ok(())
}

/// Refuses, before the run, a file to write that exists (the picture
/// too): the files are never overwritten, and a long viscous run is not lost to a name
/// found taken at its end (the writes refuse one made meanwhile too).
/// And a `--field` not named `.vtu`, which ParaView would open with
/// another reader; and a `--field-series` directory that is a file or
/// holds anything.
fn check_outputs(a: &Aero2dArgs) -> Result<()> {
    if let Some(dir) = a.field_series.as_ref().filter(|d| d.exists()) {
        let empty = std::fs::read_dir(dir).is_ok_and(|mut entries| entries.next().is_none());
        if !empty {
            bail!(
                "--field-series {}: not an empty directory (the series' files are never \
                 written over anything); name a new directory or empty this one",
                dir.display()
            );
        }
    }
    if let Some(path) = &a.field {
        let vtu = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("vtu"));
        if !vtu {
            bail!(
                "--field {}: name it FILE.vtu (a VTK XML unstructured grid, which ParaView \
                 opens by that extension)",
                path.display()
            );
        }
    }
    refuse_taken(
        [
            ("--plot", &a.plot),
            ("--history", &a.history),
            ("--surface", &a.surface),
            ("--field", &a.field),
        ]
        .into_iter()
        .filter_map(|(flag, path)| Some((flag, path.as_deref()?))),
    )
}

/// The context of a data file's failed write (its cause follows it;
/// one that exists is refused before the run: [`check_outputs`]).
fn not_written(flag: &str, path: &std::path::Path) -> String {
    format!("{flag} {}: not written", path.display())
}

/// The case the arguments describe.
fn case(a: &Aero2dArgs) -> Result<Case> {
    let deformation = match &a.deformation {
        Some(path) => Some(SectionFile::read(path)?.points()),
        None => None,
    };
    let section = match a.model {
        FlowModel::Ns => {
            let shape = SectionModel::named_viscous_deforming(
                &a.section,
                a.ns_thickness,
                deformation.as_deref(),
            )
            .with_context(|| match &a.deformation {
                Some(path) => format!("--section {} --deformation {}", a.section, path.display()),
                None => format!("--section {}", a.section),
            })?;
            let plate = ViscousSection::new(shape);
            let plate = match a.ns_radial {
                Some(radial) => plate.with_radial(radial),
                None => plate,
            };
            SectionModel::Viscous(ViscousSection {
                around: a.ns_around.unwrap_or(plate.around),
                courant: a.ns_courant.unwrap_or(plate.courant),
                field_frames: a
                    .field_series
                    .as_ref()
                    .map_or(0, |_| a.field_frames.unwrap_or(DEFAULT_FIELD_FRAMES)),
                ..plate
            })
        }
        FlowModel::Inviscid => {
            SectionModel::named(&a.section).with_context(|| format!("--section {}", a.section))?
        }
    };
    Ok(Case {
        section,
        motion: Motion {
            reduced_frequency: a.reduced_frequency,
            plunge_amplitude: a.plunge_amplitude,
            mean_pitch: a.mean_pitch_deg.to_radians(),
            pitch_amplitude: a.pitch_amplitude_deg.to_radians(),
            pitch_phase: a.pitch_phase_deg.to_radians(),
            pivot: a.pivot,
        },
        cycles: a.cycles,
        duration: a.duration,
        lesp_critical: a.lesp_critical,
        reynolds: a.reynolds,
        deformation,
    })
}

/// What the JSON output calls the model that ran.
fn model_name(section: &SectionModel) -> &'static str {
    match section {
        SectionModel::Flat => "thin line (LDVM)",
        SectionModel::Thick(_) => "thick section (panel)",
        SectionModel::Viscous(_) => "laminar Navier-Stokes (ns2d)",
    }
}

/// The result as text for a person.
fn print_text(a: &Aero2dArgs, case: &Case, run: &CaseRun) {
    let m = run.means();
    let net = m.net_ct();
    let k = a.reduced_frequency;
    let lev_count = run.leading_edge_vortices;
    let garrick = case.garrick();
    println!(
        "{} section ({}), k = {k}, h0 = {} c, pitch {} +- {} deg, {} cycles (dt {:.4} c/U){}",
        a.section,
        model_name(&case.section),
        a.plunge_amplitude,
        a.mean_pitch_deg,
        a.pitch_amplitude_deg,
        a.cycles,
        run.dt,
        if a.deformation.is_some() {
            ", deforming"
        } else {
            ""
        }
    );
    let efficiency = match (m.efficiency(), m.net_efficiency()) {
        (Some(eta), Some(net)) => format!("{eta:.3} (net {net:.3})"),
        _ => UNDEFINED_EFFICIENCY.to_string(),
    };
    let viscous = matches!(case.section, SectionModel::Viscous(_));
    let ct_note = if viscous {
        format!("friction included, Re {:.0}", a.reynolds)
    } else {
        format!("net of friction {net:.5}, Re {:.0}", a.reynolds)
    };
    println!(
        "  last cycle: CL {:.4}  CT {:.5} ({ct_note})  CP {:.5}  efficiency {efficiency}",
        m.cl, m.ct, m.cp
    );
    let shed = if viscous {
        String::new()
    } else {
        format!("; {lev_count} leading-edge vortices shed")
    };
    println!(
        "  CT change from the cycle before: {:+.2} %{shed}",
        100.0 * m.periodicity
    );
    if let Some((gct, gcp, geta)) = garrick {
        let geta = if gcp == 0.0 {
            UNDEFINED_EFFICIENCY.to_string()
        } else {
            format!("{geta:.3}")
        };
        println!("  Garrick (1936): CT {gct:.5}  CP {gcp:.5}  efficiency {geta}");
    }
}

/// What a run hands on as it goes: the `--field-series` frames, and how
/// far it has come, shown on a terminal for the Navier–Stokes model (a
/// default run of it takes a minute or more, and printed nothing until
/// its end).
struct RunOutputs {
    series: Option<FlowSeries>,
    bar: Option<ProgressBar>,
}

impl FrameSink for RunOutputs {
    fn take(&mut self, frame: &FlowField) -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
        match &mut self.series {
            Some(series) => series.take(frame),
            None => Ok(()),
        }
    }

    fn reached(&mut self, time: f64, duration: f64) {
        if let Some(bar) = &self.bar {
            bar.set_position((RUN_BAR_LENGTH as f64 * time / duration) as u64);
            bar.set_message(travelled(time, duration));
        }
    }
}

/// How far a run of `duration` chords has come at `time`, as its bar
/// says.
fn travelled(time: f64, duration: f64) -> String {
    format!("{time:.2} of {duration:.2} chords travelled")
}

/// The run's progress bar's length: its position is the share of the run
/// done, in thousandths.
const RUN_BAR_LENGTH: u64 = 1000;

/// The progress bar of a Navier–Stokes run of `duration` chords, saying
/// so from its start (a fine grid's first load sample may be minutes
/// away).
fn run_bar(duration: f64) -> ProgressBar {
    let bar = super::progress::bar(RUN_BAR_LENGTH, "[{elapsed_precise}] {bar:30} {msg}");
    bar.set_message(travelled(0.0, duration));
    bar
}

/// How far the viscous grid's section departs from the contour given
/// (chords, at the map's samples: [`ViscousSection::map_deviation`]),
/// warned of on stderr beyond [`MAP_DEVIATION_WARNING`]; `None` for the
/// inviscid models and the ellipse. A map that does not fit is the run's
/// error, said there.
fn map_deviation(a: &Aero2dArgs, case: &Case) -> Option<f64> {
    let SectionModel::Viscous(section) = &case.section else {
        return None;
    };
    let deviation = section.map_deviation().ok().flatten()?;
    if deviation > MAP_DEVIATION_WARNING {
        eprintln!(
            "warning: --section {}: the grid's section departs from the contour given by about \
             {deviation:.1e} chords where it departs most (its conformal map, {} terms, smooths \
             a corner or fold there, or a bend too tight for so few terms): the run is of that \
             smoothed section; round the contour there, or give more --ns-around (the terms are \
             half of it) where it is merely curved",
            a.section,
            section.around / 2
        );
    }
    Some(deviation)
}

/// Runs the command.
pub fn run(a: &Aero2dArgs) -> Result<()> {
    check(a)?;
    check_outputs(a)?;
    let case = case(a)?;
    case.check_work()?;
    if let SectionModel::Viscous(section) = &case.section {
        let cost = ViscousCost::of(section);
        if cost.is_far_beyond_default() {
            confirm_cost(
                "Navier–Stokes run",
                &cost,
                a.yes,
                "choose a coarser grid (--ns-around, --ns-radial) or fewer --field-frames",
            )?;
        }
    }
    let map_deviation = map_deviation(a, &case);
    // The series is written as the run reaches each frame.
    let series = match &a.field_series {
        Some(dir) => {
            Some(FlowSeries::create(dir).with_context(|| not_written("--field-series", dir))?)
        }
        None => None,
    };
    let live = a.model == FlowModel::Ns && std::io::stderr().is_terminal();
    let mut outputs = RunOutputs {
        series,
        bar: live.then(|| run_bar(case.settings().duration)),
    };
    let run = case.run_into(&mut outputs);
    if let Some(bar) = &outputs.bar {
        bar.finish_and_clear();
    }
    let series = outputs.series;
    // The library's advice on a blow-up, in this command's flags.
    let flags = match &run {
        Err(CaseError::Viscous(ViscousError::Diverged { .. })) => {
            " (the Courant number: --ns-courant; the grid: --ns-around, --ns-radial)"
        }
        _ => "",
    };
    let run = run.with_context(|| {
        let case = match &a.deformation {
            Some(path) => format!(
                "--section {} --deformation {}{flags}",
                a.section,
                path.display()
            ),
            None => format!("--section {}{flags}", a.section),
        };
        match &series {
            Some(s) if !s.is_empty() => format!(
                "{case} (the --field-series frames written so far, {}, are in {})",
                s.len(),
                s.collection().display()
            ),
            _ => case,
        }
    })?;
    if let Some(png) = &a.plot {
        // A run of a given duration has no periods to mark.
        let period = a.duration.is_none().then_some(run.period);
        create_new(png, |temporary| {
            draw(&run.history, &run.vortices, &run.body, period, temporary)
        })
        .with_context(|| format!("--plot {}", png.display()))?;
    }
    if let Some(csv) = &a.history {
        write_history_csv(&run.history, csv).with_context(|| not_written("--history", csv))?;
    }
    if let (Some(csv), Some(surface)) = (&a.surface, &run.surface) {
        write_surface_csv(surface, csv).with_context(|| not_written("--surface", csv))?;
    }
    if let (Some(vtu), Some(field)) = (&a.field, &run.field) {
        write_flow_field(field, vtu).with_context(|| not_written("--field", vtu))?;
    }
    match a.duration {
        Some(duration) => report_window(a, &case, &run, duration, map_deviation),
        None => report_cycles(a, &case, &run, map_deviation),
    }
}

/// The motion in words: `at rest, pitch 10 deg` or `k = 1, h0 = 0.05 c,
/// pitch 0 +- 5 deg`.
fn motion_words(a: &Aero2dArgs, still: bool) -> String {
    if still {
        format!("at rest, pitch {} deg", a.mean_pitch_deg)
    } else {
        format!(
            "k = {}, h0 = {} c, pitch {} +- {} deg",
            a.reduced_frequency, a.plunge_amplitude, a.mean_pitch_deg, a.pitch_amplitude_deg
        )
    }
}

/// The case as the JSON output names it (the section, its motion and
/// deformation, the Reynolds number), with the report's own `fields`.
fn case_json(
    a: &Aero2dArgs,
    map_deviation: Option<f64>,
    fields: serde_json::Value,
) -> serde_json::Value {
    let mut v = serde_json::json!({
        "section": a.section,
        "reduced_frequency": a.reduced_frequency,
        "plunge_amplitude_chords": a.plunge_amplitude,
        "pitch_amplitude_deg": a.pitch_amplitude_deg,
        "mean_pitch_deg": a.mean_pitch_deg,
        "pitch_phase_deg": a.pitch_phase_deg,
        "pivot_chords": a.pivot,
        "deforming": a.deformation.is_some(),
        "reynolds": a.reynolds,
        "section_map_deviation_chords": map_deviation,
    });
    if let (Some(v), serde_json::Value::Object(fields)) = (v.as_object_mut(), fields) {
        v.extend(fields);
    }
    v
}

/// Prints a run without a period (`--duration`): the loads over its
/// second half and at its end.
fn report_window(
    a: &Aero2dArgs,
    case: &Case,
    run: &CaseRun,
    duration: f64,
    map_deviation: Option<f64>,
) -> Result<()> {
    let w = run.second_half().context(
        "the run left fewer than two load samples over its second half: give a longer --duration",
    )?;
    let h = &run.history;
    let last = h.time.len() - 1;
    let (end, cl_end, cd_end) = (h.time[last], h.cl[last], -h.ct[last]);
    let still = case.is_still();
    if a.json {
        let v = case_json(
            a,
            map_deviation,
            serde_json::json!({
                "model": model_name(&case.section),
                "at_rest": still,
                "duration_chords": duration,
                "sample_chords": run.dt,
                "window": {
                    "from_chords": w.from,
                    "to_chords": w.to,
                    "mean_cl": w.cl_mean,
                    "cl_swing": w.cl_swing,
                    "mean_cd": w.cd_mean,
                    "cd_swing": w.cd_swing,
                    "mean_cp": w.cp_mean,
                },
                "shedding": w.shedding.map(|s| serde_json::json!({
                    "strouhal": s.strouhal,
                    "periods": s.periods,
                })),
                "end": {"time_chords": end, "cl": cl_end, "cd": cd_end},
            }),
        );
        println!("{v:#}");
        return Ok(());
    }
    println!(
        "{} section ({}), {}, {duration} chords travelled (loads every {:.4} c/U), Re {:.0}{}",
        a.section,
        model_name(&case.section),
        motion_words(a, still),
        run.dt,
        a.reynolds,
        if a.deformation.is_some() {
            ", deforming"
        } else {
            ""
        }
    );
    println!(
        "  over U t/c {:.2} to {:.2}: CL {:.4} +- {:.4}  CD {:.4} +- {:.4}  CP {:.5}",
        w.from, w.to, w.cl_mean, w.cl_swing, w.cd_mean, w.cd_swing, w.cp_mean
    );
    match w.shedding {
        Some(s) => println!(
            "  the lift oscillates at Strouhal number f c/U {:.4} ({} periods)",
            s.strouhal, s.periods
        ),
        None => println!(
            "  the lift does not oscillate over it (steady, or fewer than {MIN_SHEDDING_PERIODS} \
             periods)"
        ),
    }
    println!("  at U t/c {end:.2}: CL {cl_end:.4}  CD {cd_end:.4}");
    Ok(())
}

/// Prints a periodic run: the last cycle's means and its periodicity
/// (an error, [`Doubtful`], when it is not periodic).
fn report_cycles(
    a: &Aero2dArgs,
    case: &Case,
    run: &CaseRun,
    map_deviation: Option<f64>,
) -> Result<()> {
    let m = run.means();
    let periodic = (!m.is_periodic()).then(|| {
        format!(
            "the result is not periodic: the mean CT changed by {:.0}% of its size or swing \
             between the last two cycles (more than {:.0}%); run more --cycles ({} now)",
            100.0 * m.change_of_swing,
            100.0 * PERIODIC_CHANGE,
            a.cycles
        )
    });
    let doubt: Vec<String> = periodic
        .into_iter()
        .chain(separation_doubt(a, run))
        .collect();
    let net = m.net_ct();
    let (wake_count, lev_count) = (run.wake_vortices, run.leading_edge_vortices);
    let garrick = case.garrick();
    if a.json {
        let mut v = case_json(
            a,
            map_deviation,
            serde_json::json!({
                "lesp_critical": a.lesp_critical,
                "cycles": a.cycles,
                "time_step_chords": run.dt,
                "mean_cl": m.cl,
                "mean_ct": m.ct,
                "mean_cd_friction": m.cd_friction,
                "mean_ct_net": net,
                "mean_cp": m.cp,
                "efficiency": m.efficiency(),
                "net_efficiency": m.net_efficiency(),
                "mean_ct_change_last_two_cycles": m.periodicity,
                "periodic": m.is_periodic(),
                "warnings": doubt,
                "wake_vortices": wake_count,
                "leading_edge_vortices": lev_count,
                "model": model_name(&case.section),
            }),
        );
        if let Some((gct, gcp, geta)) = garrick {
            let geta = (gcp != 0.0).then_some(geta);
            v["garrick"] = serde_json::json!({"mean_ct": gct, "mean_cp": gcp, "efficiency": geta});
        }
        println!("{v:#}");
    } else {
        print_text(a, case, run);
    }
    if doubt.is_empty() {
        Ok(())
    } else {
        Err(Doubtful(doubt).into())
    }
}

/// A thin-line run kept attached (no `--lesp-critical`) whose leading
/// edge would have shed: its leading-edge suction parameter passed the
/// flat plate's critical value ([`FWAV_LESP_CRITICAL`]) in the last cycle.
/// Attached flow is the theory Garrick's is (a valid comparison), but not
/// the flow a plate holds there: a mean pitch of 45 deg gave CL 4.27.
fn separation_doubt(a: &Aero2dArgs, run: &CaseRun) -> Option<String> {
    let peak = run.peak_lesp()?;
    (a.lesp_critical.is_none() && peak > FWAV_LESP_CRITICAL).then(|| {
        format!(
            "the flow was kept attached (no --lesp-critical), but the leading-edge suction \
             parameter |A0| reached {peak:.3} in the last cycle, past the flat plate's critical \
             {FWAV_LESP_CRITICAL} beyond which its leading edge sheds a vortex (Ramesh et al. \
             2014): the loads are those of a flow the section does not hold; give \
             --lesp-critical {FWAV_LESP_CRITICAL} to shed it, or a gentler motion"
        )
    })
}
