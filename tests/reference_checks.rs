//! Hand-worked checks of the reference geometry (tests/support/reference.rs) that the property
//! tests rely on: closest points at endpoints (anchors), parallel, crossing and degenerate
//! segments, triangles, ellipsoids, cones, slerp and τ(t) — and brute-force comparisons.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

#[allow(dead_code)]
#[path = "support/reference.rs"]
mod reference;

#[allow(dead_code)]
#[path = "support/gen.rs"]
mod gen;

use reference::*;
use std::f64::consts::{FRAC_PI_2, PI};

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

macro_rules! assert_close {
    ($a:expr, $b:expr, $tol:expr) => {{
        let (a, b) = ($a, $b);
        assert!(close(a, b, $tol), "{} = {a:e}, expected {b:e} (tol {:e})", stringify!($a), $tol);
    }};
}

// ----------------------------------------------------------------------------- points, segments

#[test]
fn point_segment_cases() {
    let (a, b) = (v3(0.0, 0.0, 0.0), v3(2.0, 0.0, 0.0));
    assert_close!(point_segment_dist(v3(1.0, 3.0, 4.0), a, b), 5.0, 1e-15); // interior foot
    assert_close!(point_segment_dist(v3(-3.0, 4.0, 0.0), a, b), 5.0, 1e-15); // before a
    assert_close!(point_segment_dist(v3(5.0, 0.0, 4.0), a, b), 5.0, 1e-15); // after b
    assert_close!(point_segment_dist(v3(1.0, 0.0, 0.0), a, b), 0.0, 0.0); // on it
    assert_close!(point_segment_dist(v3(3.0, 4.0, 0.0), a, a), 5.0, 1e-15); // degenerate segment
}

#[test]
fn crossing_segments_have_distance_zero() {
    let d = segment_segment_dist(v3(-1.0, 0.0, 0.0), v3(1.0, 0.0, 0.0), v3(0.0, -1.0, 0.0), v3(0.0, 1.0, 0.0));
    assert_close!(d, 0.0, 1e-16);
    // crossing off-centre, in a tilted plane
    let d = segment_segment_dist(v3(0.0, 0.0, 0.0), v3(4.0, 2.0, 2.0), v3(0.0, 2.0, 1.0), v3(4.0, 0.0, 1.0));
    assert_close!(d, 0.0, 1e-15);
}

#[test]
fn skew_segments_interior_closest_points() {
    // x-axis segment and a y-parallel segment 3 above it
    let d = segment_segment_dist(v3(-1.0, 0.0, 0.0), v3(1.0, 0.0, 0.0), v3(0.5, -1.0, 3.0), v3(0.5, 1.0, 3.0));
    assert_close!(d, 3.0, 1e-15);
    // general skew lines: distance = |(p0−q0)·(d1×d2)| / |d1×d2| when the feet are interior
    let (p0, p1, q0, q1) = (v3(-1.0, -1.0, 0.0), v3(1.0, 1.0, 0.2), v3(1.0, -1.0, 1.0), v3(-1.0, 1.0, 0.8));
    let n = (p1 - p0).cross(q1 - q0);
    let expect = (p0 - q0).dot(n).abs() / n.norm();
    assert_close!(segment_segment_dist(p0, p1, q0, q1), expect, 1e-15);
}

