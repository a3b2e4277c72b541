//! A small dense linear-programming solver: maximise cᵀx subject to A x = b, x ≥ 0, by the
//! two-phase simplex method (Harris' ratio test; Bland's entering rule after degenerate streaks).
//! Sized for the per-pose wrench and joint-space statics problems (up to about a hundred rows and
//! a few hundred columns); not for large sparse problems.

use nalgebra::{DMatrix, DVector};

/// Pivot and feasibility tolerance, relative to the problem's scale.
const EPS: f64 = 1e-11;
/// Least pivot, relative to the largest entry of its column in the tableau (the row's, in the
/// dual pivots that restore feasibility).
const PIVOT: f64 = 1e-9;
/// How far below zero (relative to the problem's scale) Harris' ratio test lets a basic variable
/// go for a larger pivot; each phase's end repairs it.
const HARRIS: f64 = 1e-9;
/// Least sum of the artificials (per row, relative to the problem's scale) that phase 1 must
/// leave for the program to count as infeasible: 1e-11 per row once failed a feasible 16-row
/// program whose tableau had accumulated 4e-9 of rounding.
const INFEASIBLE: f64 = 1e-9;

/// The result of a linear program.
#[derive(Debug, Clone, PartialEq)]
pub enum LpResult {
    /// An optimal point and its objective value.
    Optimal {
        /// The maximiser.
        x: DVector<f64>,
        /// cᵀx there.
        value: f64,
    },
    /// No x satisfies the constraints.
    Infeasible,
    /// The objective grows without bound.
    Unbounded,
}

/// A simplex tableau: rows [A | b] in canonical form for `basis`, objective row last, stored row
/// by row (a pivot updates whole rows in place).
struct Tableau {
    t: Vec<f64>,
    width: usize,
    basis: Vec<usize>,
    eps: f64,
    /// Least entry taken as a pivot, relative to the largest of its column (smaller ones are
    /// rounding, or would amplify it).
    pivot_tol: f64,
    /// How far below zero the ratio test lets a basic variable go for a larger pivot (Harris).
    slack: f64,
    /// Bland's rules from the first pivot (the retry of a program whose phases did not settle).
    bland_always: bool,
    /// Least reduced cost that improves: relative to the phase's largest cost times the problem's
    /// scale, as reduced costs are sums of costs times entries (a dual program's costs are
    /// tension bounds, up to 8e5 on SJTUSnake).
    dual_eps: f64,
}

/// How a phase of the simplex ended.
#[derive(PartialEq)]
enum Phase {
    /// Optimal, checked on the tableau rebuilt from the program.
    Optimal,
    /// The objective grows without bound.
    Unbounded,
    /// The rebuilt tableau could not be made feasible and optimal (a singular basis, or dual
    /// pivots that did not end): the answer is the simplex's own, unchecked.
    Unsettled,
}

/// What leaves the basis when a column enters.
enum Leaving {
    /// This row, at this step (ratio).
    Row(f64, usize),
    /// No row limits the column: the objective grows without bound along it.
    Unbounded,
    /// Only entries below the pivot tolerance limit it: the column is passed over.
    Tiny,
}

/// Consecutive degenerate pivots after which the entering rule turns from the steepest reduced
/// cost (few pivots) to Bland's (the first improving column) for the rest of the run.
const DEGENERATE_STREAK: usize = 30;

impl Tableau {
    fn new(rows: usize, cols: usize, basis: Vec<usize>, [eps, pivot_tol, slack]: [f64; 3], bland_always: bool) -> Tableau {
        Tableau { t: vec![0.0; (rows + 1) * (cols + 1)], width: cols + 1, basis, eps, pivot_tol, slack, bland_always, dual_eps: eps }
    }

    fn rows(&self) -> usize {
        self.t.len() / self.width - 1
    }

    fn cols(&self) -> usize {
        self.width - 1
    }

    fn at(&self, r: usize, c: usize) -> f64 {
        self.t[r * self.width + c]
    }

    fn set(&mut self, r: usize, c: usize, x: f64) {
        self.t[r * self.width + c] = x;
    }

    /// Row `target` −= f · row `source`.
    fn subtract_row(&mut self, target: usize, source: usize, f: f64) {
        let w = self.width;
        let (lo, hi) = (target.min(source), target.max(source));
        let (head, tail) = self.t.split_at_mut(hi * w);
        let (a, b) = (&mut head[lo * w..(lo + 1) * w], &mut tail[..w]);
        let (dst, src) = if target < source { (a, &*b) } else { (b, &*a) };
        for (d, s) in dst.iter_mut().zip(src) {
            *d -= f * s;
        }
    }

