//! Shell finite elements against classical plate and shell solutions
//! (formulas and values: ../shared/REFERENCES.md).

use fwav::shell::assembly::pressure_loads;
use fwav::shell::material::{Layer, Section};
use fwav::shell::mesh::ShellMesh;
use fwav::shell::modal::modes;
use fwav::validation::shell::{
    flexural_rigidity, leissa_cantilever_mode, nafems_21t, nafems_21t_peak, plate_layer,
    scordelis_lo_roof as scordelis_lo_case, simply_supported, square_plate, sze_liu_lo_end_moment,
    sze_liu_lo_end_moment_path, sze_liu_lo_end_shear, sze_liu_lo_end_shear_path,
    timoshenko_clamped_plate, timoshenko_simply_supported_plate, Strip, Support, SZE_END_MOMENT,
    SZE_END_SHEAR,
};
use nalgebra::Rotation3;

/// Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells (1959),
/// tables 8 and 35 (nu = 0.3): centre deflection 0.00126 q a^4 / D clamped,
/// 0.00406 q a^4 / D simply supported; within 2% on a 16 x 16 mesh (the
/// validation cases `shell/timoshenko-*`), and the error falls as the mesh
/// is refined (4, 8, 16).
#[test]
fn square_plates_under_pressure() {
    for (support, validation, name) in [
        (Support::Clamped, timoshenko_clamped_plate(), "clamped"),
        (
            Support::Simple,
            timoshenko_simply_supported_plate(),
            "simply supported",
        ),
    ] {
        let case = validation.run();
        assert_eq!(case.tolerance, 0.02);
        let reference = case.reference_value;
        let errors: Vec<f64> = [4, 8]
            .iter()
            .map(|&n| {
                let w = square_plate(n, support).unwrap();
                let e = w / reference - 1.0;
                println!("{name} {n}x{n}: w D/(q a^4) = {w:.6} ({:+.2}%)", 100.0 * e);
                e
            })
            .chain(case.error)
            .collect();
        println!(
            "{name} 16x16: w D/(q a^4) = {:.6} ({:+.2}%)",
            case.value.unwrap_or(f64::NAN),
            100.0 * errors.last().unwrap_or(&f64::NAN)
        );
        assert!(case.pass, "{case:?}");
        assert!(errors[2].abs() < errors[0].abs(), "{name}: no convergence");
    }
}

/// Leissa, Vibration of Plates (NASA SP-160, 1969), table 4.30: a square
/// cantilever plate (clamped at x = 0, free elsewhere), nu = 0.3, has
/// `omega a^2 sqrt(rho t / D)` = 3.492, 8.525, 21.43 for its first three
/// modes (1st bending, 1st torsion, 2nd bending); within 2% on 20 x 20
/// (the validation cases `shell/leissa-cantilever-mode*`, one modal
/// analysis; in-plane modes are far higher, so the bending ones are taken
/// from the lowest five).
#[test]
fn cantilever_plate_frequencies() {
    for mode in 1..=3 {
        let case = leissa_cantilever_mode(mode).run();
        println!(
            "cantilever plate mode {mode}: {:.4} vs Leissa {} ({:+.2}%)",
            case.value.unwrap_or(f64::NAN),
            case.reference_value,
            100.0 * case.error.unwrap_or(f64::NAN)
        );
        assert_eq!(case.tolerance, 0.02);
        assert!(case.pass, "{case:?}");
    }
}

/// Scordelis–Lo roof (MacNeal & Harder 1985 benchmark set): cylindrical
/// shell R = 25, L = 50, 80 deg arc, t = 0.25, E = 4.32e8, nu = 0, gravity
/// 90 per unit area, rigid diaphragms at the curved ends. Vertical
/// displacement at the midside of the free edge: 0.3024 (the deep-shell
/// value, REFERENCES.md), within 2% on a 16 x 16 quarter model (the
/// validation case `shell/scordelis-lo-roof`).
#[test]
fn scordelis_lo_roof() {
    let case = scordelis_lo_case().run();
    println!(
        "Scordelis-Lo: {:.4} vs {} ({:+.2}%)",
        case.value.unwrap_or(f64::NAN),
        case.reference_value,
        100.0 * case.error.unwrap_or(f64::NAN)
    );
    assert_eq!((case.reference_value, case.tolerance), (0.3024, 0.02));
    assert!(case.pass, "{case:?}");
}

