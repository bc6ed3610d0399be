//! The default FWAV mid-span section under the Navier–Stokes model (the
//! aerodynamic discipline's with `section_model = "ns"`: Re 12,300, 11
//! Hz, +-30 deg, a 4 % plate): what one evaluation costs at the default
//! resolution, how its first stroke converges with the wall cell, how
//! much the window the discipline scores scatters from window to window,
//! and how the evaluation's scores and the long mean converge with the
//! step and the grid.
//! All but the helpers are benchmarks or heavy checks, ignored in CI; the
//! resolution study's figures are in `ns2d/README.md`.

use std::f64::consts::PI;

use fwav::aero2d::history::{cycle_means_until, History};
use fwav::aero2d::viscous::{SectionPath, ViscousSection};

/// The default FWAV mid-span section's flow (the aerodynamic
/// discipline's, chord 0.06 m at 3 m/s): Reynolds number 12,329 and the
/// reduced frequency of 11 Hz.
fn fwav_mid_span_flow() -> (f64, f64) {
    let case = fwav::discipline::section::SectionCase::fwav_mid_span();
    (case.reynolds(), case.reduced_frequency(11.0))
}

/// The plate's thickness, chords: `FWAV_NS_THICKNESS` where set, else
/// the default ([`ViscousSection::DEFAULT_THICKNESS`]; `ns2d/README.md`, "The
/// plate's thickness").
pub(crate) fn env_thickness() -> f64 {
    std::env::var("FWAV_NS_THICKNESS")
        .map_or(ViscousSection::DEFAULT_THICKNESS, |v| v.parse().unwrap())
}

/// `cycles` periods of the default FWAV mid-span section flapping at 11
/// Hz, +-30 deg, stroke plane 90 deg, rigid, as `section`.
fn fwav_mid_span_run(section: &ViscousSection, cycles: f64) -> fwav::aero2d::viscous::ViscousRun {
    use fwav::aero2d::motion::SectionFlapping;
    use fwav::discipline::section::SectionCase;
    let case = SectionCase::fwav_mid_span();
    let (reynolds, k) = fwav_mid_span_flow();
    let flapping = SectionFlapping {
        reduced_frequency: k,
        radius: case.radius / case.chord,
        amplitude: 30f64.to_radians(),
        mean_angle: 0.0,
        stroke_plane: 90f64.to_radians(),
    };
    section
        .run(SectionPath::Flapping(flapping), reynolds, cycles * PI / k)
        .unwrap()
}

