//! Display tessellation: every obstacle shape, boxes and thin tubes as triangle lists with
//! normals. Only for drawing — the conditions use the exact shapes.

use cablenav::shape::Shape;
use glam::DVec3;
use nalgebra::{Cholesky, Matrix3, Vector3};
use std::f64::consts::{PI, TAU};

/// Segments around a circle.
const AROUND: usize = 24;
/// Rings from pole to pole of a sphere.
const RINGS: usize = 12;

/// Triangles, three corners each, with a normal per corner (zero: draw unlit).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Tris {
    /// Corner positions, 3 per triangle.
    pub positions: Vec<DVec3>,
    /// Corner normals, parallel to `positions`.
    pub normals: Vec<DVec3>,
}

impl Tris {
    /// Number of triangles.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.positions.len() / 3
    }

    fn tri(&mut self, p: [DVec3; 3], n: [DVec3; 3]) {
        self.positions.extend(p);
        self.normals.extend(n);
    }

    /// A flat triangle, its normal from the winding.
    fn flat(&mut self, p: [DVec3; 3]) {
        let n = (p[1] - p[0]).cross(p[2] - p[0]).normalize_or_zero();
        self.tri(p, [n; 3]);
    }

    /// The quad a b c d (in order around it) as two triangles with corner normals.
    fn quad(&mut self, p: [DVec3; 4], n: [DVec3; 4]) {
        self.tri([p[0], p[1], p[2]], [n[0], n[1], n[2]]);
        self.tri([p[0], p[2], p[3]], [n[0], n[2], n[3]]);
    }
}

/// A nalgebra vector as glam's.
pub fn dv(v: &Vector3<f64>) -> DVec3 {
    DVec3::new(v.x, v.y, v.z)
}

/// Two unit vectors perpendicular to `axis` and to each other.
fn basis(axis: DVec3) -> (DVec3, DVec3) {
    let a = axis.normalize_or_zero();
    let helper = if a.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let u = a.cross(helper).normalize();
    (u, a.cross(u))
}

/// Unit sphere directions on a latitude/longitude grid: `grid[i][j]`, ring i from the south pole.
fn unit_sphere() -> Vec<Vec<DVec3>> {
    (0..=RINGS)
        .map(|i| {
            let lat = -PI / 2.0 + PI * i as f64 / RINGS as f64;
            (0..=AROUND)
                .map(|j| {
                    let lon = TAU * j as f64 / AROUND as f64;
                    DVec3::new(lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin())
                })
                .collect()
        })
        .collect()
}

/// The sphere's directions mapped by `point` (position) and `normal`.
fn mapped_sphere(out: &mut Tris, point: impl Fn(DVec3) -> DVec3, normal: impl Fn(DVec3) -> DVec3) {
    let g = unit_sphere();
    for i in 0..RINGS {
        for j in 0..AROUND {
            let d = [g[i][j], g[i][j + 1], g[i + 1][j + 1], g[i + 1][j]];
            out.quad(d.map(&point), d.map(&normal));
        }
    }
}

/// A circular tube (open ends) of `radius` around the segment a → b, `sides` facets.
pub fn tube(out: &mut Tris, a: DVec3, b: DVec3, radius: f64, sides: usize) {
    let (u, v) = basis(b - a);
    let ring = |k: usize| {
        let ang = TAU * k as f64 / sides as f64;
        u * ang.cos() + v * ang.sin()
    };
    for k in 0..sides {
        let (n0, n1) = (ring(k), ring(k + 1));
        out.quad([a + n0 * radius, a + n1 * radius, b + n1 * radius, b + n0 * radius], [n0, n1, n1, n0]);
    }
}

/// A closed solid cylinder from `a` to `b`, flat ends.
fn cylinder(out: &mut Tris, a: DVec3, b: DVec3, radius: f64) {
    tube(out, a, b, radius, AROUND);
    let (u, v) = basis(b - a);
    let axis = (b - a).normalize_or_zero();
    for k in 0..AROUND {
        let r = |k: usize| {
            let ang = TAU * k as f64 / AROUND as f64;
            (u * ang.cos() + v * ang.sin()) * radius
        };
        out.tri([a, a + r(k + 1), a + r(k)], [-axis; 3]);
        out.tri([b, b + r(k), b + r(k + 1)], [axis; 3]);
    }
}

