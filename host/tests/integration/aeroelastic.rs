//! The system analysis's parts against independent solutions.

use fwav::aeroelastic::floating_frame::FloatingFrameWing;
use fwav::aeroelastic::{
    run, FlappingKinematics, FlightCondition, SystemResult, SystemSettings, WingModel,
};
use fwav::shell::dynamics::GeneralizedAlpha;
use fwav::shell::material::Layer;
use fwav::shell::nonlinear_dynamics::NonlinearTransient;
use fwav::shell::wing::Planform;
use nalgebra::Vector3;

/// A coarse copy of the built-in wing (16 x 6 elements).
fn coarse_wing(carbon: f64) -> WingModel {
    let planform = Planform {
        span_elements: 16,
        chord_elements: 6,
        ..Planform::FWAV
    };
    WingModel::new(planform, &Layer::CARBON, &Layer::MYLAR, None, carbon).unwrap()
}

/// Largest difference of the elastic tip deflection (flapping frame)
/// between the floating-frame shell and the co-rotational shell over two
/// cycles of flapping in vacuum from rest, and the peak deflection, m.
fn vacuum_flapping(wing: &WingModel, kinematics: &FlappingKinematics) -> (f64, f64) {
    let mesh = &wing.wing.mesh;
    let steps_per_cycle = 100;
    let settings = GeneralizedAlpha {
        dt: kinematics.period() / steps_per_cycle as f64,
        rho_inf: 0.9,
        mass_damping: 0.0,
        stiffness_damping: 0.0,
    };
    let held = wing.wing.clamped_dofs();
    let floating = FloatingFrameWing::new(mesh, &wing.sections, &held, settings).unwrap();
    let nonlinear = NonlinearTransient::new(mesh, &wing.sections, &held, settings).unwrap();
    let zero = vec![Vector3::zeros(); mesh.nodes.len()];
    let no_load = vec![0.0; mesh.dofs()];
    let tip = mesh.nodes.len() - 1;
    let start = kinematics.motion(0.0).rotation;
    let mut previous = floating.inertial_loads(&kinematics.motion(0.0), &zero, &zero);
    let mut state = floating.start(&previous);
    let mut ground = nonlinear.rest();
    let (mut worst, mut peak) = (0.0f64, 0.0f64);
    for k in 1..=2 * steps_per_cycle {
        let motion = kinematics.motion(k as f64 * settings.dt);
        // Floating frame: the inertial loads at the new displacement and
        // velocity, iterated to a fixed point as the coupled analysis does.
        let mut next = state.clone();
        let mut load = previous.clone();
        for _ in 0..6 {
            load = floating.inertial_loads(
                &motion,
                &floating.translations(&next),
                &floating.velocities(&next),
            );
            next = floating.step(&state, &previous, &load);
        }
        previous = load;
        state = next;
        // Ground frame: the root nodes turned by the rotation since t = 0
        // (the co-rotational model starts flat).
        let q = motion.rotation * start.inverse();
        let prescribed = wing
            .wing
            .root_nodes
            .iter()
            .map(|&n| (n, q * mesh.nodes[n] - mesh.nodes[n], q))
            .collect();
        nonlinear.step(&mut ground, &no_load, &prescribed).unwrap();
        let x = mesh.nodes[tip] + ground.configuration.displacement[tip];
        let elastic_ground = q.inverse() * x - mesh.nodes[tip];
        let elastic_floating = floating.translations(&state)[tip];
        worst = worst.max((elastic_ground.z - elastic_floating.z).abs());
        peak = peak.max(elastic_ground.z.abs());
    }
    (worst, peak)
}

/// The floating-frame shell (linear elasticity in the flapping frame with
/// the frame's inertial loads, `aeroelastic::floating_frame`) against the
/// geometrically nonlinear co-rotational shell driven by the same root
/// rotation in the ground frame (an independent formulation: there the
/// nodes carry the large rotation themselves). The full-carbon coarse wing
/// (first mode 26 Hz) flaps at 11 Hz in vacuum from rest, undamped; at ±3°
/// the elastic tip deflection in the flapping frame agrees within 3% of its
/// peak over two cycles (measured 1.3%, peak 3.6 mm). At ±10° and ±30° the
/// figures are printed, not asserted: the deflection reaches 8% and 23% of
/// the span, the linear model's frequency drifts from the stiffened
/// nonlinear one, and the undamped start-up vibration dephases (measured
/// 11% and 51% of the peak) — the floating frame is a small-deflection
/// model, as its module says.
#[test]
fn floating_frame_matches_the_corotational_shell_in_vacuum() {
    let wing = coarse_wing(1.0);
    for amplitude_deg in [3.0f64, 10.0, 30.0] {
        let kinematics = FlappingKinematics {
            amplitude: amplitude_deg.to_radians(),
            ..FlappingKinematics::INITIAL
        };
        let (worst, peak) = vacuum_flapping(&wing, &kinematics);
        println!(
            "flapping ±{amplitude_deg}° in vacuum: tip peak {:.2} mm, worst difference {:.1}% of it",
            1e3 * peak,
            100.0 * worst / peak
        );
        if amplitude_deg == 3.0 {
            assert!(peak > 1e-3, "{peak}");
            assert!(worst < 0.03 * peak, "{worst} of {peak}");
        }
    }
}

