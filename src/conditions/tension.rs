//! Wrench feasibility of a robot with as many cables as degrees of freedom (six on a spatial
//! platform, three on a point mass or a planar platform, whose structure matrix has the rows of
//! the wrench components it balances) as exact conditions: cable i's tension stays within its
//! lower (upper) bound for every wrench of the ellipsoid W (Bohigas et al. §3).
//!
//! Along a motion every quantity is a polynomial in λ once denominators are cleared (the
//! derivation is `docs/wrench.md`, "Exact intervals"): with the unnormalised structure matrix Ñ
//! (columns [s̃_i ; r̃_i × s̃_i], rows scaled by powers of the motion's weight w), its determinant
//! Δ, the cofactors of each column, α_i = (adj Ñ · D_w w0)_i and β_i = ĉ_iᵀ D_w E⁻¹ D_w ĉ_i ≥ 0,
//!
//!   f0,i = ρ_i α_i / Δ,   v_ii = ρ_i √β_i / |Δ|,   ρ_i = √P_i / w,  P_i = ‖s̃_i‖².
//!
//! On a piece where sign Δ = σ is constant, a_i = σ α_i and the bounds become
//! √P_i (a_i ∓ √β_i) ≷ f·w·|Δ|, which the case splits below turn into strict polynomial sign
//! conditions without square roots. Singular poses (Δ = 0) violate both bounds of every cable
//! whose adjugate row does not vanish there; they always lie inside a violated interval.

use std::borrow::Cow;
use std::rc::Rc;

use super::algebra::H;
use super::load::{inverse_square, split_part, split_under, with_inertia, TimeLaw};
use super::primitives::{all_of, any_of, GT, LT};
use super::structure::{quadratic_form, row_weight, structure_numerators};
use super::{Condition, Kind, Local, PoseCheck, Sweep};
use crate::model::Load;
use crate::poly::{Bern, Minors, Partition, Truth};
use crate::query::cables::PoseCables;

/// Which tension bound a [`CableTension`] condition is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TensionSide {
    /// f0,i − v_ii > f_min,i.
    Lower,
    /// f0,i + v_ii < f_max,i.
    Upper,
}

/// One tension bound of one cable of a robot with as many cables as degrees of freedom, over the
/// whole wrench ellipsoid.
#[derive(Debug, Clone)]
pub struct CableTension {
    /// The cable (0-based, below the degrees of freedom).
    pub cable: usize,
    /// Which bound.
    pub side: TensionSide,
    /// The bound's value (f_min,i or f_max,i; finite).
    pub bound: f64,
    /// What the cables balance (wrench set, weight, inertia), shared by the twelve conditions of
    /// a robot.
    pub load: Rc<Load>,
}

/// One cable's polynomials in [`TensionPolys`].
#[derive(Debug, Clone)]
struct Column {
    cable: usize,
    /// α_i's static part; with a load over w^q (inertia) it carries the factor w^q.
    alpha: Bern,
    /// β_i (with the factor w^2q).
    beta: Bern,
    /// α_i's inertial part per unit g·g' and per unit g² ([`super::load::Inertial`]), along a
    /// timed motion.
    split: Option<(Bern, Bern)>,
    /// α_i's inertial part under the motion's law for one second: a motion run in T seconds has
    /// α_i = alpha + inertial/T².
    inertial: Option<Bern>,
}

/// The polynomials the tension conditions of one motion share, on one λ-interval.
#[derive(Debug, Clone)]
pub struct TensionPolys {
    /// The λ-interval [c, d] they are expanded on (λ = c + (d − c)·x).
    span: (f64, f64),
    /// The motion's polynomials there, to re-expand refined pieces from; `None` for those of a
    /// part of a sweep ([`TensionPolys::part`]), which re-expand from the part's sweep.
    local: Option<Local>,
    /// The motion's weight w there.
    weight: Bern,
    /// w^q, the positive factor the load carries (`None` for 1).
    scale: Option<Bern>,
    /// Δ = det Ñ.
    delta: Bern,
    /// The cables expanded here (all on a whole motion, one on a refined piece).
    columns: Vec<Column>,
    /// P_i = ‖s̃_i‖² per cable.
    len2: Vec<Bern>,
    /// Whether the wrench set is its nominal wrench alone (E⁻¹ = 0, so β_i = 0).
    single: bool,
}

