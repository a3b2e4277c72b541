//! Random multi-link robots for the tests: chains of random links, joints and cables as scenario
//! JSON, with a random configuration. Shared by `tests/chain.rs` and `tests/joint_statics.rs`,
//! which include this file by path.
#![allow(dead_code)]

use super::support::reference::Rng;
use serde_json::{json, Value};
use std::f64::consts::PI;

/// A random vector in the cube [−r, r]³.
pub fn v3(rng: &mut Rng, r: f64) -> [f64; 3] {
    [rng.range(-r, r), rng.range(-r, r), rng.range(-r, r)]
}

/// A random chain of 1–3 links (spherical, revolute, prismatic, free, universal, planar or spatial
/// joints with random axes, each link's parent
/// any earlier one), 3–7 cables from a ring of base anchors to random links, random clearances, an
/// obstacle sometimes; and a random configuration `q`.
pub fn random_chain(rng: &mut Rng) -> (Value, Vec<f64>) {
    let n = rng.int(1, 3);
    random_chain_of(rng, n, &["spherical", "revolute", "prismatic", "free", "universal", "planar", "spatial"], &|rng, _| rng.int(3, 7))
}

/// A random chain of `n` links with joints drawn from `kinds`, as many cables as `cables` says
/// for its degrees of freedom, and a random configuration ([`random_chain`]).
pub fn random_chain_of(rng: &mut Rng, n: usize, kinds: &[&str], cables: &dyn Fn(&mut Rng, usize) -> usize) -> (Value, Vec<f64>) {
    let mut links = Vec::new();
    let mut q = Vec::new();
    for k in 0..n {
        let kind = kinds[rng.int(0, kinds.len() - 1)];
        let names: Vec<String> = match kind {
            "spherical" => ["a", "b", "c"].iter().map(|x| format!("{x}{k}")).collect(),
            "free" => ["x", "y", "z", "phi", "theta", "sigma"].iter().map(|x| format!("{x}{k}")).collect(),
            "spatial" => ["x", "y", "z", "a", "b", "c"].iter().map(|x| format!("{x}{k}")).collect(),
            "universal" => ["u", "v"].iter().map(|x| format!("{x}{k}")).collect(),
            "planar" => ["u", "v", "w"].iter().map(|x| format!("{x}{k}")).collect(),
            _ => vec![format!("q{k}x")],
        };
        for i in 0..names.len() {
            let angle = match kind {
                "spherical" | "revolute" | "universal" => true,
                "free" | "spatial" => i >= 3,
                "planar" => i == 2,
                _ => false,
            };
            q.push(if angle { rng.range(-1.2, 1.2) } else { rng.range(-0.3, 0.3) });
        }
        let mut joint = json!({"type": kind, "coordinates": names});
        if kind == "revolute" || kind == "prismatic" {
            joint["axis"] = json!(v3(rng, 1.0));
        }
        if kind == "universal" {
            joint["axes"] = json!([v3(rng, 1.0), v3(rng, 1.0)]);
        }
        if kind == "planar" {
            joint["axes"] = json!([v3(rng, 1.0), v3(rng, 1.0), v3(rng, 1.0)]);
        }
        let mut link = json!({
            "name": format!("L{k}"),
            "location": if k == 0 { [0.0, 0.0, rng.range(0.0, 0.5)] } else { [rng.range(-0.2, 0.2), rng.range(-0.2, 0.2), rng.range(0.3, 0.8)] },
            "joint": joint,
            "body": {"from": [0.0, 0.0, 0.0], "to": [rng.range(-0.1, 0.1), rng.range(-0.1, 0.1), rng.range(0.3, 0.8)], "radius": rng.range(0.0, 0.08)},
        });
        if k > 0 {
            link["parent"] = json!(format!("L{}", rng.int(0, k - 1)));
        }
        links.push(link);
    }
    let m = cables(rng, q.len());
    let cables: Vec<Value> = (0..m)
        .map(|i| {
            let t = 2.0 * PI * (i as f64 + rng.range(-0.3, 0.3)) / m as f64;
            let r = rng.range(0.8, 1.5);
            json!({
                "base": [r * t.cos(), r * t.sin(), rng.range(-0.2, 1.5)],
                "link": format!("L{}", rng.int(0, n - 1)),
                "platform": [rng.range(-0.3, 0.3), rng.range(-0.3, 0.3), rng.range(0.0, 0.8)],
            })
        })
        .collect();
    let mut scenario = json!({
        "format": "cablenav-scenario/3",
        "name": "random chain",
        "robot": {"links": links, "cables": cables, "length": {"min": rng.range(0.0, 0.5), "max": rng.range(1.5, 3.0)}},
        "clearance": {"cable_cable": rng.range(0.0, 0.1), "cable_link": rng.range(0.0, 0.1), "cable_obstacle": rng.range(0.0, 0.1)},
    });
    if rng.chance(0.4) {
        scenario["obstacles"] = json!([{"type": "sphere", "center": [rng.range(-0.8, 0.8), rng.range(-0.8, 0.8), rng.range(0.0, 1.0)], "radius": rng.range(0.05, 0.3)}]);
    }
    (scenario, q)
}

/// Whether `x` lies in one of `intervals`, at least `margin` inside.
pub fn inside(intervals: &[[f64; 2]], x: f64, margin: f64) -> bool {
    intervals.iter().any(|iv| x > iv[0] + margin && x < iv[1] - margin)
}

