//! The wake: a sheet of vortex rings shed from the trailing edge, one row
//! per time step (Katz & Plotkin 2001, §13.12: the Kutta condition makes
//! the newest wake row carry the circulation the trailing-edge panels had
//! when it was shed; the rings then keep their circulation and are
//! convected, Kelvin's theorem).
//!
//! Layout: ring row 0 is the youngest. Point row `r` is the trailing edge
//! of ring row `r − 1` and the leading edge of ring row `r`. Point row 0 is
//! the shed line, the trailing segment of the wing's last bound ring
//! (trailing edge + shed offset): every solve replaces it by the shed line
//! of the surface being solved, so the youngest ring always stretches from
//! the present trailing edge to where the previous shed line has been
//! convected. The stored row 0 is that of the last committed surface (for
//! output).

use nalgebra::Vector3;

use super::vortex::{grid_segments, Segment};
use super::UvlmError;

/// Wake corner points (m) and ring circulations (m²/s).
#[derive(Debug, Clone, PartialEq)]
pub struct WakeSheet {
    spanwise: usize,
    /// `(rows + 1) * (spanwise + 1)` points, point `(r, j)` at
    /// `r * (spanwise + 1) + j`; empty before the first shedding.
    points: Vec<Vector3<f64>>,
    /// `rows * spanwise` ring circulations, ring `(i, j)` at
    /// `i * spanwise + j`.
    strengths: Vec<f64>,
}

impl WakeSheet {
    /// An empty wake behind a lattice of `spanwise` panels along the span.
    pub fn new(spanwise: usize) -> Self {
        Self {
            spanwise,
            points: Vec::new(),
            strengths: Vec::new(),
        }
    }

    /// Panels along the span.
    pub fn spanwise(&self) -> usize {
        self.spanwise
    }

    /// Number of ring rows (the number of steps shed, up to the
    /// truncation).
    pub fn rows(&self) -> usize {
        self.strengths.len().checked_div(self.spanwise).unwrap_or(0)
    }

    /// All corner points, m: `(rows + 1) * (spanwise + 1)` of them (none
    /// for an empty wake), row 0 the shed line of the last committed
    /// surface.
    pub fn points(&self) -> &[Vector3<f64>] {
        &self.points
    }

    /// All ring circulations, m²/s, `rows * spanwise`, youngest row first
    /// (same orientation as the bound rings: positive for a wing that
    /// lifted towards +n when the row was shed).
    pub fn strengths(&self) -> &[f64] {
        &self.strengths
    }

    /// Corner `(r, j)`, m (`r <= rows`, `j <= spanwise`).
    pub fn point(&self, r: usize, j: usize) -> Vector3<f64> {
        self.points[r * (self.spanwise + 1) + j]
    }

    /// Circulation of ring `(i, j)`, m²/s (`i < rows`, `j < spanwise`).
    pub fn strength(&self, i: usize, j: usize) -> f64 {
        self.strengths[i * self.spanwise + j]
    }

    /// The corner points as rows from the shed line back (`rows + 1` rows
    /// of `spanwise + 1` points, none for an empty wake), m: ring row `r`
    /// spans corner rows `r` and `r + 1`.
    pub fn corner_rows(&self) -> Vec<Vec<Vector3<f64>>> {
        self.points
            .chunks_exact(self.spanwise + 1)
            .map(<[_]>::to_vec)
            .collect()
    }

    /// The ring circulations as rows (`rows` rows of `spanwise` values,
    /// youngest first), m²/s.
    pub fn strength_rows(&self) -> Vec<Vec<f64>> {
        self.strengths
            .chunks_exact(self.spanwise.max(1))
            .map(<[_]>::to_vec)
            .collect()
    }

    /// Points of the sheet with point row 0 replaced by `shed_line`
    /// (`spanwise + 1` points): the wake as seen by the surface whose
    /// shed line that is.
    pub fn points_behind(&self, shed_line: &[Vector3<f64>]) -> Vec<Vector3<f64>> {
        let width = self.spanwise + 1;
        let mut points = self.points.clone();
        if points.len() >= width {
            points[..width].copy_from_slice(&shed_line[..width]);
        }
        points
    }

