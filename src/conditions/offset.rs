//! The exact clearance conditions of the curved obstacles: where a cable a + u·s(λ), u ∈ [0, 1],
//! comes closer than c > 0 to a finite cylinder, a finite cone or an ellipsoid (its start a fixed,
//! or moving with a link: [`Start`]). Each is
//! "∃u ∈ [0, 1] with the cable point in the offset solid K ⊕ B_c", written as sign conditions on
//! polynomials in (u, λ) and decided by [`super::exists`]; the derivations are in
//! `docs/verification.md` ("Curved obstacles with a clearance").
//!
//! The offset solid is split by the feature of K that is nearest:
//! * cylinder (axis from P, unit e, length L, radius r): the side gives the solid cylinder of radius
//!   r + c over 0 < h < L, the caps the solid cylinder of radius r over −c < h < L + c, and each
//!   rim circle the solid torus of tube radius c around it;
//! * cone (apex A, unit axis e, half-angle α, height H, base radius R = H tan α): the lateral
//!   surface (with the solid itself) gives the region whose foot on the generator lies between apex
//!   and rim, within c of it and below the base plane; the apex the ball of radius c; the base the
//!   solid cylinder of radius R over H − c < h < H + c; the rim the solid torus.
//!
//! Every such piece lies within c of K and together they cover K ⊕ B_c, so the union is exact.
//! The ellipsoid, whose offset surface is not a quadric, is handled through Lagrange duality (see
//! [`ellipsoid_clear`]).

use super::algebra::{HVec, H};
use super::exists::{exists, Atom, Clause, VPoly};
use crate::axes::{each_axis, per_axis};
use crate::poly::{Bern, Partition};
use crate::query::EllipsoidFrame;
use nalgebra::Vector3;

type V = Vector3<f64>;

/// Where a cable starts: fixed (a cable from the base), or moving with a link (a routed cable's
/// segment between two links) as its numerators Â over the motion's weight w, like Ŝ.
#[derive(Debug, Clone)]
pub enum Start {
    /// A fixed point.
    Fixed(V),
    /// Â, the start being Â/w.
    Moving([Bern; 3]),
}

impl Start {
    /// The start along the part [lo, hi] of the motion (re-parametrised to [0, 1]).
    fn restrict(&self, lo: f64, hi: f64) -> Start {
        match self {
            Start::Fixed(a) => Start::Fixed(*a),
            Start::Moving(p) => Start::Moving(each_axis(p, |q| q.restrict(lo, hi))),
        }
    }

    /// The numerators of start − `origin` over `w`.
    fn offset(&self, w: &Bern, origin: &V) -> [Bern; 3] {
        match self {
            Start::Fixed(a) => {
                let e = a - origin;
                per_axis(|i| w.scale(e[i]))
            }
            Start::Moving(p) => per_axis(|i| p[i].sub(&w.scale(origin[i]))),
        }
    }

    /// Bounds [lo, hi] on the start's distance to `centre` over the motion, with w within
    /// [w_lo, w_hi]: certified from the Bernstein coefficients for a moving start.
    fn distance(&self, w: &Bern, centre: &V, (w_lo, w_hi): (f64, f64)) -> (f64, f64) {
        match self {
            Start::Fixed(a) => {
                let d = (a - centre).norm();
                (d, d)
            }
            Start::Moving(_) => {
                let n = self.offset(w, centre);
                let hi = n.iter().map(|p| (p.max_abs() + p.err).powi(2)).sum::<f64>().sqrt() / w_lo;
                let len2 = n[0].mul(&n[0]).add(&n[1].mul(&n[1])).add(&n[2].mul(&n[2]));
                let lo = (len2.c.iter().fold(f64::INFINITY, |m, &x| m.min(x)) - len2.err).max(0.0).sqrt() / w_hi;
                (lo, hi)
            }
        }
    }
}

