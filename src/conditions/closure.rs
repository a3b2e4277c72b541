//! Wrench conditions of robots with more than six cables (m ≥ 7): wrench closure (thesis WCC: a
//! strictly positive tension vector in the null space of the structure matrix J, J of rank 6) and
//! static feasibility of the nominal wrench w0 (tensions strictly within their bounds balance it).
//!
//! Both are written with the facets of the column configuration: for a set S of five columns,
//! n_S·x = det [J_S | x]. Up to a positive factor (powers of w and cable lengths),
//! det [J_S | j_k] = d_k = det [Ñ_S | ñ_k] and det [J_S | w0] = d_0 = det [Ñ_S | D_w w0], with Ñ
//! the polynomial structure matrix of [`super::structure`].
//!
//! * Closure holds iff for every S not degenerate (some d_k ≠ 0), columns lie strictly on both
//!   sides: some d_k > 0 and some d_k < 0. Polynomial sign conditions: exact along motions.
//! * w0 lies inside the zonotope {J f : f_min < f < f_max} iff for every such S
//!   Σ_{k∉S} min(d_k f_min,k, d_k f_max,k)/ρ_k < d_0 < Σ_{k∉S} max(…)/ρ_k (hyperplane shifting).
//!   The 1/ρ_k = w/√P_k make these non-polynomial: along motions they are decided on
//!   sub-intervals by enclosures (Bernstein coefficient ranges, interval arithmetic), bisected
//!   down to the boundary tolerance; what stays undecided is reported as such. Per pose the test is
//!   a small linear program ([`crate::query::wrench::static_margin`]).

use std::rc::Rc;

use super::primitives::{GT, LT};
use super::structure::{det_with, minors, structure_numerators, Local};
use super::{Condition, Kind, PoseCables, PoseCheck, Sweep};
use crate::model::{Bounds, Wrench};
use crate::poly::{Bern, Partition, Truth};
use crate::query::wrench::{closure_holds, static_margin, subsets};

/// One facet candidate: five columns S, d_k for the other columns, and d_0.
#[derive(Debug, Clone)]
struct Facet {
    /// (k, d_k) for every column k ∉ S.
    others: Vec<(usize, Bern)>,
    /// d_0 = det [Ñ_S | D_w w0].
    load: Bern,
}

impl Facet {
    /// S is degenerate all along the motion: every d_k is indistinguishable from zero.
    fn degenerate(&self) -> bool {
        self.others.iter().all(|(_, d)| d.max_abs() <= d.err)
    }
}

/// The polynomials the closure and static-feasibility conditions of one motion share.
#[derive(Debug, Clone)]
pub struct FacetPolys {
    facets: Vec<Facet>,
    /// P_k = ‖s̃_k‖² per cable.
    len2: Vec<Bern>,
    /// The motion's weight w.
    weight: Bern,
}

impl FacetPolys {
    /// The shared polynomials of `sweep` for `wrench`.
    pub fn new(sweep: &Sweep, wrench: &Wrench) -> FacetPolys {
        let local = Local::of(sweep);
        let n = structure_numerators(&local, wrench);
        let w = &local.weight;
        let w2 = w.mul(w);
        let load: [Bern; 6] = std::array::from_fn(|j| if j < 3 { w.scale(wrench.nominal[j]) } else { w2.scale(wrench.nominal[j]) });
        let m = local.cables.len();
        let facets = subsets(m, 5)
            .into_iter()
            .map(|s| {
                let minors = minors(&n, &s);
                let others = (0..m)
                    .filter(|k| !s.contains(k))
                    .map(|k| (k, det_with(&minors, &std::array::from_fn::<_, 6, _>(|j| &n[j][k]))))
                    .collect();
                Facet { others, load: det_with(&minors, &std::array::from_fn::<_, 6, _>(|j| &load[j])) }
            })
            .collect();
        let len2 = local.len2();
        FacetPolys { facets, len2, weight: w.clone() }
    }

    fn of(sweep: &mut Sweep, wrench: &Wrench) -> Rc<FacetPolys> {
        match &sweep.facets {
            Some(p) => Rc::clone(p),
            None => {
                let p = Rc::new(FacetPolys::new(sweep, wrench));
                sweep.facets = Some(Rc::clone(&p));
                p
            }
        }
    }
}

