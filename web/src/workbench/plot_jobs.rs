//! The plots along the followed path (clearances, tension envelope), computed in one resident
//! Web Worker: a new path sends a job that supersedes the previous one; they follow a drag at
//! its end (the strip and the view follow every move).

use super::path::{is_chain, PathSignals};
use crate::state::Shared;
use crate::worker::host;
use crate::worker::protocol::{pose_to_wire, Job, Reply};
use cablenav::report::TensionEnvelope;
use cablenav::verify::profile::ClearanceProfile;
use leptos::prelude::*;

/// Samples per path for the clearance and tension plots.
pub const PLOT_SAMPLES: usize = 200;

/// The clearance profile along the path and its label, as the worker last answered.
pub type Profile = RwSignal<Option<Shared<(Result<ClearanceProfile, String>, String)>>>;
/// The tension envelope, the x axis' name and (a timed trajectory) its duration.
pub type Envelope = RwSignal<Option<Shared<(Result<TensionEnvelope, String>, &'static str, Option<f64>)>>>;

/// Starts the plots' worker for the path `path` follows (the scenario's JSON from `source`),
/// resting while `drag_active`; returns the signals its answers land in.
pub fn profiles_in_worker(path: PathSignals, source: RwSignal<String>, drag_active: RwSignal<bool>) -> (Profile, Envelope) {
    let parsed = path.parsed;
    let profile_data = RwSignal::new(None::<Shared<(Result<ClearanceProfile, String>, String)>>);
    // the envelope, the x axis' name and (a timed trajectory) its duration
    let envelope = RwSignal::new(None::<Shared<(Result<TensionEnvelope, String>, &'static str, Option<f64>)>>);
    let plots_worker: StoredValue<host::Resident, LocalStorage> = StoredValue::new_local(host::Resident::new());
    Effect::new(move |_| {
        if drag_active.get() {
            return;
        }
        if is_chain(&parsed.get()) {
            plots_worker.with_value(host::Resident::forget);
            let e = "not drawn for multi-link robots yet: their clearances are certified in the strip and the intervals (docs/multilink.md)".to_string();
            profile_data.set(Some(Shared::new((Err(e.clone()), String::new()))));
            envelope.set(Some(Shared::new((Err("a multi-link robot has no wrench set: its wrench condition is joint-space wrench closure, in the strip".to_string()), "t", None))));
            return;
        }
        let request = path.followed(|_, path| {
            let samples = path.samples(PLOT_SAMPLES).iter().map(|(t, p)| (*t, pose_to_wire(p))).collect();
            Some((path.name(), path.param(), samples, path.timed()))
        });
        let Some((name, param, samples, timed)) = request else {
            plots_worker.with_value(host::Resident::forget);
            profile_data.set(None);
            envelope.set(None);
            return;
        };
        let Some(json) = source.try_get_untracked() else { return };
        let label = format!("{name}; x: {param}");
        let (trajectory, duration) = match timed {
            Some((n, d)) => (Some(n), d),
            None => (None, None),
        };
        let on_reply = move |reply: Reply| {
            let (clearances, tension) = match reply {
                Reply::Progress { .. } => return,
                Reply::Profiles { clearances, tension } => (clearances.map(Into::into), tension.map(Into::into)),
                Reply::Failed { error } => (Err(error.clone()), Err(error)),
                _ => {
                    let e = "the worker answered a plots job with another job's reply".to_string();
                    (Err(e.clone()), Err(e))
                }
            };
            profile_data.set(Some(Shared::new((clearances, label.clone()))));
            envelope.set(Some(Shared::new((tension, param, duration))));
        };
        match plots_worker.with_value(|w| w.send(&Job::Profiles { scenario: json, name: name.clone(), samples, trajectory }, on_reply)) {
            Ok(()) => {}
            Err(e) => {
                profile_data.set(Some(Shared::new((Err(e.clone()), format!("{name}; x: {param}")))));
                envelope.set(Some(Shared::new((Err(e), param, duration))));
            }
        }
    });
    (profile_data, envelope)
}
