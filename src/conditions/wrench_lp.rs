//! Wrench feasibility of a single wrench by linear programs, for any number of cables (the method
//! that scales: no C(m, 5) facets as in [`super::closure`]): along a motion, the nominal load —
//! the wrench set's w0 plus the platform's weight and inertia — must be balanced by tensions
//! strictly within their bounds. The verifier uses it for every robot with more than six cables
//! whose wrench set has no ellipsoid.
//!
//! The system is written scaled so that only the cable lengths stay non-polynomial: with N the
//! structure numerators ([`structure_numerators`]), `load` the load rows and W = w·w^q their
//! positive factor, J f = w_required ⇔ N φ = load with φ_k = W f_k / L_k (L_k = √P_k, P_k the
//! squared cable length times w²). On a piece of the motion (its polynomials re-expanded there by
//! halving) each 1/L_k is its linear Taylor polynomial s_k(λ) at the middle within ±ε_k (the
//! remainder bounded from enclosures of P_k, P_k', P_k''), and the middle's linear programs give
//! the certificates:
//!
//! * **Feasible**: f* and t* > 0, the largest-margin tensions at the middle
//!   ([`crate::query::wrench::static_margin_of`]) — or first, without a linear program, the last
//!   feasible piece's tensions (on a motion's first piece, the middle of the bounds) moved by
//!   the least-norm correction that balances this middle, if they stay within the bounds (any
//!   tensions balancing the middle serve: the certificate below bounds the rest). The tension
//!   law φ = W ψ, ψ_k = s_k f*_k + (λ − ½) γ_k + (λ − ½)² η_k, with γ and then η chosen (least
//!   norm, from the entries' values, slopes and curvatures at the middle) so that the residual
//!   ρ = load − N φ vanishes to first and to second order at the middle, leaves a residual of
//!   third order; the correction δ with N δ = ρ has ‖δ‖ ≤ ‖Dρ‖/σ_min(DN) (D a row scaling,
//!   σ_min(DN(λ)) bounded below from the middle's by the entries' ranges). The piece is feasible
//!   when every cable keeps ψ_k − f_min,k s_k − |f_min,k| ε_k − ‖δ‖/W > 0 (the quadratic's least
//!   Bernstein coefficient) and likewise below f_max,k.
//! * **Infeasible**: a direction y from the middle ([`crate::query::wrench::separating_direction`])
//!   with y·load above the zonotope's support Σ_k u_k max(f_min,k a_k, f_max,k a_k) (a_k = y·n_k,
//!   u_k = W/L_k) throughout; each max is bounded above by its chord over a_k's range (exact when
//!   a_k keeps its sign), so the excess is one polynomial less Σ_k W ε_k |…|.
//! * Otherwise the piece is halved, down to the boundary tolerance; what stays is undecided.
//!
//! **A wrench ellipsoid** beyond the facets' reach (more than [`crate::scenario::validate::MAX_FACETS`]
//! facet pairs: 11 cables and more on a spatial platform) is decided with the same system and a
//! cover of the wrench directions ([`crate::query::zonotope`]): at the piece's middle, cones of
//! directions each with tensions f whose minorant y·J̃f − h_W̃(y) is positive at the cone's rays
//! (the scaled ellipsoid W̃ = D W, D the rows' positive factors: W for forces, W·w for moments),
//! each clearing how far the columns, the load and the ellipsoid's reach drift over the piece
//! (enclosures of the polynomials and of 1/L_k). The cones are fixed sets of directions, so one
//! cover, refined where a piece needs it, serves every piece of the motion. **Infeasible** where
//! a direction y of the middle with G(y) < 0 keeps y·load + reach(y) above the zonotope's
//! support throughout (the certificate above, with the reach's least value on the piece added).
//!
//! **Wrench closure** beyond the facets' reach ([`WrenchFeasibilityLp::closure`]) is the same
//! program with the zero load and tensions in [1, ∞) (up to scale, a strictly positive null vector
//! of J; the feasible certificate's σ_min bound gives rank 6). Where it fails the zero load lies on
//! the zonotope's boundary, so no direction separates it strictly; instead a direction y with
//! every column strictly on its negative side ([`crate::query::wrench::enclosing_direction`])
//! shows that J f = 0 has no solution f ≥ 1, and the infeasible certificate above holds with it.
//!
//! Both certificates are sufficient and both margins are exact polynomials up to second-order
//! terms, so each certificate holds on small enough pieces wherever the condition holds (or
//! fails) strictly: only the boundaries' neighbourhoods stay undecided, and stretches that graze
//! the boundary need pieces of width ~√(margin), not ~margin. The cost per piece is two linear
//! programs in O(m) variables, O(m) polynomial linear combinations and a few products.

use std::borrow::Cow;
use std::cell::RefCell;
use std::rc::Rc;

use nalgebra::{DMatrix, DVector};

use super::interval::Iv;
use super::load::{inverse_square, with_inertia};
use super::structure::{quadratic_form, structure_numerators};
use super::{Condition, Kind, Local, PoseCheck, Sweep};
use crate::model::{Bounds, Load};
use crate::poly::{Bern, Partition, Truth};
use crate::query::cables::PoseCables;
use crate::query::wrench::{closure_by_lp, enclosing_direction, select, select_square, separating_direction, static_margin, static_margin_of, structure_matrix_m};
use crate::query::zonotope::{contains, Containment, Cover, Verdict};

