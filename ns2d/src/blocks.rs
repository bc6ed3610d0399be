//! Blocks of columns for the parallel sweeps: a field stored ring by ring
//! (rings contiguous) is swept along its columns (radial lines, Fourier
//! modes) with the columns of a block side by side, one block per worker
//! thread. Used by the radial sweeps ([`crate::Flow`]) and the
//! streamfunction's mode systems ([`crate::stream`]). Nothing a block
//! computes may depend on which columns share it (a test over a block's
//! columns, say), or the flow would change with the thread count:
//! `tests/thread_count.rs` runs flows on one, two and three threads and
//! asserts them the same to the bit.

/// The bounds of the blocks of columns `start..end`: one block per worker
/// thread (fewer if there are fewer columns).
pub(crate) fn bounds(start: usize, end: usize) -> Vec<usize> {
    let columns = end - start;
    let blocks = rayon::current_num_threads().clamp(1, columns);
    (0..=blocks).map(|b| start + b * columns / blocks).collect()
}

/// Each ring of `data` (rings of `width`) cut at the columns `bounds`
/// (those before `bounds[0]` and from the last bound on are left out): per
/// block, its pieces of every ring.
pub(crate) fn pieces<'a, T>(
    data: &'a mut [T],
    width: usize,
    bounds: &[usize],
) -> Vec<Vec<&'a mut [T]>> {
    let blocks = bounds.len() - 1;
    let mut out: Vec<Vec<&mut [T]>> = (0..blocks)
        .map(|_| Vec::with_capacity(data.len() / width))
        .collect();
    for ring in data.chunks_mut(width) {
        let (_, mut rest) = ring.split_at_mut(bounds[0]);
        for (b, block) in out.iter_mut().enumerate() {
            let (piece, tail) = rest.split_at_mut(bounds[b + 1] - bounds[b]);
            block.push(piece);
            rest = tail;
        }
    }
    out
}
