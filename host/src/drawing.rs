//! The one error of every picture the host draws with plotters (the 2D
//! flow plots, the discipline's main effects and Pareto plane, the layout
//! picture, the design run's plots): the backend's error (font, file,
//! bitmap), or an input the picture cannot show, as a message.

use std::error::Error;

use plotters::prelude::DrawingAreaErrorKind;

/// A picture could not be drawn, with the reason.
#[derive(Debug, thiserror::Error)]
#[error("picture: {0}")]
pub struct DrawingError(pub(crate) String);

impl<E: Error + Send + Sync> From<DrawingAreaErrorKind<E>> for DrawingError {
    fn from(e: DrawingAreaErrorKind<E>) -> Self {
        Self(e.to_string())
    }
}
