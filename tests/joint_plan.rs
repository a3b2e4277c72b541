//! Planning in joint space (issue 25, item 4): queries between configurations of a multi-link
//! robot (scenario format 3), the lattice planner over its joint coordinates, and the planned path
//! through configurations verified exactly — on the thesis' 4-DoF arm
//! (`static/multilink/bmarm-x4-2.json`, docs/multilink.md), with α, β, γ and θ all free.
//!
//! The queries are added here to the preset's JSON. `ul` → `lr` join two configurations of the
//! upper region of the Fig. 3.12 cross-section (γ = −π/12, θ = π/12; ul at α = −0.1, β = 0.75
//! near the top of the section, lr at α = 0.59, β = 0.22 near its right) whose straight path
//! leaves joint-space wrench closure in between (the region's boundary with the tension-infeasible
//! corner bulges into the chord); `below` → `above` (the preset's configurations, β = ∓0.4) cross
//! the cables 2–3 gap.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::model::{Coord, JointPath};
use cablenav::plan::{run, PlanStatus, PlannerKind, PlannerOptions};
use cablenav::scenario::with_joint_path;
use cablenav::verify::{check_config, verify_along, Along};
use cablenav::Scenario;
use serde_json::{json, Value};
use std::f64::consts::PI;

const ARM: &str = include_str!("../static/multilink/bmarm-x4-2.json");

#[path = "shared/arm_queries.rs"]
mod arm_queries;

/// The preset with the configurations `ul` and `lr` and the queries `around` (ul → lr, all free),
/// `around-2d` (the same in the α–β cross-section), `gap` (below → above, all free) and `gap-2d`
/// of `tests/data/bmarm-queries.json` ([`arm_queries`], which the command line's tests use too).
fn arm_json() -> Value {
    arm_queries::with_queries(ARM)
}

fn arm() -> Scenario {
    Scenario::from_json(&arm_json().to_string()).expect("the arm with its queries is valid")
}

fn lattice() -> PlannerOptions {
    PlannerOptions::new(PlannerKind::Lattice)
}

fn clean(r: &cablenav::report::VerifyReport) -> bool {
    r.infeasible.is_empty() && r.uncertain.is_empty() && r.feasible == vec![[0.0, 1.0]]
}

#[test]
fn queries_name_configurations_and_joint_coordinates() {
    let s = arm();
    assert_eq!(s.queries.len(), 4);
    let q = &s.queries[3];
    assert_eq!((q.start.as_str(), q.goal.as_str()), ("below", "above"));
    assert_eq!(q.fixed, [Coord::Joint { index: 2, angle: true }, Coord::Joint { index: 3, angle: true }]);
    assert_eq!(q.region, [(Coord::Joint { index: 0, angle: true }, [-0.7854, 0.7854])]);
}

#[test]
fn bad_queries_name_the_field() {
    let refused = |edit: &dyn Fn(&mut Value)| {
        let mut v = arm_json();
        edit(&mut v);
        Scenario::from_json(&v.to_string()).expect_err("refused")
    };
    let e = refused(&|v| v["queries"][0]["goal"] = json!("nowhere"));
    assert_eq!(e.field, "queries[0].goal");
    assert!(e.reason.contains("no configuration named \"nowhere\"") && e.reason.contains("known configurations: above, below"), "{e}");
    let e = refused(&|v| v["queries"][1]["start"] = json!("upright"));
    assert_eq!(e.field, "queries[1].start");
    let e = refused(&|v| v["queries"][0]["region"] = json!({"bogus": [0, 1]}));
    assert_eq!(e.field, "queries[0].region.bogus");
    assert!(e.reason.contains("\"bogus\" is not a coordinate of this robot; its coordinates: alpha, beta, gamma, theta"), "{e}");
    let e = refused(&|v| v["queries"][0]["fixed"] = json!(["theta", "x"]));
    assert_eq!(e.field, "queries[0].fixed[1]");
    assert!(e.reason.contains("\"x\" is not a coordinate of this robot"), "{e}");
    let e = refused(&|v| v["queries"][0]["fixed"] = json!(["theta", "theta"]));
    assert_eq!(e.field, "queries[0].fixed[1]");
    let e = refused(&|v| v["queries"][0]["region"] = json!({"beta": [0.5, 0.5]}));
    assert_eq!(e.field, "queries[0].region.beta");
    assert!(e.reason.contains("LO < HI"), "{e}");
    let e = refused(&|v| v["queries"][1]["region"] = json!({"gamma": [-0.3, 0.3]}));
    assert_eq!(e.field, "queries[1].region.gamma");
    assert!(e.reason.contains("fixed by this query"), "{e}");
    let e = refused(&|v| v["queries"][0]["region"] = json!({"alpha": [0, f64::NAN]}));
    assert!(e.field.starts_with("queries[0].region.alpha"), "{e}");
    let e = refused(&|v| v["queries"][1]["name"] = json!("around"));
    assert_eq!(e.field, "queries[1].name");
    // poses stay a platform robot's
    let e = refused(&|v| v["poses"] = json!({"p": {"position": [0, 0, 1]}}));
    assert_eq!(e.field, "poses");
}