impl TensionPolys {
    /// The shared polynomials of `sweep` (whose robot has as many cables as `load` has wrench
    /// components: 6, or 3 for a point mass or a planar platform) under `load`; with `split`, the
    /// inertial parts kept apart from the time law too, for parts of the sweep ([`Self::part`]).
    pub fn new(sweep: &Sweep, load: &Load, split: bool) -> TensionPolys {
        let all: Vec<usize> = (0..load.rows().len()).collect();
        TensionPolys::on(Local::of(sweep, load), (0.0, 1.0), load, &all, split)
    }

    /// Whether they keep the inertial parts apart from the time law (or have none).
    pub fn is_split(&self) -> bool {
        self.columns.iter().all(|c| c.inertial.is_none() || c.split.is_some())
    }

    /// The polynomials on the part [a, b] of the motion they were expanded on (all of it),
    /// re-parametrised to [0, 1] and run by `law` there (for one second): restricted, not
    /// expanded again — the part's λ̈' and λ̇'² weigh the inertial parts by h and h² (h = b − a).
    /// `None` when the inertial parts were not kept apart from the law ([`Self::is_split`]).
    pub fn part(&self, (a, b): (f64, f64), law: Option<&TimeLaw>) -> Option<TensionPolys> {
        if !self.is_split() || self.span != (0.0, 1.0) {
            return None;
        }
        let r = |p: &Bern| p.restrict(a, b);
        let columns = self
            .columns
            .iter()
            .map(|c| {
                let split = split_part(&c.split, (a, b));
                let inertial = split_under(&split, law);
                Column { cable: c.cable, alpha: r(&c.alpha), beta: r(&c.beta), split, inertial }
            })
            .collect();
        Some(TensionPolys {
            span: (0.0, 1.0),
            local: None,
            weight: r(&self.weight),
            scale: self.scale.as_ref().map(r),
            delta: r(&self.delta),
            columns,
            len2: self.len2.iter().map(r).collect(),
            single: self.single,
        })
    }

    /// α_i (for a motion run in T seconds, `inv_t2` = 1/T², 0 at rest) and β_i of cable i, if
    /// expanded here.
    fn column(&self, i: usize, inv_t2: f64) -> Option<(Bern, &Bern)> {
        self.columns.iter().find(|c| c.cable == i).map(|c| (with_inertia(&c.alpha, c.inertial.as_ref(), inv_t2), &c.beta))
    }

    /// Cable i's polynomials (and Δ) re-expanded on [c, d] ⊆ [0, 1] of `sweep`'s motion.
    fn refined(&self, (c, d): (f64, f64), load: &Load, i: usize, sweep: &Sweep) -> TensionPolys {
        let (c0, d0) = self.span;
        let whole = match &self.local {
            Some(local) => Cow::Borrowed(local),
            None => Cow::Owned(Local::of(sweep, load)),
        };
        let local = whole.restrict((c - c0) / (d0 - c0), (d - c0) / (d0 - c0));
        TensionPolys::on(local, (c, d), load, &[i], false)
    }

