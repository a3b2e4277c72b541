//! The fastest safe timing against time (`cablenav time`, docs/timing.md): the platform's speed,
//! each cable's tension with the bounds dashed, and above them the constraint that binds, stretch
//! by stretch, as coloured bands named on hover.

use super::geom::{extent, polyline, ticks, Scale};
use super::Chart;
use crate::logic::fmt_num;
use cablenav::report::TimingReport;
use leptos::prelude::*;

/// Plot width and the heights of its parts, in pixels.
pub const WIDTH: f64 = 900.0;
const LEFT: f64 = 56.0;
const RIGHT: f64 = 12.0;
const BANDS_TOP: f64 = 6.0;
const BANDS_H: f64 = 16.0;
const PANEL_H: f64 = 150.0;
const GAP: f64 = 26.0;
/// The whole plot's height.
pub const HEIGHT: f64 = BANDS_TOP + BANDS_H + 8.0 + 2.0 * PANEL_H + GAP + 28.0;

/// Colours of the binding stretches, by constraint (in order of first appearance).
const BAND_COLOURS: [&str; 8] = ["#3b6fd8", "#e0912a", "#2f9e6b", "#b23bd4", "#d43b3b", "#5b6670", "#1aa3b5", "#9c7a2b"];
/// Colours of the cables' tension lines.
const CABLE_COLOURS: [&str; 8] = ["#3b6fd8", "#e0912a", "#2f9e6b", "#b23bd4", "#d43b3b", "#1aa3b5", "#9c7a2b", "#5b6670"];

/// One binding stretch as drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    /// Its x extent.
    pub x: [f64; 2],
    /// Its colour.
    pub colour: &'static str,
    /// The constraint.
    pub label: String,
    /// Its time span, for the tooltip.
    pub seconds: [f64; 2],
}

/// A panel: its top, its line(s), y ticks and dashed bounds.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// Its top y.
    pub top: f64,
    /// (colour, path data) per line.
    pub lines: Vec<(&'static str, String)>,
    /// (y, label) ticks.
    pub y_ticks: Vec<(f64, String)>,
    /// (y, value) of dashed bounds.
    pub bounds: Vec<(f64, f64)>,
    /// Its axis title.
    pub title: &'static str,
}

/// Everything the plot draws, in pixels.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// The binding stretches.
    pub bands: Vec<Band>,
    /// Speed, then tensions.
    pub panels: Vec<Panel>,
    /// (x, label) ticks of the time axis.
    pub x_ticks: Vec<(f64, String)>,
}

