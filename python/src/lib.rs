//! `cablenav._cablenav`: the Python bindings of the cablenav core (PyO3, abi3).
//!
//! Each function takes a scenario (a dict, a JSON string or a path), builds the core's
//! [`Request`] from its keyword arguments, runs it with the GIL released and returns the report
//! as plain dicts and lists: `json.loads` of exactly the text `cablenav … --json` prints
//! ([`Output::json`], the one serialisation). Every error of the core is raised as
//! `cablenav.ScenarioError` with the field it names (a JSON path into the scenario, or the
//! parameter) in `.field`.

use cablenav::command::{self, Request};
use cablenav::plan::{atlas_params, lattice_params, AtlasOptions, PlannerKind, PlannerNaming};
use cablenav::{Error, Scenario};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

/// How Python's users choose the planners.
const NAMING: PlannerNaming = PlannerNaming { atlas: "planner=\"atlas\"", lattice: "planner=\"lattice\"" };

pyo3::create_exception!(
    cablenav,
    ScenarioError,
    PyValueError,
    "A scenario or an argument the core rejects. `.field` names where (a JSON path into the \
     scenario such as `robot.cables[3].base`, or the argument such as `range`), `.reason` says \
     why, `.path` is the scenario file's path when it was given as one (else None)."
);

/// Where a scenario comes from.
enum Source {
    /// JSON text (a dict is dumped to this).
    Json(String),
    /// A file path.
    Path(String),
}

impl Source {
    /// A dict, a JSON string (its first non-blank character is `{`), a path string or an
    /// `os.PathLike`.
    fn of(scenario: &Bound<'_, PyAny>) -> PyResult<Source> {
        let py = scenario.py();
        if scenario.is_instance_of::<PyString>() {
            let text: String = scenario.extract()?;
            return Ok(if text.trim_start().starts_with('{') { Source::Json(text) } else { Source::Path(text) });
        }
        if scenario.is_instance_of::<PyDict>() {
            let mut text = String::new();
            return match write_json(scenario, &mut String::new(), &mut text)? {
                Ok(()) => Ok(Source::Json(text)),
                Err(e) => Err(scenario_error(py, e, None)),
            };
        }
        match py.import("os")?.call_method1("fspath", (scenario,)) {
            Ok(path) => Ok(Source::Path(path.extract()?)),
            Err(_) => Err(PyTypeError::new_err(format!(
                "scenario must be a dict, a JSON string or a path, not {}",
                scenario.get_type().name()?
            ))),
        }
    }

    /// The file's path, if the scenario is one.
    fn path(&self) -> Option<&str> {
        match self {
            Source::Path(p) => Some(p),
            Source::Json(_) => None,
        }
    }

    /// Reads and parses the scenario (without the GIL).
    fn load(&self) -> cablenav::Result<Scenario> {
        let text = match self {
            Source::Json(text) => std::borrow::Cow::Borrowed(text.as_str()),
            Source::Path(path) => std::borrow::Cow::Owned(std::fs::read_to_string(path).map_err(|e| Error::new("", format!("cannot read: {e}")))?),
        };
        Scenario::from_json(&text)
    }
}

