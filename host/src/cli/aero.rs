//! `fwav aero2d`: one 2D unsteady analysis of a plunging/pitching,
//! optionally deforming section.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use fwav::aero2d::camber::CamberHistory;
use fwav::aero2d::friction::{friction_history, FWAV_REYNOLDS};
use fwav::aero2d::ldvm::{
    cycle_mean_of, cycle_means, cycle_means_until, History, Ldvm, Motion, Settings,
};
use fwav::aero2d::naca::{read_points, Naca4, TrailingEdge};
use fwav::aero2d::panel::{PanelSettings, PanelSolver, SectionShape, ShapeHistory, DEFAULT_PANELS};
use fwav::aero2d::plot::draw;
use fwav::aero2d::theory::garrick_plunge;

/// The command's options.
#[derive(clap::Args)]
pub struct Aero2dArgs {
    /// Section: `flat` (thin line, LDVM), a NACA 4-digit name such as
    /// `naca0012` (thick section, panel method), or a file of x y points
    /// (Selig order or clockwise from the trailing edge, chords).
    #[arg(long, default_value = "flat")]
    pub section: String,
    /// Plunge amplitude, chords.
    #[arg(long, default_value_t = 0.05)]
    pub plunge_amplitude: f64,
    /// Reduced frequency k = omega c / (2 U).
    #[arg(long, default_value_t = 1.0)]
    pub reduced_frequency: f64,
    /// Pitch amplitude, degrees.
    #[arg(long, default_value_t = 0.0)]
    pub pitch_amplitude_deg: f64,
    /// Phase by which pitch leads plunge, degrees.
    #[arg(long, default_value_t = 90.0)]
    pub pitch_phase_deg: f64,
    /// Mean pitch angle, degrees.
    #[arg(long, default_value_t = 0.0)]
    pub mean_pitch_deg: f64,
    /// Pitch axis, chords from the leading edge.
    #[arg(long, default_value_t = 0.25)]
    pub pivot: f64,
    /// Cycles to simulate.
    #[arg(long, default_value_t = 5)]
    pub cycles: u32,
    /// Critical leading-edge suction parameter: shed leading-edge vortices
    /// beyond it (LDVM). Off when not given.
    #[arg(long)]
    pub lesp_critical: Option<f64>,
    /// Chord Reynolds number for the laminar skin-friction estimate
    /// (default: the built-in FWAV, 3 m/s, 0.075 m chord, sea-level air).
    #[arg(long, default_value_t = FWAV_REYNOLDS)]
    pub reynolds: f64,
    /// Deformation history of the section over one period, JSON:
    /// `{"samples": [[[x, y], ...], ...]}`, samples equally spaced in time,
    /// in the section's kinematic frame (chords, leading edge at (0, 0),
    /// trailing edge at (1, 0)): for `flat` the mid-line points from the
    /// leading to the trailing edge; for a thick section the whole contour,
    /// as many points as the section has, in its order.
    #[arg(long)]
    pub deformation: Option<PathBuf>,
    /// Draw the wake and the force histories to this PNG.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Machine-readable output.
    #[arg(long)]
    pub json: bool,
}

/// The deformation file's layout (`fwav system-analysis --out` writes it
/// as `section.json`, with a description and the period it covers).
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct DeformationFile {
    samples: Vec<Vec<(f64, f64)>>,
    #[serde(default, rename = "description")]
    _description: Option<String>,
    #[serde(default, rename = "period_s")]
    _period_s: Option<f64>,
}

/// The samples of a deformation file.
fn read_samples(path: &Path) -> Result<Vec<Vec<(f64, f64)>>> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
    let file: DeformationFile = serde_json::from_str(&text)
        .with_context(|| format!("{}: not a deformation history", path.display()))?;
    Ok(file.samples)
}

/// A thin section's deformation: mid-line samples as a camber history.
fn read_deformation(path: &Path, period: f64) -> Result<CamberHistory> {
    let samples = read_samples(path)?;
    let stations = samples.iter().map(Vec::len).max().unwrap_or(0).max(21);
    CamberHistory::from_section_points(&samples, period, stations)
        .with_context(|| format!("{}", path.display()))
}

