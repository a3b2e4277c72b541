//! The thesis' planner (Zhang, §4.1): a ray lattice over the query's free coordinates
//! ([`crate::lattice`]); the start and goal joined to it through their own rays and, where those
//! do not reach it, by straight segments to the corners of their grid cell that verify exactly;
//! A* over the lattice's points (edge cost: the metric length along the ray); a Bézier curve
//! with the A* waypoints as control points; exact verification of the result, and repair where a
//! piece is infeasible — split the control polygon at the waypoint nearest the infeasible section
//! and smooth each half, down to single polyline edges, which lie on feasible rays (an edge along
//! an angle whose slerp leaves the ray is halved along the ray). What still fails after
//! [`LatticeParams::max_halvings`] halvings is reported, never hidden. On an angle axis over a
//! whole turn the two ends of the range are one orientation: A* joins them (at cost 0), so a path
//! may cross ±π, and the polyline goes on past the range's end rather than jumping by 2π.
//!
//! For a multi-link robot the same planner runs over its joint coordinates (`space.rs`): the
//! lattice's rays are joint rays, the segments and pieces are paths through configurations
//! (`model::JointPath`, every joint at once with tan-half-angle timing) and the result is one
//! such path through the A* waypoints, verified exactly; a polyline of configurations needs no
//! smoothing (each leg along one coordinate is that coordinate's feasible ray piece), and a leg
//! that still fails is reported, not halved.
//!
//! The planner sees the scenario only through the lattice's rays and the trajectory verifier: it
//! never looks at a condition. [`LatticePlanner::step`] does a bounded amount of work per unit:
//! one ray, one segment verification, one A* pop, or one piece verification.
//!
//! The files follow the planner's stages: this one holds the planner and the state machine that
//! drives it; `space.rs` the steps that differ between poses and configurations, `graph.rs`
//! numbers the search's vertices and joins the start and goal to the lattice, `astar.rs` searches
//! it, `smooth.rs` smooths the path into pieces and repairs them, `report.rs` has the progress and
//! the report.

mod astar;
mod graph;
mod report;
mod smooth;
mod space;

pub use report::{LatticePlanProgress, LatticePlanReport};

use super::PlanStatus;
use crate::error::{Error, Result};
use crate::lattice::{Lattice, LatticeSpec};
use crate::model::pose::wrap_angle;
use crate::model::{Coord, JointPath, Pose, Trajectory};
use crate::report::VerifyReport;
use crate::scenario::Scenario;
use crate::verify::{check_config, check_pose, verify_along, verify_trajectory, Along};
use astar::Open;
use graph::EndRay;
use serde::Serialize;
use smooth::Run;
use space::Space;
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

/// The default range of a multi-link robot's free joint coordinate `c` with no `region` entry:
/// the joint's range, widened to take in the start's and goal's values `s` and `g` where they lie
/// outside it (a configuration may, with a warning); an end the joint leaves unbounded (a
/// prismatic or free joint's length) lies 1 length unit beyond the farther of start and goal.
pub fn joint_default_range(scenario: &Scenario, c: Coord, s: f64, g: f64) -> [f64; 2] {
    let range = scenario.robot.chain.as_ref().and_then(|chain| chain.coords().nth(c.index()).map(|(_, _, jc)| jc.range)).unwrap_or([f64::NEG_INFINITY, f64::INFINITY]);
    let (lo, hi) = (s.min(g), s.max(g));
    [if range[0].is_finite() { range[0].min(lo) } else { lo - 1.0 }, if range[1].is_finite() { range[1].max(hi) } else { hi + 1.0 }]
}

/// A resumable lattice planner for one query.
pub struct LatticePlanner {
    query: String,
    params: LatticeParams,
    /// Poses or joint configurations.
    space: Space,
    /// The start's and goal's coordinates (x, y, z, φ, θ, σ, or the joint coordinates), the goal
    /// on the start's slice.
    start: Vec<f64>,
    goal: Vec<f64>,
    lattice: Lattice,
    /// Special points of the search: the start, the goal, or where one of their rays crosses a
    /// lattice ray between grid points (vertex number: grid points, then these).
    specials: Vec<Vec<f64>>,
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
    polyline: Vec<Vec<f64>>,
    waypoints: Vec<Vec<f64>>,
    runs: Vec<Run>,
    repairs: usize,
    /// The result: a platform robot's trajectory, or a multi-link robot's path.
    trajectory: Option<Trajectory>,
    joint_path: Option<JointPath>,
    verification: Option<VerifyReport>,
    status: Option<PlanStatus>,
}

