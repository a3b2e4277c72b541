//! Cable length bounds: ρ_min ≤ ‖s‖ ≤ ρ_max. A routed cable's length is the sum of its segments'
//! lengths: its sections come from [`super::lipschitz`] (a sum of square roots has no polynomial
//! sign), the straight cable's from the polynomial ‖s‖² − ρ².

use super::algebra::H;
use super::lipschitz::{point_at, violation as lipschitz_violation, Speed};
use super::primitives::{all_of, any_of, GT, LT};
use super::{on_undecided, Condition, Kind, PoseCheck, Sweep};
use crate::model::Bounds;
use crate::poly::{Bern, Partition, Truth};
use crate::query::cables::PoseCables;

/// Length bounds of one cable.
#[derive(Debug, Clone)]
pub struct CableLength {
    /// The cable (0-based).
    pub cable: usize,
    /// Its segments (indices into the sweep's cables and a pose's, [`crate::model::Robot::segments`]):
    /// `[cable]` for a straight cable of a robot without routed ones.
    pub segments: Vec<usize>,
    /// Allowed length range.
    pub bounds: Bounds,
}

impl CableLength {
    /// min(L − ρ_min, ρ_max − L) for the length L: positive where the bounds hold strictly.
    fn margin(&self, len: f64) -> f64 {
        let below = if self.bounds.min > 0.0 { len - self.bounds.min } else { f64::INFINITY };
        below.min(self.bounds.max - len)
    }

    /// The routed cable's sections: its length's margin at single λ, the ends' speeds bounding
    /// how fast it changes (each end moves a segment's length at most as fast as it moves).
    fn routed(&self, sweep: &Sweep) -> Partition {
        let w = &sweep.motion().weight;
        let ends: Vec<([Bern; 3], [Bern; 3])> = self.segments.iter().map(|&i| (sweep.cables[i].start_hat(w), sweep.cables[i].tip_hat(w))).collect();
        let speeds: Vec<(Speed, Speed)> = ends.iter().map(|(a, x)| (Speed::of(a, w), Speed::of(x, w))).collect();
        let margin = |lam: f64| {
            let (mut len, mut err) = (0.0, 0.0);
            for (a, x) in &ends {
                let ((pa, ea), (px, ex)) = (point_at(a, w, lam), point_at(x, w, lam));
                len += (px - pa).norm();
                err += 2.0 * (ea + ex) + 1e-15 * (px.abs().max() + pa.abs().max());
            }
            (self.margin(len), err + 1e-12 * (1.0 + len))
        };
        let rate = |a: f64, b: f64| speeds.iter().map(|(s, x)| s.over(a, b) + x.over(a, b)).sum::<f64>();
        lipschitz_violation(margin, rate, sweep.tol, &sweep.settled)
    }
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
        let &[segment] = self.segments.as_slice() else { return self.routed(sweep) };
        let (lo, hi) = (self.bounds.min, self.bounds.max);
        let undecided = sweep.cables[segment].tube.undecided_length(lo, hi, &sweep.settled);
        on_undecided(sweep, &undecided, &[segment], |alg, _, s, tol, _| {
            let ss = alg.dot(s[0], s[0]);
            any_of!(
                if lo > 0.0 { all_of!(tol; alg.sub(&ss, &H::constant(lo * lo)) => LT) } else { Partition::constant(Truth::False) },
                if hi.is_finite() { all_of!(tol; alg.sub(&ss, &H::constant(hi * hi)) => GT) } else { Partition::constant(Truth::False) },
            )
        })
    }

    fn check(&self, cables: &PoseCables) -> PoseCheck {
        let len: f64 = self.segments.iter().map(|&i| (cables[i].1 - cables[i].0).norm()).sum();
        PoseCheck { violated: !self.bounds.contains(len), distance: Some(len) }
    }
}
