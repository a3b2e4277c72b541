//! Bernstein-form polynomials on [0, 1] with coefficient error bounds.
//!
//! A [`Bern`] of degree n stands for p(x) = Σ c_k C(n,k) x^k (1−x)^(n−k). Its field `err` bounds
//! |c_k − c̃_k| for every k, where c̃ are the coefficients exact arithmetic would have produced from
//! the same inputs. Because the Bernstein basis is non-negative and sums to 1, `err` also bounds the
//! error of p(x) for every x in [0, 1], and every operation below (all of them convex or
//! positively-weighted combinations) adds a small, explicitly bounded rounding term.

use smallvec::{smallvec, SmallVec};
use std::borrow::Cow;
use std::sync::OnceLock;

/// Bernstein coefficients: up to [`INLINE`] of them stored in place (every polynomial of the
/// presets' verifications), more on the heap.
pub type Coeffs = SmallVec<[f64; INLINE]>;

/// n zero coefficients.
fn zeros(n: usize) -> Coeffs {
    if n <= INLINE {
        Coeffs::from_buf_and_len([0.0; INLINE], n)
    } else {
        smallvec![0.0; n]
    }
}

/// Coefficients kept without allocating: degree 24, the products of two cable vectors' cross
/// products along a quadratic trajectory with a slerp.
pub const INLINE: usize = 25;

/// Unit roundoff of f64.
const U: f64 = f64::EPSILON * 0.5;

/// Largest degree the binomial table covers.
const MAX_DEGREE: usize = 320;

fn pascal() -> &'static Vec<Vec<f64>> {
    static TABLE: OnceLock<Vec<Vec<f64>>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut rows: Vec<Vec<f64>> = Vec::with_capacity(MAX_DEGREE + 1);
        for n in 0..=MAX_DEGREE {
            let mut row = vec![1.0; n + 1];
            for k in 1..n {
                row[k] = rows[n - 1][k - 1] + rows[n - 1][k];
            }
            rows.push(row);
        }
        rows
    })
}

