//! The cross-section both the slice map and the ray lattice are drawn over: the pose the other
//! coordinates come from and two coordinates with their ranges, with the scenario's defaults.
//! One set of controls for both panels (each panel adds its own resolution and buttons as
//! children), the overlay both draw (start, goal and path in the section's coordinates), and the
//! one SVG frame they draw in: plot area, ticks, axis names and the overlay.

use super::geom::{polyline, ticks, Scale};
use super::Chart;
use crate::logic::fmt_num;
use crate::palette::{css, Rgba};
use crate::worker::protocol::WireAtlas;
use crate::view3d::scene::{self, Polyline};
use cablenav::model::{Coord, Pose};
use cablenav::Scenario;
use leptos::prelude::*;
use std::f64::consts::{PI, TAU};

/// The plot's width (SVG viewBox units).
const W: f64 = 520.0;
/// Plot height.
const H: f64 = 500.0;
const LEFT: f64 = 56.0;
const RIGHT: f64 = 14.0;
const TOP: f64 = 14.0;
const BOTTOM: f64 = 46.0;
/// The plot area inside the frame: x, y, width, height.
pub const AREA: [f64; 4] = [LEFT, TOP, W - LEFT - RIGHT, H - TOP - BOTTOM];

/// What to draw over a cross-section: start, goal and coloured path pieces.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Overlay {
    /// The start pose.
    pub start: Option<Pose>,
    /// The goal pose.
    pub goal: Option<Pose>,
    /// The path, in coloured pieces.
    pub pieces: Vec<Polyline>,
    /// A multi-link robot's path instead: coloured pieces of configurations (joint coordinates).
    pub joint_pieces: Vec<(Rgba, Vec<Vec<f64>>)>,
    /// A multi-link robot's path's start and goal configurations.
    pub joint_ends: [Option<Vec<f64>>; 2],
    /// The atlas planner's charts on the planned path's 2-D slice, drawn when the section's axes
    /// are the slice's two coordinates.
    pub atlas: Option<WireAtlas>,
}

/// A chart over a section: its polygon, its centre (map coordinates), its state and whether the
/// path runs through it.
pub type ChartPolygon<'a> = (Vec<(f64, f64)>, (f64, f64), &'a str, bool);

/// The charts of `atlas` as polygons over a section with `axes` (in map coordinates), when the
/// atlas's slice is over those two coordinates (in either order): each chart's polygon, its
/// centre, its state and whether the path runs through it.
pub fn chart_polygons(atlas: &WireAtlas, axes: [Coord; 2]) -> Vec<ChartPolygon<'_>> {
    let names = [axes[0].name(), axes[1].name()];
    let swap = if atlas.coords == names { false } else if atlas.coords == [names[1], names[0]] { true } else { return vec![] };
    let at = |p: &[f64; 2]| if swap { (p[1], p[0]) } else { (p[0], p[1]) };
    atlas.charts.iter().map(|c| (c.polygon.iter().map(at).collect(), at(&[c.centre[0], c.centre[1]]), c.state.as_str(), c.on_path)).collect()
}

/// The default slice axes: the first two coordinates a query leaves free, else x and y (a
/// multi-link robot's first two joint coordinates).
pub fn default_axes(s: &Scenario) -> [Coord; 2] {
    if s.robot.chain.is_some() {
        let c = s.coords();
        return [c[0], c[c.len().min(2) - 1]];
    }
    s.queries
        .first()
        .map(|q| Coord::ALL.into_iter().filter(|c| !q.fixed.contains(c)).collect::<Vec<_>>())
        .filter(|free| free.len() >= 2)
        .map_or([Coord::X, Coord::Y], |free| [free[0], free[1]])
}

/// The default pose the other coordinates come from: the first query's start, else the first pose
/// (a multi-link robot's first configuration).
pub fn default_pose(s: &Scenario) -> Option<String> {
    s.queries.first().map(|q| q.start.clone()).or_else(|| s.config_names().into_iter().next())
}

