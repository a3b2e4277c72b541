//! Cable length bounds: ρ_min ≤ ‖s‖ ≤ ρ_max.

use super::algebra::H;
use super::primitives::{all_of, any_of, GT, LT};
use super::{on_undecided, Condition, Kind, PoseCheck, Sweep};
use crate::model::Bounds;
use crate::poly::{Partition, Truth};
use crate::query::cables::PoseCables;

/// Length bounds of one cable.
#[derive(Debug, Clone)]
pub struct CableLength {
    /// The cable (0-based).
    pub cable: usize,
    /// Allowed length range.
    pub bounds: Bounds,
}

impl Condition for CableLength {
    fn kind(&self) -> Kind {
        Kind::Length
    }

    fn label(&self) -> String {
        format!("cable {} length", self.cable + 1)
    }

    fn cables(&self) -> Vec<usize> {
        vec![self.cable]
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let (lo, hi) = (self.bounds.min, self.bounds.max);
        let undecided = sweep.cables[self.cable].tube.undecided_length(lo, hi, &sweep.settled);
        on_undecided(sweep, &undecided, &[self.cable], |alg, _, s, tol, _| {
            let ss = alg.dot(s[0], s[0]);
            any_of!(
                if lo > 0.0 { all_of!(tol; alg.sub(&ss, &H::constant(lo * lo)) => LT) } else { Partition::constant(Truth::False) },
                if hi.is_finite() { all_of!(tol; alg.sub(&ss, &H::constant(hi * hi)) => GT) } else { Partition::constant(Truth::False) },
            )
        })
    }

    fn check(&self, cables: &PoseCables) -> PoseCheck {
        let (a, x) = cables[self.cable];
        let len = (x - a).norm();
        PoseCheck { violated: !self.bounds.contains(len), distance: Some(len) }
    }
}
