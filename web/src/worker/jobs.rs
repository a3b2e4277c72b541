//! Running a [`Job`] to its end, reporting [`Reply`]s as it goes: plain Rust over the core,
//! tested natively (the worker calls [`run`]; so do the tests).

use super::protocol::{pose_to_wire, Job, LatticeResult, PlannedTrajectory, RaySections, Reply, SliceSpec, WireAtlas, WireChart, WireReport};
use cablenav::lattice::{Lattice, LatticeSpec};
use crate::logic::fmt_num;
use cablenav::model::Pose;
use cablenav::plan::{Details, PathPlanner, PlanProgress, PlanResult, PlannerKind, PlannerOptions};
use cablenav::plan::{atlas::PathPose, PlanStatus};
use nalgebra::{Quaternion, UnitQuaternion};
use cablenav::Scenario;

/// Milliseconds of work between two progress replies.
pub const PROGRESS_MS: f64 = 50.0;

/// Poses sampled along a planned trajectory for the page's view and plots (the lattice planner's
/// smoothed pieces; the atlas' path is sent as its own poses).
const PATH_SAMPLES: usize = 200;

/// How a planning run ended, as the page shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct Finished {
    /// `found`, `no_path`, `budget` or `unrepaired`.
    pub status: &'static str,
    /// One line for people.
    pub summary: String,
    /// The path, start to goal (empty when there is none).
    pub path: Vec<Pose>,
    /// The lattice planner's A* polyline (empty for the atlas).
    pub polyline: Vec<Pose>,
}

/// The core's planner kind for a page planner id (of [`crate::state::PLANNERS`]).
pub fn kind_of(id: &str) -> Option<PlannerKind> {
    match id {
        "continuation" => Some(PlannerKind::Atlas),
        "ray-lattice" => Some(PlannerKind::Lattice),
        _ => None,
    }
}

/// The planner `id` set up for query `query`, behind the core's common interface: the atlas with
/// at most `max_charts` charts and its angles identified or not (`identify_angles`), the lattice
/// with `steps` grid values per free coordinate (checked by the core, which refuses a count out of
/// range as `cablenav plan --steps` does).
pub fn planner(id: &str, s: &Scenario, query: &str, max_charts: usize, steps: usize, identify_angles: bool) -> Result<Box<dyn PathPlanner>, String> {
    let kind = kind_of(id).ok_or_else(|| format!("the planner “{id}” is not available"))?;
    let mut options = PlannerOptions::new(kind);
    options.atlas.max_charts = max_charts;
    options.atlas.identify_angles = identify_angles;
    options.lattice.steps = steps;
    cablenav::plan::planner(s, query, &options).map_err(|e| e.to_string())
}

/// One line describing a result.
pub fn summary(r: &PlanResult) -> String {
    match &r.details {
        Details::Atlas(o) => {
            let v = &o.verification;
            match o.status {
                PlanStatus::Found => format!(
                    "Path found: {} poses, {} charts{}. Re-verified: {} edge(s), {} infeasible and {} uncertain section(s); {} of {} poses wrench-infeasible{}.",
                    o.path.len(),
                    o.charts,
                    kept(o.atlas.reused_charts),
                    v.edges,
                    v.infeasible_sections,
                    v.uncertain_sections,
                    v.wrench_infeasible_poses,
                    v.wrench_poses,
                    v.least_wrench_margin.map_or(String::new(), |m| format!(", least wrench margin {}", fmt_num(m)))
                ),
                PlanStatus::NoPath => format!("No path at this resolution: the start's component was exhausted after {} charts{}.", o.charts, kept(o.atlas.reused_charts)),
                PlanStatus::Budget => format!("Chart budget exhausted after {} charts: nothing is claimed.", o.charts),
                PlanStatus::Unrepaired => "The path could not be verified feasible everywhere.".to_string(),
            }
        }
        Details::Lattice(l) => match l.status {
            PlanStatus::Found | PlanStatus::Unrepaired => format!(
                "{}. A* polyline: {} points; smoothed into {} piece(s) after {} repair(s); {} rays, {} component(s).",
                capitalised(&l.message),
                l.polyline.len(),
                l.pieces,
                l.repairs,
                l.rays,
                l.components
            ),
            _ => format!("{}.", capitalised(&l.message)),
        },
    }
}

/// How many of an atlas's charts were kept from earlier runs, for a summary ("" for none).
fn kept(reused: usize) -> String {
    if reused == 0 { String::new() } else { format!(" ({reused} kept from earlier runs)") }
}

fn capitalised(s: &str) -> String {
    let mut c = s.chars();
    c.next().map_or(String::new(), |f| f.to_uppercase().chain(c).collect())
}

