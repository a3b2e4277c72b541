//! Path planning on the wrench-feasible C-space of a 6-cable robot (Bohigas et al., "Navigating
//! the wrench-feasible C-space of cable-driven hexapods"): the C-space, or a slice of it with some
//! of (x, y, z, φ, θ, σ) fixed, is a smooth manifold ([`manifold`]); an atlas of it is grown by
//! Henderson's continuation ([`atlas`], [`chart`]) under an A* search ([`search`]) until the goal
//! is reached (`found`), the start's component is exhausted (`no_path`, at the stated
//! resolution), or the chart budget runs out (`budget`). Every path found is re-verified edge by
//! edge by the exact verifier. By default the charts' radii adapt to the manifold's curvature
//! (between 0.1 and 1) and the search weights its heuristic by 1.5, which finds the full 6-D
//! Robocrane query in seconds; [`PlanParams`] with `min_radius = radius = 0.4` and
//! `heuristic_weight = 1` is paper 1's and CuikSuite's setting. docs/planner.md has the
//! formulation and the guarantees.
//!
//! [`AtlasPlanner`] is resumable ([`AtlasPlanner::step`]) so the page can drive it between frames;
//! [`plan`] runs it to the end. Nothing here reads a clock: time budgets are the caller's.

// The planner is named after the atlas it grows, which keeps its own name (Henderson's).
#[allow(clippy::module_inception)]
pub mod atlas;
pub mod chart;
pub mod file;
pub mod manifold;
pub mod search;
pub mod view;

use super::{edge_trajectory, PlanStatus};
use crate::error::{Error, Result};
use crate::model::pose::wrap_angle;
use crate::model::{Coord, Pose};
use crate::report::VerifyReport;
use crate::scenario::Scenario;
use crate::verify::{verify_trajectory, wrench_at};
use atlas::AtlasParams;
use manifold::{CableManifold, Manifold};
use search::{Continuation, Ended};
use serde::Serialize;
use std::f64::consts::PI;

/// The planner's parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, serde::Deserialize)]
pub struct PlanParams {
    /// Largest chart radius r, in tangent coordinates of the manifold (pose coordinates and
    /// auxiliaries): the start chart's radius and the most any chart gets.
    pub radius: f64,
    /// Smallest radius the curvature adaptation gives a chart (each new chart's radius is the step
    /// at which its parent's tangent approximation error would reach half of ε, see
    /// docs/planner.md); `min_radius ≥ radius` turns the adaptation off (every chart has radius
    /// r, as in CuikSuite).
    pub min_radius: f64,
    /// Chart validity threshold ε: a new chart's centre must be within ε of its parent's tangent
    /// space, and |det(Ψ_iᵀΨ_j)| ≥ 1 − ε.
    pub epsilon: f64,
    /// Largest step δ between consecutive path poses, in the pose metric.
    pub delta: f64,
    /// Most charts the atlas may have before the search stops with `budget`.
    pub max_charts: usize,
    /// Weight w of the heuristic in the search's f = g + w·h: 1 is paper 1's A*; above 1 the
    /// search heads more directly for the goal (far fewer charts in 6-D) and its chart path may
    /// be up to w times longer. `no_path` still means the start's component was exhausted.
    pub heuristic_weight: f64,
    /// Barrier scale κ of the auxiliaries w = −κ ln μ (μ: a bound's normalised margin).
    pub barrier: f64,
    /// Least normalised margin μ the atlas explores: charts with some μ below it are not expanded
    /// (the auxiliary bound w ≤ −κ ln min_margin).
    pub min_margin: f64,
    /// Length that one radian of rotation counts as in the pose metric (path length, heuristic).
    pub rotation_length: f64,
    /// Treat angle coordinates as angles: differences wrapped to (−π, π] and the goal accepted in
    /// both tilt-and-torsion triples of its rotation. Off: the angles are plain coordinates, as in
    /// paper 1 (only for comparing with it: the atlas of a component that winds around an angle
    /// then never ends).
    pub identify_angles: bool,
}

