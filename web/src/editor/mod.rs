//! The scenario editor: a structured copy of the scenario JSON that the widgets edit; every
//! valid edit is written back to the page's `source` (the single source of truth the views
//! read). Text that is not a value (a typo in a number) stays in its field with a message and
//! is not written; a value the core rejects is written, and the core's error is shown at the
//! field it names. One module per part of the editor.

pub mod configs;
pub mod fields;
pub mod knots;
pub mod links;
pub mod obstacles;
pub mod poses;
pub mod robot;
pub mod share;
pub mod timing;
pub mod trajectories;
pub mod wrench;

use cablenav::Scenario;
use leptos::prelude::*;
use serde_json::Value;

use crate::edit_logic::{self as el, Path};

/// The editor's state, shared by its widgets (a copyable bundle of signals).
#[derive(Debug, Clone, Copy)]
pub struct Ed {
    /// The scenario as a JSON tree; `None` while `source` is not JSON.
    pub doc: RwSignal<Option<Value>>,
    /// The page's scenario JSON.
    pub source: RwSignal<String>,
    /// Where `source` came from; edits make it `"edited"`.
    pub origin: RwSignal<&'static str>,
    /// The core's reading of `source`.
    pub checked: Memo<Result<Scenario, cablenav::Error>>,
}

impl Ed {
    /// Editor state over the page's `source` and `origin`; follows `source` when it changes
    /// elsewhere (a preset, the JSON box, an import).
    pub fn new(source: RwSignal<String>, origin: RwSignal<&'static str>) -> Ed {
        let doc = RwSignal::new(serde_json::from_str(&source.get_untracked()).ok());
        // during a drag the form waits for its end (crate::state::Quiet): every field re-reads
        // the tree, too much for every pointer move
        let quiet = crate::state::Quiet::watch();
        Effect::new(move |_| {
            if quiet() {
                return;
            }
            let parsed: Option<Value> = source.with(|s| serde_json::from_str(s).ok());
            if doc.with_untracked(|d| *d != parsed) {
                doc.set(parsed);
            }
        });
        let checked = Memo::new(move |prev: Option<&Result<Scenario, cablenav::Error>>| match prev {
            Some(p) if quiet() => p.clone(),
            _ => source.with(|s| Scenario::from_json(s)),
        });
        Ed { doc, source, origin, checked }
    }

    /// Applies `f` to the tree and writes the result to `source`.
    pub fn edit(&self, f: impl FnOnce(&mut Value)) {
        let mut text = None;
        self.doc.update(|d| {
            if let Some(d) = d {
                f(d);
                text = serde_json::to_string_pretty(d).ok();
            }
        });
        if let Some(text) = text {
            self.source.set(text);
            self.origin.set("edited");
        }
    }

    /// Reads the tree (tracked); `None` while the source is not JSON.
    pub fn read<T>(&self, f: impl FnOnce(&Value) -> T) -> Option<T> {
        self.doc.with(|d| d.as_ref().map(f))
    }

    /// The number at `path` (tracked).
    pub fn num(&self, path: &Path) -> Option<f64> {
        self.read(|d| el::get(d, path).and_then(Value::as_f64)).flatten()
    }

    /// The string at `path` (tracked).
    pub fn text(&self, path: &Path) -> Option<String> {
        self.read(|d| el::get(d, path).and_then(Value::as_str).map(str::to_string)).flatten()
    }

    /// The number of items of the list (or members of the object) at `path`, as a memo that
    /// changes only when the number does.
    pub fn count(&self, path: Path) -> Memo<usize> {
        let ed = *self;
        Memo::new(move |_| ed.read(|d| el::len(d, &path)).unwrap_or(0))
    }

    /// The core's name for `path` (tracked).
    pub fn core_path(&self, path: &Path) -> String {
        self.read(|d| el::core_path(d, path)).unwrap_or_default()
    }

    /// The core's error, when it concerns the widget at `path` (the field itself, or with
    /// `inside` anything within it) (tracked).
    pub fn error_at(&self, path: &Path, inside: bool) -> Option<String> {
        let field = self.core_path(path);
        self.checked.with(|r| match r {
            Err(e) if el::error_belongs(&e.field, &field, inside) => Some(e.reason.clone()),
            _ => None,
        })
    }
}

