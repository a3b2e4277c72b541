//! Long slerps (issue 12, item 2): slerp angles θ (cos θ = Qs·Qe) up to π − 10⁻³, the long way
//! round included, are cut into pieces of at most π/2 (`Motion::trajectory`) and must certify like
//! short ones: every report agrees with dense sampling of the independent reference
//! (tests/support), and no uncertain section is wider than [`UNCERTAIN_MAX`] in t.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

mod support;

use support::{env_usize, on_two_threads};
use support::gen::*;
use support::harness::*;
use support::reference::*;

/// Widest uncertain section allowed (docs/verification.md, "Long slerps").
const UNCERTAIN_MAX: f64 = 1e-7;

#[cfg(not(target_arch = "wasm32"))]
const SCENARIOS: usize = 60;
#[cfg(target_arch = "wasm32")]
const SCENARIOS: usize = 8;
#[cfg(not(target_arch = "wasm32"))]
const SAMPLES: usize = 5_000;
#[cfg(target_arch = "wasm32")]
const SAMPLES: usize = 2_000;

/// A random scenario whose trajectories rotate by slerp angles spread over (0, π − 10⁻³], a fifth
/// of them within 0.05 of that limit.
fn long_slerp_scenario(rng: &mut Rng, i: usize) -> RefScenario {
    let mut sc = random_scenario(rng, &format!("slerp{i:03}"), 2);
    for t in &mut sc.trajectories {
        let limit = std::f64::consts::PI - 1e-3;
        let theta = if rng.chance(0.2) { rng.range(limit - 0.05, limit) } else { rng.range(0.05, limit) };
        // a rotation by 2θ about a random axis: Qs·Qe = cos θ (negative past π/2: the long way)
        t.qe = quat_normalize(quat_mul(t.qs, quat_axis_angle(rng.unit_vector(), 2.0 * theta)));
        assert!((slerp_angle(t.qs, t.qe) - theta).abs() < 1e-6);
    }
    sc
}

#[test]
fn long_slerps_certify_and_agree_with_dense_sampling() {
    let n = env_usize("CABLENAV_SLERP_SCENARIOS", SCENARIOS);
    let mut rng = Rng::new(0x51E2F);
    let scenarios: Vec<RefScenario> = (0..n).map(|i| long_slerp_scenario(&mut rng, i)).collect();
    let per = |i: usize| {
        let sc = &scenarios[i];
        let stats = run_scenario(sc, SAMPLES, 31 + i as u64, None);
        let s = cablenav::Scenario::from_json(&sc.to_json()).expect("scenario");
        let widest = s
            .trajectories
            .iter()
            .filter_map(|t| cablenav::verify::verify_trajectory(&s, t).ok())
            .flat_map(|r| r.uncertain.into_iter().map(|iv| iv[1] - iv[0]))
            .fold(0.0f64, f64::max);
        (stats, widest)
    };
    let results = on_two_threads(n, &per);
    let mut total = Stats::default();
    let mut widest = 0.0f64;
    for (s, w) in results {
        total.merge(s);
        widest = widest.max(w);
    }
    println!("long slerps: {}; widest uncertain section {widest:.2e}", total.summary());
    for f in total.failures.iter().take(20) {
        println!("  {f}");
    }
    assert!(total.failure_counts.is_empty(), "{:?}", total.failure_counts);
    assert!(total.trajectories >= 2 * n);
    assert!(widest <= UNCERTAIN_MAX, "an uncertain section {widest:e} wide");
}
