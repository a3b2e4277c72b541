//! The t-strip: feasible/infeasible/uncertain sections over t ∈ [0, 1] (labelled in seconds for a
//! timed trajectory) and a tick at each boundary naming the active constraint — as an SVG tooltip on hover, and in a readout line on
//! tap or click (touch screens show no tooltips). Test contract: `svg[data-testid=strip]` holds
//! `rect[data-testid=section]` with `data-kind`, `data-t0`, `data-t1` and a `<title>`, and
//! `g[data-testid=boundary]` with `data-t` and an SVG `<title>`.

use super::{ExportButtons, FONT};
use crate::logic::{fmt_exact, fmt_num, Section, StripModel, Tick};
use crate::palette::{css, kind_colour};
use leptos::prelude::*;

const STRIP_W: f64 = 1000.0;
const STRIP_Y: f64 = 6.0;
const STRIP_H: f64 = 36.0;

/// The horizontal strip over t ∈ [0, 1].
#[component]
pub fn Strip(model: StripModel) -> impl IntoView {
    let axis = [0.0, 0.25, 0.5, 0.75, 1.0];
    let picked = RwSignal::new(None::<String>);
    let svg_ref = NodeRef::<leptos::svg::Svg>::new();
    view! {
        <svg
            node_ref=svg_ref
            xmlns="http://www.w3.org/2000/svg"
            data-testid="strip"
            class="strip"
            viewBox=format!("-12 0 {} 64", STRIP_W + 24.0)
            font-family=FONT
            role="img"
            aria-label=match model.duration {
                Some(d) => format!("feasibility along the trajectory, t from 0 to 1 (0 to {} s)", fmt_num(d)),
                None => "feasibility along the trajectory, t from 0 to 1".to_string(),
            }
        >
            {model.sections.iter().map(|s| view! { <SectionRect section=s.clone() /> }).collect_view()}
            {model.ticks.iter().map(|t| view! { <TickMark tick=t.clone() picked /> }).collect_view()}
            {axis
                .iter()
                .map(|&t| {
                    view! {
                        <text class="axis" x=t * STRIP_W y=STRIP_Y + STRIP_H + 16.0 text-anchor="middle" font-size="13" fill="#5b6670">
                            {model.axis_label(t)}
                        </text>
                    }
                })
                .collect_view()}
        </svg>
        <p class="strip-readout" data-testid="boundary-readout" aria-live="polite">
            {move || picked.get().unwrap_or_else(|| "Tap or hover a boundary tick for its active constraint.".into())}
            " "
            <ExportButtons id="strip" svg_ref width=STRIP_W + 24.0 height=64.0 />
        </p>
        {(!model.gaps.is_empty())
            .then(|| {
                let gaps = model
                    .gaps
                    .iter()
                    .map(|g| format!("[{}, {}]", fmt_num(g[0]), fmt_num(g[1])))
                    .collect::<Vec<_>>()
                    .join(", ");
                view! { <p class="error">{format!("Not covered by the report: t ∈ {gaps}")}</p> }
            })}
    }
}

/// One section of the strip.
#[component]
fn SectionRect(section: Section) -> impl IntoView {
    let kind = section.kind.as_str();
    let title = format!("{kind}: t ∈ [{}, {}]", fmt_num(section.t0), fmt_num(section.t1));
    view! {
        <rect
            data-testid="section"
            data-kind=kind
            data-t0=fmt_exact(section.t0)
            data-t1=fmt_exact(section.t1)
            class=kind
            fill=css(kind_colour(section.kind))
            x=section.t0 * STRIP_W
            y=STRIP_Y
            width=((section.t1 - section.t0) * STRIP_W).max(0.0)
            height=STRIP_H
        >
            <title>{title}</title>
        </rect>
    }
}

/// One boundary tick with its tooltip; a tap, click, Enter or Space (it is focusable) shows its
/// label in the readout.
#[component]
fn TickMark(tick: Tick, picked: RwSignal<Option<String>>) -> impl IntoView {
    let x = tick.t * STRIP_W;
    let (label, key_label) = (tick.label.clone(), tick.label.clone());
    // the 3-D view shows this boundary's clearance tubes while it is pointed at (state::Focus)
    let focus = use_context::<crate::state::Focus>();
    let (t1, t2, t3) = (tick.clone(), tick.clone(), tick.clone());
    let set = move |t: Option<Tick>| {
        if let Some(f) = focus {
            f.0.set(t)
        }
    };
    view! {
        <g
            data-testid="boundary"
            data-t=fmt_exact(tick.t)
            class=format!("tick enters-{}", tick.enters)
            tabindex="0"
            on:click=move |_| {
                picked.set(Some(label.clone()));
                set(Some(t1.clone()))
            }
            on:keydown=move |ev: web_sys::KeyboardEvent| {
                if ev.key() == "Enter" || ev.key() == " " {
                    ev.prevent_default();
                    picked.set(Some(key_label.clone()))
                }
            }
            on:mouseenter=move |_| set(Some(t2.clone()))
            on:focus=move |_| set(Some(t3.clone()))
            on:mouseleave=move |_| set(None)
            on:blur=move |_| set(None)
        >
            <line x1=x x2=x y1=STRIP_Y - 4.0 y2=STRIP_Y + STRIP_H + 4.0 stroke="#1d2329" stroke-width="2" />
            // A wider invisible target carries the tooltip, so it is easy to hover. (The <title>
            // must be an only child: leptos's view! makes an ambiguous <title> among siblings
            // an HTML element, which browsers do not show as an SVG tooltip.)
            <rect class="hover" x=x - 5.0 y=0 width=10 height=STRIP_H + 2.0 * STRIP_Y fill="transparent">
                <title>{tick.label.clone()}</title>
            </rect>
        </g>
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::palette::{GREEN, RED};

    #[test]
    fn colours_as_css() {
        assert_eq!(css(GREEN), "rgb(46, 158, 74)");
        assert_eq!(css(RED), "rgb(212, 59, 59)");
    }
}
