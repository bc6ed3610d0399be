//! The final kinematics as the flight controller's profile file
//! (`kinematics.json`, the `fwav-profile` format of
//! [`fwav_protocol::document`], read by `fwav profile check` and sent by
//! `fwav upload`), with the actuator's verdict on them.
//!
//! The file holds the final design's kinematics as they are: the ones the
//! last system analysis evaluated and `summary.json` and `report.md` call
//! the final design. There is no derating after the fact: feasibility is
//! a constraint of the aerodynamic discipline (every candidate judged on
//! the cycle's vehicle) and the driver stops before the disciplines if the
//! initial design cannot be flown. The verdict here judges the final
//! kinematics on the design's vehicle ([`crate::vehicle::Vehicle`]: the
//! final cycle's wing, its aerodynamic damping calibrated on the final
//! system analysis, the design file's `[actuator]`; the plant
//! `plant.toml` holds), the steady-state motor torque, current and
//! terminal voltage against the stall torque, the controller's current
//! limit and the bridge's reach, with the `[actuator]` reserve. Should the
//! final analysis's damping make the design infeasible where the
//! discipline's (the previous cycle's) did not, the file still holds the
//! analysed kinematics and the verdict says so.

use std::path::{Path, PathBuf};

use fwav_actuator::feasibility::Margin;
use fwav_protocol::Limits;
use serde::{Deserialize, Serialize};

use crate::aeroelastic::kinematics::FlappingKinematics;
use crate::profile_file::ProfileFile;
use crate::vehicle::Vehicle;

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

/// The actuator verdict on the final design's kinematics (which
/// `kinematics.json` flies), on the design's vehicle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ActuatorCheck {
    /// Every margin is at least `reserve`.
    pub feasible: bool,
    /// The reserve asked of every margin, fraction of the limit.
    pub reserve: f64,
    /// The torque, current and voltage margins.
    pub margins: Vec<ActuatorMargin>,
    /// The quantity with the smallest margin (the one that limits, or
    /// would limit first).
    pub limiting: ActuatorMargin,
    /// Frequency judged and flown, Hz (6 significant digits).
    pub frequency_hz: f64,
    /// Amplitude judged and flown, deg.
    pub amplitude_deg: f64,
    /// Mean angle judged and flown, deg.
    pub mean_angle_deg: f64,
    /// The vehicle's half-wing mass, kg.
    pub wing_mass_kg: f64,
    /// The wing's inertia about the flapping axis, kg m^2.
    pub wing_inertia_kg_m2: f64,
    /// The aerodynamic damping `c_a` (final system analysis), N m s^2.
    pub aero_damping_nms2: f64,
    /// The spring's stiffness at the flown frequency, N m/rad.
    pub spring_nm_per_rad: f64,
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

/// Judges `kinematics` (to 6 significant digits) on `vehicle` (see the
/// module docs): the verdict `summary.json` keeps. Analytic, a few
/// milliseconds.
pub fn actuator_check(
    vehicle: &Vehicle,
    kinematics: &FlappingKinematics,
) -> Result<ActuatorCheck, DesignError> {
    let mut demand = Vehicle::demand(kinematics);
    demand.frequency_hz = round(demand.frequency_hz);
    demand.amplitude_deg = round(demand.amplitude_deg);
    demand.mean_deg = round(demand.mean_deg);
    let verdict = vehicle
        .check(&demand)
        .map_err(|e| DesignError::output(KINEMATICS_FILE, e))?;
    Ok(ActuatorCheck {
        feasible: verdict.feasible,
        reserve: verdict.reserve,
        margins: verdict.margins().iter().map(ActuatorMargin::from).collect(),
        limiting: ActuatorMargin::from(&verdict.limiting),
        frequency_hz: demand.frequency_hz,
        amplitude_deg: demand.amplitude_deg,
        mean_angle_deg: demand.mean_deg,
        wing_mass_kg: vehicle.wing_mass_kg,
        wing_inertia_kg_m2: vehicle.wing_inertia_kg_m2,
        aero_damping_nms2: vehicle.aero_damping_nms2,
        spring_nm_per_rad: vehicle.spring_nm_per_rad(demand.frequency_hz),
    })
}

/// The flight controller's envelope the profile must respect.
const ENVELOPE: Limits = Limits::REFERENCE_FWAV;

/// Writes `dir/kinematics.json` for `kinematics` (as they are) with the
/// verdict of [`actuator_check`] on `vehicle` in its description. The
/// stroke plane is a mounting angle, not a motor command: it goes into
/// the description only. Returns the verdict and the file's path.
pub fn write_kinematics(
    dir: &Path,
    vehicle: &Vehicle,
    kinematics: &FlappingKinematics,
    description: &str,
) -> Result<(ActuatorCheck, PathBuf), DesignError> {
    let check = actuator_check(vehicle, kinematics)?;
    let limiting = &check.limiting;
    let limiting = format!(
        "{} {:.4} {} of {:.4} {} (margin {:.1}%)",
        limiting.quantity,
        limiting.value,
        limiting.unit,
        limiting.limit,
        limiting.unit,
        100.0 * limiting.margin
    );
    let verdict_text = if check.feasible {
        format!("feasible on the designed vehicle (limiting: {limiting})")
    } else {
        format!(
            "NOT feasible with the {:.0}% reserve on the designed vehicle with the final analysis's damping (limiting: {limiting})",
            100.0 * check.reserve
        )
    };
    let source = format!(
        "{description} Stroke plane {:.1} deg (set by the mounting); {verdict_text}",
        kinematics.stroke_plane_deg()
    );
    let path = dir.join(KINEMATICS_FILE);
    let profile = ProfileFile::from_kinematics(
        &path,
        check.frequency_hz,
        check.amplitude_deg,
        check.mean_angle_deg,
        &source,
        &ENVELOPE,
    )
    .map_err(|e| DesignError::output(KINEMATICS_FILE, e))?;
    profile
        .save()
        .map_err(|e| DesignError::output(KINEMATICS_FILE, e))?;
    Ok((check, path))
}
