//! ParaView output: a mesh of quadrilaterals (a shell mesh, or any
//! grid given as points and cells) as a VTK XML unstructured grid
//! (`.vtu`, ASCII), with point fields (e.g. displacement) and cell fields
//! (e.g. density, strain energy). [`write()`] writes to a temporary file
//! and renames it, so a reader never sees half a file (the design run's
//! own directory); [`write_new`] refuses a file that exists (a path the
//! user named).

use std::fmt::Write as _;
use std::io;
use std::path::Path;

use crate::shell::mesh::ShellMesh;

/// A field to write: name and values (3 components a point for vectors).
#[derive(Clone, Copy, Debug)]
pub enum Field<'a> {
    /// One value per point.
    PointScalar(&'a str, &'a [f64]),
    /// Three values per point (x, y, z), e.g. displacement.
    PointVector(&'a str, &'a [[f64; 3]]),
    /// One value per cell.
    CellScalar(&'a str, &'a [f64]),
}

/// Why a file was not written.
#[derive(Debug, thiserror::Error)]
pub enum VtuError {
    /// A field's length does not match the mesh.
    #[error("field {name:?} has {got} values for {expected} points or cells")]
    Length {
        /// Field name.
        name: String,
        /// Values given.
        got: usize,
        /// Values expected.
        expected: usize,
    },
    /// A cell names a point that is not there.
    #[error("a cell names point {index} of {points}")]
    Cell {
        /// The point's index.
        index: usize,
        /// Points given.
        points: usize,
    },
    /// The file could not be written.
    #[error("writing {path}: {source}")]
    Io {
        /// Target path.
        path: String,
        /// Cause.
        source: io::Error,
    },
}

