//! The benchmark cases, shared by the native benchmark (`examples/bench/main.rs`) and the
//! wasm-in-node one (`tests/bench_wasm.rs`, which includes this file by path), so both time
//! exactly the same work. The clock is passed in: `std::time::Instant` natively,
//! `performance.now()` under node.
//!
//! Each case prints one machine-readable line that `scripts/bench.sh` collects:
//! `BENCH <platform> <case> <median_us> <best_us> <calls> <samples> <summary>`.

use cablenav::model::Coord;
use cablenav::plan::atlas::{plan, AtlasPlanner, PlanOutcome, PlanParams};
use cablenav::query::wrench::tension_ranges;
use cablenav::verify::{ray, slice, slice::default_range, verify_pointwise, verify_sections, verify_trajectory};
use cablenav::Scenario;

const CDPR7: &str = include_str!("../../static/scenarios/cdpr7.json");
const CDPR7_TREE: &str = include_str!("../../static/scenarios/cdpr7-tree.json");
const CDPR7_BOX: &str = include_str!("../../static/scenarios/cdpr7-box.json");
const ROBOCRANE: &str = include_str!("../../static/scenarios/robocrane.json");
const ROBOCRANE_TIMED: &str = include_str!("../../static/scenarios/robocrane-timed.json");
const COGIRO: [&str; 3] = [
    include_str!("../../../shared/models/caspr/CoGiRo/CoGiRo_bodies.xml"),
    include_str!("../../../shared/models/caspr/CoGiRo/CoGiRo_cables.xml"),
    include_str!("../../../shared/models/caspr/CoGiRo/CoGiRo_trajectories.xml"),
];

/// The Robocrane preset plus a slerp from q1 tilting on to θ = 1.4, past the tension bound (the
/// trajectory of `tests/wrench_exact.rs`).
fn robocrane_tilt() -> Scenario {
    let mut v: serde_json::Value = serde_json::from_str(ROBOCRANE).expect("bundled scenario is JSON");
    v["poses"]["tilted"] = serde_json::json!({"position": [0, 0, 2], "tilt_torsion": [-0.5, 1.4, 0.6108652381980153]});
    v["trajectories"] = serde_json::json!([
        {"name": "slerp q1-q2", "translation": {"line": [[0, 0, 2], [0, 0, 2]]}, "orientation": {"slerp": ["q1", "q2"]}},
        {"name": "tilt", "translation": {"line": [[0, 0, 2], [0, 0, 2]]}, "orientation": {"slerp": ["q1", "tilted"]}}
    ]);
    Scenario::from_json(&v.to_string()).expect("robocrane tilt parses")
}

/// A cable-suspended platform on 64 cables (a ring of anchors above, two below; 1 kg, tensions
/// in [0, 3] N) on a timed slerp with a linear translation, 1 s; without a wrench section (the
/// linear-program certificates of `conditions::wrench_lp`), or with a wrench ball of `radius`
/// around zero (the cover of wrench directions).
fn ring64(radius: Option<f64>) -> Scenario {
    let cables: Vec<serde_json::Value> = (0..64)
        .map(|k| {
            let angle = 2.0 * std::f64::consts::PI * k as f64 / 64.0;
            let below = k < 2;
            let twist = if k % 2 == 0 { 0.6 } else { -0.6 };
            serde_json::json!({
                "base": [2.0 * angle.cos(), 2.0 * angle.sin(), if below { 4.0 } else { 0.0 }],
                "platform": [0.4 * (angle + twist).cos(), 0.4 * (angle + twist).sin(), if below { 0.1 } else { -0.1 }]
            })
        })
        .collect();
    let q = [1.0, 0.1, 0.1, 0.18];
    let norm = q.iter().map(|x: &f64| x * x).sum::<f64>().sqrt();
    let v = serde_json::json!({
        "format": "cablenav-scenario/4",
        "name": "ring64",
        "robot": {
            "cables": cables,
            "tension": {"min": 0.0, "max": 3.0},
            "dynamics": {"mass": 1.0, "com": [0, 0, -0.02], "inertia": [[0.05, 0, 0], [0, 0.05, 0], [0, 0, 0.08]], "gravity": [0, 0, 10.0]}
        },
        "trajectories": [{
            "name": "sweep", "duration": 1.0,
            "translation": {"polynomial": [[0.0, 0.3], [0.0, -0.2], [2.2, 0.1]]},
            "orientation": {"slerp": [[1, 0, 0, 0], q.map(|x| x / norm)]}
        }]
    });
    let mut v = v;
    if let Some(r) = radius {
        v["wrench"] = serde_json::json!({"nominal": [0, 0, 0, 0, 0, 0], "radius": r});
    }
    Scenario::from_json(&v.to_string()).expect("ring64 parses")
}

