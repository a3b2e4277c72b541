//! Point masses and planar robots (format 5 `robot.mobility`) through the geometric tools: rays
//! along their own coordinates against dense point-wise sampling, slices and rays refused along a
//! coordinate they do not move along, and the lattice planner's path verified exactly.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::conditions::{for_scenario, Condition};
use cablenav::model::{Coord, Pose};
use cablenav::plan::{PlanStatus, PlannerKind, PlannerOptions};
use cablenav::query::cables::cables_at;
use cablenav::verify::{ray, verify_trajectory};
use cablenav::Scenario;
use serde_json::json;

/// A point mass under four cables from the corners of a 4 × 4 m frame 3 m up, a sphere below one
/// corner, and a query across.
fn point_mass() -> Scenario {
    let v = json!({
        "format": "cablenav-scenario/5", "name": "point mass",
        "robot": {"mobility": "point",
            "cables": [{"base": [0, 0, 3]}, {"base": [4, 0, 3]}, {"base": [4, 4, 3]}, {"base": [0, 4, 3]}],
            "tension": {"min": 0.5, "max": 9},
            "dynamics": {"mass": 1, "gravity": [0, 0, -9.81]}},
        "obstacles": [{"name": "ball", "type": "sphere", "center": [1.2, 1.2, 2.2], "radius": 0.3}],
        "poses": {"a": {"position": [0.8, 2.0, 1.5]}, "b": {"position": [3.2, 2.2, 1.2]}},
        "queries": [{"name": "across", "start": "a", "goal": "b"}]
    });
    Scenario::from_json(&v.to_string()).unwrap()
}

/// A vertical planar robot (gravity along −y in the plane z = 0) on four crossed cables, and a
/// query that turns it.
fn planar() -> Scenario {
    let v = json!({
        "format": "cablenav-scenario/5", "name": "planar",
        "robot": {"mobility": "planar",
            "cables": [{"base": [0, 0, 0], "platform": [0.15, -0.1, 0]}, {"base": [3, 0, 0], "platform": [-0.15, -0.1, 0]},
                       {"base": [3, 3, 0], "platform": [-0.15, 0.1, 0]}, {"base": [0, 3, 0], "platform": [0.15, 0.1, 0]}],
            "tension": {"min": 1, "max": 60},
            "dynamics": {"mass": 2, "inertia": [[0, 0, 0], [0, 0, 0], [0, 0, 0.05]], "gravity": [0, -9.81, 0]}},
        "poses": {"a": {"position": [1.2, 1.4, 0], "euler_xyz_deg": [0, 0, 0]}, "b": {"position": [1.8, 1.6, 0], "euler_xyz_deg": [0, 0, 15]}},
        "queries": [{"name": "turn", "start": "a", "goal": "b"}]
    });
    Scenario::from_json(&v.to_string()).unwrap()
}

fn infeasible_at(s: &Scenario, conds: &[Box<dyn Condition>], base: &Pose, coord: Coord, value: f64) -> bool {
    let mut c = base.coords();
    c[coord.index()] = value;
    let cables = cables_at(&s.robot, &Pose::from_coords(c));
    conds.iter().any(|cond| cond.check(&cables).violated)
}

#[test]
fn rays_along_their_own_coordinates_agree_with_dense_sampling() {
    let samples = if cfg!(target_arch = "wasm32") { 2_000 } else { 20_000 };
    let mut boundaries = 0;
    for (s, rays) in [
        (point_mass(), vec![(Coord::X, 0.1, 3.9), (Coord::Y, 0.1, 3.9), (Coord::Z, 0.2, 2.9)]),
        (planar(), vec![(Coord::X, 0.2, 2.8), (Coord::Y, 0.2, 2.8), (Coord::Sigma, -1.5, 1.5)]),
    ] {
        let conds = for_scenario(&s);
        for pose in ["a", "b"] {
            let base = *s.pose(pose).unwrap();
            for &(coord, lo, hi) in &rays {
                let r = ray(&s, pose, coord, lo, hi).unwrap();
                // undecided only within the boundary tolerance
                let uncertain: f64 = r.uncertain.iter().map(|u| u[1] - u[0]).sum();
                assert!(uncertain <= 1e-6 * (hi - lo), "{} {pose} {}: {:?}", s.name, coord.name(), r.uncertain);
                boundaries += r.boundaries.len();
                let margin = 1e-6 * (hi - lo);
                for i in 0..samples {
                    let x = lo + (hi - lo) * (i as f64 + 0.5) / samples as f64;
                    let inside = |v: &[[f64; 2]]| v.iter().any(|iv| iv[0] + margin < x && x < iv[1] - margin);
                    let bad = infeasible_at(&s, &conds, &base, coord, x);
                    assert!(!(inside(&r.feasible) && bad), "{} {pose} {} = {x}: reported feasible, violated", s.name, coord.name());
                    assert!(!(inside(&r.infeasible) && !bad), "{} {pose} {} = {x}: reported infeasible, feasible", s.name, coord.name());
                }
            }
        }
    }
    assert!(boundaries >= 8, "only {boundaries} boundaries on these rays");
}

