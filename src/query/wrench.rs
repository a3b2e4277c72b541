//! Per-pose wrench feasibility (Bohigas et al. §3): the tension ranges of a robot with as many
//! cables as degrees of freedom, wrench closure, and the wrench set inside the available wrench
//! set for any number of cables.
//!
//! A point-mass or planar robot balances only some of the six wrench components
//! ([`crate::model::Mobility::rows`]): its structure matrix has those rows (n = 3), and every
//! test below works in that n-dimensional wrench space; wrenches and facet normals are passed and
//! returned as 6-vectors, the components not balanced ignored (normals zero there).
//!
//! The structure matrix J has one column per cable, [e_i ; (x_i − c) × e_i], where e_i is the unit
//! vector from the base anchor to the platform anchor x_i and c the wrench's application point.
//! Tensions f ≥ 0 pull the platform towards the base anchors and balance the applied wrench when
//! J f = w. Over the ellipsoid W the tensions form the ellipsoid f0 + J⁻¹(w − w0), so cable i
//! ranges over f0,i ± v_ii with f0 = J⁻¹ w0 and v_ii = sqrt((J⁻¹ E⁻¹ J⁻ᵀ)_ii).

pub use super::facets::{binomial, facet_normal, subsets, SINGULAR_RATIO};
use crate::model::{Pose, Robot, Wrench};
use super::lp::{maximise, LpResult};
use crate::model::Bounds;
use nalgebra::{DMatrix, DVector, Matrix6, Vector3, Vector6};

/// The components `rows` of the 6-D wrench `w`.
pub fn select(w: &Vector6<f64>, rows: &[usize]) -> DVector<f64> {
    DVector::from_iterator(rows.len(), rows.iter().map(|&r| w[r]))
}

/// The rows and columns `rows` of the 6 × 6 matrix `m` (an ellipsoid's shape in those
/// components).
pub fn select_square(m: &Matrix6<f64>, rows: &[usize]) -> DMatrix<f64> {
    DMatrix::from_fn(rows.len(), rows.len(), |a, b| m[(rows[a], rows[b])])
}

/// The 6-D wrench with components `rows` from `v` (as many), zero elsewhere.
pub fn embed(v: &DVector<f64>, rows: &[usize]) -> Vector6<f64> {
    let mut w = Vector6::zeros();
    for (k, &r) in rows.iter().enumerate() {
        w[r] = v[k];
    }
    w
}

/// The structure matrix of `robot` at `pose` with moments about `point`.
pub fn structure_matrix(robot: &Robot, pose: &Pose, point: &Vector3<f64>) -> Matrix6<f64> {
    let cables: Vec<_> = robot.cables.iter().take(6).map(|c| (c.base, pose.transform(&c.platform))).collect();
    structure_matrix_of(&cables, point)
}

/// The structure matrix of the first six (base anchor, platform anchor) pairs, in the world
/// frame, with moments about `point`.
pub fn structure_matrix_of(cables: &[(Vector3<f64>, Vector3<f64>)], point: &Vector3<f64>) -> Matrix6<f64> {
    let mut j = Matrix6::zeros();
    for (i, &(base, x)) in cables.iter().take(6).enumerate() {
        j.set_column(i, &column(base, x, point));
    }
    j
}

/// One column of the structure matrix: [e ; (x − c) × e], e the unit vector from the base anchor
/// to the platform anchor x.
fn column(base: Vector3<f64>, x: Vector3<f64>, point: &Vector3<f64>) -> Vector6<f64> {
    let d = x - base;
    let e = d / d.norm();
    let m = (x - point).cross(&e);
    Vector6::new(e.x, e.y, e.z, m.x, m.y, m.z)
}

/// The n×m structure matrix of any number of cables: the wrench components `rows` (all six for
/// a spatial platform) of each column.
pub fn structure_matrix_m(cables: &[(Vector3<f64>, Vector3<f64>)], point: &Vector3<f64>, rows: &[usize]) -> DMatrix<f64> {
    let mut j = DMatrix::zeros(rows.len(), cables.len());
    for (i, &(base, x)) in cables.iter().enumerate() {
        let c = column(base, x, point);
        for (r, &row) in rows.iter().enumerate() {
            j[(r, i)] = c[row];
        }
    }
    j
}

