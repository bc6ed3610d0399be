//! Aerodynamic loads of the ring lattice: Kutta–Joukowski forces on the
//! bound vortex segments plus the unsteady `ρ ∂Φ/∂t` pressure, split into
//! the normal pressure on each panel and the in-plane (leading-edge
//! suction) force of each spanwise strip.
//!
//! Why not the pressure alone: the textbook pressure jump of the unsteady
//! lifting-surface method (Katz & Plotkin 2001, §13.12, eq. 13.151-type
//! unsteady Bernoulli: tangential velocity times the circulation gradients
//! plus `∂Γ/∂t`) acts along the panel normals, so it gives no thrust on a
//! heaving flat plate: the leading-edge suction of thin-aerofoil theory, an
//! in-plane force concentrated at the sharp leading edge, is missing
//! (Simpson, Palacios & Murua 2013, AIAA J. 51(7) 1775). Katz & Plotkin's
//! Program 16 adds an induced-drag formula instead, which is right for a
//! wing at a fixed angle but omits the plunge velocity. Here, following
//! Simpson et al.'s Joukowski method, each bound segment `l` of net
//! circulation `Γ_s` gets the Kutta–Joukowski force
//!
//! `F_s = ρ Γ_s (V × l)`, `V = U∞ − v_surface + v_induced` at its midpoint
//!
//! (the induced velocity of all bound rings, their mirror image and the
//! wake, the segment itself contributing nothing on its own line), and
//! each panel the unsteady force `ρ (∂Φ/∂t) A n`. The normal part of `F_s`
//! equals the textbook's `ρ (V·τ) ΔΓ Δb` pressure term, so
//!
//! - `pressure_jump = (Σ F_s · n + ρ A ∂Φ/∂t) / A` per panel, the
//!   discrete unsteady Bernoulli equation with the local velocity, and
//!   `panel_force = Δp A n`;
//! - the in-plane remainder `F_s − (F_s · n) n` of all segments of a
//!   spanwise strip is its leading-edge suction (a thin surface carries
//!   in-plane force only through the leading-edge singularity; the
//!   lattice smears it over the bound vortices, mostly the first) and is
//!   reported per strip, to be applied at the leading edge;
//! - `force` is the sum of both, i.e. the total Kutta–Joukowski plus
//!   unsteady force; `power = −Σ panel_force · v_panel − Σ suction ·
//!   v_leading_edge`.
//!
//! Segment ownership: the spanwise segment on panel `(i, j)`'s quarter
//! chord (net `Γ(i, j) − Γ(i − 1, j)`) belongs to that panel; a chordwise
//! segment (net `Γ(i, j − 1) − Γ(i, j)`) is shared half and half by its
//! two panels (wholly by the edge panel at the tip, and at the root of a
//! non-symmetric model; at the root of a symmetric one it cancels with its
//! mirror image). The shed segment behind the trailing edge is free
//! vorticity and carries no force.

use nalgebra::Vector3;

use super::lattice::Lattice;
use super::rings::BoundRings;
use super::settings::{PotentialRate, TimeDerivative, UvlmSettings};
use super::vortex::{grid_segments, induced_velocities, Segment};
use super::wake::WakeSheet;

/// Bound circulation and loads of a surface at one time level (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// Ring circulation per panel, m²/s (positive lifts towards +n in a
    /// stream from leading to trailing edge).
    pub circulation: Vec<f64>,
    /// `Δp = p_lower − p_upper` per panel, Pa (lower = the −n side), from
    /// the unsteady Bernoulli equation with the local velocity (module
    /// docs).
    pub pressure_jump: Vec<f64>,
    /// `Δp · area · n` per panel, N: the normal pressure load.
    pub panel_force: Vec<Vector3<f64>>,
    /// In-plane (leading-edge suction) force of each spanwise strip
    /// `j = 0 .. spanwise`, N, acting at the middle of the strip's leading
    /// edge (module docs). Zero on a surface without circulation.
    pub leading_edge_suction: Vec<Vector3<f64>>,
    /// Total force on the (half) surface, N: `Σ panel_force + Σ
    /// leading_edge_suction`.
    pub force: Vector3<f64>,
    /// Power the surface's motion puts into the fluid, W: `−Σ panel_force
    /// · v_centroid − Σ leading_edge_suction · v_leading_edge` (positive
    /// for a thrusting flapping wing).
    pub power: f64,
    /// The shed line the solution was computed with (trailing edge + shed
    /// offset, `spanwise + 1` points, m): the trailing segment of the last
    /// bound rings and the leading edge of the wake.
    pub shed_line: Vec<Vector3<f64>>,
}

