//! Static feasibility of multi-link robots (issue 25, item 3): tensions strictly within their
//! bounds holding the links' weights. Checked against a reference written from the principle of
//! virtual work, apart from the core's joint rows: a cable of tension f does work −f·δL, gravity
//! m·g·δc, a force τ_i applied to coordinate i τ_i·δq_i, so at equilibrium
//! Σ_k f_k ∂L_k/∂q = Σ_l m_l g·∂c_l/∂q + τ, both gradients by central
//! differences of the cables' lengths and the centres of mass, and the largest margin of tensions
//! within their bounds by a linear program of the tests' own (`support::lp`). Per configuration on
//! random chains and on CASPR's arms, along random joint rays and paths against dense samples, and
//! bad link masses, wrenches and joint forces refused by field.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::conditions::{for_scenario, Condition};
use cablenav::model::Coord;
use cablenav::query::cables::cables_at_config;
use cablenav::model::Bounds;
use cablenav::query::wrench::{separating_direction, static_margin_of};
use cablenav::scenario::caspr::{model_to_json, to_json};
use cablenav::verify::ray_sections;
use cablenav::Scenario;
use cablenav::model::PointFrame;
use nalgebra::{DMatrix, DVector, Vector3};
use serde_json::{json, Value};

mod support;
use support::env_usize;
use support::lp::lp_margin_each;
use support::reference::Rng;

#[path = "shared/chains.rs"]
mod chains;
use chains::{random_chain_of, routed, v3};

/// Differences' step in the joint coordinates.
const H: f64 = 1e-6;

/// The scenario's static feasibility condition.
fn statics(s: &Scenario) -> Box<dyn Condition> {
    for_scenario(s).into_iter().find(|c| c.label() == "static feasibility").expect("a weighed chain is checked for static feasibility")
}

/// The virtual-work system at `q`: ∂L_k/∂q_i (columns per cable) and the loads' generalised
/// forces Σ_l m_l g·∂c_l/∂q_i + F·v_i + M·ω_i, the last two for the wrench (F at the point x of a
/// link, M) with the link turning by ω_i (the axial vector of ∂R/∂q_i Rᵀ) per unit q_i and the
/// material point at x moving by v_i = ∂o/∂q_i + ω_i × (x − o).
fn virtual_work(s: &Scenario, q: &[f64]) -> (DMatrix<f64>, DVector<f64>) {
    let chain = s.robot.chain.as_ref().unwrap();
    let lengths = |q: &[f64]| chains::cable_lengths(s, q);
    // the weights' work m g·c, summed over the links
    let work = |q: &[f64]| chain.frames(q).iter().zip(&chain.links).map(|((p, r), l)| l.mass * chain.gravity.dot(&(p + r * l.com))).sum::<f64>();
    let (n, m) = (q.len(), s.robot.cables.len());
    let (mut j, mut g) = (DMatrix::zeros(n, m), DVector::zeros(n));
    for i in 0..n {
        let (mut up, mut down) = (q.to_vec(), q.to_vec());
        up[i] += H;
        down[i] -= H;
        let (lu, ld) = (lengths(&up), lengths(&down));
        for k in 0..m {
            j[(i, k)] = (lu[k] - ld[k]) / (2.0 * H);
        }
        // a force applied to the coordinate itself does work τ_i·δq_i
        g[i] = (work(&up) - work(&down)) / (2.0 * H) + chain.joint_forces.get(i).copied().unwrap_or(0.0);
        if let Some(w) = &chain.load {
            let ((o, r), (ou, ru), (od, rd)) = (chain.frames(q)[w.link], chain.frames(&up)[w.link], chain.frames(&down)[w.link]);
            let turn = (ru - rd) / (2.0 * H) * r.transpose();
            let omega = Vector3::new(turn[(2, 1)] - turn[(1, 2)], turn[(0, 2)] - turn[(2, 0)], turn[(1, 0)] - turn[(0, 1)]) / 2.0;
            let x = match w.frame {
                PointFrame::Platform => o + r * w.point,
                PointFrame::World => o + w.point,
            };
            let v = (ou - od) / (2.0 * H) + omega.cross(&(x - o));
            g[i] += w.nominal.fixed_rows::<3>(0).dot(&v) + w.nominal.fixed_rows::<3>(3).dot(&omega);
        }
    }
    (j, g)
}

