//! Multi-link robots (issue 11): the CASPR arms imported, exact rays over joint coordinates against
//! dense point-wise sampling on random chains, the one-link free-joint chain against the platform
//! robot on every preset, bad chains refused by field, and the thesis' Fig. 3.12 cross-section.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::conditions::{for_scenario, Condition, Kind};
use cablenav::lattice::{point_grid, Lattice, LatticeSpec};
use cablenav::model::Coord;
use cablenav::query::cables::cables_at_config;
use cablenav::query::lp::{maximise, LpResult};
use nalgebra::{DMatrix, DVector};
use cablenav::scenario::caspr::to_json;
use cablenav::verify::profile::cable_states_at;
use cablenav::verify::{check_config, ray_sections};
use cablenav::Scenario;
use serde_json::{json, Value};
use std::f64::consts::PI;

mod support;
use support::reference::Rng;

#[path = "shared/chains.rs"]
mod chains;
use chains::{inside, massless, random_chain, random_chain_of, random_routed_chain, routed};

macro_rules! model {
    ($path:literal) => {
        include_str!(concat!("../../shared/models/caspr/", $path))
    };
}

const X4_BODIES: &str = model!("BMArm_X4_2/BMArm_X4_2_bodies.xml");
const X4_CABLES: &str = model!("BMArm_X4_2/BMArm_X4_2_cables.xml");
const ARM_BODIES: &str = model!("BMArm/BMArm_bodies.xml");
const ARM_CABLES: &str = model!("BMArm/BMArm_cables.xml");

fn import(bodies: &str, cables: &str) -> Value {
    serde_json::from_str(&to_json("arm", bodies, cables).expect("imports").json).expect("JSON")
}


#[test]
fn bmarm_x4_2_imports_with_its_joints_and_cables() {
    let s = Scenario::from_json(&import(X4_BODIES, X4_CABLES).to_string()).expect("valid");
    let chain = s.robot.chain.as_ref().expect("a chain");
    let names: Vec<&str> = chain.coords().map(|(_, _, c)| c.name.as_str()).collect();
    assert_eq!(names, ["alpha", "beta", "gamma", "theta"]);
    assert_eq!(chain.coords().nth(2).map(|c| c.2.range), Some([-0.1745, 0.1745]));
    assert_eq!(chain.links[1].parent, Some(0));
    assert_eq!(chain.links[1].location, nalgebra::Vector3::new(0.0, 0.0, 0.7));
    // thesis Table 3.3: cables T1–T5 are the XML's cables 1, 3, 4, 5, 6
    let table = [
        ([1.0, 1.0, 0.0], 0, [-0.2121, 0.2121, 0.6]),
        ([-1.0, -1.0, 0.0], 0, [0.2121, -0.2121, 0.6]),
        ([1.0, -1.0, 0.0], 0, [-0.3536, -0.3536, 0.6]),
        ([0.0, 0.3, 0.0], 1, [0.0, 0.1, 0.4]),
        ([0.0, -0.3, 0.0], 1, [0.0, -0.1, 0.4]),
    ];
    assert_eq!(s.robot.cables.len(), 5);
    for (c, (a, link, b)) in s.robot.cables.iter().zip(table) {
        assert_eq!(c.link, link);
        for i in 0..3 {
            assert!((c.base[i] - a[i]).abs() < 1e-4 && (c.platform[i] - b[i]).abs() < 1e-4, "{c:?}");
        }
    }
    assert_eq!(s.config("initial").unwrap(), vec![0.0; 4]);
    // upright, the two lower-arm cables and the revolute axis lie in one plane: the cables' joint
    // forces do not hold the weights there; tilted by θ they do. Imported with its masses, the arm
    // is judged on its statics alone (robot.closure false): asked for, closure fails upright too
    let upright = check_config(&s, "initial", &[0.0; 4]);
    assert_eq!(upright.violated, ["static feasibility"]);
    let mut closed = s.clone();
    closed.robot.chain.as_mut().unwrap().closure = true;
    assert_eq!(check_config(&closed, "initial", &[0.0; 4]).violated, ["static feasibility", "wrench closure"]);
    let tilted = check_config(&s, "tilted", &[0.0, 0.0, 0.0, 0.3]);
    assert!(tilted.feasible, "{:?}", tilted.violated);
    // its links carry their masses (0.871 kg and 0.3334 kg) under CASPR's gravity, and the
    // tilted arm holds them (static feasibility)
    let chain = s.robot.chain.as_ref().unwrap();
    assert!(chain.links.iter().all(|l| l.mass > 0.0) && chain.gravity == nalgebra::Vector3::new(0.0, 0.0, -9.81));
}

#[test]
fn bmarm_imports_and_checks() {
    let s = Scenario::from_json(&import(ARM_BODIES, ARM_CABLES).to_string()).expect("valid");
    let chain = s.robot.chain.as_ref().unwrap();
    assert_eq!(chain.dof(), 4);
    assert_eq!(s.robot.cables.iter().map(|c| c.link).collect::<Vec<_>>(), [0, 0, 0, 0, 1, 1]);
    let q = s.config("initial").unwrap();
    assert_eq!(q, vec![0.18, 0.0, 0.0, -0.45]);
    let r = check_config(&s, "initial", &q);
    assert_eq!(r.lengths.len(), 6);
}

/// The largest t with J f = 0, f ≥ t, Σ f = 1 for the columns of `j` scaled to unit length:
/// closure (with rank n) iff t > 0.
fn closure_margin(j: &DMatrix<f64>) -> f64 {
    let (n, m) = j.shape();
    let mut a = DMatrix::zeros(n + 1, m + 2);
    for k in 0..m {
        let col = j.column(k) / j.column(k).norm().max(1e-300);
        for r in 0..n {
            a[(r, k)] = col[r];
            a[(r, m)] += col[r];
            a[(r, m + 1)] -= col[r];
        }
        a[(n, k)] = 1.0;
    }
    a[(n, m)] = m as f64;
    a[(n, m + 1)] = -(m as f64);
    let mut b = DVector::zeros(n + 1);
    b[n] = 1.0;
    let mut c = DVector::zeros(m + 2);
    c[m] = 1.0;
    c[m + 1] = -1.0;
    match maximise(&a, &b, &c) {
        LpResult::Optimal { value, .. } => value,
        _ => -1.0,
    }
}

