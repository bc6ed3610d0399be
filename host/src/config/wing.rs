//! The `[wing]` table: planform, shell mesh and the uniform carbon
//! density of the starting design.

use fwav_settings::{Allowed, Integers, Interval, Setting, Table, Value};
use serde::{Deserialize, Serialize};

use crate::shell::wing::Planform;

/// The `[wing]` table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WingConfig {
    /// Semi-span, m.
    pub semi_span_m: f64,
    /// Root chord, m.
    pub root_chord_m: f64,
    /// Tip chord, m.
    pub tip_chord_m: f64,
    /// Leading-edge spar width, m.
    pub spar_width_m: f64,
    /// Root attachment length from the leading edge, m.
    pub root_attachment_m: f64,
    /// Shell elements along the span.
    pub span_elements: usize,
    /// Shell elements along the chord.
    pub chord_elements: usize,
    /// Uniform carbon density of the design layer, in [0, 1]. Default 1, the
    /// full carbon layer (first bending mode 26 Hz on the built-in wing);
    /// the topology's uniform starting density of 0.3 would put it at
    /// 16.8 Hz, so near the 11 Hz flapping that the wing's tip swings by
    /// more than its span in the small-deflection floating frame.
    pub carbon_fraction: f64,
}

impl Default for WingConfig {
    fn default() -> Self {
        let p = Planform::FWAV;
        Self {
            semi_span_m: p.semi_span,
            root_chord_m: p.root_chord,
            tip_chord_m: p.tip_chord,
            spar_width_m: p.spar_width,
            root_attachment_m: p.root_attachment,
            span_elements: p.span_elements,
            chord_elements: p.chord_elements,
            carbon_fraction: 1.0,
        }
    }
}

impl WingConfig {
    /// The planform.
    pub fn planform(&self) -> Planform {
        Planform {
            semi_span: self.semi_span_m,
            root_chord: self.root_chord_m,
            tip_chord: self.tip_chord_m,
            spar_width: self.spar_width_m,
            root_attachment: self.root_attachment_m,
            span_elements: self.span_elements,
            chord_elements: self.chord_elements,
        }
    }
}

/// The `[wing]` table's settings.
pub const WING: Table<WingConfig> = Table {
    name: "wing",
    doc: "The wing: planform, shell mesh, and the carbon design layer over the mylar skin.",
    settings: &[
        Setting {
            key: "semi_span_m",
            unit: "m",
            allowed: Allowed::Real(Interval::closed(0.01, 2.0)),
            doc: "Semi-span",
            value: |w| Value::Real(w.semi_span_m),
        },
        Setting {
            key: "root_chord_m",
            unit: "m",
            allowed: Allowed::Real(Interval::closed(0.005, 1.0)),
            doc: "Root chord",
            value: |w| Value::Real(w.root_chord_m),
        },
        Setting {
            key: "tip_chord_m",
            unit: "m",
            allowed: Allowed::Real(Interval::closed(0.005, 1.0)),
            doc: "Tip chord",
            value: |w| Value::Real(w.tip_chord_m),
        },
        Setting {
            key: "spar_width_m",
            unit: "m",
            allowed: Allowed::Real(Interval::closed(1e-4, 0.1)),
            doc: "Leading-edge carbon spar width (outside the design domain)",
            value: |w| Value::Real(w.spar_width_m),
        },
        Setting {
            key: "root_attachment_m",
            unit: "m",
            allowed: Allowed::Real(Interval::closed(1e-4, 1.0)),
            doc: "Root attachment length from the leading edge (clamped)",
            value: |w| Value::Real(w.root_attachment_m),
        },
        Setting {
            key: "span_elements",
            unit: "",
            allowed: Allowed::Integer(Integers::between(2, 400)),
            doc: "Shell elements along the span",
            value: |w| Value::unsigned(w.span_elements),
        },
        Setting {
            key: "chord_elements",
            unit: "",
            allowed: Allowed::Integer(Integers::between(2, 200)),
            doc: "Shell elements along the chord",
            value: |w| Value::unsigned(w.chord_elements),
        },
        Setting {
            key: "carbon_fraction",
            unit: "",
            allowed: Allowed::Real(Interval::closed(0.0, 1.0)),
            doc: "Uniform carbon density of the starting design (before the first layout)",
            value: |w| Value::Real(w.carbon_fraction),
        },
    ],
};

