//! The design run's result files for a person: `summary.json` and the
//! ParaView files of the layouts ([`files`]), the run's pictures
//! ([`plot`]) and `report.md` ([`report`]).
//!
//! They render the run's own records (the stages' records of
//! [`super::records`], [`super::summary::Summary`], the driver's stage
//! context) and the driver calls them, so they live in
//! this sub-room of [`crate::mdois`] rather than in [`crate::output`]:
//! there they would make an import circle `mdois` ↔ `output`. They draw
//! and write with [`crate::output`]'s tools (the drawing error, the
//! discipline's plots, the layout picture, the ParaView writer); nothing
//! here computes a stage, and nothing outside `mdois` imports this room.
//!
//! May import: [`crate::output`], [`crate::files`], the records and result
//! types of `mdois` and of the solvers it ran.

pub mod files;
pub mod plot;
pub mod report;
