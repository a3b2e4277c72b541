//! The ray lattice and the lattice planner (issue 10), in the core: Fig. 3.10's ray, grid statuses
//! against `check` and the point-wise grid, components against a brute-force flood fill on a fine
//! point-wise grid, bounded stepping, both planners behind one interface, format 2 pieces. The
//! command-line side (rays against the `ray` command, bad requests, planning written with `--out`
//! and checked with `cablenav verify`, no path through a wall) is `cli/tests/lattice.rs`.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::lattice::{point_grid, Lattice, LatticeSpec};
use cablenav::model::{Coord, Pose};
use cablenav::plan::{planner, PlanStatus, PlannerKind, PlannerOptions};
use cablenav::verify::check_pose;
use cablenav::Scenario;
use serde_json::{json, Value};

const CDPR7_BOX: &str = include_str!("../static/scenarios/cdpr7-box.json");
const CDPR7_TREE: &str = include_str!("../static/scenarios/cdpr7-tree.json");
const ROBOCRANE: &str = include_str!("../static/scenarios/robocrane.json");

/// Six cables from ceiling anchors (z = 4 over the square [0, 4]²) to a platform 0.4 wide.
fn ceiling_cables() -> Vec<Value> {
    let tops = [[0, 0, 4], [4, 0, 4], [4, 4, 4], [0, 4, 4], [2, 0, 4], [2, 4, 4]];
    let plats = [[-0.2, -0.2, 0.0], [0.2, -0.2, 0.0], [0.2, 0.2, 0.0], [-0.2, 0.2, 0.0], [0.0, -0.2, 0.0], [0.0, 0.2, 0.0]];
    tops.iter().zip(plats).map(|(b, p)| json!({"base": b, "platform": p})).collect()
}

/// A robot hanging from six ceiling anchors over a wall standing on the floor (x ∈ [1.9, 2.1]):
/// in the region below the wall's top, poses left and right of it are in different components.
fn wall() -> String {
    json!({
        "format": "cablenav-scenario/1", "name": "wall",
        "robot": {"cables": ceiling_cables()},
        "clearance": {"cable_cable": 0, "cable_obstacle": 0.1},
        "obstacles": [{"name": "wall", "type": "box", "center": [2, 2, 0.5], "size": [0.2, 4, 1]}],
        "poses": {"left": {"position": [1, 2, 0.5], "quaternion": [1, 0, 0, 0]}, "right": {"position": [3, 2, 0.5], "quaternion": [1, 0, 0, 0]}},
        "queries": [{"name": "across", "start": "left", "goal": "right", "fixed": ["phi", "theta", "sigma"],
                     "region": {"x": [0.5, 3.5], "y": [1, 3], "z": [0.2, 0.9]}}]
    })
    .to_string()
}

/// Fig. 3.10's x–z cross-section: y = 2, identity orientation, `steps` values over x ∈ [0.2, 3.8]
/// and z ∈ [0.3, 3.7].
fn fig310(steps: usize) -> LatticeSpec {
    LatticeSpec::new(vec![Coord::X, Coord::Z], vec![[0.2, 3.8], [0.3, 3.7]], vec![steps], [0.0, 2.0, 0.0, 0.0, 0.0, 0.0]).unwrap()
}

fn feasible_at(s: &Scenario, c: Vec<f64>) -> bool {
    check_pose(s, "grid", &Pose::from_slice(&c)).feasible
}

#[test]
fn fig_3_10_ray_at_z_0_8667_starts_at_2_002() {
    let s = Scenario::from_json(CDPR7_BOX).unwrap();
    let l = Lattice::build(&s, fig310(7));
    assert_eq!(l.rays.len(), 14);
    let z = 0.3 + 3.4 / 6.0;
    let ray = l.rays.iter().find(|r| r.vary == "x" && r.fixed.iter().any(|(k, v)| k == "z" && (v - z).abs() < 1e-12)).expect("the x-ray at z = 0.8667");
    assert_eq!(ray.feasible.len(), 1, "{:?}", ray.feasible);
    assert!((ray.feasible[0][0] - 2.002).abs() < 5e-4, "starts at {}", ray.feasible[0][0]);
    assert_eq!(ray.feasible[0][1], 3.8);
    assert_eq!(l.graph().unwrap().disagreements, 0);
}

