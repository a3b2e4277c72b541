//! The tension envelope along a path (Bohigas et al. Fig. 6, bottom): one small panel per cable
//! with its least–greatest tension band over the wrench set and its bounds drawn dashed.

use super::geom::{band, extent, polyline, ticks, Scale};
use super::Chart;
use crate::logic::fmt_num;
use cablenav::report::TensionEnvelope;
use leptos::prelude::*;

/// One cable's panel, in panel pixels (see [`PANEL_W`], [`PANEL_H`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// Cable number, from 1.
    pub cable: usize,
    /// The band's path data.
    pub band: String,
    /// The least tension's line.
    pub min_line: String,
    /// The greatest tension's line.
    pub max_line: String,
    /// y of the lower and upper tension bound.
    pub bounds_y: [f64; 2],
    /// The bounds' values.
    pub bounds: [f64; 2],
    /// y ticks: (y, label).
    pub y_ticks: Vec<(f64, String)>,
    /// Whether some sample leaves the bounds.
    pub violated: bool,
}

/// Panel size in pixels, and its plotting box inside.
pub const PANEL_W: f64 = 300.0;
/// Panel height.
pub const PANEL_H: f64 = 150.0;
const LEFT: f64 = 44.0;
const RIGHT: f64 = 8.0;
const TOP: f64 = 18.0;
const BOTTOM: f64 = 20.0;

/// The x scale of a panel (t ∈ [0, 1]).
pub fn x_scale() -> Scale {
    Scale::new(0.0, 1.0, LEFT, PANEL_W - RIGHT)
}

/// The panels of an envelope, one per cable; each y range holds the bounds and the data.
pub fn panels(env: &TensionEnvelope) -> Vec<Panel> {
    let xs: Vec<f64> = env.t.iter().map(|&t| x_scale().at(t)).collect();
    env.bounds
        .iter()
        .enumerate()
        .map(|(i, &[lo, hi])| {
            let mins: Vec<Option<f64>> = env.tension_min.iter().map(|m| m.as_ref().and_then(|v| v.get(i).copied())).collect();
            let maxs: Vec<Option<f64>> = env.tension_max.iter().map(|m| m.as_ref().and_then(|v| v.get(i).copied())).collect();
            let values = mins.iter().chain(&maxs).flatten().copied().chain([lo, hi]);
            let [y0, y1] = extent(values, 0.08).unwrap_or([0.0, 1.0]);
            let y = Scale::new(y0, y1, PANEL_H - BOTTOM, TOP);
            let line = |v: &[Option<f64>]| polyline(&xs.iter().zip(v).map(|(x, v)| v.map(|v| (*x, y.at(v)))).collect::<Vec<_>>());
            let ys = |v: &[Option<f64>]| v.iter().map(|v| v.map(|v| y.at(v))).collect::<Vec<_>>();
            let violated = mins.iter().flatten().any(|&m| m < lo) || maxs.iter().flatten().any(|&m| m > hi);
            Panel {
                cable: i + 1,
                band: band(&xs, &ys(&mins), &ys(&maxs)),
                min_line: line(&mins),
                max_line: line(&maxs),
                bounds_y: [y.at(lo), y.at(hi)],
                bounds: [lo, hi],
                y_ticks: ticks(y0, y1, 4).into_iter().map(|v| (y.at(v), fmt_num(v))).collect(),
                violated,
            }
        })
        .collect()
}

/// The x axis' tick label at t: t, or for a timed trajectory of `duration` the time it is reached.
pub fn x_label(t: f64, duration: Option<f64>) -> String {
    match duration {
        Some(d) => format!("{} s", fmt_num(t * d)),
        None => fmt_num(t),
    }
}

