//! Velocity induced by straight vortex segments and vortex rings
//! (Biot–Savart law), with a regularised core, and its sums over many
//! segments, optionally with the mirror image about the plane y = 0.
//!
//! A segment from `a` to `b` of circulation `Γ` (positive by the
//! right-hand rule about `a -> b`) induces at `p`, with `r0 = b - a`,
//! `r1 = p - a`, `r2 = p - b` (Katz & Plotkin 2001, §2.11, eq. 2.72):
//!
//! `q = Γ/(4π) · (r1 × r2)/|r1 × r2|² · r0·(r1/|r1| − r2/|r2|)`.
//!
//! `|r1 × r2| = h |r0|` with `h` the distance of `p` from the segment's
//! line, so `q ~ 1/h` next to the line. A free wake rolls up and its
//! segments pass close to each other and to the wing, where `1/h` gives
//! unbounded, meaningless velocities; the kernel is therefore multiplied by
//! `h² / (h² + r_c²)`, the Scully (Vatistas n = 1) core of radius `r_c`
//! (Vatistas, Kozel & Mih 1991, Exp. Fluids 11), i.e. the denominator
//! becomes `|r1 × r2|² + r_c² |r0|²`: solid-body rotation inside `r_c`,
//! the exact field outside a few `r_c`. Points on a segment's line (`r1`
//! and `r2` parallel to within 1e-9 rad, i.e. up to rounding), where the
//! exact field of a straight line vortex is zero or undefined, get zero —
//! as with the cut-off of Katz & Plotkin's programs (Program 13/16,
//! `RCUT`). That makes a segment's own midpoint, or a point on the
//! extension of a collinear neighbour, see nothing of it, as it should.
//!
//! The mirror image about y = 0 (a symmetric half-wing model) is the
//! reflected system with opposite circulation; its velocity at `p` is
//! `M q(M p)` with `M = diag(1, -1, 1)` and `q` the field of the original
//! system (Katz & Plotkin 2001, §12.3, Program 16's `WING(X, -Y, Z)`).

use nalgebra::Vector3;
use rayon::prelude::*;

const FOUR_PI: f64 = 4.0 * std::f64::consts::PI;

/// `|r1 × r2| / (|r1| |r2|)` (the sine of the angle the segment subtends)
/// below which a point counts as on the segment's line: far above the
/// rounding of the cross product (~1e-16), far below any real geometry.
const ON_LINE: f64 = 1e-9;

/// A straight vortex segment (end points in m, circulation in m²/s,
/// positive by the right-hand rule about `start -> end`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// First end point, m.
    pub start: Vector3<f64>,
    /// Second end point, m.
    pub end: Vector3<f64>,
    /// Circulation, m²/s.
    pub strength: f64,
}

/// Velocity (m/s) induced at `point` by the segment `start -> end` of
/// circulation `strength` (m²/s), with the Scully core `core_radius` (m)
/// (module docs; Katz & Plotkin 2001, eq. 2.72).
#[inline]
pub fn segment_velocity(
    start: &Vector3<f64>,
    end: &Vector3<f64>,
    strength: f64,
    point: &Vector3<f64>,
    core_radius: f64,
) -> Vector3<f64> {
    let r0 = end - start;
    let r1 = point - start;
    let r2 = point - end;
    let cross = r1.cross(&r2);
    let cross2 = cross.norm_squared();
    let (r1r1, r2r2) = (r1.norm_squared(), r2.norm_squared());
    // On the line, at an end point or for a zero-length segment: zero
    // (and r1 or r2 may be a zero vector).
    if cross2 <= ON_LINE * ON_LINE * r1r1 * r2r2 {
        return Vector3::zeros();
    }
    let l2 = r0.norm_squared();
    // r0·(r1/|r1| − r2/|r2|) over the denominator, with one division.
    let (n1, n2) = (r1r1.sqrt(), r2r2.sqrt());
    let along = r0.dot(&r1) * n2 - r0.dot(&r2) * n1;
    let k = strength * along / (FOUR_PI * n1 * n2 * (cross2 + core_radius * core_radius * l2));
    k * cross
}

/// Velocity induced at `point` by the closed ring `corners[0] -> corners[1]
/// -> corners[2] -> corners[3] -> corners[0]` of circulation `strength`
/// (Katz & Plotkin 2001, §12.3: a vortex ring is four segments of equal
/// circulation).
#[inline]
pub fn ring_velocity(
    corners: &[Vector3<f64>; 4],
    strength: f64,
    point: &Vector3<f64>,
    core_radius: f64,
) -> Vector3<f64> {
    (0..4)
        .map(|k| {
            segment_velocity(
                &corners[k],
                &corners[(k + 1) % 4],
                strength,
                point,
                core_radius,
            )
        })
        .sum()
}

/// Reflection about the plane y = 0.
#[inline]
pub fn mirror(v: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(v.x, -v.y, v.z)
}

/// Velocity induced at `point` by a set of segments, plus that of their
/// mirror image about y = 0 when `symmetric`.
pub fn induced_velocity(
    segments: &[Segment],
    point: &Vector3<f64>,
    core_radius: f64,
    symmetric: bool,
) -> Vector3<f64> {
    let mut v = Vector3::zeros();
    if symmetric {
        let image_point = mirror(point);
        let mut image = Vector3::zeros();
        for s in segments {
            v += segment_velocity(&s.start, &s.end, s.strength, point, core_radius);
            image += segment_velocity(&s.start, &s.end, s.strength, &image_point, core_radius);
        }
        v + mirror(&image)
    } else {
        for s in segments {
            v += segment_velocity(&s.start, &s.end, s.strength, point, core_radius);
        }
        v
    }
}

