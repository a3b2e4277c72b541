//! The commands every front end offers — the `cablenav` CLI, the Python package, the npm package:
//! a typed [`Request`], [`run`] against a scenario, and the [`Output`] as JSON (the one
//! serialisation all of them print or return) or as readable text. Parsing of command lines
//! lives in the `cablenav-cli` crate (`cli/`), so the core stays free of argument parsers.
//!
//! Errors name the command-line option they come from (`--range`, `--radius`, …): the bindings
//! map those to their parameter names.

use crate::error::{Error, Result};
use crate::model::Coord;
use crate::lattice::{Lattice, LatticeReport, LatticeSpec};
use crate::model::{JointPath, Trajectory};
use crate::plan::atlas::{PlanParams, PlanReport};
use crate::plan::lattice::{LatticeParams, LatticePlanReport};
use crate::plan::timing::{self, TimingOptions};
use crate::plan::{self, Details, PlanStatus, PlannerKind, PlannerNaming, PlannerOptions};
use crate::report::{PoseReport, RayReport, Side, TensionEnvelope, TimingReport, VerifyReport};
use crate::verify::slice::{default_range, slice_counted, Class, SliceMap};
use crate::verify::{along, check_along, check_config, check_pose, ray, tension_envelope, verify_all_counted, verify_along, verify_pointwise_along};
use std::sync::atomic::{AtomicUsize, Ordering};
use crate::Scenario;
use serde::Serialize;

/// One command with its parameters, already parsed and typed.
#[derive(Debug, Clone, PartialEq)]
pub enum Request {
    /// Feasible/infeasible t-sections of a trajectory (exact, or sampled every `pointwise` in t).
    Verify {
        /// Trajectory name (`None`: the scenario's first).
        trajectory: Option<String>,
        /// Sample step Δt instead of the exact verifier.
        pointwise: Option<f64>,
    },
    /// [`Request::Verify`] for every trajectory of the scenario, in parallel on native targets.
    VerifyAll {
        /// Sample step Δt instead of the exact verifier.
        pointwise: Option<f64>,
    },
    /// Feasible intervals of one coordinate over `range`, the others fixed at the pose's (or the
    /// multi-link robot's configuration's).
    Ray {
        /// Pose (or configuration) name.
        pose: String,
        /// The coordinate varied, by name (x, y, z, phi, theta, sigma, or a joint coordinate).
        vary: String,
        /// [LO, HI].
        range: [f64; 2],
    },
    /// Lengths, distances, violated conditions and the wrench set's tension ranges at one pose.
    Check {
        /// Pose name.
        pose: String,
    },
    /// [`Request::Check`] where a trajectory is at t, moving as it moves there if it is timed.
    CheckAt {
        /// Trajectory name (`None`: the scenario's first).
        trajectory: Option<String>,
        /// The trajectory's parameter t ∈ [0, 1].
        t: f64,
    },
    /// Each cable's least and greatest tension over the wrench set along a trajectory.
    Envelope {
        /// Trajectory name (`None`: the scenario's first).
        trajectory: Option<String>,
        /// Sample count (`None`: 100).
        samples: Option<usize>,
    },
    /// The fastest timing of a trajectory, certified along it (docs/timing.md).
    Time {
        /// Trajectory name (`None`: the scenario's first).
        trajectory: Option<String>,
        /// Grid cells (`None`: 400).
        cells: Option<usize>,
        /// Relative margin on the limits at the grid points (`None`: 1e-3).
        margin: Option<f64>,
    },
    /// A res × res classified grid over two coordinates and its feasible components.
    Slice {
        /// Pose the other coordinates come from.
        pose: String,
        /// The two coordinates (columns, rows), by name.
        axes: [String; 2],
        /// Grid side.
        res: usize,
        /// Ranges of the two axes (`None`: [-π, π] for angles; position axes need one).
        range: Option<[[f64; 2]; 2]>,
    },
    /// The thesis' ray lattice over `axes` (the others from the pose): every ray's exact feasible
    /// intervals, the graph of feasible pieces and its components (docs/lattice.md).
    Lattice {
        /// Pose (or configuration) the other coordinates come from.
        pose: String,
        /// The chosen coordinates, by name.
        axes: Vec<String>,
        /// [LO, HI] per axis.
        ranges: Vec<[f64; 2]>,
        /// Grid values: one number for every axis, or one per axis.
        steps: Vec<usize>,
    },
    /// A feasible path for each of the scenario's queries named, in order, by the atlas or the
    /// lattice planner; the atlas planner answers later queries on the same slice from the atlas
    /// it kept from the earlier ones.
    Plan {
        /// Query names (at least one).
        queries: Vec<String>,
        /// Atlas planner parameters (defaults: [`PlanParams::default`]).
        params: PlanParams,
        /// Which planner.
        planner: PlannerKind,
        /// Lattice planner parameters (defaults: [`LatticeParams::default`]).
        lattice: LatticeParams,
        /// An atlas file's text to start the atlas planner from (empty: none yet), whose atlas at
        /// the end then comes back in the output ([`Output::atlas_file`]); `None` keeps none.
        atlas: Option<String>,
        /// How the caller's users choose the planners, for the refusals that name them.
        naming: PlannerNaming,
    },
}

