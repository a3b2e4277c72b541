//! Clearance profiles along a path, sampled: at each sample pose the least cable–cable and the least
//! cable–obstacle distance, from the conditions' point-wise [`Condition::check`] — data for a plot,
//! never a certificate (the exact sections come from [`super::verify_trajectory`]). Also the state
//! of every cable at one pose (interference, length, tension margin), for drawing it.

use super::wrench_at;
use crate::conditions::{self, for_scenario, Condition};
use crate::error::{Error, Result};
use crate::model::{Pose, Trajectory};
use crate::query::cables::{cables_at, cables_at_config, PoseCables};
use crate::scenario::Scenario;
use serde::Serialize;

/// Most samples accepted along one path.
pub const MAX_SAMPLES: usize = 100_000;

/// What a tagged condition is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Profiled {
    CableCable,
    /// A cable's clearance to an obstacle, or to a link of a multi-link robot.
    CableBody,
    Length,
}

/// A condition with the cables it concerns.
struct Tagged {
    kind: Profiled,
    cables: Vec<usize>,
    condition: Box<dyn Condition>,
}

/// The length and clearance conditions of `s` ([`crate::conditions::for_scenario`]), tagged with
/// their kind and cables; tensions are read from [`wrench_at`] instead, and the winch limits,
/// which need time, are not profiled.
fn tagged_conditions(s: &Scenario) -> Vec<Tagged> {
    for_scenario(s)
        .into_iter()
        .filter_map(|condition| {
            let cables = condition.cables();
            let kind = match (condition.kind(), cables.len()) {
                (conditions::Kind::Length, _) => Profiled::Length,
                (conditions::Kind::Interference, 2) => Profiled::CableCable,
                (conditions::Kind::Interference, _) => Profiled::CableBody,
                (conditions::Kind::Tension | conditions::Kind::Winch, _) => return None,
            };
            Some(Tagged { kind, cables, condition })
        })
        .collect()
}

/// The least distance of one kind at one pose, and between what.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Closest {
    /// The distance: between cable centrelines, or from a centreline to an obstacle's surface.
    pub distance: f64,
    /// The condition it comes from, e.g. `"cables 2-5"`, `"cable 3 - crown"`.
    pub between: String,
}

/// The clearances at one sample.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ClearanceSample {
    /// The path parameter.
    pub t: f64,
    /// The least cable–cable distance (`None` when no pair of cables is checked).
    pub cable_cable: Option<Closest>,
    /// The least cable–obstacle distance over the obstacles whose check gives one (`None` if
    /// none does).
    pub cable_obstacle: Option<Closest>,
    /// Labels of the length and clearance conditions violated at this sample (including the
    /// obstacles checked by membership only).
    pub violated: Vec<String>,
}

/// Clearances along a path.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ClearanceProfile {
    /// The samples, in path order.
    pub samples: Vec<ClearanceSample>,
    /// The required cable–cable clearance.
    pub clearance_cable_cable: f64,
    /// The required cable–obstacle clearance.
    pub clearance_cable_obstacle: f64,
    /// Cable–obstacle conditions decided by membership only (none of today's shapes: every one
    /// reports an exact distance); their violations would appear in each sample's `violated` but
    /// not in `cable_obstacle`.
    pub membership_only: Vec<String>,
}

/// The state of one cable at one pose.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CableState {
    /// A cable–cable or cable–obstacle clearance involving this cable is violated.
    pub interfering: bool,
    /// Its length is within its bounds.
    pub length_ok: bool,
    /// Its tension margin over the wrench set, min(f_min-side, f_max-side) in force units
    /// (negative when a bound is crossed); `None` without a wrench section or at a singular pose.
    pub tension_margin: Option<f64>,
    /// Its tension bounds' width f_max − f_min, to scale the margin.
    pub tension_span: f64,
}

fn least(best: &mut Option<Closest>, distance: f64, label: impl FnOnce() -> String) {
    if best.as_ref().is_none_or(|b| distance < b.distance) {
        *best = Some(Closest { distance, between: label() });
    }
}

/// The clearances of `s` at the given `(t, pose)` samples (e.g. the poses of a planned path).
pub fn clearances_at(s: &Scenario, samples: &[(f64, Pose)]) -> Result<ClearanceProfile> {
    if samples.len() > MAX_SAMPLES {
        return Err(Error::new("samples", format!("at most {MAX_SAMPLES} samples, got {}", samples.len())));
    }
    if s.robot.chain.is_some() {
        return Err(Error::new("robot.links", "clearance profiles along poses are for platform robots; a multi-link robot's clearances are in its verification"));
    }
    let conditions = tagged_conditions(s);
    let mut out = Vec::with_capacity(samples.len());
    for (t, pose) in samples {
        let cables = cables_at(&s.robot, pose);
        let mut sample = ClearanceSample { t: *t, cable_cable: None, cable_obstacle: None, violated: vec![] };
        for c in &conditions {
            let r = c.condition.check(&cables);
            if r.violated {
                sample.violated.push(c.condition.label());
            }
            match (c.kind, r.distance) {
                (Profiled::CableCable, Some(d)) => least(&mut sample.cable_cable, d, || c.condition.label()),
                (Profiled::CableBody, Some(d)) => least(&mut sample.cable_obstacle, d, || c.condition.label()),
                _ => {}
            }
        }
        out.push(sample);
    }
    let probe = samples.first().map(|(_, p)| cables_at(&s.robot, p));
    let membership_only = conditions
        .iter()
        .filter(|c| c.kind == Profiled::CableBody && probe.as_ref().is_some_and(|cables| c.condition.check(cables).distance.is_none()))
        .map(|c| c.condition.label())
        .collect();
    Ok(ClearanceProfile {
        samples: out,
        clearance_cable_cable: s.clearance.cable_cable,
        clearance_cable_obstacle: s.clearance.cable_obstacle,
        membership_only,
    })
}

