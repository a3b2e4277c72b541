//! The points the 3-D view lets the user drag: the via points (or line ends, or Bézier control
//! points) of the selected trajectory, the poses' positions and the obstacles, and what moving
//! one of them does to the scenario's JSON tree.

use serde_json::Value;

use super::path::points;
use super::{get, len, number, point, pose_names, round12, set, set_via_points, translation_kind, via_points_of, Path};

/// What a handle moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grip {
    /// Point `k` of trajectory `t`'s translation: a via point of a polynomial (the polynomial
    /// through the via points is rewritten), an end of a line or a Bézier control point; `n` is
    /// the number of points when the drag began (a drag that makes a quadratic straight keeps
    /// its three via points).
    Trajectory { t: usize, k: usize, n: usize },
    /// The position of pose `i` (in file order).
    Pose(usize),
    /// Obstacle `i`, moved as a whole (every point of it shifted alike).
    Obstacle(usize),
}

/// A draggable point: what it moves, where it is (m, world frame) and its name for people.
#[derive(Debug, Clone, PartialEq)]
pub struct Handle {
    /// What dragging it changes.
    pub grip: Grip,
    /// Where it is now.
    pub at: [f64; 3],
    /// E.g. `via point 2 of “quadratic”`, `pose “start”`, `obstacle “crown” (sphere)`.
    pub label: String,
}

/// The keys of an obstacle's points, and whether each is a list of points.
const OBSTACLE_POINTS: [(&str, bool); 5] = [("center", false), ("apex", false), ("from", false), ("to", false), ("vertices", true)];

/// The point that stands for obstacle `o`: its centre or apex, its axis's midpoint, or its
/// vertices' mean.
fn obstacle_handle(o: &Value) -> Option<[f64; 3]> {
    let at = |k: &str| point(o, &Path::of(&[k]));
    if let Some(p) = at("center").or_else(|| at("apex")) {
        return Some(p);
    }
    if let (Some(a), Some(b)) = (at("from"), at("to")) {
        return Some(std::array::from_fn(|i| (a[i] + b[i]) / 2.0));
    }
    let v = points(o, &Path::of(&["vertices"]));
    (!v.is_empty()).then(|| std::array::from_fn(|i| v.iter().map(|p| p[i]).sum::<f64>() / v.len() as f64))
}

/// The points of trajectory `t`'s translation that its handles move (for a polynomial, at least
/// `n` via points).
fn trajectory_points(doc: &Value, t: usize, n: usize) -> Vec<[f64; 3]> {
    let path = Path::of(&["trajectories"]).i(t);
    let tr = path.k("translation");
    match translation_kind(doc, &path) {
        Some("polynomial") => via_points_of(doc, &tr.k("polynomial"), n).unwrap_or_default(),
        Some("line") => points(doc, &tr.k("line")),
        Some("bezier") => points(doc, &tr.k("bezier")),
        _ => Vec::new(),
    }
}

/// The handles of the scenario: trajectory `trajectory`'s points, every pose, every obstacle.
pub fn handles(doc: &Value, trajectory: usize) -> Vec<Handle> {
    let mut out = Vec::new();
    let tname = get(doc, &Path::of(&["trajectories"]).i(trajectory).k("name")).and_then(Value::as_str).unwrap_or("").to_string();
    let path = Path::of(&["trajectories"]).i(trajectory);
    let what = match translation_kind(doc, &path) {
        Some("polynomial") => "via point",
        Some("line") => "end",
        _ => "control point",
    };
    let pts = trajectory_points(doc, trajectory, 0);
    let n = pts.len();
    for (k, at) in pts.into_iter().enumerate() {
        out.push(Handle { grip: Grip::Trajectory { t: trajectory, k, n }, at, label: format!("{what} {} of “{tname}”", k + 1) });
    }
    for (i, name) in pose_names(doc).iter().enumerate() {
        if let Some(at) = point(doc, &Path::of(&["poses"]).i(i).k("position")) {
            out.push(Handle { grip: Grip::Pose(i), at, label: format!("pose “{name}”") });
        }
    }
    let obstacles = Path::of(&["obstacles"]);
    for i in 0..len(doc, &obstacles) {
        let Some(o) = get(doc, &obstacles.i(i)) else { continue };
        if let Some(at) = obstacle_handle(o) {
            let kind = o.get("type").and_then(Value::as_str).unwrap_or("?");
            let name = o.get("name").and_then(Value::as_str).map_or_else(|| format!("{}", i + 1), |n| format!("“{n}”"));
            out.push(Handle { grip: Grip::Obstacle(i), at, label: format!("obstacle {name} ({kind})") });
        }
    }
    out
}

fn json_point(p: [f64; 3]) -> Value {
    Value::Array(p.iter().map(|x| number(round12(*x))).collect())
}

