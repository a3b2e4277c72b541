//! Slice maps: a cell-centred res × res grid over two coordinates (pose coordinates, or a
//! multi-link robot's joint coordinates), the others fixed from a pose (or configuration), each
//! cell classified by the conditions at its centre; and the 4-neighbour connected
//! components of the feasible cells (Bohigas et al. Fig. 5). An angle axis whose range is one
//! whole turn (e.g. φ ∈ [−π, π]) closes on itself: its first and last cells are neighbours.

use std::sync::atomic::{AtomicUsize, Ordering};
use crate::conditions::{for_scenario, Condition, Kind};
use crate::error::{Error, Result};
use crate::model::{Coord, Load};
use crate::query::cables::cables_at_config;
use crate::scenario::Scenario;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Largest grid side accepted.
pub const MAX_RES: usize = 2000;

/// What holds at a cell centre.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Class {
    /// Every condition holds.
    Feasible,
    /// Some cable's tension range leaves its bounds over the wrench set (a multi-link robot:
    /// joint-space wrench closure fails).
    Tension,
    /// Some cable length is out of its bounds.
    Length,
    /// The structure matrix is singular.
    Singular,
    /// A clearance (cable–cable or cable–obstacle) is violated.
    Interference,
}

/// A classified slice.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SliceMap {
    /// The two coordinates, first along the columns (i), second along the rows (j).
    pub axes: [String; 2],
    /// The ranges [lo, hi] of the two axes.
    pub range: [[f64; 2]; 2],
    /// Grid side.
    pub res: usize,
    /// The coordinates of the fixed pose or configuration (the axes' entries are overwritten per
    /// cell).
    pub fixed: Vec<f64>,
    /// Share of feasible cells.
    pub fraction_feasible: f64,
    /// Number of connected components of feasible cells.
    pub components: usize,
    /// Cell classes, row-major: index j·res + i, i along the first axis.
    pub classes: Vec<Class>,
    /// Component id (0-based) of each cell, `None` where infeasible.
    pub component: Vec<Option<usize>>,
    /// For every scenario pose on the slice, the component of its cell (`None` if infeasible);
    /// serialised as an object `{"q1": id, …}` in file order.
    #[serde(serialize_with = "as_object")]
    pub pose_components: Vec<(String, Option<usize>)>,
    /// The singularity curves (det J = 0) of a six-cable robot's slice, as polylines of
    /// [first axis, second axis] points ([`super::singular`]); empty otherwise, and until
    /// computed (`cablenav slice` computes them after the classes; the page asks a worker).
    pub singular_curves: Vec<Vec<[f64; 2]>>,
}

fn as_object<S: serde::Serializer>(v: &[(String, Option<usize>)], ser: S) -> std::result::Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let mut m = ser.serialize_map(Some(v.len()))?;
    for (k, c) in v {
        m.serialize_entry(k, c)?;
    }
    m.end()
}

impl SliceMap {
    /// The map as an RGB image, one pixel per cell, the second axis growing upwards: feasible
    /// green, tension out of range blue, length out of range red, singular black, interference
    /// orange (the colours of paper 1 Fig. 5, plus two).
    pub fn png(&self) -> Vec<u8> {
        let colour = |c: Class| match c {
            Class::Feasible => [46, 160, 67],
            Class::Tension => [59, 111, 216],
            Class::Length => [208, 59, 59],
            Class::Singular => [0, 0, 0],
            Class::Interference => [230, 145, 30],
        };
        let pixels: Vec<[u8; 3]> = (0..self.res).rev().flat_map(|j| (0..self.res).map(move |i| (i, j))).map(|(i, j)| colour(self.classes[j * self.res + i])).collect();
        crate::png::encode_rgb(self.res as u32, self.res as u32, &pixels)
    }

    /// Centre value of cell `k` along axis `a` (0 or 1).
    pub fn center(&self, a: usize, k: usize) -> f64 {
        let [lo, hi] = self.range[a];
        lo + (hi - lo) * (k as f64 + 0.5) / self.res as f64
    }

