//! The ordered path's factor: faer's supernodal Cholesky of an
//! [`OrderedStiffness`] on the structure's nested-dissection order, its
//! storage and workspace kept for the next factorization, solved for many
//! load cases at once.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::cholesky::LltRef;
use faer::sparse::SparseColMatRef;
use faer::{Conj, Mat, MatMut, Par, Side};
use rayon::prelude::*;

use super::{not_positive, Ordered, OrderedStiffness, Structure};
use crate::shell::assembly::AssemblyError;

/// The Cholesky factor `L L^T = P K P^T` of an [`OrderedStiffness`]
/// (faer's supernodal factorization on the nested-dissection order), its
/// storage kept for the next factorization on the same structure.
pub struct OrderedFactor<'a> {
    structure: &'a Structure,
    ordered: &'a Ordered,
    values: Vec<f64>,
    /// faer's workspace of the numeric factorization, kept with the
    /// factor's storage.
    scratch: MemBuffer,
    /// Whether `values` hold a successful factorization.
    valid: bool,
}

impl<'a> OrderedFactor<'a> {
    /// Factorizes `k` (assembled on `structure`). Sequential: on the
    /// 2-core development machine faer's parallelism inside the supernodes
    /// made the default wing's factorization slower, not faster (0.12 to
    /// 0.18 s against 0.07 to 0.08 s); the cores share the solves instead.
    pub fn new(structure: &'a Structure, k: &OrderedStiffness) -> Result<Self, AssemblyError> {
        let ordered = structure.ordered()?;
        let scratch = MemBuffer::try_new(
            ordered
                .symbolic
                .factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default()),
        )
        .map_err(|e| AssemblyError::Sparse(e.to_string()))?;
        let mut factor = Self {
            structure,
            ordered,
            values: vec![0.0; ordered.symbolic.len_val()],
            scratch,
            valid: false,
        };
        factor.refactorize(k)?;
        Ok(factor)
    }

    /// Factorizes a new stiffness on the same structure into the same
    /// storage (no allocation of the factor). On an error the factor is
    /// unusable until a successful refactorization.
    pub fn refactorize(&mut self, k: &OrderedStiffness) -> Result<(), AssemblyError> {
        self.valid = false;
        let ordered = self.ordered;
        if k.values.len() != ordered.pattern.row_idx().len() {
            return Err(AssemblyError::Length {
                got: k.values.len(),
                expected: ordered.pattern.row_idx().len(),
            });
        }
        let par = Par::Seq;
        ordered
            .symbolic
            .factorize_numeric_llt(
                &mut self.values,
                SparseColMatRef::new(ordered.pattern.as_ref(), &k.values),
                Side::Lower,
                Default::default(),
                par,
                MemStack::new(&mut self.scratch),
                Default::default(),
            )
            .map_err(|e| AssemblyError::Singular(not_positive(e)))?;
        self.valid = true;
        Ok(())
    }

    /// Displacements under global load vectors (N, one per load case), all
    /// solved together, the load cases shared among the cores. Returned
    /// interleaved over the global DOFs: `u[d * loads.len() + l]` is DOF
    /// `d` of load case `l` (m or rad; fixed DOFs zero), so that an
    /// element's displacements in every load case lie together.
    pub fn solve(&self, loads: &[Vec<f64>]) -> Result<Vec<f64>, AssemblyError> {
        let dofs = self.structure.map.dofs();
        if !self.valid {
            return Err(AssemblyError::Singular(
                "the last factorization failed".into(),
            ));
        }
        if let Some(f) = loads.iter().find(|f| f.len() != dofs) {
            return Err(AssemblyError::Length {
                got: f.len(),
                expected: dofs,
            });
        }
        let cases = loads.len();
        if cases == 0 {
            return Ok(Vec::new());
        }
        let global = &self.ordered.global;
        let mut x = Mat::from_fn(global.len(), cases, |k, l| loads[l][global[k]]);
        let factor = LltRef::new(&self.ordered.symbolic, &self.values);
        let groups = rayon::current_num_threads().clamp(1, cases);
        x.as_mut()
            .par_col_partition_mut(groups)
            .for_each(|block: MatMut<'_, f64>| {
                let mut scratch = MemBuffer::new(
                    self.ordered
                        .symbolic
                        .solve_in_place_scratch::<f64>(block.ncols(), Par::Seq),
                );
                factor.solve_in_place_with_conj(
                    Conj::No,
                    block,
                    Par::Seq,
                    MemStack::new(&mut scratch),
                );
            });
        let mut u = vec![0.0; dofs * cases];
        for (k, &g) in global.iter().enumerate() {
            for l in 0..cases {
                u[g * cases + l] = x[(k, l)];
            }
        }
        Ok(u)
    }
}
