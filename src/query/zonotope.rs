//! Whether an ellipsoid lies inside a zonotope, for any number of generators: the wrench set
//! W = {w : (w − c)ᵀE(w − c) ≤ 1} inside the available wrench set Z = {J f : f_min ≤ f ≤ f_max} of
//! a robot with any number of cables, without the C(m, n − 1) facet pairs of hyperplane shifting
//! ([`super::wrench::wrench_set_margin`], whose margin this is).
//!
//! In support functions, with a_k(y) = y·j_k for the columns j_k of J:
//! h_Z(y) = Σ_k max(f_min,k a_k, f_max,k a_k) (+∞ where a column without an upper bound has
//! a_k > 0), h_W(y) = y·c + √(yᵀQy) with Q = E⁻¹, and s(y) = Σ_k |a_k|, the rate at which
//! shrinking the tension box by t moves h_Z. W lies in the box shrunk by t iff
//! G_t(y) = h_Z(y) − t·s(y) − h_W(y) ≥ 0 for every direction y, so the margin is t* = min G_0/s
//! (capped at half the narrowest finite tension range).
//!
//! **Branch and bound over directions.** The directions are covered by simplicial cones — the 2ⁿ
//! orthants, each split in two across its longest edge as needed. On a cone with rays v_i (y =
//! Σ_i μ_i v_i, μ in the simplex), tensions f within the box give y·Jf ≤ h_Z(y), so
//! G_t(y) ≥ Σ_i μ_i (v_i·Jf − h_W(v_i)) (h_W is convex and homogeneous: h_W(y) ≤ Σ_i μ_i h_W(v_i)),
//! and the best f makes this max_f min_i (v_i·Jf − h_W(v_i)), a linear program with one row per
//! ray ([`max_min`]). By duality its value is min over the cone's slice of h_Z(y) − Σ_i μ_i h_W(v_i):
//! the zonotope enters exactly, kinks and all, and the bound falls short of min G_t only by the
//! convexity gap of the ellipsoid's reach, which shrinks with the square of the cone's width. So
//! each cone is cut only where the margin is smaller than that gap: near the least margin, or
//! everywhere when the ellipsoid is large and barely fits.
//!
//! The same cones serve a whole piece of a motion ([`Cover::certify`]): they are fixed sets of
//! directions, so tensions f that make every v_i·Jf − h_W(v_i) positive at the piece's middle
//! hold along the piece wherever each ray's v_i·J(λ)f − h_W(v_i, λ) stays positive, which the
//! caller checks on the motion's polynomials.

use std::collections::{BinaryHeap, HashMap};

use nalgebra::{DMatrix, DVector};

use super::facets::{binomial, facet_normal, subsets, SINGULAR_RATIO};
use crate::model::Bounds;
use crate::order::Least;

/// An infinite upper tension bound taken along a piece of a motion, in multiples of the largest
/// tension the cone's loads call for ([`Cover::bound`]).
const FINITE: f64 = 8.0;

/// Cones narrower than this (1 − cos of their longest edge's angle) are not split further.
const NARROWEST: f64 = 1e-15;

/// Most vertices of the columns' arrangement a cone's margin is found among one by one
/// ([`margin`]): C(12, 5).
const ENUMERATED: usize = 792;

/// An ellipsoid and a zonotope in ℝⁿ: is {w : (w − c)ᵀQ⁻¹(w − c) ≤ 1} inside {J f : f_min ≤ f ≤
/// f_max}?
#[derive(Debug, Clone, Copy)]
pub struct Containment<'a> {
    /// The zonotope's generators, the columns of J (n × m).
    pub j: &'a DMatrix<f64>,
    /// Each column's bounds (an upper bound may be infinite).
    pub bounds: &'a [Bounds],
    /// The ellipsoid's centre c.
    pub centre: &'a DVector<f64>,
    /// Its shape Q = E⁻¹ (symmetric, positive semi-definite; zero for the single point c).
    pub shape: &'a DMatrix<f64>,
}

/// The margin t* of [`Containment`] bracketed by the branch and bound: lo ≤ t* ≤ hi.
#[derive(Debug, Clone, PartialEq)]
pub struct Margin {
    /// A lower bound.
    pub lo: f64,
    /// The least G/s found at a direction (an upper bound).
    pub hi: f64,
    /// That direction (unit length).
    pub worst: DVector<f64>,
}

/// What a cover says of a piece of a motion.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// The ellipsoid lies strictly inside throughout.
    Holds,
    /// At the middle, G < 0 along these unit directions, the most violated first (the caller
    /// certifies one over the piece).
    Fails(Vec<DVector<f64>>),
    /// Neither within the budget.
    Unknown,
}

