//! The `cablenav` command line: argument parsing and output formatting over the core. Pure: it
//! takes the arguments and a file reader and returns the text to print, so it is testable and the
//! binary stays a thin wrapper.

use crate::error::{Error, Result};
use crate::model::Coord;
use crate::lattice::{Lattice, LatticeReport, LatticeSpec};
use crate::plan::choice::{run as run_planner, Details, PlannerKind, PlannerOptions};
use crate::plan::lattice::LatticePlanReport;
use crate::plan::{PlanReport, PlanStatus};
use crate::scenario::with_trajectory;
use crate::report::{PoseReport, RayReport, Side, TensionEnvelope, VerifyReport};
use crate::verify::slice::{default_range, Class, SliceMap};
use crate::verify::{check_pose, ray, slice, tension_envelope, verify_pointwise, verify_trajectory};
use crate::Scenario;
use serde::Serialize;

/// Usage text.
pub const USAGE: &str = "\
usage:
  cablenav verify SCENARIO [--trajectory NAME] [--pointwise DT] [--json]
  cablenav ray    SCENARIO --pose NAME --vary x|y|z|phi|theta|sigma --range LO HI [--json]
  cablenav check  SCENARIO --pose NAME [--json]
  cablenav envelope SCENARIO [--trajectory NAME] [--samples N] [--json]
  cablenav slice  SCENARIO --pose NAME --axes A,B --res N [--range LO HI LO HI] [--png FILE] [--json]
  cablenav lattice SCENARIO --pose NAME --axes A,B[,C…] --range LO HI [LO HI …] --steps N[,N…] [--json]
  cablenav plan   SCENARIO --query NAME [--planner atlas|lattice] [--steps N] [--max-charts N]
                  [--radius R] [--epsilon E] [--out FILE] [--json]

SCENARIO is a cablenav-scenario/1 JSON file (docs/scenario-format.md).
verify  feasible/infeasible t-sections of a trajectory (exact; --pointwise DT samples instead)
ray     feasible intervals of one pose coordinate, the others fixed at the pose's values
check   lengths, distances, violated conditions and the wrench set's tension ranges at one pose
envelope  each cable's least and greatest tension over the wrench set along a trajectory
slice   classify a res×res grid over two coordinates (others from the pose) and find the
        connected components of its feasible cells; angles default to [-pi, pi]
lattice the thesis' ray lattice over the chosen coordinates (others from the pose): every ray's
        exact feasible intervals, the graph of feasible pieces and its components (docs/lattice.md)
plan    a feasible path for a query of the scenario. --planner atlas (default; 6 cables with a
        wrench set): Henderson atlas + A*, docs/planner.md, found / no_path / budget, the path
        re-verified edge by edge. --planner lattice (any robot): ray lattice with --steps values
        per free coordinate (default 7) + A* + Bézier smoothing, verified exactly and repaired,
        docs/lattice.md. --out FILE writes the scenario with the planned trajectory added";

/// Parsed options of one command.
struct Opts {
    positional: Vec<String>,
    flags: Vec<(String, Vec<String>)>,
}

impl Opts {
    fn parse(args: &[String], command: &str) -> Result<Opts> {
        let slice = command == "slice";
        let takes = |f: &str| match f {
            "--trajectory" | "--pointwise" | "--pose" | "--vary" | "--axes" | "--res" | "--png" | "--samples" | "--query" | "--max-charts"
            | "--radius" | "--epsilon" | "--planner" | "--steps" | "--out" => Some(1),
            "--range" => Some(if slice { 4 } else { 2 }),
            "--json" => Some(0),
            _ => None,
        };
        let mut o = Opts { positional: vec![], flags: vec![] };
        let mut i = 0;
        while i < args.len() {
            let a = &args[i];
            if a.starts_with("--") {
                let mut n = takes(a).ok_or_else(|| Error::new(a.as_str(), "unknown option"))?;
                if command == "lattice" && a == "--range" {
                    // LO HI per axis: every number that follows
                    n = args[i + 1..].iter().take_while(|x| x.parse::<f64>().is_ok()).count();
                }
                if i + 1 + n > args.len() {
                    return Err(Error::new(a.as_str(), format!("needs {n} value(s)")));
                }
                if o.flags.iter().any(|(f, _)| f == a) {
                    return Err(Error::new(a.as_str(), "given twice"));
                }
                o.flags.push((a.clone(), args[i + 1..i + 1 + n].to_vec()));
                i += 1 + n;
            } else {
                o.positional.push(a.clone());
                i += 1;
            }
        }
        Ok(o)
    }

