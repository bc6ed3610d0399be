//! The section's motion: the body frame the grid is fixed in.
//!
//! The grid moves rigidly with the section (translation of its origin and
//! rotation about it). The flow is solved for the absolute vorticity, which
//! the relative velocity carries (in 2D the frame's rotation adds nothing
//! to the absolute vorticity equation), and the streamfunction of the
//! absolute velocity; the velocities are relative to the fluid far away
//! (Galilean), so a free stream `U∞` is the frame moving at `-U∞`.

use realfft::num_complex::Complex64;

/// The body frame at one instant, relative to the far fluid, in the fixed
/// (ground) axes. Angles in radians, counter-clockwise.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FrameState {
    /// Velocity of the frame's origin relative to the fluid far away.
    pub velocity: Complex64,
    /// Acceleration of the frame's origin.
    pub acceleration: Complex64,
    /// Angle of the body axes to the fixed axes.
    pub angle: f64,
    /// Rotation rate `dα/dt`.
    pub rate: f64,
    /// Angular acceleration `d²α/dt²`.
    pub angular_acceleration: f64,
}

impl FrameState {
    /// The frame's velocity in the body axes.
    #[must_use]
    pub fn body_velocity(&self) -> Complex64 {
        self.velocity * Complex64::from_polar(1.0, -self.angle)
    }

    /// The frame's acceleration in the body axes.
    #[must_use]
    pub fn body_acceleration(&self) -> Complex64 {
        self.acceleration * Complex64::from_polar(1.0, -self.angle)
    }

    /// Velocity of the body point `z` (body axes) relative to the far
    /// fluid, in body axes: `V + Ω × z`.
    #[must_use]
    pub fn point_velocity(&self, z: Complex64) -> Complex64 {
        self.rigid_field().velocity_at(z)
    }

    /// Acceleration of the body point `z`, body axes:
    /// `A + Ω̇ × z - Ω² z`.
    #[must_use]
    pub fn point_acceleration(&self, z: Complex64) -> Complex64 {
        self.body_acceleration() + Complex64::new(0.0, self.angular_acceleration) * z
            - z * (self.rate * self.rate)
    }

    /// The rigid velocity field in body axes (for many points).
    #[must_use]
    pub fn rigid_field(&self) -> RigidField {
        RigidField {
            velocity: self.body_velocity(),
            rate: self.rate,
        }
    }

    /// The streamfunction of the rigid velocity field `V + Ω × z`:
    /// `Im(conj(V) z) - Ω |z|²/2` (body axes).
    #[must_use]
    pub fn streamfunction(&self, z: Complex64) -> f64 {
        self.rigid_field().streamfunction(z)
    }

    /// The gradient `(∂ψ/∂x, ∂ψ/∂y)` of [`Self::streamfunction`] as a
    /// complex number: `iV - Ω z`.
    #[must_use]
    pub fn streamfunction_gradient(&self, z: Complex64) -> Complex64 {
        Complex64::new(0.0, 1.0) * self.body_velocity() - z * self.rate
    }
}

/// The rigid velocity field of a [`FrameState`] in body axes, with the
/// rotation of the frame's velocity into them done once.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RigidField {
    /// The frame's velocity in body axes.
    pub velocity: Complex64,
    /// The rotation rate.
    pub rate: f64,
}

impl RigidField {
    /// The streamfunction `Im(conj(V) z) - Ω |z|²/2`.
    #[must_use]
    #[inline]
    pub fn streamfunction(&self, z: Complex64) -> f64 {
        (self.velocity.conj() * z).im - 0.5 * self.rate * z.norm_sqr()
    }

    /// The velocity at `z`, `V + iΩz`.
    #[must_use]
    #[inline]
    pub fn velocity_at(&self, z: Complex64) -> Complex64 {
        self.velocity + Complex64::new(0.0, self.rate) * z
    }
}

/// A prescribed motion of the section.
pub trait Motion {
    /// The frame at time `t`.
    fn state(&self, t: f64) -> FrameState;
}

/// A section at rest in a uniform stream of speed `speed` along +x (the
/// frame moves at `-speed` relative to the fluid), optionally spun about
/// its origin for one period of `kick_period` with peak rate `kick_rate`
/// to break the symmetry of a bluff body's wake (the perturbation of
/// Braza, Chassaing & Ha Minh 1986); the angle returns to zero after it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyStream {
    /// Free-stream speed.
    pub speed: f64,
    /// Peak rotation rate of the start-up kick (0 for none).
    pub kick_rate: f64,
    /// Duration of the kick.
    pub kick_period: f64,
}

impl Motion for SteadyStream {
    fn state(&self, t: f64) -> FrameState {
        let mut state = FrameState {
            velocity: Complex64::new(-self.speed, 0.0),
            ..FrameState::default()
        };
        if self.kick_rate != 0.0 && t > 0.0 && t < self.kick_period {
            let w = std::f64::consts::TAU / self.kick_period;
            state.rate = self.kick_rate * (w * t).sin();
            state.angular_acceleration = self.kick_rate * w * (w * t).cos();
            state.angle = self.kick_rate / w * (1.0 - (w * t).cos());
        }
        state
    }
}

/// A section in a stream of speed `speed` along +x that plunges
/// `h = h0 sin(ωt)` across it and pitches nose-up `α = α0 + α1 sin(ωt + φ)`
/// about its origin (the pivot; place the section relative to it with
/// the map's centre). The chord lies along body +x, leading edge
/// upstream, so a nose-up pitch is a clockwise rotation of the frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlungePitch {
    /// Free-stream speed.
    pub speed: f64,
    /// Angular frequency `ω`.
    pub omega: f64,
    /// Plunge amplitude `h0`.
    pub plunge: f64,
    /// Mean pitch `α0`, radians.
    pub mean_pitch: f64,
    /// Pitch amplitude `α1`, radians.
    pub pitch: f64,
    /// Pitch lead over the plunge `φ`, radians.
    pub phase: f64,
}

impl Motion for PlungePitch {
    fn state(&self, t: f64) -> FrameState {
        let w = self.omega;
        let (s, c) = (w * t).sin_cos();
        let (sp, cp) = (w * t + self.phase).sin_cos();
        FrameState {
            velocity: Complex64::new(-self.speed, self.plunge * w * c),
            acceleration: Complex64::new(0.0, -self.plunge * w * w * s),
            angle: -(self.mean_pitch + self.pitch * sp),
            rate: -self.pitch * w * cp,
            angular_acceleration: self.pitch * w * w * sp,
        }
    }
}
