//! Influence of constant-strength source and doublet panels and of the
//! doublet sheet of the wake (Katz & Plotkin 2001, sections 10.2.1–10.2.2
//! for the 2D panel potentials and velocities, 11.4.2 for the
//! source/doublet Dirichlet method), and the panel geometry of a contour.
//!
//! Panel from `a` to `b`, length `L`, local coordinates of the field point
//! `(x, y)` (x along `a -> b`, y to its left), `r1 = |p - a|`,
//! `r2 = |p - b|`, `beta` the angle from `a - p` to `b - p` (in (-pi, pi],
//! `+pi` just left of the panel, `-pi` just right of it):
//! - unit doublet (jump `phi_left - phi_right = 1`): `phi = beta / (2 pi)`,
//!   velocity that of point vortices `+1` at `b`, `-1` at `a` (ccw);
//! - unit source (`(1/2pi) int ln r ds`):
//!   `phi = [x ln r1 - (x - L) ln r2 - L + y beta] / (2 pi)`, velocity
//!   `(ln(r1/r2), beta) / (2 pi)` in the panel's axes.

use std::f64::consts::PI;

use faer::linalg::solvers::{PartialPivLu, Solve};
use faer::Mat;

use super::shape::V2;

#[inline]
pub(super) fn sub(a: V2, b: V2) -> V2 {
    [a[0] - b[0], a[1] - b[1]]
}