/// Wrench closure at one pose (m > n cables, n the wrench components `rows`): J has rank n and,
/// for every n − 1 columns S spanning a hyperplane, the other columns lie strictly on both sides
/// of it — equivalently, a strictly positive tension vector lies in J's null space. Determinants
/// below [`SINGULAR_RATIO`] times the product of the columns' norms count as zero.
pub fn closure_holds(cables: &[(Vector3<f64>, Vector3<f64>)], point: &Vector3<f64>, rows: &[usize]) -> bool {
    positively_spans(&structure_matrix_m(cables, point, rows))
}

/// Whether the columns of the n×m matrix `j` positively span ℝⁿ: rank n and, for every n − 1
/// columns S spanning a hyperplane, the other columns lie strictly on both sides of it.
/// Determinants below [`SINGULAR_RATIO`] times the product of the columns' norms count as zero.
pub fn positively_spans(j: &DMatrix<f64>) -> bool {
    let (n, m) = j.shape();
    if n == 0 || m <= n {
        return false;
    }
    let norms: Vec<f64> = (0..m).map(|i| j.column(i).norm()).collect();
    let det_of = |cols: &[usize]| {
        let a = DMatrix::from_fn(n, n, |r, c| j[(r, cols[c])]);
        let scale: f64 = cols.iter().map(|&k| norms[k]).product();
        let d = a.determinant();
        if d.abs() > SINGULAR_RATIO * scale { d.signum() } else { 0.0 }
    };
    let mut full_rank = false;
    let mut s = vec![0usize; n];
    for subset in subsets(m, n - 1) {
        s[..n - 1].copy_from_slice(&subset);
        let (mut pos, mut neg) = (false, false);
        for k in (0..m).filter(|k| !subset.contains(k)) {
            s[n - 1] = k;
            let d = det_of(&s);
            pos |= d > 0.0;
            neg |= d < 0.0;
        }
        if pos || neg {
            full_rank = true;
            if !(pos && neg) {
                return false;
            }
        }
    }
    full_rank
}

/// Static feasibility of the wrench `w0` at one pose (any number of cables; its components
/// `rows`): the largest t such that tensions with f_min + t ≤ f ≤ f_max − t balance w0
/// (J f = w0), found by a linear program, and those tensions. Feasible (strictly within the
/// bounds) iff t > 0. `None` if no tensions at all balance w0 (J f = w0 has no solution).
pub fn static_margin(cables: &[(Vector3<f64>, Vector3<f64>)], point: &Vector3<f64>, w0: &Vector6<f64>, bounds: &[Bounds], rows: &[usize]) -> Option<(f64, Vec<f64>)> {
    static_margin_of(&structure_matrix_m(cables, point, rows), &select(w0, rows), bounds)
}

/// [`static_margin`] for the structure matrix `j` (n×m) itself and the n components of `w0`.
pub fn static_margin_of(j: &DMatrix<f64>, w0: &DVector<f64>, bounds: &[Bounds]) -> Option<(f64, Vec<f64>)> {
    let (n, m) = j.shape();
    // f = f_min + t·1 + g with g ≥ 0 and t = tp − tn; rows: J g + J1 (tp − tn) = w0 − J f_min;
    // g_k + 2 (tp − tn) + s_k = f_max,k − f_min,k for finite f_max; tp + s = CAP.
    let finite: Vec<usize> = (0..m).filter(|&k| bounds[k].max.is_finite()).collect();
    let cap = bounds.iter().map(|b| b.min.abs() + if b.max.is_finite() { b.max.abs() } else { 0.0 }).sum::<f64>() + w0.amax() + 1.0;
    let nvar = m + 2 + finite.len() + 1;
    let rows = n + finite.len() + 1;
    let mut a = DMatrix::zeros(rows, nvar);
    let mut b = DVector::zeros(rows);
    let fmin = DVector::from_iterator(m, bounds.iter().map(|b| b.min));
    let rhs = w0 - j * &fmin;
    let ones = j.column_sum();
    for r in 0..n {
        for k in 0..m {
            a[(r, k)] = j[(r, k)];
        }
        a[(r, m)] = ones[r];
        a[(r, m + 1)] = -ones[r];
        b[r] = rhs[r];
    }
    for (i, &k) in finite.iter().enumerate() {
        let r = n + i;
        a[(r, k)] = 1.0;
        a[(r, m)] = 2.0;
        a[(r, m + 1)] = -2.0;
        a[(r, m + 2 + i)] = 1.0;
        b[r] = bounds[k].max - bounds[k].min;
    }
    a[(rows - 1, m)] = 1.0;
    a[(rows - 1, nvar - 1)] = 1.0;
    b[rows - 1] = cap;
    let mut c = DVector::zeros(nvar);
    c[m] = 1.0;
    c[m + 1] = -1.0;
    match maximise(&a, &b, &c) {
        LpResult::Optimal { x, value } => Some((value, (0..m).map(|k| bounds[k].min + value + x[k]).collect())),
        LpResult::Infeasible | LpResult::Unbounded => None,
    }
}

