//! The continuation planner (src/plan): the cable manifold's equations against finite differences
//! and against the per-pose wrench test, the generic atlas on manifolds with known answers
//! (circle, sphere, torus, two concentric circles), and the Robocrane queries of Bohigas et al.
//! with every path re-verified and the straight segments shown to leave the feasible set.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

mod support;

use cablenav::model::{Coord, Pose};
use cablenav::plan::atlas::atlas::AtlasParams;
use cablenav::plan::atlas::manifold::{BoundKind, CableManifold, Manifold};
use cablenav::plan::atlas::search::{Continuation, Ended};
use cablenav::plan::atlas::{plan, verify_path, AtlasPlanner, PlanParams};
use cablenav::plan::PlanStatus;
use cablenav::shape::{Obstacle, Shape};
use cablenav::query::wrench::tension_ranges;
use cablenav::scenario::Query;
use cablenav::verify::wrench_at;
use cablenav::Scenario;
use nalgebra::DMatrix;
use std::f64::consts::PI;
use support::reference::Rng;

const ROBOCRANE: &str = include_str!("../static/scenarios/robocrane.json");

fn robocrane() -> Scenario {
    Scenario::from_json(ROBOCRANE).expect("robocrane preset parses")
}

// ---------------------------------------------------------------------------------------------
// The cable manifold's equations

/// Random feasible coordinates near a reference pose (rejection sampling on the wrench test).
fn feasible_coords(s: &Scenario, rng: &mut Rng, count: usize) -> Vec<[f64; 6]> {
    let mut out = Vec::new();
    while out.len() < count {
        let q = [rng.range(-0.3, 0.3), rng.range(-0.3, 0.3), rng.range(1.5, 2.5), rng.range(-PI, PI), rng.range(-1.2, 1.2), rng.range(-1.0, 1.0)];
        if wrench_at(s, &Pose::from_coords(q)).is_some_and(|w| w.feasible) {
            out.push(q);
        }
    }
    out
}

/// The closed-form Jacobian agrees with central differences of F, on and off the manifold, for
/// the full 6-D space and for a slice.
#[test]
fn jacobian_matches_finite_differences() {
    let s = robocrane();
    let mut rng = Rng::new(11);
    for fixed in [[None; 6], [Some(0.0), Some(0.0), Some(2.0), None, None, Some(35f64.to_radians())]] {
        let m = CableManifold::new(&s, fixed, true, 0.1, 1e-3, 1.0).unwrap();
        let (n, eqs) = (m.ambient(), m.equations());
        assert_eq!(eqs, 18, "6 cables × (tension low, tension high, length)");
        for mut q in feasible_coords(&s, &mut rng, 6) {
            for (c, v) in fixed.iter().enumerate() {
                if let Some(v) = v {
                    q[c] = *v;
                }
            }
            let Ok(mut x) = m.lift(&q) else { continue };
            // Off the manifold too: perturb the auxiliaries.
            for w in x[n - eqs..].iter_mut() {
                *w += rng.range(-0.05, 0.05);
            }
            let mut f = vec![0.0; eqs];
            let mut jac = DMatrix::zeros(eqs, n);
            assert!(m.eval(&x, &mut f, &mut jac));
            for col in 0..n {
                let h = 1e-6;
                let (mut xp, mut xm) = (x.clone(), x.clone());
                xp[col] += h;
                xm[col] -= h;
                let (mut fp, mut fm) = (vec![0.0; eqs], vec![0.0; eqs]);
                let mut scratch = DMatrix::zeros(eqs, n);
                assert!(m.eval(&xp, &mut fp, &mut scratch) && m.eval(&xm, &mut fm, &mut scratch));
                for row in 0..eqs {
                    let fd = (fp[row] - fm[row]) / (2.0 * h);
                    let tol = 1e-5 * (1.0 + fd.abs());
                    assert!((jac[(row, col)] - fd).abs() <= tol, "dF{row}/dx{col}: closed form {} vs finite differences {fd}", jac[(row, col)]);
                }
            }
        }
    }
}

/// The manifold's margins are the per-pose wrench test's: (f0 − v − f_min)/span and
/// (f_max − f0 − v)/span from `tension_ranges`, and the lengths' product form.
#[test]
fn margins_agree_with_the_per_pose_wrench_test() {
    let s = robocrane();
    let m = CableManifold::new(&s, [None; 6], true, 0.1, 1e-3, 1.0).unwrap();
    let mut rng = Rng::new(5);
    for q in feasible_coords(&s, &mut rng, 20) {
        let pose = Pose::from_coords(q);
        let ranges = tension_ranges(&s.robot, &pose, s.wrench.as_ref().unwrap()).unwrap();
        let mu = m.margins(&q, false).unwrap().values;
        for (b, v) in m.barriers().iter().zip(&mu) {
            let (cable, r) = (&s.robot.cables[b.cable], ranges[b.cable]);
            let span = cable.tension.max - cable.tension.min;
            let len = (pose.transform(&cable.platform) - cable.base).norm();
            let expect = match b.kind {
                BoundKind::TensionLow => (r.nominal - r.spread - cable.tension.min) / span,
                BoundKind::TensionHigh => (cable.tension.max - r.nominal - r.spread) / span,
                BoundKind::Length => (len - cable.length.min) * (cable.length.max - len) / ((cable.length.max - cable.length.min).powi(2) / 4.0),
            };
            assert!((v - expect).abs() < 1e-9, "{}: {v} vs {expect}", b.label());
        }
        // A lifted point is on the manifold: F = 0 there.
        let x = m.lift(&q).unwrap();
        let mut f = vec![0.0; 18];
        let mut jac = DMatrix::zeros(18, 24);
        assert!(m.eval(&x, &mut f, &mut jac));
        assert!(f.iter().all(|v| v.abs() < 1e-12));
    }
}

// ---------------------------------------------------------------------------------------------
// The generic continuation on manifolds with known answers

/// A manifold given by closures: F: ℝⁿ → ℝ (one equation) and its gradient.
struct Implicit {
    n: usize,
    f: fn(&[f64]) -> f64,
    grad: fn(&[f64]) -> Vec<f64>,
}

impl Manifold for Implicit {
    fn ambient(&self) -> usize {
        self.n
    }
    fn equations(&self) -> usize {
        1
    }
    fn eval(&self, x: &[f64], f: &mut [f64], jac: &mut DMatrix<f64>) -> bool {
        f[0] = (self.f)(x);
        for (j, g) in (self.grad)(x).into_iter().enumerate() {
            jac[(0, j)] = g;
        }
        true
    }
}

