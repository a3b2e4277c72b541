//! The page and its top bar. State lives in signals (types in [`crate::state`]); every
//! computation is a call into [`crate::logic`] (and through it, the core).

use leptos::prelude::*;

use crate::logic;
use crate::presets::PRESETS;
use crate::state::{PageState, Parsed, Shared, Undo, Verified};
use crate::workbench::Workbench;

/// The whole page: a top bar (what the page shows, the scenario and trajectory pickers, undo,
/// redo and reset), then the workbench: the 3-D view and the strip first, the editor in a side
/// panel, the results in tabs under the view. Embed mode keeps the view and the strip.
#[component]
pub fn App() -> impl IntoView {
    // Where the page starts: a shared link, the autosave, or the first preset (crate::persist).
    let boot = crate::persist::boot();
    let embed = boot.embed;
    let preset = RwSignal::new(boot.preset);
    // The scenario JSON being analysed: a preset's text, or the user's edit of it.
    let source = RwSignal::new(boot.source);
    let trajectory = RwSignal::new(0usize);
    // Where `source` came from: a preset's id, or "edited" (shown as `data-origin` for tests).
    let origin = RwSignal::new(boot.origin);
    // The open results tab and the planning choices, kept in the address with the scenario.
    let settings = RwSignal::new(boot.settings);
    // The path the planner found for the current scenario, if any.
    let planned = RwSignal::new(None);
    let history = Undo::new(source, origin, preset);
    provide_context(crate::state::Quiet(history.batching.into()));
    crate::persist::keep(source, origin, preset, settings, embed);

    let parsed: Memo<Parsed> = Memo::new(move |_| Shared::new(logic::parse_scenario(&source.get())));
    // during a drag the trajectory is verified in a worker (crate::live) and its reports shown as
    // they come; at the drag's end (and for any other edit) here
    let live = crate::live::Live::new(source, trajectory, history.batching);
    let verified: Memo<Verified> = Memo::new(move |prev: Option<&Verified>| {
        if history.batching.get() {
            if let Some(v) = live.report.get().or_else(|| prev.cloned()) {
                return v;
            }
        }
        let parsed = parsed.get();
        Shared::new(match parsed.0.as_ref() {
            Ok(s) => logic::trajectory_index(s, trajectory.get()).map(|i| logic::verify(s, i)),
            _ => None,
        })
    });

    let pick_preset = move |i: usize| {
        preset.set(i);
        trajectory.set(0);
        source.set(PRESETS[i].json.to_string());
        origin.set(PRESETS[i].id);
    };
    let apply_edit = move |text: String| {
        trajectory.set(0);
        source.set(text);
        origin.set("edited");
    };
    if !embed {
        undo_keys(history);
    }

    let note = boot.note.map(|n| view! { <p class="error" role="alert">{n}</p> });
    let page = PageState { parsed, verified, live_ms: live.ms, trajectory, planned, source, origin, history, settings };
    view! {
        <header class="topbar" class:embed=embed>
            <div class="title">
                <h1>"cablenav"</h1>
                <p class="explain" data-testid="explain">
                    "The cable robot in 3-D and, under it, its trajectory's exact verdict along t from 0 to 1: "
                    <span class="key feasible">"green"</span>" where every cable condition is certified to hold, "
                    <span class="key infeasible">"red"</span>" where one fails, "
                    <span class="key uncertain">"grey"</span>" where it cannot be certified; ticks mark the boundaries."
                </p>
            </div>
        </header>
        <main class="layout" class:embed=embed data-embed=embed.to_string()>
            <nav class="controls" aria-label="scenario">
                {(!embed).then(|| view! { <PresetPicker preset on_pick=pick_preset /> })}
                <TrajectoryPicker parsed trajectory />
                {(!embed).then(|| view! { <HistoryButtons history preset on_pick=pick_preset /> })}
                {note}
            </nav>
            <Workbench page embed />
            {if embed {
                view! { <crate::editor::share::OpenFull source origin /> }.into_any()
            } else {
                view! {
                    <aside class="side" data-testid="side-panel" aria-label="scenario editor, sharing and help">
                        <crate::editor::ScenarioEditor source origin />
                        <Editor source on_apply=apply_edit />
                        <crate::editor::share::SharePanel source origin settings trajectory />
                        <crate::help::Help />
                    </aside>
                }
                .into_any()
            }}
        </main>
    }
}

