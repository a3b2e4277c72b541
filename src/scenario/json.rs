//! The raw scenario JSON as serde reads it, before validation.
//!
//! Every struct denies unknown fields, and a mistake is reported at its JSON path
//! (`robot.cables[2].base: expected 3 numbers, got 2`), found from the error's position
//! ([`super::json_path`]).
//! Shapes that JSON alone cannot say (which obstacle fields go with which `type`, "exactly one of"
//! choices, sizes of arrays that depend on other arrays) are checked in `validate`.
//!
//! Untagged and internally tagged serde enums are avoided on purpose: they buffer their input and
//! lose both the path and the precise message. Alternatives are read with small hand-written
//! visitors instead (a number or an array, a quaternion or a pose name).

use serde::de::{self, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use std::fmt;
use std::marker::PhantomData;

use super::json_path::{offset, path_at, Anchor};
use crate::error::{Error, Result};

/// The scenario format version 1, which every writer uses unless it needs version 2.
pub const FORMAT: &str = "cablenav-scenario/1";
/// Format version 2: version 1 plus piecewise trajectories (`trajectories[k].pieces`). A file
/// using pieces must declare it, so that a reader of version 1 refuses the file by its version
/// instead of by an unknown field.
pub const FORMAT_2: &str = "cablenav-scenario/2";
/// Format version 3: version 2 plus multi-link robots (`robot.links`, cables' `link`,
/// `configurations`, `clearance.cable_link`). A file using them must declare it.
pub const FORMAT_3: &str = "cablenav-scenario/3";
/// Format version 4: version 3 plus time and mass (`robot.dynamics`, `robot.winch`,
/// trajectories' `duration`) and the opt-in wrench closure condition (`wrench.closure`). A file
/// using them must declare it.
pub const FORMAT_4: &str = "cablenav-scenario/4";
/// Format version 5: version 4 plus point-mass and planar robots (`robot.mobility`). A file using
/// them must declare it.
pub const FORMAT_5: &str = "cablenav-scenario/5";
/// Format version 6: version 5 plus routed cables of multi-link robots (cables' `from` and
/// `via`), `robot.closure` and paths whose joints move in proportion (`trajectories[k].joints`).
/// A file using them must declare it.
pub const FORMAT_6: &str = "cablenav-scenario/6";

/// The version number of a format string this reader knows (1 to 6), or `None`.
pub fn version(format: &str) -> Option<u8> {
    [FORMAT, FORMAT_2, FORMAT_3, FORMAT_4, FORMAT_5, FORMAT_6].iter().position(|f| *f == format).map(|k| k as u8 + 1)
}

/// The whole file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawScenario {
    /// Must be [`FORMAT`] (checked before this struct is read).
    #[allow(dead_code)]
    pub format: String,
    pub name: String,
    pub robot: RawRobot,
    #[serde(default)]
    pub wrench: Option<RawWrench>,
    #[serde(default)]
    pub clearance: Option<RawClearance>,
    #[serde(default)]
    pub obstacles: Vec<RawObstacle>,
    #[serde(default)]
    pub poses: Ordered<RawPose>,
    #[serde(default)]
    pub trajectories: Vec<RawTrajectory>,
    #[serde(default)]
    pub queries: Vec<RawQuery>,
    #[serde(default)]
    pub configurations: Ordered<Ordered<f64>>,
    /// Generalised forces applied to a multi-link robot's joint coordinates from outside, by
    /// coordinate name (format 6).
    #[serde(default)]
    pub joint_forces: Ordered<f64>,
}

