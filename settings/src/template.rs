//! The commented TOML template of a file of declared tables: the caller's
//! plain TOML of the default values (so the template always parses back
//! to the default), each table header under its doc and each key under
//! its setting's comment (doc, range and unit). Imports
//! [`crate::setting`].

use crate::setting::Table;

/// Width the comments are wrapped to, `# ` included.
const WIDTH: usize = 80;

/// The declared tables of a file, ready to comment its TOML.
#[derive(Clone, Debug, Default)]
pub struct Template {
    header: String,
    tables: Vec<Commented>,
}

/// One table's comments.
#[derive(Clone, Debug)]
struct Commented {
    name: &'static str,
    doc: &'static str,
    /// Each key with its doc and its range text.
    keys: Vec<(&'static str, &'static str, String)>,
}

/// Why a template could not be rendered: the TOML and the declarations
/// disagree (a bug: declare the new key, or drop the stale declaration).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum TemplateError {
    /// A table header with no declared table.
    #[error("configuration table [{table}] is not declared")]
    UndeclaredTable {
        /// The table.
        table: String,
    },
    /// A key with no declared setting.
    #[error("configuration key {table}.{key} is not declared")]
    UndeclaredKey {
        /// The table (empty for a key before any header).
        table: String,
        /// The key.
        key: String,
    },
    /// A declared setting the TOML does not write.
    #[error("declared configuration key {table}.{key} is not in the file")]
    Missing {
        /// The table.
        table: &'static str,
        /// The key.
        key: &'static str,
    },
}

impl Template {
    /// A template whose file starts with `header` (each line becomes a
    /// `# ` comment line).
    pub fn new(header: &str) -> Self {
        Self {
            header: header.to_string(),
            tables: Vec::new(),
        }
    }

    /// Adds a table's declarations.
    pub fn table<T>(mut self, table: &Table<T>) -> Self {
        self.tables.push(Commented {
            name: table.name,
            doc: table.doc,
            keys: table
                .settings
                .iter()
                .map(|s| (s.key, s.doc, s.limits().to_string()))
                .collect(),
        });
        self
    }

    /// Comments `plain`, a TOML text of `[table]` headers and one-line
    /// `key = value` entries (what `toml::to_string` writes for flat
    /// tables): every header and key must be declared, and every declared
    /// table and key present.
    pub fn render(&self, plain: &str) -> Result<String, TemplateError> {
        let mut out = String::new();
        for line in self.header.lines() {
            out.push_str(comment_line(line).trim_end());
            out.push('\n');
        }
        let mut table: Option<&Commented> = None;
        let mut seen: Vec<(&str, &str)> = Vec::new();
        for line in plain.lines() {
            let trimmed = line.trim();
            if let Some(name) = trimmed.strip_prefix('[').and_then(|t| t.strip_suffix(']')) {
                let t = self.tables.iter().find(|t| t.name == name).ok_or_else(|| {
                    TemplateError::UndeclaredTable {
                        table: name.to_string(),
                    }
                })?;
                out.push('\n');
                out.push_str(&wrap(t.doc, None));
                out.push_str(trimmed);
                out.push('\n');
                table = Some(t);
            } else if let Some((key, _)) = trimmed.split_once('=') {
                let key = key.trim();
                let undeclared = || TemplateError::UndeclaredKey {
                    table: table.map_or(String::new(), |t| t.name.to_string()),
                    key: key.to_string(),
                };
                let t = table.ok_or_else(undeclared)?;
                let (k, doc, limits) = t
                    .keys
                    .iter()
                    .find(|(k, _, _)| *k == key)
                    .ok_or_else(undeclared)?;
                seen.push((t.name, k));
                out.push_str(&wrap(doc, Some(limits)));
                out.push_str(trimmed);
                out.push('\n');
            } else if !trimmed.is_empty() {
                out.push_str(trimmed);
                out.push('\n');
            }
        }
        for t in &self.tables {
            for (k, _, _) in &t.keys {
                if !seen.contains(&(t.name, k)) {
                    return Err(TemplateError::Missing {
                        table: t.name,
                        key: k,
                    });
                }
            }
        }
        Ok(out)
    }
}

