//! Wrench conditions written with the facets of the structure matrix's columns (any m ≥ n, n the
//! wrench components balanced: 6, or 3 for a point mass or a planar platform; the verifier uses
//! them for m > n): wrench closure (thesis WCC: a strictly positive tension vector in the null
//! space of J, J of rank n), where the scenario asks for it, and wrench feasibility
//! (every wrench of the ellipsoid around the nominal load — the wrench set's w0, plus the
//! platform's weight and inertia — is balanced by tensions strictly within their bounds).
//!
//! For a set S of n − 1 columns (five on a spatial platform), n_S·x = det [J_S | x]. Up to a positive factor (powers of w and
//! cable lengths), det [J_S | j_k] = d_k = det [Ñ_S | ñ_k] and det [J_S | x] = n̂_S·(D_w x), with
//! Ñ the polynomial structure matrix of [`super::structure`] and n̂_S its cofactor vector.
//!
//! * Closure holds iff for every S not degenerate (some d_k ≠ 0), columns lie strictly on both
//!   sides: some d_k > 0 and some d_k < 0. Polynomial sign conditions: exact along motions.
//! * The ellipsoid W around the load lies inside the zonotope {J f : f_min < f < f_max} iff for
//!   every such S, with d_0 = n̂_S·(D_w ℓ) and the ellipsoid's reach r_S = √((D_w n̂_S)ᵀE⁻¹(D_w n̂_S)),
//!   Σ_{k∉S} min(d_k f_min,k, d_k f_max,k)/ρ_k < d_0 − r_S and d_0 + r_S < Σ_{k∉S} max(…)/ρ_k
//!   (hyperplane shifting). The 1/ρ_k = w/√P_k and √ make these non-polynomial: along motions they
//!   are decided on sub-intervals by enclosures (Bernstein coefficient ranges, interval
//!   arithmetic), bisected down to the boundary tolerance; what stays undecided is reported as
//!   such. Per pose: [`crate::query::wrench::wrench_set_margin`].

use std::rc::Rc;

use super::interval::Iv;
use super::load::{inverse_square, split_part, split_under, with_inertia, TimeLaw};
use super::primitives::{GT, LT};
use super::structure::{det_with, quadratic_form, row_weight, structure_numerators};
use super::{Condition, Kind, Local, PoseCheck, Sweep};
use crate::model::{Bounds, Load};
use crate::poly::{Bern, Minors, Partition, Truth};
use crate::query::cables::PoseCables;
use crate::query::wrench::{closure_holds, subsets, wrench_set_margin};

/// One facet candidate: n − 1 columns S, d_k for the other columns, d_0 and the ellipsoid's reach.
#[derive(Debug, Clone)]
struct Facet {
    /// (k, d_k) for every column k ∉ S.
    others: Vec<(usize, Bern)>,
    /// d_0 = n̂_S·(D_w ℓ) (times the load's w^q), and its inertial part for one second (a
    /// motion run in T seconds has d_0 + inertial/T²).
    load: (Bern, Option<Bern>),
    /// The inertial part kept apart from the time law, (per unit λ̈, per unit λ̇²), where
    /// asked for ([`FacetPolys::new`]): what [`FacetPolys::part`] restricts.
    split: Option<(Bern, Bern)>,
    /// r_S² = (D_w n̂_S)ᵀ E⁻¹ (D_w n̂_S) ≥ 0 (times w^2q); `None` for a single wrench (E⁻¹ = 0).
    reach2: Option<Bern>,
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
    /// w^q, the positive factor the loads d_0 carry (`None` for 1).
    scale: Option<Bern>,
    /// Whether the inertial parts are kept apart from the law (or there are none).
    split: bool,
}

