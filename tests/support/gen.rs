//! Deterministic random scenarios for the property tests (pure reference model, no cablenav).

use super::reference::*;

/// Half the side of the frame the base anchors sit on.
pub const FRAME: f64 = 2.0;

/// A random robot with 6–8 cables. Mostly the usual non-crossed layout (base anchors near
/// distinct corners of the cube [−2, 2]³, each cable's platform anchor near the platform corner in
/// the same octant), jittered; sometimes base anchors anywhere on the cube's surface with random
/// platform anchors (cables then cross often). Anchors are sometimes shared between two cables.
pub fn random_cables(rng: &mut Rng) -> Vec<(V3, V3)> {
    let m = rng.int(6, 8);
    let mut cables = Vec::with_capacity(m);
    let half = rng.range(0.25, 0.5);
    if rng.chance(0.8) {
        // distinct corners, in random order
        let mut corners: Vec<usize> = (0..8).collect();
        for i in (1..8).rev() {
            corners.swap(i, rng.int(0, i));
        }
        let jitter = rng.range(0.0, 0.5);
        for &c in corners.iter().take(m) {
            let sgn = v3(
                if c & 1 == 0 { -1.0 } else { 1.0 },
                if c & 2 == 0 { -1.0 } else { 1.0 },
                if c & 4 == 0 { -1.0 } else { 1.0 },
            );
            let mut base = sgn * FRAME + rng.in_box(jitter);
            // back onto the cube's surface
            match rng.int(0, 2) {
                0 => base.x = sgn.x * FRAME,
                1 => base.y = sgn.y * FRAME,
                _ => base.z = sgn.z * FRAME,
            }
            let plat = sgn * half + rng.in_box(0.3 * half);
            cables.push((base, plat));
        }
        // a crossed pair (as in many real robots): swap the platform anchors of two cables,
        // so that those cables pass close to each other and may cross during the motion
        // (pairs at adjacent corners of the frame)
        if rng.chance(0.3) {
            let i = rng.int(0, m - 1);
            let adjacent: Vec<usize> = (0..m).filter(|&j| (corners[i] ^ corners[j]).count_ones() == 1).collect();
            if !adjacent.is_empty() {
                let j = adjacent[rng.int(0, adjacent.len() - 1)];
                let (pi, pj) = (cables[i].1, cables[j].1);
                cables[i].1 = pj;
                cables[j].1 = pi;
            }
        }
    } else {
        for _ in 0..m {
            let mut b = rng.in_box(FRAME);
            let s = if rng.chance(0.5) { FRAME } else { -FRAME };
            match rng.int(0, 2) {
                0 => b.x = s,
                1 => b.y = s,
                _ => b.z = s,
            }
            cables.push((b, rng.unit_vector() * (half * rng.range(0.5, 1.0))));
        }
    }
    if rng.chance(0.15) {
        let (i, j) = (rng.int(0, m - 1), rng.int(0, m - 1));
        if i != j {
            cables[j].0 = cables[i].0;
        }
    }
    if rng.chance(0.1) {
        let (i, j) = (rng.int(0, m - 1), rng.int(0, m - 1));
        // (never both anchors of a cable equal to another's: the scenario rejects that)
        if i != j && cables[i].0 != cables[j].0 {
            cables[j].1 = cables[i].1;
        }
    }
    cables
}

/// A random rotation matrix as rows (via a random unit quaternion).
pub fn random_rotation(rng: &mut Rng) -> M3 {
    quat_to_matrix(quat_axis_angle(rng.unit_vector(), rng.range(0.0, std::f64::consts::PI)))
}

/// A random obstacle of the given kind (0 sphere, 1 box, 2 mesh, 3 ellipsoid, 4 cylinder,
/// 5 cone), centred in [−1.5, 1.5]³ and small enough to stay clear of the base anchors.
pub fn random_shape(rng: &mut Rng, kind: usize) -> RefShape {
    let center = rng.in_box(1.5);
    random_shape_at(rng, kind, center)
}

