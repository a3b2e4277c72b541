//! Motions as rational polynomial curves in one parameter λ ∈ [0, 1]: the form every exact
//! condition is written in.
//!
//! A [`Motion`] gives p(λ) = P̂(λ)/w(λ) and R(λ) = M̂(λ)/w(λ), where P̂, M̂ and w are polynomials in
//! Bernstein form and w > 0. The rotation comes from a quaternion polynomial N(λ):
//! M̂ = the quadratic-form rotation numerator of N and w = |N|², so R(λ) is exactly a rotation for
//! every λ whatever the rounding of N's coefficients.
//!
//! * A trajectory (thesis §4.2): λ = τ. The slerp with T = tan(tθ/2) = hτ, h = tan(θ/2), is
//!   Q ∝ Qs + τ (Qe − Qs cos θ)/cos²(θ/2) − τ² h² Qs (a form with no division by sin θ, stable
//!   as θ → 0), and t = 2·atan(hτ)/θ.
//! * A ray in x, y or z: λ maps linearly onto the range; w = 1.
//! * A ray in an angle of tilt-and-torsion: the range is cut into pieces at most [`ANGLE_PIECE`]
//!   (π/8) wide; on a piece starting at γ0 the angle is γ0 + 2·atan(hλ), and a rotation by ψ about an axis k is the
//!   quaternion (1, tan(ψ/2)·k) up to scale.

use super::pose::{Coord, Pose};
use super::trajectory::{Orientation, Segment, Trajectory, Translation};
use crate::axes::{each_axis, per_axis};
use crate::poly::{binomial, Bern};
use nalgebra::{Quaternion, UnitQuaternion};
use std::f64::consts::FRAC_PI_2;

/// Widest piece of an angle ray. On a piece of width ψ the rotation numerator and the weight grow
/// like powers of (1 + h²λ²), h = tan(ψ/2): at ψ = π/2
/// (h = 1) the wrench conditions' high powers of w span orders of magnitude over [0, 1] and their
/// sign tests stayed undecided over most of a piece (Robocrane φ-rays: uncertain over half the
/// range); at π/8 (h ≈ 0.2) they decide, and the ray is faster for it.
pub const ANGLE_PIECE: f64 = FRAC_PI_2 / 4.0;

/// How λ ∈ [0, 1] maps to the parameter a user sees.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Param {
    /// A stretch [t0, t1] of a trajectory's t that rotates by ψ at a constant rate:
    /// t = t0 + (t1 − t0)·2·atan(hλ)/ψ with h = tan(ψ/2) (t = t0 + (t1 − t0)·λ when ψ = 0), or,
    /// `centred`, t = t0 + (t1 − t0)·(½ + atan((2λ − 1)h)/ψ); or a part of such a stretch
    /// (`within`).
    Trajectory {
        /// The piece's rotation angle ψ.
        psi: f64,
        /// tan(ψ/2).
        h: f64,
        /// The whole trajectory's t at λ = 0.
        t0: f64,
        /// The whole trajectory's t at λ = 1 of the stretch.
        t1: f64,
        /// The part [a, b] of the stretch's λ this motion covers: (0, 1) but for a part
        /// ([`Motion::part`]), whose λ' ∈ [0, 1] is the stretch's a + (b − a)·λ'.
        within: (f64, f64),
        /// Whether the angle runs from the stretch's middle (λ = ½) rather than its start: the
        /// quaternion (1 − λ)Q0 + λQ1 of a slerp in place ([`Motion::trajectory`]).
        centred: bool,
    },
    /// A linear coordinate: value = lo + (hi − lo)·λ.
    Linear {
        /// Value at λ = 0.
        lo: f64,
        /// Value at λ = 1.
        hi: f64,
    },
    /// An angle: value = start + 2·atan(hλ).
    Angle {
        /// Value at λ = 0.
        start: f64,
        /// Value at λ = 1.
        end: f64,
        /// tan((end − start) / 2).
        h: f64,
    },
}

impl Param {
    /// The user-facing value (t for trajectories) at λ; exactly the range's ends at λ = 0 and 1.
    pub fn value(&self, lam: f64) -> f64 {
        match *self {
            Param::Trajectory { psi, h, t0, t1, within: (a, b), centred } => {
                let lam = if lam >= 1.0 { b } else { a + (b - a) * lam };
                let local = if psi < 1e-9 || lam <= 0.0 || lam >= 1.0 {
                    lam.clamp(0.0, 1.0)
                } else if centred {
                    (0.5 + (h * (2.0 * lam - 1.0)).atan() / psi).clamp(0.0, 1.0)
                } else {
                    (2.0 * (h * lam).atan() / psi).clamp(0.0, 1.0)
                };
                if local >= 1.0 {
                    t1
                } else {
                    t0 + (t1 - t0) * local
                }
            }
            Param::Linear { lo, hi } => lo * (1.0 - lam) + hi * lam,
            Param::Angle { start, end, h } => {
                if lam >= 1.0 {
                    end
                } else {
                    (start + 2.0 * (h * lam).atan()).min(end)
                }
            }
        }
    }

