//! An independent, point-wise reference for cablenav's documented feasibility semantics.
//!
//! Everything here is written from the written definitions (scenario format and condition
//! semantics), deliberately without looking at `src/conditions` or `src/query`: the property
//! tests compare cablenav's exact interval verifier against dense sampling of this model.
//!
//! * [`V3`], [`Rng`]: tiny vector type and a deterministic splitmix64 generator (no crates);
//! * pose evaluation: direct sin-based slerp (signs kept as given), τ(t), quaternion → matrix;
//! * geometry: point/segment/triangle distances, segment–triangle crossing, segment vs.
//!   ellipsoid in a metric, segment vs. solid truncated cone;
//! * [`RefScenario`]: the model, its scenario JSON, and [`RefScenario::checks`] /
//!   [`RefScenario::feasible`] at a trajectory parameter t.

use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

// ---------------------------------------------------------------------------------------------
// Vectors
// ---------------------------------------------------------------------------------------------

/// A 3-vector.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct V3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

/// Shorthand constructor.
pub const fn v3(x: f64, y: f64, z: f64) -> V3 {
    V3 { x, y, z }
}

impl V3 {
    pub const ZERO: V3 = v3(0.0, 0.0, 0.0);
    pub fn from_arr(a: [f64; 3]) -> V3 {
        v3(a[0], a[1], a[2])
    }
    pub fn arr(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }
    pub fn dot(self, o: V3) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    pub fn cross(self, o: V3) -> V3 {
        v3(self.y * o.z - self.z * o.y, self.z * o.x - self.x * o.z, self.x * o.y - self.y * o.x)
    }
    pub fn norm2(self) -> f64 {
        self.dot(self)
    }
    pub fn norm(self) -> f64 {
        self.norm2().sqrt()
    }
    pub fn normalized(self) -> V3 {
        self / self.norm()
    }
    pub fn max_abs(self) -> f64 {
        self.x.abs().max(self.y.abs()).max(self.z.abs())
    }
    pub fn get(self, i: usize) -> f64 {
        match i {
            0 => self.x,
            1 => self.y,
            _ => self.z,
        }
    }
}

impl Add for V3 {
    type Output = V3;
    fn add(self, o: V3) -> V3 {
        v3(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}
impl AddAssign for V3 {
    fn add_assign(&mut self, o: V3) {
        *self = *self + o;
    }
}
impl Sub for V3 {
    type Output = V3;
    fn sub(self, o: V3) -> V3 {
        v3(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}
impl Neg for V3 {
    type Output = V3;
    fn neg(self) -> V3 {
        v3(-self.x, -self.y, -self.z)
    }
}
impl Mul<f64> for V3 {
    type Output = V3;
    fn mul(self, s: f64) -> V3 {
        v3(self.x * s, self.y * s, self.z * s)
    }
}
impl Div<f64> for V3 {
    type Output = V3;
    fn div(self, s: f64) -> V3 {
        v3(self.x / s, self.y / s, self.z / s)
    }
}

/// A 3×3 matrix, rows first.
pub type M3 = [[f64; 3]; 3];

pub fn mat_vec(m: &M3, v: V3) -> V3 {
    v3(
        m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
        m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
        m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z,
    )
}

pub fn mat_mul(a: &M3, b: &M3) -> M3 {
    let mut r = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            r[i][j] = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    r
}

pub fn transpose(a: &M3) -> M3 {
    let mut r = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            r[i][j] = a[j][i];
        }
    }
    r
}

pub fn det3(m: &M3) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

/// Inverse by the adjugate (fine for the well-conditioned SPD matrices used here).
pub fn inv3(m: &M3) -> M3 {
    let d = det3(m);
    let c = |i: usize, j: usize| {
        let (r0, r1) = ((i + 1) % 3, (i + 2) % 3);
        let (c0, c1) = ((j + 1) % 3, (j + 2) % 3);
        m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]
    };
    // (adj m)_{ij} = cofactor_{ji}; the cyclic index choice already carries the sign.
    [0, 1, 2].map(|i| [0, 1, 2].map(|j| c(j, i) / d))
}

/// xᵀ M x.
pub fn quad_form(m: &M3, x: V3) -> f64 {
    x.dot(mat_vec(m, x))
}

// ---------------------------------------------------------------------------------------------
// Deterministic PRNG
// ---------------------------------------------------------------------------------------------

/// splitmix64: tiny, fast, deterministic on every platform.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed ^ 0x5DEE_CE66_D1CE_4E5B)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
    /// Uniform in [a, b).
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.f64()
    }
    /// Uniform integer in [lo, hi] (inclusive).
    pub fn int(&mut self, lo: usize, hi: usize) -> usize {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as usize
    }
    pub fn chance(&mut self, p: f64) -> bool {
        self.f64() < p
    }
    /// Standard normal (Box–Muller).
    pub fn normal(&mut self) -> f64 {
        let u1 = 1.0 - self.f64();
        let u2 = self.f64();
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    }
    pub fn unit_vector(&mut self) -> V3 {
        loop {
            let v = v3(self.normal(), self.normal(), self.normal());
            let n = v.norm();
            if n > 1e-3 {
                return v / n;
            }
        }
    }
    pub fn in_box(&mut self, half: f64) -> V3 {
        v3(self.range(-half, half), self.range(-half, half), self.range(-half, half))
    }
}

