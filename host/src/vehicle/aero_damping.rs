//! The aerodynamic moment about the flapping axis as the actuator model
//! carries it: one law, `T_a = c_a phi' |phi'|` (quadratic damping, the
//! plant's and the feasibility check's form, [`fwav_actuator::plant`]),
//! whose coefficient `c_a` is calibrated on the system analysis so that
//! its work per cycle equals the work the analysis's drive puts into the
//! wing per cycle at the analysed kinematics:
//!
//! `c_a = W / int_cycle |phi'|^3 dt`, `W = int_cycle T_d phi' dt`,
//!
//! with `T_d` the analysis's drive torque about the flapping axis
//! ([`crate::aeroelastic::StepRecord::drive_torque_nm`]) and `phi'` the
//! prescribed flapping rate, both over the last analysed cycle and summed
//! with the same rectangle rule on the analysis's steps (so the law's work
//! on those samples is `W` exactly).
//!
//! What `W` is: the drive torque is the wing's inertial torque less the
//! aerodynamic moment about the axis. Over a periodic cycle the rigid
//! rotation's inertial torque does no net work (`int J phi'' phi' dt` is
//! the change of the kinetic energy, zero), nor does the elastic motion's
//! (its kinetic and strain energies return), so `W` is the energy the air
//! takes from the flapping wing per cycle — the aerodynamic work the drive
//! must supply, with no inertial part to subtract. The law keeps that
//! energy at other kinematics by scaling with `|phi'|^3` (a wing moving
//! through still air at high angle: force ~ speed squared); it does not
//! keep the moment's phase or its mean-angle dependence, nor the forward
//! flight's share (at the analysed point that share is inside `W`).
//!
//! May import: [`crate::aeroelastic`] (the analysis's records and the
//! kinematics).

use fwav_settings::Shown;

use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::aeroelastic::StepRecord;

/// One instant of a flapping cycle as the drive sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DriveSample {
    /// Flapping rate, rad/s.
    pub rate_rad_s: f64,
    /// Torque the drive applies about the flapping axis, N m.
    pub torque_nm: f64,
}

/// Why `c_a` could not be calibrated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CalibrationError {
    /// No samples, or a non-positive or non-finite period.
    #[error("the drive history has {samples} samples over a period of {} s: give at least one cycle of the system analysis (steps_per_cycle > 0, frequency > 0)", Shown(*.period_s))]
    Empty {
        /// Samples given.
        samples: usize,
        /// Period, s.
        period_s: f64,
    },
    /// The wing does not move (`int |phi'|^3 dt` is zero) or a sample is
    /// not a number.
    #[error("the drive history has no motion or a non-finite sample (int |rate|^3 dt = {cube}): the analysed amplitude must be above zero")]
    NoMotion {
        /// `int |phi'|^3 dt`, rad^3/s^2.
        cube: f64,
    },
    /// The air gives the wing energy over the cycle: a damping law cannot
    /// carry that.
    #[error("the drive puts {work_j:.4e} J per cycle into the wing (the air does work on it): a damping law needs positive work; check that the analysis reached its periodic state (more cycles)")]
    NegativeWork {
        /// Work per cycle, J.
        work_j: f64,
    },
}

/// The calibrated law and what it was calibrated against.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct AeroDamping {
    /// `c_a` of `T_a = c_a phi' |phi'|`, N m s^2.
    pub coefficient_nms2: f64,
    /// The drive's work per cycle it reproduces, J.
    pub work_per_cycle_j: f64,
}

/// Calibrates `c_a` on one cycle of `samples`, evenly spaced over
/// `period_s` (module docs).
pub fn calibrate(samples: &[DriveSample], period_s: f64) -> Result<AeroDamping, CalibrationError> {
    if samples.is_empty() || !(period_s > 0.0 && period_s.is_finite()) {
        return Err(CalibrationError::Empty {
            samples: samples.len(),
            period_s,
        });
    }
    let dt = period_s / samples.len() as f64;
    let work: f64 = samples
        .iter()
        .map(|s| s.torque_nm * s.rate_rad_s)
        .sum::<f64>()
        * dt;
    let cube: f64 = samples
        .iter()
        .map(|s| s.rate_rad_s.abs().powi(3))
        .sum::<f64>()
        * dt;
    if !(cube > 0.0 && cube.is_finite() && work.is_finite()) {
        return Err(CalibrationError::NoMotion { cube });
    }
    if work <= 0.0 {
        return Err(CalibrationError::NegativeWork { work_j: work });
    }
    Ok(AeroDamping {
        coefficient_nms2: work / cube,
        work_per_cycle_j: work,
    })
}

