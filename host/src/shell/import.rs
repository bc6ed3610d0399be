//! Bringing a user's wing mesh in: NASTRAN bulk data (GRID, CQUAD4,
//! CTRIA3, PSHELL, MAT1; small-field fixed columns or free field with
//! commas) and Gmsh `.msh` version 4 ASCII (quadrangles and triangles).
//! Triangles become degenerate quadrilaterals `[a, b, c, c]` (the flat
//! MITC4 element collapsed; less accurate than quads, so quad-dominant
//! meshes are preferred).

use std::collections::HashMap;

use nalgebra::Vector3;

use super::element::NODES;
use super::material::{Layer, Section};
use super::mesh::{MeshError, ShellMesh};

/// Why a file was refused; every variant names the line (1-based).
#[derive(Debug, thiserror::Error)]
pub enum ImportError {
    /// A field is not a number where one is needed.
    #[error("line {line}: field {field} ({text:?}) is not a number")]
    Number {
        /// Line.
        line: usize,
        /// Field index (1-based, the card name is field 0).
        field: usize,
        /// Its text.
        text: String,
    },
    /// A card has too few fields.
    #[error("line {line}: {card} needs at least {needed} fields")]
    Short {
        /// Line.
        line: usize,
        /// Card name.
        card: String,
        /// Fields needed.
        needed: usize,
    },
    /// A referenced id is not defined.
    #[error("line {line}: {what} {id} is not defined")]
    Undefined {
        /// Line.
        line: usize,
        /// What kind of id.
        what: &'static str,
        /// The id.
        id: i64,
    },
    /// Something this reader does not handle.
    #[error("line {line}: {message}")]
    Unsupported {
        /// Line.
        line: usize,
        /// What.
        message: String,
    },
    /// A block says it has more entries than the file has lines left.
    #[error("line {line}: a block of {count} entries runs past the end of the file")]
    Truncated {
        /// The block's header line.
        line: usize,
        /// The entries it announces.
        count: usize,
    },
    /// The mesh itself is bad.
    #[error(transparent)]
    Mesh(#[from] MeshError),
}

/// An imported mesh with one section per element (from PSHELL/MAT1; a
/// Gmsh mesh has none and gets the `default` section).
#[derive(Clone, Debug)]
pub struct ImportedMesh {
    /// The mesh.
    pub mesh: ShellMesh,
    /// Section of each element.
    pub sections: Vec<Section>,
    /// The file's id of each node.
    pub node_ids: Vec<i64>,
    /// The file's id of each element.
    pub element_ids: Vec<i64>,
}

/// NASTRAN real: `1.5`, `1.5e-3`, and the exponent shorthand `1.5-3`.
fn nastran_real(text: &str) -> Option<f64> {
    let t = text.trim();
    if let Ok(v) = t.parse::<f64>() {
        return Some(v);
    }
    let bytes = t.as_bytes();
    let split = (1..bytes.len()).rev().find(|&i| {
        (bytes[i] == b'-' || bytes[i] == b'+') && !matches!(bytes[i - 1], b'e' | b'E')
    })?;
    format!("{}e{}", &t[..split], &t[split..]).parse().ok()
}

/// The fields of a bulk-data line (free field if it has a comma, else
/// fixed 8-character columns).
fn fields(line: &str) -> Vec<String> {
    if line.contains(',') {
        line.split(',').map(|f| f.trim().to_string()).collect()
    } else {
        let chars: Vec<char> = line.chars().collect();
        chars
            .chunks(8)
            .map(|c| c.iter().collect::<String>().trim().to_string())
            .collect()
    }
}

/// Reads NASTRAN bulk data.
pub fn nastran(text: &str) -> Result<ImportedMesh, ImportError> {
    let mut bulk = Bulk::default();
    for (index, raw) in text.lines().enumerate() {
        let raw = raw.split('$').next().unwrap_or("");
        if raw.trim().is_empty() {
            continue;
        }
        let fields = fields(raw);
        bulk.read(&Card::new(index + 1, &fields))?;
    }
    bulk.into_mesh()
}

/// One bulk-data line's fields, with the readers of its numbers.
struct Card<'f> {
    /// Line (1-based).
    line: usize,
    /// The card's name, upper case.
    name: String,
    /// Its fields, the name first.
    fields: &'f [String],
}

impl<'f> Card<'f> {
    /// The card of `fields` on `line`.
    fn new(line: usize, fields: &'f [String]) -> Self {
        Self {
            line,
            name: fields[0].to_ascii_uppercase(),
            fields,
        }
    }

