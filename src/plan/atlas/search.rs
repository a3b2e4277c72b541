//! A* over the chart centres of an atlas that grows as the search goes (Bohigas et al. §4): the
//! chart with least f = g + w·h is popped (w = 1: A*; w > 1: weighted A*, Pohl 1970), tested for
//! the goal, and expanded fully before its neighbours are relaxed. g sums the manifold's distance
//! between consecutive centres and h is the distance to the nearest goal point, so h is
//! admissible. Edges are checked lazily: when a chart path is found its dense path is built edge
//! by edge, and an edge whose walks do not meet or whose motions the manifold's motion validator
//! rejects is removed and the search restarted on the atlas built so far.
//!
//! Generic over [`Manifold`] and resumable: [`Continuation::step`] does a bounded amount of work.

use super::atlas::{Atlas, AtlasParams};
use super::chart::ChartState;
use super::manifold::Manifold;
use crate::order::Least;
use std::collections::{BinaryHeap, HashMap, HashSet};

/// How a search ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ended {
    /// A dense path to a goal point was built.
    Found,
    /// Every chart reachable from the start was expanded without reaching a goal point.
    Exhausted,
    /// The chart budget ran out.
    Budget,
}

/// Progress of a continuation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContinuationProgress {
    /// Charts in the atlas.
    pub charts: usize,
    /// Entries in the open list.
    pub open: usize,
    /// Least heuristic over the open list (infinity when empty).
    pub best_heuristic: f64,
    /// How it ended, once it has.
    pub ended: Option<Ended>,
}

/// An open-list entry: the heap pops the least f (key), ties broken by the least h, then the
/// least chart (id).
type Entry = Least<()>;

/// A chart path to a goal whose dense path is being built, one edge per unit of work.
struct Pending {
    /// Chart indices from the start chart to the chart holding the goal.
    chain: Vec<usize>,
    /// The goal point reached.
    goal: Vec<f64>,
    /// The goal's tangent coordinates in the last chart.
    t: Vec<f64>,
    /// Index in `chain` of the next edge's first chart.
    next: usize,
    /// The dense path so far.
    points: Vec<Vec<f64>>,
}

/// An atlas and an A* search over it, from the start point to any of the goal points. The atlas
/// outlives a search: [`Continuation::retarget`] starts another one (another start and goal on
/// the same manifold) on the atlas built so far, which then grows only where the new search needs
/// it.
pub struct Continuation<M: Manifold> {
    /// The atlas built so far.
    pub atlas: Atlas<M>,
    goals: Vec<Vec<f64>>,
    /// The chart the search starts from: the one holding the start point.
    start: usize,
    /// The dense path from the start point to that chart's centre (the start point alone when it
    /// is the centre).
    prefix: Vec<Vec<f64>>,
    /// Whether popped open charts are expanded. A retargeted search first runs on the atlas as
    /// it is (open charts only relaxed) and grows it only if that finds no path.
    grow: bool,
    /// Whether the current pass reached an open chart it did not expand.
    skipped_open: bool,
    max_charts: usize,
    /// The heuristic's weight w in f = g + w·h (1: A*).
    weight: f64,
    g: Vec<f64>,
    parent: Vec<Option<usize>>,
    popped: Vec<bool>,
    open: BinaryHeap<Entry>,
    expanding: Option<usize>,
    /// The path being built, if a goal was reached.
    pending: Option<Pending>,
    /// Chart pairs whose dense edge could not be built or failed the motion validator (removed
    /// from the graph).
    broken: HashSet<(usize, usize)>,
    /// Of those, the pairs whose dense edge was built but rejected by the motion validator.
    rejected: usize,
    /// Walks from a goal's chart to the goal that could not be followed (a numerical failure,
    /// counted with the broken edges).
    goal_walk_failures: usize,
    /// Motion-validator calls made so far.
    motion_checks: usize,
    /// Steps the motion validator accepted, by their two points' bits (either order): walks and
    /// edges that later searches repeat or reverse are not validated again.
    valid_steps: HashSet<Vec<u64>>,
    /// Dense edges built so far, by (from, to) chart; `None` for a broken one.
    edges: HashMap<(usize, usize), Option<Vec<Vec<f64>>>>,
    ended: Option<Ended>,
    path: Vec<Vec<f64>>,
    /// The charts the path runs through, start chart first.
    path_charts: Vec<usize>,
}