/// Moves the handle `grip` to `to` (m, world frame; written rounded to 12 digits). The error,
/// if any, is the core's (a polynomial that cannot pass through the via points) or says what is
/// missing.
pub fn move_grip(doc: &mut Value, grip: Grip, to: [f64; 3]) -> Result<(), String> {
    match grip {
        Grip::Trajectory { t, k, n } => {
            let path = Path::of(&["trajectories"]).i(t);
            let tr = path.k("translation");
            let mut pts = trajectory_points(doc, t, n);
            let slot = pts.get_mut(k).ok_or("no such point of the trajectory")?;
            *slot = to;
            match translation_kind(doc, &path) {
                Some("polynomial") => set_via_points(doc, &tr.k("polynomial"), &pts).map_err(|e| e.to_string()),
                Some(kind) => {
                    set(doc, &tr.k(kind).i(k), json_point(to));
                    Ok(())
                }
                None => Err("the trajectory has no translation".into()),
            }
        }
        Grip::Pose(i) => {
            let p = Path::of(&["poses"]).i(i).k("position");
            get(doc, &p).ok_or("no such pose")?;
            set(doc, &p, json_point(to));
            Ok(())
        }
        Grip::Obstacle(i) => {
            let path = Path::of(&["obstacles"]).i(i);
            let from = get(doc, &path).and_then(obstacle_handle).ok_or("no such obstacle")?;
            let d: [f64; 3] = std::array::from_fn(|j| to[j] - from[j]);
            let shift = |p: [f64; 3]| json_point(std::array::from_fn(|j| p[j] + d[j]));
            for (key, list) in OBSTACLE_POINTS {
                let at = path.k(key);
                if list {
                    let moved: Vec<Value> = points(doc, &at).into_iter().map(shift).collect();
                    if !moved.is_empty() {
                        set(doc, &at, Value::Array(moved));
                    }
                } else if let Some(p) = point(doc, &at) {
                    set(doc, &at, shift(p));
                }
            }
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::*;
    use super::*;
    use crate::presets::{find, PRESETS};

    fn tree() -> Value {
        serde_json::from_str(PRESETS[find("cdpr7-tree").unwrap()].json).unwrap()
    }

    fn close(a: [f64; 3], b: [f64; 3]) -> bool {
        a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9)
    }

    #[test]
    fn handles_cover_the_trajectory_poses_and_obstacles() {
        let d = tree();
        let h = handles(&d, 1);
        let via = h.iter().filter(|x| matches!(x.grip, Grip::Trajectory { t: 1, .. })).count();
        assert!(via >= 3, "the quadratic has at least 3 via points: {h:?}");
        assert_eq!(h.iter().filter(|x| matches!(x.grip, Grip::Pose(_))).count(), pose_names(&d).len());
        assert_eq!(h.iter().filter(|x| matches!(x.grip, Grip::Obstacle(_))).count(), 3);
        assert!(h[0].label.starts_with("via point 1 of “quadratic”"), "{}", h[0].label);
    }

    #[test]
    fn a_via_point_moves_and_the_others_stay() {
        let mut d = tree();
        let before = handles(&d, 1);
        let k = 1;
        let Handle { grip, at, .. } = before[k].clone();
        let to = [at[0] + 0.2, at[1] - 0.1, at[2] + 0.05];
        move_grip(&mut d, grip, to).unwrap();
        let after = handles(&d, 1);
        assert!(close(after[k].at, to), "{:?} vs {to:?}", after[k].at);
        for j in 0..before.len() {
            if j != k && matches!(before[j].grip, Grip::Trajectory { .. }) {
                assert!(close(after[j].at, before[j].at), "via point {j} moved");
            }
        }
        // a drag that makes the curve straight keeps its three via points
        let mut line = tree();
        let h3 = handles(&line, 1);
        let (a, c) = (h3[0].at, h3[2].at);
        move_grip(&mut line, h3[1].grip, std::array::from_fn(|i| (a[i] + c[i]) / 2.0)).unwrap();
        move_grip(&mut line, h3[1].grip, [0.5, 0.5, 0.5]).unwrap();
        assert!(close(handles(&line, 1)[0].at, a) && close(handles(&line, 1)[2].at, c), "the ends stay");
        // the scenario stays valid for the core
        cablenav::Scenario::from_json(&serde_json::to_string(&d).unwrap()).unwrap();
    }

    #[test]
    fn poses_and_obstacles_move_whole() {
        let mut d = tree();
        move_grip(&mut d, Grip::Pose(0), [1.0, 2.0, 0.5]).unwrap();
        assert_eq!(point(&d, &Path::of(&["poses"]).i(0).k("position")), Some([1.0, 2.0, 0.5]));
        // the cylinder (from/to): both ends shift alike, its length is kept
        let i = (0..3).find(|&i| get(&d, &Path::of(&["obstacles"]).i(i).k("type")).and_then(Value::as_str) == Some("cylinder")).unwrap();
        let o = Path::of(&["obstacles"]).i(i);
        let (a, b) = (point(&d, &o.k("from")).unwrap(), point(&d, &o.k("to")).unwrap());
        let mid: [f64; 3] = std::array::from_fn(|j| (a[j] + b[j]) / 2.0);
        move_grip(&mut d, Grip::Obstacle(i), [mid[0] + 0.3, mid[1], mid[2] - 0.1]).unwrap();
        let (a2, b2) = (point(&d, &o.k("from")).unwrap(), point(&d, &o.k("to")).unwrap());
        assert!(close(a2, [a[0] + 0.3, a[1], a[2] - 0.1]) && close(b2, [b[0] + 0.3, b[1], b[2] - 0.1]));
        // a mesh: every vertex
        let mut m = serde_json::json!({"obstacles": [obstacle_template("mesh", [0.0, 0.0, 0.0])]});
        let h = handles(&m, 0);
        move_grip(&mut m, h[0].grip, [1.0, 1.0, 1.0]).unwrap();
        assert!(close(handles(&m, 0)[0].at, [1.0, 1.0, 1.0]));
        assert_eq!(move_grip(&mut m, Grip::Obstacle(5), [0.0; 3]), Err("no such obstacle".into()));
    }
}
