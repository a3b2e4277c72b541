//! What limits the speed at one point of the path, as half-planes in (u, x) = (λ̈, λ̇²): the
//! timing's whole view of the scenario's conditions there.
//!
//! Every speed-dependent condition is affine in (u, x) at a fixed point: the wrench the cables
//! must balance is W0 + A·u + B·x (weight and the wrench set's w0, plus the d'Alembert wrench,
//! whose accelerations are affine in λ̈ and λ̇² and whose ω × Iω is linear in λ̇²); a cable's
//! speed is l̇ = l̇₁·√x and its acceleration l̈ = a_u·u + a_x·x; the platform's speed is |dp/dλ|·√x.
//! The tensions' condition is hyperplane shifting (`crate::query::wrench::facets`): for every
//! facet pair of the zonotope {J f}, n·W + √(nᵀE⁻¹n) within [lower, upper] shrunk by the margin.
//! Each limit is tightened by a small relative margin, so that the exact verification of the
//! timed result, which needs strict inequalities, has room at the grid's points.

use super::path::Jet;
use crate::error::{Error, Result};
use crate::model::{Bounds, Load};
use crate::query::cables::cable_rates;
use crate::query::wrench::{binomial, facet_normal, facets, structure_matrix_m, subsets};
use crate::scenario::Scenario;
use nalgebra::{Matrix6, Vector3};

/// Most facet pairs the timing's tension limits enumerate at every point: C(m, n − 1) for m
/// cables and n degrees of freedom, 792 = C(12, 5) (12 cables on a spatial platform, 40 on a
/// point mass or a planar one).
pub const MAX_TIMING_FACETS: usize = 792;

/// What a half-plane stands for, to name the binding constraint.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum What {
    /// A facet of the available wrench set: the five-column set's index and which side.
    Facet {
        /// Index in `subsets(m, 5)`.
        set: usize,
        /// The upper side (n·W ≤ upper) or the lower.
        upper: bool,
    },
    /// Cable `0`'s speed.
    CableSpeed(usize),
    /// Cable `0`'s acceleration.
    CableAcceleration(usize),
    /// The platform's speed.
    PlatformSpeed,
    /// A cap the certification put on the speed there.
    Cap,
}

/// The half-plane a·u + b·x ≤ c.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HalfPlane {
    /// Coefficient of u = λ̈.
    pub a: f64,
    /// Coefficient of x = λ̇².
    pub b: f64,
    /// Right-hand side.
    pub c: f64,
    /// What it limits.
    pub what: What,
}

/// The speed-dependent limits of a scenario, with the margins they are tightened by.
pub struct Limits<'a> {
    scenario: &'a Scenario,
    load: Option<Load>,
    bounds: Vec<Bounds>,
    /// Tension margin (force units): tensions kept within [f_min + δ, f_max − δ].
    delta: f64,
    /// Relative margin on the winch and speed limits.
    relative: f64,
}

