//! Cable–obstacle clearance: the distance from a cable to an obstacle must be at least the
//! clearance. Every shape is exact: meshes (and boxes) and spheres by point/segment/face tests,
//! cylinders, cones and ellipsoids with a clearance through their offset solids
//! ([`super::offset`]), and without one through the solid itself. A routed cable's segment
//! between two links has a moving start, which every test reads as fractions of the motion like
//! the cable vector (a point's offset from it, a face's corner offsets, the offset solids' cable
//! line).

use super::algebra::{hvec_const, Alg, HVec, H};
use super::offset::{cone_near, cylinder_near, ellipsoid_clear, Start};
use super::primitives::{point_segment, segment_cone, segment_face, segment_segment, ConeSolid, ALL_ENDS};
use super::tube::Bound;
use super::{on_undecided, Condition, Cost, Kind, PoseCheck, Sweep};
use crate::axes::{each_axis, per_axis};
use crate::poly::{Partition, Truth};
use crate::query::cables::PoseCables;
use crate::query::{
    point_cone_dist, point_cylinder_dist, point_segment_dist2, segment_crosses_triangle, segment_meets_cone, segment_min_convex,
    segment_triangle_dist, EllipsoidFrame,
};
use crate::shape::{Obstacle, Shape};
use nalgebra::{Matrix3, Vector3};
use std::collections::BTreeSet;

type V = Vector3<f64>;

/// The tested geometry.
#[derive(Debug, Clone)]
enum Geom {
    Mesh { faces: Vec<([V; 3], Bound)>, edges: Vec<(V, V)> },
    Sphere { center: V, radius: f64, reach: f64 },
    Ellipsoid { metric: Matrix3<f64>, frame: EllipsoidFrame },
    Cylinder { from: V, to: V, radius: f64 },
    Cone { solid: ConeSolid, half_angle: f64 },
}

/// Clearance between one cable (one segment of a routed cable) and one obstacle.
#[derive(Debug, Clone)]
pub struct CableShape {
    /// The cable, for reports.
    cable: usize,
    /// The segment (index into the sweep's cables and a pose's).
    segment: usize,
    /// How reports name the cable.
    cable_name: String,
    name: String,
    clearance: f64,
    geom: Geom,
    bound: Bound,
}

impl CableShape {
    /// The condition for segment `segment` (of the sweep's and a pose's cables) of cable `cable`
    /// (0-based, reported as `cable_name`) against `obstacle` with clearance `c`.
    pub fn new(cable: usize, segment: usize, cable_name: String, obstacle: &Obstacle, c: f64) -> CableShape {
        let (geom, bound) = match &obstacle.shape {
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
                (Geom::Mesh { faces, edges }, Bound::ball_around(&mesh.vertices, c))
            }
            Shape::Sphere { center, radius } => {
                let reach = radius + c;
                (Geom::Sphere { center: *center, radius: *radius, reach }, Bound::Ball(*center, reach))
            }
            Shape::Ellipsoid { center, matrix } => {
                let frame = EllipsoidFrame::new(*center, matrix);
                // the largest semi-axis is 1/√(least eigenvalue)
                let reach = 1.0 / frame.m.min().max(f64::MIN_POSITIVE).sqrt() + c;
                (Geom::Ellipsoid { metric: *matrix, frame }, Bound::Ball(*center, reach))
            }
            Shape::Cylinder { from, to, radius } => {
                (Geom::Cylinder { from: *from, to: *to, radius: *radius }, Bound::Capsule(*from, *to, radius + c))
            }
            Shape::Cone { apex, axis, half_angle, height } => {
                let base = apex + axis * *height;
                // the cone lies in the capsule around its axis with the base radius
                let r = height * half_angle.tan() + c;
                let solid = ConeSolid { apex: *apex, axis: *axis, cos2: half_angle.cos().powi(2), height: *height };
                (Geom::Cone { solid, half_angle: *half_angle }, Bound::Capsule(*apex, base, r))
            }
        };
        CableShape { cable, segment, cable_name, name: obstacle.name.clone(), clearance: c, geom, bound }
    }
}

impl Condition for CableShape {
    fn kind(&self) -> Kind {
        Kind::Interference
    }

    fn label(&self) -> String {
        format!("{} - {}", self.cable_name, self.name)
    }

    fn cables(&self) -> Vec<usize> {
        vec![self.cable]
    }

