//! The MDOIS design process (seed paper, "Design process using MDOIS"):
//! multidisciplinary design optimization based on independent subspaces.
//! A cycle is one coupled 3D aeroelastic system analysis of the current
//! design, whose results go to two disciplines that optimize independently
//! and side by side — the flapping kinematics on 2D analyses of the
//! deforming mid-span section ([`crate::discipline`]) and the carbon
//! layout by ESLSO under the pressure history ([`crate::topology`]) — and
//! whose proposals make the next cycle's design. The process stops when no
//! design variable changes.
//!
//! - [`driver`]: the cycle loop, [`start`] and [`resume`].
//! - [`directory`]: where a run may write ([`RunDir`]: an output
//!   directory checked, made and locked), and [`lock`], its lock file.
//! - [`stage`]: the three stages as functions from files to files (the
//!   computation, and the order of reading, computing and writing).
//! - [`records`]: each stage's JSON record (`system.json`,
//!   `kinematics.json`, `topology.json`) and its reading back.
//! - [`state`]: which stages are finished (`state.json`), resumable.
//! - [`progress`]: what the driver reports as it goes.
//! - [`summary`]: `summary.json`, per cycle and initial against final.
//! - [`output`]: the result files, pictures and `report.md` (drawn with
//!   [`crate::output`]'s tools).
//! - [`plant`]: the designed vehicle as hil-sim's plant file
//!   (`plant.toml`).
//! - [`profile`]: the final kinematics as a flight-controller profile,
//!   within the actuator's limits.
//! - [`error`]: why a run stopped.
//!
//! Imports: every room below it (the configuration, the solvers, the
//! disciplines, [`crate::output`]'s tools for `mdois/output/`); nothing
//! imports `mdois` but the program.

pub mod directory;
pub mod driver;
pub mod error;
pub mod lock;
pub mod output;
pub mod plant;
pub mod profile;
pub mod progress;
pub mod records;
pub mod stage;
pub mod state;
pub mod summary;

pub use directory::{Replace, RunDir};
pub use driver::{resume, start, DesignRun, RunOptions};
pub use error::DesignError;
pub use progress::{Event, Progress};
pub use state::{Outcome, Stage};