/// What the page shows of a result: the atlas' path poses, or the lattice planner's smoothed
/// trajectory at [`PATH_SAMPLES`] + 1 poses with its A* polyline.
pub fn finished(r: &PlanResult) -> Finished {
    let (path, polyline) = match (&r.details, &r.trajectory) {
        (_, None) => (vec![], vec![]),
        (Details::Atlas(o), Some(_)) => (o.path.iter().map(path_pose).collect(), vec![]),
        (Details::Lattice(l), Some(traj)) => (
            (0..=PATH_SAMPLES).map(|k| traj.pose_at(k as f64 / PATH_SAMPLES as f64)).collect(),
            l.polyline.iter().map(|c| Pose::from_coords(std::array::from_fn(|i| c.get(i).copied().unwrap_or(0.0)))).collect(),
        ),
    };
    Finished { status: r.status.name(), summary: summary(r), path, polyline }
}

/// The pose a report's path pose states, bit for bit (its quaternion is a unit quaternion's
/// coordinates, taken as they are rather than normalised again).
fn path_pose(p: &PathPose) -> Pose {
    let [w, i, j, k] = p.quaternion;
    Pose { position: p.position.into(), rotation: UnitQuaternion::new_unchecked(Quaternion::new(w, i, j, k)) }
}

/// Progress as a fraction for the bar, never going back, below 1 until the end.
pub fn fraction(p: &PlanProgress, shown: f64) -> f64 {
    if p.done.is_some() {
        return 1.0;
    }
    p.fraction.clamp(0.0, 0.99).max(shown)
}

/// Runs `job` to its end: progress replies at most every [`PROGRESS_MS`] of work (by `now`, in
/// ms), then the final reply.
pub fn run(job: Job, report: &mut dyn FnMut(Reply), now: fn() -> f64) {
    let last = match job {
        Job::Plan { scenario, query, planner: id, max_charts, steps, identify_angles } => plan(&scenario, &query, &id, [max_charts, steps], identify_angles, report, now),
        Job::Slice { map, rows } => slice_rows(&map, rows),
        Job::Singular { map } => singular(&map),
        Job::LatticeRays { scenario, pose, axes, ranges, steps, rays } => {
            lattice_rays(&scenario, &pose, &axes, ranges, steps, rays, report, now)
        }
        Job::Profiles { scenario, name, samples, trajectory } => profiles(&scenario, &name, &samples, trajectory.as_deref()),
        Job::Verify { scenario, index } => Ok(verify(&scenario, index, now)),
        Job::VerifyEvery { scenario } => verify_every(&scenario, report, now),
        Job::Time { scenario, index } => Ok(fastest_timing(&scenario, index, report, now)),
    };
    report(last.unwrap_or_else(|error| Reply::Failed { error }));
}

/// Trajectory `index` (clamped) of the scenario, verified exactly at its own timing (without the
/// search of the least time scale, which the page runs when the drag ends), timed by `now`.
fn verify(json: &str, index: usize, now: fn() -> f64) -> Reply {
    let started = now();
    let report = scenario(json).and_then(|s| {
        let i = crate::logic::trajectory_index(&s, index).ok_or("the scenario has no trajectory")?;
        crate::logic::verify_sections(&s, i)
    });
    Reply::Verified { report: report.as_ref().map(WireReport::from).map_err(Clone::clone), ms: now() - started }
}

/// Trajectory `index` (clamped) of the scenario timed as fast as its limits allow, certified
/// (`cablenav time` with its defaults), timed by `now`; each certification round reported as it
/// starts (round r at fraction 1 − 1/(1 + r): rising, below 1).
fn fastest_timing(json: &str, index: usize, report: &mut dyn FnMut(Reply), now: fn() -> f64) -> Reply {
    let started = now();
    let mut hear = |p: cablenav::plan::timing::TimingProgress| {
        if p.done == 0 {
            let fraction = 1.0 - 1.0 / (1.0 + p.round as f64);
            report(Reply::Progress { fraction, detail: format!("certifying: round {}, {} cells", p.round + 1, p.total) });
        }
    };
    let report = scenario(json).and_then(|s| {
        let i = crate::logic::trajectory_index(&s, index).ok_or("the scenario has no trajectory")?;
        let options = cablenav::plan::timing::TimingOptions::default();
        cablenav::plan::timing::fastest_reporting(&s, &s.trajectories[i], options, &mut hear).map(|(r, _)| r).map_err(|e| e.to_string())
    });
    let ms = now() - started;
    match report {
        Ok(r) => Reply::Timed { report: serde_json::to_string(&r).unwrap_or_default(), error: String::new(), ms },
        Err(error) => Reply::Timed { report: String::new(), error, ms },
    }
}

