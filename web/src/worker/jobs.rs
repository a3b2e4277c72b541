//! Running a [`Job`] to its end, reporting [`Reply`]s as it goes: plain Rust over the core,
//! tested natively (the worker calls [`run`]; so do the tests).

use super::protocol::{pose_to_wire, Job, Reply};
use crate::logic::fmt_num;
use cablenav::model::{Coord, Pose};
use cablenav::plan::{PlanOutcome, PlanParams, PlanStatus, Planner};
use cablenav::Scenario;

/// Milliseconds of work between two progress replies.
pub const PROGRESS_MS: f64 = 50.0;

/// Where a planner is after a step.
#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    /// Whether the search has ended ([`PlannerRun::finish`] may be called).
    pub done: bool,
    /// How far from the goal the search front is (decreasing towards 0; any unit), for the bar.
    pub distance: f64,
    /// One line for people.
    pub detail: String,
}

/// How a planning run ended.
#[derive(Debug, Clone, PartialEq)]
pub struct Finished {
    /// `found`, `no_path` or `budget`.
    pub status: &'static str,
    /// One line for people.
    pub summary: String,
    /// The path, start to goal (empty unless found).
    pub path: Vec<Pose>,
}

/// A resumable planner as the worker drives it: bounded steps, then the result. Each planner
/// the page offers implements it (see [`planner`]).
pub trait PlannerRun {
    /// Advances by at most `budget` units of the planner's work.
    fn step(&mut self, budget: usize) -> Step;
    /// The result, once a step reported `done`.
    fn finish(&mut self) -> Result<Finished, String>;
}

/// The atlas-continuation planner (paper 1) as a [`PlannerRun`].
struct Atlas(Planner);

impl PlannerRun for Atlas {
    fn step(&mut self, budget: usize) -> Step {
        let p = self.0.step(budget);
        Step {
            done: p.done.is_some(),
            distance: p.best_heuristic,
            detail: if p.done.is_some() {
                format!("{} charts; re-verifying the path…", p.charts)
            } else {
                format!("{} charts, {} open, distance to goal {}", p.charts, p.open, fmt_num(p.best_heuristic))
            },
        }
    }

    fn finish(&mut self) -> Result<Finished, String> {
        let o = self.0.outcome().ok_or("the planner ended without an outcome")?;
        let status = match o.status {
            PlanStatus::Found => "found",
            PlanStatus::NoPath => "no_path",
            PlanStatus::Budget => "budget",
        };
        Ok(Finished { status, summary: summary(&o), path: if o.status == PlanStatus::Found { o.path } else { vec![] } })
    }
}

/// One line describing an atlas planner's outcome.
pub fn summary(o: &PlanOutcome) -> String {
    let v = &o.verification;
    match o.status {
        PlanStatus::Found => format!(
            "Path found: {} poses, {} charts. Re-verified: {} edge(s), {} infeasible and {} uncertain section(s); {} of {} poses wrench-infeasible{}.",
            o.path.len(),
            o.charts,
            v.edges,
            v.infeasible_sections,
            v.uncertain_sections,
            v.wrench_infeasible_poses,
            v.wrench_poses,
            v.least_wrench_margin.map_or(String::new(), |m| format!(", least wrench margin {}", fmt_num(m)))
        ),
        PlanStatus::NoPath => format!("No path at this resolution: the start's component was exhausted after {} charts.", o.charts),
        PlanStatus::Budget => format!("Chart budget exhausted after {} charts: nothing is claimed.", o.charts),
    }
}

/// The planner `id` (of [`crate::planning::PLANNERS`]) set up for query `query`.
pub fn planner(id: &str, s: &Scenario, query: &str, max_charts: usize) -> Result<Box<dyn PlannerRun>, String> {
    match id {
        "continuation" => {
            let params = PlanParams { max_charts, ..PlanParams::default() };
            Ok(Box::new(Atlas(Planner::new(s, query, params).map_err(|e| e.to_string())?)))
        }
        other => Err(format!("the planner “{other}” is not available")),
    }
}

/// Progress as a fraction for the bar: how much of the start's distance to the goal the search
/// front has covered, 1 − d/d₀, never going back (d₀: the distance before any step), below 1
/// until the end.
pub fn fraction(first: f64, step: &Step, shown: f64) -> f64 {
    if step.done {
        return 1.0;
    }
    if !(first.is_finite() && first > 0.0 && step.distance.is_finite()) {
        return shown;
    }
    (1.0 - step.distance / first).clamp(0.0, 0.99).max(shown)
}

/// Runs `job` to its end: progress replies at most every [`PROGRESS_MS`] of work (by `now`, in
/// ms), then the final reply.
pub fn run(job: Job, report: &mut dyn FnMut(Reply), now: fn() -> f64) {
    let last = match job {
        Job::Plan { scenario, query, planner: id, max_charts } => plan(&scenario, &query, &id, max_charts, report, now),
        Job::Slice { scenario, pose, axes, res, range, rows } => slice_rows(&scenario, &pose, &axes, res, range, rows),
    };
    report(last.unwrap_or_else(|error| Reply::Failed { error }));
}

