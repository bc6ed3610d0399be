//! Output for a person: the pictures (PNG, drawn with plotters) and the
//! ParaView files (`.vtu`, `.pvd`) of the solvers' results.
//!
//! - [`drawing`]: the one drawing error and what every picture shares.
//! - [`section_plot`]: one 2D section run ([`crate::aero2d`]): the wake
//!   and the section, and the force histories; [`history_csv`]: the
//!   histories as CSV; [`surface_csv`]: a viscous run's wall pressure
//!   and skin friction as CSV; [`flow_field_vtu`]: a viscous run's flow
//!   at its end (vorticity and streamfunction on the grid) for ParaView.
//! - [`discipline_plot`]: the aerodynamic discipline
//!   ([`crate::discipline`]): main effects and the CT–efficiency plane
//!   with the Pareto front.
//! - [`layout_picture`]: a carbon layout ([`crate::topology`]) as a
//!   picture of the planform.
//! - [`vtu`]: the ParaView writer: a shell mesh, or any mesh of
//!   quadrilaterals, with point and cell fields.
//! - [`wing_series`]: a system analysis ([`crate::aeroelastic`]) as
//!   ParaView time series of the deformed wing and its wake.
//!
//! What it may import: the solvers' result types and meshes (`aero2d`,
//! `discipline`, `topology`, `shell`, `aeroelastic`) and plotters.
//! What may import it: the program (`src/cli`) and the design run, whose
//! own report and pictures live in [`crate::mdois`]'s `output` (they
//! render the run's records, so they sit beside them, and this room need
//! not know the design run). No solver room (`aero2d`, `uvlm`, `shell`,
//! `aeroelastic`, `topology`, `discipline`, `optimize`, `validation`)
//! imports this room or plotters: the numbers do not depend on how they
//! are shown.

pub mod discipline_plot;
pub mod drawing;
pub mod flow_field_vtu;
pub mod history_csv;
pub mod layout_picture;
pub mod section_plot;
pub mod surface_csv;
pub mod vtu;
pub mod wing_series;

pub use drawing::DrawingError;