/// Ctrl+Z / Ctrl+Shift+Z (and Ctrl+Y, ⌘ on macOS) anywhere on the page undo and redo, except in
/// a text field, where the browser's own undo of the typing applies (and edits the scenario).
fn undo_keys(history: Undo) {
    let handle = window_event_listener(leptos::ev::keydown, move |ev: web_sys::KeyboardEvent| {
        if !(ev.ctrl_key() || ev.meta_key()) || ev.alt_key() {
            return;
        }
        let key = ev.key().to_lowercase();
        let typing = ev
            .target()
            .and_then(|t| wasm_bindgen::JsCast::dyn_into::<web_sys::Element>(t).ok())
            .is_some_and(|e| {
                let tag = e.tag_name().to_lowercase();
                tag == "textarea" || (tag == "input" && e.get_attribute("type").is_none_or(|t| t == "text" || t == "number"))
            });
        if typing || !(key == "z" || key == "y") {
            return;
        }
        ev.prevent_default();
        if key == "y" || ev.shift_key() {
            history.redo()
        } else {
            history.undo()
        }
    });
    on_cleanup(move || handle.remove());
}

/// Undo, Redo and "Reset to preset".
#[component]
fn HistoryButtons(history: Undo, preset: RwSignal<usize>, on_pick: impl Fn(usize) + Copy + 'static) -> impl IntoView {
    let reset_label = move || format!("Reset to preset “{}”", crate::presets::label(PRESETS[preset.get()].id));
    view! {
        <span class="history">
            <button data-testid="undo" title="Undo (Ctrl+Z)" disabled=move || history.depth.get().0 == 0 on:click=move |_| history.undo()>"↶ Undo"</button>
            <button data-testid="redo" title="Redo (Ctrl+Shift+Z)" disabled=move || history.depth.get().1 == 0 on:click=move |_| history.redo()>"↷ Redo"</button>
            <button
                data-testid="reset-preset"
                title=reset_label
                aria-label=reset_label
                disabled=move || history.source.with(|s| s == PRESETS[preset.get()].json)
                on:click=move |_| on_pick(preset.get_untracked())
            >
                "Reset"
            </button>
        </span>
    }
}

/// The scenario preset `<select>`.
#[component]
fn PresetPicker(preset: RwSignal<usize>, on_pick: impl Fn(usize) + 'static) -> impl IntoView {
    view! {
        <label>
            "Scenario "
            <select
                data-testid="preset"
                prop:value=move || PRESETS[preset.get()].id
                on:change=move |ev| {
                    if let Some(i) = crate::presets::find(&event_target_value(&ev)) {
                        on_pick(i)
                    }
                }
            >
                {PRESETS
                    .iter()
                    .map(|p| view! { <option value=p.id selected=move || PRESETS[preset.get()].id == p.id>
                            {crate::presets::label(p.id)}
                        </option> })
                    .collect_view()}
            </select>
        </label>
    }
}

/// The trajectory `<select>` over the parsed scenario's trajectories.
#[component]
fn TrajectoryPicker(parsed: Memo<Parsed>, trajectory: RwSignal<usize>) -> impl IntoView {
    let names = move || match parsed.get().0.as_ref() {
        Ok(s) => logic::trajectory_names(s),
        Err(_) => Vec::new(),
    };
    view! {
        <label>
            "Trajectory "
            <select
                data-testid="trajectory"
                prop:value=move || trajectory.get().to_string()
                on:change=move |ev| {
                    if let Ok(i) = event_target_value(&ev).parse::<usize>() {
                        trajectory.set(i)
                    }
                }
            >
                {move || {
                    names()
                        .into_iter()
                        .enumerate()
                        .map(|(i, name)| {
                            view! {
                                <option value=i.to_string() selected=move || trajectory.get() == i>
                                    {name}
                                </option>
                            }
                        })
                        .collect_view()
                }}
            </select>
        </label>
    }
}

/// The scenario JSON, editable; "Verify" analyses the edit.
#[component]
fn Editor(source: RwSignal<String>, on_apply: impl Fn(String) + 'static) -> impl IntoView {
    let draft = RwSignal::new(String::new());
    // Follow the analysed source (a new preset replaces the draft).
    Effect::new(move |_| draft.set(source.get()));
    view! {
        <details class="editor">
            <summary>"Scenario JSON (editable)"</summary>
            <textarea
                data-testid="source"
                spellcheck="false"
                prop:value=move || draft.get()
                on:input=move |ev| draft.set(event_target_value(&ev))
            ></textarea>
            <button data-testid="apply" on:click=move |_| on_apply(draft.get_untracked())>
                "Verify this JSON"
            </button>
        </details>
    }
}
