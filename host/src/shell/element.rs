//! The flat four-node shell element: a membrane with incompatible modes,
//! an MITC4 plate and a small drilling stiffness, in the element's own
//! plane, rotated to global axes. Six degrees of freedom a node,
//! `[u, v, w, theta_x, theta_y, theta_z]` (m, rad).
//!
//! - Membrane: bilinear Q4 enriched with the two incompatible modes
//!   `1 - xi^2`, `1 - eta^2` in each direction, their derivatives taken with
//!   the centre Jacobian so the patch test passes (Taylor, Beresford &
//!   Wilson 1976, "QM6"), condensed out: no locking in in-plane bending.
//! - Plate: Reissner–Mindlin Q4 with the MITC4 assumed transverse shear
//!   strains, tied at the edge midpoints (Bathe & Dvorkin 1985, Int. J.
//!   Numer. Meth. Engng 21): no shear locking for thin plates. Rotations
//!   `beta_x = theta_y`, `beta_y = -theta_x` (`u = z beta_x`).
//! - Drilling: a penalty `1e-3 A_66 * area` on `theta_z`, which the flat
//!   element does not otherwise resist.
//! - Mass: lumped, a quarter of the element's mass and rotary inertia at
//!   each node.
//!
//! Warped quads are projected on their mean plane (a flat facet).

use nalgebra::{Matrix2, Matrix3, SMatrix, SVector, Vector3};

use super::material::Section;

/// Corner nodes of an element.
pub const NODES: usize = 4;
/// Degrees of freedom of a node, `[u, v, w, theta_x, theta_y, theta_z]`;
/// node `i`'s global DOFs are `NODE_DOFS * i + d`.
pub const NODE_DOFS: usize = 6;
/// Degrees of freedom of an element (24): corner `i`'s DOF `d` is local
/// DOF `NODE_DOFS * i + d`.
pub const DOFS: usize = NODES * NODE_DOFS;
/// Entries of an element matrix (24 x 24 = 576), column-major: entry
/// `(a, b)` is number `DOFS * b + a`.
pub const MATRIX_ENTRIES: usize = DOFS * DOFS;

/// The 3 x 3 blocks along an element matrix's side: a corner's
/// translations, then its rotations, corner after corner.
const BLOCKS: usize = DOFS / 3;

/// [`DOFS`] x [`DOFS`] element matrix.
pub type ElementMatrix = SMatrix<f64, DOFS, DOFS>;
/// [`DOFS`]-vector of element DOFs.
pub type ElementVector = SVector<f64, DOFS>;

const GAUSS: [f64; 2] = [-0.577_350_269_189_625_8, 0.577_350_269_189_625_8];
const CORNERS: [(f64, f64); NODES] = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];

/// The element's plane: rotation rows `e1, e2, e3` (global -> local) and
/// the corners' in-plane coordinates (m).
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    /// Rows are the local axes in global coordinates.
    pub rotation: Matrix3<f64>,
    /// In-plane corner coordinates.
    pub corners: [(f64, f64); NODES],
    /// Element area, m^2.
    pub area: f64,
}

impl Frame {
    /// The mean plane of four corners (counter-clockwise seen from +e3).
    pub fn new(x: &[Vector3<f64>; NODES]) -> Self {
        let d1 = x[2] - x[0];
        let d2 = x[3] - x[1];
        let e3 = d1.cross(&d2).normalize();
        let along = (x[1] - x[0]) + (x[2] - x[3]);
        let e1 = (along - e3 * along.dot(&e3)).normalize();
        let e2 = e3.cross(&e1);
        let centre = (x[0] + x[1] + x[2] + x[3]) / 4.0;
        let corners = x.map(|p| {
            let r = p - centre;
            (r.dot(&e1), r.dot(&e2))
        });
        let area = 0.5 * d1.cross(&d2).norm();
        Self {
            rotation: Matrix3::from_rows(&[e1.transpose(), e2.transpose(), e3.transpose()]),
            corners,
            area,
        }
    }

    /// Shape function values and natural derivatives at `(xi, eta)`.
    fn shape(xi: f64, eta: f64) -> ([f64; NODES], [f64; NODES], [f64; NODES]) {
        let mut n = [0.0; 4];
        let mut dxi = [0.0; 4];
        let mut deta = [0.0; 4];
        for (i, &(a, b)) in CORNERS.iter().enumerate() {
            n[i] = 0.25 * (1.0 + a * xi) * (1.0 + b * eta);
            dxi[i] = 0.25 * a * (1.0 + b * eta);
            deta[i] = 0.25 * b * (1.0 + a * xi);
        }
        (n, dxi, deta)
    }