/// The reference's margin at `q` (the largest t with tensions in [f_min + t, f_max − t] in
/// equilibrium), or `None` where it cannot judge: no equilibrium at all is a failure (−∞), but a
/// margin within the differences' error of 0, or a rank-deficient gradient (Euler angles at gimbal
/// lock), is left out.
fn reference_margin(s: &Scenario, q: &[f64], bounds: (f64, f64)) -> Option<f64> {
    let m = s.robot.cables.len();
    reference_margin_each(s, q, &vec![bounds.0; m], &vec![bounds.1; m])
}

/// [`reference_margin`] with each cable's own tension bounds.
fn reference_margin_each(s: &Scenario, q: &[f64], lo: &[f64], hi: &[f64]) -> Option<f64> {
    let top = hi.iter().copied().fold(0.0, f64::max);
    let (j, g) = virtual_work(s, q);
    // rows nothing reaches (0 = 0) dropped, as their equation holds for any tensions
    let keep: Vec<usize> = (0..j.nrows()).filter(|&r| j.row(r).amax() > 1e-9 || g[r].abs() > 1e-9).collect();
    let (j, g) = (j.select_rows(&keep), g.select_rows(&keep));
    if (0..j.nrows()).any(|r| j.row(r).amax() <= 1e-9) {
        return Some(f64::NEG_INFINITY); // a weight no cable reaches
    }
    let sv = j.clone().svd(false, false).singular_values;
    if sv.min() < 1e-4 * sv.max() {
        return None;
    }
    match lp_margin_each(&j, &g, lo, hi) {
        Some((t, _)) if t.abs() < 1e-5 * (1.0 + top) => None,
        Some((t, _)) => Some(t),
        None => Some(f64::NEG_INFINITY),
    }
}

/// A random chain of 1–3 links with masses (most links), centres of mass, tension bounds,
/// sometimes a gravity other than the standard one, half the time a wrench on one link, 40 % of
/// the time forces on the coordinates of its revolute, prismatic, universal and planar joints;
/// 1 to 4 cables beyond its degrees of freedom.
fn weighed_chain(rng: &mut Rng, kinds: &[&str], route: bool) -> (Value, Vec<f64>, (f64, f64)) {
    let links = rng.int(1, 3);
    let (mut value, q) = random_chain_of(rng, links, kinds, &|rng, dof| dof + rng.int(1, 4));
    if route {
        value = routed(rng, value);
    } else {
        value["format"] = json!("cablenav-scenario/4");
    }
    for link in value["robot"]["links"].as_array_mut().unwrap() {
        if rng.chance(0.8) {
            link["mass"] = json!(rng.range(0.2, 3.0));
            link["com"] = json!(v3(rng, 0.3));
        }
    }
    if rng.chance(0.3) {
        let g = v3(rng, 10.0);
        value["robot"]["gravity"] = json!(g);
    }
    let bounds = (rng.range(0.0, 2.0), rng.range(30.0, 150.0));
    value["robot"]["tension"] = json!({"min": bounds.0, "max": bounds.1});
    if rng.chance(0.5) {
        // a wrench on one link: a force at a point of it and a moment
        let mut wrench = json!({
            "nominal": [rng.range(-8.0, 8.0), rng.range(-8.0, 8.0), rng.range(-8.0, 8.0), rng.range(-2.0, 2.0), rng.range(-2.0, 2.0), rng.range(-2.0, 2.0)],
            "link": format!("L{}", rng.int(0, links - 1)),
            "point": v3(rng, 0.4),
        });
        if rng.chance(0.3) {
            wrench["point_frame"] = json!("world");
        }
        value["wrench"] = wrench;
    }
    if rng.chance(0.4) {
        // forces from outside on the coordinates of the joints that take them: torques about
        // axes, forces along them
        let mut forces = serde_json::Map::new();
        for link in value["robot"]["links"].as_array().unwrap() {
            let kind = link["joint"]["type"].as_str().unwrap();
            if !matches!(kind, "revolute" | "prismatic" | "universal" | "planar") {
                continue;
            }
            for (k, name) in link["joint"]["coordinates"].as_array().unwrap().iter().enumerate() {
                let slides = kind == "prismatic" || (kind == "planar" && k < 2);
                let top = if slides { 15.0 } else { 5.0 };
                forces.insert(name.as_str().unwrap().to_string(), json!(rng.range(-top, top)));
            }
        }
        if !forces.is_empty() {
            value["format"] = json!("cablenav-scenario/6");
            value["joint_forces"] = Value::Object(forces);
        }
    }
    (value, q, bounds)
}

const KINDS: [&str; 7] = ["spherical", "revolute", "prismatic", "free", "universal", "planar", "spatial"];

