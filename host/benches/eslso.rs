//! Speed of the whole structural discipline on the default case (issue
//! target < 2 min on 2 cores): ESLSO on the default FWAV wing (6760
//! elements) under the pressure history of the default system analysis,
//! from the wing the system analysis flew (full carbon layer), to
//! convergence or the cycle cap. The system analysis that makes the pressure is not timed;
//! `FWAV_PRESSURE=path/pressure.json` reuses one already written.
//! `FWAV_LAYOUT=topology.json` starts from a layout `fwav topology` wrote,
//! `FWAV_RESPONSE_ONLY=1` stops after the first nonlinear analysis, and
//! `FWAV_SIMP_ITERATIONS=n` changes SIMP's iteration cap per cycle and
//! `FWAV_LAYOUT_TOLERANCE=x` the fraction of design elements that may
//! still flip in a converged cycle (0: the paper's strict rule).
//! `cargo bench -p fwav --bench eslso`.

use std::time::Instant;

use fwav::aeroelastic::analysis::{run, SystemSettings};
use fwav::aeroelastic::kinematics::FlappingKinematics;
use fwav::aeroelastic::model::{FlightCondition, WingModel};
use fwav::shell::material::Layer;
use fwav::topology::eslso::{optimize, DesignProblem, EslsoProgress, EslsoSettings};
use fwav::topology::pressure::PressureHistory;
use fwav::topology::response::nonlinear_response;

fn main() {
    let wing = WingModel::fwav(1.0).expect("default wing");
    let elements = wing.wing.mesh.elements.len();
    let pressure = match std::env::var("FWAV_PRESSURE") {
        Ok(path) => {
            let text = std::fs::read_to_string(&path).expect("pressure file");
            PressureHistory::from_json(&text, elements).expect("pressure history")
        }
        Err(_) => {
            let result = run(
                &wing,
                &FlappingKinematics::INITIAL,
                &FlightCondition::FWAV,
                &SystemSettings::default(),
                0,
                |_, _| {},
            )
            .expect("system analysis");
            PressureHistory::new(result.dt_s, result.pressure_history, elements)
                .expect("pressure history")
        }
    };
    let problem = DesignProblem::wing(&wing.wing, Layer::CARBON, Layer::MYLAR);
    let mut settings = EslsoSettings::default();
    // `FWAV_SIMP_ITERATIONS=n` changes the SIMP iteration cap per cycle.
    if let Some(n) = std::env::var("FWAV_SIMP_ITERATIONS")
        .ok()
        .and_then(|v| v.parse().ok())
    {
        settings.simp.max_iterations = n;
    }
    if let Some(x) = std::env::var("FWAV_LAYOUT_TOLERANCE")
        .ok()
        .and_then(|v| v.parse().ok())
    {
        settings.layout_tolerance = x;
    }
    let design_elements = problem.design.iter().filter(|&&d| d).count();
    println!(
        "{design_elements} design elements; unchanged when at most {} flip",
        (settings.layout_tolerance * design_elements as f64).floor()
    );
    // The MDOIS hands the discipline the wing of the system analysis;
    // `FWAV_LAYOUT=topology.json` starts from a layout written by `fwav
    // topology` instead, and `FWAV_RESPONSE_ONLY=1` stops after its first
    // nonlinear analysis (the profile of one analysis).
    let start = match std::env::var("FWAV_LAYOUT") {
        Ok(path) => {
            let text = std::fs::read_to_string(&path).expect("layout file");
            let value: serde_json::Value = serde_json::from_str(&text).expect("layout JSON");
            serde_json::from_value(value["carbon"].clone()).expect("carbon densities")
        }
        Err(_) => wing.densities.clone(),
    };
    // One nonlinear dynamic analysis of the starting design, with progress.
    let clock = Instant::now();
    let mut last = Instant::now();
    let response = nonlinear_response(
        &problem.mesh,
        &problem.sections(&start, settings.simp.penalty),
        &problem.fixed,
        &pressure,
        &settings.response,
        |done, total| {
            if last.elapsed().as_secs_f64() > 20.0 || done == total {
                last = Instant::now();
                println!(
                    "  step {done}/{total} at {:.0} s",
                    clock.elapsed().as_secs_f64()
                );
            }
        },
    )
    .expect("nonlinear response");
    println!(
        "nonlinear dynamic analysis of the starting design: {:.1} s, {} Newton iterations, peak displacement {:.2} mm",
        clock.elapsed().as_secs_f64(),
        response.newton_iterations,
        1e3 * response.peak_displacement.iter().fold(0.0f64, |m, &p| m.max(p))
    );
    if std::env::var_os("FWAV_RESPONSE_ONLY").is_some() {
        return;
    }
    let clock = Instant::now();
    let mut last = Instant::now();
    let result = optimize(&problem, &pressure, &start, &settings, |p| {
        let c = match p {
            EslsoProgress::Step { cycle, done, total } => {
                if last.elapsed().as_secs_f64() > 20.0 {
                    last = Instant::now();
                    println!("  cycle {cycle}: step {done}/{total} at {:.0} s", clock.elapsed().as_secs_f64());
                }
                return;
            }
            EslsoProgress::Cycle(c) => c,
        };
        println!(
            "cycle {}: strain energy {:.4e} J, mass {:.3}, peak {:.2} mm, {} Newton, {} SIMP iterations, {} changed (densities within {:.3} of the threshold), {:.1} s + {:.1} s",
            c.cycle,
            c.strain_energy_j,
            c.mass_fraction,
            1e3 * c.peak_displacement_m,
            c.newton_iterations,
            c.simp_iterations,
            c.changed,
            c.flip_margin,
            c.analysis_s,
            c.optimization_s
        )
    })
    .expect("ESLSO");
    println!(
        "ESLSO on the default wing ({elements} elements, {} load cases): {:.1} s, {} cycles, converged {}",
        pressure.samples.len() / settings.response.sample_every,
        clock.elapsed().as_secs_f64(),
        result.cycles.len(),
        result.converged
    );
}