    fn get(&self, flag: &str) -> Option<&[String]> {
        self.flags.iter().find(|(f, _)| f == flag).map(|(_, v)| v.as_slice())
    }

    fn one(&self, flag: &str) -> Option<&str> {
        self.get(flag).and_then(|v| v.first()).map(String::as_str)
    }

    fn required(&self, flag: &str) -> Result<&str> {
        self.one(flag).ok_or_else(|| Error::new(flag, "is required"))
    }

    fn json(&self) -> bool {
        self.get("--json").is_some()
    }

    fn allow(&self, allowed: &[&str]) -> Result<()> {
        match self.flags.iter().find(|(f, _)| !allowed.contains(&f.as_str())) {
            Some((f, _)) => Err(Error::new(f.as_str(), "is not an option of this command")),
            None => Ok(()),
        }
    }
}

fn number(flag: &str, text: &str) -> Result<f64> {
    let x: f64 = text.parse().map_err(|_| Error::new(flag, format!("not a number: {text:?}")))?;
    crate::error::finite(flag, x)
}

fn to_json<T: Serialize>(v: &T) -> Result<String> {
    serde_json::to_string_pretty(v).map_err(|e| Error::new("output", e.to_string()))
}

/// Reads a scenario file by path.
pub type Read<'a> = &'a dyn Fn(&str) -> Result<String>;
/// Writes an output file (`--png`) by path.
pub type Write<'a> = &'a dyn Fn(&str, &[u8]) -> Result<()>;

