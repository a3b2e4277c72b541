//! Import of CASPR multi-link robots (arms, trees, necks, snakes: the whole multi-link library)
//! into a `cablenav-scenario/3` scenario (format 6 with masses, routed cables or trajectories).
//! Conventions: `../shared/notes/caspr-mcdr-conventions.md`.
//!
//! What is read:
//!
//! * bodies: every `<link_rigid num="k">` in order, with its `<parent>` (`num`, 0 = base, and the
//!   joint's `location` in the parent's frame) and joint: `S_EULER_XYZ` (spherical, coordinates
//!   alpha, beta, gamma), `SPATIAL_EULER_XYZ` (spatial: x, y, z, alpha, beta, gamma),
//!   `R_X`/`R_Y`/`R_Z`/`R_AXIS` (revolute about that axis of the joint frame, or the `axis`
//!   attribute's, coordinate theta), `P_X`/`P_Y`/`P_Z` (prismatic, coordinate d),
//!   `U_XY`/`U_XZ`/`U_YZ` (universal: about the first axis, then the second; alpha, beta or gamma
//!   by axis), `PLANAR_XY`/`PLANAR_XZ`/`PLANAR_YZ` (planar: the two translations, then the
//!   rotation about the third axis, theta); a name already taken gets the link number appended
//!   (`theta3`). `q_min`/`q_max` become the coordinates' ranges, `q_initial`
//!   the configuration `initial`. The link's body is the segment from its joint to its
//!   `end_location`, radius 0 (CASPR has no collision geometry); its `<mass>` and `com_location`
//!   become the link's `mass` and `com` (format 4, with CASPR's gravity as `robot.gravity`; a
//!   mass that is not positive is left out, with a note). The inertia is not read: statics
//!   needs none.
//! * cables: each through its attachments in order (link 0 the base, in the world frame; link k
//!   in its frame, `attachment_reference="com"` adding k's `com_location`): straight from the
//!   base to one link, or (format 6) from a link and over several: `from`, `via`, `link` and
//!   `platform` of `docs/scenario-format.md`. A cable listed from a link back to the base is read
//!   from the base.
//!
//! * trajectories (when given): [`super::joint_paths`].
//!
//! Not supported, with a message: other joint types; a cable with fewer than two attachments or
//! all of them on one link.

use roxmltree::Node;
use serde::Serialize;
use std::collections::BTreeMap;

use super::joint_paths::{joint_paths, OutJointPath};
use super::out::{OutAnchor, OutBody, OutCable, OutCableBounds, OutJoint, OutLink, OutRobot, Properties};
use super::xml::{cable_set, child, child_numbers, children, document, line, parse_xml, properties};
use super::{Import, CASPR_GRAVITY};
use crate::error::{Error, Result};
use crate::scenario::{FORMAT_3, FORMAT_6};

const BODIES: &str = "bodies";

const CABLES: &str = "cables";

/// Whether a bodies file describes a multi-link robot: more than one link, or one whose joint is
/// none of the platform joints [`super::platform::LONE_LINK_JOINTS`] (`SPATIAL_EULER_XYZ`,
/// `PLANAR_XY`, `T_XYZ`, and the reduced point and planar joints `platform.rs` refuses by name):
/// a lone revolute, prismatic, universal or spherical link is an arm of one link.
pub(super) fn is_multi_link(bodies_xml: &str) -> bool {
    let Ok(doc) = parse_xml(bodies_xml) else { return false };
    let Some(links) = child(doc.root_element(), "links") else { return false };
    let all: Vec<Node> = links.children().filter(|c| c.is_element()).collect();
    match all.as_slice() {
        [one] => child(*one, "joint").and_then(|j| j.attribute("type")).is_some_and(|t| !super::platform::LONE_LINK_JOINTS.contains(&t)),
        more => more.len() > 1,
    }
}

/// One link as read.
struct LinkIn {
    name: String,
    parent: usize,
    location: [f64; 3],
    kind: &'static str,
    axes: Vec<[f64; 3]>,
    coordinates: Vec<String>,
    range: Vec<[f64; 2]>,
    initial: Vec<f64>,
    end: [f64; 3],
    com: [f64; 3],
    /// Its `<mass>`, when given.
    mass: Option<f64>,
}

