//! A multi-link robot's configurations (one number per joint coordinate, by name) and its paths
//! through them (scenario format 3). The edits themselves are `edit_logic::links`.

use leptos::prelude::*;
use serde_json::Value;

use super::fields::{FieldMessage, NameField, NumField, TextField};
use super::Ed;
use crate::edit_logic::{self as el, Path};

/// The configurations' part of the editor.
#[component]
pub fn ConfigurationsEditor(ed: Ed) -> impl IntoView {
    let count = ed.count(Path::of(&["configurations"]));
    view! {
        <p class="hint">"Every joint coordinate by name (radians for angles, metres for lengths); a value outside a joint's range is a warning."</p>
        <For each=move || 0..count.get() key=|i| *i let:i>
            <ConfigurationItem ed i />
        </For>
        <button type="button" data-testid="add-configuration" on:click=move |_| ed.edit(|d| { el::add_configuration(d); })>
            "Add a configuration"
        </button>
    }
}

/// One configuration.
#[component]
fn ConfigurationItem(ed: Ed, i: usize) -> impl IntoView {
    let path = Path::of(&["configurations"]).i(i);
    let name = Memo::new(move |_| ed.read(|d| el::configuration_names(d).get(i).cloned()).flatten().unwrap_or_default());
    let coords = Memo::new(move |_| ed.read(el::all_coordinates).unwrap_or_default());
    let error = Signal::derive({
        let path = path.clone();
        move || ed.error_at(&path, false)
    });
    let values = {
        let path = path.clone();
        move || {
            coords
                .get()
                .into_iter()
                .map(|(c, unit)| view! { <NumField ed path=path.k(&c) label=c unit /> })
                .collect_view()
        }
    };
    let remove_path = path.clone();
    view! {
        <fieldset class="configuration" data-testid="configuration" class:invalid=move || error.with(Option::is_some)>
            <legend>{move || format!("Configuration “{}”", name.get())}</legend>
            <NameField ed name rename=move |d: &mut Value, new: &str| el::rename_configuration(d, i, new) label="Name" field=format!("configurations[{i}].name") />
            <div class="values">{values}</div>
            <FieldMessage local=RwSignal::new(None) core=error />
            <button type="button" class="remove" on:click=move |_| ed.edit(|d| { el::remove(d, &remove_path); })>
                {move || format!("Delete configuration “{}”", name.get())}
            </button>
        </fieldset>
    }
}

/// The paths through configurations (a multi-link robot's trajectories).
#[component]
pub fn PathsEditor(ed: Ed) -> impl IntoView {
    let count = ed.count(Path::of(&["trajectories"]));
    view! {
        <p class="hint">"A path runs through its configurations in order, every joint moving at once (docs/multilink.md)."</p>
        <For each=move || 0..count.get() key=|i| *i let:i>
            <PathItem ed i />
        </For>
        <button type="button" data-testid="add-path" on:click=move |_| ed.edit(|d| { el::add_path(d); })>
            "Add a path"
        </button>
    }
}

/// One path: its name and its steps.
#[component]
fn PathItem(ed: Ed, i: usize) -> impl IntoView {
    let path = Path::of(&["trajectories"]).i(i);
    let through = path.k("through");
    let steps = Memo::new({
        let through = through.clone();
        move |_| ed.read(|d| (0..el::len(d, &through)).map(|s| el::get(d, &through.i(s)).and_then(Value::as_str).unwrap_or_default().to_string()).collect::<Vec<_>>()).unwrap_or_default()
    });
    let error = Signal::derive({
        let path = path.clone();
        move || ed.error_at(&path, true)
    });
    let step_list = {
        let through = through.clone();
        move || {
            steps
                .get()
                .into_iter()
                .enumerate()
                .map(|(s, name)| {
                    let at = through.i(s);
                    view! {
                        <li data-testid="path-step">
                            {name.clone()}
                            <button type="button" class="remove small" aria-label=format!("remove step {} ({name})", s + 1)
                                on:click=move |_| ed.edit(|d| { el::remove(d, &at); })>"✕"</button>
                        </li>
                    }
                })
                .collect_view()
        }
    };
    let add = move |ev: leptos::ev::Event| {
        let name = event_target_value(&ev);
        if !name.is_empty() {
            ed.edit(|d| el::add_step(d, i, &name));
        }
    };
    let remove_path = path.clone();
    view! {
        <fieldset class="path" data-testid="path" class:invalid=move || error.with(Option::is_some)>
            <legend>{move || format!("Path “{}”", ed.text(&path.k("name")).unwrap_or_default())}</legend>
            <TextField ed path=Path::of(&["trajectories"]).i(i).k("name") label="Name" />
            <ol class="steps">{step_list}</ol>
            <label class="field choice">
                <span class="label">"Then through"</span>
                <select data-testid=format!("path-{i}-add-step") prop:value="" on:change=add>
                    <option value="">"(add a configuration)"</option>
                    {move || ed.read(el::configuration_names).unwrap_or_default().into_iter().map(|n| {
                        let v = n.clone();
                        view! { <option value=v>{n}</option> }
                    }).collect_view()}
                </select>
            </label>
            <FieldMessage local=RwSignal::new(None) core=error />
            <button type="button" class="remove" on:click=move |_| ed.edit(|d| { el::remove(d, &remove_path); })>"Delete this path"</button>
        </fieldset>
    }
}