/// Per configuration, the condition's verdict and margin against the virtual-work reference.
#[test]
fn random_chains_per_configuration_match_virtual_work() {
    per_configuration_matches_virtual_work(7, false);
}

/// The same with routed cables: a cable's tension does work −f·δL with L the sum of its
/// segments' lengths, so its pull acts on every link it touches.
#[test]
fn routed_chains_per_configuration_match_virtual_work() {
    per_configuration_matches_virtual_work(9, true);
}

fn per_configuration_matches_virtual_work(seed: u64, route: bool) {
    let mut rng = Rng::new(seed);
    let wanted = env_usize("CABLENAV_STATICS_CHAINS", if cfg!(target_arch = "wasm32") { 300 } else { 1500 });
    let (mut judged, mut held, mut failed) = (0, 0, 0);
    for _ in 0..wanted {
        let (value, q, bounds) = weighed_chain(&mut rng, &KINDS, route);
        let s = Scenario::from_json(&value.to_string()).unwrap_or_else(|e| panic!("{e}\n{value}"));
        let Some(chain) = s.robot.chain.as_ref() else { unreachable!() };
        if !chain.is_loaded() {
            continue;
        }
        let Some(reference) = reference_margin(&s, &q, bounds) else { continue };
        let check = statics(&s).check(&cables_at_config(&s.robot, &q));
        assert_eq!(!check.violated, reference > 0.0, "margin {reference} by virtual work, {:?} by the condition\n{value}\nq = {q:?}", check.distance);
        if let (Some(d), true) = (check.distance, reference.is_finite()) {
            assert!((d - reference).abs() <= 1e-4 * (1.0 + bounds.1), "margins {d} and {reference}\n{value}\nq = {q:?}");
        }
        judged += 1;
        if reference > 0.0 { held += 1 } else { failed += 1 }
    }
    assert!(judged * 2 > wanted && held * 20 > wanted && failed * 20 > wanted, "{judged} of {wanted} judged: {held} hold, {failed} fail");
}

/// Along joint rays: no sample inside a reported section contradicts the reference.
#[test]
fn random_chain_rays_agree_with_virtual_work() {
    rays_agree_with_virtual_work(19, false);
}

/// The same with routed cables.
#[test]
fn routed_chain_rays_agree_with_virtual_work() {
    rays_agree_with_virtual_work(23, true);
}

fn rays_agree_with_virtual_work(seed: u64, route: bool) {
    let mut rng = Rng::new(seed);
    let wanted = env_usize("CABLENAV_STATICS_RAYS", if cfg!(target_arch = "wasm32") { 30 } else { 120 });
    let (mut rays, mut judged, mut held, mut failed, mut mixed, mut uncertain, mut ends) = (0, 0, 0, 0, 0, 0.0, 0);
    while rays < wanted {
        let (value, q, bounds) = weighed_chain(&mut rng, &KINDS, route);
        let s = Scenario::from_json(&value.to_string()).unwrap_or_else(|e| panic!("{e}\n{value}"));
        let chain = s.robot.chain.as_ref().unwrap();
        if !chain.is_loaded() {
            continue;
        }
        let condition = statics(&s);
        let i = rng.int(0, chain.dof() - 1);
        let coord = Coord::Joint { index: i as u8, angle: chain.is_angle(i) };
        let width = if coord.is_angle() { rng.range(0.3, 2.0) } else { rng.range(0.1, 0.6) };
        let lo = q[i] - rng.range(0.0, width);
        let sec = ray_sections(&s, std::slice::from_ref(&condition), &q, coord, lo, lo + width);
        rays += 1;
        mixed += usize::from(!sec.feasible.is_empty() && !sec.infeasible.is_empty());
        uncertain += sec.uncertain.iter().map(|u| u[1] - u[0]).sum::<f64>() / width;
        let margin = 1e-6 * width;
        // each end of a feasible section inside the ray is where the check changes its verdict:
        // the loads' polynomials are exact, not merely close where samples fall
        let check_at = |v: f64| {
            let mut at = q.clone();
            at[i] = v;
            !condition.check(&cables_at_config(&s.robot, &at)).violated
        };
        for &[a, b] in &sec.feasible {
            for (end, out) in [(a, -margin), (b, margin)] {
                if end - margin > lo && end + margin < lo + width {
                    assert!(check_at(end - out) && !check_at(end + out), "ray {rays}: the section [{a}, {b}] does not end at {end}\n{value}\nq = {q:?}");
                    ends += 1;
                }
            }
        }
        for k in 0..=100 {
            let v = lo + width * k as f64 / 100.0;
            let mut at = q.clone();
            at[i] = v;
            let claim = if chains::inside(&sec.feasible, v, margin) { true } else if chains::inside(&sec.infeasible, v, margin) { false } else { continue };
            // the per-configuration check agrees with the sections wherever they speak
            assert_eq!(!condition.check(&cables_at_config(&s.robot, &at)).violated, claim, "ray {rays}: check at {v}\n{value}");
            let Some(reference) = reference_margin(&s, &at, bounds) else { continue };
            assert_eq!(claim, reference > 0.0, "ray {rays} at {v}: reported {claim}, virtual work's margin {reference}\n{value}\nq = {q:?}");
            judged += 1;
            if claim { held += 1 } else { failed += 1 }
        }
    }
    assert!(judged > wanted * 40 && held > wanted * 5 && failed > wanted * 5 && mixed * 20 >= wanted && ends * 20 >= wanted, "{judged} samples judged: {held} hold, {failed} fail; {mixed} rays with both, {ends} ends checked");
    // undecided only near boundaries: a few percent of the rays' length at most
    assert!(uncertain <= 0.05 * wanted as f64, "{uncertain} rays' worth undecided of {wanted}");
}

