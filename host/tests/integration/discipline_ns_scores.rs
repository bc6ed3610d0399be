//! The Navier–Stokes section model's scores in the aerodynamic discipline
//! measured on the default FWAV section at the default resolution: what
//! an evaluation and a discipline run cost, how much the scores scatter
//! from evaluation to evaluation, and how they move with the time step
//! and a coarser spin-up. All heavy (minutes to half an hour): ignored
//! benchmarks, run by name (the README, "Speed" and "The evaluation's
//! window", quotes their figures).

use fwav::aero2d::viscous::ViscousSection;
use fwav::aeroelastic::FlappingKinematics;
use fwav::config::SystemConfig;
use fwav::discipline::cache::EvaluationCache;
use fwav::discipline::section::SectionCase;
use fwav::discipline::section_model::{
    SectionFlowModel, ViscousPlate, NS_LONG_MEAN_SCATTER, NS_WINDOW_SCATTER,
};

use crate::discipline_ns::ns_case;
use crate::viscous_default_section::{env_thickness, mean, standard_deviation, window_of};

/// The NS model of `plate` on the default FWAV section, deforming as the
/// built-in design's first system analysis found
/// (`tests/data/fwav_cycle1_section.json`).
fn deforming_case(plate: ViscousPlate) -> SectionCase {
    use fwav::aeroelastic::handoff::section::SectionFile;
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/fwav_cycle1_section.json");
    SectionCase {
        deformation: SectionFile::read(&path).unwrap().samples,
        ..ns_case(plate)
    }
}

/// The default plate ([`ViscousSection::DEFAULT_THICKNESS`] at the
/// default resolution): the declared scatter and the recorded rows are
/// its.
fn default_plate() -> ViscousPlate {
    ViscousPlate::new(ViscousSection::DEFAULT_THICKNESS)
}

/// The design of `FWAV_NS_DESIGN` ("13,20,0,110": Hz and degrees), or
/// the built-in initial kinematics.
fn env_design() -> FlappingKinematics {
    std::env::var("FWAV_NS_DESIGN").map_or(FlappingKinematics::INITIAL, |v| parse_design(&v))
}

/// A design written "13,20,0,110" (Hz and degrees).
fn parse_design(text: &str) -> FlappingKinematics {
    let x: Vec<f64> = text.split(',').map(|x| x.trim().parse().unwrap()).collect();
    FlappingKinematics::from_degrees([x[0], x[1], x[2], x[3]])
}

/// The default plate, its thickness, rings and Courant number replaced
/// by `FWAV_NS_THICKNESS` (chords), `FWAV_NS_RADIAL` (the grid refined
/// or coarsened as a whole,
/// [`fwav::aero2d::viscous::ViscousSection::with_radial`]) and
/// `FWAV_NS_COURANT` where set; `FWAV_NS_FAR=none` for the exponential
/// stretching throughout (the default before 2026-12-05, on 320 rings).
fn env_plate() -> ViscousPlate {
    let default = ViscousPlate::new(env_thickness());
    let radial = std::env::var("FWAV_NS_RADIAL").map_or(default.radial, |v| v.parse().unwrap());
    let far = match std::env::var("FWAV_NS_FAR").as_deref() {
        Ok("none") => None,
        _ => default.far.map(|f| f.scaled(default.radial, radial)),
    };
    ViscousPlate {
        radial,
        far,
        courant: std::env::var("FWAV_NS_COURANT").map_or(default.courant, |v| v.parse().unwrap()),
        ..default
    }
}

