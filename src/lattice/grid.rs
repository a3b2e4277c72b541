//! The point-wise grid at a lattice's resolution (thesis Fig. 3.10(b), 3.12(d)): every grid point
//! checked with the conditions at that pose, and the components of feasible points joined to
//! their feasible grid neighbours along each axis (and, on an angle axis over a whole turn, to
//! their seam twins) — connectivity assumed between samples, which the ray lattice certifies
//! instead.

use super::{LatticeSpec, UnionFind};
use crate::conditions::for_scenario;
use crate::query::cables::cables_at_config;
use crate::scenario::Scenario;
use serde::Serialize;

/// The classified grid.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PointGrid {
    /// Per grid point (flat index, first axis fastest): every condition holds there.
    pub feasible: Vec<bool>,
    /// Per grid point, its component among the feasible points (`None` where infeasible).
    pub component: Vec<Option<usize>>,
    /// Number of components.
    pub components: usize,
}

/// Checks every grid point of `spec` (already bounded by [`super::MAX_POINTS`]) and labels the
/// components of the feasible ones, neighbours being one grid step apart along one axis or seam
/// twins ([`LatticeSpec::seam_twin`]).
pub fn point_grid(s: &Scenario, spec: &LatticeSpec) -> PointGrid {
    let conditions = for_scenario(s);
    let points = spec.point_count() as usize;
    let feasible: Vec<bool> = (0..points)
        .map(|flat| {
            let cables = cables_at_config(&s.robot, &spec.coords(&spec.point_indices(flat)));
            conditions.iter().all(|c| !c.check(&cables).violated)
        })
        .collect();
    let (component, components) = neighbour_components(spec, &feasible);
    PointGrid { feasible, component, components }
}

/// The components of the grid points of `spec` marked `feasible`, each joined to its feasible
/// neighbours one grid step away along an axis and to its seam twin on an axis that wraps: the
/// component of each point (`None` where infeasible), numbered in grid order, and their count.
pub(crate) fn neighbour_components(spec: &LatticeSpec, feasible: &[bool]) -> (Vec<Option<usize>>, usize) {
    let points = feasible.len();
    let mut uf = UnionFind::new(points);
    let mut stride = 1;
    for (a, &n) in spec.steps.iter().enumerate() {
        for flat in 0..points {
            if (flat / stride) % n + 1 < n && feasible[flat] && feasible[flat + stride] {
                uf.union(flat, flat + stride);
            }
            // across the seam of a whole turn: the first and last grid values are one pose
            if spec.wraps(a) && (flat / stride) % n == 0 && feasible[flat] && feasible[flat + (n - 1) * stride] {
                uf.union(flat, flat + (n - 1) * stride);
            }
        }
        stride *= n;
    }
    let (labels, _) = uf.labels();
    // renumber over the feasible points only
    let mut map = vec![usize::MAX; points];
    let mut next = 0;
    let component = (0..points)
        .map(|flat| {
            feasible[flat].then(|| {
                let l = labels[flat];
                if map[l] == usize::MAX {
                    map[l] = next;
                    next += 1;
                }
                map[l]
            })
        })
        .collect();
    (component, next)
}
