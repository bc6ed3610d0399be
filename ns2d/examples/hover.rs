//! The hovering ellipse of Wang, Birch & Dickinson (2004), Re 75: lift
//! history by period.
//!
//! `cargo run --release -p fwav-ns2d --example hover -- AROUND RADIAL OUTER FIRST_CELL DT PERIODS`

use fwav_ns2d::cases::{HoveringEllipse, HoveringStroke, Resolution};
use fwav_ns2d::{Flow, GridSpec, SectionMap};

fn main() {
    let args: Vec<f64> = std::env::args().skip(1).map(|a| a.parse().unwrap()).collect();
    let grid = GridSpec {
        around: args[0] as usize,
        radial: args[1] as usize,
        outer_radius: args[2],
        first_cell: args[3],
    };
    let dt = args[4];
    let periods = args[5];
    let stroke = HoveringStroke::wang_2004();
    let map = SectionMap::ellipse(0.5, 0.06, (0.0, 0.0)).unwrap();
    let probe = Flow::new(&map, grid, stroke, stroke.peak_speed() / 75.0).unwrap();
    eprintln!("stable dt at start: {:.3e}", probe.stable_dt(0.5));
    let started = std::time::Instant::now();
    let lift = HoveringEllipse { reynolds: 75.0, periods }
        .run(Resolution { grid, dt })
        .unwrap();
    let text: String = lift.iter().map(|(t, cl)| format!("{t} {cl}\n")).collect();
    std::fs::write("/tmp/hover_lift.txt", text).unwrap();
    println!("{} steps in {:.1} s", lift.len(), started.elapsed().as_secs_f64());
}