/// The RMS relative change of the rows' net CT and net efficiency from
/// those listed in `file` (docs/ns-design): `l18-384x256.txt`, the
/// default grid's at Courant 3 (2026-12-05), or `l18-384x320.txt`, the
/// exponential 384 x 320's (the default until then), the first cycle's
/// rows of the NS design run on the same section, whose efficiency was
/// `η / (1 + η)` of today's (`exponential_power`: taken so).
fn rows_against(
    file: &str,
    exponential_power: bool,
    runs: &[fwav::discipline::kinematic::Evaluated],
) -> (f64, f64) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../docs/ns-design")
        .join(file);
    let text = std::fs::read_to_string(&path).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .filter_map(|l| {
            let cells: Vec<f64> = l.split('|').filter_map(|c| c.trim().parse().ok()).collect();
            (cells.len() >= 9).then_some(cells)
        })
        .collect();
    assert_eq!(rows.len(), runs.len(), "{}", path.display());
    let (mut thrust, mut efficiency) = (0.0, 0.0);
    for (row, run) in rows.iter().zip(runs) {
        assert_eq!(run.design.degrees(), [row[1], row[2], row[3], row[4]]);
        let r = run.result.as_ref().unwrap();
        let listed = if exponential_power {
            row[6] / (1.0 + row[6])
        } else {
            row[6]
        };
        thrust += (r.ct_net / row[5] - 1.0).powi(2);
        efficiency += (r.efficiency_net / listed - 1.0).powi(2);
    }
    let n = rows.len() as f64;
    ((thrust / n).sqrt(), (efficiency / n).sqrt())
}