    fn pivot(&mut self, r: usize, c: usize) {
        let w = self.width;
        let p = self.at(r, c);
        self.t[r * w..(r + 1) * w].iter_mut().for_each(|x| *x /= p);
        for i in 0..=self.rows() {
            if i != r {
                let f = self.at(i, c);
                if f != 0.0 {
                    self.subtract_row(i, r, f);
                }
            }
        }
        self.basis[r] = c;
    }

    /// The least pivot among `entries` (a column, or a row for the dual pivots): [`PIVOT`] of
    /// their largest, and never below the tolerance.
    fn least_pivot(&self, entries: impl Iterator<Item = f64>) -> f64 {
        (self.pivot_tol * entries.map(f64::abs).fold(0.0, f64::max)).max(self.eps)
    }

    /// Rebuilds the tableau from the program itself for the current basis: the rows B⁻¹ [M | r]
    /// (M the constraint columns, artificials included, r the right-hand side, all in `system`,
    /// k × (cols + 1)) and the objective row of `cost` (to maximise, per column) made canonical.
    /// The pivots' rounding accumulates in the tableau; this clears it. `false` when the basis
    /// matrix is singular to working precision (the tableau is then left as it was).
    fn refactor(&mut self, system: &DMatrix<f64>, cost: &[f64]) -> bool {
        let k = self.rows();
        let basis = DMatrix::from_fn(k, k, |r, i| system[(r, self.basis[i])]);
        let Some(rows) = basis.lu().solve(system) else { return false };
        if !rows.iter().all(|x| x.is_finite()) {
            return false;
        }
        for r in 0..k {
            for c in 0..self.width {
                self.set(r, c, rows[(r, c)]);
            }
        }
        for c in 0..self.width {
            let basic: f64 = (0..k).map(|r| cost[self.basis[r]] * rows[(r, c)]).sum();
            let own = if c < self.cols() { cost[c] } else { 0.0 };
            self.set(k, c, basic - own);
        }
        true
    }

    /// Dual simplex pivots over the columns `< allowed` until no right-hand side is below the
    /// tolerance's negative (Harris' steps and rounding left a basic variable negative; the
    /// objective row stays optimal). `false` when a negative row has no entering column, or after
    /// ten pivots per row (8S_neck's dual programs took more than one per row).
    fn restore_feasibility(&mut self, allowed: usize) -> bool {
        let (obj, rhs) = (self.rows(), self.cols());
        for _ in 0..=10 * obj {
            let lowest = (0..obj).filter(|&r| self.at(r, rhs) < -self.eps).min_by(|&p, &q| self.at(p, rhs).total_cmp(&self.at(q, rhs)));
            let Some(r) = lowest else { return true };
            let least = self.least_pivot((0..allowed).map(|j| self.at(r, j)));
            let entering = (0..allowed)
                .filter(|&j| self.at(r, j) < -least)
                .min_by(|&p, &q| (self.at(obj, p).max(0.0) / -self.at(r, p)).total_cmp(&(self.at(obj, q).max(0.0) / -self.at(r, q))));
            let Some(c) = entering else { return false };
            self.pivot(r, c);
        }
        false
    }

    /// Ends a phase: the simplex over the columns `< allowed`, then the tableau rebuilt from
    /// `system` and checked — a ray the simplex found must still be one, a basic variable below
    /// the tolerance's negative is restored by dual pivots, a reduced cost that still improves
    /// resumes the simplex — a few rounds. The basic
    /// variables are then those of B⁻¹b for the final basis, to rounding (once the tableau's own,
    /// 8S_neck's balance was off by 3e-4).
    fn settle(&mut self, allowed: usize, system: &DMatrix<f64>, cost: &[f64]) -> Phase {
        for _ in 0..4 {
            let bounded = self.optimise(allowed);
            if !self.refactor(system, cost) {
                return Phase::Unsettled;
            }
            let obj = self.rows();
            // a ray found on the running objective row may be its rounding (a free variable's two
            // halves: one basic, the other's reduced cost, exactly 0, drifted past the tolerance):
            // unbounded only if the rebuilt row still has one
            if !bounded && (0..allowed).any(|j| self.at(obj, j) < -self.dual_eps && matches!(self.leaving(j, allowed, false), Leaving::Unbounded)) {
                return Phase::Unbounded;
            }
            let improving = |t: &Tableau| (0..allowed).any(|j| t.at(obj, j) < -t.dual_eps);
            if (0..obj).all(|r| self.at(r, self.cols()) >= -self.eps) && !improving(self) {
                return Phase::Optimal;
            }
            if !self.restore_feasibility(allowed) {
                return Phase::Unsettled;
            }
        }
        Phase::Unsettled
    }

