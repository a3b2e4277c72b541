//! Import of CASPR robot models (the XML "bodies" and "cables" files of CASPR, the Cable-robot
//! Analysis and Simulation Platform for Research) into a scenario (`cablenav-scenario/1`, or a
//! later format when the model needs it).
//!
//! What is read:
//!
//! * bodies: exactly one rigid link (the platform) with a `SPATIAL_EULER_XYZ` joint on the
//!   base (parent 0). Its `q_initial = "x y z a b g"` becomes the pose `initial`: position
//!   (x, y, z) plus the parent `location`, orientation R = Rx(a)·Ry(b)·Rz(g) with the angles in
//!   radians (written as `euler_xyz_deg`). A lone `PLANAR_XY` link (q = x y θ) is a planar robot
//!   (`cablenav-scenario/5`, `robot.mobility` "planar": position (x, y, 0) plus the location,
//!   R = Rz(θ)) when its joint, centre of mass and every anchor lie in z = 0; a lone `T_XYZ` link
//!   (q = x y z) a point mass ("point") when its cables all end at one point of it. The reduced
//!   joints `P_XY`/`P_XZ` (a point in a plane, 2 DoF) and `PLANAR_XZ`/`PLANAR_YZ` are refused
//!   naming the joint (`platform.rs`). Multi-link robots (arms, trees, a lone link on another
//!   joint) are read by `links.rs` into a `cablenav-scenario/3` scenario (`/4` when its links
//!   have masses).
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
//!   note. A point mass keeps its mass alone.
//!
//! The scenario also gets one trajectory, `hold initial`, that stays at the initial pose, as a
//! starting point for editing. Everything else (clearances, obstacles, length bounds) is left at
//! the format's defaults. Errors name the file (`bodies` or `cables`) as the field and give the
//! XML line.
//!
//! The files: this one has the entry points; `platform.rs` reads a platform robot and
//! `links.rs` a multi-link one, `trajectories.rs` a platform's trajectories file; both readers
//! use the XML toolkit of `xml.rs` (elements, numbers, the cable set, errors with the line) and
//! write the scenario with the types of `out.rs`.

mod joint;
mod joint_paths;
mod links;
mod out;
mod platform;
mod trajectories;
mod xml;

use super::Scenario;
use crate::error::{Error, Result};
use xml::parse_xml;

/// CASPR's gravity: 9.81 m/s² along −z of the base frame.
const CASPR_GRAVITY: [f64; 3] = [0.0, 0.0, -9.81];

/// An imported model: the scenario JSON and what the user should know about the conversion.
#[derive(Debug, Clone, PartialEq)]
pub struct Import {
    /// The scenario, as `cablenav-scenario/1` to `/6` JSON text (pretty-printed).
    pub json: String,
    /// Notes on the conversion (values combined or left out).
    pub notes: Vec<String>,
}

/// Converts a CASPR bodies file and cables file (its default cable set) into scenario JSON
/// called `name`.
pub fn to_json(name: &str, bodies_xml: &str, cables_xml: &str) -> Result<Import> {
    model_to_json(name, bodies_xml, cables_xml, None, None)
}

/// A whole CASPR model as scenario JSON called `name`: its bodies and the cable set `cable_set`
/// of its cables file (by id; `None`: the file's default), and, when given, the timed
/// trajectories of its trajectories file (`trajectories.rs`; format 4 when there are any). A
/// cables file with several sets adds a note naming the one imported and the others. The CLI's
/// `import`, the Python and npm packages and the page call this; an unknown set is an error at
/// `cable_set` listing the file's.
pub fn model_to_json(name: &str, bodies_xml: &str, cables_xml: &str, trajectories_xml: Option<&str>, cable_set: Option<&str>) -> Result<Import> {
    let mut out = if links::is_multi_link(bodies_xml) {
        links::to_json(name, bodies_xml, cables_xml, trajectories_xml, cable_set)?
    } else {
        platform::to_json(name, bodies_xml, cables_xml, trajectories_xml, cable_set)?
    };
    let sets = cable_sets(cables_xml)?;
    if sets.ids.len() > 1 {
        let used = cable_set.or(sets.default.as_deref()).unwrap_or_default();
        let others: Vec<&String> = sets.ids.iter().filter(|id| id.as_str() != used).collect();
        out.notes.push(format!("cable set {used:?} of {} (the others: {others:?}; choose one with --cable-set)", sets.ids.len()));
    }
    Ok(out)
}

/// The cable sets of a CASPR cables file: their ids in file order and the default one.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CableSets {
    /// Every `<cable_set id=…>`, in file order.
    pub ids: Vec<String>,
    /// The `default_cable_set`, if the file names one.
    pub default: Option<String>,
}

/// The cable sets of the cables file `cables_xml`.
pub fn cable_sets(cables_xml: &str) -> Result<CableSets> {
    let doc = xml::document("cables", cables_xml, "cables")?;
    let root = doc.root_element();
    let ids = xml::children(root, "cable_set").filter_map(|s| s.attribute("id").map(str::to_owned)).collect();
    Ok(CableSets { ids, default: root.attribute("default_cable_set").map(str::to_owned) })
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
