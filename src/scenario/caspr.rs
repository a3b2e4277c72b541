//! Import of CASPR robot models (the XML "bodies" and "cables" files of CASPR, the Cable-robot
//! Analysis and Simulation Platform for Research) into a `cablenav-scenario/1` scenario.
//!
//! What is read:
//!
//! * bodies: exactly one rigid link (the platform) with a `SPATIAL_EULER_XYZ` joint on the
//!   base (parent 0). Its `q_initial = "x y z a b g"` becomes the pose `initial`: position
//!   (x, y, z) plus the parent `location`, orientation R = Rx(a)·Ry(b)·Rz(g) with the angles in
//!   radians (written as `euler_xyz_deg`). Multi-link robots (arms, trees) are read by
//!   [`super::caspr_links`] into a `cablenav-scenario/3` scenario.
//! * cables: the `default_cable_set` (or the only set); every `cable_*` element with two
//!   attachments, one on link 0 (the base anchor, world frame) and one on link 1 (the platform
//!   anchor). With `attachment_reference="com"` the platform location is relative to the
//!   link's centre of mass, so `com_location` is added; with `"joint"` it is used as is.
//!   `force_min`/`force_max` become the tension bounds, `diameter` the robot's diameter (the
//!   largest, if they differ).
//!
//! * physical data: the platform link's `<physical>` `mass`, `com_location` and `inertia` become
//!   `robot.dynamics` (format 4) with CASPR's gravity, 9.81 m/s² down the base's z axis; an
//!   inertia given about the joint (`ref="joint"`) is moved to the centre of mass (parallel axes).
//!   A link without a positive mass and a positive definite inertia is imported massless, with a
//!   note.
//!
//! The scenario also gets one trajectory, `hold initial`, that stays at the initial pose, as a
//! starting point for editing. Everything else (clearances, obstacles, length bounds) is left at
//! the format's defaults. Errors name the file (`bodies` or `cables`) as the field and give the
//! XML line.

use roxmltree::{Document, Node, ParsingOptions};
use serde::Serialize;
use std::collections::BTreeMap;

use super::{Scenario, FORMAT, FORMAT_4};
use crate::error::{Error, Result};

/// An imported model: the scenario JSON and what the user should know about the conversion.
#[derive(Debug, Clone, PartialEq)]
pub struct Import {
    /// The scenario, as `cablenav-scenario/1` JSON text (pretty-printed).
    pub json: String,
    /// Notes on the conversion (values combined or left out).
    pub notes: Vec<String>,
}

/// Converts a CASPR bodies file and cables file into scenario JSON called `name`.
pub fn to_json(name: &str, bodies_xml: &str, cables_xml: &str) -> Result<Import> {
    model_to_json(name, bodies_xml, cables_xml, None)
}

/// A whole CASPR model as scenario JSON called `name`: its bodies and cables ([`to_json`]) and,
/// when given, the timed trajectories of its trajectories file
/// ([`super::caspr_trajectories`]; format 4 when there are any). The CLI's `import`, the Python
/// and npm packages and the page call this.
pub fn model_to_json(name: &str, bodies_xml: &str, cables_xml: &str, trajectories_xml: Option<&str>) -> Result<Import> {
    if super::caspr_links::is_multi_link(bodies_xml) {
        let mut out = super::caspr_links::to_json(name, bodies_xml, cables_xml)?;
        if trajectories_xml.is_some() {
            out.notes.push("the trajectories file was not read: trajectories of multi-link robots are not imported yet".to_string());
        }
        return Ok(out);
    }
    let platform = platform(bodies_xml)?;
    let cables = cables(cables_xml, &platform)?;
    let mut notes = Vec::new();
    let splines = match trajectories_xml {
        Some(xml) => super::caspr_trajectories::splines(xml, platform.origin, &mut notes)?,
        None => Vec::new(),
    };
    let Properties { diameter, tension, per_cable } = Properties::of(cables.iter().map(|c| [c.force_min, c.force_max, c.diameter]).collect(), &mut notes);

    let dynamics = platform.physical.and_then(|ph| ph.dynamics(&mut notes));
    let out = OutScenario {
        format: if dynamics.is_some() || !splines.is_empty() { FORMAT_4 } else { FORMAT },
        name,
        robot: OutRobot {
            dynamics,
            links: None,
            cables: cables
                .iter()
                .map(|c| OutCable {
                    base: c.base,
                    link: None,
                    platform: c.platform,
                    tension: per_cable.then_some(OutCableBounds { min: c.force_min, max: c.force_max }),
                })
                .collect(),
            tension,
            diameter,
        },
        poses: BTreeMap::from([(
            "initial",
            OutPose { position: platform.position, euler_xyz_deg: platform.euler_rad.map(f64::to_degrees) },
        )]),
        trajectories: std::iter::once(OutTrajectory::Hold {
            name: "hold initial",
            translation: OutLine { line: [platform.position, platform.position] },
            orientation: OutSlerp { slerp: ["initial", "initial"] },
        })
        .chain(splines.into_iter().map(OutTrajectory::Spline))
        .collect(),
    };
    let json = serde_json::to_string_pretty(&out).map_err(|e| Error::new("", format!("internal: {e}")))?;
    Ok(Import { json, notes })
}