    fn on(local: Local, span: (f64, f64), load: &Load, cables: &[usize], split: bool) -> TensionPolys {
        let wrench = &load.wrench;
        let w = &local.weight;
        let rows = load.rows();
        let dim = rows.len();
        let n = structure_numerators(&local, wrench, rows);
        let w2 = w.mul(w);
        let mut delta: Option<Bern> = None;
        let mut columns = Vec::with_capacity(cables.len());
        let mut minors = Minors::new(&n);
        for &i in cables {
            let others: Vec<usize> = (0..dim).filter(|&c| c != i).collect();
            let minors = minors.of(&others);
            // Cofactors C_ji = (−1)^{i+j} M_ji; Δ = Σ_j Ñ_ji C_ji; g_j = w^{k_j} C_ji.
            let cofactors: Vec<Bern> = (0..dim).map(|j| if (i + j) % 2 == 0 { minors[j].clone() } else { minors[j].scale(-1.0) }).collect();
            if delta.is_none() {
                delta = Some((0..dim).fold(Bern::constant(0.0), |d, j| d.add(&n[j][i].mul(&cofactors[j]))));
            }
            let g: Vec<Bern> = cofactors.iter().zip(rows).map(|(c, &row)| c.mul(row_weight(row, w, &w2))).collect();
            // α = Σ C_j (D_w ℓ)_j w^q
            let dot = |load_rows: &[Bern; 6]| (0..dim).fold(Bern::constant(0.0), |acc, j| acc.add(&cofactors[j].mul(&load_rows[rows[j]])));
            let alpha = match (&local.load.scale, load.dynamics.is_some()) {
                // a constant load: α = Σ g_j w0_j
                (None, false) => Bern::linear_combination(&(0..dim).map(|j| (&g[j], wrench.nominal[rows[j]])).collect::<Vec<_>>()),
                _ => dot(&local.load.rows),
            };
            // apart from the law (for parts) or under it: one dot product fewer
            let (split, inertial) = if split {
                let split = local.load.inertial.as_ref().map(|r| (dot(&r.accel), dot(&r.square)));
                let inertial = split_under(&split, local.law.as_ref());
                (split, inertial)
            } else {
                (None, local.inertial().map(dot))
            };
            // β = 0 for a single wrench: not expanded (the single wrench's conditions never read it)
            let beta = if wrench.is_single() { Bern::constant(0.0) } else { local.load.scaled_square(quadratic_form(&g, &wrench.ellipsoid_inv, rows)) };
            columns.push(Column { cable: i, alpha, beta, split, inertial });
        }
        let len2 = local.len2();
        TensionPolys {
            span,
            weight: local.weight.clone(),
            scale: local.load.scale.clone(),
            delta: delta.unwrap_or_else(|| Bern::constant(0.0)),
            columns,
            len2,
            local: Some(local),
            single: wrench.is_single(),
        }
    }
}

/// A polynomial as a fraction with no denominator, for the sign-condition macros.
fn h(p: Bern) -> H {
    H { p, k: 0 }
}

/// `first` and then, unless that is already false everywhere, `rest`.
fn and_then(first: Partition, rest: impl FnOnce() -> Partition) -> Partition {
    if first.is_all(Truth::False) {
        first
    } else {
        first.and(&rest())
    }
}

/// The constants (c, d) of the AM–GM bounds √β ≤ (β + c²)/(2c) and √P ≤ (P + d²)/(2d), c² and
/// d² the largest Bernstein coefficients of β and P, so that each bound is off by at most c/2
/// (d/2); `None` when either vanishes.
fn amgm(beta: &Bern, p: &Bern) -> Option<(f64, f64)> {
    let (c, d) = (beta.max_abs().sqrt(), p.max_abs().sqrt());
    (c > 0.0 && d > 0.0 && c.is_finite() && d.is_finite()).then_some((c, d))
}

/// How many points of the motion [`Condition::hint`] looks at.
const HINT_PROBES: usize = 8;

/// How many times undecided pieces are re-expanded locally.
const REFINE_ROUNDS: usize = 3;

impl CableTension {
    /// Where the bound is violated on `t`'s span (as a partition of [0, 1] over it): violated
    /// unless (Δ > 0 and it holds with σ = +1) or (Δ < 0 and with σ = −1) — so also wherever Δ
    /// vanishes identically. Undecided, without work, on the ordered, disjoint intervals `spare`
    /// (where other conditions already settle the answer).
    fn violated_on(&self, t: &TensionPolys, inv_t2: f64, tol: f64, spare: &[(f64, f64)]) -> Partition {
        // false on the spared intervals (nothing is classified there), true elsewhere
        let open = Partition::outside(spare);
        let holds = any_of!(
            and_then(all_of!(from open.clone(), tol; h(t.delta.clone()) => GT), || self.holds(t, 1.0, inv_t2, tol, &open)),
            and_then(all_of!(from open.clone(), tol; h(t.delta.clone()) => LT), || self.holds(t, -1.0, inv_t2, tol, &open)),
        );
        // the spared intervals undecided
        holds.or(&open.not().and(&Partition::constant(Truth::Unknown))).not()
    }

