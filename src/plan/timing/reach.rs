//! The fastest law along a grid of cells by reachability (Pham & Pham's TOPP-RA, in the
//! first-order form that checks each cell's limits at both its ends): the state on cell i is
//! x = λ̇² at its start and the control u = λ̈, constant on the cell, so x at its end is
//! x + 2Δu. A backward pass finds, for each cell, the interval of start states from which the
//! rest of the path can still be followed to a stop (the controllable sets); a forward pass then
//! takes the greatest acceleration that stays inside them. Knows nothing of robots: each cell
//! comes as half-planes in (u, x).

use super::limits::HalfPlane;

/// One step of the passes: cell i's half-planes in (u, x_start) (its limits at the start, and
/// at the end with x_end = x + 2Δu substituted), its width Δ in λ, the factor from its end's x
/// to the next cell's start, and whether the platform stops at its end.
#[derive(Debug, Clone)]
pub struct Step {
    /// The half-planes.
    pub planes: Vec<HalfPlane>,
    /// Δ.
    pub delta: f64,
    /// The next cell's x per unit of this one's end x.
    pub factor: f64,
    /// x = 0 at its end.
    pub stop: bool,
    /// Caps on x at its start and end (the certification's slow-downs; infinite: none).
    pub caps: (f64, f64),
}

/// A convex polygon in (u, x), counter-clockwise, with the buffer its clipping writes into (the
/// passes clip thousands of times: no allocation per clip).
#[derive(Debug, Clone, Default)]
struct Polygon {
    points: Vec<[f64; 2]>,
    scratch: Vec<[f64; 2]>,
}

impl Polygon {
    /// Becomes the rectangle [−u, u] × [0, x].
    fn set_rect(&mut self, u: f64, x: f64) {
        self.points.clear();
        self.points.extend([[-u, 0.0], [u, 0.0], [u, x], [-u, x]]);
    }

    /// Keeps the part with a·u + b·x ≤ c (Sutherland–Hodgman against one half-plane).
    fn clip(&mut self, a: f64, b: f64, c: f64) {
        let value = |p: &[f64; 2]| a * p[0] + b * p[1] - c;
        let n = self.points.len();
        self.scratch.clear();
        for k in 0..n {
            let (p, q) = (self.points[k], self.points[(k + 1) % n]);
            let (vp, vq) = (value(&p), value(&q));
            if vp <= 0.0 {
                self.scratch.push(p);
            }
            if (vp < 0.0 && vq > 0.0) || (vp > 0.0 && vq < 0.0) {
                let s = vp / (vp - vq);
                self.scratch.push([p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])]);
            }
        }
        std::mem::swap(&mut self.points, &mut self.scratch);
    }

    fn clip_all(&mut self, planes: &[HalfPlane]) {
        for h in planes {
            if self.points.is_empty() {
                return;
            }
            self.clip(h.a, h.b, h.c);
        }
    }

    /// The least and greatest x.
    fn x_range(&self) -> Option<(f64, f64)> {
        let xs = self.points.iter().map(|p| p[1]);
        (!self.points.is_empty()).then(|| (xs.clone().fold(f64::INFINITY, f64::min), xs.fold(f64::NEG_INFINITY, f64::max)))
    }

    fn extent(&self) -> f64 {
        self.points.iter().map(|p| p[0].abs().max(p[1].abs())).fold(0.0, f64::max)
    }
}

/// Beyond this a state or control counts as unbounded: nothing limits the speed there.
pub const UNBOUNDED: f64 = 1e12;

/// The start states of a cell from which its end state can be kept within the controllable set
/// of the next: their least and greatest x, and the "peak": the greatest x among those from which
/// the end state goes furthest.
#[derive(Debug, Clone, Copy)]
struct Range {
    lo: f64,
    hi: f64,
    /// Past it a faster start only leaves a slower end: where the path nearly stands still, a
    /// large λ̇² means little speed, and the start's limits, which hold λ̈ for the whole cell,
    /// then take more braking than the extra start speed gives.
    peak: f64,
}