/// Free vibration in the first mode of a simply supported plate, 40 steps
/// a period, 100 periods: the generalized-alpha scheme with rho_inf = 1 (no
/// numerical dissipation, the default for linear transients) conserves the
/// energy (kinetic + strain) within 1% (measured: to round-off); with
/// rho_inf = 0.9 the loss is printed for the record.
#[test]
fn free_vibration_conserves_energy() {
    use fwav::shell::dynamics::{GeneralizedAlpha, Transient};
    let (a, t) = (1.0, 0.01);
    let mesh = ShellMesh::rectangle(a, a, 8, 8).unwrap();
    let sections = vec![Section::single(&plate_layer(t)); mesh.elements.len()];
    let fixed = simply_supported(&mesh, a, a);
    let first = &modes(&mesh, &sections, &fixed, 1).unwrap()[0];
    let period = 1.0 / first.frequency;
    for rho_inf in [1.0, 0.9] {
        let settings = GeneralizedAlpha {
            dt: period / 40.0,
            rho_inf,
            mass_damping: 0.0,
            stiffness_damping: 0.0,
        };
        let model = Transient::new(&mesh, &sections, &fixed, settings).unwrap();
        let u0: Vec<f64> = model
            .model()
            .map()
            .restrict(&first.shape)
            .iter()
            .map(|v| 1e-3 * v)
            .collect();
        let zero = vec![0.0; u0.len()];
        let mut state = model.start(u0, &zero);
        let e0 = model.energy(&state);
        for _ in 0..4000 {
            model.step(&mut state, &zero);
        }
        let change = model.energy(&state) / e0 - 1.0;
        println!(
            "rho_inf {rho_inf}: energy change over 100 periods {:+.3e}",
            change
        );
        if rho_inf == 1.0 {
            assert!(change.abs() < 0.01, "{change}");
        }
    }
}

/// NAFEMS test 21T (linear transient; REFERENCES.md): simply supported
/// plate 10 x 10 x 1 m, E = 200 GPa, nu = 0.3, rho = 8000 kg/m^3, 1 MPa
/// pressure applied as a step, 2% damping at the fundamental 288.379
/// rad/s (here stiffness-proportional, `a_K = 2 zeta / omega`): static
/// centre deflection 2.333 mm, dynamic peak 4.524 mm at t = 0.0108 s.
/// Within 2% (deflections; the peak is the validation case
/// `shell/nafems-21t-peak`) and 3% (peak time) on a 12 x 12 mesh.
#[test]
fn nafems_21t_step_load() {
    let case = nafems_21t_peak().run();
    let r = nafems_21t().unwrap();
    println!(
        "NAFEMS 21T: static {:.4} mm (2.333), peak {:.4} mm (4.524) at {:.5} s (0.0108)",
        1e3 * r.static_m,
        1e3 * r.peak_m,
        r.peak_time_s
    );
    assert_eq!((case.reference_value, case.tolerance), (4.524, 0.02));
    assert!(case.pass, "{case:?}");
    assert!((1e3 * r.static_m / 2.333 - 1.0).abs() < 0.02);
    assert!((r.peak_time_s / 0.0108 - 1.0).abs() < 0.03);
}