/// The links of the bodies file, in order, each with its joint, coordinates and body; what was
/// changed on the way in `notes`.
fn links(xml: &str, notes: &mut Vec<String>) -> Result<Vec<LinkIn>> {
    let doc = document(BODIES, xml, "bodies_system")?;
    let root = doc.root_element();
    let links = child(root, "links").ok_or_else(|| Error::new(BODIES, "no <links> element"))?;
    let mut out: Vec<LinkIn> = Vec::new();
    let mut taken: Vec<String> = Vec::new();
    for (k, link) in links.children().filter(|c| c.is_element()).enumerate() {
        let at = line(link);
        if link.tag_name().name() != "link_rigid" {
            return Err(Error::new(BODIES, format!("{at}: <{}> is not supported, only <link_rigid>", link.tag_name().name())));
        }
        let num = link.attribute("num").and_then(|n| n.parse::<usize>().ok()).unwrap_or(k + 1);
        if num != k + 1 {
            return Err(Error::new(BODIES, format!("{at}: links must be numbered 1, 2, … in order; found num=\"{num}\" at position {}", k + 1)));
        }
        let name = link.attribute("name").map_or_else(|| format!("link {num}"), str::to_owned);
        let joint = child(link, "joint").ok_or_else(|| Error::new(BODIES, format!("{at}: the link has no <joint>")))?;
        let jt = joint.attribute("type").unwrap_or_default();
        let (x, y, z) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
        // the joint type as written, its axis (revolute, prismatic) or axes (universal, planar),
        // and its coordinates' base names
        let (kind, axes, base_names): (&str, Vec<[f64; 3]>, &[&str]) = match jt {
            "S_EULER_XYZ" => ("spherical", vec![], &["alpha", "beta", "gamma"]),
            "SPATIAL_EULER_XYZ" => ("spatial", vec![], &["x", "y", "z", "alpha", "beta", "gamma"]),
            "R_X" => ("revolute", vec![x], &["theta"]),
            "R_Y" => ("revolute", vec![y], &["theta"]),
            "R_Z" => ("revolute", vec![z], &["theta"]),
            "R_AXIS" => ("revolute", vec![joint_axis(joint, num)?], &["theta"]),
            "P_X" => ("prismatic", vec![x], &["d"]),
            "P_Y" => ("prismatic", vec![y], &["d"]),
            "P_Z" => ("prismatic", vec![z], &["d"]),
            "U_XY" => ("universal", vec![x, y], &["alpha", "beta"]),
            "U_XZ" => ("universal", vec![x, z], &["alpha", "gamma"]),
            "U_YZ" => ("universal", vec![y, z], &["beta", "gamma"]),
            // CASPR's planar joints: the two translations, then the rotation about the third axis
            "PLANAR_XY" => ("planar", vec![x, y, z], &["x", "y", "theta"]),
            "PLANAR_XZ" => ("planar", vec![x, z, y], &["x", "z", "theta"]),
            "PLANAR_YZ" => ("planar", vec![y, z, x], &["y", "z", "theta"]),
            other => {
                return Err(Error::new(
                    BODIES,
                    format!(
                        "{}: joint type {other:?} of link {num} is not supported in a multi-link robot (S_EULER_XYZ, SPATIAL_EULER_XYZ, \
                         R_X/R_Y/R_Z/R_AXIS, P_X/P_Y/P_Z, U_XY/U_XZ/U_YZ and PLANAR_XY/PLANAR_XZ/PLANAR_YZ are)",
                        line(joint)
                    ),
                ))
            }
        };
        let n = base_names.len();
        let read = |attr: &str, default: f64| -> Result<Vec<f64>> {
            match joint.attribute(attr) {
                None => Ok(vec![default; n]),
                Some(text) => {
                    let parts: Vec<&str> = text.split_whitespace().collect();
                    if parts.len() != n {
                        return Err(Error::new(BODIES, format!("{}: {attr} of a {jt} joint needs {n} number(s), got {:?}", line(joint), text.trim())));
                    }
                    parts.iter().map(|p| p.parse::<f64>().ok().filter(|x| x.is_finite()).ok_or_else(|| Error::new(BODIES, format!("{}: {attr}: {p:?} is not a finite number", line(joint))))).collect()
                }
            }
        };
        let (mut lo, mut hi, initial) = (read("q_min", -std::f64::consts::PI)?, read("q_max", std::f64::consts::PI)?, read("q_initial", 0.0)?);
        // an angle's range wider than one turn becomes [−π, π] if it holds it, else one turn
        // about its middle: CASPR writes
        // ±π rounded (±3.1416, ±3.142), a rounding wider than a turn, said nothing of; wider
        // still (CAREX's −3.416 for −3.1416) with a note
        for (k, (l, h)) in lo.iter_mut().zip(hi.iter_mut()).enumerate() {
            let turn = base_names.get(k).is_some_and(|b| ["alpha", "beta", "gamma", "theta"].contains(b));
            let (pi, width) = (std::f64::consts::PI, *h - *l);
            if turn && width > 2.0 * pi {
                let mid = if *l <= -pi && *h >= pi { 0.0 } else { 0.5 * (*l + *h) };
                if width > 2.0 * pi + 2e-3 {
                    notes.push(format!("{}: link {num}'s {} range [{l}, {h}] is wider than one turn; imported as [{}, {}]", line(joint), base_names[k], mid - pi, mid + pi));
                }
                (*l, *h) = (mid - pi, mid + pi);
            }
        }
        let coordinates: Vec<String> = base_names
            .iter()
            .map(|b| if taken.iter().any(|t| t == b) { format!("{b}{num}") } else { (*b).to_string() })
            .collect();
        taken.extend(coordinates.iter().cloned());
        let (location, parent) = match child(link, "parent") {
            None => ([0.0; 3], 0),
            Some(p) => (child_numbers::<3>(BODIES, p, "location")?.unwrap_or([0.0; 3]), child_numbers::<1>(BODIES, p, "num")?.map_or(0.0, |[x]| x) as usize),
        };
        if parent >= num {
            return Err(Error::new(BODIES, format!("{at}: link {num}'s parent is link {parent}; a parent must come before its child (0 is the base)")));
        }
        let (end, com, mass) = match child(link, "physical") {
            Some(ph) => (
                child_numbers::<3>(BODIES, ph, "end_location")?.unwrap_or([0.0; 3]),
                child_numbers::<3>(BODIES, ph, "com_location")?.unwrap_or([0.0; 3]),
                child_numbers::<1>(BODIES, ph, "mass")?.map(|[m]| m),
            ),
            None => ([0.0; 3], [0.0; 3], None),
        };
        out.push(LinkIn { name, parent, location, kind, axes, coordinates, range: lo.into_iter().zip(hi).map(|(a, b)| [a, b]).collect(), initial, end, com, mass });
    }
    Ok(out)
}

