//! Time along a timed trajectory: its sections in seconds, and the least uniform time scale at
//! which the conditions that depend on speed hold throughout, certified.
//!
//! Under a uniform time scale k (every duration × k) velocities scale by 1/k and accelerations
//! by 1/k², so at each λ the tension conditions (the load is w_rest + w_inertial/k²) and the winch
//! limits (l̇² ∝ 1/k², l̈ ∝ 1/k²) are each linear in u = 1/k²: the scales that work at one λ
//! form an interval of u (holding 0 where the robot holds at rest), and so do the scales that
//! work along the whole trajectory. Its ends — the least k, and the largest where the rest fails —
//! are therefore found by bisection in k, each step an exact verification of those conditions
//! (certified feasible, certainly violated, or undecided). A spline that stops at a knot (zero
//! velocity and acceleration) stops there at every timing: if it fails at rest around that knot,
//! no scale helps, and the answer is "none" without a search.

use super::sections::{sections, Sections};
use super::{one_link, pieces_on, sweeps, Along, BOUNDARY_TOL};
use crate::conditions::{for_scenario, Condition, Kind, Sweep};
use crate::model::{Motion, Trajectory};
use crate::poly::Truth;
use crate::report::Seconds;
use crate::scenario::Scenario;

/// The `min_time_scale_note` of a report made without the search of the least time scale
/// ([`super::verify_sections`], a live update).
pub const NOT_SEARCHED: &str = "not searched here: the least time scale comes from the exact verification with its search (cablenav verify)";

/// Relative width of the bracket [k_lo, k_hi] the bisection stops at.
pub const SCALE_TOL: f64 = 1e-4;

/// Width (in t) below which the scale search leaves a piece undecided. A verdict at one scale
/// needs no boundary to [`BOUNDARY_TOL`]; near the least scale the trajectory grazes the boundary
/// over a stretch whose margin is below the enclosures' rounding, and resolving that stretch at
/// 1e-10 cost thousands of pieces per scale tried.
const VERDICT_TOL: f64 = 1e-7;

/// Largest and smallest scales tried: beyond them the answer is reported as such.
const SCALE_RANGE: (f64, f64) = (1e-6, 1e6);

/// The verdict on the speed-dependent conditions at one time scale.
#[derive(Debug, Clone, PartialEq)]
enum Verdict {
    /// Certified to hold along the whole trajectory.
    Holds,
    /// Certainly violated somewhere; the constraint at the first violated stretch.
    Fails(String),
    /// Neither could be certified.
    Undecided,
}

/// The speed-dependent conditions of `s`: tensions (under weight and inertia) and winch limits.
pub(crate) fn speed_conditions(s: &Scenario) -> Vec<Box<dyn Condition>> {
    for_scenario(s).into_iter().filter(|c| matches!(c.kind(), Kind::Tension | Kind::Winch)).collect()
}

/// The sections of `conditions` along `sweeps` run in `duration` seconds (`None`: at rest; the
/// sweeps must have been made at rest then, timed otherwise: the expansions the conditions keep
/// in the sweeps serve every duration), and the verdict, which names the conditions certainly
/// violated just inside the first infeasible section.
fn sections_at(conditions: &[Box<dyn Condition>], sweeps: &mut [Sweep], duration: Option<f64>) -> (Sections, Verdict) {
    for sweep in sweeps.iter_mut() {
        sweep.duration = duration;
    }
    let (overall, per) = pieces_on(conditions, sweeps, true);
    let sec = sections(&overall, &per, &|k| conditions[k].label(), BOUNDARY_TOL);
    let verdict = if let Some(&[a, b]) = sec.infeasible.first() {
        let at = a + (0.5 * (b - a)).min(1e-6);
        let names: Vec<String> = per
            .iter()
            .enumerate()
            .filter(|(_, pieces)| pieces.iter().any(|&(x, y, t)| t == Truth::True && x <= at && at <= y))
            .map(|(k, _)| conditions[k].label())
            .collect();
        Verdict::Fails(format!("{} from t = {a:.9}", names.join(", ")))
    } else if sec.uncertain.is_empty() {
        Verdict::Holds
    } else {
        Verdict::Undecided
    };
    (sec, verdict)
}