/// Along paths through configurations (every joint at once): the verifier's sections against
/// the reference at dense samples.
#[test]
fn random_chain_paths_agree_with_virtual_work() {
    paths_agree_with_virtual_work(41, false);
}

/// The same with routed cables.
#[test]
fn routed_chain_paths_agree_with_virtual_work() {
    paths_agree_with_virtual_work(43, true);
}

fn paths_agree_with_virtual_work(seed: u64, route: bool) {
    let mut rng = Rng::new(seed);
    let wanted = env_usize("CABLENAV_STATICS_PATHS", if cfg!(target_arch = "wasm32") { 20 } else { 80 });
    let (mut paths, mut judged, mut held, mut failed) = (0, 0, 0, 0);
    while paths < wanted {
        let (mut value, q, bounds) = weighed_chain(&mut rng, &["spherical", "revolute", "universal", "prismatic"], route);
        // only statics (and closure): no clearances, no link radii, no length bounds
        value["clearance"] = json!({"cable_cable": 0.0, "cable_link": 0.0, "cable_obstacle": 0.0});
        for link in value["robot"]["links"].as_array_mut().unwrap() {
            link["body"]["radius"] = json!(0.0);
        }
        value["robot"]["length"] = json!({"min": 0.0, "max": 100.0});
        value.as_object_mut().unwrap().remove("obstacles");
        let names: Vec<String> = {
            let s = Scenario::from_json(&value.to_string()).unwrap();
            if !s.robot.chain.as_ref().unwrap().is_loaded() {
                continue;
            }
            s.robot.chain.as_ref().unwrap().coords().map(|(_, _, c)| c.name.clone()).collect()
        };
        let mut configs = serde_json::Map::new();
        for k in 0..2 {
            let c: serde_json::Map<String, Value> = names.iter().zip(&q).map(|(n, v)| (n.clone(), json!(v + rng.range(-0.5, 0.5)))).collect();
            configs.insert(format!("c{k}"), Value::Object(c));
        }
        value["configurations"] = Value::Object(configs);
        value["trajectories"] = json!([{"name": "path", "through": ["c0", "c1"]}]);
        let s = Scenario::from_json(&value.to_string()).unwrap_or_else(|e| panic!("{e}\n{value}"));
        let along = cablenav::verify::along(&s, None).unwrap();
        let report = cablenav::verify::verify_along(&s, along).unwrap();
        paths += 1;
        let closure = for_scenario(&s).into_iter().find(|c| c.label() == "wrench closure").unwrap();
        let (Some(chain), cablenav::verify::Along::Joints(path)) = (s.robot.chain.as_ref(), along) else { unreachable!() };
        for k in 0..=200 {
            let t = k as f64 / 200.0;
            let at = path.config_at(chain, t);
            let claim = if chains::inside(&report.feasible, t, 1e-6) { true } else if chains::inside(&report.infeasible, t, 1e-6) { false } else { continue };
            let Some(reference) = reference_margin(&s, &at, bounds) else { continue };
            let closed = !closure.check(&cables_at_config(&s.robot, &at)).violated;
            assert_eq!(claim, reference > 0.0 && closed, "path {paths} at t = {t}: reported {claim}; virtual work's margin {reference}, closure {closed}\n{value}");
            judged += 1;
            if claim { held += 1 } else { failed += 1 }
        }
    }
    assert!(judged > wanted * 100 && held > wanted * 5 && failed > wanted * 5, "{judged} samples judged: {held} hold, {failed} fail");
}

