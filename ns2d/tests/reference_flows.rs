//! The Navier–Stokes section solver against published flows. The
//! references are the authors' curves as distributed with PetIBM
//! (`data/`, each file names its source); the heavy cases run in
//! `fwav validate` and are `#[ignore]`d here with their cost.

use fwav_ns2d::cases::{CylinderWake, ImpulsiveCylinder, Resolution};
use fwav_ns2d::GridSpec;

/// `(x, y)` rows of a reference file (`#` comments).
fn reference(name: &str) -> Vec<(f64, f64)> {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let mut v = l.split_whitespace().map(|x| x.parse::<f64>().unwrap());
            (v.next().unwrap(), v.next().unwrap())
        })
        .collect()
}

/// Linear interpolation of a sampled curve.
fn at(curve: &[(f64, f64)], x: f64) -> f64 {
    let i = curve.partition_point(|p| p.0 < x).clamp(1, curve.len() - 1);
    let (a, b) = (curve[i - 1], curve[i]);
    a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)
}

/// The largest relative error of `computed` against the reference points
/// with `x` in `range`, and where.
fn worst_relative(computed: &[(f64, f64)], reference: &[(f64, f64)], range: (f64, f64)) -> (f64, f64) {
    reference
        .iter()
        .filter(|p| p.0 >= range.0 && p.0 <= range.1)
        .map(|p| ((at(computed, p.0) - p.1).abs() / p.1, p.0))
        .fold((0.0, 0.0), |w, e| if e.0 > w.0 { e } else { w })
}

/// Koumoutsakos & Leonard (1995), J. Fluid Mech. 296, fig. 18: the drag
/// of the impulsively started cylinder at Re 550 over U t / R in [0.5, 3]
/// within 5% (issue 23). Measured: 2.9% (at U t/R = 0.61) on 256 x 192,
/// first cell 0.001 D, dt = 0.004 D/U.
#[test]
fn the_impulsively_started_cylinder_at_re_550_drags_as_koumoutsakos_and_leonard_found() {
    let drag = ImpulsiveCylinder {
        reynolds: 550.0,
        until: 3.05,
    }
    .run(ImpulsiveCylinder::validated())
    .unwrap();
    let (error, x) = worst_relative(&drag, &reference("koumoutsakos_leonard_1995_re550.dat"), (0.5, 3.0));
    assert!(error < 0.05, "CD off by {:.1}% at U t/R = {x:.2}", 100.0 * error);
}