/// The sections `t` (in the trajectory's t ∈ [0, 1]) in seconds.
fn in_seconds(v: &[[f64; 2]], duration: f64) -> Vec<[f64; 2]> {
    v.iter().map(|iv| [iv[0] * duration, iv[1] * duration]).collect()
}

/// The `seconds` part of a report along `along`, if it is a timed trajectory: its sections `sec`
/// (in t) in seconds and, when `scale` is true, its least certified time scale (the point-wise
/// baseline passes false).
pub(super) fn seconds(s: &Scenario, along: Along, sec: &Sections, scale: bool) -> Option<Box<Seconds>> {
    let Along::Trajectory(traj) = along else { return None };
    let duration = traj.duration?;
    let mut out = Seconds {
        duration,
        feasible: in_seconds(&sec.feasible, duration),
        infeasible: in_seconds(&sec.infeasible, duration),
        uncertain: in_seconds(&sec.uncertain, duration),
        min_time_scale: None,
        min_time_scale_bracket: None,
        min_duration: None,
        max_time_scale: None,
        min_time_scale_note: NOT_SEARCHED.to_string(),
        infeasible_at_rest: Vec::new(),
    };
    if scale {
        min_time_scale(s, traj, duration, &mut out);
    }
    Some(Box::new(out))
}

/// Fills in the least time scale of `traj` (run in `duration` seconds). The scales that work
/// form an interval (module docs): if the trajectory holds at rest, every scale above the least
/// one; otherwise (inertia helps somewhere — a fast swing keeps a cable taut that hangs slack at
/// rest) at most a bounded interval, whose upper end is reported too. A scale that holds is
/// found first (halving from 1 when the rest holds; else trying 1, ½, 2, ¼, 4, …), then each end
/// is bracketed by doubling or halving and bisected.
fn min_time_scale(s: &Scenario, traj: &Trajectory, duration: f64, out: &mut Seconds) {
    let conditions = speed_conditions(s);
    if conditions.is_empty() {
        out.min_time_scale_note = "no condition depends on speed (the scenario has no platform dynamics and no winch limits)".to_string();
        return;
    }
    let motions = one_link(Motion::trajectory(traj));
    let (at_rest, rest_verdict) = sections_at(&conditions, &mut sweeps(s, &motions, BOUNDARY_TOL, None), None);
    out.infeasible_at_rest = at_rest.infeasible.clone();
    let rest_holds = rest_verdict == Verdict::Holds;
    if let Some((j, t)) = stop_inside(traj, &at_rest.infeasible) {
        // there the platform stands still at every timing: no scale can help
        out.min_time_scale_note = format!(
            "none: at knot {j} (t = {t:.6}, {:.6} s) the platform stops whatever the timing, and it fails at rest there (t ∈ {})",
            t * duration,
            list(&at_rest.infeasible)
        );
        return;
    }
    let mut timed = sweeps(s, &motions, VERDICT_TOL, Some(duration));
    let mut check = |k: f64| sections_at(&conditions, &mut timed, Some(duration * k)).1;
    // a scale that holds: 1, 2, 4, … when the rest holds (slower always helps then); else 1, ½,
    // 2, ¼, 4, …
    let tries: Vec<f64> = if rest_holds {
        (0..=20).map(|j| 2f64.powi(j)).collect()
    } else {
        (0..=40).map(|j| if j % 2 == 0 { 2f64.powi(j / 2) } else { 0.5f64.powi(j / 2 + 1) }).collect()
    };
    let mut held = None;
    for &k in &tries {
        match check(k) {
            Verdict::Holds => {
                held = Some(k);
                break;
            }
            Verdict::Fails(_) | Verdict::Undecided => {}
        }
    }
    let Some(k_hold) = held else {
        out.min_time_scale_note = match rest_verdict {
            Verdict::Fails(c) => format!("none: at rest the trajectory fails ({c}) on t ∈ {}, and no scale from 2^-20 to 2^20 is certified to hold", list(&at_rest.infeasible)),
            Verdict::Holds => "none certified: it holds at rest, but no scale up to 2^20 was certified to hold (uncertain stretches)".to_string(),
            Verdict::Undecided => format!("none certified: at rest the tensions are uncertain on t ∈ {}", list(&at_rest.uncertain)),
        };
        return;
    };
    let (lower, binding) = edge(&mut check, k_hold, 0.5, SCALE_RANGE.0);
    out.min_time_scale = Some(lower.holds);
    out.min_time_scale_bracket = Some([lower.fails.unwrap_or(0.0), lower.holds]);
    out.min_duration = Some(lower.holds * duration);
    out.min_time_scale_note = match (&binding, lower.fails) {
        (Some(c), Some(k)) => format!("binding: {c} (certainly violated at k = {k})"),
        (_, None) if lower.holds < 2.0 * SCALE_RANGE.0 => format!("holds down to k = {:e}, the smallest scale tried: speed hardly matters", lower.holds),
        _ => "certified at the scale found; nothing failing below it was certified".to_string(),
    };
    if !rest_holds {
        let (upper, binding) = edge(&mut check, k_hold, 2.0, SCALE_RANGE.1);
        out.max_time_scale = Some(upper.holds);
        let rest = match rest_verdict {
            Verdict::Fails(c) => format!("at rest it fails ({c})"),
            _ => "at rest it is uncertain".to_string(),
        };
        out.min_time_scale_note += &format!(
            "; slower than k = {} it fails too{}: {rest}, so only scales in [{}, {}] are certified",
            upper.holds,
            binding.map_or(String::new(), |c| format!(" ({c})")),
            lower.holds,
            upper.holds
        );
    }
}

