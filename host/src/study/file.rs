//! The study file (TOML): a base design configuration and its
//! variations, the outputs to plot and the executors' settings.
//!
//! ```toml
//! [study]
//! name = "span-speed"             # default: the file's stem
//! base = "coarse.toml"            # a design file, relative to this one;
//!                                 # or inline tables [base.wing] ...;
//!                                 # neither: the built-in FWAV
//! outputs = ["ct", "efficiency"]  # plotted against each varied key
//!
//! [grid]                          # every combination of the values
//! wing.semi_span_m = [0.12, 0.15, 0.18]
//! flight.speed_m_s = [2.0, 3.0, 4.0]
//!
//! # or: [latin_hypercube] cases = 8, seed = 1,
//! #     wing.semi_span_m = [0.12, 0.18]   (low, high)
//! # or: [[case]] wing.semi_span_m = 0.12 ... (one table a case)
//!
//! [slurm]                         # `--executor slurm` (flags override)
//! partition = "compute"
//! time = "01:00:00"               # a case's time limit
//! cpus_per_task = 2
//! options = ["--account=myproject"]
//!
//! [local]
//! jobs = 2                        # cases at a time (`--jobs`)
//! ```
//!
//! Any key of the design file may vary, written `table.key` (quoted or
//! as TOML's dotted key): it must be declared ([`crate::config::keys`])
//! and its values of the declared kind; each case's configuration is then
//! checked whole by the design file's own check
//! ([`crate::config::SystemConfig::from_toml`]), in [`super::cases`].
//! Reading this file checks everything it can alone: the tables and
//! keys, the value kinds, the hypercube's ranges against the declared
//! ranges, the outputs, the Slurm settings.

use std::path::{Path, PathBuf};

use fwav_settings::{Allowed, Shown};
use serde::{Deserialize, Serialize};

use crate::config::keys::{declared, DeclaredKey, UnknownKey};

use super::results::Output;

/// The most cases a study may hold (a grid multiplies quickly).
pub const MAX_CASES: usize = 10_000;

/// The longest time between two looks at a Slurm queue, s: a day (a
/// longer one is a slip, and 1e300 s was more than a `Duration` holds).
pub const MAX_POLL_S: f64 = 86_400.0;

/// Where the base configuration comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum Base {
    /// The built-in FWAV (no base given).
    BuiltIn,
    /// The `[base]` tables of the study file.
    Inline,
    /// A design file (`[study] base`), as resolved.
    File(PathBuf),
}

/// How the cases are made.
#[derive(Clone, Debug, PartialEq)]
pub enum Variations {
    /// Every combination of the listed values; keys in the design file's
    /// order, the last varying fastest.
    Grid(Vec<(DeclaredKey, Vec<toml::Value>)>),
    /// A Latin hypercube of `cases` points over the ranges (one stratum
    /// of each range per case), drawn with `seed`.
    LatinHypercube {
        /// Number of cases.
        cases: usize,
        /// The random generator's seed.
        seed: u64,
        /// Each key with its range (low, high).
        ranges: Vec<(DeclaredKey, f64, f64)>,
    },
    /// The cases as listed, each with its own keys.
    List(Vec<Vec<(DeclaredKey, toml::Value)>>),
}

/// The `[slurm]` table: how `--executor slurm` submits (every key
/// optional; command-line flags override).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SlurmSettings {
    /// `--partition` (default: the cluster's default partition).
    pub partition: Option<String>,
    /// `--time`: a case's time limit, Slurm's forms (`MM`, `MM:SS`,
    /// `HH:MM:SS`, `D-HH`, `D-HH:MM`, `D-HH:MM:SS`).
    pub time: Option<String>,
    /// `--cpus-per-task` (default 2: a design runs its two disciplines
    /// side by side).
    pub cpus_per_task: Option<u32>,
    /// `--mem` (e.g. `4G`; default: the cluster's).
    pub mem: Option<String>,
    /// At most this many cases at once (the array's `%N`).
    pub max_parallel: Option<usize>,
    /// Further `#SBATCH` options, each as on sbatch's command line
    /// (`--account=proj`, `--qos=long`).
    pub options: Vec<String>,
    /// Seconds between two looks at the queue (default 10).
    pub poll_s: Option<f64>,
}

