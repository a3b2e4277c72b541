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
