//! The wing's mass moment of inertia about the flapping axis, from the
//! shell model's mass: `I = sum_e mu_e int_e |p x a|^2 dA`, with `mu_e` the
//! element's mass per unit area (both layers, the carbon one at its
//! layout density), `p` a point of the element and `a` the unit flapping
//! axis through the root leading edge (the origin of the wing axes, see
//! [`crate::aeroelastic::kinematics`]); `|p x a|` is the point's distance
//! from the axis. Each bilinear element is integrated by 2 x 2 Gauss
//! points, exact for the flat, straight-sided elements of the wing mesh
//! (the integrand `|p x a|^2 det J` is at most cubic in each parent
//! coordinate). The sections' rotary inertia (`rho t^3 / 12`, about 1e-9 of
//! the translational term for these millimetre layers) is left out.
//!
//! May import: [`crate::shell`] (mesh and sections) and nalgebra.

use nalgebra::{Unit, Vector3};

use crate::shell::element::NODES;
use crate::shell::material::Section;
use crate::shell::mesh::ShellMesh;

/// Gauss points of the 2-point rule on [-1, 1] (weights 1).
const GAUSS: [f64; 2] = [-0.577_350_269_189_625_8, 0.577_350_269_189_625_8];

/// Why the inertia could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum InertiaError {
    /// The sections do not match the mesh's elements.
    #[error("{sections} sections for {elements} shell elements: give one section per element")]
    Sections {
        /// Sections given.
        sections: usize,
        /// Elements of the mesh.
        elements: usize,
    },
}

/// Mass and inertia of a shell about an axis through the origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AxisInertia {
    /// Mass, kg.
    pub mass_kg: f64,
    /// Mass moment of inertia about the axis, kg m^2.
    pub inertia_kg_m2: f64,
}

/// The mass and the inertia about the axis `axis` through the origin of
/// the shell `mesh` with one `sections` entry per element (module docs).
pub fn axis_inertia(
    mesh: &ShellMesh,
    sections: &[Section],
    axis: &Unit<Vector3<f64>>,
) -> Result<AxisInertia, InertiaError> {
    if sections.len() != mesh.elements.len() {
        return Err(InertiaError::Sections {
            sections: sections.len(),
            elements: mesh.elements.len(),
        });
    }
    let mut out = AxisInertia {
        mass_kg: 0.0,
        inertia_kg_m2: 0.0,
    };
    for (e, section) in sections.iter().enumerate() {
        let x = mesh.corners(e);
        for &xi in &GAUSS {
            for &eta in &GAUSS {
                let (point, area) = bilinear(&x, xi, eta);
                let r_perp = point.cross(axis).norm_squared();
                out.mass_kg += section.mass * area;
                out.inertia_kg_m2 += section.mass * r_perp * area;
            }
        }
    }
    Ok(out)
}

/// The bilinear element's point at `(xi, eta)` and its area scale `|dx/dxi
/// x dx/deta|` (the Jacobian's determinant of the surface map).
fn bilinear(x: &[Vector3<f64>; NODES], xi: f64, eta: f64) -> (Vector3<f64>, f64) {
    // Corners at (-1,-1), (1,-1), (1,1), (-1,1).
    let n = [
        0.25 * (1.0 - xi) * (1.0 - eta),
        0.25 * (1.0 + xi) * (1.0 - eta),
        0.25 * (1.0 + xi) * (1.0 + eta),
        0.25 * (1.0 - xi) * (1.0 + eta),
    ];
    let dxi = [
        -0.25 * (1.0 - eta),
        0.25 * (1.0 - eta),
        0.25 * (1.0 + eta),
        -0.25 * (1.0 + eta),
    ];
    let deta = [
        -0.25 * (1.0 - xi),
        -0.25 * (1.0 + xi),
        0.25 * (1.0 + xi),
        0.25 * (1.0 - xi),
    ];
    let mut p = Vector3::zeros();
    let (mut a, mut b) = (Vector3::zeros(), Vector3::zeros());
    for i in 0..NODES {
        p += n[i] * x[i];
        a += dxi[i] * x[i];
        b += deta[i] * x[i];
    }
    (p, a.cross(&b).norm())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shell::material::Layer;

    /// A uniform rectangular plate `a x b` (chord x span) of mass `m`
    /// hinged along its root edge (the x axis) has `I = m b^2 / 3`; about
    /// the normal through its corner (the z axis) `I = m (a^2 + b^2) / 3`
    /// (thin rectangular plate, e.g. Meriam & Kraige, *Engineering
    /// Mechanics: Dynamics*, table D/4, with the parallel-axis theorem).
    /// Both hold on a coarse mesh since the Gauss rule is exact.
    #[test]
    fn uniform_plate_matches_m_l_squared_over_three() {
        let (a, b) = (0.05, 0.15);
        let mesh = ShellMesh::rectangle(a, b, 3, 7).unwrap();
        let section = Section::single(&Layer::MYLAR);
        let sections = vec![section; mesh.elements.len()];
        let m = section.mass * a * b;
        let root = axis_inertia(&mesh, &sections, &Vector3::x_axis()).unwrap();
        assert!((root.mass_kg / m - 1.0).abs() < 1e-12, "{root:?}");
        assert!(
            (root.inertia_kg_m2 / (m * b * b / 3.0) - 1.0).abs() < 1e-12,
            "{root:?}"
        );
        let normal = axis_inertia(&mesh, &sections, &Vector3::z_axis()).unwrap();
        let expected = m * (a * a + b * b) / 3.0;
        assert!((normal.inertia_kg_m2 / expected - 1.0).abs() < 1e-12);
    }

    /// The built-in wing (tapered, 10.3 g with the full carbon layer):
    /// `I = mu int_0^L c(y) y^2 dy = mu (c_r L^3/3 - (c_r - c_t) L^3/4)`
    /// about the root chord line, the mass `mu (c_r + c_t) L / 2`.
    #[test]
    fn tapered_wing_matches_its_closed_form() {
        let model = crate::aeroelastic::model::WingModel::fwav(1.0).unwrap();
        let p = model.planform;
        let mu = Section::two_layer(&Layer::CARBON, &Layer::MYLAR, 1.0, 3.0).mass;
        let l = p.semi_span;
        let expected =
            mu * (p.root_chord * l.powi(3) / 3.0 - (p.root_chord - p.tip_chord) * l.powi(3) / 4.0);
        let got = axis_inertia(&model.wing.mesh, &model.sections, &Vector3::x_axis()).unwrap();
        assert!((got.mass_kg / (mu * 0.5 * (p.root_chord + p.tip_chord) * l) - 1.0).abs() < 1e-9);
        assert!(
            (got.inertia_kg_m2 / expected - 1.0).abs() < 1e-9,
            "{got:?} vs {expected}"
        );
    }

    #[test]
    fn mismatched_sections_are_an_error() {
        let mesh = ShellMesh::rectangle(1.0, 1.0, 2, 2).unwrap();
        let e = axis_inertia(&mesh, &[], &Vector3::x_axis()).unwrap_err();
        assert_eq!(
            e.to_string(),
            "0 sections for 4 shell elements: give one section per element"
        );
    }
}
