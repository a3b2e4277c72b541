//! Cable–cable clearance: the minimum distance between two cable segments must be at least the
//! clearance.

use super::algebra::{hvec_const, HVec};
use super::primitives::{segment_segment, ALL_ENDS};
use super::{on_undecided, subtract, Condition, Cost, Kind, PoseCheck, Sweep};
use crate::poly::Partition;
use crate::query::cables::PoseCables;
use crate::query::segment_segment_dist;

/// Clearance between cables `i` and `j` (0-based; reports number them from 1).
#[derive(Debug, Clone)]
pub struct CableCable {
    /// First cable.
    pub i: usize,
    /// Second cable.
    pub j: usize,
    /// Minimum allowed distance.
    pub clearance: f64,
}

impl Condition for CableCable {
    fn kind(&self) -> Kind {
        Kind::Interference
    }

    fn label(&self) -> String {
        format!("cables {}-{}", self.i + 1, self.j + 1)
    }

    fn cables(&self) -> Vec<usize> {
        vec![self.i, self.j]
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
        let r: HVec = hvec_const(&(cj.base - ci.base));
        on_undecided(sweep, &undecided, &[self.i, self.j], |alg, _, s, tol, _| segment_segment(alg, &r, s[0], s[1], self.clearance, ends, tol))
    }

    fn check(&self, cables: &PoseCables) -> PoseCheck {
        let (ai, xi) = cables[self.i];
        let (aj, xj) = cables[self.j];
        let d = segment_segment_dist(&ai, &(xi - ai), &aj, &(xj - aj));
        PoseCheck { violated: d < self.clearance, distance: Some(d) }
    }
}
