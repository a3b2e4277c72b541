//! The wrench set (`wrench`): the nominal wrench, its point and frame, the ellipsoid or radius
//! around it, and the opt-in `wrench.closure` (format 4).

use nalgebra::{Matrix6, Vector3, Vector6};

use super::{needs_format, num, positive, spd, vec3};
use crate::error::{Error, Result};
use crate::model::{PointFrame, Wrench};
use crate::scenario::json::{RawScenario, RawWrench};

/// The wrench section: E from `ellipsoid` or from `radius` (E = I/radius²), at most one of them;
/// neither (format 4): the nominal wrench alone (E⁻¹ = 0, as [`Wrench::zero`]).
pub(super) fn wrench(raw: &RawWrench, version: u8) -> Result<Wrench> {
    let nominal = Vector6::from_fn(|i, _| raw.nominal.0[i]);
    for i in 0..6 {
        num(&format!("wrench.nominal[{i}]"), nominal[i])?;
    }
    let point = match &raw.point {
        Some(p) => vec3("wrench.point", p)?,
        None => Vector3::zeros(),
    };
    let frame = match raw.point_frame.as_deref() {
        None | Some("platform") => PointFrame::Platform,
        Some("world") => PointFrame::World,
        Some(other) => return Err(Error::new("wrench.point_frame", format!("{other:?} is not \"platform\" or \"world\""))),
    };
    let ellipsoid = match (&raw.ellipsoid, raw.radius) {
        (Some(m), None) => spd("wrench.ellipsoid", m, "the wrench set {w : (w−w0)ᵀE(w−w0) ≤ 1} needs E with positive eigenvalues")?,
        (None, Some(r)) => Matrix6::identity() / positive("wrench.radius", r)?.powi(2),
        (Some(_), Some(_)) => return Err(Error::new("wrench", "give either \"ellipsoid\" or \"radius\", not both")),
        (None, None) if version >= 4 => return Ok(Wrench { nominal, point, frame, ..Wrench::zero() }),
        (None, None) => {
            return Err(Error::new("wrench", "needs \"ellipsoid\" (a 6×6 SPD matrix E) or \"radius\" (format 4 also takes the nominal wrench alone)"))
        }
    };
    let ellipsoid_inv = ellipsoid
        .try_inverse()
        .filter(|m| m.iter().all(|x| x.is_finite()))
        .ok_or_else(|| Error::new("wrench.ellipsoid", "cannot be inverted in floating point"))?;
    Ok(Wrench { nominal, ellipsoid, ellipsoid_inv, point, frame, closure: false })
}

/// Whether `wrench.closure` asks for the wrench closure condition (false when absent).
pub(super) fn closure(raw: &RawScenario, version: u8) -> Result<bool> {
    match raw.wrench.as_ref().and_then(|w| w.closure) {
        Some(c) => {
            needs_format(version, 4, "wrench.closure")?;
            Ok(c)
        }
        None => Ok(false),
    }
}