/// `# text`, or `#` for an empty line.
fn comment_line(text: &str) -> String {
    format!("# {text}")
}

/// `doc` as `# ` comment lines of at most [`WIDTH`] columns (a longer
/// word stands alone), each ending in a newline; with `limits`, the
/// [`crate::setting::Setting::comment`] form `<doc>; <limits>.`, the
/// limits never broken across lines.
fn wrap(doc: &str, limits: Option<&str>) -> String {
    let mut words: Vec<String> = doc.split_whitespace().map(str::to_string).collect();
    if let Some(limits) = limits {
        match words.last_mut() {
            Some(last) => *last = format!("{last}; {limits}."),
            None => words.push(format!("{limits}.")),
        }
    }
    let mut out = String::new();
    let mut line = String::from("#");
    for word in &words {
        if line.len() > 1 && line.len() + 1 + word.len() > WIDTH {
            out.push_str(&line);
            out.push('\n');
            line = String::from("#");
        }
        line.push(' ');
        line.push_str(word);
    }
    out.push_str(&line);
    out.push('\n');
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::range::{Allowed, Integers, Interval};
    use crate::setting::{Setting, Value};

    struct Motor {
        resistance_ohm: f64,
        poles: u32,
    }

    const MOTOR: Table<Motor> = Table {
        name: "motor",
        doc:
            "The DC motor driving the flapping linkage through the gearbox, as the plant models it.",
        settings: &[
            Setting {
                key: "resistance_ohm",
                unit: "ohm",
                allowed: Allowed::Real(Interval::positive()),
                doc: "Winding resistance",
                value: |m| Value::Real(m.resistance_ohm),
            },
            Setting {
                key: "poles",
                unit: "",
                allowed: Allowed::Integer(Integers::at_least(2)),
                doc: "Magnet poles",
                value: |m| Value::Integer(m.poles.into()),
            },
        ],
    };

    /// Headers and keys get their comments, wrapped; the values stay as
    /// the caller wrote them.
    #[test]
    fn renders_declared_comments() {
        let plain = "[motor]\nresistance_ohm = 1.5\npoles = 2\n";
        let text = Template::new("A motor file.\n\nEdit it.")
            .table(&MOTOR)
            .render(plain)
            .unwrap();
        assert_eq!(
            text,
            "# A motor file.\n#\n# Edit it.\n\n\
             # The DC motor driving the flapping linkage through the gearbox, as the plant\n\
             # models it.\n\
             [motor]\n\
             # Winding resistance; (0, inf) ohm.\n\
             resistance_ohm = 1.5\n\
             # Magnet poles; >= 2.\n\
             poles = 2\n"
        );
        assert!(MOTOR
            .check(&Motor {
                resistance_ohm: 1.5,
                poles: 2
            })
            .is_ok());
    }

    /// An undeclared table or key, or a declared key the file lacks, is an
    /// error.
    #[test]
    fn undeclared_and_missing_keys_are_errors() {
        let t = Template::new("").table(&MOTOR);
        assert_eq!(
            t.render("[motor]\nresistance_ohm = 1.5\npoles = 2\nturns = 3\n"),
            Err(TemplateError::UndeclaredKey {
                table: "motor".into(),
                key: "turns".into()
            })
        );
        assert_eq!(
            t.render("[gear]\nratio = 3\n"),
            Err(TemplateError::UndeclaredTable {
                table: "gear".into()
            })
        );
        assert_eq!(
            t.render("[motor]\nresistance_ohm = 1.5\n"),
            Err(TemplateError::Missing {
                table: "motor",
                key: "poles"
            })
        );
        assert!(matches!(
            t.render("top = 1\n"),
            Err(TemplateError::UndeclaredKey { .. })
        ));
    }
}