// ---------------------------------------------------------------------------------------------
// Quaternions and the orientation / parameter maps
// ---------------------------------------------------------------------------------------------

/// A quaternion `[w, x, y, z]`.
pub type Quat = [f64; 4];

pub fn quat_dot(a: Quat, b: Quat) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]
}

pub fn quat_norm(q: Quat) -> f64 {
    quat_dot(q, q).sqrt()
}

pub fn quat_normalize(q: Quat) -> Quat {
    let n = quat_norm(q);
    [q[0] / n, q[1] / n, q[2] / n, q[3] / n]
}

/// Hamilton product a ⊗ b.
pub fn quat_mul(a: Quat, b: Quat) -> Quat {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// The unit quaternion of a rotation by `angle` radians about the unit `axis`.
pub fn quat_axis_angle(axis: V3, angle: f64) -> Quat {
    let (s, c) = (angle / 2.0).sin_cos();
    [c, axis.x * s, axis.y * s, axis.z * s]
}

/// Rotation matrix of a (normalised here) quaternion `[w, x, y, z]`.
pub fn quat_to_matrix(q: Quat) -> M3 {
    let [w, x, y, z] = quat_normalize(q);
    [
        [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)],
        [2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)],
        [2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)],
    ]
}

/// The slerp angle θ ∈ [0, π] with cos θ = Qs·Qe (signs as given), computed robustly as
/// 2·atan2(|Qs − Qe|, |Qs + Qe|) on the normalised quaternions.
pub fn slerp_angle(qs: Quat, qe: Quat) -> f64 {
    let (a, b) = (quat_normalize(qs), quat_normalize(qe));
    let d: f64 = (0..4).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt();
    let s: f64 = (0..4).map(|i| (a[i] + b[i]).powi(2)).sum::<f64>().sqrt();
    2.0 * d.atan2(s)
}

/// Q(t) = (Qs sin((1−t)θ) + Qe sin(tθ)) / sin θ, evaluated directly (Q = Qs when θ = 0).
pub fn slerp(qs: Quat, qe: Quat, t: f64) -> Quat {
    let (a, b) = (quat_normalize(qs), quat_normalize(qe));
    let theta = slerp_angle(a, b);
    if theta == 0.0 {
        return a;
    }
    let st = theta.sin();
    let (wa, wb) = (((1.0 - t) * theta).sin() / st, (t * theta).sin() / st);
    quat_normalize([a[0] * wa + b[0] * wb, a[1] * wa + b[1] * wb, a[2] * wa + b[2] * wb, a[3] * wa + b[3] * wb])
}

/// τ(t) = tan(tθ/2) / tan(θ/2), and τ = t when θ = 0.
pub fn tau_of_t(theta: f64, t: f64) -> f64 {
    if theta == 0.0 {
        t
    } else {
        (t * theta / 2.0).tan() / (theta / 2.0).tan()
    }
}

// ---------------------------------------------------------------------------------------------
// Geometry
// ---------------------------------------------------------------------------------------------

/// Squared distance from point `p` to segment `a`–`b` (a point when a = b).
pub fn point_segment_dist2(p: V3, a: V3, b: V3) -> f64 {
    let d = b - a;
    let l2 = d.norm2();
    let s = if l2 > 0.0 { ((p - a).dot(d) / l2).clamp(0.0, 1.0) } else { 0.0 };
    (a + d * s - p).norm2()
}

pub fn point_segment_dist(p: V3, a: V3, b: V3) -> f64 {
    point_segment_dist2(p, a, b).sqrt()
}

/// Minimum distance between segments p0–p1 and q0–q1.
///
/// The squared distance is a convex quadratic on [0,1]²: its minimum is either the interior
/// critical point (only for non-parallel lines) or on an edge of the square, i.e. one of the four
/// endpoint-to-segment distances. Every candidate is a distance between actual points of the two
/// segments, so parallel, nearly parallel and degenerate segments need no special cases.
pub fn segment_segment_dist(p0: V3, p1: V3, q0: V3, q1: V3) -> f64 {
    let mut best = point_segment_dist2(p0, q0, q1)
        .min(point_segment_dist2(p1, q0, q1))
        .min(point_segment_dist2(q0, p0, p1))
        .min(point_segment_dist2(q1, p0, p1));
    let (d1, d2, r) = (p1 - p0, q1 - q0, p0 - q0);
    let (a, e, b) = (d1.norm2(), d2.norm2(), d1.dot(d2));
    let (c, f) = (d1.dot(r), d2.dot(r));
    let denom = a * e - b * b;
    if denom > 1e-14 * a * e && denom > 0.0 {
        let s = (b * f - c * e) / denom;
        let t = (a * f - b * c) / denom;
        if (0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&t) {
            best = best.min((p0 + d1 * s - (q0 + d2 * t)).norm2());
        }
    }
    best.sqrt()
}

