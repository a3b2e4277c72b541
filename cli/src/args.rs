//! The command line's grammar (clap derive): one subcommand per core command, each with its own
//! `--help`, turned into a [`Request`] for the core.

use cablenav::command::Request;
use cablenav::plan::atlas::PlanParams;
use cablenav::plan::{atlas_params, lattice_params, AtlasOptions, PlannerKind, PlannerNaming};
use clap::{Parser, Subcommand};
use clap_complete::Shell;

/// How the command line's users choose the planners.
const NAMING: PlannerNaming = PlannerNaming { atlas: "--planner atlas", lattice: "--planner lattice" };

/// The exit codes, as `cablenav --help` documents them.
pub const EXIT_CODES: &str = "\
Exit codes:
  0   success (also --help, --version, completions)
  2   bad command line (unknown option, missing or malformed value: clap's message and usage on
      stderr) or bad input (unreadable or invalid scenario, unknown pose/trajectory/query, a value
      the core rejects: one line on stderr naming the option or the scenario field)
  70  internal error: a bug (please report the command and the scenario)
  74  the report could not be written to stdout";

const SCENARIO_HELP: &str = "A cablenav-scenario/1 to /6 JSON file (docs/scenario-format.md)";

/// Exact feasibility of cable-driven parallel robot motions.
///
/// Every command reads a cablenav-scenario/1 JSON file (docs/scenario-format.md) and prints a
/// readable report, or with --json the report as JSON (the same JSON the page, the Python and
/// the npm packages return).
#[derive(Debug, Parser)]
#[command(name = "cablenav", version, after_help = EXIT_CODES, arg_required_else_help = true)]
pub struct Cli {
    /// The command to run.
    #[command(subcommand)]
    pub command: Command,
}

