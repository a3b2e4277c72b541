//! Poses: position and orientation as numbers and sliders, in tilt-and-torsion, XYZ Euler or a
//! quaternion, with the live feasibility of the pose being edited (the core's `check_pose`).

use leptos::prelude::*;
use std::f64::consts::PI;

use super::fields::{options, Choice, FieldMessage, NameField, NumField};
use super::Ed;
use crate::edit_logic::{self as el, Path, ORIENTATIONS};

/// The poses' part of the editor.
#[component]
pub fn PoseEditor(ed: Ed) -> impl IntoView {
    let count = ed.count(Path::of(&["poses"]));
    view! {
        <p class="hint">
            "Position p of the platform origin in the world frame (m). Tilt-and-torsion (φ, θ, σ) in radians: \
             R = Rz(φ)·Ry(θ)·Rz(σ−φ); XYZ Euler (α, β, γ) in degrees: R = Rx(α)·Ry(β)·Rz(γ)."
        </p>
        <For each=move || 0..count.get() key=|i| *i let:i>
            <PoseItem ed i />
        </For>
        <button type="button" data-testid="add-pose" on:click=move |_| ed.edit(|d| { el::add_pose(d); })>
            "Add a pose"
        </button>
    }
}

/// One pose.
#[component]
fn PoseItem(ed: Ed, i: usize) -> impl IntoView {
    let path = Path::of(&["poses"]).i(i);
    let name = Memo::new(move |_| ed.read(|d| el::pose_names(d).get(i).cloned()).flatten().unwrap_or_default());
    let kind = Memo::new({
        let path = path.clone();
        move |_| ed.read(|d| el::orientation_kind(d, &path)).flatten().unwrap_or("tilt_torsion")
    });
    let range = Memo::new(move |_| ed.read(el::workspace_range).unwrap_or([[-1.0, 1.0]; 3]));
    let pose_error = Signal::derive({
        let path = path.clone();
        move || ed.error_at(&path, false)
    });
    let position = {
        let path = path.k("position");
        (0..3)
            .map(|a| {
                let axis = ["x", "y", "z"][a];
                let p = path.i(a);
                view! {
                    <div class="coord">
                        <NumField ed path=p.clone() label=axis unit="m" />
                        <Slider ed path=p lo=Signal::derive(move || range.get()[a][0]) hi=Signal::derive(move || range.get()[a][1]) label=format!("{axis} slider") />
                    </div>
                }
            })
            .collect_view()
    };
    let angles = {
        let path = path.clone();
        move || {
            let k = kind.get();
            let p = path.k(k);
            match k {
                "quaternion" => ["w", "x", "y", "z"]
                    .into_iter()
                    .enumerate()
                    .map(|(j, c)| view! { <NumField ed path=p.i(j) label=format!("q{c}") /> })
                    .collect_view()
                    .into_any(),
                _ => {
                    let (names, unit, lim): ([&str; 3], &str, f64) = if k == "euler_xyz_deg" {
                        (["α (about x)", "β (about y)", "γ (about z)"], "°", 180.0)
                    } else {
                        (["φ tilt azimuth", "θ tilt", "σ torsion"], "rad", PI)
                    };
                    (0..3)
                        .map(|j| {
                            let pj = p.i(j);
                            view! {
                                <div class="coord">
                                    <NumField ed path=pj.clone() label=names[j] unit />
                                    <Slider ed path=pj lo=Signal::derive(move || -lim) hi=Signal::derive(move || lim) label=format!("{} slider", names[j]) />
                                </div>
                            }
                        })
                        .collect_view()
                        .into_any()
                }
            }
        }
    };
    let convert = {
        let path = path.clone();
        Callback::new(move |k: String| ed.edit(|d| { el::convert_orientation(d, &path, &k); }))
    };
    let remove_path = path.clone();
    view! {
        <fieldset class="pose" data-testid="pose" class:invalid=move || pose_error.with(Option::is_some)>
            <legend>{move || format!("Pose “{}”", name.get())}</legend>
            <NameField ed name rename=move |d: &mut serde_json::Value, new: &str| el::rename_pose(d, i, new) label="Name" field=format!("poses[{i}].name") />
            <fieldset class="position"><legend>"Position (m)"</legend>{position}</fieldset>
            <Choice
                label="Orientation as"
                options=options(&ORIENTATIONS)
                current=Signal::derive(move || kind.get().to_string())
                on_pick=convert
                testid="orientation-kind"
            />
            <fieldset class="angles"><legend>"Orientation"</legend>{angles}</fieldset>
            <FieldMessage local=RwSignal::new(None) core=pose_error />
            <PoseCheck ed name />
            <button
                type="button"
                class="remove"
                on:click=move |_| ed.edit(|d| { el::remove(d, &remove_path); })
            >
                {move || format!("Delete pose “{}”", name.get())}
            </button>
        </fieldset>
    }
}

/// A slider over the number at `path`.
#[component]
fn Slider(ed: Ed, path: Path, lo: Signal<f64>, hi: Signal<f64>, #[prop(into)] label: String) -> impl IntoView {
    let p2 = path.clone();
    let value = Memo::new(move |_| ed.num(&path).unwrap_or(0.0));
    view! {
        <input
            type="range"
            class="slider"
            aria-label=label
            step="any"
            min=move || lo.get().min(value.get()).to_string()
            max=move || hi.get().max(value.get()).to_string()
            prop:value=move || value.get().to_string()
            on:input=move |ev| {
                if let Ok(Some(x)) = el::parse_number(&event_target_value(&ev)) {
                    let x = el::round12(x);
                    ed.edit(|d| { el::set(d, &p2, el::number(x)); });
                }
            }
        />
    }
}

/// The live check of this pose: feasible or the violated conditions (and the wrench verdict).
#[component]
fn PoseCheck(ed: Ed, name: Memo<String>) -> impl IntoView {
    move || {
        let n = name.get();
        ed.checked.with(|r| match r {
            Ok(s) => match el::check_pose(s, &n) {
                Some(report) => {
                    let class = if report.feasible { "check feasible" } else { "check infeasible" };
                    view! {
                        <p class=class data-testid="pose-check" data-feasible=report.feasible.to_string() aria-live="polite">
                            {el::pose_verdict(&report)}
                        </p>
                    }
                    .into_any()
                }
                None => view! { <p class="check">"—"</p> }.into_any(),
            },
            Err(_) => view! {
                <p class="check unknown" data-testid="pose-check" data-feasible="unknown">
                    "Feasibility shows once the scenario is valid (see the message above)."
                </p>
            }
            .into_any(),
        })
    }
}