/// Most pieces one motion is bisected into before the rest is reported undecided.
const MAX_NODES: usize = 4_000;

/// Most cuts of the wrench directions' cover along one motion (an ellipsoid's condition).
const MAX_CUTS: usize = 40_000;

/// Relative slack for the rounding of scalar steps outside the polynomials' tracked error.
const SLACK: f64 = 1e-13;

/// Wrench feasibility of the nominal load by linear programs (module docs), or of the load's
/// whole wrench ellipsoid by a cover of the wrench directions; or, with `closure`, wrench closure:
/// the zero load balanced by tensions in [1, ∞) (a strictly positive null vector of J, J of rank
/// 6), shown infeasible by a direction with every column strictly on one side.
#[derive(Debug, Clone)]
pub struct WrenchFeasibilityLp {
    /// The load (its wrench set, with or without an ellipsoid; without for closure).
    pub load: Rc<Load>,
    /// Each cable's tension bounds.
    pub bounds: Vec<Bounds>,
    /// Whether this is wrench closure (load zero, bounds [1, ∞)).
    pub closure: bool,
    /// The tensions of the last piece certified feasible (by any motion of this verification),
    /// to try first on the next: a neighbouring pose is usually balanced by nearly the same.
    warm: RefCell<Option<Vec<f64>>>,
}

impl WrenchFeasibilityLp {
    /// Wrench feasibility of `load` (its nominal wrench, or its ellipsoid) with tensions within
    /// `bounds`.
    pub fn new(load: Rc<Load>, bounds: Vec<Bounds>) -> WrenchFeasibilityLp {
        WrenchFeasibilityLp { load, bounds, closure: false, warm: RefCell::new(None) }
    }

    /// Wrench closure of `m` cables about the point of `load`'s wrench set.
    pub fn closure(load: &Load, m: usize) -> WrenchFeasibilityLp {
        let wrench = crate::model::Wrench { point: load.wrench.point, frame: load.wrench.frame, ..crate::model::Wrench::zero() };
        let bounds = vec![Bounds { min: 1.0, max: f64::INFINITY }; m];
        WrenchFeasibilityLp { closure: true, ..WrenchFeasibilityLp::new(Rc::new(Load { wrench, dynamics: None, mobility: load.mobility }), bounds) }
    }

    /// The middle of every cable's tension bounds (`None` where one is unbounded above).
    fn centre(&self) -> Option<Vec<f64>> {
        self.bounds.iter().map(|b| b.max.is_finite().then(|| 0.5 * (b.min + b.max))).collect()
    }
}

/// `f` moved by the least-norm correction that balances the load `b` at J = `j` (J f = b), if
/// the result stays strictly within `bounds`.
fn balanced(j: &DMatrix<f64>, b: &DVector<f64>, f: &[f64], bounds: &[Bounds]) -> Option<Vec<f64>> {
    if f.len() != j.ncols() {
        return None;
    }
    let f = DVector::from_column_slice(f);
    let y = (j * j.transpose()).lu().solve(&(b - j * &f))?;
    let f = f + j.transpose() * y;
    f.iter().zip(bounds).all(|(x, bd)| *x > bd.min && *x < bd.max).then(|| f.iter().copied().collect())
}

/// The scaled system on a piece of the motion: N (n × m, the wrench components balanced), the
/// load rows at the motion's timing,
/// their factor W = w·w^q, and per cable P_k with its first and second derivatives in the
/// motion's parameter (taken on the whole motion and halved along: derivatives of the local
/// expansions would carry rounding amplified by the degree at every level), and the piece's width.
#[derive(Debug, Clone)]
struct Piece {
    n: Vec<Vec<Bern>>,
    load: Vec<Bern>,
    w: Bern,
    len2: Vec<[Bern; 3]>,
    width: f64,
    /// For a multi-link robot with routed cables: the cable of each column of `n` (a segment of
    /// it, `len2` that segment's), the cable's column the sum of its segments' n_s/L_s; `None`:
    /// one column per cable.
    cable_of: Option<Rc<Vec<usize>>>,
    /// With a wrench ellipsoid: each row's positive factor d_r (W for a force, W·w for a
    /// moment), the scaled ellipsoid's shape being D E⁻¹ D.
    row_scale: Option<Vec<Bern>>,
}

impl Piece {
    fn of(sweep: &Sweep, load: &Load) -> Piece {
        let local = Local::of(sweep, load);
        let n = structure_numerators(&local, &load.wrench, load.rows());
        let k = inverse_square(sweep.duration);
        let inertial = local.inertial();
        let rows = load.rows().iter().map(|&j| with_inertia(&local.load.rows[j], inertial.map(|r| &r[j]), k)).collect();
        let w = match &local.load.scale {
            Some(q) => local.weight.mul(q),
            None => local.weight.clone(),
        };
        let row_scale = (!load.wrench.is_single()).then(|| load.rows().iter().map(|&r| if r < 3 { w.clone() } else { w.mul(&local.weight) }).collect());
        Piece { row_scale, ..Piece::new(n, rows, w, local.len2()) }
    }

    /// The system N φ = load on all of [0, 1]: N's rows `n`, the load rows, their factor W and
    /// the cables' squared lengths P_k (with their derivatives taken here).
    fn new(n: Vec<Vec<Bern>>, load: Vec<Bern>, w: Bern, len2: Vec<Bern>) -> Piece {
        let len2 = len2
            .into_iter()
            .map(|p| {
                let d = p.derivative();
                let dd = d.derivative();
                [p, d, dd]
            })
            .collect();
        Piece { len2, n, load, w, width: 1.0, cable_of: None, row_scale: None }
    }

