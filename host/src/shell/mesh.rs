//! Quadrilateral shell meshes: nodes in 3D and four-node elements
//! (counter-clockwise seen from the side the element normal points to).

use nalgebra::Vector3;

use super::element::{NODES, NODE_DOFS};

/// Why a mesh is refused.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum MeshError {
    /// An element refers to a node that does not exist.
    #[error("element {element} refers to node {node}, but the mesh has {nodes} nodes")]
    NodeIndex {
        /// Element index.
        element: usize,
        /// The bad node index.
        node: usize,
        /// Number of nodes.
        nodes: usize,
    },
    /// A node coordinate is not finite.
    #[error("node {0} has a coordinate that is not finite")]
    NotFinite(usize),
    /// An element has (nearly) zero area or repeats a node.
    #[error("element {0} is degenerate (repeated node or zero area)")]
    Degenerate(usize),
    /// A generator parameter is out of range.
    #[error("{0}")]
    Parameter(String),
}

/// A shell mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct ShellMesh {
    /// Node positions, m.
    pub nodes: Vec<Vector3<f64>>,
    /// Corner node indices of each element.
    pub elements: Vec<[usize; NODES]>,
}

impl ShellMesh {
    /// A mesh after checking indices, finiteness and element areas.
    pub fn new(nodes: Vec<Vector3<f64>>, elements: Vec<[usize; NODES]>) -> Result<Self, MeshError> {
        if let Some(i) = nodes.iter().position(|p| !p.iter().all(|v| v.is_finite())) {
            return Err(MeshError::NotFinite(i));
        }
        for (e, corners) in elements.iter().enumerate() {
            if let Some(&node) = corners.iter().find(|&&n| n >= nodes.len()) {
                return Err(MeshError::NodeIndex {
                    element: e,
                    node,
                    nodes: nodes.len(),
                });
            }
            let x = corners.map(|n| nodes[n]);
            let diagonal = (x[2] - x[0]).cross(&(x[3] - x[1])).norm();
            let size = (x[2] - x[0]).norm().max((x[3] - x[1]).norm());
            if diagonal <= 1e-12 * size * size || size == 0.0 {
                return Err(MeshError::Degenerate(e));
            }
        }
        Ok(Self { nodes, elements })
    }

    /// Corner positions of element `e`.
    pub fn corners(&self, e: usize) -> [Vector3<f64>; NODES] {
        self.elements[e].map(|n| self.nodes[n])
    }

    /// Area of element `e`, m²: half the cross product of its diagonals
    /// (exact for a flat quadrilateral, the mean projection for a warped
    /// one).
    pub fn element_area(&self, e: usize) -> f64 {
        let x = self.corners(e);
        0.5 * (x[2] - x[0]).cross(&(x[3] - x[1])).norm()
    }

    /// Number of degrees of freedom (six a node).
    pub fn dofs(&self) -> usize {
        NODE_DOFS * self.nodes.len()
    }

    /// A structured mesh of the parametric square `[0, 1]^2` mapped by
    /// `place(s, t)`, with `ns x nt` elements; node `(i, j)` (i along s) is
    /// `j * (ns + 1) + i`.
    pub fn mapped(
        ns: usize,
        nt: usize,
        place: impl Fn(f64, f64) -> Vector3<f64>,
    ) -> Result<Self, MeshError> {
        if ns == 0 || nt == 0 {
            return Err(MeshError::Parameter(format!(
                "a mapped mesh needs at least one element each way (got {ns} x {nt})"
            )));
        }
        let nodes = (0..=nt)
            .flat_map(|j| (0..=ns).map(move |i| (i, j)))
            .map(|(i, j)| place(i as f64 / ns as f64, j as f64 / nt as f64))
            .collect();
        let id = |i: usize, j: usize| j * (ns + 1) + i;
        let elements = (0..nt)
            .flat_map(|j| (0..ns).map(move |i| (i, j)))
            .map(|(i, j)| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
            .collect();
        Self::new(nodes, elements)
    }

    /// A flat rectangle `[0, lx] x [0, ly]` in the xy-plane, `nx x ny`
    /// elements.
    pub fn rectangle(lx: f64, ly: f64, nx: usize, ny: usize) -> Result<Self, MeshError> {
        Self::mapped(nx, ny, |s, t| Vector3::new(s * lx, t * ly, 0.0))
    }

    /// Nodes satisfying `select`.
    pub fn nodes_where(&self, select: impl Fn(&Vector3<f64>) -> bool) -> Vec<usize> {
        (0..self.nodes.len())
            .filter(|&n| select(&self.nodes[n]))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_meshes_are_refused() {
        let p = |x: f64, y: f64| Vector3::new(x, y, 0.0);
        let nodes = vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
        assert!(ShellMesh::new(nodes.clone(), vec![[0, 1, 2, 3]]).is_ok());
        assert_eq!(
            ShellMesh::new(nodes.clone(), vec![[0, 1, 2, 7]]),
            Err(MeshError::NodeIndex {
                element: 0,
                node: 7,
                nodes: 4
            })
        );
        assert_eq!(
            ShellMesh::new(nodes.clone(), vec![[0, 1, 1, 0]]),
            Err(MeshError::Degenerate(0))
        );
        let mut bad = nodes;
        bad[2].x = f64::NAN;
        assert_eq!(ShellMesh::new(bad, vec![]), Err(MeshError::NotFinite(2)));
        let m = ShellMesh::rectangle(2.0, 1.0, 4, 2).unwrap();
        assert_eq!((m.nodes.len(), m.elements.len()), (15, 8));
    }
}