/// The result of a [`Request`].
// one value per command run, moved once: the variants' sizes do not matter enough to box them
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// Of [`Request::Verify`].
    Verify(VerifyReport),
    /// Of [`Request::VerifyAll`]: one report per trajectory, in file order.
    VerifyAll(Vec<VerifyReport>),
    /// Of [`Request::Ray`].
    Ray(RayReport),
    /// Of [`Request::Check`] and [`Request::CheckAt`].
    Check(PoseReport),
    /// Of [`Request::Envelope`].
    Envelope(TensionEnvelope),
    /// Of [`Request::Time`].
    Time(TimingReport),
    /// Of [`Request::Slice`].
    Slice(SliceMap),
    /// Of [`Request::Plan`] with the atlas planner, the path as a trajectory, and the atlas file
    /// when the request keeps one (on the last query's output).
    Plan(PlanReport, Option<Trajectory>, Option<String>),
    /// Of [`Request::Lattice`].
    Lattice(LatticeReport),
    /// Of [`Request::Plan`] with the lattice planner, and its smoothed trajectory (a platform
    /// robot's) or its path through configurations (a multi-link robot's).
    LatticePlan(LatticePlanReport, Option<Trajectory>, Option<JointPath>),
    /// Of [`Request::Plan`] with several queries: one [`Output::Plan`] or [`Output::LatticePlan`]
    /// per query, in order.
    Plans(Vec<Output>),
}

/// How far a long command has come, for progress bars: `done` of `total` units of `stage`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// What is being counted (`"charts"`, `"path edges verified"`).
    pub stage: &'static str,
    /// Units done.
    pub done: usize,
    /// Units in all (for the planner's search: the chart budget, an upper bound).
    pub total: usize,
}

