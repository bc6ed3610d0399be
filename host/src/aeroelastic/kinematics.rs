//! The flapping motion of the wing root: a rotation about a fixed axis
//! through the root leading edge, with the design variables of the
//! kinematic optimization (seed paper, aerodynamic discipline): flapping
//! frequency, amplitude, mean flapping angle (front view) and the
//! inclination of the stroke plane (side view).
//!
//! Axes as in [`crate::shell::wing`]: `x` chordwise from the leading edge
//! to the trailing edge (the direction the air moves past the vehicle in
//! forward flight), `y` spanwise from root to tip, `z` up. The stroke plane
//! is the plane the wing's span sweeps; it contains `y` and is inclined by
//! `stroke_plane` from the horizontal `xy`-plane about `y`: 90° (the
//! paper's initial design) is the vertical plane across the flight path,
//! the wing beating up and down about the `x` axis. The flapping axis is
//! the stroke plane's normal, `(sin b, 0, cos b)` for inclination `b`.
//!
//! The flapping angle is `phi(t) = mean + amplitude cos(2 pi f t)`, positive
//! tip up for the vertical stroke plane; the cosine starts the motion at
//! the top of the stroke, at rest, so an analysis begins without an
//! impulsive start.

use nalgebra::{Rotation3, Unit, Vector3};
use serde::{Deserialize, Serialize};

/// Flapping kinematics (SI: Hz and radians).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FlappingKinematics {
    /// Flapping frequency, Hz (paper: 11 Hz).
    pub frequency: f64,
    /// Flapping amplitude (half the stroke angle), rad (built-in: 30°).
    pub amplitude: f64,
    /// Mean flapping angle (front view), rad, positive tip up.
    pub mean_angle: f64,
    /// Stroke-plane inclination from the horizontal (side view), rad; 90°
    /// is the vertical stroke plane across the flight path.
    pub stroke_plane: f64,
}

/// Why kinematics were refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum KinematicsError {
    /// A value out of its range.
    #[error("flapping kinematics: {field} = {value} is outside {range}")]
    OutOfRange {
        /// The field name.
        field: &'static str,
        /// Its value, in the unit of `range` (Hz or degrees).
        value: f64,
        /// The allowed range, as text.
        range: &'static str,
    },
}

impl FlappingKinematics {
    /// The built-in FWAV's initial design: 11 Hz, ±30°, mean 0°, vertical
    /// stroke plane.
    pub const INITIAL: FlappingKinematics = FlappingKinematics {
        frequency: 11.0,
        amplitude: std::f64::consts::PI / 6.0,
        mean_angle: 0.0,
        stroke_plane: std::f64::consts::FRAC_PI_2,
    };

    /// Checks the ranges: frequency in (0, 200] Hz, amplitude in [0, 80°],
    /// mean angle within ±60°, stroke plane in [0, 180°].
    pub fn validate(&self) -> Result<(), KinematicsError> {
        let deg = std::f64::consts::PI / 180.0;
        let checks: [(&'static str, f64, f64, f64, &'static str); 4] = [
            ("frequency", self.frequency, 1e-9, 200.0, "(0, 200] Hz"),
            ("amplitude", self.amplitude, 0.0, 80.0 * deg, "[0, 80] deg"),
            (
                "mean_angle",
                self.mean_angle,
                -60.0 * deg,
                60.0 * deg,
                "[-60, 60] deg",
            ),
            (
                "stroke_plane",
                self.stroke_plane,
                0.0,
                180.0 * deg,
                "[0, 180] deg",
            ),
        ];
        for (field, value, low, high, range) in checks {
            if !(value.is_finite() && (low..=high).contains(&value)) {
                let value = if field == "frequency" {
                    value
                } else {
                    value.to_degrees()
                };
                return Err(KinematicsError::OutOfRange {
                    field,
                    value,
                    range,
                });
            }
        }
        Ok(())
    }

    /// The flapping period, s.
    pub fn period(&self) -> f64 {
        1.0 / self.frequency
    }

    /// The flapping axis (unit, inertial and body frames alike: the
    /// rotation is about it).
    pub fn axis(&self) -> Unit<Vector3<f64>> {
        Unit::new_normalize(Vector3::new(
            self.stroke_plane.sin(),
            0.0,
            self.stroke_plane.cos(),
        ))
    }

