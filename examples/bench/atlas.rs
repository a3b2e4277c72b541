//! The atlas planner's adaptive defaults against its former ones (fixed chart radius 0.4, plain
//! A*) on the Robocrane queries, natively, in one run:
//!
//!     cargo run --release --example bench -- atlas
//!
//! prints one markdown table row per query and setting (`scripts/bench.sh --atlas` writes them to
//! the "Atlas planner defaults" section of docs/benchmarks.md). A query that takes under half a
//! second is run five times and its median reported; slower ones once (the former defaults on the
//! 6-D query run out of a 1500-chart budget after minutes).

use cablenav::model::Coord;
use cablenav::plan::atlas::{AtlasPlanner, PlanOutcome, PlanParams};
use cablenav::scenario::Query;
use cablenav::Scenario;
use std::f64::consts::PI;
use std::time::Instant;

/// What one planning problem is.
enum Problem {
    /// A query of the scenario.
    Query(&'static str),
    /// Start and goal as raw coordinates with the angles as plain coordinates (paper 1's q3 → q4).
    PaperCoords([f64; 6], [f64; 6]),
}

/// Runs the comparison, printing a markdown row per query and setting.
pub fn run_atlas() {
    let mut crane = Scenario::from_json(include_str!("../../static/scenarios/robocrane.json")).expect("robocrane.json");
    let slice = vec![Coord::X, Coord::Y, Coord::Z, Coord::Sigma];
    // The island of the slice p = [0, 0, 2], σ = 35° (tests/plan.rs, robocrane_other_component_is_no_path):
    // the centre of cell (66, 61) of the 72 × 72 slice map over (φ, θ) ∈ [−π, π]².
    let cell = |i: f64| -PI + (i + 0.5) * 2.0 * PI / 72.0;
    crane.poses.push(("island".to_string(), cablenav::model::Pose::from_coords([0.0, 0.0, 2.0, cell(66.0), cell(61.0), 7.0 * PI / 36.0])));
    let query = |name: &str, start: &str, goal: &str, fixed: Vec<Coord>| Query { name: name.into(), start: start.into(), goal: goal.into(), fixed, region: vec![] };
    crane.queries.push(query("island-q1", "island", "q1", slice.clone()));
    crane.queries.push(query("q1-q2-6d", "q1", "q2", vec![]));
    let sigma = 7.0 * PI / 36.0;
    let problems = [
        ("q1-q2", "p = [0,0,2], σ = 35° (2-D)", Problem::Query("q1-q2")),
        ("q3-q4 (rotations identified)", "p = [0,0,2], σ = 35° (2-D)", Problem::Query("q3-q4")),
        ("q3-q4 in the paper coordinates", "p = [0,0,2], σ = 35° (2-D)", Problem::PaperCoords([0.0, 0.0, 2.0, 0.8, -2.4, sigma], [0.0, 0.0, 2.0, -2.4, 2.4, sigma])),
        ("island → q1", "p = [0,0,2], σ = 35° (2-D)", Problem::Query("island-q1")),
        ("q5-q6", "x = y = 0, σ = 35° (3-D)", Problem::Query("q5-q6")),
        ("q1-q2, nothing fixed", "the whole C-space (6-D)", Problem::Query("q1-q2-6d")),
    ];
    let before = PlanParams { radius: 0.4, min_radius: 0.4, heuristic_weight: 1.0, max_charts: 1500, ..PlanParams::default() };
    let settings = [("before: r = 0.4 fixed, A*, ≤ 1500 charts", before), ("after: defaults", PlanParams::default())];
    for (name, slice_text, problem) in &problems {
        for (setting, params) in &settings {
            let once = || {
                let start = Instant::now();
                let mut p = match problem {
                    Problem::Query(q) => AtlasPlanner::new(&crane, q, *params),
                    Problem::PaperCoords(a, b) => AtlasPlanner::between_coords(&crane, *a, *b, &slice, PlanParams { identify_angles: false, ..*params }),
                }
                .expect("planner");
                while p.step(1000).done.is_none() {}
                let out: PlanOutcome = p.outcome().expect("outcome");
                (start.elapsed().as_secs_f64(), out)
            };
            let (first, out) = once();
            let mut times = vec![first];
            if first < 0.5 {
                times.extend((0..4).map(|_| once().0));
            }
            times.sort_by(f64::total_cmp);
            let median = times[times.len() / 2];
            let [lo, hi] = out.atlas.chart_radii;
            let radii = if lo < hi { format!("{lo:.2}–{hi:.2}") } else { format!("{hi}") };
            let v = &out.verification;
            let path = if out.path.is_empty() { "–".to_string() } else { format!("{} poses, {} infeasible, {} uncertain", out.path.len(), v.infeasible_sections, v.uncertain_sections) };
            println!(
                "| {name} | {slice_text} | {setting} | {} | {} | {radii} | {path} | {} | {} s |",
                out.status.name(),
                out.charts,
                if times.len() > 1 { format!("median of {}", times.len()) } else { "1 run".to_string() },
                if median < 1.0 { format!("{:.3}", median) } else { format!("{:.1}", median) }
            );
        }
    }
}