/// Writes a scenario given as Python data (dicts with string keys, lists, tuples, strings,
/// numbers, booleans, None) as JSON text, keeping the dicts' key order (pose order matters). A
/// value JSON cannot hold (NaN, ±inf, another type) is an error at its path (`poses.a.position[1]`),
/// as the core names fields; `path` is the current one.
fn write_json(value: &Bound<'_, PyAny>, path: &mut String, out: &mut String) -> PyResult<Result<(), Error>> {
    use pyo3::types::{PyBool, PyFloat, PyInt, PyList, PyTuple};
    let quoted = |text: &str| serde_json::to_string(text).unwrap_or_default();
    if value.is_none() {
        out.push_str("null");
    } else if let Ok(b) = value.cast::<PyBool>() {
        out.push_str(if b.is_true() { "true" } else { "false" });
    } else if value.is_instance_of::<PyInt>() {
        match value.extract::<i64>() {
            Ok(i) => out.push_str(&i.to_string()),
            Err(_) => return Ok(Err(Error::new(path.clone(), "integer too large"))),
        }
    } else if let Ok(x) = value.cast::<PyFloat>() {
        let x = x.value();
        if !x.is_finite() {
            return Ok(Err(Error::new(path.clone(), format!("must be a finite number, got {x}"))));
        }
        out.push_str(&serde_json::to_string(&x).unwrap_or_default());
    } else if value.is_instance_of::<PyString>() {
        out.push_str(&quoted(&value.extract::<String>()?));
    } else if let Ok(dict) = value.cast::<PyDict>() {
        out.push('{');
        for (i, (key, item)) in dict.iter().enumerate() {
            let Ok(key) = key.extract::<String>() else {
                return Ok(Err(Error::new(path.clone(), format!("keys must be strings, got {}", key.get_type().name()?))));
            };
            if i > 0 {
                out.push(',');
            }
            out.push_str(&quoted(&key));
            out.push(':');
            let len = path.len();
            if !path.is_empty() {
                path.push('.');
            }
            path.push_str(&key);
            if let Err(e) = write_json(&item, path, out)? {
                return Ok(Err(e));
            }
            path.truncate(len);
        }
        out.push('}');
    } else if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        out.push('[');
        for (i, item) in value.try_iter()?.enumerate() {
            if i > 0 {
                out.push(',');
            }
            let len = path.len();
            path.push_str(&format!("[{i}]"));
            if let Err(e) = write_json(&item?, path, out)? {
                return Ok(Err(e));
            }
            path.truncate(len);
        }
        out.push(']');
    } else {
        return Ok(Err(Error::new(path.clone(), format!("a {} is not JSON data", value.get_type().name()?))));
    }
    Ok(Ok(()))
}

/// The core's error as a `ScenarioError`; the command-line option names the core uses
/// (`--range`, `--max-charts`) become the Python parameter names (`range`, `max_charts`).
fn scenario_error(py: Python<'_>, e: Error, path: Option<&str>) -> PyErr {
    let field = match e.field.strip_prefix("--") {
        Some(option) => option.replace('-', "_"),
        None => e.field,
    };
    let message = if field.is_empty() { e.reason.clone() } else { format!("{field}: {}", e.reason) };
    let message = match path {
        Some(p) => format!("{p}: {message}"),
        None => message,
    };
    let err = ScenarioError::new_err(message);
    let value = err.value(py);
    let set = value.setattr("field", field).and(value.setattr("reason", e.reason)).and(value.setattr("path", path));
    set.err().unwrap_or(err)
}

/// Runs `request` on the scenario with the GIL released and returns the report as Python data.
fn call(py: Python<'_>, scenario: &Bound<'_, PyAny>, request: Result<Request, Error>) -> PyResult<Py<PyAny>> {
    call_renaming(py, scenario, request, None)
}

/// [`call`], where an error about the core's option `rename.0` names the parameter `rename.1`
/// (for parameters named differently from the option, e.g. `ranges` for `--range`).
fn call_renaming(py: Python<'_>, scenario: &Bound<'_, PyAny>, request: Result<Request, Error>, rename: Option<(&str, &str)>) -> PyResult<Py<PyAny>> {
    let output = run_request(py, scenario, request, rename)?;
    from_json(py, &output.json())
}

/// Runs `request` on the scenario with the GIL released: the core's output ([`call_renaming`]
/// names the parameters).
fn run_request(py: Python<'_>, scenario: &Bound<'_, PyAny>, request: Result<Request, Error>, rename: Option<(&str, &str)>) -> PyResult<command::Output> {
    let source = Source::of(scenario)?;
    let request = request.map_err(|e| scenario_error(py, e, None))?;
    py.detach(|| -> cablenav::Result<command::Output> {
        let scenario = source.load()?;
        command::run(&scenario, &request, &mut |_| {})
    })
    .map_err(|e| match rename {
        Some((option, name)) if e.field == option => Error::new(name, e.reason),
        _ => e,
    })
    .map_err(|e| scenario_error(py, e, source.path()))
}

/// JSON text as Python data.
fn from_json(py: Python<'_>, json: &str) -> PyResult<Py<PyAny>> {
    Ok(py.import("json")?.call_method1("loads", (json,))?.unbind())
}

