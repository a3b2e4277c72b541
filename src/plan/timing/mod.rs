//! The fastest safe timing of a path: the time law s(t) of least duration under the tension
//! bounds (with the wrench set), the winch limits and the platform's speed limit, certified along
//! the whole path by the exact verifier rather than at grid points only.
//!
//! 1. The trajectory's motions are cut into cells ([`path`]); at each cell's ends and its middle
//!    the limits are half-planes in (λ̈, λ̇²) ([`limits`]), tightened by a small margin. (The
//!    middle's keep the law from bulging past a limit between the ends where the limit curves,
//!    a cruise at a speed limit along a bend: without them a tenth of the cells of batotp's
//!    path failed the certification at first, and each round of slowing down re-verifies
//!    hundreds of cells.)
//! 2. Reachability analysis finds the fastest law on that grid, λ̈ constant per cell
//!    ([`reach`]): the uncertified optimum, which meets the limits at those points only.
//! 3. Each cell of the law is verified exactly ([`certify`]); where a limit is left between grid
//!    points (or cannot be decided) the cell is halved (once), then its speed capped lower, and
//!    the law recomputed, until every cell is certified (or the rounds run out: then the report
//!    says where it is not).
//!
//! The planner of step 2 knows nothing of robots: it sees half-planes per cell.

pub mod certify;
pub mod limits;
pub mod path;
pub mod reach;

use crate::error::{Error, Result};
use crate::model::motion::Param;
use crate::model::{Motion, Trajectory};
use crate::query::wrench::static_margin;
use crate::report::{BindingStretch, ProfilePoint, TimingReport};
use crate::scenario::Scenario;
use certify::Verdict;
use limits::{HalfPlane, Limits, What};
use path::{Cell, Jet, Rates};
use reach::{Failure, Step};

/// How the timing is computed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimingOptions {
    /// Grid cells over the whole path.
    pub cells: usize,
    /// Relative margin the limits are tightened by at the grid points.
    pub margin: f64,
    /// Most slow-down rounds of the certification.
    pub rounds: usize,
}

impl Default for TimingOptions {
    fn default() -> Self {
        TimingOptions { cells: 400, margin: 1e-3, rounds: 40 }
    }
}

/// Each slow-down round caps a failing cell's speed (x = λ̇²) at this share of what it was.
const SLOW_DOWN: f64 = 0.8;

/// How many times a failing cell is halved before it is slowed instead.
const MAX_HALVINGS: u8 = 1;

/// Relative difference of the velocity per unit t across a junction of motions above which the
/// path has a corner there (the platform must stop).
const CORNER: f64 = 1e-6;

/// The certified timed law, to evaluate: per cell its motion's parameter, λ-range, x at both
/// ends and its start time.
#[derive(Debug, Clone)]
pub struct TimedPath {
    cells: Vec<(Param, f64, f64, f64, f64, f64)>,
    duration: f64,
}

impl TimedPath {
    /// Its duration (s).
    pub fn duration(&self) -> f64 {
        self.duration
    }

    /// The trajectory's t at `time` seconds (clamped to [0, duration]): on a cell λ̈ = u is
    /// constant, so λ = a + √x₀·τ + u·τ²/2 with τ the time since the cell's start.
    pub fn t_at(&self, time: f64) -> f64 {
        let k = self.cells.partition_point(|c| c.5 <= time).saturating_sub(1);
        let (param, a, b, x0, x1, start) = self.cells[k];
        let delta = b - a;
        let u = (x1 - x0) / (2.0 * delta);
        let tau = (time - start).max(0.0);
        let lam = (a + x0.sqrt() * tau + 0.5 * u * tau * tau).clamp(a, b);
        param.value(lam)
    }

    /// The cells' start times and ends in t, for samplers that avoid the law's kinks: (t at
    /// the start, start time) per cell.
    pub fn knots(&self) -> Vec<(f64, f64)> {
        self.cells.iter().map(|c| (c.0.value(c.1), c.5)).collect()
    }
}

/// How far a timing has come: in certification round `round` (0 first), `done` of the `total`
/// cells that round verifies (reported as a round starts and ends: chunks of a round would leave
/// the cores idle at each chunk's end, cells near a spline's knots taking far longer than others).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TimingProgress {
    /// The round.
    pub round: usize,
    /// Cells verified in it.
    pub done: usize,
    /// Cells it verifies.
    pub total: usize,
}

/// The fastest certified timing of `traj` in `s`, rest to rest.
pub fn fastest(s: &Scenario, traj: &Trajectory, options: TimingOptions) -> Result<(TimingReport, TimedPath)> {
    fastest_reporting(s, traj, options, &mut |_| {})
}

