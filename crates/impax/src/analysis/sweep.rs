//! A deterministic parallel sweep driver with constant memory.
//!
//! The index range `0..total` is cut into fixed chunks of `chunk` points. Chunks are
//! computed in parallel (rayon, in the current thread pool) a wave at a time and handed to
//! the caller's sink **in index order**, while the next wave is being computed. The sink
//! (where a front end writes CSV, fills a map or tallies) therefore sees the same sequence
//! of chunk results whatever the number of threads, and at most two waves of chunk results
//! exist at once: memory does not grow with `total`.
//!
//! The library does no I/O: the caller's `work` turns an index range into a value (e.g.
//! formatted rows), and the caller's `sink` consumes it.
//!
//! ```
//! use impax::analysis::run_ordered;
//! let mut seen = Vec::new();
//! run_ordered(10, 3, |r| r.clone().map(|i| i * i).collect::<Vec<u64>>(), |chunk| {
//!     seen.extend(chunk);
//!     Ok::<(), ()>(())
//! })
//! .unwrap();
//! assert_eq!(seen, (0..10).map(|i| i * i).collect::<Vec<_>>());
//! ```

use rayon::prelude::*;
use std::ops::Range;

/// How many chunks [`run_ordered`] computes per wave and per thread (enough to balance
/// uneven chunks while the results of two waves stay small, e.g. megabytes of CSV rows).
pub const CHUNKS_PER_THREAD: usize = 4;

/// Compute `work(range)` for consecutive ranges of `chunk` indices covering `0..total`, in
/// parallel, and pass the results to `sink` in index order.
///
/// Stops at the first error of `sink` and returns it. `chunk = 0` is taken as 1.
pub fn run_ordered<T, E, W, S>(total: u64, chunk: u64, work: W, sink: S) -> Result<(), E>
where
    T: Send,
    E: Send,
    W: Fn(Range<u64>) -> T + Sync,
    S: FnMut(T) -> Result<(), E> + Send,
{
    run_ordered_waves(total, chunk, CHUNKS_PER_THREAD, work, sink)
}

/// [`run_ordered`] with `chunks_per_thread` chunks per wave and per thread (at least 1).
///
/// Each wave ends when its slowest chunk does, so a thread can idle for up to one chunk per
/// wave: with small chunk results (a tally, a few numbers) a long wave (e.g. 64 chunks per
/// thread) keeps every core busy; with large ones (rows of text) a short wave bounds the
/// memory (two waves of results at most). The order of the results seen by `sink` does not
/// depend on `chunks_per_thread` nor on the number of threads.
pub fn run_ordered_waves<T, E, W, S>(
    total: u64,
    chunk: u64,
    chunks_per_thread: usize,
    work: W,
    mut sink: S,
) -> Result<(), E>
where
    T: Send,
    E: Send,
    W: Fn(Range<u64>) -> T + Sync,
    S: FnMut(T) -> Result<(), E> + Send,
{
    let chunk = chunk.max(1);
    let n_chunks = total.div_ceil(chunk);
    let wave = (rayon::current_num_threads() * chunks_per_thread.max(1)).max(1) as u64;
    let range_of = |c: u64| c * chunk..((c + 1) * chunk).min(total);
    let compute = |first: u64| -> Vec<T> {
        let last = (first + wave).min(n_chunks);
        (first..last)
            .into_par_iter()
            .map(|c| work(range_of(c)))
            .collect()
    };
    let mut current = compute(0);
    let mut next_first = wave;
    while !current.is_empty() {
        let (next, drained) = rayon::join(
            || {
                if next_first < n_chunks {
                    compute(next_first)
                } else {
                    Vec::new()
                }
            },
            || {
                for t in current {
                    sink(t)?;
                }
                Ok(())
            },
        );
        drained?;
        current = next;
        next_first += wave;
    }
    Ok(())
}
