//! Conditions with one more variable: the set of λ ∈ [0, 1] where
//! ∃ v ∈ [0, 1] : Φ(v, λ), for Φ a disjunction of conjunctions of strict sign conditions on
//! polynomials in (v, λ), certified by Bernstein subdivision in both variables.
//!
//! The offset obstacles need it: "the cable comes closer than c to a rim circle" is
//! ∃u (a point of the cable) with a quartic in u negative, and the ellipsoid's distance is the
//! maximum over a Lagrange multiplier. A polynomial in (v, λ) is held as its Bernstein rows in v,
//! each a [`Bern`] in λ with its own error bound; since the tensor Bernstein basis is non-negative
//! and sums to 1, all coefficients of all rows above their error bounds prove the polynomial
//! positive on the whole (v, λ) box.
//!
//! λ is bisected (every few levels the polynomials are built afresh on the strip, so that their
//! error bounds follow their local magnitudes); on each λ-strip the v-interval is searched depth first for a box on which some
//! conjunction is certainly true (then Φ holds for every λ of the strip), while boxes on which
//! every conjunction has a certainly false atom are dropped (if all are, no v works anywhere on the
//! strip). A strip neither proved nor refuted within the box budget is bisected; one narrower than
//! the tolerance is `Unknown`. The budget grows with the depth, because near a boundary λ* where Φ
//! is tangent in v the witnessing v-box has a width of order √|λ − λ*|.

use crate::poly::{binomial, halve, Bern, Partition, Truth};

/// Unit roundoff of f64.
const U: f64 = f64::EPSILON * 0.5;

/// A polynomial in (v, λ): ascending monomial coefficients in v, each a polynomial in λ.
#[derive(Debug, Clone)]
pub struct VPoly(pub Vec<Bern>);

impl VPoly {
    /// A polynomial in λ only.
    pub fn of(p: Bern) -> VPoly {
        VPoly(vec![p])
    }

    /// `a + b·v`.
    pub fn linear(a: Bern, b: Bern) -> VPoly {
        VPoly(vec![a, b])
    }

    /// A polynomial in v only, with ascending (exact) monomial coefficients.
    pub fn in_v(c: &[f64]) -> VPoly {
        VPoly(c.iter().map(|&x| Bern::constant(x)).collect())
    }

    fn zip(&self, o: &VPoly, sign: f64) -> VPoly {
        let n = self.0.len().max(o.0.len());
        VPoly(
            (0..n)
                .map(|k| match (self.0.get(k), o.0.get(k)) {
                    (Some(a), Some(b)) => {
                        if sign > 0.0 {
                            a.add(b)
                        } else {
                            a.sub(b)
                        }
                    }
                    (Some(a), None) => a.clone(),
                    (None, Some(b)) => b.scale(sign),
                    (None, None) => Bern::constant(0.0),
                })
                .collect(),
        )
    }

    /// self + o.
    pub fn add(&self, o: &VPoly) -> VPoly {
        self.zip(o, 1.0)
    }

    /// self − o.
    pub fn sub(&self, o: &VPoly) -> VPoly {
        self.zip(o, -1.0)
    }

    /// self · k for an exact constant k.
    pub fn scale(&self, k: f64) -> VPoly {
        VPoly(self.0.iter().map(|p| p.scale(k)).collect())
    }

    /// self · p for a polynomial p in λ.
    pub fn times(&self, p: &Bern) -> VPoly {
        VPoly(self.0.iter().map(|q| q.mul(p)).collect())
    }

    /// self · o.
    pub fn mul(&self, o: &VPoly) -> VPoly {
        let mut out: Vec<Option<Bern>> = vec![None; self.0.len() + o.0.len() - 1];
        for (i, a) in self.0.iter().enumerate() {
            for (j, b) in o.0.iter().enumerate() {
                let t = a.mul(b);
                out[i + j] = Some(match out[i + j].take() {
                    None => t,
                    Some(s) => s.add(&t),
                });
            }
        }
        VPoly(out.into_iter().map(|p| p.unwrap_or_else(|| Bern::constant(0.0))).collect())
    }

    /// The Bernstein rows in v: row_i = Σ_{k ≤ i} C(i,k)/C(m,k) · a_k, the rounding of each ratio
    /// added to the row's error bound.
    fn rows(&self) -> Vec<Bern> {
        let m = self.0.len() - 1;
        (0..=m)
            .map(|i| {
                let mut acc = self.0[0].clone();
                for k in 1..=i {
                    let r = binomial(i, k) / binomial(m, k);
                    let mut t = self.0[k].scale(r);
                    t.err += U * r * (self.0[k].max_abs() + self.0[k].err);
                    acc = acc.add(&t);
                }
                acc
            })
            .collect()
    }
}

