//! The impulsively started cylinder (Koumoutsakos & Leonard 1995) at a
//! chosen resolution and time step: the drag's worst deviation from the
//! published curve over U t / R in [0.5, 3], the largest Courant number
//! and wall residual of the run, and its cost. For choosing a time step
//! against the Courant number it costs.
//!
//! `cargo run --release -p fwav-ns2d --example impulsive -- RE AROUND RADIAL FIRST_CELL_D DT`

use fwav_ns2d::{Flow, GridSpec, ReferenceCurve, SectionMap, SteadyStream};

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| {
            a.parse()
                .expect("numbers: RE AROUND RADIAL FIRST_CELL_D DT")
        })
        .collect();
    let [re, around, radial, first, dt] = args[..] else {
        panic!("usage: RE AROUND RADIAL FIRST_CELL_D DT");
    };
    let name = format!("koumoutsakos_leonard_1995_re{re:.0}.dat");
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("Re 550 or 3000");
    let curve = ReferenceCurve::parse(&text).unwrap();
    let spec = GridSpec {
        around: around as usize,
        radial: radial as usize,
        outer_radius: 100.0,
        first_cell: first,
        far: None,
    };
    let motion = SteadyStream {
        speed: 1.0,
        kick_rate: 0.0,
        kick_period: 1.0,
    };
    let map = SectionMap::circle(0.5).unwrap();
    let mut flow = Flow::new(&map, spec, motion, 1.0 / re).unwrap();
    let clock = std::time::Instant::now();
    let (mut courant, mut residual) = (0.0_f64, 0.0_f64);
    let mut drag = Vec::new();
    while 2.0 * flow.time() < 3.05 {
        courant = courant.max(dt / flow.stable_dt(1.0));
        flow.step(dt).unwrap();
        residual = residual.max(flow.wall_residual());
        drag.push((2.0 * flow.time(), 2.0 * flow.loads().force.re));
        if std::env::var("TRACE").is_ok() {
            let w = flow.vorticity();
            let worst = w.iter().enumerate().fold((0, 0.0_f64), |m, (i, v)| {
                if v.abs() > m.1 {
                    (i, v.abs())
                } else {
                    m
                }
            });
            eprintln!(
                "{:.3} CD {:.4} res {:.1e} max|w| {:.1} at ring {} node {}",
                2.0 * flow.time(),
                drag.last().unwrap().1,
                flow.wall_residual(),
                worst.1,
                worst.0 / (around as usize),
                worst.0 % (around as usize)
            );
        }
    }
    let seconds = clock.elapsed().as_secs_f64();
    let (error, at) = curve.worst_deviation(&drag, (0.5, 3.0), f64::abs);
    println!(
        "Re {re} {around}x{radial} dt {dt}: worst {:.2}% at U t/R {at:.2}; Courant {courant:.2}, \
         wall residual {residual:.1e}; {seconds:.1} s, {:.1} ns per cell per step",
        100.0 * error,
        1e9 * seconds / (around * radial * drag.len() as f64)
    );
}
