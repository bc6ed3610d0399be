//! A section's contour: a closed polygon of points round the section,
//! checked once on construction, the input of the numerical conformal map
//! ([`crate::SectionMap::from_contour`]).
//!
//! The checks, each a typed [`NsError`] naming the point or segment: at
//! least 8 points (a closing duplicate not counted), every coordinate finite, no two consecutive
//! points equal, no segment meeting another (a figure-eight, a bow-tie, a
//! spike going back on itself), a non-zero enclosed area. Points may come
//! in either orientation and with or without the closing duplicate (a
//! last point within 1e-5 of the perimeter of the first is one); they
//! are kept counterclockwise (the section on the left) without it, so
//! indices in errors are those of the points as given.
//!
//! Cost: the crossing test sorts the segments by their left end and
//! compares only those whose x-ranges overlap, `O(n log n)` for a section
//! (thin sections: `O(n²)` at worst, a few ms for 2000 points).
//!
//! Constructors of the sections fwav uses: [`Contour::naca4`] (NACA
//! 4-digit, rounded trailing edge) and [`Contour::membrane`] /
//! [`Contour::flat_plate`] (a thin plate of given thickness with
//! semicircular ends round a mid-line).

pub(crate) mod naca;
mod plate;
mod trailing_edge;

use realfft::num_complex::Complex64;

use crate::error::NsError;

/// The largest distance, as a fraction of the perimeter, at which the last
/// point given is taken as the first one repeated.
const CLOSING_GAP: f64 = 1e-5;

/// A closed, simple, counterclockwise polygon round a section (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Contour {
    /// The points, counterclockwise, no closing duplicate.
    points: Vec<Complex64>,
}

impl Contour {
    /// The contour through `points` `(x, y)`, in either orientation, with
    /// or without the first point repeated at the end.
    ///
    /// # Errors
    /// [`NsError::ContourTooFewPoints`], [`NsError::ContourPointNotFinite`],
    /// [`NsError::ContourRepeatedPoint`], [`NsError::ContourCrossing`],
    /// [`NsError::ContourDegenerate`] (module docs).
    pub fn from_points(points: &[(f64, f64)]) -> Result<Self, NsError> {
        for (index, &(x, y)) in points.iter().enumerate() {
            if !(x.is_finite() && y.is_finite()) {
                return Err(NsError::ContourPointNotFinite { index, x, y });
            }
        }
        let mut z: Vec<Complex64> = points.iter().map(|&(x, y)| Complex64::new(x, y)).collect();
        // A closing point: the first repeated, or within 1e-5 of the
        // perimeter of it (a coordinate file's trailing edge closed as
        // `1.00001 -0.00000`, which would cross the first segment).
        if z.len() > 1 {
            let gap = (z[0] - z[z.len() - 1]).norm();
            if gap == 0.0 || gap < CLOSING_GAP * perimeter(&z) {
                z.pop();
            }
        }
        if z.len() < 8 {
            return Err(NsError::ContourTooFewPoints { count: z.len() });
        }
        let n = z.len();
        for i in 0..n {
            let next = (i + 1) % n;
            if z[i] == z[next] {
                return Err(NsError::ContourRepeatedPoint {
                    index: i,
                    next,
                    x: z[i].re,
                    y: z[i].im,
                });
            }
        }
        if let Some((first, second, at)) = first_crossing(&z) {
            return Err(NsError::ContourCrossing {
                first,
                first_end: (first + 1) % n,
                second,
                second_end: (second + 1) % n,
                x: at.re,
                y: at.im,
            });
        }
        let area = signed_area(&z);
        let perimeter = perimeter(&z);
        if area.abs() <= 1e-12 * perimeter * perimeter {
            return Err(NsError::ContourDegenerate {
                area: area.abs(),
                perimeter,
            });
        }
        if area < 0.0 {
            z.reverse();
        }
        Ok(Self { points: z })
    }

    /// The points, counterclockwise, without the closing duplicate.
    #[must_use]
    pub fn points(&self) -> &[Complex64] {
        &self.points
    }

    /// Number of distinct points.
    #[must_use]
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Never empty (at least 8 points).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The polygon's perimeter.
    #[must_use]
    pub fn perimeter(&self) -> f64 {
        perimeter(&self.points)
    }

    /// The polygon's enclosed area (positive).
    #[must_use]
    pub fn area(&self) -> f64 {
        signed_area(&self.points)
    }

    /// Whether the polygon encloses `z`: its winding number round `z`
    /// (crossings of the ray to the right of `z`, counted with their
    /// direction) is not zero. `O(n)`.
    #[must_use]
    pub(crate) fn encloses(&self, z: Complex64) -> bool {
        let n = self.points.len();
        let mut winding = 0_i32;
        for i in 0..n {
            let (p, q) = (self.points[i], self.points[(i + 1) % n]);
            let side = cross(p, q, z);
            if p.im <= z.im && q.im > z.im && side > 0.0 {
                winding += 1;
            } else if p.im > z.im && q.im <= z.im && side < 0.0 {
                winding -= 1;
            }
        }
        winding != 0
    }

