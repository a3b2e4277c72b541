//! The platform as a rigid body: its mass, centre of mass and inertia, gravity, the winches'
//! limits, and the wrench the cables must balance at one instant of a motion.
//!
//! Convention (as for the wrench set, docs/wrench.md): tensions f balance a wrench w when
//! J f = w, w being what acts on the platform from outside, taken about the wrench set's
//! application point c. The platform's own weight and its inertia add the d'Alembert wrench
//!
//!   F = m (g − ẍ_c),   M = (x_c − c) × F − (I α + ω × I ω),
//!
//! x_c the centre of mass in the world, I = R I_b Rᵀ its inertia in the world frame, ω and α the
//! platform's angular velocity and acceleration (world frame). At rest (ẍ_c, ω, α = 0) only the
//! weight remains.

use super::pose::Pose;
use nalgebra::{Matrix3, Vector3, Vector6};

/// The platform's rigid-body data (format 4 `robot.dynamics`).
#[derive(Debug, Clone, PartialEq)]
pub struct Dynamics {
    /// Mass m > 0 (kg).
    pub mass: f64,
    /// Centre of mass in the platform frame (m).
    pub com: Vector3<f64>,
    /// Inertia tensor about the centre of mass, platform frame (kg·m²), symmetric positive
    /// definite.
    pub inertia: Matrix3<f64>,
    /// Gravity in the world frame (m/s²).
    pub gravity: Vector3<f64>,
}

/// Limits of the winches (format 4 `robot.winch`): |l̇| and |l̈| of every cable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Winch {
    /// Largest cable speed |l̇| (m/s), if limited.
    pub speed: Option<f64>,
    /// Largest cable acceleration |l̈| (m/s²), if limited.
    pub acceleration: Option<f64>,
}

/// The platform's motion at one instant, in the world frame: the velocity and acceleration of
/// its origin, its angular velocity and angular acceleration.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Kinematics {
    /// ṗ (m/s).
    pub velocity: Vector3<f64>,
    /// p̈ (m/s²).
    pub acceleration: Vector3<f64>,
    /// ω (rad/s).
    pub omega: Vector3<f64>,
    /// α = ω̇ (rad/s²).
    pub alpha: Vector3<f64>,
}

impl Kinematics {
    /// The velocity and acceleration of the platform point `b` (platform frame) at `pose`.
    pub fn of_point(&self, pose: &Pose, b: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        let r = pose.rotation * b;
        let v = self.velocity + self.omega.cross(&r);
        let a = self.acceleration + self.alpha.cross(&r) + self.omega.cross(&self.omega.cross(&r));
        (v, a)
    }
}

impl Dynamics {
    /// The wrench of weight and inertia (the d'Alembert wrench above) about `point` at `pose`,
    /// moving as `kin` (`None`: at rest, the weight alone).
    pub fn wrench(&self, pose: &Pose, kin: Option<&Kinematics>, point: &Vector3<f64>) -> Vector6<f64> {
        let x_c = pose.transform(&self.com);
        let (accel, moment) = match kin {
            None => (Vector3::zeros(), Vector3::zeros()),
            Some(k) => {
                let (_, a_c) = k.of_point(pose, &self.com);
                let r = pose.rotation.to_rotation_matrix().into_inner();
                let inertia: Matrix3<f64> = r * self.inertia * r.transpose();
                (a_c, inertia * k.alpha + k.omega.cross(&(inertia * k.omega)))
            }
        };
        let force = (self.gravity - accel) * self.mass;
        let m = (x_c - point).cross(&force) - moment;
        Vector6::new(force.x, force.y, force.z, m.x, m.y, m.z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::UnitQuaternion;

    fn body() -> Dynamics {
        Dynamics {
            mass: 2.0,
            com: Vector3::new(0.1, -0.2, 0.3),
            inertia: Matrix3::new(0.5, 0.01, 0.02, 0.01, 0.4, -0.03, 0.02, -0.03, 0.3),
            gravity: Vector3::new(0.0, 0.0, -9.81),
        }
    }

    #[test]
    fn at_rest_the_weight_acts_at_the_centre_of_mass() {
        let d = body();
        let pose = Pose { position: Vector3::new(1.0, 2.0, 3.0), rotation: UnitQuaternion::from_euler_angles(0.3, -0.1, 0.7) };
        let c = Vector3::new(1.0, 2.0, 3.5);
        let w = d.wrench(&pose, None, &c);
        let x_c = pose.transform(&d.com);
        let f = Vector3::new(0.0, 0.0, -9.81 * 2.0);
        assert!((w.fixed_rows::<3>(0) - f).norm() < 1e-12);
        assert!((w.fixed_rows::<3>(3) - (x_c - c).cross(&f)).norm() < 1e-12);
        // standing still is the same as at rest
        assert_eq!(d.wrench(&pose, Some(&Kinematics::default()), &c), w);
    }

    #[test]
    fn inertial_wrench_is_the_rate_of_change_of_momentum() {
        // A body spinning about a fixed axis with changing rate: finite differences of the
        // momentum about a fixed point equal −(inertial wrench) there (gravity off).
        let mut d = body();
        d.gravity = Vector3::zeros();
        let axis = nalgebra::Unit::new_normalize(Vector3::new(0.2, 0.5, 1.0));
        let pos = |t: f64| Vector3::new(t * t, 0.5 * t, -t * t * t);
        let angle = |t: f64| 0.4 * t + 0.3 * t * t;
        let state = |t: f64| {
            let pose = Pose { position: pos(t), rotation: UnitQuaternion::from_axis_angle(&axis, angle(t)) };
            let rate = 0.4 + 0.6 * t;
            let kin = Kinematics {
                velocity: Vector3::new(2.0 * t, 0.5, -3.0 * t * t),
                acceleration: Vector3::new(2.0, 0.0, -6.0 * t),
                omega: axis.into_inner() * rate,
                alpha: axis.into_inner() * 0.6,
            };
            (pose, kin)
        };
        let origin = Vector3::new(0.3, 0.1, -0.2);
        // linear and angular momentum about `origin`
        let momentum = |t: f64| {
            let (pose, kin) = state(t);
            let (v_c, _) = kin.of_point(&pose, &d.com);
            let r = pose.rotation.to_rotation_matrix().into_inner();
            let inertia = r * d.inertia * r.transpose();
            let x_c = pose.transform(&d.com);
            let lin = v_c * d.mass;
            (lin, (x_c - origin).cross(&lin) + inertia * kin.omega)
        };
        let (t, h) = (0.7, 1e-5);
        let (l1, a1) = momentum(t + h);
        let (l0, a0) = momentum(t - h);
        let (pose, kin) = state(t);
        let w = d.wrench(&pose, Some(&kin), &origin);
        assert!(((l1 - l0) / (2.0 * h) + w.fixed_rows::<3>(0)).norm() < 1e-6);
        assert!(((a1 - a0) / (2.0 * h) + w.fixed_rows::<3>(3)).norm() < 1e-6);
    }
}
