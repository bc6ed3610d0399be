//! Analysis of means (ANOM) of an orthogonal-array experiment: the level
//! means of each factor, the grand mean, the best level of each factor and
//! the additive prediction of the response at chosen levels.
//!
//! Reference: `shared/REFERENCES.md`, "Design of experiments and
//! optimization": the level mean m_{j,l} is the mean response over the runs
//! where column j is at level l, and the predicted optimum is
//! m + Σ_j (m_{j,l*} − m). The prediction is exact when the response is an
//! additive function of the factors (no interactions), because a
//! strength-2 array balances every other factor within each level.

use super::doe::{DoeError, OrthogonalArray};

/// Whether a larger or a smaller response is better (Taguchi's
/// "larger-the-better" / "smaller-the-better").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Goal {
    /// Maximize the response.
    LargerIsBetter,
    /// Minimize the response.
    SmallerIsBetter,
}

/// Errors of the analysis of means.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum AnomError {
    /// The factor-to-column assignment is invalid.
    #[error(transparent)]
    Assignment(#[from] DoeError),
    /// The number of responses differs from the number of runs.
    #[error("{found} responses given for {expected} runs")]
    ResponseCount {
        /// Responses given.
        found: usize,
        /// Runs in the array.
        expected: usize,
    },
    /// A response is NaN or infinite.
    #[error("response of run {run} is not finite ({value})")]
    NonFiniteResponse {
        /// 0-based run index.
        run: usize,
        /// The value.
        value: f64,
    },
    /// A level of an assigned column never occurs in the array, so its mean
    /// is undefined.
    #[error("factor {factor}: level {level} occurs in no run")]
    EmptyLevel {
        /// 0-based factor index.
        factor: usize,
        /// 0-based level.
        level: u8,
    },
    /// Levels were given for a different number of factors.
    #[error("{found} levels given for {expected} factors")]
    FactorCount {
        /// Levels given.
        found: usize,
        /// Factors analysed.
        expected: usize,
    },
    /// A level is out of range for its factor.
    #[error("factor {factor}: level {level} is not below {levels}")]
    LevelOutOfRange {
        /// 0-based factor index.
        factor: usize,
        /// The 0-based level given.
        level: u8,
        /// Levels of the factor.
        levels: usize,
    },
}

/// The one-way table of an orthogonal-array experiment.
#[derive(Debug, Clone, PartialEq)]
pub struct Anom {
    /// The array columns the factors were assigned to, in factor order.
    pub columns: Vec<usize>,
    /// Mean response over all runs (same units as the response).
    pub grand_mean: f64,
    /// `level_means[f][l]`: mean response over the runs where factor `f` is
    /// at 0-based level `l`.
    pub level_means: Vec<Vec<f64>>,
}

impl Anom {
    /// Computes the level means of the factors assigned to `columns` from
    /// `responses[r]`, the response of run `r` of `array`.
    pub fn new(
        array: &OrthogonalArray,
        columns: &[usize],
        responses: &[f64],
    ) -> Result<Self, AnomError> {
        array.check_assignment(columns)?;
        if responses.len() != array.n_runs() {
            return Err(AnomError::ResponseCount {
                found: responses.len(),
                expected: array.n_runs(),
            });
        }
        if let Some((run, &value)) = responses.iter().enumerate().find(|(_, y)| !y.is_finite()) {
            return Err(AnomError::NonFiniteResponse { run, value });
        }
        let grand_mean = responses.iter().sum::<f64>() / responses.len() as f64;
        let mut level_means = Vec::with_capacity(columns.len());
        for (factor, &c) in columns.iter().enumerate() {
            let n_levels = usize::from(array.levels[c]);
            let mut sum = vec![0.0; n_levels];
            let mut count = vec![0usize; n_levels];
            for (row, &y) in array.runs.iter().zip(responses) {
                sum[usize::from(row[c])] += y;
                count[usize::from(row[c])] += 1;
            }
            let mut means = Vec::with_capacity(n_levels);
            for (level, (&s, &k)) in sum.iter().zip(&count).enumerate() {
                if k == 0 {
                    return Err(AnomError::EmptyLevel {
                        factor,
                        // n_levels comes from a u8, so the index fits.
                        level: level as u8,
                    });
                }
                means.push(s / k as f64);
            }
            level_means.push(means);
        }
        Ok(Self {
            columns: columns.to_vec(),
            grand_mean,
            level_means,
        })
    }

    /// Number of factors analysed.
    pub fn n_factors(&self) -> usize {
        self.level_means.len()
    }

    /// The best 0-based level of each factor for `goal`: the level with the
    /// largest (or smallest) mean. Ties go to the lowest level index.
    pub fn best_levels(&self, goal: Goal) -> Vec<u8> {
        self.level_means
            .iter()
            .map(|means| {
                let mut best = 0usize;
                for (l, &m) in means.iter().enumerate().skip(1) {
                    let better = match goal {
                        Goal::LargerIsBetter => m > means[best],
                        Goal::SmallerIsBetter => m < means[best],
                    };
                    if better {
                        best = l;
                    }
                }
                // Level counts come from u8 columns.
                best as u8
            })
            .collect()
    }

    /// Effect range of each factor, max − min of its level means: a larger
    /// range means a more influential factor (same units as the response).
    pub fn ranges(&self) -> Vec<f64> {
        self.level_means
            .iter()
            .map(|m| {
                let max = m.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                let min = m.iter().copied().fold(f64::INFINITY, f64::min);
                max - min
            })
            .collect()
    }

    /// Additive prediction at the given 0-based levels (one per factor):
    /// ŷ = m + Σ_f (m_{f,l_f} − m) (REFERENCES.md, ANOM).
    pub fn predict(&self, levels: &[u8]) -> Result<f64, AnomError> {
        if levels.len() != self.n_factors() {
            return Err(AnomError::FactorCount {
                found: levels.len(),
                expected: self.n_factors(),
            });
        }
        let mut y = self.grand_mean;
        for (factor, (&l, means)) in levels.iter().zip(&self.level_means).enumerate() {
            let m = means
                .get(usize::from(l))
                .ok_or(AnomError::LevelOutOfRange {
                    factor,
                    level: l,
                    levels: means.len(),
                })?;
            y += m - self.grand_mean;
        }
        Ok(y)
    }

    /// The best levels for `goal` and the additive prediction there.
    pub fn optimum(&self, goal: Goal) -> (Vec<u8>, f64) {
        let levels = self.best_levels(goal);
        // The best levels are in range by construction.
        let y = self.grand_mean
            + levels
                .iter()
                .zip(&self.level_means)
                .map(|(&l, m)| m[usize::from(l)] - self.grand_mean)
                .sum::<f64>();
        (levels, y)
    }
}
