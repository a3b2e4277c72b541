//! The atlas of a 3-D slice in the slice's own space (paper 1, Fig. 7: the polytopes of the
//! charts over (z, φ, θ)): every chart's faces drawn back to front in an orthographic view that
//! the user turns by dragging (or with the two sliders), the path through them, and the box of
//! the charts with its coordinates' ranges. Each coordinate is scaled to the box's side, so metres
//! and radians share one picture. The projection is plain functions, tested natively.

use super::section::Overlay;
use super::Chart;
use crate::logic::fmt_num;
use crate::worker::protocol::WireAtlas;
use cablenav::model::{Coord, Pose};
use glam::{DMat3, DVec3};
use leptos::prelude::*;

/// The figure's width and height (SVG viewBox units).
const SIZE: f64 = 460.0;
/// Half the side of the drawn box, in viewBox units.
const HALF: f64 = 120.0;
/// Most faces drawn: past it the charts on the path are drawn and the others up to the limit
/// (the caption says how many).
const MAX_FACES: usize = 6000;

/// One face as drawn: its SVG points, its chart's state, whether the chart is on the path, and
/// its chart's index.
#[derive(Debug, Clone, PartialEq)]
pub struct DrawnFace {
    /// `x,y x,y …` in viewBox units.
    pub points: String,
    /// The chart's state.
    pub state: String,
    /// Whether the path runs through the chart.
    pub on_path: bool,
    /// The chart's index in the atlas.
    pub chart: usize,
}

/// The projected picture.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Picture {
    /// Faces, back to front.
    pub faces: Vec<DrawnFace>,
    /// Charts whose faces were left out (past [`MAX_FACES`]).
    pub charts_left_out: usize,
    /// The path as an SVG path (`M … L …`), empty without one.
    pub path: String,
    /// The box's edges as SVG paths, and the three labelled axes: (from, to, label).
    pub edges: Vec<String>,
    /// Each coordinate's axis label and where it goes.
    pub labels: Vec<(f64, f64, String)>,
}

/// The box around every chart's faces: per coordinate [lo, hi] (a zero extent widened).
fn bounds(atlas: &WireAtlas) -> [[f64; 2]; 3] {
    let mut b = [[f64::INFINITY, f64::NEG_INFINITY]; 3];
    for p in atlas.charts.iter().flat_map(|c| c.faces.iter().flatten()) {
        for k in 0..3 {
            b[k] = [b[k][0].min(p[k]), b[k][1].max(p[k])];
        }
    }
    b.map(|[lo, hi]| if !(lo.is_finite() && hi.is_finite()) { [-1.0, 1.0] } else if hi - lo < 1e-9 { [lo - 0.5, hi + 0.5] } else { [lo, hi] })
}

/// The view's rotation: `yaw` about the third coordinate's axis, then `pitch` about the screen's
/// horizontal (radians).
fn rotation(yaw: f64, pitch: f64) -> DMat3 {
    DMat3::from_rotation_x(pitch) * DMat3::from_rotation_z(yaw)
}

/// Projects `atlas` (a 3-D slice) and the `path` points (slice coordinates) for the view turned
/// by `yaw` and `pitch`: screen x right, screen y up along the third coordinate at pitch 0, depth
/// into the screen.
pub fn picture(atlas: &WireAtlas, path: &[[f64; 3]], yaw: f64, pitch: f64) -> Picture {
    let b = bounds(atlas);
    let r = rotation(yaw, pitch);
    // a slice point to the unit box [−1, 1]³, turned: (screen x, depth, screen up)
    let turn = |p: &[f64; 3]| r * DVec3::from_array(std::array::from_fn(|k| 2.0 * (p[k] - b[k][0]) / (b[k][1] - b[k][0]) - 1.0));
    let screen = |v: DVec3| (SIZE / 2.0 + HALF * v.x, SIZE / 2.0 - HALF * v.z);
    let fmt = |(x, y): (f64, f64)| format!("{x:.1},{y:.1}");
    // the charts on the path first, so that they are kept past the limit
    let mut order: Vec<usize> = (0..atlas.charts.len()).collect();
    cablenav::order::sort_by_key(&mut order, |&i| f64::from(u8::from(!atlas.charts[i].on_path)));
    let (mut faces, mut left_out) = (Vec::new(), 0);
    for i in order {
        let c = &atlas.charts[i];
        if faces.len() + c.faces.len() > MAX_FACES {
            left_out += 1;
            continue;
        }
        for f in &c.faces {
            let turned: Vec<DVec3> = f.iter().map(turn).collect();
            let depth = turned.iter().map(|v| v.y).sum::<f64>() / turned.len().max(1) as f64;
            let points = turned.iter().map(|&v| fmt(screen(v))).collect::<Vec<_>>().join(" ");
            faces.push((depth, DrawnFace { points, state: c.state.clone(), on_path: c.on_path, chart: i }));
        }
    }
    // back to front: the farthest (greatest depth) first
    cablenav::order::sort_by_key(&mut faces, |f| -f.0);
    let path = path
        .iter()
        .enumerate()
        .map(|(k, p)| format!("{}{} ", if k == 0 { "M" } else { "L" }, fmt(screen(turn(p)))))
        .collect::<String>();
    let corner = |k: usize| DVec3::new(if k & 1 == 0 { -1.0 } else { 1.0 }, if k & 2 == 0 { -1.0 } else { 1.0 }, if k & 4 == 0 { -1.0 } else { 1.0 });
    let edges = (0..8)
        .flat_map(|a| [1, 2, 4].into_iter().filter(move |bit| a & bit == 0).map(move |bit| (a, a | bit)))
        .map(|(a, b)| format!("M{} L{}", fmt(screen(r * corner(a))), fmt(screen(r * corner(b)))))
        .collect();
    let labels = (0..3)
        .map(|k| {
            let mut v = DVec3::splat(-1.0);
            v[k] = 1.15;
            let (x, y) = screen(r * v);
            (x, y, format!("{} [{}, {}]", atlas.coords[k], fmt_num(b[k][0]), fmt_num(b[k][1])))
        })
        .collect();
    Picture { faces: faces.into_iter().map(|(_, f)| f).collect(), charts_left_out: left_out, path, edges, labels }
}

