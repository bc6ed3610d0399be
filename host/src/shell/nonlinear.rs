//! Geometrically nonlinear statics: Newton–Raphson on the co-rotational
//! shell ([`super::corotational`]) with the load applied in equal steps,
//! each step converged before the next (dead loads: forces and moments of
//! fixed direction).

use std::sync::Arc;

use super::assembly::{element_dofs, AssemblyError};
use super::corotational::{Configuration, Corotational, ElementResponse};
use super::element::ElementVector;
use super::material::Section;
use super::mesh::ShellMesh;
use super::structure::{OrderedFactor, OrderedStiffness, Structure};

/// Why a nonlinear solve stopped.
#[derive(Debug, thiserror::Error)]
pub enum NonlinearError {
    /// Assembly or factorization (e.g. a tangent that lost definiteness
    /// past a limit point).
    #[error(transparent)]
    Assembly(#[from] AssemblyError),
    /// Newton did not converge within the iteration cap.
    #[error("load step {step} (load factor {load:.3}) did not converge in {iterations} iterations (residual {residual:.3e} of the load)")]
    NoConvergence {
        /// Step index.
        step: usize,
        /// Load factor.
        load: f64,
        /// Iterations spent.
        iterations: usize,
        /// Relative residual at the end.
        residual: f64,
    },
    /// A time step's Newton iterations did not converge.
    #[error("time step {step} (t = {time:.5} s) did not converge in {iterations} iterations (residual {residual:.3e} of the largest force)")]
    StepNoConvergence {
        /// Step index (from 1, in steps of the transient's size).
        step: usize,
        /// Time at the step's end, s.
        time: f64,
        /// Iterations spent.
        iterations: usize,
        /// Relative residual at the end.
        residual: f64,
    },
}

/// A nonlinear model: mesh, elements and sparse structure with supports.
pub struct NonlinearStatic<'a> {
    mesh: &'a ShellMesh,
    elements: Corotational,
    structure: Arc<Structure>,
}

/// Newton settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NewtonSettings {
    /// Equal load steps from 0 to the full load.
    pub steps: usize,
    /// Convergence: residual norm below this fraction of the load norm.
    /// (The tangent is the symmetric part and leaves out the load stiffness
    /// of moments, so Newton's last digits come slowly: 1e-5 is where it
    /// reliably gets.)
    pub tolerance: f64,
    /// Iterations allowed a step.
    pub max_iterations: usize,
}

impl Default for NewtonSettings {
    fn default() -> Self {
        Self {
            steps: 10,
            tolerance: 1e-5,
            max_iterations: 30,
        }
    }
}

impl<'a> NonlinearStatic<'a> {
    /// The model of `mesh` with `sections` and the global DOFs in `fixed`
    /// held at zero.
    pub fn new(
        mesh: &'a ShellMesh,
        sections: &[Section],
        fixed: &[usize],
    ) -> Result<Self, NonlinearError> {
        Ok(Self {
            mesh,
            elements: Corotational::new(mesh, sections)?,
            structure: Arc::new(Structure::new(mesh, fixed)?),
        })
    }

    /// Relative residual norm over the free DOFs at load factor `lambda`.
    fn residual(&self, load: &[f64], internal: &[f64], lambda: f64) -> Vec<f64> {
        self.structure.map().restrict(
            &load
                .iter()
                .zip(internal)
                .map(|(f, i)| lambda * f - i)
                .collect::<Vec<_>>(),
        )
    }

    /// Equilibrium path under `load` (global forces and moments at full
    /// load): the configuration at the end of each load step.
    pub fn solve(
        &self,
        load: &[f64],
        settings: NewtonSettings,
    ) -> Result<Vec<(f64, Configuration)>, NonlinearError> {
        let map = self.structure.map();
        if load.len() != map.dofs() {
            return Err(AssemblyError::Length {
                got: load.len(),
                expected: map.dofs(),
            }
            .into());
        }
        let load_norm = norm(&map.restrict(load)).max(f64::MIN_POSITIVE);
        let mut c = Configuration::initial(self.mesh.nodes.len());
        let mut previous = c.clone();
        let mut path = Vec::with_capacity(settings.steps);
        let mut workspace = TangentWorkspace::new(&self.structure);
        for step in 1..=settings.steps {
            let lambda = step as f64 / settings.steps as f64;
            // Predictor: repeat the last step's motion (translations and
            // rotations alike). A linear predictor from the tangent alone
            // would stretch a rotating, membrane-stiff shell far off the
            // path and Newton would not come back.
            let converged_last = c.clone();
            c.extrapolate(&previous);
            previous = converged_last;
            let mut residual_norm = f64::INFINITY;
            let mut converged = false;
            for _ in 0..settings.max_iterations {
                self.elements
                    .responses_into(self.mesh, &c, &mut workspace.responses);
                let internal = internal_force(self.mesh, &workspace.responses);
                let residual = self.residual(load, &internal, lambda);
                residual_norm = norm(&residual) / load_norm;
                if residual_norm < settings.tolerance {
                    converged = true;
                    break;
                }
                let factor =
                    workspace.factor(None, || self.elements.material_responses(self.mesh, &c))?;
                let increment = factor.solve(&[map.expand(&residual)])?;
                c.update(&increment);
            }
            if !converged {
                return Err(NonlinearError::NoConvergence {
                    step,
                    load: lambda,
                    iterations: settings.max_iterations,
                    residual: residual_norm,
                });
            }
            path.push((lambda, c.clone()));
        }
        Ok(path)
    }
}

