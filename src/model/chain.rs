//! Multi-link robots (thesis §3.2, §3.5.2): rigid links joined in a tree by passive joints, each
//! link's frame at its joint. The configuration is the vector of every joint's coordinates, in
//! link order; the platform robot is the one-link chain with a free joint.
//!
//! Poses of links (CASPR's convention, `../shared/notes/caspr-mcdr-conventions.md`):
//! R_k = R_parent · R_joint(q_k) and p_k = p_parent + R_parent · (location + t_joint(q_k)), with
//! the base (p = 0, R = I) as the parent of root links.
//!
//! Along a ray of one joint coordinate every link moves as a rational polynomial [`Motion`] with
//! one common weight (thesis Theorems 1–2): the varied joint's motion is a tan-half-angle ramp
//! (rotations) or a linear one (translations); links upstream of it stay constant (scaled by the
//! weight), links downstream compose the varied one with constant transforms. The exact conditions
//! see no difference between a platform and a link.

use super::motion::{quat_const, quat_mul, ramp_about, Motion, Param, QuatPoly, ANGLE_PIECE};
use super::pose::{rot_x, rot_y, rot_z, Coord, Pose};
use crate::poly::Bern;
use nalgebra::{Matrix3, UnitQuaternion, Vector3};

/// How a link moves relative to its parent.
#[derive(Debug, Clone, PartialEq)]
pub enum Joint {
    /// Six coordinates (x, y, z, φ, θ, σ): a translation and tilt-and-torsion angles, as the
    /// platform of a parallel robot.
    Free,
    /// A ball joint with XYZ Euler angles (α, β, γ), R = Rx(α)·Ry(β)·Rz(γ) (CASPR `S_EULER_XYZ`).
    Spherical,
    /// A rotation by one angle about a unit axis of the joint frame (CASPR `R_X`, `R_Y`, `R_Z`).
    Revolute(Vector3<f64>),
    /// A translation by one length along a unit axis of the joint frame.
    Prismatic(Vector3<f64>),
}

impl Joint {
    /// Number of coordinates.
    pub fn dof(&self) -> usize {
        match self {
            Joint::Free => 6,
            Joint::Spherical => 3,
            Joint::Revolute(_) | Joint::Prismatic(_) => 1,
        }
    }

    /// Whether coordinate `k` of this joint is an angle (radians).
    pub fn is_angle(&self, k: usize) -> bool {
        match self {
            Joint::Free => k >= 3,
            Joint::Spherical | Joint::Revolute(_) => true,
            Joint::Prismatic(_) => false,
        }
    }

    /// The joint's translation and rotation at its coordinates `q` (relative to the joint frame
    /// placed at the link's `location` in its parent).
    pub fn transform(&self, q: &[f64]) -> (Vector3<f64>, Matrix3<f64>) {
        match self {
            Joint::Free => {
                let pose = Pose::from_coords([q[0], q[1], q[2], q[3], q[4], q[5]]);
                (pose.position, pose.matrix())
            }
            Joint::Spherical => (Vector3::zeros(), rot_x(q[0]) * rot_y(q[1]) * rot_z(q[2])),
            Joint::Revolute(axis) => {
                let r = UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_unchecked(*axis), q[0]);
                (Vector3::zeros(), *r.to_rotation_matrix().matrix())
            }
            Joint::Prismatic(axis) => (axis * q[0], Matrix3::identity()),
        }
    }

    /// The joint's motion (translation and rotation relative to the joint frame) as coordinate `k`
    /// runs over [lo, hi] and the others stay at `q`: one piece for a translation, one per
    /// [`ANGLE_PIECE`] or less of range for an angle.
    fn ray(&self, q: &[f64], k: usize, lo: f64, hi: f64) -> Vec<Motion> {
        if let Joint::Free = self {
            let c = [q[0], q[1], q[2], q[3], q[4], q[5]];
            return Motion::ray_through(c, Coord::ALL[k], lo, hi);
        }
        if let Joint::Prismatic(axis) = self {
            let position = [0, 1, 2].map(|i| Bern::from_bernstein(vec![axis[i] * lo, axis[i] * hi]));
            return vec![Motion::from_parts(position, &quat_const(&UnitQuaternion::identity()), Param::Linear { lo, hi })];
        }
        let pieces = (((hi - lo).abs() / ANGLE_PIECE).ceil() as usize).max(1);
        let zero = [0, 1, 2].map(|_| Bern::constant(0.0));
        (0..pieces)
            .map(|p| {
                let start = lo + (hi - lo) * p as f64 / pieces as f64;
                let end = if p + 1 == pieces { hi } else { lo + (hi - lo) * (p + 1) as f64 / pieces as f64 };
                let h = ((end - start) / 2.0).tan();
                let about = |axis: Vector3<f64>, a: f64| quat_const(&UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_unchecked(axis), a));
                let n: QuatPoly = match self {
                    Joint::Revolute(axis) => quat_mul(&about(*axis, start), &ramp_about(axis, h)),
                    _ => {
                        // Rx(α)·Ry(β)·Rz(γ) with the varied factor advanced by ψ(λ)
                        let axes = [Vector3::x(), Vector3::y(), Vector3::z()];
                        let mut n: QuatPoly = [vec![1.0], vec![0.0], vec![0.0], vec![0.0]];
                        for (i, axis) in axes.iter().enumerate() {
                            let angle = if i == k { start } else { q[i] };
                            n = quat_mul(&n, &about(*axis, angle));
                            if i == k {
                                n = quat_mul(&n, &ramp_about(axis, h));
                            }
                        }
                        n
                    }
                };
                Motion::from_parts(zero.clone(), &n, Param::Angle { start, end, h })
            })
            .collect()
    }
}

