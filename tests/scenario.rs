//! Scenario JSON: presets parse, every kind of bad input is an error that names its JSON path,
//! orientation conventions convert both ways, and no input (truncated, mutated) panics.
//!
//! Presets are embedded with `include_str!` (no file system), so these tests also run under
//! `wasm-pack test --node`.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::model::{Coord, Orientation, Pose, Translation};
use cablenav::shape::Shape;
use cablenav::{Error, Scenario};
use nalgebra::{Matrix3, Vector3};
use serde_json::{json, Value};
use std::f64::consts::{FRAC_PI_2, PI};

const CDPR7: &str = include_str!("../static/scenarios/cdpr7.json");
const CDPR7_BOX: &str = include_str!("../static/scenarios/cdpr7-box.json");
const CDPR7_TREE: &str = include_str!("../static/scenarios/cdpr7-tree.json");
const FORMAT_DOC: &str = include_str!("../docs/scenario-format.md");
const PRESETS: [(&str, &str); 3] = [("cdpr7", CDPR7), ("cdpr7-box", CDPR7_BOX), ("cdpr7-tree", CDPR7_TREE)];

// ---------------------------------------------------------------------------------------------
// Helpers

/// A small valid scenario (the Table 3.1 robot, no bounds) to break one field at a time.
fn base() -> Value {
    json!({
        "format": "cablenav-scenario/1",
        "name": "t",
        "robot": {
            "cables": [
                {"base": [0, 1, 0], "platform": [-0.15, -0.1, 0.3]},
                {"base": [0, 3, 0], "platform": [-0.15, 0.1, 0.3]},
                {"base": [4, 2, 0], "platform": [0.15, 0, 0.3]},
                {"base": [0, 0, 4], "platform": [-0.15, -0.2, -0.3]},
                {"base": [0, 4, 4], "platform": [-0.15, 0.2, -0.3]},
                {"base": [4, 4, 4], "platform": [0.15, 0.2, -0.3]},
                {"base": [4, 0, 4], "platform": [0.15, -0.2, -0.3]}
            ]
        },
        "poses": {
            "q1": {"position": [2, 1.5, 1], "euler_xyz_deg": [0, 0, 30]},
            "q2": {"position": [1.5, 2.3, 3], "quaternion": [1, 0, 0, 0]}
        },
        "trajectories": [
            {"name": "t1", "translation": {"line": [[2, 1.5, 1], [1.5, 2.3, 3]]},
             "orientation": {"slerp": ["q1", "q2"]}}
        ],
        "queries": [{"name": "go", "start": "q1", "goal": "q2", "fixed": ["x", "sigma"]}]
    })
}

fn parse_value(v: &Value) -> Result<Scenario, Error> {
    Scenario::from_json(&v.to_string())
}

/// The base scenario changed by `f`, which must fail.
fn err_with(f: impl FnOnce(&mut Value)) -> Error {
    let mut v = base();
    f(&mut v);
    match parse_value(&v) {
        Ok(_) => panic!("expected an error for {v}"),
        Err(e) => e,
    }
}

/// The base scenario changed by `f`, which must parse.
fn ok_with(f: impl FnOnce(&mut Value)) -> Scenario {
    let mut v = base();
    f(&mut v);
    match parse_value(&v) {
        Ok(s) => s,
        Err(e) => panic!("unexpected error {e} for {v}"),
    }
}

#[track_caller]
fn assert_err(e: &Error, field: &str, reason_part: &str) {
    assert_eq!(e.field, field, "wrong field in error: {e}");
    assert!(
        e.reason.to_lowercase().contains(&reason_part.to_lowercase()),
        "reason of `{e}` should contain `{reason_part}`"
    );
}

#[track_caller]
fn expect(f: impl FnOnce(&mut Value), field: &str, reason_part: &str) {
    let e = err_with(f);
    assert_err(&e, field, reason_part);
}

fn err_text(text: &str) -> Error {
    match Scenario::from_json(text) {
        Ok(_) => panic!("expected an error for {text}"),
        Err(e) => e,
    }
}

fn set_obstacles(v: &mut Value, obstacles: Value) {
    v["obstacles"] = obstacles;
}

/// Deterministic xorshift64* generator (no `rand` dependency).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

fn close_m(a: &Matrix3<f64>, b: &Matrix3<f64>, tol: f64) -> bool {
    (a - b).abs().max() <= tol
}

/// Equal as rotations: q or −q.
fn same_rotation(a: &Pose, b: &Pose, tol: f64) -> bool {
    close_m(&a.matrix(), &b.matrix(), tol)
}

fn angle_diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(2.0 * PI);
    d.min(2.0 * PI - d)
}

// ---------------------------------------------------------------------------------------------
// Presets

#[test]
fn presets_parse_without_warnings() {
    for (name, text) in PRESETS {
        let s = Scenario::from_json(text).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(s.name, name);
        assert!(s.warnings.is_empty(), "{name}: unexpected warnings {:?}", s.warnings);
        assert_eq!(s.robot.cables.len(), 7);
        assert_eq!(s.robot.diameter, 0.02);
        assert_eq!(s.clearance.cable_cable, 0.1);
        assert_eq!(s.clearance.cable_obstacle, 0.2);
        for c in &s.robot.cables {
            assert_eq!((c.length.min, c.length.max), (0.0, 10.0));
            assert_eq!(c.tension.min, 0.0);
            assert!(c.tension.max.is_infinite(), "no tension bounds in the presets");
        }
        let names: Vec<&str> = s.poses.iter().map(|(n, _)| n.as_str()).collect();
        // the box and tree presets add the two poses of their lattice-planner query (docs/lattice.md)
        let query: &[&str] = match name {
            "cdpr7-box" => &["box-left", "box-right"],
            "cdpr7-tree" => &["tree-left", "tree-right"],
            _ => &[],
        };
        assert_eq!(names, [&["start", "end", "fig310"][..], query].concat(), "poses keep file order");
        let traj: Vec<&str> = s.trajectories.iter().map(|t| t.name.as_str()).collect();
        assert_eq!(traj, ["linear", "quadratic"]);
        assert!(s.wrench.is_none());
        assert_eq!(s.queries.len(), usize::from(!query.is_empty()));
    }
}

#[test]
fn preset_robot_is_table_3_1() {
    let s = Scenario::from_json(CDPR7).expect("cdpr7");
    let a = [[0., 1., 0.], [0., 3., 0.], [4., 2., 0.], [0., 0., 4.], [0., 4., 4.], [4., 4., 4.], [4., 0., 4.]];
    let b = [
        [-0.15, -0.1, 0.3],
        [-0.15, 0.1, 0.3],
        [0.15, 0.0, 0.3],
        [-0.15, -0.2, -0.3],
        [-0.15, 0.2, -0.3],
        [0.15, 0.2, -0.3],
        [0.15, -0.2, -0.3],
    ];
    for (i, c) in s.robot.cables.iter().enumerate() {
        assert_eq!(c.base, Vector3::from(a[i]), "cable {}", i + 1);
        assert_eq!(c.platform, Vector3::from(b[i]), "cable {}", i + 1);
    }
}

#[test]
fn preset_poses_and_thesis_trajectories() {
    let s = Scenario::from_json(CDPR7).expect("cdpr7");
    let start = s.pose("start").expect("start");
    assert_eq!(start.position, Vector3::new(2.0, 1.5, 1.0));
    // Thesis (4.34): Qs = [0.9659, 0, 0, 0.2588], Qe = [1, 0, 0, 0].
    let q = start.quaternion();
    let h = 15f64.to_radians();
    for (x, y) in q.iter().zip([h.cos(), 0.0, 0.0, h.sin()]) {
        assert!((x - y).abs() < 1e-12, "{q:?}");
    }
    assert_eq!(s.pose("end").expect("end").quaternion(), [1.0, 0.0, 0.0, 0.0]);
    let fig = s.pose("fig310").expect("fig310");
    assert!((fig.position - Vector3::new(2.0016, 2.0, 0.3 + 3.4 / 6.0)).norm() < 1e-15);

    // (4.33): the linear trajectory joins the two positions.
    let lin = s.trajectory(None).expect("first trajectory");
    assert_eq!(lin.name, "linear");
    assert!((lin.translation.at(0.0) - Vector3::new(2.0, 1.5, 1.0)).norm() < 1e-15);
    assert!((lin.translation.at(1.0) - Vector3::new(1.5, 2.3, 3.0)).norm() < 1e-15);
    // (4.42), converted from T = τ·tan(7.5°): passes (1.2, 1.9, 1.8) at τ = 0.5 and joins the ends.
    let quad = s.trajectory(Some("quadratic")).expect("quadratic");
    assert!((quad.translation.at(0.5) - Vector3::new(1.2, 1.9, 1.8)).norm() < 1e-12);
    assert!((quad.translation.at(1.0) - Vector3::new(1.5, 2.3, 3.0)).norm() < 1e-12);
    // The thesis's printed coefficients in T, times tan(7.5°)^k, are our τ-coefficients.
    let t = 7.5f64.to_radians().tan();
    let Translation::Polynomial(c) = &quad.translation else { panic!("polynomial expected") };
    assert!((c[0][1] - (-20.5085 * t)).abs() < 1e-4 && (c[0][2] - 126.9301 * t * t).abs() < 1e-4);
    assert!((c[1][1] - 6.0766 * t).abs() < 1e-4);
    assert!((c[2][1] - 9.1149 * t).abs() < 1e-4 && (c[2][2] - 46.1564 * t * t).abs() < 1e-4);
    let Orientation::Slerp(qs, qe) = &quad.orientation else { panic!("a slerp") };
    assert_eq!(qs, &start.rotation);
    assert!(qs.coords.dot(&qe.coords) > 0.0);

    assert_err(&s.pose("nowhere").expect_err("unknown pose"), "pose", "nowhere");
    assert_err(&s.trajectory(Some("nothing")).expect_err("unknown trajectory"), "trajectory", "linear");
}

