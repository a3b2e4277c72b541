//! Timed trajectories of robots with mass: exact dynamic sections against dense sampling of an
//! independent per-pose reference, the least time scale against the reference's own, and the
//! per-pose wrench-set test of six cables against paper 1's.
//!
//! The reference (below) is written from the definitions, sharing nothing with the core's
//! conditions: the pose from the test-support model (direct slerp, τ(t)); velocities and
//! accelerations by 5-point finite differences of that pose (ω and α from the skew parts of ṘRᵀ
//! and R̈Rᵀ); the required wrench by Newton–Euler about the centre of mass; J from its definition;
//! then for six cables J⁻¹ (f0 ± v), and for more a linear program (largest t with J f = w,
//! f_min + t ≤ f ≤ f_max − t) — with an ellipsoid, "infeasible" when a sampled direction u has
//! u·w + √(uᵀE⁻¹u) beyond the zonotope's support Σ_k max(f_min u·j_k, f_max u·j_k), "feasible"
//! when the LP's tensions plus a pseudo-inverse correction stay inside for the whole ellipsoid
//! (sufficient), undecided (skipped) otherwise. Winch limits from the cable vectors' finite
//! differences (the position's and the rotation's taken apart, so that a platform turning in
//! place far from the origin keeps its rounding small).

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

mod support;

use cablenav::model::{Bounds, Mobility};
use cablenav::query::wrench::{tension_ranges_at, wrench_set_margin};
use cablenav::verify::verify_trajectory;
use cablenav::Scenario;
use nalgebra::{DMatrix, DVector, Matrix3, Matrix6, Vector3, Vector6};
use support::{env_usize, lone_boundaries, reported};
use support::lp::lp_margin;
use support::reference::*;

#[cfg(not(target_arch = "wasm32"))]
const CASES: usize = 300;
#[cfg(target_arch = "wasm32")]
const CASES: usize = 40;
#[cfg(not(target_arch = "wasm32"))]
const SAMPLES: usize = 2_000;
#[cfg(target_arch = "wasm32")]
const SAMPLES: usize = 400;

/// Up to this many cables the reference enumerates every facet pair of the available wrench set
/// (C(15, 5) = 3003) and takes the sign of the ellipsoid's margin as its verdict; beyond, sampled
/// directions (necessary) and the pseudo-inverse's tensions (sufficient).
const EXACT_ELLIPSOID_CABLES: usize = 15;

/// Finite-difference step in t (5-point stencils: truncation ~h⁴, rounding ~1e-16/h²).
const H: f64 = 1e-3;

/// The step along a time-optimal law, whose acceleration jumps from cell to cell: the stencils
/// stay inside one cell (rounding ~1e-6 relative, hence the wider [`TIMED_EPS`]).
const TIMED_H: f64 = 1e-5;

/// Relative band around a bound inside which the reference calls a timed sample undecided.
const TIMED_EPS: f64 = 1e-5;

/// A robot with mass, its load and one timed trajectory, as the reference sees them. z points
/// down: gravity is +z, the cables mostly hang from anchors at z = 0 (a planar robot's plane is
/// z = 0 and its gravity is +y).
#[derive(Clone)]
struct Case {
    /// The wrench components the cables balance: all six on a spatial platform, the force on a
    /// point mass, fx, fy and mz on a planar platform.
    mobility: Mobility,
    cables: Vec<(V3, V3)>,
    tension: (f64, f64),
    mass: f64,
    com: V3,
    inertia: Matrix3<f64>,
    gravity: V3,
    /// The wrench set (nominal, E⁻¹, point in the platform frame), if any.
    wrench: Option<(Vector6<f64>, Matrix6<f64>, V3)>,
    /// Winch speed and acceleration limits.
    winch: Option<(f64, f64)>,
    path: Path,
    duration: f64,
    /// Finite-difference step ([`H`], or [`TIMED_H`] along a time-optimal law).
    h: f64,
    /// Relative band around a bound within which a verdict is left undecided.
    eps: f64,
}

/// How the reference moves the platform in t ∈ [0, 1].
#[derive(Clone)]
enum Path {
    /// The thesis' form: translation in τ, slerp in t.
    Slerp(RefTrajectory),
    /// CASPR's spline through knots (times in seconds, poses): [`Spline`].
    Spline(Spline),
    /// Another path run by a time law (`cablenav time`'s): t here is time / duration, and the
    /// path's own t is the law's at that time.
    Timed(Box<Path>, cablenav::plan::timing::TimedPath),
}

/// CASPR's quintic spline as its documentation and `generateTrajectoryQuinticSpline` state it,
/// written here from that statement: between consecutive knots (at rest) the position is the
/// quintic with zero end velocities and accelerations — solved here from its six conditions, not
/// taken from a closed form — and the rotation R_k·Rot(axis, θ·s), axis and θ those of R_kᵀR_(k+1),
/// s the same quintic from 0 to 1.
#[derive(Clone)]
struct Spline {
    times: Vec<f64>,
    poses: Vec<(Vector3<f64>, Matrix3<f64>)>,
}

impl Spline {
    /// The knots of the trajectory `id` in CASPR's trajectories file (relative times, q = x y z
    /// a b g with R = Rx(a)·Ry(b)·Rz(g)), read by scanning the text.
    fn from_caspr(xml: &str, id: &str) -> Spline {
        let start = xml.find(&format!("id=\"{id}\"")).expect("trajectory id");
        let block = &xml[start..start + xml[start..].find("</quintic_spline_trajectory>").unwrap()];
        let (mut times, mut poses) = (vec![], vec![]);
        for point in block.split("<point").skip(2) {
            let time = point.split("time=\"").nth(1).map_or(0.0, |t| t[..t.find('"').unwrap()].parse::<f64>().unwrap());
            let q_text = &point[point.find("<q>").unwrap() + 3..point.find("</q>").unwrap()];
            let q: Vec<f64> = q_text.split_whitespace().map(|v| v.parse().unwrap()).collect();
            let rx = Matrix3::new(1.0, 0.0, 0.0, 0.0, q[3].cos(), -q[3].sin(), 0.0, q[3].sin(), q[3].cos());
            let ry = Matrix3::new(q[4].cos(), 0.0, q[4].sin(), 0.0, 1.0, 0.0, -q[4].sin(), 0.0, q[4].cos());
            let rz = Matrix3::new(q[5].cos(), -q[5].sin(), 0.0, q[5].sin(), q[5].cos(), 0.0, 0.0, 0.0, 1.0);
            times.push(times.last().map_or(0.0, |t: &f64| t + time));
            poses.push((Vector3::new(q[0], q[1], q[2]), rx * ry * rz));
        }
        Spline { times, poses }
    }

    fn duration(&self) -> f64 {
        self.times[self.times.len() - 1]
    }

