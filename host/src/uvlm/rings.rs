//! The bound vortex rings of a surface lattice (Katz & Plotkin 2001,
//! §12.3 and §13.12, Fig. 13.27): each panel's ring has its leading
//! segment on the panel's quarter-chord line and its trailing segment on
//! the next panel's quarter-chord line; the last row's trailing segment is
//! the shed line, a fraction of the step's travel behind the trailing edge
//! (Program 16: `QF(NC+1) = C + 0.3 VINF DT`).
//!
//! The ring corners form a `(chordwise + 1) x (spanwise + 1)` grid laid
//! out like the lattice's corners ([`super::vortex::grid_segments`]).

use nalgebra::Vector3;

use super::lattice::Lattice;

/// The ring corner grid of a surface, m, with its velocities (m/s).
#[derive(Debug, Clone)]
pub(crate) struct BoundRings {
    /// `(chordwise + 1) * (spanwise + 1)` ring corners.
    pub points: Vec<Vector3<f64>>,
    /// Velocity of the surface at each ring corner (the shed line moves
    /// with the trailing edge).
    pub velocities: Vec<Vector3<f64>>,
}

impl BoundRings {
    /// Ring corners of `surface` with corner velocities `corner_velocity`
    /// and the shed line `shed_line` (`spanwise + 1` points).
    pub fn new(
        surface: &Lattice,
        corner_velocity: &[Vector3<f64>],
        shed_line: &[Vector3<f64>],
    ) -> Self {
        let (nc, ns) = (surface.chordwise, surface.spanwise);
        let mut points = Vec::with_capacity(surface.corner_count());
        let mut velocities = Vec::with_capacity(surface.corner_count());
        for i in 0..nc {
            for j in 0..=ns {
                let (a, b) = (surface.corner_index(i, j), surface.corner_index(i + 1, j));
                points.push(quarter(&surface.corners[a], &surface.corners[b]));
                velocities.push(quarter(&corner_velocity[a], &corner_velocity[b]));
            }
        }
        points.extend_from_slice(shed_line);
        for j in 0..=ns {
            velocities.push(corner_velocity[surface.corner_index(nc, j)]);
        }
        Self { points, velocities }
    }

    /// The corners of ring `(i, j)` in traversal order (root to tip along
    /// the leading segment).
    pub fn ring(&self, spanwise: usize, i: usize, j: usize) -> [Vector3<f64>; 4] {
        let p = |r: usize, c: usize| self.points[r * (spanwise + 1) + c];
        [p(i, j), p(i, j + 1), p(i + 1, j + 1), p(i + 1, j)]
    }
}

/// The shed line of `surface`: each trailing-edge corner plus
/// `shed_offset (U∞ − v_TE) dt`, i.e. displaced along the air's velocity
/// relative to the trailing edge (for a wing at rest in a stream `U` along
/// x, `0.3 U dt` behind the trailing edge, as in Program 16).
pub(crate) fn shed_line(
    surface: &Lattice,
    corner_velocity: &[Vector3<f64>],
    freestream: &Vector3<f64>,
    dt: f64,
    shed_offset: f64,
) -> Vec<Vector3<f64>> {
    (0..=surface.spanwise)
        .map(|j| {
            let k = surface.corner_index(surface.chordwise, j);
            surface.corners[k] + shed_offset * dt * (freestream - corner_velocity[k])
        })
        .collect()
}

fn quarter(a: &Vector3<f64>, b: &Vector3<f64>) -> Vector3<f64> {
    a + 0.25 * (b - a)
}
