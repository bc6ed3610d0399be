//! The `[mdois]` table of the configuration file: how many design cycles
//! the driver may run and when a design variable counts as unchanged (the
//! seed paper's stopping rule: "if all the design variables are unchanged
//! in optimization, the process terminates").
//!
//! ```toml
//! [mdois]
//! max_cycles = 5
//! kinematics_tolerance = 0.01   # of each variable's level range
//! layout_tolerance = 0.01       # fraction of design elements that may flip
//! ```
//!
//! The paper's rule is exact equality; fwav's aerodynamic discipline ends
//! in a continuous search (response surfaces and NSGA-II), so a kinematic
//! variable counts as unchanged when it moved by at most
//! `kinematics_tolerance` times its level range (high minus low level of
//! the `[design]` table; relative to the range rather than to the value
//! because the mean angle's initial value is 0). The layout is 0/1; it is
//! unchanged when at most `layout_tolerance` of the design-domain elements
//! flipped (1% by default, 0 for the paper's exact rule). The strict rule
//! is ill-posed on the default wing: border elements whose density sits
//! near the threshold flip on perturbations below the Newton tolerance of
//! the nonlinear analysis (see [`crate::topology::eslso`], which uses the
//! same default for its own loop).

use serde::{Deserialize, Serialize};

use crate::aeroelastic::config::{check_ranges, ConfigError, RangeCheck};

/// The `[mdois]` table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct MdoisConfig {
    /// Design cycles allowed (system analysis and both disciplines). When
    /// the design still changes in the last one, the driver analyses the
    /// last proposal once more and reports the cap as reached.
    pub max_cycles: usize,
    /// A kinematic variable is unchanged when it moved by at most this
    /// fraction of its level range (module docs).
    pub kinematics_tolerance: f64,
    /// The layout is unchanged when at most this fraction of the
    /// design-domain elements changed (0: none).
    pub layout_tolerance: f64,
}

impl Default for MdoisConfig {
    /// 5 cycles (the seed paper converged in 3), 1% of a level range, 1%
    /// of the design elements.
    fn default() -> Self {
        Self {
            max_cycles: 5,
            kinematics_tolerance: 0.01,
            layout_tolerance: 0.01,
        }
    }
}

impl MdoisConfig {
    /// Checks every key's range; the error names the key.
    pub fn check(&self) -> Result<(), ConfigError> {
        let ranges: [RangeCheck; 3] = [
            (
                "mdois.max_cycles",
                self.max_cycles as f64,
                1.0,
                50.0,
                "1..=50",
            ),
            (
                "mdois.kinematics_tolerance",
                self.kinematics_tolerance,
                0.0,
                0.5,
                "[0, 0.5] of a level range",
            ),
            (
                "mdois.layout_tolerance",
                self.layout_tolerance,
                0.0,
                0.5,
                "[0, 0.5] of the design elements",
            ),
        ];
        check_ranges(&ranges)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The defaults pass; a bad key is named with its range.
    #[test]
    fn defaults_pass_and_errors_name_the_key() {
        MdoisConfig::default().check().unwrap();
        let bad = MdoisConfig {
            max_cycles: 0,
            ..MdoisConfig::default()
        };
        let e = bad.check().unwrap_err().to_string();
        assert!(
            e.contains("mdois.max_cycles") && e.contains("1..=50"),
            "{e}"
        );
        let bad = MdoisConfig {
            layout_tolerance: f64::NAN,
            ..MdoisConfig::default()
        };
        let e = bad.check().unwrap_err().to_string();
        assert!(e.contains("mdois.layout_tolerance"), "{e}");
    }
}