/// The files of a CASPR model directory: its bodies and cables files, and the model's name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ModelFiles {
    /// The model's name: the files' common prefix (`CoGiRo` of `CoGiRo_bodies.xml`).
    pub name: String,
    /// `<name>_bodies.xml`.
    pub bodies: String,
    /// `<name>_cables.xml`.
    pub cables: String,
    /// `<name>_trajectories.xml`, if the directory has it.
    pub trajectories: Option<String>,
}

/// Picks a model's bodies and cables files from the names in its directory: exactly one
/// `*_bodies.xml`, and the `*_cables.xml` of the same name (and its `*_trajectories.xml`, if there). Errors (field `model`) say what is
/// missing or ambiguous.
pub fn model_files(names: &[String]) -> Result<ModelFiles> {
    let mut bodies: Vec<&String> = names.iter().filter(|n| n.ends_with("_bodies.xml")).collect();
    bodies.sort();
    let [only] = bodies.as_slice() else {
        return Err(Error::new("model", format!("needs exactly one CASPR <name>_bodies.xml, found {}: {bodies:?}", bodies.len())));
    };
    let name = only.trim_end_matches("_bodies.xml").to_string();
    let cables = format!("{name}_cables.xml");
    if !names.contains(&cables) {
        return Err(Error::new("model", format!("{only} has no {cables} beside it")));
    }
    let trajectories = Some(format!("{name}_trajectories.xml")).filter(|t| names.contains(t));
    Ok(ModelFiles { bodies: (*only).clone(), cables, trajectories, name })
}

/// Converts and validates: the scenario of [`to_json`], parsed by [`Scenario::from_json`].
pub fn import(name: &str, bodies_xml: &str, cables_xml: &str) -> Result<Scenario> {
    Scenario::from_json(&to_json(name, bodies_xml, cables_xml)?.json)
}

/// Which CASPR file an XML text is, by its root element: `"bodies"`, `"cables"`,
/// `"trajectories"`, or `None` (not XML, or another CASPR file such as operational spaces).
pub fn kind(xml: &str) -> Option<&'static str> {
    let doc = parse_xml(xml).ok()?;
    match doc.root_element().tag_name().name() {
        "bodies_system" => Some("bodies"),
        "cables" => Some("cables"),
        "trajectories" => Some("trajectories"),
        _ => None,
    }
}

/// The robot-level cable properties of an import: the diameter (the largest given), the tension
/// bounds (one number when all cables agree), or whether the bounds go on each cable.
pub(super) struct Properties {
    pub(super) diameter: Option<f64>,
    pub(super) tension: Option<OutBounds>,
    pub(super) per_cable: bool,
}