/// The `[local]` table.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LocalSettings {
    /// Cases at a time (default 1).
    pub jobs: Option<usize>,
}

/// A study file, read and checked.
#[derive(Clone, Debug, PartialEq)]
pub struct StudyFile {
    /// The file read.
    pub path: PathBuf,
    /// The study's name.
    pub name: String,
    /// Where the base configuration comes from.
    pub base_source: Base,
    /// The base configuration's TOML tables (empty: every key default).
    pub base: toml::Table,
    /// The variations.
    pub variations: Variations,
    /// The outputs plotted against each varied key.
    pub outputs: Vec<Output>,
    /// Slurm's settings.
    pub slurm: SlurmSettings,
    /// The local pool's settings.
    pub local: LocalSettings,
}

/// Why a study file was refused.
#[derive(Debug, thiserror::Error)]
pub enum StudyFileError {
    /// The file (or its base file) could not be read.
    #[error("cannot read {}: {source}", .path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// Not TOML, or a table or key the study file does not have.
    #[error("{}: {source}", .path.display())]
    Parse {
        /// The file.
        path: PathBuf,
        /// The parser's complaint (names the key and line).
        source: toml::de::Error,
    },
    /// Both a base file and inline `[base]` tables.
    #[error("both [study] base = {file:?} and [base] tables are given: keep one")]
    TwoBases {
        /// The base file named.
        file: String,
    },
    /// No variation, or more than one kind.
    #[error(
        "the study needs exactly one of [grid], [latin_hypercube] or [[case]] (found {})",
        if .found.is_empty() { "none".to_string() } else { .found.join(", ") }
    )]
    Variations {
        /// The kinds given.
        found: Vec<&'static str>,
    },
    /// A key that is not a design key.
    #[error("{place}: {source}")]
    Key {
        /// Where (`[grid]`, `case 003`).
        place: String,
        /// Which key and the nearest declared one.
        source: UnknownKey,
    },
    /// A table nested deeper than `table.key`.
    #[error("{place}: `{key}` is nested too deep: design keys are `table.key`")]
    Nested {
        /// Where.
        place: String,
        /// The path found.
        key: String,
    },
    /// A value of the wrong kind for its key.
    #[error("{place}: {key} = {value} is not {expected} ({key} allows {limits})")]
    Kind {
        /// Where.
        place: String,
        /// The key.
        key: String,
        /// The value given, as TOML.
        value: String,
        /// What it must be (`a number`, `an integer`, ...).
        expected: &'static str,
        /// The declared range.
        limits: String,
    },
    /// A grid key without a non-empty list of values.
    #[error("[grid] {key} must be a non-empty list of values, e.g. {key} = [1.0, 2.0]")]
    GridValues {
        /// The key.
        key: String,
    },
    /// A hypercube setting out of place.
    #[error("[latin_hypercube] {what}")]
    Hypercube {
        /// What is wrong.
        what: String,
    },
    /// A hypercube range outside its key's declared range.
    #[error(
        "[latin_hypercube] {key} = [{low}, {high}] reaches outside {key}'s allowed range {limits}"
    )]
    RangeOutside {
        /// The key.
        key: String,
        /// Its range's low end.
        low: f64,
        /// Its high end.
        high: f64,
        /// The declared range.
        limits: String,
    },
    /// Too many cases.
    #[error("the study has {count} cases, more than {MAX_CASES}: split it")]
    TooMany {
        /// Cases the variations make.
        count: usize,
    },
    /// An output that does not exist.
    #[error("[study] outputs: `{name}` is not an output; choose among {}", Output::names().join(", "))]
    Output {
        /// The name given.
        name: String,
    },
    /// A Slurm or local setting that cannot be used.
    #[error("[{table}] {key} = {value}: {why}")]
    Setting {
        /// `slurm` or `local`.
        table: &'static str,
        /// The key.
        key: &'static str,
        /// The value given.
        value: String,
        /// What is wrong.
        why: String,
    },
}

