//! cablenav — exact feasibility of cable-driven parallel robot motions.
//!
//! Data flows through the modules in this order:
//!
//! `scenario` (JSON) → `model` (+ `shape`) → `conditions` → `verify` → `report`
//!
//! and the ray lattice and the planners build on the verifier: `verify` → `lattice` → `plan`.
//!
//! * [`scenario`] parses and validates the versioned scenario JSON into the model
//!   ([`scenario::validate`], section by section), imports CASPR models ([`scenario::caspr`]) and
//!   carries a scenario in a shareable URL ([`scenario::share_url`]).
//! * [`model`] holds the robot, poses, trajectories and the rational [`model::Motion`] the exact
//!   conditions are written in; [`shape`] holds the obstacles.
//! * [`poly`] is the certified polynomial machinery: Bernstein arithmetic with error bounds and
//!   sign partitions (root isolation with error control).
//! * [`query`] answers point-wise questions for one pose: distances, the cables at a pose
//!   ([`query::cables`]) and its wrench feasibility ([`query::wrench`]).
//! * [`conditions`] states each feasibility condition — cable–cable, cable–shape, cable length —
//!   as one implementation of [`conditions::Condition`], usable exactly along a motion and
//!   point-wise at a pose.
//! * [`verify`] computes feasible intervals along trajectories and rays, exactly and point-wise,
//!   and per-pose checks; [`report`] holds the serialisable results.
//! * [`lattice`] is the ray lattice of a slice: the exact feasible intervals of a ray along each
//!   chosen coordinate through every grid point, and the graph of their pieces.
//! * [`plan`] plans a path for a query of a scenario: the planning interface (which planner, its
//!   options, the common result) and the planners, [`plan::atlas`] (an atlas of the
//!   wrench-feasible C-space) and [`plan::lattice`] (A* over the ray lattice, Bézier smoothing).
//! * [`parallel`] spreads many independent queries (slice cells, batch verification, the two
//!   runs of pieces of a long trajectory) over threads natively; other single queries stay
//!   single-threaded.
//! * [`command`] is the commands over all of it — typed requests, JSON and text output — shared
//!   by the `cablenav` CLI (the `cli/` crate, which parses command lines with clap), the Python
//!   package (`python/`) and the npm package (`npm/`).
//! * [`error`] is the one error type, naming the input field at fault; [`png`] writes the slice
//!   maps as images.
//!
//! The crate has no web dependency and builds for native targets and `wasm32-unknown-unknown`.

// `!(x > 0.0)` is how this crate rejects NaN together with the values a test excludes (a NaN
// compares false, so it fails the test); `x <= 0.0` would let NaN through. Clippy's suggestion
// (partial_cmp) hides that intent, so the lint is off for the crate.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod axes;
pub mod command;
pub mod conditions;
pub mod error;
pub mod lattice;
pub mod model;
pub mod order;
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