    /// The net vortex segments of the sheet with point row 0 replaced by
    /// `shed_line` ([`grid_segments`]). The leading segments carry the full
    /// circulation of the youngest rings, because the wing's last ring is
    /// not part of this set.
    pub fn segments_behind(&self, shed_line: &[Vector3<f64>]) -> Vec<Segment> {
        if self.rows() == 0 {
            return Vec::new();
        }
        grid_segments(
            self.rows(),
            self.spanwise,
            &self.points_behind(shed_line),
            &self.strengths,
        )
    }

    /// Sheds a new youngest row and convects the sheet one step.
    ///
    /// `shed_line` is the shed line of the committed surface,
    /// `circulation` the circulation of its trailing-edge rings (the new
    /// youngest ring row, the Kutta condition), `displacement` the
    /// displacement over the step of every point of the sheet with row 0
    /// replaced by `shed_line` (`(rows + 1) * (spanwise + 1)` values, in
    /// the layout of [`WakeSheet::points`]). Afterwards point row 0 is
    /// `shed_line`, row `r + 1` is the old row `r` displaced. Keeps at most
    /// `keep_rows` ring rows.
    pub(crate) fn shed(
        &mut self,
        shed_line: &[Vector3<f64>],
        circulation: &[f64],
        displacement: &[Vector3<f64>],
        keep_rows: usize,
    ) -> Result<(), UvlmError> {
        let width = self.spanwise + 1;
        let rows = self.rows();
        for (what, got, expected) in [
            ("shed line", shed_line.len(), width),
            (
                "trailing-edge circulation",
                circulation.len(),
                self.spanwise,
            ),
            ("wake displacement", displacement.len(), (rows + 1) * width),
        ] {
            if got != expected {
                return Err(UvlmError::Length {
                    what,
                    got,
                    expected,
                });
            }
        }
        let mut old = self.points_behind(shed_line);
        if old.is_empty() {
            old = shed_line.to_vec();
        }
        let kept = (rows + 1).min(keep_rows);
        let mut points = Vec::with_capacity((kept + 1) * width);
        points.extend_from_slice(shed_line);
        for (p, d) in old.iter().zip(displacement).take(kept * width) {
            points.push(p + d);
        }
        let mut strengths = Vec::with_capacity(kept * self.spanwise);
        strengths.extend_from_slice(circulation);
        strengths.extend_from_slice(&self.strengths);
        strengths.truncate(kept * self.spanwise);
        if kept == 0 {
            points.clear();
        }
        self.points = points;
        self.strengths = strengths;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shedding_and_truncation() {
        let mut wake = WakeSheet::new(2);
        let line: Vec<_> = (0..3).map(|j| Vector3::new(1.0, j as f64, 0.0)).collect();
        let step = vec![Vector3::new(0.5, 0.0, 0.0); 3];
        wake.shed(&line, &[1.0, 2.0], &step, 10).unwrap();
        assert_eq!(wake.rows(), 1);
        assert_eq!(wake.point(1, 2), Vector3::new(1.5, 2.0, 0.0));
        let step2 = vec![Vector3::new(0.5, 0.0, 0.0); 6];
        wake.shed(&line, &[3.0, 4.0], &step2, 10).unwrap();
        assert_eq!(wake.rows(), 2);
        assert_eq!(wake.strengths(), &[3.0, 4.0, 1.0, 2.0]);
        assert_eq!(wake.point(2, 0), Vector3::new(2.0, 0.0, 0.0));
        let step3 = vec![Vector3::new(0.5, 0.0, 0.0); 9];
        wake.shed(&line, &[5.0, 6.0], &step3, 2).unwrap();
        assert_eq!(wake.rows(), 2);
        assert_eq!(wake.points().len(), 9);
        assert_eq!(wake.strengths(), &[5.0, 6.0, 3.0, 4.0]);
        assert!(wake.shed(&line, &[1.0], &step3, 2).is_err());
    }
}
