//! The editor's input widgets. Each keeps what the user typed: text that is not a value stays
//! in the field with a message (and is not written); a value is written, and the core's error
//! for that field, if any, is shown beside it.

use leptos::prelude::*;
use serde_json::Value;

use super::Ed;
use crate::edit_logic::{self as el, Path};

/// The message under a field: the local parse problem first, else the core's error.
#[component]
pub fn FieldMessage(local: RwSignal<Option<String>>, core: Signal<Option<String>>) -> impl IntoView {
    move || {
        local.get().or_else(|| core.get()).map(|m| {
            view! { <span class="msg" data-testid="field-error" role="alert">{m}</span> }
        })
    }
}

/// A number input over any value: shows `value`, calls `on_value` with each number typed (or
/// `None` for an emptied field, when `optional`).
#[component]
pub fn NumInput(
    /// The value shown (tracked).
    #[prop(into)]
    value: Signal<Option<f64>>,
    /// Called with each valid entry.
    on_value: Callback<Option<f64>>,
    /// What the number is.
    #[prop(into)]
    label: String,
    /// Its unit, shown after the field ("m", "N", "rad", "°").
    #[prop(optional)]
    unit: &'static str,
    /// The core's name of the field (`data-field`), for tests and error matching.
    #[prop(into)]
    field: Signal<String>,
    /// The core's error for this field.
    #[prop(into)]
    error: Signal<Option<String>>,
    /// Whether an empty field is allowed (the value is then absent).
    #[prop(optional)]
    optional: bool,
    /// Label only for assistive technology (in tables).
    #[prop(optional)]
    compact: bool,
    /// Whether only numbers > 0 are accepted (others stay in the field with a message).
    #[prop(optional)]
    positive: bool,
) -> impl IntoView {
    let text = RwSignal::new(value.get_untracked().map(el::fmt_field).unwrap_or_default());
    let local = RwSignal::new(None::<String>);
    // Follow the value when it changes elsewhere, unless the text already says it.
    Effect::new(move |_| {
        let v = value.get();
        if el::parse_number(&text.get_untracked()).ok().flatten() != v {
            text.set(v.map(el::fmt_field).unwrap_or_default());
            local.set(None);
        }
    });
    let on_input = move |ev| {
        let typed = event_target_value(&ev);
        text.set(typed.clone());
        match el::parse_number(&typed) {
            Ok(Some(x)) if positive && x <= 0.0 => local.set(Some(format!("must be positive, got {x}"))),
            Ok(Some(x)) => {
                local.set(None);
                on_value.run(Some(x));
            }
            Ok(None) if optional => {
                local.set(None);
                on_value.run(None);
            }
            Ok(None) => local.set(Some("enter a number".into())),
            Err(e) => local.set(Some(e)),
        }
    };
    let invalid = move || local.with(Option::is_some) || error.with(Option::is_some);
    let title = format!("{label}{}", if unit.is_empty() { String::new() } else { format!(" ({unit})") });
    view! {
        <label class="field num" class:compact=compact class:invalid=invalid>
            {(!compact).then(|| view! { <span class="label">{label.clone()}</span> })}
            <input
                type="text"
                inputmode="decimal"
                data-field=move || field.get()
                aria-label=title.clone()
                title=title
                aria-invalid=move || invalid().to_string()
                prop:value=move || text.get()
                on:input=on_input
            />
            {(!unit.is_empty() && !compact).then(|| view! { <span class="unit">{unit}</span> })}
            <FieldMessage local core=error />
        </label>
    }
}

/// A number at `path` of the scenario; a `timed` one is a format-4 field (mass, winch limit,
/// duration): writing it raises the file's format, and only positive numbers are taken. `write`,
/// when given, writes each value (`None`: an emptied field) instead of setting or removing it at
/// `path` (a field of a newer format, say).
#[component]
pub fn NumField(
    ed: Ed,
    path: Path,
    #[prop(into)] label: String,
    #[prop(optional)] unit: &'static str,
    #[prop(optional)] optional: bool,
    #[prop(optional)] compact: bool,
    #[prop(optional)] timed: bool,
    #[prop(optional)] write: Option<fn(&mut serde_json::Value, &Path, Option<f64>)>,
) -> impl IntoView {
    let (p1, p2, p3, p4) = (path.clone(), path.clone(), path.clone(), path);
    let value = Memo::new(move |_| ed.num(&p1));
    let write = write.or(timed.then_some(el::set_timed_number as fn(&mut serde_json::Value, &Path, Option<f64>)));
    let on_value = Callback::new(move |v: Option<f64>| {
        ed.edit(|d| match (write, v) {
            (Some(write), v) => write(d, &p2, v),
            (None, Some(x)) => {
                el::set(d, &p2, el::number(x));
            }
            (None, None) => {
                el::remove(d, &p2);
            }
        })
    });
    view! {
        <NumInput
            value
            on_value
            label
            unit
            optional
            compact
            positive=timed
            field=Signal::derive(move || ed.core_path(&p3))
            error=Signal::derive(move || ed.error_at(&p4, true))
        />
    }
}

