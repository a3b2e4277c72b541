//! The (n−1)×(n−1) minors of an n-row matrix of polynomials restricted to sets of n − 1 columns,
//! for many sets in turn ([`Minors`]) — the cofactors every wrench condition is written in.
//!
//! Laplace expansion along the last column of each set, with the determinants of every row subset
//! on every prefix of a set memoised and shared between the sets (the six cofactor columns of a
//! 6×6 matrix share all prefixes up to the column each leaves out; the facets' five-column sets
//! share theirs). Every entry is first raised to its row's degree d_r, so that the determinant of
//! the rows R has the degree D(R) = Σ_{r∈R} d_r whichever entries it is made of, and every term of
//! an expansion lands on the same coefficients. The sub-determinants are kept in scaled Bernstein
//! form, c̃_k = C(D, k)·c_k, in which a product is a plain convolution: each term adds its
//! products straight into one accumulator, with no intermediate polynomial, and only the minors
//! returned are divided back.
//!
//! Error bounds (those of [`Bern`], bounds on every plain coefficient): a sub-determinant's value
//! is *defined* as its scaled coefficients divided by the exact binomials, so only the entries'
//! scaling, the accumulation and the final division round. For a term e_r·M_r (e_r of largest
//! coefficient A_r and error ε_r, M_r of B_r and η_r), Σ_i C(d_r, i)·C(D', k − i) = C(D, k) makes
//! the plain effect of |ẽ_i|·|M̃_{k−i}| at most A_r·B_r per coefficient; each term's sums of at
//! most q products are within γ_q of exact (γ_q = q·u/(1 − q·u)), the T terms' sum within γ_T,
//! the scaled entries within u (and the binomial table's own rounding past C(56, k), the last row
//! exact in f64). So a determinant's error is Σ_r (ε_r B_r + η_r A_r + ε_r η_r) +
//! (γ_q + γ_T + 3u')·Σ_r A_r B_r.

use std::collections::HashMap;

use super::bernstein::{binomial, Bern};

/// Unit roundoff of f64.
const U: f64 = f64::EPSILON * 0.5;

/// The largest n for which every binomial C(n, k) is an exact f64.
const EXACT_BINOMIALS: usize = 56;

/// Relative error of C(n, k) as the table gives it: none up to [`EXACT_BINOMIALS`], past it the
/// rounding of n additions of positive numbers (Pascal's rule, row by row).
fn binomial_error(n: usize) -> f64 {
    if n <= EXACT_BINOMIALS { 0.0 } else { (n + 1) as f64 * U }
}

/// A polynomial in scaled Bernstein form: `scaled[k]` = C(D, k)·c_k of degree D, with the largest
/// plain |c_k| (an upper bound) and the bound on every plain c_k's error.
#[derive(Debug, Clone)]
struct Scaled {
    scaled: Vec<f64>,
    max: f64,
    err: f64,
}

impl Scaled {
    /// From plain Bernstein form (the scaling rounds each coefficient once: within u' = u + the
    /// binomials' error, counted where the scaled coefficients are used).
    fn of(p: &Bern) -> Scaled {
        let n = p.degree();
        Scaled { scaled: p.c.iter().enumerate().map(|(k, c)| c * binomial(n, k)).collect(), max: p.max_abs(), err: p.err }
    }

    fn degree(&self) -> usize {
        self.scaled.len() - 1
    }

    /// Back to plain Bernstein form: one division per coefficient (and the binomials' error).
    fn plain(&self) -> Bern {
        let n = self.degree();
        let c: Vec<f64> = self.scaled.iter().enumerate().map(|(k, c)| c / binomial(n, k)).collect();
        let max = c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let mut out = Bern::from_bernstein(c);
        out.err = self.err + (U + binomial_error(n)) * max;
        out
    }

    /// The largest plain coefficient of scaled coefficients `scaled` (degree n), rounded up.
    fn max_of(scaled: &[f64]) -> f64 {
        let n = scaled.len() - 1;
        let max = scaled.iter().enumerate().fold(0.0f64, |m, (k, c)| m.max(c.abs() / binomial(n, k)));
        max * (1.0 + 2.0 * (U + binomial_error(n)))
    }
}