/// The speed target for the discipline: the whole aerodynamic
/// discipline (the initial design, the 18 L18 rows and the ANOM and RSM
/// confirmations, each a 4-stroke Navier–Stokes evaluation at the default
/// resolution, in parallel) on the built-in FWAV's mid-span section, the
/// 4 % plate deforming as the built-in design's first system analysis
/// found (`tests/data/fwav_cycle1_section.json`), from the built-in
/// initial design, equal weights, under 10 minutes on this 2-core
/// machine: the work of the first cycle's discipline of `fwav design`
/// with `section_model = "ns"` (885 s in the deforming design run of
/// docs/ns-design, commit c35523c, on 256 × 160 before the step control
/// that lengthens the step where the flow allows). Measured on the
/// default 384 × 240 at Courant 3 (2026-12-03): 1,487 s for 19
/// evaluations, in an hour when this machine ran slow (the deforming
/// evaluation of `ns_deforming_evaluation_benchmark` took 84.9 s then,
/// 57.3 s half an hour before; scaled, about 1,000 s). Before, 924 s on
/// 384 × 160 at Courant 1.5 and 494 s on 256 × 160. Fails.
///
/// At another step (`FWAV_NS_COURANT`) it compares the rows with the
/// default's. On the exponential 384 x 320 (the default then; the NS
/// design run's first cycle, docs/ns-design, `l18-384x320.txt`): at
/// Courant 4 (2026-12-04) the 19 evaluations took 1,712 s, and the rows'
/// CT moved by 5.59 % RMS and their efficiency by 4.95 %, so one
/// evaluation's scatter was 3.95 % and 3.50 % (`NS_WINDOW_SCATTER` until
/// 2026-12-05; on the far-coarsened default, below). The choice
/// moved with them: best row 13 Hz, ±40°, −10°, plane 70° (2.595; at
/// Courant 3 13 Hz, ±30°, 0°, 70°, 2.580), ANOM 13 Hz, ±40°, 10°, 110°
/// (Courant 3: ±30°, 0°, 110°); frequency level means 1.56, 1.93, 2.47
/// (1.61, 2.05, 2.55).
///
/// With the input power fixed (2026-12-04, `aero2d/viscous/march.rs`),
/// at the default step: 2,421 s for 20 evaluations; each row's efficiency
/// is the earlier listing's `η / (1 + η)` (row 2: 0.0330 against 0.0341)
/// and its CT the same to four digits but on the four rows whose flow
/// wanders (rows 4, 14, 16, 18; row 14 0.1279 against 0.1216: the
/// thread-count fix of the same day changed their rounding); best row 13
/// Hz, ±40°, 10°, 110° (2.709), where the design run, judging the rows
/// against its own vehicle's actuator, took 13 Hz, ±30°, 0°, 70°.
/// After the step's passes were fused and the deforming grid's trimmed
/// (2026-12-04, the same flow to the bit) it took 1,950 s (2026-12-05,
/// a slow hour: the deforming evaluation benchmark took 110 s then), the
/// same rows to the digits listed (row 2 CT 0.0850, efficiency 0.0330;
/// row 14 CT 0.1279) and the same best row (2.709). The rows step on the
/// pool's workers, one each, so the workers kept awake of `fwav-ns2d`'s
/// `awake_pool.rs` do not apply here.
///
/// On the default 384 x 256 with the far field coarsened (2026-12-05,
/// the machine otherwise idle): **1,507 s** (−23 %). Against the
/// exponential 384 x 320's rows of the file the rows' CT moved by 7.16 %
/// RMS (mean +1.3 %; rows 1 and 18 +16 %, row 14 −12 %) and their
/// efficiency, taken in today's definition (the file's `η / (1 + η)`),
/// by 5.84 % (mean +0.7 %; 6.40 % against the file's values as
/// listed, as this benchmark printed before it took them so), a little
/// more than the step's change moved them on that grid (5.59 % and
/// 4.95 %), with the mean within its standard error (7.2 % / √18 =
/// 1.7 %). Best row 13 Hz, ±40°, −10°, plane 70° (2.707; the
/// exponential grid's, the same day: 13 Hz, ±40°, 10°, 110°, 2.709);
/// ANOM 13 Hz, ±30°, −10°, 70°; frequency level means 1.58, 1.96, 2.50.
/// Its rows are docs/ns-design's `l18-384x256.txt`, which this
/// benchmark now compares with. At Courant 4 on this grid (1,086 s, 19
/// evaluations) the rows moved from them by 7.50 % RMS in CT and 6.36 %
/// in efficiency: `NS_WINDOW_SCATTER` (5.30 % and 4.50 %) is these over
/// √2, and the Courant-4 run on the default grid checks it within 10 %.
///
/// On a plate as thick as the vehicle's leading edge
/// (`FWAV_NS_THICKNESS=0.01`, 2026-12-05) the rows are compared with
/// that plate's own at Courant 3 (docs/ns-design,
/// `l18-384x256-t0.01.txt`: 3,033 s, best row 13 Hz, ±20°, 0°, 110°). At
/// Courant 4 (2,234 s, the same best row) they moved by 23.9 % RMS in CT
/// and 23.1 % in efficiency: 16.9 % and 16.3 % an evaluation, three to
/// four times the 0.04 c plate's (README, "The plate's thickness").
#[test]
#[ignore = "benchmark (25 to 35 min: 1,507 s at Courant 3 on 2026-12-05; over the issue's 10): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scores::ns_discipline_benchmark`"]
fn ns_discipline_benchmark() {
    use fwav::discipline::kinematic::{optimize, DesignSpace, Weights};
    use fwav::optimize::nsga2::Nsga2Config;
    let plate = env_plate();
    let case = deforming_case(plate);
    let cache = EvaluationCache::new();
    let clock = std::time::Instant::now();
    let result = optimize(
        &case,
        &DesignSpace::fwav(),
        SystemConfig::default().kinematics(),
        Weights {
            thrust: 1.0,
            efficiency: 1.0,
        },
        &Nsga2Config::default(),
        &cache,
    )
    .unwrap();
    let seconds = clock.elapsed().as_secs_f64();
    println!(
        "NS discipline: {} evaluations in {seconds:.1} s; chosen {:?}",
        cache.len(),
        result.chosen.map(|i| &result.candidates[i].method)
    );
    // Each row's scores, to set beside docs/ns-design's listing.
    for (row, run) in result.runs.iter().enumerate() {
        if let Ok(r) = &run.result {
            println!(
                "row {}: {:?}: CT {:.4}, CP {:.4}, efficiency {:.4}",
                row + 1,
                run.design.degrees(),
                r.ct,
                r.cp,
                r.efficiency
            );
        }
    }
    println!("level means: {:?}", result.level_means);
    for c in &result.candidates {
        println!(
            "{}: {:?} combined {:?}",
            c.method,
            c.confirmation.design.degrees(),
            c.combined
        );
    }
    assert!(result.runs.iter().all(|e| e.result.is_ok()));
    let default = default_plate();
    // Each plate's rows against its own record: the default plate's on
    // the default grid at Courant 3 (at another step the declared
    // scatter's measurement) and on the exponential 384 x 320 (the
    // default until 2026-12-05: the far field's effect); the vehicle's
    // leading edge's at Courant 3.
    let records: &[(&str, bool)] =
        if plate.thickness == THIN_PLATE && plate.thickness != default.thickness {
            &[(THIN_PLATE_ROWS, false)]
        } else {
            &[("l18-384x256.txt", false), ("l18-384x320.txt", true)]
        };
    let one = |rms: f64| rms / std::f64::consts::SQRT_2;
    let changes: Vec<(f64, f64)> = records
        .iter()
        .map(|&(file, exponential_power)| {
            let (thrust, efficiency) = rows_against(file, exponential_power, &result.runs);
            println!(
                "against the rows of {file}: RMS change CT {:.2} %, efficiency {:.2} % \
                 (one evaluation's scatter, if only the step differs: {:.2} % and {:.2} %)",
                100.0 * thrust,
                100.0 * efficiency,
                100.0 * one(thrust),
                100.0 * one(efficiency)
            );
            (thrust, efficiency)
        })
        .collect();
    if plate != default {
        // The default plate and grid at another step.
        let only_the_step_differs = ViscousPlate {
            courant: default.courant,
            ..plate
        } == default;
        if plate.courant == 4.0 && only_the_step_differs {
            let (thrust, efficiency) = changes[0];
            for (measured, declared) in [
                (one(thrust), NS_WINDOW_SCATTER.0),
                (one(efficiency), NS_WINDOW_SCATTER.1),
            ] {
                assert!(
                    (declared / measured - 1.0).abs() < 0.1,
                    "declared {declared:.4}, measured {measured:.4}"
                );
            }
        }
        return;
    }
    assert!(seconds < 600.0, "{seconds:.1} s against the issue's 600 s");
}

