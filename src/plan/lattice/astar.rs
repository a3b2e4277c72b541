//! A* over the lattice's points and the special points (edge cost: the metric length along the
//! ray; heuristic: the metric distance to the goal, `space.rs`), through the seam of an angle axis
//! over a whole turn at cost 0; the path found is unwrapped across that seam.

use super::graph::Key;
use super::smooth::{initial_runs, turning_points};
use super::{LatticePlanner, Stage};
use crate::plan::PlanStatus;
use crate::order::Least;

/// An open-list entry: the heap pops the least f = g + h (key), ties broken by the least h,
/// then the least vertex (id). The item is the cost g from the start with which the vertex was
/// pushed: the entry is stale exactly when g is no longer the vertex's best cost (an exact
/// comparison of the stored number; recomputing it as f − h can exceed it by a rounding error,
/// which skipped live entries, platform-dependently).
pub(super) type Open = Least<f64>;

impl LatticePlanner {
    fn heuristic(&self, v: usize) -> f64 {
        self.metric(&self.coords_of(v), &self.goal)
    }

    pub(super) fn start_search(&mut self) {
        let s = self.ends[0];
        let h = self.heuristic(s);
        self.g.insert(s, 0.0);
        self.open.push(Open { key: h, tie: h, id: s, item: 0.0 });
        self.stage = Stage::Search;
    }

    /// The neighbours of `v` with edge costs: grid neighbours along each axis within one feasible
    /// piece of the ray between them, and the extra edges of special points and segments.
    fn neighbours(&self, v: usize) -> Vec<(usize, f64)> {
        let mut out = self.extra.get(&v).cloned().unwrap_or_default();
        if v < self.points() {
            let spec = &self.lattice.spec;
            let idx = spec.point_indices(v);
            let here = spec.coords(&idx);
            for a in 0..spec.axes.len() {
                let r = spec.ray_index(a, &idx);
                let ray = &self.lattice.rays[r];
                let Some(piece) = ray.piece_at(spec.value(a, idx[a])) else { continue };
                for j in [idx[a].wrapping_sub(1), idx[a] + 1] {
                    if j < spec.steps[a] && ray.piece_at(spec.value(a, j)) == Some(piece) {
                        let mut n = idx.clone();
                        n[a] = j;
                        let w = spec.point_index(&n);
                        out.push((w, self.metric(&here, &spec.coords(&n))));
                    }
                }
            }
        }
        out.extend(self.seam_twins(v).into_iter().map(|w| (w, 0.0)));
        out
    }

    /// The vertices that are the same pose as `v` across the seam of an angle axis over a whole
    /// turn: `v`'s value at one end of the range exchanged for the other end (grid points, and
    /// special points whose twin the start's or goal's rays also made).
    fn seam_twins(&self, v: usize) -> Vec<usize> {
        let spec = &self.lattice.spec;
        let wrapping = (0..spec.axes.len()).filter(|&a| spec.wraps(a));
        if v < self.points() {
            let idx = spec.point_indices(v);
            return wrapping.filter_map(|a| spec.seam_twin(&idx, a)).map(|twin| spec.point_index(&twin)).collect();
        }
        let c = self.coords_of(v);
        let keys = self.keys(&c);
        let mut out = vec![];
        for a in wrapping {
            let Key::Grid(i) = keys[a] else { continue };
            let last = spec.steps[a] - 1;
            if i == 0 || i == last {
                let mut twin = c.clone();
                twin[spec.axes[a].index()] = spec.value(a, last - i);
                out.extend(self.specials.iter().position(|s| *s == twin).map(|j| self.points() + j));
            }
        }
        out
    }

    pub(super) fn search_unit(&mut self) {
        let goal = self.ends[1];
        let Some(Open { item: g_pushed, id: v, .. }) = self.open.pop() else {
            self.status = Some(PlanStatus::NoPath);
            self.stage = Stage::Done;
            return;
        };
        if g_pushed > self.g.get(&v).copied().unwrap_or(f64::INFINITY) {
            return; // a stale entry: v was reached more cheaply since
        }
        self.expanded += 1;
        if v == goal {
            let mut path = vec![v];
            while let Some(&p) = self.parent.get(path.last().unwrap_or(&v)) {
                path.push(p);
            }
            path.reverse();
            self.polyline = self.unwrapped(&path);
            self.waypoints = turning_points(&self.polyline);
            self.runs = initial_runs(&self.waypoints);
            self.stage = Stage::Smooth { next: 0 };
            return;
        }
        let gv = self.g.get(&v).copied().unwrap_or(f64::INFINITY);
        for (w, cost) in self.neighbours(v) {
            let gw = gv + cost;
            if gw < self.g.get(&w).copied().unwrap_or(f64::INFINITY) {
                self.g.insert(w, gw);
                self.parent.insert(w, v);
                let h = self.heuristic(w);
                self.open.push(Open { key: gw + h, tie: h, id: w, item: gw });
            }
        }
    }

    /// The coordinates of the A* path `path`, continuous across the seam of a wrapping angle
    /// axis: a hop to the seam twin (the same pose) is dropped and the points after it keep going
    /// past the range's end (φ = π + 0.1 rather than −π + 0.1), so that every edge and every
    /// halving of it runs the short way along its ray.
    fn unwrapped(&self, path: &[usize]) -> Vec<Vec<f64>> {
        let mut shift = vec![0.0; self.start.len()];
        let mut out: Vec<Vec<f64>> = Vec::with_capacity(path.len());
        for (k, &w) in path.iter().enumerate() {
            let c = self.coords_of(w);
            if k > 0 && self.seam_twins(path[k - 1]).contains(&w) {
                let before = self.coords_of(path[k - 1]);
                for (s, (b, x)) in shift.iter_mut().zip(before.iter().zip(&c)) {
                    *s += b - x;
                }
                continue;
            }
            out.push(c.iter().zip(&shift).map(|(x, s)| x + s).collect());
        }
        out
    }
}
