//! Quadratic response surfaces in coded variables: least-squares fit by QR,
//! fit statistics (R², adjusted R², PRESS, predicted R²) and a model reducer
//! for designs that cannot support the full quadratic.
//!
//! The full quadratic in k coded variables x ∈ [−1, 1]^k has the
//! (k+1)(k+2)/2 terms 1, x_i, x_i², x_i x_j (i < j) (REFERENCES.md,
//! "Design of experiments and optimization"; R², adjusted R², PRESS and
//! predicted R² as in Myers, Montgomery & Anderson-Cook, *Response Surface
//! Methodology*, the chapters on linear regression; PRESS from Allen 1974,
//! Technometrics 16(1)).
//!
//! The fit is y ≈ X β with X the n × p model matrix. It is solved through
//! the thin QR factorization X = Q R (never the normal equations, whose
//! condition number is the square of X's): β = R⁻¹ Qᵀ y. The hat matrix is
//! H = Q Qᵀ, so the leverage of run i is h_ii = ‖row i of Q‖², and the
//! leave-one-out residual of run i is e_i / (1 − h_ii), which gives
//! PRESS = Σ (e_i / (1 − h_ii))² without n refits.

use std::fmt;

use nalgebra::{DMatrix, DVector};

/// Relative threshold under which a model column counts as a linear
/// combination of the columns before it: |R_jj| ≤ RANK_TOLERANCE · ‖X_j‖,
/// i.e. the sine of the angle between column j and the span of the earlier
/// columns. Below 1e-8 the coefficients would carry more rounding than
/// signal anyway.
pub const RANK_TOLERANCE: f64 = 1e-8;

/// Leverage at or above 1 − LEVERAGE_TOLERANCE means a run is fit exactly
/// whatever its response, so it cannot be left out and PRESS is undefined.
const LEVERAGE_TOLERANCE: f64 = 1e-10;

/// One term of a polynomial response surface; variable indices are 0-based.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Term {
    /// The constant 1.
    Intercept,
    /// x_i.
    Linear(usize),
    /// x_i².
    Square(usize),
    /// x_i x_j with i < j.
    Interaction(usize, usize),
}

impl Term {
    /// The value of the term at the coded point `x`; a variable index
    /// outside `x` reads as 0 (callers check indices, see [`fit`]).
    pub fn value(&self, x: &[f64]) -> f64 {
        let v = |i: usize| x.get(i).copied().unwrap_or(0.0);
        match *self {
            Term::Intercept => 1.0,
            Term::Linear(i) => v(i),
            Term::Square(i) => v(i) * v(i),
            Term::Interaction(i, j) => v(i) * v(j),
        }
    }

    /// The largest variable index the term uses, if any.
    fn max_variable(&self) -> Option<usize> {
        match *self {
            Term::Intercept => None,
            Term::Linear(i) | Term::Square(i) => Some(i),
            Term::Interaction(i, j) => Some(i.max(j)),
        }
    }
}

impl fmt::Display for Term {
    /// 1-based names: `1`, `x1`, `x1^2`, `x1*x2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Term::Intercept => write!(f, "1"),
            Term::Linear(i) => write!(f, "x{}", i + 1),
            Term::Square(i) => write!(f, "x{}^2", i + 1),
            Term::Interaction(i, j) => write!(f, "x{}*x{}", i + 1, j + 1),
        }
    }
}

/// The full quadratic in `k` variables, in the order intercept, linear
/// terms, squares, interactions (x_i x_j with i < j, i-major).
pub fn quadratic_terms(k: usize) -> Vec<Term> {
    let mut terms = vec![Term::Intercept];
    terms.extend((0..k).map(Term::Linear));
    terms.extend((0..k).map(Term::Square));
    for i in 0..k {
        terms.extend(((i + 1)..k).map(|j| Term::Interaction(i, j)));
    }
    terms
}