/// Runs `request` on `scenario`, reporting progress of long commands (the planner) to `progress`.
pub fn run(scenario: &Scenario, request: &Request, progress: &mut dyn FnMut(Progress)) -> Result<Output> {
    Ok(match request {
        Request::Verify { trajectory, pointwise } => {
            let path = along(scenario, trajectory.as_deref())?;
            Output::Verify(match pointwise {
                Some(dt) => verify_pointwise_along(scenario, path, *dt)?,
                None => verify_along(scenario, path)?,
            })
        }
        Request::VerifyAll { pointwise } => {
            let total = scenario.trajectories.len() + scenario.joint_paths.len();
            Output::VerifyAll(counted("trajectories verified", total, progress, |done| verify_all_counted(scenario, *pointwise, done))?)
        }
        Request::Ray { pose, vary, range } => Output::Ray(ray(scenario, pose, scenario.coord("--vary", vary)?, range[0], range[1])?),
        Request::Check { pose } => Output::Check(match scenario.robot.chain {
            Some(_) => check_config(scenario, pose, &scenario.config(pose)?),
            None => check_pose(scenario, pose, scenario.pose(pose)?),
        }),
        Request::CheckAt { .. } if scenario.robot.chain.is_some() => {
            return Err(Error::new("--trajectory", "checking along a path is for platform robots; check a multi-link robot's configurations with --pose"));
        }
        Request::CheckAt { trajectory, t } => Output::Check(check_along(scenario, scenario.trajectory(trajectory.as_deref())?, *t)?),
        Request::Envelope { .. } if scenario.robot.chain.is_some() => {
            return Err(Error::new("envelope", "tension envelopes need a wrench set; a multi-link robot's wrench condition is joint-space wrench closure, which has no tension ranges"));
        }
        Request::Envelope { trajectory, samples } => {
            let traj = scenario.trajectory(trajectory.as_deref())?;
            Output::Envelope(tension_envelope(scenario, traj, samples.unwrap_or(100))?)
        }
        Request::Time { trajectory, cells, margin } => {
            let defaults = TimingOptions::default();
            let options = TimingOptions { cells: cells.unwrap_or(defaults.cells), margin: margin.unwrap_or(defaults.margin), ..defaults };
            let mut hear = |p: timing::TimingProgress| progress(Progress { stage: "cells certified", done: p.done, total: p.total });
            Output::Time(timing::fastest_reporting(scenario, scenario.trajectory(trajectory.as_deref())?, options, &mut hear)?.0)
        }
        Request::Slice { pose, axes, res, range } => {
            let axes = [scenario.coord("--axes", &axes[0])?, scenario.coord("--axes", &axes[1])?];
            let range = match range {
                Some(r) => *r,
                None => {
                    let pick = |c: Coord| default_range(c).ok_or_else(|| Error::new("--range", format!("is required for the position axis {}", scenario.coord_name(c))));
                    [pick(axes[0])?, pick(axes[1])?]
                }
            };
            let mut map = counted("slice rows", *res, progress, |done| slice_counted(scenario, pose, axes, *res, range, done))?;
            map.singular_curves = crate::verify::singular::singularity_curves(scenario, pose, axes, *res, range)?;
            Output::Slice(map)
        }
        Request::Lattice { pose, axes, ranges, steps } => {
            let axes = axes.iter().map(|a| scenario.coord("--axes", a.trim())).collect::<Result<Vec<Coord>>>()?;
            let spec = LatticeSpec::new(axes, ranges.clone(), steps.clone(), scenario.config(pose)?)?;
            let total = spec.ray_count() as usize;
            let report = counted("rays", total, progress, |done| {
                let mut lattice = Lattice::new(scenario, spec);
                lattice.finish(done);
                lattice.report()
            });
            Output::Lattice(report.ok_or_else(|| Error::new("lattice", "the lattice stopped before its end"))?)
        }
        Request::Plan { planner: PlannerKind::Atlas, naming, .. } if scenario.robot.chain.is_some() => {
            return Err(Error::new(
                "plan",
                format!("the atlas planner ({}, the default) is for platform robots; plan a multi-link robot's queries with {} (docs/multilink.md)", naming.atlas, naming.lattice),
            ));
        }
        Request::Plan { queries, params, planner, lattice, atlas, .. } => {
            let option = |e: Error| match e.field.as_str() {
                "radius" | "min_radius" | "heuristic_weight" | "epsilon" | "max_charts" => Error::new(format!("--{}", e.field.replace('_', "-")), e.reason),
                _ => e,
            };
            if queries.is_empty() {
                return Err(Error::new("--query", "name at least one query"));
            }
            let options = PlannerOptions { kind: *planner, atlas: *params, lattice: *lattice };
            // the planner is picked by name and stepped through the common interface
            let mut hear = |step: &plan::PlanProgress| progress(Progress { stage: "planning (‰)", done: (step.fraction * 1000.0) as usize, total: 1000 });
            let (results, mut saved) = plan::run_queries(scenario, queries, &options, atlas.as_deref(), &clock(), &mut hear).map_err(option)?;
            let last = results.len().saturating_sub(1);
            let mut outputs: Vec<Output> = results
                .into_iter()
                .enumerate()
                .map(|(i, result)| match result.details {
                    Details::Atlas(r) => Output::Plan(r, result.trajectory, if i == last { saved.take() } else { None }),
                    Details::Lattice(r) => Output::LatticePlan(r, result.trajectory, result.joint_path),
                })
                .collect();
            if outputs.len() == 1 {
                outputs.pop().ok_or_else(|| Error::new("plan", "no result"))?
            } else {
                Output::Plans(outputs)
            }
        }
    })
}

