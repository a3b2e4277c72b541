//! The thesis' smoothing and its repair: the A* waypoints as the control points of Bézier pieces,
//! each verified exactly; an infeasible piece's control polygon is split at the waypoint nearest
//! the infeasible section, down to single polyline edges, which are halved along their ray.

use super::{LatticePlanner, Stage};
use crate::model::{Orientation, Pose, Segment, Trajectory, Translation};
use crate::verify::verify_trajectory;
use nalgebra::{UnitQuaternion, Vector3};

/// Most control points of one Bézier piece (the scenario format's degree limit, 10, plus one).
const MAX_CONTROL: usize = 11;

/// A run of waypoints smoothed into one Bézier piece.
#[derive(Debug, Clone)]
pub(super) struct Run {
    pub(super) points: Vec<[f64; 6]>,
    /// How often this run's edge was halved along its ray.
    pub(super) halvings: u32,
    /// Verified feasible.
    pub(super) ok: bool,
    /// Given up: its verification's infeasible or uncertain sections stay.
    pub(super) failed: bool,
}

impl LatticePlanner {
    pub(super) fn smooth_unit(&mut self, k: usize) {
        let run = &self.runs[k];
        if run.ok || run.failed {
            self.stage = Stage::Smooth { next: k + 1 };
            return;
        }
        let traj = run_trajectory(&run.points, "piece");
        let report = verify_trajectory(self.lattice.scenario(), &traj).ok();
        let bad: Option<f64> = match &report {
            Some(r) if r.infeasible.is_empty() && r.uncertain.is_empty() => None,
            Some(r) => r.infeasible.iter().chain(&r.uncertain).map(|iv| 0.5 * (iv[0] + iv[1])).next().or(Some(0.5)),
            None => Some(0.5),
        };
        let Some(t_bad) = bad else {
            self.runs[k].ok = true;
            self.stage = Stage::Smooth { next: k + 1 };
            return;
        };
        let run = self.runs[k].clone();
        let n = run.points.len();
        if n >= 3 {
            // split the control polygon at the interior waypoint nearest the bad section
            let m = ((t_bad * (n - 1) as f64).round() as usize).clamp(1, n - 2);
            let left = Run { points: run.points[..=m].to_vec(), halvings: run.halvings, ok: false, failed: false };
            let right = Run { points: run.points[m..].to_vec(), halvings: run.halvings, ok: false, failed: false };
            self.runs.splice(k..=k, [left, right]);
            self.repairs += 1;
            return;
        }
        // a single edge: halve it where it runs along one coordinate (its slerp then approaches the ray)
        let (a, b) = (run.points[0], run.points[1]);
        let differing = (0..6).filter(|&i| a[i] != b[i]).count();
        if differing == 1 && run.halvings < self.params.max_halvings {
            let mid: [f64; 6] = std::array::from_fn(|i| 0.5 * (a[i] + b[i]));
            let h = run.halvings + 1;
            self.runs.splice(
                k..=k,
                [Run { points: vec![a, mid], halvings: h, ok: false, failed: false }, Run { points: vec![mid, b], halvings: h, ok: false, failed: false }],
            );
            self.repairs += 1;
            return;
        }
        self.runs[k].failed = true;
        self.stage = Stage::Smooth { next: k + 1 };
    }

    pub(super) fn assemble(&self) -> Trajectory {
        let pieces: Vec<Segment> = self.runs.iter().map(|r| run_segment(&r.points)).collect();
        Trajectory::piecewise(format!("{}-lattice", self.query), pieces).unwrap_or_else(|| run_trajectory(&[self.start.coords(), self.start.coords()], "empty"))
    }
}

/// The polyline without points inside straight runs (where the path goes on along the same single
/// coordinate in the same direction).
pub(super) fn turning_points(path: &[[f64; 6]]) -> Vec<[f64; 6]> {
    let dir = |a: &[f64; 6], b: &[f64; 6]| {
        let d: Vec<usize> = (0..6).filter(|&i| a[i] != b[i]).collect();
        (d.len() == 1).then(|| (d[0], (b[d[0]] - a[d[0]]).signum() as i8))
    };
    let mut out: Vec<[f64; 6]> = Vec::with_capacity(path.len());
    for (i, p) in path.iter().enumerate() {
        if i > 0 && i + 1 < path.len() {
            let (before, after) = (dir(&path[i - 1], p), dir(p, &path[i + 1]));
            if before.is_some() && before == after {
                continue;
            }
        }
        out.push(*p);
    }
    out
}

/// The thesis' smoothing: one Bézier curve with every waypoint as a control point — in runs of at
/// most [`MAX_CONTROL`] points (the format's degree limit), consecutive runs sharing a waypoint.
pub(super) fn initial_runs(waypoints: &[[f64; 6]]) -> Vec<Run> {
    let n = waypoints.len();
    if n < 2 {
        return vec![Run { points: vec![waypoints[0], waypoints[0]], halvings: 0, ok: false, failed: false }];
    }
    let chunks = (n - 1).div_ceil(MAX_CONTROL - 1);
    let per = (n - 1).div_ceil(chunks);
    let mut runs = vec![];
    let mut i = 0;
    while i + 1 < n {
        let j = (i + per).min(n - 1);
        runs.push(Run { points: waypoints[i..=j].to_vec(), halvings: 0, ok: false, failed: false });
        i = j;
    }
    runs
}

/// The piece of a run: Bézier translation through its points' positions as control points (a line
/// for two), slerp between its end rotations (the short way).
fn run_segment(points: &[[f64; 6]]) -> Segment {
    let poses: Vec<Pose> = points.iter().map(|&c| Pose::from_coords(c)).collect();
    let (first, last) = (poses[0], poses[poses.len() - 1]);
    let positions: Vec<Vector3<f64>> = poses.iter().map(|p| p.position).collect();
    let translation = if positions.len() == 2 { Translation::Line(positions[0], positions[1]) } else { Translation::Bezier(positions) };
    let qe = if first.rotation.quaternion().dot(last.rotation.quaternion()) < 0.0 { UnitQuaternion::new_unchecked(-last.rotation.into_inner()) } else { last.rotation };
    Segment { translation, orientation: Orientation::Slerp(first.rotation, qe) }
}

/// The run through `points` as a trajectory of one piece called `name`.
fn run_trajectory(points: &[[f64; 6]], name: &str) -> Trajectory {
    let seg = run_segment(points);
    Trajectory::single(name, seg.translation, seg.orientation)
}
