//! Planning from the page: pick a planner and a query, run it with a progress bar and a Cancel
//! button. The core's resumable [`cablenav::plan::Planner`] is advanced in bounded `step` calls
//! from animation frames, [`SLICE_MS`] of work per frame, so the page stays responsive; Cancel
//! stops calling `step` and drops the planner.

use crate::app::{Parsed, Shared};
use crate::logic::fmt_num;
use crate::workbench::Planned;
use cablenav::plan::{PlanOutcome, PlanParams, PlanProgress, PlanStatus, Planner};
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
    [("continuation", "Atlas continuation (Bohigas et al.)", true), ("ray-lattice", "Ray lattice (not available yet)", false)];

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

/// Progress as a fraction for the bar: how much of the start's distance to the goal the search
/// front has covered, 1 − h/h₀, never going back (h₀: the least heuristic before any step).
pub fn fraction(first_h: f64, p: &PlanProgress, shown: f64) -> f64 {
    if p.done.is_some() {
        return 1.0;
    }
    if !(first_h.is_finite() && first_h > 0.0 && p.best_heuristic.is_finite()) {
        return shown;
    }
    (1.0 - p.best_heuristic / first_h).clamp(0.0, 0.99).max(shown)
}

/// One line describing an outcome.
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
        PlanStatus::Unrepaired => "The path could not be verified feasible everywhere.".to_string(),
    }
}

/// A run in progress: the planner and what the page shows of it.
struct Run {
    planner: Planner,
    generation: u32,
    query: String,
    /// The least heuristic before any work: the start's distance to the goal.
    first_h: f64,
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
        let first_h = r.first_h;
        ui.progress.update(|shown| *shown = fraction(first_h, &p, *shown));
        drop(slot);
        match p.done {
            None => {
                ui.detail.set(format!("{} charts, {} open, distance to goal {}", p.charts, p.open, fmt_num(p.best_heuristic)));
                pump(run, generation, ui)
            }
            Some(_) => {
                ui.detail.set(format!("{} charts; re-verifying the path…", p.charts));
                finish(run, generation, ui)
            }
        }
    });
}

/// In the next frame: the outcome (the planner re-verifies the path edge by edge), its summary and
/// the end state; the path itself is handed to the page a frame later, so that drawing it does not
/// share a frame with the verification.
fn finish(run: Rc<RefCell<Option<Run>>>, generation: u32, ui: Ui) {
    request_animation_frame(move || {
        let Some(r) = run.borrow_mut().take_if(|r| r.generation == generation) else { return };
        let Some(o) = r.planner.outcome() else {
            ui.state.set(RunState::Failed("the planner ended without an outcome".into()));
            return;
        };
        ui.detail.set(summary(&o));
        ui.state.set(RunState::Done(o.status));
        if o.status == PlanStatus::Found && !o.path.is_empty() {
            let (start, goal) = (o.path[0], o.path[o.path.len() - 1]);
            let planned = Planned { query: r.query, start, goal, poses: o.path };
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
        if !PLANNERS.iter().any(|(id, _, ok)| *ok && *id == planner_id.get_untracked()) {
            ui.state.set(RunState::Failed(format!("the planner “{}” is not available", planner_id.get_untracked())));
            return;
        }
        let params = PlanParams { max_charts: budget.get_untracked(), ..PlanParams::default() };
        let q = query.get_untracked();
        planned.set(None);
        match Planner::new(s, &q, params) {
            Err(e) => ui.state.set(RunState::Failed(e.to_string())),
            Ok(mut planner) => {
                gen2.set(gen2.get() + 1);
                let first_h = planner.step(0).best_heuristic;
                *run2.borrow_mut() = Some(Run { planner, generation: gen2.get(), query: q, first_h });
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
            <label>
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

    fn progress(h: f64, done: Option<PlanStatus>) -> PlanProgress {
        PlanProgress { charts: 1, open: 1, best_heuristic: h, done, verifying: None }
    }

    #[test]
    fn the_bar_only_moves_forward() {
        assert_eq!(fraction(2.0, &progress(2.0, None), 0.0), 0.0);
        assert_eq!(fraction(2.0, &progress(1.0, None), 0.0), 0.5);
        assert_eq!(fraction(2.0, &progress(1.5, None), 0.5), 0.5, "a worse front does not move it back");
        assert_eq!(fraction(2.0, &progress(0.0, None), 0.5), 0.99, "full only when done");
        assert_eq!(fraction(2.0, &progress(0.3, Some(PlanStatus::Found)), 0.5), 1.0);
        assert_eq!(fraction(f64::INFINITY, &progress(1.0, None), 0.2), 0.2);
    }

    #[test]
    fn state_names() {
        assert_eq!(RunState::Done(PlanStatus::NoPath).name(), "no_path");
        assert_eq!(RunState::Failed("x".into()).name(), "error");
        assert_eq!(PLANNERS.iter().filter(|p| p.2).count(), 1);
    }

    #[test]
    fn robocrane_plans_from_the_page_logic_and_the_path_ends_at_the_query() {
        let s = crate::logic::parse_scenario(crate::presets::PRESETS[crate::presets::find("robocrane").unwrap()].json).unwrap();
        let mut p = Planner::new(&s, "q1-q2", PlanParams { max_charts: 20_000, ..PlanParams::default() }).unwrap();
        let first = p.step(0);
        assert_eq!(first.done, None);
        let mut shown = 0.0;
        let mut seen = vec![];
        let mut last = first;
        for _ in 0..200_000 {
            last = p.step(1);
            shown = fraction(first.best_heuristic, &last, shown);
            seen.push(shown);
            if last.done.is_some() {
                break;
            }
        }
        assert_eq!(last.done, Some(PlanStatus::Found));
        assert_eq!(shown, 1.0);
        assert!(seen.iter().any(|&f| f > 0.0 && f < 1.0), "the bar moves before the end: {seen:?}");
        let o = p.outcome().unwrap();
        assert_eq!(o.path[0], *s.pose("q1").unwrap());
        assert_eq!(*o.path.last().unwrap(), *s.pose("q2").unwrap());
        assert!(summary(&o).starts_with("Path found:"), "{}", summary(&o));
    }
}