/// Keys of the `[wing]` table, each within its range, that do not fit
/// together (what the mesh generator would refuse later without naming
/// them).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlanformConflict {
    /// The root attachment is longer than the root chord.
    #[error(
        "wing.root_attachment_m = {attachment_m} m is longer than the root chord \
         (wing.root_chord_m = {root_chord_m} m): the attachment runs from the leading edge \
         along the root chord; make it at most the root chord"
    )]
    AttachmentBeyondChord {
        /// The attachment, m.
        attachment_m: f64,
        /// The root chord, m.
        root_chord_m: f64,
    },
    /// The spar is as wide as the narrowest chord or wider.
    #[error(
        "wing.spar_width_m = {spar_m} m is not narrower than the chord ({key} = {chord_m} m): \
         the spar runs along the leading edge inside the wing; make it narrower"
    )]
    SparTooWide {
        /// The spar width, m.
        spar_m: f64,
        /// The narrower chord's key.
        key: &'static str,
        /// That chord, m.
        chord_m: f64,
    },
    /// The attachment is shorter than one chordwise element at the root.
    #[error(
        "wing.root_attachment_m = {attachment_m} m is shorter than one of the \
         wing.chord_elements = {chord_elements} elements of the root chord ({element_m:.4} m \
         each): the wing would hang on one node; use at least {needed} chordwise elements, or \
         a longer attachment"
    )]
    AttachmentOnOneNode {
        /// The attachment, m.
        attachment_m: f64,
        /// Elements along the chord.
        chord_elements: usize,
        /// One element's length along the root chord, m.
        element_m: f64,
        /// The fewest chordwise elements that give the attachment two
        /// nodes.
        needed: usize,
    },
}

/// Checks the planform keys against each other (the mesh generator's
/// conditions, [`Planform::mesh`], with the keys named).
pub fn check_planform(w: &WingConfig) -> Result<(), PlanformConflict> {
    if w.root_attachment_m > w.root_chord_m {
        return Err(PlanformConflict::AttachmentBeyondChord {
            attachment_m: w.root_attachment_m,
            root_chord_m: w.root_chord_m,
        });
    }
    let (key, chord_m) = if w.tip_chord_m < w.root_chord_m {
        ("wing.tip_chord_m", w.tip_chord_m)
    } else {
        ("wing.root_chord_m", w.root_chord_m)
    };
    if w.spar_width_m >= chord_m {
        return Err(PlanformConflict::SparTooWide {
            spar_m: w.spar_width_m,
            key,
            chord_m,
        });
    }
    // The root's nodes lie every root_chord / chord_elements from the
    // leading edge; the mesh generator's tolerance.
    let element_m = w.root_chord_m / w.chord_elements as f64;
    if element_m > w.root_attachment_m + 1e-9 * w.root_chord_m {
        return Err(PlanformConflict::AttachmentOnOneNode {
            attachment_m: w.root_attachment_m,
            chord_elements: w.chord_elements,
            element_m,
            needed: (w.root_chord_m / w.root_attachment_m).ceil() as usize,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The default wing fits; each conflict is the mesh generator's
    /// refusal, found before meshing and naming the keys.
    #[test]
    fn planform_conflicts_match_the_mesh_generator() {
        let default = WingConfig::default();
        assert_eq!(check_planform(&default), Ok(()));
        assert!(default.planform().mesh().is_ok());
        let cases = [
            WingConfig {
                root_attachment_m: 0.08,
                ..default.clone()
            },
            WingConfig {
                spar_width_m: 0.05,
                ..default.clone()
            },
            WingConfig {
                chord_elements: 4,
                ..default.clone()
            },
        ];
        for (wing, key) in cases.iter().zip([
            "wing.root_chord_m",
            "wing.tip_chord_m",
            "wing.chord_elements",
        ]) {
            let e = check_planform(wing).unwrap_err();
            assert!(e.to_string().contains(key), "{e}");
            assert!(wing.planform().mesh().is_err(), "{e}");
        }
        let five = WingConfig {
            chord_elements: 5,
            ..default
        };
        assert_eq!(check_planform(&five), Ok(()));
        assert!(five.planform().mesh().is_ok());
    }
}