/// Centre deflection of a simply supported Kirchhoff plate `a x a` under a
/// uniform pressure `q` applied as a step at t = 0, undamped, by its modal
/// series (Timoshenko & Woinowsky-Krieger, *Theory of Plates and Shells*,
/// eq. 131 for the static Navier coefficients; each mode answers a step
/// with `1 - cos(omega_mn t)`, `omega_mn = pi^2 (m^2 + n^2) / a^2 sqrt(D /
/// rho h)`), odd m, n up to 99.
fn navier_step_response(a: f64, q: f64, d: f64, mass: f64, t: f64) -> f64 {
    let pi = std::f64::consts::PI;
    let mut w = 0.0;
    for m in (1..100).step_by(2) {
        for n in (1..100).step_by(2) {
            let k2 = ((m * m + n * n) as f64) / (a * a);
            let coefficient = 16.0 * q / (pi.powi(6) * d * (m * n) as f64 * k2 * k2);
            let sign = if ((m + n) / 2 - 1) % 2 == 0 {
                1.0
            } else {
                -1.0
            };
            let omega = pi * pi * k2 * (d / mass).sqrt();
            w += sign * coefficient * (1.0 - (omega * t).cos());
        }
    }
    w
}

/// The step-load response against the modal solution: a simply supported
/// square plate (a = 1 m, a/t = 100, undamped) under a suddenly applied
/// uniform pressure, its centre deflection over two fundamental periods
/// against the Navier modal series of [`navier_step_response`] (sign of
/// the mode at the centre: `sin(m pi/2) sin(n pi/2)`). Within 2% of the
/// peak at every step on a 32 x 32 mesh, 200 steps a period, rho_inf = 1
/// (measured 0.78%; 1.88% on 16 x 16, where the higher modes the step
/// excites are coarser; 0.63% with the step halved too).
#[test]
fn step_load_matches_the_modal_solution() {
    use fwav::shell::dynamics::{GeneralizedAlpha, Transient};
    let (a, t, q) = (1.0, 0.01, 1.0e3);
    let layer = plate_layer(t);
    let d = flexural_rigidity(t);
    let mass = layer.density * t;
    let mesh = ShellMesh::rectangle(a, a, 32, 32).unwrap();
    let sections = vec![Section::single(&layer); mesh.elements.len()];
    let fixed = simply_supported(&mesh, a, a);
    let centre = mesh.nodes_where(|p| (p.x - 0.5).abs() < 1e-9 && (p.y - 0.5).abs() < 1e-9)[0];
    let period = 2.0 * std::f64::consts::PI
        / (2.0 * std::f64::consts::PI.powi(2) / (a * a) * (d / mass).sqrt());
    let settings = GeneralizedAlpha {
        dt: period / 200.0,
        rho_inf: 1.0,
        mass_damping: 0.0,
        stiffness_damping: 0.0,
    };
    let model = Transient::new(&mesh, &sections, &fixed, settings).unwrap();
    let map = model.model().map().clone();
    let f = map.restrict(&pressure_loads(&mesh, &vec![q; mesh.elements.len()]).unwrap());
    let w_dof = map.free(6 * centre + 2).unwrap();
    let mut state = model.start(vec![0.0; f.len()], &f);
    let peak = navier_step_response(a, q, d, mass, 0.5 * period);
    let mut worst: f64 = 0.0;
    for _ in 0..400 {
        model.step(&mut state, &f);
        let exact = navier_step_response(a, q, d, mass, state.time);
        worst = worst.max((state.u[w_dof] - exact).abs() / peak);
    }
    println!(
        "step load: modal peak {:.4e} m, worst difference over two periods {:.2}% of it",
        peak,
        100.0 * worst
    );
    assert!(worst < 0.02, "{worst}");
}