#[test]
fn endpoint_closest_points() {
    // T configuration: q's endpoint q0 is closest to p's interior
    let d = segment_segment_dist(v3(-1.0, 0.0, 0.0), v3(1.0, 0.0, 0.0), v3(0.3, 0.5, 0.0), v3(0.3, 3.0, 0.0));
    assert_close!(d, 0.5, 1e-15);
    // endpoint–endpoint (anchors): two cables diverging from nearby anchors
    let d = segment_segment_dist(v3(0.0, 0.0, 0.0), v3(-1.0, -1.0, 0.0), v3(0.3, 0.4, 0.0), v3(1.0, 2.0, 0.5));
    assert_close!(d, 0.5, 1e-15);
    // lines cross beyond the segments: closest is an endpoint to the other's interior
    let d = segment_segment_dist(v3(1.0, 0.0, 0.0), v3(3.0, 0.0, 0.0), v3(0.0, -1.0, 0.0), v3(0.0, 1.0, 0.0));
    assert_close!(d, 1.0, 1e-15);
    // both feet clamped: lines cross, but both segments end before the crossing
    let d = segment_segment_dist(v3(1.0, 0.0, 0.0), v3(3.0, 0.0, 0.0), v3(0.0, 1.0, 0.0), v3(0.0, 3.0, 0.0));
    assert_close!(d, 2f64.sqrt(), 1e-15);
    // two cables sharing a platform-side anchor point meet there
    let d = segment_segment_dist(v3(-2.0, 2.0, 2.0), v3(0.1, 0.2, 0.3), v3(2.0, 2.0, 2.0), v3(0.1, 0.2, 0.3));
    assert_close!(d, 0.0, 1e-15);
}

#[test]
fn parallel_segments() {
    // overlapping, 0.25 apart
    let d = segment_segment_dist(v3(0.0, 0.0, 0.0), v3(2.0, 0.0, 0.0), v3(1.0, 0.25, 0.0), v3(3.0, 0.25, 0.0));
    assert_close!(d, 0.25, 1e-15);
    // anti-parallel, overlapping
    let d = segment_segment_dist(v3(0.0, 0.0, 0.0), v3(2.0, 0.0, 0.0), v3(3.0, 0.0, 0.25), v3(1.0, 0.0, 0.25));
    assert_close!(d, 0.25, 1e-15);
    // collinear with a gap
    let d = segment_segment_dist(v3(0.0, 0.0, 0.0), v3(1.0, 0.0, 0.0), v3(1.5, 0.0, 0.0), v3(4.0, 0.0, 0.0));
    assert_close!(d, 0.5, 1e-15);
    // parallel, not overlapping: endpoint to endpoint
    let d = segment_segment_dist(v3(0.0, 0.0, 0.0), v3(1.0, 0.0, 0.0), v3(4.0, 4.0, 0.0), v3(5.0, 4.0, 0.0));
    assert_close!(d, 5.0, 1e-15);
    // nearly parallel (1e-12 tilt)
    let d = segment_segment_dist(v3(0.0, 0.0, 0.0), v3(2.0, 0.0, 0.0), v3(0.5, 0.3, 0.0), v3(1.5, 0.3, 1e-12));
    assert_close!(d, 0.3, 1e-14);
}

#[test]
fn degenerate_segments() {
    let p = v3(1.0, 1.0, 1.0);
    assert_close!(segment_segment_dist(p, p, v3(0.0, 0.0, 0.0), v3(2.0, 0.0, 0.0)), 2f64.sqrt(), 1e-15);
    assert_close!(segment_segment_dist(v3(0.0, 0.0, 0.0), v3(2.0, 0.0, 0.0), p, p), 2f64.sqrt(), 1e-15);
    assert_close!(segment_segment_dist(p, p, v3(1.0, 4.0, 5.0), v3(1.0, 4.0, 5.0)), 5.0, 1e-15);
}

/// Brute force: minimum over a fine grid, refined locally (a convex function of (s, t)).
fn brute_segment_segment(p0: V3, p1: V3, q0: V3, q1: V3) -> f64 {
    let f = |s: f64, t: f64| (p0 + (p1 - p0) * s - (q0 + (q1 - q0) * t)).norm();
    let n = 200;
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for i in 0..=n {
        for j in 0..=n {
            let (s, t) = (i as f64 / n as f64, j as f64 / n as f64);
            let v = f(s, t);
            if v < best.0 {
                best = (v, s, t);
            }
        }
    }
    // coordinate descent refinement
    let (mut s, mut t) = (best.1, best.2);
    for _ in 0..60 {
        s = golden_arg(|x| f(x, t), 0.0, 1.0);
        t = golden_arg(|y| f(s, y), 0.0, 1.0);
    }
    f(s, t).min(best.0)
}

fn golden_arg(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let r = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..100 {
        let c = b - r * (b - a);
        let d = a + r * (b - a);
        if f(c) < f(d) {
            b = d
        } else {
            a = c
        }
    }
    0.5 * (a + b)
}

