//! The ray lattice (thesis §3.5): Fig. 3.10's ray, grid statuses against `check`, rays against the
//! `ray` command, components against a brute-force flood fill, and bad requests.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::lattice::{point_grid, Lattice, LatticeSpec, MAX_RAYS};
use cablenav::model::{Coord, Pose};
use cablenav::verify::check_pose;
use cablenav::Scenario;

const CDPR7_BOX: &str = include_str!("../static/scenarios/cdpr7-box.json");
const CDPR7_TREE: &str = include_str!("../static/scenarios/cdpr7-tree.json");

/// Fig. 3.10's x–z cross-section: y = 2, identity orientation, 7 values over x ∈ [0.2, 3.8] and
/// z ∈ [0.3, 3.7].
fn fig310(steps: usize) -> LatticeSpec {
    LatticeSpec::new(vec![Coord::X, Coord::Z], vec![[0.2, 3.8], [0.3, 3.7]], vec![steps], [0.0, 2.0, 0.0, 0.0, 0.0, 0.0]).unwrap()
}

#[test]
fn fig_3_10_ray_at_z_0_8667_starts_at_2_002() {
    let s = Scenario::from_json(CDPR7_BOX).unwrap();
    let l = Lattice::build(&s, fig310(7));
    let ray = l.rays.iter().find(|r| r.vary == "x" && r.fixed.iter().any(|&(k, v)| k == "z" && (v - (0.3 + 3.4 / 6.0)).abs() < 1e-12)).expect("the x-ray at z = 0.8667");
    let last = ray.feasible.last().expect("a feasible piece");
    assert!((last[0] - 2.002).abs() < 1e-3, "starts at {}", last[0]);
    assert_eq!(last[1], 3.8);
    let g = l.graph().unwrap();
    assert_eq!(g.disagreements, 0);
    assert_eq!(l.rays.len(), 14);
}