    /// s(σ): the quintic with s(0) = 0, s(1) = 1 and zero first and second derivatives at both
    /// ends, from its 6×6 system.
    fn rest_to_rest(sigma: f64) -> f64 {
        let rows = [[1.0, 0.0, 0.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 2.0, 0.0, 0.0, 0.0], [1.0; 6], [0.0, 1.0, 2.0, 3.0, 4.0, 5.0], [0.0, 0.0, 2.0, 6.0, 12.0, 20.0]];
        let a = nalgebra::Matrix6::from_fn(|i, j| rows[i][j]);
        let c = a.lu().solve(&Vector6::new(0.0, 0.0, 0.0, 1.0, 0.0, 0.0)).unwrap();
        (0..6).map(|k| c[k] * sigma.powi(k as i32)).sum()
    }

    /// The pose at t ∈ [0, 1] of the whole time.
    fn pose(&self, t: f64) -> (Vector3<f64>, Matrix3<f64>) {
        let time = t.clamp(0.0, 1.0) * self.duration();
        let k = (0..self.times.len() - 1).find(|&k| time <= self.times[k + 1]).unwrap_or(self.times.len() - 2);
        let sigma = (time - self.times[k]) / (self.times[k + 1] - self.times[k]);
        let s = Spline::rest_to_rest(sigma);
        let ((p0, r0), (p1, r1)) = (&self.poses[k], &self.poses[k + 1]);
        let rel = nalgebra::Rotation3::from_matrix_unchecked(r0.transpose() * r1);
        let turn = rel.axis_angle().map_or(Matrix3::identity(), |(axis, angle)| *nalgebra::Rotation3::from_axis_angle(&axis, angle * s).matrix());
        (p0 + (p1 - p0) * s, r0 * turn)
    }
}

fn to_v(v: V3) -> Vector3<f64> {
    Vector3::new(v.x, v.y, v.z)
}

fn to_m(m: &M3) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| m[i][j])
}

fn vee_skew(m: &Matrix3<f64>) -> Vector3<f64> {
    Vector3::new(m[(2, 1)] - m[(1, 2)], m[(0, 2)] - m[(2, 0)], m[(1, 0)] - m[(0, 1)]) * 0.5
}

/// What the reference finds at one t.
struct At {
    /// Least margin (negative: violated) when decided, with a scale for rounding.
    verdict: Option<bool>,
    /// For six cables without winch limits: the largest u = 1/k² that holds here (∞ if any).
    u_max: f64,
    /// The least slack to a bound, relative to it (winch limits) or to the tension range
    /// (tensions: the largest uniform shrink of the tension box that still balances), where
    /// computed: 0 where some constraint is at its bound.
    slack: f64,
}

impl Case {
    fn json(&self) -> String {
        let point = self.mobility == Mobility::Point;
        // a point mass's cables end at the point: no platform anchor
        let cables: Vec<_> = self.cables.iter().map(|(a, b)| if point { serde_json::json!({"base": a.arr()}) } else { serde_json::json!({"base": a.arr(), "platform": b.arr()}) }).collect();
        let inertia: Vec<Vec<f64>> = (0..3).map(|i| (0..3).map(|j| self.inertia[(i, j)]).collect()).collect();
        let Path::Slerp(traj) = &self.path else { unreachable!("spline cases come from CASPR's files") };
        let mut traj = traj.to_json();
        traj["duration"] = serde_json::json!(self.duration);
        let dynamics = if point {
            serde_json::json!({"mass": self.mass, "gravity": self.gravity.arr()})
        } else {
            serde_json::json!({"mass": self.mass, "com": self.com.arr(), "inertia": inertia, "gravity": self.gravity.arr()})
        };
        let mut v = serde_json::json!({
            "format": "cablenav-scenario/5",
            "name": "random timed case",
            "robot": {
                "mobility": self.mobility.name(),
                "cables": cables,
                "tension": {"min": self.tension.0, "max": self.tension.1},
                "dynamics": dynamics,
            },
            "trajectories": [traj],
        });
        if let Some((w0, e_inv, point)) = &self.wrench {
            v["wrench"] = serde_json::json!({"nominal": w0.as_slice(), "point": point.arr(), "point_frame": "platform"});
            // E⁻¹ = 0: the nominal wrench alone (format 4), no ellipsoid
            if e_inv.iter().any(|x| *x != 0.0) {
                let e = e_inv.try_inverse().unwrap();
                let rows: Vec<Vec<f64>> = (0..6).map(|i| (0..6).map(|j| 0.5 * (e[(i, j)] + e[(j, i)])).collect()).collect();
                v["wrench"]["ellipsoid"] = serde_json::json!(rows);
            }
        }
        if let Some((speed, accel)) = self.winch {
            v["robot"]["winch"] = serde_json::json!({"speed": speed, "acceleration": accel});
        }
        v.to_string()
    }

    fn pose(&self, t: f64) -> (Vector3<f64>, Matrix3<f64>) {
        Case::pose_on(&self.path, t)
    }

    fn pose_on(path: &Path, t: f64) -> (Vector3<f64>, Matrix3<f64>) {
        match path {
            Path::Slerp(traj) => {
                let (p, r) = traj.pose(t);
                (to_v(p), to_m(&r))
            }
            Path::Spline(spline) => spline.pose(t),
            Path::Timed(inner, law) => Case::pose_on(inner, law.t_at(t * law.duration())),
        }
    }

    /// f and its first and second derivatives in t by 5-point stencils.
    fn derivatives<T>(&self, t: f64, f: impl Fn(f64) -> T) -> (T, T, T)
    where
        T: std::ops::Add<Output = T> + std::ops::Sub<Output = T> + std::ops::Mul<f64, Output = T> + Copy,
    {
        let h = self.h;
        let (m2, m1, z, p1, p2) = (f(t - 2.0 * h), f(t - h), f(t), f(t + h), f(t + 2.0 * h));
        let d1 = (m2 - p2 + (p1 - m1) * 8.0) * (1.0 / (12.0 * h));
        let d2 = ((p1 + m1) * 16.0 - z * 30.0 - m2 - p2) * (1.0 / (12.0 * h * h));
        (z, d1, d2)
    }

