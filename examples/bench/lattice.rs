//! Benchmark cases of the ray lattice (thesis Table 3.2) and the lattice planner, shared by the
//! native benchmark (`cargo run --release --example bench -- lattice`) and the wasm-in-node one
//! (`tests/bench_wasm.rs`, test `bench_wasm_lattice`). Each prints one line that
//! `scripts/bench.sh --lattice` collects: `BENCH <platform> <case> <median_us> <best_us> <runs> <runs> <summary>`.
//!
//! The lattices take seconds, so each is timed over a few whole runs (not the µs-scale sampling of
//! `cases.rs`): the median and the fastest of `RUNS` runs after one untimed run.

use cablenav::lattice::{point_grid, Lattice, LatticeSpec};
use cablenav::model::Coord;
use cablenav::plan::lattice::{LatticeParams, LatticePlanner};
use cablenav::verify::{along, verify_along, verify_pointwise_along};
use cablenav::Scenario;

const CDPR7: &str = include_str!("../../static/scenarios/cdpr7.json");
const CDPR7_TREE: &str = include_str!("../../static/scenarios/cdpr7-tree.json");
const CDPR7_BOX: &str = include_str!("../../static/scenarios/cdpr7-box.json");
const ROBOCRANE: &str = include_str!("../../static/scenarios/robocrane.json");
const ARM: &str = include_str!("../../static/multilink/bmarm-x4-2.json");
const X4_BODIES: &str = include_str!("../../../shared/models/caspr/BMArm_X4_2/BMArm_X4_2_bodies.xml");
const X4_CABLES: &str = include_str!("../../../shared/models/caspr/BMArm_X4_2/BMArm_X4_2_cables.xml");

/// The arm of `ARM` with its links' masses and centres of mass as CASPR's BMArm_X4_2 has them
/// (format 4, CASPR's gravity): static feasibility is checked too.
fn weighed_arm() -> Scenario {
    let mut arm: serde_json::Value = serde_json::from_str(ARM).expect("arm JSON");
    let caspr: serde_json::Value = serde_json::from_str(&cablenav::scenario::caspr::to_json("arm", X4_BODIES, X4_CABLES).expect("imports").json).expect("JSON");
    arm["format"] = "cablenav-scenario/4".into();
    arm["robot"]["gravity"] = caspr["robot"]["gravity"].clone();
    for (link, theirs) in arm["robot"]["links"].as_array_mut().expect("links").iter_mut().zip(caspr["robot"]["links"].as_array().expect("links")) {
        link["mass"] = theirs["mass"].clone();
        link["com"] = theirs["com"].clone();
    }
    Scenario::from_json(&arm.to_string()).expect("the weighed arm parses")
}

/// Timed runs per case (after one untimed run).
const RUNS: usize = 3;

/// Times `f` RUNS times; prints and returns the line.
fn time(platform: &str, now: &dyn Fn() -> f64, filter: &str, case: &str, f: &mut dyn FnMut() -> String, out: &mut dyn FnMut(&str)) {
    if !case.contains(filter) {
        return;
    }
    let summary = f();
    let mut ms: Vec<f64> = (0..RUNS)
        .map(|_| {
            let s = now();
            std::hint::black_box(f());
            now() - s
        })
        .collect();
    ms.sort_by(|a, b| a.total_cmp(b));
    out(&format!("BENCH {platform} {case} {:.3} {:.3} {RUNS} {RUNS} {summary}", ms[RUNS / 2] * 1000.0, ms[0] * 1000.0));
}

/// The thesis' constant-orientation workspace (§3.5.1): x ∈ [0.2, 3.8], y ∈ [1.1, 2.9],
/// z ∈ [0.3, 3.7], identity orientation, `steps` values per axis.
fn thesis_spec(steps: usize) -> LatticeSpec {
    LatticeSpec::new(vec![Coord::X, Coord::Y, Coord::Z], vec![[0.2, 3.8], [1.1, 2.9], [0.3, 3.7]], vec![steps], [0.0; 6]).expect("thesis lattice")
}