impl FacetPolys {
    /// The shared polynomials of `sweep` under `load`; with `split`, the inertial parts are
    /// also kept apart from the time law, so that parts of the motion under other laws can be
    /// restricted from them ([`Self::part`]).
    pub fn new(sweep: &Sweep, load: &Load, split: bool) -> FacetPolys {
        let local = Local::of(sweep, load);
        let rows = load.rows();
        let dim = rows.len();
        let n = structure_numerators(&local, &load.wrench, rows);
        let w = &local.weight;
        let w2 = w.mul(w);
        let e_inv = &load.wrench.ellipsoid_inv;
        let single = load.wrench.is_single();
        let load_rows = &local.load.rows;
        let m = local.cables.len();
        let mut minors_of = Minors::new(&n);
        let facets = subsets(m, dim - 1)
            .into_iter()
            .map(|s| {
                let minors = minors_of.of(&s);
                let others = (0..m)
                    .filter(|k| !s.contains(k))
                    .map(|k| (k, det_with(&minors, &(0..dim).map(|j| &n[j][k]).collect::<Vec<_>>())))
                    .collect();
                let reach2 = (!single).then(|| {
                    // D_w n̂: the cofactors (−1)^(j+n−1) M_j times w (force rows) or w² (moments)
                    let g: Vec<Bern> = (0..dim)
                        .map(|j| {
                            let c = minors[j].mul(row_weight(rows[j], w, &w2));
                            if (j + dim - 1) % 2 == 0 { c } else { c.scale(-1.0) }
                        })
                        .collect();
                    local.load.scaled_square(quadratic_form(&g, e_inv, rows))
                });
                let d0 = |all: &[Bern; 6]| det_with(&minors, &rows.iter().map(|&r| &all[r]).collect::<Vec<_>>());
                // d_0 is linear in the rows: the split parts' d_0 under the law is the rows'
                let split = if split { local.load.inertial.as_ref().map(|r| (d0(&r.accel), d0(&r.square))) } else { None };
                let inertial = if split.is_some() { split_under(&split, local.law.as_ref()) } else { local.inertial().map(d0) };
                Facet { others, load: (d0(load_rows), inertial), split, reach2 }
            })
            .collect();
        let len2 = local.len2();
        FacetPolys { facets, len2, weight: w.clone(), scale: local.load.scale.clone(), split: split || local.load.inertial.is_none() }
    }

    /// The polynomials on the part [a, b] of the motion they were expanded on, re-parametrised
    /// to [0, 1] and run by `law` there (for one second): restricted, not expanded again, as
    /// [`super::tension::TensionPolys::part`] does. `None` unless the inertial parts were kept
    /// apart from the law.
    pub fn part(&self, (a, b): (f64, f64), law: Option<&TimeLaw>) -> Option<FacetPolys> {
        if !self.split {
            return None;
        }
        let r = |p: &Bern| p.restrict(a, b);
        let facets = self
            .facets
            .iter()
            .map(|f| {
                let split = split_part(&f.split, (a, b));
                let inertial = split_under(&split, law);
                Facet { others: f.others.iter().map(|(k, d)| (*k, r(d))).collect(), load: (r(&f.load.0), inertial), split, reach2: f.reach2.as_ref().map(r) }
            })
            .collect();
        Some(FacetPolys { facets, len2: self.len2.iter().map(r).collect(), weight: r(&self.weight), scale: self.scale.as_ref().map(r), split: true })
    }

    /// The sweep's polynomials, built if they are not yet (or, when `split` asks for the
    /// inertial parts apart from the law, they are not).
    fn of(sweep: &mut Sweep, load: &Load, split: bool) -> Rc<FacetPolys> {
        match &sweep.facets {
            Some(p) if !split || p.split => Rc::clone(p),
            _ => {
                let p = Rc::new(FacetPolys::new(sweep, load, split));
                sweep.facets = Some(Rc::clone(&p));
                p
            }
        }
    }
}

/// Wrench closure (thesis WCC), where the scenario asks for it (`wrench.closure`).
#[derive(Debug, Clone)]
pub struct WrenchClosure {
    /// The load (its wrench point fixes the moment arm; closure does not depend on it but the
    /// structure matrix is built the same way as for the other wrench conditions).
    pub load: Rc<Load>,
}

impl Condition for WrenchClosure {
    fn kind(&self) -> Kind {
        Kind::Tension
    }

    fn label(&self) -> String {
        "wrench closure".to_string()
    }

    fn prepare(&self, sweep: &mut Sweep) {
        FacetPolys::of(sweep, &self.load, true);
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let tol = sweep.tol;
        let polys = FacetPolys::of(sweep, &self.load, false);
        not_spanning(polys.facets.iter().map(|f| f.others.iter().map(|(_, d)| d.clone()).collect()), tol)
    }

