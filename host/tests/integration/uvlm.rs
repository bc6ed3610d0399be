//! The unsteady vortex-lattice method (`fwav::uvlm`) against Katz &
//! Plotkin's own program for the sudden start of rectangular wings, and
//! against Garrick's thrust and Theodorsen's lift for a heaving plate of
//! large aspect ratio; the cost-saving wake options and the convergence in
//! time step and lattice size. Every test prints the numbers it checks.

use std::f64::consts::PI;

use fwav::aero2d::theory::{garrick_plunge, theodorsen};
use fwav::uvlm::{Lattice, Uvlm, UvlmSettings};
use fwav::validation::uvlm::{heave, katz_plotkin, sudden_start, Heave};
use nalgebra::Vector3;

/// Katz & Plotkin (2001), *Low-Speed Aerodynamics*, 2nd ed., §13.12,
/// Fig. 13.34: lift after the sudden start of rectangular wings (alpha = 5
/// deg, U dt / c = 1/16, 160 steps), here against the output of their
/// Program 16 (App. D) for AR 4 and 8 with the same discretization and
/// conventions. CL(t) within 3% from step 2 on (step 1 is the impulsive
/// added-mass spike, compared too but reported separately); the steady CL
/// of a long frozen wake (U dt = 10 c, 5 steps: Program 16's steady mode)
/// within 2% of the program's steady value.
#[test]
fn sudden_start_matches_katz_plotkin_program_16() {
    for (ar, semi_span) in [(4, 2.0), (8, 4.0)] {
        let (reference, steady_reference) = katz_plotkin(ar).expect("reference data");
        let cl = sudden_start(semi_span, reference.len(), 1.0 / 16.0, 5).expect("run");
        let error = |step: usize| cl[step].0 / reference[step] - 1.0;
        let (worst_step, worst) =
            (1..cl.len())
                .map(|s| (s + 1, error(s)))
                .fold(
                    (0, 0.0f64),
                    |a, b| if b.1.abs() > a.1.abs() { b } else { a },
                );
        let normal_worst = (1..cl.len())
            .map(|s| (cl[s].1 / reference[s] - 1.0).abs())
            .fold(0.0f64, f64::max);
        println!(
            "AR {ar}: step 1 (added-mass spike) CL {:.4} vs {:.4} ({:+.2}%); steps 2-{}: \
             worst {:+.2}% at step {worst_step} (normal-force lift: worst {:.2}%); \
             step 160 CL {:.4} vs {:.4}",
            cl[0].0,
            reference[0],
            100.0 * error(0),
            cl.len(),
            100.0 * worst,
            100.0 * normal_worst,
            cl[cl.len() - 1].0,
            reference[reference.len() - 1]
        );
        for step in [2, 5, 10, 20, 40, 80, 120, 160] {
            println!(
                "  step {step:3}  U t / c = {:.4}  CL {:.4}  reference {:.4}  ({:+.2}%)",
                (step - 1) as f64 / 16.0,
                cl[step - 1].0,
                reference[step - 1],
                100.0 * error(step - 1)
            );
        }
        assert!(worst.abs() < 0.03, "AR {ar}: {:.2}%", 100.0 * worst);
        assert!(
            error(0).abs() < 0.03,
            "AR {ar} spike {:.2}%",
            100.0 * error(0)
        );
        let steady = sudden_start(semi_span, 5, 10.0, 0).expect("run")[4].0;
        let steady_error = steady / steady_reference - 1.0;
        println!(
            "AR {ar}: steady CL {steady:.4} (frozen wake, U dt = 10 c, 5 steps) vs Program 16 \
             {steady_reference:.4} ({:+.2}%); sudden start at U t / c = 9.94 is {:.1}% below \
             its own steady value",
            100.0 * steady_error,
            100.0 * (1.0 - cl[cl.len() - 1].0 / steady)
        );
        assert!(
            steady_error.abs() < 0.02,
            "AR {ar}: {:.2}%",
            100.0 * steady_error
        );
    }
}

