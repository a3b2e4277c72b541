//! Robots with more than six cables: wrench closure per pose against a linear program, the
//! static-feasibility LP against a brute-force search along the null space (7 cables), and the
//! exact closure / static-feasibility sections along trajectories against per-pose sampling.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::model::{Bounds, Pose};
use cablenav::query::cables::cables_at;
use cablenav::query::lp::{maximise, LpResult};
use cablenav::query::wrench::{closure_holds, static_margin, structure_matrix_m};

/// Every wrench component: these robots are spatial platforms.
const ALL: &[usize] = &[0, 1, 2, 3, 4, 5];
use cablenav::verify::{verify_trajectory, wrench_at};
use cablenav::Scenario;
use nalgebra::{DMatrix, DVector, UnitQuaternion, Vector3, Vector6};
use serde_json::json;

const CDPR7: &str = include_str!("../static/scenarios/cdpr7.json");

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

/// The thesis' 7-cable robot with a load (platform weight along −z at the platform origin),
/// tension bounds and no clearances, with the given poses and trajectories (or the preset's).
fn cdpr7_with_load(poses_and_trajectories: Option<(serde_json::Value, serde_json::Value)>) -> Scenario {
    let mut v: serde_json::Value = serde_json::from_str(CDPR7).unwrap();
    v["robot"]["tension"] = json!({"min": 0.1, "max": 40});
    v["format"] = json!("cablenav-scenario/4");
    v["wrench"] = json!({"nominal": [0, 0, -10, 0, 0, 0], "radius": 1, "point": [0, 0, 0], "closure": true});
    v["clearance"] = json!({"cable_cable": 0, "cable_obstacle": 0});
    if let Some((poses, trajectories)) = poses_and_trajectories {
        v["poses"] = poses;
        v["trajectories"] = trajectories;
    }
    Scenario::from_json(&v.to_string()).unwrap()
}

/// A random pose around the middle of the frame, where closure comes and goes.
fn random_pose(rng: &mut Rng) -> Pose {
    let q = UnitQuaternion::from_euler_angles(rng.range(-0.3, 0.3), rng.range(-0.3, 0.3), rng.range(-0.8, 0.8));
    Pose { position: Vector3::new(rng.range(1.2, 2.8), rng.range(1.2, 2.8), rng.range(0.6, 3.0)), rotation: q }
}

/// Closure by LP, from the definition: the largest t with J f = 0, f ≥ t, Σ f = 1; closure iff
/// t > 0 and J has rank 6. Returns (closure, t).
fn closure_by_lp(j: &DMatrix<f64>) -> (bool, f64) {
    let m = j.ncols();
    // f = t·1 + g, t = tp − tn: [J, J1, −J1] and [1ᵀ, m, −m] rows.
    let mut a = DMatrix::zeros(7, m + 2);
    let ones = j.column_sum();
    for r in 0..6 {
        for k in 0..m {
            a[(r, k)] = j[(r, k)];
        }
        a[(r, m)] = ones[r];
        a[(r, m + 1)] = -ones[r];
    }
    for k in 0..m {
        a[(6, k)] = 1.0;
    }
    a[(6, m)] = m as f64;
    a[(6, m + 1)] = -(m as f64);
    let mut b = DVector::zeros(7);
    b[6] = 1.0;
    let mut c = DVector::zeros(m + 2);
    c[m] = 1.0;
    c[m + 1] = -1.0;
    let t = match maximise(&a, &b, &c) {
        LpResult::Optimal { value, .. } => value,
        other => panic!("closure LP: {other:?}"),
    };
    let sv = j.clone().svd(false, false).singular_values;
    let rank6 = sv.min() > 1e-9 * sv.max();
    (rank6 && t > 0.0, t)
}

#[test]
fn seven_cable_closure_matches_an_lp_check() {
    let s = cdpr7_with_load(None);
    let mut rng = Rng(11);
    let poses = if cfg!(target_arch = "wasm32") { 300 } else { 3000 };
    let (mut closed, mut open, mut skipped) = (0, 0, 0);
    for _ in 0..poses {
        let pose = random_pose(&mut rng);
        let at = cables_at(&s.robot, &pose);
        let point = pose.position;
        let (lp, t) = closure_by_lp(&structure_matrix_m(&at.cables, &point, ALL));
        if t.abs() < 1e-9 {
            skipped += 1; // on the boundary: either answer is within rounding
            continue;
        }
        assert_eq!(closure_holds(&at.cables, &point, ALL), lp, "pose {pose:?}: LP margin {t}");
        if lp { closed += 1 } else { open += 1 }
    }
    // Closure holds in a few percent of these poses: both answers must be exercised.
    assert!(closed >= poses / 60 && open >= poses / 60, "closed {closed}, open {open}, skipped {skipped}");
}

