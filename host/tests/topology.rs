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
