//! Shell FE speed: the linear static solve of the default wing (6760
//! two-layer elements, carbon and mylar, 41.7k DOFs) including assembly
//! and factorization (issue target < 0.3 s on 2 cores), from scratch and on
//! a kept sparse structure.

use criterion::{criterion_group, criterion_main, Criterion};
use fwav::shell::assembly::pressure_loads;
use fwav::shell::linear::LinearStatic;
use fwav::shell::material::{Layer, Section};
use fwav::shell::wing::Planform;

fn linear_static(c: &mut Criterion) {
    let wing = Planform::FWAV.mesh().expect("default planform");
    let n = wing.mesh.elements.len();
    let sections = vec![Section::two_layer(&Layer::CARBON, &Layer::MYLAR, 1.0, 3.0); n];
    let fixed = wing.clamped_dofs();
    let load = pressure_loads(&wing.mesh, &vec![10.0; n]).expect("loads");
    let mut group = c.benchmark_group("shell");
    group.sample_size(10);
    group.bench_function(
        "linear static, default wing, assembly + factor + solve",
        |b| {
            b.iter(|| {
                let model = LinearStatic::new(&wing.mesh, &sections, &fixed).expect("model");
                model.solve(std::slice::from_ref(&load)).expect("solve")
            })
        },
    );
    // The optimization loops re-solve the same mesh with new densities:
    // the pattern and symbolic analysis are kept, assembly and numeric
    // factorization redone.
    let model = LinearStatic::new(&wing.mesh, &sections, &fixed).expect("model");
    let structure = model.structure().clone();
    group.bench_function(
        "linear static on a kept structure: assembly + factor + solve",
        |b| {
            b.iter(|| {
                let model = LinearStatic::with_structure(structure.clone(), &wing.mesh, &sections)
                    .expect("model");
                model.solve(std::slice::from_ref(&load)).expect("solve")
            })
        },
    );
    // One Newton iteration of the nonlinear analysis: co-rotational forces
    // and tangents of every element, assembly, factorization, solve.
    let corotational =
        fwav::shell::corotational::Corotational::new(&wing.mesh, &sections).expect("elements");
    let state = fwav::shell::corotational::Configuration::initial(wing.mesh.nodes.len());
    group.bench_function(
        "nonlinear Newton iteration (co-rotational tangent + factor + solve)",
        |b| {
            b.iter(|| {
                let responses = corotational.responses(&wing.mesh, &state);
                let tangents: Vec<_> = responses.iter().map(|r| r.tangent).collect();
                let k = structure.assemble(&tangents).expect("assemble");
                let factor = structure.factorize(&k).expect("factor");
                let rhs = faer::Mat::from_fn(structure.map().free_count(), 1, |i, _| i as f64);
                faer::linalg::solvers::Solve::solve(&factor, &rhs)
            })
        },
    );
    let loads = vec![load; 20];
    group.bench_function("20 load cases on one factorization", |b| {
        b.iter(|| model.solve(&loads).expect("solve"))
    });
    group.finish();
}

criterion_group!(benches, linear_static);
criterion_main!(benches);