/// A random obstacle of the given kind around `center`.
pub fn random_shape_at(rng: &mut Rng, kind: usize, center: V3) -> RefShape {
    match kind {
        0 => RefShape::Sphere { center, radius: rng.range(0.05, 0.3) },
        1 => RefShape::Box { center, size: v3(rng.range(0.05, 0.5), rng.range(0.05, 0.5), rng.range(0.05, 0.5)) },
        2 => {
            if rng.chance(0.6) {
                // a tetrahedron
                let vertices: Vec<V3> = (0..4).map(|_| center + rng.in_box(0.25)).collect();
                RefShape::Mesh { vertices, triangles: vec![[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]] }
            } else {
                // a triangle soup (open surface)
                let n = rng.int(1, 4);
                let mut vertices = Vec::new();
                let mut triangles = Vec::new();
                for k in 0..n {
                    let c = center + rng.in_box(0.2);
                    for _ in 0..3 {
                        vertices.push(c + rng.in_box(0.25));
                    }
                    triangles.push([3 * k, 3 * k + 1, 3 * k + 2]);
                }
                RefShape::Mesh { vertices, triangles }
            }
        }
        3 => {
            let r = random_rotation(rng);
            let d = [rng.range(0.05, 0.35), rng.range(0.05, 0.35), rng.range(0.05, 0.35)];
            // M = R diag(1/a²) Rᵀ, exactly symmetric (entry ij sums the same products as ji)
            let m = [0, 1, 2].map(|i| [0, 1, 2].map(|j| (0..3).map(|k| r[i][k] * r[j][k] / (d[k] * d[k])).sum()));
            RefShape::Ellipsoid { center, matrix: m }
        }
        4 => {
            let dir = rng.unit_vector();
            let len = rng.range(0.1, 0.8);
            RefShape::Cylinder {
                from: center - dir * (len / 2.0),
                to: center + dir * (len / 2.0),
                radius: rng.range(0.03, 0.15),
            }
        }
        _ => RefShape::Cone {
            apex: center,
            axis: rng.unit_vector(),
            half_angle: rng.range(0.2, 1.0),
            height: rng.range(0.1, 0.5),
        },
    }
}

/// An obstacle name without digits (so that cable numbers in labels stay unambiguous).
pub fn obstacle_name(shape: &RefShape, k: usize) -> String {
    format!("{}-{}", shape.kind(), (b'a' + (k % 26) as u8) as char)
}

/// Bézier control points → ascending monomial coefficients per axis.
pub fn bezier_to_monomial(p: &[V3]) -> [Vec<f64>; 3] {
    let n = p.len() - 1;
    let binom = |n: usize, k: usize| -> f64 { (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64) };
    let mut out: [Vec<f64>; 3] = [vec![0.0; n + 1], vec![0.0; n + 1], vec![0.0; n + 1]];
    for k in 0..=n {
        for (i, pi) in p.iter().enumerate().take(k + 1) {
            let sign = if (k - i).is_multiple_of(2) { 1.0 } else { -1.0 };
            let w = binom(n, k) * binom(k, i) * sign;
            for (ax, o) in out.iter_mut().enumerate() {
                o[k] += w * pi.get(ax);
            }
        }
    }
    out
}

/// A random translation: polynomial (degree 1–6, either converted from Bézier points or with
/// random coefficients), Bézier (degree 1–6) or line, within about [−1, 1]³.
pub fn random_translation(rng: &mut Rng) -> RefTranslation {
    let u = rng.f64();
    let deg = rng.int(1, 6);
    if u < 0.6 {
        if rng.chance(0.5) {
            let pts: Vec<V3> = (0..=deg).map(|_| rng.in_box(1.0)).collect();
            RefTranslation::Polynomial(bezier_to_monomial(&pts))
        } else {
            let mut c: [Vec<f64>; 3] = Default::default();
            for axis in c.iter_mut() {
                // per-axis degree may differ (trailing coefficients omitted)
                let d = if rng.chance(0.2) { rng.int(1, deg) } else { deg };
                axis.push(rng.range(-1.0, 1.0));
                for k in 1..=d {
                    axis.push(rng.range(-1.0, 1.0) * 1.6 / k as f64);
                }
            }
            RefTranslation::Polynomial(c)
        }
    } else if u < 0.85 {
        RefTranslation::Bezier((0..=deg).map(|_| rng.in_box(1.0)).collect())
    } else {
        RefTranslation::Line(rng.in_box(1.0), rng.in_box(1.0))
    }
}

/// A random slerp: a start orientation tilted by up to 30°, and an end orientation rotated from it
/// by up to 90° (sometimes exactly none).
pub fn random_slerp(rng: &mut Rng) -> (Quat, Quat) {
    let qs = quat_axis_angle(rng.unit_vector(), rng.range(0.0, 30f64.to_radians()));
    let qs = quat_normalize(qs);
    if rng.chance(0.08) {
        return (qs, qs);
    }
    let rot = quat_axis_angle(rng.unit_vector(), rng.range(0.0, 90f64.to_radians()));
    let qe = quat_normalize(quat_mul(qs, rot));
    (qs, qe)
}

