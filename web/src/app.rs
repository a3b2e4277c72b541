//! The page's components. State lives in signals; every computation is a call into
//! [`crate::logic`] (and through it, the core).

use std::sync::Arc;

use cablenav::report::VerifyReport;
use cablenav::Scenario;
use leptos::prelude::*;

use crate::logic::{self, fmt_num, Section, StripModel};
use crate::plots::strip::Strip;
use crate::presets::PRESETS;
use crate::workbench::Workbench;

/// A value shared by reference inside a memo; two are equal only if they are the same
/// computation, so the core's types need not implement `PartialEq`.
#[derive(Debug)]
pub(crate) struct Shared<T>(pub(crate) Arc<T>);

impl<T> Clone for Shared<T> {
    fn clone(&self) -> Self {
        Shared(Arc::clone(&self.0))
    }
}

impl<T> PartialEq for Shared<T> {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl<T> Shared<T> {
    pub(crate) fn new(value: T) -> Self {
        Shared(Arc::new(value))
    }
}

pub(crate) type Parsed = Shared<Result<Scenario, String>>;
pub(crate) type Verified = Shared<Option<Result<VerifyReport, String>>>;

/// The whole page.
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
    crate::persist::keep(source, origin, preset, embed);
    // The path the planner found for the current scenario, if any.
    let planned = RwSignal::new(None);

    let parsed: Memo<Parsed> = Memo::new(move |_| Shared::new(logic::parse_scenario(&source.get())));
    let verified: Memo<Verified> = Memo::new(move |_| {
        let parsed = parsed.get();
        Shared::new(match parsed.0.as_ref() {
            Ok(s) if !s.trajectories.is_empty() => {
                Some(logic::verify(s, trajectory.get().min(s.trajectories.len() - 1)))
            }
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

    let note = boot.note.map(|n| view! { <p class="error" role="alert">{n}</p> });
    view! {
        <header class:embed=embed>
            <h1>"cablenav"</h1>
            <p class="tagline">"Exact feasible intervals along cable-robot trajectories"</p>
        </header>
        <main class:embed=embed data-embed=embed.to_string()>
            {note}
            <section class="controls">
                {(!embed).then(|| view! { <PresetPicker preset on_pick=pick_preset /> })}
                <TrajectoryPicker parsed trajectory />
            </section>
            <Outcome parsed verified trajectory origin />
            <Workbench parsed verified trajectory planned />
            {if embed {
                view! { <crate::editor::share::OpenFull source origin /> }.into_any()
            } else {
                view! {
                    <crate::editor::ScenarioEditor source origin />
                    <Editor source on_apply=apply_edit />
                    <crate::editor::share::SharePanel source origin />
                    <crate::help::Help />
                }
                .into_any()
            }}
        </main>
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

/// The verification result: errors, the strip, the tables and the notes.
#[component]
fn Outcome(
    parsed: Memo<Parsed>,
    verified: Memo<Verified>,
    trajectory: RwSignal<usize>,
    origin: RwSignal<&'static str>,
) -> impl IntoView {
    move || {
        let parsed = parsed.get();
        let scenario = match parsed.0.as_ref() {
            Err(e) => return view! { <ErrorText prefix="Scenario" message=e.clone() /> }.into_any(),
            Ok(s) => s,
        };
        let verified = verified.get();
        let notes_view = |report: Option<&VerifyReport>| {
            view! { <Notes notes=logic::notes(&scenario.warnings, report) /> }
        };
        match verified.0.as_ref() {
            None => view! {
                <p class="empty">{format!("Scenario “{}” has no trajectory.", scenario.name)}</p>
                {notes_view(None)}
            }
            .into_any(),
            Some(Err(e)) => view! {
                <ErrorText prefix="Verification" message=e.clone() />
                {notes_view(None)}
            }
            .into_any(),
            Some(Ok(report)) => {
                let model = logic::strip(report);
                let index = trajectory.get().min(scenario.trajectories.len().saturating_sub(1));
                view! {
                    <section
                        class="result"
                        data-testid="result"
                        data-origin=origin.get()
                        data-trajectory-index=index
                        data-method=report.method.clone()
                    >
                        <h2>{format!("{} — {}", scenario.name, report.trajectory)}</h2>
                        <Strip model=model.clone() />
                        <Legend />
                        <Tables model />
                        {notes_view(Some(report))}
                    </section>
                }
                .into_any()
            }
        }
    }
}

/// An error as text.
#[component]
fn ErrorText(prefix: &'static str, message: String) -> impl IntoView {
    view! {
        <p class="error" data-testid="error" role="alert">
            <strong>{format!("{prefix} error: ")}</strong>
            {message}
        </p>
    }
}

/// The colour key.
#[component]
fn Legend() -> impl IntoView {
    view! {
        <p class="legend">
            <span class="swatch feasible"></span>
            "feasible "
            <span class="swatch infeasible"></span>
            "infeasible "
            <span class="swatch uncertain"></span>
            "uncertain "
            <span class="tick-key"></span>
            "boundary (hover for the constraint)"
        </p>
    }
}

/// The tables of intervals and boundaries.
#[component]
fn Tables(model: StripModel) -> impl IntoView {
    let tau = |s: &Section| match s.tau {
        Some([a, b]) => (fmt_num(a), fmt_num(b)),
        None => ("—".to_string(), "—".to_string()),
    };
    view! {
        <div class="tables">
            <table data-testid="intervals">
                <caption>"Intervals"</caption>
                <thead>
                    <tr><th>"kind"</th><th>"t from"</th><th>"t to"</th><th>"τ from"</th><th>"τ to"</th></tr>
                </thead>
                <tbody>
                    {model
                        .sections
                        .iter()
                        .map(|s| {
                            let (a, b) = tau(s);
                            view! {
                                <tr class=s.kind.as_str()>
                                    <td>{s.kind.as_str()}</td>
                                    <td>{fmt_num(s.t0)}</td>
                                    <td>{fmt_num(s.t1)}</td>
                                    <td>{a}</td>
                                    <td>{b}</td>
                                </tr>
                            }
                        })
                        .collect_view()}
                </tbody>
            </table>
            <table data-testid="boundaries">
                <caption>"Boundaries"</caption>
                <thead>
                    <tr><th>"t"</th><th>"τ"</th><th>"constraint"</th><th>"enters"</th></tr>
                </thead>
                <tbody>
                    {if model.ticks.is_empty() {
                        view! { <tr><td colspan="4">"none"</td></tr> }.into_any()
                    } else {
                        model
                            .ticks
                            .iter()
                            .map(|t| {
                                view! {
                                    <tr>
                                        <td>{fmt_num(t.t)}</td>
                                        <td>{fmt_num(t.tau)}</td>
                                        <td>{t.constraint.clone()}</td>
                                        <td>{t.enters}</td>
                                    </tr>
                                }
                            })
                            .collect_view()
                            .into_any()
                    }}
                </tbody>
            </table>
        </div>
    }
}

/// The scenario's and the report's warnings.
#[component]
fn Notes(notes: Vec<String>) -> impl IntoView {
    (!notes.is_empty()).then(|| {
        view! {
            <section class="notes" data-testid="warnings">
                <h3>"Warnings"</h3>
                <ul>{notes.into_iter().map(|n| view! { <li>{n}</li> }).collect_view()}</ul>
            </section>
        }
    })
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