/// The Euclidean norm of a force or residual vector, N (or N m).
///
/// Summed plainly as it always was, so that every result stays the same
/// to the bit; where the squares overflow (a pressure file of 1e160 Pa) it
/// is taken again by faer's scaled sum. The plain sum's `inf` made the
/// load's norm infinite, every residual 0 against it, and the analysis
/// "converge" at rest: a strain energy of 0 reported as a design.
pub(crate) fn norm(v: &[f64]) -> f64 {
    let plain = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    if plain.is_finite() || v.iter().any(|x| !x.is_finite()) {
        plain
    } else {
        faer::ColRef::from_slice(v).norm_l2()
    }
}

/// The element internal forces summed over the global DOFs.
pub(crate) fn internal_force(mesh: &ShellMesh, responses: &[ElementResponse]) -> Vec<f64> {
    summed_forces(mesh, responses.iter().map(|r| &r.force))
}

/// Element force vectors (in element order) summed over the global DOFs.
pub(crate) fn summed_forces<'f>(
    mesh: &ShellMesh,
    forces: impl Iterator<Item = &'f ElementVector>,
) -> Vec<f64> {
    let mut force = vec![0.0; mesh.dofs()];
    for (e, f) in forces.enumerate() {
        for (local, g) in element_dofs(mesh, e).into_iter().enumerate() {
            force[g] += f[local];
        }
    }
    force
}

/// Factorizes `k` into `slot`: numerically again when it already holds a
/// factor of the same pattern, symbolically and numerically when empty.
fn factorize<'s>(
    slot: &mut Option<OrderedFactor<'s>>,
    structure: &'s Structure,
    k: &OrderedStiffness,
) -> Result<(), AssemblyError> {
    match slot {
        Some(f) => f.refactorize(k),
        None => {
            *slot = Some(OrderedFactor::new(structure, k)?);
            Ok(())
        }
    }
}

/// The storage a Newton iteration's tangent reuses from one iteration to
/// the next: the element responses, the assembled matrix and the Cholesky
/// factor (on the default wing about 33 MB, 8 MB and the factor, which
/// fresh allocations every iteration paid for again in page faults and
/// zeroing).
pub struct TangentWorkspace<'s> {
    structure: &'s Structure,
    /// The element responses of the current iterate.
    pub(crate) responses: Vec<ElementResponse>,
    /// Element internal forces alone, for iterations that keep the last
    /// factor.
    pub(crate) forces: Vec<ElementVector>,
    stiffness: OrderedStiffness,
    factor: Option<OrderedFactor<'s>>,
    /// The inertia shift the factor was made with (NaN: none), s^-2.
    shift: f64,
}

impl<'s> TangentWorkspace<'s> {
    /// Empty storage for tangents on `structure`.
    pub fn new(structure: &'s Structure) -> Self {
        Self {
            structure,
            responses: Vec::new(),
            forces: Vec::new(),
            stiffness: OrderedStiffness::default(),
            factor: None,
            shift: f64::NAN,
        }
    }

    /// The last factorization if it was made with the inertia shift
    /// `shift` (bit for bit: a step of another length needs its own).
    pub(crate) fn factor_with_shift(&self, shift: f64) -> Option<&OrderedFactor<'s>> {
        self.factor.as_ref().filter(|_| self.shift == shift)
    }

    /// [`Self::factor`] for an iteration matrix with the inertia shift
    /// `shift` (recorded for [`Self::factor_with_shift`]).
    pub(crate) fn factor_shifted(
        &mut self,
        shift: f64,
        diagonal: &[f64],
        material: impl FnOnce() -> Vec<ElementResponse>,
    ) -> Result<&OrderedFactor<'s>, AssemblyError> {
        self.factor(Some(diagonal), material)?;
        self.shift = shift;
        self.factor
            .as_ref()
            .ok_or_else(|| AssemblyError::Singular("no factorization".into()))
    }

    /// The factorized tangent over the free DOFs from [`Self::responses`],
    /// plus `diagonal` (free DOFs) if given: the full tangent, or the
    /// material part of `material()` (the responses' material tangents,
    /// computed only then) where the full one is not positive definite
    /// (far from equilibrium after a large step; Newton then converges
    /// linearly until it is again).
    pub(crate) fn factor(
        &mut self,
        diagonal: Option<&[f64]>,
        material: impl FnOnce() -> Vec<ElementResponse>,
    ) -> Result<&OrderedFactor<'s>, AssemblyError> {
        // A factor made here carries no recorded shift until
        // factor_shifted records one.
        self.shift = f64::NAN;
        let structure = self.structure;
        let assemble = |responses: &[ElementResponse], k: &mut OrderedStiffness| {
            structure.assemble_ordered_into(responses.len(), |e| &responses[e].tangent, k)?;
            if let Some(d) = diagonal {
                structure.add_diagonal(k, d)?;
            }
            Ok::<(), AssemblyError>(())
        };
        assemble(&self.responses, &mut self.stiffness)?;
        if factorize(&mut self.factor, structure, &self.stiffness).is_err() {
            assemble(&material(), &mut self.stiffness)?;
            factorize(&mut self.factor, structure, &self.stiffness)?;
        }
        self.factor
            .as_ref()
            .ok_or_else(|| AssemblyError::Singular("no factorization".into()))
    }
}

#[cfg(test)]
mod tests {
    use super::norm;

    /// The plain sum where it is finite, the scaled one where the squares
    /// overflow (1e160 squared is beyond an f64), and NaN or infinite
    /// entries left as they are.
    #[test]
    fn the_norm_survives_forces_whose_squares_overflow() {
        assert_eq!(norm(&[3.0, 4.0]), 5.0);
        let big = norm(&[3e160, 4e160]);
        assert!((big / 5e160 - 1.0).abs() < 1e-15, "{big:e}");
        assert!(norm(&[f64::NAN, 1.0]).is_nan());
        assert_eq!(norm(&[f64::INFINITY, 1.0]), f64::INFINITY);
    }
}
