//! Planning a multi-link robot on the command line (issue 25, item 4): `cablenav plan SCENARIO
//! --query Q --planner lattice` on the thesis' 4-DoF arm with queries between its configurations,
//! the path written with `--out` as a trajectory through configurations and checked with
//! `cablenav verify`; no path across the cables 2–3 gap; the atlas planner refused naming
//! `--planner lattice`. The core's side is `tests/joint_plan.rs`.

use serde_json::{json, Value};
use support::Files;

mod support;
#[path = "../../tests/shared/arm_queries.rs"]
mod arm_queries;

const ARM: &str = include_str!("../../static/multilink/bmarm-x4-2.json");

/// The preset with two configurations of its upper region, `ul` and `lr`, whose straight path
/// leaves wrench closure, and the queries `around` (ul → lr) and `gap` (below → above), all four
/// joint coordinates free (with their α–β cross-sections `around-2d` and `gap-2d`): those of
/// `tests/data/bmarm-queries.json` ([`arm_queries`], which the core's tests use too).
fn arm() -> String {
    arm_queries::with_queries(ARM).to_string()
}

#[test]
fn plan_writes_a_path_through_configurations_that_verify_checks() {
    let files = Files::new(&[("arm.json", arm())]);
    let v = files.json(&["plan", "arm.json", "--query", "around", "--planner", "lattice", "--out", "planned.json", "--json"]);
    assert_eq!(v["status"], "found", "{v}");
    assert_eq!(v["axes"], json!(["alpha", "beta", "gamma", "theta"]));
    assert_eq!(v["joint_coordinates"], json!(["alpha", "beta", "gamma", "theta"]));
    assert_eq!(v["verification"]["feasible"], json!([[0.0, 1.0]]));
    let waypoints = v["waypoints"].as_array().unwrap();
    assert!(waypoints.len() >= 3 && waypoints.iter().all(|w| w.as_array().unwrap().len() == 4), "{v}");

    // the written scenario: the path through new configurations, verified by `cablenav verify`
    let written: Value = serde_json::from_str(&files.0.borrow()["planned.json"]).unwrap();
    let path = written["trajectories"].as_array().unwrap().last().unwrap().clone();
    assert_eq!(path["name"], "around-lattice");
    assert_eq!(path["through"].as_array().unwrap().len(), waypoints.len());
    assert_eq!(written["configurations"]["around-lattice-0"], written["configurations"]["ul"]);
    let r = files.json(&["verify", "planned.json", "--trajectory", "around-lattice", "--json"]);
    assert_eq!(r["feasible"], json!([[0.0, 1.0]]), "{r}");
    assert_eq!((r["infeasible"].as_array().unwrap().len(), r["uncertain"].as_array().unwrap().len()), (0, 0));

    // the text report names the joint coordinates
    let text = files.cli(&["plan", "arm.json", "--query", "around", "--planner", "lattice"]).unwrap();
    assert!(text.starts_with("plan around (lattice): found"), "{text}");
    assert!(text.contains("alpha = -0.100000, beta = 0.750000"), "{text}");
}

#[test]
fn no_path_across_the_gap_and_refusals() {
    let files = Files::new(&[("arm.json", arm())]);
    let v = files.json(&["plan", "arm.json", "--query", "gap", "--planner", "lattice", "--json"]);
    assert_eq!(v["status"], "no_path");
    assert!(v["message"].as_str().unwrap().starts_with("no path in the lattice at this resolution (alpha: 7 values"), "{v}");
    let e = files.cli(&["plan", "arm.json", "--query", "gap", "--planner", "lattice", "--out", "x.json"]).unwrap_err();
    assert_eq!(e.field(), "--out");
    // the atlas planner (the default) is for platforms: the message says which planner to use
    let e = files.cli(&["plan", "arm.json", "--query", "around"]).unwrap_err();
    assert_eq!(e.field(), "plan");
    assert!(e.to_string().contains("--planner lattice"), "{e}");
    let e = files.cli(&["plan", "arm.json", "--query", "nowhere", "--planner", "lattice"]).unwrap_err();
    assert_eq!(e.field(), "query");
    assert!(e.to_string().contains("known queries: around, around-2d, gap, gap-2d"), "{e}");
}
