//! Property tests: cablenav's exact trajectory verifier against dense point-wise sampling of an
//! independent reference model (tests/support/reference.rs).
//!
//! For every trajectory the verifier's report is compared with ~10^5 samples of t: a sample
//! contradicts the report when the reference's verdict differs from the reported interval it lies
//! in, it is farther than 1e-9 from every reported boundary, outside every uncertain interval, and
//! the reference's margin is not within 1e-9·scale of zero. Every reported boundary must separate
//! reference-feasible from reference-infeasible parameters 1e-6 to either side (unless another
//! boundary or an uncertain interval is that close), in the reported direction, and name a
//! condition that is at its limit there.
//!
//! Environment overrides (native only): CABLENAV_PROPERTY_SCENARIOS, CABLENAV_PROPERTY_SAMPLES.
//! Failing scenarios are written to target/property-failures/ as JSON.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

mod support;

use support::env_usize;

use support::gen::*;
use support::harness::*;
use support::reference::*;

/// Random scenarios, each with `TRAJ_PER_SCENARIO` trajectories.
#[cfg(not(target_arch = "wasm32"))]
const SCENARIOS: usize = 260;
#[cfg(target_arch = "wasm32")]
const SCENARIOS: usize = 10;
const TRAJ_PER_SCENARIO: usize = 2;
/// Samples of t per trajectory.
#[cfg(not(target_arch = "wasm32"))]
const SAMPLES: usize = 100_000;
#[cfg(target_arch = "wasm32")]
const SAMPLES: usize = 10_000;
/// Samples per trajectory for the targeted cases.
#[cfg(not(target_arch = "wasm32"))]
const TARGETED_SAMPLES: usize = 100_000;
#[cfg(target_arch = "wasm32")]
const TARGETED_SAMPLES: usize = 10_000;


fn dump_dir() -> Option<&'static str> {
    if cfg!(target_arch = "wasm32") {
        None
    } else {
        Some(concat!(env!("CARGO_MANIFEST_DIR"), "/target/property-failures"))
    }
}

/// Runs the harness over all scenarios (two worker threads natively), merging in input order.
fn run_all(scenarios: &[RefScenario], samples: usize, seed: u64) -> Stats {
    let per = |i: usize, sc: &RefScenario| run_scenario(sc, samples, seed.wrapping_add(1000 * i as u64), dump_dir());
    let mut total = Stats::default();
    for (_, s) in run_indexed(scenarios, &per) {
        total.merge(s);
    }
    total
}

#[cfg(not(target_arch = "wasm32"))]
fn run_indexed(scenarios: &[RefScenario], per: &(dyn Fn(usize, &RefScenario) -> Stats + Sync)) -> Vec<(usize, Stats)> {
    let workers = 2;
    let mut results: Vec<(usize, Stats)> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..workers)
            .map(|w| {
                s.spawn(move || {
                    (0..scenarios.len())
                        .filter(|i| i % workers == w)
                        .map(|i| (i, per(i, &scenarios[i])))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().expect("worker panicked")).collect()
    });
    results.sort_by_key(|r| r.0);
    results
}

#[cfg(target_arch = "wasm32")]
fn run_indexed(scenarios: &[RefScenario], per: &dyn Fn(usize, &RefScenario) -> Stats) -> Vec<(usize, Stats)> {
    scenarios.iter().enumerate().map(|(i, sc)| (i, per(i, sc))).collect()
}

fn assert_clean(what: &str, stats: &Stats) {
    println!("{what}: {}", stats.summary());
    for f in stats.failures.iter().take(40) {
        println!("  {f}");
    }
    assert!(
        stats.failure_counts.is_empty(),
        "{what}: {:?} failures (scenarios written to target/property-failures/); first: {}",
        stats.failure_counts,
        stats.failures.first().map(|f| f.to_string()).unwrap_or_default()
    );
}