/// Runs the lattice cases whose id contains `filter`.
pub fn run_lattice(platform: &str, filter: &str, now: &dyn Fn() -> f64, out: &mut dyn FnMut(&str)) {
    let parse = |text: &str| Scenario::from_json(text).expect("bundled scenario parses");
    let cases = [("case1-cables", parse(CDPR7)), ("case2-box", parse(CDPR7_BOX)), ("case3-tree", parse(CDPR7_TREE))];
    for steps in [20, 30, 40] {
        for (name, s) in &cases {
            let spec = thesis_spec(steps);
            time(platform, now, filter, &format!("lattice/{name}/rays-{steps}"), &mut || {
                let l = Lattice::build(s, spec.clone());
                let r = l.report().expect("built");
                format!("rays={};components={};feasible_points={}", r.rays.len(), r.components, r.feasible_points)
            }, out);
            // the rays spread over every core (natively only: wasm has no threads here)
            if platform == "native" {
                time(platform, now, filter, &format!("lattice/{name}/rays-parallel-{steps}"), &mut || {
                    let r = Lattice::build_parallel(s, spec.clone()).report().expect("built");
                    format!("rays={};components={};feasible_points={}", r.rays.len(), r.components, r.feasible_points)
                }, out);
            }
            time(platform, now, filter, &format!("lattice/{name}/points-{steps}"), &mut || {
                let g = point_grid(s, &spec);
                format!("points={};components={};feasible_points={}", g.feasible.len(), g.components, g.feasible.iter().filter(|&&f| f).count())
            }, out);
        }
    }
    // the thesis' 4-DoF arm (§3.5.2): Fig. 3.12's α–β cross-section, and the path across its gap
    let arm = parse(ARM);
    let axes = vec![arm.coord("--axes", "alpha").expect("alpha"), arm.coord("--axes", "beta").expect("beta")];
    let quarter = std::f64::consts::FRAC_PI_4;
    for steps in [10, 40] {
        let spec = LatticeSpec::new(axes.clone(), vec![[-quarter, quarter]; 2], vec![steps], arm.config("fig312").expect("fig312")).expect("arm lattice");
        time(platform, now, filter, &format!("lattice/mcdr-fig312/rays-{steps}"), &mut || {
            let r = Lattice::build(&arm, spec.clone()).report().expect("built");
            format!("rays={};components={};feasible_points={}", r.rays.len(), r.components, r.feasible_points)
        }, out);
        time(platform, now, filter, &format!("lattice/mcdr-fig312/points-{steps}"), &mut || {
            let g = point_grid(&arm, &spec);
            format!("points={};components={};feasible_points={}", g.feasible.len(), g.components, g.feasible.iter().filter(|&&f| f).count())
        }, out);
    }
    let path = along(&arm, Some("across the gap")).expect("path");
    time(platform, now, filter, "lattice/mcdr-path/exact", &mut || {
        let r = verify_along(&arm, path).expect("verified");
        format!("infeasible={:?}", r.infeasible).replace(' ', "")
    }, out);
    for dt in [0.01, 0.001] {
        time(platform, now, filter, &format!("lattice/mcdr-path/pointwise-{dt}"), &mut || {
            let r = verify_pointwise_along(&arm, path, dt).expect("sampled");
            format!("infeasible={:?}", r.infeasible).replace(' ', "")
        }, out);
    }
    // the same path with the links' weights held (static feasibility, by linear programs)
    let weighed = weighed_arm();
    let path = along(&weighed, Some("across the gap")).expect("path");
    time(platform, now, filter, "lattice/mcdr-weighed/exact", &mut || {
        let r = verify_along(&weighed, path).expect("verified");
        format!("infeasible={:?};uncertain={:?}", r.infeasible, r.uncertain).replace(' ', "")
    }, out);
    for dt in [0.01, 0.001] {
        time(platform, now, filter, &format!("lattice/mcdr-weighed/pointwise-{dt}"), &mut || {
            let r = verify_pointwise_along(&weighed, path, dt).expect("sampled");
            format!("infeasible={:?}", r.infeasible).replace(' ', "")
        }, out);
    }
    let queries = [("tree/around-tree", parse(CDPR7_TREE), "around-tree"), ("box/over-box", parse(CDPR7_BOX), "over-box"), ("robocrane/q1-q2", parse(ROBOCRANE), "q1-q2")];
    for (id, s, query) in &queries {
        time(platform, now, filter, &format!("lattice/plan/{id}"), &mut || {
            let mut p = LatticePlanner::new(s, query, LatticeParams::default()).expect("query");
            while p.step(1000).done.is_none() {}
            let r = p.report(0.0).expect("done");
            format!("status={:?};rays={};pieces={};repairs={}", r.status, r.rays, r.pieces, r.repairs)
        }, out);
    }
}