/// A wrench direction y (|y_i| ≤ 1) that shows `w0` unbalanced by tensions within their bounds
/// at the structure matrix `j` (n×m, `w0` its n components): y·w0 exceeds the support Σ_k max(f_min,k y·j_k,
/// f_max,k y·j_k) of the zonotope {J f : f_min ≤ f ≤ f_max} (with an infinite f_max, y·j_k ≤ 0).
/// Found by a linear program (the dual of the static-feasibility program); returns y and its
/// excess as the program computed it (the caller re-checks it), or `None` when no direction has
/// a positive excess (w0 lies in the zonotope).
pub fn separating_direction(j: &DMatrix<f64>, w0: &DVector<f64>, bounds: &[Bounds]) -> Option<(DVector<f64>, f64)> {
    let (n, m) = j.shape();
    // max(f_min a, f_max a) = f_min a + (f_max − f_min) max(a, 0), a = y·j_k: with v_k ≥ a_k,
    // v_k ≥ 0 (v_k − a_k − s_k = 0), maximise y·w0 − Σ_k (f_min,k a_k + (f_max,k − f_min,k) v_k);
    // an infinite f_max needs a_k ≤ 0 instead (a_k + s_k = 0).
    // variables: y⁺ (n), y⁻ (n), v (m), s (m), p (n), q (n), all ≥ 0; y = y⁺ − y⁻, y⁺ + p = 1, y⁻ + q = 1
    let (yp, yn, v, sl, pp, qq) = (0, n, 2 * n, 2 * n + m, 2 * n + 2 * m, 3 * n + 2 * m);
    let nvar = 4 * n + 2 * m;
    let rows = m + 2 * n;
    let mut a = DMatrix::zeros(rows, nvar);
    let mut b = DVector::zeros(rows);
    let mut c = DVector::zeros(nvar);
    for r in 0..n {
        c[yp + r] = w0[r];
        c[yn + r] = -w0[r];
    }
    for k in 0..m {
        let finite = bounds[k].max.is_finite();
        if finite {
            a[(k, v + k)] = 1.0;
            a[(k, sl + k)] = -1.0;
            c[v + k] = -(bounds[k].max - bounds[k].min);
        } else {
            a[(k, sl + k)] = 1.0;
        }
        let sign = if finite { -1.0 } else { 1.0 };
        for r in 0..n {
            let d = j[(r, k)];
            a[(k, yp + r)] = sign * d;
            a[(k, yn + r)] = -sign * d;
            // −f_min a_k in the objective
            c[yp + r] -= bounds[k].min * d;
            c[yn + r] += bounds[k].min * d;
        }
    }
    box_rows(&mut a, &mut b, m, n, [yp, yn, pp, qq]);
    // an excess within the program's rounding is none
    let size = w0.amax() + j.amax() * bounds.iter().map(|b| b.min.abs().max(if b.max.is_finite() { b.max.abs() } else { 0.0 })).sum::<f64>();
    match maximise(&a, &b, &c) {
        LpResult::Optimal { x, value } if value > 1e-12 * (1.0 + size) => Some((DVector::from_fn(n, |r, _| x[yp + r] - x[yn + r]), value)),
        _ => None,
    }
}

/// Rows `row .. row + 2n` of a direction program in n dimensions: y⁺ + p = 1 and y⁻ + q = 1 per
/// component (|y_i| ≤ 1 for y = y⁺ − y⁻), the variables' first columns given as `[y⁺, y⁻, p, q]`.
fn box_rows(a: &mut DMatrix<f64>, b: &mut DVector<f64>, row: usize, n: usize, [yp, yn, pp, qq]: [usize; 4]) {
    for r in 0..n {
        a[(row + r, yp + r)] = 1.0;
        a[(row + r, pp + r)] = 1.0;
        b[row + r] = 1.0;
        a[(row + n + r, yn + r)] = 1.0;
        a[(row + n + r, qq + r)] = 1.0;
        b[row + n + r] = 1.0;
    }
}

