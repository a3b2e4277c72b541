//! The wrench set: nominal wrench, application point and its frame, and the ellipsoid E as one
//! radius, per-axis radii or the full 6×6 matrix (its positive definiteness is the core's check);
//! and a multi-link robot's wrench on one of its links and forces on its joints.

use leptos::prelude::*;
use serde_json::Value;

use super::fields::{Choice, FieldMessage, MatrixField, NumField, NumInput, Vec3Field};
use super::Ed;
use crate::edit_logic::{self as el, Path};

/// Names and units of the six wrench components.
const COMPONENTS: [(&str, &str); 6] = [("fx", "N"), ("fy", "N"), ("fz", "N"), ("mx", "N·m"), ("my", "N·m"), ("mz", "N·m")];

/// The wrench part of the editor.
#[component]
pub fn WrenchEditor(ed: Ed) -> impl IntoView {
    let present = Memo::new(move |_| ed.read(|d| d.get("wrench").is_some()).unwrap_or(false));
    let section_error = Signal::derive(move || ed.error_at(&Path::of(&["wrench"]), false));
    view! {
        <p class="hint">
            "The platform must withstand every wrench w with (w − w₀)ᵀ E (w − w₀) ≤ 1, applied at the point, with \
             every cable tension within its bounds (6-cable robots)."
        </p>
        <Show
            when=move || present.get()
            fallback=move || view! {
                <button
                    type="button"
                    data-testid="add-wrench"
                    on:click=move |_| ed.edit(|d| { el::set(d, &Path::of(&["wrench"]), el::wrench_template()); })
                >
                    "Add a wrench set"
                </button>
            }
        >
            <NominalAndPoint ed body="platform" />
            <Ellipsoid ed />
            <FieldMessage local=RwSignal::new(None) core=section_error />
            <button
                type="button"
                on:click=move |_| ed.edit(|d| { el::remove(d, &Path::of(&["wrench"])); })
            >
                "Remove the wrench set"
            </button>
        </Show>
    }
}

/// The nominal wrench's six components, its point and the point's frame, on the `body` it acts
/// on ("platform", or "link" for a multi-link robot).
#[component]
fn NominalAndPoint(ed: Ed, body: &'static str) -> impl IntoView {
    view! {
        <fieldset class="wrench-nominal">
            <legend>"Nominal wrench w₀ (world-parallel axes at the point)"</legend>
            {COMPONENTS
                .iter()
                .enumerate()
                .map(|(i, (name, unit))| {
                    view! { <NumField ed path=Path::of(&["wrench", "nominal"]).i(i) label=*name unit=*unit /> }
                })
                .collect_view()}
        </fieldset>
        <Vec3Field ed path=Path::of(&["wrench", "point"]) label="Application point offset" unit="m" />
        <Choice
            label="Point frame"
            options=vec![
                ("platform".to_string(), format!("{body} (rotates with it: c = p + R·point)")),
                ("world".to_string(), "world (stays parallel: c = p + point)".to_string()),
            ]
            current=Signal::derive(move || ed.text(&Path::of(&["wrench", "point_frame"])).unwrap_or_else(|| "platform".into()))
            on_pick=Callback::new(move |v: String| ed.edit(|d| { el::set(d, &Path::of(&["wrench", "point_frame"]), Value::String(v)); }))
            testid="point-frame"
        />
    }
}

/// A multi-link robot's wrench: applied to one link (format 4), its nominal value alone, held by
/// the cables with the links' weights (static feasibility).
#[component]
pub fn LinkWrenchEditor(ed: Ed) -> impl IntoView {
    let present = Memo::new(move |_| ed.read(|d| d.get("wrench").is_some()).unwrap_or(false));
    let section_error = Signal::derive(move || ed.error_at(&Path::of(&["wrench"]), false));
    let link = move || {
        let names = ed.read(el::link_names).unwrap_or_default();
        let choices = names.into_iter().map(|n| (n.clone(), n)).collect();
        let current = Signal::derive(move || ed.text(&Path::of(&["wrench", "link"])).unwrap_or_default());
        let pick = Callback::new(move |v: String| ed.edit(|d| { el::set(d, &Path::of(&["wrench", "link"]), Value::String(v)); }));
        view! { <Choice label="Link" options=choices current on_pick=pick testid="wrench-link" /> }
    };
    view! {
        <p class="hint">
            "A wrench applied to one link from outside (a payload, a tool's reaction): the cables must hold it, \
             with the links' weights, by tensions within their bounds (static feasibility)."
        </p>
        <Show
            when=move || present.get()
            fallback=move || view! {
                <button type="button" data-testid="add-link-wrench" on:click=move |_| ed.edit(el::add_link_wrench)>
                    "Apply a wrench to a link"
                </button>
            }
        >
            {link}
            <NominalAndPoint ed body="link" />
            <FieldMessage local=RwSignal::new(None) core=section_error />
            <button type="button" on:click=move |_| ed.edit(|d| { el::remove(d, &Path::of(&["wrench"])); })>
                "Remove the wrench"
            </button>
        </Show>
    }
}

