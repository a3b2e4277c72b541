//! Validation of the format-4 sections about time and mass: the platform's dynamics
//! (`robot.dynamics`), the winches' limits (`robot.winch`), trajectories' `duration`, and the
//! opt-in `wrench.closure`. Each needs `"format": "cablenav-scenario/4"`.

use nalgebra::Vector3;

use super::json::{RawScenario, RawWinch, FORMAT_4};
use super::validate::{spd, vec3, positive};
use crate::error::{Error, Result};
use crate::model::{Dynamics, Trajectory, Winch};

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

/// Sets each trajectory's duration from its `duration` (a positive number of seconds).
pub(super) fn durations(raw: &RawScenario, version: u8, trajectories: &mut [Trajectory]) -> Result<()> {
    for (k, (t, out)) in raw.trajectories.iter().zip(trajectories.iter_mut()).enumerate() {
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
