//! One kinematic evaluation with the thick-section panel method: a 4-cycle
//! run of a plunging NACA 0012 (k = 1, h0 = 0.05 c) at the default
//! resolution (160 panels, dt = 0.015; target < 0.3 s on one core).

use criterion::{criterion_group, criterion_main, Criterion};
use fwav::aero2d::ldvm::Motion;
use fwav::aero2d::naca::{Naca4, TrailingEdge};
use fwav::aero2d::panel::{PanelSettings, PanelSolver, SectionShape, DEFAULT_PANELS};

fn four_cycles(c: &mut Criterion) {
    let k = 1.0;
    let motion = Motion::plunge(k, 0.05);
    let settings = PanelSettings {
        duration: 4.0 * std::f64::consts::PI / k,
        ..PanelSettings::default()
    };
    let naca: Naca4 = "0012".parse().expect("a valid designation");
    let points = naca
        .points(DEFAULT_PANELS, TrailingEdge::Closed)
        .expect("an even panel count");
    let section = SectionShape::new(&points).expect("a valid contour");
    let mut group = c.benchmark_group("aero2d_panel");
    group.sample_size(10);
    group.bench_function("NACA 0012, 4 cycles, k = 1, default resolution", |b| {
        b.iter(|| {
            PanelSolver::new(&section, motion, settings)
                .expect("valid settings")
                .run()
        })
    });
    group.finish();
}

criterion_group!(benches, four_cycles);
criterion_main!(benches);
