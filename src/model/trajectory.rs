//! Trajectories as the scenario states them (thesis §4.2): a translation that is polynomial in
//! τ ∈ [0, 1] and an orientation that is a slerp in t ∈ [0, 1], tied by τ = tan(tθ/2)/tan(θ/2).
//! A piecewise trajectory (format 2) chains such pieces, each starting where the previous ends;
//! piece k of n covers t ∈ [k/n, (k+1)/n] of the whole.
//!
//! A trajectory through timed knots (format 4 `knots`, CASPR's splines: [`super::knots`]) is
//! piecewise too, one piece per pair of knots, covering its share of the time; its pieces turn
//! about a fixed axis ([`Orientation::Turn`]) and their translation is polynomial in t itself.

use super::dynamics::Kinematics;
use super::pose::Pose;
use nalgebra::{Quaternion, Unit, UnitQuaternion, Vector3};

/// Highest polynomial degree of a translation the scenario format accepts (and so at most
/// `MAX_DEGREE + 1` Bézier points): the exact conditions multiply the translation with itself and
/// with the rotation, so their degree grows several times faster than this, and the limit keeps
/// exact verification tractable.
pub const MAX_DEGREE: usize = 10;

/// The translation part of a trajectory, a polynomial in τ ∈ [0, 1].
#[derive(Debug, Clone, PartialEq)]
pub enum Translation {
    /// Ascending coefficients per axis: x(τ) = Σ `cx[k]` τ^k, and likewise y, z.
    Polynomial([Vec<f64>; 3]),
    /// Bézier control points: x(τ) = Σ P_k B_{k,n}(τ).
    Bezier(Vec<Vector3<f64>>),
    /// The segment from the first point (τ = 0) to the second (τ = 1).
    Line(Vector3<f64>, Vector3<f64>),
}

/// The orientation part of a trajectory.
#[derive(Debug, Clone, PartialEq)]
pub enum Orientation {
    /// Spherical linear interpolation from the first to the second quaternion. The quaternions'
    /// signs are kept as given: cos θ = Qs·Qe, so a negative dot product takes the long way round.
    Slerp(UnitQuaternion<f64>, UnitQuaternion<f64>),
    /// CASPR's rotation between two knots: from `from`, a turn about the fixed `axis` (in the
    /// frame of `from`) by `angle`·s(t), s the rest-to-rest `profile`. The piece's translation
    /// is then polynomial in t itself (τ = t).
    Turn {
        /// The rotation at t = 0.
        from: UnitQuaternion<f64>,
        /// The turn's axis in the frame of `from` (also in the moving frame: it does not move).
        axis: Unit<Vector3<f64>>,
        /// The whole turn (rad), ≥ 0.
        angle: f64,
        /// How the turn proceeds in t.
        profile: Profile,
    },
}

/// A rest-to-rest time profile s(t) on [0, 1]: s(0) = 0, s(1) = 1, ṡ = 0 at both ends (and s̈ = 0
/// for the quintic).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Profile {
    /// s = 10t³ − 15t⁴ + 6t⁵ (CASPR's quintic spline between knots at rest).
    Quintic,
    /// s = 3t² − 2t³ (CASPR's cubic spline between knots at rest).
    Cubic,
}

impl Profile {
    /// Ascending monomial coefficients of s(t).
    pub fn coefficients(self) -> &'static [f64] {
        match self {
            Profile::Quintic => &[0.0, 0.0, 0.0, 10.0, -15.0, 6.0],
            Profile::Cubic => &[0.0, 0.0, 3.0, -2.0],
        }
    }

    /// s(t), s'(t) and s''(t).
    pub fn at(self, t: f64) -> [f64; 3] {
        let c = self.coefficients();
        let mut out = [0.0; 3];
        for (k, &a) in c.iter().enumerate() {
            let k_f = k as f64;
            out[0] += a * t.powi(k as i32);
            if k >= 1 {
                out[1] += a * k_f * t.powi(k as i32 - 1);
            }
            if k >= 2 {
                out[2] += a * k_f * (k_f - 1.0) * t.powi(k as i32 - 2);
            }
        }
        out
    }
}

