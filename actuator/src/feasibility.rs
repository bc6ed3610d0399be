//! Can the actuator fly a harmonic flapping demand? The steady-state torque,
//! current and terminal voltage over one cycle, from the plant's own
//! equations ([`crate::plant`]) run backwards, against what the motor, the
//! battery and the flight controller allow; and, when the demand is too
//! much, the nearest kinematics that are not.
//!
//! ## Inverse dynamics (steady state, one cycle)
//! The wing follows `phi(t) = phi_0 + A sin(w t)`, `w = 2 pi f`. With `J =
//! J_wing + N^2 J_rotor` and the regularized friction sign `s(phi')` of the
//! plant, the torque the gearbox must deliver at the flapping axis is
//! `T = J phi'' + k phi + c_a phi'|phi'| + N^2 b phi' + N T_c s`.
//! The gearbox passes `u - (1 - eta)|u| s` of the motor's axis torque
//! `u = N K_t i`; inverted (it is increasing in `u`, so `u` has the sign of
//! `T`): `u = T / (1 - (1 - eta) s)` for `T >= 0`, `u = T / (1 + (1 - eta) s)`
//! for `T < 0` (driving through the gearbox costs `1/eta`; back-driven, the
//! loss helps). Then
//! - current `i = u / (N K_t)`, motor torque `K_t i` (motor shaft),
//! - terminal voltage `V = R i + L di/dt + K_t N phi'` (`di/dt` by a central
//!   difference over one of [`SAMPLES_PER_CYCLE`] steps: it spreads the
//!   friction sign change over a step, as the current loop does; the
//!   inductive term is small: `L/R = 40 us` against a ~90 ms wingbeat),
//! - available voltage: the bridge applies `d (V_b - R_b d i)` for duty `d`
//!   (averaged bridge, battery sag `R_b` times the supply current `d i`);
//!   the most it reaches in the direction `sigma` of `V` is
//!   `max_{0 <= d <= 1} d V_b - d^2 R_b sigma i` (at `d = 1` unless the sag
//!   is huge).
//!
//! ## Limits (see [`ActuatorLimits`])
//! - **Current**: the flight controller's current limit
//!   (`ParamId::CurrentLimit`, 1.5 A by default). The firmware clamps the
//!   duty so that the current predicted from the back-EMF,
//!   `(d V - K_t N phi')/R`, stays within it: a demand above it is not
//!   flown. (The over-current trip, 3 A, is above it and only catches
//!   faults.)
//! - **Torque**: the motor's stall torque on this battery, `K_t V_b / (R +
//!   R_b)` at the motor shaft. The model has no torque saturation of its
//!   own (`torque = K_t i`); the stall torque is the most the motor makes
//!   from this supply whenever it is driving (current with the rate: the
//!   back-EMF only lowers it), i.e. its peak-torque rating here. Back-driven,
//!   the back-EMF could push more current; the check does not count on that
//!   (it is conservative by at most `I_max / I_stall` there). Torque and
//!   current are both `|i|` scaled: with the default plant the stall current
//!   (1.44 A) is below the controller's 1.5 A, so torque binds first;
//!   current binds on a stiffer supply or a lowered current limit.
//! - **Voltage**: the needed terminal voltage against the available one at
//!   every instant (so it includes the back-EMF at that frequency and
//!   amplitude and the battery sag at that current).
//!
//! A demand is feasible when every margin `1 - value / limit` is at least
//! the [`ActuatorLimits::reserve`] kept for the feedback loop.
//!
//! ## Against the flight controller flying the plant (hil-sim)
//! `hil-sim/tests/check_agrees.rs` flies 18 demands with the firmware core
//! on the default plant: every demand judged feasible is flown (amplitude
//! within 2%, duty never saturated, under the current limit); every one
//! beyond a limit without the reserve saturates the duty (23% to 78% of
//! the cycle); where it flies, this check's peak current and voltage are
//! within 7.6% and 5.9% of the flown ones (below them: the encoder's
//! quantization through the rate observer, and the gearbox loss switching
//! at the stroke reversal, which the controller's model leaves to its
//! feedback). With ideal sensors and a lossless transmission they agree
//! within 0.25%: the check and the plant are one set of equations.
//!
//! Issue 21 found 1.58 A and 9.58 V here against a 1.21 A peak and a
//! -0.03% amplitude error in `hil-sim run` at 13 Hz, +-40 deg, mean -10
//! deg. The check is right: at its peak (the fastest downstroke, back-EMF
//! 1.69 V) following the sinusoid needs `5 ohm * 1.577 A + 1.69 V = 9.58
//! V` against the 7.16 V the bridge reaches, and full duty drives at most
//! `(7.4 - 1.69) / 5.15 = 1.11 A` there. hil-sim's duty sat at +-1 for 35%
//! of the cycle; its amplitude error is that of the fundamental, which the
//! per-stroke loop restores by overdriving (a square wave at 7.16 V carries
//! `4/pi * 7.16 = 9.12 V` of fundamental, more than the needed voltage's
//! 7.62 V), so the motion carried harmonics (RMS tracking error 3.55%) and
//! the current stayed at what full duty gives (1.21 A). hil-sim's report
//! now gives the steady-state peaks and the share of time the duty is
//! saturated (`duty_saturated_pct`).
//!
//! Imports the parameters and the plant's friction regularization of this
//! crate, and the device's parameters and envelope from `fwav-protocol`.