/// Sze, Liu & Lo (2004), Finite Elem. Anal. Des. 40, the cantilever strip
/// under an end moment (L = 12, width 1, t = 0.1, E = 1.2e6, nu = 0,
/// M_max = 2 pi E I / L = 50 pi / 3): it rolls into a semicircle at half
/// the moment (tip -u = 12, w = 2 L / pi = 7.639) and a full circle at
/// M_max (tip back at the root: -u = 12, w = 0). Tip position within 1% of
/// L, 16 x 1 elements, 20 load steps (measured: -u 12.0000, w 7.6517 at
/// half the moment; -u 12.0000, w 0.0000 at the full moment). The
/// semicircle's w is the validation case `shell/sze-liu-lo-end-moment`.
#[test]
fn strip_rolls_into_a_circle_under_an_end_moment() {
    let length = 12.0;
    let tips = sze_liu_lo_end_moment_path().unwrap();
    for ((lambda, (u_ref, w_ref)), (u, w)) in [0.5, 1.0].iter().zip(SZE_END_MOMENT).zip(tips) {
        println!("M/M_max = {lambda}: -u = {u:.4} ({u_ref}), w = {w:.4} ({w_ref})");
        assert!(
            (u - u_ref).abs() < 0.01 * length && (w - w_ref).abs() < 0.01 * length,
            "M/M_max {lambda}: -u {u}, w {w}"
        );
    }
    let case = sze_liu_lo_end_moment().run();
    assert_eq!(
        (case.reference_value, case.tolerance),
        (7.639, 0.01 * length)
    );
    assert!(case.pass, "{case:?}");
}

/// Sze, Liu & Lo (2004), the cantilever strip under an end shear (10 x 1 x
/// 0.1, E = 1.2e6, nu = 0, P_max = 4 in total at the tip, dead load): tip
/// -u = 0.026, 1.604, 3.286 and w = 0.663, 4.933, 6.698 at P/P_max = 0.05,
/// 0.5, 1 (their 16 x 1 reference mesh). Within 2% on 16 x 1, 20 steps
/// (measured: w within 0.01% at all three; -u +1.55% at the smallest load,
/// where it is the difference of nearly equal lengths, 0.00/0.01% else).
/// The tip w at P_max is the validation case `shell/sze-liu-lo-end-shear`.
#[test]
fn strip_under_end_shear() {
    let tips = sze_liu_lo_end_shear_path().unwrap();
    for ((lambda, (u_ref, w_ref)), (u, w)) in [0.05, 0.5, 1.0].iter().zip(SZE_END_SHEAR).zip(tips) {
        println!(
            "P/P_max = {lambda}: -u = {u:.4} ({u_ref}, {:+.2}%), w = {w:.4} ({w_ref}, {:+.2}%)",
            100.0 * (u / u_ref - 1.0),
            100.0 * (w / w_ref - 1.0)
        );
        assert!((w / w_ref - 1.0).abs() < 0.02, "w {w} vs {w_ref}");
        assert!((u / u_ref - 1.0).abs() < 0.02, "u {u} vs {u_ref}");
    }
    let case = sze_liu_lo_end_shear().run();
    assert_eq!((case.reference_value, case.tolerance), (6.698, 0.02));
    assert!(case.pass, "{case:?}");
}

