//! The stage's drag bar: which handle the 3-D view's drag moves (or nudges by a step along x, y
//! or z), the drag's constraint, and the last update's times.

use crate::edit_logic::Handle;
use crate::logic::fmt_num;
use crate::view3d::drag::Constraint;
use leptos::prelude::*;

/// The drag bar (hidden for a multi-link robot, which is posed by its joint sliders): the
/// handles of `handle_list` to pick from, the `constraint`, nudge buttons (`on_nudge` gets the
/// axis and the sign) with their `nudge_step`, and the readout of the selected handle's place,
/// the last update on the main thread (`update_ms`) and the worker's verification (`live_ms`).
#[component]
pub fn DragBar(
    hidden: Signal<bool>,
    handle_list: Memo<Vec<Handle>>,
    selected: RwSignal<Option<usize>>,
    constraint: RwSignal<Constraint>,
    nudge_step: RwSignal<f64>,
    update_ms: RwSignal<Option<f64>>,
    live_ms: RwSignal<Option<f64>>,
    on_nudge: Callback<(usize, f64)>,
) -> impl IntoView {
    let nudge = move |axis: usize, sign: f64| on_nudge.run((axis, sign));
    view! {
    <div class="drag-bar" data-testid="drag-bar" hidden=move || hidden.get()>
        <label>
            "Move "
            <select data-testid="handle" on:change=move |ev| selected.set(event_target_value(&ev).parse::<usize>().ok())>
                <option value="" selected=move || selected.get().is_none()>"(drag a yellow handle, or pick one)"</option>
                {move || handle_list.get().into_iter().enumerate().map(|(i, h)| view! {
                    <option value=i.to_string() selected=move || selected.get() == Some(i)>{h.label}</option>
                }).collect_view()}
            </select>
        </label>
        <label>
            " "
            <select data-testid="drag-constraint" aria-label="drag constraint" on:change=move |ev| {
                if let Some(c) = Constraint::from_id(&event_target_value(&ev)) {
                    constraint.set(c)
                }
            }>
                {Constraint::CHOICES.map(|(c, id, label)| view! { <option value=id selected=move || constraint.get() == c>{label}</option> })}
            </select>
        </label>
        <span class="nudge" role="group" aria-label="nudge the selected handle">
            {[(0usize, "x"), (1, "y"), (2, "z")].map(|(axis, name)| view! {
                <button class="small" data-testid=format!("nudge-{name}-minus") disabled=move || selected.get().is_none() on:click=move |_| nudge(axis, -1.0)
                    aria-label=format!("move the selected handle by −step along {name}")>{format!("−{name}")}</button>
                <button class="small" data-testid=format!("nudge-{name}-plus") disabled=move || selected.get().is_none() on:click=move |_| nudge(axis, 1.0)
                    aria-label=format!("move the selected handle by +step along {name}")>{format!("+{name}")}</button>
            })}
        </span>
        <label>
            " step "
            <input class="num" type="number" min="0.001" step="0.01" data-testid="nudge-step" prop:value=move || nudge_step.get().to_string()
                on:change=move |ev| {
                    if let Some(v) = event_target_value(&ev).trim().parse::<f64>().ok().filter(|v| v.is_finite() && *v > 0.0) {
                        nudge_step.set(v)
                    }
                } />
            " m"
        </label>
        <span class="readout" data-testid="handle-readout" data-update-ms=move || update_ms.get().map(|t| format!("{t:.3}")).unwrap_or_default()
            data-verify-ms=move || live_ms.get().map(|t| format!("{t:.3}")).unwrap_or_default()>
            {move || {
                let at = selected.get().and_then(|i| handle_list.with(|h| h.get(i).map(|h| h.at)));
                let pos = at.map(|p| format!("at x {} y {} z {} m", fmt_num(p[0]), fmt_num(p[1]), fmt_num(p[2]))).unwrap_or_default();
                let t = update_ms.get().map(|t| format!(" · last update {t:.1} ms (edit and scene)")).unwrap_or_default();
                let v = live_ms.get().map(|t| format!(", exact verification {t:.1} ms in a worker")).unwrap_or_default();
                format!("{pos}{t}{v}")
            }}
        </span>
    </div>
    }
}
