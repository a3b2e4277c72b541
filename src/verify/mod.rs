//! Verification: where along a trajectory or a ray every condition holds, exactly (certified
//! polynomial sign partitions) or point-wise (the sampled baseline), and all conditions at one pose.

mod pointwise;
pub mod profile;
mod sections;
pub mod singular;
pub mod slice;
pub mod timing;

pub use pointwise::{verify_pointwise, verify_pointwise_along};
pub use sections::{push_merged, sections, Piece, Sections};
pub use slice::{slice, SliceMap};

use std::sync::atomic::{AtomicUsize, Ordering};
use crate::conditions::{for_scenario, Condition, Sweep};
use crate::model::{Bounds, Load};
use crate::query::cables::{cable_lengths, cables_at, cables_at_config, PoseCables};
use crate::query::wrench::{closure_holds, static_margin, wrench_set_margin};
use crate::error::{Error, Result};
use crate::model::motion::Param;
use crate::model::{Coord, JointPath, Motion, Pose, Trajectory};
use crate::poly::{Partition, Truth};
use crate::report::{Seconds, Boundary, CheckEntry, PoseReport, RayBoundary, RayReport, TensionEnvelope, VerifyReport, WrenchReport};
use crate::scenario::Scenario;

/// Accuracy of reported boundaries, in the user's parameter (t, or the ray's coordinate).
pub const BOUNDARY_TOL: f64 = 1e-10;

/// Violation pieces along a list of motions, mapped to user units and concatenated: the overall
/// union and each condition's own.
/// `duration` times the motion (a timed trajectory; `None` for a ray or an untimed one).
fn violation_pieces(conditions: &[Box<dyn Condition>], s: &Scenario, motions: &[Vec<Motion>], tol_user: f64, duration: Option<f64>) -> (Vec<Piece>, Vec<Vec<Piece>>) {
    pieces_settling(conditions, s, motions, tol_user, duration, true)
}

/// [`violation_pieces`], with `settle` saying whether conditions get the settled intervals.
/// Each entry of `motions` is one piece: the motion of every link (the platform's alone for a
/// platform robot).
fn pieces_settling(conditions: &[Box<dyn Condition>], s: &Scenario, motions: &[Vec<Motion>], tol_user: f64, duration: Option<f64>, settle: bool) -> (Vec<Piece>, Vec<Vec<Piece>>) {
    pieces_on(conditions, &mut sweeps(s, motions, tol_user, duration), settle)
}

/// The sweeps of the pieces `motions` (each the motion of every link), with the tolerance in λ
/// for `tol_user` in the user's parameter, timed by `duration` (`None`: at rest).
fn sweeps(s: &Scenario, motions: &[Vec<Motion>], tol_user: f64, duration: Option<f64>) -> Vec<Sweep> {
    motions
        .iter()
        .map(|links| {
            let tol = tol_user / links[0].param.max_slope().max(1e-300);
            let mut sweep = Sweep::of_links(&s.robot, links, tol);
            sweep.duration = duration;
            sweep
        })
        .collect()
}

/// The violation pieces of `conditions` along `sweeps` (consecutive pieces of one range), mapped
/// to user units and concatenated: the union and each condition's own. The sweeps keep the
/// polynomials the conditions expanded on them, so a caller may run them again — at another
/// duration, say — without expanding anew.
fn pieces_on(conditions: &[Box<dyn Condition>], sweeps: &mut [Sweep], settle: bool) -> (Vec<Piece>, Vec<Vec<Piece>>) {
    pieces_within(conditions, sweeps, settle, (false, false))
}