    /// Flapping angle, its rate and its acceleration at `t`: rad, rad/s,
    /// rad/s².
    pub fn angle(&self, t: f64) -> (f64, f64, f64) {
        let w = 2.0 * std::f64::consts::PI * self.frequency;
        let (s, c) = (w * t).sin_cos();
        (
            self.mean_angle + self.amplitude * c,
            -self.amplitude * w * s,
            -self.amplitude * w * w * c,
        )
    }

    /// The root's rigid motion at `t`: the rotation from body to inertial
    /// axes, the angular velocity and the angular acceleration (rad/s,
    /// rad/s²; the same vectors in both frames, the axis being fixed).
    pub fn motion(&self, t: f64) -> RootMotion {
        let (phi, rate, acceleration) = self.angle(t);
        let axis = self.axis();
        RootMotion {
            rotation: Rotation3::from_axis_angle(&axis, phi),
            angular_velocity: axis.into_inner() * rate,
            angular_acceleration: axis.into_inner() * acceleration,
        }
    }
}

/// The rigid motion of the body frame at one time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RootMotion {
    /// Body → inertial rotation.
    pub rotation: Rotation3<f64>,
    /// Angular velocity, rad/s.
    pub angular_velocity: Vector3<f64>,
    /// Angular acceleration, rad/s².
    pub angular_acceleration: Vector3<f64>,
}

impl RootMotion {
    /// Inertial position of the body-frame point `p`, m.
    pub fn position(&self, p: &Vector3<f64>) -> Vector3<f64> {
        self.rotation * p
    }

    /// Inertial velocity of a point at body position `p` moving with
    /// body-frame velocity `v` (m/s): `Omega x R p + R v`.
    pub fn velocity(&self, p: &Vector3<f64>, v: &Vector3<f64>) -> Vector3<f64> {
        self.angular_velocity.cross(&(self.rotation * p)) + self.rotation * v
    }

    /// The frame's acceleration of a point fixed at body position `p`
    /// plus the Coriolis term of a body velocity `v`, in body axes:
    /// `alpha x p + Omega x (Omega x p) + 2 Omega x v` (m/s²; Omega and
    /// alpha along the fixed axis are the same in both frames).
    pub fn frame_acceleration(&self, p: &Vector3<f64>, v: &Vector3<f64>) -> Vector3<f64> {
        let w = self.angular_velocity;
        self.angular_acceleration.cross(p) + w.cross(&w.cross(p)) + 2.0 * w.cross(v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rates_are_the_derivatives_of_the_angle() {
        let k = FlappingKinematics {
            mean_angle: 0.1,
            ..FlappingKinematics::INITIAL
        };
        let (t, h) = (0.013, 1e-6);
        let (_, rate, acc) = k.angle(t);
        let d = |t: f64| k.angle(t);
        assert!(((d(t + h).0 - d(t - h).0) / (2.0 * h) - rate).abs() < 1e-6 * rate.abs());
        assert!(((d(t + h).1 - d(t - h).1) / (2.0 * h) - acc).abs() < 1e-6 * acc.abs());
        // Vertical stroke plane: positive angle lifts the tip.
        let up = FlappingKinematics::INITIAL.motion(0.0);
        assert!(up.position(&Vector3::new(0.0, 1.0, 0.0)).z > 0.4);
        // Velocity of a body point equals the time derivative of its position.
        let p = Vector3::new(0.03, 0.1, 0.0);
        let x = |t: f64| k.motion(t).position(&p);
        let v = k.motion(t).velocity(&p, &Vector3::zeros());
        assert!(((x(t + h) - x(t - h)) / (2.0 * h) - v).norm() < 1e-6 * v.norm());
    }

    #[test]
    fn ranges_are_checked() {
        let bad = FlappingKinematics {
            frequency: -1.0,
            ..FlappingKinematics::INITIAL
        };
        assert!(matches!(
            bad.validate(),
            Err(KinematicsError::OutOfRange {
                field: "frequency",
                ..
            })
        ));
        assert!(FlappingKinematics::INITIAL.validate().is_ok());
    }
}
