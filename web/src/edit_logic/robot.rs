//! Robot edits: cables added and removed with their per-cable bound lists kept in step, and
//! the workspace box around the base anchors (where new items go, slider ranges).

use serde_json::{json, Value};

use super::path::get_mut_existing;
use super::{get, len, number, point, remove, round12, set, Path};

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

/// How cable `i` of a multi-link robot is routed, for its row in the table: `from LINK` when its
/// base anchor is on a link, and how many anchors it runs through (`via`); `None` for a straight
/// cable from the base. The table edits the base and end anchors; the route is kept as written.
pub fn route_summary(doc: &Value, i: usize) -> Option<String> {
    let cable = Path::of(&["robot", "cables"]).i(i);
    let from = get(doc, &cable.k("from")).and_then(Value::as_str).map(|l| format!("base anchor on {l}"));
    let via = len(doc, &cable.k("via"));
    let through = (via > 0).then(|| format!("through {via} anchor{}", if via == 1 { "" } else { "s" }));
    let parts: Vec<String> = [from, through].into_iter().flatten().collect();
    (!parts.is_empty()).then(|| format!("routed: {}", parts.join(", ")))
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

#[cfg(test)]
mod tests {
    use super::super::test_doc as doc;
    use super::super::*;
    use super::*;
    use cablenav::Scenario;
    use serde_json::json;

    #[test]
    fn a_routed_cable_says_how_it_runs() {
        let mut d = doc();
        assert_eq!(route_summary(&d, 0), None);
        d["robot"]["cables"][0]["from"] = json!("Upper Arm");
        assert_eq!(route_summary(&d, 0).as_deref(), Some("routed: base anchor on Upper Arm"));
        d["robot"]["cables"][0]["via"] = json!([{"point": [0, 0, 1]}, {"link": "Lower Arm", "point": [0, 0, 0.1]}]);
        assert_eq!(route_summary(&d, 0).as_deref(), Some("routed: base anchor on Upper Arm, through 2 anchors"));
        d["robot"]["cables"][0].as_object_mut().unwrap().remove("from");
        assert_eq!(route_summary(&d, 0).as_deref(), Some("routed: through 2 anchors"));
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
    fn workspace_box_and_centre() {
        let d = doc();
        assert_eq!(workspace_centre(&d), [12.0 / 7.0, 2.0, 16.0 / 7.0].map(round12));
        assert_eq!(workspace_range(&d), [[-0.5, 4.5], [-0.5, 4.5], [-0.5, 4.5]]);
    }
}