#[test]
fn segment_segment_matches_brute_force() {
    let mut rng = Rng::new(1);
    for k in 0..300 {
        let (p0, p1) = (rng.in_box(1.0), rng.in_box(1.0));
        let (q0, mut q1) = (rng.in_box(1.0), rng.in_box(1.0));
        if k % 5 == 0 {
            q1 = q0 + (p1 - p0) * rng.range(-1.5, 1.5); // parallel
        }
        let d = segment_segment_dist(p0, p1, q0, q1);
        let b = brute_segment_segment(p0, p1, q0, q1);
        // the reference is a distance between actual points, so never below the true minimum
        assert!(d <= b + 1e-12, "case {k}: reference {d} > brute {b}");
        assert!(d >= b - 1e-6, "case {k}: reference {d} < brute {b}");
    }
}

// ----------------------------------------------------------------------------- triangles

#[test]
fn point_triangle_cases() {
    let tri = [v3(0.0, 0.0, 0.0), v3(2.0, 0.0, 0.0), v3(0.0, 2.0, 0.0)];
    assert_close!(point_triangle_dist(v3(0.5, 0.5, 3.0), &tri), 3.0, 1e-15); // above the interior
    assert_close!(point_triangle_dist(v3(0.5, 0.5, -3.0), &tri), 3.0, 1e-15); // below
    assert_close!(point_triangle_dist(v3(-3.0, -4.0, 0.0), &tri), 5.0, 1e-15); // beyond vertex 0
    assert_close!(point_triangle_dist(v3(1.0, -1.0, 1.0), &tri), 2f64.sqrt(), 1e-15); // beyond edge 01
    assert_close!(point_triangle_dist(v3(2.0, 2.0, 0.0), &tri), 2f64.sqrt(), 1e-15); // beyond hypotenuse
    assert_close!(point_triangle_dist(v3(0.5, 0.5, 0.0), &tri), 0.0, 0.0); // inside
}

#[test]
fn segment_triangle_cases() {
    let tri = [v3(0.0, 0.0, 0.0), v3(2.0, 0.0, 0.0), v3(0.0, 2.0, 0.0)];
    // crossing the interior
    let (a, b) = (v3(0.5, 0.5, -1.0), v3(0.5, 0.5, 1.0));
    assert!(segment_crosses_triangle(a, b, &tri).is_some());
    assert_close!(segment_triangle_dist(a, b, &tri), 0.0, 0.0);
    assert_close!(segment_crosses_triangle(a, b, &tri).unwrap(), 0.5, 1e-15); // depth: edge distance
                                                                              // passing beside it (the line meets the plane outside the triangle)
    let (a, b) = (v3(3.0, 3.0, -1.0), v3(3.0, 3.0, 1.0));
    assert!(segment_crosses_triangle(a, b, &tri).is_none());
    assert_close!(segment_triangle_dist(a, b, &tri), (2.0f64 * 4.0 * 4.0).sqrt() / 2.0, 1e-15);
    // ending above the interior (anchor closest)
    let (a, b) = (v3(0.5, 0.5, 0.3), v3(0.5, 0.5, 5.0));
    assert_close!(segment_triangle_dist(a, b, &tri), 0.3, 1e-15);
    // parallel to the plane, above it
    let (a, b) = (v3(-1.0, 0.5, 0.2), v3(3.0, 0.5, 0.2));
    assert_close!(segment_triangle_dist(a, b, &tri), 0.2, 1e-15);
    // in the plane, crossing an edge
    let (a, b) = (v3(-1.0, 0.5, 0.0), v3(0.5, 0.5, 0.0));
    assert_close!(segment_triangle_dist(a, b, &tri), 0.0, 0.0);
    // skew to an edge, closest to the edge's interior
    let (a, b) = (v3(1.0, -1.0, -1.0), v3(1.0, -1.0, 1.0));
    assert_close!(segment_triangle_dist(a, b, &tri), 1.0, 1e-15);
    // touching at an endpoint exactly on the triangle
    let (a, b) = (v3(0.5, 0.5, 0.0), v3(0.5, 0.5, 1.0));
    assert_close!(segment_triangle_dist(a, b, &tri), 0.0, 0.0);
}

