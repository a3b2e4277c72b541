//! The ray lattice as a cross-section (thesis Figs. 3.9–3.10, 4.1–4.3): over two chosen
//! coordinates (the others from a chosen pose) the core's [`Lattice`] is built ray by ray from
//! animation frames, with progress and Cancel; each ray is drawn red where infeasible and, where
//! feasible, in its piece's component colour, with the start, the goal, the planned path and the
//! lattice planner's A* polyline over it.

use super::section::{scales, CrossSection, Overlay, PathLook, SectionControls, SectionFrame};
use crate::logic::fmt_exact;
use crate::palette::{component_colour, COMPONENTS, INFEASIBLE};
use crate::rays::ray_pieces;
use crate::state::Shared;
use crate::worker::host::{self, row_blocks, FanOut};
use crate::worker::jobs::{join_lattice, lattice_spec};
use crate::worker::protocol::{Job, LatticeResult, RaySections, Reply};
use cablenav::model::Coord;
use leptos::prelude::*;

/// A lattice as the page holds it: the worker's result, or why there is none.
pub type LatticeState = Option<Shared<Result<LatticeResult, String>>>;

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

/// Every ray of a 2-D lattice as stretches over its two axes: the feasible pieces in their
/// component's colour and the gaps between them (infeasible or uncertain) in red.
pub fn stretches(r: &LatticeResult) -> Vec<Stretch> {
    let (Some(&a), Some(&b)) = (r.axis_index.first(), r.axis_index.get(1)) else { return vec![] };
    ray_pieces(r)
        .into_iter()
        .map(|p| {
            let at = |v: f64| {
                let mut c = p.at.clone();
                c[p.vary] = v;
                (c[a], c[b])
            };
            Stretch { from: at(p.from), to: at(p.to), colour: component_colour(p.component), component: p.component }
        })
        .collect()
}

/// The cross-section's controls and plot. The lattice's rays are computed by several Web
/// Workers at once (a block of rays each, [`row_blocks`]), then joined here into the core's graph
/// and components ([`join_lattice`], as the slice map joins its rows), with progress and Cancel
/// (which terminates the workers); the result is kept in `lattice`, which the 3-D view draws too.
#[component]
pub fn LatticePanel(parsed: Memo<crate::state::Parsed>, source: RwSignal<String>, lattice: RwSignal<LatticeState>, overlay: Signal<Overlay>) -> impl IntoView {
    let scenario = Signal::derive(move || parsed.get().0.as_ref().as_ref().ok().cloned());
    let section = CrossSection::new();
    let steps = RwSignal::new(7usize);
    let progress = RwSignal::new(None::<(f64, String)>);
    let run = FanOut::new();
    let stop = move || {
        progress.set(None);
        run.stop()
    };
    // a new scenario resets the choices, stops a build and drops the lattice
    Effect::new(move |_| {
        if let Some(s) = scenario.get() {
            section.reset(&s);
            stop();
            lattice.set(None);
        }
    });
    let start = move |_| {
        let (Some(s), Some(json)) = (scenario.get_untracked(), source.try_get_untracked()) else { return };
        let this = stop();
        let (pose, a, r, n) = (section.pose.get_untracked(), section.axes.get_untracked(), section.range.get_untracked(), steps.get_untracked());
        let axes: Vec<String> = a.iter().map(|&c| s.coord_name(c)).collect();
        // the request's checks first (the core's errors), before any worker starts
        let spec = match lattice_spec(&s, &pose, &axes, r.to_vec(), n) {
            Ok(spec) => spec,
            Err(e) => return lattice.set(Some(Shared::new(Err(e)))),
        };
        let blocks = row_blocks(spec.ray_count() as usize, host::parallelism());
        let workers = blocks.len();
        let jobs: Vec<Job> = blocks
            .iter()
            .map(|rays| Job::LatticeRays { scenario: json.clone(), pose: pose.clone(), axes: axes.clone(), ranges: r.to_vec(), steps: n, rays: *rays })
            .collect();
        let part = |reply: Reply| match reply {
            Reply::Progress { .. } => None,
            Reply::LatticeRays { sections, .. } => Some(Ok(sections)),
            Reply::Failed { error } => Some(Err(error)),
            _ => Some(Err("the worker answered a lattice job with another job's reply".to_string())),
        };
        let on_progress = move |f: f64, parts: usize| {
            if run.is_current(this) {
                progress.set(Some((f.min(0.99), format!("{:.0} % of the rays, {parts} of {workers} blocks done ({workers} workers)", f * 100.0))));
            }
        };
        let on_done = move |parts: Result<Vec<Vec<RaySections>>, String>| {
            run.finish(this, || {
                let result = parts.and_then(|p| join_lattice(&s, spec.clone(), &p.concat()));
                lattice.set(Some(Shared::new(result)));
                progress.set(None);
            })
        };
        match host::start_all(&jobs, part, on_progress, on_done) {
            Ok(started) => {
                run.hold(started);
                lattice.set(None);
                progress.set(Some((0.0, format!("starting {workers} worker(s)…"))));
            }
            Err(e) => lattice.set(Some(Shared::new(Err(e)))),
        }
    };
    let busy = move || progress.get().is_some();
    view! {
        <SectionControls section scenario prefix="lattice">
            <label>
                "values per axis "
                <input class="num" type="number" min="2" step="1" data-testid="lattice-steps" prop:value=move || steps.get().to_string()
                    on:change=move |ev| {
                        if let Ok(v) = event_target_value(&ev).trim().parse::<usize>() {
                            steps.set(v)
                        }
                    } />
            </label>
            <button data-testid="lattice-build" on:click=start disabled=busy>"Build lattice"</button>
            <button data-testid="lattice-cancel" on:click=move |_| { stop(); } disabled=move || !busy()>"Cancel"</button>
            <progress data-testid="lattice-progress" max="1" prop:value=move || progress.get().map_or(0.0, |p| p.0) aria-label="lattice progress"></progress>
            <span class="readout" data-testid="lattice-state" data-state=move || if busy() { "running" } else { "idle" } aria-live="polite">
                {move || progress.get().map(|p| p.1)}
            </span>
        </SectionControls>
        {move || lattice.get().map(|r| match r.0.as_ref() {
            Err(e) => view! { <p class="error" data-testid="lattice-error">{format!("Lattice: {e}")}</p> }.into_any(),
            Ok(r) => view! { <LatticeView report=r.clone() axes=section.axes.get_untracked() overlay /> }.into_any(),
        })}
    }
}