/// The determinants of every row subset (a bit mask) on one prefix of a column set; `None` for an
/// exactly zero determinant (no term: every entry of its last column exactly zero there).
type Table = Vec<Option<Scaled>>;

/// The minors of one matrix on column sets asked for one after another, the sub-determinants
/// kept from one set to the next.
pub struct Minors {
    /// Each entry raised to its row's degree, scaled; `None` where exactly zero.
    entries: Vec<Vec<Option<Scaled>>>,
    /// Each row's degree.
    degree: Vec<usize>,
    /// The determinants on each prefix met so far (a column bit mask), by row subset.
    tables: HashMap<u64, Table>,
}

impl Minors {
    /// Ready for the minors of `rows` (1 to 24 rows of polynomials, at most 64 columns).
    pub fn new(rows: &[Vec<Bern>]) -> Minors {
        let n = rows.len();
        assert!((1..=24).contains(&n) && rows.iter().all(|r| r.len() <= 64), "minors of 1 to 24 rows of at most 64 columns");
        let degree: Vec<usize> = rows.iter().map(|row| row.iter().map(Bern::degree).max().unwrap_or(0)).collect();
        let entries = rows
            .iter()
            .zip(&degree)
            .map(|(row, &d)| row.iter().map(|p| (!p.is_exact_zero()).then(|| Scaled::of(&p.elevate(d)))).collect())
            .collect();
        let mut empty = vec![None; 1 << n];
        empty[0] = Some(Scaled { scaled: vec![1.0], max: 1.0, err: 0.0 });
        Minors { entries, degree, tables: HashMap::from([(0, empty)]) }
    }

    /// The n minors on the n − 1 columns `set` (in increasing order): entry j is the
    /// determinant of the matrix restricted to those columns without row j; an exactly zero
    /// minor is the constant 0.
    pub fn of(&mut self, set: &[usize]) -> Vec<Bern> {
        let n = self.entries.len();
        assert!(set.len() + 1 == n && set.windows(2).all(|w| w[0] < w[1]), "n − 1 columns in increasing order");
        let mut prefix = 0u64;
        for (k, &c) in set.iter().enumerate() {
            let next = prefix | (1u64 << c);
            if !self.tables.contains_key(&next) {
                let table = expand(&self.entries, &self.degree, &self.tables[&prefix], c, k + 1);
                self.tables.insert(next, table);
            }
            prefix = next;
        }
        let (table, full) = (&self.tables[&prefix], (1u32 << n) - 1);
        (0..n).map(|j| table[(full & !(1u32 << j)) as usize].as_ref().map_or_else(|| Bern::constant(0.0), Scaled::plain)).collect()
    }
}