    /// Field `i` as a real (an empty or missing field is not one).
    fn number(&self, i: usize) -> Result<f64, ImportError> {
        let text = self.fields.get(i).map(String::as_str).unwrap_or("");
        nastran_real(text).ok_or_else(|| ImportError::Number {
            line: self.line,
            field: i,
            text: text.to_string(),
        })
    }

    /// Field `i` as an integer.
    fn integer(&self, i: usize) -> Result<i64, ImportError> {
        let v = self.number(i)?;
        if v.fract() == 0.0 && v.abs() < 1e15 {
            Ok(v as i64)
        } else {
            Err(ImportError::Number {
                line: self.line,
                field: i,
                text: self.fields[i].clone(),
            })
        }
    }

    /// Whether the card has field `n`.
    fn need(&self, n: usize) -> Result<(), ImportError> {
        if self.fields.len() <= n {
            Err(ImportError::Short {
                line: self.line,
                card: self.name.clone(),
                needed: n,
            })
        } else {
            Ok(())
        }
    }
}

/// The cards read so far.
#[derive(Default)]
struct Bulk {
    /// GRID: id and position.
    grids: Vec<(i64, Vector3<f64>)>,
    /// CQUAD4 and CTRIA3: line, element id, PSHELL id, GRID ids.
    shells: Vec<(usize, i64, i64, Vec<i64>)>,
    /// PSHELL by id: MAT1 id and thickness.
    pshell: HashMap<i64, (i64, f64)>,
    /// MAT1 by id: Young's modulus, Poisson's ratio, density.
    mat1: HashMap<i64, (f64, f64, f64)>,
}

impl Bulk {
    /// Takes in one card (others than GRID, CQUAD4, CTRIA3, PSHELL and
    /// MAT1 are skipped; large-field and continuation cards refused).
    fn read(&mut self, card: &Card<'_>) -> Result<(), ImportError> {
        let (line, f) = (card.line, card.fields);
        match card.name.as_str() {
            "GRID" => {
                card.need(5)?;
                if !f[2].is_empty() && card.integer(2)? != 0 {
                    return Err(ImportError::Unsupported {
                        line,
                        message: "GRID in a coordinate system other than the basic one".into(),
                    });
                }
                self.grids.push((
                    card.integer(1)?,
                    Vector3::new(card.number(3)?, card.number(4)?, card.number(5)?),
                ));
            }
            "CQUAD4" | "CTRIA3" => {
                let corners = if card.name == "CQUAD4" { 4 } else { 3 };
                card.need(2 + corners)?;
                let nodes = (3..3 + corners)
                    .map(|i| card.integer(i))
                    .collect::<Result<_, _>>()?;
                self.shells
                    .push((line, card.integer(1)?, card.integer(2)?, nodes));
            }
            "PSHELL" => {
                card.need(3)?;
                self.pshell
                    .insert(card.integer(1)?, (card.integer(2)?, card.number(3)?));
            }
            "MAT1" => {
                card.need(4)?;
                let e = card.number(2)?;
                let nu = if f[4].is_empty() {
                    // NASTRAN: nu from E and G when only those are given.
                    e / (2.0 * card.number(3)?) - 1.0
                } else {
                    card.number(4)?
                };
                let rho = if f.len() > 5 && !f[5].is_empty() {
                    card.number(5)?
                } else {
                    0.0
                };
                self.mat1.insert(card.integer(1)?, (e, nu, rho));
            }
            c if c.ends_with('*') || c.starts_with('+') || c.starts_with('*') => {
                return Err(ImportError::Unsupported {
                    line,
                    message: format!("large-field or continuation card {c:?}"),
                });
            }
            _ => {}
        }
        Ok(())
    }

    /// The mesh of the cards read, each element with the section of its
    /// PSHELL and MAT1.
    fn into_mesh(self) -> Result<ImportedMesh, ImportError> {
        let Self {
            grids,
            shells,
            pshell,
            mat1,
        } = self;
        let index: HashMap<i64, usize> = grids.iter().enumerate().map(|(i, g)| (g.0, i)).collect();
        let mut elements = Vec::with_capacity(shells.len());
        let mut sections = Vec::with_capacity(shells.len());
        let mut element_ids = Vec::with_capacity(shells.len());
        for (line, eid, pid, nodes) in &shells {
            let mut corners = [0usize; NODES];
            for (k, id) in nodes.iter().enumerate() {
                corners[k] = *index.get(id).ok_or(ImportError::Undefined {
                    line: *line,
                    what: "GRID",
                    id: *id,
                })?;
            }
            if nodes.len() == 3 {
                corners[3] = corners[2];
            }
            let &(mid, t) = pshell.get(pid).ok_or(ImportError::Undefined {
                line: *line,
                what: "PSHELL",
                id: *pid,
            })?;
            let &(young, poisson, density) = mat1.get(&mid).ok_or(ImportError::Undefined {
                line: *line,
                what: "MAT1",
                id: mid,
            })?;
            elements.push(corners);
            element_ids.push(*eid);
            sections.push(Section::single(&Layer {
                young,
                poisson,
                density,
                thickness: t,
            }));
        }
        Ok(ImportedMesh {
            mesh: ShellMesh::new(grids.iter().map(|g| g.1).collect(), elements)?,
            sections,
            node_ids: grids.iter().map(|g| g.0).collect(),
            element_ids,
        })
    }
}

