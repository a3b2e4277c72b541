//! CASPR's joint-space trajectories (issue 25, item 5): imported as paths through their points
//! with every joint moving in proportion, the path CASPR's splines follow (each coordinate from
//! value to value, a ball joint by its shortest rotation), verified exactly. Checked against
//! CASPR's interpolation written apart (a ball joint by nalgebra's quaternion slerp), the
//! library's trajectories against dense samples, random chains whose legs turn by multiples of
//! one angle against dense samples, and bad paths refused by field.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::conditions::for_scenario;
use cablenav::model::{Chain, Joint, JointPath};
use cablenav::query::cables::cables_at_config;
use cablenav::scenario::caspr::model_to_json;
use cablenav::verify::{verify_along, Along};
use cablenav::Scenario;
use nalgebra::{Unit, UnitQuaternion, Vector3};
use serde_json::{json, Value};

mod support;
use support::reference::Rng;

#[path = "shared/chains.rs"]
mod chains;
use chains::{inside, random_chain_of};

macro_rules! model {
    ($name:literal) => {
        (
            $name,
            include_str!(concat!("../../shared/models/caspr/", $name, "/", $name, "_bodies.xml")),
            include_str!(concat!("../../shared/models/caspr/", $name, "/", $name, "_cables.xml")),
            include_str!(concat!("../../shared/models/caspr/", $name, "/", $name, "_trajectories.xml")),
        )
    };
}

/// A model imported with its trajectories, and the import's notes.
fn import((name, bodies, cables, trajectories): (&str, &str, &str, &str)) -> (Scenario, Vec<String>) {
    let imported = model_to_json(name, bodies, cables, Some(trajectories), None).unwrap_or_else(|e| panic!("{name}: {e}"));
    (Scenario::from_json(&imported.json).unwrap_or_else(|e| panic!("{name}: {e}")), imported.notes)
}

/// The rotation R = Rx(α)·Ry(β)·Rz(γ) of a ball joint's Euler angles, as a quaternion.
fn ball(q: &[f64]) -> UnitQuaternion<f64> {
    let about = |axis: Vector3<f64>, a: f64| UnitQuaternion::from_axis_angle(&Unit::new_unchecked(axis), a);
    about(Vector3::x(), q[0]) * about(Vector3::y(), q[1]) * about(Vector3::z(), q[2])
}

/// CASPR's interpolation from `a` to `b` at progress u, joint by joint: (the joint's translation
/// and rotation) — a ball joint by slerp, every other coordinate along its line.
fn caspr_at(chain: &Chain, a: &[f64], b: &[f64], u: f64) -> Vec<(Vector3<f64>, nalgebra::Matrix3<f64>)> {
    let mut o = 0;
    chain
        .links
        .iter()
        .map(|link| {
            let n = link.joint.dof();
            let (qa, qb) = (&a[o..o + n], &b[o..o + n]);
            o += n;
            match link.joint {
                Joint::Spherical => (Vector3::zeros(), *ball(qa).slerp(&ball(qb), u).to_rotation_matrix().matrix()),
                _ => link.joint.transform(&qa.iter().zip(qb).map(|(x, y)| x + (y - x) * u).collect::<Vec<_>>()),
            }
        })
        .collect()
}

/// The path's configurations and the exact motions agree with CASPR's interpolation: at each
/// t the joints equal slerp / linear interpolation at the same progress along the leg, and the
/// links' rational motions equal the frames there.
fn follows_caspr(chain: &Chain, path: &JointPath) {
    let legs = path.through.len() - 1;
    for k in 0..=200 {
        let t = k as f64 / 200.0;
        let leg = ((t * legs as f64).floor() as usize).min(legs - 1);
        let u = t * legs as f64 - leg as f64;
        let want = caspr_at(chain, &path.through[leg], &path.through[leg + 1], u);
        // the joints at the path's configuration, written the same way (a ball joint's slerp
        // from the configuration to itself is its rotation)
        let q = path.config_at(chain, t);
        let got = caspr_at(chain, &q, &q, 0.0);
        for (l, ((wp, wr), (gp, gr))) in want.iter().zip(&got).enumerate() {
            assert!((wp - gp).norm() < 1e-9 && (wr - gr).norm() < 1e-9, "{}: link {l} at t = {t}", path.name);
        }
    }
    for piece in path.motions(chain) {
        for k in 0..=4 {
            let lam = k as f64 / 4.0;
            let frames = chain.frames(&path.config_at(chain, piece[0].param.value(lam)));
            for (l, m) in piece.iter().enumerate() {
                let (p, r) = m.eval(lam);
                assert!((p - frames[l].0).norm() < 1e-9 && (r - frames[l].1).norm() < 1e-9, "{}: link {l} at λ = {lam}", path.name);
            }
        }
    }
}

