//! The static margin of a balance by a linear program, for the reference checks: the tests
//! build J and the load from definitions of their own and ask this program, written apart from
//! the core's `static_margin_of`.

use cablenav::query::lp::{maximise, LpResult};
use nalgebra::{DMatrix, DVector};

/// Largest t with J f = w, f_min + t ≤ f ≤ f_max − t (an LP over g = f − f_min − t ≥ 0,
/// t = t⁺ − t⁻, upper slacks, t⁺ capped), and the tensions; None when J f = w has no solution.
pub fn lp_margin(j: &DMatrix<f64>, w: &DVector<f64>, (lo, hi): (f64, f64)) -> Option<(f64, DVector<f64>)> {
    lp_margin_each(j, w, &vec![lo; j.ncols()], &vec![hi; j.ncols()])
}

/// [`lp_margin`] with bounds of each cable's own, [lo[k], hi[k]].
pub fn lp_margin_each(j: &DMatrix<f64>, w: &DVector<f64>, lo: &[f64], hi: &[f64]) -> Option<(f64, DVector<f64>)> {
    let (n, m) = j.shape();
    let nvar = m + 2 + m + 1;
    let mut a = DMatrix::zeros(n + m + 1, nvar);
    let mut b = DVector::zeros(n + m + 1);
    for r in 0..n {
        let row_sum: f64 = (0..m).map(|k| j[(r, k)]).sum();
        for k in 0..m {
            a[(r, k)] = j[(r, k)];
        }
        a[(r, m)] = row_sum;
        a[(r, m + 1)] = -row_sum;
        b[r] = w[r] - (0..m).map(|k| j[(r, k)] * lo[k]).sum::<f64>();
    }
    for k in 0..m {
        a[(n + k, k)] = 1.0;
        a[(n + k, m)] = 2.0;
        a[(n + k, m + 1)] = -2.0;
        a[(n + k, m + 2 + k)] = 1.0;
        b[n + k] = hi[k] - lo[k];
    }
    a[(n + m, m)] = 1.0;
    a[(n + m, nvar - 1)] = 1.0;
    b[n + m] = hi.iter().copied().fold(0.0, f64::max);
    let mut c = DVector::zeros(nvar);
    c[m] = 1.0;
    c[m + 1] = -1.0;
    match maximise(&a, &b, &c) {
        LpResult::Optimal { x, value } => Some((value, DVector::from_fn(m, |k, _| lo[k] + value + x[k]))),
        _ => None,
    }
}
