//! The wrench the cables must balance along a motion, as polynomials: the wrench set's nominal
//! wrench, the platform's weight about the wrench point, and along a timed trajectory the
//! d'Alembert inertial wrench (`crate::model::dynamics`).
//!
//! With p = P̂/w, R = M̂/w and g = dλ/ds (s the time; g² and g g' polynomials, [`TimeLaw`]), every
//! term is a polynomial over a power of w:
//!
//! * centre of mass X̂ = P̂ + M̂ c_b (over w); its acceleration Ã/w³ with
//!   Ã = g g' (X̂'w − X̂w') w + g² ((X̂''w − X̂w'') w − 2w'(X̂'w − X̂w'));
//! * angular velocity ω = g Ω̂/w², Ω̂ the axial vector of M̂'M̂ᵀ's skew part (R'Rᵀ = M̂'M̂ᵀ/w² −
//!   (w'/w) I because M̂M̂ᵀ = w² I), and α = α̃/w³ with α̃ = g g' Ω̂ w + g² (Ω̂'w − 2Ω̂w');
//! * world inertia I = M̂ I_b M̂ᵀ/w².
//!
//! The rows are returned scaled as the structure matrix's rows are (forces times w, moments times
//! w²) and over a common w^q: [`LoadPolys::rows`] = D_w ℓ · w^q.

use super::structure::{cross, point_offset, times_const};
use super::Local;
use crate::axes::{each_axis, per_axis, per_component};
use crate::model::motion::{Param, Spin};
use crate::model::{Dynamics, Load};
use crate::poly::Bern;

/// The load along a motion: D_w ℓ · w^q, row by row, and w^q (`None` when q = 0). Along a timed
/// motion the inertial rows are kept apart, and apart from the time law ([`Inertial`]): a
/// trajectory run in T seconds has the rows `rows + inertial(law) / T²` (velocities scale with
/// 1/T, accelerations with 1/T²), so one expansion serves every timing and every law.
#[derive(Debug, Clone)]
pub(crate) struct LoadPolys {
    /// Rows 0–2: force · w · w^q; rows 3–5: moment · w² · w^q — the wrench set's nominal wrench
    /// and the weight.
    pub(crate) rows: [Bern; 6],
    /// The d'Alembert rows, along a timed motion.
    pub(crate) inertial: Option<Inertial>,
    /// w^q, the positive factor the rows carry (`None` for 1).
    pub(crate) scale: Option<Bern>,
}

/// The d'Alembert rows (same scaling as [`LoadPolys::rows`]) as a time law makes them: linear in
/// its λ̈ = g·g' and its λ̇² = g², so kept as the rows per unit of each. Under a re-parametrisation
/// λ = a + hλ' (a part of the motion) they are h and h² times those per unit of the part's own
/// λ̈' and λ̇'² ([`Inertial::part`]).
#[derive(Debug, Clone)]
pub(crate) struct Inertial {
    /// Per unit g·g'.
    pub(crate) accel: [Bern; 6],
    /// Per unit g².
    pub(crate) square: [Bern; 6],
}

impl Inertial {
    /// The rows under `law`: g·g'·accel + g²·square.
    pub(crate) fn under(&self, law: &TimeLaw) -> [Bern; 6] {
        per_component(|j| law.accel.mul(&self.accel[j]).add(&law.square.mul(&self.square[j])))
    }

    /// The rows on [a, b] ⊆ [0, 1] in the same parameter (values kept).
    fn restrict(&self, a: f64, b: f64) -> Inertial {
        Inertial { accel: restrict_rows(&self.accel, a, b), square: restrict_rows(&self.square, a, b) }
    }
}

impl LoadPolys {
    /// `p` times (w^q)², for a square (the ellipsoid's reach squared) that must carry the factor
    /// the rows carry.
    pub(crate) fn scaled_square(&self, p: Bern) -> Bern {
        match &self.scale {
            Some(q) => p.mul(&q.mul(q)),
            None => p,
        }
    }