use std::f64::consts::PI;
use std::fmt;

use fwav_protocol::ParamId;
use fwav_settings::Shown;
use serde::Serialize;

use crate::params::{ConfigError, PlantParams};
use crate::plant::FRICTION_SLOPE;

pub mod nearest;
pub use nearest::{nearest_feasible, within_envelope, Alternative, Change, NearestFeasible};

/// Samples per flapping cycle of the steady-state analysis.
pub const SAMPLES_PER_CYCLE: usize = 1024;

/// Default [`ActuatorLimits::reserve`]: 10% of each limit is left to what
/// the steady-state analysis does not have. In hil-sim the firmware's
/// feedback rides on the smooth demand: its response to encoder
/// quantization (through the rate observer) and to the gearbox loss
/// switching at the stroke reversal (absent from its model) raised the
/// peak current by up to 7.6% and the peak voltage by up to 5.9% over the
/// analytic ones (15 Hz, +-20 deg; `hil-sim/tests/check_agrees.rs`). On
/// hardware the battery's state of charge and the motor constants' spread
/// take more. (Beyond zero margin hil-sim saturates the duty; it may still
/// reach the fundamental amplitude of the profile by distorting the motion:
/// see the module docs.)
pub const DEFAULT_RESERVE: f64 = 0.1;

/// Why a feasibility question could not be answered.
#[derive(Debug, thiserror::Error)]
pub enum FeasibilityError {
    /// The plant parameters are out of range.
    #[error("plant parameters: {0}")]
    Params(#[from] ConfigError),
    /// A field of the demand is out of range or not a number.
    #[error("flapping demand: {field} = {} is outside {range}", Shown(*value))]
    Demand {
        /// The field, e.g. `frequency_hz`.
        field: &'static str,
        /// Its value.
        value: f64,
        /// The allowed range, for people.
        range: &'static str,
    },
    /// A field of the actuator limits or of the device envelope is out of
    /// range or not a number.
    #[error("limits: {field} = {} is outside {range}", Shown(*value))]
    Limits {
        /// The field, e.g. `current_a`.
        field: &'static str,
        /// Its value.
        value: f64,
        /// The allowed range, for people.
        range: &'static str,
    },
    /// Not even the smallest amplitude nor the lowest frequency of the
    /// envelope is feasible (e.g. the mean angle alone needs too much
    /// spring torque).
    #[error("nothing near {demand} is feasible: at zero amplitude the {limiting} is at {value:.4} of its limit {limit:.4}")]
    NothingFeasible {
        /// The demand brought into the envelope.
        demand: FlappingDemand,
        /// What limits even at zero amplitude.
        limiting: Quantity,
        /// Its value there (N m, A or V).
        value: f64,
        /// Its limit (N m, A or V).
        limit: f64,
    },
}

/// A harmonic flapping demand `phi(t) = mean + amplitude sin(2 pi f t)`
/// (degrees, as a person and the profile document write them).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct FlappingDemand {
    /// Flapping frequency, Hz.
    pub frequency_hz: f64,
    /// Peak amplitude (half the stroke), deg.
    pub amplitude_deg: f64,
    /// Mean flapping angle, deg.
    pub mean_deg: f64,
}