/// The directions of ℝⁿ covered by simplicial cones (n rays each), with the values of the
/// problem last loaded at their rays.
#[derive(Debug, Clone)]
pub struct Cover {
    n: usize,
    m: usize,
    /// The rays' unit directions, n numbers each.
    dirs: Vec<f64>,
    /// a_k(v) = v·j_k, m numbers per ray.
    a: Vec<f64>,
    /// h_W(v) per ray.
    hw: Vec<f64>,
    /// Per column, ‖j_k‖.
    norms: Vec<f64>,
    /// Per ray, the load its values were computed for ([`Cover::ensure`]).
    stamp: Vec<u32>,
    /// The load in force (counted from 1).
    current: u32,
    /// The cones, n ray indices each; a cone split in two is left empty (ids stay).
    cones: Vec<Vec<u32>>,
    /// Per cone id, the two cones it was split into.
    halves_of: Vec<Option<[usize; 2]>>,
    /// The ray halving each edge split so far, shared by the cones on both sides of it.
    halves: HashMap<(u32, u32), u32>,
}

/// A cone's bound: the linear program's value (a lower bound on G_t over the cone's slice, less
/// the drift), the tensions reaching it and the direction where its dual puts the least.
struct Bound {
    value: f64,
    tensions: Vec<f64>,
    worst: DVector<f64>,
}

impl Cover {
    /// The 2ⁿ orthants of ℝⁿ, with no problem loaded.
    pub fn orthants(n: usize) -> Cover {
        let mut dirs = Vec::with_capacity(2 * n * n);
        for i in 0..n {
            for sign in [1.0, -1.0] {
                dirs.extend((0..n).map(|r| if r == i { sign } else { 0.0 }));
            }
        }
        let cones = (0..1usize << n).map(|signs| (0..n).map(|i| (2 * i + (signs >> i & 1)) as u32).collect()).collect();
        let halves_of = vec![None; 1 << n];
        Cover { n, m: 0, dirs, a: Vec::new(), hw: Vec::new(), norms: Vec::new(), stamp: Vec::new(), current: 0, cones, halves_of, halves: HashMap::new() }
    }

    /// How many cones the cover has.
    pub fn len(&self) -> usize {
        self.cones.iter().filter(|c| !c.is_empty()).count()
    }

    /// Whether the cover has no cone (never, for a cover made by [`Cover::orthants`]).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The ids of all its cones (for [`Cover::certify`]).
    pub fn all(&self) -> Vec<usize> {
        (0..self.cones.len()).filter(|&c| !self.cones[c].is_empty()).collect()
    }

    /// Takes `p` as the problem (its dimension must be the cover's); the rays' values follow as
    /// cones need them ([`Cover::ensure`]): every ray's are stale once `current` moves on.
    pub fn load(&mut self, p: &Containment) {
        let m = p.j.ncols();
        let rays = self.dirs.len() / self.n;
        if self.m != m || self.a.len() != rays * m {
            self.a = vec![0.0; rays * m];
        }
        self.m = m;
        self.norms = (0..m).map(|k| p.j.column(k).norm()).collect();
        self.hw.resize(rays, 0.0);
        self.stamp.resize(rays, 0);
        self.current += 1;
    }

    /// The loaded problem's values at the rays of cone `c`.
    fn ensure(&mut self, c: usize, p: &Containment) {
        for i in 0..self.n {
            let r = self.cones[c][i] as usize;
            if self.stamp[r] != self.current {
                self.value(r, p);
            }
        }
    }

    /// The problem's a_k and h_W at ray `r`.
    fn value(&mut self, r: usize, p: &Containment) {
        let (n, m) = (self.n, self.m);
        let v = &self.dirs[r * n..(r + 1) * n];
        for k in 0..m {
            self.a[r * m + k] = (0..n).map(|i| v[i] * p.j[(i, k)]).sum();
        }
        self.hw[r] = support_of_ellipsoid(p, v);
        self.stamp[r] = self.current;
    }

    /// The ray halving the edge between rays `x` and `y` (made, and evaluated under `p`, once).
    fn half(&mut self, x: u32, y: u32, p: &Containment) -> u32 {
        let key = (x.min(y), x.max(y));
        if let Some(&r) = self.halves.get(&key) {
            return r;
        }
        let n = self.n;
        let u: Vec<f64> = (0..n).map(|i| self.dirs[x as usize * n + i] + self.dirs[y as usize * n + i]).collect();
        let norm = u.iter().map(|v| v * v).sum::<f64>().sqrt();
        let r = (self.dirs.len() / n) as u32;
        self.dirs.extend(u.iter().map(|v| v / norm));
        self.a.extend(std::iter::repeat_n(0.0, self.m));
        self.hw.push(0.0);
        self.stamp.push(0);
        self.value(r as usize, p);
        self.halves.insert(key, r);
        r
    }

    /// `cone` split across its longest edge, or `None` when every edge is narrower than
    /// [`NARROWEST`].
    fn split(&mut self, cone: &[u32], p: &Containment) -> Option<(Vec<u32>, Vec<u32>)> {
        let n = self.n;
        let dot = |x: u32, y: u32| (0..n).map(|i| self.dirs[x as usize * n + i] * self.dirs[y as usize * n + i]).sum::<f64>();
        let (mut best, mut edge) = (f64::INFINITY, (0, 0));
        for i in 0..n {
            for j in i + 1..n {
                let d = dot(cone[i], cone[j]);
                if d < best {
                    (best, edge) = (d, (i, j));
                }
            }
        }
        if 1.0 - best < NARROWEST {
            return None;
        }
        let mid = self.half(cone[edge.0], cone[edge.1], p);
        let (mut left, mut right) = (cone.to_vec(), cone.to_vec());
        left[edge.0] = mid;
        right[edge.1] = mid;
        Some((left, right))
    }

