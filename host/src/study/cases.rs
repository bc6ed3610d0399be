//! A study's cases: made from its variations (every combination of a
//! grid, the points of a Latin hypercube, or the listed cases), each
//! applied to the base configuration and checked whole by the design
//! file's own check, so that a bad case is refused — named with its
//! number, its values and the key at fault — before anything is written
//! or submitted.

use fwav_settings::Allowed;
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::config::keys::DeclaredKey;
use crate::config::{ConfigError, SystemConfig};

use super::file::{StudyFile, Variations};

/// One case: its number (from 1) and the values it sets.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// Its number, from 1 (the Slurm array index and the directory
    /// `cases/NNN`).
    pub number: usize,
    /// The keys it sets and their values.
    pub values: Vec<(DeclaredKey, toml::Value)>,
}

/// A case with its whole configuration, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct PreparedCase {
    /// The case.
    pub case: Case,
    /// Its configuration: the base with the case's values.
    pub config: SystemConfig,
}

/// A case refused.
#[derive(Debug, thiserror::Error)]
#[error("{case} ({values}): {source}")]
pub struct CaseError {
    /// `case 003`.
    pub case: String,
    /// Its values, `key = value, ...`.
    pub values: String,
    /// What the design file's check says (names the key).
    pub source: ConfigError,
}

/// Cases refused: every one of them (the first ten listed).
#[derive(Debug, thiserror::Error)]
#[error(
    "{} of {total} cases refused; nothing was written or submitted:\n  {}{}",
    .errors.len(),
    .errors.iter().take(10).map(ToString::to_string).collect::<Vec<_>>().join("\n  "),
    if .errors.len() > 10 { format!("\n  and {} more", .errors.len() - 10) } else { String::new() }
)]
pub struct CasesRefused {
    /// The cases of the study.
    pub total: usize,
    /// Each refused case.
    pub errors: Vec<CaseError>,
}

/// Digits of a case number in names: three, or more for a bigger study.
pub fn width(total: usize) -> usize {
    total.max(1).to_string().len().max(3)
}

/// A case's number as its directory name (`003`).
pub fn dir_name(number: usize, total: usize) -> String {
    format!("{number:0w$}", w = width(total))
}

/// A case as people read it (`case 003`).
pub fn case_name(number: usize, total: usize) -> String {
    format!("case {}", dir_name(number, total))
}