/// The `axis` attribute of an `R_AXIS` joint (CASPR normalises it), a nonzero direction.
fn joint_axis(joint: roxmltree::Node, num: usize) -> Result<[f64; 3]> {
    let text = joint.attribute("axis").ok_or_else(|| Error::new(BODIES, format!("{}: the R_AXIS joint of link {num} has no axis", line(joint))))?;
    let parts: Vec<f64> = text.split_whitespace().filter_map(|p| p.parse::<f64>().ok().filter(|x| x.is_finite())).collect();
    match parts[..] {
        [a, b, c] if (a * a + b * b + c * c).sqrt() > 1e-12 => Ok([a, b, c]),
        _ => Err(Error::new(BODIES, format!("{}: axis of the R_AXIS joint of link {num}: {:?} is not a nonzero direction of three numbers", line(joint), text.trim()))),
    }
}

/// One cable as read: its attachments in order, each a link number (0 the base) and a point in
/// that link's frame (`attachment_reference="com"` already added), the last on a link; its
/// properties.
struct CableIn {
    attachments: Vec<(usize, [f64; 3])>,
    props: [Option<f64>; 3],
}

impl CableIn {
    /// Whether it is more than one straight segment from the base (format 6).
    fn is_routed(&self) -> bool {
        self.attachments.len() > 2 || self.attachments[0].0 != 0
    }
}

