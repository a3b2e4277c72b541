//! Validation of the raw JSON into the model. Every check names the JSON path of the offending
//! value; nothing here indexes user data unchecked or unwraps it, so no input can panic.

use nalgebra::{Cholesky, Const, Matrix6, Quaternion, SMatrix, UnitQuaternion, Vector3, Vector6};
use std::collections::HashMap;
use std::f64::consts::FRAC_PI_2;

use super::json::{
    Fixed, QuatRef, RawBounds, RawCable, RawCableBounds, RawObstacle, RawOrientation, RawPose, RawQuery, RawRobot,
    RawPiece, RawScenario, RawTrajectory, RawTranslation, RawWrench, ScalarOrList,
};
use super::{Query, Scenario};
use crate::error::{finite, Error, Result};
use crate::model::{Bounds, Cable, Clearance, Coord, Orientation, PointFrame, Pose, Robot, Segment, Trajectory, Translation, Wrench};
use crate::shape::{Mesh, Obstacle, Shape};

/// Fewest cables of a 6-DoF robot.
pub const MIN_CABLES: usize = 6;
/// Most cables supported.
pub const MAX_CABLES: usize = 64;
/// Most obstacles in one scenario.
pub const MAX_OBSTACLES: usize = 1000;
/// Most mesh triangles in one scenario, over all obstacles (a box counts 12).
pub const MAX_TRIANGLES: usize = 100_000;
/// Highest polynomial degree of a translation (and so at most `MAX_DEGREE + 1` Bézier points):
/// the exact conditions multiply the translation with itself and with the rotation, so their
/// degree grows several times faster than this, and the limit keeps exact verification tractable.
pub const MAX_DEGREE: usize = 10;
/// Most pieces of one piecewise trajectory.
pub const MAX_PIECES: usize = 10_000;
/// Largest gap accepted between consecutive pieces of a trajectory: in position relative to the
/// coordinates' size (at least 1), and in rotation angle (radians).
pub const JOIN_TOLERANCE: f64 = 1e-9;
/// Largest deviation of a quaternion's norm from 1 accepted without a warning.
pub const UNIT_TOLERANCE: f64 = 1e-9;

/// Validates a raw scenario; warnings go into the result.
pub fn scenario(raw: RawScenario) -> Result<Scenario> {
    let mut warnings = Vec::new();
    let version = super::json::version(&raw.format).unwrap_or(1);
    let mut robot = robot(&raw.robot)?;
    robot.dynamics = super::timing::dynamics(&raw, version)?;
    robot.winch = super::timing::winch(&raw, version)?;
    let clearance = clearance(&raw)?;
    let configs = multi_link(&raw, &mut robot, &clearance, &mut warnings)?;
    if robot.chain.is_some() {
        let joint_paths = super::chain::joint_paths(&raw.trajectories, &configs)?;
        let obstacles = obstacles(&raw.obstacles)?;
        return Ok(Scenario { name: raw.name, robot, clearance, obstacles, poses: Vec::new(), trajectories: Vec::new(), queries: Vec::new(), wrench: None, configs, joint_paths, warnings });
    }
    let obstacles = obstacles(&raw.obstacles)?;
    let poses = poses(&raw.poses.0, &mut warnings)?;
    check_cable_lengths(&robot, &poses)?;
    let mut trajectories = trajectories(&raw.trajectories, version >= 2, &poses, &mut warnings)?;
    super::timing::durations(&raw, version, &mut trajectories)?;
    let queries = queries(&raw.queries, &poses)?;
    let mut wrench = raw.wrench.as_ref().map(|w| wrench(w, version)).transpose()?;
    if let Some(w) = &mut wrench {
        w.closure = super::timing::closure(&raw, version)?;
    }
    let m = robot.cables.len();
    if let Some(w) = wrench.as_ref().filter(|_| m > MAX_WRENCH_CABLES) {
        let why = "(the ellipsoid and closure are tested against every facet of the available wrench set, one per 5 \
                   structure-matrix columns; beyond that the nominal wrench and the platform's dynamics are tested by \
                   linear programs)";
        if !w.is_single() {
            let field = if raw.wrench.as_ref().is_some_and(|r| r.radius.is_some()) { "wrench.radius" } else { "wrench.ellipsoid" };
            return Err(Error::new(field, format!("a wrench ellipsoid is supported for up to {MAX_WRENCH_CABLES} cables {why}; this robot has {m}")));
        }
        if w.closure {
            return Err(Error::new("wrench.closure", format!("wrench closure is supported for up to {MAX_WRENCH_CABLES} cables {why}; this robot has {m}")));
        }
    }
    Ok(Scenario { name: raw.name, robot, clearance, obstacles, poses, trajectories, queries, wrench, configs, joint_paths: Vec::new(), warnings })
}

