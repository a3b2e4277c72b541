//! CASPR's joint-space interpolation, exactly: from one configuration to the next every joint
//! progresses in proportion — revolute, universal, prismatic and planar coordinates along the
//! straight line between their values, a ball joint (spherical) by its shortest rotation from
//! the one orientation to the other — the path CASPR's joint splines (quintic, cubic, linear)
//! follow whenever their knots' velocities and accelerations are zero, their timing aside
//! (`JointBase.generateTrajectoryQuinticSpline` per coordinate, `SphericalEulerXYZ` through
//! `Quaternion.QuinticInterpolation`: R_s·Rot(e, θ(t)) with e, Θ the axis and angle of R_sᵀR_e).
//!
//! Along the path every moving rotation turns about a fixed axis by Δ·u (u ∈ [0, 1] the common
//! progress). That is a rational curve of one parameter when every |Δ| is a small integer
//! multiple k of one angle δ: with T = h·λ, h = tan(δ_p/2) (δ_p = δ/n on each of n pieces), the
//! quaternion (1 + iT)^k turns by k·2·atan(T), so every joint turns by its k times the same base
//! angle — exactly in proportion. Translations are linear in u, so they move along a rational
//! path only when nothing turns. A leg whose angles are not in small integer ratios (or that
//! translates while it turns) has no such form: validation refuses it, naming the leg.

use nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3};

use super::chain::{Chain, Joint, Step};
use super::motion::{quat_const, quat_mul, Motion, Param, QuatPoly, ANGLE_PIECE};
use crate::poly::Bern;

/// Largest integer ratio between a leg's turning angles and their common base angle.
const MAX_MULTIPLE: usize = 8;

/// Relative tolerance of an angle being k times the base angle (CASPR files write angles to
/// about nine digits).
const RATIO_TOLERANCE: f64 = 1e-7;

/// How one joint moves along a leg.
#[derive(Debug, Clone)]
enum Moves {
    /// A free joint, which CASPR's splines do not move in proportion: it must stay put.
    Still,
    /// Its elementary steps, each from its value by Δ (a slide's length, a turn's angle).
    Steps(Vec<(Step, f64, f64)>),
    /// A ball joint: its rotation at the start, then a turn about the unit axis e (in the
    /// turned frame) by Θ ∈ [0, π].
    Ball { start: Matrix3<f64>, axis: Vector3<f64>, angle: f64 },
}

/// One leg of a proportional path, from configuration `a` to `b`: every joint's moves, the base
/// angle δ with each turn's multiple of it, and the number of pieces.
#[derive(Debug, Clone)]
pub struct Leg {
    a: Vec<f64>,
    b: Vec<f64>,
    moves: Vec<Moves>,
    /// The base angle δ (0 when nothing turns).
    base: f64,
    /// Equal pieces of the progress u, each turning every joint by at most [`ANGLE_PIECE`].
    pieces: usize,
}

/// The axis and angle in [0, π] of a rotation matrix.
fn axis_angle(r: &Matrix3<f64>) -> (Vector3<f64>, f64) {
    let q = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(*r));
    match q.axis_angle() {
        Some((axis, angle)) => (axis.into_inner(), angle),
        None => (Vector3::x(), 0.0),
    }
}

/// Rotation by `angle` about the unit `axis`.
fn rot(axis: &Vector3<f64>, angle: f64) -> Matrix3<f64> {
    *Rotation3::from_axis_angle(&Unit::new_unchecked(*axis), angle).matrix()
}

