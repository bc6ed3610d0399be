//! System analysis speed (issue target: the default FWAV case, the paper's
//! 2 x 6760-element shell with the default lattice, 4 flapping cycles,
//! converged coupling, < 60 s on 2 cores). One run is long enough to time
//! by itself, so this bench runs it once (plus the rigid wing for scale)
//! and prints seconds per cycle and per step, then the default case's
//! time-step and lattice convergence (step halved, lattice doubled each
//! way); `cargo bench -p fwav --bench system`.

use std::time::Instant;

use fwav::aeroelastic::{run, FlappingKinematics, FlightCondition, SystemSettings};
use fwav::config::SystemConfig;

fn main() {
    // The default configuration's wing: the full carbon layer.
    let wing = SystemConfig::default().wing_model().expect("default wing");
    let base = SystemSettings::default();
    let cases = [
        (
            "rigid wing",
            SystemSettings {
                rigid: true,
                ..base
            },
        ),
        ("flexible wing, 2 x 6760 shell elements", base),
        (
            "flexible, step halved",
            SystemSettings {
                steps_per_cycle: 2 * base.steps_per_cycle,
                ..base
            },
        ),
        (
            "flexible, lattice doubled",
            SystemSettings {
                chordwise_panels: 2 * base.chordwise_panels,
                spanwise_panels: 2 * base.spanwise_panels,
                ..base
            },
        ),
    ];
    for (name, settings) in cases {
        let started = Instant::now();
        let result = run(
            &wing,
            &FlappingKinematics::INITIAL,
            &FlightCondition::FWAV,
            &settings,
            0,
            |_, _| {},
        )
        .expect("system analysis");
        let seconds = started.elapsed().as_secs_f64();
        let steps = result.steps.len();
        let sub = result.steps.iter().map(|s| s.subiterations).sum::<usize>() as f64 / steps as f64;
        println!(
            "system analysis ({}), {} x {} lattice, {} cycles x {} steps: {:.1} s, {:.2} s a cycle, {:.1} ms a step, {:.1} sub-iterations a step; CT {:.4}, CP {:.4}, efficiency {:.3}",
            name,
            settings.chordwise_panels,
            settings.spanwise_panels,
            settings.cycles,
            settings.steps_per_cycle,
            seconds,
            seconds / settings.cycles as f64,
            1e3 * seconds / steps as f64,
            sub,
            result.means.ct,
            result.means.cp,
            result.means.efficiency
        );
    }
}
