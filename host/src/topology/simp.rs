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
use crate::shell::structure::{OrderedFactor, OrderedLayer, OrderedStiffness, Structure};

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
    check(mesh, design, loads, settings, start)?;
    let problem = Problem::new(mesh, fixed, design, carbon, skin, loads, settings)?;
    let n = mesh.elements.len();
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
        let mut rho = problem.filter.apply(&x);
        problem.fix(&mut rho);
        let u = problem.displacements(&rho, &mut factor)?;
        let objective = problem.compliance(&u);
        let d_x = problem.filter.back(&problem.sensitivities(&rho, &u));
        let next = problem.optimality_criteria(&x, &d_x);
        let change = (0..n)
            .map(|e| (next[e] - x[e]).abs())
            .fold(0.0f64, f64::max);
        history.push(SimpIteration {
            objective,
            mass_fraction: problem.mass(&rho),
            change,
        });
        x = next;
        if change < s.tolerance {
            converged = true;
            break;
        }
    }
    let mut densities = problem.filter.apply(&x);
    problem.fix(&mut densities);
    Ok(SimpResult {
        densities,
        design_variables: x,
        history,
        converged,
    })
}

/// Checks the settings, the design flags, the load cases and the start
/// against the mesh.
fn check(
    mesh: &ShellMesh,
    design: &[bool],
    loads: &[Vec<f64>],
    s: &SimpSettings,
    start: Option<&[f64]>,
) -> Result<(), SimpError> {
    if let Some(x) = start {
        if x.len() != mesh.elements.len() || x.iter().any(|v| !(0.0..=1.0).contains(v)) {
            return Err(SimpError::Setting(format!(
                "{} start values in [0, 1] needed for {} elements",
                x.len(),
                mesh.elements.len()
            )));
        }
    }
    // (name, value, inside, range); written so that NaN is outside.
    let settings = [
        ("penalty", s.penalty, s.penalty >= 1.0, "[1, inf)"),
        (
            "mass_fraction",
            s.mass_fraction,
            s.mass_fraction > 0.0 && s.mass_fraction <= 1.0,
            "(0, 1]",
        ),
        (
            "filter_radius",
            s.filter_radius,
            s.filter_radius > 0.0,
            "(0, inf) m",
        ),
        (
            "move_limit",
            s.move_limit,
            s.move_limit > 0.0 && s.move_limit <= 1.0,
            "(0, 1]",
        ),
        ("tolerance", s.tolerance, s.tolerance > 0.0, "(0, inf)"),
    ];
    if let Some((name, value, _, range)) = settings.iter().find(|(_, _, inside, _)| !inside) {
        return Err(SimpError::Setting(format!(
            "{name} = {value} is outside {range}"
        )));
    }
    if design.len() != mesh.elements.len() || loads.is_empty() {
        return Err(SimpError::Setting(format!(
            "{} design flags for {} elements and {} load cases",
            design.len(),
            mesh.elements.len(),
            loads.len()
        )));
    }
    Ok(())
}

/// What stays fixed over the iterations: the filter, the structure with
/// the skin's stiffness and the carbon layer's element matrices, and the
/// mass's weights.
struct Problem<'a> {
    settings: &'a SimpSettings,
    design: &'a [bool],
    loads: &'a [Vec<f64>],
    /// Element areas, m².
    area: Vec<f64>,
    /// Total area of the design elements, m².
    design_area: f64,
    filter: DensityFilter,
    structure: Structure,
    /// The carbon layer's element stiffnesses (full density).
    carbon_k: Vec<ElementMatrix>,
    /// The same, packed for the ordered assembly.
    carbon_layer: OrderedLayer,
    /// The skin's part of the global stiffness.
    skin_stiffness: OrderedStiffness,
    /// Each element's global DOFs.
    dofs: Vec<[usize; element::DOFS]>,
    /// The mass's derivative by the design variables, times the design
    /// area.
    d_mass: Vec<f64>,
}

impl<'a> Problem<'a> {
    /// The fixed parts of the optimization of [`optimize_from`].
    fn new(
        mesh: &ShellMesh,
        fixed: &[usize],
        design: &'a [bool],
        carbon: &Layer,
        skin: &Layer,
        loads: &'a [Vec<f64>],
        settings: &'a SimpSettings,
    ) -> Result<Self, SimpError> {
        let n = mesh.elements.len();
        let area: Vec<f64> = (0..n).map(|e| mesh.element_area(e)).collect();
        let design_area: f64 = (0..n).filter(|&e| design[e]).map(|e| area[e]).sum();
        let filter = DensityFilter::new(mesh, settings.filter_radius);
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
        let dofs: Vec<[usize; element::DOFS]> = (0..n).map(|e| element_dofs(mesh, e)).collect();
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
        Ok(Self {
            settings,
            design,
            loads,
            area,
            design_area,
            filter,
            structure,
            carbon_k,
            carbon_layer,
            skin_stiffness,
            dofs,
            d_mass,
        })
    }