#[test]
fn preset_obstacles() {
    let s = Scenario::from_json(CDPR7_BOX).expect("box");
    assert_eq!(s.obstacles.len(), 1);
    assert_eq!(s.obstacles[0].name, "box");
    let Shape::Mesh(m) = &s.obstacles[0].shape else { panic!("a box is a mesh") };
    assert_eq!(m.triangles.len(), 12);
    let lo = m.vertices.iter().fold(Vector3::repeat(f64::INFINITY), |a, v| a.inf(v));
    let hi = m.vertices.iter().fold(Vector3::repeat(f64::NEG_INFINITY), |a, v| a.sup(v));
    assert!((lo - Vector3::new(2.85, 1.75, 0.0)).norm() < 1e-12);
    assert!((hi - Vector3::new(3.15, 2.25, 0.3)).norm() < 1e-12);

    let s = Scenario::from_json(CDPR7_TREE).expect("tree");
    let names: Vec<&str> = s.obstacles.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["crown", "trunk", "cone"]);
    match &s.obstacles[2].shape {
        Shape::Cone { apex, axis, half_angle, height } => {
            assert_eq!(*apex, Vector3::new(2.0, 2.0, 0.3));
            assert_eq!(*axis, Vector3::new(0.0, 0.0, -1.0));
            assert!((half_angle - PI / 6.0).abs() < 1e-15);
            // Between M and the ground.
            assert!((apex.z + axis.z * height).abs() < 1e-15);
        }
        other => panic!("cone expected, got {other:?}"),
    }
}

#[test]
fn documented_example_parses() {
    // The last ```json block of docs/scenario-format.md is the complete example.
    let start = FORMAT_DOC.rfind("```json\n").expect("a json block in the doc") + "```json\n".len();
    let len = FORMAT_DOC[start..].find("```").expect("closing fence");
    let s = Scenario::from_json(&FORMAT_DOC[start..start + len]).unwrap_or_else(|e| panic!("doc example: {e}"));
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    assert_eq!(s.obstacles.len(), 6);
    assert_eq!(s.trajectories.len(), 3);
    assert_eq!(s.queries[1].fixed, [Coord::Z, Coord::Phi, Coord::Theta]);
    let c = &s.robot.cables;
    assert_eq!((c[1].length.min, c[1].length.max), (0.1, 8.0));
    assert_eq!((c[6].tension.min, c[6].tension.max), (20.0, 800.0));
    assert_eq!((c[0].tension.min, c[0].tension.max), (10.0, 500.0));
}

// ---------------------------------------------------------------------------------------------
// Valid variations and defaults

#[test]
fn defaults() {
    let s = ok_with(|_| {});
    assert_eq!(s.robot.diameter, 0.0);
    assert_eq!((s.clearance.cable_cable, s.clearance.cable_obstacle), (0.0, 0.0));
    for c in &s.robot.cables {
        assert_eq!(c.length.min, 0.0);
        assert!(c.length.max.is_infinite());
        assert_eq!(c.tension.min, 0.0);
        assert!(c.tension.max.is_infinite());
    }
    assert!(s.obstacles.is_empty());
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    assert_eq!(s.queries[0].fixed, [Coord::X, Coord::Sigma]);
    let s = ok_with(|v| {
        let o = v.as_object_mut().expect("object");
        o.remove("poses");
        o.remove("trajectories");
        o.remove("queries");
    });
    assert!(s.poses.is_empty() && s.trajectories.is_empty() && s.queries.is_empty());
    assert_err(&s.trajectory(None).expect_err("none"), "trajectory", "no trajectories");
}

#[test]
fn per_cable_bounds() {
    let s = ok_with(|v| {
        v["robot"]["length"] = json!({"min": [0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6], "max": 9});
        v["robot"]["tension"] = json!({"max": 100});
        v["robot"]["cables"][2]["length"] = json!({"max": 5});
        v["robot"]["cables"][3]["tension"] = json!({"min": 10, "max": 50});
    });
    let c = &s.robot.cables;
    assert_eq!((c[1].length.min, c[1].length.max), (0.1, 9.0));
    assert_eq!((c[2].length.min, c[2].length.max), (0.2, 5.0));
    assert_eq!((c[0].tension.min, c[0].tension.max), (0.0, 100.0));
    assert_eq!((c[3].tension.min, c[3].tension.max), (10.0, 50.0));
}

#[test]
fn all_obstacle_types_parse() {
    let s = ok_with(|v| {
        set_obstacles(
            v,
            json!([
                {"type": "box", "center": [3, 2, 0.15], "size": [0.3, 0.5, 0.3]},
                {"name": "tri", "type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]]},
                {"type": "sphere", "center": [1, 1, 1], "radius": 0.5},
                {"type": "ellipsoid", "center": [1, 1, 1], "matrix": [[4, 1, 0], [1, 3, 0], [0, 0, 2]]},
                {"type": "cylinder", "from": [0, 0, 0], "to": [0, 0, 1], "radius": 0.1},
                {"type": "cone", "apex": [2, 2, 0.3], "axis": [0, 0, -3], "half_angle": 0.5, "height": 0.3}
            ]),
        )
    });
    let names: Vec<&str> = s.obstacles.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["obstacle 1", "tri", "obstacle 3", "obstacle 4", "obstacle 5", "obstacle 6"]);
    match &s.obstacles[5].shape {
        Shape::Cone { axis, .. } => assert_eq!(*axis, Vector3::new(0.0, 0.0, -1.0), "axis normalised"),
        other => panic!("cone expected, got {other:?}"),
    }
}

#[test]
fn cable_with_base_equal_platform_coordinates_is_fine() {
    let s = ok_with(|v| v["robot"]["cables"][0] = json!({"base": [1, 1, 1], "platform": [1, 1, 1]}));
    assert_eq!(s.robot.cables[0].base, s.robot.cables[0].platform);
}

#[test]
fn pose_order_is_file_order() {
    let mut text = base().to_string();
    text = text.replacen(
        "\"poses\":{",
        "\"poses\":{\"zz\":{\"position\":[1,1,1],\"tilt_torsion\":[0.1,0.2,0.3]},\
         \"aa\":{\"position\":[2,2,2],\"quaternion\":[1,0,0,0]},",
        1,
    );
    let s = Scenario::from_json(&text).expect("parses");
    let names: Vec<&str> = s.poses.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names[..2], ["zz", "aa"]);
}