#[test]
fn segment_triangle_matches_brute_force() {
    let mut rng = Rng::new(2);
    for k in 0..200 {
        let tri = [rng.in_box(1.0), rng.in_box(1.0), rng.in_box(1.0)];
        let (p0, p1) = (rng.in_box(1.5), rng.in_box(1.5));
        let d = segment_triangle_dist(p0, p1, &tri);
        // brute force: segment samples to the triangle (point–triangle is checked above), and the
        // triangle's sampled points to the segment
        let n = 2000;
        let mut b = f64::INFINITY;
        for i in 0..=n {
            let s = i as f64 / n as f64;
            b = b.min(point_triangle_dist(p0 + (p1 - p0) * s, &tri));
        }
        assert!(d <= b + 1e-12, "case {k}: {d} > {b}");
        // sampling error: step |p1 − p0| / n
        assert!(d >= b - (p1 - p0).norm() / n as f64, "case {k}: {d} < {b}");
        if segment_crosses_triangle(p0, p1, &tri).is_some() {
            assert!(b <= (p1 - p0).norm() / n as f64);
        }
    }
}

#[test]
fn box_triangles_cover_the_box_surface() {
    let tris = box_triangles(v3(1.0, 2.0, 3.0), v3(2.0, 4.0, 6.0));
    assert_eq!(tris.len(), 12);
    let area: f64 = tris.iter().map(|t| (t[1] - t[0]).cross(t[2] - t[0]).norm() / 2.0).sum();
    assert_close!(area, 2.0 * (2.0 * 4.0 + 4.0 * 6.0 + 2.0 * 6.0), 1e-12);
    // a segment through the box crosses two faces; one outside crosses none
    let crossings = |a: V3, b: V3| tris.iter().filter(|t| segment_crosses_triangle(a, b, t).is_some()).count();
    assert!(crossings(v3(1.0, 2.0, -5.0), v3(1.3, 2.2, 10.0)) >= 2);
    assert_eq!(crossings(v3(5.0, 2.0, -5.0), v3(5.0, 2.2, 10.0)), 0);
    // distance from a point outside a face
    let d = tris
        .iter()
        .map(|t| segment_triangle_dist(v3(1.0, 2.0, 7.0), v3(1.5, 2.5, 9.0), t))
        .fold(f64::INFINITY, f64::min);
    assert_close!(d, 1.0, 1e-15);
}

// ----------------------------------------------------------------------------- ellipsoids

#[test]
fn matrix_inverse_and_determinant() {
    let m = [[4.0, 1.0, 0.5], [1.0, 3.0, 0.2], [0.5, 0.2, 2.0]];
    let i = inv3(&m);
    let p = mat_mul(&m, &i);
    for (r, row) in p.iter().enumerate() {
        for (c, x) in row.iter().enumerate() {
            assert_close!(*x, if r == c { 1.0 } else { 0.0 }, 1e-14);
        }
    }
    assert_close!(det3(&[[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.0]]), 24.0, 0.0);
}

#[test]
fn ellipsoid_metric_minimum() {
    // axis-aligned semi-axes (1, 2, 0.5)
    let m = [[1.0, 0.0, 0.0], [0.0, 0.25, 0.0], [0.0, 0.0, 4.0]];
    let c = v3(0.0, 0.0, 0.0);
    // a segment parallel to x at z = 1: min q = (1/0.5)² = 4 at x = 0
    let (q, s) = segment_metric_min(v3(-3.0, 0.0, 1.0), v3(1.0, 0.0, 1.0), c, &m);
    assert_close!(q, 4.0, 1e-15);
    assert_close!(s, 0.75, 1e-15);
    // endpoint closest (anchor): the segment stops before the axis
    let (q, s) = segment_metric_min(v3(3.0, 0.0, 0.0), v3(6.0, 0.0, 0.0), c, &m);
    assert_close!(q, 9.0, 1e-15);
    assert_eq!(s, 0.0);
    // degenerate segment
    let (q, _) = segment_metric_min(v3(0.0, 2.0, 0.0), v3(0.0, 2.0, 0.0), c, &m);
    assert_close!(q, 1.0, 1e-15);
}