/// The commands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Feasible/infeasible t-sections of a trajectory (exact; --pointwise DT samples instead)
    #[command(after_help = EXIT_CODES)]
    Verify {
        #[arg(value_name = "SCENARIO", help = SCENARIO_HELP)]
        scenario: String,
        /// The trajectory to verify [default: the scenario's first]
        #[arg(long, value_name = "NAME", conflicts_with = "all")]
        trajectory: Option<String>,
        /// Verify every trajectory of the scenario (in parallel; one report each, in file order)
        #[arg(long)]
        all: bool,
        /// Sample every DT in t instead of verifying exactly (1e-7 ≤ DT ≤ 1)
        #[arg(long, value_name = "DT", value_parser = finite, allow_negative_numbers = true)]
        pointwise: Option<f64>,
        /// Print the report as JSON
        #[arg(long)]
        json: bool,
    },
    /// Feasible intervals of one coordinate, the others fixed at the pose's (or a multi-link
    /// robot's configuration's) values
    #[command(after_help = EXIT_CODES)]
    Ray {
        #[arg(value_name = "SCENARIO", help = SCENARIO_HELP)]
        scenario: String,
        /// The pose (multi-link robots: the configuration) the other coordinates come from
        #[arg(long, value_name = "NAME")]
        pose: String,
        /// The coordinate to vary: one of x, y, z, phi, theta, sigma, or a multi-link robot's joint
        /// coordinate (its name in the scenario, or q1, q2, …)
        #[arg(long, value_name = "COORD")]
        vary: String,
        /// The interval of the varied coordinate (angles in radians)
        #[arg(long, num_args = 2, value_names = ["LO", "HI"], required = true, value_parser = finite, allow_negative_numbers = true)]
        range: Vec<f64>,
        /// Print the report as JSON
        #[arg(long)]
        json: bool,
    },
    /// Lengths, distances, violated conditions and the wrench set's tension ranges at one pose, or
    /// where a trajectory is at t (--trajectory NAME --t T: moving, if the trajectory is timed)
    #[command(after_help = EXIT_CODES)]
    Check {
        #[arg(value_name = "SCENARIO", help = SCENARIO_HELP)]
        scenario: String,
        /// The pose to check
        #[arg(long, value_name = "NAME", required_unless_present = "trajectory", conflicts_with = "trajectory")]
        pose: Option<String>,
        /// Check where this trajectory is at --t instead of a pose
        #[arg(long, value_name = "NAME", requires = "t")]
        trajectory: Option<String>,
        /// The trajectory's parameter t ∈ [0, 1]
        #[arg(long, value_name = "T", value_parser = finite, requires = "trajectory")]
        t: Option<f64>,
        /// Print the report as JSON
        #[arg(long)]
        json: bool,
    },
    /// Each cable's least and greatest tension over the wrench set along a trajectory
    #[command(after_help = EXIT_CODES)]
    Envelope {
        #[arg(value_name = "SCENARIO", help = SCENARIO_HELP)]
        scenario: String,
        /// The trajectory [default: the scenario's first]
        #[arg(long, value_name = "NAME")]
        trajectory: Option<String>,
        /// Samples along the trajectory [default: 100]
        #[arg(long, value_name = "N")]
        samples: Option<usize>,
        /// Print the report as JSON
        #[arg(long)]
        json: bool,
    },
    /// The fastest timing of a trajectory, rest to rest, certified along it by the exact verifier
    /// (tension bounds with the wrench set, winch and platform speed limits)
    #[command(after_help = EXIT_CODES)]
    Time {
        #[arg(value_name = "SCENARIO", help = SCENARIO_HELP)]
        scenario: String,
        /// The trajectory [default: the scenario's first]
        #[arg(long, value_name = "NAME")]
        trajectory: Option<String>,
        /// Grid cells over the whole path [default: 400]
        #[arg(long, value_name = "N")]
        cells: Option<usize>,
        /// Relative margin the limits are tightened by at the grid points [default: 0.001]
        #[arg(long, value_name = "M", value_parser = finite, allow_negative_numbers = true)]
        margin: Option<f64>,
        /// Print the report as JSON
        #[arg(long)]
        json: bool,
    },
    /// Classify a res×res grid over two coordinates (the others from the pose) and find the
    /// connected components of its feasible cells
    #[command(after_help = EXIT_CODES)]
    Slice {
        #[arg(value_name = "SCENARIO", help = SCENARIO_HELP)]
        scenario: String,
        /// The pose the other coordinates come from
        #[arg(long, value_name = "NAME")]
        pose: String,
        /// Two coordinates, columns first (x, y, z, phi, theta, sigma)
        #[arg(long, value_name = "A,B", value_parser = axes)]
        axes: [String; 2],
        /// Grid side (cells per axis)
        #[arg(long, value_name = "N")]
        res: usize,
        /// The two axes' ranges [default for angles: -pi pi; required for position axes]
        #[arg(long, num_args = 4, value_names = ["LO1", "HI1", "LO2", "HI2"], value_parser = finite, allow_negative_numbers = true)]
        range: Option<Vec<f64>>,
        /// Also write the map as a PNG image, one pixel per cell
        #[arg(long, value_name = "FILE")]
        png: Option<String>,
        /// Print the report as JSON
        #[arg(long)]
        json: bool,
    },
    /// The thesis' ray lattice over the chosen coordinates (the others from the pose): every
    /// ray's exact feasible intervals, the graph of feasible pieces and its components
    /// (docs/lattice.md)
    #[command(after_help = EXIT_CODES)]
    Lattice {
        #[arg(value_name = "SCENARIO", help = SCENARIO_HELP)]
        scenario: String,
        /// The pose (multi-link robots: the configuration) the other coordinates come from
        #[arg(long, value_name = "NAME")]
        pose: String,
        /// The coordinates, comma-separated (x, y, z, phi, theta, sigma, or a multi-link robot's
        /// joint coordinates)
        #[arg(long, value_name = "A,B[,C…]")]
        axes: String,
        /// One LO HI pair per axis, in the order of --axes
        #[arg(long, num_args = 2.., value_names = ["LO", "HI"], value_parser = finite, allow_negative_numbers = true)]
        range: Vec<f64>,
        /// Grid values per axis (both ends of the range count): one number, or one per axis (7,9)
        #[arg(long, value_name = "N[,N…]")]
        steps: String,
        /// Print the report as JSON
        #[arg(long)]
        json: bool,
    },
    /// A feasible path for a query of the scenario. --planner atlas (default; 6 cables with a
    /// wrench set): Henderson atlas + A*, docs/planner.md, found / no_path / budget, the path
    /// re-verified edge by edge. --planner lattice (any robot): ray lattice + A* + Bézier
    /// smoothing, verified exactly and repaired, docs/lattice.md; for a multi-link robot over its
    /// joint coordinates, a path through configurations verified exactly, docs/multilink.md
    #[command(after_help = EXIT_CODES)]
    Plan {
        #[arg(value_name = "SCENARIO", help = SCENARIO_HELP)]
        scenario: String,
        /// The query (start and goal poses or configurations) to plan; repeat it to plan several in order, one report
        /// each (later queries on the same slice reuse the atlas of the earlier ones)
        #[arg(long, value_name = "NAME", required = true)]
        query: Vec<String>,
        /// The planner: atlas or lattice
        #[arg(long, value_name = "NAME", default_value = "atlas")]
        planner: String,
        /// Lattice planner: grid values per free coordinate [default: 7]
        #[arg(long, value_name = "N")]
        steps: Option<usize>,
        /// Write the scenario with the planned trajectory added (as QUERY-lattice or QUERY-atlas; a
        /// multi-link robot's through new configurations QUERY-lattice-0, -1, …) to FILE, so that
        /// `cablenav verify FILE --trajectory NAME` checks it
        #[arg(long, value_name = "FILE")]
        out: Option<String>,
        /// Atlas planner: chart budget (it stops with `budget` after this many charts)
        #[arg(long, value_name = "N", help = format!("Atlas planner: chart budget (it stops with `budget` after this many charts) [default: {}]", PlanParams::default().max_charts))]
        max_charts: Option<usize>,
        /// Atlas planner: largest chart radius r (the start chart's)
        #[arg(long, value_name = "R", value_parser = finite, allow_negative_numbers = true, help = format!("Atlas planner: largest chart radius r (the start chart's) [default: {}]", PlanParams::default().radius))]
        radius: Option<f64>,
        /// Atlas planner: smallest chart radius the curvature adaptation gives
        #[arg(long, value_name = "R", value_parser = finite, allow_negative_numbers = true, help = format!("Atlas planner: smallest chart radius the curvature adaptation gives (≥ --radius: every chart has radius r) [default: {}]", PlanParams::default().min_radius))]
        min_radius: Option<f64>,
        /// Atlas planner: weight w of the search's heuristic
        #[arg(long, value_name = "W", value_parser = finite, allow_negative_numbers = true, help = format!("Atlas planner: weight w of the search's heuristic, f = g + w·h (1: A*) [default: {}]", PlanParams::default().heuristic_weight))]
        heuristic_weight: Option<f64>,
        /// Atlas planner: chart validity threshold ε
        #[arg(long, value_name = "E", value_parser = finite, allow_negative_numbers = true, help = format!("Atlas planner: chart validity threshold ε (distance to the parent's tangent space) [default: {}]", PlanParams::default().epsilon))]
        epsilon: Option<f64>,
        /// Atlas planner: false takes the angles as plain coordinates, as paper 1 does (the poses'
        /// angles as the scenario writes them, no wrapping) [default: true]
        #[arg(long, value_name = "BOOL", action = clap::ArgAction::Set)]
        identify_angles: Option<bool>,
        /// Atlas planner: start from the atlas saved in FILE (if it can be read; it must have been
        /// made for this robot and these parameters) and save the atlas there afterwards, so
        /// that later runs answer queries on its slice from it
        #[arg(long, value_name = "FILE")]
        atlas: Option<String>,
        /// Print the report as JSON
        #[arg(long)]
        json: bool,
    },
    /// Convert a CASPR model into a scenario: MODEL_DIR holds CASPR's <name>_bodies.xml and
    /// <name>_cables.xml (the platform's mass and inertia come along, format 4); the scenario
    /// goes to --out FILE, or to stdout without it
    #[command(after_help = EXIT_CODES)]
    Import {
        /// The model's directory
        #[arg(value_name = "MODEL_DIR")]
        dir: String,
        /// Write the scenario JSON to FILE (and print a summary) instead of printing it
        #[arg(long, value_name = "FILE")]
        out: Option<String>,
        /// The scenario's name [default: the model's, from its file names]
        #[arg(long, value_name = "NAME")]
        name: Option<String>,
        /// Read the timed trajectories from FILE, another CASPR trajectories file of the same
        /// model [default: MODEL_DIR's <name>_trajectories.xml, if there]
        #[arg(long, value_name = "FILE")]
        trajectories: Option<String>,
        /// Import the cable set with this id [default: the cables file's default_cable_set]
        #[arg(long, value_name = "ID")]
        cable_set: Option<String>,
    },
    /// Print a shell completion script (e.g. `cablenav completions bash > /etc/bash_completion.d/cablenav`)
    Completions {
        /// The shell
        #[arg(value_enum)]
        shell: Shell,
    },
}

