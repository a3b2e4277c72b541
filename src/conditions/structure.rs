//! The structure matrix along a motion, as polynomials: the numerators of its columns over the
//! motion's weight w, and the minors the wrench conditions are written in. Shared by the 6-cable
//! tension conditions and the m-cable closure and static-feasibility conditions.

use super::Local;
use crate::axes::per_axis;
use crate::model::{PointFrame, Wrench};
use crate::poly::Bern;
use nalgebra::Vector3;

/// a × b for polynomial vectors.
pub(crate) fn cross(a: &[Bern; 3], b: &[Bern; 3]) -> [Bern; 3] {
    let component = |i: usize, j: usize| Bern::sum_of_products(&[(&a[i], &b[j], 1.0), (&a[j], &b[i], -1.0)]);
    [component(1, 2), component(2, 0), component(0, 1)]
}

/// M̂ c for a constant vector c.
pub(crate) fn times_const(m: &[[Bern; 3]; 3], c: &Vector3<f64>) -> [Bern; 3] {
    per_axis(|i| Bern::linear_combination(&[(&m[i][0], c[0]), (&m[i][1], c[1]), (&m[i][2], c[2])]))
}

/// The wrench's application point relative to the platform origin, times w: M̂·P for a point
/// held in the platform frame, w·P for one held world-parallel (so c̃ = P̂ + this).
pub(crate) fn point_offset(m: &Local, wrench: &Wrench) -> [Bern; 3] {
    match wrench.frame {
        PointFrame::World => per_axis(|i| m.weight.scale(wrench.point[i])),
        PointFrame::Platform => times_const(&m.rotation, &wrench.point),
    }
}

/// Numerators of the columns of Ñ in the wrench components `rows` (all six for a spatial
/// platform, [`crate::model::Mobility::rows`]): entry [k][cable] for component rows[k], a force
/// over w, a moment over w² ([`row_weight`]).
pub(crate) fn structure_numerators(m: &Local, wrench: &Wrench, rows: &[usize]) -> Vec<Vec<Bern>> {
    let w = &m.weight;
    // c̃ = c·w, the application point.
    let offset = point_offset(m, wrench);
    let c: [Bern; 3] = per_axis(|i| m.position[i].add(&offset[i]));
    let mut out: Vec<Vec<Bern>> = vec![Vec::with_capacity(m.cables.len()); rows.len()];
    let moments = rows.iter().any(|&r| r >= 3);
    for (base, s) in &m.cables {
        // r̃ = a·w − c̃; (x − c) × s = r × s because s × s = 0.
        let moment = moments.then(|| cross(&per_axis(|i| w.scale(base[i]).sub(&c[i])), s));
        for (k, &row) in rows.iter().enumerate() {
            out[k].push(match (row, &moment) {
                (0..3, _) => s[row].clone(),
                (_, Some(mo)) => mo[row - 3].clone(),
                (_, None) => unreachable!("moments are computed when a moment row is asked for"),
            });
        }
    }
    out
}

/// The power of w a structure row's numerator is over: w for a force component (rows 0–2), w²
/// for a moment (rows 3–5); `w2` is w².
pub(crate) fn row_weight<'a>(row: usize, w: &'a Bern, w2: &'a Bern) -> &'a Bern {
    if row < 3 { w } else { w2 }
}

/// det [Ñ_S | x] for the n − 1 columns S whose minors ([`crate::poly::Minors`]) are `minors`, x
/// an n-th column:
/// expansion along the last column, Σ_j (−1)^(j+n−1) x_j M_j.
pub(crate) fn det_with(minors: &[Bern], x: &[&Bern]) -> Bern {
    let n = minors.len();
    (0..n).fold(Bern::constant(0.0), |acc, j| {
        let t = x[j].mul(&minors[j]);
        if (j + n - 1).is_multiple_of(2) { acc.add(&t) } else { acc.sub(&t) }
    })
}

/// gᵀ M g for the block of the symmetric 6×6 matrix `m` (E⁻¹) on the wrench components `rows`
/// and as many polynomials g: each product once, the off-diagonal ones twice.
pub(crate) fn quadratic_form(g: &[Bern], m: &nalgebra::Matrix6<f64>, rows: &[usize]) -> Bern {
    let n = rows.len();
    (0..n).fold(Bern::constant(0.0), |acc, j| {
        let terms: Vec<(&Bern, f64)> = (j..n).map(|k| (&g[k], if k == j { 1.0 } else { 2.0 } * m[(rows[j], rows[k])])).collect();
        acc.add(&g[j].mul(&Bern::linear_combination(&terms)))
    })
}