/// All vortex segments of the surface and its wake with their net
/// circulations: the bound ring grid continued by the wake rows (the
/// wake's point row 0 is the rings' shed line).
pub(crate) fn all_segments(
    surface: &Lattice,
    rings: &BoundRings,
    circulation: &[f64],
    wake: &WakeSheet,
) -> Vec<Segment> {
    let width = surface.spanwise + 1;
    let mut points = rings.points.clone();
    let mut strengths = circulation.to_vec();
    if wake.rows() > 0 {
        points.extend_from_slice(&wake.points()[width..]);
        strengths.extend_from_slice(wake.strengths());
    }
    grid_segments(
        surface.chordwise + wake.rows(),
        surface.spanwise,
        &points,
        &strengths,
    )
}

/// The potential jump of panel `(i, j)` in the chosen convention.
fn potential(rate: PotentialRate, gamma: &[f64], spanwise: usize, i: usize, j: usize) -> f64 {
    let own = gamma[i * spanwise + j];
    let ahead = if i > 0 {
        gamma[(i - 1) * spanwise + j]
    } else {
        0.0
    };
    match rate {
        PotentialRate::Ring => own,
        PotentialRate::NeighbourMean => 0.5 * (own + ahead),
        PotentialRate::PanelAverage => 0.75 * own + 0.25 * ahead,
    }
}

/// A bound segment carrying force and the panels sharing it.
struct ForceSegment {
    segment: Segment,
    surface_velocity: Vector3<f64>,
    owners: [(usize, f64); 2],
}

/// The bound segments that carry force for circulation `gamma`: each
/// panel's leading segment (with the strength of its ring less the one
/// ahead), then the chordwise segments of the row (between neighbouring
/// rings, halves to each; the root's left out of a `symmetric` half wing).
fn force_segments(
    surface: &Lattice,
    rings: &BoundRings,
    gamma: &[f64],
    symmetric: bool,
) -> Vec<ForceSegment> {
    let (nc, ns) = (surface.chordwise, surface.spanwise);
    let point = |r: usize, c: usize| r * (ns + 1) + c;
    let mut bound = Vec::with_capacity(nc * (2 * ns + 1));
    for i in 0..nc {
        for j in 0..ns {
            let behind = if i > 0 { gamma[(i - 1) * ns + j] } else { 0.0 };
            let (a, b) = (point(i, j), point(i, j + 1));
            bound.push(ForceSegment {
                segment: Segment {
                    start: rings.points[a],
                    end: rings.points[b],
                    strength: gamma[i * ns + j] - behind,
                },
                surface_velocity: 0.5 * (rings.velocities[a] + rings.velocities[b]),
                owners: [(i * ns + j, 1.0), (0, 0.0)],
            });
        }
        for c in 0..=ns {
            if c == 0 && symmetric {
                continue;
            }
            let root_side = if c > 0 { gamma[i * ns + c - 1] } else { 0.0 };
            let tip_side = if c < ns { gamma[i * ns + c] } else { 0.0 };
            let owners = match (c > 0, c < ns) {
                (true, true) => [(i * ns + c - 1, 0.5), (i * ns + c, 0.5)],
                (true, false) => [(i * ns + c - 1, 1.0), (0, 0.0)],
                _ => [(i * ns + c, 1.0), (0, 0.0)],
            };
            let (a, b) = (point(i, c), point(i + 1, c));
            bound.push(ForceSegment {
                segment: Segment {
                    start: rings.points[a],
                    end: rings.points[b],
                    strength: root_side - tip_side,
                },
                surface_velocity: 0.5 * (rings.velocities[a] + rings.velocities[b]),
                owners,
            });
        }
    }
    bound
}

