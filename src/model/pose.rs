//! Platform poses and the three orientation conventions a scenario may use.
//!
//! * unit quaternion `[w, x, y, z]`;
//! * tilt-and-torsion (φ, θ, σ) with R = Rz(φ)·Ry(θ)·Rz(σ−φ) (Bohigas et al., eq. 1);
//! * XYZ Euler angles in degrees, R = Rx(α)·Ry(β)·Rz(γ) (rotations about the moving axes).

use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector3};
use std::f64::consts::PI;

/// One of the six pose coordinates (x, y, z, φ, θ, σ) — position and tilt-and-torsion angles —
/// or a joint coordinate of a multi-link robot.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Coord {
    /// Joint coordinate `index` (0-based, in [`crate::model::Chain::coords`] order) of a
    /// multi-link robot, an angle or a length; its scenario name is
    /// [`crate::Scenario::coord_name`]'s.
    Joint {
        /// Index into the configuration.
        index: u8,
        /// Whether it is an angle (radians).
        angle: bool,
    },
    /// Position x.
    X,
    /// Position y.
    Y,
    /// Position z.
    Z,
    /// Tilt azimuth φ.
    Phi,
    /// Tilt angle θ.
    Theta,
    /// Torsion σ.
    Sigma,
}

impl Coord {
    /// All six, in the order of [`Pose::coords`].
    pub const ALL: [Coord; 6] = [Coord::X, Coord::Y, Coord::Z, Coord::Phi, Coord::Theta, Coord::Sigma];

    /// Parses `x`, `y`, `z`, `phi`, `theta` or `sigma`.
    pub fn parse(name: &str) -> Option<Coord> {
        Coord::ALL.into_iter().find(|c| c.name() == name)
    }

    /// The name used in scenarios and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Coord::X => "x",
            Coord::Y => "y",
            Coord::Z => "z",
            Coord::Phi => "phi",
            Coord::Theta => "theta",
            Coord::Sigma => "sigma",
            Coord::Joint { index, .. } => JOINT_NAMES.get(index as usize).copied().unwrap_or("q?"),
        }
    }

    /// Index into [`Pose::coords`], or into a multi-link robot's configuration.
    pub fn index(self) -> usize {
        match self {
            Coord::Joint { index, .. } => index as usize,
            _ => Coord::ALL.iter().position(|&c| c == self).unwrap_or(0),
        }
    }

    /// Whether this coordinate is an angle (radians).
    pub fn is_angle(self) -> bool {
        match self {
            Coord::Joint { angle, .. } => angle,
            _ => self.index() >= 3,
        }
    }
}

/// Generic names of joint coordinates (`q1` … `q64`), for messages that have no scenario at hand.
const JOINT_NAMES: [&str; 64] = [
    "q1", "q2", "q3", "q4", "q5", "q6", "q7", "q8", "q9", "q10", "q11", "q12", "q13", "q14", "q15", "q16", "q17", "q18", "q19", "q20", "q21", "q22",
    "q23", "q24", "q25", "q26", "q27", "q28", "q29", "q30", "q31", "q32", "q33", "q34", "q35", "q36", "q37", "q38", "q39", "q40", "q41", "q42", "q43",
    "q44", "q45", "q46", "q47", "q48", "q49", "q50", "q51", "q52", "q53", "q54", "q55", "q56", "q57", "q58", "q59", "q60", "q61", "q62", "q63", "q64",
];

/// A platform pose: position of the platform origin and orientation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// Position p of the platform frame's origin in the world frame.
    pub position: Vector3<f64>,
    /// Orientation R as a unit quaternion.
    pub rotation: UnitQuaternion<f64>,
}

/// Rotation about z by `a` radians.
pub fn rot_z(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
}

/// Rotation about y by `a` radians.
pub fn rot_y(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c)
}

/// Rotation about x by `a` radians.
pub fn rot_x(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c)
}

/// Wraps an angle into (−π, π].
pub fn wrap_angle(a: f64) -> f64 {
    let w = a.rem_euclid(2.0 * PI);
    if w > PI {
        w - 2.0 * PI
    } else {
        w
    }
}

fn unit_from_matrix(m: Matrix3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(m))
}

