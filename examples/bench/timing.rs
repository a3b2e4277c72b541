//! The fastest safe timing (`cablenav time`, docs/timing.md) on the timed presets and CoGiRo's
//! CASPR trajectories, natively, in one run:
//!
//!     cargo run --release --example bench -- timing
//!
//! prints one markdown table row per trajectory (`scripts/bench.sh --timing` writes them to the
//! "Fastest safe timing" section of docs/benchmarks.md): the certified duration, the grid's
//! uncertified optimum, what the certificate cost, and the median compute time of five runs (on
//! every core: the cells are verified in parallel).

use cablenav::plan::timing::{fastest, TimingOptions};
use cablenav::Scenario;
use std::time::Instant;

/// Runs the cases, printing a markdown row per trajectory.
pub fn run_timing() {
    let crane = Scenario::from_json(include_str!("../../static/scenarios/robocrane-timed.json")).expect("robocrane-timed.json");
    let caspr = |file: &str| std::fs::read_to_string(format!("../shared/models/caspr/CoGiRo/{file}")).expect("CoGiRo's CASPR files");
    let imported = cablenav::scenario::caspr::model_to_json("CoGiRo", &caspr("CoGiRo_bodies.xml"), &caspr("CoGiRo_cables.xml"), Some(&caspr("CoGiRo_trajectories.xml")), None).expect("CoGiRo imports");
    let cogiro = Scenario::from_json(&imported.json).expect("CoGiRo scenario");
    let cases: Vec<(&str, &Scenario, &str)> = vec![
        ("Robocrane timed", &crane, "slerp q1-q2"),
        ("Robocrane timed", &crane, "quick drop"),
        ("Robocrane timed", &crane, "swing"),
        ("CoGiRo (CASPR)", &cogiro, "general_1"),
        ("CoGiRo (CASPR)", &cogiro, "general_2"),
        ("CoGiRo (CASPR)", &cogiro, "general_3"),
        ("CoGiRo (CASPR)", &cogiro, "long_stable"),
    ];
    for (robot, s, name) in cases {
        let traj = s.trajectories.iter().find(|t| t.name == name).expect("trajectory");
        let mut times = Vec::new();
        let mut last = None;
        for _ in 0..5 {
            let started = Instant::now();
            last = Some(fastest(s, traj, TimingOptions::default()));
            times.push(started.elapsed().as_secs_f64() * 1000.0);
        }
        times.sort_by(f64::total_cmp);
        let ms = times[times.len() / 2];
        match last.expect("five runs") {
            Ok((r, _)) => {
                let certified = r.duration.map_or("not certified".to_string(), |d| format!("{d:.4} s"));
                let cost = r.certificate_cost.map_or("—".to_string(), |c| format!("{:.3} %", 100.0 * c));
                println!("| {robot} | `{name}` | {certified} | {:.4} s | {cost} | {} | {} | {ms:.0} ms |", r.uncertified_duration, r.cells, r.rounds);
            }
            Err(e) => println!("| {robot} | `{name}` | none: {} | — | — | — | — | {ms:.0} ms |", e.reason),
        }
    }
}
