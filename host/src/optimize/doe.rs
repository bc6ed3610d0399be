//! Orthogonal arrays for design of experiments: the Taguchi L18
//! (2^1 × 3^7) array, assignment of factors to its columns, and the mapping
//! of levels to physical values.
//!
//! Levels are 0-based indices throughout (the printed Taguchi tables count
//! from 1). Reference: the L18 table in `shared/REFERENCES.md`, section
//! "Design of experiments and optimization" (Taguchi's standard L18,
//! columns A..H, A two-level).

/// The Taguchi L18 array with 0-based levels: 18 runs × 8 columns A..H.
/// Column A has two levels, columns B..H three.
///
/// Transcribed from the standard table (REFERENCES.md) by subtracting 1
/// from every entry.
pub const L18_RUNS: [[u8; 8]; 18] = [
    [0, 0, 0, 0, 0, 0, 0, 0],
    [0, 0, 1, 1, 1, 1, 1, 1],
    [0, 0, 2, 2, 2, 2, 2, 2],
    [0, 1, 0, 0, 1, 1, 2, 2],
    [0, 1, 1, 1, 2, 2, 0, 0],
    [0, 1, 2, 2, 0, 0, 1, 1],
    [0, 2, 0, 1, 0, 2, 1, 2],
    [0, 2, 1, 2, 1, 0, 2, 0],
    [0, 2, 2, 0, 2, 1, 0, 1],
    [1, 0, 0, 2, 2, 1, 1, 0],
    [1, 0, 1, 0, 0, 2, 2, 1],
    [1, 0, 2, 1, 1, 0, 0, 2],
    [1, 1, 0, 1, 2, 0, 2, 1],
    [1, 1, 1, 2, 0, 1, 0, 2],
    [1, 1, 2, 0, 1, 2, 1, 0],
    [1, 2, 0, 2, 1, 2, 0, 1],
    [1, 2, 1, 0, 2, 0, 1, 2],
    [1, 2, 2, 1, 0, 1, 2, 0],
];

/// Number of levels of each L18 column A..H.
pub const L18_LEVELS: [u8; 8] = [2, 3, 3, 3, 3, 3, 3, 3];

/// Errors of orthogonal-array construction and use.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum DoeError {
    /// The array has no runs or no columns.
    #[error("an orthogonal array needs at least one run and one column")]
    Empty,
    /// A run has a different number of columns than `levels`.
    #[error("run {run} has {found} columns, expected {expected}")]
    RunLength {
        /// 0-based run index.
        run: usize,
        /// Columns in that run.
        found: usize,
        /// Columns declared by `levels`.
        expected: usize,
    },
    /// A column declares fewer than two levels.
    #[error("column {column} has {levels} levels; at least 2 are needed")]
    TooFewLevels {
        /// 0-based column index.
        column: usize,
        /// Declared level count.
        levels: u8,
    },
    /// An entry is not below its column's level count.
    #[error("run {run}, column {column}: level {level} is not below {levels}")]
    LevelOutOfRange {
        /// 0-based run index.
        run: usize,
        /// 0-based column index.
        column: usize,
        /// The offending 0-based level.
        level: u8,
        /// The column's level count.
        levels: u8,
    },
    /// A column index is not in the array.
    #[error("column {column} does not exist (the array has {columns} columns)")]
    NoSuchColumn {
        /// Requested 0-based column.
        column: usize,
        /// Columns in the array.
        columns: usize,
    },
    /// The same column was assigned to two factors.
    #[error("column {column} is assigned to more than one factor")]
    DuplicateColumn {
        /// The repeated 0-based column.
        column: usize,
    },
    /// More factors were asked for than there are columns with that many levels.
    #[error("{requested} factors with {levels} levels asked for, but only {available} suitable columns are available")]
    TooManyFactors {
        /// Factors requested.
        requested: usize,
        /// Level count requested.
        levels: u8,
        /// Columns with that level count.
        available: usize,
    },
    /// Level values were given for a different number of factors than columns.
    #[error("level values given for {found} factors, but {expected} columns are assigned")]
    FactorCount {
        /// Factors with level values.
        found: usize,
        /// Columns assigned.
        expected: usize,
    },
    /// A factor has a different number of level values than its column's levels.
    #[error("factor {factor} has {found} level values, but its column has {expected} levels")]
    LevelValueCount {
        /// 0-based factor index.
        factor: usize,
        /// Values given.
        found: usize,
        /// Levels of the column.
        expected: u8,
    },
}

/// An orthogonal array: `runs[r][c]` is the 0-based level of column `c` in
/// run `r`, and `levels[c]` is the number of levels of column `c`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OrthogonalArray {
    /// The runs (rows), each with one 0-based level per column.
    pub runs: Vec<Vec<u8>>,
    /// Number of levels of each column.
    pub levels: Vec<u8>,
}