/// Runs `work`, which counts its finished units (of `total`) in the counter it is given, and
/// reports that count to `progress` as `stage`. Natively the work runs on a scoped thread (it
/// spreads over rayon's workers itself) while this one polls the counter every 50 ms; on wasm
/// (no threads) it runs here and the count is reported once, at the end.
fn counted<T: Send>(stage: &'static str, total: usize, progress: &mut dyn FnMut(Progress), work: impl FnOnce(&AtomicUsize) -> T + Send) -> T {
    let done = AtomicUsize::new(0);
    #[cfg(not(target_arch = "wasm32"))]
    let result = std::thread::scope(|scope| {
        let worker = scope.spawn(|| work(&done));
        progress(Progress { stage, done: 0, total });
        while !worker.is_finished() {
            std::thread::sleep(std::time::Duration::from_millis(50));
            progress(Progress { stage, done: done.load(Ordering::Relaxed), total });
        }
        worker.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic))
    });
    #[cfg(target_arch = "wasm32")]
    let result = work(&done);
    progress(Progress { stage, done: done.load(Ordering::Relaxed), total });
    result
}

impl Output {
    /// The report as pretty-printed JSON: what `cablenav … --json` prints.
    pub fn json(&self) -> String {
        let text = match self {
            Output::Verify(r) => to_json(r),
            Output::VerifyAll(r) => to_json(r),
            Output::Ray(r) => to_json(r),
            Output::Check(r) => to_json(r),
            Output::Envelope(r) => to_json(r),
            Output::Time(r) => to_json(r),
            Output::Slice(r) => to_json(r),
            Output::Plan(r, ..) => to_json(r),
            Output::Lattice(r) => to_json(r),
            Output::LatticePlan(r, ..) => to_json(r),
            Output::Plans(outputs) => {
                // each report as its own type serialises it (a round trip through
                // `serde_json::Value` would sort the fields where `preserve_order` is off)
                #[derive(Serialize)]
                #[serde(untagged)]
                enum Each<'a> {
                    Atlas(&'a PlanReport),
                    Lattice(&'a LatticePlanReport),
                }
                let each: Vec<Each> = outputs
                    .iter()
                    .filter_map(|o| match o {
                        Output::Plan(r, ..) => Some(Each::Atlas(r)),
                        Output::LatticePlan(r, ..) => Some(Each::Lattice(r)),
                        _ => None,
                    })
                    .collect();
                to_json(&each)
            }
        };
        // Serialising these plain structs cannot fail; non-finite floats become null.
        text.unwrap_or_else(|e| format!("{{\"error\": {:?}}}", e.to_string()))
    }

    /// The report as readable text: what `cablenav …` prints without `--json`.
    pub fn text(&self) -> String {
        match self {
            Output::Verify(r) => verify_text(r),
            Output::VerifyAll(r) => r.iter().map(verify_text).collect::<Vec<_>>().join("\n"),
            Output::Ray(r) => ray_text(r),
            Output::Check(r) => check_text(r),
            Output::Envelope(r) => envelope_text(r),
            Output::Time(r) => time_text(r),
            Output::Slice(r) => slice_text(r),
            Output::Plan(r, ..) => plan_text(r),
            Output::Lattice(r) => lattice_text(r),
            Output::LatticePlan(r, ..) => lattice_plan_text(r),
            Output::Plans(outputs) => outputs.iter().map(Output::text).collect::<Vec<_>>().join("\n"),
        }
    }

    /// The planned motion of a plan (the atlas' path as line + slerp pieces, the lattice
    /// planner's smoothed trajectory), for `--out`; `None` for other commands or without a path
    /// (or for a multi-link robot's, [`Output::joint_path`]).
    pub fn trajectory(&self) -> Option<&Trajectory> {
        match self {
            Output::Plan(_, t, _) | Output::LatticePlan(_, t, _) => t.as_ref(),
            _ => None,
        }
    }

    /// The lattice planner's path through configurations of a plan for a multi-link robot, for
    /// `--out` (`scenario::with_joint_path`); `None` otherwise.
    pub fn joint_path(&self) -> Option<&JointPath> {
        match self {
            Output::LatticePlan(_, _, p) => p.as_ref(),
            _ => None,
        }
    }

    /// The atlas file a plan request that keeps one returns (the atlas at the end of its last
    /// query); `None` otherwise.
    pub fn atlas_file(&self) -> Option<&str> {
        match self {
            Output::Plan(_, _, file) => file.as_deref(),
            Output::Plans(outputs) => outputs.last()?.atlas_file(),
            _ => None,
        }
    }
}

fn to_json<T: Serialize>(v: &T) -> serde_json::Result<String> {
    serde_json::to_string_pretty(v)
}

fn side(s: Side) -> &'static str {
    match s {
        Side::Feasible => "feasible",
        Side::Infeasible => "infeasible",
    }
}

