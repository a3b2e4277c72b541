//! Slice maps on the Robocrane (Bohigas et al. Fig. 5): classes, components, poses on the slice.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::model::{Coord, Pose};
use cablenav::verify::singular::singularity_curves;
use cablenav::verify::slice::Class;
use cablenav::verify::{slice, wrench_at};
use cablenav::Scenario;
use std::f64::consts::PI;

const ROBOCRANE: &str = include_str!("../static/scenarios/robocrane.json");

#[test]
fn robocrane_phi_theta_slice_components() {
    let s = Scenario::from_json(ROBOCRANE).unwrap();
    let res = if cfg!(target_arch = "wasm32") { 100 } else { 200 };
    let m = slice(&s, "q1", [Coord::Phi, Coord::Theta], res, [[-PI, PI], [-PI, PI]]).unwrap();
    let comp = |name: &str| m.pose_components.iter().find(|(n, _)| n == name).unwrap_or_else(|| panic!("{name} not on the slice")).1;
    assert!(comp("q1").is_some() && comp("q1") == comp("q2"), "{:?}", m.pose_components);
    assert!(comp("q3").is_some() && comp("q3") == comp("q4"), "{:?}", m.pose_components);
    assert!(m.pose_components.iter().all(|(n, _)| n != "q5"), "q5 has z = 1.2, off the slice");
    // every cell's class agrees with the per-pose test at its centre
    for j in (0..res).step_by(7) {
        for i in (0..res).step_by(5) {
            let mut c = m.fixed.clone();
            c[3] = m.center(0, i);
            c[4] = m.center(1, j);
            let w = wrench_at(&s, &Pose::from_slice(&c)).unwrap();
            let class = m.classes[j * res + i];
            assert_eq!(class == Class::Feasible, w.feasible, "cell ({i}, {j})");
            assert_eq!(m.component[j * res + i].is_some(), w.feasible);
        }
    }
    let feasible = m.classes.iter().filter(|&&c| c == Class::Feasible).count();
    assert!((m.fraction_feasible - feasible as f64 / (res * res) as f64).abs() < 1e-15);
    assert!(m.components >= 2);
}

#[test]
fn components_are_four_connected_and_maximal() {
    let s = Scenario::from_json(ROBOCRANE).unwrap();
    let res = 80;
    let m = slice(&s, "q1", [Coord::Phi, Coord::Theta], res, [[-PI, PI], [-PI, PI]]).unwrap();
    for j in 0..res {
        for i in 0..res {
            let k = j * res + i;
            // 4-neighbours that are both feasible share a component
            if i + 1 < res && m.component[k].is_some() && m.component[k + 1].is_some() {
                assert_eq!(m.component[k], m.component[k + 1]);
            }
            if j + 1 < res && m.component[k].is_some() && m.component[k + res].is_some() {
                assert_eq!(m.component[k], m.component[k + res]);
            }
        }
    }
    let ids: std::collections::BTreeSet<usize> = m.component.iter().flatten().copied().collect();
    assert_eq!(ids.len(), m.components);
    assert_eq!(ids.iter().copied().max().map_or(0, |x| x + 1), m.components);
}

#[test]
fn slice_png_is_a_png_of_the_grid() {
    let s = Scenario::from_json(ROBOCRANE).unwrap();
    let m = slice(&s, "q1", [Coord::Phi, Coord::Theta], 30, [[-PI, PI], [-PI, PI]]).unwrap();
    let png = m.png();
    assert_eq!(&png[..8], &[0x89, b'P', b'N', b'G', 0x0D, 0x0A, 0x1A, 0x0A]);
    assert_eq!(u32::from_be_bytes(png[16..20].try_into().unwrap()), 30);
    assert_eq!(u32::from_be_bytes(png[20..24].try_into().unwrap()), 30);
}

#[test]
fn bad_slice_requests() {
    let s = Scenario::from_json(ROBOCRANE).unwrap();
    let r = [[-PI, PI], [-PI, PI]];
    assert_eq!(slice(&s, "q1", [Coord::Phi, Coord::Phi], 10, r).unwrap_err().field, "--axes");
    assert_eq!(slice(&s, "q1", [Coord::Phi, Coord::Theta], 0, r).unwrap_err().field, "--res");
    assert_eq!(slice(&s, "q1", [Coord::Phi, Coord::Theta], 100_000, r).unwrap_err().field, "--res");
    assert_eq!(slice(&s, "q1", [Coord::Phi, Coord::Theta], 10, [[1.0, 0.0], [0.0, 1.0]]).unwrap_err().field, "--range");
    assert_eq!(slice(&s, "nobody", [Coord::Phi, Coord::Theta], 10, r).unwrap_err().field, "pose");
}