#[test]
fn random_trajectories_agree_with_dense_sampling() {
    let n = env_usize("CABLENAV_PROPERTY_SCENARIOS", SCENARIOS);
    let samples = env_usize("CABLENAV_PROPERTY_SAMPLES", SAMPLES);
    let mut rng = Rng::new(0xCAB1E);
    let scenarios: Vec<RefScenario> =
        (0..n).map(|i| random_scenario(&mut rng, &format!("random{i:03}"), TRAJ_PER_SCENARIO)).collect();
    let started = now();
    let stats = run_all(&scenarios, samples, 17);
    println!("random trajectories: {:.1}s wall", elapsed(started));
    assert!(stats.trajectories >= n * TRAJ_PER_SCENARIO);
    assert!(stats.boundaries > 0, "the random scenarios should produce boundaries");
    assert_clean("random trajectories", &stats);
}

/// Slerps whose quaternions have a negative dot product (the long way round, kept as given).
#[test]
fn long_way_slerp_agrees_with_dense_sampling() {
    let mut rng = Rng::new(0x10_9E);
    let scenarios: Vec<RefScenario> = (0..env_usize("CABLENAV_PROPERTY_SCENARIOS", 10).min(10))
        .map(|i| {
            let mut sc = random_scenario(&mut rng, &format!("longway{i:02}"), 2);
            for t in &mut sc.trajectories {
                let rot = quat_axis_angle(rng.unit_vector(), rng.range(10f64.to_radians(), 120f64.to_radians()));
                let qe = quat_normalize(quat_mul(t.qs, rot));
                t.qe = [-qe[0], -qe[1], -qe[2], -qe[3]];
                assert!(quat_dot(t.qs, t.qe) < 0.0);
            }
            sc
        })
        .collect();
    let stats = run_all(&scenarios, TARGETED_SAMPLES, 23);
    assert_clean("long-way slerp", &stats);
}

/// Boxes and meshes with zero obstacle clearance: only crossings of the surface count.
#[test]
fn zero_obstacle_clearance_meshes() {
    let mut rng = Rng::new(0xB0C5);
    let scenarios: Vec<RefScenario> = (0..env_usize("CABLENAV_PROPERTY_SCENARIOS", 10).min(10))
        .map(|i| {
            let mut sc = random_scenario(&mut rng, &format!("zeroclear{i:02}"), 2);
            sc.cable_obstacle = 0.0;
            sc.obstacles = (0..rng.int(1, 3))
                .map(|k| {
                    let shape = random_shape(&mut rng, [1, 2, 0, 3, 4, 5][k % 6]);
                    RefObstacle { name: obstacle_name(&shape, k), shape }
                })
                .collect();
            sc
        })
        .collect();
    let stats = run_all(&scenarios, TARGETED_SAMPLES, 29);
    assert_clean("zero obstacle clearance", &stats);
}

/// (t*, D*, the smallest value farther than 0.05 from t*) of a function on [0, 1]: dense
/// sampling, then golden-section refinement around the best sample.
fn global_min(f: &dyn Fn(f64) -> f64, n: usize) -> (f64, f64, f64) {
    let vals: Vec<(f64, f64)> = (0..=n).map(|i| i as f64 / n as f64).map(|t| (t, f(t))).collect();
    let (bi, _) = vals.iter().enumerate().min_by(|a, b| a.1 .1.partial_cmp(&b.1 .1).unwrap()).unwrap();
    let (a, b) = (vals[bi.saturating_sub(1)].0, vals[(bi + 1).min(n)].0);
    // golden section keeping the argument
    let r = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (a, b);
    for _ in 0..200 {
        let c = b - r * (b - a);
        let d = a + r * (b - a);
        if f(c) < f(d) {
            b = d;
        } else {
            a = c;
        }
        if b - a < 1e-14 {
            break;
        }
    }
    let ts = 0.5 * (a + b);
    let ds = f(ts).min(vals[bi].1);
    let ts = if f(ts) <= vals[bi].1 { ts } else { vals[bi].0 };
    let second = vals.iter().filter(|(t, _)| (t - ts).abs() > 0.05).map(|v| v.1).fold(f64::INFINITY, f64::min);
    (ts, ds, second)
}

