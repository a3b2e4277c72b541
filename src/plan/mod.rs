//! Path planning for a query of a scenario, laid out like OMPL: this module is the interface
//! (OMPL's `Planner`) and each planner a folder of its own. The CLI and the page pick the atlas
//! planner ([`atlas::AtlasPlanner`], Bohigas et al.) or the lattice planner
//! ([`lattice::LatticePlanner`], Zhang's thesis) by name ([`PlannerKind`], [`PlannerOptions`]),
//! step it ([`PathPlanner`]), and take its result ([`PlanResult`]) — a status, the planned
//! trajectory in the scenario format, and the planner's own report — without knowing what either
//! does inside, and neither planner knows what a condition is.

pub mod atlas;
pub mod lattice;
pub mod timing;

use crate::error::{Error, Result};
use crate::model::{JointPath, Orientation, Pose, Segment, Trajectory, Translation};
use crate::scenario::Scenario;
use atlas::{AtlasPlanner, PlanParams, PlanReport};
use lattice::{LatticeParams, LatticePlanReport, LatticePlanner};
use nalgebra::UnitQuaternion;
use serde::Serialize;

/// The planners on offer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PlannerKind {
    /// Henderson atlas + A* on the wrench-feasible C-space (6-cable platform robots with a wrench
    /// set).
    Atlas,
    /// Ray lattice + A* + Bézier smoothing, verified exactly (any robot; a multi-link robot's
    /// result is a path through configurations).
    Lattice,
}

impl PlannerKind {
    /// Parses `atlas` or `lattice`; the error names `--planner`.
    pub fn parse(name: &str) -> Result<PlannerKind> {
        match name {
            "atlas" => Ok(PlannerKind::Atlas),
            "lattice" => Ok(PlannerKind::Lattice),
            other => Err(Error::new("--planner", format!("{other:?} is not a planner; expected atlas or lattice"))),
        }
    }

    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            PlannerKind::Atlas => "atlas",
            PlannerKind::Lattice => "lattice",
        }
    }
}

/// Which planner, with the parameters of each.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlannerOptions {
    /// The planner to run.
    pub kind: PlannerKind,
    /// The atlas planner's parameters.
    pub atlas: PlanParams,
    /// The lattice planner's parameters.
    pub lattice: LatticeParams,
}

impl PlannerOptions {
    /// Default parameters for `kind`.
    pub fn new(kind: PlannerKind) -> PlannerOptions {
        PlannerOptions { kind, atlas: PlanParams::default(), lattice: LatticeParams::default() }
    }
}

/// The atlas planner's options as the Python and npm packages take them, each `None` for
/// [`PlanParams::default`]'s value (the CLI's defaults). Not checked here: the planner checks
/// them ([`PlanParams::validate`]) and `command::run` names the option at fault as the CLI does
/// (`--min-radius`, which the packages spell `min_radius` and `minRadius`).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AtlasOptions {
    /// Chart budget.
    pub max_charts: Option<usize>,
    /// Largest chart radius.
    pub radius: Option<f64>,
    /// Least chart radius the curvature adaptation gives.
    pub min_radius: Option<f64>,
    /// Weight w of the search's heuristic, f = g + w·h (1: A*).
    pub heuristic_weight: Option<f64>,
    /// Validity threshold ε.
    pub epsilon: Option<f64>,
    /// Angles as angles (true, the default) or as plain coordinates (false, paper 1's way).
    pub identify_angles: Option<bool>,
}

impl AtlasOptions {
    /// The parameters: each given option, the default for the others.
    pub fn params(&self) -> PlanParams {
        let d = PlanParams::default();
        PlanParams {
            max_charts: self.max_charts.unwrap_or(d.max_charts),
            radius: self.radius.unwrap_or(d.radius),
            min_radius: self.min_radius.unwrap_or(d.min_radius),
            heuristic_weight: self.heuristic_weight.unwrap_or(d.heuristic_weight),
            epsilon: self.epsilon.unwrap_or(d.epsilon),
            identify_angles: self.identify_angles.unwrap_or(d.identify_angles),
            ..d
        }
    }
}