    /// Where the bound holds over the whole ellipsoid, assuming sign Δ = `sigma` (the caller
    /// restricts to those pieces), on the pieces where `open` is true (false elsewhere).
    fn holds(&self, t: &TensionPolys, sigma: f64, inv_t2: f64, tol: f64, open: &Partition) -> Partition {
        let i = self.cable;
        let Some((alpha, beta)) = t.column(i, inv_t2) else { return Partition::constant(Truth::Unknown) };
        let a = alpha.scale(sigma);
        let abs_delta = t.delta.scale(sigma);
        let p = &t.len2[i];
        // 4 P² a² β, the square of the cross term 2 P a √β.
        let cross = || {
            let pa = p.mul(&a);
            pa.mul(&pa).mul(beta).scale(4.0)
        };
        let a2_minus_b = || a.mul(&a).sub(beta);
        // f·w·|Δ|(·w^q): the bound with the denominators of ρ, Δ (and the load) cleared.
        let scaled_bound = || {
            let k = t.weight.mul(&abs_delta).scale(self.bound);
            match &t.scale {
                Some(q) => k.mul(q),
                None => k,
            }
        };
        let open = || open.clone();
        match self.side {
            // a single wrench (β = 0): √P a > k ≥ 0 iff a > 0 and P a² > k² (for k = 0, a > 0);
            // √P a < K iff a < 0 or K² > P a²
            TensionSide::Lower if t.single && self.bound == 0.0 => all_of!(from open(), tol; h(a.clone()) => GT),
            TensionSide::Lower if t.single => {
                let k = scaled_bound();
                all_of!(from open(), tol; h(a.clone()) => GT, h(p.mul(&a.mul(&a)).sub(&k.mul(&k))) => GT)
            }
            TensionSide::Upper if t.single => {
                let kk = scaled_bound();
                any_of!(all_of!(from open(), tol; h(a.clone()) => LT), all_of!(from open(), tol; h(kk.mul(&kk).sub(&p.mul(&a.mul(&a)))) => GT))
            }
            // √P (a − √β) > k with k ≥ 0: a > √β, then square.
            TensionSide::Lower if self.bound == 0.0 => all_of!(from open(), tol; h(a.clone()) => GT, h(a2_minus_b()) => GT),
            TensionSide::Lower => {
                let k = scaled_bound();
                let l = || p.mul(&a.mul(&a).add(beta)).sub(&k.mul(&k));
                all_of!(from open(), tol;
                    h(a.clone()) => GT,
                    h(a2_minus_b()) => GT,
                    h(l()) => GT,
                    h({ let l = l(); l.mul(&l).sub(&cross()) }) => GT,
                )
            }
            // √P (a + √β) < K; with M = K² − P (a² + β): for a ≥ 0 iff M > 2 P a √β; for a < 0
            // it holds when a + √β ≤ 0, else iff M > −2 P |a| √β.
            TensionSide::Upper => {
                let kk = scaled_bound();
                let cert = match amgm(beta, p) {
                    Some((c, d)) if self.bound >= 0.0 => {
                        // √P (a + √β) ≤ (P + d²)(2ca + β + c²)/(4cd) for a ≥ 0
                        let s = kk.scale(4.0 * c * d).sub(&Bern::linear_combination(&[(p, 1.0), (&Bern::constant(d * d), 1.0)]).mul(&Bern::linear_combination(&[(&a, 2.0 * c), (beta, 1.0), (&Bern::constant(c * c), 1.0)])));
                        all_of!(from open(), tol; h(a.clone()) => GT, h(s) => GT)
                    }
                    _ => Partition::constant(Truth::Unknown),
                };
                // the exact squares only where the certificate leaves it open
                let start = open().and(&cert.is_not(Truth::True));
                if start.is_all(Truth::False) {
                    return cert;
                }
                let m = || kk.mul(&kk).sub(&p.mul(&a.mul(&a).add(beta)));
                cert.or(&any_of!(
                    all_of!(from start.clone(), tol; h(a.clone()) => GT, h(m()) => GT, h({ let m = m(); m.mul(&m).sub(&cross()) }) => GT),
                    and_then(all_of!(from start, tol; h(a.clone()) => LT), || any_of!(
                        all_of!(tol; h(a2_minus_b()) => GT),
                        all_of!(tol; h(m()) => GT),
                        all_of!(tol; h({ let m = m(); cross().sub(&m.mul(&m)) }) => GT),
                    )),
                ))
            }
        }
    }
}