/// One end of the interval of scales that hold: `holds` certified, `fails` (if found) certainly
/// violated, within [`SCALE_TOL`] of each other.
struct End {
    holds: f64,
    fails: Option<f64>,
}

/// The end of the scales that hold reached from `k_hold` by multiplying with `step` (½: the
/// least scale, 2: the largest), no further than `limit`; the condition violated past it.
fn edge(check: &mut impl FnMut(f64) -> Verdict, k_hold: f64, step: f64, limit: f64) -> (End, Option<String>) {
    let (mut holds, mut fails, mut binding) = (k_hold, None, None);
    // bracket: step away until a scale does not hold
    let mut k = k_hold;
    let mut far = loop {
        k *= step;
        if (step < 1.0 && k < limit) || (step > 1.0 && k > limit) {
            return (End { holds, fails }, binding);
        }
        match check(k) {
            Verdict::Holds => holds = k,
            Verdict::Fails(c) => {
                (fails, binding) = (Some(k), Some(c));
                break k;
            }
            Verdict::Undecided => break k,
        }
    };
    // bisect between holds and far
    while (holds - far).abs() > SCALE_TOL * holds.max(far) {
        let mid = 0.5 * (holds + far);
        match check(mid) {
            Verdict::Holds => holds = mid,
            Verdict::Fails(c) => {
                (far, fails, binding) = (mid, Some(mid), Some(c));
            }
            // not certified either way: narrow without claiming a failure
            Verdict::Undecided => far = mid,
        }
    }
    (End { holds, fails }, binding)
}

/// A knot where the trajectory stops at every timing (a quintic spline's knot with zero velocity
/// and acceleration: its turn stops there too) strictly inside one of the stretches `infeasible`
/// at rest: its index and t.
fn stop_inside(traj: &Trajectory, infeasible: &[[f64; 2]]) -> Option<(usize, f64)> {
    let knots = traj.knots.as_ref().filter(|k| k.profile == crate::model::Profile::Quintic)?;
    let start = knots.points.first()?.time;
    let duration = knots.duration();
    knots.points.iter().enumerate().find_map(|(j, k)| {
        let t = (k.time - start) / duration;
        let stops = k.velocity == nalgebra::Vector3::zeros() && k.acceleration == nalgebra::Vector3::zeros();
        (stops && infeasible.iter().any(|iv| iv[0] < t && t < iv[1])).then_some((j, t))
    })
}

fn list(v: &[[f64; 2]]) -> String {
    v.iter().map(|iv| format!("[{:.6}, {:.6}]", iv[0], iv[1])).collect::<Vec<_>>().join(", ")
}
