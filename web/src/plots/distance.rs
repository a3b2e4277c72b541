//! Least cable–cable and cable–obstacle distance along a path (sampled point-wise by the core),
//! with the required clearances dashed and the samples where some condition fails marked. The
//! plot says which is which: the line is sampled (a rug of ticks at the samples, not a
//! certificate); the verifier's certified boundaries (exact roots) are drawn as full-height lines.

use super::geom::{extent, polyline, ticks, Scale};
use super::Chart;
use crate::logic::fmt_num;
use cablenav::verify::profile::ClearanceProfile;
use leptos::prelude::*;

/// Plot size and plotting box.
pub const W: f64 = 900.0;
/// Plot height.
pub const H: f64 = 240.0;
const LEFT: f64 = 52.0;
const RIGHT: f64 = 12.0;
const TOP: f64 = 12.0;
const BOTTOM: f64 = 40.0;

/// Cable–cable line colour.
pub const CC: &str = "#3b6fd8";
/// Cable–obstacle line colour.
pub const CO: &str = "#e6911e";

/// The plot's geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct DistanceModel {
    /// Cable–cable line.
    pub cable_cable: String,
    /// Cable–obstacle line.
    pub cable_obstacle: String,
    /// y of the cable–cable and cable–obstacle clearances.
    pub clearance_y: [f64; 2],
    /// y ticks (y, label).
    pub y_ticks: Vec<(f64, String)>,
    /// x ticks (x, label).
    pub x_ticks: Vec<(f64, String)>,
    /// Per sample: x, and its tooltip (t, both distances with what they are between, violations).
    pub samples: Vec<(f64, String)>,
    /// x of the samples where some condition is violated.
    pub violated_x: Vec<f64>,
    /// Conditions known by membership only (no distance drawn).
    pub membership_only: Vec<String>,
    /// The certified boundaries on the plot: x and tooltip.
    pub certified: Vec<(f64, String)>,
    /// Whether any sample has a cable–obstacle distance (else that line, its clearance and its
    /// legend are left out).
    pub obstacles: bool,
}

/// Builds the plot of a profile, with the verifier's certified boundaries `certified` (the
/// parameter and a tooltip each) on the same axis.
pub fn model(p: &ClearanceProfile, certified: &[(f64, String)]) -> DistanceModel {
    let ts: Vec<f64> = p.samples.iter().map(|s| s.t).collect();
    let x = Scale::new(ts.first().copied().unwrap_or(0.0), ts.last().copied().unwrap_or(1.0), LEFT, W - RIGHT);
    let obstacles = p.samples.iter().any(|s| s.cable_obstacle.is_some());
    let values = p
        .samples
        .iter()
        .flat_map(|s| [s.cable_cable.as_ref(), s.cable_obstacle.as_ref()])
        .flatten()
        .map(|c| c.distance)
        .chain([0.0, p.clearance_cable_cable])
        .chain(obstacles.then_some(p.clearance_cable_obstacle));
    let [y0, y1] = extent(values, 0.05).unwrap_or([0.0, 1.0]);
    let y = Scale::new(y0, y1, H - BOTTOM, TOP);
    let line = |pick: fn(&cablenav::verify::profile::ClearanceSample) -> Option<f64>| {
        polyline(&p.samples.iter().map(|s| pick(s).map(|d| (x.at(s.t), y.at(d)))).collect::<Vec<_>>())
    };
    let describe = |c: &Option<cablenav::verify::profile::Closest>| {
        c.as_ref().map_or("—".to_string(), |c| format!("{} ({})", fmt_num(c.distance), c.between))
    };
    DistanceModel {
        cable_cable: line(|s| s.cable_cable.as_ref().map(|c| c.distance)),
        cable_obstacle: line(|s| s.cable_obstacle.as_ref().map(|c| c.distance)),
        clearance_y: [y.at(p.clearance_cable_cable), y.at(p.clearance_cable_obstacle)],
        y_ticks: ticks(y0, y1, 5).into_iter().map(|v| (y.at(v), fmt_num(v))).collect(),
        x_ticks: ticks(x.d0, x.d1, 5).into_iter().map(|v| (x.at(v), fmt_num(v))).collect(),
        samples: p
            .samples
            .iter()
            .map(|s| {
                let mut tip = format!(
                    "t = {}: cable–cable {}, cable–obstacle {}",
                    fmt_num(s.t),
                    describe(&s.cable_cable),
                    describe(&s.cable_obstacle)
                );
                if !s.violated.is_empty() {
                    tip += &format!("; violated: {}", s.violated.join(", "));
                }
                (x.at(s.t), tip)
            })
            .collect(),
        violated_x: p.samples.iter().filter(|s| !s.violated.is_empty()).map(|s| x.at(s.t)).collect(),
        membership_only: p.membership_only.clone(),
        certified: certified.iter().filter(|(t, _)| *t >= x.d0 && *t <= x.d1).map(|(t, tip)| (x.at(*t), tip.clone())).collect(),
        obstacles,
    }
}

