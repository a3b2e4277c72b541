//! Planning from the page: pick a planner and a query, run it with a progress bar and a Cancel
//! button. The core's resumable planner ([`cablenav::plan::choice::PathPlanner`]: the atlas or the
//! ray lattice, picked by name) is advanced in bounded `step` calls from animation frames,
//! [`SLICE_MS`] of work per frame, so the page stays responsive; Cancel stops calling `step` and
//! drops the planner.

use crate::app::{Parsed, Shared};
use crate::logic::fmt_num;
use crate::workbench::Planned;
use cablenav::model::Pose;
use cablenav::plan::choice::{planner, Details, PathPlanner, PlanResult, PlannerKind, PlannerOptions, Progress};
use cablenav::plan::PlanStatus;
use crate::view3d::scene::Rgba;
use leptos::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

/// Milliseconds of planning work per animation frame: steps are taken while less than this has
/// passed, and one `step(1)` takes up to about 5–8 ms in wasm (measured on Robocrane), so a
/// frame's work stays near 15 ms,
/// well under the 50 ms a frame may take.
pub const SLICE_MS: f64 = 8.0;

/// The planners the page offers: (id, label, available).
pub const PLANNERS: [(&str, &str, bool); 2] =
    [("continuation", "Atlas continuation (Bohigas et al.)", true), ("ray-lattice", "Ray lattice + A* + Bézier (Zhang)", true)];

/// Colour of the lattice planner's A* polyline, drawn beside the smoothed path.
pub const POLYLINE: Rgba = [0.93, 0.55, 0.12, 1.0];

/// Poses sampled along a planned trajectory for the page's view and plots.
const PATH_SAMPLES: usize = 200;

/// The core's planner kind for a page planner id.
pub fn kind_of(id: &str) -> Option<PlannerKind> {
    match id {
        "continuation" => Some(PlannerKind::Atlas),
        "ray-lattice" => Some(PlannerKind::Lattice),
        _ => None,
    }
}

/// Where a run is.
#[derive(Debug, Clone, PartialEq)]
pub enum RunState {
    /// Nothing run yet.
    Idle,
    /// Running.
    Running,
    /// Finished with a status.
    Done(PlanStatus),
    /// Stopped by the user.
    Cancelled,
    /// The planner refused the query.
    Failed(String),
}

impl RunState {
    /// The name in `data-state` (for tests).
    pub fn name(&self) -> &'static str {
        match self {
            RunState::Idle => "idle",
            RunState::Running => "running",
            RunState::Done(PlanStatus::Found) => "found",
            RunState::Done(PlanStatus::NoPath) => "no_path",
            RunState::Done(PlanStatus::Budget) => "budget",
            RunState::Done(PlanStatus::Unrepaired) => "unrepaired",
            RunState::Cancelled => "cancelled",
            RunState::Failed(_) => "error",
        }
    }
}

/// Progress as a fraction for the bar, never going back.
pub fn fraction(p: &Progress, shown: f64) -> f64 {
    if p.done.is_some() {
        return 1.0;
    }
    p.fraction.clamp(0.0, 0.99).max(shown)
}

