//! The wrench set a pose must withstand (Bohigas et al. §2): every wrench w in the ellipsoid
//! W = {w : (w − w0)ᵀ E (w − w0) ≤ 1}, applied at a point of the platform.

use super::dynamics::{Dynamics, Kinematics};
use super::pose::Pose;
use super::robot::Mobility;
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
    /// Whether wrench closure is required as well (format 4 `wrench.closure`): a condition of its
    /// own, not implied by the wrench set (a cable-suspended robot holds its load without it).
    pub closure: bool,
}

impl Wrench {
    /// The set holding the zero wrench alone (E⁻¹ = 0; E is infinite): what the cables balance
    /// when a scenario gives the platform a mass but no wrench section.
    pub fn zero() -> Wrench {
        Wrench {
            nominal: Vector6::zeros(),
            ellipsoid: Matrix6::from_element(f64::INFINITY),
            ellipsoid_inv: Matrix6::zeros(),
            point: Vector3::zeros(),
            frame: PointFrame::Platform,
            closure: false,
        }
    }

    /// Whether the set is the nominal wrench alone (E⁻¹ = 0: no ellipsoid around it).
    pub fn is_single(&self) -> bool {
        self.ellipsoid_inv.iter().all(|x| *x == 0.0)
    }

    /// The application point in the world frame at `pose`.
    pub fn point_at(&self, pose: &Pose) -> Vector3<f64> {
        match self.frame {
            PointFrame::Platform => pose.transform(&self.point),
            PointFrame::World => pose.position + self.point,
        }
    }
}

/// Everything the cables must balance: the wrench set (external loads) and, when the platform has
/// a mass, its weight and (along a timed motion) its inertia. Shared by the tension conditions.
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    /// The external wrench set ([`Wrench::zero`] if the scenario has none).
    pub wrench: Wrench,
    /// The platform's rigid-body data, if given.
    pub dynamics: Option<Dynamics>,
    /// How the platform moves: which wrench components the cables balance.
    pub mobility: Mobility,
}

impl Load {
    /// The wrench components the cables balance ([`Mobility::rows`]).
    pub fn rows(&self) -> &'static [usize] {
        self.mobility.rows()
    }

    /// Whether the load is zero everywhere: no nominal wrench and no platform dynamics (whose
    /// weight alone is a load).
    pub fn is_zero(&self) -> bool {
        self.dynamics.is_none() && self.wrench.nominal == Vector6::zeros() && self.wrench.is_single()
    }

    /// The nominal wrench the cables balance at `pose` moving as `kin` (`None`: at rest): the
    /// wrench set's w0 plus weight and inertia, about the wrench set's point.
    pub fn nominal_at(&self, pose: &Pose, kin: Option<&Kinematics>) -> Vector6<f64> {
        match &self.dynamics {
            None => self.wrench.nominal,
            Some(d) => self.wrench.nominal + d.wrench(pose, kin, &self.wrench.point_at(pose)),
        }
    }
}