/// Errors of response-surface coding and fitting.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum RsmError {
    /// A coding range is empty, reversed or not finite.
    #[error("invalid variable range [{low}, {high}]: need finite low < high")]
    InvalidRange {
        /// Lower bound.
        low: f64,
        /// Upper bound.
        high: f64,
    },
    /// A point has the wrong number of variables.
    #[error("point has {found} variables, expected {expected}")]
    Dimension {
        /// Variables given.
        found: usize,
        /// Variables expected.
        expected: usize,
    },
    /// No runs, or no terms, to fit.
    #[error("nothing to fit: {runs} runs, {terms} terms")]
    Empty {
        /// Runs given.
        runs: usize,
        /// Terms given.
        terms: usize,
    },
    /// The responses do not match the runs.
    #[error("{found} responses given for {expected} runs")]
    ResponseCount {
        /// Responses given.
        found: usize,
        /// Runs given.
        expected: usize,
    },
    /// A design coordinate or a response is NaN or infinite.
    #[error("run {run} has a non-finite value")]
    NonFinite {
        /// 0-based run index.
        run: usize,
    },
    /// A term uses a variable the runs do not have.
    #[error("term {term} uses a variable beyond the {variables} of the design")]
    TermVariable {
        /// The term.
        term: Term,
        /// Variables of the design.
        variables: usize,
    },
    /// More terms than runs − 1: the fit would leave no residual degree of
    /// freedom, so neither adjusted R² nor PRESS would mean anything.
    #[error("{terms} terms cannot be fit from {runs} runs (at most runs − 1)")]
    TooManyTerms {
        /// Terms requested (after any reduction).
        terms: usize,
        /// Runs available.
        runs: usize,
    },
    /// A term's column is (numerically) a combination of earlier columns:
    /// the design cannot separate it. [`fit_reduced`] drops such terms.
    #[error("term {term} is aliased with earlier terms on this design (rank deficient)")]
    RankDeficient {
        /// The first dependent term, in term order.
        term: Term,
    },
    /// All responses are equal, so R² (relative to the variation about the
    /// mean) is undefined.
    #[error("all responses are equal; R² is undefined")]
    ConstantResponse,
}

/// Linear map between a physical variable on [low, high] and its coded
/// value on [−1, 1]: coded = (2x − (high + low)) / (high − low).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coding {
    low: f64,
    high: f64,
}

impl Coding {
    /// A coding for a variable ranging over [low, high] (physical units).
    pub fn new(low: f64, high: f64) -> Result<Self, RsmError> {
        if !(low.is_finite() && high.is_finite() && low < high) {
            return Err(RsmError::InvalidRange { low, high });
        }
        Ok(Self { low, high })
    }

    /// Lower physical bound (coded −1).
    pub fn low(&self) -> f64 {
        self.low
    }

    /// Upper physical bound (coded +1).
    pub fn high(&self) -> f64 {
        self.high
    }

    /// Coded value of the physical value `x`.
    pub fn to_coded(&self, x: f64) -> f64 {
        (2.0 * x - (self.high + self.low)) / (self.high - self.low)
    }

    /// Physical value of the coded value `c`.
    pub fn to_physical(&self, c: f64) -> f64 {
        0.5 * (self.high + self.low) + 0.5 * c * (self.high - self.low)
    }
}

/// Codes a physical point variable by variable.
pub fn code_point(codings: &[Coding], x: &[f64]) -> Result<Vec<f64>, RsmError> {
    check_dimension(x.len(), codings.len())?;
    Ok(codings.iter().zip(x).map(|(c, &v)| c.to_coded(v)).collect())
}

/// Decodes a coded point back to physical values, variable by variable.
pub fn decode_point(codings: &[Coding], c: &[f64]) -> Result<Vec<f64>, RsmError> {
    check_dimension(c.len(), codings.len())?;
    Ok(codings
        .iter()
        .zip(c)
        .map(|(k, &v)| k.to_physical(v))
        .collect())
}

fn check_dimension(found: usize, expected: usize) -> Result<(), RsmError> {
    if found != expected {
        return Err(RsmError::Dimension { found, expected });
    }
    Ok(())
}

/// A fitted response surface and its statistics.
#[derive(Debug, Clone, PartialEq)]
pub struct ResponseSurface {
    /// Number of (coded) variables.
    pub n_variables: usize,
    /// The model terms, in fit order.
    pub terms: Vec<Term>,
    /// Coefficient of each term (response units).
    pub coefficients: Vec<f64>,
    /// t statistic of each coefficient, β_j / se(β_j) with
    /// se² = σ² (R⁻¹R⁻ᵀ)_jj. When the residual is exactly zero, |t| is +∞
    /// (signed) for a nonzero coefficient and 0 for a zero one.
    pub t_values: Vec<f64>,
    /// Residual e_i = y_i − ŷ_i of each run.
    pub residuals: Vec<f64>,
    /// Leverage h_ii (hat-matrix diagonal) of each run.
    pub leverage: Vec<f64>,
    /// Residual sum of squares Σ e_i².
    pub sse: f64,
    /// Total sum of squares about the mean, Σ (y_i − ȳ)².
    pub sst: f64,
    /// R² = 1 − SSE/SST.
    pub r_squared: f64,
    /// Adjusted R² = 1 − (SSE/(n − p)) / (SST/(n − 1)).
    pub adjusted_r_squared: f64,
    /// PRESS = Σ (e_i / (1 − h_ii))²; `None` when some run has leverage 1
    /// (the model reproduces it whatever its response, so it cannot be
    /// predicted from the others).
    pub press: Option<f64>,
    /// Predicted R² = 1 − PRESS/SST; `None` with PRESS.
    pub predicted_r_squared: Option<f64>,
}