    /// The wrench the cables balance at t run in `duration` (None: at rest) about the wrench
    /// point, and J there.
    fn required(&self, t: f64, duration: Option<f64>) -> (Vector6<f64>, DMatrix<f64>) {
        let com = to_v(self.com);
        let (p, r) = self.pose(t);
        let x_c = p + r * com;
        let point = self.wrench.as_ref().map_or(Vector3::zeros(), |w| to_v(w.2));
        let c = p + r * point;
        let (accel, moment) = match duration {
            None => (Vector3::zeros(), Vector3::zeros()),
            Some(d) => {
                // p and R·c apart: a large p (it may stand still) adds no rounding to R·c's
                let (_, _, p2) = self.derivatives(t, |s| self.pose(s).0);
                let (_, r1, r2) = self.derivatives(t, |s| self.pose(s).1);
                let xc2 = p2 + r2 * com;
                let omega = vee_skew(&(r1 * r.transpose())) / d;
                let alpha = vee_skew(&(r2 * r.transpose())) / (d * d);
                let iw = r * self.inertia * r.transpose();
                (xc2 / (d * d), iw * alpha + omega.cross(&(iw * omega)))
            }
        };
        let force = (to_v(self.gravity) - accel) * self.mass;
        let m = (x_c - c).cross(&force) - moment;
        let nominal = self.wrench.as_ref().map_or(Vector6::zeros(), |w| w.0);
        let w = nominal + Vector6::new(force.x, force.y, force.z, m.x, m.y, m.z);
        let mut j = DMatrix::zeros(6, self.cables.len());
        for (i, (a, b)) in self.cables.iter().enumerate() {
            let x = p + r * to_v(*b);
            let e = (x - to_v(*a)).normalize();
            let mo = (x - c).cross(&e);
            for k in 0..3 {
                j[(k, i)] = e[k];
                j[(k + 3, i)] = mo[k];
            }
        }
        (w, j)
    }

    /// The components the robot balances of the wrench `w` and of J's rows.
    fn project(&self, w: &Vector6<f64>, j: &DMatrix<f64>) -> (DVector<f64>, DMatrix<f64>) {
        let rows = self.mobility.rows();
        (DVector::from_fn(rows.len(), |r, _| w[rows[r]]), DMatrix::from_fn(rows.len(), j.ncols(), |r, k| j[(rows[r], k)]))
    }

    /// The block of E⁻¹ on the components the robot balances.
    fn e_block(&self, e_inv: &Matrix6<f64>) -> DMatrix<f64> {
        let rows = self.mobility.rows();
        DMatrix::from_fn(rows.len(), rows.len(), |a, b| e_inv[(rows[a], rows[b])])
    }

    /// The largest t such that every wrench of the ellipsoid around `w` is balanced by tensions
    /// within [f_min + t, f_max − t]: the ellipsoid inside the polytope {J f} shrunk by t holds
    /// against each of its facets; a facet's normal n is the dual vector of n − 1 columns (the
    /// last row of the inverse of those columns completed by a random n-th).
    fn ellipsoid_margin(&self, j: &DMatrix<f64>, w: &DVector<f64>, e_inv: &DMatrix<f64>) -> f64 {
        if j.ncols() > EXACT_ELLIPSOID_CABLES {
            return f64::INFINITY; // too many facets to enumerate at every sample
        }
        let (dim, m) = j.shape();
        let mut rng = Rng::new(5);
        let mut least = f64::INFINITY;
        let mut subset: Vec<usize> = (0..dim - 1).collect();
        loop {
            let extra = DVector::from_fn(dim, |_, _| rng.normal());
            let square = DMatrix::from_fn(dim, dim, |r, c| if c < dim - 1 { j[(r, subset[c])] } else { extra[r] });
            let scale: f64 = subset.iter().map(|&k| j.column(k).norm()).product::<f64>() * extra.norm();
            if square.determinant().abs() > 1e-9 * scale {
                let inv = square.try_inverse().unwrap();
                let n = DVector::from_fn(dim, |c, _| inv[(dim - 1, c)]).normalize();
                let (mut lower, mut upper, mut spread) = (0.0, 0.0, 0.0);
                for k in (0..m).filter(|k| !subset.contains(k)) {
                    let d = n.dot(&j.column(k));
                    lower += (d * self.tension.0).min(d * self.tension.1);
                    upper += (d * self.tension.0).max(d * self.tension.1);
                    spread += d.abs();
                }
                let reach = n.dot(&(e_inv * &n)).max(0.0).sqrt();
                let centre = n.dot(w);
                least = least.min(((upper - centre).min(centre - lower) - reach) / spread);
            }
            // the next (n − 1)-subset in lexicographic order
            let size = dim - 1;
            let Some(i) = (0..size).rev().find(|&i| subset[i] < m - size + i) else { break };
            subset[i] += 1;
            for k in i + 1..size {
                subset[k] = subset[k - 1] + 1;
            }
        }
        least.min(0.5 * (self.tension.1 - self.tension.0))
    }