/// The path's poses in the slice's coordinates (angles wrapped to (−π, π], as the charts'
/// centres are).
fn path_points(overlay: &Overlay, coords: &[Coord]) -> Vec<[f64; 3]> {
    let Some(piece) = overlay.pieces.first() else { return vec![] };
    let at = |p: &Pose| {
        let c = p.coords();
        std::array::from_fn(|k| {
            let v = c[coords[k].index()];
            if coords[k].is_angle() { cablenav::model::pose::wrap_angle(v) } else { v }
        })
    };
    piece.poses.iter().map(at).collect()
}

/// Fill of a face by its chart's state (as the slice map's polygons).
fn fill(state: &str) -> &'static str {
    match state {
        "expanded" => "#8a8f98",
        "open" => "#c9ccd2",
        _ => "#e6b0a8",
    }
}

/// The 3-D slice's atlas, when the overlay has one.
#[component]
pub fn AtlasSpace(overlay: Signal<Overlay>) -> impl IntoView {
    let yaw = RwSignal::new(-0.6f64);
    let pitch = RwSignal::new(-0.35f64);
    let drag = StoredValue::new(None::<(f64, f64)>);
    let atlas = Memo::new(move |_| overlay.with(|o| o.atlas.clone().filter(|a| a.coords.len() == 3)));
    let coords = move || atlas.with(|a| a.as_ref().map(|a| a.coords.iter().filter_map(|n| Coord::ALL.into_iter().find(|c| c.name() == n)).collect::<Vec<_>>()));
    let picture = Memo::new(move |_| {
        let a = atlas.get()?;
        let coords = coords().filter(|c| c.len() == 3)?;
        let path = overlay.with(|o| path_points(o, &coords));
        Some(picture(&a, &path, yaw.get(), pitch.get()))
    });
    let down = move |ev: leptos::ev::PointerEvent| drag.set_value(Some((ev.client_x() as f64, ev.client_y() as f64)));
    let up = move |_| drag.set_value(None);
    let moved = move |ev: leptos::ev::PointerEvent| {
        if let Some((x0, y0)) = drag.get_value() {
            let (x, y) = (ev.client_x() as f64, ev.client_y() as f64);
            yaw.update(|v| *v += (x - x0) * 0.01);
            pitch.update(|v| *v = (*v + (y - y0) * 0.01).clamp(-1.5, 1.5));
            drag.set_value(Some((x, y)));
        }
    };
    let slider = move |label: &'static str, id: &'static str, value: RwSignal<f64>, lo: f64, hi: f64| {
        view! {
            <label>
                {label}
                <input type="range" data-testid=id min=lo max=hi step="0.01" prop:value=move || value.get().to_string()
                    on:input=move |ev| {
                        if let Ok(v) = event_target_value(&ev).parse::<f64>() {
                            value.set(v)
                        }
                    } />
            </label>
        }
    };
    move || {
        let p = picture.get()?;
        let shown = p.faces.iter().map(|f| f.chart).collect::<std::collections::BTreeSet<_>>().len();
        let total = atlas.with(|a| a.as_ref().map_or(0, |a| a.charts.len()));
        let title = format!(
            "The atlas in its 3-D slice (paper 1, Fig. 7): {total} chart(s){}; drag to turn",
            if p.charts_left_out > 0 { format!(", {shown} drawn ({} left out past {MAX_FACES} faces)", p.charts_left_out) } else { String::new() }
        );
        Some(view! {
            <div class="atlas-space" on:pointerdown=down on:pointerup=up on:pointerleave=up on:pointermove=moved style="touch-action: none">
                <Chart id="atlas-space" title width=SIZE height=SIZE>
                    {p.edges.iter().map(|d| view! { <path d=d.clone() fill="none" stroke="#b0b4bb" stroke-width="0.8" /> }).collect_view()}
                    {p.faces.iter().map(|f| view! {
                        <polygon data-testid="atlas-face" data-chart=f.chart.to_string() data-state=f.state.clone() data-on-path=f.on_path.to_string()
                            points=f.points.clone() fill=fill(&f.state) fill-opacity="0.55"
                            stroke=if f.on_path { "#6b3bd4" } else { "#4a4f57" } stroke-width=if f.on_path { "1.2" } else { "0.4" } />
                    }).collect_view()}
                    {(!p.path.is_empty()).then(|| view! { <path data-testid="atlas-path" d=p.path.clone() fill="none" stroke="#6b3bd4" stroke-width="2.2" /> })}
                    {p.labels.iter().map(|(x, y, t)| view! { <text x=format!("{x:.1}") y=format!("{y:.1}") font-size="11" text-anchor="middle">{t.clone()}</text> }).collect_view()}
                </Chart>
            </div>
            <p class="legend">
                {slider("turn ", "atlas-yaw", yaw, -std::f64::consts::PI, std::f64::consts::PI)}
                {slider(" tilt ", "atlas-pitch", pitch, -1.5, 1.5)}
                " · faces of each chart's polytope, darker where expanded, outlined in purple along the path; the purple line is the path"
            </p>
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::worker::protocol::WireChart;

    /// A unit cube's six faces around `c`.
    fn cube(c: [f64; 3], on_path: bool) -> WireChart {
        let v = |dx: f64, dy: f64, dz: f64| [c[0] + dx, c[1] + dy, c[2] + dz];
        let faces = vec![
            vec![v(0., 0., 0.), v(1., 0., 0.), v(1., 1., 0.), v(0., 1., 0.)],
            vec![v(0., 0., 1.), v(1., 0., 1.), v(1., 1., 1.), v(0., 1., 1.)],
            vec![v(0., 0., 0.), v(1., 0., 0.), v(1., 0., 1.), v(0., 0., 1.)],
            vec![v(0., 1., 0.), v(1., 1., 0.), v(1., 1., 1.), v(0., 1., 1.)],
            vec![v(0., 0., 0.), v(0., 1., 0.), v(0., 1., 1.), v(0., 0., 1.)],
            vec![v(1., 0., 0.), v(1., 1., 0.), v(1., 1., 1.), v(1., 0., 1.)],
        ];
        WireChart { centre: vec![c[0] + 0.5, c[1] + 0.5, c[2] + 0.5], polygon: vec![], faces, state: "expanded".into(), on_path }
    }

    fn xy(points: &str) -> Vec<(f64, f64)> {
        points.split(' ').map(|p| p.split_once(',').map(|(x, y)| (x.parse().unwrap(), y.parse().unwrap())).unwrap()).collect()
    }

    #[test]
    fn faces_fill_the_box_and_come_back_to_front() {
        let atlas = WireAtlas { coords: vec!["z".into(), "phi".into(), "theta".into()], charts: vec![cube([0., 0., 0.], true), cube([1., 0., 0.], false)] };
        // seen head-on (no turn): x across, the third coordinate up, the second into the screen
        let p = picture(&atlas, &[[0.5, 0.5, 0.5], [1.5, 0.5, 0.5]], 0.0, 0.0);
        assert_eq!(p.faces.len(), 12);
        assert_eq!(p.charts_left_out, 0);
        let all: Vec<(f64, f64)> = p.faces.iter().flat_map(|f| xy(&f.points)).collect();
        let (xs, ys): (Vec<f64>, Vec<f64>) = all.into_iter().unzip();
        let span = |v: &[f64]| (v.iter().cloned().fold(f64::INFINITY, f64::min), v.iter().cloned().fold(f64::NEG_INFINITY, f64::max));
        assert_eq!(span(&xs), (SIZE / 2.0 - HALF, SIZE / 2.0 + HALF));
        assert_eq!(span(&ys), (SIZE / 2.0 - HALF, SIZE / 2.0 + HALF));
        assert!(p.path.starts_with('M') && p.path.contains('L'));
        assert_eq!(p.edges.len(), 12);
        assert!(p.labels[0].2.starts_with("z [0, 2]"), "{:?}", p.labels);
        // a quarter turn about the third axis keeps the box's outline
        let q = picture(&atlas, &[], std::f64::consts::FRAC_PI_2, 0.0);
        assert_eq!(q.faces.len(), 12);
        assert!(q.path.is_empty());
    }

    #[test]
    fn past_the_face_limit_the_path_charts_stay() {
        let mut charts: Vec<WireChart> = (0..MAX_FACES / 6 + 5).map(|i| cube([i as f64, 0., 0.], false)).collect();
        charts.last_mut().unwrap().on_path = true;
        let atlas = WireAtlas { coords: vec!["x".into(), "y".into(), "z".into()], charts };
        let p = picture(&atlas, &[], 0.3, 0.2);
        assert_eq!(p.faces.len(), MAX_FACES);
        assert_eq!(p.charts_left_out, 5);
        assert!(p.faces.iter().any(|f| f.on_path && f.chart == MAX_FACES / 6 + 4));
    }
}