impl<M: Manifold> Continuation<M> {
    /// A search from `start` (a point of the manifold) to any of `goals` (points of the manifold;
    /// none: explore the start's whole component), with at most `max_charts` charts, popping
    /// charts by f = g + `weight`·h (1: A*; above 1: weighted A*, which goes more directly
    /// towards the goal and creates far fewer charts in high dimensions, for a chart path that
    /// may be up to `weight` times longer; the weight orders the expansion only: `Exhausted`
    /// still means every chart reachable from the start was expanded).
    pub fn new(manifold: M, start: &[f64], goals: Vec<Vec<f64>>, params: AtlasParams, max_charts: usize, weight: f64) -> Result<Continuation<M>, String> {
        let mut s = Continuation::resume(Atlas::new(manifold, start, params)?, goals, max_charts, weight);
        s.grow = true;
        Ok(s)
    }

    /// A continuation on an atlas made before (read from a file), searching from its chart 0 to
    /// `goals` over the charts there are; [`Continuation::retarget`] gives it its own start.
    pub fn resume(atlas: Atlas<M>, goals: Vec<Vec<f64>>, max_charts: usize, weight: f64) -> Continuation<M> {
        let start = atlas.charts[0].centre.clone();
        let mut s = Continuation {
            atlas,
            goals,
            start: 0,
            prefix: vec![start],
            grow: false,
            skipped_open: false,
            max_charts: max_charts.max(1),
            weight,
            g: vec![],
            parent: vec![],
            popped: vec![],
            open: BinaryHeap::new(),
            expanding: None,
            pending: None,
            broken: HashSet::new(),
            rejected: 0,
            goal_walk_failures: 0,
            motion_checks: 0,
            valid_steps: HashSet::new(),
            edges: HashMap::new(),
            ended: None,
            path: vec![],
            path_charts: vec![],
        };
        s.restart();
        s
    }

    /// Starts a new search from `starts` (points of the manifold that stand for one start, as the
    /// goal points stand for one goal; at least one) to any of `goals` on the atlas built so far,
    /// keeping its charts and the dense edges already built and checked between them. The start
    /// is reached from the first chart whose ball holds one of its points (by a walk the motion
    /// validator accepts); where none does, a chart is added at the first point. The search first runs
    /// over the charts there are, expanding none; only if that finds no path while some chart it
    /// reached is still open does it start again, growing the atlas as a first search does. The
    /// chart budget counts the whole atlas. Fails only if no chart can be made at the start.
    pub fn retarget(&mut self, starts: &[Vec<f64>], goals: Vec<Vec<f64>>) -> Result<(), String> {
        let start = starts.first().ok_or("no start point")?;
        let charts = (0..self.atlas.charts.len()).filter(|&c| self.atlas.charts[c].state != ChartState::Blocked);
        let held = starts.iter().flat_map(|x| charts.clone().map(move |c| (c, x))).find_map(|(c, x)| {
            let t = self.atlas.locate(c, x)?;
            let mut walk = self.atlas.walk(c, &t)?;
            walk.reverse();
            // a start at the centre itself walks one step of length zero
            walk.dedup_by(|a, b| self.atlas.manifold.distance(a, b) <= 1e-12);
            Some((c, walk))
        });
        let (chart, prefix) = match held.filter(|(_, walk)| self.motions_valid(walk)) {
            Some(found) => found,
            None => (self.atlas.insert(start)?, vec![start.to_vec()]),
        };
        self.start = chart;
        self.prefix = prefix;
        self.goals = goals;
        self.ended = None;
        self.path.clear();
        self.path_charts.clear();
        self.grow = false;
        self.restart();
        Ok(())
    }

    /// Forgets the search state (not the atlas) and starts again from the start chart.
    fn restart(&mut self) {
        let n = self.atlas.charts.len();
        self.g = vec![f64::INFINITY; n];
        self.parent = vec![None; n];
        self.popped = vec![false; n];
        self.open.clear();
        self.expanding = None;
        self.pending = None;
        self.skipped_open = false;
        self.g[self.start] = 0.0;
        let h = self.heuristic(self.start);
        self.open.push(Entry { key: self.weight * h, tie: h, id: self.start, item: () });
    }