/// The default range of a coordinate: [−π, π] for angles, the scene's extent for positions; a
/// joint coordinate's own range where it has one.
pub fn default_range(s: &Scenario, c: Coord) -> [f64; 2] {
    let joint = s.robot.chain.as_ref().filter(|_| matches!(c, Coord::Joint { .. })).and_then(|ch| ch.coords().nth(c.index()));
    if let Some((_, _, jc)) = joint {
        let [lo, hi] = jc.range;
        return if lo.is_finite() && hi.is_finite() { [lo, hi] } else { [lo.max(-1.0), hi.min(1.0)] };
    }
    if c.is_angle() {
        return [-PI, PI];
    }
    let (min, max) = scene::bounds(s);
    let i = c.index();
    if max[i] - min[i] > 1e-9 { [min[i], max[i]] } else { [min[i] - 1.0, max[i] + 1.0] }
}

/// Every place a pose falls on the map: its equivalent coordinate triples — (φ, θ, σ) and
/// (φ + π, −θ, σ), angles shifted by whole turns — inside `range`, without repeats.
pub fn slice_copies(pose: &Pose, axes: [Coord; 2], range: [[f64; 2]; 2]) -> Vec<(f64, f64)> {
    let c = pose.coords();
    let alt = [c[0], c[1], c[2], c[3] + PI, -c[4], c[5]];
    let shifts = |axis: Coord| if axis.is_angle() { vec![0.0, -TAU, TAU] } else { vec![0.0] };
    let inside = |v: f64, r: [f64; 2]| v >= r[0] - 1e-12 && v <= r[1] + 1e-12;
    let mut out: Vec<(f64, f64)> = Vec::new();
    for cand in [c, alt] {
        for da in shifts(axes[0]) {
            for db in shifts(axes[1]) {
                let p = (cand[axes[0].index()] + da, cand[axes[1].index()] + db);
                let known = out.iter().any(|q| (q.0 - p.0).abs() < 1e-9 && (q.1 - p.1).abs() < 1e-9);
                if inside(p.0, range[0]) && inside(p.1, range[1]) && !known {
                    out.push(p);
                }
            }
        }
    }
    out
}

/// Where a pose falls on the map's axes: of its [`slice_copies`], the first, or the nearest to
/// `prev` when given (angle differences taken modulo 2π, so a path stays on its branch across a
/// wrap). `None` if none is inside.
pub fn slice_point(pose: &Pose, axes: [Coord; 2], range: [[f64; 2]; 2], prev: Option<(f64, f64)>) -> Option<(f64, f64)> {
    let diff = |a: f64, b: f64, axis: Coord| if axis.is_angle() { cablenav::model::pose::wrap_angle(a - b) } else { a - b };
    let dist = |p: &(f64, f64)| prev.map_or(0.0, |q| diff(p.0, q.0, axes[0]).hypot(diff(p.1, q.1, axes[1])));
    slice_copies(pose, axes, range).into_iter().min_by(|a, b| dist(a).total_cmp(&dist(b)))
}

/// A multi-link robot's configurations in map coordinates: the two axes' joint coordinates,
/// `None` outside the map.
pub fn config_points(configs: &[Vec<f64>], axes: [Coord; 2], range: [[f64; 2]; 2]) -> Vec<Option<(f64, f64)>> {
    let inside = |v: f64, r: [f64; 2]| v >= r[0] - 1e-12 && v <= r[1] + 1e-12;
    configs
        .iter()
        .map(|q| {
            let p = (*q.get(axes[0].index())?, *q.get(axes[1].index())?);
            (inside(p.0, range[0]) && inside(p.1, range[1])).then_some(p)
        })
        .collect()
}

