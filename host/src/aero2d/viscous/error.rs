//! Why a viscous run cannot be done ([`ViscousError`]).

use fwav_ns2d::NsError;

use crate::aero2d::camber::CamberError;

#[cfg(doc)]
use super::{ViscousSection, MAX_VISCOUS_STEPS, TRAILING_EDGE_LAYER};
#[cfg(doc)]
use fwav_ns2d::{FarStretch, MAX_FAR_GROWTH};

/// Why a viscous run cannot be done.
#[derive(Debug, thiserror::Error)]
pub enum ViscousError {
    /// The solver refused the case (its divergence is [`Self::Diverged`]).
    #[error(transparent)]
    Solver(#[from] NsError),
    /// The flow was not finite after a step of the run
    /// (`NsError::Diverged`, told in the command's terms).
    #[error(
        "the flow is not finite at t = {time:.4} chords travelled (step {step}, a time step of \
         {dt:.3e}): the step is beyond the scheme's stability or the grid cannot resolve the \
         flow; step at a smaller Courant number (now {courant}), on a finer grid, or move the \
         section more gently"
    )]
    Diverged {
        /// The time reached, chords travelled.
        time: f64,
        /// The step number.
        step: usize,
        /// The time step used, chords travelled.
        dt: f64,
        /// The largest Courant number the steps were chosen for.
        courant: f64,
    },
    /// The flow at `time` could not be handed on
    /// ([`super::FrameSink::take`]); the run stopped there.
    #[error("the flow at {time:.4} chords travelled could not be kept: {source}")]
    Frame {
        /// The flow's time, chords travelled.
        time: f64,
        /// The sink's reason.
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// A plate thickness out of range.
    #[error(
        "plate thickness {0} chords: the Navier–Stokes model takes 0.005 to 0.3 chords \
         (thinner plates crowd the grid at the edges beyond any usable time step)"
    )]
    Thickness(f64),
    /// A deformation history given for a motion without a period.
    #[error(
        "a deformation history is periodic, and this motion has no period (a pitch ramp): run \
         the section rigid, or give a periodic motion"
    )]
    DeformingWithoutPeriod,
    /// A plate's deformation sample that is not a mid-line of the section
    /// ([`crate::aero2d::camber::check_midlines`]).
    #[error("the deformation history: {0}")]
    Midline(#[from] CamberError),
    /// A deformation sample the solver cannot map.
    #[error(
        "deformation sample {sample} of {samples}: {source}; check the section history (a \
         mid-line bent tighter than half the plate's thickness, or a contour that crosses itself)"
    )]
    DeformedShape {
        /// The sample (0-based).
        sample: usize,
        /// Samples in the history.
        samples: usize,
        /// What the solver found.
        source: NsError,
    },
    /// A spin-up on a motion without a period, or not shorter than the
    /// run.
    #[error(
        "a spin-up of {periods} periods for a run of {run:.3} periods: the spin-up is counted in \
         periods of a periodic motion and must end before the run does; shorten it or set it to 0"
    )]
    SpinUp {
        /// The spin-up asked for.
        periods: f64,
        /// The run's length in periods (0 without a period).
        run: f64,
    },
    /// A grid coarsened as a whole ([`ViscousSection::with_radial`]) so
    /// far that its far cells, or its spin-up grid's, grow by more than
    /// [`MAX_FAR_GROWTH`].
    #[error(
        "{radial} grid nodes from the wall out make the far field's cells grow by {growth:.3} a \
         ring, more than {max}: give at least {fewest} (--ns-radial)"
    )]
    FarTooCoarse {
        /// The grid's rings.
        radial: usize,
        /// Its far cells' growth (its spin-up grid's, when coarser).
        growth: f64,
        /// The most allowed ([`MAX_FAR_GROWTH`]).
        max: f64,
        /// The fewest rings of the grid that keep it, on the spin-up's
        /// grid too ([`FarStretch::fewest_rings`] without a spin-up).
        fewest: usize,
    },
    /// The grid's wall cells are longer than the laminar boundary layer
    /// is thick at the trailing edge ([`TRAILING_EDGE_LAYER`]): it cannot
    /// resolve this Reynolds number.
    #[error(
        "at Re {reynolds:.0} the grid's longest wall cell, {cell:.2e} chords, is longer than the \
         laminar boundary layer is thick at the trailing edge ({layer:.2e} chords, 5/sqrt(Re)): \
         the grid cannot resolve this Reynolds number; give at least {around} nodes round \
         (--ns-around), or a lower Reynolds number (converged results need finer cells still: \
         the default FWAV plate at Re 12,329 takes 384)"
    )]
    Unresolved {
        /// The Reynolds number.
        reynolds: f64,
        /// The longest wall cell, chords.
        cell: f64,
        /// The boundary layer's thickness at the trailing edge, chords.
        layer: f64,
        /// The fewest nodes round (even) whose wall cells pass.
        around: usize,
    },
    /// The stable time step keeps falling: the run would take too long.
    #[error(
        "the stable time step fell to {dt:.2e} chords travelled at t = {time:.3} \
         ({steps} steps for the run at that step, more than {max}): the motion is too fast for \
         this grid's cells at the section's edges; choose a thicker or blunter section \
         (--ns-thickness), fewer nodes round it, or a gentler motion"
    )]
    TooManySteps {
        /// The time step reached.
        dt: f64,
        /// When.
        time: f64,
        /// The steps the run would take at that step.
        steps: usize,
        /// The most allowed ([`MAX_VISCOUS_STEPS`]).
        max: usize,
    },
}
