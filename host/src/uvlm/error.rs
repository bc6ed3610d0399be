//! Why a lattice, a setting or a solve of the unsteady vortex-lattice
//! method was rejected.

use fwav_settings::Shown;

/// Errors of the unsteady vortex-lattice method. Every check on user data
/// (lattice sizes, non-finite coordinates, settings) ends here instead of in
/// a panic.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum UvlmError {
    /// A lattice needs at least one panel in each direction.
    #[error("a lattice needs at least one panel each way (got {chordwise} x {spanwise})")]
    EmptyLattice {
        /// Panels along the chord.
        chordwise: usize,
        /// Panels along the span.
        spanwise: usize,
    },
    /// The corner list does not have `(chordwise + 1) * (spanwise + 1)`
    /// points.
    #[error("{got} corners for a {chordwise} x {spanwise} lattice (expected {expected})")]
    CornerCount {
        /// Panels along the chord.
        chordwise: usize,
        /// Panels along the span.
        spanwise: usize,
        /// Points given.
        got: usize,
        /// Points required.
        expected: usize,
    },
    /// A coordinate or velocity is NaN or infinite.
    #[error("{what} {index} is not finite")]
    NonFinite {
        /// Which kind of input ("corner", "corner velocity", ...).
        what: &'static str,
        /// Its index.
        index: usize,
    },
    /// A panel whose diagonals are parallel (zero area, no normal).
    #[error("panel ({i}, {j}) has zero area")]
    DegeneratePanel {
        /// Chordwise index.
        i: usize,
        /// Spanwise index.
        j: usize,
    },
    /// A lattice of another size than the solver was built for.
    #[error("the lattice has {got_chordwise} x {got_spanwise} panels, the solver {chordwise} x {spanwise}")]
    Dimensions {
        /// Panels along the chord of the solver.
        chordwise: usize,
        /// Panels along the span of the solver.
        spanwise: usize,
        /// Panels along the chord of the lattice given.
        got_chordwise: usize,
        /// Panels along the span of the lattice given.
        got_spanwise: usize,
    },
    /// A per-corner or per-panel array of the wrong length.
    #[error("{what}: {got} values, expected {expected}")]
    Length {
        /// Which array.
        what: &'static str,
        /// Length given.
        got: usize,
        /// Length required.
        expected: usize,
    },
    /// A setting or geometric parameter out of its range.
    #[error("{name} = {} is invalid: {requirement}", Shown(*.value))]
    Parameter {
        /// The parameter's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// What it must satisfy.
        requirement: &'static str,
    },
    /// The influence matrix could not be solved (a solution with
    /// non-finite circulations), e.g. two collocation points on top of each
    /// other.
    #[error("the influence matrix is singular (non-finite circulation)")]
    Singular,
}