impl ResponseSurface {
    /// The surface's value at the coded point `x`.
    pub fn predict(&self, x: &[f64]) -> Result<f64, RsmError> {
        check_dimension(x.len(), self.n_variables)?;
        Ok(self
            .terms
            .iter()
            .zip(&self.coefficients)
            .map(|(t, b)| b * t.value(x))
            .sum())
    }

    /// The coefficient of `term`, if the model has it.
    pub fn coefficient(&self, term: Term) -> Option<f64> {
        self.terms
            .iter()
            .position(|&t| t == term)
            .map(|i| self.coefficients[i])
    }
}

/// The least-squares solution of one model, before statistics.
struct Solution {
    coefficients: Vec<f64>,
    /// |β_j| / sqrt((R⁻¹R⁻ᵀ)_jj) = |t_j| · σ: ranks terms like |t| (σ is
    /// common to all terms of one fit) but stays defined when σ = 0.
    t_sigma: Vec<f64>,
    residuals: Vec<f64>,
    leverage: Vec<f64>,
}

/// Checks the design and responses; returns the number of variables.
fn check_data<X: AsRef<[f64]>>(x: &[X], y: &[f64]) -> Result<usize, RsmError> {
    let k = x
        .first()
        .map(|r| r.as_ref().len())
        .ok_or(RsmError::Empty { runs: 0, terms: 0 })?;
    if y.len() != x.len() {
        return Err(RsmError::ResponseCount {
            found: y.len(),
            expected: x.len(),
        });
    }
    for (run, (row, &yi)) in x.iter().zip(y).enumerate() {
        let row = row.as_ref();
        check_dimension(row.len(), k)?;
        if !yi.is_finite() || row.iter().any(|v| !v.is_finite()) {
            return Err(RsmError::NonFinite { run });
        }
    }
    Ok(k)
}

fn model_matrix<X: AsRef<[f64]>>(x: &[X], terms: &[Term]) -> DMatrix<f64> {
    DMatrix::from_fn(x.len(), terms.len(), |r, c| terms[c].value(x[r].as_ref()))
}

/// Least squares by thin QR for p ≤ n terms (the caller checks p).
fn solve<X: AsRef<[f64]>>(x: &[X], y: &[f64], terms: &[Term]) -> Result<Solution, RsmError> {
    let a = model_matrix(x, terms);
    let p = terms.len();
    let col_norms: Vec<f64> = (0..p).map(|j| a.column(j).norm()).collect();
    let qr = a.clone().qr();
    let r = qr.r();
    let q = qr.q();
    for j in 0..p {
        // Without pivoting, |R_jj| is the distance of column j from the span
        // of columns 0..j, so the first small one names the aliased term.
        if r[(j, j)].abs() <= RANK_TOLERANCE * col_norms[j] || col_norms[j] == 0.0 {
            return Err(RsmError::RankDeficient { term: terms[j] });
        }
    }
    let yv = DVector::from_column_slice(y);
    let qty = q.transpose() * &yv;
    let beta = r
        .solve_upper_triangular(&qty)
        .ok_or(RsmError::RankDeficient { term: terms[p - 1] })?;
    let rinv = r
        .solve_upper_triangular(&DMatrix::identity(p, p))
        .ok_or(RsmError::RankDeficient { term: terms[p - 1] })?;
    let residuals = (&yv - &a * &beta).iter().copied().collect();
    let leverage = q.row_iter().map(|row| row.norm_squared()).collect();
    let t_sigma = (0..p).map(|j| beta[j].abs() / rinv.row(j).norm()).collect();
    Ok(Solution {
        coefficients: beta.iter().copied().collect(),
        t_sigma,
        residuals,
        leverage,
    })
}