/// The cables of the cable set (`set`, else the default one): each through its attachments in
/// order, from the base or a link, over any links, to a link (a cable listed from a link to the
/// base is read backwards, the same cable).
fn cables(xml: &str, links: &[LinkIn], set: Option<&str>) -> Result<Vec<CableIn>> {
    let doc = document(CABLES, xml, "cables")?;
    let set = cable_set(doc.root_element(), set)?;
    let mut out = Vec::new();
    for cable in set.children().filter(|c| c.is_element() && c.tag_name().name().starts_with("cable_")) {
        let name = cable.attribute("name").map_or_else(|| format!("#{}", out.len() + 1), str::to_owned);
        let at = format!("cable {name:?} ({})", line(cable));
        let com = match cable.attribute("attachment_reference").unwrap_or("joint") {
            "joint" => false,
            "com" => true,
            other => return Err(Error::new(CABLES, format!("{at}: attachment_reference {other:?} is not \"joint\" or \"com\""))),
        };
        let mut attachments = Vec::new();
        for a in child(cable, "attachments").map(|a| children(a, "attachment").collect::<Vec<Node>>()).unwrap_or_default() {
            let [link] = child_numbers::<1>(CABLES, a, "link")?.ok_or_else(|| Error::new(CABLES, format!("{at}: an attachment has no <link>")))?;
            let local = child_numbers::<3>(CABLES, a, "location")?.ok_or_else(|| Error::new(CABLES, format!("{at}: an attachment has no <location>")))?;
            let k = link as usize;
            // the base has no centre of mass: its attachments are in the world frame either way
            let point = match k.checked_sub(1) {
                None => local,
                Some(i) => {
                    let Some(l) = links.get(i) else {
                        return Err(Error::new(CABLES, format!("{at}: attachment on link {k}; the bodies file has links 1 to {}", links.len())));
                    };
                    if com { [0, 1, 2].map(|j| local[j] + l.com[j]) } else { local }
                }
            };
            attachments.push((k, point));
        }
        if attachments.len() < 2 {
            return Err(Error::new(CABLES, format!("{at}: {} attachment(s); a cable needs at least two", attachments.len())));
        }
        if attachments.iter().all(|a| a.0 == attachments[0].0) {
            return Err(Error::new(CABLES, format!("{at}: every attachment is on link {}; the cable pulls nothing", attachments[0].0)));
        }
        if attachments.last().is_some_and(|a| a.0 == 0) {
            attachments.reverse();
        }
        out.push(CableIn { attachments, props: properties(cable)? });
    }
    if out.is_empty() {
        return Err(Error::new(CABLES, "the cable set has no cables"));
    }
    Ok(out)
}

/// The scenario as written.
#[derive(Serialize)]
struct Out<'a> {
    format: &'static str,
    name: &'a str,
    robot: OutRobot,
    configurations: BTreeMap<String, BTreeMap<String, f64>>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    trajectories: Vec<OutJointPath>,
}

