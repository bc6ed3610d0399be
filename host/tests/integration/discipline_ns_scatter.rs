//! How much the Navier–Stokes section model's scores scatter, on the
//! default FWAV section deforming as the built-in design's first system
//! analysis found: from window to window of one run, with the time step,
//! with a coarser spin-up, with a shorter evaluation, and against the
//! rows' converged (twelve-stroke) scores. These measurements set the
//! declared scatter the adoption margin carries
//! (`section_model::NS_WINDOW_SCATTER`, `NS_LONG_MEAN_SCATTER`). All heavy
//! (minutes to an hour and a half): ignored, run by name (`ns2d/README.md`,
//! "The evaluation's window" and "A longer step", quotes their figures).
//! What an evaluation and a discipline run cost, and the rows' records,
//! are `discipline_ns_scores`.

use fwav::aeroelastic::FlappingKinematics;
use fwav::discipline::section::SectionCase;
use fwav::discipline::section_model::{
    SectionFlowModel, ViscousPlate, NS_LONG_MEAN_SCATTER, NS_WINDOW_SCATTER,
};

use crate::discipline_ns_scores::{
    default_plate, deforming_case, env_design, env_designs, env_plate, l18_rows, parse_designs,
};
use crate::viscous_default_section::{mean, standard_deviation, window_of};

