//! The sampling checker: runs cablenav's exact verifier on a reference scenario and compares its
//! report with dense point-wise sampling of the reference model.

use super::reference::*;
use cablenav::report::{Side, VerifyReport};

/// How far (in t) a sample must be from every reported boundary to be judged.
pub const BOUNDARY_EPS: f64 = 1e-9;
/// Offset (in t) at which the reference must see a change of feasibility across a boundary.
pub const BOUNDARY_PROBE: f64 = 1e-6;
/// Offsets (in t) of the extra samples taken on each side of every reported boundary.
pub const NEAR_OFFSETS: [f64; 6] = [1.5e-9, 3e-9, 1e-8, 1e-7, 1e-6, 1e-5];

/// What went wrong, with enough to reproduce it.
#[derive(Clone, Debug)]
pub struct Failure {
    pub kind: &'static str,
    pub scenario: String,
    pub trajectory: String,
    pub t: f64,
    pub detail: String,
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "[{}] {} / {} at t = {:.17e}: {}", self.kind, self.scenario, self.trajectory, self.t, self.detail)
    }
}

/// Counters and failures of a run.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    pub trajectories: usize,
    pub samples: usize,
    pub judged: usize,
    pub skipped_uncertain: usize,
    pub skipped_near_boundary: usize,
    pub tolerated: usize,
    pub boundaries: usize,
    pub boundaries_checked: usize,
    pub boundaries_skipped: usize,
    pub labels_checked: usize,
    /// Checked boundaries by the kind of condition at its limit there (cable-cable, length, or
    /// the obstacle's type).
    pub boundary_kinds: std::collections::BTreeMap<&'static str, usize>,
    /// Total measure (in t) of feasible, infeasible and uncertain intervals.
    pub feasible_len: f64,
    pub infeasible_len: f64,
    pub uncertain_len: f64,
    pub trajectories_with_uncertain: usize,
    pub verify_seconds: f64,
    pub slowest_verify: (f64, String),
    pub failures: Vec<Failure>,
    /// Failures by kind (all counted, only the first few per trajectory are kept).
    pub failure_counts: std::collections::BTreeMap<&'static str, usize>,
}

impl Stats {
    pub fn merge(&mut self, o: Stats) {
        self.trajectories += o.trajectories;
        self.samples += o.samples;
        self.judged += o.judged;
        self.skipped_uncertain += o.skipped_uncertain;
        self.skipped_near_boundary += o.skipped_near_boundary;
        self.tolerated += o.tolerated;
        self.boundaries += o.boundaries;
        self.boundaries_checked += o.boundaries_checked;
        self.boundaries_skipped += o.boundaries_skipped;
        self.labels_checked += o.labels_checked;
        for (k, v) in o.boundary_kinds {
            *self.boundary_kinds.entry(k).or_default() += v;
        }
        self.feasible_len += o.feasible_len;
        self.infeasible_len += o.infeasible_len;
        self.uncertain_len += o.uncertain_len;
        self.trajectories_with_uncertain += o.trajectories_with_uncertain;
        self.verify_seconds += o.verify_seconds;
        if o.slowest_verify.0 > self.slowest_verify.0 {
            self.slowest_verify = o.slowest_verify;
        }
        self.failures.extend(o.failures);
        for (k, v) in o.failure_counts {
            *self.failure_counts.entry(k).or_default() += v;
        }
    }

    fn fail(&mut self, f: Failure, keep: &mut usize) {
        *self.failure_counts.entry(f.kind).or_default() += 1;
        if *keep > 0 {
            *keep -= 1;
            self.failures.push(f);
        }
    }

    pub fn summary(&self) -> String {
        format!(
            "{} trajectories, {} samples ({} judged, {} in uncertain intervals, {} within {:e} of a boundary, \
             {} tolerated by margin), {} boundaries ({} checked, {} skipped next to another boundary/uncertain, \
             {} labels checked; by kind {:?}); measure feasible {:.3} / infeasible {:.3} / uncertain {:.3e} \
             ({} trajectories with uncertain parts); verifier time {:.1}s (slowest {:.2}s: {}); failures {:?}",
            self.trajectories,
            self.samples,
            self.judged,
            self.skipped_uncertain,
            self.skipped_near_boundary,
            BOUNDARY_EPS,
            self.tolerated,
            self.boundaries,
            self.boundaries_checked,
            self.boundaries_skipped,
            self.labels_checked,
            self.boundary_kinds,
            self.feasible_len,
            self.infeasible_len,
            self.uncertain_len,
            self.trajectories_with_uncertain,
            self.verify_seconds,
            self.slowest_verify.0,
            self.slowest_verify.1,
            self.failure_counts,
        )
    }
}