/// Distance from point `p` to the triangle `v` (closed, including its interior).
pub fn point_triangle_dist(p: V3, v: &[V3; 3]) -> f64 {
    let (e0, e1) = (v[1] - v[0], v[2] - v[0]);
    let n = e0.cross(e1);
    let n2 = n.norm2();
    let edges = point_segment_dist2(p, v[0], v[1])
        .min(point_segment_dist2(p, v[1], v[2]))
        .min(point_segment_dist2(p, v[2], v[0]));
    if n2 > 0.0 {
        // Barycentric coordinates of the projection of p onto the plane.
        let w = p - v[0];
        let b1 = w.cross(e1).dot(n) / n2; // weight of v[1]
        let b2 = e0.cross(w).dot(n) / n2; // weight of v[2]
        if b1 >= 0.0 && b2 >= 0.0 && b1 + b2 <= 1.0 {
            let h = w.dot(n) / n2.sqrt();
            return h.abs().min(edges.sqrt());
        }
    }
    edges.sqrt()
}

/// Whether segment p0–p1 meets the triangle `v` transversally or touches it (a point of the
/// segment lies in the closed triangle, the segment not lying in its plane). Returns a measure of
/// how deep the crossing is (the smallest of: the endpoints' distances to the plane and the
/// crossing point's distance to the triangle's edges), or `None` when it does not cross.
pub fn segment_crosses_triangle(p0: V3, p1: V3, v: &[V3; 3]) -> Option<f64> {
    let (e0, e1) = (v[1] - v[0], v[2] - v[0]);
    let n = e0.cross(e1);
    let nn = n.norm();
    if nn == 0.0 {
        return None;
    }
    let nu = n / nn;
    let (h0, h1) = ((p0 - v[0]).dot(nu), (p1 - v[0]).dot(nu));
    if h0 > 0.0 && h1 > 0.0 || h0 < 0.0 && h1 < 0.0 || h0 == h1 {
        return None; // same side, or parallel to (coplanar with) the plane
    }
    let s = h0 / (h0 - h1);
    let x = p0 + (p1 - p0) * s;
    let w = x - v[0];
    let n2 = nn * nn;
    let b1 = w.cross(e1).dot(n) / n2;
    let b2 = e0.cross(w).dot(n) / n2;
    if b1 >= 0.0 && b2 >= 0.0 && b1 + b2 <= 1.0 {
        let inplane = point_segment_dist(x, v[0], v[1])
            .min(point_segment_dist(x, v[1], v[2]))
            .min(point_segment_dist(x, v[2], v[0]));
        Some(inplane.min(h0.abs()).min(h1.abs()))
    } else {
        None
    }
}

/// Distance from segment p0–p1 to the closed triangle `v` (0 when they meet).
pub fn segment_triangle_dist(p0: V3, p1: V3, v: &[V3; 3]) -> f64 {
    if segment_crosses_triangle(p0, p1, v).is_some() {
        return 0.0;
    }
    // Not crossing: the closest pair involves a segment endpoint or a triangle edge.
    point_triangle_dist(p0, v)
        .min(point_triangle_dist(p1, v))
        .min(segment_segment_dist(p0, p1, v[0], v[1]))
        .min(segment_segment_dist(p0, p1, v[1], v[2]))
        .min(segment_segment_dist(p0, p1, v[2], v[0]))
}

/// min over s ∈ [0,1] of (x(s)−c)ᵀ M (x(s)−c) for x(s) = p0 + s(p1−p0), M SPD; returns (q, s).
pub fn segment_metric_min(p0: V3, p1: V3, center: V3, m: &M3) -> (f64, f64) {
    let (w0, d) = (p0 - center, p1 - p0);
    let md = mat_vec(m, d);
    let a = d.dot(md);
    let b = w0.dot(md);
    let mut s = if a > 0.0 { (-b / a).clamp(0.0, 1.0) } else { 0.0 };
    let mut q = quad_form(m, w0 + d * s);
    for e in [0.0, 1.0] {
        let qe = quad_form(m, w0 + d * e);
        if qe < q {
            q = qe;
            s = e;
        }
    }
    (q, s)
}

/// Distance from x to the solid ellipsoid (y−c)ᵀM(y−c) ≤ 1 (0 inside), by Lagrange duality:
/// dist² = max over t ≥ 0 of t·wᵀM(I + tM)⁻¹w − t with w = x − c (a concave function of t, whose
/// maximiser is at most √(wᵀM⁻¹w)); golden section on t.
pub fn ellipsoid_point_dist(x: V3, center: V3, m: &M3) -> f64 {
    let w = x - center;
    if quad_form(m, w) <= 1.0 {
        return 0.0;
    }
    let q = |t: f64| {
        let mut a = *m;
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] = if i == j { 1.0 } else { 0.0 } + t * m[i][j];
            }
        }
        let y = mat_vec(&inv3(&a), w);
        t * mat_vec(m, y).dot(w) - t
    };
    let hi = quad_form(&inv3(m), w).sqrt();
    (-golden_min(|t| -q(t), 0.0, hi)).max(0.0).sqrt()
}

