//! A fill-reducing ordering of a shell mesh's free DOFs by geometric
//! nested dissection (George 1973, "Nested dissection of a regular finite
//! element mesh", SIAM J. Numer. Anal. 10; George & Liu 1981, "Computer
//! Solution of Large Sparse Positive Definite Systems", ch. 8): the nodes
//! are split in two halves at the median of a coordinate, the nodes of one
//! half that touch the other form a separator, and the two halves, then the
//! separator, are ordered recursively. On a 2D mesh of `N` nodes the
//! Cholesky factor then holds `O(N log N)` entries and costs `O(N^1.5)`
//! flops.
//!
//! On the default wing (6943 nodes, 41 592 free DOFs) against faer's
//! approximate minimum degree (AMD): the same 8.2 M stored factor values,
//! but 2.06 against 2.29 GFlop and fewer, larger supernodes (2312 against
//! 2654), so faer's sequential numeric factorization takes about 0.08 s
//! against 0.11 s (measured on the 2-core development machine).
//!
//! A node's free DOFs stay together, in component order (the stiffness is
//! made of 6 x 6 node blocks); fully held nodes take no part.

use super::assembly::{AssemblyError, DofMap};
use super::element::NODE_DOFS;
use super::mesh::ShellMesh;

/// Subsets of at most this many nodes are not dissected further (their
/// factor is small and dense anyway). On the default wing, 4 to 16 give
/// the fastest factorization, 32 to 128 a 10 to 40% slower one.
const LEAF_NODES: usize = 8;

/// The free DOF indices (as numbered by `map`) in elimination order:
/// entry `k` is the free DOF eliminated `k`-th (faer's forward
/// permutation); every free DOF of `map` appears exactly once. `map` must
/// be over the DOFs of `mesh` (else [`AssemblyError::Length`]). Cost
/// `O(N log^2 N)` for `N` nodes.
pub fn nested_dissection(mesh: &ShellMesh, map: &DofMap) -> Result<Vec<usize>, AssemblyError> {
    if map.dofs() != mesh.dofs() {
        return Err(AssemblyError::Length {
            got: map.dofs(),
            expected: mesh.dofs(),
        });
    }
    let free_of = |node: usize| (0..NODE_DOFS).filter_map(move |c| map.free(NODE_DOFS * node + c));
    // The nodes with a free DOF and their neighbours (through elements)
    // among them, as compressed rows.
    let active: Vec<usize> = (0..mesh.nodes.len())
        .filter(|&node| free_of(node).next().is_some())
        .collect();
    let mut local = vec![usize::MAX; mesh.nodes.len()];
    for (i, &node) in active.iter().enumerate() {
        local[node] = i;
    }
    let mut pairs: Vec<(usize, usize)> = Vec::with_capacity(12 * mesh.elements.len());
    for corners in &mesh.elements {
        for &a in corners {
            for &b in corners {
                let (la, lb) = (local[a], local[b]);
                if a != b && la != usize::MAX && lb != usize::MAX {
                    pairs.push((la, lb));
                }
            }
        }
    }
    pairs.sort_unstable();
    pairs.dedup();
    let mut start = vec![0; active.len() + 1];
    for &(a, _) in &pairs {
        start[a + 1] += 1;
    }
    for i in 0..active.len() {
        start[i + 1] += start[i];
    }
    let graph = Graph {
        start,
        adjacent: pairs.iter().map(|&(_, b)| b).collect(),
        position: active.iter().map(|&node| mesh.nodes[node].into()).collect(),
    };
    let mut order = Vec::with_capacity(active.len());
    let mut side = vec![Side::Out; active.len()];
    dissect(&graph, (0..active.len()).collect(), &mut side, &mut order);
    Ok(order.into_iter().flat_map(|i| free_of(active[i])).collect())
}