/// How much the Navier–Stokes scores of the deforming default section
/// scatter from window to window of one run, which must be less than
/// what two evaluations differ by (`section_model::NS_WINDOW_SCATTER`,
/// taken from the L18 rows at two steps:
/// `discipline_ns_scores::ns_discipline_benchmark`): 12 strokes on the
/// full grid (no spin-up), deforming as the default
/// design's first system analysis found, at the
/// built-in initial kinematics (or `FWAV_NS_DESIGN="13,20,0,110"`: Hz and
/// degrees; `FWAV_NS_RADIAL` sets the rings, `FWAV_NS_COURANT` the
/// step's Courant number), strokes 3 to 12 as five
/// windows of two, each as the
/// discipline scores its window (mean CT, mean CT over mean CP). Until
/// 2026-12-04 this was the declared scatter (the efficiency's from the
/// initial kinematics, the thrust's from the 13 Hz design), but these
/// designs' flows settle where many L18 rows' do not. Measured on 384 x
/// 320 (2026-12-03, slow hour): at the initial kinematics CT 0.0850, 0.0885, 0.0885, 0.0869, 0.0877 (1.65 %),
/// efficiency 0.0341, 0.0352, 0.0352, 0.0346, 0.0349 (1.38 %), 561 s; at
/// 13 Hz, ±20°, plane 110° CT 0.0814, 0.0831, 0.0826, 0.0851, 0.0853
/// (1.99 %), efficiency 0.0539, 0.0544, 0.0540, 0.0544, 0.0545 (0.52 %),
/// 642 s. On 384 x 240, the default before: 2.0 % and 1.8 % (461 s),
/// 2.8 % and 1.1 % (335 s). At L18 row 18 (13 Hz, ±30°, −10°, plane 90°,
/// `FWAV_NS_DESIGN=13,30,-10,90`; shared with a design run): 0.66 % and
/// 0.57 % on 384 x 320 (1,106 s), 10.4 % and 8.9 % on 384 x 240, 7.4 %
/// and 5.6 % on 384 x 400, whose first window is within 1.6 % of 320's
/// (docs/ns-design). At Courant 4 (`FWAV_NS_COURANT=4`, initial
/// kinematics, 2026-12-04): 0.61 % and 0.65 %, 327 s against Courant 3's
/// 498 s the same hour, but its first window 5.3 % (CT) and 4.4 %
/// (efficiency) above Courant 3's (`ns2d/README.md`, "Speed"). At L18 row 14 (11
/// Hz, ±40°, −10°, plane 90°; `RAYON_NUM_THREADS=1`, 2026-12-04): CT
/// 0.1171, 0.1144, 0.1245, 0.1029, 0.1061 (7.7 %; efficiency 7.0 %),
/// 754 s, at Courant 3 (above the declared scatter: not checked there),
/// and 0.1090, 0.1035, 0.1276, 0.1297, 0.0993 (12.3 %), 581 s, at
/// Courant 4; their means agree within 0.7 % (`ns2d/README.md`, "The L18 rows at
/// another step"). The rows of `NS_LONG_MEAN_SCATTER` on the exponential
/// 384 x 320 (2026-12-04, one thread each, Courant 3 and 4; 347 s to
/// 937 s a run; on the default grid, 2026-12-05, see the constant's
/// doc): CT scatters by
/// 13.1 % and 10.3 % at row 4 (9, 20, 0, 90), 3.1 % and 6.1 % at row 6
/// (13, 40, −10, 70), 1.4 % and 9.6 % at row 7 (9, 30, −10, 110), 1.7 %
/// and 4.0 % at row 11 (11, 20, −10, 110), and 7.3 % and 3.5 % at row 18,
/// whose run of before scattered by 0.66 %: whether a row's flow settles
/// depends on the way it took. Row 4 at Courant 3 on 400 and 480 rings
/// (`FWAV_NS_RADIAL`; one thread, 827 s and 1,087 s): 12.9 % and 6.6 %,
/// means 0.0332 and 0.0355; on 320 rings again after the thread-count
/// fix (the flow changed only at rounding): 0.0327, 0.0339, 0.0350,
/// 0.0310, 0.0348 (5.0 %), mean 0.0335 against the first run's 0.0310. The five windows' mean is the score of
/// `[design] section_cycles = 12`; where the windows scatter less than
/// the two-stroke declared figure (the settled designs) it must too
/// scatter less than its own, `NS_LONG_MEAN_SCATTER`.
#[test]
#[ignore = "benchmark (about 10 min in a slow hour): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scatter::ns_deforming_window_scatter_benchmark`"]
fn ns_deforming_window_scatter_benchmark() {
    let design = env_design();
    let plate = ViscousPlate {
        spin_up: false,
        ..env_plate()
    };
    let at_default_resolution = plate == default_plate();
    let case = SectionCase {
        cycles: 12,
        ..deforming_case(plate)
    };
    let clock = std::time::Instant::now();
    let (history, _) = case.history(&design).unwrap();
    let (windows, thrust, efficiency) = crate::viscous_default_section::window_scatter(&history);
    println!(
        "{:?}: windows (CT, efficiency): {windows:.4?}; relative deviation: CT {thrust:.4}, \
         efficiency {efficiency:.4}; {:.0} s",
        design.degrees(),
        clock.elapsed().as_secs_f64()
    );
    // The declared scatter is the default resolution's: another is
    // measured, not checked. From window to window of one run the
    // scores scatter less than from run to run (`NS_WINDOW_SCATTER`).
    // Checked at the two designs whose flows settle; a row whose flow
    // wanders (row 14: 7.7 %) scatters beyond the rows' RMS.
    let settled = [
        FlappingKinematics::INITIAL,
        FlappingKinematics::from_degrees([13.0, 20.0, 0.0, 110.0]),
    ];
    if !at_default_resolution || !settled.contains(&design) {
        return;
    }
    // The long mean (the five windows', `section_cycles = 12`) scatters
    // as five independent windows' mean would, within the declared.
    let long = (windows.len() as f64).sqrt();
    for (measured, declared) in [
        (thrust, NS_WINDOW_SCATTER.0),
        (efficiency, NS_WINDOW_SCATTER.1),
        (thrust / long, NS_LONG_MEAN_SCATTER.0),
        (efficiency / long, NS_LONG_MEAN_SCATTER.1),
    ] {
        assert!(
            measured < declared,
            "declared {declared:.4}, measured {measured:.4}"
        );
    }
}

