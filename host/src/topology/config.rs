//! The `[topology]` table of the configuration file: the structural
//! discipline's settings, every key optional, units in the key names.
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

use crate::aeroelastic::config::{check_ranges, ConfigError, RangeCheck};

use super::esl::EslForm;
use super::eslso::EslsoSettings;
use super::response::ResponseSettings;
use super::simp::SimpSettings;

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

    /// Checks every key's range; the error names the key.
    pub fn check(&self) -> Result<(), ConfigError> {
        let ranges: [RangeCheck; 13] = [
            (
                "topology.mass_fraction",
                self.mass_fraction,
                0.01,
                1.0,
                "[0.01, 1]",
            ),
            ("topology.penalty", self.penalty, 1.0, 6.0, "[1, 6]"),
            (
                "topology.filter_radius_mm",
                self.filter_radius_mm,
                0.01,
                1000.0,
                "[0.01, 1000] mm",
            ),
            (
                "topology.move_limit",
                self.move_limit,
                0.01,
                1.0,
                "[0.01, 1]",
            ),
            (
                "topology.simp_iterations",
                self.simp_iterations as f64,
                1.0,
                10000.0,
                "1..=10000",
            ),
            (
                "topology.simp_tolerance",
                self.simp_tolerance,
                1e-9,
                0.5,
                "[1e-9, 0.5]",
            ),
            (
                "topology.threshold",
                self.threshold,
                0.01,
                0.99,
                "[0.01, 0.99]",
            ),
            (
                "topology.max_cycles",
                self.max_cycles as f64,
                1.0,
                100.0,
                "1..=100",
            ),
            (
                "topology.layout_tolerance",
                self.layout_tolerance,
                0.0,
                0.5,
                "[0, 0.5]",
            ),
            ("topology.periods", self.periods as f64, 2.0, 50.0, "2..=50"),
            (
                "topology.sample_every",
                self.sample_every as f64,
                1.0,
                10000.0,
                "1..=10000 (and at most the steps a period)",
            ),
            ("topology.rho_inf", self.rho_inf, 0.0, 1.0, "[0, 1]"),
            (
                "topology.newton_tolerance",
                self.newton_tolerance,
                1e-12,
                0.1,
                "[1e-12, 0.1]",
            ),
        ];
        check_ranges(&ranges)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The table round-trips the settings; a bad key is named.
    #[test]
    fn settings_round_trip_and_errors_name_the_key() {
        let s = EslsoSettings::default();
        assert_eq!(TopologyConfig::from_settings(&s).settings(), s);
        let bad = TopologyConfig {
            threshold: 1.5,
            ..TopologyConfig::default()
        };
        let e = bad.check().unwrap_err().to_string();
        assert!(e.contains("topology.threshold"), "{e}");
        let bad = TopologyConfig {
            layout_tolerance: 0.6,
            ..TopologyConfig::default()
        };
        let e = bad.check().unwrap_err().to_string();
        assert!(e.contains("topology.layout_tolerance"), "{e}");
    }
}
