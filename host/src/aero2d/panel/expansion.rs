//! The potential of the wake's doublet sheet on the section, summed fast
//! (a two-level local expansion; cf. Greengard & Rokhlin's fast multipole
//! method, J. Comput. Phys. 73, 1987, for the expansions and their shift).
//!
//! The sheet is a chain of constant doublet segments `a -> b` of strength
//! `M`, each of potential `M beta(p) / (2 pi)`, `beta` the angle from
//! `a - p` to `b - p`. About a centre `c` with all targets within `r`, a
//! segment farther than `2 r` has
//! `beta(p) = beta(c) + Im sum_m (u^m / m) [(a - c)^-m - (b - c)^-m]`,
//! `u = p - c`, converging like `2^-m` at worst; consecutive segments share
//! their ends, so the sum runs over vertices with weights `M_out - M_in`.
//! Level 0 expands the segments far from the whole section about its
//! centre, and is shifted exactly (Taylor shift of the polynomial) to the
//! centres of a few clusters of collocation points; segments nearer than
//! that are expanded about a cluster's centre when far enough from it, and
//! summed exactly (one `atan2` per target) only when close to the cluster.

use std::f64::consts::PI;

use super::influence::{angle, dot, sub};
use super::shape::V2;

/// Minimal complex arithmetic.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Complex {
    pub re: f64,
    pub im: f64,
}

impl Complex {
    pub fn new(re: f64, im: f64) -> Self {
        Self { re, im }
    }

    pub fn mul(self, o: Self) -> Self {
        Self::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }

    pub fn add(self, o: Self) -> Self {
        Self::new(self.re + o.re, self.im + o.im)
    }

    pub fn scale(self, s: f64) -> Self {
        Self::new(self.re * s, self.im * s)
    }

    pub fn inv(self) -> Self {
        let d = self.re * self.re + self.im * self.im;
        Self::new(self.re / d, -self.im / d)
    }
}

/// Highest power of the local expansions.
const TERMS: usize = 48;

/// Collocation points grouped for the expansion: indices, centre, radius.
#[derive(Clone, Debug)]
pub(super) struct Cluster {
    members: Vec<usize>,
    centre: V2,
    radius: f64,
}

/// Clusters of the points by `count` equal ranges of x (empty ones
/// dropped).
pub(super) fn clusters(points: &[V2], count: usize) -> Vec<Cluster> {
    let (lo, hi) = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p[0]), hi.max(p[0]))
        });
    let width = ((hi - lo) / count as f64).max(f64::MIN_POSITIVE);
    let mut members = vec![Vec::new(); count];
    for (i, p) in points.iter().enumerate() {
        let k = (((p[0] - lo) / width) as usize).min(count - 1);
        members[k].push(i);
    }
    members
        .into_iter()
        .filter(|m| !m.is_empty())
        .map(|members| {
            let (centre, radius) = centre_and_radius(members.iter().map(|&i| points[i]));
            Cluster {
                members,
                centre,
                radius,
            }
        })
        .collect()
}

/// Mean of the points and their largest distance from it.
fn centre_and_radius(points: impl Iterator<Item = V2> + Clone) -> (V2, f64) {
    let n = points.clone().count().max(1) as f64;
    let c = points
        .clone()
        .fold([0.0, 0.0], |a, p| [a[0] + p[0] / n, a[1] + p[1] / n]);
    let r = points
        .map(|p| {
            let d = sub(p, c);
            dot(d, d).sqrt()
        })
        .fold(0.0, f64::max);
    (c, r)
}

/// A local expansion `constant + Im sum_{m >= 0} coefficients[m] u^m`,
/// `u = p - centre` (the angle sum, before the factor `1 / (2 pi)`).
struct Local {
    centre: V2,
    radius: f64,
    constant: f64,
    coefficients: [Complex; TERMS + 1],
}

impl Local {
    fn new(centre: V2, radius: f64) -> Self {
        Self {
            centre,
            radius,
            constant: 0.0,
            coefficients: [Complex::default(); TERMS + 1],
        }
    }