/// Signed distance from x to the solid cylinder (negative inside: minus the depth).
pub fn cylinder_sdf(x: V3, from: V3, to: V3, r: f64) -> f64 {
    let len = (to - from).norm();
    let e = (to - from) / len;
    let h = (x - from).dot(e);
    let rho = (x - from - e * h).norm();
    // nearest point of the rectangle [0, L] × [0, r] in the (h, ρ) half-plane
    let (hc, rc) = (h.clamp(0.0, len), rho.min(r));
    let out = ((h - hc) * (h - hc) + (rho - rc) * (rho - rc)).sqrt();
    if out > 0.0 {
        out
    } else {
        -(r - rho).min(h).min(len - h)
    }
}

/// Solid truncated cone {x : (x−A)·u ≥ |x−A| cos α, (x−A)·u ≤ H}.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidCone {
    pub apex: V3,
    pub axis: V3,
    pub half_angle: f64,
    pub height: f64,
}

impl SolidCone {
    /// Signed distance from x (negative inside: minus the depth), by the Voronoi regions of the
    /// section's features in generator coordinates: along the generator g = h cos α + ρ sin α,
    /// off it n = ρ cos α − h sin α.
    pub fn sdf(&self, x: V3) -> f64 {
        let w = x - self.apex;
        let h = w.dot(self.axis);
        let rho = (w - self.axis * h).norm();
        let (sa, ca) = self.half_angle.sin_cos();
        let (big_h, big_r) = (self.height, self.height * self.half_angle.tan());
        let (g, n) = (h * ca + rho * sa, rho * ca - h * sa);
        if n <= 0.0 && h <= big_h {
            return -(-n).min(big_h - h);
        }
        if h > big_h && rho <= big_r {
            h - big_h
        } else if n > 0.0 && g >= 0.0 && g <= big_h / ca {
            n
        } else if g < 0.0 {
            (h * h + rho * rho).sqrt()
        } else {
            ((h - big_h) * (h - big_h) + (rho - big_r) * (rho - big_r)).sqrt()
        }
    }

    /// Whether the segment p0–p1 meets the closed solid: clip the segment parameter to the slab
    /// 0 ≤ h ≤ H (h the axial coordinate), then maximise the quadratic h² − cos²α|x−A|² over the
    /// clipped interval (h ≥ 0 there, so f ≥ 0 is exactly the cone inequality).
    pub fn meets_segment(&self, p0: V3, p1: V3) -> bool {
        let (u, ca) = (self.axis, self.half_angle.cos());
        let (w0, d) = (p0 - self.apex, p1 - p0);
        let (h0, hd) = (w0.dot(u), d.dot(u));
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        if hd == 0.0 {
            if h0 < 0.0 || h0 > self.height {
                return false;
            }
        } else {
            let (sa, sb) = (-h0 / hd, (self.height - h0) / hd);
            lo = lo.max(sa.min(sb));
            hi = hi.min(sa.max(sb));
            if lo > hi {
                return false;
            }
        }
        let c2 = ca * ca;
        let f = |s: f64| {
            let w = w0 + d * s;
            let h = w.dot(u);
            h * h - c2 * w.norm2()
        };
        let qa = hd * hd - c2 * d.norm2();
        let qb = 2.0 * (h0 * hd - c2 * w0.dot(d));
        let mut best = f(lo).max(f(hi));
        if qa < 0.0 {
            let sv = -qb / (2.0 * qa);
            if sv > lo && sv < hi {
                best = best.max(f(sv));
            }
        }
        best >= 0.0
    }

    /// A signed clearance-like function of a point: max(r cos α − h sin α, h − H) (≤ 0 exactly on
    /// the closed solid; it is the signed distance inside and a lower bound on it outside).
    pub fn phi(&self, x: V3) -> f64 {
        let w = x - self.apex;
        let h = w.dot(self.axis);
        let r = (w - self.axis * h).norm();
        let (sa, ca) = self.half_angle.sin_cos();
        (r * ca - h * sa).max(h - self.height)
    }

    /// min over the segment of [`SolidCone::phi`] (convex along the segment: golden section).
    pub fn segment_phi_min(&self, p0: V3, p1: V3) -> f64 {
        let g = |s: f64| self.phi(p0 + (p1 - p0) * s);
        golden_min(g, 0.0, 1.0).min(g(0.0)).min(g(1.0))
    }
}

/// Minimum of a convex function on [a, b] by golden-section search.
pub fn golden_min(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let r = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - r * (b - a);
    let mut d = a + r * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..200 {
        if fc < fd {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            fd = f(d);
        }
        if b - a < 1e-15 {
            break;
        }
    }
    fc.min(fd)
}

