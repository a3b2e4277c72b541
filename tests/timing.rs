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

/// `Sweep::part` restricts what the conditions prepared along a whole motion (the tension
/// columns apart from the time law, the winch factors) to a cell run by its own law: on random
/// cells and laws of the timed presets (a spatial platform turning along slerps, a point mass
/// along cubic pieces), every speed-dependent condition must find what it finds on the cell's
/// sweep expanded afresh — no sample certainly violated by one and certainly not by the other.
#[test]
fn a_sweep_part_decides_as_a_fresh_expansion() {
    use cablenav::conditions::{for_scenario, Kind, Sweep, TimeLaw};
    use cablenav::model::Motion;
    use cablenav::poly::{Bern, Partition, Truth};
    let at = |p: &Partition, x: f64| p.intervals().into_iter().find(|&(a, b, _)| a <= x && x <= b).map(|(_, _, t)| t);
    let mut seed = 7u64;
    let mut rand = move || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut violated, mut held) = (0, 0);
    for text in [TIMED, include_str!("../static/scenarios/laval-cspr3dof.json")] {
        let s = Scenario::from_json(text).unwrap();
        let conditions: Vec<_> = for_scenario(&s).into_iter().filter(|c| matches!(c.kind(), Kind::Tension | Kind::Winch)).collect();
        for traj in &s.trajectories {
            for motion in Motion::trajectory(traj).iter().take(4) {
                let mut whole = Sweep::new(&s.robot, motion, 1e-9);
                whole.duration = Some(1.0);
                for c in &conditions {
                    c.prepare(&mut whole);
                }
                for _ in 0..6 {
                    let a = 0.9 * rand();
                    let b = a + (1.0 - a) * (0.02 + 0.5 * rand());
                    let scale = 10f64.powf(7.0 * rand() - 1.0) * (b - a).powi(2);
                    let law = TimeLaw::from_square(Bern::from_bernstein(vec![scale * rand(), scale * rand()]));
                    let mut part = whole.part((a, b), Some(law.clone()));
                    let mut fresh = Sweep::new(&s.robot, &motion.part(a, b), 1e-9);
                    (fresh.duration, fresh.law) = (Some(1.0), Some(law));
                    for c in &conditions {
                        let (p, f) = (c.violation(&mut part), c.violation(&mut fresh));
                        for k in 0..=200 {
                            let x = k as f64 / 200.0;
                            match (at(&p, x), at(&f, x)) {
                                (Some(Truth::True), Some(Truth::False)) | (Some(Truth::False), Some(Truth::True)) => {
                                    panic!("{} on {} [{a}, {b}] at {x}: the part and the fresh sweep disagree", c.label(), traj.name)
                                }
                                (Some(Truth::True), _) => violated += 1,
                                (Some(Truth::False), _) => held += 1,
                                _ => {}
                            }
                        }
                    }
                }
            }
        }
    }
    // the laws range over seven decades: both answers occur
    assert!(violated > 1000 && held > 1000, "violated {violated}, held {held}");
}
