//! Validation of a multi-link robot's sections (format 3: `robot.links`, cables' `link`,
//! `configurations`): the links into a [`Chain`] (parents before children), each cable's link, and
//! the named configurations. Errors name the JSON path; a configuration outside the joint ranges
//! is kept with a warning (a cross-section may need the limits widened, thesis Fig. 3.12).

use nalgebra::Vector3;
use std::f64::consts::PI;

use super::{needs_format, positive, vec3, Fixed, MAX_DOF, MAX_LINKS, MAX_SEGMENTS, STANDARD_GRAVITY};
use crate::error::{finite, Error, Result};
use crate::model::{Anchor, Chain, Clearance, Joint, JointCoord, JointPath, Link, LinkWrench, Robot};
use crate::query::cables::{attached_inside, cables_at_config};
use crate::scenario::json::{Ordered, RawCable, RawLink, RawScenario, RawTrajectory, RawWrench, FORMAT_3};

/// The multi-link sections (format 3): the chain and each cable's link go into `robot`; returns
/// the named configurations. A platform robot must not use them, and a multi-link robot is
/// configured by configurations only (no poses; its trajectories pass through configurations and
/// its queries join two, `queries.rs`); its `wrench` acts on one link.
pub(super) fn multi_link(raw: &RawScenario, robot: &mut Robot, clearance: &Clearance, warnings: &mut Vec<String>) -> Result<Vec<(String, Vec<f64>)>> {
    let Some(links) = &raw.robot.links else {
        if let Some(k) = raw.trajectories.iter().position(|t| t.through.is_some()) {
            return Err(Error::new(format!("trajectories[{k}].through"), "only a multi-link robot's trajectories pass through configurations; a platform robot's have translation and orientation"));
        }
        if let Some(k) = raw.trajectories.iter().position(|t| t.joints.is_some()) {
            return Err(Error::new(format!("trajectories[{k}].joints"), "only a multi-link robot's joints move between configurations; a platform robot's trajectories have translation and orientation"));
        }
        for (i, c) in raw.robot.cables.iter().enumerate() {
            for (field, given) in [("link", c.link.is_some()), ("from", c.from.is_some()), ("via", c.via.is_some())] {
                if given {
                    return Err(Error::new(format!("robot.cables[{i}].{field}"), "only the cables of a multi-link robot (robot.links) name links or run through anchors"));
                }
            }
        }
        if !raw.configurations.0.is_empty() {
            return Err(Error::new("configurations", "only multi-link robots (robot.links) have configurations; a platform robot has poses"));
        }
        if raw.robot.gravity.is_some() {
            return Err(Error::new("robot.gravity", "only a multi-link robot's gravity is given here; a platform's is `robot.dynamics.gravity`"));
        }
        if raw.robot.closure.is_some() {
            return Err(Error::new("robot.closure", "only a multi-link robot's joint-space closure is asked here; a platform's is `wrench.closure`"));
        }
        if let Some((name, _)) = raw.joint_forces.0.first() {
            return Err(Error::new(format!("joint_forces.{name}"), "only a multi-link robot's joints take forces from outside; a platform's load is `wrench`"));
        }
        if raw.wrench.as_ref().is_some_and(|w| w.link.is_some()) {
            return Err(Error::new("wrench.link", "only a multi-link robot's wrench names the link it acts on; a platform's acts on the platform"));
        }
        return Ok(Vec::new());
    };
    let version = crate::scenario::json::version(&raw.format).unwrap_or(1);
    if version < 3 {
        return Err(Error::new("robot.links", format!("multi-link robots need \"format\": \"{}\"", FORMAT_3)));
    }
    let mut chain = chain(links, version)?;
    chain.gravity = match &raw.robot.gravity {
        Some(g) => {
            needs_format(version, 4, "robot.gravity")?;
            vec3("robot.gravity", g)?
        }
        None => Vector3::from(STANDARD_GRAVITY),
    };
    for (cable, link) in robot.cables.iter_mut().zip(cable_links(&raw.robot.cables, &chain)?) {
        cable.link = link;
    }
    routes(&raw.robot.cables, robot, &chain, version)?;
    let segments = robot.segments().len();
    if segments > MAX_SEGMENTS {
        return Err(Error::new("robot.cables", format!("at most {MAX_SEGMENTS} segments (pairs of consecutive anchors) are supported, all cables together; got {segments}")));
    }
    if !raw.poses.0.is_empty() {
        return Err(Error::new(
            "poses",
            "not supported for multi-link robots yet: they are configured by named joint configurations \
             (`configurations`, paths through them in `trajectories`, queries between them in `queries`)",
        ));
    }
    chain.load = raw.wrench.as_ref().map(|w| link_wrench(w, version, &chain)).transpose()?;
    chain.joint_forces = joint_forces(&raw.joint_forces, version, &chain)?;
    if let Some(closure) = raw.robot.closure {
        needs_format(version, 6, "robot.closure")?;
        chain.closure = closure;
    }
    for (i, cable) in robot.cables.iter().enumerate() {
        for anchor in cable.anchors() {
            let Some(l) = anchor.link else { continue };
            let link = &chain.links[l];
            let zone = link.radius + clearance.cable_link;
            if zone > 0.0 && attached_inside(&anchor.point, &link.body, zone) {
                warnings.push(format!(
                    "robot.cables[{i}]: cable {} is attached within {zone} (radius + clearance) of link {}'s body; \
                     its clearance to that link is not checked",
                    i + 1,
                    link.name
                ));
            }
        }
    }
    robot.chain = Some(chain);
    let chain = robot.chain.as_ref().ok_or_else(|| Error::new("robot.links", "internal: chain missing"))?;
    configurations(&raw.configurations, robot, chain, warnings)
}

