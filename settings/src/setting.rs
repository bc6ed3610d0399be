//! A declared key ([`Setting`]), a table of them ([`Table`]) and the
//! check of a parsed table's values against their declared ranges. Imports
//! [`crate::range`].

use std::fmt;

use crate::range::{Allowed, Limits};
use crate::shown::Shown;

/// A setting's value as read from the parsed file, for the check and the
/// error.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A real number.
    Real(f64),
    /// An integer.
    Integer(i64),
    /// A sequence of reals.
    Reals(Vec<f64>),
    /// A flag.
    Flag(bool),
    /// A word out of a fixed set.
    Choice(&'static str),
}

impl Value {
    /// An unsigned integer (a count, a size, a seed); values above
    /// `i64::MAX` read as `i64::MAX`, which no declared range caps.
    pub fn unsigned(n: impl TryInto<i64>) -> Self {
        Value::Integer(n.try_into().unwrap_or(i64::MAX))
    }

    /// What kind of value this is, for a mismatch error.
    fn kind(&self) -> &'static str {
        match self {
            Value::Real(_) => "real",
            Value::Integer(_) => "integer",
            Value::Reals(_) => "sequence",
            Value::Flag(_) => "flag",
            Value::Choice(_) => "word",
        }
    }
}

impl fmt::Display for Value {
    /// Reals in shortest round-trip form (`-3`, `0.25`; powers of ten
    /// where that is long, `1e300`: [`Shown`]), sequences as `[40, 30,
    /// 20]`, words quoted.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Real(x) => write!(f, "{}", Shown(*x)),
            Value::Integer(n) => write!(f, "{n}"),
            Value::Reals(xs) => {
                f.write_str("[")?;
                for (i, x) in xs.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{}", Shown(*x))?;
                }
                f.write_str("]")
            }
            Value::Flag(b) => write!(f, "{b}"),
            Value::Choice(w) => write!(f, "\"{w}\""),
        }
    }
}

/// One key of a table of `T`, declared once: its name, unit, allowed
/// range and doc, and how to read its value from a parsed `T`.
pub struct Setting<T> {
    /// The key as written in the file (`semi_span_m`).
    pub key: &'static str,
    /// The unit of the value and of its range, `""` for none.
    pub unit: &'static str,
    /// The values allowed.
    pub allowed: Allowed,
    /// What the setting is, as a phrase without a final period; the
    /// template appends `; <range> <unit>.`.
    pub doc: &'static str,
    /// The value of the setting in a parsed `T`.
    pub value: fn(&T) -> Value,
}

impl<T> Setting<T> {
    /// A real setting: `key` in `unit`, allowed in `allowed`, read by
    /// `value` (the common case of a table of measured quantities).
    pub const fn real(
        key: &'static str,
        unit: &'static str,
        allowed: crate::range::Interval,
        doc: &'static str,
        value: fn(&T) -> Value,
    ) -> Self {
        Self {
            key,
            unit,
            allowed: Allowed::Real(allowed),
            doc,
            value,
        }
    }

    /// The range with its unit.
    pub fn limits(&self) -> Limits {
        Limits {
            allowed: self.allowed,
            unit: self.unit,
        }
    }

    /// The template's comment: `<doc>; <range> <unit>.`
    pub fn comment(&self) -> String {
        format!("{}; {}.", self.doc, self.limits())
    }
}

/// A table of the file (`[wing]`) with its declared settings.
pub struct Table<T: 'static> {
    /// The table's name as written in the file.
    pub name: &'static str,
    /// What the table holds (the template's comment above its header).
    pub doc: &'static str,
    /// Its keys, in the order the check walks them.
    pub settings: &'static [Setting<T>],
}

impl<T> Table<T> {
    /// Checks every setting of `values` against its declared range, in
    /// declaration order; the first one outside is the error.
    pub fn check(&self, values: &T) -> Result<(), SettingError> {
        for s in self.settings {
            let value = (s.value)(values);
            let inside = match (&s.allowed, &value) {
                (Allowed::Real(i), Value::Real(x)) => i.contains(*x),
                (Allowed::Integer(r), Value::Integer(n)) => r.contains(*n),
                (Allowed::Increasing(i), Value::Reals(xs)) => {
                    xs.iter().all(|&x| i.contains(x)) && xs.windows(2).all(|w| w[0] < w[1])
                }
                (Allowed::Flag, Value::Flag(_)) => true,
                (Allowed::Choice(words), Value::Choice(w)) => words.contains(w),
                _ => {
                    return Err(SettingError::Mismatch {
                        table: self.name,
                        key: s.key,
                        found: value.kind(),
                        limits: s.limits(),
                    })
                }
            };
            if !inside {
                return Err(SettingError::OutOfRange {
                    table: self.name,
                    key: s.key,
                    value,
                    limits: s.limits(),
                });
            }
        }
        Ok(())
    }

    /// The setting declared for `key`, if any.
    pub fn setting(&self, key: &str) -> Option<&Setting<T>> {
        self.settings.iter().find(|s| s.key == key)
    }
}