/// Joint-space closure per configuration against its definition, independently of how the
/// condition writes its rows: the generalised forces of the cables are the gradients of their
/// lengths in joint space (a cable of tension f exerts −f ∂L/∂q), so closure holds iff the
/// columns of the length Jacobian (central differences) positively span the joint space.
#[test]
fn random_chain_closure_matches_the_length_jacobian() {
    closure_matches_the_length_jacobian(53, false);
}

/// The same with routed cables: a cable's pull is the gradient of its whole length.
#[test]
fn routed_chain_closure_matches_the_length_jacobian() {
    closure_matches_the_length_jacobian(59, true);
}

fn closure_matches_the_length_jacobian(seed: u64, route: bool) {
    let mut rng = Rng::new(seed);
    let (mut judged, mut closed, mut open) = (0, 0, 0);
    for _ in 0..400 {
        let (value, q) = random_chain(&mut rng);
        let value = if route { routed(&mut rng, value) } else { value };
        let s = Scenario::from_json(&value.to_string()).unwrap_or_else(|e| panic!("{e}\n{value}"));
        let (n, m) = (q.len(), s.robot.cables.len());
        let jac = length_jacobian(&s, &q);
        let sv = jac.clone().svd(false, false).singular_values;
        let t = closure_margin(&jac);
        if t.abs() < 1e-5 || (n <= m && sv.min() < 1e-4 * sv.max()) {
            continue; // within the differences' error of the boundary
        }
        let reference = t > 0.0 && n < m;
        let condition = for_scenario(&s).into_iter().find(|c| c.label() == "wrench closure").expect("closure is checked");
        let cables = cables_at_config(&s.robot, &q);
        assert_eq!(!condition.check(&cables).violated, reference, "closure margin {t}\n{value}\nq = {q:?}");
        judged += 1;
        if reference { closed += 1 } else { open += 1 }
    }
    assert!(judged > 300 && closed > 20 && open > 20, "{judged} judged: {closed} with closure, {open} without");
}

/// The cables' length Jacobian ∂L_k/∂q_i at `q` by central differences.
fn length_jacobian(s: &Scenario, q: &[f64]) -> DMatrix<f64> {
    let (n, m) = (q.len(), s.robot.cables.len());
    let lengths = |q: &[f64]| chains::cable_lengths(s, q);
    let h = 1e-6;
    let mut jac = DMatrix::zeros(n, m);
    for i in 0..n {
        let (mut up, mut down) = (q.to_vec(), q.to_vec());
        up[i] += h;
        down[i] -= h;
        let (lu, ld) = (lengths(&up), lengths(&down));
        for k in 0..m {
            jac[(i, k)] = (lu[k] - ld[k]) / (2.0 * h);
        }
    }
    jac
}

/// The length Jacobian's closure at `q` ([`closure_margin`] of its columns), or `None` within the
/// differences' error of the boundary.
fn closure_by_lengths(s: &Scenario, q: &[f64]) -> Option<bool> {
    let jac = length_jacobian(s, q);
    let sv = jac.clone().svd(false, false).singular_values;
    let t = closure_margin(&jac);
    (t.abs() >= 1e-5 && sv.min() >= 1e-4 * sv.max()).then_some(t > 0.0)
}

/// Every model of CASPR's multi-link library with its closure asked for (`robot.closure` true;
/// the import leaves it out of the weighed arms): per configuration ([`chains::library_config`]),
/// the condition's verdict equals the closure of the cable-length Jacobian (central differences of
/// the whole routed lengths, apart from the core's joint rows): its columns positively span the
/// joint space — a positive combination of them vanishes ([`closure_margin`]) and their rank is
/// the number of joint coordinates, which a coordinate no cable reaches (a zero row) denies. On
/// 8S_neck this once failed in the reference's own program: the simplex declared a ray that was
/// the rounding of the free margin's two halves (`query::lp`, `settle`).
#[test]
fn caspr_models_closure_matches_the_length_jacobian() {
    let models = [
        ("BMArm", ARM_BODIES, ARM_CABLES),
        ("BMArm_X4_2", X4_BODIES, X4_CABLES),
        ("Spatial_Tree", model!("Spatial_Tree/Spatial_Tree_bodies.xml"), model!("Spatial_Tree/Spatial_Tree_cables.xml")),
        ("CAREX", model!("CAREX/CAREX_bodies.xml"), model!("CAREX/CAREX_cables.xml")),
        ("4U_modular_units_arm", model!("4U_modular_units_arm/4U_modular_units_arm_bodies.xml"), model!("4U_modular_units_arm/4U_modular_units_arm_cables.xml")),
        ("RoboyLeftArm", model!("RoboyLeftArm/RoboyLeftArm_bodies.xml"), model!("RoboyLeftArm/RoboyLeftArm_cables.xml")),
        ("BioBiped_one_leg", model!("BioBiped_one_leg/BioBiped_one_leg_bodies.xml"), model!("BioBiped_one_leg/BioBiped_one_leg_cables.xml")),
        ("8S_neck", model!("8S_neck/8S_neck_bodies.xml"), model!("8S_neck/8S_neck_cables.xml")),
        ("SJTUSnake", model!("SJTUSnake/SJTUSnake_bodies.xml"), model!("SJTUSnake/SJTUSnake_cables.xml")),
    ];
    let per_model = support::env_usize("CABLENAV_CLOSURE_CONFIGS", if cfg!(target_arch = "wasm32") { 200 } else { 10_000 });
    let mut rng = Rng::new(61);
    for (name, bodies, cables) in models {
        let mut v: Value = serde_json::from_str(&to_json(name, bodies, cables).unwrap_or_else(|e| panic!("{name}: {e}")).json).unwrap();
        v["robot"]["closure"] = json!(true);
        let s = Scenario::from_json(&v.to_string()).unwrap_or_else(|e| panic!("{name}: {e}"));
        let condition = for_scenario(&s).into_iter().find(|c| c.label() == "wrench closure").expect("closure is asked for");
        let mut judged = 0;
        for _ in 0..per_model {
            let q = chains::library_config(&mut rng, &s);
            let jac = length_jacobian(&s, &q);
            let sv = jac.clone().svd(false, false).singular_values;
            let t = closure_margin(&jac);
            // the differences err by about 1e-10 (h = 1e-6): a margin below 1e-7 is no strictly
            // positive combination (CAREX's antagonist pairs balance each other with the others
            // at zero, t = 0 exactly), one from 1e-7 to 1e-5 is too close to judge
            let reference = if sv.min() < 1e-9 * sv.max() || t < 1e-7 {
                false // a coordinate no cable reaches, dependent rows, or no positive combination
            } else if t < 1e-5 || sv.min() < 1e-4 * sv.max() {
                continue;
            } else {
                true
            };
            let holds = !condition.check(&cables_at_config(&s.robot, &q)).violated;
            assert_eq!(holds, reference, "{name} at {q:?}: closure margin {t}, singular values {:.3e} to {:.3e}", sv.min(), sv.max());
            judged += 1;
        }
        assert!(judged * 10 > per_model * 9, "{name}: {judged} of {per_model} judged");
    }
}

