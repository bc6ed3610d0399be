//! The nearest feasible kinematics to a demand the actuator cannot fly.
//!
//! 1. The demand is brought into the device's envelope ([`Limits`]:
//!    frequency range, largest amplitude, |mean|, |mean| + amplitude) by
//!    clamping each variable: outside it the flight controller refuses the
//!    profile whatever the actuator could do.
//! 2. If that is still infeasible ([`super::check`]), two one-variable
//!    reductions from it:
//!    - **by amplitude**: frequency and mean kept, the largest feasible
//!      amplitude in `[0, A]`;
//!    - **by frequency**: amplitude and mean kept, the largest feasible
//!      frequency in `[f_min, f]` of the envelope.
//! 3. The nearest is the one with the smaller relative change, `1 - A'/A`
//!    against `1 - f'/f` (both from the envelope-clamped demand, so they are
//!    comparable as fractions of what was asked); a tie goes to the
//!    amplitude, which keeps the frequency the optimizer chose relative to
//!    the spring's resonance.
//!
//! "Largest feasible" is found by a downward scan of [`SCAN_STEPS`] steps
//! from the demanded value, then [`BISECTIONS`] bisections between the first
//! feasible point and the infeasible one above it. Feasibility need not be
//! monotone in frequency (below the resonance the reactive torque
//! `(k - J w^2) A` falls as `f` rises), so a bisection over the whole range
//! could land on a feasible band below an infeasible one; the scan finds the
//! feasible point closest below the demand to within one step (1/200 of the
//! range), the bisection then the boundary to 2^-40 of a step. The result is
//! always a point that was checked feasible.

use fwav_protocol::Limits;
use serde::Serialize;

use super::{check, ActuatorLimits, Feasibility, FeasibilityError, FlappingDemand};
use crate::params::PlantParams;

/// Points of the downward scan.
pub const SCAN_STEPS: usize = 200;
/// Bisection steps after the scan.
pub const BISECTIONS: usize = 40;
/// Resolution of proposed kinematics, Hz or deg: a found boundary is
/// rounded down to it (if still feasible), a clamped value is a multiple of
/// it; a profile is not flown to better than that.
pub const RESOLUTION: f64 = 0.01;

/// Which variable the nearest feasible kinematics changed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Change {
    /// None: the (envelope-clamped) demand is feasible.
    None,
    /// The amplitude was reduced.
    Amplitude,
    /// The frequency was reduced.
    Frequency,
}

/// A feasible alternative and how far it is from the demand.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Alternative {
    /// Its verdict (feasible) with its margins.
    pub feasibility: Feasibility,
    /// `1 - new / old` of the changed variable (0 if nothing changed).
    pub relative_change: f64,
}

/// The nearest feasible kinematics and the alternatives considered.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct NearestFeasible {
    /// The demand as asked.
    pub requested: FlappingDemand,
    /// The demand clamped into the device's envelope.
    pub within_envelope: FlappingDemand,
    /// The largest feasible amplitude at the demanded frequency and mean
    /// (None when no reduction was needed or none is feasible).
    pub by_amplitude: Option<Alternative>,
    /// The largest feasible frequency at the demanded amplitude and mean
    /// (None when no reduction was needed or none is feasible).
    pub by_frequency: Option<Alternative>,
    /// The one proposed: the smaller relative change.
    pub chosen: Alternative,
    /// What the chosen one changed.
    pub change: Change,
}

impl NearestFeasible {
    /// The proposed kinematics.
    pub fn demand(&self) -> FlappingDemand {
        self.chosen.feasibility.demand
    }

    /// The envelope moved the demand.
    pub fn clamped(&self) -> bool {
        self.requested != self.within_envelope
    }
}

fn envelope_error(field: &'static str, value: f32, range: &'static str) -> FeasibilityError {
    FeasibilityError::Limits {
        field,
        value: f64::from(value),
        range,
    }
}

