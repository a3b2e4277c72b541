//! A turn about a fixed axis by angle·s(t), s a polynomial time profile (CASPR's rotation between
//! knots, [`super::Orientation::Turn`]), as polynomials with a certified error.
//!
//! cos(θ(t)) and sin(θ(t)), θ = angle·s(t), are not rational in t, so no exact rational motion
//! follows the turn. On each stretch [a, b] of t they are replaced by polynomials of low degree
//! in λ (t = a + (b − a)λ), with an error bound in two parts:
//!
//! 1. the Taylor polynomials of cos and sin about θ_m (the stretch's middle) of order n, composed
//!    exactly with y(λ) = θ(t) − θ_m: by Taylor's theorem the value is off by at most
//!    Y^(n+1)/(n+1)!, Y ≥ |y| over the stretch, and the derivatives in t (chain rule) by
//!    Y^n/n!·B1 and Y^(n−1)/(n−1)!·B1² + Y^n/n!·B2, B1 ≥ |θ'|, B2 ≥ |θ''|;
//! 2. that polynomial (degree 5n) is interpolated at Chebyshev points by one of degree d, and the
//!    difference (and its derivatives) bounded by its largest Bernstein coefficient, which bounds
//!    a polynomial on [0, 1], with the rounding the Bernstein arithmetic tracks.
//!
//! Stretches are halved until the value's error is at most [`TURN_TOLERANCE`] (the first and second
//! derivatives' 100× and 10⁴× that, per unit of the piece's t). The motion's rotation is then
//! the polynomial matrix R0·(I + S·K + (1 − C)·K²) (Rodrigues' formula, K the axis's cross-product
//! matrix, C and S the polynomials for cos θ and sin θ) over the weight 1: each entry within
//! 2·[`TURN_TOLERANCE`] of CASPR's rotation (its derivatives likewise), and orthogonal to within
//! about 4·TURN_TOLERANCE — CASPR itself rounds its angles to 1e-10. The angle's own rate,
//! θ' = angle·s'(t), is a polynomial: the motion carries it ([`super::motion::Spin`]), and the
//! platform's angular velocity and acceleration are taken from it exactly. What cablenav
//! certifies along such a trajectory is this polynomial motion. (A rotation exact to rounding, the quaternion
//! (C, S·axis) over its squared norm, doubles the degree and brings a weight of that degree into
//! every condition: a turn of CASPR's spline took five times as long to verify.)

use std::cell::RefCell;
use std::rc::Rc;

use super::trajectory::Profile;
use crate::poly::Bern;

/// The largest error allowed in the cosine and sine of the angle turned; their first and second
/// derivatives per unit of the piece's t are allowed 100× and 10⁴× that.
pub const TURN_TOLERANCE: f64 = 1e-11;

/// The derivatives' tolerances, relative to [`TURN_TOLERANCE`].
const DERIVATIVE_SLACK: [f64; 3] = [1.0, 1e2, 1e4];

/// Highest degree tried before a stretch is halved.
const MAX_DEGREE: usize = 10;

/// Deepest halving of a stretch (2^−12 of a piece: never reached for angles up to π, where 32
/// stretches at most suffice — the tests check every turn up to π meets the tolerance).
const MAX_DEPTH: u32 = 12;

/// Highest Taylor order composed.
const MAX_ORDER: usize = 24;

/// One stretch [a, b] of a turn's t: cos θ and sin θ (θ the angle turned since t = 0) as
/// polynomials in λ ∈ [0, 1], t = a + (b − a)λ, and their certified errors.
#[derive(Debug, Clone, PartialEq)]
pub struct TurnStretch {
    /// Start of the stretch in the piece's t.
    pub a: f64,
    /// End of the stretch.
    pub b: f64,
    /// cos θ, ascending monomial coefficients in λ.
    pub cos: Vec<f64>,
    /// sin θ, likewise.
    pub sin: Vec<f64>,
    /// Bounds on |error|, |d error/dt| and |d² error/dt²| of both, over the stretch.
    pub error: [f64; 3],
}