    /// The reference at t, run in `duration`.
    fn at(&self, t: f64, duration: f64, rng: &mut Rng) -> At {
        let (w6, j6) = self.required(t, Some(duration));
        let (w, j) = self.project(&w6, &j6);
        let dim = w.len();
        let scale = self.mass * to_v(self.gravity).norm();
        let eps = self.eps * scale;
        let range = self.tension.1 - self.tension.0;
        let mut at = At { verdict: None, u_max: f64::INFINITY, slack: f64::INFINITY };
        // winch limits
        if let Some((speed, accel)) = self.winch {
            // the cable vector's derivatives from p's and R's apart (a small motion far from
            // the origin keeps its rounding small), then the length's: l' = v·v'/l,
            // l'' = (v'·v' + v·v'')/l − (v·v')²/l³
            let ((p, p1, p2), (r, r1, r2)) = (self.derivatives(t, |s| self.pose(s).0), self.derivatives(t, |s| self.pose(s).1));
            for (a, b) in &self.cables {
                let b = to_v(*b);
                let (v, v1, v2) = (p + r * b - to_v(*a), p1 + r1 * b, p2 + r2 * b);
                let l = v.norm();
                let (l1, l2) = (v.dot(&v1) / l, (v1.dot(&v1) + v.dot(&v2)) / l - v.dot(&v1).powi(2) / l.powi(3));
                let (v, acc) = (l1.abs() / duration, l2.abs() / (duration * duration));
                if v > speed * (1.0 + self.eps) || acc > accel * (1.0 + self.eps) {
                    return At { verdict: Some(false), ..at };
                }
                if v > speed * (1.0 - self.eps) || acc > accel * (1.0 - self.eps) {
                    return At { slack: 0.0, ..at }; // too close to call
                }
                at.slack = at.slack.min(1.0 - v / speed).min(1.0 - acc / accel);
            }
        }
        let m = self.cables.len();
        if m == dim {
            let Some(inv) = j.clone().try_inverse().filter(|i| i.amax() < 1e9) else { return at };
            let e_inv = self.e_block(&self.wrench.as_ref().map_or(Matrix6::zeros(), |w| w.1));
            let (w_rest, _) = self.required(t, None);
            let (w_rest, _) = self.project(&w_rest, &j6);
            let mut least = f64::INFINITY;
            for i in 0..dim {
                let g = DVector::from_fn(dim, |k, _| inv[(i, k)]);
                let (f0, f_rest) = (g.dot(&w), g.dot(&w_rest));
                let v = g.dot(&(&e_inv * &g)).max(0.0).sqrt();
                least = least.min(f0 - v - self.tension.0).min(self.tension.1 - f0 - v);
                // linear in u: f(u) = f_rest + u·(f0 − f_rest) at u = 1 for this duration
                let slope = f0 - f_rest;
                for room in [(f_rest - v - self.tension.0, -slope), (self.tension.1 - f_rest - v, slope)] {
                    if room.1 > 0.0 {
                        at.u_max = at.u_max.min(room.0 / room.1);
                    }
                }
            }
            if least.abs() > eps {
                at.verdict = Some(least > 0.0);
            }
            at.slack = at.slack.min(least / range);
            return at;
        }
        let Some((margin, f)) = lp_margin(&j, &w, self.tension) else { return At { verdict: Some(false), ..at } };
        at.slack = at.slack.min(margin / range);
        if margin < -eps {
            return At { verdict: Some(false), ..at };
        }
        let Some((_, e_inv, _)) = &self.wrench else {
            if margin > eps {
                at.verdict = Some(true);
            }
            return at;
        };
        let e_inv = self.e_block(e_inv);
        if e_inv.iter().any(|x| *x != 0.0) {
            let exact = self.ellipsoid_margin(&j, &w, &e_inv);
            at.slack = at.slack.min(exact / range);
            // every facet pair tested (enumerated here up to 15 cables): its sign is the verdict
            // where it clears the band
            if m <= EXACT_ELLIPSOID_CABLES {
                if exact.abs() > eps {
                    at.verdict = Some(exact > 0.0);
                }
                return at;
            }
        }
        // necessary: sampled directions against the zonotope's support function
        for _ in 0..64 {
            let u = DVector::from_fn(dim, |_, _| rng.normal());
            let reach = u.dot(&(&e_inv * &u)).max(0.0).sqrt();
            let support: f64 = (0..m).map(|k| {
                let d = u.dot(&j.column(k));
                (d * self.tension.0).max(d * self.tension.1)
            }).sum();
            if u.dot(&w) + reach > support + self.eps * u.norm() * scale {
                return At { verdict: Some(false), ..at };
            }
        }
        // sufficient: f + J⁺δw within the bounds for every δw of the ellipsoid
        let jt = j.transpose();
        let Some(pinv) = (&j * &jt).try_inverse().map(|x| &jt * x) else { return at };
        let worst = (0..m).map(|k| {
            let row = DVector::from_fn(dim, |c, _| pinv[(k, c)]);
            let reach = row.dot(&(&e_inv * &row)).max(0.0).sqrt();
            (f[k] - reach - self.tension.0).min(self.tension.1 - f[k] - reach)
        }).fold(f64::INFINITY, f64::min);
        if worst > eps {
            at.verdict = Some(true);
        }
        at
    }
}

/// A random robot with 6 to 10 cables and mass, a random load and a random timed trajectory.
fn random_case(rng: &mut Rng) -> Case {
    let m = rng.int(6, 10);
    random_case_of(rng, m)
}

/// [`random_case`] with `m` cables.
fn random_case_of(rng: &mut Rng, m: usize) -> Case {
    let (b, a) = (rng.range(1.5, 2.5), rng.range(0.6, 1.0));
    let r3 = 3f64.sqrt();
    let cables: Vec<(V3, V3)> = if m == 6 {
        // the Robocrane's octahedral layout, perturbed
        let base = [v3(-b, -b * r3 / 3.0, 0.0), v3(b, -b * r3 / 3.0, 0.0), v3(0.0, 2.0 * b * r3 / 3.0, 0.0)];
        let plat = [v3(0.0, -2.0 * a * r3 / 3.0, 0.0), v3(a, a * r3 / 3.0, 0.0), v3(-a, a * r3 / 3.0, 0.0)];
        [(0, 0), (1, 0), (1, 1), (2, 1), (2, 2), (0, 2)].iter().map(|&(i, j)| (base[i] + rng.in_box(0.2), plat[j] + rng.in_box(0.1))).collect()
    } else {
        // hanging from a ring at z = 0, up to two pulling from a ring below (z = 4)
        let low = rng.int(0, 2);
        (0..m)
            .map(|k| {
                let angle = ring_angle(rng, k, m);
                let below = k < low;
                let base = v3(b * angle.cos(), b * angle.sin(), if below { 4.0 } else { 0.0 });
                // alternate twists, so that the cables resist turning about z both ways
                let twist = if k % 2 == 0 { 0.6 } else { -0.6 };
                let on = v3(a * 0.5 * (angle + twist).cos(), a * 0.5 * (angle + twist).sin(), if below { 0.1 } else { -0.1 });
                (base, on + rng.in_box(0.05))
            })
            .collect()
    };
    let mass = rng.range(0.5, 2.0);
    let gravity = v3(0.0, 0.0, 10.0);
    let weight = mass * 10.0;
    let q = Matrix3::from_fn(|_, _| rng.normal());
    let inertia = (q * q.transpose()) * (0.02 * mass) + Matrix3::identity() * (0.01 * mass);
    let wrench = (m == 6 || rng.chance(0.5)).then(|| {
        let w0 = Vector6::from_fn(|_, _| weight * rng.range(-0.05, 0.05));
        let rot = Matrix6::from_fn(|_, _| rng.normal()).qr().q();
        let top = if m == 6 { 0.08 } else { 0.04 };
        let radii = Matrix6::from_diagonal(&Vector6::from_fn(|_, _| (weight * rng.range(0.005, top)).powi(2)));
        (w0, rot.transpose() * radii * rot, rng.in_box(0.1))
    });
    let tension = (if rng.chance(0.5) { 0.0 } else { 0.05 * weight }, weight * rng.range(0.6, 2.0));
    let winch = rng.chance(0.3).then(|| (rng.range(0.3, 1.5), rng.range(1.0, 6.0)));
    // degree 0: a slerp in place, of half the degree (Motion::trajectory)
    let deg = rng.int(0, 3);
    let centre = v3(rng.range(-0.3, 0.3), rng.range(-0.3, 0.3), rng.range(1.6, 2.4));
    let mut coeffs: [Vec<f64>; 3] = Default::default();
    for (axis, c) in coeffs.iter_mut().enumerate() {
        c.push(centre.get(axis));
        for k in 1..=deg {
            c.push(rng.range(-0.6, 0.6) / k as f64);
        }
    }
    let qs = quat_normalize(quat_axis_angle(rng.unit_vector(), rng.range(0.0, 30f64.to_radians())));
    // a turn in place turns by 15° at least: the reference's finite differences resolve the
    // dynamics of a platform that barely moves only to about the rounding of its pose
    let least = if deg == 0 { 15f64 } else { 0.0 };
    let qe = quat_normalize(quat_mul(qs, quat_axis_angle(rng.unit_vector(), rng.range(least.to_radians(), 60f64.to_radians()))));
    let traj = RefTrajectory { name: "t".into(), translation: RefTranslation::Polynomial(coeffs), qs, qe };
    Case { mobility: Mobility::Spatial, cables, tension, mass, com: rng.in_box(0.1), inertia, gravity, wrench, winch, path: Path::Slerp(traj), duration: rng.range(0.5, 2.5), h: H, eps: 1e-7 }
}

