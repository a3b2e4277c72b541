//! The workbench: the stage (the 3-D view with the platform animated along a path, and the
//! strip) and the results in tabs (tables, planning, plots, slice map, lattice, exports). It reads the
//! scenario and the verification the page already computed ([`PageState`]), and computes
//! everything else through the core.

use crate::results::{ResultTables, StripResult};
use crate::logic::Tick;
use crate::state::{Focus, Follow, PageState, Parsed, Planned, Shared, Tab, Verified};
use crate::tabs::{TabList, TabPanel};
use crate::logic::{self, fmt_num, StripModel};
use crate::joints::JointSliders;
use crate::planning::Planning;
use crate::plots::distance::DistancePlot;
use crate::plots::export;
use crate::plots::lattice::LatticePanel;
use crate::plots::slice::{Overlay, SlicePanel};
use crate::plots::tension::TensionPlot;
use crate::view3d::scene::{self, Polyline, SceneInput, Shown, PATH};
use crate::edit_logic::{self as el, handles, Grip, Handle};
use crate::view3d::drag::Constraint;
use crate::view3d::{HandleEvent, Handles, SceneView, View3d};
use crate::worker::host;
use crate::worker::protocol::{pose_to_wire, Job, Reply};
use cablenav::report::TensionEnvelope;
use cablenav::verify::profile::ClearanceProfile;
use glam::DVec3;
use cablenav::model::{Pose, Trajectory};
use cablenav::verify::profile;
use cablenav::Scenario;
use leptos::prelude::*;

/// Samples per path for the clearance and tension plots.
const PLOT_SAMPLES: usize = 200;

/// Milliseconds since the page started (for timing updates).
fn now_ms() -> f64 {
    web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now())
}

/// The path being followed, resolved.
enum PathRef<'a> {
    Trajectory(&'a Trajectory),
    Planned(&'a Planned),
}

impl PathRef<'_> {
    /// The pose at fraction `u` ∈ [0, 1]: the trajectory at t = u, or the planned path's pose
    /// nearest to fraction u of its poses (the path is the planner's own dense sequence).
    fn pose_at(&self, u: f64) -> Option<Pose> {
        match self {
            PathRef::Trajectory(t) => Some(t.pose_at(u.clamp(0.0, 1.0))),
            PathRef::Planned(p) => {
                let n = p.poses.len();
                (n > 0).then(|| p.poses[((u.clamp(0.0, 1.0) * (n - 1) as f64).round() as usize).min(n - 1)])
            }
        }
    }

    /// `(parameter, pose)` samples for plots and exports: t for a trajectory, the fraction of
    /// poses for a planned path (all of them).
    fn samples(&self, n: usize) -> Vec<(f64, Pose)> {
        match self {
            PathRef::Trajectory(t) => (0..=n).map(|k| k as f64 / n as f64).map(|u| (u, t.pose_at(u))).collect(),
            PathRef::Planned(p) => {
                let m = p.poses.len().max(2) - 1;
                p.poses.iter().enumerate().map(|(k, pose)| (k as f64 / m as f64, *pose)).collect()
            }
        }
    }

    fn name(&self) -> String {
        match self {
            PathRef::Trajectory(t) => format!("trajectory “{}”", t.name),
            PathRef::Planned(p) => format!("planned path {}", p.query),
        }
    }

    /// The scenario trajectory followed (its name and duration), if the path is one.
    fn timed(&self) -> Option<(String, Option<f64>)> {
        match self {
            PathRef::Trajectory(t) => Some((t.name.clone(), t.duration)),
            PathRef::Planned(_) => None,
        }
    }

    fn param(&self) -> &'static str {
        match self {
            PathRef::Trajectory(_) => "t",
            PathRef::Planned(_) => "fraction",
        }
    }
}

/// The scenario, if it parsed.
fn scenario_of(parsed: &Parsed) -> Option<&Scenario> {
    parsed.0.as_ref().as_ref().ok()
}