    /// An upper bound on |d value / dλ| over [0, 1].
    pub fn max_slope(&self) -> f64 {
        match *self {
            // the slope 2h/(ψ(1 + h²x²)), x = λ or 2λ − 1, is at most 2h/ψ
            Param::Trajectory { psi, h, t0, t1, within: (a, b), .. } => {
                let span = (t1 - t0) * (b - a);
                if psi < 1e-9 {
                    span
                } else {
                    span * 2.0 * h / psi
                }
            }
            Param::Linear { lo, hi } => (hi - lo).abs(),
            Param::Angle { h, .. } => 2.0 * h,
        }
    }
}

/// A pose moving with λ ∈ [0, 1] as a rational polynomial curve.
#[derive(Debug, Clone)]
pub struct Motion {
    /// P̂ = p·w, per axis.
    pub position: [Bern; 3],
    /// M̂ = R·w, row-major.
    pub rotation: [[Bern; 3]; 3],
    /// The common positive denominator w.
    pub weight: Bern,
    /// λ → user parameter.
    pub param: Param,
    /// The turn about one fixed axis the rotation encloses, with its rate known exactly (a
    /// CASPR spline's turn); `None`: the rates come from the polynomials.
    pub spin: Option<Spin>,
}

/// A turn about one fixed axis at a rate known exactly, beside the rotation that encloses it
/// (`super::turn`): the angular velocity is ω = (dθ/dλ)·λ̇·`axis` and its acceleration
/// α = ((dθ/dλ)·λ̈ + (d²θ/dλ²)·λ̇²)·`axis`, whatever the rounding of the enclosure.
#[derive(Debug, Clone)]
pub struct Spin {
    /// The axis in the world frame (unit).
    pub axis: nalgebra::Vector3<f64>,
    /// The same axis in the body's frame: Rᵀ·axis, which Rodrigues' enclosure R0·(I + S·K +
    /// (1 − C)·K²) of a turn about R0·`body` keeps exactly (K·body = 0), whatever C and S.
    pub body: nalgebra::Vector3<f64>,
    /// dθ/dλ, the angle's rate per unit of the motion's parameter.
    pub rate: Bern,
}

/// A quaternion whose components are polynomials in λ (ascending monomial coefficients).
pub(crate) type QuatPoly = [Vec<f64>; 4];

fn poly_mul(a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut c = vec![0.0; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            c[i + j] += x * y;
        }
    }
    c
}

fn poly_add(a: &[f64], b: &[f64], sign: f64) -> Vec<f64> {
    (0..a.len().max(b.len()))
        .map(|k| a.get(k).copied().unwrap_or(0.0) + sign * b.get(k).copied().unwrap_or(0.0))
        .collect()
}

/// Hamilton product of quaternion polynomials (w, x, y, z).
pub(crate) fn quat_mul(a: &QuatPoly, b: &QuatPoly) -> QuatPoly {
    let m = |i: usize, j: usize| poly_mul(&a[i], &b[j]);
    let sum = |terms: [(f64, Vec<f64>); 4]| {
        terms.iter().fold(vec![0.0], |acc, (s, p)| poly_add(&acc, p, *s))
    };
    [
        sum([(1.0, m(0, 0)), (-1.0, m(1, 1)), (-1.0, m(2, 2)), (-1.0, m(3, 3))]),
        sum([(1.0, m(0, 1)), (1.0, m(1, 0)), (1.0, m(2, 3)), (-1.0, m(3, 2))]),
        sum([(1.0, m(0, 2)), (-1.0, m(1, 3)), (1.0, m(2, 0)), (1.0, m(3, 1))]),
        sum([(1.0, m(0, 3)), (1.0, m(1, 2)), (-1.0, m(2, 1)), (1.0, m(3, 0))]),
    ]
}

/// A constant quaternion polynomial.
pub(crate) fn quat_const(q: &UnitQuaternion<f64>) -> QuatPoly {
    let q = q.quaternion();
    [vec![q.w], vec![q.i], vec![q.j], vec![q.k]]
}

/// Rotation by an angle growing with λ about coordinate axis `axis` (0 = x, 1 = y, 2 = z):
/// (1, h·λ·e_axis), or its inverse when `inverse`.
fn quat_axis_ramp(axis: usize, h: f64, inverse: bool) -> QuatPoly {
    let mut e = nalgebra::Vector3::zeros();
    e[axis] = if inverse { -1.0 } else { 1.0 };
    ramp_about(&e, h)
}