#[test]
fn wrench_section_is_validated() {
    let six = |v: &mut Value| {
        v["robot"]["cables"].as_array_mut().unwrap().pop();
    };
    let s = ok_with(|v| {
        six(v);
        v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "radius": 0.01, "point": [0.2, 0.2, 0], "point_frame": "world"});
    });
    let w = s.wrench.expect("a wrench");
    assert!((w.ellipsoid[(0, 0)] - 1e4).abs() < 1e-6 && w.ellipsoid[(0, 1)] == 0.0);
    assert_eq!(w.frame, cablenav::model::PointFrame::World);
    let full = |e: Value| {
        move |v: &mut Value| {
            six(v);
            v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "ellipsoid": e});
        }
    };
    let mut e = vec![vec![0.0; 6]; 6];
    for (i, row) in e.iter_mut().enumerate() {
        row[i] = 2.0;
    }
    let s = ok_with(full(json!(e.clone())));
    assert_eq!(s.wrench.unwrap().frame, cablenav::model::PointFrame::Platform);
    let mut asym = e.clone();
    asym[0][1] = 1.0;
    expect(full(json!(asym)), "wrench.ellipsoid", "not symmetric");
    let mut indefinite = e.clone();
    indefinite[3][3] = -1.0;
    expect(full(json!(indefinite)), "wrench.ellipsoid", "positive definite");
    expect(full(json!([[1, 0], [0, 1]])), "wrench.ellipsoid[0]", "expected 6");
    expect(|v| { six(v); v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0]}); }, "wrench", "radius");
    expect(|v| { six(v); v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "radius": 1, "ellipsoid": e}); }, "wrench", "not both");
    expect(|v| { six(v); v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "radius": -1}); }, "wrench.radius", "");
    expect(|v| { six(v); v["wrench"] = json!({"nominal": [0, 0, 1], "radius": 1}); }, "wrench.nominal", "expected 6");
    expect(|v| { six(v); v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "radius": 1, "point_frame": "moon"}); }, "wrench.point_frame", "moon");
    expect(|v| { six(v); v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "radius": 1, "mass": 3}); }, "wrench.mass", "unknown field");
    // The 7-cable base scenario takes a wrench section (the ellipsoid inside the available wrench
    // set; closure only when asked for, in format 4), without a warning; with 11 cables the
    // ellipsoid and closure are too much (facets), the nominal wrench alone is taken.
    let s = ok_with(|v| v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "radius": 1}));
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    assert!(!s.wrench.as_ref().unwrap().closure);
    expect(|v| v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "radius": 1, "closure": true}), "wrench.closure", "cablenav-scenario/4");
    let s = ok_with(|v| {
        v["format"] = json!("cablenav-scenario/4");
        v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "radius": 1, "closure": true});
    });
    assert!(s.wrench.as_ref().unwrap().closure);
    // an ellipsoid beyond 10 cables: a cover of the wrench directions, not facets
    let s = ok_with(|v| {
        for k in 0..4 {
            let cable = json!({"base": [4, k, 4], "platform": [0.1 * k as f64, 0, 0]});
            v["robot"]["cables"].as_array_mut().unwrap().push(cable);
        }
        v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "radius": 1});
    });
    assert_eq!((s.robot.cables.len(), s.wrench.as_ref().is_some_and(|w| !w.is_single())), (11, true));
    let eleven = |v: &mut Value| {
        for k in 0..4 {
            let cable = json!({"base": [4, k, 4], "platform": [0.1 * k as f64, 0, 0]});
            v["robot"]["cables"].as_array_mut().unwrap().push(cable);
        }
    };
    // closure beyond 10 cables: linear programs, not facets
    let s = ok_with(|v| {
        eleven(v);
        v["format"] = json!("cablenav-scenario/4");
        v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "closure": true});
    });
    assert!(s.wrench.as_ref().unwrap().closure);
    // format 4 takes the nominal wrench alone (no ellipsoid), for any number of cables
    let s = ok_with(|v| {
        eleven(v);
        v["format"] = json!("cablenav-scenario/4");
        v["wrench"] = json!({"nominal": [0, 0, 1, 0, 0, 0], "point": [0, 0, 0.1]});
    });
    assert_eq!(s.robot.cables.len(), 11);
    let w = s.wrench.as_ref().unwrap();
    assert!(w.is_single() && w.nominal[2] == 1.0 && w.point[2] == 0.1);
}

#[test]
fn quaternion_normalised_with_warning() {
    let s = ok_with(|v| v["poses"]["q2"]["quaternion"] = json!([2, 0, 0, 0]));
    assert_eq!(s.pose("q2").expect("q2").quaternion(), [1.0, 0.0, 0.0, 0.0]);
    assert!(
        s.warnings.iter().any(|w| w.starts_with("poses.q2.quaternion:") && w.contains("normalised")),
        "{:?}",
        s.warnings
    );
    // Within 1e-9 of unit: no warning.
    let s = ok_with(|v| v["poses"]["q2"]["quaternion"] = json!([1.0000000001, 0, 0, 0]));
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    // Tiny and huge quaternions are scaled before normalising (no under- or overflow).
    let s = ok_with(|v| v["poses"]["q2"]["quaternion"] = json!([1e-200, 0, 0, 1e-200]));
    let q = s.pose("q2").expect("q2").quaternion();
    assert!((q[0] - 0.5f64.sqrt()).abs() < 1e-12 && (q[3] - 0.5f64.sqrt()).abs() < 1e-12, "{q:?}");
    let s = ok_with(|v| v["poses"]["q2"]["quaternion"] = json!([1e300, 1e300, 0, 0]));
    assert!((s.pose("q2").expect("q2").quaternion()[1] - 0.5f64.sqrt()).abs() < 1e-12);
}

#[test]
fn slerp_endpoints_and_long_way_warning() {
    // Endpoints given as quaternions and by name.
    let s = ok_with(|v| {
        v["trajectories"][0]["orientation"] = json!({"slerp": [[1, 0, 0, 0], "q1"]});
    });
    let Orientation::Slerp(qs, qe) = &s.trajectories[0].orientation else { panic!("a slerp") };
    assert_eq!(qs.quaternion().w, 1.0);
    assert_eq!(qe, &s.pose("q1").expect("q1").rotation);
    // Negative dot product: kept as given, with a warning.
    let s = ok_with(|v| {
        v["trajectories"][0]["orientation"] = json!({"slerp": [[1, 0, 0, 0], [-0.9, 0, 0, 0.435889894354067]]});
    });
    assert!(
        s.warnings.iter().any(|w| w.starts_with("trajectories[0].orientation.slerp:") && w.contains("long way")),
        "{:?}",
        s.warnings
    );
    let Orientation::Slerp(qs, qe) = &s.trajectories[0].orientation else { panic!("a slerp") };
    assert!(qs.coords.dot(&qe.coords) < 0.0, "sign kept");
    // Same quaternion at both ends: constant orientation, fine.
    let s = ok_with(|v| v["trajectories"][0]["orientation"] = json!({"slerp": ["q1", "q1"]}));
    assert!(s.warnings.is_empty());
}

#[test]
fn trajectory_forms() {
    let s = ok_with(|v| {
        v["trajectories"] = json!([
            {"name": "p", "translation": {"polynomial": [[1, 2, 0, 0], [1], [0, 0, 3]]}, "orientation": {"slerp": ["q1", "q2"]}},
            {"name": "b", "translation": {"bezier": [[0, 0, 0], [1, 1, 1], [2, 0, 0]]}, "orientation": {"slerp": ["q1", "q2"]}},
            {"name": "l", "translation": {"line": [[0, 0, 0], [1, 1, 1]]}, "orientation": {"slerp": ["q1", "q2"]}}
        ]);
        v["queries"] = json!([]);
    });
    let Translation::Polynomial(c) = &s.trajectories[0].translation else { panic!("polynomial") };
    assert_eq!(c[0], [1.0, 2.0], "trailing zeros dropped");
    assert!(matches!(&s.trajectories[1].translation, Translation::Bezier(p) if p.len() == 3));
    assert!(matches!(&s.trajectories[2].translation, Translation::Line(..)));
    // Degree 10 (11 coefficients, 11 Bézier points) is the maximum and accepted.
    ok_with(|v| v["trajectories"][0]["translation"] = json!({"polynomial": [vec![1.0; 11], [1], [1]]}));
    ok_with(|v| v["trajectories"][0]["translation"] = json!({"bezier": vec![[0.0, 0.0, 0.0]; 11]}));
}

// ---------------------------------------------------------------------------------------------
// Errors: one per kind of mistake, each naming its JSON path

