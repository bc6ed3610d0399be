//! The reference generator: the flapping angle the wing should follow, with
//! its rate and acceleration (for feedforward), from a validated [`Profile`].
//!
//! `phi_ref = mean + A sin(theta(p))`: the cycle phase `p` in [0, 1) advances
//! at the frequency `f` and is never reset, so the motion is continuous across
//! segment changes; `theta` warps `p` for split cycles (downstroke in a
//! fraction `d` of the period, `p = 0` at the top of the stroke):
//! `theta = pi/2 + pi p/d` on the downstroke, `3pi/2 + pi (p-d)/(1-d)` on the
//! upstroke. Frequency, amplitude, mean and `d` move between segments along a
//! cubic smoothstep over the segment's ramp time, so angle and rate are
//! continuous (see `fwav_protocol::profile`).

use core::f32::consts::{FRAC_PI_2, PI};

use fwav_protocol::{EndAction, Limits, Profile, Segment, RAMP_PEAK_RATE_FACTOR};

/// The quantities a profile ramps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kinematics {
    /// Frequency, Hz.
    pub frequency_hz: f32,
    /// Peak amplitude, rad.
    pub amplitude_rad: f32,
    /// Mean angle, rad.
    pub mean_rad: f32,
    /// Downstroke fraction of the period.
    pub downstroke_fraction: f32,
}

impl Kinematics {
    /// All zero (the derivative of a held value).
    pub const ZERO: Self = Self {
        frequency_hz: 0.0,
        amplitude_rad: 0.0,
        mean_rad: 0.0,
        downstroke_fraction: 0.0,
    };

    /// At rest at frequency `f`: no amplitude, zero mean, symmetric.
    pub const fn rest(frequency_hz: f32) -> Self {
        Self {
            frequency_hz,
            amplitude_rad: 0.0,
            mean_rad: 0.0,
            downstroke_fraction: 0.5,
        }
    }

    fn of(s: &Segment) -> Self {
        Self {
            frequency_hz: s.frequency_hz,
            amplitude_rad: s.amplitude_rad,
            mean_rad: s.mean_rad,
            downstroke_fraction: s.downstroke_fraction,
        }
    }

    fn lerp(&self, to: &Self, w: f32) -> Self {
        let l = |a: f32, b: f32| a + (b - a) * w;
        Self {
            frequency_hz: l(self.frequency_hz, to.frequency_hz),
            amplitude_rad: l(self.amplitude_rad, to.amplitude_rad),
            mean_rad: l(self.mean_rad, to.mean_rad),
            downstroke_fraction: l(self.downstroke_fraction, to.downstroke_fraction),
        }
    }

    fn sub(self, o: &Self) -> Self {
        Self {
            frequency_hz: self.frequency_hz - o.frequency_hz,
            amplitude_rad: self.amplitude_rad - o.amplitude_rad,
            mean_rad: self.mean_rad - o.mean_rad,
            downstroke_fraction: self.downstroke_fraction - o.downstroke_fraction,
        }
    }

    fn scaled(self, k: f32) -> Self {
        Self {
            frequency_hz: self.frequency_hz * k,
            amplitude_rad: self.amplitude_rad * k,
            mean_rad: self.mean_rad * k,
            downstroke_fraction: self.downstroke_fraction * k,
        }
    }
}

/// The reference at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reference {
    /// Angle, rad.
    pub angle: f32,
    /// Rate, rad/s.
    pub rate: f32,
    /// Acceleration, rad/s^2.
    pub accel: f32,
}

/// The generator's state at one instant, enough to evaluate the reference
/// with a phase shift and amplitude scale (the controller's per-stroke
/// corrections).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Waveform {
    /// Cycle phase in [0, 1).
    pub phase: f32,
    /// Current kinematics.
    pub kin: Kinematics,
    /// Their time derivatives (per s).
    pub kin_rate: Kinematics,
    /// Their second time derivatives (per s^2).
    pub kin_accel: Kinematics,
}

impl Waveform {
    /// Warped angle `theta(p)` and `d theta / d p` for downstroke fraction `d`.
    pub fn theta(phase: f32, d: f32) -> (f32, f32) {
        if phase < d {
            (FRAC_PI_2 + PI * phase / d, PI / d)
        } else {
            (1.5 * PI + PI * (phase - d) / (1.0 - d), PI / (1.0 - d))
        }
    }