/// The envelope plot, or why there is none; `param` names the x axis, which is in seconds along a
/// timed trajectory (`duration`; its tensions then include the platform's inertia).
#[component]
pub fn TensionPlot(envelope: Signal<Option<Result<TensionEnvelope, String>>>, param: Signal<&'static str>, duration: Signal<Option<f64>>) -> impl IntoView {
    move || match envelope.get() {
        None => view! { <p class="empty">"No path to plot."</p> }.into_any(),
        Some(Err(e)) => view! { <p class="empty" data-testid="tension-none">{format!("No tension envelope: {e}")}</p> }.into_any(),
        Some(Ok(env)) => {
            let ps = panels(&env);
            let cols = 3usize;
            let rows = ps.len().div_ceil(cols);
            let w = PANEL_W * cols as f64;
            let h = PANEL_H * rows as f64 + 14.0;
            let x = x_scale();
            view! {
                <Chart id="tension" title=format!("Tension envelope along {} (min–max over the wrench set; bounds dashed)", env.trajectory) width=w height=h>
                    {ps
                        .into_iter()
                        .enumerate()
                        .map(|(k, p)| {
                            let (ox, oy) = ((k % cols) as f64 * PANEL_W, (k / cols) as f64 * PANEL_H);
                            view! {
                                <g transform=format!("translate({ox} {oy})") data-testid="tension-panel" data-cable=p.cable data-violated=p.violated.to_string()>
                                    <text x=LEFT y=12 font-size="12" fill="#1d2329">{format!("cable {}", p.cable)}</text>
                                    <rect x=LEFT y=TOP width=PANEL_W - LEFT - RIGHT height=PANEL_H - TOP - BOTTOM fill="none" stroke="#d8dde2" />
                                    {p.y_ticks.iter().map(|(y, l)| view! {
                                        <text x=LEFT - 4.0 y=y + 4.0 font-size="10" text-anchor="end" fill="#5b6670">{l.clone()}</text>
                                    }).collect_view()}
                                    {[0.0, 0.5, 1.0].map(|t| view! {
                                        <text x=x.at(t) y=PANEL_H - 6.0 font-size="10" text-anchor="middle" fill="#5b6670" data-testid="tension-tick">{x_label(t, duration.get())}</text>
                                    })}
                                    <path d=p.band.clone() fill="#3b6fd8" fill-opacity="0.25" stroke="none" />
                                    <path d=p.min_line.clone() fill="none" stroke="#3b6fd8" stroke-width="1.2" />
                                    <path d=p.max_line.clone() fill="none" stroke="#3b6fd8" stroke-width="1.2" />
                                    {p.bounds_y.iter().zip(p.bounds).map(|(y, b)| view! {
                                        <line x1=LEFT x2=PANEL_W - RIGHT y1=*y y2=*y stroke="#d43b3b" stroke-dasharray="4 3">
                                            <title>{format!("bound {}", fmt_num(b))}</title>
                                        </line>
                                    }).collect_view()}
                                </g>
                            }
                        })
                        .collect_view()}
                    <text x=w / 2.0 y=h - 2.0 font-size="11" text-anchor="middle" fill="#5b6670" data-testid="tension-axis">
                        {match duration.get() {
                            Some(d) => format!("time (s; {} = t·{} s, with the platform's inertia)", param.get(), fmt_num(d)),
                            None => param.get().to_string(),
                        }}
                    </text>
                </Chart>
            }
            .into_any()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env() -> TensionEnvelope {
        TensionEnvelope {
            trajectory: "x".into(),
            t: vec![0.0, 0.5, 1.0],
            tension_min: vec![Some(vec![0.2, -0.1]), None, Some(vec![0.3, 0.1])],
            tension_max: vec![Some(vec![0.6, 0.4]), None, Some(vec![0.7, 1.2])],
            bounds: vec![[0.0, 1.0], [0.0, 1.0]],
        }
    }

    #[test]
    fn one_panel_per_cable_with_gaps_at_singular_samples() {
        let ps = panels(&env());
        assert_eq!(ps.len(), 2);
        assert_eq!(ps[0].cable, 1);
        // the singular middle sample splits the band into two lone-sample pieces
        assert_eq!(ps[0].band.matches('Z').count(), 2);
        assert_eq!(ps[0].min_line.matches('M').count(), 2);
        assert!(!ps[0].violated);
        assert!(ps[1].violated, "cable 2 leaves [0, 1] on both sides");
    }

    #[test]
    fn bounds_are_inside_the_panel_and_ordered() {
        for p in panels(&env()) {
            let [lo, hi] = p.bounds_y;
            assert!(lo > hi, "the upper bound is drawn higher (smaller y)");
            assert!(hi >= TOP && lo <= PANEL_H - BOTTOM);
            assert!(!p.y_ticks.is_empty());
        }
        let x = x_scale();
        assert_eq!((x.at(0.0), x.at(1.0)), (LEFT, PANEL_W - RIGHT));
    }
}
