//! The sparsity structure of a mesh's stiffness over its free DOFs, built
//! once per mesh and support: the compressed-column pattern (6 x 6 blocks
//! of every pair of nodes sharing an element), where each element entry
//! lands in it, and the symbolic Cholesky analyses. Assembling and
//! factorizing a new stiffness on it (new densities, a new tangent) is then
//! value-only work.
//!
//! Two factorization paths share the structure:
//!
//! - [`Structure::assemble`] and [`Structure::factorize`]: the full
//!   symmetric matrix and faer's [`Llt`] with its approximate minimum
//!   degree ordering (the general path: linear, modal, dynamic and
//!   nonlinear analyses).
//! - [`Structure::ordered_layer`], [`Structure::assemble_ordered`] and
//!   [`OrderedFactor`]: the lower triangle only, gathered in parallel
//!   straight into the nested-dissection order of [`super::ordering`] from
//!   scaled element matrices (skin plus `rho^p` carbon, say), factorized
//!   sequentially into reused storage and solved for many load cases at
//!   once, the load cases shared among the cores: the path of the SIMP
//!   iterations, which factorize the same pattern a hundred times. On the
//!   default wing the ordering cuts the factorization flops by a tenth and
//!   its time by a quarter against AMD, and the sequential factorization
//!   takes half the time of faer's default parallel one on two cores.
//!
//! Each path's symbolic analysis is made on its first use.

use std::ops::Range;
use std::sync::OnceLock;

use faer::linalg::cholesky::llt::factor::LltError as PivotError;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, SymbolicCholesky, SymmetricOrdering,
};
use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::linalg::LltError;
use faer::sparse::{FaerError, SparseColMat, SymbolicSparseColMat};
use faer::Side;
use rayon::prelude::*;

use super::assembly::{element_dofs, AssemblyError, DofMap};
use super::element::{self, ElementMatrix, DOFS, MATRIX_ENTRIES, NODES, NODE_DOFS};
use super::material::Section;
use super::mesh::ShellMesh;
use super::ordering;

mod ordered_factor;

pub use ordered_factor::OrderedFactor;

/// Marks an element entry on a fixed DOF.
const FIXED: u32 = u32::MAX;

/// Pattern, scatter map and symbolic factorizations of one mesh + support.
pub struct Structure {
    map: DofMap,
    pattern: SymbolicSparseColMat<usize>,
    /// For element `e`, entry `(a, b)` goes to value `scatter[576 e + 24 a + b]`.
    scatter: Vec<u32>,
    /// faer's symbolic analysis (AMD ordering) for [`Self::factorize`].
    symbolic: OnceLock<Result<SymbolicLlt<usize>, String>>,
    /// The free DOFs in nested-dissection order.
    order: Vec<usize>,
    /// The lower triangle in that order, for [`Self::assemble_ordered`].
    ordered: OnceLock<Result<Ordered, String>>,
    /// The mesh's elements (corner nodes), for the ordered pattern.
    connectivity: Vec<[usize; NODES]>,
}

/// The lower triangle of the stiffness permuted to the nested-dissection
/// order (`K_p = P K P^T`, row and column `k` the `k`-th eliminated free
/// DOF), how element entries gather into it, and its symbolic Cholesky
/// analysis (no further ordering).
struct Ordered {
    /// Compressed columns of the lower triangle of `K_p`, rows sorted.
    pattern: SymbolicSparseColMat<usize>,
    /// Value `q` of `pattern` sums the element entries
    /// `gather[start[q]..start[q + 1]]`, each `576 e + a + 24 b` for entry
    /// `(a, b)` of element `e` (the column-major storage of
    /// [`ElementMatrix`]).
    start: Vec<usize>,
    gather: Vec<u32>,
    /// Global DOF of each position in elimination order.
    global: Vec<usize>,
    symbolic: SymbolicCholesky<usize>,
}

