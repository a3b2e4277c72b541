//! Cable–obstacle clearance: the distance from a cable to an obstacle must be at least the
//! clearance.
//!
//! Meshes (and boxes) and spheres are exact. Ellipsoids, cylinders and cones take the clearance by
//! testing an enlarged shape that contains every point within the clearance of the obstacle, so
//! they are conservative when the clearance is positive (reports say so):
//! * ellipsoid M: the ellipsoid M_c with M_c⁻¹ = (1 + 1/p)·M⁻¹ + (1 + p)·c²·I, p = c/g, g the
//!   geometric mean of the semi-axes (contains the Minkowski sum with the ball of radius c for any
//!   p > 0);
//! * cylinder: the capsule around its axis with radius r + c (also covers the flat ends);
//! * cone: the cone with the apex moved back by c/sin α along the axis and the height extended by
//!   c/sin α + c (its lateral surface is the lateral surface offset by c, its base lies c beyond
//!   the original base).

use super::algebra::{hvec_const, HVec};
use super::primitives::{point_segment, segment_cone, segment_face, segment_segment, ConeSolid};
use super::tube::Bound;
use super::{on_undecided, Condition, Kind, PoseCables, PoseCheck, Sweep};
use crate::poly::{Partition, Truth};
use crate::query::{point_segment_dist2, segment_crosses_triangle, segment_meets_cone, segment_segment_dist, segment_triangle_dist};
use crate::shape::{Obstacle, Shape};
use nalgebra::{Matrix3, Vector3};
use std::collections::BTreeSet;

type V = Vector3<f64>;

/// The tested geometry, with the clearance already applied where the shape is enlarged.
#[derive(Debug, Clone)]
enum Geom {
    Mesh { faces: Vec<([V; 3], Bound)>, edges: Vec<(V, V)> },
    Sphere { center: V, radius: f64, reach: f64 },
    Ellipsoid { center: V, metric: Matrix3<f64> },
    Capsule { from: V, to: V, radius: f64, reach: f64 },
    Cone(ConeSolid),
}

/// Clearance between one cable and one obstacle.
#[derive(Debug, Clone)]
pub struct CableShape {
    cable: usize,
    name: String,
    clearance: f64,
    exact: bool,
    geom: Geom,
    bound: Bound,
}

impl CableShape {
    /// The condition for cable `cable` (0-based) against `obstacle` with clearance `c`.
    pub fn new(cable: usize, obstacle: &Obstacle, c: f64) -> CableShape {
        let (geom, bound, exact) = match &obstacle.shape {
            Shape::Mesh(mesh) => {
                let faces: Vec<([V; 3], Bound)> = (0..mesh.triangles.len())
                    .map(|k| {
                        let tri = mesh.triangle(k);
                        (tri, Bound::ball_around(&tri, c))
                    })
                    .collect();
                let mut seen = BTreeSet::new();
                let mut edges = Vec::new();
                for t in &mesh.triangles {
                    for k in 0..3 {
                        let (a, b) = (t[k], t[(k + 1) % 3]);
                        if seen.insert((a.min(b), a.max(b))) {
                            edges.push((mesh.vertices[a], mesh.vertices[b]));
                        }
                    }
                }
                (Geom::Mesh { faces, edges }, Bound::ball_around(&mesh.vertices, c), true)
            }
            Shape::Sphere { center, radius } => {
                let reach = radius + c;
                (Geom::Sphere { center: *center, radius: *radius, reach }, Bound::Ball(*center, reach), true)
            }
            Shape::Ellipsoid { center, matrix } => {
                let inv = matrix.try_inverse().unwrap_or_else(Matrix3::identity);
                let inv_c = if c > 0.0 {
                    let g = matrix.determinant().powf(-1.0 / 6.0);
                    let p = c / g;
                    inv * (1.0 + 1.0 / p) + Matrix3::identity() * ((1.0 + p) * c * c)
                } else {
                    inv
                };
                let metric = inv_c.try_inverse().unwrap_or(*matrix);
                // the largest semi-axis is at most √(trace M_c⁻¹)
                let reach = inv_c.trace().max(0.0).sqrt();
                (Geom::Ellipsoid { center: *center, metric }, Bound::Ball(*center, reach), c == 0.0)
            }
            Shape::Cylinder { from, to, radius } => {
                let reach = radius + c;
                (Geom::Capsule { from: *from, to: *to, radius: *radius, reach }, Bound::Capsule(*from, *to, reach), false)
            }
            Shape::Cone { apex, axis, half_angle, height } => {
                let sin = half_angle.sin();
                let apex = apex - axis * (c / sin);
                let height = height + c / sin + c;
                let base = apex + axis * height;
                // the cone lies in the capsule around its axis with the base radius
                let r = height * half_angle.tan();
                (Geom::Cone(ConeSolid { apex, axis: *axis, cos2: half_angle.cos().powi(2), height }), Bound::Capsule(apex, base, r), c == 0.0)
            }
        };
        CableShape { cable, name: obstacle.name.clone(), clearance: c, exact, geom, bound }
    }
}