/// Whether t lies in one of the sorted closed intervals.
fn in_intervals(list: &[[f64; 2]], t: f64) -> bool {
    // Lists are checked to be sorted separately; a linear fallback keeps this correct regardless.
    let idx = list.partition_point(|iv| iv[0] <= t);
    (idx > 0 && list[idx - 1][1] >= t) || (!is_sorted(list) && list.iter().any(|iv| iv[0] <= t && t <= iv[1]))
}

fn is_sorted(list: &[[f64; 2]]) -> bool {
    list.windows(2).all(|w| w[0][0] <= w[1][0])
}

fn near_any(sorted: &[f64], t: f64, eps: f64) -> bool {
    let idx = sorted.partition_point(|&b| b < t - eps);
    idx < sorted.len() && sorted[idx] <= t + eps
}

/// The overall margin at t: the smallest condition margin (negative iff infeasible, up to rounding).
pub fn overall_margin(checks: &[Check]) -> f64 {
    checks.iter().map(|c| c.margin).fold(f64::INFINITY, f64::min)
}

/// The few conditions closest to their limit, for messages.
pub fn critical_checks(checks: &[Check], n: usize) -> String {
    let mut c: Vec<&Check> = checks.iter().collect();
    c.sort_by(|a, b| a.margin.partial_cmp(&b.margin).unwrap_or(std::cmp::Ordering::Equal));
    c.iter()
        .take(n)
        .map(|c| format!("{} (violated {}, margin {:.3e})", c.label, c.violated, c.margin))
        .collect::<Vec<_>>()
        .join("; ")
}

/// Whether a report's constraint label names the reference check (cable numbers, obstacle name,
/// or "length").
pub fn label_names(label: &str, ev: &Evaluator, c: &Check) -> bool {
    let l = label.to_lowercase();
    let has_cable = |i: usize| {
        let pat = format!("{}", i + 1);
        // a cable number as a whole token
        l.split(|ch: char| !ch.is_ascii_digit()).any(|tok| tok == pat)
    };
    if !has_cable(c.cables.0) {
        return false;
    }
    if let Some(j) = c.cables.1 {
        return has_cable(j);
    }
    match c.obstacle {
        Some(k) => l.contains(&ev.scenario.obstacles[k].name.to_lowercase()),
        None => l.contains("length"),
    }
}

