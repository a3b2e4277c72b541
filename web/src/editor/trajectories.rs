//! Trajectories: a line, a polynomial through via points, or Bézier control points for the
//! translation, each with a slerp between two orientations (pose names or quaternions).

use leptos::prelude::*;

use super::fields::{Choice, FieldMessage, NumField, NumInput, TextField, Vec3Field};
use super::Ed;
use crate::edit_logic::{self as el, Path, QUATERNION_END};

/// The trajectories' part of the editor.
#[component]
pub fn TrajectoryEditor(ed: Ed) -> impl IntoView {
    let count = ed.count(Path::of(&["trajectories"]));
    view! {
        <p class="hint">
            "The position is a polynomial in τ ∈ [0, 1]; the orientation a slerp in t ∈ [0, 1] (the two \
             parameters agree at the ends). Via points sit at evenly spaced τ."
        </p>
        <For each=move || 0..count.get() key=|i| *i let:i>
            <TrajectorySlot ed i />
        </For>
        <button type="button" data-testid="add-trajectory" on:click=move |_| ed.edit(|d| { el::add_trajectory(d); })>
            "Add a trajectory"
        </button>
    }
}

/// Trajectory `i` in its form's editor: the thesis' form or a timed spline (re-drawn only when
/// the form changes, not on every edit, so that typing keeps its field).
#[component]
fn TrajectorySlot(ed: Ed, i: usize) -> impl IntoView {
    let spline = Memo::new(move |_| ed.read(|d| el::is_spline(d, &Path::of(&["trajectories"]).i(i))).unwrap_or(false));
    move || {
        if spline.get() {
            view! { <super::knots::KnotsItem ed i /> }.into_any()
        } else {
            view! { <TrajectoryItem ed i /> }.into_any()
        }
    }
}

/// One trajectory.
#[component]
fn TrajectoryItem(ed: Ed, i: usize) -> impl IntoView {
    let path = Path::of(&["trajectories"]).i(i);
    let kind = Memo::new({
        let path = path.clone();
        move |_| ed.read(|d| el::translation_kind(d, &path)).flatten().unwrap_or("line")
    });
    let item_error = Signal::derive({
        let path = path.clone();
        move || ed.error_at(&path, false)
    });
    let translation_error = Signal::derive({
        let path = path.k("translation");
        move || ed.error_at(&path, false)
    });
    let form = {
        let t = path.k("translation");
        move || {
            let t = t.clone();
            match kind.get() {
                "line" => view! {
                    <Vec3Field ed path=t.k("line").i(0) label="Start (τ = 0)" unit="m" />
                    <Vec3Field ed path=t.k("line").i(1) label="End (τ = 1)" unit="m" />
                }
                .into_any(),
                "bezier" => view! { <BezierPoints ed path=t.k("bezier") /> }.into_any(),
                _ => view! { <ViaPoints ed path=t.k("polynomial") /> }.into_any(),
            }
        }
    };
    let retype = {
        let path = path.clone();
        Callback::new(move |k: String| ed.edit(|d| el::retype_translation(d, &path, &k)))
    };
    let remove_path = path.clone();
    view! {
        <fieldset class="trajectory" data-testid="trajectory-item" class:invalid=move || item_error.with(Option::is_some)>
            <legend>{move || format!("Trajectory {}", i + 1)}</legend>
            <TextField ed path=path.k("name") label="Name" />
            <NumField ed path=path.k("duration") label="Duration (empty: untimed)" unit="s" optional=true timed=true />
            <Choice
                label="Translation"
                options=vec![
                    ("line".into(), "line".into()),
                    ("polynomial".into(), "polynomial through via points".into()),
                    ("bezier".into(), "Bézier control points".into()),
                ]
                current=Signal::derive(move || kind.get().to_string())
                on_pick=retype
                testid="translation-kind"
            />
            {form}
            <FieldMessage local=RwSignal::new(None) core=translation_error />
            <SlerpEnds ed path=path.clone() />
            <FieldMessage local=RwSignal::new(None) core=item_error />
            <button type="button" data-testid="to-spline" on:click={
                let path = path.clone();
                move |_| ed.edit(|d| { el::to_spline(d, &path, i); })
            }>
                "Make it a timed spline (start to end, at rest)"
            </button>
            <button type="button" class="remove" on:click=move |_| ed.edit(|d| { el::remove(d, &remove_path); })>
                {format!("Delete trajectory {}", i + 1)}
            </button>
        </fieldset>
    }
}

