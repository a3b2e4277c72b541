//! What the planner plans over, and the few steps that depend on it: a platform robot's poses
//! (x, y, z, φ, θ, σ; the pose metric, line + slerp segments, Bézier pieces) or a multi-link
//! robot's joint configurations (a weighted Euclidean metric, paths through configurations — on
//! each leg every joint at once with tan-half-angle timing, `model::JointPath` — verified exactly).
//! The lattice, the joining, A* and the repair loop are the same for both.

use super::six;
use crate::model::pose::wrap_angle;
use crate::model::{Coord, JointPath, Orientation, Pose, Segment, Trajectory, Translation};
use crate::plan::edge_trajectory;
use crate::report::VerifyReport;
use crate::scenario::Scenario;
use crate::verify::{verify_along, verify_trajectory, Along};
use nalgebra::{UnitQuaternion, Vector3};
use std::f64::consts::PI;

/// A platform robot's poses or a multi-link robot's configurations.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Space {
    /// Poses (x, y, z, φ, θ, σ).
    Platform,
    /// Joint configurations; `angles[i]`: whether coordinate i is an angle.
    Chain { angles: Vec<bool> },
}

impl Space {
    /// The space of `s`'s robot.
    pub(super) fn of(s: &Scenario) -> Space {
        match &s.robot.chain {
            Some(chain) => Space::Chain { angles: (0..chain.dof()).map(|i| chain.is_angle(i)).collect() },
            None => Space::Platform,
        }
    }

    /// The distance that edge costs and the heuristic use: for poses √(|Δp|² + (L·angle)²), the
    /// angle the rotation between them; for configurations √(Σ (wᵢ·Δqᵢ)²), wᵢ = L for an angle
    /// (its difference taken in (−π, π]: q and q + 2π are one joint position, as the seam of a
    /// whole turn has it) and 1 for a length (L = `rotation_length`). Both are metrics, so A* on
    /// them is admissible and consistent.
    pub(super) fn metric(&self, a: &[f64], b: &[f64], rotation_length: f64) -> f64 {
        match self {
            Space::Platform => {
                let (a, b) = (Pose::from_coords(six(a)), Pose::from_coords(six(b)));
                (a.position - b.position).norm().hypot(rotation_length * a.rotation.angle_to(&b.rotation))
            }
            Space::Chain { angles } => a.iter().zip(b).zip(angles).map(|((x, y), &angle)| if angle { rotation_length * wrap_angle(y - x) } else { y - x }.powi(2)).sum::<f64>().sqrt(),
        }
    }

    /// The coordinates of start or goal `c` on the lattice's slice: every coordinate not in `axes`
    /// from `fixed`, the axes' from `c` — for a pose in whichever of its two tilt-and-torsion
    /// triples, (φ, θ, σ) or (φ + π, −θ, σ), agrees with the slice.
    pub(super) fn end_coords(&self, c: &[f64], fixed: &[f64], axes: &[Coord]) -> Vec<f64> {
        let mut out = fixed.to_vec();
        let pick = match self {
            Space::Chain { .. } => c.to_vec(),
            Space::Platform => {
                let fixed = six(fixed);
                let c = Pose::from_coords(six(c)).coords();
                let alt = [c[0], c[1], c[2], wrap_angle(c[3] + PI), -c[4], c[5]];
                let fits = |x: &[f64; 6]| Coord::ALL.iter().filter(|k| !axes.contains(k)).all(|k| {
                    let d = x[k.index()] - fixed[k.index()];
                    (if k.is_angle() { wrap_angle(d) } else { d }).abs() <= 1e-9
                });
                (if fits(&c) || !fits(&alt) { c } else { alt }).to_vec()
            }
        };
        for a in axes {
            out[a.index()] = pick[a.index()];
        }
        out
    }

    /// The exact verification of the straight motion from `a` to `b` (line + slerp; a path
    /// through the two configurations), `None` if the verifier refused it.
    pub(super) fn verify_segment(&self, s: &Scenario, a: &[f64], b: &[f64]) -> Option<VerifyReport> {
        match self {
            Space::Platform => verify_trajectory(s, &edge_trajectory(0, &Pose::from_coords(six(a)), &Pose::from_coords(six(b)))).ok(),
            Space::Chain { .. } => self.verify_run(s, &[a.to_vec(), b.to_vec()]),
        }
    }

    /// The exact verification of one smoothed piece through `points`: the Bézier curve with them
    /// as control points (poses), the path through them (configurations).
    pub(super) fn verify_run(&self, s: &Scenario, points: &[Vec<f64>]) -> Option<VerifyReport> {
        match self {
            Space::Platform => verify_trajectory(s, &bezier_trajectory(points, "piece")).ok(),
            Space::Chain { .. } => verify_along(s, Along::Joints(&JointPath { name: "piece".into(), through: points.to_vec(), proportional: false })).ok(),
        }
    }

    /// Whether halving a failing edge along one coordinate can repair it: for poses, where the
    /// slerp leaves an angle ray; a leg between two configurations that differ in one coordinate
    /// is that coordinate's ray itself, which halving does not change.
    pub(super) fn halves(&self) -> bool {
        matches!(self, Space::Platform)
    }

    /// Whether this is a multi-link robot's configuration space.
    pub(super) fn is_chain(&self) -> bool {
        matches!(self, Space::Chain { .. })
    }
}

/// The piece of a run of poses: Bézier translation through its points' positions as control
/// points (a line for two), slerp between its end rotations (the short way).
pub(super) fn bezier_segment(points: &[Vec<f64>]) -> Segment {
    let poses: Vec<Pose> = points.iter().map(|c| Pose::from_coords(six(c))).collect();
    let (first, last) = (poses[0], poses[poses.len() - 1]);
    let positions: Vec<Vector3<f64>> = poses.iter().map(|p| p.position).collect();
    let translation = if positions.len() == 2 { Translation::Line(positions[0], positions[1]) } else { Translation::Bezier(positions) };
    let qe = if first.rotation.quaternion().dot(last.rotation.quaternion()) < 0.0 { UnitQuaternion::new_unchecked(-last.rotation.into_inner()) } else { last.rotation };
    Segment { translation, orientation: Orientation::Slerp(first.rotation, qe) }
}

/// The run of poses through `points` as a trajectory of one piece called `name`.
pub(super) fn bezier_trajectory(points: &[Vec<f64>], name: &str) -> Trajectory {
    let seg = bezier_segment(points);
    Trajectory::single(name, seg.translation, seg.orientation)
}
