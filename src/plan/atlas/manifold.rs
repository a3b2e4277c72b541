//! Implicitly defined manifolds M = {x : F(x) = 0} for the continuation (the "state space" of the
//! planner), and the one cablenav plans on: the wrench-feasible C-space of a 6-cable robot with
//! the feasibility boundary sent to infinity in auxiliary variables.
//!
//! ## The cable manifold (docs/planner.md has the derivation)
//!
//! Variables x = (q_free, w_1 … w_m): the free pose coordinates among (x, y, z, φ, θ, σ) and one
//! auxiliary per bound. With f0 = J⁻¹w0 and v_i = sqrt((J⁻¹E⁻¹J⁻ᵀ)_ii) (Bohigas et al. eqs. 4–5
//! solved in closed form), each bound has a normalised margin
//!
//! * tension low:  μ = (f0_i − v_i − f_min) / (f_max − f_min),
//! * tension high: μ = (f_max − f0_i − v_i) / (f_max − f_min),
//! * length:       μ = (ρ_i − ρ_min)(ρ_max − ρ_i) / ((ρ_max − ρ_min)²/4),
//!
//! and one equation F_j = μ_j(q)·exp(w_j/κ) − 1 = 0 (paper eqs. 6–8 have μ·s = 1; here s = e^{w/κ}).
//! F is smooth wherever J is invertible, ∂F_j/∂w_j = 1/κ on M so the Jacobian always has full
//! rank, every solution has μ_j > 0 (M is exactly the feasible set: no M ∖ M⁺ component), and
//! w_j = −κ ln μ_j → ∞ at the boundary. The logarithm keeps the auxiliaries of order κ·ln(1/μ)
//! instead of 1/μ, so the atlas does not spend most of its charts climbing the barrier.

use crate::conditions::{for_scenario, Condition};
use crate::model::pose::{rot_y, rot_z, wrap_angle};
use crate::model::{Coord, PointFrame, Pose, Robot, Wrench};
use crate::plan::edge_trajectory;
use crate::query::cables::cables_at;
use crate::query::wrench::structure_matrix;
use crate::scenario::Scenario;
use crate::verify::verify_trajectory;
use nalgebra::{DMatrix, Matrix3, Matrix6, Vector3, Vector6};

/// A k-manifold implicitly defined in ℝⁿ by m = n − k smooth equations, with what the
/// continuation needs to know about it. The atlas and the search use nothing else.
pub trait Manifold {
    /// Ambient dimension n.
    fn ambient(&self) -> usize;

    /// Number of equations m.
    fn equations(&self) -> usize;

    /// Manifold dimension k = n − m.
    fn dimension(&self) -> usize {
        self.ambient() - self.equations()
    }

    /// F(x) into `f` (length m) and its Jacobian into `jac` (m × n); `false` where F is not
    /// defined at x (then the outputs are unspecified).
    fn eval(&self, x: &[f64], f: &mut [f64], jac: &mut DMatrix<f64>) -> bool;

    /// a − b in ℝⁿ, with periodic coordinates wrapped (the default is plain subtraction).
    fn difference(&self, a: &[f64], b: &[f64], out: &mut [f64]) {
        for ((o, p), q) in out.iter_mut().zip(a).zip(b) {
            *o = p - q;
        }
    }

    /// The path-length metric the search minimises and its heuristic measures (must satisfy the
    /// triangle inequality); the default is the Euclidean norm of [`Manifold::difference`].
    fn distance(&self, a: &[f64], b: &[f64]) -> f64 {
        let mut d = vec![0.0; a.len()];
        self.difference(a, b, &mut d);
        d.iter().map(|v| v * v).sum::<f64>().sqrt()
    }

    /// Whether x lies within the bounds the atlas explores (charts beyond are never expanded).
    fn within_bounds(&self, _x: &[f64]) -> bool {
        true
    }

    /// Whether a chart centred at x may be used at all (e.g. no interference there).
    fn admissible(&self, _x: &[f64]) -> bool {
        true
    }

    /// The motion validator: whether the motion between two consecutive points of a dense path
    /// is valid (e.g. free of interference all along).
    fn motion_valid(&self, _a: &[f64], _b: &[f64]) -> bool {
        true
    }
}

/// Which bound a barrier equation keeps away from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BoundKind {
    /// The cable's least tension over the wrench set above its minimum.
    TensionLow,
    /// The cable's greatest tension over the wrench set below its maximum.
    TensionHigh,
    /// The cable's length strictly inside its bounds.
    Length,
}

/// One barrier equation: a bound of one cable and the scale its margin is normalised by.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Barrier {
    /// Which bound.
    pub kind: BoundKind,
    /// The cable (0-based).
    pub cable: usize,
    /// The normaliser of the margin.
    scale: f64,
}

