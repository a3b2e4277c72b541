//! Data parallelism for the callers that answer many independent queries at once (slice maps,
//! batch verification, [`map_with`]), and for the one single query split into a few independent
//! parts: a trajectory of many pieces, verified in two runs of consecutive pieces
//! (`verify::pieces_in_parts`, [`map_parts`]). On native targets the work is spread over threads
//! with rayon; on `wasm32` (no threads in the page) it runs in order on the calling thread. Other
//! single queries (a short trajectory, one ray, one pose) never go through here: they stay
//! single-threaded.
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

/// `f(i)` for i in 0..n, in order: the first on the calling thread while rayon's workers take
/// the others — for a few parts of one query, where handing every part to the pool and waiting
/// for it would add a thread's wake-up to each call. With a pool of one thread
/// (`RAYON_NUM_THREADS=1`) every part runs on the calling thread, one after the other.
#[cfg(not(target_arch = "wasm32"))]
pub fn map_parts<T: Send>(n: usize, f: impl Fn(usize) -> T + Sync) -> Vec<T> {
    if rayon::current_num_threads() <= 1 {
        return (0..n).map(f).collect();
    }
    let mut out: Vec<Option<T>> = (0..n).map(|_| None).collect();
    if let Some((first, rest)) = out.split_first_mut() {
        let f = &f;
        rayon::in_place_scope(|scope| {
            for (i, slot) in rest.iter_mut().enumerate() {
                scope.spawn(move |_| *slot = Some(f(i + 1)));
            }
            *first = Some(f(0));
        });
    }
    out.into_iter().map(|part| part.expect("the scope ends after every part has run")).collect()
}

/// `f(i)` for i in 0..n, in order, on the calling thread (wasm32 has no threads here).
#[cfg(target_arch = "wasm32")]
pub fn map_parts<T: Send>(n: usize, f: impl Fn(usize) -> T + Sync) -> Vec<T> {
    (0..n).map(f).collect()
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

    #[test]
    fn parts_in_index_order() {
        assert_eq!(map_parts(5, |i| i * i), vec![0, 1, 4, 9, 16]);
        assert!(map_parts(0, |i| i).is_empty());
        // parts of parts: a part that splits again (as `verify --all` does with long trajectories)
        assert_eq!(map_parts(2, |i| map_parts(3, |j| 3 * i + j)), vec![vec![0, 1, 2], vec![3, 4, 5]]);
    }
}
