//! A small dense linear-programming solver: maximise cᵀx subject to A x = b, x ≥ 0, by the
//! two-phase simplex method with Bland's rule (no cycling). Sized for the per-pose wrench problems
//! (a handful of equalities, tens of variables); not for large sparse problems.

use nalgebra::{DMatrix, DVector};

/// Pivot and feasibility tolerance, relative to the problem's scale.
const EPS: f64 = 1e-11;
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
}

/// Consecutive degenerate pivots after which the entering rule turns from the steepest reduced
/// cost (few pivots) to Bland's (no cycling) for the rest of the run.
const DEGENERATE_STREAK: usize = 30;

impl Tableau {
    fn new(rows: usize, cols: usize, basis: Vec<usize>, eps: f64) -> Tableau {
        Tableau { t: vec![0.0; (rows + 1) * (cols + 1)], width: cols + 1, basis, eps }
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

    /// Runs the simplex iterations on the objective row (reduced costs stored negated: entering
    /// columns have a negative entry) over the columns `< allowed`. `false` if unbounded. The
    /// entering column is the most negative reduced cost until [`DEGENERATE_STREAK`] degenerate
    /// pivots in a row, then Bland's rule (the first negative one), which cannot cycle.
    fn optimise(&mut self, allowed: usize) -> bool {
        let obj = self.rows();
        let rhs = self.cols();
        let (mut streak, mut bland) = (0, false);
        // Bland's rule guarantees termination; the cap only guards against rounding loops.
        for _ in 0..10_000 {
            let entering = if bland {
                (0..allowed).find(|&j| self.at(obj, j) < -self.eps)
            } else {
                (0..allowed).filter(|&j| self.at(obj, j) < -self.eps).min_by(|&i, &j| self.at(obj, i).total_cmp(&self.at(obj, j)))
            };
            let Some(c) = entering else { return true };
            let mut best: Option<(f64, usize)> = None;
            for r in 0..obj {
                let a = self.at(r, c);
                // an artificial left basic (at zero) in a degenerate row after phase 1 must stay
                // at zero: its row takes part in the ratio test at ratio 0 whatever the sign of
                // the entry, so that the entering column replaces it rather than lifting it
                let artificial = self.basis[r] >= allowed;
                if a > self.eps || (artificial && a < -self.eps) {
                    let ratio = if artificial { 0.0 } else { self.at(r, rhs) / a };
                    let better = match best {
                        None => true,
                        Some((q, br)) => ratio < q - self.eps || (ratio <= q + self.eps && self.basis[r] < self.basis[br]),
                    };
                    if better {
                        best = Some((ratio, r));
                    }
                }
            }
            let Some((ratio, r)) = best else { return false };
            streak = if ratio <= self.eps { streak + 1 } else { 0 };
            bland |= streak >= DEGENERATE_STREAK;
            self.pivot(r, c);
        }
        true
    }
}

/// Maximises cᵀx subject to A x = b, x ≥ 0 (A is k×n, b has k entries, c has n).
pub fn maximise(a: &DMatrix<f64>, b: &DVector<f64>, c: &DVector<f64>) -> LpResult {
    let (k, n) = a.shape();
    let scale = a.amax().max(b.amax()).max(1.0);
    let eps = EPS * scale;
    // Phase 1: artificials y ≥ 0 with A x + y = b (rows negated where b < 0), minimise Σy.
    let mut tab = Tableau::new(k, n + k, (n..n + k).collect(), eps);
    for i in 0..k {
        let s = if b[i] < 0.0 { -1.0 } else { 1.0 };
        for j in 0..n {
            tab.set(i, j, s * a[(i, j)]);
        }
        tab.set(i, n + i, 1.0);
        tab.set(i, n + k, s * b[i]);
    }
    // Objective row of phase 1 (maximise −Σy), made canonical for the artificial basis.
    for i in 0..k {
        tab.subtract_row(k, i, 1.0);
    }
    for i in 0..k {
        // the artificials' own entries cancel: their reduced costs are zero
        tab.set(k, n + i, 0.0);
    }
    tab.optimise(n + k);
    // the artificials' sum left by phase 1 carries the tableau's rounding, which grows with the
    // pivots: a program is infeasible only when it stays clearly above that
    if -tab.at(k, n + k) > INFEASIBLE * scale * (k as f64 + 1.0) {
        return LpResult::Infeasible;
    }
    // Drive artificials out of the basis where possible (degenerate rows stay, at zero).
    for r in 0..k {
        if tab.basis[r] >= n {
            if let Some(j) = (0..n).find(|&j| tab.at(r, j).abs() > eps) {
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
    if !tab.optimise(n) {
        return LpResult::Unbounded;
    }
    let mut x = DVector::zeros(n);
    for r in 0..k {
        if tab.basis[r] < n {
            x[tab.basis[r]] = tab.at(r, n + k).max(0.0);
        }
    }
    let value = c.dot(&x);
    LpResult::Optimal { x, value }
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