/// The wrench set: nominal wrench, ellipsoid (a 6×6 matrix or a radius), application point.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawWrench {
    pub nominal: Fixed<f64, 6>,
    #[serde(default)]
    pub ellipsoid: Option<Fixed<Fixed<f64, 6>, 6>>,
    #[serde(default)]
    pub radius: Option<f64>,
    #[serde(default)]
    pub point: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub point_frame: Option<String>,
    /// Also require wrench closure (format 4; the condition is not implied by the wrench set).
    #[serde(default)]
    pub closure: Option<bool>,
    /// The link of a multi-link robot the wrench acts on (format 4).
    #[serde(default)]
    pub link: Option<String>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawRobot {
    pub cables: Vec<RawCable>,
    #[serde(default)]
    pub length: Option<RawBounds>,
    #[serde(default)]
    pub tension: Option<RawBounds>,
    #[serde(default)]
    pub diameter: Option<f64>,
    #[serde(default)]
    pub links: Option<Vec<RawLink>>,
    /// The platform's mass and inertia (format 4).
    #[serde(default)]
    pub dynamics: Option<RawDynamics>,
    /// The winches' limits (format 4).
    #[serde(default)]
    pub winch: Option<RawWinch>,
    /// The largest speed of the platform's origin (format 4).
    #[serde(default)]
    pub speed: Option<f64>,
    /// How the platform moves: "spatial", "point" or "planar" (format 5).
    #[serde(default)]
    pub mobility: Option<String>,
    /// Gravity on a multi-link robot's links (format 4; a platform's is in `dynamics`).
    #[serde(default)]
    pub gravity: Option<Fixed<f64, 3>>,
    /// Whether a multi-link robot's joint-space wrench closure is a condition (format 6;
    /// default true).
    #[serde(default)]
    pub closure: Option<bool>,
}

/// The platform as a rigid body: mass, centre of mass and inertia about it (platform frame),
/// gravity (world frame).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawDynamics {
    pub mass: f64,
    #[serde(default)]
    pub com: Option<Fixed<f64, 3>>,
    /// Required but for a point mass, which has none.
    #[serde(default)]
    pub inertia: Option<Fixed<Fixed<f64, 3>, 3>>,
    #[serde(default)]
    pub gravity: Option<Fixed<f64, 3>>,
}

/// Cable speed and acceleration limits, the same for every winch.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawWinch {
    #[serde(default)]
    pub speed: Option<f64>,
    #[serde(default)]
    pub acceleration: Option<f64>,
}

/// One link of a multi-link robot.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLink {
    pub name: String,
    /// The parent link's name; absent for a link on the base.
    #[serde(default)]
    pub parent: Option<String>,
    /// The joint's position in the parent's frame (default the origin).
    #[serde(default)]
    pub location: Option<Fixed<f64, 3>>,
    pub joint: RawJoint,
    #[serde(default)]
    pub body: Option<RawBody>,
    /// The link's mass (format 4).
    #[serde(default)]
    pub mass: Option<f64>,
    /// Its centre of mass in its frame (format 4; default the joint's origin).
    #[serde(default)]
    pub com: Option<Fixed<f64, 3>>,
}

/// A joint: its type, axis (revolute and prismatic), coordinate names and ranges.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawJoint {
    #[serde(rename = "type")]
    pub kind: String,
    #[serde(default)]
    pub axis: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub axes: Option<Vec<Fixed<f64, 3>>>,
    pub coordinates: Vec<String>,
    #[serde(default)]
    pub range: Option<Vec<Fixed<f64, 2>>>,
}

/// A link's collision body: a segment in the link's frame and a radius.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBody {
    pub from: Fixed<f64, 3>,
    pub to: Fixed<f64, 3>,
    #[serde(default)]
    pub radius: Option<f64>,
}

/// Robot-level bounds: each end a number for all cables or an array with one number per cable.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBounds {
    #[serde(default)]
    pub min: Option<ScalarOrList>,
    #[serde(default)]
    pub max: Option<ScalarOrList>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCable {
    pub base: Fixed<f64, 3>,
    /// Required but for a point-mass robot, whose cables all end at the point.
    #[serde(default)]
    pub platform: Option<Fixed<f64, 3>>,
    /// The link the cable pulls (multi-link robots), by name.
    #[serde(default)]
    pub link: Option<String>,
    /// The link `base` is fixed to (multi-link robots, format 6), by name; absent: the base.
    #[serde(default)]
    pub from: Option<String>,
    /// The anchors a routed cable runs through between `base` and `platform` (format 6).
    #[serde(default)]
    pub via: Option<Vec<RawAnchor>>,
    #[serde(default)]
    pub length: Option<RawCableBounds>,
    #[serde(default)]
    pub tension: Option<RawCableBounds>,
}

/// One anchor a routed cable runs through: a point of a link (its frame), or of the base (world
/// frame) when `link` is absent.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawAnchor {
    #[serde(default)]
    pub link: Option<String>,
    pub point: Fixed<f64, 3>,
}

