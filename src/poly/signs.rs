//! Certified sign pieces of a polynomial on [0, 1]: root isolation by Bernstein subdivision with
//! error control.
//!
//! The result covers [0, 1] with pieces on which the polynomial is certainly positive, certainly
//! negative, exactly zero, or `Unknown`. An `Unknown` piece contains every point where the sign
//! could not be certified; it is at most `tol` wide unless the polynomial is indistinguishable from
//! zero over a wider range (then it is reported as it is, never guessed).

use super::Bern;

/// The sign of a polynomial on a piece.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sign {
    /// Certainly < 0 throughout.
    Neg,
    /// Exactly 0 throughout (the polynomial is the exact zero).
    Zero,
    /// Certainly > 0 throughout.
    Pos,
    /// Not certified (a root, or values within rounding error of zero, may lie here).
    Unknown,
}

/// Limits the work on one polynomial: past this many subdivisions the rest is reported Unknown.
const MAX_NODES: usize = 20_000;

/// Sign pieces of `p` over [0, 1]: `(end, sign)` pairs in increasing order, the first piece
/// starting at 0, the last ending at 1. Unknown pieces are at most `tol` wide where certification
/// succeeds.
pub fn sign_pieces(p: &Bern, tol: f64) -> Vec<(f64, Sign)> {
    sign_pieces_outside(p, tol, &[])
}

/// [`sign_pieces`], except that a piece inside one of the ordered, disjoint intervals `skip`
/// (where the caller does not need the sign) may be reported Unknown without being examined, and
/// a root is not refined once its bracket lies inside one: never more work than without `skip`.
pub fn sign_pieces_outside(p: &Bern, tol: f64, skip: &[(f64, f64)]) -> Vec<(f64, Sign)> {
    if p.is_exact_zero() {
        return vec![(1.0, Sign::Zero)];
    }
    let mut out: Vec<(f64, Sign)> = Vec::new();
    let mut budget = MAX_NODES;
    recurse(p, 0.0, 1.0, &Limits { tol, skip }, &mut budget, &mut out);
    out
}

/// What bounds the work of one sign classification besides its node budget.
struct Limits<'a> {
    /// Width below which a piece is reported Unknown.
    tol: f64,
    /// Where the sign is not needed (see [`sign_pieces_outside`]).
    skip: &'a [(f64, f64)],
}

impl Limits<'_> {
    /// Whether [lo, hi] lies inside a skipped interval.
    fn skipped(&self, lo: f64, hi: f64) -> bool {
        self.skip.iter().any(|&(a, b)| a <= lo && hi <= b)
    }
}

fn push(out: &mut Vec<(f64, Sign)>, end: f64, s: Sign) {
    if let Some(last) = out.last_mut() {
        if last.1 == s {
            last.0 = end;
            return;
        }
    }
    out.push((end, s));
}

/// Sign classification of a coefficient: +1, −1 or 0 (within `err` of zero).
fn sign_of(c: f64, err: f64) -> i8 {
    if c > err {
        1
    } else if c < -err {
        -1
    } else {
        0
    }
}

/// Whether the coefficient signs have the pattern s…s ?…? (−s)…(−s) with certain first and last
/// coefficients: then the polynomial has exactly one root, and it is simple.
fn single_crossing(p: &Bern) -> bool {
    let (first, last) = (sign_of(p.c[0], p.err), sign_of(p.c[p.degree()], p.err));
    if first == 0 || last == 0 || first == last {
        return false;
    }
    let mut phase = 0; // 0: leading sign, 1: unknowns, 2: trailing sign
    for &c in &p.c {
        phase = match (phase, sign_of(c, p.err)) {
            (0, x) if x == first => 0,
            (0 | 1, 0) => 1,
            (_, x) if x == last => 2,
            _ => return false,
        };
    }
    true
}

fn recurse(p: &Bern, lo: f64, hi: f64, limits: &Limits, budget: &mut usize, out: &mut Vec<(f64, Sign)>) {
    let tol = limits.tol;
    if limits.skipped(lo, hi) {
        return push(out, hi, Sign::Unknown);
    }
    if p.c.iter().all(|&c| c > p.err) {
        return push(out, hi, Sign::Pos);
    }
    if p.c.iter().all(|&c| c < -p.err) {
        return push(out, hi, Sign::Neg);
    }
    // Half of tol: an Unknown piece on each side of a split point still merges to at most tol.
    if hi - lo <= 0.5 * tol || *budget == 0 || p.max_abs() <= p.err {
        return push(out, hi, Sign::Unknown);
    }
    *budget -= 1;
    if single_crossing(p) {
        return bisect_root(p, lo, hi, limits, sign_of(p.c[0], p.err), out);
    }
    let (left, right) = p.split(0.5);
    let mid = 0.5 * (lo + hi);
    recurse(&left, lo, mid, limits, budget, out);
    recurse(&right, mid, hi, limits, budget, out);
}