/// [`pieces_on`] for `sweeps` that are part of a longer run of pieces: `beyond` says whether
/// pieces of the run lie before the first sweep and after the last (their meeting points may be
/// boundaries, as between any two sweeps).
fn pieces_within(conditions: &[Box<dyn Condition>], sweeps: &mut [Sweep], settle: bool, beyond: (bool, bool)) -> (Vec<Piece>, Vec<Vec<Piece>>) {
    let mut per: Vec<Vec<Piece>> = vec![Vec::new(); conditions.len()];
    let mut overall: Vec<Piece> = Vec::new();
    let count = sweeps.len();
    for (piece, sweep) in sweeps.iter_mut().enumerate() {
        // the cheap conditions first, and within each cost those that seem violated earliest
        // (their hints; a stable sort keeps file order otherwise): where they already violate,
        // the others may stay undecided
        let hints: Vec<f64> = conditions.iter().map(|c| c.hint(sweep).unwrap_or(f64::INFINITY).clamp(0.0, 2.0)).collect();
        let mut order: Vec<usize> = (0..conditions.len()).collect();
        crate::order::sort_by_key(&mut order, |&k| 4.0 * f64::from(conditions[k].cost() as u8) + hints[k]);
        let tol = sweep.tol;
        sweep.settled.clear();
        let mut union = Partition::constant(Truth::False);
        // where the piece meets its neighbour a boundary may lie, so a margin is kept there too;
        // the range's own ends are no boundary
        let neighbours = (piece > 0 || beyond.0, piece + 1 < count || beyond.1);
        let mut found = vec![Partition::constant(Truth::False); conditions.len()];
        for &k in &order {
            found[k] = conditions[k].violation(sweep);
            union = union.or(&found[k]);
            // the union's violated set grows only where this condition is violated
            if settle && !found[k].is_all(Truth::False) {
                sweep.settled = settled(&union, SETTLED_MARGIN * tol, neighbours);
            }
        }
        // then the costlier local work, spared wherever any condition's first answer already
        // violates (the union only gains certainty here: it is made again from the answers)
        let wide = |f: &Partition| f.intervals().iter().any(|&(a, b, t)| t == Truth::Unknown && b - a > tol);
        if found.iter().any(wide) {
            for &k in &order {
                if !wide(&found[k]) {
                    continue;
                }
                let refined = conditions[k].refine(sweep, found[k].clone());
                if refined != found[k] {
                    found[k] = refined;
                    if settle {
                        union = union.or(&found[k]);
                        sweep.settled = settled(&union, SETTLED_MARGIN * tol, neighbours);
                    }
                }
            }
            union = found.iter().fold(Partition::constant(Truth::False), |u, f| u.or(f));
        }
        let param = sweep.motion().param;
        for (v, out) in found.iter().zip(per.iter_mut()) {
            append_mapped(out, v, &param);
        }
        append_mapped(&mut overall, &union, &param);
    }
    (overall, per)
}

/// How far (in tolerances) the settled intervals keep from the ends of the union's violated
/// intervals, so that a condition whose own boundary coincides with one of the union's is still
/// decided there and named as active.
const SETTLED_MARGIN: f64 = 8.0;

/// The intervals where `union` is certainly violated, each shrunk by `margin` at both ends, but
/// at λ = 0 and λ = 1 only where `neighbours` (before 0, after 1) says a piece meets it there:
/// the range's own ends are no boundary.
fn settled(union: &Partition, margin: f64, neighbours: (bool, bool)) -> Vec<(f64, f64)> {
    let shrink = |x: f64, by: f64| if (x == 0.0 && !neighbours.0) || (x == 1.0 && !neighbours.1) { x } else { x + by };
    union
        .where_is(Truth::True)
        .into_iter()
        .map(|(a, b)| (shrink(a, margin), shrink(b, -margin)))
        .filter(|(a, b)| a < b)
        .collect()
}

fn append_mapped(out: &mut Vec<Piece>, p: &Partition, param: &Param) {
    for (a, b, t) in p.intervals() {
        push_merged(out, (param.value(a), param.value(b), t));
    }
}