/// A direction y (|y_i| ≤ 1) with every column of `j` (n×m) strictly on its negative side:
/// y·j_k ≤ −s < 0 for all k, with the largest such s (a linear program). It shows that no
/// strictly positive tensions balance zero: wrench closure fails, robustly. `None` when no
/// direction has s above the program's rounding.
pub fn enclosing_direction(j: &DMatrix<f64>) -> Option<DVector<f64>> {
    let (n, m) = j.shape();
    // variables: y⁺ (n), y⁻ (n), s, slacks (m), p (n), q (n), s's cap slack; rows: y·j_k + s +
    // slack_k = 0, y⁺ + p = 1, y⁻ + q = 1, s + cap = 1
    let (yp, yn, sv, sl) = (0, n, 2 * n, 2 * n + 1);
    let (pp, qq, cap) = (sl + m, sl + m + n, sl + m + 2 * n);
    let nvar = cap + 1;
    let rows = m + 2 * n + 1;
    let mut a = DMatrix::zeros(rows, nvar);
    let mut b = DVector::zeros(rows);
    for k in 0..m {
        for r in 0..n {
            a[(k, yp + r)] = j[(r, k)];
            a[(k, yn + r)] = -j[(r, k)];
        }
        a[(k, sv)] = 1.0;
        a[(k, sl + k)] = 1.0;
    }
    box_rows(&mut a, &mut b, m, n, [yp, yn, pp, qq]);
    a[(m + 2 * n, sv)] = 1.0;
    a[(m + 2 * n, cap)] = 1.0;
    b[m + 2 * n] = 1.0;
    let mut c = DVector::zeros(nvar);
    c[sv] = 1.0;
    match maximise(&a, &b, &c) {
        LpResult::Optimal { x, value } if value > 1e-12 * (1.0 + j.amax()) => Some(DVector::from_fn(n, |r, _| x[yp + r] - x[yn + r])),
        _ => None,
    }
}

/// Wrench closure at one pose by linear programs, for any number of cables: J (n×m) of rank n
/// (its least singular value above [`SINGULAR_RATIO`] of its largest) and tensions f ≥ 1 with
/// J f = 0 (then a strictly positive null vector exists, and J's columns positively span ℝⁿ).
pub fn closure_by_lp(j: &DMatrix<f64>) -> bool {
    let sv = j.clone().svd(false, false).singular_values;
    let unit = vec![Bounds { min: 1.0, max: f64::INFINITY }; j.ncols()];
    j.ncols() >= j.nrows() && sv.min() > SINGULAR_RATIO * sv.max() && static_margin_of(j, &DVector::zeros(j.nrows()), &unit).is_some_and(|(t, _)| t >= 0.0)
}

/// Tension range of one cable over the wrench set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TensionRange {
    /// Tension balancing the nominal wrench, f0,i.
    pub nominal: f64,
    /// Half-width v_ii of the range over the ellipsoid.
    pub spread: f64,
}

/// The tension ranges of the cables of a robot with as many cables as degrees of freedom (six
/// on a spatial platform, three on a point mass or a planar platform) at `pose` over the wrench
/// set alone (no weight or inertia of the platform), or `None` at a singular pose (J not
/// invertible to within [`SINGULAR_RATIO`]).
pub fn tension_ranges(robot: &Robot, pose: &Pose, wrench: &Wrench) -> Option<Vec<TensionRange>> {
    let cables = robot.anchors(pose);
    tension_ranges_at(&cables, &wrench.point_at(pose), &wrench.nominal, wrench, robot.mobility.rows())
}

/// The tension ranges from the cables' world anchors and the wrench's application point, for the
/// ellipsoid of `wrench` around `nominal` (the wrench set's own nominal wrench, or that plus the
/// platform's weight and inertia), in the wrench components `rows`; `None` also when there are
/// not exactly as many cables as components.
pub fn tension_ranges_at(cables: &[(Vector3<f64>, Vector3<f64>)], point: &Vector3<f64>, nominal: &Vector6<f64>, wrench: &Wrench, rows: &[usize]) -> Option<Vec<TensionRange>> {
    let n = rows.len();
    if cables.len() != n {
        return None;
    }
    let j = structure_matrix_m(cables, point, rows);
    let scale: f64 = (0..n).map(|i| j.column(i).norm()).product();
    let lu = j.lu();
    if !(lu.determinant().abs() > SINGULAR_RATIO * scale) {
        return None;
    }
    let inv = lu.try_inverse()?;
    let f0 = &inv * select(nominal, rows);
    let v = &inv * select_square(&wrench.ellipsoid_inv, rows) * inv.transpose();
    Some((0..n).map(|i| TensionRange { nominal: f0[i], spread: v[(i, i)].max(0.0).sqrt() }).collect())
}

