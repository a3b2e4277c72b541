//! The ray lattice (Zhang's thesis §3.5, Figs. 3.9–3.12; Abbasnejad et al.'s lattice graph): over
//! a chosen set of pose coordinates, each with a range and a number of grid values, the others
//! fixed, a ray along each chosen coordinate through every grid point; each ray's feasible
//! intervals exactly, under every condition of the scenario (the verifier's own
//! [`crate::verify::ray_sections`]); the graph whose nodes are the feasible ray pieces and whose
//! edges join two pieces that both contain their rays' intersection point (a grid point); and its
//! connected components. An angle axis over one whole turn closes on itself: the grid points at
//! its two ends are the same pose and the pieces holding them are joined. [`point_grid`] is the point-wise grid at the same resolution, for
//! comparison (thesis Fig. 3.12(d)).
//!
//! [`Lattice`] is built in bounded, resumable steps ([`Lattice::step`], one ray per unit of work),
//! so the page can drive it between frames; the rays are independent of each other, so the loop
//! parallelises by handing each worker a range of ray indices and its own
//! [`crate::conditions::for_scenario`].

mod grid;

pub use grid::{point_grid, PointGrid};

use crate::conditions::{for_scenario, Condition, Kind};
use crate::error::{Error, Result};
use crate::model::Coord;
use crate::scenario::Scenario;
use crate::verify::slice::whole_turn;
use crate::verify::{check_ray_range, ray_sections, Sections};
use serde::Serialize;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Most grid values along one axis.
pub const MAX_STEPS: usize = 10_000;
/// Most rays in one lattice (each is one exact ray computation, ~1 ms on the thesis robot).
pub const MAX_RAYS: usize = 200_000;
/// Most grid points in one lattice (or point-wise grid).
pub const MAX_POINTS: usize = 4_000_000;

/// What to build: the axes, their ranges and grid values, and the fixed coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct LatticeSpec {
    /// The chosen coordinates, distinct, in the order given.
    pub axes: Vec<Coord>,
    /// Range [lo, hi] per axis.
    pub ranges: Vec<[f64; 2]>,
    /// Number of grid values per axis (≥ 2): lo + (hi − lo)·k/(steps − 1), k = 0 … steps − 1.
    pub steps: Vec<usize>,
    /// Every coordinate of the configuration (x, y, z, φ, θ, σ for a platform robot, the joint
    /// coordinates of a multi-link robot); the axes' entries are replaced along the grid.
    pub fixed: Vec<f64>,
}

impl LatticeSpec {
    /// A checked lattice request. `steps` has one entry for all axes or one per axis. Errors name
    /// the command-line option at fault (`--axes`, `--range`, `--steps`).
    pub fn new(axes: Vec<Coord>, ranges: Vec<[f64; 2]>, steps: Vec<usize>, fixed: impl Into<Vec<f64>>) -> Result<LatticeSpec> {
        let fixed: Vec<f64> = fixed.into();
        if axes.is_empty() {
            return Err(Error::new("--axes", "give at least one coordinate"));
        }
        for (i, a) in axes.iter().enumerate() {
            if axes[..i].contains(a) {
                return Err(Error::new("--axes", format!("{} is given twice", a.name())));
            }
        }
        if ranges.len() != axes.len() {
            return Err(Error::new("--range", format!("give one LO HI pair per axis: {} axes, {} pairs", axes.len(), ranges.len())));
        }
        for (a, r) in axes.iter().zip(&ranges) {
            check_ray_range(*a, r[0], r[1]).map_err(|e| Error::new("--range", format!("{}: {}", a.name(), e.reason)))?;
        }
        let steps = match steps.len() {
            1 => vec![steps[0]; axes.len()],
            n if n == axes.len() => steps,
            n => return Err(Error::new("--steps", format!("give one number for all axes or one per axis: {} axes, {n} numbers", axes.len()))),
        };
        for (a, &n) in axes.iter().zip(&steps) {
            if !(2..=MAX_STEPS).contains(&n) {
                return Err(Error::new("--steps", format!("{}: needs 2 to {MAX_STEPS} grid values (both ends of the range count), got {n}", a.name())));
            }
        }
        if let Some(i) = fixed.iter().position(|v| !v.is_finite()) {
            return Err(Error::new("pose", format!("coordinate {} is not finite", i + 1)));
        }
        if let Some(a) = axes.iter().find(|a| a.index() >= fixed.len()) {
            return Err(Error::new("--axes", format!("{} is not a coordinate of this robot", a.name())));
        }
        let spec = LatticeSpec { axes, ranges, steps, fixed };
        let rays = spec.ray_count();
        if rays > MAX_RAYS as f64 {
            return Err(Error::new(
                "--steps",
                format!("{:?} grid values on {} axes give {rays:.3e} rays; at most {MAX_RAYS} are allowed", spec.steps, spec.axes.len()),
            ));
        }
        let points = spec.point_count();
        if points > MAX_POINTS as f64 {
            return Err(Error::new(
                "--steps",
                format!("{:?} grid values on {} axes give {points:.3e} grid points; at most {MAX_POINTS} are allowed", spec.steps, spec.axes.len()),
            ));
        }
        Ok(spec)
    }

