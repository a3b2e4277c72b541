//! The versioned scenario JSON (`cablenav-scenario/1`, documented in `docs/scenario-format.md`):
//! parsing with serde, and validation into the model with errors that name the field.

pub mod caspr;
pub mod json;
mod json_path;
pub mod share_url;
pub mod validate;

use crate::error::{Error, Result};
use crate::model::{Clearance, Coord, Pose, Robot, Trajectory, Wrench};
use crate::shape::Obstacle;

pub use json::{FORMAT, FORMAT_3, FORMAT_4, FORMAT_5, FORMAT_6};
pub use validate::STANDARD_GRAVITY;

/// A planning query between two named poses (a multi-link robot's: configurations), optionally
/// on a slice with some coordinates fixed.
#[derive(Debug, Clone, PartialEq)]
pub struct Query {
    /// Its name.
    pub name: String,
    /// Name of the start pose (configuration).
    pub start: String,
    /// Name of the goal pose (configuration).
    pub goal: String,
    /// Coordinates held at the start's values.
    pub fixed: Vec<Coord>,
    /// The box a lattice planner searches, per free coordinate (`region` in the file); free
    /// coordinates not listed get a default range (docs/lattice.md).
    pub region: Vec<(Coord, [f64; 2])>,
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
    /// The tilt-and-torsion angles (φ, θ, σ) of each pose the file gives them, as written (a
    /// pose keeps only its rotation; [`Scenario::written_coords`]).
    pub written_angles: Vec<(String, [f64; 3])>,
    /// Trajectories, in file order.
    pub trajectories: Vec<Trajectory>,
    /// Planning queries.
    pub queries: Vec<Query>,
    /// The wrench set the robot must withstand, if any.
    pub wrench: Option<Wrench>,
    /// Named joint configurations of a multi-link robot (its coordinates in
    /// [`crate::model::Chain::coords`] order), in file order; empty for a platform robot.
    pub configs: Vec<(String, Vec<f64>)>,
    /// A multi-link robot's trajectories: paths through its configurations, in file order.
    pub joint_paths: Vec<crate::model::JointPath>,
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