/// The best static margin for 7 cables without an LP: tensions balancing w0 form the line
/// f_p + μ h (h spanning J's null space); the margin min_k min(f_k − f_min, f_max − f_k) is concave
/// in μ, maximised by ternary search over a bracket holding every breakpoint.
fn static_margin_by_line(j: &DMatrix<f64>, w0: &Vector6<f64>, b: Bounds) -> f64 {
    let f_p = j.clone().svd(true, true).solve(&DVector::from_column_slice(w0.as_slice()), 1e-12).unwrap();
    // The null direction: J padded to 7×7 has one zero singular value; its right singular vector.
    let svd_full = DMatrix::from_fn(7, 7, |r, c| if r < 6 { j[(r, c)] } else { 0.0 }).svd(false, true);
    let vt = svd_full.v_t.unwrap();
    let (idx, _) = svd_full.singular_values.iter().enumerate().fold((0, f64::INFINITY), |(bi, bv), (i, &v)| if v < bv { (i, v) } else { (bi, bv) });
    let h: DVector<f64> = vt.row(idx).transpose();
    let margin = |mu: f64| (0..7).map(|k| (f_p[k] + mu * h[k] - b.min).min(b.max - f_p[k] - mu * h[k])).fold(f64::INFINITY, f64::min);
    let reach = (0..7).map(|k| (f_p[k].abs() + b.max) / h[k].abs().max(1e-12)).fold(0.0, f64::max);
    let (mut lo, mut hi) = (-reach, reach);
    for _ in 0..300 {
        let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
        if margin(m1) < margin(m2) { lo = m1 } else { hi = m2 }
    }
    margin(0.5 * (lo + hi))
}

#[test]
fn static_feasibility_lp_matches_a_null_space_search() {
    let s = cdpr7_with_load(None);
    let w = s.wrench.clone().unwrap();
    let bounds: Vec<Bounds> = s.robot.cables.iter().map(|c| c.tension).collect();
    let mut rng = Rng(5);
    let (mut feasible, mut infeasible) = (0, 0);
    let poses = if cfg!(target_arch = "wasm32") { 200 } else { 2000 };
    for _ in 0..poses {
        let pose = random_pose(&mut rng);
        let at = cables_at(&s.robot, &pose);
        let j = structure_matrix_m(&at.cables, &pose.position, ALL);
        let sv = j.clone().svd(false, false).singular_values;
        if sv.min() < 1e-6 * sv.max() {
            continue;
        }
        let want = static_margin_by_line(&j, &w.nominal, bounds[0]);
        let (got, f) = static_margin(&at.cables, &pose.position, &w.nominal, &bounds, ALL).expect("rank 6: w0 is balanced by some tensions");
        assert!((got - want).abs() < 1e-7 * (1.0 + want.abs()), "pose {pose:?}: LP margin {got}, null-space search {want}");
        // The LP's tensions balance w0 and keep the margin.
        let fj = &j * DVector::from_vec(f.clone());
        assert!((0..6).all(|r| (fj[r] - w.nominal[r]).abs() < 1e-8 * (1.0 + w.nominal.amax())), "J f = {fj} ≠ w0");
        assert!(f.iter().all(|&fk| fk >= bounds[0].min + got - 1e-8 && fk <= bounds[0].max - got + 1e-8));
        if got > 0.0 { feasible += 1 } else { infeasible += 1 }
    }
    // A few percent of these poses are statically feasible: both answers must be exercised.
    assert!(feasible >= poses / 40 && infeasible >= poses / 40, "feasible {feasible}, infeasible {infeasible}");
}

/// Exact closure and static-feasibility sections along random motions of the 7-cable robot agree
/// with the per-pose tests sampled densely.
#[test]
fn seven_cable_sections_match_per_pose_sampling() {
    let mut rng = Rng(3);
    let ntraj = if cfg!(target_arch = "wasm32") { 4 } else { 12 };
    let samples = if cfg!(target_arch = "wasm32") { 2_000 } else { 10_000 };
    let (mut mixed, mut checked) = (0, 0);
    for k in 0..ntraj {
        let p0 = [rng.range(0.5, 3.5), rng.range(0.5, 3.5), rng.range(0.5, 3.5)];
        let p1 = [rng.range(0.5, 3.5), rng.range(0.5, 3.5), rng.range(0.5, 3.5)];
        let e0 = [rng.range(-30.0, 30.0), rng.range(-30.0, 30.0), rng.range(-60.0, 60.0)];
        let e1 = [rng.range(-30.0, 30.0), rng.range(-30.0, 30.0), rng.range(-60.0, 60.0)];
        let poses = json!({"a": {"position": p0, "euler_xyz_deg": e0}, "b": {"position": p1, "euler_xyz_deg": e1}});
        let trajectories = json!([{"name": "t", "translation": {"line": [p0, p1]}, "orientation": {"slerp": ["a", "b"]}}]);
        let s = cdpr7_with_load(Some((poses, trajectories)));
        let traj = &s.trajectories[0];
        let r = verified(&s, k, &mut mixed);
        for i in 0..samples {
            let t = (i as f64 + 0.5) / samples as f64;
            let near = r.boundaries.iter().any(|b| (b.t - t).abs() < 1e-7) || r.uncertain.iter().any(|u| t > u[0] - 1e-7 && t < u[1] + 1e-7);
            if near {
                continue;
            }
            let pose = traj.pose_at(t);
            let report = wrench_at(&s, &pose).unwrap();
            if report.margin.is_some_and(|m| m.abs() < 1e-7) {
                continue;
            }
            let claimed = r.feasible.iter().any(|iv| t >= iv[0] && t <= iv[1]);
            assert_eq!(claimed, report.feasible, "trajectory {k} at t = {t}: report {r:?}, pose {report:?}");
            checked += 1;
        }
    }
    assert!(mixed >= ntraj / 6, "only {mixed} of {ntraj} trajectories cross a boundary");
    assert!(checked > ntraj * samples / 2);
}