impl Barrier {
    /// How reports name it, e.g. `cable 3 tension lower bound`.
    pub fn label(&self) -> String {
        let what = match self.kind {
            BoundKind::TensionLow => "tension lower bound",
            BoundKind::TensionHigh => "tension upper bound",
            BoundKind::Length => "length bounds",
        };
        format!("cable {} {what}", self.cable + 1)
    }
}

/// Normalised margins μ_j at one pose and, if asked, their gradients in the six coordinates.
pub struct Margins {
    /// μ_j, one per barrier.
    pub values: Vec<f64>,
    /// ∂μ_j/∂q_c for the six coordinates c, one row per barrier.
    pub gradients: Vec<[f64; 6]>,
}

/// The wrench-feasible C-space of a 6-cable robot (optionally a slice), as a [`Manifold`].
pub struct CableManifold {
    scenario: Scenario,
    robot: Robot,
    wrench: Wrench,
    /// Value of each coordinate that is held fixed.
    fixed: [Option<f64>; 6],
    /// Indices (into x, y, z, φ, θ, σ) of the free coordinates, in order.
    free: Vec<usize>,
    /// Whether angle differences are wrapped.
    periodic: bool,
    barriers: Vec<Barrier>,
    kappa: f64,
    w_max: f64,
    rotation_length: f64,
    conditions: Vec<Box<dyn Condition>>,
}

/// Below this |det J| / Π‖column‖ the manifold treats J as singular (as `tension_ranges` does).
const SINGULAR: f64 = crate::query::wrench::SINGULAR_RATIO;

impl CableManifold {
    /// The C-space of `scenario`'s robot with `fixed` coordinates held at the given values; with
    /// `periodic`, differences of angle coordinates are wrapped to (−π, π].
    /// `kappa` is the barrier scale κ, `min_margin` the least normalised margin the atlas explores
    /// (w ≤ −κ ln min_margin), `rotation_length` the length that one radian of rotation counts
    /// as in the path metric. The scenario must have exactly six cables and a wrench section.
    pub fn new(scenario: &Scenario, fixed: [Option<f64>; 6], periodic: bool, kappa: f64, min_margin: f64, rotation_length: f64) -> crate::Result<CableManifold> {
        use crate::error::Error;
        let robot = scenario.robot.clone();
        if robot.mobility != crate::model::Mobility::Spatial {
            return Err(Error::new("robot.mobility", format!("the atlas planner is for spatial platforms (the 6-D C-space of Bohigas et al.); a {} robot moves in a lower-dimensional space: use the lattice planner", robot.mobility.name())));
        }
        if robot.cables.len() != 6 {
            return Err(Error::new("robot.cables", format!("the planner needs exactly 6 cables (the wrench model of Bohigas et al.), got {}", robot.cables.len())));
        }
        let wrench = scenario.wrench.clone().ok_or_else(|| Error::new("wrench", "the planner needs a wrench section"))?;
        let mut barriers = Vec::new();
        for (i, c) in robot.cables.iter().enumerate() {
            let t = c.tension;
            let span = if t.max.is_finite() { t.max - t.min } else { t.min.abs().max(1.0) };
            if !(span > 0.0) {
                return Err(Error::new(format!("robot.cables[{i}].tension"), "needs min < max"));
            }
            barriers.push(Barrier { kind: BoundKind::TensionLow, cable: i, scale: span });
            if t.max.is_finite() {
                barriers.push(Barrier { kind: BoundKind::TensionHigh, cable: i, scale: span });
            }
            let l = c.length;
            if l.max.is_finite() {
                if !(l.max > l.min) {
                    return Err(Error::new(format!("robot.cables[{i}].length"), "needs min < max"));
                }
                barriers.push(Barrier { kind: BoundKind::Length, cable: i, scale: (l.max - l.min).powi(2) / 4.0 });
            } else if l.min > 0.0 {
                barriers.push(Barrier { kind: BoundKind::Length, cable: i, scale: l.min });
            }
        }
        let free = (0..6).filter(|&c| fixed[c].is_none()).collect();
        Ok(CableManifold {
            scenario: scenario.clone(),
            conditions: for_scenario(scenario),
            robot,
            wrench,
            fixed,
            free,
            periodic,
            barriers,
            kappa,
            w_max: -kappa * min_margin.ln(),
            rotation_length,
        })
    }

    /// The barrier equations, in the order of the auxiliaries.
    pub fn barriers(&self) -> &[Barrier] {
        &self.barriers
    }

    /// Indices (0 = x … 5 = σ) of the free coordinates.
    pub fn free(&self) -> &[usize] {
        &self.free
    }