/// The radius of the wrench ball of the 64-cable ring's second case (N and N·m).
pub const RING_BALL: f64 = 0.2;

/// Wall time spent measuring each case (after warm-up), in milliseconds.
pub const CASE_MS: f64 = 1000.0;
/// Each sample repeats the call until it lasts at least this long (timer resolution), in ms.
const SAMPLE_MS: f64 = 2.0;
/// Warm-up before measuring each case (also finds the calls per sample), in milliseconds.
const WARMUP_MS: f64 = 200.0;
/// Fewest samples per case, whatever their length.
const MIN_SAMPLES: usize = 15;

/// One measured case.
pub struct Measured {
    /// Case id, e.g. `tree/quadratic/exact`.
    pub case: String,
    /// Median time of one call, in microseconds.
    pub median_us: f64,
    /// Fastest sample's time per call, in microseconds (least disturbed by other load).
    pub best_us: f64,
    /// Calls made while measuring.
    pub calls: usize,
    /// Samples the median is taken over.
    pub samples: usize,
    /// What the call found (interval counts), to show that both methods did the same job.
    pub summary: String,
}

/// Times `f` if `case` contains `filter`: a warm-up of WARMUP_MS, then samples of `k` calls each (k chosen so a sample lasts ≥ SAMPLE_MS)
/// until CASE_MS have passed and at least MIN_SAMPLES were taken; returns the median per call.
fn measure(now: &dyn Fn() -> f64, filter: &str, case: &str, f: &mut dyn FnMut() -> String) -> Option<Measured> {
    if !case.contains(filter) {
        return None;
    }
    let summary = f();
    // Warm-up and calibration: how many calls make one sample.
    let t0 = now();
    let mut k = 1usize;
    loop {
        let s = now();
        for _ in 0..k {
            std::hint::black_box(f());
        }
        if now() - s < SAMPLE_MS {
            k *= 2;
        } else if now() - t0 >= WARMUP_MS {
            break;
        }
    }
    let mut per_call: Vec<f64> = Vec::new();
    let mut calls = 0usize;
    let start = now();
    while now() - start < CASE_MS || per_call.len() < MIN_SAMPLES {
        let s = now();
        for _ in 0..k {
            std::hint::black_box(f());
        }
        per_call.push((now() - s) / k as f64);
        calls += k;
    }
    per_call.sort_by(|a, b| a.total_cmp(b));
    let n = per_call.len();
    let median_ms = if n % 2 == 1 { per_call[n / 2] } else { 0.5 * (per_call[n / 2 - 1] + per_call[n / 2]) };
    Some(Measured { case: case.to_string(), median_us: median_ms * 1000.0, best_us: per_call[0] * 1000.0, calls, samples: n, summary })
}

/// Times `f` on what `setup` returns, if `case` contains `filter`: each sample runs `setup`
/// (untimed) and then `f` once (timed), until CASE_MS have passed and at least MIN_SAMPLES were
/// taken — for work that changes its state, such as a later query on an atlas kept from a first.
fn measure_after<T>(now: &dyn Fn() -> f64, filter: &str, case: &str, setup: &mut dyn FnMut() -> T, f: &mut dyn FnMut(&mut T) -> String) -> Option<Measured> {
    if !case.contains(filter) {
        return None;
    }
    let summary = f(&mut setup());
    let mut per_call: Vec<f64> = Vec::new();
    let start = now();
    while now() - start < CASE_MS || per_call.len() < MIN_SAMPLES {
        let mut state = setup();
        let s = now();
        std::hint::black_box(f(&mut state));
        per_call.push(now() - s);
    }
    per_call.sort_by(|a, b| a.total_cmp(b));
    let n = per_call.len();
    let median_ms = if n % 2 == 1 { per_call[n / 2] } else { 0.5 * (per_call[n / 2 - 1] + per_call[n / 2]) };
    Some(Measured { case: case.to_string(), median_us: median_ms * 1000.0, best_us: per_call[0] * 1000.0, calls: n, samples: n, summary })
}

