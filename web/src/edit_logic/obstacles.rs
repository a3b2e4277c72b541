//! Obstacle edits: a template per type, retyping in place, fresh names.

use serde_json::{json, Map, Value};

use super::{get, len, number, point, round12, set, workspace_centre, Path};

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

#[cfg(test)]
mod tests {
    use super::super::test_doc as doc;
    
    use super::*;
    use cablenav::Scenario;
    use serde_json::json;

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
}
