//! The thesis' planner (Zhang, §4.1): a ray lattice over the query's free coordinates
//! ([`crate::lattice`]); the start and goal joined to it through their own rays and, where those
//! do not reach it, by straight segments to the corners of their grid cell that verify exactly;
//! A* over the lattice's points (edge cost: the pose-metric length along the ray); a Bézier curve
//! with the A* waypoints as control points; exact verification of the result, and repair where a
//! piece is infeasible — split the control polygon at the waypoint nearest the infeasible section
//! and smooth each half, down to single polyline edges, which lie on feasible rays (an edge along
//! an angle whose slerp leaves the ray is halved along the ray). What still fails after
//! [`LatticeParams::max_halvings`] halvings is reported, never hidden. On an angle axis over a
//! whole turn the two ends of the range are one orientation: A* joins them (at cost 0), so a path
//! may cross ±π, and the polyline goes on past the range's end rather than jumping by 2π.
//!
//! The planner sees the scenario only through the lattice's rays and the trajectory verifier: it
//! never looks at a condition. [`LatticePlanner::step`] does a bounded amount of work per unit:
//! one ray, one segment verification, one A* pop, or one piece verification.
//!
//! The files follow the planner's stages: this one holds the planner and the state machine that
//! drives it; `graph.rs` numbers the search's vertices and joins the start and goal to the
//! lattice, `astar.rs` searches it, `smooth.rs` smooths the path into Bézier pieces and repairs
//! them, `report.rs` has the progress and the report.

mod astar;
mod graph;
mod report;
mod smooth;

pub use report::{LatticePlanProgress, LatticePlanReport};

use super::PlanStatus;
use crate::error::{Error, Result};
use crate::lattice::{Lattice, LatticeSpec};
use crate::model::pose::wrap_angle;
use crate::model::{Coord, Pose, Trajectory};
use crate::report::VerifyReport;
use crate::scenario::Scenario;
use crate::verify::{check_pose, verify_trajectory};
use astar::Open;
use graph::EndRay;
use serde::Serialize;
use smooth::Run;
use std::collections::{BinaryHeap, HashMap};
use std::f64::consts::PI;

/// The lattice planner's parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LatticeParams {
    /// Grid values per free coordinate (both ends of its range included), as the thesis' "steps".
    pub steps: usize,
    /// Length that one radian of rotation counts as in the pose metric (edge costs, heuristic).
    pub rotation_length: f64,
    /// How often a failing polyline edge may be halved along its ray before its section is
    /// reported as not repaired.
    pub max_halvings: u32,
}

impl Default for LatticeParams {
    /// 7 steps (the thesis' Fig. 3.9–3.10), one radian counted as one length unit, 12 halvings.
    fn default() -> LatticeParams {
        LatticeParams { steps: 7, rotation_length: 1.0, max_halvings: 12 }
    }
}

/// The default range of a free coordinate with no `region` entry: [−π, π] for angles; for
/// positions the bounding box of the base anchors (where a cable robot's workspace lies), or
/// [p − 1, p + 1] around the start if the anchors span nothing along that axis.
pub fn default_range(s: &Scenario, c: Coord, start: &[f64; 6]) -> [f64; 2] {
    if c.is_angle() {
        return [-PI, PI];
    }
    let i = c.index();
    let (lo, hi) = s.robot.cables.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), cable| (lo.min(cable.base[i]), hi.max(cable.base[i])));
    if hi > lo {
        [lo, hi]
    } else {
        [start[i] - 1.0, start[i] + 1.0]
    }
}

/// Where the planner is.
enum Stage {
    /// Computing the lattice's rays.
    Lattice,
    /// Casting the start's and goal's rays and verifying their segments to cell corners.
    Join { next: usize, segments: Vec<(usize, usize)> },
    /// A* over the points.
    Search,
    /// Verifying and repairing the smoothed pieces; `next` is the first run not yet verified.
    Smooth { next: usize },
    /// Verifying the whole assembled trajectory.
    Final,
    /// Finished.
    Done,
}