fn verify_every(json: &str, report: &mut dyn FnMut(Reply), now: fn() -> f64) -> Result<Reply, String> {
    let s = scenario(json)?;
    let n = s.trajectories.len();
    let mut since = now();
    let reports = (0..n)
        .map(|i| {
            if now() - since >= PROGRESS_MS {
                report(Reply::Progress { fraction: i as f64 / n as f64, detail: format!("{i} of {n} trajectories verified") });
                since = now();
            }
            crate::logic::verify_sections(&s, i).as_ref().map(WireReport::from).map_err(Clone::clone)
        })
        .collect();
    Ok(Reply::VerifiedEvery { reports })
}

fn scenario(json: &str) -> Result<Scenario, String> {
    Scenario::from_json(json).map_err(|e| e.to_string())
}

thread_local! {
    /// The planner of the worker's last plan job and its options (planner id, chart budget,
    /// steps, angles identified): a later job with the same options turns it to its query
    /// ([`PathPlanner::requery`]), so the atlas planner answers from the atlas it kept.
    static KEPT: std::cell::RefCell<Option<(String, Box<dyn PathPlanner>)>> = const { std::cell::RefCell::new(None) };
}

fn plan(json: &str, query: &str, id: &str, [max_charts, steps]: [usize; 2], identify_angles: bool, report: &mut dyn FnMut(Reply), now: fn() -> f64) -> Result<Reply, String> {
    let s = scenario(json)?;
    let started = now();
    let options = format!("{id} {max_charts} {steps} {identify_angles}");
    // the kept planner turned to this query, else a fresh one
    let mut kept = KEPT.with_borrow_mut(Option::take).filter(|(key, _)| *key == options);
    let reused = match kept.as_mut().map(|(_, p)| p.requery(&s, query)) {
        Some(Err(e)) => {
            KEPT.set(kept);
            return Err(e.to_string());
        }
        Some(Ok(true)) => kept.map(|(_, p)| p),
        _ => None,
    };
    let mut p = match reused {
        Some(p) => p,
        None => planner(id, &s, query, max_charts, steps, identify_angles)?,
    };
    let mut shown = 0.0;
    let mut since = started;
    // the charts sent so far: the atlas is watched as it grows
    let mut sent = 0;
    loop {
        let step = p.step(1);
        shown = fraction(&step, shown);
        let done = step.done.is_some();
        if done || now() - since >= PROGRESS_MS {
            report(Reply::Progress { fraction: shown, detail: step.stage });
            since = now();
            if let Some(atlas) = p.as_atlas().filter(|_| !done) {
                let (coords, charts) = atlas.charts_since(sent);
                if !charts.is_empty() && WireAtlas::drawn(&coords) {
                    report(Reply::Charts { coords, from: sent, charts: charts.iter().map(WireChart::of).collect() });
                    sent += charts.len();
                }
            }
        }
        if done {
            break;
        }
    }
    let r = p.result((now() - started) / 1000.0).ok_or("the planner ended without a result")?;
    KEPT.set(Some((options, p)));
    let f = finished(&r);
    let trajectory = match (&r.trajectory, &r.joint_path) {
        (Some(t), _) => Some(Box::new(planned_trajectory(json, t)?)),
        (None, Some(p)) => Some(Box::new(planned_path(json, p)?)),
        (None, None) => None,
    };
    let atlas = match &r.details {
        Details::Atlas(report) => WireAtlas::of(&report.atlas_charts),
        Details::Lattice(_) => None,
    };
    Ok(Reply::Planned {
        status: f.status.to_string(),
        summary: f.summary,
        path: f.path.iter().map(pose_to_wire).collect(),
        polyline: f.polyline.iter().map(pose_to_wire).collect(),
        trajectory,
        atlas,
    })
}

/// The scenario `json` with the planned trajectory `t` added (as `cablenav plan --out` writes
/// it) and the exact verification of that trajectory there, read back from the written text as
/// `cablenav verify` reads it.
pub fn planned_trajectory(json: &str, t: &cablenav::model::Trajectory) -> Result<PlannedTrajectory, String> {
    let written = cablenav::scenario::with_trajectory(json, t).map_err(|e| e.to_string())?;
    verified_in(written, "the planned trajectory", |s, name| s.trajectories.iter().position(|x| x.name == name))
}

/// A multi-link robot's planned path as [`planned_trajectory`] has a platform's: the scenario
/// with the path through new configurations added (as `cablenav plan --out` writes it) and its
/// exact verification there.
pub fn planned_path(json: &str, p: &cablenav::model::JointPath) -> Result<PlannedTrajectory, String> {
    let written = cablenav::scenario::with_joint_path(json, p).map_err(|e| e.to_string())?;
    verified_in(written, "the planned path", |s, name| s.joint_paths.iter().position(|x| x.name == name))
}