macro_rules! model {
    ($path:literal) => {
        include_str!(concat!("../../shared/models/caspr/", $path))
    };
}

/// Every model of CASPR's library with its links' masses — the arms and the tree, and the models
/// with routed cables and cables between links (CAREX, 4U_modular_units_arm, RoboyLeftArm,
/// BioBiped_one_leg, 8S_neck, SJTUSnake) —: per configuration (uniformly within the joint
/// ranges) the condition agrees with the virtual-work reference.
#[test]
fn caspr_models_statics_match_virtual_work() {
    let models = [
        ("BMArm", model!("BMArm/BMArm_bodies.xml"), model!("BMArm/BMArm_cables.xml")),
        ("BMArm_X4_2", model!("BMArm_X4_2/BMArm_X4_2_bodies.xml"), model!("BMArm_X4_2/BMArm_X4_2_cables.xml")),
        ("Spatial_Tree", model!("Spatial_Tree/Spatial_Tree_bodies.xml"), model!("Spatial_Tree/Spatial_Tree_cables.xml")),
        // routed cables, cables between links
        ("CAREX", model!("CAREX/CAREX_bodies.xml"), model!("CAREX/CAREX_cables.xml")),
        ("4U_modular_units_arm", model!("4U_modular_units_arm/4U_modular_units_arm_bodies.xml"), model!("4U_modular_units_arm/4U_modular_units_arm_cables.xml")),
        ("RoboyLeftArm", model!("RoboyLeftArm/RoboyLeftArm_bodies.xml"), model!("RoboyLeftArm/RoboyLeftArm_cables.xml")),
        ("BioBiped_one_leg", model!("BioBiped_one_leg/BioBiped_one_leg_bodies.xml"), model!("BioBiped_one_leg/BioBiped_one_leg_cables.xml")),
        ("8S_neck", model!("8S_neck/8S_neck_bodies.xml"), model!("8S_neck/8S_neck_cables.xml")),
        ("SJTUSnake", model!("SJTUSnake/SJTUSnake_bodies.xml"), model!("SJTUSnake/SJTUSnake_cables.xml")),
    ];
    let per_model = env_usize("CABLENAV_STATICS_CONFIGS", if cfg!(target_arch = "wasm32") { 500 } else { 10_000 });
    let mut rng = Rng::new(3);
    for (name, bodies, cables) in models {
        let imported = to_json(name, bodies, cables).unwrap_or_else(|e| panic!("{name}: {e}"));
        let s = Scenario::from_json(&imported.json).unwrap();
        let chain = s.robot.chain.as_ref().unwrap();
        assert!(chain.is_loaded(), "{name}: its links' masses are imported");
        let (lo, hi): (Vec<f64>, Vec<f64>) = s.robot.cables.iter().map(|c| (c.tension.min, c.tension.max)).unzip();
        let configs: Vec<_> = (0..per_model).map(|_| chains::library_config(&mut rng, &s)).collect();
        // per configuration: None unjudged, else whether the reference holds; half of them on
        // each thread, each with a condition of its own
        let half = per_model.div_ceil(2);
        let verdicts: Vec<Option<bool>> = support::on_two_threads(2, &|w| {
            let condition = statics(&s);
            let judge = |q: &Vec<f64>| {
                let reference = reference_margin_each(&s, q, &lo, &hi)?;
                let check = condition.check(&cables_at_config(&s.robot, q));
                assert_eq!(!check.violated, reference > 0.0, "{name} at {q:?}: margin {reference} by virtual work, {:?} by the condition", check.distance);
                Some(reference > 0.0)
            };
            configs.iter().skip(w * half).take(half).map(judge).collect::<Vec<_>>()
        })
        .concat();
        let judged = verdicts.iter().flatten().count();
        let held = verdicts.iter().flatten().filter(|&&h| h).count();
        assert!(judged * 10 > per_model * 9, "{name}: {judged} of {per_model} judged");
        eprintln!("{name}: {judged} configurations judged, statically feasible at {held}");
    }
}

