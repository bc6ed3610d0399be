//! One kinematic evaluation of the aerodynamic discipline: a 4-cycle run of
//! the plunging flat plate at the default resolution (target < 0.3 s).

use criterion::{criterion_group, criterion_main, Criterion};
use fwav::aero2d::ldvm::{Ldvm, Motion, Settings};

fn four_cycles(c: &mut Criterion) {
    let k = 1.0;
    let motion = Motion::plunge(k, 0.05);
    let settings = Settings {
        duration: 4.0 * std::f64::consts::PI / k,
        ..Settings::default()
    };
    let mut group = c.benchmark_group("aero2d");
    group.sample_size(10);
    group.bench_function("4 cycles, k = 1, default resolution", |b| {
        b.iter(|| Ldvm::new(motion, settings).run())
    });
    group.finish();
}

criterion_group!(benches, four_cycles);
criterion_main!(benches);
