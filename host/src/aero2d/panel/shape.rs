//! Section contours for the panel method: a validated, clockwise contour
//! ([`SectionShape`]) and a periodic deforming one ([`ShapeHistory`]).

use crate::aero2d::camber::PeriodicSpan;

/// Why a contour or a shape history is refused.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ShapeError {
    /// Fewer than three points (no closed contour).
    #[error("{got} points; a contour needs at least 3")]
    TooFewPoints {
        /// Points given.
        got: usize,
    },
    /// A coordinate is infinite or NaN.
    #[error("point {point} is not finite")]
    NotFinite {
        /// Index of the point.
        point: usize,
    },
    /// Two consecutive points coincide (a zero-length panel).
    #[error("points {point} and {} coincide (zero-length panel)", point + 1)]
    Duplicate {
        /// Index of the first of the two points.
        point: usize,
    },
    /// The contour encloses no area.
    #[error("the contour encloses no area")]
    Degenerate,
    /// Two panels cross.
    #[error("panels {first} and {second} cross")]
    SelfIntersecting {
        /// Index of a panel (from point i to point i + 1).
        first: usize,
        /// Index of the panel it crosses.
        second: usize,
    },
    /// The x and y lists of a sample differ in length.
    #[error("sample {sample}: {x} x values but {y} y values")]
    MismatchedXy {
        /// Sample index.
        sample: usize,
        /// x values.
        x: usize,
        /// y values.
        y: usize,
    },
    /// A history needs a positive, finite period and at least one sample.
    #[error("the period must be positive and finite and there must be at least one sample")]
    Period,
    /// The samples of a history differ in point count.
    #[error("sample {sample} has {got} points, sample 0 has {expected}")]
    SampleLength {
        /// Sample index.
        sample: usize,
        /// Points in it.
        got: usize,
        /// Points in sample 0.
        expected: usize,
    },
    /// A sample runs the other way round, or closes its trailing edge
    /// differently, from sample 0 (point i must be the same material point
    /// in every sample).
    #[error("sample {sample} is ordered or closed differently from sample 0")]
    Inconsistent {
        /// Sample index.
        sample: usize,
    },
    /// An error in one sample of a history.
    #[error("sample {sample}: {source}")]
    Sample {
        /// Sample index.
        sample: usize,
        /// What is wrong with it.
        #[source]
        source: Box<ShapeError>,
    },
}

/// Shorthand for a 2-vector.
pub(crate) type V2 = [f64; 2];

/// A closed section contour, chords, in the body frame of
/// [`super::super::ldvm`] (x from the leading edge towards the trailing
/// edge, y up when the section is at zero pitch), ordered clockwise from
/// the trailing edge: along the lower surface to the leading edge and back
/// along the upper surface (Katz & Plotkin 2001, section 11.4; outward
/// normals on the left of the direction of travel). The first and last
/// given points are the trailing edge: if they coincide the edge is sharp
/// and the contour has one vertex there; if not, the edge is blunt and a
/// closing (base) panel joins them, the wake leaving from its middle.
#[derive(Clone, Debug, PartialEq)]
pub struct SectionShape {
    vertices: Vec<V2>,
    blunt: bool,
    /// Whether the given points ran counter-clockwise and were reversed.
    reversed: bool,
}

