//! The feasibility check against the simulator: the analytic steady-state
//! peaks against the plant flown by the firmware core; an absurd demand's
//! verdict and its nearest feasible kinematics, flown. (The check on its
//! own: `actuator/tests/feasibility.rs`.)
//!
//! Flown on the plant these numbers were measured on, the old default (a
//! 1 g wing on an 8 mm motor, `issue21_plant.toml`, `git show
//! 720cb81:actuator/plant.toml`): the machinery is the same on any plant,
//! and the new default plant (the designed vehicle) has its own
//! check-against-hil-sim test, `check_agrees.rs`.

use fwav_actuator::feasibility::{
    check, nearest_feasible, ActuatorLimits, Change, FlappingDemand, Quantity,
};
use fwav_actuator::params::PlantParams;
use fwav_hil_sim::metrics::{Report, SteadyState, TracePoint};
use fwav_hil_sim::scenario::{run_with_trace, Scenario};
use fwav_protocol::document::SegmentDocument;
use fwav_protocol::{EndAction, Limits};

/// The steady-state numbers of a run that must hold whole cycles.
fn steady(report: &Report) -> &SteadyState {
    report
        .steady
        .as_ref()
        .expect("the run holds whole reference cycles to measure")
}

fn demand(frequency_hz: f64, amplitude_deg: f64, mean_deg: f64) -> FlappingDemand {
    FlappingDemand {
        frequency_hz,
        amplitude_deg,
        mean_deg,
    }
}

/// A run of one held segment: `ramp_s` from rest, then held to `duration_s`.
fn fly(
    p: &PlantParams,
    d: &FlappingDemand,
    ramp_s: f64,
    duration_s: f64,
) -> (Report, Vec<TracePoint>) {
    let scenario = Scenario {
        duration_s,
        heartbeat_s: 0.1,
        measure_cycles: 10,
        on_end: EndAction::Hold,
        segments: vec![SegmentDocument {
            frequency_hz: d.frequency_hz,
            amplitude_deg: d.amplitude_deg,
            mean_deg: d.mean_deg,
            duration_s: 100.0,
            ramp_s,
            downstroke_fraction: 0.5,
        }],
        faults: vec![],
    };
    run_with_trace(&scenario, p).expect("the scenario runs")
}

/// Peak |current| and |terminal voltage| over the last `cycles` cycles of
/// a trace. The duty of a sample is applied over the next control period;
/// the terminal voltage is `d (V_b - R_b d i)` of the averaged bridge.
fn closed_loop_peaks(p: &PlantParams, trace: &[TracePoint], cycles: f64) -> (f64, f64) {
    let last = trace.last().unwrap();
    let from = last.sample.time_s - cycles / last.frequency_hz;
    let (vb, rb) = (p.supply.battery_v, p.supply.internal_resistance_ohm);
    trace
        .windows(2)
        .filter(|w| w[1].sample.time_s >= from)
        .fold((0.0f64, 0.0f64), |(pi, pv), w| {
            let d = f64::from(w[0].sample.duty);
            let i = w[1].sample.current_a;
            let v = d * (vb - rb * d * w[0].sample.current_a);
            (pi.max(i.abs()), pv.max(v.abs()))
        })
}

/// The plant of these tests (see the module docs).
fn plant() -> PlantParams {
    PlantParams::from_toml(include_str!("issue21_plant.toml")).unwrap()
}

/// Demands inside the envelope: at the spring's resonance, above it
/// (reactive inertia torque), below it with a mean angle (static spring
/// torque).
const CASES: [(f64, f64, f64); 3] = [(11.0, 30.0, 0.0), (15.0, 20.0, 0.0), (8.0, 35.0, 10.0)];

