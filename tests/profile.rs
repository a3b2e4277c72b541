//! Clearance profiles and cable states (`cablenav::verify::profile`) against brute-force distances
//! (nested ternary searches over the convex distance functions of segments), the per-pose check
//! and the wrench report.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::model::Pose;
use cablenav::shape::Shape;
use cablenav::verify::profile::{cable_states, clearances_along, clearances_at};
use cablenav::verify::{check_pose, verify_trajectory, wrench_at};
use cablenav::Scenario;
use nalgebra::Vector3;

type V = Vector3<f64>;

const TREE: &str = include_str!("../static/scenarios/cdpr7-tree.json");
const ROBOCRANE: &str = include_str!("../static/scenarios/robocrane.json");

/// Minimum of a convex function on [0, 1] by ternary search.
fn ternary(f: impl Fn(f64) -> f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..100 {
        let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
        if f(m1) <= f(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    f((lo + hi) / 2.0).min(f(0.0)).min(f(1.0))
}

/// Distance between segments [a, a+s] and [b, b+t]: min over u of min over v (both convex).
fn seg_seg(a: V, s: V, b: V, t: V) -> f64 {
    ternary(|u| ternary(|v| ((a + s * u) - (b + t * v)).norm()))
}

/// Distance from point p to segment [a, a+s].
fn point_seg(p: V, a: V, s: V) -> f64 {
    ternary(|u| (a + s * u - p).norm())
}

fn cables(s: &Scenario, pose: &Pose) -> Vec<(V, V)> {
    s.robot.cables.iter().map(|c| (c.base, pose.transform(&c.platform))).collect()
}

/// Brute-force least cable–cable distance over pairs not sharing an anchor.
fn ref_cable_cable(s: &Scenario, pose: &Pose) -> Option<f64> {
    let cs = cables(s, pose);
    let mut best: Option<f64> = None;
    for i in 0..cs.len() {
        for j in i + 1..cs.len() {
            if !s.robot.share_anchor(i, j) {
                let d = seg_seg(cs[i].0, cs[i].1 - cs[i].0, cs[j].0, cs[j].1 - cs[j].0);
                best = Some(best.map_or(d, |b: f64| b.min(d)));
            }
        }
    }
    best
}

/// Brute-force distance from cable `i` to the surface of each sphere, and to each cylinder's
/// capsule (the documented meaning of the cylinder distance); `None` for other shapes.
fn ref_obstacle(s: &Scenario, pose: &Pose, i: usize, shape: &Shape) -> Option<f64> {
    let (a, x) = cables(s, pose)[i];
    match shape {
        Shape::Sphere { center, radius } => Some(point_seg(*center, a, x - a) - radius),
        Shape::Cylinder { from, to, radius } => Some(seg_seg(a, x - a, *from, to - from) - radius),
        _ => None,
    }
}

#[test]
fn tree_profile_matches_brute_force_distances_and_the_pose_check() {
    let s = Scenario::from_json(TREE).unwrap();
    let traj = s.trajectory(Some("linear")).unwrap();
    let n = 12;
    let p = clearances_along(&s, traj, n).unwrap();
    assert_eq!(p.samples.len(), n + 1);
    assert_eq!((p.clearance_cable_cable, p.clearance_cable_obstacle), (0.1, 0.2));
    // every clearance condition reports its exact distance now (cones included)
    assert!(p.membership_only.is_empty(), "{:?}", p.membership_only);
    for (k, sample) in p.samples.iter().enumerate() {
        let t = k as f64 / n as f64;
        assert_eq!(sample.t, t);
        let pose = traj.pose_at(t);
        let cc = sample.cable_cable.as_ref().unwrap();
        assert!((cc.distance - ref_cable_cable(&s, &pose).unwrap()).abs() < 1e-7, "t = {t}: {cc:?}");
        let mut best = f64::INFINITY;
        for o in &s.obstacles {
            for i in 0..s.robot.cables.len() {
                if let Some(d) = ref_obstacle(&s, &pose, i, &o.shape) {
                    best = best.min(d);
                }
            }
        }
        // the reference knows spheres and cylinders: where one of them is nearest the distances
        // agree; where the cone is nearer, it is below the reference's least
        let co = sample.cable_obstacle.as_ref().unwrap();
        if co.between.ends_with("- cone") {
            assert!(co.distance <= best + 1e-7, "t = {t}: {co:?} vs {best}");
        } else {
            assert!((co.distance - best).abs() < 1e-7, "t = {t}: {co:?} vs {best}");
        }
        // the same conditions as the per-pose check, in the same order
        assert_eq!(sample.violated, check_pose(&s, "sample", &pose).violated, "t = {t}");
    }
    // the exact verifier says cable 3 meets the crown early on: the samples there agree
    let report = verify_trajectory(&s, traj).unwrap();
    let [t0, t1] = report.infeasible[0];
    for sample in p.samples.iter().filter(|x| x.t > t0 + 1e-6 && x.t < t1 - 1e-6) {
        assert!(sample.violated.contains(&"cable 3 - crown".to_string()), "{sample:?}");
        let co = sample.cable_obstacle.as_ref().unwrap();
        assert!(co.distance < 0.2, "{sample:?}");
    }
}

#[test]
fn cable_states_flag_the_interfering_cables() {
    let s = Scenario::from_json(TREE).unwrap();
    let traj = s.trajectory(Some("linear")).unwrap();
    let m = s.robot.cables.len();
    for t in [0.0, 0.3, 0.6, 0.9, 1.0] {
        let pose = traj.pose_at(t);
        let states = cable_states(&s, &pose);
        assert_eq!(states.len(), m);
        let cs = cables(&s, &pose);
        let violated = check_pose(&s, "p", &pose).violated;
        for i in 0..m {
            let mut expect = (0..m).any(|j| {
                j != i
                    && !s.robot.share_anchor(i, j)
                    && seg_seg(cs[i].0, cs[i].1 - cs[i].0, cs[j].0, cs[j].1 - cs[j].0) < s.clearance.cable_cable
            });
            for o in &s.obstacles {
                expect |= match ref_obstacle(&s, &pose, i, &o.shape) {
                    Some(d) => d < s.clearance.cable_obstacle,
                    None => violated.contains(&format!("cable {} - {}", i + 1, o.name)),
                };
            }
            assert_eq!(states[i].interfering, expect, "t = {t}, cable {}", i + 1);
            assert!(states[i].length_ok);
            assert_eq!(states[i].tension_margin, None, "no wrench section");
        }
    }
    // at t = 0.3 cable 3 is inside the crown's clearance
    assert!(cable_states(&s, &traj.pose_at(0.3))[2].interfering);
    // with a mass the seven cables have a wrench report but no per-cable tension ranges (the
    // tensions are not unique): no margins, and no panic (the page colours cables this way)
    let mut v: serde_json::Value = serde_json::from_str(TREE).unwrap();
    v["format"] = serde_json::json!("cablenav-scenario/4");
    v["robot"]["dynamics"] = serde_json::json!({"mass": 1, "inertia": [[0.04, 0, 0], [0, 0.04, 0], [0, 0, 0.04]]});
    let heavy = Scenario::from_json(&v.to_string()).unwrap();
    let pose = traj.pose_at(0.9);
    assert!(wrench_at(&heavy, &pose).is_some_and(|w| w.tension_min.is_empty()));
    assert!(cable_states(&heavy, &pose).iter().all(|c| c.tension_margin.is_none()));
    // nor an envelope: it says why instead of printing empty rows
    let e = cablenav::verify::tension_envelope(&heavy, traj, 10).unwrap_err();
    assert!(e.field == "wrench" && e.reason.contains("as many cables as degrees of freedom (6 here); with 7"), "{e}");
}

#[test]
fn tension_margins_agree_with_the_wrench_report() {
    let s = Scenario::from_json(ROBOCRANE).unwrap();
    for (name, pose) in &s.poses {
        let w = wrench_at(&s, pose).unwrap();
        let states = cable_states(&s, pose);
        if w.singular {
            assert!(states.iter().all(|c| c.tension_margin.is_none()), "{name}");
            continue;
        }
        let least = states.iter().map(|c| c.tension_margin.unwrap()).fold(f64::INFINITY, f64::min);
        assert!((least - w.margin.unwrap()).abs() < 1e-12, "{name}: {least} vs {:?}", w.margin);
        for (i, c) in states.iter().enumerate() {
            assert_eq!(c.tension_span, 1.0);
            let by_hand = (w.tension_min[i] - 0.0).min(1.0 - w.tension_max[i]);
            assert_eq!(c.tension_margin, Some(by_hand), "{name} cable {}", i + 1);
        }
    }
}

#[test]
fn sample_counts_are_checked() {
    let s = Scenario::from_json(TREE).unwrap();
    let traj = &s.trajectories[0];
    let e = clearances_along(&s, traj, 0).unwrap_err();
    assert_eq!(e.field, "samples");
    assert!(clearances_along(&s, traj, 100_000).is_err());
    let empty = clearances_at(&s, &[]).unwrap();
    assert!(empty.samples.is_empty() && empty.membership_only.is_empty());
}

#[test]
fn tension_at_poses_equals_the_trajectory_envelope() {
    use cablenav::verify::profile::tension_at;
    use cablenav::verify::tension_envelope;
    let s = Scenario::from_json(ROBOCRANE).unwrap();
    let traj = &s.trajectories[0];
    let env = tension_envelope(&s, traj, 16).unwrap();
    let samples: Vec<(f64, Pose)> = env.t.iter().map(|&t| (t, traj.pose_at(t))).collect();
    let at = tension_at(&s, &traj.name, &samples).unwrap();
    assert_eq!(at, env);
    let tree = Scenario::from_json(TREE).unwrap();
    assert_eq!(tension_at(&tree, "x", &samples).unwrap_err().field, "wrench");
}