/// The multi-link sections (format 3): the chain and each cable's link go into `robot`; returns
/// the named configurations. A platform robot must not use them, and a multi-link robot is
/// configured by configurations only (no poses, trajectories, queries or wrench set yet).
fn multi_link(raw: &RawScenario, robot: &mut Robot, clearance: &Clearance, warnings: &mut Vec<String>) -> Result<Vec<(String, Vec<f64>)>> {
    let Some(links) = &raw.robot.links else {
        if let Some(k) = raw.trajectories.iter().position(|t| t.through.is_some()) {
            return Err(Error::new(format!("trajectories[{k}].through"), "only a multi-link robot's trajectories pass through configurations; a platform robot's have translation and orientation"));
        }
        if let Some(i) = raw.robot.cables.iter().position(|c| c.link.is_some()) {
            return Err(Error::new(format!("robot.cables[{i}].link"), "only the cables of a multi-link robot (robot.links) name a link"));
        }
        if !raw.configurations.0.is_empty() {
            return Err(Error::new("configurations", "only multi-link robots (robot.links) have configurations; a platform robot has poses"));
        }
        return Ok(Vec::new());
    };
    if super::json::version(&raw.format).unwrap_or(1) < 3 {
        return Err(Error::new("robot.links", format!("multi-link robots need \"format\": \"{}\"", super::json::FORMAT_3)));
    }
    let chain = super::chain::chain(links)?;
    for (cable, link) in robot.cables.iter_mut().zip(super::chain::cable_links(&raw.robot.cables, &chain)?) {
        cable.link = link;
    }
    for (field, given) in [("poses", !raw.poses.0.is_empty()), ("queries", !raw.queries.is_empty()), ("wrench", raw.wrench.is_some())] {
        if given {
            return Err(Error::new(
                field,
                "not supported for multi-link robots yet: they are configured by named joint configurations \
                 (`configurations`, paths through them in `trajectories`), and their wrench condition is \
                 joint-space wrench closure, always checked",
            ));
        }
    }
    for (i, cable) in robot.cables.iter().enumerate() {
        let link = &chain.links[cable.link];
        let zone = link.radius + clearance.cable_link;
        if zone > 0.0 && crate::conditions::attached_inside(&cable.platform, &link.body, zone) {
            warnings.push(format!(
                "robot.cables[{i}]: cable {} is attached within {zone} (radius + clearance) of its own link {}'s body; \
                 its clearance to that link is not checked",
                i + 1,
                link.name
            ));
        }
    }
    robot.chain = Some(chain);
    let chain = robot.chain.as_ref().ok_or_else(|| Error::new("robot.links", "internal: chain missing"))?;
    super::chain::configurations(&raw.configurations, robot, chain, warnings)
}

/// Most cables for which the wrench conditions test all C(m, 5) facets of the structure matrix
/// (252 for 10 cables): a wrench ellipsoid and wrench closure are supported up to this; beyond
/// it the nominal load is tested by linear programs ([`crate::conditions::WrenchFeasibilityLp`]).
pub const MAX_WRENCH_CABLES: usize = 10;

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
pub(super) fn positive(field: &str, x: f64) -> Result<f64> {
    let x = num(field, x)?;
    if x <= 0.0 {
        return Err(Error::new(field, format!("must be positive, got {x}")));
    }
    Ok(x)
}

/// A point or vector of three finite numbers at `field`.
pub(super) fn vec3(field: &str, v: &Fixed<f64, 3>) -> Result<Vector3<f64>> {
    let [x, y, z] = v.0;
    Ok(Vector3::new(num(&format!("{field}[0]"), x)?, num(&format!("{field}[1]"), y)?, num(&format!("{field}[2]"), z)?))
}

