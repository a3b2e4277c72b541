//! Multi-link edits (scenario format 3, docs/multilink.md): links and their joints, the
//! configurations (one number per joint coordinate, by name) and the paths through them. A
//! rename follows the name everywhere it is used (a link in its children's `parent` and its
//! cables' `link`, a coordinate in every configuration, a configuration in every path); a removal
//! takes out what can no longer mean anything (a removed link's coordinates from the
//! configurations) and leaves the rest for the core to name (a cable still pulling the removed
//! link), so nothing the user typed disappears unsaid.

use serde_json::{json, Map, Value};

use super::{fresh_name, get, get_mut_existing, len, number, remove, round12, set, Path};

/// The joint types, as the format names them.
pub const JOINTS: [&str; 7] = ["free", "spatial", "spherical", "universal", "revolute", "prismatic", "planar"];

/// How many axes a joint of type `kind` is given as `axes` (universal 2, planar 3; 0: none, or
/// one `axis`), and the default ones (CASPR's `U_XZ`, `PLANAR_YZ`).
fn joint_axes(kind: &str) -> Option<Value> {
    match kind {
        "universal" => Some(json!([[1, 0, 0], [0, 0, 1]])),
        "planar" => Some(json!([[0, 1, 0], [0, 0, 1], [1, 0, 0]])),
        _ => None,
    }
}

/// Whether the scenario is a multi-link robot (it has `robot.links`).
pub fn is_multi_link(doc: &Value) -> bool {
    matches!(get(doc, &links()), Some(Value::Array(_)))
}

/// Whether some link of a multi-link robot has a `mass`: its cables then hold the weights, and
/// their tension bounds apply (static feasibility).
pub fn has_link_mass(doc: &Value) -> bool {
    matches!(get(doc, &links()), Some(Value::Array(ls)) if ls.iter().any(|l| l.get("mass").is_some()))
}

fn links() -> Path {
    Path::of(&["robot", "links"])
}

fn configurations() -> Path {
    Path::of(&["configurations"])
}

fn strings(v: Option<&Value>) -> Vec<String> {
    v.and_then(Value::as_array).map(|a| a.iter().filter_map(|x| x.as_str().map(str::to_string)).collect()).unwrap_or_default()
}

/// The links' names, in file order.
pub fn link_names(doc: &Value) -> Vec<String> {
    get(doc, &links()).and_then(Value::as_array).map(|a| a.iter().map(|l| l.get("name").and_then(Value::as_str).unwrap_or_default().to_string()).collect()).unwrap_or_default()
}

/// The joint coordinates' names of link `i`.
pub fn coordinate_names(doc: &Value, i: usize) -> Vec<String> {
    strings(get(doc, &links().i(i).k("joint").k("coordinates")))
}

/// Every joint coordinate of the robot, in configuration order, with its unit (`rad` for angles,
/// `m` for lengths).
pub fn all_coordinates(doc: &Value) -> Vec<(String, &'static str)> {
    (0..len(doc, &links()))
        .flat_map(|i| {
            let kind = joint_type(doc, i);
            coordinate_names(doc, i).into_iter().enumerate().map(move |(k, n)| (n, unit(&kind, k)))
        })
        .collect()
}

/// The coordinates a force from outside may act on (`joint_forces`: those of revolute,
/// prismatic, universal and planar joints), in configuration order, with the force's unit
/// (`N·m` about an axis, `N` along one).
pub fn forceable_coordinates(doc: &Value) -> Vec<(String, &'static str)> {
    (0..len(doc, &links()))
        .flat_map(|i| {
            let kind = joint_type(doc, i);
            let takes = matches!(kind.as_str(), "revolute" | "prismatic" | "universal" | "planar");
            let names = if takes { coordinate_names(doc, i) } else { Vec::new() };
            names.into_iter().enumerate().map(move |(k, n)| (n, if unit(&kind, k) == "m" { "N" } else { "N·m" }))
        })
        .collect()
}

/// Sets a force from outside on a coordinate, at `path` (`joint_forces.NAME`; `None`: removes
/// it, and `joint_forces` once it is empty), raising the file's format to 6 when writing.
pub fn set_joint_force(doc: &mut Value, path: &Path, value: Option<f64>) {
    let forces = Path::of(&["joint_forces"]);
    match value {
        Some(x) => {
            set(doc, path, number(x));
            super::require_format(doc, cablenav::scenario::FORMAT_6);
        }
        None => {
            remove(doc, path);
            if matches!(get(doc, &forces), Some(Value::Object(m)) if m.is_empty()) {
                remove(doc, &forces);
            }
        }
    }
}