    /// `J = [[x_xi, y_xi], [x_eta, y_eta]]`.
    fn jacobian(&self, dxi: &[f64; NODES], deta: &[f64; NODES]) -> Matrix2<f64> {
        let mut j = Matrix2::zeros();
        for i in 0..NODES {
            let (x, y) = self.corners[i];
            j[(0, 0)] += dxi[i] * x;
            j[(0, 1)] += dxi[i] * y;
            j[(1, 0)] += deta[i] * x;
            j[(1, 1)] += deta[i] * y;
        }
        j
    }

    /// At `(xi, eta)`: `det J`, `J^-1` and the Cartesian derivatives
    /// `(N_i,x, N_i,y)` of the four shape functions; `None` where `J` is
    /// singular (a degenerate point, skipped by the quadratures).
    fn cartesian_derivatives(
        &self,
        xi: f64,
        eta: f64,
    ) -> Option<(f64, Matrix2<f64>, [nalgebra::Vector2<f64>; NODES])> {
        let (_, dxi, deta) = Self::shape(xi, eta);
        let j = self.jacobian(&dxi, &deta);
        let j_inv = j.try_inverse()?;
        let d = std::array::from_fn(|i| j_inv * nalgebra::Vector2::new(dxi[i], deta[i]));
        Some((j.determinant(), j_inv, d))
    }

    /// 24 x 24 rotation of the element DOFs, global -> local.
    pub fn transformation(&self) -> ElementMatrix {
        let mut t = ElementMatrix::zeros();
        for block in 0..BLOCKS {
            t.fixed_view_mut::<3, 3>(3 * block, 3 * block)
                .copy_from(&self.rotation);
        }
        t
    }
}

/// Index of local DOF `d` (0..6) of corner `i`.
const fn dof(i: usize, d: usize) -> usize {
    NODE_DOFS * i + d
}

fn mat3(a: &[[f64; 3]; 3]) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| a[i][j])
}

/// Local stiffness: membrane, plate and drilling (in the element's frame:
/// DOFs `[u, v, w, theta_x, theta_y, theta_z]` along its axes).
pub fn local_stiffness_matrix(frame: &Frame, section: &Section) -> ElementMatrix {
    local_stiffness(frame, section)
}

fn local_stiffness(frame: &Frame, section: &Section) -> ElementMatrix {
    let mut k = ElementMatrix::zeros();
    membrane(frame, &mat3(&section.membrane), &mut k);
    plate(frame, section, &mut k);
    let drilling = 1e-3 * section.membrane[2][2] * frame.area;
    for i in 0..NODES {
        k[(dof(i, 5), dof(i, 5))] += drilling;
    }
    k
}

/// QM6 membrane, condensed, into the `u, v` rows of `k`.
fn membrane(frame: &Frame, a: &Matrix3<f64>, k: &mut ElementMatrix) {
    let (_, dxi0, deta0) = Frame::shape(0.0, 0.0);
    let j0 = frame.jacobian(&dxi0, &deta0);
    let (det0, j0_inv) = (
        j0.determinant(),
        j0.try_inverse().unwrap_or_else(Matrix2::zeros),
    );
    let mut kcc = SMatrix::<f64, 8, 8>::zeros();
    let mut kci = SMatrix::<f64, 8, 4>::zeros();
    let mut kii = SMatrix::<f64, 4, 4>::zeros();
    for &xi in &GAUSS {
        for &eta in &GAUSS {
            let Some((det, _, derivatives)) = frame.cartesian_derivatives(xi, eta) else {
                continue;
            };
            let mut bc = SMatrix::<f64, 3, 8>::zeros();
            for (i, d) in derivatives.iter().enumerate() {
                bc[(0, 2 * i)] = d.x;
                bc[(1, 2 * i + 1)] = d.y;
                bc[(2, 2 * i)] = d.y;
                bc[(2, 2 * i + 1)] = d.x;
            }
            let mut bi = SMatrix::<f64, 3, 4>::zeros();
            let modes = [(-2.0 * xi, 0.0), (0.0, -2.0 * eta)];
            for (m, &(pxi, peta)) in modes.iter().enumerate() {
                let d = (det0 / det) * (j0_inv * nalgebra::Vector2::new(pxi, peta));
                bi[(0, 2 * m)] = d.x;
                bi[(1, 2 * m + 1)] = d.y;
                bi[(2, 2 * m)] = d.y;
                bi[(2, 2 * m + 1)] = d.x;
            }
            kcc += bc.transpose() * a * bc * det;
            kci += bc.transpose() * a * bi * det;
            kii += bi.transpose() * a * bi * det;
        }
    }
    let condensed = match kii.try_inverse() {
        Some(inv) => kcc - kci * inv * kci.transpose(),
        None => kcc,
    };
    for i in 0..NODES {
        for j in 0..NODES {
            for (a, da) in [(0, 0), (1, 1)] {
                for (b, db) in [(0, 0), (1, 1)] {
                    k[(dof(i, da), dof(j, db))] += condensed[(2 * i + a, 2 * j + b)];
                }
            }
        }
    }
}