/// The spin-up (`ViscousPlate::spin_up`: the two strokes before the
/// scored window on 256 x 160 nodes) against the full grid throughout, on
/// the deforming default section at the built-in initial kinematics: the
/// window's CT and efficiency within 3 % (the convergence
/// figure; the full grid's own windows scatter 2.0 % and 1.8 %,
/// `ns_deforming_window_scatter_benchmark`).
///
/// Fails: CT 0.0712 against 0.0859 (-17 %), efficiency 0.0286 against
/// 0.0341 (-16 %), 75 s against 126 s. The full grid's flow still
/// carries a mean lift from its start into the window (stroke means
/// +0.81, +0.39, +0.22, +0.19); the spin-up grid's loses it within a
/// stroke (+0.95, +0.03, then +0.02, +0.04 on the full grid), and the
/// window differs. Over the 18 rows of the L18 array the spin-up moved
/// CT by 13 % RMS (up to 29 %) with no mean shift (docs/ns-design, "The
/// spin-up"), so it stays off.
#[test]
#[ignore = "fails (CT -17 %, efficiency -16 % against the full grid's window; docs/ns-design, \"The spin-up\"), and heavy (about 3 min): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scatter::a_spin_up_keeps_the_deforming_window_scores`"]
fn a_spin_up_keeps_the_deforming_window_scores() {
    let full = deforming_case(default_plate());
    let spun = SectionCase {
        model: SectionFlowModel::Ns(ViscousPlate {
            spin_up: true,
            ..default_plate()
        }),
        ..full.clone()
    };
    let design = FlappingKinematics::INITIAL;
    let mut results = Vec::new();
    for (name, case) in [("full grid", &full), ("spun up", &spun)] {
        let clock = std::time::Instant::now();
        let r = case.evaluate(&design).unwrap();
        println!(
            "{name}: {:.1} s, CT {:.4}, CP {:.4}, efficiency {:.4}",
            clock.elapsed().as_secs_f64(),
            r.ct,
            r.cp,
            r.efficiency
        );
        results.push(r);
    }
    let (f, s) = (&results[0], &results[1]);
    for (what, spun, full) in [
        ("CT", s.ct, f.ct),
        ("efficiency", s.efficiency, f.efficiency),
    ] {
        assert!(
            (spun / full - 1.0).abs() < 0.03,
            "{what}: spun up {spun:.4}, full grid {full:.4}"
        );
    }
}

