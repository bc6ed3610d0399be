//! Linear static SIMP topology optimization of the carbon design layer over
//! many load cases (step 3 of ESLSO): minimize the sum of the strain
//! energies (compliances) of all load cases under a mass constraint on the
//! design layer, with the density filter of [`super::filter`] and the
//! optimality-criteria update (Andreassen et al. 2011, "top88", eqs. 2–5
//! and the OC bisection; Bendsøe & Sigmund 2003, §1.2).
//!
//! An element's section is the mylar skin plus the carbon layer with
//! stiffness `rho^p` and mass `rho` ([`Section::two_layer`]); the element
//! stiffness is linear in the section, so `dK_e/drho = p rho^(p-1)
//! K_carbon,e` and the sensitivity of `C = sum_l f_l . u_l` is `-2 p
//! rho^(p-1) sum_l U_carbon,e(u_l)` with `U_carbon,e` the strain energy of
//! the element's carbon layer alone. One factorization an iteration serves
//! every load case: the skin's stiffness is assembled once and each
//! iteration adds the carbon element matrices scaled by `rho^p`, straight
//! into the nested-dissection order of the structure's ordered path
//! ([`crate::shell::structure::OrderedFactor`]).
//!
//! The mass constraint is linear in the design variables through the
//! filter, `m(x) = w . x` (see [`optimize`]), so the OC bisection tests each
//! trial multiplier with one dot product instead of filtering the trial
//! design.

use serde::{Deserialize, Serialize};

use faer::linalg::matmul::matmul;
use faer::{Accum, MatMut, MatRef, Par};
use rayon::prelude::*;

use crate::shell::assembly::{element_dofs, AssemblyError};
use crate::shell::element::{self, ElementMatrix};
use crate::shell::material::{Layer, Section};
use crate::shell::mesh::ShellMesh;
use crate::shell::structure::{OrderedFactor, Structure};

use super::filter::DensityFilter;

/// Settings of the optimization.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SimpSettings {
    /// SIMP penalty `p` (seed paper: 3).
    pub penalty: f64,
    /// Carbon mass allowed, as a fraction of the full design layer's.
    pub mass_fraction: f64,
    /// Density filter radius, m.
    pub filter_radius: f64,
    /// Largest change of a design variable in one iteration.
    pub move_limit: f64,
    /// Iterations allowed.
    pub max_iterations: usize,
    /// Stop when no design variable changes by more than this.
    pub tolerance: f64,
}

impl Default for SimpSettings {
    /// Penalty 3, 30% mass, 5 mm filter, move 0.2, 100 iterations, 0.01.
    fn default() -> Self {
        Self {
            penalty: 3.0,
            mass_fraction: 0.3,
            filter_radius: 0.005,
            move_limit: 0.2,
            max_iterations: 100,
            tolerance: 0.01,
        }
    }
}

/// One iteration's record.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SimpIteration {
    /// Sum of the load cases' compliances `f . u`, J.
    pub objective: f64,
    /// Carbon mass over the full design layer's.
    pub mass_fraction: f64,
    /// Largest change of a design variable.
    pub change: f64,
}

/// The outcome.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SimpResult {
    /// Physical (filtered) densities per element.
    pub densities: Vec<f64>,
    /// The design variables (before the filter) per element: where a
    /// later run may start ([`optimize_from`]).
    pub design_variables: Vec<f64>,
    /// Every iteration.
    pub history: Vec<SimpIteration>,
    /// Whether the change fell below the tolerance.
    pub converged: bool,
}

/// Why the optimization stopped.
#[derive(Debug, thiserror::Error)]
pub enum SimpError {
    /// Assembly, factorization or a length mismatch.
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// A setting out of range.
    #[error("SIMP setting: {0}")]
    Setting(String),
}

/// Minimizes the summed compliance of `loads` (global 6-DOF vectors, N) on
/// `mesh` with `fixed` DOFs held, over the carbon densities of the elements
/// flagged in `design` (the others stay full carbon), starting from the
/// uniform design at the mass fraction.
pub fn optimize(
    mesh: &ShellMesh,
    fixed: &[usize],
    design: &[bool],
    carbon: &Layer,
    skin: &Layer,
    loads: &[Vec<f64>],
    settings: &SimpSettings,
) -> Result<SimpResult, SimpError> {
    optimize_from(mesh, fixed, design, carbon, skin, loads, settings, None)
}

