//! The slice map: the core's classified grid over two chosen coordinates (the others fixed from
//! a chosen pose) as an image, with the start, the goal and the path drawn over it. The grid is
//! classified by several Web Workers at once, each a block of rows ([`row_blocks`]).

use super::geom::{polyline, ticks, Scale};
use super::section::{CrossSection, SectionControls};
use super::strip::css;
use super::Chart;
use crate::state::Shared;
use crate::logic::fmt_num;
use crate::view3d::scene::{self, Polyline};
use cablenav::model::{Coord, Pose};
use crate::worker::host::{self, FanOut};
use crate::worker::protocol::{Job, Reply};
use cablenav::verify::slice::{Class, SliceMap};
use cablenav::Scenario;
use leptos::prelude::*;
use std::f64::consts::{PI, TAU};

/// Plot size.
pub const W: f64 = 520.0;
/// Plot height.
pub const H: f64 = 500.0;
const LEFT: f64 = 56.0;
const RIGHT: f64 = 14.0;
const TOP: f64 = 14.0;
const BOTTOM: f64 = 46.0;

/// What to draw over the map: start, goal and coloured path pieces.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Overlay {
    /// The start pose.
    pub start: Option<Pose>,
    /// The goal pose.
    pub goal: Option<Pose>,
    /// The path, in coloured pieces.
    pub pieces: Vec<Polyline>,
    /// A multi-link robot's path instead: coloured pieces of configurations (joint coordinates).
    pub joint_pieces: Vec<(scene::Rgba, Vec<Vec<f64>>)>,
    /// A multi-link robot's path's start and goal configurations.
    pub joint_ends: [Option<Vec<f64>>; 2],
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