/// How the scored window of the deforming default section moves with the
/// time step, design by design: the section deforming as the built-in
/// design's first system analysis found (`tests/data/fwav_cycle1_section.json`),
/// the designs of `FWAV_NS_DESIGNS` ("9,20,0,90;11,40,-10,90": Hz and
/// degrees) evaluated as the discipline evaluates them (two at a time)
/// at `FWAV_NS_COURANT`. The L18 rows of the first cycle's discipline at
/// Courant 4 (`discipline_ns_scores::ns_discipline_benchmark` with
/// `FWAV_NS_COURANT=4`) against Courant 3 (the NS design run of docs/ns-design, cycle 1) moved CT by
/// 5.6 % RMS and up to 12.8 %; this runs the rows that moved most at a
/// step half the default's (`ns2d/README.md`, "A longer step"). `FWAV_NS_CYCLES`
/// sets the strokes (4 by default; all after the second scored, as
/// `[design] section_cycles` scores them). Measured
/// (2026-12-04), CT and efficiency at Courant 4 / 3 / 1.5: row 2 (the
/// initial design) 0.0895 / 0.0850 / 0.0855 and 0.0356 / 0.0341 /
/// 0.0342; row 4 (9 Hz, ±20°, 0°, 90°) 0.0370 / 0.0328 / 0.0364 and
/// 0.0454 / 0.0406 / 0.0452; row 14 (11, 40, −10, 90) 0.1081 / 0.1216 /
/// 0.1270 and 0.0242 / 0.0270 / 0.0285; row 18 (13, 30, −10, 90) 0.1256
/// / 0.1162 / 0.1288 and 0.0336 / 0.0314 / 0.0344 (898 s for the four at
/// Courant 1.5). Six strokes, strokes 5–6 scored (before the scores
/// took all strokes after the second), Courant 4 / 3: row 4
/// 0.0353 / 0.0339 and 0.0446 / 0.0422 (+4.1 %, +5.7 %), row 18 0.1168
/// / 0.1164 and 0.0311 / 0.0313 (+0.3 %, −0.6 %) (247 s and 322 s for
/// the pair); row 7 (9, 30, −10, 110) 0.0531 / 0.0562 and 0.0370 /
/// 0.0384, row 11 (11, 20, −10, 110) 0.0536 / 0.0512 and 0.0513 /
/// 0.0500, row 14 0.1202 / 0.0905 (+33 %) and 0.0268 / 0.0205, row 6
/// (13, 40, −10, 70) 0.1638 / 0.1670 and 0.0254 / 0.0260 (552 s and
/// 725 s for the four).
#[test]
#[ignore = "benchmark (about 15 min at Courant 1.5 for four designs): `FWAV_NS_COURANT=1.5 FWAV_NS_DESIGNS=\"9,20,0,90;11,40,-10,90\" cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scatter::ns_window_time_step_benchmark`"]
fn ns_window_time_step_benchmark() {
    use rayon::prelude::*;
    let plate = env_plate();
    let case = SectionCase {
        cycles: std::env::var("FWAV_NS_CYCLES").map_or(4, |v| v.parse().unwrap()),
        ..deforming_case(plate)
    };
    let designs = env_designs(|| vec![FlappingKinematics::INITIAL]);
    let clock = std::time::Instant::now();
    let results: Vec<_> = designs.par_iter().map(|d| case.evaluate(d)).collect();
    for (design, result) in designs.iter().zip(&results) {
        let r = result.as_ref().unwrap();
        println!(
            "{:?} at Courant {}: CT {:.4}, CP {:.4}, efficiency {:.4}",
            design.degrees(),
            plate.courant,
            r.ct,
            r.cp,
            r.efficiency
        );
    }
    println!("{:.0} s", clock.elapsed().as_secs_f64());
}

/// A shorter evaluation: three strokes, the last two scored (strokes 2–3),
/// would take about a quarter off the discipline's time (the NS design's
/// 54 minutes would come to about 41, under the 45). It is
/// acceptable only if it moves the rows' scores less than the scatter
/// the adoption margin already carries for one evaluation
/// ([`NS_WINDOW_SCATTER`]): measured on the deforming default section's
/// 18 L18 rows (the first cycle's, as `docs/ns-design/l18-384x256.txt`
/// lists them), strokes 2–3 against strokes 3–4 of the same run (a
/// three-stroke run is the four-stroke run's first three strokes: the
/// flow is deterministic and causal).
///
/// Fails (2026-12-05, the default 384 x 256 at Courant 3, two rows at a
/// time, 1,351 s; `docs/ns-design/strokes-384x256.txt`): CT 5.99 % RMS
/// (mean +0.31 %), efficiency 5.09 % RMS (mean +0.20 %), against the
/// declared 5.30 % and 4.50 %; row 14 (11 Hz, ±40°, −10°, 90°) +18.2 %
/// and +14.8 %. Strokes 3–4 equal the discipline's scores of that table
/// to every digit shown. Against the converged score, each row's mean
/// over strokes 3–12 of an independent twelve-stroke run at Courant 4
/// (`docs/ns-design/long-means-384x256.txt`,
/// [`the_declared_scatter_agrees_with_the_rows_error_against_their_long_means`]),
/// strokes 2–3 are the farther: their deviations scatter by 9.09 % in CT
/// and 7.31 % in efficiency, strokes 3–4's by 7.09 % and 5.75 % (means
/// +2.8 % and +2.6 %, +1.9 % and +1.7 %). On the seven rows with
/// twelve-stroke runs at Courant 3 too, against those runs' strokes 5–12,
/// 11.3 % against 8.4 % RMS in CT, 8.6 % against 6.6 % in efficiency
/// (row 14 +24 % against +5 %). Every row's first stroke thrusts 2 % to
/// 43 % above its strokes 3–4 (the start); the second lies from −19 % to
/// +24 % of them, without a common sign. So the evaluation keeps four
/// strokes. `FWAV_NS_DESIGNS` and `FWAV_NS_COURANT` run other rows or
/// another step (measured, not checked).
#[test]
#[ignore = "fails (strokes 2-3 against 3-4 over the 18 rows: CT 5.99 % RMS, efficiency 5.09 %, \
            beyond the declared 5.30 % and 4.50 %; row 14 +18 %), and heavy (1,351 s): \
            `cargo test --release -p fwav --test integration -- --ignored --nocapture \
            discipline_ns_scatter::a_three_stroke_evaluation_keeps_the_rows_scores`"]
