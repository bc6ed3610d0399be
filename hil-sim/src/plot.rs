//! Pictures of a run: target and measured angle, motor current and duty
//! over the last second, as a PNG.

use std::path::Path;

use plotters::prelude::*;
use plotters_backend::DrawingErrorKind;
use plotters_bitmap::BitMapBackendError;

use fwav_files::{create_new, NewFileError, WriteError};

use crate::metrics::TracePoint;

/// The picture could not be drawn.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// The PNG file could not be written (no such directory, no
    /// permission, disk full): the file system's or the encoder's reason.
    #[error("cannot write the file: {0}")]
    File(Box<dyn std::error::Error + Send + Sync>),
    /// The text could not be drawn (no font of the family found).
    #[error("font: {0}")]
    Font(Box<dyn std::error::Error + Send + Sync>),
    /// The plotting backend failed otherwise (its message).
    #[error("{0}")]
    Backend(String),
    /// Something has the picture's name ([`WriteError::Exists`]): it is
    /// left as it was (an existing file is never overwritten).
    #[error(transparent)]
    Exists(WriteError),
}

/// The picture's file could not be made: its name is taken
/// ([`PlotError::Exists`]), or the file system's reason ([`PlotError::File`];
/// the command names the file already).
impl From<WriteError> for PlotError {
    fn from(e: WriteError) -> Self {
        match e {
            WriteError::Io { source, .. } => Self::File(Box::new(source)),
            exists @ WriteError::Exists { .. } => Self::Exists(exists),
        }
    }
}

/// The bitmap backend's errors, whose own text is Rust's debug form
/// (`ImageError(IoError(Os { code: 2, ...`), taken apart into their
/// reason.
impl From<DrawingAreaErrorKind<BitMapBackendError>> for PlotError {
    fn from(e: DrawingAreaErrorKind<BitMapBackendError>) -> Self {
        match e {
            DrawingAreaErrorKind::BackendError(DrawingErrorKind::DrawingError(bitmap)) => {
                match bitmap {
                    BitMapBackendError::IOError(io) => Self::File(Box::new(io)),
                    BitMapBackendError::ImageError(image) => Self::File(Box::new(image)),
                    BitMapBackendError::InvalidBuffer => {
                        Self::Backend("the pixel buffer does not fit the picture".into())
                    }
                }
            }
            DrawingAreaErrorKind::BackendError(DrawingErrorKind::FontError(font)) => {
                Self::Font(font)
            }
            other => Self::Backend(other.to_string()),
        }
    }
}

/// Checks that `png` can be made new, before a run that ends by drawing
/// it: nothing has the name ([`PlotError::Exists`]) and its directory is
/// one ([`PlotError::File`]).
pub fn check_new(png: &Path) -> Result<(), PlotError> {
    fwav_files::check_new(png).map_err(|e| match e {
        NewFileError::Taken(path) => PlotError::Exists(WriteError::Exists { path }),
        not_a_directory @ NewFileError::NotADirectory(_) => {
            PlotError::File(not_a_directory.to_string().into())
        }
        NewFileError::Directory { source, .. } => PlotError::File(Box::new(source)),
    })
}

/// Draws the last second of `trace` to the new file `png`
/// ([`fwav_files::create_new`]: drawn under a temporary name beside it,
/// which takes the name only if nothing has it, so that a file there, or
/// made meanwhile, is never replaced).
pub fn draw(trace: &[TracePoint], png: &Path) -> Result<(), PlotError> {
    check_new(png)?;
    create_new(png, |temporary| draw_to(trace, temporary))
}

/// Draws the last second of `trace` to `png`, whatever is there.
fn draw_to(trace: &[TracePoint], png: &Path) -> Result<(), PlotError> {
    let end = trace.last().map_or(0.0, |p| p.sample.time_s);
    let shown: Vec<&TracePoint> = trace
        .iter()
        .filter(|p| p.sample.time_s >= end - 1.0)
        .collect();
    let (t0, t1) = (
        shown.first().map_or(0.0, |p| p.sample.time_s),
        end.max(1e-3),
    );
    let root = BitMapBackend::new(png, (1200, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((3, 1));

    let max_angle = shown
        .iter()
        .map(|p| p.sample.angle_rad.abs().max(p.target_rad.abs()))
        .fold(0.1, f64::max)
        .to_degrees()
        * 1.1;
    let mut chart = ChartBuilder::on(&panels[0])
        .caption("flapping angle", ("sans-serif", 20))
        .margin(8)
        .x_label_area_size(30)
        .y_label_area_size(60)
        .build_cartesian_2d(t0..t1, -max_angle..max_angle)?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .y_desc("angle (deg)")
        .draw()?;
    chart
        .draw_series(LineSeries::new(
            shown
                .iter()
                .map(|p| (p.sample.time_s, p.target_rad.to_degrees())),
            &BLUE,
        ))?
        .label("target")
        .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLUE));
    chart
        .draw_series(LineSeries::new(
            shown
                .iter()
                .map(|p| (p.sample.time_s, p.sample.angle_rad.to_degrees())),
            &RED,
        ))?
        .label("wing")
        .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], RED));
    chart.configure_series_labels().border_style(BLACK).draw()?;

    let max_i = shown
        .iter()
        .map(|p| p.sample.current_a.abs())
        .fold(0.1, f64::max)
        * 1.1;
    let mut chart = ChartBuilder::on(&panels[1])
        .caption("motor current", ("sans-serif", 20))
        .margin(8)
        .x_label_area_size(30)
        .y_label_area_size(60)
        .build_cartesian_2d(t0..t1, -max_i..max_i)?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .y_desc("current (A)")
        .draw()?;
    chart.draw_series(LineSeries::new(
        shown.iter().map(|p| (p.sample.time_s, p.sample.current_a)),
        &MAGENTA,
    ))?;

    let mut chart = ChartBuilder::on(&panels[2])
        .caption("H-bridge duty", ("sans-serif", 20))
        .margin(8)
        .x_label_area_size(30)
        .y_label_area_size(60)
        .build_cartesian_2d(t0..t1, -1.05f64..1.05)?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .y_desc("duty")
        .draw()?;
    chart.draw_series(LineSeries::new(
        shown
            .iter()
            .map(|p| (p.sample.time_s, f64::from(p.sample.duty))),
        &GREEN,
    ))?;
    root.present()?;
    Ok(())
}
