//! The npm package's WebAssembly API: the core's commands for JavaScript (wasm-bindgen).
//!
//! Each function takes a scenario (JSON text or an object), builds the core's [`Request`], runs
//! it and returns the report as a plain object: `JSON.parse` of exactly the text
//! `cablenav … --json` prints ([`Output::json`], the one serialisation). Errors are thrown as an
//! `Error` named `ScenarioError` whose `field` is the JSON path or the argument it is about.
//! The TypeScript interfaces of the reports are declared below and returned by name.

use cablenav::command::{self, Request};
use cablenav::plan::{atlas_params, lattice_params, AtlasOptions, PlannerKind, PlannerNaming};
use cablenav::{Error, Scenario};
use wasm_bindgen::prelude::*;

/// How npm's users choose the planners.
const NAMING: PlannerNaming = PlannerNaming { atlas: "the \"atlas\" planner", lattice: "the \"lattice\" planner" };

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** A scenario: cablenav-scenario/1 JSON text, or the parsed object. */
export type ScenarioInput = string | object;
/** An interval [lo, hi]. */
export type Interval = [number, number];
/** A pose coordinate. */
/** A coordinate: a platform pose's, or (any other string) a multi-link robot's joint coordinate by its name in the scenario, or q1, q2, …. */
export type Coord = "x" | "y" | "z" | "phi" | "theta" | "sigma" | (string & {});

/** What `verify` returns (`cablenav verify --json`). */
export interface VerifyReport {
  trajectory: string;
  method: "exact" | "pointwise";
  step?: number;
  feasible: Interval[];
  infeasible: Interval[];
  feasible_tau: Interval[];
  infeasible_tau: Interval[];
  boundaries: { t: number; tau: number; constraint: string; enters: "feasible" | "infeasible" }[];
  uncertain: Interval[];
  warnings: string[];
  /** A timed trajectory (format 4 `duration`): its sections in seconds and its least time scale. */
  seconds?: {
    duration: number;
    feasible: Interval[];
    infeasible: Interval[];
    uncertain: Interval[];
    min_time_scale: number | null;
    min_time_scale_bracket?: Interval;
    min_duration: number | null;
    max_time_scale?: number;
    min_time_scale_note: string;
    infeasible_at_rest: Interval[];
  };
}

/** What `ray` returns (`cablenav ray --json`). */
export interface RayReport {
  vary: Coord;
  pose: string;
  range: Interval;
  feasible: Interval[];
  infeasible: Interval[];
  boundaries: { value: number; constraint: string; enters: "feasible" | "infeasible" }[];
  uncertain: Interval[];
  warnings: string[];
}

/** Wrench feasibility at one pose. */
export interface WrenchReport {
  feasible: boolean;
  singular: boolean;
  margin: number | null;
  tension_min: number[];
  tension_max: number[];
  tension_nominal: number[];
  active: string;
}

/** What `check` returns (`cablenav check --json`). */
export interface PoseReport {
  pose: string;
  feasible: boolean;
  lengths: number[];
  checks: { constraint: string; violated: boolean; distance: number | null; exact: boolean }[];
  violated: string[];
  wrench?: WrenchReport;
}

/** What `envelope` returns (`cablenav envelope --json`). */
export interface TensionEnvelope {
  trajectory: string;
  t: number[];
  tension_min: (number[] | null)[];
  tension_max: (number[] | null)[];
  bounds: Interval[];
}

/** What `time` returns (`cablenav time --json`): the certified duration (null when some cell
 * could not be certified), the uncertified optimum of the same grid, the binding constraint along
 * the path and the law at every grid point. */
export interface TimingReport {
  trajectory: string;
  duration: number | null;
  uncertified_duration: number;
  certificate_cost: number | null;
  cells: number;
  rounds: number;
  margin: number;
  binding: { t: Interval; seconds: Interval; constraint: string }[];
  slowed: Interval[];
  not_certified: Interval[];
  profile: { t: number; time: number; rate: number; speed: number; tensions: number[] }[];
  notes: string[];
}

/** What `slice` returns (`cablenav slice --json`); cells row-major, index j·res + i. */
export interface SliceMap {
  axes: [Coord, Coord];
  range: [Interval, Interval];
  res: number;
  fixed: number[];
  fraction_feasible: number;
  components: number;
  classes: ("feasible" | "tension" | "length" | "singular" | "interference")[];
  component: (number | null)[];
  pose_components: Record<string, number | null>;
}

