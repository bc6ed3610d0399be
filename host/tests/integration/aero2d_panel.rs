//! The unsteady source/doublet panel method (`fwav::aero2d::panel`) against
//! exact potential flow and classical unsteady aerodynamics (formulas:
//! ../shared/REFERENCES.md; references beside each test).

use std::f64::consts::PI;

use fwav::aero2d::ldvm::{cycle_means, History, Motion};
use fwav::aero2d::naca::{Naca4, TrailingEdge};
use fwav::aero2d::panel::{
    solve_steady, PanelSettings, PanelSolver, SectionShape, ShapeHistory, DEFAULT_PANELS,
};
use fwav::aero2d::theory::{garrick_plunge, wagner};
use fwav::validation::aero2d::{
    karman_trefftz_section, panel_karman_trefftz_lift, panel_naca0012_lift_slope,
};

/// A cambered Kármán–Trefftz section (10° trailing-edge angle, 11%
/// thick, 1% camber) at 5° in steady flow against its exact solution
/// (`fwav::validation::karman_trefftz`, a conformal map: Milne-Thomson,
/// Theoretical Aerodynamics, 1958, ch. 7; Katz & Plotkin 2001, section 6.7
/// for the Joukowski special case): the lift within 1% (the validation
/// case `aero2d/panel-karman-trefftz-lift`) and the surface pressure within
/// 0.02 ahead of 95% chord, compared at the surface point nearest each
/// collocation point. Points uniform in `u - 0.8 sin(4 pi u) / (4 pi)` of
/// the way round the circle (clustered at both edges). Measured at 160
/// panels: CL -0.78%, max |Cp error| 0.015 (at the leading edge); at 320
/// -0.23% / 0.0045, at 640 -0.07% / 0.0015. Uniform in the circle angle
/// the lift converges only about linearly (-1.07% at 160, -0.46% at 320,
/// -0.20% at 640): the trailing-edge corner dominates the error.
#[test]
fn karman_trefftz_steady_lift_and_pressure() {
    let section = karman_trefftz_section();
    let alpha = 5f64.to_radians();
    let (cl_exact, cp_exact) = section.flow(alpha);
    let panels = DEFAULT_PANELS;
    let shape = SectionShape::new(&section.points(panels)).unwrap();
    let steady = solve_steady(&shape, alpha);
    let error = steady.cl / cl_exact - 1.0;
    let mut worst = (0.0f64, 0.0);
    for (j, (p, cp)) in steady.points.iter().zip(&steady.cp).enumerate() {
        let theta = section.nearest(
            *p,
            section.theta(j as f64, panels),
            section.theta(j as f64 + 1.0, panels),
        );
        if p[0] < 0.95 && (cp - cp_exact(theta)).abs() > worst.0 {
            worst = ((cp - cp_exact(theta)).abs(), p[0]);
        }
    }
    println!(
        "Karman-Trefftz at 5 deg, {panels} panels: CL {:.5} vs exact {cl_exact:.5} ({:+.2}%), \
         2 Gamma {:.5}, CD {:.1e}; max |Cp error| {:.4} at x = {:.4}",
        steady.cl,
        100.0 * error,
        2.0 * steady.circulation,
        steady.cd,
        worst.0,
        worst.1
    );
    let case = panel_karman_trefftz_lift().run();
    assert_eq!(case.value, Some(steady.cl));
    assert_eq!((case.reference_value, case.tolerance), (cl_exact, 0.01));
    assert!(case.pass, "{case:?}");
    assert!(worst.0 < 0.02, "{worst:?}");
    // Kutta–Joukowski from the circulation, and no pressure drag.
    assert!((steady.cl / (2.0 * steady.circulation) - 1.0).abs() < 0.005);
    assert!(steady.cd.abs() < 1e-3);
}

fn naca(designation: &str, panels: usize) -> SectionShape {
    let naca: Naca4 = designation.parse().unwrap();
    SectionShape::new(&naca.points(panels, TrailingEdge::Closed).unwrap()).unwrap()
}