/// The nearest point of the ellipsoid, found by brute force over a fine grid of its surface
/// (then refined), agrees with the dual formula.
#[test]
fn ellipsoid_distance_matches_surface_search() {
    let mut rng = Rng::new(3);
    let rot = quat_to_matrix(quat_axis_angle(rng.unit_vector(), 1.0));
    let d = [0.2, 0.5, 0.9];
    let mut m = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] = (0..3).map(|k| rot[i][k] * rot[j][k] / (d[k] * d[k])).sum();
        }
    }
    let center = v3(0.3, -0.2, 0.1);
    let surface = |th: f64, ph: f64| {
        let local = v3(d[0] * th.sin() * ph.cos(), d[1] * th.sin() * ph.sin(), d[2] * th.cos());
        center + mat_vec(&rot, local)
    };
    for _ in 0..40 {
        let x = center + rng.unit_vector() * rng.range(0.0, 2.0);
        let want = ellipsoid_point_dist(x, center, &m);
        if quad_form(&m, x - center) <= 1.0 {
            assert_eq!(want, 0.0);
            continue;
        }
        let (mut best, mut at) = (f64::INFINITY, (0.0, 0.0));
        let n = 200;
        for i in 0..=n {
            for j in 0..2 * n {
                let (th, ph) = (PI * i as f64 / n as f64, PI * j as f64 / n as f64);
                let dd = (surface(th, ph) - x).norm();
                if dd < best {
                    best = dd;
                    at = (th, ph);
                }
            }
        }
        // refine around the best grid point
        let mut step = PI / n as f64;
        for _ in 0..60 {
            for (a, b) in [(step, 0.0), (-step, 0.0), (0.0, step), (0.0, -step)] {
                let dd = (surface(at.0 + a, at.1 + b) - x).norm();
                if dd < best {
                    best = dd;
                    at = (at.0 + a, at.1 + b);
                }
            }
            step *= 0.7;
        }
        assert_close!(want, best, 1e-9);
    }
}

#[test]
fn cylinder_signed_distance_cases() {
    let (p, q) = (v3(0.0, 0.0, 0.0), v3(0.0, 0.0, 2.0));
    assert_close!(cylinder_sdf(v3(3.0, 0.0, 1.0), p, q, 1.0), 2.0, 1e-15);
    assert_close!(cylinder_sdf(v3(0.0, 0.5, 3.0), p, q, 1.0), 1.0, 1e-15);
    assert_close!(cylinder_sdf(v3(0.0, 4.0, -4.0), p, q, 1.0), 5.0, 1e-15);
    assert_close!(cylinder_sdf(v3(0.0, 0.7, 1.0), p, q, 1.0), -0.3, 1e-15);
    assert_close!(cylinder_sdf(v3(0.0, 0.0, 0.2), p, q, 1.0), -0.2, 1e-15);
}

// ----------------------------------------------------------------------------- cones

fn unit_cone() -> SolidCone {
    // apex at the origin, axis +z, 45°, height 1
    SolidCone { apex: v3(0.0, 0.0, 0.0), axis: v3(0.0, 0.0, 1.0), half_angle: PI / 4.0, height: 1.0 }
}