/// A multi-link robot's `wrench` (format 4): the nominal wrench alone, applied to the link
/// `link` names at `point` (in that link's frame, or along the world's axes with `point_frame`
/// "world"). Joint-space closure is always checked, and a set around the nominal wrench is not
/// supported for a chain yet.
fn link_wrench(raw: &RawWrench, version: u8, chain: &Chain) -> Result<LinkWrench> {
    needs_format(version, 4, "wrench")?;
    let Some(name) = &raw.link else {
        return Err(Error::new("wrench.link", "a multi-link robot's wrench names the link it acts on"));
    };
    let link = link_named(chain, "wrench.link", name)?;
    for (field, given) in [("wrench.ellipsoid", raw.ellipsoid.is_some()), ("wrench.radius", raw.radius.is_some())] {
        if given {
            return Err(Error::new(field, "a set of wrenches on a multi-link robot's link is not supported yet: give the nominal wrench alone"));
        }
    }
    if raw.closure.is_some() {
        return Err(Error::new("wrench.closure", "a multi-link robot's joint-space wrench closure is `robot.closure` (format 6; checked unless false)"));
    }
    let w = super::wrench::wrench(raw, version)?;
    Ok(LinkWrench { link, nominal: w.nominal, point: w.point, frame: w.frame })
}

/// A multi-link robot's `joint_forces` (format 6): the generalised force applied from outside to
/// each coordinate named, in configuration order (zero for the others; empty when none is
/// named). Only the coordinates of revolute, prismatic, universal and planar joints take one —
/// a torque about the coordinate's axis or a force along it, what its joint row of the statics
/// reads; a free, spatial or spherical joint's Euler angles have generalised forces that turn
/// with the configuration (a moment on the link is a `wrench`), and the rows of its translation
/// are along the world's axes.
fn joint_forces(raw: &Ordered<f64>, version: u8, chain: &Chain) -> Result<Vec<f64>> {
    if raw.0.is_empty() {
        return Ok(Vec::new());
    }
    needs_format(version, 6, "joint_forces")?;
    let names: Vec<&str> = chain.coords().map(|(_, _, c)| c.name.as_str()).collect();
    let mut out = vec![None; names.len()];
    for (name, value) in &raw.0 {
        let field = format!("joint_forces.{name}");
        let Some(i) = names.iter().position(|n| n == name) else {
            return Err(Error::new(field, format!("no coordinate named \"{name}\"; the robot's coordinates: {}", names.join(", "))));
        };
        let (l, _, _) = chain.coords().nth(i).ok_or_else(|| Error::new(&field, "internal: coordinate missing"))?;
        let link = &chain.links[l];
        let ball = match link.joint {
            Joint::Free => Some("free"),
            Joint::Spatial => Some("spatial"),
            Joint::Spherical => Some("spherical"),
            _ => None,
        };
        if let Some(kind) = ball {
            return Err(Error::new(
                field,
                format!(
                    "link {}'s joint is {kind}: only revolute, prismatic, universal and planar joints take forces on their coordinates \
                     (a moment or force on the link from outside is a `wrench` on link {})",
                    link.name, link.name
                ),
            ));
        }
        if out[i].is_some() {
            return Err(Error::new(field, "given twice"));
        }
        out[i] = Some(finite(&field, *value)?);
    }
    Ok(out.into_iter().map(|t| t.unwrap_or(0.0)).collect())
}