impl fmt::Display for FlappingDemand {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:.3} Hz, +-{:.3} deg, mean {:.3} deg",
            self.frequency_hz, self.amplitude_deg, self.mean_deg
        )
    }
}

impl FlappingDemand {
    /// Checks the ranges: frequency in (0, 1000] Hz, amplitude in [0, 180]
    /// deg, |mean| <= 180 deg, all finite.
    pub fn validate(&self) -> Result<(), FeasibilityError> {
        let checks: [(&'static str, f64, bool, &'static str); 3] = [
            (
                "frequency_hz",
                self.frequency_hz,
                self.frequency_hz > 0.0 && self.frequency_hz <= 1000.0,
                "(0, 1000] Hz",
            ),
            (
                "amplitude_deg",
                self.amplitude_deg,
                self.amplitude_deg >= 0.0 && self.amplitude_deg <= 180.0,
                "[0, 180] deg",
            ),
            (
                "mean_deg",
                self.mean_deg,
                self.mean_deg.abs() <= 180.0,
                "[-180, 180] deg",
            ),
        ];
        for (field, value, ok, range) in checks {
            // `ok` is false for NaN.
            if !ok {
                return Err(FeasibilityError::Demand {
                    field,
                    value,
                    range,
                });
            }
        }
        Ok(())
    }
}

/// What the flight controller allows beyond the plant's physics.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ActuatorLimits {
    /// The controller's current limit, A (`ParamId::CurrentLimit`).
    pub current_a: f64,
    /// Fraction of every limit kept free for the feedback loop, in [0, 1):
    /// feasible means every margin `1 - value / limit >= reserve`.
    pub reserve: f64,
}

impl Default for ActuatorLimits {
    fn default() -> Self {
        Self::firmware_default()
    }
}

impl ActuatorLimits {
    /// The firmware's default current limit (the protocol's default of
    /// `ParamId::CurrentLimit`, what the flight controller boots with) and
    /// [`DEFAULT_RESERVE`].
    pub fn firmware_default() -> Self {
        Self {
            current_a: f64::from(ParamId::CurrentLimit.info().default),
            reserve: DEFAULT_RESERVE,
        }
    }

    /// Checks: current limit positive and finite, reserve in [0, 1).
    pub fn validate(&self) -> Result<(), FeasibilityError> {
        if !(self.current_a > 0.0 && self.current_a.is_finite()) {
            return Err(FeasibilityError::Limits {
                field: "current_a",
                value: self.current_a,
                range: "(0, inf) A",
            });
        }
        if !(self.reserve >= 0.0 && self.reserve < 1.0) {
            return Err(FeasibilityError::Limits {
                field: "reserve",
                value: self.reserve,
                range: "[0, 1)",
            });
        }
        Ok(())
    }
}

/// The motor's stall torque on the plant's battery, `K_t V_b / (R + R_b)`,
/// N m at the motor shaft: the torque limit of the check.
pub fn stall_torque_nm(p: &PlantParams) -> f64 {
    p.motor.torque_constant_nm_per_a * p.supply.battery_v
        / (p.motor.resistance_ohm + p.supply.internal_resistance_ohm)
}

/// The actuator's state at one instant of the steady cycle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct DemandSample {
    /// Time from the cycle's start (`phi = mean`, rising), s.
    pub time_s: f64,
    /// Flapping angle, rad.
    pub angle_rad: f64,
    /// Flapping rate, rad/s.
    pub rate_rad_s: f64,
    /// Torque the gearbox delivers at the flapping axis, N m.
    pub load_torque_nm: f64,
    /// Motor current, A.
    pub current_a: f64,
    /// Motor torque `K_t i` at the motor shaft, N m.
    pub motor_torque_nm: f64,
    /// Terminal voltage needed, `R i + L di/dt + K_t N phi'`, V.
    pub voltage_v: f64,
    /// Largest terminal voltage the bridge reaches in that direction at
    /// this current (battery sag included), V (> 0).
    pub available_v: f64,
}