/// Reads a Gmsh 4.x ASCII mesh; every quadrangle (type 3) and triangle
/// (type 2) becomes an element with section `default`.
pub fn gmsh(text: &str, default: Section) -> Result<ImportedMesh, ImportError> {
    let msh = Msh {
        lines: text.lines().collect(),
    };
    if let Some(i) = msh.find("$MeshFormat") {
        let version = msh
            .row(i + 1)
            .first()
            .map_or(0.0, |v| v.parse().unwrap_or(0.0));
        if !(4.0..5.0).contains(&version) || msh.row(i + 1).get(1) != Some(&"0") {
            return Err(ImportError::Unsupported {
                line: i + 2,
                message: "only Gmsh 4.x ASCII meshes are read".into(),
            });
        }
    }
    let (ids, nodes) = msh.nodes()?;
    let index: HashMap<i64, usize> = ids.iter().enumerate().map(|(i, &id)| (id, i)).collect();
    let (elements, element_ids) = msh.elements(&index)?;
    let n = elements.len();
    Ok(ImportedMesh {
        mesh: ShellMesh::new(nodes, elements)?,
        sections: vec![default; n],
        node_ids: ids,
        element_ids,
    })
}

/// The lines of a `.msh` file, with the readers of its sections.
struct Msh<'t> {
    lines: Vec<&'t str>,
}