/// Chains past the facets' reach (C(m, n − 1) > 252 sets of columns: 4 to 12 joint coordinates,
/// 11 to 20 cables): joint-space closure by the linear programs' certificates, along random joint
/// rays against the length Jacobian's closure at dense samples.
#[test]
fn closure_beyond_the_facets_agrees_with_the_length_jacobian_along_rays() {
    let mut rng = Rng::new(71);
    let rays_wanted = if cfg!(target_arch = "wasm32") { 14 } else { 40 };
    let (mut rays, mut judged, mut closed, mut open, mut mixed, mut uncertain) = (0, 0, 0, 0, 0, 0.0);
    while rays < rays_wanted {
        let links = rng.int(2, 3);
        let cables = |rng: &mut Rng, dof: usize| {
            let least = (dof + 1..).find(|&m| cablenav::query::wrench::binomial(m, dof - 1) > 252).unwrap();
            least + rng.int(0, 3)
        };
        let (value, q) = random_chain_of(&mut rng, links, &["spherical", "free", "universal", "spatial"], &cables);
        let s = Scenario::from_json(&value.to_string()).unwrap_or_else(|e| panic!("{e}\n{value}"));
        let closure = for_scenario(&s).into_iter().find(|c| c.label() == "wrench closure").expect("closure is checked");
        let chain = s.robot.chain.as_ref().unwrap();
        let i = rng.int(0, chain.dof() - 1);
        let coord = Coord::Joint { index: i as u8, angle: chain.is_angle(i) };
        let width = if coord.is_angle() { rng.range(0.3, 2.0) } else { rng.range(0.1, 0.6) };
        let lo = q[i] - rng.range(0.0, width);
        let sec = ray_sections(&s, std::slice::from_ref(&closure), &q, coord, lo, lo + width);
        rays += 1;
        mixed += usize::from(!sec.feasible.is_empty() && !sec.infeasible.is_empty());
        uncertain += sec.uncertain.iter().map(|u| u[1] - u[0]).sum::<f64>() / width;
        let margin = 1e-6 * width;
        for k in 0..=100 {
            let v = lo + width * k as f64 / 100.0;
            let mut at = q.clone();
            at[i] = v;
            let Some(reference) = closure_by_lengths(&s, &at) else { continue };
            let claim = if inside(&sec.feasible, v, margin) { true } else if inside(&sec.infeasible, v, margin) { false } else { continue };
            assert_eq!(claim, reference, "ray {rays} at {v}: reported {claim}, the length Jacobian says {reference}\n{value}\nq = {q:?}");
            // and the per-configuration check (the linear program) agrees
            assert_eq!(!closure.check(&cables_at_config(&s.robot, &at)).violated, reference, "check at {v}\n{value}");
            judged += 1;
            if reference { closed += 1 } else { open += 1 }
        }
    }
    assert!(judged > rays_wanted * 40 && closed > rays_wanted * 3 && open > rays_wanted * 3 && mixed * 14 >= rays_wanted, "{judged} samples judged: {closed} with closure, {open} without; {mixed} rays with both");
    // undecided only near boundaries: a few percent of the rays' length at most
    assert!(uncertain <= 0.05 * rays_wanted as f64, "{uncertain} rays' worth undecided of {rays_wanted}");
}

#[test]
fn random_chain_rays_agree_with_dense_sampling() {
    let mut rng = Rng::new(11);
    let (mut rays, mut judged, mut feasible_seen, mut infeasible_seen) = (0, 0, 0, 0);
    while rays < 200 {
        let (value, q) = random_chain(&mut rng);
        let s = match Scenario::from_json(&value.to_string()) {
            Ok(s) => s,
            Err(e) => panic!("generator made an invalid chain: {e}\n{value}"),
        };
        let conditions = for_scenario(&s);
        let chain = s.robot.chain.as_ref().unwrap();
        let i = rng.int(0, chain.dof() - 1);
        let coord = Coord::Joint { index: i as u8, angle: chain.is_angle(i) };
        let width = if coord.is_angle() { rng.range(0.3, 2.5) } else { rng.range(0.1, 0.8) };
        let lo = q[i] - rng.range(0.0, width);
        let hi = lo + width;
        let sec = ray_sections(&s, &conditions, &q, coord, lo, hi);
        rays += 1;
        let margin = 1e-6 * width;
        for k in 0..=300 {
            let v = lo + (hi - lo) * k as f64 / 300.0;
            let mut at = q.clone();
            at[i] = v;
            let cables = cables_at_config(&s.robot, &at);
            let violated: Vec<String> = conditions.iter().filter(|c| c.check(&cables).violated).map(|c| c.label()).collect();
            if inside(&sec.uncertain, v, 0.0) {
                continue;
            }
            if inside(&sec.feasible, v, margin) {
                judged += 1;
                feasible_seen += 1;
                assert!(violated.is_empty(), "ray {rays}: {v} in a feasible interval {:?} but {violated:?} is violated\n{value}", sec.feasible);
            } else if inside(&sec.infeasible, v, margin) {
                judged += 1;
                infeasible_seen += 1;
                assert!(!violated.is_empty(), "ray {rays}: {v} in an infeasible interval {:?} but no condition is violated\n{value}", sec.infeasible);
            }
        }
    }
    assert!(judged > 40_000, "{judged} samples judged");
    assert!(feasible_seen > 2_000 && infeasible_seen > 2_000, "{feasible_seen} feasible, {infeasible_seen} infeasible samples");
}