/// p(α + βλ) for ascending coefficients `c`.
fn compose_linear(c: &[f64], alpha: f64, beta: f64) -> Vec<f64> {
    // Horner in polynomials: acc = acc·(α + βλ) + c_k
    let mut acc: Vec<f64> = vec![0.0; c.len()];
    for &ck in c.iter().rev() {
        let mut next = vec![0.0; c.len()];
        for (j, &a) in acc.iter().enumerate() {
            next[j] += a * alpha;
            if j + 1 < next.len() {
                next[j + 1] += a * beta;
            }
        }
        next[0] += ck;
        acc = next;
    }
    acc
}

/// A bound on |p| over [0, 1]: the largest Bernstein coefficient plus the tracked rounding.
fn sup(p: &Bern) -> f64 {
    p.max_abs() + p.err
}

/// The allowed errors of value, first and second derivative.
fn tolerances() -> [f64; 3] {
    DERIVATIVE_SLACK.map(|k| k * TURN_TOLERANCE)
}

/// The angle turned, θ = `angle`·s(t), on the stretch [a, b] of t as a polynomial in λ
/// (t = a + (b − a)λ).
pub fn angle_on(angle: f64, profile: Profile, a: f64, b: f64) -> Bern {
    // composed in monomial form, not by Bernstein restriction: restriction's tracked rounding,
    // divided by the width squared, swamps the second derivative's bound on short stretches
    Bern::from_monomial(&compose_linear(profile.coefficients(), a, b - a)).scale(angle)
}

/// The Taylor polynomials of cos θ and sin θ about the stretch's middle composed with y(λ), as
/// Bernstein polynomials, and their error bounds (part 1 of the module docs); `None` when no
/// order up to [`MAX_ORDER`] is within a quarter of the tolerances.
fn composed(angle: f64, profile: Profile, a: f64, b: f64) -> Option<(Bern, Bern, [f64; 3])> {
    let width = b - a;
    let theta = angle_on(angle, profile, a, b);
    let theta_m = angle * profile.at(0.5 * (a + b))[0];
    let y = theta.sub(&Bern::constant(theta_m));
    let big_y = sup(&y);
    let d1 = theta.derivative();
    let (b1, b2) = (sup(&d1) / width, sup(&d1.derivative()) / (width * width));
    let tol = tolerances();
    let factorial = |k: usize| (1..=k).fold(1.0, |acc, j| acc * j as f64);
    // the Taylor remainder's bounds at order n: value, first and second derivative
    let bounds = |n: usize| {
        let (yn, yn1) = (big_y.powi(n as i32) / factorial(n), big_y.powi(n as i32 - 1) / factorial(n - 1));
        [big_y.powi(n as i32 + 1) / factorial(n + 1), yn * b1, yn1 * b1 * b1 + yn * b2]
    };
    let order = (1..=MAX_ORDER).find(|&n| (0..3).all(|k| bounds(n)[k] <= 0.25 * tol[k]))?;
    let error = bounds(order);
    // C(y) = Σ (−1)^(j/2) y^j/j! over even j, S(y) over odd j: each sum in one pass
    let mut powers = vec![Bern::constant(1.0)];
    for j in 1..=order {
        powers.push(powers[j - 1].mul(&y));
    }
    let series = |parity: usize| {
        let terms: Vec<(&Bern, f64)> = (parity..=order).step_by(2).map(|j| (&powers[j], if (j / 2) % 2 == 0 { 1.0 } else { -1.0 } / factorial(j))).collect();
        Bern::linear_combination(&terms)
    };
    let (c, s) = (series(0), series(1));
    let (cm, sm) = (theta_m.cos(), theta_m.sin());
    let cos = Bern::linear_combination(&[(&c, cm), (&s, -sm)]);
    let sin = Bern::linear_combination(&[(&c, sm), (&s, cm)]);
    Some((cos, sin, error))
}

/// The d + 1 Chebyshev points of [0, 1] and the LU factors of their Vandermonde matrix, for
/// every degree d up to [`MAX_DEGREE`] (index d).
type Nodes = Vec<(Vec<f64>, nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>)>;