impl CableTension {
    /// The sweep's shared polynomials, built by the first condition that needs them (again with
    /// the inertial parts apart from the law when `split` asks for them and they are not).
    fn polys(&self, sweep: &mut Sweep, split: bool) -> Rc<TensionPolys> {
        match &sweep.tension {
            Some(p) if !split || p.is_split() => Rc::clone(p),
            _ => {
                let p = Rc::new(TensionPolys::new(sweep, &self.load, split));
                sweep.tension = Some(Rc::clone(&p));
                p
            }
        }
    }
}

impl Condition for CableTension {
    fn kind(&self) -> Kind {
        Kind::Tension
    }

    fn label(&self) -> String {
        let side = match self.side {
            TensionSide::Lower => "lower",
            TensionSide::Upper => "upper",
        };
        format!("cable {} tension {side} bound", self.cable + 1)
    }

    fn cables(&self) -> Vec<usize> {
        vec![self.cable]
    }

    fn prepare(&self, sweep: &mut Sweep) {
        self.polys(sweep, true);
    }

    /// The first of [`HINT_PROBES`] evenly spread points where the tension range read off the
    /// polynomials' control polygons (each coefficient c_k stands for the value at k/n) crosses
    /// the bound.
    fn hint(&self, sweep: &mut Sweep) -> Option<f64> {
        let t = self.polys(sweep, false);
        let c = t.columns.iter().find(|c| c.cable == self.cable)?;
        let inv_t2 = inverse_square(sweep.duration);
        let at = |p: &Bern, x: f64| p.c[(x * p.degree() as f64).round() as usize];
        // the bound against √P (a ∓ √β) with the denominators cleared, as the conditions have it
        let violated = |x: f64| {
            let delta = at(&t.delta, x);
            let a = delta.signum() * (at(&c.alpha, x) + c.inertial.as_ref().map_or(0.0, |p| inv_t2 * at(p, x)));
            let cleared = self.bound * at(&t.weight, x) * delta.abs() * t.scale.as_ref().map_or(1.0, |q| at(q, x));
            let (root_p, root_b) = (at(&t.len2[self.cable], x).max(0.0).sqrt(), at(&c.beta, x).max(0.0).sqrt());
            match self.side {
                TensionSide::Lower => !(root_p * (a - root_b) > cleared),
                TensionSide::Upper => !(root_p * (a + root_b) < cleared),
            }
        };
        Some((0..HINT_PROBES).map(|j| (j as f64 + 0.5) / HINT_PROBES as f64).find(|&x| violated(x)).unwrap_or(f64::INFINITY))
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let polys = self.polys(sweep, false);
        self.violated_on(&polys, inverse_square(sweep.duration), sweep.tol, &sweep.settled)
    }

    /// Undecided pieces wider than the tolerance (outside the sweep's settled intervals): the
    /// motion re-expanded around each and decided again, where error bounds follow the local
    /// (often much smaller) magnitudes.
    fn refine(&self, sweep: &mut Sweep, found: Partition) -> Partition {
        let tol = sweep.tol;
        let polys = self.polys(sweep, false);
        let inv_t2 = inverse_square(sweep.duration);
        let mut out = found;
        for _ in 0..REFINE_ROUNDS {
            let settled = &sweep.settled;
            let wide: Vec<(f64, f64)> = out
                .intervals()
                .into_iter()
                .filter(|&(a, b, t)| t == Truth::Unknown && b - a > tol && !settled.iter().any(|&(c, d)| c <= a && b <= d))
                .map(|(a, b, _)| (a, b))
                .collect();
            if wide.is_empty() {
                break;
            }
            for (a, b) in wide {
                let span = ((a - (b - a)).max(0.0), (b + (b - a)).min(1.0));
                let local = polys.refined(span, &self.load, self.cable, sweep);
                let inner = self.violated_on(&local, inv_t2, tol / (span.1 - span.0), &[]);
                out = out.splice((a, b), &inner, span);
            }
        }
        out
    }

    fn check(&self, at: &PoseCables) -> PoseCheck {
        match at.tension_ranges(&self.load) {
            None => PoseCheck { violated: true, distance: None },
            Some(ranges) => {
                let r = ranges[self.cable];
                let margin = match self.side {
                    TensionSide::Lower => r.nominal - r.spread - self.bound,
                    TensionSide::Upper => self.bound - r.nominal - r.spread,
                };
                PoseCheck { violated: !(margin > 0.0), distance: Some(margin) }
            }
        }
    }
}
