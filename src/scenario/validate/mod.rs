//! Validation of the raw JSON into the model. Every check names the JSON path of the offending
//! value; nothing here indexes user data unchecked or unwraps it, so no input can panic.
//!
//! [`scenario`] validates a whole file, section by section, in files by what they describe:
//! `robot.rs` the robot (cables, bounds, dynamics, winches) and the clearances, `chains.rs` a
//! multi-link robot's links and configurations, `obstacles.rs` the obstacles, `motion.rs` the
//! poses and trajectories (with their timing), `queries.rs` the planning queries and `wrench.rs`
//! the wrench set. This file holds the format's limits and the checks they share.

mod chains;
mod motion;
mod obstacles;
mod queries;
mod robot;
mod wrench;

use nalgebra::{Cholesky, Const, SMatrix, Vector3};

use super::json::{Fixed, RawScenario, FORMAT_4, FORMAT_5, FORMAT_6};
use super::Scenario;
use crate::error::{finite, Error, Result};
use crate::model::Pose;

/// Fewest cables of a 6-DoF robot (a point-mass or planar robot needs 3).
pub const MIN_CABLES: usize = 6;
/// Most cables supported on a platform robot.
pub const MAX_CABLES: usize = 64;
/// Most cables supported on a multi-link robot (CASPR's 8S_neck has 76).
pub const MAX_CHAIN_CABLES: usize = 128;
/// Most segments of a multi-link robot's cables, all cables together (a routed cable has one
/// per pair of consecutive anchors).
pub const MAX_SEGMENTS: usize = 1024;
/// Most obstacles in one scenario.
pub const MAX_OBSTACLES: usize = 1000;
/// Most mesh triangles in one scenario, over all obstacles (a box counts 12).
pub const MAX_TRIANGLES: usize = 100_000;
/// Most pieces of one piecewise trajectory.
pub const MAX_PIECES: usize = 10_000;
/// Largest gap accepted between consecutive pieces of a trajectory: in position relative to the
/// coordinates' size (at least 1), and in rotation angle (radians).
pub const JOIN_TOLERANCE: f64 = 1e-9;
/// Largest deviation of a quaternion's norm from 1 accepted without a warning.
pub const UNIT_TOLERANCE: f64 = 1e-9;

/// Largest coordinate accepted in a point or vector (metres, or the unit of the field): a cable
/// robot's scene is metres to tens of metres across, and coordinates far beyond this overflow the
/// exact arithmetic (squares of lengths, polynomial coefficients) into infinities that would
/// surface as misleading errors elsewhere (a base anchor at 1e308 read as a cable of zero length).
pub const MAX_COORD: f64 = 1e6;

/// Most links of one robot.
pub const MAX_LINKS: usize = 64;
/// Most joint coordinates of one robot.
pub const MAX_DOF: usize = 64;

/// Standard gravity, pointing down the world's z axis: the default of `robot.dynamics.gravity`.
pub const STANDARD_GRAVITY: [f64; 3] = [0.0, 0.0, -9.80665];

/// Validates a raw scenario; warnings go into the result.
pub fn scenario(raw: RawScenario) -> Result<Scenario> {
    let mut warnings = Vec::new();
    let version = super::json::version(&raw.format).unwrap_or(1);
    let mut robot = robot::robot(&raw.robot, robot::mobility(&raw.robot, version)?)?;
    robot.dynamics = robot::dynamics(&raw, version, robot.mobility)?;
    robot.winch = robot::winch(&raw, version)?;
    robot.speed = robot::platform_speed(&raw, version)?;
    let clearance = robot::clearance(&raw)?;
    let configs = chains::multi_link(&raw, &mut robot, &clearance, &mut warnings)?;
    if robot.chain.is_some() {
        let chain = robot.chain.as_ref().ok_or_else(|| Error::new("robot.links", "internal: chain missing"))?;
        let joint_paths = chains::joint_paths(&raw.trajectories, &configs, chain, version)?;
        let obstacles = obstacles::obstacles(&raw.obstacles)?;
        let queries = match &robot.chain {
            Some(chain) => queries::joint_queries(&raw.queries, &configs, chain)?,
            None => Vec::new(),
        };
        return Ok(Scenario { name: raw.name, robot, clearance, obstacles, poses: Vec::new(), written_angles: Vec::new(), trajectories: Vec::new(), queries, wrench: None, configs, joint_paths, warnings });
    }
    let obstacles = obstacles::obstacles(&raw.obstacles)?;
    // a point mass has no orientation to give
    let unoriented = robot.mobility == crate::model::Mobility::Point;
    let poses = motion::poses(&raw.poses.0, unoriented, &mut warnings)?;
    let written_angles = motion::written_angles(&raw.poses.0);
    motion::check_cable_lengths(&robot, &poses)?;
    let mut trajectories = motion::trajectories(&raw.trajectories, version >= 2, &poses, unoriented, &mut warnings)?;
    motion::durations(&raw, version, &mut trajectories)?;
    if robot.mobility == crate::model::Mobility::Planar {
        motion::in_plane(&poses, &trajectories)?;
    }
    let queries = queries::queries(&raw.queries, &poses)?;
    let mut wrench = raw.wrench.as_ref().map(|w| wrench::wrench(w, version)).transpose()?;
    if let Some(w) = &mut wrench {
        w.closure = wrench::closure(&raw, version)?;
    }
    Ok(Scenario { name: raw.name, robot, clearance, obstacles, poses, written_angles, trajectories, queries, wrench, configs, joint_paths: Vec::new(), warnings })
}