/// Theodorsen's lift of a plate plunging `h = h0 c sin(ωt)`:
/// `CL = 2π h0 [(k² + 2kG) sin(ωt) − 2kF cos(ωt)]` (Theodorsen 1935, NACA
/// Report 496, non-circulatory plus circulatory lift, `C(k) = F + iG`):
/// `(sin coefficient, cos coefficient, amplitude)`.
fn theodorsen_lift(k: f64, h0: f64) -> (f64, f64, f64) {
    let (f, g) = theodorsen(k);
    let (a, b) = (
        2.0 * PI * h0 * (k * k + 2.0 * k * g),
        -2.0 * PI * h0 * 2.0 * k * f,
    );
    (a, b, a.hypot(b))
}

/// Garrick (1936), NACA Report 567, pure plunge: cycle-mean thrust
/// `CT = 4π k² (h0/c)² (F² + G²)` ([`garrick_plunge`]) within 10%, for
/// k = 0.5 (h0 = 0.1 c) and k = 1 (h0 = 0.05 c), on a rigid rectangular
/// plate of aspect ratio 40 (semi-span 20 c with the mirror image), 8 x 6
/// panels, 8 steps a chord, a frozen flat wake (linear theory), 3 cycles
/// (the cycle before the last is printed to show the periodic state).
/// Thrust comes from the leading-edge suction of the Kutta–Joukowski
/// forces (fwav::uvlm::loads). Also printed: the input power against
/// Garrick's `CP = 4π k² (h0/c)² F` and the first harmonic of the lift
/// against Theodorsen's.
#[test]
fn heaving_plate_thrust_matches_garrick() {
    for (k, h0) in [(0.5, 0.1), (1.0, 0.05)] {
        let r = heave(k, h0, 8, 6, 20.0, 8, 3, (0, usize::MAX)).expect("heave");
        let (ct, cp, _) = garrick_plunge(k, h0);
        let (lift_sin, lift_cos, lift_amplitude) = theodorsen_lift(k, h0);
        let error = r.ct / ct - 1.0;
        println!(
            "k = {k}, h0 = {h0} c: CT {:.5} (cycle before {:.5}) vs Garrick {ct:.5} ({:+.2}%); \
             CP {:.5} vs {cp:.5} ({:+.2}%); efficiency {:.3} vs {:.3}",
            r.ct,
            r.ct_before,
            100.0 * error,
            r.cp,
            100.0 * (r.cp / cp - 1.0),
            r.ct / r.cp,
            ct / cp
        );
        println!(
            "  CL = {:.4} sin + {:.4} cos (peak {:.4}) vs Theodorsen {lift_sin:.4} sin + \
             {lift_cos:.4} cos (amplitude {lift_amplitude:.4}, {:+.2}%)",
            r.cl_sin,
            r.cl_cos,
            r.cl_peak,
            100.0 * (r.cl_sin.hypot(r.cl_cos) / lift_amplitude - 1.0)
        );
        assert!(error.abs() < 0.10, "k = {k}: {:.2}%", 100.0 * error);
    }
}

/// The cost-saving wake options on a heaving wing where the wake matters
/// more (aspect ratio 8, h0 = 0.2 c, k = 0.5, 4 x 8 panels, 8 steps a
/// chord = 50 steps a cycle, 3 cycles): rolling up only the youngest half
/// cycle of wake (25 rows) and keeping two cycles (100 rows) changes the
/// mean thrust by less than 1% against a fully free, untruncated wake.
#[test]
fn partial_rollup_and_truncation_change_thrust_below_one_percent() {
    let (k, h0) = (0.5, 0.2);
    let full = heave(k, h0, 4, 8, 4.0, 8, 3, (usize::MAX, usize::MAX)).expect("heave");
    let reduced = heave(k, h0, 4, 8, 4.0, 8, 3, (25, 100)).expect("heave");
    let frozen = heave(k, h0, 4, 8, 4.0, 8, 3, (0, 100)).expect("heave");
    let change = reduced.ct / full.ct - 1.0;
    println!(
        "AR 8, k = {k}, h0 = {h0} c: CT fully free, untruncated {:.5}; 25 free rows, 100 kept \
         {:.5} ({:+.3}%); frozen wake, 100 kept {:.5} ({:+.3}%)",
        full.ct,
        reduced.ct,
        100.0 * change,
        frozen.ct,
        100.0 * (frozen.ct / full.ct - 1.0)
    );
    assert!(change.abs() < 0.01, "{:.3}%", 100.0 * change);
}