/// Binomial coefficient C(n, k) (0 when k > n). Exact up to n = 56, correctly rounded-ish beyond.
pub fn binomial(n: usize, k: usize) -> f64 {
    if k > n {
        0.0
    } else if n <= MAX_DEGREE {
        pascal()[n][k]
    } else {
        let k = k.min(n - k);
        (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
    }
}

/// A polynomial on [0, 1] in Bernstein form with a coefficient error bound.
#[derive(Debug, Clone, PartialEq)]
pub struct Bern {
    /// Bernstein coefficients c_0 … c_n (never empty).
    pub c: Coeffs,
    /// Bound on the absolute error of every coefficient.
    pub err: f64,
}

/// The ratio, scale and direction of Horner's scheme for a Bernstein sum of degree `n` at x:
/// Σ c_j C(n,j) x^j (1−x)^(n−j) = (1−x)^n Σ c_j C(n,j) r^j with r = x/(1−x) up to the middle
/// (coefficients taken from c_n down), x^n Σ c_j C(n,j) r^(n−j) with r = (1−x)/x past it (from c_0
/// up, `forward`), so that r ≤ 1 either way.
fn horner_ratio(x: f64, n: usize) -> (f64, f64, bool) {
    if x <= 0.5 {
        (x / (1.0 - x), (1.0 - x).powi(n as i32), false)
    } else {
        ((1.0 - x) / x, x.powi(n as i32), true)
    }
}

fn max_abs(c: &[f64]) -> f64 {
    c.iter().fold(0.0, |m, x| m.max(x.abs()))
}

impl Bern {
    /// The constant `a`, exact.
    pub fn constant(a: f64) -> Bern {
        Bern { c: smallvec![a], err: 0.0 }
    }

    /// Exact Bernstein coefficients, taken as given.
    pub fn from_bernstein(c: Vec<f64>) -> Bern {
        let c = if c.is_empty() { smallvec![0.0] } else { Coeffs::from_vec(c) };
        Bern { c, err: 0.0 }
    }

    /// From ascending monomial coefficients a_j (p(x) = Σ a_j x^j):
    /// c_k = Σ_{j ≤ k} C(k, j) / C(n, j) · a_j.
    pub fn from_monomial(a: &[f64]) -> Bern {
        if a.is_empty() {
            return Bern::constant(0.0);
        }
        let n = a.len() - 1;
        let mut c = zeros(n + 1);
        let mut bound = 0.0f64;
        let bn = pascal_row(n);
        for (k, ck) in c.iter_mut().enumerate() {
            let (mut s, mut mag, bk) = (0.0, 0.0, pascal_row(k));
            for (j, aj) in a.iter().enumerate().take(k + 1) {
                let t = bk[j] / bn[j] * aj;
                s += t;
                mag += t.abs();
            }
            *ck = s;
            bound = bound.max(mag);
        }
        Bern { c, err: (2 * n + 4) as f64 * U * bound }
    }

    /// Degree n (number of coefficients − 1).
    pub fn degree(&self) -> usize {
        self.c.len() - 1
    }

    /// Largest coefficient magnitude: a bound on |p(x)| over [0, 1] (before adding `err`).
    pub fn max_abs(&self) -> f64 {
        max_abs(&self.c)
    }

    /// The same polynomial with degree raised to `n` (≥ current degree).
    pub fn elevate(&self, n: usize) -> Bern {
        if n <= self.degree() {
            return self.clone();
        }
        let mut c = zeros(n + 1);
        let err = self.elevate_to(&mut c);
        Bern { c, err }
    }

    /// Writes the coefficients of [`Bern::elevate`] to degree `out.len() − 1` (at least this
    /// degree) into `out`, without building a polynomial, and returns their error bound.
    pub fn elevate_to(&self, out: &mut [f64]) -> f64 {
        let m = self.degree();
        if out.len() == m + 1 {
            out.copy_from_slice(&self.c);
            return self.err;
        }
        elevate_into(&self.c, out);
        self.err + (m + 4) as f64 * U * self.max_abs()
    }

    fn combine(&self, other: &Bern, sign: f64) -> Bern {
        // an exact zero adds nothing: no rounding, and no degree
        if other.is_exact_zero() {
            return self.clone();
        }
        if self.is_exact_zero() {
            return other.scale(sign);
        }
        let (m, k) = (self.degree(), other.degree());
        let n = m.max(k);
        // Both operands at degree n, the lower one elevated straight into the output buffer.
        let mut c = zeros(n + 1);
        let mut err = self.err + other.err;
        if m < n {
            elevate_into(&self.c, &mut c);
            err += (m + 4) as f64 * U * self.max_abs();
            for (x, y) in c.iter_mut().zip(&other.c) {
                *x += sign * y;
            }
        } else if k < n {
            elevate_into(&other.c, &mut c);
            err += (k + 4) as f64 * U * other.max_abs();
            for (x, y) in c.iter_mut().zip(&self.c) {
                *x = y + sign * *x;
            }
        } else {
            for ((z, x), y) in c.iter_mut().zip(&self.c).zip(&other.c) {
                *z = x + sign * y;
            }
        }
        let err = err + U * max_abs(&c);
        Bern { c, err }
    }

    /// self + other.
    pub fn add(&self, other: &Bern) -> Bern {
        self.combine(other, 1.0)
    }

    /// self − other.
    pub fn sub(&self, other: &Bern) -> Bern {
        self.combine(other, -1.0)
    }

    /// self · k for a constant k (taken as exact). Times an exact 0 it is the constant 0, of
    /// degree 0 (a product with a vanishing term, w' of a constant weight, raises no degree).
    pub fn scale(&self, k: f64) -> Bern {
        if k == 0.0 {
            return Bern::constant(0.0);
        }
        let mut c = zeros(self.c.len());
        for (z, x) in c.iter_mut().zip(&self.c) {
            *z = x * k;
        }
        Bern { err: self.err * k.abs() + U * max_abs(&c), c }
    }

    /// self · other (degrees add). Computed as a convolution of the C(n,k)-scaled coefficients.
    pub fn mul(&self, other: &Bern) -> Bern {
        let (m, n) = (self.degree(), other.degree());
        if m == 0 {
            return other.scale_with_err(self.c[0], self.err);
        }
        if n == 0 {
            return self.scale_with_err(other.c[0], other.err);
        }
        let mut coeffs = zeros(m + n + 1);
        let c: &mut [f64] = &mut coeffs;
        // the C(n, j)-scaled coefficients of `other` once, then a plain convolution
        let (bm, bn) = (pascal_row(m), pascal_row(n));
        let scaled = binomial_scaled(&other.c, &bn);
        for (i, (x, bi)) in self.c.iter().zip(bm.iter()).enumerate() {
            let ai = x * bi;
            for (ck, y) in c[i..].iter_mut().zip(&scaled[..]) {
                *ck += ai * y;
            }
        }
        if m + n <= MAX_DEGREE {
            for (ck, q) in c.iter_mut().zip(&inverse_pascal()[m + n]) {
                *ck *= q;
            }
        } else {
            for (ck, b) in c.iter_mut().zip(pascal_row(m + n).iter()) {
                *ck /= b;
            }
        }
        let (ma, mb) = (self.max_abs(), other.max_abs());
        let err = self.err * mb + other.err * ma + self.err * other.err + (m.min(n) + 6) as f64 * U * ma * mb;
        Bern { c: coeffs, err }
    }

    /// Σ k_i · p_i · q_i for constants k_i (taken as exact), in one pass: the products of the
    /// highest degree are convolved into one buffer (no polynomial per product, no addition
    /// after), those of a lower degree are multiplied apart and added. Each coefficient is then
    /// one sum of at most L = Σ_i (min(deg p_i, deg q_i) + 1) products, whose magnitudes over
    /// C(N, k) sum to at most Σ_i |k_i| max|p_i| max|q_i| (Vandermonde), so its rounding is
    /// within (L + 7)·u of that: the same analysis as [`Bern::mul`] with the sum's length and one
    /// rounding more for k_i. An empty sum is the constant 0.
    pub fn sum_of_products(terms: &[(&Bern, &Bern, f64)]) -> Bern {
        let top = terms.iter().map(|(p, q, _)| p.degree() + q.degree()).max().unwrap_or(0);
        if top > MAX_DEGREE {
            return terms.iter().fold(Bern::constant(0.0), |acc, (p, q, k)| acc.add(&p.mul(q).scale(*k)));
        }
        let mut c = zeros(top + 1);
        let (mut err, mut mag, mut length) = (0.0, 0.0, 0usize);
        let mut lower: SmallVec<[Bern; 2]> = SmallVec::new();
        for &(p, q, k) in terms {
            let (m, n) = (p.degree(), q.degree());
            if m + n < top {
                lower.push(p.mul(q).scale(k));
                continue;
            }
            let (ma, mb) = (p.max_abs(), q.max_abs());
            err += k.abs() * (p.err * mb + q.err * ma + p.err * q.err);
            mag += k.abs() * ma * mb;
            length += m.min(n) + 1;
            let (bm, bn) = (&pascal()[m], &pascal()[n]);
            let scaled = binomial_scaled(&q.c, bn);
            for (i, (x, bi)) in p.c.iter().zip(bm.iter()).enumerate() {
                let ai = k * x * bi;
                for (ck, y) in c[i..].iter_mut().zip(&scaled[..]) {
                    *ck += ai * y;
                }
            }
        }
        for (ck, q) in c.iter_mut().zip(&inverse_pascal()[top]) {
            *ck *= q;
        }
        let sum = Bern { c, err: err + (length + 7) as f64 * U * mag };
        lower.iter().fold(sum, |acc, p| acc.add(p))
    }

    /// Σ k_i · p_i for constants k_i (taken as exact), at the largest degree among the p_i, in
    /// one pass: no intermediate polynomial, and only terms of a lower degree are elevated. The
    /// rounding of each coefficient, a sum of m products, is within γ_m ≤ (m + 1)u of the sum of
    /// the products' magnitudes. An empty sum is the constant 0.
    pub fn linear_combination(terms: &[(&Bern, f64)]) -> Bern {
        let n = terms.iter().map(|(p, _)| p.degree()).max().unwrap_or(0);
        let mut c = zeros(n + 1);
        let mut mag = zeros(n + 1);
        let mut err = 0.0;
        let mut lifted = Coeffs::new();
        for &(p, k) in terms {
            let coeffs: &[f64] = if p.degree() == n {
                &p.c
            } else {
                lifted.clear();
                lifted.resize(n + 1, 0.0);
                elevate_into(&p.c, &mut lifted);
                err += k.abs() * (p.degree() + 4) as f64 * U * p.max_abs();
                &lifted
            };
            for ((z, m), x) in c.iter_mut().zip(mag.iter_mut()).zip(coeffs) {
                let t = k * x;
                *z += t;
                *m += t.abs();
            }
            err += k.abs() * p.err;
        }
        let err = err + (terms.len() + 1) as f64 * U * max_abs(&mag);
        Bern { c, err }
    }

    /// (1 − x)·`a` + x·`b` for `a` and `b` of one degree n, at degree n + 1 without a product:
    /// its coefficient j is ((n + 1 − j)·a_j + j·b_(j−1))/(n + 1), a convex combination, so the
    /// error is the larger of the two plus a few roundings.
    pub fn blend(a: &Bern, b: &Bern) -> Bern {
        let n = a.degree();
        assert_eq!(n, b.degree(), "a blend of polynomials of one degree");
        let mut c = zeros(n + 2);
        let top = (n + 1) as f64;
        let (ac, bc): (&[f64], &[f64]) = (&a.c, &b.c);
        for (j, z) in c.iter_mut().enumerate() {
            let left = if j <= n { (top - j as f64) / top * ac[j] } else { 0.0 };
            let right = if j > 0 { j as f64 / top * bc[j - 1] } else { 0.0 };
            *z = left + right;
        }
        let err = a.err.max(b.err) + 4.0 * U * (max_abs(ac) + max_abs(bc));
        Bern { c, err }
    }

    fn scale_with_err(&self, k: f64, k_err: f64) -> Bern {
        if k_err == 0.0 && k == 0.0 {
            return Bern::constant(0.0);
        }
        let mut r = self.scale(k);
        r.err += k_err * (self.max_abs() + self.err);
        r
    }

    /// Value at x ∈ [0, 1] and a bound on its error ([`Bern::value`], [`Bern::value_error`]).
    pub fn eval(&self, x: f64) -> (f64, f64) {
        (self.value(x), self.value_error())
    }

    /// Value at x ∈ [0, 1]. Horner's scheme in x/(1−x) (or (1−x)/x past the middle) on the
    /// C(n,k)-scaled coefficients: O(n), no allocation.
    pub fn value(&self, x: f64) -> f64 {
        let n = self.degree();
        let row = pascal_row(n);
        let (r, scale, forward) = horner_ratio(x, n);
        let (mut acc, c) = (0.0, &self.c[..]);
        for k in 0..=n {
            // highest power first: c_n (or c_0 when running backwards)
            let j = if forward { k } else { n - k };
            acc = acc * r + c[j] * row[j];
        }
        acc * scale
    }

    /// Value, first and second derivative at x ∈ [0, 1], without error bounds (for estimates,
    /// not certificates): the last two steps of de Casteljau's scheme, from b₀, b₁, b₂ — the
    /// degree n − 2 polynomials of c_0 … c_(n−2), c_1 … c_(n−1) and c_2 … c_n at x, all three by
    /// one pass of [`Bern::value`]'s Horner scheme: p = (1 − x)²b₀ + 2x(1 − x)b₁ + x²b₂,
    /// p' = n((1 − x)(b₁ − b₀) + x(b₂ − b₁)), p'' = n(n − 1)(b₂ − 2b₁ + b₀). O(n), no allocation.
    pub fn jet(&self, x: f64) -> (f64, f64, f64) {
        let c: &[f64] = &self.c;
        let n = c.len() - 1;
        match n {
            0 => return (c[0], 0.0, 0.0),
            1 => return ((1.0 - x) * c[0] + x * c[1], c[1] - c[0], 0.0),
            _ => {}
        }
        let row = pascal_row(n - 2);
        let (r, scale, forward) = horner_ratio(x, n - 2);
        let (mut b0, mut b1, mut b2) = (0.0, 0.0, 0.0);
        for k in 0..=n - 2 {
            let j = if forward { k } else { n - 2 - k };
            b0 = b0 * r + c[j] * row[j];
            b1 = b1 * r + c[j + 1] * row[j];
            b2 = b2 * r + c[j + 2] * row[j];
        }
        let (b0, b1, b2) = (b0 * scale, b1 * scale, b2 * scale);
        let (l0, l1) = ((1.0 - x) * b0 + x * b1, (1.0 - x) * b1 + x * b2);
        let nf = n as f64;
        ((1.0 - x) * l0 + x * l1, nf * (l1 - l0), nf * (nf - 1.0) * (b2 - 2.0 * b1 + b0))
    }

    /// A bound on the error of [`Bern::value`] at any x ∈ [0, 1]: the coefficients' own, plus the
    /// rounding, taken relative to Σ|c_k|B_k(x) ≤ max|c|.
    pub fn value_error(&self) -> f64 {
        self.err + (5 * self.degree() + 5) as f64 * U * self.max_abs()
    }

    /// The two halves of the polynomial split at x, each re-parametrised to [0, 1].
    pub fn split(&self, x: f64) -> (Bern, Bern) {
        let n = self.degree();
        // de Casteljau in place in `right`: after level l, right[k] (k ≤ n − l) holds the level-l
        // point k; its first entry is the left half's coefficient l, and right[n − l] is final.
        let mut right = self.c.clone();
        let mut left = zeros(n + 1);
        // on plain slices: no inline-or-heap check per access
        let (l, r): (&mut [f64], &mut [f64]) = (&mut left, &mut right);
        l[0] = r[0];
        for (level, out) in l.iter_mut().enumerate().skip(1) {
            for k in 0..=(n - level) {
                r[k] = r[k] * (1.0 - x) + r[k + 1] * x;
            }
            *out = r[0];
        }
        let err = self.err + (2 * n + 2) as f64 * U * self.max_abs();
        (Bern { c: left, err }, Bern { c: right, err })
    }

    /// The polynomial on [a, b] ⊆ [0, 1], re-parametrised to [0, 1]: the left part of a split at
    /// b, then the right part of that at a/b, each de Casteljau's scheme in place (each adds the
    /// rounding bound of [`Bern::split`]).
    pub fn restrict(&self, a: f64, b: f64) -> Bern {
        let n = self.degree();
        let mut out = self.clone();
        let c: &mut [f64] = &mut out.c;
        if b < 1.0 {
            out.err += (2 * n + 2) as f64 * U * max_abs(c);
            // after level j, c[k] (k ≥ j) holds the level-j point k − j; c[j] is the left half's j-th
            for j in 1..=n {
                for k in (j..=n).rev() {
                    c[k] = c[k - 1] * (1.0 - b) + c[k] * b;
                }
            }
        }
        if a > 0.0 {
            let x = a / b;
            out.err += (2 * n + 2) as f64 * U * max_abs(c);
            // after level j, c[k] (k ≤ n − j) holds the level-j point k; c[n − j] is the right half's
            for j in 1..=n {
                for k in 0..=(n - j) {
                    c[k] = c[k] * (1.0 - x) + c[k + 1] * x;
                }
            }
        }
        out
    }

    /// The derivative dp/dx, of degree n − 1: n·(c_{k+1} − c_k). Each coefficient carries twice
    /// the input's error times n, plus the rounding of one subtraction and one product.
    pub fn derivative(&self) -> Bern {
        let n = self.degree();
        if n == 0 {
            return Bern::constant(0.0);
        }
        let k = n as f64;
        let mut c = zeros(n);
        for (i, ci) in c.iter_mut().enumerate() {
            *ci = k * (self.c[i + 1] - self.c[i]);
        }
        Bern { err: 2.0 * k * self.err + 3.0 * U * max_abs(&c), c }
    }

    /// Whether every coefficient is exactly zero and the error bound is zero.
    pub fn is_exact_zero(&self) -> bool {
        self.err == 0.0 && self.c.iter().all(|&x| x == 0.0)
    }
}

/// The halves at 1/2 of the Bernstein coefficients `c` (de Casteljau), written to `left` and
/// `right` (each as long as `c`); returns the added coefficient error bound (as [`Bern::split`]
/// bounds it). For callers that keep coefficients in flat arrays of their own.
pub fn halve(c: &[f64], left: &mut [f64], right: &mut [f64]) -> f64 {
    let n = c.len() - 1;
    right.copy_from_slice(c);
    left[0] = right[0];
    for (level, out) in left.iter_mut().enumerate().skip(1) {
        // the level's n − level + 1 averages, over the n − level + 2 values left of the last
        let row = &mut right[..=n - level + 1];
        for k in 0..row.len() - 1 {
            row[k] = 0.5 * (row[k] + row[k + 1]);
        }
        *out = row[0];
    }
    (2 * n + 2) as f64 * U * max_abs(c)
}

/// 1 / C(n, k), row by row up to MAX_DEGREE.
fn inverse_pascal() -> &'static Vec<Vec<f64>> {
    static TABLE: OnceLock<Vec<Vec<f64>>> = OnceLock::new();
    TABLE.get_or_init(|| pascal().iter().map(|row| row.iter().map(|b| 1.0 / b).collect()).collect())
}

