//! Validation of the format-4 sections about time and mass: the platform's dynamics
//! (`robot.dynamics`), the winches' limits (`robot.winch`), trajectories' `duration` or timed
//! `knots`, and the opt-in `wrench.closure`. Each needs `"format": "cablenav-scenario/4"`.

use nalgebra::Vector3;

use super::json::{RawKnot, RawPose, RawScenario, RawTrajectory, RawWinch, FORMAT_4};
use super::validate::{pose, positive, spd, vec3, MAX_PIECES};
use crate::error::{finite, Error, Result};
use crate::model::{Dynamics, Knot, Knots, Pose, Profile, Trajectory, Winch};

/// Standard gravity, pointing down the world's z axis: the default of `robot.dynamics.gravity`.
pub const STANDARD_GRAVITY: [f64; 3] = [0.0, 0.0, -9.80665];

/// Refuses a format-4 field in a file of an older version.
fn needs_format_4(version: u8, field: &str) -> Result<()> {
    if version < 4 {
        return Err(Error::new(field, format!("needs \"format\": \"{FORMAT_4}\"")));
    }
    Ok(())
}

/// The platform's dynamics, if given: a positive mass, the centre of mass (default the platform
/// origin), a symmetric positive definite inertia about it, gravity (default
/// [`STANDARD_GRAVITY`]).
pub(super) fn dynamics(raw: &RawScenario, version: u8) -> Result<Option<Dynamics>> {
    let Some(d) = &raw.robot.dynamics else { return Ok(None) };
    needs_format_4(version, "robot.dynamics")?;
    if raw.robot.links.is_some() {
        return Err(Error::new("robot.dynamics", "not supported for multi-link robots yet: the platform's dynamics apply to a 6-DoF platform"));
    }
    let mass = positive("robot.dynamics.mass", d.mass)?;
    let com = match &d.com {
        Some(c) => vec3("robot.dynamics.com", c)?,
        None => Vector3::zeros(),
    };
    let inertia = spd("robot.dynamics.inertia", &d.inertia, "an inertia tensor about the centre of mass is symmetric positive definite (kg·m²)")?;
    let gravity = match &d.gravity {
        Some(g) => vec3("robot.dynamics.gravity", g)?,
        None => Vector3::from(STANDARD_GRAVITY),
    };
    Ok(Some(Dynamics { mass, com, inertia, gravity }))
}

/// The winches' limits (none when absent); each given limit positive.
pub(super) fn winch(raw: &RawScenario, version: u8) -> Result<Winch> {
    let Some(RawWinch { speed, acceleration }) = &raw.robot.winch else { return Ok(Winch { speed: None, acceleration: None }) };
    needs_format_4(version, "robot.winch")?;
    if raw.robot.links.is_some() {
        return Err(Error::new("robot.winch", "not supported for multi-link robots yet"));
    }
    let speed = speed.map(|v| positive("robot.winch.speed", v)).transpose()?;
    let acceleration = acceleration.map(|a| positive("robot.winch.acceleration", a)).transpose()?;
    Ok(Winch { speed, acceleration })
}

/// Sets each trajectory's duration from its `duration` (a positive number of seconds); one
/// through knots takes its time from them.
pub(super) fn durations(raw: &RawScenario, version: u8, trajectories: &mut [Trajectory]) -> Result<()> {
    for (k, (t, out)) in raw.trajectories.iter().zip(trajectories.iter_mut()).enumerate() {
        if t.knots.is_some() {
            needs_format_4(version, &format!("trajectories[{k}].knots"))?;
            if t.duration.is_some() {
                return Err(Error::new(format!("trajectories[{k}].duration"), "a trajectory through knots takes its time from them: drop duration"));
            }
        }
        if let Some(d) = t.duration {
            let field = format!("trajectories[{k}].duration");
            needs_format_4(version, &field)?;
            out.duration = Some(positive(&field, d)?);
        }
    }
    Ok(())
}

