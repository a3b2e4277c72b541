//! Planning from the page: pick a planner and a query, run it with a progress bar and a Cancel
//! button. The run happens in a Web Worker ([`crate::worker`]): the main thread only receives
//! progress and the path, so typing, scrolling and orbiting stay smooth. The worker stays for the
//! next run and keeps the atlas planner's atlas, which answers later queries on the same slice
//! (new start and goal poses included); Cancel terminates the worker, and its atlas with it.
//! A multi-link robot's queries are planned by the lattice planner too: its path through
//! configurations comes back written into the scenario (as `cablenav plan --out` writes it,
//! verified exactly in the worker), which one click adds to the edited scenario, where the strip
//! and the 3-D view show it like any path.

use crate::state::{PlannedMotion, Parsed, Planned, Settings, Shared, PLANNERS};
use crate::palette::Rgba;
use crate::worker::host::Resident;
use crate::worker::protocol::{pose_from_wire, Job, Reply, WireAtlas, WireChart};
use leptos::prelude::*;
use std::rc::Rc;

/// The lattice planner's id in [`PLANNERS`].
const LATTICE: &str = "ray-lattice";

/// The grid values per free coordinate to send with a plan: the typed `text` as a whole number
/// for the lattice planner (the core checks its range in the worker, as for the CLI), the CLI's
/// default for the atlas, which has no steps. Text that is no whole number is refused with the
/// message `cablenav lattice --steps` gives.
pub fn lattice_steps(planner: &str, text: &str) -> Result<usize, String> {
    if planner != LATTICE {
        return Ok(cablenav::plan::lattice::LatticeParams::default().steps);
    }
    let text = text.trim();
    text.parse::<usize>().map_err(|_| cablenav::Error::new("--steps", format!("not a whole number: {text:?}")).to_string())
}

/// Colour of the lattice planner's A* polyline, drawn beside the smoothed path.
pub const POLYLINE: Rgba = [0.93, 0.55, 0.12, 1.0];

/// Where a run is.
#[derive(Debug, Clone, PartialEq)]
pub enum RunState {
    /// Nothing run yet.
    Idle,
    /// Running.
    Running,
    /// Finished with a status: `found`, `no_path`, `budget` or `unrepaired`.
    Done(String),
    /// Stopped by the user.
    Cancelled,
    /// The planner refused the query.
    Failed(String),
}

impl RunState {
    /// The name in `data-state` (for tests).
    pub fn name(&self) -> &str {
        match self {
            RunState::Idle => "idle",
            RunState::Running => "running",
            RunState::Done(status) => status,
            RunState::Cancelled => "cancelled",
            RunState::Failed(_) => "error",
        }
    }
}

/// The signals a run updates.
#[derive(Clone, Copy)]
struct Ui {
    state: RwSignal<RunState>,
    progress: RwSignal<f64>,
    detail: RwSignal<String>,
    planned: RwSignal<Option<Shared<Planned>>>,
    growing: RwSignal<Option<WireAtlas>>,
    /// A multi-link robot's planned path: the scenario with it added, and its name there.
    chain_path: RwSignal<Option<(String, String)>>,
}

/// Applies a worker's reply for query `query` to the page.
fn apply(reply: Reply, query: &str, ui: Ui) {
    match reply {
        Reply::Progress { fraction, detail } => {
            ui.progress.set(fraction);
            ui.detail.set(detail);
        }
        Reply::Charts { coords, from, charts } => ui.growing.update(|g| grow(g, coords, from, charts)),
        Reply::Planned { status, summary, path, polyline, trajectory, atlas } => {
            ui.growing.set(None);
            ui.progress.set(1.0);
            ui.detail.set(summary);
            if !path.is_empty() {
                let poses: Vec<_> = path.iter().map(pose_from_wire).collect();
                let (start, goal) = (poses[0], poses[poses.len() - 1]);
                let polyline = polyline.iter().map(pose_from_wire).collect();
                let motion = trajectory.and_then(|t| motion(*t));
                ui.planned.set(Some(Shared::new(Planned { query: query.to_string(), start, goal, poses, polyline, motion, atlas })));
            } else if let Some(t) = trajectory {
                // a multi-link robot's path through configurations: offered to add to the scenario
                ui.chain_path.set(Some((t.scenario, t.name)));
            }
            ui.state.set(RunState::Done(status));
        }
        Reply::Failed { error } => {
            ui.growing.set(None);
            ui.state.set(RunState::Failed(error));
        }
        Reply::Sliced { .. } | Reply::Singular { .. } | Reply::LatticeRays { .. } | Reply::Profiles { .. } | Reply::Verified { .. } | Reply::VerifiedEvery { .. } | Reply::Timed { .. } => {
            ui.state.set(RunState::Failed("the worker answered a planning job with another job's reply".into()));
        }
    }
}