/// NACA 0012 potential-flow lift slope: within 2% of
/// `2 pi (1 + 0.77 t/c) = 6.864 / rad`, the thin-airfoil slope with the
/// first-order thickness factor of Joukowski sections (a Joukowski section
/// of thickness ratio `t/c = (3 sqrt 3 / 4) e` has `2 pi (1 + e)`; the
/// brief of this work quotes it, and Abbott & von Doenhoff's 6.9–7.0 / rad
/// for the NACA 0012, as the reference: a secondary source). Measured
/// 6.883 (+0.28%) at the default 160 panels; the panel count converges it
/// to about 6.92 (6.900 at 320, 6.910 at 640, 6.914 at 1280), +0.8%. The
/// validation case `aero2d/panel-naca0012-lift-slope`.
#[test]
fn naca_0012_lift_slope() {
    let case = panel_naca0012_lift_slope().run();
    println!(
        "NACA 0012 lift slope {:.4} / rad vs {:.4} ({:+.2}%)",
        case.value.unwrap_or(f64::NAN),
        case.reference_value,
        100.0 * case.error.unwrap_or(f64::NAN)
    );
    assert_eq!(
        (case.reference_value, case.tolerance),
        (2.0 * PI * (1.0 + 0.77 * 0.12), 0.02)
    );
    assert!(case.pass, "{case:?}");
    // Symmetric section: zero lift at zero incidence.
    assert!(solve_steady(&naca("0012", DEFAULT_PANELS), 0.0).cl.abs() < 1e-10);
}

/// The same section from a Selig-style file (counter-clockwise, name
/// line) gives the same solution, and the original open trailing edge
/// (closed by a base panel) changes the lift slope by under 1%.
#[test]
fn point_files_and_blunt_edges() {
    use fwav::aero2d::naca::parse_points;
    let cambered: Naca4 = "2412".parse().unwrap();
    let points = cambered
        .points(DEFAULT_PANELS, TrailingEdge::Closed)
        .unwrap();
    let text: String = std::iter::once("NACA 2412 # Selig order\n".to_string())
        .chain(
            points
                .iter()
                .rev()
                .map(|(x, y)| format!("{x:.15} {y:.15}\n")),
        )
        .collect();
    let file = parse_points(&text).unwrap();
    assert_eq!(file.name.as_deref(), Some("NACA 2412"));
    let alpha = 3f64.to_radians();
    let a = solve_steady(&SectionShape::new(&points).unwrap(), alpha).cl;
    let b = solve_steady(&SectionShape::new(&file.points).unwrap(), alpha).cl;
    assert!((a - b).abs() < 1e-9, "{a} {b}");
    let open: Naca4 = "0012".parse().unwrap();
    let blunt =
        SectionShape::new(&open.points(DEFAULT_PANELS, TrailingEdge::Open).unwrap()).unwrap();
    assert!(blunt.is_blunt());
    let (cl_open, cl_closed) = (
        solve_steady(&blunt, alpha).cl,
        solve_steady(&naca("0012", DEFAULT_PANELS), alpha).cl,
    );
    println!("NACA 0012 at 3 deg: open edge CL {cl_open:.5}, closed {cl_closed:.5}");
    assert!((cl_open / cl_closed - 1.0).abs() < 0.01);
}

/// Lift `s` semichords after a sudden start at 0.05 rad, over the steady
/// lift of the same section and discretization.
fn indicial(section: &SectionShape, dt: f64, s_values: &[f64], far_wake: f64) -> Vec<f64> {
    let alpha = 0.05;
    let steady = solve_steady(section, alpha).cl;
    let duration = s_values.iter().fold(0.0f64, |a, &b| a.max(b)) / 2.0 + 0.1;
    let settings = PanelSettings {
        dt,
        duration,
        far_wake,
    };
    let history = PanelSolver::new(section, Motion::steady(alpha), settings)
        .unwrap()
        .run();
    s_values
        .iter()
        .map(|&s| {
            let i = history
                .time
                .iter()
                .position(|&t| t >= s / 2.0 - 1e-9)
                .expect("long enough");
            history.cl[i] / steady
        })
        .collect()
}