impl Default for PlanParams {
    /// Chart radii adapted between 0.1 and 1, ε = 0.4, δ = 0.04 (CuikSuite's), 100 000 charts,
    /// heuristic weight 1.5, κ = 0.1, μ ≥ 1e-3, one radian counted as one length unit, angles
    /// identified.
    fn default() -> PlanParams {
        PlanParams { radius: 1.0, min_radius: 0.1, epsilon: 0.4, delta: 0.04, max_charts: 100_000, heuristic_weight: 1.5, barrier: 0.1, min_margin: 1e-3, rotation_length: 1.0, identify_angles: true }
    }
}

impl PlanParams {
    /// Checks every parameter, naming the first bad one.
    pub fn validate(&self) -> Result<()> {
        let positive = |field: &str, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(Error::new(field, format!("must be a positive finite number, got {v}")))
            }
        };
        positive("radius", self.radius)?;
        positive("min_radius", self.min_radius)?;
        positive("epsilon", self.epsilon)?;
        positive("delta", self.delta)?;
        positive("barrier", self.barrier)?;
        positive("rotation_length", self.rotation_length)?;
        if !(self.heuristic_weight.is_finite() && self.heuristic_weight >= 1.0) {
            return Err(Error::new("heuristic_weight", format!("must be a finite number ≥ 1 (1 is A*), got {}", self.heuristic_weight)));
        }
        if self.epsilon >= 1.0 {
            return Err(Error::new("epsilon", format!("must be below 1 (the tangent test is |det| ≥ 1 − ε), got {}", self.epsilon)));
        }
        if !(self.min_margin > 0.0 && self.min_margin < 1.0) {
            return Err(Error::new("min_margin", format!("must be in (0, 1), got {}", self.min_margin)));
        }
        if self.max_charts == 0 || self.max_charts > 10_000_000 {
            return Err(Error::new("max_charts", format!("must be between 1 and 10000000, got {}", self.max_charts)));
        }
        if self.delta > self.radius {
            return Err(Error::new("delta", format!("must not exceed the radius {}, got {}", self.radius, self.delta)));
        }
        Ok(())
    }
}

/// Progress of a running atlas planner.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AtlasProgress {
    /// Charts in the atlas so far.
    pub charts: usize,
    /// A* open-list size.
    pub open: usize,
    /// Least h over the open list (pose-metric distance to the goal).
    pub best_heuristic: f64,
    /// The status once finished (the search ended and its path was re-verified).
    pub done: Option<PlanStatus>,
    /// While the found path is being re-verified: (edges verified, edges in all).
    pub verifying: Option<(usize, usize)>,
}

/// Work a planner has done so far, in units that do not depend on the machine: what bounds the
/// cost of one [`AtlasPlanner::step`] unit (docs/planner.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct PlanWork {
    /// Manifold evaluations (F and its Jacobian: Newton iterations and tangent bases).
    pub evaluations: usize,
    /// Exact-verifier calls on trajectories: the motion validator on dense-path steps during the
    /// search, then the re-verification of the path's edges (steps and edges found clean by an
    /// earlier query on a kept atlas are not checked again).
    pub trajectory_checks: usize,
    /// Per-pose wrench tests of the path's poses.
    pub pose_checks: usize,
}

/// The exact verifier's re-check of a path, edge by edge (slerp + linear translation between
/// consecutive poses), and the per-pose wrench check of every path pose.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PathVerification {
    /// Edges verified (path poses − 1).
    pub edges: usize,
    /// Of those, the edges that are steps of the dense path the motion validator verified
    /// exactly during the search — the same verification of every condition along the same
    /// slerp + line, so not run again (0 from [`verify_path`]).
    pub edges_validated: usize,
    /// Infeasible sections found along the edges (interference, cable lengths) — 0 for a good
    /// path.
    pub infeasible_sections: usize,
    /// Sections the exact verifier could not certify either way.
    pub uncertain_sections: usize,
    /// Path poses checked for wrench feasibility (every pose).
    pub wrench_poses: usize,
    /// Path poses found wrench-infeasible — 0 for a good path.
    pub wrench_infeasible_poses: usize,
    /// Least wrench margin (tension, force units) over the path poses.
    pub least_wrench_margin: Option<f64>,
    /// The verifier's reports of the edges with an infeasible or uncertain section, by edge index.
    pub failed_edges: Vec<(usize, VerifyReport)>,
    /// What the verification does and does not cover.
    pub notes: Vec<String>,
}