/// One strict sign condition: `p > 0` (`positive`) or `p < 0`, held as the tensor Bernstein
/// coefficients of p on the current (v, λ) box: one row per Bernstein coefficient in v, every row at
/// one common degree in λ, stored flat (row after row) so that a split copies two plain arrays.
#[derive(Debug, Clone)]
pub struct Atom {
    /// The rows' coefficients, `width` per row.
    c: Vec<f64>,
    /// Each row's error bound (as [`Bern::err`]).
    err: Vec<f64>,
    /// Coefficients per row: the degree in λ plus one.
    width: usize,
    positive: bool,
}

/// Largest magnitude among `c`.
fn max_abs(c: &[f64]) -> f64 {
    c.iter().fold(0.0, |m, x| m.max(x.abs()))
}

impl Atom {
    /// `p > 0` when `positive`, else `p < 0`.
    pub fn new(p: &VPoly, positive: bool) -> Atom {
        let rows = p.rows();
        let degree = rows.iter().map(Bern::degree).max().unwrap_or(0);
        let mut c = Vec::with_capacity(rows.len() * (degree + 1));
        let mut err = Vec::with_capacity(rows.len());
        for r in rows {
            let r = r.elevate(degree);
            c.extend_from_slice(&r.c);
            err.push(r.err);
        }
        Atom { c, err, width: degree + 1, positive }
    }

    /// The rows with their error bounds.
    fn rows(&self) -> impl Iterator<Item = (&[f64], f64)> {
        self.c.chunks_exact(self.width).zip(self.err.iter().copied())
    }

    /// Certified truth on the whole box the rows describe.
    fn truth(&self) -> Truth {
        let (mut pos, mut neg) = (true, true);
        for (r, e) in self.rows() {
            for &c in r {
                pos &= c > e;
                neg &= c < -e;
            }
            if !pos && !neg {
                return Truth::Unknown;
            }
        }
        match (pos, neg, self.positive) {
            (true, _, true) | (_, true, false) => Truth::True,
            _ => Truth::False,
        }
    }

    /// Whether every coefficient is within twice its error bound of zero.
    fn blurred(&self) -> bool {
        self.rows().all(|(r, e)| max_abs(r) <= 2.0 * e)
    }

    /// The two halves in v (de Casteljau on the rows, in place: after level l, rows 0 … n − l hold
    /// the level-l points, row 0 is the left half's row l and row n − l is final for the right
    /// half). Each midpoint (a + b)/2 carries the mean of its inputs' error bounds and the rounding
    /// of the sum.
    fn split_v(&self) -> (Atom, Atom) {
        let (w, n) = (self.width, self.err.len() - 1);
        let (mut right, mut right_err) = (self.c.clone(), self.err.clone());
        let (mut left, mut left_err) = (Vec::with_capacity(self.c.len()), Vec::with_capacity(n + 1));
        left.extend_from_slice(&right[..w]);
        left_err.push(right_err[0]);
        for level in 1..=n {
            for k in 0..=(n - level) {
                let (a, b) = right[k * w..(k + 2) * w].split_at_mut(w);
                for (x, y) in a.iter_mut().zip(b.iter()) {
                    *x = (*x + y) * 0.5;
                }
                right_err[k] = 0.5 * (right_err[k] + right_err[k + 1]) + 2.0 * U * max_abs(a);
            }
            left.extend_from_slice(&right[..w]);
            left_err.push(right_err[0]);
        }
        let positive = self.positive;
        (Atom { c: left, err: left_err, width: w, positive }, Atom { c: right, err: right_err, width: w, positive })
    }

    /// The atom at the first (`last` false) or last λ of its box: each row's first or last
    /// coefficient in λ, which is the row's value there, with the row's error bound.
    fn at_end(&self, last: bool) -> Atom {
        let pick = if last { self.width - 1 } else { 0 };
        let c = self.c.chunks_exact(self.width).map(|r| r[pick]).collect();
        Atom { c, err: self.err.clone(), width: 1, positive: self.positive }
    }