    fn halves(&self) -> (Piece, Piece) {
        let split_all = |ps: &[Bern]| -> (Vec<Bern>, Vec<Bern>) { ps.iter().map(|p| p.split(0.5)).unzip() };
        let (nl, nr): (Vec<Vec<Bern>>, Vec<Vec<Bern>>) = self.n.iter().map(|row| split_all(row)).unzip();
        // the halves of an array's polynomials, as two arrays (moved, not copied)
        fn split_array<const N: usize>(ps: &[Bern; N]) -> ([Bern; N], [Bern; N]) {
            let (l, r): (Vec<Bern>, Vec<Bern>) = ps.iter().map(|p| p.split(0.5)).unzip();
            let array = |v: Vec<Bern>| v.try_into().unwrap_or_else(|_| unreachable!("N halves of N polynomials"));
            (array(l), array(r))
        }
        let (ll, lr) = split_all(&self.load);
        let (wl, wr) = self.w.split(0.5);
        let (pl, pr) = self.len2.iter().map(split_array).unzip();
        let width = 0.5 * self.width;
        let cable_of = self.cable_of.clone();
        let (dl, dr) = match &self.row_scale {
            Some(d) => {
                let (l, r) = split_all(d);
                (Some(l), Some(r))
            }
            None => (None, None),
        };
        (
            Piece { n: nl, load: ll, w: wl, len2: pl, width, cable_of: cable_of.clone(), row_scale: dl },
            Piece { n: nr, load: lr, w: wr, len2: pr, width, cable_of, row_scale: dr },
        )
    }
}

/// A cable's inverse length 1/L on a piece: the affine s with |1/L − s| ≤ `eps` throughout, and
/// its value at the middle.
struct InverseLength {
    s: Bern,
    mid: f64,
    eps: f64,
}

impl InverseLength {
    /// From P = L² (positive on the piece; `None` otherwise) with its derivatives in the motion's
    /// parameter, on a piece `h` wide: the linear Taylor polynomial of P^(−1/2) at ½ and the
    /// bound |g''| ≤ ¾ P^(−5/2) P'² + ½ P^(−3/2) |P''| (local derivatives: h P', h² P'') on its
    /// remainder (times (λ − ½)²/2 ≤ 1/8), plus the rounding of the middle's value and slope.
    fn of([p, d1, d2]: &[Bern; 3], h: f64) -> Option<InverseLength> {
        let range = Iv::of(p);
        if !(range.lo > 0.0 && range.hi.is_finite()) {
            return None;
        }
        let ((pc, e0), (p1, e1)) = (p.eval(0.5), d1.eval(0.5));
        let (p1, e1) = (h * p1, h * e1);
        let g = 1.0 / pc.sqrt();
        let g1 = -0.5 * g / pc * p1;
        let (m1, m2) = (h * Iv::of(d1).mag(), h * h * Iv::of(d2).mag());
        let (r15, r25) = (range.lo.powf(-1.5), range.lo.powf(-2.5));
        let remainder = (0.75 * r25 * m1 * m1 + 0.5 * r15 * m2) / 8.0;
        let rounding = 0.5 * r15 * e0 + 0.5 * (0.75 * r25 * p1.abs() * e0 + 0.5 * r15 * e1) + SLACK * (g + g1.abs());
        let eps = remainder + rounding;
        eps.is_finite().then(|| InverseLength { s: Bern::from_bernstein(vec![g - 0.5 * g1, g + 0.5 * g1]), mid: g, eps })
    }
}

/// The cables' columns of a robot with routed cables on a piece, from its segments' columns `n`
/// and inverse lengths `inv` (`cable_of` the cable of each segment, `m` cables): entry (r, k) the
/// polynomial Σ_s n_rs·s_s over cable k's segments, its error bound grown by Σ_s |n_rs| ε_s; and
/// per cable the unit inverse length (the columns already are the unit pulls).
fn grouped<'a>(n: &[Vec<Bern>], inv: &[InverseLength], cable_of: &[usize], m: usize) -> (Cow<'a, Vec<Vec<Bern>>>, Vec<InverseLength>) {
    let columns = n
        .iter()
        .map(|row| {
            let mut out = vec![Bern::constant(0.0); m];
            for ((entry, il), &k) in row.iter().zip(inv).zip(cable_of) {
                if structurally_zero(entry) {
                    continue;
                }
                let mut term = entry.mul(&il.s);
                term.err += Iv::of(entry).mag() * il.eps;
                out[k] = out[k].add(&term);
            }
            out
        })
        .collect();
    let unit = (0..m).map(|_| InverseLength { s: Bern::from_bernstein(vec![1.0, 1.0]), mid: 1.0, eps: 0.0 }).collect();
    (Cow::Owned(columns), unit)
}

/// Σ_k n_k·ψ_k for a row of N and polynomials ψ_k of degree K − 1 given by their Bernstein
/// coefficients: one linear combination per coefficient (no product per cable), joined by de
/// Casteljau's blends ([`Bern::blend`]).
fn law_sum<const K: usize>(row: &[Bern], c: &[[f64; K]]) -> Bern {
    let mut level: Vec<Bern> = (0..K).map(|j| Bern::linear_combination(&row.iter().zip(c).map(|(p, ck)| (p, ck[j])).collect::<Vec<_>>())).collect();
    while level.len() > 1 {
        level = level.windows(2).map(|pair| Bern::blend(&pair[0], &pair[1])).collect();
    }
    level.pop().unwrap_or_else(|| Bern::constant(0.0))
}

