//! The aerodynamic discipline on the Navier–Stokes section model
//! (`[design] section_model = "ns"`): the setting, the evaluation cache
//! keeping the models apart, one evaluation end to end on a coarse grid,
//! and the rigid-section limitation said wherever results are reported.

use fwav::aero2d::theory::garrick_plunge;
use fwav::aeroelastic::FlappingKinematics;
use fwav::config::template::commented_toml;
use fwav::config::SystemConfig;
use fwav::discipline::cache::{key, EvaluationCache};
use fwav::discipline::section::{EvaluationError, SectionCase, SectionResult};
use fwav::discipline::section_model::{
    SectionFlowModel, SectionModelName, ViscousPlate, NS_WINDOW_SCATTER,
};

/// A 12 % plate on 64 × 64 nodes out to 15 chords, first cell a fifth of
/// the boundary layer: coarse, for a test of seconds (the default is
/// 384 × 160 out to 30 chords).
fn coarse_plate() -> ViscousPlate {
    ViscousPlate {
        thickness: 0.12,
        around: 48,
        radial: 48,
        outer_chords: 15.0,
        first_cell_layers: 0.2,
        courant: fwav::aero2d::viscous::ViscousSection::DEFAULT_COURANT,
        spin_up: false,
    }
}

/// The built-in mid-span section with the Navier–Stokes model of `plate`.
fn ns_case(plate: ViscousPlate) -> SectionCase {
    SectionCase {
        model: SectionFlowModel::Ns(plate),
        ..SectionCase::fwav_mid_span()
    }
}

/// `section_model` reads "ldvm" (the default) or "ns", with the plate's
/// thickness at the default resolution and no spin-up (a plate given
/// one spins up through the strokes before the scored last two);
/// `fwav init`'s template writes both keys with their docs.
#[test]
fn section_model_setting_chooses_the_model() {
    let default = SystemConfig::from_toml("").unwrap();
    assert_eq!(default.design.section_model, SectionModelName::Ldvm);
    assert_eq!(default.section_case().model, SectionFlowModel::Ldvm);
    let ns = SystemConfig::from_toml("[design]\nsection_model = \"ns\"\n").unwrap();
    assert_eq!(
        ns.section_case().model,
        SectionFlowModel::Ns(ViscousPlate::new(0.04))
    );
    let thick =
        SystemConfig::from_toml("[design]\nsection_model = \"ns\"\nns_thickness = 0.1\n").unwrap();
    let SectionFlowModel::Ns(plate) = thick.section_case().model else {
        panic!("not the NS model");
    };
    assert_eq!(
        (plate.thickness, plate.around, plate.radial, plate.spin_up),
        (0.1, 384, 320, false)
    );
    assert_eq!(plate.section(4).spin_up_periods, 0.0);
    let spun = ViscousPlate {
        spin_up: true,
        ..plate
    };
    assert_eq!(spun.section(4).spin_up_periods, 2.0);
    assert_eq!(spun.section(6).spin_up_periods, 4.0);
    let template = commented_toml(&SystemConfig::default()).unwrap();
    assert!(
        template.contains("section_model = \"ldvm\"\n"),
        "{template}"
    );
    assert!(template.contains("ns_thickness = 0.04\n"), "{template}");
    assert!(
        template.contains("\"ldvm\" or \"ns\".\nsection_model"),
        "{template}"
    );
}

/// An unknown model, a model that is not a word, and a plate thickness
/// out of the solver's range are refused naming the key, the value and
/// what is allowed.
#[test]
fn section_model_setting_refuses_bad_values() {
    for (text, value) in [
        ("section_model = \"navier\"", "\"navier\""),
        ("section_model = 2", "2"),
    ] {
        let e = SystemConfig::from_toml(&format!("[design]\n{text}\n"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("design.section_model"), "{e}");
        assert!(e.contains(value), "{e}");
        assert!(e.contains("\"ldvm\" or \"ns\""), "{e}");
    }
    let e = SystemConfig::from_toml("[design]\nns_thickness = 0.001\n")
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        "design.ns_thickness = 0.001 is outside [0.005, 0.3] chords"
    );
}

fn result(ct: f64) -> SectionResult {
    SectionResult {
        reduced_frequency: 0.69,
        ct,
        ct_net: ct,
        cp: 1.0,
        efficiency: ct,
        efficiency_net: ct,
        ct_change: 0.0,
    }
}