    fn cost(&self) -> Cost {
        match self.geom {
            Geom::Cylinder { .. } => Cost::Search,
            Geom::Cone { .. } | Geom::Ellipsoid { .. } if self.clearance > 0.0 => Cost::Search,
            Geom::Cone { .. } | Geom::Ellipsoid { .. } | Geom::Mesh { .. } | Geom::Sphere { .. } => Cost::Fixed,
        }
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let cable = &sweep.cables[self.segment];
        let undecided = cable.tube.undecided_in(&self.bound, &sweep.settled);
        // a segment between two links starts at Â/w, which moves: its start's numerators
        let moving = cable.start.clone();
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
        on_undecided(sweep, &undecided, &[self.segment], |alg, w, s, tol, (lo, hi)| {
            let s = s[0];
            // the start over the piece: as fractions (Â/w, or a constant), for the offset solids'
            // tests as it comes, and a fixed point's offset p − start
            let hat = moving.as_ref().map(|hat| each_axis(hat, |p| if (lo, hi) == (0.0, 1.0) { p.clone() } else { p.restrict(lo, hi) }));
            let start: HVec = match &hat {
                Some(hat) => each_axis(hat, |p| H { p: p.clone(), k: 1 }),
                None => hvec_const(&a),
            };
            let from = match hat {
                Some(hat) => Start::Moving(hat),
                None => Start::Fixed(a),
            };
            let from_start = |alg: &mut Alg, p: &V| -> HVec {
                match from {
                    Start::Moving(_) => per_axis(|i| alg.sub(&H::constant(p[i]), &start[i])),
                    Start::Fixed(a) => hvec_const(&(p - a)),
                }
            };
            match &self.geom {
                Geom::Mesh { faces, edges } => {
                    let mut acc = Partition::constant(Truth::False);
                    for ((p, q), _) in edges.iter().zip(&near).filter(|(_, &n)| n) {
                        if acc.is_all(Truth::True) {
                            break;
                        }
                        let r = from_start(alg, p);
                        let t: HVec = hvec_const(&(q - p));
                        acc = acc.or(&segment_segment(alg, &r, s, &t, c, ALL_ENDS, tol));
                    }
                    for ((tri, _), _) in faces.iter().zip(&near[edges.len()..]).filter(|(_, &n)| n) {
                        if acc.is_all(Truth::True) {
                            break;
                        }
                        acc = acc.or(&segment_face(alg, &start, s, tri, c, tol));
                    }
                    acc
                }
                Geom::Sphere { center, reach, .. } => {
                    let e = from_start(alg, center);
                    point_segment(alg, &e, s, *reach, None, tol)
                }
                Geom::Ellipsoid { metric, frame } => {
                    if c > 0.0 {
                        ellipsoid_clear(&from, s, w, frame, c, tol).not()
                    } else {
                        let e = from_start(alg, &frame.center);
                        point_segment(alg, &e, s, 1.0, Some(metric), tol)
                    }
                }
                Geom::Cylinder { from: p, to: q, radius } => cylinder_near(&from, s, w, p, q, *radius, c, tol),
                Geom::Cone { solid, half_angle } => {
                    let to_apex = from_start(alg, &solid.apex);
                    if c > 0.0 {
                        let apex = point_segment(alg, &to_apex, s, c, None, tol);
                        if apex.is_all(Truth::True) {
                            apex
                        } else {
                            apex.or(&cone_near(&from, s, w, &solid.apex, &solid.axis, *half_angle, solid.height, c, tol))
                        }
                    } else {
                        // segment_cone takes the start's offset from the apex, a − A = −(A − a)
                        let e = to_apex.map(|h| h.scale(-1.0));
                        segment_cone(alg, &e, s, solid, tol)
                    }
                }
            }
        })
    }

    fn check(&self, cables: &PoseCables) -> PoseCheck {
        let (a, x) = cables[self.segment];
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
            Geom::Ellipsoid { metric, frame } => {
                let d = segment_min_convex(&a, &s, |x| frame.point_dist(x));
                let violated = if c > 0.0 { d < c } else { point_segment_dist2(&frame.center, &a, &s, Some(metric)) < 1.0 };
                PoseCheck { violated, distance: Some(d) }
            }
            Geom::Cylinder { from, to, radius } => {
                let d = segment_min_convex(&a, &s, |x| point_cylinder_dist(x, from, to, *radius));
                PoseCheck { violated: if c > 0.0 { d < c } else { d == 0.0 }, distance: Some(d) }
            }
            Geom::Cone { solid: k, half_angle } => {
                let d = segment_min_convex(&a, &s, |x| point_cone_dist(x, &k.apex, &k.axis, *half_angle, k.height));
                let violated = if c > 0.0 { d < c } else { segment_meets_cone(&a, &s, &k.apex, &k.axis, k.cos2, k.height) };
                PoseCheck { violated, distance: Some(d) }
            }
        }
    }
}
