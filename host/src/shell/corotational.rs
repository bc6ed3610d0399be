//! Geometrically nonlinear shells by the element-independent co-rotational
//! formulation (Rankin & Nour-Omid 1988; Felippa & Haugen 2005, Comput.
//! Methods Appl. Mech. Engrg. 194): each element's rigid motion is taken
//! out by a frame that follows it, and what is left, small, goes through
//! the linear element. Large displacements and rotations, small strains.
//!
//! Per element, with `E` the current frame (columns), `c` the centroid and
//! `R_i` the nodal rotations:
//! - deformational translations `u_i = E^T (x_i - c) - E0^T (X_i - c0)`;
//! - deformational rotations `theta_i = log(E^T R_i E0)`;
//! - strain energy `W = 1/2 d^T K d` with the linear element's local `K`.
//!
//! Variations are taken with respect to nodal translations and spins
//! (`delta R = Spin(delta omega) R`):
//! `delta u_i = E^T (delta x_i - delta c + Spin(x_i - c) delta omega_E)`
//! and `delta theta_i = T(theta_i)^-1 E^T (delta omega_i - delta omega_E)`
//! with `T` the tangent map of SO(3) and
//! `delta omega_E = G delta x` the frame's spin (`G` in closed form from the
//! frame's definition). The internal force is the exact gradient
//! `f = J^T K d`; the tangent is `J^T K J` plus the stress-dependent part
//! `d(J^T)/dq (K d)`, the latter by forward differences of the closed-form
//! `J` (24 evaluations an element), symmetrized.

use nalgebra::{Matrix3, Rotation3, SMatrix, Vector3};
use rayon::prelude::*;

use super::assembly::{check_sections, AssemblyError};
use super::element::{
    local_stiffness_matrix, ElementMatrix, ElementVector, Frame, DOFS, NODES, NODE_DOFS,
};
use super::material::Section;
use super::mesh::ShellMesh;

/// Nodal configuration: translations from the initial positions and
/// rotations from the initial orientation.
#[derive(Clone, Debug, PartialEq)]
pub struct Configuration {
    /// Translations, m.
    pub displacement: Vec<Vector3<f64>>,
    /// Rotations.
    pub rotation: Vec<Rotation3<f64>>,
}

impl Configuration {
    /// The undeformed configuration of `nodes` nodes.
    pub fn initial(nodes: usize) -> Self {
        Self {
            displacement: vec![Vector3::zeros(); nodes],
            rotation: vec![Rotation3::identity(); nodes],
        }
    }

    /// Moves on by the motion from `before` to `self` once more:
    /// translations linearly, rotations by the same relative rotation.
    pub fn extrapolate(&mut self, before: &Configuration) {
        for n in 0..self.displacement.len() {
            let step = self.displacement[n] - before.displacement[n];
            self.displacement[n] += step;
            let relative = self.rotation[n] * before.rotation[n].inverse();
            self.rotation[n] = relative * self.rotation[n];
        }
    }

    /// Applies an increment over the global DOFs `[dx, dy, dz, dwx, dwy,
    /// dwz]` a node (spins compose on the left).
    pub fn update(&mut self, increment: &[f64]) {
        for (n, d) in increment.chunks_exact(NODE_DOFS).enumerate() {
            self.displacement[n] += Vector3::new(d[0], d[1], d[2]);
            let r = Rotation3::from_scaled_axis(Vector3::new(d[3], d[4], d[5])) * self.rotation[n];
            // Back onto SO(3): products of many increments drift off it.
            self.rotation[n] =
                nalgebra::UnitQuaternion::from_rotation_matrix(&r).to_rotation_matrix();
        }
    }
}

/// What an element keeps from its initial state.
#[derive(Clone, Debug)]
struct Reference {
    /// Initial frame, columns.
    e0: Matrix3<f64>,
    /// Initial local corner coordinates.
    p0: [Vector3<f64>; NODES],
    /// Local linear stiffness.
    k: ElementMatrix,
}