/// Rotation by the angle 2·atan(hλ) about the unit vector `axis`: the quaternion (1, h·λ·axis) up
/// to scale.
pub(crate) fn ramp_about(axis: &nalgebra::Vector3<f64>, h: f64) -> QuatPoly {
    [vec![1.0], vec![0.0, h * axis.x], vec![0.0, h * axis.y], vec![0.0, h * axis.z]]
}

/// Rotation numerator M̂ and weight w = |N|² of a quaternion polynomial. Terms that vanish
/// exactly in all four components are dropped first: a slerp that does not turn (Q1 = Q0, as
/// along every translation) has a constant N, so w and M̂ are constants and the positions keep
/// the translation's own degree rather than four more.
fn rotation_of(n: &QuatPoly) -> ([[Bern; 3]; 3], Bern) {
    let mut len = n.iter().map(Vec::len).max().unwrap_or(0);
    while len > 1 && n.iter().all(|c| c.get(len - 1).is_none_or(|&v| v == 0.0)) {
        len -= 1;
    }
    let [s, x, y, z] = [0, 1, 2, 3].map(|k| Bern::from_monomial(&n[k][..len.min(n[k].len())]));
    let (ss, xx, yy, zz) = (s.mul(&s), x.mul(&x), y.mul(&y), z.mul(&z));
    let (xy, xz, yz) = (x.mul(&y), x.mul(&z), y.mul(&z));
    let (sx, sy, sz) = (s.mul(&x), s.mul(&y), s.mul(&z));
    let rot = [
        [ss.add(&xx).sub(&yy).sub(&zz), xy.sub(&sz).scale(2.0), xz.add(&sy).scale(2.0)],
        [xy.add(&sz).scale(2.0), ss.sub(&xx).add(&yy).sub(&zz), yz.sub(&sx).scale(2.0)],
        [xz.sub(&sy).scale(2.0), yz.add(&sx).scale(2.0), ss.sub(&xx).sub(&yy).add(&zz)],
    ];
    let w = ss.add(&xx).add(&yy).add(&zz);
    (rot, w)
}

fn translation_bernstein(tr: &Translation) -> [Bern; 3] {
    match tr {
        Translation::Polynomial(c) => per_axis(|i| Bern::from_monomial(&c[i])),
        Translation::Bezier(points) => per_axis(|i| Bern::from_bernstein(points.iter().map(|p| p[i]).collect())),
        Translation::Line(a, b) => per_axis(|i| Bern::from_bernstein(vec![a[i], b[i]])),
    }
}

/// The cut points 0 = t_0 < … < t_n = 1 of a slerp of angle θ: equal pieces of at most π/2 of
/// rotation, refined where cos(tθ/2) halves (t = 2·acos(2^−j)/θ), so that on every piece the
/// Möbius denominator 1 − T0·hλ = cos(tθ/2)/(cos(t0θ/2)·cos(ψ/2)) stays within a factor of about
/// 3 of 1: near θ = π the translation, polynomial in τ = tan(tθ/2)/tan(θ/2), runs almost wholly
/// in a short stretch before t = 1, and these cuts follow it.
fn slerp_cuts(theta: f64) -> Vec<f64> {
    let pieces = ((theta / FRAC_PI_2).ceil() as usize).max(1);
    let mut cuts: Vec<f64> = (0..=pieces).map(|k| k as f64 / pieces as f64).collect();
    if theta > 1e-9 {
        let mut j = 1;
        while 0.5f64.powi(j) > (theta / 2.0).cos() && j < 60 {
            cuts.push(2.0 * 0.5f64.powi(j).acos() / theta);
            j += 1;
        }
    }
    crate::order::sort_by_key(&mut cuts, |x| *x);
    cuts.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    cuts
}

/// p^k.
fn power(p: &Bern, k: usize) -> Bern {
    (0..k).fold(Bern::constant(1.0), |acc, _| acc.mul(p))
}

impl Motion {
    /// The motion with position `position` (polynomials) and rotation from the quaternion
    /// polynomial `n`.
    pub(crate) fn from_parts(position: [Bern; 3], n: &QuatPoly, param: Param) -> Motion {
        let (rotation, weight) = rotation_of(n);
        let position = position.map(|p| p.mul(&weight));
        Motion { position, rotation, weight, param, spin: None }
    }

    /// The motion with position `position`/`den` (den > 0 on [0, 1]) and rotation from `n`.
    fn from_rational(position: [Bern; 3], den: Bern, n: &QuatPoly, param: Param) -> Motion {
        let (rotation, w) = rotation_of(n);
        let position = position.map(|p| p.mul(&w));
        let rotation = rotation.map(|row| row.map(|m| m.mul(&den)));
        Motion { position, rotation, weight: w.mul(&den), param, spin: None }
    }