/// Standard base64 with padding (for the map's PNG data URL).
pub fn base64(bytes: &[u8]) -> String {
    const ABC: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let n = (b[0] as u32) << 16 | (b[1] as u32) << 8 | b[2] as u32;
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ABC[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// `res` rows split into at most `workers` consecutive blocks of nearly equal size, as
/// `[from, to)` pairs covering `0..res`.
pub fn row_blocks(res: usize, workers: usize) -> Vec<[usize; 2]> {
    let k = workers.clamp(1, res.max(1));
    (0..k).map(|b| [b * res / k, (b + 1) * res / k]).filter(|r| r[0] < r[1]).collect()
}

/// The map's scales: first axis across, second axis up.
fn scales(range: [[f64; 2]; 2]) -> (Scale, Scale) {
    (Scale::new(range[0][0], range[0][1], LEFT, W - RIGHT), Scale::new(range[1][0], range[1][1], H - BOTTOM, TOP))
}

/// The slice controls and map.
#[component]
pub fn SlicePanel(parsed: Memo<crate::state::Parsed>, source: RwSignal<String>, overlay: Signal<Overlay>) -> impl IntoView {
    let scenario = Signal::derive(move || parsed.get().0.as_ref().as_ref().ok().cloned());
    let section = CrossSection::new();
    let CrossSection { pose, axes, range } = section;
    let res = RwSignal::new(64usize);
    let map = RwSignal::new(None::<Shared<Result<SliceMap, String>>>);
    // a new scenario resets the choices to its defaults and clears the map
    Effect::new(move |_| {
        if let Some(s) = scenario.get() {
            section.reset(&s);
            map.set(None);
        }
    });
    // the map is classified in row blocks by several workers at once (crate::worker), then
    // joined here; a new request or Cancel terminates the running ones
    let run = FanOut::new();
    let progress = RwSignal::new(None::<(usize, usize)>);
    let stop = move || {
        progress.set(None);
        run.stop()
    };
    let compute = move |_| {
        let Some(s) = scenario.get_untracked() else { return };
        let this = stop();
        let (pose_name, a, n, r) = (pose.get_untracked(), axes.get_untracked(), res.get_untracked(), range.get_untracked());
        // the whole map's checks first (same errors as the core's), before any worker starts
        if let Err(e) = cablenav::verify::slice::slice_rows(&s, &pose_name, a, n, r, 0..0) {
            map.set(Some(Shared::new(Err(e.to_string()))));
            return;
        }
        let Some(json) = source.try_get_untracked() else { return };
        let blocks = row_blocks(n, host::parallelism());
        let jobs: Vec<Job> = blocks
            .iter()
            .map(|rows| Job::Slice { scenario: json.clone(), pose: pose_name.clone(), axes: [a[0].name().to_string(), a[1].name().to_string()], res: n, range: r, rows: *rows })
            .collect();
        let part = |reply: Reply| match reply {
            Reply::Progress { .. } => None,
            Reply::Sliced { classes, .. } => Some(Ok(classes)),
            Reply::Failed { error } => Some(Err(error)),
            _ => Some(Err("the worker answered a slice job with another job's reply".to_string())),
        };
        let workers = blocks.len();
        let on_progress = move |_: f64, parts: usize| {
            if run.is_current(this) {
                progress.set(Some((parts, workers)));
            }
        };
        let on_done = move |parts: Result<Vec<Vec<Class>>, String>| {
            run.finish(this, || {
                let result = parts.and_then(|p| cablenav::verify::slice::slice_from_classes(&s, &pose_name, a, n, r, p.concat()).map_err(|e| e.to_string()));
                map.set(Some(Shared::new(result)));
                progress.set(None);
            })
        };
        match host::start_all(&jobs, part, on_progress, on_done) {
            Ok(started) => {
                run.hold(started);
                progress.set(Some((0, workers)));
            }
            Err(e) => map.set(Some(Shared::new(Err(e)))),
        }
    };
    view! {
        <SectionControls section scenario prefix="slice">
            <label>
                "cells per side "
                <select on:change=move |ev| {
                    if let Ok(v) = event_target_value(&ev).parse() {
                        res.set(v)
                    }
                }>
                    {[32usize, 64, 128, 256].map(|v| view! { <option value=v.to_string() selected=move || res.get() == v>{v}</option> })}
                </select>
            </label>
            <button data-testid="slice-compute" on:click=compute>"Compute slice"</button>
            <button data-testid="slice-cancel" disabled=move || progress.get().is_none() on:click=move |_| { stop(); }>"Cancel"</button>
            <span class="readout" data-testid="slice-progress" aria-live="polite">
                {move || progress.get().map(|(done, all)| format!("{done} of {all} row blocks done ({all} workers)"))}
            </span>
        </SectionControls>
        {move || map.get().map(|m| match m.0.as_ref() {
            Err(e) => view! { <p class="error">{format!("Slice: {e}")}</p> }.into_any(),
            Ok(m) => view! { <SliceMapView map=m.clone() axes=axes.get_untracked() overlay /> }.into_any(),
        })}
    }
}

/// The map image, its axes, and the overlay.
#[component]
fn SliceMapView(map: SliceMap, axes: [Coord; 2], overlay: Signal<Overlay>) -> impl IntoView {
    let range = map.range;
    let (x, y) = scales(range);
    let href = format!("data:image/png;base64,{}", base64(&map.png()));
    let title = format!(
        "Slice over {} × {} ({}×{} cells; {:.1}% feasible, {} component(s)); path projected",
        map.axes[0],
        map.axes[1],
        map.res,
        map.res,
        map.fraction_feasible * 100.0,
        map.components
    );
    let to_px = move |p: Option<(f64, f64)>| p.map(|(a, b)| (x.at(a), y.at(b)));
    // an orientation shows twice on a (φ, θ) map: every copy of the start and goal is marked
    let markers = move |pose: Option<Pose>| pose.map_or(vec![], |p| slice_copies(&p, axes, range).into_iter().map(|q| (x.at(q.0), y.at(q.1))).collect());
    let joint_marker = move |q: &Option<Vec<f64>>| q.as_ref().and_then(|q| config_points(std::slice::from_ref(q), axes, range)[0]).map(|p| (x.at(p.0), y.at(p.1)));
    view! {
        <Chart id="slice" title width=W height=H>
            <image href=href x=LEFT y=TOP width=W - LEFT - RIGHT height=H - TOP - BOTTOM preserveAspectRatio="none" style="image-rendering: pixelated" />
            <rect x=LEFT y=TOP width=W - LEFT - RIGHT height=H - TOP - BOTTOM fill="none" stroke="#5b6670" />
            {ticks(range[0][0], range[0][1], 6).into_iter().map(|v| view! {
                <text x=x.at(v) y=H - BOTTOM + 16.0 font-size="11" text-anchor="middle" fill="#5b6670">{fmt_num(v)}</text>
            }).collect_view()}
            {ticks(range[1][0], range[1][1], 6).into_iter().map(|v| view! {
                <text x=LEFT - 5.0 y=y.at(v) + 4.0 font-size="11" text-anchor="end" fill="#5b6670">{fmt_num(v)}</text>
            }).collect_view()}
            <text x=(LEFT + W - RIGHT) / 2.0 y=H - 12.0 font-size="12" text-anchor="middle" fill="#1d2329">{map.axes[0].clone()}</text>
            <text x=14 y=(TOP + H - BOTTOM) / 2.0 font-size="12" text-anchor="middle" fill="#1d2329" transform=format!("rotate(-90 14 {})", (TOP + H - BOTTOM) / 2.0)>{map.axes[1].clone()}</text>
            {move || {
                let o = overlay.get();
                view! {
                    {o.pieces.iter().map(|piece| (piece.colour, path_points(&piece.poses, axes, range)))
                        .chain(o.joint_pieces.iter().map(|(colour, qs)| (*colour, config_points(qs, axes, range))))
                        .map(|(colour, points)| {
                        let pts: Vec<_> = points.into_iter().map(to_px).collect();
                        let d = polyline(&pts);
                        // a white casing keeps a green path visible over green cells
                        view! {
                            <path d=d.clone() fill="none" stroke="#ffffff" stroke-width="5.5" stroke-linecap="round" stroke-linejoin="round" />
                            <path data-testid="slice-path" d=d fill="none" stroke=css(colour) stroke-width="2.5" stroke-linecap="round" stroke-linejoin="round" />
                        }
                    }).collect_view()}
                    {markers(o.start).into_iter().chain(joint_marker(&o.joint_ends[0])).map(|(cx, cy)| view! {
                        <circle data-testid="slice-start" cx=cx cy=cy r="6" fill="#ffffff" stroke="#1d2329" stroke-width="2"><title>"start"</title></circle>
                    }).collect_view()}
                    {markers(o.goal).into_iter().chain(joint_marker(&o.joint_ends[1])).map(|(cx, cy)| view! {
                        <rect data-testid="slice-goal" x=cx - 6.0 y=cy - 6.0 width="12" height="12" fill="#1d2329" stroke="#ffffff" stroke-width="1.5"><title>"goal"</title></rect>
                    }).collect_view()}
                }
            }}
        </Chart>
        <p class="legend">
            "Cells: " <span class="swatch" style="background: rgb(46,160,67)"></span> "feasible"
            <span class="swatch" style="background: rgb(59,111,216)"></span> "tension out of bounds"
            <span class="swatch" style="background: rgb(208,59,59)"></span> "length out of bounds"
            <span class="swatch" style="background: rgb(0,0,0)"></span> "singular"
            <span class="swatch" style="background: rgb(230,145,30)"></span> "interference"
            " · ○ start · ■ goal (on a (φ, θ) map each orientation shows twice, as (φ, θ) and (φ + π, −θ): both are marked)"
        </p>
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

    #[test]
    fn row_blocks_cover_the_rows_once() {
        assert_eq!(row_blocks(10, 3), [[0, 3], [3, 6], [6, 10]]);
        assert_eq!(row_blocks(2, 8), [[0, 1], [1, 2]], "no empty block");
        assert_eq!(row_blocks(64, 1), [[0, 64]]);
        for (res, k) in [(256, 7), (33, 4), (1, 2)] {
            let b = row_blocks(res, k);
            assert!(b[0][0] == 0 && b.last().unwrap()[1] == res && b.windows(2).all(|w| w[0][1] == w[1][0]), "{b:?}");
        }
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

    #[test]
    fn base64_matches_known_answers() {
        assert_eq!(base64(b""), "");
        assert_eq!(base64(b"f"), "Zg==");
        assert_eq!(base64(b"fo"), "Zm8=");
        assert_eq!(base64(b"foo"), "Zm9v");
        assert_eq!(base64(b"foobar"), "Zm9vYmFy");
        assert_eq!(base64(&[0xff, 0xfe, 0x00]), "//4A");
    }
}