/// A path's points in map coordinates, broken (`None`) where it leaves the map or jumps by more
/// than half the map's width or height (a wrap of an angle).
pub fn path_points(poses: &[Pose], axes: [Coord; 2], range: [[f64; 2]; 2]) -> Vec<Option<(f64, f64)>> {
    let (wa, wb) = (range[0][1] - range[0][0], range[1][1] - range[1][0]);
    let mut out = Vec::with_capacity(poses.len());
    let mut prev = None;
    for pose in poses {
        let p = slice_point(pose, axes, range, prev);
        if let (Some(a), Some(b)) = (prev, p) {
            if (a.0 - b.0).abs() > wa / 2.0 || (a.1 - b.1).abs() > wb / 2.0 {
                out.push(None);
            }
        }
        out.push(p);
        prev = p;
    }
    out
}

/// A section's scales over `range`: first axis across, second axis up.
pub fn scales(range: [[f64; 2]; 2]) -> (Scale, Scale) {
    (Scale::new(range[0][0], range[0][1], LEFT, W - RIGHT), Scale::new(range[1][0], range[1][1], H - BOTTOM, TOP))
}

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

/// How a frame draws the overlay's path: over the slice map's coloured cells a solid line with
/// a white casing; over the lattice's rays a dashed line, so the rays stay visible under it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PathLook {
    /// Solid, on a white casing.
    Cased,
    /// Dashed.
    Dashed,
}

