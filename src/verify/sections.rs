//! From three-valued violation partitions to the sections users see: feasible and infeasible
//! intervals, certified boundaries with the constraint active at each, and uncertain intervals.

use crate::poly::Truth;
use crate::report::Side;

/// A piece of the parameter range (in user units) with the truth of "violated" on it.
pub type Piece = (f64, f64, Truth);

/// The sections of a range.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Sections {
    /// Feasible intervals.
    pub feasible: Vec<[f64; 2]>,
    /// Infeasible intervals.
    pub infeasible: Vec<[f64; 2]>,
    /// Uncertain intervals.
    pub uncertain: Vec<[f64; 2]>,
    /// Boundaries: position, active constraint(s), side entered.
    pub boundaries: Vec<(f64, String, Side)>,
}

/// Appends a piece, extending the last one instead when it has the same truth.
pub fn push_merged(out: &mut Vec<Piece>, p: Piece) {
    match out.last_mut() {
        Some(last) if last.2 == p.2 => last.1 = p.1,
        _ => out.push(p),
    }
}

/// Resolves narrow undecided pieces between a feasible and an infeasible piece into a boundary at
/// their middle (certified to half their width, at most `tol`); every other undecided piece stays
/// uncertain.
pub fn sections(overall: &[Piece], conditions: &[Vec<Piece>], label: &dyn Fn(usize) -> String, tol: f64) -> Sections {
    let mut resolved: Vec<Piece> = Vec::new();
    for (k, &(a, b, t)) in overall.iter().enumerate() {
        if t == Truth::Unknown && b - a <= tol && k > 0 && k + 1 < overall.len() {
            let (before, after) = (overall[k - 1].2, overall[k + 1].2);
            if before != Truth::Unknown && after != Truth::Unknown && before != after {
                let mid = 0.5 * (a + b);
                if let Some(last) = resolved.last_mut() {
                    last.1 = mid;
                }
                push_merged(&mut resolved, (mid, b, after));
                continue;
            }
        }
        push_merged(&mut resolved, (a, b, t));
    }
    let mut out = Sections::default();
    for (k, &(a, b, t)) in resolved.iter().enumerate() {
        let iv = [a, b];
        match t {
            Truth::False => out.feasible.push(iv),
            Truth::True => out.infeasible.push(iv),
            Truth::Unknown => out.uncertain.push(iv),
        }
        if k > 0 && t != Truth::Unknown && resolved[k - 1].2 != Truth::Unknown {
            let side = if t == Truth::False { Side::Feasible } else { Side::Infeasible };
            out.boundaries.push((a, active_at(conditions, label, a, tol), side));
        }
    }
    out
}

/// The labels (`label` of its index) of the conditions (each one's violation pieces) whose truth
/// changes within `tol` of x, joined with " & ".
fn active_at(conditions: &[Vec<Piece>], label: &dyn Fn(usize) -> String, x: f64, tol: f64) -> String {
    let (lo, hi) = (x - 2.0 * tol, x + 2.0 * tol);
    let names: Vec<String> = conditions
        .iter()
        .enumerate()
        .filter(|(_, pieces)| {
            let mut seen: Vec<Truth> = pieces.iter().filter(|p| p.1 >= lo && p.0 <= hi).map(|p| p.2).collect();
            seen.dedup();
            seen.len() > 1 || seen.contains(&Truth::Unknown)
        })
        .map(|(k, _)| label(k))
        .collect();
    if names.is_empty() {
        "unidentified".to_string()
    } else {
        names.join(" & ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn narrow_unknown_between_sides_becomes_a_boundary() {
        let overall = vec![(0.0, 0.4, Truth::False), (0.4, 0.4 + 1e-12, Truth::Unknown), (0.4 + 1e-12, 1.0, Truth::True)];
        let s = sections(&overall, std::slice::from_ref(&overall), &|_| "cables 1-2".into(), 1e-10);
        assert_eq!(s.feasible.len(), 1);
        assert_eq!(s.infeasible.len(), 1);
        assert!(s.uncertain.is_empty());
        assert_eq!(s.boundaries.len(), 1);
        assert_eq!(s.boundaries[0].1, "cables 1-2");
        assert_eq!(s.boundaries[0].2, Side::Infeasible);
        assert!((s.boundaries[0].0 - 0.4).abs() < 1e-12);
    }

    #[test]
    fn unknown_between_equal_sides_stays_uncertain() {
        let overall = vec![(0.0, 0.4, Truth::False), (0.4, 0.4 + 1e-12, Truth::Unknown), (0.4 + 1e-12, 1.0, Truth::False)];
        let s = sections(&overall, &[], &|_| unreachable!("no condition to name"), 1e-10);
        assert_eq!(s.uncertain.len(), 1);
        assert!(s.boundaries.is_empty());
    }
}
