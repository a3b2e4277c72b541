//! A ray lattice's rays cut into pieces (feasible stretches by component, and the gaps between
//! them), which the cross-section plot and the 3-D view both draw.

use crate::worker::protocol::LatticeResult;

/// One stretch of one ray in every coordinate: the ray's configuration `at`, its varied
/// coordinate running from `from` to `to`, feasible in `component` or not (`None`: infeasible or
/// uncertain).
#[derive(Debug, Clone, PartialEq)]
pub struct RayPiece {
    /// The varied coordinate's index in the configuration.
    pub vary: usize,
    /// Whether it is an angle.
    pub angle: bool,
    /// The other coordinates (the varied one's entry is unused).
    pub at: Vec<f64>,
    /// Where the stretch starts, in the varied coordinate.
    pub from: f64,
    /// Where it ends.
    pub to: f64,
    /// The component of a feasible stretch.
    pub component: Option<usize>,
}

/// Every ray of a lattice cut into its feasible pieces and the gaps between them, end to end
/// over the ray's range.
pub fn ray_pieces(r: &LatticeResult) -> Vec<RayPiece> {
    let mut out = vec![];
    for ray in &r.rays {
        let Some(a) = r.axes.iter().position(|n| *n == ray.vary) else { continue };
        let (vary, angle, [lo, hi]) = (r.axis_index[a], r.axis_angle[a], r.ranges[a]);
        let piece = |from: f64, to: f64, component: Option<usize>| RayPiece { vary, angle, at: ray.at.clone(), from, to, component };
        let mut cursor = lo;
        for (iv, &c) in ray.feasible.iter().zip(&ray.components) {
            if iv[0] > cursor {
                out.push(piece(cursor, iv[0], None));
            }
            out.push(piece(iv[0], iv[1], Some(c)));
            cursor = iv[1];
        }
        if cursor < hi {
            out.push(piece(cursor, hi, None));
        }
    }
    out
}