/// Wagner (exact function, `fwav::aero2d::theory::wagner`): a NACA 0002
/// after a sudden start, lift over its own steady value, within 3% at
/// s = 5 and 10 semichords (dt = 0.01). Measured +0.48% and +0.15%
/// (+2.2% and +1.3% at s = 1 and 2). The NACA 0012 is printed: -4.1% and
/// -2.3% (and -8.6% at s = 1), converged in dt and panels (-4.35%/-4.29%
/// at s = 5 with dt halved / panels doubled): the thick section's
/// circulation builds up more slowly than the plate's.
#[test]
fn wagner_lift_within_3_percent_from_5_semichords() {
    let s_values = [1.0, 2.0, 5.0, 10.0];
    for (designation, checked) in [("0002", true), ("0012", false)] {
        let ratios = indicial(&naca(designation, DEFAULT_PANELS), 0.01, &s_values, 1e9);
        let errors: Vec<f64> = s_values
            .iter()
            .zip(&ratios)
            .map(|(&s, r)| r / wagner(s) - 1.0)
            .collect();
        println!(
            "NACA {designation} indicial lift vs Wagner at s = 1, 2, 5, 10: {:+.2}%, {:+.2}%, {:+.2}%, {:+.2}%",
            100.0 * errors[0],
            100.0 * errors[1],
            100.0 * errors[2],
            100.0 * errors[3]
        );
        if checked {
            assert!(
                errors[2].abs() < 0.03 && errors[3].abs() < 0.03,
                "{errors:?}"
            );
        }
    }
}

/// The steady mode is the long-time limit of the impulsive start: the
/// NACA 0002's lift at s = 40 semichords is the steady lift times Wagner's
/// `phi(40)` (0.97, the starting vortex still 20 chords away) within 1%
/// (measured -0.02%; far wake drifting beyond 3 chords).
#[test]
fn impulsive_start_tends_to_the_steady_solution() {
    let ratio = indicial(&naca("0002", DEFAULT_PANELS), 0.01, &[40.0], 3.0)[0];
    let error = ratio / wagner(40.0) - 1.0;
    println!(
        "NACA 0002 lift at s = 40: {ratio:.5} of steady, Wagner {:.5} ({:+.2}%)",
        wagner(40.0),
        100.0 * error
    );
    assert!(error.abs() < 0.01);
}

/// Cycle means (CT, CP, efficiency) over the last 2 of 4 cycles of pure
/// plunge h0 = 0.05 c at k = 1, default resolution.
fn plunge_means(section: &SectionShape) -> (f64, f64, f64) {
    let k = 1.0;
    let period = PI / k;
    let settings = PanelSettings {
        duration: 4.0 * period,
        ..PanelSettings::default()
    };
    let history = PanelSolver::new(section, Motion::plunge(k, 0.05), settings)
        .unwrap()
        .run();
    cycle_means(&history, period, 2)
}

/// Garrick (1936) pure plunge h0 = 0.05 c, k = 1
/// (`fwav::aero2d::theory::garrick_plunge`: CT 0.00946, efficiency 0.558):
/// mean thrust and efficiency within 10% for the thin NACA 0002 and 0006.
/// Measured: NACA 0002 CT +6.7%, efficiency +0.6% (CT +3.4% and +2.3%
/// with 320 and 640 panels: the 0002's leading edge, radius 4e-5 c, is not
/// resolved by 160); NACA 0006 CT +1.1%, efficiency -2.3%. NACA 0012
/// printed: CT -3.2%, efficiency -2.3% (-3.4% with 320 panels, -4.1% with
/// dt halved): in this inviscid model thickness lowers the thrust a little,
/// consistently with its lower unsteady lift (see
/// `pressure_and_impulse_lift_agree`); the brief expected the opposite
/// sign from the literature, which is not checked here.
#[test]
fn garrick_plunge_thrust_and_efficiency_within_10_percent() {
    let (ct_ref, cp_ref, eta_ref) = garrick_plunge(1.0, 0.05);
    for (designation, checked) in [("0002", true), ("0006", true), ("0012", false)] {
        let (ct, cp, eta) = plunge_means(&naca(designation, DEFAULT_PANELS));
        let (e_ct, e_eta) = (ct / ct_ref - 1.0, eta / eta_ref - 1.0);
        println!(
            "NACA {designation}: CT {ct:.5} ({:+.1}%), CP {cp:.5} ({:+.1}%), efficiency {eta:.3} ({:+.1}%) vs Garrick",
            100.0 * e_ct,
            100.0 * (cp / cp_ref - 1.0),
            100.0 * e_eta
        );
        if checked {
            assert!(e_ct.abs() < 0.10 && e_eta.abs() < 0.10);
        }
    }
}