/// `[x, y, z]` at `path`, as three numbers; the core's errors about the point as a whole show
/// under it.
#[component]
pub fn Vec3Field(ed: Ed, path: Path, #[prop(into)] label: String, #[prop(optional)] unit: &'static str) -> impl IntoView {
    let whole = path.clone();
    let local = RwSignal::new(None);
    let core = Signal::derive(move || ed.error_at(&whole, false));
    view! {
        <fieldset class="vec3">
            <legend>{format!("{label}{}", if unit.is_empty() { String::new() } else { format!(" ({unit})") })}</legend>
            {["x", "y", "z"]
                .into_iter()
                .enumerate()
                .map(|(i, axis)| {
                    view! {
                        <span class="axis" aria-hidden="true">{axis}</span>
                        <NumField ed path=path.i(i) label=format!("{label} {axis}") unit compact=true />
                    }
                })
                .collect_view()}
            <FieldMessage local core />
        </fieldset>
    }
}

/// A `rows × cols` matrix at `path` (the ellipsoid E, an ellipsoid obstacle's M).
#[component]
pub fn MatrixField(ed: Ed, path: Path, rows: usize, cols: usize, #[prop(into)] label: String) -> impl IntoView {
    let whole = path.clone();
    let local = RwSignal::new(None);
    let core = Signal::derive(move || ed.error_at(&whole, false));
    view! {
        <fieldset class="matrix" style=format!("--cols: {cols}")>
            <legend>{label.clone()}</legend>
            <div class="grid">
                {(0..rows)
                    .flat_map(|r| (0..cols).map(move |c| (r, c)))
                    .map(|(r, c)| {
                        view! { <NumField ed path=path.i(r).i(c) label=format!("{label} [{r}][{c}]") compact=true /> }
                    })
                    .collect_view()}
            </div>
            <FieldMessage local core />
        </fieldset>
    }
}

/// A field whose text is parsed into the JSON value at `path`: the text as typed, the local
/// problem with it, the core's error, and the handler of each keystroke (a value is written,
/// `None` removes the member, an error stays in the field).
struct ParsedText {
    text: RwSignal<String>,
    local: RwSignal<Option<String>>,
    core: Signal<Option<String>>,
}

