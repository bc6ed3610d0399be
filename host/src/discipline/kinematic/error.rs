//! Why the aerodynamic discipline stopped ([`KinematicError`]): each
//! variant carries what was found, the methods' own typed errors
//! included.

use crate::optimize::anom::AnomError;
use crate::optimize::doe::DoeError;
use crate::optimize::nsga2::Nsga2Error;
use crate::optimize::rsm::RsmError;

/// Why the discipline stopped.
#[derive(Debug, thiserror::Error)]
pub enum KinematicError {
    /// The initial design could not be evaluated.
    #[error("the initial design's 2D run failed: {0}")]
    Initial(String),
    /// The initial design gives no net thrust, so it cannot be the
    /// objective's reference (its ratios would flip sign).
    #[error(
        "the initial design's net thrust coefficient {ct_net:.4} (before the friction estimate \
         {ct:.4}) must be positive to serve as the objective's reference: start from \
         kinematics that produce thrust (a higher frequency or amplitude)"
    )]
    NoNetThrust {
        /// Net thrust coefficient (CT less friction).
        ct_net: f64,
        /// Thrust coefficient before the friction estimate (the LDVM's
        /// inviscid one; the net one for the Navier–Stokes model).
        ct: f64,
    },
    /// The L18 array could not be laid out over the design space's
    /// levels.
    #[error("the L18 array over the design space: {0}")]
    Array(#[from] DoeError),
    /// Every row of the L18 array failed its 2D analysis, so there is
    /// nothing to compare or fit.
    #[error(
        "every one of the {rows} L18 rows' 2D analyses failed, the first with: {first}; \
         bring the design space's levels within what the section model can run"
    )]
    EveryRowFailed {
        /// The rows run.
        rows: usize,
        /// Why the first row failed (as recorded, also in a cache).
        first: String,
    },
    /// ANOM refused the rows' combined objectives.
    #[error("ANOM of the L18 rows' combined objective: {0}")]
    Anom(#[from] AnomError),
    /// A response surface could not be fitted to the rows.
    #[error("the {response} response surface over the L18 rows: {source}")]
    Surface {
        /// The response: `"thrust"` or `"efficiency"`.
        response: &'static str,
        /// Why the fit failed.
        source: RsmError,
    },
    /// NSGA-II refused its bounds or settings.
    #[error("NSGA-II on the response surfaces: {0}")]
    Search(#[from] Nsga2Error),
    /// Every design on the response surfaces' front violates the
    /// actuator's limits.
    #[error(
        "NSGA-II found no design on the response surfaces that the actuator can fly with its \
         reserve: widen the design space toward lower frequencies and amplitudes, or give the \
         actuator more reach (gear ratio, spring, battery)"
    )]
    NothingFlyable,
}