/// Writes the coefficients `c` (degree m) raised to degree n = out.len() − 1 > m into `out`:
/// out_k = Σ_j C(m, j) c_j C(n − m, k − j) / C(n, k).
fn elevate_into(c: &[f64], out: &mut [f64]) {
    let m = c.len() - 1;
    let n = out.len() - 1;
    let r = n - m;
    out.iter_mut().for_each(|x| *x = 0.0);
    if n <= MAX_DEGREE {
        let (bm, br, inv) = (&pascal()[m], &pascal()[r], &inverse_pascal()[n]);
        for (j, (x, b)) in c.iter().zip(bm).enumerate() {
            let a = x * b;
            for (o, q) in out[j..=j + r].iter_mut().zip(br) {
                *o += a * q;
            }
        }
        for (o, q) in out.iter_mut().zip(inv) {
            *o *= q;
        }
    } else {
        let (bm, br, bn) = (pascal_row(m), pascal_row(r), pascal_row(n));
        for (k, o) in out.iter_mut().enumerate() {
            let (lo, hi) = (k.saturating_sub(r), k.min(m));
            *o = (lo..=hi).map(|j| bm[j] * br[k - j] / bn[k] * c[j]).sum();
        }
    }
}

/// The coefficients `c` times the binomial row `b` (C(n, j) c_j), filled in place rather than
/// collected (a collection checks its capacity at every element).
fn binomial_scaled(c: &[f64], b: &[f64]) -> Coeffs {
    let mut out = zeros(c.len());
    for ((o, x), bj) in out.iter_mut().zip(c).zip(b) {
        *o = x * bj;
    }
    out
}