/// The `.vtu` text of `mesh` with `fields`.
pub fn to_string(mesh: &ShellMesh, fields: &[Field<'_>]) -> Result<String, VtuError> {
    let points: Vec<[f64; 3]> = mesh.nodes.iter().map(|p| [p.x, p.y, p.z]).collect();
    quads_to_string(&points, &mesh.elements, fields)
}

/// The `.vtu` text of the quadrilaterals `quads` (four indices into
/// `points` each, in order round the cell) with `fields`.
pub fn quads_to_string(
    points: &[[f64; 3]],
    quads: &[[usize; 4]],
    fields: &[Field<'_>],
) -> Result<String, VtuError> {
    let (np, nc) = (points.len(), quads.len());
    for f in fields {
        let (name, got, expected) = match f {
            Field::PointScalar(n, v) => (n, v.len(), np),
            Field::PointVector(n, v) => (n, v.len(), np),
            Field::CellScalar(n, v) => (n, v.len(), nc),
        };
        if got != expected {
            return Err(VtuError::Length {
                name: name.to_string(),
                got,
                expected,
            });
        }
    }
    let mut s = String::new();
    // Writing to a String cannot fail.
    let _ = writeln!(s, "<?xml version=\"1.0\"?>");
    let _ = writeln!(
        s,
        "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"{np}\" NumberOfCells=\"{nc}\">"
    );
    s.push_str(
        "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
    );
    for [x, y, z] in points {
        let _ = writeln!(s, "{x:e} {y:e} {z:e}");
    }
    s.push_str("</DataArray>\n</Points>\n<Cells>\n");
    s.push_str("<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for e in quads {
        if let Some(&i) = e.iter().find(|&&i| i >= np) {
            return Err(VtuError::Cell {
                index: i,
                points: np,
            });
        }
        let _ = writeln!(s, "{} {} {} {}", e[0], e[1], e[2], e[3]);
    }
    s.push_str("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for i in 1..=nc {
        let _ = write!(s, "{} ", 4 * i);
    }
    s.push_str("\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    // VTK_QUAD = 9.
    s.push_str(&"9 ".repeat(nc));
    s.push_str("\n</DataArray>\n</Cells>\n<PointData>\n");
    for f in fields {
        match f {
            Field::PointScalar(name, v) => scalar_array(&mut s, name, v),
            Field::PointVector(name, v) => {
                let _ = writeln!(
                    s,
                    "<DataArray type=\"Float64\" Name=\"{name}\" NumberOfComponents=\"3\" format=\"ascii\">"
                );
                for [x, y, z] in v.iter() {
                    let _ = writeln!(s, "{x:e} {y:e} {z:e}");
                }
                s.push_str("</DataArray>\n");
            }
            Field::CellScalar(..) => {}
        }
    }
    s.push_str("</PointData>\n<CellData>\n");
    for f in fields {
        if let Field::CellScalar(name, v) = f {
            scalar_array(&mut s, name, v);
        }
    }
    s.push_str("</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    Ok(s)
}

fn scalar_array(s: &mut String, name: &str, v: &[f64]) {
    let _ = writeln!(
        s,
        "<DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">"
    );
    for x in v {
        let _ = write!(s, "{x:e} ");
    }
    s.push_str("\n</DataArray>\n");
}

/// Writes `mesh` with `fields` to `path` atomically.
pub fn write(path: &Path, mesh: &ShellMesh, fields: &[Field<'_>]) -> Result<(), VtuError> {
    let text = to_string(mesh, fields)?;
    let io_error = |source| VtuError::Io {
        path: path.display().to_string(),
        source,
    };
    let temporary = path.with_extension("vtu.partial");
    std::fs::write(&temporary, text).map_err(io_error)?;
    std::fs::rename(&temporary, path).map_err(io_error)
}

/// Writes the quadrilaterals `quads` of `points` with `fields` to
/// `path`, which must not exist: a file there is refused, not replaced
/// (the error's source is then of kind `AlreadyExists`). A write that
/// fails part way removes what it wrote.
pub fn write_new(
    path: &Path,
    points: &[[f64; 3]],
    quads: &[[usize; 4]],
    fields: &[Field<'_>],
) -> Result<(), VtuError> {
    use std::io::Write as _;
    let text = quads_to_string(points, quads, fields)?;
    let io_error = |source| VtuError::Io {
        path: path.display().to_string(),
        source,
    };
    let mut file = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
        .map_err(io_error)?;
    file.write_all(text.as_bytes())
        .and_then(|()| file.sync_all())
        .map_err(|e| {
            // The name was ours (created above): take back the part written.
            let _ = std::fs::remove_file(path);
            io_error(e)
        })
}

/// Per-node translations `[u, v, w]` of a global 6-DOF vector.
pub fn translations(u: &[f64]) -> Vec<[f64; 3]> {
    u.chunks_exact(6).map(|c| [c[0], c[1], c[2]]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_small_grid_is_well_formed() {
        let mesh = ShellMesh::rectangle(1.0, 1.0, 2, 1).unwrap();
        let d = vec![[0.0, 0.0, 1.0]; 6];
        let rho = [1.0, 0.5];
        let text = to_string(
            &mesh,
            &[
                Field::PointVector("displacement", &d),
                Field::CellScalar("density", &rho),
            ],
        )
        .unwrap();
        assert!(text.contains("NumberOfPoints=\"6\" NumberOfCells=\"2\""));
        assert!(text.contains("Name=\"density\"") && text.contains("4 8"));
        assert_eq!(
            text.matches("<DataArray").count(),
            text.matches("</DataArray>").count()
        );
        let outside = quads_to_string(&[[0.0; 3]; 3], &[[0, 1, 2, 3]], &[]);
        assert!(matches!(
            outside,
            Err(VtuError::Cell {
                index: 3,
                points: 3
            })
        ));
        let bad = to_string(&mesh, &[Field::CellScalar("density", &[1.0])]);
        assert!(matches!(
            bad,
            Err(VtuError::Length {
                got: 1,
                expected: 2,
                ..
            })
        ));
    }
}