#[test]
fn rays_spread_over_threads_equal_the_rays_in_order() {
    let s = Scenario::from_json(CDPR7_TREE).unwrap();
    let spec = LatticeSpec::new(vec![Coord::X, Coord::Y, Coord::Z], vec![[0.2, 3.8], [1.1, 2.9], [0.3, 3.7]], vec![6], [0.0; 6]).unwrap();
    let one = Lattice::build(&s, spec.clone());
    // half the rays on this thread, the rest spread over threads
    let mut split = Lattice::new(&s, spec.clone());
    split.step(54);
    let done = std::sync::atomic::AtomicUsize::new(0);
    assert!(split.finish(&done).done);
    assert_eq!(done.load(std::sync::atomic::Ordering::Relaxed), 54);
    assert_eq!(split.rays, one.rays);
    assert_eq!(split.graph(), one.graph());
    assert_eq!(Lattice::build_parallel(&s, spec).rays, one.rays);
}

#[test]
fn grid_statuses_equal_check_and_the_point_wise_grid() {
    for text in [CDPR7_BOX, CDPR7_TREE] {
        let s = Scenario::from_json(text).unwrap();
        let spec = fig310(7);
        let l = Lattice::build(&s, spec.clone());
        let g = l.graph().unwrap();
        let grid = point_grid(&s, &spec);
        let mut feasible = 0;
        for flat in 0..49 {
            let idx = spec.point_indices(flat);
            let c = spec.coords(&idx);
            let check = feasible_at(&s, c.clone());
            assert_eq!(g.point_feasible[flat], check, "{} at {c:?}", s.name);
            assert_eq!(grid.feasible[flat], check, "{} at {c:?}", s.name);
            // every ray through the point agrees
            assert_eq!(l.pieces_at(&idx).len(), if check { 2 } else { 0 }, "{} at {c:?}", s.name);
            feasible += usize::from(check);
        }
        assert!(feasible > 5 && feasible < 49, "{}: {feasible} feasible points", s.name);
    }
}


/// 4-neighbour components of a fine point-wise grid over the same plane, `refine` fine steps per
/// lattice step (so the lattice's rays are fine grid lines): the brute-force reference.
fn flood_fill(s: &Scenario, spec: &LatticeSpec, refine: usize) -> (Vec<Option<usize>>, usize) {
    let n: Vec<usize> = spec.steps.iter().map(|&k| (k - 1) * refine + 1).collect();
    let fine = LatticeSpec::new(spec.axes.clone(), spec.ranges.clone(), n.clone(), spec.fixed.clone()).unwrap();
    let feasible: Vec<bool> = (0..n[0] * n[1]).map(|f| feasible_at(s, fine.coords(&fine.point_indices(f)))).collect();
    let mut label = vec![None; feasible.len()];
    let mut next = 0;
    for start in 0..feasible.len() {
        if !feasible[start] || label[start].is_some() {
            continue;
        }
        let mut stack = vec![start];
        label[start] = Some(next);
        while let Some(f) = stack.pop() {
            let (i, j) = (f % n[0], f / n[0]);
            let mut near = vec![];
            if i > 0 {
                near.push(f - 1);
            }
            if i + 1 < n[0] {
                near.push(f + 1);
            }
            if j > 0 {
                near.push(f - n[0]);
            }
            if j + 1 < n[1] {
                near.push(f + n[0]);
            }
            for g in near {
                if feasible[g] && label[g].is_none() {
                    label[g] = Some(next);
                    stack.push(g);
                }
            }
        }
        next += 1;
    }
    (label, next)
}

