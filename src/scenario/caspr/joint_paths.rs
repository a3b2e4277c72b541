//! Import of a CASPR trajectories file (`<name>_trajectories.xml`) for a multi-link robot: each
//! spline trajectory of `<joint_trajectories>` (quintic, cubic or linear) whose points all have
//! zero velocity and acceleration (`q_dot`, `q_ddot` absent or zero) becomes a path through its
//! points as configurations `ID-0`, `ID-1`, … with every joint moving in proportion
//! (`"joints": "proportional"`, format 6): CASPR's splines then run along exactly that path —
//! each coordinate from value to value, a ball joint by its shortest rotation — their timing
//! aside (a multi-link robot's path is verified at rest, so its knots' times are not kept). A
//! trajectory whose knots move (CASPR's spline then curves between them), another kind of
//! trajectory, or one with a leg that has no rational form (turning angles not in small integer
//! ratios: [`crate::model::proportional`]) is skipped with a note.

use std::collections::BTreeMap;

use serde::Serialize;

use super::xml::{child, children, document, joint_trajectories, line, numbers_n};
use crate::error::{Error, Result};

const FILE: &str = "trajectories";

/// A path through configurations as written (format 6 `through` and `joints`).
#[derive(Serialize)]
pub(super) struct OutJointPath {
    pub(super) name: String,
    pub(super) through: Vec<String>,
    joints: &'static str,
}

/// The paths of `trajectories_xml` for a robot with coordinates `names` (in configuration
/// order), and the configurations they pass through; what is skipped goes into `notes`.
pub(super) fn joint_paths(trajectories_xml: &str, names: &[String], notes: &mut Vec<String>) -> Result<(Vec<OutJointPath>, Vec<(String, BTreeMap<String, f64>)>)> {
    let doc = document(FILE, trajectories_xml, "trajectories")?;
    let (mut paths, mut configs) = (Vec::new(), Vec::new());
    for (node, id) in joint_trajectories(doc.root_element(), notes) {
        let kind = node.tag_name().name();
        if !["quintic_spline_trajectory", "cubic_spline_trajectory", "linear_spline_trajectory"].contains(&kind) {
            notes.push(format!("{}: <{kind} id=\"{id}\"> skipped: cablenav takes CASPR's quintic, cubic and linear splines", line(node)));
            continue;
        }
        if id.is_empty() {
            return Err(Error::new(FILE, format!("{}: the trajectory has no id", line(node))));
        }
        let points = child(node, "points").ok_or_else(|| Error::new(FILE, format!("{}: trajectory \"{id}\" has no <points>", line(node))))?;
        let mut through = Vec::new();
        let mut moving = None;
        for (j, p) in children(points, "point").enumerate() {
            let read = |tag: &str| child(p, tag).map(|c| numbers_n(FILE, c, &format!("<{tag}> of point {j} of \"{id}\""), c.text().unwrap_or_default(), names.len())).transpose();
            let q = read("q")?.ok_or_else(|| Error::new(FILE, format!("{}: point {j} of \"{id}\" has no <q>", line(p))))?;
            if [read("q_dot")?, read("q_ddot")?].iter().flatten().any(|v| v.iter().any(|x| *x != 0.0)) {
                moving.get_or_insert(j);
            }
            let config = format!("{id}-{j}");
            configs.push((config.clone(), names.iter().cloned().zip(q).collect()));
            through.push(config);
        }
        if let Some(j) = moving {
            configs.retain(|(c, _)| !through.contains(c));
            notes.push(format!(
                "trajectory \"{id}\" skipped: point {j} moves (its q_dot or q_ddot is not zero), so CASPR's spline curves between its points; \
                 cablenav verifies the straight joint path of points at rest"
            ));
            continue;
        }
        if through.len() < 2 {
            configs.retain(|(c, _)| !through.contains(c));
            notes.push(format!("trajectory \"{id}\" skipped: it has {} point(s)", through.len()));
            continue;
        }
        paths.push(OutJointPath { name: id.to_string(), through, joints: "proportional" });
    }
    if paths.is_empty() {
        notes.push("the trajectories file holds no joint-space spline trajectory with its points at rest".to_string());
    }
    Ok((paths, configs))
}
