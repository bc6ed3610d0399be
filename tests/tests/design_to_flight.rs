//! The whole chain: the MDOIS design of the coarse case
//! (`configs/coarse.toml`, one cycle: its convergence is `host/tests/
//! design.rs`'s to check, and the capped run's final design is the
//! converged one's kinematics, analysed), its `kinematics.json` passes the
//! actuator check and the flight controller's limits, is uploaded over the
//! framed serial link to the simulated flight controller (`hil-sim serve`
//! on a pseudo-terminal, the firmware's core driving the simulated motor
//! and wing in real time) and flown: the wing reaches the commanded
//! amplitude within 2% and the commanded frequency. Then hil-sim flies the
//! designed vehicle: the run's `plant.toml` (the designed wing on the
//! design file's actuator) flies `kinematics.json` in hil-sim's in-process
//! scenario (its controller's model set to that plant) within 2% amplitude
//! in the steady state, under the controller's current limit, with the
//! duty never saturated.

use std::time::{Duration, Instant};

use fwav::config::SystemConfig;
use fwav::device::Device;
use fwav::mdois::{start, Outcome, RunOptions};
use fwav::port;
use fwav::profile_file::ProfileFile;
use fwav_actuator::params::PlantParams;
use fwav_e2e::Served;
use fwav_hil_sim::metrics::{Report, SteadyState};
use fwav_hil_sim::scenario::{run as fly_scenario, Scenario};
use fwav_protocol::{Command, EndAction, Limits};

/// The steady-state numbers of a run that must hold whole cycles.
fn steady(report: &Report) -> &SteadyState {
    report
        .steady
        .as_ref()
        .expect("the run holds whole reference cycles to measure")
}