/// The file as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Text {
    #[serde(default)]
    study: StudyTable,
    base: Option<toml::Table>,
    grid: Option<toml::Table>,
    latin_hypercube: Option<toml::Table>,
    case: Option<Vec<toml::Table>>,
    #[serde(default)]
    slurm: SlurmSettings,
    #[serde(default)]
    local: LocalSettings,
}

/// The `[study]` table.
#[derive(Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct StudyTable {
    name: Option<String>,
    base: Option<String>,
    outputs: Option<Vec<String>>,
}

impl StudyFile {
    /// Reads and checks the study file at `path` (module docs), and its
    /// base file if it names one.
    pub fn read(path: &Path) -> Result<Self, StudyFileError> {
        let text = std::fs::read_to_string(path).map_err(|source| StudyFileError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        Self::parse(path, &text)
    }

    /// Checks the text of a study file read from `path` (which names it
    /// and locates a relative base file).
    pub fn parse(path: &Path, text: &str) -> Result<Self, StudyFileError> {
        let parse_error = |source| StudyFileError::Parse {
            path: path.to_path_buf(),
            source,
        };
        let t: Text = toml::from_str(text).map_err(parse_error)?;
        let (base_source, base) = match (t.study.base, t.base) {
            (Some(file), Some(_)) => return Err(StudyFileError::TwoBases { file }),
            (Some(file), None) => {
                let resolved = path.parent().unwrap_or(Path::new("")).join(&file);
                let text =
                    std::fs::read_to_string(&resolved).map_err(|source| StudyFileError::Read {
                        path: resolved.clone(),
                        source,
                    })?;
                let table = toml::from_str(&text).map_err(|source| StudyFileError::Parse {
                    path: resolved.clone(),
                    source,
                })?;
                (Base::File(resolved), table)
            }
            (None, Some(table)) => (Base::Inline, table),
            (None, None) => (Base::BuiltIn, toml::Table::new()),
        };
        let found: Vec<&'static str> = [
            ("[grid]", t.grid.is_some()),
            ("[latin_hypercube]", t.latin_hypercube.is_some()),
            ("[[case]]", t.case.is_some()),
        ]
        .into_iter()
        .filter_map(|(name, given)| given.then_some(name))
        .collect();
        let variations = match (t.grid, t.latin_hypercube, t.case) {
            (Some(g), None, None) => grid(&g)?,
            (None, Some(h), None) => hypercube(&h)?,
            (None, None, Some(list)) => cases(&list)?,
            _ => return Err(StudyFileError::Variations { found }),
        };
        let count = case_count(&variations);
        if count > MAX_CASES {
            return Err(StudyFileError::TooMany { count });
        }
        let outputs = match t.study.outputs {
            None => Output::DEFAULT.to_vec(),
            Some(names) => names
                .into_iter()
                .map(|name| Output::named(&name).ok_or(StudyFileError::Output { name }))
                .collect::<Result<_, _>>()?,
        };
        check_slurm(&t.slurm)?;
        if t.local.jobs == Some(0) {
            return Err(setting("local", "jobs", "0", "at least 1 case at a time"));
        }
        if let Some(blank) = t.study.name.as_ref().filter(|n| n.trim().is_empty()) {
            return Err(setting(
                "study",
                "name",
                &format!("{blank:?}"),
                "a name for the report and the Slurm jobs; or leave the key out for the file's name",
            ));
        }
        let name = t.study.name.unwrap_or_else(|| {
            path.file_stem()
                .map_or_else(|| "study".to_string(), |s| s.to_string_lossy().into_owned())
        });
        Ok(Self {
            path: path.to_path_buf(),
            name,
            base_source,
            base,
            variations,
            outputs,
            slurm: t.slurm,
            local: t.local,
        })
    }

