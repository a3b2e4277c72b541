//! A timed spline trajectory through knots (CASPR's form): its kind, and per knot the time, the
//! pose (a pose name, or a position and the orientation in the form it is written in), the
//! velocity and (quintic) the acceleration of the platform origin.

use leptos::prelude::*;

use super::fields::{Choice, FieldMessage, NumField, TextField, Vec3Field};
use super::Ed;
use crate::edit_logic::{self as el, Path};

/// One spline trajectory.
#[component]
pub fn KnotsItem(ed: Ed, i: usize) -> impl IntoView {
    let path = Path::of(&["trajectories"]).i(i);
    let knots = ed.count(path.k("knots"));
    let kind = Memo::new({
        let path = path.clone();
        move |_| ed.read(|d| el::spline_kind(d, &path)).unwrap_or("quintic")
    });
    let item_error = Signal::derive({
        let path = path.clone();
        move || ed.error_at(&path, false)
    });
    let retype = {
        let path = path.clone();
        Callback::new(move |k: String| ed.edit(|d| el::set_spline_kind(d, &path, &k)))
    };
    let (add_path, remove_path, rows) = (path.clone(), path.clone(), path.k("knots"));
    view! {
        <fieldset class="trajectory spline" data-testid="spline-item" class:invalid=move || item_error.with(Option::is_some)>
            <legend>{move || format!("Trajectory {} (timed spline)", i + 1)}</legend>
            <p class="hint">
                "Between knots the position is the polynomial in time meeting both knots; the rotation turns \
                 about one axis from rest to rest (CASPR's splines). The duration is the last knot's time."
            </p>
            <TextField ed path=path.k("name") label="Name" />
            <Choice
                label="Spline"
                options=vec![("quintic".into(), "quintic (velocity and acceleration)".into()), ("cubic".into(), "cubic (velocity)".into())]
                current=Signal::derive(move || kind.get().to_string())
                on_pick=retype
                testid="spline-kind"
            />
            <For each=move || 0..knots.get() key=|j| *j let:j>
                <Knot ed path=rows.i(j) j kind removable=Signal::derive(move || knots.get() > 2) />
            </For>
            <button type="button" data-testid="add-knot" on:click=move |_| ed.edit(|d| el::add_knot(d, &add_path))>
                "Add a knot"
            </button>
            <FieldMessage local=RwSignal::new(None) core=item_error />
            <button type="button" class="remove" on:click=move |_| ed.edit(|d| { el::remove(d, &remove_path); })>
                {format!("Delete trajectory {}", i + 1)}
            </button>
        </fieldset>
    }
}

/// One knot.
#[component]
fn Knot(ed: Ed, path: Path, j: usize, kind: Memo<&'static str>, removable: Signal<bool>) -> impl IntoView {
    let orientation = Memo::new({
        let path = path.clone();
        move |_| ed.read(|d| el::knot_orientation(d, &path)).unwrap_or("quaternion")
    });
    let pose = {
        let path = path.clone();
        move || {
            let form = orientation.get();
            if form == "pose" {
                return view! { <TextField ed path=path.k("pose") label="Pose" /> }.into_any();
            }
            let p = path.k(form);
            let labels: Vec<(String, &'static str)> = match form {
                "quaternion" => ["w", "x", "y", "z"].iter().map(|c| (format!("q{c}"), "")).collect(),
                "euler_xyz_deg" => ["α", "β", "γ"].iter().map(|c| (c.to_string(), "°")).collect(),
                _ => ["φ", "θ", "σ"].iter().map(|c| (c.to_string(), "rad")).collect(),
            };
            view! {
                <Vec3Field ed path=path.k("position") label="Position" unit="m" />
                <div class="orientation">
                    {labels.into_iter().enumerate().map(|(k, (label, unit))| view! { <NumField ed path=p.i(k) label unit compact=true /> }).collect_view()}
                </div>
            }
            .into_any()
        }
    };
    let remove_path = path.clone();
    view! {
        <fieldset class="knot" data-testid="knot">
            <legend>{format!("Knot {j}")}</legend>
            <NumField ed path=path.k("time") label="Time" unit="s" />
            {pose}
            <Vec3Field ed path=path.k("velocity") label="Velocity" unit="m/s" />
            <Show when=move || kind.get() == "quintic">
                <Vec3Field ed path=path.k("acceleration") label="Acceleration" unit="m/s²" />
            </Show>
            <Show when=move || removable.get()>
                <button type="button" class="remove" aria-label=format!("remove knot {j}") on:click={
                    let p = remove_path.clone();
                    move |_| ed.edit(|d| { el::remove(d, &p); })
                }>
                    "✕"
                </button>
            </Show>
        </fieldset>
    }
}