/** What `importCaspr` returns: the scenario (as `cablenav import` writes it) and notes on the conversion. */
export interface CasprImport {
  scenario: Record<string, unknown>;
  notes: string[];
}

/** What `plan` returns (`cablenav plan --json`); `seconds` and `elapsed_ms` are null in WebAssembly. */
export interface PlanReport {
  query: string;
  status: "found" | "no_path" | "budget";
  path: { position: [number, number, number]; quaternion: [number, number, number, number]; tilt_torsion: [number, number, number] }[];
  charts: number;
  seconds: number | null;
  elapsed_ms: number | null;
  /** Charts the atlas already had when this query began (kept from earlier queries on its slice). */
  reused_charts: number;
  dimension: number;
  expansion_failures: number;
  broken_edges: number;
  rejected_edges: number;
  blocked_charts: number;
  /** Least and greatest radius of the charts that are not blocked (radii adapt to the curvature). */
  chart_radii: [number, number];
  params: Record<string, number | boolean>;
  verification: {
    edges: number;
    /** Edges that are steps the motion validator verified exactly during the search (not run again). */
    edges_validated: number;
    infeasible_sections: number;
    uncertain_sections: number;
    wrench_poses: number;
    wrench_infeasible_poses: number;
    least_wrench_margin: number | null;
    failed_edges: [number, VerifyReport][];
    notes: string[];
  };
  /** The charts in the slice's coordinates (paper 1's Fig. 6 top on a 2-D slice). */
  atlas_charts: {
    coords: Coord[];
    charts: {
      centre: number[];
      radius: number;
      state: "expanded" | "open" | "out_of_bounds" | "blocked";
      on_path: boolean;
      /** A 2-D slice: the polytope as a convex polygon, vertices in cyclic order. */
      polygon: number[][];
      /** A 3-D slice: the polytope's faces, each a convex polygon. */
      faces: number[][][];
    }[];
  };
}

/** What `plan` returns when given an atlas file's text: the reports and the atlas at the end. */
export interface PlanWithAtlas {
  reports: PlanReport[];
  /** The atlas file (format cablenav-atlas/1), to pass to the next call. */
  atlas: string;
}

/** What `lattice` returns (`cablenav lattice --json`); grid points first axis fastest. */
export interface LatticeReport {
  axes: Coord[];
  ranges: Interval[];
  steps: number[];
  /** The coordinates the others are held at (x, y, z, phi, theta, sigma for a platform robot, the joint coordinates of a multi-link robot). */
  fixed: number[];
  rays: { vary: Coord; fixed: Partial<Record<Coord, number>>; feasible: Interval[]; uncertain?: Interval[] }[];
  pieces: number;
  edges: number;
  components: number;
  piece_components: number[][];
  grid_points: number;
  feasible_points: number;
  point_components: (number | null)[];
  /** Components holding a grid point feasible on every ray through it. */
  grid_components: number;
  /** Components holding no grid point: slivers between grid points. */
  sliver_components: number;
  /** The point-wise grid's components of the same grid points. */
  pointwise_components: number;
  /** Separations of grid points the point-wise grid misses (grid_components − pointwise_components). */
  missed_separations: number;
  disagreements: number;
  uncertain_rays: number;
  warnings: string[];
}

/** A pose as its six coordinates x, y, z, phi, theta, sigma. */
export type Coords = [number, number, number, number, number, number];

/** What `plan(…, "lattice")` returns (`cablenav plan --planner lattice --json`); `seconds` and `elapsed_ms` are null in WebAssembly. */
export interface LatticePlanReport {
  query: string;
  status: "found" | "no_path" | "unrepaired";
  message: string;
  axes: Coord[];
  ranges: Interval[];
  steps: number[];
  rays: number;
  components: number;
  segments: [number, number];
  expanded: number;
  /** A platform's poses (x, y, z, phi, theta, sigma), or a multi-link robot's joint coordinates in the order of `joint_coordinates`. */
  polyline: (Coords | number[])[];
  polyline_length: number;
  /** As `polyline`. */
  waypoints: (Coords | number[])[];
  /** A multi-link robot's joint coordinates by name, in configuration order (absent for a platform robot). */
  joint_coordinates?: string[];
  pieces: number;
  polyline_pieces: number;
  repairs: number;
  verification: VerifyReport | null;
  params: { steps: number; rotation_length: number; max_halvings: number };
  seconds: number | null;
  elapsed_ms: number | null;
}