/// The verifier's sections of `path` against every condition's check at `n + 1` samples; the
/// number of samples judged. Every sample must agree: the per-configuration statics check once
/// answered a few of 8S_neck's configurations wrongly (no margin, or −14.75 N between neighbours
/// that hold by 2.4 N: tiny pivots in the simplex) and is held to every sample since.
fn sections_hold(s: &Scenario, path: &JointPath, n: usize) -> usize {
    let chain = s.robot.chain.as_ref().unwrap();
    let report = verify_along(s, Along::Joints(path)).unwrap();
    let conditions = for_scenario(s);
    let violated_at = |t: f64| -> Vec<String> {
        let at = cables_at_config(&s.robot, &path.config_at(chain, t));
        conditions.iter().filter(|c| c.check(&at).violated).map(|c| c.label()).collect()
    };
    let mut judged = 0;
    for k in 0..=n {
        let t = k as f64 / n as f64;
        let claim = if inside(&report.feasible, t, 1e-6) { true } else if inside(&report.infeasible, t, 1e-6) { false } else { continue };
        let violated = violated_at(t);
        assert_eq!(violated.is_empty(), claim, "{}: t = {t} reported {}, {violated:?} violated", path.name, if claim { "feasible" } else { "infeasible" });
        judged += 1;
    }
    judged
}

#[test]
fn the_library_trajectories_import_as_proportional_paths() {
    for (model, count) in [(model!("8S_neck"), 4), (model!("SJTUSnake"), 4), (model!("4U_modular_units_arm"), 3), (model!("BMArm"), 11), (model!("BioBiped_one_leg"), 1)] {
        let (s, notes) = import(model);
        assert_eq!(s.joint_paths.len(), count, "{}: {notes:?}", model.0);
        assert!(s.joint_paths.iter().all(|p| p.proportional && p.through.len() >= 2), "{}", model.0);
        assert!(notes.iter().any(|n| n.contains("every joint moving in proportion")), "{}: {notes:?}", model.0);
    }
    // BMArm's ball joint turns 0.5375 rad where the elbow turns 0.2: no common angle, said so
    let (_, notes) = import(model!("BMArm"));
    assert!(notes.iter().any(|n| n.contains("\"traj_p2p\" skipped") && n.contains("not multiples of one angle")), "{notes:?}");
    // BioBiped's traj1 has moving knots: CASPR's spline curves between them
    let (_, notes) = import(model!("BioBiped_one_leg"));
    assert!(notes.iter().any(|n| n.contains("\"traj1\" skipped") && n.contains("q_dot")), "{notes:?}");
}

#[test]
fn the_library_paths_follow_caspr_interpolation() {
    for model in [model!("8S_neck"), model!("SJTUSnake"), model!("BMArm")] {
        let (s, _) = import(model);
        let chain = s.robot.chain.as_ref().unwrap();
        for path in &s.joint_paths {
            follows_caspr(chain, path);
        }
    }
}

/// 8S_neck's (24 joint coordinates, 76 cables) and SJTUSnake's (432 cable segments) own
/// trajectories, and 4U_modular_units_arm's: verified exactly, every sample inside a section
/// agreeing with the conditions' checks (natively all of them; in wasm one of each).
#[test]
fn the_library_trajectories_verify_against_dense_samples() {
    let wasm = cfg!(target_arch = "wasm32");
    for model in [model!("8S_neck"), model!("SJTUSnake"), model!("4U_modular_units_arm")] {
        let (s, _) = import(model);
        for path in s.joint_paths.iter().take(if wasm { 1 } else { usize::MAX }) {
            let judged = sections_hold(&s, path, if wasm { 20 } else { 100 });
            assert!(judged > if wasm { 15 } else { 90 }, "{}: {judged} samples judged", path.name);
        }
    }
}

