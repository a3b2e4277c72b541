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
//! * spatial joint (translation and XYZ Euler angles): as the free joint;
//! * universal joint about a₁ then a₂: (R_p a₁)·((x − o_j) × s) and (R_j a₂)·((x − o_j) × s),
//!   R_p the parent's rotation (the base's for a root link);
//! * planar joint (along u, v, then about w): (R_p u)·s, (R_p v)·s and (R_j w)·((x − o_j) × s);
//!
//! and zero to the other joints. The cable's length divides every entry of its column and is
//! dropped (a positive factor per column). Along a motion every row is a polynomial over a power
//! of w (the same power along the row), so the facet test of [`super::closure`] applies with n
//! rows: facets of n − 1 columns, d_k = det [J_S | j_k]. Past [`MAX_FACETS`] facets (C(m, n − 1):
//! a 24-DoF neck with 76 cables has ~10²⁰) the linear programs' certificates decide it instead
//! ([`closure_violation`], [`closure_by_lp`] per configuration): their cost grows polynomially
//! with the joints and the cables.

use std::rc::Rc;

use super::algebra::H;
use super::closure::not_spanning;
use super::structure::{det_with, minors};
use super::{Condition, Kind, PoseCheck, Sweep};
use crate::model::{Chain, Joint};
use crate::poly::{Bern, Partition, Truth};
use crate::query::cables::PoseCables;
use super::wrench_lp::closure_violation;
use crate::query::wrench::{binomial, closure_by_lp, positively_spans, subsets};
use crate::scenario::validate::MAX_FACETS;
use nalgebra::{DMatrix, Vector3};

/// Joint-space wrench closure of a multi-link robot.
#[derive(Debug, Clone)]
pub struct JointClosure {
    /// The links.
    pub chain: Rc<Chain>,
    /// The link each cable pulls.
    pub cable_links: Vec<usize>,
}

/// The frame a joint row's axis is fixed in.
#[derive(Debug, Clone, Copy)]
enum Frame {
    /// The world's own axis number k (a free, spatial or spherical joint's rows: the force and
    /// the moment themselves).
    World(usize),
    /// The parent link's frame (the base's for a root link): a universal joint's first axis, a
    /// planar joint's translations.
    Parent,
    /// The link's own frame: a revolute or prismatic axis, the last rotation of a universal or
    /// planar joint (which leaves its own axis in place).
    Link,
}

/// Per joint coordinate: whether it turns (a moment row) or slides (a force row), the frame its
/// axis is fixed in and the axis there (module docs).
fn row_axes(joint: &Joint) -> Vec<(bool, Frame, Vector3<f64>)> {
    let world = |turn: bool| (0..3).map(move |k| (turn, Frame::World(k), Vector3::ith(k, 1.0)));
    match joint {
        Joint::Free | Joint::Spatial => world(false).chain(world(true)).collect(),
        Joint::Spherical => world(true).collect(),
        Joint::Revolute(e) => vec![(true, Frame::Link, *e)],
        Joint::Prismatic(e) => vec![(false, Frame::Link, *e)],
        Joint::Universal([a, b]) => vec![(true, Frame::Parent, *a), (true, Frame::Link, *b)],
        Joint::Planar([u, v, w]) => vec![(false, Frame::Parent, *u), (false, Frame::Parent, *v), (true, Frame::Link, *w)],
    }
}

/// The rows one joint contributes for a cable: from the cable vector s and the moment arm x − o,
/// per coordinate its force s or moment (x − o) × s along the coordinate's world axis (`axis`
/// gives it for the row's frame and axis), in whatever arithmetic the caller uses.
fn joint_rows<T: Clone>(joint: &Joint, s: [T; 3], arm: [T; 3], axis: &dyn Fn(Frame, &Vector3<f64>) -> [T; 3], ops: &Ops<T>) -> Vec<T> {
    let cross = |a: &[T; 3], b: &[T; 3]| {
        [0, 1, 2].map(|i| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            (ops.sub)(&(ops.mul)(&a[j], &b[k]), &(ops.mul)(&a[k], &b[j]))
        })
    };
    let dot = |a: &[T; 3], b: &[T; 3]| (ops.add)(&(ops.add)(&(ops.mul)(&a[0], &b[0]), &(ops.mul)(&a[1], &b[1])), &(ops.mul)(&a[2], &b[2]));
    let moment = cross(&arm, &s);
    row_axes(joint)
        .into_iter()
        .map(|(turn, frame, e)| {
            let v = if turn { &moment } else { &s };
            match frame {
                Frame::World(k) => v[k].clone(),
                _ => dot(&axis(frame, &e), v),
            }
        })
        .collect()
}

/// The arithmetic [`joint_rows`] needs.
struct Ops<T> {
    add: fn(&T, &T) -> T,
    sub: fn(&T, &T) -> T,
    mul: fn(&T, &T) -> T,
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
                    let parent = link.parent.map_or_else(nalgebra::Matrix3::identity, |p| at.links[p].1);
                    let axis = |frame: Frame, e: &Vector3<f64>| -> [f64; 3] { (if matches!(frame, Frame::Parent) { parent * e } else { r * e }).into() };
                    for (k, v) in joint_rows(&link.joint, s.into(), (x - o).into(), &axis, &ops).into_iter().enumerate() {
                        j[(row + k, c)] = v;
                    }
                }
                row += link.joint.dof();
            }
        }
        j
    }

    /// Per link, the rows of its own and its descendants' joint coordinates (only the cables
    /// pulling that subtree reach them).
    fn subtree_rows(&self) -> Vec<Vec<usize>> {
        let links = &self.chain.links;
        let first: Vec<usize> = links.iter().scan(0, |row, l| { let at = *row; *row += l.joint.dof(); Some(at) }).collect();
        (0..links.len())
            .map(|l| (0..links.len()).filter(|&k| self.chain.descends(k, l)).flat_map(|k| first[k]..first[k] + links[k].joint.dof()).collect())
            .collect()
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
                    let parent = link.parent.map(|p| &sweep.links[p]);
                    let axis = |frame: Frame, e: &Vector3<f64>| -> [Bern; 3] {
                        match (frame, parent) {
                            (Frame::Parent, None) => e.map(Bern::constant).into(),
                            (Frame::Parent, Some(p)) => [0, 1, 2].map(|i| (0..3).fold(Bern::constant(0.0), |acc, k| acc.add(&p.rotation[i][k].scale(e[k])))),
                            _ => [0, 1, 2].map(|i| (0..3).fold(Bern::constant(0.0), |acc, k| acc.add(&motion.rotation[i][k].scale(e[k])))),
                        }
                    };
                    for (k, v) in joint_rows(&link.joint, s.clone(), arm, &axis, &ops).into_iter().enumerate() {
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
        if binomial(m, n - 1) > MAX_FACETS {
            // too many facets to enumerate: the linear programs' certificates, failures looked
            // for within each link's subtree as well
            return closure_violation(rows, tol, &self.subtree_rows());
        }
        let facets = subsets(m, n - 1).into_iter().map(|s| {
            let minors = minors(&rows, &s);
            (0..m).filter(|k| !s.contains(k)).map(|k| det_with(&minors, &rows.iter().map(|r| &r[k]).collect::<Vec<_>>())).collect()
        });
        not_spanning(facets, tol)
    }

    fn check(&self, at: &PoseCables) -> PoseCheck {
        let j = self.matrix(at);
        let (n, m) = j.shape();
        let spans = if m > n && binomial(m, n - 1) > MAX_FACETS { closure_by_lp(&j) } else { positively_spans(&j) };
        PoseCheck { violated: !spans, distance: None }
    }
}