/// How a front end's users choose each planner, for the messages that name them:
/// `--planner lattice` on the command line, `planner="lattice"` in Python, `the "lattice"
/// planner` in npm.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PlannerNaming {
    /// The atlas planner's.
    pub atlas: &'static str,
    /// The lattice planner's.
    pub lattice: &'static str,
}

/// The lattice planner's parameters for a plan request that may give `steps`, the grid values
/// per free coordinate ([`LatticeParams::default`]'s 7 when `None`): an option of the lattice
/// planner only. With another planner, `steps` is an error at `--steps` (the Python and npm
/// packages name it `steps`) saying that it "is an option of `lattice`", where `lattice` is how
/// the caller's users choose the lattice planner (`--planner lattice` on the command line,
/// `planner="lattice"` in Python). The one check of the CLI and both packages.
pub fn lattice_params(kind: PlannerKind, steps: Option<usize>, lattice: &str) -> Result<LatticeParams> {
    if steps.is_some() && kind != PlannerKind::Lattice {
        return Err(Error::new("--steps", format!("is an option of {lattice}")));
    }
    Ok(LatticeParams { steps: steps.unwrap_or(LatticeParams::default().steps), ..LatticeParams::default() })
}

/// The atlas planner's parameters for a plan request with planner `kind`: the given `options`
/// over the defaults. With another planner, any given atlas option is an error at its option
/// (`--max-charts`, `--radius`, `--min-radius`, `--heuristic-weight`, `--epsilon`,
/// `--identify-angles`; the packages
/// rename them to their parameters) saying that it "is an option of `atlas`", where `atlas` is how
/// the caller's users choose the atlas planner: an option that would be ignored is refused, as
/// [`lattice_params`] refuses `steps`. The one check of the CLI and both packages.
pub fn atlas_params(kind: PlannerKind, options: &AtlasOptions, atlas: &str) -> Result<PlanParams> {
    if kind != PlannerKind::Atlas {
        let given = [
            ("--max-charts", options.max_charts.is_some()),
            ("--radius", options.radius.is_some()),
            ("--min-radius", options.min_radius.is_some()),
            ("--heuristic-weight", options.heuristic_weight.is_some()),
            ("--epsilon", options.epsilon.is_some()),
            ("--identify-angles", options.identify_angles.is_some()),
        ];
        if let Some((flag, _)) = given.iter().find(|(_, g)| *g) {
            return Err(Error::new(*flag, format!("is an option of {atlas}")));
        }
    }
    Ok(options.params())
}

/// How planning ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PlanStatus {
    /// A path from start to goal was found.
    Found,
    /// The atlas of the start's connected component was exhausted without reaching the goal: no
    /// path exists at this resolution (radius, ε, auxiliary bound).
    NoPath,
    /// The chart budget ran out first: nothing is claimed.
    Budget,
    /// A path was found, but some section of it could not be made to verify (the lattice
    /// planner's smoothed trajectory after every repair): the report says which.
    Unrepaired,
}

impl PlanStatus {
    /// The name reports use (as it serialises): `found`, `no_path`, `budget`, `unrepaired`.
    pub fn name(self) -> &'static str {
        match self {
            PlanStatus::Found => "found",
            PlanStatus::NoPath => "no_path",
            PlanStatus::Budget => "budget",
            PlanStatus::Unrepaired => "unrepaired",
        }
    }
}

/// Progress of any planner.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlanProgress {
    /// What it is doing, in a few words (`3 charts, 12 open`, `lattice: 40 of 147 rays`).
    pub stage: String,
    /// A fraction of the work done, for a progress bar (an estimate; 1 when done).
    pub fraction: f64,
    /// The status once finished.
    pub done: Option<PlanStatus>,
}

