//! The workbench: the stage (the 3-D view with the platform animated along a path, and the
//! strip) and the results in tabs (tables, planning, plots, slice map, lattice, exports). It reads the
//! scenario and the verification the page already computed ([`PageState`]), and computes
//! everything else through the core. This file wires the page's signals together; the parts are
//! its own files: the followed path (`path`), the stage's drag bar (`stage`), playback
//! (`playback`), the plots' worker (`plot_jobs`) and the Exports tab (`exports`).

mod every;
mod exports;
mod fastest;
mod path;
mod playback;
mod plot_jobs;
mod stage;

use crate::edit_logic::{self as el, handles, Grip, Handle};
use crate::joints::JointSliders;
use crate::logic::{self, fmt_num, StripModel, Tick};
use crate::palette::PATH;
use crate::planning::Planning;
use crate::plots::distance::DistancePlot;
use crate::plots::lattice::LatticePanel;
use crate::plots::section::Overlay;
use crate::plots::slice::SlicePanel;
use crate::plots::tension::TensionPlot;
use crate::results::{ResultTables, StripResult};
use crate::state::{Focus, Follow, PageState, Shared, Tab, Verified};
use crate::tabs::{TabList, TabPanel};
use crate::view3d::drag::Constraint;
use crate::view3d::scene::{self, Polyline, SceneInput, Shown};
use crate::view3d::{HandleEvent, Handles, SceneView, View3d};
use cablenav::model::Pose;
use cablenav::verify::profile;
use cablenav::Scenario;
use exports::Exports;
use glam::DVec3;
use leptos::prelude::*;
use path::{is_chain, is_planar, joint_overlay, joint_path, scenario_of, PathSignals};
use playback::Scrubber;
use stage::DragBar;

/// Milliseconds since the page started (for timing updates).
fn now_ms() -> f64 {
    web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now())
}

