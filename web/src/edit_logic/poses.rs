//! Pose edits: orientation conventions converted by the core, adding and renaming poses
//! (everywhere they are named), and the live pose check.

use cablenav::model::Pose;
use cablenav::report::PoseReport;
use cablenav::Scenario;
use nalgebra::Vector3;
use serde_json::{json, Map, Value};

use super::{fresh_name, get, get_mut, len, number, point, remove, round12, set, workspace_centre, Path};

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

#[cfg(test)]
mod tests {
    use super::super::test_doc as doc;
    use super::super::*;
    use super::*;
    use cablenav::Scenario;
    use serde_json::json;

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
}