/// A named trajectory.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    /// Its name in the scenario.
    pub name: String,
    /// Translation in τ (of the first piece).
    pub translation: Translation,
    /// Orientation in t (of the first piece).
    pub orientation: Orientation,
    /// The pieces after the first, in order, for a piecewise trajectory (format 2 `pieces`);
    /// empty for a one-piece trajectory.
    pub more: Vec<Segment>,
    /// How long the whole trajectory takes (format 4 `duration`, seconds): t = time/duration, a
    /// uniform time law. `None` for a trajectory without timing (geometry and statics only).
    /// For a trajectory through knots, the time from the first knot to the last.
    pub duration: Option<f64>,
    /// The knots a timed spline trajectory was built from (format 4 `knots`), which also set
    /// each piece's share of t; `None` for the thesis' form.
    pub knots: Option<Knots>,
}

/// One piece of a piecewise trajectory: a translation in its own τ and an orientation in its own
/// t (a slerp, or a spline's turn, for which τ = t).
#[derive(Debug, Clone, PartialEq)]
pub struct Segment {
    /// Translation in τ ∈ [0, 1].
    pub translation: Translation,
    /// Orientation in t ∈ [0, 1].
    pub orientation: Orientation,
}

impl Segment {
    /// The slerp angle θ ∈ [0, π] with cos θ = Qs·Qe (the quaternions' signs as given), taken as
    /// 2·atan2(|Qe − Qs|, |Qe + Qs|), which unlike acos stays accurate near 0 and π.
    /// For a turn, the turn's angle.
    pub fn theta(&self) -> f64 {
        match &self.orientation {
            Orientation::Slerp(qs, qe) => {
                let (s, e) = (qs.quaternion(), qe.quaternion());
                2.0 * (e - s).norm().atan2((e + s).norm())
            }
            Orientation::Turn { angle, .. } => *angle,
        }
    }

    /// τ at slerp parameter t: τ = tan(tθ/2)/tan(θ/2), or t when θ = 0; exactly 0 and 1 at the
    /// ends. τ = t along a turn.
    pub fn tau_of_t(&self, t: f64) -> f64 {
        let theta = self.theta();
        if matches!(self.orientation, Orientation::Turn { .. }) || theta < 1e-9 || t <= 0.0 || t >= 1.0 {
            t.clamp(0.0, 1.0)
        } else {
            ((t * theta / 2.0).tan() / (theta / 2.0).tan()).clamp(0.0, 1.0)
        }
    }

    /// The pose at slerp parameter t, evaluated directly: p(τ(t)) and
    /// Q(t) = (Qs sin((1−t)θ) + Qe sin(tθ)) / sin θ; along a turn Q = Q_from·(cos β, sin β·axis),
    /// β = angle·s(t)/2.
    pub fn pose_at(&self, t: f64) -> Pose {
        let q: Quaternion<f64> = match &self.orientation {
            Orientation::Slerp(qs, qe) => {
                let theta = self.theta();
                let (s, e) = (qs.quaternion(), qe.quaternion());
                if theta < 1e-9 {
                    s * (1.0 - t) + e * t
                } else {
                    (s * ((1.0 - t) * theta).sin() + e * (t * theta).sin()) / theta.sin()
                }
            }
            Orientation::Turn { from, axis, angle, profile } => {
                let half = 0.5 * angle * profile.at(t.clamp(0.0, 1.0))[0];
                from.quaternion() * Quaternion::from_parts(half.cos(), axis.into_inner() * half.sin())
            }
        };
        Pose { position: self.translation.at(self.tau_of_t(t)), rotation: UnitQuaternion::from_quaternion(q) }
    }
}

impl Segment {
    /// The motion at slerp parameter t per unit of t (the trajectory's own parameter): the
    /// origin's dp/dt and d²p/dt², and the angular velocity dΦ/dt, constant along a slerp (the
    /// angular acceleration is zero). With τ = tan(tθ/2)/tan(θ/2):
    /// τ' = (θ/2)(1 + T²)/tan(θ/2) and τ'' = (θ²/2)·T(1 + T²)/tan(θ/2), T = tan(tθ/2).
    /// Along a turn τ = t, ω = R_from·axis·angle·s'(t) and α = R_from·axis·angle·s''(t).
    pub fn rates_at(&self, t: f64) -> Kinematics {
        if let Orientation::Turn { from, axis, angle, profile } = &self.orientation {
            let [_, s1, s2] = profile.at(t.clamp(0.0, 1.0));
            let (p1, p2) = self.translation.derivatives_at(t.clamp(0.0, 1.0));
            let world = from.transform_vector(axis) * *angle;
            return Kinematics { velocity: p1, acceleration: p2, omega: world * s1, alpha: world * s2 };
        }
        let theta = self.theta();
        let (tau, d1, d2) = if theta < 1e-9 {
            (t.clamp(0.0, 1.0), 1.0, 0.0)
        } else {
            let big_t = (t * theta / 2.0).tan();
            let tan_half = (theta / 2.0).tan();
            let sec2 = 1.0 + big_t * big_t;
            (self.tau_of_t(t), 0.5 * theta * sec2 / tan_half, 0.5 * theta * theta * big_t * sec2 / tan_half)
        };
        let (p1, p2) = self.translation.derivatives_at(tau);
        Kinematics { velocity: p1 * d1, acceleration: p2 * d1 * d1 + p1 * d2, omega: self.angular_rate(), alpha: Vector3::zeros() }
    }