/// The least value of a polynomial on its piece (its Bernstein coefficients' least, less its
/// error).
fn least(p: &Bern) -> f64 {
    Iv::of(p).lo
}

impl WrenchFeasibilityLp {
    /// Feasible (True), infeasible (False) or undecided on the piece; for closure, `blocks` are
    /// sets of rows to look for a failure within as well ([`closure_violation`]); with an
    /// ellipsoid, by the cover `cover` (refined here, within `cuts` more cuts).
    fn decide(&self, piece: &Piece, blocks: &[Vec<usize>], search: &mut Search, open: &mut Option<Vec<usize>>) -> Truth {
        let w = Iv::of(&piece.w);
        if !(w.lo > 0.0 && w.hi.is_finite()) {
            return Truth::Unknown;
        }
        let Some(inv) = piece.len2.iter().map(|p| InverseLength::of(p, piece.width)).collect::<Option<Vec<_>>>() else { return Truth::Unknown };
        let (columns, inv) = match &piece.cable_of {
            None => (Cow::Borrowed(&piece.n), inv),
            Some(cable_of) => grouped(&piece.n, &inv, cable_of, self.bounds.len()),
        };
        let nn: &[Vec<Bern>] = &columns;
        let (n, m) = (nn.len(), inv.len());
        let wc = piece.w.value(0.5);
        let nc = DMatrix::from_fn(n, m, |r, k| nn[r][k].value(0.5));
        // the scaled structure matrix at the middle: columns n_k·W/L_k, and the load rows
        let j = DMatrix::from_fn(n, m, |r, k| nc[(r, k)] * wc * inv[k].mid);
        let b = DVector::from_fn(n, |r, _| piece.load[r].value(0.5));
        if let Some(d) = &piece.row_scale {
            return self.decide_ellipsoid(piece, nn, &inv, &j, &b, d, w, search, open);
        }
        // the last feasible piece's tensions, balanced here, or on a first piece the middle of
        // the bounds: no linear program where they do
        let warm = match self.warm.borrow().as_deref() {
            Some(f) => balanced(&j, &b, f, &self.bounds),
            None => self.centre().and_then(|f| balanced(&j, &b, &f, &self.bounds)),
        };
        if let Some(f) = warm {
            if self.feasible(piece, nn, &inv, &nc, &f, w) == Truth::True {
                *self.warm.borrow_mut() = Some(f);
                return Truth::True;
            }
        }
        match static_margin_of(&j, &b, &self.bounds) {
            Some((t, f)) if t > 0.0 => {
                let truth = self.feasible(piece, nn, &inv, &nc, &f, w);
                if truth == Truth::True {
                    *self.warm.borrow_mut() = Some(f);
                }
                truth
            }
            // a row of N that is zero throughout: rank below n, no closure
            _ if self.closure && nn.iter().any(|row| row.iter().all(structurally_zero)) => Truth::False,
            _ if self.closure => match enclosing_direction(&j).or_else(|| block_direction(nn, &j, blocks)) {
                Some(y) => self.infeasible(piece, nn, &inv, &y, w, None),
                None => Truth::Unknown,
            },
            _ => match separating_direction(&j, &b, &self.bounds) {
                Some((y, _)) => self.infeasible(piece, nn, &inv, &y, w, None),
                None => Truth::Unknown,
            },
        }
    }

    /// The wrench ellipsoid on the piece (module docs): the cover certifies the middle's
    /// scaled problem — J̃ = `j`, the load `b`, the shape D E⁻¹ D with D the rows' factors `d` —
    /// along the piece, or gives a direction to show it infeasible throughout. `open`: the cones
    /// still to certify here (`None`: all, on the motion's first piece), on return those left.
    #[allow(clippy::too_many_arguments)]
    fn decide_ellipsoid(&self, piece: &Piece, nn: &[Vec<Bern>], inv: &[InverseLength], j: &DMatrix<f64>, b: &DVector<f64>, d: &[Bern], w: Iv, search: &mut Search, open: &mut Option<Vec<usize>>) -> Truth {
        let n = j.nrows();
        let e_inv = select_square(&self.load.wrench.ellipsoid_inv, self.load.rows());
        let dc: Vec<f64> = d.iter().map(|p| p.value(0.5)).collect();
        let shape = DMatrix::from_fn(n, n, |a, c| dc[a] * e_inv[(a, c)] * dc[c]);
        let problem = Containment { j, bounds: &self.bounds, centre: b, shape: &shape };
        let cover = search.cover.get_or_insert_with(|| Cover::orthants(n));
        cover.load(&problem);
        let open = open.get_or_insert_with(|| cover.all());
        let mut along = Along { piece, nn, inv, d, e_inv: &e_inv, shape: &shape, shared: None };
        match cover.certify(&problem, Some(&mut |f, rays| along.holds(f, rays)), &mut search.cuts, open) {
            Verdict::Holds => Truth::True,
            Verdict::Fails(ys) => {
                let shown = ys.iter().any(|y| self.infeasible(piece, nn, inv, y, w, Some(d)) == Truth::False);
                if shown { Truth::False } else { Truth::Unknown }
            }
            Verdict::Unknown => Truth::Unknown,
        }
    }

