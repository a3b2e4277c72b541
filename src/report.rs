//! Serialisable results: what the CLI prints with `--json` and what the page draws.

use serde::Serialize;

/// Which side a boundary leads into, going forward.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    /// Feasible after the boundary.
    Feasible,
    /// Infeasible after the boundary.
    Infeasible,
}

/// A point along a trajectory where feasibility changes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Boundary {
    /// Slerp parameter t.
    pub t: f64,
    /// Translation parameter τ.
    pub tau: f64,
    /// The constraint(s) that change there, e.g. `"cables 2-5"`, `"cable 3 - plinth"`.
    pub constraint: String,
    /// Whether the motion enters the feasible or the infeasible set.
    pub enters: Side,
}

/// Feasibility along one trajectory.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct VerifyReport {
    /// The trajectory's name.
    pub trajectory: String,
    /// `"exact"`, or `"pointwise"` for the sampled baseline.
    pub method: String,
    /// The sampling step of the point-wise baseline.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub step: Option<f64>,
    /// Feasible t-intervals, sorted and disjoint.
    pub feasible: Vec<[f64; 2]>,
    /// Infeasible t-intervals.
    pub infeasible: Vec<[f64; 2]>,
    /// The feasible intervals in τ.
    pub feasible_tau: Vec<[f64; 2]>,
    /// The infeasible intervals in τ.
    pub infeasible_tau: Vec<[f64; 2]>,
    /// Where feasibility changes, with the active constraint.
    pub boundaries: Vec<Boundary>,
    /// t-intervals that could not be certified either way (never guessed).
    pub uncertain: Vec<[f64; 2]>,
    /// Notes for the user (from the scenario and the verification).
    pub warnings: Vec<String>,
    /// The sections in seconds and how fast the trajectory may run, for a timed trajectory
    /// (format 4 `duration`); absent for an untimed one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds: Option<Box<Seconds>>,
}

/// A timed trajectory's sections in seconds (time = t·duration) and its fastest uniform timing.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct Seconds {
    /// The trajectory's duration (s).
    pub duration: f64,
    /// Feasible time intervals [s0, s1].
    pub feasible: Vec<[f64; 2]>,
    /// Infeasible time intervals.
    pub infeasible: Vec<[f64; 2]>,
    /// Time intervals that could not be certified either way.
    pub uncertain: Vec<[f64; 2]>,
    /// The least uniform time scale k (every duration × k) certified to make the speed-dependent
    /// conditions (tensions under weight and inertia, winch limits) hold along the whole
    /// trajectory: k < 1 means it could run faster, k > 1 that it must run slower. `None` when no
    /// scale does (see `min_time_scale_note`) or when it was not computed (point-wise reports).
    pub min_time_scale: Option<f64>,
    /// [k_lo, k_hi]: k_hi is `min_time_scale`, certified feasible; below k_lo the conditions are
    /// certainly violated somewhere (k_lo = 0 when that was not certified).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_time_scale_bracket: Option<[f64; 2]>,
    /// The shortest certified duration, `min_time_scale` × `duration` (s).
    pub min_duration: Option<f64>,
    /// When the trajectory fails at rest but holds at some speed (the inertia keeps a cable taut):
    /// the largest scale certified to hold; slower fails. Absent when every slower timing holds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_time_scale: Option<f64>,
    /// Why `min_time_scale` is what it is: the condition that binds at the scale found, or why
    /// there is none.
    pub min_time_scale_note: String,
    /// The t-intervals where the speed-dependent conditions fail even at rest (then no scale
    /// helps).
    pub infeasible_at_rest: Vec<[f64; 2]>,
}

/// A point along a ray where feasibility changes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RayBoundary {
    /// The coordinate's value.
    pub value: f64,
    /// The constraint(s) that change there.
    pub constraint: String,
    /// Whether increasing values enter the feasible or the infeasible set.
    pub enters: Side,
}

/// Feasibility of one pose coordinate over a range, the others fixed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RayReport {
    /// The varied coordinate: x, y, z, phi, theta or sigma.
    pub vary: String,
    /// The pose the other coordinates come from.
    pub pose: String,
    /// The range studied.
    pub range: [f64; 2],
    /// Feasible value intervals.
    pub feasible: Vec<[f64; 2]>,
    /// Infeasible value intervals.
    pub infeasible: Vec<[f64; 2]>,
    /// Where feasibility changes.
    pub boundaries: Vec<RayBoundary>,
    /// Value intervals that could not be certified.
    pub uncertain: Vec<[f64; 2]>,
    /// Notes for the user.
    pub warnings: Vec<String>,
}

/// One condition at one pose.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckEntry {
    /// The condition's label.
    pub constraint: String,
    /// Whether it is violated.
    pub violated: bool,
    /// The distance it is about (cable–cable, cable–obstacle surface, or the cable length), when
    /// computed; for capsules (cylinders) the distance to the capsule.
    pub distance: Option<f64>,
}

