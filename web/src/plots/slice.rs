//! The slice map: the core's classified grid over two chosen coordinates (the others fixed from
//! a chosen pose) as an image, with the start, the goal and the path drawn over it. The grid is
//! classified by several Web Workers at once, each a block of rows ([`row_blocks`]).

use super::section::{CrossSection, Overlay, PathLook, SectionControls, SectionFrame, AREA};
use crate::state::Shared;
use crate::worker::host::{self, row_blocks, FanOut};
use crate::worker::protocol::{Job, Reply};
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
        let jobs: Vec<Job> = blocks
            .iter()
            .map(|rows| Job::Slice { scenario: json.clone(), pose: pose_name.clone(), axes: [a[0].name().to_string(), a[1].name().to_string()], res: n, range: r, rows: *rows })
            .collect();
        let part = |reply: Reply| match reply {
            Reply::Progress { .. } => None,
            Reply::Sliced { classes, .. } => Some(Ok(classes)),
            Reply::Failed { error } => Some(Err(error)),
            _ => Some(Err("the worker answered a slice job with another job's reply".to_string())),
        };
        let workers = blocks.len();
        let on_progress = move |_: f64, parts: usize| {
            if run.is_current(this) {
                progress.set(Some((parts, workers)));
            }
        };
        let on_done = move |parts: Result<Vec<Vec<Class>>, String>| {
            run.finish(this, || {
                let result = parts.and_then(|p| cablenav::verify::slice::slice_from_classes(&s, &pose_name, a, n, r, p.concat()).map_err(|e| e.to_string()));
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
    }
}

/// The map image in the cross-section's frame, with the overlay.
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
    view! {
        <SectionFrame id="slice" title range=map.range axes names=map.axes.clone() background="none" look=PathLook::Cased overlay>
            <image href=href x=x y=y width=width height=height preserveAspectRatio="none" style="image-rendering: pixelated" />
        </SectionFrame>
        <p class="legend">
            "Cells: " <span class="swatch" style="background: rgb(46,160,67)"></span> "feasible"
            <span class="swatch" style="background: rgb(59,111,216)"></span> "tension out of bounds"
            <span class="swatch" style="background: rgb(208,59,59)"></span> "length out of bounds"
            <span class="swatch" style="background: rgb(0,0,0)"></span> "singular"
            <span class="swatch" style="background: rgb(230,145,30)"></span> "interference"
            " · ○ start · ■ goal (on a (φ, θ) map each orientation shows twice, as (φ, θ) and (φ + π, −θ): both are marked)"
        </p>
    }
}

