//! Cheap certified pruning before any polynomial is built.
//!
//! On each dyadic piece of λ ([0, 1], then its halves, … down to width 2^−DEPTH, each piece halved
//! only where the coarser one cannot decide), a cable's moving end stays in the convex hull of the
//! rational Bézier control points of that piece (when all weights are positive), hence in a ball
//! (centre c, radius ρ). Every point a + u·(x − a) of the cable then lies within u·ρ ≤ ρ of the
//! fixed segment a → c. A segment of a routed cable whose start moves too (anchored on a link)
//! has a ball (c₀, ρ₀) for its start as well: its points lie within max(ρ₀, ρ) of c₀ → c. So if the distance from that segment to another cable's segment, or to a
//! ball or capsule around an obstacle, exceeds the clearance plus the radii on every piece, the
//! condition cannot be violated anywhere and is decided without polynomials.

use super::primitives::EndCases;
use super::subtract;
use crate::poly::{halve, Bern};
use crate::query::{point_segment_dist2, segment_segment_dist};
use nalgebra::Vector3;
use std::cell::RefCell;

type V = Vector3<f64>;

/// Centre and radius.
type Ball = (V, f64);

/// A cable's segment on one piece: the balls holding its start and its end.
type Ends = (Ball, Ball);

/// For the balls of a tube and of another (if any) on one piece: how far the fixed segments
/// through their centres stay beyond the gap, and the radii that margin must exceed.
type Margin<'a> = dyn Fn(&Ends, Option<&Ends>) -> (f64, f64) + 'a;


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

/// Deepest level of the dyadic refinement: pieces of width 2^−DEPTH in λ.
pub const DEPTH: usize = 6;



/// The balls holding a cable's moving end (and its start, when that moves too) on dyadic pieces
/// of λ (level l: 2^l pieces of width 2^−l), built on demand and kept: every condition of the
/// cable refines the same pieces, so the work is shared between them.
#[derive(Debug, Clone)]
pub struct Tube {
    /// The start when it is fixed (a base anchor).
    base: Option<V>,
    /// The start's balls when it moves.
    start: Option<RefCell<Pieces>>,
    pieces: RefCell<Pieces>,
}

/// The dyadic pieces built so far, in heap order (node 1 is [0, 1], node k has the halves 2k and
/// 2k + 1), in one flat store: per node, the Bernstein coefficients of X̂₀, X̂₁, X̂₂ and w restricted
/// to the piece (kept to make its halves), their error bounds, and its ball (`None` where a weight
/// is not certainly positive).
#[derive(Debug, Clone)]
struct Pieces {
    /// Coefficients per polynomial (common degree + 1).
    len: usize,
    /// Where node k's entries start in `coeffs` / `errs` and `balls` (`u32::MAX`: not built).
    slot: Vec<u32>,
    coeffs: Vec<f64>,
    errs: Vec<[f64; 4]>,
    balls: Vec<Option<Ball>>,
}

/// Slack covering the rounding of the distance computations.
fn slack(scale: f64) -> f64 {
    1e-9 * (1.0 + scale)
}

/// The points' largest coordinates in magnitude, summed: the scale of their rounding.
fn scale(points: &[&V]) -> f64 {
    points.iter().map(|p| p.abs().max()).sum()
}

/// Nodes a tube's store makes room for at first: the root and the two levels below it (a
/// cable–cable pair of CoGiRo's general_1 needs at most two).
const EXPECTED_NODES: usize = 7;