fn parsed_text<F, P>(ed: Ed, path: Path, format: F, parse: P) -> (ParsedText, impl Fn(leptos::ev::Event) + 'static)
where
    F: Fn(Option<&Value>) -> String + Copy + Send + Sync + 'static,
    P: Fn(&str) -> Result<Option<Value>, String> + Copy + Send + Sync + 'static,
{
    let (p1, p2, p3) = (path.clone(), path.clone(), path);
    let value = Memo::new(move |_| ed.read(|d| format(el::get(d, &p1))).unwrap_or_default());
    let text = RwSignal::new(value.get_untracked());
    let local = RwSignal::new(None::<String>);
    Effect::new(move |_| {
        let v = value.get();
        if parse(&text.get_untracked()).ok().map(|x| format(x.as_ref())) != Some(v.clone()) {
            text.set(v);
            local.set(None);
        }
    });
    let on_input = move |ev| {
        let typed = event_target_value(&ev);
        text.set(typed.clone());
        match parse(&typed) {
            Ok(v) => {
                local.set(None);
                ed.edit(|d| match v {
                    Some(v) => {
                        el::set(d, &p2, v);
                    }
                    None => {
                        el::remove(d, &p2);
                    }
                });
            }
            Err(e) => local.set(Some(e)),
        }
    };
    let core = Signal::derive(move || ed.error_at(&p3, true));
    (ParsedText { text, local, core }, on_input)
}

/// "A number, or one number per cable" at `path` (robot-level bounds); empty removes it.
#[component]
pub fn NumberOrListField(ed: Ed, path: Path, #[prop(into)] label: String, #[prop(optional)] unit: &'static str) -> impl IntoView {
    let field = path.clone();
    let (ParsedText { text, local, core }, on_input) =
        parsed_text(ed, path, |v| v.map(el::fmt_number_or_list).unwrap_or_default(), el::parse_number_or_list);
    let invalid = move || local.with(Option::is_some) || core.with(Option::is_some);
    view! {
        <label class="field list" class:invalid=invalid>
            <span class="label">{label.clone()}</span>
            <input
                type="text"
                data-field=move || ed.core_path(&field)
                aria-label=format!("{label} ({unit}): a number for all cables, or one per cable separated by commas; empty for none")
                placeholder="none"
                aria-invalid=move || invalid().to_string()
                prop:value=move || text.get()
                on:input=on_input
            />
            <span class="unit">{unit}</span>
            <FieldMessage local core />
        </label>
    }
}

/// Rows of numbers at `path`, one per line (mesh vertices and triangles).
#[component]
pub fn RowsField(ed: Ed, path: Path, width: usize, integers: bool, #[prop(into)] label: String) -> impl IntoView {
    let field = path.clone();
    let (ParsedText { text, local, core }, on_input) =
        parsed_text(ed, path, el::fmt_rows, move |t| el::parse_rows(t, width, integers).map(Some));
    let invalid = move || local.with(Option::is_some) || core.with(Option::is_some);
    view! {
        <label class="field rows" class:invalid=invalid>
            <span class="label">{format!("{label} (one per line, {width} numbers each)")}</span>
            <textarea
                data-field=move || ed.core_path(&field)
                spellcheck="false"
                aria-invalid=move || invalid().to_string()
                prop:value=move || text.get()
                on:input=on_input
            ></textarea>
            <FieldMessage local core />
        </label>
    }
}

/// A string at `path` (names); the core's error for it (empty, duplicate) shows beside it.
#[component]
pub fn TextField(ed: Ed, path: Path, #[prop(into)] label: String) -> impl IntoView {
    let (p1, p2, p3, p4) = (path.clone(), path.clone(), path.clone(), path);
    let value = Memo::new(move |_| ed.text(&p1).unwrap_or_default());
    let text = RwSignal::new(value.get_untracked());
    let local = RwSignal::new(None::<String>);
    Effect::new(move |_| {
        let v = value.get();
        if text.get_untracked() != v {
            text.set(v);
        }
    });
    let on_input = move |ev| {
        let typed = event_target_value(&ev);
        text.set(typed.clone());
        ed.edit(|d| {
            el::set(d, &p2, Value::String(typed));
        });
    };
    let core = Signal::derive(move || ed.error_at(&p4, true));
    view! {
        <label class="field text" class:invalid=move || core.with(Option::is_some)>
            <span class="label">{label}</span>
            <input
                type="text"
                data-field=move || ed.core_path(&p3)
                prop:value=move || text.get()
                on:input=on_input
            />
            <FieldMessage local core />
        </label>
    }
}

/// A name that other parts refer to (a pose, a link, a joint coordinate, a configuration):
/// each keystroke renames it through `rename` (which renames the references too); a refused
/// name (empty, taken) stays in the field with the message `rename` gives.
#[component]
pub fn NameField<F>(
    ed: Ed,
    /// The current name (tracked).
    name: Memo<String>,
    /// Renames in the tree; `Err` is the message for the field.
    rename: F,
    #[prop(into)] label: String,
    /// The core's name of the field (`data-field`).
    #[prop(into)]
    field: String,
) -> impl IntoView
where
    F: Fn(&mut Value, &str) -> Result<(), String> + Copy + Send + Sync + 'static,
{
    let text = RwSignal::new(name.get_untracked());
    let local = RwSignal::new(None::<String>);
    Effect::new(move |_| {
        let n = name.get();
        if local.with_untracked(Option::is_none) {
            text.set(n);
        }
    });
    let on_input = move |ev| {
        let typed = event_target_value(&ev);
        text.set(typed.clone());
        let mut result = Ok(());
        ed.edit(|d| result = rename(d, &typed));
        local.set(result.err());
    };
    view! {
        <label class="field text" class:invalid=move || local.with(Option::is_some)>
            <span class="label">{label}</span>
            <input type="text" data-field=field prop:value=move || text.get() on:input=on_input />
            <FieldMessage local core=Signal::derive(|| None::<String>) />
        </label>
    }
}

/// A `<select>` over `options` (value, text) showing `current`, calling `on_pick`.
#[component]
pub fn Choice(
    #[prop(into)] label: String,
    options: Vec<(String, String)>,
    #[prop(into)] current: Signal<String>,
    on_pick: Callback<String>,
    #[prop(optional, into)] testid: String,
) -> impl IntoView {
    view! {
        <label class="field choice">
            <span class="label">{label}</span>
            <select
                data-testid=testid
                prop:value=move || current.get()
                on:change=move |ev| on_pick.run(event_target_value(&ev))
            >
                {options
                    .into_iter()
                    .map(|(v, t)| {
                        let v2 = v.clone();
                        view! { <option value=v selected=move || current.get() == v2>{t}</option> }
                    })
                    .collect_view()}
            </select>
        </label>
    }
}

/// Options from plain names.
pub fn options(names: &[&str]) -> Vec<(String, String)> {
    names.iter().map(|n| (n.to_string(), n.replace('_', " "))).collect()
}
