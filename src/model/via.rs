//! Polynomial translations through via points, for editors: the editor shows a polynomial
//! trajectory as the points it passes at evenly spaced τ, and writes back the coefficients of
//! the one polynomial (per axis) of least degree through them.
//!
//! With n points P₀ … Pₙ₋₁ the parameters are τₖ = k/(n−1), so P₀ is the start (τ = 0) and
//! Pₙ₋₁ the end (τ = 1); the polynomial has degree ≤ n − 1. It is computed by Newton's divided
//! differences and expanded into the ascending coefficients the scenario format stores.

use crate::error::{finite, Error, Result};
use super::trajectory::MAX_DEGREE;

/// Fewest via points (a line).
pub const MIN_POINTS: usize = 2;
/// Most via points (the format's highest degree, plus one).
pub const MAX_POINTS: usize = MAX_DEGREE + 1;

/// The parameter τₖ of via point `k` of `n`.
pub fn via_tau(k: usize, n: usize) -> f64 {
    if n < 2 {
        0.0
    } else {
        k as f64 / (n - 1) as f64
    }
}

/// Ascending coefficients `[x, y, z]` of the polynomial through `points` at τₖ = k/(n−1).
/// `field` names the points in errors (e.g. `trajectories[0].translation`). Coefficients below
/// 1e-13 of the largest coordinate (rounding residue, e.g. the τ² term through three collinear
/// points) are set to zero so the degree is not raised by noise; then trailing zeros are dropped.
/// The result passes the points to about 1e-12 of their size at low degree; the monomial basis
/// loses digits as the degree grows (about 1e-9 at degree 10).
pub fn polynomial_through(field: &str, points: &[[f64; 3]]) -> Result<[Vec<f64>; 3]> {
    let n = points.len();
    if !(MIN_POINTS..=MAX_POINTS).contains(&n) {
        return Err(Error::new(
            field,
            format!("a polynomial through via points needs {MIN_POINTS} to {MAX_POINTS} points (degree ≤ {MAX_DEGREE}), got {n}"),
        ));
    }
    for (k, p) in points.iter().enumerate() {
        for (i, x) in p.iter().enumerate() {
            finite(&format!("{field}[{k}][{i}]"), *x)?;
        }
    }
    let taus: Vec<f64> = (0..n).map(|k| via_tau(k, n)).collect();
    let mut out: [Vec<f64>; 3] = Default::default();
    for (axis, slot) in out.iter_mut().enumerate() {
        let ys: Vec<f64> = points.iter().map(|p| p[axis]).collect();
        let scale = ys.iter().fold(0.0f64, |m, y| m.max(y.abs()));
        let mut c = monomial(&taus, &newton(&taus, &ys));
        for x in &mut c {
            if x.abs() <= 1e-13 * scale {
                *x = 0.0;
            }
        }
        while c.len() > 1 && c.last() == Some(&0.0) {
            c.pop();
        }
        *slot = c;
    }
    Ok(out)
}

/// The positions at τₖ = k/(n−1), k = 0 … n−1, of the polynomial with ascending coefficients
/// `coeffs` (one row per axis): the via points an editor shows for it.
pub fn via_points(coeffs: &[Vec<f64>; 3], n: usize) -> Vec<[f64; 3]> {
    (0..n)
        .map(|k| {
            let t = via_tau(k, n);
            coeffs.clone().map(|row| row.iter().rev().fold(0.0, |acc, &a| acc * t + a))
        })
        .collect()
}

/// How many via points show a polynomial: one more than its highest degree over the axes (at
/// least [`MIN_POINTS`]), so that [`polynomial_through`] of [`via_points`] gives it back.
pub fn via_count(coeffs: &[Vec<f64>; 3]) -> usize {
    coeffs.iter().map(Vec::len).max().unwrap_or(0).max(MIN_POINTS)
}

/// Newton's divided differences: d[k] = f[τ₀, …, τₖ].
fn newton(taus: &[f64], ys: &[f64]) -> Vec<f64> {
    let mut d = ys.to_vec();
    for level in 1..taus.len() {
        for k in (level..taus.len()).rev() {
            d[k] = (d[k] - d[k - 1]) / (taus[k] - taus[k - level]);
        }
    }
    d
}

/// Expands the Newton form Σ d[k]·Π_{j<k}(τ − τⱼ) into ascending monomial coefficients, by
/// Horner's scheme from the highest term down.
fn monomial(taus: &[f64], d: &[f64]) -> Vec<f64> {
    let mut c: Vec<f64> = Vec::with_capacity(d.len());
    for k in (0..d.len()).rev() {
        // c ← c·(τ − τₖ) + d[k]
        let mut next = vec![0.0; c.len() + 1];
        for (j, &a) in c.iter().enumerate() {
            next[j + 1] += a;
            next[j] -= a * taus[k];
        }
        next[0] += d[k];
        c = next;
    }
    c
}