/// Routed cables (segments between links, a cable's length the sum of its segments', its pull
/// on every link it touches), condition by condition — lengths, segment pairs, segments and
/// links, segments and obstacles (spheres: a segment between two links is exact against them
/// too), closure — along random joint rays: no dense sample inside a reported section
/// contradicts the condition's own check there; undecided only near boundaries.
#[test]
fn routed_chain_rays_agree_condition_by_condition() {
    let mut rng = Rng::new(13);
    let wanted = if cfg!(target_arch = "wasm32") { 40 } else { 200 };
    let (mut rays, mut judged, mut feasible_seen, mut infeasible_seen, mut mixed) = (0, 0, 0, 0, 0);
    let (mut uncertain, mut measured) = (0.0, 0.0);
    while rays < wanted {
        let (value, q) = random_routed_chain(&mut rng);
        let s = Scenario::from_json(&value.to_string()).unwrap_or_else(|e| panic!("generator made an invalid chain: {e}\n{value}"));
        let ray = random_ray(&mut rng, &s, &q, 2.5, 0.8);
        rays += 1;
        for condition in for_scenario(&s) {
            let got = ray_agrees(&s, &condition, &q, ray, &format!("ray {rays}\n{value}"));
            mixed += usize::from(got.both);
            uncertain += got.undecided;
            measured += 1.0;
            (judged, feasible_seen, infeasible_seen) = (judged + got.held + got.failed, feasible_seen + got.held, infeasible_seen + got.failed);
        }
    }
    assert!(judged > wanted * 1000 && feasible_seen > wanted * 200 && infeasible_seen > wanted * 50 && mixed > wanted, "{judged} samples judged: {feasible_seen} hold, {infeasible_seen} fail; {mixed} sections with both");
    assert!(uncertain <= 0.01 * measured, "{uncertain} of {measured} condition-rays undecided");
}

/// A random joint ray of `s`'s chain through `q`: the coordinate varied, its [`Coord`], and the
/// range [lo, lo + width] around q's value (an angle's up to `turn` wide, a length's up to
/// `slide`).
fn random_ray(rng: &mut Rng, s: &Scenario, q: &[f64], turn: f64, slide: f64) -> (usize, Coord, f64, f64) {
    let chain = s.robot.chain.as_ref().unwrap();
    let i = rng.int(0, chain.dof() - 1);
    let coord = Coord::Joint { index: i as u8, angle: chain.is_angle(i) };
    let width = if coord.is_angle() { rng.range(0.3, turn) } else { rng.range(0.1, slide) };
    (i, coord, q[i] - rng.range(0.0, width), width)
}

/// What [`ray_agrees`] saw of one condition along one ray.
struct RayCheck {
    /// The undecided share of the ray.
    undecided: f64,
    /// Whether both verdicts were reported.
    both: bool,
    /// Samples inside feasible and infeasible sections.
    held: usize,
    failed: usize,
}

/// The sections `condition` reports along the joint ray `(i, coord, lo, width)` from `q`, held
/// to the condition's own check at 61 samples (those within 1e-6 of the ray's width of a
/// section's end left out); `case` says which case failed.
fn ray_agrees(s: &Scenario, condition: &Box<dyn Condition>, q: &[f64], (i, coord, lo, width): (usize, Coord, f64, f64), case: &str) -> RayCheck {
    let sec = ray_sections(s, std::slice::from_ref(condition), q, coord, lo, lo + width);
    let mut out = RayCheck {
        undecided: sec.uncertain.iter().map(|u| u[1] - u[0]).sum::<f64>() / width,
        both: !sec.feasible.is_empty() && !sec.infeasible.is_empty(),
        held: 0,
        failed: 0,
    };
    let margin = 1e-6 * width;
    for k in 0..=60 {
        let v = lo + width * k as f64 / 60.0;
        let mut at = q.to_vec();
        at[i] = v;
        let claim = if inside(&sec.feasible, v, margin) { true } else if inside(&sec.infeasible, v, margin) { false } else { continue };
        let holds = !condition.check(&cables_at_config(&s.robot, &at)).violated;
        assert_eq!(holds, claim, "{}: reported {claim} at {v}, {case}\nq = {q:?}", condition.label());
        if claim { out.held += 1 } else { out.failed += 1 }
    }
    out
}

/// An obstacle of kind `kind` (box, mesh, sphere, ellipsoid, cylinder, cone) named "block",
/// about `size` across, around `centre`.
fn obstacle_near(rng: &mut Rng, kind: usize, centre: [f64; 3], size: f64) -> Value {
    let at = |d: [f64; 3]| [centre[0] + d[0], centre[1] + d[1], centre[2] + d[2]];
    let axis = chains::v3(rng, 1.0);
    let norm = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt().max(1e-3);
    let along = |t: f64| at([axis[0] / norm * t, axis[1] / norm * t, axis[2] / norm * t]);
    match kind {
        0 => json!({"name": "block", "type": "box", "center": centre, "size": [rng.range(0.5, 2.0) * size, rng.range(0.5, 2.0) * size, rng.range(0.5, 2.0) * size]}),
        1 => {
            let vertices: Vec<[f64; 3]> = (0..4).map(|_| at(chains::v3(rng, size))).collect();
            json!({"name": "block", "type": "mesh", "vertices": vertices, "triangles": [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]})
        }
        2 => json!({"name": "block", "type": "sphere", "center": centre, "radius": rng.range(0.3, 1.0) * size}),
        3 => {
            let r = [rng.range(0.3, 1.0) * size, rng.range(0.3, 1.0) * size, rng.range(0.3, 1.0) * size];
            json!({"name": "block", "type": "ellipsoid", "center": centre, "matrix": [[1.0 / (r[0] * r[0]), 0, 0], [0, 1.0 / (r[1] * r[1]), 0], [0, 0, 1.0 / (r[2] * r[2])]]})
        }
        4 => json!({"name": "block", "type": "cylinder", "from": along(-size), "to": along(size), "radius": rng.range(0.2, 0.6) * size}),
        _ => json!({"name": "block", "type": "cone", "apex": along(-size), "axis": [axis[0] / norm, axis[1] / norm, axis[2] / norm], "half_angle": rng.range(0.2, 0.7), "height": 2.0 * size}),
    }
}

