//! Shared test support: an independent reference model of cablenav's documented semantics
//! (`reference`), written from the definitions and not from `src/`; deterministic random
//! scenarios (`gen`); and the sampling checker that compares cablenav's reports with the
//! reference (`harness`).
#![allow(dead_code)]

pub mod gen;
pub mod harness;
pub mod reference;

/// A count from the environment variable `name` (native only; tests use it to scale their work),
/// else `default`.
pub fn env_usize(name: &str, default: usize) -> usize {
    #[cfg(not(target_arch = "wasm32"))]
    if let Some(v) = std::env::var(name).ok().and_then(|v| v.parse().ok()) {
        return v;
    }
    let _ = name;
    default
}

/// `per(0..n)` in input order, on two worker threads natively (sequentially in wasm).
#[cfg(not(target_arch = "wasm32"))]
pub fn on_two_threads<T: Send>(n: usize, per: &(dyn Fn(usize) -> T + Sync)) -> Vec<T> {
    let mut out: Vec<(usize, T)> = std::thread::scope(|s| {
        let handles: Vec<_> =
            (0..2).map(|w| s.spawn(move || (0..n).filter(|i| i % 2 == w).map(|i| (i, per(i))).collect::<Vec<_>>())).collect();
        handles.into_iter().flat_map(|h| h.join().expect("worker panicked")).collect()
    });
    out.sort_by_key(|r| r.0);
    out.into_iter().map(|r| r.1).collect()
}

/// `per(0..n)` in input order.
#[cfg(target_arch = "wasm32")]
pub fn on_two_threads<T>(n: usize, per: &dyn Fn(usize) -> T) -> Vec<T> {
    (0..n).map(per).collect()
}