/// The firmware core flying the plant (3 s: 1 s ramp, then held; the last
/// 10 cycles). Its feedback acts on the encoder's 1.5 mrad quantization
/// through the rate observer and adds a ripple to the smooth demand: the
/// simulated peaks lie above the analytic ones, by 1.6% (current) at the
/// resonance and 8% above it (measured), hence -3%..+10%.
#[test]
fn analytic_peaks_match_the_firmware_flying_the_plant() {
    let p = plant();
    for (f, a, m) in CASES {
        let d = demand(f, a, m);
        let peaks = check(&p, &ActuatorLimits::default(), &d).unwrap().peaks;
        let (report, trace) = fly(&p, &d, 1.0, 3.0);
        let (current, voltage) = closed_loop_peaks(&p, &trace, 10.0);
        let (ci, cv) = (
            current / peaks.peak_current_a - 1.0,
            voltage / peaks.peak_voltage_v - 1.0,
        );
        println!(
            "{d}: analytic {:.4} A {:.4} V, flown {current:.4} A ({:+.1}%) {voltage:.4} V ({:+.1}%), amplitude error {:.3}%",
            peaks.peak_current_a,
            peaks.peak_voltage_v,
            100.0 * ci,
            100.0 * cv,
            steady(&report).amplitude_error_pct
        );
        assert!(steady(&report).amplitude_error_pct.abs() < 2.0);
        assert!((-0.03..0.10).contains(&ci), "current {:+.1}%", 100.0 * ci);
        assert!((-0.03..0.10).contains(&cv), "voltage {:+.1}%", 100.0 * cv);
    }
}

/// 40 Hz +-80 deg: outside the device's envelope and far beyond the
/// actuator. The verdict names the voltage (hundreds of volts needed); the
/// nearest feasible kinematics inside the envelope (20 Hz, +-45 deg) keep
/// the amplitude and lower the frequency (50% change, against 57% for the
/// amplitude); both alternatives are feasible and, flown by the firmware,
/// reach their amplitude within 2% without touching the current limit.
#[test]
fn an_absurd_demand_is_refused_and_its_nearest_feasible_kinematics_fly() {
    let p = plant();
    let limits = ActuatorLimits::default();
    let absurd = demand(40.0, 80.0, 0.0);
    let f = check(&p, &limits, &absurd).unwrap();
    println!("{absurd}: limited by the {}", f.limiting);
    assert!(!f.feasible);
    assert_eq!(f.limiting.quantity, Quantity::Voltage);
    assert!(f.limiting.value > 10.0 * f.limiting.limit);
    assert!(f.margins().iter().all(|m| m.margin < 0.0), "{f:?}");

    let n = nearest_feasible(&p, &limits, &Limits::REFERENCE_FWAV, &absurd).unwrap();
    assert!(n.clamped());
    assert_eq!(n.within_envelope, demand(20.0, 45.0, 0.0));
    let (by_a, by_f) = (n.by_amplitude.unwrap(), n.by_frequency.unwrap());
    println!(
        "by amplitude {} ({:.1}%), by frequency {} ({:.1}%): {:?}",
        by_a.feasibility.demand,
        100.0 * by_a.relative_change,
        by_f.feasibility.demand,
        100.0 * by_f.relative_change,
        n.change
    );
    assert_eq!(n.change, Change::Frequency);
    assert_eq!(n.chosen, by_f);
    assert!(by_f.relative_change < by_a.relative_change);
    assert_eq!(n.demand().amplitude_deg, 45.0);
    for alt in [by_a, by_f] {
        let d = alt.feasibility.demand;
        assert!(alt.feasibility.feasible);
        // Again from scratch, and a step (0.01) further is not feasible.
        assert!(check(&p, &limits, &d).unwrap().feasible);
        let (report, trace) = fly(&p, &d, 1.3, 3.8);
        let (current, _) = closed_loop_peaks(&p, &trace, 10.0);
        println!(
            "{d}: amplitude error {:.3}%, peak current {current:.3} A",
            steady(&report).amplitude_error_pct
        );
        assert!(steady(&report).amplitude_error_pct.abs() < 2.0);
        assert!(current < limits.current_a);
    }
    let beyond = demand(by_f.feasibility.demand.frequency_hz + 0.02, 45.0, 0.0);
    assert!(!check(&p, &limits, &beyond).unwrap().feasible);
    let beyond = demand(20.0, by_a.feasibility.demand.amplitude_deg + 0.02, 0.0);
    assert!(!check(&p, &limits, &beyond).unwrap().feasible);
}
