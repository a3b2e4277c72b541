//! The planning queries: a start and a goal pose by name, the coordinates held fixed and the
//! region a lattice planner searches.

use super::{find_pose, known_poses, num, unique_name};
use crate::error::{Error, Result};
use crate::model::{Coord, Pose};
use crate::scenario::json::{Fixed, RawQuery};
use crate::scenario::Query;

/// The queries, named uniquely, their poses known and their coordinates valid.
pub(super) fn queries(raw: &[RawQuery], poses: &[(String, Pose)]) -> Result<Vec<Query>> {
    let mut out: Vec<Query> = Vec::with_capacity(raw.len());
    for (k, q) in raw.iter().enumerate() {
        let path = format!("queries[{k}]");
        unique_name(&path, &q.name, "query", "queries", out.iter().map(|o| o.name.as_str()))?;
        for (field, name) in [("start", &q.start), ("goal", &q.goal)] {
            if find_pose(poses, name).is_none() {
                return Err(Error::new(
                    format!("{path}.{field}"),
                    format!("unknown pose \"{name}\"; {}", known_poses(poses)),
                ));
            }
        }
        let mut fixed = Vec::with_capacity(q.fixed.len());
        for (i, s) in q.fixed.iter().enumerate() {
            let f = format!("{path}.fixed[{i}]");
            let c = coordinate(&f, s)?;
            if fixed.contains(&c) {
                return Err(Error::new(f, format!("coordinate \"{s}\" is listed twice")));
            }
            fixed.push(c);
        }
        let mut region: Vec<(Coord, [f64; 2])> = Vec::new();
        for (name, Fixed([lo, hi])) in q.region.iter().flat_map(|r| r.0.iter()) {
            let f = format!("{path}.region.{name}");
            let c = coordinate(&f, name)?;
            if fixed.contains(&c) {
                return Err(Error::new(f, format!("coordinate \"{name}\" is fixed by this query: it has no range")));
            }
            if region.iter().any(|(r, _)| *r == c) {
                return Err(Error::new(f, format!("coordinate \"{name}\" is given twice")));
            }
            let (lo, hi) = (num(&format!("{f}[0]"), *lo)?, num(&format!("{f}[1]"), *hi)?);
            if lo >= hi {
                return Err(Error::new(f, format!("needs LO < HI, got [{lo}, {hi}]")));
            }
            region.push((c, [lo, hi]));
        }
        out.push(Query { name: q.name.clone(), start: q.start.clone(), goal: q.goal.clone(), fixed, region });
    }
    Ok(out)
}

/// The coordinate named `name` at `field`, or an error listing the names.
fn coordinate(field: &str, name: &str) -> Result<Coord> {
    Coord::parse(name).ok_or_else(|| {
        let names: Vec<&str> = Coord::ALL.iter().map(|c| c.name()).collect();
        Error::new(field, format!("unknown coordinate \"{name}\"; expected one of {}", names.join(", ")))
    })
}