/// The speed target: one 4-cycle evaluation of the default FWAV
/// mid-span section (the aerodynamic discipline's, Re 12,300: chord 0.06 m
/// at 3 m/s; 11 Hz, +-30 deg, stroke plane 90 deg), rigid, as a 4 % plate
/// at the default resolution (384 x 256 with the far field coarsened,
/// Courant 3), under 60 s on this machine. Measured on 384 x 256
/// (2026-12-05, the machine otherwise idle): **58.2 s**, 22,960 steps,
/// 25.8 ns per cell per step (55.7 s the same day through
/// `discipline_ns_scores::ns_deforming_evaluation_benchmark`); the first
/// stroke's CT 0.0779, as the exponential 384 x 320's, and the last
/// two's CT 0.0710, CP 1.6997. Measured on the exponential 384 x 320,
/// the default before: 67.5 s (2026-12-05) and 118.3 s in a slow hour
/// (both in `discipline_ns_scores::ns_deforming_evaluation_benchmark`;
/// the "about 43 s in a normal hour" once scaled from 384 x 240 by the
/// rigid ratio 1.34 was withdrawn, `ns2d/README.md` "Speed"). On 384
/// x 240: 44.2 s, 20,905 steps, 22.9 ns per cell per step, on a day the
/// same run took 31.9 s in
/// `discipline_ns_scores::ns_deforming_evaluation_benchmark` (the machine's
/// speed varies by half from hour to hour); the former default, 384 x
/// 160 at Courant 1.5, 31.3 s, 36,025 steps, 14.1 ns, on a fast day (256
/// x 160 at Courant 2 with a step never lengthened: 34.4 s, 19.8 ns, an
/// earlier session).
/// Ignored: a benchmark of about a minute; run with
/// `cargo test --release -p fwav --test integration viscous_default_section:: -- --ignored --nocapture`
/// (`FWAV_NS_CYCLES=0.25` runs part of it, to see the step it takes;
/// `FWAV_NS_THICKNESS` sets the plate's thickness, `FWAV_NS_COURANT` the
/// step's Courant number, `FWAV_NS_AROUND` and `FWAV_NS_RADIAL` the grid
/// (the rings scaling the far stretch with them;
/// `FWAV_NS_FAR=none` the exponential stretching throughout)
/// and `FWAV_NS_FIRST_CELL` its first cell in boundary-layer thicknesses,
/// `FWAV_NS_OUTER` its outer boundary in chords,
/// for the convergence study).
#[test]
#[ignore = "benchmark (about a minute: 58.2 s on 2026-12-05; 2 min in a slow hour): the default section's 4-cycle viscous evaluation against the issue's 60 s"]
fn default_section_four_cycles_benchmark() {
    let thickness = env_thickness();
    let courant: f64 = std::env::var("FWAV_NS_COURANT")
        .map_or(ViscousSection::DEFAULT_COURANT, |v| v.parse().unwrap());
    let cycles: f64 = std::env::var("FWAV_NS_CYCLES").map_or(4.0, |v| v.parse().unwrap());
    let plate = ViscousSection::plate(thickness);
    let nodes =
        |key: &str, default: usize| std::env::var(key).map_or(default, |v| v.parse().unwrap());
    let plate = match std::env::var("FWAV_NS_FAR").as_deref() {
        Ok("none") => ViscousSection { far: None, ..plate },
        _ => plate,
    };
    let section = ViscousSection {
        courant,
        around: nodes("FWAV_NS_AROUND", plate.around),
        first_cell_layers: std::env::var("FWAV_NS_FIRST_CELL")
            .map_or(plate.first_cell_layers, |v| v.parse().unwrap()),
        outer_chords: std::env::var("FWAV_NS_OUTER")
            .map_or(plate.outer_chords, |v| v.parse().unwrap()),
        spin_up_periods: std::env::var("FWAV_NS_SPIN_UP")
            .map_or(plate.spin_up_periods, |v| v.parse().unwrap()),
        ..plate.with_radial(nodes("FWAV_NS_RADIAL", plate.radial))
    };
    let (reynolds, k) = fwav_mid_span_flow();
    let cells = section.around * section.radial;
    let clock = crate::machine_time::Stopwatch::start();
    let run = fwav_mid_span_run(&section, cycles);
    let lap = clock.lap();
    let seconds = lap.wall;
    // Each stroke's means: how periodic the flow is; the last two are
    // the discipline's window.
    let strokes = stroke_means(&run.history, cycles.round() as usize);
    let last_two = &strokes[strokes.len().saturating_sub(2)..];
    let last_two = (
        mean(&last_two.iter().map(|s| s.0).collect::<Vec<_>>()),
        mean(&last_two.iter().map(|s| s.1).collect::<Vec<_>>()),
    );
    println!(
        "Re {reynolds:.0}, k {k:.3}, plate {thickness}, {cycles} cycles: {lap}, {} steps \
         (last dt {:.2e}), {:.1} ns per cell per step; last two cycles: CT {:.4}, CP {:.4}",
        run.steps,
        run.dt,
        1e9 * seconds / (cells as f64 * run.steps as f64),
        last_two.0,
        last_two.1
    );
    let strokes: Vec<String> = strokes
        .iter()
        .map(|(ct, cp)| format!("CT {ct:.4} CP {cp:.4}"))
        .collect();
    println!(
        "{} x {} nodes, Courant {courant}; each stroke: {}",
        section.around,
        section.radial,
        strokes.join("; ")
    );
    assert!(seconds < 60.0, "{seconds:.1} s");
}

