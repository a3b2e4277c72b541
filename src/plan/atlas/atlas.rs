//! Henderson's multiple-parameter continuation (Henderson 2002; Bohigas et al. §4): an atlas of
//! charts grown from a start point, each chart expanded from the vertices of its polytope that lie
//! outside its ball, new charts cropping their neighbours' polytopes, until every chart is closed.
//! Generic over [`Manifold`]: it never knows what the equations mean.
//!
//! Chart radii adapt to the curvature: a new chart's radius is the step at which the tangent
//! approximation error measured on the step that made it (the gap to the parent's tangent space
//! and 1 − |det ΨᵀΨ'|, both quadratic in the step) would reach ε/2, between the least and the
//! largest radius of [`AtlasParams`]; the start chart has the largest radius.
//! The polytope cuts are bisectors whatever the radii (Voronoi cells of the centres).

use super::chart::{Chart, ChartState, Polytope};
use super::manifold::Manifold;
use nalgebra::{DMatrix, DVector};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The continuation's parameters (see [`super::PlanParams`] for their meaning and defaults).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AtlasParams {
    /// Largest chart radius r_max in tangent coordinates: the start chart's radius, and the most
    /// the adaptation gives any chart.
    pub radius: f64,
    /// Smallest radius the adaptation gives an open chart (`min_radius = radius`: every chart has
    /// radius r, CuikSuite's fixed radius).
    pub min_radius: f64,
    /// Chart validity threshold ε.
    pub epsilon: f64,
    /// Largest step δ between consecutive path points (in the manifold's distance).
    pub delta: f64,
}

/// Newton iterations allowed per projection.
const MAX_NEWTON: usize = 30;
/// A projection has converged when every residual is below this.
const NEWTON_TOL: f64 = 1e-10;
/// On an invalid new chart the step is multiplied by this …
const SHRINK: f64 = 0.7;
/// … down to this fraction of r, below which the expansion direction counts as a failure.
const MIN_STEP: f64 = 1e-3;
/// Where the point at step α is inadmissible (interference), the step is halved down to this
/// fraction of r before a blocked chart of that radius is placed: the resolution at which the
/// atlas approaches obstacles.
const OBSTACLE_STEP: f64 = 1.0 / 8.0;
/// The error (relative to ε) a chart's radius is chosen to reach at its boundary.
const TARGET_ERROR: f64 = 0.5;
/// Two points of the manifold count as the same one within this distance.
const SAME_POINT: f64 = 1e-7;
/// A walk of n nominal steps (length / δ, rounded up) may make at most WALK_FACTOR · n +
/// WALK_SLACK projections; past that the map counts as not followable. Walks on the Robocrane
/// slices make at most 3 · n (a step halved once or twice); without a cap, a walk creeping towards
/// a fold of the chart's map halved its step 26 times and made 2.2 million projections.
const WALK_FACTOR: usize = 4;
/// See [`WALK_FACTOR`].
const WALK_SLACK: usize = 16;

/// An atlas of a manifold.
pub struct Atlas<M: Manifold> {
    /// The manifold.
    pub manifold: M,
    /// The charts; chart 0 is centred at the first search's start point.
    pub charts: Vec<Chart>,
    /// The parameters.
    pub params: AtlasParams,
    /// Expansion directions in which no valid chart could be made down to MIN_STEP·r (the polytope
    /// was cut there anyway so the expansion terminates; a non-zero count weakens an exhaustion
    /// claim and is reported).
    pub failures: usize,
    /// Manifold evaluations (F and its Jacobian) made so far: the unit of the atlas's work.
    evaluations: AtomicUsize,
}

impl<M: Manifold> Atlas<M> {
    /// An atlas with one chart at `start`, which must lie on the manifold (residual below 1e-8)
    /// where the Jacobian has full rank.
    pub fn new(manifold: M, start: &[f64], params: AtlasParams) -> Result<Atlas<M>, String> {
        if start.len() != manifold.ambient() {
            return Err(format!("the start point has {} coordinates, the manifold's space {}", start.len(), manifold.ambient()));
        }
        let mut atlas = Atlas { manifold, charts: Vec::new(), params, failures: 0, evaluations: AtomicUsize::new(0) };
        atlas.insert(start)?;
        Ok(atlas)
    }