/// Routed cables' segments against every obstacle shape, each placed across the way of a segment
/// between two links: along random joint rays, no dense sample inside a section reported for a
/// cable–obstacle condition contradicts the condition's own check there, both verdicts are
/// reached, and the segments that start on a link are exact against every shape (undecided only
/// near boundaries), with and without a clearance.
#[test]
fn segments_between_links_against_every_shape() {
    let mut rng = Rng::new(37);
    let wanted = if cfg!(target_arch = "wasm32") { 60 } else { 300 };
    let (mut rays, mut judged, mut uncertain, mut by_shape) = (0, 0, 0.0, [0; 6]);
    while rays < wanted {
        let (mut value, q) = random_routed_chain(&mut rng);
        let s = Scenario::from_json(&value.to_string()).unwrap_or_else(|e| panic!("{e}\n{value}"));
        let between: Vec<usize> = s.robot.segments().iter().enumerate().filter(|(_, g)| g.from.link.is_some()).map(|(k, _)| k).collect();
        if between.is_empty() {
            continue;
        }
        let (a, x) = cables_at_config(&s.robot, &q)[between[rng.int(0, between.len() - 1)]];
        let mid = a + (x - a) * rng.range(0.3, 0.7);
        let kind = rays % 6;
        let size = rng.range(0.03, 0.15);
        value["obstacles"] = json!([obstacle_near(&mut rng, kind, mid.into(), size)]);
        // without a clearance (the solids themselves) one ray in three, else the offset solids
        let clearance = if rays % 3 == 0 { 0.0 } else { rng.range(0.005, 0.05) };
        value["clearance"]["cable_obstacle"] = json!(clearance);
        let s = Scenario::from_json(&value.to_string()).unwrap_or_else(|e| panic!("{e}\n{value}"));
        let ray = random_ray(&mut rng, &s, &q, 2.0, 0.6);
        rays += 1;
        for condition in for_scenario(&s).into_iter().filter(|c| c.label().ends_with(" - block")) {
            let got = ray_agrees(&s, &condition, &q, ray, &format!("ray {rays}\n{value}"));
            uncertain += got.undecided;
            by_shape[kind] += usize::from(got.both);
            judged += got.held + got.failed;
        }
    }
    // every shape is met and missed along its rays (box, mesh, sphere, ellipsoid, cylinder, cone)
    assert!(judged > wanted * 300 && by_shape.iter().all(|&k| k * 12 > wanted), "{judged} samples judged; condition-rays with both verdicts per shape {by_shape:?} on {wanted} rays");
    assert!(uncertain <= 0.01 * wanted as f64, "{uncertain} rays' worth undecided of {wanted}");
}

#[test]
fn random_chain_paths_agree_with_dense_sampling() {
    paths_agree_with_dense_sampling(29, false);
}

/// The same with routed cables.
#[test]
fn routed_chain_paths_agree_with_dense_sampling() {
    paths_agree_with_dense_sampling(31, true);
}

fn paths_agree_with_dense_sampling(seed: u64, route: bool) {
    let mut rng = Rng::new(seed);
    let (mut paths, mut judged, mut feasible_seen, mut infeasible_seen) = (0, 0, 0, 0);
    while paths < 100 {
        let (mut value, q) = if route { random_routed_chain(&mut rng) } else { random_chain(&mut rng) };
        let names: Vec<String> = {
            let s = Scenario::from_json(&value.to_string()).unwrap();
            s.robot.chain.as_ref().unwrap().coords().map(|(_, _, c)| c.name.clone()).collect()
        };
        // two or three configurations around q, joined by a path
        let count = rng.int(2, 3);
        let mut configs = serde_json::Map::new();
        for k in 0..count {
            let c: serde_json::Map<String, Value> = names.iter().zip(&q).map(|(n, v)| (n.clone(), json!(v + rng.range(-0.6, 0.6)))).collect();
            configs.insert(format!("c{k}"), Value::Object(c));
        }
        value["configurations"] = Value::Object(configs);
        value["trajectories"] = json!([{"name": "path", "through": (0..count).map(|k| format!("c{k}")).collect::<Vec<_>>()}]);
        let s = Scenario::from_json(&value.to_string()).unwrap_or_else(|e| panic!("{e}\n{value}"));
        let along = cablenav::verify::along(&s, None).unwrap();
        let report = cablenav::verify::verify_along(&s, along).unwrap();
        let sampled = cablenav::verify::verify_pointwise_along(&s, along, 1.0 / 300.0).unwrap();
        paths += 1;
        let conditions = for_scenario(&s);
        let (Some(chain), cablenav::verify::Along::Joints(path)) = (s.robot.chain.as_ref(), along) else { unreachable!() };
        for k in 0..=300 {
            let t = k as f64 / 300.0;
            if inside(&report.uncertain, t, 0.0) {
                continue;
            }
            let cables = cables_at_config(&s.robot, &path.config_at(chain, t));
            let violated = conditions.iter().any(|c| c.check(&cables).violated);
            if inside(&report.feasible, t, 1e-6) {
                judged += 1;
                feasible_seen += 1;
                assert!(!violated, "path {paths}: t = {t} in a feasible interval {:?} is violated\n{value}", report.feasible);
            } else if inside(&report.infeasible, t, 1e-6) {
                judged += 1;
                infeasible_seen += 1;
                assert!(violated, "path {paths}: t = {t} in an infeasible interval {:?} holds\n{value}", report.infeasible);
            }
        }
        // the point-wise baseline's sections bracket the exact ones
        assert_eq!(report.trajectory, "path");
        assert!(sampled.feasible.len() <= report.feasible.len() + 1 || report.feasible.is_empty(), "{:?} vs {:?}", sampled.feasible, report.feasible);
    }
    assert!(judged > 20_000, "{judged} samples judged");
    // routed chains hold less often (more segments, more pairs): fewer feasible samples
    let least = if route { 300 } else { 1_000 };
    assert!(feasible_seen > least && infeasible_seen > 1_000, "{feasible_seen} feasible, {infeasible_seen} infeasible samples");
}