    /// True when the tensions `f` at the middle, carried along the piece to second order and
    /// corrected, stay strictly within the bounds throughout (module docs).
    fn feasible(&self, piece: &Piece, nn: &[Vec<Bern>], inv: &[InverseLength], nc: &DMatrix<f64>, f: &[f64], w: Iv) -> Truth {
        let (n, m) = (nn.len(), inv.len());
        // ψ0_k = s_k f_k (affine); P_r = Σ_k n_rk ψ_k and ρ = load − W P, of which the middle's
        // first and second derivatives are needed: the values, slopes and curvatures there
        let psi0: Vec<[f64; 2]> = inv.iter().zip(f).map(|(i, fk)| [i.s.c[0] * fk, i.s.c[1] * fk]).collect();
        let (wc, wc1, wc2) = piece.w.jet(0.5);
        let loads: Vec<(f64, f64, f64)> = piece.load.iter().map(|p| p.jet(0.5)).collect();
        let jets: Vec<Vec<(f64, f64, f64)>> = nn.iter().map(|row| row.iter().map(|e| e.jet(0.5)).collect()).collect();
        // rows scaled to unit largest entry at the middle
        let d: Vec<f64> = (0..n).map(|r| 1.0 / nc.row(r).amax()).collect();
        if d.iter().any(|x| !x.is_finite()) {
            return Truth::Unknown;
        }
        let dn = DMatrix::from_fn(n, m, |r, k| d[r] * nc[(r, k)]);
        let svd = dn.svd(true, true);
        let (smin, smax) = (svd.singular_values.min(), svd.singular_values.max());
        // P_r, P_r' and P_r'' at the middle for ψ_k = ψ0_k + (λ − ½) g_k (no second-order term:
        // it vanishes there, and enters P'' only through N(½))
        let jet_of_p = |r: usize, g: &[f64]| {
            jets[r].iter().zip(&psi0).zip(g).fold((0.0, 0.0, 0.0), |(v, s, c), ((&(e, e1, e2), psi), gk)| {
                let (mid, rise) = (0.5 * (psi[0] + psi[1]), psi[1] - psi[0] + gk);
                (v + e * mid, s + e1 * mid + e * rise, c + e2 * mid + 2.0 * e1 * rise)
            })
        };
        // γ: least-norm solution of N(½) γ = ρ0'(½)/W(½) (ρ0 of ψ0), so that ρ vanishes to first
        // order; then η: of N(½) 2η = ρ1''(½)/W(½) (ρ1 of ψ0 + (λ − ½)γ), so that it vanishes to
        // second order: ψ_k = s_k f_k + (λ − ½) γ_k + (λ − ½)² η_k and ρ = load − W Σ_k n_k ψ_k
        let zero = vec![0.0; m];
        let slope = DVector::from_fn(n, |r, _| {
            let (p, p1, _) = jet_of_p(r, &zero);
            d[r] * (loads[r].1 - wc1 * p - wc * p1) / wc
        });
        let Ok(gamma) = svd.solve(&slope, SLACK * smax) else { return Truth::Unknown };
        let curvature = DVector::from_fn(n, |r, _| {
            let (p, p1, p2) = jet_of_p(r, gamma.as_slice());
            d[r] * (loads[r].2 - wc2 * p - 2.0 * wc1 * p1 - wc * p2) / (2.0 * wc)
        });
        let Ok(eta) = svd.solve(&curvature, SLACK * smax) else { return Truth::Unknown };
        // in Bernstein form of degree 2: λ − ½ is (−½, 0, ½), (λ − ½)² is (¼, −¼, ¼)
        let psi: Vec<[f64; 3]> = psi0
            .iter()
            .zip(gamma.iter().zip(eta.iter()))
            .map(|(p, (g, e))| [p[0] - 0.5 * g + 0.25 * e, 0.5 * (p[0] + p[1]) - 0.25 * e, p[1] + 0.5 * g + 0.25 * e])
            .collect();
        let residual = (0..n)
            .map(|r| (d[r] * Iv::of(&piece.load[r].sub(&piece.w.mul(&law_sum(&nn[r], &psi)))).mag()).powi(2))
            .sum::<f64>()
            .sqrt();
        // σ_min(D N(λ)) ≥ σ_min(D N(½)) − ‖D (N(λ) − N(½))‖_F
        let mut drift = 0.0;
        for r in 0..n {
            for k in 0..m {
                let range = Iv::of(&nn[r][k]);
                let dev = (range.hi - nc[(r, k)]).max(nc[(r, k)] - range.lo) + nn[r][k].value_error();
                drift += (d[r] * dev).powi(2);
            }
        }
        let sigma = smin - drift.sqrt() - SLACK * smax;
        if !(sigma > 0.0) {
            return Truth::Unknown;
        }
        // |δ_k|/W for the correction δ = N⁺ρ
        let correction = residual / sigma / w.lo;
        // ψ_k − f_min s_k and f_max s_k − ψ_k (quadratic: at least their least Bernstein
        // coefficient, s_k raised to degree 2) must clear ε_k and δ
        let clear = |p: &[f64; 3], s: &Bern, bound: f64, sign: f64, eps: f64| {
            let s2 = [s.c[0], 0.5 * (s.c[0] + s.c[1]), s.c[1]];
            let coefficient = |j: usize| sign * (p[j] - bound * s2[j]) - SLACK * (p[j].abs() + (bound * s2[j]).abs());
            coefficient(0).min(coefficient(1)).min(coefficient(2)) - bound.abs() * eps - correction > 0.0
        };
        for (k, (il, p)) in inv.iter().zip(&psi).enumerate() {
            let Bounds { min, max } = self.bounds[k];
            if !clear(p, &il.s, min, 1.0, il.eps) || (max.is_finite() && !clear(p, &il.s, max, -1.0, il.eps)) {
                return Truth::Unknown;
            }
        }
        Truth::True
    }

