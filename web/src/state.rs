//! The page's state types, shared by the page (`app`), the analysis area (`workbench`), the
//! planner driver (`planning`), the view and the plots: values kept in memos and signals. No
//! components here, so every module can use them without importing another's components.

use std::sync::Arc;

use cablenav::model::Pose;
use cablenav::report::VerifyReport;
use cablenav::Scenario;
use leptos::prelude::*;

/// A value shared by reference inside a memo; two are equal only if they are the same
/// computation, so the core's types need not implement `PartialEq`.
#[derive(Debug)]
pub struct Shared<T>(pub Arc<T>);

impl<T> Clone for Shared<T> {
    fn clone(&self) -> Self {
        Shared(Arc::clone(&self.0))
    }
}

impl<T> PartialEq for Shared<T> {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl<T> Shared<T> {
    /// Shares `value`.
    pub fn new(value: T) -> Self {
        Shared(Arc::new(value))
    }
}

impl<T: PartialEq> Shared<T> {
    /// `value` shared, or `prev` itself when it holds an equal value: a memo returning it does
    /// not notify its readers when its content did not change (the 3-D view is not rebuilt and
    /// redrawn for the same geometry).
    pub fn or_same(prev: Option<&Shared<T>>, value: T) -> Self {
        match prev {
            Some(p) if *p.0 == value => p.clone(),
            _ => Shared::new(value),
        }
    }
}

/// The core's reading of the scenario (or why it cannot be read).
pub type Parsed = Shared<Result<Scenario, String>>;
/// The selected trajectory's verification (`None`: no trajectory).
pub type Verified = Shared<Option<Result<VerifyReport, String>>>;

/// A path found by the planner, as the page keeps it.
#[derive(Debug, Clone, PartialEq)]
pub struct Planned {
    /// The query's name.
    pub query: String,
    /// Its start pose.
    pub start: Pose,
    /// Its goal pose.
    pub goal: Pose,
    /// The path's poses, start to goal (the lattice planner's smoothed trajectory, sampled).
    pub poses: Vec<Pose>,
    /// The lattice planner's A* polyline, drawn beside the smoothed path (empty for the atlas).
    pub polyline: Vec<Pose>,
    /// The planned motion as a trajectory of the scenario format, verified exactly (both planners
    /// give one when they find a path).
    pub motion: Option<PlannedMotion>,
    /// The atlas planner's charts on a 2-D slice (Fig. 6 of paper 1), drawn over the slice map.
    pub atlas: Option<crate::worker::protocol::WireAtlas>,
}

/// A planned motion as a trajectory: shown in the strip and the 3-D view like any trajectory.
#[derive(Debug, Clone, PartialEq)]
pub struct PlannedMotion {
    /// The scenario JSON with the trajectory added (what "Scenario with the plan" exports).
    pub scenario: String,
    /// The trajectory (named as in `scenario`).
    pub trajectory: cablenav::model::Trajectory,
    /// Its exact verification (done in the planner's worker).
    pub report: Result<VerifyReport, String>,
}

/// Which path the animation, the plots and the exports follow.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Follow {
    /// The selected trajectory.
    Trajectory,
    /// The planned path.
    Planned,
}


/// The results tabs under the 3-D view, in their order on the page.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tab {
    /// The tables of intervals and boundaries, and the warnings.
    Intervals,
    /// The planners.
    Planning,
    /// The clearances along the followed path.
    Clearances,
    /// The tension envelope along the followed path.
    Tension,
    /// The slice map.
    Slice,
    /// The ray lattice.
    Lattice,
    /// The exports.
    Exports,
    /// The 3-D view's colours and controls.
    ViewKey,
}

impl Tab {
    /// Every tab, in order.
    pub const ALL: [Tab; 8] =
        [Tab::Intervals, Tab::Planning, Tab::Clearances, Tab::Tension, Tab::Slice, Tab::Lattice, Tab::Exports, Tab::ViewKey];