/// The scenario's first trajectory (motion `k` of a test) verified exactly: uncertain on less
/// than 1e-6 of t in all; `mixed` counts it when it has feasible and infeasible sections.
fn verified(s: &Scenario, k: usize, mixed: &mut usize) -> cablenav::report::VerifyReport {
    let r = verify_trajectory(s, &s.trajectories[0]).unwrap();
    let uncertain: f64 = r.uncertain.iter().map(|u| u[1] - u[0]).sum();
    assert!(uncertain < 1e-6, "trajectory {k}: {uncertain} of t uncertain: {:?}", r.uncertain);
    *mixed += usize::from(!r.feasible.is_empty() && !r.infeasible.is_empty());
    r
}

/// Closure beyond the facets' reach: the thesis robot's seven cables and five more (12), decided
/// by the linear programs' certificates (`conditions::wrench_lp`: tensions of at least 1
/// balancing the zero wrench where it holds, a direction with every column strictly on one side
/// where it fails) along random motions, against the LP reference above at every sample. The
/// wrench section asks for closure alone: the zero wrench, tensions in (0, ∞), whose static
/// feasibility follows from closure.
#[test]
fn twelve_cable_closure_sections_match_the_lp_reference() {
    let mut rng = Rng(9);
    // the same 16 motions in wasm (several cross a boundary), sampled less densely
    let ntraj = 16;
    let samples = if cfg!(target_arch = "wasm32") { 500 } else { 4_000 };
    let (mut mixed, mut checked) = (0, 0);
    for k in 0..ntraj {
        let mut v: serde_json::Value = serde_json::from_str(CDPR7).unwrap();
        let extra = [([2.0, 0.0, 0.0], [0.0, -0.2, 0.3]), ([2.0, 4.0, 0.0], [0.0, 0.2, 0.3]), ([4.0, 2.0, 4.0], [0.15, 0.0, -0.3]), ([0.0, 2.0, 2.0], [-0.15, 0.0, 0.0]), ([2.0, 0.0, 4.0], [0.0, -0.2, -0.3])];
        for (base, platform) in extra {
            v["robot"]["cables"].as_array_mut().unwrap().push(json!({"base": base, "platform": platform}));
        }
        v["format"] = json!("cablenav-scenario/4");
        v["wrench"] = json!({"nominal": [0, 0, 0, 0, 0, 0], "point": [0, 0, 0], "closure": true});
        v["clearance"] = json!({"cable_cable": 0, "cable_obstacle": 0});
        let (a, b) = (random_pose(&mut rng), random_pose(&mut rng));
        let place = |p: &Pose| {
            let (r, pi, y) = p.rotation.euler_angles();
            json!({"position": [p.position.x, p.position.y, p.position.z], "euler_xyz_deg": [r.to_degrees(), pi.to_degrees(), y.to_degrees()]})
        };
        v["poses"] = json!({"a": place(&a), "b": place(&b)});
        v["trajectories"] = json!([{"name": "t", "translation": {"line": [[a.position.x, a.position.y, a.position.z], [b.position.x, b.position.y, b.position.z]]}, "orientation": {"slerp": ["a", "b"]}}]);
        v["queries"] = json!([]);
        let s = Scenario::from_json(&v.to_string()).unwrap();
        assert_eq!(s.robot.cables.len(), 12);
        let traj = &s.trajectories[0];
        let r = verified(&s, k, &mut mixed);
        for i in 0..samples {
            let t = (i as f64 + 0.5) / samples as f64;
            if r.boundaries.iter().any(|b| (b.t - t).abs() < 1e-7) {
                continue;
            }
            let pose = traj.pose_at(t);
            let at = cables_at(&s.robot, &pose);
            let (closed, margin) = closure_by_lp(&structure_matrix_m(&at.cables, &pose.position, ALL));
            if margin.abs() < 1e-9 {
                continue; // on a boundary: either answer is within rounding
            }
            let claimed = r.feasible.iter().any(|iv| t >= iv[0] && t <= iv[1]);
            assert_eq!(claimed, closed, "trajectory {k} at t = {t}: closure margin {margin}, report {r:?}");
            // and the per-pose check says the same
            assert_eq!(wrench_at(&s, &pose).unwrap().feasible, closed, "trajectory {k} at t = {t}: check");
            checked += 1;
        }
    }
    assert!(mixed >= 2, "only {mixed} of {ntraj} trajectories cross a closure boundary");
    assert!(checked > ntraj * samples / 2);
}
