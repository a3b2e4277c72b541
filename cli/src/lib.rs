//! The `cablenav` command line: clap parses the arguments into a [`cablenav::command::Request`],
//! the core runs it, and the report is printed as text or JSON. [`run`] is pure — it takes the
//! arguments, a file reader and writer and a progress hook and returns what to print — so it is
//! testable without processes; the binary (`src/main.rs`) adds the file system, progress bars
//! and exit codes.

mod args;

pub use args::{Cli, Command, EXIT_CODES};

use cablenav::command::{self, Output, Progress};
use cablenav::Scenario;
use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::{CommandFactory, Parser};
use std::fmt;

/// Reads a scenario file by path.
pub type Read<'a> = &'a dyn Fn(&str) -> cablenav::Result<String>;
/// Writes an output file (`--png`, `--out`) by path.
pub type Write<'a> = &'a dyn Fn(&str, &[u8]) -> cablenav::Result<()>;
/// Lists the file names in a directory (`import MODEL_DIR`).
pub type List<'a> = &'a dyn Fn(&str) -> cablenav::Result<Vec<String>>;

/// Why a command failed.
#[derive(Debug)]
pub enum CliError {
    /// The command line itself is wrong (unknown option, missing or malformed value): clap's
    /// message, with the usage and a pointer to `--help`.
    Usage(clap::Error),
    /// The command line parsed, but its input is wrong: an unreadable or invalid scenario (the
    /// field's JSON path), an unknown pose or trajectory, an option value the core rejects.
    Input(cablenav::Error),
}

impl CliError {
    /// The option, argument or scenario field the error is about (`--range`, `SCENARIO`,
    /// `robot.cables[2].base`, …); empty when there is none (a missing or unknown command).
    pub fn field(&self) -> String {
        match self {
            CliError::Input(e) => e.field.clone(),
            CliError::Usage(e) => {
                let name = |v: &ContextValue| match v {
                    ContextValue::String(s) => Some(s.clone()),
                    ContextValue::Strings(v) => v.first().cloned(),
                    _ => None,
                };
                let arg = e.get(ContextKind::InvalidArg).and_then(name).unwrap_or_default();
                // "--range <LO> <HI>" → "--range", "<SCENARIO>" → "SCENARIO".
                arg.split_whitespace().next().unwrap_or("").trim_matches(['<', '>']).to_string()
            }
        }
    }

    /// The process exit code (documented in [`EXIT_CODES`]).
    pub fn exit_code(&self) -> u8 {
        2
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Usage(e) => write!(f, "{}", e.render().to_string().trim_end()),
            CliError::Input(e) => write!(f, "cablenav: {}", e.to_string().lines().next().unwrap_or("error")),
        }
    }
}

impl From<cablenav::Error> for CliError {
    fn from(e: cablenav::Error) -> Self {
        CliError::Input(e)
    }
}