impl OrthogonalArray {
    /// Builds an array from its runs and column level counts, checking that
    /// every run has one entry per column and every entry is a valid level.
    /// Orthogonality itself is not required here (see [`Self::is_strength_two`]).
    pub fn new(runs: Vec<Vec<u8>>, levels: Vec<u8>) -> Result<Self, DoeError> {
        if runs.is_empty() || levels.is_empty() {
            return Err(DoeError::Empty);
        }
        for (column, &l) in levels.iter().enumerate() {
            if l < 2 {
                return Err(DoeError::TooFewLevels { column, levels: l });
            }
        }
        for (run, row) in runs.iter().enumerate() {
            if row.len() != levels.len() {
                return Err(DoeError::RunLength {
                    run,
                    found: row.len(),
                    expected: levels.len(),
                });
            }
            for (column, (&level, &l)) in row.iter().zip(&levels).enumerate() {
                if level >= l {
                    return Err(DoeError::LevelOutOfRange {
                        run,
                        column,
                        level,
                        levels: l,
                    });
                }
            }
        }
        Ok(Self { runs, levels })
    }

    /// The Taguchi L18 (2^1 × 3^7) array, [`L18_RUNS`] with [`L18_LEVELS`].
    pub fn l18() -> Self {
        Self {
            runs: L18_RUNS.iter().map(|r| r.to_vec()).collect(),
            levels: L18_LEVELS.to_vec(),
        }
    }

    /// Number of runs (rows).
    pub fn n_runs(&self) -> usize {
        self.runs.len()
    }

    /// Number of columns.
    pub fn n_columns(&self) -> usize {
        self.levels.len()
    }

    /// The level of `column` in every run, in run order.
    pub fn column(&self, column: usize) -> Result<Vec<u8>, DoeError> {
        self.check_column(column)?;
        Ok(self.runs.iter().map(|r| r[column]).collect())
    }

    /// How often each level pair occurs in columns `a` and `b`:
    /// `counts[la][lb]` is the number of runs with `a` at `la` and `b` at `lb`.
    pub fn pair_counts(&self, a: usize, b: usize) -> Result<Vec<Vec<usize>>, DoeError> {
        self.check_column(a)?;
        self.check_column(b)?;
        let mut counts =
            vec![vec![0usize; usize::from(self.levels[b])]; usize::from(self.levels[a])];
        for row in &self.runs {
            counts[usize::from(row[a])][usize::from(row[b])] += 1;
        }
        Ok(counts)
    }

    /// True when every column is balanced (each level occurs equally often)
    /// and every pair of distinct columns meets every level pair equally
    /// often: an orthogonal array of strength 2.
    pub fn is_strength_two(&self) -> bool {
        let n = self.n_runs();
        for a in 0..self.n_columns() {
            for b in (a + 1)..self.n_columns() {
                let cells = usize::from(self.levels[a]) * usize::from(self.levels[b]);
                if n % cells != 0 {
                    return false;
                }
                // Both indices were just range-checked by the loop bounds.
                let Ok(counts) = self.pair_counts(a, b) else {
                    return false;
                };
                if counts.iter().flatten().any(|&c| c != n / cells) {
                    return false;
                }
            }
        }
        // Pair balance implies column balance when there are two or more
        // columns; check single-column arrays directly.
        (0..self.n_columns()).all(|c| {
            let l = usize::from(self.levels[c]);
            let mut counts = vec![0usize; l];
            for row in &self.runs {
                counts[usize::from(row[c])] += 1;
            }
            n % l == 0 && counts.iter().all(|&k| k == n / l)
        })
    }

    /// Assigns `k` factors of `levels` levels each to columns: the first `k`
    /// columns (in column order) that have that many levels. For the L18 and
    /// three-level factors this is columns B, C, … (indices 1..=k), leaving
    /// the two-level column A free; k ≤ 7.
    ///
    /// For ANOM any assignment works. To fit a full quadratic response
    /// surface on the same runs, note that columns B, D and E together
    /// alias it (see [`l18_quadratic_columns`]), so k = 4 in B..E does not
    /// support the 15-term quadratic.
    pub fn assign_factors(&self, k: usize, levels: u8) -> Result<Vec<usize>, DoeError> {
        let columns: Vec<usize> = (0..self.n_columns())
            .filter(|&c| self.levels[c] == levels)
            .collect();
        if k > columns.len() {
            return Err(DoeError::TooManyFactors {
                requested: k,
                levels,
                available: columns.len(),
            });
        }
        Ok(columns[..k].to_vec())
    }