/// A resumable lattice planner for one query.
pub struct LatticePlanner {
    query: String,
    params: LatticeParams,
    start: Pose,
    goal: Pose,
    lattice: Lattice,
    /// Special points of the search: the start, the goal, or where one of their rays crosses a
    /// lattice ray between grid points (vertex number: grid points, then these).
    specials: Vec<[f64; 6]>,
    end_rays: Vec<EndRay>,
    /// Extra edges (special points and segments): from vertex to (vertex, cost).
    extra: HashMap<usize, Vec<(usize, f64)>>,
    segments: [usize; 2],
    /// The start's and goal's vertices (set when they are joined to the lattice).
    ends: [usize; 2],
    stage: Stage,
    // A*
    open: BinaryHeap<Open>,
    g: HashMap<usize, f64>,
    parent: HashMap<usize, usize>,
    expanded: usize,
    polyline: Vec<[f64; 6]>,
    waypoints: Vec<[f64; 6]>,
    runs: Vec<Run>,
    repairs: usize,
    trajectory: Option<Trajectory>,
    verification: Option<VerifyReport>,
    status: Option<PlanStatus>,
}

/// The pose-metric distance between two poses: √(|Δp|² + (L·angle)²).
fn metric(a: &Pose, b: &Pose, rotation_length: f64) -> f64 {
    (a.position - b.position).norm().hypot(rotation_length * a.rotation.angle_to(&b.rotation))
}

impl LatticePlanner {
    /// Prepares the lattice planner for scenario query `query`: the free coordinates are the ones
    /// the robot moves along (x, y, z for a point mass; x, y, σ for a planar platform) that the
    /// query does not fix, over its `region` (or [`default_range`]), with `params.steps` values
    /// each. Start and goal must be feasible, inside the region and on the same slice.
    pub fn new(scenario: &Scenario, query: &str, params: LatticeParams) -> Result<LatticePlanner> {
        let q = scenario.queries.iter().find(|q| q.name == query).ok_or_else(|| {
            let names: Vec<&str> = scenario.queries.iter().map(|q| q.name.as_str()).collect();
            let known = if names.is_empty() { "the scenario has no queries".to_string() } else { format!("known queries: {}", names.join(", ")) };
            Error::new("query", format!("no query named \"{query}\"; {known}"))
        })?;
        if !(params.rotation_length.is_finite() && params.rotation_length > 0.0) {
            return Err(Error::new("rotation_length", format!("must be a positive finite number, got {}", params.rotation_length)));
        }
        let field = format!("queries[{query}]");
        let (start, goal) = (*scenario.pose(&q.start)?, *scenario.pose(&q.goal)?);
        let (sc, mut gc) = (start.coords(), goal.coords());
        let moves = scenario.robot.mobility.coords();
        let axes: Vec<Coord> = moves.iter().copied().filter(|c| !q.fixed.contains(c)).collect();
        if axes.is_empty() {
            return Err(Error::new(format!("{field}.fixed"), "every coordinate is fixed: nothing is left to plan over"));
        }
        // The goal in the start's angle convention where its other triple (φ + π, −θ, σ) matches
        // the fixed angles better.
        let same = |c: Coord, a: f64, b: f64| if c.is_angle() { wrap_angle(a - b).abs() <= 1e-9 } else { (a - b).abs() <= 1e-9 };
        let on_slice = |g: &[f64; 6]| q.fixed.iter().all(|&c| same(c, g[c.index()], sc[c.index()]));
        if !on_slice(&gc) {
            let other = [gc[0], gc[1], gc[2], wrap_angle(gc[3] + PI), -gc[4], gc[5]];
            if on_slice(&other) {
                gc = other;
            } else {
                let differ: Vec<String> =
                    q.fixed.iter().filter(|&&c| !same(c, gc[c.index()], sc[c.index()])).map(|c| format!("{} = {} (start: {})", c.name(), gc[c.index()], sc[c.index()])).collect();
                return Err(Error::new(format!("{field}.goal"), format!("goal pose \"{}\" is not on the start's slice: {}", q.goal, differ.join(", "))));
            }
        }
        // the fixed coordinates, and those the robot does not move along (a point mass's angles;
        // a planar platform's z, and φ and θ, which leave its turn Rz(σ) as it is at θ = 0), are
        // the start's
        for c in Coord::ALL.into_iter().filter(|c| q.fixed.contains(c) || !moves.contains(c)) {
            gc[c.index()] = sc[c.index()];
        }
        let ranges: Vec<[f64; 2]> = axes.iter().map(|&c| q.region.iter().find(|(r, _)| *r == c).map_or_else(|| default_range(scenario, c, &sc), |(_, r)| *r)).collect();
        for (role, name, c) in [("start", &q.start, &sc), ("goal", &q.goal, &gc)] {
            for (a, r) in axes.iter().zip(&ranges) {
                let v = c[a.index()];
                if !(r[0] <= v && v <= r[1]) {
                    return Err(Error::new(
                        format!("{field}.region.{}", a.name()),
                        format!("the {role} pose \"{name}\" has {} = {v}, outside the lattice's range [{}, {}]", a.name(), r[0], r[1]),
                    ));
                }
            }
            let check = check_pose(scenario, name, &Pose::from_coords(*c));
            if !check.feasible {
                return Err(Error::new(format!("{field}.{role}"), format!("{role} pose \"{name}\" is infeasible: {} (see `cablenav check`)", check.violated.join(", "))));
            }
        }
        let spec = LatticeSpec::new(axes, ranges, vec![params.steps], sc).map_err(|e| match e.field.as_str() {
            "--steps" => Error::new("--steps", e.reason),
            _ => Error::new(format!("{field}.region"), e.reason),
        })?;
        let lattice = Lattice::new(scenario, spec);
        Ok(LatticePlanner {
            query: query.to_string(),
            params,
            start: Pose::from_coords(sc),
            goal: Pose::from_coords(gc),
            lattice,
            specials: vec![],
            end_rays: vec![],
            extra: HashMap::new(),
            segments: [0, 0],
            ends: [0, 0],
            stage: Stage::Lattice,
            open: BinaryHeap::new(),
            g: HashMap::new(),
            parent: HashMap::new(),
            expanded: 0,
            polyline: vec![],
            waypoints: vec![],
            runs: vec![],
            repairs: 0,
            trajectory: None,
            verification: None,
            status: None,
        })
    }

