//! The thin-plate discrete-vortex solver against classical unsteady
//! aerodynamics (formulas: ../shared/REFERENCES.md).

use std::f64::consts::PI;

use fwav::aero2d::ldvm::{cycle_means, Ldvm, Motion, Settings};
use fwav::aero2d::theory::{garrick_plunge, wagner};

fn plunge(k: f64) -> Motion {
    Motion::plunge(k, 0.05)
}

/// (CT, CP, efficiency) over the last 2 of 5 cycles; 100+ steps a cycle.
fn garrick_case(k: f64) -> (f64, f64, f64) {
    let period = PI / k;
    let settings = Settings {
        dt: 0.02 * (1.0f64).min(1.0 / k),
        duration: 5.0 * period,
        ..Settings::default()
    };
    let history = Ldvm::new(plunge(k), settings).run();
    cycle_means(&history, period, 2)
}

/// Garrick (1936) pure plunge, h0 = 0.05 c: cycle-mean thrust within 10%.
#[test]
fn garrick_thrust_within_10_percent() {
    for k in [0.5, 1.0, 2.0] {
        let (ct, _, _) = garrick_case(k);
        let (reference, _, _) = garrick_plunge(k, 0.05);
        let error = ct / reference - 1.0;
        println!(
            "k = {k}: CT {ct:.5} vs Garrick {reference:.5} ({:+.1}%)",
            100.0 * error
        );
        assert!(
            error.abs() < 0.10,
            "k = {k}: CT {ct:.5} vs Garrick {reference:.5} ({:+.1}%)",
            100.0 * error
        );
    }
}

/// Garrick efficiency within 10% at k = 0.5, 1 and 2.
#[test]
fn garrick_efficiency_within_10_percent() {
    for k in [0.5, 1.0, 2.0] {
        let (_, _, eta) = garrick_case(k);
        let (_, _, reference) = garrick_plunge(k, 0.05);
        let error = eta / reference - 1.0;
        println!(
            "k = {k}: efficiency {eta:.3} vs Garrick {reference:.3} ({:+.1}%)",
            100.0 * error
        );
        assert!(
            error.abs() < 0.10,
            "k = {k}: efficiency {eta:.3} vs Garrick {reference:.3} ({:+.1}%)",
            100.0 * error
        );
    }
}

/// Lift after a sudden start at alpha = 0.05 rad over the steady thin-plate
/// lift 2 pi sin(alpha), against Wagner's function (exact, [`wagner`]).
fn wagner_errors(dt: f64, s_values: &[f64]) -> Vec<f64> {
    let motion = Motion::steady(0.05);
    let duration = s_values.iter().fold(0.0f64, |a, &b| a.max(b)) / 2.0 + 0.1;
    let history = Ldvm::new(
        motion,
        Settings {
            dt,
            duration,
            far_wake: 1e9,
            ..Settings::default()
        },
    )
    .run();
    let steady = 2.0 * PI * 0.05f64.sin();
    s_values
        .iter()
        .map(|&s| {
            let i = history
                .time
                .iter()
                .position(|&t| t >= s / 2.0 - 1e-9)
                .expect("long enough");
            history.cl[i] / steady / wagner(s) - 1.0
        })
        .collect()
}

/// Within 3% at s = 5 and 10 semichords (measured +1.53%, +0.65% at
/// dt 0.01).
#[test]
fn wagner_lift_within_3_percent_from_5_semichords() {
    for (s, e) in [5.0, 10.0].iter().zip(wagner_errors(0.01, &[5.0, 10.0])) {
        println!("s = {s}: {:+.2}% from Wagner", 100.0 * e);
        assert!(e.abs() < 0.03, "s = {s}: {:+.2}%", 100.0 * e);
    }
}

/// The early lift converges slowly with the time step (the nascent
/// trailing-edge vortex): at s = 1 and 2 semichords +5.3%/+3.4% at dt 0.01,
/// +3.8%/+2.4% at 0.005, +2.7%/+1.7% at 0.0025 and +1.95%/+1.23% at
/// 0.00125 (against the exact Wagner function; Jones' approximation is 1.1%
/// low at s = 1). Within 3% at dt = 0.00125.
#[test]
fn wagner_lift_within_3_percent_at_1_and_2_semichords() {
    for (s, e) in [1.0, 2.0].iter().zip(wagner_errors(0.00125, &[1.0, 2.0])) {
        println!("s = {s}: {:+.2}% from Wagner (dt 0.00125)", 100.0 * e);
        assert!(e.abs() < 0.03, "s = {s}: {:+.2}%", 100.0 * e);
    }
}

/// Kelvin's theorem holds to round-off: the bound circulation equals the
/// total shed circulation at every step.
#[test]
fn circulation_is_conserved() {
    let motion = Motion {
        pitch_amplitude: 0.2,
        pitch_phase: 1.5,
        ..plunge(1.0)
    };
    let mut solver = Ldvm::new(
        motion,
        Settings {
            duration: 4.0,
            ..Settings::default()
        },
    );
    let history = solver.run();
    let shed: f64 = solver.wake().iter().map(|v| v.gamma).sum();
    let bound = *history.bound_circulation.last().unwrap();
    assert!(
        (bound - shed).abs() < 1e-9 * bound.abs().max(1e-3),
        "{bound} vs {shed}"
    );
}

