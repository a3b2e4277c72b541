//! Feasibility conditions. Each is one implementation of [`Condition`], which answers both
//! questions the rest of the core asks:
//!
//! * exactly, along a [`Motion`]: the set of λ ∈ [0, 1] where the condition is violated, as a
//!   certified three-valued [`Partition`];
//! * point-wise, at one pose: violated or not, and a distance where one is meaningful.
//!
//! The verifier, the point-wise baseline, the ray and the per-pose check all go through this
//! trait and never look inside a condition.

pub mod algebra;
mod cable_cable;
mod cable_length;
mod cable_shape;
pub mod primitives;

pub use cable_cable::CableCable;
pub use cable_length::CableLength;
pub use cable_shape::CableShape;

use crate::model::{Motion, Pose, Robot};
use crate::poly::Partition;
use crate::scenario::Scenario;
use algebra::{Alg, HVec};
use nalgebra::Vector3;

/// An axis-aligned box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    /// Lower corner.
    pub min: Vector3<f64>,
    /// Upper corner.
    pub max: Vector3<f64>,
}

impl Aabb {
    /// The smallest box holding all the points.
    pub fn around<'a>(points: impl IntoIterator<Item = &'a Vector3<f64>>) -> Aabb {
        let mut b = Aabb { min: Vector3::repeat(f64::INFINITY), max: Vector3::repeat(f64::NEG_INFINITY) };
        for p in points {
            b.min = b.min.inf(p);
            b.max = b.max.sup(p);
        }
        b
    }

    /// Grown by `r` on every side.
    pub fn inflate(&self, r: f64) -> Aabb {
        Aabb { min: self.min.add_scalar(-r), max: self.max.add_scalar(r) }
    }

    /// Whether the boxes are farther apart than `gap` along some axis (so every pair of points
    /// in them is farther apart than `gap`).
    pub fn apart(&self, o: &Aabb, gap: f64) -> bool {
        (0..3).any(|k| self.min[k] - o.max[k] > gap || o.min[k] - self.max[k] > gap)
    }
}

/// One cable along a motion: the segment base → base + s(λ), with s as a fraction over w.
#[derive(Debug, Clone)]
pub struct SweptCable {
    /// The base anchor.
    pub base: Vector3<f64>,
    /// The cable vector s = p + R b − a (one power of w).
    pub s: HVec,
    /// A box holding the cable for every λ, when one could be certified.
    pub bounds: Option<Aabb>,
}

/// Everything the exact conditions share along one motion.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// Powers of the motion's denominator.
    pub alg: Alg,
    /// The cables, in robot order.
    pub cables: Vec<SweptCable>,
    /// Width (in λ) below which an undecided piece is reported rather than subdivided further.
    pub tol: f64,
}

impl Sweep {
    /// Prepares the cables of `robot` along `motion`.
    pub fn new(robot: &Robot, motion: &Motion, tol: f64) -> Sweep {
        let w = &motion.weight;
        let cables = robot
            .cables
            .iter()
            .map(|cable| {
                // X̂ = P̂ + M̂ b (one power of w); s = X̂ − a·w
                let tip: [crate::poly::Bern; 3] = [0, 1, 2].map(|i| {
                    let mut acc = motion.position[i].clone();
                    for j in 0..3 {
                        acc = acc.add(&motion.rotation[i][j].scale(cable.platform[j]));
                    }
                    acc
                });
                let s: HVec = [0, 1, 2].map(|i| algebra::H { p: tip[i].sub(&w.scale(cable.base[i])), k: 1 });
                let bounds = hull_box(&tip, w).map(|b| {
                    let with_base = Aabb { min: b.min.inf(&cable.base), max: b.max.sup(&cable.base) };
                    with_base.inflate(1e-9 * (1.0 + with_base.max.abs().max() + with_base.min.abs().max()))
                });
                SweptCable { base: cable.base, s, bounds }
            })
            .collect();
        Sweep { alg: Alg::new(w), cables, tol }
    }
}

/// A box around the rational curve X̂/w when every weight coefficient is certainly positive (the
/// curve then stays in the convex hull of the points X̂_k/w_k).
fn hull_box(tip: &[crate::poly::Bern; 3], w: &crate::poly::Bern) -> Option<Aabb> {
    let n = tip.iter().map(|p| p.degree()).max().unwrap_or(0).max(w.degree());
    let w = w.elevate(n);
    if w.c.iter().any(|&x| x <= 2.0 * w.err) {
        return None;
    }
    let tip = tip.clone().map(|p| p.elevate(n));
    let pts: Vec<Vector3<f64>> = (0..=n).map(|k| Vector3::new(tip[0].c[k], tip[1].c[k], tip[2].c[k]) / w.c[k]).collect();
    Some(Aabb::around(pts.iter()))
}

/// The outcome of a condition at one pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoseCheck {
    /// Whether the condition is violated.
    pub violated: bool,
    /// The distance the condition is about (cable–cable, cable–obstacle, length), where one is
    /// computed exactly; `None` where only membership is decided.
    pub distance: Option<f64>,
}

/// The cables at one pose: base anchor and platform anchor in the world frame.
pub type PoseCables = [(Vector3<f64>, Vector3<f64>)];

/// The cables of `robot` at `pose`.
pub fn cables_at(robot: &Robot, pose: &Pose) -> Vec<(Vector3<f64>, Vector3<f64>)> {
    robot.cables.iter().map(|c| (c.base, pose.transform(&c.platform))).collect()
}

/// One feasibility condition.
pub trait Condition {
    /// How reports name it: `"cables 2-5"`, `"cable 3 - box"`, `"cable 4 length"`.
    fn label(&self) -> String;

    /// `true` if the violation set is exact; `false` if it is a conservative superset (the
    /// condition tests an enlarged shape), which reports say.
    fn exact(&self) -> bool {
        true
    }

    /// The set of λ ∈ [0, 1] where the condition is violated along the sweep's motion.
    fn violation(&self, sweep: &mut Sweep) -> Partition;

    /// The condition at one pose, given the cables there.
    fn check(&self, cables: &PoseCables) -> PoseCheck;
}

/// Every condition a scenario states: cable lengths (where bounded), cable–cable clearance for
/// each pair not sharing an anchor, and cable–obstacle clearance for each cable and obstacle.
pub fn for_scenario(s: &Scenario) -> Vec<Box<dyn Condition>> {
    let robot = &s.robot;
    let m = robot.cables.len();
    let mut out: Vec<Box<dyn Condition>> = Vec::new();
    for (i, cable) in robot.cables.iter().enumerate() {
        if cable.length.min > 0.0 || cable.length.max.is_finite() {
            out.push(Box::new(CableLength { cable: i, bounds: cable.length }));
        }
    }
    for i in 0..m {
        for j in (i + 1)..m {
            if !robot.share_anchor(i, j) {
                out.push(Box::new(CableCable { i, j, clearance: s.clearance.cable_cable }));
            }
        }
    }
    for obstacle in &s.obstacles {
        for i in 0..m {
            out.push(Box::new(CableShape::new(i, obstacle, s.clearance.cable_obstacle)));
        }
    }
    out
}