/// Fits the model with the given `terms` to the runs `x` (coded points, one
/// row of k variables per run) and responses `y`, by QR least squares.
///
/// Errors: more terms than runs − 1 ([`RsmError::TooManyTerms`]), a term
/// whose column is aliased with earlier ones ([`RsmError::RankDeficient`],
/// naming the first such term in `terms` order), constant responses
/// ([`RsmError::ConstantResponse`]), and malformed input.
pub fn fit<X: AsRef<[f64]>>(
    x: &[X],
    y: &[f64],
    terms: &[Term],
) -> Result<ResponseSurface, RsmError> {
    let k = check_data(x, y)?;
    let (n, p) = (x.len(), terms.len());
    if p == 0 {
        return Err(RsmError::Empty { runs: n, terms: 0 });
    }
    if let Some(&term) = terms
        .iter()
        .find(|t| t.max_variable().is_some_and(|i| i >= k))
    {
        return Err(RsmError::TermVariable { term, variables: k });
    }
    if p + 1 > n {
        return Err(RsmError::TooManyTerms { terms: p, runs: n });
    }
    let mean = y.iter().sum::<f64>() / n as f64;
    let sst: f64 = y.iter().map(|v| (v - mean).powi(2)).sum();
    if sst == 0.0 {
        return Err(RsmError::ConstantResponse);
    }
    let s = solve(x, y, terms)?;
    let sse: f64 = s.residuals.iter().map(|e| e * e).sum();
    let dof = (n - p) as f64;
    let sigma = (sse / dof).sqrt();
    let t_values = s
        .t_sigma
        .iter()
        .zip(&s.coefficients)
        .map(|(&ts, &b)| {
            if sigma > 0.0 {
                b.signum() * ts / sigma
            } else if b == 0.0 {
                0.0
            } else {
                b.signum() * f64::INFINITY
            }
        })
        .collect();
    let press = if s.leverage.iter().any(|&h| h >= 1.0 - LEVERAGE_TOLERANCE) {
        None
    } else {
        Some(
            s.residuals
                .iter()
                .zip(&s.leverage)
                .map(|(e, h)| (e / (1.0 - h)).powi(2))
                .sum::<f64>(),
        )
    };
    Ok(ResponseSurface {
        n_variables: k,
        terms: terms.to_vec(),
        coefficients: s.coefficients,
        t_values,
        residuals: s.residuals,
        leverage: s.leverage,
        sse,
        sst,
        r_squared: 1.0 - sse / sst,
        adjusted_r_squared: 1.0 - (sse / dof) / (sst / (n as f64 - 1.0)),
        predicted_r_squared: press.map(|pr| 1.0 - pr / sst),
        press,
    })
}

/// Why [`fit_reduced`] left a term out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DropReason {
    /// The term's column is a combination of earlier terms' columns on this
    /// design (e.g. x² of a two-level variable equals the intercept).
    Aliased,
    /// Dropped to bring the term count to the cap (at most runs − 1); the
    /// term had the smallest |t| of its class when dropped.
    TooFewRuns,
    /// An interaction whose |t| fell below [`ReduceOptions::min_abs_t`].
    Insignificant {
        /// Its t statistic when dropped.
        t: f64,
    },
}

/// A term left out by [`fit_reduced`], with the reason.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DroppedTerm {
    /// The term.
    pub term: Term,
    /// Why.
    pub reason: DropReason,
}

/// Options of [`fit_reduced`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReduceOptions {
    /// Largest number of terms to keep; it is always also capped at
    /// runs − 1. `None`: runs − 1.
    pub max_terms: Option<usize>,
    /// After the cap is met, keep dropping the interaction with the
    /// smallest |t| while that |t| is below this value. 0 (the default)
    /// turns significance-based elimination off.
    pub min_abs_t: f64,
}

impl Default for ReduceOptions {
    fn default() -> Self {
        Self {
            max_terms: None,
            min_abs_t: 0.0,
        }
    }
}

/// A reduced quadratic fit: the surface and the terms left out.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedFit {
    /// The fitted surface on the kept terms.
    pub surface: ResponseSurface,
    /// The full-quadratic terms left out, in the order they were dropped.
    pub dropped: Vec<DroppedTerm>,
}