/// The core's statics program on the library's largest models (8S_neck: 24 joint rows, 76 cables;
/// SJTUSnake: 24 rows, 36 cables of up to 800 kN), at the configurations of their own
/// trajectories, certified by arithmetic of the test's own: the tensions it returns balance the
/// load and keep the margin t it reports (so the largest margin is at least t: an answer above
/// the truth cannot pass), and on 8S_neck a direction y — from the dual program, with every bound
/// moved in by t + ε — shows by its support that no tensions keep t + ε (so the largest margin is
/// below it). The dense simplex once answered "no margin" or −14.75 N on 8S_neck where the margin
/// was +2.47 N, and 4 % above the truth on SJTUSnake (tiny pivots). SJTUSnake's dual program
/// (tensions near 4e5 N against loads of a few N·m) is left out of the upper side: the core
/// re-checks every direction it uses, and this one's rounding is beyond the dense simplex.
#[test]
fn library_statics_margins_are_certified_both_ways() {
    let models = [
        ("8S_neck", model!("8S_neck/8S_neck_bodies.xml"), model!("8S_neck/8S_neck_cables.xml"), model!("8S_neck/8S_neck_trajectories.xml"), true),
        ("SJTUSnake", model!("SJTUSnake/SJTUSnake_bodies.xml"), model!("SJTUSnake/SJTUSnake_cables.xml"), model!("SJTUSnake/SJTUSnake_trajectories.xml"), false),
    ];
    let samples = if cfg!(target_arch = "wasm32") { 10 } else { 60 };
    for (name, bodies, cables, trajectories, upper) in models {
        let imported = model_to_json(name, bodies, cables, Some(trajectories), None).unwrap_or_else(|e| panic!("{name}: {e}"));
        let s = Scenario::from_json(&imported.json).unwrap();
        let chain = s.robot.chain.as_ref().unwrap();
        let bounds: Vec<Bounds> = s.robot.cables.iter().map(|c| c.tension).collect();
        let top = bounds.iter().map(|b| b.max).fold(0.0, f64::max);
        let mut certified = 0;
        for path in &s.joint_paths {
            for i in 0..=samples {
                let q = path.config_at(chain, i as f64 / samples as f64);
                let (j, g) = virtual_work(&s, &q);
                let (t, f) = static_margin_of(&j, &g, &bounds).unwrap_or_else(|| panic!("{name} `{}` at {q:?}: no margin", path.name));
                let f = DVector::from_vec(f);
                // at least t: the tensions balance the load and keep t from every bound
                let scale = 1.0 + (0..j.nrows()).map(|r| (0..j.ncols()).map(|k| (j[(r, k)] * f[k]).abs()).sum::<f64>()).fold(0.0, f64::max);
                assert!((&j * &f - &g).amax() <= 1e-9 * scale, "{name} `{}`: J f − load = {:e}", path.name, (&j * &f - &g).amax());
                let kept = (0..f.len()).map(|k| (f[k] - bounds[k].min).min(bounds[k].max - f[k])).fold(f64::INFINITY, f64::min);
                assert!(kept >= t - 1e-9 * top, "{name} `{}`: the tensions keep {kept}, not the margin {t}", path.name);
                assert!(t > 0.0, "{name} `{}`: the library's trajectories hold (margin {t})", path.name);
                certified += 1;
                if !upper {
                    continue;
                }
                // below t + ε: a direction whose support falls short of the load
                let eps = 1e-5 * top;
                let inner: Vec<Bounds> = bounds.iter().map(|b| Bounds { min: b.min + t + eps, max: b.max - t - eps }).collect();
                let (y, _) = separating_direction(&j, &g, &inner).unwrap_or_else(|| panic!("{name} `{}`: no direction bounds the margin {t}", path.name));
                let support: f64 = (0..j.ncols()).map(|k| { let a = y.dot(&j.column(k)); (inner[k].min * a).max(inner[k].max * a) }).sum();
                assert!(y.dot(&g) > support, "{name} `{}`: y·load {} within the support {support} at margin {t} + ε", path.name, y.dot(&g));
            }
        }
        eprintln!("{name}: {certified} margins certified{}", if upper { " both ways" } else { " from below" });
    }
}

/// The arm imported from CASPR carries its links' masses, centres of mass and CASPR's gravity,
/// and is judged on its statics alone (`robot.closure` false, format 6).
#[test]
fn caspr_arm_imports_its_masses() {
    let imported = to_json("arm", model!("BMArm/BMArm_bodies.xml"), model!("BMArm/BMArm_cables.xml")).unwrap();
    let v: Value = serde_json::from_str(&imported.json).unwrap();
    assert_eq!((&v["format"], &v["robot"]["closure"]), (&json!("cablenav-scenario/6"), &json!(false)));
    assert_eq!(v["robot"]["gravity"], json!([0.0, 0.0, -9.81]));
    assert_eq!(v["robot"]["links"][0]["mass"], json!(0.9810187));
    assert_eq!(v["robot"]["links"][1]["com"], json!([1.56661e-07, 0.0801433, -1.28202e-07]));
}