impl Leg {
    /// The leg from `a` to `b` of `chain`, or why it has no rational form.
    pub fn new(chain: &Chain, a: &[f64], b: &[f64]) -> Result<Leg, String> {
        let mut moves = Vec::with_capacity(chain.links.len());
        let (mut turns, mut slides) = (Vec::new(), false);
        let mut o = 0;
        for link in &chain.links {
            let n = link.joint.dof();
            let (qa, qb) = (&a[o..o + n], &b[o..o + n]);
            o += n;
            let m = match (&link.joint, link.joint.steps()) {
                (Joint::Spherical, _) => {
                    let (start, end) = (link.joint.transform(qa).1, link.joint.transform(qb).1);
                    let (axis, angle) = axis_angle(&(start.transpose() * end));
                    if angle > 0.0 {
                        turns.push(angle);
                    }
                    Moves::Ball { start, axis, angle }
                }
                (_, None) => {
                    if qa != qb {
                        return Err(format!("link {}'s free joint moves: CASPR's splines do not move one in proportion", link.name));
                    }
                    Moves::Still
                }
                (_, Some(steps)) => Moves::Steps(
                    steps
                        .iter()
                        .enumerate()
                        .map(|(k, s)| {
                            let d = qb[k] - qa[k];
                            match s {
                                Step::Turn(_) if d != 0.0 => turns.push(d.abs()),
                                Step::Slide(_) if d != 0.0 => slides = true,
                                _ => {}
                            }
                            (*s, qa[k], d)
                        })
                        .collect(),
                ),
            };
            moves.push(m);
        }
        if turns.is_empty() {
            return Ok(Leg { a: a.to_vec(), b: b.to_vec(), moves, base: 0.0, pieces: 1 });
        }
        if slides {
            return Err("it slides and turns at once: a length linear in the progress of a turn has no rational form".to_string());
        }
        let widest = turns.iter().copied().fold(0.0, f64::max);
        let base = (1..=MAX_MULTIPLE)
            .map(|k| widest / k as f64)
            .find(|&d| turns.iter().all(|t| ((t / d).round() - t / d).abs() <= RATIO_TOLERANCE * t / d && (t / d).round() >= 1.0))
            .ok_or_else(|| {
                let angles: Vec<String> = turns.iter().map(|t| format!("{t:.9}")).collect();
                format!("its turning angles ({} rad) are not multiples of one angle by integers up to {MAX_MULTIPLE}", angles.join(", "))
            })?;
        let pieces = ((widest / ANGLE_PIECE).ceil() as usize).max(1);
        Ok(Leg { a: a.to_vec(), b: b.to_vec(), moves, base, pieces })
    }

    /// The number of pieces.
    pub fn pieces(&self) -> usize {
        self.pieces
    }

    /// The multiple of the base angle a turn by `d` is (its sign the direction; 0 for no turn).
    fn multiple(&self, d: f64) -> i32 {
        if d == 0.0 { 0 } else { (d / self.base).round() as i32 }
    }

    /// The base angle of one piece, and tan of its half.
    fn piece_angle(&self) -> (f64, f64) {
        let d = self.base / self.pieces as f64;
        (d, (d / 2.0).tan())
    }

    /// Every link's motion along piece `p` (of [`Leg::pieces`]), the leg's t running over
    /// [t0, t1] in proportion to the progress.
    pub fn sweep(&self, chain: &Chain, p: usize, (t0, t1): (f64, f64)) -> Vec<Motion> {
        let n = self.pieces as f64;
        let (u0, u1) = (p as f64 / n, (p + 1) as f64 / n);
        let (t0, t1) = (t0 + (t1 - t0) * u0, if p + 1 == self.pieces { t1 } else { t0 + (t1 - t0) * u1 });
        let (psi, h) = self.piece_angle();
        let param = if self.base == 0.0 { Param::Linear { lo: t0, hi: t1 } } else { Param::Trajectory { psi, h, t0, t1, within: (0.0, 1.0), centred: false } };
        let one: QuatPoly = [vec![1.0], vec![0.0], vec![0.0], vec![0.0]];
        let about = |axis: &Vector3<f64>, a: f64| quat_const(&UnitQuaternion::from_axis_angle(&Unit::new_unchecked(*axis), a));
        // a turn of d in all from `from` on: at u0, then k base angles of the piece
        let turn = |n: QuatPoly, axis: &Vector3<f64>, from: f64, d: f64| {
            let n = quat_mul(&n, &about(axis, from + d * u0));
            let k = self.multiple(d);
            if k == 0 { n } else { quat_mul(&n, &power_ramp(&(axis * f64::from(k.signum())), h, k.unsigned_abs())) }
        };
        let line = |a: &Vector3<f64>, b: &Vector3<f64>| [0, 1, 2].map(|i| Bern::from_bernstein(vec![a[i], b[i]]));
        let locals = self
            .moves
            .iter()
            .map(|m| match m {
                Moves::Still => None,
                Moves::Ball { angle, .. } if *angle == 0.0 => None,
                Moves::Ball { start, axis, angle } => {
                    let n = turn(quat_const(&UnitQuaternion::from_matrix(start)), axis, 0.0, *angle);
                    Some(Motion::from_parts(line(&Vector3::zeros(), &Vector3::zeros()), &n, param))
                }
                Moves::Steps(steps) if steps.iter().all(|(_, _, d)| *d == 0.0) => None,
                Moves::Steps(steps) => {
                    let (mut pa, mut pb, mut n) = (Vector3::zeros(), Vector3::zeros(), one.clone());
                    for (step, from, d) in steps {
                        match step {
                            Step::Slide(axis) => {
                                pa += axis * (from + d * u0);
                                pb += axis * (from + d * u1);
                            }
                            Step::Turn(axis) => n = turn(n, axis, *from, *d),
                        }
                    }
                    Some(Motion::from_parts(line(&pa, &pb), &n, param))
                }
            })
            .collect();
        chain.compose(&self.a, locals, param)
    }

