//! The robot section: its cables (anchors, length and tension bounds, diameter), the platform's
//! dynamics and the winches' limits (format 4), and the clearances its cables keep.

use nalgebra::{Matrix3, Vector3};

use super::{needs_format, non_negative, positive, spd, symmetric, vec3, MAX_CABLES, MAX_CHAIN_CABLES, MIN_CABLES, STANDARD_GRAVITY};
use crate::error::{Error, Result};
use crate::model::{Bounds, Cable, Clearance, Dynamics, Mobility, Robot, Winch};
use crate::scenario::json::{RawBounds, RawCable, RawCableBounds, RawRobot, RawScenario, RawWinch, ScalarOrList};

/// How the platform moves (`robot.mobility`, format 5): spatial when absent; a multi-link robot's
/// links move by their joints instead.
pub(super) fn mobility(raw: &RawRobot, version: u8) -> Result<Mobility> {
    let Some(name) = &raw.mobility else { return Ok(Mobility::Spatial) };
    needs_format(version, 5, "robot.mobility")?;
    let all = [Mobility::Spatial, Mobility::Point, Mobility::Planar];
    let Some(mobility) = all.into_iter().find(|m| m.name() == name) else {
        return Err(Error::new("robot.mobility", format!("unknown mobility \"{name}\": expected \"spatial\", \"point\" or \"planar\"")));
    };
    if raw.links.is_some() && mobility != Mobility::Spatial {
        return Err(Error::new("robot.mobility", "a multi-link robot moves by its links' joints: omit robot.mobility"));
    }
    Ok(mobility)
}

/// A cable's platform anchor: given for a spatial or planar platform; omitted (or the origin)
/// for a point mass, whose cables all end at the point.
fn platform_anchor(i: usize, c: &RawCable, mobility: Mobility) -> Result<Vector3<f64>> {
    let field = format!("robot.cables[{i}].platform");
    match (&c.platform, mobility) {
        (None, Mobility::Point) => Ok(Vector3::zeros()),
        (Some(p), Mobility::Point) => {
            let p = vec3(&field, p)?;
            if p != Vector3::zeros() {
                return Err(Error::new(field, format!("a point-mass robot's cables all end at the point: omit it or give [0, 0, 0], got [{}, {}, {}]", p.x, p.y, p.z)));
            }
            Ok(p)
        }
        (None, _) => Err(Error::new(field, "missing field `platform`: each cable of a rigid platform names its anchor on the platform (only a point mass's cables omit it)")),
        (Some(p), _) => vec3(&field, p),
    }
}

/// For a planar robot, `v` (at `field`) lies in the plane z = 0.
pub(super) fn in_plane(field: &str, v: &Vector3<f64>, mobility: Mobility) -> Result<()> {
    if mobility == Mobility::Planar && v.z != 0.0 {
        return Err(Error::new(format!("{field}[2]"), format!("a planar robot lies in the plane z = 0, got z = {}", v.z)));
    }
    Ok(())
}