pub use crate::query::facets::{facets_enumerable, MAX_FACETS};

/// A finite number at `field`.
fn num(field: &str, x: f64) -> Result<f64> {
    finite(field, x)
}

/// A finite, non-negative number at `field`.
fn non_negative(field: &str, x: f64) -> Result<f64> {
    let x = num(field, x)?;
    if x < 0.0 {
        return Err(Error::new(field, format!("must not be negative, got {x}")));
    }
    Ok(x)
}

/// A finite, positive number at `field`.
fn positive(field: &str, x: f64) -> Result<f64> {
    let x = num(field, x)?;
    if x <= 0.0 {
        return Err(Error::new(field, format!("must be positive, got {x}")));
    }
    Ok(x)
}

/// A point or vector of three finite numbers at `field`.
fn vec3(field: &str, v: &Fixed<f64, 3>) -> Result<Vector3<f64>> {
    let [x, y, z] = v.0;
    Ok(Vector3::new(coordinate(&format!("{field}[0]"), x)?, coordinate(&format!("{field}[1]"), y)?, coordinate(&format!("{field}[2]"), z)?))
}

/// A finite number within ±[`MAX_COORD`] at `field`.
fn coordinate(field: &str, x: f64) -> Result<f64> {
    let x = num(field, x)?;
    if x.abs() > MAX_COORD {
        return Err(Error::new(field, format!("must be within ±{MAX_COORD:e} (a sane range for a cable robot's scene), got {x:e}")));
    }
    Ok(x)
}

/// Largest absolute component.
fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// A symmetric positive definite N×N matrix at `field`; symmetric up to a relative 1e-9 (then
/// symmetrised), definiteness by Cholesky.
fn spd<const N: usize>(field: &str, m: &Fixed<Fixed<f64, N>, N>, what: &str) -> Result<SMatrix<f64, N, N>> {
    let sym = symmetric(field, m)?;
    let scale = max_abs(sym.as_slice());
    if scale == 0.0 || Cholesky::<f64, Const<N>>::new(sym).is_none() || !sym.iter().all(|x| x.is_finite()) {
        return Err(Error::new(field, format!("not positive definite (its Cholesky factorisation fails): {what}")));
    }
    Ok(sym)
}

/// A symmetric N×N matrix of finite numbers at `field`; symmetric up to a relative 1e-9 (then
/// symmetrised).
fn symmetric<const N: usize>(field: &str, m: &Fixed<Fixed<f64, N>, N>) -> Result<SMatrix<f64, N, N>> {
    let mut a = SMatrix::<f64, N, N>::zeros();
    for (i, row) in m.0.iter().enumerate() {
        for (j, x) in row.0.iter().enumerate() {
            a[(i, j)] = num(&format!("{field}[{i}][{j}]"), *x)?;
        }
    }
    let scale = max_abs(a.as_slice());
    for i in 0..N {
        for j in (i + 1)..N {
            if (a[(i, j)] - a[(j, i)]).abs() > 1e-9 * scale {
                return Err(Error::new(
                    field,
                    format!("not symmetric: [{i}][{j}] = {} but [{j}][{i}] = {}", a[(i, j)], a[(j, i)]),
                ));
            }
        }
    }
    Ok((a + a.transpose()) * 0.5)
}

/// Refuses a field of format version `least` (4 to 6) in a file of an older version.
fn needs_format(version: u8, least: u8, field: &str) -> Result<()> {
    if version < least {
        let format = match least {
            ..=4 => FORMAT_4,
            5 => FORMAT_5,
            _ => FORMAT_6,
        };
        return Err(Error::new(field, format!("needs \"format\": \"{format}\"")));
    }
    Ok(())
}

/// The pose called `name`, if there is one.
fn find_pose<'a>(poses: &'a [(String, Pose)], name: &str) -> Option<&'a Pose> {
    poses.iter().find(|(n, _)| n == name).map(|(_, p)| p)
}

/// The names of `poses`, for a message about an unknown one.
fn known_poses(poses: &[(String, Pose)]) -> String {
    if poses.is_empty() {
        "the scenario has no poses".to_owned()
    } else {
        let names: Vec<&str> = poses.iter().map(|(n, _)| n.as_str()).collect();
        format!("known poses: {}", names.join(", "))
    }
}

/// The name of list entry `path` must be non-empty and differ from the `earlier` entries' names.
fn unique_name<'a>(path: &str, name: &str, kind: &str, list: &str, earlier: impl Iterator<Item = &'a str>) -> Result<()> {
    if name.trim().is_empty() {
        return Err(Error::new(format!("{path}.name"), "must not be empty"));
    }
    match earlier.enumerate().find(|(_, o)| *o == name) {
        Some((j, _)) => Err(Error::new(format!("{path}.name"), format!("duplicate {kind} name \"{name}\" (also {list}[{j}])"))),
        None => Ok(()),
    }
}