#[test]
fn cone_segment_cases() {
    let k = unit_cone();
    // through the solid along the axis
    assert!(k.meets_segment(v3(0.0, 0.0, -1.0), v3(0.0, 0.0, 2.0)));
    // horizontal at z = 0.5, passing at radius 0.4 (< 0.5): meets; at radius 0.6: misses
    assert!(k.meets_segment(v3(-2.0, 0.4, 0.5), v3(2.0, 0.4, 0.5)));
    assert!(!k.meets_segment(v3(-2.0, 0.6, 0.5), v3(2.0, 0.6, 0.5)));
    // above the base plane: misses even though inside the infinite cone
    assert!(!k.meets_segment(v3(-0.1, 0.0, 1.2), v3(0.1, 0.0, 1.5)));
    // below the apex, in the mirrored (lower) nappe: misses
    assert!(!k.meets_segment(v3(-0.1, 0.0, -0.5), v3(0.1, 0.0, -0.5)));
    // crossing the base disc from above to outside: meets
    assert!(k.meets_segment(v3(0.3, 0.0, 1.5), v3(0.3, 0.0, 0.9)));
    // ending just outside the lateral surface (anchor closest)
    assert!(!k.meets_segment(v3(0.55, 0.0, 0.5), v3(3.0, 0.0, 0.5)));
    assert!(k.meets_segment(v3(0.45, 0.0, 0.5), v3(3.0, 0.0, 0.5)));
    // a single point inside / outside
    assert!(k.meets_segment(v3(0.1, 0.1, 0.5), v3(0.1, 0.1, 0.5)));
    assert!(!k.meets_segment(v3(0.5, 0.5, 0.5), v3(0.5, 0.5, 0.5)));
    // phi: signed distance to the lateral surface inside, and to the base plane
    assert_close!(k.phi(v3(0.0, 0.0, 0.5)), -0.5 * FRAC_PI_2.sin() * (PI / 4.0).sin(), 1e-15);
    assert_close!(k.phi(v3(0.0, 0.0, 1.25)), 0.25, 1e-15);
    assert_close!(k.phi(v3(1.0, 0.0, 0.0)), (PI / 4.0).cos(), 1e-15);
}

/// The cone's signed distance against brute force over its surface (lateral grid and base disc).
#[test]
fn cone_signed_distance_matches_surface_search() {
    let k = unit_cone();
    let mut rng = Rng::new(4);
    let n = 400;
    let mut surface = Vec::new();
    for i in 0..=n {
        let h = i as f64 / n as f64;
        for j in 0..n {
            let ph = 2.0 * PI * j as f64 / n as f64;
            surface.push(v3(h * ph.cos(), h * ph.sin(), h)); // lateral (tan 45° = 1)
            surface.push(v3(h * ph.cos(), h * ph.sin(), 1.0)); // base disc
        }
    }
    for _ in 0..60 {
        let p = v3(rng.range(-1.5, 1.5), rng.range(-1.5, 1.5), rng.range(-0.8, 1.8));
        let best = surface.iter().map(|s| (*s - p).norm()).fold(f64::INFINITY, f64::min);
        let d = k.sdf(p);
        // grid spacing 2π/400 at radius ≤ 1: within 0.016 of the true surface distance
        assert!((d.abs() - best).abs() < 0.02, "{p:?}: sdf {d}, surface {best}");
        assert_eq!(d <= 0.0, k.phi(p) <= 0.0, "{p:?}");
    }
}

#[test]
fn cone_meets_agrees_with_phi_and_sampling() {
    let mut rng = Rng::new(5);
    let mut hits = 0;
    for i in 0..2000 {
        let k = SolidCone {
            apex: rng.in_box(0.5),
            axis: rng.unit_vector(),
            half_angle: rng.range(0.2, 1.2),
            height: rng.range(0.2, 1.0),
        };
        let (p0, p1) = (rng.in_box(1.5), rng.in_box(1.5));
        let meets = k.meets_segment(p0, p1);
        let m = k.segment_phi_min(p0, p1);
        if m.abs() > 1e-9 {
            assert_eq!(meets, m < 0.0, "case {i}: meets {meets} but phi min {m}");
        }
        // sampling can only find a point inside when the exact test says it meets
        let n = 500;
        let sampled = (0..=n).any(|j| k.phi(p0 + (p1 - p0) * (j as f64 / n as f64)) < -1e-12);
        if sampled {
            assert!(meets, "case {i}: a sample is inside");
        }
        hits += usize::from(meets);
    }
    assert!(hits > 200 && hits < 1800, "a useful mix of cases ({hits})");
}

// ----------------------------------------------------------------------------- orientation