impl Properties {
    /// From each cable's `[force_min, force_max, diameter]`; a note when diameters differ.
    pub(super) fn of(each: Vec<[Option<f64>; 3]>, notes: &mut Vec<String>) -> Properties {
        let diameters: Vec<f64> = each.iter().filter_map(|c| c[2]).collect();
        let diameter = diameters.iter().copied().reduce(f64::max);
        if let Some(d) = diameter {
            if diameters.iter().any(|x| *x != d) {
                notes.push(format!("cable diameters differ; robot.diameter is the largest, {d}"));
            }
        }
        let (min, max) = (combine(each.iter().map(|c| c[0])), combine(each.iter().map(|c| c[1])));
        let per_cable = min.is_none() && each.iter().any(|c| c[0].is_some()) || max.is_none() && each.iter().any(|c| c[1].is_some());
        let tension = (!per_cable && (min.is_some() || max.is_some())).then_some(OutBounds { min, max });
        Properties { diameter, tension, per_cable }
    }
}

/// One value for all cables when they agree, one per cable when all give one, else `None`.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub(super) enum OneOrEach {
    One(f64),
    Each(Vec<f64>),
}

fn combine(values: impl Iterator<Item = Option<f64>>) -> Option<OneOrEach> {
    let all: Option<Vec<f64>> = values.collect();
    let all = all?;
    let first = *all.first()?;
    Some(if all.iter().all(|x| *x == first) { OneOrEach::One(first) } else { OneOrEach::Each(all) })
}

#[derive(Serialize)]
struct OutScenario<'a> {
    format: &'static str,
    name: &'a str,
    robot: OutRobot,
    poses: BTreeMap<&'static str, OutPose>,
    trajectories: Vec<OutTrajectory>,
}

/// The robot as written: its links (multi-link robots only), cables, tension bounds, diameter.
#[derive(Serialize)]
pub(super) struct OutRobot {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) links: Option<Vec<super::caspr_links::OutLink>>,
    pub(super) cables: Vec<OutCable>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) tension: Option<OutBounds>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) diameter: Option<f64>,
    /// The platform's mass and inertia (format 4), platform robots only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) dynamics: Option<OutDynamics>,
}

/// `robot.dynamics` as written.
#[derive(Serialize)]
pub(super) struct OutDynamics {
    mass: f64,
    com: [f64; 3],
    inertia: [[f64; 3]; 3],
    gravity: [f64; 3],
}

/// CASPR's gravity: 9.81 m/s² along −z of the base frame.
const CASPR_GRAVITY: [f64; 3] = [0.0, 0.0, -9.81];

/// A link's `<physical>` data as read: mass, centre of mass (link frame), inertia and the point it
/// is given about.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Physical {
    mass: f64,
    com: [f64; 3],
    /// Ixx, Iyy, Izz, Ixy, Ixz, Iyz as the tensor's entries.
    inertia: [f64; 6],
    /// Given about the joint (`ref="joint"`) rather than the centre of mass.
    about_joint: bool,
}

impl Physical {
    /// `robot.dynamics`, the inertia moved to the centre of mass; `None` (with a note) for data
    /// that gives no rigid body: a mass that is not positive, an inertia not positive definite.
    fn dynamics(&self, notes: &mut Vec<String>) -> Option<OutDynamics> {
        let [xx, yy, zz, xy, xz, yz] = self.inertia;
        let mut i = nalgebra::Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz);
        if self.about_joint {
            // parallel axes: I_joint = I_com + m (|c|² E − c cᵀ)
            let c = nalgebra::Vector3::from(self.com);
            i -= (nalgebra::Matrix3::identity() * c.norm_squared() - c * c.transpose()) * self.mass;
        }
        if !(self.mass > 0.0) || nalgebra::Cholesky::new(i).is_none() {
            notes.push(format!("the platform's physical data (mass {}, inertia about its centre of mass {:?}) is not a rigid body; imported massless", self.mass, i.as_slice()));
            return None;
        }
        Some(OutDynamics { mass: self.mass, com: self.com, inertia: [0, 1, 2].map(|r| [0, 1, 2].map(|c| i[(r, c)])), gravity: CASPR_GRAVITY })
    }
}