#[test]
fn components_match_a_brute_force_flood_fill() {
    let wall = Scenario::from_json(&wall()).unwrap();
    let tree = Scenario::from_json(CDPR7_TREE).unwrap();
    let wall_spec = LatticeSpec::new(vec![Coord::X, Coord::Z], vec![[0.5, 3.5], [0.2, 0.9]], vec![9], [0.0, 2.0, 0.0, 0.0, 0.0, 0.0]).unwrap();
    for (s, spec, refine) in [(&tree, fig310(7), 8), (&wall, wall_spec, 6)] {
        let l = Lattice::build(s, spec.clone());
        let (fine, fine_count) = flood_fill(s, &spec, refine);
        let fine_spec_n = (spec.steps[0] - 1) * refine + 1;
        // the component of each feasible lattice point, in the lattice and in the fine grid
        let mut pairs = vec![];
        for flat in 0..spec.point_count() as usize {
            let idx = spec.point_indices(flat);
            let f = idx[0] * refine + idx[1] * refine * fine_spec_n;
            assert_eq!(l.component_at(&idx).is_some(), fine[f].is_some(), "{} at {idx:?}", s.name);
            if let (Some(a), Some(b)) = (l.component_at(&idx), fine[f]) {
                pairs.push((a, b));
            }
        }
        for p in &pairs {
            for q in &pairs {
                assert_eq!(p.0 == q.0, p.1 == q.1, "{}: lattice components {} {} vs flood fill {} {}", s.name, p.0, q.0, p.1, q.1);
            }
        }
        let lattice_components: std::collections::BTreeSet<usize> = pairs.iter().map(|p| p.0).collect();
        assert!(lattice_components.len() >= 2, "{}: a case with more than one component", s.name);
        assert!(fine_count >= lattice_components.len());
    }
}



/// The `wall()` robot without the wall, at z = 1, with minimum cable lengths (4 for the corner
/// cables, 3.7 for the middle ones) that, for x ∈ [1.5, 2.5], only torsions |σ| ≥ 2.3 meet (all
/// of them from |σ| ≈ 2.55; the platform's anchors turned away from their cables' bases): one
/// feasible band across σ = ±π. `left` (x = 1.7, σ = 2.6) and `right` (x = 2.3, σ = −2.6) lie in it, on either side
/// of the seam.
fn seam() -> String {
    json!({
        "format": "cablenav-scenario/1", "name": "seam",
        "robot": {"cables": ceiling_cables(), "length": {"min": [4.0, 4.0, 4.0, 4.0, 3.7, 3.7]}},
        "poses": {"left": {"position": [1.7, 2, 1], "tilt_torsion": [0, 0, 2.6]}, "right": {"position": [2.3, 2, 1], "tilt_torsion": [0, 0, -2.6]}},
        "queries": [{"name": "across", "start": "left", "goal": "right", "fixed": ["y", "z", "phi", "theta"], "region": {"x": [1.5, 2.5]}}]
    })
    .to_string()
}

#[test]
fn a_whole_turn_of_an_angle_axis_closes_the_lattice() {
    let s = Scenario::from_json(&seam()).unwrap();
    let spec = |sigma: [f64; 2]| LatticeSpec::new(vec![Coord::X, Coord::Sigma], vec![[1.5, 2.5], sigma], vec![7], [0.0, 2.0, 1.0, 0.0, 0.0, 0.0]).unwrap();
    let pi = std::f64::consts::PI;
    // σ ∈ [−π, π]: the band meets both ends of the range; its two halves are one component
    let whole = Lattice::build(&s, spec([-pi, pi]));
    assert!(whole.spec.wraps(1) && !whole.spec.wraps(0));
    let g = whole.graph().unwrap();
    assert_eq!(g.components, 1);
    assert_eq!(g.disagreements, 0);
    for i in 0..7 {
        assert_eq!(whole.component_at(&[i, 0]), Some(0), "x index {i}, σ = −π");
        assert_eq!(whole.component_at(&[i, 6]), Some(0), "x index {i}, σ = π");
        assert_eq!(whole.component_at(&[i, 3]), None, "σ = 0 is infeasible");
    }
    // 7 σ-rays with two pieces each, 2 x-rays (σ = ±π) with one piece: 16 pieces; edges at the 14
    // feasible grid points (2 rays each: 1 edge) and 7 across the seam
    assert_eq!((g.piece_component.len(), g.edges), (16, 21));
    // the point-wise grid at the same resolution closes too
    assert_eq!(point_grid(&s, &whole.spec).components, 1);
    // the same band in the middle of another whole turn: one component, no seam needed
    assert_eq!(Lattice::build(&s, spec([0.0, 2.0 * pi])).graph().unwrap().components, 1);
    // a range short of a whole turn does not close: the band's halves are apart
    let short = Lattice::build(&s, spec([-pi, pi - 1e-3]));
    assert!(!short.spec.wraps(1));
    assert_eq!(short.graph().unwrap().components, 2);
    assert_eq!(point_grid(&s, &short.spec).components, 2);
}