    /// The bound on `cone` with the box shrunk by `t` (module docs); with `finite`, an upper
    /// bound that is infinite is taken as a finite one instead (`FINITE` times the largest
    /// tension the loads call for), so that the tensions found are finite.
    fn bound(&self, cone: &[u32], p: &Containment, t: f64, finite: bool) -> Bound {
        let (n, m) = (self.n, self.m);
        let lo: Vec<f64> = p.bounds.iter().map(|b| b.min + t).collect();
        let cap = FINITE * (cone.iter().map(|&r| self.hw[r as usize].abs()).fold(0.0, f64::max) / self.norms.iter().copied().fold(f64::INFINITY, f64::min).max(f64::MIN_POSITIVE) + lo.iter().fold(0.0f64, |x, v| x.max(v.abs())));
        let hi: Vec<f64> = p.bounds.iter().zip(&lo).map(|(b, l)| if finite && !b.max.is_finite() { l + cap } else { b.max - t }).collect();
        let mut g = Vec::with_capacity(n * m);
        let mut b = Vec::with_capacity(n);
        for &r in cone {
            let r = r as usize;
            g.extend_from_slice(&self.a[r * m..(r + 1) * m]);
            b.push(-self.hw[r]);
        }
        let (value, tensions, mu) = max_min(&b, &g, m, &lo, &hi);
        let worst = DVector::from_fn(n, |i, _| cone.iter().zip(&mu).map(|(&r, w)| w * self.dirs[r as usize * n + i]).sum::<f64>());
        let norm = worst.norm();
        Bound { value, tensions, worst: if norm > 0.0 { worst / norm } else { self.dir(cone[0]) } }
    }

    /// The columns whose hyperplane a_k = 0 meets `cone` (closed, to within 1e-12 of the column's
    /// norm): every vertex of the columns' arrangement in the cone lies on n − 1 of them.
    fn meeting(&self, cone: &[u32]) -> Vec<usize> {
        let m = self.m;
        (0..m)
            .filter(|&k| {
                let eps = 1e-12 * self.norms[k];
                let (lo, hi) = cone.iter().map(|&r| self.a[r as usize * m + k]).fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), a| (l.min(a), h.max(a)));
                lo <= eps && hi >= -eps
            })
            .collect()
    }

    /// The unit direction of ray `r`.
    fn dir(&self, r: u32) -> DVector<f64> {
        DVector::from_column_slice(&self.dirs[r as usize * self.n..(r as usize + 1) * self.n])
    }

    /// Certifies the cones `open` (ids; on return the ids not certified, empty when it holds),
    /// splitting at most `budget` cones (counted down); the cover keeps the splits made, which
    /// serve every later problem. `p` is loaded; with `transport`, it is the middle of a piece of
    /// a motion, and a cone holds along the piece when `transport`, given the cone's tensions
    /// and its rays, certifies that the rays' minorants stay positive throughout (a cone
    /// certified along a piece holds on every part of it, so a part's check need only look at what
    /// its piece left open). Without `transport`, `p` is the whole problem (one pose).
    ///
    /// A cone holds at the middle when its linear program's bound is positive there. Only cones
    /// that fail at the middle are split: a cone that holds there but not along the piece needs a
    /// shorter piece, not a smaller cone (`Unknown`, once no cone shows the middle infeasible).
    /// `Fails` as soon as a direction has G < 0 at the middle.
    pub fn certify(&mut self, p: &Containment, mut transport: Option<&mut dyn FnMut(&[f64], &[DVector<f64>]) -> bool>, budget: &mut usize, open: &mut Vec<usize>) -> Verdict {
        let mut queue = std::mem::take(open);
        // cones that hold at the middle but not along the piece: the piece is not certified, yet
        // another cone may still show it infeasible
        let mut short = Vec::new();
        let verdict = loop {
            let Some(c) = queue.pop() else { break if short.is_empty() { Verdict::Holds } else { Verdict::Unknown } };
            if let Some(parts) = self.halves_of[c] {
                queue.extend(parts); // split since it was left open: its parts are
                continue;
            }
            self.ensure(c, p);
            let rays: Vec<DVector<f64>> = self.cones[c].iter().map(|&r| self.dir(r)).collect();
            // along a piece every tension is kept finite: a cone free at the middle (a column
            // without an upper bound pulling all over it) need not be along the piece
            let middle = self.bound(&self.cones[c], p, 0.0, transport.is_some());
            if middle.value > 0.0 {
                if let Some(t) = transport.as_mut() {
                    if !t(&middle.tensions, &rays) {
                        short.push(c);
                    }
                }
                continue;
            }
            // the middle's own verdict where the bound points: G < 0 there shows it infeasible;
            // the other open cones' rays offer more violated directions
            let worst = rays.iter().cloned().chain([middle.worst]).map(|y| (ratio(p, &y), y)).filter(|w| w.0 < 0.0).min_by(|x, y| x.0.total_cmp(&y.0));
            if let Some(worst) = worst {
                queue.push(c);
                let mut found = vec![worst];
                for &o in &queue {
                    if self.cones[o].is_empty() || o == c {
                        continue;
                    }
                    self.ensure(o, p);
                    found.extend(self.cones[o].iter().map(|&r| (self.ray_ratio(r as usize, p), r)).filter(|w| w.0 < 0.0).map(|(q, r)| (q, self.dir(r))));
                }
                crate::order::sort_by_key(&mut found, |f| f.0);
                break Verdict::Fails(found.into_iter().take(FAILING).map(|f| f.1).collect());
            }
            let cone = self.cones[c].clone();
            let halves = if *budget > 0 { self.split(&cone, p) } else { None };
            match halves {
                Some((left, right)) => {
                    *budget -= 1;
                    self.cones[c].clear();
                    let ids = [self.cones.len(), self.cones.len() + 1];
                    self.halves_of[c] = Some(ids);
                    self.cones.extend([left, right]);
                    self.halves_of.extend([None, None]);
                    queue.extend(ids);
                }
                None => {
                    queue.push(c);
                    break Verdict::Unknown;
                }
            }
        };
        queue.append(&mut short);
        *open = queue;
        verdict
    }

    /// G/s at ray `r` from its loaded values, as [`ratio`] computes it.
    fn ray_ratio(&self, r: usize, p: &Containment) -> f64 {
        let m = self.m;
        ratio_of(p.bounds, (0..m).map(|k| (self.a[r * m + k], self.norms[k])), || self.hw[r])
    }
}

