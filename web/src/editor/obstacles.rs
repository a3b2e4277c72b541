//! Obstacles: add, edit and delete every type, with a name and a display colour.

use leptos::prelude::*;
use serde_json::Value;

use super::fields::{options, Choice, FieldMessage, MatrixField, NumField, RowsField, TextField, Vec3Field};
use super::Ed;
use crate::edit_logic::{self as el, Path, OBSTACLE_TYPES};

/// The colour an obstacle without one is drawn in (shown in the colour picker).
pub const DEFAULT_COLOR: &str = "#8a8f98";

/// The obstacles' part of the editor.
#[component]
pub fn ObstacleEditor(ed: Ed) -> impl IntoView {
    let count = ed.count(Path::of(&["obstacles"]));
    let new_kind = RwSignal::new("box".to_string());
    view! {
        <p class="hint">
            "Cables must keep the cable–obstacle clearance from every obstacle. Lengths in metres, angles in radians."
        </p>
        <For each=move || 0..count.get() key=|i| *i let:i>
            <ObstacleItem ed i />
        </For>
        <div class="add-row">
            <Choice
                label="New obstacle"
                options=options(&OBSTACLE_TYPES)
                current=Signal::derive(move || new_kind.get())
                on_pick=Callback::new(move |k: String| new_kind.set(k))
                testid="new-obstacle-type"
            />
            <button
                type="button"
                data-testid="add-obstacle"
                on:click=move |_| ed.edit(|d| el::add_obstacle(d, &new_kind.get_untracked()))
            >
                "Add obstacle"
            </button>
        </div>
    }
}

/// One obstacle: name, colour, type and the fields of its type.
#[component]
fn ObstacleItem(ed: Ed, i: usize) -> impl IntoView {
    let path = Path::of(&["obstacles"]).i(i);
    let kind = Memo::new({
        let path = path.clone();
        move |_| ed.text(&path.k("type")).unwrap_or_default()
    });
    let item_error = Signal::derive({
        let path = path.clone();
        move || ed.error_at(&path, false)
    });
    let fields = {
        let path = path.clone();
        move || {
            let p = path.clone();
            match kind.get().as_str() {
                "box" => view! {
                    <Vec3Field ed path=p.k("center") label="Centre" unit="m" />
                    <Vec3Field ed path=p.k("size") label="Size (full side lengths)" unit="m" />
                }
                .into_any(),
                "sphere" => view! {
                    <Vec3Field ed path=p.k("center") label="Centre" unit="m" />
                    <NumField ed path=p.k("radius") label="Radius" unit="m" />
                }
                .into_any(),
                "cylinder" => view! {
                    <Vec3Field ed path=p.k("from") label="Axis from" unit="m" />
                    <Vec3Field ed path=p.k("to") label="Axis to" unit="m" />
                    <NumField ed path=p.k("radius") label="Radius" unit="m" />
                }
                .into_any(),
                "cone" => view! {
                    <Vec3Field ed path=p.k("apex") label="Apex" unit="m" />
                    <Vec3Field ed path=p.k("axis") label="Axis direction (apex → base)" />
                    <NumField ed path=p.k("half_angle") label="Half-angle" unit="rad" />
                    <NumField ed path=p.k("height") label="Height" unit="m" />
                }
                .into_any(),
                "ellipsoid" => view! {
                    <Vec3Field ed path=p.k("center") label="Centre" unit="m" />
                    <MatrixField ed path=p.k("matrix") rows=3 cols=3 label="M: the solid (x−c)ᵀM(x−c) ≤ 1 (1/m²)" />
                }
                .into_any(),
                "mesh" => view! {
                    <RowsField ed path=p.k("vertices") width=3 integers=false label="Vertices x y z (m)" />
                    <RowsField ed path=p.k("triangles") width=3 integers=true label="Triangles: vertex indices from 0" />
                }
                .into_any(),
                other => view! { <p class="error">{format!("unknown type “{other}”: choose one above")}</p> }.into_any(),
            }
        }
    };
    let color_path = path.k("color");
    let color = Memo::new({
        let p = color_path.clone();
        move |_| ed.text(&p)
    });
    let (cp1, cp2, cp3) = (color_path.clone(), color_path.clone(), color_path);
    view! {
        <fieldset class="obstacle" data-testid="obstacle" class:invalid=move || item_error.with(Option::is_some)>
            <legend>{move || format!("Obstacle {} — {}", i + 1, kind.get())}</legend>
            <TextField ed path=path.k("name") label="Name" />
            <label class="field color">
                <span class="label">"Colour"</span>
                <input
                    type="color"
                    data-field=move || ed.core_path(&cp1)
                    prop:value=move || color.get().unwrap_or_else(|| DEFAULT_COLOR.to_string())
                    on:input={
                        let p = cp2.clone();
                        move |ev| {
                            let c = event_target_value(&ev);
                            ed.edit(|d| { el::set(d, &p, Value::String(c)); });
                        }
                    }
                />
                {move || match color.get() {
                    None => view! { <span class="unit">"(default)"</span> }.into_any(),
                    Some(_) => {
                        let p = cp2.clone();
                        view! {
                            <button
                                type="button"
                                class="small"
                                title="draw it in the default colour"
                                on:click=move |_| ed.edit(|d| { el::remove(d, &p); })
                            >
                                "default"
                            </button>
                        }
                        .into_any()
                    }
                }}
                <FieldMessage local=RwSignal::new(None) core=Signal::derive(move || ed.error_at(&cp3, false)) />
            </label>
            <Choice
                label="Type"
                options=options(&OBSTACLE_TYPES)
                current=Signal::derive(move || kind.get())
                on_pick=Callback::new(move |k: String| ed.edit(|d| el::retype_obstacle(d, i, &k)))
            />
            {fields}
            <FieldMessage local=RwSignal::new(None) core=item_error />
            <button
                type="button"
                class="remove"
                data-testid="remove-obstacle"
                on:click=move |_| ed.edit(|d| { el::remove(d, &Path::of(&["obstacles"]).i(i)); })
            >
                {format!("Delete obstacle {}", i + 1)}
            </button>
        </fieldset>
    }
}