    /// The cell holding `value` along axis `a`, if inside the range.
    fn cell(&self, a: usize, value: f64) -> Option<usize> {
        let [lo, hi] = self.range[a];
        if !(value >= lo && value <= hi) {
            return None;
        }
        Some((((value - lo) / (hi - lo)) * self.res as f64).floor().min(self.res as f64 - 1.0) as usize)
    }
}

/// Default range of a coordinate: [−π, π] for angles; none for positions.
pub fn default_range(c: Coord) -> Option<[f64; 2]> {
    c.is_angle().then_some([-PI, PI])
}

/// Whether an axis along `c` over `range` closes on itself: `c` is an angle and the range is one
/// whole turn (to 1e-9 of 2π), so its two ends are the same orientation. Slice maps and the ray
/// lattice join their cells, pieces and grid points across that seam.
pub fn whole_turn(c: Coord, range: [f64; 2]) -> bool {
    c.is_angle() && (range[1] - range[0] - 2.0 * PI).abs() <= 1e-9 * 2.0 * PI
}

/// The class of configuration `q`; `load` is the scenario's ([`Scenario::load`]), made once.
fn classify(s: &Scenario, load: Option<&Load>, conditions: &[Box<dyn Condition>], q: &[f64]) -> Class {
    let cables = cables_at_config(&s.robot, q);
    let violated = |kind: Kind| conditions.iter().filter(|c| c.kind() == kind).any(|c| c.check(&cables).violated);
    if violated(Kind::Length) {
        return Class::Length;
    }
    if let Some(load) = load {
        if s.robot.cables.len() == s.robot.mobility.dof() && cables.tension_ranges(load).is_none() {
            return Class::Singular;
        }
    }
    if violated(Kind::Tension) {
        return Class::Tension;
    }
    if violated(Kind::Interference) {
        return Class::Interference;
    }
    Class::Feasible
}

/// Classifies the slice of `s` through pose `pose_name` over `axes` with `res` cells per side.
pub fn slice(s: &Scenario, pose_name: &str, axes: [Coord; 2], res: usize, range: [[f64; 2]; 2]) -> Result<SliceMap> {
    slice_counted(s, pose_name, axes, res, range, &AtomicUsize::new(0))
}

/// [`slice()`], adding 1 to `rows_done` after each of the `res` rows is classified (from any
/// worker thread), so that a caller on another thread can show progress.
pub fn slice_counted(s: &Scenario, pose_name: &str, axes: [Coord; 2], res: usize, range: [[f64; 2]; 2], rows_done: &AtomicUsize) -> Result<SliceMap> {
    let classes = classify_rows(s, pose_name, axes, res, range, 0..res, rows_done)?;
    slice_from_classes(s, pose_name, axes, res, range, classes)
}

/// The map's frame before any cell is classified, after checking the arguments.
fn empty_map(s: &Scenario, pose_name: &str, axes: [Coord; 2], res: usize, range: [[f64; 2]; 2]) -> Result<SliceMap> {
    if axes[0] == axes[1] {
        return Err(Error::new("--axes", "the two axes must differ"));
    }
    if res == 0 || res > MAX_RES {
        return Err(Error::new("--res", format!("must be between 1 and {MAX_RES}, got {res}")));
    }
    for r in range {
        if !(r[0].is_finite() && r[1].is_finite() && r[0] < r[1]) {
            return Err(Error::new("--range", format!("needs finite LO < HI, got {} {}", r[0], r[1])));
        }
    }
    Ok(SliceMap {
        axes: [s.coord_name(axes[0]), s.coord_name(axes[1])],
        range,
        res,
        fixed: s.config(pose_name)?,
        fraction_feasible: 0.0,
        components: 0,
        classes: Vec::new(),
        component: vec![None; res * res],
        pose_components: vec![],
        singular_curves: vec![],
    })
}

/// The classes of rows `rows` (j, along the second axis) of the slice [`slice()`] computes, row
/// by row: so that parts of one map can be classified apart (the page's workers) and joined by
/// [`slice_from_classes`].
pub fn slice_rows(s: &Scenario, pose_name: &str, axes: [Coord; 2], res: usize, range: [[f64; 2]; 2], rows: std::ops::Range<usize>) -> Result<Vec<Class>> {
    classify_rows(s, pose_name, axes, res, range, rows, &AtomicUsize::new(0))
}

