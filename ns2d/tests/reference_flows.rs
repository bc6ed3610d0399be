//! The Navier–Stokes section solver against published flows. The
//! references are the authors' curves as distributed with PetIBM
//! (`data/`, each file names its source); the heavy cases run in
//! `fwav validate` and are `#[ignore]`d here with their cost.

use fwav_ns2d::cases::{CylinderWake, HoveringEllipse, ImpulsiveCylinder};
use fwav_ns2d::{GridSpec, ReferenceCurve};

/// A reference curve of `tests/data`.
fn reference(name: &str) -> ReferenceCurve {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    ReferenceCurve::parse(&text).unwrap()
}

/// Koumoutsakos & Leonard (1995), J. Fluid Mech. 296, fig. 18: the drag
/// of the impulsively started cylinder at Re 550 over U t / R in [0.5, 3]
/// within 5% (issue 23). Measured: 3.6% on 256 x 192, first cell 0.001 D,
/// dt = 0.004 D/U (with the wall pressure's vorticity flux compact; 3.2%
/// with it one-sided, before 2026-12-03).
#[test]
fn the_impulsively_started_cylinder_at_re_550_drags_as_koumoutsakos_and_leonard_found() {
    let drag = ImpulsiveCylinder {
        reynolds: 550.0,
        until: 3.05,
    }
    .run(ImpulsiveCylinder::validated())
    .unwrap();
    let (error, x) = reference("koumoutsakos_leonard_1995_re550.dat").worst_deviation(
        &drag,
        (0.5, 3.0),
        f64::abs,
    );
    assert!(
        error < 0.05,
        "CD off by {:.1}% at U t/R = {x:.2}",
        100.0 * error
    );
}

/// The wake statistics against a band widened by `margin` (issue 23).
fn assert_in_band(what: &str, value: f64, (low, high): (f64, f64), margin: f64) {
    assert!(
        value >= low * (1.0 - margin) && value <= high * (1.0 + margin),
        "{what} = {value:.4}, band {low}..{high} +-{:.0}%",
        100.0 * margin
    );
}

