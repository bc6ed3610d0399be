//! The panel lattice of a thin lifting surface: its corners, and per panel
//! the normal, area and collocation point of the vortex-ring method
//! (Katz & Plotkin 2001, §12.3 for the steady ring lattice, §13.12 for its
//! unsteady use).
//!
//! Axes: x chordwise (leading edge to trailing edge, the freestream
//! direction), y spanwise (root to tip), z up. Corner `(i, j)`, `i = 0`
//! the leading edge to `i = chordwise` the trailing edge, `j = 0` the root
//! to `j = spanwise` the tip, is stored at `i * (spanwise + 1) + j`. Panel
//! `(i, j)` (index `i * spanwise + j`) has the corners `A = (i, j)`,
//! `B = (i + 1, j)`, `C = (i + 1, j + 1)`, `D = (i, j + 1)`.

use nalgebra::Vector3;

use super::UvlmError;

/// A structured quadrilateral lattice of `chordwise x spanwise` panels
/// (corner coordinates in m).
#[derive(Debug, Clone, PartialEq)]
pub struct Lattice {
    /// Panels along the chord.
    pub chordwise: usize,
    /// Panels along the span.
    pub spanwise: usize,
    /// `(chordwise + 1) * (spanwise + 1)` corner points, m, corner `(i, j)`
    /// at `i * (spanwise + 1) + j`.
    pub corners: Vec<Vector3<f64>>,
}

impl Lattice {
    /// A lattice from its corners. Checks the counts, that every
    /// coordinate is finite and that every panel has an area (non-parallel
    /// diagonals), so that normals and collocation points exist.
    pub fn new(
        chordwise: usize,
        spanwise: usize,
        corners: Vec<Vector3<f64>>,
    ) -> Result<Self, UvlmError> {
        if chordwise == 0 || spanwise == 0 {
            return Err(UvlmError::EmptyLattice {
                chordwise,
                spanwise,
            });
        }
        let expected =
            (chordwise + 1)
                .checked_mul(spanwise + 1)
                .ok_or(UvlmError::EmptyLattice {
                    chordwise,
                    spanwise,
                })?;
        if corners.len() != expected {
            return Err(UvlmError::CornerCount {
                chordwise,
                spanwise,
                got: corners.len(),
                expected,
            });
        }
        if let Some(index) = corners.iter().position(|c| !all_finite(c)) {
            return Err(UvlmError::NonFinite {
                what: "corner",
                index,
            });
        }
        let lattice = Self {
            chordwise,
            spanwise,
            corners,
        };
        for i in 0..chordwise {
            for j in 0..spanwise {
                // The diagonals' cross product is twice the (projected)
                // area; zero means no normal can be defined.
                if lattice.diagonal_cross(i, j).norm_squared() == 0.0 {
                    return Err(UvlmError::DegeneratePanel { i, j });
                }
            }
        }
        Ok(lattice)
    }

    /// A flat rectangular plate of `chord` x `semi_span` (m) with uniform
    /// panels, leading edge along y at x = 0, pitched nose-up by
    /// `alpha_rad` about the leading edge: the trailing edge goes down,
    /// corner at chord station `xi` is at `(xi cos(alpha), y, -xi sin(alpha))`.
    pub fn rectangle(
        chord: f64,
        semi_span: f64,
        chordwise: usize,
        spanwise: usize,
        alpha_rad: f64,
    ) -> Result<Self, UvlmError> {
        positive("chord", chord)?;
        positive("semi_span", semi_span)?;
        if !alpha_rad.is_finite() {
            return Err(UvlmError::Parameter {
                name: "alpha_rad",
                value: alpha_rad,
                requirement: "must be finite",
            });
        }
        if chordwise == 0 || spanwise == 0 {
            return Err(UvlmError::EmptyLattice {
                chordwise,
                spanwise,
            });
        }
        let (sin, cos) = alpha_rad.sin_cos();
        let mut corners = Vec::with_capacity((chordwise + 1) * (spanwise + 1));
        for i in 0..=chordwise {
            let xi = chord * i as f64 / chordwise as f64;
            for j in 0..=spanwise {
                let y = semi_span * j as f64 / spanwise as f64;
                corners.push(Vector3::new(xi * cos, y, -xi * sin));
            }
        }
        Self::new(chordwise, spanwise, corners)
    }

    /// The same lattice moved rigidly by `offset` (m).
    pub fn translated(&self, offset: &Vector3<f64>) -> Self {
        Self {
            chordwise: self.chordwise,
            spanwise: self.spanwise,
            corners: self.corners.iter().map(|c| c + offset).collect(),
        }
    }

    /// Number of panels, `chordwise * spanwise`.
    pub fn panels(&self) -> usize {
        self.chordwise * self.spanwise
    }

    /// Number of corners, `(chordwise + 1) * (spanwise + 1)`.
    pub fn corner_count(&self) -> usize {
        (self.chordwise + 1) * (self.spanwise + 1)
    }

