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
use super::pose::{Coord, Pose};
use crate::poly::Bern;
use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use smallvec::{smallvec, SmallVec};

/// How a link moves relative to its parent.
#[derive(Debug, Clone, PartialEq)]
pub enum Joint {
    /// Six coordinates (x, y, z, φ, θ, σ): a translation and tilt-and-torsion angles, as the
    /// platform of a parallel robot.
    Free,
    /// A ball joint with XYZ Euler angles (α, β, γ), R = Rx(α)·Ry(β)·Rz(γ) (CASPR `S_EULER_XYZ`).
    Spherical,
    /// A rotation by one angle about a unit axis of the joint frame (CASPR `R_X`, `R_Y`, `R_Z`,
    /// `R_AXIS`).
    Revolute(Vector3<f64>),
    /// A translation by one length along a unit axis of the joint frame.
    Prismatic(Vector3<f64>),
    /// Two rotations, about the first unit axis and then about the second (turned with the
    /// first): R = R(a₁, q₁)·R(a₂, q₂) (CASPR `U_XZ`, `U_YZ`, `U_XY`).
    Universal([Vector3<f64>; 2]),
    /// A translation in a plane and a rotation: by q₁ along the first unit axis, q₂ along the
    /// second, then R = R(a₃, q₃) (CASPR `PLANAR_YZ`: y, z, then about x).
    Planar([Vector3<f64>; 3]),
    /// Six coordinates (x, y, z, α, β, γ): a translation and XYZ Euler angles,
    /// R = Rx(α)·Ry(β)·Rz(γ) (CASPR `SPATIAL_EULER_XYZ` on a link of a tree).
    Spatial,
}

/// One coordinate's elementary motion, in the frame the joint's earlier coordinates have turned
/// to: a translation along a unit axis, or a rotation about one. Every joint but the free one is
/// a sequence of them, its translations first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Step {
    /// A translation along the axis.
    Slide(Vector3<f64>),
    /// A rotation about the axis.
    Turn(Vector3<f64>),
}

/// A joint's elementary motions, one per coordinate.
pub type Steps = SmallVec<[Step; 6]>;

impl Joint {
    /// The elementary motions of the joint's coordinates, in order; `None` for the free joint
    /// (tilt-and-torsion angles are no sequence of fixed-axis rotations).
    /// Kept in place (at most six), since the per-pose checks ask for them at every pose.
    pub fn steps(&self) -> Option<Steps> {
        let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
        Some(match self {
            Joint::Free => return None,
            Joint::Spherical => smallvec![Step::Turn(x), Step::Turn(y), Step::Turn(z)],
            Joint::Revolute(a) => smallvec![Step::Turn(*a)],
            Joint::Prismatic(a) => smallvec![Step::Slide(*a)],
            Joint::Universal([a, b]) => smallvec![Step::Turn(*a), Step::Turn(*b)],
            Joint::Planar([u, v, w]) => smallvec![Step::Slide(*u), Step::Slide(*v), Step::Turn(*w)],
            Joint::Spatial => smallvec![Step::Slide(x), Step::Slide(y), Step::Slide(z), Step::Turn(x), Step::Turn(y), Step::Turn(z)],
        })
    }

    /// Number of coordinates.
    pub fn dof(&self) -> usize {
        self.steps().map_or(6, |s| s.len())
    }

    /// Whether coordinate `k` of this joint is an angle (radians).
    pub fn is_angle(&self, k: usize) -> bool {
        match self.steps() {
            None => k >= 3,
            Some(steps) => matches!(steps.get(k), Some(Step::Turn(_))),
        }
    }