/// Per-cable bounds, overriding the robot-level ones end by end.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCableBounds {
    #[serde(default)]
    pub min: Option<f64>,
    #[serde(default)]
    pub max: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawClearance {
    #[serde(default)]
    pub cable_cable: Option<f64>,
    #[serde(default)]
    pub cable_obstacle: Option<f64>,
    #[serde(default)]
    pub cable_link: Option<f64>,
}

/// An obstacle with the union of all types' fields; `validate` checks that exactly the fields of
/// its `type` are present.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawObstacle {
    #[serde(default)]
    pub name: Option<String>,
    #[serde(default)]
    pub color: Option<String>,
    #[serde(rename = "type")]
    pub kind: String,
    #[serde(default)]
    pub center: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub size: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub vertices: Option<Vec<Fixed<f64, 3>>>,
    #[serde(default)]
    pub triangles: Option<Vec<Fixed<usize, 3>>>,
    #[serde(default)]
    pub radius: Option<f64>,
    #[serde(default)]
    pub matrix: Option<Fixed<Fixed<f64, 3>, 3>>,
    #[serde(default)]
    pub from: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub to: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub apex: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub axis: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub half_angle: Option<f64>,
    #[serde(default)]
    pub height: Option<f64>,
}

impl RawObstacle {
    /// The optional geometric fields that are present, by JSON name.
    pub fn present_fields(&self) -> Vec<&'static str> {
        let mut v = Vec::new();
        let mut add = |name: &'static str, present: bool| {
            if present {
                v.push(name)
            }
        };
        add("center", self.center.is_some());
        add("size", self.size.is_some());
        add("vertices", self.vertices.is_some());
        add("triangles", self.triangles.is_some());
        add("radius", self.radius.is_some());
        add("matrix", self.matrix.is_some());
        add("from", self.from.is_some());
        add("to", self.to.is_some());
        add("apex", self.apex.is_some());
        add("axis", self.axis.is_some());
        add("half_angle", self.half_angle.is_some());
        add("height", self.height.is_some());
        v
    }
}

/// A pose: a position and exactly one orientation form (checked in `validate`).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPose {
    pub position: Fixed<f64, 3>,
    #[serde(default)]
    pub quaternion: Option<Fixed<f64, 4>>,
    #[serde(default)]
    pub tilt_torsion: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub euler_xyz_deg: Option<Fixed<f64, 3>>,
}

/// A trajectory: `translation` and `orientation`, or (format 2) `pieces` instead (checked in
/// `validate`).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawTrajectory {
    pub name: String,
    #[serde(default)]
    pub translation: Option<RawTranslation>,
    #[serde(default)]
    pub orientation: Option<RawOrientation>,
    #[serde(default)]
    pub pieces: Option<Vec<RawPiece>>,
    /// A multi-link robot's path: the names of the configurations it passes through (format 3).
    #[serde(default)]
    pub through: Option<Vec<String>>,
    /// How a multi-link robot's joints move between those configurations: `"proportional"`
    /// (format 6, CASPR's joint splines' path) or `"tangent"` (the default).
    #[serde(default)]
    pub joints: Option<String>,
    /// How long the trajectory takes, in seconds (format 4).
    #[serde(default)]
    pub duration: Option<f64>,
    /// A timed spline's kind, `"quintic"` (the default) or `"cubic"` (format 4, with `knots`).
    #[serde(default)]
    pub spline: Option<String>,
    /// The timed knots a spline trajectory passes through (format 4).
    #[serde(default)]
    pub knots: Option<Vec<RawKnot>>,
}

/// A knot of a timed spline trajectory: its time, its pose (a named pose, or a position and one
/// orientation form, as in `poses`), and the origin's velocity and acceleration there (default
/// zero).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawKnot {
    pub time: f64,
    #[serde(default)]
    pub pose: Option<String>,
    #[serde(default)]
    pub position: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub quaternion: Option<Fixed<f64, 4>>,
    #[serde(default)]
    pub tilt_torsion: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub euler_xyz_deg: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub velocity: Option<Fixed<f64, 3>>,
    #[serde(default)]
    pub acceleration: Option<Fixed<f64, 3>>,
}

/// One piece of a piecewise trajectory.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPiece {
    pub translation: RawTranslation,
    /// Required but for a point-mass robot (its orientation is immaterial).
    #[serde(default)]
    pub orientation: Option<RawOrientation>,
}