/// The links of `raw` as a chain, parents before children (file order otherwise); their masses
/// need format `version` ≥ 4.
fn chain(raw: &[RawLink], version: u8) -> Result<Chain> {
    if raw.is_empty() {
        return Err(Error::new("robot.links", "a multi-link robot needs at least one link"));
    }
    if raw.len() > MAX_LINKS {
        return Err(Error::new("robot.links", format!("at most {MAX_LINKS} links are supported, got {}", raw.len())));
    }
    let names: Vec<&str> = raw.iter().map(|l| l.name.as_str()).collect();
    for (k, name) in names.iter().enumerate() {
        if name.is_empty() {
            return Err(Error::new(format!("robot.links[{k}].name"), "a link name must not be empty"));
        }
        if names[..k].contains(name) {
            return Err(Error::new(format!("robot.links[{k}].name"), format!("duplicate link name \"{name}\"")));
        }
    }
    // parents by file index
    let mut parent: Vec<Option<usize>> = Vec::with_capacity(raw.len());
    for (k, l) in raw.iter().enumerate() {
        parent.push(match &l.parent {
            None => None,
            Some(p) => match names.iter().position(|n| n == p) {
                Some(i) if i == k => return Err(Error::new(format!("robot.links[{k}].parent"), format!("link \"{p}\" cannot be its own parent"))),
                Some(i) => Some(i),
                None => return Err(Error::new(format!("robot.links[{k}].parent"), format!("no link named \"{p}\"; known links: {}", names.join(", ")))),
            },
        });
    }
    for k in 0..raw.len() {
        let mut path = vec![k];
        let mut at = k;
        while let Some(p) = parent[at] {
            if path.contains(&p) {
                path.push(p);
                let cycle: Vec<&str> = path.iter().map(|&i| names[i]).collect();
                return Err(Error::new(format!("robot.links[{k}].parent"), format!("the links form a loop ({}); a chain's parents must lead to the base", cycle.join(" → "))));
            }
            path.push(p);
            at = p;
        }
    }
    // parents before children: repeatedly take, in file order, the links whose parent is placed
    let mut order: Vec<usize> = Vec::with_capacity(raw.len());
    while order.len() < raw.len() {
        for (k, p) in parent.iter().enumerate() {
            if !order.contains(&k) && p.is_none_or(|p| order.contains(&p)) {
                order.push(k);
            }
        }
    }
    let mut links = Vec::with_capacity(raw.len());
    let mut all_names: Vec<String> = Vec::new();
    for &k in &order {
        let l = &raw[k];
        let path = format!("robot.links[{k}]");
        let location = l.location.as_ref().map(|v| vec3(&format!("{path}.location"), v)).transpose()?.unwrap_or_else(Vector3::zeros);
        let joint = joint(&path, l)?;
        let coords = coordinates(&path, l, &joint, &mut all_names)?;
        let (body, radius) = match &l.body {
            None => ([Vector3::zeros(); 2], 0.0),
            Some(b) => {
                let r = b.radius.unwrap_or(0.0);
                if !r.is_finite() || r < 0.0 {
                    return Err(Error::new(format!("{path}.body.radius"), format!("must be a finite number ≥ 0, got {r}")));
                }
                ([vec3(&format!("{path}.body.from"), &b.from)?, vec3(&format!("{path}.body.to"), &b.to)?], r)
            }
        };
        let mass = match l.mass {
            Some(m) => {
                needs_format(version, 4, &format!("{path}.mass"))?;
                positive(&format!("{path}.mass"), m)?
            }
            None => 0.0,
        };
        let com = match &l.com {
            Some(c) if l.mass.is_none() => return Err(Error::new(format!("{path}.com"), format!("a centre of mass {:?} without a mass: give the link's `mass` too", c.0))),
            Some(c) => vec3(&format!("{path}.com"), c)?,
            None => Vector3::zeros(),
        };
        let parent = parent[k].map(|p| order.iter().position(|&o| o == p).unwrap_or(0));
        links.push(Link { name: l.name.clone(), parent, location, joint, coords, body, radius, mass, com });
    }
    let chain = Chain { links, gravity: Vector3::zeros(), load: None, joint_forces: Vec::new(), closure: true };
    if chain.dof() > MAX_DOF {
        return Err(Error::new("robot.links", format!("at most {MAX_DOF} joint coordinates are supported, got {}", chain.dof())));
    }
    Ok(chain)
}

