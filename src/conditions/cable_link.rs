//! Cable–link clearance of a multi-link robot (thesis §3.4): a link's collision body is a segment
//! with a radius, moving with the link; the cable's centreline must stay at least the clearance
//! away from the body's surface, i.e. farther than radius + clearance from its segment. Along a
//! motion both segments move, so this is the cable–cable primitive with a moving offset.

use super::algebra::{HVec, H};
use super::primitives::{point_segment, segment_segment, ALL_ENDS};
use super::{on_undecided, Condition, Cost, Kind, PoseCheck, Sweep};
use crate::axes::{each_axis, per_axis};
use crate::poly::{Bern, Partition};
use crate::query::cables::PoseCables;
use crate::query::{point_segment_dist2, segment_segment_dist};
use nalgebra::Vector3;

/// Clearance between one cable (one segment of a routed cable) and one link's body.
#[derive(Debug, Clone)]
pub struct CableLink {
    /// The cable (0-based), for reports.
    pub cable: usize,
    /// The segment (index into the sweep's cables and a pose's, [`crate::model::Robot::segments`];
    /// the cable's own for a robot without routed cables).
    pub segment: usize,
    /// How reports name the cable (`cable 3`, or `cable 3 segment 2` when routed).
    pub cable_name: String,
    /// The link (index into the chain).
    pub link: usize,
    /// The link's name, for reports.
    pub name: String,
    /// The body segment in the link's frame (a point when both ends are equal).
    pub body: [Vector3<f64>; 2],
    /// The body's radius.
    pub radius: f64,
    /// Minimum allowed distance from the cable's centreline to the body's surface.
    pub clearance: f64,
}

impl Condition for CableLink {
    fn kind(&self) -> Kind {
        Kind::Interference
    }

    fn label(&self) -> String {
        format!("{} - link {}", self.cable_name, self.name)
    }

    fn cables(&self) -> Vec<usize> {
        vec![self.cable]
    }

    fn cost(&self) -> Cost {
        Cost::Moving
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let m = &sweep.links[self.link];
        let start = sweep.cables[self.segment].start_hat(&m.weight);
        let [b0, b1] = self.body;
        let d = b1 - b0;
        // r̂ = B̂0 − Â = P̂ + M̂ b0 − Â (Â = a·w for a base anchor) and d̂ = M̂ (b1 − b0), both over w
        let row = |i: usize, v: &Vector3<f64>| [(&m.rotation[i][0], v[0]), (&m.rotation[i][1], v[1]), (&m.rotation[i][2], v[2])];
        let r: [Bern; 3] = per_axis(|i| {
            let [x, y, z] = row(i, &b0);
            Bern::linear_combination(&[(&m.position[i], 1.0), (&start[i], -1.0), x, y, z])
        });
        let dir: [Bern; 3] = per_axis(|i| Bern::linear_combination(&row(i, &d)));
        let point = d == Vector3::zeros();
        let c = self.radius + self.clearance;
        on_undecided(sweep, &[(0.0, 1.0)], &[self.segment], |alg, _, s, tol, (a, b)| {
            let local = |v: &[Bern; 3]| -> HVec { each_axis(v, |p| H { p: if (a, b) == (0.0, 1.0) { p.clone() } else { p.restrict(a, b) }, k: 1 }) };
            let r = local(&r);
            if point {
                point_segment(alg, &r, s[0], c, None, tol)
            } else {
                segment_segment(alg, &r, s[0], &local(&dir), c, ALL_ENDS, tol)
            }
        })
    }

    fn check(&self, cables: &PoseCables) -> PoseCheck {
        let (a, x) = cables[self.segment];
        let (p, rot) = cables.links[self.link];
        let (b0, b1) = (p + rot * self.body[0], p + rot * self.body[1]);
        let centre = if b0 == b1 { point_segment_dist2(&b0, &a, &(x - a), None).sqrt() } else { segment_segment_dist(&a, &(x - a), &b0, &(b1 - b0)) };
        let d = centre - self.radius;
        PoseCheck { violated: d < self.clearance, distance: Some(d) }
    }
}
