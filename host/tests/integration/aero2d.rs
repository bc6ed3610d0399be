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

/// Within 3% at s = 5 and 10 semichords (measured +0.04%, +0.01% at
/// dt 0.01; +1.53%, +0.65% before 2026-12-07, when the newest wake vortex
/// was placed a third of the way to the last and the chord saw the
/// vortices' 1.3 U dt core: `fwav::aero2d::ldvm`, "The wake next to the
/// edge").
#[test]
fn wagner_lift_within_3_percent_from_5_semichords() {
    for (s, e) in [5.0, 10.0].iter().zip(wagner_errors(0.01, &[5.0, 10.0])) {
        println!("s = {s}: {:+.2}% from Wagner", 100.0 * e);
        assert!(e.abs() < 0.03, "s = {s}: {:+.2}%", 100.0 * e);
    }
}

/// The early lift, at s = 1 and 2 semichords, within 1% at dt 0.01
/// (against the exact Wagner function; Jones' approximation is 1.1% low
/// at s = 1): measured +0.26%/+0.13% at dt 0.01, +0.16%/+0.07% at 0.005,
/// +0.14%/+0.06% at 0.0025 and +0.32%/+0.18% at 0.00125, where the
/// step's travel nears the spacing of the chord's end stations (80
/// stations: 4e-4 c). Before 2026-12-07 (the newest wake vortex a third of
/// the way to the last, the 1.3 U dt core on the chord) the nascent
/// vortex made it converge as sqrt(dt): +5.3%/+3.4% at dt 0.01, +3.8%/+2.4%
/// at 0.005, +2.7%/+1.7% at 0.0025 and +1.95%/+1.23% at 0.00125, and this
/// test ran at 0.00125 within 3%.
#[test]
fn wagner_lift_within_1_percent_at_1_and_2_semichords() {
    for (s, e) in [1.0, 2.0].iter().zip(wagner_errors(0.01, &[1.0, 2.0])) {
        println!("s = {s}: {:+.2}% from Wagner (dt 0.01)", 100.0 * e);
        assert!(e.abs() < 0.01, "s = {s}: {:+.2}%", 100.0 * e);
    }
}

/// Garrick's (1936) small plunge (k = 1, h = 0.01 c, where his linear
/// theory holds) at the validation's step, 0.02, and at its half and
/// quarter: thrust and input power each within 1% of his at every step,
/// so no `sqrt(dt)` term is left (`fwav::aero2d::ldvm`, "The wake next to
/// the edge"). Measured: CT -0.04%, -0.04%, +0.03%; CP +0.21%, +0.11%,
/// +0.13%. With Ramesh et al.'s placement (a third of the way to the
/// last vortex) and the vortices' 1.3 U dt core on the chord, until
/// 2026-12-07: CT +6.04%, +4.12%, +2.91%, CP +10.31%, +7.41%, +5.36%,
/// each halving of the step taking off the same fraction, 1/sqrt(2), of
/// the error.
#[test]
fn garrick_loads_within_1_percent_at_every_step() {
    let (k, h) = (1.0, 0.01);
    let period = PI / k;
    let (ct_garrick, cp_garrick, _) = garrick_plunge(k, h);
    for dt in [0.02, 0.01, 0.005] {
        let settings = Settings {
            dt,
            duration: 5.0 * period,
            ..Settings::default()
        };
        let history = Ldvm::new(Motion::plunge(k, h), settings).run();
        let (ct, cp, _) = cycle_means(&history, period, 2);
        let (ct_error, cp_error) = (ct / ct_garrick - 1.0, cp / cp_garrick - 1.0);
        println!(
            "dt {dt}: CT {:+.2}%, CP {:+.2}% against Garrick",
            100.0 * ct_error,
            100.0 * cp_error
        );
        assert!(
            ct_error.abs() < 0.01 && cp_error.abs() < 0.01,
            "dt {dt}: CT {:+.2}%, CP {:+.2}%",
            100.0 * ct_error,
            100.0 * cp_error
        );
    }
}

