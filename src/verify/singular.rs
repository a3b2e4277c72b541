//! Singularity curves of a slice (paper 1, Fig. 5): where the structure matrix of a six-cable
//! robot is singular, det J = 0, as curves in the slice's two coordinates rather than as cells.
//!
//! det J is evaluated at the corners of the slice map's cells ((res + 1)² points, the other
//! coordinates from the slice's pose); on every cell edge whose two corners have determinants of
//! opposite signs the zero is found by bisection to `ROOT_TOL` of the edge (det J is continuous
//! along it where the cable lengths do not vanish); marching squares joins the crossings of each
//! cell into segments (a saddle cell, with four crossings, is resolved by the sign at its centre)
//! and the segments are chained into polylines. The moment point does not matter: moving it
//! multiplies J by a matrix of determinant 1. Only sign changes are seen: a curve where det J
//! touches zero without crossing it, or two crossings within one cell edge, is missed at this
//! resolution; so is a line along which det J vanishes identically (Robocrane's θ = ±π, the
//! platform upside down: determinants below `ZERO` of the grid's largest have no sign, so its
//! rounding noise draws nothing). Robots with other than six cables have no such curves (their J
//! is not square).

use crate::error::Result;
use crate::model::{Coord, Pose};
use crate::query::wrench::structure_matrix_m;
use crate::scenario::Scenario;
use std::collections::HashMap;

/// Bisection stops when the bracket is this fraction of a cell edge.
const ROOT_TOL: f64 = 1e-12;

/// Determinants below this fraction of the largest on the grid have no sign.
const ZERO: f64 = 1e-12;

/// The singularity curves (det J = 0) of the slice of `s` through pose `pose_name` over `axes`
/// and `range`, sampled at the corners of `res` × `res` cells: polylines of points
/// [first axis, second axis]. Empty for a robot without as many cables as degrees of freedom
/// or a multi-link robot. Checks its arguments as [`super::slice::slice`] does.
pub fn singularity_curves(s: &Scenario, pose_name: &str, axes: [Coord; 2], res: usize, range: [[f64; 2]; 2]) -> Result<Vec<Vec<[f64; 2]>>> {
    let fixed = super::slice::slice_rows(s, pose_name, axes, res, range, 0..0).and_then(|_| s.config(pose_name))?;
    let rows = s.robot.mobility.rows();
    if s.robot.chain.is_some() || s.robot.cables.len() != rows.len() {
        return Ok(vec![]);
    }
    let at = |u: f64, v: f64| -> f64 {
        let mut c = [0.0; 6];
        c.copy_from_slice(&fixed[..6]);
        c[axes[0].index()] = u;
        c[axes[1].index()] = v;
        let pose = Pose::from_coords(c);
        structure_matrix_m(&s.robot.anchors(&pose), &pose.position, rows).determinant()
    };
    let coord = |a: usize, k: f64| range[a][0] + (range[a][1] - range[a][0]) * k / res as f64;
    let n = res + 1;
    let corners: Vec<f64> = crate::parallel::map_with(n, || (), |_, j| (0..n).map(|i| at(coord(0, i as f64), coord(1, j as f64))).collect::<Vec<_>>()).concat();
    let det = |i: usize, j: usize| corners[j * n + i];
    // below 1e-12 of the largest |det J| on the grid a determinant counts as zero, without a
    // sign: where det J vanishes along a whole line (Robocrane at θ = ±π, upside down) its
    // rounding noise would otherwise trace curves along it
    let zero = ZERO * corners.iter().filter(|d| d.is_finite()).fold(0.0f64, |a, d| a.max(d.abs()));
    let sign = |d: f64| if d > zero { 1 } else if d < -zero { -1 } else { 0 };
    // the zero on an edge between corners (i0, j0) and (i1, j1), cached by edge
    let mut roots: HashMap<(usize, usize, bool), [f64; 2]> = HashMap::new();
    let mut root = |i: usize, j: usize, horizontal: bool| -> [f64; 2] {
        *roots.entry((i, j, horizontal)).or_insert_with(|| {
            let (i1, j1) = if horizontal { (i + 1, j) } else { (i, j + 1) };
            let point = |t: f64| [coord(0, i as f64 + t * (i1 - i) as f64), coord(1, j as f64 + t * (j1 - j) as f64)];
            let (mut lo, mut hi) = (0.0, 1.0);
            let s0 = sign(det(i, j));
            while hi - lo > ROOT_TOL {
                let mid = 0.5 * (lo + hi);
                let p = point(mid);
                if sign(at(p[0], p[1])) == s0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            point(0.5 * (lo + hi))
        })
    };
    let crosses = |a: f64, b: f64| a.is_finite() && b.is_finite() && sign(a) * sign(b) < 0;
    let mut segments: Vec<([usize; 3], [usize; 3])> = Vec::new();
    for j in 0..res {
        for i in 0..res {
            // the cell's edges, counter-clockwise from the bottom: (i, j, horizontal?)
            let edges = [(i, j, true), (i + 1, j, false), (i, j + 1, true), (i, j, false)];
            let ends = [((i, j), (i + 1, j)), ((i + 1, j), (i + 1, j + 1)), ((i, j + 1), (i + 1, j + 1)), ((i, j), (i, j + 1))];
            let hit: Vec<[usize; 3]> = edges
                .iter()
                .zip(ends)
                .filter(|(_, (a, b))| crosses(det(a.0, a.1), det(b.0, b.1)))
                .map(|(e, _)| [e.0, e.1, e.2 as usize])
                .collect();
            match hit.len() {
                2 => segments.push((hit[0], hit[1])),
                4 => {
                    // a saddle: the corner (i, j) joins the centre's side or not
                    let centre = at(coord(0, i as f64 + 0.5), coord(1, j as f64 + 0.5));
                    if sign(centre) == sign(det(i, j)) {
                        segments.push((hit[0], hit[1]));
                        segments.push((hit[2], hit[3]));
                    } else {
                        segments.push((hit[0], hit[3]));
                        segments.push((hit[1], hit[2]));
                    }
                }
                _ => {}
            }
        }
    }
    let chains = chain(&segments);
    Ok(chains.into_iter().map(|c| c.into_iter().map(|e| root(e[0], e[1], e[2] == 1)).collect()).collect())
}

/// Joins segments between edge ids into polylines (each id is shared by at most two segments).
fn chain(segments: &[([usize; 3], [usize; 3])]) -> Vec<Vec<[usize; 3]>> {
    let mut at: HashMap<[usize; 3], Vec<usize>> = HashMap::new();
    for (k, (a, b)) in segments.iter().enumerate() {
        at.entry(*a).or_default().push(k);
        at.entry(*b).or_default().push(k);
    }
    let mut used = vec![false; segments.len()];
    let mut out = Vec::new();
    // open chains first (from an end shared by one segment), then the closed loops
    let ends: Vec<usize> = (0..segments.len()).filter(|&k| at[&segments[k].0].len() == 1 || at[&segments[k].1].len() == 1).collect();
    for first in ends.into_iter().chain(0..segments.len()) {
        if used[first] {
            continue;
        }
        let (a, b) = segments[first];
        let (mut line, mut tip) = if at[&a].len() == 1 { (vec![a, b], b) } else { (vec![b, a], a) };
        used[first] = true;
        while let Some(&next) = at[&tip].iter().find(|&&k| !used[k]) {
            used[next] = true;
            let (c, d) = segments[next];
            tip = if c == tip { d } else { c };
            line.push(tip);
        }
        out.push(line);
    }
    out
}