/** Thrown by every function: `field` is the JSON path (`robot.cables[3].base`) or the argument. */
export interface ScenarioError extends Error {
  name: "ScenarioError";
  field: string;
  reason: string;
}
"#;

/// The core's error as a thrown `Error` named `ScenarioError` with `field` and `reason`; the
/// core's command-line option names (`--range`, `--max-charts`) become the argument names
/// (`range`, `maxCharts`).
fn scenario_error(e: Error) -> JsValue {
    let field = match e.field.strip_prefix("--") {
        Some(option) => {
            let mut parts = option.split('-');
            let first = parts.next().unwrap_or_default().to_string();
            parts.fold(first, |name, part| name + &part[..1].to_uppercase() + &part[1..])
        }
        None => e.field,
    };
    let message = if field.is_empty() { e.reason.clone() } else { format!("{field}: {}", e.reason) };
    let error = js_sys::Error::new(&message);
    error.set_name("ScenarioError");
    let value = JsValue::from(error);
    // Setting a property on a fresh Error object cannot fail.
    let _ = js_sys::Reflect::set(&value, &"field".into(), &field.into());
    let _ = js_sys::Reflect::set(&value, &"reason".into(), &e.reason.into());
    value
}

/// Runs `request` on the scenario and returns the report as a plain object.
fn call(scenario: JsValue, request: Result<Request, Error>) -> Result<JsValue, JsValue> {
    call_renaming(scenario, request, None)
}

/// [`call`], where an error about the core's option `rename.0` names the argument `rename.1`
/// (for arguments named differently from the option, e.g. `ranges` for `--range`).
fn call_renaming(scenario: JsValue, request: Result<Request, Error>, rename: Option<(&str, &str)>) -> Result<JsValue, JsValue> {
    js_sys::JSON::parse(&run_request(scenario, request, rename)?.json())
}

/// Runs `request` on the scenario: the core's output ([`call_renaming`] names the arguments).
fn run_request(scenario: JsValue, request: Result<Request, Error>, rename: Option<(&str, &str)>) -> Result<command::Output, JsValue> {
    let text = match scenario.as_string() {
        Some(text) => text,
        None => js_sys::JSON::stringify(&scenario)?.as_string().unwrap_or_default(),
    };
    let scenario = Scenario::from_json(&text).map_err(scenario_error)?;
    let renamed = |e: Error| match rename {
        Some((option, name)) if e.field == option => Error::new(name, e.reason),
        _ => e,
    };
    command::run(&scenario, &request.map_err(scenario_error)?, &mut |_| {}).map_err(|e| scenario_error(renamed(e)))
}

/// Feasible and infeasible t-sections of a trajectory (default: the scenario's first), exactly;
/// with `pointwise` (Δt) sampled instead.
#[wasm_bindgen(unchecked_return_type = "VerifyReport")]
pub fn verify(#[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue, trajectory: Option<String>, pointwise: Option<f64>) -> Result<JsValue, JsValue> {
    call(scenario, Ok(Request::Verify { trajectory, pointwise }))
}

/// Lengths, clearances, violated conditions and the wrench set's tension ranges at one pose.
#[wasm_bindgen(unchecked_return_type = "PoseReport")]
pub fn check(#[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue, pose: String) -> Result<JsValue, JsValue> {
    call(scenario, Ok(Request::Check { pose }))
}

/// A CASPR model as a scenario: the texts of its bodies and cables files and, optionally, of its
/// trajectories file (timed quintic and cubic splines) and the id of the cable set to import (the
/// file's default without it), as `cablenav import [--cable-set ID]` converts them.
#[wasm_bindgen(js_name = importCaspr, unchecked_return_type = "CasprImport")]
pub fn import_caspr(name: String, bodies: String, cables: String, trajectories: Option<String>, cable_set: Option<String>) -> Result<JsValue, JsValue> {
    let imported = cablenav::scenario::caspr::model_to_json(&name, &bodies, &cables, trajectories.as_deref(), cable_set.as_deref()).map_err(scenario_error)?;
    let out = js_sys::Object::new();
    js_sys::Reflect::set(&out, &"scenario".into(), &js_sys::JSON::parse(&imported.json)?)?;
    let notes: js_sys::Array = imported.notes.iter().map(|n| JsValue::from_str(n)).collect();
    js_sys::Reflect::set(&out, &"notes".into(), &notes)?;
    Ok(out.into())
}

