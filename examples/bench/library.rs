//! CASPR's multi-link library (issue 25, item 6): every model whose joint-space trajectories
//! import (docs/multilink.md), each trajectory verified exactly and point-wise at Δt = 0.01 in
//! one run, natively:
//!
//!     cargo run --release --example bench -- library
//!
//! prints one markdown table row per trajectory (`scripts/bench.sh --library` writes them to the
//! "CASPR's multi-link library" section of docs/benchmarks.md): the model's size, the median of
//! three runs of each method, their ratio and both answers. The models are read from
//! `../shared/models/caspr/` as `cablenav import` reads them.

use cablenav::scenario::caspr::model_to_json;
use cablenav::report::VerifyReport;
use cablenav::verify::{along, verify_along, verify_pointwise_along};
use cablenav::Scenario;
use std::time::Instant;

/// The library's models with joint-space trajectories that import (the others have none, or
/// none at rest at their knots: docs/multilink.md).
const MODELS: [&str; 5] = ["8S_neck", "SJTUSnake", "4U_modular_units_arm", "BMArm", "BioBiped_one_leg"];
/// Timed runs per method and trajectory.
const RUNS: usize = 3;
/// The point-wise baseline's step in t.
const DT: f64 = 0.01;

/// A model imported from its CASPR files with its trajectories.
fn import(model: &str) -> Scenario {
    let file = |suffix: &str| {
        let path = format!("{}/../shared/models/caspr/{model}/{model}_{suffix}.xml", env!("CARGO_MANIFEST_DIR"));
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
    };
    let imported = model_to_json(model, &file("bodies"), &file("cables"), Some(&file("trajectories")), None).unwrap_or_else(|e| panic!("{model}: {e}"));
    Scenario::from_json(&imported.json).unwrap_or_else(|e| panic!("{model}: {e}"))
}

/// The median time of [`RUNS`] runs of `f` in seconds, and its last report.
fn timed(f: &dyn Fn() -> VerifyReport) -> (f64, VerifyReport) {
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..RUNS {
        let started = Instant::now();
        last = Some(f());
        times.push(started.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[RUNS / 2], last.expect("runs"))
}

/// A report's sections, short: the infeasible ones (else "feasible throughout") and the
/// uncertain ones.
fn answer(r: &VerifyReport) -> String {
    let list = |s: &[[f64; 2]]| s.iter().map(|[a, b]| format!("[{a:.3}, {b:.3}]")).collect::<Vec<_>>().join(" ∪ ");
    let mut out = if r.infeasible.is_empty() { "feasible throughout".to_string() } else { format!("infeasible {}", list(&r.infeasible)) };
    if !r.uncertain.is_empty() {
        out += &format!("; uncertain {}", list(&r.uncertain));
    }
    out
}

/// A time, in ms below a second.
fn seconds(s: f64) -> String {
    if s < 1.0 { format!("{:.1} ms", s * 1000.0) } else { format!("{s:.2} s") }
}

/// Runs every model's trajectories, printing a markdown row per trajectory.
pub fn run_library() {
    for model in MODELS {
        let s = import(model);
        let chain = s.robot.chain.as_ref().expect("a multi-link model");
        let size = format!("{} DoF, {} cables, {} segments", chain.dof(), s.robot.cables.len(), s.robot.segments().len());
        for path in &s.joint_paths {
            let route = || along(&s, Some(&path.name)).expect("the imported path");
            let (exact, exact_report) = timed(&|| verify_along(&s, route()).expect("verifies"));
            let (sampled, sampled_report) = timed(&|| verify_pointwise_along(&s, route(), DT).expect("samples"));
            println!(
                "| {model} | `{}` | {size} | {} | {} | {:.2}× | {} | {} |",
                path.name,
                seconds(exact),
                seconds(sampled),
                sampled / exact,
                answer(&exact_report),
                answer(&sampled_report)
            );
        }
    }
}