/// The written scenario `text` and the exact verification of its motion `name` (`what`, for the
/// error), found at the index `index` gives.
fn verified_in((text, name): (String, String), what: &str, index: impl Fn(&Scenario, &str) -> Option<usize>) -> Result<PlannedTrajectory, String> {
    let s = scenario(&text)?;
    let index = index(&s, &name).ok_or_else(|| format!("{what} is missing from the written scenario"))?;
    let report = crate::logic::verify(&s, index).map(|r| WireReport::from(&r));
    Ok(PlannedTrajectory { scenario: text, name, report })
}

fn profiles(json: &str, name: &str, samples: &[(f64, [u64; 7])], trajectory: Option<&str>) -> Result<Reply, String> {
    use cablenav::verify::profile::{clearances_at, tension_at};
    let s = scenario(json)?;
    let samples: Vec<(f64, Pose)> = samples.iter().map(|(t, p)| (*t, super::protocol::pose_from_wire(p))).collect();
    let clearances = clearances_at(&s, &samples).map(Into::into).map_err(|e| e.to_string());
    // a timed trajectory's tensions with its inertia, as `cablenav envelope` gives them
    let timed = trajectory.and_then(|n| s.trajectory(Some(n)).ok()).filter(|t| t.duration.is_some());
    let tension = match timed {
        Some(traj) => cablenav::verify::tension_envelope(&s, traj, samples.len().saturating_sub(1)).map(|mut e| {
            e.trajectory = name.to_string();
            e
        }),
        None => tension_at(&s, name, &samples),
    };
    let tension = tension.map(Into::into).map_err(|e| e.to_string());
    Ok(Reply::Profiles { clearances, tension })
}

/// The checked lattice request of a [`Job::LatticeRays`] (the page checks it before starting
/// workers; each worker checks it again).
pub fn lattice_spec(s: &Scenario, pose: &str, axes: &[String], ranges: Vec<[f64; 2]>, steps: usize) -> Result<LatticeSpec, String> {
    let coords = axes.iter().map(|n| s.coord("axes", n).map_err(|_| format!("unknown coordinate “{n}”"))).collect::<Result<Vec<_>, _>>()?;
    let at = s.config(pose).map_err(|e| e.to_string())?;
    LatticeSpec::new(coords, ranges, vec![steps], at).map_err(|e| e.to_string())
}

#[allow(clippy::too_many_arguments)]
fn lattice_rays(
    json: &str,
    pose: &str,
    axes: &[String],
    ranges: Vec<[f64; 2]>,
    steps: usize,
    rays: [usize; 2],
    report: &mut dyn FnMut(Reply),
    now: fn() -> f64,
) -> Result<Reply, String> {
    let s = scenario(json)?;
    let spec = lattice_spec(&s, pose, axes, ranges, steps)?;
    let total = spec.ray_count() as usize;
    if rays[0] > rays[1] || rays[1] > total {
        return Err(format!("rays {}..{} of a lattice of {total}", rays[0], rays[1]));
    }
    let l = Lattice::new(&s, spec);
    let mut sections = Vec::with_capacity(rays[1] - rays[0]);
    let mut since = now();
    for r in rays[0]..rays[1] {
        let (a, cell) = l.spec.ray_at(r);
        let sec = l.cast(&l.spec.coords(&cell), a);
        sections.push(RaySections::new(&sec.feasible, &sec.uncertain));
        if now() - since >= PROGRESS_MS {
            let done = sections.len();
            report(Reply::Progress { fraction: done as f64 / (rays[1] - rays[0]).max(1) as f64, detail: format!("{done} of {} rays", rays[1] - rays[0]) });
            since = now();
        }
    }
    Ok(Reply::LatticeRays { rays, sections })
}

/// The lattice of `spec` from every ray's sections (in ray order, as [`Job::LatticeRays`] blocks
/// give them): the core's graph and components over them, as the page draws it.
pub fn join_lattice(s: &Scenario, spec: LatticeSpec, sections: &[RaySections]) -> Result<LatticeResult, String> {
    let total = spec.ray_count() as usize;
    if sections.len() != total {
        return Err(format!("{} ray(s) for a lattice of {total}", sections.len()));
    }
    let mut l = Lattice::new(s, spec);
    l.rays = sections
        .iter()
        .enumerate()
        .map(|(r, sec)| l.ray_with(r, sec.feasible(), sec.uncertain()))
        .collect();
    // every ray is there: this step computes none and builds the graph
    l.step(1);
    l.report().map(|r| LatticeResult::of(s, &r)).ok_or_else(|| "the lattice's graph was not built".to_string())
}

fn slice_rows(map: &SliceSpec, rows: [usize; 2]) -> Result<Reply, String> {
    let (s, axes) = slice_axes(map)?;
    let classes = cablenav::verify::slice::slice_rows(&s, &map.pose, axes, map.res, map.range, rows[0]..rows[1]).map_err(|e| e.to_string())?;
    Ok(Reply::Sliced { rows, classes })
}