    /// Grid value `k` of axis `a` (exactly the range's ends at k = 0 and steps − 1).
    pub fn value(&self, a: usize, k: usize) -> f64 {
        let [lo, hi] = self.ranges[a];
        let last = self.steps[a] - 1;
        if k >= last {
            hi
        } else {
            lo + (hi - lo) * k as f64 / last as f64
        }
    }

    /// Whether axis `a` closes on itself: an angle over one whole turn (e.g. φ over [−π, π]), whose
    /// first and last grid values are the same orientation ([`whole_turn`]).
    pub fn wraps(&self, a: usize) -> bool {
        whole_turn(self.axes[a], self.ranges[a])
    }

    /// The grid point that is the same pose as `idx` across the seam of wrapping axis `a` (its
    /// index 0 and its last index exchanged), if `a` wraps and `idx` lies on one end of it.
    pub fn seam_twin(&self, idx: &[usize], a: usize) -> Option<Vec<usize>> {
        let last = self.steps[a] - 1;
        if !self.wraps(a) || (idx[a] != 0 && idx[a] != last) {
            return None;
        }
        let mut twin = idx.to_vec();
        twin[a] = last - idx[a];
        Some(twin)
    }

    /// Grid spacing along axis `a`.
    pub fn spacing(&self, a: usize) -> f64 {
        (self.ranges[a][1] - self.ranges[a][0]) / (self.steps[a] - 1) as f64
    }

    /// The index of `v` on axis `a`'s grid, if it is a grid value (to 1e-12 of the range).
    pub fn grid_index(&self, a: usize, v: f64) -> Option<usize> {
        let [lo, hi] = self.ranges[a];
        let x = (v - lo) / (hi - lo) * (self.steps[a] - 1) as f64;
        let k = x.round();
        ((x - k).abs() <= 1e-12 * (self.steps[a] as f64) && k >= 0.0 && k <= (self.steps[a] - 1) as f64).then_some(k as usize)
    }

    /// Number of rays, Σₐ Π_{b≠a} stepsᵦ (as a float: it may be huge before the cap is applied).
    pub fn ray_count(&self) -> f64 {
        (0..self.axes.len()).map(|a| self.steps.iter().enumerate().filter(|(b, _)| *b != a).map(|(_, &n)| n as f64).product::<f64>()).sum()
    }

    /// Number of grid points, Πₐ stepsₐ.
    pub fn point_count(&self) -> f64 {
        self.steps.iter().map(|&n| n as f64).product()
    }