/// Covariant transverse shear strains `(gamma_xi, gamma_eta)` at `(xi,
/// eta)` as rows over the plate DOFs `[w, theta_x, theta_y]` of each corner.
fn covariant_shear(frame: &Frame, xi: f64, eta: f64) -> SMatrix<f64, 2, 12> {
    let (n, dxi, deta) = Frame::shape(xi, eta);
    let j = frame.jacobian(&dxi, &deta);
    let mut g = SMatrix::<f64, 2, 12>::zeros();
    for i in 0..NODES {
        for (row, dn) in [(0, dxi[i]), (1, deta[i])] {
            let (x_s, y_s) = (j[(row, 0)], j[(row, 1)]);
            g[(row, 3 * i)] = dn;
            // beta_x x_s + beta_y y_s with beta_x = theta_y, beta_y = -theta_x.
            g[(row, 3 * i + 1)] = -n[i] * y_s;
            g[(row, 3 * i + 2)] = n[i] * x_s;
        }
    }
    g
}

/// MITC4 plate into the `w, theta_x, theta_y` rows of `k`.
fn plate(frame: &Frame, section: &Section, k: &mut ElementMatrix) {
    let d = mat3(&section.bending);
    // Tying points: gamma_xi at A (0, 1), C (0, -1); gamma_eta at B (1, 0), D (-1, 0).
    let (ga, gc) = (
        covariant_shear(frame, 0.0, 1.0),
        covariant_shear(frame, 0.0, -1.0),
    );
    let (gb, gd) = (
        covariant_shear(frame, 1.0, 0.0),
        covariant_shear(frame, -1.0, 0.0),
    );
    let mut kp = SMatrix::<f64, 12, 12>::zeros();
    for &xi in &GAUSS {
        for &eta in &GAUSS {
            let Some((det, j_inv, derivatives)) = frame.cartesian_derivatives(xi, eta) else {
                continue;
            };
            let mut bb = SMatrix::<f64, 3, 12>::zeros();
            for (i, dn) in derivatives.iter().enumerate() {
                // kappa_x = beta_x,x; kappa_y = beta_y,y; kappa_xy = beta_x,y + beta_y,x.
                bb[(0, 3 * i + 2)] = dn.x;
                bb[(1, 3 * i + 1)] = -dn.y;
                bb[(2, 3 * i + 2)] = dn.y;
                bb[(2, 3 * i + 1)] = -dn.x;
            }
            let mut tied = SMatrix::<f64, 2, 12>::zeros();
            tied.set_row(
                0,
                &(ga.row(0) * (0.5 * (1.0 + eta)) + gc.row(0) * (0.5 * (1.0 - eta))),
            );
            tied.set_row(
                1,
                &(gb.row(1) * (0.5 * (1.0 + xi)) + gd.row(1) * (0.5 * (1.0 - xi))),
            );
            // Covariant -> Cartesian: [g_xi, g_eta] = J [g_x, g_y].
            let bs = j_inv * tied;
            kp += (bb.transpose() * d * bb + bs.transpose() * bs * section.shear) * det;
        }
    }
    for i in 0..NODES {
        for j in 0..NODES {
            for a in 0..3 {
                for b in 0..3 {
                    k[(dof(i, 2 + a), dof(j, 2 + b))] += kp[(3 * i + a, 3 * j + b)];
                }
            }
        }
    }
}