/// The clearances along `traj` at `samples` + 1 evenly spaced t in [0, 1].
pub fn clearances_along(s: &Scenario, traj: &Trajectory, samples: usize) -> Result<ClearanceProfile> {
    if samples == 0 || samples >= MAX_SAMPLES {
        return Err(Error::new("samples", format!("must be between 1 and {}, got {samples}", MAX_SAMPLES - 1)));
    }
    let poses: Vec<(f64, Pose)> = (0..=samples)
        .map(|k| {
            let t = k as f64 / samples as f64;
            (t, traj.pose_at(t))
        })
        .collect();
    clearances_at(s, &poses)
}

/// The state of each cable of `s` at `pose`, in cable order.
pub fn cable_states(s: &Scenario, pose: &Pose) -> Vec<CableState> {
    let wrench = wrench_at(s, pose).filter(|w| !w.singular);
    states_of(s, &cables_at(&s.robot, pose), wrench)
}

/// The state of each cable of `s` at configuration `q` (a multi-link robot's joint coordinates,
/// or a platform pose's six coordinates), in cable order; a multi-link robot has no wrench set,
/// so no tension margins.
pub fn cable_states_at(s: &Scenario, q: &[f64]) -> Vec<CableState> {
    let cables = cables_at_config(&s.robot, q);
    let wrench = if s.robot.chain.is_none() { wrench_at(s, &cables.pose).filter(|w| !w.singular) } else { None };
    states_of(s, &cables, wrench)
}

fn states_of(s: &Scenario, cables: &PoseCables, wrench: Option<crate::report::WrenchReport>) -> Vec<CableState> {
    let mut out: Vec<CableState> = s
        .robot
        .cables
        .iter()
        .enumerate()
        .map(|(i, c)| CableState {
            interfering: false,
            length_ok: true,
            // per-cable ranges exist for six cables only (with more the tensions are not unique)
            tension_margin: wrench
                .as_ref()
                .and_then(|w| Some((w.tension_min.get(i)? - c.tension.min).min(c.tension.max - w.tension_max.get(i)?))),
            tension_span: c.tension.max - c.tension.min,
        })
        .collect();
    for c in tagged_conditions(s) {
        if c.condition.check(cables).violated {
            for &i in &c.cables {
                match c.kind {
                    Profiled::Length => out[i].length_ok = false,
                    Profiled::CableCable | Profiled::CableBody => out[i].interfering = true,
                }
            }
        }
    }
    out
}

/// Each cable's tension range over the wrench set at the given `(t, pose)` samples (e.g. a
/// planned path's poses), as [`super::tension_envelope`] gives it along a trajectory; `name`
/// labels the path. As many cables as degrees of freedom only (six on a spatial platform, three
/// on a point mass or a planar one; with more the tensions are not unique): an error says so.
pub fn tension_at(s: &Scenario, name: &str, samples: &[(f64, Pose)]) -> Result<crate::report::TensionEnvelope> {
    if s.load().is_none() {
        return Err(Error::new("wrench", "the scenario has no wrench section and no platform dynamics: no tensions to compute"));
    }
    let (m, n) = (s.robot.cables.len(), s.robot.mobility.dof());
    if m != n {
        return Err(Error::new(
            "wrench",
            format!("each cable's tension range is defined for as many cables as degrees of freedom ({n} here); with {m} the tensions balancing a wrench are not unique (check gives the wrench set's margin instead)"),
        ));
    }
    if samples.len() > MAX_SAMPLES {
        return Err(Error::new("samples", format!("at most {MAX_SAMPLES} samples, got {}", samples.len())));
    }
    let mut env = crate::report::TensionEnvelope {
        trajectory: name.to_string(),
        t: vec![],
        tension_min: vec![],
        tension_max: vec![],
        bounds: s.robot.cables.iter().map(|c| [c.tension.min, c.tension.max]).collect(),
    };
    for (t, pose) in samples {
        push_tensions(&mut env, *t, wrench_at(s, pose));
    }
    Ok(env)
}

/// [`tension_at`] with the cables at each sample given (moving, along a timed trajectory).
pub fn tension_of(s: &Scenario, name: &str, samples: &[(f64, PoseCables)]) -> Result<crate::report::TensionEnvelope> {
    let mut env = tension_at(s, name, &[])?;
    if samples.len() > MAX_SAMPLES {
        return Err(Error::new("samples", format!("at most {MAX_SAMPLES} samples, got {}", samples.len())));
    }
    for (t, cables) in samples {
        push_tensions(&mut env, *t, super::wrench_of(s, cables));
    }
    Ok(env)
}

/// One sample of an envelope: the tension ranges of a wrench report, `None` where singular.
fn push_tensions(env: &mut crate::report::TensionEnvelope, t: f64, w: Option<crate::report::WrenchReport>) {
    let w = w.filter(|w| !w.singular);
    env.t.push(t);
    env.tension_min.push(w.as_ref().map(|w| w.tension_min.clone()));
    env.tension_max.push(w.map(|w| w.tension_max));
}