    /// Whether the open polyline `path` crosses one of the polygon's
    /// segments (each of the two strictly on either side of the other's
    /// line; a touch is no crossing, unlike [`meeting`]'s).
    /// `O(n × path.len())`.
    #[must_use]
    pub(crate) fn crossed_by(&self, path: &[Complex64]) -> bool {
        let n = self.points.len();
        path.windows(2).any(|w| {
            (0..n).any(|i| {
                let (p, q) = (self.points[i], self.points[(i + 1) % n]);
                cross(w[0], w[1], p) * cross(w[0], w[1], q) < 0.0
                    && cross(p, q, w[0]) * cross(p, q, w[1]) < 0.0
            })
        })
    }

    /// The distance from `z` to the polygon (its nearest segment), `O(n)`.
    #[must_use]
    pub fn distance_to(&self, z: Complex64) -> f64 {
        let n = self.points.len();
        (0..n)
            .map(|i| segment_distance(z, self.points[i], self.points[(i + 1) % n]))
            .fold(f64::INFINITY, f64::min)
    }
}

/// Twice-halved shoelace sum: positive counterclockwise.
fn signed_area(z: &[Complex64]) -> f64 {
    let n = z.len();
    0.5 * (0..n)
        .map(|i| {
            let (p, q) = (z[i], z[(i + 1) % n]);
            p.re * q.im - q.re * p.im
        })
        .sum::<f64>()
}

fn perimeter(z: &[Complex64]) -> f64 {
    let n = z.len();
    (0..n).map(|i| (z[(i + 1) % n] - z[i]).norm()).sum()
}

fn segment_distance(z: Complex64, p: Complex64, q: Complex64) -> f64 {
    let d = q - p;
    let t = (((z - p) * d.conj()).re / d.norm_sqr()).clamp(0.0, 1.0);
    (z - (p + d * t)).norm()
}

/// `(q - p) × (r - p)`: positive when `r` is left of `p → q`.
fn cross(p: Complex64, q: Complex64, r: Complex64) -> f64 {
    let (a, b) = (q - p, r - p);
    a.re * b.im - a.im * b.re
}

/// Whether `r`, collinear with `p → q`, lies within the segment's box.
fn within(p: Complex64, q: Complex64, r: Complex64) -> bool {
    r.re >= p.re.min(q.re)
        && r.re <= p.re.max(q.re)
        && r.im >= p.im.min(q.im)
        && r.im <= p.im.max(q.im)
}

/// Where segments `p1 p2` and `q1 q2` meet (crossing or touching), if
/// they do.
fn meeting(p1: Complex64, p2: Complex64, q1: Complex64, q2: Complex64) -> Option<Complex64> {
    let d1 = cross(q1, q2, p1);
    let d2 = cross(q1, q2, p2);
    let d3 = cross(p1, p2, q1);
    let d4 = cross(p1, p2, q2);
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        let t = d1 / (d1 - d2);
        return Some(p1 + (p2 - p1) * t);
    }
    let touching = [
        (d1, q1, q2, p1),
        (d2, q1, q2, p2),
        (d3, p1, p2, q1),
        (d4, p1, p2, q2),
    ];
    touching
        .into_iter()
        .find(|&(d, a, b, r)| d == 0.0 && within(a, b, r))
        .map(|(_, _, _, r)| r)
}

/// The first pair of segments `(i, j)`, `i < j`, that meet other than at
/// the vertex adjacent ones share (an adjacent pair counts when it doubles
/// back on itself), with where.
fn first_crossing(z: &[Complex64]) -> Option<(usize, usize, Complex64)> {
    let n = z.len();
    let seg = |i: usize| (z[i], z[(i + 1) % n]);
    let mut order: Vec<usize> = (0..n).collect();
    let left = |i: usize| seg(i).0.re.min(seg(i).1.re);
    let right = |i: usize| seg(i).0.re.max(seg(i).1.re);
    order.sort_by(|&a, &b| left(a).total_cmp(&left(b)));
    let mut found: Option<(usize, usize, Complex64)> = None;
    for (pos, &i) in order.iter().enumerate() {
        for &j in &order[pos + 1..] {
            if left(j) > right(i) {
                break;
            }
            let (a, b) = (i.min(j), i.max(j));
            let adjacent = b == a + 1 || (a == 0 && b == n - 1);
            let (p1, p2) = seg(a);
            let (q1, q2) = seg(b);
            let hit = if adjacent {
                doubling_back(b == a + 1, p1, p2, q1, q2)
            } else {
                meeting(p1, p2, q1, q2)
            };
            if let Some(at) = hit {
                if found.is_none_or(|(fa, fb, _)| (a, b) < (fa, fb)) {
                    found = Some((a, b, at));
                }
            }
        }
    }
    found
}

/// Adjacent segments meet at their shared vertex; they overlap only when
/// they are collinear and turn back (a spike).
/// `in_order`: the first segment's end is the second's start (else the
/// pair wraps round, the last segment ending at the first's start).
fn doubling_back(
    in_order: bool,
    p1: Complex64,
    p2: Complex64,
    q1: Complex64,
    q2: Complex64,
) -> Option<Complex64> {
    // The shared vertex and the two far ends.
    let (shared, far_a, far_b) = if in_order { (p2, p1, q2) } else { (p1, p2, q1) };
    let (u, v) = (far_a - shared, far_b - shared);
    let turned_back = (u.re * v.im - u.im * v.re) == 0.0 && (u * v.conj()).re > 0.0;
    turned_back.then_some(shared)
}

#[cfg(test)]
mod tests;