/// Centre and radius of a ball holding X̂/w over the piece whose coefficients are `c` (X̂₀, X̂₁,
/// X̂₂, w, each `len` long) with error bounds `err`, or `None` when a weight is not certainly
/// positive. The control points X̂_j/w_j are in the ball; so is the curve (convex hull).
fn hull_ball(c: &[f64], err: &[f64; 4], len: usize) -> Option<Ball> {
    let (x, w) = (&c[..3 * len], &c[3 * len..4 * len]);
    let w_min = w.iter().copied().fold(f64::INFINITY, f64::min);
    if !(w_min > 2.0 * err[3]) {
        return None;
    }
    // the control points X̂_j / w_j, through the reciprocals (the rounding is far inside `slack`)
    let mut inv = [0.0; 16];
    for (i, wj) in inv.iter_mut().zip(w) {
        *i = 1.0 / wj;
    }
    let point = |j: usize| {
        let i = if j < inv.len() { inv[j] } else { 1.0 / w[j] };
        V::new(x[j] * i, x[len + j] * i, x[2 * len + j] * i)
    };
    let centre = (0..len).map(point).sum::<V>() / len as f64;
    let (mut r2, mut mag) = (0.0f64, 0.0f64);
    for j in 0..len {
        let p = point(j);
        r2 = r2.max((p - centre).norm_squared());
        mag = mag.max(p.abs().max());
    }
    let e = (err[0].max(err[1]).max(err[2]) + mag * err[3]) / (w_min - err[3]);
    Some((centre, r2.sqrt() + e + slack(mag)))
}

/// The λ-interval of dyadic node `k` (heap order).
fn node_interval(k: usize) -> (f64, f64) {
    let level = usize::BITS - 1 - k.leading_zeros();
    let width = 1.0 / (1u64 << level) as f64;
    let start = (k - (1usize << level)) as f64 * width;
    (start, start + width)
}

/// Appends [a, b] to ordered intervals, merging it with the last one when they touch.
fn push_interval(out: &mut Vec<(f64, f64)>, (a, b): (f64, f64)) {
    match out.last_mut() {
        Some(last) if last.1 >= a => last.1 = b,
        _ => out.push((a, b)),
    }
}

impl Pieces {
    /// The root piece of the point X̂/w.
    fn new(tip: &[Bern; 3], w: &Bern) -> Pieces {
        let n = tip.iter().map(Bern::degree).max().unwrap_or(0).max(w.degree());
        let nodes = 2 << DEPTH;
        // room for the root and two levels below it, what most pieces need; more as they come
        let mut coeffs = Vec::with_capacity(EXPECTED_NODES * 4 * (n + 1));
        coeffs.resize(4 * (n + 1), 0.0);
        let mut errs = [0.0; 4];
        for ((p, out), e) in [&tip[0], &tip[1], &tip[2], w].into_iter().zip(coeffs.chunks_exact_mut(n + 1)).zip(&mut errs) {
            *e = p.elevate_to(out);
        }
        let ball = hull_ball(&coeffs, &errs, n + 1);
        let mut slot = vec![u32::MAX; nodes];
        slot[1] = 0;
        let (mut all_errs, mut balls) = (Vec::with_capacity(EXPECTED_NODES), Vec::with_capacity(EXPECTED_NODES));
        all_errs.push(errs);
        balls.push(ball);
        Pieces { len: n + 1, slot, coeffs, errs: all_errs, balls }
    }

    /// The ball of dyadic node `k`, building it, its sibling and their missing ancestors.
    fn ball_of(cell: &RefCell<Pieces>, k: usize) -> Option<Ball> {
        let slot = cell.borrow().slot[k];
        if slot != u32::MAX {
            return cell.borrow().balls[slot as usize];
        }
        Pieces::ball_of(cell, k / 2);
        let mut pieces = cell.borrow_mut();
        pieces.build_pair(k);
        let slot = pieces.slot[k] as usize;
        pieces.balls[slot]
    }