fn circle() -> Implicit {
    Implicit { n: 2, f: |x| x[0] * x[0] + x[1] * x[1] - 1.0, grad: |x| vec![2.0 * x[0], 2.0 * x[1]] }
}

fn sphere() -> Implicit {
    Implicit { n: 3, f: |x| x.iter().map(|v| v * v).sum::<f64>() - 1.0, grad: |x| x.iter().map(|v| 2.0 * v).collect() }
}

/// Torus with centre-line radius 1 and tube radius 0.5 around the z axis.
fn torus() -> Implicit {
    Implicit {
        n: 3,
        f: |x| {
            let rho = x[0].hypot(x[1]);
            (rho - 1.0).powi(2) + x[2] * x[2] - 0.25
        },
        grad: |x| {
            let rho = x[0].hypot(x[1]);
            let k = 2.0 * (rho - 1.0) / rho;
            vec![k * x[0], k * x[1], 2.0 * x[2]]
        },
    }
}

/// Two concentric circles of radii 1 and 1.3: a curve with two components 0.3 apart, closer than
/// two chart radii, so charts of one see centres of the other as candidates.
fn two_circles() -> Implicit {
    Implicit {
        n: 2,
        f: |x| {
            let r2 = x[0] * x[0] + x[1] * x[1];
            (r2 - 1.0) * (r2 - 1.69)
        },
        grad: |x| {
            let r2 = x[0] * x[0] + x[1] * x[1];
            let d = 2.0 * r2 - 2.69;
            vec![2.0 * x[0] * d, 2.0 * x[1] * d]
        },
    }
}

const PARAMS: AtlasParams = AtlasParams { radius: 0.3, min_radius: 0.3, epsilon: 0.3, delta: 0.05 };

fn run<M: Manifold>(m: M, start: &[f64], goals: Vec<Vec<f64>>, max_charts: usize) -> Continuation<M> {
    run_with(m, start, goals, max_charts, PARAMS)
}

/// [`run`] with other atlas parameters (A*, weight 1).
fn run_with<M: Manifold>(m: M, start: &[f64], goals: Vec<Vec<f64>>, max_charts: usize, params: AtlasParams) -> Continuation<M> {
    let mut c = Continuation::new(m, start, goals, params, max_charts, 1.0).unwrap();
    while c.step(100).ended.is_none() {}
    c
}

/// The ellipse x²/9 + 4y² = 1: curvature 12 at (±3, 0), 1/18 at (0, ±1/2).
fn ellipse() -> Implicit {
    Implicit { n: 2, f: |x| x[0] * x[0] / 9.0 + 4.0 * x[1] * x[1] - 1.0, grad: |x| vec![2.0 * x[0] / 9.0, 8.0 * x[1]] }
}

/// Adaptive chart radii (between 0.05 and 1): on the ellipse the charts are small near the sharp
/// ends and large along the flat sides (each radius is where the error along the step that made
/// the chart would reach ε/2; a chart reached from a flat side may be larger than the curvature at
/// its centre allows, and its own steps then shrink), and the atlas is still exhausted without
/// failures and covers the curve (every sample within some chart's ball), with fewer charts than
/// the smallest radius would need.
#[test]
fn adaptive_radii_follow_the_curvature() {
    let params = AtlasParams { radius: 1.0, min_radius: 0.05, epsilon: 0.3, delta: 0.05 };
    let on = |x: &[f64]| x[0] * x[0] / 9.0 + 4.0 * x[1] * x[1] - 1.0;
    let c = run_with(ellipse(), &[0.0, 0.5], vec![], 10_000, params);
    assert_eq!(c.ended(), Some(Ended::Exhausted));
    assert_eq!(c.atlas.failures, 0);
    let charts = &c.atlas.charts;
    let radius_where = |pick: &dyn Fn(&[f64]) -> bool| charts.iter().filter(|ch| pick(&ch.centre)).map(|ch| ch.radius).collect::<Vec<f64>>();
    let (ends, sides) = (radius_where(&|x| x[0].abs() > 2.5), radius_where(&|x| x[0].abs() < 1.5));
    let mean = |r: &[f64]| r.iter().sum::<f64>() / r.len() as f64;
    assert!(!ends.is_empty() && !sides.is_empty());
    assert!(mean(&ends) < 0.5 * mean(&sides), "radii near the ends {ends:?}, along the sides {sides:?}");
    // At the ends, κr²/2 ≤ ε/2 gives r ≤ sqrt(ε/κ) = 0.16: the smallest charts are there.
    let smallest = charts.iter().map(|ch| ch.radius).fold(f64::INFINITY, f64::min);
    assert!(ends.contains(&smallest) && smallest <= (0.3f64 / 12.0).sqrt(), "smallest radius {smallest}");
    for ch in charts {
        assert!(on(&ch.centre).abs() < 1e-9 && ch.radius >= params.min_radius && ch.radius <= params.radius);
    }
    for i in 0..1000 {
        let (s, co) = (i as f64 * 2.0 * PI / 1000.0).sin_cos();
        let p = [3.0 * co, 0.5 * s];
        let covered = charts.iter().any(|ch| (ch.centre[0] - p[0]).hypot(ch.centre[1] - p[1]) <= ch.radius);
        assert!(covered, "{p:?} is in no chart's ball");
    }
    // The perimeter is about 13.4: charts of radius 0.05 would need more than 13.4 / 0.1 = 134.
    assert!(charts.len() < 134 / 2, "{} charts", charts.len());
    // A goal on the far side is reached along the curve.
    let found = run_with(ellipse(), &[0.0, 0.5], vec![vec![0.0, -0.5]], 10_000, params);
    assert_eq!(found.ended(), Some(Ended::Found));
    assert!(found.path().iter().all(|p| on(p).abs() < 1e-9));
}

/// Every chart centre is on the manifold and every sample point of the manifold is within one
/// chart radius (plus the chart-to-manifold gap) of some centre: the atlas covers it.
fn assert_covers<M: Manifold>(c: &Continuation<M>, samples: &[Vec<f64>], on: impl Fn(&[f64]) -> f64) {
    for chart in &c.atlas.charts {
        assert!(on(&chart.centre).abs() < 1e-9, "centre {:?} off the manifold", chart.centre);
    }
    for p in samples {
        let nearest = c.atlas.charts.iter().map(|ch| ch.centre.iter().zip(p).map(|(a, b)| (a - b).powi(2)).sum::<f64>().sqrt()).fold(f64::INFINITY, f64::min);
        assert!(nearest <= 1.2 * PARAMS.radius, "{p:?} is {nearest} from the nearest chart centre");
    }
}

