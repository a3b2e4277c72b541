//! A 6-DoF cable robot: m ≥ 6 cables, each the segment from a base anchor (world frame) to a
//! platform anchor (platform frame), with length and tension bounds.

use nalgebra::Vector3;

/// A closed range `[min, max]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// Lower end.
    pub min: f64,
    /// Upper end.
    pub max: f64,
}

impl Bounds {
    /// Whether `x` lies in the closed range.
    pub fn contains(&self, x: f64) -> bool {
        x >= self.min && x <= self.max
    }
}

/// One cable: the segment a_i → p + R·b_i.
#[derive(Debug, Clone, PartialEq)]
pub struct Cable {
    /// Base anchor a_i in the world frame.
    pub base: Vector3<f64>,
    /// Platform anchor b_i in the platform frame.
    pub platform: Vector3<f64>,
    /// Allowed cable length.
    pub length: Bounds,
    /// Allowed cable tension.
    pub tension: Bounds,
}

/// The robot: its cables and the cable diameter (informational; clearances are between centrelines).
#[derive(Debug, Clone, PartialEq)]
pub struct Robot {
    /// The cables, numbered from 1 in reports.
    pub cables: Vec<Cable>,
    /// Cable diameter.
    pub diameter: f64,
}

/// Minimum distances the verifier enforces, between cable centrelines and from a centreline to an
/// obstacle's surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clearance {
    /// Minimum distance between two cables.
    pub cable_cable: f64,
    /// Minimum distance between a cable and an obstacle.
    pub cable_obstacle: f64,
}

impl Robot {
    /// Whether cables `i` and `j` share an anchor (base or platform): such cables meet there by
    /// design, so their mutual clearance is not checked.
    pub fn share_anchor(&self, i: usize, j: usize) -> bool {
        let (a, b) = (&self.cables[i], &self.cables[j]);
        a.base == b.base || a.platform == b.platform
    }
}
