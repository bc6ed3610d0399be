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
}