/// `key = value, ...`.
pub fn values_text(values: &[(DeclaredKey, toml::Value)]) -> String {
    values
        .iter()
        .map(|(k, v)| format!("{k} = {v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The cases the variations make, numbered from 1.
pub fn generate(variations: &Variations) -> Vec<Case> {
    let rows: Vec<Vec<(DeclaredKey, toml::Value)>> = match variations {
        Variations::Grid(keys) => grid(keys),
        Variations::LatinHypercube {
            cases,
            seed,
            ranges,
        } => hypercube(*cases, *seed, ranges),
        Variations::List(list) => list.clone(),
    };
    rows.into_iter()
        .enumerate()
        .map(|(i, values)| Case {
            number: i + 1,
            values,
        })
        .collect()
}

/// Every combination, the last key varying fastest.
fn grid(keys: &[(DeclaredKey, Vec<toml::Value>)]) -> Vec<Vec<(DeclaredKey, toml::Value)>> {
    let mut rows = vec![Vec::new()];
    for (key, values) in keys {
        rows = rows
            .into_iter()
            .flat_map(|row| {
                values.iter().map(move |v| {
                    let mut next = row.clone();
                    next.push((*key, v.clone()));
                    next
                })
            })
            .collect();
    }
    rows
}

/// `x` to 6 significant digits (a sample people read).
fn significant(x: f64) -> f64 {
    format!("{x:.5e}").parse().unwrap_or(x)
}

/// A Latin hypercube: for each key its range cut into `n` equal strata,
/// one point drawn uniformly in each, the strata shuffled per key; reals
/// to 6 significant digits, integers rounded, within the range.
fn hypercube(
    n: usize,
    seed: u64,
    ranges: &[(DeclaredKey, f64, f64)],
) -> Vec<Vec<(DeclaredKey, toml::Value)>> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let columns: Vec<Vec<toml::Value>> = ranges
        .iter()
        .map(|(key, low, high)| {
            let mut strata: Vec<usize> = (0..n).collect();
            strata.shuffle(&mut rng);
            strata
                .into_iter()
                .map(|s| {
                    let u: f64 = rng.random();
                    let x = low + (s as f64 + u) / n as f64 * (high - low);
                    match key.limits.allowed {
                        Allowed::Integer(_) => toml::Value::Integer(x.round() as i64),
                        _ => toml::Value::Float(significant(x).clamp(*low, *high)),
                    }
                })
                .collect()
        })
        .collect();
    (0..n)
        .map(|i| {
            ranges
                .iter()
                .zip(&columns)
                .map(|((key, ..), column)| (*key, column[i].clone()))
                .collect()
        })
        .collect()
}

/// The base with `values` set (a base table that is not a table is left
/// for the design file's check to name).
fn applied(base: &toml::Table, values: &[(DeclaredKey, toml::Value)]) -> toml::Table {
    let mut table = base.clone();
    for (key, value) in values {
        let entry = table
            .entry(key.table)
            .or_insert_with(|| toml::Value::Table(toml::Table::new()));
        if let Some(t) = entry.as_table_mut() {
            t.insert(key.key.to_string(), value.clone());
        }
    }
    table
}

/// The configuration of one case: the base with its values, checked by
/// the design file's own check (every range and cross-table rule) and
/// its wing built (the design run's first step).
pub fn configuration(base: &toml::Table, case: &Case) -> Result<SystemConfig, ConfigError> {
    let table = applied(base, &case.values);
    let text = toml::to_string(&table).unwrap_or_default();
    let config = SystemConfig::from_toml(&text)?;
    config.wing_model()?;
    Ok(config)
}

/// Every case of `study`, configured and checked; the refusal lists every
/// bad case.
pub fn prepare(study: &StudyFile) -> Result<Vec<PreparedCase>, CasesRefused> {
    let cases = generate(&study.variations);
    let total = cases.len();
    let mut prepared = Vec::new();
    let mut errors = Vec::new();
    for case in cases {
        match configuration(&study.base, &case) {
            Ok(config) => prepared.push(PreparedCase { case, config }),
            Err(source) => errors.push(CaseError {
                case: case_name(case.number, total),
                values: values_text(&case.values),
                source,
            }),
        }
    }
    if errors.is_empty() {
        Ok(prepared)
    } else {
        Err(CasesRefused { total, errors })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::keys::declared;
    use std::path::Path;

    fn study(text: &str) -> StudyFile {
        StudyFile::parse(Path::new("s.toml"), text).unwrap()
    }

    fn floats(cases: &[Case], key: usize) -> Vec<f64> {
        cases
            .iter()
            .map(|c| c.values[key].1.as_float().unwrap())
            .collect()
    }

    /// A grid makes every combination, the last key fastest.
    #[test]
    fn grid_makes_every_combination() {
        let s =
            study("[grid]\nflight.speed_m_s = [2.0, 3.0]\nwing.semi_span_m = [0.12, 0.15, 0.18]\n");
        let cases = generate(&s.variations);
        assert_eq!(cases.len(), 6);
        assert_eq!(floats(&cases, 0), [0.12, 0.12, 0.15, 0.15, 0.18, 0.18]);
        assert_eq!(floats(&cases, 1), [2.0, 3.0, 2.0, 3.0, 2.0, 3.0]);
        assert_eq!((cases[0].number, cases[5].number), (1, 6));
        assert_eq!(
            values_text(&cases[1].values),
            "wing.semi_span_m = 0.12, flight.speed_m_s = 3.0"
        );
        let prepared = prepare(&s).unwrap();
        assert_eq!(prepared[3].config.wing.semi_span_m, 0.15);
        assert_eq!(prepared[3].config.flight.speed_m_s, 3.0);
        assert_eq!(
            prepared[3].config.kinematics,
            SystemConfig::default().kinematics
        );
    }

    /// A Latin hypercube puts one point in each of the `n` strata of
    /// every range, the same points for the same seed and others for
    /// another; integers are whole and within their range.
    #[test]
    fn latin_hypercube_fills_every_stratum_once() {
        let text = |seed: u64| {
            format!(
                "[latin_hypercube]\ncases = 7\nseed = {seed}\nwing.semi_span_m = [0.12, 0.19]\n\
                 topology.mass_fraction = [0.2, 0.6]\nwing.span_elements = [10, 16]\n"
            )
        };
        let cases = generate(&study(&text(3)).variations);
        assert_eq!(cases.len(), 7);
        for (key, low, high) in [(0, 0.12, 0.19), (2, 0.2, 0.6)] {
            let mut strata: Vec<usize> = floats(&cases, key)
                .iter()
                .map(|x| {
                    assert!((low..=high).contains(x), "{x}");
                    ((x - low) / (high - low) * 7.0).floor().min(6.0) as usize
                })
                .collect();
            strata.sort();
            assert_eq!(strata, (0..7).collect::<Vec<_>>(), "key {key}");
        }
        for c in &cases {
            let n = c.values[1].1.as_integer().unwrap();
            assert!((10..=16).contains(&n), "{n}");
        }
        assert_eq!(generate(&study(&text(3)).variations), cases);
        assert_ne!(generate(&study(&text(4)).variations), cases);
    }

    /// A bad case is refused before anything happens, naming the case,
    /// its values and the key; every bad case is listed.
    #[test]
    fn bad_cases_name_the_case_and_the_key() {
        let s = study(
            "[[case]]\nwing.semi_span_m = 0.12\n[[case]]\nwing.semi_span_m = 5.0\n\
             [[case]]\ntopology.mass_fraction = 1.5\n",
        );
        let e = prepare(&s).unwrap_err();
        assert_eq!(e.errors.len(), 2);
        assert_eq!(
            e.to_string(),
            "2 of 3 cases refused; nothing was written or submitted:\n  \
             case 002 (wing.semi_span_m = 5.0): wing.semi_span_m = 5 is outside [0.01, 2] m\n  \
             case 003 (topology.mass_fraction = 1.5): topology.mass_fraction = 1.5 is outside \
             [0.2, 1]"
        );
        // A cross-table rule names its keys too.
        let s = study("[grid]\nwing.root_attachment_m = [0.01, 0.5]\n");
        let e = prepare(&s).unwrap_err().to_string();
        assert!(
            e.contains("case 002 (wing.root_attachment_m = 0.5): ")
                && e.contains("wing.root_attachment_m"),
            "{e}"
        );
        assert_eq!(dir_name(7, 9), "007");
        assert_eq!(dir_name(7, 1500), "0007");
        assert!(declared("wing.semi_span_m").is_ok());
    }
}