/// The growing atlas `atlas` with charts `from..` added (a first batch, or a batch that does not
/// follow on, starts it anew).
fn grow(atlas: &mut Option<WireAtlas>, coords: Vec<String>, from: usize, charts: Vec<WireChart>) {
    match atlas {
        Some(a) if a.coords == coords && a.charts.len() == from => a.charts.extend(charts),
        _ => *atlas = Some(WireAtlas { coords, charts }),
    }
}

/// The planned trajectory as the page keeps it: read back from the scenario the worker wrote
/// (a parse, no verification: the worker verified it).
fn motion(t: crate::worker::protocol::PlannedTrajectory) -> Option<PlannedMotion> {
    let s = crate::logic::parse_scenario(&t.scenario).ok()?;
    let trajectory = s.trajectories.into_iter().find(|x| x.name == t.name)?;
    Some(PlannedMotion { scenario: t.scenario, trajectory, report: t.report.map(|r| r.report()) })
}

/// The planning controls.
#[component]
pub fn Planning(
    parsed: Memo<Parsed>,
    source: RwSignal<String>,
    planned: RwSignal<Option<Shared<Planned>>>,
    settings: RwSignal<Settings>,
    growing: RwSignal<Option<WireAtlas>>,
    trajectory: RwSignal<usize>,
    origin: RwSignal<&'static str>,
) -> impl IntoView {
    let query = RwSignal::new(String::new());
    // the planner is one of the page's settings (kept in the address)
    let planner_id = Memo::new(move |_| settings.with(|s| s.planner));
    let budget = RwSignal::new(20_000usize);
    // the atlas planner's angles as plain coordinates, paper 1's way (`--identify-angles false`)
    let paper = RwSignal::new(false);
    let ui = Ui { state: RwSignal::new(RunState::Idle), progress: RwSignal::new(0.0), detail: RwSignal::new(String::new()), planned, growing, chain_path: RwSignal::new(None) };
    let worker = Rc::new(Resident::new());
    // each run has a generation: replies of older runs are ignored
    let generation = Rc::new(std::cell::Cell::new(0u32));

    let queries = move || parsed.get().0.as_ref().as_ref().map(|s| s.queries.iter().map(|q| q.name.clone()).collect::<Vec<_>>()).unwrap_or_default();
    // a multi-link robot: only the lattice planner plans it (the atlas planner refuses it)
    let chain = move || parsed.with(|p| p.0.as_ref().as_ref().is_ok_and(|s| s.robot.chain.is_some()));
    // a new scenario stops any run and selects its first query (and, for a multi-link robot, the
    // lattice planner)
    let (worker1, gen1) = (worker.clone(), generation.clone());
    Effect::new(move |_| {
        query.set(queries().into_iter().next().unwrap_or_default());
        if chain() && planner_id.get_untracked() != LATTICE {
            settings.update(|s| s.planner = LATTICE);
        }
        gen1.set(gen1.get() + 1);
        worker1.forget();
        growing.set(None);
        ui.chain_path.set(None);
        ui.state.set(RunState::Idle);
        ui.progress.set(0.0);
        ui.detail.set(String::new());
    });

    let (worker2, gen2) = (worker.clone(), generation.clone());
    let start = move |_| {
        let Some(json) = source.try_get_untracked() else { return };
        if parsed.get_untracked().0.is_err() {
            return;
        }
        if !PLANNERS.iter().any(|(id, _, ok)| *ok && *id == planner_id.get_untracked()) {
            ui.state.set(RunState::Failed(format!("the planner “{}” is not available", planner_id.get_untracked())));
            return;
        }
        let steps = match settings.with_untracked(|s| lattice_steps(planner_id.get_untracked(), &s.steps)) {
            Ok(n) => n,
            Err(e) => return ui.state.set(RunState::Failed(e)),
        };
        let q = query.get_untracked();
        let identify_angles = !paper.get_untracked();
        let job = Job::Plan { scenario: json, query: q.clone(), planner: planner_id.get_untracked().to_string(), max_charts: budget.get_untracked(), steps, identify_angles };
        if planned.with_untracked(Option::is_some) {
            planned.set(None);
        }
        growing.set(None);
        ui.chain_path.set(None);
        gen2.set(gen2.get() + 1);
        let this = gen2.get();
        let gen = gen2.clone();
        let on_reply = move |reply: Reply| {
            if gen.get() == this {
                apply(reply, &q, ui);
            }
        };
        match worker2.send(&job, on_reply) {
            Err(e) => ui.state.set(RunState::Failed(e)),
            Ok(()) => {
                ui.progress.set(0.0);
                ui.detail.set("starting the planner in a worker…".into());
                ui.state.set(RunState::Running);
            }
        }
    };
    let (worker3, gen3) = (worker.clone(), generation.clone());
    let cancel = move |_| {
        gen3.set(gen3.get() + 1);
        worker3.stop();
        growing.set(None);
        ui.state.set(RunState::Cancelled);
        ui.detail.set("Cancelled: the planner's worker was stopped.".into());
    };
    let running = move || ui.state.get() == RunState::Running;
    // a multi-link robot's planned path added to the scenario (an edit, undoable) and selected
    let add_path = move |_| {
        let Some((text, _)) = ui.chain_path.get_untracked() else { return };
        let index = parsed.with_untracked(|p| p.0.as_ref().as_ref().map_or(0, |s| s.joint_paths.len()));
        source.set(text);
        origin.set("edited");
        trajectory.set(index);
    };
    let lattice = move || planner_id.get() == LATTICE;

    view! {
        <h2>"Planning"</h2>
        <div class="planning" data-testid="planning">
            <label>
                "Planner "
                <select data-testid="planner" on:change=move |ev| {
                    let id = event_target_value(&ev);
                    if let Some((id, _, _)) = PLANNERS.iter().find(|p| p.0 == id) {
                        settings.update(|s| s.planner = id)
                    }
                }>
                    {PLANNERS.map(|(id, label, ok)| view! {
                        <option value=id disabled=move || !ok || (chain() && id != LATTICE) selected=move || planner_id.get() == id>{label}</option>
                    })}
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
            <label title="grid values per free coordinate, both ends of its range included (cablenav plan --planner lattice --steps N)">
                "Lattice steps "
                <input class="num" type="number" min="2" max="10000" step="1" data-testid="plan-steps" disabled=move || !lattice()
                    prop:value=move || settings.with(|s| s.steps.clone())
                    on:change=move |ev| {
                        let text = event_target_value(&ev);
                        settings.update(|s| s.steps = text.trim().to_string())
                    } />
            </label>
            <label title="the angles as plain coordinates, as paper 1 plans (cablenav plan --identify-angles false): the poses' angles as the scenario writes them, no wrapping">
                <input type="checkbox" data-testid="plan-paper" disabled=lattice prop:checked=move || paper.get()
                    on:change=move |ev| paper.set(event_target_checked(&ev)) />
                " Paper coordinates"
            </label>
            <button data-testid="plan-run" on:click=start disabled=move || running() || queries().is_empty()>"Plan"</button>
            <button data-testid="plan-cancel" on:click=cancel disabled=move || !running()>"Cancel"</button>
            <progress data-testid="plan-progress" max="1" prop:value=move || ui.progress.get() aria-label="planning progress"></progress>
            {move || ui.chain_path.get().map(|(_, name)| view! { <button data-testid="plan-add-path" on:click=add_path>{format!("Add “{name}” to the scenario")}</button> })}
        </div>
        <p class="plan-status" data-testid="plan-status" data-state=move || ui.state.get().name().to_string() aria-live="polite">
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

    #[test]
    fn state_names() {
        assert_eq!(RunState::Done("no_path".into()).name(), "no_path");
        assert_eq!(RunState::Failed("x".into()).name(), "error");
        assert_eq!(PLANNERS.iter().filter(|p| p.2).count(), 2, "the atlas and the ray lattice");
        assert!(PLANNERS.iter().any(|p| p.0 == LATTICE));
    }

    #[test]
    fn steps_are_whole_numbers_for_the_lattice_only() {
        assert_eq!(lattice_steps(LATTICE, " 9 "), Ok(9));
        assert_eq!(lattice_steps(LATTICE, "1"), Ok(1), "the range is the core's to check");
        assert_eq!(lattice_steps(LATTICE, "7.5"), Err("--steps: not a whole number: \"7.5\"".into()));
        assert_eq!(lattice_steps(LATTICE, ""), Err("--steps: not a whole number: \"\"".into()));
        assert_eq!(lattice_steps(PLANNERS[0].0, "nonsense"), Ok(7), "the atlas has no steps");
    }
}
