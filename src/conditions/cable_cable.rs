//! Cable–cable clearance: the minimum distance between two cable segments must be at least the
//! clearance.

use super::algebra::{hvec_const, HVec};
use super::primitives::segment_segment;
use super::{Condition, Kind, PoseCables, PoseCheck, Sweep};
use crate::poly::{Partition, Truth};
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

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let Sweep { alg, cables, tol, .. } = sweep;
        let (ci, cj) = (&cables[self.i], &cables[self.j]);
        if ci.tube.clear_of_tube(&cj.tube, self.clearance) {
            return Partition::constant(Truth::False);
        }
        let r: HVec = hvec_const(&(cj.base - ci.base));
        segment_segment(alg, &r, &ci.s, &cj.s, self.clearance, *tol)
    }

    fn check(&self, cables: &PoseCables) -> PoseCheck {
        let (ai, xi) = cables[self.i];
        let (aj, xj) = cables[self.j];
        let d = segment_segment_dist(&ai, &(xi - ai), &aj, &(xj - aj));
        PoseCheck { violated: d < self.clearance, distance: Some(d) }
    }
}
