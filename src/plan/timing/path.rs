//! The path a timing runs along: a trajectory's motions cut into cells, and at each point of the
//! grid the derivatives the limits take — the pose, and the platform's velocity, acceleration and
//! angular rates per unit of the motion's λ.
//!
//! Each motion has its own λ ∈ [0, 1]; the timing's state on a cell is x = λ̇² of that motion
//! (λ̈ constant on the cell, so x is linear in λ there). Where one motion ends and the next
//! begins, λ changes variable but the trajectory's t runs on smoothly, so x jumps by the factor
//! (dλ_next/dt)² / (dλ/dt)² ([`Cell::factor`]); where two pieces of a trajectory meet at a corner
//! (the velocity per unit t differs on the two sides) the platform must stop ([`Cell::stop`]).

use crate::conditions::TimeLaw;
use crate::model::motion::Param;
use crate::model::{Motion, Pose};
use crate::poly::Bern;
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

/// One cell of the grid: λ ∈ [a, b] of motion `motion`.
#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    /// The motion (index into the trajectory's motions).
    pub motion: usize,
    /// Its start in the motion's λ.
    pub a: f64,
    /// Its end.
    pub b: f64,
    /// x at the start of the next cell per unit of x at the end of this one (1 inside a motion).
    pub factor: f64,
    /// Whether the platform must stand still at this cell's end (a corner, or the path's end).
    pub stop: bool,
    /// How many times the certification halved the grid's cell this one is part of.
    pub depth: u8,
}

impl Cell {
    /// Its two halves: the first flows into the second; the second ends as this one does.
    pub fn halves(&self) -> [Cell; 2] {
        let m = 0.5 * (self.a + self.b);
        let depth = self.depth + 1;
        [Cell { b: m, factor: 1.0, stop: false, depth, ..self.clone() }, Cell { a: m, depth, ..self.clone() }]
    }
}

/// The platform at a point of the path with its rates per unit λ: velocity ṗ = `dp`·λ̇,
/// acceleration p̈ = `dp`·λ̈ + `ddp`·λ̇², angular velocity ω = `omega`·λ̇ and acceleration
/// α = `omega`·λ̈ + `domega`·λ̇² (world frame).
#[derive(Debug, Clone, PartialEq)]
pub struct Jet {
    /// The pose.
    pub pose: Pose,
    /// dp/dλ.
    pub dp: Vector3<f64>,
    /// d²p/dλ².
    pub ddp: Vector3<f64>,
    /// ω per unit λ̇.
    pub omega: Vector3<f64>,
    /// dω/dλ per unit λ̇² (the part of α that does not come from λ̈).
    pub domega: Vector3<f64>,
}

impl Jet {
    /// The platform's motion when λ̇ = √x and λ̈ = u.
    pub fn kinematics(&self, u: f64, x: f64) -> crate::model::Kinematics {
        let v = x.max(0.0).sqrt();
        crate::model::Kinematics { velocity: self.dp * v, acceleration: self.dp * u + self.ddp * x, omega: self.omega * v, alpha: self.omega * u + self.domega * x }
    }
}

/// A motion's polynomials and their first two derivatives, for jets at any λ.
pub struct Rates {
    motion: Motion,
    dpos: [Bern; 3],
    ddpos: [Bern; 3],
    drot: [[Bern; 3]; 3],
    ddrot: [[Bern; 3]; 3],
    dw: Bern,
    ddw: Bern,
}

impl Rates {
    /// The derivatives of `motion`.
    pub fn new(motion: Motion) -> Rates {
        let d = |p: &Bern| p.derivative();
        let dpos = motion.position.each_ref().map(d);
        let ddpos = dpos.each_ref().map(d);
        let drot = motion.rotation.each_ref().map(|r| r.each_ref().map(d));
        let ddrot = drot.each_ref().map(|r| r.each_ref().map(d));
        let dw = motion.weight.derivative();
        let ddw = dw.derivative();
        Rates { motion, dpos, ddpos, drot, ddrot, dw, ddw }
    }

    /// The motion.
    pub fn motion(&self) -> &Motion {
        &self.motion
    }