#[cfg(not(target_arch = "wasm32"))]
/// A platform scenario rewritten as a one-link chain with a free joint: the cables pull the link,
/// the poses become configurations (x, y, z, φ, θ, σ), no wrench set, mass or winch limits.
fn as_chain(text: &str) -> Option<(Scenario, Scenario)> {
    // a spatial platform robot: one free link moves as it does (a point mass or a planar
    // platform is not a free link)
    let platform = Scenario::from_json(text).ok().filter(|s| s.robot.chain.is_none() && s.robot.mobility == cablenav::model::Mobility::Spatial)?;
    let mut v: Value = serde_json::from_str(text).ok()?;
    let o = v.as_object_mut()?;
    for k in ["wrench", "trajectories", "queries", "poses"] {
        o.remove(k);
    }
    o.insert("format".into(), json!("cablenav-scenario/3"));
    let names = ["x", "y", "z", "phi", "theta", "sigma"];
    let configs: serde_json::Map<String, Value> =
        platform.poses.iter().map(|(n, p)| (n.clone(), Value::Object(names.iter().zip(p.coords()).map(|(k, x)| (k.to_string(), json!(x))).collect()))).collect();
    o.insert("configurations".into(), Value::Object(configs));
    let robot = o.get_mut("robot")?.as_object_mut()?;
    // the platform's mass and winches are not for chains yet
    robot.remove("dynamics");
    robot.remove("winch");
    robot.insert("links".into(), json!([{"name": "platform", "joint": {"type": "free", "coordinates": names}}]));
    for c in robot.get_mut("cables")?.as_array_mut()? {
        c["link"] = json!("platform");
    }
    let chain = Scenario::from_json(&v.to_string()).expect("the chain version is valid");
    let mut plain = platform.clone();
    plain.wrench = None;
    plain.robot.dynamics = None;
    plain.robot.winch = cablenav::model::Winch { speed: None, acceleration: None };
    Some((plain, chain))
}

// reads the preset directory: native only (wasm32 in node has no file system)
#[cfg(not(target_arch = "wasm32"))]
#[test]
fn one_free_link_equals_the_platform_robot_on_every_preset() {
    use cablenav::verify::profile::cable_states;
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/static/scenarios");
    let mut compared = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "json") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let Some((platform, chain)) = as_chain(&text) else { continue };
        let without_tensions = |s: &Scenario| -> Vec<_> { for_scenario(s).into_iter().filter(|c| c.kind() != Kind::Tension).collect() };
        let (pc, cc) = (without_tensions(&platform), without_tensions(&chain));
        assert_eq!(pc.iter().map(|c| c.label()).collect::<Vec<_>>(), cc.iter().map(|c| c.label()).collect::<Vec<_>>());
        for (name, pose) in &platform.poses {
            let q = pose.coords();
            for (k, c) in Coord::ALL.into_iter().enumerate() {
                let (lo, hi) = if c.is_angle() { (q[k] - 0.8, q[k] + 0.8) } else { (q[k] - 0.5, q[k] + 0.5) };
                let a = ray_sections(&platform, &pc, &q, c, lo, hi);
                let b = ray_sections(&chain, &cc, &q, Coord::Joint { index: k as u8, angle: c.is_angle() }, lo, hi);
                assert_eq!(a, b, "{} pose {name} along {}", path.display(), c.name());
                compared += 1;
            }
            // the cable ends come from a quaternion (platform) and a rotation matrix (chain):
            // equal to rounding
            let (x, y) = (check_config(&platform, name, &q), check_config(&chain, name, &q));
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + a.abs());
            assert!(x.lengths.iter().zip(&y.lengths).all(|(a, b)| close(*a, *b)), "{} pose {name}", path.display());
            assert_eq!(x.violated, y.violated.iter().filter(|v| !v.contains("wrench")).cloned().collect::<Vec<_>>());
            let dist = |r: &cablenav::report::PoseReport| r.checks.iter().filter(|c| !c.constraint.contains("wrench")).map(|c| c.distance.unwrap_or(0.0)).collect::<Vec<_>>();
            assert!(dist(&x).iter().zip(dist(&y)).all(|(a, b)| close(*a, b)), "{} pose {name}", path.display());
            // the drawn cable states: the same flags (the chain has no wrench set: no margins)
            let flags = |v: Vec<cablenav::verify::profile::CableState>| v.into_iter().map(|c| (c.interfering, c.length_ok)).collect::<Vec<_>>();
            assert_eq!(flags(cable_states(&platform, pose)), flags(cable_states_at(&chain, &q)), "{} pose {name}", path.display());
            assert!(cable_states_at(&chain, &q).iter().all(|c| c.tension_margin.is_none()));
        }
    }
    assert!(compared >= 60, "{compared} rays compared");
}

fn refused(v: &Value) -> cablenav::Error {
    Scenario::from_json(&v.to_string()).expect_err("refused")
}

