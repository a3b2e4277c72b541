//! Paths into the scenario's JSON tree: reading, writing (creating the way), removing, and
//! the core's name for a path (its `Error::field` syntax), so errors land on their widget.

use serde_json::{Map, Value};

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
pub(super) fn get_mut_existing<'a>(doc: &'a mut Value, path: &Path) -> Option<&'a mut Value> {
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
/// A point `[x, y, z]` at `path`, if it is one.
pub fn point(doc: &Value, path: &Path) -> Option<[f64; 3]> {
    let a = get(doc, path)?.as_array()?;
    match a.as_slice() {
        [x, y, z] => Some([x.as_f64()?, y.as_f64()?, z.as_f64()?]),
        _ => None,
    }
}

/// The points `[x, y, z]` in the list at `path` (those that are points).
pub(super) fn points(doc: &Value, path: &Path) -> Vec<[f64; 3]> {
    (0..len(doc, path)).filter_map(|i| point(doc, &path.i(i))).collect()
}

#[cfg(test)]
mod tests {
    use super::super::test_doc as doc;
    use super::super::*;
    use super::*;
    
    use serde_json::{json, Value};

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
}