/// What the atlas looked like at the end, and what a `no_path` claim rests on.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AtlasSummary {
    /// The manifold's dimension (free coordinates).
    pub dimension: usize,
    /// Expansion directions where no valid chart could be made (0 for a certified `no_path`).
    pub expansion_failures: usize,
    /// Chart pairs dropped from the search because their dense edge could not be followed, and
    /// walks from a goal's chart to the goal that could not be followed (numerical failures, a
    /// walk's projection cap included: 0 for a certified `no_path`).
    pub broken_edges: usize,
    /// Chart pairs dropped because the exact verifier rejected a step of their dense edge.
    pub rejected_edges: usize,
    /// Charts whose centre violates a clearance (never expanded nor entered).
    pub blocked_charts: usize,
    /// The least and the greatest radius of the charts that are not blocked (the curvature
    /// adaptation's range on this atlas).
    pub chart_radii: [f64; 2],
    /// Charts the atlas already had when this query began (an atlas kept from earlier queries on
    /// the same slice, [`AtlasPlanner::requery`]; 0 for a fresh one).
    pub reused_charts: usize,
    /// The parameters used.
    pub params: PlanParams,
}

/// The result of planning.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanOutcome {
    /// How it ended.
    pub status: PlanStatus,
    /// The path (when found): dense poses, each consecutive pair at most δ apart in the pose
    /// metric; the first is exactly the query's start pose and the last exactly its goal pose.
    pub path: Vec<Pose>,
    /// Charts in the atlas.
    pub charts: usize,
    /// The atlas's dimension, failures, dropped edges, blocked charts and parameters.
    pub atlas: AtlasSummary,
    /// The re-verification of the path (empty for no path).
    pub verification: PathVerification,
    /// The atlas drawn in the slice's coordinates, with the path's charts.
    pub view: view::AtlasView,
}

/// One path pose as the CLI and the page print it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PathPose {
    /// Position.
    pub position: [f64; 3],
    /// Orientation, [w, x, y, z].
    pub quaternion: [f64; 4],
    /// Tilt-and-torsion angles (φ, θ, σ), radians.
    pub tilt_torsion: [f64; 3],
}

/// The serialisable report of a planning run (`cablenav plan --json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlanReport {
    /// The query's name.
    pub query: String,
    /// `found`, `no_path` or `budget`.
    pub status: PlanStatus,
    /// The path's poses.
    pub path: Vec<PathPose>,
    /// Charts in the atlas.
    pub charts: usize,
    /// Wall-clock seconds, as measured by the caller.
    pub seconds: f64,
    /// The same time in milliseconds.
    pub elapsed_ms: f64,
    /// The atlas summary (its fields appear at the top level of the JSON).
    #[serde(flatten)]
    pub atlas: AtlasSummary,
    /// The exact re-verification of the path.
    pub verification: PathVerification,
    /// The charts in the slice's coordinates: centres, radii, states, polygons (2-D slice) or
    /// polytope faces (3-D), the path's charts.
    pub atlas_charts: view::AtlasView,
}

impl PlanOutcome {
    /// The serialisable report, with the wall-clock time the caller measured.
    pub fn report(&self, query: &str, seconds: f64) -> PlanReport {
        PlanReport {
            query: query.to_string(),
            status: self.status,
            path: self
                .path
                .iter()
                .map(|p| PathPose { position: [p.position.x, p.position.y, p.position.z], quaternion: p.quaternion(), tilt_torsion: p.tilt_torsion() })
                .collect(),
            charts: self.charts,
            seconds,
            elapsed_ms: seconds * 1000.0,
            atlas: self.atlas.clone(),
            verification: self.verification.clone(),
            atlas_charts: self.view.clone(),
        }
    }
}

/// A resumable planner for one query of a scenario. Owns everything it needs.
pub struct AtlasPlanner {
    scenario: Scenario,
    start: Pose,
    goal: Pose,
    params: PlanParams,
    /// The slice: the fixed coordinates' values (`None` for a free one).
    fixed: [Option<f64>; 6],
    /// Charts the atlas had when the current query began.
    reused: usize,
    /// Path edges the exact verifier was run on, over all queries.
    verified_edges: usize,
    /// Path poses checked by the queries before the current one.
    checked_poses: usize,
    search: Continuation<CableManifold>,
    /// Once the search has ended: its path, re-verified edge by edge by later `step` calls.
    check: Option<PathCheck>,
}

