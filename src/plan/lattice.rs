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

use super::PlanStatus;
use crate::error::{Error, Result};
use crate::lattice::{Lattice, LatticeSpec, Ray};
use crate::model::pose::wrap_angle;
use crate::model::{Coord, Orientation, Pose, Segment, Trajectory, Translation};
use crate::report::VerifyReport;
use crate::scenario::Scenario;
use crate::verify::{check_pose, verify_trajectory};
use nalgebra::{UnitQuaternion, Vector3};
use serde::Serialize;
use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};
use std::f64::consts::PI;

/// Most control points of one Bézier piece (the scenario format's degree limit, 10, plus one).
const MAX_CONTROL: usize = 11;

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

/// One grid axis key of a point: on the grid (its index) or off it (its value).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Key {
    Grid(usize),
    Off(f64),
}


/// A ray through the start or the goal that is not a lattice ray.
#[derive(Debug, Clone)]
struct EndRay {
    axis: usize,
    feasible: Vec<[f64; 2]>,
}

/// An open-list entry (least f first, ties: least h). `g` is the cost from the start with which
/// `v` was pushed: the entry is stale exactly when `g` is no longer `v`'s best cost (an exact
/// comparison of the stored number; recomputing it as f − h can exceed it by a rounding error,
/// which skipped live entries, platform-dependently).
#[derive(Debug, Clone, Copy)]
struct Open {
    f: f64,
    h: f64,
    g: f64,
    v: usize,
}
impl PartialEq for Open {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}
impl Eq for Open {}
impl PartialOrd for Open {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Open {
    fn cmp(&self, o: &Self) -> Ordering {
        o.f.total_cmp(&self.f).then(o.h.total_cmp(&self.h)).then(o.v.cmp(&self.v))
    }
}

/// A run of waypoints smoothed into one Bézier piece.
#[derive(Debug, Clone)]
struct Run {
    points: Vec<[f64; 6]>,
    /// How often this run's edge was halved along its ray.
    halvings: u32,
    /// Verified feasible.
    ok: bool,
    /// Given up: its verification's infeasible or uncertain sections stay.
    failed: bool,
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

/// Progress of a lattice planner.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LatticeProgress {
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
    /// the query does not fix, over its `region` (or [`default_range`]), with `params.steps`
    /// values each. Start and goal must be feasible, inside the region and on the same slice.
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
        let axes: Vec<Coord> = Coord::ALL.into_iter().filter(|c| !q.fixed.contains(c)).collect();
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
        for c in &q.fixed {
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
    pub fn step(&mut self, budget: usize) -> LatticeProgress {
        for _ in 0..budget.max(1) {
            if matches!(self.stage, Stage::Done) {
                break;
            }
            self.unit();
        }
        self.progress()
    }

    /// Where the planner is.
    pub fn progress(&self) -> LatticeProgress {
        let lp = self.lattice.progress();
        let (stage, done_units, total_units) = match &self.stage {
            Stage::Lattice => ("lattice", lp.rays_done, Some(lp.rays_total)),
            Stage::Join { next, segments } => ("join", *next, Some(segments.len())),
            Stage::Search => ("search", self.expanded, None),
            Stage::Smooth { next } => ("smooth", *next, Some(self.runs.len())),
            Stage::Final => ("verify", 0, Some(1)),
            Stage::Done => ("done", 1, Some(1)),
        };
        LatticeProgress { stage, done_units, total_units, done: self.status }
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

    // ---- vertices: grid points are numbered by their flat index, special points after them ----

    fn points(&self) -> usize {
        self.lattice.spec.point_count() as usize
    }

    fn coords_of(&self, v: usize) -> [f64; 6] {
        let n = self.points();
        if v < n {
            six(&self.lattice.spec.coords(&self.lattice.spec.point_indices(v)))
        } else {
            self.specials[v - n]
        }
    }

    fn keys(&self, c: &[f64; 6]) -> Vec<Key> {
        let spec = &self.lattice.spec;
        (0..spec.axes.len()).map(|a| spec.grid_index(a, c[spec.axes[a].index()]).map_or(Key::Off(c[spec.axes[a].index()]), Key::Grid)).collect()
    }

    /// The vertex for `c`: its grid point if every key is on the grid, else a new special point.
    fn vertex(&mut self, c: [f64; 6]) -> usize {
        let keys = self.keys(&c);
        if keys.iter().all(|k| matches!(k, Key::Grid(_))) {
            let idx: Vec<usize> = keys.iter().map(|k| if let Key::Grid(i) = k { *i } else { 0 }).collect();
            return self.lattice.spec.point_index(&idx);
        }
        let n = self.points();
        if let Some(j) = self.specials.iter().position(|s| *s == c) {
            return n + j;
        }
        self.specials.push(c);
        n + self.specials.len() - 1
    }

    fn add_edge(&mut self, a: usize, b: usize) {
        if a == b {
            return;
        }
        let cost = metric(&Pose::from_coords(self.coords_of(a)), &Pose::from_coords(self.coords_of(b)), self.params.rotation_length);
        self.extra.entry(a).or_default().push((b, cost));
        self.extra.entry(b).or_default().push((a, cost));
    }

    /// Joins the start and goal to the lattice through their rays; returns the segments to their
    /// cell corners still to verify, as (special vertex, corner vertex).
    fn join_rays(&mut self) -> Vec<(usize, usize)> {
        let k = self.lattice.spec.axes.len();
        let ends = [slice_coords(&self.start, &six(&self.lattice.spec.fixed), &self.lattice.spec.axes), slice_coords(&self.goal, &six(&self.lattice.spec.fixed), &self.lattice.spec.axes)];
        let ids = [self.vertex(ends[0]), self.vertex(ends[1])];
        self.ends = ids;
        let mut segments = vec![];
        for (e, &c) in ends.iter().enumerate() {
            let v = ids[e];
            if v < self.points() {
                continue; // a grid point: on the lattice already
            }
            let keys = self.keys(&c);
            for a in 0..k {
                let off: Vec<usize> = (0..k).filter(|&b| b != a && matches!(keys[b], Key::Off(_))).collect();
                if off.is_empty() {
                    // c lies on the lattice ray along a: join it to its grid neighbours on that ray
                    self.join_on_lattice_ray(v, a, &keys);
                    continue;
                }
                // c's own ray along a
                let feasible = self.lattice.cast(&c, a).feasible;
                self.end_rays.push(EndRay { axis: a, feasible });
                let ray_no = self.end_rays.len() - 1;
                let mut on_ray: Vec<usize> = vec![v];
                if off.len() == 1 {
                    // it crosses the lattice rays along `off[0]` at a's grid values
                    let b = off[0];
                    for i in 0..self.lattice.spec.steps[a] {
                        let mut x = c;
                        x[self.lattice.spec.axes[a].index()] = self.lattice.spec.value(a, i);
                        let w = self.vertex(x);
                        on_ray.push(w);
                        let wk = self.keys(&x);
                        self.join_on_lattice_ray(w, b, &wk);
                    }
                }
                // the other end, if it lies on this ray
                let other = ids[1 - e];
                let oc = self.coords_of(other);
                if (0..k).filter(|&b| b != a).all(|b| oc[self.lattice.spec.axes[b].index()] == c[self.lattice.spec.axes[b].index()]) {
                    on_ray.push(other);
                }
                self.chain(ray_no, on_ray);
            }
            // segments to the feasible corners of c's grid cell
            let spec = &self.lattice.spec;
            let lows: Vec<usize> = (0..k).map(|a| match keys[a] {
                Key::Grid(i) => i,
                Key::Off(x) => ((((x - spec.ranges[a][0]) / spec.spacing(a)).floor().max(0.0)) as usize).min(spec.steps[a] - 2),
            }).collect();
            for corner in 0..(1usize << k) {
                let idx: Vec<usize> = (0..k).map(|a| match keys[a] {
                    Key::Grid(i) => i,
                    Key::Off(_) => lows[a] + ((corner >> a) & 1),
                }).collect();
                let w = spec.point_index(&idx);
                if self.lattice.graph().is_some_and(|g| g.point_feasible[w]) && !segments.contains(&(v, w)) {
                    segments.push((v, w));
                }
            }
        }
        segments
    }

    /// Joins vertex `v` (keys `keys`, on the grid in every axis but `a`) to the nearest grid points
    /// on both sides along the lattice ray along `a`, where the same feasible piece holds both.
    fn join_on_lattice_ray(&mut self, v: usize, a: usize, keys: &[Key]) {
        let spec = &self.lattice.spec;
        let mut idx: Vec<usize> = keys.iter().map(|k| if let Key::Grid(i) = k { *i } else { 0 }).collect();
        let Key::Off(x) = keys[a] else { return };
        let r = spec.ray_index(a, &idx);
        let ray: &Ray = &self.lattice.rays[r];
        let Some(piece) = ray.piece_at(x) else { return };
        let below = ((x - spec.ranges[a][0]) / spec.spacing(a)).floor().max(0.0) as usize;
        let mut joins = vec![];
        for i in [below, below + 1] {
            if i < spec.steps[a] && ray.piece_at(spec.value(a, i)) == Some(piece) {
                idx[a] = i;
                joins.push(spec.point_index(&idx));
            }
        }
        for w in joins {
            self.add_edge(v, w);
        }
    }

    /// Joins consecutive vertices of `on_ray` (all on end ray `ray_no`) that one feasible piece holds.
    fn chain(&mut self, ray_no: usize, mut on_ray: Vec<usize>) {
        let a = self.end_rays[ray_no].axis;
        let ax = self.lattice.spec.axes[a].index();
        let mut with_value: Vec<(f64, usize)> = on_ray.drain(..).map(|v| (self.coords_of(v)[ax], v)).collect();
        with_value.sort_by(|p, q| p.0.total_cmp(&q.0));
        let ray = &self.end_rays[ray_no];
        let piece = |x: f64| ray.feasible.iter().position(|iv| iv[0] <= x && x <= iv[1]);
        let pairs: Vec<(usize, usize)> =
            with_value.windows(2).filter(|w| piece(w[0].0).is_some() && piece(w[0].0) == piece(w[1].0)).map(|w| (w[0].1, w[1].1)).collect();
        for (p, q) in pairs {
            self.add_edge(p, q);
        }
    }

    /// Verifies the straight segment (line + slerp) from `v` to grid point `w` exactly; joins them if
    /// it is feasible throughout.
    fn try_segment(&mut self, v: usize, w: usize) {
        self.segments[1] += 1;
        let (a, b) = (Pose::from_coords(self.coords_of(v)), Pose::from_coords(self.coords_of(w)));
        let traj = super::edge_trajectory(0, &a, &b);
        if let Ok(r) = verify_trajectory(self.lattice.scenario(), &traj) {
            if r.infeasible.is_empty() && r.uncertain.is_empty() {
                self.segments[0] += 1;
                self.add_edge(v, w);
            }
        }
    }

    // ---- A* ----

    fn heuristic(&self, v: usize) -> f64 {
        metric(&Pose::from_coords(self.coords_of(v)), &self.goal, self.params.rotation_length)
    }

    fn start_search(&mut self) {
        let s = self.ends[0];
        let h = self.heuristic(s);
        self.g.insert(s, 0.0);
        self.open.push(Open { f: h, h, g: 0.0, v: s });
        self.stage = Stage::Search;
    }

    /// The neighbours of `v` with edge costs: grid neighbours along each axis within one feasible
    /// piece of the ray between them, and the extra edges of special points and segments.
    fn neighbours(&self, v: usize) -> Vec<(usize, f64)> {
        let mut out = self.extra.get(&v).cloned().unwrap_or_default();
        if v < self.points() {
            let spec = &self.lattice.spec;
            let idx = spec.point_indices(v);
            let here = Pose::from_coords(six(&spec.coords(&idx)));
            for a in 0..spec.axes.len() {
                let r = spec.ray_index(a, &idx);
                let ray = &self.lattice.rays[r];
                let Some(piece) = ray.piece_at(spec.value(a, idx[a])) else { continue };
                for j in [idx[a].wrapping_sub(1), idx[a] + 1] {
                    if j < spec.steps[a] && ray.piece_at(spec.value(a, j)) == Some(piece) {
                        let mut n = idx.clone();
                        n[a] = j;
                        let w = spec.point_index(&n);
                        out.push((w, metric(&here, &Pose::from_coords(six(&spec.coords(&n))), self.params.rotation_length)));
                    }
                }
            }
        }
        out.extend(self.seam_twins(v).into_iter().map(|w| (w, 0.0)));
        out
    }

    /// The vertices that are the same pose as `v` across the seam of an angle axis over a whole
    /// turn: `v`'s value at one end of the range exchanged for the other end (grid points, and
    /// special points whose twin the start's or goal's rays also made).
    fn seam_twins(&self, v: usize) -> Vec<usize> {
        let spec = &self.lattice.spec;
        let wrapping = (0..spec.axes.len()).filter(|&a| spec.wraps(a));
        if v < self.points() {
            let idx = spec.point_indices(v);
            return wrapping.filter_map(|a| spec.seam_twin(&idx, a)).map(|twin| spec.point_index(&twin)).collect();
        }
        let c = self.coords_of(v);
        let keys = self.keys(&c);
        let mut out = vec![];
        for a in wrapping {
            let Key::Grid(i) = keys[a] else { continue };
            let last = spec.steps[a] - 1;
            if i == 0 || i == last {
                let mut twin = c;
                twin[spec.axes[a].index()] = spec.value(a, last - i);
                out.extend(self.specials.iter().position(|s| *s == twin).map(|j| self.points() + j));
            }
        }
        out
    }

    fn search_unit(&mut self) {
        let goal = self.ends[1];
        let Some(Open { g: g_pushed, v, .. }) = self.open.pop() else {
            self.status = Some(PlanStatus::NoPath);
            self.stage = Stage::Done;
            return;
        };
        if g_pushed > self.g.get(&v).copied().unwrap_or(f64::INFINITY) {
            return; // a stale entry: v was reached more cheaply since
        }
        self.expanded += 1;
        if v == goal {
            let mut path = vec![v];
            while let Some(&p) = self.parent.get(path.last().unwrap_or(&v)) {
                path.push(p);
            }
            path.reverse();
            self.polyline = self.unwrapped(&path);
            self.waypoints = turning_points(&self.polyline);
            self.runs = initial_runs(&self.waypoints);
            self.stage = Stage::Smooth { next: 0 };
            return;
        }
        let gv = self.g.get(&v).copied().unwrap_or(f64::INFINITY);
        for (w, cost) in self.neighbours(v) {
            let gw = gv + cost;
            if gw < self.g.get(&w).copied().unwrap_or(f64::INFINITY) {
                self.g.insert(w, gw);
                self.parent.insert(w, v);
                let h = self.heuristic(w);
                self.open.push(Open { f: gw + h, h, g: gw, v: w });
            }
        }
    }

    /// The coordinates of the A* path `path`, continuous across the seam of a wrapping angle
    /// axis: a hop to the seam twin (the same pose) is dropped and the points after it keep going
    /// past the range's end (φ = π + 0.1 rather than −π + 0.1), so that every edge and every
    /// halving of it runs the short way along its ray.
    fn unwrapped(&self, path: &[usize]) -> Vec<[f64; 6]> {
        let mut shift = [0.0; 6];
        let mut out: Vec<[f64; 6]> = Vec::with_capacity(path.len());
        for (k, &w) in path.iter().enumerate() {
            let c = self.coords_of(w);
            if k > 0 && self.seam_twins(path[k - 1]).contains(&w) {
                let before = self.coords_of(path[k - 1]);
                for i in 0..6 {
                    shift[i] += before[i] - c[i];
                }
                continue;
            }
            out.push(std::array::from_fn(|i| c[i] + shift[i]));
        }
        out
    }

    // ---- smoothing and repair ----

    fn smooth_unit(&mut self, k: usize) {
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

    fn assemble(&self) -> Trajectory {
        let pieces: Vec<Segment> = self.runs.iter().map(|r| run_segment(&r.points)).collect();
        Trajectory::piecewise(format!("{}-lattice", self.query), pieces).unwrap_or_else(|| run_trajectory(&[self.start.coords(), self.start.coords()], "empty"))
    }

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
        })
    }