/// The [`Range`] of `step` for an end state in [lo, hi] and x ≤ `cap`: its half-planes and that
/// strip, clipped inside a box just around the set, so that the vertices carry no rounding from a
/// huge one — a box the speed limits give where they bound x, else one found by clipping first
/// inside a huge box to learn the set's extent (`polygons`: the two, reused). `Err(())` when
/// unbounded.
fn start_range(step: &Step, lo: f64, hi: f64, cap: f64, polygons: (&mut Polygon, &mut Polygon)) -> Result<Option<Range>, ()> {
    if lo == hi {
        // a stop (or an end state pinned to one value): u = (lo − x)/(2Δ), each half-plane a
        // bound on x alone — a strip of width zero would leave the clipping only rounding
        let (mut x_lo, mut x_hi) = (0.0f64, cap);
        for h in &step.planes {
            let (k, r) = (h.b - h.a / (2.0 * step.delta), h.c - h.a * lo / (2.0 * step.delta));
            if k > 0.0 {
                x_hi = x_hi.min(r / k);
            } else if k < 0.0 {
                x_lo = x_lo.max(r / k);
            } else if r < 0.0 {
                return Ok(None);
            }
        }
        if x_hi >= 0.5 * UNBOUNDED {
            return Err(());
        }
        return Ok((x_lo <= x_hi).then_some(Range { lo: x_lo, hi: x_hi, peak: x_hi }));
    }
    let clip = |p: &mut Polygon, (half_u, half_x): (f64, f64)| {
        p.set_rect(half_u, half_x);
        p.clip(2.0 * step.delta, 1.0, hi);
        p.clip(-2.0 * step.delta, -1.0, -lo);
        p.clip(0.0, 1.0, cap);
        p.clip_all(&step.planes);
    };
    let (first, tight) = polygons;
    // a box around the set when the speed limits bound x (x ≤ x_max gives |u| ≤ (|lo| + |hi| +
    // x_max)/2Δ through the strip): one clip inside twice that box; else a first clip inside a
    // huge box finds the extent
    let x_max = step.planes.iter().filter(|h| h.a == 0.0 && h.b > 0.0).map(|h| h.c / h.b).fold(cap, f64::min);
    let u_max = (lo.abs() + hi.abs() + x_max) / (2.0 * step.delta);
    let set = if (0.0..0.5 * UNBOUNDED).contains(&x_max) && u_max < 0.5 * UNBOUNDED {
        clip(tight, (2.0 * u_max + 1e-300, 2.0 * x_max + 1e-300));
        if tight.points.is_empty() {
            return Ok(None);
        }
        &*tight
    } else {
        clip(first, (UNBOUNDED, UNBOUNDED));
        if first.points.is_empty() {
            return Ok(None);
        }
        let e = first.extent();
        if e >= 0.5 * UNBOUNDED {
            return Err(());
        }
        clip(tight, (2.0 * e + 1e-300, 2.0 * e + 1e-300));
        if tight.points.is_empty() { &*first } else { &*tight }
    };
    let e = set.extent();
    let Some((x_lo, x_hi)) = set.x_range() else { return Ok(None) };
    let end = |p: &[f64; 2]| p[1] + 2.0 * step.delta * p[0];
    let best = set.points.iter().map(end).fold(f64::NEG_INFINITY, f64::max);
    let slack = 1e-12 * (best.abs() + e);
    let peak = set.points.iter().filter(|p| end(p) >= best - slack).map(|p| p[1]).fold(x_lo, f64::max);
    Ok(Some(Range { lo: x_lo, hi: x_hi, peak }))
}

/// Why no law exists.
#[derive(Debug, Clone, PartialEq)]
pub enum Failure {
    /// No state of cell `0` can still reach the end (or no (u, x) meets its limits at all).
    Stuck(usize),
    /// Cell `0`'s states are unbounded: nothing limits the speed there.
    Unbounded(usize),
}

/// A law: x at every cell's start and end, and each cell's peak: the start speed past which a
/// faster start ends the cell slower.
#[derive(Debug, Clone, PartialEq)]
pub struct Law {
    /// (x at the start, x at the end) per cell.
    pub x: Vec<(f64, f64)>,
    /// The start speed past which the cell's end speed falls.
    pub peaks: Vec<f64>,
}

/// The greatest law within the limits: x at every cell's start and end, from rest to rest.
pub fn greedy(steps: &[Step]) -> Result<Law, Failure> {
    let n = steps.len();
    // backward: controllable start states of each cell
    let mut controllable = vec![(0.0, 0.0); n];
    let mut peaks = vec![0.0; n];
    let mut next = (0.0, 0.0); // the end: at rest
    let (mut first, mut tight) = (Polygon::default(), Polygon::default());
    for i in (0..n).rev() {
        let s = &steps[i];
        // the end state x + 2Δu within next / factor (0 at a stop) and the end cap
        let (lo, mut hi) = if s.stop { (0.0, 0.0) } else { (next.0 / s.factor, next.1 / s.factor) };
        hi = hi.min(s.caps.1);
        let Some(range) = start_range(s, lo, hi, s.caps.0, (&mut first, &mut tight)).map_err(|()| Failure::Unbounded(i))? else { return Err(Failure::Stuck(i)) };
        controllable[i] = (range.lo.max(0.0), range.hi.max(0.0));
        peaks[i] = range.peak.max(0.0);
        next = controllable[i];
    }
    if controllable[0].0 > 0.0 {
        return Err(Failure::Stuck(0));
    }
    // forward: the greatest u that keeps the end state controllable
    let mut out = Vec::with_capacity(n);
    let mut x: f64 = 0.0;
    for i in 0..n {
        let s = &steps[i];
        x = x.clamp(controllable[i].0, controllable[i].1);
        let (lo, hi) = match (s.stop, controllable.get(i + 1)) {
            (true, _) | (_, None) => (0.0, 0.0),
            (false, Some(c)) => (c.0 / s.factor, (c.1 / s.factor).min(s.caps.1)),
        };
        let mut u_hi = (hi - x) / (2.0 * s.delta);
        for h in s.planes.iter().filter(|h| h.a > 0.0) {
            u_hi = u_hi.min((h.c - h.b * x) / h.a);
        }
        // where the interval is a point rounding can leave it empty (u_hi a hair below u_lo):
        // the greatest u, which keeps the end controllable, is the one to take either way
        let end = if hi == 0.0 { 0.0 } else { (x + 2.0 * s.delta * u_hi).clamp(lo, hi) };
        out.push((x, end));
        x = end * s.factor;
    }
    Ok(Law { x: out, peaks })
}