/// Frame (columns) and centroid of four points: the mean plane of
/// [`Frame::new`] (`e3` along the diagonals' cross product, `e1` along the
/// mean of the sides 0→1 and 3→2 projected onto the plane).
fn frame(x: &[Vector3<f64>; NODES]) -> (Matrix3<f64>, Vector3<f64>) {
    let (e, _) = frame_and_spin(x);
    (e, (x[0] + x[1] + x[2] + x[3]) / 4.0)
}

/// The frame (columns) of four points and its spin per corner translation,
/// `G` (3 × 12) with `delta omega_E = G delta x`, `delta e_k = delta omega_E
/// x e_k`, in closed form. With `n = d1 x d2` (`d1 = x2 - x0`,
/// `d2 = x3 - x1`) and `a` the in-plane part of `(x1 - x0) + (x2 - x3)`:
/// `omega . e1 = -e2 . delta n / |n|`, `omega . e2 = e1 . delta n / |n|`,
/// `omega . e3 = (e2 . delta along - (along . e3) e2 . delta n / |n|) / |a|`.
fn frame_and_spin(x: &[Vector3<f64>; NODES]) -> (Matrix3<f64>, SMatrix<f64, 3, 12>) {
    let d1 = x[2] - x[0];
    let d2 = x[3] - x[1];
    let n = d1.cross(&d2);
    let n_norm = n.norm();
    let e3 = n / n_norm;
    let along = (x[1] - x[0]) + (x[2] - x[3]);
    let in_plane = along - e3 * along.dot(&e3);
    let a_norm = in_plane.norm();
    let e1 = in_plane / a_norm;
    let e2 = e3.cross(&e1);
    let e = Matrix3::from_columns(&[e1, e2, e3]);
    // Gradients of v . delta n over the corners: delta n = delta d1 x d2 +
    // d1 x delta d2, so v . delta n = delta d1 . (d2 x v) + delta d2 . (v x d1).
    let normal_gradient = |v: &Vector3<f64>| -> [Vector3<f64>; NODES] {
        let g1 = d2.cross(v);
        let g2 = v.cross(&d1);
        [-g1, -g2, g1, g2]
    };
    let n2 = normal_gradient(&e2);
    let n1 = normal_gradient(&e1);
    let tilt = along.dot(&e3);
    let along_sign = [-1.0, 1.0, 1.0, -1.0];
    let mut g = SMatrix::<f64, 3, 12>::zeros();
    for j in 0..NODES {
        let r1 = -n2[j] / n_norm;
        let r2 = n1[j] / n_norm;
        let r3 = (e2 * along_sign[j] - n2[j] * (tilt / n_norm)) / a_norm;
        let block = e1 * r1.transpose() + e2 * r2.transpose() + e3 * r3.transpose();
        g.fixed_view_mut::<3, 3>(0, 3 * j).copy_from(&block);
    }
    (e, g)
}

fn spin(v: &Vector3<f64>) -> Matrix3<f64> {
    v.cross_matrix()
}

/// Inverse of the SO(3) tangent map: `delta theta = T(theta)^-1 delta phi`
/// for a spatial spin `delta phi` (`delta R R^T = Spin(delta phi)`).
fn tangent_inverse(theta: &Vector3<f64>) -> Matrix3<f64> {
    let a = theta.norm();
    let s = spin(theta);
    if a < 1e-6 {
        return Matrix3::identity() - 0.5 * s + s * s / 12.0;
    }
    let coefficient = 1.0 / (a * a) - (1.0 + a.cos()) / (2.0 * a * a.sin());
    Matrix3::identity() - 0.5 * s + coefficient * s * s
}

/// Rotation vector of a rotation matrix, accurate near the identity (the
/// `acos` of the trace alone loses half the digits there: an error of 1e-8
/// rad is a force of 1 N in a stiff element at rest). For angles below pi.
fn log_so3(m: &Matrix3<f64>) -> Vector3<f64> {
    let v = 0.5
        * Vector3::new(
            m[(2, 1)] - m[(1, 2)],
            m[(0, 2)] - m[(2, 0)],
            m[(1, 0)] - m[(0, 1)],
        );
    let s = v.norm();
    let c = 0.5 * (m.trace() - 1.0);
    let angle = s.atan2(c);
    if s < 1e-300 {
        return v;
    }
    v * (angle / s)
}

