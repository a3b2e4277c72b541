//! Every trajectory of the scenario at once in the 3-D view, each in its exact sections (the
//! thesis' families of paths through via points, Figs. 4.4, 4.6 and 4.7, shown together): on
//! request, one worker verifies them all ([`Job::VerifyEvery`]) and the page draws the others
//! beside the selected one, green where feasible and red where not.

use crate::logic;
use crate::state::{Parsed, Shared};
use crate::view3d::scene::{self, Polyline};
use crate::worker::host::{self, FanOut};
use crate::worker::protocol::{Job, Reply, WireReport};
use leptos::prelude::*;

/// Every trajectory's exact sections as polylines, but trajectory `selected` (drawn on its own),
/// from the worker's reports (in the scenario's order); a trajectory whose verification failed
/// is left out.
pub fn pieces(s: &cablenav::Scenario, reports: &[Result<WireReport, String>], selected: usize) -> Vec<Polyline> {
    let mut out = Vec::new();
    for (i, (t, r)) in s.trajectories.iter().zip(reports).enumerate() {
        if let (Ok(r), true) = (r, i != selected) {
            out.extend(scene::section_polylines(&logic::strip(&r.report()), |u| t.pose_at(u)));
        }
    }
    out
}

/// The other trajectories' pieces while `on`, for the scenario `source` parses to (`parsed`),
/// beside trajectory `selected`; with a line for people on what is drawn (`status`).
pub fn every_trajectory(parsed: Memo<Parsed>, source: RwSignal<String>, selected: Signal<usize>, on: RwSignal<bool>, status: RwSignal<String>) -> Memo<Shared<Vec<Polyline>>> {
    let reports = RwSignal::new(None::<Shared<Vec<Result<WireReport, String>>>>);
    let run = FanOut::new();
    // a new scenario (or switching it on) verifies them all again in a worker
    Effect::new(move |_| {
        let parsed = parsed.get();
        let this = run.stop();
        reports.set(None);
        let Some(s) = parsed.0.as_ref().as_ref().ok().filter(|s| on.get() && s.robot.chain.is_none() && s.trajectories.len() > 1) else {
            let why = match parsed.0.as_ref().as_ref().ok() {
                Some(s) if on.get_untracked() && s.robot.chain.is_some() => "a multi-link robot's paths are drawn one at a time",
                Some(s) if on.get_untracked() && s.trajectories.len() < 2 => "the scenario has no other trajectory",
                _ => "",
            };
            status.set(why.to_string());
            return;
        };
        let Some(json) = source.try_get_untracked() else { return };
        let n = s.trajectories.len();
        status.set(format!("verifying {n} trajectories…"));
        let part = |reply: Reply| match reply {
            Reply::Progress { .. } => None,
            Reply::VerifiedEvery { reports } => Some(Ok(reports)),
            Reply::Failed { error } => Some(Err(error)),
            _ => Some(Err("the worker answered with another job's reply".to_string())),
        };
        let done = move |got: Result<Vec<Vec<Result<WireReport, String>>>, String>| {
            run.finish(this, || match got {
                Ok(mut all) => {
                    let got = all.pop().unwrap_or_default();
                    let failed = got.iter().filter(|r| r.is_err()).count();
                    status.set(format!("{n} trajectories drawn in their exact sections{}", if failed > 0 { format!(" ({failed} could not be verified)") } else { String::new() }));
                    reports.set(Some(Shared::new(got)));
                }
                Err(e) => status.set(format!("could not verify them: {e}")),
            })
        };
        match host::start_all(&[Job::VerifyEvery { scenario: json }], part, |_, _| {}, done) {
            Ok(started) => run.hold(started),
            Err(e) => status.set(format!("could not start a worker: {e}")),
        }
    });
    Memo::new(move |prev| {
        let parsed = parsed.get();
        let (Some(s), Some(r)) = (parsed.0.as_ref().as_ref().ok(), reports.get()) else { return Shared::or_same(prev, vec![]) };
        Shared::or_same(prev, pieces(s, &r.0, selected.get()))
    })
}