    /// Sets the densities of the non-design elements to full carbon.
    fn fix(&self, rho: &mut [f64]) {
        for (r, &d) in rho.iter_mut().zip(self.design) {
            if !d {
                *r = 1.0;
            }
        }
    }

    /// The carbon mass of the (filtered) densities `rho` over the full
    /// design layer's.
    fn mass(&self, rho: &[f64]) -> f64 {
        (0..rho.len())
            .filter(|&e| self.design[e])
            .map(|e| rho[e] * self.area[e])
            .sum::<f64>()
            / self.design_area
    }

    /// The mass of the design variables `x`, the same without filtering
    /// them (linear in them).
    fn mass_of_design(&self, x: &[f64]) -> f64 {
        x.iter().zip(&self.d_mass).map(|(x, w)| x * w).sum::<f64>() / self.design_area
    }

    /// The displacements of every load case for the densities `rho`,
    /// interleaved: `u[d * cases + l]`, DOF `d` of load case `l`. Factorizes
    /// in `factor`'s storage (kept from one iteration to the next).
    fn displacements<'s>(
        &'s self,
        rho: &[f64],
        factor: &mut Option<OrderedFactor<'s>>,
    ) -> Result<Vec<f64>, SimpError> {
        let p = self.settings.penalty;
        let scales: Vec<f64> = rho.iter().map(|r| r.powf(p)).collect();
        let stiffness = self.structure.assemble_ordered(
            &self.carbon_layer,
            &scales,
            Some(&self.skin_stiffness),
        )?;
        let factor = match factor.as_mut() {
            Some(factor) => {
                factor.refactorize(&stiffness)?;
                factor
            }
            None => factor.insert(OrderedFactor::new(&self.structure, &stiffness)?),
        };
        drop(stiffness);
        Ok(factor.solve(self.loads)?)
    }

    /// The summed compliance `sum_l f_l . u_l` of the interleaved
    /// displacements `u`, J.
    fn compliance(&self, u: &[f64]) -> f64 {
        let cases = self.loads.len();
        self.loads
            .iter()
            .enumerate()
            .map(|(l, f)| {
                f.iter()
                    .enumerate()
                    .map(|(d, f)| f * u[d * cases + l])
                    .sum::<f64>()
            })
            .sum()
    }

    /// The compliance's derivatives by the densities `rho` (0 off the
    /// design elements).
    ///
    /// dC/drho_e = -p rho^(p-1) sum_l u_l,e . K_carbon,e u_l,e (twice the
    /// carbon strain energy): with U_e the element's displacements in
    /// every load case (24 x cases), the sum of U_e o (K_carbon,e U_e),
    /// one small matrix product an element (faer's SIMD kernels).
    fn sensitivities(&self, rho: &[f64], u: &[f64]) -> Vec<f64> {
        const DOFS: usize = element::DOFS;
        let (s, cases) = (self.settings, self.loads.len());
        (0..rho.len())
            .into_par_iter()
            .map_init(
                || (vec![0.0; DOFS * cases], vec![0.0; DOFS * cases]),
                |(ue, product), e| {
                    if !self.design[e] {
                        return 0.0;
                    }
                    for (row, &g) in ue.chunks_exact_mut(cases).zip(&self.dofs[e]) {
                        row.copy_from_slice(&u[g * cases..(g + 1) * cases]);
                    }
                    matmul(
                        MatMut::from_row_major_slice_mut(product, DOFS, cases),
                        Accum::Replace,
                        MatRef::from_column_major_slice(self.carbon_k[e].as_slice(), DOFS, DOFS),
                        MatRef::from_row_major_slice(ue, DOFS, cases),
                        1.0,
                        Par::Seq,
                    );
                    let energy: f64 = ue.iter().zip(product.iter()).map(|(u, p)| u * p).sum();
                    -s.penalty * rho[e].powf(s.penalty - 1.0) * energy
                },
            )
            .collect()
    }

    /// The next design variables after `x` by the optimality criteria,
    /// with `d_x` the compliance's derivatives by them: bisection on the
    /// multiplier of the mass.
    fn optimality_criteria(&self, x: &[f64], d_x: &[f64]) -> Vec<f64> {
        let s = self.settings;
        let (mut low, mut high) = (0.0f64, 1e12f64);
        let mut next = x.to_vec();
        while (high - low) / (high + low).max(1e-300) > 1e-6 {
            let mid = 0.5 * (low + high);
            for e in 0..x.len() {
                if !self.design[e] {
                    continue;
                }
                let scale = (-d_x[e] / (mid * self.d_mass[e])).max(0.0).sqrt();
                next[e] = (x[e] * scale)
                    .clamp(x[e] - s.move_limit, x[e] + s.move_limit)
                    .clamp(0.0, 1.0);
            }
            if self.mass_of_design(&next) > s.mass_fraction {
                low = mid;
            } else {
                high = mid;
            }
        }
        next
    }
}
