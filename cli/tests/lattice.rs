//! The ray lattice and the lattice planner on the command line (issue 10): every lattice ray
//! against the `ray` command and dense sampling, the `lattice` command's JSON and text, bad
//! requests naming the option, and planning — around the tree, over the box, Robocrane q1 → q2
//! with its wrench set — each result written with `--out` and checked with `cablenav verify`
//! feasible on all of [0, 1]; a wall gives "no path in the lattice at this resolution".

use cablenav::lattice::{Lattice, LatticeSpec};
use cablenav::model::{Coord, Pose};
use cablenav::verify::check_pose;
use cablenav::Scenario;
use serde_json::{json, Value};
use support::Files;

mod support;

const CDPR7_BOX: &str = include_str!("../../static/scenarios/cdpr7-box.json");
const CDPR7_TREE: &str = include_str!("../../static/scenarios/cdpr7-tree.json");
const ROBOCRANE: &str = include_str!("../../static/scenarios/robocrane.json");

/// A robot hanging from six ceiling anchors over a wall standing on the floor (x ∈ [1.9, 2.1]):
/// in the region below the wall's top, poses left and right of it are in different components.
fn wall() -> String {
    let tops = [[0, 0, 4], [4, 0, 4], [4, 4, 4], [0, 4, 4], [2, 0, 4], [2, 4, 4]];
    let plats = [[-0.2, -0.2, 0.0], [0.2, -0.2, 0.0], [0.2, 0.2, 0.0], [-0.2, 0.2, 0.0], [0.0, -0.2, 0.0], [0.0, 0.2, 0.0]];
    let cables: Vec<Value> = tops.iter().zip(plats).map(|(b, p)| json!({"base": b, "platform": p})).collect();
    json!({
        "format": "cablenav-scenario/1", "name": "wall",
        "robot": {"cables": cables},
        "clearance": {"cable_cable": 0, "cable_obstacle": 0.1},
        "obstacles": [{"name": "wall", "type": "box", "center": [2, 2, 0.5], "size": [0.2, 4, 1]}],
        "poses": {"left": {"position": [1, 2, 0.5], "quaternion": [1, 0, 0, 0]}, "right": {"position": [3, 2, 0.5], "quaternion": [1, 0, 0, 0]}},
        "queries": [{"name": "across", "start": "left", "goal": "right", "fixed": ["phi", "theta", "sigma"],
                     "region": {"x": [0.5, 3.5], "y": [1, 3], "z": [0.2, 0.9]}}]
    })
    .to_string()
}

/// The CLI over an in-memory file system: the presets, the wall, and whatever `--out` wrote.
fn presets() -> Files {
    Files::new(&[("box.json", CDPR7_BOX.to_string()), ("tree.json", CDPR7_TREE.to_string()), ("robocrane.json", ROBOCRANE.to_string()), ("wall.json", wall())])
}

/// Fig. 3.10's x–z cross-section: y = 2, identity orientation, `steps` values over x ∈ [0.2, 3.8]
/// and z ∈ [0.3, 3.7].
fn fig310(steps: usize) -> LatticeSpec {
    LatticeSpec::new(vec![Coord::X, Coord::Z], vec![[0.2, 3.8], [0.3, 3.7]], vec![steps], [0.0, 2.0, 0.0, 0.0, 0.0, 0.0]).unwrap()
}

fn feasible_at(s: &Scenario, c: [f64; 6]) -> bool {
    check_pose(s, "grid", &Pose::from_coords(c)).feasible
}