/// Runs one command and returns what to print.
pub fn run(args: &[String], read: Read, write: Write) -> Result<String> {
    let Some((command, rest)) = args.split_first() else {
        return Err(Error::new("", format!("no command given\n{USAGE}")));
    };
    if command == "--help" || command == "-h" || command == "help" {
        return Ok(USAGE.to_string());
    }
    let o = Opts::parse(rest, command)?;
    let path = match o.positional.as_slice() {
        [p] => p.as_str(),
        [] => return Err(Error::new("SCENARIO", "no scenario file given")),
        more => return Err(Error::new("SCENARIO", format!("expected one scenario file, got {}", more.len()))),
    };
    let scenario = Scenario::from_json(&read(path)?).map_err(|e| Error::new(format!("{path}: {}", e.field), e.reason))?;
    match command.as_str() {
        "verify" => {
            o.allow(&["--trajectory", "--pointwise", "--json"])?;
            let traj = scenario.trajectory(o.one("--trajectory"))?;
            let report = match o.one("--pointwise") {
                Some(dt) => verify_pointwise(&scenario, traj, number("--pointwise", dt)?)?,
                None => verify_trajectory(&scenario, traj)?,
            };
            if o.json() { to_json(&report) } else { Ok(verify_text(&report)) }
        }
        "ray" => {
            o.allow(&["--pose", "--vary", "--range", "--json"])?;
            let pose = o.required("--pose")?;
            let vary = o.required("--vary")?;
            let coord = Coord::parse(vary).ok_or_else(|| Error::new("--vary", format!("{vary:?} is not one of x, y, z, phi, theta, sigma")))?;
            let range = o.get("--range").ok_or_else(|| Error::new("--range", "is required"))?;
            let report = ray(&scenario, pose, coord, number("--range", &range[0])?, number("--range", &range[1])?)?;
            if o.json() { to_json(&report) } else { Ok(ray_text(&report)) }
        }
        "check" => {
            o.allow(&["--pose", "--json"])?;
            let name = o.required("--pose")?;
            let report = check_pose(&scenario, name, scenario.pose(name)?);
            if o.json() { to_json(&report) } else { Ok(check_text(&report)) }
        }
        "envelope" => {
            o.allow(&["--trajectory", "--samples", "--json"])?;
            let traj = scenario.trajectory(o.one("--trajectory"))?;
            let samples = match o.one("--samples") {
                Some(n) => n.parse().map_err(|_| Error::new("--samples", format!("not a whole number: {n:?}")))?,
                None => 100,
            };
            let env = tension_envelope(&scenario, traj, samples)?;
            if o.json() { to_json(&env) } else { Ok(envelope_text(&env)) }
        }
        "slice" => {
            o.allow(&["--pose", "--axes", "--res", "--range", "--png", "--json"])?;
            let pose = o.required("--pose")?;
            let axes_text = o.required("--axes")?;
            let axes: Vec<Coord> = axes_text.split(',').map(|a| Coord::parse(a.trim())).collect::<Option<_>>().filter(|v: &Vec<Coord>| v.len() == 2).ok_or_else(|| {
                Error::new("--axes", format!("{axes_text:?} is not two of x, y, z, phi, theta, sigma separated by a comma"))
            })?;
            let res_text = o.required("--res")?;
            let res: usize = res_text.parse().map_err(|_| Error::new("--res", format!("not a whole number: {res_text:?}")))?;
            let range = match o.get("--range") {
                Some(r) => {
                    let v = r.iter().map(|x| number("--range", x)).collect::<Result<Vec<f64>>>()?;
                    [[v[0], v[1]], [v[2], v[3]]]
                }
                None => {
                    let pick = |c: Coord| default_range(c).ok_or_else(|| Error::new("--range", format!("is required for the position axis {}", c.name())));
                    [pick(axes[0])?, pick(axes[1])?]
                }
            };
            let map = slice(&scenario, pose, [axes[0], axes[1]], res, range)?;
            if let Some(path) = o.one("--png") {
                write(path, &map.png())?;
            }
            if o.json() { to_json(&map) } else { Ok(slice_text(&map)) }
        }
        "lattice" => {
            o.allow(&["--pose", "--axes", "--range", "--steps", "--json"])?;
            let pose = scenario.pose(o.required("--pose")?)?;
            let axes_text = o.required("--axes")?;
            let axes = axes_text
                .split(',')
                .map(|a| Coord::parse(a.trim()).ok_or_else(|| Error::new("--axes", format!("{:?} is not one of x, y, z, phi, theta, sigma", a.trim()))))
                .collect::<Result<Vec<Coord>>>()?;
            let range = o.get("--range").ok_or_else(|| Error::new("--range", "is required"))?;
            let v = range.iter().map(|x| number("--range", x)).collect::<Result<Vec<f64>>>()?;
            if v.len() % 2 != 0 {
                return Err(Error::new("--range", format!("needs LO HI pairs, got {} numbers", v.len())));
            }
            let ranges = v.chunks(2).map(|p| [p[0], p[1]]).collect();
            let steps = o
                .required("--steps")?
                .split(',')
                .map(|n| n.trim().parse::<usize>().map_err(|_| Error::new("--steps", format!("not a whole number: {n:?}"))))
                .collect::<Result<Vec<usize>>>()?;
            let spec = LatticeSpec::new(axes, ranges, steps, pose.coords())?;
            let report = Lattice::build(&scenario, spec).report().ok_or_else(|| Error::new("lattice", "the lattice stopped before its end"))?;
            if o.json() { to_json(&report) } else { Ok(lattice_text(&report)) }
        }
        "plan" => {
            o.allow(&["--query", "--planner", "--steps", "--max-charts", "--radius", "--epsilon", "--out", "--json"])?;
            let query = o.required("--query")?;
            let kind = PlannerKind::parse(o.one("--planner").unwrap_or("atlas"))?;
            let mut options = PlannerOptions::new(kind);
            let only = |flag: &str, for_kind: PlannerKind| {
                if o.one(flag).is_some() && kind != for_kind {
                    Err(Error::new(flag, format!("is an option of --planner {}", for_kind.name())))
                } else {
                    Ok(())
                }
            };
            for flag in ["--max-charts", "--radius", "--epsilon"] {
                only(flag, PlannerKind::Atlas)?;
            }
            only("--steps", PlannerKind::Lattice)?;
            if let Some(n) = o.one("--max-charts") {
                options.atlas.max_charts = n.parse().map_err(|_| Error::new("--max-charts", format!("not a whole number: {n:?}")))?;
            }
            if let Some(r) = o.one("--radius") {
                options.atlas.radius = number("--radius", r)?;
            }
            if let Some(e) = o.one("--epsilon") {
                options.atlas.epsilon = number("--epsilon", e)?;
            }
            if let Some(n) = o.one("--steps") {
                options.lattice.steps = n.parse().map_err(|_| Error::new("--steps", format!("not a whole number: {n:?}")))?;
            }
            let result = run_planner(&scenario, query, &options, &clock).map_err(|e| match e.field.as_str() {
                "radius" | "epsilon" | "max_charts" => Error::new(format!("--{}", e.field.replace('_', "-")), e.reason),
                _ => e,
            })?;
            let mut out = match (&result.details, o.json()) {
                (details, true) => to_json(details)?,
                (Details::Atlas(r), false) => plan_text(r),
                (Details::Lattice(r), false) => lattice_plan_text(r),
            };
            if let Some(file) = o.one("--out") {
                let traj = result.trajectory.as_ref().ok_or_else(|| Error::new("--out", "no trajectory was planned: nothing to write"))?;
                let (text, name) = with_trajectory(&read(path)?, traj)?;
                write(file, text.as_bytes())?;
                if !o.json() {
                    out += &format!("\n  wrote {file} with the trajectory \"{name}\" (check it: cablenav verify {file} --trajectory \"{name}\")\n");
                }
            }
            Ok(out)
        }
        other => Err(Error::new("", format!("unknown command {other:?}\n{USAGE}"))),
    }
}

