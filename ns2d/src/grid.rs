//! The O-grid: the conformal image of a stretched polar grid.
//!
//! Nodes sit at `ζ = exp(ξ_j + iθ_k)`, `θ_k = 2πk/N_θ`, with the radial
//! coordinate `ξ = g(η)` of a uniform `η ∈ [0, 1]` ([`RadialStretch`]):
//! `ξ_0 = 0` is the wall, `ξ_N = ln(R_out/|a|)` the outer boundary. The map
//! is conformal, so each cell is a rectangle in the physical plane, and the
//! only metric the equations need is `J = |∂z/∂ξ|²` (the cell's area per
//! `dξ dθ`) with `g'` and `g''/g'` of the stretching.

use realfft::num_complex::Complex64;

use crate::error::NsError;
use crate::section_map::SectionMap;

/// `ξ = g(η) = A (exp(sη) - 1)`: exponential growth of the radial cells
/// from a given first cell at the wall to a given outer radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RadialStretch {
    amplitude: f64,
    rate: f64,
}

impl RadialStretch {
    /// The stretching with `g(1) = xi_max` and a first cell of `first_cell`
    /// in `ξ` on `cells` uniform `η` intervals (Newton on
    /// `(e^s - 1)/s = xi_max cells / first_cell`).
    ///
    /// # Errors
    /// [`NsError::NoStretching`] when the first cell is not finer than a
    /// uniform grid's.
    pub fn new(xi_max: f64, first_cell: f64, cells: usize) -> Result<Self, NsError> {
        let uniform = xi_max / cells as f64;
        let ratio = uniform / first_cell;
        if ratio.is_nan() || ratio <= 1.0 + 1e-9 {
            return Err(NsError::NoStretching {
                first: first_cell,
                uniform,
            });
        }
        // f(s) = (e^s - 1)/s - ratio is convex and increasing for s > 0.
        let mut s = 2.0 * ratio.ln().max(0.1);
        for _ in 0..100 {
            let e = s.exp();
            let f = (e - 1.0) / s - ratio;
            let df = (s * e - (e - 1.0)) / (s * s);
            let next = s - f / df;
            let next = if next <= 0.0 { 0.5 * s } else { next };
            if (next - s).abs() < 1e-14 * s {
                s = next;
                break;
            }
            s = next;
        }
        Ok(Self {
            amplitude: xi_max / s.exp_m1(),
            rate: s,
        })
    }

    /// `g(η)`.
    #[must_use]
    pub fn xi(&self, eta: f64) -> f64 {
        self.amplitude * (self.rate * eta).exp_m1()
    }

    /// `g'(η)`.
    #[must_use]
    pub fn slope(&self, eta: f64) -> f64 {
        self.amplitude * self.rate * (self.rate * eta).exp()
    }

    /// `g''(η)/g'(η)` (a constant for the exponential).
    #[must_use]
    pub fn curvature(&self) -> f64 {
        self.rate
    }
}

/// Resolution of an [`OGrid`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridSpec {
    /// Nodes around the section (even; a power of two is fastest).
    pub around: usize,
    /// Radial nodes, wall and outer boundary included.
    pub radial: usize,
    /// The outer boundary's radius over the map scale `|a|` (about the
    /// section's half-length).
    pub outer_radius: f64,
    /// The first radial cell at the wall, in `ξ` (physical height about
    /// this times the local `|∂z/∂ξ|`).
    pub first_cell: f64,
}

/// The nodes and metrics of the O-grid (module docs).
#[derive(Debug, Clone)]
pub struct OGrid {
    /// Nodes around (`N_θ`).
    pub nt: usize,
    /// Radial nodes (`N_η + 1`).
    pub nr: usize,
    /// `Δη`.
    pub d_eta: f64,
    /// `Δθ`.
    pub d_theta: f64,
    /// `ξ_j`.
    pub xi: Vec<f64>,
    /// `g'(η_j)`.
    pub slope: Vec<f64>,
    /// `g''/g'`.
    pub curvature: f64,
    /// Physical node positions `z` (row-major, radial index outer).
    pub z: Vec<Complex64>,
    /// `∂z/∂ξ` at the nodes (`∂z/∂θ = i ∂z/∂ξ`).
    pub dz_dxi: Vec<Complex64>,
    /// `J = |∂z/∂ξ|²`.
    pub jac: Vec<f64>,
    /// `1/J`.
    pub inv_jac: Vec<f64>,
}

impl OGrid {
    /// The grid of `spec` around the section of `map`.
    ///
    /// # Errors
    /// [`NsError::BadGrid`] for a resolution out of range,
    /// [`NsError::NoStretching`] for a first cell no finer than uniform.
    pub fn new(map: &SectionMap, spec: GridSpec) -> Result<Self, NsError> {
        let checks = [
            ("around", spec.around as f64, 16.0, 8192.0),
            ("radial", spec.radial as f64, 8.0, 8192.0),
            ("outer_radius", spec.outer_radius, 2.0, 1e4),
            ("first_cell", spec.first_cell, 1e-6, 1.0),
        ];
        for (what, value, min, max) in checks {
            if !(value >= min && value <= max) {
                return Err(NsError::BadGrid {
                    what,
                    value,
                    min,
                    max,
                });
            }
        }
        if spec.around % 2 != 0 {
            return Err(NsError::BadGrid {
                what: "around (must be even)",
                value: spec.around as f64,
                min: 16.0,
                max: 8192.0,
            });
        }
        let (nt, nr) = (spec.around, spec.radial);
        let stretch = RadialStretch::new(spec.outer_radius.ln(), spec.first_cell, nr - 1)?;
        let d_eta = 1.0 / (nr - 1) as f64;
        let d_theta = std::f64::consts::TAU / nt as f64;
        let xi: Vec<f64> = (0..nr).map(|j| stretch.xi(j as f64 * d_eta)).collect();
        let slope = (0..nr).map(|j| stretch.slope(j as f64 * d_eta)).collect();
        let mut z = Vec::with_capacity(nt * nr);
        let mut dz_dxi = Vec::with_capacity(nt * nr);
        for &x in &xi {
            for k in 0..nt {
                let zeta = Complex64::from_polar(x.exp(), k as f64 * d_theta);
                z.push(map.point(zeta));
                dz_dxi.push(map.radial_derivative(zeta));
            }
        }
        let jac: Vec<f64> = dz_dxi.iter().map(Complex64::norm_sqr).collect();
        let inv_jac = jac.iter().map(|j| 1.0 / j).collect();
        Ok(Self {
            nt,
            nr,
            d_eta,
            d_theta,
            xi,
            slope,
            curvature: stretch.curvature(),
            z,
            dz_dxi,
            jac,
            inv_jac,
        })
    }

    /// Index of node `(j, k)`: radial `j`, around `k`.
    #[must_use]
    pub fn at(&self, j: usize, k: usize) -> usize {
        j * self.nt + k
    }

    /// Number of nodes.
    #[must_use]
    pub fn len(&self) -> usize {
        self.nt * self.nr
    }

    /// Whether the grid has no nodes (never, for a built grid).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stretching_meets_its_ends() {
        let s = RadialStretch::new(4.6, 0.002, 200).unwrap();
        assert!(s.xi(0.0).abs() < 1e-15);
        assert!((s.xi(1.0) - 4.6).abs() < 1e-12);
        assert!((s.slope(0.0) / 200.0 - 0.002).abs() < 1e-12);
    }

    #[test]
    fn a_first_cell_coarser_than_uniform_is_refused() {
        assert!(matches!(
            RadialStretch::new(1.0, 0.1, 100),
            Err(NsError::NoStretching { .. })
        ));
    }
}
