//! The exact verification of a timed law, cell by cell: on cell [a, b] of a motion the law has
//! λ̇² linear in λ, so with the cell's own λ' = (λ − a)/(b − a) it is λ'̇² = x(λ)/(b − a)², a
//! polynomial, and every speed-dependent condition (tensions under weight and inertia, winch and
//! speed limits) is decided by the same exact verifier as any timed trajectory
//! ([`crate::conditions::TimeLaw`]).

use super::path::{Cell, Rates};
use crate::conditions::{Condition, Sweep, TimeLaw};
use crate::poly::{Bern, Truth};
use crate::scenario::Scenario;
use crate::verify::timing::speed_conditions;

/// Width (in a cell's λ') below which a stretch is left undecided.
const CELL_TOL: f64 = 1e-7;

/// The verdict on one cell.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// Every speed-dependent condition certified to hold on the whole cell.
    Holds,
    /// Certainly violated somewhere on the cell: the conditions violated.
    Fails(Vec<String>),
    /// Not violated, but not certified everywhere either: the conditions left undecided.
    Undecided(Vec<String>),
}

/// Chunks of consecutive cells each core takes at a time: enough to balance the cores (cells near
/// a spline's knots take far longer than others), few enough that each motion's polynomials are
/// prepared only a few times.
const CHUNKS: usize = 16;

/// The verdict on each of `cells` (indices `which`) run with `law` (x at each cell's start and
/// end), on every core natively: in chunks of consecutive cells, each preparing the conditions'
/// polynomials once along each motion it meets and restricting them to each cell
/// ([`Sweep::part`]).
pub fn verdicts(s: &Scenario, cells: &[Cell], rates: &[Rates], law: &[(f64, f64)], which: &[usize]) -> Vec<Verdict> {
    let size = which.len().div_ceil(CHUNKS).max(1);
    let chunks: Vec<&[usize]> = which.chunks(size).collect();
    let per_chunk = crate::parallel::map_with(chunks.len(), || speed_conditions(s), |conditions, k| {
        let mut wholes: Vec<(usize, Sweep)> = Vec::new();
        chunks[k]
            .iter()
            .map(|&i| {
                let motion = cells[i].motion;
                let k = wholes.iter().position(|(m, _)| *m == motion).unwrap_or_else(|| {
                    wholes.push((motion, prepared(s, conditions, &rates[motion])));
                    wholes.len() - 1
                });
                verdict(conditions, &wholes[k].1, &cells[i], law[i])
            })
            .collect::<Vec<_>>()
    });
    per_chunk.into_iter().flatten().collect()
}

/// The sweep along a whole motion, timed, with every condition's polynomials built.
fn prepared(s: &Scenario, conditions: &[Box<dyn Condition>], rates: &Rates) -> Sweep {
    let mut sweep = Sweep::new(&s.robot, rates.motion(), CELL_TOL);
    sweep.duration = Some(1.0);
    for c in conditions {
        c.prepare(&mut sweep);
    }
    sweep
}

fn verdict(conditions: &[Box<dyn Condition>], whole: &Sweep, cell: &Cell, (x0, x1): (f64, f64)) -> Verdict {
    let width2 = (cell.b - cell.a).powi(2);
    let mut sweep = whole.part((cell.a, cell.b), Some(TimeLaw::from_square(Bern::from_bernstein(vec![x0 / width2, x1 / width2]))));
    let (mut failed, mut open) = (Vec::new(), Vec::new());
    for c in conditions {
        let v = c.decided(&mut sweep);
        if !v.where_is(Truth::True).is_empty() {
            failed.push(c.label());
        } else if !v.where_is(Truth::Unknown).is_empty() {
            open.push(c.label());
        }
    }
    if !failed.is_empty() {
        Verdict::Fails(failed)
    } else if !open.is_empty() {
        Verdict::Undecided(open)
    } else {
        Verdict::Holds
    }
}