/// First harmonic `(amplitude, phase)` at `omega` of a series over its last
/// `period`.
fn harmonic(history: &History, values: &[f64], omega: f64, period: f64) -> (f64, f64) {
    let end = *history.time.last().unwrap();
    let (mut a, mut b, mut n) = (0.0, 0.0, 0.0);
    for (t, v) in history.time.iter().zip(values) {
        if *t > end - period {
            a += v * (omega * t).cos();
            b += v * (omega * t).sin();
            n += 1.0;
        }
    }
    ((2.0 * a / n).hypot(2.0 * b / n), a.atan2(b))
}

/// Two independent lifts: the pressure integral and the rate of the
/// vorticity's impulse (Wu 1981, AIAA J. 19; the section's interior taken
/// as fluid at rest, so its surface carries the sheet `-u . t`), for a
/// NACA 0012 plunging and pitching (h0 = 0.1, 0.1 rad, pitch leading by
/// 1 rad, k = 1): first harmonics within 2% in amplitude and 0.02 rad in
/// phase. Measured 1.0% and 0.001 rad (pure plunge or pitch, NACA 0002 to
/// 0012: within 0.9%).
#[test]
fn pressure_and_impulse_lift_agree() {
    let motion = Motion {
        pitch_amplitude: 0.1,
        pitch_phase: 1.0,
        ..Motion::plunge(1.0, 0.1)
    };
    let period = PI;
    let settings = PanelSettings {
        duration: 4.0 * period,
        ..PanelSettings::default()
    };
    let h = PanelSolver::new(&naca("0012", DEFAULT_PANELS), motion, settings)
        .unwrap()
        .run();
    let (a, pa) = harmonic(&h, &h.cl, 2.0, period);
    let (b, pb) = harmonic(&h, &h.cl_impulse, 2.0, period);
    println!("CL first harmonic: pressure {a:.5} at {pa:.4} rad, impulse {b:.5} at {pb:.4} rad");
    assert!((b / a - 1.0).abs() < 0.02 && (pa - pb).abs() < 0.02);
}

/// Kelvin's theorem to round-off: the shed circulation equals the bound
/// circulation after every step of a pitching and plunging run (checked at
/// several durations).
#[test]
fn circulation_is_conserved() {
    let motion = Motion {
        pitch_amplitude: 0.2,
        pitch_phase: 1.5,
        ..Motion::plunge(1.0, 0.3)
    };
    for duration in [0.5, 1.3, 3.0] {
        let settings = PanelSettings {
            duration,
            ..PanelSettings::default()
        };
        let mut solver = PanelSolver::new(&naca("0012", DEFAULT_PANELS), motion, settings).unwrap();
        let history = solver.run();
        let shed: f64 = solver.wake().iter().map(|v| v.gamma).sum();
        let bound = solver.bound_circulation();
        assert_eq!(history.bound_circulation.last(), Some(&bound));
        let scale = solver
            .wake()
            .iter()
            .fold(0.0f64, |a, v| a.max(v.gamma.abs()));
        println!(
            "t = {duration}: bound {bound:.6}, shed {shed:.6}, difference {:.1e}",
            shed - bound
        );
        assert!((shed - bound).abs() <= 1e-12 * scale.max(bound.abs()));
    }
}