/// The workbench: the stage (3-D view, scrubber, strip) on the first screen and, outside embed
/// mode, the results in tabs ([`crate::tabs`]; tables, planning, plots, slice map, lattice,
/// exports, the view's key).
#[component]
pub fn Workbench(page: PageState, embed: bool) -> impl IntoView {
    let PageState { parsed, verified, live_ms, trajectory, planned, origin, source, history, settings } = page;
    let scrub = RwSignal::new(0.0f64);
    let follow = RwSignal::new(Follow::Trajectory);
    let path = PathSignals { parsed, planned, follow, trajectory };
    // the atlas planner's atlas while a run grows it, drawn in place of any other
    let growing = RwSignal::new(None::<crate::worker::protocol::WireAtlas>);
    let playing = RwSignal::new(false);
    // the drag in progress: what it moves, and the scenario tree it edits
    let dragging: StoredValue<Option<(Grip, serde_json::Value)>> = StoredValue::new(None);

    // a new scenario drops the planned path and rewinds (not while dragging: the platform stays)
    Effect::new(move |_| {
        parsed.track();
        if planned.with_untracked(Option::is_some) {
            planned.set(None);
        }
        follow.set(Follow::Trajectory);
        if dragging.with_value(Option::is_none) {
            scrub.set(0.0);
        }
    });

    // the draggable handles of the scenario and the selected trajectory (edit_logic::handles)
    let handle_list: Memo<Vec<Handle>> = Memo::new(move |_| {
        if is_chain(&parsed.get()) {
            return vec![]; // a multi-link robot is posed by its joint sliders
        }
        source.with(|s| serde_json::from_str::<serde_json::Value>(s).ok()).map_or_else(Vec::new, |doc| handles(&doc, trajectory.get()))
    });
    let selected = RwSignal::new(None::<usize>);
    let constraint = RwSignal::new(Constraint::View);
    // a planar robot moves in the plane z = 0: its points are dragged in the xy plane unless the
    // user picks otherwise
    Effect::new(move |_| {
        if is_planar(&parsed.get()) && constraint.get_untracked() == Constraint::View {
            constraint.set(Constraint::Plane(2));
        }
    });
    let update_ms = RwSignal::new(None::<f64>);
    let drag_active = RwSignal::new(false);
    let nudge_step = RwSignal::new(0.05f64);
    // a new scenario or trajectory with fewer handles drops a selection past the end
    Effect::new(move |_| {
        let n = handle_list.with(Vec::len);
        if selected.get_untracked().is_some_and(|i| i >= n) {
            selected.set(None);
        }
    });
    // a new plan is followed at once
    Effect::new(move |_| {
        if planned.get().is_some() {
            follow.set(Follow::Planned);
            scrub.set(0.0);
        }
    });

    // the verification the strip, the tables and the 3-D sections show: the planned motion's
    // while the planned path is followed, else the selected trajectory's
    let motion = move || planned.get().filter(|_| follow.get() == Follow::Planned).filter(|p| p.0.motion.is_some());
    let shown: Memo<Verified> = Memo::new(move |_| match motion() {
        Some(p) => Shared::new(p.0.motion.as_ref().map(|m| m.report.clone())),
        None => verified.get(),
    });
    let strip: Memo<Option<StripModel>> = Memo::new(move |_| match shown.get().0.as_ref() {
        Some(Ok(r)) => Some(logic::strip(r)),
        _ => None,
    });
    let traj_index = move |s: &Scenario| trajectory.get().min(s.trajectories.len().saturating_sub(1));
    let trajectory_pieces: Memo<Shared<Vec<Polyline>>> = Memo::new(move |prev| {
        let parsed = parsed.get();
        let pieces = match (scenario_of(&parsed), strip.get(), motion()) {
            (_, Some(model), Some(p)) => p.0.motion.as_ref().map_or_else(Vec::new, |m| scene::section_polylines(&model, |t| m.trajectory.pose_at(t))),
            (Some(s), Some(model), None) => match (&s.robot.chain, joint_path(s, trajectory.get())) {
                (Some(chain), Some(along)) => scene::section_polylines(&model, |t| scene::end_pose(chain, &along.config_at(s, t))),
                _ if !s.trajectories.is_empty() => {
                    let traj = &s.trajectories[traj_index(s)];
                    scene::section_polylines(&model, |t| traj.pose_at(t))
                }
                _ => vec![],
            },
            _ => vec![],
        };
        Shared::or_same(prev, pieces)
    });
    // beside it: the planned path (unless it is the one drawn in its sections) and the lattice
    // planner's A* polyline
    let path_pieces: Memo<Shared<Vec<Polyline>>> = Memo::new(move |prev| {
        let Some(p) = planned.get() else { return Shared::or_same(prev, vec![]) };
        let mut pieces = vec![];
        if motion().is_none() {
            pieces.push(Polyline { colour: PATH, poses: p.0.poses.clone() });
        }
        if !p.0.polyline.is_empty() {
            pieces.push(Polyline { colour: crate::planning::POLYLINE, poses: p.0.polyline.clone() });
        }
        Shared::or_same(prev, pieces)
    });
    // every other trajectory beside the selected one, on request
    let every_on = RwSignal::new(false);
    let every_status = RwSignal::new(String::new());
    let selected_trajectory = Signal::derive(move || trajectory.get());
    let every_pieces = every::every_trajectory(parsed, source, selected_trajectory, every_on, every_status);
    // the ray lattice built in its panel, drawn in the 3-D view too
    let lattice = RwSignal::new(None::<Shared<Result<crate::worker::protocol::LatticeResult, String>>>);
    let lattice_in_view = RwSignal::new(true);
    let lattice_infeasible = RwSignal::new(false);
    let lattice_pieces: Memo<Shared<Vec<Polyline>>> = Memo::new(move |prev| {
        let parsed = parsed.get();
        let pieces = match (lattice.get(), lattice_in_view.get(), scenario_of(&parsed)) {
            (Some(l), true, Some(s)) => l.0.as_ref().as_ref().map_or_else(|_| vec![], |l| scene::lattice_polylines(s, l, lattice_infeasible.get())),
            _ => vec![],
        };
        Shared::or_same(prev, pieces)
    });

    // a boundary pointed at in the strip: the platform goes there, with its clearance tubes
    let focus = RwSignal::new(None::<Tick>);
    provide_context(Focus(focus));
    let focused = move || focus.get().filter(|_| follow.get() == Follow::Trajectory);
    let shown_pose: Memo<Option<Pose>> = Memo::new(move |_| {
        let u = focused().map_or_else(|| scrub.get(), |t| t.t);
        path.followed(|_, path| path.pose_at(u))
    });
    // a multi-link robot: the configuration shown, from the joint sliders once they are moved, else
    // along the selected path (the scrubber or a focused boundary)
    let slid = RwSignal::new(None::<Vec<f64>>);
    Effect::new(move |_| {
        parsed.track();
        scrub.track();
        slid.set(None);
    });
    let shown_config: Memo<Option<Vec<f64>>> = Memo::new(move |_| {
        let parsed = parsed.get();
        let s = scenario_of(&parsed).filter(|s| s.robot.chain.is_some())?;
        if let Some(q) = slid.get() {
            return Some(q);
        }
        let u = focused().map_or_else(|| scrub.get(), |t| t.t);
        match joint_path(s, trajectory.get()) {
            Some(along) => Some(along.config_at(s, u.clamp(0.0, 1.0))),
            None => s.config_names().first().and_then(|n| s.config(n).ok()),
        }
    });

    // the backdrop (grid, anchors, obstacles) is rebuilt only when what it shows changes
    let backdrop_key = Memo::new(move |_| scenario_of(&parsed.get()).map(scene::BackdropKey::of));
    let backdrop = Memo::new(move |_| backdrop_key.get().map(|k| Shared::new(scene::backdrop(&k))));
    let scene_view: Memo<Option<Shared<SceneView>>> = Memo::new(move |_| {
        let parsed = parsed.get();
        let s = scenario_of(&parsed)?;
        let backdrop = backdrop.get()?;
        let bounds = backdrop.0.bounds;
        let (shown, cables) = match (&s.robot.chain, shown_config.get()) {
            (Some(chain), Some(q)) => (Some(Shown::config(chain, &q)), profile::cable_states_at(s, &q)),
            (Some(_), None) => (None, vec![]),
            (None, _) => {
                let pose = shown_pose.get();
                (pose.map(Shown::Platform), pose.map(|p| profile::cable_states(s, &p)).unwrap_or_default())
            }
        };
        let tubes = focused().map(|t| scene::clearance_tubes(s, &t.constraint)).unwrap_or_default();
        let pieces = trajectory_pieces.get();
        let paths = path_pieces.get();
        let others = every_pieces.get();
        let other_pieces = others.0.len();
        let paths: Vec<Polyline> = paths.0.iter().chain(others.0.iter()).cloned().collect();
        let lattice = lattice_pieces.get();
        let points: Vec<DVec3> = handle_list.with(|h| h.iter().map(|h| DVec3::from_array(h.at)).collect());
        let axis = match constraint.get() {
            Constraint::Axis(k) => Some(k),
            _ => None,
        };
        let geometry = scene::build(&SceneInput {
            scenario: s,
            shown,
            cables: &cables,
            trajectory: &pieces.0,
            paths: &paths,
            lattice: &lattice.0,
            handles: &points,
            selected: selected.get(),
            axis,
            tubes: &tubes,
        }, bounds);
        let sections = strip
            .get()
            .map(|m| m.sections.iter().map(|x| format!("{}:{}:{}", x.kind.as_str(), logic::fmt_exact(x.t0), logic::fmt_exact(x.t1))).collect::<Vec<_>>().join(" "))
            .unwrap_or_default();
        Some(Shared::new(SceneView {
            backdrop,
            geometry,
            bounds,
            sections,
            cables: cables.iter().map(|c| scene::cable_look(c).0).collect::<Vec<_>>().join(" "),
            path_poses: planned.get().map_or(0, |p| p.0.poses.len()),
            polyline_poses: planned.get().map_or(0, |p| p.0.polyline.len()),
            lattice_pieces: lattice.0.len(),
            other_pieces,
            tubes: tubes.iter().map(|(i, r)| format!("{}:{}", i + 1, logic::fmt_exact(*r))).collect::<Vec<_>>().join(" "),
        }))
    });

    let (profile_data, envelope) = plot_jobs::profiles_in_worker(path, source, drag_active);
    let overlay = Memo::new(move |_| {
        let parsed = parsed.get();
        let Some(s) = scenario_of(&parsed) else { return Overlay::default() };
        if let (Some(along), Some(model)) = (joint_path(s, trajectory.get()), strip.get()) {
            return joint_overlay(s, along, &model);
        }
        if s.robot.chain.is_some() {
            return Overlay::default();
        }
        let mut overlay = match (follow.get(), planned.get()) {
            (Follow::Planned, Some(p)) => {
                let mut pieces = vec![Polyline { colour: PATH, poses: p.0.poses.clone() }];
                if !p.0.polyline.is_empty() {
                    pieces.push(Polyline { colour: crate::planning::POLYLINE, poses: p.0.polyline.clone() });
                }
                Overlay { start: Some(p.0.start), goal: Some(p.0.goal), pieces, atlas: p.0.atlas.clone(), ..Overlay::default() }
            }
            _ => {
                let t = s.trajectories.get(traj_index(s));
                Overlay { start: t.map(|t| t.pose_at(0.0)), goal: t.map(|t| t.pose_at(1.0)), pieces: (*trajectory_pieces.get().0).clone(), ..Overlay::default() }
            }
        };
        if let Some(atlas) = growing.get() {
            overlay.atlas = Some(atlas);
        }
        overlay
    });

    // a drag: one undo step; every move rewrites the scenario, which re-verifies exactly (the
    // `verified` memo) and repaints the strip, the view and the editor's fields
    let on_handle = Callback::new(move |ev: HandleEvent| match ev {
        HandleEvent::Begin(i) => {
            let grip = handle_list.with_untracked(|h| h.get(i).map(|h| h.grip));
            let doc = source.with_untracked(|s| serde_json::from_str::<serde_json::Value>(s).ok());
            if let (Some(grip), Some(doc)) = (grip, doc) {
                history.begin_batch();
                dragging.set_value(Some((grip, doc)));
                drag_active.set(true);
            }
        }
        HandleEvent::Move(_, to) => {
            let started = now_ms();
            let text = dragging
                .try_update_value(|d| {
                    let (grip, doc) = d.as_mut()?;
                    el::move_grip(doc, *grip, to).ok()?;
                    serde_json::to_string_pretty(doc).ok()
                })
                .flatten();
            if let Some(text) = text {
                source.set(text);
                origin.set("edited");
                // rebuild the scene now, to time the main thread's whole update (the exact
                // verification runs in a worker meanwhile: crate::live)
                verified.with_untracked(|_| ());
                scene_view.with_untracked(|_| ());
                update_ms.set(Some(now_ms() - started));
            }
        }
        HandleEvent::End => {
            dragging.set_value(None);
            drag_active.set(false);
            history.end_batch();
        }
    });
    let handles_prop = Handles {
        points: Signal::derive(move || handle_list.with(|h| h.iter().map(|h| DVec3::from_array(h.at)).collect())),
        selected,
        constraint,
        on_event: on_handle,
    };
    let nudge = move |axis: usize, sign: f64| {
        let Some(i) = selected.get_untracked() else { return };
        let Some(at) = handle_list.with_untracked(|h| h.get(i).map(|h| h.at)) else { return };
        on_handle.run(HandleEvent::Begin(i));
        on_handle.run(HandleEvent::Move(i, crate::view3d::drag::nudge(at, axis, sign * nudge_step.get_untracked())));
        on_handle.run(HandleEvent::End);
    };

    let readout = move || {
        if let (Some(q), Ok(s)) = (shown_config.get(), parsed.get().0.as_ref()) {
            return Some(s.coords().iter().filter_map(|c| q.get(c.index()).map(|v| format!("{} {}", s.coord_name(*c), fmt_num(*v)))).collect::<Vec<_>>().join(" · "));
        }
        let pose = shown_pose.get()?;
        let c = pose.coords();
        Some(format!(
            "x {} y {} z {} m · φ {} θ {} σ {} rad",
            fmt_num(c[0]),
            fmt_num(c[1]),
            fmt_num(c[2]),
            fmt_num(c[3]),
            fmt_num(c[4]),
            fmt_num(c[5])
        ))
    };

    let stage = view! {
        <section class="stage" class:chain=move || is_chain(&parsed.get()) data-testid="stage" aria-label="3-D view and verdict">
            <View3d scene=scene_view handles=handles_prop />
            {move || is_chain(&parsed.get()).then(|| view! {
                <JointSliders parsed shown=shown_config set=Callback::new(move |q| slid.set(Some(q))) />
            })}
            <DragBar hidden=Signal::derive(move || is_chain(&parsed.get())) handle_list selected constraint nudge_step update_ms live_ms
                on_nudge=Callback::new(move |(axis, sign)| nudge(axis, sign)) />
            <Scrubber scrub follow playing planned readout=Signal::derive(readout) />
            <StripResult parsed verified=shown trajectory origin planned=Signal::derive(move || motion().is_some()) />
        </section>
    };
    if embed {
        return stage.into_any();
    }
    let tab = Memo::new(move |_| settings.with(|s| s.tab));
    let pick_tab = move |t: Tab| settings.update(|s| s.tab = t);
    view! {
        {stage}
        <section class="results" data-testid="results" aria-label="results">
            <TabList open=tab on_pick=pick_tab />
            <TabPanel of=Tab::Intervals open=tab>
                <ResultTables parsed verified=shown />
                <fastest::FastestTiming parsed source trajectory=selected_trajectory />
            </TabPanel>
            <TabPanel of=Tab::Planning open=tab>
                <Planning parsed source planned settings growing trajectory origin />
            </TabPanel>
            <TabPanel of=Tab::Clearances open=tab wide=true>
                <h2>"Clearances along the path"</h2>
                <DistancePlot
                    profile=Signal::derive(move || profile_data.get().map(|p| p.0.0.clone()))
                    label=Signal::derive(move || profile_data.get().map(|p| p.0.1.clone()).unwrap_or_default())
                    certified=Signal::derive(move || match (follow.get(), strip.get()) {
                        (Follow::Trajectory, Some(m)) => m.ticks.iter().map(|t| (t.t, t.label.clone())).collect(),
                        _ => vec![],
                    })
                />
            </TabPanel>
            <TabPanel of=Tab::Tension open=tab wide=true>
                <h2>"Tension envelope"</h2>
                <TensionPlot
                    envelope=Signal::derive(move || envelope.get().map(|e| e.0.0.clone()))
                    param=Signal::derive(move || envelope.get().map_or("t", |e| e.0.1))
                    duration=Signal::derive(move || envelope.get().and_then(|e| e.0.2))
                />
            </TabPanel>
            <TabPanel of=Tab::Slice open=tab wide=true>
                <h2>"Slice map"</h2>
                <SlicePanel parsed source overlay=Signal::derive(move || overlay.get()) />
            </TabPanel>
            <TabPanel of=Tab::Lattice open=tab wide=true>
                <h2>"Ray lattice"</h2>
                <LatticePanel parsed source lattice overlay=Signal::derive(move || overlay.get()) />
                <p class="lattice-3d">
                    <Toggle testid="lattice-in-view" value=lattice_in_view label=" draw the lattice in the 3-D view (feasible pieces in their component's colour)" />
                    <Toggle testid="lattice-infeasible-in-view" value=lattice_infeasible label=" with the infeasible pieces in red" />
                </p>
            </TabPanel>
            <TabPanel of=Tab::Exports open=tab>
                <Exports path strip verified />
            </TabPanel>
            <TabPanel of=Tab::ViewKey open=tab>
                <h2>"3-D view: colours and controls"</h2>
                <p class="legend">
                    "Path: " <span class="swatch feasible"></span> "feasible " <span class="swatch infeasible"></span> "infeasible "
                    <span class="swatch" style="background: rgb(107,59,212)"></span> "planned (thick: platform origin; thin: a point on its z axis). "
                    "Cables: " <span class="swatch" style="background: rgb(59,112,217)"></span> "tension margin ≥ ¼ of the bounds' span, "
                    <span class="swatch" style="background: rgb(230,145,31)"></span> "margin near 0, "
                    <span class="swatch" style="background: rgb(143,59,212)"></span> "tension out of bounds, "
                    <span class="swatch infeasible"></span> "interfering or length out of bounds, "
                    <span class="swatch" style="background: rgb(51,64,77)"></span> "no wrench set."
                </p>
                <p class="legend">
                    <Toggle testid="every-trajectory" value=every_on
                        label=" draw every trajectory of the scenario, each in its exact sections (a family of paths, as the thesis' Figs. 4.4, 4.6 and 4.7 show them)" />
                    " "
                    <span class="readout" data-testid="every-status" aria-live="polite">{move || every_status.get()}</span>
                </p>
                <p class="legend">"Drag to orbit, right-drag or shift-drag to pan, wheel or pinch to zoom; with the view focused, arrow keys orbit and + / − zoom."</p>
            </TabPanel>
        </section>
    }
    .into_any()
}

/// A checkbox bound to `value`, with its `label` and `testid` (for tests).
#[component]
fn Toggle(testid: &'static str, value: RwSignal<bool>, label: &'static str) -> impl IntoView {
    view! {
        <label>
            <input type="checkbox" data-testid=testid prop:checked=move || value.get() on:change=move |ev| value.set(event_target_checked(&ev)) />
            {label}
        </label>
    }
}
