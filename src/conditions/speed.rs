//! The platform's speed limit along a timed motion: |ṗ| < v_max for the platform's origin, an
//! exact polynomial sign condition.
//!
//! With p = P̂/w, dp/dλ = (P̂'w − P̂w')/w² and ṗ = g·dp/dλ (g = dλ/ds, s the time), so
//! |ṗ| < v ⇔ v² w⁴ − g² |P̂'w − P̂w'|² > 0 (g² from the sweep's [`super::TimeLaw`]).

use super::load::sweep_law;
use super::{Condition, Kind, PoseCheck, Sweep};
use crate::axes::each_axis;
use crate::poly::{Bern, Partition, Truth};
use crate::query::cables::PoseCables;

/// The largest speed of the platform's origin (format 4 `robot.speed`).
#[derive(Debug, Clone)]
pub struct PlatformSpeed {
    /// The limit (positive, m/s).
    pub limit: f64,
}

impl Condition for PlatformSpeed {
    fn kind(&self) -> Kind {
        Kind::Winch
    }

    fn label(&self) -> String {
        "platform speed".to_string()
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let Some(law) = sweep_law(sweep) else {
            return Partition::constant(Truth::False);
        };
        let m = sweep.motion();
        let (w, dw) = (&m.weight, m.weight.derivative());
        let rate: [Bern; 3] = each_axis(&m.position, |p| p.derivative().mul(w).sub(&p.mul(&dw)));
        let speed2 = rate[0].mul(&rate[0]).add(&rate[1].mul(&rate[1])).add(&rate[2].mul(&rate[2]));
        let w2 = w.mul(w);
        let margin = w2.mul(&w2).scale(self.limit * self.limit).sub(&law.square.mul(&speed2));
        Partition::atom_outside(&margin, true, sweep.tol, &sweep.settled).not()
    }

    /// The origin's speed at the pose (0 at rest).
    fn check(&self, at: &PoseCables) -> PoseCheck {
        let speed = at.kinematics.map_or(0.0, |k| k.velocity.norm());
        PoseCheck { violated: !(speed < self.limit), distance: Some(speed) }
    }
}