/// h_W(v) = v·c + √(vᵀQv) for the numbers `v` of a direction.
fn support_of_ellipsoid(p: &Containment, v: &[f64]) -> f64 {
    let n = v.len();
    let centre: f64 = (0..n).map(|i| v[i] * p.centre[i]).sum();
    let quad: f64 = (0..n).map(|i| v[i] * (0..n).map(|l| p.shape[(i, l)] * v[l]).sum::<f64>()).sum();
    centre + quad.max(0.0).sqrt()
}

/// G(y)/s(y) at the unit direction `y` (+∞ where a column without an upper bound pulls along
/// y, or where y is orthogonal to every column). A column within 1e-11 of its norm of being
/// orthogonal to y counts as not pulling: the least ratio sits on such columns' hyperplanes,
/// where rounding leaves a_k a few ulps either side.
pub fn ratio(p: &Containment, y: &DVector<f64>) -> f64 {
    let products = (0..p.j.ncols()).map(|k| {
        let column = p.j.column(k);
        (y.dot(&column), column.norm())
    });
    ratio_of(p.bounds, products, || support_of_ellipsoid(p, y.as_slice()))
}

/// G/s from each column's a_k = y·j_k and norm ‖j_k‖ (in the order of `bounds`) and h_W(y)
/// (asked for only when G is finite), as [`ratio`] describes it.
fn ratio_of(bounds: &[Bounds], products: impl Iterator<Item = (f64, f64)>, hw: impl FnOnce() -> f64) -> f64 {
    let (mut support, mut s) = (0.0, 0.0);
    for (b, (a, norm)) in bounds.iter().zip(products) {
        s += a.abs();
        support += if a > 1e-11 * norm { if b.max.is_finite() { b.max * a } else { return f64::INFINITY } } else { b.min * a };
    }
    if s > 0.0 { (support - hw()) / s } else { f64::INFINITY }
}