    /// `theta` and its first two time derivatives, with `p' = f` and the
    /// split cycle `d` itself moving during a ramp (`d'`, `d''`).
    ///
    /// Downstroke `theta = pi/2 + pi p/d`:
    /// `theta' = pi f/d - pi p d'/d^2`,
    /// `theta'' = pi f'/d - 2 pi f d'/d^2 - pi p d''/d^2 + 2 pi p d'^2/d^3`.
    /// Upstroke `theta = 3pi/2 + pi (p-d)/(1-d)`, with `q = 1 - d`:
    /// `theta' = pi f/q + pi (p-1) d'/q^2`,
    /// `theta'' = pi f'/q + 2 pi f d'/q^2 + pi (p-1) d''/q^2 + 2 pi (p-1) d'^2/q^3`.
    fn theta_with_rates(&self, p: f32) -> (f32, f32, f32) {
        let (f, f1) = (self.kin.frequency_hz, self.kin_rate.frequency_hz);
        let (d, d1, d2) = (
            self.kin.downstroke_fraction,
            self.kin_rate.downstroke_fraction,
            self.kin_accel.downstroke_fraction,
        );
        let (theta, _) = Self::theta(p, d);
        if p < d {
            let rate = PI * f / d - PI * p * d1 / (d * d);
            let accel = PI * f1 / d - 2.0 * PI * f * d1 / (d * d) - PI * p * d2 / (d * d)
                + 2.0 * PI * p * d1 * d1 / (d * d * d);
            (theta, rate, accel)
        } else {
            let q = 1.0 - d;
            let rate = PI * f / q + PI * (p - 1.0) * d1 / (q * q);
            let accel = PI * f1 / q
                + 2.0 * PI * f * d1 / (q * q)
                + PI * (p - 1.0) * d2 / (q * q)
                + 2.0 * PI * (p - 1.0) * d1 * d1 / (q * q * q);
            (theta, rate, accel)
        }
    }

    /// The reference with the phase advanced by `phase_shift` cycles and the
    /// amplitude multiplied by `amplitude_scale`.
    pub fn evaluate(&self, phase_shift: f32, amplitude_scale: f32) -> Reference {
        let (theta, w, w_dot) = self.theta_with_rates(wrap(self.phase + phase_shift));
        let (s, c) = crate::trig::sincos(theta);
        let a = self.kin.amplitude_rad * amplitude_scale;
        let a_dot = self.kin_rate.amplitude_rad * amplitude_scale;
        let a_ddot = self.kin_accel.amplitude_rad * amplitude_scale;
        Reference {
            angle: self.kin.mean_rad + a * s,
            rate: self.kin_rate.mean_rad + a_dot * s + a * c * w,
            accel: self.kin_accel.mean_rad + a_ddot * s + 2.0 * a_dot * c * w - a * s * w * w
                + a * c * w_dot,
        }
    }
}

/// `x` wrapped into [0, 1).
pub fn wrap(x: f32) -> f32 {
    let w = x - libm::floorf(x);
    // floorf can leave exactly 1.0 for tiny negative x.
    if w >= 1.0 {
        0.0
    } else {
        w
    }
}

/// A smoothstep transition between two kinematics.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Ramp {
    from: Kinematics,
    to: Kinematics,
    duration: f32,
    /// f64: an f32 clock stops advancing by 100 us steps after ~2000 s.
    elapsed: f64,
}

impl Ramp {
    fn hold(k: Kinematics) -> Self {
        Self {
            from: k,
            to: k,
            duration: 0.0,
            elapsed: 0.0,
        }
    }

    /// Value, rate and acceleration now.
    fn sample(&self) -> (Kinematics, Kinematics, Kinematics) {
        if self.done() {
            return (self.to, Kinematics::ZERO, Kinematics::ZERO);
        }
        let x = (self.elapsed / f64::from(self.duration)) as f32;
        let delta = self.to.sub(&self.from);
        let w = x * x * (3.0 - 2.0 * x);
        let dw = 6.0 * x * (1.0 - x) / self.duration;
        let ddw = (6.0 - 12.0 * x) / (self.duration * self.duration);
        (
            self.from.lerp(&self.to, w),
            delta.scaled(dw),
            delta.scaled(ddw),
        )
    }

    fn done(&self) -> bool {
        self.duration <= 0.0 || self.elapsed >= f64::from(self.duration)
    }
}

/// What the generator is doing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Not flapping.
    Idle,
    /// Flying segment `index` of the profile.
    Segment(usize),
    /// Ramping to rest; then idle.
    Stopping,
}

/// Turns a profile into a continuous reference, one control step at a time.
#[derive(Clone, Debug)]
pub struct ReferenceGenerator {
    profile: Profile,
    limits: Limits,
    /// The last segment is held for ever ([`EndAction::Hold`]).
    holding: bool,
    /// Went idle because the profile ended with [`EndAction::Stop`].
    ended: bool,
    mode: Mode,
    ramp: Ramp,
    /// Time spent in the current segment, s (f64, as [`Ramp::elapsed`]).
    in_segment: f64,
    phase: f32,
}

impl Default for ReferenceGenerator {
    fn default() -> Self {
        Self::new()
    }
}

impl ReferenceGenerator {
    /// An idle generator.
    pub fn new() -> Self {
        Self {
            profile: Profile::default(),
            limits: Limits::REFERENCE_FWAV,
            holding: false,
            ended: false,
            mode: Mode::Idle,
            ramp: Ramp::hold(Kinematics::rest(1.0)),
            in_segment: 0.0,
            phase: 0.0,
        }
    }