/// A link's `<physical>` element, if it has one with a `<mass>`.
fn physical(node: Node) -> Result<Option<Physical>> {
    const FILE: &str = "bodies";
    let Some(ph) = child(node, "physical") else { return Ok(None) };
    let Some([mass]) = child_numbers::<1>(FILE, ph, "mass")? else { return Ok(None) };
    let com = child_numbers::<3>(FILE, ph, "com_location")?.unwrap_or([0.0; 3]);
    let Some(inertia) = child(ph, "inertia") else {
        return Err(Error::new(FILE, format!("{}: <physical> has a <mass> but no <inertia>", line(ph))));
    };
    let about_joint = match inertia.attribute("ref").unwrap_or("com") {
        "com" => false,
        "joint" => true,
        other => return Err(Error::new(FILE, format!("{}: inertia ref {other:?} is not \"com\" or \"joint\"", line(inertia)))),
    };
    let mut entries = [0.0; 6];
    for (slot, tag) in entries.iter_mut().zip(["Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz"]) {
        *slot = child_numbers::<1>(FILE, inertia, tag)?.map_or(0.0, |[x]| x);
    }
    Ok(Some(Physical { mass, com, inertia: entries, about_joint }))
}

/// A cable as written: its base anchor, the link it pulls (multi-link robots only), its anchor
/// there, its own tension bounds.
#[derive(Serialize)]
pub(super) struct OutCable {
    pub(super) base: [f64; 3],
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) link: Option<String>,
    pub(super) platform: [f64; 3],
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) tension: Option<OutCableBounds>,
}

/// Robot-level tension bounds as written.
#[derive(Serialize)]
pub(super) struct OutBounds {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) min: Option<OneOrEach>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) max: Option<OneOrEach>,
}

/// A cable's own tension bounds as written.
#[derive(Serialize)]
pub(super) struct OutCableBounds {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) min: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) max: Option<f64>,
}

#[derive(Serialize)]
struct OutPose {
    position: [f64; 3],
    euler_xyz_deg: [f64; 3],
}

/// A trajectory as written: the initial pose held, or a spline of the trajectories file.
#[derive(Serialize)]
#[serde(untagged)]
enum OutTrajectory {
    Hold { name: &'static str, translation: OutLine, orientation: OutSlerp },
    Spline(super::caspr_trajectories::OutSpline),
}

#[derive(Serialize)]
struct OutLine {
    line: [[f64; 3]; 2],
}

#[derive(Serialize)]
struct OutSlerp {
    slerp: [&'static str; 2],
}

/// The platform link as the cables need it.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Platform {
    /// The parent location: where q's position counts from.
    origin: [f64; 3],
    /// Initial position (parent location + q_initial's x, y, z).
    position: [f64; 3],
    /// Initial XYZ Euler angles in radians.
    euler_rad: [f64; 3],
    /// The centre of mass in the link frame (for `attachment_reference="com"`).
    com: [f64; 3],
    /// Its physical data, if given.
    physical: Option<Physical>,
}

/// One cable as read.
#[derive(Debug, Clone, PartialEq)]
struct RawCable {
    base: [f64; 3],
    platform: [f64; 3],
    force_min: Option<f64>,
    force_max: Option<f64>,
    diameter: Option<f64>,
}

/// Parses XML; CASPR files start with a `<!DOCTYPE ... SYSTEM "...dtd">`, which is allowed (an
/// external DTD is never loaded).
pub(super) fn parse_xml(text: &str) -> std::result::Result<Document<'_>, roxmltree::Error> {
    Document::parse_with_options(text, ParsingOptions { allow_dtd: true, ..ParsingOptions::default() })
}

/// Parses `text` as XML for `file`, with the root element `root`.
pub(super) fn document<'a>(file: &str, text: &'a str, root: &str) -> Result<Document<'a>> {
    let doc = parse_xml(text).map_err(|e| Error::new(file, format!("not well-formed XML: {e}")))?;
    let got = doc.root_element().tag_name().name();
    if got != root {
        return Err(Error::new(
            file,
            format!("the root element is <{got}>, expected <{root}> (is this the CASPR {file} file?)"),
        ));
    }
    Ok(doc)
}