/// The cache never serves one model's result for the other, nor one
/// grid's for another's, nor a rigid section's for a deforming one's
/// (both models take the deformation); the Navier–Stokes model's result
/// serves any critical LESP (it takes none); an LDVM case is keyed as
/// before the model existed (older cache files still match).
#[test]
fn evaluation_cache_keeps_the_models_apart() {
    let design = FlappingKinematics::INITIAL;
    let ldvm = SectionCase::fwav_mid_span();
    let ns = ns_case(ViscousPlate::new(0.04));
    let cache = EvaluationCache::new();
    cache.insert(&ldvm, &design, result(0.5));
    assert_eq!(cache.get(&ns, &design), None);
    cache.insert(&ns, &design, result(0.3));
    assert_eq!(cache.get(&ldvm, &design), Some(result(0.5)));
    assert_eq!(cache.get(&ns, &design), Some(result(0.3)));
    assert_eq!(cache.get(&ns_case(coarse_plate()), &design), None);
    assert_eq!(cache.get(&ns_case(ViscousPlate::new(0.05)), &design), None);

    let deformation = vec![vec![[0.0, 0.0], [0.5, 0.02], [1.0, 0.0]]; 8];
    let deforming_ns = SectionCase {
        deformation: deformation.clone(),
        ..ns.clone()
    };
    assert_eq!(cache.get(&deforming_ns, &design), None);
    let other_lesp = SectionCase {
        lesp_critical: Some(0.3),
        ..ns.clone()
    };
    assert_eq!(cache.get(&other_lesp, &design), Some(result(0.3)));
    let deforming_ldvm = SectionCase {
        deformation,
        ..ldvm.clone()
    };
    assert_eq!(cache.get(&deforming_ldvm, &design), None);

    let written = serde_json::to_value(&ldvm).unwrap();
    assert!(written.get("model").is_none(), "{written}");
    let read: SectionCase = serde_json::from_value(written).unwrap();
    assert_eq!(read, ldvm);
    let read: SectionCase = serde_json::from_value(serde_json::to_value(&ns).unwrap()).unwrap();
    assert_eq!(read, ns);
    assert_ne!(key(&ldvm, &design), key(&ns, &design));
}

/// One Navier–Stokes evaluation of the FWAV's mid-span section flapping
/// at 11 Hz, ±30° in a vertical stroke plane (k = 0.69, a plunge of
/// `r sin 30° = 0.63` chords, Strouhal number `2 f h / U = 0.27`), at its
/// chord Reynolds number (12,300), through `SectionCase::evaluate`, on a
/// coarse grid. What the physics fixes:
/// - the section drives the air: mean power positive;
/// - a plunging plate at Strouhal 0.27 makes thrust: Garrick's inviscid
///   thrust of the equivalent harmonic plunge is more than ten times the
///   laminar friction of two faces (`2 x 1.328 / sqrt(Re)`), both
///   computed here: mean CT positive;
/// - thrust power is less than the power put in (the rest is left in the
///   wake and dissipated): efficiency below 1;
/// - the forces include the friction: net CT is CT;
/// - a different model from the LDVM: its CT differs by more than 1 %.
#[test]
fn ns_evaluation_of_a_flapping_section_end_to_end() {
    let case = SectionCase {
        cycles: 3,
        ..ns_case(coarse_plate())
    };
    let kinematics = FlappingKinematics::from_degrees([11.0, 30.0, 0.0, 90.0]);
    let clock = std::time::Instant::now();
    let r = case.evaluate(&kinematics).unwrap();
    let seconds = clock.elapsed().as_secs_f64();
    let ldvm = SectionCase {
        cycles: 3,
        ..SectionCase::fwav_mid_span()
    }
    .evaluate(&kinematics)
    .unwrap();
    println!(
        "NS ({seconds:.1} s, Re {:.0}): k {:.3}, CT {:.4}, CP {:.4}, efficiency {:.4}, CT change \
         {:+.3}; LDVM: CT {:.4} (net {:.4}), CP {:.4}, net efficiency {:.4}",
        case.reynolds(),
        r.reduced_frequency,
        r.ct,
        r.cp,
        r.efficiency,
        r.ct_change,
        ldvm.ct,
        ldvm.ct_net,
        ldvm.cp,
        ldvm.efficiency_net
    );
    let (garrick, _, _) = garrick_plunge(
        r.reduced_frequency,
        case.radius / case.chord * 30f64.to_radians().sin(),
    );
    let friction = 2.0 * 1.328 / case.reynolds().sqrt();
    println!("Garrick CT {garrick:.3}, laminar friction of two faces {friction:.4}");
    assert!(garrick > 10.0 * friction);
    assert!((r.reduced_frequency - ldvm.reduced_frequency).abs() < 1e-15);
    assert!(r.cp > 0.0, "{r:?}");
    assert!(r.ct > 0.0, "{r:?}");
    assert!(r.efficiency > 0.0 && r.efficiency < 1.0, "{r:?}");
    assert_eq!(r.ct_net, r.ct);
    assert!((r.efficiency_net - r.efficiency).abs() < 1e-12 * r.efficiency);
    assert!(
        (r.ct - ldvm.ct_net).abs() > 0.01 * ldvm.ct_net.abs(),
        "{r:?} {ldvm:?}"
    );
}