/// The loads (module docs) for circulation `circulation` on `surface`,
/// with the committed circulations of the last step `previous` and of the
/// step before, `older`, if any (for `∂Φ/∂t`).
#[allow(clippy::too_many_arguments)]
pub(crate) fn loads(
    surface: &Lattice,
    corner_velocity: &[Vector3<f64>],
    rings: &BoundRings,
    circulation: Vec<f64>,
    previous: &[f64],
    older: Option<&[f64]>,
    wake: &WakeSheet,
    settings: &UvlmSettings,
    shed_line: Vec<Vector3<f64>>,
) -> Solution {
    let (nc, ns) = (surface.chordwise, surface.spanwise);
    let rho = settings.density;
    let gamma = &circulation;
    let bound = force_segments(surface, rings, gamma, settings.symmetric);
    let everything = all_segments(surface, rings, gamma, wake);
    let midpoints: Vec<_> = bound
        .iter()
        .map(|f| 0.5 * (f.segment.start + f.segment.end))
        .collect();
    let induced = induced_velocities(
        &everything,
        &midpoints,
        settings.core_radius,
        settings.symmetric,
    );
    // Kutta–Joukowski force of the bound segments, summed per panel.
    let mut steady = vec![Vector3::zeros(); nc * ns];
    for (f, v) in bound.iter().zip(&induced) {
        let velocity = settings.freestream - f.surface_velocity + v;
        let l = f.segment.end - f.segment.start;
        let force = rho * f.segment.strength * velocity.cross(&l);
        for &(panel, weight) in &f.owners {
            steady[panel] += weight * force;
        }
    }
    let mut pressure_jump = vec![0.0; nc * ns];
    let mut panel_force = vec![Vector3::zeros(); nc * ns];
    let mut suction = vec![Vector3::zeros(); ns];
    let mut power = 0.0;
    for i in 0..nc {
        for j in 0..ns {
            let p = i * ns + j;
            let (n, area) = (surface.normal(i, j), surface.area(i, j));
            let phi = |g: &[f64]| potential(settings.potential_rate, g, ns, i, j);
            let rate = match (settings.time_derivative, older) {
                (TimeDerivative::SecondOrder, Some(older)) => {
                    (3.0 * phi(gamma) - 4.0 * phi(previous) + phi(older)) / (2.0 * settings.dt)
                }
                _ => (phi(gamma) - phi(previous)) / settings.dt,
            };
            let normal = steady[p].dot(&n);
            pressure_jump[p] = (normal + rho * area * rate) / area;
            panel_force[p] = pressure_jump[p] * area * n;
            suction[j] += steady[p] - normal * n;
            let v: Vector3<f64> = (0..4)
                .map(|k| {
                    let (di, dj) = [(0, 0), (1, 0), (1, 1), (0, 1)][k];
                    corner_velocity[surface.corner_index(i + di, j + dj)]
                })
                .sum::<Vector3<f64>>()
                / 4.0;
            power -= panel_force[p].dot(&v);
        }
    }
    for (j, s) in suction.iter().enumerate() {
        let v = 0.5
            * (corner_velocity[surface.corner_index(0, j)]
                + corner_velocity[surface.corner_index(0, j + 1)]);
        power -= s.dot(&v);
    }
    let force = panel_force.iter().chain(&suction).sum();
    Solution {
        circulation,
        pressure_jump,
        panel_force,
        leading_edge_suction: suction,
        force,
        power,
        shed_line,
    }
}
