//! The robot and its motions as the rest of the core sees them, after the scenario was validated:
//! cables and their bounds, poses, trajectories, and the rational motions the exact conditions use.

pub mod chain;
pub mod joint_path;
pub mod dynamics;
pub mod knots;
pub mod motion;
pub mod pose;
pub mod proportional;
pub mod robot;
pub mod trajectory;
pub mod turn;
pub mod via;
pub mod wrench;

pub use chain::{Chain, Joint, JointCoord, Link, LinkWrench};
pub use joint_path::JointPath;
pub use dynamics::{Dynamics, Kinematics, Winch};
pub use motion::Motion;
pub use pose::{Coord, Pose};
pub use robot::{Anchor, Bounds, Cable, CableSegment, Clearance, Mobility, Robot};
pub use trajectory::{Knot, Knots, Orientation, Profile, Segment, Trajectory, Translation};
pub use wrench::{Load, PointFrame, Wrench};
