//! The density filter of SIMP topology optimization (Bruns & Tortorelli
//! 2001; Andreassen et al. 2011, "top88", eq. 9): each element's physical
//! density is the area- and distance-weighted mean of the design variables
//! within a radius, `rho_e = sum_i H_ei a_i x_i / sum_i H_ei a_i` with
//! `H_ei = max(0, r - |c_e - c_i|)`; the sensitivities go back through the
//! transpose. It sets a minimum member size and makes the layout
//! independent of the mesh.

use nalgebra::Vector3;
use rayon::prelude::*;

use crate::shell::mesh::ShellMesh;

/// Weights of the filter, row by row (sparse).
#[derive(Clone, Debug)]
pub struct DensityFilter {
    /// For each element, its neighbours and their weights `H_ei a_i`.
    rows: Vec<Vec<(usize, f64)>>,
    /// `sum_i H_ei a_i` per element.
    totals: Vec<f64>,
}

impl DensityFilter {
    /// The filter of radius `radius` (m, > 0) on `mesh`; neighbours are
    /// found through a grid of cells the size of the radius, so building it
    /// is linear in the element count (the rows in parallel).
    pub fn new(mesh: &ShellMesh, radius: f64) -> Self {
        let centres: Vec<Vector3<f64>> = (0..mesh.elements.len())
            .map(|e| mesh.corners(e).iter().sum::<Vector3<f64>>() / 4.0)
            .collect();
        let areas: Vec<f64> = (0..mesh.elements.len())
            .map(|e| mesh.element_area(e))
            .collect();
        let cell = |p: &Vector3<f64>| {
            (
                (p.x / radius).floor() as i64,
                (p.y / radius).floor() as i64,
                (p.z / radius).floor() as i64,
            )
        };
        let mut grid: std::collections::HashMap<(i64, i64, i64), Vec<usize>> =
            std::collections::HashMap::new();
        for (e, c) in centres.iter().enumerate() {
            grid.entry(cell(c)).or_default().push(e);
        }
        let rows: Vec<Vec<(usize, f64)>> = centres
            .par_iter()
            .map(|c| {
                let (i, j, k) = cell(c);
                let mut row = Vec::new();
                for di in -1..=1 {
                    for dj in -1..=1 {
                        for dk in -1..=1 {
                            for &n in grid.get(&(i + di, j + dj, k + dk)).into_iter().flatten() {
                                let w = radius - (centres[n] - c).norm();
                                if w > 0.0 {
                                    row.push((n, w * areas[n]));
                                }
                            }
                        }
                    }
                }
                row
            })
            .collect();
        let totals = rows
            .iter()
            .map(|r| r.iter().map(|(_, w)| w).sum())
            .collect();
        Self { rows, totals }
    }

    /// Physical densities of the design variables `x`.
    pub fn apply(&self, x: &[f64]) -> Vec<f64> {
        self.rows
            .iter()
            .zip(&self.totals)
            .map(|(row, total)| row.iter().map(|&(n, w)| w * x[n]).sum::<f64>() / total)
            .collect()
    }

    /// Sensitivities with respect to the design variables from those with
    /// respect to the physical densities (the transpose of [`Self::apply`]).
    pub fn back(&self, d_rho: &[f64]) -> Vec<f64> {
        let mut d_x = vec![0.0; d_rho.len()];
        for (e, row) in self.rows.iter().enumerate() {
            for &(n, w) in row {
                d_x[n] += w * d_rho[e] / self.totals[e];
            }
        }
        d_x
    }
}
