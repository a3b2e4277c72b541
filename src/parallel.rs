//! Data parallelism for the callers that answer many independent queries at once (slice maps,
//! batch verification), and for the one single query split into independent parts: a trajectory
//! of many pieces, verified in two runs of consecutive pieces (`verify::pieces_in_parts`). On
//! native targets the work is spread over threads with rayon; on `wasm32` (no threads in the
//! page) it runs in order on the calling thread. Other single queries (a short trajectory, one
//! ray, one pose) never go through here: they stay single-threaded.
//!
//! Results come back in index order either way, so the output does not depend on the schedule.

/// `f(state, i)` for i in 0..n, in order. Each worker thread builds its own `state` with
/// `init` once (for what cannot be shared between threads, e.g. a scenario's conditions) and
/// reuses it for the indices it takes.
#[cfg(not(target_arch = "wasm32"))]
pub fn map_with<S, T: Send>(n: usize, init: impl Fn() -> S + Sync + Send, f: impl Fn(&mut S, usize) -> T + Sync + Send) -> Vec<T> {
    use rayon::prelude::*;
    (0..n).into_par_iter().map_init(init, f).collect()
}

/// `f(state, i)` for i in 0..n, in order, on the calling thread (wasm32 has no threads here).
#[cfg(target_arch = "wasm32")]
pub fn map_with<S, T: Send>(n: usize, init: impl Fn() -> S + Sync + Send, f: impl Fn(&mut S, usize) -> T + Sync + Send) -> Vec<T> {
    let mut state = init();
    (0..n).map(|i| f(&mut state, i)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::rc::Rc;

    #[test]
    fn results_in_index_order_with_per_worker_state() {
        // Rc is not Send: each worker must build its own state.
        let out = map_with(1000, || Rc::new(3usize), |k, i| i * **k);
        assert_eq!(out, (0..1000).map(|i| 3 * i).collect::<Vec<_>>());
    }
}