    /// False when the direction `y` keeps y·load (plus, with an ellipsoid — given its rows'
    /// factors D — the reach √((Dy)ᵀE⁻¹(Dy))) above the zonotope's support on the whole piece
    /// (module docs).
    fn infeasible(&self, piece: &Piece, nn: &[Vec<Bern>], inv: &[InverseLength], y: &DVector<f64>, w: Iv, row_scale: Option<&[Bern]>) -> Truth {
        let (n, m) = (nn.len(), inv.len());
        // max(f_min a_k, f_max a_k) ≤ α_k + β_k a_k on the range of a_k = y·n_k (the chord of a
        // convex function); the support's polynomial part over W is Σ_k s_k (α_k + β_k a_k) =
        // Σ_k α_k s_k + Σ_r y_r Σ_k β_k s_k n_rk, and Σ_k ε_k |α_k + β_k a_k| bounds the rest
        let (mut constant, mut rest) = ([0.0; 2], 0.0);
        let mut weights = Vec::with_capacity(m);
        for (k, il) in inv.iter().enumerate() {
            let a = Bern::linear_combination(&(0..n).map(|r| (&nn[r][k], y[r])).collect::<Vec<_>>());
            let range = Iv::of(&a);
            let Bounds { min, max } = self.bounds[k];
            let (alpha, beta) = if range.hi <= 0.0 {
                (0.0, min)
            } else if !max.is_finite() {
                return Truth::Unknown; // the support may be unbounded
            } else if range.lo >= 0.0 {
                (0.0, max)
            } else {
                let (lo, hi) = (min * range.lo, max * range.hi);
                let beta = (hi - lo) / (range.hi - range.lo);
                (lo - beta * range.lo + SLACK * (lo.abs() + hi.abs()), beta)
            };
            rest += il.eps * (alpha.abs() + beta.abs() * range.mag());
            for (k, c) in constant.iter_mut().zip(&il.s.c) {
                *k += alpha * c;
            }
            weights.push([beta * il.s.c[0], beta * il.s.c[1]]);
        }
        let mut support = Bern::from_bernstein(constant.to_vec());
        for r in 0..n {
            let c: Vec<[f64; 2]> = weights.iter().map(|b| [y[r] * b[0], y[r] * b[1]]).collect();
            support = support.add(&law_sum(&nn[r], &c));
        }
        let excess = Bern::linear_combination(&(0..n).map(|r| (&piece.load[r], y[r])).collect::<Vec<_>>()).sub(&piece.w.mul(&support));
        // the reach's least value on the piece: (Dy)ᵀE⁻¹(Dy) is a polynomial
        let reach = row_scale.map_or(0.0, |d| {
            let dy: Vec<Bern> = d.iter().zip(y.iter()).map(|(p, &yr)| p.scale(yr)).collect();
            least(&quadratic_form(&dy, &self.load.wrench.ellipsoid_inv, self.load.rows())).max(0.0).sqrt()
        });
        if least(&excess) + reach * (1.0 - SLACK) - w.hi * rest - SLACK * excess.max_abs() > 0.0 {
            Truth::False
        } else {
            Truth::Unknown
        }
    }

    /// Where the condition fails along the motion of `piece` (on all of [0, 1]), to the boundary
    /// tolerance `tol`.
    fn violation_of(&self, piece: Piece, tol: f64, blocks: &[Vec<usize>]) -> Partition {
        let mut pieces = Vec::new();
        let mut search = Search { nodes: MAX_NODES, cuts: MAX_CUTS, cover: None };
        self.bisect(piece, (0.0, 1.0), tol, blocks, &mut search, None, &mut pieces);
        Partition::from_pieces(pieces).not()
    }

    /// Bisection of `piece` = [a, b]: pieces of `out` as (end, feasible?). With an ellipsoid,
    /// `open` are the cover's cones the piece must still certify (`None`: all of them): those its
    /// parent certified hold on it too.
    #[allow(clippy::too_many_arguments)]
    fn bisect(&self, piece: Piece, (a, b): (f64, f64), tol: f64, blocks: &[Vec<usize>], search: &mut Search, mut open: Option<Vec<usize>>, out: &mut Vec<(f64, Truth)>) {
        let truth = self.decide(&piece, blocks, search, &mut open);
        // a quarter of the tolerance: two undecided neighbours merged stay narrower than it
        if truth != Truth::Unknown || b - a <= 0.25 * tol || search.nodes == 0 {
            out.push((b, truth));
            return;
        }
        search.nodes -= 1;
        let (left, right) = piece.halves();
        let mid = 0.5 * (a + b);
        self.bisect(left, (a, mid), tol, blocks, search, open.clone(), out);
        self.bisect(right, (mid, b), tol, blocks, search, open, out);
    }
}

