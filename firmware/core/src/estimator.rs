//! What the controller knows about the wing beyond one encoder reading: the
//! angle and rate ([`RateObserver`]), and per stroke the amplitude and phase
//! of the motion against the reference ([`StrokeEstimator`]) and its
//! frequency ([`FrequencyEstimator`]).

use core::f32::consts::PI;

/// Second-order tracking observer of angle and rate behind a quantized
/// encoder: `x' = w + 2 omega e`, `w' = a_ff + omega^2 e`, `e = measured - x`
/// (critically damped, bandwidth `omega`), with the reference acceleration as
/// feed-forward so it does not lag a known motion. Differencing a 4096-count
/// encoder at 10 kHz would give rate noise of ~15 rad/s; the observer at
/// 200 Hz gives well under 1 rad/s.
#[derive(Clone, Copy, Debug, Default)]
pub struct RateObserver {
    angle: f32,
    rate: f32,
    started: bool,
}

impl RateObserver {
    /// An observer that starts at the first measurement.
    pub const fn new() -> Self {
        Self {
            angle: 0.0,
            rate: 0.0,
            started: false,
        }
    }

    /// Forgets the state; the next update starts at the measurement, at rest.
    pub fn reset(&mut self) {
        self.started = false;
    }

    /// Takes one measurement; returns (angle, rate) estimates (rad, rad/s).
    /// A non-finite measurement is ignored (the fault monitor reports it).
    pub fn update(
        &mut self,
        measured: f32,
        accel_ff: f32,
        bandwidth_hz: f32,
        dt: f32,
    ) -> (f32, f32) {
        if !measured.is_finite() {
            return (self.angle, self.rate);
        }
        let accel_ff = if accel_ff.is_finite() { accel_ff } else { 0.0 };
        if !self.started {
            *self = Self {
                angle: measured,
                rate: 0.0,
                started: true,
            };
            return (self.angle, self.rate);
        }
        let omega = 2.0 * PI * bandwidth_hz;
        // Keep the explicit update stable whatever the settings (omega dt < 1).
        let omega = if omega * dt > 0.5 { 0.5 / dt } else { omega };
        self.angle += self.rate * dt + 0.5 * accel_ff * dt * dt;
        self.rate += accel_ff * dt;
        let e = measured - self.angle;
        self.angle += 2.0 * omega * dt * e;
        self.rate += omega * omega * dt * e;
        (self.angle, self.rate)
    }
}

/// One stroke's result of the [`StrokeEstimator`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrokeEstimate {
    /// Fundamental amplitude of the measured motion, rad.
    pub measured_amplitude: f32,
    /// Fundamental amplitude of the reference over the same cycle, rad.
    pub reference_amplitude: f32,
    /// How far the measured motion lags the reference, rad (of theta).
    pub phase_lag: f32,
    /// Length of the cycle, s.
    pub period: f32,
}

/// Lock-in (single-bin Fourier) estimate of amplitude and phase over each
/// reference cycle: `a = 2/T int (phi - m) sin theta dt`,
/// `b = 2/T int (phi - m) cos theta dt` against the reference's own warped
/// phase `theta`, for which `2/T int sin^2 theta dt = 1` holds for any split
/// cycle (each half-stroke sweeps theta by pi uniformly). The reference is
/// demodulated the same way, so the ratio is exact even while ramping.
#[derive(Clone, Copy, Debug, Default)]
pub struct StrokeEstimator {
    sin_meas: f32,
    cos_meas: f32,
    sin_ref: f32,
    cos_ref: f32,
    time: f32,
    /// A cycle boundary has been seen, so the sums cover whole cycles.
    aligned: bool,
}

impl StrokeEstimator {
    /// An estimator waiting for its first cycle boundary.
    pub const fn new() -> Self {
        Self {
            sin_meas: 0.0,
            cos_meas: 0.0,
            sin_ref: 0.0,
            cos_ref: 0.0,
            time: 0.0,
            aligned: false,
        }
    }

    /// Forgets the current cycle; estimates resume after the next boundary.
    pub fn reset(&mut self) {
        *self = Self::new();
    }

    /// Adds one step, with `sin_cos` = (sin, cos) of the reference's warped
    /// phase theta; at a cycle boundary (`cycle_done`) returns the estimate
    /// of the cycle that just ended.
    pub fn update(
        &mut self,
        measured: f32,
        reference: f32,
        mean: f32,
        sin_cos: (f32, f32),
        dt: f32,
        cycle_done: bool,
    ) -> Option<StrokeEstimate> {
        let mut result = None;
        if cycle_done {
            if self.aligned && self.time > 0.0 {
                let k = 2.0 / self.time;
                let (a, b) = (k * self.sin_meas, k * self.cos_meas);
                let (ar, br) = (k * self.sin_ref, k * self.cos_ref);
                // phi = A sin(theta - psi) gives a = A cos psi, b = -A sin psi.
                let lag = libm::atan2f(-b, a) - libm::atan2f(-br, ar);
                result = Some(StrokeEstimate {
                    measured_amplitude: libm::sqrtf(a * a + b * b),
                    reference_amplitude: libm::sqrtf(ar * ar + br * br),
                    phase_lag: wrap_pi(lag),
                    period: self.time,
                });
            }
            *self = Self {
                aligned: true,
                ..Self::new()
            };
        }
        let (s, c) = sin_cos;
        self.sin_meas += (measured - mean) * s * dt;
        self.cos_meas += (measured - mean) * c * dt;
        self.sin_ref += (reference - mean) * s * dt;
        self.cos_ref += (reference - mean) * c * dt;
        self.time += dt;
        result
    }
}