fn a_three_stroke_evaluation_keeps_the_rows_scores() {
    use rayon::prelude::*;
    let plate = env_plate();
    let cycles = 4;
    let case = SectionCase {
        cycles,
        ..deforming_case(plate)
    };
    let listed = std::env::var("FWAV_NS_DESIGNS").ok();
    let designs: Vec<FlappingKinematics> = listed.as_deref().map_or_else(l18_rows, parse_designs);
    let clock = std::time::Instant::now();
    let strokes: Vec<Vec<(f64, f64)>> =
        designs.par_iter().map(|d| stroke_means(&case, d)).collect();
    let (mut d_ct, mut d_eta) = (Vec::new(), Vec::new());
    for (design, s) in designs.iter().zip(&strokes) {
        let (four, three) = (window_of(&s[2..4]), window_of(&s[1..3]));
        d_ct.push(three.0 / four.0 - 1.0);
        d_eta.push(three.1 / four.1 - 1.0);
        println!(
            "{:?}: strokes (CT, CP) {s:.4?}; strokes 3-4 CT {:.4} efficiency {:.4}; \
             strokes 2-3 CT {:.4} ({:+.1} %) efficiency {:.4} ({:+.1} %)",
            design.degrees(),
            four.0,
            four.1,
            three.0,
            100.0 * d_ct.last().unwrap(),
            three.1,
            100.0 * d_eta.last().unwrap()
        );
    }
    let (ct, eta) = (root_mean_square(&d_ct), root_mean_square(&d_eta));
    println!(
        "strokes 2-3 against 3-4 over {} rows: CT {:.2} % RMS (mean {:+.2} %), efficiency {:.2} % \
         RMS (mean {:+.2} %); Courant {}; {:.0} s",
        designs.len(),
        100.0 * ct,
        100.0 * mean(&d_ct),
        100.0 * eta,
        100.0 * mean(&d_eta),
        plate.courant,
        clock.elapsed().as_secs_f64()
    );
    // The declared scatter is the default resolution's rows'.
    if plate != default_plate() || listed.is_some() {
        return;
    }
    for (measured, declared) in [(ct, NS_WINDOW_SCATTER.0), (eta, NS_WINDOW_SCATTER.1)] {
        assert!(
            measured < declared,
            "strokes 2-3 moved the rows by {measured:.4} RMS, beyond the declared {declared:.4}"
        );
    }
}