    /// The motions of a trajectory: for each of its pieces (format 2), one per stretch of at most
    /// π/2 of rotation, so that long slerps (up to π) keep small, well-conditioned coefficients.
    pub fn trajectory(traj: &Trajectory) -> Vec<Motion> {
        traj.pieces().iter().enumerate().flat_map(|(k, seg)| Motion::segment(seg, traj.piece_span(k))).collect()
    }

    /// The motions of one piece covering `span` of its trajectory's t.
    ///
    /// On the stretch t ∈ [t0, t1] of the piece's own t with rotation ψ = θ(t1 − t0) and h = tan(ψ/2), λ is the tan-half-
    /// angle parameter of the piece: t = t0 + 2·atan(hλ)/θ. The rotation is the slerp from Q(t0) to
    /// Q(t1), N(λ) = Q0 + λ·(Q1 − Q0 cos ψ)/cos²(ψ/2) − λ²h²Q0 (as for the whole trajectory), and
    /// τ(λ) = tan(t θ/2)/tan(θ/2) is the Möbius map (T0 + hλ)/(tan(θ/2)·(1 − T0·hλ)),
    /// T0 = tan(t0 θ/2), so a translation of degree d in τ becomes P̃(λ)/D(λ)^d with
    /// D = 1 − T0·hλ > 0 (homogeneous Bernstein substitution).
    fn segment(seg: &Segment, [from, to]: [f64; 2]) -> Vec<Motion> {
        let (qs, qe) = match &seg.orientation {
            Orientation::Slerp(qs, qe) => (qs, qe),
            Orientation::Turn { from: q0, axis, angle, profile } => return Motion::turn(&seg.translation, q0, axis, *angle, *profile, [from, to]),
        };
        let theta = seg.theta();
        let translation = translation_bernstein(&seg.translation);
        if translation.iter().all(|p| p.c.iter().all(|&c| c == p.c[0])) {
            return Motion::slerp_in_place(seg, translation.map(|p| Bern::constant(p.c[0])), [from, to]);
        }
        let cuts = slerp_cuts(theta);
        let pieces = cuts.len() - 1;
        let whole = |t: f64| if t >= 1.0 { to } else { from + (to - from) * t };
        let (s, e) = (qs.quaternion(), qe.quaternion());
        // Q(t) on the slerp's great circle (signs as given, so consecutive ends are ψ apart)
        let q_at = |t: f64| -> Quaternion<f64> {
            if t <= 0.0 {
                *s
            } else if t >= 1.0 {
                *e
            } else {
                seg.pose_at(t).rotation.into_inner()
            }
        };
        (0..pieces)
            .map(|k| {
                let (t0, t1) = (cuts[k], cuts[k + 1]);
                let psi = theta * (t1 - t0);
                let (q0, q1) = (q_at(t0), q_at(t1));
                let h = (psi / 2.0).tan();
                let lin: Quaternion<f64> = (q1 - q0 * psi.cos()) / (psi / 2.0).cos().powi(2);
                let quad: Quaternion<f64> = -q0 * (h * h);
                let n: QuatPoly = [
                    vec![q0.w, lin.w, quad.w],
                    vec![q0.i, lin.i, quad.i],
                    vec![q0.j, lin.j, quad.j],
                    vec![q0.k, lin.k, quad.k],
                ];
                let param = Param::Trajectory { psi, h, t0: whole(t0), t1: whole(t1), within: (0.0, 1.0), centred: false };
                if pieces == 1 {
                    return Motion::from_parts(translation.clone(), &n, param);
                }
                // τ(λ) = num/den with num = (T0 + hλ)/tan(θ/2), den = 1 − T0·hλ (both linear)
                let (big_t0, tan_half) = ((t0 * theta / 2.0).tan(), (theta / 2.0).tan());
                let num = Bern::from_bernstein(vec![big_t0 / tan_half, (big_t0 + h) / tan_half]);
                let den = Bern::from_bernstein(vec![1.0, 1.0 - big_t0 * h]);
                let rest = den.sub(&num);
                let position = translation.clone().map(|p| {
                    // Σ c_j C(d,j) τ^j (1−τ)^(d−j) · den^d = Σ c_j C(d,j) num^j (den − num)^(d−j)
                    let d = p.degree();
                    let mut acc = Bern::constant(0.0);
                    for j in 0..=d {
                        let mut term = Bern::constant(p.c[j] * binomial(d, j));
                        for _ in 0..j {
                            term = term.mul(&num);
                        }
                        for _ in j..d {
                            term = term.mul(&rest);
                        }
                        acc = acc.add(&term);
                    }
                    acc
                });
                // every coordinate's numerator over the common den^degree
                let degree = translation.iter().map(Bern::degree).max().unwrap_or(0);
                let position = per_axis(|i| position[i].mul(&power(&den, degree - translation[i].degree())));
                Motion::from_rational(position, power(&den, degree), &n, param)
            })
            .collect()
    }

