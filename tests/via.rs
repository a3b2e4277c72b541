//! Polynomials through via points (the editor's trajectory form): interpolation checked against
//! the points themselves, against Lagrange's formula at other τ, and against known answers.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::model::via::{polynomial_through, via_count, via_points, via_tau, MAX_POINTS};

fn eval(c: &[f64], t: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &a| acc * t + a)
}

/// Lagrange's form at t, an independent reference.
fn lagrange(points: &[[f64; 3]], axis: usize, t: f64) -> f64 {
    let n = points.len();
    (0..n)
        .map(|k| {
            let tk = via_tau(k, n);
            let w: f64 = (0..n).filter(|&j| j != k).map(|j| (t - via_tau(j, n)) / (tk - via_tau(j, n))).product();
            points[k][axis] * w
        })
        .sum()
}

#[test]
fn the_thesis_quadratic_comes_back_from_its_via_points() {
    // trajectory (4.42) in τ: x = 2 − 2.7τ + 2.2τ², y = 1.5 + 0.8τ, z = 1 + 1.2τ + 0.8τ²
    let c = [vec![2.0, -2.7, 2.2], vec![1.5, 0.8], vec![1.0, 1.2, 0.8]];
    assert_eq!(via_count(&c), 3);
    let pts = via_points(&c, 3);
    // the thesis: it passes (1.2, 1.9, 1.8) at τ = 0.5
    for (a, b) in pts[1].iter().zip([1.2, 1.9, 1.8]) {
        assert!((a - b).abs() < 1e-12, "{pts:?}");
    }
    let back = polynomial_through("t", &pts).unwrap();
    for axis in 0..3 {
        assert_eq!(back[axis].len(), c[axis].len(), "degree of axis {axis}: {back:?}");
        for (a, b) in back[axis].iter().zip(&c[axis]) {
            assert!((a - b).abs() < 1e-12, "{back:?}");
        }
    }
}

#[test]
fn interpolation_passes_every_point_and_agrees_with_lagrange() {
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 8.0 - 4.0
    };
    for n in 2..=MAX_POINTS {
        let points: Vec<[f64; 3]> = (0..n).map(|_| [rnd(), rnd(), rnd()]).collect();
        let c = polynomial_through("t", &points).unwrap();
        for axis in 0..3 {
            assert!(c[axis].len() <= n);
            for (k, p) in points.iter().enumerate() {
                let got = eval(&c[axis], via_tau(k, n));
                // the monomial basis loses digits at high degree (coefficients ~1e4 for n = 11)
                assert!((got - p[axis]).abs() < 1e-8, "n {n} axis {axis} point {k}: {got} vs {}", p[axis]);
            }
            for j in 0..=40 {
                let t = j as f64 / 40.0;
                let (a, b) = (eval(&c[axis], t), lagrange(&points, axis, t));
                assert!((a - b).abs() < 1e-7, "n {n} axis {axis} t {t}: {a} vs {b}");
            }
        }
    }
}

#[test]
fn collinear_points_give_a_line_and_equal_points_a_constant() {
    let c = polynomial_through("t", &[[0.0, 1.0, 5.0], [1.0, 1.0, 5.0], [2.0, 1.0, 5.0], [3.0, 1.0, 5.0]]).unwrap();
    assert_eq!(c, [vec![0.0, 3.0], vec![1.0], vec![5.0]]);
}

#[test]
fn bad_input_is_an_error_at_the_field() {
    let e = polynomial_through("trajectories[0].translation", &[[0.0; 3]]).unwrap_err();
    assert_eq!(e.field, "trajectories[0].translation");
    assert!(e.reason.contains("2 to 11"), "{e}");
    assert!(polynomial_through("f", &vec![[0.0; 3]; MAX_POINTS + 1]).is_err());
    let e = polynomial_through("f", &[[0.0; 3], [0.0, f64::NAN, 0.0]]).unwrap_err();
    assert_eq!(e.field, "f[1][1]");
}