#[test]
fn dynamics_winch_and_duration_are_validated() {
    let v4 = |v: &mut Value| v["format"] = json!("cablenav-scenario/4");
    let inertia = json!([[2, 0.1, 0], [0.1, 3, 0], [0, 0, 4]]);
    let dynamics = json!({"mass": 12.5, "com": [0, 0, 0.1], "inertia": inertia});
    // format 4 is needed for each new field
    expect(|v| v["robot"]["dynamics"] = dynamics.clone(), "robot.dynamics", "cablenav-scenario/4");
    expect(|v| v["robot"]["winch"] = json!({"speed": 1}), "robot.winch", "cablenav-scenario/4");
    expect(|v| v["trajectories"][0]["duration"] = json!(2), "trajectories[0].duration", "cablenav-scenario/4");
    let s = ok_with(|v| {
        v4(v);
        v["robot"]["dynamics"] = dynamics.clone();
        v["robot"]["winch"] = json!({"speed": 1.5, "acceleration": 4});
        v["trajectories"][0]["duration"] = json!(2.5);
    });
    let d = s.robot.dynamics.as_ref().unwrap();
    assert_eq!(d.mass, 12.5);
    assert_eq!(d.gravity, nalgebra::Vector3::from(cablenav::scenario::STANDARD_GRAVITY));
    assert_eq!((d.inertia[(0, 1)], d.inertia[(2, 2)]), (0.1, 4.0));
    assert_eq!((s.robot.winch.speed, s.robot.winch.acceleration), (Some(1.5), Some(4.0)));
    assert_eq!(s.trajectories[0].duration, Some(2.5));
    assert!(s.load().is_some(), "a mass alone brings tension conditions");
    // bad values name their field
    let with_dynamics = |f: fn(&mut Value)| {
        move |v: &mut Value| {
            v4(v);
            v["robot"]["dynamics"] = json!({"mass": 12.5, "inertia": [[2, 0.1, 0], [0.1, 3, 0], [0, 0, 4]]});
            f(v)
        }
    };
    expect(with_dynamics(|v| v["robot"]["dynamics"]["mass"] = json!(0)), "robot.dynamics.mass", "positive");
    expect(with_dynamics(|v| v["robot"]["dynamics"]["mass"] = json!(-3)), "robot.dynamics.mass", "positive");
    expect(with_dynamics(|v| v["robot"]["dynamics"]["inertia"] = json!([[2, 0.5, 0], [0.1, 3, 0], [0, 0, 4]])), "robot.dynamics.inertia", "not symmetric");
    expect(with_dynamics(|v| v["robot"]["dynamics"]["inertia"] = json!([[2, 0, 0], [0, -3, 0], [0, 0, 4]])), "robot.dynamics.inertia", "positive definite");
    expect(with_dynamics(|v| v["robot"]["dynamics"]["inertia"] = json!([[2, 0], [0, 3]])), "robot.dynamics.inertia[0]", "expected 3");
    expect(with_dynamics(|v| v["robot"]["dynamics"]["com"] = json!([0, "x", 0])), "robot.dynamics.com[1]", "");
    expect(with_dynamics(|v| v["robot"]["dynamics"]["gravity"] = json!([0, 0])), "robot.dynamics.gravity", "expected 3");
    expect(with_dynamics(|v| v["robot"]["dynamics"]["spin"] = json!(1)), "robot.dynamics.spin", "unknown field");
    expect(|v| { v4(v); v["robot"]["winch"] = json!({"speed": 0}); }, "robot.winch.speed", "positive");
    expect(|v| { v4(v); v["robot"]["winch"] = json!({"acceleration": -1}); }, "robot.winch.acceleration", "positive");
    expect(|v| { v4(v); v["trajectories"][0]["duration"] = json!(0); }, "trajectories[0].duration", "positive");
    expect(|v| { v4(v); v["trajectories"][0]["duration"] = json!(-2); }, "trajectories[0].duration", "positive");
    expect(|v| { v4(v); v["trajectories"][0]["duration"] = json!("2 s"); }, "trajectories[0].duration", "");
}

#[test]
fn format_field() {
    expect(|v| v["format"] = json!("cablenav-scenario/7"), "format", "cablenav-scenario/6");
    expect(|v| v["format"] = json!(1), "format", "cablenav-scenario/1");
    expect(
        |v| {
            v.as_object_mut().expect("object").remove("format");
        },
        "format",
        "cablenav-scenario/1",
    );
}

#[test]
fn missing_required_fields() {
    type Edit = dyn Fn(&mut Value);
    let cases: [(&Edit, &str); 8] = [
        (&|v| drop(v.as_object_mut().map(|o| o.remove("name"))), "name"),
        (&|v| drop(v.as_object_mut().map(|o| o.remove("robot"))), "robot"),
        (&|v| drop(v["robot"].as_object_mut().map(|o| o.remove("cables"))), "robot.cables"),
        (&|v| drop(v["robot"]["cables"][2].as_object_mut().map(|o| o.remove("platform"))), "robot.cables[2].platform"),
        (&|v| drop(v["poses"]["q1"].as_object_mut().map(|o| o.remove("position"))), "poses.q1.position"),
        (
            &|v| drop(v["trajectories"][0].as_object_mut().map(|o| o.remove("orientation"))),
            "trajectories[0].orientation",
        ),
        (&|v| drop(v["queries"][0].as_object_mut().map(|o| o.remove("goal"))), "queries[0].goal"),
        (
            &|v| drop(v["trajectories"][0]["orientation"].as_object_mut().map(|o| o.remove("slerp"))),
            "trajectories[0].orientation.slerp",
        ),
    ];
    for (f, field) in cases {
        expect(f, field, "missing field");
    }
    expect(|v| set_obstacles(v, json!([{"type": "sphere", "radius": 1}])), "obstacles[0].center", "missing field");
    expect(|v| set_obstacles(v, json!([{"center": [0, 0, 0], "radius": 1}])), "obstacles[0].type", "missing field");
}

#[test]
fn unknown_fields_are_named() {
    expect(|v| v["colour"] = json!("red"), "colour", "unknown field `colour`");
    expect(|v| v["robot"]["cables"][1]["bse"] = json!([0, 0, 0]), "robot.cables[1].bse", "unknown field `bse`");
    expect(|v| v["robot"]["length"] = json!({"minimum": 1}), "robot.length.minimum", "unknown field");
    expect(|v| v["clearance"] = json!({"cable_cables": 1}), "clearance.cable_cables", "unknown field");
    expect(|v| v["poses"]["q1"]["orientation"] = json!([1, 0, 0, 0]), "poses.q1.orientation", "unknown field");
    expect(
        |v| v["trajectories"][0]["translation"] = json!({"spline": [[0, 0, 0]]}),
        "trajectories[0].translation.spline",
        "unknown field",
    );
    expect(|v| v["queries"][0]["via"] = json!("q1"), "queries[0].via", "unknown field");
    expect(
        |v| set_obstacles(v, json!([{"type": "sphere", "center": [0, 0, 0], "radius": 1, "colour": 3}])),
        "obstacles[0].colour",
        "unknown field",
    );
    // A field of another obstacle type.
    expect(
        |v| set_obstacles(v, json!([{"type": "box", "center": [0, 0, 0], "size": [1, 1, 1], "radius": 1}])),
        "obstacles[0].radius",
        "not a field of a box",
    );
}