/// The first feasible range a report gives, as the thesis' Table 4.1 lists it (`[a,b]` to four
/// decimals, `none` if none).
fn first_feasible(r: &cablenav::report::VerifyReport) -> String {
    r.feasible.first().map_or("first_feasible=none".to_string(), |&[a, b]| format!("first_feasible=[{a:.4},{b:.4}]"))
}

fn summary_of(r: &cablenav::report::VerifyReport) -> String {
    format!("feasible={};infeasible={};boundaries={};uncertain={}", r.feasible.len(), r.infeasible.len(), r.boundaries.len(), r.uncertain.len())
}

/// Runs every case whose id contains `filter` (all for "") with the clock `now` (milliseconds)
/// and reports each through `out`.
pub fn run_all(platform: &str, filter: &str, now: &dyn Fn() -> f64, out: &mut dyn FnMut(&str)) -> Vec<Measured> {
    let parse = |text: &str| Scenario::from_json(text).expect("bundled scenario parses");
    let (plain, tree, boxed) = (parse(CDPR7), parse(CDPR7_TREE), parse(CDPR7_BOX));
    let traj = |s: &Scenario, name: &str| s.trajectory(Some(name)).expect("bundled trajectory").clone();
    let (tree_q, plain_q, box_l) = (traj(&tree, "quadratic"), traj(&plain, "quadratic"), traj(&boxed, "linear"));

    let exact = |s: &Scenario, t: &cablenav::model::Trajectory| summary_of(&verify_trajectory(s, t).expect("exact verification"));
    let pointwise = |s: &Scenario, t: &cablenav::model::Trajectory, dt: f64| summary_of(&verify_pointwise(s, t, dt).expect("point-wise verification"));

    let mut results = Vec::new();
    let mut record = |m: Option<Measured>, out: &mut dyn FnMut(&str)| {
        let Some(m) = m else { return };
        out(&format!("BENCH {platform} {} {:.3} {:.3} {} {} {}", m.case, m.median_us, m.best_us, m.calls, m.samples, m.summary));
        results.push(m);
    };
    record(measure(now, filter, "tree/quadratic/exact", &mut || exact(&tree, &tree_q)), out);
    record(measure(now, filter, "tree/quadratic/pointwise-0.01", &mut || pointwise(&tree, &tree_q, 0.01)), out);
    record(measure(now, filter, "tree/quadratic/pointwise-0.001", &mut || pointwise(&tree, &tree_q, 0.001)), out);
    record(measure(now, filter, "cdpr7/quadratic/exact", &mut || exact(&plain, &plain_q)), out);
    // The thesis' Table 4.1: its quadratic trajectory (4.42) point-wise at Δt = 0.1, 0.05 and 0.01
    // against exact, with the first feasible range each finds; and the same for cdpr7-tree's,
    // which does leave the feasible set
    for (id, s, t) in [("cdpr7", &plain, &plain_q), ("tree", &tree, &tree_q)] {
        record(measure(now, filter, &format!("t41/{id}/exact"), &mut || first_feasible(&verify_trajectory(s, t).expect("exact verification"))), out);
        for dt in ["0.1", "0.05", "0.01"] {
            let step: f64 = dt.parse().expect("a step");
            record(measure(now, filter, &format!("t41/{id}/pointwise-{dt}"), &mut || first_feasible(&verify_pointwise(s, t, step).expect("point-wise verification"))), out);
        }
    }
    record(measure(now, filter, "cdpr7/quadratic/pointwise-0.001", &mut || pointwise(&plain, &plain_q, 0.001)), out);
    record(measure(now, filter, "box/linear/exact", &mut || exact(&boxed, &box_l)), out);
    record(measure(now, filter, "box/linear/pointwise-0.001", &mut || pointwise(&boxed, &box_l, 0.001)), out);
    let crane = robocrane_tilt();
    let (crane_q12, crane_tilt) = (traj(&crane, "slerp q1-q2"), traj(&crane, "tilt"));
    let q1 = *crane.pose("q1").expect("q1");
    let wrench = crane.wrench.clone().expect("wrench");
    record(
        measure(now, filter, "crane/pose-wrench", &mut || {
            let r = tension_ranges(&crane.robot, &q1, &wrench).expect("q1 is not singular");
            format!("f0_1={:.6}", r[0].nominal)
        }),
        out,
    );
    record(measure(now, filter, "crane/q1-q2/exact", &mut || exact(&crane, &crane_q12)), out);
    record(measure(now, filter, "crane/q1-q2/pointwise-0.01", &mut || pointwise(&crane, &crane_q12, 0.01)), out);
    record(measure(now, filter, "crane/q1-q2/pointwise-0.001", &mut || pointwise(&crane, &crane_q12, 0.001)), out);
    record(measure(now, filter, "crane/tilt/exact", &mut || exact(&crane, &crane_tilt)), out);
    record(measure(now, filter, "crane/tilt/pointwise-0.01", &mut || pointwise(&crane, &crane_tilt, 0.01)), out);
    record(measure(now, filter, "crane/tilt/pointwise-0.001", &mut || pointwise(&crane, &crane_tilt, 0.001)), out);
    // A timed trajectory with mass (docs/dynamics.md): the exact verification includes the search
    // of the least time scale; the point-wise baseline checks weight, inertia and winch limits at
    // each sample, without the scale.
    let timed = parse(ROBOCRANE_TIMED);
    for name in ["quick drop", "swing"] {
        let t = traj(&timed, name);
        let id = name.replace(' ', "-");
        record(measure(now, filter, &format!("timed/{id}/exact"), &mut || exact(&timed, &t)), out);
        // what the page's live update runs while a drag goes on: the sections at its timing
        record(measure(now, filter, &format!("timed/{id}/exact-sections"), &mut || summary_of(&verify_sections(&timed, &t).expect("exact verification"))), out);
        record(measure(now, filter, &format!("timed/{id}/pointwise-0.01"), &mut || pointwise(&timed, &t, 0.01)), out);
        record(measure(now, filter, &format!("timed/{id}/pointwise-0.001"), &mut || pointwise(&timed, &t, 0.001)), out);
    }
    // CoGiRo (8 cables, 91 kg) imported from CASPR's files: its quintic spline general_1, whose
    // turns are enclosed by polynomials (docs/dynamics.md), exact at its own timing, exact with the
    // search of the least time scale, and point-wise.
    let cogiro = cablenav::scenario::caspr::model_to_json("CoGiRo", COGIRO[0], COGIRO[1], Some(COGIRO[2]), None).expect("CoGiRo imports");
    let cogiro = parse(&cogiro.json);
    let general = traj(&cogiro, "general_1");
    let sections = |s: &Scenario, t: &cablenav::model::Trajectory| summary_of(&verify_sections(s, t).expect("exact verification"));
    record(measure(now, filter, "cogiro/general-1/exact-sections", &mut || sections(&cogiro, &general)), out);
    record(measure(now, filter, "cogiro/general-1/exact", &mut || exact(&cogiro, &general)), out);
    record(measure(now, filter, "cogiro/general-1/pointwise-0.01", &mut || pointwise(&cogiro, &general, 0.01)), out);
    record(measure(now, filter, "cogiro/general-1/pointwise-0.001", &mut || pointwise(&cogiro, &general, 0.001)), out);
    // 64 cables, a single wrench (weight and inertia): linear programs instead of C(64, 5) facets
    let ring = ring64(None);
    let sweep = traj(&ring, "sweep");
    record(measure(now, filter, "ring64/sweep/exact-sections", &mut || sections(&ring, &sweep)), out);
    record(measure(now, filter, "ring64/sweep/pointwise-0.01", &mut || pointwise(&ring, &sweep, 0.01)), out);
    // the same with a wrench ball: the cover of wrench directions instead of C(64, 5) facets
    let ball = ring64(Some(RING_BALL));
    let sweep = traj(&ball, "sweep");
    record(measure(now, filter, "ring64-ball/sweep/exact-sections", &mut || sections(&ball, &sweep)), out);
    record(measure(now, filter, "ring64-ball/sweep/pointwise-0.01", &mut || pointwise(&ball, &sweep, 0.01)), out);
    record(
        measure(now, filter, "crane/slice-400", &mut || {
            let range = [default_range(Coord::Phi).expect("angle"), default_range(Coord::Theta).expect("angle")];
            let m = slice(&crane, "q1", [Coord::Phi, Coord::Theta], 400, range).expect("slice");
            format!("components={};fraction_feasible={:.4}", m.components, m.fraction_feasible)
        }),
        out,
    );
    record(
        measure(now, filter, "box/ray-fig310-x/exact", &mut || {
            let r = ray(&boxed, "fig310", Coord::X, 0.2, 3.8).expect("ray");
            format!("feasible={};infeasible={};boundaries={};uncertain={}", r.feasible.len(), r.infeasible.len(), r.boundaries.len(), r.uncertain.len())
        }),
        out,
    );
    // The planner (default parameters) on the Robocrane queries of Bohigas et al. §5, including
    // the edge-by-edge re-verification of the path.
    let crane = parse(ROBOCRANE);
    let summary = |o: PlanOutcome| format!("status={:?};charts={};poses={};infeasible={}", o.status, o.charts, o.path.len(), o.verification.infeasible_sections);
    for query in ["q1-q2", "q3-q4", "q5-q6"] {
        record(measure(now, filter, &format!("robocrane/plan-{query}"), &mut || summary(plan(&crane, query, PlanParams::default()).expect("planning"))), out);
    }
    // Later queries on the slice of q1 → q2 answered from the atlas kept from it
    // (`AtlasPlanner::requery`): the same query again, the way back, and q3 → q4.
    let mut crane = crane;
    crane.queries.push(cablenav::scenario::Query { name: "q2-q1".into(), start: "q2".into(), goal: "q1".into(), fixed: vec![Coord::X, Coord::Y, Coord::Z, Coord::Sigma], region: vec![] });
    for query in ["q1-q2", "q2-q1", "q3-q4"] {
        let mut first = || {
            let mut p = AtlasPlanner::new(&crane, "q1-q2", PlanParams::default()).expect("planner");
            while p.step(1000).done.is_none() {}
            p
        };
        let mut then = |p: &mut AtlasPlanner| {
            assert!(p.requery(&crane, query).expect("requery"), "same slice");
            while p.step(1000).done.is_none() {}
            summary(p.outcome().expect("outcome"))
        };
        record(measure_after(now, filter, &format!("robocrane/plan-{query}-kept"), &mut first, &mut then), out);
    }
    // q3 → q4 as paper 1 posed it: from (φ, θ) = (0.8, −2.4) to (−2.4, 2.4) with the angles as
    // plain coordinates (their rotations are only 0.11 rad apart).
    record(
        measure(now, filter, "robocrane/plan-q3-q4-coordinates", &mut || {
            let sigma = 7.0 * std::f64::consts::PI / 36.0;
            let params = PlanParams { identify_angles: false, ..PlanParams::default() };
            let fixed = [Coord::X, Coord::Y, Coord::Z, Coord::Sigma];
            let mut p = AtlasPlanner::between_coords(&crane, [0.0, 0.0, 2.0, 0.8, -2.4, sigma], [0.0, 0.0, 2.0, -2.4, 2.4, sigma], &fixed, params).expect("planner");
            while p.step(1000).done.is_none() {}
            summary(p.outcome().expect("outcome"))
        }),
        out,
    );
    results
}