/// The part [u0, u1] of the cable that can come within `reach` of `centre` at any λ (`None`: no
/// part can), from certified bounds on |s| = |Ŝ|/w and on the start's distance d to the centre:
/// a point a + u·s is at least |u·|s| − d| from the centre. Trimming the cable to that part keeps
/// the polynomials' magnitudes (and so their error bounds) at the scale of the obstacle, not of
/// the whole cable.
fn u_range(a: &Start, s: &HVec, w: &Bern, centre: &V, reach: f64) -> Option<(f64, f64)> {
    let w_lo = w.c.iter().fold(f64::INFINITY, |m, &x| m.min(x)) - w.err;
    let w_hi = w.max_abs() + w.err;
    if !(w_lo > 0.0) {
        return Some((0.0, 1.0));
    }
    let s_hi = (0..3).map(|i| (s[i].p.max_abs() + s[i].p.err).powi(2)).sum::<f64>().sqrt() / w_lo;
    let len2 = s[0].p.mul(&s[0].p).add(&s[1].p.mul(&s[1].p)).add(&s[2].p.mul(&s[2].p));
    let len2_lo = len2.c.iter().fold(f64::INFINITY, |m, &x| m.min(x)) - len2.err;
    let s_lo = len2_lo.max(0.0).sqrt() / w_hi;
    let ((d_lo, d_hi), reach) = (a.distance(w, centre, (w_lo, w_hi)), reach * (1.0 + 1e-9) + 1e-12);
    let u0 = if s_hi > 0.0 { ((d_lo - reach) / s_hi * (1.0 - 1e-9)).max(0.0) } else { 0.0 };
    let u1 = if s_lo > 0.0 { ((d_hi + reach) / s_lo * (1.0 + 1e-9)).min(1.0) } else { 1.0 };
    if u0 >= 1.0 || u1 < u0 {
        None
    } else {
        Some((u0, u1))
    }
}

/// The cable part u ∈ [u0, u1] in homogeneous form relative to an origin O, in its own parameter
/// v ∈ [0, 1] (u = u0 + (u1 − u0)·v): X(v) = w·(a − O) + u0·Ŝ + (u1 − u0)·v·Ŝ (w·(a − O) being
/// Â − w·O for a moving start), so that the cable point is O + X/w, with the weight w.
struct CableLine {
    x: [VPoly; 3],
    w: VPoly,
}

impl CableLine {
    fn new(a: &Start, s: &HVec, w: &Bern, origin: &V, (u0, u1): (f64, f64)) -> CableLine {
        let e = a.offset(w, origin);
        let x = per_axis(|i| VPoly::linear(e[i].add(&s[i].p.scale(u0)), s[i].p.scale(u1 - u0)));
        CableLine { x, w: VPoly::of(w.clone()) }
    }

    /// X·d for a constant vector d.
    fn along(&self, d: &V) -> VPoly {
        self.x[0].scale(d[0]).add(&self.x[1].scale(d[1])).add(&self.x[2].scale(d[2]))
    }

    /// Axial coordinate h·w and squared radial distance ρ²·w² about the axis through the origin
    /// with unit direction `axis` (ρ² from two unit normals of the axis, free of the cancellation
    /// in |X|² − h²).
    fn axial(&self, axis: &V) -> (VPoly, VPoly) {
        let h = self.along(axis);
        let n1 = axis.cross(&if axis.x.abs() < 0.6 { V::x() } else { V::y() }).normalize();
        let n2 = axis.cross(&n1);
        let (p1, p2) = (self.along(&n1), self.along(&n2));
        (h, p1.mul(&p1).add(&p2.mul(&p2)))
    }
}

/// `p > 0`.
fn gt(p: &VPoly) -> Atom {
    Atom::new(p, true)
}

/// `p < 0`.
fn lt(p: &VPoly) -> Atom {
    Atom::new(p, false)
}

/// The cable point inside the solid cylinder lo < h < hi, ρ < radius (h, ρ about the axis).
fn slab(h: &VPoly, rho2: &VPoly, w: &VPoly, radius: f64, lo: f64, hi: f64) -> Clause {
    let w2 = w.mul(w);
    vec![gt(&h.sub(&w.scale(lo))), gt(&w.scale(hi).sub(h)), lt(&rho2.sub(&w2.scale(radius * radius)))]
}

/// The cable point within c of the circle of radius r about `axis` centred at `centre`:
/// h² + (ρ − r)² < c² ⇔ W < 2rρ with W = h² + ρ² + r² − c², that is W < 0 or W² < 4r²ρ²
/// (ρ ≥ 0). W < 0 needs c > r and is left out otherwise.
fn torus(a: &Start, s: &HVec, w: &Bern, centre: &V, axis: &V, r: f64, c: f64) -> Vec<Clause> {
    let Some(range) = u_range(a, s, w, centre, r + c) else {
        return vec![];
    };
    let line = CableLine::new(a, s, w, centre, range);
    let (dh, rho2) = line.axial(axis);
    let rho2 = &rho2;
    let w2 = line.w.mul(&line.w);
    let big_w = dh.mul(&dh).add(rho2).add(&w2.scale(r * r - c * c));
    let quartic = big_w.mul(&big_w).sub(&rho2.mul(&w2).scale(4.0 * r * r));
    let mut out = vec![vec![lt(&quartic)]];
    if c > r {
        out.push(vec![lt(&big_w)]);
    }
    out
}