#[test]
fn quaternion_matrix() {
    let q = quat_axis_angle(v3(0.0, 0.0, 1.0), FRAC_PI_2);
    let r = quat_to_matrix(q);
    let x = mat_vec(&r, v3(1.0, 0.0, 0.0));
    assert_close!(x.x, 0.0, 1e-15);
    assert_close!(x.y, 1.0, 1e-15);
    let y = mat_vec(&r, v3(0.0, 1.0, 0.0));
    assert_close!(y.x, -1.0, 1e-15);
    // orthonormal for a random quaternion (unnormalised input is normalised)
    let mut rng = Rng::new(6);
    let q = [rng.normal(), rng.normal(), rng.normal(), rng.normal()];
    let r = quat_to_matrix(q);
    let p = mat_mul(&r, &transpose(&r));
    for (i, row) in p.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            assert_close!(*x, if i == j { 1.0 } else { 0.0 }, 1e-14);
        }
    }
    assert_close!(det3(&r), 1.0, 1e-14);
    // a quaternion and its negative give the same rotation
    let rn = quat_to_matrix([-q[0], -q[1], -q[2], -q[3]]);
    for i in 0..3 {
        for j in 0..3 {
            assert_close!(r[i][j], rn[i][j], 1e-15);
        }
    }
}

#[test]
fn slerp_and_tau() {
    let qs = quat_axis_angle(v3(1.0, 0.0, 0.0), 0.3);
    let qe = quat_mul(qs, quat_axis_angle(v3(0.0, 0.0, 1.0), 1.2));
    let theta = slerp_angle(qs, qe);
    assert_close!(theta, 0.6, 1e-15); // half the relative rotation angle
    for (a, b) in slerp(qs, qe, 0.0).iter().zip(qs) {
        assert_close!(*a, b, 1e-15);
    }
    for (a, b) in slerp(qs, qe, 1.0).iter().zip(qe) {
        assert_close!(*a, b, 1e-15);
    }
    // constant angular speed: the midpoint rotates by half the angle
    let mid = slerp(qs, qe, 0.5);
    for (a, b) in mid.iter().zip(quat_mul(qs, quat_axis_angle(v3(0.0, 0.0, 1.0), 0.6))) {
        assert_close!(*a, b, 1e-15);
    }
    // τ(0) = 0, τ(1) = 1, monotone, τ = t when θ = 0
    assert_close!(tau_of_t(theta, 0.0), 0.0, 0.0);
    assert_close!(tau_of_t(theta, 1.0), 1.0, 1e-15);
    assert_close!(tau_of_t(theta, 0.5), (0.15f64).tan() / (0.3f64).tan(), 1e-15);
    assert_eq!(tau_of_t(0.0, 0.37), 0.37);
    assert_eq!(slerp_angle(qs, qs), 0.0);
    // long way round: the sign is kept as given
    let qen = [-qe[0], -qe[1], -qe[2], -qe[3]];
    assert_close!(slerp_angle(qs, qen), PI - 0.6, 1e-15);
    let m = slerp(qs, qen, 0.5);
    // halfway the long way = rotated by (2π − 1.2)/2 = π − 0.6 about z relative to qs
    let expect = quat_mul(qs, quat_axis_angle(v3(0.0, 0.0, -1.0), PI - 0.6));
    let same = (0..4).all(|i| close(m[i], expect[i], 1e-14)) || (0..4).all(|i| close(m[i], -expect[i], 1e-14));
    assert!(same, "{m:?} vs {expect:?}");
}

