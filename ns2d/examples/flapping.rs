//! A thin ellipse plunging and pitching in a stream: cycle-mean thrust,
//! power and the cost of a cycle.
//!
//! `cargo run --release -p fwav-ns2d --example flapping -- RE K H0 PITCH_DEG PHASE_DEG THICKNESS AROUND RADIAL STEPS_PER_CYCLE CYCLES`
//! (chord 1, unit stream, reduced frequency k = ω c / 2U, pivot at the
//! quarter chord).

use fwav_ns2d::{Flow, GridSpec, PlungePitch, SectionMap};

fn main() {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|x| x.parse().unwrap())
        .collect();
    let (re, k, h0, pitch, phase, thickness) = (a[0], a[1], a[2], a[3], a[4], a[5]);
    let (around, radial, steps, cycles) =
        (a[6] as usize, a[7] as usize, a[8] as usize, a[9] as usize);
    let omega = 2.0 * k;
    let motion = PlungePitch {
        speed: 1.0,
        omega,
        plunge: h0,
        mean_pitch: 0.0,
        pitch: pitch.to_radians(),
        phase: phase.to_radians(),
    };
    // Pivot at the quarter chord: the ellipse's centre 0.25 c behind it.
    let map = SectionMap::ellipse(0.5, 0.5 * thickness, (0.25, 0.0)).unwrap();
    let grid = GridSpec {
        around,
        radial,
        outer_radius: 120.0,
        first_cell: 0.3 / re.sqrt(),
        far: None,
    };
    let mut flow = Flow::new(&map, grid, motion, 1.0 / re).unwrap();
    let period = std::f64::consts::TAU / omega;
    let dt = period / steps as f64;
    eprintln!("dt {dt:.2e}, stable at start {:.2e}", flow.stable_dt(0.5));
    let started = std::time::Instant::now();
    for cycle in 0..cycles {
        let (mut thrust, mut power) = (0.0, 0.0);
        for _ in 0..steps {
            flow.step(dt).unwrap();
            let loads = flow.loads();
            thrust += -loads.force.re * dt;
            power += loads.power * dt;
        }
        let (ct, cp) = (2.0 * thrust / period, 2.0 * power / period);
        eprintln!(
            "cycle {}: CT {ct:.4} CP {cp:.4} efficiency {:.3} (stable dt now {:.2e})",
            cycle + 1,
            ct / cp,
            flow.stable_dt(0.5)
        );
    }
    let wall = started.elapsed().as_secs_f64();
    println!(
        "{cycles} cycles in {wall:.1} s: {:.1} ns per cell per step",
        wall * 1e9 / (cycles * steps * around * radial) as f64
    );
}