/// Structural checks of a report: sorted disjoint intervals within [0, 1] covering it, boundaries
/// sorted and at feasible/infeasible transitions, τ consistent with t.
fn check_structure(ev: &Evaluator, k: usize, r: &VerifyReport, stats: &mut Stats, keep: &mut usize) {
    let traj = &ev.scenario.trajectories[k];
    let mk = |t: f64, detail: String| Failure {
        kind: "structure",
        scenario: ev.scenario.name.clone(),
        trajectory: traj.name.clone(),
        t,
        detail,
    };
    for (name, list) in [("feasible", &r.feasible), ("infeasible", &r.infeasible), ("uncertain", &r.uncertain)] {
        for iv in list.iter() {
            if !(iv[0] <= iv[1] && iv[0] >= 0.0 && iv[1] <= 1.0) {
                stats.fail(mk(iv[0], format!("{name} interval {iv:?} is not within [0,1]")), keep);
            }
        }
        for w in list.windows(2) {
            if w[0][1] > w[1][0] {
                stats.fail(mk(w[1][0], format!("{name} intervals {:?}, {:?} not sorted/disjoint", w[0], w[1])), keep);
            }
        }
    }
    let mut all: Vec<([f64; 2], &str)> = r
        .feasible
        .iter()
        .map(|iv| (*iv, "feasible"))
        .chain(r.infeasible.iter().map(|iv| (*iv, "infeasible")))
        .chain(r.uncertain.iter().map(|iv| (*iv, "uncertain")))
        .collect();
    all.sort_by(|a, b| a.0[0].partial_cmp(&b.0[0]).unwrap());
    let mut reach = 0.0f64;
    for (iv, name) in &all {
        if iv[0] > reach + 1e-12 {
            stats.fail(mk(reach, format!("[{reach}, {}] is covered by no interval", iv[0])), keep);
        }
        if iv[0] < reach - 1e-12 {
            stats.fail(mk(iv[0], format!("{name} interval {iv:?} overlaps an earlier one ending at {reach}")), keep);
        }
        reach = reach.max(iv[1]);
    }
    if reach < 1.0 - 1e-12 {
        stats.fail(mk(reach, format!("[{reach}, 1] is covered by no interval")), keep);
    }
    for w in r.boundaries.windows(2) {
        if w[0].t > w[1].t {
            stats.fail(mk(w[1].t, "boundaries not sorted".into()), keep);
        }
    }
    let theta = traj.theta();
    for b in &r.boundaries {
        let tau = tau_of_t(theta, b.t);
        if (tau - b.tau).abs() > 1e-9 {
            stats.fail(mk(b.t, format!("boundary tau {} but tau(t) = {}", b.tau, tau)), keep);
        }
        let (from, to) = match b.enters {
            Side::Feasible => (&r.infeasible, &r.feasible),
            Side::Infeasible => (&r.feasible, &r.infeasible),
        };
        let ends_from = from.iter().any(|iv| (iv[1] - b.t).abs() <= 1e-12)
            || r.uncertain.iter().any(|iv| (iv[1] - b.t).abs() <= 1e-12);
        let starts_to = to.iter().any(|iv| (iv[0] - b.t).abs() <= 1e-12);
        if !(ends_from && starts_to) {
            stats.fail(
                mk(
                    b.t,
                    format!(
                        "boundary ({}, enters {:?}) is not at a matching interval transition",
                        b.constraint, b.enters
                    ),
                ),
                keep,
            );
        }
    }
    if r.feasible_tau.len() != r.feasible.len() || r.infeasible_tau.len() != r.infeasible.len() {
        stats.fail(mk(0.0, "tau interval lists differ in length from the t lists".into()), keep);
    } else {
        for (a, b) in r.feasible.iter().zip(&r.feasible_tau).chain(r.infeasible.iter().zip(&r.infeasible_tau)) {
            for e in 0..2 {
                if (tau_of_t(theta, a[e]) - b[e]).abs() > 1e-9 {
                    stats.fail(mk(a[e], format!("tau interval {b:?} does not match t interval {a:?}")), keep);
                }
            }
        }
    }
}

