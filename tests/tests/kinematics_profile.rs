//! Optimized kinematics to `kinematics.json`: the host's profile builder
//! (protocol limits) and the actuator feasibility check (`fwav-actuator`)
//! together, as the design run writes the file, and the written file flown
//! by the firmware core on the simulated plant.

use fwav::profile_file::{ProfileFile, ProfileFileError};
use fwav_actuator::feasibility::{check, nearest_feasible, ActuatorLimits, FlappingDemand};
use fwav_actuator::params::PlantParams;
use fwav_hil_sim::metrics::{Report, SteadyState};
use fwav_hil_sim::scenario::{run, Scenario};
use fwav_protocol::document::ProfileDocument;
use fwav_protocol::{Limits, ProfileError};

/// The steady-state numbers of a run that must hold whole cycles.
fn steady(report: &Report) -> &SteadyState {
    report
        .steady
        .as_ref()
        .expect("the run holds whole reference cycles to measure")
}

/// A file in the system's temporary directory, removed when dropped.
struct TempFile(std::path::PathBuf);

impl TempFile {
    fn new(name: &str) -> Self {
        Self(std::env::temp_dir().join(format!("fwav-{}-{name}", std::process::id())))
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

#[test]
fn kinematics_profile_is_built_checked_and_round_trips() {
    let limits = Limits::REFERENCE_FWAV;
    let file = ProfileFile::from_kinematics(
        "kinematics.json",
        11.0,
        30.0,
        0.0,
        "initial design",
        &limits,
    )
    .unwrap();
    assert!(
        file.document
            .description
            .starts_with("initial design: 11 Hz, +-30 deg"),
        "{}",
        file.document.description
    );
    let s = &file.profile.segments[0];
    assert!((s.amplitude_rad - 30f32.to_radians()).abs() < 1e-6);
    assert_eq!(s.downstroke_fraction, 0.5);
    assert_eq!(file.document.segments[0].ramp_s, 1.0);
    let text = file.document.to_json_pretty();
    assert_eq!(ProfileDocument::from_json(&text).unwrap(), file.document);

    // 45 deg needs 1.5 * 45 / (0.9 * 60) = 1.25 s of ramp: rounded up.
    let wide = ProfileFile::from_kinematics("k.json", 11.0, 45.0, 0.0, "x", &limits).unwrap();
    assert_eq!(wide.document.segments[0].ramp_s, 1.3);
    assert!(wide.violations(&limits).is_empty());

    let refused =
        ProfileFile::from_kinematics("k.json", 40.0, 80.0, 0.0, "absurd", &limits).unwrap_err();
    println!("{refused}");
    match refused {
        ProfileFileError::OutOfLimits { violations, .. } => {
            assert!(violations.len() >= 2, "{violations:?}");
            assert!(violations
                .iter()
                .any(|v| matches!(v, ProfileError::FrequencyOutOfRange { .. })));
            assert!(violations
                .iter()
                .any(|v| matches!(v, ProfileError::AmplitudeOutOfRange { .. })));
        }
        other => panic!("{other}"),
    }
    let nan = ProfileFile::from_kinematics("k.json", f64::NAN, 30.0, 0.0, "nan", &limits);
    assert!(matches!(nan, Err(ProfileFileError::OutOfLimits { .. })));
}

/// The absurd optimum 40 Hz +-80 deg: refused by the actuator check with
/// its limiting quantity; the nearest feasible kinematics become the
/// profile, written, read back as `fwav upload` reads it, and flown: the
/// wing reaches the commanded amplitude within 2%.
#[test]
fn nearest_feasible_kinematics_written_and_flown_reach_their_amplitude() {
    let plant = PlantParams::default();
    let limits = ActuatorLimits::firmware_default();
    let envelope = Limits::REFERENCE_FWAV;
    let optimum = FlappingDemand {
        frequency_hz: 40.0,
        amplitude_deg: 80.0,
        mean_deg: 0.0,
    };
    let verdict = check(&plant, &limits, &optimum).unwrap();
    assert!(!verdict.feasible);
    let nearest = nearest_feasible(&plant, &limits, &envelope, &optimum).unwrap();
    let d = nearest.demand();
    let source = format!(
        "nearest feasible to the optimum {optimum} (limited by the {})",
        verdict.limiting
    );
    let path = TempFile::new("kinematics.json");
    let built = ProfileFile::from_kinematics(
        &path.0,
        d.frequency_hz,
        d.amplitude_deg,
        d.mean_deg,
        &source,
        &envelope,
    )
    .unwrap();
    built.save().unwrap();
    let loaded = ProfileFile::load(&path.0).unwrap();
    println!("{}", loaded.document.to_json_pretty());
    assert_eq!(loaded.document, built.document);
    assert!(loaded.violations(&envelope).is_empty());

    let segment = loaded.document.segments[0];
    let scenario = Scenario {
        duration_s: segment.ramp_s + 2.5,
        heartbeat_s: 0.1,
        measure_cycles: 10,
        on_end: loaded.document.on_end,
        segments: loaded.document.segments.clone(),
        faults: vec![],
    };
    let report = run(&scenario, &plant).unwrap();
    println!(
        "{d}: amplitude error {:.3}%, peak current {:.3} A",
        steady(&report).amplitude_error_pct,
        report.peak_current_a
    );
    assert!((steady(&report).target_amplitude_deg - d.amplitude_deg).abs() < 1e-3);
    assert!(steady(&report).amplitude_error_pct.abs() < 2.0);
    assert!(report.peak_current_a <= report.current_limit_a);
}