/// Largest absolute component.
fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// The unit quaternion for `[w, x, y, z]` at `field`: zero is an error, a non-unit one is
/// normalised with a warning.
fn unit_quaternion(field: &str, q: [f64; 4], warnings: &mut Vec<String>) -> Result<UnitQuaternion<f64>> {
    for (i, x) in q.iter().enumerate() {
        num(&format!("{field}[{i}]"), *x)?;
    }
    let m = max_abs(&q);
    if m == 0.0 {
        return Err(Error::new(field, "zero quaternion: it describes no rotation"));
    }
    // Scale first so that the norm neither overflows nor underflows.
    let s = q.map(|x| x / m);
    let ns = s.iter().map(|x| x * x).sum::<f64>().sqrt();
    let norm = ns * m;
    if (norm - 1.0).abs() > UNIT_TOLERANCE {
        warnings.push(format!("{field}: quaternion of norm {norm} is not unit; normalised"));
    }
    let u = s.map(|x| x / ns);
    Ok(UnitQuaternion::from_quaternion(Quaternion::new(u[0], u[1], u[2], u[3])))
}

fn robot(raw: &RawRobot) -> Result<Robot> {
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
    Ok(Robot { cables, diameter, chain: None, dynamics: None, winch: crate::model::Winch { speed: None, acceleration: None } })
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

fn clearance(raw: &RawScenario) -> Result<Clearance> {
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

/// Obstacle types and the geometric fields each takes (besides `name` and `type`).
const OBSTACLE_FIELDS: [(&str, &[&str]); 6] = [
    ("box", &["center", "size"]),
    ("mesh", &["vertices", "triangles"]),
    ("sphere", &["center", "radius"]),
    ("ellipsoid", &["center", "matrix"]),
    ("cylinder", &["from", "to", "radius"]),
    ("cone", &["apex", "axis", "half_angle", "height"]),
];

/// A field that the obstacle's type requires.
fn required<'a, T>(path: &str, kind: &str, name: &str, v: &'a Option<T>) -> Result<&'a T> {
    v.as_ref()
        .ok_or_else(|| Error::new(format!("{path}.{name}"), format!("missing field `{name}` (required for a {kind})")))
}

