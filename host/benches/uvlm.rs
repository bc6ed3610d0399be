//! UVLM speed: one `solve` + `advance` step of an 8 x 20 ring lattice
//! (a symmetric half wing) behind a wake of 160 rows, the youngest 40 of
//! them free: the cost of a time step of the aeroelastic analysis once the
//! wake has grown (influence matrix, LU, loads, rollup).

use criterion::{criterion_group, criterion_main, Criterion};
use fwav::uvlm::{Lattice, Uvlm, UvlmSettings};
use nalgebra::Vector3;

fn step(c: &mut Criterion) {
    let (nc, ns) = (8, 20);
    let (chord, semi_span, speed) = (0.1, 0.3, 5.0);
    let dt = chord / nc as f64 / speed;
    let mut settings = UvlmSettings::new(dt, 1.225, Vector3::new(speed, 0.0, 0.0));
    settings.symmetric = true;
    settings.free_wake_rows = 40;
    settings.wake_rows = 160;
    let mut uvlm = Uvlm::new(nc, ns, settings).expect("settings");
    // A heaving wing (h0 = 0.2 c, k = 0.5) so that the wake is not trivial.
    let omega = 2.0 * 0.5 * speed / chord;
    let wing = Lattice::rectangle(chord, semi_span, nc, ns, 0.05).expect("lattice");
    let at = |t: f64| {
        let surface = wing.translated(&Vector3::new(0.0, 0.0, 0.2 * chord * (omega * t).sin()));
        let v = Vector3::new(0.0, 0.0, 0.2 * chord * omega * (omega * t).cos());
        (surface, vec![v; wing.corner_count()])
    };
    for _ in 0..170 {
        let (surface, velocity) = at(uvlm.time());
        let solution = uvlm.solve(&surface, &velocity).expect("solve");
        uvlm.advance(&surface, &solution).expect("advance");
    }
    assert_eq!(uvlm.wake().rows(), 160);
    let mut group = c.benchmark_group("uvlm");
    group.sample_size(10);
    group.bench_function(
        "8 x 20 lattice, 160 wake rows (40 free): solve + advance",
        |b| {
            b.iter_batched(
                || uvlm.clone(),
                |mut state| {
                    let (surface, velocity) = at(state.time());
                    let solution = state.solve(&surface, &velocity).expect("solve");
                    state.advance(&surface, &solution).expect("advance");
                    state
                },
                criterion::BatchSize::LargeInput,
            )
        },
    );
    let (surface, velocity) = at(uvlm.time());
    group.bench_function("8 x 20 lattice, 160 wake rows: solve only", |b| {
        b.iter(|| uvlm.solve(&surface, &velocity).expect("solve"))
    });
    group.finish();
}

criterion_group!(benches, step);
criterion_main!(benches);
