//! The flapping wing's planform and its structured shell mesh.
//!
//! Wing axes: `x` chordwise from the leading edge towards the trailing
//! edge, `y` spanwise from the root, `z` up (the flat wing lies in z = 0).
//! The leading edge is straight along `y`; the trailing edge tapers
//! linearly from the root chord to the tip chord. A carbon leading-edge
//! spar of given width runs along the span; the root attachment (the nodes
//! at the root from the leading edge over a given length) is tied rigidly
//! to the drive point, so those nodes follow its motion exactly (clamped in
//! the topology optimization, driven by the flapping motion in the
//! aeroelastic analysis).

use nalgebra::Vector3;

use super::element::NODE_DOFS;
use super::mesh::{MeshError, ShellMesh};

/// A wing planform and its mesh density (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Planform {
    /// Semi-span, root to tip, m.
    pub semi_span: f64,
    /// Root chord, m.
    pub root_chord: f64,
    /// Tip chord, m.
    pub tip_chord: f64,
    /// Width of the leading-edge spar, m.
    pub spar_width: f64,
    /// Length of the root attachment from the leading edge, m.
    pub root_attachment: f64,
    /// Elements along the span.
    pub span_elements: usize,
    /// Elements along the chord.
    pub chord_elements: usize,
}

impl Planform {
    /// The built-in FWAV wing (a documented choice where the paper's copy
    /// lost the values): semi-span 0.15 m, root chord 0.075 m tapering to
    /// 0.045 m at the tip, a 4 mm leading-edge spar, a 15 mm root
    /// attachment, and the paper's mesh size, 130 x 52 = 6760 elements a
    /// layer.
    pub const FWAV: Planform = Planform {
        semi_span: 0.15,
        root_chord: 0.075,
        tip_chord: 0.045,
        spar_width: 0.004,
        root_attachment: 0.015,
        span_elements: 130,
        chord_elements: 52,
    };

    /// Chord at spanwise station `y`, m.
    pub fn chord(&self, y: f64) -> f64 {
        let s = (y / self.semi_span).clamp(0.0, 1.0);
        self.root_chord + (self.tip_chord - self.root_chord) * s
    }

    /// The mesh, its spar elements and root attachment nodes.
    pub fn mesh(&self) -> Result<WingMesh, MeshError> {
        let positive = [
            self.semi_span,
            self.root_chord,
            self.tip_chord,
            self.spar_width,
            self.root_attachment,
        ];
        if !positive.iter().all(|v| v.is_finite() && *v > 0.0)
            || self.span_elements == 0
            || self.chord_elements == 0
        {
            return Err(MeshError::Parameter(format!(
                "planform dimensions must be positive and finite and element counts at least 1 \
                 (semi-span {} m, root chord {} m, tip chord {} m, spar width {} m, root attachment {} m, \
                 {} spanwise and {} chordwise elements)",
                self.semi_span,
                self.root_chord,
                self.tip_chord,
                self.spar_width,
                self.root_attachment,
                self.span_elements,
                self.chord_elements
            )));
        }
        if self.spar_width >= self.root_chord.min(self.tip_chord)
            || self.root_attachment > self.root_chord
        {
            return Err(MeshError::Parameter(format!(
                "the spar ({} m) must be narrower than the chord and the root attachment ({} m) no longer than the root chord",
                self.spar_width, self.root_attachment
            )));
        }
        let mesh = ShellMesh::mapped(self.chord_elements, self.span_elements, |s, t| {
            let y = t * self.semi_span;
            Vector3::new(s * self.chord(y), y, 0.0)
        })?;
        let spar = (0..mesh.elements.len())
            .map(|e| {
                let centre = mesh.corners(e).iter().sum::<Vector3<f64>>() / 4.0;
                centre.x < self.spar_width
            })
            .collect();
        let tolerance = 1e-9 * self.root_chord;
        let root_nodes =
            mesh.nodes_where(|p| p.y.abs() < tolerance && p.x <= self.root_attachment + tolerance);
        if root_nodes.len() < 2 {
            return Err(MeshError::Parameter(format!(
                "the root attachment ({} m) holds {} node of the {} chordwise elements: the wing would hang on one node; use at least {} chordwise elements",
                self.root_attachment,
                root_nodes.len(),
                self.chord_elements,
                (self.root_chord / self.root_attachment).ceil() as usize
            )));
        }
        Ok(WingMesh {
            mesh,
            spar,
            root_nodes,
        })
    }
}

/// A meshed wing.
#[derive(Clone, Debug, PartialEq)]
pub struct WingMesh {
    /// The shell mesh.
    pub mesh: ShellMesh,
    /// Whether each element belongs to the leading-edge spar.
    pub spar: Vec<bool>,
    /// Nodes tied to the drive point.
    pub root_nodes: Vec<usize>,
}

impl WingMesh {
    /// All six DOFs of the root attachment nodes (clamped root).
    pub fn clamped_dofs(&self) -> Vec<usize> {
        self.root_nodes
            .iter()
            .flat_map(|n| (0..NODE_DOFS).map(move |c| NODE_DOFS * n + c))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_paper_mesh_size_and_regions() {
        let w = Planform::FWAV.mesh().unwrap();
        assert_eq!(w.mesh.elements.len(), 6760);
        let spar = w.spar.iter().filter(|&&s| s).count();
        // 4 mm of a 45-75 mm chord at 52 elements: 3 to 4 elements a row.
        assert!((2 * 130..=5 * 130).contains(&spar), "{spar}");
        // 15 mm of 75 mm at 52 elements: nodes 0..=10.
        assert_eq!(w.root_nodes.len(), 11);
        let area: f64 = (0..w.mesh.elements.len())
            .map(|e| w.mesh.element_area(e))
            .sum();
        assert!((area - 0.15 * (0.075 + 0.045) / 2.0).abs() < 1e-12);
        let bad = Planform {
            spar_width: 0.1,
            ..Planform::FWAV
        };
        assert!(matches!(bad.mesh(), Err(MeshError::Parameter(_))));
        let one_node = Planform {
            chord_elements: 4,
            ..Planform::FWAV
        };
        assert!(
            matches!(one_node.mesh(), Err(MeshError::Parameter(m)) if m.contains("at least 5"))
        );
    }
}