/// The first stroke's thrust of the default FWAV section converges with
/// the wall's first cell (issue 23's 3 %): halved from the default 0.1
/// boundary-layer thicknesses (`c / sqrt(Re)`, at mid-chord) to 0.05, at
/// the default resolution (384 x 256 with the far field coarsened,
/// Courant 3; 2026-12-05): CT 0.0779 -> 0.0771 (-1.1 %), CP 1.7855 ->
/// 1.7801 (-0.3 %), 34 s. On the exponential 384 x 320, the default
/// before: CT 0.0779 -> 0.0770 (-1.1 %), CP 1.7070 -> 1.7021 (-0.3 %;
/// the input power counted the flight's work then), 95 s in a slow
/// hour. On 384 x 240
/// (the default before), with the step's velocity centred: CT 0.0758 ->
/// 0.0750 (-1.1 %), CP 1.7118 -> 1.7057 (-0.4 %), 18 s. Before (the step start's velocity,
/// Courant 1.5), with the wall pressure's vorticity flux compact (the
/// first cell's difference less half a cell of `ω_ξξ` from the vorticity
/// equation at the wall, `fwav_ns2d::Flow::loads`): CT 0.0775 -> 0.0760
/// (-2.0 %), CP 1.7136 -> 1.7080 (-0.3 %), 55 s; and, with the same
/// formula before it was adopted, first cell 0.2 and 0.025: CT 0.0808 and
/// 0.0740. On the default's 160 rings the halving moves CT 3.3 % (0.0791
/// -> 0.0765): the finer cell coarsens the rings further out.
///
/// With the flux one-sided (`(-3ω_0 + 4ω_1 - ω_2)/2Δη`, in use until
/// 2026-12-03) this failed: CT 0.0918, 0.0820, 0.0771, 0.0743 at first
/// cell 0.2, 0.1, 0.05, 0.025 (-6.0 % at the halving, about first order)
/// while CP settled (1.7551, 1.7157, 1.7095, 1.7095): it read the wall
/// layer's curvature from rings 1 and 2, where the layer is not yet
/// parabolic (`ns2d/README.md`, "The wall's first cell").
#[test]
#[ignore = "heavy (about 35 s in release: 34 s on 2026-12-05): `cargo test --release -p fwav --test integration -- \
            --ignored --nocapture wall_cell`"]
fn default_section_thrust_converges_with_the_wall_cell() {
    let first_stroke = |first_cell_layers| {
        let section = ViscousSection {
            first_cell_layers,
            ..ViscousSection::plate(ViscousSection::DEFAULT_THICKNESS)
        };
        let run = fwav_mid_span_run(&section, 1.0);
        stroke_means(&run.history, 1)[0]
    };
    let layers = ViscousSection::plate(ViscousSection::DEFAULT_THICKNESS).first_cell_layers;
    let (ct, cp) = first_stroke(layers);
    let (ct_fine, cp_fine) = first_stroke(0.5 * layers);
    let change = (ct_fine / ct - 1.0, cp_fine / cp - 1.0);
    println!(
        "first cell {layers} -> {}: CT {ct:.4} -> {ct_fine:.4} ({:+.1} %), CP {cp:.4} -> \
         {cp_fine:.4} ({:+.1} %)",
        0.5 * layers,
        100.0 * change.0,
        100.0 * change.1
    );
    assert!(change.0.abs() < 0.03, "CT {:+.1} %", 100.0 * change.0);
    assert!(change.1.abs() < 0.03, "CP {:+.1} %", 100.0 * change.1);
}

/// The effect of the plate's thickness (issue 23: a membrane modelled
/// as a thin plate of finite thickness with rounded edges, "show the
/// effect of the thickness you choose"). The plate stands for the
/// vehicle's section, 0.1 mm of mylar (0.0017 c on the 60 mm mid-span
/// chord) with 0.6 mm at the carbon leading edge (0.010 c): its
/// thickness is a modelling error, which the bound for the
/// resolution (CT and efficiency within 3 % when refined) should hold
/// as it thins. Asked of the first stroke of the rigid default section
/// (11 Hz, ±30°, default grid), which starts from rest and is the same
/// flow from run to run (the later strokes wander,
/// `NS_WINDOW_SCATTER`): the default 0.04 c against half of it, with a
/// quarter of it and twice it printed for the trend.
///
/// Fails (2026-12-05, 384 x 256, Courant 3; 115 s on one thread beside
/// other runs): CT 0.0138, 0.0370, 0.0779, 0.1303 at 0.01, 0.02, 0.04,
/// 0.08 c (0.0594 at 0.03, 0.1088 at 0.06, from the four-stroke
/// benchmark's first stroke), CP 1.7545, 1.8021, 1.7855, 1.7809: the
/// thrust grows about in proportion to the thickness while the power
/// stays within 3 %. Halved, CT −52.6 % and efficiency −53.0 %; at the
/// vehicle's leading edge (0.01 c) 18 % of the default's. The
/// discipline's evaluation (deforming, strokes 3–4, net;
/// `discipline_ns_scores::ns_deforming_evaluation_benchmark` with
/// `FWAV_NS_THICKNESS`) moves alike: CT 0.0319, 0.0493, 0.0881 and
/// efficiency 0.0118, 0.0188, 0.0339 at 0.01, 0.02, 0.04 c. It is
/// the suction on the rounded nose, whose frontal area is the
/// thickness; extrapolated linearly from 0.01 and 0.02 c, the plate of
/// no thickness would drag (CT about −0.009). Not the grid: 512 nodes
/// round move CT by −1.4 % at 0.01 c, +1.4 % at 0.02 c and +1.7 % at
/// 0.04 c. The thinner plate costs more steps (first stroke: 11,169,
/// 7,971, 5,895, 4,178 at 0.01, 0.02, 0.04, 0.08 c; its edges' cells are
/// smaller). `ns2d/README.md`, "The plate's thickness".
#[test]
#[ignore = "fails: the plate's thickness sets the thrust (first stroke CT -52.6 % at half the \
            default 0.04 c; `ns2d/README.md`, \"The plate's thickness\"); heavy (about 2 min): \
            `cargo test --release -p fwav --test integration -- --ignored --nocapture \
            viscous_default_section::the_scores_hardly_depend_on_the_plates_thickness`"]
fn the_scores_hardly_depend_on_the_plates_thickness() {
    let default = ViscousSection::DEFAULT_THICKNESS;
    let first_stroke = |thickness: f64| {
        let clock = std::time::Instant::now();
        let run = fwav_mid_span_run(&ViscousSection::plate(thickness), 1.0);
        let (ct, cp) = stroke_means(&run.history, 1)[0];
        println!(
            "plate {thickness} c: first stroke CT {ct:.4}, CP {cp:.4}, efficiency {:.4}; {} steps, \
             {:.0} s",
            ct / cp,
            run.steps,
            clock.elapsed().as_secs_f64()
        );
        (ct, ct / cp)
    };
    let chosen = first_stroke(default);
    let half = first_stroke(0.5 * default);
    first_stroke(0.25 * default);
    first_stroke(2.0 * default);
    let change = (half.0 / chosen.0 - 1.0, half.1 / chosen.1 - 1.0);
    println!(
        "halved from {default} c: CT {:+.1} %, efficiency {:+.1} %",
        100.0 * change.0,
        100.0 * change.1
    );
    assert!(change.0.abs() < 0.03, "CT {:+.1} %", 100.0 * change.0);
    assert!(
        change.1.abs() < 0.03,
        "efficiency {:+.1} %",
        100.0 * change.1
    );
}

/// Each stroke's mean CT and CP of a run of `strokes` strokes (its
/// history ends with the last), each over its period as the aerodynamic
/// discipline takes its window (`fwav::aero2d::history::cycle_means_until`).
pub(crate) fn stroke_means(history: &History, strokes: usize) -> Vec<(f64, f64)> {
    let period = history.time.last().copied().unwrap_or(0.0) / strokes as f64;
    (1..=strokes)
        .map(|stroke| {
            let (ct, cp, _) = cycle_means_until(history, period, 1, stroke as f64 * period);
            (ct, cp)
        })
        .collect()
}

/// A window's CT and efficiency (mean CT over mean CP) from its strokes'
/// means, as the discipline scores it (every stroke has as many
/// samples).
pub(crate) fn window_of(strokes: &[(f64, f64)]) -> (f64, f64) {
    let ct = mean(&strokes.iter().map(|x| x.0).collect::<Vec<_>>());
    let cp = mean(&strokes.iter().map(|x| x.1).collect::<Vec<_>>());
    (ct, ct / cp)
}

/// Twelve strokes' loads cut, from the third stroke on, into five windows
/// of two strokes, each scored as the aerodynamic discipline scores its
/// window ([`window_of`]); and the relative standard deviations (sample,
/// n - 1) of the windows' CT and efficiency.
pub(crate) fn window_scatter(history: &History) -> (Vec<(f64, f64)>, f64, f64) {
    let windows: Vec<(f64, f64)> = stroke_means(history, 12)[2..]
        .chunks_exact(2)
        .map(window_of)
        .collect();
    let thrust = relative_deviation(&windows.iter().map(|w| w.0).collect::<Vec<_>>());
    let efficiency = relative_deviation(&windows.iter().map(|w| w.1).collect::<Vec<_>>());
    (windows, thrust, efficiency)
}

/// The mean of `values`.
pub(crate) fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len() as f64
}

/// The sample standard deviation (n - 1) of `values`.
pub(crate) fn standard_deviation(values: &[f64]) -> f64 {
    let m = mean(values);
    let variance = values.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (values.len() - 1) as f64;
    variance.sqrt()
}

/// The sample standard deviation (n - 1) of `values` over their mean.
fn relative_deviation(values: &[f64]) -> f64 {
    standard_deviation(values) / mean(values)
}

/// The scatter of the Navier–Stokes evaluation's scored window
/// ([`fwav::discipline::section_model::NS_WINDOW_SCATTER`], the margin a
/// candidate must clear in the aerodynamic discipline): the default
/// section flapped for 12 strokes at the default resolution, strokes 3 to
/// 12 cut into five windows of two strokes (the discipline scores the
/// last two of four), the relative standard deviation of the windows' CT
/// and efficiency `CT / CP` (sample, n - 1). On the default 384 x 320
/// the rigid section's flow repeats from the fourth stroke, so both must
/// lie well below the declared scatter, which is how far the deforming
/// section's L18 rows move with the step (`discipline_ns_scores::ns_discipline_benchmark`):
/// below half of it. Measured on the default 384 x 256 with the far field
/// coarsened (2026-12-05): windows CT 0.0710, 0.0712, 0.0714, 0.0714,
/// 0.0714, relative deviation CT 0.24 %, efficiency 0.12 %, 172 s.
/// Measured on the exponential 384 x 320 (2026-12-03, the
/// `default_section_four_cycles_benchmark` run with `FWAV_NS_CYCLES=12`,
/// from its stroke means): CT 0.20 %, efficiency 0.32 %, 293 s in a slow
/// hour. On 384 x 240, the default before, whose flow never settled:
/// CT 3.92 %, efficiency 0.79 % (211 s in a slow hour), and the declared
/// thrust scatter was this section's.
#[test]
#[ignore = "benchmark (about 3 min: 172 s on 2026-12-05; 5 min in a slow hour): `cargo test --release -p fwav --test integration -- --ignored --nocapture viscous_default_section::ns_evaluation_window_scatter_benchmark`"]
fn ns_evaluation_window_scatter_benchmark() {
    use fwav::discipline::section_model::NS_WINDOW_SCATTER;
    let section = ViscousSection::plate(ViscousSection::DEFAULT_THICKNESS);
    let run = fwav_mid_span_run(&section, 12.0);
    let (windows, thrust, efficiency) = window_scatter(&run.history);
    println!(
        "windows (CT, efficiency): {windows:.4?}; relative deviation: CT {thrust:.4}, efficiency \
         {efficiency:.4}; declared {NS_WINDOW_SCATTER:?}"
    );
    // Periodic: far below the deforming section's declared scatter.
    for (measured, declared) in [
        (thrust, NS_WINDOW_SCATTER.0),
        (efficiency, NS_WINDOW_SCATTER.1),
    ] {
        assert!(
            measured < 0.5 * declared,
            "declared {declared:.4}, measured {measured:.4}"
        );
    }
}

/// Strokes 3 to 12 of a 12-stroke run ([`stroke_means`]): the mean CT,
/// the efficiency `mean CT / mean CP`, and the standard error of the CT
/// mean from its ten strokes (sample deviation over `sqrt(10)`).
fn long_mean(history: &History) -> (f64, f64, f64) {
    let strokes = &stroke_means(history, 12)[2..];
    let (ct, efficiency) = window_of(strokes);
    let thrusts: Vec<f64> = strokes.iter().map(|s| s.0).collect();
    (ct, efficiency, relative_deviation(&thrusts) / 10f64.sqrt())
}

/// Issue 23's convergence (CT and efficiency within 3 % when the grid and
/// the time step are refined), asked of the mean over strokes 3 to 12 of
/// the default section (rigid, 11 Hz, +-30 deg): the default (384 x 256,
/// the far field coarsened, Courant 3) against the step halved, the grid
/// refined radially as a whole to 320 rings
/// ([`ViscousSection::with_radial`]: the near grid's 320 rings become
/// 400, the far growth 4.5 % a cell 3.6 %) and 512 nodes round, one at a
/// time. Measured (2026-12-05; `ns2d/README.md`, "The far field coarsened"): CT
/// 0.0713 (standard error 0.1 %: periodic), efficiency 0.0417; the step
/// halved -0.6 % and +0.0 %, 320 rings -0.1 % and +0.3 %, 512 round
/// -0.5 % and +1.2 %; passed, 1,004 s for the four runs (the first one
/// slowed by a build beside it). On the exponential 384 x 320, the
/// default before (2026-12-03, a slow hour; `ns2d/README.md`, "The long mean"):
/// CT 0.0715, efficiency 0.0436 (the input power counted the flight's
/// work then); the step halved -1.6 % and -0.5 %, 400 rings -0.2 % and
/// +0.2 %, 512 round -0.6 % and +1.1 %; passed, 1,836 s. On 384 x 240,
/// the default before that, this failed: its flow never settled (CT
/// 0.0680, standard error 1.3 %), and 320 rings moved CT +5.1 % and the
/// efficiency +2.7 %, 512 round +3.6 % and +2.8 % (the step halved:
/// -1.0 %, +0.3 %).
#[test]
#[ignore = "heavy (about 17 min: 1,004 s on 2026-12-05): `cargo test --release -p fwav --test \
            integration -- --ignored --nocapture viscous_default_section::the_long_mean`"]
fn the_long_mean_converges_with_the_resolution() {
    let default = ViscousSection::plate(ViscousSection::DEFAULT_THICKNESS);
    let measure = |section: &ViscousSection| {
        let clock = std::time::Instant::now();
        let run = fwav_mid_span_run(section, 12.0);
        let means = long_mean(&run.history);
        println!(
            "{} x {}, Courant {}: CT {:.4} (standard error {:.1} %), efficiency {:.4}; {:.0} s",
            section.around,
            section.radial,
            section.courant,
            means.0,
            100.0 * means.2,
            means.1,
            clock.elapsed().as_secs_f64()
        );
        means
    };
    let base = measure(&default);
    let refined = [
        ViscousSection {
            courant: 0.5 * default.courant,
            ..default.clone()
        },
        default.with_radial(320),
        ViscousSection {
            around: 512,
            ..default.clone()
        },
    ];
    let mut worst: f64 = 0.0;
    for section in &refined {
        let (ct, efficiency, _) = measure(section);
        let change = (ct / base.0 - 1.0, efficiency / base.1 - 1.0);
        println!(
            "  CT {:+.1} %, efficiency {:+.1} %",
            100.0 * change.0,
            100.0 * change.1
        );
        worst = worst.max(change.0.abs()).max(change.1.abs());
    }
    assert!(worst < 0.03, "the largest change is {:.1} %", 100.0 * worst);
}

/// Issue 23's convergence of the evaluation the aerodynamic discipline
/// makes of the default design (four strokes, strokes 3 and 4 scored, the
/// initial kinematics), rigid and deforming as the first system analysis
/// found: the `fwav validate` cases `ns2d/refined-*`
/// (`fwav::validation::ns2d`'s `convergence`), each the change of CT or
/// efficiency when the step is halved (Courant 3 to 1.5) or the grid
/// refined (384 x 256 to 480 x 320), within 3 %. Measured (2026-12-06;
/// `ns2d/README.md`, "The default section's evaluation refined"): the step
/// halved, rigid CT -0.86 % and efficiency -0.12 %, deforming +0.52 % and
/// +0.63 %; the grid refined, rigid +0.33 % and +1.11 %, deforming +0.49 %
/// and +0.65 %. The L18 rows far from the initial design are another
/// matter (`discipline_ns_scatter`'s refined long means: up to 14.5 %).
#[test]
#[ignore = "heavy (about 12 min on two threads, 705 s on 2026-12-06: six four-stroke evaluations): `cargo test --release \
            -p fwav --test integration -- --ignored --nocapture \
            viscous_default_section::the_default_evaluation_converges`"]
fn the_default_evaluation_converges_with_the_step_and_the_grid() {
    let cases = fwav::validation::matching(Some("ns2d/refined-"));
    assert_eq!(cases.len(), 8);
    let mut failed = Vec::new();
    for case in cases.iter().map(fwav::validation::Validation::run) {
        println!(
            "{}: {:+.2} % ({}){}",
            case.name,
            100.0 * case.error.unwrap_or(f64::NAN),
            case.note.as_deref().unwrap_or(""),
            case.failure
                .as_deref()
                .map_or(String::new(), |f| format!(" failed: {f}"))
        );
        if !case.pass {
            failed.push(case.name);
        }
    }
    assert!(failed.is_empty(), "not within 3 %, or failed: {failed:?}");
}