/// max over f with l ≤ f ≤ u of min_i (b_i + g_i·f), for r rows b_i, g_i (g row-major, r × m)
/// and m bounded variables (u may be +∞): the value reached — computed from the final f itself, so
/// that rounding in the simplex can only make it smaller, never wrong as a lower bound of the
/// maximum — that f, and the rows' weights μ (≥ 0, summing to 1) of the final dual, which put
/// the most on the rows that bind. +∞ when the objective is unbounded (f then at its start). A bounded-variable primal simplex
/// on z ≤ b_i + g_i·f with r basic variables among z, the rows' slacks and the f's.
pub fn max_min(b: &[f64], g: &[f64], m: usize, l: &[f64], u: &[f64]) -> (f64, Vec<f64>, Vec<f64>) {
    let r = b.len();
    // variables: f_0..f_m, slacks s_0..s_r (s_i = b_i + g_i·f − z ≥ 0), z; rows g_i·f − z − s_i = −b_i
    let (z, slack) = (m + r, |i: usize| m + i);
    let column = |var: usize, row: usize| -> f64 {
        if var < m {
            g[row * m + var]
        } else if var == z {
            -1.0
        } else if var - m == row {
            -1.0
        } else {
            0.0
        }
    };
    let scale = b.iter().fold(0.0f64, |x, v| x.max(v.abs())) + g.iter().fold(0.0f64, |x, v| x.max(v.abs())) * l.iter().chain(u).filter(|v| v.is_finite()).fold(1.0f64, |x, v| x.max(v.abs()));
    let tol = 1e-12 * scale.max(f64::MIN_POSITIVE);
    // f at the bound the rows favour on average; z basic in the least row, the other slacks basic
    let mut x = vec![0.0; m + r + 1];
    let mut upper = vec![false; m];
    for k in 0..m {
        let pull: f64 = (0..r).map(|i| g[i * m + k]).sum();
        upper[k] = pull > 0.0 && u[k].is_finite();
        x[k] = if upper[k] { u[k] } else { l[k] };
    }
    let row_value = |x: &[f64], i: usize| b[i] + (0..m).map(|k| g[i * m + k] * x[k]).sum::<f64>();
    let least = (0..r).min_by(|&i, &j| row_value(&x, i).total_cmp(&row_value(&x, j))).unwrap_or(0);
    let mut basis: Vec<usize> = (0..r).map(|i| if i == least { z } else { slack(i) }).collect();
    let mut basic = vec![false; m + r + 1];
    for &v in &basis {
        basic[v] = true;
    }
    let mut y = vec![-1.0 / r as f64; r];
    let mut degenerate = 0;
    let mut inv = vec![0.0; r * r];
    for _ in 0..(50 + 4 * m) {
        for row in 0..r {
            for (c, &var) in basis.iter().enumerate() {
                inv[row * r + c] = column(var, row);
            }
        }
        if !invert(&mut inv, r) {
            break;
        }
        // the basic values from the nonbasic ones
        let rhs: Vec<f64> = (0..r).map(|i| -b[i] - (0..m).filter(|&k| !basic[k]).map(|k| g[i * m + k] * x[k]).sum::<f64>()).collect();
        for (pos, &var) in basis.iter().enumerate() {
            x[var] = (0..r).map(|i| inv[pos * r + i] * rhs[i]).sum();
        }
        let zpos = basis.iter().position(|&v| v == z).unwrap_or(0);
        y = (0..r).map(|i| inv[zpos * r + i]).collect();
        // reduced costs of the nonbasic variables (the objective is z)
        let bland = degenerate > 20;
        // candidates (variable, reduced cost, direction): the f's off their bounds' side, the slacks
        let candidates = (0..m)
            .filter(|&k| !basic[k])
            .map(|k| (k, -(0..r).map(|i| y[i] * g[i * m + k]).sum::<f64>(), if upper[k] { -1.0 } else { 1.0 }))
            .chain((0..r).filter(|&i| !basic[slack(i)]).map(|i| (slack(i), y[i], 1.0)));
        let mut entering: Option<(usize, f64, f64)> = None;
        for (var, d, dir) in candidates {
            let gain = d * dir;
            if gain > tol && entering.is_none_or(|e| gain > e.1) {
                entering = Some((var, gain, dir));
                if bland {
                    break;
                }
            }
        }
        let Some((var, _, dir)) = entering else { break };
        // the basic variables move by −dir·θ·B⁻¹a
        let w: Vec<f64> = (0..r).map(|pos| (0..r).map(|i| inv[pos * r + i] * column(var, i)).sum()).collect();
        let own = if var < m { u[var] - l[var] } else { f64::INFINITY };
        let tiny = 1e-12 * w.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let (mut step, mut leaving) = (own, None);
        for (pos, &bv) in basis.iter().enumerate() {
            if bv == z {
                continue;
            }
            let rate = -dir * w[pos];
            let (low, high) = if bv < m { (l[bv], u[bv]) } else { (0.0, f64::INFINITY) };
            let room = if rate < -tiny { (x[bv] - low).max(0.0) / -rate } else if rate > tiny && high.is_finite() { (high - x[bv]).max(0.0) / rate } else { continue };
            if room < step {
                step = room;
                leaving = Some((pos, rate > 0.0));
            }
        }
        if !step.is_finite() {
            // unbounded only if the ray found raises every row: f moves up (only where there is
            // no upper bound) along d and every g_i·d > 0, checked on its own
            let mut d = vec![0.0; m];
            if var < m {
                d[var] = dir;
            }
            for (pos, &bv) in basis.iter().enumerate() {
                if bv < m {
                    d[bv] = -dir * w[pos];
                }
            }
            let size = d.iter().fold(0.0f64, |s, v| s.max(v.abs()));
            let upward = (0..m).all(|k| d[k] >= 0.0 && (d[k] == 0.0 || !u[k].is_finite()));
            let rises = (0..r).all(|i| (0..m).map(|k| g[i * m + k] * d[k]).sum::<f64>() > 1e-9 * size * scale.max(f64::MIN_POSITIVE));
            if upward && rises {
                return (f64::INFINITY, (0..m).map(|k| x[k].clamp(l[k], u[k])).collect(), mu_of(&y));
            }
            break;
        }
        degenerate = if step <= tol { degenerate + 1 } else { 0 };
        x[var] += dir * step;
        match leaving {
            None => upper[var] = !upper[var],
            Some((pos, at_high)) => {
                let out = basis[pos];
                if out < m {
                    upper[out] = at_high;
                    x[out] = if at_high { u[out] } else { l[out] };
                } else {
                    x[out] = 0.0;
                }
                basis[pos] = var;
                basic[out] = false;
                basic[var] = true;
            }
        }
    }
    let f: Vec<f64> = (0..m).map(|k| x[k].clamp(l[k], u[k])).collect();
    let value = (0..r).map(|i| row_value(&f, i)).fold(f64::INFINITY, f64::min);
    (value, f, mu_of(&y))
}

