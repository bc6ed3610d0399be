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

use fwav_settings::{Allowed, Integers, Interval, Setting, Table, Value};

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

/// The `[mdois]` table's settings.
pub const MDOIS: Table<MdoisConfig> = Table {
    name: "mdois",
    doc: "The MDOIS cycle loop: system analysis, then both disciplines, until no design \
          variable changes.",
    settings: &[
        Setting {
            key: "max_cycles",
            unit: "",
            allowed: Allowed::Integer(Integers::between(1, 50)),
            doc: "Design cycles allowed (at the cap the last proposal is analysed once more \
                  and the cap reported)",
            value: |m| Value::unsigned(m.max_cycles),
        },
        Setting {
            key: "kinematics_tolerance",
            unit: "of a level range",
            allowed: Allowed::Real(Interval::closed(0.0, 0.5)),
            doc: "A kinematic variable is unchanged when it moved by at most this fraction of \
                  its level range (high - low level of [design])",
            value: |m| Value::Real(m.kinematics_tolerance),
        },
        Setting {
            key: "layout_tolerance",
            unit: "of the design elements",
            allowed: Allowed::Real(Interval::closed(0.0, 0.5)),
            doc: "The layout is unchanged when at most this fraction of the design elements \
                  changed (0: none, the paper's rule; 0.01 by default, see the topology key)",
            value: |m| Value::Real(m.layout_tolerance),
        },
    ],
};

#[cfg(test)]
mod tests {
    use super::*;

    /// The defaults pass; a bad key is named with its range.
    #[test]
    fn defaults_pass_and_errors_name_the_key() {
        MDOIS.check(&MdoisConfig::default()).unwrap();
        let bad = MdoisConfig {
            max_cycles: 0,
            ..MdoisConfig::default()
        };
        let e = MDOIS.check(&bad).unwrap_err().to_string();
        assert!(
            e.contains("mdois.max_cycles") && e.contains("1..=50"),
            "{e}"
        );
        let bad = MdoisConfig {
            layout_tolerance: f64::NAN,
            ..MdoisConfig::default()
        };
        let e = MDOIS.check(&bad).unwrap_err().to_string();
        assert!(e.contains("mdois.layout_tolerance"), "{e}");
    }
}
