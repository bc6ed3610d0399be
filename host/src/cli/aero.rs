//! `fwav aero2d`: one 2D unsteady analysis of a plunging/pitching section.

use std::f64::consts::PI;

use anyhow::{bail, Result};
use fwav::aero2d::ldvm::{cycle_means, cycle_means_until, Ldvm, Motion, Settings};
use fwav::aero2d::theory::garrick_plunge;

/// The command's options.
#[derive(clap::Args)]
pub struct Aero2dArgs {
    /// Section: flat (thin plate).
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
    /// Pitch axis, chords from the leading edge.
    #[arg(long, default_value_t = 0.25)]
    pub pivot: f64,
    /// Cycles to simulate.
    #[arg(long, default_value_t = 5)]
    pub cycles: u32,
    /// Machine-readable output.
    #[arg(long)]
    pub json: bool,
}

pub fn run(a: &Aero2dArgs) -> Result<()> {
    if a.section != "flat" {
        bail!("--section {:?}: only `flat` (thin plate) is available so far; naca0012 and point files come with the thick-section panel model", a.section);
    }
    if !(a.reduced_frequency > 0.0 && a.reduced_frequency <= 20.0) {
        bail!(
            "--reduced-frequency {} must be in (0, 20]",
            a.reduced_frequency
        );
    }
    if !(a.plunge_amplitude.abs() <= 2.0
        && a.pitch_amplitude_deg.abs() <= 60.0
        && (0.0..=1.0).contains(&a.pivot))
    {
        bail!(
            "amplitudes out of range: plunge <= 2 chords, pitch <= 60 deg, pivot in [0, 1] chords"
        );
    }
    if a.cycles < 2 || a.cycles > 50 {
        bail!("--cycles {} must be between 2 and 50", a.cycles);
    }
    let k = a.reduced_frequency;
    let period = PI / k;
    let motion = Motion {
        reduced_frequency: k,
        plunge_amplitude: a.plunge_amplitude,
        mean_pitch: 0.0,
        pitch_amplitude: a.pitch_amplitude_deg.to_radians(),
        pitch_phase: a.pitch_phase_deg.to_radians(),
        pivot: a.pivot,
    };
    // At least ~100 steps a cycle.
    let defaults = Settings::default();
    let settings = Settings {
        dt: defaults.dt.min(period / 100.0),
        duration: f64::from(a.cycles) * period,
        ..defaults
    };
    let mut solver = Ldvm::new(motion, settings);
    let history = solver.run();
    let (ct, cp, eta) = cycle_means(&history, period, 1);
    // The cycle before the last, for the periodicity check: the window ends
    // one period's worth of steps before the last sample.
    let steps_per_period = (period / settings.dt).round() as usize;
    let end_previous = history
        .time
        .len()
        .checked_sub(steps_per_period + 1)
        .map_or(0.0, |i| history.time[i]);
    let (ct_prev, _, _) = cycle_means_until(&history, period, 1, end_previous);
    let periodicity = (ct - ct_prev) / ct.abs().max(1e-12);
    let garrick = (a.pitch_amplitude_deg == 0.0).then(|| garrick_plunge(k, a.plunge_amplitude));
    if a.json {
        let mut v = serde_json::json!({
            "section": a.section,
            "reduced_frequency": k,
            "plunge_amplitude_chords": a.plunge_amplitude,
            "pitch_amplitude_deg": a.pitch_amplitude_deg,
            "cycles": a.cycles,
            "time_step_chords": settings.dt,
            "mean_ct": ct,
            "mean_cp": cp,
            "efficiency": eta,
            "mean_ct_change_last_two_cycles": periodicity,
            "wake_vortices": solver.wake().len(),
        });
        if let Some((gct, gcp, geta)) = garrick {
            v["garrick"] = serde_json::json!({"mean_ct": gct, "mean_cp": gcp, "efficiency": geta});
        }
        println!("{v:#}");
    } else {
        println!(
            "flat plate, k = {k}, h0 = {} c, pitch {} deg, {} cycles (dt {:.4} c/U)",
            a.plunge_amplitude, a.pitch_amplitude_deg, a.cycles, settings.dt
        );
        println!("  last cycle: CT {ct:.5}  CP {cp:.5}  efficiency {eta:.3}  (CT change from the cycle before: {:+.2} %)", 100.0 * periodicity);
        if let Some((gct, gcp, geta)) = garrick {
            println!("  Garrick (1936): CT {gct:.5}  CP {gcp:.5}  efficiency {geta:.3}");
        }
    }
    Ok(())
}