/// The field an invalid scenario is refused for, and the reason.
fn refused(v: &Value) -> (String, String) {
    let e = Scenario::from_json(&v.to_string()).expect_err("refused");
    (e.field, e.reason)
}

#[test]
fn bad_link_masses_wrenches_and_joint_forces_name_the_field() {
    let mut rng = Rng::new(5);
    let (base, _, _) = weighed_chain(&mut rng, &["revolute"], false);
    let with = |f: &dyn Fn(&mut Value)| {
        let mut v = base.clone();
        f(&mut v);
        v
    };
    for (bad, field, says) in [
        (with(&|v| v["robot"]["links"][0]["mass"] = json!(-1.0)), "robot.links[0].mass", "positive"),
        (with(&|v| v["robot"]["links"][0]["mass"] = json!(0.0)), "robot.links[0].mass", "positive"),
        (with(&|v| v["robot"]["links"][0]["mass"] = json!("heavy")), "robot.links[0].mass", ""),
        (with(&|v| { v["robot"]["links"][0]["mass"] = json!(1.0); v["robot"]["links"][0]["com"] = json!([0.0, 1.0]) }), "robot.links[0].com", ""),
        (with(&|v| { v["robot"]["links"][0].as_object_mut().unwrap().remove("mass"); v["robot"]["links"][0]["com"] = json!([0.0, 1.0, 0.0]) }), "robot.links[0].com", "mass"),
        (with(&|v| { v["robot"]["links"][0]["mass"] = json!(1.0); v["format"] = json!("cablenav-scenario/3") }), "robot.links[0].mass", "cablenav-scenario/4"),
        (with(&|v| v["robot"]["gravity"] = json!([0.0, 0.0])), "robot.gravity", ""),
        (with(&|v| v["robot"]["dynamics"] = json!({"mass": 1.0, "inertia": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]})), "robot.dynamics", "links"),
        (with(&|v| v["wrench"] = json!({"nominal": [0, 0, -1, 0, 0, 0]})), "wrench.link", "names the link"),
        (with(&|v| v["wrench"] = json!({"nominal": [0, 0, -1, 0, 0, 0], "link": "nowhere"})), "wrench.link", "known links: L0"),
        (with(&|v| v["wrench"] = json!({"nominal": [0, 0, -1, 0, 0, 0], "link": "L0", "radius": 1.0})), "wrench.radius", "nominal wrench alone"),
        (with(&|v| v["wrench"] = json!({"nominal": [0, 0, -1, 0, 0, 0], "link": "L0", "closure": true})), "wrench.closure", "robot.closure"),
        (with(&|v| v["wrench"] = json!({"nominal": [0, 0, -1, 0, 0], "link": "L0"})), "wrench.nominal", ""),
        (
            with(&|v| {
                *v = chains::massless(v.clone());
                v["wrench"] = json!({"nominal": [0, 0, -1, 0, 0, 0], "link": "L0"});
            }),
            "wrench",
            "cablenav-scenario/4",
        ),
        (with(&|v| { v["format"] = json!("cablenav-scenario/6"); v["joint_forces"] = json!({"nowhere": 1.0}) }), "joint_forces.nowhere", "the robot's coordinates: q0x"),
        (with(&|v| { v["format"] = json!("cablenav-scenario/6"); v["joint_forces"] = json!({"q0x": "strong"}) }), "joint_forces", ""),
        (with(&|v| { v["format"] = json!("cablenav-scenario/4"); v["joint_forces"] = json!({"q0x": 1.0}) }), "joint_forces", "cablenav-scenario/6"),
        (
            with(&|v| {
                v["format"] = json!("cablenav-scenario/6");
                v["robot"]["links"][0]["joint"] = json!({"type": "spherical", "coordinates": ["a0", "b0", "c0"]});
                v["joint_forces"] = json!({"b0": 1.0});
            }),
            "joint_forces.b0",
            "joint is spherical",
        ),
    ] {
        let (f, reason) = refused(&bad);
        assert!(f.starts_with(field), "expected {field}, got {f}: {reason}");
        assert!(reason.contains(says), "{f}: {reason}");
    }
    // a platform robot's gravity belongs in its dynamics
    let platform = json!({"format": "cablenav-scenario/4", "name": "p", "robot": {"gravity": [0, 0, -9.8], "cables": (0..6).map(|k| json!({"base": [k as f64, 0.0, 1.0], "platform": [0.0, k as f64 * 0.1, 0.0]})).collect::<Vec<_>>()}});
    let (f, reason) = refused(&platform);
    assert_eq!(f, "robot.gravity", "{reason}");
    assert!(reason.contains("robot.dynamics.gravity"), "{reason}");
    let mut platform = platform;
    platform["robot"].as_object_mut().unwrap().remove("gravity");
    platform["wrench"] = json!({"nominal": [0, 0, -1, 0, 0, 0], "link": "platform"});
    let (f, reason) = refused(&platform);
    assert_eq!(f, "wrench.link", "{reason}");
    // … and forces on joint coordinates are a multi-link robot's
    platform.as_object_mut().unwrap().remove("wrench");
    platform["format"] = json!("cablenav-scenario/6");
    platform["joint_forces"] = json!({"x": 1.0});
    let (f, reason) = refused(&platform);
    assert_eq!((f.as_str(), reason.contains("multi-link")), ("joint_forces.x", true), "{reason}");
}