#[test]
fn circle_atlas_is_exhausted_and_covers_it() {
    let c = run(circle(), &[1.0, 0.0], vec![], 10_000);
    assert_eq!(c.ended(), Some(Ended::Exhausted));
    assert_eq!(c.atlas.failures, 0);
    let n = c.atlas.charts.len();
    // Charts are about r apart along a curve of length 2π.
    assert!((2.0 * PI / (2.0 * PARAMS.radius)) as usize <= n && n <= (2.0 * PI / (0.5 * PARAMS.radius)) as usize, "{n} charts");
    let samples: Vec<Vec<f64>> = (0..500).map(|i| (i as f64 * 2.0 * PI / 500.0).sin_cos()).map(|(s, c)| vec![c, s]).collect();
    assert_covers(&c, &samples, |x| x[0] * x[0] + x[1] * x[1] - 1.0);
}

#[test]
fn circle_path_follows_the_arc() {
    let c = run(circle(), &[1.0, 0.0], vec![vec![-1.0, 0.0]], 10_000);
    assert_eq!(c.ended(), Some(Ended::Found));
    let path = c.path();
    assert_eq!(path.first().unwrap(), &vec![1.0, 0.0]);
    assert_eq!(path.last().unwrap(), &vec![-1.0, 0.0]);
    let mut length = 0.0;
    for w in path.windows(2) {
        let d = (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
        assert!(d <= PARAMS.delta + 1e-12, "step {d}");
        length += d;
    }
    for p in path {
        assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-9);
    }
    // Half the circle: π, never the chord (2) nor a detour.
    assert!(length > 0.99 * PI && length < 1.1 * PI, "length {length}");
}

#[test]
fn sphere_atlas_is_exhausted_and_covers_it() {
    let c = run(sphere(), &[0.0, 0.0, 1.0], vec![], 10_000);
    assert_eq!(c.ended(), Some(Ended::Exhausted));
    assert_eq!(c.atlas.failures, 0);
    let n = c.atlas.charts.len() as f64;
    // Area 4π, each chart's polytope covers between the inscribed hexagon of a disc of radius r/2
    // … and the disc of radius r.
    assert!(n >= 4.0 * PI / (PI * PARAMS.radius.powi(2)) && n <= 4.0 * PI / (0.5 * PARAMS.radius.powi(2)), "{n} charts");
    let mut rng = Rng::new(3);
    let samples: Vec<Vec<f64>> = (0..500)
        .map(|_| {
            let (z, a) = (rng.range(-1.0, 1.0), rng.range(0.0, 2.0 * PI));
            let s = (1.0 - z * z).sqrt();
            vec![s * a.cos(), s * a.sin(), z]
        })
        .collect();
    assert_covers(&c, &samples, |x| x.iter().map(|v| v * v).sum::<f64>() - 1.0);
}

#[test]
fn torus_atlas_is_exhausted_covers_it_and_connects_opposite_points() {
    let on = |x: &[f64]| (x[0].hypot(x[1]) - 1.0).powi(2) + x[2] * x[2] - 0.25;
    let c = run(torus(), &[1.5, 0.0, 0.0], vec![], 20_000);
    assert_eq!(c.ended(), Some(Ended::Exhausted));
    assert_eq!(c.atlas.failures, 0);
    let mut rng = Rng::new(9);
    let samples: Vec<Vec<f64>> = (0..500)
        .map(|_| {
            let (u, v) = (rng.range(0.0, 2.0 * PI), rng.range(0.0, 2.0 * PI));
            let rho = 1.0 + 0.5 * v.cos();
            vec![rho * u.cos(), rho * u.sin(), 0.5 * v.sin()]
        })
        .collect();
    assert_covers(&c, &samples, on);
    // From the outer equator to the inner one on the far side.
    let found = run(torus(), &[1.5, 0.0, 0.0], vec![vec![-0.5, 0.0, 0.0]], 20_000);
    assert_eq!(found.ended(), Some(Ended::Found));
    assert!(found.path().iter().all(|p| on(p).abs() < 1e-9));
    assert!(found.path().windows(2).all(|w| w[0].iter().zip(&w[1]).map(|(a, b)| (a - b).powi(2)).sum::<f64>().sqrt() <= PARAMS.delta + 1e-12));
}

/// The start's circle is exhausted without a single chart on the other circle, 0.3 away: no path;
/// a goal on the start's own circle is found.
#[test]
fn two_component_curve_proves_no_path_between_components() {
    let none = run(two_circles(), &[1.0, 0.0], vec![vec![-1.3, 0.0]], 10_000);
    assert_eq!(none.ended(), Some(Ended::Exhausted));
    assert_eq!(none.atlas.failures, 0);
    assert!(none.atlas.charts.iter().all(|c| (c.centre[0].hypot(c.centre[1]) - 1.0).abs() < 1e-9), "a chart jumped to the other circle");
    let alone = run(circle(), &[1.0, 0.0], vec![], 10_000);
    assert_eq!(none.atlas.charts.len(), alone.atlas.charts.len(), "the same atlas as the circle alone");
    let found = run(two_circles(), &[1.3, 0.0], vec![vec![0.0, -1.3]], 10_000);
    assert_eq!(found.ended(), Some(Ended::Found));
    assert!(found.path().iter().all(|p| (p[0].hypot(p[1]) - 1.3).abs() < 1e-9));
}

/// A chart budget smaller than the atlas ends with `Budget`, never with a claim.
#[test]
fn budget_is_reported_as_budget() {
    let c = run(sphere(), &[0.0, 0.0, 1.0], vec![vec![0.0, 0.0, -1.0]], 10);
    assert_eq!(c.ended(), Some(Ended::Budget));
    assert_eq!(c.atlas.charts.len(), 10);
}

// ---------------------------------------------------------------------------------------------
// Robocrane (Bohigas et al. §5)