#[test]
fn the_coarse_designs_kinematics_fly_in_hil_sim() {
    let mut config =
        SystemConfig::from_toml(include_str!("../../configs/coarse.toml")).expect("coarse case");
    // One cycle of the disciplines (the whole design converges in cycle 2,
    // host/tests/integration/design.rs, at 18 s a cycle of CI's time): the
    // final design is cycle 2's analysis of cycle 1's proposal.
    config.mdois.max_cycles = 1;
    let dir = std::env::temp_dir().join(format!("fwav-design-to-flight-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    let started = Instant::now();
    let run = start(&config, &dir, &RunOptions::default(), &|_| {}).expect("the design runs");
    let seconds = started.elapsed().as_secs_f64();
    println!("coarse design: {:?} in {seconds:.1} s", run.outcome);
    // At the cycle cap the run ends as "cycle cap reached", never as
    // converged: with one cycle allowed, the coarse design still changes
    // in cycle 1, and cycle 2 is only the system analysis of its
    // proposal, reported as the final design (checked here rather than by
    // a run of its own in host/tests/integration/design.rs).
    assert!(
        matches!(run.outcome, Some(Outcome::CycleCap { max_cycles: 1 })),
        "{:?}",
        run.outcome
    );
    assert_eq!(run.stages_computed, 4);
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["outcome"], "cycle cap reached");
    assert!(summary["converged_cycle"].is_null());
    assert_eq!(summary["final"]["cycle"], 2);
    assert_eq!(summary["cycles"][0]["change"]["design_unchanged"], false);
    assert!(summary["cycles"][1]["aerodynamic"].is_null());
    let report = std::fs::read_to_string(dir.join("report.md")).unwrap();
    assert!(report.contains("Not converged: the cycle cap of 1 was reached"));
    assert!(dir.join("topology.png").exists());
    let actuator = run.summary.actuator.as_ref().expect("actuator verdict");
    println!(
        "actuator: feasible {}, limiting {} {:.4} {} of {:.4}",
        actuator.feasible,
        actuator.limiting.quantity,
        actuator.limiting.value,
        actuator.limiting.unit,
        actuator.limiting.limit
    );

    // The flown kinematics are the analysed ones, feasible on the designed
    // vehicle with the reserve (the discipline's constraint; no derating).
    assert!(actuator.feasible, "{actuator:?}");
    let file = ProfileFile::load(dir.join("kinematics.json")).expect("kinematics.json loads");
    assert!(file.violations(&Limits::REFERENCE_FWAV).is_empty());
    let segment = file.document.segments[0];
    assert_eq!(segment.frequency_hz, actuator.frequency_hz);
    assert_eq!(segment.amplitude_deg, actuator.amplitude_deg);

    let served = Served::start();
    let mut device =
        Device::connect(port::open(&served.path).expect("pty")).expect("handshake with hil-sim");
    device
        .upload(&file.profile)
        .expect("accepted and read back");
    let session = device.arm().unwrap();
    device.command(Command::Start).unwrap();
    device.telemetry(true, 100).unwrap();
    // The ramp, then 1.5 s (16 or more flapping cycles) to settle.
    let flight = Duration::from_secs_f64(segment.ramp_s + 1.5);
    let clock = Instant::now();
    let mut samples = Vec::new();
    while clock.elapsed() < flight {
        device.heartbeat(session).unwrap();
        let status = device.status().unwrap();
        assert!(status.armed && status.running, "{status:?}");
        device.link.listen(Duration::from_millis(100)).unwrap();
        samples.extend(device.link.take_telemetry());
    }
    let last = samples.last().expect("telemetry");
    let amplitude = f64::from(last.amplitude_est_rad).to_degrees();
    let frequency = f64::from(last.frequency_est_hz);
    println!(
        "flown: amplitude {amplitude:.3} deg (commanded {}), frequency {frequency:.3} Hz (commanded {})",
        segment.amplitude_deg, segment.frequency_hz
    );
    assert!(
        (amplitude - segment.amplitude_deg).abs() < 0.02 * segment.amplitude_deg,
        "amplitude {amplitude} deg against {}",
        segment.amplitude_deg
    );
    assert!(
        (frequency - segment.frequency_hz).abs() < 0.01 * segment.frequency_hz,
        "frequency {frequency} Hz against {}",
        segment.frequency_hz
    );
    device.command(Command::Stop).unwrap();
    device.command(Command::Disarm).unwrap();

    // The designed vehicle flies the designed kinematics.
    let plant_text = std::fs::read_to_string(dir.join("plant.toml")).expect("plant.toml written");
    let plant = PlantParams::from_toml(&plant_text).expect("plant.toml parses");
    assert!(
        plant_text.contains("fwav fc params --set wing_inertia="),
        "plant.toml names the controller's parameters"
    );
    let scenario = Scenario {
        // The ramp, then 2.5 s held; the steady state is the last 10 cycles.
        duration_s: segment.ramp_s + 2.5,
        heartbeat_s: 0.1,
        measure_cycles: 10,
        on_end: EndAction::Hold,
        segments: file.document.segments.clone(),
        faults: vec![],
    };
    let report = fly_scenario(&scenario, &plant).expect("the scenario runs");
    println!(
        "designed vehicle (wing {:.4e} kg m^2, spring {:.4} N m/rad): amplitude error {:+.3}%, steady peak current {:.3} A of {:.3} A, duty saturated {:.1}%",
        plant.wing.inertia_kg_m2,
        plant.transmission.spring_nm_per_rad,
        steady(&report).amplitude_error_pct,
        steady(&report).steady_peak_current_a,
        report.current_limit_a,
        steady(&report).duty_saturated_pct
    );
    assert!(
        steady(&report).amplitude_error_pct.abs() < 2.0,
        "{report:?}"
    );
    assert!(
        steady(&report).steady_peak_current_a < report.current_limit_a,
        "{report:?}"
    );
    assert_eq!(steady(&report).duty_saturated_pct, 0.0, "{report:?}");
    std::fs::remove_dir_all(&dir).ok();
}
