//! Quality of an obtained Pareto-front approximation against a reference
//! front: the inverted generational distance (IGD).
//!
//! IGD(A, R) = (1/|R|) Σ_{r ∈ R} min_{a ∈ A} ‖r − a‖₂, the mean Euclidean
//! distance from each reference point to its nearest obtained point, in
//! objective units (Coello Coello & Reyes Sierra 2004, MICAI, LNAI 2972,
//! where it is introduced as the generational distance "inverted"; the
//! form here, with the plain mean of distances, is the one in common use,
//! e.g. Zhang et al. 2008 CEC test suite report). It measures convergence
//! and spread at once: a front that misses a part of the reference front
//! is charged for every reference point there.

/// Errors of the front metrics.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum MetricError {
    /// The reference or the obtained set is empty.
    #[error("IGD needs a non-empty reference front and a non-empty obtained set")]
    Empty,
    /// Points have different numbers of objectives.
    #[error("a point has {found} objectives, expected {expected}")]
    Dimension {
        /// Objectives of the offending point.
        found: usize,
        /// Objectives of the first reference point.
        expected: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("a point has a non-finite objective")]
    NonFinite,
}

/// Inverted generational distance of `obtained` with respect to
/// `reference` (both lists of objective vectors of equal length).
pub fn igd<R: AsRef<[f64]>, A: AsRef<[f64]>>(
    reference: &[R],
    obtained: &[A],
) -> Result<f64, MetricError> {
    let m = reference.first().ok_or(MetricError::Empty)?.as_ref().len();
    if obtained.is_empty() {
        return Err(MetricError::Empty);
    }
    for p in reference
        .iter()
        .map(AsRef::as_ref)
        .chain(obtained.iter().map(AsRef::as_ref))
    {
        if p.len() != m {
            return Err(MetricError::Dimension {
                found: p.len(),
                expected: m,
            });
        }
        if p.iter().any(|v| !v.is_finite()) {
            return Err(MetricError::NonFinite);
        }
    }
    let total: f64 = reference
        .iter()
        .map(|r| {
            let r = r.as_ref();
            obtained
                .iter()
                .map(|a| {
                    r.iter()
                        .zip(a.as_ref())
                        .map(|(x, y)| (x - y) * (x - y))
                        .sum::<f64>()
                })
                .fold(f64::INFINITY, f64::min)
                .sqrt()
        })
        .sum();
    Ok(total / reference.len() as f64)
}