#[test]
fn bad_chains_name_the_field() {
    let good = import(X4_BODIES, X4_CABLES);
    Scenario::from_json(&good.to_string()).expect("the imported arm is valid");

    // routed cables (format 6): unknown links, a segment of no length, a cable that pulls nothing,
    // an older format, a platform robot's cable, closure asked on a platform
    let mut v = good.clone();
    v["format"] = json!("cablenav-scenario/6");
    Scenario::from_json(&v.to_string()).expect("format 6 reads the arm");
    let mut r = v.clone();
    r["robot"]["cables"][3]["via"] = json!([{"link": "Upper Arm", "point": [0.01, 0.02, 0.1]}, {"link": "Elbow", "point": [0, 0, 0]}]);
    let e = refused(&r);
    assert!(e.field == "robot.cables[3].via[1].link" && e.reason.contains("no link named \"Elbow\""), "{e}");
    r["robot"]["cables"][3]["via"] = json!([{"link": "Upper Arm", "point": [0.01, 0.02, "x"]}]);
    assert_eq!(refused(&r).field, "robot.cables[3].via[0].point[2]");
    r["robot"]["cables"][3]["via"] = json!([{"point": [0.5, 0.5, 0.5]}, {"point": [0.5, 0.5, 0.5]}]);
    let e = refused(&r);
    assert!(e.field == "robot.cables[3].via[1]" && e.reason.contains("no length"), "{e}");
    let mut r = v.clone();
    r["robot"]["cables"][3]["from"] = json!("Shoulder");
    assert_eq!(refused(&r).field, "robot.cables[3].from");
    let link = r["robot"]["cables"][3]["link"].clone();
    r["robot"]["cables"][3]["from"] = link;
    let e = refused(&r);
    assert!(e.field == "robot.cables[3]" && e.reason.contains("pulls nothing"), "{e}");
    let mut r = good.clone();
    r["format"] = json!("cablenav-scenario/5");
    r["robot"]["cables"][0]["via"] = json!([{"point": [0.5, 0.5, 0.5]}]);
    let e = refused(&r);
    assert!(e.field == "robot.cables[0].via" && e.reason.contains("cablenav-scenario/6"), "{e}");
    let mut r = v.clone();
    r["robot"]["closure"] = json!(false);
    let s = Scenario::from_json(&r.to_string()).expect("closure may be left out");
    assert!(!for_scenario(&s).iter().any(|c| c.label() == "wrench closure"));
    r["format"] = json!("cablenav-scenario/5");
    assert_eq!(refused(&r).field, "robot.closure");
    let platform = json!({"format": "cablenav-scenario/6", "name": "p", "robot": {"closure": true, "cables": (0..6).map(|i| json!({"base": [i, 0, 1], "platform": [0, 0, 0]})).collect::<Vec<_>>()}});
    assert_eq!(refused(&platform).field, "robot.closure");
    let mut platform = platform;
    platform["robot"].as_object_mut().unwrap().remove("closure");
    platform["robot"]["cables"][2]["via"] = json!([{"point": [0.5, 0.5, 0.5]}]);
    assert_eq!(refused(&platform).field, "robot.cables[2].via");

    let mut v = good.clone();
    v["robot"]["cables"][3]["link"] = json!("Forearm");
    let e = refused(&v);
    assert_eq!(e.field, "robot.cables[3].link");
    assert!(e.reason.contains("no link named \"Forearm\"") && e.reason.contains("Upper Arm"), "{e}");

    let mut v = good.clone();
    v["robot"]["links"][1]["joint"]["axis"] = json!([0.0, 0.0, 0.0]);
    let e = refused(&v);
    assert_eq!(e.field, "robot.links[1].joint.axis");
    assert!(e.reason.contains("zero length"), "{e}");

    // universal and planar joints take `axes`: as many as they turn and slide about, not parallel
    let joint = |v: &mut Value, j: Value| v["robot"]["links"][1]["joint"] = j;
    let mut v = good.clone();
    joint(&mut v, json!({"type": "universal", "coordinates": ["u", "w"]}));
    let e = refused(&v);
    assert_eq!((e.field.as_str(), e.reason.contains("needs 2 axes")), ("robot.links[1].joint.axes", true), "{e}");
    joint(&mut v, json!({"type": "universal", "axes": [[1, 0, 0], [-2, 0, 0]], "coordinates": ["u", "w"]}));
    let e = refused(&v);
    assert_eq!((e.field.as_str(), e.reason.contains("parallel")), ("robot.links[1].joint.axes", true), "{e}");
    joint(&mut v, json!({"type": "planar", "axes": [[0, 1, 0], [0, 0, 1]], "coordinates": ["u", "v", "w"]}));
    let e = refused(&v);
    assert_eq!((e.field.as_str(), e.reason.contains("needs 3 axes, got 2")), ("robot.links[1].joint.axes", true), "{e}");
    joint(&mut v, json!({"type": "planar", "axes": [[0, 1, 0], [0, 0, 1], [0, 0, 0]], "coordinates": ["u", "v", "w"]}));
    assert_eq!(refused(&v).field, "robot.links[1].joint.axes[2]");
    joint(&mut v, json!({"type": "spatial", "axes": [[1, 0, 0]], "coordinates": ["x", "y", "z", "a", "b", "c"]}));
    assert_eq!(refused(&v).field, "robot.links[1].joint.axes");
    joint(&mut v, json!({"type": "revolute", "axis": [1, 0, 0], "axes": [[1, 0, 0]], "coordinates": ["q"]}));
    assert_eq!(refused(&v).field, "robot.links[1].joint.axes");
    joint(&mut v, json!({"type": "spatial", "coordinates": ["x", "y", "z", "a", "b"]}));
    assert_eq!(refused(&v).field, "robot.links[1].joint.coordinates");
    joint(&mut v, json!({"type": "hinge", "coordinates": ["q"]}));
    let e = refused(&v);
    assert!(e.field == "robot.links[1].joint.type" && e.reason.contains("universal") && e.reason.contains("planar"), "{e}");

    let mut v = good.clone();
    v["robot"]["links"][0]["parent"] = json!("Lower Arm");
    let e = refused(&v);
    assert_eq!(e.field, "robot.links[0].parent");
    assert!(e.reason.contains("loop"), "{e}");

    let mut v = good.clone();
    v["robot"]["links"][1]["joint"]["range"] = json!([[-4.0, 4.0]]);
    let e = refused(&v);
    assert_eq!(e.field, "robot.links[1].joint.range[0]");
    assert!(e.reason.contains("2π"), "{e}");

    let mut v = good.clone();
    v["format"] = json!("cablenav-scenario/2");
    assert_eq!(refused(&v).field, "robot.links");

    let mut v = good.clone();
    v["configurations"]["initial"]["omega"] = json!(1.0);
    let e = refused(&v);
    assert_eq!(e.field, "configurations.initial.omega");

    let mut v = good.clone();
    v["robot"]["links"][1]["joint"]["type"] = json!("helical");
    assert_eq!(refused(&v).field, "robot.links[1].joint.type");

    let mut v = good;
    v["robot"]["links"][1]["joint"]["coordinates"] = json!(["alpha"]);
    let e = refused(&v);
    assert_eq!(e.field, "robot.links[1].joint.coordinates[0]");
    assert!(e.reason.contains("duplicate"), "{e}");
}

