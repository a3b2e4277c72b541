//! A multi-link robot's links (scenario format 3): per link its name, parent, joint (type, axis,
//! coordinates and their ranges), location, mass and centre of mass (format 4) and collision body;
//! add and remove links. The edits themselves are `edit_logic::links`.

use leptos::prelude::*;
use serde_json::{json, Value};

use super::fields::{options, Choice, FieldMessage, MatrixField, NameField, NumField, Vec3Field};
use super::Ed;
use crate::edit_logic::{self as el, Path, JOINTS};

/// The links' part of the editor.
#[component]
pub fn LinksEditor(ed: Ed) -> impl IntoView {
    let count = ed.count(Path::of(&["robot", "links"]));
    view! {
        <p class="hint">
            "Each link hangs from its parent (or the base) at its joint's location, in the parent's frame; \
             spherical joints turn by XYZ Euler angles (R = Rx·Ry·Rz), revolute and prismatic ones about and along \
             their axis. Angles in radians, lengths in metres; ranges are shown, not checked as conditions."
        </p>
        <For each=move || 0..count.get() key=|i| *i let:i>
            <LinkItem ed i />
        </For>
        <button type="button" data-testid="add-link" on:click=move |_| ed.edit(|d| { el::add_link(d); })>
            "Add a link"
        </button>
    }
}

/// One link.
#[component]
fn LinkItem(ed: Ed, i: usize) -> impl IntoView {
    let path = Path::of(&["robot", "links"]).i(i);
    let name = Memo::new(move |_| ed.read(|d| el::link_names(d).get(i).cloned()).flatten().unwrap_or_default());
    let kind = Memo::new(move |_| ed.read(|d| el::joint_type(d, i)).unwrap_or_default());
    let coords = Memo::new(move |_| ed.read(|d| el::coordinate_names(d, i)).unwrap_or_default());
    let error = Signal::derive({
        let path = path.clone();
        move || ed.error_at(&path, false)
    });
    let parent = {
        let path = path.k("parent");
        let current = Signal::derive({
            let path = path.clone();
            move || ed.text(&path).unwrap_or_default()
        });
        move || {
            let names = ed.read(el::link_names).unwrap_or_default();
            let mut choices = vec![(String::new(), "the base".to_string())];
            choices.extend(names.into_iter().enumerate().filter(|(j, _)| *j != i).map(|(_, n)| (n.clone(), n)));
            let path = path.clone();
            let pick = Callback::new(move |p: String| {
                ed.edit(|d| {
                    if p.is_empty() {
                        el::remove(d, &path);
                    } else {
                        el::set(d, &path, json!(p));
                    }
                })
            });
            view! { <Choice label="Parent" options=choices current=current on_pick=pick testid=format!("link-{i}-parent") /> }
        }
    };
    let retype = Callback::new(move |k: String| ed.edit(|d| el::set_joint_type(d, i, &k)));
    let joint = path.k("joint");
    let axis = {
        let joint = joint.clone();
        move || match kind.get().as_str() {
            "revolute" | "prismatic" => Some(view! { <Vec3Field ed path=joint.k("axis") label="Axis (joint frame)" /> }.into_any()),
            "universal" => Some(view! { <MatrixField ed path=joint.k("axes") rows=2 cols=3 label="Axes: the first rotation's, then the second's" /> }.into_any()),
            "planar" => Some(view! { <MatrixField ed path=joint.k("axes") rows=3 cols=3 label="Axes: two translations, then the rotation's" /> }.into_any()),
            _ => None,
        }
    };
    let coordinate_rows = {
        let joint = joint.clone();
        move || {
            let k_unit = kind.get();
            coords
                .get()
                .into_iter()
                .enumerate()
                .map(|(k, _)| {
                    let unit = el::unit(&k_unit, k);
                    let name = Memo::new(move |_| coords.with(|c| c.get(k).cloned().unwrap_or_default()));
                    let range = joint.k("range").i(k);
                    view! {
                        <div class="coordinate" data-testid="link-coordinate">
                            <NameField ed name rename=move |d: &mut Value, new: &str| el::rename_coordinate(d, i, k, new)
                                label="Coordinate" field=format!("robot.links[{i}].joint.coordinates[{k}]") />
                            <NumField ed path=range.i(0) label="from" unit />
                            <NumField ed path=range.i(1) label="to" unit />
                        </div>
                    }
                })
                .collect_view()
        }
    };
    let body = path.k("body");
    view! {
        <fieldset class="link" data-testid="link" class:invalid=move || error.with(Option::is_some)>
            <legend>{move || format!("Link “{}”", name.get())}</legend>
            <NameField ed name rename=move |d: &mut Value, new: &str| el::rename_link(d, i, new) label="Name" field=format!("robot.links[{i}].name") />
            {parent}
            <Choice label="Joint" options=options(&JOINTS) current=Signal::derive(move || kind.get()) on_pick=retype testid=format!("link-{i}-joint") />
            {axis}
            <Vec3Field ed path=path.k("location") label="Joint location (parent's frame)" unit="m" />
            <fieldset class="coordinates"><legend>"Joint coordinates and their ranges"</legend>{coordinate_rows}</fieldset>
            <fieldset class="mass">
                <legend>"Mass: its weight the cables must hold (static feasibility)"</legend>
                <NumField ed path=path.k("mass") label="Mass (empty: massless)" unit="kg" optional=true timed=true />
                <Vec3Field ed path=path.k("com") label="Centre of mass (link frame)" unit="m" />
            </fieldset>
            <fieldset class="body">
                <legend>"Collision body: a segment with a radius (link frame)"</legend>
                <Vec3Field ed path=body.k("from") label="from" unit="m" />
                <Vec3Field ed path=body.k("to") label="to" unit="m" />
                <NumField ed path=body.k("radius") label="radius" unit="m" />
            </fieldset>
            <FieldMessage local=RwSignal::new(None) core=error />
            <button type="button" class="remove" data-testid="remove-link" on:click=move |_| ed.edit(|d| el::remove_link(d, i))>
                {move || format!("Delete link “{}”", name.get())}
            </button>
        </fieldset>
    }
}