fn scenario(json: &str) -> Result<Scenario, String> {
    Scenario::from_json(json).map_err(|e| e.to_string())
}

fn plan(json: &str, query: &str, id: &str, max_charts: usize, report: &mut dyn FnMut(Reply), now: fn() -> f64) -> Result<Reply, String> {
    let s = scenario(json)?;
    let mut p = planner(id, &s, query, max_charts)?;
    let first = p.step(0);
    let mut shown = 0.0;
    let mut since = now();
    loop {
        let step = p.step(1);
        shown = fraction(first.distance, &step, shown);
        if step.done {
            report(Reply::Progress { fraction: shown, detail: step.detail });
            break;
        }
        if now() - since >= PROGRESS_MS {
            report(Reply::Progress { fraction: shown, detail: step.detail });
            since = now();
        }
    }
    let f = p.finish()?;
    Ok(Reply::Planned { status: f.status.to_string(), summary: f.summary, path: f.path.iter().map(pose_to_wire).collect() })
}

fn slice_rows(json: &str, pose: &str, axes: &[String; 2], res: usize, range: [[f64; 2]; 2], rows: [usize; 2]) -> Result<Reply, String> {
    let s = scenario(json)?;
    let coord = |n: &str| Coord::parse(n).ok_or_else(|| format!("unknown coordinate “{n}”"));
    let axes = [coord(&axes[0])?, coord(&axes[1])?];
    let classes = cablenav::verify::slice::slice_rows(&s, pose, axes, res, range, rows[0]..rows[1]).map_err(|e| e.to_string())?;
    Ok(Reply::Sliced { rows, classes })
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
        let step = |distance: f64, done: bool| Step { done, distance, detail: String::new() };
        assert_eq!(fraction(2.0, &step(2.0, false), 0.0), 0.0);
        assert_eq!(fraction(2.0, &step(1.0, false), 0.0), 0.5);
        assert_eq!(fraction(2.0, &step(1.5, false), 0.5), 0.5, "a worse front does not move it back");
        assert_eq!(fraction(2.0, &step(0.0, false), 0.5), 0.99, "full only when done");
        assert_eq!(fraction(2.0, &step(0.3, true), 0.5), 1.0);
        assert_eq!(fraction(f64::INFINITY, &step(1.0, false), 0.2), 0.2);
    }

    #[test]
    fn a_plan_job_finds_robocrane_q1_q2_and_ends_at_the_query() {
        let json = PRESETS[find("robocrane").unwrap()].json;
        let mut replies = vec![];
        run(Job::Plan { scenario: json.into(), query: "q1-q2".into(), planner: "continuation".into(), max_charts: 20_000 }, &mut |r| replies.push(r), clock);
        let Some(Reply::Planned { status, summary, path }) = replies.last() else { panic!("{replies:?}") };
        assert_eq!(status, "found");
        assert!(summary.starts_with("Path found:"), "{summary}");
        let s = Scenario::from_json(json).unwrap();
        assert_eq!(super::super::protocol::pose_from_wire(&path[0]), *s.pose("q1").unwrap());
        assert_eq!(super::super::protocol::pose_from_wire(path.last().unwrap()), *s.pose("q2").unwrap());
        let bar: Vec<f64> = replies.iter().filter_map(|r| if let Reply::Progress { fraction, .. } = r { Some(*fraction) } else { None }).collect();
        assert!(bar.windows(2).all(|w| w[0] <= w[1]) && bar.last() == Some(&1.0), "{bar:?}");
    }

    #[test]
    fn bad_jobs_fail_with_a_reason() {
        let mut replies = vec![];
        let json = PRESETS[find("robocrane").unwrap()].json.to_string();
        run(Job::Plan { scenario: json.clone(), query: "q1-q2".into(), planner: "nope".into(), max_charts: 1 }, &mut |r| replies.push(r), clock);
        run(Job::Plan { scenario: "{".into(), query: "q".into(), planner: "continuation".into(), max_charts: 1 }, &mut |r| replies.push(r), clock);
        run(Job::Slice { scenario: json, pose: "q1".into(), axes: ["x".into(), "w".into()], res: 4, range: [[0.0, 1.0]; 2], rows: [0, 4] }, &mut |r| replies.push(r), clock);
        let errors: Vec<&str> = replies.iter().filter_map(|r| if let Reply::Failed { error } = r { Some(error.as_str()) } else { None }).collect();
        assert_eq!(errors.len(), 3, "{replies:?}");
        assert!(errors[0].contains("not available") && errors[2].contains("“w”"), "{errors:?}");
    }
}