impl Msh<'_> {
    /// Field `field` of line `line` (0-based) as a number.
    fn number(&self, line: usize, field: usize, t: &str) -> Result<f64, ImportError> {
        t.parse().map_err(|_| ImportError::Number {
            line: line + 1,
            field,
            text: t.to_string(),
        })
    }

    /// The fields of line `i` (none past the end).
    fn row(&self, i: usize) -> Vec<&str> {
        self.lines
            .get(i)
            .map_or(Vec::new(), |l| l.split_whitespace().collect())
    }

    fn find(&self, tag: &str) -> Option<usize> {
        self.lines.iter().position(|l| l.trim() == tag)
    }

    fn short(line: usize) -> ImportError {
        ImportError::Short {
            line: line + 1,
            card: "Gmsh block".into(),
            needed: 4,
        }
    }

    /// A section opens with its tag, then a line whose first field is the
    /// number of entity blocks; the blocks start on the line after it.
    fn section(&self, tag: &str) -> Result<(usize, usize), ImportError> {
        let start = self.find(tag).ok_or(ImportError::Unsupported {
            line: 0,
            message: format!("no {tag} section"),
        })?;
        let head = start + 1;
        let first = self.row(head).first().copied().ok_or(Self::short(head))?;
        let blocks = self.number(head, 0, first)? as usize;
        Ok((blocks, start + 2))
    }

    /// The line after a block of `count` entries of `per` lines each whose
    /// header is on line `at`, if the file holds them all (a count read as
    /// a huge number is refused, never walked).
    fn block_end(&self, at: usize, count: usize, per: usize) -> Result<usize, ImportError> {
        count
            .checked_mul(per)
            .and_then(|n| n.checked_add(at + 1))
            .filter(|&end| end <= self.lines.len())
            .ok_or(ImportError::Truncated {
                line: at + 1,
                count,
            })
    }

    /// The `$Nodes` section: the node ids and positions.
    fn nodes(&self) -> Result<(Vec<i64>, Vec<Vector3<f64>>), ImportError> {
        let (blocks, mut at) = self.section("$Nodes")?;
        let mut ids = Vec::new();
        let mut nodes = Vec::new();
        for _ in 0..blocks {
            let head = self.row(at);
            let count = self.number(at, 3, head.get(3).ok_or(Self::short(at))?)? as usize;
            let end = self.block_end(at, count, 2)?;
            for l in at + 1..at + 1 + count {
                let id = self.row(l).first().copied().ok_or(Self::short(l))?;
                ids.push(self.number(l, 0, id)? as i64);
            }
            for l in at + 1 + count..end {
                let r = self.row(l);
                if r.len() < 3 {
                    return Err(Self::short(l));
                }
                nodes.push(Vector3::new(
                    self.number(l, 0, r[0])?,
                    self.number(l, 1, r[1])?,
                    self.number(l, 2, r[2])?,
                ));
            }
            at = end;
        }
        Ok((ids, nodes))
    }

    /// The `$Elements` section: the corners (node indices, via `index`)
    /// and ids of its quadrangles and triangles; other kinds are skipped.
    fn elements(
        &self,
        index: &HashMap<i64, usize>,
    ) -> Result<(Vec<[usize; NODES]>, Vec<i64>), ImportError> {
        let (blocks, mut at) = self.section("$Elements")?;
        let (mut elements, mut element_ids) = (Vec::new(), Vec::new());
        for _ in 0..blocks {
            let head = self.row(at);
            if head.len() < 4 {
                return Err(Self::short(at));
            }
            let kind = self.number(at, 2, head[2])? as i64;
            let count = self.number(at, 3, head[3])? as usize;
            let end = self.block_end(at, count, 1)?;
            let corners = match kind {
                2 => 3,
                3 => 4,
                // Not a shell element (points, lines, volumes): skipped.
                _ => {
                    at = end;
                    continue;
                }
            };
            for l in at + 1..end {
                let r = self.row(l);
                if r.len() < 1 + corners {
                    return Err(Self::short(l));
                }
                let mut c = [0usize; NODES];
                for j in 0..corners {
                    let id = self.number(l, j + 1, r[j + 1])? as i64;
                    c[j] = *index.get(&id).ok_or(ImportError::Undefined {
                        line: l + 1,
                        what: "node",
                        id,
                    })?;
                }
                if corners == 3 {
                    c[3] = c[2];
                }
                elements.push(c);
                element_ids.push(self.number(l, 0, r[0])? as i64);
            }
            at = end;
        }
        Ok((elements, element_ids))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DECK: &str = "$ a two-element plate
GRID,1,,0.,0.,0.
GRID,2,,1.,0.,0.
GRID,3,,1.,1.,0.
GRID,4,,0.,1.,0.
GRID,5,,2.,0.5,0.
CQUAD4,10,7,1,2,3,4
CTRIA3,11,7,2,5,3
PSHELL,7,3,1.-3
MAT1,3,70.+9,,0.3,2700.
";

    #[test]
    fn a_free_field_deck() {
        let m = nastran(DECK).unwrap();
        assert_eq!(m.mesh.nodes.len(), 5);
        assert_eq!(m.mesh.elements, vec![[0, 1, 2, 3], [1, 4, 2, 2]]);
        assert_eq!(m.element_ids, vec![10, 11]);
        let expected = Section::single(&Layer {
            young: 70e9,
            poisson: 0.3,
            density: 2700.0,
            thickness: 1e-3,
        });
        assert_eq!(m.sections[1], expected);
    }

    #[test]
    fn fixed_field_grid() {
        let deck = "GRID           1       0      0.      0.      0.\n\
                    GRID           2              1.      0.      0.\n\
                    GRID           3              1.      1.      0.\n\
                    CTRIA3         5       1       1       2       3\n\
                    PSHELL         1       1    .001\n\
                    MAT1           1   1.+11            0.3  7800.\n";
        let m = nastran(deck).unwrap();
        assert_eq!(m.mesh.nodes[2], Vector3::new(1.0, 1.0, 0.0));
        assert_eq!(m.sections.len(), 1);
    }

    #[test]
    fn errors_name_the_line() {
        let bad = DECK.replace("GRID,3,,1.,1.,0.", "GRID,3,,1.,one,0.");
        let e = nastran(&bad).unwrap_err().to_string();
        assert!(e.contains("line 4") && e.contains("\"one\""), "{e}");
        let bad = DECK.replace("CQUAD4,10,7,1,2,3,4", "CQUAD4,10,7,1,2,3,9");
        assert!(nastran(&bad).unwrap_err().to_string().contains("GRID 9"));
        let bad = DECK.replace("PSHELL,7", "PSHELL,8");
        assert!(nastran(&bad).unwrap_err().to_string().contains("PSHELL 7"));
    }

    #[test]
    fn a_gmsh_v4_mesh() {
        let msh = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 3 4\n$EndElements\n";
        let m = gmsh(msh, Section::single(&Layer::MYLAR)).unwrap();
        assert_eq!(m.mesh.elements, vec![[0, 1, 2, 3]]);
        let bad = msh.replace("1 1 2 3 4", "1 1 2 3 8");
        assert!(gmsh(&bad, Section::single(&Layer::MYLAR))
            .unwrap_err()
            .to_string()
            .contains("node 8"));
    }
}