#[test]
fn a_coordinate_the_robot_does_not_move_along_is_refused_by_name() {
    let s = point_mass();
    let e = s.coord("--vary", "theta").unwrap_err();
    assert_eq!(e.field, "--vary");
    assert!(e.reason.contains("point") && e.reason.contains("x, y, z"), "{e}");
    assert_eq!(s.coords(), vec![Coord::X, Coord::Y, Coord::Z]);
    let p = planar();
    assert!(p.coord("--axes", "z").unwrap_err().reason.contains("x, y, sigma"));
    assert_eq!(p.coords(), vec![Coord::X, Coord::Y, Coord::Sigma]);
    // the atlas planner is for spatial platforms
    let e = cablenav::plan::run(&s, "across", &PlannerOptions::new(PlannerKind::Atlas), &|| 0.0).unwrap_err();
    assert_eq!(e.field, "robot.mobility", "{e}");
}

#[test]
fn the_lattice_planner_finds_a_path_that_verifies_exactly() {
    for (s, query) in [(point_mass(), "across"), (planar(), "turn")] {
        let r = cablenav::plan::run(&s, query, &PlannerOptions::new(PlannerKind::Lattice), &|| 0.0).unwrap();
        assert_eq!(r.status, PlanStatus::Found, "{}", s.name);
        let traj = r.trajectory.expect("a trajectory");
        let v = verify_trajectory(&s, &traj).unwrap();
        assert_eq!(v.feasible, vec![[0.0, 1.0]], "{}: {v:?}", s.name);
        // it stays a point mass's or a planar robot's motion: from start to goal, in the plane
        let (start, goal) = (s.pose(&s.queries[0].start).unwrap(), s.pose(&s.queries[0].goal).unwrap());
        assert!((traj.pose_at(0.0).position - start.position).norm() < 1e-9 && (traj.pose_at(1.0).position - goal.position).norm() < 1e-9);
        if s.robot.mobility == cablenav::model::Mobility::Planar {
            for k in 0..=20 {
                let p = traj.pose_at(k as f64 / 20.0);
                assert!(p.position.z.abs() < 1e-12 && p.rotation.i.abs() < 1e-12 && p.rotation.j.abs() < 1e-12, "{p:?}");
            }
            assert!(goal.rotation.angle_to(&traj.pose_at(1.0).rotation) < 1e-9);
        }
    }
}

#[test]
fn slices_over_their_own_coordinates_classify_as_the_per_pose_checks() {
    use cablenav::verify::slice::{slice, Class};
    for (s, axes, range) in [
        (point_mass(), [Coord::X, Coord::Y], [[0.1, 3.9], [0.1, 3.9]]),
        (planar(), [Coord::X, Coord::Sigma], [[0.2, 2.8], [-1.5, 1.5]]),
    ] {
        let res = 24;
        let map = slice(&s, "a", axes, res, range).unwrap();
        let conds = for_scenario(&s);
        let base = s.pose("a").unwrap().coords();
        let (mut feasible, mut other) = (0, 0);
        for j in 0..res {
            for i in 0..res {
                let mut c = base;
                c[axes[0].index()] = range[0][0] + (range[0][1] - range[0][0]) * (i as f64 + 0.5) / res as f64;
                c[axes[1].index()] = range[1][0] + (range[1][1] - range[1][0]) * (j as f64 + 0.5) / res as f64;
                let cables = cables_at(&s.robot, &Pose::from_coords(c));
                let bad = conds.iter().any(|cond| cond.check(&cables).violated);
                let class = map.classes[j * res + i];
                assert_eq!(class == Class::Feasible, !bad, "{} cell ({i}, {j}) at {c:?}: {class:?}", s.name);
                if bad { other += 1 } else { feasible += 1 }
            }
        }
        assert!(feasible > 0 && other > 0, "{}: {feasible} feasible, {other} not", s.name);
    }
    // a point mass has no θ to slice along
    assert_eq!(point_mass().coord("--axes", "theta").unwrap_err().field, "--axes");
}

#[test]
fn a_three_cable_point_mass_has_its_tensions_enveloped_as_the_statics_give_them() {
    // Laval's CSPR (batotp's case): at rest along its path the tensions are unique, J f = m g
    let s = Scenario::from_json(include_str!("../static/scenarios/laval-cspr3dof.json")).unwrap();
    let traj = s.trajectory(Some("batotp-path")).unwrap();
    let env = cablenav::verify::tension_envelope(&s, traj, 40).unwrap();
    let g = s.robot.dynamics.as_ref().unwrap().gravity;
    for (k, &t) in env.t.iter().enumerate() {
        let p = traj.pose_at(t).position;
        // columns: unit vectors from the anchors to the point; tensions pull it back
        let j = nalgebra::Matrix3::from_columns(&s.robot.cables.iter().map(|c| (p - c.base).normalize()).collect::<Vec<_>>());
        let f = j.lu().solve(&g).expect("not singular along the path");
        let (lo, hi) = (env.tension_min[k].as_ref().unwrap(), env.tension_max[k].as_ref().unwrap());
        for i in 0..3 {
            assert!((lo[i] - f[i]).abs() < 1e-9 * (1.0 + f[i].abs()) && lo[i] == hi[i], "t = {t}, cable {}: {} vs {}", i + 1, lo[i], f[i]);
        }
    }
    // with more cables than degrees of freedom the tensions are not unique, and the error says so
    let e = cablenav::verify::tension_envelope(&point_mass(), &cablenav::model::Trajectory::single("x".to_string(), cablenav::model::Translation::Line(nalgebra::Vector3::new(1.0, 1.0, 1.0), nalgebra::Vector3::new(2.0, 2.0, 1.0)), cablenav::model::Orientation::Slerp(nalgebra::UnitQuaternion::identity(), nalgebra::UnitQuaternion::identity())), 10).unwrap_err();
    assert!(e.reason.contains("degrees of freedom (3 here)"), "{e}");
}