// ---------------------------------------------------------------------------------------------
// The model
// ---------------------------------------------------------------------------------------------

/// Obstacle geometry as the scenario states it.
#[derive(Clone, Debug, PartialEq)]
pub enum RefShape {
    Sphere {
        center: V3,
        radius: f64,
    },
    /// Axis-aligned box: centre and full side lengths.
    Box {
        center: V3,
        size: V3,
    },
    Mesh {
        vertices: Vec<V3>,
        triangles: Vec<[usize; 3]>,
    },
    Ellipsoid {
        center: V3,
        matrix: M3,
    },
    Cylinder {
        from: V3,
        to: V3,
        radius: f64,
    },
    Cone {
        apex: V3,
        axis: V3,
        half_angle: f64,
        height: f64,
    },
}

impl RefShape {
    pub fn kind(&self) -> &'static str {
        match self {
            RefShape::Sphere { .. } => "sphere",
            RefShape::Box { .. } => "box",
            RefShape::Mesh { .. } => "mesh",
            RefShape::Ellipsoid { .. } => "ellipsoid",
            RefShape::Cylinder { .. } => "cylinder",
            RefShape::Cone { .. } => "cone",
        }
    }
}

/// The 12 triangles of an axis-aligned box (any triangulation of the faces has the same union).
pub fn box_triangles(center: V3, size: V3) -> Vec<[V3; 3]> {
    let h = size * 0.5;
    let corner = |i: usize| {
        center
            + v3(
                if i & 1 == 0 { -h.x } else { h.x },
                if i & 2 == 0 { -h.y } else { h.y },
                if i & 4 == 0 { -h.z } else { h.z },
            )
    };
    let faces = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]];
    let mut tris = Vec::new();
    for f in faces {
        tris.push([corner(f[0]), corner(f[1]), corner(f[2])]);
        tris.push([corner(f[0]), corner(f[2]), corner(f[3])]);
    }
    tris
}

/// A named obstacle.
#[derive(Clone, Debug, PartialEq)]
pub struct RefObstacle {
    pub name: String,
    pub shape: RefShape,
}

/// The translation of a trajectory, in τ ∈ [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub enum RefTranslation {
    /// Ascending coefficients per axis.
    Polynomial([Vec<f64>; 3]),
    Bezier(Vec<V3>),
    Line(V3, V3),
}

impl RefTranslation {
    pub fn at(&self, tau: f64) -> V3 {
        match self {
            RefTranslation::Polynomial(c) => {
                let h = |k: &Vec<f64>| k.iter().rev().fold(0.0, |acc, &a| acc * tau + a);
                v3(h(&c[0]), h(&c[1]), h(&c[2]))
            }
            RefTranslation::Bezier(pts) => {
                let mut p = pts.clone();
                for level in (1..p.len()).rev() {
                    for k in 0..level {
                        p[k] = p[k] * (1.0 - tau) + p[k + 1] * tau;
                    }
                }
                p[0]
            }
            RefTranslation::Line(a, b) => *a * (1.0 - tau) + *b * tau,
        }
    }

    pub fn to_json(&self) -> serde_json::Value {
        match self {
            RefTranslation::Polynomial(c) => serde_json::json!({ "polynomial": [c[0], c[1], c[2]] }),
            RefTranslation::Bezier(p) => {
                serde_json::json!({ "bezier": p.iter().map(|q| q.arr()).collect::<Vec<_>>() })
            }
            RefTranslation::Line(a, b) => serde_json::json!({ "line": [a.arr(), b.arr()] }),
        }
    }

    pub fn kind(&self) -> String {
        match self {
            RefTranslation::Polynomial(c) => {
                format!("polynomial deg {}", c.iter().map(|k| k.len()).max().unwrap_or(1) - 1)
            }
            RefTranslation::Bezier(p) => format!("bezier deg {}", p.len() - 1),
            RefTranslation::Line(..) => "line".into(),
        }
    }
}

/// A trajectory: translation in τ, slerp orientation in t.
#[derive(Clone, Debug, PartialEq)]
pub struct RefTrajectory {
    pub name: String,
    pub translation: RefTranslation,
    pub qs: Quat,
    pub qe: Quat,
}

impl RefTrajectory {
    pub fn theta(&self) -> f64 {
        slerp_angle(self.qs, self.qe)
    }
    pub fn tau(&self, t: f64) -> f64 {
        tau_of_t(self.theta(), t)
    }
    /// The pose at t: position p(τ(t)) and rotation matrix R(Q(t)).
    pub fn pose(&self, t: f64) -> (V3, M3) {
        let theta = self.theta();
        let p = self.translation.at(tau_of_t(theta, t));
        (p, quat_to_matrix(slerp(self.qs, self.qe, t)))
    }
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "name": self.name,
            "translation": self.translation.to_json(),
            "orientation": { "slerp": [self.qs, self.qe] },
        })
    }
}