    /// The varied keys, in the design file's order.
    pub fn keys(&self) -> Vec<DeclaredKey> {
        let mut keys: Vec<DeclaredKey> = match &self.variations {
            Variations::Grid(g) => g.iter().map(|(k, _)| *k).collect(),
            Variations::LatinHypercube { ranges, .. } => ranges.iter().map(|(k, ..)| *k).collect(),
            Variations::List(list) => list.iter().flatten().map(|(k, _)| *k).collect(),
        };
        sort_by_declaration(&mut keys);
        keys.dedup();
        keys
    }
}

/// The number of cases the variations make.
fn case_count(v: &Variations) -> usize {
    match v {
        Variations::Grid(g) => g
            .iter()
            .map(|(_, values)| values.len())
            .fold(1usize, usize::saturating_mul),
        Variations::LatinHypercube { cases, .. } => *cases,
        Variations::List(list) => list.len(),
    }
}

/// A key's place in the design file ([`crate::config::keys::all`]).
fn declaration_order() -> impl Fn(&DeclaredKey) -> usize {
    let order = crate::config::keys::all();
    move |k| order.iter().position(|o| o == k).unwrap_or(usize::MAX)
}

/// Keys in the design file's order.
fn sort_by_declaration(keys: &mut [DeclaredKey]) {
    keys.sort_by_key(declaration_order());
}

/// The entries of a variation table as `(table.key, value)`: a nested
/// table `[grid.wing]` or a dotted key `wing.semi_span_m` becomes
/// `wing.semi_span_m`, as does a quoted `"wing.semi_span_m"`.
fn flatten(
    table: &toml::Table,
    place: &str,
    skip: &[&str],
) -> Result<Vec<(DeclaredKey, toml::Value)>, StudyFileError> {
    let mut entries = Vec::new();
    for (name, value) in table {
        if skip.contains(&name.as_str()) {
            continue;
        }
        let mut push = |qualified: String, value: &toml::Value| {
            let key = declared(&qualified).map_err(|source| StudyFileError::Key {
                place: place.to_string(),
                source,
            })?;
            entries.push((key, value.clone()));
            Ok::<(), StudyFileError>(())
        };
        match value {
            toml::Value::Table(inner) => {
                for (key, value) in inner {
                    if value.is_table() {
                        return Err(StudyFileError::Nested {
                            place: place.to_string(),
                            key: format!("{name}.{key}"),
                        });
                    }
                    push(format!("{name}.{key}"), value)?;
                }
            }
            _ => push(name.clone(), value)?,
        }
    }
    Ok(entries)
}

/// What a value of `key` must be, and `value` made so (an integer where
/// a real is declared becomes a real), or the error at `place`.
pub fn of_kind(
    key: &DeclaredKey,
    value: &toml::Value,
    place: &str,
) -> Result<toml::Value, StudyFileError> {
    use toml::Value as V;
    let number = |v: &V| match v {
        V::Float(x) => Some(*x),
        V::Integer(n) => Some(*n as f64),
        _ => None,
    };
    let (made, expected) = match key.limits.allowed {
        Allowed::Real(_) => (number(value).map(V::Float), "a number"),
        Allowed::Integer(_) => (value.as_integer().map(V::Integer), "an integer"),
        Allowed::Increasing(_) => (
            value
                .as_array()
                .and_then(|xs| xs.iter().map(number).collect::<Option<Vec<f64>>>())
                .map(|xs| V::Array(xs.into_iter().map(V::Float).collect())),
            "a list of numbers",
        ),
        Allowed::Flag => (value.as_bool().map(V::Boolean), "true or false"),
        Allowed::Choice(_) => (value.as_str().map(|s| V::String(s.into())), "a word"),
    };
    made.ok_or_else(|| StudyFileError::Kind {
        place: place.to_string(),
        key: key.to_string(),
        value: value.to_string(),
        expected,
        limits: key.limits.to_string(),
    })
}