/// Whether the declared scatter of one evaluation ([`NS_WINDOW_SCATTER`])
/// is what the adoption margin needs: each row's error against its
/// converged score. `NS_WINDOW_SCATTER` is measured as a change of the
/// step; two runs that differ only in their step share the start, so
/// their difference leaves out what the start puts into both. Here the
/// first cycle's 18 L18 rows are scored as the discipline scores them
/// (four strokes at Courant 3, strokes 3–4) and set against their
/// converged scores from independent runs (twelve strokes at Courant 4,
/// the mean over strokes 3–12, as `[design] section_cycles = 12` scores
/// them); the rows' relative deviations have their mean (an error common
/// to every design, which the margin need not carry) and the long means'
/// own scatter ([`NS_LONG_MEAN_SCATTER`]) taken out.
///
/// Agrees (2026-12-05; `docs/ns-design/long-means-384x256.txt`): 5.84 %
/// in CT and 4.62 % in efficiency (deviations' standard deviation 7.09 %
/// and 5.75 %, means +2.56 % and +1.73 %; row 18 +19.0 %, row 1 +16.0 %),
/// against the declared 5.30 % and 4.50 %: within the 17 % by which a
/// standard deviation of 18 values is itself uncertain, so the start adds
/// little that a change of step leaves out, and the declared figure
/// stands. Measured from the same flows, not from one run of this test:
/// the four-stroke rows of
/// [`a_three_stroke_evaluation_keeps_the_rows_scores`] and the
/// twelve-stroke rows of `ns_deforming_window_scatter_benchmark` with
/// `FWAV_NS_COURANT=4` (one thread each, 248–408 s a run; their
/// efficiency the five windows' mean, here the ratio of the strokes'
/// means, which differ by far less than the figures' precision). The
/// seven rows measured first gave 8.1 % and 6.6 %: most of an RMS over
/// few rows comes from the one or two whose flows wander. Run as one
/// (2026-12-05, stopped after six rows to leave the machine to CI: 44
/// min, 24 of them beside a CI run), it gave the recorded
/// scores and long means of rows 1, 2, 3, 10, 11 and 12, to the last
/// digit in CT but row 2's long mean (0.0874 against 0.0873; the five
/// windows' printed CTs average 0.08734, so the two lie either side of
/// a rounding), and the efficiencies' last digit apart by the two
/// definitions (0.0335 against 0.0334 for row 1). Run as one again with
/// each plate sample's map moved by its rigid part (2026-12-06, the
/// binary of `ba486e3`, 6,012 s, its first hour beside compiles and
/// tests): CT 4.43 % (mean +1.40 %), efficiency 4.09 % (mean +0.98 %),
/// passing (`docs/ns-design/long-means-384x256-moved.txt`), with the
/// long-mean scatter of then (4.03 % and 3.43 %) taken out.
///
/// Fails with [`NS_LONG_MEAN_SCATTER`] as measured since (2026-12-06
/// afternoon: 4.64 % and 4.18 %, four runs of each of seven rows):
/// taken out of the same deviations (7.09 % and 5.75 % before, 5.99 %
/// and 5.34 % with the present maps), 3.79 % and 3.32 %, −28.6 % and
/// −26.2 % from the declared (computed from the run's printed figures,
/// not run again). On the safe side: the declared window scatter is
/// larger than this implies; the long means' scatter comes from seven
/// rows chosen among those whose windows moved most, and may overstate
/// the 18 rows' (`section_model::NS_WINDOW_SCATTER`'s docs).
#[test]
#[ignore = "fails since NS_LONG_MEAN_SCATTER was measured on four runs a row (2026-12-06: \
            3.79 % and 3.32 % against the declared 5.3 % and 4.5 %, outside the 17.1 %, on the safe side; \
            computed from the last run's figures), and heavy (about 90 min: 18 four-stroke and \
            18 twelve-stroke runs, two at a time, a round of two rows 10-13 min): \
            `cargo test --release -p fwav --test integration -- --ignored --nocapture \
            discipline_ns_scatter::the_declared_scatter_agrees_with_the_rows_error_against_their_long_means`"]