fn coarse_settings() -> SystemSettings {
    SystemSettings {
        cycles: 3,
        steps_per_cycle: 40,
        chordwise_panels: 4,
        spanwise_panels: 8,
        ..SystemSettings::default()
    }
}

fn analyse(wing: &WingModel, settings: &SystemSettings) -> SystemResult {
    run(
        wing,
        &FlappingKinematics::INITIAL,
        &FlightCondition::FWAV,
        settings,
        0,
        |_, _| {},
    )
    .unwrap()
}

/// The coupling's limits: a wing a thousand times stiffer than carbon
/// flaps like the rigid wing (mean CT within 0.5%; measured 0.01%), and the
/// coupled answer hardly depends on the coupling tolerance: 1e-6 (the
/// default) against 1e-8 moves the mean CT by less than 0.01% (1.3285
/// both; 0.17% with the former 0.01 c vortex core), asserted below 0.5%,
/// a quarter of the lattice's own discretization change in
/// `time_step_and_lattice_convergence` (this bound was 0.1% while the loads
/// went to the shell as point forces, where the measured change was 0.09%;
/// the distributed pressure loads made it 0.17%).
#[test]
fn coupling_reaches_its_limits() {
    let settings = coarse_settings();
    let rigid = analyse(
        &coarse_wing(1.0),
        &SystemSettings {
            rigid: true,
            ..settings
        },
    );
    let stiff_layer = Layer {
        young: 1e3 * Layer::CARBON.young,
        ..Layer::CARBON
    };
    let planform = coarse_wing(1.0).planform;
    let stiff = WingModel::new(planform, &stiff_layer, &Layer::MYLAR, None, 1.0).unwrap();
    let stiff = analyse(&stiff, &settings);
    let flexible = analyse(&coarse_wing(1.0), &settings);
    let tight = analyse(
        &coarse_wing(1.0),
        &SystemSettings {
            coupling_tolerance: 1e-8,
            max_subiterations: 60,
            ..settings
        },
    );
    let change = |a: f64, b: f64| (a / b - 1.0).abs();
    println!(
        "mean CT: rigid {:.4}, 1000x stiffer {:.4}, carbon {:.4} (coupled to 1e-8: {:.4}); sub-iterations a step {:.1} / {:.1}",
        rigid.means.ct,
        stiff.means.ct,
        flexible.means.ct,
        tight.means.ct,
        mean_subiterations(&flexible),
        mean_subiterations(&tight)
    );
    assert!(change(stiff.means.ct, rigid.means.ct) < 0.005);
    assert!(change(flexible.means.ct, tight.means.ct) < 0.005);
    assert!(tight.steps.iter().all(|s| s.residual < 1e-8));
}

fn mean_subiterations(r: &SystemResult) -> f64 {
    r.steps.iter().map(|s| s.subiterations as f64).sum::<f64>() / r.steps.len() as f64
}

/// Time-step and lattice convergence of the coupled analysis (coarse shell
/// mesh, 2 cycles): halving the step (20, 40, 80 steps a cycle) changes
/// the mean CT by -1.30% then -0.07% (asserted: the second change under
/// half the first); refining the lattice by 1.5 each way (4 x 8, 6 x 12,
/// 9 x 18 panels) by -1.46% then -0.73% (asserted: the second change
/// smaller than the first). Doubling instead (4 x 8, 8 x 16, 16 x 32)
/// gave -2.03% then +0.45%, which puts the 8 x 16 default within about
/// half a percent of the lattice limit (the heaving plate of
/// `uvlm.rs` converges to 0.4%), but that form of the test took 48 s
/// here against this one's 18 s. With the former 0.01 c vortex core the
/// doubling's changes were -1.80% and -0.47%, -4.17% and -1.95%: the
/// thinner cores of the wake passing the wing made the answer depend more
/// on the discretization.
#[test]
fn time_step_and_lattice_convergence() {
    let wing = coarse_wing(1.0);
    let base = SystemSettings {
        cycles: 2,
        ..coarse_settings()
    };
    let ct = |steps: usize, nc: usize, ns: usize| {
        analyse(
            &wing,
            &SystemSettings {
                steps_per_cycle: steps,
                chordwise_panels: nc,
                spanwise_panels: ns,
                ..base
            },
        )
        .means
        .ct
    };
    let time = [ct(20, 4, 8), ct(40, 4, 8), ct(80, 4, 8)];
    let lattice = [time[1], ct(40, 6, 12), ct(40, 9, 18)];
    for (name, c) in [
        ("steps a cycle 20/40/80", time),
        ("lattice 4x8/6x12/9x18", lattice),
    ] {
        let (first, second) = (c[1] / c[0] - 1.0, c[2] / c[1] - 1.0);
        println!(
            "{name}: mean CT {:.4} {:.4} {:.4} (changes {:+.2}%, {:+.2}%)",
            c[0],
            c[1],
            c[2],
            100.0 * first,
            100.0 * second
        );
        let factor = if name.starts_with("steps") { 0.5 } else { 1.0 };
        assert!(second.abs() < factor * first.abs(), "{name}: {c:?}");
    }
}

