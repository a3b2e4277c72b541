//! What the lattice planner tells: its progress while it runs and its report once finished.

use serde::Serialize;

use super::{metric, LatticeParams, LatticePlanner};
use crate::model::{Pose, Trajectory};
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
    /// The lattice's axes.
    pub axes: Vec<&'static str>,
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
    /// The A* path's points (x, y, z, φ, θ, σ), start to goal.
    pub polyline: Vec<[f64; 6]>,
    /// Its length in the pose metric.
    pub polyline_length: f64,
    /// The waypoints the smoothing used (the A* path without points inside straight runs).
    pub waypoints: Vec<[f64; 6]>,
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
        let res = spec.resolution();
        let unrepaired: Vec<String> = self
            .verification
            .iter()
            .flat_map(|r| r.infeasible.iter().chain(&r.uncertain))
            .map(|iv| format!("[{:.6}, {:.6}]", iv[0], iv[1]))
            .collect();
        let message = match status {
            PlanStatus::Found => format!("path found and verified feasible on t ∈ [0, 1] (lattice {res})"),
            PlanStatus::NoPath => format!("no path in the lattice at this resolution ({res}): start and goal are not connected in it"),
            PlanStatus::Unrepaired => format!("a lattice path was found ({res}) but the smoothed trajectory could not be repaired on t ∈ {}", unrepaired.join(" ∪ ")),
            PlanStatus::Budget => format!("stopped before the end ({res})"),
        };
        let polyline_length = self.polyline.windows(2).map(|w| metric(&Pose::from_coords(w[0]), &Pose::from_coords(w[1]), self.params.rotation_length)).sum();
        Some(LatticePlanReport {
            query: self.query.clone(),
            status,
            message,
            axes: spec.axes.iter().map(|a| a.name()).collect(),
            ranges: spec.ranges.clone(),
            steps: spec.steps.clone(),
            rays: self.lattice.rays.len() + self.end_rays.len(),
            components: self.lattice.graph().map_or(0, |g| g.components),
            segments: self.segments,
            expanded: self.expanded,
            polyline: self.polyline.clone(),
            polyline_length,
            waypoints: self.waypoints.clone(),
            pieces: self.runs.len(),
            polyline_pieces: self.runs.iter().filter(|r| r.points.len() == 2).count(),
            repairs: self.repairs,
            verification: self.verification.clone(),
            params: self.params,
            seconds,
            elapsed_ms: seconds * 1000.0,
        })
    }

    /// The smoothed trajectory, once finished with a path.
    pub fn trajectory(&self) -> Option<&Trajectory> {
        self.trajectory.as_ref()
    }
}