    /// An atlas of the charts `charts` (read back from a file, [`super::file`]), with the
    /// expansion failures it had.
    pub fn from_charts(manifold: M, charts: Vec<Chart>, params: AtlasParams, failures: usize) -> Atlas<M> {
        Atlas { manifold, charts, params, failures, evaluations: AtomicUsize::new(0) }
    }

    /// Adds a chart centred at `x` (a point of the manifold, residual below 1e-8, where the
    /// Jacobian has full rank) with the largest radius, linked with every chart it neighbours on
    /// its sheet: a second start in an atlas grown from another. Returns its index.
    pub fn insert(&mut self, x: &[f64]) -> Result<usize, String> {
        if x.len() != self.manifold.ambient() {
            return Err(format!("the point has {} coordinates, the manifold's space {}", x.len(), self.manifold.ambient()));
        }
        let basis = self.chart_basis(x, 1e-8)?;
        let state = if self.manifold.admissible(x) { ChartState::Open } else { ChartState::Blocked };
        Ok(self.add_chart(x.to_vec(), basis, None, self.params.radius, state))
    }

    /// Manifold evaluations made so far (each Newton iteration and each tangent basis is one).
    pub fn evaluations(&self) -> usize {
        self.evaluations.load(Ordering::Relaxed)
    }

    /// Evaluates F and its Jacobian at `x`, counting the evaluation.
    fn eval(&self, x: &[f64], f: &mut [f64], jac: &mut DMatrix<f64>) -> bool {
        self.evaluations.fetch_add(1, Ordering::Relaxed);
        self.manifold.eval(x, f, jac)
    }

    /// The orthonormal tangent basis at `x`, checking that x is on the manifold (max residual
    /// ≤ `tol`) and that the Jacobian has full rank there.
    pub fn chart_basis(&self, x: &[f64], tol: f64) -> Result<DMatrix<f64>, String> {
        let (n, m) = (self.manifold.ambient(), self.manifold.equations());
        let mut f = vec![0.0; m];
        let mut jac = DMatrix::zeros(m, n);
        if !self.eval(x, &mut f, &mut jac) {
            return Err("the equations are not defined there".into());
        }
        let worst = f.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        if !(worst <= tol) {
            return Err(format!("not on the manifold (residual {worst:.3e})"));
        }
        tangent_basis(&jac).ok_or_else(|| "the Jacobian is rank-deficient there".into())
    }

    /// a − b as the manifold measures it.
    fn diff(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        let mut d = vec![0.0; a.len()];
        self.manifold.difference(a, b, &mut d);
        d
    }

    /// Tangent coordinates Ψᵀ(x − x_c) of `x` in chart `c`.
    pub fn coordinates(&self, c: usize, x: &[f64]) -> Vec<f64> {
        let d = DVector::from_vec(self.diff(x, &self.charts[c].centre));
        (self.charts[c].basis.transpose() * d).as_slice().to_vec()
    }

    /// The point of the manifold with tangent coordinates `u` in chart `c`: Newton on
    /// [F(x) = 0; Ψᵀ(x − x_c) − u = 0] from `guess`.
    pub fn project(&self, c: usize, u: &[f64], guess: &[f64]) -> Option<Vec<f64>> {
        let chart = &self.charts[c];
        let (n, m) = (self.manifold.ambient(), self.manifold.equations());
        let k = n - m;
        let mut x = guess.to_vec();
        let mut f = vec![0.0; m];
        let mut jac = DMatrix::zeros(m, n);
        let mut big = DMatrix::zeros(n, n);
        for _ in 0..MAX_NEWTON {
            if !self.eval(&x, &mut f, &mut jac) {
                return None;
            }
            let t = self.coordinates(c, &x);
            let mut rhs = DVector::zeros(n);
            for i in 0..m {
                rhs[i] = -f[i];
            }
            for i in 0..k {
                rhs[m + i] = u[i] - t[i];
            }
            if rhs.amax() < NEWTON_TOL {
                return Some(x);
            }
            big.view_mut((0, 0), (m, n)).copy_from(&jac);
            big.view_mut((m, 0), (k, n)).copy_from(&chart.basis.transpose());
            let step = big.clone().lu().solve(&rhs)?;
            if !step.iter().all(|s| s.is_finite()) || step.norm() > 1e3 * (1.0 + self.params.radius) {
                return None;
            }
            for (xi, s) in x.iter_mut().zip(step.iter()) {
                *xi += s;
            }
        }
        None
    }