/// A finished search's path and its re-verification so far.
#[derive(Debug, Clone)]
struct PathCheck {
    status: PlanStatus,
    path: Vec<Pose>,
    /// The path's points of the manifold (the poses but the first and last are theirs).
    points: Vec<Vec<f64>>,
    verification: PathVerification,
    /// Edges verified so far (with their end poses; pose 0 with edge 0).
    next: usize,
    /// Whether every edge and pose has been checked.
    finished: bool,
}

/// The coordinates of `pose` equivalent to `q` under (φ, θ, σ) ~ (φ + π, −θ, σ): the two
/// tilt-and-torsion triples of one rotation.
fn equivalent_coords(q: [f64; 6]) -> [[f64; 6]; 2] {
    let mut other = q;
    other[3] = wrap_angle(q[3] + PI);
    other[4] = -q[4];
    [q, other]
}

/// Whether two values of coordinate `c` agree (angles modulo 2π).
fn same_value(c: Coord, a: f64, b: f64) -> bool {
    let d = if c.is_angle() { wrap_angle(a - b) } else { a - b };
    d.abs() <= 1e-9
}

/// Whether two slices (each fixed coordinate's value, `None` for a free one) are the same.
fn same_slice(a: &[Option<f64>; 6], b: &[Option<f64>; 6]) -> bool {
    a.iter().zip(b).enumerate().all(|(c, (a, b))| match (a, b) {
        (Some(a), Some(b)) => same_value(Coord::ALL[c], *a, *b),
        (None, None) => true,
        _ => false,
    })
}

/// The two ends of a planning problem, as [`AtlasPlanner`]'s constructors resolve them.
struct Ends {
    /// Prefix of error fields (`queries[q1-q2]`).
    field: String,
    /// Names of the start and goal poses, for messages.
    names: [String; 2],
    /// The exact start and goal poses the path begins and ends with.
    poses: [Pose; 2],
    /// Their coordinates (x, y, z, φ, θ, σ).
    coords: [[f64; 6]; 2],
    /// The fixed coordinates, held at the start's values.
    fixed: Vec<Coord>,
}

/// The ends of scenario query `query`: its poses, and their coordinates — the canonical angles
/// of their rotations, or with the angles as plain coordinates (`identify_angles` off) the
/// angles as the scenario file writes them, as paper 1 poses its queries.
fn query_ends(scenario: &Scenario, query: &str, params: PlanParams) -> Result<Ends> {
    let q = scenario.queries.iter().find(|q| q.name == query).ok_or_else(|| {
        let names: Vec<&str> = scenario.queries.iter().map(|q| q.name.as_str()).collect();
        let known = if names.is_empty() { "the scenario has no queries".to_string() } else { format!("known queries: {}", names.join(", ")) };
        Error::new("query", format!("no query named \"{query}\"; {known}"))
    })?;
    let (start, goal) = (*scenario.pose(&q.start)?, *scenario.pose(&q.goal)?);
    let coords = |name: &str, pose: &Pose| if params.identify_angles { Ok(pose.coords()) } else { scenario.written_coords(name) };
    let coords = [coords(&q.start, &start)?, coords(&q.goal, &goal)?];
    Ok(Ends { field: format!("queries[{query}]"), names: [q.start.clone(), q.goal.clone()], poses: [start, goal], coords, fixed: q.fixed.clone() })
}

/// The ends of a planning problem between two poses given by their coordinates.
fn coords_ends(start: [f64; 6], goal: [f64; 6], fixed: &[Coord]) -> Result<Ends> {
    for (role, c) in [("start", &start), ("goal", &goal)] {
        if let Some(bad) = c.iter().position(|v| !v.is_finite()) {
            return Err(Error::new(format!("{role}[{bad}]"), format!("must be a finite number, got {}", c[bad])));
        }
    }
    Ok(Ends { field: "coords".to_string(), names: ["start".to_string(), "goal".to_string()], poses: [Pose::from_coords(start), Pose::from_coords(goal)], coords: [start, goal], fixed: fixed.to_vec() })
}

/// A slice (each coordinate's fixed value, `None` where free) and the goal's coordinates on it.
type SliceEnds = ([Option<f64>; 6], Vec<[f64; 6]>);

