//! The O-grid: the conformal image of a stretched polar grid.
//!
//! Nodes sit at `ζ = exp(ξ_j + iθ_k)`, `θ_k = 2πk/N_θ`, with the radial
//! coordinate `ξ = g(η)` of a uniform `η ∈ [0, 1]` ([`RingSpacing`]):
//! `ξ_0 = 0` is the wall, `ξ_N = ln(R_out/|a|)` the outer boundary. The map
//! is conformal, so each cell is a rectangle in the physical plane, and the
//! only metric the equations need is `J = |∂z/∂ξ|²` (the cell's area per
//! `dξ dθ`) with `g'` and `g''/g'` of the stretching.

use realfft::num_complex::Complex64;

use crate::error::NsError;
use crate::section_map::SectionMap;
use crate::stretch::{FarStretch, RingSpacing};

/// The nodes round a grid may have ([`GridSpec::around`]; even too).
pub const AROUND: std::ops::RangeInclusive<usize> = 16..=8192;
/// The nodes from the wall out a grid may have ([`GridSpec::radial`]).
pub const RADIAL: std::ops::RangeInclusive<usize> = 8..=8192;

/// Checks a grid's nodes round: even and in [`AROUND`].
///
/// # Errors
/// [`NsError::BadGrid`] outside the range, [`NsError::OddAround`] for an
/// odd count within it.
pub fn check_around(around: usize) -> Result<(), NsError> {
    if !AROUND.contains(&around) {
        return Err(NsError::BadGrid {
            what: "around",
            value: around as f64,
            min: *AROUND.start() as f64,
            max: *AROUND.end() as f64,
        });
    }
    if around % 2 != 0 {
        return Err(NsError::OddAround { around });
    }
    Ok(())
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
    /// The first radial cell at the wall, in `ξ`: the stretching's slope
    /// at the wall times `Δη`, `g'(0) Δη` (the first ring itself lies at
    /// `g(Δη)`, about half a cell's growth further out: 2.4 % on 48 cells
    /// out to 40 map radii); physical height about this times the local
    /// `|∂z/∂ξ|`. Halved with `Δη`, it keeps `g`: the finer grid's every
    /// other ring is the coarser's (`tests/deforming_sections.rs`,
    /// `the_grids_are_nested`).
    pub first_cell: f64,
    /// The far field coarsened ([`FarStretch`]), or `None` for the
    /// exponential stretching throughout ([`crate::RadialStretch`]).
    pub far: Option<FarStretch>,
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
    /// `g''/g'` at each ring.
    pub curvature: Vec<f64>,
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
        check_around(spec.around)?;
        let checks = [
            (
                "radial",
                spec.radial as f64,
                *RADIAL.start() as f64,
                *RADIAL.end() as f64,
            ),
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
        let (nt, nr) = (spec.around, spec.radial);
        let RingSpacing {
            xi,
            slope,
            curvature,
        } = RingSpacing::new(spec.outer_radius.ln(), spec.first_cell, nr, spec.far)?;
        let d_eta = 1.0 / (nr - 1) as f64;
        let d_theta = std::f64::consts::TAU / nt as f64;
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
            curvature,
            z,
            dz_dxi,
            jac,
            inv_jac,
        })
    }

    /// Ring `j`'s radial operator `∂ηη - (g''/g') ∂η` by central
    /// differences: the coefficients of the values at rings `j - 1` and
    /// `j + 1` (that of ring `j` is `-2/Δη²`). The one place the advection
    /// rates, the radial sweep and the streamfunction solve take them from.
    #[must_use]
    pub fn radial_neighbours(&self, j: usize) -> (f64, f64) {
        let h2 = 1.0 / (self.d_eta * self.d_eta);
        let half = self.curvature[j] / (2.0 * self.d_eta);
        (h2 + half, h2 - half)
    }

    /// Index of node `(j, k)`: radial `j`, around `k`.
    #[must_use]
    pub fn at(&self, j: usize, k: usize) -> usize {
        j * self.nt + k
    }

    /// The fluid's velocity at node `(j, k)` of the streamfunction `psi`
    /// (body axes): `u + iv = -i (ψ_ξ + i ψ_θ) / conj(∂z/∂ξ)`, `ψ_θ`
    /// central round the ring, `ψ_ξ = ψ_η / g'` central in the uniform
    /// radial coordinate `η` and one-sided (second order) on the wall and
    /// outer rings. Cost `O(1)`.
    #[must_use]
    pub fn velocity(&self, psi: &[f64], j: usize, k: usize) -> Complex64 {
        let (nt, nr) = (self.nt, self.nr);
        let at = |jj: usize, kk: usize| psi[self.at(jj, kk)];
        let psi_eta = if j == 0 {
            (-3.0 * at(0, k) + 4.0 * at(1, k) - at(2, k)) / (2.0 * self.d_eta)
        } else if j == nr - 1 {
            (3.0 * at(j, k) - 4.0 * at(j - 1, k) + at(j - 2, k)) / (2.0 * self.d_eta)
        } else {
            (at(j + 1, k) - at(j - 1, k)) / (2.0 * self.d_eta)
        };
        let psi_xi = psi_eta / self.slope[j];
        let (before, after) = ((k + nt - 1) % nt, (k + 1) % nt);
        let psi_theta = (at(j, after) - at(j, before)) / (2.0 * self.d_theta);
        -Complex64::new(0.0, 1.0) * Complex64::new(psi_xi, psi_theta)
            / self.dz_dxi[self.at(j, k)].conj()
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
