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

use crate::poly::{binomial, Bern, Partition, Truth};

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

/// One strict sign condition on a polynomial in (v, λ): `p > 0` (`positive`) or `p < 0`, with p held
/// by its tensor Bernstein coefficients on the current box (row i in v, column j in λ, stored row
/// by row) and one bound on the error of every coefficient.
#[derive(Debug, Clone)]
pub struct Atom {
    /// Coefficients in v (rows).
    nv: usize,
    /// Coefficients in λ (columns).
    nl: usize,
    c: Vec<f64>,
    err: f64,
    positive: bool,
}

fn max_abs(c: &[f64]) -> f64 {
    c.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

impl Atom {
    /// `p > 0` when `positive`, else `p < 0`.
    pub fn new(p: &VPoly, positive: bool) -> Atom {
        let rows = p.rows();
        let n = rows.iter().map(Bern::degree).max().unwrap_or(0);
        let mut c = Vec::with_capacity(rows.len() * (n + 1));
        let mut err = 0.0f64;
        for r in &rows {
            let r = r.elevate(n);
            err = err.max(r.err);
            c.extend_from_slice(&r.c);
        }
        Atom { nv: rows.len(), nl: n + 1, c, err, positive }
    }

    /// Certified truth on the whole box the coefficients describe.
    fn truth(&self) -> Truth {
        let (mut pos, mut neg) = (true, true);
        for &x in &self.c {
            pos &= x > self.err;
            neg &= x < -self.err;
            if !pos && !neg {
                return Truth::Unknown;
            }
        }
        match (pos, neg, self.positive) {
            (true, _, true) | (_, true, false) => Truth::True,
            _ => Truth::False,
        }
    }

    /// Whether every coefficient is within twice the error bound of zero.
    fn blurred(&self) -> bool {
        max_abs(&self.c) <= 2.0 * self.err
    }

    /// The added error bound of one de Casteljau halving along an axis of `n + 1` coefficients
    /// (as [`Bern::split`] bounds it).
    fn halving_err(&self, n: usize) -> f64 {
        (2 * n + 2) as f64 * U * max_abs(&self.c)
    }

    /// The two halves in v: de Casteljau at 1/2 over the rows, column by column.
    fn split_v(&self) -> (Atom, Atom) {
        let (nv, nl) = (self.nv, self.nl);
        let err = self.err + self.halving_err(nv - 1);
        let mut right = self.c.clone();
        let mut left = vec![0.0; right.len()];
        left[..nl].copy_from_slice(&right[..nl]);
        for level in 1..nv {
            for k in 0..(nv - level) {
                for j in 0..nl {
                    right[k * nl + j] = 0.5 * (right[k * nl + j] + right[(k + 1) * nl + j]);
                }
            }
            left[level * nl..(level + 1) * nl].copy_from_slice(&right[..nl]);
        }
        (self.with(left, err), self.with(right, err))
    }

    /// The two halves in λ: de Casteljau at 1/2 within every row.
    fn split_lambda(&self) -> (Atom, Atom) {
        let nl = self.nl;
        let err = self.err + self.halving_err(nl - 1);
        let mut right = self.c.clone();
        let mut left = vec![0.0; right.len()];
        for (l, r) in left.chunks_exact_mut(nl).zip(right.chunks_exact_mut(nl)) {
            l[0] = r[0];
            for level in 1..nl {
                for k in 0..(nl - level) {
                    r[k] = 0.5 * (r[k] + r[k + 1]);
                }
                l[level] = r[0];
            }
        }
        (self.with(left, err), self.with(right, err))
    }

    /// An atom of this one's shape and sign with coefficients `c` and error bound `err`.
    fn with(&self, c: Vec<f64>, err: f64) -> Atom {
        Atom { nv: self.nv, nl: self.nl, c, err, positive: self.positive }
    }
}

/// A conjunction of atoms.
pub type Clause = Vec<Atom>;

/// A dyadic v-interval: [index, index + 1] / 2^depth.
#[derive(Debug, Clone, Copy)]
struct VBox {
    index: u64,
    depth: usize,
}

impl VBox {
    /// Whether `other` lies in this box.
    fn holds(self, other: VBox) -> bool {
        other.depth >= self.depth && other.index >> (other.depth - self.depth) == self.index
    }

    fn halves(self) -> (VBox, VBox) {
        let d = self.depth + 1;
        (VBox { index: 2 * self.index, depth: d }, VBox { index: 2 * self.index + 1, depth: d })
    }
}

/// A v-box of the current strip with the clauses that may still hold on it (atoms already
/// certainly true there dropped, clauses with a certainly false atom dropped).
#[derive(Debug, Clone)]
struct Cell {
    at: VBox,
    clauses: Vec<Clause>,
}

/// The clauses (on the v-box `at`) restricted to each of `boxes` (sorted, inside `at`), appended
/// to `out` as cells: the shared halvings are done once, walking down the dyadic tree.
fn onto_cells(clauses: Vec<Clause>, at: VBox, boxes: &[VBox], out: &mut Vec<Cell>) {
    match boxes {
        [] => {}
        [only] if only.depth == at.depth => out.push(Cell { at, clauses }),
        _ => {
            let (a, b) = at.halves();
            let split = boxes.partition_point(|x| a.holds(*x));
            let (mut left, mut right) = (Vec::with_capacity(clauses.len()), Vec::with_capacity(clauses.len()));
            for c in &clauses {
                let (l, r): (Clause, Clause) = c.iter().map(Atom::split_v).unzip();
                left.push(l);
                right.push(r);
            }
            onto_cells(left, a, &boxes[..split], out);
            onto_cells(right, b, &boxes[split..], out);
        }
    }
}

/// Splits made in v per strip (its halves go on from where it stopped, see [`roots`]).
const BUDGET: usize = 4;
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
    let root = Cell { at: VBox { index: 0, depth: 0 }, clauses: build(0.0, 1.0) };
    strips(build, vec![root], 0.0, 1.0, 0, tol, &mut out);
    Partition::from_pieces(out)
}

