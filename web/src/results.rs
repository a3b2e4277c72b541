//! The verification result as the page shows it: the strip of sections with its colour key (on
//! the first screen, under the 3-D view), and the tables of intervals and boundaries with the
//! warnings (in the results panels). Both read the page's `parsed` and `verified` memos.

use cablenav::report::{Seconds, VerifyReport};
use leptos::prelude::*;

use crate::logic::{self, fmt_num, Section, StripModel};
use crate::plots::strip::Strip;
use crate::state::{Parsed, Verified};

/// The verification result on the first screen: the scenario's or the verification's error, or
/// the strip of sections with its colour key. Test contract: `section[data-testid=result]` with
/// `data-origin`, `data-trajectory-index`, `data-follow` (`trajectory` or `planned`) and
/// `data-method`.
#[component]
pub fn StripResult(
    parsed: Memo<Parsed>,
    verified: Memo<Verified>,
    trajectory: RwSignal<usize>,
    origin: RwSignal<&'static str>,
    /// Whether `verified` is the planned motion's (`data-follow="planned"`), not the selected
    /// trajectory's.
    #[prop(optional, into)]
    planned: Signal<bool>,
) -> impl IntoView {
    move || {
        let parsed = parsed.get();
        let scenario = match parsed.0.as_ref() {
            Err(e) => return view! { <ErrorText prefix="Scenario" message=e.clone() /> }.into_any(),
            Ok(s) => s,
        };
        match verified.get().0.as_ref() {
            None => view! { <p class="empty">{format!("Scenario “{}” has no trajectory.", scenario.name)}</p> }.into_any(),
            Some(Err(e)) => view! { <ErrorText prefix="Verification" message=e.clone() /> }.into_any(),
            Some(Ok(report)) => {
                let index = logic::trajectory_index(scenario, trajectory.get()).unwrap_or(0);
                view! {
                    <section
                        class="result"
                        data-testid="result"
                        data-origin=origin.get()
                        data-trajectory-index=index
                        data-follow=if planned.get() { "planned" } else { "trajectory" }
                        data-method=report.method.clone()
                    >
                        <h2>{format!("{} — {}", scenario.name, report.trajectory)}</h2>
                        <Strip model=logic::strip(report) />
                        <Legend />
                    </section>
                }
                .into_any()
            }
        }
    }
}

/// The verification result in detail: the tables of intervals and boundaries, and the
/// scenario's and the report's warnings.
#[component]
pub fn ResultTables(parsed: Memo<Parsed>, verified: Memo<Verified>) -> impl IntoView {
    move || {
        let parsed = parsed.get();
        let Ok(scenario) = parsed.0.as_ref() else { return ().into_any() };
        let verified = verified.get();
        let notes_view = |report: Option<&VerifyReport>| view! { <Notes notes=logic::notes(&scenario.warnings, report) /> };
        match verified.0.as_ref() {
            Some(Ok(report)) => view! {
                {report.seconds.clone().map(|seconds| view! { <Timing seconds=*seconds trajectory=report.trajectory.clone() /> })}
                <Tables model=logic::strip(report) />
                {notes_view(Some(report))}
            }
            .into_any(),
            _ => notes_view(None).into_any(),
        }
    }
}

/// An error as text.
#[component]
fn ErrorText(prefix: &'static str, message: String) -> impl IntoView {
    view! {
        <p class="error" data-testid="error" role="alert">
            <strong>{format!("{prefix} error: ")}</strong>
            {message}
        </p>
    }
}

/// The colour key.
#[component]
fn Legend() -> impl IntoView {
    view! {
        <p class="legend">
            <span class="swatch feasible"></span>
            "feasible "
            <span class="swatch infeasible"></span>
            "infeasible "
            <span class="swatch uncertain"></span>
            "uncertain "
            <span class="tick-key"></span>
            "boundary (hover for the constraint)"
        </p>
    }
}

