//! Playback along the followed path: which path is followed, Play/Pause (a pass in 6 s, by
//! animation frames), the scrubber and the shown pose's readout.

use crate::state::{Follow, Planned, Shared};
use crate::logic::fmt_num;
use leptos::prelude::*;

/// The scrubber row: `follow` chooses the path (the planned one once there is one), `playing`
/// runs `scrub` from where it is to the end, and `readout` names the shown pose.
#[component]
pub fn Scrubber(
    scrub: RwSignal<f64>,
    follow: RwSignal<Follow>,
    playing: RwSignal<bool>,
    planned: RwSignal<Option<Shared<Planned>>>,
    readout: Signal<Option<String>>,
) -> impl IntoView {
    // play: advance the scrubber by animation frames, a pass in 6 s
    let step_play = move |prev: f64| {
        fn frame(prev: f64, scrub: RwSignal<f64>, playing: RwSignal<bool>) {
            request_animation_frame(move || {
                if !playing.get_untracked() {
                    return;
                }
                let now = web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now());
                let dt = if prev > 0.0 { (now - prev) / 6000.0 } else { 0.0 };
                let next = scrub.get_untracked() + dt;
                if next >= 1.0 {
                    scrub.set(1.0);
                    playing.set(false);
                } else {
                    scrub.set(next);
                    frame(now, scrub, playing);
                }
            });
        }
        frame(prev, scrub, playing);
    };
    let toggle_play = move |_| {
        if playing.get_untracked() {
            playing.set(false);
        } else {
            if scrub.get_untracked() >= 1.0 {
                scrub.set(0.0);
            }
            playing.set(true);
            step_play(0.0);
        }
    };

    let follow_label = move || match follow.get() {
        Follow::Trajectory => "trajectory",
        Follow::Planned => "planned path",
    };

    view! {
    <div class="scrubber">
        <label>
            "Follow "
            <select data-testid="follow" on:change=move |ev| {
                follow.set(if event_target_value(&ev) == "planned" { Follow::Planned } else { Follow::Trajectory });
                scrub.set(0.0);
            }>
                <option value="trajectory" selected=move || follow.get() == Follow::Trajectory>"trajectory"</option>
                <option value="planned" selected=move || follow.get() == Follow::Planned disabled=move || planned.get().is_none()>
                    "planned path"
                </option>
            </select>
        </label>
        <button data-testid="play" on:click=toggle_play>{move || if playing.get() { "Pause" } else { "Play" }}</button>
        <input
            data-testid="scrubber"
            type="range"
            min="0"
            max="1000"
            step="1"
            aria-label=move || format!("position along the {}", follow_label())
            prop:value=move || (scrub.get() * 1000.0).round().to_string()
            on:input=move |ev| {
                if let Ok(v) = event_target_value(&ev).parse::<f64>() {
                    playing.set(false);
                    scrub.set(v / 1000.0)
                }
            }
        />
        <span class="readout" data-testid="pose-readout">{move || format!("{} = {} · {}", if follow.get() == Follow::Trajectory { "t" } else { "fraction" }, fmt_num(scrub.get()), readout.get().unwrap_or_default())}</span>
    </div>
    }
}