    /// Its id: in the address (`&tab=…`), the element ids and the panel's `data-testid`
    /// (`panel-<id>`).
    pub fn id(self) -> &'static str {
        match self {
            Tab::Intervals => "intervals",
            Tab::Planning => "planning",
            Tab::Clearances => "clearances",
            Tab::Tension => "tension",
            Tab::Slice => "slice",
            Tab::Lattice => "lattice",
            Tab::Exports => "exports",
            Tab::ViewKey => "view-key",
        }
    }

    /// Its label on the page.
    pub fn label(self) -> &'static str {
        match self {
            Tab::Intervals => "Intervals",
            Tab::Planning => "Planning",
            Tab::Clearances => "Clearances",
            Tab::Tension => "Tensions",
            Tab::Slice => "Slice map",
            Tab::Lattice => "Ray lattice",
            Tab::Exports => "Exports",
            Tab::ViewKey => "3-D view key",
        }
    }

    /// The tab of id `id`.
    pub fn from_id(id: &str) -> Option<Tab> {
        Tab::ALL.into_iter().find(|t| t.id() == id)
    }

    /// Where a key pressed on this tab moves (the WAI-ARIA tabs pattern): `ArrowRight` and
    /// `ArrowLeft` to the next and previous tab, wrapping around, `Home` and `End` to the first and
    /// last; `None` for any other key.
    pub fn after_key(self, key: &str) -> Option<Tab> {
        let n = Tab::ALL.len();
        let i = Tab::ALL.iter().position(|t| *t == self).unwrap_or(0);
        let to = match key {
            "ArrowRight" => (i + 1) % n,
            "ArrowLeft" => (i + n - 1) % n,
            "Home" => 0,
            "End" => n - 1,
            _ => return None,
        };
        Some(Tab::ALL[to])
    }
}

/// The planners the page offers: (id, label, available). The id goes to the worker
/// ([`crate::worker::jobs::planner`] sets it up).
pub const PLANNERS: [(&str, &str, bool); 2] =
    [("continuation", "Atlas continuation (Bohigas et al.)", true), ("ray-lattice", "Ray lattice + A* + Bézier (Zhang)", true)];

/// What the page's address keeps beside the scenario (`#preset=…&tab=…`, [`crate::persist`]):
/// the open results tab and the planning choices.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Settings {
    /// The open results tab.
    pub tab: Tab,
    /// The planner's id (one of [`PLANNERS`]).
    pub planner: &'static str,
    /// The lattice planner's grid values per free coordinate, as typed (checked by the core when
    /// a plan starts, as `cablenav plan --planner lattice --steps N` checks it).
    pub steps: String,
}

impl Default for Settings {
    /// The intervals tab, the atlas planner, 7 lattice steps (the CLI's default).
    fn default() -> Settings {
        Settings {
            tab: Tab::Intervals,
            planner: PLANNERS[0].0,
            steps: cablenav::plan::lattice::LatticeParams::default().steps.to_string(),
        }
    }
}

/// The scenario as the page holds it at one moment: its JSON text and where it came from (a
/// preset's id, or `"edited"`). What undo and redo restore.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Snapshot {
    /// The scenario JSON, exactly as the page analyses it.
    pub source: String,
    /// A preset id, or `"edited"`.
    pub origin: &'static str,
}

/// Undo and redo over whole scenarios: every change of the page's scenario is one step, except
/// inside a batch (a drag in the 3-D view), which is one step however many changes it makes.
#[derive(Debug, Clone, PartialEq)]
pub struct History {
    past: Vec<Snapshot>,
    current: Snapshot,
    future: Vec<Snapshot>,
    /// Inside a batch: whether its first change has been recorded.
    batch: Option<bool>,
}

impl History {
    /// Steps kept to undo (the oldest are dropped first).
    pub const LIMIT: usize = 200;

    /// A history whose present is `current`, with nothing to undo or redo.
    pub fn new(current: Snapshot) -> History {
        History { past: Vec::new(), current, future: Vec::new(), batch: None }
    }

    /// The page's scenario became `next`: the present becomes a step to undo (once per batch)
    /// and nothing is left to redo. No step when `next` is the present (an undo being applied).
    pub fn record(&mut self, next: Snapshot) {
        if next == self.current {
            return;
        }
        let old = std::mem::replace(&mut self.current, next);
        match self.batch {
            Some(true) => {}
            batch => {
                self.past.push(old);
                if self.past.len() > Self::LIMIT {
                    self.past.remove(0);
                }
                if batch.is_some() {
                    self.batch = Some(true);
                }
            }
        }
        self.future.clear();
    }