/// Inverts the r × r matrix `a` (row-major) in place by Gauss–Jordan elimination with partial
/// pivoting; false when it is singular to rounding.
fn invert(a: &mut [f64], r: usize) -> bool {
    let mut inv = vec![0.0; r * r];
    for i in 0..r {
        inv[i * r + i] = 1.0;
    }
    let size = a.iter().fold(0.0f64, |x, v| x.max(v.abs()));
    for col in 0..r {
        let Some(pivot) = (col..r).max_by(|&i, &j| a[i * r + col].abs().total_cmp(&a[j * r + col].abs())) else { return false };
        if !(a[pivot * r + col].abs() > 1e-14 * size) {
            return false;
        }
        for c in 0..r {
            a.swap(col * r + c, pivot * r + c);
            inv.swap(col * r + c, pivot * r + c);
        }
        let d = a[col * r + col];
        for c in 0..r {
            a[col * r + c] /= d;
            inv[col * r + c] /= d;
        }
        for row in (0..r).filter(|&row| row != col) {
            let f = a[row * r + col];
            if f != 0.0 {
                for c in 0..r {
                    a[row * r + c] -= f * a[col * r + c];
                    inv[row * r + c] -= f * inv[col * r + c];
                }
            }
        }
    }
    a.copy_from_slice(&inv);
    true
}

/// The rows' weights from the duals y of the rows (μ_i = −y_i, kept ≥ 0 and normalised).
fn mu_of(y: &[f64]) -> Vec<f64> {
    let mu: Vec<f64> = y.iter().map(|v| (-v).max(0.0)).collect();
    let total: f64 = mu.iter().sum();
    if total > 0.0 { mu.iter().map(|v| v / total).collect() } else { vec![1.0 / y.len() as f64; y.len()] }
}

/// Whether J has full row rank n (its least singular value above [`SINGULAR_RATIO`] of its
/// largest).
pub fn full_rank(j: &DMatrix<f64>) -> bool {
    let sv = j.clone().svd(false, false).singular_values;
    j.ncols() >= j.nrows() && sv.min() > SINGULAR_RATIO * sv.max()
}

/// Most violated directions [`Cover::certify`] offers when it fails.
const FAILING: usize = 4;

/// Most splits [`contains`] makes before it gives up (and reports the pose as not certified).
const DECISION_SPLITS: usize = 100_000;

/// Whether the ellipsoid of `p` lies strictly inside the zonotope (every wrench of it balanced
/// by tensions strictly within their bounds): the branch and bound of [`Cover::certify`] at one
/// pose, which stops at the first cone that certifies the answer either way — much cheaper than
/// the margin near a round zonotope. `None` when J has rank below n; `Some(false)` also where
/// the margin is zero to rounding (no cone can be certified).
pub fn contains(p: &Containment) -> Option<bool> {
    if !full_rank(p.j) {
        return None;
    }
    let mut cover = Cover::orthants(p.j.nrows());
    cover.load(p);
    let mut open = cover.all();
    Some(cover.certify(p, None, &mut DECISION_SPLITS.clone(), &mut open) == Verdict::Holds)
}