    /// Storage index of corner `(i, j)`.
    pub fn corner_index(&self, i: usize, j: usize) -> usize {
        i * (self.spanwise + 1) + j
    }

    /// Storage index of panel `(i, j)`.
    pub fn panel_index(&self, i: usize, j: usize) -> usize {
        i * self.spanwise + j
    }

    /// Corner `(i, j)`, m (`i <= chordwise`, `j <= spanwise`).
    pub fn corner(&self, i: usize, j: usize) -> Vector3<f64> {
        self.corners[self.corner_index(i, j)]
    }

    /// The corners `[A, B, C, D]` of panel `(i, j)`.
    pub fn panel_corners(&self, i: usize, j: usize) -> [Vector3<f64>; 4] {
        [
            self.corner(i, j),
            self.corner(i + 1, j),
            self.corner(i + 1, j + 1),
            self.corner(i, j + 1),
        ]
    }

    fn diagonal_cross(&self, i: usize, j: usize) -> Vector3<f64> {
        let [a, b, c, d] = self.panel_corners(i, j);
        (c - a).cross(&(d - b))
    }

    /// Unit normal of panel `(i, j)`, `(C - A) x (D - B)` normalized: +z
    /// for a flat wing in the xy plane (the normal from the cross product
    /// of the panel's diagonals, Katz & Plotkin 2001, §12.3).
    pub fn normal(&self, i: usize, j: usize) -> Vector3<f64> {
        self.diagonal_cross(i, j).normalize()
    }

    /// Area of panel `(i, j)`, m², `|(C - A) x (D - B)| / 2` (exact for a
    /// planar quadrilateral, the projected area for a warped one).
    pub fn area(&self, i: usize, j: usize) -> f64 {
        0.5 * self.diagonal_cross(i, j).norm()
    }

    /// Collocation point of panel `(i, j)`, m: three quarters of the way
    /// from the middle of the panel's leading edge `(A + D)/2` to the
    /// middle of its trailing edge `(B + C)/2` (the ring's leading segment
    /// lies on the quarter chord, so the collocation point sits at the
    /// ring's centre; Katz & Plotkin 2001, §12.3, Fig. 12.11).
    pub fn collocation_point(&self, i: usize, j: usize) -> Vector3<f64> {
        let [a, b, c, d] = self.panel_corners(i, j);
        bilinear(&[a, b, c, d], 0.75, 0.5)
    }

    /// Centroid of panel `(i, j)` (mean of its corners), m.
    pub fn centroid(&self, i: usize, j: usize) -> Vector3<f64> {
        let [a, b, c, d] = self.panel_corners(i, j);
        0.25 * (a + b + c + d)
    }
}

/// Bilinear interpolation over a panel's corners `[A, B, C, D]` at the
/// chordwise fraction `xi` (0 at AD, 1 at BC) and spanwise fraction `eta`
/// (0 at AB, 1 at DC). Used for positions and for corner velocities alike.
pub fn bilinear(corners: &[Vector3<f64>; 4], xi: f64, eta: f64) -> Vector3<f64> {
    let [a, b, c, d] = corners;
    let lead = a + eta * (d - a);
    let trail = b + eta * (c - b);
    lead + xi * (trail - lead)
}

pub(crate) fn all_finite(v: &Vector3<f64>) -> bool {
    v.iter().all(|x| x.is_finite())
}

fn positive(name: &'static str, value: f64) -> Result<(), UvlmError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(UvlmError::Parameter {
            name,
            value,
            requirement: "must be positive and finite",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rectangle_geometry() {
        let alpha = 0.1f64;
        let l = Lattice::rectangle(2.0, 3.0, 4, 6, alpha).unwrap();
        assert_eq!(l.corners.len(), 35);
        let n = l.normal(1, 2);
        assert!((n - Vector3::new(alpha.sin(), 0.0, alpha.cos())).norm() < 1e-12);
        assert!((l.area(0, 0) - 0.5 * 0.5).abs() < 1e-12);
        let cp = l.collocation_point(0, 0);
        assert!((cp.x - 0.375 * alpha.cos()).abs() < 1e-12 && (cp.y - 0.25).abs() < 1e-12);
        assert!(cp.z < 0.0);
    }

    #[test]
    fn rejects_bad_input() {
        assert!(Lattice::new(0, 3, vec![]).is_err());
        assert!(matches!(
            Lattice::new(1, 1, vec![Vector3::zeros(); 3]),
            Err(UvlmError::CornerCount { .. })
        ));
        let mut c = vec![Vector3::zeros(); 4];
        assert!(matches!(
            Lattice::new(1, 1, c.clone()),
            Err(UvlmError::DegeneratePanel { i: 0, j: 0 })
        ));
        c[1].x = f64::NAN;
        assert!(matches!(
            Lattice::new(1, 1, c),
            Err(UvlmError::NonFinite { index: 1, .. })
        ));
        assert!(Lattice::rectangle(-1.0, 1.0, 1, 1, 0.0).is_err());
    }
}
