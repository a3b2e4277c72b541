//! Point-wise geometric queries for one pose: distances between cable segments, points,
//! triangles, and membership tests against solid shapes. Free functions over plain vectors.

pub mod cables;
pub mod facets;
pub mod lp;
pub mod wrench;
pub mod zonotope;

use nalgebra::{Matrix3, Vector3};

type V = Vector3<f64>;

/// Squared distance, in the metric of SPD matrix `g` ((x)ᵀG(x); `None` = Euclidean), from point
/// `p` to the segment a → a + s.
pub fn point_segment_dist2(p: &V, a: &V, s: &V, g: Option<&Matrix3<f64>>) -> f64 {
    let dot = |x: &V, y: &V| match g {
        Some(g) => x.dot(&(g * y)),
        None => x.dot(y),
    };
    let e = p - a;
    let ss = dot(s, s);
    let lam = if ss > 0.0 { (dot(&e, s) / ss).clamp(0.0, 1.0) } else { 0.0 };
    let d = e - s * lam;
    dot(&d, &d)
}

/// Distance between the segments a → a + s and b → b + t (parallel and degenerate segments
/// included): the least of the interior critical pair, when it lies inside both segments, and
/// the four endpoint-to-segment distances.
pub fn segment_segment_dist(a: &V, s: &V, b: &V, t: &V) -> f64 {
    let mut best = point_segment_dist2(b, a, s, None)
        .min(point_segment_dist2(&(b + t), a, s, None))
        .min(point_segment_dist2(a, b, t, None))
        .min(point_segment_dist2(&(a + s), b, t, None));
    let n = s.cross(t);
    let d = n.norm_squared();
    if d > 1e-24 * s.norm_squared() * t.norm_squared() {
        let r = b - a;
        let u = r.cross(t).dot(&n) / d;
        let v = r.cross(s).dot(&n) / d;
        if (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v) {
            best = best.min((a + s * u - b - t * v).norm_squared());
        }
    }
    best.sqrt()
}

/// Whether the segment a → a + s crosses the triangle's interior (a proper crossing).
pub fn segment_crosses_triangle(a: &V, s: &V, tri: &[V; 3]) -> bool {
    let n = (tri[1] - tri[0]).cross(&(tri[2] - tri[0]));
    let (o0, o1) = (n.dot(&(a - tri[0])), n.dot(&(a + s - tri[0])));
    if o0 * o1 >= 0.0 {
        return false;
    }
    let vol = |k: usize| (tri[k] - a).cross(&(tri[(k + 1) % 3] - a)).dot(s);
    let (v0, v1, v2) = (vol(0), vol(1), vol(2));
    (v0 > 0.0 && v1 > 0.0 && v2 > 0.0) || (v0 < 0.0 && v1 < 0.0 && v2 < 0.0)
}

/// Distance from point p to the (closed) triangle.
pub fn point_triangle_dist(p: &V, tri: &[V; 3]) -> f64 {
    let n = (tri[1] - tri[0]).cross(&(tri[2] - tri[0]));
    let nn = n.norm_squared();
    let inside = (0..3).all(|k| n.cross(&(tri[(k + 1) % 3] - tri[k])).dot(&(p - tri[k])) >= 0.0);
    if inside && nn > 0.0 {
        return (p - tri[0]).dot(&n).abs() / nn.sqrt();
    }
    (0..3)
        .map(|k| point_segment_dist2(p, &tri[k], &(tri[(k + 1) % 3] - tri[k]), None))
        .fold(f64::INFINITY, f64::min)
        .sqrt()
}

/// Distance from the segment a → a + s to the triangle (0 when it crosses it).
pub fn segment_triangle_dist(a: &V, s: &V, tri: &[V; 3]) -> f64 {
    if segment_crosses_triangle(a, s, tri) {
        return 0.0;
    }
    let edges = (0..3).map(|k| segment_segment_dist(a, s, &tri[k], &(tri[(k + 1) % 3] - tri[k])));
    let ends = [point_triangle_dist(a, tri), point_triangle_dist(&(a + s), tri)];
    edges.chain(ends).fold(f64::INFINITY, f64::min)
}

/// Whether the segment a → a + s meets the solid truncated cone with the given apex, unit axis,
/// cos² of the half-angle and height: {x : (x−A)·u ≥ |x−A| cos α, (x−A)·u ≤ H}.
pub fn segment_meets_cone(a: &V, s: &V, apex: &V, axis: &V, cos2: f64, height: f64) -> bool {
    // Restrict the segment parameter to the slab 0 ≤ g(λ) ≤ H, then maximise the quadratic
    // f(λ) = g² − cos²α |x − A|² over what is left: the segment meets the cone iff the max ≥ 0.
    let e = a - apex;
    let (g0, g1) = (e.dot(axis), s.dot(axis));
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    if g1.abs() < 1e-300 {
        if g0 < 0.0 || g0 > height {
            return false;
        }
    } else {
        let (l0, l1) = ((0.0 - g0) / g1, (height - g0) / g1);
        lo = lo.max(l0.min(l1));
        hi = hi.min(l0.max(l1));
        if lo > hi {
            return false;
        }
    }
    let c2 = g1 * g1 - cos2 * s.norm_squared();
    let c1 = 2.0 * (g0 * g1 - cos2 * e.dot(s));
    let c0 = g0 * g0 - cos2 * e.norm_squared();
    let f = |lam: f64| c0 + lam * (c1 + lam * c2);
    let mut best = f(lo).max(f(hi));
    if c2 < 0.0 {
        let v = -c1 / (2.0 * c2);
        if v > lo && v < hi {
            best = best.max(f(v));
        }
    }
    best >= 0.0
}

