//! Cable–cable clearance: the minimum distance between two cable segments must be at least the
//! clearance.

use super::algebra::{hvec_const, HVec, H};
use super::primitives::{segment_segment, ALL_ENDS};
use super::{on_undecided, subtract, Condition, Cost, Kind, PoseCheck, Sweep};
use crate::axes::{each_axis, per_axis};
use crate::poly::Partition;
use crate::query::cables::PoseCables;
use crate::query::segment_segment_dist;

/// Clearance between cables `i` and `j` (0-based; reports number them from 1) — for a robot with
/// routed cables, between segments `i` and `j` of [`crate::model::Robot::segments`], reported as
/// their cables.
#[derive(Debug, Clone)]
pub struct CableCable {
    /// First cable (segment).
    pub i: usize,
    /// Second cable (segment).
    pub j: usize,
    /// Their cables, for colouring.
    pub cables: [usize; 2],
    /// How reports name it.
    pub name: String,
    /// Minimum allowed distance.
    pub clearance: f64,
}

impl Condition for CableCable {
    fn kind(&self) -> Kind {
        Kind::Interference
    }

    fn label(&self) -> String {
        self.name.clone()
    }

    fn cables(&self) -> Vec<usize> {
        self.cables.to_vec()
    }

    fn cost(&self) -> Cost {
        Cost::Moving
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let (ci, cj) = (&sweep.cables[self.i], &sweep.cables[self.j]);
        let undecided = ci.tube.undecided_near(&cj.tube, self.clearance, &sweep.settled);
        // which endpoint cases the exact work needs, asked only where there is exact work
        let work = !subtract(&undecided, &sweep.settled).0.is_empty();
        let ends = if work { ci.tube.ends_near(&cj.tube, self.clearance, &sweep.settled) } else { ALL_ENDS };
        // from one start to the other: constant between base anchors, over w when either moves
        let r: HVec = match (&ci.start, &cj.start) {
            (None, None) => hvec_const(&(cj.base - ci.base)),
            _ => {
                let w = &sweep.motion().weight;
                let (a, b) = (ci.start_hat(w), cj.start_hat(w));
                per_axis(|i| H { p: b[i].sub(&a[i]), k: 1 })
            }
        };
        on_undecided(sweep, &undecided, &[self.i, self.j], |alg, _, s, tol, (a, b)| {
            let r = if (a, b) == (0.0, 1.0) || r.iter().all(|h| h.k == 0) { r.clone() } else { each_axis(&r, |h| H { p: h.p.restrict(a, b), k: h.k }) };
            segment_segment(alg, &r, s[0], s[1], self.clearance, ends, tol)
        })
    }

    fn check(&self, cables: &PoseCables) -> PoseCheck {
        let (ai, xi) = cables[self.i];
        let (aj, xj) = cables[self.j];
        let d = segment_segment_dist(&ai, &(xi - ai), &aj, &(xj - aj));
        PoseCheck { violated: d < self.clearance, distance: Some(d) }
    }
}