/// A parsed command: which scenario file, what to ask the core, how to print it.
#[derive(Debug, Clone, PartialEq)]
pub struct Invocation {
    /// The scenario file's path.
    pub scenario: String,
    /// The core's request.
    pub request: Request,
    /// Print JSON instead of text.
    pub json: bool,
    /// Where to write the slice map's PNG.
    pub png: Option<String>,
    /// Where to write the scenario with the planned trajectory added.
    pub out: Option<String>,
    /// The atlas file to start planning from and save the atlas to.
    pub atlas: Option<String>,
}

impl Command {
    /// The core request of a command that reads a scenario (not of `completions`).
    pub fn invocation(self) -> cablenav::Result<Invocation> {
        let plain = |scenario, request, json| Ok(Invocation { scenario, request, json, png: None, out: None, atlas: None });
        match self {
            Command::Verify { scenario, all: true, pointwise, json, .. } => plain(scenario, Request::VerifyAll { pointwise }, json),
            Command::Verify { scenario, trajectory, pointwise, json, .. } => plain(scenario, Request::Verify { trajectory, pointwise }, json),
            Command::Ray { scenario, pose, vary, range, json } => {
                plain(scenario, Request::Ray { pose, vary, range: [range[0], range[1]] }, json)
            }
            Command::Check { scenario, pose, trajectory, t, json } => {
                let request = match (pose, t) {
                    (Some(pose), _) => Request::Check { pose },
                    (None, Some(t)) => Request::CheckAt { trajectory, t },
                    (None, None) => return Err(cablenav::Error::new("--pose", "give --pose NAME, or --trajectory NAME --t T")),
                };
                plain(scenario, request, json)
            }
            Command::Envelope { scenario, trajectory, samples, json } => plain(scenario, Request::Envelope { trajectory, samples }, json),
            Command::Time { scenario, trajectory, cells, margin, json } => plain(scenario, Request::Time { trajectory, cells, margin }, json),
            Command::Slice { scenario, pose, axes, res, range, png, json } => {
                let range = range.map(|r| [[r[0], r[1]], [r[2], r[3]]]);
                Ok(Invocation { scenario, request: Request::Slice { pose, axes, res, range }, json, png, out: None, atlas: None })
            }
            Command::Lattice { scenario, pose, axes, range, steps, json } => {
                let axes = axes.split(',').map(|a| a.trim().to_string()).collect();
                if range.len() % 2 != 0 {
                    return Err(cablenav::Error::new("--range", format!("needs LO HI pairs, got {} numbers", range.len())));
                }
                let ranges = range.chunks(2).map(|p| [p[0], p[1]]).collect();
                let steps = steps
                    .split(',')
                    .map(|n| n.trim().parse::<usize>().map_err(|_| cablenav::Error::new("--steps", format!("not a whole number: {n:?}"))))
                    .collect::<cablenav::Result<Vec<usize>>>()?;
                plain(scenario, Request::Lattice { pose, axes, ranges, steps }, json)
            }
            Command::Plan { scenario, query, planner, steps, out, max_charts, radius, min_radius, heuristic_weight, epsilon, identify_angles, atlas: atlas_file, json } => {
                let planner = PlannerKind::parse(&planner)?;
                let lattice = lattice_params(planner, steps, NAMING.lattice)?;
                let atlas = AtlasOptions { max_charts, radius, min_radius, heuristic_weight, epsilon, identify_angles };
                let params = atlas_params(planner, &atlas, NAMING.atlas)?;
                if out.is_some() && query.len() > 1 {
                    return Err(cablenav::Error::new("--out", format!("writes one planned trajectory: give one --query, not {}", query.len())));
                }
                if atlas_file.is_some() && planner != PlannerKind::Atlas {
                    return Err(cablenav::Error::new("--atlas", "is an option of --planner atlas"));
                }
                // the file's text is read by `run`, which also writes the atlas back
                let atlas = atlas_file.as_ref().map(|_| String::new());
                Ok(Invocation { scenario, request: Request::Plan { queries: query, params, planner, lattice, atlas, naming: NAMING }, json, png: None, out, atlas: atlas_file })
            }
            Command::Completions { .. } => Err(cablenav::Error::new("completions", "reads no scenario")),
            Command::Import { .. } => Err(cablenav::Error::new("import", "reads a CASPR model, not a scenario")),
        }
    }
}

/// A finite number.
fn finite(text: &str) -> Result<f64, String> {
    let x: f64 = text.parse().map_err(|_| format!("not a number: {text:?}"))?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!("must be a finite number, got {x}"))
    }
}

/// Two coordinate names separated by a comma (checked against the scenario by the core).
fn axes(text: &str) -> Result<[String; 2], String> {
    match text.split(',').map(|a| a.trim().to_string()).collect::<Vec<_>>().as_slice() {
        [a, b] if !a.is_empty() && !b.is_empty() => Ok([a.clone(), b.clone()]),
        _ => Err(format!("{text:?} is not two coordinates separated by a comma (x, y, z, phi, theta, sigma, or a multi-link robot's joint coordinates)")),
    }
}