    /// A one-line description of the resolution, for messages: `x: 7 values over [0.2, 3.8]
    /// (spacing 0.6), z: …`.
    pub fn resolution(&self) -> String {
        (0..self.axes.len())
            .map(|a| {
                let [lo, hi] = self.ranges[a];
                format!("{}: {} values over [{lo}, {hi}] (spacing {:.4})", self.axes[a].name(), self.steps[a], self.spacing(a))
            })
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// Flat index of a grid point from its per-axis indices (first axis fastest).
    pub fn point_index(&self, idx: &[usize]) -> usize {
        let mut flat = 0;
        for a in (0..self.axes.len()).rev() {
            flat = flat * self.steps[a] + idx[a];
        }
        flat
    }

    /// Per-axis indices of grid point `flat`.
    pub fn point_indices(&self, mut flat: usize) -> Vec<usize> {
        self.steps
            .iter()
            .map(|&n| {
                let k = flat % n;
                flat /= n;
                k
            })
            .collect()
    }

    /// The coordinates of the grid point with per-axis indices `idx`.
    pub fn coords(&self, idx: &[usize]) -> Vec<f64> {
        let mut c = self.fixed.clone();
        for (a, &k) in idx.iter().enumerate() {
            c[self.axes[a].index()] = self.value(a, k);
        }
        c
    }

    /// Rays along axis `a`: Π_{b≠a} stepsᵦ.
    fn rays_along(&self, a: usize) -> usize {
        self.steps.iter().enumerate().filter(|(b, _)| *b != a).map(|(_, &n)| n).product()
    }

    /// Ray number `r` (in the order axis by axis, then grid point of the other axes, first axis
    /// fastest): its axis and the per-axis indices of its grid line (the axis' own entry 0).
    pub fn ray_at(&self, mut r: usize) -> (usize, Vec<usize>) {
        let mut a = 0;
        while a + 1 < self.axes.len() && r >= self.rays_along(a) {
            r -= self.rays_along(a);
            a += 1;
        }
        let idx = self
            .steps
            .iter()
            .enumerate()
            .map(|(b, &n)| {
                if b == a {
                    return 0;
                }
                let k = r % n;
                r /= n;
                k
            })
            .collect();
        (a, idx)
    }

    /// The number of the ray along axis `a` through the grid point with indices `idx` (the
    /// inverse of [`LatticeSpec::ray_at`]).
    pub fn ray_index(&self, a: usize, idx: &[usize]) -> usize {
        let offset: usize = (0..a).map(|b| self.rays_along(b)).sum();
        let mut local = 0;
        for b in (0..self.axes.len()).rev() {
            if b != a {
                local = local * self.steps[b] + idx[b];
            }
        }
        offset + local
    }
}

/// One ray of the lattice and its exact sections.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Ray {
    /// The coordinate varied.
    pub vary: String,
    /// Index of that coordinate among the lattice's axes.
    #[serde(skip)]
    pub axis: usize,
    /// The grid indices of the other axes (the varied axis' entry is 0).
    #[serde(skip)]
    pub cell: Vec<usize>,
    /// Every other coordinate's value (the other axes' grid values and the fixed coordinates):
    /// `{"y": 2, "z": 0.8667, "phi": 0, …}` in configuration order (x, y, z, φ, θ, σ for a
    /// platform robot).
    #[serde(serialize_with = "as_object")]
    pub fixed: Vec<(String, f64)>,
    /// Feasible intervals of the varied coordinate, certified (the lattice's pieces).
    pub feasible: Vec<[f64; 2]>,
    /// Intervals the verifier could not certify either way (counted as infeasible).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub uncertain: Vec<[f64; 2]>,
}

/// The scenario's conditions of `kind` (`None`: all).
fn conditions_of(s: &Scenario, kind: Option<Kind>) -> Vec<Box<dyn Condition>> {
    for_scenario(s).into_iter().filter(|c| kind.is_none_or(|k| c.kind() == k)).collect()
}

/// The exact sections of ray `r` of `spec` under `conditions`.
fn ray_of(s: &Scenario, conditions: &[Box<dyn Condition>], spec: &LatticeSpec, r: usize) -> Sections {
    let (a, cell) = spec.ray_at(r);
    let [lo, hi] = spec.ranges[a];
    ray_sections(s, conditions, &spec.coords(&cell), spec.axes[a], lo, hi)
}

fn as_object<S: serde::Serializer>(v: &[(String, f64)], ser: S) -> std::result::Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let mut m = ser.serialize_map(Some(v.len()))?;
    for (k, x) in v {
        m.serialize_entry(k, x)?;
    }
    m.end()
}

impl Ray {
    /// The index of the feasible piece containing `v`, if any.
    pub fn piece_at(&self, v: f64) -> Option<usize> {
        let k = self.feasible.partition_point(|iv| iv[1] < v);
        self.feasible.get(k).filter(|iv| iv[0] <= v && v <= iv[1]).map(|_| k)
    }
}

/// Progress of a lattice being built.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct LatticeProgress {
    /// Rays computed so far.
    pub rays_done: usize,
    /// Rays in all.
    pub rays_total: usize,
    /// Whether the rays, the graph and its components are complete.
    pub done: bool,
}

/// The ray lattice of a scenario, built ray by ray.
pub struct Lattice {
    scenario: Scenario,
    /// Which conditions (`None`: all of the scenario's), so that threads can make their own.
    kind: Option<Kind>,
    conditions: Vec<Box<dyn Condition>>,
    /// The request.
    pub spec: LatticeSpec,
    /// The rays computed so far, in [`LatticeSpec::ray_at`] order.
    pub rays: Vec<Ray>,
    total: usize,
    graph: Option<Graph>,
}