/// The solid cone with `apex`, unit `axis`, `half_angle` and `height`, closed by its base disc.
fn cone(out: &mut Tris, apex: DVec3, axis: DVec3, half_angle: f64, height: f64) {
    let axis = axis.normalize_or_zero();
    let radius = height * half_angle.tan();
    let centre = apex + axis * height;
    let (u, v) = basis(axis);
    let dir = |k: usize| {
        let ang = TAU * k as f64 / AROUND as f64;
        u * ang.cos() + v * ang.sin()
    };
    for k in 0..AROUND {
        let (d0, d1) = (dir(k), dir(k + 1));
        // the side's normal tilts back towards the apex by the half-angle
        let n = |d: DVec3| (d * half_angle.cos() - axis * half_angle.sin()).normalize();
        out.tri([apex, centre + d0 * radius, centre + d1 * radius], [n((d0 + d1) / 2.0), n(d0), n(d1)]);
        out.tri([centre, centre + d1 * radius, centre + d0 * radius], [axis; 3]);
    }
}

/// The ellipsoid {x : (x−c)ᵀ M (x−c) = 1}: with M = L Lᵀ (Cholesky), x = c + L⁻ᵀ u for unit u,
/// and the outward normal is M (x − c). `None` if M is not positive definite.
fn ellipsoid(out: &mut Tris, center: DVec3, m: &Matrix3<f64>) -> Option<()> {
    let l = Cholesky::new(*m)?.l();
    let map = l.transpose().try_inverse()?;
    let point = |u: DVec3| center + dv(&(map * Vector3::new(u.x, u.y, u.z)));
    let normal = |u: DVec3| {
        let x = map * Vector3::new(u.x, u.y, u.z);
        dv(&(m * x)).normalize_or_zero()
    };
    mapped_sphere(out, point, normal);
    Some(())
}

/// An obstacle's surface as triangles.
pub fn shape(s: &Shape) -> Tris {
    let mut out = Tris::default();
    match s {
        Shape::Mesh(mesh) => {
            for k in 0..mesh.triangles.len() {
                out.flat(mesh.triangle(k).map(|v| dv(&v)));
            }
        }
        Shape::Sphere { center, radius } => {
            let c = dv(center);
            mapped_sphere(&mut out, |u| c + u * *radius, |u| u);
        }
        Shape::Ellipsoid { center, matrix } => {
            // the scenario checks M is SPD; if it somehow is not, draw nothing rather than junk
            let _ = ellipsoid(&mut out, dv(center), matrix);
        }
        Shape::Cylinder { from, to, radius } => cylinder(&mut out, dv(from), dv(to), *radius),
        Shape::Cone { apex, axis, half_angle, height } => cone(&mut out, dv(apex), dv(axis), *half_angle, *height),
    }
    out
}