impl Structure {
    /// Builds the structure of `mesh` with the global DOFs in `fixed` held.
    /// Cost: `O(nnz log(row length))` plus the nested-dissection ordering;
    /// the symbolic factorizations come on first use.
    pub fn new(mesh: &ShellMesh, fixed: &[usize]) -> Result<Self, AssemblyError> {
        let map = DofMap::new(mesh.dofs(), fixed)?;
        let mut neighbours = vec![Vec::new(); mesh.nodes.len()];
        for corners in &mesh.elements {
            for &a in corners {
                neighbours[a].extend(corners.iter().copied());
            }
        }
        neighbours.par_iter_mut().for_each(|near: &mut Vec<usize>| {
            near.sort_unstable();
            near.dedup();
        });
        let n = map.free_count();
        let mut col_ptr = Vec::with_capacity(n + 1);
        let mut row_idx = Vec::new();
        col_ptr.push(0);
        for (node, near) in neighbours.iter().enumerate() {
            for c in 0..NODE_DOFS {
                if map.free(NODE_DOFS * node + c).is_none() {
                    continue;
                }
                for &m in near {
                    row_idx.extend((0..NODE_DOFS).filter_map(|d| map.free(NODE_DOFS * m + d)));
                }
                col_ptr.push(row_idx.len());
            }
        }
        if row_idx.len() >= FIXED as usize || MATRIX_ENTRIES * mesh.elements.len() >= FIXED as usize
        {
            return Err(AssemblyError::Sparse(format!(
                "{} stiffness entries of {} elements exceed the 32-bit scatter map",
                row_idx.len(),
                mesh.elements.len()
            )));
        }
        let mut scatter = vec![FIXED; MATRIX_ENTRIES * mesh.elements.len()];
        scatter
            .par_chunks_mut(MATRIX_ENTRIES)
            .enumerate()
            .for_each(|(e, out)| {
                let corners = &mesh.elements[e];
                for (b, fb) in element_dofs(mesh, e).iter().enumerate() {
                    let Some(fb) = map.free(*fb) else { continue };
                    let rows = &row_idx[col_ptr[fb]..col_ptr[fb + 1]];
                    for (corner, &m) in corners.iter().enumerate() {
                        // A node's free DOFs are consecutive rows: one search
                        // a node, then the next row (present by
                        // construction: the nodes share this element).
                        let mut last: Option<usize> = None;
                        for d in 0..NODE_DOFS {
                            let Some(fa) = map.free(NODE_DOFS * m + d) else {
                                continue;
                            };
                            let at = match last {
                                Some(k) if rows.get(k + 1) == Some(&fa) => k + 1,
                                _ => match rows.binary_search(&fa) {
                                    Ok(k) => k,
                                    Err(_) => continue,
                                },
                            };
                            out[DOFS * (NODE_DOFS * corner + d) + b] = (col_ptr[fb] + at) as u32;
                            last = Some(at);
                        }
                    }
                }
            });
        let pattern = SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx);
        let order = ordering::nested_dissection(mesh, &map)?;
        Ok(Self {
            map,
            pattern,
            scatter,
            symbolic: OnceLock::new(),
            order,
            ordered: OnceLock::new(),
            connectivity: mesh.elements.clone(),
        })
    }

    /// The DOF map.
    pub fn map(&self) -> &DofMap {
        &self.map
    }

    /// Sums element matrices (one per element, global axes) into the
    /// pattern.
    pub fn assemble(
        &self,
        matrices: &[ElementMatrix],
    ) -> Result<SparseColMat<usize, f64>, AssemblyError> {
        if matrices.len() != self.connectivity.len() {
            return Err(AssemblyError::Sections {
                sections: matrices.len(),
                elements: self.connectivity.len(),
            });
        }
        let mut values = vec![0.0; self.pattern.row_idx().len()];
        for (k, positions) in matrices
            .iter()
            .zip(self.scatter.chunks_exact(MATRIX_ENTRIES))
        {
            for a in 0..DOFS {
                for b in 0..DOFS {
                    let p = positions[DOFS * a + b];
                    if p != FIXED {
                        values[p as usize] += k[(a, b)];
                    }
                }
            }
        }
        Ok(SparseColMat::new(self.pattern.clone(), values))
    }

    /// The linear stiffness of `mesh` with one section per element.
    pub fn stiffness(
        &self,
        mesh: &ShellMesh,
        sections: &[Section],
    ) -> Result<SparseColMat<usize, f64>, AssemblyError> {
        if sections.len() != mesh.elements.len() {
            return Err(AssemblyError::Sections {
                sections: sections.len(),
                elements: mesh.elements.len(),
            });
        }
        let matrices: Vec<ElementMatrix> = (0..mesh.elements.len())
            .into_par_iter()
            .map(|e| element::stiffness(&mesh.corners(e), &sections[e]))
            .collect();
        self.assemble(&matrices)
    }

    /// Numeric Cholesky factorization of a matrix on this structure
    /// (faer's AMD ordering; its symbolic analysis is made on the first
    /// call).
    pub fn factorize(
        &self,
        k: &SparseColMat<usize, f64>,
    ) -> Result<Llt<usize, f64>, AssemblyError> {
        let symbolic = self
            .symbolic
            .get_or_init(|| {
                SymbolicLlt::try_new(self.pattern.as_ref(), Side::Lower).map_err(sparse_failure)
            })
            .as_ref()
            .map_err(|e| AssemblyError::Sparse(e.clone()))?;
        Llt::try_new_with_symbolic(symbolic.clone(), k.as_ref(), Side::Lower).map_err(|e| match e {
            LltError::Numeric(pivot) => AssemblyError::Singular(not_positive(pivot)),
            LltError::Generic(e) => AssemblyError::Sparse(sparse_failure(e)),
        })
    }

    /// The free DOFs in the nested-dissection elimination order of
    /// [`ordering::nested_dissection`] (entry `k`: the free DOF index
    /// eliminated `k`-th).
    pub fn order(&self) -> &[usize] {
        &self.order
    }

    /// Element matrices (one per element, global axes) laid out for
    /// [`Self::assemble_ordered`]: each entry that lands on the lower
    /// triangle, in the order the assembly reads them, so that assembling a
    /// layer again and again with new scales streams through memory. The
    /// first call builds the ordered pattern and its symbolic analysis.
    pub fn ordered_layer(&self, matrices: &[ElementMatrix]) -> Result<OrderedLayer, AssemblyError> {
        if matrices.len() != self.connectivity.len() {
            return Err(AssemblyError::Sections {
                sections: matrices.len(),
                elements: self.connectivity.len(),
            });
        }
        let ordered = self.ordered()?;
        let values = ordered
            .gather
            .par_iter()
            .map(|&code| {
                matrices[code as usize / MATRIX_ENTRIES].as_slice()[code as usize % MATRIX_ENTRIES]
            })
            .collect();
        Ok(OrderedLayer { values })
    }

    /// `sum_e scales[e] K_e` over the free DOFs for the element matrices
    /// `K_e` of `layer`, plus `base` if given, as the lower triangle in the
    /// nested-dissection order for [`OrderedFactor`]: one scale per element
    /// (for instance SIMP's `rho_e^p` on the carbon layer, with `base` the
    /// skin). Parallel over the values.
    pub fn assemble_ordered(
        &self,
        layer: &OrderedLayer,
        scales: &[f64],
        base: Option<&OrderedStiffness>,
    ) -> Result<OrderedStiffness, AssemblyError> {
        if scales.len() != self.connectivity.len() {
            return Err(AssemblyError::Sections {
                sections: scales.len(),
                elements: self.connectivity.len(),
            });
        }
        let ordered = self.ordered()?;
        if layer.values.len() != ordered.gather.len() {
            return Err(AssemblyError::Length {
                got: layer.values.len(),
                expected: ordered.gather.len(),
            });
        }
        let nnz = ordered.pattern.row_idx().len();
        let mut values = match base {
            Some(base) if base.values.len() == nnz => base.values.clone(),
            Some(base) => {
                return Err(AssemblyError::Length {
                    got: base.values.len(),
                    expected: nnz,
                })
            }
            None => vec![0.0; nnz],
        };
        const CHUNK: usize = 4096;
        values
            .par_chunks_mut(CHUNK)
            .enumerate()
            .for_each(|(chunk, out)| {
                for (i, value) in out.iter_mut().enumerate() {
                    let q = chunk * CHUNK + i;
                    let range = ordered.start[q]..ordered.start[q + 1];
                    *value += ordered.gather[range.clone()]
                        .iter()
                        .zip(&layer.values[range])
                        .map(|(&code, &k)| scales[code as usize / MATRIX_ENTRIES] * k)
                        .sum::<f64>();
                }
            });
        Ok(OrderedStiffness { values })
    }

    /// `sum_e K_e` over the free DOFs for one matrix per element (global
    /// axes), as the ordered lower triangle for [`OrderedFactor`], gathered
    /// straight from the matrices (for matrices that change every time,
    /// such as tangents). Parallel over the values.
    pub fn assemble_matrices_ordered(
        &self,
        matrices: &[ElementMatrix],
    ) -> Result<OrderedStiffness, AssemblyError> {
        self.assemble_ordered_from(matrices.len(), |e| &matrices[e])
    }

    /// [`Self::assemble_matrices_ordered`] with element `e`'s matrix given
    /// by `matrix(e)` for `count` elements (so that matrices kept inside
    /// other per-element results need not be copied out first).
    pub fn assemble_ordered_from<'m>(
        &self,
        count: usize,
        matrix: impl Fn(usize) -> &'m ElementMatrix + Sync,
    ) -> Result<OrderedStiffness, AssemblyError> {
        let mut k = OrderedStiffness { values: Vec::new() };
        self.assemble_ordered_into(count, matrix, &mut k)?;
        Ok(k)
    }

    /// [`Self::assemble_ordered_from`] into the storage of `k` (any
    /// earlier stiffness on this structure, or an empty one), so that
    /// repeated assemblies (Newton iterations) allocate nothing.
    pub fn assemble_ordered_into<'m>(
        &self,
        count: usize,
        matrix: impl Fn(usize) -> &'m ElementMatrix + Sync,
        k: &mut OrderedStiffness,
    ) -> Result<(), AssemblyError> {
        if count != self.connectivity.len() {
            return Err(AssemblyError::Sections {
                sections: count,
                elements: self.connectivity.len(),
            });
        }
        let ordered = self.ordered()?;
        k.values.resize(ordered.pattern.row_idx().len(), 0.0);
        k.values.par_iter_mut().enumerate().for_each(|(q, value)| {
            *value = ordered.gather[ordered.start[q]..ordered.start[q + 1]]
                .iter()
                .map(|&code| {
                    matrix(code as usize / MATRIX_ENTRIES).as_slice()
                        [code as usize % MATRIX_ENTRIES]
                })
                .sum();
        });
        Ok(())
    }

    /// Adds `diagonal` (one value per free DOF, in the free numbering of
    /// [`Self::map`]) to the diagonal of an ordered stiffness: a lumped
    /// mass term of an iteration matrix, for instance.
    pub fn add_diagonal(
        &self,
        k: &mut OrderedStiffness,
        diagonal: &[f64],
    ) -> Result<(), AssemblyError> {
        let ordered = self.ordered()?;
        if diagonal.len() != self.order.len() || k.values.len() != ordered.pattern.row_idx().len() {
            return Err(AssemblyError::Length {
                got: diagonal.len(),
                expected: self.order.len(),
            });
        }
        // Column k's rows start at k: its first value is the diagonal.
        let col_ptr = ordered.pattern.col_ptr();
        for (position, &free) in self.order.iter().enumerate() {
            k.values[col_ptr[position]] += diagonal[free];
        }
        Ok(())
    }

    /// The ordered lower triangle, built on first use.
    fn ordered(&self) -> Result<&Ordered, AssemblyError> {
        self.ordered
            .get_or_init(|| self.build_ordered())
            .as_ref()
            .map_err(|e| AssemblyError::Sparse(e.clone()))
    }

    /// The lower triangle of the stiffness in the nested-dissection
    /// order, column by column (in parallel): the rows of column `k` are
    /// the free DOFs of the nodes sharing an element with its node, from
    /// position `k` on, and each value gathers the element entries on it.
    /// Then faer's symbolic analysis of it.
    fn build_ordered(&self) -> Result<Ordered, String> {
        let n = self.map.free_count();
        let sources = ColumnSources::new(self);
        // Columns in parallel blocks: each block's row indices, the number
        // of element entries on each of its values, and those entries.
        const BLOCK: usize = 1024;
        let blocks: Vec<ColumnBlock> = (0..n.div_ceil(BLOCK))
            .into_par_iter()
            .map(|block| sources.block(block * BLOCK..(block * BLOCK + BLOCK).min(n)))
            .collect();
        let columns = ColumnBlock::concatenate(n, blocks);
        let pattern =
            SymbolicSparseColMat::new_checked(n, n, columns.col_ptr, None, columns.row_idx);
        let symbolic = symbolic_cholesky(&pattern)?;
        Ok(Ordered {
            pattern,
            start: columns.start,
            gather: columns.gather,
            global: sources.global,
            symbolic,
        })
    }
}

