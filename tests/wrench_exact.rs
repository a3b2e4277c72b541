//! Exact wrench-feasible intervals along trajectories against dense sampling of an independent
//! per-pose reference.
//!
//! The reference (below) builds J from its definition with the test-support pose model (direct
//! sin-based slerp, τ(t)), and gets each cable's extreme tensions over the ellipsoid from
//! g_i = J⁻ᵀ e_i: f0,i = g_i·w0, v_ii = √(g_iᵀ E⁻¹ g_i) (QR solves, Cholesky for E) — none of it
//! shared with the core's polynomial conditions.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

mod support;

use support::{env_usize, lone_boundaries, reported};

use cablenav::report::{Side, VerifyReport};
use cablenav::verify::verify_trajectory;
use cablenav::Scenario;
use nalgebra::{Matrix6, Vector6};
use support::reference::*;

/// Random trajectories (one per random robot) and samples of t per trajectory.
#[cfg(not(target_arch = "wasm32"))]
const TRAJECTORIES: usize = 300;
#[cfg(target_arch = "wasm32")]
const TRAJECTORIES: usize = 20;
#[cfg(not(target_arch = "wasm32"))]
const SAMPLES: usize = 100_000;
#[cfg(target_arch = "wasm32")]
const SAMPLES: usize = 10_000;

/// A 6-cable robot, its wrench set and one trajectory, as the reference sees them.
struct Case {
    cables: Vec<(V3, V3)>,
    tension: (f64, f64),
    nominal: Vector6<f64>,
    e_inv: Matrix6<f64>,
    point: V3,
    world_frame: bool,
    traj: RefTrajectory,
}

impl Case {
    fn json(&self) -> String {
        let cables: Vec<_> = self.cables.iter().map(|(a, b)| serde_json::json!({"base": a.arr(), "platform": b.arr()})).collect();
        let e = self.e_inv.try_inverse().unwrap();
        let rows: Vec<Vec<f64>> = (0..6).map(|i| (0..6).map(|j| 0.5 * (e[(i, j)] + e[(j, i)])).collect()).collect();
        serde_json::json!({
            "format": "cablenav-scenario/1",
            "name": "random wrench case",
            "robot": {"cables": cables, "tension": {"min": self.tension.0, "max": self.tension.1}},
            "wrench": {
                "nominal": self.nominal.as_slice(),
                "ellipsoid": rows,
                "point": self.point.arr(),
                "point_frame": if self.world_frame { "world" } else { "platform" },
            },
            "trajectories": [self.traj.to_json()],
        })
        .to_string()
    }

    /// Least tension margin over the cables and both bounds at t (negative: violated), the
    /// (cable, lower?) attaining it, and a scale for rounding; `None` at a singular pose.
    // `!(x < bound)` rejects NaN together with the values past the bound, as the crate does
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    fn margin(&self, t: f64) -> Option<(f64, (usize, bool), f64)> {
        let (p, r) = self.traj.pose(t);
        let c = if self.world_frame { p + self.point } else { p + mat_vec(&r, self.point) };
        let mut j = Matrix6::zeros();
        for (i, (a, b)) in self.cables.iter().enumerate() {
            let x = p + mat_vec(&r, *b);
            let e = (x - *a).normalized();
            let m = (x - c).cross(e);
            for k in 0..3 {
                j[(k, i)] = e.get(k);
                j[(k + 3, i)] = m.get(k);
            }
        }
        // g_i = J⁻ᵀ e_i is row i of J⁻¹ (Gauss–Jordan with partial pivoting, via nalgebra).
        let inv = j.try_inverse()?;
        if !(inv.amax() < 1e9) {
            return None; // numerically singular
        }
        let mut best = (f64::INFINITY, (0, true));
        let mut scale: f64 = 1.0;
        for i in 0..6 {
            let g: Vector6<f64> = inv.row(i).transpose();
            let f0 = g.dot(&self.nominal);
            let v = g.dot(&(self.e_inv * g)).max(0.0).sqrt();
            scale = scale.max(f0.abs() + v);
            for (m, lower) in [(f0 - v - self.tension.0, true), (self.tension.1 - f0 - v, false)] {
                if m < best.0 {
                    best = (m, (i, lower));
                }
            }
        }
        Some((best.0, best.1, scale))
    }

    fn feasible(&self, t: f64) -> bool {
        self.margin(t).is_some_and(|(m, _, _)| m > 0.0)
    }
}

