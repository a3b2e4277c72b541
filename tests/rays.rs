//! Rays in every coordinate, checked against dense point-wise sampling of the same pose family.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::conditions::{for_scenario, Condition};
use cablenav::model::{Coord, Pose};
use cablenav::query::cables::cables_at;
use cablenav::verify::ray;
use cablenav::Scenario;

fn infeasible_at(s: &Scenario, conds: &[Box<dyn Condition>], base: &Pose, coord: Coord, value: f64) -> bool {
    let mut c = base.coords();
    c[coord.index()] = value;
    let cables = cables_at(&s.robot, &Pose::from_coords(c));
    conds.iter().any(|cond| cond.check(&cables).violated)
}

fn in_any(v: &[[f64; 2]], x: f64, margin: f64) -> bool {
    v.iter().any(|iv| iv[0] + margin < x && x < iv[1] - margin)
}

#[test]
fn rays_agree_with_dense_sampling() {
    let presets = [include_str!("../static/scenarios/cdpr7-tree.json"), include_str!("../static/scenarios/cdpr7-box.json")];
    let samples = if cfg!(target_arch = "wasm32") { 2_000 } else { 20_000 };
    let mut boundaries = 0;
    for text in presets {
        let s = Scenario::from_json(text).unwrap();
        let conds = for_scenario(&s);
        for pose_name in ["start", "end"] {
            let base = *s.pose(pose_name).unwrap();
            let c = base.coords();
            let ranges = [
                (Coord::X, 0.3, 3.7),
                (Coord::Y, 0.3, 3.7),
                (Coord::Z, 0.2, 3.8),
                (Coord::Phi, -3.0, 3.0),
                (Coord::Theta, c[4] - 1.2, c[4] + 1.2),
                (Coord::Sigma, -3.1, 3.1),
            ];
            for (coord, lo, hi) in ranges {
                let r = ray(&s, pose_name, coord, lo, hi).unwrap();
                let margin = 1e-7 * (hi - lo);
                for k in 0..=samples {
                    let x = lo + (hi - lo) * k as f64 / samples as f64;
                    let bad = infeasible_at(&s, &conds, &base, coord, x);
                    if bad {
                        assert!(!in_any(&r.feasible, x, margin), "{pose_name} {coord:?} = {x}: sampled infeasible, reported feasible");
                    } else {
                        assert!(!in_any(&r.infeasible, x, margin), "{pose_name} {coord:?} = {x}: sampled feasible, reported infeasible");
                    }
                }
                for b in &r.boundaries {
                    let h = 1e-7 * (hi - lo);
                    assert_ne!(infeasible_at(&s, &conds, &base, coord, b.value - h), infeasible_at(&s, &conds, &base, coord, b.value + h), "{coord:?} boundary {} ({})", b.value, b.constraint);
                    boundaries += 1;
                }
            }
        }
    }
    assert!(boundaries > 10, "only {boundaries} boundaries exercised");
}