    /// The six coordinates of an ambient point.
    pub fn coords(&self, x: &[f64]) -> [f64; 6] {
        let mut q = [0.0; 6];
        let mut k = 0;
        for (c, slot) in q.iter_mut().enumerate() {
            *slot = match self.fixed[c] {
                Some(v) => v,
                None => {
                    k += 1;
                    x[k - 1]
                }
            };
        }
        q
    }

    /// The point of M over the coordinates `q` (auxiliaries in closed form), or the reason there
    /// is none: a singular structure matrix, or the barrier whose margin is not positive.
    pub fn lift(&self, q: &[f64; 6]) -> Result<Vec<f64>, String> {
        let m = self.margins(q, false).ok_or_else(|| "the structure matrix is singular there".to_string())?;
        let mut x: Vec<f64> = self.free.iter().map(|&c| q[c]).collect();
        for (b, &mu) in self.barriers.iter().zip(&m.values) {
            if !(mu > 0.0) {
                return Err(format!("{} violated (normalised margin {mu:.3e})", b.label()));
            }
            x.push(-self.kappa * mu.ln());
        }
        Ok(x)
    }

    /// The least normalised margin at an ambient point of M, and the barrier it belongs to.
    pub fn tightest(&self, x: &[f64]) -> (f64, String) {
        let k = self.free.len();
        let (j, w) = x[k..].iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)).unwrap_or((0, &0.0));
        ((-w / self.kappa).exp(), self.barriers.get(j).map(Barrier::label).unwrap_or_default())
    }

    /// Normalised margins at coordinates `q` and, with `grad`, their gradients; `None` where the
    /// structure matrix is singular.
    pub fn margins(&self, q: &[f64; 6], grad: bool) -> Option<Margins> {
        let pose = Pose::from_coords(*q);
        let point = self.wrench.point_at(&pose);
        let j = structure_matrix(&self.robot, &pose, &point);
        let scale: f64 = (0..6).map(|i| j.column(i).norm()).product();
        let lu = j.lu();
        if !(lu.determinant().abs() > SINGULAR * scale) {
            return None;
        }
        let a = lu.try_inverse()?;
        let f0 = a * self.wrench.nominal;
        let g = self.wrench.ellipsoid_inv * a.transpose();
        let v: Vector6<f64> = Vector6::from_fn(|i, _| (a.row(i) * g.column(i))[0].max(0.0).sqrt());
        let cables = cables_at(&self.robot, &pose);
        let rho: Vec<f64> = cables.iter().map(|(b, x)| (x - b).norm()).collect();

        // Per coordinate: dJ, and the derivative of each cable length.
        let mut df0 = [Vector6::zeros(); 6];
        let mut dv = [Vector6::zeros(); 6];
        let mut drho = [[0.0; 6]; 6];
        if grad {
            let r = pose.matrix();
            let dr = rotation_derivatives(q);
            for c in 0..6 {
                let mut dj = Matrix6::zeros();
                for (i, cable) in self.robot.cables.iter().enumerate() {
                    let (dx, dc) = if c < 3 {
                        let e = Vector3::from_fn(|k, _| if k == c { 1.0 } else { 0.0 });
                        (e, e)
                    } else {
                        let rot = dr[c - 3];
                        let dc = match self.wrench.frame {
                            PointFrame::World => Vector3::zeros(),
                            PointFrame::Platform => rot * self.wrench.point,
                        };
                        (rot * cable.platform, dc)
                    };
                    let x = pose.position + r * cable.platform;
                    let e = (x - cable.base) / rho[i];
                    let de = (dx - e * e.dot(&dx)) / rho[i];
                    let dm = (dx - dc).cross(&e) + (x - point).cross(&de);
                    for k in 0..3 {
                        dj[(k, i)] = de[k];
                        dj[(k + 3, i)] = dm[k];
                    }
                    drho[c][i] = e.dot(&dx);
                }
                let da = -(a * dj * a);
                df0[c] = da * self.wrench.nominal;
                dv[c] = Vector6::from_fn(|i, _| if v[i] > 0.0 { (da.row(i) * g.column(i))[0] / v[i] } else { 0.0 });
            }
        }
        let mut values = Vec::with_capacity(self.barriers.len());
        let mut gradients = Vec::with_capacity(if grad { self.barriers.len() } else { 0 });
        for b in &self.barriers {
            let i = b.cable;
            let (t, l) = (self.robot.cables[i].tension, self.robot.cables[i].length);
            let finite_length = l.max.is_finite();
            let value = match b.kind {
                BoundKind::TensionLow => f0[i] - v[i] - t.min,
                BoundKind::TensionHigh => t.max - f0[i] - v[i],
                BoundKind::Length if finite_length => (rho[i] - l.min) * (l.max - rho[i]),
                BoundKind::Length => rho[i] - l.min,
            };
            values.push(value / b.scale);
            if grad {
                gradients.push(std::array::from_fn(|c| {
                    let slope = match b.kind {
                        BoundKind::TensionLow => df0[c][i] - dv[c][i],
                        BoundKind::TensionHigh => -df0[c][i] - dv[c][i],
                        BoundKind::Length if finite_length => (l.max + l.min - 2.0 * rho[i]) * drho[c][i],
                        BoundKind::Length => drho[c][i],
                    };
                    slope / b.scale
                }));
            }
        }
        Some(Margins { values, gradients })
    }
}