/// A random 6-cable robot hanging below its base (z down, load along +z): the Robocrane's
/// octahedral layout (paper 1 §5) with random sizes and anchors moved by up to 0.2, a random
/// ellipsoid and a random polynomial + slerp trajectory.
fn random_case(rng: &mut Rng) -> Case {
    let (b, a) = (rng.range(1.5, 2.5), rng.range(0.6, 1.2));
    let r3 = 3f64.sqrt();
    let base = [v3(-b, -b * r3 / 3.0, 0.0), v3(b, -b * r3 / 3.0, 0.0), v3(0.0, 2.0 * b * r3 / 3.0, 0.0)];
    let plat = [v3(0.0, -2.0 * a * r3 / 3.0, 0.0), v3(a, a * r3 / 3.0, 0.0), v3(-a, a * r3 / 3.0, 0.0)];
    let pairs = [(0, 0), (1, 0), (1, 1), (2, 1), (2, 2), (0, 2)];
    let cables = pairs.iter().map(|&(i, j)| (base[i] + rng.in_box(0.2), plat[j] + rng.in_box(0.1))).collect();
    let mass = rng.range(0.5, 2.0);
    let nominal = Vector6::from_fn(|k, _| if k == 2 { mass } else { mass * rng.range(-0.1, 0.1) });
    // E⁻¹ = Qᵀ diag(r²) Q, radii up to 10 % of the load.
    let q = Matrix6::from_fn(|_, _| rng.normal()).qr().q();
    let radii = Matrix6::from_diagonal(&Vector6::from_fn(|_, _| (mass * rng.range(0.005, 0.1)).powi(2)));
    let e_inv = q.transpose() * radii * q;
    let tension = (if rng.chance(0.5) { 0.0 } else { 0.05 * mass }, mass * rng.range(1.0, 4.0));
    // degree 0: a slerp in place, of half the degree (Motion::trajectory)
    let deg = rng.int(0, 3);
    let centre = v3(rng.range(-0.3, 0.3), rng.range(-0.3, 0.3), rng.range(1.5, 2.5));
    let mut coeffs: [Vec<f64>; 3] = Default::default();
    for (axis, c) in coeffs.iter_mut().enumerate() {
        c.push(centre.get(axis));
        for k in 1..=deg {
            c.push(rng.range(-0.6, 0.6) / k as f64);
        }
    }
    let (qs, qe) = {
        let qs = quat_normalize(quat_axis_angle(rng.unit_vector(), rng.range(0.0, 50f64.to_radians())));
        let rot = quat_axis_angle(rng.unit_vector(), rng.range(0.0, 90f64.to_radians()));
        (qs, quat_normalize(quat_mul(qs, rot)))
    };
    let traj = RefTrajectory { name: "t".into(), translation: RefTranslation::Polynomial(coeffs), qs, qe };
    let point = rng.in_box(0.3);
    Case { cables, tension, nominal, e_inv, point, world_frame: rng.chance(0.5), traj }
}

/// Dense comparison of one case: (samples compared, contradictions, boundaries, boundary misses).
fn compare(case: &Case, r: &VerifyReport, samples: usize, seed: u64) -> (usize, Vec<String>, usize) {
    let mut rng = Rng::new(seed);
    let offset = rng.f64();
    let mut compared = 0;
    let mut bad = Vec::new();
    for k in 0..samples {
        let t = (k as f64 + offset) / samples as f64;
        let Some(claim) = reported(r, t, 1e-9) else { continue };
        let Some((m, _, scale)) = case.margin(t) else {
            if claim {
                bad.push(format!("t = {t}: reported feasible, reference singular"));
            }
            continue;
        };
        if m.abs() < 1e-9 * scale {
            continue;
        }
        compared += 1;
        if claim != (m > 0.0) {
            bad.push(format!("t = {t}: reported {claim}, reference margin {m}"));
        }
    }
    // Each boundary separates reference verdicts 1e-6 to either side, in the reported direction.
    for (b, lo, hi, enters_feasible) in lone_boundaries(r, 1e-6) {
        if case.feasible(lo) == enters_feasible || case.feasible(hi) != enters_feasible {
            bad.push(format!("boundary t = {} ({}) not matched by the reference within 1e-6", b.t, b.constraint));
        }
    }
    (compared, bad, r.boundaries.len())
}

/// Per-case outcome: samples compared, contradictions, boundaries, and whether the trajectory
/// has both feasible and infeasible sections.
fn run_case(k: usize, case: &Case) -> (usize, Vec<String>, usize, bool) {
    let s = Scenario::from_json(&case.json()).unwrap_or_else(|e| panic!("case {k}: {e}"));
    let r = verify_trajectory(&s, &s.trajectories[0]).unwrap();
    let uncertain: f64 = r.uncertain.iter().map(|u| u[1] - u[0]).sum();
    assert!(uncertain < 1e-6, "case {k}: {uncertain} of t uncertain: {:?}", r.uncertain);
    let (n, bad, nb) = compare(case, &r, SAMPLES, k as u64);
    let bad = bad.into_iter().map(|b| format!("case {k}: {b}\n{}", case.json())).collect();
    (n, bad, nb, !r.feasible.is_empty() && !r.infeasible.is_empty())
}