fn intervals(v: &[[f64; 2]]) -> String {
    if v.is_empty() {
        return "none".to_string();
    }
    v.iter().map(|iv| format!("[{:.9}, {:.9}]", iv[0], iv[1])).collect::<Vec<_>>().join(" ∪ ")
}

/// The closing lines of a report: its warnings.
fn notes(warnings: &[String]) -> String {
    let mut out = String::new();
    for w in warnings {
        out += &format!("  warning: {w}\n");
    }
    out
}

fn verify_text(r: &VerifyReport) -> String {
    let mut out = format!("trajectory {} ({}", r.trajectory, r.method);
    if let Some(dt) = r.step {
        out += &format!(", Δt = {dt}");
    }
    out += ")\n";
    out += &format!("  feasible   t ∈ {}\n", intervals(&r.feasible));
    out += &format!("  infeasible t ∈ {}\n", intervals(&r.infeasible));
    // τ is the trajectory's own parameter; a multi-link robot's path has none besides t
    let has_tau = r.feasible_tau != r.feasible || r.boundaries.iter().any(|b| b.tau != b.t);
    if has_tau {
        out += &format!("  feasible   τ ∈ {}\n", intervals(&r.feasible_tau));
    }
    for b in &r.boundaries {
        let tau = if has_tau { format!(" (τ = {:.9})", b.tau) } else { String::new() };
        out += &format!("  boundary t = {:.9}{tau}: {} → {}\n", b.t, b.constraint, side(b.enters));
    }
    out += &format!("  uncertain  t ∈ {}\n", intervals(&r.uncertain));
    if let Some(sec) = &r.seconds {
        out += &seconds_text(sec);
    }
    out + &notes(&r.warnings)
}

/// A timed trajectory's sections in seconds and its least time scale.
fn seconds_text(sec: &crate::report::Seconds) -> String {
    let mut out = format!("  timed: {} s\n", sec.duration);
    out += &format!("    feasible   s ∈ {}\n", intervals(&sec.feasible));
    out += &format!("    infeasible s ∈ {}\n", intervals(&sec.infeasible));
    out += &format!("    uncertain  s ∈ {}\n", intervals(&sec.uncertain));
    match (sec.min_time_scale, sec.min_duration) {
        (Some(k), Some(d)) => out += &format!("    min time scale {k:.6} (shortest certified duration {d:.6} s): {}\n", sec.min_time_scale_note),
        _ => out += &format!("    min time scale: {}\n", sec.min_time_scale_note),
    }
    out
}