/// A spatial link alone (Spatial_Tree's end effector, its tree left out) is the platform robot
/// with the link's mass as the platform's: the joint-space margin equals the platform's static
/// margin (`robot.dynamics`, the platform's own condition and structure matrix) at every pose.
#[test]
fn a_spatial_link_holds_its_weight_as_the_platform_does() {
    let imported = to_json("tree", model!("Spatial_Tree/Spatial_Tree_bodies.xml"), model!("Spatial_Tree/Spatial_Tree_cables.xml")).unwrap();
    let mut chain: Value = serde_json::from_str(&imported.json).unwrap();
    chain["robot"]["links"].as_array_mut().unwrap().truncate(1);
    chain["configurations"]["initial"].as_object_mut().unwrap().remove("theta");
    let cables: Vec<Value> = chain["robot"]["cables"].as_array().unwrap().iter().map(|c| json!({"base": c["base"], "platform": c["platform"]})).collect();
    let platform = json!({
        "format": "cablenav-scenario/4", "name": "cube",
        "robot": {"cables": cables, "tension": chain["robot"]["tension"],
                  "dynamics": {"mass": 1.0, "inertia": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "gravity": [0.0, 0.0, -9.81]}},
        "wrench": {"nominal": [0, 0, 0, 0, 0, 0]},
    });
    let (chain, platform) = (Scenario::from_json(&chain.to_string()).unwrap(), Scenario::from_json(&platform.to_string()).unwrap());
    assert_eq!(chain.robot.chain.as_ref().unwrap().links[0].mass, 1.0);
    let (joint, wrench) = (statics(&chain), for_scenario(&platform).into_iter().find(|c| c.label() == "wrench feasibility").unwrap());
    let mut rng = Rng::new(23);
    let (mut compared, mut held) = (0, 0);
    for _ in 0..2000 {
        // its cables, attached at matching corners of the cube and of the frame, leave it
        // singular when level (every cable's moment is normal to the offset from the frame's
        // centre) and hold it only near level: half the poses level on the frame's vertical axis
        // (held), half anywhere and turned
        let (turn, off) = if rng.chance(0.5) { (0.0, 0.0) } else { (0.05, 2.0) };
        let q = [2.5 + rng.range(-off, off), 2.5 + rng.range(-off, off), rng.range(0.5, 4.5), rng.range(-turn, turn), rng.range(-turn, turn), rng.range(-turn, turn)];
        let r = nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::x_axis(), q[3]) * nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::y_axis(), q[4]) * nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::z_axis(), q[5]);
        let pose = cablenav::model::Pose { position: nalgebra::Vector3::new(q[0], q[1], q[2]), rotation: nalgebra::UnitQuaternion::from_rotation_matrix(&r) };
        let (a, b) = (joint.check(&cables_at_config(&chain.robot, &q)), wrench.check(&cablenav::query::cables::cables_at(&platform.robot, &pose)));
        match (a.distance, b.distance) {
            (Some(x), Some(y)) => assert!((x - y).abs() <= 1e-7 * (1.0 + y.abs()), "at {q:?}: joint space {x}, platform {y}"),
            (x, y) => assert_eq!(x.is_some(), y.is_some(), "at {q:?}: joint space {x:?}, platform {y:?}"),
        }
        assert_eq!(a.violated, b.violated, "at {q:?}");
        compared += 1;
        held += usize::from(!a.violated);
    }
    assert!(held > 100 && compared - held > 100, "{held} of {compared} poses hold");
}