/// Converts a CASPR multi-link bodies file and cables file (and, when given, its trajectories
/// file: [`super::joint_paths`]) into scenario JSON called `name`.
pub(super) fn to_json(name: &str, bodies_xml: &str, cables_xml: &str, trajectories_xml: Option<&str>, set: Option<&str>) -> Result<Import> {
    let mut notes = vec!["multi-link robot: clearances are left at 0 (the thesis' case study uses ε = 0.02, clearance.cable_cable and clearance.cable_link); link bodies are segments of radius 0".to_string()];
    let links = links(bodies_xml, &mut notes)?;
    let cables = cables(cables_xml, &links, set)?;
    let Properties { diameter, tension, per_cable } = Properties::of(cables.iter().map(|c| c.props).collect(), &mut notes);
    let link_name = |num: usize| links.get(num.wrapping_sub(1)).map(|l| l.name.clone());
    let initial = links.iter().flat_map(|l| l.coordinates.iter().cloned().zip(l.initial.iter().copied())).collect();
    let coordinates: Vec<String> = links.iter().flat_map(|l| l.coordinates.iter().cloned()).collect();
    let (trajectories, along) = match trajectories_xml {
        Some(xml) => joint_paths(xml, &coordinates, &mut notes)?,
        None => (Vec::new(), Vec::new()),
    };
    let mut configurations = BTreeMap::from([("initial".to_string(), initial)]);
    configurations.extend(along);
    for l in links.iter().filter(|l| l.mass.is_some_and(|m| !(m > 0.0))) {
        notes.push(format!("link {:?}'s mass {} is not positive; imported massless", l.name, l.mass.unwrap_or(0.0)));
    }
    let mass = |l: &LinkIn| l.mass.filter(|m| *m > 0.0);
    let weighed = links.iter().any(|l| mass(l).is_some());
    let routed = cables.iter().any(CableIn::is_routed);
    if weighed {
        notes.push(
            "joint-space wrench closure is left out (robot.closure false): CASPR's arms hang from their cables and hold their weight \
             (static feasibility, from the links' masses); set robot.closure true to ask for it as well"
                .to_string(),
        );
    }
    let mut out = Out {
        format: if routed || weighed || !trajectories.is_empty() { FORMAT_6 } else { FORMAT_3 },
        name,
        robot: OutRobot {
            mobility: None,
            dynamics: None,
            gravity: weighed.then_some(CASPR_GRAVITY),
            closure: weighed.then_some(false),
            links: Some(links
                .iter()
                .map(|l| OutLink {
                    name: l.name.clone(),
                    parent: link_name(l.parent),
                    location: l.location,
                    joint: OutJoint::new(l.kind, &l.axes, l.coordinates.clone(), l.range.clone()),
                    body: OutBody { from: [0.0; 3], to: l.end },
                    mass: mass(l),
                    com: mass(l).map(|_| l.com),
                })
                .collect()),
            cables: cables
                .iter()
                .map(|c| {
                    let (first, last) = (c.attachments[0], c.attachments[c.attachments.len() - 1]);
                    let inner = &c.attachments[1..c.attachments.len() - 1];
                    OutCable {
                        base: first.1,
                        from: link_name(first.0),
                        via: (!inner.is_empty()).then(|| inner.iter().map(|&(k, point)| OutAnchor { link: link_name(k), point }).collect()),
                        link: link_name(last.0),
                        platform: Some(last.1),
                        tension: per_cable.then_some(OutCableBounds { min: c.props[0], max: c.props[1] }),
                    }
                })
                .collect(),
            tension,
            diameter,
        },
        configurations,
        trajectories,
    };
    // a path with a leg of no rational form is dropped, with why
    loop {
        let json = serde_json::to_string_pretty(&out).map_err(|e| Error::new("", format!("internal: {e}")))?;
        let refused = crate::Scenario::from_json(&json).err().and_then(|e| {
            let k: usize = e.field.strip_prefix("trajectories[")?.split(']').next()?.parse().ok()?;
            Some((k, e.reason))
        });
        let Some((k, why)) = refused.filter(|(k, _)| *k < out.trajectories.len()) else {
            if !out.trajectories.is_empty() {
                let n = out.trajectories.len();
                notes.push(format!(
                    "{n} trajector{} imported as paths through {} points (configurations ID-0, ID-1, …), every joint moving in proportion as CASPR's splines do; \
                     their times are not kept (a multi-link robot's path is verified at rest)",
                    if n == 1 { "y" } else { "ies" },
                    if n == 1 { "its" } else { "their" }
                ));
            }
            return Ok(Import { json, notes });
        };
        let path = out.trajectories.remove(k);
        out.configurations.retain(|c, _| !path.through.contains(c));
        notes.push(format!("trajectory \"{}\" skipped: {why}", path.name));
    }
}