/// The nonlinear transient at small amplitude is the linear one: a simply
/// supported plate released from its first mode at 1% of its thickness
/// (geometric effects ~1e-4), centre deflection over two periods within 1%
/// of the amplitude from the linear generalized-alpha run (same steps;
/// measured 4.7e-4).
#[test]
fn nonlinear_dynamics_reduces_to_linear() {
    use fwav::shell::dynamics::{GeneralizedAlpha, Transient};
    use fwav::shell::nonlinear_dynamics::{NonlinearTransient, Predictor};
    let (a, t) = (1.0, 0.01);
    let mesh = ShellMesh::rectangle(a, a, 6, 6).unwrap();
    let sections = vec![Section::single(&plate_layer(t)); mesh.elements.len()];
    let fixed = simply_supported(&mesh, a, a);
    let first = &modes(&mesh, &sections, &fixed, 1).unwrap()[0];
    let period = 1.0 / first.frequency;
    let settings = GeneralizedAlpha {
        dt: period / 40.0,
        rho_inf: 1.0,
        mass_damping: 0.0,
        stiffness_damping: 0.0,
    };
    let centre = mesh.nodes_where(|p| (p.x - 0.5).abs() < 1e-9 && (p.y - 0.5).abs() < 1e-9)[0];
    let amplitude = 0.01 * t;
    let scale = amplitude / first.shape[6 * centre + 2];
    let shape: Vec<f64> = first.shape.iter().map(|v| scale * v).collect();
    let linear = Transient::new(&mesh, &sections, &fixed, settings).unwrap();
    let map = linear.model().map().clone();
    let zero = vec![0.0; map.free_count()];
    let k_u = linear.model().apply(&map.restrict(&shape));
    let w = map.free(6 * centre + 2).unwrap();
    // Both Newton starts converge to the same steps.
    for predictor in [
        Predictor::ConstantAcceleration,
        Predictor::ConstantDisplacement,
    ] {
        let mut ls = linear.start(map.restrict(&shape), &zero);
        let mut nonlinear = NonlinearTransient::new(&mesh, &sections, &fixed, settings).unwrap();
        nonlinear.predictor = predictor;
        let mut ns = nonlinear.rest();
        ns.configuration.update(&shape);
        // Consistent start: M acc0 = -f_int(q0) = -K q0 at this amplitude.
        let acc0 = map.expand(
            &k_u.iter()
                .zip(linear.mass())
                .map(|(f, m)| -f / m)
                .collect::<Vec<_>>(),
        );
        ns.acceleration = acc0.clone();
        ns.algorithmic = acc0;
        let load = vec![0.0; mesh.dofs()];
        let mut worst: f64 = 0.0;
        for _ in 0..80 {
            linear.step(&mut ls, &zero);
            nonlinear.step(&mut ns, &load, &Vec::new()).unwrap();
            let wn = ns.configuration.displacement[centre].z;
            worst = worst.max((wn - ls.u[w]).abs() / amplitude);
        }
        println!("nonlinear ({predictor:?}) vs linear transient: worst difference {worst:.2e} of the amplitude");
        assert!(worst < 0.01, "{predictor:?}: {worst}");
    }
}