/// The element's corner positions and rotations in a configuration.
fn element_state(
    mesh: &ShellMesh,
    e: usize,
    c: &Configuration,
) -> ([Vector3<f64>; NODES], [Rotation3<f64>; NODES]) {
    let nodes = mesh.elements[e];
    (
        nodes.map(|n| mesh.nodes[n] + c.displacement[n]),
        nodes.map(|n| c.rotation[n]),
    )
}

/// Deformational DOFs `d` and their Jacobian `J = dd/dq` (q: nodal
/// translations and spins).
fn deformation(
    reference: &Reference,
    x: &[Vector3<f64>; NODES],
    r: &[Rotation3<f64>; NODES],
) -> (ElementVector, ElementMatrix) {
    let (e, g) = frame_and_spin(x);
    let c = (x[0] + x[1] + x[2] + x[3]) / 4.0;
    let et = e.transpose();
    let mut d = ElementVector::zeros();
    let mut jac = ElementMatrix::zeros();
    for i in 0..NODES {
        let u = et * (x[i] - c) - reference.p0[i];
        let theta = log_so3(&(et * r[i].matrix() * reference.e0));
        d.fixed_rows_mut::<3>(NODE_DOFS * i).copy_from(&u);
        d.fixed_rows_mut::<3>(NODE_DOFS * i + 3).copy_from(&theta);
        let arm = et * spin(&(x[i] - c)) * g;
        let rot = tangent_inverse(&theta) * et;
        let rot_g = rot * g;
        for j in 0..NODES {
            let own = if i == j { 1.0 } else { 0.0 };
            let translate = et * (own - 0.25);
            let mut block_u = translate;
            block_u += arm.fixed_view::<3, 3>(0, 3 * j);
            jac.fixed_view_mut::<3, 3>(NODE_DOFS * i, NODE_DOFS * j)
                .copy_from(&block_u);
            jac.fixed_view_mut::<3, 3>(NODE_DOFS * i + 3, NODE_DOFS * j)
                .copy_from(&(-rot_g.fixed_view::<3, 3>(0, 3 * j)));
            if i == j {
                jac.fixed_view_mut::<3, 3>(NODE_DOFS * i + 3, NODE_DOFS * j + 3)
                    .copy_from(&rot);
            }
        }
    }
    (d, jac)
}

/// The pieces of `J^T f` for a vector `f` over the deformational DOFs at
/// the configuration `x`, `r` (see [`deformation`] for `J`'s blocks),
/// without forming `J`: per node `j`, translations
/// `E f_u_j - 1/4 sum_i E f_u_i + G_j^T (a - b)` with
/// `a = sum_i (E f_u_i) x (x_i - c)` and `b = sum_i s_i`, spins
/// `s_j = E T_j^-T f_theta_j`. A few hundred flops against the 24 x 24
/// Jacobian's thousands: the stress-dependent part of the tangent takes
/// this once per corner translation, and a turned node changes only its
/// own `s_j` (the frame does not depend on the nodal rotations).
struct PulledForce {
    /// Frame (columns).
    e: Matrix3<f64>,
    /// Frame spin per corner translation.
    g: SMatrix<f64, 3, 12>,
    /// `E f_u_i` per corner.
    pulled: [Vector3<f64>; NODES],
    /// `sum_i E f_u_i`.
    sum: Vector3<f64>,
    /// `sum_i (E f_u_i) x (x_i - c)`.
    a: Vector3<f64>,
    /// `s_i` per corner.
    spin: [Vector3<f64>; NODES],
    /// `sum_i s_i`.
    b: Vector3<f64>,
}

impl PulledForce {
    fn new(
        reference: &Reference,
        x: &[Vector3<f64>; NODES],
        r: &[Rotation3<f64>; NODES],
        f: &ElementVector,
    ) -> Self {
        let mut out = Self::with_spins(x, f, [Vector3::zeros(); 4]);
        for (i, r_i) in r.iter().enumerate() {
            out.spin[i] = out.spin_force(reference, r_i, f, i);
            out.b += out.spin[i];
        }
        out
    }

