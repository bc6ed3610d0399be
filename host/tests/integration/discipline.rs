//! The aerodynamic discipline's evaluation: the flapping mid-span section
//! in 2D.

use std::path::PathBuf;
use std::sync::OnceLock;

use fwav::aero2d::theory::garrick_plunge;
use fwav::aeroelastic::{FlappingKinematics, FlightCondition};
use fwav::discipline::cache::EvaluationCache;
use fwav::discipline::kinematic::KinematicResult;
use fwav::discipline::section::{EvaluationError, SectionCase, FWAV_LESP_CRITICAL};
use fwav::discipline::section_model::LDVM_SHEDDING_SCATTER;

/// The physical-to-reduced mapping, against Garrick (1936): a vertical
/// stroke plane at a small amplitude is a harmonic plunge of `r A` — here
/// the FWAV's mid-span section (c = 0.06 m, r = 0.075 m, 3 m/s) at the
/// frequency that makes `k = pi f c / U = 1` and the amplitude that makes
/// `h0 = r A = 0.05 c`: mean CT within 10% of Garrick's (the LDVM's own
/// Garrick validation shows +0.12% at this k; +6.18% before 2026-12-07,
/// `fwav::aero2d::ldvm` "The wake next to the edge"). And flight speed and frequency
/// doubled together give the same coefficients (same k, same sweep).
#[test]
fn section_evaluation_maps_flapping_to_garricks_plunge() {
    // Garrick's theory is attached flow: leading-edge shedding off.
    let case = SectionCase {
        lesp_critical: None,
        ..SectionCase::fwav_mid_span()
    };
    let frequency = case.flight.speed / (std::f64::consts::PI * case.chord);
    let kinematics = FlappingKinematics {
        frequency,
        amplitude: 0.05 * case.chord / case.radius,
        mean_angle: 0.0,
        stroke_plane: std::f64::consts::FRAC_PI_2,
    };
    let r = case.evaluate(&kinematics).unwrap();
    let (ct, _, _) = garrick_plunge(1.0, 0.05);
    println!(
        "k {:.3}: CT {:.5} vs Garrick {ct:.5} ({:+.1}%), CP {:.4}, efficiency {:.3}, CT change over the last cycle {:+.2e}",
        r.reduced_frequency,
        r.ct,
        100.0 * (r.ct / ct - 1.0),
        r.cp,
        r.efficiency,
        r.ct_change
    );
    assert!((r.reduced_frequency - 1.0).abs() < 1e-12);
    assert!((r.ct / ct - 1.0).abs() < 0.1);

    let faster = SectionCase {
        flight: FlightCondition {
            speed: 2.0 * case.flight.speed,
            ..case.flight
        },
        ..case.clone()
    };
    let doubled = faster
        .evaluate(&FlappingKinematics {
            frequency: 2.0 * frequency,
            ..kinematics
        })
        .unwrap();
    assert!((doubled.ct - r.ct).abs() < 1e-9 * r.ct.abs());
    assert!((doubled.cp - r.cp).abs() < 1e-9 * r.cp.abs());
    // The friction estimate does depend on speed (Reynolds number).
    assert!(doubled.ct_net > r.ct_net);
}

