//! Exact violation sets of the geometric primitives along a motion, as three-valued partitions of
//! λ ∈ [0, 1]. Each is a finite union of conjunctions of strict polynomial sign conditions; the
//! derivations are in `docs/conditions.md`.
//!
//! Inputs are fractions over the motion's w (see [`super::algebra`]); a segment is a start point
//! plus an offset vector, and a point is given by its offset `e` from the segment's start.

use super::algebra::{hvec_const, Alg, HVec, H};
use crate::poly::{Partition, Truth};
use nalgebra::{Matrix3, Vector3};

/// `p > 0`.
pub const GT: bool = true;
/// `p < 0`.
pub const LT: bool = false;

/// Conjunction of sign conditions, evaluated lazily: once the conjunction is false everywhere the
/// remaining polynomials are not even built, and each sign is classified only where the
/// conditions before it are not already false. `all_of!(from start, tol; …)` conjoins them with
/// the partition `start` (false where the caller needs no answer).
macro_rules! all_of {
    ($tol:expr; $($poly:expr => $side:expr),+ $(,)?) => {
        all_of!(from Partition::constant(Truth::True), $tol; $($poly => $side),+)
    };
    (from $start:expr, $tol:expr; $($poly:expr => $side:expr),+ $(,)?) => {{
        let mut acc: Partition = $start;
        $(
            if !acc.is_all(Truth::False) {
                let h: H = $poly;
                acc = acc.and(&Partition::atom_outside(&h.p, $side, $tol, &acc.where_is(Truth::False)));
            }
        )+
        acc
    }};
}

/// Disjunction of partitions built lazily: stops once the union is true everywhere.
macro_rules! any_of {
    ($($part:expr),+ $(,)?) => {{
        let mut acc = Partition::constant(Truth::False);
        $(
            if !acc.is_all(Truth::True) {
                let p: Partition = $part;
                acc = acc.or(&p);
            }
        )+
        acc
    }};
}
pub(crate) use {all_of, any_of};

/// Where the point at offset `e` from a segment's start lies within distance `r` of the segment
/// start + λ·`s`, λ ∈ [0, 1] (in the metric `g`, or Euclidean). Exact: the closest segment point is
/// the start, the end, or the interior foot of the perpendicular.
pub fn point_segment(alg: &mut Alg, e: &HVec, s: &HVec, r: f64, g: Option<&Matrix3<f64>>, tol: f64) -> Partition {
    if r <= 0.0 {
        return Partition::constant(Truth::False); // no distance is below 0
    }
    let dot = |alg: &mut Alg, a: &HVec, b: &HVec| match g {
        Some(g) => alg.dot_metric(a, g, b),
        None => alg.dot(a, b),
    };
    let r2 = H::constant(r * r);
    let ee = dot(alg, e, e);
    let es = dot(alg, e, s);
    let ss = dot(alg, s, s);
    any_of!(
        all_of!(tol; alg.sub(&ee, &r2) => LT),
        {
            // |e − s|² = |e|² − 2 e·s + |s|²
            let t = alg.sub(&ss, &es.scale(2.0));
            all_of!(tol; { let d = alg.add(&ee, &t); alg.sub(&d, &r2) } => LT)
        },
        all_of!(tol;
            es.clone() => GT,
            alg.sub(&ss, &es) => GT,
            {
                // Gram determinant |e|²|s|² − (e·s)² < r² |s|²
                let gram = alg.sub(&ee.mul(&ss), &es.mul(&es));
                alg.sub(&gram, &ss.scale(r * r))
            } => LT,
        ),
    )
}

/// Which of the four endpoint cases of [`segment_segment`] may hold somewhere, in its order: the
/// second segment's start within the distance of the first segment, the first's start of the
/// second, the second's end of the first, the first's end of the second.
pub type EndCases = [bool; 4];

/// Every endpoint case examined.
pub const ALL_ENDS: EndCases = [true; 4];

