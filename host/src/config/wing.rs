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