#[test]
fn a_map_classified_in_row_blocks_is_the_whole_map() {
    use cablenav::verify::slice::{slice_from_classes, slice_rows};
    let s = Scenario::from_json(ROBOCRANE).unwrap();
    let (axes, res, range) = ([Coord::Phi, Coord::Theta], 24, [[-PI, PI], [-PI, PI]]);
    let whole = slice(&s, "q1", axes, res, range).unwrap();
    let mut classes = vec![];
    for rows in [0..5, 5..5, 5..17, 17..24] {
        classes.extend(slice_rows(&s, "q1", axes, res, range, rows).unwrap());
    }
    assert_eq!(slice_from_classes(&s, "q1", axes, res, range, classes).unwrap(), whole);
    assert_eq!(slice_rows(&s, "q1", axes, res, range, 20..25).unwrap_err().field, "rows");
    assert_eq!(slice_from_classes(&s, "q1", axes, res, range, vec![Class::Feasible; 3]).unwrap_err().field, "classes");
}

/// The singularity curves (det J = 0) against the definition, written here: J's columns
/// [e_i; x_i × e_i] from the pose, det by nalgebra. Every curve point is a zero of det J (to 1e-9
/// of the determinant's scale on the slice), and a fine grid's sign changes of det J between
/// neighbouring samples (those with no other within one coarse cell) all lie within two coarse
/// cells of a curve; the curves are long arcs, not cells (paper 1, Fig. 5). A
/// seven-cable robot has none.
#[test]
fn singularity_curves_are_where_det_j_changes_sign() {
    use nalgebra::{Matrix6, Vector6};
    let s = Scenario::from_json(ROBOCRANE).unwrap();
    let (res, fine) = (72, 300);
    let range = [[-PI, PI], [-PI, PI]];
    let curves = singularity_curves(&s, "q1", [Coord::Phi, Coord::Theta], res, range).unwrap();
    let fixed = s.config("q1").unwrap();
    let det = |phi: f64, theta: f64| {
        let mut c = fixed.clone();
        c[3] = phi;
        c[4] = theta;
        let pose = Pose::from_slice(&c);
        let mut j = Matrix6::zeros();
        for (k, cable) in s.robot.cables.iter().enumerate() {
            let x = pose.position + pose.rotation * cable.platform;
            let e = (x - cable.base).normalize();
            let moment = (x - pose.position).cross(&e);
            j.set_column(k, &Vector6::new(e.x, e.y, e.z, moment.x, moment.y, moment.z));
        }
        j.determinant()
    };
    let step = |a: usize, k: usize| range[a][0] + (range[a][1] - range[a][0]) * k as f64 / fine as f64;
    let samples: Vec<Vec<f64>> = (0..=fine).map(|j| (0..=fine).map(|i| det(step(0, i), step(1, j))).collect()).collect();
    let scale = samples.iter().flatten().fold(0.0f64, |a, d| a.max(d.abs()));
    assert!(!curves.is_empty());
    for p in curves.iter().flatten() {
        assert!(det(p[0], p[1]).abs() <= 1e-9 * scale, "det J = {} at {p:?}", det(p[0], p[1]));
    }
    let cell = 2.0 * PI / res as f64;
    let near = |u: f64, v: f64| curves.iter().flatten().any(|p| (p[0] - u).hypot(p[1] - v) <= 2.0 * cell);
    // two crossings within one coarse cell are beyond the coarse grid (module docs): only the
    // isolated ones are required
    let (mut changes, mut missed) = (0, vec![]);
    for j in 0..=fine {
        // a sign change between samples above the rounding noise (det J vanishes identically
        // along θ = ±π, where only noise changes sign)
        let signed = |d: f64| d.abs() > 1e-12 * scale;
        let row: Vec<f64> = (0..fine)
            .filter(|&i| samples[j][i] * samples[j][i + 1] < 0.0 && signed(samples[j][i]) && signed(samples[j][i + 1]))
            .map(|i| 0.5 * (step(0, i) + step(0, i + 1)))
            .collect();
        for (k, &u) in row.iter().enumerate() {
            let paired = row.iter().enumerate().any(|(l, &w)| l != k && (w - u).abs() <= cell);
            if paired {
                continue;
            }
            changes += 1;
            if !near(u, step(1, j)) {
                missed.push((u, step(1, j)));
            }
        }
    }
    assert!(changes > 50, "{changes} isolated sign changes");
    assert!(missed.is_empty(), "{} of {changes} sign changes of det J far from every curve: {:?}", missed.len(), &missed[..missed.len().min(5)]);
    // curves, not dots: the drops of Fig. 5 run across many cells; none along θ = ±π, where
    // det J vanishes identically (the platform upside down)
    assert!(curves.iter().filter(|c| c.len() > 20).count() >= 4);
    assert!(curves.iter().all(|c| c.iter().any(|p| (p[1].abs() - PI).abs() > 1e-9)), "a curve along θ = ±π");
    assert!(det(0.3, PI).abs() <= 1e-12 * scale && det(-2.0, -PI).abs() <= 1e-12 * scale);
    let tree = Scenario::from_json(include_str!("../static/scenarios/cdpr7-tree.json")).unwrap();
    let pose = tree.poses[0].0.clone();
    assert!(singularity_curves(&tree, &pose, [Coord::X, Coord::Y], 8, [[0.5, 3.5], [0.5, 3.5]]).unwrap().is_empty());
    // the arguments are checked as a slice map's
    assert_eq!(singularity_curves(&s, "q1", [Coord::Phi, Coord::Phi], 8, range).unwrap_err().field, "--axes");
}
