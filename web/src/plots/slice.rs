//! The slice map: the core's classified grid over two chosen coordinates (the others fixed from
//! a chosen pose) as an image, with the singularity curves (det J = 0), the start, the goal and
//! the path drawn over it. The grid is classified by several Web Workers at once, each a block of
//! rows ([`row_blocks`]), while one more traces the singularity curves.

use super::section::{CrossSection, Overlay, PathLook, SectionControls, SectionFrame, AREA};
use crate::state::Shared;
use crate::worker::host::{self, row_blocks, FanOut};
use crate::worker::protocol::{Job, Reply, SliceSpec};
use cablenav::model::Coord;
use cablenav::verify::slice::{Class, SliceMap};
use leptos::prelude::*;

/// The slice controls and map.
#[component]
pub fn SlicePanel(parsed: Memo<crate::state::Parsed>, source: RwSignal<String>, overlay: Signal<Overlay>) -> impl IntoView {
    let scenario = Signal::derive(move || parsed.get().0.as_ref().as_ref().ok().cloned());
    let section = CrossSection::new();
    let CrossSection { pose, axes, range } = section;
    let res = RwSignal::new(64usize);
    let map = RwSignal::new(None::<Shared<Result<SliceMap, String>>>);
    // a new scenario resets the choices to its defaults and clears the map
    Effect::new(move |_| {
        if let Some(s) = scenario.get() {
            section.reset(&s);
            map.set(None);
        }
    });
    // the map is classified in row blocks by several workers at once (crate::worker), then
    // joined here; a new request or Cancel terminates the running ones
    let run = FanOut::new();
    let progress = RwSignal::new(None::<(usize, usize)>);
    let stop = move || {
        progress.set(None);
        run.stop()
    };
    let compute = move |_| {
        let Some(s) = scenario.get_untracked() else { return };
        let this = stop();
        let (pose_name, a, n, r) = (pose.get_untracked(), axes.get_untracked(), res.get_untracked(), range.get_untracked());
        // the whole map's checks first (same errors as the core's), before any worker starts
        if let Err(e) = cablenav::verify::slice::slice_rows(&s, &pose_name, a, n, r, 0..0) {
            map.set(Some(Shared::new(Err(e.to_string()))));
            return;
        }
        let Some(json) = source.try_get_untracked() else { return };
        let blocks = row_blocks(n, host::parallelism());
        let spec = SliceSpec { scenario: json, pose: pose_name.clone(), axes: [a[0].name().to_string(), a[1].name().to_string()], res: n, range: r };
        let mut jobs: Vec<Job> = blocks.iter().map(|rows| Job::Slice { map: spec.clone(), rows: *rows }).collect();
        jobs.push(Job::Singular { map: spec });
        let part = |reply: Reply| match reply {
            Reply::Progress { .. } => None,
            Reply::Sliced { classes, .. } => Some(Ok(Part::Rows(classes))),
            Reply::Singular { curves } => Some(Ok(Part::Curves(curves))),
            Reply::Failed { error } => Some(Err(error)),
            _ => Some(Err("the worker answered a slice job with another job's reply".to_string())),
        };
        let workers = jobs.len();
        let on_progress = move |_: f64, parts: usize| {
            if run.is_current(this) {
                progress.set(Some((parts, workers)));
            }
        };
        let on_done = move |parts: Result<Vec<Part>, String>| {
            run.finish(this, || {
                let result = parts.and_then(|parts| {
                    let (mut classes, mut curves) = (Vec::new(), Vec::new());
                    for p in parts {
                        match p {
                            Part::Rows(rows) => classes.extend(rows),
                            Part::Curves(c) => curves = c,
                        }
                    }
                    let mut map = cablenav::verify::slice::slice_from_classes(&s, &pose_name, a, n, r, classes).map_err(|e| e.to_string())?;
                    map.singular_curves = curves;
                    Ok(map)
                });
                map.set(Some(Shared::new(result)));
                progress.set(None);
            })
        };
        match host::start_all(&jobs, part, on_progress, on_done) {
            Ok(started) => {
                run.hold(started);
                progress.set(Some((0, workers)));
            }
            Err(e) => map.set(Some(Shared::new(Err(e)))),
        }
    };
    view! {
        <SectionControls section scenario prefix="slice">
            <label>
                "cells per side "
                <select on:change=move |ev| {
                    if let Ok(v) = event_target_value(&ev).parse() {
                        res.set(v)
                    }
                }>
                    {[32usize, 64, 128, 256].map(|v| view! { <option value=v.to_string() selected=move || res.get() == v>{v}</option> })}
                </select>
            </label>
            <button data-testid="slice-compute" on:click=compute>"Compute slice"</button>
            <button data-testid="slice-cancel" disabled=move || progress.get().is_none() on:click=move |_| { stop(); }>"Cancel"</button>
            <span class="readout" data-testid="slice-progress" aria-live="polite">
                {move || progress.get().map(|(done, all)| format!("{done} of {all} row blocks done ({all} workers)"))}
            </span>
        </SectionControls>
        {move || map.get().map(|m| match m.0.as_ref() {
            Err(e) => view! { <p class="error">{format!("Slice: {e}")}</p> }.into_any(),
            Ok(m) => view! { <SliceMapView map=m.clone() axes=axes.get_untracked() overlay /> }.into_any(),
        })}
        <super::atlas_space::AtlasSpace overlay />
    }
}