fn the_declared_scatter_agrees_with_the_rows_error_against_their_long_means() {
    use rayon::prelude::*;
    let plate = default_plate();
    let scored = deforming_case(plate);
    let long = SectionCase {
        cycles: 12,
        ..deforming_case(ViscousPlate {
            courant: 4.0,
            ..plate
        })
    };
    let clock = std::time::Instant::now();
    let deviations: Vec<(f64, f64)> = l18_rows()
        .par_iter()
        .map(|design| {
            let (window, converged) = rayon::join(
                || window_of(&stroke_means(&scored, design)[2..4]),
                || window_of(&stroke_means(&long, design)[2..]),
            );
            println!(
                "{:?}: strokes 3-4 CT {:.4} efficiency {:.4}; long mean CT {:.4} efficiency {:.4}",
                design.degrees(),
                window.0,
                window.1,
                converged.0,
                converged.1
            );
            (window.0 / converged.0 - 1.0, window.1 / converged.1 - 1.0)
        })
        .collect();
    let own = |values: Vec<f64>, long_mean: f64| {
        let deviation = standard_deviation(&values);
        let own = (deviation * deviation - long_mean * long_mean)
            .max(0.0)
            .sqrt();
        (mean(&values), own)
    };
    let (ct_mean, ct) = own(
        deviations.iter().map(|d| d.0).collect(),
        NS_LONG_MEAN_SCATTER.0,
    );
    let (eta_mean, eta) = own(
        deviations.iter().map(|d| d.1).collect(),
        NS_LONG_MEAN_SCATTER.1,
    );
    println!(
        "one evaluation against the long means: CT {:.2} % (mean {:+.2} %), efficiency {:.2} % \
         (mean {:+.2} %); {:.0} s",
        100.0 * ct,
        100.0 * ct_mean,
        100.0 * eta,
        100.0 * eta_mean,
        clock.elapsed().as_secs_f64()
    );
    // A sample standard deviation of n values is uncertain by about
    // 1/sqrt(2 (n - 1)) of itself.
    let uncertainty = 1.0 / (2.0 * (deviations.len() - 1) as f64).sqrt();
    for (measured, declared) in [(ct, NS_WINDOW_SCATTER.0), (eta, NS_WINDOW_SCATTER.1)] {
        assert!(
            (measured / declared - 1.0).abs() <= uncertainty,
            "one evaluation's error against the long means {measured:.4}, declared {declared:.4}"
        );
    }
}

/// Each stroke's mean CT and CP of `case` at `design`
/// ([`crate::viscous_default_section::stroke_means`]).
fn stroke_means(case: &SectionCase, design: &FlappingKinematics) -> Vec<(f64, f64)> {
    let (history, _) = case.history(design).unwrap();
    crate::viscous_default_section::stroke_means(&history, case.cycles)
}

/// The root mean square of `values`.
fn root_mean_square(values: &[f64]) -> f64 {
    (mean(&values.iter().map(|x| x * x).collect::<Vec<_>>())).sqrt()
}