/// What a verification runs along: a platform robot's trajectory or a multi-link robot's path
/// through configurations; both parametrised by t ∈ [0, 1].
#[derive(Debug, Clone, Copy)]
pub enum Along<'a> {
    /// A platform robot's trajectory.
    Trajectory(&'a Trajectory),
    /// A multi-link robot's path.
    Joints(&'a JointPath),
}

impl Along<'_> {
    /// Its name.
    pub fn name(&self) -> &str {
        match self {
            Along::Trajectory(t) => &t.name,
            Along::Joints(p) => &p.name,
        }
    }

    /// Its pieces as the verifier takes them: the motion of every link per piece.
    fn motions(&self, s: &Scenario) -> Vec<Vec<Motion>> {
        match (self, &s.robot.chain) {
            (Along::Joints(p), Some(chain)) => p.motions(chain),
            (Along::Trajectory(t), _) => one_link(Motion::trajectory(t)),
            (Along::Joints(_), None) => Vec::new(),
        }
    }

    /// The cables at t (moving, on a timed trajectory).
    fn cables_at(&self, s: &Scenario, t: f64) -> PoseCables {
        match (self, &s.robot.chain) {
            (Along::Joints(p), Some(chain)) => cables_at_config(&s.robot, &p.config_at(chain, t)),
            // a path needs a chain (validation pairs them); without one only its start is known
            (Along::Joints(p), None) => cables_at_config(&s.robot, p.through.first().map_or(&[0.0; 6][..], |q| q)),
            (Along::Trajectory(traj), _) => {
                let at = cables_at(&s.robot, &traj.pose_at(t));
                match traj.duration {
                    Some(d) => at.moving(traj.kinematics_at(t, d)),
                    None => at,
                }
            }
        }
    }

    /// How long it takes in seconds, if it is timed.
    pub fn duration(&self) -> Option<f64> {
        match self {
            Along::Trajectory(t) => t.duration,
            Along::Joints(_) => None,
        }
    }

    /// The configuration at t: a multi-link robot's joint coordinates, or the platform pose's six
    /// coordinates (x, y, z, φ, θ, σ), as [`crate::query::cables::cables_at_config`] takes them.
    pub fn config_at(&self, s: &Scenario, t: f64) -> Vec<f64> {
        match (self, &s.robot.chain) {
            (Along::Joints(p), Some(chain)) => p.config_at(chain, t),
            (Along::Joints(p), None) => p.through.first().cloned().unwrap_or_default(),
            (Along::Trajectory(traj), _) => traj.pose_at(t).coords().to_vec(),
        }
    }

    /// τ of t (the trajectory's own parameter; t itself for a path).
    fn tau_of_t(&self, t: f64) -> f64 {
        match self {
            Along::Trajectory(traj) => traj.tau_of_t(t),
            Along::Joints(_) => t,
        }
    }
}

/// The trajectory (platform robot) or path (multi-link robot) called `name`, or the first one for
/// `None`.
pub fn along<'a>(s: &'a Scenario, name: Option<&str>) -> Result<Along<'a>> {
    if s.robot.chain.is_none() {
        return s.trajectory(name).map(Along::Trajectory);
    }
    let paths = &s.joint_paths;
    let found = match name {
        None => paths.first(),
        Some(n) => paths.iter().find(|p| p.name == n),
    };
    found.map(Along::Joints).ok_or_else(|| {
        let names: Vec<&str> = paths.iter().map(|p| p.name.as_str()).collect();
        let known = if names.is_empty() { "the scenario has no trajectories".to_owned() } else { format!("known trajectories: {}", names.join(", ")) };
        match name {
            None => Error::new("trajectory", "the scenario has no trajectories"),
            Some(n) => Error::new("trajectory", format!("no trajectory named \"{n}\"; {known}")),
        }
    })
}

/// Every trajectory of the scenario, in file order (a multi-link robot's paths).
pub fn all_along(s: &Scenario) -> Vec<Along<'_>> {
    match s.robot.chain {
        Some(_) => s.joint_paths.iter().map(Along::Joints).collect(),
        None => s.trajectories.iter().map(Along::Trajectory).collect(),
    }
}

/// Exact verification of a trajectory: feasible and infeasible t-intervals, each boundary certified
/// to [`BOUNDARY_TOL`] in t with its active constraint, or reported in `uncertain`.
pub fn verify_trajectory(s: &Scenario, traj: &Trajectory) -> Result<VerifyReport> {
    verify_along(s, Along::Trajectory(traj))
}

/// [`verify_trajectory`] without the search of the least time scale: the sections at the
/// trajectory's own timing (in t and, if timed, in seconds), the `seconds` object's scale fields
/// left empty with a note saying so — what a live update needs.
pub fn verify_sections(s: &Scenario, traj: &Trajectory) -> Result<VerifyReport> {
    verify_along_sections(s, Along::Trajectory(traj))
}