/// The `[grid]` table.
fn grid(table: &toml::Table) -> Result<Variations, StudyFileError> {
    let mut keys = Vec::new();
    for (key, values) in flatten(table, "[grid]", &[])? {
        let list = match values.as_array() {
            Some(list) if !list.is_empty() => list,
            _ => {
                return Err(StudyFileError::GridValues {
                    key: key.to_string(),
                })
            }
        };
        let values = list
            .iter()
            .map(|v| of_kind(&key, v, "[grid]"))
            .collect::<Result<Vec<_>, _>>()?;
        keys.push((key, values));
    }
    if keys.is_empty() {
        return Err(StudyFileError::GridValues {
            key: "table.key".into(),
        });
    }
    let position = declaration_order();
    keys.sort_by_key(|(k, _)| position(k));
    Ok(Variations::Grid(keys))
}

/// The `[latin_hypercube]` table: `cases`, `seed` and a range
/// `[low, high]` for each key (reals and integers only).
fn hypercube(table: &toml::Table) -> Result<Variations, StudyFileError> {
    let bad = |what: String| StudyFileError::Hypercube { what };
    let cases = match table.get("cases") {
        Some(toml::Value::Integer(n)) if *n >= 1 => *n as usize,
        Some(v) => return Err(bad(format!("cases = {v}: a number of cases, at least 1"))),
        None => return Err(bad("needs cases = N, the number of cases".into())),
    };
    let seed = match table.get("seed") {
        Some(toml::Value::Integer(n)) if *n >= 0 => *n as u64,
        Some(v) => return Err(bad(format!("seed = {v}: a whole number, 0 or more"))),
        None => 1,
    };
    let mut ranges = Vec::new();
    for (key, range) in flatten(table, "[latin_hypercube]", &["cases", "seed"])? {
        let interval = match key.limits.allowed {
            Allowed::Real(i) => i,
            Allowed::Integer(r) => fwav_settings::Interval {
                low: fwav_settings::Bound::Closed(r.min as f64),
                high: r.max.map_or(fwav_settings::Bound::Unbounded, |m| {
                    fwav_settings::Bound::Closed(m as f64)
                }),
            },
            _ => {
                return Err(bad(format!(
                    "{key} takes {}: only numeric keys can be sampled (list its values in \
                     [grid] or [[case]] instead)",
                    key.limits
                )))
            }
        };
        let pair = range.as_array().map(|xs| {
            xs.iter()
                .map(|x| x.as_float().or_else(|| x.as_integer().map(|n| n as f64)))
                .collect::<Option<Vec<f64>>>()
        });
        let [low, high] = match pair {
            Some(Some(v)) if v.len() == 2 && v[0] < v[1] => [v[0], v[1]],
            _ => {
                return Err(bad(format!(
                    "{key} = {range}: a range [low, high] with low < high"
                )))
            }
        };
        if !(interval.contains(low) && interval.contains(high)) {
            return Err(StudyFileError::RangeOutside {
                key: key.to_string(),
                low,
                high,
                limits: key.limits.to_string(),
            });
        }
        ranges.push((key, low, high));
    }
    let position = declaration_order();
    ranges.sort_by_key(|(k, ..)| position(k));
    if ranges.is_empty() {
        return Err(bad(
            "needs at least one key with its range, e.g. wing.semi_span_m = [0.12, 0.18]".into(),
        ));
    }
    Ok(Variations::LatinHypercube {
        cases,
        seed,
        ranges,
    })
}

/// The `[[case]]` tables.
fn cases(list: &[toml::Table]) -> Result<Variations, StudyFileError> {
    let mut cases = Vec::new();
    let position = declaration_order();
    for (i, table) in list.iter().enumerate() {
        let place = super::cases::case_name(i + 1, list.len());
        let mut entries = flatten(table, &place, &[])?
            .into_iter()
            .map(|(key, value)| Ok((key, of_kind(&key, &value, &place)?)))
            .collect::<Result<Vec<_>, StudyFileError>>()?;
        entries.sort_by_key(|(k, _)| position(k));
        cases.push(entries);
    }
    Ok(Variations::List(cases))
}