/// Hyperplane shifting (Gouttefarde & Gosselin; Bouchard et al.): the zonotope
/// Z(t) = {J f : f_min + t ≤ f ≤ f_max − t} has a facet pair for every set S of five columns (n − 1
/// in the n wrench components `rows` of a point-mass or planar robot)
/// spanning a hyperplane, with normal n_S (the cofactors of [J_S | x], so n_S·x = det [J_S | x])
/// and support h(±n_S) = Σ_k max(±d_k (f_min,k + t), ±d_k (f_max,k − t)), d_k = n_S·j_k. The
/// ellipsoid W = {w : (w − w0)ᵀE(w − w0) ≤ 1} lies in Z(t) iff for every S,
/// |n_S·w0| + √(n_Sᵀ E⁻¹ n_S) stays inside on both sides; each side is linear in t, so the
/// largest t is the least over facets of (h(±n_S) at t = 0 ∓ n_S·w0 − √(n_Sᵀ E⁻¹ n_S)) / Σ_k |d_k|,
/// and at most half the narrowest finite tension range (the shrunk box is empty beyond).
/// The result is that largest t: every wrench of W is balanced within [f_min + t, f_max − t], so
/// the pose is wrench-feasible iff t > 0; for a single wrench (E⁻¹ = 0) it is the
/// static-feasibility LP's margin. Any number of cables ≥ n: up to
/// [`super::facets::MAX_FACETS`] facet pairs each is tested, beyond that the same
/// margin comes from the branch and bound over wrench directions of [`super::zonotope::margin`]
/// (to 1e-9 of the largest finite tension bound). `None` when J has rank below n (no facet has
/// columns off its hyperplane, or some hyperplane holds them all): W, or w0, is then balanced
/// nowhere but on that hyperplane, reported as singular.
pub fn wrench_set_margin(cables: &[(Vector3<f64>, Vector3<f64>)], point: &Vector3<f64>, nominal: &Vector6<f64>, ellipsoid_inv: &Matrix6<f64>, bounds: &[Bounds], rows: &[usize]) -> Option<f64> {
    let j = structure_matrix_m(cables, point, rows);
    if binomial(j.ncols(), rows.len() - 1) > super::facets::MAX_FACETS {
        return cover_margin(&j, &select(nominal, rows), &select_square(ellipsoid_inv, rows), bounds);
    }
    let facets = facets(&j, rows, bounds)?;
    let best = facets
        .iter()
        .map(|f| {
            let reach = (f.normal.dot(&(ellipsoid_inv * f.normal))).max(0.0).sqrt();
            let centre = f.normal.dot(nominal);
            // n·w ≤ upper and n·w ≥ lower for every w of W, with the box shrunk by t
            ((f.upper - centre).min(centre - f.lower) - reach) / f.spread
        })
        .fold(f64::INFINITY, f64::min);
    // past half the narrowest finite tension range the shrunk box is empty
    let half = bounds.iter().filter(|b| b.max.is_finite()).map(|b| 0.5 * (b.max - b.min)).fold(f64::INFINITY, f64::min);
    (!facets.is_empty()).then_some(best.min(half))
}

/// Most cuts of the directions one pose's margin may take ([`super::zonotope::margin`]).
const MARGIN_CUTS: usize = 200_000;

/// The margin of the ellipsoid around `nominal` with shape `ellipsoid_inv` (both in the rows of
/// `j`) inside the available wrench set of `j`, by the branch and bound over wrench directions:
/// its certified lower end where the bracket leaves the sign open (out of cuts), else the value
/// at the worst direction found.
fn cover_margin(j: &DMatrix<f64>, nominal: &DVector<f64>, ellipsoid_inv: &DMatrix<f64>, bounds: &[Bounds]) -> Option<f64> {
    let scale = bounds.iter().flat_map(|b| [b.min.abs(), if b.max.is_finite() { b.max.abs() } else { 0.0 }]).fold(1e-300, f64::max);
    let problem = super::zonotope::Containment { j, bounds, centre: nominal, shape: ellipsoid_inv };
    let m = super::zonotope::margin(&problem, 1e-9 * scale, MARGIN_CUTS)?;
    Some(if m.hi > 0.0 { m.lo } else { m.hi })
}

