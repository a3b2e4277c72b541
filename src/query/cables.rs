//! The cables at one pose, in the world frame: where each cable runs for a platform robot at a
//! pose or any robot at a configuration, with the tension ranges there computed once for all who
//! ask; and whether a cable is attached inside its own link's clearance zone. The conditions'
//! point-wise checks, the scenario's validation and the verifier all read a pose's cables here.

use std::cell::OnceCell;

use super::wrench::{tension_ranges_at, TensionRange};
use crate::model::chain::Frame;
use crate::model::{Anchor, Kinematics, Load, Pose, Robot};
use nalgebra::Vector3;

/// The cables at one pose — base anchor and platform anchor in the world frame, indexable as a
/// slice of pairs (for a multi-link robot, the two ends of each segment of each cable) — with the pose itself, every link's frame, and the tension ranges, computed at
/// most once per pose for all the tension conditions that ask.
#[derive(Debug, Clone)]
pub struct PoseCables {
    /// The pose (of the platform, or of a multi-link robot's first link).
    pub pose: Pose,
    /// (base anchor, platform anchor) per cable; for a multi-link robot (start, end) per segment
    /// ([`Robot::segments`]), as many as cables when none is routed.
    pub cables: Vec<(Vector3<f64>, Vector3<f64>)>,
    /// Every link's frame (the platform's alone for a platform robot).
    pub links: Vec<Frame>,
    /// How the platform moves there, on a timed trajectory; `None`: at rest.
    pub kinematics: Option<Kinematics>,
    tensions: OnceCell<Option<Vec<TensionRange>>>,
}

impl std::ops::Deref for PoseCables {
    type Target = [(Vector3<f64>, Vector3<f64>)];
    fn deref(&self) -> &Self::Target {
        &self.cables
    }
}

impl PoseCables {
    /// The cables' tension ranges under `load` (the scenario's only one), or `None` at a
    /// singular pose or when the robot has not as many cables as degrees of freedom.
    pub fn tension_ranges(&self, load: &Load) -> Option<&[TensionRange]> {
        self.tensions.get_or_init(|| tension_ranges_at(&self.cables, &load.wrench.point_at(&self.pose), &self.nominal(load), &load.wrench, load.rows())).as_deref()
    }

    /// The nominal wrench the cables balance here under `load` (with the platform's weight and,
    /// when moving, its inertia).
    pub fn nominal(&self, load: &Load) -> nalgebra::Vector6<f64> {
        load.nominal_at(&self.pose, self.kinematics.as_ref())
    }

    /// The same cables with the platform moving as `kin`.
    pub fn moving(mut self, kin: Kinematics) -> PoseCables {
        self.kinematics = Some(kin);
        self.tensions = OnceCell::new();
        self
    }
}

/// The cables of a platform robot at `pose`.
pub fn cables_at(robot: &Robot, pose: &Pose) -> PoseCables {
    PoseCables {
        pose: *pose,
        cables: robot.anchors(pose),
        links: vec![(pose.position, pose.matrix())],
        kinematics: None,
        tensions: OnceCell::new(),
    }
}

/// The cables of `robot` at configuration `q`: the pose coordinates (x, y, z, φ, θ, σ) of a
/// platform robot, the joint coordinates of a multi-link robot.
pub fn cables_at_config(robot: &Robot, q: &[f64]) -> PoseCables {
    match &robot.chain {
        Some(chain) => cables_of_chain(robot, chain.frames(q)),
        None => cables_at(robot, &Pose::from_coords([q[0], q[1], q[2], q[3], q[4], q[5]])),
    }
}

/// The cables of a multi-link `robot` with its links at `links`: one pair per segment
/// ([`Robot::segments`]), its two ends in the world frame.
fn cables_of_chain(robot: &Robot, links: Vec<Frame>) -> PoseCables {
    let (p, r) = links[0];
    let pose = Pose { position: p, rotation: nalgebra::UnitQuaternion::from_matrix(&r) };
    let world = |a: &Anchor| a.link.map_or(a.point, |l| links[l].0 + links[l].1 * a.point);
    PoseCables {
        pose,
        cables: robot.segments().iter().map(|s| (world(&s.from), world(&s.to))).collect(),
        links,
        kinematics: None,
        tensions: OnceCell::new(),
    }
}

/// Each cable's length at the pose `at` of `robot`: the sum of its segments' for a routed cable.
pub fn cable_lengths(robot: &Robot, at: &PoseCables) -> Vec<f64> {
    let mut out = vec![0.0; robot.cables.len()];
    for (seg, (a, x)) in robot.segments().iter().zip(at.iter()) {
        out[seg.cable] += (x - a).norm();
    }
    out
}

/// Whether the anchor `b` (in its link's frame) lies within distance `r` of the link's body
/// segment: the cable then starts inside the clearance zone of its own link.
pub fn attached_inside(b: &Vector3<f64>, body: &[Vector3<f64>; 2], r: f64) -> bool {
    super::point_segment_dist2(b, &body[0], &(body[1] - body[0]), None) < r * r
}

/// A cable's length rates (l̇, l̈) at `pose` moving as `kin`, the cable from the base anchor `a`
/// to the platform anchor `x` (world frame): with e the unit cable direction and v_b, a_b the
/// anchor's velocity and acceleration, l̇ = e·v_b and l̈ = e·a_b + (|v_b|² − l̇²)/l.
pub fn cable_rates(pose: &crate::model::Pose, kin: &crate::model::Kinematics, a: &Vector3<f64>, x: &Vector3<f64>) -> (f64, f64) {
    let b = pose.rotation.inverse_transform_vector(&(x - pose.position));
    let (v, acc) = kin.of_point(pose, &b);
    let len = (x - a).norm();
    let e = (x - a) / len;
    let speed = e.dot(&v);
    (speed, e.dot(&acc) + (v.norm_squared() - speed * speed) / len)
}