    /// The joint's translation and rotation at its coordinates `q` (relative to the joint frame
    /// placed at the link's `location` in its parent).
    pub fn transform(&self, q: &[f64]) -> (Vector3<f64>, Matrix3<f64>) {
        let Some(steps) = self.steps() else {
            let pose = Pose::from_coords([q[0], q[1], q[2], q[3], q[4], q[5]]);
            return (pose.position, pose.matrix());
        };
        let (mut position, mut rotation) = (Vector3::zeros(), Matrix3::identity());
        for (step, &v) in steps.iter().zip(q) {
            match step {
                Step::Slide(a) => position += rotation * a * v,
                Step::Turn(a) => rotation *= UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_unchecked(*a), v).to_rotation_matrix().matrix(),
            }
        }
        (position, rotation)
    }

    /// The joint's motion (translation and rotation relative to the joint frame) as coordinate `k`
    /// runs over [lo, hi] and the others stay at `q`: one piece for a translation, one per
    /// [`ANGLE_PIECE`] or less of range for an angle (the platform's own pieces for a free joint).
    fn ray(&self, q: &[f64], k: usize, lo: f64, hi: f64) -> Vec<Motion> {
        if let Joint::Free = self {
            let c = [q[0], q[1], q[2], q[3], q[4], q[5]];
            return Motion::ray_through(c, Coord::ALL[k], lo, hi);
        }
        if !self.is_angle(k) {
            return self.sweep(&with(q, k, lo), &with(q, k, hi), Param::Linear { lo, hi }).into_iter().collect();
        }
        let pieces = (((hi - lo).abs() / ANGLE_PIECE).ceil() as usize).max(1);
        (0..pieces)
            .filter_map(|p| {
                let start = lo + (hi - lo) * p as f64 / pieces as f64;
                let end = if p + 1 == pieces { hi } else { lo + (hi - lo) * (p + 1) as f64 / pieces as f64 };
                let h = ((end - start) / 2.0).tan();
                self.sweep(&with(q, k, start), &with(q, k, end), Param::Angle { start, end, h })
            })
            .collect()
    }

    /// The joint's motion from coordinates `from` to `to` (`None` if they are equal): every angle
    /// advances by the tan-half-angle ramp 2·atan(h·λ), h = tan(Δ/2), every length linearly —
    /// for a free joint the angles are φ, θ and σ − φ (R = Rz(φ)·Ry(θ)·Rz(σ − φ)). Steps of an
    /// angle should stay small (the callers keep them within [`ANGLE_PIECE`]). A joint's
    /// translations come before its rotations, so its translation is linear in λ.
    fn sweep(&self, from: &[f64], to: &[f64], param: Param) -> Option<Motion> {
        if from == to {
            return None;
        }
        let about = |axis: &Vector3<f64>, a: f64| quat_const(&UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_unchecked(*axis), a));
        // a rotation by `a` then by the ramp of `d` about `axis`, on the right of `n`
        let turn = |n: QuatPoly, axis: &Vector3<f64>, a: f64, d: f64| {
            let n = quat_mul(&n, &about(axis, a));
            if d == 0.0 { n } else { quat_mul(&n, &ramp_about(axis, (d / 2.0).tan())) }
        };
        let one: QuatPoly = [vec![1.0], vec![0.0], vec![0.0], vec![0.0]];
        let line = |a: &Vector3<f64>, b: &Vector3<f64>| [0, 1, 2].map(|i| Bern::from_bernstein(vec![a[i], b[i]]));
        let Some(steps) = self.steps() else {
            let (y, z) = (Vector3::y(), Vector3::z());
            let (pa, pb) = (Vector3::new(from[0], from[1], from[2]), Vector3::new(to[0], to[1], to[2]));
            let n = turn(one, &z, from[3], to[3] - from[3]);
            let n = turn(n, &y, from[4], to[4] - from[4]);
            return Some(Motion::from_parts(line(&pa, &pb), &turn(n, &z, from[5] - from[3], (to[5] - to[3]) - (from[5] - from[3])), param));
        };
        let (mut pa, mut pb, mut n) = (Vector3::zeros(), Vector3::zeros(), one);
        for (k, step) in steps.iter().enumerate() {
            match step {
                Step::Slide(a) => {
                    pa += a * from[k];
                    pb += a * to[k];
                }
                Step::Turn(a) => n = turn(n, a, from[k], to[k] - from[k]),
            }
        }
        Some(Motion::from_parts(line(&pa, &pb), &n, param))
    }
}

/// `q` with entry `k` set to `v`.
fn with(q: &[f64], k: usize, v: f64) -> Vec<f64> {
    let mut out = q.to_vec();
    out[k] = v;
    out
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
    /// Its mass (kg; 0 for a massless link).
    pub mass: f64,
    /// Its centre of mass, in the link's frame.
    pub com: Vector3<f64>,
}

