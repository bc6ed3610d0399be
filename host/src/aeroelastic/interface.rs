//! The fluid–structure interface: the aerodynamic lattice placed on the
//! shell mesh of the wing planform.
//!
//! Both meshes are structured over the planform's parametric square (`s`
//! chordwise, `t` spanwise, see [`crate::shell::wing::Planform::mesh`]).
//! A lattice point at `(s, t)` moves with the bilinear interpolation `H` of
//! the four shell nodes of the element that holds it (consistent
//! displacement transfer). Loads go back two ways: the panels' pressure
//! jumps become element pressures, scaled so that each panel's force is
//! carried exactly, and enter the shell as consistent (distributed) nodal
//! loads; in-plane point forces (the leading-edge suction) go to the four
//! nodes around their point with the same bilinear weights, `f = H^T F`,
//! which keeps their total and their virtual work on the interpolated
//! displacements exactly (Farhat, Lesoinne & Le Tallec 1998, CMAME 157).
//! Point forces at the panel centres would be conservative too, but they
//! dimple the fine shell mesh locally. The lattice has its own resolution,
//! independent of the element counts.

use nalgebra::Vector3;

use crate::shell::mesh::ShellMesh;
use crate::shell::wing::Planform;

/// Four nodes and their bilinear weights.
type Stencil = [(usize, f64); 4];

/// Why the interface could not be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum InterfaceError {
    /// The shell mesh is not the planform's structured mesh.
    #[error("the shell mesh has {nodes} nodes; the planform's {chord} x {span} element grid needs {expected}")]
    NotThePlanformMesh {
        /// Nodes in the mesh.
        nodes: usize,
        /// Chordwise elements.
        chord: usize,
        /// Spanwise elements.
        span: usize,
        /// Nodes the grid needs.
        expected: usize,
    },
    /// A lattice without panels.
    #[error("the aerodynamic lattice needs at least one panel each way (got {0} x {1})")]
    EmptyLattice(usize, usize),
}

/// The lattice on the shell mesh.
#[derive(Clone, Debug)]
pub struct SurfaceMap {
    /// Chordwise lattice panels.
    pub chordwise: usize,
    /// Spanwise lattice panels.
    pub spanwise: usize,
    corners: Vec<Stencil>,
    centres: Vec<Stencil>,
    leading_edge: Vec<Stencil>,
    element_panel: Vec<usize>,
    /// Panel area over the area of the elements it hands its pressure to.
    pressure_scale: Vec<f64>,
    body_corners: Vec<Vector3<f64>>,
    nodes: usize,
}