    /// The two halves in λ (de Casteljau at ½ on every row, [`halve`]).
    fn split_lambda(&self) -> (Atom, Atom) {
        let w = self.width;
        let (mut left, mut right) = (vec![0.0; self.c.len()], vec![0.0; self.c.len()]);
        let mut err = self.err.clone();
        for (((c, l), r), e) in self.c.chunks_exact(w).zip(left.chunks_exact_mut(w)).zip(right.chunks_exact_mut(w)).zip(err.iter_mut()) {
            *e += halve(c, l, r);
        }
        let positive = self.positive;
        (Atom { c: left, err: err.clone(), width: w, positive }, Atom { c: right, err, width: w, positive })
    }
}

/// A conjunction of atoms.
pub type Clause = Vec<Atom>;

/// Boxes a strip may examine at λ-depth d: `BASE_BUDGET + 2·d`.
const BASE_BUDGET: usize = 12;
/// Deepest v-subdivision.
const MAX_V_DEPTH: usize = 48;
/// A strip at most this many tolerances wide is not bisected further when what is left undecided
/// is within rounding of zero (no narrower strip can do better; it is reported `Unknown`).
const BLUR_WIDTH: f64 = 64.0;

/// Every this many λ-bisections the clauses are built afresh on the strip (from the inputs
/// restricted to it) instead of being split, so that their error bounds follow the polynomials'
/// magnitudes there rather than over all of [0, 1].
const REBUILD_EVERY: usize = 4;

/// The set of λ ∈ [0, 1] where some v ∈ [0, 1] satisfies one of the clauses, certified to `tol`.
/// `build(lo, hi)` gives the clauses for λ ∈ [lo, hi], re-parametrised to [0, 1].
pub fn exists(build: &dyn Fn(f64, f64) -> Vec<Clause>, tol: f64) -> Partition {
    let mut out = Vec::new();
    let clauses = build(0.0, 1.0);
    let ends = [at_end(&clauses, false, 0), at_end(&clauses, true, 0)];
    strips(build, clauses, 0.0, 1.0, 0, tol, ends, &mut out);
    Partition::from_pieces(out)
}

/// Certified truth of ∃v at the strip's first (`last` false) or last λ, from the atoms' first or
/// last Bernstein coefficients in λ (which are their values there): a search in v alone.
fn at_end(clauses: &[Clause], last: bool, depth: usize) -> Truth {
    let point: Vec<Clause> = clauses.iter().map(|c| c.iter().map(|a| a.at_end(last)).collect()).collect();
    search_v(&point, BASE_BUDGET + depth).0
}

/// One λ-strip [lo, hi] of [`exists`], with the certified truths at its two ends (`ends`, each
/// possibly `Unknown`): a strip whose ends are decided differently holds a boundary, so it cannot
/// be decided as a whole and is bisected without a search in v (near a boundary, where that
/// search would spend its whole budget in vain on every level).
#[allow(clippy::too_many_arguments)]
fn strips(build: &dyn Fn(f64, f64) -> Vec<Clause>, clauses: Vec<Clause>, lo: f64, hi: f64, depth: usize, tol: f64, ends: [Truth; 2], out: &mut Vec<(f64, Truth)>) {
    let clauses: Vec<Clause> = clauses.into_iter().filter(|c| !c.is_empty()).collect();
    if clauses.is_empty() {
        return out.push((hi, Truth::False));
    }
    let crossing = ends[0] != Truth::Unknown && ends[1] != Truth::Unknown && ends[0] != ends[1];
    let (t, blurred) = if crossing { (Truth::Unknown, false) } else { search_v(&clauses, BASE_BUDGET + 2 * depth) };
    if t != Truth::Unknown {
        return out.push((hi, t));
    }
    if hi - lo <= 0.125 * tol || (blurred && hi - lo <= BLUR_WIDTH * tol) {
        return out.push((hi, Truth::Unknown));
    }
    let mid = 0.5 * (lo + hi);
    let (left, right) = if (depth + 1).is_multiple_of(REBUILD_EVERY) {
        (build(lo, mid), build(mid, hi))
    } else {
        let (mut left, mut right) = (Vec::with_capacity(clauses.len()), Vec::with_capacity(clauses.len()));
        for c in &clauses {
            let (l, r): (Clause, Clause) = c.iter().map(Atom::split_lambda).unzip();
            left.push(l);
            right.push(r);
        }
        (left, right)
    };
    let middle = at_end(&left, true, depth + 1);
    strips(build, left, lo, mid, depth + 1, tol, [ends[0], middle], out);
    strips(build, right, mid, hi, depth + 1, tol, [middle, ends[1]], out);
}