/// The paper's start and goal coordinates (x, y, z, φ, θ, σ) of each query.
fn paper_coords(query: &str) -> ([f64; 6], [f64; 6]) {
    let s = 7.0 * PI / 36.0;
    match query {
        "q1-q2" => ([0.0, 0.0, 2.0, -0.5, 0.9, s], [0.0, 0.0, 2.0, 2.0, 0.9, s]),
        "q3-q4" => ([0.0, 0.0, 2.0, 0.8, -2.4, s], [0.0, 0.0, 2.0, -2.4, 2.4, s]),
        _ => ([0.0, 0.0, 1.2, 0.8, -2.6, s], [0.0, 0.0, 2.0, -2.4, 2.4, s]),
    }
}

/// Checks a found path: exact ends, fixed coordinates kept to 1e-9, steps at most δ (position and
/// rotation angle), every pose wrench-feasible, and the re-verification clean.
fn assert_good_path(s: &Scenario, query: &str, params: &PlanParams) -> usize {
    let out = plan(s, query, *params).unwrap();
    assert_eq!(out.status, PlanStatus::Found, "{query}");
    let q = s.queries.iter().find(|q| q.name == query).unwrap();
    let (start, goal) = (*s.pose(&q.start).unwrap(), *s.pose(&q.goal).unwrap());
    assert_eq!(out.path.first(), Some(&start));
    assert_eq!(out.path.last(), Some(&goal));
    let start_coords = start.coords();
    for p in &out.path {
        let c = p.coords();
        for f in &q.fixed {
            let i = f.index();
            let d = if f.is_angle() { cablenav::model::pose::wrap_angle(c[i] - start_coords[i]) } else { c[i] - start_coords[i] };
            assert!(d.abs() <= 1e-9, "{query}: {} drifted by {d}", f.name());
        }
        let w = wrench_at(s, p).unwrap();
        assert!(w.feasible, "{query}: a path pose is wrench-infeasible ({})", w.active);
    }
    for w in out.path.windows(2) {
        let step = (w[1].position - w[0].position).norm().hypot(w[0].rotation.angle_to(&w[1].rotation));
        assert!(step <= params.delta + 1e-9, "{query}: step {step}");
    }
    let v = &out.verification;
    assert_eq!(v.edges, out.path.len() - 1);
    assert_eq!((v.infeasible_sections, v.uncertain_sections, v.wrench_infeasible_poses), (0, 0, 0), "{query}: {:?}", v.failed_edges);
    assert_eq!(v.wrench_poses, out.path.len());
    out.charts
}

/// The straight segment between the paper's start and goal coordinates leaves the feasible set
/// (per-pose checks at 1000 points), as the paper reports.
fn assert_straight_segment_leaves(s: &Scenario, query: &str) {
    let (a, b) = paper_coords(query);
    let infeasible = (0..=1000)
        .filter(|&k| {
            let t = k as f64 / 1000.0;
            let q: [f64; 6] = std::array::from_fn(|i| a[i] + t * (b[i] - a[i]));
            !wrench_at(s, &Pose::from_coords(q)).unwrap().feasible
        })
        .count();
    assert!(infeasible > 0, "{query}: the straight segment stays feasible");
    // The paper's coordinates are the preset's poses.
    let q = s.queries.iter().find(|q| q.name == query).unwrap();
    for (c, name) in [(a, &q.start), (b, &q.goal)] {
        let p = s.pose(name).unwrap();
        assert!(Pose::from_coords(c).rotation.angle_to(&p.rotation) < 1e-12 && (Pose::from_coords(c).position - p.position).norm() < 1e-12);
    }
}

#[test]
fn robocrane_slice_queries_find_verified_paths() {
    let s = robocrane();
    let params = PlanParams::default();
    for query in ["q1-q2", "q3-q4", "q5-q6"] {
        assert_straight_segment_leaves(&s, query);
        assert_good_path(&s, query, &params);
    }
}

/// q3 → q4 as paper 1 posed it: from (φ, θ) = (0.8, −2.4) to (−2.4, 2.4) with the angles as
/// plain coordinates (`identify_angles: false`). The rotations are only 0.11 rad apart but the
/// path in coordinates must go the long way round (the straight segment leaves the feasible set):
/// it is found, verified clean, and is more than ten times longer than the direct rotation.
#[test]
fn robocrane_q3_q4_in_the_paper_coordinates() {
    let s = robocrane();
    let (a, b) = paper_coords("q3-q4");
    let params = PlanParams { identify_angles: false, ..PlanParams::default() };
    let mut p = AtlasPlanner::between_coords(&s, a, b, &[Coord::X, Coord::Y, Coord::Z, Coord::Sigma], params).unwrap();
    while p.step(500).done.is_none() {}
    let out = p.outcome().unwrap();
    assert_eq!(out.status, PlanStatus::Found);
    assert_eq!(out.path.first(), Some(&Pose::from_coords(a)));
    assert_eq!(out.path.last(), Some(&Pose::from_coords(b)));
    let v = &out.verification;
    assert_eq!((v.infeasible_sections, v.uncertain_sections, v.wrench_infeasible_poses), (0, 0, 0));
    let length: f64 = out.path.windows(2).map(|w| w[0].rotation.angle_to(&w[1].rotation)).sum();
    let direct = Pose::from_coords(a).rotation.angle_to(&Pose::from_coords(b).rotation);
    assert!(direct < 0.12 && length > 10.0 * direct, "direct {direct}, path {length}");
}

/// A pose in a component of the slice p = [0, 0, 2], σ = 35° other than q1's: the small region
/// around (φ, θ) = (2.66, 2.23) that `cablenav slice robocrane.json --pose q1 --axes phi,theta
/// --res 72` shows apart from the band holding q1 (the test takes the centre of one of its grid
/// cells). Planning from it to q1 exhausts its component's atlas: `no_path`.
#[test]
fn robocrane_other_component_is_no_path() {
    let mut s = robocrane();
    // Independent check on a grid: on the slice map's 4-neighbour components neither coordinate
    // copy of the island, (φ, θ) and (φ + π, −θ), shares a component with either copy of q1.
    let res = 72;
    let map = cablenav::verify::slice(&s, "q1", [Coord::Phi, Coord::Theta], res, [[-PI, PI], [-PI, PI]]).unwrap();
    let cell = |phi: f64, theta: f64| {
        let idx = |v: f64| (((cablenav::model::pose::wrap_angle(v) + PI) / (2.0 * PI) * res as f64).floor() as usize).min(res - 1);
        map.component[idx(theta) * res + idx(phi)]
    };
    let (phi, theta) = (map.center(0, 66), map.center(1, 61));
    let island = [cell(phi, theta), cell(phi + PI, -theta)];
    let q1 = [cell(-0.5, 0.9), cell(-0.5 + PI, -0.9)];
    assert!(island.iter().all(Option::is_some) && q1.iter().all(Option::is_some), "island {island:?}, q1 {q1:?}");
    assert!(island.iter().all(|c| !q1.contains(c)), "grid components: island {island:?}, q1 {q1:?}");

    let other = Pose::from_coords([0.0, 0.0, 2.0, phi, theta, 7.0 * PI / 36.0]);
    assert!(wrench_at(&s, &other).unwrap().feasible);
    s.poses.push(("island".to_string(), other));
    s.queries.push(Query { name: "island-q1".to_string(), start: "island".to_string(), goal: "q1".to_string(), fixed: vec![Coord::X, Coord::Y, Coord::Z, Coord::Sigma], region: vec![] });
    let out = plan(&s, "island-q1", PlanParams::default()).unwrap();
    assert_eq!(out.status, PlanStatus::NoPath);
    assert_eq!((out.atlas.expansion_failures, out.atlas.broken_edges), (0, 0), "a certified no_path");
    assert!(out.path.is_empty());
    assert!(out.charts > 1);
}