    /// The motions of a piece `seg` that slerps (quaternion angle θ) at the fixed `position`,
    /// covering `span` of the trajectory's t: pieces of at most π/2 of quaternion angle ψ, each
    /// N(λ) = (1 − λ)Q0 + λQ1 — linear in λ, so that the rotation numerator and the weight have
    /// degree 2, half the degree of a slerp that also translates, and w = |N|² stays within
    /// [cos²(ψ/2), 1]. The quaternion angle from Q0 is ψ/2 + atan((2λ − 1)·tan(ψ/2)): the
    /// `centred` form of [`Param::Trajectory`]. (A translation polynomial in τ, the tangent of the
    /// half angle, is not rational in this λ: moving slerps keep [`Motion::segment`]'s form.)
    fn slerp_in_place(seg: &Segment, position: [Bern; 3], [from, to]: [f64; 2]) -> Vec<Motion> {
        let theta = seg.theta();
        let pieces = ((theta / FRAC_PI_2).ceil() as usize).max(1);
        let whole = |t: f64| if t >= 1.0 { to } else { from + (to - from) * t };
        // Q at the end of piece k on the slerp's great circle (signs as given)
        let q_at = |k: usize| -> Quaternion<f64> {
            match (&seg.orientation, k) {
                (Orientation::Slerp(qs, _), 0) => *qs.quaternion(),
                (Orientation::Slerp(_, qe), k) if k == pieces => *qe.quaternion(),
                _ => seg.pose_at(k as f64 / pieces as f64).rotation.into_inner(),
            }
        };
        let psi = theta / pieces as f64;
        (0..pieces)
            .map(|k| {
                let (q0, q1) = (q_at(k), q_at(k + 1));
                let d = q1 - q0;
                let n: QuatPoly = [vec![q0.w, d.w], vec![q0.i, d.i], vec![q0.j, d.j], vec![q0.k, d.k]];
                let (t0, t1) = (whole(k as f64 / pieces as f64), whole((k + 1) as f64 / pieces as f64));
                Motion::from_parts(position.clone(), &n, Param::Trajectory { psi, h: (psi / 2.0).tan(), t0, t1, within: (0.0, 1.0), centred: true })
            })
            .collect()
    }

    /// The motions of a piece that turns (`super::turn`): one per stretch of the turn's
    /// polynomial enclosure, λ linear in the piece's t (and so in time), the translation (a
    /// polynomial in t) restricted to the stretch, the rotation R0·(I + S(λ)K + (1 − C(λ))K²)
    /// (R0 of `q0`, K the axis's cross-product matrix, C and S the stretch's cos θ and sin θ)
    /// over the weight 1.
    fn turn(translation: &Translation, q0: &UnitQuaternion<f64>, axis: &nalgebra::Unit<nalgebra::Vector3<f64>>, angle: f64, profile: super::Profile, [from, to]: [f64; 2]) -> Vec<Motion> {
        let whole = translation_bernstein(translation);
        let at = |t: f64| if t >= 1.0 { to } else { from + (to - from) * t };
        // R = R0 (I + sin θ K + (1 − cos θ) K²), K the cross-product matrix of the axis
        let k = axis.into_inner().cross_matrix();
        let (r0, k2) = (q0.to_rotation_matrix().into_inner(), k * k);
        let (r0k, r0k2) = (r0 * k, r0 * k2);
        super::turn::turn_stretches(angle, profile)
            .iter()
            .map(|s| {
                let position = each_axis(&whole, |p| p.restrict(s.a, s.b));
                let (c, sn, one) = (Bern::from_monomial(&s.cos), Bern::from_monomial(&s.sin), Bern::constant(1.0));
                let rotation = per_axis(|i| per_axis(|j| Bern::linear_combination(&[(&one, r0[(i, j)] + r0k2[(i, j)]), (&sn, r0k[(i, j)]), (&c, -r0k2[(i, j)])])));
                // θ = angle·s(t) on the stretch, t = a + (b − a)λ: its rate in λ, exactly
                let rate = super::turn::angle_on(angle, profile, s.a, s.b).derivative();
                let spin = Some(Spin { axis: q0 * axis.into_inner(), body: axis.into_inner(), rate });
                Motion { position, rotation, weight: Bern::constant(1.0), param: Param::Trajectory { psi: 0.0, h: 0.0, t0: at(s.a), t1: at(s.b), within: (0.0, 1.0), centred: false }, spin }
            })
            .collect()
    }

    /// The motions of a ray: `coord` runs from `lo` to `hi`, the other coordinates stay at
    /// `pose`'s (x, y, z, φ, θ, σ). Linear coordinates give one piece; angles one piece per
    /// [`ANGLE_PIECE`] or less of range.
    pub fn ray(pose: &Pose, coord: Coord, lo: f64, hi: f64) -> Vec<Motion> {
        Motion::ray_through(pose.coords(), coord, lo, hi)
    }