/// One named coordinate of a joint, with its allowed range.
#[derive(Debug, Clone, PartialEq)]
pub struct JointCoord {
    /// Its name (`alpha`, `theta`, …), unique in the robot.
    pub name: String,
    /// Allowed range [min, max].
    pub range: [f64; 2],
}

/// One rigid link.
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    /// Its name.
    pub name: String,
    /// Index of its parent link, `None` for the base.
    pub parent: Option<usize>,
    /// The joint's position in the parent's frame.
    pub location: Vector3<f64>,
    /// The joint.
    pub joint: Joint,
    /// The joint's coordinates, as many as [`Joint::dof`].
    pub coords: Vec<JointCoord>,
    /// The collision body: a segment in the link's frame (from, to) …
    pub body: [Vector3<f64>; 2],
    /// … with this radius (≥ 0).
    pub radius: f64,
}

/// The links of a multi-link robot, parents before children.
#[derive(Debug, Clone, PartialEq)]
pub struct Chain {
    /// The links.
    pub links: Vec<Link>,
}

/// A link's pose in the world: origin and rotation.
pub type Frame = (Vector3<f64>, Matrix3<f64>);

impl Chain {
    /// The platform robot as a chain: one link with a free joint, its body a point.
    pub fn platform() -> Chain {
        let coords = Coord::ALL
            .iter()
            .map(|c| JointCoord { name: c.name().to_string(), range: if c.is_angle() { [-std::f64::consts::PI, std::f64::consts::PI] } else { [f64::NEG_INFINITY, f64::INFINITY] } })
            .collect();
        Chain {
            links: vec![Link {
                name: "platform".into(),
                parent: None,
                location: Vector3::zeros(),
                joint: Joint::Free,
                coords,
                body: [Vector3::zeros(); 2],
                radius: 0.0,
            }],
        }
    }

    /// Total number of coordinates.
    pub fn dof(&self) -> usize {
        self.links.iter().map(|l| l.joint.dof()).sum()
    }

    /// Every coordinate with its link and its index in that link's joint, in configuration order.
    pub fn coords(&self) -> impl Iterator<Item = (usize, usize, &JointCoord)> {
        self.links.iter().enumerate().flat_map(|(l, link)| link.coords.iter().enumerate().map(move |(k, c)| (l, k, c)))
    }

    /// The index of the coordinate called `name`.
    pub fn coord_index(&self, name: &str) -> Option<usize> {
        self.coords().position(|(_, _, c)| c.name == name)
    }

    /// Whether coordinate `i` of the configuration is an angle.
    pub fn is_angle(&self, i: usize) -> bool {
        self.coords().nth(i).is_some_and(|(l, k, _)| self.links[l].joint.is_angle(k))
    }

    /// Where link `l`'s coordinates start in the configuration.
    fn offset(&self, l: usize) -> usize {
        self.links[..l].iter().map(|x| x.joint.dof()).sum()
    }

    /// Whether link `d` is `a` or lies downstream of it.
    pub fn descends(&self, mut d: usize, a: usize) -> bool {
        loop {
            if d == a {
                return true;
            }
            match self.links[d].parent {
                Some(p) => d = p,
                None => return false,
            }
        }
    }

    /// Every link's frame at configuration `q` (of length [`Chain::dof`]).
    pub fn frames(&self, q: &[f64]) -> Vec<Frame> {
        let mut out: Vec<Frame> = Vec::with_capacity(self.links.len());
        for (l, link) in self.links.iter().enumerate() {
            let (pp, rp) = link.parent.map_or((Vector3::zeros(), Matrix3::identity()), |p| out[p]);
            let o = self.offset(l);
            let (t, r) = link.joint.transform(&q[o..o + link.joint.dof()]);
            out.push((pp + rp * (link.location + t), rp * r));
        }
        out
    }

    /// Every link's motion as configuration coordinate `i` runs over [lo, hi], the others held at
    /// `q`: one list (a motion per link, all with the same weight and parameter) per piece of the
    /// ray.
    pub fn ray(&self, q: &[f64], i: usize, lo: f64, hi: f64) -> Vec<Vec<Motion>> {
        let Some((varied, k, _)) = self.coords().nth(i) else { return Vec::new() };
        let frames = self.frames(q);
        let o = self.offset(varied);
        let link = &self.links[varied];
        link.joint
            .ray(&q[o..o + link.joint.dof()], k, lo, hi)
            .into_iter()
            .map(|joint| {
                let w = joint.weight.clone();
                let mut out: Vec<Motion> = Vec::with_capacity(self.links.len());
                for (l, link) in self.links.iter().enumerate() {
                    let m = if l == varied {
                        let (pp, rp) = link.parent.map_or((Vector3::zeros(), Matrix3::identity()), |p| frames[p]);
                        joint.placed(&(pp + rp * link.location), &rp)
                    } else if self.descends(l, varied) {
                        let parent = link.parent.expect("a link below the varied one has a parent");
                        let lo_ = self.offset(l);
                        let (t, r) = link.joint.transform(&q[lo_..lo_ + link.joint.dof()]);
                        out[parent].then(&(link.location + t), &r)
                    } else {
                        Motion::fixed(&frames[l], &w, joint.param)
                    };
                    out.push(m);
                }
                out
            })
            .collect()
    }
}