    fn check(&self, at: &PoseCables) -> PoseCheck {
        PoseCheck { violated: !closure_holds(&at.cables, &self.load.wrench.point_at(&at.pose), self.load.rows()), distance: None }
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

/// Wrench feasibility of a robot with more cables than degrees of freedom: every wrench of the ellipsoid around the
/// load is balanced by tensions strictly within their bounds.
#[derive(Debug, Clone)]
pub struct WrenchFeasibility {
    /// The load: the wrench set (ellipsoid, nominal wrench, application point), weight, inertia.
    pub load: Rc<Load>,
    /// Tension bounds per cable.
    pub bounds: Vec<Bounds>,
}

/// Deepest bisection of the static-feasibility decision before a piece is reported undecided.
const MAX_NODES: usize = 4_000;

/// One facet on a piece of the motion: (k, d_k) for the other columns, d_0 at the motion's
/// timing, r_S².
/// A facet's other columns on a piece: (k, d_k).
type Others = Vec<(usize, Bern)>;

type LocalFacet = (Others, Bern, Option<Bern>);

impl WrenchFeasibility {
    /// The truth of "wrench-feasible" on the piece of the motion where `polys` are expanded
    /// (all of them restricted to it): True, False, or Unknown when the enclosures cannot tell —
    /// then with the positions in `polys` of the facets not certainly satisfied (a facet that
    /// holds on a piece holds on every part of it, so only those need looking at there).
    fn decide(&self, polys: &[LocalFacet], len2: &[Bern], weight: &Bern, scale: Option<&Bern>) -> (Truth, Vec<usize>) {
        let w = Iv::of(weight);
        // 1/w^q: the loads' positive factor divided out
        let inv_scale = scale.map(|q| {
            let q = Iv::of(q);
            if q.lo > 0.0 { Iv { lo: 1.0 / q.hi, hi: 1.0 / q.lo } } else { Iv { lo: 0.0, hi: f64::INFINITY } }
        });
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
        let mut open = Vec::new();
        for (pos, (others, load, reach2)) in polys.iter().enumerate() {
            let d0 = Iv::of(load);
            // the ellipsoid's reach r = √(r²) (over the same w^q as d_0)
            let reach = reach2.as_ref().map_or(Iv { lo: 0.0, hi: 0.0 }, |r| {
                let r = Iv::of(r);
                Iv { lo: r.lo.max(0.0).sqrt(), hi: r.hi.max(0.0).sqrt() }
            });
            // the extreme loads d_0 ∓ r, divided by w^q
            let (d_lo, d_hi) = (Iv { lo: d0.lo - reach.hi, hi: d0.hi - reach.lo }, Iv { lo: d0.lo + reach.lo, hi: d0.hi + reach.hi });
            let (d_lo, d_hi) = match inv_scale {
                Some(s) => (d_lo.mul(s), d_hi.mul(s)),
                None => (d_lo, d_hi),
            };
            let (mut lower, mut upper) = (Iv { lo: 0.0, hi: 0.0 }, Iv { lo: 0.0, hi: 0.0 });
            for (k, d) in others {
                let b = self.bounds[*k];
                let (lo_t, hi_t) = Iv::of(d).min_max_of_scaled(b.min, b.max);
                lower = lower.add(lo_t.mul(inv_rho[*k]));
                upper = upper.add(hi_t.mul(inv_rho[*k]));
            }
            // margins: upper − (d0 + r) > 0 and (d0 − r) − lower > 0
            let above = Iv { lo: upper.lo - d_hi.hi, hi: upper.hi - d_hi.lo };
            let below = Iv { lo: d_lo.lo - lower.hi, hi: d_lo.hi - lower.lo };
            if above.hi < 0.0 || below.hi < 0.0 {
                return (Truth::False, Vec::new());
            }
            if !(above.lo > 0.0 && below.lo > 0.0) {
                open.push(pos);
            }
        }
        if open.is_empty() {
            (Truth::True, open)
        } else {
            (Truth::Unknown, open)
        }
    }

    /// Bisection over [a, b] ⊆ [0, 1], the facets in `local` (and the squared lengths, weight and
    /// scale) expanded on it: pieces of `out` as (end, feasible?). Each half is expanded from
    /// this piece by one de Casteljau split at ½ (not again from [0, 1]), and only the facets
    /// not yet certainly satisfied go on.
    fn bisect(&self, local: Piece, (a, b): (f64, f64), tol: f64, budget: &mut usize, out: &mut Vec<(f64, Truth)>) {
        let (truth, open) = self.decide(&local.facets, &local.len2, &local.weight, local.scale.as_ref());
        // a quarter of the tolerance: two undecided neighbours merged stay narrower than it
        if truth != Truth::Unknown || b - a <= 0.25 * tol || *budget == 0 {
            out.push((b, truth));
            return;
        }
        *budget -= 1;
        let (left, right) = local.halves(&open);
        let mid = 0.5 * (a + b);
        self.bisect(left, (a, mid), tol, budget, out);
        self.bisect(right, (mid, b), tol, budget, out);
    }
}

/// What the bisection looks at on one piece: the live facets, the squared cable lengths, the
/// weight and the loads' scale, expanded there.
struct Piece {
    facets: Vec<LocalFacet>,
    len2: Vec<Bern>,
    weight: Bern,
    scale: Option<Bern>,
}

impl Piece {
    /// The facets `live` of `all` (with the loads `loads`) on all of [0, 1].
    fn whole(all: &FacetPolys, loads: &[Bern], live: &[usize]) -> Piece {
        let facets = live.iter().map(|&i| (all.facets[i].others.clone(), loads[i].clone(), all.facets[i].reach2.clone())).collect();
        Piece { facets, len2: all.len2.clone(), weight: all.weight.clone(), scale: all.scale.clone() }
    }

    /// The two halves, keeping the facets at positions `open`.
    fn halves(&self, open: &[usize]) -> (Piece, Piece) {
        let split_all = |ps: &[Bern]| -> (Vec<Bern>, Vec<Bern>) { ps.iter().map(|p| p.split(0.5)).unzip() };
        let mut facets = (Vec::with_capacity(open.len()), Vec::with_capacity(open.len()));
        for &pos in open {
            let (others, load, reach2) = &self.facets[pos];
            let (ol, or): (Others, Others) = others
                .iter()
                .map(|(k, d)| {
                    let (l, r) = d.split(0.5);
                    ((*k, l), (*k, r))
                })
                .unzip();
            let (ll, lr) = load.split(0.5);
            let (rl, rr) = match reach2 {
                Some(p) => {
                    let (l, r) = p.split(0.5);
                    (Some(l), Some(r))
                }
                None => (None, None),
            };
            facets.0.push((ol, ll, rl));
            facets.1.push((or, lr, rr));
        }
        let (len_l, len_r) = split_all(&self.len2);
        let (w_l, w_r) = self.weight.split(0.5);
        let (s_l, s_r) = match &self.scale {
            Some(q) => {
                let (l, r) = q.split(0.5);
                (Some(l), Some(r))
            }
            None => (None, None),
        };
        (Piece { facets: facets.0, len2: len_l, weight: w_l, scale: s_l }, Piece { facets: facets.1, len2: len_r, weight: w_r, scale: s_r })
    }
}

impl Condition for WrenchFeasibility {
    fn kind(&self) -> Kind {
        Kind::Tension
    }

    fn label(&self) -> String {
        "wrench feasibility".to_string()
    }

    fn prepare(&self, sweep: &mut Sweep) {
        FacetPolys::of(sweep, &self.load, true);
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let tol = sweep.tol;
        let polys = FacetPolys::of(sweep, &self.load, false);
        let live: Vec<usize> = (0..polys.facets.len()).filter(|&i| !polys.facets[i].degenerate()).collect();
        if live.is_empty() {
            return Partition::constant(Truth::True); // rank < n − 1 all along: nothing is balanced
        }
        let mut pieces = Vec::new();
        let mut budget = MAX_NODES;
        let inv_t2 = inverse_square(sweep.duration);
        let loads: Vec<Bern> = polys.facets.iter().map(|f| with_inertia(&f.load.0, f.load.1.as_ref(), inv_t2)).collect();
        self.bisect(Piece::whole(&polys, &loads, &live), (0.0, 1.0), tol, &mut budget, &mut pieces);
        Partition::from_pieces(pieces).not()
    }

    fn check(&self, at: &PoseCables) -> PoseCheck {
        let wrench = &self.load.wrench;
        match wrench_set_margin(&at.cables, &wrench.point_at(&at.pose), &at.nominal(&self.load), &wrench.ellipsoid_inv, &self.bounds, self.load.rows()) {
            Some(margin) => PoseCheck { violated: !(margin > 0.0), distance: Some(margin) },
            None => PoseCheck { violated: true, distance: None },
        }
    }
}