    /// The motions of a ray through the coordinates `c` (x, y, z, φ, θ, σ) as given — not the
    /// canonical angles of their rotation, which may differ: a lattice's rays keep the user's
    /// angle triple.
    pub fn ray_through(c: [f64; 6], coord: Coord, lo: f64, hi: f64) -> Vec<Motion> {
        let pose = Pose::from_coords(c);
        if !coord.is_angle() {
            let i = coord.index();
            let position = per_axis(|k| {
                if k == i {
                    Bern::from_bernstein(vec![lo, hi])
                } else {
                    Bern::constant(c[k])
                }
            });
            return vec![Motion::from_parts(position, &quat_const(&pose.rotation), Param::Linear { lo, hi })];
        }
        let pieces = (((hi - lo).abs() / ANGLE_PIECE).ceil() as usize).max(1);
        let position = per_axis(|k| Bern::constant(c[k]));
        (0..pieces)
            .map(|k| {
                let start = lo + (hi - lo) * k as f64 / pieces as f64;
                let end = if k + 1 == pieces { hi } else { lo + (hi - lo) * (k + 1) as f64 / pieces as f64 };
                let width = end - start;
                let h = (width / 2.0).tan();
                let mut at_start = c;
                at_start[coord.index()] = start;
                let [phi, theta, sigma] = [at_start[3], at_start[4], at_start[5]];
                let qz = |a: f64| quat_const(&UnitQuaternion::from_axis_angle(&nalgebra::Vector3::z_axis(), a));
                let qy = |a: f64| quat_const(&UnitQuaternion::from_axis_angle(&nalgebra::Vector3::y_axis(), a));
                // q = qz(φ)·qy(θ)·qz(σ−φ), with the varied angle advanced by ψ(λ)
                let n = match coord {
                    Coord::Theta => quat_mul(&quat_mul(&quat_mul(&qz(phi), &qy(theta)), &quat_axis_ramp(1, h, false)), &qz(sigma - phi)),
                    Coord::Sigma => quat_mul(&quat_mul(&qz(phi), &qy(theta)), &quat_mul(&qz(sigma - phi), &quat_axis_ramp(2, h, false))),
                    _ => {
                        let left = quat_mul(&quat_mul(&qz(phi), &quat_axis_ramp(2, h, false)), &qy(theta));
                        quat_mul(&quat_mul(&left, &qz(sigma - phi)), &quat_axis_ramp(2, h, true))
                    }
                };
                Motion::from_parts(position.clone(), &n, Param::Angle { start, end, h })
            })
            .collect()
    }

    /// This motion seen from a fixed frame: the frame's origin `p` and rotation `r` applied on
    /// the left (P̂ ↦ r·P̂ + p·w, M̂ ↦ r·M̂). The identity frame leaves the motion as it is.
    pub fn placed(&self, p: &nalgebra::Vector3<f64>, r: &nalgebra::Matrix3<f64>) -> Motion {
        if *p == nalgebra::Vector3::zeros() && *r == nalgebra::Matrix3::identity() {
            return self.clone();
        }
        let w = &self.weight;
        let position = per_axis(|i| Bern::linear_combination(&[(w, p[i]), (&self.position[0], r[(i, 0)]), (&self.position[1], r[(i, 1)]), (&self.position[2], r[(i, 2)])]));
        let m = &self.rotation;
        let rotation = per_axis(|i| per_axis(|c| Bern::linear_combination(&[(&m[0][c], r[(i, 0)]), (&m[1][c], r[(i, 1)]), (&m[2][c], r[(i, 2)])])));
        let spin = self.spin.as_ref().map(|sp| Spin { axis: r * sp.axis, ..sp.clone() });
        Motion { position, rotation, weight: w.clone(), param: self.param, spin }
    }

    /// The frame fixed to this moving one at offset `t` and relative rotation `r`
    /// (P̂ ↦ P̂ + M̂·t, M̂ ↦ M̂·r).
    pub fn then(&self, t: &nalgebra::Vector3<f64>, r: &nalgebra::Matrix3<f64>) -> Motion {
        let m = &self.rotation;
        let position = per_axis(|i| Bern::linear_combination(&[(&self.position[i], 1.0), (&m[i][0], t[0]), (&m[i][1], t[1]), (&m[i][2], t[2])]));
        let rotation = per_axis(|i| per_axis(|c| Bern::linear_combination(&[(&m[i][0], r[(0, c)]), (&m[i][1], r[(1, c)]), (&m[i][2], r[(2, c)])])));
        let spin = self.spin.as_ref().map(|sp| Spin { body: r.transpose() * sp.body, ..sp.clone() });
        Motion { position, rotation, weight: self.weight.clone(), param: self.param, spin }
    }

