//! Timed spline trajectories through knots (format 4 `spline` and `knots`, CASPR's form): telling
//! them from the thesis' form, their spline kind, knots added and removed, and a trajectory of
//! the thesis' form turned into one (its start and end poses, computed by the core, at rest).

use serde_json::{json, Value};

use super::{get, len, number, remove, round12, set, timing::{require_format, FORMAT_4}, Path};

/// Whether the trajectory at `path` goes through knots.
pub fn is_spline(doc: &Value, path: &Path) -> bool {
    get(doc, &path.k("knots")).is_some()
}

/// The spline's kind: `"quintic"` (also when not given) or `"cubic"`.
pub fn spline_kind(doc: &Value, path: &Path) -> &'static str {
    match get(doc, &path.k("spline")).and_then(Value::as_str) {
        Some("cubic") => "cubic",
        _ => "quintic",
    }
}

/// Sets the spline's kind; a cubic meets no accelerations, so they are dropped from its knots
/// (and a quintic gets zero ones where a knot has none).
pub fn set_spline_kind(doc: &mut Value, path: &Path, kind: &str) {
    set(doc, &path.k("spline"), json!(kind));
    let knots = path.k("knots");
    for j in 0..len(doc, &knots) {
        let acceleration = knots.i(j).k("acceleration");
        if kind == "cubic" {
            remove(doc, &acceleration);
        } else if get(doc, &acceleration).is_none() {
            set(doc, &acceleration, json!([0.0, 0.0, 0.0]));
        }
    }
}

/// How the knot at `knot` gives its orientation: a pose name (`"pose"`) or one of the pose forms.
pub fn knot_orientation(doc: &Value, knot: &Path) -> &'static str {
    ["pose", "quaternion", "tilt_torsion", "euler_xyz_deg"].into_iter().find(|k| get(doc, &knot.k(k)).is_some()).unwrap_or("quaternion")
}

/// Adds a knot after the last one: the same pose, one second later, at rest.
pub fn add_knot(doc: &mut Value, path: &Path) {
    let knots = path.k("knots");
    let n = len(doc, &knots);
    let Some(mut knot) = get(doc, &knots.i(n.saturating_sub(1))).cloned() else { return };
    let time = knot.get("time").and_then(Value::as_f64).unwrap_or(0.0);
    knot["time"] = number(round12(time + 1.0));
    knot["velocity"] = json!([0.0, 0.0, 0.0]);
    if knot.get("acceleration").is_some() {
        knot["acceleration"] = json!([0.0, 0.0, 0.0]);
    }
    set(doc, &knots.i(n), knot);
}

/// Turns the trajectory at `path` (thesis form, valid) into a quintic spline from its start pose
/// to its end pose, at rest at both, taking its duration (2 s if untimed). False (nothing
/// changed) when the scenario does not parse.
pub fn to_spline(doc: &mut Value, path: &Path, index: usize) -> bool {
    let Ok(s) = cablenav::Scenario::from_json(&doc.to_string()) else { return false };
    let Some(traj) = s.trajectories.get(index) else { return false };
    let duration = traj.duration.unwrap_or(2.0);
    let knot = |t: f64, time: f64| {
        let p = traj.pose_at(t);
        let q = p.rotation.quaternion();
        json!({
            "time": time,
            "position": [number(p.position.x), number(p.position.y), number(p.position.z)],
            "quaternion": [number(q.w), number(q.i), number(q.j), number(q.k)],
            "velocity": [0.0, 0.0, 0.0],
            "acceleration": [0.0, 0.0, 0.0]
        })
    };
    let name = traj.name.clone();
    set(doc, path, json!({"name": name, "spline": "quintic", "knots": [knot(0.0, 0.0), knot(1.0, duration)]}));
    require_format(doc, FORMAT_4);
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_trajectory_becomes_a_spline_and_its_knots_are_edited() {
        let mut doc = super::super::test_doc();
        let path = Path::of(&["trajectories"]).i(0);
        assert!(!is_spline(&doc, &path));
        let before = cablenav::Scenario::from_json(&doc.to_string()).unwrap().trajectories[0].clone();
        assert!(to_spline(&mut doc, &path, 0));
        assert!(is_spline(&doc, &path) && spline_kind(&doc, &path) == "quintic");
        let s = cablenav::Scenario::from_json(&doc.to_string()).unwrap();
        let after = &s.trajectories[0];
        assert_eq!(after.duration, Some(2.0));
        for t in [0.0, 1.0] {
            assert!((after.pose_at(t).position - before.pose_at(t).position).norm() < 1e-12);
            assert!(after.pose_at(t).rotation.angle_to(&before.pose_at(t).rotation) < 1e-9);
        }
        add_knot(&mut doc, &path);
        assert_eq!(doc["trajectories"][0]["knots"][2]["time"].as_f64(), Some(3.0));
        assert_eq!(knot_orientation(&doc, &path.k("knots").i(2)), "quaternion");
        set_spline_kind(&mut doc, &path, "cubic");
        assert!(doc["trajectories"][0]["knots"][1].get("acceleration").is_none());
        let s = cablenav::Scenario::from_json(&doc.to_string()).unwrap();
        assert_eq!((s.trajectories[0].duration, s.trajectories[0].piece_count()), (Some(3.0), 2));
        set_spline_kind(&mut doc, &path, "quintic");
        assert_eq!(doc["trajectories"][0]["knots"][1]["acceleration"], json!([0.0, 0.0, 0.0]));
        assert!(cablenav::Scenario::from_json(&doc.to_string()).is_ok());
    }
}
