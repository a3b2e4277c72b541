//! The combinatorics of a zonotope's facets: which n − 1 of its m generators (a structure
//! matrix's columns) span a facet's hyperplane, how many such sets there are, and the
//! hyperplane's normal; and the determinant ratio below which such columns count as dependent.
//! Shared by hyperplane shifting ([`super::wrench`]) and the search over wrench directions
//! ([`super::zonotope`]).

use nalgebra::{DMatrix, DVector};

/// Below this |det J| / Π‖column‖ (Hadamard ratio) a pose counts as singular.
pub const SINGULAR_RATIO: f64 = 1e-10;

/// C(m, k): how many k-element subsets 0..m has, `usize::MAX` where it does not fit (the callers
/// compare it with a cap). Each step's product is taken in 128 bits: 8S_neck's C(76, 23) fits,
/// but its product on the way did not.
pub fn binomial(m: usize, k: usize) -> usize {
    if k > m {
        return 0;
    }
    (0..k).try_fold(1usize, |c, i| usize::try_from(c as u128 * (m - i) as u128 / (i + 1) as u128).ok()).unwrap_or(usize::MAX)
}

/// The k-element subsets of 0..m in lexicographic order.
pub fn subsets(m: usize, k: usize) -> Vec<Vec<usize>> {
    let mut out = Vec::new();
    let mut cur = Vec::with_capacity(k);
    fn rec(start: usize, m: usize, k: usize, cur: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
        if cur.len() == k {
            out.push(cur.clone());
            return;
        }
        for i in start..m {
            cur.push(i);
            rec(i + 1, m, k, cur, out);
            cur.pop();
        }
    }
    rec(0, m, k, &mut cur, &mut out);
    out
}

/// The normal of the hyperplane through the n − 1 columns `s` of the n×m matrix `j`: the
/// cofactors of the last column of [J_S | x], so that n·x = det [J_S | x].
pub fn facet_normal(j: &DMatrix<f64>, s: &[usize]) -> DVector<f64> {
    let n = j.nrows();
    DVector::from_fn(n, |r, _| {
        let minor = DMatrix::from_fn(n - 1, n - 1, |a, b| j[(if a < r { a } else { a + 1 }, s[b])]);
        let sign = if (r + n - 1) % 2 == 0 { 1.0 } else { -1.0 };
        sign * minor.determinant()
    })
}

/// Most facet pairs (sets of n − 1 of the structure matrix's m columns, C(m, n − 1); 252 = C(10, 5))
/// for which the wrench conditions test them all; beyond it a single wrench and closure are
/// tested by linear programs, and a wrench ellipsoid by a cover of the wrench directions
/// (`conditions::WrenchFeasibilityLp`, `query::zonotope`).
pub const MAX_FACETS: usize = 252;

/// Whether the wrench conditions enumerate the facets of `m` cables for a platform moving as
/// `mobility` (at most [`MAX_FACETS`] of them): up to 10 cables on a spatial platform, 23 on a
/// point mass or a planar one.
pub fn facets_enumerable(m: usize, mobility: crate::model::Mobility) -> bool {
    binomial(m, mobility.dof() - 1) <= MAX_FACETS
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Binomials exact where they fit (against Pascal's rule), saturated where they do not.
    #[test]
    fn binomials_are_exact_or_saturated() {
        assert_eq!((binomial(10, 5), binomial(5, 7), binomial(7, 0)), (252, 0, 1));
        // 8S_neck: 76 cables, 23 of its 24 rows (saturated where usize has 32 bits, as in wasm32)
        let exact: u128 = 17_061_084_191_613_232_800;
        assert_eq!(binomial(76, 23) as u128, exact.min(usize::MAX as u128));
        assert_eq!(binomial(76, 23), binomial(75, 22).saturating_add(binomial(75, 23)));
        assert_eq!(binomial(128, 64), usize::MAX);
    }
}