/// The graph of feasible ray pieces, once every ray is computed.
#[derive(Debug, Clone, PartialEq)]
pub struct Graph {
    /// Offset of each ray's first piece in the piece numbering (pieces numbered ray by ray).
    pub piece_offset: Vec<usize>,
    /// Component (0-based, in order of first piece) of each piece.
    pub piece_component: Vec<usize>,
    /// Number of connected components.
    pub components: usize,
    /// Edges: pairs of pieces joined at a grid point (or across the seam of a wrapping axis).
    pub edges: usize,
    /// Per grid point (flat index): whether every ray through it holds it in a feasible piece.
    pub point_feasible: Vec<bool>,
    /// Grid points where the rays through them disagree (some hold it feasible, some not: a grid
    /// point within the boundary tolerance of a ray's boundary). 0 normally.
    pub disagreements: usize,
}

impl Lattice {
    /// Prepares the lattice of `scenario` for `spec`; no ray is computed yet.
    pub fn new(scenario: &Scenario, spec: LatticeSpec) -> Lattice {
        Lattice::of_kind(scenario, spec, None)
    }

    /// [`Lattice::new`] under the scenario's conditions of `kind` only (`None`: all), e.g. the
    /// interference-free or the wrench-closure workspace alone.
    pub fn of_kind(scenario: &Scenario, spec: LatticeSpec, kind: Option<Kind>) -> Lattice {
        let total = spec.ray_count() as usize;
        let conditions = conditions_of(scenario, kind);
        Lattice { scenario: scenario.clone(), kind, conditions, spec, rays: Vec::with_capacity(total), total, graph: None }
    }

    /// Computes up to `budget` more rays (at least one); once all are computed, the same call
    /// builds the graph and its components (linear in the grid points).
    pub fn step(&mut self, budget: usize) -> LatticeProgress {
        for _ in 0..budget.max(1) {
            if self.rays.len() >= self.total {
                break;
            }
            let ray = self.compute(self.rays.len());
            self.rays.push(ray);
        }
        if self.rays.len() >= self.total && self.graph.is_none() {
            self.graph = Some(self.build_graph());
        }
        self.progress()
    }

    /// Where the build is.
    pub fn progress(&self) -> LatticeProgress {
        LatticeProgress { rays_done: self.rays.len(), rays_total: self.total, done: self.graph.is_some() }
    }

    /// Runs [`Lattice::step`] to the end, on this thread alone.
    pub fn build(scenario: &Scenario, spec: LatticeSpec) -> Lattice {
        let mut l = Lattice::new(scenario, spec);
        while !l.step(64).done {}
        l
    }

    /// Computes every ray not computed yet, spread over threads natively (each worker with its
    /// own conditions; in order on wasm), counting the finished rays in `done`; then the graph.
    /// The rays come out in order, equal to [`Lattice::step`]'s.
    pub fn finish(&mut self, done: &AtomicUsize) -> LatticeProgress {
        let first = self.rays.len();
        let (scenario, kind, spec) = (&self.scenario, self.kind, &self.spec);
        let sections = crate::parallel::map_with(self.total - first, || conditions_of(scenario, kind), |conditions, i| {
            let sec = ray_of(scenario, conditions, spec, first + i);
            done.fetch_add(1, Ordering::Relaxed);
            sec
        });
        for (i, sec) in sections.into_iter().enumerate() {
            let ray = self.ray_with(first + i, sec.feasible, sec.uncertain);
            self.rays.push(ray);
        }
        self.step(1)
    }

    /// [`Lattice::build`] with the rays spread over threads ([`Lattice::finish`]).
    pub fn build_parallel(scenario: &Scenario, spec: LatticeSpec) -> Lattice {
        let mut l = Lattice::new(scenario, spec);
        l.finish(&AtomicUsize::new(0));
        l
    }

    /// The graph, once done.
    pub fn graph(&self) -> Option<&Graph> {
        self.graph.as_ref()
    }

    /// The scenario the lattice is of.
    pub fn scenario(&self) -> &Scenario {
        &self.scenario
    }

    /// The exact sections of the ray through `c` along axis `a` over the axis' range (rays through
    /// points off the grid: a planner's start and goal).
    pub fn cast(&self, c: &[f64], a: usize) -> Sections {
        let [lo, hi] = self.spec.ranges[a];
        ray_sections(&self.scenario, &self.conditions, c, self.spec.axes[a], lo, hi)
    }

