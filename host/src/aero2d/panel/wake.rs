//! The convection of the free wake (forward Euler), with the section's
//! singularities summed by a multipole expansion far from it.

use std::f64::consts::PI;

use super::expansion::Complex;
use super::influence::{dot, source_velocity, sub};
use super::shape::V2;
use crate::aero2d::ldvm::{induced, FreeVortex};

/// Far-wake vortices lumped together for induction on the near wake.
const FAR_GROUP: usize = 8;

/// The section's singularities as seen by the wake (global frame): source
/// panels (strength per unit length) and the doublet panels as vortices at
/// the vertices, with their multipole (outer) expansion about `centre`,
/// `u - i v = sum_m b_m / (z - c)^(m + 1)`,
/// `b_m = sum_k (q_k - i Gamma_k) (z_k - c)^m / (2 pi)` (sources as points
/// of total strength `q = sigma L` at the panel midpoints), used beyond
/// twice the section's radius, where it is accurate to 1e-12 relative.
pub(super) struct BodyField {
    panels: Vec<(V2, V2, f64)>,
    vortices: Vec<FreeVortex>,
    centre: V2,
    radius: f64,
    coefficients: Vec<Complex>,
}

/// Terms of the body's multipole expansion.
const BODY_TERMS: usize = 40;

impl BodyField {
    /// `panels`: `(a, b, sigma)`; `vortices`: the vertex vortices.
    pub fn new(panels: Vec<(V2, V2, f64)>, vortices: Vec<FreeVortex>) -> Self {
        let n = (panels.len() + vortices.len()).max(1) as f64;
        let centre = vortices
            .iter()
            .map(|v| [v.x, v.y])
            .chain(panels.iter().map(|p| p.0))
            .fold([0.0, 0.0], |c, p| [c[0] + p[0] / n, c[1] + p[1] / n]);
        let radius = vortices
            .iter()
            .map(|v| [v.x, v.y])
            .chain(panels.iter().flat_map(|p| [p.0, p.1]))
            .map(|p| {
                let d = sub(p, centre);
                dot(d, d).sqrt()
            })
            .fold(0.0, f64::max);
        let mut coefficients = vec![Complex::default(); BODY_TERMS];
        let elements = panels
            .iter()
            .map(|&(a, b, sigma)| {
                let d = sub(b, a);
                let q = sigma * dot(d, d).sqrt();
                (
                    [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])],
                    Complex::new(q, 0.0),
                )
            })
            .chain(
                vortices
                    .iter()
                    .map(|v| ([v.x, v.y], Complex::new(0.0, -v.gamma))),
            );
        let items: Vec<(Complex, Complex)> = elements
            .map(|(z, s)| {
                (
                    Complex::new(z[0] - centre[0], z[1] - centre[1]),
                    s.scale(1.0 / (2.0 * PI)),
                )
            })
            .collect();
        // In chunks of eight, powers outermost: independent products.
        for chunk in items.chunks(8) {
            let mut power = [Complex::default(); 8];
            for (p, item) in power.iter_mut().zip(chunk) {
                *p = item.1;
            }
            for c in coefficients.iter_mut() {
                let mut sum = Complex::default();
                for (p, item) in power.iter_mut().zip(chunk) {
                    sum = sum.add(*p);
                    *p = p.mul(item.0);
                }
                *c = c.add(sum);
            }
        }
        Self {
            panels,
            vortices,
            centre,
            radius,
            coefficients,
        }
    }

    /// Velocity induced at `p` (vortex cores of squared radius `core2`).
    pub fn velocity(&self, p: V2, core2: f64) -> V2 {
        let d = sub(p, self.centre);
        if dot(d, d) > 4.0 * self.radius * self.radius {
            let inv = Complex::new(d[0], d[1]).inv();
            // sum_m b_m inv^(m + 1), by Horner.
            let mut acc = Complex::default();
            for c in self.coefficients.iter().rev() {
                acc = acc.mul(inv);
                acc.re += c.re;
                acc.im += c.im;
            }
            let w = acc.mul(inv);
            return [w.re, -w.im];
        }
        let mut v = [0.0, 0.0];
        for q in &self.vortices {
            let (du, dv) = induced(q, p[0], p[1], core2);
            v[0] += du;
            v[1] += dv;
        }
        for &(a, b, sigma) in &self.panels {
            let s = source_velocity(a, b, sigma, p);
            v[0] += s[0];
            v[1] += s[1];
        }
        v
    }
}