/// The thick section named by `--section`: a NACA 4-digit name or a point
/// file.
fn thick_section(name: &str) -> Result<SectionShape> {
    let points = match name.parse::<Naca4>() {
        Ok(naca) => naca
            .points(DEFAULT_PANELS, TrailingEdge::Closed)
            .with_context(|| format!("--section {name}"))?,
        Err(naca_error) => {
            let path = Path::new(name);
            if !path.exists() {
                bail!("--section {name:?}: neither `flat`, a NACA 4-digit name ({naca_error}), nor an existing point file");
            }
            read_points(path)
                .with_context(|| format!("--section {name}"))?
                .points
        }
    };
    SectionShape::new(&points).with_context(|| format!("--section {name}"))
}

/// A thick section's deformation: the same file layout, each sample the
/// closed contour (as many points as the section, in its order).
fn read_contour_history(path: &Path, period: f64) -> Result<ShapeHistory> {
    ShapeHistory::new(&read_samples(path)?, period).with_context(|| format!("{}", path.display()))
}

fn check(a: &Aero2dArgs) -> Result<()> {
    if a.section != "flat" && a.lesp_critical.is_some() {
        bail!("--lesp-critical applies to the thin-line (`--section flat`) model only");
    }
    if !(a.reduced_frequency > 0.0 && a.reduced_frequency <= 20.0) {
        bail!(
            "--reduced-frequency {} must be in (0, 20]",
            a.reduced_frequency
        );
    }
    if !(-2.0..=2.0).contains(&a.plunge_amplitude) {
        bail!(
            "--plunge-amplitude {} must be within +-2 chords",
            a.plunge_amplitude
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
            a.pivot
        );
    }
    if a.cycles < 2 || a.cycles > 50 {
        bail!("--cycles {} must be between 2 and 50", a.cycles);
    }
    if let Some(l) = a.lesp_critical {
        if !(l > 0.0 && l < 10.0) {
            bail!("--lesp-critical {l} must be in (0, 10)");
        }
    }
    if !(100.0..=1e8).contains(&a.reynolds) {
        bail!("--reynolds {} must be in [100, 1e8]", a.reynolds);
    }
    Ok(())
}

/// Cycle means of one run.
struct Means {
    ct: f64,
    cp: f64,
    efficiency: f64,
    cd_friction: f64,
    cl: f64,
    periodicity: f64,
}

fn means(history: &History, period: f64, dt: f64) -> Means {
    let (ct, cp, efficiency) = cycle_means(history, period, 1);
    // The cycle before the last, for the periodicity check: the window ends
    // one period's worth of steps before the last sample.
    let steps_per_period = (period / dt).round() as usize;
    let end_previous = history
        .time
        .len()
        .checked_sub(steps_per_period + 1)
        .map_or(0.0, |i| history.time[i]);
    let (ct_prev, _, _) = cycle_means_until(history, period, 1, end_previous);
    Means {
        ct,
        cp,
        efficiency,
        cd_friction: cycle_mean_of(history, &history.cd_friction, period, 1),
        cl: cycle_mean_of(history, &history.cl, period, 1),
        periodicity: (ct - ct_prev) / ct.abs().max(1e-12),
    }
}