/// Locates the single simple root of `p` on [lo, hi] (local parameter 0…1) on certified values:
/// Illinois false position, with a bisection step every third iteration so the bracket always
/// shrinks, until the bracket is narrower than the tolerance or lies inside a skipped interval.
/// Emits sign `s0` before the root, Unknown around it, −s0 after.
fn bisect_root(p: &Bern, lo: f64, hi: f64, limits: &Limits, s0: i8, out: &mut Vec<(f64, Sign)>) {
    let tol = limits.tol;
    let e = p.value_error();
    let sign_at = |x: f64| -> (i8, f64) {
        let v = p.value(x);
        (if v > e { 1 } else if v < -e { -1 } else { 0 }, v)
    };
    let width = hi - lo;
    let (mut a, mut b) = (0.0f64, 1.0f64);
    let (mut fa, mut fb) = (p.c[0], p.c[p.degree()]);
    let mut last_side = 0i8;
    let mut step = 0usize;
    while (b - a) * width > tol && step < 200 && !limits.skipped(lo + a * width, lo + b * width) {
        step += 1;
        let secant = (a * fb - b * fa) / (fb - fa);
        let m = if step.is_multiple_of(3) || !(secant > a && secant < b) { 0.5 * (a + b) } else { secant };
        match sign_at(m) {
            (s, v) if s == s0 => {
                a = m;
                fa = v;
                if last_side == 1 {
                    fb *= 0.5;
                }
                last_side = 1;
            }
            (0, _) => {
                // The root is within rounding of m: widen a bracket around m step by step until
                // both ends are certified (the narrowest such bracket, within a factor 2).
                let h = 0.25 * tol / width;
                let mut d = h;
                while m - d > a && sign_at(m - d).0 != s0 {
                    d *= 2.0;
                }
                a = a.max(m - d);
                let mut d = h;
                while m + d < b && sign_at(m + d).0 != -s0 {
                    d *= 2.0;
                }
                b = b.min(m + d);
                break;
            }
            (_, v) => {
                b = m;
                fb = v;
                if last_side == -1 {
                    fa *= 0.5;
                }
                last_side = -1;
            }
        }
    }
    let (s_before, s_after) = if s0 > 0 { (Sign::Pos, Sign::Neg) } else { (Sign::Neg, Sign::Pos) };
    if a > 0.0 {
        push(out, lo + a * width, s_before);
    }
    push(out, lo + b * width, Sign::Unknown);
    if b < 1.0 {
        push(out, hi, s_after);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn roots_of(pieces: &[(f64, Sign)]) -> Vec<(f64, f64)> {
        let mut start = 0.0;
        let mut out = vec![];
        for &(end, s) in pieces {
            if s == Sign::Unknown {
                out.push((start, end));
            }
            start = end;
        }
        out
    }

    #[test]
    fn isolates_simple_roots_to_tolerance() {
        // (x − 0.2)(x − 0.5)(x − 0.9)
        let a = [-0.09, 0.73, -1.6, 1.0];
        let pieces = sign_pieces(&Bern::from_monomial(&a), 1e-12);
        let roots = roots_of(&pieces);
        assert_eq!(roots.len(), 3, "{pieces:?}");
        for (r, want) in roots.iter().zip([0.2, 0.5, 0.9]) {
            assert!(r.0 <= want + 1e-15 && want - 1e-15 <= r.1, "{r:?} vs {want}");
            assert!(r.1 - r.0 <= 1e-12, "{r:?} {pieces:?}");
        }
        assert_eq!(pieces[0].1, Sign::Neg);
        assert_eq!(pieces.last().unwrap().1, Sign::Pos);
    }

    #[test]
    fn certifies_constant_signs_and_zero() {
        assert_eq!(sign_pieces(&Bern::from_monomial(&[1.0, -1.0, 1.0]), 1e-12), vec![(1.0, Sign::Pos)]);
        assert_eq!(sign_pieces(&Bern::constant(0.0), 1e-12), vec![(1.0, Sign::Zero)]);
    }

    #[test]
    fn skipped_intervals_are_left_unknown_and_the_rest_kept() {
        // (x − 0.2)(x − 0.5)(x − 0.9), the sign not needed on [0.4, 0.6]
        let p = Bern::from_monomial(&[-0.09, 0.73, -1.6, 1.0]);
        let full = sign_pieces(&p, 1e-12);
        let pieces = sign_pieces_outside(&p, 1e-12, &[(0.4, 0.6)]);
        let roots = roots_of(&pieces);
        // the roots outside the skipped interval are isolated as before; the middle one is not
        // refined: its Unknown piece stays inside [0.4, 0.6] and is wider than the tolerance
        assert_eq!(roots.len(), 3, "{pieces:?}");
        assert_eq!((roots[0], roots[2]), (roots_of(&full)[0], roots_of(&full)[2]));
        assert!(roots[1].0 >= 0.4 && roots[1].1 <= 0.6 && roots[1].1 - roots[1].0 > 1e-12, "{pieces:?}");
        // certified signs stay true wherever they are given
        let mut start = 0.0;
        for &(end, s) in &pieces {
            let mid = 0.5 * (start + end);
            let v = p.value(mid);
            match s {
                Sign::Pos => assert!(v > 0.0),
                Sign::Neg => assert!(v < 0.0),
                _ => {}
            }
            start = end;
        }
    }

    #[test]
    fn double_root_is_reported_unknown_not_guessed() {
        // (x − 0.5)², touching zero at 0.5
        let pieces = sign_pieces(&Bern::from_monomial(&[0.25, -1.0, 1.0]), 1e-10);
        let roots = roots_of(&pieces);
        assert_eq!(roots.len(), 1);
        assert!(roots[0].0 <= 0.5 && 0.5 <= roots[0].1);
        assert!(pieces.iter().all(|p| p.1 != Sign::Neg));
    }
}
