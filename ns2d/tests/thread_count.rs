//! The flow does not depend on how many threads compute it.
//!
//! The step's parallel parts split the grid's lines and Fourier modes
//! into one block per worker thread (`blocks.rs`), so a machine with more
//! cores cuts them differently. Every line and mode is computed the same
//! whatever its block, so the flow, and the loads a design is scored by,
//! are the same to the last bit on one thread, two, or three (a split
//! into uneven blocks), and when stepped from outside any pool, where the
//! global pool's other workers spin beside each step (`awake_pool.rs`).
//! Until 2026-12-04 they were not: the radial sweep's wall correction
//! stopped a whole block of lines where its largest carried change fell
//! to rounding, and the rounding-level differences grew, in the
//! deforming default section's wandering flow, to 3.7 % of a two-stroke
//! window's thrust between a run on one thread and one on two.
//!
//! Case: an ellipse of thickness ratio 0.2 (chord 1) at Re 200, plunging
//! and pitching about its centre (rigid), or breathing (its thickness
//! changing, a deformation), 128 × 96 nodes, 300 steps of 0.004.

use std::f64::consts::PI;

use fwav_ns2d::{Deformation, Flow, GridSpec, Motion, PlungePitch, SectionMap, SteadyStream};

const STEPS: usize = 300;
const DT: f64 = 0.004;
const NU: f64 = 1.0 / 200.0;

fn grid() -> GridSpec {
    GridSpec {
        around: 128,
        radial: 96,
        outer_radius: 40.0,
        first_cell: 0.01,
        far: None,
    }
}

fn ellipse(thickness: f64) -> SectionMap {
    SectionMap::ellipse(0.5, 0.5 * thickness, (0.0, 0.0)).unwrap()
}

/// The vorticity after [`STEPS`] steps and the force and power at each,
/// computed on a pool of `threads` worker threads; with `None`, stepped
/// from this test's own thread, outside any pool: each step then runs on
/// rayon's global pool with its other workers kept awake beside it
/// (`awake_pool.rs`).
fn run<M: Motion + Send>(
    threads: Option<usize>,
    flow: impl FnOnce() -> Flow<M> + Send,
) -> Vec<f64> {
    let steps = || {
        let mut flow = flow();
        let mut out = Vec::new();
        for _ in 0..STEPS {
            flow.step(DT).unwrap();
            let loads = flow.loads();
            out.extend([loads.force.re, loads.force.im, loads.power]);
        }
        out.extend_from_slice(flow.vorticity());
        out
    };
    match threads {
        Some(threads) => rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(steps),
        None => steps(),
    }
}

/// The runs on 1, 2 and 3 threads, and the one stepped from outside any
/// pool (the global pool's workers kept awake), agree bit for bit.
fn assert_same_on_any_thread_count<M: Motion + Send>(
    name: &str,
    flow: impl Fn() -> Flow<M> + Send + Sync,
) {
    let one = run(Some(1), &flow);
    for threads in [Some(2), Some(3), None] {
        let other = run(threads, &flow);
        let differing = one
            .iter()
            .zip(&other)
            .filter(|(a, b)| a.to_bits() != b.to_bits())
            .count();
        assert_eq!(
            differing,
            0,
            "{name}: {differing} of {} values differ between 1 thread and {}",
            one.len(),
            threads.map_or("a call from outside any pool".to_string(), |n| format!(
                "{n} threads"
            ))
        );
    }
}

#[test]
fn a_rigid_flow_is_the_same_on_any_thread_count() {
    let motion = PlungePitch {
        speed: 1.0,
        omega: PI,
        plunge: 0.25,
        mean_pitch: 0.0,
        pitch: 0.3,
        phase: 0.5 * PI,
    };
    assert_same_on_any_thread_count("rigid", || {
        Flow::new(&ellipse(0.2), grid(), motion, NU).unwrap()
    });
}

#[test]
fn a_deforming_flow_is_the_same_on_any_thread_count() {
    // The thickness breathing from 0.15 to 0.25 and back over a period
    // of 2, in a unit stream.
    let samples = 16;
    let maps: Vec<SectionMap> = (0..samples)
        .map(|i| ellipse(0.2 + 0.05 * (2.0 * PI * i as f64 / samples as f64).sin()))
        .collect();
    let breathing = Deformation::periodic(&maps, 2.0).unwrap();
    let stream = SteadyStream {
        speed: 1.0,
        kick_rate: 0.0,
        kick_period: 1.0,
    };
    assert_same_on_any_thread_count("deforming", || {
        Flow::deforming(breathing.clone(), grid(), stream, NU).unwrap()
    });
}
