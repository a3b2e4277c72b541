//! Exact clearance to cylinders, cones and ellipsoids (issue 12, item 1) against the independent
//! reference of tests/support: exact point–cylinder, point–cone and point–ellipsoid distances
//! (meridian-plane Voronoi regions, Lagrange duality by golden section) minimised along each cable
//! segment. For each shape, [`TRAJECTORIES`] random trajectories pass near one such obstacle with a
//! clearance c > 0 (no other condition is active): the harness samples every trajectory densely and
//! probes 1e-9 … 1e-6 to either side of every reported boundary, failing on a sampled infeasible
//! point inside a reported feasible interval, a sampled feasible point (margin above 1e-9·scale)
//! inside a reported infeasible one, or a boundary that does not separate the reference's verdicts
//! 1e-6 to either side (so each boundary is within 1e-6 in t of the reference's).

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

mod support;

use support::{env_usize, on_two_threads};
use support::gen::*;
use support::harness::*;
use support::reference::*;

/// Trajectories per shape.
#[cfg(not(target_arch = "wasm32"))]
const TRAJECTORIES: usize = 1000;
#[cfg(target_arch = "wasm32")]
const TRAJECTORIES: usize = 24;
const TRAJ_PER_SCENARIO: usize = 4;
/// Samples of t per trajectory (besides the probes around boundaries).
#[cfg(not(target_arch = "wasm32"))]
const SAMPLES: usize = 1000;
#[cfg(target_arch = "wasm32")]
const SAMPLES: usize = 500;

/// A random robot and trajectories with one obstacle of `kind` (3 ellipsoid, 4 cylinder, 5 cone)
/// placed where some cable passes at some instant, clearance in [0.02, 0.3], no cable–cable
/// clearance and no length bounds.
fn near_shape(rng: &mut Rng, kind: usize, i: usize) -> RefScenario {
    let mut sc = random_scenario(rng, &format!("{}{i:03}", ["", "", "", "ellipsoid", "cylinder", "cone"][kind]), TRAJ_PER_SCENARIO);
    sc.cable_cable = 0.0;
    sc.length = None;
    sc.cable_obstacle = rng.range(0.02, 0.3);
    let traj = &sc.trajectories[rng.int(0, sc.trajectories.len() - 1)];
    let (p, r) = traj.pose(rng.f64());
    let (a, b) = sc.cables[rng.int(0, sc.cables.len() - 1)];
    let end = p + mat_vec(&r, b);
    let centre = a + (end - a) * rng.range(0.3, 0.9) + rng.in_box(0.3);
    let shape = random_shape_at(rng, kind, centre);
    sc.obstacles = vec![RefObstacle { name: obstacle_name(&shape, 0), shape }];
    sc
}

fn check_shape(kind: usize, seed: u64) {
    let n = env_usize("CABLENAV_QUADRIC_TRAJECTORIES", TRAJECTORIES).div_ceil(TRAJ_PER_SCENARIO);
    let mut rng = Rng::new(seed);
    let scenarios: Vec<RefScenario> = (0..n).map(|i| near_shape(&mut rng, kind, i)).collect();
    let dump = if cfg!(target_arch = "wasm32") { None } else { Some(concat!(env!("CARGO_MANIFEST_DIR"), "/target/property-failures")) };
    let per = |i: usize| run_scenario(&scenarios[i], SAMPLES, seed + i as u64, dump);
    let mut total = Stats::default();
    for s in on_two_threads(n, &per) {
        total.merge(s);
    }
    let name = ["", "", "", "ellipsoid", "cylinder", "cone"][kind];
    println!("{name}: {}", total.summary());
    for f in total.failures.iter().take(20) {
        println!("  {f}");
    }
    assert!(total.failure_counts.is_empty(), "{name}: {:?}", total.failure_counts);
    assert!(total.trajectories >= n * TRAJ_PER_SCENARIO);
    assert!(total.boundaries > total.trajectories / 10, "{name}: too few boundaries ({}) to test", total.boundaries);
}

#[test]
fn ellipsoid_clearance_agrees_with_exact_distances() {
    check_shape(3, 0xE11);
}

#[test]
fn cylinder_clearance_agrees_with_exact_distances() {
    check_shape(4, 0xC71);
}

#[test]
fn cone_clearance_agrees_with_exact_distances() {
    check_shape(5, 0xC0E);
}