/// Whether some v-box of the strip certainly satisfies a clause (True), none can (False), or
/// neither was shown within `budget` splits (Unknown, with whether every box left undecided had,
/// in each open clause, an atom whose coefficients are all within twice its error bound of zero, so
/// that only better precision could decide it). Boxes are examined breadth first, so a wide
/// witness is found before the budget goes into the corners of a boundary. Atoms certainly true on
/// a box are dropped for its sub-boxes, clauses with a certainly false atom are dropped.
fn search_v(clauses: &[Clause], mut budget: usize) -> (Truth, bool) {
    let mut queue: std::collections::VecDeque<(Vec<Clause>, usize)> = std::collections::VecDeque::new();
    let mut undecided = false;
    let mut blurred = true;
    let mut first = Some(clauses);
    loop {
        let owned;
        let (boxed, depth): (&[Clause], usize) = match first.take() {
            Some(c) => (c, 0),
            None => match queue.pop_front() {
                Some((c, d)) => {
                    owned = c;
                    (&owned, d)
                }
                None => return if undecided { (Truth::Unknown, blurred) } else { (Truth::False, false) },
            },
        };
        let mut alive: Vec<Vec<&Atom>> = Vec::with_capacity(boxed.len());
        for clause in boxed {
            let mut open: Vec<&Atom> = Vec::with_capacity(clause.len());
            let mut dead = false;
            for atom in clause {
                match atom.truth() {
                    Truth::False => {
                        dead = true;
                        break;
                    }
                    Truth::True => {}
                    Truth::Unknown => open.push(atom),
                }
            }
            if dead {
                continue;
            }
            if open.is_empty() {
                return (Truth::True, false);
            }
            alive.push(open);
        }
        if alive.is_empty() {
            continue;
        }
        if depth >= MAX_V_DEPTH || budget == 0 {
            undecided = true;
            blurred &= alive.iter().all(|c| c.iter().any(|a| a.blurred()));
            continue;
        }
        budget -= 1;
        let (mut left, mut right) = (Vec::with_capacity(alive.len()), Vec::with_capacity(alive.len()));
        for c in &alive {
            let (l, r): (Clause, Clause) = c.iter().map(|a| a.split_v()).unzip();
            left.push(l);
            right.push(r);
        }
        queue.push_back((left, depth + 1));
        queue.push_back((right, depth + 1));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// a + bλ on [lo, hi], re-parametrised.
    fn lin(a: f64, b: f64, (lo, hi): (f64, f64)) -> Bern {
        Bern::from_bernstein(vec![a + b * lo, a + b * hi])
    }

    #[test]
    fn tangent_parabola_gives_a_certified_boundary() {
        // ∃v: (v − 0.5)² < λ − 0.3  ⇔  λ > 0.3
        let build = |lo, hi| {
            let p = VPoly::in_v(&[0.25, -1.0, 1.0]).sub(&VPoly::of(lin(-0.3, 1.0, (lo, hi))));
            vec![vec![Atom::new(&p, false)]]
        };
        let part = exists(&build, 1e-10);
        let iv = part.intervals();
        assert_eq!(iv.len(), 3, "{iv:?}");
        assert_eq!((iv[0].2, iv[1].2, iv[2].2), (Truth::False, Truth::Unknown, Truth::True));
        assert!(iv[1].0 <= 0.3 && 0.3 <= iv[1].1 && iv[1].1 - iv[1].0 <= 1e-10, "{iv:?}");
    }

    #[test]
    fn conjunctions_and_disjunctions() {
        // (v > 0.8 ∧ v < λ) ∨ (v < 0.1 ∧ λ < 0.2)  ⇔  λ > 0.8 or λ < 0.2
        let build = |lo, hi| {
            let v = VPoly::in_v(&[0.0, 1.0]);
            let c1 = vec![Atom::new(&v.sub(&VPoly::in_v(&[0.8])), true), Atom::new(&v.sub(&VPoly::of(lin(0.0, 1.0, (lo, hi)))), false)];
            let c2 = vec![Atom::new(&v.sub(&VPoly::in_v(&[0.1])), false), Atom::new(&VPoly::of(lin(-0.2, 1.0, (lo, hi))), false)];
            vec![c1, c2]
        };
        let part = exists(&build, 1e-10);
        let iv = part.intervals();
        let truth_at = |x: f64| iv.iter().find(|p| p.0 <= x && x <= p.1).unwrap().2;
        assert_eq!(truth_at(0.1), Truth::True);
        assert_eq!(truth_at(0.5), Truth::False);
        assert_eq!(truth_at(0.9), Truth::True);
        for (a, b, t) in iv {
            assert!(t != Truth::Unknown || b - a <= 1e-10);
        }
    }
}