/// Cylinder at Re 100 (Liu, Zheng & Sung 1998; Park, Kwon & Choi 1998):
/// Strouhal 0.164–0.165, mean CD 1.33–1.35, CL amplitude 0.33–0.34, each
/// within 3% of its band.
#[test]
#[ignore = "heavy (about 30 s); `fwav validate --only ns2d/cylinder-re100` runs it. Measured on \
            256 x 192, dt = 0.005: St 0.1649, CD 1.328, CL amplitude 0.323 (all within 3% of their \
            bands; 0.1656, 1.333, 0.329 before the step's velocity was centred, 2026-12-03)"]
fn the_cylinder_wake_at_re_100_sheds_as_published() {
    let s = CylinderWake {
        reynolds: 100.0,
        duration: 150.0,
        averaged: 0.4,
    }
    .run(CylinderWake::validated())
    .unwrap();
    assert_in_band("St", s.strouhal, (0.164, 0.165), 0.03);
    assert_in_band("CD", s.drag, (1.33, 1.35), 0.03);
    assert_in_band("CL amplitude", s.lift_amplitude, (0.33, 0.34), 0.03);
}

/// Cylinder at Re 200 (Braza, Chassaing & Ha Minh 1986): CD 1.40 +- 0.05,
/// CL +-0.75, Strouhal 0.20, within 5%.
#[test]
#[ignore = "fails, and heavy (about 40 s): on 256 x 192, dt = 0.005, St 0.1962 and CD 1.330 pass \
            but the CL amplitude is 0.678, 9.6% below 0.75 (5% allowed; Liu, Zheng & Sung 1998 \
            computed 0.69). Before the step's velocity was centred (2026-12-03): 0.688, converged \
            with the grid (384 x 288, dt = 0.004: 0.688); `fwav validate --only ns2d/`"]
fn the_cylinder_wake_at_re_200_sheds_as_braza_found() {
    let s = CylinderWake {
        reynolds: 200.0,
        duration: 150.0,
        averaged: 0.4,
    }
    .run(CylinderWake::validated())
    .unwrap();
    assert_in_band("St", s.strouhal, (0.20, 0.20), 0.05);
    assert_in_band("CD", s.drag, (1.35, 1.45), 0.05);
    assert_in_band("CL amplitude", s.lift_amplitude, (0.75, 0.75), 0.05);
}

/// Koumoutsakos & Leonard (1995) at Re 3000: CD within 5% over U t/R in
/// [0.5, 3].
#[test]
#[ignore = "heavy (about 10 s); `fwav validate --only ns2d/impulsive-cylinder-re3000` runs it. \
            Measured on 512 x 320, dt = 0.0007: worst 4.8%, since the step's velocity was centred \
            (2026-12-03). Before it, 5.2% at U t/R = 0.61, the drag's minimum, with the wall \
            pressure's vorticity flux compact and 4.4% with it one-sided"]
fn the_impulsively_started_cylinder_at_re_3000_drags_as_koumoutsakos_and_leonard_found() {
    let resolution = ImpulsiveCylinder::validated_re_3000();
    let drag = ImpulsiveCylinder {
        reynolds: 3000.0,
        until: 3.05,
    }
    .run(resolution)
    .unwrap();
    let (error, x) = reference("koumoutsakos_leonard_1995_re3000.dat").worst_deviation(
        &drag,
        (0.5, 3.0),
        f64::abs,
    );
    assert!(
        error < 0.05,
        "CD off by {:.1}% at U t/R = {x:.2}",
        100.0 * error
    );
}

/// The hovering ellipse of Wang, Birch & Dickinson (2004) at Re 75 on the
/// validated resolution: lift over the fourth period, `(t/T, CL)`.
fn hovering_lift() -> Vec<(f64, f64)> {
    HoveringEllipse {
        reynolds: 75.0,
        periods: 4.0,
    }
    .run(HoveringEllipse::validated())
    .unwrap()
}

/// The worst deviation of `lift` from the reference curve `name` over the
/// fourth period, as a fraction of the curve's peak there, and where.
fn fourth_period_deviation(lift: &[(f64, f64)], name: &str) -> (f64, f64) {
    let reference = reference(name);
    let peak = reference.peak_in((3.0, 4.0));
    reference.worst_deviation(lift, (3.0, 4.0), |_| peak)
}

/// The hovering ellipse against the 2D computation of Li, Dong & Liu
/// (2015): CL over the fourth period within 10% of its peak (issue 23).
/// Both start from rest, and the two half-strokes differ (the second lifts
/// 1.29 against 1.03 in theirs, 1.26 against 0.96 here): a memory of the
/// first stroke that Eldredge's (2007) and PetIBM's computations share,
/// not a broken symmetry (`tests/mirror_symmetry.rs`). Measured on 192 x
/// 128, dt = 0.00025: worst 9.7% (9.8% at t/T = 3.70 before the step's
/// velocity was centred, 2026-12-03).
///
/// The curve of Wang, Birch & Dickinson (2004) as distributed with PetIBM
/// (`tests/data/wang_birch_dickinson_2004_lift_re75.dat`, which PetIBM's
/// flapping example reads as the robotic wing's) lifts alike in both
/// half-strokes: all three 2D computations depart from it by about 30%
/// of its peak over the fourth period (this solver 30%, Li et al. 32%,
/// Eldredge 32%), so it is not a reference for them.
#[test]
#[ignore = "heavy (about 45 s); `fwav validate --only ns2d/hovering` runs it. Measured on 192 x 128, \
            dt = 0.00025: worst 9.7% of the peak"]
fn the_hovering_ellipse_lifts_as_li_dong_and_liu_computed() {
    let lift = hovering_lift();
    let (error, t) = fourth_period_deviation(&lift, "li_dong_liu_2015_lift_re75.dat");
    assert!(
        error < 0.10,
        "worst {:.1}% of the peak at t/T = {t:.3}",
        100.0 * error
    );
}

/// The hovering ellipse against Eldredge's (2007) vortex-particle
/// computation: CL over the fourth period within 10% of its peak. The two
/// published computations differ from each other by 12% of the peak (at
/// t/T = 3.73); this solver lies between them.
///
/// The miss is not this solver's resolution (`examples/hover.rs`,
/// 2026-12-04; worst deviation from Eldredge's curve, and from Li et
/// al.'s): 192 x 128 at dt = 0.00025, 10.64% and 9.74%; the step halved,
/// the same to four digits; 288 x 192, 10.51% and 9.61%; 384 x 256 at
/// half the step, 10.48% and 9.58%. Both published curves lift more than
/// this solver's just after the reversal (t/T = 3.10: 0.48 here, 0.51
/// and 0.59 theirs).
#[test]
#[ignore = "fails, and heavy (about 35 s): on 192 x 128, dt = 0.00025, worst 10.6% of the peak at \
            t/T = 3.12 (0.41 against 0.54, the hump after the stroke reversal; the peaks agree \
            within 4%), 10.5% on 384 x 256 at half the step: converged, not the grid's. Li et \
            al.'s curve, within 9.7%, differs from Eldredge's by 12%"]
fn the_hovering_ellipse_lifts_as_eldredge_computed() {
    let lift = hovering_lift();
    let (error, t) = fourth_period_deviation(&lift, "eldredge_2007_lift_re75.dat");
    assert!(
        error < 0.10,
        "worst {:.1}% of the peak at t/T = {t:.3}",
        100.0 * error
    );
}

/// Kelvin's theorem on a lifting section: an ellipse (12% thick) set off
/// at 45 degrees in a stroke sheds a starting vortex and carries the
/// opposite circulation in its boundary layer; the fluid's total stays
/// zero (nothing has left yet) and the wall pressure's trip round the
/// section closes (it was off by the whole pressure range, 23 of 24, when
/// the circulation drifted, and CL was 11).
#[test]
fn a_lifting_ellipse_keeps_the_fluids_circulation_at_zero() {
    use fwav_ns2d::cases::HoveringStroke;
    use fwav_ns2d::{Flow, SectionMap};
    let stroke = HoveringStroke {
        pitch: 0.0,
        mean_angle: 0.75 * std::f64::consts::PI,
        ..HoveringStroke::wang_2004()
    };
    let map = SectionMap::ellipse(0.5, 0.06, (0.0, 0.0)).unwrap();
    let grid = GridSpec {
        around: 128,
        radial: 96,
        outer_radius: 100.0,
        first_cell: 0.01,
        far: None,
    };
    let mut flow = Flow::new(&map, grid, stroke, stroke.peak_speed() / 75.0).unwrap();
    while flow.time() < 0.6 {
        flow.step(0.0005).unwrap();
    }
    let loads = flow.loads();
    let range = loads.pressure.iter().fold(0.0f64, |m, p| m.max(p.abs()));
    assert!(
        flow.circulation().abs() < 1e-6,
        "fluid circulation {}",
        flow.circulation()
    );
    assert!(
        loads.closure.abs() < 0.01 * range,
        "trip round {} of {range}",
        loads.closure
    );
}