/// Whether segments `a-b` and `c-d` cross (proper intersection or overlap).
fn segments_cross(a: V2, b: V2, c: V2, d: V2) -> bool {
    let orient =
        |p: V2, q: V2, r: V2| (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    let (d1, d2) = (orient(c, d, a), orient(c, d, b));
    let (d3, d4) = (orient(a, b, c), orient(a, b, d));
    (d1 * d2 < 0.0) && (d3 * d4 < 0.0)
}

impl SectionShape {
    /// Validates a contour given as points (see the type documentation;
    /// either orientation: a counter-clockwise list, e.g. a Selig file, is
    /// reversed). Coincident ends closer than `1e-9` of the contour's size
    /// make a sharp trailing edge.
    pub fn new(points: &[(f64, f64)]) -> Result<Self, ShapeError> {
        if points.len() < 3 {
            return Err(ShapeError::TooFewPoints { got: points.len() });
        }
        if let Some(point) = points
            .iter()
            .position(|p| !p.0.is_finite() || !p.1.is_finite())
        {
            return Err(ShapeError::NotFinite { point });
        }
        if let Some(point) = points.windows(2).position(|w| w[0] == w[1]) {
            return Err(ShapeError::Duplicate { point });
        }
        let size = points
            .iter()
            .map(|p| p.0.abs().max(p.1.abs()))
            .fold(0.0f64, f64::max)
            .max(f64::MIN_POSITIVE);
        let (first, last) = (points[0], points[points.len() - 1]);
        let blunt = (first.0 - last.0).hypot(first.1 - last.1) > 1e-9 * size;
        let mut vertices: Vec<V2> = points.iter().map(|p| [p.0, p.1]).collect();
        if !blunt {
            vertices.pop();
        }
        if vertices.len() < 3 {
            return Err(ShapeError::TooFewPoints { got: points.len() });
        }
        let m = vertices.len();
        let twice_area: f64 = (0..m)
            .map(|i| {
                let (p, q) = (vertices[i], vertices[(i + 1) % m]);
                p[0] * q[1] - q[0] * p[1]
            })
            .sum();
        if twice_area.abs() <= 1e-14 * size * size {
            return Err(ShapeError::Degenerate);
        }
        // Panels i: vertex i to vertex i + 1 (cyclic). Neighbours share a
        // vertex and cannot cross properly.
        for i in 0..m {
            for j in i + 2..m {
                if i == 0 && j == m - 1 {
                    continue;
                }
                let (a, b) = (vertices[i], vertices[(i + 1) % m]);
                let (c, d) = (vertices[j], vertices[(j + 1) % m]);
                if segments_cross(a, b, c, d) {
                    return Err(ShapeError::SelfIntersecting {
                        first: i,
                        second: j,
                    });
                }
            }
        }
        let reversed = twice_area > 0.0;
        if reversed {
            vertices.reverse();
            if !blunt {
                // Keep the trailing edge as vertex 0.
                vertices.rotate_right(1);
            }
        }
        if blunt {
            let (a, b) = (vertices[0], vertices[m - 1]);
            vertices.insert(0, [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]);
        }
        Ok(Self {
            vertices,
            blunt,
            reversed,
        })
    }

    /// The contour vertices, clockwise from the trailing edge (for a blunt
    /// edge, the middle of its base); panel `i` runs from vertex `i` to
    /// vertex `i + 1` (cyclic).
    pub fn vertices(&self) -> &[V2] {
        &self.vertices
    }

    /// Number of panels (equal to the number of vertices; with a blunt
    /// trailing edge the first and last are the two halves of the base).
    pub fn panels(&self) -> usize {
        self.vertices.len()
    }

    /// Whether the trailing edge is blunt (closed by two base panels).
    pub fn is_blunt(&self) -> bool {
        self.blunt
    }
}

/// A periodic deforming contour: the `(x, y)` (chords, body frame, as for
/// [`SectionShape`]) of every surface point at samples equally spaced over
/// one period, interpolated in time by a periodic Catmull-Rom cubic (as
/// [`super::super::camber::CamberHistory`] does), so the surface velocity
/// is continuous. Point `i` is the same material point in every sample; the
/// rigid plunge and pitch of the [`super::super::ldvm::Motion`] act on top.
#[derive(Clone, Debug, PartialEq)]
pub struct ShapeHistory {
    samples: Vec<SectionShape>,
    period: f64,
}

impl ShapeHistory {
    /// `samples[i]`: the contour at time `i * period / samples.len()`
    /// (chords travelled); each validated like [`SectionShape::new`], all
    /// with the same point count, orientation and trailing-edge closure.
    pub fn new(samples: &[Vec<(f64, f64)>], period: f64) -> Result<Self, ShapeError> {
        let period_ok = period > 0.0 && period.is_finite();
        if !period_ok || samples.is_empty() {
            return Err(ShapeError::Period);
        }
        let mut shapes: Vec<SectionShape> = Vec::with_capacity(samples.len());
        for (sample, points) in samples.iter().enumerate() {
            if points.len() != samples[0].len() {
                return Err(ShapeError::SampleLength {
                    sample,
                    got: points.len(),
                    expected: samples[0].len(),
                });
            }
            let shape = SectionShape::new(points).map_err(|e| ShapeError::Sample {
                sample,
                source: Box::new(e),
            })?;
            if let Some(first) = shapes.first() {
                if shape.reversed != first.reversed || shape.blunt != first.blunt {
                    return Err(ShapeError::Inconsistent { sample });
                }
            }
            shapes.push(shape);
        }
        Ok(Self {
            samples: shapes,
            period,
        })
    }

    /// The same from separate x and y lists per sample.
    pub fn from_xy(x: &[Vec<f64>], y: &[Vec<f64>], period: f64) -> Result<Self, ShapeError> {
        if x.len() != y.len() {
            return Err(ShapeError::MismatchedXy {
                sample: x.len().min(y.len()),
                x: x.len(),
                y: y.len(),
            });
        }
        let mut samples = Vec::with_capacity(x.len());
        for (sample, (xs, ys)) in x.iter().zip(y).enumerate() {
            if xs.len() != ys.len() {
                return Err(ShapeError::MismatchedXy {
                    sample,
                    x: xs.len(),
                    y: ys.len(),
                });
            }
            samples.push(xs.iter().copied().zip(ys.iter().copied()).collect());
        }
        Self::new(&samples, period)
    }

    /// Number of vertices of every sample (the midpoint of a blunt edge
    /// included).
    pub fn vertex_count(&self) -> usize {
        self.samples[0].vertices.len()
    }

    /// Whether the trailing edge is blunt.
    pub fn is_blunt(&self) -> bool {
        self.samples[0].blunt
    }

    /// The period, chords travelled.
    pub fn period(&self) -> f64 {
        self.period
    }

    /// Vertex positions and velocities (chords, chords per unit time, body
    /// frame) at time `t`.
    pub fn at(&self, t: f64) -> (Vec<V2>, Vec<V2>) {
        let n = self.samples.len();
        if n == 1 {
            let v = self.samples[0].vertices.clone();
            let zero = vec![[0.0; 2]; v.len()];
            return (v, zero);
        }
        let span = PeriodicSpan::new(t, self.period, n);
        let [p0, p1, p2, p3] = span.samples.map(|j| &self.samples[j].vertices);
        let cubic = |a: f64, b: f64, c: f64, d: f64| span.cubic(a, b, c, d);
        p1.iter()
            .enumerate()
            .map(|(k, _)| {
                let (x, u) = cubic(p0[k][0], p1[k][0], p2[k][0], p3[k][0]);
                let (y, v) = cubic(p0[k][1], p1[k][1], p2[k][1], p3[k][1]);
                ([x, y], [u, v])
            })
            .unzip()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<(f64, f64)> {
        vec![(1.0, 0.0), (0.0, -0.1), (0.0, 0.1), (1.0, 0.0)]
    }

    #[test]
    fn contours_are_validated_and_put_clockwise() {
        let s = SectionShape::new(&square()).unwrap();
        assert_eq!(s.panels(), 3);
        assert!(!s.is_blunt());
        // Counter-clockwise input: reversed, the trailing edge stays first.
        let mut ccw = square();
        ccw.reverse();
        let r = SectionShape::new(&ccw).unwrap();
        assert_eq!(r.vertices(), s.vertices());
        let blunt =
            SectionShape::new(&[(1.0, -0.01), (0.0, -0.01), (0.0, 0.01), (1.0, 0.01)]).unwrap();
        assert!(blunt.is_blunt() && blunt.panels() == 5);
        assert_eq!(blunt.vertices()[0], [1.0, 0.0]);
        assert_eq!(
            SectionShape::new(&[(1.0, -0.01), (0.0, 0.0), (1.0, 0.01)])
                .unwrap()
                .panels(),
            4
        );
        assert_eq!(
            SectionShape::new(&[(0.0, 0.0), (1.0, 0.0)]),
            Err(ShapeError::TooFewPoints { got: 2 })
        );
        assert_eq!(
            SectionShape::new(&[(1.0, 0.0), (0.0, f64::NAN), (0.0, 1.0)]),
            Err(ShapeError::NotFinite { point: 1 })
        );
        assert_eq!(
            SectionShape::new(&[(1.0, 0.0), (0.0, 0.0), (0.0, 0.0), (0.0, 1.0)]),
            Err(ShapeError::Duplicate { point: 1 })
        );
        assert_eq!(
            SectionShape::new(&[(1.0, 0.0), (0.5, 0.0), (0.0, 0.0), (1.0, 0.0)]),
            Err(ShapeError::Degenerate)
        );
        // A bow tie.
        assert!(matches!(
            SectionShape::new(&[(1.0, 0.0), (0.0, 0.1), (0.0, -0.1), (0.5, 0.2), (1.0, 0.0)]),
            Err(ShapeError::SelfIntersecting { .. })
        ));
    }

    #[test]
    fn histories_are_validated_and_interpolated() {
        assert_eq!(ShapeHistory::new(&[square()], 0.0), Err(ShapeError::Period));
        assert_eq!(ShapeHistory::new(&[], 1.0), Err(ShapeError::Period));
        assert_eq!(
            ShapeHistory::new(&[square()], f64::NAN),
            Err(ShapeError::Period)
        );
        let mut short = square();
        short.remove(1);
        assert!(matches!(
            ShapeHistory::new(&[square(), short], 1.0),
            Err(ShapeError::SampleLength {
                sample: 1,
                got: 3,
                expected: 4
            })
        ));
        let mut ccw = square();
        ccw.reverse();
        assert_eq!(
            ShapeHistory::new(&[square(), ccw], 1.0),
            Err(ShapeError::Inconsistent { sample: 1 })
        );
        assert!(matches!(
            ShapeHistory::new(
                &[
                    square(),
                    vec![(1.0, 0.0), (0.0, f64::INFINITY), (0.0, 0.1), (1.0, 0.0)]
                ],
                1.0
            ),
            Err(ShapeError::Sample { sample: 1, .. })
        ));
        assert!(matches!(
            ShapeHistory::from_xy(&[vec![1.0, 0.0, 0.0, 1.0]], &[vec![0.0, -0.1, 0.1]], 1.0),
            Err(ShapeError::MismatchedXy {
                sample: 0,
                x: 4,
                y: 3
            })
        ));
        assert!(matches!(
            ShapeHistory::from_xy(&[vec![1.0]], &[], 1.0),
            Err(ShapeError::MismatchedXy { .. })
        ));
        // A breathing square, sampled 64 times: positions and velocities to
        // the accuracy of the cubic.
        let period = 2.0;
        let omega = 2.0 * std::f64::consts::PI / period;
        let at = |t: f64| -> Vec<(f64, f64)> {
            let a = 0.1 + 0.02 * (omega * t).sin();
            vec![(1.0, 0.0), (0.0, -a), (0.0, a), (1.0, 0.0)]
        };
        let samples: Vec<_> = (0..64).map(|i| at(i as f64 * period / 64.0)).collect();
        let h = ShapeHistory::new(&samples, period).unwrap();
        for k in 0..50 {
            let t = 0.173 * k as f64;
            let (p, v) = h.at(t);
            assert!((p[2][1] - at(t)[2].1).abs() < 1e-6);
            assert!((v[2][1] - 0.02 * omega * (omega * t).cos()).abs() < 2e-4);
            assert_eq!(v[0], [0.0, 0.0]);
        }
    }
}