    /// The slerp's angular velocity per unit of t, in the world frame: Q(t) = Qs·(Qs⁻¹Qe)^t turns
    /// about the axis u (in the platform frame of Qs) of Qs⁻¹Qe = (cos θ, sin θ·u) at the rate
    /// 2θ, which in the world frame is Rs·u·2θ.
    fn angular_rate(&self) -> Vector3<f64> {
        let Orientation::Slerp(qs, qe) = &self.orientation else { return Vector3::zeros() };
        let rel = qs.quaternion().conjugate() * qe.quaternion();
        let theta = self.theta();
        // 2θ·u = 2θ/sin θ · vec(rel); θ/sin θ → 1 as θ → 0
        let factor = if theta < 1e-6 { 2.0 * (1.0 + theta * theta / 6.0) } else { 2.0 * theta / theta.sin() };
        qs.transform_vector(&(rel.imag() * factor))
    }
}

impl Translation {
    /// dp/dτ and d²p/dτ² at τ.
    pub fn derivatives_at(&self, tau: f64) -> (Vector3<f64>, Vector3<f64>) {
        match self {
            Translation::Polynomial(c) => {
                let d = |k: usize| {
                    Vector3::from_fn(|i, _| {
                        c[i].iter().enumerate().skip(k).rev().fold(0.0, |acc, (j, &a)| {
                            let falling = if k == 1 { j as f64 } else { (j * (j - 1)) as f64 };
                            acc * tau + a * falling
                        })
                    })
                };
                (d(1), d(2))
            }
            Translation::Bezier(points) => {
                let diff = |pts: &[Vector3<f64>]| -> Vec<Vector3<f64>> {
                    let n = (pts.len() - 1) as f64;
                    pts.windows(2).map(|w| (w[1] - w[0]) * n).collect()
                };
                let first = if points.len() > 1 { diff(points) } else { vec![] };
                let second = if first.len() > 1 { diff(&first) } else { vec![] };
                let at = |pts: Vec<Vector3<f64>>| if pts.is_empty() { Vector3::zeros() } else { Translation::Bezier(pts).at(tau) };
                (at(first), at(second))
            }
            Translation::Line(a, b) => (b - a, Vector3::zeros()),
        }
    }

    /// The position at τ (direct evaluation, used by the point-wise baseline).
    pub fn at(&self, tau: f64) -> Vector3<f64> {
        match self {
            Translation::Polynomial(c) => {
                Vector3::from_fn(|i, _| c[i].iter().rev().fold(0.0, |acc, &a| acc * tau + a))
            }
            Translation::Bezier(points) => {
                let mut pts = points.clone();
                for level in (1..pts.len()).rev() {
                    for k in 0..level {
                        pts[k] = pts[k] * (1.0 - tau) + pts[k + 1] * tau;
                    }
                }
                pts.first().copied().unwrap_or_else(Vector3::zeros)
            }
            Translation::Line(a, b) => a * (1.0 - tau) + b * tau,
        }
    }
}

impl Trajectory {
    /// A one-piece trajectory.
    pub fn single(name: impl Into<String>, translation: Translation, orientation: Orientation) -> Trajectory {
        Trajectory { name: name.into(), translation, orientation, more: vec![], duration: None, knots: None }
    }

    /// A trajectory of one or more pieces (the first must exist: `None` for an empty list).
    pub fn piecewise(name: impl Into<String>, pieces: Vec<Segment>) -> Option<Trajectory> {
        let mut it = pieces.into_iter();
        let first = it.next()?;
        Some(Trajectory { name: name.into(), translation: first.translation, orientation: first.orientation, more: it.collect(), duration: None, knots: None })
    }

    /// Number of pieces (1 for an ordinary trajectory).
    pub fn piece_count(&self) -> usize {
        1 + self.more.len()
    }