/// The slice the ends lie on — each fixed coordinate at the start's value — and the goal's
/// coordinates on it (either tilt-and-torsion triple of its rotation when angles are identified).
fn slice(ends: &Ends, params: PlanParams) -> Result<SliceEnds> {
    let Ends { field, names, coords: [start_coords, goal_coords], fixed: fixed_coords, .. } = ends;
    if fixed_coords.len() >= 6 {
        return Err(Error::new(format!("{field}.fixed"), "every coordinate is fixed: nothing is left to plan over"));
    }
    let mut fixed = [None; 6];
    for c in fixed_coords.iter() {
        fixed[c.index()] = Some(start_coords[c.index()]);
    }
    let goal_copies = on_slice(*goal_coords, fixed_coords, start_coords, params.identify_angles);
    if goal_copies.is_empty() {
        let g = goal_coords;
        let differ: Vec<String> = fixed_coords
            .iter()
            .filter(|&&c| !same_value(c, g[c.index()], start_coords[c.index()]))
            .map(|c| format!("{} = {} (start: {})", c.name(), g[c.index()], start_coords[c.index()]))
            .collect();
        return Err(Error::new(format!("{field}.goal"), format!("goal pose \"{}\" is not on the start's slice: {}", names[1], differ.join(", "))));
    }
    Ok((fixed, goal_copies))
}

/// The coordinates `q` stands for — itself, and with `identify_angles` also the other
/// tilt-and-torsion triple of its rotation — that lie on the slice through `start` with
/// `fixed_coords` fixed.
fn on_slice(q: [f64; 6], fixed_coords: &[Coord], start: &[f64; 6], identify_angles: bool) -> Vec<[f64; 6]> {
    let candidates = if identify_angles { equivalent_coords(q).to_vec() } else { vec![q] };
    candidates.into_iter().filter(|g| fixed_coords.iter().all(|&c| same_value(c, g[c.index()], start[c.index()]))).collect()
}

/// The start's point of the manifold and the goal copies' points, each checked: wrench-feasible,
/// within the auxiliary bound, no clearance violated.
fn lift_ends(manifold: &CableManifold, ends: &Ends, goal_copies: &[[f64; 6]], params: PlanParams) -> Result<(Vec<f64>, Vec<Vec<f64>>)> {
    let field = &ends.field;
    let lift = |name: &str, role: &str, coords: &[f64; 6]| {
        let x = manifold.lift(coords).map_err(|why| Error::new(format!("{field}.{role}"), format!("{role} pose \"{name}\" is not wrench-feasible: {why}")))?;
        if !manifold.within_bounds(&x) {
            let (mu, label) = manifold.tightest(&x);
            return Err(Error::new(
                format!("{field}.{role}"),
                format!("{role} pose \"{name}\" is closer to the feasibility boundary than min_margin = {} allows ({label}: normalised margin {mu:.3e})", params.min_margin),
            ));
        }
        if !manifold.admissible(&x) {
            return Err(Error::new(format!("{field}.{role}"), format!("{role} pose \"{name}\" violates a clearance (see `cablenav check`)")));
        }
        Ok(x)
    };
    let start = lift(&ends.names[0], "start", &ends.coords[0])?;
    let goals = goal_copies.iter().map(|g| lift(&ends.names[1], "goal", g)).collect::<Result<Vec<_>>>()?;
    Ok((start, goals))
}

impl AtlasPlanner {
    /// Prepares planning for scenario query `query` (its name in `scenario.queries`): checks the
    /// parameters, that start and goal are wrench-feasible, non-singular, interference-free and
    /// on the same slice, and builds the first chart.
    pub fn new(scenario: &Scenario, query: &str, params: PlanParams) -> Result<AtlasPlanner> {
        params.validate()?;
        AtlasPlanner::build(scenario, query_ends(scenario, query, params)?, params)
    }

    /// Plans query `query` of `scenario` next, on the atlas built so far, when the scenario has
    /// the same robot, wrench set, obstacles and clearances (its poses and queries may differ: a
    /// user picking new start and goal poses) and the query lies on the same slice (the same
    /// coordinates fixed, at the same values): the search starts again from the new start,
    /// through the charts already made, and the atlas grows only where it must. `Ok(false)`, with
    /// nothing changed, when the atlas does not carry over (build a fresh planner); an error, as
    /// [`AtlasPlanner::new`]'s, when the query's start or goal is unusable.
    pub fn requery(&mut self, scenario: &Scenario, query: &str) -> Result<bool> {
        if !self.scenario.same_space(scenario) {
            return Ok(false);
        }
        let kept = self.retarget(query_ends(scenario, query, self.params)?)?;
        if kept {
            self.scenario = scenario.clone();
        }
        Ok(kept)
    }