/// Compares one report against the reference: structure, `nsamples` jittered samples plus probes
/// around every boundary, and the feasibility change across every boundary.
pub fn check_report(ev: &Evaluator, k: usize, r: &VerifyReport, nsamples: usize, seed: u64) -> Stats {
    let mut stats = Stats { trajectories: 1, ..Default::default() };
    let mut keep = 5usize;
    let traj = &ev.scenario.trajectories[k];
    let tol = 1e-9 * ev.scale;
    check_structure(ev, k, r, &mut stats, &mut keep);

    stats.feasible_len = r.feasible.iter().map(|iv| iv[1] - iv[0]).sum();
    stats.infeasible_len = r.infeasible.iter().map(|iv| iv[1] - iv[0]).sum();
    stats.uncertain_len = r.uncertain.iter().map(|iv| iv[1] - iv[0]).sum();
    stats.trajectories_with_uncertain = usize::from(!r.uncertain.is_empty());

    let mut bts: Vec<f64> = r.boundaries.iter().map(|b| b.t).collect();
    bts.sort_by(|a, b| a.partial_cmp(b).unwrap());
    // Interval ends that are not boundaries (e.g. next to uncertain intervals) are excluded too.
    let mut ends: Vec<f64> = bts.clone();
    for iv in r.feasible.iter().chain(&r.infeasible) {
        ends.extend([iv[0], iv[1]].into_iter().filter(|&e| e > 0.0 && e < 1.0));
    }
    ends.sort_by(|a, b| a.partial_cmp(b).unwrap());

    // Samples: stratified jitter, the ends, and probes on both sides of every boundary.
    let mut rng = Rng::new(seed);
    let mut ts: Vec<f64> = (0..nsamples).map(|i| (i as f64 + rng.f64()) / nsamples as f64).collect();
    ts.extend([0.0, 1.0]);
    for &b in &bts {
        for d in NEAR_OFFSETS {
            ts.extend([b - d, b + d]);
        }
    }
    ts.retain(|t| (0.0..=1.0).contains(t));

    for &t in &ts {
        stats.samples += 1;
        if in_intervals(&r.uncertain, t) {
            stats.skipped_uncertain += 1;
            continue;
        }
        if near_any(&ends, t, BOUNDARY_EPS) {
            stats.skipped_near_boundary += 1;
            continue;
        }
        let (inf, ininf) = (in_intervals(&r.feasible, t), in_intervals(&r.infeasible, t));
        if inf == ininf {
            let f = Failure {
                kind: "coverage",
                scenario: ev.scenario.name.clone(),
                trajectory: traj.name.clone(),
                t,
                detail: format!("sample in {} of the feasible/infeasible lists", if inf { "both" } else { "neither" }),
            };
            stats.fail(f, &mut keep);
            continue;
        }
        stats.judged += 1;
        let reference = ev.feasible(k, t);
        if reference != inf {
            let checks = ev.checks(k, t);
            let m = overall_margin(&checks);
            if m.abs() <= tol {
                stats.tolerated += 1;
                continue;
            }
            let f = Failure {
                kind: "contradiction",
                scenario: ev.scenario.name.clone(),
                trajectory: traj.name.clone(),
                t,
                detail: format!(
                    "reference {} but reported {}; overall margin {:.3e}; critical: {}",
                    if reference { "feasible" } else { "infeasible" },
                    if inf { "feasible" } else { "infeasible" },
                    m,
                    critical_checks(&checks, 3)
                ),
            };
            stats.fail(f, &mut keep);
        }
    }

    // Boundaries: the reference must change across each one, in the reported direction, and the
    // named constraint must be at its limit there.
    let uncertain_near =
        |t: f64| r.uncertain.iter().any(|iv| iv[0] <= t + BOUNDARY_PROBE && iv[1] >= t - BOUNDARY_PROBE);
    for (bi, b) in r.boundaries.iter().enumerate() {
        stats.boundaries += 1;
        let other_near = r.boundaries.iter().enumerate().any(|(bj, o)| bj != bi && (o.t - b.t).abs() <= BOUNDARY_PROBE);
        let lo = (b.t - BOUNDARY_PROBE).max(0.0);
        let hi = (b.t + BOUNDARY_PROBE).min(1.0);
        let checks_at = ev.checks(k, b.t);
        // label: one of the conditions at their limit at b.t must be the named one
        let near_zero: Vec<&Check> = checks_at.iter().filter(|c| c.margin.abs() <= 1e-6 * ev.scale).collect();
        if !near_zero.is_empty() {
            stats.labels_checked += 1;
            if let Some(c) = near_zero.iter().find(|c| label_names(&b.constraint, ev, c)) {
                let kind = match (c.cables.1, c.obstacle) {
                    (Some(_), _) => "cable-cable",
                    (None, Some(k)) => ev.scenario.obstacles[k].shape.kind(),
                    (None, None) => "length",
                };
                *stats.boundary_kinds.entry(kind).or_default() += 1;
            } else {
                let f = Failure {
                    kind: "label",
                    scenario: ev.scenario.name.clone(),
                    trajectory: traj.name.clone(),
                    t: b.t,
                    detail: format!(
                        "boundary names '{}' but the conditions at their limit are: {}",
                        b.constraint,
                        near_zero.iter().map(|c| c.label.as_str()).collect::<Vec<_>>().join(", ")
                    ),
                };
                stats.fail(f, &mut keep);
            }
        }
        if other_near || uncertain_near(b.t) || lo == b.t || hi == b.t {
            stats.boundaries_skipped += 1;
            continue;
        }
        stats.boundaries_checked += 1;
        let (fl, fh) = (ev.feasible(k, lo), ev.feasible(k, hi));
        let want_hi = matches!(b.enters, Side::Feasible);
        if fl != fh && fh == want_hi {
            continue;
        }
        let (ml, mh) = (overall_margin(&ev.checks(k, lo)), overall_margin(&ev.checks(k, hi)));
        if ml.abs() <= tol || mh.abs() <= tol {
            stats.tolerated += 1;
            continue;
        }
        let f = Failure {
            kind: "boundary",
            scenario: ev.scenario.name.clone(),
            trajectory: traj.name.clone(),
            t: b.t,
            detail: format!(
                "boundary '{}' enters {:?}, but the reference is {} at t-1e-6 (margin {:.3e}) and {} at t+1e-6 \
                 (margin {:.3e}); at t: {}",
                b.constraint,
                b.enters,
                if fl { "feasible" } else { "infeasible" },
                ml,
                if fh { "feasible" } else { "infeasible" },
                mh,
                critical_checks(&checks_at, 3)
            ),
        };
        stats.fail(f, &mut keep);
    }
    stats
}