/// ∂R/∂φ, ∂R/∂θ, ∂R/∂σ for R = Rz(φ)·Ry(θ)·Rz(σ − φ).
fn rotation_derivatives(q: &[f64; 6]) -> [Matrix3<f64>; 3] {
    let (phi, theta, sigma) = (q[3], q[4], q[5]);
    let dz = |a: f64| {
        let (s, c) = a.sin_cos();
        Matrix3::new(-s, -c, 0.0, c, -s, 0.0, 0.0, 0.0, 0.0)
    };
    let dy = |a: f64| {
        let (s, c) = a.sin_cos();
        Matrix3::new(-s, 0.0, c, 0.0, 0.0, 0.0, -c, 0.0, -s)
    };
    let (z1, y, z2) = (rot_z(phi), rot_y(theta), rot_z(sigma - phi));
    [dz(phi) * y * z2 - z1 * y * dz(sigma - phi), z1 * dy(theta) * z2, z1 * y * dz(sigma - phi)]
}

impl Manifold for CableManifold {
    fn ambient(&self) -> usize {
        self.free.len() + self.barriers.len()
    }

    fn equations(&self) -> usize {
        self.barriers.len()
    }

    fn eval(&self, x: &[f64], f: &mut [f64], jac: &mut DMatrix<f64>) -> bool {
        let k = self.free.len();
        if x.iter().any(|v| !v.is_finite()) || x[k..].iter().any(|w| w / self.kappa > 600.0) {
            return false;
        }
        let Some(m) = self.margins(&self.coords(x), true) else { return false };
        jac.fill(0.0);
        for (j, (mu, g)) in m.values.iter().zip(&m.gradients).enumerate() {
            let s = (x[k + j] / self.kappa).exp();
            f[j] = mu * s - 1.0;
            for (col, &c) in self.free.iter().enumerate() {
                jac[(j, col)] = s * g[c];
            }
            jac[(j, k + j)] = mu * s / self.kappa;
        }
        true
    }

    fn difference(&self, a: &[f64], b: &[f64], out: &mut [f64]) {
        for (i, o) in out.iter_mut().enumerate() {
            let d = a[i] - b[i];
            *o = if self.periodic && i < self.free.len() && Coord::ALL[self.free[i]].is_angle() { wrap_angle(d) } else { d };
        }
    }

    /// sqrt(‖Δp‖² + (L·angle)²), with angle the rotation angle between the two orientations and L
    /// the rotation length: a metric on SE(3), so A*'s straight-line heuristic is admissible.
    fn distance(&self, a: &[f64], b: &[f64]) -> f64 {
        let (qa, qb) = (self.coords(a), self.coords(b));
        let dp = Vector3::new(qa[0] - qb[0], qa[1] - qb[1], qa[2] - qb[2]).norm();
        let ra = Pose::from_coords(qa).rotation;
        let rb = Pose::from_coords(qb).rotation;
        dp.hypot(self.rotation_length * ra.angle_to(&rb))
    }

    fn within_bounds(&self, x: &[f64]) -> bool {
        x[self.free.len()..].iter().all(|&w| w <= self.w_max)
    }

    fn admissible(&self, x: &[f64]) -> bool {
        let cables = cables_at(&self.robot, &Pose::from_coords(self.coords(x)));
        self.conditions.iter().all(|c| !c.check(&cables).violated)
    }

    /// The exact verifier on the slerp + linear motion between the two poses: valid if it finds
    /// no infeasible and no uncertain section.
    fn motion_valid(&self, a: &[f64], b: &[f64]) -> bool {
        if self.conditions.is_empty() {
            return true;
        }
        let (pa, pb) = (Pose::from_coords(self.coords(a)), Pose::from_coords(self.coords(b)));
        verify_trajectory(&self.scenario, &edge_trajectory(0, &pa, &pb)).is_ok_and(|r| r.infeasible.is_empty() && r.uncertain.is_empty())
    }
}