/// `x` rounded down to a multiple of [`RESOLUTION`].
fn floor_to_resolution(x: f64) -> f64 {
    (x / RESOLUTION).floor() * RESOLUTION
}

/// The largest multiple of [`RESOLUTION`] in `[0, x]` that `fits` (the
/// protocol's own `f32` comparison), or 0.
fn fit_below(x: f64, fits: impl Fn(f64) -> bool) -> f64 {
    let mut steps = (x / RESOLUTION).floor();
    while steps > 0.0 && !fits(steps * RESOLUTION) {
        steps -= 1.0;
    }
    (steps * RESOLUTION).max(0.0)
}

/// Degrees to the `f32` radians of the wire, as the profile document
/// converts them.
fn wire_rad(deg: f64) -> f32 {
    deg.to_radians() as f32
}

/// `demand` clamped into `envelope`: the mean to the largest |mean|, then
/// the amplitude to the smaller of the largest amplitude and the excursion
/// left by the mean, then the frequency to the range. A value that is
/// clamped becomes the largest multiple of [`RESOLUTION`] that the device's
/// own `f32` check accepts (so `45 deg` is not written as the `f32` limit's
/// `45.0000012`); one within its bound is kept as it is.
pub fn within_envelope(
    demand: &FlappingDemand,
    envelope: &Limits,
) -> Result<FlappingDemand, FeasibilityError> {
    demand.validate()?;
    let e = envelope;
    if !(e.min_frequency_hz > 0.0 && e.min_frequency_hz.is_finite()) {
        return Err(envelope_error(
            "min_frequency_hz",
            e.min_frequency_hz,
            "(0, inf) Hz",
        ));
    }
    if !(e.max_frequency_hz >= e.min_frequency_hz && e.max_frequency_hz.is_finite()) {
        return Err(envelope_error(
            "max_frequency_hz",
            e.max_frequency_hz,
            "[min_frequency_hz, inf) Hz",
        ));
    }
    for (field, value) in [
        ("max_amplitude_rad", e.max_amplitude_rad),
        ("max_mean_rad", e.max_mean_rad),
        ("max_excursion_rad", e.max_excursion_rad),
    ] {
        if !(value >= 0.0 && value.is_finite()) {
            return Err(envelope_error(field, value, "[0, inf) rad"));
        }
    }
    let mean_fits = |m: f64| wire_rad(m).abs() <= e.max_mean_rad;
    let mean = if mean_fits(demand.mean_deg) {
        demand.mean_deg
    } else {
        fit_below(demand.mean_deg.abs(), mean_fits).copysign(demand.mean_deg)
    };
    let mean_rad = wire_rad(mean).abs();
    let amplitude_fits = |a: f64| {
        wire_rad(a) <= e.max_amplitude_rad && mean_rad + wire_rad(a) <= e.max_excursion_rad
    };
    let amplitude = if amplitude_fits(demand.amplitude_deg) {
        demand.amplitude_deg
    } else {
        fit_below(demand.amplitude_deg, amplitude_fits)
    };
    // f32 frequencies are exact in f64: the bounds round-trip as they are.
    let frequency = demand
        .frequency_hz
        .max(f64::from(e.min_frequency_hz))
        .min(f64::from(e.max_frequency_hz));
    Ok(FlappingDemand {
        frequency_hz: frequency,
        amplitude_deg: amplitude,
        mean_deg: mean,
    })
}

/// The largest `x` in `[lo, hi]` whose `judge(x)` is feasible (see the
/// module docs), rounded down to [`RESOLUTION`] when that stays feasible
/// and within `[lo, hi]`, with its verdict; None if no point of the scan is.
fn largest_feasible(
    lo: f64,
    hi: f64,
    judge: impl Fn(f64) -> Result<Feasibility, FeasibilityError>,
) -> Result<Option<Feasibility>, FeasibilityError> {
    let Some((x, found)) = boundary(lo, hi, &judge)? else {
        return Ok(None);
    };
    let rounded = floor_to_resolution(x);
    if rounded < x && rounded >= lo {
        let v = judge(rounded)?;
        if v.feasible {
            return Ok(Some(v));
        }
    }
    Ok(Some(found))
}