/// Large-amplitude free vibration of a cantilever strip (released from rest
/// with its tip deflected by a third of its length under a tip load): the
/// total energy should stay within 1% over 20 periods.
#[test]
#[ignore = "not met at 50 steps a period: released at w = 0.345 L, Newton stops \
            converging after 1.3 periods with rho_inf = 1 and 1.8 with 0.9, and the energy \
            grows 1e8-fold at 400 steps a period; at 1600 steps a period (the strip's \
            membrane modes resolved) it holds to 2e-5 over 2.5 periods. So the scheme is \
            consistent but not energy-stable with unresolved stiff membrane modes, the \
            known weakness of generalized-alpha in nonlinear elastodynamics (Kuhl & \
            Crisfield 1999): an energy-momentum or energy-decaying scheme is the fix."]
fn nonlinear_free_vibration_energy() {
    use fwav::shell::dynamics::GeneralizedAlpha;
    use fwav::shell::nonlinear::{NewtonSettings, NonlinearStatic};
    use fwav::shell::nonlinear_dynamics::NonlinearTransient;
    let (length, width) = (1.0, 0.1);
    let layer = Layer {
        young: 70e9,
        poisson: 0.3,
        density: 2700.0,
        thickness: 0.002,
    };
    let Strip {
        mesh,
        sections,
        root: fixed,
        tip,
    } = Strip::clamped(length, width, layer, 10).unwrap();
    let ei = 70e9 * width * 0.002f64.powi(3) / 12.0;
    let mut load = vec![0.0; mesh.dofs()];
    for &n in &tip {
        load[6 * n + 2] = 1.2 * ei / length.powi(2) / tip.len() as f64;
    }
    let deflected = NonlinearStatic::new(&mesh, &sections, &fixed)
        .unwrap()
        .solve(&load, NewtonSettings::default())
        .unwrap()
        .pop()
        .unwrap()
        .1;
    let w_tip = deflected.displacement[tip[0]].z;
    // First bending period of a cantilever: 2 pi / (1.875^2 sqrt(EI / (m L^4))).
    let m = 2700.0 * width * 0.002;
    let period =
        2.0 * std::f64::consts::PI / (1.875f64.powi(2) * (ei / (m * length.powi(4))).sqrt());
    let settings = GeneralizedAlpha {
        dt: period / 50.0,
        rho_inf: 0.9,
        mass_damping: 0.0,
        stiffness_damping: 0.0,
    };
    let model = NonlinearTransient::new(&mesh, &sections, &fixed, settings).unwrap();
    let mut state = model.rest();
    state.configuration = deflected;
    let zero = vec![0.0; mesh.dofs()];
    let e0 = {
        let (k, s) = model.energy(&state);
        k + s
    };
    let mut worst: f64 = 0.0;
    for _ in 0..1000 {
        model.step(&mut state, &zero, &Vec::new()).unwrap();
        let (k, s) = model.energy(&state);
        worst = worst.max(((k + s) / e0 - 1.0).abs());
    }
    println!(
        "tip released at w = {:.3} L: worst energy change over 20 periods {:.2e}",
        w_tip / length,
        worst
    );
    assert!(w_tip / length > 0.25);
    assert!(worst < 0.01, "{worst}");
}

/// A driven root: a strip whose root line is turned by 90 degrees about
/// the y axis (lifting the strip out of its plane), slowly (a smooth ramp
/// over 20 first-mode periods, 400 steps, rho_inf 0.9): the tip follows the
/// rigid rotation within 1% of the length (measured 0.1%).
#[test]
fn prescribed_root_rotation_carries_the_strip() {
    use fwav::shell::dynamics::GeneralizedAlpha;
    use fwav::shell::nonlinear_dynamics::NonlinearTransient;
    let (length, width) = (1.0, 0.1);
    let layer = Layer {
        young: 70e9,
        poisson: 0.3,
        density: 2700.0,
        thickness: 0.01,
    };
    let Strip {
        mesh,
        sections,
        root: held,
        ..
    } = Strip::clamped(length, width, layer, 10).unwrap();
    let root = mesh.nodes_where(|p| p.x.abs() < 1e-9);
    let ei = 70e9 * width * 0.01f64.powi(3) / 12.0;
    let m = 2700.0 * width * 0.01;
    let period =
        2.0 * std::f64::consts::PI / (1.875f64.powi(2) * (ei / (m * length.powi(4))).sqrt());
    let duration = 20.0 * period;
    let steps = 400;
    let settings = GeneralizedAlpha {
        dt: duration / steps as f64,
        rho_inf: 0.9,
        mass_damping: 0.0,
        stiffness_damping: 0.0,
    };
    let model = NonlinearTransient::new(&mesh, &sections, &held, settings).unwrap();
    let mut state = model.rest();
    let zero = vec![0.0; mesh.dofs()];
    // Rotation about the y axis (lifting the strip out of its plane), the
    // root line lying on that axis.
    let angle = |t: f64| {
        let s = (t / duration).min(1.0);
        0.5 * std::f64::consts::FRAC_PI_2 * (1.0 - (std::f64::consts::PI * s).cos())
    };
    for k in 1..=steps {
        let t = k as f64 * settings.dt;
        let q = Rotation3::from_axis_angle(&nalgebra::Vector3::y_axis(), -angle(t));
        let prescribed = root
            .iter()
            .map(|&n| (n, q * mesh.nodes[n] - mesh.nodes[n], q))
            .collect();
        model.step(&mut state, &zero, &prescribed).unwrap();
    }
    let q = Rotation3::from_axis_angle(&nalgebra::Vector3::y_axis(), -angle(duration));
    let tip = mesh.nodes_where(|p| (p.x - length).abs() < 1e-9);
    let worst = tip
        .iter()
        .map(|&n| {
            ((mesh.nodes[n] + state.configuration.displacement[n]) - q * mesh.nodes[n]).norm()
        })
        .fold(0.0f64, f64::max);
    println!(
        "driven root, 90 deg: tip off the rigid rotation by {:.2e} L",
        worst / length
    );
    assert!(worst < 0.01 * length, "{worst}");
}

/// Modified Newton (a step's first iterations on the last factorization,
/// `keep_factor_below`) converges to the same steps as a fresh tangent
/// every iteration: a clamped strip under a sudden tip load that swings it
/// to 0.69 of its length (geometrically nonlinear), 60 steps over about
/// 1.5 first-mode periods. The tip histories agree to 1e-4 of the peak
/// (both converged to the Newton tolerance, 1e-5 of the forces; measured
/// 1.0e-7), and the kept factorizations add no more than one iteration a
/// step (measured: none, 293 each).
#[test]
fn kept_factorizations_give_the_same_steps() {
    use fwav::shell::dynamics::GeneralizedAlpha;
    use fwav::shell::nonlinear_dynamics::{NonlinearTransient, Predictor};
    let (length, width, t) = (1.0, 0.1, 0.01);
    let layer = Layer {
        young: 70e9,
        poisson: 0.3,
        density: 2700.0,
        thickness: t,
    };
    let Strip {
        mesh,
        sections,
        root,
        tip,
    } = Strip::clamped(length, width, layer, 10).unwrap();
    let ei = 70e9 * width * t.powi(3) / 12.0;
    let m = 2700.0 * width * t;
    let period =
        2.0 * std::f64::consts::PI / (1.875f64.powi(2) * (ei / (m * length.powi(4))).sqrt());
    let settings = GeneralizedAlpha {
        dt: 1.5 * period / 60.0,
        rho_inf: 0.8,
        mass_damping: 0.0,
        stiffness_damping: 0.0,
    };
    // A static tip load of 1.5 EI/L^2 bends the strip to about w = 0.4 L
    // (Bisshopp & Drucker 1945); suddenly applied it swings further.
    let mut load = vec![0.0; mesh.dofs()];
    for &n in &tip {
        load[6 * n + 2] = 1.5 * ei / length.powi(2) / tip.len() as f64;
    }
    let run = |keep: f64| {
        let mut model = NonlinearTransient::new(&mesh, &sections, &root, settings).unwrap();
        model.predictor = Predictor::ConstantDisplacement;
        model.keep_factor_below = keep;
        let mut workspace = model.workspace();
        let mut state = model.rest();
        let mut history = Vec::new();
        let mut iterations = 0;
        for _ in 0..60 {
            iterations += model
                .step_in(
                    &mut workspace,
                    &mut state,
                    &load,
                    &Vec::new(),
                    settings.dt,
                    25,
                )
                .unwrap();
            history.push(state.configuration.displacement[tip[0]].z);
        }
        (history, iterations)
    };
    let (fresh, fresh_iterations) = run(0.0);
    let (kept, kept_iterations) = run(0.05);
    let peak = fresh.iter().fold(0.0f64, |p, w| p.max(w.abs()));
    let worst = fresh
        .iter()
        .zip(&kept)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f64, f64::max);
    println!(
        "peak tip deflection {:.3} L; kept factorizations vs fresh: worst difference {:.2e} of the peak, {kept_iterations} against {fresh_iterations} iterations",
        peak / length,
        worst / peak
    );
    assert!(peak > 0.5 * length, "not in the nonlinear range: {peak}");
    assert!(worst < 1e-4 * peak, "{worst}");
    assert!(
        kept_iterations <= fresh_iterations + 60,
        "{kept_iterations}"
    );
}

/// A plate held nowhere has a singular stiffness: the error says so in
/// words, with the pivot, not in faer's debug form
/// (`Numeric(NonPositivePivot { index: 0 })`) (issue 22).
#[test]
fn an_unsupported_plate_is_singular_in_words() {
    let mesh =
        ShellMesh::mapped(2, 2, |s, t| nalgebra::Vector3::new(0.1 * s, 0.1 * t, 0.0)).unwrap();
    let sections = vec![Section::single(&Layer::MYLAR); mesh.elements.len()];
    let e = fwav::shell::linear::LinearStatic::new(&mesh, &sections, &[])
        .err()
        .expect("a free plate cannot be factorized");
    let text = e.to_string();
    assert!(
        text.contains("singular or indefinite") && text.contains("is not positive"),
        "{text}"
    );
    assert!(
        !text.contains('{') && !text.contains("NonPositivePivot"),
        "{text}"
    );
}