/// [`fastest`], telling `progress` how the certification goes.
pub fn fastest_reporting(s: &Scenario, traj: &Trajectory, options: TimingOptions, progress: &mut dyn FnMut(TimingProgress)) -> Result<(TimingReport, TimedPath)> {
    if !(options.cells >= 1 && options.cells <= 100_000) {
        return Err(Error::new("--cells", format!("{} cells: give 1 to 100000", options.cells)));
    }
    if !(options.margin > 0.0 && options.margin < 0.5) {
        return Err(Error::new("--margin", format!("{}: give a relative margin in (0, 0.5)", options.margin)));
    }
    let limits = Limits::new(s, options.margin)?;
    let (mut cells, rates) = path::grid(Motion::trajectory(traj), options.cells, CORNER);
    let t_of = |c: &Cell, lam: f64| rates[c.motion].motion().param.value(lam);
    // the limits at both ends and the middle of every cell, as half-planes in (u, x_start)
    let mut steps = Vec::with_capacity(cells.len());
    let mut jets = Vec::with_capacity(cells.len());
    // a cell's end is the next one's start: the limits there are computed once
    let mut end: Option<(usize, f64, Vec<HalfPlane>, Jet)> = None;
    for c in &cells {
        let start = match end.take() {
            Some((motion, lam, planes, jet)) if motion == c.motion && lam == c.a => (planes, jet),
            _ => limits_at(&limits, &rates, c.motion, c.a)?,
        };
        let (middle, _) = limits_at(&limits, &rates, c.motion, 0.5 * (c.a + c.b))?;
        let at_end = limits_at(&limits, &rates, c.motion, c.b)?;
        steps.push(step_from(c, &start.0, &middle, &at_end.0));
        jets.push(start.1);
        end = Some((c.motion, c.b, at_end.0, at_end.1));
    }
    let first = reach::fastest(&mut steps, |law| duration(&cells, law)).map_err(|f| failure(&limits, &cells, &jets, &steps, f, &t_of))?;
    let uncertified = duration(&cells, &first);
    let mut law = first;
    let mut known: Vec<Option<((f64, f64), Verdict)>> = vec![None; cells.len()];
    let mut slowed = vec![false; cells.len()];
    let mut rounds = 0;
    let open = loop {
        let which: Vec<usize> = (0..cells.len()).filter(|&i| known[i].as_ref().is_none_or(|(x, _)| *x != law[i])).collect();
        progress(TimingProgress { round: rounds, done: 0, total: which.len() });
        for (i, v) in which.iter().zip(certify::verdicts(s, &cells, &rates, &law, &which)) {
            known[*i] = Some((law[*i], v));
        }
        progress(TimingProgress { round: rounds, done: which.len(), total: which.len() });
        let failing: Vec<usize> = (0..cells.len()).filter(|&i| !matches!(known[i], Some((_, Verdict::Holds)))).collect();
        if failing.is_empty() || rounds == options.rounds {
            break failing;
        }
        rounds += 1;
        // a failing cell is halved (the law then follows the limits more closely) until it is
        // small enough, then slowed
        for &i in failing.iter().rev() {
            if cells[i].depth < MAX_HALVINGS {
                let [first, second] = cells[i].halves();
                let ((s0, j0), (s1, j1)) = (step_of(&limits, &rates, &first)?, step_of(&limits, &rates, &second)?);
                (cells[i], steps[i], jets[i], known[i], slowed[i]) = (first, s0, j0, None, false);
                cells.insert(i + 1, second);
                steps.insert(i + 1, s1);
                jets.insert(i + 1, j1);
                known.insert(i + 1, None);
                slowed.insert(i + 1, false);
            } else {
                let (x0, x1) = law[i];
                steps[i].caps = (x0 * SLOW_DOWN, x1 * SLOW_DOWN);
                slowed[i] = true;
            }
        }
        law = reach::fastest(&mut steps, |law| duration(&cells, law)).map_err(|f| failure(&limits, &cells, &jets, &steps, f, &t_of))?;
    };
    let total = duration(&cells, &law);
    let certified = open.is_empty();
    let interval = |i: usize| [t_of(&cells[i], cells[i].a), t_of(&cells[i], cells[i].b)];
    let merged = |flags: &dyn Fn(usize) -> bool| {
        let mut out: Vec<[f64; 2]> = Vec::new();
        for i in (0..cells.len()).filter(|&i| flags(i)) {
            let [a, b] = interval(i);
            match out.last_mut() {
                Some(last) if last[1] == a => last[1] = b,
                _ => out.push([a, b]),
            }
        }
        out
    };
    // times at every cell's start
    let mut times = Vec::with_capacity(cells.len() + 1);
    let mut clock = 0.0;
    for (c, &(x0, x1)) in cells.iter().zip(&law) {
        times.push(clock);
        clock += cell_time(c, x0, x1);
    }
    times.push(clock);
    let binding = binding_stretches(&limits, &cells, &jets, &steps, &slowed, &law, &times, &t_of);
    let profile = profile(s, &cells, &rates, &jets, &law, &times, &t_of);
    let mut notes = vec!["the certificate covers the speed-dependent conditions (tensions under weight and inertia, winch and speed limits); the path's geometry (lengths, interference, closure) does not depend on the timing: `cablenav verify` certifies it".to_string()];
    if !certified {
        let names: Vec<String> = open.iter().filter_map(|&i| match &known[i] {
            Some((_, Verdict::Fails(v) | Verdict::Undecided(v))) => Some(v.join(", ")),
            _ => None,
        }).take(3).collect();
        notes.push(format!("{} cells not certified after {rounds} rounds ({}…)", open.len(), names.join("; ")));
    }
    let report = TimingReport {
        trajectory: traj.name.clone(),
        duration: certified.then_some(total),
        uncertified_duration: uncertified,
        certificate_cost: certified.then_some(total / uncertified - 1.0),
        cells: cells.len(),
        rounds,
        margin: options.margin,
        binding,
        slowed: merged(&|i| slowed[i]),
        not_certified: merged(&|i| open.contains(&i)),
        profile,
        notes,
    };
    let timed = TimedPath {
        cells: cells.iter().zip(&law).zip(&times).map(|((c, &(x0, x1)), &start)| (rates[c.motion].motion().param, c.a, c.b, x0, x1, start)).collect(),
        duration: total,
    };
    Ok((report, timed))
}