/// Where the segments a_i + u·s_i and a_i + r + v·s_j (u, v ∈ [0, 1]) come closer than `c`.
/// `r` is the offset between the two starts. Exact: the closest pair is interior to both (the
/// common perpendicular) or has an endpoint on one of them. When the two lines are parallel
/// throughout (|s_i × s_j|² zero within its error bound) the interior case cannot give the
/// minimum and is skipped. `ends` says which endpoint cases may hold somewhere (see
/// [`EndCases`]); one known false everywhere is skipped.
pub fn segment_segment(alg: &mut Alg, r: &HVec, si: &HVec, sj: &HVec, c: f64, ends: EndCases, tol: f64) -> Partition {
    if c <= 0.0 {
        return Partition::constant(Truth::False); // no distance is below 0
    }
    let neg_r: HVec = [r[0].scale(-1.0), r[1].scale(-1.0), r[2].scale(-1.0)];
    let never = || Partition::constant(Truth::False);
    any_of!(
        if ends[0] { point_segment(alg, r, si, c, None, tol) } else { never() },
        if ends[1] { point_segment(alg, &neg_r, sj, c, None, tol) } else { never() },
        if ends[2] { let e = alg.vadd(r, sj); point_segment(alg, &e, si, c, None, tol) } else { never() },
        if ends[3] { let e = alg.vsub(si, r); point_segment(alg, &e, sj, c, None, tol) } else { never() },
        {
            let n = alg.cross(si, sj);
            let d = alg.dot(&n, &n);
            if d.p.max_abs() <= d.p.err {
                Partition::constant(Truth::False)
            } else {
                // the lines' distance first (it implies d > 0, and usually decides alone), then
                // the feet u/d and v/d of the common perpendicular inside both segments
                let line = all_of!(tol; { let rn = alg.dot(r, &n); alg.sub(&rn.mul(&rn), &d.scale(c * c)) } => LT);
                let foot = |alg: &mut Alg, acc: Partition, s: &HVec| {
                    if acc.is_all(Truth::False) {
                        return acc;
                    }
                    let rs = alg.cross(r, s);
                    let u = alg.dot(&rs, &n);
                    acc.and(&all_of!(tol; u.clone() => GT, alg.sub(&d, &u) => GT))
                };
                let on_i = foot(alg, line, sj);
                foot(alg, on_i, si)
            }
        },
    )
}

/// Where the segment a + λ·s comes closer than `c` to the triangle, or crosses it, given by its
/// face only (the edges are checked separately, once per mesh edge): an end projects inside the
/// triangle within `c` of its plane, or the segment crosses the triangle's interior. The start `a`
/// is fractions like `s`: constant for a cable from the base, moving for a segment that starts on
/// a link.
pub fn segment_face(alg: &mut Alg, a: &HVec, s: &HVec, tri: &[Vector3<f64>; 3], c: f64, tol: f64) -> Partition {
    let n = (tri[1] - tri[0]).cross(&(tri[2] - tri[0]));
    let nn = n.norm_squared();
    let hn = hvec_const(&n);
    let m: [Vector3<f64>; 3] = std::array::from_fn(|k| n.cross(&(tri[(k + 1) % 3] - tri[k])));
    // a fixed start's own tests are numbers (the common case: a cable from the base)
    let fixed: Option<Vector3<f64>> = a.iter().all(|h| h.k == 0 && h.p.c.len() == 1).then(|| Vector3::new(a[0].p.c[0], a[1].p.c[0], a[2].p.c[0]));
    // the start's offsets from the corners, d_k = a − tri_k, and what the tests read of them:
    // m_k·d_k (inside edge k where positive) and n·d_0 (the height over the plane)
    let mut d: [HVec; 3] = std::array::from_fn(|_| hvec_const(&Vector3::zeros()));
    let mut inside_start: [H; 3] = std::array::from_fn(|_| H::constant(0.0));
    for k in 0..3 {
        match fixed {
            Some(p) => inside_start[k] = H::constant(m[k].dot(&(p - tri[k]))),
            None => {
                for i in 0..3 {
                    d[k][i] = alg.sub(&a[i], &H::constant(tri[k][i]));
                }
                inside_start[k] = alg.dot(&hvec_const(&m[k]), &d[k]);
            }
        }
    }
    let o_a = match fixed {
        Some(p) => H::constant(n.dot(&(p - tri[0]))),
        None => alg.dot(&hn, &d[0]),
    };
    let too_close = |alg: &mut Alg, h: &H| alg.sub(&h.mul(h), &H::constant(c * c * nn));
    let start_near = match fixed {
        Some(_) => {
            let value = |h: &H| h.p.c[0];
            let near = (0..3).all(|k| value(&inside_start[k]) > 0.0) && value(&o_a).powi(2) < c * c * nn;
            Partition::constant(if near { Truth::True } else { Truth::False })
        }
        None => all_of!(tol;
            inside_start[0].clone() => GT,
            inside_start[1].clone() => GT,
            inside_start[2].clone() => GT,
            too_close(alg, &o_a) => LT,
        ),
    };
    any_of!(
        // the start within c of the plane, inside all three edges
        start_near,
        {
            // the moving end a + s: the same, m_k·(d_k + s) and n·(d_0 + s)
            let edge_atom = |alg: &mut Alg, k: usize| {
                let ms = alg.dot(&hvec_const(&m[k]), s);
                alg.add(&ms, &inside_start[k])
            };
            all_of!(tol;
                edge_atom(alg, 0) => GT,
                edge_atom(alg, 1) => GT,
                edge_atom(alg, 2) => GT,
                { let ns = alg.dot(&hn, s); let h = alg.add(&ns, &o_a); too_close(alg, &h) } => LT,
            )
        },
        {
            // crossing: the ends on opposite sides of the plane, the line through the triangle
            if o_a.p.c.iter().all(|v| *v == 0.0) {
                Partition::constant(Truth::False) // the start stays in the plane: the tests above
            } else {
                let ns = alg.dot(&hn, s);
                let o_x = alg.add(&ns, &o_a);
                let side = match fixed {
                    Some(_) => all_of!(tol; o_x => o_a.p.c[0] < 0.0),
                    None => all_of!(tol; o_a.mul(&o_x) => LT),
                };
                if side.is_all(Truth::False) {
                    side
                } else {
                    // (tri_k − a) × (tri_{k+1} − a) = d_k × d_{k+1}, against s
                    let vol = |alg: &mut Alg, k: usize| {
                        let v = match fixed {
                            Some(p) => hvec_const(&(tri[k] - p).cross(&(tri[(k + 1) % 3] - p))),
                            None => alg.cross(&d[k], &d[(k + 1) % 3]),
                        };
                        alg.dot(&v, s)
                    };
                    let through = any_of!(
                        all_of!(tol; vol(alg, 0) => GT, vol(alg, 1) => GT, vol(alg, 2) => GT),
                        all_of!(tol; vol(alg, 0) => LT, vol(alg, 1) => LT, vol(alg, 2) => LT),
                    );
                    side.and(&through)
                }
            }
        },
    )
}