/// Convects the free vortices over `dt` (forward Euler): those within
/// `limit` (an x position) with the local velocity (freestream, the
/// section, the near wake vortex by vortex, the far wake in groups of
/// [`FAR_GROUP`] at their |Gamma|-weighted centroids), those beyond it (a
/// prefix, as they are kept in shedding order) with the freestream.
pub(super) fn convect(wake: &mut [FreeVortex], body: &BodyField, limit: f64, dt: f64, core2: f64) {
    let near_from = wake.iter().position(|v| v.x <= limit).unwrap_or(wake.len());
    let proxies: Vec<FreeVortex> = wake[..near_from]
        .chunks(FAR_GROUP)
        .map(|group| {
            let weight = group
                .iter()
                .map(|v| v.gamma.abs())
                .sum::<f64>()
                .max(f64::MIN_POSITIVE);
            FreeVortex {
                x: group.iter().map(|v| v.x * v.gamma.abs()).sum::<f64>() / weight,
                y: group.iter().map(|v| v.y * v.gamma.abs()).sum::<f64>() / weight,
                gamma: group.iter().map(|v| v.gamma).sum(),
            }
        })
        .collect();
    let near = &wake[near_from..];
    let mut velocity: Vec<V2> = near
        .iter()
        .map(|p| {
            let mut v = body.velocity([p.x, p.y], core2);
            v[0] += 1.0;
            for q in &proxies {
                let (du, dv) = induced(q, p.x, p.y, core2);
                v[0] += du;
                v[1] += dv;
            }
            v
        })
        .collect();
    // Near-wake pairs once each: the kernel is antisymmetric.
    for i in 0..near.len() {
        for j in i + 1..near.len() {
            let (a, b) = (&near[i], &near[j]);
            let (du, dv) = induced(&FreeVortex { gamma: 1.0, ..*b }, a.x, a.y, core2);
            velocity[i][0] += b.gamma * du;
            velocity[i][1] += b.gamma * dv;
            velocity[j][0] -= a.gamma * du;
            velocity[j][1] -= a.gamma * dv;
        }
    }
    for p in &mut wake[..near_from] {
        p.x += dt;
    }
    for (p, v) in wake[near_from..].iter_mut().zip(velocity) {
        p.x += v[0] * dt;
        p.y += v[1] * dt;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The body's multipole expansion equals the direct sum of its
    /// singularities.
    #[test]
    fn expansions_equal_direct_sums() {
        let panels: Vec<(V2, V2, f64)> = (0..40)
            .map(|k| {
                let (t0, t1) = (-0.157 * k as f64, -0.157 * (k + 1) as f64);
                (
                    [0.5 + 0.5 * t0.cos(), 0.06 * t0.sin()],
                    [0.5 + 0.5 * t1.cos(), 0.06 * t1.sin()],
                    (0.7 * k as f64).sin(),
                )
            })
            .collect();
        let vortices: Vec<FreeVortex> = panels
            .iter()
            .enumerate()
            .map(|(k, p)| FreeVortex {
                x: p.0[0],
                y: p.0[1],
                gamma: 0.01 * (k as f64).cos(),
            })
            .collect();
        let field = BodyField::new(panels.clone(), vortices.clone());
        for p in [[1.6, 0.1], [-1.0, -0.5], [0.5, 3.0]] {
            let v = field.velocity(p, 1e-4);
            let mut direct = [0.0, 0.0];
            for q in &vortices {
                let (du, dv) = induced(q, p[0], p[1], 0.0);
                direct = [direct[0] + du, direct[1] + dv];
            }
            for &(a, b, s) in &panels {
                let d = sub(b, a);
                let l = dot(d, d).sqrt();
                let m = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
                let r = sub(p, m);
                let k = s * l / (2.0 * PI * dot(r, r));
                direct = [direct[0] + k * r[0], direct[1] + k * r[1]];
            }
            assert!(
                (v[0] - direct[0]).abs() < 1e-12 && (v[1] - direct[1]).abs() < 1e-12,
                "{v:?} {direct:?}"
            );
        }
    }
}