fn obstacles(raw: &[RawObstacle]) -> Result<Vec<Obstacle>> {
    if raw.len() > MAX_OBSTACLES {
        return Err(Error::new(
            "obstacles",
            format!("at most {MAX_OBSTACLES} obstacles are supported, got {}", raw.len()),
        ));
    }
    let mut out = Vec::with_capacity(raw.len());
    let mut names: HashMap<String, usize> = HashMap::new();
    let mut triangles = 0usize;
    for (k, o) in raw.iter().enumerate() {
        let path = format!("obstacles[{k}]");
        let name = match &o.name {
            Some(s) if s.trim().is_empty() => {
                return Err(Error::new(format!("{path}.name"), "must not be empty"));
            }
            Some(s) => s.clone(),
            None => format!("obstacle {}", k + 1),
        };
        if let Some(j) = names.get(&name) {
            let field = if o.name.is_some() { format!("{path}.name") } else { path.clone() };
            return Err(Error::new(field, format!("duplicate obstacle name \"{name}\" (also obstacles[{j}])")));
        }
        names.insert(name.clone(), k);
        let Some((kind, allowed)) = OBSTACLE_FIELDS.iter().find(|(t, _)| *t == o.kind) else {
            let types: Vec<&str> = OBSTACLE_FIELDS.iter().map(|(t, _)| *t).collect();
            return Err(Error::new(
                format!("{path}.type"),
                format!("unknown obstacle type \"{}\"; expected one of {}", o.kind, types.join(", ")),
            ));
        };
        for f in o.present_fields() {
            if !allowed.contains(&f) {
                return Err(Error::new(
                    format!("{path}.{f}"),
                    format!("not a field of a {kind} obstacle (its fields: name, color, type, {})", allowed.join(", ")),
                ));
            }
        }
        let what = format!("{kind} obstacle");
        let shape = match *kind {
            "box" => {
                let center = vec3(&format!("{path}.center"), required(&path, &what, "center", &o.center)?)?;
                let size = vec3(&format!("{path}.size"), required(&path, &what, "size", &o.size)?)?;
                for i in 0..3 {
                    positive(&format!("{path}.size[{i}]"), size[i])?;
                }
                Shape::Mesh(Mesh::cuboid(center, size))
            }
            "mesh" => Shape::Mesh(mesh(&path, o)?),
            "sphere" => Shape::Sphere {
                center: vec3(&format!("{path}.center"), required(&path, &what, "center", &o.center)?)?,
                radius: positive(&format!("{path}.radius"), *required(&path, &what, "radius", &o.radius)?)?,
            },
            "ellipsoid" => {
                let center = vec3(&format!("{path}.center"), required(&path, &what, "center", &o.center)?)?;
                let m = required(&path, &what, "matrix", &o.matrix)?;
                Shape::Ellipsoid { center, matrix: spd(&format!("{path}.matrix"), m, "an ellipsoid {x : (x−c)ᵀM(x−c) ≤ 1} needs M with positive eigenvalues")? }
            }
            "cylinder" => {
                let from = vec3(&format!("{path}.from"), required(&path, &what, "from", &o.from)?)?;
                let to = vec3(&format!("{path}.to"), required(&path, &what, "to", &o.to)?)?;
                if from == to {
                    return Err(Error::new(format!("{path}.to"), "equals `from`: the cylinder axis has zero length"));
                }
                let radius = positive(&format!("{path}.radius"), *required(&path, &what, "radius", &o.radius)?)?;
                Shape::Cylinder { from, to, radius }
            }
            _ => {
                // "cone", the last entry of OBSTACLE_FIELDS.
                let apex = vec3(&format!("{path}.apex"), required(&path, &what, "apex", &o.apex)?)?;
                let axis = vec3(&format!("{path}.axis"), required(&path, &what, "axis", &o.axis)?)?;
                let m = max_abs(axis.as_slice());
                if m == 0.0 {
                    return Err(Error::new(format!("{path}.axis"), "zero vector: the cone axis needs a direction"));
                }
                let axis = (axis / m).normalize();
                let field = format!("{path}.half_angle");
                let half_angle = num(&field, *required(&path, &what, "half_angle", &o.half_angle)?)?;
                if !(half_angle > 0.0 && half_angle < FRAC_PI_2) {
                    return Err(Error::new(field, format!("must be in (0, π/2) radians, got {half_angle}")));
                }
                let height = positive(&format!("{path}.height"), *required(&path, &what, "height", &o.height)?)?;
                Shape::Cone { apex, axis, half_angle, height }
            }
        };
        if let Shape::Mesh(m) = &shape {
            triangles += m.triangles.len();
            if triangles > MAX_TRIANGLES {
                return Err(Error::new(
                    path,
                    format!(
                        "the scenario's meshes have more than {MAX_TRIANGLES} triangles in total (a box counts 12)"
                    ),
                ));
            }
        }
        let color = o.color.as_deref().map(|c| color(&format!("{path}.color"), c)).transpose()?;
        out.push(Obstacle { name, shape, color });
    }
    Ok(out)
}

/// A display colour: `#` and six hexadecimal digits (`#rrggbb`), kept as given.
fn color(field: &str, c: &str) -> Result<String> {
    let hex = c.strip_prefix('#').unwrap_or_default();
    if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return Err(Error::new(field, format!("{c:?} is not a colour of the form \"#rrggbb\" (six hexadecimal digits)")));
    }
    Ok(c.to_owned())
}

fn mesh(path: &str, o: &RawObstacle) -> Result<Mesh> {
    let what = "mesh obstacle";
    let raw_vertices = required(path, what, "vertices", &o.vertices)?;
    let raw_triangles = required(path, what, "triangles", &o.triangles)?;
    if raw_triangles.is_empty() {
        return Err(Error::new(format!("{path}.triangles"), "a mesh needs at least one triangle"));
    }
    if raw_triangles.len() > MAX_TRIANGLES {
        return Err(Error::new(
            format!("{path}.triangles"),
            format!("at most {MAX_TRIANGLES} triangles are supported, got {}", raw_triangles.len()),
        ));
    }
    let vertices = raw_vertices
        .iter()
        .enumerate()
        .map(|(i, v)| vec3(&format!("{path}.vertices[{i}]"), v))
        .collect::<Result<Vec<_>>>()?;
    let nv = vertices.len();
    let mut triangles = Vec::with_capacity(raw_triangles.len());
    for (t, tri) in raw_triangles.iter().enumerate() {
        let mut corners = [Vector3::zeros(); 3];
        for (c, &idx) in tri.0.iter().enumerate() {
            match vertices.get(idx) {
                Some(v) => corners[c] = *v,
                None => {
                    return Err(Error::new(
                        format!("{path}.triangles[{t}][{c}]"),
                        format!("vertex index {idx} out of range: the mesh has {nv} vertices (indices from 0)"),
                    ))
                }
            }
        }
        let [a, b, c] = corners;
        let scale = (b - a).norm().max((c - a).norm()).max((c - b).norm());
        let area2 = (b - a).cross(&(c - a)).norm();
        if area2.is_nan() || area2 <= 1e-12 * scale * scale {
            return Err(Error::new(
                format!("{path}.triangles[{t}]"),
                "degenerate triangle (zero area): its corners coincide or are collinear",
            ));
        }
        triangles.push(tri.0);
    }
    Ok(Mesh { vertices, triangles })
}