/// The margin t* of `p` (module docs) to within `tol` (hi − lo ≤ tol unless `cap` splits were
/// not enough), by the branch and bound; capped at half the narrowest finite tension range.
/// `None` when J has rank below n (W is then balanced only on a hyperplane, reported as singular).
///
/// Best first by the least ratio seen in a cone: a cone is set aside once its bound with the box
/// shrunk by hi − tol is non-negative (its ratios are then all at least hi − tol, and stay so as
/// hi falls), split otherwise, the direction its dual points at tried as a better hi.
pub fn margin(p: &Containment, tol: f64, cap: usize) -> Option<Margin> {
    let n = p.j.nrows();
    if !full_rank(p.j) {
        return None;
    }
    let half = p.bounds.iter().filter(|b| b.max.is_finite()).map(|b| 0.5 * (b.max - b.min)).fold(f64::INFINITY, f64::min);
    let mut cover = Cover::orthants(n);
    cover.load(p);
    for c in cover.all() {
        cover.ensure(c, p);
    }
    let (mut hi, mut worst) = (half, cover.dir(0));
    let seen = |cover: &Cover, cone: &[u32]| cone.iter().map(|&r| (ratio(p, &cover.dir(r)), r)).fold((f64::INFINITY, cone[0]), |x, y| if y.0 < x.0 { y } else { x });
    let mut heap = BinaryHeap::new();
    for cone in std::mem::take(&mut cover.cones) {
        let (least, r) = seen(&cover, &cone);
        if least < hi {
            (hi, worst) = (least, cover.dir(r));
        }
        heap.push(Least { key: least, tie: 0.0, id: 0, item: cone });
    }
    let mut splits = 0;
    let mut open = Vec::new();
    while let Some(Least { item: cone, .. }) = heap.pop() {
        let t = (hi - tol).min(half);
        let bound = cover.bound(&cone, p, t, false);
        if bound.value >= 0.0 {
            continue;
        }
        let at = ratio(p, &bound.worst);
        if at < hi {
            (hi, worst) = (at, bound.worst.clone());
        }
        // few hyperplanes meet the cone: its vertices of the columns' arrangement (hyperplane
        // shifting's facet normals, where the least ratio lies) are few, and tried one by one
        let meeting = cover.meeting(&cone);
        if meeting.len() < n - 1 {
            continue; // no vertex in it
        }
        if binomial(meeting.len(), n - 1) <= ENUMERATED {
            for s in subsets(meeting.len(), n - 1) {
                let cols: Vec<usize> = s.iter().map(|&i| meeting[i]).collect();
                let normal = facet_normal(p.j, &cols);
                let norm = normal.norm();
                if !(norm > 0.0) {
                    continue;
                }
                for y in [&normal / norm, -&normal / norm] {
                    let at = ratio(p, &y);
                    if at < hi {
                        (hi, worst) = (at, y);
                    }
                }
            }
            continue;
        }
        if splits >= cap {
            open.push(cone);
            continue;
        }
        match cover.split(&cone, p) {
            Some((left, right)) => {
                splits += 1;
                for c in [left, right] {
                    let (least, r) = seen(&cover, &c);
                    if least < hi {
                        (hi, worst) = (least, cover.dir(r));
                    }
                    heap.push(Least { key: least.min(at), tie: 0.0, id: 0, item: c });
                }
            }
            None => open.push(cone),
        }
    }
    // cones left open: the largest shrink each still holds at, by bisection
    let floor = |cone: &[u32]| -> f64 {
        let (mut a, mut b) = (-(1.0 + hi.abs()), hi - tol);
        while cover.bound(cone, p, a, false).value < 0.0 {
            a *= 2.0;
            if a < -1e12 {
                return f64::NEG_INFINITY;
            }
        }
        for _ in 0..60 {
            let mid = 0.5 * (a + b);
            if cover.bound(cone, p, mid, false).value >= 0.0 { a = mid } else { b = mid }
        }
        a
    };
    let lo = open.iter().map(|c| floor(c)).fold((hi - tol).min(half), f64::min);
    Some(Margin { lo: lo.min(hi), hi, worst })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::wrench::facets;

    /// A deterministic uniform generator on [−1, 1).
    fn rng(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        }
    }

    /// Hyperplane shifting's margin: every facet pair of the zonotope against the ellipsoid.
    fn by_facets(p: &Containment) -> Option<f64> {
        let n = p.j.nrows();
        let rows: Vec<usize> = (0..n).collect();
        let all = facets(p.j, &rows, p.bounds)?;
        let least = all
            .iter()
            .map(|f| {
                let normal = DVector::from_fn(n, |r, _| f.normal[r]);
                let reach = normal.dot(&(p.shape * &normal)).max(0.0).sqrt();
                let centre = normal.dot(p.centre);
                ((f.upper - centre).min(centre - f.lower) - reach) / f.spread
            })
            .fold(f64::INFINITY, f64::min);
        let half = p.bounds.iter().filter(|b| b.max.is_finite()).map(|b| 0.5 * (b.max - b.min)).fold(f64::INFINITY, f64::min);
        Some(least.min(half))
    }

    /// Random zonotopes (6 or 3 rows, up to 14 columns, some without an upper bound) and
    /// ellipsoids: the branch and bound's margin equals hyperplane shifting's, and the decision
    /// agrees with its sign.
    #[test]
    fn margins_agree_with_hyperplane_shifting() {
        let mut r = rng(3);
        let (mut feasible, mut infeasible) = (0, 0);
        for case in 0..400 {
            let n = if case % 4 == 0 { 3 } else { 6 };
            let m = n + (r().abs() * (15 - n) as f64) as usize;
            let unbounded = case % 5 == 1;
            // without upper bounds, columns that all pull down along the first axis (as cables
            // from anchors above do): otherwise they positively span and Z is everything
            let j = DMatrix::from_fn(n, m, |row, _| if unbounded && row == 0 { -0.3 - r().abs() } else { r() });
            let bounds: Vec<Bounds> = (0..m).map(|_| Bounds { min: 0.1 + 0.2 * r().abs(), max: if unbounded { f64::INFINITY } else { 1.5 + r().abs() } }).collect();
            // the centre: the image of tensions inside the box, nudged
            let inside = DVector::from_fn(m, |k, _| bounds[k].min + 0.5 * r().abs());
            let centre = &j * inside + DVector::from_fn(n, |_, _| 0.3 * r());
            let l = DMatrix::from_fn(n, n, |_, _| 0.3 * r());
            let shape = &l * l.transpose();
            let p = Containment { j: &j, bounds: &bounds, centre: &centre, shape: &shape };
            let reference = by_facets(&p).expect("full rank");
            let got = margin(&p, 1e-10 * (1.0 + reference.abs()), 200_000).expect("full rank");
            let scale = 1.0 + reference.abs();
            assert!(reference.is_finite(), "case {case}: facets give {reference}");
            assert!(got.lo <= got.hi + 1e-12 && got.hi - got.lo <= 1e-9 * scale, "case {case}: bracket {got:?}, facets {reference}");
            assert!((got.hi - reference).abs() <= 1e-9 * scale, "case {case} ({n}×{m}, unbounded {unbounded}): {got:?} against facets {reference}");
            if reference.abs() > 1e-9 {
                assert_eq!(contains(&p), Some(reference > 0.0), "case {case}: facets' margin {reference}");
            }
            if reference > 0.0 { feasible += 1 } else { infeasible += 1 }
        }
        assert!(feasible > 60 && infeasible > 60, "{feasible} feasible, {infeasible} infeasible");
    }
}
#[cfg(test)]
mod lp_tests {
    use super::*;
    use crate::query::lp::{maximise, LpResult};