fn chebyshev() -> &'static Nodes {
    static TABLE: std::sync::OnceLock<Nodes> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        (0..=MAX_DEGREE)
            .map(|d| {
                let nodes: Vec<f64> = (0..=d).map(|k| 0.5 - 0.5 * (std::f64::consts::PI * (2 * k + 1) as f64 / (2 * d + 2) as f64).cos()).collect();
                let v = nalgebra::DMatrix::from_fn(d + 1, d + 1, |i, j| nodes[i].powi(j as i32));
                (nodes, v.lu())
            })
            .collect()
    })
}

/// The polynomial of degree d ≤ [`MAX_DEGREE`] through `p` at d + 1 Chebyshev points of [0, 1]
/// (ascending monomial coefficients), or `None` if the system is singular. (Its error is
/// bounded afterwards, [`difference`]: how it is found does not matter to the certificate.)
fn interpolate(p: &Bern, d: usize) -> Option<Vec<f64>> {
    let (nodes, lu) = &chebyshev()[d];
    let rhs = nalgebra::DVector::from_iterator(d + 1, nodes.iter().map(|&x| p.value(x)));
    lu.solve(&rhs).map(|c| c.iter().copied().collect())
}

/// The bounds on |p − q|, |(p − q)'| and |(p − q)''| in t over the stretch of width `width`.
fn difference(p: &Bern, q: &[f64], width: f64) -> [f64; 3] {
    let diff = p.sub(&Bern::from_monomial(q));
    let d1 = diff.derivative();
    [
        sup(&diff),
        sup(&d1) / width,
        sup(&d1.derivative()) / (width * width),
    ]
}

/// How many turns [`turn_stretches`] remembers (per thread).
const REMEMBERED: usize = 32;

thread_local! {
    /// The last turns built, by angle and profile, newest last.
    static BUILT: RefCell<Vec<((u64, Profile), Rc<Vec<TurnStretch>>)>> = const { RefCell::new(Vec::new()) };
}

/// The stretches of a turn by `angle` with `profile` over t ∈ [0, 1], each within the tolerances
/// ([`build_stretches`]), remembered: a turn depends on its angle and profile alone, and a
/// scenario verified again (the page's live updates, another duration, another condition) asks
/// for the same turns.
pub fn turn_stretches(angle: f64, profile: Profile) -> Rc<Vec<TurnStretch>> {
    let key = (angle.to_bits(), profile);
    if let Some(found) = BUILT.with(|b| b.borrow().iter().find(|(k, _)| *k == key).map(|(_, s)| Rc::clone(s))) {
        return found;
    }
    let built = Rc::new(build_stretches(angle, profile));
    BUILT.with(|b| {
        let mut b = b.borrow_mut();
        if b.len() == REMEMBERED {
            b.remove(0);
        }
        b.push((key, Rc::clone(&built)));
    });
    built
}

/// The stretches of a turn by `angle` with `profile` over t ∈ [0, 1], each within the tolerances,
/// built anew. A turn by 0 is one stretch with the exact polynomials 1 and 0.
pub fn build_stretches(angle: f64, profile: Profile) -> Vec<TurnStretch> {
    if angle == 0.0 {
        return vec![TurnStretch {
            a: 0.0,
            b: 1.0,
            cos: vec![1.0],
            sin: vec![0.0],
            error: [0.0; 3],
        }];
    }
    let mut out = Vec::new();
    stretch(angle, profile, 0.0, 1.0, 0, &mut out);
    out
}