/// Where the cable a + u·s comes closer than c to the solid cylinder (meets its interior when
/// c = 0) from `from` to `to` with
/// radius r.
#[allow(clippy::too_many_arguments)]
pub fn cylinder_near(a: &Start, s: &HVec, w: &Bern, from: &V, to: &V, r: f64, c: f64, tol: f64) -> Partition {
    exists(&|lo, hi| with_restricted(a, s, w, lo, hi, |a, s, w| cylinder_clauses(a, s, w, from, to, r, c)), tol)
}

/// The inputs restricted to λ ∈ [lo, hi] (re-parametrised to [0, 1]), passed to `f`.
fn with_restricted<T>(a: &Start, s: &HVec, w: &Bern, lo: f64, hi: f64, f: impl FnOnce(&Start, &HVec, &Bern) -> T) -> T {
    if lo == 0.0 && hi == 1.0 {
        return f(a, s, w);
    }
    let rs: HVec = per_axis(|i| H { p: s[i].p.restrict(lo, hi), k: s[i].k });
    f(&a.restrict(lo, hi), &rs, &w.restrict(lo, hi))
}

fn cylinder_clauses(a: &Start, s: &HVec, w: &Bern, from: &V, to: &V, r: f64, c: f64) -> Vec<Clause> {
    let len = (to - from).norm();
    let axis = (to - from) / len;
    let mid = 0.5 * (from + to);
    let Some(range) = u_range(a, s, w, &mid, (0.5 * len + c).hypot(r + c)) else {
        return vec![];
    };
    let line = CableLine::new(a, s, w, from, range);
    let (h, rho2) = line.axial(&axis);
    let w = &line.w;
    if c <= 0.0 {
        return vec![slab(&h, &rho2, w, r, 0.0, len)];
    }
    let mut clauses = vec![slab(&h, &rho2, w, r + c, 0.0, len), slab(&h, &rho2, w, r, -c, len + c)];
    clauses.extend(torus(a, s, &line.w.0[0], from, &axis, r, c));
    clauses.extend(torus(a, s, &line.w.0[0], to, &axis, r, c));
    clauses
}

/// Where the cable comes closer than c > 0 to the solid cone, apart from its apex (the ball of
/// radius c around the apex is a point–segment condition, added by the caller).
///
/// In the meridian half-plane (h, ρ) with generator d = (cos α, sin α) and outward normal
/// n = (−sin α, cos α), the lateral piece is 0 < (h, ρ)·d < H/cos α, (h, ρ)·n < c, h < H; each
/// linear condition on ρ is squared with the sign of its other side.
#[allow(clippy::too_many_arguments)]
pub fn cone_near(a: &Start, s: &HVec, w: &Bern, apex: &V, axis: &V, half_angle: f64, height: f64, c: f64, tol: f64) -> Partition {
    exists(&|lo, hi| with_restricted(a, s, w, lo, hi, |a, s, w| cone_clauses(a, s, w, apex, axis, half_angle, height, c)), tol)
}

#[allow(clippy::too_many_arguments)]
fn cone_clauses(a: &Start, s: &HVec, w: &Bern, apex: &V, axis: &V, half_angle: f64, height: f64, c: f64) -> Vec<Clause> {
    let (sa, ca) = half_angle.sin_cos();
    let radius = height * half_angle.tan();
    let slant = height / ca;
    // the cone lies within the ball around its axis' midpoint through the rim
    let mid = apex + axis * (0.5 * height);
    let Some(range) = u_range(a, s, w, &mid, (0.5 * height).hypot(radius) + c) else {
        return vec![];
    };
    let line = CableLine::new(a, s, w, apex, range);
    let (h, rho2) = line.axial(axis);
    let w = &line.w;
    // ρ cos α < c + h sin α
    let l1 = w.scale(c).add(&h.scale(sa));
    // ρ sin α < slant − h cos α
    let l3 = w.scale(slant).sub(&h.scale(ca));
    let lateral = vec![
        gt(&l1),
        lt(&rho2.scale(ca * ca).sub(&l1.mul(&l1))),
        gt(&l3),
        lt(&rho2.scale(sa * sa).sub(&l3.mul(&l3))),
        gt(&w.scale(height).sub(&h)),
    ];
    // ρ sin α > −h cos α: h > 0, or ρ² sin²α > h² cos²α
    let mut ahead = lateral.clone();
    ahead.push(gt(&h));
    let mut beside = lateral;
    beside.push(gt(&rho2.scale(sa * sa).sub(&h.mul(&h).scale(ca * ca))));
    let mut clauses = vec![ahead, beside, slab(&h, &rho2, w, radius, height - c, height + c)];
    clauses.extend(torus(a, s, &line.w.0[0], &(apex + axis * height), axis, radius, c));
    clauses
}