/// The tables of intervals and boundaries.
#[component]
fn Tables(model: StripModel) -> impl IntoView {
    let tau = |s: &Section| match s.tau {
        Some([a, b]) => (fmt_num(a), fmt_num(b)),
        None => ("—".to_string(), "—".to_string()),
    };
    view! {
        <div class="tables">
            <table data-testid="intervals">
                <caption>"Intervals"</caption>
                <thead>
                    <tr><th>"kind"</th><th>"t from"</th><th>"t to"</th><th>"τ from"</th><th>"τ to"</th></tr>
                </thead>
                <tbody>
                    {model
                        .sections
                        .iter()
                        .map(|s| {
                            let (a, b) = tau(s);
                            view! {
                                <tr class=s.kind.as_str()>
                                    <td>{s.kind.as_str()}</td>
                                    <td>{fmt_num(s.t0)}</td>
                                    <td>{fmt_num(s.t1)}</td>
                                    <td>{a}</td>
                                    <td>{b}</td>
                                </tr>
                            }
                        })
                        .collect_view()}
                </tbody>
            </table>
            <table data-testid="boundaries">
                <caption>"Boundaries"</caption>
                <thead>
                    <tr><th>"t"</th><th>"τ"</th><th>"constraint"</th><th>"enters"</th></tr>
                </thead>
                <tbody>
                    {if model.ticks.is_empty() {
                        view! { <tr><td colspan="4">"none"</td></tr> }.into_any()
                    } else {
                        model
                            .ticks
                            .iter()
                            .map(|t| {
                                view! {
                                    <tr>
                                        <td>{fmt_num(t.t)}</td>
                                        <td>{fmt_num(t.tau)}</td>
                                        <td>{t.constraint.clone()}</td>
                                        <td>{t.enters}</td>
                                    </tr>
                                }
                            })
                            .collect_view()
                            .into_any()
                    }}
                </tbody>
            </table>
        </div>
    }
}

/// A timed trajectory: its sections in seconds and how fast it may run. Test contract:
/// `[data-testid=timing]` with `data-trajectory` and `data-duration`, the summary
/// `[data-testid=time-scale]` with `data-min-duration` (empty when there is none), the table
/// `[data-testid=seconds]`.
#[component]
fn Timing(seconds: Seconds, trajectory: String) -> impl IntoView {
    let rows: Vec<(&'static str, [f64; 2])> = [("feasible", &seconds.feasible), ("infeasible", &seconds.infeasible), ("uncertain", &seconds.uncertain)]
        .into_iter()
        .flat_map(|(kind, v)| v.iter().map(move |iv| (kind, *iv)))
        .collect();
    view! {
        <section class="timing" data-testid="timing" data-trajectory=trajectory data-duration=logic::fmt_exact(seconds.duration)>
            <p data-testid="time-scale" data-min-duration=seconds.min_duration.map(logic::fmt_exact).unwrap_or_default()>
                <strong>{format!("Timed: {} s. ", fmt_num(seconds.duration))}</strong>
                {logic::time_scale_summary(&seconds)}
            </p>
            <table data-testid="seconds">
                <caption>"Sections in seconds"</caption>
                <thead>
                    <tr><th>"kind"</th><th>"from (s)"</th><th>"to (s)"</th></tr>
                </thead>
                <tbody>
                    {rows
                        .into_iter()
                        .map(|(kind, [a, b])| view! { <tr class=kind><td>{kind}</td><td>{fmt_num(a)}</td><td>{fmt_num(b)}</td></tr> })
                        .collect_view()}
                </tbody>
            </table>
        </section>
    }
}

/// The scenario's and the report's warnings.
#[component]
fn Notes(notes: Vec<String>) -> impl IntoView {
    (!notes.is_empty()).then(|| {
        view! {
            <section class="notes" data-testid="warnings">
                <h3>"Warnings"</h3>
                <ul>{notes.into_iter().map(|n| view! { <li>{n}</li> }).collect_view()}</ul>
            </section>
        }
    })
}