/// The pose at the centre of the grid cell of the 72×72 (φ, θ) slice map through q1 that lies in
/// the small component around (2.66, 2.23), apart from q1's (`robocrane_other_component_is_no_path`
/// checks that it is), added to `s` as pose "island" with the query "island-q1".
fn with_island(s: &mut Scenario) {
    let map = cablenav::verify::slice(s, "q1", [Coord::Phi, Coord::Theta], 72, [[-PI, PI], [-PI, PI]]).unwrap();
    let island = Pose::from_coords([0.0, 0.0, 2.0, map.center(0, 66), map.center(1, 61), 7.0 * PI / 36.0]);
    s.poses.push(("island".to_string(), island));
    s.queries.push(Query { name: "island-q1".to_string(), start: "island".to_string(), goal: "q1".to_string(), fixed: vec![Coord::X, Coord::Y, Coord::Z, Coord::Sigma], region: vec![] });
}

/// Runs `p` to its outcome.
fn finish(p: &mut AtlasPlanner) -> cablenav::plan::atlas::PlanOutcome {
    while p.step(500).done.is_none() {}
    p.outcome().unwrap()
}

/// One atlas kept across the queries of Robocrane's slice p = [0, 0, 2], σ = 35°: each later query
/// gets the verdict a fresh atlas gives (found, verified clean, between its own poses; no_path from
/// the island), says how many charts it found made, and the query repeated at once makes no new
/// chart, runs the exact verifier only on the path's two end edges (which meet the exact poses)
/// and does a fifth of the first run's manifold evaluations at most. A query on another slice is
/// declined (`false`), leaving the planner as it was.
#[test]
fn robocrane_atlas_is_kept_for_later_queries_on_its_slice() {
    let mut s = robocrane();
    with_island(&mut s);
    s.queries.push(Query { name: "q2-q1".to_string(), start: "q2".to_string(), goal: "q1".to_string(), fixed: vec![Coord::X, Coord::Y, Coord::Z, Coord::Sigma], region: vec![] });
    let params = PlanParams::default();
    let mut p = AtlasPlanner::new(&s, "q1-q2", params).unwrap();
    let first = finish(&mut p);
    assert_eq!((first.status, first.atlas.reused_charts), (PlanStatus::Found, 0));
    let first_evaluations = p.work().evaluations;
    for query in ["q1-q2", "q2-q1", "q3-q4", "island-q1"] {
        let before = (p.outcome().unwrap().charts, p.work().evaluations, p.work().trajectory_checks);
        assert!(p.requery(&s, query).unwrap(), "{query} is on the same slice");
        let out = finish(&mut p);
        let fresh = plan(&s, query, params).unwrap();
        assert_eq!(out.status, fresh.status, "{query}: kept atlas against a fresh one");
        assert_eq!(out.atlas.reused_charts, before.0, "{query}");
        let q = s.queries.iter().find(|q| q.name == query).unwrap();
        if out.status == PlanStatus::Found {
            assert_eq!(out.path.first(), Some(s.pose(&q.start).unwrap()), "{query}");
            assert_eq!(out.path.last(), Some(s.pose(&q.goal).unwrap()), "{query}");
            let v = &out.verification;
            assert_eq!((v.infeasible_sections, v.uncertain_sections, v.wrench_infeasible_poses), (0, 0, 0), "{query}: {:?}", v.failed_edges);
        }
        let work = p.work();
        if query == "q1-q2" {
            assert_eq!(out.charts, before.0, "the repeated query made new charts");
            // the path's inner edges are steps the motion validator checked for the first query
            assert_eq!(work.trajectory_checks - before.2, 2, "the repeated query verified more than its two end edges");
            assert_eq!(out.verification.edges_validated, out.verification.edges - 2);
            let evaluations = work.evaluations - before.1;
            assert!(5 * evaluations <= first_evaluations, "repeated: {evaluations} manifold evaluations, first run {first_evaluations}");
        }
    }
    let charts = p.outcome().unwrap().charts;
    assert!(!p.requery(&s, "q5-q6").unwrap(), "q5-q6 lies on another slice");
    assert_eq!(p.outcome().unwrap().charts, charts);
    assert!(p.requery(&s, "nope").is_err());
}

/// With the angles as plain coordinates, a scenario query is posed with its poses' angles as the
/// file writes them: q3-q4 from the preset is paper 1's query, the same as the raw coordinates.
#[test]
fn paper_mode_takes_the_written_angles() {
    let s = robocrane();
    let params = PlanParams { identify_angles: false, ..PlanParams::default() };
    assert_eq!(s.written_coords("q3").unwrap(), paper_coords("q3-q4").0);
    let by_name = plan(&s, "q3-q4", params).unwrap();
    let (a, b) = paper_coords("q3-q4");
    let mut raw = AtlasPlanner::between_coords(&s, a, b, &[Coord::X, Coord::Y, Coord::Z, Coord::Sigma], params).unwrap();
    let raw = finish(&mut raw);
    assert_eq!((by_name.status, by_name.charts), (raw.status, raw.charts));
    assert!(by_name.charts > 100, "the paper's hard query: {} charts", by_name.charts);
}

