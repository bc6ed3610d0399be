//! The Navier–Stokes section model's scores in the aerodynamic discipline
//! measured on the default FWAV section at the default resolution: what
//! an evaluation and a discipline run cost, and the discipline's L18 rows
//! against their records (docs/ns-design), which give one evaluation's
//! scatter as the step's change. The benchmarks are heavy (minutes to
//! half an hour): ignored, run by name (`ns2d/README.md`, "Speed" and "The
//! evaluation's window", quotes their figures). How the scores scatter
//! otherwise (window to window, with the step, the spin-up, a shorter
//! evaluation, against the long means) is `discipline_ns_scatter`; the
//! setting-up of the cases they share is here.

use fwav::aero2d::viscous::ViscousSection;
use fwav::aeroelastic::FlappingKinematics;
use fwav::config::SystemConfig;
use fwav::discipline::cache::EvaluationCache;
use fwav::discipline::section::SectionCase;
use fwav::discipline::section_model::{ViscousPlate, NS_WINDOW_SCATTER};

use crate::discipline_ns::ns_case;
use crate::machine_time::Stopwatch;
use crate::viscous_default_section::env_thickness;

/// The NS model of `plate` on the default FWAV section, deforming as the
/// built-in design's first system analysis found
/// (`tests/data/fwav_cycle1_section.json`).
pub(crate) fn deforming_case(plate: ViscousPlate) -> SectionCase {
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
pub(crate) fn default_plate() -> ViscousPlate {
    ViscousPlate::new(ViscousSection::DEFAULT_THICKNESS)
}

/// The design of `FWAV_NS_DESIGN` ("13,20,0,110": Hz and degrees), or
/// the built-in initial kinematics.
pub(crate) fn env_design() -> FlappingKinematics {
    std::env::var("FWAV_NS_DESIGN").map_or(FlappingKinematics::INITIAL, |v| parse_design(&v))
}

/// The designs of `FWAV_NS_DESIGNS` ([`parse_designs`]), or
/// `otherwise`'s.
pub(crate) fn env_designs(
    otherwise: impl FnOnce() -> Vec<FlappingKinematics>,
) -> Vec<FlappingKinematics> {
    std::env::var("FWAV_NS_DESIGNS").map_or_else(|_| otherwise(), |v| parse_designs(&v))
}

/// Designs written "9,20,0,90;11,40,-10,90" ([`parse_design`]'s, apart
/// by `;`).
pub(crate) fn parse_designs(text: &str) -> Vec<FlappingKinematics> {
    text.split(';').map(parse_design).collect()
}

/// A design written "13,20,0,110" (Hz and degrees).
pub(crate) fn parse_design(text: &str) -> FlappingKinematics {
    let x: Vec<f64> = text.split(',').map(|x| x.trim().parse().unwrap()).collect();
    FlappingKinematics::from_degrees([x[0], x[1], x[2], x[3]])
}

/// The default plate, its thickness, rings, nodes round and Courant
/// number replaced by `FWAV_NS_THICKNESS` (chords), `FWAV_NS_RADIAL` (the
/// grid refined or coarsened as a whole,
/// [`fwav::aero2d::viscous::ViscousSection::with_radial`]),
/// `FWAV_NS_AROUND` and `FWAV_NS_COURANT` where set; `FWAV_NS_FAR=none`
/// for the exponential stretching throughout (the default before
/// 2026-12-05, on 320 rings).
pub(crate) fn env_plate() -> ViscousPlate {
    let default = ViscousPlate::new(env_thickness());
    let radial = std::env::var("FWAV_NS_RADIAL").map_or(default.radial, |v| v.parse().unwrap());
    let resized = default.with_radial(radial);
    let far = match std::env::var("FWAV_NS_FAR").as_deref() {
        Ok("none") => None,
        _ => resized.far,
    };
    ViscousPlate {
        far,
        around: std::env::var("FWAV_NS_AROUND").map_or(default.around, |v| v.parse().unwrap()),
        courant: std::env::var("FWAV_NS_COURANT").map_or(default.courant, |v| v.parse().unwrap()),
        ..resized
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
/// With each plate sample's map its change of shape's moved by its rigid
/// part (2026-12-06, commit `d202268`; the machine otherwise idle but for
/// editing): **1,720 s**, 19 evaluations. The rows moved from
/// `l18-384x256.txt` by 5.02 % RMS in CT (mean −2.2 %) and 4.48 % in
/// efficiency: less than two evaluations at another step differ
/// (7.50 % and 6.36 %, below). Best row 13 Hz, ±40°, −10°, 70° again
/// (2.598); ANOM 13 Hz, ±30°, 0°, 70°; frequency level means 1.50, 1.92,
/// 2.40 (docs/ns-design, `l18-384x256-moved.txt`). After the moving
/// grid's trims (2026-12-06, the binary of `19df000`: the same flows to
/// the bit, the rows and the best row the same to every digit printed;
/// the machine otherwise idle, on a day when the rigid evaluation, whose
/// code did not change, took 57.2 s, 64.9 s and 68.2 s in the
/// hours round it against its quiet 54.3 s that morning): **1,671 s**.
///
/// On a plate as thick as the vehicle's leading edge
/// (`FWAV_NS_THICKNESS=0.01`, 2026-12-05) the rows are compared with
/// that plate's own at Courant 3 (docs/ns-design,
/// `l18-384x256-t0.01.txt`: 3,033 s, best row 13 Hz, ±20°, 0°, 110°). At
/// Courant 4 (2,234 s, the same best row) they moved by 23.9 % RMS in CT
/// and 23.1 % in efficiency: 16.9 % and 16.3 % an evaluation, three to
/// four times the 0.04 c plate's (`ns2d/README.md`, "The plate's thickness").
#[test]
#[ignore = "benchmark (25 to 35 min: 1,671 s at Courant 3 on 2026-12-06; over the issue's 10): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scores::ns_discipline_benchmark`"]
fn ns_discipline_benchmark() {
    use fwav::discipline::kinematic::{optimize, DesignSpace, Weights};
    use fwav::optimize::nsga2::Nsga2Config;
    let plate = env_plate();
    let case = deforming_case(plate);
    let cache = EvaluationCache::new();
    let clock = Stopwatch::start();
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
    let lap = clock.lap();
    let seconds = lap.wall;
    println!(
        "NS discipline: {} evaluations in {lap}; chosen {:?}",
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
/// 0.6 mm on the 60 mm chord; `ns2d/README.md`, "The plate's thickness").
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
/// day against 57.3 s with slower code on 2026-12-03: withdrawn (`ns2d/README.md`,
/// "Speed").
///
/// On the default 384 x 256 with the far field coarsened (2026-12-05,
/// the machine otherwise idle): **rigid 55.7 s, deforming 81.0 s** (CT
/// 0.0881, efficiency 0.0339: +3.6 % and +2.7 % from 384 x 320's, within
/// one evaluation's scatter, `NS_WINDOW_SCATTER`; rigid CT 0.0710). The
/// rigid evaluation meets the 60 s; the deforming one, which the
/// discipline runs, does not.
///
/// At Courant 4 (`FWAV_NS_COURANT=4`, 2026-12-05, the machine otherwise
/// idle): rigid 47.5 s, deforming 70.1 s (CT 0.0890, efficiency 0.0341)
/// against 56.5 s and 84.0 s at the default 3 run next: a sixth off, not
/// the quarter the Courant numbers' ratio would give, and still over the
/// 60 s (`ns2d/README.md`, "A longer step").
///
/// With each plate sample's map its change of shape's moved by its
/// rigid part and the grid's rigid part taken off by its streamfunction
/// (2026-12-06, the machine otherwise idle): rigid 52.5 s (the same flow
/// to the bit), deforming 93.1 s (CT 0.0898, efficiency 0.0345: +1.9 %
/// and +1.8 %), against 55.3 s and 85.6 s for the binary of before run
/// the same hour; a first run gave 111.2 s deforming, the same flow, in
/// a slower minute. Four strokes on one thread, side by side: 154.4 s
/// against 144.0 s (+7 %). With the moving grid's own passes trimmed
/// (2026-12-06, the same flow to the bit; `fwav-ns2d`'s
/// `flow/deforming.rs`), run in turn with the binary of before in a noisy
/// hour: 58.2 s and 95.0 s against 68.0 s and 96.5 s; three deforming
/// strokes on one thread, the two side by side, 109.1 s and 107.6 s
/// against 123.9 s and 122.5 s (−12 %). Run again later that day with
/// the machine otherwise idle: **rigid 54.3 s, deforming 82.2 s** (the
/// same flows to the bit: CT 7.10436678696318e-2 and
/// 8.980278828971328e-2), the deforming evaluation 11.7 % sooner than the
/// quiet 93.1 s before the trim and 1.37 times the 60 s. After
/// the swept fluxes' parts were kept apart (`NodeFlux`, the binary of
/// `19df000`; −4.2 % on three deforming strokes on one thread, side by
/// side: `ns2d/README.md`, "Speed"), in a slow hour: rigid 68.2 s,
/// deforming 92.6 s, the same flows to the bit. Later, the machine
/// otherwise idle (the binary of `a44c85a`, the same flows to the bit),
/// twice in a row: **rigid 51.2 s, deforming 77.0 s** (1.28 times the
/// issue's 60 s), and rigid 51.8 s, deforming 86.1 s the run before.
/// On 2026-12-07 (the same flows to the bit) 74.0 s and 119.1 s, then
/// 66.1 s and 95.5 s with 0.3 s stolen by the host and 1.91 cores' CPU
/// time each: each run prints what the machine gave it
/// ([`Stopwatch`]; `ns2d/README.md`, "Slow hours are not the
/// hypervisor's").
///
/// The plate is `env_plate`'s: `FWAV_NS_THICKNESS` sets its thickness
/// (chords; `ns2d/README.md`, "The plate's thickness"), `FWAV_NS_COURANT` the
/// step's Courant number, `FWAV_NS_RADIAL` and `FWAV_NS_AROUND` the grid.
#[test]
#[ignore = "benchmark (2 to 3 min); fails the issue's 60 s deforming (77.0 s on 2026-12-06, the machine idle, after the moving grid's trims; rigid 51.2 s): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scores::ns_deforming_evaluation_benchmark`"]
fn ns_deforming_evaluation_benchmark() {
    let rigid = ns_case(env_plate());
    let deforming = deforming_case(env_plate());
    let design = FlappingKinematics::INITIAL;
    let mut laps = Vec::new();
    let mut results = Vec::new();
    for case in [&rigid, &deforming] {
        let clock = Stopwatch::start();
        results.push(case.evaluate(&design).unwrap());
        laps.push(clock.lap());
    }
    for (name, (r, lap)) in ["rigid", "deforming"].iter().zip(results.iter().zip(&laps)) {
        println!(
            "{name}: {lap}, CT {:.4}, CP {:.4}, efficiency {:.4}, CT change {:+.4} \
             (to the bit: CT {:e}, CP {:e})",
            r.ct, r.cp, r.efficiency, r.ct_change, r.ct, r.cp
        );
    }
    assert!(
        laps[1].wall < 60.0,
        "the issue's 60 s: {:.1} s",
        laps[1].wall
    );
}

/// The deforming default section's deformation taken three ways, at the
/// built-in initial kinematics ([`ViscousPlate::shape_tolerance`],
/// `ViscousSection::run_deflecting`): all on the moving grid (`None`,
/// the default), or its rigid part (heave ±0.13 c, pitch ±1.4°) as the
/// frame's motion and its change of shape (at most 1.05e-3 c) on the
/// moving grid (`Some(0)`) or left out (`Some(0.01)`); and the rigid
/// part alone on the moving grid (each sample's straight mid-line
/// carried by its fit) or as the frame, its heave alone (the fit's
/// translation, no turn) either way, and twice the change of shape.
/// Prints the first stroke's means (and strokes 3–4 as the discipline
/// scores them when there are four), with each run's time.
/// `FWAV_NS_CYCLES` sets the strokes (at least 3, the fewest an
/// evaluation takes), `FWAV_NS_ONLY` runs one way (its name as
/// printed), `env_plate`'s variables set the plate.
///
/// Measured (2026-12-06, 384 × 256, three strokes, one thread each,
/// beside other runs; the first stroke's CT and CP; `ns2d/README.md`, "The
/// deformation's rigid part"), since each plate sample's map is its
/// change of shape's moved by its rigid part (`ViscousSection`'s
/// deformation) and the moving grid's rigid part is taken off by its
/// streamfunction (`fwav-ns2d`):
///
/// | way | Courant 3 | Courant 1.5 | Courant 0.75 |
/// | --- | --- | --- | --- |
/// | all on the moving grid | 0.09966, 2.7243 (125.5 s) | 0.10094, 2.7168 | 0.10131, 2.7155 |
/// | shape on the moving grid | 0.09973, 2.7248 | 0.10091, 2.7171 | 0.10131, 2.7155 |
/// | shape left out | 0.09785, 2.7306 (76.8 s) | 0.09788, 2.7267 | |
/// | rigid part alone, on the moving grid | 0.09775, 2.7302 | | |
/// | rigid part alone as the frame | 0.09788, 2.7303 | | 0.09841, 2.7235 |
/// | twice the shape's change | 0.10165, 2.7215 | | |
/// | the heave alone, on the moving grid | 0.09085, 2.7242 | | |
/// | the heave alone as the frame | 0.09131, 2.7288 | | |
///
/// (The heave alone and twice the shape's change were measured before
/// the two changes; the frame's ways did not move by them.) Before them,
/// all on the moving grid gave 0.10376, 0.10423 and 0.10343, and the
/// rigid part alone on the moving grid 0.10200, 0.09969 and 0.09882:
/// each sample's map fitted on its own put the rigid part 4.5 % above
/// the frame's at Courant 3, an error of the fitted maps, not of the
/// moving grid. The two ways are now one: the default's CT within 0.07 %
/// of the split way's, the rigid part alone within 0.13 % of the
/// frame's. The change of shape moves CT by 3.7 % at the step's limit
/// (about 0.1015): it may not be left out. Run whole at the default
/// plate, it checks the first stroke's CT: the default within 0.5 % of
/// the rigid part as the frame with the shape on the moving grid, the
/// rigid part alone on the moving grid within 0.5 % of it as the frame
/// and within 0.2 % of the shape left out, the shape's effect over 1 %
/// and twice the change's 1.6 to 2.4 times it (measured 1.92 % and
/// 3.88 %: 2.02 times). Run whole before the two changes (2026-12-06,
/// two threads, the machine otherwise idle): 535 s, the checks then
/// passed; three strokes took 54.2 s with the shape left out against
/// 64.0 s all on the moving grid.
#[test]
#[ignore = "benchmark (about 9 min for the eight ways): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns_scores::ns_deflected_evaluation_benchmark`"]
fn ns_deflected_evaluation_benchmark() {
    let cycles = std::env::var("FWAV_NS_CYCLES").map_or(3, |v| v.parse().unwrap());
    let plate = env_plate();
    let design = FlappingKinematics::INITIAL;
    let real = deforming_case(plate).deformation;
    let fitted: Vec<Vec<[f64; 2]>> = real.iter().map(|s| rigid_fit(s, true)).collect();
    let heaved: Vec<Vec<[f64; 2]>> = real.iter().map(|s| rigid_fit(s, false)).collect();
    let doubled: Vec<Vec<[f64; 2]>> = real
        .iter()
        .zip(&fitted)
        .map(|(r, f)| {
            r.iter()
                .zip(f)
                .map(|(a, b)| [2.0 * a[0] - b[0], 2.0 * a[1] - b[1]])
                .collect()
        })
        .collect();
    let ways = [
        ("shape left out", Some(0.01), &real),
        ("shape on the moving grid", Some(0.0), &real),
        ("all on the moving grid", None, &real),
        ("rigid part alone, on the moving grid", None, &fitted),
        (
            "rigid part alone as the frame, on the moving grid",
            Some(0.0),
            &fitted,
        ),
        (
            "twice the shape's change, on the moving grid",
            Some(0.0),
            &doubled,
        ),
        ("the heave alone, on the moving grid", None, &heaved),
        ("the heave alone as the frame", Some(0.0), &heaved),
    ];
    let only = std::env::var("FWAV_NS_ONLY").ok();
    let mut first_ct = Vec::new();
    for (name, shape_tolerance, deformation) in ways {
        if only.as_deref().is_some_and(|o| o != name) {
            continue;
        }
        let case = SectionCase {
            cycles,
            deformation: deformation.clone(),
            ..deforming_case(ViscousPlate {
                shape_tolerance,
                ..plate
            })
        };
        let clock = std::time::Instant::now();
        let (history, _) = case.history(&design).unwrap();
        let seconds = clock.elapsed().as_secs_f64();
        let strokes = crate::viscous_default_section::stroke_means(&history, cycles);
        print!(
            "{name}: {seconds:.1} s; first stroke CT {:.5}, CP {:.5}",
            strokes[0].0, strokes[0].1
        );
        if cycles >= 4 {
            let (ct, efficiency) = crate::viscous_default_section::window_of(&strokes[2..4]);
            print!("; strokes 3-4 CT {ct:.5}, efficiency {efficiency:.5}");
        }
        println!();
        first_ct.push(strokes[0].0);
    }
    if only.is_some() || plate != default_plate() {
        return;
    }
    // The table's claims, on the first stroke's CT: the two ways are one
    // (the whole deformation on the moving grid and the rigid part as
    // the frame, with the change of shape or without it); the rigid part
    // alone as the frame is the section with its change of shape left
    // out (one motion, two ways); the change of shape matters (over 1 %)
    // and its effect is about linear in it (twice the change, twice the
    // effect, within a fifth).
    let [left_out, on_grid, default, rigid_grid, rigid_frame, twice, ..] = first_ct[..] else {
        unreachable!("eight ways")
    };
    assert!((default / on_grid - 1.0).abs() < 5e-3, "{first_ct:?}");
    assert!(
        (rigid_grid / rigid_frame - 1.0).abs() < 5e-3,
        "{first_ct:?}"
    );
    assert!((rigid_frame / left_out - 1.0).abs() < 2e-3, "{first_ct:?}");
    let (once, double) = (on_grid / left_out - 1.0, twice / left_out - 1.0);
    assert!(once > 0.01, "{first_ct:?}");
    assert!((double / once - 2.0).abs() < 0.4, "{first_ct:?}");
}

/// The 18 rows of the aerodynamic discipline's L18 array over the built-in
/// design space (`DesignSpace::l18_designs`, as the discipline lays them
/// out; the first cycle's are listed in `docs/ns-design/l18-384x256.txt`).
pub(crate) fn l18_rows() -> Vec<FlappingKinematics> {
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

/// `sample`'s straight mid-line carried and, if `turned`, turned by its
/// rigid fit.
pub(crate) fn rigid_fit(sample: &[[f64; 2]], turned: bool) -> Vec<[f64; 2]> {
    use fwav::aero2d::viscous::RigidDeflection;
    use fwav_ns2d::Complex64;
    let points: Vec<(f64, f64)> = sample.iter().map(|p| (p[0], p[1])).collect();
    let d = RigidDeflection::fit(std::slice::from_ref(&points), 0.5, 1.0)
        .unwrap()
        .state(0.0);
    let turn = Complex64::from_polar(1.0, if turned { d.angle } else { 0.0 });
    let mut s = 0.0;
    let mut out = Vec::new();
    for (i, p) in points.iter().enumerate() {
        if i > 0 {
            s += (p.0 - points[i - 1].0).hypot(p.1 - points[i - 1].1);
        }
        let z = Complex64::new(0.5, 0.0) + d.translation + turn * (s - 0.5);
        out.push([z.re, z.im]);
    }
    out
}
