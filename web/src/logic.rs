//! Everything the page shows, computed by plain functions over the core's results (no Leptos
//! here, so all of it is unit-tested natively). No maths either: the intervals come from
//! `cablenav::verify`; this module only sorts and formats them.

use cablenav::report::{Seconds, Side, VerifyReport};
use cablenav::Scenario;

/// What a t-section of the strip is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SectionKind {
    /// Every constraint holds.
    Feasible,
    /// Some constraint is violated.
    Infeasible,
    /// The core could not decide.
    Uncertain,
}

impl SectionKind {
    /// The name used in `data-kind`, CSS classes and the table.
    pub fn as_str(self) -> &'static str {
        match self {
            SectionKind::Feasible => "feasible",
            SectionKind::Infeasible => "infeasible",
            SectionKind::Uncertain => "uncertain",
        }
    }
}

/// One drawn section of the strip: `t ∈ [t0, t1]`, with the τ range where the core gives one.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// What it is.
    pub kind: SectionKind,
    /// Start in t.
    pub t0: f64,
    /// End in t.
    pub t1: f64,
    /// The same section in τ, for feasible and infeasible sections.
    pub tau: Option<[f64; 2]>,
}

/// One boundary tick: where the motion enters or leaves the feasible set.
#[derive(Debug, Clone, PartialEq)]
pub struct Tick {
    /// Where, in t.
    pub t: f64,
    /// Where, in τ.
    pub tau: f64,
    /// The constraint that becomes (in)active there.
    pub constraint: String,
    /// The side entered at `t`: `"feasible"` or `"infeasible"`.
    pub enters: &'static str,
    /// The tooltip text.
    pub label: String,
}

/// The strip, the tables and the notes for one verified trajectory.
#[derive(Debug, Clone, PartialEq)]
pub struct StripModel {
    /// Sections sorted by start.
    pub sections: Vec<Section>,
    /// Boundaries sorted by t.
    pub ticks: Vec<Tick>,
    /// Parts of [0, 1] that no section covers (should be empty; shown if not).
    pub gaps: Vec<[f64; 2]>,
    /// A timed trajectory's duration (s): the strip's axis is then in seconds as well.
    pub duration: Option<f64>,
}

impl StripModel {
    /// The strip's axis label at t: t itself, or for a timed trajectory the time it is reached.
    pub fn axis_label(&self, t: f64) -> String {
        match self.duration {
            Some(d) => format!("{} s", fmt_num(t * d)),
            None => fmt_num(t),
        }
    }
}

/// Parses scenario JSON with the core; the error is the core's "field: reason" text.
pub fn parse_scenario(text: &str) -> Result<Scenario, String> {
    Scenario::from_json(text).map_err(|e| e.to_string())
}

/// Verifies trajectory `index` of `scenario` (a multi-link robot's path through configurations
/// alike) with the core.
pub fn verify(scenario: &Scenario, index: usize) -> Result<VerifyReport, String> {
    let along = along(scenario, index)?;
    cablenav::verify::verify_along(scenario, along).map_err(|e| e.to_string())
}

/// [`verify`] without the search of the least time scale: the sections at the trajectory's own
/// timing, what a drag's live update needs (the search follows when the drag ends).
pub fn verify_sections(scenario: &Scenario, index: usize) -> Result<VerifyReport, String> {
    let along = along(scenario, index)?;
    cablenav::verify::verify_along_sections(scenario, along).map_err(|e| e.to_string())
}

/// Trajectory (or multi-link path) `index` of the scenario.
fn along(scenario: &Scenario, index: usize) -> Result<cablenav::verify::Along<'_>, String> {
    cablenav::verify::all_along(scenario).get(index).copied().ok_or_else(|| format!("trajectory #{index}: the scenario has no such trajectory"))
}

/// Names of the scenario's trajectories (a multi-link robot's paths), in file order.
pub fn trajectory_names(scenario: &Scenario) -> Vec<String> {
    cablenav::verify::all_along(scenario).iter().map(|a| a.name().to_string()).collect()
}

