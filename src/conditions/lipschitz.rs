//! Certified sections of a condition that is no polynomial sign — a routed cable's length, a sum
//! of square roots — from its margin at single points and a bound on how fast the margin can
//! change. On a piece [a, b] of λ with the margin m at the middle and |dm/dλ| ≤ L throughout,
//! the margin stays within m ± L(b − a)/2: positive throughout (the condition holds), negative
//! throughout (violated), or the piece is halved, down to the boundary tolerance, where what
//! stays is reported undecided. The bound L comes from the speeds of the points the margin is
//! made of ([`Speed`]), each of which moves the margin at most as fast as it moves (a length, a
//! distance to a fixed set: 1-Lipschitz in each end).

use crate::poly::{Bern, Partition, Truth};
use nalgebra::Vector3;

use super::interval::Iv;

/// Most pieces one motion is bisected into before the rest is reported undecided.
const MAX_NODES: usize = 20_000;

/// Equal pieces of [0, 1] a point's speed is bounded on.
const PIECES: usize = 16;

/// Bounds on the speed |dX/dλ| of a point X = X̂/w along a motion, one per equal piece of [0, 1]
/// (infinite where the weight is not certainly positive).
#[derive(Debug, Clone)]
pub(super) struct Speed {
    bounds: [f64; PIECES],
}

impl Speed {
    /// The speed bounds of X̂/w: on each piece, |X'| ≤ √Σᵢ (|X̂ᵢ'| max w + |X̂ᵢ| |w'|)² / (min w)²,
    /// each magnitude the range of the piece's Bernstein coefficients (error included).
    pub(super) fn of(x: &[Bern; 3], w: &Bern) -> Speed {
        let mut bounds = [f64::INFINITY; PIECES];
        for (k, bound) in bounds.iter_mut().enumerate() {
            let (a, b) = (k as f64 / PIECES as f64, (k + 1) as f64 / PIECES as f64);
            let local = |p: &Bern| p.restrict(a, b);
            let wl = local(w);
            let range = Iv::of(&wl);
            if !(range.lo > 0.0) {
                continue;
            }
            // derivatives in the local parameter: (b − a) times slower in λ
            let dw = Iv::of(&wl.derivative()).mag() / (b - a);
            let sum: f64 = x
                .iter()
                .map(|p| {
                    let pl = local(p);
                    let d = Iv::of(&pl.derivative()).mag() / (b - a);
                    (d * range.hi + Iv::of(&pl).mag() * dw).powi(2)
                })
                .sum();
            *bound = sum.sqrt() / (range.lo * range.lo) * (1.0 + 1e-12);
        }
        Speed { bounds }
    }

    /// The largest speed on [a, b] ⊆ [0, 1].
    pub(super) fn over(&self, a: f64, b: f64) -> f64 {
        let first = ((a * PIECES as f64).floor() as usize).min(PIECES - 1);
        let last = ((b * PIECES as f64).ceil() as usize).clamp(first + 1, PIECES);
        self.bounds[first..last].iter().copied().fold(0.0, f64::max)
    }
}

/// The point X̂(λ)/w(λ) and a bound on its rounding error.
pub(super) fn point_at(x: &[Bern; 3], w: &Bern, lam: f64) -> (Vector3<f64>, f64) {
    let (wv, we) = w.eval(lam);
    let mut p = Vector3::zeros();
    let mut err = 0.0f64;
    for i in 0..3 {
        let (v, e) = x[i].eval(lam);
        p[i] = v / wv;
        err = err.max((e + p[i].abs() * we) / wv);
    }
    (p, err)
}

/// Where `margin` (its value at λ and a bound on that value's error) is negative along a motion,
/// `rate(a, b)` bounding |d margin/dλ| on [a, b]: True where certainly negative, False where
/// certainly positive, Unknown near the boundaries (pieces narrower than a quarter of `tol`) and
/// inside `spare` (ordered, disjoint intervals where the answer is not needed).
pub(super) fn violation(margin: impl Fn(f64) -> (f64, f64), rate: impl Fn(f64, f64) -> f64, tol: f64, spare: &[(f64, f64)]) -> Partition {
    let mut out: Vec<(f64, Truth)> = Vec::new();
    let mut budget = MAX_NODES;
    let mut stack = vec![(0.0f64, 1.0f64)];
    while let Some((a, b)) = stack.pop() {
        let truth = if spare.iter().any(|&(c, d)| c <= a && b <= d) {
            Truth::Unknown
        } else {
            let (m, err) = margin(0.5 * (a + b));
            let reach = rate(a, b) * 0.5 * (b - a) + err;
            if m - reach > 0.0 {
                Truth::False
            } else if m + reach < 0.0 {
                Truth::True
            } else if b - a <= 0.25 * tol || budget == 0 {
                Truth::Unknown
            } else {
                budget -= 1;
                let mid = 0.5 * (a + b);
                stack.push((mid, b));
                stack.push((a, mid));
                continue;
            }
        };
        out.push((b, truth));
    }
    Partition::from_pieces(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sections_of_a_known_margin() {
        // margin 0.3 − |λ − 0.5| (rate 1): violated below 0.2 and above 0.8
        let p = violation(|lam| (0.3 - (lam - 0.5).abs(), 0.0), |_, _| 1.0, 1e-9, &[]);
        let bad = p.where_is(Truth::True);
        assert_eq!(bad.len(), 2);
        assert!(bad[0].0 == 0.0 && (bad[0].1 - 0.2).abs() < 1e-9 && (bad[1].0 - 0.8).abs() < 1e-9 && bad[1].1 == 1.0);
        assert!(p.where_is(Truth::Unknown).iter().all(|(a, b)| b - a < 1e-9));
    }

    #[test]
    fn speeds_bound_the_motion() {
        // X = (λ², 1 − λ, 2λ)/(1 + λ²): sampled speed below the bound on every piece
        let w = Bern::from_monomial(&[1.0, 0.0, 1.0]);
        let x = [Bern::from_monomial(&[0.0, 0.0, 1.0]), Bern::from_monomial(&[1.0, -1.0]), Bern::from_monomial(&[0.0, 2.0])];
        let speed = Speed::of(&x, &w);
        for k in 0..1000 {
            let (l0, l1) = (k as f64 / 1000.0, (k + 1) as f64 / 1000.0);
            let v = (point_at(&x, &w, l1).0 - point_at(&x, &w, l0).0).norm() / (l1 - l0);
            assert!(v <= speed.over(l0, l1), "at {l0}: {v} > {}", speed.over(l0, l1));
        }
    }
}