/// A symmetric positive definite N×N matrix at `field`; symmetric up to a relative 1e-9 (then
/// symmetrised), definiteness by Cholesky.
pub(super) fn spd<const N: usize>(field: &str, m: &Fixed<Fixed<f64, N>, N>, what: &str) -> Result<SMatrix<f64, N, N>> {
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
    let sym = (a + a.transpose()) * 0.5;
    if scale == 0.0 || Cholesky::<f64, Const<N>>::new(sym).is_none() || !sym.iter().all(|x| x.is_finite()) {
        return Err(Error::new(field, format!("not positive definite (its Cholesky factorisation fails): {what}")));
    }
    Ok(sym)
}

/// The wrench section: E from `ellipsoid` or from `radius` (E = I/radius²), at most one of them;
/// neither (format 4): the nominal wrench alone (E⁻¹ = 0, as [`Wrench::zero`]).
fn wrench(raw: &RawWrench, version: u8) -> Result<Wrench> {
    let nominal = Vector6::from_fn(|i, _| raw.nominal.0[i]);
    for i in 0..6 {
        num(&format!("wrench.nominal[{i}]"), nominal[i])?;
    }
    let point = match &raw.point {
        Some(p) => vec3("wrench.point", p)?,
        None => Vector3::zeros(),
    };
    let frame = match raw.point_frame.as_deref() {
        None | Some("platform") => PointFrame::Platform,
        Some("world") => PointFrame::World,
        Some(other) => return Err(Error::new("wrench.point_frame", format!("{other:?} is not \"platform\" or \"world\""))),
    };
    let ellipsoid = match (&raw.ellipsoid, raw.radius) {
        (Some(m), None) => spd("wrench.ellipsoid", m, "the wrench set {w : (w−w0)ᵀE(w−w0) ≤ 1} needs E with positive eigenvalues")?,
        (None, Some(r)) => Matrix6::identity() / positive("wrench.radius", r)?.powi(2),
        (Some(_), Some(_)) => return Err(Error::new("wrench", "give either \"ellipsoid\" or \"radius\", not both")),
        (None, None) if version >= 4 => return Ok(Wrench { nominal, point, frame, ..Wrench::zero() }),
        (None, None) => {
            return Err(Error::new("wrench", "needs \"ellipsoid\" (a 6×6 SPD matrix E) or \"radius\" (format 4 also takes the nominal wrench alone)"))
        }
    };
    let ellipsoid_inv = ellipsoid
        .try_inverse()
        .filter(|m| m.iter().all(|x| x.is_finite()))
        .ok_or_else(|| Error::new("wrench.ellipsoid", "cannot be inverted in floating point"))?;
    Ok(Wrench { nominal, ellipsoid, ellipsoid_inv, point, frame, closure: false })
}

fn poses(raw: &[(String, RawPose)], warnings: &mut Vec<String>) -> Result<Vec<(String, Pose)>> {
    let mut out: Vec<(String, Pose)> = Vec::with_capacity(raw.len());
    for (name, p) in raw {
        let path = format!("poses.{name}");
        if name.is_empty() {
            return Err(Error::new("poses", "a pose name must not be empty"));
        }
        if out.iter().any(|(n, _)| n == name) {
            return Err(Error::new(path, format!("duplicate pose name \"{name}\"")));
        }
        out.push((name.clone(), pose(&path, p, warnings)?));
    }
    Ok(out)
}