    /// Ray `r` computed exactly.
    fn compute(&self, r: usize) -> Ray {
        let sec = ray_of(&self.scenario, &self.conditions, &self.spec, r);
        self.ray_with(r, sec.feasible, sec.uncertain)
    }

    /// Ray `r` with its sections `feasible` and `uncertain`, computed here or elsewhere (the
    /// page's workers compute rays apart and join them).
    pub fn ray_with(&self, r: usize, feasible: Vec<[f64; 2]>, uncertain: Vec<[f64; 2]>) -> Ray {
        let (a, cell) = self.spec.ray_at(r);
        let (coord, c) = (self.spec.axes[a], self.spec.coords(&cell));
        let s = &self.scenario;
        let fixed = (0..c.len()).filter(|&k| k != coord.index()).map(|k| (s.coord_name(s.coord_at(k)), c[k])).collect();
        Ray { vary: s.coord_name(coord), axis: a, cell, fixed, feasible, uncertain }
    }

    /// The pieces containing grid point `idx` (one per ray through it that holds it feasible), as
    /// (ray, piece) pairs.
    pub fn pieces_at(&self, idx: &[usize]) -> Vec<(usize, usize)> {
        (0..self.spec.axes.len())
            .filter_map(|a| {
                let r = self.spec.ray_index(a, idx);
                self.rays[r].piece_at(self.spec.value(a, idx[a])).map(|p| (r, p))
            })
            .collect()
    }

    fn build_graph(&self) -> Graph {
        let mut piece_offset = Vec::with_capacity(self.rays.len());
        let mut n = 0;
        for ray in &self.rays {
            piece_offset.push(n);
            n += ray.feasible.len();
        }
        let mut uf = UnionFind::new(n);
        let k = self.spec.axes.len();
        let points = self.spec.point_count() as usize;
        let mut point_feasible = vec![false; points];
        let (mut edges, mut disagreements) = (0, 0);
        for (flat, slot) in point_feasible.iter_mut().enumerate() {
            let idx = self.spec.point_indices(flat);
            let pieces = self.pieces_at(&idx);
            *slot = pieces.len() == k;
            if !pieces.is_empty() && pieces.len() < k {
                disagreements += 1;
            }
            for w in pieces.windows(2) {
                let (p, q) = (piece_offset[w[0].0] + w[0].1, piece_offset[w[1].0] + w[1].1);
                uf.union(p, q);
                edges += 1;
            }
        }
        // across the seam of a wrapping axis: a grid point at the range's start is the same pose as
        // its twin at the end, so the pieces holding either are joined (one edge per twin pair)
        for a in (0..k).filter(|&a| self.spec.wraps(a)) {
            for flat in 0..points {
                let idx = self.spec.point_indices(flat);
                let Some(twin) = self.spec.seam_twin(&idx, a).filter(|_| idx[a] == 0) else { continue };
                if let (Some(&(r, p)), Some(&(s, q))) = (self.pieces_at(&idx).first(), self.pieces_at(&twin).first()) {
                    uf.union(piece_offset[r] + p, piece_offset[s] + q);
                    edges += 1;
                }
            }
        }
        let (piece_component, components) = uf.labels();
        Graph { piece_offset, piece_component, components, edges, point_feasible, disagreements }
    }

    /// The component of grid point `idx`, if it is feasible.
    pub fn component_at(&self, idx: &[usize]) -> Option<usize> {
        let g = self.graph.as_ref()?;
        if !g.point_feasible[self.spec.point_index(idx)] {
            return None;
        }
        let r = self.spec.ray_index(0, idx);
        let p = self.rays[r].piece_at(self.spec.value(0, idx[0]))?;
        Some(g.piece_component[g.piece_offset[r] + p])
    }

