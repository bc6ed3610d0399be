//! The feasibility check against the simulator: the analytic steady-state
//! peaks against the plant driven open-loop by the analytic voltage and
//! against the plant flown by the firmware core; the default design's
//! margins; an absurd demand's verdict and its nearest feasible kinematics,
//! flown.

use fwav_hil_sim::config::PlantParams;
use fwav_hil_sim::feasibility::{
    check, demand_waveform, nearest_feasible, ActuatorLimits, Change, FeasibilityError,
    FlappingDemand, Quantity,
};
use fwav_hil_sim::metrics::TracePoint;
use fwav_hil_sim::plant::{Drive, Plant, State};
use fwav_hil_sim::scenario::{run_with_trace, Scenario};
use fwav_protocol::document::SegmentDocument;
use fwav_protocol::{EndAction, Limits};

fn demand(frequency_hz: f64, amplitude_deg: f64, mean_deg: f64) -> FlappingDemand {
    FlappingDemand {
        frequency_hz,
        amplitude_deg,
        mean_deg,
    }
}

/// Peaks of the plant driven open-loop by the analytic terminal voltage
/// (duty solving `d V_b - d^2 R_b i = V` at the plant's own current), from
/// the analytic state at the cycle's start, over the last 5 of 20 cycles:
/// (peak |current| A, peak |terminal voltage| V, amplitude deg, mean deg).
fn open_loop(p: &PlantParams, d: &FlappingDemand) -> (f64, f64, f64, f64) {
    let samples = demand_waveform(p, d).unwrap();
    let m = samples.len();
    let period = 1.0 / d.frequency_hz;
    let voltage = |t: f64| {
        let x = (t / period).fract() * m as f64;
        let k = x.floor() as usize % m;
        let w = x - x.floor();
        samples[k].voltage_v * (1.0 - w) + samples[(k + 1) % m].voltage_v * w
    };
    let mut plant = Plant::new(p);
    plant.state = State {
        current_a: samples[0].current_a,
        angle_rad: samples[0].angle_rad,
        rate_rad_s: samples[0].rate_rad_s,
    };
    let (vb, rb) = (p.supply.battery_v, p.supply.internal_resistance_ohm);
    let h = 1e-5;
    let steps = (20.0 * period / h).round() as usize;
    let window = (5.0 * period / h).round() as usize;
    let (mut peak_i, mut peak_v) = (0.0f64, 0.0f64);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for k in 0..steps {
        let v = voltage((k as f64 + 0.5) * h);
        let x = rb * plant.state.current_a;
        // Root of x d^2 - V_b d + V = 0 nearest V / V_b.
        let duty = if x.abs() < 1e-12 {
            v / vb
        } else {
            (vb - (vb * vb - 4.0 * x * v).sqrt()) / (2.0 * x)
        };
        let terminal = duty * (vb - rb * duty * plant.state.current_a);
        plant.step(
            Drive {
                duty,
                enabled: true,
            },
            h,
        );
        if k >= steps - window {
            peak_i = peak_i.max(plant.state.current_a.abs());
            peak_v = peak_v.max(terminal.abs());
            lo = lo.min(plant.state.angle_rad);
            hi = hi.max(plant.state.angle_rad);
        }
    }
    (
        peak_i,
        peak_v,
        (0.5 * (hi - lo)).to_degrees(),
        (0.5 * (hi + lo)).to_degrees(),
    )
}

/// A run of one held segment: `ramp_s` from rest, then held to `duration_s`.
fn fly(
    p: &PlantParams,
    d: &FlappingDemand,
    ramp_s: f64,
    duration_s: f64,
) -> (fwav_hil_sim::metrics::Report, Vec<TracePoint>) {
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

/// Demands inside the envelope: at the spring's resonance, above it
/// (reactive inertia torque), below it with a mean angle (static spring
/// torque).
const CASES: [(f64, f64, f64); 3] = [(11.0, 30.0, 0.0), (15.0, 20.0, 0.0), (8.0, 35.0, 10.0)];

/// The same equations forward (RK4 at 10 us, driven by the analytic
/// voltage) and backward (1024 samples a cycle, voltage interpolated
/// linearly): they differ only by discretization, so 0.5%. Measured:
/// agreement to 4 digits.
#[test]
fn analytic_peaks_match_the_plant_driven_open_loop() {
    let p = PlantParams::default();
    for (f, a, m) in CASES {
        let d = demand(f, a, m);
        let peaks = check(&p, &ActuatorLimits::default(), &d).unwrap().peaks;
        let (current, voltage, amplitude, mean) = open_loop(&p, &d);
        println!(
            "{d}: analytic {:.4} A {:.4} V, open loop {current:.4} A {voltage:.4} V, +-{amplitude:.3} deg about {mean:.3} deg",
            peaks.peak_current_a, peaks.peak_voltage_v
        );
        assert!((current / peaks.peak_current_a - 1.0).abs() < 0.005);
        assert!((voltage / peaks.peak_voltage_v - 1.0).abs() < 0.005);
        assert!((amplitude / a - 1.0).abs() < 0.005, "{amplitude} deg");
        assert!((mean - m).abs() < 0.005 * a, "{mean} deg");
    }
}

/// The firmware core flying the plant (3 s: 1 s ramp, then held; the last
/// 10 cycles). Its feedback acts on the encoder's 1.5 mrad quantization
/// through the rate observer and adds a ripple to the smooth demand: the
/// simulated peaks lie above the analytic ones, by 1.6% (current) at the
/// resonance and 8% above it (measured), hence -3%..+10%.
#[test]
fn analytic_peaks_match_the_firmware_flying_the_plant() {
    let p = PlantParams::default();
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
            report.amplitude_error_pct
        );
        assert!(report.amplitude_error_pct.abs() < 2.0);
        assert!((-0.03..0.10).contains(&ci), "current {:+.1}%", 100.0 * ci);
        assert!((-0.03..0.10).contains(&cv), "voltage {:+.1}%", 100.0 * cv);
    }
}

