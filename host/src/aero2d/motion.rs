//! Prescribed rigid motion of a section: harmonic plunge and pitch
//! ([`Motion`]) and Eldredge's smoothed pitch ramp ([`PitchRamp`]), in
//! chords, radians and chords travelled (`c = U = 1`).

/// Prescribed motion of the section (all amplitudes in chords / radians).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Reduced frequency `k = omega c / (2 U)`; 0 for a steady (impulsively
    /// started) motion.
    pub reduced_frequency: f64,
    /// Plunge `h = h0 sin(omega t)`, positive up, chords.
    pub plunge_amplitude: f64,
    /// Mean pitch angle (nose up), rad.
    pub mean_pitch: f64,
    /// Pitch amplitude, rad: `alpha = mean + a sin(omega t + phase)`.
    pub pitch_amplitude: f64,
    /// Phase by which pitch leads plunge, rad.
    pub pitch_phase: f64,
    /// Pitch axis, chords from the leading edge.
    pub pivot: f64,
}

impl Motion {
    /// Pure plunge `h = h0 sin(omega t)` at reduced frequency `k`, no pitch.
    pub fn plunge(reduced_frequency: f64, plunge_amplitude: f64) -> Self {
        Self {
            reduced_frequency,
            plunge_amplitude,
            mean_pitch: 0.0,
            pitch_amplitude: 0.0,
            pitch_phase: 0.0,
            pivot: 0.25,
        }
    }

    /// A steady plate at `alpha` (rad), started impulsively at t = 0.
    pub fn steady(alpha: f64) -> Self {
        Self {
            mean_pitch: alpha,
            ..Self::plunge(0.0, 0.0)
        }
    }

    /// `(h, h', alpha, alpha')` at time `t` (chords travelled).
    pub fn at(&self, t: f64) -> (f64, f64, f64, f64) {
        let w = 2.0 * self.reduced_frequency;
        let (s, c) = (w * t).sin_cos();
        let (sp, cp) = (w * t + self.pitch_phase).sin_cos();
        (
            self.plunge_amplitude * s,
            self.plunge_amplitude * w * c,
            self.mean_pitch + self.pitch_amplitude * sp,
            self.pitch_amplitude * w * cp,
        )
    }
}

/// The motion of one spanwise section of a wing flapping about a root
/// axis (the 2D evaluation of the kinematic optimization): the flapping
/// angle `phi = mean + amplitude cos(omega t)` turns the section, at
/// `radius` chords from the axis, about the stroke-plane normal `(sin b,
/// 0, cos b)` (axes of [`crate::aeroelastic::kinematics`]), so in the
/// section's plane it plunges by `r (sin phi - sin mean) sin b` and surges
/// downstream by `-r (sin phi - sin mean) cos b`: a vertical stroke plane
/// (b = 90°) is pure plunge, an inclined one adds a fore-and-aft motion
/// that changes the speed of the air over the section. Chords, radians,
/// chords travelled (`c = U = 1`); no pitch (a section's twist comes from
/// the wing's deformation, given as a camber history).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SectionFlapping {
    /// Reduced frequency `k = omega c / (2 U)`.
    pub reduced_frequency: f64,
    /// Distance of the section from the flapping axis, chords.
    pub radius: f64,
    /// Flapping amplitude, rad.
    pub amplitude: f64,
    /// Mean flapping angle, rad.
    pub mean_angle: f64,
    /// Stroke-plane inclination from the horizontal, rad.
    pub stroke_plane: f64,
}

impl SectionFlapping {
    /// `(x, x', h, h')`: surge (downstream) and plunge (up) and their
    /// rates at time `t` (chords, chords travelled).
    pub fn at(&self, t: f64) -> (f64, f64, f64, f64) {
        let w = 2.0 * self.reduced_frequency;
        let (s, c) = (w * t).sin_cos();
        let phi = self.mean_angle + self.amplitude * c;
        let phi_dot = -self.amplitude * w * s;
        let sweep = self.radius * (phi.sin() - self.mean_angle.sin());
        let sweep_dot = self.radius * phi.cos() * phi_dot;
        let (sb, cb) = self.stroke_plane.sin_cos();
        (-sweep * cb, -sweep_dot * cb, sweep * sb, sweep_dot * sb)
    }

    /// `(x'', h'')`: the accelerations of the surge and the plunge of
    /// [`Self::at`] at time `t`.
    pub fn acceleration(&self, t: f64) -> (f64, f64) {
        let w = 2.0 * self.reduced_frequency;
        let (s, c) = (w * t).sin_cos();
        let phi = self.mean_angle + self.amplitude * c;
        let (phi_dot, phi_ddot) = (-self.amplitude * w * s, -self.amplitude * w * w * c);
        let sweep_ddot = self.radius * (phi.cos() * phi_ddot - phi.sin() * phi_dot * phi_dot);
        let (sb, cb) = self.stroke_plane.sin_cos();
        (-sweep_ddot * cb, sweep_ddot * sb)
    }
}