/// A solid truncated cone {x : (x−A)·u ≥ |x−A| cos α, (x−A)·u ≤ H}.
#[derive(Debug, Clone, Copy)]
pub struct ConeSolid {
    /// Apex A.
    pub apex: Vector3<f64>,
    /// Unit axis u.
    pub axis: Vector3<f64>,
    /// cos² α.
    pub cos2: f64,
    /// Height H.
    pub height: f64,
}

/// Where the segment a + λ·s meets the solid cone. Exact: with g(λ) = (x−A)·u and
/// f(λ) = g² − cos²α |x−A|² (a quadratic), the segment meets the cone iff the maximum of f over
/// the λ ∈ [0, 1] with 0 ≤ g ≤ H is positive; that maximum is at λ = 0, λ = 1, where g = H, or
/// at the vertex of f (f ≤ 0 where g = 0). The offset e = a − A of the start is fractions like
/// `s` (constant for a fixed start, moving for a segment that starts on a link), and so are the
/// quadratic's coefficients f0, f1, f2 and g's, g0 and g1.
pub fn segment_cone(alg: &mut Alg, e: &HVec, s: &HVec, cone: &ConeSolid, tol: f64) -> Partition {
    let (hgt, k2) = (cone.height, cone.cos2);
    let axis = hvec_const(&cone.axis);
    let g0 = alg.dot(&axis, e);
    let ee = alg.dot(e, e);
    let f0 = alg.sub(&g0.mul(&g0), &ee.scale(k2));
    let g1 = alg.dot(&axis, s);
    let es = alg.dot(e, s);
    let ss = alg.dot(s, s);
    let f1 = alg.sub(&g1.mul(&g0).scale(2.0), &es.scale(2.0 * k2));
    let f2 = alg.sub(&g1.mul(&g1), &ss.scale(k2));
    let d = alg.sub(&H::constant(hgt), &g0);
    let fixed = [&f0, &g0, &d].iter().all(|h| h.k == 0 && h.p.c.len() == 1);
    let start_inside = if fixed {
        let near = f0.p.c[0] > 0.0 && g0.p.c[0] > 0.0 && d.p.c[0] > 0.0;
        Partition::constant(if near { Truth::True } else { Truth::False })
    } else {
        all_of!(tol; f0.clone() => GT, g0.clone() => GT, d.clone() => GT)
    };
    any_of!(
        start_inside,
        all_of!(tol;
            { let t = alg.add(&f1, &f2); alg.add(&t, &f0) } => GT,
            alg.add(&g1, &g0) => GT,
            alg.sub(&d, &g1) => GT,
        ),
        all_of!(tol;
            g1.mul(&d) => GT,
            { let gd = g1.mul(&d); alg.sub(&g1.mul(&g1), &gd) } => GT,
            {
                let t = alg.add(&g1.mul(&g1).mul(&f0), &f1.mul(&g1).mul(&d));
                alg.add(&t, &f2.mul(&d).mul(&d))
            } => GT,
        ),
        all_of!(tol;
            f2.clone() => LT,
            f1.clone() => GT,
            alg.add(&f1, &f2.scale(2.0)) => LT,
            alg.sub(&f2.mul(&f0).scale(4.0), &f1.mul(&f1)) => LT,
            alg.sub(&f2.mul(&g0).scale(2.0), &f1.mul(&g1)) => LT,
            { let below = alg.sub(&g0, &H::constant(hgt)); alg.sub(&f2.mul(&below).scale(2.0), &f1.mul(&g1)) } => GT,
        ),
    )
}