/// Wrench closure of a robot with m ≥ 7 cables.
#[derive(Debug, Clone)]
pub struct WrenchClosure {
    /// The wrench set (its application point fixes the moment arm; closure does not depend on it
    /// but the structure matrix is built the same way as for the other wrench conditions).
    pub wrench: Rc<Wrench>,
}

impl Condition for WrenchClosure {
    fn kind(&self) -> Kind {
        Kind::Tension
    }

    fn label(&self) -> String {
        "wrench closure".to_string()
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let tol = sweep.tol;
        let polys = FacetPolys::of(sweep, &self.wrench);
        not_spanning(polys.facets.iter().map(|f| f.others.iter().map(|(_, d)| d.clone()).collect()), tol)
    }

    fn check(&self, at: &PoseCables) -> PoseCheck {
        PoseCheck { violated: !closure_holds(&at.cables, &self.wrench.point_at(&at.pose)), distance: None }
    }
}

/// Where the columns of a structure matrix along a motion do not positively span: given, per
/// facet candidate S (n − 1 columns), the determinants d_k = det [J_S | j_k] of the other columns
/// (computed lazily: the search stops once closure fails everywhere), closure holds where every
/// facet not degenerate all along has some d_k > 0 and some d_k < 0; nowhere if every facet is
/// degenerate (rank below n − 1 all along).
pub(super) fn not_spanning(facets: impl Iterator<Item = Vec<Bern>>, tol: f64) -> Partition {
    // Some d_k with the given sign (`GT`: positive), lazily.
    let some_side = |d: &[Bern], side: bool| {
        d.iter().fold(Partition::constant(Truth::False), |acc, p| if acc.is_all(Truth::True) { acc } else { acc.or(&Partition::atom(p, side, tol)) })
    };
    let mut holds = Partition::constant(Truth::True);
    let mut any_facet = false;
    for d in facets.filter(|d| !d.iter().all(|p| p.max_abs() <= p.err)) {
        any_facet = true;
        holds = holds.and(&some_side(&d, GT)).and(&some_side(&d, LT));
        if holds.is_all(Truth::False) {
            break;
        }
    }
    if !any_facet {
        return Partition::constant(Truth::True);
    }
    holds.not()
}

/// Static feasibility of the nominal wrench for a robot with m ≥ 7 cables: tensions strictly
/// within their bounds balance w0.
#[derive(Debug, Clone)]
pub struct StaticFeasibility {
    /// The wrench set (its nominal wrench and application point).
    pub wrench: Rc<Wrench>,
    /// Tension bounds per cable.
    pub bounds: Vec<Bounds>,
}

/// A closed interval [lo, hi] of reals (possibly infinite ends).
#[derive(Debug, Clone, Copy)]
struct Iv {
    lo: f64,
    hi: f64,
}

impl Iv {
    /// The range of a Bernstein polynomial over its whole domain, rounding error included.
    fn of(p: &Bern) -> Iv {
        let (lo, hi) = p.c.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &c| (l.min(c), h.max(c)));
        Iv { lo: lo - p.err, hi: hi + p.err }
    }

    fn add(self, o: Iv) -> Iv {
        Iv { lo: self.lo + o.lo, hi: self.hi + o.hi }
    }

    fn mul(self, o: Iv) -> Iv {
        let p = [self.lo * o.lo, self.lo * o.hi, self.hi * o.lo, self.hi * o.hi];
        if p.iter().any(|x| x.is_nan()) {
            return Iv { lo: f64::NEG_INFINITY, hi: f64::INFINITY };
        }
        Iv { lo: p.iter().copied().fold(f64::INFINITY, f64::min), hi: p.iter().copied().fold(f64::NEG_INFINITY, f64::max) }
    }

    /// c·x for a constant c (possibly infinite).
    fn scale(self, c: f64) -> Iv {
        self.mul(Iv { lo: c, hi: c })
    }

    /// Pointwise min and max of c·x and e·x over the interval of x.
    fn min_max_of_scaled(self, c: f64, e: f64) -> (Iv, Iv) {
        let (a, b) = (self.scale(c), self.scale(e));
        (Iv { lo: a.lo.min(b.lo), hi: a.hi.min(b.hi) }, Iv { lo: a.lo.max(b.lo), hi: a.hi.max(b.hi) })
    }
}