/// The unit of coordinate `k` of a joint of type `kind`.
pub fn unit(kind: &str, k: usize) -> &'static str {
    match (kind, k) {
        ("free" | "spatial", 0..=2) | ("prismatic", _) | ("planar", 0..=1) => "m",
        _ => "rad",
    }
}

/// Link `i`'s joint type (`""` if missing).
pub fn joint_type(doc: &Value, i: usize) -> String {
    get(doc, &links().i(i).k("joint").k("type")).and_then(Value::as_str).unwrap_or_default().to_string()
}

/// The names a joint of type `kind` would call its coordinates.
fn stems(kind: &str) -> &'static [&'static str] {
    match kind {
        "free" => &["x", "y", "z", "phi", "theta", "sigma"],
        "spatial" => &["x", "y", "z", "alpha", "beta", "gamma"],
        "spherical" => &["alpha", "beta", "gamma"],
        "universal" => &["alpha", "gamma"],
        "planar" => &["u", "v", "theta"],
        "prismatic" => &["d"],
        _ => &["q"],
    }
}

/// `stem`, or `stem2`, `stem3`, … : the first not in `taken`.
fn free_name(stem: &str, taken: &[String]) -> String {
    std::iter::once(stem.to_string()).chain((2..).map(|k| format!("{stem}{k}"))).find(|n| !taken.contains(n)).unwrap_or_default()
}

/// The default range of coordinate `k` of a joint of type `kind`: a whole turn for angles,
/// ±1 m for lengths.
fn default_range(kind: &str, k: usize) -> Value {
    let r = if unit(kind, k) == "m" { 1.0 } else { round12(std::f64::consts::PI) };
    json!([number(-r), number(r)])
}

/// Every coordinate name of the robot except link `skip`'s.
fn names_outside(doc: &Value, skip: Option<usize>) -> Vec<String> {
    (0..len(doc, &links())).filter(|&j| Some(j) != skip).flat_map(|j| coordinate_names(doc, j)).collect()
}

/// Gives link `i` a joint of type `kind`: coordinates with names not used elsewhere (kept where
/// the count and the units stay), explicit ranges, an axis for revolute and prismatic joints (the old one
/// kept, else x), axes for universal and planar ones (the old ones kept, else CASPR's `U_XZ`,
/// `PLANAR_YZ`). Every configuration drops the old coordinates and gets the new ones (at 0, or
/// the old value where the name is kept).
pub fn set_joint_type(doc: &mut Value, i: usize, kind: &str) {
    if !JOINTS.contains(&kind) {
        return;
    }
    let old_names = coordinate_names(doc, i);
    let old_kind = joint_type(doc, i);
    let want = stems(kind);
    let mut taken = names_outside(doc, Some(i));
    let same_units = (0..want.len()).all(|k| unit(&old_kind, k) == unit(kind, k));
    let names: Vec<String> = if old_names.len() == want.len() && same_units {
        old_names.clone()
    } else {
        want.iter()
            .map(|s| {
                let n = free_name(s, &taken);
                taken.push(n.clone());
                n
            })
            .collect()
    };
    let joint = links().i(i).k("joint");
    let axis = get(doc, &joint.k("axis")).cloned().unwrap_or_else(|| json!([1, 0, 0]));
    let mut j = Map::new();
    j.insert("type".into(), json!(kind));
    if matches!(kind, "revolute" | "prismatic") {
        j.insert("axis".into(), axis);
    }
    if let Some(axes) = joint_axes(kind) {
        // the old axes kept where the count stays
        let old = get(doc, &joint.k("axes")).filter(|a| a.as_array().map(Vec::len) == axes.as_array().map(Vec::len)).cloned();
        j.insert("axes".into(), old.unwrap_or(axes));
    }
    j.insert("coordinates".into(), json!(names));
    j.insert("range".into(), Value::Array((0..names.len()).map(|k| default_range(kind, k)).collect()));
    set(doc, &joint, Value::Object(j));
    for c in 0..len(doc, &configurations()) {
        if let Some(Value::Object(q)) = get_mut_existing(doc, &configurations().i(c)) {
            for n in &old_names {
                if !names.contains(n) {
                    q.shift_remove(n);
                }
            }
            for n in &names {
                q.entry(n.clone()).or_insert(json!(0));
            }
        }
    }
}

