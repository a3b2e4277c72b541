//! Generalised forces of a multi-link robot: what a force applied at a point of a link does to
//! each joint coordinate, per configuration (numbers) and along a motion (polynomials). The
//! cables' columns and the loads (the links' weights, a wrench on a link) are written here, so
//! that the joint-space closure ([`super::joint_closure`]) and the static feasibility
//! ([`super::joint_statics`]) read one definition.
//!
//! A force F at world point x of link k, with a pure moment M, acts on each joint j from the root
//! to k (o_j the joint's origin, R_j its link's rotation; the moment about o_j is
//! (x − o_j) × F + M):
//! * free joint: F and the moment (six rows);
//! * spherical joint: the moment about the ball (three rows: Euler-rate forces are these times a
//!   matrix invertible away from gimbal lock, the same for every force, so equilibrium and
//!   positive spanning read the same either way);
//! * revolute joint about axis e: (R_j e)·moment;
//! * prismatic joint along e: (R_j e)·F;
//! * spatial joint (translation and XYZ Euler angles): as the free joint;
//! * universal joint about a₁ then a₂: (R_p a₁)·moment and (R_j a₂)·moment, R_p the parent's
//!   rotation (the base's for a root link);
//! * planar joint (along u, v, then about w): (R_p u)·F, (R_p v)·F and (R_j w)·moment;
//!
//! and zero to the other joints. Along a motion every link's position and rotation are
//! polynomials over its weight w: a row built from a vector over w^a (the cable vector s, a = 1;
//! a weight m·g or an applied force, a = 0), a moment arm over w (a pure moment is taken times w
//! to match) and an axis over w (a link's or parent link's frame) or constant (a world axis, a
//! root's parent) is a polynomial over w^(a + arm + axis), the same power along the row whatever
//! the force.

use std::rc::Rc;

use super::{body_point, Sweep};
use crate::axes::{each_axis, per_axis};
use crate::model::chain::Frame as LinkFrame;
use crate::model::{CableSegment, Chain, Joint, PointFrame};
use crate::poly::Bern;
use crate::query::cables::PoseCables;
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};

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

/// The arithmetic [`joint_rows`] needs.
struct Ops<T> {
    add: fn(&T, &T) -> T,
    sub: fn(&T, &T) -> T,
    mul: fn(&T, &T) -> T,
}

/// a × b in the caller's arithmetic.
fn cross<T>(a: &[T; 3], b: &[T; 3], ops: &Ops<T>) -> [T; 3] {
    per_axis(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        (ops.sub)(&(ops.mul)(&a[j], &b[k]), &(ops.mul)(&a[k], &b[j]))
    })
}

/// The rows one joint contributes for a force `f` and a moment `moment` about the joint's origin
/// (the force's (x − o) × f, plus any pure moment): per coordinate the force or the moment along
/// the coordinate's world axis (`axis` gives it for the row's frame and axis), in whatever
/// arithmetic the caller uses.
fn joint_rows<T: Clone>(joint: &Joint, f: &[T; 3], moment: &[T; 3], axis: &dyn Fn(Frame, &Vector3<f64>) -> [T; 3], ops: &Ops<T>) -> Vec<T> {
    let dot = |a: &[T; 3], b: &[T; 3]| (ops.add)(&(ops.add)(&(ops.mul)(&a[0], &b[0]), &(ops.mul)(&a[1], &b[1])), &(ops.mul)(&a[2], &b[2]));
    row_axes(joint)
        .into_iter()
        .map(|(turn, frame, e)| {
            let v = if turn { moment } else { f };
            match frame {
                Frame::World(k) => v[k].clone(),
                _ => dot(&axis(frame, &e), v),
            }
        })
        .collect()
}

/// The first row of each link's joint coordinates.
fn first_rows(chain: &Chain) -> Vec<usize> {
    chain.links.iter().scan(0, |row, l| { let at = *row; *row += l.joint.dof(); Some(at) }).collect()
}

/// Adds to `out` (one entry per joint coordinate) the generalised forces of the force `f` at
/// world point `x` of link `on` and of the pure moment `m`, the links at `frames`.
fn add_point_force(chain: &Chain, frames: &[LinkFrame], on: usize, f: &Vector3<f64>, x: &Vector3<f64>, m: &Vector3<f64>, out: &mut [f64]) {
    for ((l, link), row) in chain.links.iter().enumerate().zip(first_rows(chain)) {
        if !chain.descends(on, l) {
            continue;
        }
        let (o, r) = frames[l];
        let parent = link.parent.map_or_else(Matrix3::identity, |p| frames[p].1);
        let axis = |frame: Frame, e: &Vector3<f64>| -> [f64; 3] { (if matches!(frame, Frame::Parent) { parent * e } else { r * e }).into() };
        for (k, v) in joint_rows(&link.joint, &(*f).into(), &((x - o).cross(f) + m).into(), &axis, &NUMBERS).into_iter().enumerate() {
            out[row + k] += v;
        }
    }
}