/// A cell's limits at both its ends and its middle as half-planes in (u, x_start)
/// ([`step_from`]), and the jet at its start.
fn step_of(limits: &Limits, rates: &[Rates], c: &Cell) -> Result<(Step, Jet)> {
    let (start, jet) = limits_at(limits, rates, c.motion, c.a)?;
    let (middle, _) = limits_at(limits, rates, c.motion, 0.5 * (c.a + c.b))?;
    let (end, _) = limits_at(limits, rates, c.motion, c.b)?;
    Ok((step_from(c, &start, &middle, &end), jet))
}

/// The limits at λ = `lam` of motion `motion`, and the jet there.
fn limits_at(limits: &Limits, rates: &[Rates], motion: usize, lam: f64) -> Result<(Vec<HalfPlane>, Jet)> {
    let r = &rates[motion];
    let jet = r.jet(lam);
    let mut planes = Vec::new();
    limits.at(&jet, r.motion().param.value(lam), &mut planes)?;
    Ok((planes, jet))
}

/// A cell's step from the half-planes at its `start`, its `middle` and its `end`, the latter two
/// with x = x_start + Δu and x_start + 2Δu substituted (λ̇² is linear along the cell).
fn step_from(c: &Cell, start: &[HalfPlane], middle: &[HalfPlane], end: &[HalfPlane]) -> Step {
    let delta = c.b - c.a;
    let mut planes = Vec::with_capacity(start.len() + middle.len() + end.len());
    planes.extend_from_slice(start);
    planes.extend(middle.iter().map(|h| HalfPlane { a: h.a + delta * h.b, ..*h }));
    planes.extend(end.iter().map(|h| HalfPlane { a: h.a + 2.0 * delta * h.b, ..*h }));
    Step { planes, delta, factor: c.factor, stop: c.stop, caps: (f64::INFINITY, f64::INFINITY) }
}

/// Seconds a cell takes: λ̇² linear in λ from x₀ to x₁ over Δ gives 2Δ/(√x₀ + √x₁).
fn cell_time(c: &Cell, x0: f64, x1: f64) -> f64 {
    2.0 * (c.b - c.a) / (x0.max(0.0).sqrt() + x1.max(0.0).sqrt())
}

fn duration(cells: &[Cell], law: &[(f64, f64)]) -> f64 {
    cells.iter().zip(law).map(|(c, &(x0, x1))| cell_time(c, x0, x1)).sum()
}

