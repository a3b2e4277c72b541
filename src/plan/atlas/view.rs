//! The atlas as a picture: each chart's centre, radius, state and polytope in the slice's own
//! coordinates (the free pose coordinates), as paper 1 draws it (Fig. 6 top: the polygons of a
//! 2-D slice's charts; Fig. 7: the faces of a 3-D slice's polytopes), and which charts the path
//! runs through. The polytope lives in a chart's tangent space; x_c + Ψ u maps its vertices to the
//! ambient space, whose first coordinates are the free pose coordinates. That map is affine, so
//! a convex polygon stays convex and its vertices keep their cyclic order.

use super::atlas::Atlas;
use super::chart::ChartState;
use super::manifold::CableManifold;
use crate::model::pose::wrap_angle;
use nalgebra::{DVector, Vector3};
use serde::Serialize;

/// The charts of an atlas in the slice's coordinates.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AtlasView {
    /// The slice's coordinates (the free ones: `phi`, `theta`, …), in order.
    pub coords: Vec<String>,
    /// Every chart, by index (chart 0 is the first query's start).
    pub charts: Vec<ChartView>,
}

/// One chart in the slice's coordinates.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChartView {
    /// Its centre; an angle coordinate wrapped to (−π, π] (the polytope shifted with it).
    pub centre: Vec<f64>,
    /// The radius of its ball (tangent coordinates).
    pub radius: f64,
    /// `expanded` (explored: its polytope lies within its ball), `open` (made, not expanded: its
    /// polytope still reaches out of the ball), `out_of_bounds` (beyond the auxiliary bounds) or
    /// `blocked` (its centre violates a clearance).
    pub state: &'static str,
    /// Whether the last path found runs through it.
    pub on_path: bool,
    /// A 2-D slice: its polytope's vertices in cyclic order (a convex polygon). Empty otherwise.
    pub polygon: Vec<Vec<f64>>,
    /// A 3-D slice: its polytope's faces, each a convex polygon in cyclic order. Empty otherwise.
    pub faces: Vec<Vec<Vec<f64>>>,
}

/// The view of `atlas`, whose last path ran through `path_charts`.
pub fn view(atlas: &Atlas<CableManifold>, path_charts: &[usize]) -> AtlasView {
    AtlasView { coords: coords(atlas), charts: (0..atlas.charts.len()).map(|i| chart_view(atlas, i, path_charts.contains(&i))).collect() }
}

/// The names of the slice's coordinates.
pub fn coords(atlas: &Atlas<CableManifold>) -> Vec<String> {
    atlas.manifold.free().iter().map(|&c| crate::model::Coord::ALL[c].name().to_string()).collect()
}

/// Charts `from..` of `atlas` as they are now, none on a path: an atlas watched as it grows.
pub fn charts_from(atlas: &Atlas<CableManifold>, from: usize) -> Vec<ChartView> {
    (from..atlas.charts.len()).map(|i| chart_view(atlas, i, false)).collect()
}

/// Chart `i` of `atlas` in the slice's coordinates.
fn chart_view(atlas: &Atlas<CableManifold>, i: usize, on_path: bool) -> ChartView {
    let free = atlas.manifold.free();
    let k = free.len();
    let chart = &atlas.charts[i];
    // shift each angle coordinate so the centre lies in (−π, π]; the polytope moves with it
    let shift: Vec<f64> = (0..k).map(|j| if crate::model::Coord::ALL[free[j]].is_angle() { wrap_angle(chart.centre[j]) - chart.centre[j] } else { 0.0 }).collect();
    let to_slice = |u: &[f64]| -> Vec<f64> {
        let x = &chart.basis * DVector::from_column_slice(u);
        (0..k).map(|j| chart.centre[j] + x[j] + shift[j]).collect()
    };
    let vertices: Vec<&[f64]> = chart.polytope.vertices().collect();
    let (polygon, faces) = match k {
        2 => (from_lowest(cyclic(&vertices.iter().map(|v| [v[0], v[1], 0.0]).collect::<Vec<_>>(), Vector3::z()).into_iter().map(|j| to_slice(vertices[j])).collect()), vec![]),
        3 => {
            let faces = chart
                .polytope
                .faces()
                .into_iter()
                .filter_map(|face| {
                    let points: Vec<[f64; 3]> = face.iter().map(|&j| [vertices[j][0], vertices[j][1], vertices[j][2]]).collect();
                    let normal = plane_normal(&points)?;
                    Some(from_lowest(cyclic(&points, normal).into_iter().map(|j| to_slice(vertices[face[j]])).collect()))
                })
                .collect();
            (vec![], faces)
        }
        _ => (vec![], vec![]),
    };
    let state = match chart.state {
        ChartState::Open => "open",
        ChartState::Expanded => "expanded",
        ChartState::OutOfBounds => "out_of_bounds",
        ChartState::Blocked => "blocked",
    };
    ChartView { centre: to_slice(&vec![0.0; k]), radius: chart.radius, state, on_path, polygon, faces }
}

/// A polygon's vertices in the same cyclic order, starting from its lowest vertex (least first
/// coordinate, ties within 1e-9 broken by the next): the same start on every platform, although
/// the angles that ordered them may differ in their last bits.
fn from_lowest(mut polygon: Vec<Vec<f64>>) -> Vec<Vec<f64>> {
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()));
    let lower = |p: &[f64], q: &[f64]| p.iter().zip(q).find(|(a, b)| !close(**a, **b)).is_some_and(|(a, b)| a < b);
    let start = (0..polygon.len()).fold(0, |best, k| if lower(&polygon[k], &polygon[best]) { k } else { best });
    polygon.rotate_left(start);
    polygon
}

/// The order of coplanar `points` (normal `normal`) around their centroid.
fn cyclic(points: &[[f64; 3]], normal: Vector3<f64>) -> Vec<usize> {
    let n = points.len().max(1) as f64;
    let c = points.iter().fold(Vector3::zeros(), |a, p| a + Vector3::from(*p)) / n;
    let Some(first) = points.iter().map(|p| Vector3::from(*p) - c).find(|d| d.norm() > 0.0) else { return (0..points.len()).collect() };
    let e1 = first.normalize();
    let e2 = normal.normalize().cross(&e1);
    let angle = |p: &[f64; 3]| {
        let d = Vector3::from(*p) - c;
        d.dot(&e2).atan2(d.dot(&e1))
    };
    // an insertion sort: a face has a handful of vertices
    let angles: Vec<f64> = points.iter().map(angle).collect();
    let mut order: Vec<usize> = Vec::with_capacity(points.len());
    for k in 0..points.len() {
        let at = order.iter().position(|&j| angles[j] > angles[k]).unwrap_or(order.len());
        order.insert(at, k);
    }
    order
}

/// The normal of the plane through `points`: the largest cross product of two of their offsets
/// from the first (planar points, so any non-degenerate pair gives the plane); `None` when they
/// are collinear.
fn plane_normal(points: &[[f64; 3]]) -> Option<Vector3<f64>> {
    let origin = Vector3::from(*points.first()?);
    let offsets: Vec<Vector3<f64>> = points.iter().map(|p| Vector3::from(*p) - origin).collect();
    let scale = offsets.iter().fold(0.0f64, |a, d| a.max(d.norm()));
    let mut best = Vector3::zeros();
    for (k, a) in offsets.iter().enumerate() {
        for b in &offsets[k + 1..] {
            let n = a.cross(b);
            if n.norm() > best.norm() {
                best = n;
            }
        }
    }
    (best.norm() > 1e-12 * scale * scale).then_some(best)
}