    /// The configuration at progress u ∈ [0, 1]: coordinates along their lines, a ball joint's
    /// Euler angles of its rotation there (the branch nearest the straight line between its
    /// ends' angles).
    pub fn config_at(&self, u: f64) -> Vec<f64> {
        let mut q: Vec<f64> = self.a.iter().zip(&self.b).map(|(x, y)| x + (y - x) * u).collect();
        let mut o = 0;
        for m in &self.moves {
            match m {
                Moves::Ball { start, axis, angle } => {
                    let r = start * rot(axis, angle * u);
                    let near = [q[o], q[o + 1], q[o + 2]];
                    q[o..o + 3].copy_from_slice(&euler_xyz(&r, near));
                    o += 3;
                }
                Moves::Steps(steps) => o += steps.len(),
                Moves::Still => o += 6,
            }
        }
        q
    }

    /// The progress u ∈ [0, 1] at λ of piece `p`.
    pub fn progress(&self, p: usize, lam: f64) -> f64 {
        let n = self.pieces as f64;
        if self.base == 0.0 {
            return (p as f64 + lam) / n;
        }
        let (psi, h) = self.piece_angle();
        (p as f64 + (2.0 * (h * lam).atan() / psi).clamp(0.0, 1.0)) / n
    }
}

/// The quaternion (1 + i·h·λ)^k about the unit `axis`: a turn by k·2·atan(hλ), degree k in λ.
fn power_ramp(axis: &Vector3<f64>, h: f64, k: u32) -> QuatPoly {
    // (1 + ix)^k = Σ C(k, j) (ix)^j: the even powers real, the odd ones imaginary
    let (mut re, mut im) = (vec![0.0; k as usize + 1], vec![0.0; k as usize + 1]);
    let mut c = 1.0;
    for j in 0..=k as usize {
        let term = c * h.powi(j as i32);
        match j % 4 {
            0 => re[j] = term,
            1 => im[j] = term,
            2 => re[j] = -term,
            _ => im[j] = -term,
        }
        c = c * (k as usize - j) as f64 / (j + 1) as f64;
    }
    [re, im.iter().map(|v| v * axis.x).collect(), im.iter().map(|v| v * axis.y).collect(), im.iter().map(|v| v * axis.z).collect()]
}