/// [`induced_velocity`] at many points, in parallel (rayon).
pub fn induced_velocities(
    segments: &[Segment],
    points: &[Vector3<f64>],
    core_radius: f64,
    symmetric: bool,
) -> Vec<Vector3<f64>> {
    points
        .par_iter()
        .map(|p| induced_velocity(segments, p, core_radius, symmetric))
        .collect()
}

/// The segments of a structured grid of vortex rings, each shared segment
/// once with the net circulation of its two rings (half the work of
/// summing ring by ring).
///
/// `points` holds `(rows + 1) * (spanwise + 1)` ring corners, point
/// `(r, j)` at `r * (spanwise + 1) + j`; ring `(i, j)` has the circulation
/// `strengths[i * spanwise + j]` and is traversed `(i, j) -> (i, j + 1) ->
/// (i + 1, j + 1) -> (i + 1, j)` (root to tip along its leading segment,
/// Katz & Plotkin's Program 16 orientation: positive circulation lifts
/// towards +z on a wing in a +x stream). Hence the spanwise segment
/// `(r, j) -> (r, j + 1)` carries `Γ(r, j) − Γ(r − 1, j)` and the chordwise
/// segment `(i, c) -> (i + 1, c)` carries `Γ(i, c − 1) − Γ(i, c)` (absent
/// rings count as zero).
pub fn grid_segments(
    rows: usize,
    spanwise: usize,
    points: &[Vector3<f64>],
    strengths: &[f64],
) -> Vec<Segment> {
    let mut segments = Vec::with_capacity((rows + 1) * spanwise + rows * (spanwise + 1));
    let point = |r: usize, j: usize| points[r * (spanwise + 1) + j];
    let gamma = |i: usize, j: usize| strengths[i * spanwise + j];
    for r in 0..=rows {
        for j in 0..spanwise {
            let ahead = if r < rows { gamma(r, j) } else { 0.0 };
            let behind = if r > 0 { gamma(r - 1, j) } else { 0.0 };
            segments.push(Segment {
                start: point(r, j),
                end: point(r, j + 1),
                strength: ahead - behind,
            });
        }
    }
    for i in 0..rows {
        for c in 0..=spanwise {
            let root_side = if c > 0 { gamma(i, c - 1) } else { 0.0 };
            let tip_side = if c < spanwise { gamma(i, c) } else { 0.0 };
            segments.push(Segment {
                start: point(i, c),
                end: point(i + 1, c),
                strength: root_side - tip_side,
            });
        }
    }
    segments
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An infinite line vortex approximated by a long segment: Γ/(2πh).
    #[test]
    fn long_segment_is_a_line_vortex() {
        let v = segment_velocity(
            &Vector3::new(0.0, -1e4, 0.0),
            &Vector3::new(0.0, 1e4, 0.0),
            2.0,
            &Vector3::new(0.5, 0.0, 0.0),
            0.0,
        );
        // Γ along +y, point at +x: velocity along -z (right-hand rule).
        let expected = 2.0 / (2.0 * std::f64::consts::PI * 0.5);
        assert!((v.z + expected).abs() < 1e-6 * expected && v.x.abs() < 1e-12);
        // On the line and its extension: zero.
        let on = segment_velocity(
            &Vector3::zeros(),
            &Vector3::new(1.0, 0.0, 0.0),
            1.0,
            &Vector3::new(2.0, 0.0, 0.0),
            0.0,
        );
        assert_eq!(on, Vector3::zeros());
    }

    /// The grid's net segments reproduce the ring-by-ring sum, and the
    /// mirror image equals the explicitly reflected rings.
    #[test]
    fn grid_equals_rings_and_mirror_equals_reflection() {
        let (rows, span) = (2, 3);
        let points: Vec<_> = (0..=rows)
            .flat_map(|r| {
                (0..=span).map(move |j| {
                    Vector3::new(r as f64 * 0.3, 0.1 + j as f64 * 0.4, 0.05 * (r * j) as f64)
                })
            })
            .collect();
        let strengths: Vec<f64> = (0..rows * span).map(|k| 1.0 + 0.3 * k as f64).collect();
        let p = Vector3::new(0.37, 0.52, 0.11);
        let core = 0.01;
        let grid = grid_segments(rows, span, &points, &strengths);
        let mut rings = Vector3::zeros();
        let mut images = Vector3::zeros();
        for i in 0..rows {
            for j in 0..span {
                let c = |r: usize, s: usize| points[r * (span + 1) + s];
                let ring = [c(i, j), c(i, j + 1), c(i + 1, j + 1), c(i + 1, j)];
                let g = strengths[i * span + j];
                rings += ring_velocity(&ring, g, &p, core);
                // Reflection reverses the orientation of the ring.
                let image = [
                    mirror(&ring[3]),
                    mirror(&ring[2]),
                    mirror(&ring[1]),
                    mirror(&ring[0]),
                ];
                images += ring_velocity(&image, g, &p, core);
            }
        }
        let direct = induced_velocity(&grid, &p, core, false);
        assert!((direct - rings).norm() < 1e-12);
        let both = induced_velocity(&grid, &p, core, true);
        assert!((both - rings - images).norm() < 1e-12);
    }

    /// The core bounds the velocity near the line: solid-body rotation.
    #[test]
    fn core_regularises() {
        let a = Vector3::new(0.0, -1e3, 0.0);
        let b = Vector3::new(0.0, 1e3, 0.0);
        let near = segment_velocity(&a, &b, 1.0, &Vector3::new(1e-4, 0.0, 0.0), 0.1);
        let line = 1.0 / (2.0 * std::f64::consts::PI);
        assert!((near.z.abs() - line * 1e-4 / (1e-8 + 0.01)).abs() < 1e-6);
    }
}
