//! What the scenario editor does to the scenario, as plain functions over its JSON tree (no
//! Leptos here, so all of it is unit-tested natively): paths into the tree and the core's
//! error field they correspond to, reading and writing numbers, list edits that keep
//! per-cable arrays in step, templates for new items, and conversions done by the core
//! (orientation conventions, via points, pose checks).

use cablenav::model::via::{polynomial_through, via_count, via_points};
use cablenav::model::Pose;
use cablenav::report::PoseReport;
use cablenav::Scenario;
use nalgebra::Vector3;
use serde_json::{json, Map, Number, Value};

/// Componentwise mean of points (`None` for none).
fn centroid(points: &[[f64; 3]]) -> Option<[f64; 3]> {
    if points.is_empty() {
        return None;
    }
    let n = points.len() as f64;
    let mut c = [0.0; 3];
    for p in points {
        for (ci, pi) in c.iter_mut().zip(p) {
            *ci += pi / n;
        }
    }
    Some(c)
}

/// One step of a path into the JSON tree.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Seg {
    /// An object's member.
    Key(String),
    /// An array's element, or an object's n-th member (poses are an object in file order).
    Idx(usize),
}

/// A path into the scenario's JSON tree.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Default)]
pub struct Path(pub Vec<Seg>);

impl Path {
    /// The root.
    pub fn root() -> Path {
        Path(Vec::new())
    }
    /// A path of object keys, e.g. `Path::of(&["robot", "cables"])`.
    pub fn of(keys: &[&str]) -> Path {
        Path(keys.iter().map(|k| Seg::Key((*k).to_string())).collect())
    }
    /// This path, then member `key`.
    pub fn k(&self, key: &str) -> Path {
        let mut p = self.clone();
        p.0.push(Seg::Key(key.to_string()));
        p
    }
    /// This path, then element (or n-th member) `i`.
    pub fn i(&self, i: usize) -> Path {
        let mut p = self.clone();
        p.0.push(Seg::Idx(i));
        p
    }
    /// The path without its last step, and that step.
    pub fn split_last(&self) -> Option<(Path, &Seg)> {
        let (last, rest) = self.0.split_last()?;
        Some((Path(rest.to_vec()), last))
    }
}