/// The element's global stiffness matrix (N/m, N, N m blocks): `T^T K T`
/// with `T` block-diagonal, done 3 x 3 block by block (64 small products
/// instead of two dense 24 x 24 ones).
pub fn stiffness(x: &[Vector3<f64>; NODES], section: &Section) -> ElementMatrix {
    let frame = Frame::new(x);
    let local = local_stiffness(&frame, section);
    let r = frame.rotation;
    let rt = r.transpose();
    let mut k = ElementMatrix::zeros();
    for bi in 0..BLOCKS {
        for bj in 0..BLOCKS {
            let block: Matrix3<f64> = local.fixed_view::<3, 3>(3 * bi, 3 * bj).into_owned();
            k.fixed_view_mut::<3, 3>(3 * bi, 3 * bj)
                .copy_from(&(rt * block * r));
        }
    }
    k
}

/// The element's lumped mass: a quarter of its mass on each corner's
/// translations and of its rotary inertia on each corner's rotations (kg,
/// kg m^2; diagonal, the same in any axes).
pub fn lumped_mass(x: &[Vector3<f64>; NODES], section: &Section) -> ElementVector {
    let area = Frame::new(x).area;
    let mut m = ElementVector::zeros();
    for i in 0..NODES {
        for d in 0..3 {
            m[dof(i, d)] = 0.25 * section.mass * area;
            m[dof(i, 3 + d)] = 0.25 * section.rotary * area;
        }
    }
    m
}

/// Consistent nodal forces of a uniform pressure `p` (Pa, along the
/// element normal `e3`), in global axes (N).
pub fn pressure_load(x: &[Vector3<f64>; NODES], p: f64) -> ElementVector {
    let frame = Frame::new(x);
    let normal = frame.rotation.row(2).transpose();
    let mut f = ElementVector::zeros();
    for &xi in &GAUSS {
        for &eta in &GAUSS {
            let (n, dxi, deta) = Frame::shape(xi, eta);
            let det = frame.jacobian(&dxi, &deta).determinant();
            for i in 0..NODES {
                for d in 0..3 {
                    f[dof(i, d)] += n[i] * p * det * normal[d];
                }
            }
        }
    }
    f
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shell::material::Layer;

    fn skewed() -> [Vector3<f64>; 4] {
        [
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(1.2, 0.1, 0.0),
            Vector3::new(1.1, 0.9, 0.0),
            Vector3::new(-0.1, 1.0, 0.0),
        ]
    }

    /// Six rigid-body motions of a (rotated, skewed) element store no
    /// energy, and the stiffness is symmetric with 6 zero eigenvalues
    /// (only the drilling penalty resists the in-plane rotation, slightly).
    #[test]
    fn rigid_body_modes_are_free() {
        let r = nalgebra::Rotation3::from_euler_angles(0.3, -0.5, 1.1);
        let x = skewed().map(|p| r * p);
        let k = stiffness(&x, &Section::single(&Layer::CARBON));
        assert!((k - k.transpose()).norm() < 1e-9 * k.norm());
        let scale = k.norm();
        for mode in 0..5 {
            let mut u = ElementVector::zeros();
            for (i, p) in x.iter().enumerate() {
                let (t, w) = match mode {
                    0..=2 => (Vector3::ith(mode, 1.0), Vector3::zeros()),
                    // Rotations about the element's in-plane axes (about
                    // its normal only the drilling penalty resists).
                    _ => (Vector3::zeros(), r * Vector3::ith(mode - 3, 1.0)),
                };
                let disp = t + w.cross(p);
                for d in 0..3 {
                    u[dof(i, d)] = disp[d];
                    u[dof(i, 3 + d)] = w[d];
                }
            }
            let energy = (u.transpose() * k * u)[0];
            assert!(energy.abs() < 1e-9 * scale, "mode {mode}: {energy}");
        }
    }

    /// Pressure loads sum to p times the area along the normal.
    #[test]
    fn pressure_resultant() {
        let f = pressure_load(&skewed(), 2.0);
        let fz: f64 = (0..4).map(|i| f[dof(i, 2)]).sum();
        assert!((fz - 2.0 * Frame::new(&skewed()).area).abs() < 1e-12);
    }
}
