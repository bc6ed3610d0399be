//! The numbers a run is judged by, computed from its trace: steady-state
//! amplitude, frequency and phase of the true wing motion against the
//! target profile (lock-in over whole reference cycles), tracking error,
//! current, power, energy balance, settling after a segment change and
//! failsafe timings.

use std::f64::consts::PI;

use fwav_fc_core::reference::Waveform;
use fwav_protocol::ParamId;
use serde::Serialize;

use crate::scenario::{FaultKind, Scenario};
use crate::sim::{Sample, Simulator};
use fwav_actuator::params::PlantParams;
use fwav_actuator::plant::{balance_residual, EnergyLedger};

/// One control period of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TracePoint {
    /// The simulator's sample.
    pub sample: Sample,
    /// Target angle (profile, no corrections), rad.
    pub target_rad: f64,
    /// Target's warped phase theta, rad.
    pub theta: f64,
    /// Target's cycle phase in [0, 1).
    pub phase: f64,
    /// Target amplitude, mean and frequency.
    pub amplitude_rad: f64,
    /// Target mean angle, rad.
    pub mean_rad: f64,
    /// Target frequency, Hz.
    pub frequency_hz: f64,
    /// Segment of the profile.
    pub segment: Option<usize>,
}

impl TracePoint {
    /// A point from a sample and the target waveform at the same instant.
    pub fn new(sample: &Sample, target: &Waveform, segment: Option<usize>) -> Self {
        let (theta, _) = Waveform::theta(target.phase, target.kin.downstroke_fraction);
        Self {
            sample: *sample,
            target_rad: f64::from(target.evaluate(0.0, 1.0).angle),
            theta: f64::from(theta),
            phase: f64::from(target.phase),
            amplitude_rad: f64::from(target.kin.amplitude_rad),
            mean_rad: f64::from(target.kin.mean_rad),
            frequency_hz: f64::from(target.kin.frequency_hz),
            segment,
        }
    }
}

/// The result of a run (JSON keys carry their units).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Report {
    /// Simulated time, s.
    pub duration_s: f64,
    /// Seed of the sensor noise.
    pub seed: u64,
    /// Reference cycles in the steady-state window: the scenario's
    /// `measure_cycles`, or fewer when the run holds fewer whole cycles
    /// before its end and its first fault.
    pub measured_cycles: u32,
    /// The cycles the scenario asked to measure (`measure_cycles`).
    pub cycles_asked: u32,
    /// The numbers of the steady-state window; `None` (absent from the
    /// JSON) when the run holds no whole reference cycle before its end
    /// and its first fault, so there is nothing to measure them over.
    #[serde(flatten)]
    pub steady: Option<SteadyState>,
    /// Largest |motor current| while running, A.
    pub peak_current_a: f64,
    /// The controller's current limit, A.
    pub current_limit_a: f64,
    /// Energy balance E_in - (losses + dE_stored) over the run, % of E_in.
    pub energy_balance_residual_pct: f64,
    /// Per segment change: cycles until the per-cycle amplitude stays within
    /// 2% of the (ramping) target; null if never.
    pub settle_cycles: Vec<Option<u32>>,
    /// From link silence to the wing at rest (|angle| < 1 deg for good), s.
    pub time_to_rest_after_link_silence_s: Option<f64>,
    /// From an encoder-loss or stall fault to the bridge disarmed, s.
    pub time_to_disarm_after_fault_s: Option<f64>,
    /// Armed at the end.
    pub armed_at_end: bool,
    /// Latched faults at the end.
    pub faults_at_end: String,
}

/// The numbers of the steady-state window: the last `measured_cycles`
/// whole reference cycles before the run's end and its first fault.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SteadyState {
    /// Target frequency in the window, Hz.
    pub target_frequency_hz: f64,
    /// Target amplitude in the window, deg.
    pub target_amplitude_deg: f64,
    /// (measured - target) / target fundamental amplitude, %; NaN (null
    /// in the JSON) when the target does not move (amplitude 0), as the
    /// phase lag and the tracking error then are.
    pub amplitude_error_pct: f64,
    /// (measured - target) / target frequency, %; `None` (null) when the
    /// wing crossed its mean upward fewer than twice in the window (one
    /// cycle measured, or a wing that barely moves), which leaves no
    /// period to measure.
    pub frequency_error_pct: Option<f64>,
    /// Phase lag of the wing behind the target, deg.
    pub phase_lag_deg: f64,
    /// RMS of (angle - target) over the window / target amplitude, %.
    pub rms_tracking_error_pct: f64,
    /// Largest |motor current| in the steady-state window, A.
    pub steady_peak_current_a: f64,
    /// Largest |terminal voltage| of the motor in the steady-state window,
    /// V (see [`crate::sim::Sample::terminal_v`]).
    pub steady_peak_voltage_v: f64,
    /// Share of the window's control periods with the duty at full scale
    /// (|duty| = 1), %. Above 0 the drive is out of voltage: the profile is
    /// not followed at every instant; the per-stroke loop may still bring
    /// the fundamental amplitude to the target (a small amplitude error) by
    /// distorting the motion, which then carries harmonics. A demand the
    /// actuator can fly keeps this at 0.
    pub duty_saturated_pct: f64,
    /// RMS motor current over the window, A.
    pub rms_current_a: f64,
    /// Mean battery power over the window, W.
    pub battery_power_w: f64,
    /// Battery energy per flapping cycle in the window, J.
    pub energy_per_cycle_j: f64,
}

