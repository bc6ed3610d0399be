//! The wall's pressure and skin friction at one instant, in the global
//! frame of [`super::super::case`]: what `fwav aero2d --surface` writes.
//!
//! The solver integrates the wall pressure along the wall from the
//! momentum equation there (`fwav_ns2d::WallLoads`), which fixes its
//! differences; its level, the mean round the wall relative to the far
//! stream's pressure, comes from the momentum equation along the grid's
//! radial lines (`fwav_ns2d::Flow::wall_pressure_mean`), so `cp` is the
//! usual `(p - p∞) / (1/2 rho U^2)`: 1 at a steady stagnation point. The
//! forces do not depend on the level (a uniform pressure on a closed
//! contour gives none), nor does the loading across a thin section. The
//! skin friction is the wall's shear stress `ν ω` along the wall,
//! given as a vector.

use fwav_ns2d::{Complex64, Flow, Motion as _};

use super::SectionPath;

/// The wall's loads at one instant, one entry a wall node, counter-
/// clockwise round the section; coefficients on `1/2 rho U^2`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SurfaceLoads {
    /// When, chords travelled.
    pub time: f64,
    /// The nodes, global frame, chords.
    pub points: Vec<(f64, f64)>,
    /// Arc length from the first node, chords.
    pub arc: Vec<f64>,
    /// Pressure coefficient, `(p - p∞) / (1/2 rho U^2)` (module docs).
    pub cp: Vec<f64>,
    /// Skin-friction coefficient: the shear stress the fluid puts on the
    /// wall, global axes `(x downstream, y up)`.
    pub cf: Vec<(f64, f64)>,
}

impl SurfaceLoads {
    /// The wall of `flow` (kinematic viscosity `viscosity`, moving by
    /// `path`) now. Cost: one pass of the solver's loads round the wall
    /// and one over the grid (the level).
    pub(super) fn of(flow: &Flow<SectionPath>, path: &SectionPath, viscosity: f64) -> Self {
        let g = flow.grid();
        let loads = flow.loads();
        let level = flow.wall_pressure_mean();
        let place = path.placement(flow.time());
        // Body to global axes: the frame's angle (a nose-up pitch turns
        // the body axes clockwise), as the solver's resultant force.
        let turn = Complex64::from_polar(1.0, path.state(flow.time()).angle);
        let mut surface = Self {
            time: flow.time(),
            ..Self::default()
        };
        let mut arc = 0.0;
        for k in 0..g.nt {
            let i = g.at(0, k);
            if k > 0 {
                arc += (g.z[i] - g.z[g.at(0, k - 1)]).norm();
            }
            let dz = g.dz_dxi[i];
            // The counter-clockwise tangent, along which the solver's
            // wall vorticity times ν is the stress on the wall.
            let tangent = Complex64::new(0.0, 1.0) * dz / dz.norm();
            let stress = 2.0 * viscosity * loads.wall_vorticity[k] * tangent * turn;
            surface.points.push(place(g.z[i]));
            surface.arc.push(arc);
            surface.cp.push(2.0 * (loads.pressure[k] + level));
            surface.cf.push((stress.re, stress.im));
        }
        surface
    }
}