/// A planner's own report.
// one value per planning run: the variants' sizes do not matter enough to box them
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Details {
    /// The atlas planner's.
    Atlas(PlanReport),
    /// The lattice planner's.
    Lattice(LatticePlanReport),
}

/// What a planner returns.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanResult {
    /// How it ended.
    pub status: PlanStatus,
    /// The planned motion as a scenario trajectory (the atlas' path as line + slerp pieces, the
    /// lattice's smoothed pieces), when there is one (a platform robot's).
    pub trajectory: Option<Trajectory>,
    /// A multi-link robot's planned motion: a path through configurations (the lattice
    /// planner's), when there is one.
    pub joint_path: Option<JointPath>,
    /// The planner's report.
    pub details: Details,
}

/// A resumable planner for one query at a time.
pub trait PathPlanner {
    /// Advances by at most `budget` units of work (each bounded; see the planner's docs).
    fn step(&mut self, budget: usize) -> PlanProgress;
    /// The result once `step` reported `done`; `seconds` is the wall-clock time the caller
    /// measured, for the report.
    fn result(&self, seconds: f64) -> Option<PlanResult>;
    /// Turns to query `query` of `scenario` (the same robot and surroundings, its poses and
    /// queries perhaps edited), keeping what the planner has built that the query can use (the
    /// atlas planner's atlas, on the same slice): `Ok(true)`, ready to step; `Ok(false)`,
    /// unchanged, when nothing carries over (make a fresh planner); an error when the query is
    /// unusable, as the planner's constructor would report it.
    fn requery(&mut self, _scenario: &Scenario, _query: &str) -> Result<bool> {
        Ok(false)
    }
    /// The atlas planner behind this one, if it is one (to save its atlas, `atlas::file`; a
    /// reference, so that code using planners without files, the page's, links no file code).
    fn as_atlas(&self) -> Option<&AtlasPlanner> {
        None
    }
}

/// The atlas planner behind the common interface.
struct AtlasPathPlanner {
    planner: AtlasPlanner,
    query: String,
    /// The least heuristic before any work (the start's distance to the goal), for the fraction.
    first_h: f64,
}

impl PathPlanner for AtlasPathPlanner {
    fn step(&mut self, budget: usize) -> PlanProgress {
        let p = self.planner.step(budget);
        let first = self.first_h;
        let fraction = if p.done.is_some() {
            1.0
        } else if first.is_finite() && first > 0.0 && p.best_heuristic.is_finite() {
            (1.0 - p.best_heuristic / first).clamp(0.0, 0.99)
        } else {
            0.0
        };
        let stage = match p.verifying {
            Some((done, all)) => format!("re-verifying the path: {done} of {all} edges"),
            None => format!("{} charts, {} open", p.charts, p.open),
        };
        PlanProgress { stage, fraction, done: p.done }
    }

    fn result(&self, seconds: f64) -> Option<PlanResult> {
        let o = self.planner.outcome()?;
        let pieces: Vec<Segment> = o
            .path
            .windows(2)
            .enumerate()
            .map(|(i, w)| {
                let t = edge_trajectory(i, &w[0], &w[1]);
                Segment { translation: t.translation, orientation: t.orientation }
            })
            .collect();
        let trajectory = (o.status == PlanStatus::Found).then(|| Trajectory::piecewise(format!("{}-atlas", self.query), pieces)).flatten();
        Some(PlanResult { status: o.status, trajectory, joint_path: None, details: Details::Atlas(o.report(&self.query, seconds)) })
    }

    fn as_atlas(&self) -> Option<&AtlasPlanner> {
        Some(&self.planner)
    }

    fn requery(&mut self, scenario: &Scenario, query: &str) -> Result<bool> {
        if !self.planner.requery(scenario, query)? {
            return Ok(false);
        }
        self.query = query.to_string();
        self.first_h = self.planner.step(0).best_heuristic;
        Ok(true)
    }
}

