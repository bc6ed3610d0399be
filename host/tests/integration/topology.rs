//! SIMP topology optimization of the design layer (ESLSO's linear step).

use fwav::shell::material::Layer;
use fwav::shell::mesh::ShellMesh;
use fwav::topology::simp::{optimize, SimpResult, SimpSettings};

const STIFF: Layer = Layer {
    young: 1.0e9,
    poisson: 0.3,
    density: 1000.0,
    thickness: 0.02,
};
/// A skin 10^4 times softer: the void's residual stiffness (SIMP's
/// minimum density), which keeps the stiffness matrix positive definite.
const SKIN: Layer = Layer {
    young: 1.0e5,
    poisson: 0.3,
    density: 1.0,
    thickness: 0.02,
};

/// A cantilever plate 2 m x 1 m clamped along x = 0, bent by two load
/// cases at its free edge (1 N down at each corner), on an `nx x ny` mesh.
fn cantilever(nx: usize, ny: usize, settings: &SimpSettings) -> SimpResult {
    let mesh = ShellMesh::rectangle(2.0, 1.0, nx, ny).unwrap();
    let fixed: Vec<usize> = mesh
        .nodes_where(|p| p.x.abs() < 1e-9)
        .into_iter()
        .flat_map(|n| (0..6).map(move |c| 6 * n + c))
        .collect();
    let loads: Vec<Vec<f64>> = [0.0, 1.0]
        .iter()
        .map(|&y| {
            let mut f = vec![0.0; mesh.dofs()];
            let corner =
                mesh.nodes_where(|p| (p.x - 2.0).abs() < 1e-9 && (p.y - y).abs() < 1e-9)[0];
            f[6 * corner + 2] = -1.0;
            f
        })
        .collect();
    let design = vec![true; mesh.elements.len()];
    optimize(&mesh, &fixed, &design, &STIFF, &SKIN, &loads, settings).unwrap()
}

/// The standard SIMP checks (Andreassen et al. 2011, top88; Bendsøe &
/// Sigmund 2003 §1.2) on a cantilever plate in bending, two load cases:
/// the summed compliance falls monotonically after the first iterations
/// (from the 5th on), the mass constraint holds within 0.5% at the end,
/// and with the filter radius fixed in metres the layout is mesh
/// independent: the final compliance on a 40 x 20 and a 60 x 30 mesh within
/// 3%.
#[test]
fn simp_cantilever_plate() {
    let settings = SimpSettings {
        mass_fraction: 0.4,
        filter_radius: 0.12,
        max_iterations: 80,
        ..SimpSettings::default()
    };
    let coarse = cantilever(40, 20, &settings);
    let fine = cantilever(60, 30, &settings);
    for (name, r) in [("40 x 20", &coarse), ("60 x 30", &fine)] {
        let h = &r.history;
        let last = h.last().unwrap();
        println!(
            "{name}: {} iterations (converged {}), compliance {:.4e} -> {:.4e} J, mass fraction {:.4}",
            h.len(),
            r.converged,
            h[0].objective,
            last.objective,
            last.mass_fraction
        );
        let rises: Vec<usize> = (5..h.len())
            .filter(|&i| h[i].objective > h[i - 1].objective * (1.0 + 1e-9))
            .collect();
        assert!(
            rises.is_empty(),
            "{name}: compliance rose at iterations {rises:?}"
        );
        assert!((last.mass_fraction / 0.4 - 1.0).abs() < 0.005, "{name}");
        assert!(last.objective < 0.7 * h[0].objective, "{name}");
    }
    let ratio = fine.history.last().unwrap().objective / coarse.history.last().unwrap().objective;
    println!("compliance fine / coarse: {ratio:.4}");
    assert!((ratio - 1.0).abs() < 0.03);
}

mod eslso {
    use fwav::shell::linear::LinearStatic;
    use fwav::shell::material::Layer;
    use fwav::shell::material::Section;
    use fwav::shell::mesh::ShellMesh;
    use fwav::topology::esl::{EquivalentStaticLoads, EslForm};
    use fwav::topology::eslso::{
        optimize, optimize_from, DesignProblem, EslsoProgress, EslsoSettings,
    };
    use fwav::topology::pressure::PressureHistory;
    use fwav::topology::response::{nonlinear_response, ResponseSettings};
    use fwav::topology::simp::SimpSettings;