/// The error for a law that does not exist: where, and which limits are violated at rest there.
fn failure(limits: &Limits, cells: &[Cell], jets: &[Jet], steps: &[Step], f: Failure, t_of: &dyn Fn(&Cell, f64) -> f64) -> Error {
    match f {
        Failure::Stuck(i) => {
            let c = &cells[i];
            let mut at_rest: Vec<String> = steps[i].planes.iter().filter(|h| h.c < 0.0).map(|h| limits.name(h.what, &jets[i])).collect();
            at_rest.sort_unstable();
            at_rest.dedup();
            let why = match at_rest.len() {
                0 => "the limits leave no speed to go on with (nor to stop in time)".to_string(),
                1..=3 => format!("violated at rest there: {}", at_rest.join("; ")),
                k => format!("violated at rest there: {}; and {} more", at_rest[..3].join("; "), k - 3),
            };
            Error::new("trajectory", format!("no timing follows the path: at t ∈ [{:.6}, {:.6}] {why}", t_of(c, c.a), t_of(c, c.b)))
        }
        Failure::Unbounded(i) => {
            let c = &cells[i];
            let (t0, t1) = (t_of(c, c.a), t_of(c, c.b));
            let jet = &jets[i];
            if jet.dp.norm() + jet.omega.norm() < 1e-9 * (1.0 + jet.pose.position.norm()) {
                Error::new("trajectory", format!("the path stands still at t ∈ [{t0:.6}, {t1:.6}] (repeated points): no speed along it means anything there; remove the stretch"))
            } else {
                Error::new("trajectory", format!("nothing limits the speed at t ∈ [{t0:.6}, {t1:.6}]: give the platform a mass, winch limits or a speed limit"))
            }
        }
    }
}

/// The binding constraint cell by cell (the half-plane with the least relative slack at the
/// law's (u, x), or the certification's cap where a `slowed` cell runs at it), merged into
/// stretches. (The law's own improvement caps a cell's start past its peak too; that cap is a
/// choice of the law, not a certification's slow-down, and the least slack names the cell.)
#[allow(clippy::too_many_arguments)]
fn binding_stretches(limits: &Limits, cells: &[Cell], jets: &[Jet], steps: &[Step], slowed: &[bool], law: &[(f64, f64)], times: &[f64], t_of: &dyn Fn(&Cell, f64) -> f64) -> Vec<BindingStretch> {
    let mut out: Vec<BindingStretch> = Vec::new();
    for (i, c) in cells.iter().enumerate() {
        let (x0, x1) = law[i];
        let u = (x1 - x0) / (2.0 * (c.b - c.a));
        let capped = slowed[i] && (x0 >= steps[i].caps.0 * (1.0 - 1e-9) || x1 >= steps[i].caps.1 * (1.0 - 1e-9));
        let what = if capped {
            What::Cap
        } else {
            let slack = |h: &HalfPlane| (h.c - h.a * u - h.b * x0) / (h.c.abs() + (h.a * u).abs() + (h.b * x0).abs() + 1e-300);
            steps[i].planes.iter().min_by(|p, q| slack(p).total_cmp(&slack(q))).map_or(What::Cap, |h| h.what)
        };
        let name = limits.name(what, &jets[i]);
        let (t, seconds) = ([t_of(c, c.a), t_of(c, c.b)], [times[i], times[i + 1]]);
        match out.last_mut() {
            Some(last) if last.constraint == name => {
                last.t[1] = t[1];
                last.seconds[1] = seconds[1];
            }
            _ => out.push(BindingStretch { t, seconds, constraint: name }),
        }
    }
    out
}

/// The law at every grid point (each cell's start, and the path's end).
fn profile(s: &Scenario, cells: &[Cell], rates: &[Rates], jets: &[Jet], law: &[(f64, f64)], times: &[f64], t_of: &dyn Fn(&Cell, f64) -> f64) -> Vec<ProfilePoint> {
    let load = s.load();
    let bounds: Vec<crate::model::Bounds> = s.robot.cables.iter().map(|c| c.tension).collect();
    let point = |i: usize, jet: &Jet, lam: f64, x: f64, u: f64| {
        let c = &cells[i];
        let per_t = rates[c.motion].per_t(lam);
        let kin = jet.kinematics(u, x);
        let tensions = load.as_ref().map_or(Vec::new(), |l| {
            let w = l.nominal_at(&jet.pose, Some(&kin));
            static_margin(&s.robot.anchors(&jet.pose), &l.wrench.point_at(&jet.pose), &w, &bounds, l.rows()).map_or(Vec::new(), |(_, f)| f)
        });
        ProfilePoint { t: t_of(c, lam), time: 0.0, rate: x.max(0.0).sqrt() / per_t, speed: kin.velocity.norm(), tensions }
    };
    let mut out: Vec<ProfilePoint> = cells
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let (x0, x1) = law[i];
            let mut p = point(i, &jets[i], c.a, x0, (x1 - x0) / (2.0 * (c.b - c.a)));
            p.time = times[i];
            p
        })
        .collect();
    if let Some(i) = cells.len().checked_sub(1) {
        let c = &cells[i];
        let (x0, x1) = law[i];
        let mut p = point(i, &rates[c.motion].jet(c.b), c.b, x1, (x1 - x0) / (2.0 * (c.b - c.a)));
        p.time = times[i + 1];
        out.push(p);
    }
    out
}