/// The scores are the means over every cycle after the first two
/// (`[design] section_cycles`): the LDVM's attached flow repeats from the
/// third, so Garrick's plunge of the test above scores the same over
/// cycles 3 to 8 as over 3 and 4 (within 0.5 %), both within 10 % of
/// Garrick (1936), and the scores' declared scatter stays zero.
#[test]
fn more_cycles_score_the_same_periodic_flow() {
    let case = SectionCase {
        lesp_critical: None,
        ..SectionCase::fwav_mid_span()
    };
    let kinematics = FlappingKinematics {
        frequency: case.flight.speed / (std::f64::consts::PI * case.chord),
        amplitude: 0.05 * case.chord / case.radius,
        mean_angle: 0.0,
        stroke_plane: std::f64::consts::FRAC_PI_2,
    };
    let long = SectionCase {
        cycles: 8,
        ..case.clone()
    };
    assert_eq!((case.scored_cycles(), long.scored_cycles()), (2, 6));
    let (four, eight) = (
        case.evaluate(&kinematics).unwrap(),
        long.evaluate(&kinematics).unwrap(),
    );
    let (garrick, _, _) = garrick_plunge(1.0, 0.05);
    println!(
        "CT over cycles 3-4 {:.5}, 3-8 {:.5}, Garrick {garrick:.5}; efficiency {:.4}, {:.4}",
        four.ct, eight.ct, four.efficiency, eight.efficiency
    );
    assert!((eight.ct / four.ct - 1.0).abs() < 0.005);
    assert!((eight.efficiency / four.efficiency - 1.0).abs() < 0.005);
    assert!((eight.ct / garrick - 1.0).abs() < 0.1);
    assert_eq!(long.scatter(), (0.0, 0.0));
}

/// Separation limits the high-amplitude corner. The thrust of a thin
/// section in attached flow is the leading-edge suction, which grows as the
/// square of the leading-edge suction parameter A0 (Garrick 1936: the
/// suction force is `pi rho c U^2 A0^2` per unit span); the LDVM sheds a
/// leading-edge vortex whenever |A0| would exceed the critical LESP and so
/// holds |A0| at it (Ramesh et al. 2014, J. Fluid Mech. 751, section 3),
/// losing the suction above it. The mid-span section at 11 Hz plunges at
/// up to `r 2 pi f A` = 1.8 m/s (±20°) and 3.6 m/s (±40°) against 3 m/s:
/// effective incidences near 31° and 50°, both far above an A0 of 0.11,
/// and the larger amplitude above it for longer and by more. So with the
/// FWAV's critical LESP the mean CT falls below attached flow's at both
/// amplitudes, and by a larger fraction at ±40° than at ±20°.
#[test]
fn leading_edge_shedding_costs_more_thrust_at_high_amplitude() {
    let shedding = SectionCase::fwav_mid_span();
    assert_eq!(shedding.lesp_critical, Some(FWAV_LESP_CRITICAL));
    let attached = SectionCase {
        lesp_critical: None,
        ..shedding.clone()
    };
    let loss = |amplitude_deg: f64| {
        let k = FlappingKinematics::from_degrees([11.0, amplitude_deg, 0.0, 90.0]);
        let on = shedding.evaluate(&k).unwrap();
        let off = attached.evaluate(&k).unwrap();
        println!(
            "±{amplitude_deg}°: CT {:.4} with shedding, {:.4} attached ({:.1}% lost); \
             efficiency {:.3} / {:.3}; net CT {:.4} / {:.4}",
            on.ct,
            off.ct,
            100.0 * (1.0 - on.ct / off.ct),
            on.efficiency,
            off.efficiency,
            on.ct_net,
            off.ct_net
        );
        assert!(on.ct < off.ct, "±{amplitude_deg}°: {} vs {}", on.ct, off.ct);
        1.0 - on.ct / off.ct
    };
    let (low, high) = (loss(20.0), loss(40.0));
    assert!(high > low, "loss at ±40° {high:.3}, at ±20° {low:.3}");
}

/// Bad input is refused with the reason: kinematics out of range, a
/// deformation sample with one point.
#[test]
fn section_evaluation_refuses_bad_input() {
    let case = SectionCase::fwav_mid_span();
    let bad = FlappingKinematics {
        amplitude: 2.0,
        ..FlappingKinematics::INITIAL
    };
    let e = case.evaluate(&bad).unwrap_err();
    assert!(e.to_string().contains("amplitude"), "{e}");
    let broken = SectionCase {
        deformation: vec![vec![[0.0, 0.0]]; 10],
        ..case
    };
    assert!(matches!(
        broken.evaluate(&FlappingKinematics::INITIAL),
        Err(EvaluationError::Deformation(_))
    ));
}