/// Plain arithmetic for [`joint_rows`].
const NUMBERS: Ops<f64> = Ops { add: |a, b| a + b, sub: |a, b| a - b, mul: |a, b| a * b };

/// As [`add_point_force`] along a sweep's motion: the force's components `f`, the point's X̂
/// (over the sweep's weight w) and the pure moment (`m`, taken times w: a moment about a joint
/// has one power of w more than the force) as polynomials.
fn add_point_force_along(chain: &Chain, sweep: &Sweep, on: usize, f: &[Bern; 3], x: &[Bern; 3], m: Option<&[Bern; 3]>, out: &mut [Bern]) {
    let ops = Ops { add: Bern::add, sub: Bern::sub, mul: Bern::mul };
    for ((l, link), row) in chain.links.iter().enumerate().zip(first_rows(chain)) {
        if !chain.descends(on, l) {
            continue;
        }
        let motion = &sweep.links[l];
        let arm: [Bern; 3] = per_axis(|i| x[i].sub(&motion.position[i]));
        let mut moment = cross(&arm, f, &ops);
        if let Some(m) = m {
            moment = per_axis(|i| moment[i].add(&m[i]));
        }
        let parent = link.parent.map(|p| &sweep.links[p]);
        let axis = |frame: Frame, e: &Vector3<f64>| -> [Bern; 3] {
            match (frame, parent) {
                (Frame::Parent, None) => e.map(Bern::constant).into(),
                (Frame::Parent, Some(p)) => per_axis(|i| (0..3).fold(Bern::constant(0.0), |acc, k| acc.add(&p.rotation[i][k].scale(e[k])))),
                _ => per_axis(|i| (0..3).fold(Bern::constant(0.0), |acc, k| acc.add(&motion.rotation[i][k].scale(e[k])))),
            }
        };
        for (k, v) in joint_rows(&link.joint, f, &moment, &axis, &ops).into_iter().enumerate() {
            out[row + k] = out[row + k].add(&v);
        }
    }
}

/// The cables' structure matrix at one configuration (one row per joint coordinate, one column
/// per cable, `m` cables): column k the generalised forces of cable k's unit pull, up to its
/// sign — the sum over its segments of the segment vector s = x − a at its end x (on the end's
/// link) and −s at its start a (on the start's link, if any), each divided by |s|.
pub(super) fn cable_matrix(chain: &Chain, segments: &[CableSegment], m: usize, at: &PoseCables) -> DMatrix<f64> {
    let mut j = DMatrix::zeros(chain.dof(), m);
    let mut column = vec![0.0; chain.dof()];
    for (seg, &(a, x)) in segments.iter().zip(at.cables.iter()).filter(|(seg, _)| pulls(seg)) {
        column.iter_mut().for_each(|v| *v = 0.0);
        let s = x - a;
        if let Some(l) = seg.to.link {
            add_point_force(chain, &at.links, l, &s, &x, &Vector3::zeros(), &mut column);
        }
        if let Some(l) = seg.from.link {
            add_point_force(chain, &at.links, l, &-s, &a, &Vector3::zeros(), &mut column);
        }
        let len = s.norm();
        for (entry, v) in j.column_mut(seg.cable).iter_mut().zip(&column) {
            *entry += v / len;
        }
    }
    j
}

/// The generalised forces of the loads on the links at one configuration: the weights (m·g at
/// each centre of mass), the wrench applied from outside and the joint forces.
pub(super) fn load_vector(chain: &Chain, at: &PoseCables) -> DVector<f64> {
    let mut out = vec![0.0; chain.dof()];
    for (l, link) in chain.links.iter().enumerate().filter(|(_, l)| l.mass > 0.0) {
        let (p, r) = at.links[l];
        add_point_force(chain, &at.links, l, &(chain.gravity * link.mass), &(p + r * link.com), &Vector3::zeros(), &mut out);
    }
    if let Some(load) = &chain.load {
        let (force, moment, point) = load.at(&at.links[load.link]);
        add_point_force(chain, &at.links, load.link, &force, &point, &moment, &mut out);
    }
    for (v, t) in out.iter_mut().zip(&chain.joint_forces) {
        *v += t;
    }
    DVector::from_vec(out)
}

/// Whether a segment pulls anything: one between two points of the same link (or of the base)
/// pulls both ends of one rigid body together, forces that cancel exactly (left out rather than
/// left to rounding).
fn pulls(seg: &CableSegment) -> bool {
    seg.from.link != seg.to.link
}

/// The cable of each segment when some cable has several (`m` cables), for the linear programs'
/// grouping of segment columns into cable columns; `None` when each cable is one segment.
pub(super) fn routing(segments: &[CableSegment], m: usize) -> Option<Vec<usize>> {
    (segments.len() > m).then(|| segments.iter().map(|s| s.cable).collect())
}

/// [`cable_numerators`] of the sweep, built by the first condition that asks and kept in the
/// sweep for the others (closure and statics read the same rows).
pub(super) fn shared_cable_numerators(chain: &Chain, segments: &[CableSegment], sweep: &mut Sweep) -> Rc<Vec<Vec<Bern>>> {
    if let Some(rows) = &sweep.joint_rows {
        return Rc::clone(rows);
    }
    let rows = Rc::new(cable_numerators(chain, segments, sweep));
    sweep.joint_rows = Some(Rc::clone(&rows));
    rows
}