/// The last cycle of the analysis `steps` (of `steps_per_cycle` steps,
/// at `kinematics`; `SystemResult::steps` or a stored record's) as drive
/// samples: the drive torque and the prescribed flapping rate at each
/// step's time.
pub fn drive_history(
    steps: &[StepRecord],
    kinematics: &FlappingKinematics,
    steps_per_cycle: usize,
) -> Vec<DriveSample> {
    steps[steps.len().saturating_sub(steps_per_cycle)..]
        .iter()
        .map(|s| DriveSample {
            rate_rad_s: kinematics.angle(s.time_s).1,
            torque_nm: s.drive_torque_nm,
        })
        .collect()
}

/// `c_a` calibrated on the last cycle of the system analysis `steps` of
/// `kinematics` (module docs).
pub fn from_analysis(
    steps: &[StepRecord],
    kinematics: &FlappingKinematics,
    steps_per_cycle: usize,
) -> Result<AeroDamping, CalibrationError> {
    calibrate(
        &drive_history(steps, kinematics, steps_per_cycle),
        kinematics.period(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// A synthetic cycle: `T = J phi'' + k phi + c phi'|phi'|` at `phi =
    /// A cos(w t)`. The inertial and spring parts do no work over the
    /// cycle, so the calibration recovers `c`, and the law's work equals
    /// the history's (both by the rectangle rule on the same samples, and
    /// against the analytic `c (A w)^3 T 4 / (3 pi)` for the cycle average
    /// of `|sin|^3`, 4 / (3 pi)).
    #[test]
    fn work_per_cycle_is_kept_and_inertia_does_none() {
        let (a, f, j, k, c) = (0.5, 11.0, 7e-5, 0.3, 2e-5);
        let w = 2.0 * PI * f;
        let n = 400;
        let period = 1.0 / f;
        let samples: Vec<DriveSample> = (0..n)
            .map(|i| {
                let t = (i as f64 + 1.0) * period / n as f64;
                let (phi, rate, accel) = (
                    a * (w * t).cos(),
                    -a * w * (w * t).sin(),
                    -a * w * w * (w * t).cos(),
                );
                DriveSample {
                    rate_rad_s: rate,
                    torque_nm: j * accel + k * phi + c * rate * rate.abs(),
                }
            })
            .collect();
        let d = calibrate(&samples, period).unwrap();
        assert!((d.coefficient_nms2 / c - 1.0).abs() < 1e-9, "{d:?}");
        let analytic = c * (a * w).powi(3) * period * 4.0 / (3.0 * PI);
        assert!(
            (d.work_per_cycle_j / analytic - 1.0).abs() < 1e-9,
            "{d:?} vs {analytic}"
        );
        let dt = period / n as f64;
        let law: f64 = samples
            .iter()
            .map(|s| d.coefficient_nms2 * s.rate_rad_s.abs().powi(3))
            .sum::<f64>()
            * dt;
        assert!((law / d.work_per_cycle_j - 1.0).abs() < 1e-12);
    }

    #[test]
    fn histories_it_cannot_carry_are_errors() {
        assert!(matches!(
            calibrate(&[], 0.1),
            Err(CalibrationError::Empty { .. })
        ));
        let still = [DriveSample {
            rate_rad_s: 0.0,
            torque_nm: 1.0,
        }];
        assert!(matches!(
            calibrate(&still, 0.1),
            Err(CalibrationError::NoMotion { .. })
        ));
        let pushed = [
            DriveSample {
                rate_rad_s: 1.0,
                torque_nm: -1.0,
            },
            DriveSample {
                rate_rad_s: -1.0,
                torque_nm: 1.0,
            },
        ];
        let e = calibrate(&pushed, 0.1).unwrap_err();
        assert!(e.to_string().contains("the air does work on it"), "{e}");
    }
}