/// "line N" of a node, for messages.
pub(super) fn line(node: Node) -> String {
    format!("line {}", node.document().text_pos_at(node.range().start).row)
}

/// Element children of `node` called `tag`.
pub(super) fn children<'a, 'i>(node: Node<'a, 'i>, tag: &'a str) -> impl Iterator<Item = Node<'a, 'i>> {
    node.children().filter(move |c| c.is_element() && c.tag_name().name() == tag)
}

/// The one child `tag` of `node`, if any.
pub(super) fn child<'a, 'i>(node: Node<'a, 'i>, tag: &'a str) -> Option<Node<'a, 'i>> {
    children(node, tag).next()
}

/// `N` finite numbers separated by white space, from `text` at `node` (for messages).
pub(super) fn numbers<const N: usize>(file: &str, node: Node, what: &str, text: &str) -> Result<[f64; N]> {
    let parts: Vec<&str> = text.split_whitespace().collect();
    if parts.len() != N {
        return Err(Error::new(file, format!("{}: {what} needs {N} numbers, got {:?}", line(node), text.trim())));
    }
    let mut out = [0.0; N];
    for (slot, p) in out.iter_mut().zip(&parts) {
        *slot = p
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| Error::new(file, format!("{}: {what}: {p:?} is not a finite number", line(node))))?;
    }
    Ok(out)
}

/// The text of child `tag` of `node` as `N` numbers; `None` when there is no such child.
pub(super) fn child_numbers<const N: usize>(file: &str, node: Node, tag: &str) -> Result<Option<[f64; N]>> {
    match child(node, tag) {
        None => Ok(None),
        Some(c) => numbers(file, c, &format!("<{tag}>"), c.text().unwrap_or_default()).map(Some),
    }
}

fn platform(xml: &str) -> Result<Platform> {
    const FILE: &str = "bodies";
    let doc = document(FILE, xml, "bodies_system")?;
    let root = doc.root_element();
    let links = child(root, "links").ok_or_else(|| Error::new(FILE, "no <links> element"))?;
    let all: Vec<Node> = links.children().filter(|c| c.is_element()).collect();
    let [link] = all.as_slice() else {
        return Err(Error::new(
            FILE,
            format!(
                "{} links; only a single rigid platform (one <link_rigid> with a SPATIAL_EULER_XYZ joint on the \
                 base) can be imported — multi-link robots (arms, trees) are not supported",
                all.len()
            ),
        ));
    };
    if link.tag_name().name() != "link_rigid" {
        return Err(Error::new(FILE, format!("{}: <{}> is not supported, only <link_rigid>", line(*link), link.tag_name().name())));
    }
    let joint = child(*link, "joint").ok_or_else(|| Error::new(FILE, format!("{}: the link has no <joint>", line(*link))))?;
    let kind = joint.attribute("type").unwrap_or_default();
    if kind != "SPATIAL_EULER_XYZ" {
        return Err(Error::new(
            FILE,
            format!("{}: joint type {kind:?} is not supported; a 6-DoF platform needs SPATIAL_EULER_XYZ", line(joint)),
        ));
    }
    let q: [f64; 6] = match joint.attribute("q_initial") {
        Some(text) => numbers(FILE, joint, "q_initial", text)?,
        None => [0.0; 6],
    };
    let (parent_location, parent_num) = match child(*link, "parent") {
        None => ([0.0; 3], 0.0),
        Some(p) => (
            child_numbers::<3>(FILE, p, "location")?.unwrap_or([0.0; 3]),
            child_numbers::<1>(FILE, p, "num")?.map_or(0.0, |[n]| n),
        ),
    };
    if parent_num != 0.0 {
        return Err(Error::new(FILE, format!("{}: the platform's parent must be the base (link 0), got {parent_num}", line(*link))));
    }
    let com = match child(*link, "physical") {
        Some(ph) => child_numbers::<3>(FILE, ph, "com_location")?.unwrap_or([0.0; 3]),
        None => [0.0; 3],
    };
    Ok(Platform {
        origin: parent_location,
        position: [parent_location[0] + q[0], parent_location[1] + q[1], parent_location[2] + q[2]],
        euler_rad: [q[3], q[4], q[5]],
        com,
        physical: physical(*link)?,
    })
}