impl<'a> Limits<'a> {
    /// The limits of `s`, tightened by the relative margin `margin` (tensions by `margin` times
    /// the narrowest finite tension range). An error when nothing limits the speed, or the robot
    /// is beyond what the timing takes.
    pub fn new(s: &'a Scenario, margin: f64) -> Result<Limits<'a>> {
        let m = s.robot.cables.len();
        if s.robot.chain.is_some() {
            return Err(Error::new("--trajectory", "the fastest timing is for platform robots; a multi-link robot has no timed motion yet"));
        }
        let load = s.load();
        let n = s.robot.mobility.dof();
        if load.as_ref().is_some_and(|l| l.dynamics.is_some()) && binomial(m, n - 1) > MAX_TIMING_FACETS {
            return Err(Error::new("robot.cables", format!("the fastest timing's tension limits enumerate the C(m, {}) facets of the available wrench set at every point, at most {MAX_TIMING_FACETS} (12 cables on a spatial platform, 40 on a point mass or a planar one); {m} cables give {}", n - 1, binomial(m, n - 1))));
        }
        let limited = s.robot.dynamics.is_some() || s.robot.winch.speed.is_some() || s.robot.winch.acceleration.is_some() || s.robot.speed.is_some();
        if !limited {
            return Err(Error::new("robot", "nothing limits the speed: give the platform a mass (robot.dynamics), winch limits (robot.winch) or a speed limit (robot.speed)"));
        }
        let bounds: Vec<Bounds> = s.robot.cables.iter().map(|c| c.tension).collect();
        let range = bounds.iter().filter(|b| b.max.is_finite()).map(|b| b.max - b.min).fold(f64::INFINITY, f64::min);
        let scale = if range.is_finite() { range } else { bounds.iter().map(|b| b.min.abs()).fold(1.0, f64::max) };
        Ok(Limits { scenario: s, load, bounds, delta: margin * scale, relative: margin })
    }

    /// The half-planes at the point `jet`, appended to `out`; an error naming `t` when the
    /// structure matrix is singular there (the tensions cannot balance the load).
    pub fn at(&self, jet: &Jet, t: f64, out: &mut Vec<HalfPlane>) -> Result<()> {
        let robot = &self.scenario.robot;
        let pose = &jet.pose;
        let cables = robot.anchors(pose);
        if let Some(load) = self.load.as_ref().filter(|l| l.dynamics.is_some() || !l.is_zero()) {
            let point = load.wrench.point_at(pose);
            let w0 = load.nominal_at(pose, None);
            let coefficient = |u: f64, x: f64| load.nominal_at(pose, Some(&jet.kinematics(u, x))) - w0;
            let (au, bx) = (coefficient(1.0, 0.0), coefficient(0.0, 1.0));
            let j = structure_matrix_m(&cables, &point, load.rows());
            let Some(facets) = facets(&j, load.rows(), &self.bounds) else {
                return Err(Error::new("trajectory", format!("the structure matrix is singular at t = {t:.6}: no tensions balance the load there")));
            };
            let e_inv: &Matrix6<f64> = &load.wrench.ellipsoid_inv;
            for f in &facets {
                let reach = f.normal.dot(&(e_inv * f.normal)).max(0.0).sqrt();
                let shrink = reach + self.delta * f.spread;
                let (a, b, centre) = (f.normal.dot(&au), f.normal.dot(&bx), f.normal.dot(&w0));
                if f.upper.is_finite() {
                    out.push(HalfPlane { a, b, c: f.upper - shrink - centre, what: What::Facet { set: f.set, upper: true } });
                }
                if f.lower.is_finite() {
                    out.push(HalfPlane { a: -a, b: -b, c: centre - f.lower - shrink, what: What::Facet { set: f.set, upper: false } });
                }
            }
        }
        let keep = 1.0 - self.relative;
        let (speed, accel) = (robot.winch.speed, robot.winch.acceleration);
        if speed.is_some() || accel.is_some() {
            for (i, (a, x)) in cables.iter().enumerate() {
                let (l1, lx) = cable_rates(pose, &jet.kinematics(0.0, 1.0), a, x);
                let (_, lu) = cable_rates(pose, &jet.kinematics(1.0, 0.0), a, x);
                if let Some(v) = speed {
                    out.push(HalfPlane { a: 0.0, b: l1 * l1, c: (v * keep).powi(2), what: What::CableSpeed(i) });
                }
                if let Some(acc) = accel {
                    out.push(HalfPlane { a: lu, b: lx, c: acc * keep, what: What::CableAcceleration(i) });
                    out.push(HalfPlane { a: -lu, b: -lx, c: acc * keep, what: What::CableAcceleration(i) });
                }
            }
        }
        if let Some(v) = robot.speed {
            out.push(HalfPlane { a: 0.0, b: jet.dp.norm_squared(), c: (v * keep).powi(2), what: What::PlatformSpeed });
        }
        Ok(())
    }

    /// How a report names `what` at the point `jet`: for a facet, the cables off its hyperplane
    /// and the bound each sits at when the facet binds ("cable 3 max, cable 7 min tension").
    pub fn name(&self, what: What, jet: &Jet) -> String {
        match what {
            What::Facet { set, upper } => {
                let robot = &self.scenario.robot;
                let m = robot.cables.len();
                let cables = robot.anchors(&jet.pose);
                let point = self.load.as_ref().map_or(Vector3::zeros(), |l| l.wrench.point_at(&jet.pose));
                let j = structure_matrix_m(&cables, &point, robot.mobility.rows());
                let Some(s) = subsets(m, j.nrows() - 1).into_iter().nth(set) else { return "tensions".to_string() };
                let n = facet_normal(&j, &s);
                let sides: Vec<String> = (0..m)
                    .filter(|k| !s.contains(k))
                    .filter_map(|k| {
                        let d = n.dot(&j.column(k));
                        (d != 0.0).then(|| format!("cable {} {}", k + 1, if (d > 0.0) == upper { "max" } else { "min" }))
                    })
                    .collect();
                format!("{} tension", sides.join(", "))
            }
            What::CableSpeed(i) => format!("cable {} speed", i + 1),
            What::CableAcceleration(i) => format!("cable {} acceleration", i + 1),
            What::PlatformSpeed => "platform speed".to_string(),
            What::Cap => "slowed to certify".to_string(),
        }
    }
}