/// A multi-link scenario without its links' masses, its gravity and its wrench, closure checked
/// (format 3).
pub fn massless(mut v: Value) -> Value {
    v["format"] = json!("cablenav-scenario/3");
    v["robot"].as_object_mut().unwrap().remove("gravity");
    v["robot"].as_object_mut().unwrap().remove("closure");
    v.as_object_mut().unwrap().remove("wrench");
    for link in v["robot"]["links"].as_array_mut().unwrap() {
        let link = link.as_object_mut().unwrap();
        link.remove("mass");
        link.remove("com");
    }
    v
}

/// A random chain of 1–3 links with 2–5 cables beyond its degrees of freedom, routed at random
/// ([`routed`]).
pub fn random_routed_chain(rng: &mut Rng) -> (Value, Vec<f64>) {
    let n = rng.int(1, 3);
    let (v, q) = random_chain_of(rng, n, &["spherical", "revolute", "prismatic", "free", "universal", "planar", "spatial"], &|rng, dof| dof + rng.int(2, 5));
    (routed(rng, v), q)
}

/// The chain `v` with its cables routed at random (format 6): about half of them start on a
/// link (`from`, the base anchor then in that link's frame) or run through one to three anchors
/// (`via`) on random links or, now and then, on the base.
pub fn routed(rng: &mut Rng, mut v: Value) -> Value {
    v["format"] = json!("cablenav-scenario/6");
    // longer cables, thinner links, smaller clearances: a routed cable is longer and passes
    // more bodies and cables
    v["robot"]["length"]["max"] = json!(rng.range(2.5, 5.0));
    for c in ["cable_cable", "cable_link"] {
        let x = v["clearance"][c].as_f64().unwrap();
        v["clearance"][c] = json!(x / 4.0);
    }
    for link in v["robot"]["links"].as_array_mut().unwrap() {
        let r = link["body"]["radius"].as_f64().unwrap();
        link["body"]["radius"] = json!(r / 4.0);
    }
    let links = v["robot"]["links"].as_array().unwrap().len();
    for cable in v["robot"]["cables"].as_array_mut().unwrap() {
        if rng.chance(0.5) {
            continue;
        }
        if rng.chance(0.4) {
            cable["from"] = json!(format!("L{}", rng.int(0, links - 1)));
            cable["base"] = json!([rng.range(-0.3, 0.3), rng.range(-0.3, 0.3), rng.range(0.0, 0.8)]);
        }
        let via: Vec<Value> = (0..rng.int(0, 3))
            .map(|_| {
                if rng.chance(0.2) {
                    json!({"point": [rng.range(-1.2, 1.2), rng.range(-1.2, 1.2), rng.range(-0.2, 1.5)]})
                } else {
                    json!({"link": format!("L{}", rng.int(0, links - 1)), "point": [rng.range(-0.3, 0.3), rng.range(-0.3, 0.3), rng.range(0.0, 0.8)]})
                }
            })
            .collect();
        if !via.is_empty() {
            cable["via"] = json!(via);
        }
        // a cable with every anchor on one link pulls nothing (refused): start it on the base
        let on = |a: &Value| a["link"].as_str().map(str::to_owned);
        let mut links_of: Vec<Option<String>> = vec![cable["from"].as_str().map(str::to_owned)];
        links_of.extend(via.iter().map(on));
        links_of.push(on(cable));
        if links_of.iter().all(|l| *l == links_of[0]) {
            cable.as_object_mut().unwrap().remove("from");
            cable["base"] = json!([rng.range(-1.2, 1.2), rng.range(-1.2, 1.2), rng.range(-0.2, 1.5)]);
        }
    }
    v
}

/// Each cable's length at configuration `q`, from the links' frames and the cables' anchors
/// alone (no segment or pose code of the core): the sum of the distances between consecutive
/// anchors in the world frame.
pub fn cable_lengths(s: &cablenav::Scenario, q: &[f64]) -> Vec<f64> {
    let frames = s.robot.chain.as_ref().unwrap().frames(q);
    let world = |a: &cablenav::model::Anchor| a.link.map_or(a.point, |l| frames[l].0 + frames[l].1 * a.point);
    s.robot.cables.iter().map(|c| c.anchors().windows(2).map(|w| (world(&w[1]) - world(&w[0])).norm()).sum()).collect()
}

/// A random configuration of an imported library model `s`: each coordinate uniformly within its
/// joint's range, a range CASPR pins to one value on a link the cables pull (Spatial_Tree's y, z
/// and angles: a model for x alone, singular there by symmetry) opened around it, ±1 m or
/// ±0.05 rad; a link no cable pulls stays where it is pinned (the tree stands upright: tilted,
/// nothing would hold it).
#[allow(dead_code)] // not every test file that includes this module samples the library
pub fn library_config(rng: &mut Rng, s: &cablenav::Scenario) -> Vec<f64> {
    let chain = s.robot.chain.as_ref().expect("a multi-link model");
    chain
        .coords()
        .enumerate()
        .map(|(i, (l, _, c))| {
            let open = if chain.is_angle(i) { 0.05 } else { 1.0 };
            let pulled = s.robot.cables.iter().any(|cable| cable.link == l);
            let [lo, hi] = if c.range[1] > c.range[0] || !pulled { c.range } else { [c.range[0] - open, c.range[0] + open] };
            rng.range(lo, hi)
        })
        .collect()
}