/// faer's symbolic Cholesky analysis of the lower triangle `pattern`, in
/// its own order.
fn symbolic_cholesky(
    pattern: &SymbolicSparseColMat<usize>,
) -> Result<SymbolicCholesky<usize>, String> {
    // faer's symbolic analysis without reordering reads the upper
    // triangle whatever the side given: hand it the transpose (the
    // numeric factorization then reads the lower triangle).
    let upper = pattern
        .as_ref()
        .transpose()
        .to_col_major()
        .map_err(sparse_failure)?;
    factorize_symbolic_cholesky(
        upper.as_ref(),
        Side::Upper,
        SymmetricOrdering::Identity,
        Default::default(),
    )
    .map_err(sparse_failure)
}

/// What the columns of the ordered lower triangle are built from: the
/// structure, where each free DOF is eliminated, and the elements around
/// each node.
struct ColumnSources<'s> {
    structure: &'s Structure,
    /// Position in elimination order of each free DOF.
    position: Vec<usize>,
    /// Global DOF of each position in elimination order.
    global: Vec<usize>,
    /// The elements around node `i` are
    /// `around[around_start[i]..around_start[i + 1]]` (compressed rows).
    around_start: Vec<usize>,
    around: Vec<usize>,
    /// Position of each node's first free DOF (`usize::MAX`: none): its
    /// free DOFs follow it in component order (the ordering keeps them
    /// together).
    node_first: Vec<usize>,
}