/// The one SVG frame of a cross-section plot (`id`, `title`): `children` (the panel's content,
/// placed in [`AREA`]) over a `background`, the area's border, the ticks of `range` on both
/// axes with the axes' `names`, and the `overlay` (the atlas's charts when its slice is this
/// section's, clipped to the area; its paths; its start and goal at every place they fall,
/// [`slice_copies`]). Test ids: `{id}-chart` (with `data-state`, `data-on-path` and
/// `data-centre`), `{id}-path`, `{id}-start`, `{id}-goal`.
#[component]
pub fn SectionFrame(
    id: &'static str,
    title: String,
    range: [[f64; 2]; 2],
    axes: [Coord; 2],
    names: [String; 2],
    background: &'static str,
    look: PathLook,
    overlay: Signal<Overlay>,
    children: Children,
) -> impl IntoView {
    let (x, y) = scales(range);
    let [ax, ay, aw, ah] = AREA;
    let to_px = move |p: Option<(f64, f64)>| p.map(|(a, b)| (x.at(a), y.at(b)));
    // an orientation shows twice on a (φ, θ) section: every copy of the start and goal is marked
    let markers = move |pose: Option<Pose>| pose.map_or(vec![], |p| slice_copies(&p, axes, range).into_iter().map(|q| (x.at(q.0), y.at(q.1))).collect());
    let joint_marker = move |q: &Option<Vec<f64>>| q.as_ref().and_then(|q| config_points(std::slice::from_ref(q), axes, range)[0]).map(|p| (x.at(p.0), y.at(p.1)));
    let [across, up] = names;
    view! {
        <Chart id title width=W height=H>
            <rect x=ax y=ay width=aw height=ah fill=background />
            {children()}
            <rect x=ax y=ay width=aw height=ah fill="none" stroke="#5b6670" />
            {ticks(range[0][0], range[0][1], 6).into_iter().map(|v| view! {
                <text x=x.at(v) y=H - BOTTOM + 16.0 font-size="11" text-anchor="middle" fill="#5b6670">{fmt_num(v)}</text>
            }).collect_view()}
            {ticks(range[1][0], range[1][1], 6).into_iter().map(|v| view! {
                <text x=LEFT - 5.0 y=y.at(v) + 4.0 font-size="11" text-anchor="end" fill="#5b6670">{fmt_num(v)}</text>
            }).collect_view()}
            <text x=(LEFT + W - RIGHT) / 2.0 y=H - 12.0 font-size="12" text-anchor="middle" fill="#1d2329">{across}</text>
            <text x=14 y=(TOP + H - BOTTOM) / 2.0 font-size="12" text-anchor="middle" fill="#1d2329" transform=format!("rotate(-90 14 {})", (TOP + H - BOTTOM) / 2.0)>{up}</text>
            {move || {
                let o = overlay.get();
                let clip = format!("{id}-area");
                let charts = o.atlas.as_ref().map_or(vec![], |a| chart_polygons(a, axes).into_iter().map(|(polygon, centre, state, on_path)| {
                    let points = polygon.iter().map(|&(a, b)| format!("{:.2},{:.2}", x.at(a), y.at(b))).collect::<Vec<_>>().join(" ");
                    let fill = if state == "expanded" { "rgba(29,35,41,0.16)" } else { "rgba(29,35,41,0.05)" };
                    view! {
                        <polygon data-testid=format!("{id}-chart") data-state=state.to_string() data-on-path=on_path.to_string()
                            data-centre=format!("{} {}", centre.0, centre.1) points=points fill=fill stroke="#1d2329"
                            stroke-width=if on_path { "1.6" } else { "0.7" } />
                    }
                }).collect::<Vec<_>>());
                view! {
                    <clipPath id=clip.clone()><rect x=ax y=ay width=aw height=ah /></clipPath>
                    <g clip-path=format!("url(#{clip})")>{charts}</g>
                    {o.pieces.iter().map(|piece| (piece.colour, path_points(&piece.poses, axes, range)))
                        .chain(o.joint_pieces.iter().map(|(colour, qs)| (*colour, config_points(qs, axes, range))))
                        .map(|(colour, points)| {
                        let d = polyline(&points.into_iter().map(to_px).collect::<Vec<_>>());
                        match look {
                            PathLook::Cased => view! {
                                <path d=d.clone() fill="none" stroke="#ffffff" stroke-width="5.5" stroke-linecap="round" stroke-linejoin="round" />
                                <path data-testid=format!("{id}-path") d=d fill="none" stroke=css(colour) stroke-width="2.5" stroke-linecap="round" stroke-linejoin="round" />
                            }.into_any(),
                            PathLook::Dashed => view! {
                                <path data-testid=format!("{id}-path") d=d fill="none" stroke=css(colour) stroke-width="2" stroke-dasharray="5 3" />
                            }.into_any(),
                        }
                    }).collect_view()}
                    {markers(o.start).into_iter().chain(joint_marker(&o.joint_ends[0])).map(|(cx, cy)| view! {
                        <circle data-testid=format!("{id}-start") cx=cx cy=cy r="6" fill="#ffffff" stroke="#1d2329" stroke-width="2"><title>"start"</title></circle>
                    }).collect_view()}
                    {markers(o.goal).into_iter().chain(joint_marker(&o.joint_ends[1])).map(|(cx, cy)| view! {
                        <rect data-testid=format!("{id}-goal") x=cx - 6.0 y=cy - 6.0 width="12" height="12" fill="#1d2329" stroke="#ffffff" stroke-width="1.5"><title>"goal"</title></rect>
                    }).collect_view()}
                }
            }}
        </Chart>
    }
}

#[cfg(test)]
// ±0.7854 is the arm's joint range as its CASPR file writes it, not an approximation of π/4
#[allow(clippy::approx_constant)]
mod tests {
    use super::*;
    use crate::presets::{find, PRESETS};
    use nalgebra::Vector3;