/// A random six-cable case (its mass, load, winch limits, path and duration) recast as a robot
/// moving as `mobility` on `cables`, and its weight (mass × 10).
fn recast(rng: &mut Rng, mobility: Mobility, cables: Vec<(V3, V3)>) -> (Case, f64) {
    let case = random_case_of(rng, 6);
    let weight = case.mass * 10.0;
    (Case { mobility, cables, ..case }, weight)
}

/// The angle of anchor `k` of `m` around a ring, jittered by a fifth of the spacing.
fn ring_angle(rng: &mut Rng, k: usize, m: usize) -> f64 {
    2.0 * std::f64::consts::PI * (k as f64 + rng.range(-0.2, 0.2)) / m as f64
}

/// A random point mass (3 to 8 cables meeting at it: hanging from a ring at z = 0, up to two
/// pulling from below), with mass, a random load and a random timed path (its orientation
/// immaterial: the identity throughout).
fn random_point_case(rng: &mut Rng) -> Case {
    let m = rng.int(3, 8);
    let b = rng.range(1.5, 2.5);
    let low = if m > 3 { rng.int(0, 2) } else { 0 };
    let cables = (0..m)
        .map(|k| {
            let angle = ring_angle(rng, k, m);
            let z = if k < low { 4.0 } else { rng.range(-0.2, 0.2) };
            (v3(b * angle.cos(), b * angle.sin(), z), v3(0.0, 0.0, 0.0))
        })
        .collect();
    let (mut case, weight) = recast(rng, Mobility::Point, cables);
    case.com = v3(0.0, 0.0, 0.0);
    case.inertia = Matrix3::zeros();
    // a point mass's few cables share its weight: tighter bounds than a platform's, so that
    // paths leave them
    case.tension = (if rng.chance(0.5) { 0.0 } else { 0.1 * weight }, weight * rng.range(0.35, 1.0));
    if let Path::Slerp(traj) = &mut case.path {
        (traj.qs, traj.qe) = ([1.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]);
        // longer paths than a platform's: towards the ring, where the cables flatten
        if let RefTranslation::Polynomial(c) = &mut traj.translation {
            for row in c.iter_mut() {
                row.iter_mut().skip(1).for_each(|x| *x *= 2.0);
            }
        }
    }
    case
}

/// A random planar robot (3 to 8 cables in the plane z = 0 from a ring to a small platform, with
/// alternating twists), gravity +y in the plane, mass, a random load and a random timed path in
/// the plane turning about z.
fn random_planar_case(rng: &mut Rng) -> Case {
    let m = rng.int(3, 8);
    let (b, a) = (rng.range(1.5, 2.5), rng.range(0.3, 0.6));
    let cables = (0..m)
        .map(|k| {
            let angle = ring_angle(rng, k, m);
            let twist = if k % 2 == 0 { 0.6 } else { -0.6 };
            let on = v3(a * (angle + twist).cos() + rng.range(-0.05, 0.05), a * (angle + twist).sin() + rng.range(-0.05, 0.05), 0.0);
            (v3(b * angle.cos(), b * angle.sin() - 0.5 * b, 0.0), on)
        })
        .collect();
    let (mut case, weight) = recast(rng, Mobility::Planar, cables);
    case.gravity = v3(0.0, 10.0, 0.0);
    case.com = v3(rng.range(-0.1, 0.1), rng.range(-0.1, 0.1), 0.0);
    case.tension = (if rng.chance(0.5) { 0.0 } else { 0.05 * weight }, weight * rng.range(0.6, 2.0));
    if let Path::Slerp(traj) = &mut case.path {
        if let RefTranslation::Polynomial(c) = &mut traj.translation {
            c[0][0] = rng.range(-0.3, 0.3);
            c[1][0] = rng.range(-0.3, 0.3);
            c[2] = vec![0.0];
        }
        let z = v3(0.0, 0.0, 1.0);
        traj.qs = quat_axis_angle(z, rng.range(-0.3, 0.3));
        traj.qe = quat_normalize(quat_mul(traj.qs, quat_axis_angle(z, rng.range(-0.7, 0.7))));
    }
    case
}

/// A random robot of each kind in turn (`k` mod 3): spatial, point mass, planar.
fn random_case_of_kind(rng: &mut Rng, k: usize) -> Case {
    match k % 3 {
        0 => random_case(rng),
        1 => random_point_case(rng),
        _ => random_planar_case(rng),
    }
}

/// Per case, at `samples` evenly spread samples: samples compared, contradictions, boundaries
/// checked, mixed sections.
fn run_case_sampled(k: usize, case: &Case, samples: usize) -> (usize, Vec<String>, usize, bool) {
    let s = Scenario::from_json(&case.json()).unwrap_or_else(|e| panic!("case {k}: {e}"));
    let r = verify_trajectory(&s, &s.trajectories[0]).unwrap();
    let mut rng = Rng::new(k as u64);
    let mut bad = Vec::new();
    let uncertain: f64 = r.uncertain.iter().map(|u| u[1] - u[0]).sum();
    if uncertain > 1e-6 {
        bad.push(format!("{uncertain} of t uncertain: {:?}", r.uncertain));
    }
    let offset = rng.f64();
    let mut compared = 0;
    for i in 0..samples {
        let t = (i as f64 + offset) / samples as f64;
        let Some(claim) = reported(&r, t, 1e-9) else { continue };
        let Some(truth) = case.at(t, case.duration, &mut rng).verdict else { continue };
        compared += 1;
        if claim != truth {
            bad.push(format!("t = {t}: reported {claim}, reference {truth}"));
        }
    }
    // each boundary separates decided reference verdicts 1e-6 to either side, as reported
    let mut checked = 0;
    for (b, lo, hi, enters) in lone_boundaries(&r, 1e-6) {
        let (before, after) = (case.at(lo, case.duration, &mut rng).verdict, case.at(hi, case.duration, &mut rng).verdict);
        if before == Some(enters) || after == Some(!enters) {
            bad.push(format!("boundary t = {} ({}) not matched by the reference within 1e-6: {before:?} → {after:?}", b.t, b.constraint));
        }
        checked += usize::from(before.is_some() && after.is_some());
    }
    let bad = bad.into_iter().map(|b| format!("case {k} ({} cables): {b}\n{}", case.cables.len(), case.json())).collect();
    (compared, bad, checked, !r.feasible.is_empty() && !r.infeasible.is_empty())
}