#[test]
fn exact_wrench_intervals_match_dense_sampling_on_random_robots() {
    let mut rng = Rng::new(2024);
    let cases: Vec<Case> = (0..env_usize("CABLENAV_WRENCH_CASES", TRAJECTORIES)).map(|_| random_case(&mut rng)).collect();
    #[cfg(not(target_arch = "wasm32"))]
    let results: Vec<_> = {
        // The sampling dominates: share the cases between the cores.
        let workers = std::thread::available_parallelism().map_or(1, |n| n.get());
        std::thread::scope(|scope| {
            let handles: Vec<_> = (0..workers)
                .map(|w| {
                    let cases = &cases;
                    scope.spawn(move || (w..cases.len()).step_by(workers).map(|k| run_case(k, &cases[k])).collect::<Vec<_>>())
                })
                .collect();
            handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
        })
    };
    #[cfg(target_arch = "wasm32")]
    let results: Vec<_> = cases.iter().enumerate().map(|(k, c)| run_case(k, c)).collect();
    let compared: usize = results.iter().map(|r| r.0).sum();
    let boundaries: usize = results.iter().map(|r| r.2).sum();
    let mixed = results.iter().filter(|r| r.3).count();
    let failures: Vec<&String> = results.iter().flat_map(|r| &r.1).collect();
    let n = cases.len();
    assert!(failures.is_empty(), "{} contradictions, first: {}", failures.len(), failures[0]);
    // The cases must exercise the conditions: many trajectories cross a tension bound.
    assert!(mixed * 3 >= n, "only {mixed} of {n} trajectories have both kinds of section");
    assert!(boundaries >= n / 2 && compared > n * SAMPLES / 2, "{boundaries} boundaries, {compared} samples");
}


const ROBOCRANE: &str = include_str!("../static/scenarios/robocrane.json");

/// A Robocrane slerp from q1 tilting on past the feasible range (θ from 0.9 to 1.4 with φ, σ and
/// the position of q1): the exact verifier finds an infeasible end section whose boundary is the
/// named cable's tension bound, where the reference's margin of that very bound crosses zero.
#[test]
fn robocrane_slerp_across_a_tension_boundary() {
    let mut v: serde_json::Value = serde_json::from_str(ROBOCRANE).unwrap();
    v["poses"]["tilted"] = serde_json::json!({"position": [0, 0, 2], "tilt_torsion": [-0.5, 1.4, 0.6108652381980153]});
    v["trajectories"] = serde_json::json!([{"name": "tilt", "translation": {"line": [[0, 0, 2], [0, 0, 2]]}, "orientation": {"slerp": ["q1", "tilted"]}}]);
    let s = Scenario::from_json(&v.to_string()).unwrap();
    let r = verify_trajectory(&s, &s.trajectories[0]).unwrap();
    assert!(r.uncertain.is_empty(), "{:?}", r.uncertain);
    assert_eq!(r.infeasible.len(), 1, "{r:?}");
    assert_eq!(r.boundaries.len(), 1, "{r:?}");
    let b = &r.boundaries[0];
    assert!(matches!(b.enters, Side::Infeasible) && r.infeasible[0][1] == 1.0);
    // The reference: the same wrench set and poses, from the definitions.
    let w = s.wrench.as_ref().unwrap();
    let to_q = |p: &cablenav::model::Pose| {
        let q = p.rotation.quaternion();
        [q.w, q.i, q.j, q.k]
    };
    let case = Case {
        cables: s.robot.cables.iter().map(|c| (V3::from_arr(c.base.into()), V3::from_arr(c.platform.into()))).collect(),
        tension: (0.0, 1.0),
        nominal: w.nominal,
        e_inv: w.ellipsoid_inv,
        point: V3::from_arr(w.point.into()),
        world_frame: true,
        traj: RefTrajectory {
            name: "tilt".into(),
            translation: RefTranslation::Line(v3(0.0, 0.0, 2.0), v3(0.0, 0.0, 2.0)),
            qs: to_q(s.pose("q1").unwrap()),
            qe: to_q(s.pose("tilted").unwrap()),
        },
    };
    let (compared, bad, _) = compare(&case, &r, SAMPLES, 1);
    assert!(bad.is_empty(), "{bad:?}");
    assert!(compared > SAMPLES * 9 / 10);
    // The named bound is the one whose reference margin vanishes at the boundary.
    let (m, (cable, lower), _) = case.margin(b.t).unwrap();
    assert!(m.abs() < 1e-8, "margin {m} at the boundary");
    let name = format!("cable {} tension {} bound", cable + 1, if lower { "lower" } else { "upper" });
    assert_eq!(b.constraint, name);
}
