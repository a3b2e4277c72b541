//! Import of a CASPR trajectories file (`<name>_trajectories.xml`) for a platform robot: each
//! `quintic_spline_trajectory` and `cubic_spline_trajectory` of `<joint_trajectories>` becomes a
//! timed trajectory through knots (format 4 `spline` and `knots`, [`crate::model::knots`]).
//!
//! A point's `q` is read as the platform's `q_initial` is: `x y z a b g` of a 6-DoF platform
//! (position plus the parent location, R = Rx(a)·Ry(b)·Rz(g)), `x y θ` of a planar one (position
//! (x, y, 0) plus the parent location, R = Rz(θ)), `x y z` of a point mass (no orientation);
//! `q_dot` and `q_ddot` give the knot's velocity and acceleration (their translational parts:
//! CASPR refuses angular rates at a spline's knots, and so does this import). A planar platform's
//! θ may not change by half a turn or more between two points: cablenav's knots turn the shortest
//! way, CASPR's splines of θ the way the numbers go. Times are `relative` (each point's `time` counts from the previous point)
//! or `absolute`, as the element's `time_definition` says; the first point is at 0. Other kinds
//! of trajectory (linear splines, parabolic blends, operational-space trajectories) are skipped
//! with a note. [`super::model_to_json`] writes them after the bodies and cables.

use serde::Serialize;

use super::joint::{place, split_rate};
use super::xml::{child, children, document, joint_trajectories, line, numbers_n};
use crate::error::{Error, Result};
use crate::model::Mobility;

const FILE: &str = "trajectories";

/// A spline trajectory as written (format 4 `spline` and `knots`).
#[derive(Serialize)]
pub(super) struct OutSpline {
    name: String,
    spline: &'static str,
    knots: Vec<OutKnot>,
}

/// A knot as written.
#[derive(Serialize)]
struct OutKnot {
    time: f64,
    position: [f64; 3],
    /// None for a point mass.
    #[serde(skip_serializing_if = "Option::is_none")]
    euler_xyz_deg: Option<[f64; 3]>,
    velocity: [f64; 3],
    #[serde(skip_serializing_if = "Option::is_none")]
    acceleration: Option<[f64; 3]>,
}

/// The spline trajectories of `trajectories_xml` for a platform that moves as `mobility` says,
/// its joint's coordinates counting from `origin`; what is skipped goes into `notes`.
pub(super) fn splines(trajectories_xml: &str, mobility: Mobility, origin: [f64; 3], notes: &mut Vec<String>) -> Result<Vec<OutSpline>> {
    let doc = document(FILE, trajectories_xml, "trajectories")?;
    let mut out = Vec::new();
    for (node, id) in joint_trajectories(doc.root_element(), notes) {
        let spline = match node.tag_name().name() {
            "quintic_spline_trajectory" => "quintic",
            "cubic_spline_trajectory" => "cubic",
            other => {
                notes.push(format!("{}: <{other} id=\"{id}\"> skipped: cablenav takes CASPR's quintic and cubic splines", line(node)));
                continue;
            }
        };
        out.push(trajectory(node, id, spline, mobility, origin)?);
    }
    if out.is_empty() {
        notes.push("the trajectories file holds no quintic or cubic spline trajectory".to_string());
    }
    Ok(out)
}

/// One spline trajectory element.
fn trajectory(node: roxmltree::Node, id: &str, spline: &'static str, mobility: Mobility, origin: [f64; 3]) -> Result<OutSpline> {
    if id.is_empty() {
        return Err(Error::new(FILE, format!("{}: the trajectory has no id", line(node))));
    }
    let absolute = match node.attribute("time_definition").unwrap_or("relative") {
        "relative" => false,
        "absolute" => true,
        other => return Err(Error::new(FILE, format!("{}: time_definition {other:?} is neither \"relative\" nor \"absolute\"", line(node)))),
    };
    let points = child(node, "points").ok_or_else(|| Error::new(FILE, format!("{}: trajectory \"{id}\" has no <points>", line(node))))?;
    let mut knots = Vec::new();
    let mut time = 0.0;
    let mut previous_theta = 0.0;
    for (j, p) in children(points, "point").enumerate() {
        if j > 0 {
            let given: f64 = p
                .attribute("time")
                .and_then(|t| t.trim().parse().ok())
                .filter(|t: &f64| t.is_finite())
                .ok_or_else(|| Error::new(FILE, format!("{}: point {j} of \"{id}\" needs a finite time attribute", line(p))))?;
            time = if absolute { given } else { time + given };
        }
        let n = mobility.dof();
        let read = |tag: &str| -> Result<Vec<f64>> {
            match child(p, tag) {
                Some(c) => numbers_n(FILE, c, &format!("<{tag}>"), c.text().unwrap_or_default(), n),
                None if tag == "q" => Err(Error::new(FILE, format!("{}: point {j} of \"{id}\" has no <q>", line(p)))),
                None => Ok(vec![0.0; n]),
            }
        };
        let (q, qd, qdd) = (read("q")?, read("q_dot")?, read("q_ddot")?);
        let ((velocity, turning), (acceleration, turning_faster)) = (split_rate(mobility, &qd), split_rate(mobility, &qdd));
        if turning.iter().chain(turning_faster).any(|v| *v != 0.0) {
            return Err(Error::new(
                FILE,
                format!("{}: point {j} of \"{id}\" has an angular rate; CASPR's splines (and cablenav's) turn from rest to rest between knots", line(p)),
            ));
        }
        if mobility == Mobility::Planar && j > 0 {
            let turn = q[2] - previous_theta;
            if turn.abs() >= std::f64::consts::PI {
                return Err(Error::new(
                    FILE,
                    format!(
                        "{}: point {j} of \"{id}\" turns θ by {turn} rad from the point before, half a turn or more; cablenav's knots turn the shortest way (add a point between)",
                        line(p)
                    ),
                ));
            }
        }
        previous_theta = q.get(2).copied().unwrap_or_default();
        let (position, euler_rad) = place(mobility, origin, &q);
        knots.push(OutKnot {
            time,
            position,
            euler_xyz_deg: euler_rad.map(|e| e.map(f64::to_degrees)),
            velocity,
            acceleration: (spline == "quintic").then_some(acceleration),
        });
    }
    Ok(OutSpline { name: id.to_string(), spline, knots })
}
