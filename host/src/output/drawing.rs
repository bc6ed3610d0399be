//! The one error of every picture the host draws with plotters (the 2D
//! section plots, the discipline's main effects and Pareto plane, the
//! layout picture, the design run's plots) and what those pictures share.
//! Imports plotters only.

use std::error::Error;

use plotters::prelude::DrawingAreaErrorKind;

/// The font family of every picture's text.
pub(crate) const FONT: &str = "sans-serif";

/// A picture could not be drawn, with the reason.
#[derive(Debug, thiserror::Error)]
pub enum DrawingError {
    /// The plotting backend failed (font, file, bitmap); its message.
    #[error("picture: {0}")]
    Backend(String),
    /// A layout has not one value per element of a non-empty mesh.
    #[error("picture: {values} layout values for {elements} elements")]
    LayoutLength {
        /// Layout values given.
        values: usize,
        /// Elements of the mesh.
        elements: usize,
    },
}

impl<E: Error + Send + Sync> From<DrawingAreaErrorKind<E>> for DrawingError {
    fn from(e: DrawingAreaErrorKind<E>) -> Self {
        Self::Backend(e.to_string())
    }
}
