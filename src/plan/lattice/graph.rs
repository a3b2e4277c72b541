//! The search's vertices and their joining: grid points are numbered by their flat index, special
//! points (the start, the goal, where their rays cross lattice rays) after them; the start and the
//! goal are joined to the lattice through their own rays and by exactly verified segments to the
//! corners of their grid cell.

use super::LatticePlanner;
use crate::lattice::Ray;

/// One grid axis key of a point: on the grid (its index) or off it (its value).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Key {
    Grid(usize),
    Off(f64),
}

/// A ray through the start or the goal that is not a lattice ray.
#[derive(Debug, Clone)]
pub(super) struct EndRay {
    axis: usize,
    feasible: Vec<[f64; 2]>,
}

impl LatticePlanner {
    pub(super) fn points(&self) -> usize {
        self.lattice.spec.point_count() as usize
    }

    pub(super) fn coords_of(&self, v: usize) -> Vec<f64> {
        let n = self.points();
        if v < n {
            self.lattice.spec.coords(&self.lattice.spec.point_indices(v))
        } else {
            self.specials[v - n].clone()
        }
    }

    pub(super) fn keys(&self, c: &[f64]) -> Vec<Key> {
        let spec = &self.lattice.spec;
        (0..spec.axes.len()).map(|a| spec.grid_index(a, c[spec.axes[a].index()]).map_or(Key::Off(c[spec.axes[a].index()]), Key::Grid)).collect()
    }

    /// The vertex for `c`: its grid point if every key is on the grid, else a new special point.
    fn vertex(&mut self, c: Vec<f64>) -> usize {
        let keys = self.keys(&c);
        if keys.iter().all(|k| matches!(k, Key::Grid(_))) {
            let idx: Vec<usize> = keys.iter().map(|k| if let Key::Grid(i) = k { *i } else { 0 }).collect();
            return self.lattice.spec.point_index(&idx);
        }
        let n = self.points();
        if let Some(j) = self.specials.iter().position(|s| *s == c) {
            return n + j;
        }
        self.specials.push(c);
        n + self.specials.len() - 1
    }

    fn add_edge(&mut self, a: usize, b: usize) {
        if a == b {
            return;
        }
        let cost = self.metric(&self.coords_of(a), &self.coords_of(b));
        self.extra.entry(a).or_default().push((b, cost));
        self.extra.entry(b).or_default().push((a, cost));
    }

    /// Joins the start and goal to the lattice through their rays; returns the segments to their
    /// cell corners still to verify, as (special vertex, corner vertex).
    pub(super) fn join_rays(&mut self) -> Vec<(usize, usize)> {
        let k = self.lattice.spec.axes.len();
        let (fixed, axes) = (&self.lattice.spec.fixed, &self.lattice.spec.axes);
        let ends = [self.space.end_coords(&self.start, fixed, axes), self.space.end_coords(&self.goal, fixed, axes)];
        let ids = [self.vertex(ends[0].clone()), self.vertex(ends[1].clone())];
        self.ends = ids;
        let mut segments = vec![];
        for (e, c) in ends.iter().enumerate() {
            let v = ids[e];
            if v < self.points() {
                continue; // a grid point: on the lattice already
            }
            let keys = self.keys(c);
            for a in 0..k {
                let off: Vec<usize> = (0..k).filter(|&b| b != a && matches!(keys[b], Key::Off(_))).collect();
                if off.is_empty() {
                    // c lies on the lattice ray along a: join it to its grid neighbours on that ray
                    self.join_on_lattice_ray(v, a, &keys);
                    continue;
                }
                // c's own ray along a
                let feasible = self.lattice.cast(c, a).feasible;
                self.end_rays.push(EndRay { axis: a, feasible });
                let ray_no = self.end_rays.len() - 1;
                let mut on_ray: Vec<usize> = vec![v];
                if off.len() == 1 {
                    // it crosses the lattice rays along `off[0]` at a's grid values
                    let b = off[0];
                    for i in 0..self.lattice.spec.steps[a] {
                        let mut x = c.clone();
                        x[self.lattice.spec.axes[a].index()] = self.lattice.spec.value(a, i);
                        let wk = self.keys(&x);
                        let w = self.vertex(x);
                        on_ray.push(w);
                        self.join_on_lattice_ray(w, b, &wk);
                    }
                }
                // the other end, if it lies on this ray
                let other = ids[1 - e];
                let oc = self.coords_of(other);
                if (0..k).filter(|&b| b != a).all(|b| oc[self.lattice.spec.axes[b].index()] == c[self.lattice.spec.axes[b].index()]) {
                    on_ray.push(other);
                }
                self.chain(ray_no, on_ray);
            }
            // segments to the feasible corners of c's grid cell
            let spec = &self.lattice.spec;
            let lows: Vec<usize> = (0..k).map(|a| match keys[a] {
                Key::Grid(i) => i,
                Key::Off(x) => ((((x - spec.ranges[a][0]) / spec.spacing(a)).floor().max(0.0)) as usize).min(spec.steps[a] - 2),
            }).collect();
            for corner in 0..(1usize << k) {
                let idx: Vec<usize> = (0..k).map(|a| match keys[a] {
                    Key::Grid(i) => i,
                    Key::Off(_) => lows[a] + ((corner >> a) & 1),
                }).collect();
                let w = spec.point_index(&idx);
                if self.lattice.graph().is_some_and(|g| g.point_feasible[w]) && !segments.contains(&(v, w)) {
                    segments.push((v, w));
                }
            }
        }
        segments
    }