/// Feasible and infeasible sections of a trajectory, exactly (or sampled every `pointwise` in t).
///
/// Returns the dict `cablenav verify SCENARIO --json` prints: `trajectory`, `method`,
/// `feasible`/`infeasible`/`uncertain` t-intervals, `feasible_tau`, `boundaries` (t, τ, the
/// constraint, the side entered), `warnings`. `trajectory` defaults to the
/// scenario's first.
#[pyfunction]
#[pyo3(signature = (scenario, trajectory=None, *, pointwise=None))]
fn verify(py: Python<'_>, scenario: &Bound<'_, PyAny>, trajectory: Option<String>, pointwise: Option<f64>) -> PyResult<Py<PyAny>> {
    call(py, scenario, Ok(Request::Verify { trajectory, pointwise }))
}

/// Lengths, clearances, violated conditions and the wrench set's tension ranges at one pose.
///
/// Returns the dict `cablenav check SCENARIO --pose POSE --json` prints.
#[pyfunction]
#[pyo3(signature = (scenario, pose))]
fn check(py: Python<'_>, scenario: &Bound<'_, PyAny>, pose: String) -> PyResult<Py<PyAny>> {
    call(py, scenario, Ok(Request::Check { pose }))
}

/// `check` where a trajectory (default: the scenario's first) is at `t` ∈ [0, 1], moving as it
/// moves there if it is timed (its tension ranges then include the platform's inertia).
///
/// Returns the dict `cablenav check SCENARIO --trajectory NAME --t T --json` prints.
#[pyfunction]
#[pyo3(signature = (scenario, t, trajectory=None))]
fn check_at(py: Python<'_>, scenario: &Bound<'_, PyAny>, t: f64, trajectory: Option<String>) -> PyResult<Py<PyAny>> {
    call(py, scenario, Ok(Request::CheckAt { trajectory, t }))
}

/// Exact feasible intervals of one pose coordinate over `range`, the others held at `pose`'s.
///
/// `vary` is one of "x", "y", "z", "phi", "theta", "sigma" (or, for a multi-link robot, one of
/// its joint coordinates, `pose` naming a configuration); `range` is (lo, hi), angles in
/// radians. Returns the dict `cablenav ray SCENARIO --pose POSE --vary V --range LO HI --json`
/// prints.
#[pyfunction]
#[pyo3(signature = (scenario, pose, vary, range))]
fn ray(py: Python<'_>, scenario: &Bound<'_, PyAny>, pose: String, vary: &str, range: (f64, f64)) -> PyResult<Py<PyAny>> {
    call(py, scenario, Ok(Request::Ray { pose, vary: vary.to_string(), range: [range.0, range.1] }))
}

/// Each cable's least and greatest tension over the wrench set at `samples` points of a trajectory.
///
/// Returns the dict `cablenav envelope SCENARIO --json` prints (`samples` defaults to 100,
/// `trajectory` to the scenario's first).
#[pyfunction]
#[pyo3(signature = (scenario, trajectory=None, *, samples=None))]
fn envelope(py: Python<'_>, scenario: &Bound<'_, PyAny>, trajectory: Option<String>, samples: Option<usize>) -> PyResult<Py<PyAny>> {
    call(py, scenario, Ok(Request::Envelope { trajectory, samples }))
}

/// The fastest rest-to-rest timing of a trajectory, certified along it by the exact verifier.
///
/// Returns the dict `cablenav time SCENARIO --json` prints (`trajectory` defaults to the
/// scenario's first, `cells` to 400, `margin` to 1e-3).
#[pyfunction]
#[pyo3(signature = (scenario, trajectory=None, *, cells=None, margin=None))]
fn time(py: Python<'_>, scenario: &Bound<'_, PyAny>, trajectory: Option<String>, cells: Option<usize>, margin: Option<f64>) -> PyResult<Py<PyAny>> {
    call(py, scenario, Ok(Request::Time { trajectory, cells, margin }))
}

/// A res × res grid over two coordinates (the others from `pose`), each cell classified, and the
/// connected components of the feasible cells.
///
/// `axes` is two coordinate names, e.g. ("phi", "theta"); `range` is ((lo, hi), (lo, hi)),
/// optional for angle axes ([-π, π]). Returns the dict `cablenav slice … --json` prints
/// (`classes` row-major, `component`, `pose_components`, `fraction_feasible`, …).
#[pyfunction]
#[pyo3(signature = (scenario, pose, axes, res, range=None))]
fn slice(py: Python<'_>, scenario: &Bound<'_, PyAny>, pose: String, axes: (String, String), res: usize, range: Option<((f64, f64), (f64, f64))>) -> PyResult<Py<PyAny>> {
    let request = Request::Slice { pose, axes: [axes.0, axes.1], res, range: range.map(|(a, b)| [[a.0, a.1], [b.0, b.1]]) };
    call(py, scenario, Ok(request))
}

