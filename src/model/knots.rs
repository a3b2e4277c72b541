//! Trajectories through timed knots, in CASPR's form (its `quintic_spline_trajectory` and
//! `cubic_spline_trajectory`): between consecutive knots the position follows the quintic (or
//! cubic) polynomial in time that meets the knots' positions, velocities and accelerations (or
//! positions and velocities), and the rotation turns about one fixed axis, the shortest way from
//! one knot's rotation to the next, by the rest-to-rest quintic (cubic) angle profile — as CASPR's
//! `generateTrajectoryQuinticSpline` does for a `SPATIAL_EULER_XYZ` joint. CASPR supports no
//! angular velocity at a knot, and nor does this form.

use super::trajectory::{Knot, Knots, Orientation, Profile, Segment, Trajectory, Translation};
use nalgebra::{Unit, Vector3};

impl Knots {
    /// The pieces between consecutive knots, each in its own t ∈ [0, 1] (its time share).
    pub fn segments(&self) -> Vec<Segment> {
        self.points
            .windows(2)
            .map(|w| segment(self.profile, &w[0], &w[1]))
            .collect()
    }
}

/// The piece from knot `a` to knot `b`: the polynomial translation in the piece's own t (time
/// scaled by T = b.time − a.time, so velocities count T times, accelerations T² times) and the
/// turn between the rotations.
fn segment(profile: Profile, a: &Knot, b: &Knot) -> Segment {
    let span = b.time - a.time;
    let coefficients: [Vec<f64>; 3] = std::array::from_fn(|i| {
        let (p0, p1) = (a.pose.position[i], b.pose.position[i]);
        let (v0, v1) = (a.velocity[i] * span, b.velocity[i] * span);
        let d = p1 - p0;
        match profile {
            Profile::Quintic => {
                let (a0, a1) = (
                    a.acceleration[i] * span * span,
                    b.acceleration[i] * span * span,
                );
                vec![
                    p0,
                    v0,
                    0.5 * a0,
                    10.0 * d - 6.0 * v0 - 4.0 * v1 - 0.5 * (3.0 * a0 - a1),
                    -15.0 * d + 8.0 * v0 + 7.0 * v1 + 0.5 * (3.0 * a0 - 2.0 * a1),
                    6.0 * d - 3.0 * v0 - 3.0 * v1 - 0.5 * (a0 - a1),
                ]
            }
            Profile::Cubic => vec![p0, v0, 3.0 * d - 2.0 * v0 - v1, -2.0 * d + v0 + v1],
        }
    });
    let relative = a.pose.rotation.inverse() * b.pose.rotation;
    let (axis, angle) = relative
        .axis_angle()
        .unwrap_or((Unit::new_unchecked(Vector3::x()), 0.0));
    Segment {
        translation: Translation::Polynomial(coefficients),
        orientation: Orientation::Turn {
            from: a.pose.rotation,
            axis,
            angle,
            profile,
        },
    }
}

impl Trajectory {
    /// The trajectory through `knots` (at least two), run in their time: one piece per pair of
    /// knots, `duration` the time from the first to the last.
    pub fn through_knots(name: impl Into<String>, knots: Knots) -> Option<Trajectory> {
        if knots.points.len() < 2 {
            return None;
        }
        let mut traj = Trajectory::piecewise(name, knots.segments())?;
        traj.duration = Some(knots.duration());
        traj.knots = Some(knots);
        Some(traj)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Pose;
    use nalgebra::UnitQuaternion;

    fn knot(time: f64, p: [f64; 3], angles: [f64; 3], v: [f64; 3], a: [f64; 3]) -> Knot {
        let rotation = UnitQuaternion::from_euler_angles(angles[0], angles[1], angles[2]);
        Knot {
            time,
            pose: Pose {
                position: Vector3::from(p),
                rotation,
            },
            velocity: Vector3::from(v),
            acceleration: Vector3::from(a),
        }
    }

    /// The spline meets every knot's pose, velocity and acceleration (by finite differences of the
    /// poses and by the trajectory's own rates), and its rotation turns about one axis.
    #[test]
    fn splines_meet_their_knots() {
        for profile in [Profile::Quintic, Profile::Cubic] {
            let points = vec![
                knot(0.0, [0.0, 1.0, 2.0], [0.1, -0.2, 0.3], [0.0; 3], [0.0; 3]),
                knot(
                    1.5,
                    [1.0, -1.0, 2.5],
                    [0.4, 0.1, -0.2],
                    [0.3, -0.2, 0.1],
                    [0.5, 0.0, -0.4],
                ),
                knot(4.0, [2.0, 0.0, 1.0], [-0.3, 0.2, 0.6], [0.0; 3], [0.0; 3]),
            ];
            let traj = Trajectory::through_knots(
                "k",
                Knots {
                    profile,
                    points: points.clone(),
                },
            )
            .unwrap();
            let d = traj.duration.unwrap();
            assert_eq!(d, 4.0);
            for k in &points {
                let t = k.time / d;
                let pose = traj.pose_at(t);
                assert!(
                    (pose.position - k.pose.position).norm() < 1e-12,
                    "{profile:?} position at {}",
                    k.time
                );
                assert!(pose.rotation.angle_to(&k.pose.rotation) < 1e-12);
                let m = traj.kinematics_at(t, d);
                assert!(
                    (m.velocity - k.velocity).norm() < 1e-9,
                    "{profile:?} velocity at {}: {}",
                    k.time,
                    m.velocity
                );
                if profile == Profile::Quintic {
                    assert!(
                        (m.acceleration - k.acceleration).norm() < 1e-9,
                        "acceleration at {}",
                        k.time
                    );
                }
                assert!(
                    m.omega.norm() < 1e-12,
                    "rest-to-rest turns stop at the knots"
                );
            }
            // the rates are the poses' derivatives in time, inside each piece
            for &time in &[0.4, 1.2, 2.2, 3.7] {
                let (t, h) = (time / d, 1e-5);
                let (a, b) = (traj.pose_at(t - h / d), traj.pose_at(t + h / d));
                let m = traj.kinematics_at(t, d);
                assert!(((b.position - a.position) / (2.0 * h) - m.velocity).norm() < 1e-6);
                let omega = (b.rotation * a.rotation.inverse()).scaled_axis() / (2.0 * h);
                assert!(
                    (omega - m.omega).norm() < 1e-6,
                    "{profile:?} ω at {time}: {omega} vs {}",
                    m.omega
                );
                let (m0, m1) = (
                    traj.kinematics_at(t - h / d, d),
                    traj.kinematics_at(t + h / d, d),
                );
                assert!(((m1.omega - m0.omega) / (2.0 * h) - m.alpha).norm() < 1e-5);
                assert!(((m1.velocity - m0.velocity) / (2.0 * h) - m.acceleration).norm() < 1e-5);
            }
        }
    }
}