/// Distance from point p to the solid finite cylinder with end-face centres `from`, `to` and
/// radius r (0 inside): in the axial and radial coordinates (h, ρ) it is the distance to the
/// rectangle [0, L] × [0, r].
pub fn point_cylinder_dist(p: &V, from: &V, to: &V, r: f64) -> f64 {
    let d = to - from;
    let len = d.norm();
    let e = d / len;
    let w = p - from;
    let h = w.dot(&e);
    let rho = (w - e * h).norm();
    let dh = (-h).max(h - len).max(0.0);
    let dr = (rho - r).max(0.0);
    dh.hypot(dr)
}

/// Distance from point p to the solid cone with the given apex, unit axis, half-angle α and
/// height H (0 inside): in the axial and radial coordinates (h, ρ ≥ 0) the cone's section is the
/// triangle (0, 0), (H, H tan α), (H, 0), and the nearest point lies on its lateral or base edge.
pub fn point_cone_dist(p: &V, apex: &V, axis: &V, half_angle: f64, height: f64) -> f64 {
    let w = p - apex;
    let h = w.dot(axis);
    let rho = (w - axis * h).norm();
    let radius = height * half_angle.tan();
    if h >= 0.0 && h <= height && rho <= h * half_angle.tan() {
        return 0.0;
    }
    let to_edge = |(x0, y0): (f64, f64), (x1, y1): (f64, f64)| {
        let (dx, dy) = (x1 - x0, y1 - y0);
        let k = (((h - x0) * dx + (rho - y0) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
        (h - x0 - k * dx).hypot(rho - y0 - k * dy)
    };
    to_edge((0.0, 0.0), (height, radius)).min(to_edge((height, 0.0), (height, radius)))
}

/// An ellipsoid {x : (x−c)ᵀ M (x−c) ≤ 1} by its principal frame: `axes` holds M's unit
/// eigenvectors as columns and `m` the eigenvalues (1/semi-axis²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipsoidFrame {
    /// Centre c.
    pub center: V,
    /// Eigenvectors of M, as columns.
    pub axes: Matrix3<f64>,
    /// Eigenvalues of M (all > 0).
    pub m: V,
}

impl EllipsoidFrame {
    /// The principal frame of the SPD matrix `matrix` centred at `center`.
    pub fn new(center: V, matrix: &Matrix3<f64>) -> EllipsoidFrame {
        let eig = nalgebra::SymmetricEigen::new(*matrix);
        EllipsoidFrame { center, axes: eig.eigenvectors, m: eig.eigenvalues }
    }

    /// Distance from point p to the solid ellipsoid (0 inside). Outside, the nearest point is
    /// y_i = z_i/(1 + m_i t) in principal coordinates z, where t > 0 is the root of
    /// Σ m_i z_i²/(1 + m_i t)² = 1 (decreasing in t, bracketed by [0, √(Σ z_i²/m_i)] and found by
    /// bisection to the last bit).
    pub fn point_dist(&self, p: &V) -> f64 {
        let z = self.axes.transpose() * (p - self.center);
        let g = |t: f64| (0..3).map(|i| self.m[i] * (z[i] / (1.0 + self.m[i] * t)).powi(2)).sum::<f64>() - 1.0;
        if g(0.0) <= 0.0 {
            return 0.0;
        }
        let (mut lo, mut hi) = (0.0f64, (0..3).map(|i| z[i] * z[i] / self.m[i]).sum::<f64>().sqrt());
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if g(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let t = 0.5 * (lo + hi);
        (0..3).map(|i| (z[i] * self.m[i] * t / (1.0 + self.m[i] * t)).powi(2)).sum::<f64>().sqrt()
    }
}

/// Minimum over the segment a → a + s of a convex function of the point (a distance to a convex
/// solid): golden-section search on the segment parameter, and both ends.
pub fn segment_min_convex(a: &V, s: &V, f: impl Fn(&V) -> f64) -> f64 {
    let g = |u: f64| f(&(a + s * u));
    let r = (5f64.sqrt() - 1.0) / 2.0;
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    let (mut c, mut d) = (hi - r * (hi - lo), lo + r * (hi - lo));
    let (mut fc, mut fd) = (g(c), g(d));
    for _ in 0..120 {
        if fc < fd {
            hi = d;
            d = c;
            fd = fc;
            c = hi - r * (hi - lo);
            fc = g(c);
        } else {
            lo = c;
            c = d;
            fc = fd;
            d = lo + r * (hi - lo);
            fd = g(d);
        }
        if hi - lo < 1e-16 {
            break;
        }
    }
    fc.min(fd).min(g(0.0)).min(g(1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64, z: f64) -> V {
        V::new(x, y, z)
    }

    #[test]
    fn segment_distances_on_hand_cases() {
        // crossing at right angles, 1 apart
        assert!((segment_segment_dist(&v(-1., 0., 0.), &v(2., 0., 0.), &v(0., -1., 1.), &v(0., 2., 0.)) - 1.0).abs() < 1e-15);
        // closest points are endpoints (anchors)
        assert!((segment_segment_dist(&v(0., 0., 0.), &v(1., 0., 0.), &v(2., 1., 0.), &v(0., 1., 0.)) - 2f64.sqrt()).abs() < 1e-15);
        // parallel, overlapping
        assert!((segment_segment_dist(&v(0., 0., 0.), &v(1., 0., 0.), &v(0.5, 0.3, 0.), &v(1., 0., 0.)) - 0.3).abs() < 1e-15);
        // degenerate (a point)
        assert!((segment_segment_dist(&v(0., 0., 0.), &v(0., 0., 0.), &v(0., 0., 2.), &v(1., 0., 0.)) - 2.0).abs() < 1e-15);
    }

    #[test]
    fn triangle_and_cone_queries() {
        let tri = [v(0., 0., 0.), v(1., 0., 0.), v(0., 1., 0.)];
        assert_eq!(segment_triangle_dist(&v(0.2, 0.2, -1.), &v(0., 0., 2.), &tri), 0.0);
        assert!((segment_triangle_dist(&v(0.2, 0.2, 0.5), &v(0., 0., 1.), &tri) - 0.5).abs() < 1e-15);
        assert!((point_triangle_dist(&v(2., 0., 0.), &tri) - 1.0).abs() < 1e-15);
        let cos2 = (std::f64::consts::FRAC_PI_6).cos().powi(2);
        let (apex, axis) = (v(0., 0., 1.), v(0., 0., -1.));
        assert!(segment_meets_cone(&v(-1., 0., 0.5), &v(2., 0., 0.), &apex, &axis, cos2, 1.0));
        assert!(!segment_meets_cone(&v(-1., 0., 1.5), &v(2., 0., 0.), &apex, &axis, cos2, 1.0));
        assert!(!segment_meets_cone(&v(-1., 0., -0.5), &v(2., 0., 0.), &apex, &axis, cos2, 1.0));
    }

    #[test]
    fn quadric_distances_on_hand_cases() {
        let (p, q) = (v(0., 0., 0.), v(0., 0., 2.));
        assert!((point_cylinder_dist(&v(3., 0., 1.), &p, &q, 1.0) - 2.0).abs() < 1e-15);
        assert!((point_cylinder_dist(&v(0.5, 0., 3.), &p, &q, 1.0) - 1.0).abs() < 1e-15);
        assert!((point_cylinder_dist(&v(4., 0., 6.), &p, &q, 1.0) - 5.0).abs() < 1e-15);
        assert_eq!(point_cylinder_dist(&v(0.5, 0.5, 1.), &p, &q, 1.0), 0.0);
        // cone: apex at 0, axis +z, 45°, height 1: the lateral normal through (0, 1, 0) hits the apex
        let a45 = std::f64::consts::FRAC_PI_4;
        assert!((point_cone_dist(&v(0., 1., 0.), &p, &v(0., 0., 1.), a45, 1.0) - 0.5f64.sqrt()).abs() < 1e-15);
        assert!((point_cone_dist(&v(0., 0., -1.), &p, &v(0., 0., 1.), a45, 1.0) - 1.0).abs() < 1e-15);
        assert!((point_cone_dist(&v(0., 0.5, 3.), &p, &v(0., 0., 1.), a45, 1.0) - 2.0).abs() < 1e-15);
        assert!((point_cone_dist(&v(0., 2., 2.), &p, &v(0., 0., 1.), a45, 1.0) - 2f64.sqrt()).abs() < 1e-15);
        // ellipsoid with semi-axes 1, 2, 3
        let m = Matrix3::from_diagonal(&v(1.0, 0.25, 1.0 / 9.0));
        let e = EllipsoidFrame::new(v(1., 1., 1.), &m);
        assert!((e.point_dist(&v(4., 1., 1.)) - 2.0).abs() < 1e-14);
        assert!((e.point_dist(&v(1., 1., 5.)) - 1.0).abs() < 1e-14);
        assert_eq!(e.point_dist(&v(1.5, 1., 1.)), 0.0);
        let d = segment_min_convex(&v(3., -5., 1.), &v(0., 10., 0.), |x| e.point_dist(x));
        assert!((d - 1.0).abs() < 1e-12, "{d}");
    }
}
