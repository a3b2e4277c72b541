//! Static feasibility of a multi-link robot in joint space (thesis §3.5.2's static workspace):
//! tensions strictly within their bounds hold the loads on the links, i.e. J f = g with
//! f_min < f < f_max, J's column k the generalised forces of cable k's unit pull and g those of
//! the loads — the weights m·g at the centres of mass and the wrench applied to a link from
//! outside (`wrench` with `link`) — ([`super::joint_forces`]; a cable pulls its link towards the
//! base anchor, so −J f + g = 0 at the passive joints).
//!
//! Per configuration: the largest-margin linear program ([`static_margin_of`]), feasible iff the
//! margin is positive. Along a motion: with s = ŝ/w the cable vector, row r of J's numerators N
//! is over w^(p_r) and divided by |s| = √P/w (P = ŝ·ŝ), the loads' row over w^(p_r − 1), so
//! after multiplying row r by w^(p_r − 1) the system is exactly N φ = G with φ_k = f_k/√P_k —
//! the form the linear programs' certificates of [`super::wrench_lp`] decide for any number of
//! joints and cables (the 1/√P_k enclosed by Taylor polynomials with error bounds). Rows that
//! neither a cable nor a load reaches (a massless link no cable pulls) read 0 = 0 and are left
//! out; a row a load reaches but no cable fails wherever the load's share there is not zero.
//! A routed cable's column is the sum of its segments' n_s/√P_s, enclosed on each piece of the
//! motion as the certificates bisect it ([`super::wrench_lp`]).

use std::rc::Rc;

use super::joint_forces::{cable_matrix, load_numerators, load_vector, routing, shared_cable_numerators};
use super::wrench_lp::{feasibility_violation, structurally_zero};
use super::{Condition, Kind, PoseCheck, Sweep, SweptCable};
use crate::model::{Bounds, CableSegment, Chain};
use crate::poly::{Bern, Partition};
use crate::query::cables::PoseCables;
use crate::query::wrench::static_margin_of;
use nalgebra::{DMatrix, DVector};

/// Joint-space static feasibility of a multi-link robot under its links' weights and the wrench
/// applied to a link.
#[derive(Debug, Clone)]
pub struct JointStatics {
    /// The links, with their masses, gravity and the wrench applied to a link.
    pub chain: Rc<Chain>,
    /// The cables' segments ([`crate::model::Robot::segments`]; one per cable unless routed).
    pub segments: Vec<CableSegment>,
    /// Each cable's tension bounds.
    pub bounds: Vec<Bounds>,
}

impl JointStatics {
    /// The structure matrix (columns: unit pulls) and the loads' generalised forces at one
    /// configuration, without the rows nothing reaches.
    pub fn system(&self, at: &PoseCables) -> (DMatrix<f64>, DVector<f64>) {
        let j = cable_matrix(&self.chain, &self.segments, self.bounds.len(), at);
        let g = load_vector(&self.chain, at);
        let keep: Vec<usize> = (0..j.nrows()).filter(|&r| g[r] != 0.0 || j.row(r).iter().any(|v| *v != 0.0)).collect();
        (j.select_rows(&keep), g.select_rows(&keep))
    }
}

impl Condition for JointStatics {
    fn kind(&self) -> Kind {
        Kind::Tension
    }

    fn label(&self) -> String {
        "static feasibility".to_string()
    }

    fn violation(&self, sweep: &mut Sweep) -> Partition {
        let rows = shared_cable_numerators(&self.chain, &self.segments, sweep);
        let load = load_numerators(&self.chain, sweep);
        let len2 = sweep.cables.iter().map(SweptCable::len2).collect();
        // rows nothing reaches (0 = 0) left out
        let (rows, load): (Vec<Vec<Bern>>, Vec<Bern>) =
            rows.iter().zip(load).filter(|(row, g)| !(structurally_zero(g) && row.iter().all(structurally_zero))).map(|(row, g)| (row.clone(), g)).unzip();
        feasibility_violation(rows, load, len2, self.bounds.clone(), routing(&self.segments, self.bounds.len()), sweep.tol)
    }

    fn check(&self, at: &PoseCables) -> PoseCheck {
        let (j, g) = self.system(at);
        match static_margin_of(&j, &g, &self.bounds) {
            Some((margin, _)) => PoseCheck { violated: !(margin > 0.0), distance: Some(margin) },
            None => PoseCheck { violated: true, distance: None },
        }
    }
}