    /// Current mode.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// True unless idle.
    pub fn is_active(&self) -> bool {
        self.mode != Mode::Idle
    }

    /// True once the profile has ended with [`EndAction::Stop`] and the
    /// ramp to rest is done (until the next start or halt).
    pub fn profile_ended(&self) -> bool {
        self.ended && self.mode == Mode::Idle
    }

    /// Index of the segment being flown.
    pub fn active_segment(&self) -> Option<usize> {
        match self.mode {
            Mode::Segment(i) => Some(i),
            _ => None,
        }
    }

    /// Starts `profile` (validated against `limits`) from rest at its first
    /// segment, phase 0 (top of the stroke). An empty profile leaves it idle.
    /// `limits` also sets the slew of [`ReferenceGenerator::stop`].
    pub fn start(&mut self, profile: &Profile, limits: &Limits) {
        let Some(first) = profile.segments.first() else {
            self.mode = Mode::Idle;
            return;
        };
        self.profile = profile.clone();
        self.limits = *limits;
        self.holding = false;
        self.ended = false;
        self.phase = 0.0;
        self.enter_segment(0, Kinematics::rest(first.frequency_hz));
    }

    fn enter_segment(&mut self, index: usize, from: Kinematics) {
        let seg = &self.profile.segments[index];
        self.mode = Mode::Segment(index);
        self.in_segment = 0.0;
        self.ramp = Ramp {
            from,
            to: Kinematics::of(seg),
            duration: seg.ramp_s,
            elapsed: 0.0,
        };
    }

    /// Ramps amplitude and mean to zero at the slew limit, then idles.
    /// Frequency is held so the phase keeps advancing smoothly.
    pub fn stop(&mut self) {
        if matches!(self.mode, Mode::Idle | Mode::Stopping) {
            return;
        }
        let (now, _, _) = self.ramp.sample();
        let change = libm::fmaxf(libm::fabsf(now.amplitude_rad), libm::fabsf(now.mean_rad));
        let duration = RAMP_PEAK_RATE_FACTOR * change / self.limits.max_angle_slew_rad_s;
        self.stop_over(now, duration);
    }

    /// Ramps to rest within one wingbeat of the current frequency (the link
    /// failsafe: faster than the slew limit, as ESCs do on signal loss).
    pub fn stop_within_one_wingbeat(&mut self) {
        if self.mode == Mode::Idle {
            return;
        }
        let (now, _, _) = self.ramp.sample();
        self.stop_over(now, 1.0 / now.frequency_hz);
    }

    fn stop_over(&mut self, now: Kinematics, duration: f32) {
        let rest = Kinematics {
            frequency_hz: now.frequency_hz,
            ..Kinematics::rest(now.frequency_hz)
        };
        self.mode = Mode::Stopping;
        // A NaN or negative duration (corrupt limits) means: stop at once.
        let duration = if duration > 0.0 { duration } else { 0.0 };
        self.ramp = Ramp {
            from: now,
            to: rest,
            duration,
            elapsed: 0.0,
        };
    }

    /// Idles at once (disarm): no ramp.
    pub fn halt(&mut self) {
        self.mode = Mode::Idle;
        self.ended = false;
        let f = self.ramp.to.frequency_hz;
        self.ramp = Ramp::hold(Kinematics::rest(f));
    }

    /// The waveform now (before [`ReferenceGenerator::advance`]).
    pub fn waveform(&self) -> Waveform {
        let (kin, kin_rate, kin_accel) = if self.mode == Mode::Idle {
            (
                Kinematics::rest(self.ramp.to.frequency_hz),
                Kinematics::ZERO,
                Kinematics::ZERO,
            )
        } else {
            self.ramp.sample()
        };
        Waveform {
            phase: self.phase,
            kin,
            kin_rate,
            kin_accel,
        }
    }

    /// Moves time on by `dt` seconds: phase, ramps, segment sequence.
    pub fn advance(&mut self, dt: f32) {
        if self.mode == Mode::Idle {
            return;
        }
        let (now, _, _) = self.ramp.sample();
        self.phase = wrap(self.phase + now.frequency_hz * dt);
        self.ramp.elapsed += f64::from(dt);
        self.in_segment += f64::from(dt);
        match self.mode {
            Mode::Stopping if self.ramp.done() => {
                let ended = self.ended;
                self.halt();
                self.ended = ended;
            }
            Mode::Segment(i)
                if !self.holding
                    && self.in_segment >= f64::from(self.profile.segments[i].duration_s) =>
            {
                let (now, _, _) = self.ramp.sample();
                let next = i + 1;
                if next < self.profile.segments.len() {
                    self.enter_segment(next, now);
                } else {
                    match self.profile.on_end {
                        EndAction::Hold => self.holding = true,
                        EndAction::Repeat => self.enter_segment(0, now),
                        EndAction::Stop => {
                            self.stop();
                            self.ended = true;
                        }
                    }
                }
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests;