    /// The jet at λ: with f = F/w, f' = (F'w − Fw')/w² and f'' = (F''w − Fw'')/w² − 2w'f'/w.
    pub fn jet(&self, lam: f64) -> Jet {
        let at = |p: &Bern| p.value(lam);
        let (w, w1, w2) = (at(&self.motion.weight), at(&self.dw), at(&self.ddw));
        let quotient = |f: f64, f1: f64, f2: f64| {
            let d1 = (f1 * w - f * w1) / (w * w);
            (f / w, d1, (f2 * w - f * w2) / (w * w) - 2.0 * w1 * d1 / w)
        };
        let mut p = [Vector3::zeros(); 3];
        for (i, ((f, d1), d2)) in self.motion.position.iter().zip(&self.dpos).zip(&self.ddpos).enumerate() {
            (p[0][i], p[1][i], p[2][i]) = quotient(at(f), at(d1), at(d2));
        }
        let mut r = [Matrix3::zeros(); 3];
        for i in 0..3 {
            for j in 0..3 {
                let (v, d1, d2) = quotient(at(&self.motion.rotation[i][j]), at(&self.drot[i][j]), at(&self.ddrot[i][j]));
                (r[0][(i, j)], r[1][(i, j)], r[2][(i, j)]) = (v, d1, d2);
            }
        }
        // ω = axial(R'Rᵀ); dω/dλ = axial(R''Rᵀ) (R'R'ᵀ is symmetric)
        let axial = |m: Matrix3<f64>| 0.5 * Vector3::new(m[(2, 1)] - m[(1, 2)], m[(0, 2)] - m[(2, 0)], m[(1, 0)] - m[(0, 1)]);
        let rotation = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(r[0]));
        Jet { pose: Pose { position: p[0], rotation }, dp: p[1], ddp: p[2], omega: axial(r[1] * r[0].transpose()), domega: axial(r[2] * r[0].transpose()) }
    }

    /// dλ/dt at λ (t the trajectory's parameter).
    pub fn per_t(&self, lam: f64) -> f64 {
        let law = TimeLaw::uniform(&self.motion.param, 1.0).expect("a trajectory's motion");
        law.square.value(lam).sqrt()
    }
}

/// The cells of a grid of `count` cells (at least one per motion) over `motions`, spread in
/// proportion to each motion's share of t, equal steps of λ within a motion; and the rates of
/// every motion. A corner between motions (the velocity or angular velocity per unit t differs
/// by more than `corner` relative) makes the platform stop there.
pub fn grid(motions: Vec<Motion>, count: usize, corner: f64) -> (Vec<Cell>, Vec<Rates>) {
    let rates: Vec<Rates> = motions.into_iter().map(Rates::new).collect();
    let span = |r: &Rates| match r.motion.param {
        Param::Trajectory { t0, t1, within: (a, b), .. } => (t1 - t0) * (b - a),
        _ => 1.0,
    };
    let whole: f64 = rates.iter().map(span).sum();
    let mut cells = Vec::new();
    for (k, r) in rates.iter().enumerate() {
        let n = ((count as f64 * span(r) / whole).round() as usize).max(1);
        let last = k + 1 == rates.len();
        let (factor, stop) = if last {
            (1.0, true)
        } else {
            let (end, start) = (rates[k].jet(1.0), rates[k + 1].jet(0.0));
            let (g0, g1) = (rates[k].per_t(1.0), rates[k + 1].per_t(0.0));
            // per unit t: velocity dp/dλ·dλ/dt on both sides
            let (v0, v1) = (end.dp * g0, start.dp * g1);
            let (w0, w1) = (end.omega * g0, start.omega * g1);
            let scale = v0.norm().max(v1.norm()).max(w0.norm()).max(w1.norm()).max(1e-300);
            let corner_here = (v0 - v1).norm() > corner * scale || (w0 - w1).norm() > corner * scale;
            ((g1 / g0).powi(2), corner_here)
        };
        for j in 0..n {
            let (a, b) = (j as f64 / n as f64, (j + 1) as f64 / n as f64);
            let end = j + 1 == n;
            cells.push(Cell { motion: k, a, b, factor: if end { factor } else { 1.0 }, stop: end && stop, depth: 0 });
        }
    }
    (cells, rates)
}
