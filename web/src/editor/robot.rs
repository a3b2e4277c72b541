//! The robot: the scenario's name, the cable table (anchors; add and remove cables), length and
//! tension bounds, cable diameter and clearances.

use leptos::prelude::*;

use super::fields::{FieldMessage, NumField, NumberOrListField, TextField};
use super::Ed;
use crate::edit_logic::{self as el, Path};

/// The robot's part of the editor.
#[component]
pub fn RobotEditor(ed: Ed) -> impl IntoView {
    let cables = Path::of(&["robot", "cables"]);
    let count = ed.count(cables.clone());
    let table_error = Signal::derive({
        let cables = cables.clone();
        move || ed.error_at(&cables, false)
    });
    let chain = Memo::new(move |_| ed.read(el::is_multi_link).unwrap_or(false));
    // a multi-link robot's tensions matter once a link has a mass or carries a wrench, or its
    // joints take forces (static feasibility)
    let weighed = Memo::new(move |_| ed.read(|d| el::has_link_mass(d) || d.get("wrench").is_some() || d.get("joint_forces").is_some()).unwrap_or(false));
    view! {
        <TextField ed path=Path::of(&["name"]) label="Scenario name" />
        // the table scrolls sideways inside the side panel when it is wider (a multi-link robot's
        // link column on a narrow panel) rather than being cut at the panel's edge
        <div class="table-scroll" data-testid="cable-table-scroll">
        <table class="cables" data-testid="cable-table">
            <caption>
                {move || if chain.get() {
                    "Cables: base anchor aᵢ (world frame, or the frame of the link a routed cable starts on), the link pulled and the point bᵢ on it (that link's frame), in metres; ↝ marks a routed cable, its route kept as the file has it"
                } else {
                    "Cables: base anchor aᵢ (world frame) and platform anchor bᵢ (platform frame), in metres"
                }}
            </caption>
            // two header rows: the anchor over its three coordinates, so that each column is as
            // narrow as its number field
            <thead>
                <tr>
                    <th scope="col" rowspan="2">"#"</th>
                    <th scope="colgroup" colspan="3">"base aᵢ"</th>
                    {move || chain.get().then(|| view! { <th scope="col" rowspan="2">"link"</th> })}
                    <th scope="colgroup" colspan="3">{move || if chain.get() { "on the link bᵢ" } else { "platform bᵢ" }}</th>
                    <th scope="col" rowspan="2"><span class="sr-only">"remove"</span></th>
                </tr>
                <tr>
                    <th scope="col">"x"</th><th scope="col">"y"</th><th scope="col">"z"</th>
                    <th scope="col">"x"</th><th scope="col">"y"</th><th scope="col">"z"</th>
                </tr>
            </thead>
            <tbody>
                <For each=move || 0..count.get() key=|i| *i let:i>
                    <CableRow ed i />
                </For>
            </tbody>
        </table>
        </div>
        <FieldMessage local=RwSignal::new(None) core=table_error />
        <button type="button" data-testid="add-cable" on:click=move |_| ed.edit(el::add_cable)>
            "Add a cable"
        </button>
        <p class="hint" data-testid="robot-hint">{move || if chain.get() {
            "A multi-link robot's cables pull on its links; it is checked for cable–cable, cable–link and cable–obstacle \
             interference, cable lengths and joint-space wrench closure, and, once a link has a mass, for static \
             feasibility: tensions within their bounds holding the links' weights and a wrench on a link \
             (docs/multilink.md). A wrench set around that wrench does not apply to it yet."
        } else {
            "A 6-DoF robot needs 6 to 64 cables. A wrench ellipsoid or closure is tested for up to 10; a single wrench and the platform's mass for any number."
        }}</p>
        <div class="bounds">
            <BoundsGroup ed what="length" title="Cable length bounds" unit="m" />
            // a multi-link robot's tension bounds are read once a link has a mass: offered then
            {move || (!chain.get() || weighed.get()).then(|| view! { <BoundsGroup ed what="tension" title="Cable tension bounds" unit="N" /> })}
            <NumField ed path=Path::of(&["robot", "diameter"]) label="Cable diameter" unit="m" optional=true />
            <NumField ed path=Path::of(&["clearance", "cable_cable"]) label="Clearance cable–cable" unit="m" optional=true />
            <NumField ed path=Path::of(&["clearance", "cable_obstacle"]) label="Clearance cable–obstacle" unit="m" optional=true />
            {move || chain.get().then(|| view! {
                <NumField ed path=Path::of(&["clearance", "cable_link"]) label="Clearance cable–link" unit="m" optional=true />
            })}
        </div>
    }
}

