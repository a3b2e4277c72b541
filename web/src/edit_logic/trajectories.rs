//! Trajectory edits: translation forms (retyped keeping their ends), polynomial via points
//! (through the core), slerp ends as poses or quaternions, new trajectories.

use cablenav::model::via::{polynomial_through, via_count, via_points};
use serde_json::{json, Value};

use super::path::points;
use super::{core_path, fresh_name, get, len, number, point, pose_names, pose_of, round12, set, workspace_centre, Path};

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

#[cfg(test)]
mod tests {
    use super::super::test_doc as doc;
    use super::super::*;
    use super::*;
    use cablenav::Scenario;
    use serde_json::json;

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
}