/// Appends a link: a revolute joint about x at the end of the last link's body (the base for
/// the first), a body 0.3 m along z, every configuration with its coordinate at 0; returns its
/// index.
pub fn add_link(doc: &mut Value) -> usize {
    let n = len(doc, &links());
    let name = fresh_name(doc, &links(), "link");
    let mut link = json!({"name": name, "location": [0, 0, 0], "body": {"from": [0, 0, 0], "to": [0, 0, 0.3], "radius": 0}});
    if let Some(last) = n.checked_sub(1).and_then(|k| get(doc, &links().i(k))) {
        link["parent"] = last.get("name").cloned().unwrap_or(Value::Null);
        if let Some(to) = last.get("body").and_then(|b| b.get("to")) {
            link["location"] = to.clone();
        }
    }
    set(doc, &links().i(n), link);
    set_joint_type(doc, n, "revolute");
    n
}

/// Removes link `i` and its coordinates from every configuration. Its children and its cables
/// keep naming it: the core then names each field to fix.
pub fn remove_link(doc: &mut Value, i: usize) {
    let gone = coordinate_names(doc, i);
    remove(doc, &links().i(i));
    for c in 0..len(doc, &configurations()) {
        if let Some(Value::Object(q)) = get_mut_existing(doc, &configurations().i(c)) {
            for n in &gone {
                q.shift_remove(n);
            }
        }
    }
}

/// Checks a new name against the others in use: a message for the field, or `Ok`.
fn check_name(new: &str, old: &str, taken: &[String], what: &str) -> Result<(), String> {
    if new.trim().is_empty() {
        return Err(format!("a {what} needs a name"));
    }
    if new != old && taken.iter().any(|t| t == new) {
        return Err(format!("another {what} is called “{new}”"));
    }
    Ok(())
}

/// Renames link `i`, and the name in its children's `parent`, its cables' `link`, a routed
/// cable's `from` and `via[k].link`, and the `wrench.link` of a wrench applied to it.
pub fn rename_link(doc: &mut Value, i: usize, new: &str) -> Result<(), String> {
    let names = link_names(doc);
    let old = names.get(i).cloned().ok_or("no such link")?;
    check_name(new, &old, &names, "link")?;
    set(doc, &links().i(i).k("name"), json!(new));
    for j in 0..names.len() {
        let parent = links().i(j).k("parent");
        if get(doc, &parent).and_then(Value::as_str) == Some(old.as_str()) {
            set(doc, &parent, json!(new));
        }
    }
    let cables = Path::of(&["robot", "cables"]);
    let routes = (0..len(doc, &cables)).flat_map(|c| {
        let via = cables.i(c).k("via");
        let anchors = (0..len(doc, &via)).map(move |k| via.i(k).k("link"));
        [cables.i(c).k("link"), cables.i(c).k("from")].into_iter().chain(anchors)
    });
    let references = routes.chain([Path::of(&["wrench", "link"])]).collect::<Vec<_>>();
    for link in references {
        if get(doc, &link).and_then(Value::as_str) == Some(old.as_str()) {
            set(doc, &link, json!(new));
        }
    }
    Ok(())
}

/// Renames coordinate `k` of link `i`, and its entry in every configuration and in the joint
/// forces (in place).
pub fn rename_coordinate(doc: &mut Value, i: usize, k: usize, new: &str) -> Result<(), String> {
    let old = coordinate_names(doc, i).get(k).cloned().ok_or("no such coordinate")?;
    check_name(new, &old, &names_outside(doc, None), "coordinate")?;
    set(doc, &links().i(i).k("joint").k("coordinates").i(k), json!(new));
    for c in 0..len(doc, &configurations()) {
        rename_key(doc, &configurations().i(c), &old, new);
    }
    rename_key(doc, &Path::of(&["joint_forces"]), &old, new);
    Ok(())
}

/// Renames member `old` of the object at `path` to `new`, keeping its place.
fn rename_key(doc: &mut Value, path: &Path, old: &str, new: &str) {
    if let Some(Value::Object(m)) = get_mut_existing(doc, path) {
        if old != new && m.contains_key(old) {
            *m = std::mem::take(m).into_iter().map(|(k, v)| if k == old { (new.to_string(), v) } else { (k, v) }).collect();
        }
    }
}

/// The configurations' names, in file order.
pub fn configuration_names(doc: &Value) -> Vec<String> {
    get(doc, &configurations()).and_then(Value::as_object).map(|m| m.keys().cloned().collect()).unwrap_or_default()
}