/// The distance plot, or why there is none.
#[component]
pub fn DistancePlot(profile: Signal<Option<Result<ClearanceProfile, String>>>, label: Signal<String>, certified: Signal<Vec<(f64, String)>>) -> impl IntoView {
    move || match profile.get() {
        None => view! { <p class="empty">"No path to plot."</p> }.into_any(),
        Some(Err(e)) => view! { <p class="error">{format!("Clearances: {e}")}</p> }.into_any(),
        Some(Ok(p)) => {
            let m = model(&p, &certified.get());
            let n = p.samples.len();
            let step = if n > 1 { (W - LEFT - RIGHT) / (n - 1) as f64 } else { 8.0 };
            let title = format!(
                "Least distances (m) along {}: sampled at {} points (grey rug; a sampled line is not a certificate); clearances dashed; red marks: a condition fails at a sample; dark lines: the verifier's certified boundaries (exact roots)",
                label.get(),
                n
            );
            view! {
                <Chart id="distance" title width=W height=H>
                    <rect x=LEFT y=TOP width=W - LEFT - RIGHT height=H - TOP - BOTTOM fill="none" stroke="#d8dde2" />
                    {m.y_ticks.iter().map(|(y, l)| view! {
                        <text x=LEFT - 5.0 y=y + 4.0 font-size="11" text-anchor="end" fill="#5b6670">{l.clone()}</text>
                        <line x1=LEFT x2=W - RIGHT y1=*y y2=*y stroke="#eef1f4" />
                    }).collect_view()}
                    {m.x_ticks.iter().map(|(x, l)| view! {
                        <text x=*x y=H - BOTTOM + 16.0 font-size="11" text-anchor="middle" fill="#5b6670">{l.clone()}</text>
                    }).collect_view()}
                    <line x1=LEFT x2=W - RIGHT y1=m.clearance_y[0] y2=m.clearance_y[0] stroke=CC stroke-dasharray="5 4" />
                    {m.obstacles.then(|| view! { <line x1=LEFT x2=W - RIGHT y1=m.clearance_y[1] y2=m.clearance_y[1] stroke=CO stroke-dasharray="5 4" /> })}
                    <path d=m.cable_cable.clone() fill="none" stroke=CC stroke-width="1.8" stroke-linecap="round" data-testid="distance-cc" />
                    <path d=m.cable_obstacle.clone() fill="none" stroke=CO stroke-width="1.8" stroke-linecap="round" data-testid="distance-co" />
                    {m.samples.iter().map(|(x, _)| view! {
                        <line x1=*x x2=*x y1=TOP y2=TOP + 4.0 stroke="#9aa3ab" stroke-width="1" data-testid="distance-sample" />
                    }).collect_view()}
                    {m.certified.iter().map(|(x, tip)| view! {
                        <g data-testid="distance-certified">
                            <line x1=*x x2=*x y1=TOP y2=H - BOTTOM stroke="#1d2329" stroke-width="1.5" />
                            <rect x=x - 4.0 y=TOP width="8" height=H - TOP - BOTTOM fill="transparent"><title>{format!("certified boundary: {tip}")}</title></rect>
                        </g>
                    }).collect_view()}
                    {m.violated_x.iter().map(|x| view! {
                        <line x1=*x x2=*x y1=H - BOTTOM - 6.0 y2=H - BOTTOM stroke="#d43b3b" stroke-width="2" />
                    }).collect_view()}
                    {m.samples.iter().map(|(x, tip)| view! {
                        <rect x=x - step / 2.0 y=TOP width=step height=H - TOP - BOTTOM fill="transparent"><title>{tip.clone()}</title></rect>
                    }).collect_view()}
                    <text x=LEFT y=H - 6.0 font-size="11" fill=CC>"— cable–cable"</text>
                    <text x=LEFT + 380.0 y=H - 6.0 font-size="11" fill="#1d2329">"| certified boundary   "<tspan fill="#9aa3ab">"ˈ sample"</tspan></text>
                    {m.obstacles.then(|| view! { <text x=LEFT + 120.0 y=H - 6.0 font-size="11" fill=CO>"— cable–obstacle (to the surface)"</text> })}
                    <text x=W - RIGHT y=H - 6.0 font-size="11" text-anchor="end" fill="#5b6670">{label.get()}</text>
                </Chart>
                {(!m.membership_only.is_empty()).then(|| view! {
                    <p class="note">{format!("Decided by membership only (no distance drawn; failures marked): {}", m.membership_only.join(", "))}</p>
                })}
            }
            .into_any()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cablenav::verify::profile::{ClearanceSample, Closest};

    fn sample(t: f64, cc: Option<f64>, co: Option<f64>, violated: &[&str]) -> ClearanceSample {
        ClearanceSample {
            t,
            cable_cable: cc.map(|d| Closest { distance: d, between: "cables 1-2".into() }),
            cable_obstacle: co.map(|d| Closest { distance: d, between: "cable 3 - crown".into() }),
            violated: violated.iter().map(|s| s.to_string()).collect(),
        }
    }

    #[test]
    fn lines_tooltips_and_violations() {
        let p = ClearanceProfile {
            samples: vec![sample(0.0, Some(0.5), Some(-0.1), &["cable 3 - crown"]), sample(0.5, Some(0.3), None, &[]), sample(1.0, Some(0.4), Some(0.6), &[])],
            clearance_cable_cable: 0.1,
            clearance_cable_obstacle: 0.2,
            membership_only: vec!["cable 1 - cone".into()],
        };
        let m = model(&p, &[(0.5, "t = 0.5: cable 3 - crown".into()), (2.0, "off the axis".into())]);
        assert_eq!(m.certified, [((LEFT + W - RIGHT) / 2.0, "t = 0.5: cable 3 - crown".to_string())], "inside the axis only");
        assert_eq!(m.cable_cable.matches('M').count(), 1);
        assert_eq!(m.cable_obstacle.matches('M').count(), 2, "a gap where no obstacle distance is known");
        assert_eq!(m.violated_x, [LEFT]);
        assert_eq!(m.samples[0].1, "t = 0: cable–cable 0.5 (cables 1-2), cable–obstacle -0.1 (cable 3 - crown); violated: cable 3 - crown");
        assert_eq!(m.samples[1].1, "t = 0.5: cable–cable 0.3 (cables 1-2), cable–obstacle —");
        assert_eq!(m.samples[2].0, W - RIGHT);
        // the y range holds 0, the clearances and every distance; larger distances are higher
        assert!(m.clearance_y[0] > m.clearance_y[1]);
        assert!(m.y_ticks.iter().all(|(y, _)| *y >= TOP - 1e-9 && *y <= H - BOTTOM + 1e-9));
        assert!(m.obstacles);
        let bare = ClearanceProfile { samples: vec![sample(0.0, Some(0.5), None, &[])], membership_only: vec![], ..p };
        assert!(!model(&bare, &[]).obstacles);
    }
}