#[test]
fn trajectory_pose_evaluation() {
    let traj = RefTrajectory {
        name: "t".into(),
        translation: RefTranslation::Polynomial([vec![1.0, 2.0, 3.0], vec![0.0], vec![-1.0, 0.0, 0.0, 4.0]]),
        qs: [1.0, 0.0, 0.0, 0.0],
        qe: [1.0, 0.0, 0.0, 0.0],
    };
    let (p, r) = traj.pose(0.5);
    assert_close!(p.x, 1.0 + 1.0 + 0.75, 1e-15);
    assert_close!(p.y, 0.0, 0.0);
    assert_close!(p.z, -1.0 + 0.5, 1e-15);
    assert_eq!(r, quat_to_matrix([1.0, 0.0, 0.0, 0.0]));
    // Bézier and the equivalent polynomial agree
    let mut rng = Rng::new(7);
    let pts: Vec<V3> = (0..6).map(|_| rng.in_box(1.0)).collect();
    let a = RefTranslation::Bezier(pts.clone());
    // the generator's conversion, which the property tests use to write Bézier trajectories
    let b = RefTranslation::Polynomial(gen::bezier_to_monomial(&pts));
    for i in 0..=10 {
        let tau = i as f64 / 10.0;
        assert!((a.at(tau) - b.at(tau)).norm() < 1e-13);
    }
    assert_eq!(a.at(0.0), pts[0]);
    assert!((a.at(1.0) - pts[5]).norm() < 1e-15);
    let l = RefTranslation::Line(v3(0.0, 0.0, 0.0), v3(2.0, 4.0, 6.0));
    assert_eq!(l.at(0.25), v3(0.5, 1.0, 1.5));
}

// ----------------------------------------------------------------------------- whole conditions

#[test]
fn conditions_on_a_small_robot() {
    // two cables from the ceiling to a point platform-ish layout, one sphere
    let sc = RefScenario {
        name: "small".into(),
        cables: vec![
            (v3(-2.0, 0.0, 2.0), v3(-0.1, 0.0, 0.0)),
            (v3(2.0, 0.0, 2.0), v3(0.1, 0.0, 0.0)),
            (v3(0.0, 2.0, 2.0), v3(0.0, 0.1, 0.0)),
            (v3(-2.0, 0.0, 2.0), v3(0.0, -0.1, 0.0)), // shares a base anchor with cable 1
        ],
        length: Some((1.0, 3.0)),
        cable_cable: 0.15,
        cable_obstacle: 0.05,
        obstacles: vec![RefObstacle {
            name: "ball".into(),
            shape: RefShape::Sphere { center: v3(0.0, 0.0, 3.0), radius: 0.5 },
        }],
        trajectories: vec![RefTrajectory {
            name: "lift".into(),
            translation: RefTranslation::Line(v3(0.0, 0.0, 0.0), v3(0.0, 0.0, 1.0)),
            qs: [1.0, 0.0, 0.0, 0.0],
            qe: [1.0, 0.0, 0.0, 0.0],
        }],
    };
    let ev = sc.evaluator();
    assert!(!ev.pairs.contains(&(0, 3)));
    assert_eq!(ev.pairs.len(), 5);
    let checks = ev.checks(0, 0.0);
    let get = |l: &str| checks.iter().find(|c| c.label == l).unwrap_or_else(|| panic!("{l}"));
    // at the start the platform anchors of cables 1 and 2 are 0.2 apart (closest at the anchors)
    assert_close!(get("cable 1 - cable 2").margin, 0.2 - 0.15, 1e-15);
    assert!(!get("cable 1 - cable 2").violated);
    // cable 1 length = |(-0.1,0,0) − (−2,0,2)| = sqrt(1.9² + 4)
    let l1 = (1.9f64 * 1.9 + 4.0).sqrt();
    assert_close!(get("cable 1 length").margin, (3.0 - l1).min(l1 - 1.0), 1e-15);
    // sphere: distance from (0,0,3) to cable 3 (segment (0,2,2)–(0,0.1,0))
    let d = point_segment_dist(v3(0.0, 0.0, 3.0), v3(0.0, 2.0, 2.0), v3(0.0, 0.1, 0.0));
    assert_close!(get("cable 3 - ball").margin, d - 0.55, 1e-15);
    // cables 1 and 3 end 0.1·√2 < 0.15 apart: violated, closest at the platform anchors
    assert_close!(get("cable 1 - cable 3").margin, 0.02f64.sqrt() - 0.15, 1e-15);
    assert!(get("cable 1 - cable 3").violated);
    assert!(!ev.feasible(0, 0.0));
    // at the top, cables are shorter than 3 still, but the ball (reach 0.55 to z = 2.45) is
    // closer to the cables
    let top = ev.checks(0, 1.0);
    let feasible = top.iter().all(|c| !c.violated);
    assert_eq!(ev.feasible(0, 1.0), feasible);
}