/// One pose at `path`: its position and exactly one orientation form.
pub(super) fn pose(path: &str, p: &RawPose, warnings: &mut Vec<String>) -> Result<Pose> {
    let position = vec3(&format!("{path}.position"), &p.position)?;
    let given: Vec<&str> = [
        ("quaternion", p.quaternion.is_some()),
        ("tilt_torsion", p.tilt_torsion.is_some()),
        ("euler_xyz_deg", p.euler_xyz_deg.is_some()),
    ]
    .iter()
    .filter(|(_, present)| *present)
    .map(|(n, _)| *n)
    .collect();
    if given.len() != 1 {
        let got = if given.is_empty() { "none".to_owned() } else { given.join(" and ") };
        return Err(Error::new(
            path,
            format!("give the orientation as exactly one of quaternion, tilt_torsion, euler_xyz_deg; got {got}"),
        ));
    }
    let pose = if let Some(q) = &p.quaternion {
        Pose { position, rotation: unit_quaternion(&format!("{path}.quaternion"), q.0, warnings)? }
    } else if let Some(a) = &p.tilt_torsion {
        canonical(Pose::from_tilt_torsion(position, angles(&format!("{path}.tilt_torsion"), a)?))
    } else if let Some(a) = &p.euler_xyz_deg {
        canonical(Pose::from_euler_xyz_deg(position, angles(&format!("{path}.euler_xyz_deg"), a)?))
    } else {
        return Err(Error::new(path, "no orientation given"));
    };
    Ok(pose)
}

fn angles(field: &str, a: &Fixed<f64, 3>) -> Result<[f64; 3]> {
    let v = vec3(field, a)?;
    Ok([v.x, v.y, v.z])
}

/// The quaternion of an orientation given by angles, with its sign chosen so that w ≥ 0 (the
/// sign is otherwise an artefact of the conversion, and slerps between named poses should
/// not take the long way round because of it).
fn canonical(p: Pose) -> Pose {
    if p.rotation.quaternion().w < 0.0 {
        Pose { position: p.position, rotation: UnitQuaternion::new_unchecked(-p.rotation.into_inner()) }
    } else {
        p
    }
}

/// A cable of zero length at a named pose has no direction: an error.
fn check_cable_lengths(robot: &Robot, poses: &[(String, Pose)]) -> Result<()> {
    for (name, pose) in poses {
        for (i, c) in robot.cables.iter().enumerate() {
            let end = pose.transform(&c.platform);
            let scale = 1.0 + c.base.norm().max(end.norm());
            if (end - c.base).norm() <= 1e-12 * scale {
                return Err(Error::new(
                    format!("poses.{name}"),
                    format!("cable {} has zero length at pose {name}", i + 1),
                ));
            }
        }
    }
    Ok(())
}

fn find_pose<'a>(poses: &'a [(String, Pose)], name: &str) -> Option<&'a Pose> {
    poses.iter().find(|(n, _)| n == name).map(|(_, p)| p)
}

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

fn trajectories(
    raw: &[RawTrajectory],
    version_2: bool,
    poses: &[(String, Pose)],
    warnings: &mut Vec<String>,
) -> Result<Vec<Trajectory>> {
    let mut out: Vec<Trajectory> = Vec::with_capacity(raw.len());
    for (k, t) in raw.iter().enumerate() {
        let path = format!("trajectories[{k}]");
        unique_name(&path, &t.name, "trajectory", "trajectories", out.iter().map(|o| o.name.as_str()))?;
        if t.knots.is_some() || t.spline.is_some() {
            if t.pieces.is_some() || t.translation.is_some() || t.orientation.is_some() {
                return Err(Error::new(format!("{path}.knots"), "give either knots or translation and orientation (or pieces), not both"));
            }
            out.push(super::timing::through_knots(&path, t, poses, warnings)?);
            continue;
        }
        let traj = match (&t.pieces, &t.translation, &t.orientation) {
            (Some(pieces), None, None) => {
                if !version_2 {
                    return Err(Error::new(
                        format!("{path}.pieces"),
                        format!("piecewise trajectories need \"format\": \"{}\"", super::json::FORMAT_2),
                    ));
                }
                piecewise(&path, &t.name, pieces, poses, warnings)?
            }
            (Some(_), _, _) => {
                return Err(Error::new(format!("{path}.pieces"), "give either pieces or translation and orientation, not both"));
            }
            (None, Some(tr), Some(or)) => Trajectory::single(
                t.name.clone(),
                translation(&format!("{path}.translation"), tr)?,
                orientation(&format!("{path}.orientation"), or, poses, warnings)?,
            ),
            (None, None, _) => return Err(Error::new(format!("{path}.translation"), "missing field `translation`")),
            (None, _, None) => return Err(Error::new(format!("{path}.orientation"), "missing field `orientation`")),
        };
        out.push(traj);
    }
    Ok(out)
}

