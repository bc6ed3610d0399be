//! A cylinder of diameter 1 in a unit stream: force history and the
//! shedding's Strouhal number.
//!
//! `cargo run --release -p fwav-ns2d --example cylinder -- RE AROUND RADIAL OUTER_D FIRST_CELL T_END [DT]`

use fwav_ns2d::{Flow, GridSpec, SectionMap, SteadyStream};

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().unwrap())
        .collect();
    let (re, around, radial, outer_d, first, t_end) = (
        args[0],
        args[1] as usize,
        args[2] as usize,
        args[3],
        args[4],
        args[5],
    );
    let fixed_dt = args.get(6).copied().unwrap_or(0.01);
    let map = SectionMap::circle(0.5).unwrap();
    let spec = GridSpec {
        around,
        radial,
        outer_radius: 2.0 * outer_d,
        first_cell: first,
        far: None,
    };
    let motion = SteadyStream {
        speed: 1.0,
        kick_rate: std::env::var("KICK").map_or(0.5, |v| v.parse().unwrap()),
        kick_period: 2.0,
    };
    let mut flow = Flow::new(&map, spec, motion, 1.0 / re).unwrap();
    let started = std::time::Instant::now();
    let mut history = Vec::new();
    let mut dt;
    while flow.time() < t_end {
        if history.len() % 200 == 0 {
            let limit = flow.stable_dt(0.5);
            if limit < fixed_dt {
                eprintln!(
                    "t {:.2}: dt {fixed_dt} above the limit {limit:.2e}",
                    flow.time()
                );
            }
        }
        dt = fixed_dt;
        flow.step(dt).unwrap();
        let loads = flow.loads();
        history.push((flow.time(), loads.force.re * 2.0, loads.force.im * 2.0));
        if std::env::var("WHERE").is_ok() {
            let w = flow.vorticity();
            let (imax, _) = w.iter().enumerate().fold((0, 0.0f64), |(bi, bm), (i, v)| {
                if v.abs() > bm {
                    (i, v.abs())
                } else {
                    (bi, bm)
                }
            });
            eprintln!(
                "step {} wmax at j {} k {} = {:.3e}; wall mean {:.3e}",
                history.len(),
                imax / around,
                imax % around,
                w[imax],
                w[..around].iter().sum::<f64>() / around as f64
            );
        }
        if std::env::var("CLOSURE").is_ok() && history.len() % 100 == 0 {
            let p = &loads.pressure;
            let range = p.iter().fold(f64::MIN, |m, v| m.max(*v))
                - p.iter().fold(f64::MAX, |m, v| m.min(*v));
            eprintln!(
                "t {:.2} closure {:.4} range {:.4} CL {:.4}",
                flow.time(),
                loads.closure,
                range,
                loads.force.im * 2.0
            );
        }
        if history.len() % 500 == 0 || history.len() < 40 {
            eprintln!(
                "t {:.4} dt {:.2e} wmax {:.3e} CD {:.4} CL {:.4}",
                flow.time(),
                dt,
                flow.vorticity().iter().fold(0.0f64, |m, w| m.max(w.abs())),
                loads.force.re * 2.0,
                loads.force.im * 2.0
            );
        }
    }
    let wall = started.elapsed().as_secs_f64();
    if let Ok(path) = std::env::var("HISTORY") {
        let text: String = history
            .iter()
            .map(|h| format!("{} {} {}\n", h.0, h.1, h.2))
            .collect();
        std::fs::write(path, text).unwrap();
    }
    // Last third: mean CD, CL amplitude, period from upward zero crossings.
    let from = t_end * 2.0 / 3.0;
    let tail: Vec<_> = history.iter().filter(|h| h.0 >= from).collect();
    let cd = tail.iter().map(|h| h.1).sum::<f64>() / tail.len() as f64;
    let cl_max = tail.iter().map(|h| h.2).fold(f64::MIN, f64::max);
    let cl_min = tail.iter().map(|h| h.2).fold(f64::MAX, f64::min);
    let mut ups = Vec::new();
    for w in tail.windows(2) {
        if w[0].2 < 0.0 && w[1].2 >= 0.0 {
            ups.push(w[0].0 + (w[1].0 - w[0].0) * (-w[0].2) / (w[1].2 - w[0].2));
        }
    }
    let st = if ups.len() > 1 {
        (ups.len() - 1) as f64 / (ups[ups.len() - 1] - ups[0])
    } else {
        f64::NAN
    };
    let steps = history.len();
    let cells = around * radial;
    println!(
        "Re {re}: CD {cd:.4} CL +{cl_max:.4}/{cl_min:.4} St {st:.4} | {steps} steps {wall:.1} s, {:.1} ns/cell/step",
        wall * 1e9 / (steps as f64 * cells as f64)
    );
}