/// The box with corners `corners` (the 8 corners of a cuboid, index bits = x, y, z sides, as in
/// [`cablenav::shape::Mesh::cuboid`], whose outward triangles it reuses) as 12 flat triangles.
pub fn cuboid(out: &mut Tris, corners: [DVec3; 8]) {
    for [a, b, c] in cablenav::shape::Mesh::cuboid(Vector3::zeros(), Vector3::repeat(1.0)).triangles {
        out.flat([corners[a], corners[b], corners[c]]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cablenav::shape::Mesh;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    /// Distance from p to the infinite line through a along unit d, and the coordinate along it.
    fn axial(p: DVec3, a: DVec3, d: DVec3) -> (f64, f64) {
        let along = (p - a).dot(d);
        ((p - a - d * along).length(), along)
    }

    #[test]
    fn sphere_corners_lie_on_it_with_radial_normals() {
        let c = Vector3::new(1.0, -2.0, 0.5);
        let t = shape(&Shape::Sphere { center: c, radius: 0.7 });
        assert_eq!(t.len(), RINGS * AROUND * 2);
        for (p, n) in t.positions.iter().zip(&t.normals) {
            assert!(close((*p - dv(&c)).length(), 0.7, 1e-12));
            assert!(close(n.dot((*p - dv(&c)).normalize()), 1.0, 1e-9));
        }
    }

    #[test]
    fn ellipsoid_corners_satisfy_its_equation_with_gradient_normals() {
        let m = Matrix3::new(4.0, 1.0, 0.0, 1.0, 2.0, 0.5, 0.0, 0.5, 1.0);
        let c = Vector3::new(0.5, 0.5, 2.0);
        let t = shape(&Shape::Ellipsoid { center: c, matrix: m });
        assert!(t.len() > 100);
        for (p, n) in t.positions.iter().zip(&t.normals) {
            let x = Vector3::new(p.x, p.y, p.z) - c;
            assert!(close(x.dot(&(m * x)), 1.0, 1e-9), "{p}");
            let grad = dv(&(m * x)).normalize();
            assert!(close(n.dot(grad), 1.0, 1e-9));
        }
        let not_spd = Matrix3::new(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0);
        assert_eq!(shape(&Shape::Ellipsoid { center: c, matrix: not_spd }).len(), 0);
    }

    #[test]
    fn cylinder_corners_are_on_its_surface() {
        let (a, b) = (DVec3::new(2.0, 2.0, 0.0), DVec3::new(2.0, 3.0, 1.5));
        let t = shape(&Shape::Cylinder { from: Vector3::new(2.0, 2.0, 0.0), to: Vector3::new(2.0, 3.0, 1.5), radius: 0.12 });
        let d = (b - a).normalize();
        let len = (b - a).length();
        for p in &t.positions {
            let (r, along) = axial(*p, a, d);
            let on_side = close(r, 0.12, 1e-12) && along > -1e-12 && along < len + 1e-12;
            let on_cap = r <= 0.12 + 1e-12 && (close(along, 0.0, 1e-12) || close(along, len, 1e-12));
            assert!(on_side || on_cap, "{p}: r = {r}, along = {along}");
        }
    }

    #[test]
    fn cone_corners_are_on_its_surface() {
        let apex = DVec3::new(2.0, 2.0, 0.3);
        let half = 0.5f64;
        let t = shape(&Shape::Cone { apex: Vector3::new(2.0, 2.0, 0.3), axis: Vector3::new(0.0, 0.0, -1.0), half_angle: half, height: 0.3 });
        for (p, n) in t.positions.iter().zip(&t.normals) {
            let (r, along) = axial(*p, apex, -DVec3::Z);
            let on_side = close(r, along * half.tan(), 1e-12) && (-1e-12..=0.3 + 1e-12).contains(&along);
            let on_base = close(along, 0.3, 1e-12) && r <= 0.3 * half.tan() + 1e-12;
            assert!(on_side || on_base, "{p}");
            assert!(close(n.length(), 1.0, 1e-9));
        }
    }

    #[test]
    fn meshes_keep_their_triangles_and_boxes_their_faces() {
        let mesh = Mesh::cuboid(Vector3::new(3.0, 2.0, 0.15), Vector3::new(0.3, 0.5, 0.3));
        let t = shape(&Shape::Mesh(mesh.clone()));
        assert_eq!(t.len(), 12);
        for (k, p) in t.positions.chunks(3).enumerate() {
            let expect = mesh.triangle(k).map(|v| dv(&v));
            assert_eq!(p, expect);
        }
        let mut b = Tris::default();
        let corners: [DVec3; 8] = std::array::from_fn(|i| DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64));
        cuboid(&mut b, corners);
        assert_eq!(b.len(), 12);
        // every normal of the unit cube points out of its centre
        for (p, n) in b.positions.iter().zip(&b.normals) {
            assert!(n.dot(*p - DVec3::splat(0.5)) > 0.0);
        }
    }

    #[test]
    fn tubes_surround_their_segment() {
        let mut t = Tris::default();
        let (a, b) = (DVec3::new(0.0, 1.0, 0.0), DVec3::new(1.0, 1.0, 3.0));
        tube(&mut t, a, b, 0.02, 6);
        assert_eq!(t.len(), 12);
        let d = (b - a).normalize();
        for (p, n) in t.positions.iter().zip(&t.normals) {
            let (r, _) = axial(*p, a, d);
            assert!(close(r, 0.02, 1e-12));
            assert!(close(n.dot(d), 0.0, 1e-12));
        }
    }
}
