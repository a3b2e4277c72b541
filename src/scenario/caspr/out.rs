//! The scenario JSON as the CASPR readers write it: the robot (links, cables, tension bounds,
//! diameter, dynamics), and the robot-level cable properties combined from each cable's.

use serde::Serialize;

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

/// The value of every cable when all give one: one number when they agree.
fn combine(values: impl Iterator<Item = Option<f64>>) -> Option<OneOrEach> {
    let all: Option<Vec<f64>> = values.collect();
    let all = all?;
    let first = *all.first()?;
    Some(if all.iter().all(|x| *x == first) { OneOrEach::One(first) } else { OneOrEach::Each(all) })
}

/// The robot as written: how its platform moves (format 5; point-mass and planar platforms
/// only), its links (multi-link robots only), cables, tension bounds, diameter.
#[derive(Serialize)]
pub(super) struct OutRobot {
    /// `"point"` or `"planar"` (format 5); absent for a spatial platform and a multi-link robot.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) mobility: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) links: Option<Vec<OutLink>>,
    pub(super) cables: Vec<OutCable>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) tension: Option<OutBounds>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) diameter: Option<f64>,
    /// The platform's mass and inertia (format 4), platform robots only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) dynamics: Option<OutDynamics>,
    /// Gravity on the links (format 4), multi-link robots with masses only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) gravity: Option<[f64; 3]>,
    /// Whether joint-space wrench closure is a condition (format 6), multi-link robots only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) closure: Option<bool>,
}

/// `robot.dynamics` as written; a point mass has neither centre of mass nor inertia.
#[derive(Serialize)]
pub(super) struct OutDynamics {
    pub(super) mass: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) com: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) inertia: Option<[[f64; 3]; 3]>,
    pub(super) gravity: [f64; 3],
}

/// A cable as written: its base anchor, the link it pulls (multi-link robots only), its anchor
/// there (none for a point mass: the cable ends at the point), its own tension bounds.
#[derive(Serialize)]
pub(super) struct OutCable {
    pub(super) base: [f64; 3],
    /// The link the base anchor is fixed to (a routed cable's, format 6).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) from: Option<String>,
    /// The anchors a routed cable runs through (format 6).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) via: Option<Vec<OutAnchor>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) link: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) platform: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) tension: Option<OutCableBounds>,
}

/// An anchor a routed cable runs through, as written: on a link (by name) or the base.
#[derive(Serialize)]
pub(super) struct OutAnchor {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) link: Option<String>,
    pub(super) point: [f64; 3],
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

/// A link as written.
#[derive(Serialize)]
pub(super) struct OutLink {
    pub(super) name: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) parent: Option<String>,
    pub(super) location: [f64; 3],
    pub(super) joint: OutJoint,
    pub(super) body: OutBody,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) mass: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) com: Option<[f64; 3]>,
}

/// A link's joint as written.
#[derive(Serialize)]
pub(super) struct OutJoint {
    #[serde(rename = "type")]
    pub(super) kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) axis: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) axes: Option<Vec<[f64; 3]>>,
    pub(super) coordinates: Vec<String>,
    pub(super) range: Vec<[f64; 2]>,
}

impl OutJoint {
    /// A joint of type `kind` with its axes: one is written as `axis`, more as `axes`.
    pub(super) fn new(kind: &'static str, axes: &[[f64; 3]], coordinates: Vec<String>, range: Vec<[f64; 2]>) -> OutJoint {
        let (axis, axes) = match axes {
            [] => (None, None),
            [one] => (Some(*one), None),
            more => (None, Some(more.to_vec())),
        };
        OutJoint { kind, axis, axes, coordinates, range }
    }
}

/// A link's body as written: the segment from its joint.
#[derive(Serialize)]
pub(super) struct OutBody {
    pub(super) from: [f64; 3],
    pub(super) to: [f64; 3],
}
