//! The ray lattice as a cross-section (thesis Figs. 3.9–3.10, 4.1–4.3): over two chosen
//! coordinates (the others from a chosen pose) the core's [`Lattice`] is built ray by ray from
//! animation frames, with progress and Cancel; each ray is drawn red where infeasible and, where
//! feasible, in its piece's component colour, with the start, the goal, the planned path and the
//! lattice planner's A* polyline over it.

use super::geom::{polyline, ticks, Scale};
use super::slice::{default_axes, default_pose, default_range, path_points, slice_copies, Overlay};
use super::strip::css;
use super::Chart;
use crate::state::Shared;
use crate::logic::fmt_num;
use cablenav::lattice::{Lattice, LatticeReport, LatticeSpec};
use cablenav::model::Coord;
use leptos::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

const W: f64 = 520.0;
const H: f64 = 500.0;
const LEFT: f64 = 56.0;
const RIGHT: f64 = 14.0;
const TOP: f64 = 14.0;
const BOTTOM: f64 = 46.0;
/// Milliseconds of lattice work per animation frame.
const SLICE_MS: f64 = 8.0;
/// Colour of infeasible ray parts.
pub const INFEASIBLE: &str = "#d03b3b";
/// Component colours, in turn (the first is the thesis' green).
pub const COMPONENTS: [&str; 8] = ["#2ea043", "#3b6fd8", "#8e44ad", "#e0a800", "#16a2b8", "#c2185b", "#6d8b00", "#795548"];

/// One drawn stretch of a ray, in data coordinates: (a0, b0) → (a1, b1) and its colour.
#[derive(Debug, Clone, PartialEq)]
pub struct Stretch {
    /// Start, along the first and second axes.
    pub from: (f64, f64),
    /// End.
    pub to: (f64, f64),
    /// CSS colour: [`INFEASIBLE`] or a component's.
    pub colour: &'static str,
    /// The component of a feasible stretch.
    pub component: Option<usize>,
}

/// Every ray of a 2-D lattice report as stretches: the feasible pieces in their component's colour
/// and the gaps between them (infeasible or uncertain) in red.
pub fn stretches(r: &LatticeReport) -> Vec<Stretch> {
    let mut out = vec![];
    for (ray, comps) in r.rays.iter().zip(&r.piece_components) {
        let along = usize::from(r.axes.get(1) == Some(&ray.vary));
        let other = r.axes[1 - along];
        let fixed = ray.fixed.iter().find(|(k, _)| *k == other).map_or(0.0, |p| p.1);
        let at = |v: f64| if along == 0 { (v, fixed) } else { (fixed, v) };
        let [lo, hi] = r.ranges[along];
        let mut cursor = lo;
        for (iv, &c) in ray.feasible.iter().zip(comps) {
            if iv[0] > cursor {
                out.push(Stretch { from: at(cursor), to: at(iv[0]), colour: INFEASIBLE, component: None });
            }
            out.push(Stretch { from: at(iv[0]), to: at(iv[1]), colour: COMPONENTS[c % COMPONENTS.len()], component: Some(c) });
            cursor = iv[1];
        }
        if cursor < hi {
            out.push(Stretch { from: at(cursor), to: at(hi), colour: INFEASIBLE, component: None });
        }
    }
    out
}

/// A lattice being built from animation frames.
struct Build {
    lattice: Lattice,
    generation: u32,
}