/// The fastest law found: the greedy one, improved where it starts a cell past its peak (a
/// faster start there leaves a slower end: where the path nearly stands still, a large λ̇² means
/// little speed, and the start's limits, which hold λ̈ for the whole cell, then take more braking
/// than the extra start speed gives — the greedy law is not the fastest then). Such starts are
/// capped, round by round (at their peak, or at 0.8 of the speed when the peak is lower), while
/// the law gets shorter (`duration`).
pub fn fastest(steps: &mut [Step], duration: impl Fn(&[(f64, f64)]) -> f64) -> Result<Vec<(f64, f64)>, Failure> {
    let mut law = greedy(steps)?;
    let mut best = duration(&law.x);
    for _ in 0..IMPROVE_ROUNDS {
        let past: Vec<usize> = (0..steps.len()).filter(|&i| law.x[i].0 > law.peaks[i] * (1.0 + 1e-9) && law.peaks[i] < steps[i].caps.0).collect();
        if past.is_empty() {
            break;
        }
        let kept: Vec<(f64, f64)> = past.iter().map(|&i| steps[i].caps).collect();
        for &i in &past {
            steps[i].caps.0 = law.peaks[i].max(super::SLOW_DOWN * law.x[i].0);
        }
        let trial = greedy(steps);
        match trial {
            Ok(t) if duration(&t.x) < best => {
                best = duration(&t.x);
                law = t;
            }
            _ => {
                for (&i, &c) in past.iter().zip(&kept) {
                    steps[i].caps = c;
                }
                break;
            }
        }
    }
    Ok(law.x)
}

/// Most improvement rounds of [`fastest`].
const IMPROVE_ROUNDS: usize = 20;

#[cfg(test)]
mod tests {
    use super::super::limits::What;
    use super::*;

    fn plane(a: f64, b: f64, c: f64) -> HalfPlane {
        HalfPlane { a, b, c, what: What::Cap }
    }

    /// A point moving a unit distance with |u| ≤ 1: bang-bang, x peaks at 1 in the middle
    /// (x = 2·s on the way up), and the law meets the limits at every cell.
    #[test]
    fn bang_bang_under_an_acceleration_limit() {
        let n = 100;
        let delta = 1.0 / n as f64;
        let steps: Vec<Step> = (0..n)
            .map(|i| Step { planes: vec![plane(1.0, 0.0, 1.0), plane(-1.0, 0.0, 1.0)], delta, factor: 1.0, stop: i + 1 == n, caps: (f64::INFINITY, f64::INFINITY) })
            .collect();
        let law = greedy(&steps).unwrap().x;
        for (i, &(x0, x1)) in law.iter().enumerate() {
            let s = i as f64 * delta;
            let expect = (2.0 * s).min(2.0 * (1.0 - s));
            assert!((x0 - expect).abs() < 1e-9, "cell {i}: x = {x0}, expected {expect}");
            let u = (x1 - x0) / (2.0 * delta);
            assert!(u.abs() <= 1.0 + 1e-9, "cell {i}: u = {u}");
        }
    }

    /// A speed limit x ≤ 0.25 on top: the law cruises at it in the middle.
    #[test]
    fn cruises_at_a_speed_limit() {
        let n = 200;
        let delta = 1.0 / n as f64;
        let steps: Vec<Step> = (0..n)
            .map(|i| Step { planes: vec![plane(1.0, 0.0, 1.0), plane(-1.0, 0.0, 1.0), plane(0.0, 1.0, 0.25)], delta, factor: 1.0, stop: i + 1 == n, caps: (f64::INFINITY, f64::INFINITY) })
            .collect();
        let law = greedy(&steps).unwrap().x;
        assert!((law[n / 2].0 - 0.25).abs() < 1e-12);
        assert!(law.iter().all(|&(a, b)| a <= 0.25 + 1e-12 && b <= 0.25 + 1e-12));
    }

    #[test]
    fn an_infeasible_cell_is_named() {
        let steps: Vec<Step> = (0..10)
            .map(|i| Step { planes: if i == 4 { vec![plane(0.0, 1.0, -1.0)] } else { vec![plane(1.0, 0.0, 1.0), plane(-1.0, 0.0, 1.0)] }, delta: 0.1, factor: 1.0, stop: i == 9, caps: (f64::INFINITY, f64::INFINITY) })
            .collect();
        assert_eq!(greedy(&steps), Err(Failure::Stuck(4)));
    }
}
