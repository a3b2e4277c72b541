//! Exact verification while a drag goes on, in a Web Worker: the main thread only edits the
//! scenario and draws, so a slow verification (some via-point positions take 12 ms) never holds
//! a frame. The newest scenario is sent whenever the worker is free (moves in between are
//! skipped, never queued), its report replaces the strip's as it arrives, and when the drag ends
//! the page verifies the final scenario itself, as for any edit.

use crate::state::{Shared, Verified};
use crate::worker::host::Resident;
use crate::worker::protocol::{Job, Reply};
use leptos::prelude::*;

/// The live verification of a drag: the latest report in, and the worker's time for it.
#[derive(Clone, Copy)]
pub struct Live {
    /// The newest report the worker gave during this drag (`None` before the first).
    pub report: RwSignal<Option<Verified>>,
    /// How long the worker took for it (ms).
    pub ms: RwSignal<Option<f64>>,
    worker: StoredValue<Resident, LocalStorage>,
    busy: StoredValue<bool>,
    pending: StoredValue<Option<(String, usize)>>,
}

impl Live {
    /// Verifies `source`'s trajectory `trajectory` in a worker whenever `source` changes while
    /// `active` (a drag) holds.
    pub fn new(source: RwSignal<String>, trajectory: RwSignal<usize>, active: RwSignal<bool>) -> Live {
        let live = Live {
            report: RwSignal::new(None),
            ms: RwSignal::new(None),
            worker: StoredValue::new_local(Resident::new()),
            busy: StoredValue::new(false),
            pending: StoredValue::new(None),
        };
        Effect::new(move |_| {
            if !active.get() {
                live.stop();
                return;
            }
            let text = source.get();
            live.offer(text, trajectory.get_untracked());
        });
        live
    }

    /// Sends this scenario now if the worker is free, else when it is.
    fn offer(self, scenario: String, index: usize) {
        self.pending.set_value(Some((scenario, index)));
        if !self.busy.get_value() {
            self.dispatch();
        }
    }

    /// Sends the pending scenario, if any; its reply sends the next.
    fn dispatch(self) {
        let Some((scenario, index)) = self.pending.try_update_value(Option::take).flatten() else {
            self.busy.set_value(false);
            return;
        };
        self.busy.set_value(true);
        let on_reply = move |reply: Reply| {
            let report = match reply {
                Reply::Progress { .. } => return,
                Reply::Verified { report, ms } => {
                    self.ms.set(Some(ms));
                    report.map(|r| r.report())
                }
                Reply::Failed { error } => Err(error),
                _ => Err("the worker answered a verification with another job's reply".to_string()),
            };
            self.report.set(Some(Shared::new(Some(report))));
            self.dispatch();
        };
        if self.worker.with_value(|w| w.send(&Job::Verify { scenario, index }, on_reply)).is_err() {
            self.busy.set_value(false);
        }
    }

    /// The drag ended: replies still on their way are dropped, the next drag starts afresh.
    fn stop(self) {
        self.worker.with_value(Resident::forget);
        self.busy.set_value(false);
        self.pending.set_value(None);
        if self.report.with_untracked(Option::is_some) {
            self.report.set(None);
        }
    }
}