fn side(s: Side) -> &'static str {
    match s {
        Side::Feasible => "feasible",
        Side::Infeasible => "infeasible",
    }
}

fn intervals(v: &[[f64; 2]]) -> String {
    if v.is_empty() {
        return "none".to_string();
    }
    v.iter().map(|iv| format!("[{:.9}, {:.9}]", iv[0], iv[1])).collect::<Vec<_>>().join(" ∪ ")
}

/// The closing lines of a report: conservative conditions and warnings.
fn notes(conservative: &[String], warnings: &[String]) -> String {
    let mut out = String::new();
    if !conservative.is_empty() {
        out += &format!("  conservative (enlarged shapes): {}\n", conservative.join(", "));
    }
    for w in warnings {
        out += &format!("  warning: {w}\n");
    }
    out
}

fn verify_text(r: &VerifyReport) -> String {
    let mut out = format!("trajectory {} ({}", r.trajectory, r.method);
    if let Some(dt) = r.step {
        out += &format!(", Δt = {dt}");
    }
    out += ")\n";
    out += &format!("  feasible   t ∈ {}\n", intervals(&r.feasible));
    out += &format!("  infeasible t ∈ {}\n", intervals(&r.infeasible));
    out += &format!("  feasible   τ ∈ {}\n", intervals(&r.feasible_tau));
    for b in &r.boundaries {
        out += &format!("  boundary t = {:.9} (τ = {:.9}): {} → {}\n", b.t, b.tau, b.constraint, side(b.enters));
    }
    out += &format!("  uncertain  t ∈ {}\n", intervals(&r.uncertain));
    out + &notes(&r.conservative, &r.warnings)
}

fn ray_text(r: &RayReport) -> String {
    let mut out = format!("ray {} over [{}, {}] from pose {}\n", r.vary, r.range[0], r.range[1], r.pose);
    out += &format!("  feasible   {} ∈ {}\n", r.vary, intervals(&r.feasible));
    out += &format!("  infeasible {} ∈ {}\n", r.vary, intervals(&r.infeasible));
    for b in &r.boundaries {
        out += &format!("  boundary {} = {:.9}: {} → {}\n", r.vary, b.value, b.constraint, side(b.enters));
    }
    out += &format!("  uncertain  {} ∈ {}\n", r.vary, intervals(&r.uncertain));
    out + &notes(&r.conservative, &r.warnings)
}

fn check_text(r: &PoseReport) -> String {
    let mut out = format!("pose {}: {}\n", r.pose, if r.feasible { "feasible" } else { "infeasible" });
    let lengths: Vec<String> = r.lengths.iter().map(|l| format!("{l:.6}")).collect();
    out += &format!("  cable lengths: {}\n", lengths.join(" "));
    for c in &r.checks {
        let d = c.distance.map_or("-".to_string(), |d| format!("{d:.6}"));
        let mark = if c.violated { "VIOLATED" } else { "ok" };
        let exact = if c.exact { "" } else { " (conservative)" };
        out += &format!("  {:<28} {:>12}  {}{}\n", c.constraint, d, mark, exact);
    }
    if let Some(w) = &r.wrench {
        let verdict = if w.feasible { "feasible" } else { "infeasible" };
        match w.margin {
            Some(m) => out += &format!("  wrench: {verdict}, margin {m:.6}, active: {}\n", w.active),
            None => out += &format!("  wrench: {verdict} ({})\n", w.active),
        }
        for (i, (lo, hi)) in w.tension_min.iter().zip(&w.tension_max).enumerate() {
            out += &format!("    cable {} tension ∈ [{lo:.6}, {hi:.6}]\n", i + 1);
        }
    }
    out
}