/// One facet pair of the zonotope {J f : f_min ≤ f ≤ f_max} ([`wrench_set_margin`]): the wrenches
/// w with `lower` ≤ n·w ≤ `upper`, n the hyperplane's normal; shrinking the tension box by t
/// moves both sides inward by t·`spread`.
#[derive(Debug, Clone, PartialEq)]
pub struct Facet {
    /// Which n − 1 columns: the index of the set in [`subsets`]`(m, n − 1)`'s order.
    pub set: usize,
    /// n_S, the cofactors of [J_S | x], as a 6-D wrench (zero in the components not balanced).
    pub normal: Vector6<f64>,
    /// The least n·J f over the tension box.
    pub lower: f64,
    /// The greatest n·J f over the tension box.
    pub upper: f64,
    /// Σ_k |n·j_k| over the columns off the hyperplane.
    pub spread: f64,
}

/// The facet pairs of the zonotope {J f : f_min ≤ f ≤ f_max} of the n×m structure matrix `j` of
/// the wrench components `rows` (C(m, n − 1) candidate sets of n − 1 columns; those not spanning a
/// hyperplane are skipped), or `None` when J has rank below n (some hyperplane holds every
/// column).
pub fn facets(j: &DMatrix<f64>, rows: &[usize], bounds: &[Bounds]) -> Option<Vec<Facet>> {
    let m = j.ncols();
    let norms: Vec<f64> = (0..m).map(|i| j.column(i).norm()).collect();
    let mut out = Vec::new();
    for (set, s) in subsets(m, j.nrows() - 1).into_iter().enumerate() {
        let n = facet_normal(j, &s);
        let scale: f64 = s.iter().map(|&k| norms[k]).product();
        if !(n.norm() > SINGULAR_RATIO * scale) {
            continue; // the five columns do not span a hyperplane
        }
        let (mut lower, mut upper, mut spread) = (0.0, 0.0, 0.0);
        for k in (0..m).filter(|k| !s.contains(k)) {
            let d = n.dot(&j.column(k));
            if d.abs() <= SINGULAR_RATIO * scale * norms[k] {
                continue;
            }
            let (a, b) = (d * bounds[k].min, d * bounds[k].max);
            lower += a.min(b);
            upper += a.max(b);
            spread += d.abs();
        }
        if spread == 0.0 {
            return None; // every column on this hyperplane: rank 5
        }
        out.push(Facet { set, normal: embed(&n, rows), lower, upper, spread });
    }
    Some(out)
}

#[cfg(test)]
mod separating_tests {
    use super::*;

    /// Random 6×m matrices and loads: a direction is found exactly when the static margin is
    /// negative, and it separates: y·w0 above the zonotope's support.
    #[test]
    fn a_separating_direction_exists_iff_the_margin_is_negative() {
        let mut seed = 7u64;
        let mut rnd = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        let (mut found, mut none) = (0, 0);
        for round in 0..300 {
            // six rows (a spatial platform) or three (a point mass, a planar platform)
            let n = if round % 3 == 0 { 3 } else { 6 };
            let m = n + 1 + (rnd().abs() * 10.0) as usize;
            let j = DMatrix::from_fn(n, m, |_, _| rnd());
            let w0 = DVector::from_fn(n, |_, _| 1.5 * rnd());
            let bounds: Vec<Bounds> = (0..m).map(|_| Bounds { min: 0.1, max: 2.0 }).collect();
            let (t, f) = static_margin_of(&j, &w0, &bounds).expect("full rank");
            let f = DVector::from_vec(f);
            let residual = (&j * &f - &w0).amax();
            assert!(residual < 1e-9 * (1.0 + w0.amax()), "the margin's tensions leave J f = w0 by {residual} (margin {t})");
            assert!(f.iter().all(|x| *x >= 0.1 + t - 1e-9 && *x <= 2.0 - t + 1e-9), "tensions {f} outside the box shrunk by {t}");
            match separating_direction(&j, &w0, &bounds) {
                Some((y, excess)) => {
                    let support: f64 = (0..m).map(|k| {
                        let d = y.dot(&j.column(k));
                        (d * 0.1).max(d * 2.0)
                    }).sum();
                    assert!((y.dot(&w0) - support - excess).abs() < 1e-9 * (1.0 + excess), "excess {excess} vs {}", y.dot(&w0) - support);
                    assert!(t < 1e-9, "separated, yet margin {t}");
                    found += 1;
                }
                None => {
                    assert!(t > -1e-9, "margin {t} but no direction");
                    none += 1;
                }
            }
        }
        assert!(found > 30 && none > 30, "{found} separated, {none} not");
    }
}
