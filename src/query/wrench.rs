//! Per-pose wrench feasibility of a 6-cable robot (Bohigas et al. §3).
//!
//! The structure matrix J has one column per cable, [e_i ; (x_i − c) × e_i], where e_i is the unit
//! vector from the base anchor to the platform anchor x_i and c the wrench's application point.
//! Tensions f ≥ 0 pull the platform towards the base anchors and balance the applied wrench when
//! J f = w. Over the ellipsoid W the tensions form the ellipsoid f0 + J⁻¹(w − w0), so cable i
//! ranges over f0,i ± v_ii with f0 = J⁻¹ w0 and v_ii = sqrt((J⁻¹ E⁻¹ J⁻ᵀ)_ii).

use crate::model::{Pose, Robot, Wrench};
use nalgebra::{Matrix6, Vector3};

/// Below this |det J| / Π‖column‖ (Hadamard ratio) a pose counts as singular.
pub const SINGULAR_RATIO: f64 = 1e-10;

/// The structure matrix of `robot` at `pose` with moments about `point`.
pub fn structure_matrix(robot: &Robot, pose: &Pose, point: &Vector3<f64>) -> Matrix6<f64> {
    let cables: Vec<_> = robot.cables.iter().take(6).map(|c| (c.base, pose.transform(&c.platform))).collect();
    structure_matrix_of(&cables, point)
}

/// The structure matrix of the first six (base anchor, platform anchor) pairs, in the world
/// frame, with moments about `point`.
pub fn structure_matrix_of(cables: &[(Vector3<f64>, Vector3<f64>)], point: &Vector3<f64>) -> Matrix6<f64> {
    let mut j = Matrix6::zeros();
    for (i, &(base, x)) in cables.iter().take(6).enumerate() {
        let d = x - base;
        let e = d / d.norm();
        let m = (x - point).cross(&e);
        for k in 0..3 {
            j[(k, i)] = e[k];
            j[(k + 3, i)] = m[k];
        }
    }
    j
}

/// Tension range of one cable over the wrench set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TensionRange {
    /// Tension balancing the nominal wrench, f0,i.
    pub nominal: f64,
    /// Half-width v_ii of the range over the ellipsoid.
    pub spread: f64,
}

/// The tension ranges of the six cables at `pose`, or `None` at a singular pose (J not
/// invertible to within [`SINGULAR_RATIO`]).
pub fn tension_ranges(robot: &Robot, pose: &Pose, wrench: &Wrench) -> Option<[TensionRange; 6]> {
    let cables: Vec<_> = robot.cables.iter().map(|c| (c.base, pose.transform(&c.platform))).collect();
    tension_ranges_at(&cables, &wrench.point_at(pose), wrench)
}

/// [`tension_ranges`] from the cables' world anchors and the wrench's application point; `None`
/// also when there are not exactly six cables.
pub fn tension_ranges_at(cables: &[(Vector3<f64>, Vector3<f64>)], point: &Vector3<f64>, wrench: &Wrench) -> Option<[TensionRange; 6]> {
    if cables.len() != 6 {
        return None;
    }
    let j = structure_matrix_of(cables, point);
    let scale: f64 = (0..6).map(|i| j.column(i).norm()).product();
    let lu = j.lu();
    if !(lu.determinant().abs() > SINGULAR_RATIO * scale) {
        return None;
    }
    let inv = lu.try_inverse()?;
    let f0 = inv * wrench.nominal;
    let v = inv * wrench.ellipsoid_inv * inv.transpose();
    Some(std::array::from_fn(|i| TensionRange { nominal: f0[i], spread: v[(i, i)].max(0.0).sqrt() }))
}