/// Verifies every trajectory of `sc` with cablenav and checks each report. Parse and verify
/// errors (and panics) are failures too. When `dump_dir` is given, failing scenarios are
/// written there as JSON.
pub fn run_scenario(sc: &RefScenario, nsamples: usize, seed: u64, dump_dir: Option<&str>) -> Stats {
    let mut stats = Stats::default();
    let json = sc.to_json();
    let ev = sc.evaluator();
    let parsed = cablenav::Scenario::from_json(&json);
    let scenario = match parsed {
        Ok(s) => s,
        Err(e) => {
            stats.fail(
                Failure {
                    kind: "parse",
                    scenario: sc.name.clone(),
                    trajectory: String::new(),
                    t: 0.0,
                    detail: e.to_string(),
                },
                &mut 5,
            );
            dump(dump_dir, sc, &json);
            return stats;
        }
    };
    for (k, traj) in scenario.trajectories.iter().enumerate() {
        let started = now();
        let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            cablenav::verify::verify_trajectory(&scenario, traj)
        }));
        let secs = elapsed(started);
        stats.verify_seconds += secs;
        if secs > stats.slowest_verify.0 {
            stats.slowest_verify = (secs, format!("{}/{}", sc.name, sc.trajectories[k].name));
        }
        let fail = |kind, detail: String| Failure {
            kind,
            scenario: sc.name.clone(),
            trajectory: sc.trajectories[k].name.clone(),
            t: 0.0,
            detail,
        };
        match result {
            Ok(Ok(report)) => {
                let s = check_report(&ev, k, &report, nsamples, seed.wrapping_add(k as u64));
                stats.merge(s);
            }
            Ok(Err(e)) => {
                stats.trajectories += 1;
                stats.fail(fail("verify-error", e.to_string()), &mut 5);
            }
            Err(_) => {
                stats.trajectories += 1;
                stats.fail(fail("panic", "verify_trajectory panicked".into()), &mut 5);
            }
        }
    }
    if !stats.failure_counts.is_empty() {
        dump(dump_dir, sc, &json);
    }
    stats
}

#[cfg(not(target_arch = "wasm32"))]
fn dump(dir: Option<&str>, sc: &RefScenario, json: &str) {
    if let Some(d) = dir {
        let _ = std::fs::create_dir_all(d);
        let _ = std::fs::write(format!("{d}/{}.json", sc.name), json);
    }
}

#[cfg(target_arch = "wasm32")]
fn dump(_dir: Option<&str>, _sc: &RefScenario, _json: &str) {}

#[cfg(not(target_arch = "wasm32"))]
pub type Instant = std::time::Instant;
#[cfg(not(target_arch = "wasm32"))]
pub fn now() -> Instant {
    std::time::Instant::now()
}
#[cfg(not(target_arch = "wasm32"))]
pub fn elapsed(i: Instant) -> f64 {
    i.elapsed().as_secs_f64()
}

#[cfg(target_arch = "wasm32")]
pub type Instant = ();
#[cfg(target_arch = "wasm32")]
pub fn now() -> Instant {}
#[cfg(target_arch = "wasm32")]
pub fn elapsed(_: Instant) -> f64 {
    0.0
}