    /// The pieces at `x` with the spin terms `s_i` given rather than found
    /// from the nodal rotations (no rotation logarithm: the translation
    /// columns of the tangent take them linearized, see
    /// [`Corotational::element`]).
    fn with_spins(
        x: &[Vector3<f64>; NODES],
        f: &ElementVector,
        spin: [Vector3<f64>; NODES],
    ) -> Self {
        let (e, g) = frame_and_spin(x);
        let c = (x[0] + x[1] + x[2] + x[3]) / 4.0;
        let mut out = Self {
            e,
            g,
            pulled: [Vector3::zeros(); 4],
            sum: Vector3::zeros(),
            a: Vector3::zeros(),
            spin,
            b: spin[0] + spin[1] + spin[2] + spin[3],
        };
        for (i, x_i) in x.iter().enumerate() {
            out.pulled[i] = e * f.fixed_rows::<3>(NODE_DOFS * i);
            out.sum += out.pulled[i];
            out.a += out.pulled[i].cross(&(x_i - c));
        }
        out
    }

    /// `s_i` for node `i` at rotation `r_i` in this frame.
    fn spin_force(
        &self,
        reference: &Reference,
        r_i: &Rotation3<f64>,
        f: &ElementVector,
        i: usize,
    ) -> Vector3<f64> {
        let theta = log_so3(&(self.e.transpose() * r_i.matrix() * reference.e0));
        self.e * (tangent_inverse(&theta).transpose() * f.fixed_rows::<3>(NODE_DOFS * i + 3))
    }

    /// `J^T f`.
    fn vector(&self) -> ElementVector {
        let mut out = ElementVector::zeros();
        let ab = self.a - self.b;
        for j in 0..NODES {
            let t = self.pulled[j] - 0.25 * self.sum
                + self.g.fixed_view::<3, 3>(0, 3 * j).transpose() * ab;
            out.fixed_rows_mut::<3>(NODE_DOFS * j).copy_from(&t);
            out.fixed_rows_mut::<3>(NODE_DOFS * j + 3)
                .copy_from(&self.spin[j]);
        }
        out
    }

    /// The change of `J^T f` when node `j`'s `s_j` changes by `ds` (its
    /// rotation turned, everything else held).
    fn spin_change(&self, j: usize, ds: &Vector3<f64>) -> ElementVector {
        let mut out = ElementVector::zeros();
        for k in 0..NODES {
            let t = -(self.g.fixed_view::<3, 3>(0, 3 * k).transpose() * ds);
            out.fixed_rows_mut::<3>(NODE_DOFS * k).copy_from(&t);
        }
        out.fixed_rows_mut::<3>(NODE_DOFS * j + 3).copy_from(ds);
        out
    }
}

/// The co-rotational element set of a mesh.
pub struct Corotational {
    references: Vec<Reference>,
}

/// One element's contribution.
pub struct ElementResponse {
    /// Internal force (global translations and spins), N and N m.
    pub force: ElementVector,
    /// Tangent stiffness: the full one, or its material part `J^T K J`
    /// alone (positive semi-definite) from the `material` methods.
    pub tangent: ElementMatrix,
    /// Strain energy, J.
    pub energy: f64,
}

impl Corotational {
    /// Keeps each element's initial frame and local linear stiffness (one
    /// section per element).
    pub fn new(mesh: &ShellMesh, sections: &[Section]) -> Result<Self, AssemblyError> {
        check_sections(mesh, sections)?;
        let references = (0..mesh.elements.len())
            .map(|e| {
                let x = mesh.corners(e);
                let (e0, c0) = frame(&x);
                let p0 = x.map(|p| e0.transpose() * (p - c0));
                Reference {
                    e0,
                    p0,
                    k: local_stiffness_matrix(&Frame::new(&x), &sections[e]),
                }
            })
            .collect();
        Ok(Self { references })
    }