    /// The pieces in order, the first included.
    pub fn pieces(&self) -> Vec<Segment> {
        let first = Segment { translation: self.translation.clone(), orientation: self.orientation.clone() };
        std::iter::once(first).chain(self.more.iter().cloned()).collect()
    }

    /// The share [t0, t1] of the whole t ∈ [0, 1] that piece `k` covers: 1/n each, or through
    /// knots the piece's share of the time.
    pub fn piece_span(&self, k: usize) -> [f64; 2] {
        if let Some(knots) = &self.knots {
            return knots.span(k);
        }
        let n = self.piece_count() as f64;
        [k as f64 / n, if k + 1 == self.piece_count() { 1.0 } else { (k + 1) as f64 / n }]
    }

    /// The piece holding t and t's value within it.
    fn locate(&self, t: f64) -> (Segment, usize, f64) {
        let n = self.piece_count();
        let t = t.clamp(0.0, 1.0);
        let k = match &self.knots {
            Some(_) => (0..n).find(|&k| t < self.piece_span(k)[1]).unwrap_or(n - 1),
            None => ((t * n as f64).floor() as usize).min(n - 1),
        };
        let [t0, t1] = self.piece_span(k);
        let seg = if k == 0 {
            Segment { translation: self.translation.clone(), orientation: self.orientation.clone() }
        } else {
            self.more[k - 1].clone()
        };
        (seg, k, ((t - t0) / (t1 - t0)).clamp(0.0, 1.0))
    }

    /// τ at slerp parameter t: τ = tan(tθ/2)/tan(θ/2), or t when θ = 0; exactly 0 and 1 at the
    /// ends. For a piecewise trajectory, piece k's own τ mapped onto [k/n, (k+1)/n].
    pub fn tau_of_t(&self, t: f64) -> f64 {
        let (seg, k, local) = self.locate(t);
        let [t0, t1] = self.piece_span(k);
        t0 + (t1 - t0) * seg.tau_of_t(local)
    }

    /// The pose at slerp parameter t, evaluated directly: p(τ(t)) and
    /// Q(t) = (Qs sin((1−t)θ) + Qe sin(tθ)) / sin θ (in the piece holding t).
    pub fn pose_at(&self, t: f64) -> Pose {
        let (seg, _, local) = self.locate(t);
        seg.pose_at(local)
    }

    /// The platform's motion at t, evaluated directly, when the trajectory is run in `duration`
    /// seconds (time = t·duration): piece k covers [t0, t1] of t, so its own t runs
    /// 1/((t1 − t0)·duration) per second.
    pub fn kinematics_at(&self, t: f64, duration: f64) -> Kinematics {
        let (seg, k, local) = self.locate(t);
        let [t0, t1] = self.piece_span(k);
        let rate = 1.0 / ((t1 - t0) * duration);
        let m = seg.rates_at(local);
        Kinematics { velocity: m.velocity * rate, acceleration: m.acceleration * (rate * rate), omega: m.omega * rate, alpha: m.alpha * (rate * rate) }
    }
}

/// One knot: when the platform is where, and how its origin moves there.
#[derive(Debug, Clone, PartialEq)]
pub struct Knot {
    /// Seconds from the first knot (0 there), strictly increasing.
    pub time: f64,
    /// The pose at that time.
    pub pose: Pose,
    /// The origin's velocity (m/s).
    pub velocity: Vector3<f64>,
    /// The origin's acceleration (m/s²); unused by a cubic spline.
    pub acceleration: Vector3<f64>,
}

/// The knots of a timed spline trajectory and the spline through them (its pieces:
/// [`super::knots`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Knots {
    /// Quintic (positions, velocities, accelerations met) or cubic (positions, velocities).
    pub profile: Profile,
    /// Two or more knots in time order.
    pub points: Vec<Knot>,
}

impl Knots {
    /// Seconds from the first knot to the last.
    pub fn duration(&self) -> f64 {
        self.points.last().map_or(0.0, |k| k.time) - self.points.first().map_or(0.0, |k| k.time)
    }

    /// The share [t0, t1] of t ∈ [0, 1] (time / duration) between knot `k` and knot `k + 1`.
    pub fn span(&self, k: usize) -> [f64; 2] {
        let (start, d) = (self.points[0].time, self.duration());
        let end = if k + 2 >= self.points.len() {
            1.0
        } else {
            (self.points[k + 1].time - start) / d
        };
        [(self.points[k].time - start) / d, end]
    }
}