/// Trajectory `index` of the scenario, or its last one past the end (`None`: it has none).
pub fn trajectory_index(scenario: &Scenario, index: usize) -> Option<usize> {
    cablenav::verify::all_along(scenario).len().checked_sub(1).map(|last| index.min(last))
}

/// A number for people: up to 4 decimals, trailing zeros dropped ("0.25", "1", "0.3333").
pub fn fmt_num(x: f64) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    let s = format!("{x:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".to_string() } else { s.to_string() }
}

/// What the page says about a timed trajectory's fastest uniform timing (docs/dynamics.md): the
/// least certified scale and duration, the largest one where slower fails too, or why there is
/// none; then the core's note on what binds.
pub fn time_scale_summary(s: &Seconds) -> String {
    let lead = match (s.min_time_scale, s.min_duration, s.max_time_scale) {
        (Some(k), Some(d), Some(k_max)) => {
            format!("Certified for durations from {} s to {} s (time scale {} to {})", fmt_num(d), fmt_num(k_max * s.duration), fmt_num(k), fmt_num(k_max))
        }
        (Some(k), Some(d), None) if k <= 1.0 => format!("Could run in {} s (time scale {}; certified for every slower timing)", fmt_num(d), fmt_num(k)),
        (Some(k), Some(d), None) => format!("Must run slower: at least {} s (time scale {})", fmt_num(d), fmt_num(k)),
        _ if s.min_time_scale_note == cablenav::verify::timing::NOT_SEARCHED => return "The fastest timing is searched when the drag ends.".to_string(),
        _ => "No certified timing".to_string(),
    };
    format!("{lead}. {}", s.min_time_scale_note)
}

/// Intervals as `[a, b] ∪ [c, d]` (`none` for none), their ends as [`fmt_num`] writes them.
pub fn intervals_text(v: &[[f64; 2]]) -> String {
    if v.is_empty() {
        return "none".to_string();
    }
    v.iter().map(|[a, b]| format!("[{}, {}]", fmt_num(*a), fmt_num(*b))).collect::<Vec<_>>().join(" ∪ ")
}

/// A number for machines (`data-t0` etc.): the shortest text that parses back to the same f64.
pub fn fmt_exact(x: f64) -> String {
    format!("{x:?}")
}

/// Builds the strip from a report: feasible, infeasible and uncertain sections sorted by t,
/// boundary ticks with their tooltips, and any gaps in the cover of [0, 1].
pub fn strip(report: &VerifyReport) -> StripModel {
    let mut sections = Vec::new();
    for (i, &[t0, t1]) in report.feasible.iter().enumerate() {
        sections.push(Section { kind: SectionKind::Feasible, t0, t1, tau: report.feasible_tau.get(i).copied() });
    }
    for (i, &[t0, t1]) in report.infeasible.iter().enumerate() {
        sections.push(Section { kind: SectionKind::Infeasible, t0, t1, tau: report.infeasible_tau.get(i).copied() });
    }
    for &[t0, t1] in &report.uncertain {
        sections.push(Section { kind: SectionKind::Uncertain, t0, t1, tau: None });
    }
    // by t0, then t1 (two stable sorts, the minor key first)
    cablenav::order::sort_by_key(&mut sections, |s| s.t1);
    cablenav::order::sort_by_key(&mut sections, |s| s.t0);

    let duration = report.seconds.as_ref().map(|s| s.duration);
    let at = |t: f64| duration.map_or_else(String::new, |d| format!(", {} s", fmt_num(t * d)));
    let mut ticks: Vec<Tick> = report
        .boundaries
        .iter()
        .map(|b| {
            let enters = match b.enters {
                Side::Feasible => "feasible",
                Side::Infeasible => "infeasible",
            };
            let label = format!("t = {} (τ = {}{}): {} — enters {}", fmt_num(b.t), fmt_num(b.tau), at(b.t), b.constraint, enters);
            Tick { t: b.t, tau: b.tau, constraint: b.constraint.clone(), enters, label }
        })
        .collect();
    cablenav::order::sort_by_key(&mut ticks, |t| t.t);

    let gaps = gaps(&sections);
    StripModel { sections, ticks, gaps, duration }
}

