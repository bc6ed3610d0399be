//! The errors of the Navier–Stokes section analysis.

/// What is wrong with a case, and what to change.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum NsError {
    /// A section dimension that is not a positive number.
    #[error("the {what} is {value}: give a positive, finite number")]
    BadSection {
        /// Which dimension.
        what: &'static str,
        /// The value given.
        value: f64,
    },
    /// A section contour with too few points.
    #[error(
        "the section contour has {count} points (a last point closing it on the first not \
         counted): give at least 8 points round the section"
    )]
    ContourTooFewPoints {
        /// The points given, a closing repeat of the first not counted
        /// (points repeated elsewhere are [`NsError::ContourRepeatedPoint`]
        /// once there are 8).
        count: usize,
    },
    /// A contour point that is not a finite number.
    #[error(
        "section contour point {index} is ({x}, {y}): every coordinate must be a finite number"
    )]
    ContourPointNotFinite {
        /// The point's index (from 0, in the order given).
        index: usize,
        /// Its x.
        x: f64,
        /// Its y.
        y: f64,
    },
    /// Two consecutive contour points that coincide.
    #[error(
        "section contour points {index} and {next} coincide at ({x}, {y}): remove the repeated point"
    )]
    ContourRepeatedPoint {
        /// The first point's index (in the order given).
        index: usize,
        /// The next point's index.
        next: usize,
        /// The point's x.
        x: f64,
        /// The point's y.
        y: f64,
    },
    /// The contour crosses (or touches) itself.
    #[error(
        "the section contour crosses itself: segment {first} (points {first}->{first_end}) meets \
         segment {second} (points {second}->{second_end}) near ({x:.6}, {y:.6}); the points must go \
         once round the section without loops (a figure-eight or bow-tie is not a section): \
         reorder or remove the points there"
    )]
    ContourCrossing {
        /// The first segment (from point `first` to `first_end`, in the order given).
        first: usize,
        /// Its end point.
        first_end: usize,
        /// The second segment.
        second: usize,
        /// Its end point.
        second_end: usize,
        /// Where they meet, x.
        x: f64,
        /// Where they meet, y.
        y: f64,
    },
    /// A contour that encloses (next to) no area.
    #[error(
        "the section contour encloses an area of {area:.3e} for a perimeter of {perimeter:.3e}: \
         the points lie on a line; give a closed section of finite thickness"
    )]
    ContourDegenerate {
        /// The enclosed area.
        area: f64,
        /// The perimeter.
        perimeter: f64,
    },
    /// A NACA designation that is not four digits with a valid camber position.
    #[error(
        "{code:?} is not a NACA 4-digit section: give four digits MPTT (camber M %, its position \
         P tenths of chord, thickness TT %), P from 1 to 9 when M > 0, TT from 01"
    )]
    BadNaca {
        /// The designation given.
        code: String,
    },
    /// The numerical conformal map did not converge.
    #[error(
        "the conformal map of the section did not converge ({}): \
         the contour is too thin, too sharp or too hooked for its {points} points; give more \
         points where it turns fast, round its corners, thicken it if it is thin, or give a \
         less extreme section",
        if correction.is_finite() {
            format!(
                "in up to {iterations} Newton steps a try, the closest ended with a boundary \
                 correction {correction:.3e} of the perimeter"
            )
        } else {
            "every try's first Newton step failed".to_string()
        }
    )]
    MapNotConverged {
        /// The most Newton steps a try takes.
        iterations: usize,
        /// The smallest of the tries' last corrections of the boundary
        /// correspondence, over the perimeter (each pre-map's, and the
        /// zipper's start's: `correspondence.rs`).
        correction: f64,
        /// The contour's points.
        points: usize,
    },
    /// The fitted Laurent series is not one-to-one outside the unit circle.
    #[error(
        "the fitted map with {terms} terms is not one-to-one outside the unit circle (its \
         derivative has {zeros} zeros there): use more terms, or more points where the contour \
         turns fast"
    )]
    MapNotUnivalent {
        /// The number of Laurent terms `b_k`.
        terms: usize,
        /// Zeros of `F'` counted in `|ζ| > 1` (argument principle).
        zeros: i64,
    },
    /// An odd number of nodes round (the grid's ring transforms take even
    /// ones).
    #[error("grid around = {around} is odd: the nodes round must be even, in 16..=8192")]
    OddAround {
        /// The nodes round given.
        around: usize,
    },
    /// A grid setting out of its working range.
    #[error("grid {what} = {value} is outside {min}..={max}")]
    BadGrid {
        /// The setting.
        what: &'static str,
        /// The value given.
        value: f64,
        /// The smallest value that works.
        min: f64,
        /// The largest value that works.
        max: f64,
    },
    /// The first radial cell asked for is coarser than a uniform grid's.
    #[error(
        "the first radial cell {first:.3e} (in ξ) is not finer than a uniform grid's {uniform:.3e}: \
         ask for a smaller first cell or fewer radial nodes"
    )]
    NoStretching {
        /// The first cell asked for.
        first: f64,
        /// The uniform spacing.
        uniform: f64,
    },
    /// A tailed stretching whose rings cannot reach the outer boundary.
    #[error(
        "{radial} rings that keep the {near_radial}-ring grid's cells near the wall cannot reach the \
         outer boundary growing {growth} a cell past them: give more rings or a larger far growth"
    )]
    NoTail {
        /// The grid's rings.
        radial: usize,
        /// The near grid's rings.
        near_radial: usize,
        /// The far growth a cell.
        growth: f64,
    },
    /// The Reynolds number is not a positive number.
    #[error("the Reynolds number is {0}: give a positive, finite number")]
    BadReynolds(f64),
    /// A reference curve's row that is not two numbers (or too few rows).
    #[error("reference curve: {0:?} is not a row of two numbers (x y)")]
    BadReferenceRow(String),
    /// The wall's influence matrix is singular for this time step.
    #[error(
        "the wall vorticity condition has no unique solution for the time step {dt:.3e}: \
         change the time step or the grid"
    )]
    SingularWall {
        /// The time step.
        dt: f64,
    },
    /// The flow was not finite after a step: a time step beyond the
    /// scheme's stability or a case the grid cannot resolve.
    #[error(
        "the flow is not finite at t = {time:.4} (step {step}): the time step {dt:.3e} is beyond \
         the scheme's stability or the grid cannot resolve this Reynolds number; take a smaller \
         time step or a finer grid"
    )]
    Diverged {
        /// The time reached.
        time: f64,
        /// The step number.
        step: usize,
        /// The time step used.
        dt: f64,
    },
    /// A flow continued on a grid of another section
    /// ([`crate::Flow::continue_from`]).
    #[error(
        "the flow to continue is round another section or grid extent (its wall or outer boundary \
         is {distance:.3e} from this grid's): continue a flow only on a grid of the same section, \
         outer radius and time"
    )]
    OtherSection {
        /// The largest distance between the two grids' compared nodes.
        distance: f64,
    },
}