/// The seed paper's initial design, 11 Hz +-30 deg, on the default plant:
/// feasible with room to spare; the terminal voltage (back-EMF plus the
/// resistive drop at the aerodynamic peak) comes closest to its limit.
#[test]
fn the_initial_design_is_feasible() {
    let p = PlantParams::default();
    let f = check(&p, &ActuatorLimits::default(), &demand(11.0, 30.0, 0.0)).unwrap();
    for m in f.margins() {
        println!("{m}");
        assert!(m.margin > 0.4, "{m:?}");
    }
    assert!(f.feasible);
    assert_eq!(f.limiting.quantity, Quantity::Voltage);
    assert_eq!(f.limiting, f.voltage);
}

/// 40 Hz +-80 deg: outside the device's envelope and far beyond the
/// actuator. The verdict names the voltage (hundreds of volts needed); the
/// nearest feasible kinematics inside the envelope (20 Hz, +-45 deg) keep
/// the amplitude and lower the frequency (50% change, against 57% for the
/// amplitude); both alternatives are feasible and, flown by the firmware,
/// reach their amplitude within 2% without touching the current limit.
#[test]
fn an_absurd_demand_is_refused_and_its_nearest_feasible_kinematics_fly() {
    let p = PlantParams::default();
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
            report.amplitude_error_pct
        );
        assert!(report.amplitude_error_pct.abs() < 2.0);
        assert!(current < limits.current_a);
    }
    let beyond = demand(by_f.feasibility.demand.frequency_hz + 0.02, 45.0, 0.0);
    assert!(!check(&p, &limits, &beyond).unwrap().feasible);
    let beyond = demand(20.0, by_a.feasibility.demand.amplitude_deg + 0.02, 0.0);
    assert!(!check(&p, &limits, &beyond).unwrap().feasible);
}

/// Bad input is a typed error, never a panic.
#[test]
fn bad_input_is_refused() {
    let p = PlantParams::default();
    let limits = ActuatorLimits::default();
    for d in [
        demand(f64::NAN, 30.0, 0.0),
        demand(0.0, 30.0, 0.0),
        demand(11.0, -1.0, 0.0),
        demand(11.0, 30.0, f64::INFINITY),
    ] {
        assert!(matches!(
            check(&p, &limits, &d),
            Err(FeasibilityError::Demand { .. })
        ));
    }
    let nan = ActuatorLimits {
        current_a: f64::NAN,
        ..limits
    };
    assert!(matches!(
        check(&p, &nan, &demand(11.0, 30.0, 0.0)),
        Err(FeasibilityError::Limits { .. })
    ));
    let mut broken = p.clone();
    broken.motor.resistance_ohm = -1.0;
    assert!(matches!(
        check(&broken, &limits, &demand(11.0, 30.0, 0.0)),
        Err(FeasibilityError::Params(_))
    ));
    let envelope = Limits {
        max_frequency_hz: f32::NAN,
        ..Limits::REFERENCE_FWAV
    };
    assert!(matches!(
        nearest_feasible(&p, &limits, &envelope, &demand(11.0, 30.0, 0.0)),
        Err(FeasibilityError::Limits { .. })
    ));
    // A mean angle whose spring torque alone is too much: nothing is.
    let weak = ActuatorLimits {
        current_a: 0.1,
        ..limits
    };
    let e = nearest_feasible(
        &p,
        &weak,
        &Limits::REFERENCE_FWAV,
        &demand(11.0, 30.0, 20.0),
    )
    .unwrap_err();
    assert!(
        matches!(
            e,
            FeasibilityError::NothingFeasible {
                limiting: Quantity::Current,
                ..
            }
        ),
        "{e}"
    );
}
