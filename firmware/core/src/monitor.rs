//! Sensor-based failsafes: encoder faults and over-current, checked every
//! control step while armed. (Link silence is timed by the flight
//! controller, which sees the frames.)

use fwav_protocol::{FaultFlags, ParamId};

use crate::controller::Measurement;
use crate::params::ParamSet;

/// The encoder is declared dead if the bridge drives at least this |duty|...
pub const ENCODER_STUCK_DUTY: f32 = 0.2;
/// ...and the reading does not change for this long, s. At 11 Hz and 30 deg a
/// 4096-count encoder is still for ~2 ms at a stroke reversal, so 20 ms never
/// trips on a healthy wing yet disarms well within 50 ms.
pub const ENCODER_STUCK_S: f32 = 0.02;
/// No wing moves faster than this, rad/s (20 Hz at 45 deg peaks at 99 rad/s);
/// a reading that implies more is a glitch or a lost count.
pub const MAX_PLAUSIBLE_RATE: f32 = 500.0;
/// Slack on the jump test for encoder quantization, rad.
const JUMP_SLACK: f32 = 0.01;
/// Consecutive over-limit current samples that trip (filters single spikes).
pub const OVER_CURRENT_SAMPLES: u8 = 3;

/// State of the sensor checks.
#[derive(Clone, Copy, Debug, Default)]
pub struct FaultMonitor {
    last_angle: Option<f32>,
    still_for: f32,
    over_current: u8,
}

impl FaultMonitor {
    /// Fresh state (on arming).
    pub const fn new() -> Self {
        Self {
            last_angle: None,
            still_for: 0.0,
            over_current: 0,
        }
    }

    /// Checks one step; returns the faults it detects. `duty` is the duty
    /// applied during the step that led to `m`.
    ///
    /// A non-finite angle is an encoder fault; a non-finite current an
    /// over-current fault (without a current reading the motor cannot be
    /// protected, so it is treated as the worst case).
    pub fn check(&mut self, m: &Measurement, duty: f32, p: &ParamSet, dt: f32) -> FaultFlags {
        let mut faults = FaultFlags::NONE;
        if !m.angle_rad.is_finite() {
            faults = faults.union(FaultFlags::ENCODER);
        } else if let Some(last) = self.last_angle {
            let change = (m.angle_rad - last).abs();
            if change > MAX_PLAUSIBLE_RATE * dt + JUMP_SLACK {
                faults = faults.union(FaultFlags::ENCODER);
            }
            if change == 0.0 && duty.abs() >= ENCODER_STUCK_DUTY {
                self.still_for += dt;
            } else {
                self.still_for = 0.0;
            }
            if self.still_for >= ENCODER_STUCK_S {
                faults = faults.union(FaultFlags::ENCODER);
            }
        }
        if m.angle_rad.is_finite() {
            self.last_angle = Some(m.angle_rad);
        }

        let trip = p.get(ParamId::OverCurrentTrip);
        // Written so that a NaN reading counts as over the limit.
        let within = m.current_a.abs() <= trip;
        if !within {
            self.over_current = self.over_current.saturating_add(1);
        } else {
            self.over_current = 0;
        }
        if self.over_current >= OVER_CURRENT_SAMPLES {
            faults = faults.union(FaultFlags::OVER_CURRENT);
        }
        faults
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DT: f32 = 1e-4;

    fn m(angle_rad: f32, current_a: f32) -> Measurement {
        Measurement {
            angle_rad,
            current_a,
            supply_v: None,
        }
    }

    #[test]
    fn stuck_encoder_while_driven_trips_within_the_window() {
        let mut mon = FaultMonitor::new();
        let p = ParamSet::DEFAULT;
        let mut tripped_at = None;
        for i in 0..1000 {
            if !mon.check(&m(0.1, 0.5), 0.5, &p, DT).is_empty() {
                tripped_at = Some(i as f32 * DT);
                break;
            }
        }
        let t = tripped_at.expect("a stuck encoder trips");
        assert!(
            (ENCODER_STUCK_S - 2.0 * DT..=ENCODER_STUCK_S + 2.0 * DT).contains(&t),
            "{t}"
        );
    }

    #[test]
    fn a_still_encoder_at_low_duty_is_fine_and_a_moving_one_too() {
        let mut mon = FaultMonitor::new();
        let p = ParamSet::DEFAULT;
        for _ in 0..10_000 {
            assert!(mon.check(&m(0.0, 0.0), 0.1, &p, DT).is_empty());
        }
        // 11 Hz, 30 deg through a 4096-count encoder, driven hard.
        let count = 2.0 * core::f32::consts::PI / 4096.0;
        for i in 0..20_000 {
            let t = i as f32 * DT;
            let a = libm::roundf(
                core::f32::consts::FRAC_PI_6 * libm::sinf(2.0 * core::f32::consts::PI * 11.0 * t)
                    / count,
            ) * count;
            assert!(mon.check(&m(a, 0.5), 0.9, &p, DT).is_empty(), "t = {t}");
        }
    }

    #[test]
    fn impossible_jumps_and_nan_are_encoder_faults() {
        let p = ParamSet::DEFAULT;
        let mut mon = FaultMonitor::new();
        assert!(mon.check(&m(0.0, 0.0), 0.0, &p, DT).is_empty());
        assert!(mon
            .check(&m(0.5, 0.0), 0.0, &p, DT)
            .contains(FaultFlags::ENCODER));
        let mut mon = FaultMonitor::new();
        assert!(mon
            .check(&m(f32::NAN, 0.0), 0.0, &p, DT)
            .contains(FaultFlags::ENCODER));
    }

    #[test]
    fn over_current_needs_consecutive_samples() {
        let p = ParamSet::DEFAULT;
        let trip = p.get(ParamId::OverCurrentTrip);
        let mut mon = FaultMonitor::new();
        // Isolated spikes do not trip (the last sample, i = 98, is quiet).
        for i in 0..99 {
            let i_a = if i % 3 == 0 { 2.0 * trip } else { 0.0 };
            assert!(mon.check(&m(0.0, i_a), 0.0, &p, DT).is_empty());
        }
        let hits: std::vec::Vec<bool> = (0..3)
            .map(|_| {
                mon.check(&m(0.0, -2.0 * trip), 0.0, &p, DT)
                    .contains(FaultFlags::OVER_CURRENT)
            })
            .collect();
        assert_eq!(hits, vec![false, false, true]);
        let mut mon = FaultMonitor::new();
        let nan: std::vec::Vec<bool> = (0..3)
            .map(|_| {
                mon.check(&m(0.0, f32::NAN), 0.0, &p, DT)
                    .contains(FaultFlags::OVER_CURRENT)
            })
            .collect();
        assert_eq!(nan, vec![false, false, true]);
    }
}
