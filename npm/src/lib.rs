//! The npm package's WebAssembly API: the core's commands for JavaScript (wasm-bindgen).
//!
//! Each function takes a scenario (JSON text or an object), builds the core's [`Request`], runs
//! it and returns the report as a plain object: `JSON.parse` of exactly the text
//! `cablenav … --json` prints ([`Output::json`], the one serialisation). Errors are thrown as an
//! `Error` named `ScenarioError` whose `field` is the JSON path or the argument it is about.
//! The TypeScript interfaces of the reports are declared below and returned by name.

use cablenav::command::{self, Request};
use cablenav::model::Coord;
use cablenav::plan::PlanParams;
use cablenav::{Error, Scenario};
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** A scenario: cablenav-scenario/1 JSON text, or the parsed object. */
export type ScenarioInput = string | object;
/** An interval [lo, hi]. */
export type Interval = [number, number];
/** A pose coordinate. */
export type Coord = "x" | "y" | "z" | "phi" | "theta" | "sigma";

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

/** What `plan` returns (`cablenav plan --json`); `seconds` is null in WebAssembly. */
export interface PlanReport {
  query: string;
  status: "found" | "no_path" | "budget";
  path: { position: [number, number, number]; quaternion: [number, number, number, number]; tilt_torsion: [number, number, number] }[];
  charts: number;
  seconds: number | null;
  dimension: number;
  expansion_failures: number;
  broken_edges: number;
  rejected_edges: number;
  blocked_charts: number;
  params: Record<string, number | boolean>;
  verification: {
    edges: number;
    infeasible_sections: number;
    uncertain_sections: number;
    wrench_poses: number;
    wrench_infeasible_poses: number;
    least_wrench_margin: number | null;
    failed_edges: [number, VerifyReport][];
    notes: string[];
  };
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
    let text = match scenario.as_string() {
        Some(text) => text,
        None => js_sys::JSON::stringify(&scenario)?.as_string().unwrap_or_default(),
    };
    let scenario = Scenario::from_json(&text).map_err(scenario_error)?;
    let output = command::run(&scenario, &request.map_err(scenario_error)?, &mut |_| {}).map_err(scenario_error)?;
    js_sys::JSON::parse(&output.json())
}

fn coord(field: &str, name: &str) -> Result<Coord, Error> {
    Coord::parse(name).ok_or_else(|| Error::new(field, format!("{name:?} is not one of x, y, z, phi, theta, sigma")))
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

/// Exact feasible intervals of one coordinate over [lo, hi], the others held at the pose's.
#[wasm_bindgen(unchecked_return_type = "RayReport")]
pub fn ray(
    #[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue,
    pose: String,
    #[wasm_bindgen(unchecked_param_type = "Coord")] vary: String,
    lo: f64,
    hi: f64,
) -> Result<JsValue, JsValue> {
    call(scenario, coord("vary", &vary).map(|vary| Request::Ray { pose, vary, range: [lo, hi] }))
}

/// Each cable's least and greatest tension over the wrench set at `samples` (default 100)
/// points of a trajectory (default: the scenario's first).
#[wasm_bindgen(unchecked_return_type = "TensionEnvelope")]
pub fn envelope(#[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue, trajectory: Option<String>, samples: Option<usize>) -> Result<JsValue, JsValue> {
    call(scenario, Ok(Request::Envelope { trajectory, samples }))
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
    let request = range.and_then(|range| Ok(Request::Slice { pose, axes: [coord("axes", &first)?, coord("axes", &second)?], res, range }));
    call(scenario, request)
}

/// A wrench-feasible, interference-free path for one of the scenario's queries, re-verified
/// edge by edge. Runs to the end: call it in a Web Worker on a page.
#[wasm_bindgen(unchecked_return_type = "PlanReport")]
pub fn plan(
    #[wasm_bindgen(unchecked_param_type = "ScenarioInput")] scenario: JsValue,
    query: String,
    #[wasm_bindgen(js_name = maxCharts)] max_charts: Option<usize>,
    radius: Option<f64>,
    epsilon: Option<f64>,
) -> Result<JsValue, JsValue> {
    let d = PlanParams::default();
    let params = PlanParams { max_charts: max_charts.unwrap_or(d.max_charts), radius: radius.unwrap_or(d.radius), epsilon: epsilon.unwrap_or(d.epsilon), ..d };
    call(scenario, Ok(Request::Plan { query, params }))
}

/// The package's version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