/// Where the cable stays at least c > 0 from the solid ellipsoid (the complement is the violation).
///
/// With principal coordinates z and eigenvalues m_i of M, Lagrange duality for the nearest point
/// gives dist(z, E)² = max over t ≥ 0 of q(t, z) = Σ m_i t z_i²/(1 + m_i t) − t, and since q is
/// convex in z and concave in t, the minimax theorem gives
/// dist(cable, E)² = max_t min_u q(t, z(u)). So the cable is clear iff some t ≥ 0 makes the
/// quadratic α u² + β u + γ = (q − c²)·(positive factor) non-negative on u ∈ [0, 1]: γ ≥ 0,
/// α + β + γ ≥ 0, and the vertex outside (0, 1) or 4αγ − β² ≥ 0. With t = v/(1 − v) and the
/// positive factor (1 − v)⁴ Π(1 + m_i t), α, β and γ are polynomials in (v, λ).
pub fn ellipsoid_clear(a: &Start, s: &HVec, w: &Bern, frame: &EllipsoidFrame, c: f64, tol: f64) -> Partition {
    exists(&|lo, hi| with_restricted(a, s, w, lo, hi, |a, s, w| ellipsoid_clauses(a, s, w, frame, c)), tol)
}

/// The clauses of [`ellipsoid_clear`]; one always-true clause when no part of the cable comes near.
fn ellipsoid_clauses(a: &Start, s: &HVec, w: &Bern, frame: &EllipsoidFrame, c: f64) -> Vec<Clause> {
    let m = frame.m;
    let reach = 1.0 / m.min().max(f64::MIN_POSITIVE).sqrt() + c;
    let Some(range) = u_range(a, s, w, &frame.center, reach) else {
        return vec![vec![Atom::new(&VPoly::in_v(&[1.0]), true)]];
    };
    let line = CableLine::new(a, s, w, &frame.center, range);
    // p_i(v) = (1 − v)(1 + m_i t) = 1 + (m_i − 1) v
    let p: [VPoly; 3] = per_axis(|i| VPoly::in_v(&[1.0, m[i] - 1.0]));
    let v_1mv = VPoly::in_v(&[0.0, 1.0, -1.0]);
    // A_i = m_i v (1 − v) Π_{j≠i} p_j;  B = (v + c²(1 − v)) Π p_j
    let coef: [VPoly; 3] = per_axis(|i| v_1mv.mul(&p[(i + 1) % 3]).mul(&p[(i + 2) % 3]).scale(m[i]));
    let b = VPoly::in_v(&[c * c, 1.0 - c * c]).mul(&p[0]).mul(&p[1]).mul(&p[2]);
    let mut alpha = VPoly::in_v(&[0.0]);
    let mut beta = VPoly::in_v(&[0.0]);
    let mut gamma = b.times(&w.mul(w)).scale(-1.0);
    for (i, coef) in coef.iter().enumerate() {
        let z = line.along(&frame.axes.column(i).into_owned());
        let (z0, z1) = (&z.0[0], &z.0[1]);
        alpha = alpha.add(&coef.times(&z1.mul(z1)));
        beta = beta.add(&coef.times(&z0.mul(z1)).scale(2.0));
        gamma = gamma.add(&coef.times(&z0.mul(z0)));
    }
    let ends = || vec![gt(&gamma), gt(&alpha.add(&beta).add(&gamma))];
    let with = |extra: Atom| {
        let mut c = ends();
        c.push(extra);
        c
    };
    vec![
        with(gt(&beta)),
        with(lt(&alpha.scale(2.0).add(&beta))),
        with(gt(&alpha.mul(&gamma).scale(4.0).sub(&beta.mul(&beta)))),
    ]
}
