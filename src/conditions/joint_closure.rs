//! Wrench closure of a multi-link robot in joint space: the cables' generalised-force directions
//! positively span the joint-force space, so that positive tensions can produce any joint force
//! (thesis §3.5.2, the WCW of Fig. 3.12(b)).
//!
//! A cable pulling link k at world point x along s = x − a (towards its tip; the sign is the same
//! for every cable, which positive spanning ignores) contributes to each joint j from the root to k
//! (o_j the joint's origin, R_j its link's rotation):
//! * free joint: s and (x − o_j) × s (six rows);
//! * spherical joint: (x − o_j) × s, the moment about the ball (three rows: Euler-rate forces are
//!   these times an invertible matrix away from gimbal lock, which positive spanning ignores);
//! * revolute joint about axis e: (R_j e)·((x − o_j) × s);
//! * prismatic joint along e: (R_j e)·s;
//!
//! and zero to the other joints. The cable's length divides every entry of its column and is
//! dropped (a positive factor per column). Along a motion every row is a polynomial over a power
//! of w (the same power along the row), so the facet test of [`super::closure`] applies with n
//! rows: facets of n − 1 columns, d_k = det [J_S | j_k].

use std::rc::Rc;

use super::algebra::H;
use super::closure::not_spanning;
use super::structure::{det_with, minors};
use super::{Condition, Kind, PoseCheck, Sweep};
use crate::model::{Chain, Joint};
use crate::poly::{Bern, Partition, Truth};
use crate::query::cables::PoseCables;
use crate::query::wrench::{positively_spans, subsets};
use nalgebra::{DMatrix, Vector3};

/// Joint-space wrench closure of a multi-link robot.
#[derive(Debug, Clone)]
pub struct JointClosure {
    /// The links.
    pub chain: Rc<Chain>,
    /// The link each cable pulls.
    pub cable_links: Vec<usize>,
}

/// The rows one joint contributes for a cable: from the cable vector s, the moment arm
/// x − o and the joint's world axis (when it has one), in whatever arithmetic the caller uses.
fn joint_rows<T: Clone>(joint: &Joint, s: [T; 3], arm: [T; 3], axis: Option<[T; 3]>, ops: &Ops<T>) -> Vec<T> {
    let cross = |a: &[T; 3], b: &[T; 3]| {
        [0, 1, 2].map(|i| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            (ops.sub)(&(ops.mul)(&a[j], &b[k]), &(ops.mul)(&a[k], &b[j]))
        })
    };
    let dot = |a: &[T; 3], b: &[T; 3]| (ops.add)(&(ops.add)(&(ops.mul)(&a[0], &b[0]), &(ops.mul)(&a[1], &b[1])), &(ops.mul)(&a[2], &b[2]));
    match joint {
        Joint::Free => {
            let m = cross(&arm, &s);
            s.into_iter().chain(m).collect()
        }
        Joint::Spherical => cross(&arm, &s).into_iter().collect(),
        Joint::Revolute(_) => vec![dot(&axis.expect("a revolute joint has an axis"), &cross(&arm, &s))],
        Joint::Prismatic(_) => vec![dot(&axis.expect("a prismatic joint has an axis"), &s)],
    }
}

/// The arithmetic [`joint_rows`] needs.
struct Ops<T> {
    add: fn(&T, &T) -> T,
    sub: fn(&T, &T) -> T,
    mul: fn(&T, &T) -> T,
}

fn joint_axis(joint: &Joint) -> Option<Vector3<f64>> {
    match joint {
        Joint::Revolute(e) | Joint::Prismatic(e) => Some(*e),
        Joint::Free | Joint::Spherical => None,
    }
}

impl JointClosure {
    /// The structure matrix (one row per joint coordinate, one column per cable) at one
    /// configuration, from the cables and link frames there.
    fn matrix(&self, at: &PoseCables) -> DMatrix<f64> {
        let n = self.chain.dof();
        let m = at.cables.len();
        let ops = Ops { add: |a: &f64, b: &f64| a + b, sub: |a: &f64, b: &f64| a - b, mul: |a: &f64, b: &f64| a * b };
        let mut j = DMatrix::zeros(n, m);
        for (c, &(a, x)) in at.cables.iter().enumerate() {
            let s = x - a;
            let mut row = 0;
            for (l, link) in self.chain.links.iter().enumerate() {
                if self.chain.descends(self.cable_links[c], l) {
                    let (o, r) = at.links[l];
                    let axis = joint_axis(&link.joint).map(|e| (r * e).into());
                    for (k, v) in joint_rows(&link.joint, s.into(), (x - o).into(), axis, &ops).into_iter().enumerate() {
                        j[(row + k, c)] = v;
                    }
                }
                row += link.joint.dof();
            }
        }
        j
    }

    /// The structure numerators along the sweep's motion: rows[row][cable].
    fn numerators(&self, sweep: &Sweep) -> Vec<Vec<Bern>> {
        let n = self.chain.dof();
        let m = sweep.cables.len();
        let w = &sweep.motion().weight;
        let ops = Ops { add: Bern::add, sub: Bern::sub, mul: Bern::mul };
        let mut rows = vec![vec![Bern::constant(0.0); m]; n];
        for (c, cable) in sweep.cables.iter().enumerate() {
            let s: [Bern; 3] = cable.s.each_ref().map(|h: &H| h.p.clone());
            // x̂ = ŝ + a·w
            let x: [Bern; 3] = [0, 1, 2].map(|i| s[i].add(&w.scale(cable.base[i])));
            let mut row = 0;
            for (l, link) in self.chain.links.iter().enumerate() {
                if self.chain.descends(self.cable_links[c], l) {
                    let motion = &sweep.links[l];
                    let arm: [Bern; 3] = [0, 1, 2].map(|i| x[i].sub(&motion.position[i]));
                    let axis = joint_axis(&link.joint)
                        .map(|e| [0, 1, 2].map(|i| (0..3).fold(Bern::constant(0.0), |acc, k| acc.add(&motion.rotation[i][k].scale(e[k])))));
                    for (k, v) in joint_rows(&link.joint, s.clone(), arm, axis, &ops).into_iter().enumerate() {
                        rows[row + k][c] = v;
                    }
                }
                row += link.joint.dof();
            }
        }
        rows
    }
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
        let rows = self.numerators(sweep);
        let (n, m) = (rows.len(), sweep.cables.len());
        if m <= n {
            return Partition::constant(Truth::True); // m ≤ n cables never positively span ℝⁿ
        }
        let facets = subsets(m, n - 1).into_iter().map(|s| {
            let minors = minors(&rows, &s);
            (0..m).filter(|k| !s.contains(k)).map(|k| det_with(&minors, &rows.iter().map(|r| &r[k]).collect::<Vec<_>>())).collect()
        });
        not_spanning(facets, tol)
    }

    fn check(&self, at: &PoseCables) -> PoseCheck {
        PoseCheck { violated: !positively_spans(&self.matrix(at)), distance: None }
    }
}
