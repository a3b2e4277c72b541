//! The versioned scenario JSON (`cablenav-scenario/1`, documented in `docs/scenario-format.md`):
//! parsing with serde, and validation into the model with errors that name the field.

pub mod caspr;
pub mod json;
pub mod link;
pub mod validate;

use crate::error::{Error, Result};
use crate::model::{Clearance, Coord, Pose, Robot, Trajectory, Wrench};
use crate::shape::Obstacle;

pub use json::FORMAT;

/// A planning query between two named poses, optionally on a slice with some coordinates fixed.
#[derive(Debug, Clone, PartialEq)]
pub struct Query {
    /// Its name.
    pub name: String,
    /// Name of the start pose.
    pub start: String,
    /// Name of the goal pose.
    pub goal: String,
    /// Coordinates held at the start pose's values.
    pub fixed: Vec<Coord>,
}

/// A validated scenario: the robot, its surroundings, and the named poses, trajectories and
/// queries to study.
#[derive(Debug, Clone, PartialEq)]
pub struct Scenario {
    /// Its name.
    pub name: String,
    /// The robot.
    pub robot: Robot,
    /// Required clearances.
    pub clearance: Clearance,
    /// Obstacles.
    pub obstacles: Vec<Obstacle>,
    /// Named poses, in file order.
    pub poses: Vec<(String, Pose)>,
    /// Trajectories, in file order.
    pub trajectories: Vec<Trajectory>,
    /// Planning queries.
    pub queries: Vec<Query>,
    /// The wrench set the robot must withstand, if any.
    pub wrench: Option<Wrench>,
    /// Things the user should know that did not stop parsing (e.g. a quaternion normalised).
    pub warnings: Vec<String>,
}

impl Scenario {
    /// Parses and validates a scenario in the `cablenav-scenario/1` JSON format. Errors name the
    /// JSON path of the offending value; things worth knowing that did not stop parsing (a
    /// quaternion normalised, a slerp the long way round) are in [`Scenario::warnings`].
    pub fn from_json(text: &str) -> Result<Scenario> {
        validate::scenario(json::parse(text)?)
    }

    /// The pose called `name`.
    pub fn pose(&self, name: &str) -> Result<&Pose> {
        self.poses.iter().find(|(n, _)| n == name).map(|(_, p)| p).ok_or_else(|| {
            let names: Vec<&str> = self.poses.iter().map(|(n, _)| n.as_str()).collect();
            let known = if names.is_empty() {
                "the scenario has no poses".to_owned()
            } else {
                format!("known poses: {}", names.join(", "))
            };
            Error::new("pose", format!("no pose named \"{name}\"; {known}"))
        })
    }

    /// The trajectory called `name`, or the first one for `None`.
    pub fn trajectory(&self, name: Option<&str>) -> Result<&Trajectory> {
        match name {
            None => {
                self.trajectories.first().ok_or_else(|| Error::new("trajectory", "the scenario has no trajectories"))
            }
            Some(name) => self.trajectories.iter().find(|t| t.name == name).ok_or_else(|| {
                let names: Vec<&str> = self.trajectories.iter().map(|t| t.name.as_str()).collect();
                let known = if names.is_empty() {
                    "the scenario has no trajectories".to_owned()
                } else {
                    format!("known trajectories: {}", names.join(", "))
                };
                Error::new("trajectory", format!("no trajectory named \"{name}\"; {known}"))
            }),
        }
    }
}
