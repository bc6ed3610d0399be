//! Speed of the whole design (issue target: the default full-size design
//! in < 15 min on 2 cores): `fwav design` on the built-in FWAV (6760-element
//! wing, default `[design]`, `[topology]` and `[mdois]`), to convergence or
//! the cycle cap, printing each stage's start and end. The run's files stay
//! in `FWAV_DESIGN_DIR` (default: a new directory under the system's
//! temporary directory); an existing run there is resumed.
//! `cargo bench -p fwav --bench design`.

use std::path::PathBuf;
use std::time::Instant;

use fwav::config::SystemConfig;
use fwav::mdois::{resume, start, Event, Progress, RunOptions};

fn main() {
    let dir = std::env::var("FWAV_DESIGN_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|_| {
            std::env::temp_dir().join(format!("fwav-design-bench-{}", std::process::id()))
        });
    let config = SystemConfig::default();
    let report = |p: &Progress| match p.event {
        Event::Started | Event::Finished { .. } | Event::Reused | Event::InnerCycle { .. } => {
            println!(
                "{:7.1} s  cycle {} {:?}: {:?}",
                p.elapsed.as_secs_f64(),
                p.cycle,
                p.stage,
                p.event
            );
        }
        Event::Advanced { .. } => {}
    };
    let clock = Instant::now();
    let run = if dir.join("state.json").exists() {
        resume(&dir, None, &RunOptions::default(), &report)
    } else {
        start(&config, &dir, &RunOptions::default(), &report)
    }
    .expect("the design runs");
    let seconds = clock.elapsed().as_secs_f64();
    println!(
        "default design: {:?} after {} cycle(s), {seconds:.0} s ({:.1} min) wall, {:.0} s of stage time; results in {}",
        run.outcome,
        run.summary.cycles.len(),
        seconds / 60.0,
        run.summary.stage_seconds,
        dir.display()
    );
    for c in &run.summary.cycles {
        println!("{}", serde_json::to_string(c).unwrap_or_default());
    }
}