    /// This (moving) frame followed by a joint at `location` in it moving by `joint` (relative):
    /// P̂ = P̂·ŵ_j + M̂·(location·ŵ_j + P̂_j), M̂ = M̂·M̂_j over the product of the weights.
    pub fn compose(&self, location: &nalgebra::Vector3<f64>, joint: &Motion) -> Motion {
        let wj = &joint.weight;
        let position = per_axis(|i| {
            (0..3).fold(self.position[i].mul(wj), |acc, k| acc.add(&self.rotation[i][k].mul(&joint.position[k].add(&wj.scale(location[k])))))
        });
        let rotation = per_axis(|i| per_axis(|c| (0..3).fold(Bern::constant(0.0), |acc, k| acc.add(&self.rotation[i][k].mul(&joint.rotation[k][c])))));
        Motion { position, rotation, weight: self.weight.mul(wj), param: self.param, spin: None }
    }

    /// The same motion over a weight `f` times larger (numerators and weight multiplied by the
    /// positive polynomial `f`).
    pub fn times(&self, f: &Bern) -> Motion {
        Motion {
            position: each_axis(&self.position, |p| p.mul(f)),
            rotation: each_axis(&self.rotation, |row| each_axis(row, |p| p.mul(f))),
            weight: self.weight.mul(f),
            param: self.param,
            spin: self.spin.clone(),
        }
    }

    /// A frame that does not move, written over the weight `w` of the motions beside it.
    pub fn fixed((p, r): &(nalgebra::Vector3<f64>, nalgebra::Matrix3<f64>), w: &Bern, param: Param) -> Motion {
        Motion {
            position: per_axis(|i| w.scale(p[i])),
            rotation: per_axis(|i| per_axis(|j| w.scale(r[(i, j)]))),
            weight: w.clone(),
            param,
            spin: None,
        }
    }

    /// The part λ ∈ [a, b] of this motion as a motion of its own in λ' ∈ [0, 1]
    /// (λ = a + (b − a)·λ'), its parameter mapped to match. Only a trajectory's motion has parts.
    pub fn part(&self, a: f64, b: f64) -> Motion {
        let Param::Trajectory { psi, h, t0, t1, within: (c, d), centred } = self.param else {
            panic!("only a trajectory's motion is cut into parts");
        };
        let r = |p: &Bern| p.restrict(a, b);
        Motion {
            position: each_axis(&self.position, r),
            rotation: each_axis(&self.rotation, |row| each_axis(row, r)),
            weight: r(&self.weight),
            param: Param::Trajectory { psi, h, t0, t1, within: (c + (d - c) * a, c + (d - c) * b), centred },
            // dθ/dλ' = (b − a)·dθ/dλ
            spin: self.spin.as_ref().map(|sp| Spin { rate: r(&sp.rate).scale(b - a), ..sp.clone() }),
        }
    }

    /// Position and rotation matrix at λ (for checks; the exact conditions use the polynomials).
    pub fn eval(&self, lam: f64) -> (nalgebra::Vector3<f64>, nalgebra::Matrix3<f64>) {
        let w = self.weight.value(lam);
        let p = nalgebra::Vector3::from_fn(|i, _| self.position[i].value(lam) / w);
        let r = nalgebra::Matrix3::from_fn(|i, j| self.rotation[i][j].value(lam) / w);
        (p, r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    #[test]
    fn trajectory_motion_matches_slerp_and_polynomial() {
        let qs = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.9);
        let translation = Translation::Polynomial([vec![1.0, 2.0, -1.0], vec![0.5, 0.0, 0.0, 3.0], vec![2.0]]);
        // slerp angles θ (cos θ = Qs·Qe): short (one piece), long (two) and almost π (two; over the
        // whole slerp tan(θ/2) would be about 2000)
        for (angle, pieces) in [(1.2, 1), (2.5, 2), (std::f64::consts::PI - 1e-3, 2)] {
            let qe = qs * UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_normalize(Vector3::new(0.3, -0.5, 0.8)), 2.0 * angle);
            assert!((qs.quaternion().dot(qe.quaternion()) - f64::cos(angle)).abs() < 1e-12);
            let traj = Trajectory::single("t", translation.clone(), Orientation::Slerp(qs, qe));
            let motions = Motion::trajectory(&traj);
            assert!(motions.len() >= pieces, "θ = {angle}");
            if angle <= FRAC_PI_2 {
                assert_eq!(motions.len(), 1);
            }
            follows(&traj, &motions, angle);
        }
    }