/// The discipline over the built-in design space from the initial design,
/// equal weights, default NSGA-II, evaluations through `cache`.
fn equal_weights(case: &SectionCase, cache: &EvaluationCache) -> KinematicResult {
    use fwav::discipline::kinematic::{optimize, DesignSpace, Weights};
    use fwav::optimize::nsga2::Nsga2Config;
    optimize(
        case,
        &DesignSpace::fwav(),
        fwav::aeroelastic::kinematics::FlappingKinematics::from_degrees([11.0, 30.0, 0.0, 90.0]),
        Weights {
            thrust: 1.0,
            efficiency: 1.0,
        },
        &Nsga2Config::default(),
        cache,
    )
    .unwrap()
}

/// The discipline's run by [`equal_weights`] on the FWAV's mid-span
/// section from an empty cache, made once for the tests of this module.
struct EqualWeightsRun {
    case: SectionCase,
    result: KinematicResult,
    /// Its evaluations (the initial design, the 18 array rows and the
    /// confirmations), which the other discipline tests read: each of
    /// their evaluations of the same section and design is one of these,
    /// bit for bit, so they compute only their own.
    cache: EvaluationCache,
    /// How many evaluations the run made, and the file they were saved
    /// to right after it (before any other test could add to `cache`).
    evaluations: usize,
    file: PathBuf,
    seconds: f64,
}

/// The run (about 10 s on 2 cores), made by whichever test needs it
/// first; the others wait for it.
fn equal_weights_run() -> &'static EqualWeightsRun {
    static RUN: OnceLock<EqualWeightsRun> = OnceLock::new();
    RUN.get_or_init(|| {
        let case = SectionCase::fwav_mid_span();
        let cache = EvaluationCache::new();
        let started = std::time::Instant::now();
        let result = equal_weights(&case, &cache);
        let seconds = started.elapsed().as_secs_f64();
        let file = std::env::temp_dir().join(format!("fwav-cache-{}.json", std::process::id()));
        cache.save(&file).unwrap();
        EqualWeightsRun {
            case,
            result,
            evaluations: cache.len(),
            cache,
            file,
            seconds,
        }
    })
}

/// The whole aerodynamic discipline on the FWAV's rigid mid-span section
/// (L18 → best row, ANOM + confirmation, RSM + NSGA-II + confirmation):
/// the chosen kinematics beat the initial design in the combined objective
/// (equal weights on CT / CT_0 and eta / eta_0, net of friction, with
/// leading-edge shedding), and that is the direct
/// confirmation run's value, not a prediction.
#[test]
fn kinematic_discipline_beats_the_initial_design() {
    let EqualWeightsRun {
        case,
        result,
        evaluations,
        file,
        seconds,
        ..
    } = equal_weights_run();
    let initial = result.initial.result.as_ref().unwrap();
    println!(
        "initial: CT {:.4}, efficiency {:.3}; surfaces R² CT {:.3} (adj {:.3}), eta {:.3} (adj {:.3}); {} Pareto points; {:.1} s",
        initial.ct,
        initial.efficiency,
        result.surface_quality[0].0,
        result.surface_quality[0].1,
        result.surface_quality[1].0,
        result.surface_quality[1].1,
        result.pareto.len(),
        seconds
    );
    for c in &result.candidates {
        let r = c.confirmation.result.as_ref().unwrap();
        println!(
            "{}: {:?} -> CT {:.4}, efficiency {:.3}, combined {:.3} (predicted {:?})",
            c.method,
            c.confirmation.design,
            r.ct,
            r.efficiency,
            c.combined.unwrap(),
            c.predicted
        );
    }
    // The shedding LDVM's scores scatter with its step: the margin is one
    // standard deviation of two runs' difference, at the initial design
    // (the objective's reference) √2 times the declared scatters' sum.
    let (thrust, efficiency) = LDVM_SHEDDING_SCATTER;
    let expected = std::f64::consts::SQRT_2 * (thrust + efficiency);
    assert!(
        (result.adoption_margin - expected).abs() < 1e-9,
        "{} against {expected}",
        result.adoption_margin
    );
    let chosen = result.chosen.expect("a candidate beats the initial design");
    let confirmed = result.candidates[chosen].combined.unwrap();
    let direct = case
        .evaluate(&result.candidates[chosen].confirmation.design)
        .unwrap();
    // The objective is on net thrust and net efficiency.
    let again = direct.ct_net / initial.ct_net + direct.efficiency_net / initial.efficiency_net;
    assert!(confirmed > 2.0, "{confirmed}");
    assert!((again - confirmed).abs() < 1e-12);

    // A rerun takes every evaluation from the cache (1 + 18 + 2 runs),
    // through a file, and gives the same answer.
    let reloaded = EvaluationCache::load(file).unwrap();
    assert_eq!(reloaded.len(), *evaluations);
    let started = std::time::Instant::now();
    let rerun = equal_weights(case, &reloaded);
    println!(
        "rerun from the cache ({} evaluations): {:.2} s",
        reloaded.len(),
        started.elapsed().as_secs_f64()
    );
    assert_eq!(reloaded.len(), *evaluations);
    // (JSON keeps the values to the last bit or so.)
    assert_eq!(rerun.chosen, result.chosen);
    for (a, b) in rerun.candidates.iter().zip(&result.candidates) {
        assert!((a.combined.unwrap() - b.combined.unwrap()).abs() < 1e-12);
    }
    std::fs::remove_file(file).ok();
}