impl PathPlanner for LatticePlanner {
    fn step(&mut self, budget: usize) -> PlanProgress {
        let p = LatticePlanner::step(self, budget);
        // the lattice's rays are most of the work; the rest is shared out evenly
        let (lo, width) = match p.stage {
            "lattice" => (0.0, 0.7),
            "join" => (0.7, 0.1),
            "search" => (0.8, 0.0),
            "smooth" => (0.8, 0.15),
            _ => (0.95, 0.05),
        };
        let part = p.total_units.filter(|&t| t > 0).map_or(0.0, |t| p.done_units as f64 / t as f64);
        let fraction = if p.done.is_some() { 1.0 } else { lo + width * part.min(1.0) };
        let stage = match p.total_units {
            Some(t) => format!("{}: {} of {t}", p.stage, p.done_units),
            None => format!("{}: {} points expanded", p.stage, p.done_units),
        };
        PlanProgress { stage, fraction, done: p.done }
    }

    fn result(&self, seconds: f64) -> Option<PlanResult> {
        let report = self.report(seconds)?;
        let planned = report.status != PlanStatus::NoPath;
        let trajectory = if planned { self.trajectory().cloned() } else { None };
        let joint_path = if planned { self.joint_path().cloned() } else { None };
        Some(PlanResult { status: report.status, trajectory, joint_path, details: Details::Lattice(report) })
    }
}

/// The planner `options.kind` for query `query` of `scenario`, ready to step. A multi-link robot
/// is planned by the lattice planner only (the atlas planner's charts are of platform poses).
pub fn planner(scenario: &Scenario, query: &str, options: &PlannerOptions) -> Result<Box<dyn PathPlanner>> {
    if options.kind == PlannerKind::Atlas && scenario.robot.chain.is_some() {
        return Err(Error::new("planner", "the atlas planner is for platform robots; a multi-link robot is planned by the lattice planner"));
    }
    Ok(match options.kind {
        PlannerKind::Atlas => atlas_path_planner(AtlasPlanner::new(scenario, query, options.atlas)?, query),
        PlannerKind::Lattice => Box::new(LatticePlanner::new(scenario, query, options.lattice)?),
    })
}

/// [`planner`], the atlas planner starting from the atlas file `atlas`
/// ([`AtlasPlanner::with_atlas`]; the lattice planner keeps no atlas and ignores it).
pub fn planner_from(scenario: &Scenario, query: &str, options: &PlannerOptions, atlas: &str) -> Result<Box<dyn PathPlanner>> {
    match options.kind {
        PlannerKind::Atlas => Ok(atlas_path_planner(AtlasPlanner::with_atlas(scenario, query, options.atlas, atlas)?, query)),
        PlannerKind::Lattice => planner(scenario, query, options),
    }
}

/// The atlas planner for `query` behind the common interface.
fn atlas_path_planner(mut planner: AtlasPlanner, query: &str) -> Box<dyn PathPlanner> {
    let first_h = planner.step(0).best_heuristic;
    Box::new(AtlasPathPlanner { planner, query: query.to_string(), first_h })
}

/// Runs a planner to the end (CLI, tests); `clock` gives seconds (for the report).
pub fn run(scenario: &Scenario, query: &str, options: &PlannerOptions, clock: &dyn Fn() -> f64) -> Result<PlanResult> {
    let (mut results, _) = run_queries(scenario, &[query.to_string()], options, None, clock, &mut |_| {})?;
    results.pop().ok_or_else(|| Error::new("plan", "the planner stopped without a result"))
}