fn joint(path: &str, l: &RawLink) -> Result<Joint> {
    let j = &l.joint;
    let field = format!("{path}.joint");
    let unit = |at: String, a: &Fixed<f64, 3>| -> Result<Vector3<f64>> {
        let a = vec3(&at, a)?;
        let n = a.norm();
        if !(n > 1e-12) || !n.is_finite() {
            return Err(Error::new(at, "has zero length: a joint axis needs a direction"));
        }
        Ok(a / n)
    };
    let axis = |needed: bool| -> Result<Option<Vector3<f64>>> {
        match (&j.axis, needed) {
            (None, true) => Err(Error::new(format!("{field}.axis"), format!("a {} joint needs an axis", j.kind))),
            (Some(_), false) => Err(Error::new(format!("{field}.axis"), format!("a {} joint has no axis", j.kind))),
            (None, false) => Ok(None),
            (Some(a), true) => unit(format!("{field}.axis"), a).map(Some),
        }
    };
    // the axes of a universal (2) or planar (3) joint, none for the others
    let axes = |count: usize| -> Result<Vec<Vector3<f64>>> {
        match (&j.axes, count) {
            (Some(_), 0) => Err(Error::new(format!("{field}.axes"), format!("a {} joint has no axes", j.kind))),
            (None, 0) => Ok(vec![]),
            (None, _) => Err(Error::new(format!("{field}.axes"), format!("a {} joint needs {count} axes", j.kind))),
            (Some(list), _) if list.len() != count => Err(Error::new(format!("{field}.axes"), format!("a {} joint needs {count} axes, got {}", j.kind, list.len()))),
            (Some(list), _) => list.iter().enumerate().map(|(k, a)| unit(format!("{field}.axes[{k}]"), a)).collect(),
        }
    };
    let apart = |a: &Vector3<f64>, b: &Vector3<f64>, what: &str| -> Result<()> {
        if a.cross(b).norm() < 1e-9 {
            return Err(Error::new(format!("{field}.axes"), format!("{what} are parallel: they must span a plane")));
        }
        Ok(())
    };
    let kind = j.kind.as_str();
    if !matches!(kind, "universal" | "planar") {
        axes(0)?;
    }
    Ok(match kind {
        "free" | "spherical" | "spatial" => {
            axis(false)?;
            match kind {
                "free" => Joint::Free,
                "spherical" => Joint::Spherical,
                _ => Joint::Spatial,
            }
        }
        "revolute" => Joint::Revolute(axis(true)?.unwrap_or_else(Vector3::x)),
        "prismatic" => Joint::Prismatic(axis(true)?.unwrap_or_else(Vector3::x)),
        "universal" => {
            axis(false)?;
            let a = axes(2)?;
            apart(&a[0], &a[1], "the two rotation axes")?;
            Joint::Universal([a[0], a[1]])
        }
        "planar" => {
            axis(false)?;
            let a = axes(3)?;
            apart(&a[0], &a[1], "the two translation axes")?;
            Joint::Planar([a[0], a[1], a[2]])
        }
        other => {
            return Err(Error::new(
                format!("{field}.type"),
                format!("unknown joint type {other:?}; expected free, spatial, spherical, universal, revolute, prismatic or planar"),
            ))
        }
    })
}