    /// Internal force, tangent and energy of element `e`.
    pub fn element(&self, mesh: &ShellMesh, e: usize, c: &Configuration) -> ElementResponse {
        let reference = &self.references[e];
        let (x, r) = element_state(mesh, e, c);
        let (d, jac) = deformation(reference, &x, &r);
        let local_force = reference.k * d;
        let force = jac.transpose() * local_force;
        let mut tangent = jac.transpose() * reference.k * jac;
        // Stress-dependent part: d(J^T f_local)/dq with f_local held (the
        // base point by the same block formula, so that the difference
        // carries no round-off of two ways of computing it).
        let pieces = PulledForce::new(reference, &x, &r, &local_force);
        let base = pieces.vector();
        // `s_i = E T_i^-T f_theta_i` depends on the nodal rotation and on
        // the frame only. `turn[i]` is its derivative by a spatial spin of
        // node i (forward differences: J is closed-form, round-off ~1e-16
        // of it, so a step of 1e-7 leaves a truncation error near 1e-7
        // and a round-off near 1e-9). A frame spin `w` changes the
        // relative rotation `E^T R_i E0` as the node spin `-w` does and
        // also turns `E`: `ds_i = -(turn[i] + Spin(s_i)) w`. The 12
        // translation columns take `s_i` linearized that way, which spares
        // them 48 rotation logarithms and tangent inverses.
        let h = 1e-7;
        let mut turn = [Matrix3::zeros(); 4];
        for (node, t) in turn.iter_mut().enumerate() {
            for k in 0..3 {
                let turned = Rotation3::from_scaled_axis(Vector3::ith(k, h)) * r[node];
                let ds =
                    pieces.spin_force(reference, &turned, &local_force, node) - pieces.spin[node];
                t.set_column(k, &(ds / h));
            }
        }
        let frame_turn = [0, 1, 2, 3].map(|i| -(turn[i] + spin(&pieces.spin[i])));
        let size = (x[2] - x[0]).norm().max((x[3] - x[1]).norm());
        for col in 0..DOFS {
            let (node, dof) = (col / NODE_DOFS, col % NODE_DOFS);
            let column = if dof < 3 {
                let step = h * size;
                let mut xp = x;
                xp[node][dof] += step;
                let w = pieces.g.column(3 * node + dof) * step;
                let spins = [0, 1, 2, 3].map(|i| pieces.spin[i] + frame_turn[i] * w);
                (PulledForce::with_spins(&xp, &local_force, spins).vector() - base) / step
            } else {
                // A turned node moves no frame: only its own s_j changes.
                pieces.spin_change(node, &turn[node].column(dof - 3).into_owned())
            };
            for row in 0..DOFS {
                tangent[(row, col)] += column[row];
            }
        }
        let tangent = 0.5 * (tangent + tangent.transpose());
        ElementResponse {
            force,
            tangent,
            energy: 0.5 * d.dot(&local_force),
        }
    }

    /// Internal force of element `e` alone (no tangent): a sixth of the
    /// cost of [`Corotational::element`].
    pub fn element_force(&self, mesh: &ShellMesh, e: usize, c: &Configuration) -> ElementVector {
        let reference = &self.references[e];
        let (x, r) = element_state(mesh, e, c);
        let (d, jac) = deformation(reference, &x, &r);
        jac.transpose() * (reference.k * d)
    }

    /// Internal force, energy and the material tangent `J^T K J` of
    /// element `e`, without the stress-dependent part (its `tangent` is the
    /// material one): a sixth of the cost of [`Corotational::element`],
    /// for iteration matrices where that part is small against others (the
    /// inertia shift of a short time step).
    pub fn element_material(
        &self,
        mesh: &ShellMesh,
        e: usize,
        c: &Configuration,
    ) -> ElementResponse {
        let reference = &self.references[e];
        let (x, r) = element_state(mesh, e, c);
        let (d, jac) = deformation(reference, &x, &r);
        let local_force = reference.k * d;
        ElementResponse {
            force: jac.transpose() * local_force,
            tangent: jac.transpose() * reference.k * jac,
            energy: 0.5 * d.dot(&local_force),
        }
    }

    /// All elements' responses with the material tangent only (see
    /// [`Corotational::element_material`]), in parallel.
    pub fn material_responses(&self, mesh: &ShellMesh, c: &Configuration) -> Vec<ElementResponse> {
        (0..self.references.len())
            .into_par_iter()
            .map(|e| self.element_material(mesh, e, c))
            .collect()
    }