/// The robot-level `min` and `max` of `robot.<what>`; errors about the pair (min > max) show
/// under both.
#[component]
fn BoundsGroup(ed: Ed, what: &'static str, title: &'static str, unit: &'static str) -> impl IntoView {
    let group = Path::of(&["robot", what]);
    let error = Signal::derive({
        let group = group.clone();
        move || ed.error_at(&group, false)
    });
    view! {
        <fieldset class="bounds-group" class:invalid=move || error.with(Option::is_some)>
            <legend>{format!("{title} ({unit}; empty: none)")}</legend>
            <NumberOrListField ed path=group.k("min") label="min" unit />
            <NumberOrListField ed path=group.k("max") label="max" unit />
            <FieldMessage local=RwSignal::new(None) core=error />
        </fieldset>
    }
}

/// One row of the cable table.
#[component]
fn CableRow(ed: Ed, i: usize) -> impl IntoView {
    let cable = Path::of(&["robot", "cables"]).i(i);
    let row_error = Signal::derive({
        let cable = cable.clone();
        move || ed.error_at(&cable, false)
    });
    // a multi-link robot's cable names the link it pulls
    let link_cell = {
        let path = cable.k("link");
        move || {
            ed.read(el::is_multi_link).unwrap_or(false).then(|| {
                let names = ed.read(el::link_names).unwrap_or_default();
                let p2 = path.clone();
                let current = Memo::new({
                    let p1 = path.clone();
                    move |_| ed.text(&p1).unwrap_or_default()
                });
                view! {
                    <td>
                        <select aria-label=format!("cable {} link", i + 1) data-field=format!("robot.cables[{i}].link")
                            prop:value=move || current.get()
                            on:change=move |ev| {
                                let v = event_target_value(&ev);
                                ed.edit(|d| { el::set(d, &p2, serde_json::json!(v)); })
                            }>
                            {names.into_iter().map(|n| {
                                let (v, sel) = (n.clone(), n.clone());
                                view! { <option value=v selected=move || current.get() == sel>{n}</option> }
                            }).collect_view()}
                        </select>
                    </td>
                }
            })
        }
    };
    let cell = move |end: &'static str, axis: usize| {
        let name = ["x", "y", "z"][axis];
        view! {
            <td>
                <NumField ed path=cable.k(end).i(axis) label=format!("cable {} {end} {name}", i + 1) unit="m" compact=true />
            </td>
        }
    };
    // a routed cable (format 6) says how it runs: the row edits its two end anchors only
    let route = move || ed.read(|d| el::route_summary(d, i)).flatten();
    view! {
        <tr data-testid="cable-row" class:invalid=move || row_error.with(Option::is_some)>
            <th scope="row">
                {i + 1}
                {move || route().map(|r| view! { <span class="routed" data-testid="cable-route" title=r.clone() aria-label=r>"↝"</span> })}
            </th>
            {cell("base", 0)}{cell("base", 1)}{cell("base", 2)}
            {link_cell}
            {cell("platform", 0)}{cell("platform", 1)}{cell("platform", 2)}
            <td>
                <button
                    type="button"
                    class="remove"
                    aria-label=format!("remove cable {}", i + 1)
                    title=format!("remove cable {}", i + 1)
                    on:click=move |_| ed.edit(|d| el::remove_cable(d, i))
                >
                    "✕"
                </button>
                <FieldMessage local=RwSignal::new(None) core=row_error />
            </td>
        </tr>
    }
}