/// The deformation machinery against rigid motion (as
/// `camber_that_is_a_rotation_lifts_like_pitch` does for the LDVM): a
/// NACA 0012 whose shape history is its rigid rotation by
/// `delta = 2 deg sin(omega t)` about the quarter chord (200 samples a
/// period) lifts like the same section pitching by `delta`, and its
/// deformation power equals the pitching power: lift amplitude and mean
/// power within 2%. Measured equal to the printed 4 digits (+0.00%).
#[test]
fn shape_history_that_is_a_rotation_lifts_like_pitch() {
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
    let settings = PanelSettings {
        duration: 3.0 * period,
        ..PanelSettings::default()
    };
    let section = naca("0012", DEFAULT_PANELS);
    let pitch = PanelSolver::new(&section, pitching, settings)
        .unwrap()
        .run();
    let base: Naca4 = "0012".parse().unwrap();
    let points = base.points(DEFAULT_PANELS, TrailingEdge::Closed).unwrap();
    let samples: Vec<Vec<(f64, f64)>> = (0..200)
        .map(|i| {
            let (s, c) = (amplitude * (2.0 * PI * i as f64 / 200.0).sin()).sin_cos();
            points
                .iter()
                .map(|&(x, y)| (pivot + c * (x - pivot) + s * y, -s * (x - pivot) + c * y))
                .collect()
        })
        .collect();
    let history = ShapeHistory::new(&samples, period).unwrap();
    let still = Motion {
        pitch_amplitude: 0.0,
        ..pitching
    };
    let mut solver = PanelSolver::new(&section, still, settings)
        .unwrap()
        .with_shape_history(history)
        .unwrap();
    let flex = solver.run();
    let (a, _) = harmonic(&pitch, &pitch.cl, 2.0 * k, period);
    let (b, _) = harmonic(&flex, &flex.cl, 2.0 * k, period);
    let (_, cp_pitch, _) = cycle_means(&pitch, period, 1);
    let (_, cp_flex, _) = cycle_means(&flex, period, 1);
    println!(
        "lift amplitude: pitching {a:.5}, rotating shape {b:.5} ({:+.2}%); mean power {cp_pitch:.6} vs {cp_flex:.6} ({:+.2}%)",
        100.0 * (b / a - 1.0),
        100.0 * (cp_flex / cp_pitch - 1.0)
    );
    assert!((b / a - 1.0).abs() < 0.02);
    assert!((cp_flex / cp_pitch - 1.0).abs() < 0.02);
    // Kelvin holds for the deforming section too.
    let shed: f64 = solver.wake().iter().map(|v| v.gamma).sum();
    assert!((shed - solver.bound_circulation()).abs() < 1e-12);
}

/// Bad inputs give typed errors, not panics.
#[test]
fn bad_inputs_are_refused() {
    use fwav::aero2d::naca::{parse_points, NacaError, PointsError};
    use fwav::aero2d::panel::{PanelError, ShapeError};
    assert!(matches!(
        "naca12".parse::<Naca4>(),
        Err(NacaError::Designation(_))
    ));
    assert!(matches!(
        "3012".parse::<Naca4>(),
        Err(NacaError::CamberPosition(_))
    ));
    let naca12: Naca4 = "0012".parse().unwrap();
    assert_eq!(
        naca12.points(7, TrailingEdge::Closed),
        Err(NacaError::Panels(7))
    );
    assert_eq!(
        parse_points("section\n1 0\n0.5 0.06\n0 zero\n"),
        Err(PointsError::NotANumber {
            line: 4,
            text: "zero".into()
        })
    );
    assert_eq!(
        parse_points("1 0\n0.5\n0 0\n"),
        Err(PointsError::Columns { line: 2, found: 1 })
    );
    assert_eq!(
        SectionShape::new(&[(1.0, 0.0), (0.0, 0.0)]),
        Err(ShapeError::TooFewPoints { got: 2 })
    );
    let square = vec![(1.0, 0.0), (0.0, -0.1), (0.0, 0.1), (1.0, 0.0)];
    assert_eq!(
        ShapeHistory::new(std::slice::from_ref(&square), -1.0),
        Err(ShapeError::Period)
    );
    assert!(matches!(
        ShapeHistory::from_xy(&[vec![1.0, 0.0, 0.0, 1.0]], &[vec![0.0, -0.1, 0.1]], 1.0),
        Err(ShapeError::MismatchedXy { .. })
    ));
    assert!(matches!(
        ShapeHistory::new(
            &[
                square.clone(),
                vec![(1.0, 0.0), (0.0, f64::NAN), (0.0, 0.1), (1.0, 0.0)]
            ],
            1.0
        ),
        Err(ShapeError::Sample { sample: 1, .. })
    ));
    let section = naca("0012", 40);
    let bad =
        |settings: PanelSettings| PanelSolver::new(&section, Motion::steady(0.0), settings).err();
    for settings in [
        PanelSettings {
            dt: 0.0,
            ..PanelSettings::default()
        },
        PanelSettings {
            dt: f64::NAN,
            ..PanelSettings::default()
        },
        PanelSettings {
            duration: -1.0,
            ..PanelSettings::default()
        },
        PanelSettings {
            far_wake: 0.0,
            ..PanelSettings::default()
        },
    ] {
        assert!(
            matches!(bad(settings), Some(PanelError::Settings(_))),
            "{settings:?}"
        );
    }
    let nan_motion = Motion {
        pivot: f64::NAN,
        ..Motion::steady(0.0)
    };
    assert!(matches!(
        PanelSolver::new(&section, nan_motion, PanelSettings::default()),
        Err(PanelError::Settings(_))
    ));
    let history = ShapeHistory::new(&[square], 1.0).unwrap();
    assert!(matches!(
        PanelSolver::new(&section, Motion::steady(0.0), PanelSettings::default())
            .unwrap()
            .with_shape_history(history),
        Err(PanelError::HistoryMismatch {
            section: 40,
            history: 3
        })
    ));
}