    /// The lattice (complete once the stage is past `lattice`).
    pub fn lattice(&self) -> &Lattice {
        &self.lattice
    }

    /// Advances by at most `budget` units of work (at least one) and returns the progress.
    pub fn step(&mut self, budget: usize) -> LatticePlanProgress {
        for _ in 0..budget.max(1) {
            if matches!(self.stage, Stage::Done) {
                break;
            }
            self.unit();
        }
        self.progress()
    }

    /// Where the planner is.
    pub fn progress(&self) -> LatticePlanProgress {
        let lp = self.lattice.progress();
        let (stage, done_units, total_units) = match &self.stage {
            Stage::Lattice => ("lattice", lp.rays_done, Some(lp.rays_total)),
            Stage::Join { next, segments } => ("join", *next, Some(segments.len())),
            Stage::Search => ("search", self.expanded, None),
            Stage::Smooth { next } => ("smooth", *next, Some(self.runs.len())),
            Stage::Final => ("verify", 0, Some(1)),
            Stage::Done => ("done", 1, Some(1)),
        };
        LatticePlanProgress { stage, done_units, total_units, done: self.status }
    }

    /// One unit of work.
    fn unit(&mut self) {
        match &mut self.stage {
            Stage::Lattice => {
                if self.lattice.step(1).done {
                    let segments = self.join_rays();
                    self.stage = Stage::Join { next: 0, segments };
                }
            }
            Stage::Join { next, segments } => {
                if let Some(&(special, corner)) = segments.get(*next) {
                    *next += 1;
                    self.try_segment(special, corner);
                } else {
                    self.start_search();
                }
            }
            Stage::Search => self.search_unit(),
            Stage::Smooth { next } => {
                let k = *next;
                if k >= self.runs.len() {
                    self.stage = Stage::Final;
                } else {
                    self.smooth_unit(k);
                }
            }
            Stage::Final => {
                let traj = self.assemble();
                let report = verify_trajectory(self.lattice.scenario(), &traj).ok();
                let clean = report.as_ref().is_some_and(|r| r.infeasible.is_empty() && r.uncertain.is_empty());
                self.status = Some(if clean { PlanStatus::Found } else { PlanStatus::Unrepaired });
                self.trajectory = Some(traj);
                self.verification = report;
                self.stage = Stage::Done;
            }
            Stage::Done => {}
        }
    }
}

/// The six pose coordinates of a platform robot's lattice point (the lattice planner plans for
/// platform robots only; their configurations have six coordinates).
fn six(c: &[f64]) -> [f64; 6] {
    std::array::from_fn(|i| c.get(i).copied().unwrap_or(0.0))
}