/// Runs one command line (without the program name) and returns what to print on stdout:
/// the report, `--help`, `--version` or a completion script. Long commands report to `progress`.
pub fn run<I, S>(args: I, read: Read, write: Write, list: List, progress: &mut dyn FnMut(Progress)) -> Result<String, CliError>
where
    I: IntoIterator<Item = S>,
    S: Into<std::ffi::OsString> + Clone,
{
    let args = std::iter::once(std::ffi::OsString::from("cablenav")).chain(args.into_iter().map(Into::into));
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) => return Ok(e.render().to_string()),
        Err(e) => return Err(CliError::Usage(e)),
    };
    let invocation = match cli.command {
        Command::Completions { shell } => {
            let mut out = Vec::new();
            clap_complete::generate(shell, &mut Cli::command(), "cablenav", &mut out);
            return Ok(String::from_utf8_lossy(&out).into_owned());
        }
        Command::Import { dir, out, name, trajectories, cable_set } => {
            let model = Model { out: out.as_deref(), name: name.as_deref(), trajectories: trajectories.as_deref(), cable_set: cable_set.as_deref() };
            return Ok(import(&dir, model, read, write, list)?);
        }
        command => command.invocation()?,
    };
    let path = &invocation.scenario;
    let scenario = Scenario::from_json(&read(path)?).map_err(|e| cablenav::Error::new(format!("{path}: {}", e.field), e.reason))?;
    let mut request = invocation.request.clone();
    if let (Some(file), command::Request::Plan { atlas, .. }) = (&invocation.atlas, &mut request) {
        // a file that cannot be read is one not made yet: the atlas starts afresh
        *atlas = Some(read(file).unwrap_or_default());
    }
    let output = command::run(&scenario, &request, progress).map_err(|e| match (&invocation.atlas, e.field.strip_prefix("atlas")) {
        // an atlas file's fault names the option and the file (and the chart, if one is at fault)
        (Some(file), Some(within)) => cablenav::Error::new("--atlas", format!("{file}{}: {}", within.trim_start_matches('.').split_once('[').map_or(String::new(), |(_, c)| format!(", chart [{c}")), e.reason)),
        _ => e,
    })?;
    if let (Output::Slice(map), Some(png)) = (&output, &invocation.png) {
        write(png, &map.png())?;
    }
    let mut printed = if invocation.json { output.json() } else { output.text() };
    if let (Some(file), Some(text)) = (&invocation.atlas, output.atlas_file()) {
        write(file, text.as_bytes())?;
        if !invocation.json {
            printed += &format!("\n  saved the atlas to {file} (a later `plan --atlas {file}` starts from it)\n");
        }
    }
    if let Some(file) = &invocation.out {
        // a multi-link robot's path goes in as a trajectory through new configurations
        let (text, name) = match (output.joint_path(), output.trajectory()) {
            (Some(p), _) => cablenav::scenario::with_joint_path(&read(path)?, p)?,
            (None, Some(traj)) => cablenav::scenario::with_trajectory(&read(path)?, traj)?,
            (None, None) => return Err(cablenav::Error::new("--out", "no trajectory was planned: nothing to write").into()),
        };
        write(file, text.as_bytes())?;
        if !invocation.json {
            printed += &format!("\n  wrote {file} with the trajectory \"{name}\" (check it: cablenav verify {file} --trajectory {name})\n");
        }
    }
    Ok(printed)
}

/// The options of `cablenav import`.
struct Model<'a> {
    /// Where to write the scenario.
    out: Option<&'a str>,
    /// The scenario's name.
    name: Option<&'a str>,
    /// Another trajectories file than the model directory's.
    trajectories: Option<&'a str>,
    /// The cable set to import (`None`: the file's default).
    cable_set: Option<&'a str>,
}

/// `cablenav import`: the CASPR model in `dir` (with its trajectories, or those of
/// `--trajectories`) as scenario JSON, written to `out` (then a summary is returned) or returned.
fn import(dir: &str, Model { out, name, trajectories, cable_set }: Model, read: Read, write: Write, list: List) -> cablenav::Result<String> {
    let files = cablenav::scenario::caspr::model_files(&list(dir)?).map_err(|e| cablenav::Error::new(dir, e.reason))?;
    let path = |f: &str| format!("{}/{f}", dir.trim_end_matches('/'));
    let (bodies, cables) = (read(&path(&files.bodies))?, read(&path(&files.cables))?);
    let trajectories = match (trajectories, &files.trajectories) {
        (Some(file), _) => Some(read(file)?),
        (None, Some(own)) => Some(read(&path(own))?),
        (None, None) => None,
    };
    let imported = cablenav::scenario::caspr::model_to_json(name.unwrap_or(&files.name), &bodies, &cables, trajectories.as_deref(), cable_set)
        .map_err(|e| if e.field == "cable_set" { cablenav::Error::new("--cable-set", e.reason) } else { e })?;
    let scenario = Scenario::from_json(&imported.json)?;
    let Some(out) = out else { return Ok(imported.json) };
    write(out, imported.json.as_bytes())?;
    let mut text = format!("wrote {out}: {} ({} cables", scenario.name, scenario.robot.cables.len());
    let links_mass: f64 = scenario.robot.chain.iter().flat_map(|c| &c.links).map(|l| l.mass).sum();
    text += &match &scenario.robot.dynamics {
        Some(d) => format!(", mass {} kg", d.mass),
        None if links_mass > 0.0 => format!(", links' mass {links_mass} kg"),
        None => ", massless".to_string(),
    };
    let timed: Vec<&str> = scenario.trajectories.iter().filter(|t| t.knots.is_some()).map(|t| t.name.as_str()).collect();
    text += &match timed.as_slice() {
        [] => ")\n".to_string(),
        names => format!(", timed trajectories {})\n", names.join(", ")),
    };
    for note in &imported.notes {
        text += &format!("  note: {note}\n");
    }
    Ok(text)
}