#[test]
fn wrong_types_and_array_lengths() {
    expect(|v| v["robot"]["cables"][2]["base"] = json!([1, 2]), "robot.cables[2].base", "expected 3 numbers, got 2");
    expect(
        |v| v["robot"]["cables"][2]["base"] = json!([1, 2, 3, 4]),
        "robot.cables[2].base",
        "expected 3 numbers, got 4",
    );
    expect(|v| v["robot"]["cables"][2]["base"] = json!([1, "2", 3]), "robot.cables[2].base[1]", "invalid type");
    expect(
        |v| v["robot"]["cables"][2]["base"] = json!("here"),
        "robot.cables[2].base",
        "expected an array of 3 numbers",
    );
    expect(|v| v["robot"]["cables"] = json!({}), "robot.cables", "invalid type");
    expect(|v| v["robot"]["diameter"] = json!("thin"), "robot.diameter", "invalid type");
    expect(|v| v["name"] = json!(3), "name", "invalid type");
    expect(|v| v["robot"]["length"] = json!({"min": "0"}), "robot.length.min", "number or an array");
    expect(|v| v["robot"]["length"] = json!({"max": [1, "x"]}), "robot.length.max[1]", "invalid type");
    expect(|v| v["poses"]["q2"]["quaternion"] = json!([1, 0, 0]), "poses.q2.quaternion", "expected 4 numbers, got 3");
    expect(|v| v["poses"] = json!([]), "poses", "invalid type");
    expect(
        |v| v["trajectories"][0]["orientation"] = json!({"slerp": ["q1", "q2", "q1"]}),
        "trajectories[0].orientation.slerp",
        "expected 2",
    );
    expect(
        |v| v["trajectories"][0]["orientation"] = json!({"slerp": ["q1", 7]}),
        "trajectories[0].orientation.slerp[1]",
        "quaternion [w, x, y, z] or a pose name",
    );
    expect(
        |v| v["trajectories"][0]["orientation"] = json!({"slerp": ["q1", [1, 0]]}),
        "trajectories[0].orientation.slerp[1]",
        "expected 4 numbers, got 2",
    );
    expect(
        |v| v["trajectories"][0]["translation"] = json!({"line": [[0, 0, 0]]}),
        "trajectories[0].translation.line",
        "expected 2 points",
    );
    expect(|v| v["queries"][0]["fixed"] = json!("x"), "queries[0].fixed", "invalid type");
    expect(
        |v| {
            set_obstacles(
                v,
                json!([{"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, -1, 2]]}]),
            )
        },
        "obstacles[0].triangles[0][1]",
        "invalid value",
    );
    expect(
        |v| {
            set_obstacles(
                v,
                json!([{"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1.5, 2]]}]),
            )
        },
        "obstacles[0].triangles[0][1]",
        "invalid type",
    );
    expect(
        |v| set_obstacles(v, json!([{"type": "ellipsoid", "center": [0, 0, 0], "matrix": [[1, 0, 0], [0, 1, 0]]}])),
        "obstacles[0].matrix",
        "expected 3",
    );
}

#[test]
fn overflowing_numbers_name_the_field() {
    let text = base().to_string().replacen("[4,2,0]", "[4,1e999,0]", 1);
    assert!(text.contains("1e999"));
    let e = err_text(&text);
    assert_err(&e, "robot.cables[2].base[1]", "number out of range");
    let text = base().to_string().replacen("\"euler_xyz_deg\":[0,0,30]", "\"euler_xyz_deg\":[0,0,-1e400]", 1);
    assert!(text.contains("1e400"));
    assert_err(&err_text(&text), "poses.q1.euler_xyz_deg[2]", "number out of range");
}

#[test]
fn malformed_json_reports_line_and_column() {
    let e = err_text("{\"format\": \"cablenav-scenario/1\",\n \"name\": \"x\" \"robot\": {}}");
    assert!(e.reason.contains("line 2") && e.reason.contains("column"), "{e}");
    let e = err_text("{\"format\": \"cablenav-scenario/1\", \"name\": \"x\", \"robot\": {\"cables\": [");
    assert!(e.reason.contains("truncated") && e.reason.contains("line 1"), "{e}");
    let e = err_text("");
    assert!(e.reason.contains("line"), "{e}");
    // Trailing garbage after the object.
    let text = format!("{} x", base());
    assert!(err_text(&text).reason.contains("malformed"));
    // Not an object at all.
    err_text("[1, 2, 3]");
    err_text("null");
    err_text("\"cablenav-scenario/1\"");
    // Deep nesting is refused (serde_json's recursion limit), not a stack overflow.
    let deep =
        format!("{{\"format\": \"cablenav-scenario/1\", \"wrench\": {}{}}}", "[".repeat(100_000), "]".repeat(100_000));
    err_text(&deep);
}

#[test]
fn cable_count_limits() {
    expect(
        |v| {
            v["robot"]["cables"].as_array_mut().expect("array").truncate(5);
        },
        "robot.cables",
        "at least 6",
    );
    expect(
        |v| {
            v["robot"]["cables"] =
                Value::Array((0..65).map(|i| json!({"base": [i, 0, 0], "platform": [0, 0, 0]})).collect());
        },
        "robot.cables",
        "at most 64",
    );
    // 64 is fine.
    ok_with(|v| {
        v["robot"]["cables"] =
            Value::Array((0..64).map(|i| json!({"base": [i, 0, 10], "platform": [0, 0, 0]})).collect());
    });
}

#[test]
fn coincident_anchors() {
    expect(|v| v["robot"]["cables"][3] = v["robot"]["cables"][1].clone(), "robot.cables[3]", "coincident anchors");
}

#[test]
fn coordinates_beyond_a_sane_range_are_refused_by_field() {
    // 1e308 once passed as finite and overflowed into "cable 1 has zero length"
    expect(|v| v["robot"]["cables"][0]["base"][0] = json!(1e308), "robot.cables[0].base[0]", "within ±1e6");
    expect(|v| v["robot"]["cables"][2]["platform"][2] = json!(-2e6), "robot.cables[2].platform[2]", "within ±1e6");
    expect(|v| v["poses"]["q1"] = json!({"position": [0, 1e7, 1], "quaternion": [1, 0, 0, 0]}), "poses.q1.position[1]", "got 1e7");
    // the bound itself is accepted
    ok_with(|v| v["robot"]["cables"][0]["base"][0] = json!(1e6));
}

#[test]
fn zero_cable_length_at_a_pose() {
    // Cable 3: base (4, 2, 0), platform anchor (0.15, 0, 0.3) → zero length at position (3.85, 2, −0.3).
    let e = err_with(|v| v["poses"]["q1"] = json!({"position": [3.85, 2, -0.3], "quaternion": [1, 0, 0, 0]}));
    assert_err(&e, "poses.q1", "cable 3 has zero length at pose q1");
}

#[test]
fn bounds_errors() {
    expect(|v| v["robot"]["length"] = json!({"min": 3, "max": 2}), "robot.length", "greater than max");
    expect(|v| v["robot"]["tension"] = json!({"min": 3, "max": 2}), "robot.tension", "greater than max");
    expect(
        |v| {
            v["robot"]["length"] = json!({"max": 10});
            v["robot"]["cables"][1]["length"] = json!({"min": 11});
        },
        "robot.cables[1].length",
        "greater than max",
    );
    // Only an override of the maximum below the robot-level minimum.
    expect(
        |v| {
            v["robot"]["length"] = json!({"min": 1});
            v["robot"]["cables"][4]["length"] = json!({"max": 0.5});
        },
        "robot.cables[4].length",
        "greater than max",
    );
    expect(|v| v["robot"]["length"] = json!({"min": -1}), "robot.length.min", "negative");
    expect(|v| v["robot"]["tension"] = json!({"max": -1}), "robot.tension.max", "negative");
    expect(|v| v["robot"]["length"] = json!({"max": [1, 2, 3, -4, 5, 6, 7]}), "robot.length.max[3]", "negative");
    expect(|v| v["robot"]["cables"][2]["tension"] = json!({"min": -0.5}), "robot.cables[2].tension.min", "negative");
    expect(|v| v["robot"]["length"] = json!({"min": [0, 0, 0, 0, 0, 0]}), "robot.length.min", "7 numbers");
    expect(|v| v["robot"]["diameter"] = json!(-0.02), "robot.diameter", "negative");
    expect(|v| v["clearance"] = json!({"cable_cable": -0.1}), "clearance.cable_cable", "negative");
    expect(|v| v["clearance"] = json!({"cable_obstacle": -0.1}), "clearance.cable_obstacle", "negative");
}

#[test]
fn obstacle_errors() {
    let tri = json!([[0, 0, 0], [1, 0, 0], [0, 1, 0]]);
    let cases: Vec<(Value, &str, &str)> = vec![
        (json!({"type": "torus", "center": [0, 0, 0]}), "obstacles[0].type", "unknown obstacle type"),
        (
            json!({"type": "mesh", "vertices": tri, "triangles": [[0, 1, 2], [0, 1, 3]]}),
            "obstacles[0].triangles[1][2]",
            "out of range",
        ),
        (json!({"type": "mesh", "vertices": tri, "triangles": [[0, 1, 1]]}), "obstacles[0].triangles[0]", "degenerate"),
        (
            json!({"type": "mesh", "vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]], "triangles": [[0, 1, 2]]}),
            "obstacles[0].triangles[0]",
            "degenerate",
        ),
        (json!({"type": "mesh", "vertices": tri, "triangles": []}), "obstacles[0].triangles", "at least one triangle"),
        (json!({"type": "mesh", "triangles": [[0, 1, 2]]}), "obstacles[0].vertices", "missing field"),
        (json!({"type": "box", "center": [0, 0, 0], "size": [1, 0, 1]}), "obstacles[0].size[1]", "positive"),
        (json!({"type": "box", "center": [0, 0, 0], "size": [1, 1, -1]}), "obstacles[0].size[2]", "positive"),
        (json!({"type": "sphere", "center": [0, 0, 0], "radius": 0}), "obstacles[0].radius", "positive"),
        (
            json!({"type": "cylinder", "from": [0, 0, 0], "to": [0, 0, 1], "radius": -1}),
            "obstacles[0].radius",
            "positive",
        ),
        (
            json!({"type": "cylinder", "from": [0, 0, 1], "to": [0, 0, 1], "radius": 1}),
            "obstacles[0].to",
            "zero length",
        ),
        (
            json!({"type": "ellipsoid", "center": [0, 0, 0], "matrix": [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]}),
            "obstacles[0].matrix",
            "not symmetric",
        ),
        (
            json!({"type": "ellipsoid", "center": [0, 0, 0], "matrix": [[1, 2, 0], [2, 1, 0], [0, 0, 1]]}),
            "obstacles[0].matrix",
            "not positive definite",
        ),
        (
            json!({"type": "ellipsoid", "center": [0, 0, 0], "matrix": [[0, 0, 0], [0, 0, 0], [0, 0, 0]]}),
            "obstacles[0].matrix",
            "not positive definite",
        ),
        (
            json!({"type": "cone", "apex": [0, 0, 0], "axis": [0, 0, 0], "half_angle": 0.5, "height": 1}),
            "obstacles[0].axis",
            "zero",
        ),
        (
            json!({"type": "cone", "apex": [0, 0, 0], "axis": [0, 0, 1], "half_angle": 0, "height": 1}),
            "obstacles[0].half_angle",
            "(0, π/2)",
        ),
        (
            json!({"type": "cone", "apex": [0, 0, 0], "axis": [0, 0, 1], "half_angle": FRAC_PI_2, "height": 1}),
            "obstacles[0].half_angle",
            "(0, π/2)",
        ),
        (
            json!({"type": "cone", "apex": [0, 0, 0], "axis": [0, 0, 1], "half_angle": -0.1, "height": 1}),
            "obstacles[0].half_angle",
            "(0, π/2)",
        ),
        (
            json!({"type": "cone", "apex": [0, 0, 0], "axis": [0, 0, 1], "half_angle": 0.5, "height": 0}),
            "obstacles[0].height",
            "positive",
        ),
        (json!({"name": "", "type": "sphere", "center": [0, 0, 0], "radius": 1}), "obstacles[0].name", "empty"),
    ];
    for (o, field, reason) in cases {
        expect(|v| set_obstacles(v, json!([o])), field, reason);
    }
    // Symmetric up to a relative 1e-9 is accepted.
    ok_with(|v| {
        set_obstacles(
            v,
            json!([{"type": "ellipsoid", "center": [0, 0, 0], "matrix": [[1, 1e-12, 0], [0, 1, 0], [0, 0, 1]]}]),
        )
    });
}

#[test]
fn obstacle_limits() {
    let many = |n: usize| -> Value {
        json!([{"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": vec![[0, 1, 2]; n]}])
    };
    expect(|v| set_obstacles(v, many(100_001)), "obstacles[0].triangles", "at most 100000");
    ok_with(|v| set_obstacles(v, many(100_000)));
    // The total over all meshes (boxes count 12).
    expect(
        |v| {
            let mut obs = many(99_990);
            if let Some(a) = obs.as_array_mut() {
                a.push(json!({"type": "box", "center": [0, 0, 0], "size": [1, 1, 1]}));
            }
            set_obstacles(v, obs)
        },
        "obstacles[1]",
        "100000 triangles in total",
    );
    let spheres = |n: usize| -> Value {
        Value::Array((0..n).map(|i| json!({"type": "sphere", "center": [i, 0, 0], "radius": 0.1})).collect())
    };
    expect(|v| set_obstacles(v, spheres(1001)), "obstacles", "at most 1000");
    ok_with(|v| set_obstacles(v, spheres(1000)));
}

#[test]
fn pose_errors() {
    expect(|v| v["poses"]["q2"]["quaternion"] = json!([0, 0, 0, 0]), "poses.q2.quaternion", "zero quaternion");
    expect(|v| v["poses"]["q2"]["tilt_torsion"] = json!([0, 0, 0]), "poses.q2", "exactly one");
    expect(|v| v["poses"]["q2"] = json!({"position": [0, 0, 0]}), "poses.q2", "exactly one");
    // Duplicate pose names: a JSON object with the key twice.
    let text = base().to_string().replacen(
        "\"poses\":{",
        "\"poses\":{\"q2\":{\"position\":[1,1,1],\"quaternion\":[1,0,0,0]},",
        1,
    );
    assert_err(&err_text(&text), "poses.q2", "duplicate pose name");
}

#[test]
fn trajectory_errors() {
    let t = "trajectories[0].translation";
    let set = |tr: Value| move |v: &mut Value| v["trajectories"][0]["translation"] = tr;
    expect(set(json!({"polynomial": [[1], [2]]})), &format!("{t}.polynomial"), "3 rows");
    expect(set(json!({"polynomial": [[1], [2], [3], [4]]})), &format!("{t}.polynomial"), "3 rows");
    expect(set(json!({"polynomial": [[1], [], [3]]})), &format!("{t}.polynomial[1]"), "empty row");
    expect(set(json!({"polynomial": [vec![1.0; 12], [2], [3]]})), &format!("{t}.polynomial[0]"), "exact verification");
    expect(set(json!({"bezier": vec![[0.0, 0.0, 0.0]; 12]})), &format!("{t}.bezier"), "exact verification");
    expect(set(json!({"bezier": [[0, 0, 0]]})), &format!("{t}.bezier"), "at least 2");
    expect(set(json!({"line": [[0, 0, 0], [1, 1, 1]], "bezier": [[0, 0, 0], [1, 1, 1]]})), t, "exactly one");
    expect(set(json!({})), t, "exactly one");
    expect(
        |v| v["trajectories"][0]["orientation"] = json!({"slerp": ["q1", "elsewhere"]}),
        "trajectories[0].orientation.slerp[1]",
        "unknown pose \"elsewhere\"",
    );
    expect(
        |v| v["trajectories"][0]["orientation"] = json!({"slerp": [[0, 0, 0, 0], "q1"]}),
        "trajectories[0].orientation.slerp[0]",
        "zero quaternion",
    );
    expect(
        |v| v["trajectories"][0]["orientation"] = json!({"slerp": [[0.6, 0, 0.8, 0], [-0.6, 0, -0.8, 0]]}),
        "trajectories[0].orientation.slerp",
        "undefined",
    );
    // Up to 1e-12.
    expect(
        |v| v["trajectories"][0]["orientation"] = json!({"slerp": [[1, 0, 0, 0], [-1, 0, 1e-7, 0]]}),
        "trajectories[0].orientation.slerp",
        "undefined",
    );
    expect(
        |v| {
            let t0 = v["trajectories"][0].clone();
            if let Some(a) = v["trajectories"].as_array_mut() {
                a.push(t0);
            }
        },
        "trajectories[1].name",
        "duplicate trajectory name",
    );
    expect(|v| v["trajectories"][0]["name"] = json!(""), "trajectories[0].name", "empty");
}

#[test]
fn query_errors() {
    expect(|v| v["queries"][0]["goal"] = json!("q3"), "queries[0].goal", "unknown pose \"q3\"");
    expect(|v| v["queries"][0]["start"] = json!("q0"), "queries[0].start", "unknown pose");
    expect(|v| v["queries"][0]["fixed"] = json!(["x", "alpha"]), "queries[0].fixed[1]", "unknown coordinate");
    expect(|v| v["queries"][0]["fixed"] = json!(["x", "x"]), "queries[0].fixed[1]", "twice");
    expect(
        |v| {
            let q0 = v["queries"][0].clone();
            if let Some(a) = v["queries"].as_array_mut() {
                a.push(q0);
            }
        },
        "queries[1].name",
        "duplicate query name",
    );
}

#[test]
fn duplicate_obstacle_names() {
    expect(
        |v| {
            set_obstacles(
                v,
                json!([
                    {"name": "rock", "type": "sphere", "center": [0, 0, 0], "radius": 1},
                    {"name": "rock", "type": "sphere", "center": [1, 0, 0], "radius": 1}
                ]),
            )
        },
        "obstacles[1].name",
        "duplicate obstacle name",
    );
    // A default name colliding with an explicit one.
    expect(
        |v| {
            set_obstacles(
                v,
                json!([
                    {"name": "obstacle 2", "type": "sphere", "center": [0, 0, 0], "radius": 1},
                    {"type": "sphere", "center": [1, 0, 0], "radius": 1}
                ]),
            )
        },
        "obstacles[1]",
        "duplicate obstacle name",
    );
}

// ---------------------------------------------------------------------------------------------
// Orientation conventions, both ways

#[test]
fn tilt_torsion_round_trip() {
    let mut rng = Rng(0x5eed_1234_abcd_0001);
    for k in 0..2000 {
        let phi = rng.range(-PI, PI);
        let theta = match k % 10 {
            0 => 0.0,
            1 => PI,
            2 => 1e-9,
            _ => rng.range(0.0, PI),
        };
        let sigma = rng.range(-PI, PI);
        let p = Pose::from_tilt_torsion(Vector3::zeros(), [phi, theta, sigma]);
        let [phi2, theta2, sigma2] = p.tilt_torsion();
        let back = Pose::from_tilt_torsion(Vector3::zeros(), [phi2, theta2, sigma2]);
        assert!(same_rotation(&p, &back, 1e-13), "({phi}, {theta}, {sigma}) -> ({phi2}, {theta2}, {sigma2})");
        assert!((theta - theta2).abs() < 1e-13, "θ {theta} vs {theta2}");
        if theta > 1e-3 && theta < PI - 1e-3 {
            assert!(angle_diff(phi, phi2) < 1e-9, "φ {phi} vs {phi2}");
            assert!(angle_diff(sigma, sigma2) < 1e-9, "σ {sigma} vs {sigma2}");
        } else if theta == 0.0 {
            // R = Rz(σ): φ is not determined, σ is.
            assert_eq!(phi2, 0.0);
            assert!(angle_diff(sigma, sigma2) < 1e-9, "σ {sigma} vs {sigma2}");
        }
        // Via the quaternion.
        let q = p.quaternion();
        let via_q = Pose::from_quaternion(Vector3::zeros(), q);
        assert!(same_rotation(&p, &via_q, 1e-12));
        let [a, b, c] = via_q.tilt_torsion();
        assert!(same_rotation(&p, &Pose::from_tilt_torsion(Vector3::zeros(), [a, b, c]), 1e-9));
    }
}

#[test]
fn euler_round_trip() {
    let mut rng = Rng(0x0dd_ba11_cafe_f00d);
    for k in 0..2000 {
        let a = rng.range(-180.0, 180.0);
        let b = match k % 10 {
            0 => 90.0,
            1 => -90.0,
            2 => 0.0,
            _ => rng.range(-90.0, 90.0),
        };
        let c = rng.range(-180.0, 180.0);
        let p = Pose::from_euler_xyz_deg(Vector3::zeros(), [a, b, c]);
        let [a2, b2, c2] = p.euler_xyz_deg();
        let back = Pose::from_euler_xyz_deg(Vector3::zeros(), [a2, b2, c2]);
        assert!(same_rotation(&p, &back, 1e-13), "({a}, {b}, {c}) -> ({a2}, {b2}, {c2})");
        if b.abs() < 89.9 {
            assert!(angle_diff(a.to_radians(), a2.to_radians()) < 1e-9);
            assert!((b - b2).abs() < 1e-9);
            assert!(angle_diff(c.to_radians(), c2.to_radians()) < 1e-9);
        } else if b.abs() == 90.0 {
            assert!((b - b2).abs() < 1e-12, "β {b} vs {b2}");
            assert_eq!(c2, 0.0, "gimbal lock: γ folded into α");
        }
        // Euler → tilt-and-torsion → Euler.
        let tt = Pose::from_tilt_torsion(Vector3::zeros(), p.tilt_torsion());
        assert!(same_rotation(&p, &tt, 1e-9));
        let [a3, b3, c3] = tt.euler_xyz_deg();
        assert!(same_rotation(&p, &Pose::from_euler_xyz_deg(Vector3::zeros(), [a3, b3, c3]), 1e-9));
    }
}

#[test]
fn quaternion_round_trip() {
    let mut rng = Rng(0xfeed_beef_0000_0042);
    for _ in 0..2000 {
        let q = [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)];
        let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        if n < 1e-3 {
            continue;
        }
        let p = Pose::from_quaternion(Vector3::zeros(), q);
        let u = q.map(|x| x / n);
        let back = Pose::from_tilt_torsion(Vector3::zeros(), p.tilt_torsion()).quaternion();
        let dot: f64 = u.iter().zip(back).map(|(a, b)| a * b).sum();
        assert!((dot.abs() - 1.0).abs() < 1e-9, "{u:?} vs {back:?}");
        let back = Pose::from_euler_xyz_deg(Vector3::zeros(), p.euler_xyz_deg()).quaternion();
        let dot: f64 = u.iter().zip(back).map(|(a, b)| a * b).sum();
        assert!((dot.abs() - 1.0).abs() < 1e-9, "{u:?} vs {back:?}");
    }
}

#[test]
fn three_forms_in_json_agree() {
    // The same rotations given three ways in a scenario.
    let mut rng = Rng(42);
    for _ in 0..50 {
        let tt = [rng.range(-PI, PI), rng.range(0.0, PI), rng.range(-PI, PI)];
        let reference = Pose::from_tilt_torsion(Vector3::zeros(), tt);
        let e = reference.euler_xyz_deg();
        let q = reference.quaternion();
        let s = ok_with(|v| {
            v["poses"]["a"] = json!({"position": [1, 1, 1], "tilt_torsion": tt});
            v["poses"]["b"] = json!({"position": [1, 1, 1], "euler_xyz_deg": e});
            v["poses"]["c"] = json!({"position": [1, 1, 1], "quaternion": q});
        });
        let (a, b, c) = (s.pose("a").expect("a"), s.pose("b").expect("b"), s.pose("c").expect("c"));
        assert!(same_rotation(a, b, 1e-9) && same_rotation(a, c, 1e-9));
        // Angle forms get the sign w ≥ 0.
        assert!(a.quaternion()[0] >= 0.0 && b.quaternion()[0] >= 0.0);
    }
    // Conventions: tilt-and-torsion (0, θ, 0) tilts about y; Euler (α, 0, 0) is about x.
    let s = ok_with(|v| {
        v["poses"]["t"] = json!({"position": [1, 1, 1], "tilt_torsion": [0, FRAC_PI_2, 0]});
        v["poses"]["e"] = json!({"position": [1, 1, 1], "euler_xyz_deg": [90, 0, 0]});
        v["poses"]["s"] = json!({"position": [1, 1, 1], "tilt_torsion": [0.7, 0, 0.3]});
    });
    let z = Vector3::z();
    assert!((s.pose("t").expect("t").rotation * z - Vector3::x()).norm() < 1e-12);
    assert!((s.pose("e").expect("e").rotation * z + Vector3::y()).norm() < 1e-12);
    // θ = 0: a pure torsion by σ, whatever φ.
    let r = s.pose("s").expect("s").matrix();
    assert!(close_m(&r, &cablenav::model::pose::rot_z(0.3), 1e-12));
}

// ---------------------------------------------------------------------------------------------
// Robustness: truncated and mutated input never panics

#[test]
fn truncated_presets_are_errors() {
    for (name, text) in PRESETS {
        let body = text.trim_end();
        for (cut, _) in body.char_indices() {
            let prefix = &body[..cut];
            assert!(Scenario::from_json(prefix).is_err(), "{name}: prefix of {cut} bytes parsed");
        }
    }
}

#[test]
fn mutated_presets_never_panic() {
    const ALPHABET: &[u8] = b"{}[]\":,.-+eE0123456789 \nabcxyz\\/ntf";
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let mut errors = 0usize;
    let rounds = 3000;
    for round in 0..rounds {
        let (_, text) = PRESETS[round % PRESETS.len()];
        let mut bytes = text.as_bytes().to_vec();
        let edits = 1 + rng.below(3);
        for _ in 0..edits {
            let at = rng.below(bytes.len());
            match rng.below(3) {
                0 => bytes[at] = ALPHABET[rng.below(ALPHABET.len())],
                1 => {
                    bytes.remove(at);
                }
                _ => bytes.insert(at, ALPHABET[rng.below(ALPHABET.len())]),
            }
        }
        let mutated = String::from_utf8_lossy(&bytes);
        match Scenario::from_json(&mutated) {
            Err(e) => {
                errors += 1;
                assert!(!e.reason.is_empty());
            }
            Ok(s) => {
                // Whatever parsed is still a valid scenario.
                assert!(s.robot.cables.len() >= 6);
                assert!(s.robot.cables.iter().all(|c| c.length.min <= c.length.max));
            }
        }
    }
    // Most random edits break the file.
    assert!(errors > rounds / 2, "only {errors} of {rounds} mutations were rejected");
}

// ---------------------------------------------------------------------------------------------
// Obstacle colours (optional, display only)

#[test]
fn obstacle_colours_are_kept_and_checked() {
    let s = ok_with(|v| {
        set_obstacles(
            v,
            json!([
                {"type": "sphere", "center": [9, 9, 9], "radius": 0.1, "color": "#1a2B3c"},
                {"type": "sphere", "center": [8, 8, 8], "radius": 0.1}
            ]),
        )
    });
    assert_eq!(s.obstacles[0].color.as_deref(), Some("#1a2B3c"));
    assert_eq!(s.obstacles[1].color, None);
    for bad in ["red", "#12345", "#1234567", "#12345g", "123456", ""] {
        expect(
            |v| set_obstacles(v, json!([{"type": "sphere", "center": [9, 9, 9], "radius": 0.1, "color": bad}])),
            "obstacles[0].color",
            "#rrggbb",
        );
    }
    expect(
        |v| set_obstacles(v, json!([{"type": "sphere", "center": [9, 9, 9], "radius": 0.1, "color": 3}])),
        "obstacles[0].color",
        "invalid type",
    );
}

/// Timed spline trajectories through knots (format 4): what they accept, and every bad knot named.
#[test]
fn knots_are_validated() {
    let knots = json!([
        {"time": 0, "pose": "q1"},
        {"time": 1.5, "position": [1.8, 2.0, 2.0], "tilt_torsion": [10, 20, 0], "velocity": [0.1, 0, 0.2], "acceleration": [0, 0, -0.1]},
        {"time": 3, "pose": "q2"}
    ]);
    let spline = |knots: Value| {
        move |v: &mut Value| {
            v["format"] = json!("cablenav-scenario/4");
            v["trajectories"][0] = json!({"name": "k", "spline": "quintic", "knots": knots});
        }
    };
    let s = ok_with(spline(knots.clone()));
    let t = &s.trajectories[0];
    assert_eq!((t.duration, t.piece_count()), (Some(3.0), 2));
    assert_eq!(t.piece_span(1), [0.5, 1.0]);
    assert!((t.pose_at(0.5).position - nalgebra::Vector3::new(1.8, 2.0, 2.0)).norm() < 1e-12);
    // written back, it reads the same
    let mut v = base();
    v["format"] = json!("cablenav-scenario/4");
    v["trajectories"][0] = cablenav::scenario::trajectory_json(t);
    let again = parse_value(&v).unwrap();
    assert!((again.trajectories[0].pose_at(0.3).position - t.pose_at(0.3).position).norm() < 1e-12);
    assert!(again.trajectories[0].pose_at(0.7).rotation.angle_to(&t.pose_at(0.7).rotation) < 1e-12);
    // the bad inputs
    expect(|v| v["trajectories"][0] = json!({"name": "k", "knots": [{"time": 0, "pose": "q1"}, {"time": 1, "pose": "q2"}]}), "trajectories[0].knots", "cablenav-scenario/4");
    let with = |edit: fn(&mut Value)| {
        let knots = knots.clone();
        move |v: &mut Value| {
            spline(knots)(v);
            edit(&mut v["trajectories"][0]);
        }
    };
    expect(with(|t| t["knots"][2]["time"] = json!(1.0)), "trajectories[0].knots[2].time", "out of order");
    expect(with(|t| t["knots"][1]["time"] = json!("soon")), "trajectories[0].knots[1].time", "");
    expect(with(|t| t["knots"][0]["time"] = json!(0.5)), "trajectories[0].knots[0].time", "time 0");
    expect(with(|t| t["knots"] = json!([{"time": 0, "pose": "q1"}])), "trajectories[0].knots", "2 to");
    expect(with(|t| t["spline"] = json!("linear")), "trajectories[0].spline", "quintic");
    expect(with(|t| t["duration"] = json!(2)), "trajectories[0].duration", "from them");
    expect(with(|t| t["translation"] = json!({"line": [[0, 0, 0], [1, 1, 1]]})), "trajectories[0].knots", "not both");
    expect(with(|t| t["knots"][0]["pose"] = json!("nowhere")), "trajectories[0].knots[0].pose", "no pose named");
    expect(with(|t| t["knots"][0]["position"] = json!([0, 0, 0])), "trajectories[0].knots[0].pose", "not both");
    expect(with(|t| drop(t["knots"][1].as_object_mut().map(|o| o.remove("position")))), "trajectories[0].knots[1].position", "pose name or a position");
    expect(with(|t| drop(t["knots"][1].as_object_mut().map(|o| o.remove("tilt_torsion")))), "trajectories[0].knots[1]", "exactly one of");
    expect(with(|t| t["knots"][1]["velocity"] = json!([0, 0])), "trajectories[0].knots[1].velocity", "expected 3");
    expect(with(|t| t["knots"][1]["spin"] = json!(1)), "trajectories[0].knots[1].spin", "unknown field");
    expect(with(|t| t["spline"] = json!("cubic")), "trajectories[0].knots[1].acceleration", "cubic");
    let cubic = ok_with(with(|t| {
        t["spline"] = json!("cubic");
        drop(t["knots"][1].as_object_mut().map(|o| o.remove("acceleration")));
    }));
    assert_eq!(cubic.trajectories[0].knots.as_ref().unwrap().profile, cablenav::model::Profile::Cubic);
}

/// A point mass hanging from three cables and a planar platform on four (format 5), as the
/// tests below change them.
fn mobile(mobility: &str) -> Value {
    let planar = mobility == "planar";
    let cables = if planar {
        json!([{"base": [0, 0, 0], "platform": [0.1, 0, 0]}, {"base": [2, 0, 0], "platform": [0, 0.1, 0]},
               {"base": [2, 2, 0], "platform": [-0.1, 0, 0]}, {"base": [0, 2, 0], "platform": [0, -0.1, 0]}])
    } else {
        json!([{"base": [0, 0, 3]}, {"base": [4, 0, 3]}, {"base": [2, 3.5, 3]}])
    };
    let dynamics = if planar { json!({"mass": 2, "inertia": [[0, 0, 0], [0, 0, 0], [0, 0, 0.1]]}) } else { json!({"mass": 1}) };
    let mut v = json!({
        "format": "cablenav-scenario/5", "name": mobility,
        "robot": {"mobility": mobility, "cables": cables, "tension": {"min": 1, "max": 50}, "dynamics": dynamics},
        "poses": {"a": {"position": [1, 1, 1]}},
        "trajectories": [{"name": "line", "translation": {"line": [[1, 1, 1], [1.2, 1.1, 1.5]]}}]
    });
    if planar {
        // a planar platform's orientation is given (a turn about z), as a spatial one's
        v["poses"]["a"] = json!({"position": [1, 1, 0], "euler_xyz_deg": [0, 0, 20]});
        v["trajectories"][0] = json!({"name": "line", "translation": {"line": [[1, 1, 0], [1.2, 1.1, 0]]}, "orientation": {"slerp": ["a", [1, 0, 0, 0]]}});
    }
    v
}

/// `mobile(mobility)` changed by `f` must fail at `field` with `reason_part` in the message.
fn expect_mobile(mobility: &str, f: impl FnOnce(&mut Value), field: &str, reason_part: &str) {
    let mut v = mobile(mobility);
    f(&mut v);
    let e = parse_value(&v).map(|_| ()).expect_err(&format!("expected an error for {v}"));
    assert_err(&e, field, reason_part);
}

#[test]
fn point_masses_and_planar_platforms_read_and_refuse_what_they_cannot_be() {
    // as written: a point mass without platform anchors, orientations or inertia; a planar
    // platform whose inertia is its I_zz alone
    let point = parse_value(&mobile("point")).expect("the point mass reads");
    assert_eq!(point.robot.mobility, cablenav::model::Mobility::Point);
    assert!(point.robot.cables.iter().all(|c| c.platform == nalgebra::Vector3::zeros()));
    assert_eq!(point.poses[0].1.rotation, nalgebra::UnitQuaternion::identity());
    let planar = parse_value(&mobile("planar")).expect("the planar robot reads");
    assert_eq!(planar.robot.mobility.rows(), &[0, 1, 5]);
    // the version, the name
    expect_mobile("point", |v| v["format"] = json!("cablenav-scenario/4"), "robot.mobility", "cablenav-scenario/5");
    expect_mobile("point", |v| v["robot"]["mobility"] = json!("wheeled"), "robot.mobility", "unknown mobility");
    // a point mass: its cables end at the point, it has no inertia, at least three cables
    expect_mobile("point", |v| v["robot"]["cables"][1]["platform"] = json!([0, 0, 0.1]), "robot.cables[1].platform", "end at the point");
    expect_mobile("point", |v| v["robot"]["dynamics"]["inertia"] = json!([[1, 0, 0], [0, 1, 0], [0, 0, 1]]), "robot.dynamics.inertia", "no inertia");
    expect_mobile("point", |v| v["robot"]["dynamics"]["com"] = json!([0, 0, 0.1]), "robot.dynamics.com", "the point");
    expect_mobile("point", |v| drop(v["robot"]["cables"].as_array_mut().map(|c| c.pop())), "robot.cables", "a point-mass robot needs at least 3");
    // a spatial platform still names every platform anchor and its inertia
    expect_mobile("point", |v| v["robot"]["mobility"] = json!("spatial"), "robot.cables", "at least 6");
    // a planar platform: everything in z = 0, turning about z only, I_zz > 0
    expect_mobile("planar", |v| v["robot"]["cables"][2]["base"] = json!([2, 2, 0.5]), "robot.cables[2].base[2]", "plane z = 0");
    expect_mobile("planar", |v| v["robot"]["cables"][0]["platform"] = json!([0.1, 0, 0.01]), "robot.cables[0].platform[2]", "plane z = 0");
    expect_mobile("planar", |v| v["poses"]["a"]["position"] = json!([1, 1, 0.2]), "poses.a.position[2]", "plane z = 0");
    expect_mobile("planar", |v| v["poses"]["a"]["euler_xyz_deg"] = json!([10, 0, 0]), "poses.a", "about the z axis");
    expect_mobile("planar", |v| v["trajectories"][0]["translation"] = json!({"line": [[1, 1, 0], [1, 1, 0.3]]}), "trajectories[0].translation[2]", "plane z = 0");
    expect_mobile(
        "planar",
        |v| v["trajectories"][0]["orientation"] = json!({"slerp": [[1, 0, 0, 0], [0.9950041652780258, 0.09983341664682815, 0, 0]]}),
        "trajectories[0].orientation.slerp[1]",
        "about the z axis",
    );
    expect_mobile("planar", |v| v["robot"]["dynamics"]["inertia"][2][2] = json!(0), "robot.dynamics.inertia[2][2]", "must be positive");
}