/// [`slice_rows`], adding 1 to `rows_done` after each row.
fn classify_rows(s: &Scenario, pose_name: &str, axes: [Coord; 2], res: usize, range: [[f64; 2]; 2], rows: std::ops::Range<usize>, rows_done: &AtomicUsize) -> Result<Vec<Class>> {
    let map = empty_map(s, pose_name, axes, res, range)?;
    if rows.start > rows.end || rows.end > res {
        return Err(Error::new("rows", format!("must lie within 0..{res}, got {}..{}", rows.start, rows.end)));
    }
    // rows in parallel natively (each worker with its own conditions), in order on wasm
    let first = rows.start;
    let load = s.load();
    let classes = crate::parallel::map_with(rows.len(), || for_scenario(s), |conditions, k| {
        let row = (0..res)
            .map(|i| {
                let mut c = map.fixed.clone();
                c[axes[0].index()] = map.center(0, i);
                c[axes[1].index()] = map.center(1, first + k);
                classify(s, load.as_ref(), conditions, &c)
            })
            .collect::<Vec<_>>();
        rows_done.fetch_add(1, Ordering::Relaxed);
        row
    });
    Ok(classes.concat())
}

/// The slice map from all its cells' classes (row-major, as [`slice_rows`] gives them): its
/// feasible components, their share and the poses on it.
pub fn slice_from_classes(s: &Scenario, pose_name: &str, axes: [Coord; 2], res: usize, range: [[f64; 2]; 2], classes: Vec<Class>) -> Result<SliceMap> {
    let mut map = empty_map(s, pose_name, axes, res, range)?;
    if classes.len() != res * res {
        return Err(Error::new("classes", format!("expected {} cells, got {}", res * res, classes.len())));
    }
    map.classes = classes;
    let wraps = [0, 1].map(|a| whole_turn(axes[a], range[a]));
    label_components(&mut map, wraps);
    map.fraction_feasible = map.classes.iter().filter(|&&c| c == Class::Feasible).count() as f64 / (res * res) as f64;
    map.pose_components = poses_on_slice(s, &map, axes);
    Ok(map)
}

/// 4-neighbour flood fill of the feasible cells; along an axis that `wraps` (a whole turn of an
/// angle) the first and last cells are neighbours too.
fn label_components(map: &mut SliceMap, wraps: [bool; 2]) {
    let res = map.res;
    let mut next = 0;
    let mut stack = Vec::new();
    for start in 0..res * res {
        if map.classes[start] != Class::Feasible || map.component[start].is_some() {
            continue;
        }
        map.component[start] = Some(next);
        stack.push(start);
        while let Some(k) = stack.pop() {
            let (i, j) = (k % res, k / res);
            let mut neighbours = Vec::with_capacity(4);
            for (at, step, wrap) in [(i, 1, wraps[0]), (j, res, wraps[1])] {
                if at > 0 {
                    neighbours.push(k - step);
                } else if wrap && res > 1 {
                    neighbours.push(k + (res - 1) * step);
                }
                if at + 1 < res {
                    neighbours.push(k + step);
                } else if wrap && res > 1 {
                    neighbours.push(k - (res - 1) * step);
                }
            }
            for n in neighbours {
                if map.classes[n] == Class::Feasible && map.component[n].is_none() {
                    map.component[n] = Some(next);
                    stack.push(n);
                }
            }
        }
        next += 1;
    }
    map.components = next;
}