    /// The rows restricted to [a, b] ⊆ [0, 1].
    pub(crate) fn restrict(&self, a: f64, b: f64) -> LoadPolys {
        LoadPolys { rows: restrict_rows(&self.rows, a, b), inertial: self.inertial.as_ref().map(|i| i.restrict(a, b)), scale: self.scale.as_ref().map(|p| p.restrict(a, b)) }
    }
}

/// Six rows restricted to [a, b] ⊆ [0, 1].
fn restrict_rows(rows: &[Bern; 6], a: f64, b: f64) -> [Bern; 6] {
    per_component(|j| rows[j].restrict(a, b))
}

/// Scales a polynomial per unit of the whole motion's λ̈ (`power` 1) or λ̇² (`power` 2) restricted
/// to a part of width h to one per unit of the part's own: h or h² times it (λ = a + hλ' gives
/// λ̈ = h·λ̈' and λ̇² = h²·λ̇'²).
pub(crate) fn per_part_unit(p: &Bern, (a, b): (f64, f64), power: i32) -> Bern {
    p.restrict(a, b).scale((b - a).powi(power))
}

/// An inertial part kept apart from the time law — (per unit λ̈, per unit λ̇²) — under `law`:
/// λ̈·accel + λ̇²·square (`None` without either).
pub(crate) fn split_under(split: &Option<(Bern, Bern)>, law: Option<&TimeLaw>) -> Option<Bern> {
    let ((accel, square), law) = (split.as_ref()?, law?);
    Some(law.accel.mul(accel).add(&law.square.mul(square)))
}

/// A split inertial part ([`split_under`]) on the part [a, b] of the motion, per unit of the
/// part's own λ̈ and λ̇² ([`per_part_unit`]).
pub(crate) fn split_part(split: &Option<(Bern, Bern)>, (a, b): (f64, f64)) -> Option<(Bern, Bern)> {
    split.as_ref().map(|(accel, square)| (per_part_unit(accel, (a, b), 1), per_part_unit(square, (a, b), 2)))
}

/// 1/T² for a motion run in `duration` seconds (0 at rest, `None`).
pub(crate) fn inverse_square(duration: Option<f64>) -> f64 {
    duration.map_or(0.0, |d| 1.0 / (d * d))
}

/// `fixed + inertial · k` (the inertial part absent: `fixed`).
pub(crate) fn with_inertia(fixed: &Bern, inertial: Option<&Bern>, k: f64) -> Bern {
    match inertial {
        Some(i) if k != 0.0 => Bern::linear_combination(&[(fixed, 1.0), (i, k)]),
        _ => fixed.clone(),
    }
}

/// How λ runs in time along a motion (s the time, g = dλ/ds): g² and g·g' = ½ d(g²)/dλ as
/// polynomials in λ — all that the inertial wrench and the winch limits take from the time law.
/// A law whose g² is a polynomial is any uniform law (the slerp's atan parameter included) and
/// any law of piecewise constant λ̈ (g² linear: a time-optimal law, `crate::plan::timing`).
#[derive(Debug, Clone, PartialEq)]
pub struct TimeLaw {
    /// g² = λ̇².
    pub square: Bern,
    /// g·g' = λ̈.
    pub accel: Bern,
}

impl TimeLaw {
    /// The law with λ̇² = `square` (a polynomial, non-negative on [0, 1]).
    pub fn from_square(square: Bern) -> TimeLaw {
        let accel = square.derivative().scale(0.5);
        TimeLaw { square, accel }
    }

    /// The uniform law along a trajectory's motion run in `duration` seconds in all (time =
    /// t·duration); `None` for a motion without time (a ray).
    pub fn uniform(param: &Param, duration: f64) -> Option<TimeLaw> {
        let Param::Trajectory { psi, h, t0, t1, within: (a, b), centred } = *param else { return None };
        // g on the whole stretch, then on its part: λ = a + (b − a)λ' ⇒ dλ'/ds = g(λ)/(b − a)
        let span = (t1 - t0) * duration;
        let g = if psi < 1e-9 {
            Bern::constant(1.0 / span)
        } else {
            // t = t0 + (t1 − t0)·2·atan(hλ)/ψ  ⇒  dλ/dt = ψ(1 + h²λ²)/(2h(t1 − t0)); centred,
            // t = t0 + (t1 − t0)·(½ + atan((2λ − 1)h)/ψ)  ⇒  dλ/dt = ψ(1 + h²(2λ − 1)²)/(2h(t1 − t0))
            let c = psi / (2.0 * h * span);
            let monomial = if centred { [1.0 + h * h, -4.0 * h * h, 4.0 * h * h] } else { [1.0, 0.0, h * h] };
            Bern::from_monomial(&monomial.map(|m| c * m))
        };
        let g = g.restrict(a, b).scale(1.0 / (b - a));
        Some(TimeLaw::from_square(g.mul(&g)))
    }

