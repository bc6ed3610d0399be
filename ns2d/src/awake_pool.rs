//! A step's parallel regions with rayon's workers kept awake between
//! them.
//!
//! A step of [`crate::Flow`] is some twenty parallel regions (sweeps,
//! transforms, the grid's motion), each a few hundred microseconds on the
//! default FWAV section, with short serial parts between them. A rayon
//! worker that finds no work yields 32 times and then sleeps on a futex;
//! the next region must wake it, and a region's caller, waiting for the
//! other half, sleeps in turn and must be woken. On this project's 2-core
//! machine three strokes of the deforming default section made 700,000
//! futex calls (counted with `perf stat`), 255,000 with the workers kept
//! awake, and the wake-ups' latency was on the step's critical path.
//!
//! [`on_awake_pool`] runs an operation on a worker while each other
//! worker of the pool loops on [`rayon::yield_now`]: it takes a region's
//! other half the moment it is pushed, and does not sleep until the
//! operation ends. When it finds no work it yields its core to the
//! system (`sched_yield`), so a test or another program that wants the
//! core gets it. Measured on three strokes of the deforming default
//! section, each binary run in turn with the one of before (2026-12-05,
//! the same flow to the bit: the regions split the work as before, only
//! who waits, and how, changed): 85.1 s and 83.3 s against 88.2 s and
//! 91.8 s; with a busy spin instead of the yield, 79.2 s to 84.8 s
//! against 84.7 s to 91.8 s in four pairs, no better. The evaluation
//! benchmark (four strokes and the spin-up) took 68.8 s rigid and 105.0 s
//! deforming against 75.9 s and 110.2 s. So about 5–9 % sooner. A
//! patched rayon that yields 20,000 rounds before sleeping (a
//! measurement only, not used) gave about 10 %: the rest is the caller's
//! own waits at the end of a region, which rayon's join keeps; finer
//! blocks for the sweeps (four per thread) did not recover it.
//!
//! Only a caller from outside the pool (a single analysis, `fwav aero2d`,
//! a validation case) has the workers kept: called from a worker (the
//! discipline's rows run in parallel, one per worker), the other workers
//! have their own rows to step, and the operation runs in place as any
//! rayon job.
//!
//! Why this cannot deadlock: a spinner ends only when the operation has
//! ended, so it must never run beneath the operation on the operation's
//! own thread. The spinners are pushed before the operation starts, so
//! they are the oldest jobs on that worker's deque; the worker waits only
//! for jobs the operation pushed later and another worker stole, and
//! thieves take a deque's oldest job first, so by then every spinner has
//! been taken by another worker. A spinner left unstolen is popped by the
//! scope's end, after the operation, and returns at once. This rests on
//! rayon's deques being last in, first out for their own worker and first
//! in, first out for thieves, its default; a pool built with the
//! deprecated `breadth_first` would pop a spinner first, and nothing in
//! fwav builds one (the global pool is rayon's default).

use std::sync::atomic::{AtomicBool, Ordering};

/// Runs `op` on a worker of rayon's global pool with the pool's other
/// workers spinning beside it, ready for its parallel regions (module
/// docs); called from a worker, runs `op` in place. The spinners keep a
/// core each busy while `op` runs (yielding it to any other thread that
/// wants it). A panic in `op` still releases them and is then
/// propagated.
pub(crate) fn on_awake_pool<R: Send>(op: impl FnOnce() -> R + Send) -> R {
    if rayon::current_thread_index().is_some() {
        return op();
    }
    let done = AtomicBool::new(false);
    rayon::scope(|scope| {
        for _ in 1..rayon::current_num_threads() {
            scope.spawn(|_| spin_until(&done));
        }
        let _release = Release(&done);
        op()
    })
}

/// Runs whatever work the pool has, else yields the core, until `done`.
fn spin_until(done: &AtomicBool) {
    while !done.load(Ordering::Acquire) {
        if rayon::yield_now() != Some(rayon::Yield::Executed) {
            std::thread::yield_now();
        }
    }
}

/// Sets its flag when dropped: the spinners end when the operation does,
/// also when it panics.
struct Release<'a>(&'a AtomicBool);

impl Drop for Release<'_> {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Release);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rayon::prelude::*;

    /// The operation's parallel regions run, on the pool, and give what
    /// they give without the spinners (a sum of integers: exact).
    #[test]
    fn the_operations_regions_run_beside_the_spinners() {
        let n = 1_000_000_u64;
        for _ in 0..50 {
            let sum = on_awake_pool(|| (0..n).into_par_iter().sum::<u64>());
            assert_eq!(sum, n * (n - 1) / 2);
        }
    }

    /// Called from a worker, the operation runs on that worker, in place.
    #[test]
    fn from_a_worker_the_operation_runs_in_place() {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        pool.install(|| {
            let caller = rayon::current_thread_index();
            let inside = on_awake_pool(rayon::current_thread_index);
            assert_eq!(inside, caller);
        });
    }

    /// A panicking operation still releases the spinners (else the scope
    /// would wait for them for ever), and its panic reaches the caller.
    #[test]
    fn a_panic_releases_the_spinners_and_reaches_the_caller() {
        let caught = std::panic::catch_unwind(|| {
            on_awake_pool(|| {
                let _: u64 = (0..1000_u64).into_par_iter().sum();
                panic!("the operation failed");
            })
        });
        assert!(caught.is_err());
        // The pool is free again.
        assert_eq!(on_awake_pool(|| 7), 7);
    }
}