/// Decides the strip λ ∈ [lo, hi] from the v-cells not yet refuted on it (those of its parent
/// strip: a cell refuted on a strip is refuted on its halves), bisecting it while undecided.
fn strips(build: &dyn Fn(f64, f64) -> Vec<Clause>, cells: Vec<Cell>, lo: f64, hi: f64, depth: usize, tol: f64, out: &mut Vec<(f64, Truth)>) {
    let (t, blurred, cells) = search_v(cells, BUDGET);
    if t != Truth::Unknown {
        return out.push((hi, t));
    }
    if hi - lo <= 0.125 * tol || (blurred && hi - lo <= BLUR_WIDTH * tol) {
        return out.push((hi, Truth::Unknown));
    }
    let mid = 0.5 * (lo + hi);
    let (left, right) = if (depth + 1) % REBUILD_EVERY == 0 {
        let fresh = |a: f64, b: f64| {
            let mut out = Vec::with_capacity(cells.len());
            onto_cells(build(a, b), VBox { index: 0, depth: 0 }, &cells.iter().map(|c| c.at).collect::<Vec<_>>(), &mut out);
            out
        };
        (fresh(lo, mid), fresh(mid, hi))
    } else {
        let (mut left, mut right) = (Vec::with_capacity(cells.len()), Vec::with_capacity(cells.len()));
        for cell in &cells {
            let (mut l, mut r) = (Vec::with_capacity(cell.clauses.len()), Vec::with_capacity(cell.clauses.len()));
            for c in &cell.clauses {
                let (a, b): (Clause, Clause) = c.iter().map(Atom::split_lambda).unzip();
                l.push(a);
                r.push(b);
            }
            left.push(Cell { at: cell.at, clauses: l });
            right.push(Cell { at: cell.at, clauses: r });
        }
        (left, right)
    };
    drop(cells);
    strips(build, left, lo, mid, depth + 1, tol, out);
    strips(build, right, mid, hi, depth + 1, tol, out);
}

