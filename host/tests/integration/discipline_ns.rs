//! The aerodynamic discipline on the Navier–Stokes section model
//! (`[design] section_model = "ns"`): the setting, the evaluation cache
//! keeping the models apart, one evaluation end to end on a coarse grid,
//! and what was modelled said wherever results are reported. The heavy
//! measurements of the model's scores on the default section are
//! `discipline_ns_scores` (their cost, the rows' records) and
//! `discipline_ns_scatter` (their scatter and convergence).

use fwav::aero2d::theory::garrick_plunge;
use fwav::aero2d::viscous::ViscousSection;
use fwav::aeroelastic::FlappingKinematics;
use fwav::config::template::commented_toml;
use fwav::config::SystemConfig;
use fwav::discipline::cache::{key, EvaluationCache};
use fwav::discipline::section::{EvaluationError, SectionCase, SectionResult};
use fwav::discipline::section_model::{
    SectionFlowModel, SectionModelName, ViscousPlate, LDVM_SHEDDING_DEFORMING_SCATTER,
    LDVM_SHEDDING_SCATTER, NS_LONG_MEAN_SCATTER, NS_WINDOW_SCATTER,
};

use crate::program::fwav_command;

/// A 12 % plate on 80 × 48 nodes out to 15 chords (exponential
/// stretching), first cell a fifth of the boundary layer: coarse, for a
/// test of seconds (the default is 384 × 256 out to 30 chords); 80 round
/// are the fewest whose wall cells the Reynolds number of the built-in
/// mid-span section (12,329) lets pass (78, `ViscousError::Unresolved`).
fn coarse_plate() -> ViscousPlate {
    ViscousPlate {
        thickness: 0.12,
        around: 80,
        radial: 48,
        far: None,
        outer_chords: 15.0,
        first_cell_layers: 0.2,
        courant: fwav::aero2d::viscous::ViscousSection::DEFAULT_COURANT,
        spin_up: false,
        shape_tolerance: None,
    }
}

/// The built-in mid-span section with the Navier–Stokes model of `plate`.
pub(crate) fn ns_case(plate: ViscousPlate) -> SectionCase {
    SectionCase {
        model: SectionFlowModel::Ns(plate),
        ..SectionCase::fwav_mid_span()
    }
}

/// `section_model` reads "ldvm" (the default) or "ns", with the plate's
/// thickness at the default resolution and no spin-up (a plate given
/// one spins up through the two strokes before the scored ones); the
/// strokes each analysis runs, 4 by default (strokes 3 and 4 scored),
/// are `section_cycles`, and the scatter of the adoption margin follows
/// them; `fwav init`'s template writes the three keys with their docs.
#[test]
fn section_model_setting_chooses_the_model() {
    let default = SystemConfig::from_toml("").unwrap();
    assert_eq!(default.design.section_model, SectionModelName::Ldvm);
    assert_eq!(default.section_case().model, SectionFlowModel::Ldvm);
    let ns = SystemConfig::from_toml("[design]\nsection_model = \"ns\"\n").unwrap();
    assert_eq!(
        ns.section_case().model,
        SectionFlowModel::Ns(ViscousPlate::new(ViscousSection::DEFAULT_THICKNESS))
    );
    let thick =
        SystemConfig::from_toml("[design]\nsection_model = \"ns\"\nns_thickness = 0.1\n").unwrap();
    let SectionFlowModel::Ns(plate) = thick.section_case().model else {
        panic!("not the NS model");
    };
    assert_eq!(
        (plate.thickness, plate.around, plate.radial, plate.spin_up),
        (0.1, 384, 256, false)
    );
    assert_eq!(
        plate.far,
        Some(fwav::aero2d::viscous::ViscousSection::DEFAULT_FAR)
    );
    assert_eq!(plate.section().spin_up_periods, 0.0);
    let spun = ViscousPlate {
        spin_up: true,
        ..plate
    };
    assert_eq!(spun.section().spin_up_periods, 2.0);
    assert_eq!(default.section_case().cycles, 4);
    assert_eq!(default.section_case().scored_cycles(), 2);
    let long = SystemConfig::from_toml("[design]\nsection_cycles = 12\n").unwrap();
    assert_eq!(long.section_case().scored_cycles(), 10);
    // The adoption margin's scatter: the shedding LDVM's whatever the
    // strokes scored, on a rigid or a deforming section, the attached
    // LDVM's none; the Navier–Stokes model's follows the strokes scored,
    // the two-stroke window's, and the long mean's from ten strokes on,
    // deforming or not.
    assert_eq!(long.section_case().scatter(), LDVM_SHEDDING_SCATTER);
    assert_eq!(default.section_case().scatter(), LDVM_SHEDDING_SCATTER);
    let attached = SystemConfig::from_toml("[design]\nlesp_critical = 0.0\n").unwrap();
    assert_eq!(attached.section_case().scatter(), (0.0, 0.0));
    let mut deforming = default.section_case();
    deforming.deformation = vec![vec![[0.0, 0.0], [1.0, 0.0]]; 8];
    assert_eq!(deforming.scatter(), LDVM_SHEDDING_DEFORMING_SCATTER);
    deforming.lesp_critical = None;
    assert_eq!(deforming.scatter(), (0.0, 0.0));
    assert_eq!(ns.section_case().scatter(), NS_WINDOW_SCATTER);
    let mut ns_deforming = ns.section_case();
    ns_deforming.deformation = vec![vec![[0.0, 0.0], [1.0, 0.0]]; 8];
    assert_eq!(ns_deforming.scatter(), NS_WINDOW_SCATTER);
    let long_ns =
        SystemConfig::from_toml("[design]\nsection_model = \"ns\"\nsection_cycles = 12\n").unwrap();
    assert_eq!(long_ns.section_case().scatter(), NS_LONG_MEAN_SCATTER);
    let eleven = SectionCase {
        cycles: 11,
        ..long_ns.section_case()
    };
    assert_eq!(eleven.scatter(), NS_WINDOW_SCATTER);
    let template = commented_toml(&SystemConfig::default()).unwrap();
    assert!(
        template.contains("section_model = \"ldvm\"\n"),
        "{template}"
    );
    assert!(template.contains("ns_thickness = 0.04\n"), "{template}");
    assert!(template.contains("section_cycles = 4\n"), "{template}");
    assert!(
        template.contains("\"ldvm\" or \"ns\".\nsection_model"),
        "{template}"
    );
}