    /// The smoothed trajectory, once finished with a path.
    pub fn trajectory(&self) -> Option<&Trajectory> {
        self.trajectory.as_ref()
    }
}

/// The coordinates of `pose` with every coordinate not in `axes` taken from `fixed` (the
/// lattice's slice) and the axes' values from the pose — in whichever of its two tilt-and-torsion
/// triples, (φ, θ, σ) or (φ + π, −θ, σ), agrees with the slice.
fn slice_coords(pose: &Pose, fixed: &[f64; 6], axes: &[Coord]) -> [f64; 6] {
    {
        let c = pose.coords();
        let alt = [c[0], c[1], c[2], wrap_angle(c[3] + PI), -c[4], c[5]];
        let fits = |x: &[f64; 6]| Coord::ALL.iter().filter(|k| !axes.contains(k)).all(|k| {
            let d = x[k.index()] - fixed[k.index()];
            (if k.is_angle() { wrap_angle(d) } else { d }).abs() <= 1e-9
        });
        let pick = if fits(&c) || !fits(&alt) { c } else { alt };
        let mut out = *fixed;
        for a in axes {
            out[a.index()] = pick[a.index()];
        }
        out
    }
}

/// The polyline without points inside straight runs (where the path goes on along the same single
/// coordinate in the same direction).
fn turning_points(path: &[[f64; 6]]) -> Vec<[f64; 6]> {
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
fn initial_runs(waypoints: &[[f64; 6]]) -> Vec<Run> {
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

fn run_trajectory(points: &[[f64; 6]], name: &str) -> Trajectory {
    let seg = run_segment(points);
    Trajectory::single(name, seg.translation, seg.orientation)
}

/// The six pose coordinates of a platform robot's lattice point (the lattice planner plans for
/// platform robots only; their configurations have six coordinates).
fn six(c: &[f64]) -> [f64; 6] {
    std::array::from_fn(|i| c.get(i).copied().unwrap_or(0.0))
}