/// [`run_case_sampled`] on every case (on two threads natively), asserting that no sample contradicts the
/// reference; the per-case results in order.
fn run_cases(cases: &[Case]) -> Vec<(usize, Vec<String>, usize, bool)> {
    run_cases_sampled(cases, env_usize("CABLENAV_DYNAMICS_SAMPLES", SAMPLES))
}

/// [`run_cases`] at `samples` samples per case.
fn run_cases_sampled(cases: &[Case], samples: usize) -> Vec<(usize, Vec<String>, usize, bool)> {
    #[cfg(not(target_arch = "wasm32"))]
    let results = support::on_two_threads(cases.len(), &|k| run_case_sampled(k, &cases[k], samples));
    #[cfg(target_arch = "wasm32")]
    let results: Vec<_> = cases.iter().enumerate().map(|(k, c)| run_case_sampled(k, c, samples)).collect();
    let failures: Vec<&String> = results.iter().flat_map(|r| &r.1).collect();
    assert!(failures.is_empty(), "{} contradictions, first: {}", failures.len(), failures[0]);
    results
}

#[test]
fn dynamic_sections_match_an_independent_reference_on_random_robots() {
    let mut rng = Rng::new(22);
    let cases: Vec<Case> = (0..env_usize("CABLENAV_DYNAMICS_CASES", CASES)).map(|_| random_case(&mut rng)).collect();
    let results = run_cases(&cases);
    let compared: usize = results.iter().map(|r| r.0).sum();
    let boundaries: usize = results.iter().map(|r| r.2).sum();
    let mixed = results.iter().filter(|r| r.3).count();
    let n = cases.len();
    assert!(mixed * 5 >= n, "only {mixed} of {n} trajectories have both kinds of section");
    let samples = env_usize("CABLENAV_DYNAMICS_SAMPLES", SAMPLES);
    assert!(boundaries >= n / 12 && compared > n * samples / 2, "{boundaries} boundaries, {compared} samples");
}

/// Point masses (3 to 8 cables meeting at the point) and planar robots (3 to 8 cables in the
/// plane z = 0), with mass, loads and winch limits, along random timed paths: the exact sections
/// against the reference in the components each balances (the force; fx, fy and mz).
#[test]
fn point_mass_and_planar_sections_match_the_reference() {
    let mut rng = Rng::new(41);
    let n = if cfg!(target_arch = "wasm32") { 60 } else { env_usize("CABLENAV_DYNAMICS_CASES", 240) };
    let cases: Vec<Case> = (0..n).map(|k| random_case_of_kind(&mut rng, 1 + k % 2)).collect();
    let results = run_cases(&cases);
    let compared: usize = results.iter().map(|r| r.0).sum();
    let boundaries: usize = results.iter().map(|r| r.2).sum();
    let mixed = results.iter().filter(|r| r.3).count();
    for kind in [1, 2] {
        let of_kind = results.iter().enumerate().filter(|(k, r)| 1 + k % 2 == kind && r.3).count();
        assert!(of_kind * 10 >= n / 2, "only {of_kind} of the {} trajectories of kind {kind} have both kinds of section", n / 2);
    }
    let samples = env_usize("CABLENAV_DYNAMICS_SAMPLES", SAMPLES);
    assert!(mixed * 5 >= n && boundaries >= n / 40 && compared > n * samples / 2, "{mixed} mixed, {boundaries} boundaries, {compared} samples");
}

/// A single wrench for any number of cables (11 to 24, and some up to 64; mass, and for about
/// half of them a nominal external wrench at a point without an ellipsoid: the linear-program
/// certificates of `conditions::wrench_lp`), against the same reference.
#[test]
fn many_cables_by_linear_programs_match_the_reference() {
    let mut rng = Rng::new(26);
    let n = if cfg!(target_arch = "wasm32") { 6 } else { 40 };
    let cases: Vec<Case> = (0..n)
        .map(|_| {
            let m = if rng.chance(0.15) { rng.int(25, 64) } else { rng.int(11, 24) };
            let mut case = random_case_of(&mut rng, m);
            // a random external wrench at a random point, without its ellipsoid (format 4's
            // nominal-only wrench section), or none
            if let Some((_, e_inv, _)) = &mut case.wrench {
                *e_inv = Matrix6::zeros();
            }
            case
        })
        .collect();
    let results = run_cases(&cases);
    let mixed = results.iter().filter(|r| r.3).count();
    let boundaries: usize = results.iter().map(|r| r.2).sum();
    assert!(mixed * 5 >= n && boundaries * 12 >= n, "{mixed} of {n} trajectories with both kinds of section, {boundaries} boundaries checked");
}

/// A wrench ellipsoid beyond the facets' reach (11 to 15 cables, against the reference's own
/// enumeration of every facet pair; and some with 16 to 64 against its sampled directions and
/// pseudo-inverse tensions), with mass and inertia along random timed trajectories: the cover of
/// wrench directions of `conditions::wrench_lp`.
#[test]
fn many_cables_with_an_ellipsoid_match_the_reference() {
    let mut rng = Rng::new(27);
    let n = if cfg!(target_arch = "wasm32") { 3 } else { env_usize("CABLENAV_ELLIPSOID_CASES", 16) };
    let cases: Vec<Case> = (0..n)
        .map(|k| {
            let m = if k % 5 == 4 { rng.int(16, 64) } else { rng.int(11, 15) };
            loop {
                let mut case = random_case_of(&mut rng, m);
                // ellipsoids up to three times as wide: more of them graze the available wrench
                // set along the motion
                if let Some((_, e_inv, _)) = &mut case.wrench {
                    *e_inv *= rng.range(1.0, 3.0).powi(2);
                    // the facets' margin is exact to rounding: a narrower band than the
                    // finite differences' 1e-7 still clears their 1e-10, and decides the
                    // reference 1e-6 from a boundary
                    case.eps = 1e-9;
                    break case;
                }
            }
        })
        .collect();
    let results = run_cases_sampled(&cases, if cfg!(target_arch = "wasm32") { 100 } else { 300 });
    let mixed = results.iter().filter(|r| r.3).count();
    let boundaries: usize = results.iter().map(|r| r.2).sum();
    assert!(mixed * 4 >= n && boundaries * 4 >= n, "{mixed} of {n} trajectories with both kinds of section, {boundaries} boundaries checked");
}