/// An unknown model, a model that is not a word, a plate thickness out
/// of the solver's range and fewer than three cycles (none scored after
/// the start's two) are refused naming the key, the value and what is
/// allowed.
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
    let e = SystemConfig::from_toml("[design]\nsection_cycles = 2\n")
        .unwrap_err()
        .to_string();
    assert_eq!(e, "design.section_cycles = 2 is outside 3..=40");
}

/// The Navier–Stokes model at a mid-span Reynolds number its grid cannot
/// resolve (its wall cells longer than the laminar boundary layer is
/// thick at the trailing edge, `5 c / √Re`, Blasius) is refused when the
/// file is read, naming what sets it and the highest it resolves; the
/// same flight on the LDVM, and the NS model at the built-in flight
/// (Re 12,329) and at 20 m/s on the built-in wing (Re 82,192; at 50 m/s
/// its lowest frequency level would be refused as too many steps), are
/// taken; the default grid resolves up to Re 338,773.
#[test]
fn ns_model_refuses_a_reynolds_number_its_grid_cannot_resolve() {
    let fast_wide = "[flight]\nspeed_m_s = 50.0\n[wing]\nroot_chord_m = 0.2\ntip_chord_m = 0.2\n";
    let e = SystemConfig::from_toml(&format!("{fast_wide}[design]\nsection_model = \"ns\"\n"))
        .unwrap_err()
        .to_string();
    for says in [
        "flight.speed_m_s = 50",
        "0.2 m chord",
        "Re 684932",
        "cannot resolve",
        "up to Re 338773",
        "section_model = \"ldvm\"",
    ] {
        assert!(e.contains(says), "{says}: {e}");
    }
    assert!(SystemConfig::from_toml(fast_wide).is_ok());
    assert!(SystemConfig::from_toml("[design]\nsection_model = \"ns\"\n").is_ok());
    assert!(SystemConfig::from_toml(
        "[flight]\nspeed_m_s = 20.0\n[design]\nsection_model = \"ns\"\n"
    )
    .is_ok());
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
/// serves any critical LESP (it takes none); an LDVM case is written as
/// before the model existed (its key adds the LDVM's results revision, so
/// cache files from before 2026-12-07's LDVM changes are recomputed).
#[test]
fn evaluation_cache_keeps_the_models_apart() {
    let design = FlappingKinematics::INITIAL;
    let ldvm = SectionCase::fwav_mid_span();
    let ns = ns_case(ViscousPlate::new(ViscousSection::DEFAULT_THICKNESS));
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

    // The grid's stretching is part of the key: the exponential grid of
    // the same rings (the default until 2026-12-05 on 320) is another
    // grid; a plate written without the key was on the exponential one.
    let exponential = ViscousPlate {
        far: None,
        ..ViscousPlate::new(ViscousSection::DEFAULT_THICKNESS)
    };
    assert_eq!(cache.get(&ns_case(exponential), &design), None);
    let mut written = serde_json::to_value(exponential).unwrap();
    written.as_object_mut().unwrap().remove("far");
    let read: ViscousPlate = serde_json::from_value(written).unwrap();
    assert_eq!(read, exponential);
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

/// The deformation's rigid part moves the frame (`run_deflecting`): a
/// history that is rigid alone (the default section's first system
/// analysis's, each sample's straight mid-line carried by its rigid fit)
/// gives the same loads whether its change of shape, nothing but
/// rounding, runs on the moving grid (`Some(0)`) or is left out
/// (`Some(0.01)`): the change taken out of each sample is the one
/// the frame carries (a wrong sign or a turn about another point would
/// leave a shape that moves the grid by the heave, 0.13 chords). The
/// whole history on the moving grid (`None`) differs by the moving
/// grid's error on this coarse grid, and is no check. Measured: CT
/// 0.241348 and 0.241576 (0.09 %), CP 2.569262 and 2.569694 (0.02 %),
/// the two plates' contours built two ways (the undeformed plate's, and
/// the membrane round each sample's mid-line); with the turn taken out
/// the wrong way round, CT −9.5 %.
#[test]
fn a_rigid_deformation_is_the_frames_motion() {
    use crate::discipline_ns_scores::rigid_fit;
    use fwav::aeroelastic::handoff::section::SectionFile;
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/fwav_cycle1_section.json");
    let rigid: Vec<Vec<[f64; 2]>> = SectionFile::read(&path)
        .unwrap()
        .samples
        .iter()
        .map(|s| rigid_fit(s, true))
        .collect();
    let kinematics = FlappingKinematics::INITIAL;
    let run = |shape_tolerance| {
        SectionCase {
            cycles: 3,
            deformation: rigid.clone(),
            ..ns_case(ViscousPlate {
                shape_tolerance,
                ..coarse_plate()
            })
        }
        .evaluate(&kinematics)
        .unwrap()
    };
    let (frame, grid) = (run(Some(0.01)), run(Some(0.0)));
    println!(
        "frame CT {:.6} CP {:.6}; shape on the moving grid CT {:.6} CP {:.6}",
        frame.ct, frame.cp, grid.ct, grid.cp
    );
    assert!(
        (grid.ct / frame.ct - 1.0).abs() < 3e-3,
        "{frame:?} {grid:?}"
    );
    assert!(
        (grid.cp / frame.cp - 1.0).abs() < 3e-3,
        "{frame:?} {grid:?}"
    );
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
        ..ns_case(ViscousPlate::new(ViscousSection::DEFAULT_THICKNESS))
    };
    let said = ns.modelled_section();
    println!("{}", said.note);
    assert_eq!(said.model, SectionModelName::Ns);
    assert!(said.deformation_given && said.deformation_modelled);
    assert_eq!(
        said.note,
        "ns: the section deforms as the system analysis found (a plate 0.04 chords thick round \
         the deforming mid-line), scored over strokes 3 to 4"
    );
    let ldvm = SectionCase {
        deformation,
        ..SectionCase::fwav_mid_span()
    }
    .modelled_section();
    assert!(ldvm.deformation_modelled, "{}", ldvm.note);
    let rigid_ns = ns_case(ViscousPlate::new(ViscousSection::DEFAULT_THICKNESS)).modelled_section();
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
        let mut command = fwav_command(&["kinematics", "--config"]);
        command.arg(&config_file);
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
    let said = ModelledSection::new(&SectionFlowModel::ns(0.04), true, 4);
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
             chords thick round the deforming mid-line), scored over strokes 3 to 4; a candidate \
             had to beat the analysed design's combined objective by 0.066, the scatter of two \
             runs (the scores move with the time step, or from stroke to stroke)\n"
        ),
        "{report}"
    );
}
