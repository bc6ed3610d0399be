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

use fwav_settings::Shown;
use nalgebra::{Rotation3, Unit, Vector3};
use serde::{Deserialize, Serialize};

/// Flapping kinematics (SI: Hz and radians): the one kinematic design
/// type — the `[kinematics]` table of the design file, the designs of the
/// aerodynamic discipline and of its records and cache keys.
///
/// Files carry it in Hz and degrees (`frequency_hz`, `amplitude_deg`,
/// `mean_angle_deg`, `stroke_plane_deg`; a missing key takes
/// [`FlappingKinematics::default`]'s). Reading converts each angle once
/// with `to_radians`. Writing gives the angle as the shortest decimal
/// whose `to_radians` is the stored angle exactly ([`Self::degrees`]), so
/// a file written and read back by a correctly rounding reader (TOML;
/// serde_json's default reader may be a unit in the last place off)
/// yields the same radians to the bit, and
/// an angle that came from degrees people typed is written as they typed
/// it (30, not the 29.999999999999996 of `to_degrees`). An angle that did
/// not come from degrees (no decimal maps to it) is written as its
/// `to_degrees`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(from = "Degrees", into = "Degrees")]
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

/// [`FlappingKinematics`] as files write it: Hz and degrees.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
struct Degrees {
    frequency_hz: f64,
    amplitude_deg: f64,
    mean_angle_deg: f64,
    stroke_plane_deg: f64,
}

impl Default for Degrees {
    fn default() -> Self {
        FlappingKinematics::default().into()
    }
}

impl From<Degrees> for FlappingKinematics {
    fn from(d: Degrees) -> Self {
        Self::from_degrees([
            d.frequency_hz,
            d.amplitude_deg,
            d.mean_angle_deg,
            d.stroke_plane_deg,
        ])
    }
}

impl From<FlappingKinematics> for Degrees {
    fn from(k: FlappingKinematics) -> Self {
        let [frequency_hz, amplitude_deg, mean_angle_deg, stroke_plane_deg] = k.degrees();
        Self {
            frequency_hz,
            amplitude_deg,
            mean_angle_deg,
            stroke_plane_deg,
        }
    }
}

/// The shortest decimal number of degrees whose `to_radians` is
/// `radians` exactly, looked for around `to_degrees` (a few units in the
/// last place either side); `to_degrees` itself when there is none.
fn degrees_of(radians: f64) -> f64 {
    let near = radians.to_degrees();
    if !near.is_finite() {
        return near;
    }
    let step = |x: f64, ulps: i64| f64::from_bits(x.to_bits().wrapping_add_signed(ulps));
    let candidates: Vec<f64> = (-3..=3).map(|u| step(near, u)).collect();
    for digits in 1..=17usize {
        for &c in &candidates {
            let d: f64 = format!("{c:.*e}", digits - 1).parse().unwrap_or(c);
            if d.to_radians() == radians {
                return d;
            }
        }
    }
    near
}

impl Default for FlappingKinematics {
    /// [`FlappingKinematics::INITIAL`] from the degrees a person types
    /// (11 Hz, 30°, 0°, 90°, each converted with `to_radians`).
    fn default() -> Self {
        Self::from_degrees([FlappingKinematics::INITIAL.frequency, 30.0, 0.0, 90.0])
    }
}