/// A failed evaluation is recorded with its reason and the discipline goes
/// on: with the stroke plane's high level at 190° (outside the kinematics'
/// range) the six array runs at that level fail, say why, count as the
/// worst response, and the candidates are still found and confirmed.
/// The twelve rows at the other levels, and the initial design, are the
/// equal-weights run's and come from its cache (failures are never
/// cached: the six are run).
#[test]
fn failed_evaluations_are_recorded_and_the_discipline_goes_on() {
    use fwav::discipline::kinematic::{optimize, DesignSpace, Weights};
    use fwav::optimize::nsga2::Nsga2Config;
    let space = DesignSpace {
        stroke_plane_deg: [70.0, 90.0, 190.0],
        ..DesignSpace::fwav()
    };
    let result = optimize(
        &SectionCase::fwav_mid_span(),
        &space,
        fwav::aeroelastic::kinematics::FlappingKinematics::from_degrees([11.0, 30.0, 0.0, 90.0]),
        Weights {
            thrust: 1.0,
            efficiency: 1.0,
        },
        &Nsga2Config {
            generations: 50,
            ..Nsga2Config::default()
        },
        &equal_weights_run().cache,
    )
    .unwrap();
    let failed: Vec<&String> = result
        .runs
        .iter()
        .filter_map(|r| r.result.as_ref().err())
        .collect();
    println!("{} failed runs, e.g. {:?}", failed.len(), failed.first());
    assert_eq!(failed.len(), 6);
    assert!(failed.iter().all(|e| e.contains("stroke_plane")));
    assert_eq!(result.candidates.len(), 3);
    assert!(result.candidates[0].combined.is_some());
}