/// A random scenario with `ntraj` trajectories.
pub fn random_scenario(rng: &mut Rng, name: &str, ntraj: usize) -> RefScenario {
    let cables = random_cables(rng);
    let length = if rng.chance(0.5) { Some((rng.range(0.5, 1.8), rng.range(3.3, 4.5))) } else { None };
    let cable_cable = rng.range(0.02, 0.3);
    let cable_obstacle = if rng.chance(0.1) { 0.0 } else { rng.range(0.02, 0.3) };
    let trajectories: Vec<RefTrajectory> = (0..ntraj)
        .map(|k| {
            let translation = random_translation(rng);
            let (qs, qe) = random_slerp(rng);
            RefTrajectory { name: format!("traj{}", k + 1), translation, qs, qe }
        })
        .collect();
    // Obstacles, mostly near where some cable passes at some instant (so that trajectories
    // interfere with them part of the time), kept within [−1.5, 1.5]³.
    let nobs = rng.int(0, 3);
    let obstacles = (0..nobs)
        .map(|k| {
            let kind = rng.int(0, 5);
            let center = if rng.chance(0.7) && !trajectories.is_empty() {
                let traj = &trajectories[rng.int(0, trajectories.len() - 1)];
                let (p, r) = traj.pose(rng.f64());
                let (a, b) = cables[rng.int(0, cables.len() - 1)];
                let end = p + mat_vec(&r, b);
                let c = a + (end - a) * rng.range(0.3, 0.9) + rng.in_box(0.25);
                v3(c.x.clamp(-1.5, 1.5), c.y.clamp(-1.5, 1.5), c.z.clamp(-1.5, 1.5))
            } else {
                rng.in_box(1.5)
            };
            let shape = random_shape_at(rng, kind, center);
            RefObstacle { name: obstacle_name(&shape, k), shape }
        })
        .collect();
    let mut sc =
        RefScenario { name: name.to_string(), cables, length, cable_cable, cable_obstacle, obstacles, trajectories };
    adapt_bounds(rng, &mut sc);
    sc
}

/// The q-quantile (0 ≤ q ≤ 1) of some values.
fn quantile(v: &mut [f64], q: f64) -> f64 {
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v[((v.len() - 1) as f64 * q).round() as usize]
}

/// Most of the time, chooses the clearances (within [0.02, 0.3]) and length bounds from the
/// distances and lengths met along the trajectories, so that each condition changes along the
/// motion rather than holding or failing throughout.
fn adapt_bounds(rng: &mut Rng, sc: &mut RefScenario) {
    let mut probe = sc.clone();
    probe.cable_cable = 0.0;
    probe.cable_obstacle = 0.0;
    probe.length = None;
    let ev = probe.evaluator();
    let n = 48;
    let (mut pair, mut obs, mut lmin, mut lmax) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for i in 0..n {
        let k = i % sc.trajectories.len();
        let checks = ev.checks(k, (i as f64 + 0.5) / n as f64);
        let min_of =
            |f: &dyn Fn(&Check) -> bool| checks.iter().filter(|c| f(c)).map(|c| c.margin).fold(f64::INFINITY, f64::min);
        pair.push(min_of(&|c| c.cables.1.is_some()));
        obs.push(min_of(&|c| c.obstacle.is_some()));
        let lens: Vec<f64> =
            ev.segments(k, (i as f64 + 0.5) / n as f64).iter().map(|(a, b)| (*b - *a).norm()).collect();
        lmin.push(lens.iter().cloned().fold(f64::INFINITY, f64::min));
        lmax.push(lens.iter().cloned().fold(0.0, f64::max));
    }
    if rng.chance(0.7) && pair.iter().all(|x| x.is_finite()) {
        let q = rng.range(0.05, 0.6);
        sc.cable_cable = quantile(&mut pair, q).clamp(0.02, 0.3);
    }
    if sc.cable_obstacle > 0.0 && rng.chance(0.7) && obs.iter().all(|x| x.is_finite()) {
        let q = rng.range(0.05, 0.6);
        sc.cable_obstacle = quantile(&mut obs, q).clamp(0.02, 0.3);
    }
    if sc.length.is_some() && rng.chance(0.4) {
        let lo = quantile(&mut lmin, rng.range(0.0, 0.4));
        let hi = quantile(&mut lmax, rng.range(0.6, 1.0));
        sc.length = Some((lo.max(0.0), hi.max(lo)));
    }
}
