//! A viscous run's flow ([`FlowField`]) as ParaView files: the grid's
//! cells as quadrilaterals in the plane `z = 0`, the vorticity, the
//! streamfunction and the velocity at the nodes; at the run's end
//! (`fwav aero2d --model ns --field FILE.vtu`, ASCII, double precision)
//! or as a series through the run (`--field-series DIR`: binary, single
//! precision, and a `.pvd` that ParaView plays).

use std::path::{Path, PathBuf};

use super::vtu::{self, Field, VtuError};
use crate::aero2d::viscous::{FlowField, FrameSink};

/// Writes `field` to `path` as a `.vtu` (point fields `vorticity`,
/// `streamfunction` and the vector `velocity`, [`FlowField`]'s units).
/// A file that exists is refused ([`vtu::write_new`]).
///
/// # Errors
/// [`VtuError`]: the file exists or could not be written.
pub fn write_flow_field(field: &FlowField, path: &Path) -> Result<(), VtuError> {
    let arrays = FlowArrays::of(field);
    vtu::write_new(path, &arrays.points, &field.quads(), &arrays.fields(field))
}

/// A flow's points and velocity as ParaView's 3-vectors (`z` = 0), for
/// the arrays every flow file holds: the same in `--field` and in each
/// frame of a series.
struct FlowArrays {
    points: Vec<[f64; 3]>,
    velocity: Vec<[f64; 3]>,
}

impl FlowArrays {
    fn of(field: &FlowField) -> Self {
        Self {
            points: field.points.iter().map(|&(x, y)| [x, y, 0.0]).collect(),
            velocity: field.velocity.iter().map(|&(u, v)| [u, v, 0.0]).collect(),
        }
    }

    /// The point arrays of `field` (of which these are the vectors).
    fn fields<'a>(&'a self, field: &'a FlowField) -> [Field<'a>; 3] {
        [
            Field::PointScalar("vorticity", &field.vorticity),
            Field::PointScalar("streamfunction", &field.streamfunction),
            Field::PointVector("velocity", &self.velocity),
        ]
    }
}

/// The file name of frame `k` of a series ([`FlowSeries`]).
pub fn series_file(k: usize) -> String {
    format!("flow-{k:04}.vtu")
}

/// The series' time collection, `dir/flow.pvd`.
pub const SERIES_COLLECTION: &str = "flow.pvd";

/// A series of flows being written into a directory, one binary `.vtu`
/// a flow as it comes ([`series_file`]; [`vtu::quads_to_binary`]: 5.2 MB
/// a frame on the default FWAV section's grid, under a third of the
/// ASCII file) and [`SERIES_COLLECTION`], the collection ParaView plays,
/// written again after each frame: a run that stops part way leaves a
/// series ParaView opens, up to its last frame. A file that exists is
/// refused, not replaced (the collection is the series' own).
#[derive(Debug)]
pub struct FlowSeries {
    dir: PathBuf,
    entries: Vec<(f64, String)>,
}

impl FlowSeries {
    /// A series into `dir`, created if missing.
    ///
    /// # Errors
    /// [`VtuError::Io`]: the directory could not be made.
    pub fn create(dir: &Path) -> Result<Self, VtuError> {
        std::fs::create_dir_all(dir).map_err(|source| VtuError::Io {
            path: dir.display().to_string(),
            source,
        })?;
        Ok(Self {
            dir: dir.to_path_buf(),
            entries: Vec::new(),
        })
    }

    /// Writes `frame` as the series' next `.vtu`, at its time in chords
    /// travelled, and the collection with it.
    ///
    /// # Errors
    /// [`VtuError`]: the frame's file exists or a file could not be
    /// written.
    pub fn write(&mut self, frame: &FlowField) -> Result<(), VtuError> {
        let arrays = FlowArrays::of(frame);
        let bytes = vtu::quads_to_binary(&arrays.points, &frame.quads(), &arrays.fields(frame))?;
        let name = series_file(self.entries.len());
        vtu::write_new_bytes(&self.dir.join(&name), &bytes)?;
        self.entries.push((frame.time, name));
        crate::files::write_atomic(&self.dir, SERIES_COLLECTION, vtu::collection(&self.entries))?;
        Ok(())
    }

    /// Frames written so far.
    #[must_use]
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// Whether no frame is written yet.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// The collection's path.
    #[must_use]
    pub fn collection(&self) -> PathBuf {
        self.dir.join(SERIES_COLLECTION)
    }
}

impl FrameSink for FlowSeries {
    fn take(&mut self, frame: &FlowField) -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
        Ok(self.write(frame)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two rings of three nodes: three cells and both fields written; a
    /// second write to the same path is refused and leaves the first.
    #[test]
    fn a_field_is_written_once() {
        let field = FlowField {
            time: 0.0,
            around: 3,
            rings: 2,
            points: (0..6).map(|i| (f64::from(i), 0.5)).collect(),
            vorticity: vec![1.5; 6],
            streamfunction: vec![-2.0; 6],
            velocity: vec![(0.25, -0.5); 6],
        };
        let dir = std::env::temp_dir().join(format!("fwav-field-vtu-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("flow.vtu");
        std::fs::remove_file(&path).ok();
        write_flow_field(&field, &path).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.contains("NumberOfPoints=\"6\" NumberOfCells=\"3\""));
        assert!(text.contains("Name=\"vorticity\"") && text.contains("Name=\"streamfunction\""));
        assert!(text.contains("2 0 3 5"), "the last cell closes the ring");
        let again = write_flow_field(&field, &path);
        assert!(
            matches!(&again, Err(VtuError::Exists { path: p }) if p == &path.display().to_string()),
            "{again:?}"
        );
        assert_eq!(std::fs::read_to_string(&path).unwrap(), text);
        std::fs::remove_dir_all(&dir).ok();
    }
}