/// The cross-section's controls and plot.
#[component]
pub fn LatticePanel(parsed: Memo<crate::state::Parsed>, overlay: Signal<Overlay>) -> impl IntoView {
    let scenario = move || parsed.get().0.as_ref().as_ref().ok().cloned();
    let pose = RwSignal::new(String::new());
    let axes = RwSignal::new([Coord::X, Coord::Y]);
    let range = RwSignal::new([[0.0, 1.0]; 2]);
    let steps = RwSignal::new(7usize);
    let report = RwSignal::new(None::<Shared<Result<LatticeReport, String>>>);
    let progress = RwSignal::new(None::<(usize, usize)>);
    let build: Rc<RefCell<Option<Build>>> = Rc::new(RefCell::new(None));
    let generation = Rc::new(std::cell::Cell::new(0u32));
    let (b0, g0) = (build.clone(), generation.clone());
    Effect::new(move |_| {
        if let Some(s) = scenario() {
            let a = default_axes(&s);
            pose.set(default_pose(&s).unwrap_or_default());
            axes.set(a);
            range.set([default_range(&s, a[0]), default_range(&s, a[1])]);
            g0.set(g0.get() + 1);
            *b0.borrow_mut() = None;
            report.set(None);
            progress.set(None);
        }
    });
    let (b1, g1) = (build.clone(), generation.clone());
    let start = move |_| {
        let Some(s) = scenario() else { return };
        let spec = s
            .pose(&pose.get_untracked())
            .map_err(|e| e.to_string())
            .and_then(|p| LatticeSpec::new(axes.get_untracked().to_vec(), range.get_untracked().to_vec(), vec![steps.get_untracked()], p.coords()).map_err(|e| e.to_string()));
        match spec {
            Err(e) => report.set(Some(Shared::new(Err(e)))),
            Ok(spec) => {
                g1.set(g1.get() + 1);
                *b1.borrow_mut() = Some(Build { lattice: Lattice::new(&s, spec), generation: g1.get() });
                report.set(None);
                progress.set(Some((0, 1)));
                pump(b1.clone(), g1.get(), report, progress);
            }
        }
    };
    let (b2, g2) = (build.clone(), generation.clone());
    let cancel = move |_| {
        g2.set(g2.get() + 1);
        *b2.borrow_mut() = None;
        progress.set(None);
    };
    let set_axis = move |k: usize, name: String| {
        if let (Some(c), Some(s)) = (Coord::parse(&name), scenario()) {
            axes.update(|a| a[k] = c);
            range.update(|r| r[k] = default_range(&s, c));
        }
    };
    let set_range = move |k: usize, end: usize, text: String| {
        if let Ok(v) = text.trim().parse::<f64>() {
            range.update(|r| r[k][end] = v);
        }
    };
    let axis_select = move |k: usize| {
        view! {
            <select data-testid=format!("lattice-axis-{k}") on:change=move |ev| set_axis(k, event_target_value(&ev))>
                {Coord::ALL.map(|c| view! { <option value=c.name() selected=move || axes.get()[k] == c>{c.name()}</option> })}
            </select>
            " from "
            <input class="num" type="number" step="any" prop:value=move || fmt_num(range.get()[k][0]) on:change=move |ev| set_range(k, 0, event_target_value(&ev)) />
            " to "
            <input class="num" type="number" step="any" prop:value=move || fmt_num(range.get()[k][1]) on:change=move |ev| set_range(k, 1, event_target_value(&ev)) />
        }
    };
    let running = move || progress.get().is_some();
    view! {
        <div class="slice-controls">
            <label>
                "Other coordinates from pose "
                <select data-testid="lattice-pose" on:change=move |ev| pose.set(event_target_value(&ev))>
                    {move || scenario().map(|s| s.poses.iter().map(|(n, _)| {
                        let (value, key, text) = (n.clone(), n.clone(), n.clone());
                        view! { <option value=value selected=move || pose.get() == key>{text}</option> }
                    }).collect_view())}
                </select>
            </label>
            <label>"across " {axis_select(0)}</label>
            <label>"up " {axis_select(1)}</label>
            <label>
                "values per axis "
                <input class="num" type="number" min="2" step="1" data-testid="lattice-steps" prop:value=move || steps.get().to_string()
                    on:change=move |ev| {
                        if let Ok(v) = event_target_value(&ev).trim().parse::<usize>() {
                            steps.set(v)
                        }
                    } />
            </label>
            <button data-testid="lattice-build" on:click=start disabled=running>"Build lattice"</button>
            <button data-testid="lattice-cancel" on:click=cancel disabled=move || !running()>"Cancel"</button>
            <progress data-testid="lattice-progress" max="1" prop:value=move || progress.get().map_or(0.0, |(d, t)| d as f64 / t.max(1) as f64) aria-label="lattice progress"></progress>
        </div>
        {move || report.get().map(|r| match r.0.as_ref() {
            Err(e) => view! { <p class="error">{format!("Lattice: {e}")}</p> }.into_any(),
            Ok(r) => view! { <LatticeView report=r.clone() overlay /> }.into_any(),
        })}
    }
}

fn now() -> f64 {
    web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now())
}

/// Builds the lattice of `generation` for one frame's slice, then schedules the next frame.
fn pump(build: Rc<RefCell<Option<Build>>>, generation: u32, report: RwSignal<Option<Shared<Result<LatticeReport, String>>>>, progress: RwSignal<Option<(usize, usize)>>) {
    request_animation_frame(move || {
        let mut slot = build.borrow_mut();
        let Some(b) = slot.as_mut().filter(|b| b.generation == generation) else { return };
        let started = now();
        let mut p = b.lattice.step(1);
        while !p.done && now() - started < SLICE_MS {
            p = b.lattice.step(1);
        }
        if p.done {
            let r = b.lattice.report().ok_or_else(|| "the lattice ended without a report".to_string());
            *slot = None;
            drop(slot);
            progress.set(None);
            report.set(Some(Shared::new(r)));
        } else {
            drop(slot);
            progress.set(Some((p.rays_done, p.rays_total)));
            pump(build, generation, report, progress);
        }
    });
}