    /// All elements' responses, in parallel.
    pub fn responses(&self, mesh: &ShellMesh, c: &Configuration) -> Vec<ElementResponse> {
        (0..self.references.len())
            .into_par_iter()
            .map(|e| self.element(mesh, e, c))
            .collect()
    }

    /// All elements' internal forces into `out` (storage kept), in
    /// parallel.
    pub fn forces_into(&self, mesh: &ShellMesh, c: &Configuration, out: &mut Vec<ElementVector>) {
        let n = self.references.len();
        out.truncate(n);
        out.resize(n, ElementVector::zeros());
        out.par_iter_mut()
            .enumerate()
            .for_each(|(e, f)| *f = self.element_force(mesh, e, c));
    }

    /// [`Self::responses`] into `out`, whose storage is kept: on the
    /// default wing the responses take about 33 MB, which a fresh vector
    /// every Newton iteration paid for again in page faults and zeroing
    /// (about a sixth of an iteration's time).
    pub fn responses_into(
        &self,
        mesh: &ShellMesh,
        c: &Configuration,
        out: &mut Vec<ElementResponse>,
    ) {
        let n = self.references.len();
        out.truncate(n);
        out.resize_with(n, || ElementResponse {
            force: ElementVector::zeros(),
            tangent: ElementMatrix::zeros(),
            energy: 0.0,
        });
        out.par_iter_mut()
            .enumerate()
            .for_each(|(e, r)| *r = self.element(mesh, e, c));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shell::element;
    use crate::shell::material::Layer;

    /// One element whose corners are nodes 0..4 in order, so element and
    /// global DOF orders agree.
    pub(super) fn one() -> (ShellMesh, Vec<Section>) {
        let p = |x: f64, y: f64| Vector3::new(x, y, 0.0);
        let nodes = vec![p(0.0, 0.0), p(1.2, 0.1), p(1.1, 0.9), p(-0.1, 1.0)];
        let mesh = ShellMesh::new(nodes, vec![[0, 1, 2, 3]]).unwrap();
        (mesh, vec![Section::single(&Layer::CARBON)])
    }

    /// At the undeformed state the tangent is the linear stiffness, and a
    /// small displacement gives the linear force.
    #[test]
    fn small_motions_are_linear() {
        let (mesh, sections) = one();
        let cr = Corotational::new(&mesh, &sections).unwrap();
        let k = element::stiffness(&mesh.corners(0), &sections[0]);
        let r = cr.element(&mesh, 0, &Configuration::initial(4));
        // Up to the drilling penalty: the linear element resists a rigid
        // in-plane rotation with it, the co-rotated one does not.
        let error = (r.tangent - k).norm() / k.norm();
        assert!(error < 2e-3, "tangent {error}");
        let mut c = Configuration::initial(4);
        let u: Vec<f64> = (0..24)
            .map(|i| 1e-9 * ((i * 7 % 11) as f64 - 5.0))
            .collect();
        c.update(&u);
        let f = cr.element(&mesh, 0, &c).force;
        let linear = k * ElementVector::from_column_slice(&u);
        // (Up to the drilling penalty, as above: 2e-4 here.)
        assert!((f - linear).norm() < 1e-3 * linear.norm(), "{f} {linear}");
    }

    /// The closed-form frame is [`Frame::new`]'s, and its spin is the
    /// central difference of the frame (`omega = 1/2 sum_k e_k x delta e_k`)
    /// on a warped, skewed quadrilateral.
    #[test]
    fn frame_spin_is_the_derivative_of_the_frame() {
        let x = [
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(1.2, 0.1, 0.2),
            Vector3::new(1.1, 0.9, -0.1),
            Vector3::new(-0.1, 1.0, 0.15),
        ];
        let (e, g) = frame_and_spin(&x);
        assert!((e - Frame::new(&x).rotation.transpose()).norm() < 1e-15);
        let h = 1e-6;
        let mut worst: f64 = 0.0;
        for col in 0..12 {
            let (mut plus, mut minus) = (x, x);
            plus[col / 3][col % 3] += h;
            minus[col / 3][col % 3] -= h;
            let (ep, _) = frame_and_spin(&plus);
            let (em, _) = frame_and_spin(&minus);
            let mut w = Vector3::zeros();
            for m in 0..3 {
                w += 0.5
                    * e.column(m)
                        .cross(&((ep.column(m) - em.column(m)) / (2.0 * h)));
            }
            worst = worst.max((w - g.column(col)).norm());
        }
        assert!(worst < 1e-8, "{worst}");
    }

    /// `J^T f` from the blocks equals the formed Jacobian's, at a large,
    /// general configuration.
    #[test]
    fn transposed_jacobian_product_matches_the_jacobian() {
        let (mesh, sections) = one();
        let cr = Corotational::new(&mesh, &sections).unwrap();
        let c = super::tests::bent();
        let (x, r) = element_state(&mesh, 0, &c);
        let reference = &cr.references[0];
        let (_, jac) = deformation(reference, &x, &r);
        let f = ElementVector::from_fn(|i, _| ((i * 5 % 7) as f64 - 3.0) * 0.7);
        let direct = jac.transpose() * f;
        let blocks = PulledForce::new(reference, &x, &r, &f).vector();
        assert!(
            (direct - blocks).norm() < 1e-12 * direct.norm(),
            "{}",
            (direct - blocks).norm()
        );
    }

    /// [`one`]'s nodes moved and turned by up to 0.05 m and 0.05 rad: a
    /// large, general configuration.
    pub(super) fn bent() -> Configuration {
        let mut c = Configuration::initial(4);
        let u: Vec<f64> = (0..24)
            .map(|i| 0.05 * ((i * 7 % 11) as f64 - 5.0) / 5.0)
            .collect();
        c.update(&u);
        c
    }

    /// A large rigid rotation and translation stores nothing and loads
    /// nothing.
    #[test]
    fn rigid_motion_is_free() {
        let (mesh, sections) = one();
        let cr = Corotational::new(&mesh, &sections).unwrap();
        let q = Rotation3::from_euler_angles(0.7, -1.2, 2.0);
        let mut c = Configuration::initial(4);
        for n in 0..4 {
            c.displacement[n] = q * mesh.nodes[n] - mesh.nodes[n] + Vector3::new(1.0, 2.0, 3.0);
            c.rotation[n] = q;
        }
        let r = cr.element(&mesh, 0, &c);
        assert!(r.energy.abs() < 1e-15, "{}", r.energy);
        assert!(
            r.force.norm() < 1e-12 * r.tangent.norm(),
            "{}",
            r.force.norm()
        );
    }
}

#[cfg(test)]
mod consistency {
    use super::*;