/// One condition's verdict at a pose: a label, whether it is violated, and a signed margin in
/// length units (≈ distance − required distance; negative iff violated, up to rounding).
#[derive(Clone, Debug, PartialEq)]
pub struct Check {
    pub label: String,
    /// What the condition is about: cable indices (0-based) and obstacle index, if any.
    pub cables: (usize, Option<usize>),
    pub obstacle: Option<usize>,
    pub violated: bool,
    pub margin: f64,
}

/// A scenario as the reference sees it.
#[derive(Clone, Debug, PartialEq)]
pub struct RefScenario {
    pub name: String,
    /// (base anchor in the world, platform anchor in the platform frame).
    pub cables: Vec<(V3, V3)>,
    /// Cable length bounds (min, max), if any.
    pub length: Option<(f64, f64)>,
    pub cable_cable: f64,
    pub cable_obstacle: f64,
    pub obstacles: Vec<RefObstacle>,
    pub trajectories: Vec<RefTrajectory>,
}

/// Obstacle data prepared for fast repeated queries.
#[derive(Clone, Debug)]
enum Prepared {
    Sphere { center: V3, reach: f64 },
    Mesh { tris: Vec<[V3; 3]>, center: V3, radius: f64 },
    /// `reach`: the largest semi-axis plus the clearance; `least`: a lower bound on the smallest
    /// semi-axis, 1/√(a bound on M's largest eigenvalue).
    Ellipsoid { center: V3, m: M3, scale: f64, reach: f64, least: f64 },
    Cylinder { from: V3, to: V3, radius: f64 },
    Cone { cone: SolidCone },
}

/// A scenario prepared for many evaluations.
#[derive(Clone, Debug)]
pub struct Evaluator {
    pub scenario: RefScenario,
    prepared: Vec<Prepared>,
    /// Cable pairs whose clearance is checked (no shared base or platform anchor).
    pub pairs: Vec<(usize, usize)>,
    /// A length scale of the scenario (for tolerances).
    pub scale: f64,
}

impl RefScenario {
    /// The scenario JSON (`cablenav-scenario/1`).
    pub fn to_json(&self) -> String {
        use serde_json::json;
        let cables: Vec<_> = self.cables.iter().map(|(a, b)| json!({ "base": a.arr(), "platform": b.arr() })).collect();
        let mut robot = json!({ "cables": cables });
        if let Some((lo, hi)) = self.length {
            robot["length"] = json!({ "min": lo, "max": hi });
        }
        let obstacles: Vec<_> = self
            .obstacles
            .iter()
            .map(|o| {
                let mut v = match &o.shape {
                    RefShape::Sphere { center, radius } => {
                        json!({ "type": "sphere", "center": center.arr(), "radius": radius })
                    }
                    RefShape::Box { center, size } => {
                        json!({ "type": "box", "center": center.arr(), "size": size.arr() })
                    }
                    RefShape::Mesh { vertices, triangles } => json!({
                        "type": "mesh",
                        "vertices": vertices.iter().map(|v| v.arr()).collect::<Vec<_>>(),
                        "triangles": triangles,
                    }),
                    RefShape::Ellipsoid { center, matrix } => {
                        json!({ "type": "ellipsoid", "center": center.arr(), "matrix": matrix })
                    }
                    RefShape::Cylinder { from, to, radius } => json!({
                        "type": "cylinder", "from": from.arr(), "to": to.arr(), "radius": radius
                    }),
                    RefShape::Cone { apex, axis, half_angle, height } => json!({
                        "type": "cone", "apex": apex.arr(), "axis": axis.arr(),
                        "half_angle": half_angle, "height": height
                    }),
                };
                v["name"] = json!(o.name);
                v
            })
            .collect();
        let doc = json!({
            "format": "cablenav-scenario/1",
            "name": self.name,
            "robot": robot,
            "clearance": { "cable_cable": self.cable_cable, "cable_obstacle": self.cable_obstacle },
            "obstacles": obstacles,
            "trajectories": self.trajectories.iter().map(|t| t.to_json()).collect::<Vec<_>>(),
        });
        serde_json::to_string_pretty(&doc).expect("scenario JSON")
    }

    /// A length scale: the largest absolute coordinate of an anchor or obstacle point, at least 1.
    pub fn scale(&self) -> f64 {
        let mut s: f64 = 1.0;
        for (a, b) in &self.cables {
            s = s.max(a.max_abs()).max(b.max_abs());
        }
        s
    }