/// The segments' structure numerators along the sweep's motion, rows[row][segment]: the
/// generalised forces of ŝ at the end X̂ and of −ŝ at the start Â (module docs; s = ŝ/w), as
/// [`cable_matrix`] per segment before the division by |s|, row r over w^(p_r). One column per
/// cable for a robot without routed cables.
fn cable_numerators(chain: &Chain, segments: &[CableSegment], sweep: &Sweep) -> Vec<Vec<Bern>> {
    let (n, m) = (chain.dof(), sweep.cables.len());
    let w = &sweep.motion().weight;
    let mut rows = vec![vec![Bern::constant(0.0); m]; n];
    let mut column = vec![Bern::constant(0.0); n];
    for (c, (cable, seg)) in sweep.cables.iter().zip(segments).enumerate().filter(|(_, (_, seg))| pulls(seg)) {
        column.iter_mut().for_each(|v| *v = Bern::constant(0.0));
        let s: [Bern; 3] = each_axis(&cable.s, |h| h.p.clone());
        if let Some(l) = seg.to.link {
            add_point_force_along(chain, sweep, l, &s, &cable.tip_hat(w), None, &mut column);
        }
        if let Some(l) = seg.from.link {
            add_point_force_along(chain, sweep, l, &each_axis(&s, |p| p.scale(-1.0)), &cable.start_hat(w), None, &mut column);
        }
        for (row, v) in rows.iter_mut().zip(column.iter_mut()) {
            row[c] = std::mem::replace(v, Bern::constant(0.0));
        }
    }
    rows
}

/// The loads' generalised forces along the sweep's motion ([`load_vector`]), one polynomial per
/// row: row r over w^(p_r − 1), one power fewer than the cables' numerators (the loads are
/// constant).
pub(super) fn load_numerators(chain: &Chain, sweep: &Sweep) -> Vec<Bern> {
    let mut out = vec![Bern::constant(0.0); chain.dof()];
    // X̂ = P̂ + M̂ c for a point c in link l's frame, or P̂ + w·c along the world's axes
    let point = |l: usize, c: &Vector3<f64>, frame: PointFrame| -> [Bern; 3] {
        let m = &sweep.links[l];
        match frame {
            PointFrame::Platform => body_point(&m.position, &m.rotation, c),
            PointFrame::World => per_axis(|i| Bern::linear_combination(&[(&m.position[i], 1.0), (&m.weight, c[i])])),
        }
    };
    let constant = |v: Vector3<f64>| -> [Bern; 3] { v.map(Bern::constant).into() };
    for (l, link) in chain.links.iter().enumerate().filter(|(_, l)| l.mass > 0.0) {
        add_point_force_along(chain, sweep, l, &constant(chain.gravity * link.mass), &point(l, &link.com, PointFrame::Platform), None, &mut out);
    }
    if let Some(load) = &chain.load {
        let w = &sweep.links[load.link].weight;
        let moment: [Bern; 3] = per_axis(|i| w.scale(load.nominal[3 + i]));
        add_point_force_along(chain, sweep, load.link, &constant(load.nominal.fixed_rows::<3>(0).into()), &point(load.link, &load.point, load.frame), Some(&moment), &mut out);
    }
    if chain.joint_forces.iter().any(|t| *t != 0.0) {
        let w = &sweep.motion().weight;
        for ((v, t), power) in out.iter_mut().zip(&chain.joint_forces).zip(load_powers(chain)) {
            let scaled = (0..power).fold(Bern::constant(*t), |acc, _| acc.mul(w));
            *v = v.add(&scaled);
        }
    }
    out
}

/// Per row, the power of the motion's weight w the loads' row is over ([`load_numerators`]): a
/// force row's vector is constant and a moment row's arm over w, an axis fixed in a link's
/// frame (its own, or a parent link's) over w and a world axis or the base's constant (module
/// docs) — so that a generalised force τ applied at the row reads τ·w^power there.
fn load_powers(chain: &Chain) -> Vec<u32> {
    chain
        .links
        .iter()
        .flat_map(|link| {
            row_axes(&link.joint).into_iter().map(move |(turn, frame, _)| {
                let axis = match frame {
                    Frame::World(_) => 0,
                    Frame::Parent => u32::from(link.parent.is_some()),
                    Frame::Link => 1,
                };
                u32::from(turn) + axis
            })
        })
        .collect()
}

/// Per link, the rows of its own and its descendants' joint coordinates (only the forces on
/// that subtree reach them).
pub(super) fn subtree_rows(chain: &Chain) -> Vec<Vec<usize>> {
    let links = &chain.links;
    let first = first_rows(chain);
    (0..links.len())
        .map(|l| (0..links.len()).filter(|&k| chain.descends(k, l)).flat_map(|k| first[k]..first[k] + links[k].joint.dof()).collect())
        .collect()
}