    /// At a large, general configuration the force is the gradient of the
    /// energy and the tangent the symmetric part of the derivative of the
    /// force (central differences in translations and spins).
    #[test]
    fn force_and_tangent_are_derivatives() {
        let (mesh, sections) = super::tests::one();
        let cr = Corotational::new(&mesh, &sections).unwrap();
        let c = super::tests::bent();
        let r = cr.element(&mesh, 0, &c);
        let h = 1e-6;
        let mut worst_f: f64 = 0.0;
        let mut fd = ElementMatrix::zeros();
        for col in 0..24 {
            let mut step = vec![0.0; 24];
            step[col] = h;
            let mut plus = c.clone();
            plus.update(&step);
            step[col] = -h;
            let mut minus = c.clone();
            minus.update(&step);
            let (rp, rm) = (cr.element(&mesh, 0, &plus), cr.element(&mesh, 0, &minus));
            let df = (rp.energy - rm.energy) / (2.0 * h);
            worst_f = worst_f.max((df - r.force[col]).abs() / r.force.norm());
            fd.set_column(col, &((rp.force - rm.force) / (2.0 * h)));
        }
        assert!(worst_f < 1e-8, "force {worst_f}");
        // The tangent is the symmetric part (off equilibrium the spin
        // derivative has a small skew part, which vanishes there).
        let sym = 0.5 * (fd + fd.transpose());
        let error = (sym - r.tangent).norm() / r.tangent.norm();
        // Measured 2.5e-9 with the closed-form frame spin (about 1e-6 when
        // the spin was itself a central difference).
        assert!(error < 1e-7, "tangent {error}");
    }
}