/// Why a table's values were refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SettingError {
    /// A value outside its declared range.
    #[error("{table}.{key} = {value} {}", Complaint(limits))]
    OutOfRange {
        /// The table.
        table: &'static str,
        /// The key in it.
        key: &'static str,
        /// The value read.
        value: Value,
        /// The declared range and unit.
        limits: Limits,
    },
    /// The declaration reads a kind of value its range does not describe
    /// (a bug in the declaration, found by any check of the table).
    #[error("{table}.{key}: the declaration reads a {found} value for the range {limits}")]
    Mismatch {
        /// The table.
        table: &'static str,
        /// The key in it.
        key: &'static str,
        /// The kind of value read.
        found: &'static str,
        /// The declared range and unit.
        limits: Limits,
    },
}

/// What is wrong with a value outside `limits`, in the words that fit
/// the kind of range: `is outside [0.01, 2] m` for an interval or an
/// integer range, `must be increasing, each in [0, 80] deg` for a
/// sequence, `must be "a" or "b"` for a choice.
struct Complaint<'l>(&'l Limits);

impl fmt::Display for Complaint<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.allowed {
            Allowed::Real(_) | Allowed::Integer(_) => write!(f, "is outside {}", self.0),
            Allowed::Increasing(_) | Allowed::Flag | Allowed::Choice(_) => {
                write!(f, "must be {}", self.0)
            }
        }
    }
}

impl SettingError {
    /// The qualified key, `table.key`.
    pub fn qualified_key(&self) -> String {
        match self {
            SettingError::OutOfRange { table, key, .. }
            | SettingError::Mismatch { table, key, .. } => {
                format!("{table}.{key}")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::range::{Integers, Interval};

    struct Wing {
        span_m: f64,
        elements: usize,
        levels_deg: [f64; 3],
        rigid: bool,
        form: &'static str,
    }

    const WING: Table<Wing> = Table {
        name: "wing",
        doc: "The wing.",
        settings: &[
            Setting {
                key: "span_m",
                unit: "m",
                allowed: Allowed::Real(Interval::closed(0.01, 2.0)),
                doc: "Span",
                value: |w| Value::Real(w.span_m),
            },
            Setting {
                key: "elements",
                unit: "",
                allowed: Allowed::Integer(Integers::between(2, 400)),
                doc: "Elements",
                value: |w| Value::unsigned(w.elements),
            },
            Setting {
                key: "levels_deg",
                unit: "deg",
                allowed: Allowed::Increasing(Interval::closed(0.0, 80.0)),
                doc: "Levels",
                value: |w| Value::Reals(w.levels_deg.to_vec()),
            },
            Setting {
                key: "rigid",
                unit: "",
                allowed: Allowed::Flag,
                doc: "Rigid",
                value: |w| Value::Flag(w.rigid),
            },
            Setting {
                key: "form",
                unit: "",
                allowed: Allowed::Choice(&["a", "b"]),
                doc: "Form",
                value: |w| Value::Choice(w.form),
            },
        ],
    };

    fn good() -> Wing {
        Wing {
            span_m: 0.15,
            elements: 24,
            levels_deg: [20.0, 30.0, 40.0],
            rigid: false,
            form: "a",
        }
    }

    /// The first value outside is named with its table, value and the
    /// generated range text.
    #[test]
    fn errors_name_the_key_value_and_range() {
        WING.check(&good()).unwrap();
        let e = WING
            .check(&Wing {
                span_m: -3.0,
                elements: 1,
                ..good()
            })
            .unwrap_err();
        assert_eq!(e.to_string(), "wing.span_m = -3 is outside [0.01, 2] m");
        assert_eq!(e.qualified_key(), "wing.span_m");
        let e = WING
            .check(&Wing {
                elements: 1,
                ..good()
            })
            .unwrap_err();
        assert_eq!(e.to_string(), "wing.elements = 1 is outside 2..=400");
        let e = WING
            .check(&Wing {
                levels_deg: [40.0, 30.0, 20.0],
                ..good()
            })
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "wing.levels_deg = [40, 30, 20] must be increasing, each in [0, 80] deg"
        );
        let e = WING
            .check(&Wing {
                span_m: f64::NAN,
                ..good()
            })
            .unwrap_err();
        assert!(matches!(e, SettingError::OutOfRange { key: "span_m", .. }));
        let e = WING
            .check(&Wing {
                form: "c",
                ..good()
            })
            .unwrap_err();
        assert_eq!(e.to_string(), "wing.form = \"c\" must be \"a\" or \"b\"");
    }

    /// A declaration that reads the wrong kind of value is refused.
    #[test]
    fn a_mismatched_declaration_is_refused() {
        const BAD: Table<Wing> = Table {
            name: "wing",
            doc: "",
            settings: &[Setting {
                key: "span_m",
                unit: "m",
                allowed: Allowed::Integer(Integers::at_least(0)),
                doc: "Span",
                value: |w| Value::Real(w.span_m),
            }],
        };
        let e = BAD.check(&good()).unwrap_err();
        assert!(
            matches!(e, SettingError::Mismatch { found: "real", .. }),
            "{e}"
        );
        assert_eq!(
            WING.setting("rigid").unwrap().comment(),
            "Rigid; true or false."
        );
    }
}
