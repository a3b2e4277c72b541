//! Shared test support: an independent reference model of cablenav's documented semantics
//! (`reference`), written from the definitions and not from `src/`; deterministic random
//! scenarios (`gen`); the largest-margin tensions by a linear program (`lp`); and the sampling checker that compares cablenav's reports with the
//! reference (`harness`).
#![allow(dead_code)]

pub mod gen;
pub mod harness;
pub mod lp;
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

/// A report's verdict at t: Some(feasible) inside a reported interval at least `gap` from its
/// ends, None near a boundary or in (or within `gap` of) an uncertain interval.
pub fn reported(r: &cablenav::report::VerifyReport, t: f64, gap: f64) -> Option<bool> {
    let inside = |iv: &[f64; 2]| t > iv[0] + gap && t < iv[1] - gap;
    let near = |iv: &[f64; 2]| t >= iv[0] - gap && t <= iv[1] + gap;
    if r.uncertain.iter().any(near) {
        return None;
    }
    if r.feasible.iter().any(inside) {
        Some(true)
    } else if r.infeasible.iter().any(inside) {
        Some(false)
    } else {
        None
    }
}

/// The boundaries of a report that stand alone — no other boundary within 2·`gap`, no uncertain
/// interval within 2·`gap`, t ± `gap` inside [0, 1] — each with t − `gap` and t + `gap`, and
/// whether the motion enters the feasible set there: where a reference's verdicts on either side
/// must be the reported ones.
pub fn lone_boundaries(r: &cablenav::report::VerifyReport, gap: f64) -> Vec<(&cablenav::report::Boundary, f64, f64, bool)> {
    r.boundaries
        .iter()
        .filter_map(|b| {
            let (lo, hi) = (b.t - gap, b.t + gap);
            let crowded = r.boundaries.iter().any(|o| o.t != b.t && (o.t - b.t).abs() < 2.0 * gap) || r.uncertain.iter().any(|u| u[0] < hi + gap && u[1] > lo - gap);
            (!crowded && lo >= 0.0 && hi <= 1.0).then_some((b, lo, hi, b.enters == cablenav::report::Side::Feasible))
        })
        .collect()
}