    pub fn evaluator(&self) -> Evaluator {
        let c = self.cable_obstacle;
        let prepared = self
            .obstacles
            .iter()
            .map(|o| match &o.shape {
                RefShape::Sphere { center, radius } => Prepared::Sphere { center: *center, reach: radius + c },
                RefShape::Box { center, size } => mesh_prep(box_triangles(*center, *size)),
                RefShape::Mesh { vertices, triangles } => {
                    mesh_prep(triangles.iter().map(|t| [vertices[t[0]], vertices[t[1]], vertices[t[2]]]).collect())
                }
                RefShape::Ellipsoid { center, matrix } => {
                    // the largest semi-axis is at most √(trace M⁻¹)
                    let mi = inv3(matrix);
                    let reach = (mi[0][0] + mi[1][1] + mi[2][2]).sqrt() + c;
                    // M's largest eigenvalue is at most its trace and its largest absolute row sum
                    let trace = matrix[0][0] + matrix[1][1] + matrix[2][2];
                    let rows = matrix.iter().map(|r| r.iter().map(|x| x.abs()).sum::<f64>()).fold(0.0, f64::max);
                    let least = 1.0 / trace.min(rows).sqrt();
                    Prepared::Ellipsoid { center: *center, m: *matrix, scale: det3(matrix).powf(-1.0 / 6.0), reach, least }
                }
                RefShape::Cylinder { from, to, radius } => Prepared::Cylinder { from: *from, to: *to, radius: *radius },
                RefShape::Cone { apex, axis, half_angle, height } => Prepared::Cone {
                    cone: SolidCone { apex: *apex, axis: *axis, half_angle: *half_angle, height: *height },
                },
            })
            .collect();
        let m = self.cables.len();
        let mut pairs = Vec::new();
        for i in 0..m {
            for j in i + 1..m {
                let (ci, cj) = (self.cables[i], self.cables[j]);
                if ci.0 != cj.0 && ci.1 != cj.1 {
                    pairs.push((i, j));
                }
            }
        }
        Evaluator { scenario: self.clone(), prepared, pairs, scale: self.scale() }
    }
}

fn mesh_prep(tris: Vec<[V3; 3]>) -> Prepared {
    let mut lo = v3(f64::INFINITY, f64::INFINITY, f64::INFINITY);
    let mut hi = -lo;
    for t in &tris {
        for p in t {
            lo = v3(lo.x.min(p.x), lo.y.min(p.y), lo.z.min(p.z));
            hi = v3(hi.x.max(p.x), hi.y.max(p.y), hi.z.max(p.z));
        }
    }
    let center = (lo + hi) * 0.5;
    let radius = tris.iter().flat_map(|t| t.iter()).map(|p| (*p - center).norm()).fold(0.0, f64::max);
    Prepared::Mesh { tris, center, radius }
}

impl Evaluator {
    /// The cable segments (base anchor, world platform anchor) at parameter t of trajectory `k`.
    pub fn segments(&self, traj: usize, t: f64) -> Vec<(V3, V3)> {
        let (p, r) = self.scenario.trajectories[traj].pose(t);
        self.scenario.cables.iter().map(|(a, b)| (*a, p + mat_vec(&r, *b))).collect()
    }

    /// Whether obstacle `k` is violated by segment (a, b), with early outs (no margin).
    fn obstacle_violated(&self, k: usize, a: V3, b: V3) -> bool {
        let c = self.scenario.cable_obstacle;
        match &self.prepared[k] {
            Prepared::Sphere { center, reach } => point_segment_dist2(*center, a, b) < reach * reach,
            Prepared::Mesh { tris, center, radius } => {
                let slack = 1e-9 * self.scale;
                if point_segment_dist(*center, a, b) - radius > c + slack {
                    return false;
                }
                // (a crossing counts even when c = 0)
                tris.iter()
                    .any(|tri| segment_crosses_triangle(a, b, tri).is_some() || segment_triangle_dist(a, b, tri) < c)
            }
            Prepared::Ellipsoid { center, m, least, .. } => {
                // A lower bound first: a point x with ‖x − c‖_M = √q ≥ 1 is at least (√q − 1)·least
                // from the solid (the triangle inequality in the M-norm, and ‖v‖ ≥ ‖v‖_M·least),
                // so a segment whose least q gives a bound above the clearance (by more than the
                // harness' 1e-9·scale tolerance) clears it without the nested golden sections of
                // the exact distance, which cost ~80 % of the property tests' time.
                // And an upper bound: the distance of the segment's point of least q, closer than
                // the clearance (by the same tolerance), is a violation.
                let (q, u) = segment_metric_min(a, b, *center, m);
                let slack = 1e-9 * self.scale;
                if q >= 1.0 && (q.sqrt() - 1.0) * least > c + slack {
                    return false;
                }
                if q < 1.0 || ellipsoid_point_dist(a + (b - a) * u, *center, m) < c - slack {
                    return true;
                }
                self.curved_check(k, a, b).0
            }
            Prepared::Cylinder { .. } | Prepared::Cone { .. } => self.curved_check(k, a, b).0,
        }
    }