/// Lock-in sums over a range of the trace: (a, b, a_ref, b_ref, T).
fn lock_in(points: &[TracePoint], dt: f64) -> (f64, f64, f64, f64, f64) {
    let mut acc = (0.0, 0.0, 0.0, 0.0, 0.0);
    for p in points {
        let (s, c) = p.theta.sin_cos();
        let x = p.sample.angle_rad - p.mean_rad;
        let r = p.target_rad - p.mean_rad;
        acc.0 += x * s * dt;
        acc.1 += x * c * dt;
        acc.2 += r * s * dt;
        acc.3 += r * c * dt;
        acc.4 += dt;
    }
    let k = 2.0 / acc.4.max(f64::MIN_POSITIVE);
    (k * acc.0, k * acc.1, k * acc.2, k * acc.3, acc.4)
}

/// Indices where a reference cycle starts: the run's first point, where
/// the profile starts at phase 0, and each where the phase wraps.
fn cycle_starts(points: &[TracePoint]) -> Vec<usize> {
    let first = points.first().filter(|p| p.phase == 0.0).map(|_| 0);
    first
        .into_iter()
        .chain((1..points.len()).filter(|&i| points[i].phase < points[i - 1].phase))
        .collect()
}

impl Report {
    /// Computes the report of a finished run.
    pub fn from_trace(
        scenario: &Scenario,
        plant: &PlantParams,
        trace: &[TracePoint],
        sim: &Simulator,
        start_ledger: &EnergyLedger,
        start_stored: f64,
    ) -> Self {
        let dt = plant.control_dt();
        let first_fault = scenario.first_fault_s().unwrap_or(f64::INFINITY);
        let usable = trace
            .iter()
            .take_while(|p| p.sample.time_s <= first_fault)
            .count();
        let starts = cycle_starts(&trace[..usable]);
        let n = (scenario.measure_cycles as usize).min(starts.len().saturating_sub(1));
        let steady = (n > 0).then(|| {
            let window = &trace[starts[starts.len() - 1 - n]..starts[starts.len() - 1]];
            SteadyState::over(window, n, dt)
        });
        let running = trace.iter().filter(|p| p.sample.armed);
        let peak_current = running
            .map(|p| p.sample.current_a.abs())
            .fold(0.0, f64::max);
        Self {
            duration_s: scenario.duration_s,
            seed: plant.sensors.seed,
            measured_cycles: n as u32,
            cycles_asked: scenario.measure_cycles,
            steady,
            peak_current_a: peak_current,
            current_limit_a: f64::from(sim.fc.params().get(ParamId::CurrentLimit)),
            energy_balance_residual_pct: 100.0
                * balance_residual(start_ledger, start_stored, &sim.plant),
            settle_cycles: settle_cycles(&trace[..usable], dt),
            time_to_rest_after_link_silence_s: fault_time(scenario, FaultKind::LinkSilence)
                .and_then(|tf| time_to_rest(trace, tf)),
            time_to_disarm_after_fault_s: fault_time(scenario, FaultKind::EncoderLoss)
                .or_else(|| fault_time(scenario, FaultKind::Stall))
                .and_then(|tf| {
                    trace
                        .iter()
                        .find(|p| p.sample.time_s > tf && !p.sample.armed)
                        .map(|p| p.sample.time_s - tf)
                }),
            armed_at_end: sim.fc.is_armed(),
            faults_at_end: sim.fc.faults().to_string(),
        }
    }
}