/// Whether some v-cell of the strip certainly satisfies a clause (True), none can (False), or
/// neither was shown within `budget` splits (Unknown, with whether every cell left undecided had,
/// in each open clause, an atom whose coefficients are all within twice its error bound of zero, so
/// that only better precision could decide it, and at most [`ROOTS`] cells covering every cell
/// left undecided, for the halves of the strip to start from). Cells are examined breadth first,
/// so a wide witness is found before the budget goes into the corners of a boundary. Atoms
/// certainly true on a cell are dropped for its sub-cells, clauses with a certainly false atom
/// are dropped, cells with no clause left are refuted.
fn search_v(cells: Vec<Cell>, mut budget: usize) -> (Truth, bool, Vec<Cell>) {
    let mut queue: std::collections::VecDeque<Cell> = cells.into();
    // every cell split or left undecided, with its open clauses; the undecided ones are marked
    let mut seen: Vec<(Cell, bool)> = Vec::new();
    let mut blurred = true;
    while let Some(cell) = queue.pop_front() {
        let mut alive: Vec<Clause> = Vec::with_capacity(cell.clauses.len());
        for clause in cell.clauses {
            let mut open: Clause = Vec::with_capacity(clause.len());
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
                return (Truth::True, false, Vec::new());
            }
            alive.push(open);
        }
        if alive.is_empty() {
            continue;
        }
        if cell.at.depth >= MAX_V_DEPTH || budget == 0 {
            blurred &= alive.iter().all(|c| c.iter().any(Atom::blurred));
            seen.push((Cell { at: cell.at, clauses: alive }, true));
            continue;
        }
        budget -= 1;
        let (mut left, mut right) = (Vec::with_capacity(alive.len()), Vec::with_capacity(alive.len()));
        for c in &alive {
            let (l, r): (Clause, Clause) = c.iter().map(Atom::split_v).unzip();
            left.push(l);
            right.push(r);
        }
        let (a, b) = cell.at.halves();
        queue.push_back(Cell { at: a, clauses: left });
        queue.push_back(Cell { at: b, clauses: right });
        seen.push((Cell { at: cell.at, clauses: alive }, false));
    }
    if seen.iter().any(|(_, undecided)| *undecided) {
        (Truth::Unknown, blurred, roots(seen))
    } else {
        (Truth::False, false, Vec::new())
    }
}

/// At most this many cells are handed from a strip to its halves.
const ROOTS: usize = 4;

/// The cells the halves of a strip start from: the deepest cover of the undecided cells of `seen`
/// by at most [`ROOTS`] of the cells in `seen` (an undecided cell's ancestors in `seen` are those
/// the search split on its way to it), sorted along v.
fn roots(seen: Vec<(Cell, bool)>) -> Vec<Cell> {
    let mut at: Vec<((usize, u64), usize)> = seen.iter().enumerate().map(|(k, (c, _))| ((c.at.depth, c.at.index), k)).collect();
    at.sort_unstable();
    let undecided: Vec<VBox> = seen.iter().filter(|(_, u)| *u).map(|(c, _)| c.at).collect();
    // the cell of `seen` holding box b at the depth nearest to d (not deeper than b)
    let cover = |b: VBox, d: usize| -> usize {
        let mut depth = d.min(b.depth);
        loop {
            if let Ok(k) = at.binary_search_by_key(&(depth, b.index >> (b.depth - depth)), |e| e.0) {
                return at[k].1;
            }
            depth += 1;
        }
    };
    let deepest = undecided.iter().map(|b| b.depth).max().unwrap_or(0);
    let mut chosen: Vec<usize> = undecided.iter().map(|&b| cover(b, 0)).collect();
    for d in 1..=deepest {
        let mut next: Vec<usize> = undecided.iter().map(|&b| cover(b, d)).collect();
        next.sort_unstable();
        next.dedup();
        if next.len() > ROOTS {
            break;
        }
        chosen = next;
    }
    chosen.sort_unstable();
    chosen.dedup();
    let mut seen: Vec<Option<Cell>> = seen.into_iter().map(|(c, _)| Some(c)).collect();
    let mut out: Vec<Cell> = chosen.into_iter().filter_map(|k| seen[k].take()).collect();
    out.sort_by_key(|c| c.at.index << (MAX_V_DEPTH - c.at.depth));
    out
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
