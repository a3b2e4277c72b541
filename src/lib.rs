//! cablenav — exact feasibility of cable-driven parallel robot motions.
//!
//! Data flows through the modules in this order:
//!
//! `scenario` (JSON) → `model` (+ `shape`) → `conditions` → `verify` → `report`
//!
//! * [`scenario`] parses and validates the versioned scenario JSON into the model.
//! * [`model`] holds the robot, poses, trajectories and the rational [`model::Motion`] the exact
//!   conditions are written in; [`shape`] holds the obstacles.
//! * [`poly`] is the certified polynomial machinery: Bernstein arithmetic with error bounds and
//!   sign partitions (root isolation with error control).
//! * [`query`] answers point-wise geometric questions (distances) for one pose.
//! * [`conditions`] states each feasibility condition — cable–cable, cable–shape, cable length —
//!   as one implementation of [`conditions::Condition`], usable exactly along a motion and
//!   point-wise at a pose.
//! * [`verify`] computes feasible intervals along trajectories and rays, exactly and point-wise,
//!   and per-pose checks; [`report`] holds the serialisable results.
//! * [`parallel`] spreads many independent queries (slice cells, batch verification) over
//!   threads natively; single queries stay single-threaded.
//! * [`command`] is the commands over all of it — typed requests, JSON and text output — shared
//!   by the `cablenav` CLI (the `cli/` crate, which parses command lines with clap), the Python
//!   package (`python/`) and the npm package (`npm/`).
//!
//! The crate has no web dependency and builds for native targets and `wasm32-unknown-unknown`.

// `!(x > 0.0)` is how this crate rejects NaN together with the values a test excludes (a NaN
// compares false, so it fails the test); `x <= 0.0` would let NaN through. Clippy's suggestion
// (partial_cmp) hides that intent, so the lint is off for the crate.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod command;
pub mod conditions;
pub mod error;
pub mod lattice;
pub mod model;
pub mod parallel;
pub mod plan;
pub mod png;
pub mod poly;
pub mod query;
pub mod report;
pub mod scenario;
pub mod shape;
pub mod verify;

pub use error::{Error, Result};
pub use scenario::Scenario;