    /// Checks a user-chosen factor-to-column assignment: every column exists
    /// and none is used twice.
    pub fn check_assignment(&self, columns: &[usize]) -> Result<(), DoeError> {
        for (i, &c) in columns.iter().enumerate() {
            self.check_column(c)?;
            if columns[..i].contains(&c) {
                return Err(DoeError::DuplicateColumn { column: c });
            }
        }
        Ok(())
    }

    /// The experiment plan in physical values: row `r`, entry `f` is
    /// `level_values[f][level]` where `level` is run `r`'s level in column
    /// `columns[f]`. `level_values[f]` must list one value per level of that
    /// column (units are the factor's own).
    pub fn design(
        &self,
        columns: &[usize],
        level_values: &[Vec<f64>],
    ) -> Result<Vec<Vec<f64>>, DoeError> {
        self.check_assignment(columns)?;
        if level_values.len() != columns.len() {
            return Err(DoeError::FactorCount {
                found: level_values.len(),
                expected: columns.len(),
            });
        }
        for (factor, (&c, values)) in columns.iter().zip(level_values).enumerate() {
            if values.len() != usize::from(self.levels[c]) {
                return Err(DoeError::LevelValueCount {
                    factor,
                    found: values.len(),
                    expected: self.levels[c],
                });
            }
        }
        Ok(self
            .runs
            .iter()
            .map(|row| {
                columns
                    .iter()
                    .zip(level_values)
                    .map(|(&c, values)| values[usize::from(row[c])])
                    .collect()
            })
            .collect())
    }

    fn check_column(&self, column: usize) -> Result<(), DoeError> {
        if column >= self.n_columns() {
            return Err(DoeError::NoSuchColumn {
                column,
                columns: self.n_columns(),
            });
        }
        Ok(())
    }
}

/// Three-level L18 columns for `k` ≤ 4 factors on which the full quadratic
/// response surface (1, x_i, x_i², x_i x_j) is estimable: the first `k` of
/// C, D, E, F (indices 2..=5).
///
/// Why not B..E: on the 18 runs of the L18 in coded levels (−1, 0, 1),
/// columns B, D and E satisfy
/// 1 + ½(b + d − e) − ½(b² + d² + e²) − bd + be + de = 0 in every run, so
/// the quadratic model in any assignment containing B, D and E has rank one
/// less than its term count (checked exactly in `host/tests/integration/optimize.rs`).
/// Every other set of four of the columns B..H supports all 15 terms.
/// More than 4 factors cannot: 21 terms exceed the 17 that 18 runs allow.
pub fn l18_quadratic_columns(k: usize) -> Result<Vec<usize>, DoeError> {
    const COLUMNS: [usize; 4] = [2, 3, 4, 5];
    if k > COLUMNS.len() {
        return Err(DoeError::TooManyFactors {
            requested: k,
            levels: 3,
            available: COLUMNS.len(),
        });
    }
    Ok(COLUMNS[..k].to_vec())
}

/// The coded value in [-1, 1] of 0-based `level` out of `n_levels` equally
/// spaced levels: −1 for the first, +1 for the last (three levels: −1, 0, 1).
/// Returns 0 when `n_levels < 2` (a single level sits at the centre).
pub fn coded_level(level: u8, n_levels: u8) -> f64 {
    if n_levels < 2 {
        return 0.0;
    }
    -1.0 + 2.0 * f64::from(level) / f64::from(n_levels - 1)
}

/// Equally spaced coded level values for a column with `n_levels` levels,
/// suitable as one entry of the `level_values` of [`OrthogonalArray::design`].
pub fn coded_levels(n_levels: u8) -> Vec<f64> {
    (0..n_levels).map(|l| coded_level(l, n_levels)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn l18_is_valid_and_orthogonal() {
        let a = OrthogonalArray::l18();
        assert!(OrthogonalArray::new(a.runs.clone(), a.levels.clone()).is_ok());
        assert!(a.is_strength_two());
    }

    #[test]
    fn default_assignment_skips_the_two_level_column() {
        let a = OrthogonalArray::l18();
        assert_eq!(a.assign_factors(4, 3), Ok(vec![1, 2, 3, 4]));
        assert!(matches!(
            a.assign_factors(8, 3),
            Err(DoeError::TooManyFactors { available: 7, .. })
        ));
    }

    #[test]
    fn design_checks_its_inputs() {
        let a = OrthogonalArray::l18();
        assert_eq!(
            a.design(&[1, 1], &[vec![0.0; 3], vec![0.0; 3]]),
            Err(DoeError::DuplicateColumn { column: 1 })
        );
        assert!(matches!(
            a.design(&[0], &[vec![0.0; 3]]),
            Err(DoeError::LevelValueCount { .. })
        ));
        assert_eq!(coded_levels(3), vec![-1.0, 0.0, 1.0]);
    }
}