/// The second-order check of a cone along a piece ([`Cover::certify`]'s transport): with the
/// cone's tensions f fixed, each ray's minorant v·(J̃(λ)f − ℓ̃(λ)) − reach(v, λ) is one polynomial
/// up to the inverse lengths' ε_k — J̃(λ)f = W Σ_k f_k s_k n_k, and √r ≤ (r + c²)/(2c) bounds
/// the reach by the polynomial r = (Dv)ᵀE⁻¹(Dv), tightly at c = its middle value — and must stay
/// positive on the piece.
struct Along<'a> {
    piece: &'a Piece,
    nn: &'a [Vec<Bern>],
    inv: &'a [InverseLength],
    d: &'a [Bern],
    e_inv: &'a DMatrix<f64>,
    /// The middle's shape D E⁻¹ D (D at the middle), for the tangent point c of each ray.
    shape: &'a DMatrix<f64>,
    /// What every cone's check on this piece shares, made by the first.
    shared: Option<Shared>,
}

/// The polynomials of a piece that every cone's check reads, raised to common degrees once: N's
/// rows (each to its own), and the load rows and the products d_a·d_b (a ≤ b) to the degree of the
/// checks' polynomials.
struct Shared {
    rows: Vec<Vec<Bern>>,
    load: Vec<Bern>,
    squares: Vec<Vec<Bern>>,
    degree: usize,
    /// max |n_rk|·max |W| per row and cable, for the ε_k of the inverse lengths.
    size: Vec<Vec<f64>>,
}

impl Along<'_> {
    fn shared(&mut self) -> &Shared {
        let (nn, piece, d) = (self.nn, self.piece, self.d);
        self.shared.get_or_insert_with(|| {
            let n = nn.len();
            let rows: Vec<Vec<Bern>> = nn.iter().map(|row| {
                let top = row.iter().map(Bern::degree).max().unwrap_or(0);
                row.iter().map(|p| p.elevate(top)).collect()
            }).collect();
            let squares: Vec<Vec<Bern>> = (0..n).map(|a| (a..n).map(|b| d[a].mul(&d[b])).collect()).collect();
            let q_degree = rows.iter().map(|r| r.first().map_or(0, Bern::degree) + 1).max().unwrap_or(0) + piece.w.degree();
            let degree = piece.load.iter().chain(squares.iter().flatten()).map(Bern::degree).fold(q_degree, usize::max);
            let w_mag = Iv::of(&piece.w).mag();
            let size = nn.iter().map(|row| row.iter().map(|p| Iv::of(p).mag() * w_mag).collect()).collect();
            Shared {
                load: piece.load.iter().map(|p| p.elevate(degree)).collect(),
                squares: squares.iter().map(|row| row.iter().map(|p| p.elevate(degree)).collect()).collect(),
                rows,
                degree,
                size,
            }
        })
    }

    fn holds(&mut self, f: &[f64], rays: &[DVector<f64>]) -> bool {
        let (inv, e_inv, shape, w) = (self.inv, self.e_inv, self.shape, &self.piece.w);
        let shared = self.shared();
        let n = shared.rows.len();
        // q_r = W Σ_k f_k s_k n_rk − load_r, within err_r of J̃(λ)f − ℓ̃ (the ε_k of 1/L_k)
        let scaled: Vec<[f64; 2]> = inv.iter().zip(f).map(|(il, fk)| [fk * il.s.c[0], fk * il.s.c[1]]).collect();
        let q: Vec<Bern> = (0..n).map(|r| w.mul(&law_sum(&shared.rows[r], &scaled)).elevate(shared.degree).sub(&shared.load[r])).collect();
        let err: Vec<f64> = (0..n).map(|r| inv.iter().zip(f).enumerate().map(|(k, (il, fk))| fk.abs() * shared.size[r][k] * il.eps).sum()).collect();
        let scale = q.iter().map(Bern::max_abs).fold(0.0, f64::max);
        rays.iter().all(|v| {
            let reach2 = v.dot(&(shape * v));
            let c = reach2.max(0.0).sqrt().max(1e-12 * scale).max(f64::MIN_POSITIVE);
            // Σ_r v_r q_r − (Σ_ab v_a v_b E⁻¹_ab d_a d_b + c²)/(2c)
            let mut terms: Vec<(&Bern, f64)> = (0..n).map(|r| (&q[r], v[r])).collect();
            for a in 0..n {
                for b in a..n {
                    let weight = if a == b { 1.0 } else { 2.0 } * v[a] * v[b] * e_inv[(a, b)];
                    terms.push((&shared.squares[a][b - a], -weight / (2.0 * c)));
                }
            }
            let margin = Bern::linear_combination(&terms);
            let slack: f64 = (0..n).map(|r| v[r].abs() * err[r]).sum::<f64>() + SLACK * (margin.max_abs() + scale);
            least(&margin) - c / 2.0 - slack > 0.0
        })
    }
}

/// What one motion's bisection spends and keeps: the pieces and the cover's cuts it may still
/// make, and the cover of the wrench directions (with an ellipsoid), refined along the way.
struct Search {
    nodes: usize,
    cuts: usize,
    cover: Option<Cover>,
}

/// A polynomial that is exactly zero (every coefficient 0, no error): an entry of N, or of the
/// load, that no force reaches (a joint the cable's or the load's link does not descend from).
pub(super) fn structurally_zero(p: &Bern) -> bool {
    p.err == 0.0 && p.c.iter().all(|c| *c == 0.0)
}