/// `x` wrapped into (-pi, pi].
pub fn wrap_pi(x: f32) -> f32 {
    let two_pi = 2.0 * PI;
    let w = x - two_pi * libm::floorf((x + PI) / two_pi);
    if w <= -PI {
        w + two_pi
    } else {
        w
    }
}

/// Flapping frequency from the measured motion: the time between upward
/// crossings of the mean, interpolated within the step, with hysteresis so
/// encoder steps near the mean do not count twice. Only time since the last
/// crossing is kept, so precision does not decay over hours of running.
#[derive(Clone, Copy, Debug, Default)]
pub struct FrequencyEstimator {
    /// Time since the last crossing, s (None before the first).
    since_crossing: Option<f32>,
    armed_below: bool,
    previous: f32,
    frequency: f32,
}

impl FrequencyEstimator {
    /// No estimate yet.
    pub const fn new() -> Self {
        Self {
            since_crossing: None,
            armed_below: false,
            previous: 0.0,
            frequency: 0.0,
        }
    }

    /// Forgets everything.
    pub fn reset(&mut self) {
        *self = Self::new();
    }

    /// Last estimate, Hz (0 until two crossings were seen).
    pub fn frequency_hz(&self) -> f32 {
        self.frequency
    }

    /// Adds one step of `x = angle - mean`; `hysteresis` > 0 (rad).
    pub fn update(&mut self, x: f32, hysteresis: f32, dt: f32) {
        if let Some(t) = self.since_crossing.as_mut() {
            *t += dt;
        }
        if !x.is_finite() {
            return;
        }
        if x < -hysteresis {
            self.armed_below = true;
        } else if self.armed_below && x >= 0.0 && self.previous < 0.0 {
            // The crossing happened this long before the current sample.
            let back = dt * x / (x - self.previous);
            if let Some(since) = self.since_crossing {
                let period = since - back;
                if period > 0.0 {
                    self.frequency = 1.0 / period;
                }
            }
            self.since_crossing = Some(back);
            self.armed_below = false;
        }
        self.previous = x;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn observer_tracks_a_quantized_sinusoid() {
        // 11 Hz, 30 deg, read through a 4096-count encoder at 10 kHz.
        let (f, a, dt) = (11.0f32, core::f32::consts::FRAC_PI_6, 1e-4f32); // 30 deg
        let count = 2.0 * PI / 4096.0;
        let w = 2.0 * PI * f;
        let mut obs = RateObserver::default();
        let mut worst = 0.0f32;
        for i in 0..20_000 {
            let t = i as f32 * dt;
            let truth = a * libm::sinf(w * t);
            let measured = libm::roundf(truth / count) * count;
            let accel = -a * w * w * libm::sinf(w * t);
            let (_, rate) = obs.update(measured, accel, 200.0, dt);
            if t > 0.1 {
                worst = worst.max((rate - a * w * libm::cosf(w * t)).abs());
            }
        }
        // Peak rate 36 rad/s; differencing would be off by ~15 rad/s.
        assert!(worst < 1.0, "rate error {worst} rad/s");
    }

    #[test]
    fn lock_in_finds_amplitude_and_lag_for_split_cycles() {
        for d in [0.5f32, 0.6] {
            let (f, dt) = (10.0f32, 1e-4f32);
            let mut est = StrokeEstimator::default();
            let mut phase = 0.0f32;
            let mut last = None;
            for _ in 0..5_000 {
                let (theta, _) = crate::reference::Waveform::theta(phase, d);
                let reference = 0.1 + 0.4 * libm::sinf(theta);
                // Measured: 90% amplitude, lagging by 0.2 rad of theta.
                let measured = 0.1 + 0.36 * libm::sinf(theta - 0.2);
                let next = crate::reference::wrap(phase + f * dt);
                let done = next < phase;
                if let Some(e) =
                    est.update(measured, reference, 0.1, libm::sincosf(theta), dt, done)
                {
                    last = Some(e);
                }
                phase = next;
            }
            let e = last.expect("whole cycles were seen");
            assert!((e.reference_amplitude - 0.4).abs() < 2e-3, "{e:?}");
            assert!((e.measured_amplitude - 0.36).abs() < 2e-3, "{e:?}");
            assert!((e.phase_lag - 0.2).abs() < 1e-2, "{e:?}");
            assert!((e.period - 0.1).abs() < 2e-4, "{e:?}");
        }
    }

    #[test]
    fn frequency_from_crossings_ignores_encoder_chatter() {
        let (f, dt) = (11.0f32, 1e-4f32);
        let mut fe = FrequencyEstimator::default();
        for i in 0..10_000 {
            let t = i as f32 * dt;
            // One-count chatter around the crossings.
            let chatter = if i % 2 == 0 { 1.5e-3 } else { -1.5e-3 };
            fe.update(0.5 * libm::sinf(2.0 * PI * f * t) + chatter, 0.05, dt);
        }
        assert!(
            (fe.frequency_hz() - f).abs() < 0.02,
            "{}",
            fe.frequency_hz()
        );
    }

    #[test]
    fn wrap_pi_range() {
        for x in [-7.0f32, -PI, 0.0, PI, 3.5, 10.0] {
            let w = wrap_pi(x);
            assert!(w > -PI - 1e-6 && w <= PI + 1e-6, "{x} -> {w}");
            assert!((libm::sinf(w) - libm::sinf(x)).abs() < 1e-5);
        }
    }
}
