//! The fastest safe timing (`cablenav time`, `cablenav::plan::timing`) on the presets and CoGiRo:
//! certified rest to rest, the limits it names binding, corners and standing stretches handled,
//! and bad input named. Its soundness and near-optimality against an independent reference on
//! random robots are in `tests/dynamics.rs`.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::plan::timing::{fastest, TimingOptions};
use cablenav::report::TimingReport;
use cablenav::Scenario;
use serde_json::{json, Value};

const TIMED: &str = include_str!("../static/scenarios/robocrane-timed.json");

fn timed_with(edit: impl FnOnce(&mut Value)) -> Scenario {
    let mut v: Value = serde_json::from_str(TIMED).unwrap();
    edit(&mut v);
    Scenario::from_json(&v.to_string()).unwrap()
}

fn time(s: &Scenario, name: &str, options: TimingOptions) -> cablenav::Result<TimingReport> {
    let traj = s.trajectories.iter().find(|t| t.name == name).expect("trajectory");
    fastest(s, traj, options).map(|(r, _)| r)
}

/// Every timed preset trajectory: certified, from rest to rest, time increasing along the profile,
/// the certificate costing little over the grid's optimum, the binding stretches covering the path.
#[test]
fn the_presets_time_certified_rest_to_rest() {
    let s = Scenario::from_json(TIMED).unwrap();
    for traj in &s.trajectories {
        let r = time(&s, &traj.name, TimingOptions::default()).unwrap();
        let d = r.duration.unwrap_or_else(|| panic!("{}: not certified on {:?}", traj.name, r.not_certified));
        assert!(d >= r.uncertified_duration && d <= 1.05 * r.uncertified_duration, "{}: {d} vs {}", traj.name, r.uncertified_duration);
        let (first, last) = (&r.profile[0], r.profile.last().unwrap());
        assert_eq!((first.t, first.time, first.rate), (0.0, 0.0, 0.0));
        assert_eq!((last.t, last.rate), (1.0, 0.0));
        assert!((last.time - d).abs() <= 1e-12 * d);
        assert!(r.profile.windows(2).all(|w| w[0].t < w[1].t && w[0].time < w[1].time), "{}: profile not increasing", traj.name);
        assert_eq!(r.binding.first().unwrap().t[0], 0.0);
        assert_eq!(r.binding.last().unwrap().t[1], 1.0);
        assert!(r.binding.windows(2).all(|w| w[0].t[1] == w[1].t[0] && w[0].constraint != w[1].constraint));
        // six cables, a load: the tensions are given at every point, within the bounds
        assert!(r.profile.iter().all(|p| p.tensions.len() == 6 && p.tensions.iter().all(|f| (0.0..=1.0).contains(f))));
    }
}

/// A finer grid costs less certificate and gets no slower: the law converges.
#[test]
fn a_finer_grid_converges() {
    let s = Scenario::from_json(TIMED).unwrap();
    let coarse = time(&s, "swing", TimingOptions { cells: 100, ..TimingOptions::default() }).unwrap();
    let fine = time(&s, "swing", TimingOptions { cells: 800, ..TimingOptions::default() }).unwrap();
    let (c, f) = (coarse.duration.unwrap(), fine.duration.unwrap());
    assert!((c - f).abs() <= 0.01 * f, "100 cells {c} s, 800 cells {f} s");
}

/// A speed limit on the platform: the profile never exceeds it and cruises at it.
#[test]
fn a_platform_speed_limit_binds() {
    let s = timed_with(|v| v["robot"]["speed"] = json!(0.05));
    let r = time(&s, "quick drop", TimingOptions::default()).unwrap();
    assert!(r.duration.is_some());
    let top = r.profile.iter().map(|p| p.speed).fold(0.0, f64::max);
    assert!(top <= 0.05 && top >= 0.049, "top speed {top}");
    assert!(r.binding.iter().any(|b| b.constraint == "platform speed"), "{:?}", r.binding);
    // the line is 0.206 m long: at most 0.05 m/s takes more than 4.1 s
    assert!(r.duration.unwrap() > 0.206 / 0.05);
}

/// Two lines meeting at a right angle: the platform stops at the corner (a velocity jump would
/// need an infinite force), and only there in between.
#[test]
fn a_corner_stops_the_platform() {
    let s = timed_with(|v| {
        v["format"] = json!("cablenav-scenario/4");
        v["trajectories"] = json!([{"name": "corner", "pieces": [
            {"translation": {"line": [[0, 0, 2], [0.1, 0, 2]]}, "orientation": {"slerp": ["q1", "q1"]}},
            {"translation": {"line": [[0.1, 0, 2], [0.1, 0.1, 2]]}, "orientation": {"slerp": ["q1", "q1"]}}]}]);
    });
    let r = time(&s, "corner", TimingOptions::default()).unwrap();
    assert!(r.duration.is_some());
    let stops: Vec<f64> = r.profile.iter().filter(|p| p.rate == 0.0).map(|p| p.t).collect();
    assert_eq!(stops, vec![0.0, 0.5, 1.0]);
}

/// Bad input: each a clear error naming its cause.
#[test]
fn bad_input_is_named() {
    let s = Scenario::from_json(TIMED).unwrap();
    let field = |r: cablenav::Result<TimingReport>| r.unwrap_err();
    let e = field(time(&s, "swing", TimingOptions { margin: 0.0, ..TimingOptions::default() }));
    assert_eq!(e.field, "--margin");
    let e = field(time(&s, "swing", TimingOptions { cells: 0, ..TimingOptions::default() }));
    assert_eq!(e.field, "--cells");
    // a zero speed limit is refused by the scenario itself
    let mut v: Value = serde_json::from_str(TIMED).unwrap();
    v["robot"]["speed"] = json!(0.0);
    assert_eq!(Scenario::from_json(&v.to_string()).unwrap_err().field, "robot.speed");
    // nothing limits the speed
    let s = timed_with(|v| {
        v["robot"].as_object_mut().unwrap().remove("dynamics");
        v["robot"].as_object_mut().unwrap().remove("winch");
    });
    let e = field(time(&s, "swing", TimingOptions::default()));
    assert_eq!(e.field, "robot");
    assert!(e.reason.contains("nothing limits the speed"), "{e}");
    // tensions too low to hold the platform at its start: the start itself is infeasible
    let s = timed_with(|v| v["robot"]["tension"]["max"] = json!(0.05));
    let e = field(time(&s, "swing", TimingOptions::default()));
    assert!(e.reason.contains("no timing follows the path") && e.reason.contains("violated at rest") && e.reason.contains("max tension"), "{e}");
    // a path that stands still (repeated points) over one of its pieces
    let s = timed_with(|v| {
        v["trajectories"] = json!([{"name": "pause", "pieces": [
            {"translation": {"line": [[0, 0, 2], [0.1, 0, 2]]}, "orientation": {"slerp": ["q1", "q1"]}},
            {"translation": {"line": [[0.1, 0, 2], [0.1, 0, 2]]}, "orientation": {"slerp": ["q1", "q1"]}}]}]);
    });
    let e = field(time(&s, "pause", TimingOptions::default()));
    assert!(e.reason.contains("stands still") && e.reason.contains("repeated points"), "{e}");
}