/// The scenario's poses (or a multi-link robot's configurations) that lie on the slice (their
/// other coordinates equal the fixed ones to 1e-9) and inside its square, with the component of
/// their cell. A tilt-and-torsion orientation has two coordinate triples, (φ, θ, σ) and
/// (φ + π, −θ, σ): the first inside the square is used.
fn poses_on_slice(s: &Scenario, map: &SliceMap, axes: [Coord; 2]) -> Vec<(String, Option<usize>)> {
    let wrap = crate::model::pose::wrap_angle;
    let same = |a: f64, b: f64, angle: bool| if angle { wrap(a - b).abs() < 1e-9 } else { (a - b).abs() < 1e-9 };
    let named: Vec<(String, Vec<Vec<f64>>)> = match s.robot.chain {
        Some(_) => s.configs.iter().map(|(n, q)| (n.clone(), vec![q.clone()])).collect(),
        None => s
            .poses
            .iter()
            .map(|(n, p)| {
                let c = p.coords();
                (n.clone(), vec![c.to_vec(), vec![c[0], c[1], c[2], wrap(c[3] + PI), -c[4], c[5]]])
            })
            .collect(),
    };
    let mut out = vec![];
    for (name, candidates) in named {
        for cand in candidates {
            let on_slice = (0..cand.len()).map(|k| s.coord_at(k)).filter(|k| !axes.contains(k)).all(|k| same(cand[k.index()], map.fixed[k.index()], k.is_angle()));
            // an angle axis may hold the value shifted by a whole turn
            let value = |a: usize| {
                let v = cand[axes[a].index()];
                if axes[a].is_angle() && map.cell(a, v).is_none() {
                    [v - 2.0 * PI, v + 2.0 * PI].into_iter().find(|&w| map.cell(a, w).is_some()).unwrap_or(v)
                } else {
                    v
                }
            };
            if let (true, Some(i), Some(j)) = (on_slice, map.cell(0, value(0)), map.cell(1, value(1))) {
                out.push((name.clone(), map.component[j * map.res + i]));
                break;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 4 × 4 map whose feasible cells are the first and last columns (F.. F per row).
    fn two_edge_columns() -> SliceMap {
        let res = 4;
        let classes = (0..res * res).map(|k| if k % res == 0 || k % res == res - 1 { Class::Feasible } else { Class::Length }).collect();
        SliceMap {
            axes: ["phi".into(), "z".into()],
            range: [[-PI, PI], [0.0, 1.0]],
            res,
            fixed: vec![0.0; 6],
            fraction_feasible: 0.0,
            components: 0,
            classes,
            component: vec![None; res * res],
            pose_components: vec![],
            singular_curves: vec![],
        }
    }

    #[test]
    fn a_whole_turn_closes_on_itself() {
        let mut apart = two_edge_columns();
        label_components(&mut apart, [false, false]);
        assert_eq!(apart.components, 2);
        let mut joined = two_edge_columns();
        label_components(&mut joined, [true, false]);
        assert_eq!(joined.components, 1);
        assert!(joined.component.iter().flatten().all(|&c| c == 0));
        // wrapping the other axis (rows) joins nothing new here: both columns already span it
        let mut rows = two_edge_columns();
        label_components(&mut rows, [false, true]);
        assert_eq!(rows.components, 2);
    }

    /// Through the public entry: φ over a whole turn wraps, a shorter φ range or a length axis
    /// over the same numbers does not.
    #[test]
    fn only_a_whole_turn_of_an_angle_wraps() {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/static/scenarios/robocrane.json")).unwrap();
        let s = Scenario::from_json(&text).unwrap();
        let pose = s.poses.first().map(|(n, _)| n.clone()).unwrap();
        let classes = two_edge_columns().classes;
        let count = |axes: [Coord; 2], range: [[f64; 2]; 2]| slice_from_classes(&s, &pose, axes, 4, range, classes.clone()).unwrap().components;
        let (phi, theta, z) = (Coord::ALL[3], Coord::ALL[4], Coord::ALL[2]);
        assert_eq!(count([phi, theta], [[-PI, PI], [0.0, 1.4]]), 1);
        assert_eq!(count([phi, theta], [[0.0, 2.0 * PI], [0.0, 1.4]]), 1);
        assert_eq!(count([phi, theta], [[-3.0, 3.0], [0.0, 1.4]]), 2);
        assert_eq!(count([z, theta], [[-PI, PI], [0.0, 1.4]]), 2);
    }
}
