//! Cheap certified pruning before any polynomial is built.
//!
//! On each of n sub-intervals of λ (n = 1, then 4, then 16, each finer level built only when the
//! coarser one cannot decide), a cable's moving end stays in the convex hull of the
//! rational Bézier control points of that piece (when all weights are positive), hence in a ball
//! (centre c, radius ρ). Every point a + u·(x − a) of the cable then lies within u·ρ ≤ ρ of the
//! fixed segment a → c. So if the distance from that segment to another cable's segment, or to a
//! ball or capsule around an obstacle, exceeds the clearance plus the radii on every piece, the
//! condition cannot be violated anywhere and is decided without polynomials.

use crate::poly::Bern;
use crate::query::{point_segment_dist2, segment_segment_dist};
use nalgebra::Vector3;
use std::cell::OnceCell;

type V = Vector3<f64>;

/// Centre and radius.
type Ball = (V, f64);

/// Numbers of sub-intervals of the successive levels.
pub const LEVELS: [usize; 3] = [1, 4, 16];

/// A simple solid around an obstacle (or part of one), already grown by the clearance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bound {
    /// A ball.
    Ball(V, f64),
    /// A capsule around the segment from the first to the second point.
    Capsule(V, V, f64),
}

/// A ball holding the points: their centroid and the largest distance to it.
fn ball(points: &[V]) -> (V, f64) {
    let centre = points.iter().sum::<V>() / (points.len().max(1) as f64);
    (centre, points.iter().map(|p| (p - centre).norm()).fold(0.0, f64::max))
}

impl Bound {
    /// The ball around points, grown by `grow`.
    pub fn ball_around(points: &[V], grow: f64) -> Bound {
        let (centre, r) = ball(points);
        Bound::Ball(centre, r + grow)
    }

    /// A lower bound on the distance from the segment a → a + s to the bound's solid (negative
    /// inside).
    fn distance_from(&self, a: &V, s: &V) -> f64 {
        match self {
            Bound::Ball(c, r) => point_segment_dist2(c, a, s, None).sqrt() - r,
            Bound::Capsule(p, q, r) => segment_segment_dist(a, s, p, &(q - p)) - r,
        }
    }
}

/// The balls holding a cable's moving end on each piece, level by level, built on demand.
#[derive(Debug, Clone)]
pub struct Tube {
    /// The fixed end (base anchor).
    pub base: V,
    tip: [Bern; 3],
    w: Bern,
    levels: [OnceCell<Option<Vec<Ball>>>; 3],
}

/// Slack covering the rounding of the distance computations.
fn slack(scale: f64) -> f64 {
    1e-9 * (1.0 + scale)
}

/// `p` cut into `n` equal pieces, each re-parametrised to [0, 1].
fn cut(p: &Bern, n: usize) -> Vec<Bern> {
    let mut out = Vec::with_capacity(n);
    let mut rest = p.clone();
    for j in 0..n - 1 {
        let (left, right) = rest.split(1.0 / (n - j) as f64);
        out.push(left);
        rest = right;
    }
    out.push(rest);
    out
}

/// Centre and radius of a ball holding X̂/w over [0, 1], or `None` when a weight is not
/// certainly positive.
fn hull_ball(x: [&Bern; 3], w: &Bern) -> Option<(V, f64)> {
    let w_min = w.c.iter().copied().fold(f64::INFINITY, f64::min);
    if !(w_min > 2.0 * w.err) {
        return None;
    }
    let pts: Vec<V> = (0..w.c.len()).map(|j| V::new(x[0].c[j], x[1].c[j], x[2].c[j]) / w.c[j]).collect();
    let (centre, r) = ball(&pts);
    let mag = pts.iter().map(|p| p.abs().max()).fold(0.0, f64::max);
    let err = (x.iter().map(|p| p.err).fold(0.0, f64::max) + mag * w.err) / (w_min - w.err);
    Some((centre, r + err + slack(mag)))
}

impl Tube {
    /// The tube of the cable from `base` to X̂/w.
    pub fn new(base: V, tip: &[Bern; 3], w: &Bern) -> Tube {
        let n = tip.iter().map(Bern::degree).max().unwrap_or(0).max(w.degree());
        Tube { base, tip: tip.clone().map(|p| p.elevate(n)), w: w.elevate(n), levels: Default::default() }
    }

    fn level(&self, l: usize) -> Option<&Vec<Ball>> {
        self.levels[l]
            .get_or_init(|| {
                let n = LEVELS[l];
                let (xs, ws) = (self.tip.clone().map(|p| cut(&p, n)), cut(&self.w, n));
                (0..n).map(|k| hull_ball([&xs[0][k], &xs[1][k], &xs[2][k]], &ws[k])).collect()
            })
            .as_ref()
    }

    /// Whether the cable stays farther than `gap` from the other cable on every piece.
    pub fn clear_of_tube(&self, other: &Tube, gap: f64) -> bool {
        (0..LEVELS.len()).any(|l| match (self.level(l), other.level(l)) {
            (Some(a), Some(b)) => a.iter().zip(b).all(|((c, r), (d, q))| {
                let dist = segment_segment_dist(&self.base, &(c - self.base), &other.base, &(d - other.base));
                dist - r - q > gap + slack(c.abs().max() + d.abs().max())
            }),
            _ => false,
        })
    }

    /// Whether the cable stays outside `bound` (already grown by the clearance) on every piece.
    pub fn clear_of(&self, bound: &Bound) -> bool {
        (0..LEVELS.len()).any(|l| {
            self.level(l).is_some_and(|pieces| pieces.iter().all(|(c, r)| bound.distance_from(&self.base, &(c - self.base)) - r > slack(c.abs().max())))
        })
    }
}
