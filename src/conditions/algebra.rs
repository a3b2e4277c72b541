//! Polynomial algebra over a motion's common denominator w.
//!
//! An [`H`] is a rational function p/w^k. Along a [`Motion`](crate::model::Motion) every point and
//! vector is such a fraction, and since w > 0 the sign of p/w^k is the sign of p: conditions can be
//! written naturally (e.g. e·s > 0) and compared with zero by their numerators. Sums bring both
//! terms to the larger power of w first.

use crate::axes::per_axis;
use crate::poly::Bern;
use nalgebra::Vector3;

/// The fraction p / w^k.
#[derive(Debug, Clone)]
pub struct H {
    /// Numerator.
    pub p: Bern,
    /// Power of the denominator w.
    pub k: usize,
}

/// A 3-vector of fractions with one power of w.
pub type HVec = [H; 3];

/// The powers of w of one motion, and the operations that need them.
#[derive(Debug, Clone)]
pub struct Alg {
    wpow: Vec<Bern>,
}

impl H {
    /// A constant.
    pub fn constant(c: f64) -> H {
        H { p: Bern::constant(c), k: 0 }
    }

    /// Product (powers add).
    pub fn mul(&self, o: &H) -> H {
        H { p: self.p.mul(&o.p), k: self.k + o.k }
    }

    /// Product with a constant.
    pub fn scale(&self, c: f64) -> H {
        H { p: self.p.scale(c), k: self.k }
    }
}

/// A constant vector as fractions.
pub fn hvec_const(v: &Vector3<f64>) -> HVec {
    [H::constant(v.x), H::constant(v.y), H::constant(v.z)]
}

impl Alg {
    /// The algebra of a motion with denominator `w`.
    pub fn new(w: &Bern) -> Alg {
        Alg { wpow: vec![Bern::constant(1.0), w.clone()] }
    }

    fn power(&mut self, k: usize) -> &Bern {
        while self.wpow.len() <= k {
            let next = self.wpow[self.wpow.len() - 1].mul(&self.wpow[1]);
            self.wpow.push(next);
        }
        &self.wpow[k]
    }

    fn combine(&mut self, a: &H, b: &H, sign: f64) -> H {
        let k = a.k.max(b.k);
        let op = |x: &Bern, y: &Bern| if sign > 0.0 { x.add(y) } else { x.sub(y) };
        // only the operand with fewer powers of w is lifted (multiplied by the missing ones)
        let p = if a.k == b.k {
            op(&a.p, &b.p)
        } else if a.k < k {
            op(&a.p.mul(self.power(k - a.k)), &b.p)
        } else {
            op(&a.p, &b.p.mul(self.power(k - b.k)))
        };
        H { p, k }
    }

    /// a + b.
    pub fn add(&mut self, a: &H, b: &H) -> H {
        self.combine(a, b, 1.0)
    }

    /// a − b.
    pub fn sub(&mut self, a: &H, b: &H) -> H {
        self.combine(a, b, -1.0)
    }

    /// Σ of products of pairs.
    pub fn sum_of_products(&mut self, terms: &[(&H, &H)]) -> H {
        let mut acc: Option<H> = None;
        for (a, b) in terms {
            let t = a.mul(b);
            acc = Some(match acc {
                None => t,
                Some(s) => self.add(&s, &t),
            });
        }
        acc.unwrap_or_else(|| H::constant(0.0))
    }

    /// a · b.
    pub fn dot(&mut self, a: &HVec, b: &HVec) -> H {
        self.sum_of_products(&[(&a[0], &b[0]), (&a[1], &b[1]), (&a[2], &b[2])])
    }

    /// aᵀ G b for a symmetric matrix G.
    pub fn dot_metric(&mut self, a: &HVec, g: &nalgebra::Matrix3<f64>, b: &HVec) -> H {
        let gb: HVec = per_axis(|i| {
            let mut acc = b[0].scale(g[(i, 0)]);
            for j in 1..3 {
                acc = self.add(&acc, &b[j].scale(g[(i, j)]));
            }
            acc
        });
        self.dot(a, &gb)
    }

    /// a × b.
    pub fn cross(&mut self, a: &HVec, b: &HVec) -> HVec {
        [
            self.diff_of_products(&a[1], &b[2], &a[2], &b[1]),
            self.diff_of_products(&a[2], &b[0], &a[0], &b[2]),
            self.diff_of_products(&a[0], &b[1], &a[1], &b[0]),
        ]
    }

    fn diff_of_products(&mut self, a: &H, b: &H, c: &H, d: &H) -> H {
        let (x, y) = (a.mul(b), c.mul(d));
        self.sub(&x, &y)
    }

    /// a − b, componentwise.
    pub fn vsub(&mut self, a: &HVec, b: &HVec) -> HVec {
        [self.sub(&a[0], &b[0]), self.sub(&a[1], &b[1]), self.sub(&a[2], &b[2])]
    }

    /// a + b, componentwise.
    pub fn vadd(&mut self, a: &HVec, b: &HVec) -> HVec {
        [self.add(&a[0], &b[0]), self.add(&a[1], &b[1]), self.add(&a[2], &b[2])]
    }
}
