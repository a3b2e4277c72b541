//! Native benchmark: exact verification versus the point-wise baseline on the bundled scenarios.
//!
//!     cargo run --release --example bench            # every case
//!     cargo run --release --example bench -- tree/   # the cases whose id contains "tree/"
//!     cargo run --release --example bench -- lattice # the ray lattice cases (lattice.rs) instead
//!     cargo run --release --example bench -- atlas   # the atlas planner's defaults, before/after (atlas.rs)
//!     cargo run --release --example bench -- timing  # the fastest safe timing (timing.rs)
//!     cargo run --release --example bench -- library # CASPR's multi-link library (library.rs)
//!     cargo run --release --example bench -- batotp  # the fastest safe timing against batotp (batotp.rs)
//!     cargo run --release --example bench -- batotp-preset  # writes static/scenarios/laval-cspr3dof.json
//!
//! `scripts/bench.sh` runs it together with the wasm-in-node benchmark (`tests/bench_wasm.rs`,
//! same cases from `cases.rs`) and writes `docs/benchmarks.md`.

mod atlas;
mod batotp;
mod cases;
mod lattice;
mod library;
mod timing;

fn main() {
    let origin = std::time::Instant::now();
    let now = move || origin.elapsed().as_secs_f64() * 1000.0;
    let filter = std::env::args().nth(1).unwrap_or_default();
    if filter == "atlas" {
        atlas::run_atlas();
        return;
    }
    if filter == "batotp" {
        batotp::run_batotp();
        return;
    }
    if filter == "batotp-preset" {
        batotp::run_preset();
        return;
    }
    if filter == "library" {
        library::run_library();
        return;
    }
    if filter == "timing" {
        timing::run_timing();
        return;
    }
    if filter.starts_with("lattice") {
        lattice::run_lattice("native", &filter, &now, &mut |line| println!("{line}"));
        return;
    }
    let results = cases::run_all("native", &filter, &now, &mut |line| println!("{line}"));
    let get = |c: &str| results.iter().find(|m| m.case == c).map(|m| m.median_us).unwrap_or(f64::NAN);
    eprintln!();
    for m in &results {
        eprintln!("{:34} median {:>10.1} µs, best {:>10.1} µs  ({} calls, {} samples; {})", m.case, m.median_us, m.best_us, m.calls, m.samples, m.summary);
    }
    let exact = get("tree/quadratic/exact");
    eprintln!("\npoint-wise / exact, cdpr7-tree quadratic: Δt=0.01 {:.1}×, Δt=0.001 {:.1}×",
        get("tree/quadratic/pointwise-0.01") / exact, get("tree/quadratic/pointwise-0.001") / exact);
}