/// Adds a configuration: a copy of the first one (every coordinate at 0 if there is none);
/// returns its name.
pub fn add_configuration(doc: &mut Value) -> String {
    let name = fresh_name(doc, &configurations(), "configuration");
    let values = match get(doc, &configurations().i(0)) {
        Some(first @ Value::Object(_)) => first.clone(),
        _ => Value::Object(all_coordinates(doc).into_iter().map(|(n, _)| (n, json!(0))).collect()),
    };
    if !matches!(get(doc, &configurations()), Some(Value::Object(_))) {
        set(doc, &configurations(), Value::Object(Map::new()));
    }
    if let Some(Value::Object(m)) = get_mut_existing(doc, &configurations()) {
        m.insert(name.clone(), values);
    }
    name
}

/// Renames configuration `i` (keeping its place), and the name in every path through it.
pub fn rename_configuration(doc: &mut Value, i: usize, new: &str) -> Result<(), String> {
    let names = configuration_names(doc);
    let old = names.get(i).cloned().ok_or("no such configuration")?;
    check_name(new, &old, &names, "configuration")?;
    rename_key(doc, &configurations(), &old, new);
    let paths = Path::of(&["trajectories"]);
    for t in 0..len(doc, &paths) {
        let through = paths.i(t).k("through");
        for s in 0..len(doc, &through) {
            if get(doc, &through.i(s)).and_then(Value::as_str) == Some(old.as_str()) {
                set(doc, &through.i(s), json!(new));
            }
        }
    }
    Ok(())
}

/// Adds a path through the first two configurations (the first twice if there is one, none if
/// there is none); returns its index.
pub fn add_path(doc: &mut Value) -> usize {
    let list = Path::of(&["trajectories"]);
    let names = configuration_names(doc);
    let through = match names.as_slice() {
        [] => json!([]),
        [one] => json!([one, one]),
        [a, b, ..] => json!([a, b]),
    };
    let n = len(doc, &list);
    let name = fresh_name(doc, &list, "path");
    set(doc, &list.i(n), json!({"name": name, "through": through}));
    n
}

/// Appends configuration `name` to path `t`'s `through`.
pub fn add_step(doc: &mut Value, t: usize, name: &str) {
    let through = Path::of(&["trajectories"]).i(t).k("through");
    let n = len(doc, &through);
    set(doc, &through.i(n), json!(name));
}

#[cfg(test)]
mod tests {
    use super::super::*;
    use super::*;
    use cablenav::Scenario;

    fn arm() -> Value {
        serde_json::from_str(crate::presets::PRESETS[crate::presets::find("bmarm-x4-2").unwrap()].json).unwrap()
    }

    fn valid(d: &Value) -> Scenario {
        Scenario::from_json(&d.to_string()).unwrap_or_else(|e| panic!("{e}: {d}"))
    }

    #[test]
    fn the_arm_is_read_as_links_coordinates_and_configurations() {
        let d = arm();
        assert!(is_multi_link(&d) && !is_multi_link(&test_doc()));
        assert!(!has_link_mass(&d) && !has_link_mass(&test_doc()));
        assert_eq!(link_names(&d), ["Upper Arm", "Lower Arm"]);
        assert_eq!(all_coordinates(&d).iter().map(|c| c.0.as_str()).collect::<Vec<_>>(), ["alpha", "beta", "gamma", "theta"]);
        assert_eq!(configuration_names(&d), ["above", "below", "fig312", "initial"]);
        assert_eq!(unit("free", 1), "m");
        assert_eq!(unit("free", 4), "rad");
        assert_eq!(unit("prismatic", 0), "m");
    }

    #[test]
    fn renaming_a_link_renames_the_wrench_applied_to_it() {
        let mut d = arm();
        set(&mut d, &Path::of(&["format"]), json!(FORMAT_4));
        set(&mut d, &Path::of(&["wrench"]), json!({"nominal": [0.0, 0.0, -2.0, 0.0, 0.0, 0.0], "link": "Lower Arm", "point": [0.0, 0.0, 0.5]}));
        rename_link(&mut d, 1, "Forearm").unwrap();
        assert_eq!(d["wrench"]["link"], "Forearm");
        rename_link(&mut d, 0, "Shoulder").unwrap();
        assert_eq!(d["wrench"]["link"], "Forearm");
        let s = valid(&d);
        assert_eq!(s.robot.chain.as_ref().unwrap().load.as_ref().map(|w| w.link), Some(1));
    }