    /// Whether segment `a -> b` is far enough (`2 radius`) to expand.
    fn admits(&self, a: V2, b: V2) -> bool {
        let ra = sub(a, self.centre);
        let d = sub(b, a);
        let along = (-dot(ra, d) / dot(d, d).max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
        let closest = [ra[0] + along * d[0], ra[1] + along * d[1]];
        dot(closest, closest) >= 4.0 * self.radius * self.radius
    }

    /// Adds the segments `k` (`points[k] -> points[k + 1]`, strength
    /// `strengths[k]`), given in increasing order.
    fn add(&mut self, segments: &[usize], points: &[V2], strengths: &[f64]) {
        let c = self.centre;
        // Vertices with their weights, shared ends merged.
        let mut vertices: Vec<(usize, f64)> = Vec::with_capacity(segments.len() + 1);
        for &k in segments {
            let m = strengths[k];
            let (a, b) = (sub(points[k], c), sub(points[k + 1], c));
            self.constant += m * angle(a, b);
            match vertices.last_mut() {
                Some(last) if last.0 == k => last.1 += m,
                _ => vertices.push((k, m)),
            }
            vertices.push((k + 1, -m));
        }
        // Per vertex: 1 / (v - c) and the terms it needs
        // (`(r / |v - c|)^m / m < 1e-16`).
        let items: Vec<(Complex, f64, usize)> = vertices
            .iter()
            .filter(|v| v.1 != 0.0)
            .map(|&(k, w)| {
                let d = sub(points[k], c);
                let ratio = self.radius / dot(d, d).sqrt();
                let terms = if ratio > 0.0 {
                    ((-16.0 * std::f64::consts::LN_10) / ratio.ln())
                        .ceil()
                        .clamp(1.0, TERMS as f64) as usize
                } else {
                    1
                };
                (Complex::new(d[0], d[1]).inv(), w, terms)
            })
            .collect();
        // In chunks of eight, powers outermost: independent products.
        for chunk in items.chunks(8) {
            let n = chunk.iter().map(|i| i.2).max().unwrap_or(0);
            let mut power = [Complex::default(); 8];
            for (p, item) in power.iter_mut().zip(chunk) {
                *p = item.0.scale(item.1);
            }
            for m in 1..=n {
                let f = 1.0 / m as f64;
                let mut sum = Complex::default();
                for (p, item) in power.iter_mut().zip(chunk) {
                    sum = sum.add(*p);
                    *p = p.mul(item.0);
                }
                self.coefficients[m] = self.coefficients[m].add(sum.scale(f));
            }
        }
    }

    /// The same expansion about `centre` (exact Taylor shift).
    fn shifted(&self, centre: V2, radius: f64) -> Self {
        let d = Complex::new(centre[0] - self.centre[0], centre[1] - self.centre[1]);
        let mut b = self.coefficients;
        for i in 0..TERMS {
            for j in (i..TERMS).rev() {
                b[j] = b[j].add(d.mul(b[j + 1]));
            }
        }
        Self {
            centre,
            radius,
            constant: self.constant,
            coefficients: b,
        }
    }

    fn at(&self, p: V2) -> f64 {
        let u = Complex::new(p[0] - self.centre[0], p[1] - self.centre[1]);
        let mut acc = Complex::default();
        for c in self.coefficients.iter().rev() {
            acc = acc.mul(u).add(*c);
        }
        self.constant + acc.im
    }
}

/// Potential at the `targets` (grouped in `clusters`) of the chain of
/// doublet segments `points[k] -> points[k + 1]` of strengths
/// `strengths[k]` (added into `out`).
pub(super) fn chain_potential(
    points: &[V2],
    strengths: &[f64],
    targets: &[V2],
    clusters: &[Cluster],
    out: &mut [f64],
) {
    let (centre, radius) = centre_and_radius(targets.iter().copied());
    let mut level0 = Local::new(centre, radius);
    let (far, near): (Vec<usize>, Vec<usize>) = (0..strengths.len())
        .filter(|&k| strengths[k] != 0.0)
        .partition(|&k| level0.admits(points[k], points[k + 1]));
    level0.add(&far, points, strengths);
    for cluster in clusters {
        let mut local = level0.shifted(cluster.centre, cluster.radius);
        let (expand, exact): (Vec<usize>, Vec<usize>) = near
            .iter()
            .partition(|&&k| local.admits(points[k], points[k + 1]));
        local.add(&expand, points, strengths);
        for &i in &cluster.members {
            let p = targets[i];
            let direct: f64 = exact
                .iter()
                .map(|&k| strengths[k] * angle(sub(points[k], p), sub(points[k + 1], p)))
                .sum();
            out[i] += (local.at(p) + direct) / (2.0 * PI);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aero2d::panel::influence::doublet_potential;

    /// The expansions equal the direct sum for a wake that starts close
    /// behind the section and winds away.
    #[test]
    fn chain_expansion_equals_the_direct_sum() {
        let targets: Vec<V2> = (0..40)
            .map(|k| {
                let t = 2.0 * PI * k as f64 / 40.0;
                [0.5 + 0.5 * t.cos(), 0.05 * t.sin()]
            })
            .collect();
        let points: Vec<V2> = (0..300)
            .map(|k| {
                let s = 0.02 * k as f64;
                [1.01 + s, 0.3 * (2.0 * s).sin()]
            })
            .collect();
        let strengths: Vec<f64> = (0..299).map(|k| (0.3 * k as f64).cos()).collect();
        for count in 1..=4 {
            let mut fast = vec![0.0; targets.len()];
            chain_potential(
                &points,
                &strengths,
                &targets,
                &clusters(&targets, count),
                &mut fast,
            );
            for (p, got) in targets.iter().zip(&fast) {
                let direct: f64 = points
                    .windows(2)
                    .zip(&strengths)
                    .map(|(w, s)| s * doublet_potential(w[0], w[1], *p))
                    .sum();
                assert!((got - direct).abs() < 1e-11, "{count}: {got} {direct}");
            }
        }
    }
}
