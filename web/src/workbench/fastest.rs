//! "Fastest safe timing" for the selected trajectory (docs/timing.md): on request one worker times
//! its path as fast as its limits allow, certified along it (`cablenav time`), and the page shows
//! the certified duration beside the uncertified optimum, the binding constraint stretch by
//! stretch, and the speed and tensions against time. Cancel stops the worker; a new scenario or
//! trajectory drops the result.
//!
//! Test contract: the button `[data-testid=fastest-run]` (and `fastest-cancel` while running),
//! the status `[data-testid=fastest-status]`, the result `[data-testid=fastest]` with
//! `data-trajectory`, `data-duration` (empty when not certified), `data-uncertified`, and its
//! table `[data-testid=fastest-binding]`, one row per stretch.

use crate::logic::{self, fmt_num};
use crate::plots::timing::TimingChart;
use crate::state::Parsed;
use crate::worker::host::{self, FanOut};
use crate::worker::protocol::{Job, Reply};
use cablenav::report::TimingReport;
use leptos::prelude::*;

/// A worker's answer: the report (or why there is none) and its time (ms).
type Timed = (Result<TimingReport, String>, f64);

/// The panel for trajectory `trajectory` of the scenario `source` parses to (`parsed`).
#[component]
pub fn FastestTiming(parsed: Memo<Parsed>, source: RwSignal<String>, trajectory: Signal<usize>) -> impl IntoView {
    let result = RwSignal::new(None::<Result<TimingReport, String>>);
    let running = RwSignal::new(false);
    let status = RwSignal::new(String::new());
    let run = FanOut::new();
    // a new scenario or trajectory: what was shown no longer holds
    Effect::new(move |_| {
        parsed.track();
        trajectory.track();
        run.stop();
        running.set(false);
        result.set(None);
        status.set(String::new());
    });
    let start = move |_| {
        let Some(json) = source.try_get_untracked() else { return };
        let index = trajectory.get_untracked();
        let this = run.stop();
        result.set(None);
        running.set(true);
        status.set("timing the path and certifying it in a worker…".to_string());
        let part = move |reply: Reply| match reply {
            Reply::Progress { detail, .. } => {
                // a reply already on its way when Cancel stopped the run says nothing now
                if run.is_current(this) {
                    status.set(detail);
                }
                None
            }
            Reply::Timed { report, error, ms } if error.is_empty() => Some(Ok((serde_json::from_str(&report).map_err(|e| e.to_string()), ms))),
            Reply::Timed { error, ms, .. } => Some(Ok((Err(error), ms))),
            Reply::Failed { error } => Some(Err(error)),
            _ => Some(Err("the worker answered with another job's reply".to_string())),
        };
        let done = move |got: Result<Vec<Timed>, String>| {
            run.finish(this, || {
                running.set(false);
                match got.map(|mut v| v.pop()) {
                    Ok(Some((report, ms))) => {
                        status.set(format!("done in {} ms", fmt_num(ms)));
                        result.set(Some(report));
                    }
                    Ok(None) => status.set("no answer".to_string()),
                    Err(e) => status.set(format!("could not time it: {e}")),
                }
            })
        };
        match host::start_all(&[Job::Time { scenario: json, index }], part, |_, _| {}, done) {
            Ok(started) => run.hold(started),
            Err(e) => {
                running.set(false);
                status.set(format!("could not start a worker: {e}"));
            }
        }
    };
    let cancel = move |_| {
        run.stop();
        running.set(false);
        status.set("cancelled".to_string());
    };
    let bounds = move || parsed.with(|p| p.0.as_ref().as_ref().map(|s| s.robot.cables.iter().map(|c| [c.tension.min, c.tension.max]).collect::<Vec<_>>()).unwrap_or_default());
    view! {
        <section class="fastest" aria-label="fastest safe timing">
            <h3>"Fastest safe timing"</h3>
            <p class="hint">
                "The path timed from rest to rest as fast as the tension bounds (with the wrench set, the platform's weight and inertia), the winch limits and the platform's speed limit allow — certified between the grid's points by the exact verifier, not only at them."
            </p>
            <p>
                <button data-testid="fastest-run" on:click=start disabled=move || running.get()>"Fastest safe timing"</button>
                " "
                {move || running.get().then(|| view! { <button data-testid="fastest-cancel" on:click=cancel>"Cancel"</button> })}
                " "
                <span class="readout" data-testid="fastest-status" aria-live="polite">{move || status.get()}</span>
            </p>
            {move || match result.get() {
                None => ().into_any(),
                Some(Err(e)) => view! { <p class="error" data-testid="fastest-error" role="alert">{e}</p> }.into_any(),
                Some(Ok(r)) => view! { <Summary report=r bounds=bounds() /> }.into_any(),
            }}
        </section>
    }
}

/// A timing report: the durations, the binding stretches and the plot.
#[component]
fn Summary(report: TimingReport, bounds: Vec<[f64; 2]>) -> impl IntoView {
    let headline = match report.duration {
        Some(d) => format!(
            "{} s certified (the grid's uncertified optimum {} s: the certificate costs {} %)",
            fmt_num(d),
            fmt_num(report.uncertified_duration),
            fmt_num(100.0 * report.certificate_cost.unwrap_or(0.0))
        ),
        None => format!("not certified on t ∈ {} after {} rounds", logic::intervals_text(&report.not_certified), report.rounds),
    };
    view! {
        <div data-testid="fastest" data-trajectory=report.trajectory.clone() data-duration=report.duration.map(logic::fmt_exact).unwrap_or_default()
            data-uncertified=logic::fmt_exact(report.uncertified_duration)>
            <p><strong>{headline}</strong>{format!(" — {} cells, {} certification rounds.", report.cells, report.rounds)}</p>
            <TimingChart report=report.clone() bounds />
            <table data-testid="fastest-binding">
                <caption>"What binds along the path"</caption>
                <thead><tr><th>"t"</th><th>"seconds"</th><th>"constraint"</th></tr></thead>
                <tbody>
                    {report.binding.iter().map(|b| view! {
                        <tr>
                            <td>{format!("{} – {}", fmt_num(b.t[0]), fmt_num(b.t[1]))}</td>
                            <td>{format!("{} – {}", fmt_num(b.seconds[0]), fmt_num(b.seconds[1]))}</td>
                            <td>{b.constraint.clone()}</td>
                        </tr>
                    }).collect_view()}
                </tbody>
            </table>
        </div>
    }
}
