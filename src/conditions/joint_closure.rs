//! Wrench closure of a multi-link robot in joint space: the cables' generalised-force directions
//! positively span the joint-force space, so that positive tensions can produce any joint force
//! (thesis §3.5.2, the WCW of Fig. 3.12(b)).
//!
//! A cable pulling link k at x along s = x − a (towards its tip; the sign is the same for every
//! cable, which positive spanning ignores) contributes to the joints from the root to k the
//! generalised forces of s at x ([`super::joint_forces`]: forces and moments about each joint
//! along its coordinates' axes), and zero to the other joints. The cable's length divides every
//! entry of its column and is dropped (a positive factor per column). Along a motion every row is a polynomial over a power
//! of w (the same power along the row), so the facet test of [`super::closure`] applies with n
//! rows: facets of n − 1 columns, d_k = det [J_S | j_k]. Past [`MAX_FACETS`] facets (C(m, n − 1):
//! a 24-DoF neck with 76 cables has ~10²⁰) the linear programs' certificates decide it instead
//! ([`closure_violation`], [`closure_by_lp`] per configuration): their cost grows polynomially
//! with the joints and the cables. A routed cable's column is the sum of its segments' pulls, each
//! divided by its own length (no common factor to drop): the linear programs decide it.

use std::rc::Rc;

use super::closure::not_spanning;
use super::joint_forces::{cable_matrix, routing, shared_cable_numerators, subtree_rows};
use super::structure::det_with;
use super::wrench_lp::closure_violation;
use super::{Condition, Kind, PoseCheck, Sweep, SweptCable};
use crate::model::{CableSegment, Chain};
use crate::poly::{Bern, Minors, Partition, Truth};
use crate::query::cables::PoseCables;
use crate::query::wrench::{binomial, closure_by_lp, positively_spans, subsets};
use crate::scenario::validate::MAX_FACETS;

/// Joint-space wrench closure of a multi-link robot.
#[derive(Debug, Clone)]
pub struct JointClosure {
    /// The links.
    pub chain: Rc<Chain>,
    /// The cables' segments ([`crate::model::Robot::segments`]; one per cable unless routed).
    pub segments: Vec<CableSegment>,
    /// The number of cables.
    pub cables: usize,
}

impl Condition for JointClosure {
    fn kind(&self) -> Kind {
        Kind::Tension
    }

    fn label(&self) -> String {
        "wrench closure".to_string()
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let tol = sweep.tol;
        let rows = shared_cable_numerators(&self.chain, &self.segments, sweep);
        let (n, m) = (rows.len(), self.cables);
        if m <= n {
            return Partition::constant(Truth::True); // m ≤ n cables never positively span ℝⁿ
        }
        if let Some(cable_of) = routing(&self.segments, m) {
            // a routed cable's column is no polynomial multiple: the linear programs' certificates
            let len2 = sweep.cables.iter().map(SweptCable::len2).collect();
            return closure_violation(rows.as_ref().clone(), len2, Some(cable_of), tol, &subtree_rows(&self.chain));
        }
        if binomial(m, n - 1) > MAX_FACETS {
            // too many facets to enumerate: the linear programs' certificates, failures looked
            // for within each link's subtree as well
            return closure_violation(rows.as_ref().clone(), vec![Bern::constant(1.0); m], None, tol, &subtree_rows(&self.chain));
        }
        let mut minors_of = Minors::new(&rows);
        let facets = subsets(m, n - 1).into_iter().map(|s| {
            let minors = minors_of.of(&s);
            (0..m).filter(|k| !s.contains(k)).map(|k| det_with(&minors, &rows.iter().map(|r| &r[k]).collect::<Vec<_>>())).collect()
        });
        not_spanning(facets, tol)
    }

    fn check(&self, at: &PoseCables) -> PoseCheck {
        let j = cable_matrix(&self.chain, &self.segments, self.cables, at);
        let (n, m) = j.shape();
        let spans = if m > n && binomial(m, n - 1) > MAX_FACETS { closure_by_lp(&j) } else { positively_spans(&j) };
        PoseCheck { violated: !spans, distance: None }
    }
}