/// A wrench applied to one link from outside (a payload, a tool's reaction): a force and a
/// moment in the world frame, the force acting at a point of the link (format 4 `wrench` with
/// `link`).
#[derive(Debug, Clone, PartialEq)]
pub struct LinkWrench {
    /// The link it acts on.
    pub link: usize,
    /// Force [fx, fy, fz] and moment [mx, my, mz], world frame.
    pub nominal: nalgebra::Vector6<f64>,
    /// The force's point, offset from the link's origin …
    pub point: Vector3<f64>,
    /// … in the link's frame (`Platform`) or along the world's axes (`World`).
    pub frame: super::PointFrame,
}

impl LinkWrench {
    /// The force, the moment and the force's world point with the link at `(origin, rotation)`.
    pub fn at(&self, (o, r): &Frame) -> (Vector3<f64>, Vector3<f64>, Vector3<f64>) {
        let point = match self.frame {
            super::PointFrame::Platform => o + r * self.point,
            super::PointFrame::World => o + self.point,
        };
        (self.nominal.fixed_rows::<3>(0).into(), self.nominal.fixed_rows::<3>(3).into(), point)
    }
}

/// The links of a multi-link robot, parents before children.
#[derive(Debug, Clone, PartialEq)]
pub struct Chain {
    /// The links.
    pub links: Vec<Link>,
    /// Gravity (world frame, m/s²), acting on the links' masses.
    pub gravity: Vector3<f64>,
    /// A wrench applied to one link from outside, if any.
    pub load: Option<LinkWrench>,
    /// Generalised forces applied to the joint coordinates from outside (format 6
    /// `joint_forces`: a torque about a revolute or universal joint's axis, a force along a
    /// prismatic or planar joint's axis), one per coordinate in configuration order; empty when
    /// none is applied.
    pub joint_forces: Vec<f64>,
    /// Whether joint-space wrench closure is a condition (format 6 `robot.closure`; true unless
    /// the file leaves it out: a loaded arm hanging from its cables holds its weight without it).
    pub closure: bool,
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
                mass: 0.0,
                com: Vector3::zeros(),
            }],
            gravity: Vector3::zeros(),
            load: None,
            joint_forces: Vec::new(),
            closure: true,
        }
    }

    /// Whether a load acts on the links — a weight (some link's mass under gravity), a wrench
    /// or joint forces from outside: the cables then hold it, and the chain's static feasibility
    /// is a condition.
    pub fn is_loaded(&self) -> bool {
        self.gravity != Vector3::zeros() && self.links.iter().any(|l| l.mass > 0.0) || self.load.is_some() || self.joint_forces.iter().any(|t| *t != 0.0)
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
        let o = self.offset(varied);
        let link = &self.links[varied];
        link.joint
            .ray(&q[o..o + link.joint.dof()], k, lo, hi)
            .into_iter()
            .map(|joint| {
                let param = joint.param;
                let mut locals = vec![None; self.links.len()];
                locals[varied] = Some(joint);
                self.compose(q, locals, param)
            })
            .collect()
    }

    /// Every link's motion from configuration `from` to `to`, all joints at once (each as
    /// [`Joint`]'s sweep: tan-half-angle ramps, linear lengths), λ mapped to the user's parameter
    /// by `param`. The angle steps should be at most [`ANGLE_PIECE`] (see [`JointPath`]).
    pub fn sweep(&self, from: &[f64], to: &[f64], param: Param) -> Vec<Motion> {
        let locals = self
            .links
            .iter()
            .enumerate()
            .map(|(l, link)| {
                let o = self.offset(l);
                let n = link.joint.dof();
                link.joint.sweep(&from[o..o + n], &to[o..o + n], param)
            })
            .collect();
        self.compose(from, locals, param)
    }

    /// The links' world motions from each joint's own motion (`None`: the joint stays at `q`),
    /// brought to one common weight: the product of the moving joints' weights; `param` maps
    /// their λ to the user's parameter (kept when no joint moves).
    pub(crate) fn compose(&self, q: &[f64], locals: Vec<Option<Motion>>, param: Param) -> Vec<Motion> {
        let frames = self.frames(q);
        // per link: its motion (None while constant) and which joints' weights it carries
        let mut moving: Vec<Option<(Motion, Vec<usize>)>> = Vec::with_capacity(self.links.len());
        for (l, link) in self.links.iter().enumerate() {
            let parent = link.parent.and_then(|p| moving[p].clone());
            let m = match (&locals[l], parent) {
                (None, None) => None,
                (None, Some((m, carried))) => {
                    let o = self.offset(l);
                    let (t, r) = link.joint.transform(&q[o..o + link.joint.dof()]);
                    Some((m.then(&(link.location + t), &r), carried))
                }
                (Some(j), None) => {
                    let (pp, rp) = link.parent.map_or((Vector3::zeros(), Matrix3::identity()), |p| frames[p]);
                    Some((j.placed(&(pp + rp * link.location), &rp), vec![l]))
                }
                (Some(j), Some((m, mut carried))) => {
                    carried.push(l);
                    Some((m.compose(&link.location, j), carried))
                }
            };
            moving.push(m);
        }
        let weights: Vec<(usize, &Bern)> = locals.iter().enumerate().filter_map(|(l, m)| m.as_ref().map(|m| (l, &m.weight))).collect();
        let product = |skip: &[usize]| {
            let mut factors = weights.iter().filter(|(l, _)| !skip.contains(l)).map(|(_, w)| *w);
            let first = factors.next().cloned().unwrap_or_else(|| Bern::constant(1.0));
            factors.fold(first, |acc, w| acc.mul(w))
        };
        let all = product(&[]);
        moving
            .into_iter()
            .enumerate()
            .map(|(l, m)| match m {
                None => Motion::fixed(&frames[l], &all, param),
                Some((m, carried)) if carried.len() == weights.len() => m,
                Some((m, carried)) => m.times(&product(&carried)),
            })
            .collect()
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    fn link(name: &str, parent: Option<usize>, location: [f64; 3], joint: Joint) -> Link {
        let coords = (0..joint.dof()).map(|k| JointCoord { name: format!("{name}{k}"), range: [-10.0, 10.0] }).collect();
        Link { name: name.into(), parent, location: Vector3::from(location), joint, coords, body: [Vector3::zeros(); 2], radius: 0.0, mass: 0.0, com: Vector3::zeros() }
    }

    /// A tree with every joint type: free root, spherical and prismatic children, a revolute
    /// grandchild, universal and planar links below them, a spatial root.
    pub(crate) fn tree() -> Chain {
        Chain {
            links: vec![
                link("f", None, [0.1, 0.2, 0.3], Joint::Free),
                link("s", Some(0), [0.0, 0.0, 0.7], Joint::Spherical),
                link("p", Some(0), [0.3, 0.0, 0.1], Joint::Prismatic(Vector3::new(0.6, 0.0, 0.8))),
                link("r", Some(1), [0.0, 0.1, 0.5], Joint::Revolute(Vector3::new(0.0, 0.6, -0.8))),
                link("u", Some(2), [0.1, 0.0, 0.2], Joint::Universal([Vector3::new(0.0, 0.8, 0.6), Vector3::z()])),
                link("l", Some(3), [0.0, 0.2, 0.1], Joint::Planar([Vector3::y(), Vector3::z(), Vector3::x()])),
                link("e", None, [0.4, -0.2, 0.0], Joint::Spatial),
            ],
            gravity: Vector3::zeros(),
            load: None,
            joint_forces: Vec::new(),
            closure: true,
        }
    }

    pub(crate) fn close(m: &Motion, lam: f64, (p, r): &Frame) -> bool {
        let (mp, mr) = m.eval(lam);
        (mp - p).norm() < 1e-11 && (mr - r).norm() < 1e-11
    }

    /// Rotation matrices written out, as CASPR's joint classes write them.
    fn rx(a: f64) -> Matrix3<f64> {
        Matrix3::new(1.0, 0.0, 0.0, 0.0, a.cos(), -a.sin(), 0.0, a.sin(), a.cos())
    }
    fn ry(a: f64) -> Matrix3<f64> {
        Matrix3::new(a.cos(), 0.0, a.sin(), 0.0, 1.0, 0.0, -a.sin(), 0.0, a.cos())
    }
    fn rz(a: f64) -> Matrix3<f64> {
        Matrix3::new(a.cos(), -a.sin(), 0.0, a.sin(), a.cos(), 0.0, 0.0, 0.0, 1.0)
    }

    #[test]
    fn joints_move_as_caspr_defines_them() {
        let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
        let same = |(p, r): (Vector3<f64>, Matrix3<f64>), (wp, wr): (Vector3<f64>, Matrix3<f64>)| (p - wp).norm() < 1e-14 && (r - wr).norm() < 1e-14;
        // UniversalXZ: R = Rx(α)·Rz(γ); UniversalYZ: Ry(β)·Rz(γ); no translation
        assert!(same(Joint::Universal([x, z]).transform(&[0.3, -0.7]), (Vector3::zeros(), rx(0.3) * rz(-0.7))));
        assert!(same(Joint::Universal([y, z]).transform(&[1.1, 0.4]), (Vector3::zeros(), ry(1.1) * rz(0.4))));
        // PlanarYZ: r = (0, y, z), R = Rx(θ); PlanarXZ: r = (x, 0, z), R = Ry(θ)
        assert!(same(Joint::Planar([y, z, x]).transform(&[0.2, -0.5, 0.9]), (Vector3::new(0.0, 0.2, -0.5), rx(0.9))));
        assert!(same(Joint::Planar([x, z, y]).transform(&[0.2, -0.5, 0.9]), (Vector3::new(0.2, 0.0, -0.5), ry(0.9))));
        // SpatialEulerXYZ: r = (x, y, z), R = Rx(α)·Ry(β)·Rz(γ)
        assert!(same(Joint::Spatial.transform(&[1.0, 2.0, 3.0, 0.1, -0.2, 0.3]), (Vector3::new(1.0, 2.0, 3.0), rx(0.1) * ry(-0.2) * rz(0.3))));
        assert!(same(Joint::Spherical.transform(&[0.1, -0.2, 0.3]), (Vector3::zeros(), rx(0.1) * ry(-0.2) * rz(0.3))));
        // RevoluteAxis: Rodrigues' formula about the unit axis
        let a = Vector3::new(0.05101, -0.9984, 0.02231).normalize();
        let k = a.cross_matrix();
        let t = 1.3_f64;
        assert!(same(Joint::Revolute(a).transform(&[t]), (Vector3::zeros(), Matrix3::identity() + t.sin() * k + (1.0 - t.cos()) * k * k)));
        assert_eq!((Joint::Universal([x, z]).dof(), Joint::Planar([y, z, x]).dof(), Joint::Spatial.dof()), (2, 3, 6));
        assert!(!Joint::Planar([y, z, x]).is_angle(1) && Joint::Planar([y, z, x]).is_angle(2) && !Joint::Spatial.is_angle(2) && Joint::Spatial.is_angle(3));
    }

    #[test]
    fn rays_follow_the_links_frames() {
        let chain = tree();
        let q = [0.2, -0.1, 0.4, 0.3, 0.5, -0.2, 0.3, -0.4, 0.2, 0.15, 0.7, 0.4, -0.6, 0.1, -0.2, 0.8, 0.5, 0.6, 0.7, -0.3, 0.2, 0.4];
        assert_eq!(chain.dof(), q.len());
        for i in 0..chain.dof() {
            let (lo, hi) = (q[i] - 0.9, q[i] + 0.6);
            for piece in chain.ray(&q, i, lo, hi) {
                assert!(piece.iter().all(|m| m.weight == piece[0].weight));
                for k in 0..=4 {
                    let lam = k as f64 / 4.0;
                    let frames = chain.frames(&with(&q, i, piece[0].param.value(lam)));
                    for (l, m) in piece.iter().enumerate() {
                        assert!(close(m, lam, &frames[l]), "coordinate {i}, link {l}, λ = {lam}");
                    }
                }
            }
        }
    }

}