/// Row n of the binomial table: borrowed from the table up to [`MAX_DEGREE`], computed past it
/// in O(n), each entry the same number [`binomial`] gives (the same products in the same order,
/// mirrored about the middle).
fn pascal_row(n: usize) -> Cow<'static, [f64]> {
    if n <= MAX_DEGREE {
        return Cow::Borrowed(&pascal()[n]);
    }
    let mut row = vec![1.0; n + 1];
    let mut acc = 1.0;
    for i in 0..n / 2 {
        acc = acc * (n - i) as f64 / (i + 1) as f64;
        row[i + 1] = acc;
        row[n - i - 1] = acc;
    }
    Cow::Owned(row)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mono_eval(a: &[f64], x: f64) -> f64 {
        a.iter().rev().fold(0.0, |acc, c| acc * x + c)
    }

    /// Rows past the table are the numbers `binomial` gives, bit for bit.
    #[test]
    fn rows_past_the_table_are_binomial() {
        for n in [MAX_DEGREE - 1, MAX_DEGREE, MAX_DEGREE + 1, MAX_DEGREE + 2, 400, 777] {
            let row = pascal_row(n);
            assert_eq!(row.len(), n + 1);
            assert!((0..=n).all(|k| row[k].to_bits() == binomial(n, k).to_bits()), "row {n}");
        }
    }

    #[test]
    fn monomial_round_trip_and_products() {
        let a = [1.0, -3.0, 0.5, 2.0];
        let b = [0.25, 4.0, -1.0];
        let pa = Bern::from_monomial(&a);
        let pb = Bern::from_monomial(&b);
        let prod = pa.mul(&pb);
        let sum = pa.add(&pb);
        for i in 0..=20 {
            let x = i as f64 / 20.0;
            let (v, e) = prod.eval(x);
            let want = mono_eval(&a, x) * mono_eval(&b, x);
            assert!((v - want).abs() <= e + 1e-15, "product at {x}: {v} vs {want} (err {e})");
            let (v, e) = sum.eval(x);
            assert!((v - (mono_eval(&a, x) + mono_eval(&b, x))).abs() <= e + 1e-15);
        }
    }

    #[test]
    fn split_halves_agree_with_whole() {
        let p = Bern::from_monomial(&[0.3, -2.0, 5.0, -1.0, 0.7]);
        let (l, r) = p.split(0.3);
        for i in 0..=10 {
            let x = i as f64 / 10.0;
            assert!((l.value(x) - p.value(0.3 * x)).abs() < 1e-13);
            assert!((r.value(x) - p.value(0.3 + 0.7 * x)).abs() < 1e-13);
        }
    }

    #[test]
    fn restriction_keeps_values() {
        let p = Bern::from_monomial(&[0.3, -2.0, 5.0, -1.0]);
        let q = p.restrict(0.25, 0.75);
        for i in 0..=10 {
            let x = i as f64 / 10.0;
            assert!((q.value(x) - p.value(0.25 + 0.5 * x)).abs() < 1e-13);
        }
    }

    #[test]
    fn linear_combination_matches_its_terms() {
        let (p, q, r) = (Bern::from_monomial(&[1.0, 2.0, -3.0]), Bern::from_monomial(&[0.5, -1.0, 0.25, 4.0]), Bern::constant(-0.7));
        let sum = Bern::linear_combination(&[(&p, 2.0), (&q, -0.3), (&r, 1.5)]);
        assert_eq!(sum.degree(), 3);
        for i in 0..=10 {
            let x = i as f64 / 10.0;
            let want = 2.0 * p.value(x) - 0.3 * q.value(x) + 1.5 * r.value(x);
            let (v, e) = sum.eval(x);
            assert!((v - want).abs() <= e + 1e-15, "at {x}: {v} vs {want} (err {e})");
        }
        assert!(sum.err > 0.0 && sum.err < 1e-13, "{}", sum.err);
        assert_eq!(Bern::linear_combination(&[]).c[..], [0.0]);
    }

    /// A sum of products equals the products summed (within both error bounds), products of
    /// unequal degrees included, and its bound covers the error against the exact
    /// coefficients: on integer-valued Bernstein coefficients small enough that every step of
    /// the reference below is exact in f64.
    #[test]
    fn a_sum_of_products_is_the_products_summed() {
        let (a, b) = (Bern::from_bernstein(vec![3.0, -1.0, 4.0, 1.0, -5.0]), Bern::from_bernstein(vec![-2.0, 6.0, 5.0, -3.0]));
        let (c, d) = (Bern::from_monomial(&[0.3, -2.0, 5.0, -1.0, 0.7, 0.1]), Bern::from_monomial(&[1.5, 0.25]));
        let terms = [(&a, &b, 1.0), (&a, &a, -0.5), (&c, &d, 2.0), (&d, &d, 3.0)];
        let sum = Bern::sum_of_products(&terms);
        let reference = terms.iter().fold(Bern::constant(0.0), |acc, (p, q, k)| acc.add(&p.mul(q).scale(*k)));
        assert_eq!(sum.degree(), 8);
        for (x, y) in sum.c.iter().zip(&reference.c) {
            assert!((x - y).abs() <= sum.err + reference.err, "{sum:?} vs {reference:?}");
        }
        // exact coefficients of a·b − 2 a² (degree 7): Σ_{i+j=k} C(4,i)C(3,j) a_i b_j / C(7,k) and
        // Σ C(4,i)C(4,j) a_i a_j / C(8,k) raised by one degree — compared in the scaled form,
        // integers below 2^53
        let exact = Bern::sum_of_products(&[(&a, &b, 1.0), (&a, &a, -2.0)]);
        let scaled = |p: &Bern, q: &Bern| -> Vec<f64> {
            let (m, n) = (p.degree(), q.degree());
            let mut out = vec![0.0; m + n + 1];
            for i in 0..=m {
                for j in 0..=n {
                    out[i + j] += binomial(m, i) * binomial(n, j) * p.c[i] * q.c[j];
                }
            }
            out
        };
        let (ab, aa) = (scaled(&a, &b), scaled(&a, &a));
        for k in 0..=8 {
            // a·b of degree 7 raised to 8: C(8,k) c_k = C(7,k) c'_k + C(7,k−1) c'_(k−1) on scaled forms
            let ab8 = ab.get(k).copied().unwrap_or(0.0) + if k > 0 { ab[k - 1] } else { 0.0 };
            let want = (ab8 - 2.0 * aa[k]) / binomial(8, k);
            assert!((exact.c[k] - want).abs() <= exact.err, "coefficient {k}: {} vs {want} (err {})", exact.c[k], exact.err);
        }
        assert!(exact.err > 0.0 && exact.err < 1e-12, "{}", exact.err);
        assert_eq!(Bern::sum_of_products(&[]).c[..], [0.0]);
    }

    #[test]
    fn a_jet_matches_the_derivatives() {
        let p = Bern::from_monomial(&[0.3, -2.0, 5.0, -1.0, 0.7]);
        let (d1, d2) = (p.derivative(), p.derivative().derivative());
        for x in [0.0, 0.2, 0.5, 0.7, 1.0] {
            let (v, s, c) = p.jet(x);
            assert!((v - p.value(x)).abs() < 1e-14 && (s - d1.value(x)).abs() < 1e-13 && (c - d2.value(x)).abs() < 1e-12, "at {x}");
        }
        assert_eq!(Bern::constant(2.5).jet(0.3), (2.5, 0.0, 0.0));
        let line = Bern::from_bernstein(vec![1.0, 3.0]);
        assert_eq!(line.jet(0.25), (1.5, 2.0, 0.0));
    }

    #[test]
    fn a_blend_is_the_products_sum() {
        let (a, b) = (Bern::from_monomial(&[1.0, 2.0, -3.0, 0.5]), Bern::from_monomial(&[-0.4, 0.1, 2.0, 1.5]));
        let blend = Bern::blend(&a, &b);
        let products = a.mul(&Bern::from_bernstein(vec![1.0, 0.0])).add(&b.mul(&Bern::from_bernstein(vec![0.0, 1.0])));
        assert_eq!(blend.degree(), 4);
        for (x, y) in blend.c.iter().zip(&products.c) {
            assert!((x - y).abs() <= blend.err + products.err, "{blend:?} vs {products:?}");
        }
        assert!(blend.err > 0.0 && blend.err < 1e-14, "{}", blend.err);
    }

    #[test]
    fn elevation_keeps_values() {
        let p = Bern::from_monomial(&[1.0, 2.0, -3.0]);
        let q = p.elevate(7);
        for i in 0..=10 {
            let x = i as f64 / 10.0;
            assert!((p.value(x) - q.value(x)).abs() < 1e-14);
        }
    }
}