/// Exactly one of the three forms (checked in `validate`).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawTranslation {
    #[serde(default)]
    pub polynomial: Option<Vec<Vec<f64>>>,
    #[serde(default)]
    pub bezier: Option<Vec<Fixed<f64, 3>>>,
    #[serde(default)]
    pub line: Option<Fixed<Fixed<f64, 3>, 2>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawOrientation {
    pub slerp: Fixed<QuatRef, 2>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawQuery {
    pub name: String,
    pub start: String,
    pub goal: String,
    #[serde(default)]
    pub fixed: Vec<String>,
    #[serde(default)]
    pub region: Option<Ordered<Fixed<f64, 2>>>,
}

/// What a fixed-size array holds, for messages such as "expected 3 numbers".
pub trait Noun {
    /// Plural noun for the elements.
    const NOUN: &'static str;
}

impl Noun for f64 {
    const NOUN: &'static str = "numbers";
}

impl Noun for usize {
    const NOUN: &'static str = "vertex indices";
}

impl Noun for Fixed<f64, 3> {
    const NOUN: &'static str = "points [x, y, z]";
}

impl Noun for Fixed<f64, 6> {
    const NOUN: &'static str = "rows of 6 numbers";
}

impl Noun for QuatRef {
    const NOUN: &'static str = "orientations (quaternion [w, x, y, z] or pose name)";
}

/// An array of exactly `N` elements; the error for another length says how many were expected
/// and how many were given.
#[derive(Debug, Clone, PartialEq)]
pub struct Fixed<T, const N: usize>(pub [T; N]);

impl<'de, T, const N: usize> Deserialize<'de> for Fixed<T, N>
where
    T: Deserialize<'de> + Noun,
{
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        struct V<T, const N: usize>(PhantomData<T>);
        impl<'de, T, const N: usize> Visitor<'de> for V<T, N>
        where
            T: Deserialize<'de> + Noun,
        {
            type Value = Fixed<T, N>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                write!(f, "an array of {N} {}", T::NOUN)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> std::result::Result<Self::Value, A::Error> {
                let mut out: Vec<T> = Vec::with_capacity(N);
                while out.len() < N {
                    match seq.next_element::<T>()? {
                        Some(x) => out.push(x),
                        None => {
                            return Err(de::Error::custom(format!("expected {N} {}, got {}", T::NOUN, out.len())));
                        }
                    }
                }
                let mut extra = 0usize;
                while seq.next_element::<IgnoredAny>()?.is_some() {
                    extra += 1;
                }
                if extra > 0 {
                    return Err(de::Error::custom(format!("expected {N} {}, got {}", T::NOUN, N + extra)));
                }
                let n = out.len();
                <[T; N]>::try_from(out)
                    .map(Fixed)
                    .map_err(|_| de::Error::custom(format!("expected {N} {}, got {n}", T::NOUN)))
            }
        }
        deserializer.deserialize_seq(V::<T, N>(PhantomData))
    }
}

/// A number (the same for every cable) or an array of numbers (one per cable).
#[derive(Debug, Clone, PartialEq)]
pub enum ScalarOrList {
    /// One value for all cables.
    Scalar(f64),
    /// One value per cable.
    List(Vec<f64>),
}

impl<'de> Deserialize<'de> for ScalarOrList {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = ScalarOrList;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number or an array of numbers (one per cable)")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> std::result::Result<Self::Value, E> {
                Ok(ScalarOrList::Scalar(v))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> std::result::Result<Self::Value, E> {
                Ok(ScalarOrList::Scalar(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> std::result::Result<Self::Value, E> {
                Ok(ScalarOrList::Scalar(v as f64))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> std::result::Result<Self::Value, A::Error> {
                let mut v = Vec::new();
                while let Some(x) = seq.next_element::<f64>()? {
                    v.push(x);
                }
                Ok(ScalarOrList::List(v))
            }
        }
        deserializer.deserialize_any(V)
    }
}

/// A slerp end: a quaternion `[w, x, y, z]` or the name of a pose whose orientation is used.
#[derive(Debug, Clone, PartialEq)]
pub enum QuatRef {
    /// An explicit quaternion (not yet normalised).
    Quat([f64; 4]),
    /// A pose name.
    Pose(String),
}

impl<'de> Deserialize<'de> for QuatRef {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = QuatRef;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a quaternion [w, x, y, z] or a pose name")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> std::result::Result<Self::Value, E> {
                Ok(QuatRef::Pose(v.to_owned()))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> std::result::Result<Self::Value, A::Error> {
                let Fixed(q) = <Fixed<f64, 4> as Deserialize>::deserialize(de::value::SeqAccessDeserializer::new(seq))?;
                Ok(QuatRef::Quat(q))
            }
        }
        deserializer.deserialize_any(V)
    }
}