/// Eldredge's canonical pitch-up, hold, pitch-down manoeuvre (Eldredge, Wang
/// & Ol 2009, AIAA 2009-3687; the motion of the LDVM paper's ramp cases,
/// Ramesh et al. 2014, J. Fluid Mech. 751, section 4):
/// `alpha(t) = A G(t) / max G`,
/// `G = ln[cosh a(t - t1) cosh a(t - t4) / (cosh a(t - t2) cosh a(t - t3))]`
/// with `t2 = t1 + A / (2K)` (the pitch rate `K = alpha' c / (2U)`),
/// a hold `t3 - t2 = pi A / (4K) - A / (2K)` and the return `t4 = t3 + A / (2K)`;
/// `a` sets how sharp the corners are. Times in chords travelled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PitchRamp {
    /// Amplitude `A`, rad.
    pub amplitude: f64,
    /// Reduced pitch rate `K = alpha' c / (2 U)`.
    pub pitch_rate: f64,
    /// Corner sharpness `a`.
    pub smoothing: f64,
    /// Start of the ramp `t1`, chords travelled.
    pub start: f64,
}

/// `ln cosh x` without overflow.
fn ln_cosh(x: f64) -> f64 {
    let x = x.abs();
    x + (-2.0 * x).exp().ln_1p() - std::f64::consts::LN_2
}

impl PitchRamp {
    /// Corner times `t1..t4`.
    fn corners(&self) -> [f64; 4] {
        let ramp = self.amplitude.abs() / (2.0 * self.pitch_rate);
        let t1 = self.start;
        let t2 = t1 + ramp;
        let t3 = t2 + std::f64::consts::PI * self.amplitude.abs() / (4.0 * self.pitch_rate) - ramp;
        [t1, t2, t3, t3 + ramp]
    }

    fn g(&self, t: f64) -> f64 {
        let [t1, t2, t3, t4] = self.corners();
        let a = self.smoothing;
        ln_cosh(a * (t - t1)) + ln_cosh(a * (t - t4))
            - ln_cosh(a * (t - t2))
            - ln_cosh(a * (t - t3))
    }

    /// `(alpha, alpha')` at time `t`; the peak of `G` is mid-hold by symmetry.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let [t1, t2, t3, t4] = self.corners();
        let scale = self.amplitude / self.g(0.5 * (t2 + t3));
        let a = self.smoothing;
        let rate = a
            * ((a * (t - t1)).tanh() + (a * (t - t4)).tanh()
                - (a * (t - t2)).tanh()
                - (a * (t - t3)).tanh());
        (scale * self.g(t), scale * rate)
    }

    /// `alpha''` at time `t` (rad per chord travelled squared), the
    /// derivative of [`Self::at`]'s rate: `a² Σ ± sech²`.
    pub fn acceleration(&self, t: f64) -> f64 {
        let [t1, t2, t3, t4] = self.corners();
        let scale = self.amplitude / self.g(0.5 * (t2 + t3));
        let a = self.smoothing;
        let sech2 = |x: f64| 1.0 / (a * x).cosh().powi(2);
        scale * a * a * (sech2(t - t1) + sech2(t - t4) - sech2(t - t2) - sech2(t - t3))
    }

    /// End of the return, `t4`, chords travelled.
    pub fn end(&self) -> f64 {
        self.corners()[3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ramp rises at the nominal rate 2K mid-ramp, holds at A, returns
    /// to 0, and its rate is the derivative of its angle.
    #[test]
    fn pitch_ramp_shape_and_rate() {
        let r = PitchRamp {
            amplitude: 25f64.to_radians(),
            pitch_rate: 0.11,
            smoothing: 11.0,
            start: 1.0,
        };
        let [t1, t2, t3, t4] = r.corners();
        assert!(r.at(0.0).0.abs() < 1e-6 && r.at(t4 + 1.0).0.abs() < 1e-6);
        assert!((r.at(0.5 * (t2 + t3)).0 - r.amplitude).abs() < 1e-12);
        assert!(
            (r.at(0.5 * (t1 + t2)).1 - 0.22).abs() < 0.01,
            "{:?}",
            r.at(0.5 * (t1 + t2))
        );
        for k in 0..100 {
            let t = k as f64 * 0.07;
            let d = (r.at(t + 1e-6).0 - r.at(t - 1e-6).0) / 2e-6;
            assert!((d - r.at(t).1).abs() < 1e-6, "{t}");
            let dd = (r.at(t + 1e-6).1 - r.at(t - 1e-6).1) / 2e-6;
            assert!((dd - r.acceleration(t)).abs() < 1e-5, "{t}");
        }
    }
}
