//! Sharing: the link to this scenario, the embed snippet, JSON export and import by file, and
//! CASPR model import (bodies + cables XML files, and its trajectories file if chosen too; a
//! cables file with several cable sets offers them, as `cablenav import --cable-set`).

use leptos::prelude::*;
use wasm_bindgen::JsCast;

use crate::persist;

/// The sharing panel. `trajectory` is the picked trajectory's index: a file loaded is shown from
/// its first one.
#[component]
pub fn SharePanel(source: RwSignal<String>, origin: RwSignal<&'static str>, settings: RwSignal<crate::state::Settings>, trajectory: RwSignal<usize>) -> impl IntoView {
    // one link per edit, made once, and during a drag at its end (crate::state::Quiet)
    let quiet = crate::state::Quiet::watch();
    let hash = Memo::new(move |prev: Option<&String>| match prev {
        Some(h) if quiet() => h.clone(),
        _ => settings.with(|s| persist::share_hash(&source.get(), origin.get(), s)),
    });
    let link = Memo::new(move |_| format!("{}{}", persist::page_address(), hash.get()));
    let snippet = Memo::new(move |_| persist::embed_snippet(&persist::page_address(), &hash.get()));
    let message = RwSignal::new(None::<(bool, String)>);
    let load = move |text: String, what: String| {
        // The file's scenario replaces the text, whatever it holds (an invalid one shows the
        // core's error; nothing is dropped), shown from its first trajectory.
        trajectory.set(0);
        source.set(text);
        origin.set("edited");
        message.set(Some((true, what)));
    };
    let export = move |_| {
        let text = source.get_untracked();
        let name = cablenav::Scenario::from_json(&text).map(|s| s.name).unwrap_or_else(|_| "scenario".into());
        if let Err(e) = persist::download(&persist::export_name(&name), &text, "application/json") {
            message.set(Some((false, e)));
        }
    };
    let import_json = move |ev: leptos::ev::Event| {
        let files = input_files(&ev);
        leptos::task::spawn_local(async move {
            match persist::read_files(files).await.into_iter().next() {
                Some((name, Ok(text))) => load(text, format!("Loaded {name}.")),
                Some((_, Err(e))) => message.set(Some((false, e))),
                None => {}
            }
        });
    };
    // the CASPR files last picked, and their cable sets with the one imported: picking another
    // set imports the same files again with it
    let caspr_files = StoredValue::new(Vec::<(String, Result<String, String>)>::new());
    let cable_sets = RwSignal::new((Vec::<String>::new(), String::new()));
    let convert = move |set: Option<String>| {
        let result = caspr_files.with_value(|files| crate::edit_logic::caspr_pair(files, set.as_deref()));
        match result {
            Ok(got) => {
                let extra = if got.notes.is_empty() { String::new() } else { format!(" Notes: {}", got.notes.join("; ")) };
                cable_sets.set((got.sets, got.set));
                load(got.json, format!("Imported the CASPR model “{}”.{extra}", got.name));
            }
            Err(e) => message.set(Some((false, e))),
        }
    };
    let import_caspr = move |ev: leptos::ev::Event| {
        let files = input_files(&ev);
        leptos::task::spawn_local(async move {
            caspr_files.set_value(persist::read_files(files).await);
            cable_sets.set((vec![], String::new()));
            convert(None);
        });
    };
    view! {
        <section class="share" data-testid="share">
            <h2>"Share and save"</h2>
            <p class="hint">
                "Your edits are saved in this browser as you type; the address bar always holds a link to the \
                 current scenario."
            </p>
            <label class="field wide">
                <span class="label">"Link to this scenario"</span>
                <input type="text" readonly data-testid="share-link" prop:value=move || link.get() />
                <button type="button" on:click=move |_| persist::copy_text(&link.get_untracked())>"Copy link"</button>
            </label>
            <label class="field wide">
                <span class="label">"Embed in a course page (view and results only)"</span>
                <textarea readonly data-testid="embed-snippet" rows="2" prop:value=move || snippet.get()></textarea>
                <button type="button" on:click=move |_| persist::copy_text(&snippet.get_untracked())>"Copy snippet"</button>
            </label>
            <div class="files">
                <button type="button" data-testid="export-json" on:click=export>"Export JSON file"</button>
                <label class="file">
                    "Import JSON file "
                    <input type="file" accept=".json,application/json" data-testid="import-json" on:change=import_json />
                </label>
                <label class="file">
                    "Import CASPR model (choose its bodies and cables XML files together, and its trajectories XML for its timed splines) "
                    <input type="file" accept=".xml,text/xml" multiple data-testid="import-caspr" on:change=import_caspr />
                </label>
                {move || {
                    let (sets, used) = cable_sets.get();
                    (sets.len() > 1).then(|| view! {
                        <label>
                            "Cable set "
                            <select data-testid="caspr-cable-set" on:change=move |ev| convert(Some(event_target_value(&ev)))>
                                {sets.into_iter().map(|id| {
                                    let (selected, value) = (id == used, id.clone());
                                    view! { <option value=value selected=selected>{id}</option> }
                                }).collect_view()}
                            </select>
                        </label>
                    })
                }}
            </div>
            {move || message.get().map(|(ok, m)| {
                view! {
                    <p class=if ok { "status ok" } else { "status error" } data-testid="share-message" role="status">{m}</p>
                }
            })}
        </section>
    }
}

/// The files chosen in the input that fired `ev`.
fn input_files(ev: &leptos::ev::Event) -> Option<web_sys::FileList> {
    ev.target()?.dyn_into::<web_sys::HtmlInputElement>().ok()?.files()
}

/// In embed mode: a link that opens the full page (editor included) on the same scenario.
#[component]
pub fn OpenFull(source: RwSignal<String>, origin: RwSignal<&'static str>) -> impl IntoView {
    let href = move || format!("{}{}", persist::page_address(), persist::hash_for(&source.get(), origin.get()));
    view! {
        <p class="open-full">
            <a href=href target="_blank" rel="noopener" data-testid="open-full">"Open in cablenav (edit this scenario) ↗"</a>
        </p>
    }
}