/// A piecewise trajectory: 1 to [`MAX_PIECES`] pieces, each starting where the previous ends
/// (position and rotation within [`JOIN_TOLERANCE`]).
fn piecewise(path: &str, name: &str, raw: &[RawPiece], poses: &[(String, Pose)], warnings: &mut Vec<String>) -> Result<Trajectory> {
    let field = format!("{path}.pieces");
    if raw.is_empty() || raw.len() > MAX_PIECES {
        return Err(Error::new(field, format!("needs 1 to {MAX_PIECES} pieces, got {}", raw.len())));
    }
    let mut pieces: Vec<Segment> = Vec::with_capacity(raw.len());
    for (j, p) in raw.iter().enumerate() {
        let pf = format!("{field}[{j}]");
        let seg = Segment {
            translation: translation(&format!("{pf}.translation"), &p.translation)?,
            orientation: orientation(&format!("{pf}.orientation"), &p.orientation, poses, warnings)?,
        };
        if let Some(prev) = pieces.last() {
            let (a, b) = (prev.pose_at(1.0), seg.pose_at(0.0));
            let scale = a.position.amax().max(1.0);
            let gap = (a.position - b.position).norm();
            if gap > JOIN_TOLERANCE * scale {
                return Err(Error::new(
                    format!("{pf}.translation"),
                    format!("starts {gap:.3e} away from where piece {} ends: the pieces of a trajectory must join", j - 1),
                ));
            }
            let angle = a.rotation.angle_to(&b.rotation);
            if angle > JOIN_TOLERANCE {
                return Err(Error::new(
                    format!("{pf}.orientation"),
                    format!("starts {angle:.3e} rad away from the rotation where piece {} ends: the pieces of a trajectory must join", j - 1),
                ));
            }
        }
        pieces.push(seg);
    }
    Trajectory::piecewise(name, pieces).ok_or_else(|| Error::new(field, "needs at least one piece"))
}

fn translation(path: &str, t: &RawTranslation) -> Result<Translation> {
    let count = [t.polynomial.is_some(), t.bezier.is_some(), t.line.is_some()].iter().filter(|b| **b).count();
    if count != 1 {
        return Err(Error::new(path, format!("give exactly one of polynomial, bezier, line; got {count}")));
    }
    if let Some(rows) = &t.polynomial {
        let field = format!("{path}.polynomial");
        if rows.len() != 3 {
            return Err(Error::new(field, format!("expected 3 rows of coefficients (x, y, z), got {}", rows.len())));
        }
        let mut out: [Vec<f64>; 3] = Default::default();
        for (i, (row, slot)) in rows.iter().zip(out.iter_mut()).enumerate() {
            let rf = format!("{field}[{i}]");
            if row.is_empty() {
                return Err(Error::new(rf, "empty row: give at least the constant coefficient"));
            }
            let mut coeffs =
                row.iter().enumerate().map(|(j, x)| num(&format!("{rf}[{j}]"), *x)).collect::<Result<Vec<f64>>>()?;
            // Trailing zero coefficients do not raise the degree.
            while coeffs.len() > 1 && coeffs.last() == Some(&0.0) {
                coeffs.pop();
            }
            let degree = coeffs.len() - 1;
            if degree > MAX_DEGREE {
                return Err(Error::new(
                    rf,
                    format!(
                        "degree {degree} is above the maximum {MAX_DEGREE}: the exact interference conditions \
                         have several times the trajectory's degree, and the limit keeps exact verification \
                         tractable"
                    ),
                ));
            }
            *slot = coeffs;
        }
        return Ok(Translation::Polynomial(out));
    }
    if let Some(points) = &t.bezier {
        let field = format!("{path}.bezier");
        let n = points.len();
        if n < 2 {
            return Err(Error::new(field, format!("a Bézier curve needs at least 2 control points, got {n}")));
        }
        if n > MAX_DEGREE + 1 {
            return Err(Error::new(
                field,
                format!(
                    "at most {} control points (degree {MAX_DEGREE}) are supported, got {n}: the exact \
                     interference conditions have several times the trajectory's degree, and the limit keeps \
                     exact verification tractable",
                    MAX_DEGREE + 1
                ),
            ));
        }
        let pts =
            points.iter().enumerate().map(|(i, p)| vec3(&format!("{field}[{i}]"), p)).collect::<Result<Vec<_>>>()?;
        return Ok(Translation::Bezier(pts));
    }
    if let Some(Fixed([a, b])) = &t.line {
        let field = format!("{path}.line");
        return Ok(Translation::Line(vec3(&format!("{field}[0]"), a)?, vec3(&format!("{field}[1]"), b)?));
    }
    Err(Error::new(path, "give exactly one of polynomial, bezier, line"))
}