/// `check` where a trajectory (default: the scenario's first) is at t ∈ [0, 1], moving as it
/// moves there if it is timed (its tension ranges then include the platform's inertia).
#[wasm_bindgen(js_name = checkAt, unchecked_return_type = "PoseReport")]
pub fn check_at(#[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue, t: f64, trajectory: Option<String>) -> Result<JsValue, JsValue> {
    call(scenario, Ok(Request::CheckAt { trajectory, t }))
}

/// Exact feasible intervals of one coordinate over [lo, hi], the others held at the pose's (a
/// multi-link robot: `pose` names a configuration, `vary` a joint coordinate).
#[wasm_bindgen(unchecked_return_type = "RayReport")]
pub fn ray(
    #[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue,
    pose: String,
    #[wasm_bindgen(unchecked_param_type = "Coord")] vary: String,
    lo: f64,
    hi: f64,
) -> Result<JsValue, JsValue> {
    call(scenario, Ok(Request::Ray { pose, vary, range: [lo, hi] }))
}

/// Each cable's least and greatest tension over the wrench set at `samples` (default 100)
/// points of a trajectory (default: the scenario's first).
#[wasm_bindgen(unchecked_return_type = "TensionEnvelope")]
pub fn envelope(#[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue, trajectory: Option<String>, samples: Option<usize>) -> Result<JsValue, JsValue> {
    call(scenario, Ok(Request::Envelope { trajectory, samples }))
}

/// The fastest rest-to-rest timing of a trajectory (default: the scenario's first), certified
/// along it by the exact verifier; `cells` grid cells (default 400), `margin` the relative margin
/// the limits are tightened by at the grid points (default 1e-3).
#[wasm_bindgen(unchecked_return_type = "TimingReport")]
pub fn time(#[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue, trajectory: Option<String>, cells: Option<usize>, margin: Option<f64>) -> Result<JsValue, JsValue> {
    call(scenario, Ok(Request::Time { trajectory, cells, margin }))
}

/// A res × res classified grid over two coordinates (the others from the pose) and the
/// connected components of its feasible cells; `range` is [lo1, hi1, lo2, hi2] (optional for
/// angle axes: [-π, π]).
#[wasm_bindgen(unchecked_return_type = "SliceMap")]
pub fn slice(
    #[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue,
    pose: String,
    #[wasm_bindgen(unchecked_param_type = "Coord")] first: String,
    #[wasm_bindgen(unchecked_param_type = "Coord")] second: String,
    res: usize,
    range: Option<Vec<f64>>,
) -> Result<JsValue, JsValue> {
    let range = match range.as_deref() {
        None => Ok(None),
        Some(&[a, b, c, d]) => Ok(Some([[a, b], [c, d]])),
        Some(other) => Err(Error::new("--range", format!("needs 4 numbers [lo1, hi1, lo2, hi2], got {}", other.len()))),
    };
    let request = range.map(|range| Request::Slice { pose, axes: [first, second], res, range });
    call(scenario, request)
}

/// The thesis' ray lattice over `axes` (the others held at the pose's): every ray's exact
/// feasible intervals, the graph of feasible pieces and its components. `ranges` is
/// [lo1, hi1, lo2, hi2, …], one pair per axis; `steps` the grid values per axis (both ends
/// count): one number for every axis, or an array with one per axis.
#[wasm_bindgen(unchecked_return_type = "LatticeReport")]
pub fn lattice(
    #[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue,
    pose: String,
    #[wasm_bindgen(unchecked_param_type = "Coord[]")] axes: Vec<String>,
    ranges: Vec<f64>,
    #[wasm_bindgen(unchecked_param_type = "number | number[]")] steps: JsValue,
) -> Result<JsValue, JsValue> {
    call_renaming(scenario, lattice_request(pose, &axes, &ranges, &steps), Some(("--range", "ranges")))
}

/// The [`Request::Lattice`] of `lattice`'s arguments.
fn lattice_request(pose: String, axes: &[String], ranges: &[f64], steps: &JsValue) -> Result<Request, Error> {
    if !ranges.len().is_multiple_of(2) {
        return Err(Error::new("ranges", format!("needs [lo, hi] pairs, got {} numbers", ranges.len())));
    }
    let ranges = ranges.chunks(2).map(|p| [p[0], p[1]]).collect();
    let whole = |v: &JsValue| v.as_f64().filter(|n| n.fract() == 0.0 && *n >= 0.0 && *n <= u32::MAX as f64).map(|n| n as usize);
    let steps = match whole(steps) {
        Some(n) => vec![n],
        None if js_sys::Array::is_array(steps) => js_sys::Array::from(steps).iter().map(|v| whole(&v)).collect::<Option<Vec<usize>>>().ok_or_else(|| Error::new("steps", "needs whole numbers"))?,
        None => return Err(Error::new("steps", "needs a whole number or an array of them")),
    };
    Ok(Request::Lattice { pose, axes: axes.to_vec(), ranges, steps })
}