/// The XYZ Euler angles (α, β, γ) of R = Rx(α)·Ry(β)·Rz(γ), each taken within π of `near`.
pub(crate) fn euler_xyz(r: &Matrix3<f64>, near: [f64; 3]) -> [f64; 3] {
    let beta = r[(0, 2)].clamp(-1.0, 1.0).asin();
    let alpha = (-r[(1, 2)]).atan2(r[(2, 2)]);
    let gamma = (-r[(0, 1)]).atan2(r[(0, 0)]);
    let wrap = |x: f64, to: f64| x + (2.0 * std::f64::consts::PI) * ((to - x) / (2.0 * std::f64::consts::PI)).round();
    [wrap(alpha, near[0]), wrap(beta, near[1]), wrap(gamma, near[2])]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::chain::{JointCoord, Link};

    fn link(name: &str, parent: Option<usize>, joint: Joint) -> Link {
        let coords = (0..joint.dof()).map(|k| JointCoord { name: format!("{name}{k}"), range: [-10.0, 10.0] }).collect();
        Link { name: name.into(), parent, location: Vector3::new(0.1, 0.0, 0.4), joint, coords, body: [Vector3::zeros(); 2], radius: 0.0, mass: 0.0, com: Vector3::zeros() }
    }

    fn chain() -> Chain {
        let links = vec![
            link("s", None, Joint::Spherical),
            link("u", Some(0), Joint::Universal([Vector3::x(), Vector3::z()])),
            link("r", Some(1), Joint::Revolute(Vector3::new(0.0, 0.6, 0.8))),
        ];
        Chain { links, gravity: Vector3::zeros(), load: None, joint_forces: Vec::new(), closure: true }
    }

    /// The links' frames along each piece equal CASPR's interpolation at the same progress: a
    /// ball joint R_a·Rot(e, Θu), the other coordinates a + (b − a)u.
    #[test]
    fn pieces_follow_caspr_interpolation() {
        let c = chain();
        let a = [0.1, -0.2, 0.3, 0.4, -0.1, 0.2];
        // every turn a multiple of 0.05 rad: the ball's angle is whatever its Euler angles give,
        // so it moves about one axis only here (α by 0.15), the universal by 0.1 and −0.05, the
        // revolute by 0.2
        let b = [0.25, -0.2, 0.3, 0.5, -0.15, 0.4];
        let leg = Leg::new(&c, &a, &b).unwrap();
        for p in 0..leg.pieces() {
            let motions = leg.sweep(&c, p, (0.0, 1.0));
            for k in 0..=8 {
                let lam = k as f64 / 8.0;
                let u = leg.progress(p, lam);
                let mut q: Vec<f64> = a.iter().zip(&b).map(|(x, y)| x + (y - x) * u).collect();
                // the ball: R_a·Rot(e, Θu) as Euler angles
                let (ra, rb) = (Joint::Spherical.transform(&a[..3]).1, Joint::Spherical.transform(&b[..3]).1);
                let (e, th) = axis_angle(&(ra.transpose() * rb));
                let near = [q[0], q[1], q[2]];
                q[..3].copy_from_slice(&euler_xyz(&(ra * rot(&e, th * u)), near));
                assert!(leg.config_at(u).iter().zip(&q).all(|(x, y)| (x - y).abs() < 1e-12), "{:?} vs {q:?}", leg.config_at(u));
                let frames = c.frames(&q);
                for (l, m) in motions.iter().enumerate() {
                    let (mp, mr) = m.eval(lam);
                    assert!((mp - frames[l].0).norm() < 1e-11 && (mr - frames[l].1).norm() < 1e-11, "link {l} at u = {u}");
                }
                assert!((m_param(&motions[0], lam) - u).abs() < 1e-12, "t runs with the progress");
            }
        }
        // a ball joint turned about a general axis (all three angles change): one turn by Θ
        let b2 = [0.2, -0.1, 0.45, 0.4, -0.1, 0.2];
        let leg = Leg::new(&c, &a, &b2).unwrap();
        assert_eq!(leg.base, leg.moves.iter().find_map(|m| if let Moves::Ball { angle, .. } = m { Some(*angle) } else { None }).unwrap());
    }

    fn m_param(m: &Motion, lam: f64) -> f64 {
        m.param.value(lam)
    }

    #[test]
    fn legs_without_a_rational_form_say_why() {
        let c = chain();
        let a = [0.0; 6];
        let e = Leg::new(&c, &a, &[0.0, 0.0, 0.0, 0.1, 0.0, 0.1 * std::f64::consts::SQRT_2]).unwrap_err();
        assert!(e.contains("not multiples of one angle"), "{e}");
        let slider = Chain { links: vec![link("p", None, Joint::Prismatic(Vector3::z())), link("r", Some(0), Joint::Revolute(Vector3::x()))], ..chain() };
        let e = Leg::new(&slider, &[0.0, 0.0], &[0.1, 0.2]).unwrap_err();
        assert!(e.contains("slides and turns"), "{e}");
        // a slide alone is linear
        let leg = Leg::new(&slider, &[0.0, 0.3], &[0.1, 0.3]).unwrap();
        let m = leg.sweep(&slider, 0, (0.0, 1.0));
        assert!((m[1].eval(0.5).0 - slider.frames(&[0.05, 0.3])[1].0).norm() < 1e-14);
    }
}