/// The steady cycle of `demand` on plant `p`, [`SAMPLES_PER_CYCLE`] samples.
pub fn demand_waveform(
    p: &PlantParams,
    demand: &FlappingDemand,
) -> Result<Vec<DemandSample>, FeasibilityError> {
    // The demand first: a vehicle's plant carries a spring tuned to the
    // demand's frequency, which a NaN frequency makes NaN, so the plant's
    // check would name the spring for the frequency's fault.
    demand.validate()?;
    p.validate()?;
    let m = SAMPLES_PER_CYCLE;
    let w = 2.0 * PI * demand.frequency_hz;
    let a = demand.amplitude_deg.to_radians();
    let mean = demand.mean_deg.to_radians();
    let n = p.transmission.gear_ratio;
    let kt = p.motor.torque_constant_nm_per_a;
    let kt_n = n * kt;
    let inertia = p.wing.inertia_kg_m2 + n * n * p.motor.rotor_inertia_kg_m2;
    let aero = p.wing.aero_damping();
    let loss = 1.0 - p.transmission.efficiency;
    let dt = 1.0 / (demand.frequency_hz * m as f64);
    // Kinematics and current at each sample.
    let motion: Vec<(f64, f64, f64, f64)> = (0..m)
        .map(|k| {
            let (sin, cos) = (w * k as f64 * dt).sin_cos();
            let angle = mean + a * sin;
            let rate = a * w * cos;
            let accel = -a * w * w * sin;
            let s = (rate * FRICTION_SLOPE).clamp(-1.0, 1.0);
            let torque = inertia * accel
                + p.transmission.spring_nm_per_rad * angle
                + aero * rate * rate.abs()
                + n * n * p.motor.viscous_friction_nms_per_rad * rate
                + n * p.motor.coulomb_friction_nm * s;
            let u = if torque >= 0.0 {
                torque / (1.0 - loss * s)
            } else {
                torque / (1.0 + loss * s)
            };
            (angle, rate, torque, u / kt_n)
        })
        .collect();
    let (r, l) = (p.motor.resistance_ohm, p.motor.inductance_h);
    let (vb, rb) = (p.supply.battery_v, p.supply.internal_resistance_ohm);
    Ok((0..m)
        .map(|k| {
            let (angle, rate, torque, i) = motion[k];
            let di = (motion[(k + 1) % m].3 - motion[(k + m - 1) % m].3) / (2.0 * dt);
            let voltage = r * i + l * di + kt_n * rate;
            let sigma = if voltage >= 0.0 { 1.0 } else { -1.0 };
            // max over d in [0, 1] of d V_b - d^2 x.
            let x = rb * sigma * i;
            let d = if x > 0.0 {
                (vb / (2.0 * x)).min(1.0)
            } else {
                1.0
            };
            DemandSample {
                time_s: k as f64 * dt,
                angle_rad: angle,
                rate_rad_s: rate,
                load_torque_nm: torque,
                current_a: i,
                motor_torque_nm: kt * i,
                voltage_v: voltage,
                available_v: d * vb - d * d * x,
            }
        })
        .collect())
}

/// Peaks of the steady cycle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ActuatorDemand {
    /// Largest |motor torque| at the motor shaft, N m.
    pub peak_motor_torque_nm: f64,
    /// Largest |current|, A.
    pub peak_current_a: f64,
    /// RMS current over the cycle (winding heating), A.
    pub rms_current_a: f64,
    /// Largest |terminal voltage| needed, V.
    pub peak_voltage_v: f64,
    /// At the instant of least voltage headroom: |voltage| needed, V.
    pub voltage_needed_v: f64,
    /// At that instant: voltage available, V.
    pub voltage_available_v: f64,
}

/// The peaks of `demand`'s steady cycle on plant `p` (see the module docs
/// for the equations).
pub fn actuator_demand(
    p: &PlantParams,
    demand: &FlappingDemand,
) -> Result<ActuatorDemand, FeasibilityError> {
    let samples = demand_waveform(p, demand)?;
    let mut out = ActuatorDemand {
        peak_motor_torque_nm: 0.0,
        peak_current_a: 0.0,
        rms_current_a: 0.0,
        peak_voltage_v: 0.0,
        voltage_needed_v: 0.0,
        voltage_available_v: p.supply.battery_v,
    };
    let mut worst = f64::NEG_INFINITY;
    let mut square = 0.0;
    for s in &samples {
        out.peak_motor_torque_nm = out.peak_motor_torque_nm.max(s.motor_torque_nm.abs());
        out.peak_current_a = out.peak_current_a.max(s.current_a.abs());
        out.peak_voltage_v = out.peak_voltage_v.max(s.voltage_v.abs());
        square += s.current_a * s.current_a;
        let ratio = s.voltage_v.abs() / s.available_v;
        if ratio > worst {
            worst = ratio;
            out.voltage_needed_v = s.voltage_v.abs();
            out.voltage_available_v = s.available_v;
        }
    }
    out.rms_current_a = (square / samples.len() as f64).sqrt();
    Ok(out)
}