    /// The row leaving the basis when column `c` enters. An artificial left basic (at zero) after
    /// phase 1 leaves first, whatever the sign of its entry, so that it stays at zero. Otherwise
    /// Harris' two passes: the least ratio with every right-hand side relaxed by the tolerance,
    /// then the largest pivot among the rows within it — a stable pivot rather than a tiny one at
    /// the exact least ratio; under Bland's rules (`bland`), the least ratio with ties to the
    /// least basic index, which cannot cycle. Entries below the pivot tolerance are never pivots: a column limited
    /// only by such entries is passed over (one of 2e-10, taken, once wrecked a tableau of
    /// SJTUSnake's statics; tiny pivots also left 8S_neck's infeasible or short by 17 N).
    fn leaving(&self, c: usize, allowed: usize, bland: bool) -> Leaving {
        let rhs = self.cols();
        let rows = 0..self.rows();
        let least = self.least_pivot(rows.clone().map(|r| self.at(r, c)));
        let artificial = rows.clone().filter(|&r| self.basis[r] >= allowed && self.at(r, c).abs() > least);
        if let Some(r) = artificial.max_by(|&p, &q| self.at(p, c).abs().total_cmp(&self.at(q, c).abs())) {
            return Leaving::Row(0.0, r);
        }
        let candidates = rows.clone().filter(|&r| self.at(r, c) > least).map(|r| (self.at(r, rhs).max(0.0) / self.at(r, c), r));
        let chosen = if bland {
            candidates.min_by(|&(p, i), &(q, j)| if (p - q).abs() <= self.eps { self.basis[i].cmp(&self.basis[j]) } else { p.total_cmp(&q) })
        } else {
            let limit = candidates.clone().map(|(_, r)| (self.at(r, rhs).max(0.0) + self.slack) / self.at(r, c)).fold(f64::INFINITY, f64::min);
            candidates.filter(|&(ratio, _)| ratio <= limit).max_by(|&(_, p), &(_, q)| self.at(p, c).total_cmp(&self.at(q, c)))
        };
        match chosen {
            Some((ratio, r)) => Leaving::Row(ratio, r),
            None if rows.into_iter().any(|r| self.at(r, c) > self.eps || (self.basis[r] >= allowed && self.at(r, c).abs() > self.eps)) => Leaving::Tiny,
            None => Leaving::Unbounded,
        }
    }

    /// Runs the simplex iterations on the objective row (reduced costs stored negated: entering
    /// columns have a negative entry) over the columns `< allowed`. `false` if unbounded. The
    /// entering column is the most negative reduced cost until [`DEGENERATE_STREAK`] degenerate
    /// pivots in a row, then Bland's rules (the first negative one entering, the leaving row by
    /// [`Tableau::leaving`]'s), which cannot cycle in exact arithmetic; the iteration cap ends a run
    /// that rounding keeps going, with a feasible point (phase 2 keeps it feasible: a margin is
    /// then an underestimate) or artificials in phase 1 (the program then counts as infeasible).
    fn optimise(&mut self, allowed: usize) -> bool {
        let obj = self.rows();
        let (mut streak, mut bland) = (0, self.bland_always);
        for _ in 0..10_000 {
            let mut improving: Vec<usize> = (0..allowed).filter(|&j| self.at(obj, j) < -self.dual_eps).collect();
            if !bland {
                crate::order::sort_by_key(&mut improving, |&i| self.at(obj, i));
            }
            let mut step = None;
            for &c in &improving {
                match self.leaving(c, allowed, bland) {
                    Leaving::Row(ratio, r) => {
                        step = Some((c, ratio, r));
                        break;
                    }
                    Leaving::Unbounded => return false,
                    Leaving::Tiny => {}
                }
            }
            // no column improves, or only through pivots below the tolerance: optimal to it
            let Some((c, ratio, r)) = step else { return true };
            streak = if ratio <= self.eps { streak + 1 } else { 0 };
            bland |= streak >= DEGENERATE_STREAK;
            self.pivot(r, c);
        }
        true
    }
}