/// Plans `queries` in order with one planner, each later query keeping what the planner built
/// for the earlier ones where it can ([`PathPlanner::requery`]: the atlas of the same slice);
/// `clock` gives seconds, each result's report has its own query's time. `progress` hears each
/// step's progress. With `atlas` (an atlas file's text, empty when there is none yet) the first
/// query starts from that atlas where it can ([`planner_from`]), and the atlas at the end is
/// returned as a file (`None` without `atlas`, or from a planner that keeps none).
pub fn run_queries(
    scenario: &Scenario,
    queries: &[String],
    options: &PlannerOptions,
    atlas: Option<&str>,
    clock: &dyn Fn() -> f64,
    progress: &mut dyn FnMut(&PlanProgress),
) -> Result<(Vec<PlanResult>, Option<String>)> {
    let mut current: Option<Box<dyn PathPlanner>> = None;
    let mut results = Vec::with_capacity(queries.len());
    for query in queries {
        let started = clock();
        let kept = match current.as_mut() {
            Some(p) => p.requery(scenario, query)?,
            None => false,
        };
        if !kept {
            let file = if current.is_none() { atlas.filter(|t| !t.trim().is_empty()) } else { None };
            current = Some(match file {
                Some(text) => planner_from(scenario, query, options, text)?,
                None => planner(scenario, query, options)?,
            });
        }
        let p = current.as_mut().ok_or_else(|| Error::new("plan", "no planner"))?;
        loop {
            let step = p.step(1000);
            if step.done.is_some() {
                break;
            }
            progress(&step);
        }
        results.push(p.result(clock() - started).ok_or_else(|| Error::new("plan", "the planner stopped without a result"))?);
    }
    let saved = atlas.and_then(|_| Some(current.as_ref()?.as_atlas()?.save_atlas()));
    Ok((results, saved))
}

/// The trajectory between two consecutive path poses: linear translation and the short slerp.
pub(crate) fn edge_trajectory(index: usize, a: &Pose, b: &Pose) -> Trajectory {
    let qb = if a.rotation.quaternion().dot(b.rotation.quaternion()) < 0.0 {
        UnitQuaternion::new_unchecked(-b.rotation.into_inner())
    } else {
        b.rotation
    };
    Trajectory::single(format!("edge {index}"), Translation::Line(a.position, b.position), Orientation::Slerp(a.rotation, qb))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_only_with_the_lattice_planner() {
        let e = lattice_params(PlannerKind::Atlas, Some(9), "--planner lattice").unwrap_err();
        assert_eq!((e.field.as_str(), e.reason.as_str()), ("--steps", "is an option of --planner lattice"));
        assert_eq!(lattice_params(PlannerKind::Atlas, None, "-").unwrap(), LatticeParams::default());
        assert_eq!(lattice_params(PlannerKind::Lattice, Some(9), "-").unwrap().steps, 9);
        assert_eq!(lattice_params(PlannerKind::Lattice, None, "-").unwrap().steps, 7);
    }

    #[test]
    fn atlas_options_fill_in_the_defaults() {
        assert_eq!(AtlasOptions::default().params(), PlanParams::default());
        let p = AtlasOptions { min_radius: Some(0.3), heuristic_weight: Some(1.0), ..AtlasOptions::default() }.params();
        assert_eq!((p.min_radius, p.heuristic_weight, p.radius), (0.3, 1.0, PlanParams::default().radius));
        let p = AtlasOptions { max_charts: Some(5), radius: Some(0.5), epsilon: Some(0.2), ..AtlasOptions::default() }.params();
        // with the lattice planner an atlas option is refused, not ignored
        let o = AtlasOptions { heuristic_weight: Some(2.0), ..AtlasOptions::default() };
        let e = atlas_params(PlannerKind::Lattice, &o, "--planner atlas").unwrap_err();
        assert_eq!((e.field.as_str(), e.reason.as_str()), ("--heuristic-weight", "is an option of --planner atlas"));
        assert_eq!(atlas_params(PlannerKind::Lattice, &AtlasOptions::default(), "x").unwrap(), PlanParams::default());
        assert_eq!(atlas_params(PlannerKind::Atlas, &o, "x").unwrap(), o.params());
        assert_eq!((p.max_charts, p.radius, p.epsilon, p.min_radius), (5, 0.5, 0.2, PlanParams::default().min_radius));
    }
}