/// The rays, the axes and the overlay.
#[component]
fn LatticeView(report: LatticeReport, overlay: Signal<Overlay>) -> impl IntoView {
    let axes = [Coord::parse(report.axes[0]).unwrap_or(Coord::X), Coord::parse(report.axes[1]).unwrap_or(Coord::Y)];
    let range = [report.ranges[0], report.ranges[1]];
    let x = Scale::new(range[0][0], range[0][1], LEFT, W - RIGHT);
    let y = Scale::new(range[1][0], range[1][1], H - BOTTOM, TOP);
    let title = format!(
        "Ray lattice over {} × {} ({} rays, {} of {} grid points feasible, {} component(s))",
        report.axes[0], report.axes[1], report.rays.len(), report.feasible_points, report.grid_points, report.components
    );
    let lines = stretches(&report);
    let to_px = move |p: Option<(f64, f64)>| p.map(|(a, b)| (x.at(a), y.at(b)));
    let markers = move |pose: Option<cablenav::model::Pose>| pose.map_or(vec![], |p| slice_copies(&p, axes, range).into_iter().map(|q| (x.at(q.0), y.at(q.1))).collect());
    view! {
        <Chart id="lattice" title width=W height=H>
            <rect x=LEFT y=TOP width=W - LEFT - RIGHT height=H - TOP - BOTTOM fill="#ffffff" stroke="#5b6670" />
            {lines.into_iter().map(|s| view! {
                <line data-testid="lattice-ray" data-component=s.component.map_or("none".to_string(), |c| c.to_string())
                    x1=x.at(s.from.0) y1=y.at(s.from.1) x2=x.at(s.to.0) y2=y.at(s.to.1)
                    stroke=s.colour stroke-width=if s.component.is_some() { "2.5" } else { "1.2" } />
            }).collect_view()}
            {ticks(range[0][0], range[0][1], 6).into_iter().map(|v| view! {
                <text x=x.at(v) y=H - BOTTOM + 16.0 font-size="11" text-anchor="middle" fill="#5b6670">{fmt_num(v)}</text>
            }).collect_view()}
            {ticks(range[1][0], range[1][1], 6).into_iter().map(|v| view! {
                <text x=LEFT - 5.0 y=y.at(v) + 4.0 font-size="11" text-anchor="end" fill="#5b6670">{fmt_num(v)}</text>
            }).collect_view()}
            <text x=(LEFT + W - RIGHT) / 2.0 y=H - 12.0 font-size="12" text-anchor="middle" fill="#1d2329">{report.axes[0]}</text>
            <text x=14 y=(TOP + H - BOTTOM) / 2.0 font-size="12" text-anchor="middle" fill="#1d2329" transform=format!("rotate(-90 14 {})", (TOP + H - BOTTOM) / 2.0)>{report.axes[1]}</text>
            {move || {
                let o = overlay.get();
                view! {
                    {o.pieces.iter().map(|piece| {
                        let d = polyline(&path_points(&piece.poses, axes, range).into_iter().map(to_px).collect::<Vec<_>>());
                        view! { <path data-testid="lattice-path" d=d fill="none" stroke=css(piece.colour) stroke-width="2" stroke-dasharray="5 3" /> }
                    }).collect_view()}
                    {markers(o.start).into_iter().map(|(cx, cy)| view! { <circle cx=cx cy=cy r="6" fill="#ffffff" stroke="#1d2329" stroke-width="2"><title>"start"</title></circle> }).collect_view()}
                    {markers(o.goal).into_iter().map(|(cx, cy)| view! { <rect x=cx - 6.0 y=cy - 6.0 width="12" height="12" fill="#1d2329"><title>"goal"</title></rect> }).collect_view()}
                }
            }}
        </Chart>
        <p class="legend">
            "Rays: " <span class="swatch" style=format!("background: {INFEASIBLE}")></span> "infeasible or uncertain; feasible pieces coloured by connected component ("
            <span class="swatch" style=format!("background: {}", COMPONENTS[0])></span> "first, "
            <span class="swatch" style=format!("background: {}", COMPONENTS[1])></span> "second, …) · dashed: the planned path and the A* polyline"
        </p>
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::{find, PRESETS};

    #[test]
    fn rays_become_coloured_stretches_covering_their_range() {
        let s = crate::logic::parse_scenario(PRESETS[find("cdpr7-box").unwrap()].json).unwrap();
        let spec = LatticeSpec::new(vec![Coord::X, Coord::Z], vec![[0.2, 3.8], [0.3, 3.7]], vec![7], s.pose("fig310").unwrap().coords()).unwrap();
        let r = Lattice::build(&s, spec).report().unwrap();
        let st = stretches(&r);
        // the x-ray at z = 0.8667: red up to x ≈ 2.0016, then the first component's green
        let z = 0.3 + 3.4 / 6.0;
        let on_ray: Vec<&Stretch> = st.iter().filter(|s| s.from.0 != s.to.0 && (s.from.1 - z).abs() < 1e-12).collect();
        assert_eq!(on_ray.len(), 2, "{on_ray:?}");
        assert_eq!(on_ray[0].colour, INFEASIBLE);
        assert!((on_ray[0].to.0 - 2.0016).abs() < 1e-3);
        assert_eq!((on_ray[1].colour, on_ray[1].to.0), (COMPONENTS[0], 3.8));
        // every ray is covered end to end
        let total: f64 = st.iter().map(|s| (s.to.0 - s.from.0).abs() + (s.to.1 - s.from.1).abs()).sum();
        assert!((total - (7.0 * 3.6 + 7.0 * 3.4)).abs() < 1e-9, "{total}");
    }
}