    /// What the cables must balance — the wrench set and the platform's weight and inertia —
    /// if the scenario states either (a wrench section, or `robot.dynamics`); `None` means no
    /// tension condition.
    pub fn load(&self) -> Option<crate::model::Load> {
        if self.wrench.is_none() && self.robot.dynamics.is_none() {
            return None;
        }
        Some(crate::model::Load { wrench: self.wrench.clone().unwrap_or_else(Wrench::zero), dynamics: self.robot.dynamics.clone(), mobility: self.robot.mobility })
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

    /// Whether `other` describes the same configuration space: the same robot, wrench set,
    /// obstacles and clearances (its poses, trajectories and queries may differ).
    pub fn same_space(&self, other: &Scenario) -> bool {
        self.robot == other.robot && self.wrench == other.wrench && self.obstacles == other.obstacles && self.clearance == other.clearance
    }

    /// Pose `name`'s coordinates (x, y, z, φ, θ, σ) with the angles as the file writes them,
    /// when it gives tilt-and-torsion angles (the canonical angles of its rotation otherwise): the
    /// angles as plain coordinates, paper 1's way of posing a query (q3 = (0.8, −2.4) is
    /// (0.8 − π, 2.4) as a rotation).
    pub fn written_coords(&self, name: &str) -> Result<[f64; 6]> {
        let mut c = self.pose(name)?.coords();
        if let Some((_, a)) = self.written_angles.iter().find(|(n, _)| n == name) {
            c[3..].copy_from_slice(a);
        }
        Ok(c)
    }

    /// The configuration called `name`: a multi-link robot's joint coordinates, or a platform
    /// pose's coordinates (x, y, z, φ, θ, σ).
    pub fn config(&self, name: &str) -> Result<Vec<f64>> {
        if self.robot.chain.is_none() {
            return Ok(self.pose(name)?.coords().to_vec());
        }
        self.configs.iter().find(|(n, _)| n == name).map(|(_, q)| q.clone()).ok_or_else(|| {
            let names: Vec<&str> = self.configs.iter().map(|(n, _)| n.as_str()).collect();
            let known = if names.is_empty() { "the scenario has no configurations".to_owned() } else { format!("known configurations: {}", names.join(", ")) };
            Error::new("pose", format!("no configuration named \"{name}\"; {known}"))
        })
    }

    /// The coordinate called `name`: a joint coordinate's name (or `q1`, `q2`, …) for a
    /// multi-link robot, one of x, y, z, phi, theta, sigma for a spatial platform (x, y, z for a
    /// point mass; x, y, sigma for a planar platform). Errors name `field`.
    pub fn coord(&self, field: &str, name: &str) -> Result<Coord> {
        let Some(chain) = &self.robot.chain else {
            let free = self.robot.mobility.coords();
            let names = || free.iter().map(|c| c.name()).collect::<Vec<_>>().join(", ");
            return Coord::parse(name).filter(|c| free.contains(c)).ok_or_else(|| Error::new(field, format!("{name:?} is not a coordinate of this robot ({}): its coordinates are {}", self.robot.mobility.name(), names())));
        };
        let by_q = name.strip_prefix('q').and_then(|k| k.parse::<usize>().ok()).filter(|k| (1..=chain.dof()).contains(k)).map(|k| k - 1);
        let index = chain.coord_index(name).or(by_q).ok_or_else(|| {
            let names: Vec<&str> = chain.coords().map(|(_, _, c)| c.name.as_str()).collect();
            Error::new(field, format!("{name:?} is not a coordinate of this robot; its coordinates: {}", names.join(", ")))
        })?;
        Ok(Coord::Joint { index: index as u8, angle: chain.is_angle(index) })
    }

    /// Every coordinate the robot moves along, in order: x, y, z, φ, θ, σ for a spatial platform
    /// (x, y, z for a point mass, x, y, σ for a planar platform), the joint coordinates for a
    /// multi-link robot (named by [`Scenario::coord_name`]). [`Coord::index`] places each in a
    /// configuration.
    pub fn coords(&self) -> Vec<Coord> {
        match &self.robot.chain {
            Some(c) => (0..c.dof()).map(|k| self.coord_at(k)).collect(),
            None => self.robot.mobility.coords().to_vec(),
        }
    }

    /// The names of the configurations commands start from: a platform robot's poses, a
    /// multi-link robot's configurations, in file order.
    pub fn config_names(&self) -> Vec<String> {
        match self.robot.chain {
            Some(_) => self.configs.iter().map(|(n, _)| n.clone()).collect(),
            None => self.poses.iter().map(|(n, _)| n.clone()).collect(),
        }
    }

    /// Coordinate number `k` of a configuration (0-based; x, y, z, φ, θ, σ for a platform robot).
    pub fn coord_at(&self, k: usize) -> Coord {
        match &self.robot.chain {
            Some(chain) => Coord::Joint { index: k as u8, angle: chain.is_angle(k) },
            None => Coord::ALL[k.min(5)],
        }
    }

    /// A warning when [lo, hi] leaves the range of joint coordinate `c` (multi-link robots; the
    /// joints' ranges are not conditions, a ray or a map may look past them).
    pub fn range_warning(&self, c: Coord, [lo, hi]: [f64; 2]) -> Option<String> {
        let chain = self.robot.chain.as_ref()?;
        let (_, _, jc) = chain.coords().nth(c.index())?;
        let [a, b] = jc.range;
        (lo < a || hi > b).then(|| format!("{}: [{lo}, {hi}] leaves the joint's range [{a}, {b}] (joint ranges are not checked as conditions)", jc.name))
    }

    /// The name the scenario gives coordinate `c`.
    pub fn coord_name(&self, c: Coord) -> String {
        match (&self.robot.chain, c) {
            (Some(chain), Coord::Joint { index, .. }) => chain.coords().nth(index as usize).map_or_else(|| c.name().to_string(), |(_, _, jc)| jc.name.clone()),
            _ => c.name().to_string(),
        }
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

/// A trajectory as scenario JSON: `translation` and `orientation`, or `pieces` for a piecewise
/// one (format 2), or `spline` and `knots` for one through knots (format 4). Orientations are
/// written as quaternions `[w, x, y, z]` with their signs. (A turning piece built by hand, not
/// from knots, is written descriptively as `{"turn": …}`, which scenario files do not take.)
pub fn trajectory_json(traj: &Trajectory) -> serde_json::Value {
    use crate::model::{Orientation, Translation};
    use serde_json::json;
    let v3 = |p: &nalgebra::Vector3<f64>| json!([p.x, p.y, p.z]);
    let q = |q: &nalgebra::UnitQuaternion<f64>| json!([q.w, q.i, q.j, q.k]);
    if let Some(knots) = &traj.knots {
        let spline = match knots.profile {
            crate::model::Profile::Quintic => "quintic",
            crate::model::Profile::Cubic => "cubic",
        };
        let points: Vec<serde_json::Value> = knots
            .points
            .iter()
            .map(|k| {
                let mut v = json!({"time": k.time, "position": v3(&k.pose.position), "quaternion": q(&k.pose.rotation), "velocity": v3(&k.velocity)});
                if knots.profile == crate::model::Profile::Quintic {
                    v["acceleration"] = v3(&k.acceleration);
                }
                v
            })
            .collect();
        return json!({"name": traj.name, "spline": spline, "knots": points});
    }
    let piece = |seg: &crate::model::Segment| {
        let translation = match &seg.translation {
            Translation::Polynomial(c) => json!({"polynomial": c}),
            Translation::Bezier(points) => json!({"bezier": points.iter().map(v3).collect::<Vec<_>>()}),
            Translation::Line(a, b) => json!({"line": [v3(a), v3(b)]}),
        };
        let orientation = match &seg.orientation {
            Orientation::Slerp(qs, qe) => json!({"slerp": [q(qs), q(qe)]}),
            Orientation::Turn { from, axis, angle, profile } => {
                json!({"turn": {"from": q(from), "axis": v3(axis), "angle": angle, "profile": format!("{profile:?}").to_lowercase()}})
            }
        };
        json!({"translation": translation, "orientation": orientation})
    };
    let pieces = traj.pieces();
    if pieces.len() == 1 {
        let mut v = piece(&pieces[0]);
        v["name"] = json!(traj.name);
        v
    } else {
        json!({"name": traj.name, "pieces": pieces.iter().map(piece).collect::<Vec<_>>()})
    }
}

/// The scenario text `text` with `traj` appended to its trajectories under its name, or the name
/// with ` 2`, ` 3`, … added if that is taken; the format becomes version 2 when the trajectory has
/// several pieces. Returns the new text (pretty-printed) and the name used. The text must be a
/// valid scenario.
pub fn with_trajectory(text: &str, traj: &Trajectory) -> Result<(String, String)> {
    let scenario = Scenario::from_json(text)?;
    let mut value: serde_json::Value = serde_json::from_str(text).map_err(|e| Error::new("", format!("malformed JSON: {e}")))?;
    let taken = |n: &str| scenario.trajectories.iter().any(|t| t.name == n);
    let mut name = traj.name.clone();
    let mut k = 2;
    while taken(&name) {
        name = format!("{} {k}", traj.name);
        k += 1;
    }
    let mut t = traj.clone();
    t.name = name.clone();
    if t.piece_count() > 1 {
        value["format"] = serde_json::json!(json::FORMAT_2);
    }
    match value.get_mut("trajectories").and_then(|v| v.as_array_mut()) {
        Some(list) => list.push(trajectory_json(&t)),
        None => value["trajectories"] = serde_json::json!([trajectory_json(&t)]),
    }
    let out = serde_json::to_string_pretty(&value).map_err(|e| Error::new("output", e.to_string()))?;
    Ok((out, name))
}

/// The text of a multi-link robot's scenario `text` with `path` appended to its trajectories
/// under its name, or the name with ` 2`, ` 3`, … added if that is taken, and each configuration
/// it passes through added to `configurations` as `NAME-0`, `NAME-1`, … (NAME the name used; a
/// configuration name taken gets ` 2`, … likewise). Returns the new text (pretty-printed) and the
/// name used. The text must be a valid scenario of a multi-link robot.
pub fn with_joint_path(text: &str, path: &crate::model::JointPath) -> Result<(String, String)> {
    let scenario = Scenario::from_json(text)?;
    let chain = scenario.robot.chain.as_ref().ok_or_else(|| Error::new("trajectories", "a path through configurations is for a multi-link robot"))?;
    let names: Vec<&str> = chain.coords().map(|(_, _, c)| c.name.as_str()).collect();
    let mut value: serde_json::Value = serde_json::from_str(text).map_err(|e| Error::new("", format!("malformed JSON: {e}")))?;
    let free = |taken: &dyn Fn(&str) -> bool, base: &str| {
        let mut name = base.to_string();
        let mut k = 2;
        while taken(&name) {
            name = format!("{base} {k}");
            k += 1;
        }
        name
    };
    let name = free(&|n| scenario.joint_paths.iter().any(|p| p.name == n), &path.name);
    let mut through = Vec::with_capacity(path.through.len());
    if !value.get("configurations").is_some_and(|c| c.is_object()) {
        value["configurations"] = serde_json::json!({});
    }
    for (i, q) in path.through.iter().enumerate() {
        let config = free(&|n| scenario.configs.iter().any(|(c, _)| c == n), &format!("{name}-{i}"));
        let coords: serde_json::Map<String, serde_json::Value> = names.iter().zip(q).map(|(n, x)| (n.to_string(), serde_json::json!(x))).collect();
        value["configurations"][config.as_str()] = serde_json::Value::Object(coords);
        through.push(config);
    }
    let entry = serde_json::json!({"name": name, "through": through});
    match value.get_mut("trajectories").and_then(|v| v.as_array_mut()) {
        Some(list) => list.push(entry),
        None => value["trajectories"] = serde_json::json!([entry]),
    }
    let out = serde_json::to_string_pretty(&value).map_err(|e| Error::new("output", e.to_string()))?;
    Ok((out, name))
}