#[test]
fn a_lattice_plan_crosses_the_seam_of_a_whole_turn() {
    let s = Scenario::from_json(&seam()).unwrap();
    let pi = std::f64::consts::PI;
    let r = cablenav::plan::run(&s, "across", &PlannerOptions::new(PlannerKind::Lattice), &|| 0.0).unwrap();
    assert_eq!(r.status, PlanStatus::Found);
    let cablenav::plan::Details::Lattice(d) = &r.details else { panic!("a lattice report") };
    assert_eq!(d.components, 1, "{d:?}");
    // the polyline is continuous: past σ = π it goes on to σ = π + 0.68 (the goal's −2.6 + 2π)
    let sigma: Vec<f64> = d.polyline.iter().map(|c| c[5]).collect();
    assert!((sigma[0] - 2.6).abs() < 1e-12 && (sigma[sigma.len() - 1] - (2.0 * pi - 2.6)).abs() < 1e-12, "{sigma:?}");
    assert!(sigma.windows(2).all(|w| (w[1] - w[0]).abs() <= 2.0 * pi / 6.0 + 1e-12), "{sigma:?}");
    // σ = 0, the only way round without the seam, is infeasible; the trajectory verifies exactly
    assert!(!feasible_at(&s, vec![2.0, 2.0, 1.0, 0.0, 0.0, 0.0]));
    let traj = r.trajectory.expect("a trajectory");
    let v = cablenav::verify::verify_trajectory(&s, &traj).unwrap();
    assert_eq!(v.feasible, vec![[0.0, 1.0]], "{v:?}");
    assert!(Pose::from_coords([2.0, 2.0, 1.0, 0.0, 0.0, pi]).rotation.angle_to(&traj.pose_at(0.5).rotation) < 1.0, "through σ = π");
}

#[test]
fn stepping_is_bounded_and_gives_the_same_lattice() {
    let s = Scenario::from_json(CDPR7_TREE).unwrap();
    let whole = Lattice::build(&s, fig310(7));
    let mut l = Lattice::new(&s, fig310(7));
    let mut last = 0;
    loop {
        let p = l.step(3);
        assert!(p.rays_done <= last + 3);
        last = p.rays_done;
        if p.done {
            break;
        }
    }
    assert_eq!(l.rays, whole.rays);
    assert_eq!(l.graph(), whole.graph());
}





#[test]
fn atlas_and_lattice_behind_one_interface() {
    let s = Scenario::from_json(ROBOCRANE).unwrap();
    for kind in [PlannerKind::Atlas, PlannerKind::Lattice] {
        let mut p = planner(&s, "q1-q2", &PlannerOptions::new(kind)).unwrap();
        let mut shown = 0.0;
        let status = loop {
            let progress = p.step(5);
            assert!(progress.fraction >= 0.0 && progress.fraction <= 1.0);
            shown = f64::max(shown, progress.fraction);
            if let Some(st) = progress.done {
                break st;
            }
        };
        assert_eq!(status, PlanStatus::Found, "{kind:?}");
        let traj = p.result(0.0).unwrap().trajectory.expect("a trajectory");
        let r = cablenav::verify::verify_trajectory(&s, &traj).unwrap();
        assert_eq!(r.feasible, vec![[0.0, 1.0]], "{kind:?}: {r:?}");
        if let cablenav::plan::Details::Lattice(d) = p.result(0.0).unwrap().details {
            // The shortest lattice path: θ down to 0 (0.9 rad), φ across at θ = 0 where every φ is
            // the same rotation (cost 0), θ up again (0.9 rad) — the same natively and in wasm32.
            // (A* once recomputed an entry's cost as f − h, which rounding made exceed g: live
            // entries were skipped, giving a longer path natively, 2.753, and no path in wasm32.)
            assert!((d.polyline_length - 1.8).abs() < 1e-9, "{}: {:?}", d.polyline_length, d.polyline);
        }
    }
    assert_eq!(PlannerKind::parse("grid").unwrap_err().field, "--planner");
}

