//! The hovering ellipse of Wang, Birch & Dickinson (2004), Re 75: lift
//! history by period.
//!
//! `cargo run --release -p fwav-ns2d --example hover -- AROUND RADIAL OUTER FIRST_CELL DT PERIODS`

use fwav_ns2d::cases::{HoveringEllipse, HoveringStroke, Resolution};
use fwav_ns2d::{Flow, GridSpec, SectionMap};

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().unwrap())
        .collect();
    let grid = GridSpec {
        around: args[0] as usize,
        radial: args[1] as usize,
        outer_radius: args[2],
        first_cell: args[3],
        far: None,
    };
    let dt = args[4];
    let periods = args[5];
    let mut stroke = HoveringStroke::wang_2004();
    if let Ok(p) = std::env::var("PITCH") {
        stroke.pitch = p.parse().unwrap();
    }
    if let Ok(a) = std::env::var("MEAN") {
        stroke.mean_angle = a.parse().unwrap();
    }
    if let Ok(a) = std::env::var("STROKE") {
        stroke.stroke = a.parse().unwrap();
    }
    let map = SectionMap::ellipse(0.5, 0.06, (0.0, 0.0)).unwrap();
    let mut probe = Flow::new(
        &map,
        grid,
        stroke,
        HoveringStroke::wang_2004().peak_speed() / 75.0,
    )
    .unwrap();
    eprintln!("stable dt at start: {:.3e}", probe.stable_dt(0.5));
    if std::env::var("TRACE").is_ok() {
        let mut n = 0;
        while probe.time() < periods * 4.0 {
            if let Err(e) = probe.step(dt) {
                eprintln!("{e}");
                break;
            }
            n += 1;
            if n % 200 == 0 {
                let w = probe.vorticity();
                let nt = grid.around;
                let (imax, wmax) = w.iter().enumerate().fold((0, 0.0f64), |(bi, bm), (i, v)| {
                    if v.abs() > bm {
                        (i, v.abs())
                    } else {
                        (bi, bm)
                    }
                });
                eprintln!(
                    "t {:.3} stable {:.2e} wmax {:.3e} at j {} k {} CL {:.3}",
                    probe.time(),
                    probe.stable_dt(0.5),
                    wmax,
                    imax / nt,
                    imax % nt,
                    probe.loads().force.im * 2.0 / HoveringStroke::wang_2004().peak_speed().powi(2)
                );
                eprintln!(
                    "   force {:?} moment {:.4} closure {:.4} p-range {:.3}",
                    probe.loads().force,
                    probe.loads().moment,
                    probe.loads().closure,
                    probe
                        .loads()
                        .pressure
                        .iter()
                        .fold(0.0f64, |m, p| m.max(p.abs()))
                );
            }
        }
        return;
    }
    let started = std::time::Instant::now();
    let lift = HoveringEllipse {
        reynolds: 75.0,
        periods,
    }
    .run(Resolution { grid, dt })
    .unwrap();
    let text: String = lift.iter().map(|(t, cl)| format!("{t} {cl}\n")).collect();
    std::fs::write("/tmp/hover_lift.txt", text).unwrap();
    println!(
        "{} steps in {:.1} s",
        lift.len(),
        started.elapsed().as_secs_f64()
    );
}