#[test]
fn rays_equal_the_ray_command_and_dense_sampling() {
    let files = presets();
    let s = Scenario::from_json(CDPR7_TREE).unwrap();
    let l = Lattice::build(&s, fig310(7));
    let mut with_poses: Value = serde_json::from_str(CDPR7_TREE).unwrap();
    for (r, ray) in l.rays.iter().enumerate() {
        let c = l.spec.coords(&ray.cell);
        with_poses["poses"][format!("ray{r}")] = json!({"position": [c[0], c[1], c[2]], "quaternion": [1, 0, 0, 0]});
    }
    files.0.borrow_mut().insert("rays.json".into(), with_poses.to_string());
    let mut boundaries = 0;
    for (r, ray) in l.rays.iter().enumerate() {
        let [lo, hi] = l.spec.ranges[ray.axis];
        let (lo, hi, pose) = (lo.to_string(), hi.to_string(), format!("ray{r}"));
        let v = files.json(&["ray", "rays.json", "--pose", &pose, "--vary", &ray.vary, "--range", &lo, &hi, "--json"]);
        let want: Vec<[f64; 2]> = serde_json::from_value(v["feasible"].clone()).unwrap();
        // the same machinery: equal up to the rounding of the pose's coordinates through JSON
        assert_eq!(ray.feasible.len(), want.len(), "ray {r}: {:?} vs {want:?}", ray.feasible);
        for (a, b) in ray.feasible.iter().zip(&want) {
            assert!((a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12, "ray {r}: {:?} vs {want:?}", ray.feasible);
        }
        // dense sampling, away from the certified boundaries
        let cut: Vec<f64> = ray.feasible.iter().flatten().copied().collect();
        boundaries += cut.len();
        let axis = Coord::parse(&ray.vary).unwrap().index();
        let (lo, hi) = (l.spec.ranges[ray.axis][0], l.spec.ranges[ray.axis][1]);
        for k in 0..=400 {
            let x = lo + (hi - lo) * k as f64 / 400.0;
            if cut.iter().any(|b| (b - x).abs() < 1e-6) {
                continue;
            }
            let mut c = l.spec.coords(&ray.cell);
            c[axis] = x;
            assert_eq!(ray.piece_at(x).is_some(), feasible_at(&s, std::array::from_fn(|i| c[i])), "ray {r} ({}) at {x}", ray.vary);
        }
    }
    assert!(boundaries > 10);
}

#[test]
fn lattice_command_prints_rays_and_components() {
    let files = presets();
    let v = files.json(&["lattice", "box.json", "--pose", "fig310", "--axes", "x,z", "--range", "0.2", "3.8", "0.3", "3.7", "--steps", "7", "--json"]);
    let rays = v["rays"].as_array().unwrap();
    assert_eq!(rays.len(), 14);
    assert_eq!(rays[0]["vary"], "x");
    assert!(rays[0]["fixed"]["y"].is_f64() && rays[0]["fixed"]["z"].is_f64());
    assert!(rays[1]["feasible"][0][0].as_f64().is_some_and(|x| (x - 2.0016).abs() < 1e-3));
    assert_eq!(v["components"], 1);
    let text = files.cli(&["lattice", "box.json", "--pose", "fig310", "--axes", "x,z", "--range", "0.2", "3.8", "0.3", "3.7", "--steps", "7"]).unwrap();
    assert!(text.starts_with("lattice over x ∈ [0.2, 3.8] (7 values), z ∈ [0.3, 3.7] (7 values): 14 rays"), "{text}");
}

#[test]
fn bad_lattice_requests_name_the_field() {
    let files = presets();
    let base = ["lattice", "box.json", "--pose", "fig310"];
    let cases: [(&[&str], &str, &str); 9] = [
        (&["--axes", "x,z", "--range", "0.2", "3.8", "0.3", "3.7", "--steps", "0"], "--steps", "2 to"),
        (&["--axes", "x,z", "--range", "0.2", "3.8", "0.3", "3.7", "--steps", "1"], "--steps", "2 to"),
        (&["--axes", "x,z", "--range", "1", "1", "0.3", "3.7", "--steps", "7"], "--range", "LO < HI"),
        (&["--axes", "x,w", "--range", "0.2", "3.8", "0.3", "3.7", "--steps", "7"], "--axes", "\"w\""),
        (&["--axes", "x,x", "--range", "0.2", "3.8", "0.3", "3.7", "--steps", "7"], "--axes", "twice"),
        (&["--axes", "x,z", "--range", "0.2", "3.8", "--steps", "7"], "--range", "one LO HI pair per axis"),
        (&["--axes", "x,y,z", "--range", "0", "1", "0", "1", "0", "1", "--steps", "1000"], "--steps", "rays"),
        (&["--axes", "x,y,z", "--range", "0", "1", "0", "1", "0", "1", "--steps", "1000000000"], "--steps", "2 to 10000"),
        (&["--axes", "x,z", "--range", "0.2", "3.8", "0.3", "3.7", "--steps", "7,8,9"], "--steps", "one number for all axes"),
    ];
    for (rest, field, reason) in cases {
        let args: Vec<&str> = base.iter().chain(rest).copied().collect();
        let e = files.cli(&args).expect_err(&format!("{args:?} must fail"));
        assert_eq!(e.field(), field, "{args:?}: {e}");
        assert!(e.to_string().contains(reason), "{args:?}: {e}");
    }
    // 10⁹ rays, in the core: refused before any work
    let e = LatticeSpec::new(Coord::ALL.to_vec(), vec![[0.0, 1.0]; 6], vec![64], [0.0; 6]).unwrap_err();
    assert_eq!(e.field, "--steps");
    assert!(e.reason.contains("rays"), "{e}");
}

/// Plans `query` of `file` with the lattice planner through the CLI, writes the result with
/// `--out` and verifies it with `cablenav verify`: returns the plan's and the verification's JSON.
fn plan_and_verify(files: &Files, file: &str, query: &str, extra: &[&str]) -> (Value, Value) {
    let mut args = vec!["plan", file, "--query", query, "--planner", "lattice", "--out", "planned.json", "--json"];
    args.extend_from_slice(extra);
    let plan = files.json(&args);
    let name = format!("{query}-lattice");
    let verified = files.json(&["verify", "planned.json", "--trajectory", &name, "--json"]);
    (plan, verified)
}

#[test]
fn plans_over_the_box_verified_on_all_of_0_1() {
    plans_verified_on_all_of_0_1("box.json", "over-box", "box-left", "box-right");
}

#[test]
fn plans_around_the_tree_verified_on_all_of_0_1() {
    plans_verified_on_all_of_0_1("tree.json", "around-tree", "tree-left", "tree-right");
}

/// Plans `query` of `file` with the lattice planner; the result verifies on all of [0, 1].
fn plans_verified_on_all_of_0_1(file: &str, query: &str, start: &str, goal: &str) {
    let files = presets();
    {
        // the straight motion between the two poses is infeasible: the planner has work to do
        let mut v: Value = serde_json::from_str(&files.0.borrow()[file]).unwrap();
        v["trajectories"] = json!([{"name": "straight", "translation": {"line": [v["poses"][start]["position"], v["poses"][goal]["position"]]}, "orientation": {"slerp": [start, goal]}}]);
        files.0.borrow_mut().insert("straight.json".into(), v.to_string());
        let straight = files.json(&["verify", "straight.json", "--json"]);
        assert!(!straight["infeasible"].as_array().unwrap().is_empty(), "{file}: the straight line should be infeasible");

        let (plan, verified) = plan_and_verify(&files, file, query, &[]);
        assert_eq!(plan["status"], "found", "{file}: {plan}");
        assert_eq!(verified["feasible"], json!([[0.0, 1.0]]), "{file}: {verified}");
        assert!(verified["infeasible"].as_array().unwrap().is_empty() && verified["uncertain"].as_array().unwrap().is_empty());
        assert!(plan["polyline"].as_array().unwrap().len() >= 3, "{file}: the A* path turns");
        // the smoothed trajectory has a Bézier piece (not only the polyline) and starts and ends at the query's poses
        let planned: Value = serde_json::from_str(&files.0.borrow()["planned.json"]).unwrap();
        let traj = planned["trajectories"].as_array().unwrap().last().unwrap().clone();
        let pieces = traj.get("pieces").and_then(|p| p.as_array()).cloned().unwrap_or_else(|| vec![traj.clone()]);
        assert!(pieces.iter().any(|p| p["translation"].get("bezier").is_some()), "{file}: {traj}");
        let s = Scenario::from_json(&files.0.borrow()["planned.json"]).unwrap();
        let t = s.trajectory(Some(&format!("{query}-lattice"))).unwrap();
        assert!((t.pose_at(0.0).position - s.pose(start).unwrap().position).norm() < 1e-12);
        assert!((t.pose_at(1.0).position - s.pose(goal).unwrap().position).norm() < 1e-12);
    }
}

#[test]
fn plans_robocrane_q1_q2_with_its_wrench_set() {
    let files = presets();
    let (plan, verified) = plan_and_verify(&files, "robocrane.json", "q1-q2", &[]);
    assert_eq!(plan["status"], "found", "{plan}");
    assert_eq!(verified["feasible"], json!([[0.0, 1.0]]), "{verified}");
    let s = Scenario::from_json(&files.0.borrow()["planned.json"]).unwrap();
    assert!(s.wrench.is_some(), "verified with the wrench set");
}

#[test]
fn a_wall_gives_no_path_with_the_resolution() {
    let files = presets();
    let v = files.json(&["plan", "wall.json", "--query", "across", "--planner", "lattice", "--steps", "9", "--json"]);
    assert_eq!(v["status"], "no_path");
    let m = v["message"].as_str().unwrap();
    assert!(m.starts_with("no path in the lattice at this resolution"), "{m}");
    assert!(m.contains("x: 9 values over [0.5, 3.5]"), "{m}");
    let e = files.cli(&["plan", "wall.json", "--query", "across", "--planner", "lattice", "--out", "x.json"]).unwrap_err();
    assert_eq!(e.field(), "--out");
    let e = files.cli(&["plan", "robocrane.json", "--query", "q1-q2", "--planner", "grid"]).unwrap_err();
    assert_eq!(e.field(), "--planner");
    let e = files.cli(&["plan", "robocrane.json", "--query", "q1-q2", "--steps", "9"]).unwrap_err();
    assert_eq!(e.field(), "--steps");
    assert!(e.to_string().ends_with("--steps: is an option of --planner lattice"), "{e}");
    // the atlas options belong to the atlas planner: refused with the lattice planner, not ignored
    let e = files.cli(&["plan", "robocrane.json", "--query", "q1-q2", "--planner", "lattice", "--max-charts", "9"]).unwrap_err();
    assert!(e.to_string().ends_with("--max-charts: is an option of --planner atlas"), "{e}");
}

/// `plan --atlas FILE` saves the atlas and a later run starts from it: the second run of a query
/// on the same slice reuses every chart (`reused_charts`) and finds the same verdict; a file made
/// with other parameters, or not an atlas, is refused naming `--atlas` and the file.
#[test]
fn plan_saves_and_loads_the_atlas() {
    let files = presets();
    let first = files.json(&["plan", "robocrane.json", "--query", "q1-q2", "--atlas", "crane.atlas", "--json"]);
    assert_eq!(first["reused_charts"], 0);
    let saved = files.0.borrow().get("crane.atlas").cloned().expect("the atlas file is written");
    assert!(saved.contains("cablenav-atlas/1"));
    let again = files.json(&["plan", "robocrane.json", "--query", "q1-q2", "--atlas", "crane.atlas", "--json"]);
    assert_eq!((&again["status"], &again["reused_charts"], &again["charts"]), (&first["status"], &first["charts"], &first["charts"]));
    let next = files.json(&["plan", "robocrane.json", "--query", "q3-q4", "--atlas", "crane.atlas", "--json"]);
    assert_eq!((next["status"].as_str(), next["reused_charts"].as_u64()), (Some("found"), first["charts"].as_u64()));
    let e = files.cli(&["plan", "robocrane.json", "--query", "q1-q2", "--atlas", "crane.atlas", "--epsilon", "0.3"]).unwrap_err();
    assert_eq!(e.field(), "--atlas");
    assert!(e.to_string().contains("crane.atlas") && e.to_string().contains("parameters"), "{e}");
    files.0.borrow_mut().insert("junk.atlas".into(), "{\"format\": 1}".into());
    let e = files.cli(&["plan", "robocrane.json", "--query", "q1-q2", "--atlas", "junk.atlas"]).unwrap_err();
    assert_eq!(e.field(), "--atlas");
    let e = files.cli(&["plan", "robocrane.json", "--query", "q1-q2", "--planner", "lattice", "--atlas", "x.atlas"]).unwrap_err();
    assert_eq!(e.field(), "--atlas");
    let text = files.cli(&["plan", "robocrane.json", "--query", "q1-q2", "--atlas", "crane.atlas"]).unwrap();
    assert!(text.contains("saved the atlas to crane.atlas"), "{text}");
}