impl Condition for CableShape {
    fn kind(&self) -> Kind {
        Kind::Interference
    }

    fn label(&self) -> String {
        format!("cable {} - {}", self.cable + 1, self.name)
    }

    fn exact(&self) -> bool {
        self.exact
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let cable = &sweep.cables[self.cable];
        let undecided = cable.tube.undecided_in(&self.bound);
        let a = cable.base;
        let c = self.clearance;
        // which mesh edges and faces the tube of the whole motion cannot clear
        let near: Vec<bool> = match &self.geom {
            Geom::Mesh { faces, edges } if !undecided.is_empty() => {
                let edges = edges.iter().map(|(p, q)| !cable.tube.clear_of(&Bound::Capsule(*p, *q, c)));
                edges.chain(faces.iter().map(|(_, bound)| !cable.tube.clear_of(bound))).collect()
            }
            _ => Vec::new(),
        };
        on_undecided(sweep, &undecided, &[self.cable], |alg, _, s, tol| {
            let s = s[0];
            match &self.geom {
                Geom::Mesh { faces, edges } => {
                    let mut acc = Partition::constant(Truth::False);
                    for ((p, q), _) in edges.iter().zip(&near).filter(|(_, &n)| n) {
                        if acc.is_all(Truth::True) {
                            break;
                        }
                        let r: HVec = hvec_const(&(p - a));
                        let t: HVec = hvec_const(&(q - p));
                        acc = acc.or(&segment_segment(alg, &r, s, &t, c, tol));
                    }
                    for ((tri, _), _) in faces.iter().zip(&near[edges.len()..]).filter(|(_, &n)| n) {
                        if acc.is_all(Truth::True) {
                            break;
                        }
                        acc = acc.or(&segment_face(alg, &a, s, tri, c, tol));
                    }
                    acc
                }
                Geom::Sphere { center, reach, .. } => point_segment(alg, &hvec_const(&(center - a)), s, *reach, None, tol),
                Geom::Ellipsoid { center, metric } => point_segment(alg, &hvec_const(&(center - a)), s, 1.0, Some(metric), tol),
                Geom::Capsule { from, to, reach, .. } => {
                    let r = hvec_const(&(from - a));
                    let t = hvec_const(&(to - from));
                    segment_segment(alg, &r, s, &t, *reach, tol)
                }
                Geom::Cone(cone) => segment_cone(alg, &a, s, cone, tol),
            }
        })
    }

    fn check(&self, cables: &PoseCables) -> PoseCheck {
        let (a, x) = cables[self.cable];
        let s = x - a;
        let c = self.clearance;
        match &self.geom {
            Geom::Mesh { faces, .. } => {
                let d = faces.iter().map(|(t, _)| segment_triangle_dist(&a, &s, t)).fold(f64::INFINITY, f64::min);
                let crosses = faces.iter().any(|(t, _)| segment_crosses_triangle(&a, &s, t));
                PoseCheck { violated: d < c || crosses, distance: Some(d) }
            }
            Geom::Sphere { center, radius, reach } => {
                let d = point_segment_dist2(center, &a, &s, None).sqrt();
                PoseCheck { violated: d < *reach, distance: Some(d - radius) }
            }
            Geom::Ellipsoid { center, metric } => {
                PoseCheck { violated: point_segment_dist2(center, &a, &s, Some(metric)) < 1.0, distance: None }
            }
            Geom::Capsule { from, to, radius, reach } => {
                let d = segment_segment_dist(&a, &s, from, &(to - from));
                PoseCheck { violated: d < *reach, distance: Some(d - radius) }
            }
            Geom::Cone(k) => PoseCheck { violated: segment_meets_cone(&a, &s, &k.apex, &k.axis, k.cos2, k.height), distance: None },
        }
    }
}