impl LatticePlanner {
    /// Prepares the lattice planner for scenario query `query`: the free coordinates are the ones
    /// the robot moves along (x, y, z for a point mass; x, y, σ for a planar platform; a
    /// multi-link robot's joint coordinates) that the query does not fix, over its `region` (or
    /// [`default_range`], [`joint_default_range`]), with `params.steps` values each. Start and
    /// goal must be feasible, inside the region and on the same slice.
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
        let space = Space::of(scenario);
        let what = if space.is_chain() { "configuration" } else { "pose" };
        let (sc, mut gc): (Vec<f64>, Vec<f64>) = match space {
            Space::Platform => (scenario.pose(&q.start)?.coords().to_vec(), scenario.pose(&q.goal)?.coords().to_vec()),
            Space::Chain { .. } => (scenario.config(&q.start)?, scenario.config(&q.goal)?),
        };
        let moves = scenario.coords();
        let axes: Vec<Coord> = moves.iter().copied().filter(|c| !q.fixed.contains(c)).collect();
        if axes.is_empty() {
            return Err(Error::new(format!("{field}.fixed"), "every coordinate is fixed: nothing is left to plan over"));
        }
        // The goal in the start's angle convention where its other triple (φ + π, −θ, σ) matches
        // the fixed angles better (a pose's).
        let same = |c: Coord, a: f64, b: f64| if c.is_angle() { wrap_angle(a - b).abs() <= 1e-9 } else { (a - b).abs() <= 1e-9 };
        let on_slice = |g: &[f64]| q.fixed.iter().all(|&c| same(c, g[c.index()], sc[c.index()]));
        if !on_slice(&gc) {
            let other = (!space.is_chain()).then(|| vec![gc[0], gc[1], gc[2], wrap_angle(gc[3] + PI), -gc[4], gc[5]]);
            match other.filter(|o| on_slice(o)) {
                Some(o) => gc = o,
                None => {
                    let differ: Vec<String> = q
                        .fixed
                        .iter()
                        .filter(|&&c| !same(c, gc[c.index()], sc[c.index()]))
                        .map(|&c| format!("{} = {} (start: {})", scenario.coord_name(c), gc[c.index()], sc[c.index()]))
                        .collect();
                    return Err(Error::new(format!("{field}.goal"), format!("goal {what} \"{}\" is not on the start's slice: {}", q.goal, differ.join(", "))));
                }
            }
        }
        // the fixed coordinates, and those the robot does not move along (a point mass's angles;
        // a planar platform's z, and φ and θ, which leave its turn Rz(σ) as it is at θ = 0), are
        // the start's
        for i in 0..sc.len() {
            let c = scenario.coord_at(i);
            if q.fixed.contains(&c) || !moves.contains(&c) {
                gc[i] = sc[i];
            }
        }
        let ranges: Vec<[f64; 2]> = axes
            .iter()
            .map(|&c| {
                q.region.iter().find(|(r, _)| *r == c).map_or_else(
                    || match space {
                        Space::Platform => default_range(scenario, c, &six(&sc)),
                        Space::Chain { .. } => joint_default_range(scenario, c, sc[c.index()], gc[c.index()]),
                    },
                    |(_, r)| *r,
                )
            })
            .collect();
        for (role, name, c) in [("start", &q.start, &sc), ("goal", &q.goal, &gc)] {
            for (a, r) in axes.iter().zip(&ranges) {
                let v = c[a.index()];
                if !(r[0] <= v && v <= r[1]) {
                    let coord = scenario.coord_name(*a);
                    return Err(Error::new(format!("{field}.region.{coord}"), format!("the {role} {what} \"{name}\" has {coord} = {v}, outside the lattice's range [{}, {}]", r[0], r[1])));
                }
            }
            let check = match space {
                Space::Platform => check_pose(scenario, name, &Pose::from_coords(six(c))),
                Space::Chain { .. } => check_config(scenario, name, c),
            };
            if !check.feasible {
                return Err(Error::new(format!("{field}.{role}"), format!("{role} {what} \"{name}\" is infeasible: {} (see `cablenav check`)", check.violated.join(", "))));
            }
        }
        let spec = LatticeSpec::new(axes, ranges, vec![params.steps], sc.clone()).map_err(|e| match e.field.as_str() {
            "--steps" => Error::new("--steps", e.reason),
            _ => Error::new(format!("{field}.region"), e.reason),
        })?;
        let lattice = Lattice::new(scenario, spec);
        Ok(LatticePlanner {
            query: query.to_string(),
            params,
            space,
            start: sc,
            goal: gc,
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
            joint_path: None,
            verification: None,
            status: None,
        })
    }

    /// The metric of edge costs and the heuristic ([`Space::metric`]).
    fn metric(&self, a: &[f64], b: &[f64]) -> f64 {
        self.space.metric(a, b, self.params.rotation_length)
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
                // the whole result verified exactly: only what the verifier certifies is `found`
                let scenario = self.lattice.scenario();
                let report = if self.space.is_chain() {
                    let path = self.assemble_path();
                    let report = verify_along(scenario, Along::Joints(&path)).ok();
                    self.joint_path = Some(path);
                    report
                } else {
                    let traj = self.assemble();
                    let report = verify_trajectory(scenario, &traj).ok();
                    self.trajectory = Some(traj);
                    report
                };
                let clean = report.as_ref().is_some_and(|r| r.infeasible.is_empty() && r.uncertain.is_empty());
                self.status = Some(if clean { PlanStatus::Found } else { PlanStatus::Unrepaired });
                self.verification = report;
                self.stage = Stage::Done;
            }
            Stage::Done => {}
        }
    }
}

/// The six pose coordinates of a platform robot's lattice point (its configurations have six
/// coordinates).
fn six(c: &[f64]) -> [f64; 6] {
    std::array::from_fn(|i| c.get(i).copied().unwrap_or(0.0))
}
