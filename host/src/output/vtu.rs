//! ParaView output: a mesh of quadrilaterals (a shell mesh, or any
//! grid given as points and cells) as a VTK XML unstructured grid
//! (`.vtu`), with point fields (e.g. displacement) and cell fields
//! (e.g. density, strain energy): ASCII in double precision
//! ([`quads_to_string`]), or binary in single precision
//! ([`quads_to_binary`]: under a third of the size, for series of large
//! grids). [`write()`] writes through a temporary file, so a reader
//! never sees half a file, over a file there (the design run's own
//! directory) or not (an output directory the user named) as its
//! [`Existing`] says; [`write_new`] and [`write_new_bytes`] refuse a file
//! that exists (a path the user named).

use std::fmt::Write as _;
use std::io;
use std::path::Path;

use crate::files::Existing;
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
    /// A binary file's cells index points, and count their corners, by
    /// 32-bit integers.
    #[error(
        "{points} points and {cells} cells are more than a binary .vtu's 32-bit cells can hold"
    )]
    TooManyPoints {
        /// Points given.
        points: usize,
        /// Cells given.
        cells: usize,
    },
    /// A file is where a new one was to be written: it is left as it is.
    #[error(
        "{path} exists, and is left as it is (an existing file is never overwritten): choose a \
         new name or remove it"
    )]
    Exists {
        /// The file found there.
        path: String,
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

impl From<crate::files::WriteError> for VtuError {
    fn from(e: crate::files::WriteError) -> Self {
        use crate::files::WriteError;
        match e {
            WriteError::Exists { path } => Self::Exists {
                path: path.display().to_string(),
            },
            WriteError::Io { path, source } => Self::Io {
                path: path.display().to_string(),
                source,
            },
        }
    }
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
    check_lengths(np, nc, fields)?;
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

/// The `.vtu` bytes of the quadrilaterals `quads` (four indices into
/// `points` each) with `fields`, binary: the XML names each array and
/// its offset, and the arrays follow raw in the file's appended section
/// (little-endian, each after its length in bytes as a 64-bit integer):
/// points and fields as 32-bit floats (7 significant digits), cells as
/// 32-bit integers. VTK's XML reader (ParaView's) reads it. Cost `O(N)`.
pub fn quads_to_binary(
    points: &[[f64; 3]],
    quads: &[[usize; 4]],
    fields: &[Field<'_>],
) -> Result<Vec<u8>, VtuError> {
    let (np, nc) = (points.len(), quads.len());
    check_lengths(np, nc, fields)?;
    if i32::try_from(np).is_err() || i32::try_from(4 * nc).is_err() {
        return Err(VtuError::TooManyPoints {
            points: np,
            cells: nc,
        });
    }
    let mut appended = Appended::default();
    let mut xml = String::new();
    let _ = writeln!(xml, "<?xml version=\"1.0\"?>");
    let _ = writeln!(
        xml,
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"{np}\" NumberOfCells=\"{nc}\">"
    );
    let floats = |v: &mut dyn Iterator<Item = f64>| -> Vec<u8> {
        v.flat_map(|x| (x as f32).to_le_bytes()).collect()
    };
    let offset = appended.push(&floats(&mut points.iter().flatten().copied()));
    let _ = writeln!(
        xml,
        "<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"appended\" offset=\"{offset}\"/>\n</Points>\n<Cells>"
    );
    let mut connectivity = Vec::with_capacity(16 * nc);
    for e in quads {
        for &i in e {
            if i >= np {
                return Err(VtuError::Cell {
                    index: i,
                    points: np,
                });
            }
            // Below `np`, which fits (checked above).
            connectivity.extend_from_slice(&(i as i32).to_le_bytes());
        }
    }
    let offsets: Vec<u8> = (1..=nc)
        .flat_map(|i| ((4 * i) as i32).to_le_bytes())
        .collect();
    // VTK_QUAD = 9.
    for (name, kind, bytes) in [
        ("connectivity", "Int32", connectivity),
        ("offsets", "Int32", offsets),
        ("types", "UInt8", vec![9_u8; nc]),
    ] {
        let offset = appended.push(&bytes);
        let _ = writeln!(
            xml,
            "<DataArray type=\"{kind}\" Name=\"{name}\" format=\"appended\" offset=\"{offset}\"/>"
        );
    }
    xml.push_str("</Cells>\n<PointData>\n");
    let mut array = |xml: &mut String, name: &str, components: usize, bytes: Vec<u8>| {
        let offset = appended.push(&bytes);
        let _ = writeln!(
            xml,
            "<DataArray type=\"Float32\" Name=\"{name}\" NumberOfComponents=\"{components}\" format=\"appended\" offset=\"{offset}\"/>"
        );
    };
    for f in fields {
        match f {
            Field::PointScalar(name, v) => array(&mut xml, name, 1, floats(&mut v.iter().copied())),
            Field::PointVector(name, v) => {
                array(&mut xml, name, 3, floats(&mut v.iter().flatten().copied()));
            }
            Field::CellScalar(..) => {}
        }
    }
    xml.push_str("</PointData>\n<CellData>\n");
    for f in fields {
        if let Field::CellScalar(name, v) = f {
            array(&mut xml, name, 1, floats(&mut v.iter().copied()));
        }
    }
    xml.push_str("</CellData>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_");
    let mut bytes = xml.into_bytes();
    bytes.extend_from_slice(&appended.data);
    bytes.extend_from_slice(b"\n</AppendedData>\n</VTKFile>\n");
    Ok(bytes)
}

/// A binary file's appended section as it grows.
#[derive(Default)]
struct Appended {
    data: Vec<u8>,
}

impl Appended {
    /// Appends one array (its length in bytes first) and returns its
    /// offset in the section.
    fn push(&mut self, bytes: &[u8]) -> usize {
        let offset = self.data.len();
        self.data
            .extend_from_slice(&(bytes.len() as u64).to_le_bytes());
        self.data.extend_from_slice(bytes);
        offset
    }
}

/// Each field's length against the points' or cells' count.
fn check_lengths(np: usize, nc: usize, fields: &[Field<'_>]) -> Result<(), VtuError> {
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
    Ok(())
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

/// Writes `mesh` with `fields` to `path` atomically, over a file there
/// or not as `existing` says ([`crate::files::write_to`]).
pub fn write(
    path: &Path,
    mesh: &ShellMesh,
    fields: &[Field<'_>],
    existing: Existing,
) -> Result<(), VtuError> {
    Ok(crate::files::write_to(
        path,
        to_string(mesh, fields)?,
        existing,
    )?)
}

/// Writes the quadrilaterals `quads` of `points` with `fields` to
/// `path`, which must not exist, as [`write_new_bytes`] does.
pub fn write_new(
    path: &Path,
    points: &[[f64; 3]],
    quads: &[[usize; 4]],
    fields: &[Field<'_>],
) -> Result<(), VtuError> {
    write_new_bytes(path, quads_to_string(points, quads, fields)?.as_bytes())
}

/// Writes `bytes` (a file's whole contents) to `path`, which must not
/// exist: a file there, or one made meanwhile, is refused, not replaced
/// ([`VtuError::Exists`]); the file appears whole
/// ([`crate::files::write_new`]).
pub fn write_new_bytes(path: &Path, bytes: &[u8]) -> Result<(), VtuError> {
    Ok(crate::files::write_new(path, bytes)?)
}

/// A `.pvd` time collection of `entries` (time, file name relative to
/// the `.pvd`'s directory), which ParaView opens as one series and plays.
pub fn collection(entries: &[(f64, String)]) -> String {
    let mut s = String::from(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n",
    );
    for (t, file) in entries {
        let _ = writeln!(
            s,
            "<DataSet timestep=\"{t:e}\" part=\"0\" file=\"{file}\"/>"
        );
    }
    s.push_str("</Collection>\n</VTKFile>\n");
    s
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

    /// The binary form of the same grid: its arrays at the offsets the
    /// XML gives, each after its length, the points and fields in single
    /// precision and the cells as 32-bit integers; the same refusals.
    #[test]
    fn a_small_grid_in_binary_is_well_formed() {
        let mesh = ShellMesh::rectangle(1.0, 1.0, 2, 1).unwrap();
        let points: Vec<[f64; 3]> = mesh.nodes.iter().map(|p| [p.x, p.y, p.z]).collect();
        let rho = [1.0, 0.5];
        let bytes = quads_to_binary(
            &points,
            &mesh.elements,
            &[Field::CellScalar("density", &rho)],
        )
        .unwrap();
        let marker = b"<AppendedData encoding=\"raw\">\n_";
        let start = bytes
            .windows(marker.len())
            .position(|w| w == marker)
            .unwrap()
            + marker.len();
        let xml = std::str::from_utf8(&bytes[..start]).unwrap();
        assert!(xml.contains("NumberOfPoints=\"6\" NumberOfCells=\"2\""));
        let offset_of = |name: &str| -> usize {
            let tag = xml.split(&format!("Name=\"{name}\"")).nth(1).unwrap();
            let rest = tag.split("offset=\"").nth(1).unwrap();
            rest[..rest.find('"').unwrap()].parse().unwrap()
        };
        let block = |offset: usize| -> &[u8] {
            let at = start + offset;
            let n = u64::from_le_bytes(bytes[at..at + 8].try_into().unwrap()) as usize;
            &bytes[at + 8..at + 8 + n]
        };
        // The points first, at offset 0: 6 × 3 floats.
        assert_eq!(block(0).len(), 6 * 3 * 4);
        let cells: Vec<i32> = block(offset_of("connectivity"))
            .chunks_exact(4)
            .map(|c| i32::from_le_bytes(c.try_into().unwrap()))
            .collect();
        let expected: Vec<i32> = mesh
            .elements
            .iter()
            .flatten()
            .map(|&i| i32::try_from(i).unwrap())
            .collect();
        assert_eq!(cells, expected);
        assert_eq!(block(offset_of("types")), &[9, 9]);
        let density: Vec<f32> = block(offset_of("density"))
            .chunks_exact(4)
            .map(|c| f32::from_le_bytes(c.try_into().unwrap()))
            .collect();
        assert_eq!(density, [1.0, 0.5]);
        assert!(bytes.ends_with(b"</AppendedData>\n</VTKFile>\n"));
        let outside = quads_to_binary(&[[0.0; 3]; 3], &[[0, 1, 2, 3]], &[]);
        assert!(matches!(
            outside,
            Err(VtuError::Cell {
                index: 3,
                points: 3
            })
        ));
        let bad = quads_to_binary(
            &points,
            &mesh.elements,
            &[Field::CellScalar("density", &[1.0])],
        );
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