/// [`verify_sections`] along a trajectory or a multi-link robot's path.
pub fn verify_along_sections(s: &Scenario, along: Along) -> Result<VerifyReport> {
    verify_along_with(s, along, false)
}

/// Exact verification along a trajectory or a multi-link robot's path ([`verify_trajectory`]).
pub fn verify_along(s: &Scenario, along: Along) -> Result<VerifyReport> {
    verify_along_with(s, along, true)
}

/// [`verify_along`], with the time-scale search or (`scale` false) without.
fn verify_along_with(s: &Scenario, along: Along, scale: bool) -> Result<VerifyReport> {
    let conditions = for_scenario(s);
    let motions = along.motions(s);
    let (overall, per) = pieces_in_parts(&conditions, s, &motions, along.duration());
    let sec = sections(&overall, &per, &|k| conditions[k].label(), BOUNDARY_TOL);
    let mut warnings = s.warnings.clone();
    if !sec.uncertain.is_empty() {
        warnings.push(format!("{} section(s) could not be certified either way; see \"uncertain\"", sec.uncertain.len()));
    }
    let seconds = timing::seconds(s, along, &sec, scale);
    Ok(trajectory_report(along, sec, "exact", None, warnings, seconds))
}

/// Fewest pieces of a trajectory for which its verification is split into [`PARTS`].
const SPLIT_FROM: usize = 8;

/// How many runs of consecutive pieces a long trajectory's verification is split into.
const PARTS: usize = 2;

/// [`violation_pieces`] of the scenario's own `conditions` along a trajectory's `motions` at
/// [`BOUNDARY_TOL`]; from [`SPLIT_FROM`] pieces on, in [`PARTS`] runs of consecutive pieces,
/// each with conditions of its own, verified in parallel on native targets (the first run on the
/// calling thread, [`crate::parallel::map_parts`]; in order on wasm).
/// The runs are the same on every target and for any number of threads, and each starts afresh
/// (what a condition keeps from piece to piece, as the last certified tensions, stays within its
/// run), so the answer does not depend on the schedule.
fn pieces_in_parts(conditions: &[Box<dyn Condition>], s: &Scenario, motions: &[Vec<Motion>], duration: Option<f64>) -> (Vec<Piece>, Vec<Vec<Piece>>) {
    if motions.len() < SPLIT_FROM {
        return violation_pieces(conditions, s, motions, BOUNDARY_TOL, duration);
    }
    let size = motions.len().div_ceil(PARTS);
    let runs: Vec<&[Vec<Motion>]> = motions.chunks(size).collect();
    let part = |k: usize| {
        let beyond = (k > 0, k + 1 < runs.len());
        pieces_within(&for_scenario(s), &mut sweeps(s, runs[k], BOUNDARY_TOL, duration), true, beyond)
    };
    let parts = crate::parallel::map_parts(runs.len(), part);
    let mut per: Vec<Vec<Piece>> = vec![Vec::new(); conditions.len()];
    let mut overall = Vec::new();
    for (part_overall, part_per) in parts {
        part_overall.into_iter().for_each(|p| push_merged(&mut overall, p));
        for (out, pieces) in per.iter_mut().zip(part_per) {
            pieces.into_iter().for_each(|p| push_merged(out, p));
        }
    }
    (overall, per)
}

/// Verification of every trajectory of the scenario (what `cablenav verify SCENARIO --all`
/// reports), in file order: exact, or point-wise with step `pointwise`. The trajectories are
/// verified in parallel on native targets (each as [`verify_trajectory`], a long one in two runs
/// of pieces), in order on wasm. The first error (in file order) is returned.
pub fn verify_all(s: &Scenario, pointwise: Option<f64>) -> Result<Vec<VerifyReport>> {
    verify_all_counted(s, pointwise, &AtomicUsize::new(0))
}