#[inline]
pub(super) fn dot(a: V2, b: V2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

#[inline]
fn cross(a: V2, b: V2) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

/// The angle from `u` to `v`, ccw positive, in (-pi, pi].
#[inline]
pub(super) fn angle(u: V2, v: V2) -> f64 {
    cross(u, v).atan2(dot(u, v))
}

/// Potential at `p` of a unit doublet panel `a -> b` (`beta / 2 pi`).
#[inline]
pub(super) fn doublet_potential(a: V2, b: V2, p: V2) -> f64 {
    angle(sub(a, p), sub(b, p)) / (2.0 * PI)
}

/// Potential at `p` of a unit source panel `a -> b`.
pub(super) fn source_potential(a: V2, b: V2, p: V2) -> f64 {
    let d = sub(b, a);
    let length = dot(d, d).sqrt();
    let t = [d[0] / length, d[1] / length];
    let rel = sub(p, a);
    let (x, y) = (dot(rel, t), cross(t, rel));
    let (r1, r2) = (dot(rel, rel).sqrt(), sub(p, b));
    let r2 = dot(r2, r2).sqrt();
    let term = |u: f64, r: f64| if r > 0.0 { u * r.ln() } else { 0.0 };
    let beta = angle(sub(a, p), sub(b, p));
    (term(x, r1) - term(x - length, r2) - length + y * beta) / (2.0 * PI)
}

/// Velocity at `p` of a source panel `a -> b` of total strength `q = sigma L`:
/// the exact panel formula within four panel lengths, a point source at the
/// midpoint beyond (relative error below `(L/r)^2 / 12`, 0.5%).
pub(super) fn source_velocity(a: V2, b: V2, sigma: f64, p: V2) -> V2 {
    let d = sub(b, a);
    let length2 = dot(d, d);
    let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
    let rm = sub(p, mid);
    let rm2 = dot(rm, rm);
    if rm2 > 16.0 * length2 {
        let k = sigma * length2.sqrt() / (2.0 * PI * rm2);
        return [k * rm[0], k * rm[1]];
    }
    let length = length2.sqrt();
    let t = [d[0] / length, d[1] / length];
    let (ra, rb) = (sub(p, a), sub(p, b));
    let (r1, r2) = (dot(ra, ra), dot(rb, rb));
    if r1 == 0.0 || r2 == 0.0 {
        return [0.0, 0.0];
    }
    let u = 0.5 * (r1 / r2).ln() * sigma / (2.0 * PI);
    let v = angle(sub(a, p), sub(b, p)) * sigma / (2.0 * PI);
    [u * t[0] - v * t[1], u * t[1] + v * t[0]]
}

/// Weights of the derivative at `x` of the quadratic through `(s_k, f_k)`.
fn lagrange_derivative(s: [f64; 3], x: f64) -> [f64; 3] {
    [
        ((x - s[1]) + (x - s[2])) / ((s[0] - s[1]) * (s[0] - s[2])),
        ((x - s[0]) + (x - s[2])) / ((s[1] - s[0]) * (s[1] - s[2])),
        ((x - s[0]) + (x - s[1])) / ((s[2] - s[0]) * (s[2] - s[1])),
    ]
}

/// Panel geometry of a contour (in whatever frame the vertices are in).
#[derive(Clone, Debug)]
pub(super) struct Outline {
    /// Vertices; panel `i` runs from vertex `i` to `i + 1` (cyclic).
    pub vertices: Vec<V2>,
    /// Panel midpoints (the collocation points).
    pub mid: Vec<V2>,
    /// Unit tangents, in the clockwise direction of travel.
    pub tangent: Vec<V2>,
    /// Unit outward normals (left of the tangent).
    pub normal: Vec<V2>,
    /// Panel lengths.
    pub length: Vec<f64>,
    /// Index of the upper trailing-edge panel (the lower one is 0).
    pub upper: usize,
    /// Where the wake leaves: the trailing-edge vertex.
    pub root: V2,
    /// Unit bisector of the trailing edge, pointing downstream.
    pub bisector: V2,
}

impl Outline {
    pub fn new(vertices: Vec<V2>) -> Self {
        let m = vertices.len();
        let mut mid = Vec::with_capacity(m);
        let mut tangent = Vec::with_capacity(m);
        let mut normal = Vec::with_capacity(m);
        let mut length = Vec::with_capacity(m);
        for i in 0..m {
            let (a, b) = (vertices[i], vertices[(i + 1) % m]);
            let d = sub(b, a);
            let l = dot(d, d).sqrt();
            mid.push([0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]);
            tangent.push([d[0] / l, d[1] / l]);
            normal.push([-d[1] / l, d[0] / l]);
            length.push(l);
        }
        let upper = m - 1;
        let root = vertices[0];
        // Downstream along the lower and the upper trailing-edge panels;
        // for an edge of 180 degrees or near it (a split blunt base), the
        // mean outward normal.
        let (dl, du) = (tangent[0], tangent[upper]);
        let along = [du[0] - dl[0], du[1] - dl[1]];
        let across = [
            normal[0][0] + normal[upper][0],
            normal[0][1] + normal[upper][1],
        ];
        let sum = if dot(along, along) > 0.01 {
            along
        } else {
            across
        };
        let norm = dot(sum, sum).sqrt();
        let bisector = if norm > 1e-12 {
            [sum[0] / norm, sum[1] / norm]
        } else {
            [1.0, 0.0]
        };
        Self {
            vertices,
            mid,
            tangent,
            normal,
            length,
            upper,
            root,
            bisector,
        }
    }

    /// The Kutta condition as weights on the doublets:
    /// `mu_W = sum w_k mu_k`, the upper minus the lower surface potential
    /// at the trailing edge, each extrapolated linearly from the two
    /// collocation points nearest the edge.
    pub fn kutta(&self) -> [(usize, f64); 4] {
        let (l0, l1) = (self.length[0], self.length[1]);
        let (u0, u1) = (self.length[self.upper], self.length[self.upper - 1]);
        let fl = l0 / (l0 + l1);
        let fu = u0 / (u0 + u1);
        [
            (self.upper, 1.0 + fu),
            (self.upper - 1, -fu),
            (0, -(1.0 + fl)),
            (1, fl),
        ]
    }

    /// Number of panels.
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Stencils of the surface derivative `d mu / ds` (clockwise arc
    /// length) at each collocation point: three-point Lagrange on the arc
    /// positions of the collocation points, central inside, one-sided at
    /// the trailing-edge panels (never across the edge, where the potential
    /// jumps).
    pub fn derivative_stencils(&self) -> Vec<([usize; 3], [f64; 3])> {
        let last = self.upper;
        let mut s = vec![0.0; last + 1];
        for i in 1..=last {
            s[i] = s[i - 1] + 0.5 * (self.length[i - 1] + self.length[i]);
        }
        (0..=last)
            .map(|i| {
                let k = i.clamp(1, last - 1);
                let idx = [k - 1, k, k + 1];
                (idx, lagrange_derivative(idx.map(|j| s[j]), s[i]))
            })
            .collect()
    }
}

/// The Dirichlet system of a contour (body frame): the doublet matrix
/// `C_ij` (potential at collocation point i, just inside, of unit doublet
/// panel j; `C_ii = -1/2`), factored, and the source matrix `B_ij`.
pub(super) struct Matrices {
    pub doublet: PartialPivLu<f64>,
    /// Row-major `m x m`.
    pub source: Vec<f64>,
}

impl Matrices {
    pub fn new(outline: &Outline) -> Self {
        let m = outline.len();
        let v = &outline.vertices;
        let c = Mat::from_fn(m, m, |i, j| {
            if i == j {
                -0.5
            } else {
                doublet_potential(v[j], v[(j + 1) % m], outline.mid[i])
            }
        });
        let mut source = vec![0.0; m * m];
        for (i, row) in source.chunks_exact_mut(m).enumerate() {
            for (j, b) in row.iter_mut().enumerate() {
                *b = source_potential(v[j], v[(j + 1) % m], outline.mid[i]);
            }
        }
        Self {
            doublet: c.partial_piv_lu(),
            source,
        }
    }

    /// Whether the factored `C` is usable (a solve gives finite values).
    pub fn is_regular(&self) -> bool {
        let m = self.source.len().isqrt();
        let mut x = Mat::from_fn(m, 1, |i, _| 1.0 + i as f64 / m as f64);
        self.doublet.solve_in_place(x.as_mut());
        (0..m).all(|i| x[(i, 0)].is_finite())
    }

    /// Solves `(C + w v^T) mu = rhs`, `v^T mu = sum_k c_k mu_k` the Kutta
    /// condition's `mu_W` ([`Outline::kutta`]; the wake's doublet enters the
    /// equations through the column `w`), by Sherman–Morrison on the
    /// factored `C`: two back-substitutions.
    pub fn solve(&self, rhs: &[f64], w: &[f64], kutta: &[(usize, f64)]) -> Vec<f64> {
        let m = rhs.len();
        let mut x = Mat::from_fn(m, 2, |i, j| if j == 0 { rhs[i] } else { w[i] });
        self.doublet.solve_in_place(x.as_mut());
        let vy: f64 = kutta.iter().map(|&(k, c)| c * x[(k, 0)]).sum();
        let vz: f64 = kutta.iter().map(|&(k, c)| c * x[(k, 1)]).sum();
        let f = vy / (1.0 + vz);
        (0..m).map(|i| x[(i, 0)] - f * x[(i, 1)]).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The doublet panel jumps by 1 across itself (left minus right), the
    /// source panel's velocity is the gradient of its potential. and the
    /// expansion of a far chain equals the direct sum.
    #[test]
    fn kernels_are_consistent() {
        let (a, b) = ([0.1, 0.2], [0.4, 0.3]);
        let on = [0.25, 0.25];
        let n = [-0.1 / 0.1f64.hypot(0.3), 0.3 / 0.1f64.hypot(0.3)];
        let e = 1e-9;
        let left = doublet_potential(a, b, [on[0] + e * n[0], on[1] + e * n[1]]);
        let right = doublet_potential(a, b, [on[0] - e * n[0], on[1] - e * n[1]]);
        assert!((left - right - 1.0).abs() < 1e-6);
        for p in [[0.7, -0.4], [0.2, 0.26], [0.25, 0.15], [3.0, 2.0]] {
            let h = 1e-6;
            let gx = (source_potential(a, b, [p[0] + h, p[1]])
                - source_potential(a, b, [p[0] - h, p[1]]))
                / (2.0 * h);
            let gy = (source_potential(a, b, [p[0], p[1] + h])
                - source_potential(a, b, [p[0], p[1] - h]))
                / (2.0 * h);
            let v = source_velocity(a, b, 1.0, p);
            let tol = if p[0] > 1.0 {
                2e-3 * gx.hypot(gy)
            } else {
                1e-7
            };
            assert!(
                (v[0] - gx).abs() < tol && (v[1] - gy).abs() < tol,
                "{p:?} {v:?} {gx} {gy}"
            );
        }
    }
}