fn coordinates(path: &str, l: &RawLink, joint: &Joint, all: &mut Vec<String>) -> Result<Vec<JointCoord>> {
    let j = &l.joint;
    let field = format!("{path}.joint");
    let n = joint.dof();
    if j.coordinates.len() != n {
        return Err(Error::new(format!("{field}.coordinates"), format!("a {} joint has {n} coordinate(s), got {} name(s)", j.kind, j.coordinates.len())));
    }
    if let Some(r) = &j.range {
        if r.len() != n {
            return Err(Error::new(format!("{field}.range"), format!("give one [min, max] per coordinate: {n} coordinate(s), {} range(s)", r.len())));
        }
    }
    let mut out = Vec::with_capacity(n);
    for (k, name) in j.coordinates.iter().enumerate() {
        let at = format!("{field}.coordinates[{k}]");
        if name.is_empty() || name.chars().any(|c| c.is_whitespace() || c == ',') {
            return Err(Error::new(at, format!("{name:?} is not a usable coordinate name (non-empty, no spaces or commas)")));
        }
        if all.contains(name) {
            return Err(Error::new(at, format!("duplicate coordinate name \"{name}\"")));
        }
        all.push(name.clone());
        let range = match &j.range {
            Some(r) => {
                let rf = format!("{field}.range[{k}]");
                let [lo, hi] = r[k].0;
                let (lo, hi) = (finite(&rf, lo)?, finite(&rf, hi)?);
                if lo > hi {
                    return Err(Error::new(rf, format!("min {lo} is greater than max {hi}")));
                }
                if joint.is_angle(k) && hi - lo > 2.0 * PI + 1e-12 {
                    return Err(Error::new(rf, format!("an angle range wider than one turn (2π) is not meaningful, got [{lo}, {hi}]")));
                }
                [lo, hi]
            }
            None if joint.is_angle(k) => [-PI, PI],
            None => [f64::NEG_INFINITY, f64::INFINITY],
        };
        out.push(JointCoord { name: name.clone(), range });
    }
    Ok(out)
}

/// A link's index by name; an unknown name is an error at `field` listing the known ones.
fn link_named(chain: &Chain, field: &str, name: &str) -> Result<usize> {
    chain.links.iter().position(|l| l.name == name).ok_or_else(|| {
        let known: Vec<&str> = chain.links.iter().map(|l| l.name.as_str()).collect();
        Error::new(field, format!("no link named \"{name}\"; known links: {}", known.join(", ")))
    })
}

/// Routed cables (format 6): each cable's `from` (the link its base anchor is fixed to) and the
/// anchors it runs through (`via`), into `robot`; two consecutive anchors that are the same point
/// of the same link (or of the base) would make a segment of no length, an error.
fn routes(cables: &[RawCable], robot: &mut Robot, chain: &Chain, version: u8) -> Result<()> {
    for (i, (raw, cable)) in cables.iter().zip(robot.cables.iter_mut()).enumerate() {
        if let Some(name) = &raw.from {
            let field = format!("robot.cables[{i}].from");
            needs_format(version, 6, &field)?;
            cable.from = Some(link_named(chain, &field, name)?);
        }
        if let Some(via) = &raw.via {
            needs_format(version, 6, &format!("robot.cables[{i}].via"))?;
            cable.via = via
                .iter()
                .enumerate()
                .map(|(k, a)| {
                    let field = format!("robot.cables[{i}].via[{k}]");
                    let link = a.link.as_deref().map(|name| link_named(chain, &format!("{field}.link"), name)).transpose()?;
                    Ok(Anchor { link, point: vec3(&format!("{field}.point"), &a.point)? })
                })
                .collect::<Result<Vec<_>>>()?;
        }
        let anchors = cable.anchors();
        if anchors.iter().all(|a| a.link == anchors[0].link) {
            let name = anchors[0].link.map_or("the base".to_string(), |l| format!("link {}", chain.links[l].name));
            return Err(Error::new(format!("robot.cables[{i}]"), format!("every anchor is on {name}: the cable pulls nothing")));
        }
        if let Some(k) = anchors.windows(2).position(|w| w[0] == w[1]) {
            let at = |k: usize| if k == 0 { "base".to_string() } else if k == anchors.len() - 1 { "platform".to_string() } else { format!("via[{}]", k - 1) };
            return Err(Error::new(format!("robot.cables[{i}].{}", at(k + 1)), format!("the same point of the same link as {}: a segment of no length", at(k))));
        }
    }
    Ok(())
}

/// Each cable's link, by name (every cable of a multi-link robot names one).
fn cable_links(cables: &[RawCable], chain: &Chain) -> Result<Vec<usize>> {
    cables
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let field = format!("robot.cables[{i}].link");
            let Some(name) = &c.link else { return Err(Error::new(field, "a cable of a multi-link robot names the link it pulls")) };
            link_named(chain, &field, name)
        })
        .collect()
}