    /// Builds node k and its sibling from their parent, which must exist.
    fn build_pair(&mut self, k: usize) {
        let len = self.len;
        let parent = self.slot[k / 2] as usize;
        // the halves are appended to the store: the left one at `at`, the right one after it
        let at = self.coeffs.len();
        self.coeffs.resize(at + 8 * len, 0.0);
        let (old, new) = self.coeffs.split_at_mut(at);
        let (left, right) = new.split_at_mut(4 * len);
        let mut errs = [0.0; 4];
        for i in 0..4 {
            let src = &old[(parent * 4 + i) * len..(parent * 4 + i + 1) * len];
            errs[i] = self.errs[parent][i] + halve(src, &mut left[i * len..(i + 1) * len], &mut right[i * len..(i + 1) * len]);
        }
        let k0 = k & !1;
        for (j, start) in [(k0, at), (k0 + 1, at + 4 * len)] {
            self.slot[j] = self.balls.len() as u32;
            self.errs.push(errs);
            self.balls.push(hull_ball(&self.coeffs[start..start + 4 * len], &errs, len));
        }
    }
}

impl Tube {
    /// The tube of the cable from `base` to X̂/w.
    pub fn new(base: V, tip: &[Bern; 3], w: &Bern) -> Tube {
        Tube { base: Some(base), start: None, pieces: RefCell::new(Pieces::new(tip, w)) }
    }

    /// The tube of a segment whose start Ŝ/w moves too (anchored on a link) and whose end is X̂/w.
    pub fn moving(start: &[Bern; 3], tip: &[Bern; 3], w: &Bern) -> Tube {
        Tube { base: None, start: Some(RefCell::new(Pieces::new(start, w))), pieces: RefCell::new(Pieces::new(tip, w)) }
    }

    /// The balls of the start and the end on dyadic node `k` (`None` where a weight is not
    /// certainly positive).
    fn ends_of(&self, k: usize) -> Option<Ends> {
        let end = Pieces::ball_of(&self.pieces, k)?;
        let start = match (&self.start, self.base) {
            (Some(cell), _) => Pieces::ball_of(cell, k)?,
            (None, Some(base)) => (base, 0.0),
            (None, None) => return None,
        };
        Some((start, end))
    }

