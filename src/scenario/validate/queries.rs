//! The planning queries: a start and a goal by name (a platform robot's poses, a multi-link
//! robot's configurations), the coordinates held fixed and the region a lattice planner searches.

use super::{find_pose, known_poses, num, unique_name};
use crate::error::{Error, Result};
use crate::model::{Chain, Coord, Pose};
use crate::scenario::json::{Fixed, RawQuery};
use crate::scenario::Query;

/// A platform robot's queries, named uniquely, their poses known and their coordinates valid.
pub(super) fn queries(raw: &[RawQuery], poses: &[(String, Pose)]) -> Result<Vec<Query>> {
    let known = |field: &str, name: &str| match find_pose(poses, name) {
        Some(_) => Ok(()),
        None => Err(Error::new(field, format!("unknown pose \"{name}\"; {}", known_poses(poses)))),
    };
    checked(raw, &known, &coordinate)
}

/// A multi-link robot's queries (format 3): `start` and `goal` name configurations, `fixed` and
/// `region` the robot's joint coordinates.
pub(super) fn joint_queries(raw: &[RawQuery], configs: &[(String, Vec<f64>)], chain: &Chain) -> Result<Vec<Query>> {
    let known = |field: &str, name: &str| {
        if configs.iter().any(|(n, _)| n == name) {
            return Ok(());
        }
        let names: Vec<&str> = configs.iter().map(|(n, _)| n.as_str()).collect();
        let list = if names.is_empty() { "the scenario has no configurations".to_owned() } else { format!("known configurations: {}", names.join(", ")) };
        Err(Error::new(field, format!("no configuration named \"{name}\"; {list}")))
    };
    let joint = |field: &str, name: &str| {
        chain.coord_index(name).map(|index| Coord::Joint { index: index as u8, angle: chain.is_angle(index) }).ok_or_else(|| {
            let names: Vec<&str> = chain.coords().map(|(_, _, c)| c.name.as_str()).collect();
            Error::new(field, format!("\"{name}\" is not a coordinate of this robot; its coordinates: {}", names.join(", ")))
        })
    };
    checked(raw, &known, &joint)
}

/// The queries, named uniquely, `start` and `goal` accepted by `known` (its error names the field
/// it is given), the coordinates of `fixed` and `region` resolved by `coordinate` (likewise).
fn checked(raw: &[RawQuery], known: &dyn Fn(&str, &str) -> Result<()>, coordinate: &dyn Fn(&str, &str) -> Result<Coord>) -> Result<Vec<Query>> {
    let mut out: Vec<Query> = Vec::with_capacity(raw.len());
    for (k, q) in raw.iter().enumerate() {
        let path = format!("queries[{k}]");
        unique_name(&path, &q.name, "query", "queries", out.iter().map(|o| o.name.as_str()))?;
        for (field, name) in [("start", &q.start), ("goal", &q.goal)] {
            known(&format!("{path}.{field}"), name)?;
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