impl<'s> ColumnSources<'s> {
    /// The positions, the elements around the nodes and the nodes' first
    /// positions of `structure`.
    fn new(structure: &'s Structure) -> Self {
        let map = &structure.map;
        let n = map.free_count();
        let mut position = vec![0; n];
        for (k, &d) in structure.order.iter().enumerate() {
            position[d] = k;
        }
        let mut global = vec![0; n];
        for g in 0..map.dofs() {
            if let Some(f) = map.free(g) {
                global[position[f]] = g;
            }
        }
        // The elements around each node (compressed rows).
        let nodes = map.dofs() / NODE_DOFS;
        let mut around_start = vec![0usize; nodes + 1];
        for corners in &structure.connectivity {
            for &node in corners {
                around_start[node + 1] += 1;
            }
        }
        for i in 0..nodes {
            around_start[i + 1] += around_start[i];
        }
        let mut around = vec![0usize; around_start[nodes]];
        let mut next = around_start.clone();
        for (e, corners) in structure.connectivity.iter().enumerate() {
            for &node in corners {
                around[next[node]] = e;
                next[node] += 1;
            }
        }
        let mut node_first = vec![usize::MAX; nodes];
        for (k, &g) in global.iter().enumerate().rev() {
            node_first[g / NODE_DOFS] = k;
        }
        Self {
            structure,
            position,
            global,
            around_start,
            around,
            node_first,
        }
    }