/// What one worker of a slice map gives: a block of rows' classes, or the singularity curves.
enum Part {
    Rows(Vec<Class>),
    Curves(Vec<Vec<[f64; 2]>>),
}

/// The map image in the cross-section's frame, with the singularity curves and the overlay.
#[component]
fn SliceMapView(map: SliceMap, axes: [Coord; 2], overlay: Signal<Overlay>) -> impl IntoView {
    use base64::Engine as _;
    let href = format!("data:image/png;base64,{}", base64::engine::general_purpose::STANDARD.encode(map.png()));
    let title = format!(
        "Slice over {} × {} ({}×{} cells; {:.1}% feasible, {} component(s)); path projected",
        map.axes[0],
        map.axes[1],
        map.res,
        map.res,
        map.fraction_feasible * 100.0,
        map.components
    );
    let [x, y, width, height] = AREA;
    let (sx, sy) = super::section::scales(map.range);
    let curves: Vec<String> = map.singular_curves.iter().map(|c| super::geom::polyline(&c.iter().map(|p| Some((sx.at(p[0]), sy.at(p[1])))).collect::<Vec<_>>())).collect();
    let singular = !curves.is_empty();
    view! {
        <SectionFrame id="slice" title range=map.range axes names=map.axes.clone() background="none" look=PathLook::Cased overlay>
            <image href=href x=x y=y width=width height=height preserveAspectRatio="none" style="image-rendering: pixelated" />
            {curves.into_iter().map(|d| view! { <path data-testid="slice-singular" d=d fill="none" stroke="#000000" stroke-width="1.4" /> }).collect_view()}
        </SectionFrame>
        <p class="legend">
            "Cells: " <span class="swatch" style="background: rgb(46,160,67)"></span> "feasible"
            <span class="swatch" style="background: rgb(59,111,216)"></span> "tension out of bounds"
            <span class="swatch" style="background: rgb(208,59,59)"></span> "length out of bounds"
            <span class="swatch" style="background: rgb(0,0,0)"></span> "singular"
            <span class="swatch" style="background: rgb(230,145,30)"></span> "interference"
            {singular.then_some(" · black curves: singular structure matrix, det J = 0")}
            " · ○ start · ■ goal (on a (φ, θ) map each orientation shows twice, as (φ, θ) and (φ + π, −θ): both are marked)"
            {move || overlay.with(|o| o.atlas.as_ref().is_some_and(|a| !super::section::chart_polygons(a, axes).is_empty())).then_some(
                " · grey polygons: the atlas planner's charts (paper 1, Fig. 6), darker where expanded, outlined bold along the path"
            )}
        </p>
    }
}