/// A JSON object read as a list of (key, value) pairs in file order. Repeated keys are kept, so
/// `validate` can report them by name.
#[derive(Debug)]
pub struct Ordered<T>(pub Vec<(String, T)>);

impl<T> Default for Ordered<T> {
    fn default() -> Self {
        Ordered(Vec::new())
    }
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Ordered<T> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        struct V<T>(PhantomData<T>);
        impl<'de, T: Deserialize<'de>> Visitor<'de> for V<T> {
            type Value = Ordered<T>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("an object mapping names to values")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> std::result::Result<Self::Value, A::Error> {
                let mut v = Vec::new();
                while let Some((k, x)) = map.next_entry::<String, T>()? {
                    v.push((k, x));
                }
                Ok(Ordered(v))
            }
        }
        deserializer.deserialize_map(V(PhantomData))
    }
}

/// Only the `format` field, read first so that a file of another format version gets that
/// message instead of a list of unknown fields.
#[derive(Deserialize)]
struct FormatOnly {
    #[serde(default)]
    format: Option<serde_json::Value>,
}

/// Converts a serde error into the crate's error, naming the JSON path of what it is about
/// ([`super::json_path`]).
fn convert(text: &str, inner: serde_json::Error) -> Error {
    let message = inner.to_string();
    let bare = message.split(" at line ").next().unwrap_or_default();
    let anchor = match inner.classify() {
        serde_json::error::Category::Syntax if bare.starts_with("number out of range") => Anchor::Ends,
        serde_json::error::Category::Syntax | serde_json::error::Category::Eof => Anchor::Broken,
        // what a container's own visitor says: a missing field, a wrong length (`Fixed`)
        _ if bare.starts_with("missing field") || bare.starts_with("expected ") => Anchor::Inside,
        _ if bare.starts_with("invalid type: map") || bare.starts_with("invalid type: sequence") => Anchor::Starts,
        _ => Anchor::Ends,
    };
    let mut path = path_at(text, offset(text, inner.line(), inner.column()), anchor);
    let reason = match inner.classify() {
        // `1e999` is a syntax error to serde_json, but the JSON is well formed: say what it is.
        serde_json::error::Category::Syntax if message.starts_with("number out of range") => {
            format!("{message} (numbers must be finite double-precision values)")
        }
        serde_json::error::Category::Syntax => format!("malformed JSON: {inner}"),
        serde_json::error::Category::Eof => format!("truncated JSON: {inner}"),
        _ => message,
    };
    // serde reports a missing field at the object that lacks it; name the field itself.
    if let Some(rest) = reason.strip_prefix("missing field `") {
        if let Some(end) = rest.find('`') {
            let field = rest.get(..end).unwrap_or_default();
            path = if path.is_empty() { field.to_owned() } else { format!("{path}.{field}") };
        }
    }
    Error::new(path, reason)
}

fn read<'a, T: Deserialize<'a>>(text: &'a str) -> Result<T> {
    let mut de = serde_json::Deserializer::from_str(text);
    let value = T::deserialize(&mut de).map_err(|e| convert(text, e))?;
    de.end().map_err(|e| Error::new("", format!("malformed JSON: {e}")))?;
    Ok(value)
}

/// Reads the text: checks it is JSON of the supported format, then reads the whole scenario.
pub fn parse(text: &str) -> Result<RawScenario> {
    let head: FormatOnly = read(text)?;
    match head.format {
        None => {
            return Err(Error::new("format", format!("missing; this version reads \"{FORMAT}\" to \"{FORMAT_6}\"")));
        }
        Some(serde_json::Value::String(s)) if version(&s).is_some() => {}
        Some(other) => {
            return Err(Error::new("format", format!("unsupported format {other}; this version reads \"{FORMAT}\" to \"{FORMAT_6}\"")));
        }
    }
    read(text)
}