#[test]
fn planner_refusals_name_the_field() {
    let plan = |edit: &dyn Fn(&mut Value), query: &str, kind: PlannerKind| {
        let mut v = arm_json();
        edit(&mut v);
        let s = Scenario::from_json(&v.to_string()).expect("valid");
        run(&s, query, &PlannerOptions::new(kind), &|| 0.0).expect_err("refused")
    };
    let none = |_: &mut Value| {};
    let e = plan(&|v| v["queries"][0]["fixed"] = json!(["alpha", "beta", "gamma", "theta"]), "around", PlannerKind::Lattice);
    assert_eq!(e.field, "queries[around].fixed");
    assert!(e.reason.contains("every coordinate is fixed"), "{e}");
    // the goal must agree with the start on the fixed coordinates
    let e = plan(&|v| v["queries"][0]["fixed"] = json!(["alpha"]), "around", PlannerKind::Lattice);
    assert_eq!(e.field, "queries[around].goal");
    assert!(e.reason.contains("alpha = 0.59 (start: -0.1)"), "{e}");
    // fig312 lies in the gap: infeasible
    let e = plan(&|v| v["queries"][0]["start"] = json!("fig312"), "around", PlannerKind::Lattice);
    assert_eq!(e.field, "queries[around].start");
    assert!(e.reason.contains("configuration \"fig312\" is infeasible: cables 2-3"), "{e}");
    let e = plan(&|v| v["queries"][0]["region"] = json!({"alpha": [0.0, 0.7]}), "around", PlannerKind::Lattice);
    assert_eq!(e.field, "queries[around].region.alpha");
    assert!(e.reason.contains("outside the lattice's range"), "{e}");
    let e = plan(&none, "nowhere", PlannerKind::Lattice);
    assert_eq!(e.field, "query");
    // the atlas planner's charts are of platform poses
    let e = plan(&none, "around", PlannerKind::Atlas);
    assert_eq!(e.field, "planner");
    assert!(e.reason.contains("lattice planner"), "{e}");
}

/// Every configuration of `path` at `n` + 1 equally spaced t is feasible per configuration (the
/// conditions' own point-wise checks, apart from the exact verifier).
fn feasible_at_samples(s: &Scenario, path: &JointPath, n: usize) -> bool {
    let chain = s.robot.chain.as_ref().unwrap();
    (0..=n).all(|k| check_config(s, "sample", &path.config_at(chain, k as f64 / n as f64)).feasible)
}

#[test]
fn a_path_around_the_closure_boundary_verifies_exactly() {
    let s = arm();
    let (ul, lr) = (s.config("ul").unwrap(), s.config("lr").unwrap());
    // the straight path leaves wrench closure
    let straight = JointPath { name: "straight".into(), through: vec![ul.clone(), lr.clone()], proportional: false };
    let r = verify_along(&s, Along::Joints(&straight)).unwrap();
    assert_eq!(r.infeasible.len(), 1, "{r:?}");
    assert!(r.infeasible[0][1] - r.infeasible[0][0] > 0.5, "{r:?}");
    assert!(r.boundaries.iter().all(|b| b.constraint == "wrench closure"), "{r:?}");

    for query in ["around", "around-2d"] {
        let result = run(&s, query, &lattice(), &|| 0.0).unwrap();
        assert_eq!(result.status, PlanStatus::Found, "{query}");
        assert!(result.trajectory.is_none());
        let path = result.joint_path.expect("a path through configurations");
        assert_eq!(path.name, format!("{query}-lattice"));
        assert_eq!((path.through.first(), path.through.last()), (Some(&ul), Some(&lr)), "{query}");
        assert!(path.through.len() >= 3, "{query}: not the straight path");
        // verified exactly here again, and by samples
        let r = verify_along(&s, Along::Joints(&path)).unwrap();
        assert!(clean(&r), "{query}: {r:?}");
        assert!(feasible_at_samples(&s, &path, 2000), "{query}");
        let cablenav::plan::Details::Lattice(report) = &result.details else { panic!("a lattice report") };
        assert_eq!(report.axes.len(), if query == "around" { 4 } else { 2 });
        assert_eq!(report.axes[..2], ["alpha", "beta"]);
        assert_eq!(report.joint_coordinates, ["alpha", "beta", "gamma", "theta"]);
        assert!(report.verification.as_ref().is_some_and(clean));
        // γ's default range is the joint's, widened to the start's γ = −π/12 outside it
        if query == "around" {
            assert_eq!(report.ranges[2], [-PI / 12.0, 0.1745]);
            assert_eq!(report.ranges[3], [-0.7854, 0.7854]);
        }
        // written into the scenario as a trajectory through new configurations, it verifies by name
        let (text, name) = with_joint_path(&arm_json().to_string(), &path).unwrap();
        assert_eq!(name, format!("{query}-lattice"));
        let written = Scenario::from_json(&text).unwrap();
        let along = cablenav::verify::along(&written, Some(&name)).unwrap();
        let Along::Joints(p) = along else { panic!("a path") };
        assert_eq!(p.through, path.through);
        assert!(clean(&verify_along(&written, along).unwrap()));
        assert_eq!(written.config(&format!("{name}-0")).unwrap(), ul);
        // a second path of the same name is renamed, and so are its configurations
        let (again, second) = with_joint_path(&text, &path).unwrap();
        assert_eq!(second, format!("{query}-lattice 2"));
        assert!(Scenario::from_json(&again).unwrap().config(&format!("{second}-0")).is_ok());
    }
}