/// Forces from outside on a multi-link robot's joint coordinates (`joint_forces`): one optional
/// number per coordinate of a revolute, prismatic, universal or planar joint.
#[component]
pub fn JointForcesEditor(ed: Ed) -> impl IntoView {
    let coords = Memo::new(move |_| ed.read(el::forceable_coordinates).unwrap_or_default());
    let section_error = Signal::derive(move || ed.error_at(&Path::of(&["joint_forces"]), false));
    let fields = move || {
        coords
            .get()
            .into_iter()
            .map(|(name, unit)| view! { <NumField ed path=Path::of(&["joint_forces"]).k(&name) label=name unit optional=true write=el::set_joint_force /> })
            .collect_view()
    };
    view! {
        <p class="hint">
            "A torque about a joint's axis or a force along it, applied from outside (a motor, a spring, a hand): \
             the cables must hold it, with the weights and the wrench on a link. Empty: none. The coordinates of \
             ball joints take none (a moment on their link is a wrench)."
        </p>
        <div class="values" data-testid="joint-forces">{fields}</div>
        <FieldMessage local=RwSignal::new(None) core=section_error />
    }
}

/// The ellipsoid E, in the mode it is written in.
#[component]
fn Ellipsoid(ed: Ed) -> impl IntoView {
    // A diagonal matrix reads as per-axis radii; once the user asks for the full matrix, keep
    // showing it as one.
    let chosen = RwSignal::new(None::<String>);
    let mode = Memo::new(move |_| {
        let written = ed.read(el::ellipsoid_mode).unwrap_or("radius");
        match (chosen.get().as_deref(), written) {
            (Some("matrix"), "radii") => "matrix",
            (_, w) => w,
        }
    });
    view! {
        <Choice
            label="Ellipsoid E given as"
            options=vec![
                ("radius".to_string(), "one radius (E = I/r²)".to_string()),
                ("radii".to_string(), "a radius per axis (E diagonal)".to_string()),
                ("matrix".to_string(), "the full 6×6 matrix".to_string()),
                ("none".to_string(), "none: the nominal wrench alone".to_string()),
            ]
            current=Signal::derive(move || mode.get().to_string())
            on_pick=Callback::new(move |m: String| {
                ed.edit(|d| el::set_ellipsoid_mode(d, &m));
                chosen.set(Some(m));
            })
            testid="ellipsoid-mode"
        />
        {move || match mode.get() {
            "radius" => view! { <NumField ed path=Path::of(&["wrench", "radius"]) label="Radius r" unit="N, N·m" /> }.into_any(),
            "radii" => view! { <Radii ed /> }.into_any(),
            "none" => view! { <p class="hint">"Only the nominal wrench (with the platform's weight and inertia) must be balanced: no ellipsoid of wrenches around it."</p> }.into_any(),
            _ => view! { <MatrixField ed path=Path::of(&["wrench", "ellipsoid"]) rows=6 cols=6 label="E (symmetric positive definite)" /> }.into_any(),
        }}
    }
}

/// One radius per wrench axis; E = diag(1/rᵢ²).
#[component]
fn Radii(ed: Ed) -> impl IntoView {
    let radii = Memo::new(move |_| ed.read(el::ellipsoid_radii).unwrap_or([None; 6]));
    let error = Signal::derive(move || ed.error_at(&Path::of(&["wrench", "ellipsoid"]), true));
    view! {
        <fieldset class="radii">
            <legend>"Radii rᵢ (E = diag(1/rᵢ²))"</legend>
            {COMPONENTS
                .iter()
                .enumerate()
                .map(|(i, (name, unit))| {
                    let on_value = Callback::new(move |v: Option<f64>| {
                        let mut all = radii.get_untracked().map(|r| r.unwrap_or(0.0));
                        all[i] = v.unwrap_or(0.0);
                        ed.edit(|d| el::set_ellipsoid_radii(d, all));
                    });
                    view! {
                        <NumInput
                            value=Signal::derive(move || radii.get()[i])
                            on_value
                            label=format!("r {name}")
                            unit=*unit
                            field=format!("wrench.ellipsoid.radii[{i}]")
                            error=Signal::derive(|| None::<String>)
                            positive=true
                        />
                    }
                })
                .collect_view()}
            <FieldMessage local=RwSignal::new(None) core=error />
        </fieldset>
    }
}