/// A setting error.
fn setting(table: &'static str, key: &'static str, value: &str, why: &str) -> StudyFileError {
    StudyFileError::Setting {
        table,
        key,
        value: value.to_string(),
        why: why.to_string(),
    }
}

/// Whether `time` is one of Slurm's time forms.
pub fn is_slurm_time(time: &str) -> bool {
    let numbers = |s: &str, most: usize| {
        let parts: Vec<&str> = s.split(':').collect();
        parts.len() <= most
            && parts
                .iter()
                .all(|p| !p.is_empty() && p.chars().all(|c| c.is_ascii_digit()))
    };
    match time.split_once('-') {
        Some((days, rest)) => {
            !days.is_empty() && days.chars().all(|c| c.is_ascii_digit()) && numbers(rest, 3)
        }
        None => numbers(time, 3),
    }
}

/// Checks the `[slurm]` table (also used on the command line's flags).
pub fn check_slurm(s: &SlurmSettings) -> Result<(), StudyFileError> {
    let word = |v: &str| !v.is_empty() && !v.chars().any(|c| c.is_whitespace() || c == '\'');
    if let Some(p) = &s.partition {
        if !word(p) {
            return Err(setting(
                "slurm",
                "partition",
                p,
                "a partition name, one word",
            ));
        }
    }
    if let Some(t) = &s.time {
        if !is_slurm_time(t) {
            return Err(setting(
                "slurm",
                "time",
                t,
                "one of Slurm's forms: MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS",
            ));
        }
    }
    if s.cpus_per_task == Some(0) {
        return Err(setting("slurm", "cpus_per_task", "0", "at least 1"));
    }
    if let Some(m) = &s.mem {
        if !word(m) {
            return Err(setting("slurm", "mem", m, "a size such as 4G, one word"));
        }
    }
    if s.max_parallel == Some(0) {
        return Err(setting("slurm", "max_parallel", "0", "at least 1"));
    }
    for o in &s.options {
        if !o.starts_with('-') || o.contains('\n') {
            return Err(setting(
                "slurm",
                "options",
                o,
                "each an sbatch option on one line, such as --account=proj",
            ));
        }
    }
    if let Some(p) = s.poll_s {
        if !(p > 0.0 && p <= MAX_POLL_S) {
            return Err(setting(
                "slurm",
                "poll_s",
                &Shown(p).to_string(),
                "a positive number of seconds, at most a day (86400)",
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<StudyFile, StudyFileError> {
        StudyFile::parse(Path::new("/nowhere/s.toml"), text)
    }

    /// A grid's keys in either TOML form, ordered as the design file
    /// declares them; integers given for reals become reals.
    #[test]
    fn grid_keys_are_read_in_the_design_files_order() {
        let s =
            parse("[grid]\nflight.speed_m_s = [2, 3]\n\"wing.semi_span_m\" = [0.12, 0.15, 0.18]\n")
                .unwrap();
        assert_eq!(s.name, "s");
        assert_eq!(s.base_source, Base::BuiltIn);
        let Variations::Grid(g) = &s.variations else {
            panic!("{:?}", s.variations)
        };
        assert_eq!(g[0].0.to_string(), "wing.semi_span_m");
        assert_eq!(g[1].0.to_string(), "flight.speed_m_s");
        assert_eq!(
            g[1].1,
            vec![toml::Value::Float(2.0), toml::Value::Float(3.0)]
        );
        assert_eq!(s.outputs, Output::DEFAULT.to_vec());
    }

    /// Every kind of mistake is refused naming its place and key.
    #[test]
    fn mistakes_are_named() {
        let e = |text: &str| parse(text).unwrap_err().to_string();
        assert_eq!(
            e("[grid]\nwing.semi_span = [0.1]\n"),
            "[grid]: `wing.semi_span` is not a key of the design file: did you mean \
             `wing.semi_span_m`? (`fwav init` lists every key)"
        );
        assert_eq!(
            e("[[case]]\nwing.semi_span_m = 0.1\n[[case]]\nwing.span_elements = 2.5\n"),
            "case 002: wing.span_elements = 2.5 is not an integer (wing.span_elements allows 2..=400)"
        );
        assert_eq!(
            e("[grid]\nflight.speed_m_s = 3\n"),
            "[grid] flight.speed_m_s must be a non-empty list of values, e.g. \
             flight.speed_m_s = [1.0, 2.0]"
        );
        assert!(e("[study]\nname = \"x\"\n").contains("exactly one of [grid]"));
        assert!(
            e("[grid]\nwing.semi_span_m = [0.1]\n[[case]]\nwing.semi_span_m = 0.1\n")
                .contains("found [grid], [[case]]")
        );
        assert_eq!(
            e("[latin_hypercube]\ncases = 4\nwing.semi_span_m = [0.005, 0.2]\n"),
            "[latin_hypercube] wing.semi_span_m = [0.005, 0.2] reaches outside \
             wing.semi_span_m's allowed range [0.01, 2] m"
        );
        assert!(e("[latin_hypercube]\nwing.semi_span_m = [0.1, 0.2]\n").contains("cases = N"));
        assert!(
            e("[latin_hypercube]\ncases = 3\nactuator.spring = [1, 2]\n")
                .contains("only numeric keys")
        );
        assert!(
            e("[grid]\nwing.semi_span_m = [0.1]\n[study]\noutputs = [\"thrust\"]\n").starts_with(
                "[study] outputs: `thrust` is not an output; choose among frequency_hz, "
            )
        );
        assert!(
            e("[grid]\nwing.semi_span_m = [0.1]\n[slurm]\ntime = \"1h\"\n")
                .starts_with("[slurm] time = 1h: one of Slurm's forms")
        );
        assert!(
            e("[grid]\nwing.semi_span_m = [0.1]\n[slurm]\nqueue = \"x\"\n")
                .contains("unknown field `queue`")
        );
        assert!(
            e("[grid]\nwing.semi_span_m = [0.1]\n[study]\nbase = \"missing.toml\"\n")
                .starts_with("cannot read /nowhere/missing.toml")
        );
        assert!(
            e("[grid]\nwing.semi_span_m = [0.1]\n[study]\nname = \" \"\n")
                .starts_with("[study] name = \" \": a name for the report")
        );
        let big = "[grid]\nwing.semi_span_m = [0.1, 0.11, 0.12, 0.13, 0.14, 0.15, 0.16, 0.17, \
                   0.18, 0.19, 0.2]\nflight.speed_m_s = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]\n\
                   kinematics.frequency_hz = [8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18]\n\
                   kinematics.amplitude_deg = [20, 25, 30, 35, 40, 45, 50, 55]\n";
        assert!(e(big).starts_with("the study has 10648 cases"));
    }

    /// The time between two looks at the queue: positive and at most a
    /// day. 1e300 s overflowed the `Duration` it is waited as (a panic),
    /// and -1e300 was named as 301 digits.
    #[test]
    fn the_poll_is_a_positive_time_up_to_a_day() {
        let poll = |p: f64| {
            check_slurm(&SlurmSettings {
                poll_s: Some(p),
                ..SlurmSettings::default()
            })
        };
        assert!(poll(10.0).is_ok() && poll(MAX_POLL_S).is_ok());
        for (p, shown) in [
            (0.0, "poll_s = 0"),
            (-1e300, "poll_s = -1e300"),
            (1e300, "poll_s = 1e300"),
            (f64::NAN, "poll_s = NaN"),
        ] {
            let e = poll(p).unwrap_err().to_string();
            assert!(e.contains(shown) && e.contains("at most a day"), "{e}");
        }
    }

    /// Slurm's time forms.
    #[test]
    fn slurm_times() {
        for t in ["30", "30:00", "1:00:00", "2-0", "2-12:00", "2-12:00:00"] {
            assert!(is_slurm_time(t), "{t}");
        }
        for t in ["", "1h", "1:2:3:4", "-1", "a-1", "1-"] {
            assert!(!is_slurm_time(t), "{t}");
        }
    }
}