/// The flapping section's path ([`PanelSolver::with_flapping`], the
/// aerodynamic discipline's motion: plunge and the surge of an inclined
/// stroke plane) against the harmonic path it generalizes. A vertical
/// stroke plane is pure plunge, `h = r sin(A cos wt)`: at radius 10 chords
/// and `A = asin(0.005)`, within 1e-6 of `h0 cos(wt)`, `h0 = 0.05 c`,
/// whose cycle means are those of `h0 sin(wt)` (Garrick, NACA Rep. 567:
/// the means do not depend on the phase). NACA 0006, k = 1, last 2 of 4
/// cycles: the mean CT and CP of the two paths within 0.5% of each other.
/// Measured: CT 0.009593 against 0.009566 (+0.28%), CP +0.11%.
#[test]
fn flapping_in_a_vertical_stroke_plane_is_harmonic_plunge() {
    use fwav::aero2d::motion::SectionFlapping;
    let (k, period) = (1.0, PI);
    let section = naca("0006", DEFAULT_PANELS);
    let settings = PanelSettings {
        duration: 4.0 * period,
        ..PanelSettings::default()
    };
    let flapping = SectionFlapping {
        reduced_frequency: k,
        radius: 10.0,
        amplitude: 0.005_f64.asin(),
        mean_angle: 0.0,
        stroke_plane: std::f64::consts::FRAC_PI_2,
    };
    let flapped = PanelSolver::new(&section, Motion::plunge(k, 0.0), settings)
        .unwrap()
        .with_flapping(flapping)
        .run();
    let (ct_f, cp_f, _) = cycle_means(&flapped, period, 2);
    let (ct_h, cp_h, _) = plunge_means(&section);
    println!("flapping CT {ct_f:.6} CP {cp_f:.6}; harmonic plunge CT {ct_h:.6} CP {cp_h:.6}");
    assert!(
        (ct_f / ct_h - 1.0).abs() < 0.005,
        "CT {ct_f} against {ct_h}"
    );
    assert!(
        (cp_f / cp_h - 1.0).abs() < 0.005,
        "CP {cp_f} against {cp_h}"
    );
}

/// A horizontal stroke plane is pure surge: a symmetric section moving
/// fore and aft along its chord in the stream keeps its symmetry, so it
/// neither lifts nor sheds (d'Alembert: no mean force in potential flow
/// without circulation; the added-mass force of the surge averages to
/// zero over a period). NACA 0012 surging `x = -r sin(A cos wt)` with
/// r = 2 chords, A = 30°, k = 0.7 (the air's speed over it swings between
/// about -0.5 and 2.5): |CL| below 1e-9 at every sample and the mean CT
/// and CP over the last 2 of 4 cycles below 1e-3. Measured: 1.4e-12,
/// -1.2e-5, 4.9e-5.
#[test]
fn flapping_in_a_horizontal_stroke_plane_is_pure_surge() {
    use fwav::aero2d::motion::SectionFlapping;
    let k = 0.7;
    let period = PI / k;
    let settings = PanelSettings {
        duration: 4.0 * period,
        ..PanelSettings::default()
    };
    let flapping = SectionFlapping {
        reduced_frequency: k,
        radius: 2.0,
        amplitude: 30f64.to_radians(),
        mean_angle: 0.0,
        stroke_plane: 0.0,
    };
    let history = PanelSolver::new(
        &naca("0012", DEFAULT_PANELS),
        Motion::plunge(k, 0.0),
        settings,
    )
    .unwrap()
    .with_flapping(flapping)
    .run();
    let lift = history.cl.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    let (ct, cp, _) = cycle_means(&history, period, 2);
    println!("pure surge: max |CL| {lift:.2e}, mean CT {ct:.2e}, CP {cp:.2e}");
    assert!(lift < 1e-9, "{lift}");
    assert!(ct.abs() < 1e-3 && cp.abs() < 1e-3, "CT {ct}, CP {cp}");
}