/// The determinants of every k-row subset on a prefix of k columns whose last is `c`, by Laplace
/// expansion along c from `sub`, the (k−1)-row determinants on the prefix before it: the term of
/// row r at position p (in increasing row order) has the sign (−1)^(p + k − 1).
fn expand(entries: &[Vec<Option<Scaled>>], degree: &[usize], sub: &Table, c: usize, k: usize) -> Table {
    let n = entries.len();
    let mut table: Table = vec![None; 1 << n];
    for mask in (1u32..(1 << n)).filter(|m| m.count_ones() as usize == k) {
        let d: usize = (0..n).filter(|r| mask & (1 << r) != 0).map(|r| degree[r]).sum();
        let (mut acc, mut term) = (vec![0.0; d + 1], vec![0.0; d + 1]);
        let (mut terms, mut products, mut err, mut size) = (0usize, 0usize, 0.0f64, 0.0f64);
        for (pos, r) in (0..n).filter(|r| mask & (1 << r) != 0).enumerate() {
            let (Some(e), Some(m)) = (&entries[r][c], &sub[(mask & !(1 << r)) as usize]) else { continue };
            let sign = if (pos + k - 1) % 2 == 1 { -1.0 } else { 1.0 };
            // the term's convolution apart, then added: (q + T)·u rather than q·T·u
            term.fill(0.0);
            for (i, &a) in e.scaled.iter().enumerate() {
                for (o, &b) in term[i..].iter_mut().zip(&m.scaled) {
                    *o += a * b;
                }
            }
            for (o, t) in acc.iter_mut().zip(&term) {
                *o += sign * t;
            }
            terms += 1;
            products = products.max(e.degree().min(m.degree()) + 1);
            err += e.err * m.max + m.err * e.max + e.err * m.err;
            size += e.max * m.max * (1.0 + binomial_error(e.degree()));
        }
        if terms == 0 {
            continue;
        }
        // γ_q for each term's sums of q products, γ_T for adding T terms, 2u for the scaled entries
        let gamma = |n: usize| n as f64 * U / (1.0 - n as f64 * U);
        let err = err + (gamma(products) + gamma(terms) + 3.0 * U) * size;
        let max = Scaled::max_of(&acc);
        table[mask as usize] = Some(Scaled { scaled: acc, max, err });
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The determinant of a small matrix of polynomials by the permutation formula, evaluated at x.
    fn det_at(m: &[Vec<&Bern>], x: f64) -> f64 {
        fn permutations(a: &mut Vec<usize>, l: usize, out: &mut Vec<Vec<usize>>) {
            if l == a.len() {
                out.push(a.clone());
                return;
            }
            for i in l..a.len() {
                a.swap(l, i);
                permutations(a, l + 1, out);
                a.swap(l, i);
            }
        }
        let n = m.len();
        let mut all = Vec::new();
        permutations(&mut (0..n).collect(), 0, &mut all);
        all.iter()
            .map(|p| {
                let inversions = (0..n).flat_map(|i| (i + 1..n).map(move |j| (i, j))).filter(|&(i, j)| p[i] > p[j]).count();
                let sign = if inversions % 2 == 0 { 1.0 } else { -1.0 };
                sign * p.iter().enumerate().map(|(r, &c)| m[r][c].value(x)).product::<f64>()
            })
            .sum()
    }

    /// The k-element subsets of 0..m in increasing order.
    fn subsets(m: usize, k: usize) -> Vec<Vec<usize>> {
        (0u32..(1 << m)).filter(|s| s.count_ones() as usize == k).map(|s| (0..m).filter(|i| s & (1 << i) != 0).collect()).collect()
    }

    fn random_poly(seed: &mut u64, degree: usize) -> Bern {
        let mut next = || {
            *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        Bern::from_bernstein((0..=degree).map(|_| next()).collect())
    }

    /// Every minor of random polynomial matrices (rows of mixed degrees, some entries exactly
    /// zero) equals the permutation formula's at sample points, within the minor's error bound
    /// plus the reference's own rounding; shared prefixes give the same minors as sets alone.
    #[test]
    fn minors_match_the_permutation_formula() {
        let mut seed = 7u64;
        for n in [2usize, 3, 4, 6] {
            let m = n + 2;
            let rows: Vec<Vec<Bern>> = (0..n)
                .map(|r| (0..m).map(|c| if (r + 2 * c) % 7 == 3 { Bern::constant(0.0) } else { random_poly(&mut seed, 1 + (r + c) % 3) }).collect())
                .collect();
            let mut shared = Minors::new(&rows);
            for set in subsets(m, n - 1) {
                let got = shared.of(&set);
                let alone = Minors::new(&rows).of(&set);
                for j in 0..n {
                    assert_eq!(got[j].c, alone[j].c, "shared and alone differ");
                    let sub: Vec<Vec<&Bern>> = (0..n).filter(|&r| r != j).map(|r| set.iter().map(|&c| &rows[r][c]).collect()).collect();
                    for i in 0..=8 {
                        let x = i as f64 / 8.0;
                        let (v, e) = got[j].eval(x);
                        let want = det_at(&sub, x);
                        assert!((v - want).abs() <= e + 1e-13, "n={n} set {set:?} minor {j} at {x}: {v} vs {want} (bound {e})");
                    }
                    assert!(got[j].err < 1e-12, "{}", got[j].err);
                }
            }
        }
    }
}