    /// Joins vertex `v` (keys `keys`, on the grid in every axis but `a`) to the nearest grid points
    /// on both sides along the lattice ray along `a`, where the same feasible piece holds both.
    fn join_on_lattice_ray(&mut self, v: usize, a: usize, keys: &[Key]) {
        let spec = &self.lattice.spec;
        let mut idx: Vec<usize> = keys.iter().map(|k| if let Key::Grid(i) = k { *i } else { 0 }).collect();
        let Key::Off(x) = keys[a] else { return };
        let r = spec.ray_index(a, &idx);
        let ray: &Ray = &self.lattice.rays[r];
        let Some(piece) = ray.piece_at(x) else { return };
        let below = ((x - spec.ranges[a][0]) / spec.spacing(a)).floor().max(0.0) as usize;
        let mut joins = vec![];
        for i in [below, below + 1] {
            if i < spec.steps[a] && ray.piece_at(spec.value(a, i)) == Some(piece) {
                idx[a] = i;
                joins.push(spec.point_index(&idx));
            }
        }
        for w in joins {
            self.add_edge(v, w);
        }
    }

    /// Joins consecutive vertices of `on_ray` (all on end ray `ray_no`) that one feasible piece holds.
    fn chain(&mut self, ray_no: usize, mut on_ray: Vec<usize>) {
        let a = self.end_rays[ray_no].axis;
        let ax = self.lattice.spec.axes[a].index();
        let mut with_value: Vec<(f64, usize)> = on_ray.drain(..).map(|v| (self.coords_of(v)[ax], v)).collect();
        crate::order::sort_by_key(&mut with_value, |p| p.0);
        let ray = &self.end_rays[ray_no];
        let piece = |x: f64| ray.feasible.iter().position(|iv| iv[0] <= x && x <= iv[1]);
        let pairs: Vec<(usize, usize)> =
            with_value.windows(2).filter(|w| piece(w[0].0).is_some() && piece(w[0].0) == piece(w[1].0)).map(|w| (w[0].1, w[1].1)).collect();
        for (p, q) in pairs {
            self.add_edge(p, q);
        }
    }

    /// Verifies the straight segment (line + slerp; a path through the two configurations) from
    /// `v` to grid point `w` exactly; joins them if it is feasible throughout.
    pub(super) fn try_segment(&mut self, v: usize, w: usize) {
        self.segments[1] += 1;
        if let Some(r) = self.space.verify_segment(self.lattice.scenario(), &self.coords_of(v), &self.coords_of(w)) {
            if r.infeasible.is_empty() && r.uncertain.is_empty() {
                self.segments[0] += 1;
                self.add_edge(v, w);
            }
        }
    }
}