    /// The λ-intervals (ordered, disjoint, unions of dyadic pieces down to width 2^−DEPTH) where
    /// the pruning cannot decide; a piece inside one of the ordered, disjoint intervals `spare`
    /// (where the answer is not needed) is left undecided without a test. `margin` gives, for the
    /// balls of this tube and of `other` (if given) on one piece, how far the fixed segments
    /// through the balls' centres stay beyond the gap, and the sum of the radii: the piece is
    /// decided when the margin exceeds the radii; from level `first_judged` on it is halved
    /// (smaller balls) only while the margin could still beat the radii at the finest level,
    /// since where the centres' segments themselves come within the gap no refinement can decide.
    fn undecided(&self, other: Option<&Tube>, spare: &[(f64, f64)], first_judged: usize, margin: &Margin) -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        let mut stack = vec![1usize];
        while let Some(k) = stack.pop() {
            let (a, b) = node_interval(k);
            if spare.iter().any(|&(c, d)| c <= a && b <= d) {
                push_interval(&mut out, (a, b));
                continue;
            }
            let mine = self.ends_of(k);
            let theirs = other.map(|t| t.ends_of(k));
            let (m, radii) = match (mine, theirs) {
                (Some(b), None) => margin(&b, None),
                (Some(b), Some(Some(c))) => margin(&b, Some(&c)),
                _ => (f64::INFINITY, f64::INFINITY), // a weight not certainly positive: halve
            };
            if m > radii {
                continue;
            }
            let level = (usize::BITS - 1 - k.leading_zeros()) as usize;
            let levels_left = DEPTH - level;
            // a piece partly spared is halved regardless: its ball says little about the rest
            let partly_spared = spare.iter().any(|&(c, d)| c < b && a < d);
            if levels_left == 0 || (level >= first_judged && !partly_spared && !(m > radii / (1u64 << levels_left) as f64)) {
                push_interval(&mut out, (a, b));
            } else {
                stack.push(2 * k + 1);
                stack.push(2 * k);
            }
        }
        out
    }

    /// Where the cable may come within `gap` of the other cable: the λ-intervals the balls could
    /// not clear (empty when the two stay farther apart throughout), or that lie inside `spare`.
    pub fn undecided_near(&self, other: &Tube, gap: f64, spare: &[(f64, f64)]) -> Vec<(f64, f64)> {
        self.undecided(Some(other), spare, 0, &|((a, ra), (c, r)), theirs| {
            let ((b, rb), (d, q)) = theirs.expect("balls of the other tube");
            let dist = segment_segment_dist(a, &(c - a), b, &(d - b));
            (dist - gap - slack(scale(&[a, c, b, d])), ra.max(*r) + rb.max(*q))
        })
    }

    /// Which endpoint cases of the distance between this cable and `other` (in the order of
    /// [`EndCases`], this cable first) may come within `gap` outside `spare`: each case is a
    /// point (a start, or a moving end in its ball) against the other cable's segment, so its
    /// pruning clears it wherever that point stays away, even where the segments come close.
    pub fn ends_near(&self, other: &Tube, gap: f64, spare: &[(f64, f64)]) -> EndCases {
        // the distance from point p to the segment a → c
        let dist = |p: &V, a: &V, c: &V| point_segment_dist2(p, a, &(c - a), None).sqrt();
        let case = |margin: &dyn Fn(&Ends, &Ends) -> (f64, f64)| {
            let undecided = self.undecided(Some(other), spare, 0, &|mine, theirs| {
                let theirs = theirs.expect("balls of the other tube");
                let (m, radii) = margin(mine, theirs);
                (m - gap - slack(scale(&[&mine.0 .0, &mine.1 .0, &theirs.0 .0, &theirs.1 .0])), radii)
            });
            !subtract(&undecided, spare).0.is_empty()
        };
        [
            case(&|((a, ra), (c, r)), ((b, rb), _)| (dist(b, a, c), rb + ra.max(*r))),
            case(&|((a, ra), _), ((b, rb), (d, q))| (dist(a, b, d), ra + rb.max(*q))),
            case(&|((a, ra), (c, r)), (_, (d, q))| (dist(d, a, c), q + ra.max(*r))),
            case(&|(_, (c, r)), ((b, rb), (d, q))| (dist(c, b, d), r + rb.max(*q))),
        ]
    }

    /// Where the cable may enter `bound` (already grown by the clearance): the λ-intervals the
    /// balls could not clear, or that lie inside `spare`. [0, 1] is always halved once: the whole
    /// motion's ball is centred on an average of very different positions, so its centre's
    /// segment meeting the obstacle says nothing about the cable's (on cdpr7-tree "quadratic"
    /// this spares the trunk's two-variable search past the crown: 145 → 110 µs). Cable pairs
    /// keep judging from the whole motion on: halving there changes where their exact work runs,
    /// and a grazing pair's uncertain section in tests/slerp.rs then grows past 10⁻⁷.
    pub fn undecided_in(&self, bound: &Bound, spare: &[(f64, f64)]) -> Vec<(f64, f64)> {
        self.undecided(None, spare, 1, &|((a, ra), (c, r)), _| (bound.distance_from(a, &(c - a)) - slack(scale(&[a, c])), ra.max(*r)))
    }

    /// Where the cable's length may leave [lo, hi]: the λ-intervals the balls could not keep
    /// inside (the length lies within the balls' radii of the distance between their centres),
    /// or that lie inside `spare`. A bound ≤ 0 below or infinite above never binds.
    pub fn undecided_length(&self, lo: f64, hi: f64, spare: &[(f64, f64)]) -> Vec<(f64, f64)> {
        self.undecided(None, spare, 1, &|((a, ra), (c, r)), _| {
            let dist = (c - a).norm();
            let below = if lo > 0.0 { dist - lo } else { f64::INFINITY };
            (below.min(hi - dist) - slack(scale(&[a, c])), ra + r)
        })
    }

    /// Whether the cable stays outside `bound` (already grown by the clearance) throughout.
    pub fn clear_of(&self, bound: &Bound) -> bool {
        self.undecided_in(bound, &[]).is_empty()
    }
}