/// The fastest timing (`cablenav time`) of random robots' trajectories (spatial platforms with 6
/// to 10 cables, point masses and planar platforms with 3 to 8, all with mass, wrench sets, winch
/// limits on some; rest to rest): wherever a law exists, it is certified, the
/// reference moved by it in time (finite differences of the pose along the law, inside each of
/// its cells) finds no sample violated, and it is near time-optimal: at most samples some
/// constraint is within 1 % of its bound (the tension range, the winch limit).
#[test]
fn fastest_timing_is_certified_and_near_optimal_against_the_reference() {
    use cablenav::plan::timing::{fastest, TimingOptions};
    let mut rng = Rng::new(31);
    // many random robots fail at rest somewhere along their path (then no timing exists): as
    // many are drawn, in batches, as it takes to time `n` of them (about one in four can be)
    let n = if cfg!(target_arch = "wasm32") { 8 } else { env_usize("CABLENAV_TIMING_CASES", 100) };
    // spatial platforms, point masses and planar platforms in turn
    let cases: Vec<Case> = (0..12 * n).map(|k| random_case_of_kind(&mut rng, k)).collect();
    let run = |k: usize| -> (usize, usize, usize, Vec<String>) {
        let case = &cases[k];
        let s = Scenario::from_json(&case.json()).unwrap();
        let (report, law) = match fastest(&s, &s.trajectories[0], TimingOptions::default()) { Ok(x) => x, Err(_) => return (0, 0, 0, vec![]) };
        let mut bad = Vec::new();
        if report.duration.is_none() {
            bad.push(format!("case {k}: not certified on {:?}", report.not_certified));
        }
        let duration = law.duration();
        let timed = Case { path: Path::Timed(Box::new(Path::Slerp(match &case.path { Path::Slerp(t) => t.clone(), _ => unreachable!() })), law.clone()), duration, h: TIMED_H, eps: TIMED_EPS, ..case.clone() };
        let mut rng = Rng::new(k as u64);
        let (mut compared, mut near) = (0, 0);
        let knots = law.knots();
        for (i, &(_, start)) in knots.iter().enumerate() {
            let end = knots.get(i + 1).map_or(duration, |k| k.1);
            // two samples per cell, the stencils inside it
            for _ in 0..2 {
                let margin = 3.0 * TIMED_H * duration;
                if end - start <= 2.0 * margin {
                    continue;
                }
                let time = start + margin + rng.f64() * (end - start - 2.0 * margin);
                let at = timed.at(time / duration, duration, &mut rng);
                if at.verdict == Some(false) {
                    bad.push(format!("case {k}: violated at {time} s of {duration} (cell {i})"));
                }
                if at.slack.is_finite() {
                    compared += 1;
                    near += usize::from(at.slack <= 0.01);
                }
            }
        }
        (1, compared, near, bad.into_iter().map(|b| format!("{b}\n{}", case.json())).collect())
    };
    let mut results = Vec::new();
    let mut drawn = 0;
    while results.iter().map(|r: &(usize, usize, usize, Vec<String>)| r.0).sum::<usize>() < n && drawn < cases.len() {
        let batch = (2 * n).min(cases.len() - drawn);
        #[cfg(not(target_arch = "wasm32"))]
        results.extend(support::on_two_threads(batch, &|k| run(drawn + k)));
        #[cfg(target_arch = "wasm32")]
        results.extend((drawn..drawn + batch).map(run));
        drawn += batch;
    }
    let timed: usize = results.iter().map(|r| r.0).sum();
    let compared: usize = results.iter().map(|r| r.1).sum();
    let near: usize = results.iter().map(|r| r.2).sum();
    let failures: Vec<&String> = results.iter().flat_map(|r| &r.3).collect();
    assert!(failures.is_empty(), "{} failures, first: {}", failures.len(), failures[0]);
    assert!(timed >= n, "only {timed} of {drawn} cases have a timing");
    // results come in the order drawn: case k is of kind k mod 3
    let of_kind = |kind: usize| results.iter().enumerate().filter(|(k, r)| k % 3 == kind && r.0 == 1).count();
    assert!((0..3).all(|kind| of_kind(kind) * 5 >= n), "timed: {} spatial, {} point-mass, {} planar", of_kind(0), of_kind(1), of_kind(2));
    assert!(near as f64 >= 0.9 * compared as f64, "near a bound at {near} of {compared} samples");
}

/// The least time scale of six-cable trajectories (no winch limits) against the reference's:
/// per sample, the largest u = 1/k² its tensions allow is linear algebra on the rest and inertial
/// wrenches; the certified scale is never below the sampled one (soundness) and within 1e-3 of it
/// (the samples are dense, the peak smooth).
#[test]
fn min_time_scale_matches_the_reference() {
    let mut rng = Rng::new(23);
    let (mut compared, mut faster, mut slower) = (0, 0, 0);
    let n = (env_usize("CABLENAV_DYNAMICS_CASES", CASES) / 3).max(12);
    let mut k = 0;
    while compared < n && k < 20 * n {
        k += 1;
        let mut case = random_case(&mut rng);
        if case.cables.len() != 6 {
            continue;
        }
        case.winch = None;
        let s = Scenario::from_json(&case.json()).unwrap();
        let r = verify_trajectory(&s, &s.trajectories[0]).unwrap();
        let sec = r.seconds.as_ref().expect("a timed trajectory has seconds");
        assert!((sec.duration - case.duration).abs() <= 1e-15 * case.duration);
        if !sec.infeasible_at_rest.is_empty() {
            // holding only at some speeds (or at none): then the scales that hold are bounded
            assert!(sec.min_time_scale.is_none() || sec.max_time_scale.is_some(), "case {k}: {sec:?}");
            continue;
        }
        assert!(sec.max_time_scale.is_none());
        let Some(scale) = sec.min_time_scale else { panic!("case {k}: holds at rest, yet no scale: {sec:?}") };
        let samples = SAMPLES * 5;
        let u_max = (0..=samples).map(|i| case.at(i as f64 / samples as f64, case.duration, &mut rng).u_max).fold(f64::INFINITY, f64::min);
        let k_ref = if u_max.is_finite() { 1.0 / u_max.max(0.0).sqrt() } else { 0.0 };
        assert!(scale >= k_ref * (1.0 - 1e-9), "case {k}: certified {scale} below the sampled {k_ref}\n{}", case.json());
        assert!(scale <= k_ref * (1.0 + 1e-3) + 1e-6, "case {k}: certified {scale}, sampled {k_ref}\n{}", case.json());
        let [lo, hi] = sec.min_time_scale_bracket.unwrap();
        assert!(lo <= hi && hi == scale && (hi - lo) <= 2e-4 * hi + 1e-6, "{lo} {hi}");
        assert!((sec.min_duration.unwrap() - scale * case.duration).abs() < 1e-12);
        compared += 1;
        if scale < 1.0 { faster += 1 } else { slower += 1 }
    }
    assert!(compared >= n, "only {compared} comparable cases");
    assert!(faster > 0 && slower > 0, "{faster} could run faster, {slower} must run slower: both kinds are needed");
}

