//! Three-valued truth over [0, 1], piecewise constant: the sets the conditions describe.

use super::{sign_pieces_outside, Bern, Sign};

/// Truth of a statement on a piece of [0, 1].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Truth {
    /// Certainly false throughout.
    False,
    /// Certainly true throughout.
    True,
    /// Not certified.
    Unknown,
}

impl Truth {
    fn and(self, o: Truth) -> Truth {
        match (self, o) {
            (Truth::False, _) | (_, Truth::False) => Truth::False,
            (Truth::True, Truth::True) => Truth::True,
            _ => Truth::Unknown,
        }
    }

    fn or(self, o: Truth) -> Truth {
        match (self, o) {
            (Truth::True, _) | (_, Truth::True) => Truth::True,
            (Truth::False, Truth::False) => Truth::False,
            _ => Truth::Unknown,
        }
    }
}

/// A piecewise-constant three-valued truth over [0, 1]: `(end, truth)` pieces in increasing order,
/// the first starting at 0 and the last ending at 1, adjacent pieces differing.
#[derive(Debug, Clone, PartialEq)]
pub struct Partition {
    /// The pieces.
    pub pieces: Vec<(f64, Truth)>,
}

impl Partition {
    /// The same truth everywhere.
    pub fn constant(t: Truth) -> Partition {
        Partition { pieces: vec![(1.0, t)] }
    }

    /// Where `p > 0` (`positive`) or `p < 0` (otherwise), certified to `tol`.
    pub fn atom(p: &Bern, positive: bool, tol: f64) -> Partition {
        Partition::atom_outside(p, positive, tol, &[])
    }

    /// [`Partition::atom`], except that pieces inside one of the ordered, disjoint intervals
    /// `skip` may be left Unknown without work (see [`sign_pieces_outside`]): for an atom whose
    /// truth does not matter there, such as one conjoined with something false there.
    pub fn atom_outside(p: &Bern, positive: bool, tol: f64, skip: &[(f64, f64)]) -> Partition {
        let pieces = sign_pieces_outside(p, tol, skip)
            .into_iter()
            .map(|(end, s)| {
                let t = match (s, positive) {
                    (Sign::Unknown, _) => Truth::Unknown,
                    (Sign::Pos, true) | (Sign::Neg, false) => Truth::True,
                    _ => Truth::False,
                };
                (end, t)
            })
            .collect();
        Partition::normalised(pieces)
    }

    /// From `(end, truth)` pieces in increasing order, the last ending at 1 (adjacent equal
    /// pieces are merged).
    pub fn from_pieces(pieces: Vec<(f64, Truth)>) -> Partition {
        Partition::normalised(pieces)
    }

    fn normalised(pieces: Vec<(f64, Truth)>) -> Partition {
        let mut out: Vec<(f64, Truth)> = Vec::with_capacity(pieces.len());
        for (end, t) in pieces {
            match out.last_mut() {
                Some(last) if last.1 == t => last.0 = end,
                _ => out.push((end, t)),
            }
        }
        if let Some(last) = out.last_mut() {
            last.0 = 1.0;
        }
        Partition { pieces: out }
    }

    fn zip(&self, other: &Partition, f: impl Fn(Truth, Truth) -> Truth) -> Partition {
        let (mut i, mut j) = (0, 0);
        let mut out = Vec::with_capacity(self.pieces.len() + other.pieces.len());
        while i < self.pieces.len() && j < other.pieces.len() {
            let (ea, ta) = self.pieces[i];
            let (eb, tb) = other.pieces[j];
            let end = ea.min(eb);
            out.push((end, f(ta, tb)));
            if ea <= end {
                i += 1;
            }
            if eb <= end {
                j += 1;
            }
        }
        Partition::normalised(out)
    }

    /// Pointwise conjunction.
    pub fn and(&self, other: &Partition) -> Partition {
        self.zip(other, Truth::and)
    }

    /// Pointwise disjunction.
    pub fn or(&self, other: &Partition) -> Partition {
        self.zip(other, Truth::or)
    }