/// The plot of `report`, the cables' tension bounds `bounds` ([min, max] each).
pub fn layout(report: &TimingReport, bounds: &[[f64; 2]]) -> Layout {
    let end = report.profile.last().map_or(1.0, |p| p.time);
    let x = Scale::new(0.0, end, LEFT, WIDTH - RIGHT);
    let mut names: Vec<&str> = Vec::new();
    let bands = report
        .binding
        .iter()
        .map(|b| {
            let k = names.iter().position(|n| *n == b.constraint).unwrap_or_else(|| {
                names.push(&b.constraint);
                names.len() - 1
            });
            Band { x: [x.at(b.seconds[0]), x.at(b.seconds[1])], colour: BAND_COLOURS[k % BAND_COLOURS.len()], label: b.constraint.clone(), seconds: b.seconds }
        })
        .collect();
    let xs: Vec<f64> = report.profile.iter().map(|p| x.at(p.time)).collect();
    let panel = |top: f64, series: Vec<(&'static str, Vec<f64>)>, limits: Vec<f64>, title| {
        let [y0, y1] = extent(series.iter().flat_map(|(_, v)| v.iter().copied()).chain(limits.iter().copied()), 0.08).unwrap_or([0.0, 1.0]);
        let y = Scale::new(y0, y1, top + PANEL_H, top);
        Panel {
            top,
            lines: series.into_iter().map(|(c, v)| (c, polyline(&xs.iter().zip(&v).map(|(x, v)| Some((*x, y.at(*v)))).collect::<Vec<_>>()))).collect(),
            y_ticks: ticks(y0, y1, 4).into_iter().map(|v| (y.at(v), fmt_num(v))).collect(),
            bounds: limits.into_iter().map(|v| (y.at(v), v)).collect(),
            title,
        }
    };
    let top = BANDS_TOP + BANDS_H + 8.0;
    let speed = panel(top, vec![("#1d2329", report.profile.iter().map(|p| p.speed).collect())], vec![], "speed (m/s)");
    let cables = report.profile.iter().map(|p| p.tensions.len()).max().unwrap_or(0);
    let tensions: Vec<(&'static str, Vec<f64>)> = (0..cables)
        .map(|i| (CABLE_COLOURS[i % CABLE_COLOURS.len()], report.profile.iter().map(|p| p.tensions.get(i).copied().unwrap_or(f64::NAN)).collect()))
        .collect();
    let limits: Vec<f64> = {
        let lo = bounds.iter().map(|b| b[0]).fold(f64::INFINITY, f64::min);
        let hi = bounds.iter().map(|b| b[1]).filter(|v| v.is_finite()).fold(f64::NEG_INFINITY, f64::max);
        [lo, hi].into_iter().filter(|v| v.is_finite()).collect()
    };
    let mut panels = vec![speed];
    if cables > 0 {
        panels.push(panel(top + PANEL_H + GAP, tensions, limits, "tension"));
    }
    let x_ticks = ticks(0.0, end, 8).into_iter().map(|t| (x.at(t), fmt_num(t))).collect();
    Layout { bands, panels, x_ticks }
}

/// The plot of a timing report.
#[component]
pub fn TimingChart(report: TimingReport, bounds: Vec<[f64; 2]>) -> impl IntoView {
    let l = layout(&report, &bounds);
    let bottom = HEIGHT - 6.0;
    view! {
        <Chart id="fastest" title=format!("Fastest safe timing of {}: speed and tensions against time; above, the constraint that binds", report.trajectory) width=WIDTH height=HEIGHT>
            {l.bands.iter().map(|b| view! {
                <rect x=b.x[0] y=BANDS_TOP width=(b.x[1] - b.x[0]).max(0.5) height=BANDS_H fill=b.colour data-testid="binding-band">
                    <title>{format!("{} – {} s: {}", fmt_num(b.seconds[0]), fmt_num(b.seconds[1]), b.label)}</title>
                </rect>
            }).collect_view()}
            {l.panels.iter().map(|p| view! {
                <g data-testid="fastest-panel">
                    <rect x=LEFT y=p.top width=WIDTH - LEFT - RIGHT height=PANEL_H fill="none" stroke="#d8dde2" />
                    <text x=8 y=p.top + PANEL_H / 2.0 font-size="11" fill="#5b6670" transform=format!("rotate(-90 8 {})", p.top + PANEL_H / 2.0) text-anchor="middle" dominant-baseline="hanging">{p.title}</text>
                    {p.y_ticks.iter().map(|(y, t)| view! { <text x=LEFT - 4.0 y=y + 4.0 font-size="10" text-anchor="end" fill="#5b6670">{t.clone()}</text> }).collect_view()}
                    {p.bounds.iter().map(|(y, v)| view! {
                        <line x1=LEFT x2=WIDTH - RIGHT y1=*y y2=*y stroke="#d43b3b" stroke-dasharray="4 3"><title>{format!("bound {}", fmt_num(*v))}</title></line>
                    }).collect_view()}
                    {p.lines.iter().map(|(c, d)| view! { <path d=d.clone() fill="none" stroke=*c stroke-width="1.3" /> }).collect_view()}
                </g>
            }).collect_view()}
            {l.x_ticks.iter().map(|(x, t)| view! { <text x=*x y=bottom - 12.0 font-size="10" text-anchor="middle" fill="#5b6670">{t.clone()}</text> }).collect_view()}
            <text x=WIDTH / 2.0 y=bottom font-size="11" text-anchor="middle" fill="#5b6670">"time (s)"</text>
        </Chart>
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cablenav::report::{BindingStretch, ProfilePoint};

    fn report() -> TimingReport {
        let point = |t: f64, time: f64, speed: f64| ProfilePoint { t, time, rate: 0.0, speed, tensions: vec![0.2, 0.8] };
        TimingReport {
            trajectory: "x".into(),
            duration: Some(2.0),
            uncertified_duration: 2.0,
            certificate_cost: Some(0.0),
            cells: 2,
            rounds: 0,
            margin: 1e-3,
            binding: vec![
                BindingStretch { t: [0.0, 0.5], seconds: [0.0, 1.0], constraint: "cable 1 speed".into() },
                BindingStretch { t: [0.5, 1.0], seconds: [1.0, 2.0], constraint: "cable 2 max tension".into() },
            ],
            slowed: vec![],
            not_certified: vec![],
            profile: vec![point(0.0, 0.0, 0.0), point(0.5, 1.0, 1.0), point(1.0, 2.0, 0.0)],
            notes: vec![],
        }
    }

    #[test]
    fn bands_cover_the_time_axis_and_panels_hold_the_data() {
        let l = layout(&report(), &[[0.0, 1.0], [0.0, 1.0]]);
        assert_eq!(l.bands.len(), 2);
        assert_eq!(l.bands[0].x[0], LEFT);
        assert_eq!(l.bands[1].x[1], WIDTH - RIGHT);
        assert_eq!(l.bands[0].x[1], l.bands[1].x[0]);
        assert_ne!(l.bands[0].colour, l.bands[1].colour);
        assert_eq!(l.panels.len(), 2);
        assert_eq!(l.panels[1].lines.len(), 2);
        assert_eq!(l.panels[1].bounds.iter().map(|b| b.1).collect::<Vec<_>>(), vec![0.0, 1.0]);
        // the speed's peak at the top of its panel's data range, inside the panel
        let top = l.panels[0].top;
        assert!(l.panels[0].lines[0].1.split([' ', 'M', 'L']).filter_map(|v| v.parse::<f64>().ok()).all(|v| v >= 0.0));
        assert!(top > BANDS_TOP + BANDS_H);
    }
}
