//! Wasm-in-node benchmark: the same cases as the native `examples/bench` (shared `cases.rs`),
//! timed with node's `performance.now()`. Compiled only for wasm32 with the `bench` feature, so
//! the ordinary `wasm-pack test --node` run of the crate skips it:
//!
//!     wasm-pack test --node --release -- --features bench --test bench_wasm
//!
//! `scripts/bench.sh` runs it and collects the `BENCH wasm …` lines it logs.
#![cfg(all(target_arch = "wasm32", feature = "bench"))]

#[path = "../examples/bench/cases.rs"]
mod cases;
#[path = "../examples/bench/lattice.rs"]
mod lattice;

use wasm_bindgen::prelude::wasm_bindgen;
use wasm_bindgen_test::{console_log, wasm_bindgen_test};

#[wasm_bindgen]
extern "C" {
    /// node's high-resolution clock, in milliseconds (sub-microsecond resolution).
    #[wasm_bindgen(js_namespace = performance, js_name = now)]
    fn performance_now() -> f64;
}

#[wasm_bindgen_test]
fn bench_wasm() {
    let now = || performance_now();
    cases::run_all("wasm", "", &now, &mut |line| console_log!("{line}"));
}

/// The ray lattice cases (`scripts/bench.sh --lattice` runs only this test).
#[wasm_bindgen_test]
fn bench_wasm_lattice() {
    let now = || performance_now();
    lattice::run_lattice("wasm", "", &now, &mut |line| console_log!("{line}"));
}