/// Whether `wrench.closure` asks for the wrench closure condition (false when absent).
pub(super) fn closure(raw: &RawScenario, version: u8) -> Result<bool> {
    match raw.wrench.as_ref().and_then(|w| w.closure) {
        Some(c) => {
            needs_format_4(version, "wrench.closure")?;
            Ok(c)
        }
        None => Ok(false),
    }
}

/// A trajectory through timed knots (format 4 `spline` and `knots`): two or more knots, the
/// first at time 0, times strictly increasing; each knot's pose a named pose or a position and
/// one orientation form; velocities and accelerations (quintic only) finite, zero when absent.
pub(super) fn through_knots(path: &str, raw: &RawTrajectory, poses: &[(String, Pose)], warnings: &mut Vec<String>) -> Result<Trajectory> {
    let profile = match raw.spline.as_deref() {
        None | Some("quintic") => Profile::Quintic,
        Some("cubic") => Profile::Cubic,
        Some(other) => {
            return Err(Error::new(format!("{path}.spline"), format!("\"{other}\" is not a spline cablenav takes: give \"quintic\" or \"cubic\"")));
        }
    };
    let field = format!("{path}.knots");
    let Some(list) = &raw.knots else { return Err(Error::new(field, "a spline needs its knots")) };
    if list.len() < 2 || list.len() > MAX_PIECES + 1 {
        return Err(Error::new(field, format!("needs 2 to {} knots, got {}", MAX_PIECES + 1, list.len())));
    }
    let mut points: Vec<Knot> = Vec::with_capacity(list.len());
    for (j, k) in list.iter().enumerate() {
        let kf = format!("{field}[{j}]");
        let time = finite(&format!("{kf}.time"), k.time)?;
        match points.last() {
            None if time != 0.0 => return Err(Error::new(format!("{kf}.time"), format!("the first knot is at time 0 (seconds count from it), not {time}"))),
            Some(prev) if time <= prev.time => {
                return Err(Error::new(format!("{kf}.time"), format!("knots out of order: {time} s is not after knot {}'s {} s", j - 1, prev.time)));
            }
            _ => {}
        }
        let pose = knot_pose(&kf, k, poses, warnings)?;
        let velocity = k.velocity.as_ref().map(|v| vec3(&format!("{kf}.velocity"), v)).transpose()?.unwrap_or_else(Vector3::zeros);
        let acceleration = match (&k.acceleration, profile) {
            (Some(_), Profile::Cubic) => {
                return Err(Error::new(format!("{kf}.acceleration"), "a cubic spline meets positions and velocities only: drop the acceleration or use \"spline\": \"quintic\""));
            }
            (Some(a), Profile::Quintic) => vec3(&format!("{kf}.acceleration"), a)?,
            (None, _) => Vector3::zeros(),
        };
        points.push(Knot { time, pose, velocity, acceleration });
    }
    Trajectory::through_knots(raw.name.clone(), Knots { profile, points }).ok_or_else(|| Error::new(field, "needs at least two knots"))
}

/// A knot's pose: the named pose `pose`, or `position` with one orientation form.
fn knot_pose(kf: &str, k: &RawKnot, poses: &[(String, Pose)], warnings: &mut Vec<String>) -> Result<Pose> {
    let inline = k.position.is_some() || k.quaternion.is_some() || k.tilt_torsion.is_some() || k.euler_xyz_deg.is_some();
    match (&k.pose, inline) {
        (Some(_), true) => Err(Error::new(format!("{kf}.pose"), "give a pose name or a position and orientation, not both")),
        (Some(name), false) => poses
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| *p)
            .ok_or_else(|| Error::new(format!("{kf}.pose"), format!("no pose named \"{name}\""))),
        (None, _) => {
            let Some(position) = k.position.clone() else { return Err(Error::new(format!("{kf}.position"), "a knot needs a pose name or a position")) };
            let raw = RawPose { position, quaternion: k.quaternion.clone(), tilt_torsion: k.tilt_torsion.clone(), euler_xyz_deg: k.euler_xyz_deg.clone() };
            pose(kf, &raw, warnings)
        }
    }
}