/// Scenario in which one kind of distance has a single, isolated, interior minimum D* along the
/// trajectory: found by a deterministic search. `dist` gives that distance from the checks.
fn find_isolated_minimum(
    seed: u64,
    make: &dyn Fn(&mut Rng) -> RefScenario,
    dist: &dyn Fn(&[Check]) -> f64,
) -> (RefScenario, f64, f64) {
    let mut rng = Rng::new(seed);
    for _ in 0..2000 {
        let sc = make(&mut rng);
        let ev = sc.evaluator();
        let d = |t: f64| dist(&ev.checks(0, t));
        let (ts, ds, second) = global_min(&d, 2000);
        if (0.1..=0.9).contains(&ts) && ds > 0.03 && ds < 0.4 && second > ds + 2e-3 {
            return (sc, ts, ds);
        }
    }
    panic!("no isolated minimum found");
}

/// Runs a near-touch pair of scenarios: clearance = D* − 1e-6 (never violated: all feasible) and
/// D* + 1e-6 (a short violation around t*).
fn near_touch(what: &str, sc: &RefScenario, ts: f64, set: &dyn Fn(&mut RefScenario, f64), ds: f64) {
    for (sign, label) in [(-1.0, "clear"), (1.0, "touching")] {
        let mut s = sc.clone();
        s.name = format!("{}-{label}", sc.name);
        set(&mut s, ds + sign * 1e-6);
        let ev = s.evaluator();
        // the reference agrees with the construction
        assert_eq!(ev.feasible(0, ts), sign < 0.0, "{what} {label}: reference at t* = {ts}");
        let stats = run_scenario(&s, TARGETED_SAMPLES, 31, dump_dir());
        assert_clean(&format!("{what} ({label}, t* = {ts:.9}, D* = {ds:.12})"), &stats);
        // explicit: the report must not be infeasible anywhere / must be infeasible at t*
        let parsed = cablenav::Scenario::from_json(&s.to_json()).expect("parse");
        let rep = cablenav::verify::verify_trajectory(&parsed, &parsed.trajectories[0]).expect("verify");
        let unc: f64 = rep.uncertain.iter().map(|iv| iv[1] - iv[0]).sum();
        println!(
            "{what} {label}: {} feasible, {} infeasible intervals, {} boundaries, uncertain measure {unc:.3e}",
            rep.feasible.len(),
            rep.infeasible.len(),
            rep.boundaries.len()
        );
        println!(
            "  feasible {:?}\n  infeasible {:?}\n  uncertain {:?}\n  boundaries {:?}",
            rep.feasible, rep.infeasible, rep.uncertain, rep.boundaries
        );
        let in_unc = rep.uncertain.iter().any(|iv| iv[0] <= ts && ts <= iv[1]);
        if sign < 0.0 {
            assert!(rep.infeasible.is_empty(), "{what} {label}: reported infeasible {:?}", rep.infeasible);
        } else {
            assert!(
                in_unc || rep.infeasible.iter().any(|iv| iv[0] <= ts && ts <= iv[1]),
                "{what} {label}: t* = {ts} not reported infeasible: {:?}",
                rep.infeasible
            );
        }
    }
}

fn plain_scenario(rng: &mut Rng, name: &str) -> RefScenario {
    let mut sc = random_scenario(rng, name, 1);
    sc.length = None;
    sc.obstacles.clear();
    sc.cable_obstacle = 0.0;
    sc
}