impl SurfaceMap {
    /// Places a `chordwise x spanwise` lattice on `mesh`, the structured
    /// mesh of `planform`.
    pub fn new(
        planform: &Planform,
        mesh: &ShellMesh,
        chordwise: usize,
        spanwise: usize,
    ) -> Result<Self, InterfaceError> {
        if chordwise == 0 || spanwise == 0 {
            return Err(InterfaceError::EmptyLattice(chordwise, spanwise));
        }
        let (nc, nt) = (planform.chord_elements, planform.span_elements);
        let expected = (nc + 1) * (nt + 1);
        if mesh.nodes.len() != expected || mesh.elements.len() != nc * nt {
            return Err(InterfaceError::NotThePlanformMesh {
                nodes: mesh.nodes.len(),
                chord: nc,
                span: nt,
                expected,
            });
        }
        let stencil = |s: f64, t: f64| -> Stencil {
            let (fs, ft) = (s * nc as f64, t * nt as f64);
            let i = (fs.floor() as usize).min(nc - 1);
            let j = (ft.floor() as usize).min(nt - 1);
            let (a, b) = (fs - i as f64, ft - j as f64);
            let id = |i: usize, j: usize| j * (nc + 1) + i;
            [
                (id(i, j), (1.0 - a) * (1.0 - b)),
                (id(i + 1, j), a * (1.0 - b)),
                (id(i + 1, j + 1), a * b),
                (id(i, j + 1), (1.0 - a) * b),
            ]
        };
        let corners: Vec<Stencil> = (0..=chordwise)
            .flat_map(|i| (0..=spanwise).map(move |j| (i, j)))
            .map(|(i, j)| stencil(i as f64 / chordwise as f64, j as f64 / spanwise as f64))
            .collect();
        let centres = (0..chordwise)
            .flat_map(|i| (0..spanwise).map(move |j| (i, j)))
            .map(|(i, j)| {
                stencil(
                    (i as f64 + 0.5) / chordwise as f64,
                    (j as f64 + 0.5) / spanwise as f64,
                )
            })
            .collect();
        let leading_edge = (0..spanwise)
            .map(|j| stencil(0.0, (j as f64 + 0.5) / spanwise as f64))
            .collect();
        // Element (i, j) of the shell grid is element j * nc + i.
        let element_panel: Vec<usize> = (0..nt)
            .flat_map(|j| (0..nc).map(move |i| (i, j)))
            .map(|(i, j)| {
                let pi = ((i as f64 + 0.5) / nc as f64 * chordwise as f64) as usize;
                let pj = ((j as f64 + 0.5) / nt as f64 * spanwise as f64) as usize;
                pi.min(chordwise - 1) * spanwise + pj.min(spanwise - 1)
            })
            .collect();
        let body_corners: Vec<Vector3<f64>> = corners
            .iter()
            .map(|st| st.iter().map(|&(n, w)| mesh.nodes[n] * w).sum())
            .collect();
        // Elements take their panel's pressure; where the two grids do not
        // line up a panel covers a little more or less than its elements,
        // so the pressure is scaled to keep each panel's force exactly.
        let quad_area = |x: [Vector3<f64>; 4]| 0.5 * (x[2] - x[0]).cross(&(x[3] - x[1])).norm();
        let mut assigned = vec![0.0; chordwise * spanwise];
        for (e, &p) in element_panel.iter().enumerate() {
            assigned[p] += quad_area(mesh.corners(e));
        }
        let corner = |i: usize, j: usize| body_corners[i * (spanwise + 1) + j];
        let pressure_scale = (0..chordwise * spanwise)
            .map(|p| {
                let (i, j) = (p / spanwise, p % spanwise);
                let area = quad_area([
                    corner(i, j),
                    corner(i + 1, j),
                    corner(i + 1, j + 1),
                    corner(i, j + 1),
                ]);
                if assigned[p] > 0.0 {
                    area / assigned[p]
                } else {
                    0.0
                }
            })
            .collect();
        Ok(Self {
            chordwise,
            spanwise,
            corners,
            centres,
            leading_edge,
            element_panel,
            pressure_scale,
            body_corners,
            nodes: mesh.nodes.len(),
        })
    }

    /// The undeformed lattice corners in body axes, m (index `i *
    /// (spanwise + 1) + j`, `i` from the leading edge).
    pub fn body_corners(&self) -> &[Vector3<f64>] {
        &self.body_corners
    }

    /// A nodal vector field (displacement, velocity) interpolated to the
    /// lattice corners.
    pub fn interpolate(&self, nodal: &[Vector3<f64>]) -> Vec<Vector3<f64>> {
        self.corners
            .iter()
            .map(|st| st.iter().map(|&(n, w)| nodal[n] * w).sum())
            .collect()
    }

    /// Panel forces (body axes, N, panel index `i * spanwise + j`) and the
    /// leading-edge suction of each spanwise strip (body axes, N) as nodal
    /// forces on the shell (global 6-DOF vector): `H^T F` at the panel
    /// centres and at the middle of each strip's leading edge.
    pub fn nodal_forces(
        &self,
        panel_forces: &[Vector3<f64>],
        suction: &[Vector3<f64>],
    ) -> Vec<f64> {
        let mut f = vec![0.0; 6 * self.nodes];
        let applied = self
            .centres
            .iter()
            .zip(panel_forces)
            .chain(self.leading_edge.iter().zip(suction));
        for (st, force) in applied {
            for &(n, w) in st {
                for c in 0..3 {
                    f[6 * n + c] += w * force[c];
                }
            }
        }
        f
    }

    /// A panel field (e.g. the pressure jump, Pa) on the shell elements:
    /// each element takes the value of the panel holding its centre.
    pub fn element_values(&self, panel_values: &[f64]) -> Vec<f64> {
        self.element_panel
            .iter()
            .map(|&p| panel_values[p])
            .collect()
    }