/// Energy balance of the coupled analysis: over a periodic cycle the work
/// of the drive torque about the flapping axis equals the work done on the
/// air (the wing's kinetic and strain energies return to their values), so
/// the mean of `torque x flapping rate` over the last cycle matches the
/// mean aerodynamic power within 2% (rho_inf = 1, no numerical
/// dissipation; measured +0.90% after 4 cycles; for the
/// rigid wing the two agree to round-off). This checks the inertial loads,
/// the load transfer, the power bookkeeping and how close to periodic the
/// harmonic start brings the wing (from the undeformed wing at rest the
/// fourth cycle was 27% off when measured with the earlier point-load
/// transfer).
#[test]
fn drive_power_balances_the_aerodynamic_power() {
    let settings = SystemSettings {
        rho_inf: 1.0,
        cycles: 4,
        ..coarse_settings()
    };
    let r = analyse(&coarse_wing(1.0), &settings);
    let kinematics = FlappingKinematics::INITIAL;
    let last = &r.steps[r.steps.len() - settings.steps_per_cycle..];
    let n = last.len() as f64;
    let drive = last
        .iter()
        .map(|s| s.drive_torque_nm * kinematics.angle(s.time_s).1)
        .sum::<f64>()
        / n;
    let aero = last.iter().map(|s| s.power_w).sum::<f64>() / n;
    println!(
        "last cycle: drive power {:.5} W, aerodynamic power {:.5} W ({:+.2}%)",
        drive,
        aero,
        100.0 * (drive / aero - 1.0)
    );
    assert!((drive / aero - 1.0).abs() < 0.02);
}

/// The system analysis must fly every wing the structural discipline
/// proposes: the default wing (6760 elements) with the layout of its first
/// ESLSO run (2055 carbon elements, the rest mylar only;
/// `data/default_wing_first_eslso_layout.json`) at the kinematics the first
/// aerodynamic discipline chose (13 Hz, 40°, −10°), every step's coupling
/// converged (measured: worst residual 9.9e-7, 7.8 sub-iterations a step).
///
/// With the former 0.01 c vortex core it diverged at step 129 of 160,
/// stopping the full-size design in its second cycle: from step 58 on some
/// steps' coupling stalled at relative residuals of 4e-2 to 0.7, Aitken's
/// factor swinging between −1.9 and 2. IQN-ILS (Degroote et al. 2009) in
/// place of Aitken diverged too (step 147 without reuse, 19–41 with reuse
/// or a coarser QR filter), and 80 steps a cycle diverged sooner, while a
/// core of 0.03 c or 0.05 c converged every step: the previous stroke's
/// wake passing the deflected mylar panels through 0.75 mm cores made the
/// loads too sensitive to the shape. See
/// [`SystemSettings::core_radius_chords`] for the core now used.
/// (Not the classic added-mass instability: a mylar-only panel carries
/// 0.14 kg/m², more than the air it moves, about 0.09 kg/m² for the whole
/// 7.5 cm chord.)
#[test]
#[ignore = "heavy: the full-size coupled analysis, about 30 s in release (cargo test --release -- --ignored)"]
fn system_analysis_flies_the_first_eslso_layout() {
    let text = include_str!("../data/default_wing_first_eslso_layout.json");
    let value: serde_json::Value = serde_json::from_str(text).unwrap();
    let carbon: Vec<f64> = serde_json::from_value(value["carbon"].clone()).unwrap();
    let wing = WingModel::new(
        Planform::FWAV,
        &Layer::CARBON,
        &Layer::MYLAR,
        Some(&carbon),
        1.0,
    )
    .unwrap();
    let kinematics = FlappingKinematics {
        frequency: 13.0,
        amplitude: 40f64.to_radians(),
        mean_angle: (-10f64).to_radians(),
        stroke_plane: 90f64.to_radians(),
    };
    let result = run(
        &wing,
        &kinematics,
        &FlightCondition::FWAV,
        &SystemSettings::default(),
        0,
        |_, _| {},
    );
    let result = result.expect("the coupled analysis completes");
    // Every step's coupling converged, not merely stopped at its cap.
    let worst = result.steps.iter().fold(0.0f64, |m, s| m.max(s.residual));
    assert!(worst < 1e-4, "worst interface residual {worst:e}");
}
