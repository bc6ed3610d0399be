//! How the viscous model's section moves ([`SectionPath`]): the motions
//! of `fwav aero2d` (harmonic plunge and pitch, a section at rest in the
//! stream) and of the aerodynamic discipline (the flapping section), and
//! the LDVM paper's pitch ramp, each as the solver's moving frame.

use fwav_ns2d::{Complex64, FrameState};

use super::deflection::RigidDeflection;
use crate::aero2d::motion::{Motion, PitchRamp, SectionFlapping};

/// The peak rate of [`SectionPath::Still`]'s start-up turn for a mirror
/// symmetric flow, `U / c`: a cylinder's wake at Re 100 sheds fully from
/// about 40 diameters on, and the sudden start's drag moves by at most
/// 0.18 % over U t/R 0.5–3 (the turn is at most 1.8° of pitch).
pub const STILL_KICK_RATE: f64 = 0.05;

/// Its length, chords travelled.
pub const STILL_KICK_CHORDS: f64 = 2.0;

/// How the section moves, in chords and chords travelled (`c = U = 1`).
#[derive(Clone, Debug, PartialEq)]
pub enum SectionPath {
    /// Harmonic plunge and pitch about a pivot (`fwav aero2d`'s).
    Harmonic(Motion),
    /// A wing section flapping about the root axis: plunge and the surge
    /// of an inclined stroke plane, no pitch (the aerodynamic
    /// discipline's); the frame's origin is at mid-chord.
    Flapping(SectionFlapping),
    /// The flapping section carried and turned besides by the rigid part
    /// of its deformation (the wing's bending and twist at the section:
    /// [`RigidDeflection`]), the frame's origin at mid-chord: the frame
    /// of a deforming section whose change of shape beyond that part is
    /// left out or runs on the moving grid
    /// ([`super::ViscousSection::run_deflecting`]).
    Deflected(SectionFlapping, Box<RigidDeflection>),
    /// A section at rest in the stream pitched nose-up by Eldredge's ramp
    /// about `pivot` (chords from the leading edge): the LDVM paper's
    /// case 1 (no period).
    Ramp {
        /// The pitch axis, chords from the leading edge.
        pivot: f64,
        /// The pitch history.
        ramp: PitchRamp,
    },
    /// A section at rest in the stream at a fixed nose-up pitch (radians)
    /// about `pivot` (chords from the leading edge), started impulsively:
    /// a body in a steady stream, or a sudden start (no period). Over its
    /// first [`STILL_KICK_CHORDS`] it turns to and fro by one period of a
    /// sine of peak rate `kick_rate` (back to its pitch at the end). A
    /// flow that is mirror symmetric (a symmetric section at zero pitch)
    /// needs that disturbance, as a real stream has: without it its wake
    /// stays symmetric to round-off and never sheds
    /// ([`STILL_KICK_RATE`]). A lifting one sheds by itself and takes 0.
    Still {
        /// The pitch axis, chords from the leading edge.
        pivot: f64,
        /// The nose-up pitch, radians.
        pitch: f64,
        /// The start-up turn's peak rate, `U / c` (0 for none).
        kick_rate: f64,
    },
}

impl SectionPath {
    /// The frame's origin, chords from the leading edge.
    pub(super) fn pivot(&self) -> f64 {
        match self {
            Self::Harmonic(m) => m.pivot,
            Self::Flapping(_) | Self::Deflected(..) => 0.5,
            Self::Ramp { pivot, .. } | Self::Still { pivot, .. } => *pivot,
        }
    }

    pub(super) fn reduced_frequency(&self) -> f64 {
        match self {
            Self::Harmonic(m) => m.reduced_frequency,
            Self::Flapping(f) | Self::Deflected(f, _) => f.reduced_frequency,
            Self::Ramp { .. } | Self::Still { .. } => 0.0,
        }
    }

    /// Where a point `z` of the body frame is at `t` in the global frame
    /// of [`super::super::case`] (the pivot at `x = pivot` plus the surge,
    /// plunged by `h`; the body axes turned by `-alpha`, a nose-up pitch
    /// being clockwise).
    pub(super) fn placement(&self, t: f64) -> impl Fn(Complex64) -> (f64, f64) {
        let (x0, h, alpha) = self.pose(t);
        let pivot = self.pivot() + x0;
        let (s, c) = alpha.sin_cos();
        move |z: Complex64| (pivot + z.re * c + z.im * s, h - z.re * s + z.im * c)
    }