fn slice_text(m: &SliceMap) -> String {
    let mut out = format!(
        "slice over ({}, {}) ∈ [{}, {}] × [{}, {}], {}×{} cells\n  feasible: {:.2}% in {} component(s)\n",
        m.axes[0], m.axes[1], m.range[0][0], m.range[0][1], m.range[1][0], m.range[1][1], m.res, m.res,
        100.0 * m.fraction_feasible, m.components
    );
    for (name, c) in &m.pose_components {
        out += &format!("  pose {name}: {}\n", c.map_or("infeasible".to_string(), |c| format!("component {c}")));
    }
    if m.res <= 100 {
        out += &format!("  map ({} to the right, {} upwards; . feasible, T tension, L length, S singular, X interference):\n", m.axes[0], m.axes[1]);
        for j in (0..m.res).rev() {
            let row: String = (0..m.res)
                .map(|i| match m.classes[j * m.res + i] {
                    Class::Feasible => '.',
                    Class::Tension => 'T',
                    Class::Length => 'L',
                    Class::Singular => 'S',
                    Class::Interference => 'X',
                })
                .collect();
            out += &format!("  {row}\n");
        }
    }
    out
}

fn envelope_text(e: &TensionEnvelope) -> String {
    let mut out = format!("tension envelope along {} ({} samples): t, then [min, max] per cable\n", e.trajectory, e.t.len());
    for (k, t) in e.t.iter().enumerate() {
        let row = match (&e.tension_min[k], &e.tension_max[k]) {
            (Some(lo), Some(hi)) => lo.iter().zip(hi).map(|(a, b)| format!("[{a:.4}, {b:.4}]")).collect::<Vec<_>>().join(" "),
            _ => "singular".to_string(),
        };
        out += &format!("  {t:.4}  {row}\n");
    }
    out
}

/// Seconds since a fixed origin (NaN on wasm32, which has no `Instant`).
fn clock() -> f64 {
    #[cfg(not(target_arch = "wasm32"))]
    {
        use std::sync::OnceLock;
        static ORIGIN: OnceLock<std::time::Instant> = OnceLock::new();
        ORIGIN.get_or_init(std::time::Instant::now).elapsed().as_secs_f64()
    }
    #[cfg(target_arch = "wasm32")]
    {
        f64::NAN
    }
}

fn status_name(s: PlanStatus) -> &'static str {
    match s {
        PlanStatus::Found => "found",
        PlanStatus::NoPath => "no_path",
        PlanStatus::Budget => "budget",
        PlanStatus::Unrepaired => "unrepaired",
    }
}

fn lattice_text(r: &LatticeReport) -> String {
    let axes: Vec<String> = r.axes.iter().zip(&r.ranges).zip(&r.steps).map(|((a, g), n)| format!("{a} ∈ [{}, {}] ({n} values)", g[0], g[1])).collect();
    let mut out = format!("lattice over {}: {} rays, {} feasible pieces, {} component(s)\n", axes.join(", "), r.rays.len(), r.pieces, r.components);
    out += &format!("  grid points: {} of {} feasible on every ray through them", r.feasible_points, r.grid_points);
    if r.disagreements > 0 {
        out += &format!(" ({} where the rays through them disagree)", r.disagreements);
    }
    out += "\n";
    if r.uncertain_rays > 0 {
        out += &format!("  warning: {} ray(s) have uncertain sections (counted as infeasible)\n", r.uncertain_rays);
    }
    const SHOWN: usize = 200;
    for (ray, comps) in r.rays.iter().zip(&r.piece_components).take(SHOWN) {
        let at: Vec<String> = ray.fixed.iter().filter(|(k, _)| r.axes.contains(k)).map(|(k, v)| format!("{k} = {v:.6}")).collect();
        let pieces: Vec<String> = ray.feasible.iter().zip(comps).map(|(iv, c)| format!("[{:.6}, {:.6}] (component {c})", iv[0], iv[1])).collect();
        out += &format!("  {} at {}: {}\n", ray.vary, at.join(", "), if pieces.is_empty() { "none".to_string() } else { pieces.join(" ∪ ") });
    }
    if r.rays.len() > SHOWN {
        out += &format!("  … {} more rays (--json prints all)\n", r.rays.len() - SHOWN);
    }
    out + &notes(&r.conservative, &r.warnings)
}