/// Two cables that come within clearance ± 1e-6 of each other at one instant.
#[test]
fn nearly_touching_cables() {
    let make = |rng: &mut Rng| plain_scenario(rng, "neartouch-cables");
    let dist = |c: &[Check]| c.iter().filter(|c| c.cables.1.is_some()).map(|c| c.margin).fold(f64::INFINITY, f64::min);
    // margins are distances when the clearance is 0
    let mk = |rng: &mut Rng| {
        let mut s = make(rng);
        s.cable_cable = 0.0;
        s
    };
    let (sc, ts, ds) = find_isolated_minimum(0x7EA5, &mk, &dist);
    near_touch("cable-cable near touch", &sc, ts, &|s, c| s.cable_cable = c, ds);
}

/// A cable that comes within clearance ± 1e-6 of an obstacle at one instant (sphere, box, mesh,
/// cylinder), the cable–cable clearance being 0 so nothing else matters.
#[test]
fn nearly_touching_obstacles() {
    for (kind, seed) in [(0usize, 0x51u64), (1, 0xB0), (2, 0x3E), (4, 0xC1)] {
        let mk = move |rng: &mut Rng| {
            let mut s = plain_scenario(rng, &format!("neartouch-{kind}"));
            s.cable_cable = 0.0;
            s.cable_obstacle = 0.0;
            let shape = random_shape(rng, kind);
            s.obstacles = vec![RefObstacle { name: shape.kind().to_string(), shape }];
            s
        };
        let dist =
            |c: &[Check]| c.iter().filter(|c| c.obstacle.is_some()).map(|c| c.margin).fold(f64::INFINITY, f64::min);
        let (sc, ts, ds) = find_isolated_minimum(seed, &mk, &dist);
        let what = format!("{} near touch", sc.obstacles[0].shape.kind());
        near_touch(&what, &sc, ts, &|s, c| s.cable_obstacle = c, ds);
    }
}

/// A robot whose cables 1 and 2 pass through each other during the motion.
fn crossing_robot(cable_cable: f64) -> RefScenario {
    let cables = vec![
        (v3(-2.0, 0.0, 2.0), v3(0.4, 0.0, 0.0)),
        (v3(0.0, -2.0, 2.0), v3(0.0, 0.4, 0.0)),
        (v3(2.0, 2.0, -2.0), v3(0.2, 0.2, -0.2)),
        (v3(-2.0, 2.0, -2.0), v3(-0.2, 0.2, -0.2)),
        (v3(-2.0, -2.0, -2.0), v3(-0.2, -0.2, -0.2)),
        (v3(2.0, -2.0, -2.0), v3(0.2, -0.2, -0.2)),
    ];
    let qe = quat_axis_angle(v3(0.0, 0.0, 1.0), 30f64.to_radians());
    RefScenario {
        name: format!("crossing-{cable_cable}"),
        cables,
        length: None,
        cable_cable,
        cable_obstacle: 0.1,
        obstacles: vec![],
        trajectories: vec![
            RefTrajectory {
                name: "through".into(),
                translation: RefTranslation::Line(v3(-0.66, 0.44, -0.6), v3(0.3, -0.2, 0.2)),
                qs: quat_axis_angle(v3(0.0, 0.0, 1.0), -18f64.to_radians()),
                qe,
            },
            RefTrajectory {
                name: "wiggle".into(),
                translation: RefTranslation::Polynomial([
                    vec![-0.2, 0.5, 0.3, -0.4],
                    vec![0.1, -0.6, 0.2, 0.1],
                    vec![0.0, 0.3, -0.2],
                ]),
                qs: quat_axis_angle(v3(0.0, 0.0, 1.0), -20f64.to_radians()),
                qe: quat_axis_angle(v3(0.3, 0.0, 0.95).normalized(), 25f64.to_radians()),
            },
        ],
    }
}

