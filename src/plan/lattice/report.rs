//! What the lattice planner tells: its progress while it runs and its report once finished.

use serde::Serialize;

use super::{LatticeParams, LatticePlanner};
use crate::model::{JointPath, Trajectory};
use crate::plan::PlanStatus;
use crate::report::VerifyReport;

/// Progress of a lattice planner.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LatticePlanProgress {
    /// `lattice`, `join`, `search`, `smooth`, `verify` or `done`.
    pub stage: &'static str,
    /// Units done in this stage and the units it has in all, where known.
    pub done_units: usize,
    /// See `done_units`.
    pub total_units: Option<usize>,
    /// The status once finished.
    pub done: Option<PlanStatus>,
}

/// The lattice planner's result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LatticePlanReport {
    /// The query's name.
    pub query: String,
    /// `found` (the smoothed trajectory verifies on all of [0, 1]), `no_path` (start and goal in
    /// different components of the lattice at this resolution) or `unrepaired` (a path exists in the
    /// lattice but some section of the smoothed trajectory could not be repaired).
    pub status: PlanStatus,
    /// What the status means, in a sentence naming the resolution.
    pub message: String,
    /// The lattice's axes, by name (a multi-link robot's joint coordinates by theirs).
    pub axes: Vec<String>,
    /// Their ranges.
    pub ranges: Vec<[f64; 2]>,
    /// Grid values per axis.
    pub steps: Vec<usize>,
    /// Rays computed (lattice rays plus the start's and goal's own).
    pub rays: usize,
    /// Connected components of the lattice graph.
    pub components: usize,
    /// Segments from the start or goal to a cell corner that verified exactly / that were tried.
    pub segments: [usize; 2],
    /// Points popped by A*.
    pub expanded: usize,
    /// The A* path's points (x, y, z, φ, θ, σ; a multi-link robot's joint coordinates in the
    /// order of `joint_coordinates`), start to goal.
    pub polyline: Vec<Vec<f64>>,
    /// Its length in the planner's metric (the pose metric; joint space, one radian counted as
    /// `params.rotation_length`).
    pub polyline_length: f64,
    /// The waypoints the smoothing used (the A* path without points inside straight runs); a
    /// multi-link robot's planned path passes through them.
    pub waypoints: Vec<Vec<f64>>,
    /// A multi-link robot's joint coordinates, by name, in configuration order (empty, and not
    /// written, for a platform robot).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub joint_coordinates: Vec<String>,
    /// Pieces of the smoothed trajectory, and how many of them are single polyline edges.
    pub pieces: usize,
    /// See `pieces`.
    pub polyline_pieces: usize,
    /// Control-polygon splits and edge halvings made to repair infeasible pieces.
    pub repairs: usize,
    /// The exact verification of the whole smoothed trajectory.
    pub verification: Option<VerifyReport>,
    /// The parameters.
    pub params: LatticeParams,
    /// Wall-clock seconds, as measured by the caller.
    pub seconds: f64,
    /// The same time in milliseconds.
    pub elapsed_ms: f64,
}

impl LatticePlanner {
    /// The result once finished.
    pub fn report(&self, seconds: f64) -> Option<LatticePlanReport> {
        let status = self.status?;
        let spec = &self.lattice.spec;
        let scenario = self.lattice.scenario();
        // as `LatticeSpec::resolution`, a joint coordinate by its name
        let res = (0..spec.axes.len())
            .map(|a| {
                let [lo, hi] = spec.ranges[a];
                format!("{}: {} values over [{lo}, {hi}] (spacing {:.4})", scenario.coord_name(spec.axes[a]), spec.steps[a], spec.spacing(a))
            })
            .collect::<Vec<_>>()
            .join(", ");
        let unrepaired: Vec<String> = self
            .verification
            .iter()
            .flat_map(|r| r.infeasible.iter().chain(&r.uncertain))
            .map(|iv| format!("[{:.6}, {:.6}]", iv[0], iv[1]))
            .collect();
        let message = match status {
            PlanStatus::Found => format!("path found and verified feasible on t ∈ [0, 1] (lattice {res})"),
            PlanStatus::NoPath => format!("no path in the lattice at this resolution ({res}): start and goal are not connected in it"),
            PlanStatus::Unrepaired if self.space.is_chain() => {
                format!("a lattice path was found ({res}) but the path through its waypoints is not certified feasible on t ∈ {}", unrepaired.join(" ∪ "))
            }
            PlanStatus::Unrepaired => format!("a lattice path was found ({res}) but the smoothed trajectory could not be repaired on t ∈ {}", unrepaired.join(" ∪ ")),
            PlanStatus::Budget => format!("stopped before the end ({res})"),
        };
        let polyline_length = self.polyline.windows(2).map(|w| self.metric(&w[0], &w[1])).sum();
        Some(LatticePlanReport {
            query: self.query.clone(),
            status,
            message,
            axes: spec.axes.iter().map(|&a| scenario.coord_name(a)).collect(),
            ranges: spec.ranges.clone(),
            steps: spec.steps.clone(),
            rays: self.lattice.rays.len() + self.end_rays.len(),
            components: self.lattice.graph().map_or(0, |g| g.components),
            segments: self.segments,
            expanded: self.expanded,
            polyline: self.polyline.clone(),
            polyline_length,
            waypoints: self.waypoints.clone(),
            joint_coordinates: if self.space.is_chain() { scenario.coords().into_iter().map(|c| scenario.coord_name(c)).collect() } else { vec![] },
            pieces: self.runs.len(),
            polyline_pieces: self.runs.iter().filter(|r| r.points.len() == 2).count(),
            repairs: self.repairs,
            verification: self.verification.clone(),
            params: self.params,
            seconds,
            elapsed_ms: seconds * 1000.0,
        })
    }

    /// The smoothed trajectory, once finished with a path (a platform robot's).
    pub fn trajectory(&self) -> Option<&Trajectory> {
        self.trajectory.as_ref()
    }

    /// The path through configurations, once finished with a path (a multi-link robot's).
    pub fn joint_path(&self) -> Option<&JointPath> {
        self.joint_path.as_ref()
    }
}
