//! The reader of a platform robot: one rigid link on the base whose joint moves it freely — a
//! 6-DoF platform (`SPATIAL_EULER_XYZ`), a platform in the plane z = 0 (`PLANAR_XY`, format 5
//! `robot.mobility` "planar") or a point mass (`T_XYZ`, "point") —: the platform link with its
//! physical data, its cables, and the scenario with the pose `initial` and the trajectory `hold
//! initial` (format 1; format 4 with dynamics or the trajectories file's splines; format 5 for a
//! planar platform or a point mass). CASPR's reduced point and planar joints (`P_XY`, `P_XZ`,
//! `PLANAR_XZ`, `PLANAR_YZ`) are refused naming the joint. The module doc of [`super`] says what
//! is read.

use roxmltree::Node;
use serde::Serialize;
use std::collections::BTreeMap;

use super::out::{OutCable, OutCableBounds, OutDynamics, OutRobot, Properties};
use super::joint::place;
use super::CASPR_GRAVITY;
use super::trajectories::{splines, OutSpline};
use super::xml::{cable_set, child, child_numbers, children, document, line, numbers_n, properties};
use super::Import;
use crate::error::{Error, Result};
use crate::model::Mobility;
use crate::scenario::{FORMAT, FORMAT_4, FORMAT_5};

/// The joint types of a lone link on the base that this reader takes: imported as a platform
/// ([`mobility_of`]) or refused by name ([`reduced`]). [`super::links::is_multi_link`] leaves
/// every other lone link (revolute, prismatic, universal, spherical) to the multi-link reader.
pub(super) const LONE_LINK_JOINTS: [&str; 7] = ["SPATIAL_EULER_XYZ", "PLANAR_XY", "T_XYZ", "P_XY", "P_XZ", "PLANAR_XZ", "PLANAR_YZ"];

/// How a platform joint moves its link, as CASPR's joint classes define it: `SPATIAL_EULER_XYZ`
/// (q = x y z a b g, R = Rx(a)·Ry(b)·Rz(g)), `PLANAR_XY` (q = x y θ: the translation (x, y, 0),
/// R = Rz(θ)), `T_XYZ` (q = x y z, no rotation).
fn mobility_of(joint: &str) -> Option<Mobility> {
    match joint {
        "SPATIAL_EULER_XYZ" => Some(Mobility::Spatial),
        "PLANAR_XY" => Some(Mobility::Planar),
        "T_XYZ" => Some(Mobility::Point),
        _ => None,
    }
}

/// Why a lone link's reduced joint cannot be imported, or `None`: a point in a plane (2 DoF) is
/// not a 3-D point mass (its cables, all in that plane, would leave one free across it), and a
/// planar platform moves in z = 0 only.
fn reduced(joint: &str) -> Option<String> {
    match joint {
        "P_XY" | "P_XZ" => Some(format!(
            "a point moving in the {} plane (2 DoF) is not supported: cablenav's point masses move in 3-D (T_XYZ, \
             robot.mobility \"point\"; cables in one plane cannot hold one across it) and its planar robots are rigid \
             platforms moving in the plane z = 0 (PLANAR_XY, robot.mobility \"planar\")",
            &joint[2..]
        )),
        "PLANAR_XZ" | "PLANAR_YZ" => Some(format!(
            "a platform moving in the {} plane is not supported: cablenav's planar robots move in the plane z = 0 \
             (PLANAR_XY, robot.mobility \"planar\")",
            &joint[7..]
        )),
        _ => None,
    }
}

