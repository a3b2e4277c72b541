//! An atlas saved as a file and read back, so that a later run (`cablenav plan --atlas FILE`, the
//! packages' `atlas` argument) answers its queries from the atlas an earlier run built. The file
//! is JSON, format `cablenav-atlas/1`: the slice (the fixed coordinates' values), the planner's
//! parameters, a fingerprint of the scenario's robot, wrench set, obstacles and clearances, and
//! every chart — centre, tangent basis, polytope, neighbours, radius, state — exactly (floats are
//! written so that they read back bit for bit). A file made for another robot or other
//! parameters is refused; the charts are checked for consistency as they are read.

use super::atlas::{Atlas, AtlasParams};
use super::chart::{Chart, ChartState, Polytope};
use super::manifold::{CableManifold, Manifold};
use super::PlanParams;
use crate::error::{Error, Result};
use crate::scenario::Scenario;
use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};

/// The file format's name and version.
pub const FORMAT: &str = "cablenav-atlas/1";

/// One chart as the file holds it.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct FileChart {
    centre: Vec<f64>,
    /// The tangent basis, column by column.
    basis: Vec<Vec<f64>>,
    polytope: Polytope,
    neighbours: Vec<usize>,
    radius: f64,
    state: ChartState,
}

/// The file's contents.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct AtlasFile {
    format: String,
    /// [`fingerprint`] of the scenario the atlas was made for.
    space: String,
    params: PlanParams,
    /// The slice: each fixed coordinate's value (`null` for a free one).
    pub(crate) fixed: [Option<f64>; 6],
    failures: usize,
    charts: Vec<FileChart>,
}

/// A fingerprint of what an atlas depends on in `s`: its robot, wrench set, obstacles and
/// clearances (FNV-1a of their exact printed values; poses, trajectories and queries left out).
pub fn fingerprint(s: &Scenario) -> String {
    let text = format!("{:?}", (&s.robot, &s.wrench, &s.obstacles, &s.clearance));
    let hash = text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3));
    format!("{hash:016x}")
}

/// The file of `atlas`, made for `scenario` with `params` on the slice `fixed`.
pub fn save(atlas: &Atlas<CableManifold>, scenario: &Scenario, params: PlanParams, fixed: [Option<f64>; 6]) -> String {
    let charts = atlas
        .charts
        .iter()
        .map(|c| FileChart {
            centre: c.centre.clone(),
            basis: c.basis.column_iter().map(|col| col.iter().copied().collect()).collect(),
            polytope: c.polytope.clone(),
            neighbours: c.neighbours.clone(),
            radius: c.radius,
            state: c.state,
        })
        .collect();
    let file = AtlasFile { format: FORMAT.to_string(), space: fingerprint(scenario), params, fixed, failures: atlas.failures, charts };
    serde_json::to_string(&file).unwrap_or_default()
}

/// Reads an atlas file for `scenario` and `params`: the error (field `atlas`) says what does not
/// match or is malformed.
pub fn read(text: &str, scenario: &Scenario, params: PlanParams) -> Result<AtlasFile> {
    let bad = |why: String| Error::new("atlas", why);
    let file: AtlasFile = serde_json::from_str(text).map_err(|e| bad(format!("not an atlas file ({FORMAT}): {e}")))?;
    if file.format != FORMAT {
        return Err(bad(format!("format {:?}, expected {FORMAT:?}", file.format)));
    }
    if file.space != fingerprint(scenario) {
        return Err(bad("made for another robot, wrench set, obstacles or clearances than this scenario's".to_string()));
    }
    if file.params != params {
        return Err(bad(format!("made with other planner parameters ({:?}) than this run's ({params:?})", file.params)));
    }
    Ok(file)
}

impl AtlasFile {
    /// The atlas on `manifold` (the file's slice), each chart checked: dimensions, finite
    /// numbers, an orthonormal basis, neighbour indices.
    pub fn into_atlas(self, manifold: CableManifold, params: AtlasParams) -> Result<Atlas<CableManifold>> {
        let (n, k) = (manifold.ambient(), manifold.dimension());
        let count = self.charts.len();
        if count == 0 {
            return Err(Error::new("atlas", "the file holds no chart"));
        }
        let charts = self
            .charts
            .into_iter()
            .enumerate()
            .map(|(i, c)| {
                let bad = |why: &str| Error::new(format!("atlas.charts[{i}]"), why.to_string());
                if c.centre.len() != n || c.basis.len() != k || c.basis.iter().any(|col| col.len() != n) || c.polytope.dim() != k {
                    return Err(bad("its dimensions are not the slice's"));
                }
                let sound = c.centre.iter().chain(c.basis.iter().flatten()).all(|x| x.is_finite()) && c.radius > 0.0 && c.radius.is_finite() && c.polytope.is_consistent();
                if !sound {
                    return Err(bad("holds a number that is not finite or a malformed polytope"));
                }
                if c.neighbours.iter().any(|&j| j >= count || j == i) {
                    return Err(bad("names a neighbour that is not another chart of the file"));
                }
                let basis = DMatrix::from_fn(n, k, |r, j| c.basis[j][r]);
                if ((basis.transpose() * &basis) - DMatrix::identity(k, k)).amax() > 1e-9 {
                    return Err(bad("its tangent basis is not orthonormal"));
                }
                Ok(Chart { centre: c.centre, basis, polytope: c.polytope, neighbours: c.neighbours, radius: c.radius, state: c.state })
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Atlas::from_charts(manifold, charts, params, self.failures))
    }
}