pub fn run(a: &Aero2dArgs) -> Result<()> {
    check(a)?;
    let k = a.reduced_frequency;
    let period = PI / k;
    let motion = Motion {
        reduced_frequency: k,
        plunge_amplitude: a.plunge_amplitude,
        mean_pitch: a.mean_pitch_deg.to_radians(),
        pitch_amplitude: a.pitch_amplitude_deg.to_radians(),
        pitch_phase: a.pitch_phase_deg.to_radians(),
        pivot: a.pivot,
    };
    // At least ~100 steps a cycle.
    let defaults = Settings::default();
    let settings = Settings {
        dt: defaults.dt.min(period / 100.0),
        duration: f64::from(a.cycles) * period,
        lesp_critical: a.lesp_critical,
        reynolds: Some(a.reynolds),
        ..defaults
    };
    let (history, wake_count, lev_count) = if a.section == "flat" {
        let mut solver = Ldvm::new(motion, settings);
        if let Some(path) = &a.deformation {
            solver = solver.with_camber(read_deformation(path, period)?);
        }
        let history = solver.run();
        let wake: Vec<_> = solver
            .wake()
            .iter()
            .chain(solver.leading_edge_vortices())
            .copied()
            .collect();
        if let Some(png) = &a.plot {
            draw(&history, &wake, &solver.section_points(), Some(period), png)
                .with_context(|| format!("--plot {}", png.display()))?;
        }
        (
            history,
            solver.wake().len(),
            solver.leading_edge_vortices().len(),
        )
    } else {
        let section = thick_section(&a.section)?;
        let panel_settings = PanelSettings {
            dt: settings.dt,
            duration: settings.duration,
            far_wake: settings.far_wake,
        };
        let mut solver = PanelSolver::new(&section, motion, panel_settings)
            .with_context(|| format!("--section {}", a.section))?;
        if let Some(path) = &a.deformation {
            solver = solver
                .with_shape_history(read_contour_history(path, period)?)
                .with_context(|| format!("--deformation {}", path.display()))?;
        }
        let mut history = solver.run();
        history.cd_friction = friction_history(&motion, &history.time, a.reynolds);
        if let Some(png) = &a.plot {
            let t = settings.duration;
            let (h, _, alpha, _) = motion.at(t);
            let (s, c) = alpha.sin_cos();
            let p = a.pivot;
            let body: Vec<(f64, f64)> = solver
                .surface_pressure()
                .0
                .iter()
                .map(|&[x, y]| (p + (x - p) * c + y * s, h - (x - p) * s + y * c))
                .collect();
            draw(&history, solver.wake(), &body, Some(period), png)
                .with_context(|| format!("--plot {}", png.display()))?;
        }
        (history, solver.wake().len(), 0)
    };
    let m = means(&history, period, settings.dt);
    let net = m.ct - m.cd_friction;
    let rigid_plunge = a.pitch_amplitude_deg == 0.0
        && a.mean_pitch_deg == 0.0
        && a.deformation.is_none()
        && a.lesp_critical.is_none();
    let garrick = rigid_plunge.then(|| garrick_plunge(k, a.plunge_amplitude));
    if a.json {
        let mut v = serde_json::json!({
            "section": a.section,
            "reduced_frequency": k,
            "plunge_amplitude_chords": a.plunge_amplitude,
            "pitch_amplitude_deg": a.pitch_amplitude_deg,
            "mean_pitch_deg": a.mean_pitch_deg,
            "pitch_phase_deg": a.pitch_phase_deg,
            "pivot_chords": a.pivot,
            "deforming": a.deformation.is_some(),
            "lesp_critical": a.lesp_critical,
            "reynolds": a.reynolds,
            "cycles": a.cycles,
            "time_step_chords": settings.dt,
            "mean_cl": m.cl,
            "mean_ct": m.ct,
            "mean_cd_friction": m.cd_friction,
            "mean_ct_net": net,
            "mean_cp": m.cp,
            "efficiency": m.efficiency,
            "net_efficiency": net / m.cp,
            "mean_ct_change_last_two_cycles": m.periodicity,
            "wake_vortices": wake_count,
            "leading_edge_vortices": lev_count,
            "model": if a.section == "flat" { "thin line (LDVM)" } else { "thick section (panel)" },
        });
        if let Some((gct, gcp, geta)) = garrick {
            v["garrick"] = serde_json::json!({"mean_ct": gct, "mean_cp": gcp, "efficiency": geta});
        }
        println!("{v:#}");
    } else {
        println!(
            "{} section, k = {k}, h0 = {} c, pitch {} +- {} deg, {} cycles (dt {:.4} c/U){}",
            a.section,
            a.plunge_amplitude,
            a.mean_pitch_deg,
            a.pitch_amplitude_deg,
            a.cycles,
            settings.dt,
            if a.deformation.is_some() {
                ", deforming"
            } else {
                ""
            }
        );
        println!(
            "  last cycle: CL {:.4}  CT {:.5} (net of friction {net:.5}, Re {:.0})  CP {:.5}  efficiency {:.3} (net {:.3})",
            m.cl, m.ct, a.reynolds, m.cp, m.efficiency, net / m.cp
        );
        println!(
            "  CT change from the cycle before: {:+.2} %; {} leading-edge vortices shed",
            100.0 * m.periodicity,
            lev_count
        );
        if let Some((gct, gcp, geta)) = garrick {
            println!("  Garrick (1936): CT {gct:.5}  CP {gcp:.5}  efficiency {geta:.3}");
        }
    }
    Ok(())
}