fn ray_text(r: &RayReport) -> String {
    let mut out = format!("ray {} over [{}, {}] from pose {}\n", r.vary, r.range[0], r.range[1], r.pose);
    out += &format!("  feasible   {} ∈ {}\n", r.vary, intervals(&r.feasible));
    out += &format!("  infeasible {} ∈ {}\n", r.vary, intervals(&r.infeasible));
    for b in &r.boundaries {
        out += &format!("  boundary {} = {:.9}: {} → {}\n", r.vary, b.value, b.constraint, side(b.enters));
    }
    out += &format!("  uncertain  {} ∈ {}\n", r.vary, intervals(&r.uncertain));
    out + &notes(&r.warnings)
}

fn check_text(r: &PoseReport) -> String {
    let mut out = format!("pose {}: {}\n", r.pose, if r.feasible { "feasible" } else { "infeasible" });
    let lengths: Vec<String> = r.lengths.iter().map(|l| format!("{l:.6}")).collect();
    out += &format!("  cable lengths: {}\n", lengths.join(" "));
    for c in &r.checks {
        let d = c.distance.map_or("-".to_string(), |d| format!("{d:.6}"));
        let mark = if c.violated { "VIOLATED" } else { "ok" };
        out += &format!("  {:<28} {:>12}  {}\n", c.constraint, d, mark);
    }
    if let Some(w) = &r.wrench {
        let verdict = if w.feasible { "feasible" } else { "infeasible" };
        match w.margin {
            Some(m) => out += &format!("  wrench: {verdict}, margin {m:.6}, active: {}\n", w.active),
            None => out += &format!("  wrench: {verdict} ({})\n", w.active),
        }
        for (i, (lo, hi)) in w.tension_min.iter().zip(&w.tension_max).enumerate() {
            out += &format!("    cable {} tension ∈ [{lo:.6}, {hi:.6}]\n", i + 1);
        }
    }
    out
}

fn slice_text(m: &SliceMap) -> String {
    let mut out = format!(
        "slice over ({}, {}) ∈ [{}, {}] × [{}, {}], {}×{} cells\n  feasible: {:.2}% in {} component(s)\n",
        m.axes[0], m.axes[1], m.range[0][0], m.range[0][1], m.range[1][0], m.range[1][1], m.res, m.res,
        100.0 * m.fraction_feasible, m.components
    );
    for (name, c) in &m.pose_components {
        out += &format!("  pose {name}: {}\n", c.map_or("infeasible".to_string(), |c| format!("component {c}")));
    }
    if !m.singular_curves.is_empty() {
        let points: usize = m.singular_curves.iter().map(Vec::len).sum();
        out += &format!("  singularity curves (det J = 0): {} polyline(s), {points} points (singular_curves in --json)\n", m.singular_curves.len());
    }
    if m.res <= 100 {
        out += &format!("  map ({} to the right, {} upwards; . feasible, T tension, L length, S singular, X interference):\n", m.axes[0], m.axes[1]);
        for j in (0..m.res).rev() {
            let row: String = (0..m.res)
                .map(|i| match m.classes[j * m.res + i] {
                    Class::Feasible => '.',
                    Class::Tension => 'T',
                    Class::Length => 'L',
                    Class::Singular => 'S',
                    Class::Interference => 'X',
                })
                .collect();
            out += &format!("  {row}\n");
        }
    }
    out
}

fn time_text(r: &TimingReport) -> String {
    let mut out = format!("{}: fastest safe timing\n", r.trajectory);
    match r.duration {
        Some(d) => out += &format!("  certified duration: {d:.6} s (uncertified optimum of the first grid {:.6} s; the certificate cost {:.3} %)\n", r.uncertified_duration, 100.0 * r.certificate_cost.unwrap_or(0.0)),
        None => out += &format!("  not certified: {} (best law {:.6} s)\n", intervals(&r.not_certified), r.profile.last().map_or(0.0, |p| p.time)),
    }
    out += &format!("  grid: {} cells, limits tightened by {} relative; {} certification rounds", r.cells, r.margin, r.rounds);
    if !r.slowed.is_empty() {
        out += &format!(", slowed on t ∈ {}", intervals(&r.slowed));
    }
    out += "\n  binding:\n";
    for b in &r.binding {
        out += &format!("    t ∈ [{:.6}, {:.6}] ({:.4} – {:.4} s): {}\n", b.t[0], b.t[1], b.seconds[0], b.seconds[1], b.constraint);
    }
    out + &notes(&r.notes)
}

