//! The robot section: its cables (anchors, length and tension bounds, diameter), the platform's
//! dynamics and the winches' limits (format 4), and the clearances its cables keep.

use nalgebra::Vector3;

use super::{needs_format_4, non_negative, positive, spd, vec3, MAX_CABLES, MIN_CABLES, STANDARD_GRAVITY};
use crate::error::{Error, Result};
use crate::model::{Bounds, Cable, Clearance, Dynamics, Robot, Winch};
use crate::scenario::json::{RawBounds, RawCable, RawCableBounds, RawRobot, RawScenario, RawWinch, ScalarOrList};

/// The robot's cables: at least [`MIN_CABLES`] (one for a multi-link robot), at most
/// [`MAX_CABLES`], no two on one link with the same anchors; their bounds and the diameter.
pub(super) fn robot(raw: &RawRobot) -> Result<Robot> {
    let n = raw.cables.len();
    let least = if raw.links.is_some() { 1 } else { MIN_CABLES };
    if n < least {
        let what = if raw.links.is_some() { "a multi-link robot" } else { "a 6-DoF robot" };
        return Err(Error::new("robot.cables", format!("{what} needs at least {least} cable(s), got {n}")));
    }
    if n > MAX_CABLES {
        return Err(Error::new("robot.cables", format!("at most {MAX_CABLES} cables are supported, got {n}")));
    }
    let mut anchors = Vec::with_capacity(n);
    for (i, c) in raw.cables.iter().enumerate() {
        let base = vec3(&format!("robot.cables[{i}].base"), &c.base)?;
        let platform = vec3(&format!("robot.cables[{i}].platform"), &c.platform)?;
        for (j, (b, p)) in anchors.iter().enumerate() {
            if *b == base && *p == platform && raw.cables[j].link == c.link {
                return Err(Error::new(
                    format!("robot.cables[{i}]"),
                    format!(
                        "coincident anchors: cable {} has the same base and platform anchors as cable {} \
                         (robot.cables[{j}])",
                        i + 1,
                        j + 1
                    ),
                ));
            }
        }
        anchors.push((base, platform));
    }
    let length = bounds("length", raw.length.as_ref(), &raw.cables, |c| c.length.as_ref())?;
    let tension = bounds("tension", raw.tension.as_ref(), &raw.cables, |c| c.tension.as_ref())?;
    let diameter = match raw.diameter {
        Some(d) => non_negative("robot.diameter", d)?,
        None => 0.0,
    };
    let cables = anchors
        .into_iter()
        .zip(length)
        .zip(tension)
        .map(|(((base, platform), length), tension)| Cable { base, platform, link: 0, length, tension })
        .collect();
    Ok(Robot { cables, diameter, chain: None, dynamics: None, winch: Winch { speed: None, acceleration: None }, speed: None })
}

/// One value of a bound and the JSON path it came from (empty for the default).
type Sourced = (f64, String);

/// Per-cable bounds for `what` ("length" or "tension"): robot-level defaults (a number or an
/// array per cable), overridden end by end by a cable's own object.
fn bounds(
    what: &str,
    robot_level: Option<&RawBounds>,
    cables: &[RawCable],
    own: impl Fn(&RawCable) -> Option<&RawCableBounds>,
) -> Result<Vec<Bounds>> {
    let n = cables.len();
    let end = |name: &str, default: f64, v: Option<&ScalarOrList>| -> Result<Vec<Sourced>> {
        let field = format!("robot.{what}.{name}");
        Ok(match v {
            None => vec![(default, String::new()); n],
            Some(ScalarOrList::Scalar(x)) => vec![(*x, field); n],
            Some(ScalarOrList::List(xs)) => {
                if xs.len() != n {
                    return Err(Error::new(
                        field,
                        format!("expected a number or {n} numbers (one per cable), got {} numbers", xs.len()),
                    ));
                }
                xs.iter().enumerate().map(|(i, x)| (*x, format!("{field}[{i}]"))).collect()
            }
        })
    };
    let mut mins = end("min", 0.0, robot_level.and_then(|b| b.min.as_ref()))?;
    let mut maxs = end("max", f64::INFINITY, robot_level.and_then(|b| b.max.as_ref()))?;
    let mut out = Vec::with_capacity(n);
    for (i, cable) in cables.iter().enumerate() {
        let (Some(lo), Some(hi)) = (mins.get_mut(i), maxs.get_mut(i)) else {
            return Err(Error::new(format!("robot.{what}"), "internal: bound count mismatch"));
        };
        if let Some(b) = own(cable) {
            if let Some(x) = b.min {
                *lo = (x, format!("robot.cables[{i}].{what}.min"));
            }
            if let Some(x) = b.max {
                *hi = (x, format!("robot.cables[{i}].{what}.max"));
            }
        }
        for (x, src) in [&*lo, &*hi] {
            if src.is_empty() {
                continue; // a default: 0 or +inf
            }
            non_negative(src, *x)?;
        }
        if lo.0 > hi.0 {
            let field = if lo.1.starts_with("robot.cables") || hi.1.starts_with("robot.cables") {
                format!("robot.cables[{i}].{what}")
            } else {
                format!("robot.{what}")
            };
            return Err(Error::new(field, format!("min {} is greater than max {} for cable {}", lo.0, hi.0, i + 1)));
        }
        out.push(Bounds { min: lo.0, max: hi.0 });
    }
    Ok(out)
}

/// The clearances, each non-negative (0 when absent).
pub(super) fn clearance(raw: &RawScenario) -> Result<Clearance> {
    let (cc, co) = match &raw.clearance {
        Some(c) => (c.cable_cable, c.cable_obstacle),
        None => (None, None),
    };
    let cl = raw.clearance.as_ref().and_then(|c| c.cable_link);
    Ok(Clearance {
        cable_cable: match cc {
            Some(x) => non_negative("clearance.cable_cable", x)?,
            None => 0.0,
        },
        cable_obstacle: match co {
            Some(x) => non_negative("clearance.cable_obstacle", x)?,
            None => 0.0,
        },
        cable_link: match cl {
            Some(x) => non_negative("clearance.cable_link", x)?,
            None => 0.0,
        },
    })
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

/// The largest speed of the platform's origin (none when absent); positive.
pub(super) fn platform_speed(raw: &RawScenario, version: u8) -> Result<Option<f64>> {
    let Some(v) = raw.robot.speed else { return Ok(None) };
    needs_format_4(version, "robot.speed")?;
    if raw.robot.links.is_some() {
        return Err(Error::new("robot.speed", "not supported for multi-link robots yet"));
    }
    positive("robot.speed", v).map(Some)
}