/// One line describing a result.
pub fn summary(r: &PlanResult) -> String {
    match &r.details {
        Details::Atlas(o) => {
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

fn capitalised(s: &str) -> String {
    let mut c = s.chars();
    c.next().map_or(String::new(), |f| f.to_uppercase().chain(c).collect())
}

/// The page's copy of a found path: the trajectory sampled (the atlas' path poses, or the lattice
/// planner's smoothed trajectory at [`PATH_SAMPLES`] + 1 poses) and the lattice's A* polyline.
pub fn planned_of(query: String, r: &PlanResult) -> Option<Planned> {
    let traj = r.trajectory.as_ref()?;
    let (poses, polyline): (Vec<Pose>, Vec<Pose>) = match &r.details {
        Details::Atlas(o) => (o.path.iter().map(|p| Pose::from_quaternion(p.position.into(), p.quaternion)).collect(), vec![]),
        Details::Lattice(l) => (
            (0..=PATH_SAMPLES).map(|k| traj.pose_at(k as f64 / PATH_SAMPLES as f64)).collect(),
            l.polyline.iter().map(|&c| Pose::from_coords(c)).collect(),
        ),
    };
    let (start, goal) = (*poses.first()?, *poses.last()?);
    Some(Planned { query, start, goal, poses, polyline })
}

/// A run in progress: the planner and what the page shows of it.
struct Run {
    planner: Box<dyn PathPlanner>,
    generation: u32,
    query: String,
}

/// The signals a run updates.
#[derive(Clone, Copy)]
struct Ui {
    state: RwSignal<RunState>,
    progress: RwSignal<f64>,
    detail: RwSignal<String>,
    planned: RwSignal<Option<Shared<Planned>>>,
}

fn now() -> f64 {
    web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now())
}

/// Advances the run of `generation` by one frame's slice, then schedules the next frame; once the
/// search ends, [`finish`] takes the outcome in a frame of its own.
fn pump(run: Rc<RefCell<Option<Run>>>, generation: u32, ui: Ui) {
    request_animation_frame(move || {
        let mut slot = run.borrow_mut();
        let Some(r) = slot.as_mut().filter(|r| r.generation == generation) else { return };
        let started = now();
        let mut p = r.planner.step(1);
        while p.done.is_none() && now() - started < SLICE_MS {
            p = r.planner.step(1);
        }
        ui.progress.update(|shown| *shown = fraction(&p, *shown));
        drop(slot);
        ui.detail.set(p.stage.clone());
        match p.done {
            None => pump(run, generation, ui),
            Some(_) => finish(run, generation, ui),
        }
    });
}

/// In the next frame: the result, its summary and the end state; the path itself is handed to the
/// page a frame later, so that drawing it does not share a frame with the work.
fn finish(run: Rc<RefCell<Option<Run>>>, generation: u32, ui: Ui) {
    request_animation_frame(move || {
        let Some(r) = run.borrow_mut().take_if(|r| r.generation == generation) else { return };
        let Some(o) = r.planner.result(f64::NAN) else {
            ui.state.set(RunState::Failed("the planner ended without a result".into()));
            return;
        };
        ui.detail.set(summary(&o));
        ui.state.set(RunState::Done(o.status));
        if let Some(planned) = planned_of(r.query, &o) {
            request_animation_frame(move || ui.planned.set(Some(Shared::new(planned))));
        }
    });
}

/// The planning controls.
#[component]
pub fn Planning(parsed: Memo<Parsed>, planned: RwSignal<Option<Shared<Planned>>>) -> impl IntoView {
    let query = RwSignal::new(String::new());
    let planner_id = RwSignal::new(PLANNERS[0].0.to_string());
    let budget = RwSignal::new(20_000usize);
    let steps = RwSignal::new(cablenav::plan::lattice::LatticeParams::default().steps);
    let ui = Ui { state: RwSignal::new(RunState::Idle), progress: RwSignal::new(0.0), detail: RwSignal::new(String::new()), planned };
    let run: Rc<RefCell<Option<Run>>> = Rc::new(RefCell::new(None));
    let generation = Rc::new(std::cell::Cell::new(0u32));

    let queries = move || parsed.get().0.as_ref().as_ref().map(|s| s.queries.iter().map(|q| q.name.clone()).collect::<Vec<_>>()).unwrap_or_default();
    // a new scenario stops any run and selects its first query
    let (run1, gen1) = (run.clone(), generation.clone());
    Effect::new(move |_| {
        query.set(queries().into_iter().next().unwrap_or_default());
        gen1.set(gen1.get() + 1);
        *run1.borrow_mut() = None;
        ui.state.set(RunState::Idle);
        ui.progress.set(0.0);
        ui.detail.set(String::new());
    });

    let (run2, gen2) = (run.clone(), generation.clone());
    let start = move |_| {
        let parsed = parsed.get_untracked();
        let Ok(s) = parsed.0.as_ref() else { return };
        let Some(kind) = kind_of(&planner_id.get_untracked()) else {
            ui.state.set(RunState::Failed(format!("the planner “{}” is not available", planner_id.get_untracked())));
            return;
        };
        let mut options = PlannerOptions::new(kind);
        options.atlas.max_charts = budget.get_untracked();
        options.lattice.steps = steps.get_untracked();
        let q = query.get_untracked();
        planned.set(None);
        match planner(s, &q, &options) {
            Err(e) => ui.state.set(RunState::Failed(e.to_string())),
            Ok(planner) => {
                gen2.set(gen2.get() + 1);
                *run2.borrow_mut() = Some(Run { planner, generation: gen2.get(), query: q });
                ui.progress.set(0.0);
                ui.detail.set("starting…".into());
                ui.state.set(RunState::Running);
                pump(run2.clone(), gen2.get(), ui);
            }
        }
    };
    let (run3, gen3) = (run.clone(), generation.clone());
    let cancel = move |_| {
        gen3.set(gen3.get() + 1);
        *run3.borrow_mut() = None;
        ui.state.set(RunState::Cancelled);
        ui.detail.set("Cancelled: the planner was dropped.".into());
    };
    let running = move || ui.state.get() == RunState::Running;

    view! {
        <h2>"Planning"</h2>
        <div class="planning" data-testid="planning">
            <label>
                "Planner "
                <select data-testid="planner" on:change=move |ev| planner_id.set(event_target_value(&ev))>
                    {PLANNERS.map(|(id, label, ok)| view! { <option value=id disabled=!ok selected=move || planner_id.get() == id>{label}</option> })}
                </select>
            </label>
            <label>
                "Query "
                <select data-testid="plan-query" on:change=move |ev| query.set(event_target_value(&ev))>
                    {move || queries().into_iter().map(|q| {
                        let (value, key) = (q.clone(), q.clone());
                        view! { <option value=value selected=move || query.get() == key>{q}</option> }
                    }).collect_view()}
                </select>
            </label>
            <label hidden=move || planner_id.get() != "ray-lattice">
                "Lattice steps "
                <input class="num" type="number" min="2" step="1" data-testid="plan-steps" prop:value=move || steps.get().to_string()
                    on:change=move |ev| {
                        if let Ok(v) = event_target_value(&ev).trim().parse::<usize>() {
                            steps.set(v)
                        }
                    } />
            </label>
            <label hidden=move || planner_id.get() == "ray-lattice">
                "Chart budget "
                <input class="num" type="number" min="1" step="1000" prop:value=move || budget.get().to_string()
                    on:change=move |ev| {
                        if let Ok(v) = event_target_value(&ev).trim().parse::<usize>() {
                            budget.set(v.max(1))
                        }
                    } />
            </label>
            <button data-testid="plan-run" on:click=start disabled=move || running() || queries().is_empty()>"Plan"</button>
            <button data-testid="plan-cancel" on:click=cancel disabled=move || !running()>"Cancel"</button>
            <progress data-testid="plan-progress" max="1" prop:value=move || ui.progress.get() aria-label="planning progress"></progress>
        </div>
        <p class="plan-status" data-testid="plan-status" data-state=move || ui.state.get().name() aria-live="polite">
            {move || match ui.state.get() {
                RunState::Failed(e) => format!("The planner refused: {e}"),
                RunState::Idle if queries().is_empty() => "This scenario has no planning query.".into(),
                _ => ui.detail.get(),
            }}
        </p>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn progress(fraction: f64, done: Option<PlanStatus>) -> Progress {
        Progress { stage: String::new(), fraction, done }
    }

    #[test]
    fn the_bar_only_moves_forward() {
        assert_eq!(fraction(&progress(0.0, None), 0.0), 0.0);
        assert_eq!(fraction(&progress(0.5, None), 0.0), 0.5);
        assert_eq!(fraction(&progress(0.25, None), 0.5), 0.5, "a smaller estimate does not move it back");
        assert_eq!(fraction(&progress(1.0, None), 0.5), 0.99, "full only when done");
        assert_eq!(fraction(&progress(0.3, Some(PlanStatus::Found)), 0.5), 1.0);
    }

    #[test]
    fn state_names() {
        assert_eq!(RunState::Done(PlanStatus::NoPath).name(), "no_path");
        assert_eq!(RunState::Failed("x".into()).name(), "error");
        assert_eq!(PLANNERS.iter().filter(|p| p.2).count(), 2);
        assert!(PLANNERS.iter().all(|p| kind_of(p.0).is_some()));
    }

    /// Steps a planner one unit at a time, as the page does, and returns its result.
    fn run_stepwise(s: &cablenav::Scenario, query: &str, kind: PlannerKind) -> PlanResult {
        let mut p = planner(s, query, &PlannerOptions::new(kind)).unwrap();
        let mut shown = 0.0;
        let mut seen = vec![];
        for _ in 0..200_000 {
            let last = p.step(1);
            shown = fraction(&last, shown);
            seen.push(shown);
            if last.done.is_some() {
                break;
            }
        }
        assert_eq!(shown, 1.0);
        assert!(seen.iter().any(|&f| f > 0.0 && f < 1.0), "the bar moves before the end");
        p.result(0.0).unwrap()
    }

    #[test]
    fn robocrane_plans_from_the_page_logic_and_the_path_ends_at_the_query() {
        let s = crate::logic::parse_scenario(crate::presets::PRESETS[crate::presets::find("robocrane").unwrap()].json).unwrap();
        let r = run_stepwise(&s, "q1-q2", PlannerKind::Atlas);
        assert_eq!(r.status, PlanStatus::Found);
        let p = planned_of("q1-q2".into(), &r).unwrap();
        assert!((p.poses[0].position - s.pose("q1").unwrap().position).norm() < 1e-12);
        assert!(p.poses[0].rotation.angle_to(&s.pose("q1").unwrap().rotation) < 1e-9);
        assert!(p.poses.last().unwrap().rotation.angle_to(&s.pose("q2").unwrap().rotation) < 1e-9);
        assert!(p.polyline.is_empty());
        assert!(summary(&r).starts_with("Path found:"), "{}", summary(&r));
    }

    #[test]
    fn the_lattice_planner_plans_around_the_tree_from_the_page_logic() {
        let s = crate::logic::parse_scenario(crate::presets::PRESETS[crate::presets::find("cdpr7-tree").unwrap()].json).unwrap();
        let r = run_stepwise(&s, "around-tree", PlannerKind::Lattice);
        assert_eq!(r.status, PlanStatus::Found);
        let p = planned_of("around-tree".into(), &r).unwrap();
        assert_eq!(p.poses.len(), PATH_SAMPLES + 1);
        assert!(p.polyline.len() >= 3, "the A* polyline is kept beside the smoothed path");
        assert!((p.start.position - s.pose("tree-left").unwrap().position).norm() < 1e-12);
        assert!((p.goal.position - s.pose("tree-right").unwrap().position).norm() < 1e-12);
        assert!(summary(&r).starts_with("Path found and verified feasible"), "{}", summary(&r));
    }
}
