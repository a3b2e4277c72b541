//! Closed real intervals, the enclosures the wrench conditions bound non-polynomial quantities
//! with (a cable's inverse length, a square root) over a piece of a motion.

use crate::poly::Bern;

/// A closed interval [lo, hi] of reals (possibly infinite ends).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Iv {
    /// The lower end.
    pub(crate) lo: f64,
    /// The upper end.
    pub(crate) hi: f64,
}

impl Iv {
    /// The range of a Bernstein polynomial over its whole domain, rounding error included.
    pub(crate) fn of(p: &Bern) -> Iv {
        let (lo, hi) = p.c.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &c| (l.min(c), h.max(c)));
        Iv { lo: lo - p.err, hi: hi + p.err }
    }

    /// The sum.
    pub(crate) fn add(self, o: Iv) -> Iv {
        Iv { lo: self.lo + o.lo, hi: self.hi + o.hi }
    }

    /// The product (everything, when an end is an undefined 0·∞).
    pub(crate) fn mul(self, o: Iv) -> Iv {
        let p = [self.lo * o.lo, self.lo * o.hi, self.hi * o.lo, self.hi * o.hi];
        if p.iter().any(|x| x.is_nan()) {
            return Iv { lo: f64::NEG_INFINITY, hi: f64::INFINITY };
        }
        Iv { lo: p.iter().copied().fold(f64::INFINITY, f64::min), hi: p.iter().copied().fold(f64::NEG_INFINITY, f64::max) }
    }

    /// c·x for a constant c (possibly infinite).
    pub(crate) fn scale(self, c: f64) -> Iv {
        self.mul(Iv { lo: c, hi: c })
    }

    /// Pointwise min and max of c·x and e·x over the interval of x.
    pub(crate) fn min_max_of_scaled(self, c: f64, e: f64) -> (Iv, Iv) {
        let (a, b) = (self.scale(c), self.scale(e));
        (Iv { lo: a.lo.min(b.lo), hi: a.hi.min(b.hi) }, Iv { lo: a.lo.max(b.lo), hi: a.hi.max(b.hi) })
    }

    /// The largest |x|.
    pub(crate) fn mag(self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }
}