/// A feasible path for one of the scenario's queries, re-verified exactly; `query` may also be an
/// array of query names, planned in order with one planner (the atlas kept for later queries on
/// the same slice), which returns an array of reports, one per query, each with its `elapsed_ms`.
/// `planner` is "atlas" (default; Henderson atlas + A* with `maxCharts`, `radius`, `epsilon`,
/// `minRadius` — the least chart radius the curvature adaptation gives, `minRadius >= radius`
/// turns it off —, `heuristicWeight` — w in f = g + w·h, ≥ 1, 1 is A* — and `identifyAngles` —
/// false: the angles as plain coordinates, paper 1's way —, as the CLI's `--max-charts`, …,
/// `--identify-angles`; 6 cables with a wrench set) or "lattice" (ray lattice with `steps` grid
/// values per free coordinate, default 7, + A* + Bézier smoothing; any robot). Unset
/// parameters take the CLI's defaults; a bad one throws a `ScenarioError` naming it
/// (`minRadius`). `atlas`, an atlas file's text (as `cablenav plan --atlas FILE` saves it; "" for
/// none yet), starts the atlas planner from that atlas, and the result is then
/// `{ reports, atlas }`: the reports (an array) and the atlas at the end, to keep for the next
/// call. Runs to the end: call it in a Web Worker on a page.
#[wasm_bindgen(unchecked_return_type = "PlanReport | LatticePlanReport | PlanReport[] | LatticePlanReport[] | PlanWithAtlas")]
#[allow(clippy::too_many_arguments)]
pub fn plan(
    #[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue,
    #[wasm_bindgen(unchecked_param_type = "string | string[]")] query: JsValue,
    #[wasm_bindgen(js_name = maxCharts)] max_charts: Option<usize>,
    radius: Option<f64>,
    epsilon: Option<f64>,
    #[wasm_bindgen(unchecked_param_type = "\"atlas\" | \"lattice\" | undefined")] planner: Option<String>,
    steps: Option<usize>,
    #[wasm_bindgen(js_name = minRadius)] min_radius: Option<f64>,
    #[wasm_bindgen(js_name = heuristicWeight)] heuristic_weight: Option<f64>,
    #[wasm_bindgen(js_name = identifyAngles)] identify_angles: Option<bool>,
    atlas: Option<String>,
) -> Result<JsValue, JsValue> {
    let (queries, several) = match query.as_string() {
        Some(one) => (vec![one], false),
        None if js_sys::Array::is_array(&query) => (js_sys::Array::from(&query).iter().map(|q| q.as_string()).collect::<Option<Vec<String>>>().unwrap_or_default(), true),
        None => (vec![], true),
    };
    if several && queries.is_empty() {
        return Err(scenario_error(Error::new("query", "must be a query name or a non-empty array of query names")));
    }
    let options = AtlasOptions { max_charts, radius, min_radius, heuristic_weight, epsilon, identify_angles };
    let kept = atlas.clone();
    let request = PlannerKind::parse(planner.as_deref().unwrap_or("atlas")).and_then(|planner| {
        let lattice = lattice_params(planner, steps, NAMING.lattice)?;
        let params = atlas_params(planner, &options, NAMING.atlas)?;
        if kept.is_some() && planner != PlannerKind::Atlas {
            return Err(Error::new("atlas", format!("is an option of {}", NAMING.atlas)));
        }
        Ok(Request::Plan { queries, params, planner, lattice, atlas: kept, naming: NAMING })
    });
    let output = run_request(scenario, request, None)?;
    let mut reports = js_sys::JSON::parse(&output.json())?;
    // an array of one query returns an array of one report
    if (several || atlas.is_some()) && !js_sys::Array::is_array(&reports) {
        reports = js_sys::Array::of1(&reports).into();
    }
    let Some(file) = output.atlas_file() else { return Ok(reports) };
    let both = js_sys::Object::new();
    js_sys::Reflect::set(&both, &"reports".into(), &reports)?;
    js_sys::Reflect::set(&both, &"atlas".into(), &file.into())?;
    Ok(both.into())
}

/// The package's version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