/// The robot's cables: at least [`MIN_CABLES`] for a spatial platform, three for a point mass or
/// a planar platform (one for a multi-link robot), at most [`MAX_CABLES`] ([`MAX_CHAIN_CABLES`]
/// on a multi-link robot), no two on one link
/// with the same anchors; their bounds and the diameter.
pub(super) fn robot(raw: &RawRobot, mobility: Mobility) -> Result<Robot> {
    let n = raw.cables.len();
    let least = if raw.links.is_some() { 1 } else { MIN_CABLES.min(mobility.dof()) };
    if n < least {
        let what = match (raw.links.is_some(), mobility) {
            (true, _) => "a multi-link robot",
            (false, Mobility::Spatial) => "a 6-DoF robot",
            (false, Mobility::Point) => "a point-mass robot",
            (false, Mobility::Planar) => "a planar robot",
        };
        return Err(Error::new("robot.cables", format!("{what} needs at least {least} cable(s), got {n}")));
    }
    let most = if raw.links.is_some() { MAX_CHAIN_CABLES } else { MAX_CABLES };
    if n > most {
        let what = if raw.links.is_some() { "on a multi-link robot" } else { "on a platform robot" };
        return Err(Error::new("robot.cables", format!("at most {most} cables are supported {what}, got {n}")));
    }
    let mut anchors = Vec::with_capacity(n);
    for (i, c) in raw.cables.iter().enumerate() {
        let base = vec3(&format!("robot.cables[{i}].base"), &c.base)?;
        in_plane(&format!("robot.cables[{i}].base"), &base, mobility)?;
        let platform = platform_anchor(i, c, mobility)?;
        in_plane(&format!("robot.cables[{i}].platform"), &platform, mobility)?;
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
        .map(|(((base, platform), length), tension)| Cable::straight(base, platform, 0, length, tension))
        .collect();
    Ok(Robot { cables, diameter, chain: None, dynamics: None, winch: Winch { speed: None, acceleration: None }, speed: None, mobility })
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
pub(super) fn dynamics(raw: &RawScenario, version: u8, mobility: Mobility) -> Result<Option<Dynamics>> {
    let Some(d) = &raw.robot.dynamics else { return Ok(None) };
    needs_format(version, 4, "robot.dynamics")?;
    if raw.robot.links.is_some() {
        return Err(Error::new("robot.dynamics", "a multi-link robot has no platform: give each link's `mass` and `com` (robot.links[k]) and, if not standard, `robot.gravity`"));
    }
    let mass = positive("robot.dynamics.mass", d.mass)?;
    let com = match &d.com {
        Some(c) => vec3("robot.dynamics.com", c)?,
        None => Vector3::zeros(),
    };
    let inertia = match (&d.inertia, mobility) {
        (None, Mobility::Point) => Matrix3::zeros(),
        (Some(_), Mobility::Point) => return Err(Error::new("robot.dynamics.inertia", "a point mass has no inertia: omit it")),
        (None, _) => return Err(Error::new("robot.dynamics.inertia", "missing field `inertia`: a rigid platform's inertia tensor about its centre of mass (kg·m²); only a point mass has none")),
        // turning about z alone, a planar platform's inertia is its I_zz
        (Some(i), Mobility::Planar) => {
            let i = symmetric("robot.dynamics.inertia", i)?;
            if !(i[(2, 2)] > 0.0) {
                return Err(Error::new("robot.dynamics.inertia[2][2]", format!("a planar platform's moment of inertia about z must be positive, got {}", i[(2, 2)])));
            }
            i
        }
        (Some(i), _) => spd("robot.dynamics.inertia", i, "an inertia tensor about the centre of mass is symmetric positive definite (kg·m²)")?,
    };
    if mobility == Mobility::Point && com != Vector3::zeros() {
        return Err(Error::new("robot.dynamics.com", "a point mass's centre of mass is the point: omit it or give [0, 0, 0]"));
    }
    in_plane("robot.dynamics.com", &com, mobility)?;
    let gravity = match &d.gravity {
        Some(g) => vec3("robot.dynamics.gravity", g)?,
        None => Vector3::from(STANDARD_GRAVITY),
    };
    Ok(Some(Dynamics { mass, com, inertia, gravity }))
}

/// The winches' limits (none when absent); each given limit positive.
pub(super) fn winch(raw: &RawScenario, version: u8) -> Result<Winch> {
    let Some(RawWinch { speed, acceleration }) = &raw.robot.winch else { return Ok(Winch { speed: None, acceleration: None }) };
    needs_format(version, 4, "robot.winch")?;
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
    needs_format(version, 4, "robot.speed")?;
    if raw.robot.links.is_some() {
        return Err(Error::new("robot.speed", "not supported for multi-link robots yet"));
    }
    positive("robot.speed", v).map(Some)
}