/// [`verify_all`], adding 1 to `done` after each trajectory is verified (from any worker
/// thread), so that a caller on another thread can show progress.
pub fn verify_all_counted(s: &Scenario, pointwise: Option<f64>, done: &AtomicUsize) -> Result<Vec<VerifyReport>> {
    let all = all_along(s);
    let reports = crate::parallel::map_with(all.len(), || (), |_, i| {
        let report = match pointwise {
            Some(dt) => pointwise::verify_pointwise_along(s, all[i], dt),
            None => verify_along(s, all[i]),
        };
        done.fetch_add(1, Ordering::Relaxed);
        report
    });
    reports.into_iter().collect()
}

/// Builds the report of a trajectory from its sections in t.
fn trajectory_report(along: Along, sec: Sections, method: &str, step: Option<f64>, warnings: Vec<String>, seconds: Option<Box<Seconds>>) -> VerifyReport {
    let to_tau = |v: &[[f64; 2]]| v.iter().map(|iv| [along.tau_of_t(iv[0]), along.tau_of_t(iv[1])]).collect();
    VerifyReport {
        trajectory: along.name().to_string(),
        method: method.to_string(),
        step,
        feasible_tau: to_tau(&sec.feasible),
        infeasible_tau: to_tau(&sec.infeasible),
        boundaries: sec
            .boundaries
            .into_iter()
            .map(|(t, constraint, enters)| Boundary { t, tau: along.tau_of_t(t), constraint, enters })
            .collect(),
        feasible: sec.feasible,
        infeasible: sec.infeasible,
        uncertain: sec.uncertain,
        warnings,
        seconds,
    }
}

/// The pieces of a platform motion, each as the list of link motions the verifier takes.
fn one_link(motions: Vec<Motion>) -> Vec<Vec<Motion>> {
    motions.into_iter().map(|m| vec![m]).collect()
}

/// Exact feasible intervals of one coordinate over [lo, hi], the others held at the named pose's
/// (or a multi-link robot's configuration's).
pub fn ray(s: &Scenario, pose_name: &str, coord: Coord, lo: f64, hi: f64) -> Result<RayReport> {
    let q = s.config(pose_name)?;
    check_ray_range(coord, lo, hi)?;
    let conditions = for_scenario(s);
    let sec = ray_sections(s, &conditions, &q, coord, lo, hi);
    Ok(RayReport {
        vary: s.coord_name(coord),
        pose: pose_name.to_string(),
        range: [lo, hi],
        feasible: sec.feasible,
        infeasible: sec.infeasible,
        boundaries: sec.boundaries.into_iter().map(|(value, constraint, enters)| RayBoundary { value, constraint, enters }).collect(),
        uncertain: sec.uncertain,
        warnings: s.warnings.iter().cloned().chain(s.range_warning(coord, [lo, hi])).collect(),
    })
}

/// Checks a ray's range: finite LO < HI, and an angle range at most 64π wide.
pub fn check_ray_range(coord: Coord, lo: f64, hi: f64) -> Result<()> {
    if !(lo.is_finite() && hi.is_finite()) || lo >= hi {
        return Err(Error::new("--range", format!("needs finite LO < HI, got {lo} {hi}")));
    }
    if coord.is_angle() && hi - lo > 64.0 * std::f64::consts::PI {
        return Err(Error::new("--range", "an angle range wider than 64π is not meaningful"));
    }
    Ok(())
}

/// The sections of the ray through the configuration `c` (x, y, z, φ, θ, σ with the angles as
/// given, or a multi-link robot's joint coordinates) along `coord` over [lo, hi] (checked with
/// [`check_ray_range`]) under `conditions` (the scenario's, [`for_scenario`]), exactly; boundaries
/// certified to [`BOUNDARY_TOL`] relative to the range. What [`ray`] reports, and what the ray
/// lattice is made of.
pub fn ray_sections(s: &Scenario, conditions: &[Box<dyn Condition>], c: &[f64], coord: Coord, lo: f64, hi: f64) -> Sections {
    let motions = match &s.robot.chain {
        Some(chain) => chain.ray(c, coord.index(), lo, hi),
        None => one_link(Motion::ray_through([c[0], c[1], c[2], c[3], c[4], c[5]], coord, lo, hi)),
    };
    let tol = BOUNDARY_TOL * (hi - lo).abs().max(1.0);
    let (overall, per) = violation_pieces(conditions, s, &motions, tol, None);
    sections(&overall, &per, &|k| conditions[k].label(), tol)
}