/// [`optimize`] from the design variables `start` (one per element in
/// [0, 1], e.g. [`SimpResult::design_variables`] of an earlier run on
/// related loads; `None`: uniform at the mass fraction).
#[allow(clippy::too_many_arguments)]
pub fn optimize_from(
    mesh: &ShellMesh,
    fixed: &[usize],
    design: &[bool],
    carbon: &Layer,
    skin: &Layer,
    loads: &[Vec<f64>],
    settings: &SimpSettings,
    start: Option<&[f64]>,
) -> Result<SimpResult, SimpError> {
    let s = settings;
    if let Some(x) = start {
        if x.len() != mesh.elements.len() || x.iter().any(|v| !(0.0..=1.0).contains(v)) {
            return Err(SimpError::Setting(format!(
                "{} start values in [0, 1] needed for {} elements",
                x.len(),
                mesh.elements.len()
            )));
        }
    }
    let ok = s.penalty >= 1.0
        && s.mass_fraction > 0.0
        && s.mass_fraction <= 1.0
        && s.filter_radius > 0.0
        && s.move_limit > 0.0
        && s.move_limit <= 1.0
        && s.tolerance > 0.0;
    if !ok || design.len() != mesh.elements.len() || loads.is_empty() {
        return Err(SimpError::Setting(format!(
            "{s:?} with {} design flags for {} elements and {} load cases",
            design.len(),
            mesh.elements.len(),
            loads.len()
        )));
    }
    let n = mesh.elements.len();
    let area: Vec<f64> = (0..n).map(|e| mesh.element_area(e)).collect();
    let design_area: f64 = (0..n).filter(|&e| design[e]).map(|e| area[e]).sum();
    let filter = DensityFilter::new(mesh, s.filter_radius);
    let structure = Structure::new(mesh, fixed)?;
    // The carbon layer's element stiffnesses do not change: computed once
    // (24 x 24 each), they give every load case's carbon strain energy.
    let carbon_section = Section::single(carbon);
    let carbon_k: Vec<ElementMatrix> = (0..n)
        .into_par_iter()
        .map(|e| element::stiffness(&mesh.corners(e), &carbon_section))
        .collect();
    // The element stiffness is linear in the section: skin plus rho^p
    // carbon. The skin's part of the global stiffness is assembled once;
    // each iteration adds the carbon matrices scaled by rho^p.
    let skin_section = Section::single(skin);
    let skin_k: Vec<ElementMatrix> = (0..n)
        .into_par_iter()
        .map(|e| element::stiffness(&mesh.corners(e), &skin_section))
        .collect();
    let skin_stiffness =
        structure.assemble_ordered(&structure.ordered_layer(&skin_k)?, &vec![1.0; n], None)?;
    drop(skin_k);
    let carbon_layer = structure.ordered_layer(&carbon_k)?;
    let dofs: Vec<[usize; 24]> = (0..n).map(|e| element_dofs(mesh, e)).collect();
    let fix = |rho: &mut [f64]| {
        for (r, &d) in rho.iter_mut().zip(design) {
            if !d {
                *r = 1.0;
            }
        }
    };
    let mass = |rho: &[f64]| {
        (0..n)
            .filter(|&e| design[e])
            .map(|e| rho[e] * area[e])
            .sum::<f64>()
            / design_area
    };
    // The mass counts the filtered densities of the design elements only:
    // `m(x) = sum_{e in design} a_e (H x)_e / A = w . x / A` with
    // `w = H^T (a masked to the design elements)`, linear in the design
    // variables. `w` is both the mass of a trial design in the bisection
    // (exactly the filtered mass, without filtering every trial) and the
    // mass sensitivity. (Bug fix: the sensitivity used to be `H^T a` with
    // the area of every element, the non-design spar included, although
    // the constrained mass leaves the spar out.)
    let design_area_of: Vec<f64> = (0..n)
        .map(|e| if design[e] { area[e] } else { 0.0 })
        .collect();
    let d_mass = filter.back(&design_area_of);
    let mass_of_design =
        |x: &[f64]| x.iter().zip(&d_mass).map(|(x, w)| x * w).sum::<f64>() / design_area;
    let cases = loads.len();
    // Non-design elements (the spar) are carbon: their design variables
    // sit at 1 so that the filter does not average a lighter spar into
    // their neighbours' densities.
    let mut x: Vec<f64> = design
        .iter()
        .enumerate()
        .map(|(e, &d)| match (d, start) {
            (false, _) => 1.0,
            (true, Some(x)) => x[e],
            (true, None) => s.mass_fraction,
        })
        .collect();
    let mut history = Vec::new();
    let mut converged = false;
    let mut factor: Option<OrderedFactor> = None;
    for _ in 0..s.max_iterations {
        let mut rho = filter.apply(&x);
        fix(&mut rho);
        let scales: Vec<f64> = rho.iter().map(|r| r.powf(s.penalty)).collect();
        let stiffness =
            structure.assemble_ordered(&carbon_layer, &scales, Some(&skin_stiffness))?;
        let factor = match factor.as_mut() {
            Some(factor) => {
                factor.refactorize(&stiffness)?;
                factor
            }
            None => factor.insert(OrderedFactor::new(&structure, &stiffness)?),
        };
        drop(stiffness);
        // Interleaved: u[d * cases + l], DOF d of load case l.
        let u = factor.solve(loads)?;
        let objective: f64 = loads
            .iter()
            .enumerate()
            .map(|(l, f)| {
                f.iter()
                    .enumerate()
                    .map(|(d, f)| f * u[d * cases + l])
                    .sum::<f64>()
            })
            .sum();
        // dC/drho_e = -p rho^(p-1) sum_l u_l,e . K_carbon,e u_l,e (twice the
        // carbon strain energy): with U_e the element's displacements in
        // every load case (24 x cases), the sum of U_e o (K_carbon,e U_e),
        // one small matrix product an element (faer's SIMD kernels).
        let d_rho: Vec<f64> = (0..n)
            .into_par_iter()
            .map_init(
                || (vec![0.0; 24 * cases], vec![0.0; 24 * cases]),
                |(ue, product), e| {
                    if !design[e] {
                        return 0.0;
                    }
                    for (row, &g) in ue.chunks_exact_mut(cases).zip(&dofs[e]) {
                        row.copy_from_slice(&u[g * cases..(g + 1) * cases]);
                    }
                    matmul(
                        MatMut::from_row_major_slice_mut(product, 24, cases),
                        Accum::Replace,
                        MatRef::from_column_major_slice(carbon_k[e].as_slice(), 24, 24),
                        MatRef::from_row_major_slice(ue, 24, cases),
                        1.0,
                        Par::Seq,
                    );
                    let energy: f64 = ue.iter().zip(product.iter()).map(|(u, p)| u * p).sum();
                    -s.penalty * rho[e].powf(s.penalty - 1.0) * energy
                },
            )
            .collect();
        let d_x = filter.back(&d_rho);
        // Optimality criteria: bisection on the multiplier of the mass.
        let (mut low, mut high) = (0.0f64, 1e12f64);
        let mut next = x.clone();
        while (high - low) / (high + low).max(1e-300) > 1e-6 {
            let mid = 0.5 * (low + high);
            for e in 0..n {
                if !design[e] {
                    continue;
                }
                let scale = (-d_x[e] / (mid * d_mass[e])).max(0.0).sqrt();
                next[e] = (x[e] * scale)
                    .clamp(x[e] - s.move_limit, x[e] + s.move_limit)
                    .clamp(0.0, 1.0);
            }
            if mass_of_design(&next) > s.mass_fraction {
                low = mid;
            } else {
                high = mid;
            }
        }
        let change = (0..n)
            .map(|e| (next[e] - x[e]).abs())
            .fold(0.0f64, f64::max);
        history.push(SimpIteration {
            objective,
            mass_fraction: mass(&rho),
            change,
        });
        x = next;
        if change < s.tolerance {
            converged = true;
            break;
        }
    }
    let mut densities = filter.apply(&x);
    fix(&mut densities);
    Ok(SimpResult {
        densities,
        design_variables: x,
        history,
        converged,
    })
}