fn lattice_plan_text(r: &LatticePlanReport) -> String {
    let mut out = format!("plan {} (lattice): {} ({:.3} s)\n  {}\n", r.query, status_name(r.status), r.seconds, r.message);
    out += &format!(
        "  lattice: {} rays, {} component(s); {} of {} segments to cell corners verified; A* expanded {} points\n",
        r.rays, r.components, r.segments[0], r.segments[1], r.expanded
    );
    if !r.polyline.is_empty() {
        out += &format!("  A* polyline: {} points, length {:.6}; {} waypoints\n", r.polyline.len(), r.polyline_length, r.waypoints.len());
        out += &format!("  smoothed: {} piece(s) ({} single polyline edges) after {} repair(s)\n", r.pieces, r.polyline_pieces, r.repairs);
        for (i, c) in r.waypoints.iter().enumerate() {
            out += &format!("  {i:5}  p = [{:.6}, {:.6}, {:.6}]  (φ, θ, σ) = ({:.6}, {:.6}, {:.6})\n", c[0], c[1], c[2], c[3], c[4], c[5]);
        }
    }
    if let Some(v) = &r.verification {
        out += &format!("  verified: feasible t ∈ {}; infeasible t ∈ {}; uncertain t ∈ {}\n", intervals(&v.feasible), intervals(&v.infeasible), intervals(&v.uncertain));
    }
    out
}

fn plan_text(r: &PlanReport) -> String {
    let status = status_name(r.status);
    let (a, p) = (&r.atlas, &r.atlas.params);
    let mut out = format!(
        "plan {}: {status} ({} charts, {}-D, {:.3} s; r = {}, ε = {}, δ = {}, κ = {}, margins ≥ {}, ≤ {} charts)\n",
        r.query, r.charts, a.dimension, r.seconds, p.radius, p.epsilon, p.delta, p.barrier, p.min_margin, p.max_charts
    );
    match r.status {
        PlanStatus::Found => {
            let v = &r.verification;
            out += &format!("  path: {} poses; re-verified: {} edges, {} infeasible and {} uncertain sections; {} of {} poses wrench-infeasible",
                r.path.len(), v.edges, v.infeasible_sections, v.uncertain_sections, v.wrench_infeasible_poses, v.wrench_poses);
            if let Some(m) = v.least_wrench_margin {
                out += &format!(", least tension margin {m:.4}");
            }
            out += "\n";
            for (i, pose) in r.path.iter().enumerate() {
                let [x, y, z] = pose.position;
                let [a, b, c] = pose.tilt_torsion;
                out += &format!("  {i:5}  p = [{x:.6}, {y:.6}, {z:.6}]  (φ, θ, σ) = ({a:.6}, {b:.6}, {c:.6})\n");
            }
        }
        PlanStatus::NoPath => out += "  the atlas of the start's connected component is exhausted without reaching the goal: no path at this resolution\n",
        PlanStatus::Budget => out += "  the chart budget ran out: nothing is claimed (raise --max-charts)\n",
        PlanStatus::Unrepaired => {}
    }
    if a.expansion_failures > 0 {
        out += &format!("  warning: {} expansion direction(s) failed; a no_path here is not certified\n", a.expansion_failures);
    }
    if a.blocked_charts > 0 {
        out += &format!("  note: {} chart(s) blocked by a clearance violation at their centre\n", a.blocked_charts);
    }
    if a.broken_edges > 0 {
        out += &format!("  warning: {} chart pair(s) or walk(s) to the goal dropped because their dense path could not be followed; a no_path here is not certified\n", a.broken_edges);
    }
    if a.rejected_edges > 0 {
        out += &format!("  note: {} chart pair(s) dropped because the exact verifier rejected their edge (interference)\n", a.rejected_edges);
    }
    out
}