/// The value at `path`, if there is one.
pub fn get<'a>(doc: &'a Value, path: &Path) -> Option<&'a Value> {
    let mut v = doc;
    for seg in &path.0 {
        v = match (seg, v) {
            (Seg::Key(k), Value::Object(m)) => m.get(k)?,
            (Seg::Idx(i), Value::Array(a)) => a.get(*i)?,
            (Seg::Idx(i), Value::Object(m)) => m.values().nth(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

/// The value at `path`, created as needed: missing object members are created (as objects,
/// or arrays when the next step is an index), arrays are padded with nulls. `None` when the
/// path goes through a number, string or other scalar.
pub fn get_mut<'a>(doc: &'a mut Value, path: &Path) -> Option<&'a mut Value> {
    let mut v = doc;
    for (n, seg) in path.0.iter().enumerate() {
        let next_is_index = matches!(path.0.get(n + 1), Some(Seg::Idx(_)));
        let fresh = || if next_is_index { Value::Array(Vec::new()) } else { Value::Object(Map::new()) };
        v = match (seg, v) {
            (Seg::Key(k), Value::Object(m)) => m.entry(k.clone()).or_insert_with(fresh),
            (Seg::Idx(i), Value::Array(a)) => {
                while a.len() <= *i {
                    a.push(Value::Null);
                }
                let slot = &mut a[*i];
                if slot.is_null() {
                    *slot = fresh();
                }
                slot
            }
            (Seg::Idx(i), Value::Object(m)) => m.values_mut().nth(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

/// Sets the value at `path` (creating the way to it); false if the path cannot exist.
pub fn set(doc: &mut Value, path: &Path, value: Value) -> bool {
    match get_mut(doc, path) {
        Some(slot) => {
            *slot = value;
            true
        }
        None => false,
    }
}

/// Removes the value at `path` (an object member or an array element); returns it.
pub fn remove(doc: &mut Value, path: &Path) -> Option<Value> {
    let (parent, last) = path.split_last()?;
    match (get_mut_existing(doc, &parent)?, last) {
        (Value::Object(m), Seg::Key(k)) => m.shift_remove(k),
        (Value::Object(m), Seg::Idx(i)) => {
            let key = m.keys().nth(*i)?.clone();
            m.shift_remove(&key)
        }
        (Value::Array(a), Seg::Idx(i)) if *i < a.len() => Some(a.remove(*i)),
        _ => None,
    }
}

/// The value at `path`, without creating anything.
fn get_mut_existing<'a>(doc: &'a mut Value, path: &Path) -> Option<&'a mut Value> {
    let mut v = doc;
    for seg in &path.0 {
        v = match (seg, v) {
            (Seg::Key(k), Value::Object(m)) => m.get_mut(k)?,
            (Seg::Idx(i), Value::Array(a)) => a.get_mut(*i)?,
            (Seg::Idx(i), Value::Object(m)) => m.values_mut().nth(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

/// The number of elements (array) or members (object) at `path`; 0 when absent.
pub fn len(doc: &Value, path: &Path) -> usize {
    match get(doc, path) {
        Some(Value::Array(a)) => a.len(),
        Some(Value::Object(m)) => m.len(),
        _ => 0,
    }
}

/// The core's name for `path` (its `Error::field` syntax): `robot.cables[2].base[1]`,
/// `poses.start.position[0]` (an object's n-th member by its key).
pub fn core_path(doc: &Value, path: &Path) -> String {
    let mut out = String::new();
    let mut v = Some(doc);
    for seg in &path.0 {
        match (seg, v) {
            (Seg::Idx(i), Some(Value::Object(m))) => {
                let key = m.keys().nth(*i).cloned().unwrap_or_else(|| format!("#{i}"));
                if !out.is_empty() {
                    out.push('.');
                }
                out += &key;
                v = m.get(&key);
            }
            (Seg::Idx(i), _) => {
                out += &format!("[{i}]");
                v = v.and_then(|x| x.get(*i));
            }
            (Seg::Key(k), _) => {
                if !out.is_empty() {
                    out.push('.');
                }
                out += k;
                v = v.and_then(|x| x.get(k));
            }
        }
    }
    out
}

/// Whether an error at core field `error_field` belongs to the widget at `widget`: the same
/// field, or (for a widget that shows a whole value, `inside`) any field within it.
pub fn error_belongs(error_field: &str, widget: &str, inside: bool) -> bool {
    if error_field == widget {
        return true;
    }
    inside
        && error_field
            .strip_prefix(widget)
            .is_some_and(|rest| rest.starts_with('.') || rest.starts_with('['))
}

/// A number as JSON: integers stay integers (`2`, not `2.0`), so edited files stay tidy.
pub fn number(x: f64) -> Value {
    if x.fract() == 0.0 && x.abs() < 9.0e15 {
        Value::Number(Number::from(x as i64))
    } else {
        Number::from_f64(x).map_or(Value::Null, Value::Number)
    }
}

/// A number as an editor shows it: the shortest text that reads back as the same value.
pub fn fmt_field(x: f64) -> String {
    if x == 0.0 {
        "0".to_string()
    } else {
        format!("{x}")
    }
}

/// A computed number rounded to 12 significant digits, so rounding noise (1.2000000000000002)
/// neither shows nor builds up when it is written back.
pub fn round12(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let text = format!("{x:.11e}");
    text.parse().unwrap_or(x)
}

/// Reads a number typed into a field: `Ok(None)` for an empty field, an error message for
/// anything that is not one finite number.
pub fn parse_number(text: &str) -> Result<Option<f64>, String> {
    let t = text.trim();
    if t.is_empty() {
        return Ok(None);
    }
    match t.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(Some(x)),
        Ok(_) => Err(format!("“{t}” is not a finite number")),
        Err(_) if t.contains(',') && !t.contains(' ') && t.matches(',').count() == 1 => {
            Err(format!("“{t}” is not a number (use a point for decimals: {})", t.replace(',', ".")))
        }
        Err(_) => Err(format!("“{t}” is not a number")),
    }
}

/// Reads "a number, or one number per cable": `5`, or `500, 500, 800` (commas or spaces).
pub fn parse_number_or_list(text: &str) -> Result<Option<Value>, String> {
    let parts: Vec<&str> = text.split([',', ' ', ';']).map(str::trim).filter(|s| !s.is_empty()).collect();
    match parts.as_slice() {
        [] => Ok(None),
        [one] => parse_number(one).map(|x| x.map(number)),
        many => {
            let mut xs = Vec::with_capacity(many.len());
            for p in many {
                xs.push(number(parse_number(p)?.ok_or("empty entry")?));
            }
            Ok(Some(Value::Array(xs)))
        }
    }
}

/// A number or a list of numbers as text (the inverse of [`parse_number_or_list`]).
pub fn fmt_number_or_list(v: &Value) -> String {
    match v {
        Value::Array(a) => a.iter().map(|x| x.as_f64().map_or_else(|| x.to_string(), fmt_field)).collect::<Vec<_>>().join(", "),
        Value::Number(n) => n.as_f64().map_or_else(String::new, fmt_field),
        Value::Null => String::new(),
        other => other.to_string(),
    }
}

/// Reads rows of numbers, one row a line (`x y z` or `x, y, z`), each of exactly `width`;
/// `integers` asks for whole numbers ≥ 0 (mesh vertex indices).
pub fn parse_rows(text: &str, width: usize, integers: bool) -> Result<Value, String> {
    let mut rows = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let parts: Vec<&str> = line.split([',', ' ', '\t', ';']).map(str::trim).filter(|s| !s.is_empty()).collect();
        if parts.is_empty() {
            continue;
        }
        if parts.len() != width {
            return Err(format!("line {}: expected {width} numbers, got {}", n + 1, parts.len()));
        }
        let mut row = Vec::with_capacity(width);
        for p in parts {
            let x = parse_number(p).map_err(|e| format!("line {}: {e}", n + 1))?.ok_or("empty")?;
            if integers && (x < 0.0 || x.fract() != 0.0) {
                return Err(format!("line {}: “{p}” is not a vertex index (a whole number from 0)", n + 1));
            }
            row.push(number(x));
        }
        rows.push(Value::Array(row));
    }
    Ok(Value::Array(rows))
}

/// Rows of numbers as text, one row a line (the inverse of [`parse_rows`]).
pub fn fmt_rows(v: Option<&Value>) -> String {
    let Some(Value::Array(rows)) = v else { return String::new() };
    rows.iter()
        .map(|r| match r {
            Value::Array(xs) => xs.iter().map(|x| x.as_f64().map_or_else(|| x.to_string(), fmt_field)).collect::<Vec<_>>().join(" "),
            other => other.to_string(),
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// A point `[x, y, z]` at `path`, if it is one.
pub fn point(doc: &Value, path: &Path) -> Option<[f64; 3]> {
    let a = get(doc, path)?.as_array()?;
    match a.as_slice() {
        [x, y, z] => Some([x.as_f64()?, y.as_f64()?, z.as_f64()?]),
        _ => None,
    }
}

fn points(doc: &Value, path: &Path) -> Vec<[f64; 3]> {
    (0..len(doc, path)).filter_map(|i| point(doc, &path.i(i))).collect()
}

// ---------------------------------------------------------------------------------------------
// Cables

/// The robot-level bound ends that may hold one number per cable.
const PER_CABLE: [[&str; 3]; 4] =
    [["robot", "length", "min"], ["robot", "length", "max"], ["robot", "tension", "min"], ["robot", "tension", "max"]];

/// Appends a cable: a copy of the last one with its base anchor moved 0.1 m along x (two
/// cables with the same anchors are an error), and per-cable bound lists extended with the
/// last cable's value.
pub fn add_cable(doc: &mut Value) {
    let cables = Path::of(&["robot", "cables"]);
    let n = len(doc, &cables);
    let mut cable = match n.checked_sub(1).and_then(|i| get(doc, &cables.i(i))) {
        Some(last) => last.clone(),
        None => json!({"base": [0, 0, 0], "platform": [0, 0, 0]}),
    };
    if let Some([x, y, z]) = point(&cable, &Path::of(&["base"])) {
        cable["base"] = json!([number(round12(x + 0.1)), number(y), number(z)]);
    }
    set(doc, &cables.i(n), cable);
    for end in PER_CABLE {
        if let Some(Value::Array(list)) = get_mut_existing(doc, &Path::of(&end)) {
            if let Some(last) = list.last().cloned() {
                list.push(last);
            }
        }
    }
}

/// Removes cable `i` and its entry in per-cable bound lists.
pub fn remove_cable(doc: &mut Value, i: usize) {
    remove(doc, &Path::of(&["robot", "cables"]).i(i));
    for end in PER_CABLE {
        if let Some(Value::Array(list)) = get_mut_existing(doc, &Path::of(&end)) {
            if i < list.len() {
                list.remove(i);
            }
        }
    }
}

/// The centre of the base anchors (where new obstacles and poses go), or the origin.
pub fn workspace_centre(doc: &Value) -> [f64; 3] {
    let cables = Path::of(&["robot", "cables"]);
    let bases: Vec<[f64; 3]> = (0..len(doc, &cables)).filter_map(|i| point(doc, &cables.i(i).k("base"))).collect();
    centroid(&bases).map_or([0.0; 3], |c| c.map(round12))
}

/// The box around the base anchors, each side widened by 10 % (at least 1 m): slider ranges
/// for positions.
pub fn workspace_range(doc: &Value) -> [[f64; 2]; 3] {
    let cables = Path::of(&["robot", "cables"]);
    let bases: Vec<[f64; 3]> = (0..len(doc, &cables)).filter_map(|i| point(doc, &cables.i(i).k("base"))).collect();
    let mut out = [[-1.0, 1.0]; 3];
    if bases.is_empty() {
        return out;
    }
    for (axis, range) in out.iter_mut().enumerate() {
        let lo = bases.iter().map(|b| b[axis]).fold(f64::INFINITY, f64::min);
        let hi = bases.iter().map(|b| b[axis]).fold(f64::NEG_INFINITY, f64::max);
        let pad = (0.1 * (hi - lo)).max(0.5);
        *range = [round12(lo - pad), round12(hi + pad)];
    }
    out
}

// ---------------------------------------------------------------------------------------------
// Obstacles

/// The obstacle types, as the format names them.
pub const OBSTACLE_TYPES: [&str; 6] = ["box", "sphere", "cylinder", "cone", "ellipsoid", "mesh"];

/// A new obstacle of `kind` at `c`, with the fields of its type and small sizes.
pub fn obstacle_template(kind: &str, c: [f64; 3]) -> Value {
    let at = |dx: f64, dy: f64, dz: f64| json!([number(round12(c[0] + dx)), number(round12(c[1] + dy)), number(round12(c[2] + dz))]);
    match kind {
        "box" => json!({"type": "box", "center": at(0.0, 0.0, 0.0), "size": [0.3, 0.3, 0.3]}),
        "sphere" => json!({"type": "sphere", "center": at(0.0, 0.0, 0.0), "radius": 0.2}),
        "cylinder" => json!({"type": "cylinder", "from": at(0.0, 0.0, -0.3), "to": at(0.0, 0.0, 0.3), "radius": 0.1}),
        "cone" => json!({"type": "cone", "apex": at(0.0, 0.0, 0.3), "axis": [0, 0, -1], "half_angle": 0.5, "height": 0.3}),
        "ellipsoid" => json!({"type": "ellipsoid", "center": at(0.0, 0.0, 0.0), "matrix": [[25, 0, 0], [0, 25, 0], [0, 0, 11.11]]}),
        _ => json!({"type": "mesh",
            "vertices": [at(0.0, 0.0, 0.0), at(0.3, 0.0, 0.0), at(0.0, 0.3, 0.0), at(0.0, 0.0, 0.3)],
            "triangles": [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]}),
    }
}

/// A point that locates an obstacle (its centre, apex, axis start or first vertex).
fn obstacle_anchor(o: &Value) -> Option<[f64; 3]> {
    ["center", "apex", "from"].iter().find_map(|k| point(o, &Path::of(&[k]))).or_else(|| point(o, &Path::of(&["vertices"]).i(0)))
}

/// Obstacle `i` changed to `kind`: a template of the new type at the same place, keeping the
/// name and colour.
pub fn retype_obstacle(doc: &mut Value, i: usize, kind: &str) {
    let path = Path::of(&["obstacles"]).i(i);
    let Some(old) = get(doc, &path).cloned() else { return };
    let at = obstacle_anchor(&old).unwrap_or_else(|| workspace_centre(doc));
    let mut new = obstacle_template(kind, at);
    let mut out = Map::new();
    for key in ["name", "color"] {
        if let Some(v) = old.get(key) {
            out.insert(key.to_string(), v.clone());
        }
    }
    if let Value::Object(m) = &mut new {
        out.append(m);
    }
    set(doc, &path, Value::Object(out));
}

/// A name not yet used in the list at `list` (each item's `name`) or the object's keys:
/// `stem 1`, `stem 2`, …
pub fn fresh_name(doc: &Value, list: &Path, stem: &str) -> String {
    let taken: Vec<String> = match get(doc, list) {
        Some(Value::Array(a)) => a.iter().filter_map(|o| o.get("name")?.as_str().map(str::to_string)).collect(),
        Some(Value::Object(m)) => m.keys().cloned().collect(),
        _ => Vec::new(),
    };
    (1..).map(|k| format!("{stem} {k}")).find(|n| !taken.contains(n)).unwrap_or_else(|| stem.to_string())
}

/// Appends a new obstacle of `kind` near the workspace centre, named freshly.
pub fn add_obstacle(doc: &mut Value, kind: &str) {
    let list = Path::of(&["obstacles"]);
    let mut o = obstacle_template(kind, workspace_centre(doc));
    o["name"] = Value::String(fresh_name(doc, &list, kind));
    let n = len(doc, &list);
    set(doc, &list.i(n), o);
}

// ---------------------------------------------------------------------------------------------
// Poses and orientations

/// The orientation conventions a pose may be given in, as the format names them.
pub const ORIENTATIONS: [&str; 3] = ["tilt_torsion", "euler_xyz_deg", "quaternion"];

/// Which orientation field the pose at `path` uses.
pub fn orientation_kind(doc: &Value, path: &Path) -> Option<&'static str> {
    ORIENTATIONS.into_iter().find(|k| get(doc, &path.k(k)).is_some())
}

/// The pose at `path` as the core reads it (`None` if it is not complete and valid).
pub fn pose_of(doc: &Value, path: &Path) -> Option<Pose> {
    let [x, y, z] = point(doc, &path.k("position"))?;
    let position = Vector3::new(x, y, z);
    let nums = |k: &str| -> Option<Vec<f64>> { get(doc, &path.k(k))?.as_array()?.iter().map(Value::as_f64).collect() };
    match orientation_kind(doc, path)? {
        "tilt_torsion" => {
            let a: [f64; 3] = nums("tilt_torsion")?.try_into().ok()?;
            Some(Pose::from_tilt_torsion(position, a))
        }
        "euler_xyz_deg" => {
            let a: [f64; 3] = nums("euler_xyz_deg")?.try_into().ok()?;
            Some(Pose::from_euler_xyz_deg(position, a))
        }
        _ => {
            let q: [f64; 4] = nums("quaternion")?.try_into().ok()?;
            (q.iter().any(|x| *x != 0.0)).then(|| Pose::from_quaternion(position, q))
        }
    }
}

/// Rewrites the pose at `path` in the convention `kind` (same rotation, converted by the core;
/// angles rounded to 12 digits). False if the pose cannot be read.
pub fn convert_orientation(doc: &mut Value, path: &Path, kind: &str) -> bool {
    let Some(pose) = pose_of(doc, path) else { return false };
    let values: Vec<f64> = match kind {
        "tilt_torsion" => pose.tilt_torsion().to_vec(),
        "euler_xyz_deg" => pose.euler_xyz_deg().to_vec(),
        "quaternion" => pose.quaternion().to_vec(),
        _ => return false,
    };
    for k in ORIENTATIONS {
        remove(doc, &path.k(k));
    }
    set(doc, &path.k(kind), Value::Array(values.into_iter().map(|x| number(round12(x))).collect()))
}

/// Adds a pose at the workspace centre, upright, in tilt-and-torsion; returns its name.
pub fn add_pose(doc: &mut Value) -> String {
    let poses = Path::of(&["poses"]);
    if !matches!(get(doc, &poses), Some(Value::Object(_))) {
        set(doc, &poses, Value::Object(Map::new()));
    }
    let name = fresh_name(doc, &poses, "pose");
    let c = workspace_centre(doc);
    if let Some(Value::Object(m)) = get_mut(doc, &poses) {
        m.insert(name.clone(), json!({"position": c.map(number), "tilt_torsion": [0, 0, 0]}));
    }
    name
}

/// Renames pose `i` (keeping its place) and every trajectory end and query that names it.
/// Errors (empty or taken name) are messages for the field.
pub fn rename_pose(doc: &mut Value, i: usize, new: &str) -> Result<(), String> {
    let poses = Path::of(&["poses"]);
    let Some(Value::Object(m)) = get(doc, &poses) else { return Err("no poses".into()) };
    let Some(old) = m.keys().nth(i).cloned() else { return Err("no such pose".into()) };
    if new == old {
        return Ok(());
    }
    if new.trim().is_empty() {
        return Err("a pose name must not be empty".into());
    }
    if m.contains_key(new) {
        return Err(format!("there is already a pose “{new}”"));
    }
    let renamed: Map<String, Value> =
        m.iter().map(|(k, v)| (if *k == old { new.to_string() } else { k.clone() }, v.clone())).collect();
    set(doc, &poses, Value::Object(renamed));
    let trajectories = Path::of(&["trajectories"]);
    for t in 0..len(doc, &trajectories) {
        for e in 0..2 {
            let end = trajectories.i(t).k("orientation").k("slerp").i(e);
            if get(doc, &end).and_then(Value::as_str) == Some(old.as_str()) {
                set(doc, &end, Value::String(new.to_string()));
            }
        }
    }
    let queries = Path::of(&["queries"]);
    for q in 0..len(doc, &queries) {
        for key in ["start", "goal"] {
            let f = queries.i(q).k(key);
            if get(doc, &f).and_then(Value::as_str) == Some(old.as_str()) {
                set(doc, &f, Value::String(new.to_string()));
            }
        }
    }
    Ok(())
}

/// The names of the poses, in file order.
pub fn pose_names(doc: &Value) -> Vec<String> {
    match get(doc, &Path::of(&["poses"])) {
        Some(Value::Object(m)) => m.keys().cloned().collect(),
        _ => Vec::new(),
    }
}

/// The live check of the pose being edited: every condition at it (the core's `check_pose`).
pub fn check_pose(scenario: &Scenario, name: &str) -> Option<PoseReport> {
    let pose = scenario.pose(name).ok()?;
    Some(cablenav::verify::check_pose(scenario, name, pose))
}

/// One line saying whether a checked pose is feasible, and why not.
pub fn pose_verdict(r: &PoseReport) -> String {
    let mut out = if r.feasible {
        "feasible: every condition holds".to_string()
    } else {
        format!("infeasible: {}", r.violated.join("; "))
    };
    if let Some(w) = &r.wrench {
        out += &if w.feasible {
            format!(" · wrench set feasible (margin {})", w.margin.map_or("—".into(), crate::logic::fmt_num))
        } else {
            format!(" · wrench set infeasible ({})", w.active)
        };
    }
    out
}

// ---------------------------------------------------------------------------------------------
// Trajectories

/// The translation forms, as the format names them.
pub const TRANSLATIONS: [&str; 3] = ["line", "polynomial", "bezier"];

/// Which translation form the trajectory at `path` uses.
pub fn translation_kind(doc: &Value, path: &Path) -> Option<&'static str> {
    TRANSLATIONS.into_iter().find(|k| get(doc, &path.k("translation").k(k)).is_some())
}

/// The polynomial's coefficient rows at `path` (`…translation.polynomial`).
fn coefficients(doc: &Value, path: &Path) -> Option<[Vec<f64>; 3]> {
    let rows = get(doc, path)?.as_array()?;
    let row = |i: usize| -> Option<Vec<f64>> { rows.get(i)?.as_array()?.iter().map(Value::as_f64).collect() };
    Some([row(0)?, row(1)?, row(2)?])
}

/// The via points shown for the polynomial at `path`: at least `count`, and as many as its
/// degree needs (rounded to 12 digits).
pub fn via_points_of(doc: &Value, path: &Path, count: usize) -> Option<Vec<[f64; 3]>> {
    let c = coefficients(doc, path)?;
    let n = via_count(&c).max(count);
    Some(via_points(&c, n).into_iter().map(|p| p.map(round12)).collect())
}

/// Writes the polynomial through `points` at `path` (`…translation.polynomial`); the error,
/// if any, is the core's.
pub fn set_via_points(doc: &mut Value, path: &Path, points: &[[f64; 3]]) -> Result<(), cablenav::Error> {
    let field = core_path(doc, path);
    let rows = polynomial_through(&field, points)?;
    let json_rows: Vec<Value> = rows.iter().map(|r| Value::Array(r.iter().map(|x| number(round12(*x))).collect())).collect();
    set(doc, path, Value::Array(json_rows));
    Ok(())
}

/// The start and end positions of the trajectory at `path`, whatever its form.
fn translation_ends(doc: &Value, path: &Path) -> Option<[[f64; 3]; 2]> {
    let t = path.k("translation");
    match translation_kind(doc, path)? {
        "line" => Some([point(doc, &t.k("line").i(0))?, point(doc, &t.k("line").i(1))?]),
        "bezier" => {
            let pts = points(doc, &t.k("bezier"));
            Some([*pts.first()?, *pts.last()?])
        }
        _ => {
            let c = coefficients(doc, &t.k("polynomial"))?;
            let v = via_points(&c, 2);
            Some([v[0], v[1]])
        }
    }
}

/// Changes the trajectory at `path` to translation form `kind`, keeping its start and end:
/// the line between them, as a line, a degree-1 polynomial or a 2-point Bézier curve.
pub fn retype_translation(doc: &mut Value, path: &Path, kind: &str) {
    let [a, b] = translation_ends(doc, path).unwrap_or([workspace_centre(doc); 2]);
    let p = |x: [f64; 3]| Value::Array(x.iter().map(|v| number(round12(*v))).collect());
    let value = match kind {
        "line" => json!({"line": [p(a), p(b)]}),
        "bezier" => json!({"bezier": [p(a), p(b)]}),
        _ => {
            let rows: Vec<Value> = (0..3).map(|i| json!([number(round12(a[i])), number(round12(b[i] - a[i]))])).collect();
            json!({"polynomial": rows})
        }
    };
    set(doc, &path.k("translation"), value);
}

/// The value `"quaternion"` in a slerp end's choice: an explicit quaternion instead of a pose.
pub const QUATERNION_END: &str = "(quaternion)";

/// What slerp end `e` of the trajectory at `path` is: a pose name, or [`QUATERNION_END`].
pub fn slerp_end_choice(doc: &Value, path: &Path, e: usize) -> String {
    match get(doc, &path.k("orientation").k("slerp").i(e)) {
        Some(Value::String(name)) => name.clone(),
        _ => QUATERNION_END.to_string(),
    }
}

/// Sets slerp end `e` of the trajectory at `path` to pose `choice`, or to an explicit
/// quaternion (the rotation it had, when that was a readable pose; else the identity).
pub fn set_slerp_end(doc: &mut Value, path: &Path, e: usize, choice: &str) {
    let end = path.k("orientation").k("slerp").i(e);
    let value = if choice == QUATERNION_END {
        let named = get(doc, &end).and_then(Value::as_str).map(str::to_string);
        let q = named
            .and_then(|n| pose_names(doc).iter().position(|p| *p == n))
            .and_then(|i| pose_of(doc, &Path::of(&["poses"]).i(i)))
            .map_or([1.0, 0.0, 0.0, 0.0], |p| p.quaternion());
        Value::Array(q.iter().map(|x| number(round12(*x))).collect())
    } else {
        Value::String(choice.to_string())
    };
    set(doc, &end, value);
}

/// Adds a trajectory: a line through the workspace centre, slerp between the first two poses
/// (or the first pose twice, or the identity); returns its index.
pub fn add_trajectory(doc: &mut Value) -> usize {
    let list = Path::of(&["trajectories"]);
    let c = workspace_centre(doc);
    let names = pose_names(doc);
    let ends = match names.as_slice() {
        [] => json!([[1, 0, 0, 0], [1, 0, 0, 0]]),
        [one] => json!([one, one]),
        [a, b, ..] => json!([a, b]),
    };
    let t = json!({
        "name": fresh_name(doc, &list, "trajectory"),
        "translation": {"line": [[number(round12(c[0] - 0.25)), number(c[1]), number(c[2])], [number(round12(c[0] + 0.25)), number(c[1]), number(c[2])]]},
        "orientation": {"slerp": ends}
    });
    let n = len(doc, &list);
    set(doc, &list.i(n), t);
    n
}

// ---------------------------------------------------------------------------------------------
// Wrench

/// How the wrench ellipsoid is edited: `radius` (one radius, E = I/r²), `radii` (one radius
/// per axis, E diagonal) or `matrix` (the full 6×6 E).
pub fn ellipsoid_mode(doc: &Value) -> &'static str {
    let w = Path::of(&["wrench"]);
    if get(doc, &w.k("radius")).is_some() {
        return "radius";
    }
    match ellipsoid_matrix(doc) {
        Some(e) if is_diagonal(&e) => "radii",
        _ => "matrix",
    }
}

fn ellipsoid_matrix(doc: &Value) -> Option<Vec<Vec<f64>>> {
    let rows = get(doc, &Path::of(&["wrench", "ellipsoid"]))?.as_array()?;
    rows.iter().map(|r| r.as_array()?.iter().map(Value::as_f64).collect()).collect()
}

fn is_diagonal(e: &[Vec<f64>]) -> bool {
    e.len() == 6 && e.iter().enumerate().all(|(i, r)| r.len() == 6 && r.iter().enumerate().all(|(j, x)| i == j || *x == 0.0))
}

/// The per-axis radii rᵢ = 1/√Eᵢᵢ of the ellipsoid (or of the ball), rounded to 12 digits;
/// `None` where the diagonal entry is not positive.
pub fn ellipsoid_radii(doc: &Value) -> [Option<f64>; 6] {
    let w = Path::of(&["wrench"]);
    if let Some(r) = get(doc, &w.k("radius")).and_then(Value::as_f64) {
        return [Some(r); 6];
    }
    let mut out = [None; 6];
    if let Some(e) = ellipsoid_matrix(doc) {
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = e.get(i).and_then(|r| r.get(i)).filter(|x| **x > 0.0).map(|x| round12(1.0 / x.sqrt()));
        }
    }
    out
}

/// Writes the ellipsoid as the diagonal E with Eᵢᵢ = 1/rᵢ² (replacing `radius`). A radius
/// that is not positive is written as Eᵢᵢ = 0 so that the core reports E not positive definite
/// at `wrench.ellipsoid`.
pub fn set_ellipsoid_radii(doc: &mut Value, radii: [f64; 6]) {
    let rows: Vec<Value> = (0..6)
        .map(|i| {
            Value::Array(
                (0..6)
                    .map(|j| {
                        let r = radii[i];
                        number(if i != j || r <= 0.0 { 0.0 } else { round12(1.0 / (r * r)) })
                    })
                    .collect(),
            )
        })
        .collect();
    remove(doc, &Path::of(&["wrench", "radius"]));
    set(doc, &Path::of(&["wrench", "ellipsoid"]), Value::Array(rows));
}

/// Switches the ellipsoid's editing mode, converting the current values: a ball becomes its
/// diagonal matrix; a matrix becomes one radius (the mean of the per-axis radii) only in
/// `radius` mode.
pub fn set_ellipsoid_mode(doc: &mut Value, mode: &str) {
    let radii = ellipsoid_radii(doc).map(|r| r.unwrap_or(1.0));
    match mode {
        "radius" => {
            let mean = round12(radii.iter().sum::<f64>() / 6.0);
            remove(doc, &Path::of(&["wrench", "ellipsoid"]));
            set(doc, &Path::of(&["wrench", "radius"]), number(mean));
        }
        "radii" => set_ellipsoid_radii(doc, radii),
        _ => {
            if get(doc, &Path::of(&["wrench", "ellipsoid"])).is_none() {
                set_ellipsoid_radii(doc, radii);
            }
        }
    }
}

/// A wrench section to start from: a nominal force of 1 N along −z at the platform origin, and
/// a ball of radius 0.1 around it.
pub fn wrench_template() -> Value {
    json!({"nominal": [0, 0, -1, 0, 0, 0], "radius": 0.1, "point": [0, 0, 0], "point_frame": "platform"})
}

// ---------------------------------------------------------------------------------------------
// CASPR import

/// From the files a user picked (name, text), the CASPR bodies and cables files converted by
/// the core: the model's name (the bodies file's name without `_bodies.xml`), the scenario
/// JSON and the conversion notes; or a message saying what is missing or wrong.
pub fn caspr_pair(files: Vec<(String, Result<String, String>)>) -> Result<(String, String, Vec<String>), String> {
    use cablenav::scenario::caspr;
    let mut bodies = None;
    let mut cables = None;
    for (name, text) in files {
        let text = text?;
        match caspr::kind(&text) {
            Some("bodies") => bodies = Some((name, text)),
            Some("cables") => cables = Some(text),
            _ => {}
        }
    }
    let (Some((file, bodies)), Some(cables)) = (bodies, cables) else {
        return Err("choose both CASPR files of the model together: its bodies XML (<bodies_system>) and its cables XML (<cables>)".into());
    };
    let name = file.trim_end_matches(".xml").trim_end_matches("_bodies").to_string();
    let out = caspr::to_json(&name, &bodies, &cables).map_err(|e| format!("CASPR import: {e}"))?;
    Ok((name, out.json, out.notes))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn doc() -> Value {
        serde_json::from_str(crate::presets::PRESETS[crate::presets::find("cdpr7-box").unwrap()].json).unwrap()
    }

    #[test]
    fn paths_read_write_and_name_core_fields() {
        let mut d = doc();
        let p = Path::of(&["robot", "cables"]).i(2).k("base").i(1);
        assert_eq!(get(&d, &p).and_then(Value::as_f64), Some(2.0));
        assert_eq!(core_path(&d, &p), "robot.cables[2].base[1]");
        assert!(set(&mut d, &p, number(2.5)));
        assert_eq!(d["robot"]["cables"][2]["base"][1], json!(2.5));
        // poses are an object: index 1 is "end", by name in the core's path
        let q = Path::of(&["poses"]).i(1).k("position").i(0);
        assert_eq!(core_path(&d, &q), "poses.end.position[0]");
        assert_eq!(get(&d, &q).and_then(Value::as_f64), Some(1.5));
        // created on the way
        assert!(set(&mut d, &Path::of(&["wrench", "point"]).i(2), number(1.0)));
        assert_eq!(d["wrench"]["point"], json!([null, null, 1]));
        // cannot go through a number
        assert!(!set(&mut d, &Path::of(&["name", "x"]), number(1.0)));
        assert!(remove(&mut d, &Path::of(&["wrench"])).is_some());
        assert!(d.get("wrench").is_none());
    }

    #[test]
    fn key_order_survives_edits() {
        let mut d = doc();
        set(&mut d, &Path::of(&["poses"]).i(0).k("position").i(0), number(3.0));
        assert_eq!(pose_names(&d), ["start", "end", "fig310", "box-left", "box-right"]);
        let text = serde_json::to_string(&d).unwrap();
        assert!(text.starts_with("{\"format\""), "{text}");
    }

    #[test]
    fn errors_belong_to_their_widget() {
        assert!(error_belongs("robot.cables[2].base[1]", "robot.cables[2].base[1]", false));
        assert!(error_belongs("robot.cables[2].base[1]", "robot.cables[2].base", true));
        assert!(!error_belongs("robot.cables[2].base[1]", "robot.cables[2].base", false));
        assert!(!error_belongs("robot.cables[21]", "robot.cables[2]", true));
        assert!(!error_belongs("wrench.ellipsoid_x", "wrench.ellipsoid", true));
        assert!(error_belongs("wrench.ellipsoid[1][2]", "wrench.ellipsoid", true));
    }

    #[test]
    fn numbers_parse_and_format() {
        assert_eq!(parse_number(" 2.5 "), Ok(Some(2.5)));
        assert_eq!(parse_number(""), Ok(None));
        assert!(parse_number("1,5").unwrap_err().contains("1.5"));
        assert!(parse_number("abc").is_err());
        assert!(parse_number("1e999").is_err());
        assert!(parse_number("NaN").is_err());
        assert_eq!(number(2.0), json!(2));
        assert_eq!(number(-0.25), json!(-0.25));
        assert_eq!(fmt_field(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(fmt_field(round12(0.1 + 0.2)), "0.3");
        assert_eq!(fmt_field(-0.0), "0");
        assert_eq!(parse_number_or_list("500, 500 800"), Ok(Some(json!([500, 500, 800]))));
        assert_eq!(parse_number_or_list("7"), Ok(Some(json!(7))));
        assert_eq!(parse_number_or_list(" "), Ok(None));
        assert!(parse_number_or_list("1, x").is_err());
        assert_eq!(fmt_number_or_list(&json!([1, 2.5])), "1, 2.5");
        let rows = parse_rows("0 0 0\n1, 0, 0\n\n0 1 0", 3, false).unwrap();
        assert_eq!(rows, json!([[0, 0, 0], [1, 0, 0], [0, 1, 0]]));
        assert_eq!(fmt_rows(Some(&rows)), "0 0 0\n1 0 0\n0 1 0");
        assert!(parse_rows("0 1", 3, false).unwrap_err().starts_with("line 1"));
        assert!(parse_rows("0 1 2.5", 3, true).is_err());
    }

    #[test]
    fn cables_add_and_remove_with_their_list_bounds() {
        let mut d = doc();
        d["robot"]["tension"] = json!({"min": 1, "max": [1, 2, 3, 4, 5, 6, 7]});
        add_cable(&mut d);
        assert_eq!(len(&d, &Path::of(&["robot", "cables"])), 8);
        assert_eq!(d["robot"]["cables"][7]["base"], json!([4.1, 0, 4]));
        assert_eq!(d["robot"]["tension"]["max"], json!([1, 2, 3, 4, 5, 6, 7, 7]));
        let s = Scenario::from_json(&d.to_string()).expect("still valid");
        assert_eq!(s.robot.cables.len(), 8);
        remove_cable(&mut d, 0);
        assert_eq!(d["robot"]["tension"]["max"], json!([2, 3, 4, 5, 6, 7, 7]));
        assert_eq!(d["robot"]["cables"][0]["base"], json!([0, 3, 0]));
        assert_eq!(d["robot"]["tension"]["min"], json!(1));
    }

    #[test]
    fn every_obstacle_type_templates_valid_and_retypes_keep_name_and_colour() {
        let mut d = doc();
        for kind in OBSTACLE_TYPES {
            add_obstacle(&mut d, kind);
        }
        let s = Scenario::from_json(&d.to_string()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(s.obstacles.len(), 7);
        assert_eq!(s.obstacles[1].name, "box 1");
        assert_eq!(s.obstacles[2].name, "sphere 1");
        d["obstacles"][0]["color"] = json!("#112233");
        retype_obstacle(&mut d, 0, "sphere");
        assert_eq!(d["obstacles"][0], json!({"name": "box", "color": "#112233", "type": "sphere", "center": [3, 2, 0.15], "radius": 0.2}));
        Scenario::from_json(&d.to_string()).unwrap();
    }

    #[test]
    fn orientations_convert_through_the_core() {
        let mut d = doc();
        let p = Path::of(&["poses"]).i(0);
        let before = pose_of(&d, &p).unwrap();
        assert_eq!(orientation_kind(&d, &p), Some("euler_xyz_deg"));
        for kind in ["tilt_torsion", "quaternion", "euler_xyz_deg", "tilt_torsion"] {
            assert!(convert_orientation(&mut d, &p, kind));
            assert_eq!(orientation_kind(&d, &p), Some(kind));
            let after = pose_of(&d, &p).unwrap();
            assert!(before.rotation.angle_to(&after.rotation) < 1e-10, "{kind}");
        }
        // Euler (0, 0, 30°) is tilt 0 and torsion 30° = 0.5236 rad
        let tt = get(&d, &p.k("tilt_torsion")).unwrap();
        assert!((tt[1].as_f64().unwrap()).abs() < 1e-12);
        assert!((tt[2].as_f64().unwrap() - 30f64.to_radians()).abs() < 1e-11);
    }

    #[test]
    fn poses_add_and_rename_everywhere() {
        let mut d = doc();
        assert_eq!(add_pose(&mut d), "pose 1");
        assert_eq!(pose_names(&d), ["start", "end", "fig310", "box-left", "box-right", "pose 1"]);
        rename_pose(&mut d, 0, "begin").unwrap();
        assert_eq!(pose_names(&d), ["begin", "end", "fig310", "box-left", "box-right", "pose 1"]);
        assert_eq!(d["trajectories"][1]["orientation"]["slerp"], json!(["begin", "end"]));
        assert!(rename_pose(&mut d, 1, "begin").is_err());
        assert!(rename_pose(&mut d, 1, " ").is_err());
        let s = Scenario::from_json(&d.to_string()).unwrap();
        let r = check_pose(&s, "pose 1").unwrap();
        assert_eq!(r.lengths.len(), 7);
        assert!(!pose_verdict(&r).is_empty());
    }

    #[test]
    fn live_pose_check_is_the_cores() {
        // fig310 is where cable 3 touches the box's clearance: the core calls it feasible or not,
        // and the verdict repeats the core's violated list.
        let s = Scenario::from_json(&doc().to_string()).unwrap();
        let r = check_pose(&s, "fig310").unwrap();
        let direct = cablenav::verify::check_pose(&s, "fig310", s.pose("fig310").unwrap());
        assert_eq!(r, direct);
        let v = pose_verdict(&r);
        assert_eq!(v.starts_with("feasible"), r.feasible);
        for c in &r.violated {
            assert!(v.contains(c.as_str()));
        }
        assert!(check_pose(&s, "nope").is_none());
    }

    #[test]
    fn via_points_edit_the_polynomial() {
        let mut d = doc();
        let path = Path::of(&["trajectories"]).i(1).k("translation").k("polynomial");
        let pts = via_points_of(&d, &path, 0).unwrap();
        assert_eq!(pts, vec![[2.0, 1.5, 1.0], [1.2, 1.9, 1.8], [1.5, 2.3, 3.0]]);
        let mut moved = pts.clone();
        moved[1][2] = 2.0;
        set_via_points(&mut d, &path, &moved).unwrap();
        assert_eq!(via_points_of(&d, &path, 0).unwrap(), moved);
        assert_eq!(d["trajectories"][1]["translation"]["polynomial"][1], json!([1.5, 0.8]));
        // more points than the degree needs: the same curve
        assert_eq!(via_points_of(&d, &path, 5).unwrap().len(), 5);
        let e = set_via_points(&mut d, &path, &moved[..1]).unwrap_err();
        assert_eq!(e.field, "trajectories[1].translation.polynomial");
    }

    #[test]
    fn translations_retype_keeping_their_ends() {
        let mut d = doc();
        let t = Path::of(&["trajectories"]).i(1);
        for kind in ["line", "bezier", "polynomial", "line"] {
            retype_translation(&mut d, &t, kind);
            assert_eq!(translation_kind(&d, &t), Some(kind));
            assert_eq!(translation_ends(&d, &t), Some([[2.0, 1.5, 1.0], [1.5, 2.3, 3.0]]), "{kind}");
        }
        let i = add_trajectory(&mut d);
        assert_eq!(i, 2);
        assert_eq!(d["trajectories"][2]["name"], json!("trajectory 1"));
        Scenario::from_json(&d.to_string()).unwrap();
    }

    #[test]
    fn slerp_ends_switch_between_poses_and_quaternions() {
        let mut d = doc();
        let t = Path::of(&["trajectories"]).i(0);
        assert_eq!(slerp_end_choice(&d, &t, 0), "start");
        set_slerp_end(&mut d, &t, 0, QUATERNION_END);
        assert_eq!(slerp_end_choice(&d, &t, 0), QUATERNION_END);
        // Euler (0, 0, 30°) is the quaternion (cos 15°, 0, 0, sin 15°)
        let q = &d["trajectories"][0]["orientation"]["slerp"][0];
        assert!((q[0].as_f64().unwrap() - 15f64.to_radians().cos()).abs() < 1e-11, "{q}");
        assert!((q[3].as_f64().unwrap() - 15f64.to_radians().sin()).abs() < 1e-11, "{q}");
        set_slerp_end(&mut d, &t, 1, "fig310");
        assert_eq!(d["trajectories"][0]["orientation"]["slerp"][1], json!("fig310"));
        Scenario::from_json(&d.to_string()).unwrap();
    }

    #[test]
    fn wrench_ellipsoid_modes() {
        let mut d: Value = serde_json::from_str(crate::presets::PRESETS[crate::presets::find("robocrane").unwrap()].json).unwrap();
        assert_eq!(ellipsoid_mode(&d), "radius");
        assert_eq!(ellipsoid_radii(&d), [Some(0.01); 6]);
        set_ellipsoid_mode(&mut d, "radii");
        assert_eq!(ellipsoid_mode(&d), "radii");
        assert_eq!(d["wrench"]["ellipsoid"][2][2], json!(10000));
        set_ellipsoid_radii(&mut d, [1.0, 2.0, 0.5, 1.0, 1.0, 4.0]);
        assert_eq!(ellipsoid_radii(&d), [Some(1.0), Some(2.0), Some(0.5), Some(1.0), Some(1.0), Some(4.0)]);
        let s = Scenario::from_json(&d.to_string()).unwrap();
        assert!((s.wrench.unwrap().ellipsoid[(1, 1)] - 0.25).abs() < 1e-15);
        // a zero radius is not SPD: the core says so at wrench.ellipsoid
        set_ellipsoid_radii(&mut d, [1.0, 0.0, 1.0, 1.0, 1.0, 1.0]);
        let e = Scenario::from_json(&d.to_string()).unwrap_err();
        assert_eq!(e.field, "wrench.ellipsoid");
        // an off-diagonal entry makes it a matrix
        set_ellipsoid_radii(&mut d, [1.0; 6]);
        d["wrench"]["ellipsoid"][0][1] = json!(0.5);
        d["wrench"]["ellipsoid"][1][0] = json!(0.5);
        assert_eq!(ellipsoid_mode(&d), "matrix");
        set_ellipsoid_mode(&mut d, "radius");
        assert_eq!(d["wrench"]["radius"], json!(1));
        assert!(d["wrench"].get("ellipsoid").is_none());
        d["wrench"] = wrench_template();
        Scenario::from_json(&d.to_string()).unwrap();
    }

    #[test]
    fn caspr_files_are_paired_by_their_root() {
        let bodies = include_str!("../../../shared/models/caspr/NIST_ROBOCRANE/NIST_RoboCrane_bodies.xml");
        let cables = include_str!("../../../shared/models/caspr/NIST_ROBOCRANE/NIST_RoboCrane_cables.xml");
        let files = vec![
            ("NIST_RoboCrane_cables.xml".to_string(), Ok(cables.to_string())),
            ("NIST_RoboCrane_bodies.xml".to_string(), Ok(bodies.to_string())),
        ];
        let (name, json, _) = caspr_pair(files).unwrap();
        assert_eq!(name, "NIST_RoboCrane");
        assert_eq!(Scenario::from_json(&json).unwrap().robot.cables.len(), 6);
        let e = caspr_pair(vec![("a.xml".into(), Ok(bodies.to_string()))]).unwrap_err();
        assert!(e.contains("both"), "{e}");
        let e = caspr_pair(vec![("a.xml".into(), Err("could not read a.xml".into()))]).unwrap_err();
        assert_eq!(e, "could not read a.xml");
        let broken = bodies.replace("SPATIAL_EULER_XYZ", "R_X");
        let e = caspr_pair(vec![("b.xml".into(), Ok(broken)), ("c.xml".into(), Ok(cables.to_string()))]).unwrap_err();
        assert!(e.starts_with("CASPR import: bodies: line 6"), "{e}");
    }

    #[test]
    fn workspace_box_and_centre() {
        let d = doc();
        assert_eq!(workspace_centre(&d), [12.0 / 7.0, 2.0, 16.0 / 7.0].map(round12));
        assert_eq!(workspace_range(&d), [[-0.5, 4.5], [-0.5, 4.5], [-0.5, 4.5]]);
    }
}