fn orientation(
    path: &str,
    o: &RawOrientation,
    poses: &[(String, Pose)],
    warnings: &mut Vec<String>,
) -> Result<Orientation> {
    let field = format!("{path}.slerp");
    let mut ends = Vec::with_capacity(2);
    for (i, r) in o.slerp.0.iter().enumerate() {
        let f = format!("{field}[{i}]");
        let q = match r {
            QuatRef::Quat(q) => unit_quaternion(&f, *q, warnings)?,
            QuatRef::Pose(name) => match find_pose(poses, name) {
                Some(p) => p.rotation,
                None => {
                    return Err(Error::new(f, format!("unknown pose \"{name}\"; {}", known_poses(poses))));
                }
            },
        };
        ends.push(q);
    }
    let (Some(qs), Some(qe)) = (ends.first().copied(), ends.get(1).copied()) else {
        return Err(Error::new(field, "expected 2 orientations"));
    };
    let dot = qs.coords.dot(&qe.coords);
    if dot <= -1.0 + 1e-12 {
        return Err(Error::new(
            field,
            "Qs·Qe = −1: the two quaternions are the same rotation with opposite signs, so the slerp between \
             them is undefined; give both with the same sign",
        ));
    }
    if dot < 0.0 {
        warnings.push(format!(
            "{field}: Qs·Qe = {dot} is negative, so the slerp takes the long way round (cos θ = Qs·Qe is used as \
             given); negate one quaternion for the short way"
        ));
    }
    Ok(Orientation::Slerp(qs, qe))
}

fn queries(raw: &[RawQuery], poses: &[(String, Pose)]) -> Result<Vec<Query>> {
    let mut out: Vec<Query> = Vec::with_capacity(raw.len());
    for (k, q) in raw.iter().enumerate() {
        let path = format!("queries[{k}]");
        unique_name(&path, &q.name, "query", "queries", out.iter().map(|o| o.name.as_str()))?;
        for (field, name) in [("start", &q.start), ("goal", &q.goal)] {
            if find_pose(poses, name).is_none() {
                return Err(Error::new(
                    format!("{path}.{field}"),
                    format!("unknown pose \"{name}\"; {}", known_poses(poses)),
                ));
            }
        }
        let mut fixed = Vec::with_capacity(q.fixed.len());
        for (i, s) in q.fixed.iter().enumerate() {
            let f = format!("{path}.fixed[{i}]");
            let Some(c) = Coord::parse(s) else {
                let names: Vec<&str> = Coord::ALL.iter().map(|c| c.name()).collect();
                return Err(Error::new(f, format!("unknown coordinate \"{s}\"; expected one of {}", names.join(", "))));
            };
            if fixed.contains(&c) {
                return Err(Error::new(f, format!("coordinate \"{s}\" is listed twice")));
            }
            fixed.push(c);
        }
        let mut region: Vec<(Coord, [f64; 2])> = Vec::new();
        for (name, Fixed([lo, hi])) in q.region.iter().flat_map(|r| r.0.iter()) {
            let f = format!("{path}.region.{name}");
            let Some(c) = Coord::parse(name) else {
                let names: Vec<&str> = Coord::ALL.iter().map(|c| c.name()).collect();
                return Err(Error::new(f, format!("unknown coordinate \"{name}\"; expected one of {}", names.join(", "))));
            };
            if fixed.contains(&c) {
                return Err(Error::new(f, format!("coordinate \"{name}\" is fixed by this query: it has no range")));
            }
            if region.iter().any(|(r, _)| *r == c) {
                return Err(Error::new(f, format!("coordinate \"{name}\" is given twice")));
            }
            let (lo, hi) = (num(&format!("{f}[0]"), *lo)?, num(&format!("{f}[1]"), *hi)?);
            if lo >= hi {
                return Err(Error::new(f, format!("needs LO < HI, got [{lo}, {hi}]")));
            }
            region.push((c, [lo, hi]));
        }
        out.push(Query { name: q.name.clone(), start: q.start.clone(), goal: q.goal.clone(), fixed, region });
    }
    Ok(out)
}