/// Convergence on the heaving case (k = 1, h0 = 0.05 c, aspect ratio 40):
/// halving the time step and doubling the lattice both ways (8 x 6 panels,
/// 8 steps a chord -> 16 x 12 panels, 16 steps a chord) changes the mean
/// thrust by less than 3%; the changes of power and lift are printed.
#[test]
fn heaving_plate_converges_in_time_step_and_lattice() {
    let (k, h0) = (1.0, 0.05);
    let coarse = heave(k, h0, 8, 6, 20.0, 8, 3, (0, usize::MAX)).expect("heave");
    let fine = heave(k, h0, 16, 12, 20.0, 16, 3, (0, usize::MAX)).expect("heave");
    let change = |a: f64, b: f64| 100.0 * (b / a - 1.0);
    let (ct, cp, _) = garrick_plunge(k, h0);
    let (_, _, lift) = theodorsen_lift(k, h0);
    let amplitude = |r: &Heave| r.cl_sin.hypot(r.cl_cos);
    println!(
        "k = {k}: CT {:.5} -> {:.5} ({:+.2}%; Garrick {ct:.5}); CP {:.5} -> {:.5} ({:+.2}%; \
         Garrick {cp:.5}); CL amplitude {:.4} -> {:.4} ({:+.2}%; Theodorsen {lift:.4})",
        coarse.ct,
        fine.ct,
        change(coarse.ct, fine.ct),
        coarse.cp,
        fine.cp,
        change(coarse.cp, fine.cp),
        amplitude(&coarse),
        amplitude(&fine),
        change(amplitude(&coarse), amplitude(&fine)),
    );
    assert!(change(coarse.ct, fine.ct).abs() < 3.0);
}

/// The mirror image is the other half: a symmetric half-wing model gives
/// the same circulation, half the drag, lift and power of the full wing
/// modelled from tip to tip (after a few steps at alpha = 5 deg, free
/// wake); the half wing's side force is its own, cancelled by the other
/// half's.
#[test]
fn mirror_image_equals_full_span() {
    let alpha = 5f64.to_radians();
    let half = Lattice::rectangle(1.0, 2.0, 3, 4, alpha).expect("half");
    let full_corners = (0..=3)
        .flat_map(|i| {
            (0..=8).map(move |j| {
                let x = i as f64 / 3.0;
                Vector3::new(x * alpha.cos(), -2.0 + 0.5 * j as f64, -x * alpha.sin())
            })
        })
        .collect();
    let full = Lattice::new(3, 8, full_corners).expect("full");
    let run = |wing: &Lattice, symmetric: bool| {
        let mut settings = UvlmSettings::new(0.1, 1.2, Vector3::new(1.0, 0.0, 0.0));
        settings.symmetric = symmetric;
        let mut uvlm = Uvlm::new(wing.chordwise, wing.spanwise, settings).expect("solver");
        let rest = vec![Vector3::zeros(); wing.corner_count()];
        let mut last = None;
        for _ in 0..6 {
            let solution = uvlm.solve(wing, &rest).expect("solve");
            uvlm.advance(wing, &solution).expect("advance");
            last = Some(solution);
        }
        last.expect("steps")
    };
    let (h, f) = (run(&half, true), run(&full, false));
    for i in 0..3 {
        for j in 0..4 {
            let (a, b) = (h.circulation[i * 4 + j], f.circulation[i * 8 + 4 + j]);
            assert!((a - b).abs() < 1e-9 * b.abs().max(1.0), "{a} {b}");
        }
    }
    println!(
        "half-wing force {:?}, full wing / 2 {:?}",
        h.force,
        f.force / 2.0
    );
    assert!((h.force.x - f.force.x / 2.0).abs() < 1e-9 * f.force.norm());
    assert!((h.force.z - f.force.z / 2.0).abs() < 1e-9 * f.force.norm());
    assert!((h.power - f.power / 2.0).abs() < 1e-12);
}
