//! A cable robot: cables, each the segment from a base anchor (world frame) to an anchor on the
//! platform or on one link of a multi-link chain (in that link's frame), with length and tension
//! bounds.

use super::{Chain, Dynamics, Winch};
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

/// One cable: the segment a_i → p + R·b_i, (p, R) the pose of the platform or of its link.
#[derive(Debug, Clone, PartialEq)]
pub struct Cable {
    /// Base anchor a_i in the world frame.
    pub base: Vector3<f64>,
    /// Platform anchor b_i in the platform's (or its link's) frame.
    pub platform: Vector3<f64>,
    /// The link it pulls (index into the chain's links; 0 for the platform).
    pub link: usize,
    /// Allowed cable length.
    pub length: Bounds,
    /// Allowed cable tension.
    pub tension: Bounds,
}

/// How the platform of a platform robot moves, and so which wrench components its cables must
/// balance (format 5 `robot.mobility`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mobility {
    /// A rigid body with six degrees of freedom: forces and moments.
    #[default]
    Spatial,
    /// A point mass (three translations): every cable ends at the point, forces only.
    Point,
    /// A rigid body in the plane z = 0 (x, y and a rotation about z): the forces along x and y
    /// and the moment about z.
    Planar,
}

impl Mobility {
    /// The components of the 6-D wrench [fx, fy, fz, mx, my, mz] the cables balance: all six for
    /// a spatial platform, the force for a point mass, fx, fy and mz for a planar one.
    pub fn rows(self) -> &'static [usize] {
        match self {
            Mobility::Spatial => &[0, 1, 2, 3, 4, 5],
            Mobility::Point => &[0, 1, 2],
            Mobility::Planar => &[0, 1, 5],
        }
    }

    /// The number of degrees of freedom (the wrench components balanced).
    pub fn dof(self) -> usize {
        self.rows().len()
    }

    /// The pose coordinates it moves along: all six for a spatial platform, x, y, z for a point
    /// mass, x, y and σ (the turn about z, at tilt θ = 0) for a planar platform.
    pub fn coords(self) -> &'static [super::Coord] {
        use super::Coord;
        match self {
            Mobility::Spatial => &Coord::ALL,
            Mobility::Point => &[Coord::X, Coord::Y, Coord::Z],
            Mobility::Planar => &[Coord::X, Coord::Y, Coord::Sigma],
        }
    }

    /// The name `robot.mobility` gives it.
    pub fn name(self) -> &'static str {
        match self {
            Mobility::Spatial => "spatial",
            Mobility::Point => "point",
            Mobility::Planar => "planar",
        }
    }
}

/// The robot: its cables, the cable diameter (informational; clearances are between
/// centrelines), and its links if it is a multi-link robot.
#[derive(Debug, Clone, PartialEq)]
pub struct Robot {
    /// The cables, numbered from 1 in reports.
    pub cables: Vec<Cable>,
    /// Cable diameter.
    pub diameter: f64,
    /// The links of a multi-link robot; `None` for a platform robot (one link, free joint,
    /// configured by poses).
    pub chain: Option<Chain>,
    /// The platform's mass and inertia, and gravity (format 4); `None`: the platform is massless
    /// and every load is in the wrench set.
    pub dynamics: Option<Dynamics>,
    /// The winches' speed and acceleration limits (format 4); both `None` when not limited.
    pub winch: Winch,
    /// The largest speed of the platform's origin (format 4 `robot.speed`, m/s), if limited.
    pub speed: Option<f64>,
    /// How the platform moves (format 5; spatial before).
    pub mobility: Mobility,
}

/// Minimum distances the verifier enforces, between cable centrelines and from a centreline to an
/// obstacle's surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clearance {
    /// Minimum distance between two cables.
    pub cable_cable: f64,
    /// Minimum distance between a cable and an obstacle.
    pub cable_obstacle: f64,
    /// Minimum distance between a cable and a link's body (multi-link robots).
    pub cable_link: f64,
}

impl Robot {
    /// Whether cables `i` and `j` share an anchor (base or platform): such cables meet there by
    /// design, so their mutual clearance is not checked.
    pub fn share_anchor(&self, i: usize, j: usize) -> bool {
        let (a, b) = (&self.cables[i], &self.cables[j]);
        a.base == b.base || (a.link == b.link && a.platform == b.platform)
    }

    /// (base anchor, platform anchor in the world frame) per cable of a platform robot at `pose`.
    pub fn anchors(&self, pose: &super::Pose) -> Vec<(Vector3<f64>, Vector3<f64>)> {
        self.cables.iter().map(|c| (c.base, pose.transform(&c.platform))).collect()
    }
}