    /// Obstacle `k` against segment (a, b): (violated, margin).
    fn obstacle_check(&self, k: usize, a: V3, b: V3) -> (bool, f64) {
        let c = self.scenario.cable_obstacle;
        match &self.prepared[k] {
            Prepared::Sphere { center, reach } => {
                let d = point_segment_dist(*center, a, b);
                (d < *reach, d - reach)
            }
            Prepared::Mesh { tris, .. } => {
                let mut margin = f64::INFINITY;
                let mut violated = false;
                for tri in tris {
                    if let Some(depth) = segment_crosses_triangle(a, b, tri) {
                        violated = true;
                        margin = margin.min(-depth - c);
                    } else {
                        let d = segment_triangle_dist(a, b, tri);
                        violated |= d < c;
                        margin = margin.min(d - c);
                    }
                }
                (violated, margin)
            }
            Prepared::Ellipsoid { .. } | Prepared::Cylinder { .. } | Prepared::Cone { .. } => self.curved_check(k, a, b),
        }
    }

    /// A curved obstacle against segment (a, b): (violated, margin), the margin being the segment's
    /// least signed distance to the solid minus the clearance (for the ellipsoid, inside the solid
    /// the signed distance is replaced by (√q − 1)·scale, q the least value of the quadratic form).
    /// The signed distance of a convex solid is convex along the segment: golden section. Clearance
    /// 0 counts entering the interior.
    pub fn curved_check(&self, k: usize, a: V3, b: V3) -> (bool, f64) {
        let c = self.scenario.cable_obstacle;
        let margin = match &self.prepared[k] {
            Prepared::Ellipsoid { center, m, scale, reach, .. } => {
                let q = segment_metric_min(a, b, *center, m).0;
                if q < 1.0 {
                    (q.sqrt() - 1.0) * scale - c
                } else {
                    let far = point_segment_dist(*center, a, b) - reach;
                    if far > 0.0 {
                        far
                    } else {
                        let f = |u: f64| ellipsoid_point_dist(a + (b - a) * u, *center, m);
                        golden_min(f, 0.0, 1.0).min(f(0.0)).min(f(1.0)) - c
                    }
                }
            }
            Prepared::Cylinder { from, to, radius } => {
                let far = segment_segment_dist(a, b, *from, *to) - radius - c;
                if far > 0.0 {
                    far
                } else {
                    let f = |u: f64| cylinder_sdf(a + (b - a) * u, *from, *to, *radius);
                    golden_min(f, 0.0, 1.0).min(f(0.0)).min(f(1.0)) - c
                }
            }
            Prepared::Cone { cone } => {
                let base = cone.apex + cone.axis * cone.height;
                let far = segment_segment_dist(a, b, cone.apex, base) - cone.height * cone.half_angle.tan() - c;
                if far > 0.0 {
                    far
                } else {
                    let f = |u: f64| cone.sdf(a + (b - a) * u);
                    golden_min(f, 0.0, 1.0).min(f(0.0)).min(f(1.0)) - c
                }
            }
            _ => unreachable!("not a curved obstacle"),
        };
        (margin < 0.0, margin)
    }

    /// Fast feasibility at t of trajectory `traj` (stops at the first violated condition).
    pub fn feasible(&self, traj: usize, t: f64) -> bool {
        let seg = self.segments(traj, t);
        if let Some((lo, hi)) = self.scenario.length {
            for (a, b) in &seg {
                let l = (*b - *a).norm();
                if l < lo || l > hi {
                    return false;
                }
            }
        }
        let cc = self.scenario.cable_cable;
        for &(i, j) in &self.pairs {
            if segment_segment_dist(seg[i].0, seg[i].1, seg[j].0, seg[j].1) < cc {
                return false;
            }
        }
        for (a, b) in &seg {
            for k in 0..self.prepared.len() {
                if self.obstacle_violated(k, *a, *b) {
                    return false;
                }
            }
        }
        true
    }

    /// Every condition at t with its verdict and margin.
    pub fn checks(&self, traj: usize, t: f64) -> Vec<Check> {
        let seg = self.segments(traj, t);
        let mut out = Vec::new();
        if let Some((lo, hi)) = self.scenario.length {
            for (i, (a, b)) in seg.iter().enumerate() {
                let l = (*b - *a).norm();
                out.push(Check {
                    label: format!("cable {} length", i + 1),
                    cables: (i, None),
                    obstacle: None,
                    violated: l < lo || l > hi,
                    margin: (l - lo).min(hi - l),
                });
            }
        }
        let cc = self.scenario.cable_cable;
        for &(i, j) in &self.pairs {
            let d = segment_segment_dist(seg[i].0, seg[i].1, seg[j].0, seg[j].1);
            out.push(Check {
                label: format!("cable {} - cable {}", i + 1, j + 1),
                cables: (i, Some(j)),
                obstacle: None,
                violated: d < cc,
                margin: d - cc,
            });
        }
        for (i, (a, b)) in seg.iter().enumerate() {
            for k in 0..self.prepared.len() {
                let (violated, margin) = self.obstacle_check(k, *a, *b);
                out.push(Check {
                    label: format!("cable {} - {}", i + 1, self.scenario.obstacles[k].name),
                    cables: (i, None),
                    obstacle: Some(k),
                    violated,
                    margin,
                });
            }
        }
        out
    }
}
