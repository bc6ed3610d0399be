//! Speed of the aerodynamic discipline (issue target: the whole discipline
//! on the default case < 20 s on 2 cores): the built-in FWAV's mid-span
//! section deforming as the default system analysis finds it (run first,
//! not timed), 1 + 18 + 2 evaluations and NSGA-II on the surfaces, no
//! cache. `cargo bench -p fwav --bench kinematics`.

use std::time::Instant;

use fwav::aeroelastic::run;
use fwav::config::SystemConfig;
use fwav::discipline::cache::EvaluationCache;
use fwav::discipline::kinematic::{optimize, Weights};
use fwav::discipline::section::SectionCase;
use fwav::optimize::nsga2::Nsga2Config;

fn main() {
    let config = SystemConfig::default();
    let wing = config.wing_model().expect("default wing");
    let system = run(
        &wing,
        &config.kinematics(),
        &config.flight(),
        &config.analysis,
        0,
        |_, _| {},
    )
    .expect("system analysis");
    let planform = config.planform();
    let radius = 0.5 * planform.semi_span;
    let case = SectionCase {
        chord: planform.chord(radius),
        radius,
        flight: config.flight(),
        deformation: system.section_history,
        ..SectionCase::fwav_mid_span()
    };
    let started = Instant::now();
    let result = optimize(
        &case,
        &config.design_space(),
        fwav::aeroelastic::kinematics::FlappingKinematics::from_degrees([11.0, 30.0, 0.0, 90.0]),
        Weights {
            thrust: 1.0,
            efficiency: 1.0,
        },
        &Nsga2Config::default(),
        &EvaluationCache::new(),
    )
    .expect("discipline");
    println!(
        "aerodynamic discipline, deforming FWAV mid-span section: {:.2} s (chosen: {:?})",
        started.elapsed().as_secs_f64(),
        result.chosen.map(|i| result.candidates[i].method.clone())
    );
}