fn envelope_text(e: &TensionEnvelope) -> String {
    let mut out = format!("tension envelope along {} ({} samples): t, then [min, max] per cable\n", e.trajectory, e.t.len());
    for (k, t) in e.t.iter().enumerate() {
        let row = match (&e.tension_min[k], &e.tension_max[k]) {
            (Some(lo), Some(hi)) => lo.iter().zip(hi).map(|(a, b)| format!("[{a:.4}, {b:.4}]")).collect::<Vec<_>>().join(" "),
            _ => "singular".to_string(),
        };
        out += &format!("  {t:.4}  {row}\n");
    }
    out
}

/// A wall clock in seconds since it was made (NaN on wasm32, which has no `Instant`).
fn clock() -> impl Fn() -> f64 {
    #[cfg(not(target_arch = "wasm32"))]
    {
        let start = std::time::Instant::now();
        move || start.elapsed().as_secs_f64()
    }
    #[cfg(target_arch = "wasm32")]
    {
        || f64::NAN
    }
}

fn lattice_text(r: &LatticeReport) -> String {
    let axes: Vec<String> = r.axes.iter().zip(&r.ranges).zip(&r.steps).map(|((a, g), n)| format!("{a} ∈ [{}, {}] ({n} values)", g[0], g[1])).collect();
    let mut out = format!("lattice over {}: {} rays, {} feasible pieces, {} component(s)\n", axes.join(", "), r.rays.len(), r.pieces, r.components);
    out += &format!("  grid points: {} of {} feasible on every ray through them", r.feasible_points, r.grid_points);
    if r.disagreements > 0 {
        out += &format!(" ({} where the rays through them disagree)", r.disagreements);
    }
    out += "\n";
    out += &format!(
        "  components: {} holding grid points, {} slivers between grid points; the point-wise grid of the same points finds {} ({} separation(s) it misses)\n",
        r.grid_components, r.sliver_components, r.pointwise_components, r.missed_separations
    );
    if r.uncertain_rays > 0 {
        out += &format!("  warning: {} ray(s) have uncertain sections (counted as infeasible)\n", r.uncertain_rays);
    }
    const SHOWN: usize = 200;
    for (ray, comps) in r.rays.iter().zip(&r.piece_components).take(SHOWN) {
        let at: Vec<String> = ray.fixed.iter().filter(|(k, _)| r.axes.contains(k)).map(|(k, v)| format!("{k} = {v:.6}")).collect();
        let pieces: Vec<String> = ray.feasible.iter().zip(comps).map(|(iv, c)| format!("[{:.6}, {:.6}] (component {c})", iv[0], iv[1])).collect();
        out += &format!("  {} at {}: {}\n", ray.vary, at.join(", "), if pieces.is_empty() { "none".to_string() } else { pieces.join(" ∪ ") });
    }
    if r.rays.len() > SHOWN {
        out += &format!("  … {} more rays (--json prints all)\n", r.rays.len() - SHOWN);
    }
    out + &notes(&r.warnings)
}