/// The same evaluation on the section deforming as a system analysis
/// found (the breathing mid-line below, camber ±3% of the chord): it
/// runs on the moving grid, the deformation changes the answer (CT by
/// more than 1%: measured 0.220 rigid, 0.295 deforming; CP 1.468 and
/// 1.479), and the physics' signs hold (power in, thrust less than it).
#[test]
fn ns_evaluation_of_a_deforming_section() {
    let rigid = SectionCase {
        cycles: 3,
        ..ns_case(coarse_plate())
    };
    let deforming = SectionCase {
        deformation: breathing_section(),
        ..rigid.clone()
    };
    let kinematics = FlappingKinematics::from_degrees([11.0, 30.0, 0.0, 90.0]);
    let a = rigid.evaluate(&kinematics).unwrap();
    let b = deforming.evaluate(&kinematics).unwrap();
    println!(
        "rigid CT {:.4} CP {:.4}; deforming CT {:.4} CP {:.4}",
        a.ct, a.cp, b.ct, b.cp
    );
    assert!(
        b.cp > 0.0 && b.efficiency > 0.0 && b.efficiency < 1.0,
        "{b:?}"
    );
    assert!((b.ct / a.ct - 1.0).abs() > 0.01, "{a:?} {b:?}");
}

/// A Navier–Stokes failure is the evaluation's error carrying the
/// solver's (here a plate too thin to grid, refused before any step).
#[test]
fn ns_failure_is_an_evaluation_error() {
    let case = ns_case(ViscousPlate {
        thickness: 0.001,
        ..coarse_plate()
    });
    let e = case.evaluate(&FlappingKinematics::INITIAL).unwrap_err();
    assert!(
        matches!(
            &e,
            EvaluationError::Viscous(fwav::aero2d::viscous::ViscousError::Thickness(t)) if *t == 0.001
        ),
        "{e:?}"
    );
    assert!(e.to_string().contains("plate thickness 0.001"), "{e}");
}

/// Both models record the system analysis's deformation as modelled,
/// and say so; a section without one is said rigid.
#[test]
fn ns_on_a_deforming_section_says_the_deformation_is_modelled() {
    let deformation = breathing_section();
    let ns = SectionCase {
        deformation: deformation.clone(),
        ..ns_case(ViscousPlate::new(0.04))
    };
    let said = ns.modelled_section();
    println!("{}", said.note);
    assert_eq!(said.model, SectionModelName::Ns);
    assert!(said.deformation_given && said.deformation_modelled);
    assert_eq!(
        said.note,
        "ns: the section deforms as the system analysis found (a plate 0.04 chords thick round \
         the deforming mid-line)"
    );
    let ldvm = SectionCase {
        deformation,
        ..SectionCase::fwav_mid_span()
    }
    .modelled_section();
    assert!(ldvm.deformation_modelled, "{}", ldvm.note);
    let rigid_ns = ns_case(ViscousPlate::new(0.04)).modelled_section();
    assert!(!rigid_ns.deformation_given && !rigid_ns.deformation_modelled);
    assert!(
        rigid_ns.note.starts_with("ns: rigid plate"),
        "{}",
        rigid_ns.note
    );
}

/// A cambered mid-line breathing over the cycle (20 samples of 11
/// points, chords), as a system analysis's `section.json` holds it.
fn breathing_section() -> Vec<Vec<[f64; 2]>> {
    (0..20)
        .map(|i| {
            let camber = 0.03 * (std::f64::consts::TAU * f64::from(i) / 20.0).sin();
            (0..11)
                .map(|j| {
                    let x = f64::from(j) / 10.0;
                    [x, 4.0 * camber * x * (1.0 - x)]
                })
                .collect()
        })
        .collect()
}

