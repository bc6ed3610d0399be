//! The `[design]` table: the kinematic optimization's levels (the
//! discipline's own [`DesignSpace`], its keys written in this table), the
//! weights of its combined objective, the genetic algorithm's seed and the
//! section analyses' flow model ([`SectionModelName`]: the LDVM or laminar
//! Navier–Stokes of a thin plate).
//!
//! The levels are [`DesignSpace`]'s fields flattened into the table, so
//! serde cannot refuse unknown keys here (`deny_unknown_fields` does not
//! work with `flatten`); [`check_keys`] refuses them from the declared
//! settings instead.

use fwav_settings::{Allowed, Integers, Interval, Setting, Table, Value};
use serde::{Deserialize, Serialize};

use crate::aero2d::viscous::ViscousSection;
use crate::discipline::kinematic::DesignSpace;
use crate::discipline::section::{SectionCase, FWAV_LESP_CRITICAL};
use crate::discipline::section_model::{SectionFlowModel, SectionModelName};

use super::ConfigError;

/// The `[design]` table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct DesignConfig {
    /// The levels (low, initial, high) of the four kinematic variables.
    #[serde(flatten)]
    pub space: DesignSpace,
    /// Weight of the relative thrust gain in the combined objective.
    pub thrust_weight: f64,
    /// Weight of the relative efficiency gain.
    pub efficiency_weight: f64,
    /// Seed of the genetic algorithm.
    pub seed: u64,
    /// Critical leading-edge suction parameter of the section analyses
    /// (leading-edge vortex shedding beyond it); 0: attached flow. The
    /// LDVM's only.
    pub lesp_critical: f64,
    /// The section analyses' flow model.
    pub section_model: SectionModelName,
    /// Thickness of the Navier–Stokes model's plate, chords.
    pub ns_thickness: f64,
    /// Flapping cycles each section analysis runs; the scores are the
    /// means over all after the first two.
    pub section_cycles: usize,
}

impl Default for DesignConfig {
    /// [`DesignSpace::fwav`], equal weights, seed 1.
    fn default() -> Self {
        Self {
            space: DesignSpace::fwav(),
            thrust_weight: 1.0,
            efficiency_weight: 1.0,
            seed: 1,
            lesp_critical: FWAV_LESP_CRITICAL,
            section_model: SectionModelName::Ldvm,
            ns_thickness: ViscousSection::DEFAULT_THICKNESS,
            section_cycles: SectionCase::fwav_mid_span().cycles,
        }
    }
}

impl DesignConfig {
    /// The section analyses' critical LESP, None (attached flow) for 0.
    pub fn lesp(&self) -> Option<f64> {
        (self.lesp_critical > 0.0).then_some(self.lesp_critical)
    }

    /// The section analyses' flow model (the Navier–Stokes model's plate
    /// at the default resolution).
    pub fn flow_model(&self) -> SectionFlowModel {
        match self.section_model {
            SectionModelName::Ldvm => SectionFlowModel::Ldvm,
            SectionModelName::Ns => SectionFlowModel::ns(self.ns_thickness),
        }
    }
}

