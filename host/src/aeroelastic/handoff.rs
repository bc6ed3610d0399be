//! What a system analysis hands to the two disciplines, as files: the
//! mid-span section history (`section.json`, the aerodynamic discipline's
//! input and `fwav aero2d --deformation`'s) and the pressure history
//! (`pressure.json`, the structural discipline's, read back by
//! [`crate::topology::pressure::PressureHistory::from_json`]), plus the
//! step records as CSV (`steps.csv`). `fwav system-analysis --out` and the
//! MDOIS driver write the same files.

use serde::Deserialize;

use super::analysis::SystemResult;

/// The `section.json` text: the mid-span section over the last cycle.
pub fn section_json(result: &SystemResult) -> String {
    serde_json::json!({
        "description": "mid-span section (mid-line x, y in chords, flapping frame, leading edge undeformed at (0, 0)) over the last cycle; sample k at (k + 1) dt after a cycle start, where the flapping angle is mean + amplitude cos(2 pi f t)",
        "period_s": result.dt_s * result.section_history.len() as f64,
        "samples": result.section_history,
    })
    .to_string()
}

/// The `pressure.json` text: the pressure jump per shell element over the
/// last cycle.
pub fn pressure_json(result: &SystemResult) -> String {
    serde_json::json!({
        "description": "pressure jump (lower minus upper) per shell element over the last cycle, Pa",
        "dt_s": result.dt_s,
        "samples": result.pressure_history,
    })
    .to_string()
}

/// The `steps.csv` text: one row a time step.
pub fn steps_csv(result: &SystemResult) -> String {
    let mut csv = String::from(
        "time_s,fx_n,fy_n,fz_n,power_w,ct,cl,cp,drive_torque_nm,tip_dx_m,tip_dy_m,tip_dz_m,subiterations,residual\n",
    );
    for s in &result.steps {
        csv.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            s.time_s,
            s.force_n[0],
            s.force_n[1],
            s.force_n[2],
            s.power_w,
            s.ct,
            s.cl,
            s.cp,
            s.drive_torque_nm,
            s.tip_displacement_m[0],
            s.tip_displacement_m[1],
            s.tip_displacement_m[2],
            s.subiterations,
            s.residual
        ));
    }
    csv
}

/// A `section.json` read back (its other keys are ignored).
#[derive(Clone, Debug, PartialEq, Deserialize)]
pub struct SectionFile {
    /// Mid-line samples over one cycle, chords (see
    /// [`SystemResult::section_history`]).
    pub samples: Vec<Vec<[f64; 2]>>,
}

impl SectionFile {
    /// Parses the text of a `section.json`.
    pub fn from_json(text: &str) -> Result<Self, serde_json::Error> {
        serde_json::from_str(text)
    }
}