/// Parts of [0, 1] not covered by `sections` (sorted by start), ignoring gaps below 1e-12.
pub fn gaps(sections: &[Section]) -> Vec<[f64; 2]> {
    const EPS: f64 = 1e-12;
    let mut out = Vec::new();
    let mut reached = 0.0_f64;
    for s in sections {
        if s.t0 > reached + EPS {
            out.push([reached, s.t0]);
        }
        reached = reached.max(s.t1);
    }
    if reached < 1.0 - EPS {
        out.push([reached, 1.0]);
    }
    out
}

/// The notes shown under the strip: the scenario's warnings, then the report's; duplicates
/// dropped.
pub fn notes(scenario_warnings: &[String], report: Option<&VerifyReport>) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let report_warnings = report.map(|r| r.warnings.as_slice()).unwrap_or_default();
    for w in scenario_warnings.iter().chain(report_warnings) {
        if !out.contains(w) {
            out.push(w.clone());
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use cablenav::report::Boundary;

    fn report() -> VerifyReport {
        VerifyReport {
            trajectory: "line".into(),
            method: "exact".into(),
            step: None,
            feasible: vec![[0.5, 1.0], [0.0, 0.25]],
            infeasible: vec![[0.25, 0.4]],
            feasible_tau: vec![[0.6, 1.0], [0.0, 0.2]],
            infeasible_tau: vec![[0.2, 0.3]],
            boundaries: vec![
                Boundary { t: 0.4, tau: 0.3, constraint: "cables 2–5".into(), enters: Side::Feasible },
                Boundary { t: 0.25, tau: 0.2, constraint: "cable 1 vs box".into(), enters: Side::Infeasible },
            ],
            uncertain: vec![[0.4, 0.5]],
            warnings: vec!["w".into()],
            seconds: None,
        }
    }

    #[test]
    fn a_timed_strip_is_labelled_in_seconds() {
        let mut r = report();
        assert_eq!(strip(&r).axis_label(0.25), "0.25");
        r.seconds = Some(Box::new(Seconds {
            duration: 2.0,
            feasible: vec![],
            infeasible: vec![],
            uncertain: vec![],
            min_time_scale: None,
            min_time_scale_bracket: None,
            min_duration: None,
            max_time_scale: None,
            min_time_scale_note: String::new(),
            infeasible_at_rest: vec![],
        }));
        let m = strip(&r);
        assert_eq!(m.axis_label(0.25), "0.5 s");
        assert!(m.ticks[0].label.starts_with("t = 0.25 (τ = 0.2, 0.5 s): "), "{}", m.ticks[0].label);
    }

    #[test]
    fn timed_reports_say_how_fast() {
        let mut sec = Seconds {
            duration: 2.0,
            feasible: vec![[0.0, 2.0]],
            infeasible: vec![],
            uncertain: vec![],
            min_time_scale: Some(0.5),
            min_time_scale_bracket: Some([0.49995, 0.5]),
            min_duration: Some(1.0),
            max_time_scale: None,
            min_time_scale_note: "binding: cable 2 speed".into(),
            infeasible_at_rest: vec![],
        };
        assert_eq!(time_scale_summary(&sec), "Could run in 1 s (time scale 0.5; certified for every slower timing). binding: cable 2 speed");
        (sec.min_time_scale, sec.min_duration) = (Some(1.5), Some(3.0));
        assert!(time_scale_summary(&sec).starts_with("Must run slower: at least 3 s"));
        sec.max_time_scale = Some(2.0);
        assert!(time_scale_summary(&sec).starts_with("Certified for durations from 3 s to 4 s"));
        (sec.min_time_scale, sec.min_duration, sec.max_time_scale) = (None, None, None);
        assert!(time_scale_summary(&sec).starts_with("No certified timing."));
    }

    #[test]
    fn sections_are_sorted_and_keep_their_tau() {
        let m = strip(&report());
        let kinds: Vec<_> = m.sections.iter().map(|s| s.kind).collect();
        assert_eq!(kinds, [SectionKind::Feasible, SectionKind::Infeasible, SectionKind::Uncertain, SectionKind::Feasible]);
        assert_eq!(m.sections[0].tau, Some([0.0, 0.2]));
        assert_eq!(m.sections[2].tau, None);
        assert_eq!(m.sections[3].tau, Some([0.6, 1.0]));
        assert!(m.gaps.is_empty());
    }

    #[test]
    fn ticks_are_sorted_and_labelled() {
        let m = strip(&report());
        assert_eq!(m.ticks.len(), 2);
        assert_eq!(m.ticks[0].t, 0.25);
        assert_eq!(m.ticks[0].enters, "infeasible");
        assert_eq!(m.ticks[0].label, "t = 0.25 (τ = 0.2): cable 1 vs box — enters infeasible");
        assert_eq!(m.ticks[1].enters, "feasible");
    }

    #[test]
    fn gaps_are_found() {
        let s = |t0, t1| Section { kind: SectionKind::Feasible, t0, t1, tau: None };
        assert_eq!(gaps(&[]), vec![[0.0, 1.0]]);
        assert_eq!(gaps(&[s(0.0, 0.5), s(0.6, 1.0)]), vec![[0.5, 0.6]]);
        assert_eq!(gaps(&[s(0.1, 0.9)]), vec![[0.0, 0.1], [0.9, 1.0]]);
        assert!(gaps(&[s(0.0, 0.5), s(0.2, 0.7), s(0.7, 1.0)]).is_empty());
    }

    #[test]
    fn numbers_format() {
        assert_eq!(fmt_num(0.25), "0.25");
        assert_eq!(fmt_num(1.0), "1");
        assert_eq!(fmt_num(1.0 / 3.0), "0.3333");
        assert_eq!(fmt_num(-0.00001), "0");
        assert_eq!(fmt_exact(0.1), "0.1");
        assert_eq!(fmt_exact(1.0), "1.0");
        assert_eq!(fmt_exact(1.0 / 3.0).parse::<f64>().unwrap(), 1.0 / 3.0);
    }

    #[test]
    fn notes_merge_without_duplicates() {
        let r = report();
        let n = notes(&["w".into(), "s".into()], Some(&r));
        assert_eq!(n, ["w", "s"]);
        assert_eq!(notes(&[], None), Vec::<String>::new());
    }

    #[test]
    fn parse_errors_are_text() {
        let e = parse_scenario("{").unwrap_err();
        assert!(!e.is_empty());
        let e = parse_scenario("").unwrap_err();
        assert!(!e.is_empty());
    }

    #[test]
    fn every_preset_parses_and_verifies_covering_0_1() {
        for p in crate::presets::PRESETS {
            let s = parse_scenario(p.json).unwrap_or_else(|e| panic!("{}: {e}", p.id));
            let n = trajectory_names(&s).len();
            assert!(n > 0, "{} has no trajectory", p.id);
            for i in 0..n {
                let r = verify(&s, i).unwrap_or_else(|e| panic!("{} #{i}: {e}", p.id));
                let m = strip(&r);
                assert!(!m.sections.is_empty(), "{} #{i}: no section", p.id);
                assert!(m.gaps.is_empty(), "{} #{i}: gaps {:?}", p.id, m.gaps);
            }
        }
    }

    #[test]
    fn a_missing_trajectory_is_an_error_not_a_panic() {
        let s = parse_scenario(crate::presets::PRESETS[0].json).unwrap();
        assert!(verify(&s, usize::MAX).is_err());
    }

    #[test]
    fn a_multi_link_robots_paths_are_verified() {
        let arm = parse_scenario(include_str!("../../static/multilink/bmarm-x4-2.json")).unwrap();
        assert_eq!(trajectory_names(&arm), ["across the gap"]);
        let r = verify(&arm, 0).unwrap();
        let m = strip(&r);
        assert_eq!(m.sections.iter().map(|s| s.kind).collect::<Vec<_>>(), [SectionKind::Feasible, SectionKind::Infeasible, SectionKind::Feasible]);
        assert!(m.ticks.iter().all(|t| t.constraint == "cables 2-3"));
        assert!(verify(&arm, 1).is_err());
    }
}