/// The `[design]` table's settings.
pub const DESIGN: Table<DesignConfig> = Table {
    name: "design",
    doc: "The aerodynamic discipline: three levels (low, initial, high) of each kinematic \
          variable for the L18 array, and the weights of the combined objective \
          w_ct CT/CT_0 + w_eta eta/eta_0, where CT is the net thrust coefficient (the \
          LDVM's thrust less the laminar friction estimate, or the Navier-Stokes model's \
          thrust, friction included), eta = CT/CP the net efficiency, and CT_0, eta_0 the \
          initial design's (the first cycle's, for the whole design).",
    settings: &[
        Setting {
            key: "frequency_hz",
            unit: "Hz",
            allowed: Allowed::Increasing(Interval::closed(0.1, 200.0)),
            doc: "Frequency levels",
            value: |d| Value::Reals(d.space.frequency_hz.to_vec()),
        },
        Setting {
            key: "amplitude_deg",
            unit: "deg",
            // Above 0, as the kinematics' own amplitude: a row that does
            // not flap has no input power, so no efficiency, and the
            // discipline lost its six rows of such a level.
            allowed: Allowed::Increasing(Interval::above_up_to(0.0, 80.0)),
            doc: "Amplitude levels",
            value: |d| Value::Reals(d.space.amplitude_deg.to_vec()),
        },
        Setting {
            key: "mean_angle_deg",
            unit: "deg",
            allowed: Allowed::Increasing(Interval::closed(-60.0, 60.0)),
            doc: "Mean angle levels",
            value: |d| Value::Reals(d.space.mean_angle_deg.to_vec()),
        },
        Setting {
            key: "stroke_plane_deg",
            unit: "deg",
            // Open, as the kinematics' own stroke plane.
            allowed: Allowed::Increasing(Interval::open(0.0, 180.0)),
            doc: "Stroke-plane levels",
            value: |d| Value::Reals(d.space.stroke_plane_deg.to_vec()),
        },
        Setting {
            key: "thrust_weight",
            unit: "",
            allowed: Allowed::Real(Interval::closed(0.0, 100.0)),
            doc: "Weight of the relative thrust gain CT/CT_0",
            value: |d| Value::Real(d.thrust_weight),
        },
        Setting {
            key: "efficiency_weight",
            unit: "",
            allowed: Allowed::Real(Interval::closed(0.0, 100.0)),
            doc: "Weight of the relative efficiency gain eta/eta_0",
            value: |d| Value::Real(d.efficiency_weight),
        },
        Setting {
            key: "seed",
            unit: "",
            allowed: Allowed::Integer(Integers::at_least(0)),
            doc: "Seed of the genetic algorithm (NSGA-II)",
            value: |d| Value::unsigned(d.seed),
        },
        Setting {
            key: "lesp_critical",
            unit: "",
            allowed: Allowed::Real(Interval::closed(0.0, 2.0)),
            doc: "Critical leading-edge suction parameter of the section's LDVM: leading-edge \
                  vortices are shed beyond it (separation). 0.11 for the thin, sharp-edged \
                  membrane (flat-plate value of Ramesh et al. 2014, J. Fluid Mech. 751; 0.18 \
                  is their SD7003); 0 means attached flow",
            value: |d| Value::Real(d.lesp_critical),
        },
        Setting {
            key: "section_model",
            unit: "",
            allowed: Allowed::Choice(&["ldvm", "ns"]),
            doc: "Flow model of the section analyses. \"ldvm\": the inviscid LDVM with \
                  leading-edge shedding and a laminar friction estimate, of the deforming \
                  section; a fraction of a second an evaluation, seconds a discipline run. \
                  \"ns\": laminar Navier-Stokes of a thin plate (ns_thickness) with its \
                  friction and separation, the plate's mid-line deforming as the system \
                  analysis found (on a moving grid); lesp_critical does not apply. Cost: \
                  about 54 s for one 4-cycle evaluation of the default section on two \
                  cores when rigid, 82 s deforming as the default design's first system \
                  analysis found (384 x 256 nodes, the far field coarsened), about 29 \
                  minutes for a discipline run (measured alone on the default design)",
            value: |d| Value::Choice(d.section_model.word()),
        },
        Setting {
            key: "ns_thickness",
            unit: "chords",
            allowed: Allowed::Real(Interval::closed(0.005, 0.3)),
            doc: "Thickness of the Navier-Stokes model's plate, semicircular ends. Its \
                  thrust grows about in proportion, the suction on its rounded nose (the \
                  default section's first stroke: CT 0.014, 0.037, 0.078 at 0.01, 0.02, \
                  0.04; the power within 3 %). The vehicle's carbon leading edge with its \
                  mylar (0.6 mm on the 60 mm mid-span chord) is 0.01 chords, and takes 1.9 \
                  times the time steps of 0.04; the 0.1 mm membrane alone is 0.0017, \
                  thinner than the solver can grid",
            value: |d| Value::Real(d.ns_thickness),
        },
        Setting {
            key: "section_cycles",
            unit: "",
            allowed: Allowed::Integer(Integers::between(3, 40)),
            doc: "Flapping cycles each section analysis runs; its scores (net CT and \
                  efficiency) are the means over all cycles after the first two, the start's \
                  transient. The LDVM's flow repeats from the third when attached; when \
                  it sheds (lesp_critical above 0) its scores scatter with the time step, \
                  by 1.4 % (CT) and 3.1 % (efficiency) on a rigid section and 7.8 % and \
                  10.2 % on a deforming one, which the discipline's adoption margin carries \
                  and more cycles do not narrow. The Navier-Stokes flow round the deforming \
                  plate has not settled by then: over cycles 3 and 4 (4, the default) its \
                  scores scatter by 5.3 % (CT) and 4.5 % (efficiency) with any change of what \
                  led up to them, which the discipline's adoption margin carries; over cycles \
                  3 to 12 (12) by 4.6 % and 4.2 %, at three times the time (about 1.3 hours a \
                  discipline run)",
            value: |d| Value::unsigned(d.section_cycles),
        },
    ],
};

/// The level keys of the table ([`DesignSpace`]'s fields): three values
/// each.
const LEVEL_KEYS: [&str; 4] = [
    "frequency_hz",
    "amplitude_deg",
    "mean_angle_deg",
    "stroke_plane_deg",
];

/// Refuses a key of the file's `[design]` table that [`DESIGN`] does not
/// declare, a level key whose array does not hold three levels, and a
/// word of a choice (`section_model`) that is not one of its words (serde
/// would refuse it too, but naming no key inside the flattened table).
pub fn check_keys(file: &toml::Table) -> Result<(), ConfigError> {
    let Some(toml::Value::Table(table)) = file.get(DESIGN.name) else {
        return Ok(());
    };
    for setting in DESIGN.settings {
        let (Allowed::Choice(words), Some(value)) = (&setting.allowed, table.get(setting.key))
        else {
            continue;
        };
        if !value.as_str().is_some_and(|w| words.contains(&w)) {
            return Err(ConfigError::Choice {
                table: DESIGN.name,
                key: setting.key,
                value: value.to_string(),
                allowed: setting.allowed.to_string(),
            });
        }
    }
    for key in LEVEL_KEYS {
        if let Some(toml::Value::Array(levels)) = table.get(key) {
            if levels.len() != 3 {
                return Err(ConfigError::Levels {
                    key,
                    found: levels.len(),
                });
            }
        }
    }
    match table.keys().find(|k| DESIGN.setting(k).is_none()) {
        None => Ok(()),
        Some(key) => Err(ConfigError::Unknown {
            table: DESIGN.name,
            key: key.clone(),
            expected: DESIGN
                .settings
                .iter()
                .map(|s| format!("`{}`", s.key))
                .collect::<Vec<_>>()
                .join(", "),
        }),
    }
}

/// Refuses a combined objective that is 0 for every design (both weights
/// 0).
pub fn check_weights(d: &DesignConfig) -> Result<(), ConfigError> {
    if d.thrust_weight == 0.0 && d.efficiency_weight == 0.0 {
        return Err(ConfigError::NoObjective);
    }
    Ok(())
}