fn lattice_plan_text(r: &LatticePlanReport) -> String {
    let mut out = format!("plan {} (lattice): {} ({:.3} s)\n  {}\n", r.query, r.status.name(), r.seconds, r.message);
    out += &format!(
        "  lattice: {} rays, {} component(s); {} of {} segments to cell corners verified; A* expanded {} points\n",
        r.rays, r.components, r.segments[0], r.segments[1], r.expanded
    );
    if !r.polyline.is_empty() {
        out += &format!("  A* polyline: {} points, length {:.6}; {} waypoints\n", r.polyline.len(), r.polyline_length, r.waypoints.len());
        out += &format!("  smoothed: {} piece(s) ({} single polyline edges) after {} repair(s)\n", r.pieces, r.polyline_pieces, r.repairs);
        for (i, c) in r.waypoints.iter().enumerate() {
            if r.joint_coordinates.is_empty() && c.len() == 6 {
                out += &format!("  {i:5}  p = [{:.6}, {:.6}, {:.6}]  (φ, θ, σ) = ({:.6}, {:.6}, {:.6})\n", c[0], c[1], c[2], c[3], c[4], c[5]);
            } else {
                let named: Vec<String> = r.joint_coordinates.iter().zip(c).map(|(n, x)| format!("{n} = {x:.6}")).collect();
                out += &format!("  {i:5}  {}\n", named.join(", "));
            }
        }
    }
    if let Some(v) = &r.verification {
        out += &format!("  verified: feasible t ∈ {}; infeasible t ∈ {}; uncertain t ∈ {}\n", intervals(&v.feasible), intervals(&v.infeasible), intervals(&v.uncertain));
    }
    out
}

/// The chart radius as the report prints it: `0.1–1` when adapted, `0.4` when fixed.
fn radii(p: &PlanParams) -> String {
    if p.min_radius < p.radius {
        format!("{}–{}", p.min_radius, p.radius)
    } else {
        format!("{}", p.radius)
    }
}

fn plan_text(r: &PlanReport) -> String {
    let status = r.status.name();
    let (a, p) = (&r.atlas, &r.atlas.params);
    let mut out = format!(
        "plan {}: {status} ({} charts, {}-D, {:.3} s; r = {}, ε = {}, δ = {}, w = {}, κ = {}, margins ≥ {}, ≤ {} charts)\n",
        r.query, r.charts, a.dimension, r.seconds, radii(p), p.epsilon, p.delta, p.heuristic_weight, p.barrier, p.min_margin, p.max_charts
    );
    match r.status {
        PlanStatus::Found => {
            let v = &r.verification;
            out += &format!("  path: {} poses; re-verified: {} edges, {} infeasible and {} uncertain sections; {} of {} poses wrench-infeasible",
                r.path.len(), v.edges, v.infeasible_sections, v.uncertain_sections, v.wrench_infeasible_poses, v.wrench_poses);
            if let Some(m) = v.least_wrench_margin {
                out += &format!(", least tension margin {m:.4}");
            }
            out += "\n";
            for (i, pose) in r.path.iter().enumerate() {
                let [x, y, z] = pose.position;
                let [a, b, c] = pose.tilt_torsion;
                out += &format!("  {i:5}  p = [{x:.6}, {y:.6}, {z:.6}]  (φ, θ, σ) = ({a:.6}, {b:.6}, {c:.6})\n");
            }
        }
        PlanStatus::NoPath => out += "  the atlas of the start's connected component is exhausted without reaching the goal: no path at this resolution\n",
        PlanStatus::Budget => out += "  the chart budget ran out: nothing is claimed (raise --max-charts)\n",
        PlanStatus::Unrepaired => {}
    }
    if a.expansion_failures > 0 {
        out += &format!("  warning: {} expansion direction(s) failed; a no_path here is not certified\n", a.expansion_failures);
    }
    if a.chart_radii[0] < a.chart_radii[1] {
        out += &format!("  chart radii adapted to the curvature: {:.3} to {:.3}\n", a.chart_radii[0], a.chart_radii[1]);
    }
    if a.blocked_charts > 0 {
        out += &format!("  note: {} chart(s) blocked by a clearance violation at their centre\n", a.blocked_charts);
    }
    if a.broken_edges > 0 {
        out += &format!("  warning: {} chart pair(s) or walk(s) to the goal dropped because their dense path could not be followed; a no_path here is not certified\n", a.broken_edges);
    }
    if a.rejected_edges > 0 {
        out += &format!("  note: {} chart pair(s) dropped because the exact verifier rejected their edge (interference)\n", a.rejected_edges);
    }
    out
}