/// Fits as much of the full quadratic as the design supports. The rule:
///
/// 1. Aliasing: walk the full quadratic in [`quadratic_terms`] order
///    (intercept, linear, squares, interactions) and drop every term whose
///    column is within [`RANK_TOLERANCE`] of the span of the kept ones (Gram–Schmidt
///    with re-orthogonalization). The kept model has full column rank, so at most n terms.
/// 2. Cap: while there are more terms than `min(max_terms, n − 1)`, fit
///    the model and drop the interaction with the smallest |t| (ranked by
///    |β_j|/√((R⁻¹R⁻ᵀ)_jj), which orders terms as |t| does and stays defined
///    when the fit interpolates); when no interaction is left, the square
///    with the smallest |t|. Intercept and linear terms are never dropped;
///    if they alone exceed the cap, [`RsmError::TooManyTerms`].
/// 3. Significance (optional, [`ReduceOptions::min_abs_t`] > 0): backward
///    elimination of interactions by smallest |t| below the threshold.
///
/// With 18 runs and 4 three-level variables the full quadratic (15 terms)
/// survives all three steps unchanged on the L18 design.
pub fn fit_reduced<X: AsRef<[f64]>>(
    x: &[X],
    y: &[f64],
    options: ReduceOptions,
) -> Result<ReducedFit, RsmError> {
    let k = check_data(x, y)?;
    let n = x.len();
    let mut dropped = Vec::new();
    let mut terms = Vec::new();
    let mut basis: Vec<Vec<f64>> = Vec::new();
    for term in quadratic_terms(k) {
        let column: Vec<f64> = x.iter().map(|r| term.value(r.as_ref())).collect();
        match orthonormal_remainder(&column, &basis) {
            Some(q) => {
                basis.push(q);
                terms.push(term);
            }
            None => dropped.push(DroppedTerm {
                term,
                reason: DropReason::Aliased,
            }),
        }
    }
    let cap = options.max_terms.unwrap_or(n).min(n.saturating_sub(1));
    while terms.len() > cap {
        let s = solve(x, y, &terms)?;
        let weakest = weakest_of(&terms, &s.t_sigma, |t| matches!(t, Term::Interaction(..)))
            .or_else(|| weakest_of(&terms, &s.t_sigma, |t| matches!(t, Term::Square(_))));
        let Some(i) = weakest else {
            return Err(RsmError::TooManyTerms {
                terms: terms.len(),
                runs: n,
            });
        };
        dropped.push(DroppedTerm {
            term: terms.remove(i),
            reason: DropReason::TooFewRuns,
        });
    }
    let mut surface = fit(x, y, &terms)?;
    // With the default threshold 0 no |t| is below it, so this stops at once.
    loop {
        let abs_t: Vec<f64> = surface.t_values.iter().map(|t| t.abs()).collect();
        let Some(i) = weakest_of(&surface.terms, &abs_t, |t| {
            matches!(t, Term::Interaction(..))
        }) else {
            break;
        };
        // A NaN threshold compares as not-less, so it stops too.
        if abs_t[i].partial_cmp(&options.min_abs_t) != Some(std::cmp::Ordering::Less) {
            break;
        }
        let t = surface.t_values[i];
        let mut kept = surface.terms.clone();
        let term = kept.remove(i);
        dropped.push(DroppedTerm {
            term,
            reason: DropReason::Insignificant { t },
        });
        surface = fit(x, y, &kept)?;
    }
    Ok(ReducedFit { surface, dropped })
}

/// Index of the term of the class `is_class` with the smallest score
/// (ties: the later term, so that higher-order, later-listed terms go first).
fn weakest_of(terms: &[Term], score: &[f64], is_class: impl Fn(&Term) -> bool) -> Option<usize> {
    let mut best: Option<usize> = None;
    for (i, t) in terms.iter().enumerate() {
        if is_class(t) && best.is_none_or(|b| score[i] <= score[b]) {
            best = Some(i);
        }
    }
    best
}

/// The part of `column` orthogonal to the orthonormal `basis`, normalized;
/// `None` when that part is below [`RANK_TOLERANCE`] of the column's norm.
fn orthonormal_remainder(column: &[f64], basis: &[Vec<f64>]) -> Option<Vec<f64>> {
    let norm0 = column.iter().map(|v| v * v).sum::<f64>().sqrt();
    if norm0 == 0.0 {
        return None;
    }
    let mut v = column.to_vec();
    // Two passes of modified Gram–Schmidt: one pass can leave O(ε·κ)
    // components along the basis; the second removes them ("twice is enough").
    for _ in 0..2 {
        for q in basis {
            let d: f64 = q.iter().zip(&v).map(|(a, b)| a * b).sum();
            v.iter_mut().zip(q).for_each(|(vi, qi)| *vi -= d * qi);
        }
    }
    let norm = v.iter().map(|a| a * a).sum::<f64>().sqrt();
    if norm <= RANK_TOLERANCE * norm0 {
        return None;
    }
    v.iter_mut().for_each(|a| *a /= norm);
    Some(v)
}
