//! The cross-section both the slice map and the ray lattice are drawn over: the pose the other
//! coordinates come from and two coordinates with their ranges. One set of controls for both
//! panels; each panel adds its own resolution and buttons as children.

use super::slice::{default_axes, default_pose, default_range};
use crate::logic::fmt_num;
use cablenav::model::Coord;
use cablenav::Scenario;
use leptos::prelude::*;

/// The chosen cross-section, as signals.
#[derive(Debug, Clone, Copy)]
pub struct CrossSection {
    /// The pose the other coordinates come from.
    pub pose: RwSignal<String>,
    /// The coordinates across and up.
    pub axes: RwSignal<[Coord; 2]>,
    /// Their ranges.
    pub range: RwSignal<[[f64; 2]; 2]>,
}

impl CrossSection {
    /// A cross-section of nothing yet (see [`CrossSection::reset`]).
    pub fn new() -> CrossSection {
        CrossSection { pose: RwSignal::new(String::new()), axes: RwSignal::new([Coord::X, Coord::Y]), range: RwSignal::new([[0.0, 1.0]; 2]) }
    }

    /// The scenario's defaults: the first query's start (or first pose) and the first two
    /// coordinates it leaves free, over the scene's extent (angles over [−π, π]).
    pub fn reset(&self, s: &Scenario) {
        let a = default_axes(s);
        self.pose.set(default_pose(s).unwrap_or_default());
        self.axes.set(a);
        self.range.set([default_range(s, a[0]), default_range(s, a[1])]);
    }
}

impl Default for CrossSection {
    fn default() -> Self {
        CrossSection::new()
    }
}

/// The controls of a cross-section: pose, the two axes and their ranges (test ids
/// `{prefix}-pose`, `{prefix}-axis-0`, `{prefix}-axis-1`), then `children` (the panel's own).
#[component]
pub fn SectionControls(section: CrossSection, scenario: Signal<Option<Scenario>>, prefix: &'static str, children: Children) -> impl IntoView {
    let CrossSection { pose, axes, range } = section;
    let set_axis = move |k: usize, name: String| {
        if let Some((s, c)) = scenario.get_untracked().and_then(|s| s.coord("axes", &name).ok().map(|c| (s, c))) {
            axes.update(|a| a[k] = c);
            range.update(|r| r[k] = default_range(&s, c));
        }
    };
    let set_range = move |k: usize, end: usize, text: String| {
        if let Ok(v) = text.trim().parse::<f64>() {
            range.update(|r| r[k][end] = v);
        }
    };
    let axis_select = move |k: usize| {
        view! {
            <select data-testid=format!("{prefix}-axis-{k}") on:change=move |ev| set_axis(k, event_target_value(&ev))>
                {move || scenario.get().map(|s| s.coords().into_iter().map(|c| {
                    let (value, name) = (s.coord_name(c), s.coord_name(c));
                    view! { <option value=value selected=move || axes.get()[k] == c>{name}</option> }
                }).collect_view())}
            </select>
            " from "
            <input class="num" type="number" step="any" data-testid=format!("{prefix}-from-{k}") prop:value=move || fmt_num(range.get()[k][0])
                on:change=move |ev| set_range(k, 0, event_target_value(&ev)) />
            " to "
            <input class="num" type="number" step="any" data-testid=format!("{prefix}-to-{k}") prop:value=move || fmt_num(range.get()[k][1])
                on:change=move |ev| set_range(k, 1, event_target_value(&ev)) />
        }
    };
    view! {
        <div class="slice-controls">
            <label>
                {move || if scenario.get().is_some_and(|s| s.robot.chain.is_some()) { "Other coordinates from configuration " } else { "Other coordinates from pose " }}
                <select data-testid=format!("{prefix}-pose") on:change=move |ev| pose.set(event_target_value(&ev))>
                    {move || scenario.get().map(|s| s.config_names().into_iter().map(|n| {
                        let (value, key, text) = (n.clone(), n.clone(), n);
                        view! { <option value=value selected=move || pose.get() == key>{text}</option> }
                    }).collect_view())}
                </select>
            </label>
            <label>"across " {axis_select(0)}</label>
            <label>"up " {axis_select(1)}</label>
            {children()}
        </div>
    }
}