/// `s` with a ball of radius 0.05 put 0.03 beyond cable 1's platform anchor (along the cable) at
/// the pose `fraction` of the way along `path`.
fn with_ball(s: &Scenario, path: &[Pose], fraction: f64) -> Scenario {
    let pose = path[(path.len() as f64 * fraction) as usize];
    let cable = &s.robot.cables[0];
    let anchor = pose.transform(&cable.platform);
    let centre = anchor + (anchor - cable.base).normalize() * 0.03;
    let mut blocked = s.clone();
    blocked.obstacles.push(Obstacle { name: format!("ball {}", s.obstacles.len() + 1), shape: Shape::Sphere { center: centre, radius: 0.05 }, color: None });
    blocked
}

/// The components of q1 and q2 on the slice map (120 × 120 over (φ, θ) ∈ [−π, π]²) as the
/// planner sees the slice: both angles periodic (the map's left and right edges, and its top
/// and bottom, are one) and (φ, θ) the same rotation as (φ + π, −θ) — cell (i, j) the same as
/// (i + 60 mod 120, 119 − j). Components are merged across these identifications (union-find).
fn grid_components(s: &Scenario) -> [Option<usize>; 2] {
    let res = 120;
    let map = cablenav::verify::slice(s, "q1", [Coord::Phi, Coord::Theta], res, [[-PI, PI], [-PI, PI]]).unwrap();
    let mut parent: Vec<usize> = (0..map.components).collect();
    fn root(parent: &mut [usize], mut a: usize) -> usize {
        while parent[a] != a {
            parent[a] = parent[parent[a]];
            a = parent[a];
        }
        a
    }
    let mut join = |a: usize, b: usize| {
        if let (Some(a), Some(b)) = (map.component[a], map.component[b]) {
            let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
            parent[ra.max(rb)] = ra.min(rb);
        }
    };
    for k in 0..res {
        join(k * res, k * res + res - 1);
        join(k, (res - 1) * res + k);
    }
    for j in 0..res {
        for i in 0..res {
            join(j * res + i, (res - 1 - j) * res + (i + res / 2) % res);
        }
    }
    let comp = |name: &str| map.pose_components.iter().find(|(n, _)| n == name).and_then(|(_, c)| *c);
    [comp("q1"), comp("q2")].map(|c| c.map(|c| root(&mut parent, c)))
}

/// Interference: a ball in the way of the obstacle-free q1 → q2 path (which the verifier then
/// finds infeasible) but leaving q1 and q2 connected on the slice map: the planner's motion
/// validator (the exact verifier on each path step) rejects the edges through it and the new path
/// is re-verified clean. A ball near the middle of the path, where θ ≈ 0, closes the short way
/// only: the planner then goes the long way round (φ decreasing through ±π, a band with θ up to about 1.3
/// that the atlas of fixed radius 0.4 missed, reporting a `no_path` at its resolution, and that
/// a slice map without periodic edges misses too); with a ball on each path found the slice map
/// (with its periodic edges) finally separates q1 and q2, and there the planner's atlas is
/// exhausted (`no_path`), with charts blocked at its centres.
#[test]
fn robocrane_paths_avoid_obstacles() {
    let s = robocrane();
    let free = plan(&s, "q1-q2", PlanParams::default()).unwrap().path;

    let around = with_ball(&s, &free, 0.7);
    let [a, b] = grid_components(&around);
    assert!(a.is_some() && a == b, "precondition: q1 and q2 connected on the grid");
    assert!(verify_path(&around, &free).infeasible_sections > 0, "the ball must be in the old path's way");
    let out = plan(&around, "q1-q2", PlanParams::default()).unwrap();
    assert_eq!(out.status, PlanStatus::Found);
    assert!(out.atlas.rejected_edges > 0, "edges through the ball are rejected");
    assert_eq!((out.verification.infeasible_sections, out.verification.uncertain_sections, out.verification.wrench_infeasible_poses), (0, 0, 0));

    // Walls: a ball at the middle of each path found, until the grid separates q1 and q2. While it
    // does not, the planner finds a path around the balls, re-verified clean; once it does, the
    // atlas is exhausted: a certified `no_path`.
    let (mut wall, mut path) = (s.clone(), free);
    for balls in 1..=4 {
        wall = with_ball(&wall, &path, 0.5);
        let [a, b] = grid_components(&wall);
        assert!(a.is_some() && b.is_some(), "q1 and q2 stay feasible");
        let out = plan(&wall, "q1-q2", PlanParams::default()).unwrap();
        if a != b {
            assert!(balls > 1, "the first ball leaves the long way round φ = ±π open");
            assert_eq!(out.status, PlanStatus::NoPath, "{balls} balls");
            assert!(out.atlas.blocked_charts > 0);
            assert_eq!((out.atlas.expansion_failures, out.atlas.broken_edges), (0, 0), "a certified no_path");
            return;
        }
        assert_eq!(out.status, PlanStatus::Found, "{balls} balls, q1 and q2 connected on the grid");
        let v = &out.verification;
        assert_eq!((v.infeasible_sections, v.uncertain_sections, v.wrench_infeasible_poses), (0, 0, 0));
        path = out.path;
    }
    panic!("four balls never separated q1 and q2 on the grid");
}

/// The full 6-D space (nothing fixed) between q1 and q2, with the default options: found, and the
/// path checked like the slices' (exact ends, steps at most δ, every pose wrench-feasible, the
/// exact re-verification clean). With the old defaults (fixed radius 0.4, A*) this query ran out
/// of a 1500-chart budget after 255 s; docs/benchmarks.md has the figures. Within a budget of 20
/// charts it ends with an honest `budget`.
#[test]
fn robocrane_full_6d_query_is_found_with_default_options() {
    let mut s = robocrane();
    s.queries.push(Query { name: "6d".to_string(), start: "q1".to_string(), goal: "q2".to_string(), fixed: vec![], region: vec![] });
    let charts = assert_good_path(&s, "6d", &PlanParams::default());
    assert!(charts > 20, "{charts} charts");
    let out = plan(&s, "6d", PlanParams { max_charts: 20, ..PlanParams::default() }).unwrap();
    assert_eq!(out.atlas.dimension, 6);
    assert_eq!((out.status, out.charts), (PlanStatus::Budget, 20));
    assert!(out.path.is_empty());
}