    #[test]
    fn a_link_mass_raises_the_format_and_the_arm_then_holds_its_weight() {
        let mut d = arm();
        set_timed_number(&mut d, &links().i(1).k("mass"), Some(1.0));
        assert!(has_link_mass(&d));
        assert_eq!(d["format"], FORMAT_4);
        let s = valid(&d);
        assert_eq!(s.robot.chain.as_ref().unwrap().links[1].mass, 1.0);
        assert!(cablenav::conditions::for_scenario(&s).iter().any(|c| c.label() == "static feasibility"));
    }

    #[test]
    fn a_new_joint_type_rewrites_the_coordinates_and_every_configuration() {
        let mut d = arm();
        set_joint_type(&mut d, 1, "prismatic");
        let s = valid(&d);
        let chain = s.robot.chain.as_ref().unwrap();
        assert_eq!(chain.links[1].coords[0].name, "d");
        assert_eq!(chain.links[1].coords[0].range, [-1.0, 1.0]);
        assert_eq!(s.config("fig312").unwrap().len(), 4, "theta replaced by d in every configuration");
        assert!(get(&d, &Path::of(&["configurations", "fig312", "theta"])).is_none());
        // a spherical joint's three names, none taken by the upper arm's alpha, beta, gamma
        set_joint_type(&mut d, 1, "spherical");
        assert_eq!(coordinate_names(&d, 1), ["alpha2", "beta2", "gamma2"]);
        let s = valid(&d);
        assert_eq!(s.robot.chain.as_ref().unwrap().dof(), 6);
        // the same count keeps the names and the configurations' values
        set(&mut d, &Path::of(&["configurations", "above", "beta2"]), json!(0.25));
        set_joint_type(&mut d, 1, "spherical");
        assert_eq!(get(&d, &Path::of(&["configurations", "above", "beta2"])), Some(&json!(0.25)));
        // free: positions in metres, no axis
        set_joint_type(&mut d, 0, "free");
        assert!(get(&d, &Path::of(&["robot", "links"]).i(0).k("joint").k("axis")).is_none());
        valid(&d);
        // universal and planar: CASPR's U_XZ and PLANAR_YZ axes, kept when the count stays
        set_joint_type(&mut d, 1, "universal");
        let axes = Path::of(&["robot", "links"]).i(1).k("joint").k("axes");
        assert_eq!(get(&d, &axes), Some(&json!([[1, 0, 0], [0, 0, 1]])));
        assert!(valid(&d).robot.chain.as_ref().unwrap().links[1].joint == cablenav::model::Joint::Universal([nalgebra::Vector3::x(), nalgebra::Vector3::z()]));
        set(&mut d, &axes.i(1), json!([0, 1, 0]));
        set_joint_type(&mut d, 1, "universal");
        assert_eq!(get(&d, &axes), Some(&json!([[1, 0, 0], [0, 1, 0]])));
        set_joint_type(&mut d, 1, "planar");
        assert_eq!(get(&d, &axes), Some(&json!([[0, 1, 0], [0, 0, 1], [1, 0, 0]])));
        assert_eq!((unit("planar", 1), unit("planar", 2)), ("m", "rad"));
        let s = valid(&d);
        assert_eq!(s.robot.chain.as_ref().unwrap().links[1].coords.iter().map(|c| c.range).collect::<Vec<_>>(), [[-1.0, 1.0], [-1.0, 1.0], [-round12(std::f64::consts::PI), round12(std::f64::consts::PI)]], "lengths in m, the angle a whole turn");
        // spatial: six coordinates, no axes left over
        set_joint_type(&mut d, 1, "spatial");
        assert!(get(&d, &axes).is_none());
        assert_eq!(valid(&d).robot.chain.as_ref().unwrap().dof(), 12, "the free root and the spatial link: six each");
    }