fn singular(map: &SliceSpec) -> Result<Reply, String> {
    let (s, axes) = slice_axes(map)?;
    let curves = cablenav::verify::singular::singularity_curves(&s, &map.pose, axes, map.res, map.range).map_err(|e| e.to_string())?;
    Ok(Reply::Singular { curves })
}

/// The scenario of a slice map and its two axes, by name.
fn slice_axes(map: &SliceSpec) -> Result<(Scenario, [cablenav::model::Coord; 2]), String> {
    let s = scenario(&map.scenario)?;
    let coord = |n: &str| s.coord("axes", n).map_err(|_| format!("unknown coordinate “{n}”"));
    let axes = [coord(&map.axes[0])?, coord(&map.axes[1])?];
    Ok((s, axes))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::{find, PRESETS};

    fn clock() -> f64 {
        0.0
    }

    #[test]
    fn the_bar_only_moves_forward() {
        let step = |fraction: f64, done: bool| PlanProgress { stage: String::new(), fraction, done: done.then_some(PlanStatus::Found) };
        assert_eq!(fraction(&step(0.0, false), 0.0), 0.0);
        assert_eq!(fraction(&step(0.5, false), 0.0), 0.5);
        assert_eq!(fraction(&step(0.25, false), 0.5), 0.5, "a worse front does not move it back");
        assert_eq!(fraction(&step(1.0, false), 0.5), 0.99, "full only when done");
        assert_eq!(fraction(&step(0.3, true), 0.5), 1.0);
    }

    #[test]
    fn a_plan_job_finds_robocrane_q1_q2_and_ends_at_the_query() {
        let json = PRESETS[find("robocrane").unwrap()].json;
        let mut replies = vec![];
        run(Job::Plan { scenario: json.into(), query: "q1-q2".into(), planner: "continuation".into(), max_charts: 20_000, steps: 7, identify_angles: true }, &mut |r| replies.push(r), clock);
        let Some(Reply::Planned { status, summary, path, polyline, trajectory, .. }) = replies.last() else { panic!("{replies:?}") };
        assert!(polyline.is_empty(), "the atlas has no A* polyline");
        assert!(trajectory.as_ref().is_some_and(|t| t.report.is_ok()), "the atlas' path as a trajectory, verified");
        assert_eq!(status, "found");
        assert!(summary.starts_with("Path found:"), "{summary}");
        let s = Scenario::from_json(json).unwrap();
        assert_eq!(super::super::protocol::pose_from_wire(&path[0]), *s.pose("q1").unwrap());
        assert_eq!(super::super::protocol::pose_from_wire(path.last().unwrap()), *s.pose("q2").unwrap());
        let bar: Vec<f64> = replies.iter().filter_map(|r| if let Reply::Progress { fraction, .. } = r { Some(*fraction) } else { None }).collect();
        assert!(bar.windows(2).all(|w| w[0] <= w[1]) && bar.last() == Some(&1.0), "{bar:?}");
    }

    #[test]
    fn a_lattice_plan_job_sends_the_smoothed_path_and_the_polyline() {
        let json = PRESETS[find("cdpr7-box").unwrap()].json;
        let mut replies = vec![];
        run(Job::Plan { scenario: json.into(), query: "over-box".into(), planner: "ray-lattice".into(), max_charts: 1, steps: 7, identify_angles: true }, &mut |r| replies.push(r), clock);
        let Some(Reply::Planned { status, summary, path, polyline, trajectory, .. }) = replies.last() else { panic!("{replies:?}") };
        assert_eq!(status, "found", "{summary}");
        // the planned trajectory, written into the scenario, verifies feasible on all of [0, 1]
        // exactly as the core verifies it there
        let planned = trajectory.as_ref().expect("a trajectory");
        let written = Scenario::from_json(&planned.scenario).unwrap();
        let k = written.trajectories.iter().position(|t| t.name == planned.name).unwrap();
        let direct = crate::logic::verify(&written, k).unwrap();
        assert_eq!(planned.report.as_ref().unwrap().report(), direct);
        assert_eq!(direct.feasible, [[0.0, 1.0]], "{direct:?}");
        assert_eq!(path.len(), PATH_SAMPLES + 1);
        assert!(polyline.len() >= 3, "the A* path turns over the box");
        let s = Scenario::from_json(json).unwrap();
        let end = |w: &[u64; 7], name: &str| (super::super::protocol::pose_from_wire(w).position - s.pose(name).unwrap().position).norm();
        assert!(end(&path[0], "box-left") < 1e-12 && end(path.last().unwrap(), "box-right") < 1e-12);
    }

    #[test]
    fn a_multi_link_plan_job_sends_the_path_through_configurations() {
        // the thesis' arm with a query in its upper region (as tests/joint_plan.rs has it)
        let mut v: serde_json::Value = serde_json::from_str(PRESETS[find("bmarm-x4-2").unwrap()].json).unwrap();
        let (g, t) = (-std::f64::consts::PI / 12.0, std::f64::consts::PI / 12.0);
        v["configurations"]["ul"] = serde_json::json!({"alpha": -0.1, "beta": 0.75, "gamma": g, "theta": t});
        v["configurations"]["lr"] = serde_json::json!({"alpha": 0.59, "beta": 0.22, "gamma": g, "theta": t});
        v["queries"] = serde_json::json!([{"name": "around", "start": "ul", "goal": "lr", "fixed": ["gamma", "theta"]}]);
        let json = v.to_string();
        let mut replies = vec![];
        run(Job::Plan { scenario: json.clone(), query: "around".into(), planner: "ray-lattice".into(), max_charts: 1, steps: 7, identify_angles: true }, &mut |r| replies.push(r), clock);
        let Some(Reply::Planned { status, summary, path, trajectory, .. }) = replies.last() else { panic!("{replies:?}") };
        assert_eq!(status, "found", "{summary}");
        assert!(path.is_empty(), "no platform poses");
        let planned = trajectory.as_ref().expect("the path written into the scenario");
        assert_eq!(planned.name, "around-lattice");
        let written = Scenario::from_json(&planned.scenario).unwrap();
        let k = written.joint_paths.iter().position(|p| p.name == planned.name).unwrap();
        assert_eq!(planned.report.as_ref().unwrap().report().feasible, [[0.0, 1.0]]);
        assert_eq!(crate::logic::verify(&written, k).unwrap(), planned.report.as_ref().unwrap().report());
        // the atlas planner refuses a multi-link robot, saying which planner does plan it
        replies.clear();
        run(Job::Plan { scenario: json, query: "around".into(), planner: "continuation".into(), max_charts: 1, steps: 7, identify_angles: true }, &mut |r| replies.push(r), clock);
        let Some(Reply::Failed { error }) = replies.last() else { panic!("{replies:?}") };
        assert!(error.contains("lattice planner"), "{error}");
    }

    #[test]
    fn the_lattice_planners_steps_are_the_clis() {
        let json = PRESETS[find("cdpr7-box").unwrap()].json;
        let plan = |steps| {
            let mut replies = vec![];
            run(Job::Plan { scenario: json.into(), query: "over-box".into(), planner: "ray-lattice".into(), max_charts: 1, steps, identify_angles: true }, &mut |r| replies.push(r), clock);
            replies.pop().unwrap()
        };
        // the core's refusal, word for word what `cablenav plan --planner lattice --steps 1` prints
        let s = Scenario::from_json(json).unwrap();
        let params = cablenav::plan::lattice::LatticeParams { steps: 1, ..Default::default() };
        let core = cablenav::plan::lattice::LatticePlanner::new(&s, "over-box", params).err().unwrap().to_string();
        assert_eq!(core, "--steps: x: needs 2 to 10000 grid values (both ends of the range count), got 1");
        for bad in [0, 1, 10_001] {
            let Reply::Failed { error } = plan(bad) else { panic!("{bad} steps planned") };
            assert!(error.starts_with("--steps: x: needs 2 to 10000 grid values") && error.ends_with(&format!("got {bad}")), "{error}");
        }
        let Reply::Planned { status, summary, .. } = plan(9) else { panic!("9 steps") };
        assert_eq!(status, "found", "{summary}");
        assert!(summary.contains("x: 9 values over [0.2, 3.8]"), "{summary}");
    }

    #[test]
    fn a_verify_job_gives_the_pages_own_report_bit_for_bit() {
        let json = PRESETS[find("cdpr7-tree").unwrap()].json;
        let s = Scenario::from_json(json).unwrap();
        for (index, want) in [(1, 1), (9, 1), (0, 0)] {
            let mut replies = vec![];
            run(Job::Verify { scenario: json.into(), index }, &mut |r| replies.push(r), clock);
            // through JSON, as the page gets it
            let text = super::super::protocol::encode_reply(1, replies.last().unwrap());
            let Some(Ok(envelope)) = super::super::protocol::decode_reply(&text) else { panic!("{text}") };
            let Reply::Verified { report: Ok(r), .. } = envelope.body else { panic!("{text}") };
            assert_eq!(r.report(), crate::logic::verify_sections(&s, want).unwrap(), "index {index}: clamped to the last");
        }
        // a timed trajectory: the sections of the full verification, without its time-scale search
        let json = PRESETS[find("robocrane-timed").unwrap()].json;
        let s = Scenario::from_json(json).unwrap();
        let mut replies = vec![];
        run(Job::Verify { scenario: json.into(), index: 0 }, &mut |r| replies.push(r), clock);
        let Some(Reply::Verified { report: Ok(r), .. }) = replies.last() else { panic!("{replies:?}") };
        let (live, full) = (r.report(), crate::logic::verify(&s, 0).unwrap());
        assert_eq!((&live.feasible, &live.infeasible, &live.uncertain), (&full.feasible, &full.infeasible, &full.uncertain));
        let (ls, fs) = (live.seconds.as_ref().unwrap(), full.seconds.as_ref().unwrap());
        assert_eq!((&ls.feasible, &ls.infeasible), (&fs.feasible, &fs.infeasible));
        assert!(ls.min_time_scale.is_none() && fs.min_time_scale.is_some() && ls.min_time_scale_note == cablenav::verify::timing::NOT_SEARCHED);
        assert_eq!(crate::logic::time_scale_summary(ls), "The fastest timing is searched when the drag ends.");
        let mut replies = vec![];
        run(Job::Verify { scenario: "{".into(), index: 0 }, &mut |r| replies.push(r), clock);
        assert!(matches!(&replies[0], Reply::Verified { report: Err(_), .. }), "{replies:?}");
    }

    #[test]
    fn lattice_rays_in_blocks_join_into_the_cores_lattice() {
        let json = PRESETS[find("cdpr7-box").unwrap()].json;
        let s = Scenario::from_json(json).unwrap();
        let (axes, ranges) = (vec!["x".to_string(), "z".to_string()], vec![[0.2, 3.8], [0.3, 3.7]]);
        let mut sections = vec![];
        for rays in [[0, 5], [5, 6], [6, 14]] {
            let mut replies = vec![];
            let job = Job::LatticeRays { scenario: json.into(), pose: "fig310".into(), axes: axes.clone(), ranges: ranges.clone(), steps: 7, rays };
            run(job, &mut |r| replies.push(r), clock);
            // through JSON, as the page gets it
            let text = super::super::protocol::encode_reply(1, replies.last().unwrap());
            let Some(Ok(envelope)) = super::super::protocol::decode_reply(&text) else { panic!("{text}") };
            let Reply::LatticeRays { rays: got, sections: mut part } = envelope.body else { panic!("{text}") };
            assert_eq!((got, part.len()), (rays, rays[1] - rays[0]));
            sections.append(&mut part);
        }
        let spec = lattice_spec(&s, "fig310", &axes, ranges.clone(), 7).unwrap();
        let joined = join_lattice(&s, spec.clone(), &sections).unwrap();
        let core = Lattice::build(&s, spec.clone()).report().unwrap();
        assert_eq!(joined, LatticeResult::of(&s, &core), "the same rays, bit for bit, and the same graph");
        assert_eq!((joined.rays.len(), joined.components), (14, core.components));
        // the x-ray at z = 0.8667 starts at x ≈ 2.002 (thesis Fig. 3.10)
        let ray = joined.rays.iter().find(|r| r.vary == "x" && (r.at[2] - (0.3 + 3.4 / 6.0)).abs() < 1e-12).unwrap();
        assert!((ray.feasible[0][0] - 2.002).abs() < 1e-3 && ray.at[0] == 0.2 && ray.at[1] == 2.0, "{ray:?}");
        assert!(join_lattice(&s, spec, &sections[1..]).unwrap_err().contains("13 ray(s)"));
    }

    #[test]
    fn a_profiles_job_gives_the_cores_clearances_and_envelope() {
        let json = PRESETS[find("robocrane").unwrap()].json;
        let s = Scenario::from_json(json).unwrap();
        let t = &s.trajectories[0];
        let samples: Vec<(f64, Pose)> = (0..=8).map(|k| k as f64 / 8.0).map(|u| (u, t.pose_at(u))).collect();
        let mut replies = vec![];
        let wire = samples.iter().map(|(u, p)| (*u, pose_to_wire(p))).collect();
        run(Job::Profiles { scenario: json.into(), name: t.name.clone(), samples: wire, trajectory: Some(t.name.clone()) }, &mut |r| replies.push(r), clock);
        // through JSON, as the page gets it
        let text = super::super::protocol::encode_reply(1, replies.last().unwrap());
        let Some(Ok(envelope)) = super::super::protocol::decode_reply(&text) else { panic!("{text}") };
        let Reply::Profiles { clearances, tension } = envelope.body else { panic!("{text}") };
        let core = cablenav::verify::profile::tension_at(&s, &t.name, &samples).unwrap();
        let got = cablenav::report::TensionEnvelope::from(tension.unwrap());
        assert_eq!((got.t.len(), got.bounds.clone()), (core.t.len(), core.bounds.clone()));
        let close = |a: &[Option<Vec<f64>>], b: &[Option<Vec<f64>>]| a.iter().flatten().flatten().zip(b.iter().flatten().flatten()).all(|(x, y)| (x - y).abs() <= 1e-12 * y.abs().max(1.0));
        assert!(close(&got.tension_min, &core.tension_min) && close(&got.tension_max, &core.tension_max));
        let core = cablenav::verify::profile::clearances_at(&s, &samples).unwrap();
        let got = cablenav::verify::profile::ClearanceProfile::from(clearances.unwrap());
        assert_eq!(got.samples.len(), core.samples.len());
        for (g, c) in got.samples.iter().zip(&core.samples) {
            assert_eq!((g.t, &g.violated, g.cable_cable.as_ref().map(|x| &x.between)), (c.t, &c.violated, c.cable_cable.as_ref().map(|x| &x.between)));
            let d = |x: &Option<cablenav::verify::profile::Closest>| x.as_ref().map_or(0.0, |x| x.distance);
            assert!((d(&g.cable_cable) - d(&c.cable_cable)).abs() <= 1e-12 && (d(&g.cable_obstacle) - d(&c.cable_obstacle)).abs() <= 1e-12);
        }
        // no wrench set: the core's reason
        let mut replies = vec![];
        let plain = PRESETS[find("cdpr7-tree").unwrap()].json;
        run(Job::Profiles { scenario: plain.into(), name: "x".into(), samples: vec![], trajectory: None }, &mut |r| replies.push(r), clock);
        assert!(matches!(replies.last(), Some(Reply::Profiles { clearances: Ok(_), tension: Err(error) }) if error.contains("wrench")), "{replies:?}");
        // a timed trajectory with a mass: the inertia is in the tensions, as `cablenav envelope` has them
        let json = PRESETS[find("robocrane-timed").unwrap()].json;
        let s = Scenario::from_json(json).unwrap();
        let t = s.trajectory(Some("swing")).unwrap();
        let wire = (0..=8).map(|k| k as f64 / 8.0).map(|u| (u, pose_to_wire(&t.pose_at(u)))).collect();
        let mut replies = vec![];
        run(Job::Profiles { scenario: json.into(), name: "swing".into(), samples: wire, trajectory: Some("swing".into()) }, &mut |r| replies.push(r), clock);
        let Some(Reply::Profiles { tension: Ok(tension), .. }) = replies.last() else { panic!("{replies:?}") };
        let got = cablenav::report::TensionEnvelope::from(tension.clone());
        let core = cablenav::verify::tension_envelope(&s, t, 8).unwrap();
        assert_eq!(got.tension_max, core.tension_max);
        let at_rest = cablenav::verify::profile::tension_at(&s, "swing", &(0..=8).map(|k| k as f64 / 8.0).map(|u| (u, t.pose_at(u))).collect::<Vec<_>>()).unwrap();
        assert_ne!(got.tension_max, at_rest.tension_max, "the swing's inertia changes its tensions");
    }

    #[test]
    fn bad_jobs_fail_with_a_reason() {
        let mut replies = vec![];
        let json = PRESETS[find("robocrane").unwrap()].json.to_string();
        run(Job::Plan { scenario: json.clone(), query: "q1-q2".into(), planner: "nope".into(), max_charts: 1, steps: 7, identify_angles: true }, &mut |r| replies.push(r), clock);
        run(Job::Plan { scenario: "{".into(), query: "q".into(), planner: "continuation".into(), max_charts: 1, steps: 7, identify_angles: true }, &mut |r| replies.push(r), clock);
        run(Job::Slice { map: SliceSpec { scenario: json.clone(), pose: "q1".into(), axes: ["x".into(), "w".into()], res: 4, range: [[0.0, 1.0]; 2] }, rows: [0, 4] }, &mut |r| replies.push(r), clock);
        let lattice = |pose: &str, steps, rays| Job::LatticeRays { scenario: json.clone(), pose: pose.into(), axes: vec!["x".into(), "y".into()], ranges: vec![[0.0, 1.0]; 2], steps, rays };
        run(lattice("q1", 0, [0, 1]), &mut |r| replies.push(r), clock);
        run(lattice("nowhere", 3, [0, 1]), &mut |r| replies.push(r), clock);
        run(lattice("q1", 3, [2, 7]), &mut |r| replies.push(r), clock);
        let errors: Vec<&str> = replies.iter().filter_map(|r| if let Reply::Failed { error } = r { Some(error.as_str()) } else { None }).collect();
        assert_eq!(errors.len(), 6, "{replies:?}");
        assert!(errors[3].contains("steps") && errors[4].contains("nowhere") && errors[5].contains("rays 2..7 of a lattice of 6"), "{errors:?}");
        assert!(errors[0].contains("not available") && errors[2].contains("“w”"), "{errors:?}");
    }
}