/// `step` is resumable: small steps give the same result as one run, progress never goes
/// backwards, and `outcome` is `None` until done.
#[test]
fn stepping_matches_a_single_run() {
    let s = robocrane();
    let mut p = AtlasPlanner::new(&s, "q1-q2", PlanParams::default()).unwrap();
    assert!(p.outcome().is_none());
    let mut charts = 0;
    let mut steps = 0;
    loop {
        let pr = p.step(1);
        steps += 1;
        assert!(pr.charts >= charts);
        charts = pr.charts;
        if pr.done.is_some() {
            break;
        }
        assert!(pr.best_heuristic.is_finite() || pr.open == 0);
    }
    assert!(steps > 1);
    let stepped = p.outcome().unwrap();
    let whole = plan(&s, "q1-q2", PlanParams::default()).unwrap();
    assert_eq!(stepped, whole);
}

/// Bad input is an error naming the field and the reason, never a panic.
#[test]
fn bad_input_is_reported() {
    let mut s = robocrane();
    let err = |s: &Scenario, q: &str, p: PlanParams| AtlasPlanner::new(s, q, p).err().expect("an error");
    let e = err(&s, "nope", PlanParams::default());
    assert_eq!(e.field, "query");
    assert!(e.reason.contains("q1-q2"), "{}", e.reason);
    for (p, field) in [
        (PlanParams { radius: f64::NAN, ..PlanParams::default() }, "radius"),
        (PlanParams { epsilon: 1.5, ..PlanParams::default() }, "epsilon"),
        (PlanParams { max_charts: 0, ..PlanParams::default() }, "max_charts"),
        (PlanParams { delta: 1.5, ..PlanParams::default() }, "delta"),
        (PlanParams { min_radius: 0.0, ..PlanParams::default() }, "min_radius"),
        (PlanParams { heuristic_weight: 0.5, ..PlanParams::default() }, "heuristic_weight"),
        (PlanParams { min_margin: 0.0, ..PlanParams::default() }, "min_margin"),
    ] {
        assert_eq!(err(&s, "q1-q2", p).field, field);
    }
    // An infeasible start (the platform above the base: the cables would have to push), a goal
    // off the slice, a singular goal (every cable in the base plane).
    s.poses.push(("flipped".to_string(), Pose::from_coords([0.0, 0.0, -2.0, 0.0, 0.0, 0.0])));
    s.poses.push(("elsewhere".to_string(), Pose::from_coords([0.0, 0.0, 1.5, 2.0, 0.9, 7.0 * PI / 36.0])));
    s.poses.push(("flat".to_string(), Pose::from_coords([0.0, 0.0, 0.0, 0.0, 0.0, 0.0])));
    let q = |name: &str, start: &str, goal: &str, fixed: Vec<Coord>| Query { name: name.into(), start: start.into(), goal: goal.into(), fixed, region: vec![] };
    s.queries.push(q("bad-start", "flipped", "q1", vec![]));
    s.queries.push(q("off-slice", "q1", "elsewhere", vec![Coord::Z]));
    s.queries.push(q("singular-goal", "q1", "flat", vec![]));
    let e = err(&s, "bad-start", PlanParams::default());
    assert!(e.field.ends_with(".start") && e.reason.contains("not wrench-feasible"), "{e}");
    let e = err(&s, "off-slice", PlanParams::default());
    assert!(e.field.ends_with(".goal") && e.reason.contains("z = 1.5"), "{e}");
    let e = err(&s, "singular-goal", PlanParams::default());
    assert!(e.field.ends_with(".goal") && e.reason.contains("singular"), "{e}");
    let nan = [f64::NAN, 0.0, 2.0, 0.0, 0.5, 0.0];
    assert_eq!(AtlasPlanner::between_coords(&s, nan, [0.0, 0.0, 2.0, 0.0, 0.5, 0.0], &[], PlanParams::default()).err().unwrap().field, "start[0]");
    // A scenario without a wrench section cannot be planned on.
    let mut nowrench = robocrane();
    nowrench.wrench = None;
    assert_eq!(err(&nowrench, "q1-q2", PlanParams::default()).field, "wrench");
}

/// Every `step` unit does bounded work, counted in manifold evaluations and exact-verifier calls
/// (not in time). On q1 → q3 (φ, θ free) a final walk to the goal used to creep towards a fold of
/// its chart's map: one unit made 2.2 million projections (tens of seconds). With the walks'
/// projection cap a unit makes at most a few thousand evaluations — an expansion tries at most
/// 20 steps, a walk at most 4 n + 16 projections (n = length / δ; a walk goes at most halfway
/// between two centres, so its length is at most the largest radius, n ≤ radius / δ = 25 with
/// the defaults), each projection at most 30 Newton iterations — and the plan is still found and
/// re-verified clean.
#[test]
fn every_step_unit_does_bounded_work() {
    let mut s = robocrane();
    s.queries.push(Query { name: "q1-q3".to_string(), start: "q1".to_string(), goal: "q3".to_string(), fixed: vec![Coord::X, Coord::Y, Coord::Z, Coord::Sigma], region: vec![] });
    let mut p = AtlasPlanner::new(&s, "q1-q3", PlanParams::default()).unwrap();
    let mut last = p.work();
    let (mut most_evaluations, mut most_trajectories, mut most_poses, mut units) = (0, 0, 0, 0);
    while p.step(1).done.is_none() {
        let now = p.work();
        most_evaluations = most_evaluations.max(now.evaluations - last.evaluations);
        most_trajectories = most_trajectories.max(now.trajectory_checks - last.trajectory_checks);
        most_poses = most_poses.max(now.pose_checks - last.pose_checks);
        last = now;
        units += 1;
        assert!(units < 100_000, "the planner does not end");
    }
    eprintln!("q1-q3: {units} units; at most {most_evaluations} evaluations, {most_trajectories} trajectory checks, {most_poses} pose checks per unit");
    assert!(most_evaluations > 0 && most_evaluations <= 3000, "{most_evaluations} manifold evaluations in one unit");
    let n = (PlanParams::default().radius / PlanParams::default().delta).ceil() as usize;
    assert!(most_trajectories <= 2 * (4 * n + 16), "{most_trajectories} trajectory checks in one unit");
    assert!(most_poses <= 2, "{most_poses} pose checks in one unit");
    let out = p.outcome().unwrap();
    assert_eq!(out.status, PlanStatus::Found);
    let v = &out.verification;
    assert_eq!((v.infeasible_sections, v.uncertain_sections, v.wrench_infeasible_poses), (0, 0, 0), "{v:?}");
    assert_eq!((v.edges, v.wrench_poses), (out.path.len() - 1, out.path.len()));
    assert_eq!(out, plan(&s, "q1-q3", PlanParams::default()).unwrap(), "stepping by one unit gives the one-run result");
}