/// The thesis' ray lattice over `axes` (the others held at `pose`'s): every ray's exact feasible
/// intervals, the graph of feasible pieces and its connected components.
///
/// `axes` is a sequence of coordinate names, e.g. ("x", "y"); `ranges` one (lo, hi) per axis,
/// angles in radians; `steps` the grid values per axis (both ends count): one int for every
/// axis, or one per axis. Returns the dict `cablenav lattice SCENARIO --pose POSE --axes A,B
/// --range LO HI LO HI --steps N --json` prints (`rays` with their `feasible` intervals,
/// `pieces`, `edges`, `components`, `point_components`, …).
#[pyfunction]
#[pyo3(signature = (scenario, pose, axes, ranges, steps))]
fn lattice(py: Python<'_>, scenario: &Bound<'_, PyAny>, pose: String, axes: Vec<String>, ranges: Vec<(f64, f64)>, steps: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let steps: Vec<usize> = match steps.extract::<usize>() {
        Ok(n) => vec![n],
        Err(_) => steps.extract().map_err(|_| PyTypeError::new_err("steps must be an int or a sequence of ints"))?,
    };
    let request = Request::Lattice { pose, axes, ranges: ranges.iter().map(|r| [r.0, r.1]).collect(), steps };
    call_renaming(py, scenario, Ok(request), Some(("--range", "ranges")))
}

/// A feasible path for one of the scenario's queries, re-verified exactly; `query` may also be a
/// list of query names, planned in order with one planner (the atlas kept for later queries on
/// the same slice), which returns a list of reports, one per query, each with its `elapsed_ms`.
///
/// `planner="atlas"` (default; 6 cables with a wrench set): Henderson atlas + A*, with
/// `max_charts`, `radius`, `min_radius` (the least chart radius the curvature adaptation gives;
/// `min_radius >= radius` turns it off), `heuristic_weight` (w in f = g + w·h, ≥ 1; 1 is A*),
/// `epsilon` and `identify_angles` (False: the angles as plain coordinates, paper 1's way), as
/// `--max-charts`, `--radius`, `--min-radius`, `--heuristic-weight`, `--epsilon`,
/// `--identify-angles`; `atlas` (a path) starts from the atlas saved in that file, if it exists,
/// and saves the atlas there afterwards, as `--atlas FILE`.
/// `planner="lattice"` (any robot): ray lattice with `steps` grid values per free coordinate
/// (default 7) + A* + Bézier smoothing, verified and repaired.
/// Returns the dict `cablenav plan SCENARIO --query QUERY [--planner lattice --steps N] --json`
/// prints: for the atlas `status` ("found", "no_path" or "budget"), `path`, `verification`,
/// `atlas`, `charts`, `seconds`; for the lattice `status` ("found", "no_path" or "unrepaired"),
/// `message`, `polyline`, `waypoints`, `verification`, `seconds`, …. Unset parameters take the
/// CLI's defaults; a bad one raises `ScenarioError` naming it (`min_radius`).
#[pyfunction]
#[pyo3(signature = (scenario, query, *, planner="atlas", steps=None, max_charts=None, radius=None, min_radius=None, heuristic_weight=None, epsilon=None, identify_angles=None, atlas=None))]
#[allow(clippy::too_many_arguments)]
fn plan(
    py: Python<'_>,
    scenario: &Bound<'_, PyAny>,
    query: &Bound<'_, PyAny>,
    planner: &str,
    steps: Option<usize>,
    max_charts: Option<usize>,
    radius: Option<f64>,
    min_radius: Option<f64>,
    heuristic_weight: Option<f64>,
    epsilon: Option<f64>,
    identify_angles: Option<bool>,
    atlas: Option<std::path::PathBuf>,
) -> PyResult<Py<PyAny>> {
    let (queries, several) = match query.extract::<String>() {
        Ok(one) => (vec![one], false),
        Err(_) => (query.extract::<Vec<String>>().map_err(|_| scenario_error(py, Error::new("query", "must be a query name or a list of query names"), None))?, true),
    };
    let options = AtlasOptions { max_charts, radius, min_radius, heuristic_weight, epsilon, identify_angles };
    // a file that cannot be read is one not made yet: the atlas starts afresh
    let kept = atlas.as_ref().map(|file| std::fs::read_to_string(file).unwrap_or_default());
    let request = PlannerKind::parse(planner).and_then(|planner| {
        let lattice = lattice_params(planner, steps, NAMING.lattice)?;
        let params = atlas_params(planner, &options, NAMING.atlas)?;
        if kept.is_some() && planner != PlannerKind::Atlas {
            return Err(Error::new("atlas", format!("is an option of {}", NAMING.atlas)));
        }
        Ok(Request::Plan { queries, params, planner, lattice, atlas: kept, naming: NAMING })
    });
    let output = run_request(py, scenario, request, None)?;
    if let (Some(file), Some(text)) = (&atlas, output.atlas_file()) {
        std::fs::write(file, text).map_err(|e| scenario_error(py, Error::new("atlas", format!("cannot write {}: {e}", file.display())), None))?;
    }
    let reports = from_json(py, &output.json())?;
    // a list of one query returns a list of one report
    if several && !reports.bind(py).is_instance_of::<pyo3::types::PyList>() {
        return Ok(pyo3::types::PyList::new(py, [reports])?.into_any().unbind());
    }
    Ok(reports)
}