    /// Starts a batch: the changes until [`History::end_batch`] undo as one step.
    pub fn begin_batch(&mut self) {
        self.batch = Some(false);
    }

    /// Ends the batch.
    pub fn end_batch(&mut self) {
        self.batch = None;
    }

    /// The scenario before the present, which becomes the present; `None` if there is none.
    pub fn undo(&mut self) -> Option<Snapshot> {
        let prev = self.past.pop()?;
        self.future.push(std::mem::replace(&mut self.current, prev));
        Some(self.current.clone())
    }

    /// The scenario undone last, which becomes the present again; `None` if there is none.
    pub fn redo(&mut self) -> Option<Snapshot> {
        let next = self.future.pop()?;
        self.past.push(std::mem::replace(&mut self.current, next));
        Some(self.current.clone())
    }

    /// Steps there are to undo.
    pub fn undo_depth(&self) -> usize {
        self.past.len()
    }

    /// Steps there are to redo.
    pub fn redo_depth(&self) -> usize {
        self.future.len()
    }
}

/// Undo and redo of the page's scenario: a [`History`] kept in step with `source` and `origin`.
#[derive(Clone, Copy)]
pub struct Undo {
    history: StoredValue<History>,
    /// Steps to undo and to redo, for the buttons.
    pub depth: RwSignal<(usize, usize)>,
    /// A batch is open (a drag in progress): what need not follow every step of it waits for its
    /// end (see [`Quiet`]).
    pub batching: RwSignal<bool>,
    /// The page's scenario JSON.
    pub source: RwSignal<String>,
    origin: RwSignal<&'static str>,
    preset: RwSignal<usize>,
}

impl Undo {
    /// Starts recording every change of `source`/`origin` as a step.
    pub fn new(source: RwSignal<String>, origin: RwSignal<&'static str>, preset: RwSignal<usize>) -> Undo {
        let first = Snapshot { source: source.get_untracked(), origin: origin.get_untracked() };
        let u = Undo { history: StoredValue::new(History::new(first)), depth: RwSignal::new((0, 0)), batching: RwSignal::new(false), source, origin, preset };
        Effect::new(move |_| {
            let now = Snapshot { source: source.get(), origin: origin.get() };
            u.history.update_value(|h| h.record(now));
            u.sync();
        });
        u
    }

    fn sync(&self) {
        let d = self.history.with_value(|h| (h.undo_depth(), h.redo_depth()));
        if self.depth.get_untracked() != d {
            self.depth.set(d);
        }
    }

    fn restore(&self, s: Option<Snapshot>) {
        let Some(s) = s else { return };
        if let Some(i) = crate::presets::find(s.origin) {
            self.preset.set(i);
        }
        self.origin.set(s.origin);
        self.source.set(s.source);
        self.sync();
    }

    /// Goes back one step.
    pub fn undo(&self) {
        self.restore(self.history.try_update_value(|h| h.undo()).flatten());
    }

    /// Goes forward one step.
    pub fn redo(&self) {
        self.restore(self.history.try_update_value(|h| h.redo()).flatten());
    }

    /// Until [`Undo::end_batch`], changes are one step (a drag).
    pub fn begin_batch(&self) {
        self.history.update_value(History::begin_batch);
        self.batching.set(true);
    }

    /// Ends a batch.
    pub fn end_batch(&self) {
        self.history.update_value(History::end_batch);
        self.batching.set(false);
    }
}

/// While true (a drag in progress), the parts of the page that need not follow every step of an
/// edit wait for its end: the editor's form (which re-reads the whole scenario), the address and
/// the autosave. The strip, the 3-D view and the verification follow every step. Provided as a
/// context by the page; absent (never quiet) where the editor is mounted alone.
#[derive(Debug, Clone, Copy)]
pub struct Quiet(pub Signal<bool>);

impl Quiet {
    /// The context's test, looked up once where this is called (a component's setup) and read
    /// (tracked) each time it is called: always false without a [`Quiet`] context.
    pub fn watch() -> impl Fn() -> bool + Copy + 'static {
        let q = use_context::<Quiet>();
        move || q.is_some_and(|q| q.0.get())
    }
}