    /// The motions tile t ∈ [0, 1] in order, and at every λ of 21 per piece their pose is the
    /// trajectory's at the t their parameter names.
    fn follows(traj: &Trajectory, motions: &[Motion], angle: f64) {
        let mut last_t = 0.0;
        for m in motions {
            assert_eq!(m.param.value(0.0), last_t);
            for i in 0..=20 {
                let lam = i as f64 / 20.0;
                let t = m.param.value(lam);
                let (p, r) = m.eval(lam);
                let want = traj.pose_at(t);
                assert!((r - want.matrix()).norm() < 1e-11, "rotation at t={t}, θ = {angle}: {}", (r - want.matrix()).norm());
                assert!((p - want.position).norm() < 1e-9 * (1.0 + want.position.norm()), "position at t={t}, θ = {angle}: {p} vs {}", want.position);
            }
            last_t = m.param.value(1.0);
        }
        assert_eq!(last_t, 1.0);
    }

    /// A slerp that does not translate is linear in λ (rotation numerator and weight of degree 2),
    /// follows the slerp at the t its parameter names, keeps w within [cos²(ψ/2), 1] on each piece
    /// of at most π/2, and the pieces tile t ∈ [0, 1].
    #[test]
    fn slerp_in_place_is_linear_and_follows_the_slerp() {
        let qs = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.9);
        let at = Translation::Line(Vector3::new(0.5, -1.0, 2.0), Vector3::new(0.5, -1.0, 2.0));
        for (angle, pieces) in [(1e-7, 1), (0.4, 1), (FRAC_PI_2, 1), (2.5, 2), (std::f64::consts::PI - 1e-3, 2)] {
            let qe = qs * UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_normalize(Vector3::new(0.3, -0.5, 0.8)), 2.0 * angle);
            let traj = Trajectory::single("t", at.clone(), Orientation::Slerp(qs, qe));
            let motions = Motion::trajectory(&traj);
            assert_eq!(motions.len(), pieces, "θ = {angle}");
            follows(&traj, &motions, angle);
            let psi = angle / pieces as f64;
            for m in &motions {
                assert!(m.weight.degree() <= 2 && m.rotation[0][0].degree() <= 2 && m.position[0].degree() <= 2);
                for i in 0..=20 {
                    let w = m.weight.value(i as f64 / 20.0);
                    assert!(w <= 1.0 + 1e-12 && w >= (psi / 2.0).cos().powi(2) - 1e-12, "w = {w} at λ = {i}/20");
                }
            }
        }
    }

    /// Along every form of a trajectory's parameter — the general slerp's, a slerp in place's
    /// (centred) and a part of each — the uniform time law's λ̇ is dλ/dt of the parameter map
    /// (central differences), and its slope bound holds.
    #[test]
    fn uniform_law_is_the_parameter_maps_rate() {
        let qs = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.9);
        let qe = qs * UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_normalize(Vector3::new(0.3, -0.5, 0.8)), 2.6);
        let moving = Translation::Polynomial([vec![1.0, 2.0], vec![0.5], vec![2.0]]);
        let fixed = Translation::Polynomial([vec![1.0], vec![0.5], vec![2.0]]);
        for translation in [moving, fixed] {
            let traj = Trajectory::single("t", translation, Orientation::Slerp(qs, qe));
            for whole in Motion::trajectory(&traj) {
                for m in [whole.clone(), whole.part(0.2, 0.7)] {
                    let law = crate::conditions::TimeLaw::uniform(&m.param, 1.0).expect("a trajectory's law");
                    for i in 1..10 {
                        let lam = i as f64 / 10.0;
                        let h = 1e-6;
                        let dt = (m.param.value(lam + h) - m.param.value(lam - h)) / (2.0 * h);
                        let g = law.square.value(lam).sqrt();
                        assert!((g * dt - 1.0).abs() < 1e-6, "{:?} at {lam}: λ̇ {g} vs 1/{dt}", m.param);
                        assert!(dt <= m.param.max_slope() * (1.0 + 1e-9));
                    }
                }
            }
        }
    }

    #[test]
    fn angle_rays_follow_tilt_and_torsion() {
        let pose = Pose::from_coords([1.0, 2.0, 3.0, 0.4, 0.7, -0.3]);
        for coord in [Coord::Phi, Coord::Theta, Coord::Sigma] {
            let pieces = Motion::ray(&pose, coord, -2.5, 2.0);
            assert_eq!(pieces.len(), (4.5 / ANGLE_PIECE).ceil() as usize);
            for m in &pieces {
                for i in 0..=4 {
                    let lam = i as f64 / 4.0;
                    let mut c = pose.coords();
                    c[coord.index()] = m.param.value(lam);
                    let want = Pose::from_coords(c);
                    let (p, r) = m.eval(lam);
                    assert!((r - want.matrix()).norm() < 1e-12, "{coord:?} at λ={lam}");
                    assert!((p - Vector3::new(1.0, 2.0, 3.0)).norm() < 1e-12);
                }
            }
        }
    }
}
