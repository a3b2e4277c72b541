//! The reader of a platform robot (one rigid link on a `SPATIAL_EULER_XYZ` joint): the platform
//! link with its physical data, its cables, and the scenario with the pose `initial` and the
//! trajectory `hold initial` (format 1; format 4 with dynamics or the trajectories file's
//! splines). The module doc of [`super`] says what is read.

use roxmltree::Node;
use serde::Serialize;
use std::collections::BTreeMap;

use super::out::{OutCable, OutCableBounds, OutDynamics, OutRobot, Properties};
use super::trajectories::{splines, OutSpline};
use super::xml::{cable_set, child, child_numbers, children, document, line, numbers, properties};
use super::Import;
use crate::error::{Error, Result};
use crate::scenario::{FORMAT, FORMAT_4};

/// Converts a platform robot's bodies and cables files, and its trajectories file when given, into
/// scenario JSON called `name`.
pub(super) fn to_json(name: &str, bodies_xml: &str, cables_xml: &str, trajectories_xml: Option<&str>, set: Option<&str>) -> Result<Import> {
    let platform = platform(bodies_xml)?;
    let cables = cables(cables_xml, &platform, set)?;
    let mut notes = Vec::new();
    let splines = match trajectories_xml {
        Some(xml) => splines(xml, platform.origin, &mut notes)?,
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

#[derive(Serialize)]
struct OutScenario<'a> {
    format: &'static str,
    name: &'a str,
    robot: OutRobot,
    poses: BTreeMap<&'static str, OutPose>,
    trajectories: Vec<OutTrajectory>,
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
    Spline(OutSpline),
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

/// The platform link: one `<link_rigid>` with a `SPATIAL_EULER_XYZ` joint on the base.
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

/// The cables of the cable set (`set`, else the default one), each from the base (link 0) to the
/// platform (link 1).
fn cables(xml: &str, platform: &Platform, set: Option<&str>) -> Result<Vec<RawCable>> {
    const FILE: &str = "cables";
    let doc = document(FILE, xml, "cables")?;
    let set = cable_set(doc.root_element(), set)?;
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