    /// Distance from chart `c`'s centre to the nearest goal point (0 with no goals).
    fn heuristic(&self, c: usize) -> f64 {
        if self.goals.is_empty() {
            return 0.0;
        }
        let x = &self.atlas.charts[c].centre;
        self.goals.iter().map(|g| self.atlas.manifold.distance(x, g)).fold(f64::INFINITY, f64::min)
    }

    /// How it ended, if it has.
    pub fn ended(&self) -> Option<Ended> {
        self.ended
    }

    /// The dense path (points of the manifold) once [`Ended::Found`]; empty otherwise.
    pub fn path(&self) -> &[Vec<f64>] {
        &self.path
    }

    /// The charts the path runs through, from the start's chart to the goal's, once
    /// [`Ended::Found`]; empty otherwise.
    pub fn path_charts(&self) -> &[usize] {
        &self.path_charts
    }

    /// Chart pairs removed from the graph because their dense edge could not be followed (the
    /// two walks did not meet or one hit its projection cap: a numerical failure, like an
    /// expansion failure), plus walks from a goal's chart to the goal that could not be followed.
    pub fn broken_edges(&self) -> usize {
        self.broken.len() - self.rejected + self.goal_walk_failures
    }

    /// Motion-validator calls made so far (one per step of a dense path checked).
    pub fn motion_checks(&self) -> usize {
        self.motion_checks
    }

    /// Chart pairs removed from the graph because the motion validator rejected their dense edge.
    pub fn rejected_edges(&self) -> usize {
        self.rejected
    }

    /// The current progress.
    pub fn progress(&self) -> ContinuationProgress {
        ContinuationProgress {
            charts: self.atlas.charts.len(),
            open: self.open.len(),
            best_heuristic: self.open.iter().map(|e| e.tie).fold(f64::INFINITY, f64::min),
            ended: self.ended,
        }
    }

    /// Does at most `budget` units of work — one unit is one chart-creation attempt (one
    /// expansion direction, with its step shrinking), one pop of the open list, or one edge of a
    /// path being built (two walks, each with a capped number of projections, and the motion
    /// validator on their steps) — and returns the progress.
    pub fn step(&mut self, budget: usize) -> ContinuationProgress {
        let mut left = budget;
        while left > 0 && self.ended.is_none() {
            left -= 1;
            if let Some(p) = self.pending.take() {
                self.advance_path(p);
                continue;
            }
            if let Some(c) = self.expanding {
                if self.atlas.charts.len() >= self.max_charts {
                    self.ended = Some(Ended::Budget);
                } else if !self.atlas.expand_once(c) {
                    self.expanding = None;
                    self.relax(c);
                }
                continue;
            }
            let Some(Entry { id: c, .. }) = self.open.pop() else {
                if self.skipped_open {
                    // the charts there were hold no path: search again, growing the atlas
                    self.grow = true;
                    self.restart();
                } else {
                    self.ended = Some(Ended::Exhausted);
                }
                continue;
            };
            if self.popped[c] {
                continue;
            }
            self.popped[c] = true;
            if !self.try_goal(c) {
                self.leave(c);
            }
        }
        self.progress()
    }

    /// Pushes the neighbours of `c` whose g improves through `c`.
    fn relax(&mut self, c: usize) {
        let n = self.atlas.charts.len();
        self.g.resize(n, f64::INFINITY);
        self.parent.resize(n, None);
        self.popped.resize(n, false);
        for i in 0..self.atlas.charts[c].neighbours.len() {
            let nb = self.atlas.charts[c].neighbours[i];
            if self.atlas.charts[nb].state == ChartState::Blocked || self.broken.contains(&(c.min(nb), c.max(nb))) {
                continue;
            }
            let g = self.g[c] + self.atlas.manifold.distance(&self.atlas.charts[c].centre, &self.atlas.charts[nb].centre);
            if g < self.g[nb] {
                self.g[nb] = g;
                self.parent[nb] = Some(c);
                self.popped[nb] = false;
                let h = self.heuristic(nb);
                self.open.push(Entry { key: g + self.weight * h, tie: h, id: nb, item: () });
            }
        }
    }