/// A limited quantity of the actuator.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// Motor torque at the motor shaft, N m (limit: stall torque).
    Torque,
    /// Motor current, A (limit: the controller's current limit).
    Current,
    /// Terminal voltage, V (limit: the bridge's reach on the sagging bus).
    Voltage,
}

impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Torque => "motor torque",
            Self::Current => "motor current",
            Self::Voltage => "terminal voltage",
        })
    }
}

/// One quantity against its limit.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Margin {
    /// Which.
    pub quantity: Quantity,
    /// The demand's peak (voltage: at the instant of least headroom), in
    /// the quantity's unit (N m, A, V).
    pub value: f64,
    /// Its limit there, same unit.
    pub limit: f64,
    /// `1 - value / limit`: the unused fraction of the limit (negative:
    /// over it).
    pub margin: f64,
}

impl Quantity {
    /// The unit of its values: `N m`, `A` or `V`.
    pub fn unit(&self) -> &'static str {
        match self {
            Self::Torque => "N m",
            Self::Current => "A",
            Self::Voltage => "V",
        }
    }
}

impl fmt::Display for Margin {
    /// E.g. `terminal voltage 3.876 V of 7.316 V (margin 47.0%)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let unit = self.quantity.unit();
        write!(
            f,
            "{} {:.4} {unit} of {:.4} {unit} (margin {:.1}%)",
            self.quantity,
            self.value,
            self.limit,
            100.0 * self.margin
        )
    }
}

impl Margin {
    fn new(quantity: Quantity, value: f64, limit: f64) -> Self {
        Self {
            quantity,
            value,
            limit,
            margin: 1.0 - value / limit,
        }
    }
}

/// The verdict on one demand.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Feasibility {
    /// The demand judged.
    pub demand: FlappingDemand,
    /// Every margin is at least `reserve`.
    pub feasible: bool,
    /// The reserve asked for ([`ActuatorLimits::reserve`]).
    pub reserve: f64,
    /// Motor torque against the stall torque.
    pub torque: Margin,
    /// Current against the controller's limit.
    pub current: Margin,
    /// Terminal voltage against the bridge's reach.
    pub voltage: Margin,
    /// The quantity with the smallest margin (the one that limits, or would
    /// limit first).
    pub limiting: Margin,
    /// The peaks behind the margins.
    pub peaks: ActuatorDemand,
}

impl Feasibility {
    /// The three margins: torque, current, voltage.
    pub fn margins(&self) -> [Margin; 3] {
        [self.torque, self.current, self.voltage]
    }
}

/// Judges `demand` on plant `p` under `limits` (equations and limits in the
/// module docs).
pub fn check(
    p: &PlantParams,
    limits: &ActuatorLimits,
    demand: &FlappingDemand,
) -> Result<Feasibility, FeasibilityError> {
    limits.validate()?;
    let peaks = actuator_demand(p, demand)?;
    let torque = Margin::new(
        Quantity::Torque,
        peaks.peak_motor_torque_nm,
        stall_torque_nm(p),
    );
    let current = Margin::new(Quantity::Current, peaks.peak_current_a, limits.current_a);
    let voltage = Margin::new(
        Quantity::Voltage,
        peaks.voltage_needed_v,
        peaks.voltage_available_v,
    );
    let mut limiting = torque;
    for m in [current, voltage] {
        if m.margin < limiting.margin {
            limiting = m;
        }
    }
    Ok(Feasibility {
        demand: *demand,
        feasible: limiting.margin >= limits.reserve,
        reserve: limits.reserve,
        torque,
        current,
        voltage,
        limiting,
        peaks,
    })
}