    #[test]
    fn a_multi_link_robots_section_is_over_its_joint_coordinates() {
        let s = crate::logic::parse_scenario(PRESETS[find("bmarm-x4-2").unwrap()].json).unwrap();
        let axes = default_axes(&s);
        assert_eq!([s.coord_name(axes[0]), s.coord_name(axes[1])], ["alpha", "beta"]);
        assert_eq!(default_range(&s, axes[0]), [-0.7854, 0.7854], "the joint's own range");
        assert_eq!(default_pose(&s).as_deref(), Some(s.config_names()[0].as_str()));
        // configurations land on their two coordinates; outside the map they are left out
        let qs = vec![vec![0.1, -0.2, 0.0, 0.3], vec![0.9, 0.0, 0.0, 0.0]];
        assert_eq!(config_points(&qs, axes, [[-0.5, 0.5]; 2]), [Some((0.1, -0.2)), None]);
        let theta = s.coord("axes", "theta").unwrap();
        assert_eq!(config_points(&qs, [theta, axes[1]], [[-0.5, 0.5]; 2]), [Some((0.3, -0.2)), Some((0.0, 0.0))]);
    }

    fn robocrane() -> Scenario {
        crate::logic::parse_scenario(PRESETS[find("robocrane").unwrap()].json).unwrap()
    }

    #[test]
    fn defaults_follow_the_first_query() {
        let s = robocrane();
        assert_eq!(default_axes(&s), [Coord::Phi, Coord::Theta]);
        assert_eq!(default_pose(&s).as_deref(), Some("q1"));
        assert_eq!(default_range(&s, Coord::Theta), [-PI, PI]);
        let r = default_range(&s, Coord::X);
        assert!(r[0] <= -2.0 && r[1] >= 2.0, "{r:?}");
        let tree = crate::logic::parse_scenario(PRESETS[find("cdpr7-tree").unwrap()].json).unwrap();
        assert_eq!(default_axes(&tree), [Coord::X, Coord::Y]);
    }

    #[test]
    fn poses_land_on_their_coordinates_or_the_equivalent_ones() {
        let full = [[-PI, PI], [-PI, PI]];
        let s = robocrane();
        // q3 has θ = −2.4: tilt_torsion gives θ ≥ 0, so the equivalent (φ + π, −θ) is the one
        // matching; both lie inside [−π, π]², the first found wins without a previous point
        let q3 = s.pose("q3").unwrap();
        let p = slice_point(q3, [Coord::Phi, Coord::Theta], full, Some((0.8, -2.4))).unwrap();
        assert!((p.0 - 0.8).abs() < 1e-9 && (p.1 + 2.4).abs() < 1e-9, "{p:?}");
        let q1 = s.pose("q1").unwrap();
        let p = slice_point(q1, [Coord::Phi, Coord::Theta], full, None).unwrap();
        assert!((p.0 + 0.5).abs() < 1e-9 && (p.1 - 0.9).abs() < 1e-9, "{p:?}");
        // both copies of q1 are inside [−π, π]²
        let copies = slice_copies(q1, [Coord::Phi, Coord::Theta], full);
        assert_eq!(copies.len(), 2, "{copies:?}");
        assert!((copies[1].0 - (-0.5 + PI)).abs() < 1e-9 && (copies[1].1 + 0.9).abs() < 1e-9, "{copies:?}");
        // on position axes the copies coincide
        assert_eq!(slice_copies(q1, [Coord::X, Coord::Y], [[-1.0, 1.0], [-1.0, 1.0]]), [(0.0, 0.0)]);
        // outside the range: none
        let far = Pose::from_coords([9.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        assert_eq!(slice_point(&far, [Coord::X, Coord::Y], [[0.0, 1.0], [-1.0, 1.0]], None), None);
    }

    #[test]
    fn paths_break_at_wraps() {
        let poses: Vec<Pose> =
            [3.0, 3.1, -3.1, -3.0].iter().map(|&phi| Pose::from_tilt_torsion(Vector3::zeros(), [phi, 0.5, 0.0])).collect();
        let pts = path_points(&poses, [Coord::Phi, Coord::Theta], [[-PI, PI], [-PI, PI]]);
        assert_eq!(pts.len(), 5);
        assert!(pts[2].is_none(), "{pts:?}");
        assert!((pts[3].unwrap().0 + 3.1).abs() < 1e-9);
    }

}