/// Wrench feasibility of the scenario's robot at rest at `pose` (Bohigas et al. §3 for six
/// cables, the wrench set inside the available wrench set for more), if the scenario has a load
/// (a wrench section or the platform's dynamics).
pub fn wrench_at(s: &Scenario, pose: &Pose) -> Option<WrenchReport> {
    wrench_of(s, &cables_at(&s.robot, pose))
}

/// [`wrench_at`] for the cables `at` (moving as `at.kinematics` says, or at rest).
pub fn wrench_of(s: &Scenario, at: &PoseCables) -> Option<WrenchReport> {
    let load = s.load()?;
    let cables = &s.robot.cables;
    let bad_length = cables.iter().zip(at.iter()).position(|(c, (a, x))| !c.length.contains((x - a).norm()));
    if cables.len() != load.mobility.dof() {
        return Some(facet_report(s, at, &load, bad_length));
    }
    let Some(ranges) = at.tension_ranges(&load) else {
        return Some(WrenchReport {
            feasible: false,
            singular: true,
            margin: None,
            tension_min: vec![],
            tension_max: vec![],
            tension_nominal: vec![],
            active: "singular".to_string(),
        });
    };
    let mut margin = f64::INFINITY;
    let mut active = String::new();
    for (i, (r, c)) in ranges.iter().zip(cables).enumerate() {
        for (m, bound) in [(r.nominal - r.spread - c.tension.min, "lower"), (c.tension.max - r.nominal - r.spread, "upper")] {
            if m < margin {
                margin = m;
                active = format!("cable {} tension {bound} bound", i + 1);
            }
        }
    }
    if let Some(i) = bad_length {
        active = format!("cable {} length", i + 1);
    }
    Some(WrenchReport {
        feasible: margin > 0.0 && bad_length.is_none(),
        singular: false,
        margin: Some(margin),
        tension_min: ranges.iter().map(|r| r.nominal - r.spread).collect(),
        tension_max: ranges.iter().map(|r| r.nominal + r.spread).collect(),
        tension_nominal: ranges.iter().map(|r| r.nominal).collect(),
        active,
    })
}

/// The per-pose wrench report of a robot with more cables than degrees of freedom: the margin of the wrench set
/// inside the available wrench set (hyperplane shifting), the LP's tensions balancing the nominal
/// load, and wrench closure where the scenario asks for it (`tension_min`/`tension_max` stay
/// empty: the tensions are not unique).
fn facet_report(s: &Scenario, at: &PoseCables, load: &Load, bad_length: Option<usize>) -> WrenchReport {
    let wrench = &load.wrench;
    let point = wrench.point_at(&at.pose);
    let bounds: Vec<Bounds> = s.robot.cables.iter().map(|c| c.tension).collect();
    let closed = !wrench.closure
        || if crate::scenario::validate::facets_enumerable(bounds.len(), load.mobility) {
            closure_holds(&at.cables, &point, load.rows())
        } else {
            crate::query::wrench::closure_by_lp(&crate::query::wrench::structure_matrix_m(&at.cables, &point, load.rows()))
        };
    let nominal = at.nominal(load);
    let lp = static_margin(&at.cables, &point, &nominal, &bounds, load.rows());
    // a single wrench's margin is the linear program's; an ellipsoid's, hyperplane shifting's
    let margin = if wrench.is_single() { lp.as_ref().map(|(t, _)| *t) } else { wrench_set_margin(&at.cables, &point, &nominal, &wrench.ellipsoid_inv, &bounds, load.rows()) };
    let tensions = lp.map(|(_, f)| f).unwrap_or_default();
    let active = if let Some(i) = bad_length {
        format!("cable {} length", i + 1)
    } else if !closed {
        "wrench closure".to_string()
    } else {
        "wrench feasibility".to_string()
    };
    WrenchReport {
        feasible: closed && margin.is_some_and(|m| m > 0.0) && bad_length.is_none(),
        singular: margin.is_none(),
        margin,
        tension_min: vec![],
        tension_max: vec![],
        tension_nominal: tensions,
        active,
    }
}

