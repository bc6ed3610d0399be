//! A viscous run's flow at its end ([`FlowField`]) as a ParaView file:
//! the grid's cells as quadrilaterals in the plane `z = 0`, the
//! vorticity and the streamfunction at the nodes (`fwav aero2d --model
//! ns --field FILE.vtu`).

use std::path::Path;

use super::vtu::{self, Field, VtuError};
use crate::aero2d::viscous::FlowField;

/// Writes `field` to `path` as a `.vtu` (point fields `vorticity` and
/// `streamfunction`, [`FlowField`]'s units). A file that exists is
/// refused ([`vtu::write_new`]).
///
/// # Errors
/// [`VtuError`]: the file exists or could not be written.
pub fn write_flow_field(field: &FlowField, path: &Path) -> Result<(), VtuError> {
    let points: Vec<[f64; 3]> = field.points.iter().map(|&(x, y)| [x, y, 0.0]).collect();
    vtu::write_new(
        path,
        &points,
        &field.quads(),
        &[
            Field::PointScalar("vorticity", &field.vorticity),
            Field::PointScalar("streamfunction", &field.streamfunction),
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two rings of three nodes: three cells and both fields written; a
    /// second write to the same path is refused and leaves the first.
    #[test]
    fn a_field_is_written_once() {
        let field = FlowField {
            around: 3,
            rings: 2,
            points: (0..6).map(|i| (f64::from(i), 0.5)).collect(),
            vorticity: vec![1.5; 6],
            streamfunction: vec![-2.0; 6],
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
            matches!(&again, Err(VtuError::Io { source, .. })
                if source.kind() == std::io::ErrorKind::AlreadyExists),
            "{again:?}"
        );
        assert_eq!(std::fs::read_to_string(&path).unwrap(), text);
        std::fs::remove_dir_all(&dir).ok();
    }
}
