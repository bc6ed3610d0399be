//! The design file's keys by their qualified names (`wing.semi_span_m`):
//! whether a table declares a key, and its declared range and unit — the
//! same declarations the file's own check uses ([`super::SystemConfig::check`]),
//! for the files that name design keys from outside a design file (a
//! study's varied keys, `fwav study`).

use fwav_settings::{Limits, Table};

use super::{actuator, analysis, design, flight, kinematics, mdois, topology, wing};

/// The declared key `table.key`, with its range and unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeclaredKey {
    /// The table (`wing`).
    pub table: &'static str,
    /// The key in it (`semi_span_m`).
    pub key: &'static str,
    /// The allowed values and their unit.
    pub limits: Limits,
}

impl std::fmt::Display for DeclaredKey {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}.{}", self.table, self.key)
    }
}

/// A qualified key no table declares.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "`{given}` is not a key of the design file: {}",
    .suggestion.as_ref().map_or_else(
        || format!("keys are written `table.key`, the tables being {}", TABLES.join(", ")),
        |s| format!("did you mean `{s}`? (`fwav init` lists every key)"),
    )
)]
pub struct UnknownKey {
    /// The key as given.
    pub given: String,
    /// A declared key of the same table, or the same key in another
    /// table, if one is close.
    pub suggestion: Option<String>,
}

/// The tables of the design file, in its order.
const TABLES: [&str; 8] = [
    wing::WING.name,
    kinematics::KINEMATICS.name,
    flight::FLIGHT.name,
    analysis::ANALYSIS.name,
    design::DESIGN.name,
    topology::TOPOLOGY.name,
    mdois::MDOIS.name,
    actuator::ACTUATOR.name,
];

/// Every declared key of one table.
fn declared_in<T>(table: &Table<T>) -> impl Iterator<Item = DeclaredKey> + '_ {
    table.settings.iter().map(move |s| DeclaredKey {
        table: table.name,
        key: s.key,
        limits: s.limits(),
    })
}

/// Every declared key of the design file, table by table in the file's
/// order.
pub fn all() -> Vec<DeclaredKey> {
    let mut keys = Vec::new();
    keys.extend(declared_in(&wing::WING));
    keys.extend(declared_in(&kinematics::KINEMATICS));
    keys.extend(declared_in(&flight::FLIGHT));
    keys.extend(declared_in(&analysis::ANALYSIS));
    keys.extend(declared_in(&design::DESIGN));
    keys.extend(declared_in(&topology::TOPOLOGY));
    keys.extend(declared_in(&mdois::MDOIS));
    keys.extend(declared_in(&actuator::ACTUATOR));
    keys
}

/// The declaration of the qualified key `table.key`, or an error with a
/// suggestion (a key of that table sharing the first word, or the same
/// key in another table).
pub fn declared(qualified: &str) -> Result<DeclaredKey, UnknownKey> {
    let keys = all();
    if let Some(k) = keys.iter().find(|k| k.to_string() == qualified) {
        return Ok(*k);
    }
    let (table, key) = qualified.split_once('.').unwrap_or(("", qualified));
    let first_word = |k: &str| k.split('_').next().unwrap_or(k).to_string();
    let suggestion = keys
        .iter()
        .find(|k| k.table != table && k.key == key)
        .or_else(|| {
            keys.iter()
                .find(|k| k.table == table && first_word(k.key) == first_word(key))
        })
        .map(ToString::to_string);
    Err(UnknownKey {
        given: qualified.to_string(),
        suggestion,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Declared keys are found with their ranges; unknown ones are named
    /// with the nearest declared key.
    #[test]
    fn keys_are_found_or_named() {
        let k = declared("wing.semi_span_m").unwrap();
        assert_eq!(k.limits.to_string(), "[0.01, 2] m");
        assert!(declared("actuator.gear_ratio").is_ok());
        assert!(declared("topology.mass_fraction").is_ok());
        let e = declared("wing.semi_span").unwrap_err();
        assert_eq!(
            e.to_string(),
            "`wing.semi_span` is not a key of the design file: did you mean \
             `wing.semi_span_m`? (`fwav init` lists every key)"
        );
        let e = declared("flight.semi_span_m").unwrap_err();
        assert_eq!(e.suggestion.as_deref(), Some("wing.semi_span_m"));
        let e = declared("span").unwrap_err();
        assert!(
            e.to_string().contains("the tables being wing, kinematics"),
            "{e}"
        );
    }
}