/// Letting the wake beyond the default 2 chords drift (no self-induced
/// roll-up) changes the mean CT by less than 1% (issue: far-wake handling,
/// effect < 1%).
#[test]
fn far_wake_drift_changes_ct_by_less_than_1_percent() {
    let k = 1.0;
    let period = PI / k;
    let run = |far_wake| {
        let s = Settings {
            dt: 0.02,
            duration: 6.0 * period,
            far_wake,
            ..Settings::default()
        };
        cycle_means(&Ldvm::new(plunge(k), s).run(), period, 2).0
    };
    let (cut, full) = (run(Settings::default().far_wake), run(1e9));
    println!(
        "far wake drifting: CT {cut:.6} vs full {full:.6} ({:+.2}%)",
        100.0 * (cut / full - 1.0)
    );
    assert!((cut / full - 1.0).abs() < 0.01, "{cut} vs {full}");
}

/// Convergence (issue: CT changes < 2% when elements and time steps are
/// doubled at the default resolution), k = 1 plunge, 4 cycles.
#[test]
fn ct_converges_when_resolution_doubles() {
    let k = 1.0;
    let period = PI / k;
    let base = Settings {
        duration: 4.0 * period,
        ..Settings::default()
    };
    let fine = Settings {
        dt: base.dt / 2.0,
        chord_points: 2 * base.chord_points,
        fourier_terms: 2 * base.fourier_terms,
        ..base
    };
    let ct = |s| cycle_means(&Ldvm::new(plunge(k), s).run(), period, 1).0;
    let (coarse, refined) = (ct(base), ct(fine));
    println!(
        "CT {coarse:.6} -> {refined:.6} ({:+.2}%)",
        100.0 * (refined / coarse - 1.0)
    );
    assert!((refined / coarse - 1.0).abs() < 0.02);
}

/// Thin-airfoil theory: a parabolic camber line `eta = 4 m x (1 - x)` at
/// angle alpha has `A0 = alpha`, `A1 = 4 m`, so the steady lift is
/// `2 pi (alpha + 2 m)`; after a sudden start it follows Wagner's function
/// towards that value like the flat plate (within 3% at s = 5, 10).
#[test]
fn steady_camber_lifts_as_thin_airfoil_theory_says() {
    use fwav::aero2d::camber::CamberHistory;
    let (alpha, m) = (0.03, 0.02);
    let stations: Vec<f64> = (0..=40).map(|i| i as f64 / 40.0).collect();
    let offsets = stations.iter().map(|x| 4.0 * m * x * (1.0 - x)).collect();
    let camber = CamberHistory::steady(stations, offsets).unwrap();
    let motion = Motion::steady(alpha);
    let history = Ldvm::new(
        motion,
        Settings {
            dt: 0.01,
            duration: 5.2,
            ..Settings::default()
        },
    )
    .with_camber(camber)
    .run();
    let steady = 2.0 * PI * (alpha + 2.0 * m);
    for s in [5.0, 10.0] {
        let i = history
            .time
            .iter()
            .position(|&t| t >= s / 2.0 - 1e-9)
            .unwrap();
        let e = history.cl[i] / steady / wagner(s) - 1.0;
        println!(
            "cambered plate s = {s}: {:+.2}% from 2 pi (alpha + 2m) phi(s)",
            100.0 * e
        );
        assert!(e.abs() < 0.03, "s = {s}: {:+.2}%", 100.0 * e);
    }
}

/// The deformation machinery against rigid motion: a camber line that is a
/// rigid rotation about the pivot, `eta = -(x - x_p) delta(t)`, must give the
/// lift of the plate pitching by `delta(t)` (to first order in delta).
#[test]
fn camber_that_is_a_rotation_lifts_like_pitch() {
    use fwav::aero2d::camber::CamberHistory;
    let (k, amplitude, pivot) = (1.0, 2f64.to_radians(), 0.25);
    let period = PI / k;
    let pitching = Motion {
        reduced_frequency: k,
        plunge_amplitude: 0.0,
        mean_pitch: 0.0,
        pitch_amplitude: amplitude,
        pitch_phase: 0.0,
        pivot,
    };
    let settings = Settings {
        duration: 3.0 * period,
        ..Settings::default()
    };
    let pitch = Ldvm::new(pitching, settings).run();
    let stations: Vec<f64> = (0..=20).map(|i| i as f64 / 20.0).collect();
    let samples: Vec<Vec<f64>> = (0..200)
        .map(|i| {
            let delta = amplitude * (2.0 * PI * i as f64 / 200.0).sin();
            stations.iter().map(|x| -(x - pivot) * delta).collect()
        })
        .collect();
    let camber = CamberHistory::new(stations, samples, period).unwrap();
    let still = Motion {
        pitch_amplitude: 0.0,
        ..pitching
    };
    let flex = Ldvm::new(still, settings).with_camber(camber).run();
    let last = |h: &fwav::aero2d::ldvm::History| {
        let n = (period / settings.dt) as usize;
        h.cl[h.cl.len() - n..]
            .iter()
            .fold(0.0f64, |a, b| a.max(b.abs()))
    };
    let (a, b) = (last(&pitch), last(&flex));
    println!(
        "lift amplitude: pitching {a:.5}, rotating camber {b:.5} ({:+.2}%)",
        100.0 * (b / a - 1.0)
    );
    assert!((b / a - 1.0).abs() < 0.02, "{a} vs {b}");
    // And the same mean input power: pitch work = deformation work.
    let (_, cp_pitch, _) = cycle_means(&pitch, period, 1);
    let (_, cp_flex, _) = cycle_means(&flex, period, 1);
    println!(
        "mean power: pitching {cp_pitch:.6}, rotating camber {cp_flex:.6} ({:+.2}%)",
        100.0 * (cp_flex / cp_pitch - 1.0)
    );
    assert!(
        (cp_flex / cp_pitch - 1.0).abs() < 0.02,
        "{cp_pitch} vs {cp_flex}"
    );
}