/// Wrench feasibility at one pose (6 cables): the tension range of each cable over the wrench set.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WrenchReport {
    /// Non-singular, every tension range strictly inside its bounds, every length inside its bounds
    /// (more than 6 cables: wrench closure, static feasibility of w0, lengths).
    pub feasible: bool,
    /// Whether the structure matrix is singular here (then no tensions are given; more than 6
    /// cables: no tensions balance w0 at all).
    pub singular: bool,
    /// min over cables of min(f0 − v − f_min, f_max − f0 − v); `None` at a singular pose. More
    /// than 6 cables: the static-feasibility LP's margin t.
    pub margin: Option<f64>,
    /// Least tension of each cable over the wrench set, f0 − v (empty for more than 6 cables).
    pub tension_min: Vec<f64>,
    /// Greatest tension of each cable over the wrench set, f0 + v (empty for more than 6 cables).
    pub tension_max: Vec<f64>,
    /// Tension balancing the nominal wrench, f0 (more than 6 cables: the LP's tensions).
    pub tension_nominal: Vec<f64>,
    /// The bound closest to being violated (or violated): `"cable 5 tension lower bound"`,
    /// `"cable 2 length"`, `"singular"`, `"wrench closure"` or `"static feasibility"`.
    pub active: String,
}

/// All conditions at one pose.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PoseReport {
    /// The pose's name.
    pub pose: String,
    /// Whether no condition is violated.
    pub feasible: bool,
    /// Cable lengths, in cable order.
    pub lengths: Vec<f64>,
    /// Every condition's result.
    pub checks: Vec<CheckEntry>,
    /// The labels of the violated conditions.
    pub violated: Vec<String>,
    /// Wrench feasibility, when the scenario has a wrench section.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wrench: Option<WrenchReport>,
}

/// Each cable's tension range over the wrench set along a trajectory, for a plot.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TensionEnvelope {
    /// The trajectory's name.
    pub trajectory: String,
    /// Sample parameters t.
    pub t: Vec<f64>,
    /// Per sample, each cable's least tension (`None` at a singular pose).
    pub tension_min: Vec<Option<Vec<f64>>>,
    /// Per sample, each cable's greatest tension (`None` at a singular pose).
    pub tension_max: Vec<Option<Vec<f64>>>,
    /// Each cable's tension bounds [min, max].
    pub bounds: Vec<[f64; 2]>,
}

/// The fastest safe timing of a trajectory (`cablenav time`): a time law certified along the
/// whole path by the exact verifier, and what it cost over the grid's uncertified optimum.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct TimingReport {
    /// The trajectory's name.
    pub trajectory: String,
    /// The certified duration (s), rest to rest; `None` when some cell could not be certified
    /// (`not_certified` says where).
    pub duration: Option<f64>,
    /// The duration of the time-optimal law on the same grid before certification (s): the
    /// limits met at the grid's points only, as sampled planners give it.
    pub uncertified_duration: f64,
    /// duration / uncertified_duration − 1: what the certificate cost.
    pub certificate_cost: Option<f64>,
    /// Grid cells the path was cut into.
    pub cells: usize,
    /// Rounds the certification took (0: the optimum certified as it was), each halving the
    /// cells that failed (once) or slowing them.
    pub rounds: usize,
    /// The relative margin the limits were tightened by on the grid.
    pub margin: f64,
    /// The constraint that binds along the path, stretch by stretch.
    pub binding: Vec<BindingStretch>,
    /// The t-intervals the certification slowed down (a limit was left between grid points).
    pub slowed: Vec<[f64; 2]>,
    /// The t-intervals left uncertified after the last round (empty when `duration` is given).
    pub not_certified: Vec<[f64; 2]>,
    /// The law at every grid point.
    pub profile: Vec<ProfilePoint>,
    /// Notes: geometry along the path, what was left out.
    pub notes: Vec<String>,
}

/// A stretch of the path over which one constraint binds.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct BindingStretch {
    /// [t0, t1] in the trajectory's parameter.
    pub t: [f64; 2],
    /// [s0, s1] in seconds.
    pub seconds: [f64; 2],
    /// The constraint, e.g. `"cable 3 max, cable 7 min tension"`, `"cable 2 speed"`.
    pub constraint: String,
}

/// The timed law at one grid point.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct ProfilePoint {
    /// The trajectory's parameter.
    pub t: f64,
    /// Time (s).
    pub time: f64,
    /// dt/dtime (1/s).
    pub rate: f64,
    /// The platform origin's speed (m/s).
    pub speed: f64,
    /// Tensions balancing the load there, moving (the linear program's most central ones for
    /// more than six cables); empty where the robot has no load.
    pub tensions: Vec<f64>,
}
