//! A multi-link robot's joint sliders: one slider per joint coordinate over its range, a picker to
//! start from a named configuration, and the verdict of every condition at the configuration
//! shown (the core's point check). Moving a slider shows that configuration instead of the
//! path's; the scrubber shows the path's again.

use crate::logic::fmt_num;
use crate::state::Parsed;
use cablenav::Scenario;
use leptos::prelude::*;

/// Slider steps over a coordinate's range.
const STEPS: f64 = 1000.0;
/// The half-width of a slider for an unbounded (prismatic) coordinate, in metres around 0.
const UNBOUNDED: f64 = 1.0;

/// One joint coordinate as the sliders show it.
#[derive(Debug, Clone, PartialEq)]
pub struct Slider {
    /// The coordinate's name.
    pub name: String,
    /// The slider's range: the joint's range, or ±[`UNBOUNDED`] where it has none.
    pub range: [f64; 2],
    /// "rad" or "m".
    pub unit: &'static str,
}

/// The sliders of `s`'s joint coordinates, in configuration order (none for a platform robot).
pub fn sliders(s: &Scenario) -> Vec<Slider> {
    let Some(chain) = &s.robot.chain else { return vec![] };
    chain
        .coords()
        .enumerate()
        .map(|(i, (_, _, c))| {
            let [lo, hi] = c.range;
            let range = if lo.is_finite() && hi.is_finite() { [lo, hi] } else { [lo.max(-UNBOUNDED), hi.min(UNBOUNDED)] };
            Slider { name: c.name.clone(), range, unit: if chain.is_angle(i) { "rad" } else { "m" } }
        })
        .collect()
}

/// The one-line verdict of the core's point check at `q`: feasible, or the violated conditions.
pub fn verdict(s: &Scenario, q: &[f64]) -> (bool, String) {
    let r = cablenav::verify::check_config(s, "shown", q);
    if r.feasible {
        (true, "feasible: every condition holds here".to_string())
    } else {
        (false, format!("infeasible: {}", r.violated.join(", ")))
    }
}

/// The sliders. `shown` is the configuration in the view; `set` receives a configuration picked
/// or slid to.
#[component]
pub fn JointSliders(parsed: Memo<Parsed>, shown: Memo<Option<Vec<f64>>>, set: Callback<Vec<f64>>) -> impl IntoView {
    let scenario = move || parsed.get().0.as_ref().as_ref().ok().cloned();
    let list = Memo::new(move |_| scenario().map(|s| sliders(&s)).unwrap_or_default());
    let slide = move |i: usize, v: f64| {
        if let Some(mut q) = shown.get_untracked() {
            if i < q.len() {
                q[i] = v;
                set.run(q);
            }
        }
    };
    let pick = move |name: String| {
        if let Some(q) = scenario().and_then(|s| s.config(&name).ok()) {
            set.run(q);
        }
    };
    let verdict_line = move || {
        let (s, q) = (scenario()?, shown.get()?);
        Some(verdict(&s, &q))
    };
    view! {
        <fieldset class="joint-sliders" data-testid="joint-sliders">
            <legend>"Joint coordinates (multi-link robot)"</legend>
            <label>
                "From configuration "
                <select data-testid="joint-config" on:change=move |ev| pick(event_target_value(&ev))>
                    <option value="">"(pick one)"</option>
                    {move || scenario().map(|s| s.config_names().into_iter().map(|n| { let v = n.clone(); view! { <option value=v>{n}</option> } }).collect_view())}
                </select>
            </label>
            <For each=move || list.get().into_iter().enumerate() key=|(i, s)| (*i, s.name.clone()) let:item>
                {
                    let (i, sl) = item;
                    let [lo, hi] = sl.range;
                    let value = move || shown.get().and_then(|q| q.get(i).copied()).unwrap_or(0.0);
                    view! {
                        <label class="joint" data-testid=format!("joint-{}", sl.name)>
                            <span class="joint-name">{sl.name.clone()}</span>
                            <input type="range" min="0" max=STEPS.to_string() step="1"
                                aria-label=format!("{} ({}) from {} to {}", sl.name, sl.unit, fmt_num(lo), fmt_num(hi))
                                prop:value=move || (((value() - lo) / (hi - lo)).clamp(0.0, 1.0) * STEPS).round().to_string()
                                on:input=move |ev| {
                                    if let Ok(k) = event_target_value(&ev).parse::<f64>() {
                                        slide(i, lo + (hi - lo) * k / STEPS)
                                    }
                                } />
                            <input class="num" type="number" step="any" aria-label=format!("{} value ({})", sl.name, sl.unit)
                                prop:value=move || fmt_num(value())
                                on:change=move |ev| {
                                    if let Some(v) = event_target_value(&ev).trim().parse::<f64>().ok().filter(|v| v.is_finite()) {
                                        slide(i, v)
                                    }
                                } />
                            " " {sl.unit}
                        </label>
                    }
                }
            </For>
            {move || verdict_line().map(|(ok, text)| view! {
                <p class="joint-verdict" class:ok=ok class:error=!ok data-testid="joint-verdict" data-feasible=ok.to_string()>{text}</p>
            })}
        </fieldset>
    }
}

#[cfg(test)]
// ±0.7854 is the arm's joint range as its CASPR file writes it, not an approximation of π/4
#[allow(clippy::approx_constant)]
mod tests {
    use super::*;
    use crate::presets::{find, PRESETS};

    #[test]
    fn the_arms_sliders_are_its_joint_coordinates_over_their_ranges() {
        let s = crate::logic::parse_scenario(PRESETS[find("bmarm-x4-2").unwrap()].json).unwrap();
        let sl = sliders(&s);
        assert_eq!(sl.iter().map(|x| x.name.as_str()).collect::<Vec<_>>(), ["alpha", "beta", "gamma", "theta"]);
        assert!(sl.iter().all(|x| x.unit == "rad"));
        assert_eq!(sl[0].range, [-0.7854, 0.7854]);
        let platform = crate::logic::parse_scenario(PRESETS[0].json).unwrap();
        assert!(sliders(&platform).is_empty());
    }

    #[test]
    fn the_verdict_is_the_cores_point_check() {
        let s = crate::logic::parse_scenario(PRESETS[find("bmarm-x4-2").unwrap()].json).unwrap();
        let (ok, text) = verdict(&s, &s.config("below").unwrap());
        assert!(ok, "{text}");
        // in the gap of the path across it: cables 2 and 3 closer than the clearance
        let along = cablenav::verify::all_along(&s)[0];
        let (ok, text) = verdict(&s, &along.config_at(&s, 0.5));
        assert!(!ok && text.contains("cables 2-3"), "{text}");
    }
}