    /// Expands chart `c` by at most one new chart, towards its polytope's farthest vertex outside
    /// its ball: the step shrinks until the new chart is valid; where its centre is inadmissible
    /// the step is halved down to r/8 and, still inadmissible there, a blocked chart of that
    /// radius is placed. Returns `false` (and marks the chart expanded) when there is no open
    /// vertex.
    pub fn expand_once(&mut self, c: usize) -> bool {
        let r = self.charts[c].radius;
        let Some(vertex) = self.charts[c].polytope.open_vertex(r) else {
            self.charts[c].state = ChartState::Expanded;
            return false;
        };
        let len = vertex.iter().map(|a| a * a).sum::<f64>().sqrt();
        let dir: Vec<f64> = vertex.iter().map(|a| a / len).collect();
        let mut alpha = r;
        while alpha >= MIN_STEP * r {
            let u: Vec<f64> = dir.iter().map(|d| d * alpha).collect();
            let predicted = self.predict(c, &u);
            if let Some(x) = self.project(c, &u, &predicted) {
                if let Some((basis, error)) = self.valid_successor(c, &x, &predicted) {
                    if self.manifold.admissible(&x) {
                        let radius = self.adapted_radius(alpha, error);
                        self.add_chart(x, basis, Some(c), radius, ChartState::Open);
                        return true;
                    }
                    if alpha <= OBSTACLE_STEP * r {
                        self.add_chart(x, basis, Some(c), alpha, ChartState::Blocked);
                        return true;
                    }
                    alpha *= 0.5;
                    continue;
                }
            }
            alpha *= SHRINK;
        }
        self.failures += 1;
        self.charts[c].polytope.cut(&dir, 0.5 * MIN_STEP * r);
        true
    }

    /// x_c + Ψ u.
    fn predict(&self, c: usize, u: &[f64]) -> Vec<f64> {
        let chart = &self.charts[c];
        let step = &chart.basis * DVector::from_column_slice(u);
        chart.centre.iter().zip(step.iter()).map(|(a, b)| a + b).collect()
    }

    /// Henderson's validity test for a chart at `x` projected from chart `c`'s tangent point
    /// `predicted`: ‖x − predicted‖ ≤ ε and |det(Ψ_cᵀΨ_x)| ≥ 1 − ε. Returns the new basis and
    /// the step's error, max(‖x − predicted‖, 1 − |det(Ψ_cᵀΨ_x)|) / ε (at most 1).
    fn valid_successor(&self, c: usize, x: &[f64], predicted: &[f64]) -> Option<(DMatrix<f64>, f64)> {
        let eps = self.params.epsilon;
        let gap = self.diff(x, predicted).iter().map(|a| a * a).sum::<f64>().sqrt();
        if gap > eps {
            return None;
        }
        let basis = self.chart_basis(x, 1e-8).ok()?;
        let cos = (self.charts[c].basis.transpose() * &basis).determinant().abs();
        (cos >= 1.0 - eps).then_some((basis, gap.max(1.0 - cos) / eps))
    }

    /// The radius of a chart made by a valid step of length α with error e (relative to ε, see
    /// [`Atlas::valid_successor`]): both the gap to the tangent space and 1 − |det| grow as the
    /// square of the step, so the step at which the error would reach TARGET_ERROR·ε is
    /// α·sqrt(TARGET_ERROR / e): a chart grows where the manifold is flat along the step and
    /// shrinks where its tangent space turns fast; clamped to [min_radius, radius] (a min_radius
    /// above radius counts as radius).
    fn adapted_radius(&self, alpha: f64, error: f64) -> f64 {
        let p = &self.params;
        let r = if error > 0.0 { alpha * (TARGET_ERROR / error).sqrt() } else { p.radius };
        r.clamp(p.min_radius.min(p.radius), p.radius)
    }