    /// The serialisable summary (`cablenav lattice --json`).
    pub fn report(&self) -> Option<LatticeReport> {
        let g = self.graph.as_ref()?;
        let pieces = g.piece_component.len();
        let points = g.point_feasible.len();
        let point_components: Vec<Option<usize>> = (0..points).map(|flat| self.component_at(&self.spec.point_indices(flat))).collect();
        let grid_components = point_components.iter().flatten().collect::<std::collections::BTreeSet<_>>().len();
        let (_, pointwise_components) = grid::neighbour_components(&self.spec, &g.point_feasible);
        Some(LatticeReport {
            axes: self.spec.axes.iter().map(|&a| self.scenario.coord_name(a)).collect(),
            ranges: self.spec.ranges.clone(),
            steps: self.spec.steps.clone(),
            fixed: self.spec.fixed.clone(),
            rays: self.rays.clone(),
            pieces,
            edges: g.edges,
            components: g.components,
            piece_components: self.rays.iter().enumerate().map(|(r, ray)| (0..ray.feasible.len()).map(|p| g.piece_component[g.piece_offset[r] + p]).collect()).collect(),
            grid_points: points,
            feasible_points: g.point_feasible.iter().filter(|&&f| f).count(),
            point_components,
            grid_components,
            sliver_components: g.components - grid_components,
            pointwise_components,
            missed_separations: grid_components.saturating_sub(pointwise_components),
            disagreements: g.disagreements,
            uncertain_rays: self.rays.iter().filter(|r| !r.uncertain.is_empty()).count(),
            warnings: self.scenario.warnings.iter().cloned().chain(self.spec.axes.iter().zip(&self.spec.ranges).filter_map(|(&a, &r)| self.scenario.range_warning(a, r))).collect(),
        })
    }
}

/// The lattice as `cablenav lattice --json` prints it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LatticeReport {
    /// The chosen coordinates.
    pub axes: Vec<String>,
    /// Their ranges.
    pub ranges: Vec<[f64; 2]>,
    /// Their numbers of grid values.
    pub steps: Vec<usize>,
    /// The coordinates the others are held at (x, y, z, φ, θ, σ for a platform robot).
    pub fixed: Vec<f64>,
    /// Every ray with its feasible intervals.
    pub rays: Vec<Ray>,
    /// Feasible ray pieces (the graph's nodes).
    pub pieces: usize,
    /// Joins between pieces at grid points (the graph's edges, a grid point with j feasible rays
    /// counting j − 1; a pair of grid points joined across the seam of an angle axis over a
    /// whole turn counting 1 more).
    pub edges: usize,
    /// Connected components of the graph.
    pub components: usize,
    /// Per ray, the component of each of its feasible pieces.
    pub piece_components: Vec<Vec<usize>>,
    /// Grid points.
    pub grid_points: usize,
    /// Grid points feasible on every ray through them.
    pub feasible_points: usize,
    /// Per grid point (first axis fastest), its component or `null` where infeasible.
    pub point_components: Vec<Option<usize>>,
    /// Components that hold a grid point feasible on every ray through it.
    pub grid_components: usize,
    /// Components that hold no such grid point: slivers of feasible ray pieces between grid
    /// points (`components − grid_components`), which a point-wise grid cannot see at all.
    pub sliver_components: usize,
    /// The components the same grid points form joined to their feasible grid neighbours (as a
    /// point-wise grid joins them, assuming the segment between two feasible samples feasible).
    pub pointwise_components: usize,
    /// Separations of grid points the point-wise grid misses: `grid_components −
    /// pointwise_components`, each a pair of neighbouring feasible grid points whose ray segment
    /// leaves the feasible set in between (certified by the rays).
    pub missed_separations: usize,
    /// Grid points where the rays through them disagree (0 normally).
    pub disagreements: usize,
    /// Rays with an uncertain section.
    pub uncertain_rays: usize,
    /// The scenario's warnings.
    pub warnings: Vec<String>,
}

/// Disjoint sets with path halving and union by size.
pub(crate) struct UnionFind {
    parent: Vec<usize>,
    size: Vec<usize>,
}

impl UnionFind {
    pub(crate) fn new(n: usize) -> UnionFind {
        UnionFind { parent: (0..n).collect(), size: vec![1; n] }
    }

    pub(crate) fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    pub(crate) fn union(&mut self, a: usize, b: usize) {
        let (mut a, mut b) = (self.find(a), self.find(b));
        if a == b {
            return;
        }
        if self.size[a] < self.size[b] {
            std::mem::swap(&mut a, &mut b);
        }
        self.parent[b] = a;
        self.size[a] += self.size[b];
    }

    /// A label per element, numbered 0, 1, … in order of first appearance, and their count.
    pub(crate) fn labels(&mut self) -> (Vec<usize>, usize) {
        let n = self.parent.len();
        let mut label = vec![usize::MAX; n];
        let mut out = Vec::with_capacity(n);
        let mut next = 0;
        for x in 0..n {
            let r = self.find(x);
            if label[r] == usize::MAX {
                label[r] = next;
                next += 1;
            }
            out.push(label[r]);
        }
        (out, next)
    }
}
