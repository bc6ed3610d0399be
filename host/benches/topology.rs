//! Speed of one SIMP iteration on the default wing (6760 design elements
//! over the mylar skin, 41.7k DOFs) with 20 load cases (issue target
//! < 0.3 s on 2 cores): assembly, one factorization, 20 solves, the
//! carbon strain energies, the filter and the OC bisection. Runs 10
//! iterations and reports the mean, the one-off setup (element matrices,
//! pattern, nested-dissection ordering and symbolic analysis, filter)
//! included. `cargo bench -p fwav --bench topology`.

use std::time::Instant;

use fwav::shell::assembly::pressure_loads;
use fwav::shell::material::Layer;
use fwav::shell::wing::Planform;
use fwav::topology::simp::{optimize, SimpSettings};

fn main() {
    let wing = Planform::FWAV.mesh().expect("default planform");
    let n = wing.mesh.elements.len();
    // 20 pressure fields: a spanwise and chordwise varying load, scaled.
    let loads: Vec<Vec<f64>> = (0..20)
        .map(|k| {
            let p: Vec<f64> = (0..n)
                .map(|e| {
                    let c = wing.mesh.corners(e)[0];
                    10.0 * (1.0 + k as f64 * c.y / 0.15) * (1.0 - c.x / 0.075)
                })
                .collect();
            pressure_loads(&wing.mesh, &p).expect("loads")
        })
        .collect();
    let design: Vec<bool> = wing.spar.iter().map(|s| !s).collect();
    let settings = SimpSettings {
        max_iterations: 10,
        tolerance: 1e-12,
        ..SimpSettings::default()
    };
    let started = Instant::now();
    let result = optimize(
        &wing.mesh,
        &wing.clamped_dofs(),
        &design,
        &Layer::CARBON,
        &Layer::MYLAR,
        &loads,
        &settings,
    )
    .expect("SIMP");
    let seconds = started.elapsed().as_secs_f64();
    println!(
        "SIMP on the default wing, {n} elements, 20 load cases: {:.3} s an iteration ({} iterations, compliance {:.4e} -> {:.4e} J)",
        seconds / result.history.len() as f64,
        result.history.len(),
        result.history[0].objective,
        result.history.last().map_or(f64::NAN, |h| h.objective)
    );
}