/// The page's shared state, passed to the workbench and its parts (a copyable bundle of
/// signals and memos).
#[derive(Clone, Copy)]
pub struct PageState {
    /// The core's reading of the scenario.
    pub parsed: Memo<Parsed>,
    /// The selected trajectory's verification.
    pub verified: Memo<Verified>,
    /// During a drag, how long the worker took for the latest verification (ms).
    pub live_ms: RwSignal<Option<f64>>,
    /// The selected trajectory's index.
    pub trajectory: RwSignal<usize>,
    /// The path the planner found for the current scenario, if any.
    pub planned: RwSignal<Option<Shared<Planned>>>,
    /// The scenario JSON being analysed.
    pub source: RwSignal<String>,
    /// Where `source` came from: a preset's id, or `"edited"`.
    pub origin: RwSignal<&'static str>,
    /// Undo and redo of `source`.
    pub history: Undo,
    /// The open results tab and the planning choices (kept in the address).
    pub settings: RwSignal<Settings>,
}

/// The strip's boundary the user points at (hover, focus or tap), if any: the 3-D view shows the
/// platform there with the clearance tubes of the boundary's constraint. Provided as context by
/// the workbench, read by the strip's ticks.
#[derive(Clone, Copy)]
pub struct Focus(pub RwSignal<Option<crate::logic::Tick>>);

#[cfg(test)]
mod tests {
    use super::*;

    fn snap(s: &str) -> Snapshot {
        Snapshot { source: s.to_string(), origin: "edited" }
    }

    #[test]
    fn undo_and_redo_walk_the_steps_exactly() {
        let mut h = History::new(Snapshot { source: "a".into(), origin: "cdpr7" });
        h.record(snap("b"));
        h.record(snap("c"));
        assert_eq!(h.undo(), Some(snap("b")));
        assert_eq!(h.undo(), Some(Snapshot { source: "a".into(), origin: "cdpr7" }), "the origin comes back too");
        assert_eq!(h.undo(), None);
        assert_eq!(h.redo(), Some(snap("b")));
        h.record(snap("b")); // the page applying the redo: no new step
        assert_eq!((h.undo_depth(), h.redo_depth()), (1, 1));
        h.record(snap("d"));
        assert_eq!(h.redo(), None, "a new change drops what was undone");
        assert_eq!(h.undo(), Some(snap("b")));
    }

    #[test]
    fn a_batch_is_one_step() {
        let mut h = History::new(snap("a"));
        h.begin_batch();
        for s in ["b", "c", "d"] {
            h.record(snap(s));
        }
        h.end_batch();
        h.record(snap("e"));
        assert_eq!(h.undo(), Some(snap("d")));
        assert_eq!(h.undo(), Some(snap("a")), "the drag undoes at once");
        let mut empty = History::new(snap("a"));
        empty.begin_batch();
        empty.end_batch();
        assert_eq!(empty.undo(), None, "a batch without changes is no step");
    }

    #[test]
    fn an_equal_value_keeps_the_shared_one() {
        let a = Shared::new(vec![1, 2]);
        assert!(Shared::or_same(Some(&a), vec![1, 2]) == a, "the same Arc: readers are not notified");
        assert!(Shared::or_same(Some(&a), vec![1, 3]) != a);
        assert_eq!(*Shared::or_same(None, vec![4]).0, vec![4]);
    }

    #[test]
    fn tabs_have_ids_and_arrow_keys_wrap_around() {
        for t in Tab::ALL {
            assert_eq!(Tab::from_id(t.id()), Some(t));
        }
        assert_eq!(Tab::from_id("nope"), None);
        assert_eq!(Tab::Intervals.after_key("ArrowRight"), Some(Tab::Planning));
        assert_eq!(Tab::Intervals.after_key("ArrowLeft"), Some(Tab::ViewKey), "wraps to the last");
        assert_eq!(Tab::ViewKey.after_key("ArrowRight"), Some(Tab::Intervals), "wraps to the first");
        assert_eq!(Tab::Slice.after_key("Home"), Some(Tab::Intervals));
        assert_eq!(Tab::Slice.after_key("End"), Some(Tab::ViewKey));
        assert_eq!(Tab::Slice.after_key("Enter"), None);
    }

    #[test]
    fn the_oldest_steps_are_dropped() {
        let mut h = History::new(snap("0"));
        for k in 1..=History::LIMIT + 5 {
            h.record(snap(&k.to_string()));
        }
        assert_eq!(h.undo_depth(), History::LIMIT);
    }
}