/// A CASPR model directory as a scenario: its `<name>_bodies.xml` and `_cables.xml` and its
/// `_trajectories.xml` if there (or the trajectories file `trajectories`), as `cablenav import`
/// converts them. Returns `{"scenario": dict, "notes": [str]}`; `name` defaults to the model's,
/// `cable_set` (a set's id, as `--cable-set`) to the cables file's default set.
#[pyfunction]
#[pyo3(signature = (model_dir, *, trajectories=None, name=None, cable_set=None))]
fn import_caspr(py: Python<'_>, model_dir: &Bound<'_, PyAny>, trajectories: Option<&Bound<'_, PyAny>>, name: Option<String>, cable_set: Option<String>) -> PyResult<Py<PyAny>> {
    let fspath = |p: &Bound<'_, PyAny>| -> PyResult<String> { py.import("os")?.call_method1("fspath", (p,))?.extract() };
    let dir = fspath(model_dir)?;
    let trajectories = trajectories.map(fspath).transpose()?;
    let imported = py
        .detach(|| -> cablenav::Result<cablenav::scenario::caspr::Import> {
            let read = |p: &str| std::fs::read_to_string(p).map_err(|e| Error::new(p, format!("cannot read: {e}")));
            let names: Vec<String> = std::fs::read_dir(&dir)
                .map_err(|e| Error::new(dir.as_str(), format!("cannot list: {e}")))?
                .filter_map(|e| e.ok().and_then(|e| e.file_name().into_string().ok()))
                .collect();
            let files = cablenav::scenario::caspr::model_files(&names).map_err(|e| Error::new(dir.as_str(), e.reason))?;
            let path = |f: &str| std::path::Path::new(&dir).join(f).to_string_lossy().into_owned();
            let traj_text = match (&trajectories, &files.trajectories) {
                (Some(file), _) => Some(read(file)?),
                (None, Some(own)) => Some(read(&path(own))?),
                (None, None) => None,
            };
            cablenav::scenario::caspr::model_to_json(name.as_deref().unwrap_or(&files.name), &read(&path(&files.bodies))?, &read(&path(&files.cables))?, traj_text.as_deref(), cable_set.as_deref())
        })
        .map_err(|e| scenario_error(py, e, None))?;
    let json = py.import("json")?;
    let out = PyDict::new(py);
    out.set_item("scenario", json.call_method1("loads", (imported.json,))?)?;
    out.set_item("notes", imported.notes)?;
    Ok(out.into_any().unbind())
}

/// The native module; `cablenav/__init__.py` re-exports it.
#[pymodule]
fn _cablenav(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("ScenarioError", m.py().get_type::<ScenarioError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(verify, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(check_at, m)?)?;
    m.add_function(wrap_pyfunction!(ray, m)?)?;
    m.add_function(wrap_pyfunction!(envelope, m)?)?;
    m.add_function(wrap_pyfunction!(time, m)?)?;
    m.add_function(wrap_pyfunction!(slice, m)?)?;
    m.add_function(wrap_pyfunction!(lattice, m)?)?;
    m.add_function(wrap_pyfunction!(plan, m)?)?;
    m.add_function(wrap_pyfunction!(import_caspr, m)?)?;
    Ok(())
}