#[test]
fn crossing_cables() {
    for cc in [0.0, 1e-3, 0.05, 0.2] {
        let sc = crossing_robot(cc);
        let ev = sc.evaluator();
        // the construction really crosses: cables 1 and 2 reach distance ~0 on the first trajectory
        let d12 = |t: f64| {
            let s = ev.segments(0, t);
            segment_segment_dist(s[0].0, s[0].1, s[1].0, s[1].1)
        };
        let (tc, dc, _) = global_min(&d12, 4000);
        assert!(dc < 1e-9, "cables 1 and 2 should cross (min distance {dc} at {tc})");
        let stats = run_scenario(&sc, TARGETED_SAMPLES, 37, dump_dir());
        assert_clean(&format!("crossing cables (cc = {cc}, crossing at t = {tc:.9})"), &stats);
        let parsed = cablenav::Scenario::from_json(&sc.to_json()).expect("parse");
        let rep = cablenav::verify::verify_trajectory(&parsed, &parsed.trajectories[0]).expect("verify");
        if cc > 0.0 {
            assert!(
                rep.infeasible.iter().chain(&rep.uncertain).any(|iv| iv[0] <= tc && tc <= iv[1]),
                "crossing at {tc} not reported infeasible (cc = {cc}): {:?}",
                rep.infeasible
            );
        }
    }
}

/// Cables sharing a base or platform anchor are not checked against each other.
#[test]
fn shared_anchors_are_not_checked() {
    let mut sc = crossing_robot(0.3);
    sc.name = "shared-anchors".into();
    sc.cables[1].0 = sc.cables[0].0; // cables 1, 2 share a base anchor
    sc.cables[3].1 = sc.cables[2].1; // cables 3, 4 share a platform anchor
    let ev = sc.evaluator();
    assert!(!ev.pairs.contains(&(0, 1)) && !ev.pairs.contains(&(2, 3)));
    let stats = run_scenario(&sc, TARGETED_SAMPLES, 41, dump_dir());
    assert_clean("shared anchors", &stats);
}

/// Every reported interval end lies in [0, 1] (t and τ), also where the τ ↔ t round trip of the
/// slerp parameter map could round past 1. Minimal case found by the random test: any motion
/// with this slerp (θ ≈ 0.81) — here all infeasible (maximum length 0.1) or all feasible.
#[test]
fn interval_ends_stay_within_the_unit_interval() {
    let cables: Vec<(V3, V3)> = (0..6)
        .map(|i| {
            let s = v3(
                if i & 1 == 0 { -1.0 } else { 1.0 },
                if i & 2 == 0 { -1.0 } else { 1.0 },
                if i & 4 == 0 { -1.0 } else { 1.0 },
            );
            (s * 2.0, s * 0.3)
        })
        .collect();
    for max_length in [0.1, 100.0] {
        let sc = RefScenario {
            name: format!("unit-interval-{max_length}"),
            cables: cables.clone(),
            length: Some((0.0, max_length)),
            cable_cable: 0.01,
            cable_obstacle: 0.01,
            obstacles: vec![],
            trajectories: vec![RefTrajectory {
                name: "t".into(),
                translation: RefTranslation::Line(v3(0.0, 0.0, 0.0), v3(0.1, 0.0, 0.0)),
                qs: [0.9696514290003864, -0.06961614769955624, 0.14959105280572485, 0.1804223243876908],
                qe: [0.8832177054747509, -0.4475942238549857, 0.08202503833361145, -0.11339218929864048],
            }],
        };
        let parsed = cablenav::Scenario::from_json(&sc.to_json()).expect("parse");
        let rep = cablenav::verify::verify_trajectory(&parsed, &parsed.trajectories[0]).expect("verify");
        for (what, list) in [
            ("feasible", &rep.feasible),
            ("infeasible", &rep.infeasible),
            ("uncertain", &rep.uncertain),
            ("feasible_tau", &rep.feasible_tau),
            ("infeasible_tau", &rep.infeasible_tau),
        ] {
            for iv in list.iter() {
                assert!(
                    0.0 <= iv[0] && iv[0] <= iv[1] && iv[1] <= 1.0,
                    "max length {max_length}: {what} interval {iv:?} is not within [0, 1]\n{}",
                    sc.to_json()
                );
            }
        }
    }
}