/// Deepest bisection of the static-feasibility decision before a piece is reported undecided.
const MAX_NODES: usize = 4_000;

impl StaticFeasibility {
    /// The truth of "statically feasible" on the piece of the motion where `polys` are expanded
    /// (all of them restricted to it): True, False, or Unknown when the enclosures cannot tell.
    fn decide(&self, polys: &[(Vec<(usize, Bern)>, Bern)], len2: &[Bern], weight: &Bern) -> Truth {
        let w = Iv::of(weight);
        let inv_rho: Vec<Iv> = len2
            .iter()
            .map(|p| {
                let p = Iv::of(p);
                if p.lo > 0.0 {
                    Iv { lo: w.lo / p.hi.sqrt(), hi: w.hi / p.lo.sqrt() }
                } else {
                    Iv { lo: 0.0, hi: f64::INFINITY }
                }
            })
            .collect();
        let mut all_hold = true;
        for (others, load) in polys {
            let d0 = Iv::of(load);
            let (mut lower, mut upper) = (Iv { lo: 0.0, hi: 0.0 }, Iv { lo: 0.0, hi: 0.0 });
            for (k, d) in others {
                let b = self.bounds[*k];
                let (lo_t, hi_t) = Iv::of(d).min_max_of_scaled(b.min, b.max);
                lower = lower.add(lo_t.mul(inv_rho[*k]));
                upper = upper.add(hi_t.mul(inv_rho[*k]));
            }
            // margins: upper − d0 > 0 and d0 − lower > 0
            let above = Iv { lo: upper.lo - d0.hi, hi: upper.hi - d0.lo };
            let below = Iv { lo: d0.lo - lower.hi, hi: d0.hi - lower.lo };
            if above.hi < 0.0 || below.hi < 0.0 {
                return Truth::False;
            }
            if !(above.lo > 0.0 && below.lo > 0.0) {
                all_hold = false;
            }
        }
        if all_hold {
            Truth::True
        } else {
            Truth::Unknown
        }
    }

    /// Bisection over [a, b] ⊆ [0, 1]: pieces of `out` as (end, feasible?).
    fn bisect(&self, all: &FacetPolys, live: &[usize], (a, b): (f64, f64), tol: f64, budget: &mut usize, out: &mut Vec<(f64, Truth)>) {
        let restrict = |p: &Bern| p.restrict(a, b);
        let polys: Vec<(Vec<(usize, Bern)>, Bern)> = live
            .iter()
            .map(|&i| {
                let f = &all.facets[i];
                (f.others.iter().map(|(k, d)| (*k, restrict(d))).collect(), restrict(&f.load))
            })
            .collect();
        let len2: Vec<Bern> = all.len2.iter().map(restrict).collect();
        let truth = self.decide(&polys, &len2, &restrict(&all.weight));
        if truth != Truth::Unknown || b - a <= tol || *budget == 0 {
            out.push((b, truth));
            return;
        }
        *budget -= 1;
        let mid = 0.5 * (a + b);
        self.bisect(all, live, (a, mid), tol, budget, out);
        self.bisect(all, live, (mid, b), tol, budget, out);
    }
}

impl Condition for StaticFeasibility {
    fn kind(&self) -> Kind {
        Kind::Tension
    }

    fn label(&self) -> String {
        "static feasibility".to_string()
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let tol = sweep.tol;
        let polys = FacetPolys::of(sweep, &self.wrench);
        let live: Vec<usize> = (0..polys.facets.len()).filter(|&i| !polys.facets[i].degenerate()).collect();
        if live.is_empty() {
            return Partition::constant(Truth::True); // rank < 5 all along: nothing is balanced
        }
        let mut pieces = Vec::new();
        let mut budget = MAX_NODES;
        self.bisect(&polys, &live, (0.0, 1.0), tol, &mut budget, &mut pieces);
        Partition::from_pieces(pieces).not()
    }

    fn check(&self, at: &PoseCables) -> PoseCheck {
        match static_margin(&at.cables, &self.wrench.point_at(&at.pose), &self.wrench.nominal, &self.bounds) {
            Some((margin, _)) => PoseCheck { violated: !(margin > 0.0), distance: Some(margin) },
            None => PoseCheck { violated: true, distance: None },
        }
    }
}