/// Converts a platform robot's bodies and cables files, and its trajectories file when given, into
/// scenario JSON called `name`.
pub(super) fn to_json(name: &str, bodies_xml: &str, cables_xml: &str, trajectories_xml: Option<&str>, set: Option<&str>) -> Result<Import> {
    let mut platform = platform(bodies_xml)?;
    let cables = cables(cables_xml, &platform, set)?;
    let mut notes = Vec::new();
    let point = platform.mobility == Mobility::Point;
    if point {
        // the point mass is where its cables end on the link (one point, checked by `cables`)
        let end = cables[0].platform;
        platform.origin = [0, 1, 2].map(|i| platform.origin[i] + end[i]);
        if end != [0.0; 3] {
            notes.push(format!("the cables end at {end:?} in the T_XYZ link's frame: the point mass's position is the joint's plus that"));
        }
    }
    let (position, euler_rad) = place(platform.mobility, platform.origin, &platform.q);
    let splines = match trajectories_xml {
        Some(xml) => splines(xml, platform.mobility, platform.origin, &mut notes)?,
        None => Vec::new(),
    };
    let Properties { diameter, tension, per_cable } = Properties::of(cables.iter().map(|c| [c.force_min, c.force_max, c.diameter]).collect(), &mut notes);

    let dynamics = platform.physical.and_then(|ph| ph.dynamics(platform.mobility, &mut notes));
    let format = match platform.mobility {
        Mobility::Point | Mobility::Planar => FORMAT_5,
        Mobility::Spatial if dynamics.is_some() || !splines.is_empty() => FORMAT_4,
        Mobility::Spatial => FORMAT,
    };
    let out = OutScenario {
        format,
        name,
        robot: OutRobot {
            mobility: (platform.mobility != Mobility::Spatial).then_some(platform.mobility.name()),
            dynamics,
            gravity: None,
            closure: None,
            links: None,
            cables: cables
                .iter()
                .map(|c| OutCable {
                    from: None,
                    via: None,
                    base: c.base,
                    link: None,
                    platform: (!point).then_some(c.platform),
                    tension: per_cable.then_some(OutCableBounds { min: c.force_min, max: c.force_max }),
                })
                .collect(),
            tension,
            diameter,
        },
        poses: BTreeMap::from([("initial", OutPose { position, euler_xyz_deg: euler_rad.map(|e| e.map(f64::to_degrees)) })]),
        trajectories: std::iter::once(OutTrajectory::Hold {
            name: "hold initial",
            translation: OutLine { line: [position, position] },
            orientation: (!point).then_some(OutSlerp { slerp: ["initial", "initial"] }),
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
    /// A point mass keeps its mass alone (a note says when an inertia is left out).
    fn dynamics(&self, mobility: Mobility, notes: &mut Vec<String>) -> Option<OutDynamics> {
        if mobility == Mobility::Point {
            if !(self.mass > 0.0) {
                notes.push(format!("the point mass's mass {} is not positive; imported massless", self.mass));
                return None;
            }
            if self.inertia.iter().any(|x| *x != 0.0) {
                notes.push(format!("the T_XYZ link's inertia {:?} is left out: a point mass does not turn", self.inertia));
            }
            return Some(OutDynamics { mass: self.mass, com: None, inertia: None, gravity: CASPR_GRAVITY });
        }
        let [xx, yy, zz, xy, xz, yz] = self.inertia;
        let mut i = nalgebra::Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz);
        if self.about_joint {
            // parallel axes: I_joint = I_com + m (|c|² E − c cᵀ)
            let c = nalgebra::Vector3::from(self.com);
            i -= (nalgebra::Matrix3::identity() * c.norm_squared() - c * c.transpose()) * self.mass;
        }
        if !(self.mass > 0.0) || nalgebra::Cholesky::new(i).is_none() {
            let planar = if mobility == Mobility::Planar && self.mass > 0.0 && i[(2, 2)] > 0.0 {
                " (a planar platform turns about z only, but robot.dynamics.inertia must be positive definite)"
            } else {
                ""
            };
            notes.push(format!("the platform's physical data (mass {}, inertia about its centre of mass {:?}) is not a rigid body{planar}; imported massless", self.mass, i.as_slice()));
            return None;
        }
        Some(OutDynamics { mass: self.mass, com: Some(self.com), inertia: Some([0, 1, 2].map(|r| [0, 1, 2].map(|c| i[(r, c)]))), gravity: CASPR_GRAVITY })
    }
}

/// A link's `<physical>` element, if it has one with a `<mass>`; `point`: the link is a point
/// mass, whose inertia may be left out.
fn physical(node: Node, point: bool) -> Result<Option<Physical>> {
    const FILE: &str = "bodies";
    let Some(ph) = child(node, "physical") else { return Ok(None) };
    let Some([mass]) = child_numbers::<1>(FILE, ph, "mass")? else { return Ok(None) };
    let com = child_numbers::<3>(FILE, ph, "com_location")?.unwrap_or([0.0; 3]);
    let Some(inertia) = child(ph, "inertia") else {
        if point {
            return Ok(Some(Physical { mass, com, inertia: [0.0; 6], about_joint: false }));
        }
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
    /// None for a point mass.
    #[serde(skip_serializing_if = "Option::is_none")]
    euler_xyz_deg: Option<[f64; 3]>,
}

/// A trajectory as written: the initial pose held, or a spline of the trajectories file.
#[derive(Serialize)]
#[serde(untagged)]
enum OutTrajectory {
    Hold {
        name: &'static str,
        translation: OutLine,
        /// None for a point mass.
        #[serde(skip_serializing_if = "Option::is_none")]
        orientation: Option<OutSlerp>,
    },
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
#[derive(Debug, Clone, PartialEq)]
struct Platform {
    /// How its joint moves it.
    mobility: Mobility,
    /// The parent location: where q's position counts from (for a point mass, [`to_json`] adds
    /// the point's place on the link).
    origin: [f64; 3],
    /// `q_initial`, as many coordinates as the joint has ([`coordinates`]).
    q: Vec<f64>,
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

/// The platform link: one `<link_rigid>` on the base with a `SPATIAL_EULER_XYZ`, `PLANAR_XY` (its
/// joint and centre of mass in z = 0) or `T_XYZ` joint.
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
                "{} links; only a single rigid platform (one <link_rigid> with a SPATIAL_EULER_XYZ, PLANAR_XY or T_XYZ \
                 joint on the base) can be imported — multi-link robots (arms, trees) are not supported",
                all.len()
            ),
        ));
    };
    if link.tag_name().name() != "link_rigid" {
        return Err(Error::new(FILE, format!("{}: <{}> is not supported, only <link_rigid>", line(*link), link.tag_name().name())));
    }
    let joint = child(*link, "joint").ok_or_else(|| Error::new(FILE, format!("{}: the link has no <joint>", line(*link))))?;
    let kind = joint.attribute("type").unwrap_or_default();
    if let Some(why) = reduced(kind) {
        return Err(Error::new(FILE, format!("{}: <joint type=\"{kind}\">: {why}", line(joint))));
    }
    let Some(mobility) = mobility_of(kind) else {
        return Err(Error::new(
            FILE,
            format!(
                "{}: joint type {kind:?} is not supported; a platform needs SPATIAL_EULER_XYZ (6 DoF), PLANAR_XY (planar) or \
                 T_XYZ (a point mass)",
                line(joint)
            ),
        ));
    };
    let q = match joint.attribute("q_initial") {
        Some(text) => numbers_n(FILE, joint, "q_initial", text, mobility.dof())?,
        None => vec![0.0; mobility.dof()],
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
    if mobility == Mobility::Planar {
        let off_plane = |node: Node, what: &str, z: f64| -> Result<()> {
            if z != 0.0 {
                return Err(Error::new(
                    FILE,
                    format!("{}: {what} is at z = {z}; a PLANAR_XY platform is imported as a planar robot (robot.mobility \"planar\"), which lies in the plane z = 0", line(node)),
                ));
            }
            Ok(())
        };
        off_plane(child(*link, "parent").unwrap_or(*link), "the joint (<parent> <location>)", parent_location[2])?;
        off_plane(child(*link, "physical").unwrap_or(*link), "the centre of mass (<com_location>)", com[2])?;
    }
    Ok(Platform { mobility, origin: parent_location, q, com, physical: physical(*link, mobility == Mobility::Point)? })
}

/// The cables of the cable set (`set`, else the default one), each from the base (link 0) to the
/// platform (link 1): for a planar platform both anchors in z = 0, for a point mass all ending at
/// one point of the link.
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
        match platform.mobility {
            Mobility::Planar => {
                for (what, p) in [("base", base), ("platform", platform_anchor)] {
                    if p[2] != 0.0 {
                        return Err(Error::new(
                            FILE,
                            format!("{at}: its {what} anchor {p:?} is out of the plane z = 0; a PLANAR_XY platform is imported as a planar robot (robot.mobility \"planar\"), whose anchors all lie in z = 0"),
                        ));
                    }
                }
            }
            Mobility::Point => {
                if let Some(first) = out.first().map(|c: &RawCable| c.platform).filter(|f| *f != platform_anchor) {
                    return Err(Error::new(
                        FILE,
                        format!("{at}: it ends at {platform_anchor:?} on link 1, the first cable at {first:?}; a T_XYZ link is imported as a point mass (robot.mobility \"point\"), whose cables all end at the point"),
                    ));
                }
            }
            Mobility::Spatial => {}
        }
        out.push(RawCable { base, platform: platform_anchor, force_min, force_max, diameter });
    }
    if out.is_empty() {
        return Err(Error::new(FILE, "the cable set has no cables"));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every joint a lone link is read by here is either imported or refused by name, never both;
    /// and the multi-link reader takes the others.
    #[test]
    fn lone_link_joints_are_imported_or_refused() {
        for joint in LONE_LINK_JOINTS {
            assert!(mobility_of(joint).is_some() != reduced(joint).is_some(), "{joint}");
            let bodies = format!(r#"<bodies_system><links><link_rigid num="1"><joint type="{joint}"/></link_rigid></links></bodies_system>"#);
            assert!(!super::super::links::is_multi_link(&bodies), "{joint}");
        }
        let arm = r#"<bodies_system><links><link_rigid num="1"><joint type="R_X"/></link_rigid></links></bodies_system>"#;
        assert!(super::super::links::is_multi_link(arm));
    }

}
