//! A cable robot: cables, each the segment from a base anchor (world frame) to an anchor on the
//! platform or on one link of a multi-link chain (in that link's frame), with length and tension
//! bounds. A multi-link robot's cable may start on a link and be routed through anchors on
//! several links: it is then a chain of straight [`CableSegment`]s, its length their sum, its tension
//! the same along all of them.

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

/// One cable: the segment a_i → p + R·b_i, (p, R) the pose of the platform or of its link; or,
/// routed, the segments from a_i through each of `via` to b_i.
#[derive(Debug, Clone, PartialEq)]
pub struct Cable {
    /// Base anchor a_i in the world frame (in the frame of link `from`, when given).
    pub base: Vector3<f64>,
    /// Platform anchor b_i in the platform's (or its link's) frame.
    pub platform: Vector3<f64>,
    /// The link it pulls (index into the chain's links; 0 for the platform).
    pub link: usize,
    /// Allowed cable length.
    pub length: Bounds,
    /// Allowed cable tension.
    pub tension: Bounds,
    /// The link the first anchor `base` is fixed to; `None`: the base (the world).
    pub from: Option<usize>,
    /// The anchors the cable runs through between `base` and `platform`, in order; empty for a
    /// straight cable.
    pub via: Vec<Anchor>,
}

/// A point a cable is attached to or runs through: fixed to the base (world frame) or to a link
/// (in its frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Anchor {
    /// The link it is fixed to; `None`: the base.
    pub link: Option<usize>,
    /// The point, in that link's frame (the world's for the base).
    pub point: Vector3<f64>,
}

/// One straight piece of a cable, between two consecutive anchors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CableSegment {
    /// The cable it belongs to (index into the robot's cables).
    pub cable: usize,
    /// Its number along the cable (0 from the base anchor).
    pub index: usize,
    /// The anchor it starts from.
    pub from: Anchor,
    /// The anchor it ends at.
    pub to: Anchor,
}

impl Cable {
    /// A straight cable from the base anchor `base` (world frame) to `platform` on link `link`.
    pub fn straight(base: Vector3<f64>, platform: Vector3<f64>, link: usize, length: Bounds, tension: Bounds) -> Cable {
        Cable { base, platform, link, length, tension, from: None, via: Vec::new() }
    }

    /// Whether the cable is more than one straight segment from the base (routed through
    /// anchors, or starting on a link).
    pub fn is_routed(&self) -> bool {
        self.from.is_some() || !self.via.is_empty()
    }

    /// Its anchors in order, from `base` to `platform`.
    pub fn anchors(&self) -> Vec<Anchor> {
        let mut out = Vec::with_capacity(self.via.len() + 2);
        out.push(Anchor { link: self.from, point: self.base });
        out.extend(self.via.iter().copied());
        out.push(Anchor { link: Some(self.link), point: self.platform });
        out
    }
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
    /// Every cable's segments, cable by cable, each in order from its base anchor: one per
    /// straight cable, so that for a robot without routed cables segment i is cable i.
    pub fn segments(&self) -> Vec<CableSegment> {
        let mut out = Vec::with_capacity(self.cables.len());
        for (cable, c) in self.cables.iter().enumerate() {
            let anchors = c.anchors();
            out.extend(anchors.windows(2).enumerate().map(|(index, w)| CableSegment { cable, index, from: w[0], to: w[1] }));
        }
        out
    }

    /// Whether any cable is routed ([`Cable::is_routed`]).
    pub fn is_routed(&self) -> bool {
        self.cables.iter().any(Cable::is_routed)
    }

    /// Whether cables `i` and `j` share an anchor (the same point of the base or of one link):
    /// they meet there by design, so their mutual clearance is not checked. For straight cables:
    /// the same base anchor, or the same anchor on the same link.
    pub fn share_anchor(&self, i: usize, j: usize) -> bool {
        let b = self.cables[j].anchors();
        self.cables[i].anchors().iter().any(|p| b.contains(p))
    }

    /// Whether segments `a` and `b` share an anchor, as [`Robot::share_anchor`] for cables.
    pub fn segments_meet(a: &CableSegment, b: &CableSegment) -> bool {
        [a.from, a.to].iter().any(|p| [b.from, b.to].contains(p))
    }

    /// (base anchor, platform anchor in the world frame) per cable of a platform robot at `pose`.
    pub fn anchors(&self, pose: &super::Pose) -> Vec<(Vector3<f64>, Vector3<f64>)> {
        self.cables.iter().map(|c| (c.base, pose.transform(&c.platform))).collect()
    }
}
