//! The `[topology]` table of the configuration file: the structural
//! discipline's settings, every key optional, units in the key names,
//! declared in [`TOPOLOGY`], converted to the solver's [`EslsoSettings`].
//!
//! ```toml
//! [topology]
//! mass_fraction = 0.3     # carbon mass / full carbon layer (paper's value lost: 30%)
//! filter_radius_mm = 5.0
//! threshold = 0.5         # 0/1 transformation
//! max_cycles = 10
//! layout_tolerance = 0.01 # fraction of design elements that may still flip
//! esl = "dalembert"      # or "displacement" (K_L u_N, the paper's eq. (12))
//! ```

use serde::{Deserialize, Serialize};

use fwav_settings::{Allowed, Integers, Interval, Setting, Table, Value};

use super::ConfigError;

use crate::aeroelastic::analysis::SystemSettings;
use crate::topology::esl::EslForm;
use crate::topology::eslso::EslsoSettings;
use crate::topology::response::ResponseSettings;
use crate::topology::simp::SimpSettings;

/// The `[topology]` table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct TopologyConfig {
    /// Carbon mass allowed over the design domain, as a fraction of the
    /// full layer's (the seed paper's value did not survive in the copy
    /// here; 0.3 by default).
    pub mass_fraction: f64,
    /// SIMP penalty (seed paper: 3).
    pub penalty: f64,
    /// Density filter radius, mm.
    pub filter_radius_mm: f64,
    /// SIMP move limit per iteration.
    pub move_limit: f64,
    /// SIMP iterations allowed per cycle.
    pub simp_iterations: usize,
    /// SIMP stops when no density changes more than this.
    pub simp_tolerance: f64,
    /// Density at and above which an element keeps its carbon (0/1
    /// transformation).
    pub threshold: f64,
    /// ESLSO cycles allowed.
    pub max_cycles: usize,
    /// ESLSO stops when a cycle that analysed a 0/1 layout flips at most
    /// this fraction of the design elements (0: the paper's strict rule;
    /// see [`crate::topology::eslso`] for the default's reason).
    pub layout_tolerance: f64,
    /// Pressure periods of the nonlinear dynamic analysis (the last is
    /// sampled).
    pub periods: usize,
    /// Sample (one ESL load case) every this many steps.
    pub sample_every: usize,
    /// Generalized-α spectral radius of the dynamic analysis.
    pub rho_inf: f64,
    /// Newton tolerance of the dynamic analysis (relative).
    pub newton_tolerance: f64,
    /// The load cases: `"dalembert"` (`f - M a`, default) or
    /// `"displacement"` (`K_L u_N`, the seed paper's eq. (12)).
    pub esl: EslForm,
}

impl Default for TopologyConfig {
    fn default() -> Self {
        Self::from_settings(&EslsoSettings::default())
    }
}

impl TopologyConfig {
    /// The table holding `s`.
    pub fn from_settings(s: &EslsoSettings) -> Self {
        Self {
            mass_fraction: s.simp.mass_fraction,
            penalty: s.simp.penalty,
            filter_radius_mm: 1e3 * s.simp.filter_radius,
            move_limit: s.simp.move_limit,
            simp_iterations: s.simp.max_iterations,
            simp_tolerance: s.simp.tolerance,
            threshold: s.threshold,
            max_cycles: s.max_cycles,
            layout_tolerance: s.layout_tolerance,
            periods: s.response.periods,
            sample_every: s.response.sample_every,
            rho_inf: s.response.rho_inf,
            newton_tolerance: s.response.tolerance,
            esl: s.esl,
        }
    }

    /// The settings in SI.
    pub fn settings(&self) -> EslsoSettings {
        EslsoSettings {
            simp: SimpSettings {
                penalty: self.penalty,
                mass_fraction: self.mass_fraction,
                filter_radius: 1e-3 * self.filter_radius_mm,
                move_limit: self.move_limit,
                max_iterations: self.simp_iterations,
                tolerance: self.simp_tolerance,
            },
            threshold: self.threshold,
            max_cycles: self.max_cycles,
            layout_tolerance: self.layout_tolerance,
            response: ResponseSettings {
                periods: self.periods,
                sample_every: self.sample_every,
                rho_inf: self.rho_inf,
                tolerance: self.newton_tolerance,
            },
            esl: self.esl,
        }
    }
}