    /// The panels' pressure jumps (Pa) as element pressures that carry
    /// each panel's normal force exactly on the undeformed wing: the panel
    /// value scaled by the panel's area over its elements' area.
    pub fn element_pressures(&self, panel_pressure: &[f64]) -> Vec<f64> {
        self.element_panel
            .iter()
            .map(|&p| panel_pressure[p] * self.pressure_scale[p])
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn small() -> (Planform, ShellMesh) {
        let p = Planform {
            span_elements: 10,
            chord_elements: 6,
            ..Planform::FWAV
        };
        let m = p.mesh().unwrap().mesh;
        (p, m)
    }

    #[test]
    fn lattice_lies_on_the_planform_and_transfer_is_conservative() {
        let (p, mesh) = small();
        let map = SurfaceMap::new(&p, &mesh, 4, 7).unwrap();
        // Corners on the planform: trailing edge at the local chord.
        for j in 0..=7 {
            let te = map.body_corners()[4 * 8 + j];
            assert!((te.x - p.chord(te.y)).abs() < 1e-12);
        }
        // Work of panel forces on interpolated displacements equals the work
        // of nodal forces on nodal displacements, and the total is kept.
        let u: Vec<Vector3<f64>> = mesh
            .nodes
            .iter()
            .map(|x| Vector3::new(x.y * x.x, 0.3 * x.y, x.x * x.x + x.y))
            .collect();
        let forces: Vec<Vector3<f64>> = (0..28)
            .map(|k| Vector3::new(k as f64, 1.0, (k * k) as f64 * 0.1))
            .collect();
        let f = map.nodal_forces(&forces, &[]);
        let total: Vector3<f64> = forces.iter().sum();
        let nodal_total = (0..mesh.nodes.len())
            .map(|n| Vector3::new(f[6 * n], f[6 * n + 1], f[6 * n + 2]))
            .sum::<Vector3<f64>>();
        assert!((total - nodal_total).norm() < 1e-12 * total.norm());
        let nodal_work: f64 = (0..mesh.nodes.len())
            .map(|n| Vector3::new(f[6 * n], f[6 * n + 1], f[6 * n + 2]).dot(&u[n]))
            .sum();
        let centre_u: Vec<Vector3<f64>> = map
            .centres
            .iter()
            .map(|st| st.iter().map(|&(n, w)| u[n] * w).sum())
            .collect();
        let panel_work: f64 = forces.iter().zip(&centre_u).map(|(f, u)| f.dot(u)).sum();
        assert!((nodal_work - panel_work).abs() < 1e-12 * panel_work.abs());
        assert_eq!(map.element_values(&vec![2.0; 28]).len(), 60);
        // Element pressures keep every panel's force (5 x 7 panels on a
        // 6 x 10 grid: the grids do not line up).
        let odd = SurfaceMap::new(&p, &mesh, 5, 7).unwrap();
        let dp: Vec<f64> = (0..35).map(|k| 1.0 + k as f64).collect();
        let on_elements = odd.element_pressures(&dp);
        let area = |x: [Vector3<f64>; 4]| 0.5 * (x[2] - x[0]).cross(&(x[3] - x[1])).norm();
        let element_force: f64 = (0..60)
            .map(|e| on_elements[e] * area(mesh.corners(e)))
            .sum();
        let c = |i: usize, j: usize| odd.body_corners()[i * 8 + j];
        let panel_force: f64 = (0..35)
            .map(|k| {
                let (i, j) = (k / 7, k % 7);
                dp[k] * area([c(i, j), c(i + 1, j), c(i + 1, j + 1), c(i, j + 1)])
            })
            .sum();
        assert!((element_force / panel_force - 1.0).abs() < 1e-12);
    }

    #[test]
    fn refuses_a_foreign_mesh() {
        let (p, _) = small();
        let other = ShellMesh::rectangle(1.0, 1.0, 3, 3).unwrap();
        assert!(matches!(
            SurfaceMap::new(&p, &other, 4, 4),
            Err(InterfaceError::NotThePlanformMesh { .. })
        ));
    }
}