/// The whole editor: robot, then wrench, obstacles, poses, trajectories (a multi-link robot:
/// links, obstacles, configurations, paths).
#[component]
pub fn ScenarioEditor(source: RwSignal<String>, origin: RwSignal<&'static str>) -> impl IntoView {
    let ed = Ed::new(source, origin);
    let is_json = move || ed.doc.with(Option::is_some);
    let chain = Memo::new(move |_| ed.read(el::is_multi_link).unwrap_or(false));
    view! {
        <section class="scenario-editor" data-testid="scenario-editor" aria-label="scenario editor">
            <h2>"Edit the scenario"</h2>
            <Summary ed />
            <Show
                when=is_json
                fallback=|| view! {
                    <p class="error" role="alert">
                        "The scenario text is not JSON, so the form cannot show it: fix it in the JSON box below."
                    </p>
                }
            >
                <details open>
                    <summary>"Robot: cables and bounds"</summary>
                    <robot::RobotEditor ed />
                </details>
                <Show when=move || chain.get() fallback=move || view! { <PlatformParts ed /> }>
                    <MultiLinkParts ed />
                </Show>
            </Show>
        </section>
    }
}

/// A platform robot's parts: wrench set, obstacles, poses, trajectories.
#[component]
fn PlatformParts(ed: Ed) -> impl IntoView {
    view! {
        <details>
            <summary>"Mass and winches (timed motion)"</summary>
            <timing::TimingEditor ed />
        </details>
        <details>
            <summary>"Wrench set"</summary>
            <wrench::WrenchEditor ed />
        </details>
        <details>
            <summary>"Obstacles"</summary>
            <obstacles::ObstacleEditor ed />
        </details>
        <details>
            <summary>"Poses"</summary>
            <poses::PoseEditor ed />
        </details>
        <details>
            <summary>"Trajectories"</summary>
            <trajectories::TrajectoryEditor ed />
        </details>
    }
}

/// A multi-link robot's parts (format 3): links, a wrench on a link, forces on joints, obstacles, configurations,
/// paths. It has no poses or wrench set (its wrench conditions are joint-space wrench closure,
/// always checked, and static feasibility once a link has a mass, carries a wrench or its joints take
/// forces).
#[component]
fn MultiLinkParts(ed: Ed) -> impl IntoView {
    view! {
        <details open>
            <summary>"Links and joints"</summary>
            <links::LinksEditor ed />
        </details>
        <details>
            <summary>"Wrench on a link"</summary>
            <wrench::LinkWrenchEditor ed />
        </details>
        <details>
            <summary>"Forces on joints"</summary>
            <wrench::JointForcesEditor ed />
        </details>
        <details>
            <summary>"Obstacles"</summary>
            <obstacles::ObstacleEditor ed />
        </details>
        <details>
            <summary>"Configurations"</summary>
            <configs::ConfigurationsEditor ed />
        </details>
        <details>
            <summary>"Paths through configurations"</summary>
            <configs::PathsEditor ed />
        </details>
        <p class="hint" data-testid="multilink-note">
            "A multi-link robot has no poses and no wrench set around a nominal wrench: its wrench conditions are \
             joint-space wrench closure, always checked, and static feasibility once a link has a mass, carries a wrench \
             or its joints take forces; \
             it is posed by configurations (docs/multilink.md)."
        </p>
    }
}

/// One line on top: whether the core accepts the scenario, and its error (which the field it
/// names also shows).
#[component]
fn Summary(ed: Ed) -> impl IntoView {
    move || {
        ed.checked.with(|r| match r {
            Ok(_) => view! { <p class="status ok" data-testid="editor-status">"The scenario is valid."</p> }.into_any(),
            Err(e) => {
                let text = if e.field.is_empty() { e.reason.clone() } else { format!("{}: {}", e.field, e.reason) };
                view! {
                    <p class="status error" data-testid="editor-status" role="alert">
                        {format!("Not valid yet — {text}")}
                    </p>
                }
                .into_any()
            }
        })
    }
}