    /// Adds a chart of radius `radius` in state `state` (an open chart beyond the auxiliary
    /// bounds becomes [`ChartState::OutOfBounds`]), links it with its parent and with every chart
    /// it neighbours, and crops the polytopes of each linked pair by the bisector of their
    /// centres. Returns its index.
    fn add_chart(&mut self, centre: Vec<f64>, basis: DMatrix<f64>, parent: Option<usize>, radius: f64, state: ChartState) -> usize {
        let k = basis.ncols();
        let state = if state == ChartState::Open && !self.manifold.within_bounds(&centre) { ChartState::OutOfBounds } else { state };
        let j = self.charts.len();
        let polytope = Polytope::cube(k, 1.01 * radius);
        self.charts.push(Chart { centre, basis, polytope, neighbours: Vec::new(), radius, state });
        let near: Vec<usize> = (0..j)
            .filter(|&c| {
                let d = self.diff(&self.charts[j].centre, &self.charts[c].centre);
                let reach = self.charts[c].radius + radius;
                d.iter().map(|a| a * a).sum::<f64>() < reach * reach
            })
            .collect();
        for c in near {
            if Some(c) == parent || (self.same_sheet(c, j) && self.same_sheet(j, c)) {
                self.link(c, j);
            }
        }
        j
    }

    /// Whether chart `c`'s map reaches chart `j`'s centre: projecting from the tangent point of
    /// x_j converges to x_j itself (and not to another sheet of the manifold that passes close by)
    /// with x_j within ε of c's tangent space.
    fn same_sheet(&self, c: usize, j: usize) -> bool {
        let xj = &self.charts[j].centre;
        let t = self.coordinates(c, xj);
        let predicted = self.predict(c, &t);
        let off = self.diff(xj, &predicted).iter().map(|a| a * a).sum::<f64>().sqrt();
        if off > self.params.epsilon {
            return false;
        }
        self.project(c, &t, &predicted).is_some_and(|x| self.diff(&x, xj).iter().all(|d| d.abs() < SAME_POINT))
    }

    /// Records `a` and `b` as neighbours and crops each polytope by the other's ball.
    fn link(&mut self, a: usize, b: usize) {
        for (p, q) in [(a, b), (b, a)] {
            let t = self.coordinates(p, &self.charts[q].centre);
            let half = 0.5 * t.iter().map(|v| v * v).sum::<f64>();
            self.charts[p].polytope.cut(&t, half);
            self.charts[p].neighbours.push(q);
        }
    }

    /// The tangent coordinates of `x` in chart `c` if x is in the chart's ball and on the chart's
    /// sheet (the chart's map at those coordinates gives x back).
    pub fn locate(&self, c: usize, x: &[f64]) -> Option<Vec<f64>> {
        let t = self.coordinates(c, x);
        if t.iter().map(|v| v * v).sum::<f64>() > self.charts[c].radius * self.charts[c].radius {
            return None;
        }
        let predicted = self.predict(c, &t);
        let off = self.diff(x, &predicted).iter().map(|a| a * a).sum::<f64>().sqrt();
        let back = self.project(c, &t, &predicted)?;
        (off <= self.params.epsilon && self.diff(&back, x).iter().all(|d| d.abs() < SAME_POINT)).then_some(t)
    }