    /// Prepares planning for scenario query `query` from an atlas file (`file::save`'s text, from
    /// [`AtlasPlanner::save_atlas`]): when the query lies on the file's slice, the search runs
    /// on the atlas read back (as [`AtlasPlanner::requery`] does on a kept one); on another slice
    /// a fresh atlas is started. A file made for another robot or other parameters, or a
    /// malformed one, is an error at `atlas`.
    pub fn with_atlas(scenario: &Scenario, query: &str, params: PlanParams, text: &str) -> Result<AtlasPlanner> {
        params.validate()?;
        let saved = file::read(text, scenario, params)?;
        let ends = query_ends(scenario, query, params)?;
        let (fixed, _) = slice(&ends, params)?;
        if !same_slice(&fixed, &saved.fixed) {
            return AtlasPlanner::build(scenario, ends, params);
        }
        let fixed = saved.fixed;
        let manifold = CableManifold::new(scenario, fixed, params.identify_angles, params.barrier, params.min_margin, params.rotation_length)?;
        let atlas_params = AtlasParams { radius: params.radius, min_radius: params.min_radius, epsilon: params.epsilon, delta: params.delta };
        let search = Continuation::resume(saved.into_atlas(manifold, atlas_params)?, vec![], params.max_charts, params.heuristic_weight);
        let [start, goal] = ends.poses;
        let mut planner = AtlasPlanner { scenario: scenario.clone(), start, goal, params, fixed, reused: 0, verified_edges: 0, checked_poses: 0, search, check: None };
        planner.retarget(ends)?;
        Ok(planner)
    }

    /// The atlas built so far as a file ([`mod@file`]), for [`AtlasPlanner::with_atlas`].
    pub fn save_atlas(&self) -> String {
        file::save(&self.search.atlas, &self.scenario, self.params, self.fixed)
    }

    /// [`AtlasPlanner::requery`] between two poses given by their coordinates, as
    /// [`AtlasPlanner::between_coords`] takes them.
    pub fn requery_coords(&mut self, start: [f64; 6], goal: [f64; 6], fixed: &[Coord]) -> Result<bool> {
        self.retarget(coords_ends(start, goal, fixed)?)
    }

    /// The common part of the re-queries.
    fn retarget(&mut self, ends: Ends) -> Result<bool> {
        let (fixed, goal_copies) = slice(&ends, self.params)?;
        if !same_slice(&fixed, &self.fixed) {
            return Ok(false);
        }
        let manifold = &self.search.atlas.manifold;
        let (start_x, goals) = lift_ends(manifold, &ends, &goal_copies, self.params)?;
        // the start's other tilt-and-torsion triple may be the one the atlas holds
        let copies = on_slice(ends.coords[0], &ends.fixed, &ends.coords[0], self.params.identify_angles);
        let mut starts = vec![start_x];
        starts.extend(copies.iter().skip(1).filter_map(|c| manifold.lift(c).ok()));
        self.reused = self.search.atlas.charts.len();
        self.search.retarget(&starts, goals).map_err(|why| Error::new(format!("{}.start", ends.field), format!("no chart can be made at the start pose \"{}\": {why}", ends.names[0])))?;
        (self.start, self.goal) = (ends.poses[0], ends.poses[1]);
        self.checked_poses += self.check.take().map_or(0, |c| c.verification.wrench_poses);
        Ok(true)
    }

    /// Prepares planning between two poses given by their coordinates (x, y, z, φ, θ, σ) as they
    /// are — not as the canonical tilt-and-torsion angles of their rotations — with `fixed` held at
    /// the start's values. With `params.identify_angles` off this is paper 1's own setting (the
    /// angles as plain coordinates); the benchmark uses it to plan q3 → q4 as the paper did.
    pub fn between_coords(scenario: &Scenario, start: [f64; 6], goal: [f64; 6], fixed: &[Coord], params: PlanParams) -> Result<AtlasPlanner> {
        params.validate()?;
        AtlasPlanner::build(scenario, coords_ends(start, goal, fixed)?, params)
    }