/// The tension envelope along a trajectory (Bohigas et al. Fig. 6, bottom): at `samples` + 1
/// evenly spaced t, each cable's least and greatest tension over the wrench set (with the
/// platform's weight, and its inertia along a timed trajectory) — data for a plot. `None` entries
/// mark singular poses.
pub fn tension_envelope(s: &Scenario, traj: &Trajectory, samples: usize) -> Result<TensionEnvelope> {
    // samples + 1 poses, at most profile::MAX_SAMPLES of them.
    if samples == 0 || samples >= profile::MAX_SAMPLES {
        return Err(Error::new("--samples", format!("must be between 1 and {}, got {samples}", profile::MAX_SAMPLES - 1)));
    }
    let at: Vec<(f64, PoseCables)> = (0..=samples).map(|k| k as f64 / samples as f64).map(|t| (t, Along::Trajectory(traj).cables_at(s, t))).collect();
    profile::tension_of(s, &traj.name, &at)
}

/// Every condition where a trajectory is at t, moving as it moves there if it is timed (the
/// tension ranges then include the platform's inertia); the report names the pose `NAME@t`.
pub fn check_along(s: &Scenario, traj: &Trajectory, t: f64) -> Result<PoseReport> {
    if !(0.0..=1.0).contains(&t) {
        return Err(Error::new("--t", format!("must be in [0, 1], got {t}")));
    }
    let cables = Along::Trajectory(traj).cables_at(s, t);
    let wrench = wrench_of(s, &cables);
    Ok(check_cables(s, &format!("{}@{t}", traj.name), cables, wrench))
}

/// Every condition at one pose, with lengths and distances.
pub fn check_pose(s: &Scenario, name: &str, pose: &Pose) -> PoseReport {
    check_cables(s, name, cables_at(&s.robot, pose), wrench_at(s, pose))
}

/// Every condition at configuration `q` (a multi-link robot's joint coordinates, or a platform
/// pose's six coordinates), with lengths and distances.
pub fn check_config(s: &Scenario, name: &str, q: &[f64]) -> PoseReport {
    let cables = cables_at_config(&s.robot, q);
    let wrench = if s.robot.chain.is_none() { wrench_at(s, &cables.pose) } else { None };
    check_cables(s, name, cables, wrench)
}