/// The thesis' 4-DoF arm with ε = 0.02 for cable–cable and cable–link clearance, at the Fig. 3.12
/// configuration γ = −π/12, θ = π/12 (γ is outside CASPR's ±0.1745 limit: a warning).
fn fig_3_12() -> Scenario {
    // the thesis' case study asks for wrench closure and interference only, not for the links'
    // weights to be held
    let mut v = massless(import(X4_BODIES, X4_CABLES));
    v["name"] = json!("BMArm_X4_2 (thesis §3.5.2)");
    v["clearance"] = json!({"cable_cable": 0.02, "cable_link": 0.02});
    v["configurations"]["fig312"] = json!({"alpha": 0.0, "beta": 0.0, "gamma": -PI / 12.0, "theta": PI / 12.0});
    v["configurations"]["below"] = json!({"alpha": 0.0, "beta": -0.4, "gamma": -PI / 12.0, "theta": PI / 12.0});
    v["configurations"]["above"] = json!({"alpha": 0.0, "beta": 0.4, "gamma": -PI / 12.0, "theta": PI / 12.0});
    v["trajectories"] = json!([{"name": "across the gap", "through": ["below", "above"]}]);
    if cfg!(not(target_arch = "wasm32")) && std::env::var("WRITE_PRESET").is_ok() {
        std::fs::write(concat!(env!("CARGO_MANIFEST_DIR"), "/static/multilink/bmarm-x4-2.json"), serde_json::to_string_pretty(&v).unwrap() + "\n").unwrap();
    }
    let s = Scenario::from_json(&v.to_string()).expect("valid");
    assert!(s.warnings.iter().any(|w| w.contains("configurations.fig312.gamma") && w.contains("outside")), "{:?}", s.warnings);
    s
}

/// The path from β = −0.4 to 0.4 (α = 0) crosses the gap between the two regions of Fig. 3.12(c):
/// cables 2 and 3 (the thesis' T2, T3) come closer than ε there, an interval the 10-step grid
/// does not sample.
#[test]
fn the_path_across_the_gap_has_an_infeasible_section() {
    let s = fig_3_12();
    let r = cablenav::verify::verify_along(&s, cablenav::verify::along(&s, Some("across the gap")).unwrap()).unwrap();
    assert_eq!(r.infeasible.len(), 1, "{r:?}");
    assert_eq!(r.boundaries.iter().map(|b| b.constraint.as_str()).collect::<Vec<_>>(), ["cables 2-3", "cables 2-3"]);
    let [a, b] = r.infeasible[0];
    assert!(a > 0.4 && b < 0.6 && b - a > 0.05, "{a} {b}");
    assert!(r.uncertain.is_empty());
    // the page draws cables 2 and 3 (0-based 1, 2) as interfering inside the gap, none outside
    let along = cablenav::verify::along(&s, None).unwrap();
    let interfering = |t: f64| cable_states_at(&s, &along.config_at(&s, t)).iter().enumerate().filter(|(_, c)| c.interfering).map(|(i, _)| i).collect::<Vec<_>>();
    assert_eq!(interfering((a + b) / 2.0), [1, 2]);
    assert_eq!(interfering(a / 2.0), Vec::<usize>::new());
    assert_eq!(along.config_at(&s, 0.0), s.config("below").unwrap());
}

/// The α–β cross-section on the ray lattice with 10 steps, under the conditions of `kind`
/// (`None`: all): its components and feasible grid points.
fn cross_section(s: &Scenario, kind: Option<Kind>) -> (usize, usize) {
    let axes = vec![s.coord("--axes", "alpha").unwrap(), s.coord("--axes", "beta").unwrap()];
    let spec = LatticeSpec::new(axes, vec![[-PI / 4.0, PI / 4.0]; 2], vec![10], s.config("fig312").unwrap()).unwrap();
    let mut lattice = Lattice::of_kind(s, spec, kind);
    while !lattice.step(64).done {}
    let r = lattice.report().unwrap();
    assert_eq!(r.disagreements, 0);
    assert_eq!(r.uncertain_rays, 0);
    (r.components, r.feasible_points)
}

#[test]
fn the_multilink_preset_is_the_imported_arm() {
    // configurations in name order: serde_json keeps an object's order only with its
    // preserve_order feature, which depends on what else the workspace builds
    let sorted = |mut s: Scenario| {
        s.configs.sort_by(|a, b| a.0.cmp(&b.0));
        s.warnings.sort();
        s
    };
    let imported = sorted(fig_3_12());
    let preset = sorted(Scenario::from_json(include_str!("../static/multilink/bmarm-x4-2.json")).expect("valid"));
    assert_eq!(preset, imported);
}

#[test]
fn fig_3_12_cross_section_on_the_ray_lattice() {
    let s = fig_3_12();
    let ifw = cross_section(&s, Some(Kind::Interference));
    let wcw = cross_section(&s, Some(Kind::Tension));
    let both = cross_section(&s, None);
    let axes = vec![s.coord("--axes", "alpha").unwrap(), s.coord("--axes", "beta").unwrap()];
    let spec = LatticeSpec::new(axes, vec![[-PI / 4.0, PI / 4.0]; 2], vec![10], s.config("fig312").unwrap()).unwrap();
    let grid = point_grid(&s, &spec);
    let pointwise = (grid.components, grid.feasible.iter().filter(|&&f| f).count());
    println!("IFW {ifw:?}, WCW {wcw:?}, IFW ∩ WCW {both:?}, point-wise IFW ∩ WCW {pointwise:?}");
    // the thesis (Figs. 3.12, 3.13): IFW two regions, WCW one, their intersection two separated
    // by a slight gap (docs/multilink.md)
    assert_eq!((ifw.0, wcw.0, both.0), (2, 1, 2));
    assert_eq!((ifw.1, wcw.1, both.1), (96, 81, 77));
    // the point-wise grid at the same resolution sees the same 77 points as one region: the gap
    // lies between grid points (the thesis: "impossible to find … by the point-wise method")
    assert_eq!(pointwise, (1, 77));
}