/// `fwav kinematics` with `section_model = "ns"` on a deforming section
/// says in its text and its JSON that the section deforms as the system
/// analysis found. Its 21 evaluations come from a cache filled
/// with stand-ins (a cheap LDVM discipline run's results stored under the
/// Navier–Stokes case's key, so the run takes seconds; the Navier–Stokes
/// evaluation itself is tested above): the discipline asks for the same
/// designs given the same results, so it reuses all of them.
#[test]
fn kinematics_command_says_the_ns_section_deforms() {
    use fwav::discipline::kinematic::{optimize, Weights};
    use fwav::optimize::nsga2::Nsga2Config;
    let dir = std::env::temp_dir().join(format!("fwav-discipline-ns-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let toml = "[design]\nsection_model = \"ns\"\n";
    let config = SystemConfig::from_toml(toml).unwrap();
    let stand_in = SectionCase {
        cycles: 3,
        steps_per_cycle: 20,
        lesp_critical: None,
        ..config.section_case()
    };
    let stand_in = SectionCase {
        model: SectionFlowModel::Ldvm,
        ..stand_in
    };
    let ldvm_cache = EvaluationCache::new();
    let weights = Weights {
        thrust: config.design.thrust_weight,
        efficiency: config.design.efficiency_weight,
    };
    let nsga = Nsga2Config {
        seed: config.design.seed,
        ..Nsga2Config::default()
    };
    let space = config.design_space();
    let ldvm = optimize(
        &stand_in,
        &space,
        config.kinematics(),
        weights,
        &nsga,
        &ldvm_cache,
    )
    .unwrap();
    let ns_case = SectionCase {
        deformation: breathing_section(),
        ..config.section_case()
    };
    let ns_cache = EvaluationCache::new();
    let evaluated = std::iter::once(&ldvm.initial)
        .chain(&ldvm.runs)
        .chain(ldvm.candidates.iter().map(|c| &c.confirmation));
    for e in evaluated {
        ns_cache.insert(&ns_case, &e.design, *e.result.as_ref().unwrap());
    }
    let cache_file = dir.join("evaluations.json");
    ns_cache.save(&cache_file).unwrap();
    let section_file = dir.join("section.json");
    let section = serde_json::json!({
        "format": "fwav-section-history",
        "format_version": 1,
        "samples": breathing_section(),
    });
    std::fs::write(&section_file, section.to_string()).unwrap();
    let config_file = dir.join("ns.toml");
    std::fs::write(&config_file, toml).unwrap();

    let run = |json: bool| {
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_fwav"));
        command.arg("kinematics").arg("--config").arg(&config_file);
        command.arg("--section").arg(&section_file);
        command.arg("--cache").arg(&cache_file);
        if json {
            command.arg("--json");
        }
        let out = command.output().unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    let text = run(false);
    println!("{text}");
    assert!(
        text.starts_with("section model: ns: the section deforms as the system analysis found"),
        "{text}"
    );
    let json: serde_json::Value = serde_json::from_str(&run(true)).unwrap();
    assert_eq!(json["section"]["model"], "ns");
    assert_eq!(json["result"]["section"]["deformation_modelled"], true);
    // The Navier–Stokes flow's own scatter sets a margin (the LDVM's is 0).
    assert!(json["result"]["adoption_margin"].as_f64().unwrap() > 0.0);
    assert!(text.contains("a candidate had to beat the initial design's combined objective by"));
    assert!(json["result"]["section"]["note"]
        .as_str()
        .unwrap()
        .starts_with("ns: the section deforms as the system analysis found"));
    let cached = EvaluationCache::load(&cache_file).unwrap();
    assert_eq!(cached.len(), ns_cache.len(), "no evaluation was run");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A design run's `report.md` says which 2D model each cycle's
/// evaluations used and, for the Navier–Stokes model on the system
/// analysis's deforming section, that the section deforms, and the margin
/// a candidate had to clear.
#[test]
fn design_report_says_the_ns_section_deforms() {
    use fwav::discipline::section_model::ModelledSection;
    use fwav::mdois::summary::{CycleSummary, KinematicsSummary, Summary};
    let design = FlappingKinematics::INITIAL;
    let said = ModelledSection::new(&SectionFlowModel::ns(0.04), true);
    let summary = Summary {
        format: "fwav-design-summary".into(),
        format_version: 1,
        finished: false,
        outcome: "unfinished".into(),
        converged_cycle: None,
        max_cycles: 5,
        kinematics_tolerance_of_range: 0.01,
        layout_tolerance: 0.0,
        cycles: vec![CycleSummary {
            cycle: 1,
            kinematics: design,
            carbon_mass_fraction: 0.3,
            system: None,
            aerodynamic: Some(KinematicsSummary {
                analysed_2d: None,
                chosen: None,
                proposed: design,
                proposed_2d: None,
                evaluations_reused: 0,
                adoption_margin: 0.066,
                section: Some(said),
                seconds: 1.0,
                run: 1,
            }),
            structural: None,
            change: None,
            seconds: 1.0,
        }],
        initial: None,
        final_design: None,
        comparison: None,
        stage_seconds: 1.0,
        runs: 1,
        actuator: None,
    };
    let report = fwav::mdois::output::report::markdown(&summary, &[], &[]);
    assert!(
        report.contains(
            "- cycle 1: ns: the section deforms as the system analysis found (a plate 0.04 \
             chords thick round the deforming mid-line); a candidate had to beat the analysed \
             design's combined objective by 0.066, the scatter of two runs (the flow does not \
             repeat from stroke to stroke)\n"
        ),
        "{report}"
    );
}

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

/// The default plate, its rings and Courant number replaced by
/// `FWAV_NS_RADIAL` and `FWAV_NS_COURANT` where set.
fn env_plate() -> ViscousPlate {
    let default = ViscousPlate::new(0.04);
    ViscousPlate {
        radial: std::env::var("FWAV_NS_RADIAL").map_or(default.radial, |v| v.parse().unwrap()),
        courant: std::env::var("FWAV_NS_COURANT").map_or(default.courant, |v| v.parse().unwrap()),
        ..default
    }
}

/// The RMS relative change of the rows' net CT and net efficiency from
/// the default resolution's, the first cycle's rows of the NS design run
/// on the same section (docs/ns-design, `l18-384x320.txt`).
fn rows_against_the_default(runs: &[fwav::discipline::kinematic::Evaluated]) -> (f64, f64) {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/ns-design/l18-384x320.txt");
    let text = std::fs::read_to_string(&path).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .filter_map(|l| {
            let cells: Vec<f64> = l.split('|').filter_map(|c| c.trim().parse().ok()).collect();
            (cells.len() == 9).then_some(cells)
        })
        .collect();
    assert_eq!(rows.len(), runs.len(), "{}", path.display());
    let (mut thrust, mut efficiency) = (0.0, 0.0);
    for (row, run) in rows.iter().zip(runs) {
        assert_eq!(run.design.degrees(), [row[1], row[2], row[3], row[4]]);
        let r = run.result.as_ref().unwrap();
        thrust += (r.ct_net / row[5] - 1.0).powi(2);
        efficiency += (r.efficiency_net / row[6] - 1.0).powi(2);
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
/// default's (the NS design run's first cycle, docs/ns-design,
/// `l18-384x320.txt`): at Courant 4 (2026-12-04) the 19 evaluations
/// took 1,712 s, and the rows' CT moved by 5.59 % RMS and their
/// efficiency by 4.95 %, so one evaluation's scatter is 3.95 % and 3.50 %
/// (`NS_WINDOW_SCATTER`, which must be these within 10 %). The choice
/// moved with them: best row 13 Hz, ±40°, −10°, plane 70° (2.595; at
/// Courant 3 13 Hz, ±30°, 0°, 70°, 2.580), ANOM 13 Hz, ±40°, 10°, 110°
/// (Courant 3: ±30°, 0°, 110°); frequency level means 1.56, 1.93, 2.47
/// (1.61, 2.05, 2.55).
#[test]
#[ignore = "benchmark (17 to 25 min; over the issue's 10): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns::ns_discipline_benchmark`"]
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
    if plate != ViscousPlate::new(0.04) {
        // Another step: the rows against the default's, the declared
        // scatter's measurement.
        let (thrust, efficiency) = rows_against_the_default(&result.runs);
        println!(
            "against the default step's rows: RMS change CT {:.2} %, efficiency {:.2} %",
            100.0 * thrust,
            100.0 * efficiency
        );
        if plate.courant == 4.0 {
            let one = |rms: f64| rms / std::f64::consts::SQRT_2;
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

/// One Navier–Stokes evaluation of the default FWAV section at the
/// default resolution, the 4 % plate deforming as the default design's
/// first system analysis found (`host/tests/data/fwav_cycle1_section.json`,
/// 40 samples of 53 points: a heave of ±0.13 chords from the wing's
/// bending, a pitch of about ±1.4° and little camber) beside the rigid
/// plate, at the built-in initial kinematics: the cost of the moving grid
/// and what the deformation changes. Measured on the default 384 x 320
/// (2026-12-03, a slow hour): rigid 118.3 s, deforming 190.4 s (CT
/// 0.0850, efficiency 0.0341), which fails the 60 s; about 43 s
/// and 77 s in a normal hour (on 384 x 240: 31.9 s and 57.3 s).
#[test]
#[ignore = "benchmark (2 to 5 min); fails the issue's 60 s (deforming: about 77 s in a normal hour, 190 s in a slow one): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns::ns_deforming_evaluation_benchmark`"]
fn ns_deforming_evaluation_benchmark() {
    let rigid = ns_case(ViscousPlate::new(0.04));
    let deforming = deforming_case(ViscousPlate::new(0.04));
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
            "{name}: {s:.1} s, CT {:.4}, CP {:.4}, efficiency {:.4}, CT change {:+.4}",
            r.ct, r.cp, r.efficiency, r.ct_change
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
/// another step").
#[test]
#[ignore = "benchmark (about 10 min in a slow hour): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns::ns_deforming_window_scatter_benchmark`"]
fn ns_deforming_window_scatter_benchmark() {
    let design = env_design();
    let plate = ViscousPlate {
        spin_up: false,
        ..env_plate()
    };
    let at_default_resolution = plate == ViscousPlate::new(0.04);
    let case = SectionCase {
        cycles: 12,
        ..deforming_case(plate)
    };
    let clock = std::time::Instant::now();
    let (history, _) = case.history(&design).unwrap();
    let (windows, thrust, efficiency) =
        crate::viscous_default_section::window_scatter(&history.ct, &history.cp);
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
    for (measured, declared) in [
        (thrust, NS_WINDOW_SCATTER.0),
        (efficiency, NS_WINDOW_SCATTER.1),
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
#[ignore = "fails (CT -17 %, efficiency -16 % against the full grid's window; docs/ns-design, \"The spin-up\"), and heavy (about 3 min): `cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns::a_spin_up_keeps_the_deforming_window_scores`"]
fn a_spin_up_keeps_the_deforming_window_scores() {
    let full = deforming_case(ViscousPlate::new(0.04));
    let spun = SectionCase {
        model: SectionFlowModel::Ns(ViscousPlate {
            spin_up: true,
            ..ViscousPlate::new(0.04)
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
/// sets the strokes (the last two scored; 4 by default). Measured
/// (2026-12-04), CT and efficiency at Courant 4 / 3 / 1.5: row 2 (the
/// initial design) 0.0895 / 0.0850 / 0.0855 and 0.0356 / 0.0341 /
/// 0.0342; row 4 (9 Hz, ±20°, 0°, 90°) 0.0370 / 0.0328 / 0.0364 and
/// 0.0454 / 0.0406 / 0.0452; row 14 (11, 40, −10, 90) 0.1081 / 0.1216 /
/// 0.1270 and 0.0242 / 0.0270 / 0.0285; row 18 (13, 30, −10, 90) 0.1256
/// / 0.1162 / 0.1288 and 0.0336 / 0.0314 / 0.0344 (898 s for the four at
/// Courant 1.5). Six strokes, strokes 5–6 scored, Courant 4 / 3: row 4
/// 0.0353 / 0.0339 and 0.0446 / 0.0422 (+4.1 %, +5.7 %), row 18 0.1168
/// / 0.1164 and 0.0311 / 0.0313 (+0.3 %, −0.6 %) (247 s and 322 s for
/// the pair); row 7 (9, 30, −10, 110) 0.0531 / 0.0562 and 0.0370 /
/// 0.0384, row 11 (11, 20, −10, 110) 0.0536 / 0.0512 and 0.0513 /
/// 0.0500, row 14 0.1202 / 0.0905 (+33 %) and 0.0268 / 0.0205, row 6
/// (13, 40, −10, 70) 0.1638 / 0.1670 and 0.0254 / 0.0260 (552 s and
/// 725 s for the four).
#[test]
#[ignore = "benchmark (about 15 min at Courant 1.5 for four designs): `FWAV_NS_COURANT=1.5 FWAV_NS_DESIGNS=\"9,20,0,90;11,40,-10,90\" cargo test --release -p fwav --test integration -- --ignored --nocapture discipline_ns::ns_window_time_step_benchmark`"]
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
