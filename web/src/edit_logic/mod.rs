//! What the scenario editor does to the scenario, as plain functions over its JSON tree (no
//! Leptos here, so all of it is unit-tested natively), one file per part as in `editor/`:
//! [`path`] (paths into the tree and the core's error field they correspond to), [`numbers`]
//! (reading and writing numbers), and the per-part edits [`robot`] (cables, with per-cable
//! arrays kept in step), [`links`] (a multi-link robot's links, joints, configurations and paths),
//! [`obstacles`], [`poses`], [`trajectories`], [`knots`] (timed splines), [`wrench`], [`timing`]
//! (mass, winches, durations: format 4) and [`caspr`]
//! (templates for new items, conversions done by the core), and [`handles`] (the points the 3-D
//! view drags). Everything is re-exported here, so
//! callers write `edit_logic::add_cable`.

pub mod caspr;
pub mod handles;
pub mod knots;
pub mod links;
pub mod numbers;
pub mod obstacles;
pub mod path;
pub mod poses;
pub mod robot;
pub mod timing;
pub mod trajectories;
pub mod wrench;

pub use caspr::*;
pub use handles::*;
pub use knots::*;
pub use links::*;
pub use numbers::*;
pub use obstacles::*;
pub use path::*;
pub use poses::*;
pub use robot::*;
pub use timing::*;
pub use trajectories::*;
pub use wrench::*;

/// The cdpr7-box preset as a JSON tree, for the unit tests.
#[cfg(test)]
fn test_doc() -> serde_json::Value {
    serde_json::from_str(crate::presets::PRESETS[crate::presets::find("cdpr7-box").unwrap()].json).unwrap()
}