/// Kelvin's theorem holds to round-off: the bound circulation equals the
/// total shed circulation, trailing- and leading-edge, at every step (here
/// with leading-edge vortices shed).
#[test]
fn circulation_is_conserved() {
    let motion = Motion {
        pitch_amplitude: 0.1,
        pitch_phase: 0.0,
        ..Motion::plunge(1.0, 0.3)
    };
    let mut solver = Ldvm::new(
        motion,
        Settings {
            duration: 4.0,
            lesp_critical: Some(0.1),
            ..Settings::default()
        },
    );
    let history = solver.run();
    assert!(!solver.leading_edge_vortices().is_empty());
    let shed: f64 = solver
        .wake()
        .iter()
        .chain(solver.leading_edge_vortices())
        .map(|v| v.gamma)
        .sum();
    let bound = *history.bound_circulation.last().unwrap();
    assert!(
        (bound - shed).abs() < 1e-9 * bound.abs().max(1e-3),
        "{bound} vs {shed}"
    );
    assert!(history.lesp.iter().all(|a| a.abs() <= 0.1 + 1e-9));
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
/// lift of the plate pitching by `delta(t)` (to first order in delta), its
/// input power and its thrust, at k = 1, 5 and 20. Until 2026-12-07 the
/// camber's share of the unsteady pressure was taken against its rate and
/// slope at the step's end, not at the half step where the pressure's
/// backward difference is: the deformation's power was +0.4 % at k = 1,
/// +12.2 % at k = 5 and +113 % at k = 20 (now -0.00 %, -0.03 %, -0.46 %),
/// and the mean thrust -1.9 % of the mean |CT| at k = 1 (now +0.02 %).
#[test]
fn camber_that_is_a_rotation_lifts_like_pitch() {
    for k in [1.0, 5.0, 20.0] {
        camber_as_pitch_at(k);
    }
}

/// [`camber_that_is_a_rotation_lifts_like_pitch`] at reduced frequency `k`.
fn camber_as_pitch_at(k: f64) {
    use fwav::aero2d::camber::CamberHistory;
    let (amplitude, pivot) = (2f64.to_radians(), 0.25);
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
        "k = {k}: lift amplitude: pitching {a:.5}, rotating camber {b:.5} ({:+.2}%)",
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
    // And the same mean thrust: suction plus the pressure on the sloped
    // camber line (Wu 1961) is the pitching plate's suction plus its tilted
    // normal force. The mean is a small difference of those two (here
    // 1.8e-4 of a streamwise force whose mean magnitude is 2.7e-3 at k =
    // 1), so it is compared on that scale, the cycle mean of |CT|: within
    // 5% (measured +0.02%, -1.9% before the half step). Without the slope
    // term the camber gave the suction alone, 1.66e-3 (+830%, 55% of that
    // scale).
    let (ct_pitch, _, _) = cycle_means(&pitch, period, 1);
    let (ct_flex, _, _) = cycle_means(&flex, period, 1);
    let n = (period / settings.dt) as usize;
    let swing = pitch.ct[pitch.ct.len() - n..]
        .iter()
        .map(|c| c.abs())
        .sum::<f64>()
        / n as f64;
    let error = (ct_flex - ct_pitch) / swing;
    println!(
        "mean thrust: pitching {ct_pitch:.6}, rotating camber {ct_flex:.6}, mean |CT| {swing:.6} ({:+.2}% of it)",
        100.0 * error
    );
    assert!(error.abs() < 0.05, "{ct_pitch} vs {ct_flex} on {swing}");
}

/// d'Alembert for a pitch written as camber: a plate at rest at angle alpha,
/// given as the steady camber line `eta = -alpha x` on a plate at zero
/// angle, has the rigid plate's streamwise force (suction 2 pi alpha^2
/// balanced by the normal force's tilt, Wu 1961's flexible-plate thrust),
/// not the bare suction; checked at s = 20 after a sudden start, to 2% of
/// the suction (the residual is the starting vortex's induced drag).
#[test]
fn steady_camber_that_is_a_pitch_feels_no_thrust() {
    use fwav::aero2d::camber::CamberHistory;
    let alpha: f64 = 0.05;
    let stations: Vec<f64> = (0..=40).map(|i| i as f64 / 40.0).collect();
    let offsets = stations.iter().map(|x| -alpha * x).collect();
    let camber = CamberHistory::steady(stations, offsets).unwrap();
    let settings = Settings {
        dt: 0.02,
        duration: 10.0,
        ..Settings::default()
    };
    let rigid = Ldvm::new(Motion::steady(alpha), settings).run();
    let flex = Ldvm::new(Motion::steady(0.0), settings)
        .with_camber(camber)
        .run();
    let suction = 2.0 * PI * alpha * alpha;
    let (ct_rigid, ct_flex) = (*rigid.ct.last().unwrap(), *flex.ct.last().unwrap());
    let (cl_rigid, cl_flex) = (*rigid.cl.last().unwrap(), *flex.cl.last().unwrap());
    println!(
        "s = 20: CT rigid {ct_rigid:.6}, camber {ct_flex:.6}, suction {suction:.6}; CL {cl_rigid:.5} / {cl_flex:.5}"
    );
    assert!(ct_rigid.abs() < 0.1 * suction, "rigid CT {ct_rigid}");
    assert!(
        (ct_flex - ct_rigid).abs() < 0.02 * suction,
        "{ct_rigid} vs {ct_flex}"
    );
    assert!(
        (cl_flex / cl_rigid - 1.0).abs() < 0.01,
        "{cl_rigid} vs {cl_flex}"
    );
}

/// LEV shedding, the LDVM paper's case 1 (Ramesh et al. 2014, J. Fluid Mech.
/// 751): SD7003 pitched 0 -> 25 deg about the leading edge by Eldredge's
/// ramp (K = 0.11, a = 11, from t = 1), critical LESP 0.18 (the paper's
/// value for this section and Reynolds number). Against the paper's CFD
/// (tests/data/ldvm_case1_cfd.dat): over the shedding phase, from the onset
/// (LESP reaches 0.18 near t = 2; the paper's LDVM output has it at 2.05)
/// to the start of the return (t = 4), the mean lift within 15% (measured
/// +6.9%; the paper's own LDVM gives +4.4%: its force routine takes the
/// Fourier-coefficient rates before the LEV is shed, fwav keeps the LEV's
/// potential jump at the leading edge instead) and the peak lift within 15%
/// (measured +2.1%) — the validation cases `aero2d/ldvm-case1-*`. Before
/// 2026-12-07's edge placement and chord core (`fwav::aero2d::ldvm`, "The
/// wake next to the edge") the mean was +13.4% to +14.1% and the peak
/// +8.8% to +9.5%. The lift from pressures agrees with the rate of the
/// vortex impulse within 3% (measured 1.8%): without the leading-edge
/// potential jump it would fall to CL = -1.8 while the impulse says +2.8.
/// Honest caveat: with shedding switched off the same window's mean is
/// +2.3% from the CFD (+4.0% before), closer than with it: the LEV model
/// here mostly reshapes the history (the dip at t = 3 and the rise during
/// the hold), not the mean.
#[test]
fn ldvm_case_1_lift_within_15_percent_of_cfd() {
    use fwav::validation::aero2d::{
        ldvm_case1_mean_lift, ldvm_case1_peak_lift, ldvm_case1_run, ldvm_case1_shedding,
        window_mean,
    };
    let shedding = ldvm_case1_shedding().unwrap();
    let onset = shedding.time[shedding
        .lesp
        .iter()
        .position(|&a| a >= 0.18 - 1e-9)
        .unwrap()];
    let (mean, peak) = (ldvm_case1_mean_lift().run(), ldvm_case1_peak_lift().run());
    let attached = ldvm_case1_run(None).unwrap();
    let attached = window_mean(&attached.time, &attached.cl, 2.0, 4.0);
    // The pressure lift against the rate of the vortex impulse.
    let impulse = window_mean(&shedding.time, &shedding.cl_impulse, 2.0, 4.0);
    let ours = mean.value.unwrap_or(f64::NAN);
    println!(
        "LEV onset t = {onset:.3}; mean CL (t 2..4) {ours:.3} vs CFD {:.3} ({:+.1}%), \
         attached flow {attached:.3} ({:+.1}%); peak {:.3} vs {:.3} ({:+.1}%); \
         impulse lift {impulse:.3}",
        mean.reference_value,
        100.0 * mean.error.unwrap_or(f64::NAN),
        100.0 * (attached / mean.reference_value - 1.0),
        peak.value.unwrap_or(f64::NAN),
        peak.reference_value,
        100.0 * peak.error.unwrap_or(f64::NAN)
    );
    assert!((onset - 2.05).abs() < 0.1, "onset {onset}");
    for case in [&mean, &peak] {
        assert_eq!(case.tolerance, 0.15);
        assert!(case.pass, "{case:?}");
    }
    assert!((impulse / ours - 1.0).abs() < 0.03, "{impulse} vs {ours}");
}

/// A surging section (the fore-and-aft motion an inclined stroke plane
/// gives a flapping wing's section): at low reduced frequency the lift
/// follows the square of the air's speed over the section, so the mean CL
/// of a pitched plate surging with velocity `x'` grows by `<(1 - x')^2>`
/// over the plate at rest (the quasi-steady limit of Greenberg 1947, NACA
/// TN 1326, whose unsteady correction is second order in k). Stroke plane
/// 0° (pure surge), k = 0.04, surge speed up to 0.4 U, 5° pitch: the ratio
/// within 1% of the quasi-steady one (C(k) at k = 0.04 alone could lower
/// the oscillating part by some 5%, 0.4% of the ratio; measured 0.02%).
/// And a vertical stroke plane at a small amplitude is the harmonic plunge
/// `h = r A cos(omega t)`: its mean CT matches Garrick's within the 10% of
/// `garrick_thrust_within_10_percent` (k = 1, h0 = 0.05).
#[test]
fn surging_section_lifts_with_the_square_of_its_speed() {
    use fwav::aero2d::ldvm::SectionFlapping;
    let k = 0.04;
    let period = PI / k;
    let settings = Settings {
        dt: 0.03,
        duration: 2.0 * period,
        ..Settings::default()
    };
    let pitched = Motion {
        mean_pitch: 5f64.to_radians(),
        ..Motion::plunge(k, 0.0)
    };
    let surge = SectionFlapping {
        reduced_frequency: k,
        radius: 10.0,
        amplitude: 0.5,
        mean_angle: 0.0,
        stroke_plane: 0.0,
    };
    let mean_cl = |h: &fwav::aero2d::ldvm::History| {
        let last: Vec<f64> = h
            .time
            .iter()
            .zip(&h.cl)
            .filter(|(t, _)| **t > period)
            .map(|(_, c)| *c)
            .collect();
        last.iter().sum::<f64>() / last.len() as f64
    };
    let at_rest = mean_cl(&Ldvm::new(pitched, settings).run());
    let surging = mean_cl(&Ldvm::new(pitched, settings).with_flapping(surge).run());
    let samples = 10_000;
    let speed_squared = (0..samples)
        .map(|i| {
            let (_, x_dot, _, _) = surge.at(period * i as f64 / samples as f64);
            (1.0 - x_dot).powi(2)
        })
        .sum::<f64>()
        / samples as f64;
    let peak = (0..samples)
        .map(|i| surge.at(period * i as f64 / samples as f64).1.abs())
        .fold(0.0, f64::max);
    println!(
        "surge up to {peak:.3} U: mean CL {surging:.4} vs {at_rest:.4} at rest, ratio {:.4} (quasi-steady {:.4})",
        surging / at_rest,
        speed_squared
    );
    assert!(((surging / at_rest) / speed_squared - 1.0).abs() < 0.01);

    let k = 1.0;
    let period = PI / k;
    let plunging = SectionFlapping {
        reduced_frequency: k,
        radius: 10.0,
        amplitude: 0.005,
        mean_angle: 0.0,
        stroke_plane: std::f64::consts::FRAC_PI_2,
    };
    let settings = Settings {
        dt: 0.02,
        duration: 5.0 * period,
        ..Settings::default()
    };
    let history = Ldvm::new(Motion::plunge(k, 0.0), settings)
        .with_flapping(plunging)
        .run();
    let (ct, _, _) = cycle_means(&history, period, 2);
    let (reference, _, _) = garrick_plunge(k, 0.05);
    println!("vertical stroke plane, r A = 0.05 c, k = 1: CT {ct:.5} vs Garrick {reference:.5}");
    assert!((ct / reference - 1.0).abs() < 0.1);
}