/// Runs `f` on the followed path of the parsed scenario: the planned path when it is followed
/// and exists, else trajectory `traj` (clamped to the scenario's).
fn on_path<T>(parsed: &Parsed, planned: Option<&Shared<Planned>>, follow: Follow, traj: usize, f: impl FnOnce(&Scenario, PathRef) -> Option<T>) -> Option<T> {
    let s = scenario_of(parsed)?;
    match (follow, planned) {
        (Follow::Planned, Some(p)) => f(s, PathRef::Planned(&p.0)),
        _ => f(s, PathRef::Trajectory(s.trajectories.get(traj.min(s.trajectories.len().saturating_sub(1)))?)),
    }
}

/// Configurations per unit of t when drawing a multi-link robot's path on a cross-section.
const CONFIGS_PER_T: f64 = 120.0;

/// A multi-link robot's path over a cross-section: its verified sections as coloured pieces of
/// configurations, and its ends.
fn joint_overlay(s: &Scenario, along: cablenav::verify::Along, model: &StripModel) -> Overlay {
    let joint_pieces = model
        .sections
        .iter()
        .map(|sec| {
            let n = (((sec.t1 - sec.t0) * CONFIGS_PER_T).ceil() as usize).max(1);
            let qs = (0..=n).map(|k| along.config_at(s, sec.t0 + (sec.t1 - sec.t0) * k as f64 / n as f64)).collect();
            (scene::kind_colour(sec.kind), qs)
        })
        .collect();
    Overlay { joint_pieces, joint_ends: [Some(along.config_at(s, 0.0)), Some(along.config_at(s, 1.0))], ..Overlay::default() }
}

/// Whether the parsed scenario is a multi-link robot.
fn is_chain(parsed: &Parsed) -> bool {
    scenario_of(parsed).is_some_and(|s| s.robot.chain.is_some())
}

/// A multi-link robot's path `index` (clamped to its paths), if it has any.
fn joint_path(s: &Scenario, index: usize) -> Option<cablenav::verify::Along<'_>> {
    let all = cablenav::verify::all_along(s);
    logic::trajectory_index(s, index).filter(|_| s.robot.chain.is_some()).map(|i| all[i])
}

/// [`on_path`] reading (and so tracking) the signals it depends on.
fn followed<T>(
    parsed: Memo<Parsed>,
    planned: RwSignal<Option<Shared<Planned>>>,
    follow: RwSignal<Follow>,
    trajectory: RwSignal<usize>,
    f: impl FnOnce(&Scenario, PathRef) -> Option<T>,
) -> Option<T> {
    on_path(&parsed.get(), planned.get().as_ref(), follow.get(), trajectory.get(), f)
}

