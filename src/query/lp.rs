//! A small dense linear-programming solver: maximise cᵀx subject to A x = b, x ≥ 0, by the
//! two-phase simplex method with Bland's rule (no cycling). Sized for the per-pose wrench problems
//! (a handful of equalities, tens of variables); not for large sparse problems.

use nalgebra::{DMatrix, DVector};

/// Pivot and feasibility tolerance, relative to the problem's scale.
const EPS: f64 = 1e-11;

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

/// A simplex tableau: rows [A | b] in canonical form for `basis`, objective row last.
struct Tableau {
    t: DMatrix<f64>,
    basis: Vec<usize>,
    eps: f64,
}

impl Tableau {
    fn rows(&self) -> usize {
        self.t.nrows() - 1
    }

    fn cols(&self) -> usize {
        self.t.ncols() - 1
    }

    fn pivot(&mut self, r: usize, c: usize) {
        let p = self.t[(r, c)];
        let row = self.t.row(r) / p;
        self.t.set_row(r, &row);
        for i in 0..self.t.nrows() {
            if i != r {
                let f = self.t[(i, c)];
                if f != 0.0 {
                    let new = self.t.row(i) - row.clone() * f;
                    self.t.set_row(i, &new);
                }
            }
        }
        self.basis[r] = c;
    }

    /// Runs the simplex iterations on the objective row (reduced costs stored negated: entering
    /// columns have a negative entry) over the columns `< allowed`. `false` if unbounded.
    fn optimise(&mut self, allowed: usize) -> bool {
        let obj = self.rows();
        // Bland's rule guarantees termination; the cap only guards against rounding loops.
        for _ in 0..10_000 {
            let Some(c) = (0..allowed).find(|&j| self.t[(obj, j)] < -self.eps) else { return true };
            let rhs = self.cols();
            let mut best: Option<(f64, usize)> = None;
            for r in 0..obj {
                let a = self.t[(r, c)];
                if a > self.eps {
                    let ratio = self.t[(r, rhs)] / a;
                    let better = match best {
                        None => true,
                        Some((q, br)) => ratio < q - self.eps || (ratio <= q + self.eps && self.basis[r] < self.basis[br]),
                    };
                    if better {
                        best = Some((ratio, r));
                    }
                }
            }
            let Some((_, r)) = best else { return false };
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
    let mut t = DMatrix::zeros(k + 1, n + k + 1);
    for i in 0..k {
        let s = if b[i] < 0.0 { -1.0 } else { 1.0 };
        for j in 0..n {
            t[(i, j)] = s * a[(i, j)];
        }
        t[(i, n + i)] = 1.0;
        t[(i, n + k)] = s * b[i];
    }
    // Objective row of phase 1 (maximise −Σy), made canonical for the artificial basis.
    for i in 0..k {
        for j in 0..n {
            t[(k, j)] -= t[(i, j)];
        }
        t[(k, n + k)] -= t[(i, n + k)];
    }
    let mut tab = Tableau { t, basis: (n..n + k).collect(), eps };
    tab.optimise(n + k);
    if -tab.t[(k, n + k)] > eps * (k as f64 + 1.0) {
        return LpResult::Infeasible;
    }
    // Drive artificials out of the basis where possible (degenerate rows stay, at zero).
    for r in 0..k {
        if tab.basis[r] >= n {
            if let Some(j) = (0..n).find(|&j| tab.t[(r, j)].abs() > eps) {
                tab.pivot(r, j);
            }
        }
    }
    // Phase 2: the real objective (maximise cᵀx ⇒ row holds −c, made canonical).
    for j in 0..tab.t.ncols() {
        tab.t[(k, j)] = if j < n { -c[j] } else { 0.0 };
    }
    for r in 0..k {
        let bj = tab.basis[r];
        if bj < n {
            let f = tab.t[(k, bj)];
            if f != 0.0 {
                let row = tab.t.row(r) * f;
                let new = tab.t.row(k) - row;
                tab.t.set_row(k, &new);
            }
        }
    }
    if !tab.optimise(n) {
        return LpResult::Unbounded;
    }
    let mut x = DVector::zeros(n);
    for r in 0..k {
        if tab.basis[r] < n {
            x[tab.basis[r]] = tab.t[(r, n + k)].max(0.0);
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
}