/// Maximises cᵀx subject to A x = b, x ≥ 0 (A is k×n, b has k entries, c has n). A program
/// whose phases do not settle (see [`Phase::Unsettled`]) is solved again with Bland's rules from
/// the first pivot (slower; it took one of 8S_neck's dual programs to its optimum), whose answer
/// stands.
pub fn maximise(a: &DMatrix<f64>, b: &DVector<f64>, c: &DVector<f64>) -> LpResult {
    solve(a, b, c, false).unwrap_or_else(|_| solve(a, b, c, true).unwrap_or_else(|again| again))
}

/// [`maximise`] by one run of both phases, with Bland's rules from the start or not: `Err` with
/// the run's answer when a phase did not settle.
fn solve(a: &DMatrix<f64>, b: &DVector<f64>, c: &DVector<f64>, bland: bool) -> Result<LpResult, LpResult> {
    let (k, n) = a.shape();
    let scale = a.amax().max(b.amax()).max(1.0);
    let eps = EPS * scale;
    // Phase 1: artificials y ≥ 0 with A x + y = b (rows negated where b < 0), minimise Σy.
    let system = DMatrix::from_fn(k, n + k + 1, |i, j| {
        let s = if b[i] < 0.0 { -1.0 } else { 1.0 };
        match j {
            j if j < n => s * a[(i, j)],
            j if j == n + k => s * b[i],
            j => f64::from(j == n + i),
        }
    });
    let mut tab = Tableau::new(k, n + k, (n..n + k).collect(), [eps, PIVOT, HARRIS * scale], bland);
    for i in 0..k {
        for j in 0..=n + k {
            tab.set(i, j, system[(i, j)]);
        }
    }
    // Objective row of phase 1 (maximise −Σy), made canonical for the artificial basis.
    for i in 0..k {
        tab.subtract_row(k, i, 1.0);
    }
    for i in 0..k {
        // the artificials' own entries cancel: their reduced costs are zero
        tab.set(k, n + i, 0.0);
    }
    let phase1: Vec<f64> = (0..n + k).map(|j| if j < n { 0.0 } else { -1.0 }).collect();
    let mut settled = tab.settle(n + k, &system, &phase1) == Phase::Optimal;
    // the artificials' sum left by phase 1 carries the tableau's rounding, which grows with the
    // pivots: a program is infeasible only when it stays clearly above that
    if -tab.at(k, n + k) > INFEASIBLE * scale * (k as f64 + 1.0) {
        return if settled { Ok(LpResult::Infeasible) } else { Err(LpResult::Infeasible) };
    }
    // Drive artificials out of the basis where possible, each on its row's largest entry (the
    // first entry above the tolerance, once, was 1e-10 and wrecked the tableau); rows with none
    // stay, their artificial at zero.
    for r in 0..k {
        if tab.basis[r] >= n {
            let least = tab.least_pivot((0..n).map(|j| tab.at(r, j)));
            if let Some(j) = (0..n).filter(|&j| tab.at(r, j).abs() > least).max_by(|&p, &q| tab.at(r, p).abs().total_cmp(&tab.at(r, q).abs())) {
                tab.pivot(r, j);
            }
        }
    }
    // Phase 2: the real objective (maximise cᵀx ⇒ row holds −c, made canonical).
    for j in 0..=n + k {
        tab.set(k, j, if j < n { -c[j] } else { 0.0 });
    }
    for r in 0..k {
        let bj = tab.basis[r];
        if bj < n {
            let f = tab.at(k, bj);
            if f != 0.0 {
                tab.subtract_row(k, r, f);
            }
        }
    }
    let phase2: Vec<f64> = (0..n + k).map(|j| if j < n { c[j] } else { 0.0 }).collect();
    tab.dual_eps = eps * c.amax().max(1.0);
    match tab.settle(n, &system, &phase2) {
        Phase::Unbounded => return if settled { Ok(LpResult::Unbounded) } else { Err(LpResult::Unbounded) },
        Phase::Unsettled => settled = false,
        Phase::Optimal => {}
    }
    let mut x = DVector::zeros(n);
    for r in 0..k {
        if tab.basis[r] < n {
            x[tab.basis[r]] = tab.at(r, n + k).max(0.0);
        }
    }
    let value = c.dot(&x);
    if settled { Ok(LpResult::Optimal { x, value }) } else { Err(LpResult::Optimal { x, value }) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_programs() {
        // max x + y s.t. x + 2y + s1 = 4, 3x + y + s2 = 6 → (1.6, 1.2), value 2.8.
        let a = DMatrix::from_row_slice(2, 4, &[1.0, 2.0, 1.0, 0.0, 3.0, 1.0, 0.0, 1.0]);
        let b = DVector::from_vec(vec![4.0, 6.0]);
        let c = DVector::from_vec(vec![1.0, 1.0, 0.0, 0.0]);
        match maximise(&a, &b, &c) {
            LpResult::Optimal { x, value } => {
                assert!((value - 2.8).abs() < 1e-12 && (x[0] - 1.6).abs() < 1e-12 && (x[1] - 1.2).abs() < 1e-12);
            }
            other => panic!("{other:?}"),
        }
        // x + y = −1 with x, y ≥ 0 is infeasible; max x with x − y = 0 is unbounded.
        let a = DMatrix::from_row_slice(1, 2, &[1.0, 1.0]);
        assert_eq!(maximise(&a, &DVector::from_vec(vec![-1.0]), &DVector::from_vec(vec![1.0, 0.0])), LpResult::Infeasible);
        let a = DMatrix::from_row_slice(1, 2, &[1.0, -1.0]);
        assert_eq!(maximise(&a, &DVector::from_vec(vec![0.0]), &DVector::from_vec(vec![1.0, 0.0])), LpResult::Unbounded);
    }

    /// A feasible margin LP (9 cables, a timed trajectory of tests/dynamics.rs) that phase 1 once
    /// declared infeasible: a pivot on an entry barely above the tolerance wrecked the tableau.
    #[test]
    fn feasible_margin_program_is_solved() {
        let a = DMatrix::from_column_slice(16, 21, &[-0.6942088617784421, 0.11254032992983722, 0.7109210436944199, 0.3074443929707825, -0.01463795090584269, 0.30253427414549816, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -0.5432409671741603, -0.33869489838862166, 0.7682284929558421, -0.05520257782560663, -0.2373776938191918, -0.14369021283183642, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -0.3936471214456117, -0.47162081642115855, 0.7890600416291677, 0.306659311622704, 0.26270241239134184, 0.31000363544900195, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.2092508191679202, -0.4524416887411227, 0.8668971178673024, 0.3763500948244493, 0.0458285528356384, -0.06692468645085886, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.40582841056873437, -0.3053619712444518, 0.8614275173762199, -0.14614546223661604, 0.4200930981489216, 0.21776694315458497, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.3933795405563555, 0.3662896026512638, 0.8432582428065852, 0.03361985719401794, 0.41872873844698694, -0.19756859612361663, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.34657465210568567, 0.4916442318152047, 0.7988566578809118, -0.3073445079928794, -0.07340015290593754, 0.17851084586697163, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -0.23639183664601235, 0.5851004123597126, 0.7757424875715003, -0.3188732636559348, 0.17912532612123916, -0.23227468073151256, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -0.4027725043731104, 0.5551778726812067, 0.7277031258735823, 0.0794303239645095, -0.25341846331344003, 0.23730099229620194, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -0.9152278690186408, 0.5426330746418704, 7.142094727655533, 0.2759381688654264, 0.7476438669997159, 0.6056585147744341, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 1.0, 0.9152278690186408, -0.5426330746418704, -7.142094727655533, -0.2759381688654264, -0.7476438669997159, -0.6056585147744341, -2.0, -2.0, -2.0, -2.0, -2.0, -2.0, -2.0, -2.0, -2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
        let b = DVector::from_vec(vec![-0.0003739487910110027, -0.00023487449971837146, 15.463296696654266, 1.0821853767456575, 1.213347522674501, -9.133845728860924e-05, 21.59877138629173, 21.59877138629173, 21.59877138629173, 21.59877138629173, 21.59877138629173, 21.59877138629173, 21.59877138629173, 21.59877138629173, 21.59877138629173, 21.59877138629173]);
        let mut c = DVector::zeros(21);
        c[9] = 1.0;
        c[10] = -1.0;
        match maximise(&a, &b, &c) {
            LpResult::Optimal { x, value } => {
                assert!((&a * &x - &b).amax() < 1e-9, "residual");
                assert!(value > 1.0, "margin {value}");
            }
            other => panic!("{other:?}"),
        }
    }
}