/// The discipline never proposes a design the actuator cannot fly: the
/// default wing (shell model's mass, quasi-steady damping) on the default
/// `[actuator]` with its current limit lowered to 1.6 times the initial
/// design's peak current over (1 - reserve), so that the initial design
/// (11 Hz, ±30°) is feasible with its reserve while the high corner of
/// the space (13 Hz, ±40°, whose damping current is about (13·40 /
/// 11·30)² ≈ 2.5 times the initial's) is not. Every candidate carries its
/// violation, the chosen one is feasible on the same vehicle's check, the
/// Pareto front holds only feasible designs, and the constraint binds
/// (some L18 rows are infeasible). The evaluations the equal-weights run
/// made (the 18 rows) come from its cache; the constraint changes the
/// candidates, not the evaluations.
#[test]
fn kinematic_discipline_never_proposes_an_infeasible_design() {
    use fwav::config::SystemConfig;
    use fwav::discipline::kinematic::{optimize_feasible, DesignSpace, Weights};
    use fwav::optimize::nsga2::Nsga2Config;
    use fwav::vehicle::Vehicle;
    let config = SystemConfig::default();
    let model = config.wing_model().unwrap();
    let initial = config.kinematics();
    let mut vehicle = Vehicle::quasi_steady(
        &model,
        &initial,
        &config.flight(),
        config.actuator.actuator(),
    )
    .unwrap();
    let limits = vehicle.actuator.limits;
    let at_initial = vehicle.check(&Vehicle::demand(&initial)).unwrap();
    vehicle.actuator.limits.current_a =
        1.6 * at_initial.peaks.peak_current_a / (1.0 - limits.reserve);
    let tight = vehicle.check(&Vehicle::demand(&initial)).unwrap();
    assert!(tight.feasible, "{tight:?}");
    let corner = FlappingKinematics::from_degrees([13.0, 40.0, 0.0, 90.0]);
    assert!(vehicle.violation(&corner) > 0.0);
    println!(
        "initial peak current {:.4} A; limit lowered to {:.4} A",
        at_initial.peaks.peak_current_a, vehicle.actuator.limits.current_a
    );

    let result = optimize_feasible(
        &SectionCase::fwav_mid_span(),
        &DesignSpace::fwav(),
        initial,
        Weights {
            thrust: 1.0,
            efficiency: 1.0,
        },
        &Nsga2Config {
            generations: 60,
            ..Nsga2Config::default()
        },
        &equal_weights_run().cache,
        &|k: &FlappingKinematics| vehicle.violation(k),
    )
    .unwrap();
    assert_eq!(result.initial_violation, vehicle.violation(&initial));
    let infeasible_rows = result.run_violations.iter().filter(|&&v| v > 0.0).count();
    println!("{infeasible_rows} of 18 L18 rows infeasible");
    assert!(infeasible_rows > 0, "the constraint does not bind");
    for c in &result.candidates {
        println!(
            "{}: {:?} combined {:?}, violation {:.4}",
            c.method, c.confirmation.design, c.combined, c.violation
        );
        assert_eq!(c.violation, vehicle.violation(&c.confirmation.design));
    }
    for (design, _, _) in &result.pareto {
        assert_eq!(vehicle.violation(design), 0.0, "{design:?}");
    }
    if let Some(i) = result.chosen {
        let design = result.candidates[i].confirmation.design;
        let verdict = vehicle.check(&Vehicle::demand(&design)).unwrap();
        assert!(verdict.feasible, "{verdict:?}");
        assert!(verdict.limiting.margin >= limits.reserve);
    }
}

/// The combined objective divides by the reference it is given (the
/// design driver gives the first cycle's initial design's to the later
/// cycles): every candidate's combined objective is `CT/CT_0 + eta/eta_0`
/// of its confirmation run with that reference, and the result records it;
/// without one, the reference is the initial design's run. The equal-weights
/// run's evaluations come from its cache.
#[test]
fn the_objective_divides_by_the_reference_given() {
    use fwav::discipline::kinematic::{
        optimize_reporting, unconstrained, DesignSpace, ObjectiveReference, Weights,
    };
    use fwav::optimize::nsga2::Nsga2Config;
    let run = equal_weights_run();
    let initial = run.result.initial.result.clone().unwrap();
    assert_eq!(
        run.result.reference,
        Some(ObjectiveReference::of(&initial).unwrap())
    );
    let given = ObjectiveReference {
        ct_net: 2.0 * initial.ct_net,
        efficiency_net: 0.5 * initial.efficiency_net,
    };
    let result = optimize_reporting(
        &run.case,
        &DesignSpace::fwav(),
        run.result.initial.design,
        Weights {
            thrust: 1.0,
            efficiency: 1.0,
        },
        &Nsga2Config::default(),
        Some(given),
        &run.cache,
        &unconstrained,
        &|_, _| {},
    )
    .unwrap();
    assert_eq!(result.reference, Some(given));
    for c in &result.candidates {
        let r = c.confirmation.result.as_ref().unwrap();
        let expected = r.ct_net / given.ct_net + r.efficiency_net / given.efficiency_net;
        let combined = c.combined.unwrap();
        assert!(
            (combined - expected).abs() < 1e-12 * expected.abs(),
            "{}: {combined} {expected}",
            c.method
        );
    }
    // The initial design scores 1/2 + 2 = 2.5 against this reference:
    // a candidate is chosen only above it.
    if let Some(i) = result.chosen {
        assert!(result.candidates[i].combined.unwrap() > 2.5);
    }
}

