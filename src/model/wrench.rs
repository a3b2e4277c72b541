//! The wrench set a pose must withstand (Bohigas et al. §2): every wrench w in the ellipsoid
//! W = {w : (w − w0)ᵀ E (w − w0) ≤ 1}, applied at a point of the platform.

use super::pose::Pose;
use nalgebra::{Matrix6, Vector3, Vector6};

/// Where the wrench's application point is held.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointFrame {
    /// The offset rotates with the platform (a load fixed to it): c = p + R·P.
    Platform,
    /// The offset is held in the world-parallel frame: c = p + P.
    World,
}

/// An ellipsoidal wrench set.
#[derive(Debug, Clone, PartialEq)]
pub struct Wrench {
    /// Nominal wrench w0 = [fx, fy, fz, mx, my, mz] in the world-parallel frame at the point.
    pub nominal: Vector6<f64>,
    /// The SPD matrix E of the ellipsoid.
    pub ellipsoid: Matrix6<f64>,
    /// E⁻¹.
    pub ellipsoid_inv: Matrix6<f64>,
    /// The application point's offset P from the platform origin.
    pub point: Vector3<f64>,
    /// How the offset moves with the platform.
    pub frame: PointFrame,
}

impl Wrench {
    /// The application point in the world frame at `pose`.
    pub fn point_at(&self, pose: &Pose) -> Vector3<f64> {
        match self.frame {
            PointFrame::Platform => pose.transform(&self.point),
            PointFrame::World => pose.position + self.point,
        }
    }
}
