//! The Exports tab: the intervals (CSV, or copied), the report as the CLI prints it, the followed
//! path's poses (CSV, JSON), the scenario with the planned trajectory, and the 3-D view as PNG.

use super::path::PathSignals;
use super::plot_jobs::PLOT_SAMPLES;
use crate::logic::StripModel;
use crate::plots::export;
use crate::state::Verified;
use leptos::prelude::*;

/// The export buttons, over the followed `path`, its `strip` and the page's `verified` report.
#[component]
pub fn Exports(path: PathSignals, strip: Memo<Option<StripModel>>, verified: Memo<Verified>) -> impl IntoView {
    let planned = path.planned;
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
            path.followed(|_, path| {
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

    view! {
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
    }
}