/// The plate as thick as the vehicle's carbon leading edge (chords:
/// 0.6 mm on the 60 mm chord; README, "The plate's thickness").
const THIN_PLATE: f64 = 0.01;

/// Its first-cycle L18 rows at Courant 3 (docs/ns-design).
const THIN_PLATE_ROWS: &str = "l18-384x256-t0.01.txt";

/// One Navier–Stokes evaluation of the default FWAV section at the
/// default resolution, the 4 % plate deforming as the default design's
/// first system analysis found (`host/tests/data/fwav_cycle1_section.json`,
/// 40 samples of 53 points: a heave of ±0.13 chords from the wing's
/// bending, a pitch of about ±1.4° and little camber) beside the rigid
/// plate, at the built-in initial kinematics: the cost of the moving grid
/// and what the deformation changes. Measured on the default 384 x 320
/// (2026-12-03, a slow hour): rigid 118.3 s, deforming 190.4 s (CT
/// 0.0850, efficiency 0.0341), which fails the 60 s; about 43 s
/// and 77 s in a normal hour (on 384 x 240: 31.9 s and 57.3 s). With the
/// step's passes fused and the ring sweep's set-up reordered (2026-12-04,
/// the same flow to the bit, about 6.5 % sooner run alternately): 84.7 s
/// and 127.4 s, then 80.7 s and 130.1 s, in slow hours (135.5 s and
/// 209.7 s before, in a slower one). With the deforming grid's own
/// passes trimmed (2026-12-04, the same flow to the bit): 80.7 s and
/// 116.4 s in a slow hour (79.0 s and 120.0 s before the last two of
/// them, the same hour), deforming 1.44 times rigid against 1.61: about
/// 62 s in a normal hour. With the pool's workers kept awake through each
/// step (2026-12-05, `fwav-ns2d`'s `awake_pool.rs`, the same flow to the
/// bit), run in turn with the binary of before in a slow hour: 68.8 s and
/// 105.0 s against 75.9 s and 110.2 s (111.7 s deforming at the hour's
/// start). With `FaceAreas` removed (the same flow to the bit), on the
/// machine otherwise idle (2026-12-05): 67.5 s and 99.3 s. The "normal
/// hour" figures above were estimates scaled from 384 x 240 by the
/// rigid ratio 1.34; deforming, 320 rings cost 1.47 times 240 (99.0 s
/// against 67.2 s the same hour), and 384 x 240 itself took 67.2 s that
/// day against 57.3 s with slower code on 2026-12-03: withdrawn (README,
/// "Speed").
///
/// On the default 384 x 256 with the far field coarsened (2026-12-05,
/// the machine otherwise idle): **rigid 55.7 s, deforming 81.0 s** (CT
/// 0.0881, efficiency 0.0339: +3.6 % and +2.7 % from 384 x 320's, within
/// one evaluation's scatter, `NS_WINDOW_SCATTER`; rigid CT 0.0710). The
/// rigid evaluation meets the 60 s; the deforming one, which the
/// discipline runs, does not.
///
/// `FWAV_NS_THICKNESS` sets the plate's thickness (chords; README, "The
/// plate's thickness").
#[test]
#[ignore = "benchmark (2 to 3 min); fails the issue's 60 s deforming (81.0 s on 2026-12-05; rigid 55.7 s): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scores::ns_deforming_evaluation_benchmark`"]
fn ns_deforming_evaluation_benchmark() {
    let rigid = ns_case(ViscousPlate::new(env_thickness()));
    let deforming = deforming_case(ViscousPlate::new(env_thickness()));
    let design = FlappingKinematics::INITIAL;
    let mut seconds = Vec::new();
    let mut results = Vec::new();
    for case in [&rigid, &deforming] {
        let clock = std::time::Instant::now();
        results.push(case.evaluate(&design).unwrap());
        seconds.push(clock.elapsed().as_secs_f64());
    }
    for (name, (r, s)) in ["rigid", "deforming"]
        .iter()
        .zip(results.iter().zip(&seconds))
    {
        println!(
            "{name}: {s:.1} s, CT {:.4}, CP {:.4}, efficiency {:.4}, CT change {:+.4} \
             (to the bit: CT {:e}, CP {:e})",
            r.ct, r.cp, r.efficiency, r.ct_change, r.ct, r.cp
        );
    }
    assert!(seconds[1] < 60.0, "the issue's 60 s: {:.1} s", seconds[1]);
}