/// The approximation on [a, b], or on its halves: the lowest degree that meets the tolerances,
/// looked for from the degree of the stretch before (neighbouring stretches need about the same:
/// mostly two fits), downwards while it meets them, else upwards to [`MAX_DEGREE`]; where none
/// does, the stretch is halved.
fn stretch(angle: f64, profile: Profile, a: f64, b: f64, depth: u32, out: &mut Vec<TurnStretch>) {
    let tol = tolerances();
    let within = |error: &[f64; 3]| (0..3).all(|k| error[k] <= tol[k]);
    if let Some((cos, sin, taylor)) = composed(angle, profile, a, b) {
        // the interpolant of degree d, if it meets the tolerances (at the deepest halving, the
        // highest degree whatever its error)
        let fit = |d: usize| -> Option<TurnStretch> {
            let (qc, qs) = (interpolate(&cos, d)?, interpolate(&sin, d)?);
            let (ec, es) = (difference(&cos, &qc, b - a), difference(&sin, &qs, b - a));
            let error = std::array::from_fn(|k| taylor[k] + ec[k].max(es[k]));
            (within(&error) || (d == MAX_DEGREE && depth >= MAX_DEPTH)).then_some(TurnStretch { a, b, cos: qc, sin: qs, error })
        };
        let start = out.last().map_or(MAX_DEGREE, |s| s.cos.len() - 1).clamp(2, MAX_DEGREE);
        let found = match fit(start) {
            Some(mut best) => {
                while let Some(lower) = (best.cos.len() > 3).then(|| fit(best.cos.len() - 2)).flatten() {
                    best = lower;
                }
                Some(best)
            }
            None => (start + 1..=MAX_DEGREE).find_map(fit),
        };
        if let Some(best) = found {
            out.push(best);
            return;
        }
    }
    let m = 0.5 * (a + b);
    stretch(angle, profile, a, m, depth + 1, out);
    stretch(angle, profile, m, b, depth + 1, out);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn eval(c: &[f64], x: f64) -> f64 {
        c.iter().rev().fold(0.0, |acc, &a| acc * x + a)
    }

    /// Dense sampling never finds an error beyond the certified bounds, the bounds are within the
    /// tolerance, and the stretches tile [0, 1].
    #[test]
    fn stretches_follow_the_turn_within_their_bounds() {
        for profile in [Profile::Quintic, Profile::Cubic] {
            for angle in [1e-6, 0.3, 1.0, 2.0, std::f64::consts::PI] {
                let stretches = build_stretches(angle, profile);
                assert_eq!(stretches[0].a, 0.0);
                assert_eq!(stretches.last().unwrap().b, 1.0);
                for w in stretches.windows(2) {
                    assert_eq!(w[0].b, w[1].a);
                }
                for s in &stretches {
                    assert!(
                        s.error[0] <= TURN_TOLERANCE && s.error[1] <= 100.0 * TURN_TOLERANCE,
                        "{profile:?} {angle}: {:?}",
                        s.error
                    );
                    for i in 0..=200 {
                        let lam = i as f64 / 200.0;
                        let t = s.a + (s.b - s.a) * lam;
                        let theta = angle * profile.at(t)[0];
                        assert!(
                            (eval(&s.cos, lam) - theta.cos()).abs() <= s.error[0].max(1e-16),
                            "{profile:?} {angle} cos at {t}"
                        );
                        assert!(
                            (eval(&s.sin, lam) - theta.sin()).abs() <= s.error[0].max(1e-16),
                            "{profile:?} {angle} sin at {t}"
                        );
                    }
                }
                // bigger turns need more stretches, never absurdly many
                assert!(
                    stretches.len() <= 64,
                    "{profile:?} {angle}: {} stretches",
                    stretches.len()
                );
            }
        }
    }

    /// A turn asked for again is the one built the first time (the same stretches, not rebuilt),
    /// and equal to one built anew.
    #[test]
    fn turns_are_remembered() {
        let first = turn_stretches(0.8, Profile::Cubic);
        assert!(Rc::ptr_eq(&first, &turn_stretches(0.8, Profile::Cubic)));
        assert!(!Rc::ptr_eq(&first, &turn_stretches(0.8, Profile::Quintic)));
        assert_eq!(*first, build_stretches(0.8, Profile::Cubic));
    }

    #[test]
    fn no_turn_is_exact() {
        let s = build_stretches(0.0, Profile::Quintic);
        assert_eq!(s.len(), 1);
        assert_eq!(
            (s[0].cos.clone(), s[0].sin.clone(), s[0].error),
            (vec![1.0], vec![0.0], [0.0; 3])
        );
    }
}