/// The `[topology]` table's settings.
pub const TOPOLOGY: Table<TopologyConfig> = Table {
    name: "topology",
    doc: "The structural discipline: ESLSO (nonlinear dynamic response, equivalent \
          static loads, linear SIMP, 0/1 layout).",
    settings: &[
        Setting {
            key: "mass_fraction",
            unit: "",
            allowed: Allowed::Real(Interval::closed(0.2, 1.0)),
            doc: "Carbon mass allowed over the design domain, fraction of the full layer; at \
                  least 0.2: below it the layouts leave so much of the wing mylar alone that \
                  the nonlinear dynamic analysis fails (built-in wing: 0.1 fails at step 453, \
                  0.2 converges; coarse 16 x 6 wing: 0.15 and below fail, 0.2 converges)",
            value: |t| Value::Real(t.mass_fraction),
        },
        Setting {
            key: "penalty",
            unit: "",
            allowed: Allowed::Real(Interval::closed(1.0, 6.0)),
            doc: "SIMP penalty",
            value: |t| Value::Real(t.penalty),
        },
        Setting {
            key: "filter_radius_mm",
            unit: "mm",
            allowed: Allowed::Real(Interval::closed(0.01, 1000.0)),
            doc: "Density filter radius",
            value: |t| Value::Real(t.filter_radius_mm),
        },
        Setting {
            key: "move_limit",
            unit: "",
            allowed: Allowed::Real(Interval::closed(0.01, 1.0)),
            doc: "SIMP move limit an iteration",
            value: |t| Value::Real(t.move_limit),
        },
        Setting {
            key: "simp_iterations",
            unit: "",
            allowed: Allowed::Integer(Integers::between(1, 10000)),
            doc: "SIMP iterations allowed an ESLSO cycle",
            value: |t| Value::unsigned(t.simp_iterations),
        },
        Setting {
            key: "simp_tolerance",
            unit: "",
            allowed: Allowed::Real(Interval::closed(1e-9, 0.5)),
            doc: "SIMP stops when no density changes more than this",
            value: |t| Value::Real(t.simp_tolerance),
        },
        Setting {
            key: "threshold",
            unit: "",
            allowed: Allowed::Real(Interval::closed(0.01, 0.99)),
            doc: "Density at and above which an element keeps its carbon (0/1 layout)",
            value: |t| Value::Real(t.threshold),
        },
        Setting {
            key: "max_cycles",
            unit: "",
            allowed: Allowed::Integer(Integers::between(1, 100)),
            doc: "ESLSO cycles allowed in one structural discipline run",
            value: |t| Value::unsigned(t.max_cycles),
        },
        Setting {
            key: "layout_tolerance",
            unit: "",
            allowed: Allowed::Real(Interval::closed(0.0, 0.5)),
            doc: "ESLSO stops when a cycle that analysed a 0/1 layout flips at most this \
                  fraction of the design elements (0: none, the paper's rule)",
            value: |t| Value::Real(t.layout_tolerance),
        },
        Setting {
            key: "periods",
            unit: "",
            allowed: Allowed::Integer(Integers::between(2, 50)),
            doc: "Pressure periods of the nonlinear dynamic analysis (the last is sampled)",
            value: |t| Value::unsigned(t.periods),
        },
        Setting {
            key: "sample_every",
            unit: "",
            allowed: Allowed::Integer(Integers::between(1, 10000)),
            doc: "One equivalent static load case every this many steps of the last \
                  pressure period (at most analysis.steps_per_cycle, checked with the file)",
            value: |t| Value::unsigned(t.sample_every),
        },
        Setting {
            key: "rho_inf",
            unit: "",
            allowed: Allowed::Real(Interval::closed(0.0, 1.0)),
            doc: "Generalized-alpha spectral radius of the dynamic analysis",
            value: |t| Value::Real(t.rho_inf),
        },
        Setting {
            key: "newton_tolerance",
            unit: "",
            allowed: Allowed::Real(Interval::closed(1e-12, 0.1)),
            doc: "Newton tolerance of the dynamic analysis, relative",
            value: |t| Value::Real(t.newton_tolerance),
        },
        Setting {
            key: "esl",
            unit: "",
            allowed: Allowed::Choice(&["dalembert", "displacement"]),
            doc: "Load cases: f - M a (d'Alembert) or K_L u_N (the nonlinear displacements, \
                  the paper's eq. (12))",
            value: |t| {
                Value::Choice(match t.esl {
                    EslForm::Dalembert => "dalembert",
                    EslForm::Displacement => "displacement",
                })
            },
        },
    ],
};

/// Refuses a `sample_every` beyond the steps of one period of the
/// pressure history the structural discipline samples (the system
/// analysis's `steps_per_cycle`): it would take no load case.
pub fn check_sampling(
    topology: &TopologyConfig,
    analysis: &SystemSettings,
) -> Result<(), ConfigError> {
    if topology.sample_every > analysis.steps_per_cycle {
        return Err(ConfigError::SampleEvery {
            sample_every: topology.sample_every,
            steps_per_cycle: analysis.steps_per_cycle,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The table round-trips the settings; a bad key is named; both load
    /// case words parse.
    #[test]
    fn settings_round_trip_and_errors_name_the_key() {
        let s = EslsoSettings::default();
        assert_eq!(TopologyConfig::from_settings(&s).settings(), s);
        let bad = TopologyConfig {
            threshold: 1.5,
            ..TopologyConfig::default()
        };
        let e = TOPOLOGY.check(&bad).unwrap_err().to_string();
        assert!(e.contains("topology.threshold"), "{e}");
        let bad = TopologyConfig {
            layout_tolerance: 0.6,
            ..TopologyConfig::default()
        };
        let e = TOPOLOGY.check(&bad).unwrap_err().to_string();
        assert!(e.contains("topology.layout_tolerance"), "{e}");
        for word in ["dalembert", "displacement"] {
            let t: TopologyConfig = toml::from_str(&format!("esl = \"{word}\"")).unwrap();
            TOPOLOGY.check(&t).unwrap();
        }
    }
}