/// How much the Navier–Stokes scores of the deforming default section
/// scatter from window to window of one run, which must be less than
/// what two evaluations differ by (`section_model::NS_WINDOW_SCATTER`,
/// taken from the L18 rows at two steps: `ns_discipline_benchmark`): 12
/// strokes on the full grid (no spin-up), deforming as the default
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
/// (efficiency) above Courant 3's (README, "Speed"). At L18 row 14 (11
/// Hz, ±40°, −10°, plane 90°; `RAYON_NUM_THREADS=1`, 2026-12-04): CT
/// 0.1171, 0.1144, 0.1245, 0.1029, 0.1061 (7.7 %; efficiency 7.0 %),
/// 754 s, at Courant 3 (above the declared scatter: not checked there),
/// and 0.1090, 0.1035, 0.1276, 0.1297, 0.0993 (12.3 %), 581 s, at
/// Courant 4; their means agree within 0.7 % (README, "The L18 rows at
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
#[ignore = "benchmark (about 10 min in a slow hour): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scores::ns_deforming_window_scatter_benchmark`"]
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
#[ignore = "fails (CT -17 %, efficiency -16 % against the full grid's window; docs/ns-design, \"The spin-up\"), and heavy (about 3 min): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scores::a_spin_up_keeps_the_deforming_window_scores`"]
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
/// Courant 4 (`ns_discipline_benchmark` with `FWAV_NS_COURANT=4`) against
/// Courant 3 (the NS design run of docs/ns-design, cycle 1) moved CT by
/// 5.6 % RMS and up to 12.8 %; this runs the rows that moved most at a
/// step half the default's (README, "A longer step"). `FWAV_NS_CYCLES`
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
#[ignore = "benchmark (about 15 min at Courant 1.5 for four designs): `FWAV_NS_COURANT=1.5 FWAV_NS_DESIGNS=\"9,20,0,90;11,40,-10,90\" cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scores::ns_window_time_step_benchmark`"]
fn ns_window_time_step_benchmark() {
    use rayon::prelude::*;
    let plate = env_plate();
    let case = SectionCase {
        cycles: std::env::var("FWAV_NS_CYCLES").map_or(4, |v| v.parse().unwrap()),
        ..deforming_case(plate)
    };
    let designs: Vec<FlappingKinematics> = std::env::var("FWAV_NS_DESIGNS").map_or_else(
        |_| vec![FlappingKinematics::INITIAL],
        |v| v.split(';').map(parse_design).collect(),
    );
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

/// The 18 rows of the aerodynamic discipline's L18 array over the built-in
/// design space (`DesignSpace::l18_designs`, as the discipline lays them
/// out; the first cycle's are listed in `docs/ns-design/l18-384x256.txt`).
fn l18_rows() -> Vec<FlappingKinematics> {
    fwav::discipline::kinematic::DesignSpace::fwav()
        .l18_designs()
        .unwrap()
}

/// The rows the benchmarks below run are those of the record they are
/// compared with: `docs/ns-design/l18-384x256.txt`, row by row.
#[test]
fn the_l18_rows_are_the_records() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/ns-design/l18-384x256.txt");
    let text = std::fs::read_to_string(path).unwrap();
    let recorded: Vec<[f64; 4]> = text
        .lines()
        .filter_map(|line| {
            let cells: Vec<&str> = line.split('|').map(str::trim).collect();
            let row: Vec<f64> = cells
                .get(2..6)?
                .iter()
                .map(|c| c.parse().ok())
                .collect::<Option<_>>()?;
            Some([row[0], row[1], row[2], row[3]])
        })
        .collect();
    let planned: Vec<[f64; 4]> = l18_rows().iter().map(FlappingKinematics::degrees).collect();
    assert_eq!(planned, recorded);
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
            discipline_ns_scores::a_three_stroke_evaluation_keeps_the_rows_scores`"]
fn a_three_stroke_evaluation_keeps_the_rows_scores() {
    use rayon::prelude::*;
    let plate = env_plate();
    let cycles = 4;
    let case = SectionCase {
        cycles,
        ..deforming_case(plate)
    };
    let listed = std::env::var("FWAV_NS_DESIGNS").ok();
    let designs: Vec<FlappingKinematics> = listed
        .as_deref()
        .map_or_else(l18_rows, |v| v.split(';').map(parse_design).collect());
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
/// definitions (0.0335 against 0.0334 for row 1).
#[test]
#[ignore = "heavy (about 90 min: 18 four-stroke and 18 twelve-stroke runs, two at a time, \
            a round of two rows 10-13 min): \
            `cargo test --release -p fwav --test integration -- --ignored --nocapture \
            discipline_ns_scores::the_declared_scatter_agrees_with_the_rows_error_against_their_long_means`"]
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
