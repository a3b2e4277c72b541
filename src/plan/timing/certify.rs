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

/// The verdict on each of `cells` (indices `which`) run with `law` (x at each cell's start and
/// end), on every core natively.
pub fn verdicts(s: &Scenario, cells: &[Cell], rates: &[Rates], law: &[(f64, f64)], which: &[usize]) -> Vec<Verdict> {
    crate::parallel::map_with(which.len(), || speed_conditions(s), |conditions, k| {
        let i = which[k];
        verdict(s, conditions, &cells[i], &rates[cells[i].motion], law[i])
    })
}

fn verdict(s: &Scenario, conditions: &[Box<dyn Condition>], cell: &Cell, rates: &Rates, (x0, x1): (f64, f64)) -> Verdict {
    let part = rates.motion().part(cell.a, cell.b);
    let width2 = (cell.b - cell.a).powi(2);
    let mut sweep = Sweep::new(&s.robot, &part, CELL_TOL);
    sweep.duration = Some(1.0);
    sweep.law = Some(TimeLaw::from_square(Bern::from_bernstein(vec![x0 / width2, x1 / width2])));
    let (mut failed, mut open) = (Vec::new(), Vec::new());
    for c in conditions {
        let v = c.violation(&mut sweep);
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
