//! Winch limits along a timed motion: each cable's speed |l̇| < v_max and acceleration
//! |l̈| < a_max, exact polynomial sign conditions.
//!
//! With the cable vector s = s̃/w, ŝ = s̃'w − s̃w' (so ds/dλ = ŝ/w²), P = s̃·s̃, u = s̃·ŝ and
//! g = dλ/ds (time s):
//!
//! * l̇ = g u / (w² √P), so |l̇| < v ⇔ v² w⁴ P − g² u² > 0;
//! * l̈ = g Z / (w³ P^{3/2}) with Z = (g'u + g u') w P − 2 g u w' P − g u w P'/2, so
//!   |l̈| < a ⇔ a² w⁶ P³ − (g Z)² > 0, g Z a polynomial in g² and g g' ([`TimeLaw`]).
//!
//! A motion without time (a ray, an untimed trajectory) is at rest: the limits hold.

use super::load::{per_part_unit, sweep_law, TimeLaw};
use super::{Condition, Kind, PoseCheck, Sweep};
use crate::axes::{each_axis, per_axis};
use crate::poly::{Bern, Partition, Truth};
use crate::query::cables::{cable_rates, PoseCables};

/// Which rate a [`WinchLimit`] bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rate {
    /// |l̇|.
    Speed,
    /// |l̈|.
    Acceleration,
}

/// The speed or acceleration limit of one cable's winch.
#[derive(Debug, Clone)]
pub struct WinchLimit {
    /// The cable (0-based).
    pub cable: usize,
    /// Which rate.
    pub rate: Rate,
    /// The limit (positive).
    pub limit: f64,
}

/// The winch limits' polynomials along one motion, apart from the time law: per cable (built by
/// the first limit that needs them) the factors w, w', P, P', u, u' of the module docs, from which
/// each part of the motion ([`WinchPolys::part`]) restricts them — products of restricted
/// factors cost less than restricted products of their degree.
#[derive(Debug, Clone, Default)]
pub struct WinchPolys {
    entries: Vec<(usize, Factors)>,
}

/// One cable's factors [w, w', P, P', u, u'] ([`WinchPolys`]).
type Factors = [Bern; 6];

/// How many derivatives in λ each of the [`Factors`] carries: under λ = a + hλ' each is h to
/// that power times the one in λ'.
const DERIVATIVES: [i32; 6] = [0, 1, 0, 1, 1, 2];

impl WinchPolys {
    fn get(&self, cable: usize) -> Option<&Factors> {
        self.entries.iter().find(|e| e.0 == cable).map(|e| &e.1)
    }

    /// The factors on the part [a, b] of the motion, re-parametrised to [0, 1]: restricted, each
    /// weighed by h = b − a to the power of its derivatives, so that the part's own g² and g g'
    /// apply.
    pub fn part(&self, (a, b): (f64, f64)) -> WinchPolys {
        let entries = self.entries.iter().map(|(cable, f)| (*cable, std::array::from_fn(|k| per_part_unit(&f[k], (a, b), DERIVATIVES[k])))).collect();
        WinchPolys { entries }
    }
}

impl WinchLimit {
    /// Builds this cable's factors into `sweep` unless they are there.
    fn expand(&self, sweep: &mut Sweep) {
        if sweep.winch.get(self.cable).is_some() {
            return;
        }
        let w = &sweep.motion().weight;
        let s = &sweep.cables[self.cable].s;
        let st: [&Bern; 3] = [&s[0].p, &s[1].p, &s[2].p];
        let dw = w.derivative();
        let d: [Bern; 3] = each_axis(&st, |c| c.derivative());
        let hat: [Bern; 3] = per_axis(|i| d[i].mul(w).sub(&st[i].mul(&dw)));
        let dot = |a: [&Bern; 3], b: [&Bern; 3]| a[0].mul(b[0]).add(&a[1].mul(b[1])).add(&a[2].mul(b[2]));
        let p = dot(st, st);
        let dp = dot(st, [&d[0], &d[1], &d[2]]).scale(2.0);
        let u = dot(st, [&hat[0], &hat[1], &hat[2]]);
        let du = u.derivative();
        sweep.winch.entries.push((self.cable, [w.clone(), dw, p, dp, u, du]));
    }

    /// The polynomial that is positive exactly where the limit holds, on the sweep's motion timed
    /// by `law`.
    fn margin(&self, sweep: &mut Sweep, law: &TimeLaw) -> Bern {
        self.expand(sweep);
        let [w, dw, p, dp, u, du] = sweep.winch.get(self.cable).expect("expanded above");
        let w2 = w.mul(w);
        let limit2 = self.limit * self.limit;
        match self.rate {
            Rate::Speed => w2.mul(&w2).mul(p).scale(limit2).sub(&law.square.mul(&u.mul(u))),
            Rate::Acceleration => {
                // g·Z = g g' u w P + g² (u' w P − 2 u w' P − u w P'/2)
                let first = u.mul(w).mul(p);
                let second = du.mul(w).mul(p).sub(&u.mul(dw).mul(p).scale(2.0)).sub(&u.mul(w).mul(dp).scale(0.5));
                let gz = law.accel.mul(&first).add(&law.square.mul(&second));
                let w6p3 = w2.mul(&w2).mul(&w2).mul(p).mul(p).mul(p);
                w6p3.scale(limit2).sub(&gz.mul(&gz))
            }
        }
    }
}

impl Condition for WinchLimit {
    fn kind(&self) -> Kind {
        Kind::Winch
    }

    fn label(&self) -> String {
        match self.rate {
            Rate::Speed => format!("cable {} speed", self.cable + 1),
            Rate::Acceleration => format!("cable {} acceleration", self.cable + 1),
        }
    }

    fn cables(&self) -> Vec<usize> {
        vec![self.cable]
    }

    fn prepare(&self, sweep: &mut Sweep) {
        self.expand(sweep);
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let Some(law) = sweep_law(sweep) else {
            return Partition::constant(Truth::False);
        };
        let margin = self.margin(sweep, &law);
        Partition::atom_outside(&margin, true, sweep.tol, &sweep.settled).not()
    }

    /// The cable's rate at the pose ([`cable_rates`]); the distance is the rate's magnitude; at
    /// rest both are 0.
    fn check(&self, at: &PoseCables) -> PoseCheck {
        let Some(kin) = &at.kinematics else { return PoseCheck { violated: false, distance: Some(0.0) } };
        let (a, x) = at.cables[self.cable];
        let (speed, accel) = cable_rates(&at.pose, kin, &a, &x);
        let rate = match self.rate {
            Rate::Speed => speed.abs(),
            Rate::Acceleration => accel.abs(),
        };
        PoseCheck { violated: !(rate < self.limit), distance: Some(rate) }
    }
}