    /// max_min against the dense simplex on the same programs (z ≤ b_i + g_i·f, l ≤ f ≤ u).
    #[test]
    fn max_min_agrees_with_the_dense_simplex() {
        let mut state = 11u64;
        let mut r = move || { state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407); ((state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0 };
        let mut worst = 0.0f64;
        for case in 0..2000 {
            let rows = if case % 3 == 0 { 3 } else { 6 };
            let m = 1 + (r().abs() * 40.0) as usize;
            let b: Vec<f64> = (0..rows).map(|_| r()).collect();
            let g: Vec<f64> = (0..rows * m).map(|_| r()).collect();
            let l: Vec<f64> = (0..m).map(|_| r().abs() * 0.5).collect();
            let u: Vec<f64> = (0..m).map(|k| if case % 7 == 0 && k % 3 == 0 { f64::INFINITY } else { l[k] + 0.1 + r().abs() }).collect();
            let (value, f, mu) = max_min(&b, &g, m, &l, &u);
            assert!(f.iter().zip(l.iter().zip(&u)).all(|(x, (lo, hi))| lo <= x && x <= hi), "case {case}: tensions outside their bounds");
            // dense: variables f' = f − l (m), slack_u (finite u), z⁺, z⁻, row slacks
            let fin: Vec<usize> = (0..m).filter(|&k| u[k].is_finite()).collect();
            let nv = m + fin.len() + 2 + rows;
            let nr = rows + fin.len() + 1;
            let mut a = DMatrix::zeros(nr, nv);
            let mut bb = DVector::zeros(nr);
            for i in 0..rows {
                // z − g_i·f' + s_i = b_i + g_i·l
                for k in 0..m { a[(i, k)] = -g[i * m + k]; }
                a[(i, m + fin.len())] = 1.0;
                a[(i, m + fin.len() + 1)] = -1.0;
                a[(i, m + fin.len() + 2 + i)] = 1.0;
                bb[i] = b[i] + (0..m).map(|k| g[i * m + k] * l[k]).sum::<f64>();
            }
            for (q, &k) in fin.iter().enumerate() {
                a[(rows + q, k)] = 1.0;
                a[(rows + q, m + q)] = 1.0;
                bb[rows + q] = u[k] - l[k];
            }
            // z⁺ ≤ 1e6 keeps the dense program bounded
            a[(nr - 1, m + fin.len())] = 1.0;
            let cap_col = nv; let _ = cap_col;
            let mut a2 = DMatrix::zeros(nr, nv + 1);
            a2.view_mut((0, 0), (nr, nv)).copy_from(&a);
            a2[(nr - 1, nv)] = 1.0;
            bb[nr - 1] = 1e6;
            let mut c = DVector::zeros(nv + 1);
            c[m + fin.len()] = 1.0;
            c[m + fin.len() + 1] = -1.0;
            let LpResult::Optimal { value: reference, .. } = maximise(&a2, &bb, &c) else { panic!("case {case}: dense program not optimal") };
            if reference > 1e5 {
                assert!(value == f64::INFINITY, "case {case}: unbounded, got {value}");
                continue;
            }
            assert!(value <= reference + 1e-9 && value >= reference - 1e-9 * (1.0 + reference.abs()), "case {case}: {value} against {reference}");
            worst = worst.max(reference - value);
            assert!((mu.iter().sum::<f64>() - 1.0).abs() < 1e-9 && mu.iter().all(|x| *x >= 0.0));
        }
        assert!(worst < 1e-9, "shortfall {worst}");
    }
}