/// The cable set to import: the `default_cable_set`, or the only one.
pub(super) fn cable_set<'a, 'i>(root: Node<'a, 'i>) -> Result<Node<'a, 'i>> {
    const FILE: &str = "cables";
    let sets: Vec<Node> = children(root, "cable_set").collect();
    Ok(match root.attribute("default_cable_set") {
        Some(id) => sets.iter().find(|s| s.attribute("id") == Some(id)).copied().ok_or_else(|| {
            Error::new(FILE, format!("default_cable_set {id:?} names no <cable_set id=...> in the file"))
        })?,
        None => match sets.as_slice() {
            [only] => *only,
            _ => return Err(Error::new(FILE, format!("{} cable sets and no default_cable_set to choose one", sets.len()))),
        },
    })
}

/// A cable's `force_min`, `force_max` and `diameter` properties, where given.
pub(super) fn properties(cable: Node) -> Result<[Option<f64>; 3]> {
    let props = child(cable, "properties");
    let prop = |tag: &str| -> Result<Option<f64>> {
        match props {
            Some(p) => Ok(child_numbers::<1>("cables", p, tag)?.map(|[x]| x)),
            None => Ok(None),
        }
    };
    Ok([prop("force_min")?, prop("force_max")?, prop("diameter")?])
}

fn cables(xml: &str, platform: &Platform) -> Result<Vec<RawCable>> {
    const FILE: &str = "cables";
    let doc = document(FILE, xml, "cables")?;
    let set = cable_set(doc.root_element())?;
    let mut out = Vec::new();
    for cable in set.children().filter(|c| c.is_element() && c.tag_name().name().starts_with("cable_")) {
        let name = cable.attribute("name").map_or_else(|| format!("#{}", out.len() + 1), str::to_owned);
        let at = format!("cable {name:?} ({})", line(cable));
        let [force_min, force_max, diameter] = properties(cable)?;
        let attachments: Vec<Node> = child(cable, "attachments").map(|a| children(a, "attachment").collect()).unwrap_or_default();
        if attachments.len() != 2 {
            return Err(Error::new(
                FILE,
                format!("{at}: {} attachments; only straight cables from the base to the platform (2 attachments) are supported", attachments.len()),
            ));
        }
        let mut base = None;
        let mut on_platform = None;
        for a in &attachments {
            let [link] = child_numbers::<1>(FILE, *a, "link")?
                .ok_or_else(|| Error::new(FILE, format!("{at}: an attachment has no <link>")))?;
            let loc = child_numbers::<3>(FILE, *a, "location")?
                .ok_or_else(|| Error::new(FILE, format!("{at}: an attachment has no <location>")))?;
            match link {
                0.0 => base = Some(loc),
                1.0 => on_platform = Some(loc),
                l => return Err(Error::new(FILE, format!("{at}: attachment on link {l}; only links 0 (base) and 1 (platform) exist"))),
            }
        }
        let (Some(base), Some(local)) = (base, on_platform) else {
            return Err(Error::new(FILE, format!("{at}: needs one attachment on link 0 (base) and one on link 1 (platform)")));
        };
        let platform_anchor = match cable.attribute("attachment_reference").unwrap_or("joint") {
            "joint" => local,
            "com" => [local[0] + platform.com[0], local[1] + platform.com[1], local[2] + platform.com[2]],
            other => return Err(Error::new(FILE, format!("{at}: attachment_reference {other:?} is not \"joint\" or \"com\""))),
        };
        out.push(RawCable { base, platform: platform_anchor, force_min, force_max, diameter });
    }
    if out.is_empty() {
        return Err(Error::new(FILE, "the cable set has no cables"));
    }
    Ok(out)
}