    /// A small wing-like cantilever: a 100 mm x 40 mm plate of the seed
    /// paper's two layers (carbon 0.5 mm over mylar 0.1 mm, Table 4)
    /// clamped along its root edge x = 0, 16 x 8 elements, no spar.
    fn plate() -> DesignProblem {
        let mesh = ShellMesh::rectangle(0.1, 0.04, 16, 8).unwrap();
        let fixed: Vec<usize> = mesh
            .nodes_where(|p| p.x.abs() < 1e-9)
            .into_iter()
            .flat_map(|n| (0..6).map(move |c| 6 * n + c))
            .collect();
        let design = vec![true; mesh.elements.len()];
        DesignProblem {
            mesh,
            fixed,
            design,
            carbon: Layer::CARBON,
            skin: Layer::MYLAR,
        }
    }

    /// An 11 Hz pressure over one period in 40 steps: a mean of
    /// `scale` x 25 Pa and a `scale` x 35 Pa first harmonic, larger towards
    /// the tip and the leading edge (y = 0): a flapping wing's load shape.
    /// At `scale` 1 the optimized layout's tip swings 15 mm (15% of the
    /// length, 30 carbon thicknesses): well into the geometrically
    /// nonlinear range.
    fn pressure(problem: &DesignProblem, scale: f64) -> PressureHistory {
        let steps = 40;
        let period = 1.0 / 11.0;
        let dt = period / steps as f64;
        let samples = (1..=steps)
            .map(|k| {
                let phase = 2.0 * std::f64::consts::PI * k as f64 / steps as f64;
                (0..problem.mesh.elements.len())
                    .map(|e| {
                        let c = problem.mesh.corners(e);
                        let (x, y) = (
                            0.25 * (c[0].x + c[1].x + c[2].x + c[3].x),
                            0.25 * (c[0].y + c[1].y + c[2].y + c[3].y),
                        );
                        scale * (25.0 + 35.0 * phase.cos()) * (0.5 + x / 0.1) * (1.3 - y / 0.04)
                    })
                    .collect()
            })
            .collect();
        PressureHistory::new(dt, samples, problem.mesh.elements.len()).unwrap()
    }

    fn settings() -> EslsoSettings {
        EslsoSettings {
            simp: SimpSettings {
                mass_fraction: 0.3,
                filter_radius: 0.01,
                max_iterations: 60,
                ..SimpSettings::default()
            },
            max_cycles: 8,
            // The paper's strict rule: no element may change.
            layout_tolerance: 0.0,
            ..EslsoSettings::default()
        }
    }

    /// Step 2 of ESLSO (seed paper eq. (12)): the linear static response to
    /// each equivalent static load `K_L u_N(t_i)` is `u_N(t_i)` itself, to
    /// the solver's precision (1e-9 of the largest displacement), for the
    /// nonlinear dynamic response of the uniform design.
    #[test]
    fn equivalent_static_loads_reproduce_the_nonlinear_response() {
        let problem = plate();
        let sections = problem.sections(&vec![0.3; problem.mesh.elements.len()], 3.0);
        let response = nonlinear_response(
            &problem.mesh,
            &sections,
            &problem.fixed,
            &pressure(&problem, 1.0),
            &ResponseSettings::default(),
            |_, _| {},
        )
        .unwrap();
        assert_eq!(response.displacements.len(), 20);
        let peak = response
            .peak_displacement
            .iter()
            .fold(0.0f64, |m, &p| m.max(p));
        // Nonlinear range: the tip moves several percent of the length.
        assert!(peak > 0.005, "peak displacement {peak} m");
        let linear = LinearStatic::new(&problem.mesh, &sections, &problem.fixed).unwrap();
        let esl = EquivalentStaticLoads::new(&linear, &response.displacements).unwrap();
        let back = linear.solve(&esl.loads).unwrap();
        for (u, v) in response.displacements.iter().zip(&back) {
            let scale = u.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let error = u
                .iter()
                .zip(v)
                .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            assert!(error <= 1e-9 * scale, "error {error:e} of {scale:e}");
        }
    }

    /// Runs ESLSO with the load cases of `esl` from the design `start`
    /// under `pressure(scale)`; returns the summed strain energies
    /// (nonlinear dynamic analysis) of the final layout and of the
    /// uniform-thickness carbon layer of the same mass, and the layout's
    /// mass fraction.
    fn layout_against_uniform(esl: EslForm, start: f64, scale: f64) -> (f64, f64, f64) {
        let problem = plate();
        let pressure = pressure(&problem, scale);
        let settings = EslsoSettings { esl, ..settings() };
        let start = vec![start; problem.mesh.elements.len()];
        let result = optimize(&problem, &pressure, &start, &settings, |p| {
            if let EslsoProgress::Cycle(c) = p {
                eprintln!("{c:?}")
            }
        })
        .unwrap();
        assert!(result.converged, "{:?}", result.cycles);
        assert!(result.cycles.len() <= 5, "{} cycles", result.cycles.len());
        let layout = result.layout_densities();
        let mass = problem.mass_fraction(&layout);
        assert!((mass - 0.3).abs() < 0.05, "layout mass fraction {mass}");
        let energy = |sections: Vec<Section>| {
            nonlinear_response(
                &problem.mesh,
                &sections,
                &problem.fixed,
                &pressure,
                &settings.response,
                |_, _| {},
            )
            .unwrap()
            .total_strain_energy()
        };
        let optimized = energy(problem.sections(&layout, 3.0));
        let uniform = energy(problem.uniform_thickness_sections(mass));
        eprintln!("summed strain energy: layout {optimized:.4e} J, uniform {uniform:.4e} J, mass {mass:.4}");
        (optimized, uniform, mass)
    }