/// The workbench: the stage (3-D view, scrubber, strip) on the first screen and, outside embed
/// mode, the results in tabs ([`crate::tabs`]; tables, planning, plots, slice map, lattice,
/// exports, the view's key).
#[component]
pub fn Workbench(page: PageState, embed: bool) -> impl IntoView {
    let PageState { parsed, verified, live_ms, trajectory, planned, origin, source, history, settings } = page;
    let scrub = RwSignal::new(0.0f64);
    let follow = RwSignal::new(Follow::Trajectory);
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
        followed(parsed, planned, follow, trajectory, |_, path| path.pose_at(u))
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
            paths: &paths.0,
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
            tubes: tubes.iter().map(|(i, r)| format!("{}:{}", i + 1, logic::fmt_exact(*r))).collect::<Vec<_>>().join(" "),
        }))
    });

    // the plots along the path (clearances, tension envelope) are computed in one resident Web
    // Worker: a new path sends a job that supersedes the previous one; they follow a drag at its
    // end (the strip and the view follow every move)
    let profile_data = RwSignal::new(None::<Shared<(Result<ClearanceProfile, String>, String)>>);
    // the envelope, the x axis' name and (a timed trajectory) its duration
    let envelope = RwSignal::new(None::<Shared<(Result<TensionEnvelope, String>, &'static str, Option<f64>)>>);
    let plots_worker: StoredValue<host::Resident, LocalStorage> = StoredValue::new_local(host::Resident::new());
    Effect::new(move |_| {
        if drag_active.get() {
            return;
        }
        if is_chain(&parsed.get()) {
            plots_worker.with_value(host::Resident::forget);
            let e = "not drawn for multi-link robots yet: their clearances are certified in the strip and the intervals (docs/multilink.md)".to_string();
            profile_data.set(Some(Shared::new((Err(e.clone()), String::new()))));
            envelope.set(Some(Shared::new((Err("a multi-link robot has no wrench set: its wrench condition is joint-space wrench closure, in the strip".to_string()), "t", None))));
            return;
        }
        let request = followed(parsed, planned, follow, trajectory, |_, path| {
            let samples = path.samples(PLOT_SAMPLES).iter().map(|(t, p)| (*t, pose_to_wire(p))).collect();
            Some((path.name(), path.param(), samples, path.timed()))
        });
        let Some((name, param, samples, timed)) = request else {
            plots_worker.with_value(host::Resident::forget);
            profile_data.set(None);
            envelope.set(None);
            return;
        };
        let Some(json) = source.try_get_untracked() else { return };
        let label = format!("{name}; x: {param}");
        let (trajectory, duration) = match timed {
            Some((n, d)) => (Some(n), d),
            None => (None, None),
        };
        let on_reply = move |reply: Reply| {
            let (clearances, tension) = match reply {
                Reply::Progress { .. } => return,
                Reply::Profiles { clearances, tension } => (clearances.map(Into::into), tension.map(Into::into)),
                Reply::Failed { error } => (Err(error.clone()), Err(error)),
                _ => {
                    let e = "the worker answered a plots job with another job's reply".to_string();
                    (Err(e.clone()), Err(e))
                }
            };
            profile_data.set(Some(Shared::new((clearances, label.clone()))));
            envelope.set(Some(Shared::new((tension, param, duration))));
        };
        match plots_worker.with_value(|w| w.send(&Job::Profiles { scenario: json, name: name.clone(), samples, trajectory }, on_reply)) {
            Ok(()) => {}
            Err(e) => {
                profile_data.set(Some(Shared::new((Err(e.clone()), format!("{name}; x: {param}")))));
                envelope.set(Some(Shared::new((Err(e), param, duration))));
            }
        }
    });
    let overlay = Memo::new(move |_| {
        let parsed = parsed.get();
        let Some(s) = scenario_of(&parsed) else { return Overlay::default() };
        if let (Some(along), Some(model)) = (joint_path(s, trajectory.get()), strip.get()) {
            return joint_overlay(s, along, &model);
        }
        if s.robot.chain.is_some() {
            return Overlay::default();
        }
        match (follow.get(), planned.get()) {
            (Follow::Planned, Some(p)) => {
                let mut pieces = vec![Polyline { colour: PATH, poses: p.0.poses.clone() }];
                if !p.0.polyline.is_empty() {
                    pieces.push(Polyline { colour: crate::planning::POLYLINE, poses: p.0.polyline.clone() });
                }
                Overlay { start: Some(p.0.start), goal: Some(p.0.goal), pieces, ..Overlay::default() }
            }
            _ => {
                let t = s.trajectories.get(traj_index(s));
                Overlay { start: t.map(|t| t.pose_at(0.0)), goal: t.map(|t| t.pose_at(1.0)), pieces: (*trajectory_pieces.get().0).clone(), ..Overlay::default() }
            }
        }
    });

    // play: advance the scrubber by animation frames, a pass in 6 s
    let step_play = move |prev: f64| {
        fn frame(prev: f64, scrub: RwSignal<f64>, playing: RwSignal<bool>) {
            request_animation_frame(move || {
                if !playing.get_untracked() {
                    return;
                }
                let now = web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now());
                let dt = if prev > 0.0 { (now - prev) / 6000.0 } else { 0.0 };
                let next = scrub.get_untracked() + dt;
                if next >= 1.0 {
                    scrub.set(1.0);
                    playing.set(false);
                } else {
                    scrub.set(next);
                    frame(now, scrub, playing);
                }
            });
        }
        frame(prev, scrub, playing);
    };
    let toggle_play = move |_| {
        if playing.get_untracked() {
            playing.set(false);
        } else {
            if scrub.get_untracked() >= 1.0 {
                scrub.set(0.0);
            }
            playing.set(true);
            step_play(0.0);
        }
    };

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
            return Some(s.coords().iter().zip(&q).map(|(c, v)| format!("{} {}", s.coord_name(*c), fmt_num(*v))).collect::<Vec<_>>().join(" · "));
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

    // exports
    let export_intervals = move |_| {
        if let Some(m) = strip.get_untracked() {
            export::save("cablenav-intervals.csv", "text/csv", export::intervals_csv(&m).as_bytes());
        }
    };
    let copy_intervals = move |_| {
        if let Some(m) = strip.get_untracked() {
            export::copy(&export::intervals_csv(&m));
        }
    };
    let export_report = move |_| {
        if let Some(Ok(r)) = verified.get_untracked().0.as_ref() {
            export::save("cablenav-report.json", "application/json", serde_json::to_string_pretty(r).unwrap_or_default().as_bytes());
        }
    };
    let export_path = move |json: bool| {
        let text = untrack(|| {
            followed(parsed, planned, follow, trajectory, |_, path| {
                let samples = path.samples(PLOT_SAMPLES);
                Some(if json { export::poses_json(path.param(), &samples) } else { export::poses_csv(path.param(), &samples) })
            })
        });
        if let Some(text) = text {
            let (name, mime) = if json { ("cablenav-path.json", "application/json") } else { ("cablenav-path.csv", "text/csv") };
            export::save(name, mime, text.as_bytes());
        }
    };
    let export_plan = move |_| {
        if let Some(m) = planned.get_untracked().and_then(|p| p.0.motion.clone()) {
            export::save("cablenav-planned.json", "application/json", m.scenario.as_bytes());
        }
    };
    let export_view = move |_| {
        let canvas = web_sys::window()
            .and_then(|w| w.document())
            .and_then(|d| d.query_selector("canvas[data-testid=view3d]").ok().flatten())
            .and_then(|e| wasm_bindgen::JsCast::dyn_into::<web_sys::HtmlCanvasElement>(e).ok());
        if let Some(c) = canvas {
            export::save_canvas(&c, "cablenav-view.png");
        }
    };

    let follow_label = move || match follow.get() {
        Follow::Trajectory => "trajectory",
        Follow::Planned => "planned path",
    };

    let stage = view! {
        <section class="stage" class:chain=move || is_chain(&parsed.get()) data-testid="stage" aria-label="3-D view and verdict">
            <View3d scene=scene_view handles=handles_prop />
            {move || is_chain(&parsed.get()).then(|| view! {
                <JointSliders parsed shown=shown_config set=Callback::new(move |q| slid.set(Some(q))) />
            })}
            <div class="drag-bar" data-testid="drag-bar" hidden=move || is_chain(&parsed.get())>
                <label>
                    "Move "
                    <select data-testid="handle" on:change=move |ev| selected.set(event_target_value(&ev).parse::<usize>().ok())>
                        <option value="" selected=move || selected.get().is_none()>"(drag a yellow handle, or pick one)"</option>
                        {move || handle_list.get().into_iter().enumerate().map(|(i, h)| view! {
                            <option value=i.to_string() selected=move || selected.get() == Some(i)>{h.label}</option>
                        }).collect_view()}
                    </select>
                </label>
                <label>
                    " "
                    <select data-testid="drag-constraint" aria-label="drag constraint" on:change=move |ev| {
                        if let Some(c) = Constraint::from_id(&event_target_value(&ev)) {
                            constraint.set(c)
                        }
                    }>
                        {Constraint::CHOICES.map(|(c, id, label)| view! { <option value=id selected=move || constraint.get() == c>{label}</option> })}
                    </select>
                </label>
                <span class="nudge" role="group" aria-label="nudge the selected handle">
                    {[(0usize, "x"), (1, "y"), (2, "z")].map(|(axis, name)| view! {
                        <button class="small" data-testid=format!("nudge-{name}-minus") disabled=move || selected.get().is_none() on:click=move |_| nudge(axis, -1.0)
                            aria-label=format!("move the selected handle by −step along {name}")>{format!("−{name}")}</button>
                        <button class="small" data-testid=format!("nudge-{name}-plus") disabled=move || selected.get().is_none() on:click=move |_| nudge(axis, 1.0)
                            aria-label=format!("move the selected handle by +step along {name}")>{format!("+{name}")}</button>
                    })}
                </span>
                <label>
                    " step "
                    <input class="num" type="number" min="0.001" step="0.01" data-testid="nudge-step" prop:value=move || nudge_step.get().to_string()
                        on:change=move |ev| {
                            if let Some(v) = event_target_value(&ev).trim().parse::<f64>().ok().filter(|v| v.is_finite() && *v > 0.0) {
                                nudge_step.set(v)
                            }
                        } />
                    " m"
                </label>
                <span class="readout" data-testid="handle-readout" data-update-ms=move || update_ms.get().map(|t| format!("{t:.3}")).unwrap_or_default()
                    data-verify-ms=move || live_ms.get().map(|t| format!("{t:.3}")).unwrap_or_default()>
                    {move || {
                        let at = selected.get().and_then(|i| handle_list.with(|h| h.get(i).map(|h| h.at)));
                        let pos = at.map(|p| format!("at x {} y {} z {} m", fmt_num(p[0]), fmt_num(p[1]), fmt_num(p[2]))).unwrap_or_default();
                        let t = update_ms.get().map(|t| format!(" · last update {t:.1} ms (edit and scene)")).unwrap_or_default();
                        let v = live_ms.get().map(|t| format!(", exact verification {t:.1} ms in a worker")).unwrap_or_default();
                        format!("{pos}{t}{v}")
                    }}
                </span>
            </div>
            <div class="scrubber">
                <label>
                    "Follow "
                    <select data-testid="follow" on:change=move |ev| {
                        follow.set(if event_target_value(&ev) == "planned" { Follow::Planned } else { Follow::Trajectory });
                        scrub.set(0.0);
                    }>
                        <option value="trajectory" selected=move || follow.get() == Follow::Trajectory>"trajectory"</option>
                        <option value="planned" selected=move || follow.get() == Follow::Planned disabled=move || planned.get().is_none()>
                            "planned path"
                        </option>
                    </select>
                </label>
                <button data-testid="play" on:click=toggle_play>{move || if playing.get() { "Pause" } else { "Play" }}</button>
                <input
                    data-testid="scrubber"
                    type="range"
                    min="0"
                    max="1000"
                    step="1"
                    aria-label=move || format!("position along the {}", follow_label())
                    prop:value=move || (scrub.get() * 1000.0).round().to_string()
                    on:input=move |ev| {
                        if let Ok(v) = event_target_value(&ev).parse::<f64>() {
                            playing.set(false);
                            scrub.set(v / 1000.0)
                        }
                    }
                />
                <span class="readout" data-testid="pose-readout">{move || format!("{} = {} · {}", if follow.get() == Follow::Trajectory { "t" } else { "fraction" }, fmt_num(scrub.get()), readout().unwrap_or_default())}</span>
            </div>
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
            </TabPanel>
            <TabPanel of=Tab::Planning open=tab>
                <Planning parsed source planned settings />
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
                    <label>
                        <input type="checkbox" data-testid="lattice-in-view" prop:checked=move || lattice_in_view.get()
                            on:change=move |ev| lattice_in_view.set(event_target_checked(&ev)) />
                        " draw the lattice in the 3-D view (feasible pieces in their component's colour)"
                    </label>
                    <label>
                        <input type="checkbox" data-testid="lattice-infeasible-in-view" prop:checked=move || lattice_infeasible.get()
                            on:change=move |ev| lattice_infeasible.set(event_target_checked(&ev)) />
                        " with the infeasible pieces in red"
                    </label>
                </p>
            </TabPanel>
            <TabPanel of=Tab::Exports open=tab>
                <h2>"Exports"</h2>
                <p class="exports">
                    <button data-testid="export-intervals-csv" on:click=export_intervals>"Intervals (CSV)"</button>
                    <button data-testid="copy-intervals" on:click=copy_intervals>"Copy intervals"</button>
                    <button data-testid="export-report-json" on:click=export_report>"Report (JSON, as the CLI prints)"</button>
                    <button data-testid="export-path-csv" on:click=move |_| export_path(false)>"Path poses (CSV)"</button>
                    <button data-testid="export-path-json" on:click=move |_| export_path(true)>"Path poses (JSON)"</button>
                    <button data-testid="export-planned-scenario" on:click=export_plan disabled=move || planned.get().is_none_or(|p| p.0.motion.is_none())
                        title="the scenario with the planned trajectory added, as cablenav plan --out writes it">"Scenario with the plan (JSON)"</button>
                    <button data-testid="export-view-png" on:click=export_view>"3-D view (PNG)"</button>
                </p>
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
                <p class="legend">"Drag to orbit, right-drag or shift-drag to pan, wheel or pinch to zoom; with the view focused, arrow keys orbit and + / − zoom."</p>
            </TabPanel>
        </section>
    }
    .into_any()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::{find, PRESETS};

    fn robocrane() -> Scenario {
        logic::parse_scenario(PRESETS[find("robocrane").unwrap()].json).unwrap()
    }

    #[test]
    fn a_trajectory_is_followed_in_t() {
        let s = robocrane();
        let t = &s.trajectories[0];
        let path = PathRef::Trajectory(t);
        assert_eq!(path.pose_at(0.25), Some(t.pose_at(0.25)));
        assert_eq!(path.pose_at(7.0), Some(t.pose_at(1.0)), "clamped");
        let samples = path.samples(4);
        assert_eq!(samples.iter().map(|x| x.0).collect::<Vec<_>>(), [0.0, 0.25, 0.5, 0.75, 1.0]);
        assert_eq!(samples[2].1, t.pose_at(0.5));
        assert_eq!(path.param(), "t");
    }

    #[test]
    fn a_planned_path_is_followed_pose_by_pose() {
        let s = robocrane();
        let poses: Vec<Pose> = (0..5).map(|k| s.trajectories[0].pose_at(k as f64 / 4.0)).collect();
        let p = Planned { query: "q1-q2".into(), start: poses[0], goal: poses[4], poses: poses.clone(), polyline: vec![], motion: None };
        let path = PathRef::Planned(&p);
        assert_eq!(path.pose_at(0.0), Some(poses[0]));
        assert_eq!(path.pose_at(0.5), Some(poses[2]));
        assert_eq!(path.pose_at(0.6), Some(poses[2]), "the nearest pose, not an interpolation");
        assert_eq!(path.pose_at(1.0), Some(poses[4]));
        let samples = path.samples(200);
        assert_eq!(samples.len(), 5, "every pose, whatever the sample count");
        assert_eq!(samples[4], (1.0, poses[4]));
        assert_eq!(path.param(), "fraction");
        let empty = Planned { poses: vec![], ..p };
        assert_eq!(PathRef::Planned(&empty).pose_at(0.5), None);
    }

    #[test]
    fn the_followed_path_falls_back_to_the_trajectory() {
        let s = robocrane();
        let parsed: Parsed = Shared::new(Ok(s.clone()));
        let name = |follow, planned: Option<&Shared<Planned>>| on_path(&parsed, planned, follow, 9, |_, p| Some(p.name()));
        assert_eq!(name(Follow::Planned, None).as_deref(), Some("trajectory “slerp q1-q2”"), "no plan: the (clamped) trajectory");
        let pose = s.trajectories[0].pose_at(0.0);
        let plan = Shared::new(Planned { query: "q1-q2".into(), start: pose, goal: pose, poses: vec![pose], polyline: vec![], motion: None });
        assert_eq!(name(Follow::Planned, Some(&plan)).as_deref(), Some("planned path q1-q2"));
        assert_eq!(name(Follow::Trajectory, Some(&plan)).as_deref(), Some("trajectory “slerp q1-q2”"));
        let broken: Parsed = Shared::new(Err("bad".into()));
        assert_eq!(on_path(&broken, None, Follow::Trajectory, 0, |_, p| Some(p.name())), None);
    }
}