impl Pose {
    /// A pose from a position and a quaternion `[w, x, y, z]`, which must be non-zero; it is
    /// normalised.
    pub fn from_quaternion(position: Vector3<f64>, wxyz: [f64; 4]) -> Pose {
        let q = Quaternion::new(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
        Pose { position, rotation: UnitQuaternion::from_quaternion(q) }
    }

    /// A pose from a position and tilt-and-torsion angles (φ, θ, σ) in radians.
    pub fn from_tilt_torsion(position: Vector3<f64>, [phi, theta, sigma]: [f64; 3]) -> Pose {
        let m = rot_z(phi) * rot_y(theta) * rot_z(sigma - phi);
        Pose { position, rotation: unit_from_matrix(m) }
    }

    /// A pose from a position and XYZ Euler angles in degrees: R = Rx(α)·Ry(β)·Rz(γ).
    pub fn from_euler_xyz_deg(position: Vector3<f64>, [a, b, c]: [f64; 3]) -> Pose {
        let m = rot_x(a.to_radians()) * rot_y(b.to_radians()) * rot_z(c.to_radians());
        Pose { position, rotation: unit_from_matrix(m) }
    }

    /// A pose from the six coordinates (x, y, z, φ, θ, σ).
    pub fn from_coords(c: [f64; 6]) -> Pose {
        Pose::from_tilt_torsion(Vector3::new(c[0], c[1], c[2]), [c[3], c[4], c[5]])
    }

    /// A pose from a configuration slice of a platform robot (x, y, z, φ, θ, σ; missing entries
    /// are 0).
    pub fn from_slice(c: &[f64]) -> Pose {
        Pose::from_coords(std::array::from_fn(|i| c.get(i).copied().unwrap_or(0.0)))
    }

    /// The rotation matrix R.
    pub fn matrix(&self) -> Matrix3<f64> {
        *self.rotation.to_rotation_matrix().matrix()
    }

    /// The quaternion as `[w, x, y, z]`.
    pub fn quaternion(&self) -> [f64; 4] {
        let q = self.rotation.quaternion();
        [q.w, q.i, q.j, q.k]
    }

    /// Tilt-and-torsion angles (φ, θ, σ) with θ ∈ [0, π] and φ, σ ∈ (−π, π]. Where θ = 0 or π,
    /// φ is not determined and is returned as 0.
    ///
    /// θ is taken with `atan2` (well conditioned near 0 and π, unlike `acos`), and σ − φ is read
    /// from Ry(θ)ᵀ·Rz(φ)ᵀ·R, so that rounding in φ near θ = 0 is compensated in σ and the angles
    /// reproduce R to machine precision.
    pub fn tilt_torsion(&self) -> [f64; 3] {
        let r = self.matrix();
        let s = r[(0, 2)].hypot(r[(1, 2)]);
        let theta = s.atan2(r[(2, 2)]);
        if s < 1e-12 {
            let sigma = if r[(2, 2)] > 0.0 { r[(1, 0)].atan2(r[(0, 0)]) } else { r[(1, 0)].atan2(r[(1, 1)]) };
            return [0.0, theta, wrap_angle(sigma)];
        }
        let phi = r[(1, 2)].atan2(r[(0, 2)]);
        let (sp, cp) = phi.sin_cos();
        let (st, ct) = theta.sin_cos();
        let m10 = -sp * r[(0, 0)] + cp * r[(1, 0)];
        let m00 = ct * (cp * r[(0, 0)] + sp * r[(1, 0)]) - st * r[(2, 0)];
        [phi, theta, wrap_angle(phi + m10.atan2(m00))]
    }

    /// XYZ Euler angles in degrees (R = Rx(α)·Ry(β)·Rz(γ)), β ∈ [−90°, 90°]; at β = ±90° γ is 0.
    ///
    /// β is taken with `atan2` (well conditioned near ±90°, unlike `asin`), and γ is read from
    /// Rx(α)ᵀ·R, so that rounding in α near the gimbal lock is compensated in γ.
    pub fn euler_xyz_deg(&self) -> [f64; 3] {
        let r = self.matrix();
        let cb = r[(0, 0)].hypot(r[(0, 1)]);
        let b = r[(0, 2)].atan2(cb);
        if cb < 1e-12 {
            let a = r[(2, 1)].atan2(r[(1, 1)]);
            return [a.to_degrees(), b.to_degrees(), 0.0];
        }
        let a = (-r[(1, 2)]).atan2(r[(2, 2)]);
        let (sa, ca) = a.sin_cos();
        let c = (ca * r[(1, 0)] + sa * r[(2, 0)]).atan2(ca * r[(1, 1)] + sa * r[(2, 1)]);
        [a.to_degrees(), b.to_degrees(), c.to_degrees()]
    }

    /// The six coordinates (x, y, z, φ, θ, σ).
    pub fn coords(&self) -> [f64; 6] {
        let [phi, theta, sigma] = self.tilt_torsion();
        [self.position.x, self.position.y, self.position.z, phi, theta, sigma]
    }

    /// World position of a point given in the platform frame.
    pub fn transform(&self, local: &Vector3<f64>) -> Vector3<f64> {
        self.position + self.rotation * local
    }
}