    /// The consecutive `columns`, built on one thread.
    fn block(&self, columns: Range<usize>) -> ColumnBlock {
        let mut block = ColumnBlock {
            rows_per_column: Vec::with_capacity(columns.len()),
            rows: Vec::with_capacity(60 * columns.len()),
            counts: Vec::with_capacity(60 * columns.len()),
            codes: Vec::with_capacity(200 * columns.len()),
        };
        let mut corners_at: Vec<(usize, usize, usize)> = Vec::with_capacity(16);
        for k in columns {
            self.column(k, &mut corners_at, &mut block);
        }
        block
    }

    /// Appends column `k` to `block` (`corners_at`: storage).
    fn column(
        &self,
        k: usize,
        corners_at: &mut Vec<(usize, usize, usize)>,
        block: &mut ColumnBlock,
    ) {
        let (map, connectivity) = (&self.structure.map, &self.structure.connectivity);
        let (node, c) = (self.global[k] / NODE_DOFS, self.global[k] % NODE_DOFS);
        // For every corner of the elements around this column's
        // node: the corner node's first position, the element,
        // and where in the element matrix (24 b + 6 corner; the
        // corner's DOF d adds d) the entries lie.
        corners_at.clear();
        for &e in &self.around[self.around_start[node]..self.around_start[node + 1]] {
            let corners = &connectivity[e];
            let Some(slot) = corners.iter().position(|&m| m == node) else {
                continue;
            };
            for (corner, &m) in corners.iter().enumerate() {
                if self.node_first[m] != usize::MAX {
                    corners_at.push((
                        self.node_first[m],
                        e,
                        DOFS * (NODE_DOFS * slot + c) + NODE_DOFS * corner,
                    ));
                }
            }
        }
        corners_at.sort_unstable();
        let before = block.rows.len();
        let mut i = 0;
        while i < corners_at.len() {
            let first = corners_at[i].0;
            let group = corners_at[i..].iter().take_while(|x| x.0 == first).count();
            let m = self.global[first] / NODE_DOFS;
            for d in 0..NODE_DOFS {
                let Some(f) = map.free(NODE_DOFS * m + d) else {
                    continue;
                };
                let row = self.position[f];
                if row < k {
                    continue;
                }
                block.rows.push(row);
                block.counts.push(group);
                for &(_, e, offset) in &corners_at[i..i + group] {
                    block.codes.push((MATRIX_ENTRIES * e + offset + d) as u32);
                }
            }
            i += group;
        }
        block.rows_per_column.push(block.rows.len() - before);
    }
}