    #[test]
    fn links_are_added_renamed_and_removed_with_what_names_them() {
        let mut d = arm();
        let k = add_link(&mut d);
        assert_eq!(link_names(&d)[k], "link 1");
        let s = valid(&d);
        assert_eq!(s.robot.chain.as_ref().unwrap().links[k].parent, Some(1), "hangs from the last link");
        assert_eq!(coordinate_names(&d, k), ["q"]);
        // renaming the lower arm renames its child's parent and its cables' link
        rename_link(&mut d, 1, "Forearm").unwrap();
        let s = valid(&d);
        assert_eq!(s.robot.chain.as_ref().unwrap().links[1].name, "Forearm");
        assert!(get(&d, &Path::of(&["robot", "links"]).i(k).k("parent")) == Some(&json!("Forearm")));
        assert!(s.robot.cables.iter().filter(|c| c.link == 1).count() >= 1);
        assert_eq!(rename_link(&mut d, 1, "Upper Arm").unwrap_err(), "another link is called “Upper Arm”");
        // a routed cable's references follow a renamed link too (format 6: from, via)
        d["format"] = json!("cablenav-scenario/6");
        d["robot"]["cables"][0]["from"] = json!("Upper Arm");
        d["robot"]["cables"][0]["link"] = json!("Forearm");
        d["robot"]["cables"][1]["via"] = json!([{"link": "Upper Arm", "point": [0.01, 0.0, 0.1]}, {"point": [0.3, 0.0, 0.0]}]);
        rename_link(&mut d, 0, "Humerus").unwrap();
        assert_eq!((&d["robot"]["cables"][0]["from"], &d["robot"]["cables"][1]["via"][0]["link"]), (&json!("Humerus"), &json!("Humerus")));
        assert!(d["robot"]["cables"][1]["via"][1].get("link").is_none(), "a base anchor stays on the base");
        let s = valid(&d);
        assert_eq!((s.robot.cables[0].from, s.robot.cables[1].via[0].link), (Some(0), Some(0)));
        rename_link(&mut d, 0, "Upper Arm").unwrap();
        assert!(rename_link(&mut d, 1, " ").is_err());
        // removing a link drops its coordinates; what still names it is the core's error
        remove_link(&mut d, k);
        valid(&d);
        remove_link(&mut d, 1);
        let e = Scenario::from_json(&d.to_string()).unwrap_err();
        assert!(e.field.starts_with("robot.cables["), "{e}");
        assert!(get(&d, &Path::of(&["configurations", "above", "theta"])).is_none());
    }

    #[test]
    fn coordinates_and_configurations_are_renamed_everywhere() {
        let mut d = arm();
        rename_coordinate(&mut d, 0, 1, "b").unwrap();
        assert_eq!(get(&d, &Path::of(&["configurations", "above", "b"])), Some(&json!(0.4)));
        let keys: Vec<String> = get(&d, &Path::of(&["configurations", "above"])).unwrap().as_object().unwrap().keys().cloned().collect();
        assert_eq!(keys, ["alpha", "b", "gamma", "theta"], "in place");
        assert!(rename_coordinate(&mut d, 0, 0, "theta").is_err());
        valid(&d);
        rename_configuration(&mut d, 1, "low").unwrap();
        assert_eq!(configuration_names(&d), ["above", "low", "fig312", "initial"]);
        let s = valid(&d);
        assert_eq!(s.joint_paths[0].through[0], s.config("low").unwrap(), "the path follows the rename");
        assert!(rename_configuration(&mut d, 1, "above").is_err());
    }

    #[test]
    fn forces_on_joints_reach_the_core_and_follow_a_rename() {
        let mut d = arm();
        assert_eq!(forceable_coordinates(&d), [("theta".to_string(), "N·m")], "not the spherical shoulder's Euler angles");
        set_joint_force(&mut d, &Path::of(&["joint_forces", "theta"]), Some(0.5));
        assert_eq!(d["format"], json!(cablenav::scenario::FORMAT_6));
        let s = valid(&d);
        let chain = s.robot.chain.as_ref().unwrap();
        assert!(chain.joint_forces == [0.0, 0.0, 0.0, 0.5] && chain.is_loaded(), "{:?}", chain.joint_forces);
        rename_coordinate(&mut d, 1, 0, "elbow").unwrap();
        assert_eq!(d["joint_forces"], json!({"elbow": 0.5}));
        valid(&d);
        set_joint_force(&mut d, &Path::of(&["joint_forces", "elbow"]), None);
        assert!(d.get("joint_forces").is_none(), "{d}");
        assert!(!valid(&d).robot.chain.as_ref().unwrap().is_loaded());
    }

    #[test]
    fn configurations_and_paths_are_added() {
        let mut d = arm();
        let c = add_configuration(&mut d);
        assert_eq!(c, "configuration 1");
        let s = valid(&d);
        assert_eq!(s.config(&c).unwrap(), s.config("above").unwrap(), "a copy of the first");
        let t = add_path(&mut d);
        add_step(&mut d, t, "initial");
        let s = valid(&d);
        assert_eq!(s.joint_paths[t].through.len(), 3);
        assert_eq!(s.joint_paths[t].name, "path 1");
    }
}
