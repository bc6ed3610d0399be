//! The one error of every picture the host draws with plotters (the 2D
//! section plots, the discipline's main effects and Pareto plane, the
//! layout picture, the design run's plots) and what those pictures share.
//! Imports plotters (and the two crates of its bitmap backend) only.

use std::error::Error;

use plotters::prelude::DrawingAreaErrorKind;
use plotters_backend::DrawingErrorKind;
use plotters_bitmap::BitMapBackendError;

/// The font family of every picture's text.
pub(crate) const FONT: &str = "sans-serif";

/// A picture could not be drawn, with the reason.
#[derive(Debug, thiserror::Error)]
pub enum DrawingError {
    /// The PNG file could not be written (no such directory, no
    /// permission, disk full): the file system's or the encoder's reason.
    #[error("picture: cannot write the file: {0}")]
    File(Box<dyn Error + Send + Sync>),
    /// The picture's name is taken, or its file could not be made
    /// ([`crate::files::create_new`]).
    #[error("picture: {0}")]
    Write(#[from] crate::files::WriteError),
    /// The text could not be drawn (no font of the family found).
    #[error("picture: font: {0}")]
    Font(Box<dyn Error + Send + Sync>),
    /// The plotting backend failed otherwise (its message).
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

/// Every picture is a bitmap: the bitmap backend's errors, whose own
/// text is Rust's debug form (`ImageError(IoError(Os { code: 2, ...`),
/// are taken apart into their reason.
impl<E: Error + Send + Sync + 'static> From<DrawingAreaErrorKind<E>> for DrawingError {
    fn from(e: DrawingAreaErrorKind<E>) -> Self {
        match e {
            DrawingAreaErrorKind::BackendError(DrawingErrorKind::DrawingError(backend)) => {
                let backend: Box<dyn Error + Send + Sync> = Box::new(backend);
                match backend.downcast::<BitMapBackendError>().map(|b| *b) {
                    Ok(BitMapBackendError::IOError(io)) => Self::File(Box::new(io)),
                    Ok(BitMapBackendError::ImageError(image)) => Self::File(Box::new(image)),
                    Ok(BitMapBackendError::InvalidBuffer) => {
                        Self::Backend("the pixel buffer does not fit the picture".into())
                    }
                    Err(other) => Self::Backend(other.to_string()),
                }
            }
            DrawingAreaErrorKind::BackendError(DrawingErrorKind::FontError(font)) => {
                Self::Font(font)
            }
            other => Self::Backend(other.to_string()),
        }
    }
}