    /// `(x, h, alpha)`: downstream surge and plunge of the pivot, chords,
    /// and the nose-up pitch, at `t`.
    pub(super) fn pose(&self, t: f64) -> (f64, f64, f64) {
        match self {
            Self::Harmonic(m) => {
                let (h, _, alpha, _) = m.at(t);
                (0.0, h, alpha)
            }
            Self::Flapping(f) => {
                let (x, _, h, _) = f.at(t);
                (x, h, 0.0)
            }
            Self::Deflected(f, d) => {
                let (x, _, h, _) = f.at(t);
                let s = d.state(t);
                (x + s.translation.re, h + s.translation.im, -s.angle)
            }
            Self::Ramp { ramp, .. } => (0.0, 0.0, ramp.at(t).0),
            // The start-up turn included.
            Self::Still { .. } => (0.0, 0.0, -fwav_ns2d::Motion::state(self, t).angle),
        }
    }

    /// The largest speed of the section's edges relative to the stream
    /// over the one at the start (the first step is chosen at the start).
    pub(super) fn peak_speed_ratio(&self) -> f64 {
        let (peak, start) = match self {
            Self::Harmonic(m) => {
                let w = 2.0 * m.reduced_frequency;
                let plunge = m.plunge_amplitude.abs() * w;
                // The edges' speed from the pitch rate, about the farther end.
                let arm = m.pivot.max(1.0 - m.pivot);
                let pitch = m.pitch_amplitude.abs() * w * arm;
                (1.0 + plunge + pitch, m.at(0.0).1.abs() + 1.0)
            }
            Self::Flapping(f) => {
                let w = 2.0 * f.reduced_frequency;
                let (_, dx, _, dh) = f.at(0.0);
                (1.0 + f.radius * f.amplitude.abs() * w, (1.0 - dx).hypot(dh))
            }
            Self::Deflected(f, d) => {
                let w = 2.0 * f.reduced_frequency;
                let (_, dx, _, dh) = f.at(0.0);
                let v = d.state(0.0).velocity;
                (
                    1.0 + f.radius * f.amplitude.abs() * w + d.peak_speed(0.5),
                    (1.0 - dx - v.re).hypot(dh + v.im),
                )
            }
            Self::Ramp { pivot, ramp } => {
                let arm = pivot.max(1.0 - pivot);
                (1.0 + 2.0 * ramp.pitch_rate * arm, 1.0)
            }
            Self::Still { .. } => (1.0, 1.0),
        };
        peak / start
    }
}

impl fwav_ns2d::Motion for SectionPath {
    fn state(&self, t: f64) -> FrameState {
        match self {
            Self::Harmonic(m) => {
                // Nose-up pitch turns the body axes clockwise.
                let w = 2.0 * m.reduced_frequency;
                let (h, dh, alpha, dalpha) = m.at(t);
                let ddh = -w * w * h;
                let ddalpha = -w * w * (alpha - m.mean_pitch);
                FrameState {
                    velocity: Complex64::new(-1.0, dh),
                    acceleration: Complex64::new(0.0, ddh),
                    angle: -alpha,
                    rate: -dalpha,
                    angular_acceleration: -ddalpha,
                }
            }
            Self::Flapping(f) => {
                // The frame moves at -U through the air, plus its surge
                // (downstream) and plunge.
                let (_, dx, _, dh) = f.at(t);
                let (ddx, ddh) = f.acceleration(t);
                FrameState {
                    velocity: Complex64::new(dx - 1.0, dh),
                    acceleration: Complex64::new(ddx, ddh),
                    ..FrameState::default()
                }
            }
            Self::Deflected(f, d) => {
                // The flapping frame's motion, and the deflection's in
                // the same (fixed) axes.
                let (_, dx, _, dh) = f.at(t);
                let (ddx, ddh) = f.acceleration(t);
                let s = d.state(t);
                FrameState {
                    velocity: Complex64::new(dx - 1.0, dh) + s.velocity,
                    acceleration: Complex64::new(ddx, ddh) + s.acceleration,
                    angle: s.angle,
                    rate: s.rate,
                    angular_acceleration: s.angular_acceleration,
                }
            }
            Self::Ramp { ramp, .. } => {
                let (alpha, dalpha) = ramp.at(t);
                FrameState {
                    velocity: Complex64::new(-1.0, 0.0),
                    angle: -alpha,
                    rate: -dalpha,
                    angular_acceleration: -ramp.acceleration(t),
                    ..FrameState::default()
                }
            }
            Self::Still {
                pitch, kick_rate, ..
            } => {
                let mut state = FrameState {
                    velocity: Complex64::new(-1.0, 0.0),
                    angle: -pitch,
                    ..FrameState::default()
                };
                if *kick_rate != 0.0 && t > 0.0 && t < STILL_KICK_CHORDS {
                    let w = std::f64::consts::TAU / STILL_KICK_CHORDS;
                    let (s, c) = (w * t).sin_cos();
                    state.rate = kick_rate * s;
                    state.angular_acceleration = kick_rate * w * c;
                    state.angle += kick_rate / w * (1.0 - c);
                }
                state
            }
        }
    }
}