    /// The law run `1/k` times as fast: λ̇² and λ̈ times `k` (k = 1/T² turns a law for one second
    /// into one for T seconds).
    pub fn scaled(&self, k: f64) -> TimeLaw {
        TimeLaw { square: self.square.scale(k), accel: self.accel.scale(k) }
    }
}

/// The time law of `sweep` at its duration: its own law (or the uniform one) with 1/T² applied;
/// `None` at rest.
pub(crate) fn sweep_law(sweep: &super::Sweep) -> Option<TimeLaw> {
    let k = inverse_square(Some(sweep.duration?));
    reference_law(sweep).map(|law| law.scaled(k))
}

/// The time law of `sweep` for a duration of one second: its own, or the uniform one; `None`
/// when the sweep is at rest.
pub(crate) fn reference_law(sweep: &super::Sweep) -> Option<TimeLaw> {
    sweep.duration?;
    sweep.law.clone().or_else(|| TimeLaw::uniform(&sweep.motion().param, 1.0))
}

fn mat_vec(m: &[[Bern; 3]; 3], v: &[Bern; 3]) -> [Bern; 3] {
    per_axis(|i| m[i][0].mul(&v[0]).add(&m[i][1].mul(&v[1])).add(&m[i][2].mul(&v[2])))
}

/// The load along the motion of `local` (expanded on all of [0, 1]), with the inertial rows when
/// the motion is `timed` (a turn's rates taken from its `spin` where it has one).
pub(crate) fn load_polys(local: &Local, load: &Load, timed: bool, spin: Option<&Spin>) -> LoadPolys {
    let w = &local.weight;
    let w2 = w.mul(w);
    let w0 = &load.wrench.nominal;
    let Some(dynamics) = &load.dynamics else {
        return LoadPolys { rows: per_component(|j| if j < 3 { w.scale(w0[j]) } else { w2.scale(w0[j]) }), inertial: None, scale: None };
    };
    // a point mass balances forces only: its moment rows stay zero, unexpanded
    let moments = load.rows().iter().any(|&r| r >= 3);
    // r̃ = (x_c − c)·w: from the wrench point to the centre of mass (P̂ cancels)
    let (com, at) = (times_const(&local.rotation, &dynamics.com), point_offset(local, &load.wrench));
    let r: [Bern; 3] = per_axis(|i| com[i].sub(&at[i]));
    let weight = dynamics.gravity * dynamics.mass;
    let weight_b: [Bern; 3] = per_axis(|i| Bern::constant(weight[i]));
    // static rows, q = 0: force (w0 + m g)·w, moment w0·w² + (r̃ × m g)·w
    let static_moment = cross(&r, &weight_b);
    let statics: [Bern; 6] = per_component(|j| {
        if j < 3 {
            w.scale(w0[j] + weight[j])
        } else if moments {
            w2.scale(w0[j]).add(&static_moment[j - 3].mul(w))
        } else {
            Bern::constant(0.0)
        }
    });
    if !timed {
        return LoadPolys { rows: statics, inertial: None, scale: None };
    }
    let inertial = inertial_rows(local, dynamics, &com, &r, moments, spin);
    // everything over w⁴: the static rows times w⁴
    let w4 = w2.mul(&w2);
    LoadPolys { rows: per_component(|j| statics[j].mul(&w4)), inertial: Some(inertial), scale: Some(w4) }
}