    /// `self` outside [a, b]; inside, `inner`, a partition of [c, d] ⊇ [a, b] rescaled to [0, 1]
    /// (a local recomputation).
    pub fn splice(&self, (a, b): (f64, f64), inner: &Partition, (c, d): (f64, f64)) -> Partition {
        let mut out: Vec<(f64, Truth)> = Vec::with_capacity(self.pieces.len() + inner.pieces.len());
        let mut push = |end: f64, t: Truth| {
            if end > out.last().map_or(0.0, |&(last, _)| last) {
                out.push((end, t));
            }
        };
        for &(end, t) in &self.pieces {
            push(end.min(a), t);
            if end >= a {
                break;
            }
        }
        for &(end, t) in &inner.pieces {
            let x = c + end * (d - c);
            if x > a {
                push(x.min(b), t);
            }
            if x >= b {
                break;
            }
        }
        for &(end, t) in &self.pieces {
            if end > b {
                push(end, t);
            }
        }
        Partition::normalised(out)
    }

    /// Pointwise negation (Unknown stays Unknown).
    pub fn not(&self) -> Partition {
        let flip = |t: Truth| match t {
            Truth::True => Truth::False,
            Truth::False => Truth::True,
            Truth::Unknown => Truth::Unknown,
        };
        Partition { pieces: self.pieces.iter().map(|&(end, t)| (end, flip(t))).collect() }
    }

    /// True where the truth is not `t`, false where it is: the pieces a later step still has to
    /// look at (`t` = True: those a certificate has not decided).
    pub fn is_not(&self, t: Truth) -> Partition {
        Partition::normalised(self.pieces.iter().map(|&(end, u)| (end, if u == t { Truth::False } else { Truth::True })).collect())
    }

    /// False on the ordered, disjoint intervals `inside`, true elsewhere.
    pub fn outside(inside: &[(f64, f64)]) -> Partition {
        let mut pieces = Vec::with_capacity(2 * inside.len() + 1);
        for &(a, b) in inside.iter().filter(|(a, b)| b > a) {
            if a > 0.0 {
                pieces.push((a, Truth::True));
            }
            pieces.push((b.min(1.0), Truth::False));
        }
        if pieces.last().is_none_or(|p| p.0 < 1.0) {
            pieces.push((1.0, Truth::True));
        }
        Partition::normalised(pieces)
    }

    /// The intervals (ordered, disjoint, closed) where the truth is `t`.
    pub fn where_is(&self, t: Truth) -> Vec<(f64, f64)> {
        self.intervals().into_iter().filter(|p| p.2 == t).map(|(a, b, _)| (a, b)).collect()
    }

    /// Whether the truth is `t` on all of [0, 1].
    pub fn is_all(&self, t: Truth) -> bool {
        self.pieces.len() == 1 && self.pieces[0].1 == t
    }

    /// The pieces as `(start, end, truth)`.
    pub fn intervals(&self) -> Vec<(f64, f64, Truth)> {
        let mut start = 0.0;
        self.pieces
            .iter()
            .map(|&(end, t)| {
                let iv = (start, end, t);
                start = end;
                iv
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outside_and_is_not() {
        let p = Partition::outside(&[(0.0, 0.2), (0.5, 0.7)]);
        assert_eq!(p.pieces, vec![(0.2, Truth::False), (0.5, Truth::True), (0.7, Truth::False), (1.0, Truth::True)]);
        assert_eq!(Partition::outside(&[(0.3, 1.0)]).pieces, vec![(0.3, Truth::True), (1.0, Truth::False)]);
        assert!(Partition::outside(&[]).is_all(Truth::True));
        let q = Partition::from_pieces(vec![(0.4, Truth::True), (0.6, Truth::Unknown), (1.0, Truth::False)]);
        assert_eq!(q.is_not(Truth::True).pieces, vec![(0.4, Truth::False), (1.0, Truth::True)]);
        assert_eq!(q.is_not(Truth::False).pieces, vec![(0.6, Truth::True), (1.0, Truth::False)]);
    }

    #[test]
    fn and_or_merge_pieces() {
        let a = Partition { pieces: vec![(0.3, Truth::True), (0.6, Truth::False), (1.0, Truth::Unknown)] };
        let b = Partition { pieces: vec![(0.5, Truth::True), (1.0, Truth::False)] };
        assert_eq!(a.and(&b).pieces, vec![(0.3, Truth::True), (1.0, Truth::False)]);
        assert_eq!(a.or(&b).pieces, vec![(0.5, Truth::True), (0.6, Truth::False), (1.0, Truth::Unknown)]);
    }
}