/// The convergence figure asked of the twelve-stroke scores
/// (`[design] section_cycles = 12`, the mean over strokes 3–12): each of
/// the seven rows of [`NS_LONG_MEAN_SCATTER`] (L18 rows 2, 4, 6, 7, 11,
/// 14 and 18, the default section deforming as the built-in design's
/// first system analysis found) run at the default resolution, at a
/// shorter step (Courant 2 against 3) and on a grid refined both ways
/// (480 nodes round against 384, 320 rings against 256, the far
/// stretch scaled with them), its CT and efficiency to change by less
/// than 3 % under each refinement. `FWAV_NS_DESIGNS`
/// ("9,20,0,90;11,40,-10,90": Hz and degrees) runs other designs.
///
/// Fails (2026-12-06, each run one thread, two at a time, as separate
/// runs of [`ns_deforming_window_scatter_benchmark`] with
/// `FWAV_NS_COURANT=2`, and with `FWAV_NS_AROUND=480 FWAV_NS_RADIAL=320`;
/// the default's runs those of `NS_LONG_MEAN_SCATTER`'s table;
/// `docs/ns-design/long-means-refined-384x256-moved.txt`): the shorter
/// step moved CT by −2.8 %, −1.4 %, −6.6 %, −14.5 %, −0.5 %, +4.5 %
/// and +0.0 % (rows 2 to 18; 6.4 % RMS, mean −3.0 %) and the efficiency
/// by 5.2 % RMS (mean −2.3 %); the refined grid moved CT by +1.1 %,
/// +4.0 %, −11.7 %, −0.0 %, −1.0 %, −8.1 % and −1.8 % (5.7 % RMS, mean
/// −2.5 %) and the efficiency by 6.0 % RMS (mean −2.4 %). Three rows
/// of seven change by less than 3 % both ways (2, 11 and 18). The
/// flows do not converge to one mean; they scatter: row 6's long mean
/// at Courant 3 (0.1650) lies above its Courant 4, Courant 2 and
/// refined grid's (0.1526, 0.1541, 0.1457); row 7's Courant 2 run
/// climbs through its five windows (0.0415 to 0.0512) where its three
/// other runs hold at 0.054–0.058. On the refined grid the initial
/// design's flow repeats (its windows within 0.19 %, against 1.45 %
/// at the default and 4.6 % at Courant 2), as the rigid section's does
/// from 320 rings (`ns2d/README.md`, "The long mean"); row 18's within
/// 0.84 %. The three changes' means (about −3 %) share the default's
/// runs, so they are not three independent shifts.
/// The runs took 582–1,057 s at Courant 2 and 721–1,112 s on the
/// refined grid (398–839 s at the default).
#[test]
#[ignore = "fails (the step refined to Courant 2: row 7's CT -14.5 %, row 6's -6.6 %, 6.4 % RMS over \
            the seven rows; the grid refined to 480 x 320: row 6's -11.7 %, row 14's -8.1 %, 5.7 % RMS; \
            docs/ns-design/long-means-refined-384x256-moved.txt), and heavy (about 3 hours: 21 \
            twelve-stroke runs, two at a time): `cargo test --release -p fwav --test integration -- --ignored --nocapture \
            discipline_ns_scatter::the_long_means_change_less_than_3_percent_when_the_step_and_the_grid_are_refined`"]
fn the_long_means_change_less_than_3_percent_when_the_step_and_the_grid_are_refined() {
    use rayon::prelude::*;
    let designs = env_designs(|| {
        [
            [11.0, 30.0, 0.0, 90.0],
            [9.0, 20.0, 0.0, 90.0],
            [13.0, 40.0, -10.0, 70.0],
            [9.0, 30.0, -10.0, 110.0],
            [11.0, 20.0, -10.0, 110.0],
            [11.0, 40.0, -10.0, 90.0],
            [13.0, 30.0, -10.0, 90.0],
        ]
        .map(FlappingKinematics::from_degrees)
        .to_vec()
    });
    let plate = default_plate();
    let long = |plate: ViscousPlate| SectionCase {
        cycles: 12,
        ..deforming_case(plate)
    };
    let cases = [
        ("default", long(plate)),
        (
            "Courant 2",
            long(ViscousPlate {
                courant: 2.0,
                ..plate
            }),
        ),
        (
            "480 x 320",
            long(ViscousPlate {
                around: 480,
                ..plate.with_radial(320)
            }),
        ),
    ];
    let runs: Vec<(usize, usize)> = (0..designs.len())
        .flat_map(|d| (0..cases.len()).map(move |c| (d, c)))
        .collect();
    let means: Vec<(f64, f64)> = runs
        .par_iter()
        .map(|&(d, c)| window_of(&stroke_means(&cases[c].1, &designs[d])[2..]))
        .collect();
    let mut worst: f64 = 0.0;
    for (d, design) in designs.iter().enumerate() {
        let at = |c: usize| means[d * cases.len() + c];
        let default = at(0);
        for (c, (name, _)) in cases.iter().enumerate().skip(1) {
            let refined = at(c);
            let change = (refined.0 / default.0 - 1.0, refined.1 / default.1 - 1.0);
            println!(
                "{:?}: default CT {:.4} efficiency {:.4}; {name} {:.4} {:.4} ({:+.1} %, {:+.1} %)",
                design.degrees(),
                default.0,
                default.1,
                refined.0,
                refined.1,
                100.0 * change.0,
                100.0 * change.1
            );
            worst = worst.max(change.0.abs()).max(change.1.abs());
        }
    }
    assert!(worst < 0.03, "the largest change {:.1} %", 100.0 * worst);
}