/// The node graph the dissection works on (local node indices).
struct Graph {
    /// `adjacent[start[i]..start[i + 1]]` are the neighbours of node `i`.
    start: Vec<usize>,
    adjacent: Vec<usize>,
    /// Node positions, m.
    position: Vec<[f64; 3]>,
}

impl Graph {
    fn neighbours(&self, i: usize) -> &[usize] {
        &self.adjacent[self.start[i]..self.start[i + 1]]
    }
}

/// Where a node stands in the current split.
#[derive(Clone, Copy, PartialEq)]
enum Side {
    /// Not in the subset being split.
    Out,
    Low,
    High,
}

/// Appends the elimination order of `nodes` to `order`: the low half, the
/// high half (each dissected recursively), then the separator. `side` is
/// all `Out` on entry and on return.
fn dissect(graph: &Graph, nodes: Vec<usize>, side: &mut [Side], order: &mut Vec<usize>) {
    if nodes.len() <= LEAF_NODES {
        order.extend(nodes);
        return;
    }
    // The median split along each axis; keep the one with the smallest
    // separator (the high-side nodes touching the low side).
    let mut best: Option<(Vec<usize>, Vec<usize>, Vec<usize>)> = None;
    for axis in 0..3 {
        let mut sorted = nodes.clone();
        sorted.sort_unstable_by(|&a, &b| {
            graph.position[a][axis]
                .total_cmp(&graph.position[b][axis])
                .then(a.cmp(&b))
        });
        // The split nearest the median between two different coordinates,
        // so that a mesh line of equal coordinates stays on one side.
        let x = |k: usize| graph.position[sorted[k]][axis];
        let half = sorted.len() / 2;
        let above = (half..sorted.len()).find(|&k| x(k - 1) < x(k));
        let below = (1..=half).rev().find(|&k| x(k - 1) < x(k));
        let split = match (below, above) {
            (Some(b), Some(a)) => {
                if half - b <= a - half {
                    b
                } else {
                    a
                }
            }
            (Some(k), None) | (None, Some(k)) => k,
            // All at one coordinate: a flat direction.
            (None, None) => continue,
        };
        let (low, high) = sorted.split_at(split);
        for &i in low {
            side[i] = Side::Low;
        }
        for &i in high {
            side[i] = Side::High;
        }
        let (separator, rest): (Vec<usize>, Vec<usize>) = high
            .iter()
            .partition(|&&i| graph.neighbours(i).iter().any(|&j| side[j] == Side::Low));
        for &i in &nodes {
            side[i] = Side::Out;
        }
        if best
            .as_ref()
            .is_none_or(|(_, _, best_separator)| separator.len() < best_separator.len())
        {
            best = Some((low.to_vec(), rest, separator));
        }
    }
    match best {
        Some((low, high, separator)) => {
            dissect(graph, low, side, order);
            dissect(graph, high, side, order);
            order.extend(separator);
        }
        // All nodes at one point: nothing to split geometrically.
        None => order.extend(nodes),
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use super::*;
    use crate::shell::assembly::pressure_loads;
    use crate::shell::element::{self, ElementMatrix};
    use crate::shell::linear::LinearStatic;
    use crate::shell::material::{Layer, Section};
    use crate::shell::structure::{OrderedFactor, Structure};

    #[test]
    fn a_permutation_of_the_free_dofs() {
        let mesh = ShellMesh::rectangle(2.0, 1.0, 30, 14).unwrap();
        let fixed: Vec<usize> = mesh
            .nodes_where(|p| p.x.abs() < 1e-9)
            .into_iter()
            .flat_map(|n| (0..6).map(move |c| 6 * n + c))
            .chain([6 * 40 + 2])
            .collect();
        let map = DofMap::new(mesh.dofs(), &fixed).unwrap();
        let order = nested_dissection(&mesh, &map).unwrap();
        assert_eq!(order.len(), map.free_count());
        let mut seen = vec![false; map.free_count()];
        for &d in &order {
            assert!(!seen[d], "free DOF {d} twice");
            seen[d] = true;
        }
        // A node's free DOFs stay together and in order.
        let node_40: Vec<usize> = (0..6).filter_map(|c| map.free(6 * 40 + c)).collect();
        let at = order.iter().position(|&d| d == node_40[0]).unwrap();
        assert_eq!(&order[at..at + 5], &node_40[..]);
    }

    /// The nested-dissection path (lower triangle assembled in the new
    /// order from a base plus scaled element matrices, factorized, solved
    /// for several load cases at once) gives the displacements of faer's
    /// AMD path on the same matrix, on a cantilever plate with a clamped
    /// edge and one more held DOF, before and after a refactorization with
    /// new scales.
    #[test]
    fn a_solve_matches_the_amd_path() {
        let mesh = ShellMesh::rectangle(0.2, 0.1, 24, 11).unwrap();
        let fixed: Vec<usize> = mesh
            .nodes_where(|p| p.x.abs() < 1e-9)
            .into_iter()
            .flat_map(|n| (0..6).map(move |c| 6 * n + c))
            .chain([6 * 30 + 1])
            .collect();
        let structure = Arc::new(Structure::new(&mesh, &fixed).unwrap());
        let n = mesh.elements.len();
        let stiffness = |layer: &Layer| -> Vec<ElementMatrix> {
            (0..n)
                .map(|e| element::stiffness(&mesh.corners(e), &Section::single(layer)))
                .collect()
        };
        let (skin, carbon) = (stiffness(&Layer::MYLAR), stiffness(&Layer::CARBON));
        let loads: Vec<Vec<f64>> = (0..3)
            .map(|k| {
                let p: Vec<f64> = (0..n)
                    .map(|e| 10.0 + k as f64 * mesh.corners(e)[0].x * 100.0)
                    .collect();
                let mut f = pressure_loads(&mesh, &p).unwrap();
                f[6 * (mesh.nodes.len() - 1) + k] += 0.1;
                f
            })
            .collect();
        let base = structure
            .assemble_ordered(
                &structure.ordered_layer(&skin).unwrap(),
                &vec![1.0; n],
                None,
            )
            .unwrap();
        let layer = structure.ordered_layer(&carbon).unwrap();
        let mut factor: Option<OrderedFactor> = None;
        for round in 0..2 {
            let scales: Vec<f64> = (0..n)
                .map(|e| 1e-3 + ((e * (7 + round)) % 13) as f64 / 13.0)
                .collect();
            let k = structure
                .assemble_ordered(&layer, &scales, Some(&base))
                .unwrap();
            match factor.as_mut() {
                Some(f) => f.refactorize(&k).unwrap(),
                None => factor = Some(OrderedFactor::new(&structure, &k).unwrap()),
            }
            let u = factor.as_ref().unwrap().solve(&loads).unwrap();
            let matrices: Vec<ElementMatrix> =
                (0..n).map(|e| skin[e] + carbon[e] * scales[e]).collect();
            let reference = LinearStatic::from_element_matrices(structure.clone(), &matrices)
                .unwrap()
                .solve(&loads)
                .unwrap();
            // Two orderings round differently: about 1e-9 of the largest
            // displacement here (mylar beside carbon, the drilling penalty:
            // an ill-conditioned stiffness).
            for (l, r) in reference.iter().enumerate() {
                let size = r.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                let error = r.iter().enumerate().fold(0.0f64, |m, (d, r)| {
                    m.max((u[d * loads.len() + l] - r).abs())
                });
                println!(
                    "round {round}, case {l}: largest difference {:.1e} of {size:.3e}",
                    error / size
                );
                assert!(
                    size > 0.0 && error <= 1e-7 * size,
                    "round {round}, case {l}"
                );
            }
        }
    }

    #[test]
    fn the_structure_is_shared_between_threads() {
        fn send_sync<T: Send + Sync>() {}
        send_sync::<Structure>();
    }
}