#[test]
fn no_path_across_the_gap_at_this_resolution() {
    let s = arm();
    for query in ["gap", "gap-2d"] {
        let result = run(&s, query, &lattice(), &|| 0.0).unwrap();
        assert_eq!(result.status, PlanStatus::NoPath, "{query}");
        assert!(result.joint_path.is_none() && result.trajectory.is_none());
        let cablenav::plan::Details::Lattice(report) = &result.details else { panic!("a lattice report") };
        assert!(report.message.starts_with("no path in the lattice at this resolution (alpha: 7 values over [-0.7854, 0.7854]"), "{}", report.message);
        assert!(report.components >= 2);
    }
}

#[test]
fn bounded_stepping_reaches_the_same_path() {
    let s = arm();
    let mut p = cablenav::plan::planner(&s, "around-2d", &lattice()).unwrap();
    let mut steps = 0;
    while p.step(1).done.is_none() {
        steps += 1;
        assert!(steps < 10_000);
    }
    let stepped = p.result(0.0).unwrap();
    let whole = run(&s, "around-2d", &lattice(), &|| 0.0).unwrap();
    assert!(steps > 14, "one ray per unit at least: {steps}");
    assert_eq!(stepped.joint_path, whole.joint_path);
}

/// An independent check of the gap's extent: the point-wise grid (each configuration checked by
/// the conditions on their own, no rays) over all four joint coordinates — 17 × 81 × 11 × 25
/// values of α, β, γ, θ over their joints' ranges (γ's widened to −π/12), β fine enough (spacing
/// 0.02) to sample inside the cables 2–3 gap — puts `below` and `above` in different components:
/// the gap separates them over the whole range of α, γ and θ, not only in the Fig. 3.12
/// cross-section. (So do 25 × 81 × 11 × 25, 17 × 121 × 11 × 25 and 17 × 81 × 16 × 37; a grid
/// coarse in α, γ, θ — 9 × 161 × 6 × 13 — joins them, its steps along those axes jumping the
/// tilted gap. A point-wise grid assumes its neighbours joined: its separation is evidence, not a
/// proof; the lattice planner's `no_path` above is certified at its own resolution.)
#[test]
fn a_four_dimensional_point_grid_separates_below_from_above() {
    use cablenav::lattice::{point_grid, LatticeSpec};
    let s = arm();
    let axes: Vec<Coord> = (0..4).map(|k| s.coord_at(k)).collect();
    let ranges = vec![[-0.7854, 0.7854], [-0.8, 0.8], [-PI / 12.0, 0.1745], [-PI / 4.0, PI / 4.0]];
    let spec = LatticeSpec::new(axes, ranges, vec![17, 81, 11, 25], s.config("below").unwrap()).unwrap();
    let grid = point_grid(&s, &spec);
    let at = |name: &str| {
        let q = s.config(name).unwrap();
        let idx: Vec<usize> = (0..4).map(|a| ((q[a] - spec.ranges[a][0]) / spec.spacing(a)).round() as usize).collect();
        let c = spec.coords(&idx);
        assert!(c.iter().zip(&q).all(|(x, y)| (x - y).abs() < 1e-9), "{name} is a grid point: {c:?} vs {q:?}");
        grid.component[spec.point_index(&idx)].unwrap_or_else(|| panic!("{name} is feasible"))
    };
    let (below, above) = (at("below"), at("above"));
    assert_ne!(below, above, "{} components", grid.components);
}