    /// A dense path in chart `c` from its centre to tangent coordinates `to`: points of the
    /// manifold on the chart's map of the straight tangent segment, each one projected from the
    /// previous (so the path follows one sheet), consecutive points at most δ apart in the
    /// manifold's distance and never jumping (ambient step ≤ 3 × tangent step); a rejected step is
    /// halved. `None` if the map cannot be followed: a step would fall below 1e-9, or the walk
    /// would exceed its projection cap (WALK_FACTOR · nominal steps + WALK_SLACK, so a walk's work
    /// is bounded). The first point is the centre.
    pub fn walk(&self, c: usize, to: &[f64]) -> Option<Vec<Vec<f64>>> {
        let delta = self.params.delta;
        let len = to.iter().map(|a| a * a).sum::<f64>().sqrt();
        let mut points = vec![self.charts[c].centre.clone()];
        let mut lambda = 0.0;
        let mut h = if len > 0.0 { (delta / len).min(1.0) } else { 1.0 };
        let cap = WALK_FACTOR * (1.0 / h).ceil() as usize + WALK_SLACK;
        for _ in 0..cap {
            if lambda >= 1.0 {
                break;
            }
            let next = (lambda + h).min(1.0);
            let u: Vec<f64> = to.iter().map(|a| a * next).collect();
            let prev = points.last()?;
            let du: Vec<f64> = to.iter().map(|a| a * (next - lambda)).collect();
            let step = &self.charts[c].basis * DVector::from_column_slice(&du);
            let guess: Vec<f64> = prev.iter().zip(step.iter()).map(|(a, b)| a + b).collect();
            let accepted = self.project(c, &u, &guess).filter(|x| {
                let jump = self.diff(x, prev).iter().map(|a| a * a).sum::<f64>().sqrt();
                jump <= 3.0 * len * (next - lambda) + 1e-9 && self.manifold.distance(x, prev) <= delta
            });
            match accepted {
                Some(x) => {
                    points.push(x);
                    lambda = next;
                }
                None => {
                    h *= 0.5;
                    if h * len < 1e-9 {
                        return None;
                    }
                }
            }
        }
        (lambda >= 1.0).then_some(points)
    }

    /// A dense path from chart `a`'s centre to neighbouring chart `b`'s centre: a walk in `a` to
    /// the midpoint of their tangent segment, then a walk in `b` from its centre to that midpoint
    /// point, reversed. `None` if the two walks do not meet at the same point of the manifold.
    pub fn edge(&self, a: usize, b: usize) -> Option<Vec<Vec<f64>>> {
        let t: Vec<f64> = self.coordinates(a, &self.charts[b].centre).iter().map(|v| 0.5 * v).collect();
        let mut first = self.walk(a, &t)?;
        let mid = first.last()?.clone();
        let back = self.walk(b, &self.coordinates(b, &mid))?;
        if !self.diff(back.last()?, &mid).iter().all(|d| d.abs() < SAME_POINT) {
            return None;
        }
        first.extend(back.into_iter().rev().skip(1));
        Some(first)
    }
}

/// An orthonormal basis (n × k) of the null space of an m × n Jacobian of rank m, by
/// Gram–Schmidt with pivoting on the columns of I − QQᵀ (Q from a QR of Jᵀ); `None` if the
/// Jacobian is rank-deficient.
pub fn tangent_basis(jac: &DMatrix<f64>) -> Option<DMatrix<f64>> {
    let (m, n) = jac.shape();
    let k = n.checked_sub(m)?;
    let qr = jac.transpose().qr();
    let r = qr.r();
    let rmax = (0..m).fold(0.0f64, |a, i| a.max(r[(i, i)].abs()));
    if (0..m).any(|i| !(r[(i, i)].abs() > 1e-10 * rmax.max(1e-300))) {
        return None;
    }
    let q = qr.q();
    let mut cols: Vec<DVector<f64>> = (0..n)
        .map(|j| {
            let mut e = DVector::zeros(n);
            e[j] = 1.0;
            let proj = &q * (q.transpose() * &e);
            e - proj
        })
        .collect();
    let mut basis = DMatrix::zeros(n, k);
    for col in 0..k {
        let best = (0..cols.len()).max_by(|&a, &b| cols[a].norm().total_cmp(&cols[b].norm()))?;
        let mut v = cols.swap_remove(best);
        for prev in 0..col {
            let p = basis.column(prev).into_owned();
            v -= &p * p.dot(&v);
        }
        let norm = v.norm();
        if !(norm > 1e-8) {
            return None;
        }
        v /= norm;
        for other in cols.iter_mut() {
            let d = v.dot(other);
            *other -= &v * d;
        }
        basis.set_column(col, &v);
    }
    Some(basis)
}