    /// If a goal point lies in chart `c`, starts building the dense path along the chart path
    /// from the start to `c` (one edge per unit of work, [`Continuation::advance_path`]) and
    /// returns `true`.
    fn try_goal(&mut self, c: usize) -> bool {
        let Some((goal, t)) = self.goals.iter().find_map(|g| self.atlas.locate(c, g).map(|t| (g.clone(), t))) else {
            return false;
        };
        let mut chain = vec![c];
        while let Some(p) = self.parent[*chain.last().unwrap_or(&self.start)] {
            chain.push(p);
        }
        chain.reverse();
        let points = self.prefix.clone();
        self.pending = Some(Pending { chain, goal, t, next: 0, points });
        true
    }

    /// One unit of path building: the next edge of the pending chart path (built, validated and
    /// cached), or the final walk to the goal. An edge that cannot be followed or is rejected is
    /// removed from the graph and the search restarts; a final walk that fails sends the search on
    /// from the goal's chart as if it had held no goal.
    fn advance_path(&mut self, mut p: Pending) {
        if p.next + 1 < p.chain.len() {
            let (a, b) = (p.chain[p.next], p.chain[p.next + 1]);
            let pair = (a.min(b), a.max(b));
            if !self.edges.contains_key(&(a, b)) {
                // an edge built the other way (by an earlier search), reversed, or a new one
                let reversed = self.edges.get(&(b, a)).map(|e| e.as_ref().map(|e| e.iter().rev().cloned().collect::<Vec<_>>()));
                if let Some(known) = reversed {
                    self.edges.insert((a, b), known);
                }
            }
            if !self.edges.contains_key(&(a, b)) {
                let dense = self.atlas.edge(a, b);
                let rejected = dense.as_ref().is_some_and(|e| !self.motions_valid(e));
                if rejected && !self.broken.contains(&pair) {
                    self.rejected += 1;
                }
                self.edges.insert((a, b), dense.filter(|_| !rejected));
            }
            match &self.edges[&(a, b)] {
                Some(e) => {
                    p.points.extend(e.iter().skip(1).cloned());
                    p.next += 1;
                    self.pending = Some(p);
                }
                None => {
                    self.broken.insert(pair);
                    self.restart();
                }
            }
            return;
        }
        let c = p.chain[p.chain.len() - 1];
        let last = self.atlas.walk(c, &p.t);
        if last.is_none() {
            self.goal_walk_failures += 1;
        }
        match last.filter(|e| self.motions_valid(e)) {
            Some(last) => {
                p.points.extend(last.into_iter().skip(1));
                if let Some(end) = p.points.last_mut() {
                    *end = p.goal;
                }
                self.path = p.points;
                self.path_charts = p.chain;
                self.ended = Some(Ended::Found);
            }
            // The goal is in the ball but its segment cannot be followed: keep searching, another
            // chart may hold it.
            None => self.leave(c),
        }
    }

    /// Goes on from popped chart `c` without a goal: expands it if it is open (and the search
    /// grows the atlas), else relaxes its neighbours.
    fn leave(&mut self, c: usize) {
        if self.atlas.charts[c].state != ChartState::Open {
            self.relax(c);
        } else if self.grow {
            self.expanding = Some(c);
        } else {
            self.skipped_open = true;
            self.relax(c);
        }
    }

    /// Whether the motion validator has accepted the step from `a` to `b` (either way).
    pub fn step_validated(&self, a: &[f64], b: &[f64]) -> bool {
        self.valid_steps.contains(&step_key(a, b))
    }

    /// Whether the motion validator accepts every step of a dense path (steps it accepted before
    /// are not asked again).
    fn motions_valid(&mut self, dense: &[Vec<f64>]) -> bool {
        let manifold = &self.atlas.manifold;
        let (checks, valid) = (&mut self.motion_checks, &mut self.valid_steps);
        dense.windows(2).all(|w| {
            let key = step_key(&w[0], &w[1]);
            if valid.contains(&key) {
                return true;
            }
            *checks += 1;
            let ok = manifold.motion_valid(&w[0], &w[1]);
            if ok {
                valid.insert(key);
            }
            ok
        })
    }
}

/// The key of a step between two points: both points' bits, the lesser first (a step is valid
/// both ways).
fn step_key(a: &[f64], b: &[f64]) -> Vec<u64> {
    let (a, b): (Vec<u64>, Vec<u64>) = (a.iter().map(|v| v.to_bits()).collect(), b.iter().map(|v| v.to_bits()).collect());
    if a <= b {
        [a, b].concat()
    } else {
        [b, a].concat()
    }
}
