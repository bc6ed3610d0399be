//! The final kinematics as the flight controller's profile file
//! (`kinematics.json`, the `fwav-profile` format of
//! [`fwav_protocol::document`], read by `fwav profile check` and sent by
//! `fwav upload`), after the actuator feasibility check.
//!
//! Before the file is written, the kinematics are judged against the
//! actuator model ([`fwav_actuator::feasibility`], the one hil-sim flies: the
//! steady-state motor torque, current and terminal voltage that harmonic
//! flapping at that frequency, amplitude and mean angle needs from the
//! default motor, gearbox, spring and battery, against the stall torque,
//! the firmware's current limit and the bridge's reach, with a 10%
//! reserve). A feasible optimum is written as it is; an infeasible one is
//! reported with its limiting quantity, and the file holds the nearest
//! feasible kinematics instead (the smaller of the amplitude or frequency
//! reductions that make it feasible), so that the file can always be
//! flown.

use std::path::{Path, PathBuf};

use fwav_actuator::feasibility::{
    check, nearest_feasible, ActuatorLimits, Change, FlappingDemand, Margin,
};
use fwav_actuator::params::PlantParams;
use fwav_protocol::Limits;
use serde::{Deserialize, Serialize};

use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::profile_file::ProfileFile;

use super::error::DesignError;

/// The profile file's name in the run's directory.
pub const KINEMATICS_FILE: &str = "kinematics.json";

/// One actuator quantity against its limit, as `summary.json` keeps it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ActuatorMargin {
    /// `motor torque`, `motor current` or `terminal voltage`.
    pub quantity: String,
    /// The demand's peak, in `unit`.
    pub value: f64,
    /// Its limit, in `unit`.
    pub limit: f64,
    /// `N m`, `A` or `V`.
    pub unit: String,
    /// `1 - value / limit` (negative: over the limit).
    pub margin: f64,
}

impl From<&Margin> for ActuatorMargin {
    fn from(m: &Margin) -> Self {
        Self {
            quantity: m.quantity.to_string(),
            value: m.value,
            limit: m.limit,
            unit: m.quantity.unit().to_string(),
            margin: m.margin,
        }
    }
}

/// The actuator verdict on the final kinematics and what
/// `kinematics.json` flies.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ActuatorCheck {
    /// The optimum can be flown with every margin at least `reserve`.
    pub optimum_feasible: bool,
    /// The reserve asked of every margin, fraction of the limit.
    pub reserve: f64,
    /// The optimum's torque, current and voltage margins.
    pub margins: Vec<ActuatorMargin>,
    /// The optimum's quantity with the smallest margin (the one that
    /// limits, or would limit first).
    pub limiting: ActuatorMargin,
    /// What `kinematics.json` flies: frequency Hz, amplitude deg, mean
    /// angle deg (the optimum's, or the nearest feasible).
    pub flown_frequency_hz: f64,
    /// See [`Self::flown_frequency_hz`].
    pub flown_amplitude_deg: f64,
    /// See [`Self::flown_frequency_hz`].
    pub flown_mean_angle_deg: f64,
    /// What was reduced to reach the flown kinematics: `none`,
    /// `amplitude` or `frequency`.
    pub change: String,
    /// `1 - flown / optimum` of the reduced variable (0 if none).
    pub relative_change: f64,
    /// The optimum lay outside the flight controller's envelope and was
    /// clamped into it first.
    pub clamped_to_envelope: bool,
}

/// `x` to 6 significant digits (the optimizer's last digits are noise,
/// and the flight controller flies `f32`).
fn round(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let scale = 10f64.powi(5 - x.abs().log10().floor() as i32);
    (x * scale).round() / scale
}

/// The verdict on some kinematics and what to fly.
struct Judged {
    check: ActuatorCheck,
    demand: FlappingDemand,
    flown: FlappingDemand,
    limiting: Margin,
}

/// Judges `kinematics` (to 6 significant digits) on the default actuator
/// (`fwav-actuator`'s shipped plant; see the module docs): the verdict
/// `summary.json` keeps. Analytic, a few milliseconds.
pub fn actuator_check(kinematics: &FlappingKinematics) -> Result<ActuatorCheck, DesignError> {
    Ok(judge(kinematics)?.check)
}

fn judge(kinematics: &FlappingKinematics) -> Result<Judged, DesignError> {
    let fail = |e: &dyn std::fmt::Display| DesignError::output(KINEMATICS_FILE, e);
    let plant = PlantParams::default();
    let limits = ActuatorLimits::firmware_default();
    let demand = FlappingDemand {
        frequency_hz: round(kinematics.frequency),
        amplitude_deg: round(kinematics.amplitude_deg()),
        mean_deg: round(kinematics.mean_angle_deg()),
    };
    let verdict = check(&plant, &limits, &demand).map_err(|e| fail(&e))?;
    let nearest = nearest_feasible(&plant, &limits, &ENVELOPE, &demand).map_err(|e| fail(&e))?;
    let flown = if verdict.feasible && !nearest.clamped() {
        demand
    } else {
        nearest.demand()
    };
    let check = ActuatorCheck {
        optimum_feasible: verdict.feasible,
        reserve: verdict.reserve,
        margins: verdict.margins().iter().map(ActuatorMargin::from).collect(),
        limiting: ActuatorMargin::from(&verdict.limiting),
        flown_frequency_hz: flown.frequency_hz,
        flown_amplitude_deg: flown.amplitude_deg,
        flown_mean_angle_deg: flown.mean_deg,
        change: match nearest.change {
            Change::None => "none",
            Change::Amplitude => "amplitude",
            Change::Frequency => "frequency",
        }
        .to_string(),
        relative_change: nearest.chosen.relative_change,
        clamped_to_envelope: nearest.clamped(),
    };
    Ok(Judged {
        check,
        demand,
        flown,
        limiting: verdict.limiting,
    })
}

/// The flight controller's envelope the profile must respect.
const ENVELOPE: Limits = Limits::REFERENCE_FWAV;

/// Writes `dir/kinematics.json` for `kinematics` after
/// [`actuator_check`]: the kinematics themselves if feasible, otherwise
/// the nearest feasible ones. The stroke plane is a mounting angle, not a
/// motor command: it goes into the description only. Returns the verdict
/// and the file's path.
pub fn write_kinematics(
    dir: &Path,
    kinematics: &FlappingKinematics,
    description: &str,
) -> Result<(ActuatorCheck, PathBuf), DesignError> {
    let Judged {
        check,
        demand,
        flown,
        limiting,
    } = judge(kinematics)?;
    let verdict_text = if flown == demand {
        format!("feasible on the default actuator (limiting: {limiting})")
    } else {
        format!(
            "the optimum {demand} is NOT feasible on the default actuator ({limiting}); this is the nearest feasible profile ({} reduced by {:.1}%)",
            check.change,
            100.0 * check.relative_change
        )
    };
    let source = format!(
        "{description} Stroke plane {:.1} deg (set by the mounting); {verdict_text}",
        kinematics.stroke_plane_deg()
    );
    let path = dir.join(KINEMATICS_FILE);
    let profile = ProfileFile::from_kinematics(
        &path,
        flown.frequency_hz,
        flown.amplitude_deg,
        flown.mean_deg,
        &source,
        &ENVELOPE,
    )
    .map_err(|e| DesignError::output(KINEMATICS_FILE, e))?;
    profile
        .save()
        .map_err(|e| DesignError::output(KINEMATICS_FILE, e))?;
    Ok((check, path))
}