/// The atlas in the slice's coordinates (`PlanOutcome::view`, the report's `atlas_charts`): one
/// view per chart; each polygon (2-D slice) is convex, in cyclic order, holds its centre, and an
/// expanded chart's lies within its ball; the path's charts are marked, from the start's to the
/// goal's; a 3-D slice gives each chart's faces, each a planar convex polygon.
#[test]
fn atlas_view_draws_the_charts_in_slice_coordinates() {
    let s = robocrane();
    let out = plan(&s, "q1-q2", PlanParams::default()).unwrap();
    let v = &out.view;
    assert_eq!(v.coords, ["phi", "theta"]);
    assert_eq!(v.charts.len(), out.charts);
    assert!(v.charts.iter().any(|c| c.state == "expanded") && v.charts.iter().filter(|c| c.on_path).count() >= 2);
    let q1 = s.pose("q1").unwrap().coords();
    assert!((v.charts[0].centre[0] - q1[3]).abs() < 1e-9 && (v.charts[0].centre[1] - q1[4]).abs() < 1e-9 && v.charts[0].on_path);
    for (i, c) in v.charts.iter().enumerate() {
        let p = &c.polygon;
        assert!(p.len() >= 3, "chart {i}: {p:?}");
        let cross = |a: &[f64], b: &[f64], o: &[f64]| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
        let turns: Vec<f64> = (0..p.len()).map(|j| cross(&p[(j + 1) % p.len()], &p[(j + 2) % p.len()], &p[j])).collect();
        assert!(turns.iter().all(|&t| t > -1e-12) || turns.iter().all(|&t| t < 1e-12), "chart {i} is not convex in order: {turns:?}");
        let sides: Vec<f64> = (0..p.len()).map(|j| cross(&p[(j + 1) % p.len()], &c.centre, &p[j])).collect();
        assert!(sides.iter().all(|&t| t >= -1e-12) || sides.iter().all(|&t| t <= 1e-12), "chart {i}'s centre is outside its polygon");
        if c.state == "expanded" {
            let far = p.iter().map(|x| (x[0] - c.centre[0]).hypot(x[1] - c.centre[1])).fold(0.0, f64::max);
            assert!(far <= c.radius * (1.0 + 1e-9), "chart {i}: a vertex {far} from the centre, radius {}", c.radius);
        }
    }
    let cube = plan(&s, "q5-q6", PlanParams::default()).unwrap();
    assert_eq!(cube.view.coords, ["z", "phi", "theta"]);
    for c in &cube.view.charts {
        assert!(c.polygon.is_empty() && c.faces.len() >= 4);
        for face in &c.faces {
            assert!(face.len() >= 3);
            // planar: every vertex on the plane of the first three
            let d = |a: &[f64], b: &[f64]| nalgebra::Vector3::new(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
            let n = d(&face[1], &face[0]).cross(&d(&face[2], &face[0]));
            assert!(face.iter().all(|x| d(x, &face[0]).dot(&n).abs() <= 1e-9 * n.norm().max(1e-12)));
        }
    }
}

/// An atlas saved to a file reads back bit for bit (saving it again gives the same text) and
/// answers a later query from it; a file for another robot or other parameters, malformed JSON
/// and a chart naming a neighbour that does not exist are refused at `atlas`; a query on another
/// slice starts afresh.
#[test]
fn atlas_files_read_back_and_are_checked() {
    let s = robocrane();
    let params = PlanParams::default();
    let mut p = AtlasPlanner::new(&s, "q1-q2", params).unwrap();
    let first = finish(&mut p);
    let text = p.save_atlas();
    let mut again = AtlasPlanner::with_atlas(&s, "q1-q2", params, &text).unwrap();
    assert_eq!(again.save_atlas(), text, "the atlas reads back bit for bit");
    let out = finish(&mut again);
    assert_eq!((out.status, out.charts, out.atlas.reused_charts), (first.status, first.charts, first.charts));
    let other = finish(&mut AtlasPlanner::with_atlas(&s, "q5-q6", params, &text).unwrap());
    assert_eq!((other.status, other.atlas.reused_charts), (PlanStatus::Found, 0), "another slice starts afresh");
    let field = |r: cablenav::Result<AtlasPlanner>| r.err().map(|e| e.field);
    assert_eq!(field(AtlasPlanner::with_atlas(&s, "q1-q2", PlanParams { epsilon: 0.3, ..params }, &text)).as_deref(), Some("atlas"));
    let mut moved = s.clone();
    moved.robot.cables[0].base.x += 0.01;
    assert_eq!(field(AtlasPlanner::with_atlas(&moved, "q1-q2", params, &text)).as_deref(), Some("atlas"));
    assert_eq!(field(AtlasPlanner::with_atlas(&s, "q1-q2", params, "{")).as_deref(), Some("atlas"));
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["charts"][1]["neighbours"] = serde_json::json!([999]);
    assert_eq!(field(AtlasPlanner::with_atlas(&s, "q1-q2", params, &v.to_string())).as_deref(), Some("atlas.charts[1]"));
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["charts"][0]["basis"][0][0] = serde_json::json!(3.0);
    assert_eq!(field(AtlasPlanner::with_atlas(&s, "q1-q2", params, &v.to_string())).as_deref(), Some("atlas.charts[0]"));
}

/// Paper 1's Fig. 6 bottom: along the q3 → q4 path planned in the paper's coordinates, each
/// cable's least tension over the wrench set stays above its bound (0) and some cables come close
/// to it ("some cable may attain a near-zero tension"), computed here from the definition at
/// every path pose (`tension_ranges`, f0 − v): docs/planner.md gives the envelope's numbers.
#[test]
fn q3_q4_tension_envelope_comes_near_zero() {
    let s = robocrane();
    let params = PlanParams { identify_angles: false, ..PlanParams::default() };
    let out = plan(&s, "q3-q4", params).unwrap();
    assert_eq!(out.status, PlanStatus::Found);
    let wrench = s.wrench.clone().unwrap();
    let mut least = [f64::INFINITY; 6];
    for pose in &out.path {
        let r = tension_ranges(&s.robot, pose, &wrench).expect("no path pose is singular");
        for (l, t) in least.iter_mut().zip(r) {
            *l = l.min(t.nominal - t.spread);
        }
    }
    assert!(least.iter().all(|&l| l > 0.0), "{least:?}");
    assert!(least.iter().filter(|&&l| l < 0.01).count() >= 2, "near-zero least tensions expected: {least:?}");
}