/// A block of consecutive columns of the ordered lower triangle, built on
/// one thread.
struct ColumnBlock {
    /// Values in each column.
    rows_per_column: Vec<usize>,
    /// Row of each value.
    rows: Vec<usize>,
    /// Element entries on each value.
    counts: Vec<usize>,
    /// Those entries, value after value (`576 e + a + 24 b`).
    codes: Vec<u32>,
}

/// The ordered lower triangle's columns, all blocks put together.
struct Columns {
    /// Compressed-column pointers.
    col_ptr: Vec<usize>,
    /// Row of each value.
    row_idx: Vec<usize>,
    /// Value `q`'s element entries are `gather[start[q]..start[q + 1]]`.
    start: Vec<usize>,
    /// The element entries (`576 e + a + 24 b`).
    gather: Vec<u32>,
}

impl ColumnBlock {
    /// The `n` columns of consecutive `blocks`.
    fn concatenate(n: usize, blocks: Vec<ColumnBlock>) -> Columns {
        let values: usize = blocks.iter().map(|b| b.rows.len()).sum();
        let mut col_ptr = Vec::with_capacity(n + 1);
        let mut row_idx = Vec::with_capacity(values);
        let mut start = Vec::with_capacity(values + 1);
        let mut gather = Vec::with_capacity(blocks.iter().map(|b| b.codes.len()).sum());
        col_ptr.push(0);
        start.push(0);
        for block in blocks {
            for r in block.rows_per_column {
                col_ptr.push(col_ptr[col_ptr.len() - 1] + r);
            }
            row_idx.extend(block.rows);
            for c in block.counts {
                start.push(start[start.len() - 1] + c);
            }
            gather.extend(block.codes);
        }
        Columns {
            col_ptr,
            row_idx,
            start,
            gather,
        }
    }
}

/// Element matrices packed by [`Structure::ordered_layer`]: the entries on
/// the lower triangle of the ordered stiffness, in gather order (N/m, N,
/// N m as the DOFs pair).
#[derive(Clone, Debug)]
pub struct OrderedLayer {
    values: Vec<f64>,
}

/// A stiffness over the free DOFs assembled by
/// [`Structure::assemble_ordered`]: the values of the lower triangle in the
/// structure's nested-dissection order (N/m, N, N m as the DOFs pair).
#[derive(Clone, Debug, Default)]
pub struct OrderedStiffness {
    values: Vec<f64>,
}

/// faer's sparse failures in words (its own text is Rust's debug form).
fn sparse_failure(e: FaerError) -> String {
    match e {
        FaerError::IndexOverflow => "an index overflows the sparse matrix's index type".into(),
        FaerError::OutOfMemory => "out of memory".into(),
        _ => "the sparse factorization failed".into(),
    }
}

/// The pivot that was not positive, in words (faer's own text is Rust's
/// debug form).
fn not_positive(e: PivotError) -> String {
    match e {
        PivotError::NonPositivePivot { index } => {
            format!("pivot {index} of the ordered free DOFs is not positive")
        }
    }
}