    /// The common part of the constructors.
    fn build(scenario: &Scenario, ends: Ends, params: PlanParams) -> Result<AtlasPlanner> {
        let (fixed, goal_copies) = slice(&ends, params)?;
        let manifold = CableManifold::new(scenario, fixed, params.identify_angles, params.barrier, params.min_margin, params.rotation_length)?;
        let (start_x, goals) = lift_ends(&manifold, &ends, &goal_copies, params)?;
        let atlas_params = AtlasParams { radius: params.radius, min_radius: params.min_radius, epsilon: params.epsilon, delta: params.delta };
        let search = Continuation::new(manifold, &start_x, goals, atlas_params, params.max_charts, params.heuristic_weight)
            .map_err(|why| Error::new(format!("{}.start", ends.field), format!("no chart can be made at the start pose \"{}\": {why}", ends.names[0])))?;
        let [start, goal] = ends.poses;
        Ok(AtlasPlanner { scenario: scenario.clone(), start, goal, params, fixed, reused: 0, verified_edges: 0, checked_poses: 0, search, check: None })
    }

    /// Advances by at most `budget` units of work (one unit: one chart-creation attempt, one A*
    /// pop, one edge of the path being built, or — once the search has ended — the exact
    /// re-verification of one path edge and the wrench test at its end pose; every unit's work is
    /// bounded ([`AtlasPlanner::work`]): at most a few ms on the 2-D and 3-D Robocrane slices, more for
    /// 6-D chart creations, see docs/planner.md) and returns the progress.
    pub fn step(&mut self, budget: usize) -> AtlasProgress {
        let p = self.search.step(if self.check.is_some() { 0 } else { budget });
        let mut progress = AtlasProgress { charts: p.charts, open: p.open, best_heuristic: p.best_heuristic, done: None, verifying: None };
        let Some(ended) = p.ended else { return progress };
        let check = match &mut self.check {
            Some(c) => {
                let edges = c.path.len().saturating_sub(1);
                for _ in 0..budget.max(1) {
                    if c.finished {
                        break;
                    }
                    if c.next == 0 {
                        if let Some(first) = c.path.first() {
                            c.verification.add_pose(&self.scenario, first);
                        }
                    }
                    if c.next < edges {
                        // an inner edge is a step of the dense path the motion validator accepted
                        // (the same exact verification); the end edges meet the exact start and
                        // goal poses, which the manifold's points round
                        let inner = c.next > 0 && c.next + 1 < edges;
                        if inner && self.search.step_validated(&c.points[c.next], &c.points[c.next + 1]) {
                            c.verification.edges_validated += 1;
                        } else {
                            c.verification.add_edge(&self.scenario, c.next, &c.path[c.next], &c.path[c.next + 1]);
                            self.verified_edges += 1;
                        }
                        c.verification.add_pose(&self.scenario, &c.path[c.next + 1]);
                        c.next += 1;
                    }
                    c.finished = c.next >= edges;
                }
                c
            }
            None => {
                // The search ended in this call: take its path; verification starts next call.
                let manifold = &self.search.atlas.manifold;
                let mut path: Vec<Pose> = self.search.path().iter().map(|x| Pose::from_coords(manifold.coords(x))).collect();
                if let Some(first) = path.first_mut() {
                    *first = self.start;
                }
                if let Some(last) = path.last_mut() {
                    *last = self.goal;
                }
                let verification = PathVerification::start(path.len());
                let points = self.search.path().to_vec();
                self.check.insert(PathCheck { status: status(ended), path, points, verification, next: 0, finished: false })
            }
        };
        let edges = check.path.len().saturating_sub(1);
        progress.verifying = (!check.finished).then_some((check.next, edges));
        progress.done = check.finished.then_some(check.status);
        progress
    }

    /// The atlas as it grows: the slice's coordinates and the charts made since chart `from`
    /// (each as it is now), so a caller can draw it chart by chart while the search runs.
    pub fn charts_since(&self, from: usize) -> (Vec<String>, Vec<view::ChartView>) {
        (view::coords(&self.search.atlas), view::charts_from(&self.search.atlas, from))
    }

