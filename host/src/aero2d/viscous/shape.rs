//! The section of the viscous model ([`ViscousShape`]): a plate, an
//! ellipse, or a closed contour whose sharp trailing edge is made blunt
//! (a corner has no conformal map), and whether it is its own mirror
//! image.

use fwav_ns2d::Contour;

use super::ViscousError;

/// The section of the viscous model, chords, leading edge at `x = 0`.
#[derive(Clone, Debug, PartialEq)]
pub enum ViscousShape {
    /// A thin plate of this thickness (chords) with semicircular ends,
    /// `x` from 0 to 1 over all: the model of a thin section or membrane.
    Plate(f64),
    /// An ellipse of this thickness (chords) along the chord (the exact
    /// Joukowski map; its ends crowd the grid far more than the plate's).
    Ellipse(f64),
    /// A closed contour (a NACA section or a point file, a sharp trailing
    /// edge made blunt: [`ViscousShape::from_points`]), chords.
    Contour(Vec<(f64, f64)>),
}

impl ViscousShape {
    /// The contour through `points` (chords, either orientation, closed
    /// or not); when its sharpest vertex turns by more than
    /// [`CORNER_TURNING`] (an airfoil file's sharp trailing edge: a corner
    /// has no conformal map), that edge opened to
    /// [`TRAILING_EDGE_THICKNESS`] and closed by an arc tangent to both
    /// sides, on 512 points (the chord is kept).
    ///
    /// # Errors
    /// The contour's checks ([`Contour::from_points`],
    /// [`Contour::with_blunt_trailing_edge`]).
    pub fn from_points(points: &[(f64, f64)]) -> Result<Self, ViscousError> {
        let contour = Contour::from_points(points)?;
        if contour.sharpest_vertex().1 <= CORNER_TURNING {
            return Ok(Self::Contour(points.to_vec()));
        }
        let blunt = contour.with_blunt_trailing_edge(TRAILING_EDGE_THICKNESS, CONTOUR_POINTS)?;
        Ok(Self::Contour(
            blunt.points().iter().map(|z| (z.re, z.im)).collect(),
        ))
    }

    /// Whether the section is its own mirror image across its chord line
    /// `y = 0` (the plate, the ellipse, a contour each of whose points'
    /// mirror images lies within [`MIRROR_TOLERANCE`] of it): at zero
    /// pitch in a stream its flow is then mirror symmetric
    /// ([`super::SectionPath::Still`]). Cost: `O(n²)` in a contour's points.
    pub fn is_mirror_symmetric(&self) -> bool {
        let points = match self {
            Self::Plate(_) | Self::Ellipse(_) => return true,
            Self::Contour(points) => points,
        };
        let n = points.len();
        let distance = |(x, y): (f64, f64)| -> f64 {
            (0..n)
                .map(|i| {
                    let (a, b) = (points[i], points[(i + 1) % n]);
                    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                    let length = dx * dx + dy * dy;
                    let s = if length > 0.0 {
                        (((x - a.0) * dx + (y - a.1) * dy) / length).clamp(0.0, 1.0)
                    } else {
                        0.0
                    };
                    (x - a.0 - s * dx).hypot(y - a.1 - s * dy)
                })
                .fold(f64::INFINITY, f64::min)
        };
        points
            .iter()
            .all(|&(x, y)| distance((x, -y)) <= MIRROR_TOLERANCE)
    }
}

/// How far (chords) a contour's mirrored point may lie from it for the
/// contour to be mirror symmetric ([`ViscousShape::is_mirror_symmetric`]):
/// a file's rounding (points given to 5 or 6 decimals), far below any
/// camber a section is given.
pub const MIRROR_TOLERANCE: f64 = 1e-4;

/// Thickness, chords, to which a sharp trailing edge (a NACA section's, a
/// point file's) is opened for the viscous model (a corner has no
/// conformal map; [`Contour::with_blunt_trailing_edge`]). Its effect on
/// the LDVM paper's case 1 (SD7003, `fwav validate --only
/// ns2d/ldvm-case1`): 0.0025 c, mean CL +0.17% and peak -0.4% from this
/// 0.005 c; 0.01 c, -0.95% and +0.8% (measured with the semicircular back
/// of before 2026-12-07; the tangent arc since left case 1's lift
/// unchanged to four digits at 0.005 c).
pub const TRAILING_EDGE_THICKNESS: f64 = 0.005;

/// A point file's vertex that turns by more than this (radians) is a
/// corner, its sharp trailing edge, made blunt by
/// [`TRAILING_EDGE_THICKNESS`] (an airfoil's sharp trailing edge turns by
/// nearly π; a smooth contour's points by a few degrees each).
pub const CORNER_TURNING: f64 = std::f64::consts::FRAC_PI_2;

/// Points on a NACA section or a plate's contour for the map's fit.
pub(super) const CONTOUR_POINTS: usize = 512;