/// The d'Alembert rows over w⁴ (D_w-scaled), per unit g·g' and per unit g²: force −m Ã·w²,
/// moment −m (r̃ × Ã)·w² − (M̂ I_b M̂ᵀ α̃)·w − g² Ω̂ × (M̂ I_b M̂ᵀ Ω̂) (zero without `moments`);
/// `com` is M̂ c_b. Ã and α̃ are linear in (g·g', g²): Ã = g g'·(X̂'w − X̂w')w + g²·((X̂''w −
/// X̂w'')w − 2w'(X̂'w − X̂w')), α̃ = g g'·Ω̂w + g²·(Ω̂'w − 2Ω̂w').
///
/// With a `spin` (a turn about the world axis k at the exact rate θ' = dθ/dλ), Ω̂ = θ'w²·k, so
/// Ω̂'w − 2Ω̂w' = θ''w³·k, and M̂ I_b M̂ᵀ (s·k) = M̂ (I_b k_b)·(s·w) with k_b = Rᵀk the body's
/// axis: every term is a scalar polynomial times a fixed vector or M̂ times one — a fifth of the
/// degree the general products reach along a CASPR turn.
fn inertial_rows(local: &Local, d: &Dynamics, com: &[Bern; 3], r: &[Bern; 3], moments: bool, spin: Option<&Spin>) -> Inertial {
    let w = &local.weight;
    let dw = w.derivative();
    let ddw = dw.derivative();
    let w2 = w.mul(w);
    // centre of mass numerator X̂ = P̂ + M̂ c_b; its acceleration's two parts
    let x: [Bern; 3] = per_axis(|i| local.position[i].add(&com[i]));
    let parts: [[Bern; 2]; 3] = each_axis(&x, |x| {
        let x1 = x.derivative();
        let x2 = x1.derivative();
        let first = x1.mul(w).sub(&x.mul(&dw)); // X̂'w − X̂w'
        let second = x2.mul(w).sub(&x.mul(&ddw)); // X̂''w − X̂w''
        [first.mul(w), second.mul(w).sub(&dw.mul(&first).scale(2.0))]
    });
    let accel: [[Bern; 3]; 2] = [0, 1].map(|k| each_axis(&parts, |p| p[k].clone()));
    let force = |a: &[Bern; 3], j: usize| a[j].mul(&w2).scale(-d.mass);
    if !moments {
        let rows = |a: &[Bern; 3]| per_component(|j| if j < 3 { force(a, j) } else { Bern::constant(0.0) });
        return Inertial { accel: rows(&accel[0]), square: rows(&accel[1]) };
    }
    let m = &local.rotation;
    // the inertia's images of Ω̂ and of α̃ (per unit g g', α̃ = Ω̂w; per unit g²), and the
    // gyroscopic Ω̂ × (M̂ I_b M̂ᵀ Ω̂)
    let (i_alpha, gyro) = match spin {
        Some(sp) => {
            // M̂ (I_b k_b), and the scalars θ'w² (Ω̂ per k) and θ''w³ (α̃ per unit g², per k)
            let u = times_const(m, &(d.inertia * sp.body));
            let omega = sp.rate.mul(&w2);
            let alpha_square = sp.rate.derivative().mul(&w2).mul(w);
            let image = |s: &Bern| {
                let sw = s.mul(w);
                each_axis(&u, |p| p.mul(&sw))
            };
            let i_omega = image(&omega);
            // Ω̂ × i_omega = (θ'w²)²·w·(k × M̂ I_b k_b)
            let k_cross_u = cross(&per_axis(|i| Bern::constant(sp.axis[i])), &u);
            let spin_square = omega.mul(&omega).mul(w);
            let gyro = each_axis(&k_cross_u, |p| p.mul(&spin_square));
            ([each_axis(&i_omega, |p| p.mul(w)), image(&alpha_square)], gyro)
        }
        None => {
            // Ω̂ = axial vector of the skew part of M̂'M̂ᵀ
            let dm: [[Bern; 3]; 3] = each_axis(m, |row| each_axis(row, Bern::derivative));
            let a = |i: usize, j: usize| (0..3).fold(Bern::constant(0.0), |acc, k| acc.add(&dm[i][k].mul(&m[j][k])));
            let omega: [Bern; 3] = [a(2, 1).sub(&a(1, 2)).scale(0.5), a(0, 2).sub(&a(2, 0)).scale(0.5), a(1, 0).sub(&a(0, 1)).scale(0.5)];
            // α̃ per unit g²
            let alpha_square: [Bern; 3] = each_axis(&omega, |o| o.derivative().mul(w).sub(&o.mul(&dw).scale(2.0)));
            // M̂ I_b M̂ᵀ v for a polynomial vector v
            let inertia_times = |v: &[Bern; 3]| {
                let body: [Bern; 3] = per_axis(|i| (0..3).fold(Bern::constant(0.0), |acc, k| acc.add(&m[k][i].mul(&v[k]))));
                let ib: [Bern; 3] = per_axis(|i| Bern::linear_combination(&[(&body[0], d.inertia[(i, 0)]), (&body[1], d.inertia[(i, 1)]), (&body[2], d.inertia[(i, 2)])]));
                mat_vec(m, &ib)
            };
            let i_omega = inertia_times(&omega);
            let gyro = cross(&omega, &i_omega);
            ([each_axis(&i_omega, |p| p.mul(w)), inertia_times(&alpha_square)], gyro)
        }
    };
    let rows = |part: usize| -> [Bern; 6] {
        let (acc, i_alpha) = (&accel[part], &i_alpha[part]);
        let r_x_a = cross(r, acc);
        per_component(|j| {
            if j < 3 {
                force(acc, j)
            } else {
                let k = j - 3;
                let moment = r_x_a[k].mul(&w2).scale(-d.mass).sub(&i_alpha[k].mul(w));
                // the gyroscopic moment goes with g²
                if part == 1 { moment.sub(&gyro[k]) } else { moment }
            }
        })
    };
    Inertial { accel: rows(0), square: rows(1) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::conditions::Sweep;
    use crate::model::{Motion, Orientation, Profile, Trajectory, Translation};
    use nalgebra::{Matrix3, Unit, UnitQuaternion, Vector3};

    /// Along a turn (a CASPR spline's), the d'Alembert rows built from the exact rate (the
    /// motion's spin) equal those the enclosure's own derivatives give, to the enclosure's
    /// tolerance, at every point of every stretch: both per unit λ̈ and per unit λ̇².
    #[test]
    fn a_turns_exact_rate_gives_the_enclosures_inertia() {
        let s = crate::Scenario::from_json(include_str!("../../static/scenarios/robocrane-timed.json")).expect("preset");
        let mut load = s.load().expect("the preset has a mass");
        let dynamics = load.dynamics.as_mut().expect("dynamics");
        dynamics.com = Vector3::new(0.05, -0.03, 0.1);
        dynamics.inertia = Matrix3::new(0.4, 0.05, -0.02, 0.05, 0.3, 0.01, -0.02, 0.01, 0.5);
        let turn = Orientation::Turn { from: UnitQuaternion::from_euler_angles(0.2, -0.1, 0.4), axis: Unit::new_normalize(Vector3::new(0.3, 0.5, -0.8)), angle: 1.3, profile: Profile::Quintic };
        let traj = Trajectory::single("turn", Translation::Polynomial([vec![0.1, 0.3, 0.0, -0.2], vec![0.0, -0.1], vec![2.0]]), turn);
        let motions = Motion::trajectory(&traj);
        assert!(motions.len() > 1 && motions.iter().all(|m| m.spin.is_some()));
        for motion in &motions {
            let mut sweep = Sweep::new(&s.robot, motion, 1e-10);
            sweep.duration = Some(1.0);
            let local = Local::of(&sweep, &load);
            let generic = load_polys(&local, &load, true, None);
            let (exact, enclosed) = (local.load.inertial.as_ref().expect("timed"), generic.inertial.as_ref().expect("timed"));
            for (a, b) in exact.accel.iter().zip(&enclosed.accel).chain(exact.square.iter().zip(&enclosed.square)) {
                let size = a.max_abs().max(b.max_abs()).max(1.0);
                for i in 0..=20 {
                    let x = i as f64 / 20.0;
                    assert!((a.value(x) - b.value(x)).abs() <= 1e-6 * size, "{} vs {} at {x}", a.value(x), b.value(x));
                }
            }
        }
    }
}
