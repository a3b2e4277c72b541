//! The thesis' smoothing and its repair: the A* waypoints as the control points of Bézier pieces,
//! each verified exactly; an infeasible piece's control polygon is split at the waypoint nearest
//! the infeasible section, down to single polyline edges, which are halved along their ray. For a
//! multi-link robot a piece is the path through its waypoints (`space.rs`), split the same way to
//! find the leg at fault, which is reported rather than halved.

use super::space::{bezier_segment, bezier_trajectory};
use super::{LatticePlanner, Stage};
use crate::model::{JointPath, Segment, Trajectory};

/// Most control points of one Bézier piece (the scenario format's degree limit, 10, plus one).
const MAX_CONTROL: usize = 11;

/// A run of waypoints smoothed into one Bézier piece.
#[derive(Debug, Clone)]
pub(super) struct Run {
    pub(super) points: Vec<Vec<f64>>,
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
        let report = self.space.verify_run(self.lattice.scenario(), &run.points);
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
        let (a, b) = (run.points[0].clone(), run.points[1].clone());
        let differing = a.iter().zip(&b).filter(|(x, y)| x != y).count();
        if self.space.halves() && differing == 1 && run.halvings < self.params.max_halvings {
            let mid: Vec<f64> = a.iter().zip(&b).map(|(x, y)| 0.5 * (x + y)).collect();
            let h = run.halvings + 1;
            self.runs.splice(
                k..=k,
                [Run { points: vec![a, mid.clone()], halvings: h, ok: false, failed: false }, Run { points: vec![mid, b], halvings: h, ok: false, failed: false }],
            );
            self.repairs += 1;
            return;
        }
        self.runs[k].failed = true;
        self.stage = Stage::Smooth { next: k + 1 };
    }

    /// A platform robot's result: the pieces as one trajectory.
    pub(super) fn assemble(&self) -> Trajectory {
        let pieces: Vec<Segment> = self.runs.iter().map(|r| bezier_segment(&r.points)).collect();
        Trajectory::piecewise(format!("{}-lattice", self.query), pieces).unwrap_or_else(|| {
            let start = crate::model::Pose::from_coords(super::six(&self.start)).coords().to_vec();
            bezier_trajectory(&[start.clone(), start], "empty")
        })
    }

    /// A multi-link robot's result: the path through every run's waypoints (consecutive runs
    /// share one), called `QUERY-lattice`.
    pub(super) fn assemble_path(&self) -> JointPath {
        let mut through: Vec<Vec<f64>> = Vec::new();
        for r in &self.runs {
            let skip = usize::from(!through.is_empty());
            through.extend(r.points.iter().skip(skip).cloned());
        }
        if through.is_empty() {
            through.push(self.start.clone());
        }
        if through.len() == 1 {
            through.push(through[0].clone());
        }
        JointPath { name: format!("{}-lattice", self.query), through, proportional: false }
    }
}

/// The polyline without points inside straight runs (where the path goes on along the same single
/// coordinate in the same direction).
pub(super) fn turning_points(path: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let dir = |a: &[f64], b: &[f64]| {
        let d: Vec<usize> = (0..a.len()).filter(|&i| a[i] != b[i]).collect();
        (d.len() == 1).then(|| (d[0], (b[d[0]] - a[d[0]]).signum() as i8))
    };
    let mut out: Vec<Vec<f64>> = Vec::with_capacity(path.len());
    for (i, p) in path.iter().enumerate() {
        if i > 0 && i + 1 < path.len() {
            let (before, after) = (dir(&path[i - 1], p), dir(p, &path[i + 1]));
            if before.is_some() && before == after {
                continue;
            }
        }
        out.push(p.clone());
    }
    out
}

/// The thesis' smoothing: one Bézier curve with every waypoint as a control point — in runs of at
/// most [`MAX_CONTROL`] points (the format's degree limit), consecutive runs sharing a waypoint.
pub(super) fn initial_runs(waypoints: &[Vec<f64>]) -> Vec<Run> {
    let n = waypoints.len();
    if n < 2 {
        return vec![Run { points: vec![waypoints[0].clone(), waypoints[0].clone()], halvings: 0, ok: false, failed: false }];
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
