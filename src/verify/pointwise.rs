//! The point-wise baseline: the same conditions checked at samples t = 0, Δt, 2Δt, …, 1. It is
//! what exact verification replaces, kept for tests and benchmarks. Boundaries are placed halfway
//! between the samples that disagree, so they are only as good as Δt.

use super::sections::{push_merged, sections, Piece};
use super::{trajectory_report, Along};
use crate::conditions::for_scenario;
use crate::error::{Error, Result};
use crate::model::Trajectory;
use crate::poly::Truth;
use crate::report::VerifyReport;
use crate::scenario::Scenario;

/// Most samples the baseline takes (Δt ≥ 1e-7).
const MAX_SAMPLES: f64 = 1e7;

/// Point-wise verification of a trajectory with step `dt`.
pub fn verify_pointwise(s: &Scenario, traj: &Trajectory, dt: f64) -> Result<VerifyReport> {
    verify_pointwise_along(s, Along::Trajectory(traj), dt)
}

/// Point-wise verification along a trajectory or a multi-link robot's path with step `dt`.
pub fn verify_pointwise_along(s: &Scenario, along: Along, dt: f64) -> Result<VerifyReport> {
    if !(dt.is_finite() && dt > 0.0 && dt <= 1.0) || 1.0 / dt > MAX_SAMPLES {
        return Err(Error::new("--pointwise", format!("the step must be in [1e-7, 1], got {dt}")));
    }
    let conditions = for_scenario(s);
    let n = (1.0 / dt).ceil() as usize;
    let ts: Vec<f64> = (0..=n).map(|k| (k as f64 * dt).min(1.0)).collect();
    let states: Vec<Vec<bool>> = ts
        .iter()
        .map(|&t| {
            let cables = along.cables_at(s, t);
            conditions.iter().map(|c| c.check(&cables).violated).collect()
        })
        .collect();
    // Each sample stands for the cell between the midpoints to its neighbours.
    let cell = |k: usize| {
        let a = if k == 0 { 0.0 } else { 0.5 * (ts[k - 1] + ts[k]) };
        let b = if k == n { 1.0 } else { 0.5 * (ts[k] + ts[k + 1]) };
        (a, b)
    };
    let pieces_of = |f: &dyn Fn(usize) -> bool| -> Vec<Piece> {
        let mut out: Vec<Piece> = Vec::new();
        for k in 0..=n {
            let (a, b) = cell(k);
            push_merged(&mut out, (a, b, if f(k) { Truth::True } else { Truth::False }));
        }
        out
    };
    let overall = pieces_of(&|k| states[k].iter().any(|&v| v));
    let per: Vec<Vec<Piece>> = (0..conditions.len()).map(|i| pieces_of(&|k| states[k][i])).collect();
    let sec = sections(&overall, &per, &|i| conditions[i].label(), 0.0);
    let seconds = super::timing::seconds(s, along, &sec, false);
    Ok(trajectory_report(along, sec, "pointwise", Some(dt), s.warnings.clone(), seconds))
}