    /// The work done so far (cumulative; differences between calls measure a `step`).
    pub fn work(&self) -> PlanWork {
        let poses = self.checked_poses + self.check.as_ref().map_or(0, |c| c.verification.wrench_poses);
        PlanWork { evaluations: self.search.atlas.evaluations(), trajectory_checks: self.search.motion_checks() + self.verified_edges, pose_checks: poses }
    }

    /// The result once [`AtlasPlanner::step`] reported `done`, `None` before.
    pub fn outcome(&self) -> Option<PlanOutcome> {
        let check = self.check.as_ref().filter(|c| c.finished)?;
        let manifold = &self.search.atlas.manifold;
        Some(PlanOutcome {
            status: check.status,
            path: check.path.clone(),
            charts: self.search.atlas.charts.len(),
            atlas: AtlasSummary {
                dimension: manifold.free().len(),
                expansion_failures: self.search.atlas.failures,
                broken_edges: self.search.broken_edges(),
                rejected_edges: self.search.rejected_edges(),
                blocked_charts: self.search.atlas.charts.iter().filter(|c| c.state == chart::ChartState::Blocked).count(),
                chart_radii: self.search.atlas.charts.iter().filter(|c| c.state != chart::ChartState::Blocked).fold([f64::INFINITY, 0.0], |[lo, hi], c| [lo.min(c.radius), hi.max(c.radius)]),
                reused_charts: self.reused,
                params: self.params,
            },
            verification: check.verification.clone(),
            view: view::view(&self.search.atlas, self.search.path_charts()),
        })
    }
}

fn status(e: Ended) -> PlanStatus {
    match e {
        Ended::Found => PlanStatus::Found,
        Ended::Exhausted => PlanStatus::NoPath,
        Ended::Budget => PlanStatus::Budget,
    }
}

impl PathVerification {
    /// Nothing verified yet, for a path of `poses` poses.
    fn start(poses: usize) -> PathVerification {
        PathVerification {
            edges: poses.saturating_sub(1),
            edges_validated: 0,
            infeasible_sections: 0,
            uncertain_sections: 0,
            wrench_poses: 0,
            wrench_infeasible_poses: 0,
            least_wrench_margin: None,
            failed_edges: vec![],
            notes: vec![
                "edges: every condition of the scenario — interference, cable lengths and the wrench conditions — verified exactly \
                 along each slerp + linear edge (verify_trajectory)"
                    .to_string(),
                "poses: the per-pose wrench test at every path pose (margins reported)".to_string(),
            ],
        }
    }

    /// The exact verifier on edge `i`, from `a` to `b`.
    fn add_edge(&mut self, s: &Scenario, i: usize, a: &Pose, b: &Pose) {
        match verify_trajectory(s, &edge_trajectory(i, a, b)) {
            Ok(report) => {
                self.infeasible_sections += report.infeasible.len();
                self.uncertain_sections += report.uncertain.len();
                if !report.infeasible.is_empty() || !report.uncertain.is_empty() {
                    self.failed_edges.push((i, report));
                }
            }
            Err(e) => self.notes.push(format!("edge {i}: the verifier refused it: {e}")),
        }
    }

    /// The per-pose wrench test at one path pose.
    fn add_pose(&mut self, s: &Scenario, pose: &Pose) {
        if let Some(w) = wrench_at(s, pose) {
            self.wrench_poses += 1;
            if !w.feasible {
                self.wrench_infeasible_poses += 1;
            }
            if let Some(m) = w.margin {
                self.least_wrench_margin = Some(self.least_wrench_margin.map_or(m, |a: f64| a.min(m)));
            }
        }
    }
}

/// Re-verifies a path: the exact verifier on each edge, the wrench set at each pose.
pub fn verify_path(s: &Scenario, path: &[Pose]) -> PathVerification {
    let mut v = PathVerification::start(path.len());
    for (i, w) in path.windows(2).enumerate() {
        v.add_edge(s, i, &w[0], &w[1]);
    }
    for pose in path {
        v.add_pose(s, pose);
    }
    v
}

/// Runs a planner for `query` to the end (CLI, tests) and returns its outcome.
pub fn plan(scenario: &Scenario, query: &str, params: PlanParams) -> Result<PlanOutcome> {
    let mut planner = AtlasPlanner::new(scenario, query, params)?;
    while planner.step(1000).done.is_none() {}
    planner.outcome().ok_or_else(|| Error::new("plan", "the planner stopped without an outcome"))
}