/// Why kinematics were refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum KinematicsError {
    /// A value out of its range.
    #[error("flapping kinematics: {field} = {} is outside {range}", Shown(*.value))]
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
    /// mean angle within ±60°, stroke plane in (0, 180°).
    pub fn validate(&self) -> Result<(), KinematicsError> {
        let deg = std::f64::consts::PI / 180.0;
        let checks: [(&'static str, f64, f64, f64, &'static str); 3] = [
            ("frequency", self.frequency, 1e-9, 200.0, "(0, 200] Hz"),
            ("amplitude", self.amplitude, 0.0, 80.0 * deg, "[0, 80] deg"),
            (
                "mean_angle",
                self.mean_angle,
                -60.0 * deg,
                60.0 * deg,
                "[-60, 60] deg",
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
        // Open: at 0 or 180 deg the wing sweeps in its own plane, moves no
        // air and has no thrust, power or efficiency.
        if !(self.stroke_plane > 0.0 && self.stroke_plane < std::f64::consts::PI) {
            return Err(KinematicsError::OutOfRange {
                field: "stroke_plane",
                value: self.stroke_plane.to_degrees(),
                range: "(0, 180) deg",
            });
        }
        Ok(())
    }

    /// From `[frequency Hz, amplitude deg, mean angle deg, stroke plane
    /// deg]`, each angle converted with `to_radians`.
    pub fn from_degrees(x: [f64; 4]) -> Self {
        Self {
            frequency: x[0],
            amplitude: x[1].to_radians(),
            mean_angle: x[2].to_radians(),
            stroke_plane: x[3].to_radians(),
        }
    }

    /// `[frequency Hz, amplitude deg, mean angle deg, stroke plane deg]`
    /// as files write them (the type's docs: the shortest degrees that
    /// convert back to these radians exactly).
    pub fn degrees(&self) -> [f64; 4] {
        [
            self.frequency,
            degrees_of(self.amplitude),
            degrees_of(self.mean_angle),
            degrees_of(self.stroke_plane),
        ]
    }

    /// The amplitude in degrees as files write it ([`Self::degrees`]).
    pub fn amplitude_deg(&self) -> f64 {
        degrees_of(self.amplitude)
    }

    /// The mean angle in degrees as files write it.
    pub fn mean_angle_deg(&self) -> f64 {
        degrees_of(self.mean_angle)
    }

    /// The stroke-plane inclination in degrees as files write it.
    pub fn stroke_plane_deg(&self) -> f64 {
        degrees_of(self.stroke_plane)
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

    /// Degrees people typed come back as typed; any angle from degrees
    /// makes the file round trip to the same radians.
    #[test]
    fn files_carry_degrees_that_round_trip() {
        let k = FlappingKinematics::from_degrees([11.0, 30.0, -7.3, 90.0]);
        assert_eq!(k.degrees(), [11.0, 30.0, -7.3, 90.0]);
        let json = serde_json::to_string(&k).unwrap();
        assert_eq!(
            json,
            r#"{"frequency_hz":11.0,"amplitude_deg":30.0,"mean_angle_deg":-7.3,"stroke_plane_deg":90.0}"#
        );
        for x in [
            33.271_948_237_104_41,
            1e-3,
            79.999_999_999_999_99,
            0.1 + 0.2,
        ] {
            let k = FlappingKinematics::from_degrees([9.0, x, -x, 180.0 - x]);
            // (TOML, whose reader rounds correctly; serde_json's default
            // reader may land a unit in the last place off.)
            let back: FlappingKinematics = toml::from_str(&toml::to_string(&k).unwrap()).unwrap();
            assert_eq!(back, k, "{x}");
            assert_eq!(FlappingKinematics::from_degrees(k.degrees()), k, "{x}");
        }
        let partial: FlappingKinematics = serde_json::from_str(r#"{"frequency_hz":9.0}"#).unwrap();
        assert_eq!(
            partial,
            FlappingKinematics {
                frequency: 9.0,
                ..FlappingKinematics::default()
            }
        );
    }

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
        // A stroke plane of 0 or 180 deg sweeps the wing in its own plane:
        // no thrust, no power, no efficiency (the design's 2D run then
        // failed as "diverged (non-finite net efficiency)").
        for degrees in [0.0, 180.0, f64::NAN] {
            let flat = FlappingKinematics {
                stroke_plane: f64::to_radians(degrees),
                ..FlappingKinematics::INITIAL
            };
            assert!(
                matches!(
                    flat.validate(),
                    Err(KinematicsError::OutOfRange {
                        field: "stroke_plane",
                        range: "(0, 180) deg",
                        ..
                    })
                ),
                "{degrees}"
            );
        }
    }
}