/// The named configurations: every coordinate of the robot given once, finite. One outside its
/// joint's range gets a warning.
fn configurations(raw: &Ordered<Ordered<f64>>, robot: &Robot, chain: &Chain, warnings: &mut Vec<String>) -> Result<Vec<(String, Vec<f64>)>> {
    let names: Vec<&str> = chain.coords().map(|(_, _, c)| c.name.as_str()).collect();
    let mut out: Vec<(String, Vec<f64>)> = Vec::with_capacity(raw.0.len());
    for (name, values) in &raw.0 {
        let path = format!("configurations.{name}");
        if name.is_empty() {
            return Err(Error::new("configurations", "a configuration name must not be empty"));
        }
        if out.iter().any(|(n, _)| n == name) {
            return Err(Error::new(path, format!("duplicate configuration name \"{name}\"")));
        }
        let mut q = vec![f64::NAN; names.len()];
        for (coord, v) in &values.0 {
            let field = format!("{path}.{coord}");
            let Some(i) = names.iter().position(|n| n == coord) else {
                return Err(Error::new(field, format!("no coordinate named \"{coord}\"; the robot's coordinates: {}", names.join(", "))));
            };
            if !q[i].is_nan() {
                return Err(Error::new(field, "given twice"));
            }
            q[i] = finite(&field, *v)?;
        }
        if let Some(i) = q.iter().position(|v| v.is_nan()) {
            return Err(Error::new(path, format!("coordinate {} is missing (give all of {})", names[i], names.join(", "))));
        }
        for (i, (_, _, c)) in chain.coords().enumerate() {
            if q[i] < c.range[0] || q[i] > c.range[1] {
                warnings.push(format!("{path}.{}: {} is outside the joint's range [{}, {}]", c.name, q[i], c.range[0], c.range[1]));
            }
        }
        let at = cables_at_config(robot, &q);
        for ((a, x), segment) in at.iter().zip(robot.segments()) {
            if (x - a).norm() <= 1e-12 * (1.0 + a.norm().max(x.norm())) {
                let which = if robot.cables[segment.cable].is_routed() { format!(" (its segment {})", segment.index + 1) } else { String::new() };
                return Err(Error::new(path, format!("cable {}{which} has zero length at configuration {name}", segment.cable + 1)));
            }
        }
        out.push((name.clone(), q));
    }
    Ok(out)
}

/// A multi-link robot's trajectories: each a `name` and the configurations it passes `through`
/// (at least two, by name).
pub(super) fn joint_paths(raw: &[RawTrajectory], configs: &[(String, Vec<f64>)], chain: &Chain, version: u8) -> Result<Vec<JointPath>> {
    let mut out: Vec<JointPath> = Vec::with_capacity(raw.len());
    for (k, t) in raw.iter().enumerate() {
        let path = format!("trajectories[{k}]");
        if t.translation.is_some() || t.orientation.is_some() || t.pieces.is_some() {
            return Err(Error::new(path, "a multi-link robot's trajectory is `through`: the configurations it passes, by name (no translation, orientation or pieces)"));
        }
        if t.name.is_empty() {
            return Err(Error::new(format!("{path}.name"), "a trajectory name must not be empty"));
        }
        if out.iter().any(|p| p.name == t.name) {
            return Err(Error::new(format!("{path}.name"), format!("duplicate trajectory name \"{}\"", t.name)));
        }
        let Some(names) = &t.through else { return Err(Error::new(format!("{path}.through"), "missing: give the names of at least two configurations")) };
        if names.len() < 2 {
            return Err(Error::new(format!("{path}.through"), format!("needs at least two configurations, got {}", names.len())));
        }
        let through = names
            .iter()
            .enumerate()
            .map(|(i, n)| {
                configs.iter().find(|(c, _)| c == n).map(|(_, q)| q.clone()).ok_or_else(|| {
                    let known: Vec<&str> = configs.iter().map(|(c, _)| c.as_str()).collect();
                    Error::new(format!("{path}.through[{i}]"), format!("no configuration named \"{n}\"; known configurations: {}", known.join(", ")))
                })
            })
            .collect::<Result<Vec<_>>>()?;
        let proportional = match t.joints.as_deref() {
            None | Some("tangent") => false,
            Some("proportional") => {
                needs_format(version, 6, &format!("{path}.joints"))?;
                true
            }
            Some(other) => return Err(Error::new(format!("{path}.joints"), format!("{other:?} is not \"tangent\" or \"proportional\""))),
        };
        let joint_path = JointPath { name: t.name.clone(), through, proportional };
        joint_path.check_legs(chain).map_err(|(k, why)| {
            Error::new(format!("{path}.joints"), format!("from {} to {}, every joint moving in proportion: {why}", names[k], names[k + 1]))
        })?;
        out.push(joint_path);
    }
    Ok(out)
}