/// The scan and bisection of [`largest_feasible`]: the point and its
/// verdict.
fn boundary(
    lo: f64,
    hi: f64,
    judge: &impl Fn(f64) -> Result<Feasibility, FeasibilityError>,
) -> Result<Option<(f64, Feasibility)>, FeasibilityError> {
    let top = judge(hi)?;
    if top.feasible || hi <= lo {
        return Ok(top.feasible.then_some((hi, top)));
    }
    let step = (hi - lo) / SCAN_STEPS as f64;
    let mut above = hi;
    for k in 1..=SCAN_STEPS {
        let x = if k == SCAN_STEPS {
            lo
        } else {
            hi - k as f64 * step
        };
        let here = judge(x)?;
        if here.feasible {
            // Bisect [x, above]: `best` feasible, `above` not.
            let mut best = (x, here);
            let mut below = x;
            for _ in 0..BISECTIONS {
                let mid = 0.5 * (below + above);
                let v = judge(mid)?;
                if v.feasible {
                    below = mid;
                    best = (mid, v);
                } else {
                    above = mid;
                }
            }
            return Ok(Some(best));
        }
        above = x;
    }
    Ok(None)
}

/// The nearest feasible kinematics to `demand` on plant `p` under `limits`
/// inside the device's `envelope` (method in the [module docs](self)).
pub fn nearest_feasible(
    p: &PlantParams,
    limits: &ActuatorLimits,
    envelope: &Limits,
    demand: &FlappingDemand,
) -> Result<NearestFeasible, FeasibilityError> {
    let inside = within_envelope(demand, envelope)?;
    let here = check(p, limits, &inside)?;
    let mut nearest = NearestFeasible {
        requested: *demand,
        within_envelope: inside,
        by_amplitude: None,
        by_frequency: None,
        chosen: Alternative {
            feasibility: here,
            relative_change: 0.0,
        },
        change: Change::None,
    };
    if here.feasible {
        return Ok(nearest);
    }
    let change = |new: f64, old: f64| if old > 0.0 { 1.0 - new / old } else { 0.0 };
    nearest.by_amplitude = largest_feasible(0.0, inside.amplitude_deg, |a| {
        let d = FlappingDemand {
            amplitude_deg: a,
            ..inside
        };
        check(p, limits, &d)
    })?
    .map(|f| Alternative {
        relative_change: change(f.demand.amplitude_deg, inside.amplitude_deg),
        feasibility: f,
    });
    let f_min = f64::from(envelope.min_frequency_hz).min(inside.frequency_hz);
    nearest.by_frequency = largest_feasible(f_min, inside.frequency_hz, |f| {
        let d = FlappingDemand {
            frequency_hz: f,
            ..inside
        };
        check(p, limits, &d)
    })?
    .map(|f| Alternative {
        relative_change: change(f.demand.frequency_hz, inside.frequency_hz),
        feasibility: f,
    });
    let (chosen, kind) = match (nearest.by_amplitude, nearest.by_frequency) {
        (Some(a), Some(f)) if f.relative_change < a.relative_change => (f, Change::Frequency),
        (Some(a), _) => (a, Change::Amplitude),
        (None, Some(f)) => (f, Change::Frequency),
        (None, None) => {
            let rest = check(
                p,
                limits,
                &FlappingDemand {
                    amplitude_deg: 0.0,
                    ..inside
                },
            )?;
            return Err(FeasibilityError::NothingFeasible {
                demand: inside,
                limiting: rest.limiting.quantity,
                value: rest.limiting.value,
                limit: rest.limiting.limit,
            });
        }
    };
    nearest.chosen = chosen;
    nearest.change = kind;
    Ok(nearest)
}