/// The three section models over the L18 rows of the default design
/// (issue 23's comparison; the NS and the deforming-LDVM columns are the
/// design runs' in docs/ns-design): the FWAV's rigid mid-span section by
/// the unsteady panel method as a NACA 0004 (4% thick, as the NS model's
/// plate; [`SectionCase::evaluate_panel`]) and by the LDVM, both inviscid
/// and with the same laminar friction estimate for the net values. The
/// two potential-flow models of a thin section must agree where the LDVM
/// sheds no leading-edge vortex: the panel's inviscid CT within 5% of
/// the attached-flow LDVM's (LESP off) on every row (measured: 3.2% at
/// most, the panel higher, 27 s; 1.7%, the panel lower, before the LDVM's
/// step convergence of 2026-12-07, `fwav::aero2d::ldvm` "The wake next to
/// the edge", which took 3.2% to 4.5% off its attached CT). The table
/// printed (`--nocapture`) also gives the LDVM with the discipline's
/// shedding (LESP 0.11), whose difference is the shedding's.
#[test]
#[ignore = "a comparison of about a minute: `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline::three_models`"]
fn three_models_over_the_l18_rows() {
    use fwav::aero2d::naca::{Naca4, TrailingEdge};
    use fwav::aero2d::panel::{SectionShape, DEFAULT_PANELS};
    use fwav::discipline::kinematic::DesignSpace;
    use fwav::optimize::doe::{l18_quadratic_columns, OrthogonalArray};
    let naca: Naca4 = "0004".parse().unwrap();
    let shape =
        SectionShape::new(&naca.points(DEFAULT_PANELS, TrailingEdge::Closed).unwrap()).unwrap();
    let shedding = SectionCase::fwav_mid_span();
    let attached = SectionCase {
        lesp_critical: None,
        ..SectionCase::fwav_mid_span()
    };
    let space = DesignSpace::fwav();
    let levels: Vec<Vec<f64>> = [
        space.frequency_hz,
        space.amplitude_deg,
        space.mean_angle_deg,
        space.stroke_plane_deg,
    ]
    .iter()
    .map(|l| l.to_vec())
    .collect();
    let plan = OrthogonalArray::l18()
        .design(&l18_quadratic_columns(4).unwrap(), &levels)
        .unwrap();
    println!(
        "| row | f, Hz | amplitude | mean | plane | panel CT | panel CT net | panel η net | \
         LDVM attached CT | LDVM attached η net | LDVM LESP 0.11 CT net | η net |"
    );
    let mut worst: f64 = 0.0;
    for (i, x) in plan.iter().enumerate() {
        let k = FlappingKinematics::from_degrees([x[0], x[1], x[2], x[3]]);
        let panel = shedding.evaluate_panel(&k, &shape).unwrap();
        let ldvm = attached.evaluate(&k).unwrap();
        let shed = shedding.evaluate(&k).unwrap();
        worst = worst.max((panel.ct / ldvm.ct - 1.0).abs());
        println!(
            "| {} | {} | {} | {} | {} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} |",
            i + 1,
            x[0],
            x[1],
            x[2],
            x[3],
            panel.ct,
            panel.ct_net,
            panel.efficiency_net,
            ldvm.ct,
            ldvm.efficiency_net,
            shed.ct_net,
            shed.efficiency_net
        );
    }
    println!(
        "largest panel/LDVM inviscid CT difference: {:.1}%",
        100.0 * worst
    );
    assert!(worst < 0.05, "{worst}");
}