/// Random chains (ball, revolute and universal joints) whose legs turn every moving angle by a
/// multiple (−3 to 3) of one random angle, or slide alone: the paths follow CASPR's
/// interpolation and their sections agree with every condition's check at dense samples.
#[test]
fn random_proportional_paths_agree_with_dense_sampling() {
    let mut rng = Rng::new(61);
    let wanted = if cfg!(target_arch = "wasm32") { 15 } else { 60 };
    let (mut paths, mut judged) = (0, 0);
    while paths < wanted {
        let links = rng.int(1, 3);
        let (mut value, q) = random_chain_of(&mut rng, links, &["spherical", "revolute", "universal", "prismatic"], &|rng, dof| dof + rng.int(1, 4));
        let s = Scenario::from_json(&value.to_string()).unwrap();
        let chain = s.robot.chain.as_ref().unwrap().clone();
        let names: Vec<String> = chain.coords().map(|(_, _, c)| c.name.clone()).collect();
        // two legs; each moves its angles by k·δ (a ball joint about one of its Euler axes, so
        // that its shortest rotation is that angle) or, now and then, its lengths alone
        let mut configs = vec![q.clone()];
        for _ in 0..2 {
            let from = configs.last().unwrap().clone();
            let delta = rng.range(0.05, 0.4);
            let slide = rng.chance(0.2);
            let mut to = from.clone();
            let mut o = 0;
            for link in &chain.links {
                let n = link.joint.dof();
                let moved: Vec<usize> = match link.joint {
                    Joint::Spherical => vec![rng.int(0, 2)],
                    _ => (0..n).collect(),
                };
                for k in moved {
                    let angle = chain.is_angle(o + k);
                    if angle != slide {
                        to[o + k] += if angle { rng.int(0, 6) as f64 - 3.0 } else { rng.range(-0.3, 0.3) / delta } * delta;
                    }
                }
                o += n;
            }
            configs.push(to);
        }
        let config = |q: &Vec<f64>| Value::Object(names.iter().cloned().zip(q.iter().map(|v| json!(v))).collect());
        value["format"] = json!("cablenav-scenario/6");
        value["configurations"] = json!({"c0": config(&configs[0]), "c1": config(&configs[1]), "c2": config(&configs[2])});
        value["trajectories"] = json!([{"name": "spline", "through": ["c0", "c1", "c2"], "joints": "proportional"}]);
        let s = match Scenario::from_json(&value.to_string()) {
            Ok(s) => s,
            // a ball joint turned about one Euler axis away from the identity turns by that
            // angle only when the others are zero; otherwise its shortest rotation may share no
            // small multiple with the rest: such legs are refused, and skipped here
            Err(e) if e.field == "trajectories[0].joints" && e.reason.contains("not multiples") => continue,
            Err(e) => panic!("{e}\n{value}"),
        };
        paths += 1;
        follows_caspr(&chain, &s.joint_paths[0]);
        judged += sections_hold(&s, &s.joint_paths[0], 150);
    }
    assert!(judged > wanted * 100, "{judged} samples judged");
}

#[test]
fn bad_proportional_paths_name_the_field() {
    let (s, _) = import(model!("4U_modular_units_arm"));
    assert!(!s.joint_paths.is_empty());
    let imported = model_to_json("4U", model!("4U_modular_units_arm").1, model!("4U_modular_units_arm").2, Some(model!("4U_modular_units_arm").3), None).unwrap();
    let good: Value = serde_json::from_str(&imported.json).unwrap();
    let refused = |v: &Value| Scenario::from_json(&v.to_string()).expect_err("refused");
    let mut v = good.clone();
    v["trajectories"][0]["joints"] = json!("straight");
    let e = refused(&v);
    assert!(e.field == "trajectories[0].joints" && e.reason.contains("\"proportional\""), "{e}");
    // BMArm's cables are straight: without its closure left out, only its paths need format 6
    let arm = model!("BMArm");
    let mut v: Value = serde_json::from_str(&model_to_json(arm.0, arm.1, arm.2, Some(arm.3), None).unwrap().json).unwrap();
    v["format"] = json!("cablenav-scenario/5");
    v["robot"].as_object_mut().unwrap().remove("closure");
    let e = refused(&v);
    assert!(e.field == "trajectories[0].joints" && e.reason.contains("cablenav-scenario/6"), "{e}");
    // an elbow of 0.2 rad against a shoulder of 0.2·√2: no common angle
    let mut v = good.clone();
    let first = v["trajectories"][0]["through"][1].as_str().unwrap().to_string();
    v["configurations"][&first]["beta"] = json!(0.2);
    v["configurations"][&first]["beta2"] = json!(0.2 * std::f64::consts::SQRT_2);
    let e = refused(&v);
    assert!(e.field == "trajectories[0].joints" && e.reason.contains("not multiples of one angle"), "{e}");
    // a platform robot's trajectory has no joints
    let platform = json!({"format": "cablenav-scenario/6", "name": "p", "robot": {"cables": (0..6).map(|i| json!({"base": [i, 0, 1], "platform": [0, 0, 0]})).collect::<Vec<_>>()},
        "trajectories": [{"name": "t", "joints": "proportional"}]});
    assert_eq!(refused(&platform).field, "trajectories[0].joints");
}