/// The rays in the cross-section's frame, with the overlay.
#[component]
fn LatticeView(report: LatticeResult, axes: [Coord; 2], overlay: Signal<Overlay>) -> impl IntoView {
    let range = [report.ranges[0], report.ranges[1]];
    let (x, y) = scales(range);
    let [grid, slivers, pointwise, missed] = report.split;
    let title = format!(
        "Ray lattice over {} × {} ({} rays, {} of {} grid points feasible, {} component(s): {grid} holding grid points, {slivers} slivers between them; point-wise {pointwise}, {missed} separation(s) it misses)",
        report.axes[0], report.axes[1], report.rays.len(), report.feasible_points, report.grid_points, report.components
    );
    let lines = stretches(&report);
    let names = [report.axes[0].clone(), report.axes[1].clone()];
    view! {
        <SectionFrame id="lattice" title range axes names background="#ffffff" look=PathLook::Dashed overlay>
            {lines.into_iter().map(|s| view! {
                <line data-testid="lattice-ray" data-component=s.component.map_or("none".to_string(), |c| c.to_string())
                    data-from=format!("{},{}", fmt_exact(s.from.0), fmt_exact(s.from.1)) data-to=format!("{},{}", fmt_exact(s.to.0), fmt_exact(s.to.1))
                    x1=x.at(s.from.0) y1=y.at(s.from.1) x2=x.at(s.to.0) y2=y.at(s.to.1)
                    stroke=s.colour stroke-width=if s.component.is_some() { "2.5" } else { "1.2" } />
            }).collect_view()}
        </SectionFrame>
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
    use cablenav::lattice::{Lattice, LatticeSpec};

    fn box_lattice() -> LatticeResult {
        let s = crate::logic::parse_scenario(PRESETS[find("cdpr7-box").unwrap()].json).unwrap();
        let spec = LatticeSpec::new(vec![Coord::X, Coord::Z], vec![[0.2, 3.8], [0.3, 3.7]], vec![7], s.pose("fig310").unwrap().coords()).unwrap();
        LatticeResult::of(&s, &Lattice::build(&s, spec).report().unwrap())
    }

    /// The thesis' Fig. 3.12: the arm's α–β cross-section at γ = −π/12, θ = π/12 with 10 steps:
    /// two components on the rays (tests/chain.rs has the core's side).
    #[test]
    fn a_multi_link_robots_lattice_is_over_its_joint_coordinates() {
        let s = crate::logic::parse_scenario(PRESETS[find("bmarm-x4-2").unwrap()].json).unwrap();
        let q = std::f64::consts::FRAC_PI_4;
        let spec = crate::worker::jobs::lattice_spec(&s, "fig312", &["alpha".into(), "beta".into()], vec![[-q, q]; 2], 10).unwrap();
        let r = LatticeResult::of(&s, &Lattice::build(&s, spec).report().unwrap());
        assert_eq!((r.axis_index.as_slice(), r.axis_angle.as_slice()), ([0, 1].as_slice(), [true, true].as_slice()));
        assert_eq!((r.components, r.feasible_points), (2, 77));
        let pieces = ray_pieces(&r);
        assert!(pieces.iter().all(|p| p.at.len() == 4 && p.at[2] == s.config("fig312").unwrap()[2]), "γ and θ from fig312");
        let st = stretches(&r);
        assert!(st.iter().all(|x| [x.from.0, x.to.0, x.from.1, x.to.1].iter().all(|v| v.abs() <= q + 1e-12)));
        // in 3-D: the last link's poses along each piece
        let drawn = crate::view3d::scene::lattice_polylines(&s, &r, true);
        assert_eq!(drawn.len(), pieces.len());
    }

    #[test]
    fn ray_pieces_hold_every_coordinate() {
        let r = box_lattice();
        let pieces = ray_pieces(&r);
        assert!(pieces.iter().all(|p| p.at[1] == 2.0 && p.at[3..] == [0.0; 3]), "y = 2 and the orientation from the pose");
        assert_eq!(pieces.len(), stretches(&r).len());
    }

    #[test]
    fn rays_become_coloured_stretches_covering_their_range() {
        let r = box_lattice();
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