#[test]
fn piecewise_trajectories_are_format_2_and_must_join() {
    let mut v: Value = serde_json::from_str(CDPR7_TREE).unwrap();
    let piece = |a: [f64; 3], b: [f64; 3]| json!({"translation": {"line": [a, b]}, "orientation": {"slerp": ["end", "end"]}});
    v["trajectories"] = json!([{"name": "two", "pieces": [piece([1.5, 2.3, 3.0], [2.0, 2.3, 3.0]), piece([2.0, 2.3, 3.0], [2.0, 2.0, 3.0])]}]);
    let e = Scenario::from_json(&v.to_string()).unwrap_err();
    assert_eq!(e.field, "trajectories[0].pieces");
    assert!(e.reason.contains("cablenav-scenario/2"), "{e}");
    v["format"] = json!("cablenav-scenario/2");
    let s = Scenario::from_json(&v.to_string()).unwrap();
    let t = &s.trajectories[0];
    assert_eq!(t.piece_count(), 2);
    assert!((t.pose_at(0.75).position - nalgebra::Vector3::new(2.0, 2.15, 3.0)).norm() < 1e-12);
    let r = cablenav::verify::verify_trajectory(&s, t).unwrap();
    assert_eq!(r.feasible.first().map(|iv| iv[0]), Some(0.0));
    assert_eq!(r.feasible.last().map(|iv| iv[1]), Some(1.0));
    // a gap between pieces
    v["trajectories"][0]["pieces"][1] = piece([2.0, 2.4, 3.0], [2.0, 2.0, 3.0]);
    let e = Scenario::from_json(&v.to_string()).unwrap_err();
    assert_eq!(e.field, "trajectories[0].pieces[1].translation");
    assert!(e.reason.contains("must join"), "{e}");
    // pieces and translation together
    v["trajectories"][0]["translation"] = json!({"line": [[0, 0, 0], [1, 1, 1]]});
    assert_eq!(Scenario::from_json(&v.to_string()).unwrap_err().field, "trajectories[0].pieces");
}

/// The lattice's components split as the thesis' Table 3.2 discussion needs them
/// (docs/lattice.md): the tree's components at 20 values per axis are the few that hold grid points
/// plus slivers between grid points, and the point-wise grid of the same points finds as many
/// components as the grid points' own (`point_grid`, which checks each point directly); the arm's
/// cables 2–3 gap at 10 values per axis is a separation of grid points the point-wise grid misses
/// (it joins the two sides), at 20 values no longer.
#[test]
fn components_split_into_grid_ones_slivers_and_missed_separations() {
    let s = Scenario::from_json(CDPR7_TREE).unwrap();
    let n = if cfg!(target_arch = "wasm32") { 12 } else { 20 };
    let spec = LatticeSpec::new(vec![Coord::X, Coord::Y, Coord::Z], vec![[0.2, 3.8], [1.1, 2.9], [0.3, 3.7]], vec![n], [2.0016, 2.0, 0.8666666666666667, 0.0, 0.0, 0.0]).unwrap();
    let r = Lattice::build(&s, spec.clone()).report().unwrap();
    assert_eq!(r.grid_components + r.sliver_components, r.components);
    assert!(r.sliver_components > 0 && r.grid_components >= 1, "{} + {}", r.grid_components, r.sliver_components);
    let holding: std::collections::BTreeSet<usize> = r.point_components.iter().flatten().copied().collect();
    assert_eq!(holding.len(), r.grid_components);
    assert_eq!(r.pointwise_components, point_grid(&s, &spec).components);
    assert_eq!(r.missed_separations, r.grid_components - r.pointwise_components);
    let arm = Scenario::from_json(include_str!("../static/multilink/bmarm-x4-2.json")).unwrap();
    let q = arm.config("fig312").unwrap();
    let axes = vec![arm.coord("axes", "alpha").unwrap(), arm.coord("axes", "beta").unwrap()];
    let at = |steps: usize| Lattice::build(&arm, LatticeSpec::new(axes.clone(), vec![[-0.7854, 0.7854]; 2], vec![steps], q.clone()).unwrap()).report().unwrap();
    let coarse = at(10);
    assert_eq!((coarse.grid_components, coarse.pointwise_components, coarse.missed_separations, coarse.sliver_components), (2, 1, 1, 0));
    let fine = at(20);
    assert_eq!((fine.grid_components, fine.pointwise_components, fine.missed_separations), (2, 2, 0));
}