fn check_cables(s: &Scenario, name: &str, cables: PoseCables, wrench: Option<WrenchReport>) -> PoseReport {
    let checks: Vec<CheckEntry> = for_scenario(s)
        .iter()
        .map(|c| {
            let r = c.check(&cables);
            CheckEntry { constraint: c.label(), violated: r.violated, distance: r.distance }
        })
        .collect();
    let violated: Vec<String> = checks.iter().filter(|c| c.violated).map(|c| c.constraint.clone()).collect();
    PoseReport {
        pose: name.to_string(),
        feasible: violated.is_empty(),
        lengths: cable_lengths(&s.robot, &cables),
        checks,
        violated,
        wrench,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The preset scenario file `name` (static/scenarios/).
    fn read(name: &str) -> String {
        std::fs::read_to_string(format!("{}/static/scenarios/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap()
    }

    /// Whether two sections agree: the same intervals and boundaries within `tol`, the same active
    /// constraints and sides.
    fn agree(a: &Sections, b: &Sections, tol: f64) -> bool {
        let close = |x: &[[f64; 2]], y: &[[f64; 2]]| x.len() == y.len() && x.iter().zip(y).all(|(p, q)| (p[0] - q[0]).abs() <= tol && (p[1] - q[1]).abs() <= tol);
        close(&a.feasible, &b.feasible)
            && close(&a.infeasible, &b.infeasible)
            && close(&a.uncertain, &b.uncertain)
            && a.boundaries.len() == b.boundaries.len()
            && a.boundaries.iter().zip(&b.boundaries).all(|(p, q)| (p.0 - q.0).abs() <= tol && p.1 == q.1 && p.2 == q.2)
    }

    /// The settled intervals (every condition skipping where the ones before it certainly violate)
    /// change no section, boundary (beyond its certified tolerance) or active constraint on the
    /// presets' trajectories, nor on a piecewise one whose pieces meet where a boundary may lie.
    #[test]
    fn settled_intervals_change_no_section() {
        let mut piecewise: serde_json::Value = serde_json::from_str(&read("cdpr7-tree.json")).unwrap();
        let piece = |a: [f64; 3], b: [f64; 3]| serde_json::json!({"translation": {"line": [a, b]}, "orientation": {"slerp": ["end", "end"]}});
        piecewise["format"] = serde_json::json!("cablenav-scenario/2");
        piecewise["trajectories"] = serde_json::json!([{"name": "through the crown", "pieces": [
            piece([1.5, 2.3, 3.0], [2.0, 1.5, 1.0]), piece([2.0, 1.5, 1.0], [2.5, 1.5, 1.0]), piece([2.5, 1.5, 1.0], [2.0, 1.0, 2.0])
        ]}]);
        let scenarios = ["cdpr7-tree.json", "cdpr7-box.json", "cdpr7.json", "robocrane.json"]
            .map(|name| (name.to_string(), Scenario::from_json(&read(name)).unwrap()))
            .into_iter()
            .chain([("piecewise".to_string(), Scenario::from_json(&piecewise.to_string()).unwrap())]);
        let mut infeasible = 0;
        for (name, s) in scenarios {
            let conditions = for_scenario(&s);
            for traj in &s.trajectories {
                let motions = one_link(Motion::trajectory(traj));
                let [with, without] = [true, false].map(|settle| {
                    let (overall, per) = pieces_settling(&conditions, &s, &motions, BOUNDARY_TOL, None, settle);
                    sections(&overall, &per, &|k| conditions[k].label(), BOUNDARY_TOL)
                });
                assert!(agree(&with, &without, 2.0 * BOUNDARY_TOL), "{name} {}: {with:?} vs {without:?}", traj.name);
                infeasible += with.infeasible.len();
            }
        }
        assert!(infeasible >= 3, "the trajectories must leave something to settle");
    }

    /// A trajectory of [`SPLIT_FROM`] pieces or more, verified in [`PARTS`] runs, has the sections
    /// of one run over all its pieces: a zigzag through cdpr7-tree's crown in nine pieces, violated
    /// on and off along both runs.
    #[test]
    fn runs_of_pieces_change_no_section() {
        let mut zigzag: serde_json::Value = serde_json::from_str(&read("cdpr7-tree.json")).unwrap();
        let corners = [[1.5, 2.3, 3.0], [2.0, 1.5, 1.0], [2.5, 1.5, 1.0], [2.0, 1.0, 2.0]];
        let pieces: Vec<serde_json::Value> = (0..9)
            .map(|k| serde_json::json!({"translation": {"line": [corners[k % 4], corners[(k + 1) % 4]]}, "orientation": {"slerp": ["end", "end"]}}))
            .collect();
        zigzag["format"] = serde_json::json!("cablenav-scenario/2");
        zigzag["trajectories"] = serde_json::json!([{"name": "zigzag", "pieces": pieces}]);
        let s = Scenario::from_json(&zigzag.to_string()).unwrap();
        let conditions = for_scenario(&s);
        let motions = one_link(Motion::trajectory(&s.trajectories[0]));
        assert!(motions.len() >= SPLIT_FROM, "{} pieces", motions.len());
        let label = |k: usize| conditions[k].label();
        let (overall, per) = pieces_in_parts(&conditions, &s, &motions, None);
        let in_runs = sections(&overall, &per, &label, BOUNDARY_TOL);
        let (overall, per) = violation_pieces(&conditions, &s, &motions, BOUNDARY_TOL, None);
        let in_one = sections(&overall, &per, &label, BOUNDARY_TOL);
        assert!(in_one.infeasible.len() >= 2 && !in_one.feasible.is_empty(), "{in_one:?}");
        assert!(agree(&in_runs, &in_one, 2.0 * BOUNDARY_TOL), "{in_runs:?} vs {in_one:?}");
    }
}