impl SteadyState {
    /// The numbers over `window`, `cycles` whole reference cycles of
    /// control periods `dt` s long.
    fn over(window: &[TracePoint], cycles: usize, dt: f64) -> Self {
        let (a, b, ar, br, t) = lock_in(window, dt);
        let amplitude = a.hypot(b);
        let target_amplitude = ar.hypot(br);
        let lag = ((-b).atan2(a) - (-br).atan2(ar) + PI).rem_euclid(2.0 * PI) - PI;
        let target_frequency = window.last().map_or(0.0, |p| p.frequency_hz);
        let rms_err = rms(window.iter().map(|p| p.sample.angle_rad - p.target_rad));
        let battery = match (window.first(), window.last()) {
            (Some(first), Some(last)) => last.sample.battery_j - first.sample.battery_j,
            _ => 0.0,
        };
        Self {
            target_frequency_hz: target_frequency,
            target_amplitude_deg: target_amplitude.to_degrees(),
            amplitude_error_pct: 100.0 * (amplitude - target_amplitude) / target_amplitude,
            frequency_error_pct: measured_frequency(window, dt)
                .map(|f| 100.0 * (f - target_frequency) / target_frequency),
            phase_lag_deg: lag.to_degrees(),
            rms_tracking_error_pct: 100.0 * rms_err / target_amplitude,
            steady_peak_current_a: window
                .iter()
                .map(|p| p.sample.current_a.abs())
                .fold(0.0, f64::max),
            steady_peak_voltage_v: window
                .iter()
                .map(|p| p.sample.terminal_v.abs())
                .fold(0.0, f64::max),
            duty_saturated_pct: 100.0
                * window.iter().filter(|p| p.sample.duty.abs() >= 1.0).count() as f64
                / window.len().max(1) as f64,
            rms_current_a: rms(window.iter().map(|p| p.sample.current_a)),
            battery_power_w: battery / t.max(f64::MIN_POSITIVE),
            energy_per_cycle_j: battery / cycles as f64,
        }
    }
}

fn rms(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, n) = values.fold((0.0, 0usize), |(s, n), v| (s + v * v, n + 1));
    (sum / n.max(1) as f64).sqrt()
}

/// Mean frequency from upward crossings of the mean (interpolated); `None`
/// with fewer than two crossings.
fn measured_frequency(window: &[TracePoint], dt: f64) -> Option<f64> {
    let ups: Vec<f64> = window
        .windows(2)
        .filter_map(|w| {
            let (x0, x1) = (
                w[0].sample.angle_rad - w[0].mean_rad,
                w[1].sample.angle_rad - w[1].mean_rad,
            );
            (x0 < 0.0 && x1 >= 0.0).then(|| w[0].sample.time_s + dt * (-x0) / (x1 - x0))
        })
        .collect();
    match (ups.first(), ups.last()) {
        (Some(first), Some(last)) if ups.len() >= 2 => {
            Some((ups.len() - 1) as f64 / (last - first))
        }
        _ => None,
    }
}

fn fault_time(scenario: &Scenario, kind: FaultKind) -> Option<f64> {
    scenario
        .faults
        .iter()
        .filter(|f| f.kind == kind)
        .map(|f| f.at_s)
        .reduce(f64::min)
}

/// From `tf` until |angle| stays below 1 deg to the end of the trace.
fn time_to_rest(trace: &[TracePoint], tf: f64) -> Option<f64> {
    let limit = 1f64.to_radians();
    let last_moving = trace
        .iter()
        .rposition(|p| p.sample.angle_rad.abs() >= limit)?;
    let rest = trace.get(last_moving + 1)?;
    Some((rest.sample.time_s - tf).max(0.0))
}

/// Per segment change: reference cycles from the change until every later
/// cycle's fundamental amplitude is within 2% of the target's.
fn settle_cycles(trace: &[TracePoint], dt: f64) -> Vec<Option<u32>> {
    let starts = cycle_starts(trace);
    let changes: Vec<usize> = (1..trace.len())
        .filter(|&i| {
            trace[i].segment != trace[i - 1].segment && trace[i].segment.is_some_and(|s| s > 0)
        })
        .collect();
    changes
        .iter()
        .map(|&c| {
            let cycles: Vec<(usize, usize)> = starts
                .windows(2)
                .filter(|w| w[0] >= c)
                .map(|w| (w[0], w[1]))
                .collect();
            let errors: Vec<f64> = cycles
                .iter()
                .map(|&(a, b)| {
                    let (x, y, xr, yr, _) = lock_in(&trace[a..b], dt);
                    (x.hypot(y) / xr.hypot(yr) - 1.0).abs()
                })
                .collect();
            if errors.is_empty() {
                return None;
            }
            let last_bad = errors.iter().rposition(|&e| e >= 0.02);
            match last_bad {
                None => Some(0),
                Some(k) if k + 1 < errors.len() => Some(k as u32 + 1),
                Some(_) => None,
            }
        })
        .collect()
}