/// Six cables: the hyperplane-shifting margin of the wrench set equals paper 1's
/// min over cables of (f0 − v − f_min, f_max − f0 − v), on 10⁴ random poses.
#[test]
fn six_cable_wrench_set_margin_agrees_with_paper_1() {
    let mut rng = Rng::new(24);
    let poses = if cfg!(target_arch = "wasm32") { 1_000 } else { 10_000 };
    let mut signs = [0, 0];
    for _ in 0..poses {
        let case = random_case(&mut rng);
        if case.cables.len() != 6 {
            continue;
        }
        let (p, r) = case.pose(rng.f64());
        let cables: Vec<(Vector3<f64>, Vector3<f64>)> = case.cables.iter().map(|(a, b)| (to_v(*a), p + r * to_v(*b))).collect();
        let (mut w0, e_inv, point) = case.wrench.unwrap();
        w0[2] += case.mass * case.gravity.z; // the weight, as a load
        let c = p + r * to_v(point);
        let bounds = vec![Bounds { min: case.tension.0, max: case.tension.1 }; 6];
        let facets = wrench_set_margin(&cables, &c, &w0, &e_inv, &bounds, &[0, 1, 2, 3, 4, 5]);
        let wrench = cablenav::model::Wrench {
            nominal: w0,
            ellipsoid: e_inv.try_inverse().unwrap(),
            ellipsoid_inv: e_inv,
            point: to_v(point),
            frame: cablenav::model::PointFrame::Platform,
            closure: false,
        };
        let ranges = tension_ranges_at(&cables, &c, &w0, &wrench, &[0, 1, 2, 3, 4, 5]);
        match (facets, ranges) {
            (Some(f), Some(ranges)) => {
                let paper = ranges.iter().map(|t| (t.nominal - t.spread - case.tension.0).min(case.tension.1 - t.nominal - t.spread)).fold(f64::INFINITY, f64::min);
                let half = 0.5 * (case.tension.1 - case.tension.0);
                let scale = ranges.iter().map(|t| t.nominal.abs() + t.spread).fold(1.0, f64::max);
                assert!((f - paper.min(half)).abs() <= 1e-9 * scale, "facets {f} vs paper 1 {paper}");
                signs[usize::from(paper > 0.0)] += 1;
            }
            (None, None) => {}
            (f, r) => panic!("singular in one test only: {f:?} {r:?}"),
        }
    }
    assert!(signs[0] > poses / 100 && signs[1] > poses / 100, "{signs:?}");
}



const COGIRO_BODIES: &str = include_str!("../../shared/models/caspr/CoGiRo/CoGiRo_bodies.xml");
const COGIRO_CABLES: &str = include_str!("../../shared/models/caspr/CoGiRo/CoGiRo_cables.xml");
const COGIRO_TRAJECTORIES: &str = include_str!("../../shared/models/caspr/CoGiRo/CoGiRo_trajectories.xml");

/// CoGiRo (8 cables, 91 kg) imported from CASPR's files with its four quintic spline trajectories:
/// the dynamic sections at their own timing against the reference moved by CASPR's spline as
/// documented ([`Spline`], from the files' q values), and the least time scale: certified
/// feasible just above it, some sample violated just below.
#[test]
fn cogiro_spline_trajectories_match_the_reference() {
    let imported = cablenav::scenario::caspr::model_to_json("CoGiRo", COGIRO_BODIES, COGIRO_CABLES, Some(COGIRO_TRAJECTORIES), None).unwrap();
    let s = Scenario::from_json(&imported.json).unwrap();
    let d = s.robot.dynamics.clone().expect("CoGiRo has mass");
    let to3 = |v: &Vector3<f64>| v3(v.x, v.y, v.z);
    let cables: Vec<(V3, V3)> = s.robot.cables.iter().map(|c| (to3(&c.base), to3(&c.platform))).collect();
    let tension = (s.robot.cables[0].tension.min, s.robot.cables[0].tension.max);
    let mut rng = Rng::new(25);
    let samples = env_usize("CABLENAV_DYNAMICS_SAMPLES", SAMPLES) / 4;
    let mut scales = 0;
    // in wasm the two quick ones (general_2 fails at rest, and its scale search is the longest)
    let ids: &[&str] = if cfg!(target_arch = "wasm32") { &["general_1", "long_stable"] } else { &["general_1", "general_2", "general_3", "long_stable"] };
    for &id in ids {
        let traj = s.trajectories.iter().find(|t| t.name == id).expect("imported");
        let spline = Spline::from_caspr(COGIRO_TRAJECTORIES, id);
        let duration = spline.duration();
        assert_eq!(traj.duration, Some(duration));
        let case = Case { mobility: Mobility::Spatial, cables: cables.clone(), tension, mass: d.mass, com: to3(&d.com), inertia: d.inertia, gravity: to3(&d.gravity), wrench: None, winch: None, path: Path::Spline(spline), duration, h: H, eps: 1e-7 };
        let r = verify_trajectory(&s, traj).unwrap();
        assert!(r.uncertain.iter().map(|u| u[1] - u[0]).sum::<f64>() < 1e-6, "{id}: uncertain {:?}", r.uncertain);
        let mut compared = 0;
        for i in 0..samples {
            let t = (i as f64 + 0.5) / samples as f64;
            let (Some(claim), Some(truth)) = (reported(&r, t, 1e-9), case.at(t, duration, &mut rng).verdict) else { continue };
            compared += 1;
            assert_eq!(claim, truth, "{id} at t = {t}: reported {claim}, reference {truth}");
        }
        assert!(compared * 10 >= samples * 9, "{id}: only {compared} of {samples} samples decided");
        for (b, lo, hi, enters) in lone_boundaries(&r, 1e-6) {
            let (before, after) = (case.at(lo, duration, &mut rng).verdict, case.at(hi, duration, &mut rng).verdict);
            assert!(before != Some(enters) && after != Some(!enters), "{id}: boundary t = {} not matched: {before:?} → {after:?}", b.t);
        }
        let sec = r.seconds.as_ref().expect("timed");
        if id == "general_2" {
            // it fails at rest around its middle knot, where it stops at every timing: no scale
            assert!(sec.min_time_scale.is_none() && sec.min_time_scale_note.contains("knot 1"), "{sec:?}");
            assert!(case.at(0.5, duration * 1e3, &mut rng).verdict == Some(false) && case.at(0.5, duration * 1e-3, &mut rng).verdict == Some(false));
        }
        if let (Some(k), Some([lo, _])) = (sec.min_time_scale, sec.min_time_scale_bracket) {
            let holds = |k: f64, rng: &mut Rng| (0..samples).all(|i| case.at((i as f64 + 0.5) / samples as f64, duration * k, rng).verdict != Some(false));
            assert!(holds(k * (1.0 + 1e-6), &mut rng), "{id}: a sample fails at the certified scale {k}");
            assert!(!holds(lo * 0.99, &mut rng), "{id}: every sample holds 1 % below the scale certified violated, {lo}");
            scales += 1;
        }
    }
    assert!(scales >= ids.len().min(3), "CoGiRo's trajectories that hold at rest have a least time scale");
}