/// A direction y supported on one of `blocks` (sets of rows) with every column that reaches
/// those rows strictly on its negative side at the middle, and zero elsewhere: the columns that
/// do not reach them are exactly zero there ([`structurally_zero`]), so y·n_k ≡ 0 for them and
/// J f = 0 still has no solution f ≥ 1 (a link whose own cables cannot span its joints, where the
/// whole matrix has no strictly enclosing direction).
fn block_direction(nn: &[Vec<Bern>], j: &DMatrix<f64>, blocks: &[Vec<usize>]) -> Option<DVector<f64>> {
    blocks.iter().find_map(|rows| {
        let cols: Vec<usize> = (0..j.ncols()).filter(|&k| rows.iter().any(|&r| !structurally_zero(&nn[r][k]))).collect();
        let sub = DMatrix::from_fn(rows.len(), cols.len(), |r, c| j[(rows[r], cols[c])]);
        let y = enclosing_direction(&sub)?;
        let mut full = DVector::zeros(j.nrows());
        for (r, &row) in rows.iter().enumerate() {
            full[row] = y[r];
        }
        Some(full)
    })
}

/// Where the columns of the n × m matrix of polynomials `rows` (on λ ∈ [0, 1]) do not positively
/// span ℝⁿ, by the closure program's certificates: the zero load balanced by tensions in [1, ∞)
/// (a strictly positive null vector, with rank n), or a direction with every column strictly on
/// its negative side. Positive factors of a row or a column do not change positive spanning, so
/// the rows may be any positive multiples of the structure matrix's (a multi-link robot's joint
/// rows, whose columns are not divided by the cables' lengths). For any n and m: no facets.
/// `blocks` are sets of rows within which closure may fail on its own (a multi-link robot's
/// subtrees: the joints of a link and its descendants, which only the cables pulling them reach).
/// With routed cables `rows` has a column per segment, `len2` its P_s and `cable_of` its cable,
/// the cable's column the sum of its segments' n_s/√P_s; without (`cable_of` `None`) each P_k
/// is a positive factor of its column and may be given as 1.
pub(crate) fn closure_violation(rows: Vec<Vec<Bern>>, len2: Vec<Bern>, cable_of: Option<Vec<usize>>, tol: f64, blocks: &[Vec<usize>]) -> Partition {
    let n = rows.len();
    let m = cable_of.as_ref().map_or(len2.len(), |c| c.iter().max().map_or(0, |k| k + 1));
    let lp = WrenchFeasibilityLp::closure(&Load { wrench: crate::model::Wrench::zero(), dynamics: None, mobility: crate::model::Mobility::Spatial }, m);
    let mut piece = Piece::new(rows, vec![Bern::constant(0.0); n], Bern::constant(1.0), len2);
    piece.cable_of = cable_of.map(Rc::new);
    lp.violation_of(piece, tol, blocks)
}

/// Where tensions strictly within `bounds` cannot balance the load along a motion (λ ∈ [0, 1]),
/// for the system N φ = load with φ_k = f_k/√P_k: `rows` the n × m matrix N, `load` its n
/// right-hand sides and `len2` the P_k (positive; the squared lengths times a common positive
/// factor that N's rows carry too). With routed cables N has a column per segment, `cable_of`
/// its cable, and cable k's column is Σ_s n_s/√P_s over its segments. By the same certificates as the platform's, for any n and m
/// (a multi-link robot's joint-space statics).
pub(crate) fn feasibility_violation(rows: Vec<Vec<Bern>>, load: Vec<Bern>, len2: Vec<Bern>, bounds: Vec<Bounds>, cable_of: Option<Vec<usize>>, tol: f64) -> Partition {
    let lp = WrenchFeasibilityLp::new(Rc::new(Load { wrench: crate::model::Wrench::zero(), dynamics: None, mobility: crate::model::Mobility::Spatial }), bounds);
    let mut piece = Piece::new(rows, load, Bern::constant(1.0), len2);
    piece.cable_of = cable_of.map(Rc::new);
    lp.violation_of(piece, tol, &[])
}

impl Condition for WrenchFeasibilityLp {
    fn kind(&self) -> Kind {
        Kind::Tension
    }

    fn label(&self) -> String {
        if self.closure { "wrench closure" } else { "wrench feasibility" }.to_string()
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        self.violation_of(Piece::of(sweep, &self.load), sweep.tol, &[])
    }

    fn check(&self, at: &PoseCables) -> PoseCheck {
        let wrench = &self.load.wrench;
        if self.closure {
            let j = structure_matrix_m(&at.cables, &wrench.point_at(&at.pose), self.load.rows());
            return PoseCheck { violated: !closure_by_lp(&j), distance: None };
        }
        let (point, nominal) = (wrench.point_at(&at.pose), at.nominal(&self.load));
        if !wrench.is_single() {
            // the decision alone (the margin, `check`'s report, costs far more beyond the facets)
            let rows = self.load.rows();
            let j = structure_matrix_m(&at.cables, &point, rows);
            let problem = Containment { j: &j, bounds: &self.bounds, centre: &select(&nominal, rows), shape: &select_square(&wrench.ellipsoid_inv, rows) };
            return PoseCheck { violated: contains(&problem) != Some(true), distance: None };
        }
        match static_margin(&at.cables, &point, &nominal, &self.bounds, self.load.rows()) {
            Some((margin, _)) => PoseCheck { violated: !(margin > 0.0), distance: Some(margin) },
            None => PoseCheck { violated: true, distance: None },
        }
    }
}
