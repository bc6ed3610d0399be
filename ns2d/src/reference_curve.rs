//! Published curves the solver is compared with: `(x, y)` rows of a text
//! file (`#` comments), as in `tests/data`, and the deviations read
//! against them.

use crate::error::NsError;

/// A published curve `(x, y)`, `x` increasing.
#[derive(Debug, Clone, PartialEq)]
pub struct ReferenceCurve {
    points: Vec<(f64, f64)>,
}

impl ReferenceCurve {
    /// Parse the rows of `text` (two or more numbers a row; `#` lines and
    /// blank lines skipped).
    ///
    /// # Errors
    /// [`NsError::BadReferenceRow`] naming the row.
    pub fn parse(text: &str) -> Result<Self, NsError> {
        let points = text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
            .map(|l| {
                let mut values = l.split_whitespace().map(str::parse::<f64>);
                match (values.next(), values.next()) {
                    (Some(Ok(x)), Some(Ok(y))) => Ok((x, y)),
                    _ => Err(NsError::BadReferenceRow(l.to_owned())),
                }
            })
            .collect::<Result<Vec<_>, _>>()?;
        if points.len() < 2 {
            return Err(NsError::BadReferenceRow(format!("{} rows", points.len())));
        }
        Ok(Self { points })
    }

    /// The points.
    #[must_use]
    pub fn points(&self) -> &[(f64, f64)] {
        &self.points
    }

    /// The largest `|y|`.
    #[must_use]
    pub fn peak(&self) -> f64 {
        self.points.iter().map(|p| p.1.abs()).fold(0.0, f64::max)
    }

    /// The largest `|y|` of the points with `x` in `range` (0 for none).
    #[must_use]
    pub fn peak_in(&self, range: (f64, f64)) -> f64 {
        self.points
            .iter()
            .filter(|p| p.0 >= range.0 && p.0 <= range.1)
            .map(|p| p.1.abs())
            .fold(0.0, f64::max)
    }

    /// The largest deviation of `computed` (interpolated) from the points
    /// with `x` in `range`, each divided by `scale(y)`, and the `x` where
    /// it is: `scale = |y|` for relative errors, the peak for errors as a
    /// fraction of it.
    #[must_use]
    pub fn worst_deviation(
        &self,
        computed: &[(f64, f64)],
        range: (f64, f64),
        scale: impl Fn(f64) -> f64,
    ) -> (f64, f64) {
        self.points
            .iter()
            .filter(|p| p.0 >= range.0 && p.0 <= range.1)
            .map(|p| ((interpolate(computed, p.0) - p.1).abs() / scale(p.1), p.0))
            .fold((0.0, 0.0), |w, e| if e.0 > w.0 { e } else { w })
    }
}

/// Linear interpolation of samples `(x, y)` (`x` increasing, two or
/// more), extrapolating from the end intervals.
#[must_use]
pub fn interpolate(samples: &[(f64, f64)], x: f64) -> f64 {
    let i = samples
        .partition_point(|p| p.0 < x)
        .clamp(1, samples.len() - 1);
    let (a, b) = (samples[i - 1], samples[i]);
    a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_curve_is_read_and_a_shifted_copy_deviates_by_the_shift() {
        let curve = ReferenceCurve::parse("# x y\n0 1\n1 2\n\n2 4 extra\n").unwrap();
        assert_eq!(curve.points(), &[(0.0, 1.0), (1.0, 2.0), (2.0, 4.0)]);
        let computed = [(0.0, 1.1), (2.0, 4.1)];
        let (worst, x) = curve.worst_deviation(&computed, (0.0, 2.0), |_| curve.peak());
        // At x = 1 the computed line is 2.6 against 2: 0.6 of the peak 4.
        assert!((worst - 0.15).abs() < 1e-12 && x == 1.0, "{worst} at {x}");
        assert_eq!(curve.peak_in((0.0, 1.5)), 2.0);
        assert!(matches!(
            ReferenceCurve::parse("1 2\nx 3\n"),
            Err(NsError::BadReferenceRow(_))
        ));
    }
}