    /// The whole ESLSO loop (d'Alembert load cases, the default) on the
    /// small nonlinear dynamic case, starting like the MDOIS from the full
    /// carbon layer: it converges (the 0/1 layout stops changing) within a
    /// few cycles (3 measured), keeps the carbon mass near the 30% allowed
    /// (27.3% after the 0.5 threshold), and its layout's summed strain
    /// energy beats the uniform-thickness carbon layer of the same mass
    /// (measured 1.58e-3 J against 2.11e-2 J).
    #[test]
    fn eslso_beats_the_uniform_design_of_equal_mass() {
        let (optimized, uniform, _) = layout_against_uniform(EslForm::Dalembert, 1.0, 1.0);
        assert!(
            optimized < uniform,
            "layout {optimized:e} J against uniform {uniform:e} J"
        );
    }

    /// The relaxed stopping rule (`layout_tolerance`): the loop ends at the
    /// first cycle that analysed a 0/1 layout and flipped at most that
    /// fraction of the design elements. From the full carbon layer the
    /// strict rule needs 3 cycles here (93, 2 and 0 elements changed); at
    /// 2% (2 of the 128 design elements) the second cycle ends it.
    #[test]
    fn layout_tolerance_ends_the_loop_once_few_elements_flip() {
        let problem = plate();
        let pressure = pressure(&problem, 1.0);
        let settings = EslsoSettings {
            layout_tolerance: 0.02,
            ..settings()
        };
        let start = vec![1.0; problem.mesh.elements.len()];
        let result = optimize(&problem, &pressure, &start, &settings, |_| {}).unwrap();
        let design = problem.design.iter().filter(|&&d| d).count();
        let allowed = (0.02 * design as f64).floor() as usize;
        let changes: Vec<usize> = result.cycles.iter().map(|c| c.changed).collect();
        assert!(result.converged, "{changes:?}");
        let (last, before) = changes.split_last().unwrap();
        assert!(*last <= allowed, "{changes:?}, {allowed} allowed");
        assert!(
            before.iter().all(|&c| c > allowed),
            "{changes:?}, {allowed} allowed"
        );
        assert_eq!(changes.len(), 2, "{changes:?}");
        // The flips that were tolerated were undecided densities, not
        // elements SIMP had settled.
        assert!(
            result.cycles[1].flip_margin < 0.25,
            "{:?}",
            result.cycles[1]
        );
        let bad = EslsoSettings {
            layout_tolerance: 1.0,
            ..settings
        };
        let e = optimize(&problem, &pressure, &start, &bad, |_| {}).unwrap_err();
        assert!(e.to_string().contains("layout_tolerance"), "{e}");
        // A warm start of the wrong length is refused, naming what.
        let e = optimize_from(
            &problem,
            &pressure,
            &start,
            Some(&[0.5; 3]),
            &settings,
            |_| {},
        )
        .unwrap_err();
        assert!(e.to_string().contains("warm-start"), "{e}");
    }

    /// The same with the seed paper's load cases `K_L u_N` (eq. (12)), at
    /// a fifth of the load (tip about 5 mm, 10 carbon thicknesses) from
    /// the uniform 30% design. It fails: the linear model reads the
    /// second-order in-plane shortening of the bent plate as membrane
    /// strain (SIMP's summed compliance 0.032 J against a nonlinear strain
    /// energy of 3.7e-4 J in cycle 1), so SIMP optimizes that artefact; the
    /// converged layout's strain energy is 1.54e-3 J against 3.02e-4 J for
    /// the uniform layer (5x worse). At the full load the analysis of the
    /// second layout does not converge. This is why the d'Alembert form is
    /// the default; the test stays as the honest record.
    #[test]
    #[ignore = "K_L u_N ESLs of a thin plate deflecting ~10 thicknesses carry spurious membrane energy: layout 5x worse than uniform (see doc)"]
    fn eslso_displacement_form_beats_the_uniform_design() {
        let (optimized, uniform, _) = layout_against_uniform(EslForm::Displacement, 0.3, 0.2);
        assert!(
            optimized < uniform,
            "layout {optimized:e} J against uniform {uniform:e} J"
        );
    }
}