/// The polynomial as via points; editing one refits the polynomial through all of them.
#[component]
fn ViaPoints(ed: Ed, path: Path) -> impl IntoView {
    let shown = RwSignal::new(0usize);
    let points = Memo::new({
        let path = path.clone();
        move |_| ed.read(|d| el::via_points_of(d, &path, shown.get())).flatten().unwrap_or_default()
    });
    let local = RwSignal::new(None::<String>);
    let write = {
        let path = path.clone();
        move |pts: Vec<[f64; 3]>| {
            let mut result = Ok(());
            ed.edit(|d| result = el::set_via_points(d, &path, &pts));
            local.set(result.err().map(|e| e.reason));
        }
    };
    let coefficients = {
        let path = path.clone();
        move || ed.read(|d| el::get(d, &path).map(|v| v.to_string())).flatten().unwrap_or_default()
    };
    let core = Signal::derive({
        let path = path.clone();
        move || ed.error_at(&path, true)
    });
    let field = Signal::derive(move || ed.core_path(&path));
    let count = Memo::new(move |_| points.with(Vec::len));
    let write_row = write.clone();
    view! {
        <fieldset class="via" data-testid="via-points">
            <legend>"Via points (m), at τ = k/(n−1)"</legend>
            <For each=move || 0..count.get() key=|k| *k let:k>
                {
                    let write = write_row.clone();
                    let write_remove = write_row.clone();
                    view! {
                        <div class="via-point" data-testid="via-point">
                            <span class="label">{move || format!("P{k} (τ = {})", crate::logic::fmt_num(cablenav::model::via::via_tau(k, count.get())))}</span>
                            {(0..3)
                                .map(|a| {
                                    let write = write.clone();
                                    let on_value = Callback::new(move |v: Option<f64>| {
                                        let mut pts = points.get_untracked();
                                        if let (Some(x), Some(p)) = (v, pts.get_mut(k)) {
                                            p[a] = x;
                                            write(pts);
                                        }
                                    });
                                    view! {
                                        <NumInput
                                            value=Signal::derive(move || points.with(|p| p.get(k).map(|p| p[a])))
                                            on_value
                                            label=format!("P{k} {}", ["x", "y", "z"][a])
                                            unit="m"
                                            compact=true
                                            field=Signal::derive(move || format!("{}.via[{k}][{a}]", field.get()))
                                            error=Signal::derive(|| None::<String>)
                                        />
                                    }
                                })
                                .collect_view()}
                            <button
                                type="button"
                                class="remove"
                                aria-label=format!("remove via point {k}")
                                on:click=move |_| {
                                    let mut pts = points.get_untracked();
                                    if k < pts.len() {
                                        pts.remove(k);
                                        shown.set(pts.len());
                                        write_remove(pts);
                                    }
                                }
                            >
                                "✕"
                            </button>
                        </div>
                    }
                }
            </For>
            <button type="button" data-testid="add-via-point" on:click=move |_| shown.set(count.get_untracked() + 1)>
                "Add a via point"
            </button>
            <p class="coefficients">"Coefficients (ascending, per axis): " <code>{coefficients}</code></p>
            <FieldMessage local core />
        </fieldset>
    }
}

/// The Bézier control points, with add and remove.
#[component]
fn BezierPoints(ed: Ed, path: Path) -> impl IntoView {
    let count = ed.count(path.clone());
    let (p_add, p_rows) = (path.clone(), path);
    view! {
        <fieldset class="bezier">
            <legend>"Bézier control points (m)"</legend>
            <For each=move || 0..count.get() key=|k| *k let:k>
                {
                    let p = p_rows.clone();
                    view! {
                        <div class="bezier-point">
                            <Vec3Field ed path=p.i(k) label=format!("P{k}") unit="m" />
                            <button
                                type="button"
                                class="remove"
                                aria-label=format!("remove control point {k}")
                                on:click=move |_| ed.edit(|d| { el::remove(d, &p.i(k)); })
                            >
                                "✕"
                            </button>
                        </div>
                    }
                }
            </For>
            <button
                type="button"
                on:click=move |_| {
                    let p = p_add.clone();
                    ed.edit(move |d| {
                        let n = el::len(d, &p);
                        let last = n.checked_sub(1).and_then(|k| el::get(d, &p.i(k)).cloned());
                        if let Some(last) = last {
                            el::set(d, &p.i(n), last);
                        }
                    })
                }
            >
                "Add a control point"
            </button>
        </fieldset>
    }
}

/// The slerp's two ends: each a pose or an explicit quaternion.
#[component]
fn SlerpEnds(ed: Ed, path: Path) -> impl IntoView {
    let names = Memo::new(move |_| ed.read(el::pose_names).unwrap_or_default());
    (0..2)
        .map(|e| {
            let (p1, p2, p3) = (path.clone(), path.clone(), path.clone());
            let choice = Memo::new(move |_| ed.read(|d| el::slerp_end_choice(d, &p1, e)).unwrap_or_default());
            let label = if e == 0 { "Orientation at t = 0 (Qs)" } else { "Orientation at t = 1 (Qe)" };
            view! {
                <div class="slerp-end">
                    {move || {
                        let mut opts: Vec<(String, String)> = names.get().into_iter().map(|n| (n.clone(), format!("pose “{n}”"))).collect();
                        opts.push((QUATERNION_END.to_string(), "a quaternion [w, x, y, z]".to_string()));
                        let p = p2.clone();
                        view! {
                            <Choice
                                label
                                options=opts
                                current=Signal::derive(move || choice.get())
                                on_pick=Callback::new(move |c: String| ed.edit(|d| el::set_slerp_end(d, &p, e, &c)))
                            />
                        }
                    }}
                    {move || {
                        (choice.get() == QUATERNION_END).then(|| {
                            let q = p3.k("orientation").k("slerp").i(e);
                            ["w", "x", "y", "z"]
                                .into_iter()
                                .enumerate()
                                .map(|(j, c)| view! { <NumField ed path=q.i(j) label=format!("q{c}") compact=true /> })
                                .collect_view()
                        })
                    }}
                </div>
            }
        })
        .collect_view()
}
