//! The command line: JSON shapes, readable text, errors naming the option or field, `--help` per
//! command, completions, exit codes and a silent stderr when piped.

use cablenav::Error;
use cablenav_cli::{run, CliError};

fn files(path: &str) -> cablenav::Result<String> {
    match path {
        "cdpr7.json" => Ok(include_str!("../../static/scenarios/cdpr7.json").to_string()),
        "box.json" => Ok(include_str!("../../static/scenarios/cdpr7-box.json").to_string()),
        "tree.json" => Ok(include_str!("../../static/scenarios/cdpr7-tree.json").to_string()),
        "robocrane.json" => Ok(include_str!("../../static/scenarios/robocrane.json").to_string()),
        "broken.json" => Ok("{\"format\": \"cablenav-scenario/1\", \"robot\": ".to_string()),
        other => Err(Error::new(other, "cannot read: no such file")),
    }
}

fn cli(args: &str) -> Result<String, CliError> {
    run(args.split_whitespace(), &files, &|_, _| Ok(()), &|_| Ok(vec![]), &mut |_| {})
}

fn json(args: &str) -> serde_json::Value {
    serde_json::from_str(&cli(args).unwrap()).unwrap()
}

#[test]
fn verify_json_has_the_documented_fields() {
    let v = json("verify tree.json --trajectory quadratic --json");
    for key in ["trajectory", "feasible", "infeasible", "feasible_tau", "boundaries", "uncertain"] {
        assert!(v.get(key).is_some(), "missing {key}: {v}");
    }
    let b = &v["boundaries"][0];
    assert!(b["t"].is_f64() && b["constraint"].is_string());
    assert!(b["enters"] == "feasible" || b["enters"] == "infeasible");
    let p = json("verify tree.json --trajectory quadratic --pointwise 0.01 --json");
    assert_eq!(p["method"], "pointwise");
}

/// `verify --all` gives one report per trajectory, in file order, each the same as verifying that
/// trajectory alone (the batch runs in parallel; the results must not depend on it).
#[test]
fn verify_all_reports_every_trajectory_in_order() {
    let all = json("verify tree.json --all --json");
    let reports = all.as_array().expect("an array of reports");
    assert_eq!(reports.iter().map(|r| r["trajectory"].as_str().unwrap()).collect::<Vec<_>>(), ["linear", "quadratic"]);
    for r in reports {
        let name = r["trajectory"].as_str().unwrap();
        assert_eq!(r, &json(&format!("verify tree.json --trajectory {name} --json")), "{name}");
    }
    let sampled = json("verify tree.json --all --pointwise 0.01 --json");
    assert!(sampled.as_array().unwrap().iter().all(|r| r["method"] == "pointwise"));
    let text = cli("verify tree.json --all").unwrap();
    assert!(text.starts_with("trajectory linear (exact)") && text.contains("trajectory quadratic (exact)"));
    assert!(cli("verify tree.json --all --trajectory linear").is_err(), "--all and --trajectory conflict");
}

#[test]
fn ray_and_check_outputs() {
    let v = json("ray box.json --pose fig310 --vary x --range 0.2 3.8 --json");
    assert_eq!(v["vary"], "x");
    assert!(v["boundaries"][0]["value"].is_f64());
    let c = json("check box.json --pose fig310 --json");
    assert_eq!(c["feasible"], false);
    assert_eq!(c["lengths"].as_array().unwrap().len(), 7);
    assert!(c["violated"].as_array().unwrap().iter().any(|x| x == "cable 3 - box"));
    let text = cli("check box.json --pose fig310").unwrap();
    assert!(text.contains("VIOLATED"));
    let text = cli("verify cdpr7.json").unwrap();
    assert!(text.starts_with("trajectory linear (exact)"));
}

#[test]
fn bad_command_lines_name_the_culprit() {
    let cases = [
        ("", ""),
        ("frobnicate cdpr7.json", ""),
        ("verify", "SCENARIO"),
        ("verify missing.json", "missing.json"),
        ("verify broken.json", "broken.json"),
        ("verify cdpr7.json --trajectory nope", "trajectory"),
        ("verify cdpr7.json --pointwise 0", "--pointwise"),
        ("verify cdpr7.json --pointwise abc", "--pointwise"),
        ("verify cdpr7.json --pointwise NaN", "--pointwise"),
        ("verify cdpr7.json --pointwise", "--pointwise"),
        ("verify cdpr7.json --bogus", "--bogus"),
        ("verify cdpr7.json --json --json", "--json"),
        ("ray cdpr7.json --pose start --vary w --range 0 1", "--vary"),
        ("ray cdpr7.json --pose start --vary x --range 1 0", "--range"),
        ("ray cdpr7.json --pose start --vary x --range 0 inf", "--range"),
        ("ray cdpr7.json --pose start --vary x", "--range"),
        ("ray cdpr7.json --pose nobody --vary x --range 0 1", "nobody"),
        ("check cdpr7.json", "--pose"),
        ("check cdpr7.json --pose start --trajectory linear", "--trajectory"),
    ];
    for (args, field) in cases {
        let e = cli(args).expect_err(args);
        assert!(e.to_string().contains(field), "{args:?} → {e}");
    }
}

#[test]
fn slice_json_png_and_errors() {
    let v = json("slice robocrane.json --pose q1 --axes phi,theta --res 40 --json");
    assert_eq!(v["axes"], serde_json::json!(["phi", "theta"]));
    assert_eq!(v["res"], 40);
    assert_eq!(v["classes"].as_array().unwrap().len(), 1600);
    assert!(v["pose_components"]["q1"].is_u64());
    assert_eq!(v["pose_components"]["q1"], v["pose_components"]["q2"]);
    // the singularity curves det J = 0, as polylines of (phi, theta) points
    let curves = v["singular_curves"].as_array().unwrap();
    assert!(!curves.is_empty() && curves.iter().all(|c| c.as_array().unwrap().iter().all(|p| p.as_array().unwrap().len() == 2)));
    assert!(cli("slice robocrane.json --pose q1 --axes phi,theta --res 40").unwrap().contains("singularity curves (det J = 0)"));
    let written = std::cell::RefCell::new(Vec::new());
    let args = "slice robocrane.json --pose q1 --axes phi,theta --res 20 --png out.png".split(' ');
    let write = |path: &str, bytes: &[u8]| {
        written.borrow_mut().push((path.to_string(), bytes.len()));
        Ok(())
    };
    let text = run(args, &files, &write, &|_| Ok(vec![]), &mut |_| {}).unwrap();
    assert!(text.contains("component"));
    assert_eq!(written.borrow()[0].0, "out.png");
    for (args, field) in [
        ("slice robocrane.json --pose q1 --axes phi --res 10", "--axes"),
        ("slice robocrane.json --pose q1 --axes phi,theta --res ten", "--res"),
        ("slice robocrane.json --pose q1 --axes x,y --res 10", "--range"),
        ("slice robocrane.json --pose q1 --axes x,y --res 10 --range 0 1 2", "--range"),
    ] {
        let e = cli(args).expect_err(args);
        assert!(e.to_string().contains(field), "{args:?} → {e}");
    }
}

#[test]
fn binary_exits_non_zero_with_one_line_on_stderr() {
    use std::process::Command;
    let exe = env!("CARGO_BIN_EXE_cablenav");
    let out = Command::new(exe).args(["verify", "no/such/file.json"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("no/such/file.json"));
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let out = Command::new(exe).args(["verify", &format!("{root}/static/scenarios/cdpr7.json"), "--json"]).output().unwrap();
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["feasible"], serde_json::json!([[0.0, 1.0]]));
}

/// `cablenav plan --json` prints the documented fields, the path from the start pose exactly to
/// the goal pose exactly, and the verification; bad options are errors naming the option.
#[test]
fn cli_plan_prints_the_documented_report() {
    let v: serde_json::Value = serde_json::from_str(&cli("plan robocrane.json --query q1-q2 --json").unwrap()).unwrap();
    assert_eq!(v["status"], "found");
    assert!(v["charts"].as_u64().unwrap() > 1);
    assert!(v["seconds"].is_number() || v["seconds"].is_null());
    assert_eq!(v["verification"]["infeasible_sections"], 0);
    let path = v["path"].as_array().unwrap();
    let s = cablenav::Scenario::from_json(include_str!("../../static/scenarios/robocrane.json")).unwrap();
    let (start, goal) = (s.pose("q1").unwrap(), s.pose("q2").unwrap());
    let first = &path[0];
    let last = &path[path.len() - 1];
    assert_eq!(first["quaternion"], serde_json::json!(start.quaternion()));
    assert_eq!(last["quaternion"], serde_json::json!(goal.quaternion()));
    assert_eq!(first["position"], serde_json::json!([0.0, 0.0, 2.0]));
    assert_eq!(first["tilt_torsion"].as_array().unwrap().len(), 3);
    let text = cli("plan robocrane.json --query q1-q2 --radius 0.3 --epsilon 0.3 --max-charts 5000").unwrap();
    assert!(text.starts_with("plan q1-q2: found"), "{text}");
    // The defaults adapt the chart radii (here 0.1 to 1) and weight the heuristic; the old fixed
    // radius and plain A* are options. With them q5 → q6 needs more than 3 charts.
    let adapted = cli("plan robocrane.json --query q1-q2").unwrap();
    assert!(adapted.starts_with("plan q1-q2: found") && adapted.contains("r = 0.1–1,") && adapted.contains("w = 1.5,"), "{adapted}");
    let budget = cli("plan robocrane.json --query q5-q6 --radius 0.4 --min-radius 0.4 --heuristic-weight 1 --max-charts 3").unwrap();
    assert!(budget.starts_with("plan q5-q6: budget (3 charts") && budget.contains("r = 0.4,") && budget.contains("w = 1,"), "{budget}");
    for (args, field) in [
        ("plan robocrane.json", "--query"),
        ("plan robocrane.json --query q1-q2 --radius -1", "--radius"),
        ("plan robocrane.json --query q1-q2 --epsilon x", "--epsilon"),
        ("plan robocrane.json --query q1-q2 --min-radius 0", "--min-radius"),
        ("plan robocrane.json --query q1-q2 --heuristic-weight 0.9", "--heuristic-weight"),
        ("plan robocrane.json --query q1-q2 --max-charts 0", "--max-charts"),
        ("plan robocrane.json --query q1-q2 --pose q1", "--pose"),
    ] {
        assert_eq!(cli(args).unwrap_err().field(), field, "{args}");
    }
    assert_eq!(cli("plan robocrane.json --query q9").unwrap_err().field(), "query");
}

/// Every command has its own `--help` naming its options and the exit codes; `cablenav --help`
/// lists the commands; `--version` prints the version. All of them succeed (exit 0).
#[test]
fn every_command_has_its_own_help() {
    let top = cli("--help").unwrap();
    for command in ["verify", "ray", "check", "envelope", "slice", "plan", "completions"] {
        assert!(top.contains(command), "{command} missing from:\n{top}");
    }
    assert!(top.contains("Exit codes"), "{top}");
    for (command, options) in [
        ("verify", &["--trajectory", "--pointwise", "--json"][..]),
        ("ray", &["--pose", "--vary", "--range", "x, y, z, phi, theta, sigma"][..]),
        ("check", &["--pose", "--json"][..]),
        ("envelope", &["--trajectory", "--samples"][..]),
        ("slice", &["--axes", "--res", "--range", "--png"][..]),
        ("plan", &["--query", "--max-charts", "--radius", "--min-radius", "--heuristic-weight", "--epsilon", "--identify-angles", "[default: 100000]"][..]),
    ] {
        for help in [cli(&format!("{command} --help")).unwrap(), cli(&format!("help {command}")).unwrap()] {
            assert!(help.contains("Usage: cablenav"), "{help}");
            assert!(help.contains("Exit codes"), "{help}");
            for option in options {
                assert!(help.contains(option), "{command} --help lacks {option}:\n{help}");
            }
        }
    }
    assert!(cli("--version").unwrap().starts_with("cablenav "));
}

/// `cablenav completions SHELL` prints a completion script that knows the commands and options.
#[test]
fn completions_for_each_shell() {
    let bash = cli("completions bash").unwrap();
    assert!(bash.contains("complete") && bash.contains("--max-charts") && bash.contains("envelope"), "{bash}");
    for shell in ["zsh", "fish", "powershell", "elvish"] {
        let script = cli(&format!("completions {shell}")).unwrap();
        assert!(script.contains("--pointwise"), "{shell}");
    }
    assert_eq!(cli("completions tcsh").unwrap_err().field(), "SHELL");
}

/// The binary's exit codes: 0 on success and on `--help`, 2 on a bad command line (clap's
/// message with the usage) and on bad input (one line); a successful run prints nothing on a
/// piped stderr (no progress bar).
#[test]
fn binary_exit_codes_and_silent_stderr_when_piped() {
    use std::process::Command;
    let exe = env!("CARGO_BIN_EXE_cablenav");
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let run = |args: &[&str]| Command::new(exe).args(args).output().unwrap();
    let help = run(&["plan", "--help"]);
    assert_eq!(help.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&help.stdout).contains("--max-charts"));
    let usage = run(&["verify", "x.json", "--bogus"]);
    assert_eq!(usage.status.code(), Some(2));
    let err = String::from_utf8_lossy(&usage.stderr);
    assert!(err.contains("--bogus") && err.contains("Usage: cablenav verify"), "{err}");
    assert_eq!(run(&[]).status.code(), Some(2));
    let robocrane = format!("{root}/static/scenarios/robocrane.json");
    let plan = run(&["plan", &robocrane, "--query", "q1-q2", "--json"]);
    assert_eq!(plan.status.code(), Some(0));
    assert!(plan.stderr.is_empty(), "{}", String::from_utf8_lossy(&plan.stderr));
    let v: serde_json::Value = serde_json::from_slice(&plan.stdout).unwrap();
    assert_eq!(v["status"], "found");
}

/// On a terminal (a pseudo-terminal made by util-linux's `script`) a long command draws its
/// progress bar on stderr, fed by the planner's progress fraction, and clears it before the report.
#[test]
fn binary_draws_a_progress_bar_on_a_terminal() {
    use std::process::Command;
    let exe = env!("CARGO_BIN_EXE_cablenav");
    let scenario = concat!(env!("CARGO_MANIFEST_DIR"), "/../static/scenarios/robocrane.json");
    let command = format!("{exe} plan {scenario} --query q1-q2");
    let out = Command::new("script").args(["-qec", &command, "/dev/null"]).output().expect("util-linux `script` runs");
    assert!(out.status.success(), "{out:?}");
    let tty = String::from_utf8_lossy(&out.stdout);
    assert!(tty.contains("planning (‰)"), "no progress bar on the terminal:\n{tty}");
    assert!(tty.contains("\u{1b}[2K"), "the bar is not cleared:\n{tty}");
    let report = tty.rsplit("\u{1b}[2K").next().unwrap_or("");
    assert!(report.trim_start().starts_with("plan q1-q2: found"), "{report}");
}

/// `lattice`, `slice` and `verify --all` draw their bars (fed by the core's counters) on a
/// terminal and clear them; piped, stderr stays empty and stdout is exactly the report the
/// terminal shows after the bar.
#[test]
fn long_commands_draw_bars_on_a_terminal_and_print_the_same_report_when_piped() {
    use std::process::Command;
    let exe = env!("CARGO_BIN_EXE_cablenav");
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let box_ = format!("{root}/static/scenarios/cdpr7-box.json");
    let robocrane = format!("{root}/static/scenarios/robocrane.json");
    let runs: [(&str, Vec<String>); 3] = [
        ("rays", ["lattice", &box_, "--pose", "start", "--axes", "x,y,z", "--range", "0.2", "3.8", "1.1", "2.9", "0.3", "3.7", "--steps", "7"].map(String::from).to_vec()),
        ("slice rows", ["slice", &robocrane, "--pose", "q1", "--axes", "phi,theta", "--res", "200"].map(String::from).to_vec()),
        ("trajectories verified", ["verify", &box_, "--all"].map(String::from).to_vec()),
    ];
    for (stage, args) in runs {
        let out = Command::new("script").args(["-qec", &format!("{exe} {}", args.join(" ")), "/dev/null"]).output().expect("util-linux `script` runs");
        assert!(out.status.success(), "{out:?}");
        let tty = String::from_utf8_lossy(&out.stdout).replace("\r\n", "\n");
        assert!(tty.contains(stage), "{}: no progress bar on the terminal:\n{tty}", args[0]);
        assert!(tty.contains("\u{1b}[2K"), "{}: the bar is not cleared:\n{tty}", args[0]);
        let report = tty.rsplit("\u{1b}[2K").next().unwrap_or("").trim_start_matches(['\r', '\n']);
        let piped = Command::new(exe).args(&args).output().unwrap();
        assert!(piped.status.success() && piped.stderr.is_empty(), "{}: {}", args[0], String::from_utf8_lossy(&piped.stderr));
        assert_eq!(report, String::from_utf8_lossy(&piped.stdout), "{}", args[0]);
    }
}

/// `cablenav import MODEL_DIR`: the bodies, cables and trajectories files found in the directory
/// (or another trajectories file, `--trajectories`), the scenario written to --out (a summary
/// printed) or printed; a directory without a model is an error naming it.
#[test]
fn import_reads_a_model_directory() {
    let bodies = include_str!("../../../shared/models/caspr/CoGiRo/CoGiRo_bodies.xml");
    let cables = include_str!("../../../shared/models/caspr/CoGiRo/CoGiRo_cables.xml");
    let trajectories = include_str!("../../../shared/models/caspr/CoGiRo/CoGiRo_trajectories.xml");
    let only_long = trajectories.replacen("<quintic_spline_trajectory id=\"general_1\"", "<linear_spline_trajectory id=\"general_1\"", 1).replacen(
        "</quintic_spline_trajectory>\n        <quintic_spline_trajectory id=\"general_2\"",
        "</linear_spline_trajectory>\n        <quintic_spline_trajectory id=\"general_2\"",
        1,
    );
    let read = |p: &str| match p {
        "m/CoGiRo_bodies.xml" => Ok(bodies.to_string()),
        "m/CoGiRo_cables.xml" => Ok(cables.to_string()),
        "m/CoGiRo_trajectories.xml" => Ok(trajectories.to_string()),
        "other.xml" => Ok(only_long.clone()),
        _ => Err(cablenav::Error::new(p, "no such file")),
    };
    let list = |p: &str| if p == "m" || p == "m/" { Ok(vec!["CoGiRo_trajectories.xml".to_string(), "CoGiRo_cables.xml".into(), "CoGiRo_bodies.xml".into()]) } else { Ok(vec![]) };
    let written = std::cell::RefCell::new(Vec::new());
    let write = |p: &str, bytes: &[u8]| {
        written.borrow_mut().push((p.to_string(), String::from_utf8_lossy(bytes).into_owned()));
        Ok(())
    };
    let printed = run("import m/ --out cogiro.json".split(' '), &read, &write, &list, &mut |_| {}).unwrap();
    assert!(printed.contains("wrote cogiro.json: CoGiRo (8 cables, mass 91.058 kg, timed trajectories general_1, general_2, general_3, long_stable)"), "{printed}");
    let (path, text) = written.borrow()[0].clone();
    assert_eq!(path, "cogiro.json");
    let s = cablenav::Scenario::from_json(&text).unwrap();
    assert_eq!((s.name.as_str(), s.robot.dynamics.as_ref().unwrap().mass), ("CoGiRo", 91.058));
    let printed = run("import m --name crane".split(' '), &read, &write, &list, &mut |_| {}).unwrap();
    assert_eq!(cablenav::Scenario::from_json(&printed).unwrap().name, "crane");
    let printed = run("import m --trajectories other.xml --out o.json".split(' '), &read, &write, &list, &mut |_| {}).unwrap();
    assert!(printed.contains("timed trajectories general_2, general_3, long_stable)") && printed.contains("note: ") && printed.contains("linear_spline_trajectory"), "{printed}");
    let e = run("import empty".split(' '), &read, &write, &list, &mut |_| {}).unwrap_err();
    assert_eq!(e.field(), "empty");
}

/// `import --cable-set ID` imports another cable set of the cables file (the default one without
/// it, and a note names the sets); an unknown set is an error at `--cable-set` listing the file's.
#[test]
fn import_picks_a_cable_set() {
    let bodies = include_str!("../../../shared/models/caspr/Example_spatial/Example_spatial_bodies.xml");
    let cables = include_str!("../../../shared/models/caspr/Example_spatial/Example_spatial_cables.xml");
    let read = |p: &str| match p {
        "m/Example_spatial_bodies.xml" => Ok(bodies.to_string()),
        "m/Example_spatial_cables.xml" => Ok(cables.to_string()),
        _ => Err(cablenav::Error::new(p, "no such file")),
    };
    let list = |_: &str| Ok(vec!["Example_spatial_cables.xml".to_string(), "Example_spatial_bodies.xml".into()]);
    let write = |_: &str, _: &[u8]| Ok(());
    let count = |text: &str| cablenav::Scenario::from_json(text).unwrap().robot.cables.len();
    assert_eq!(count(&run("import m".split(' '), &read, &write, &list, &mut |_| {}).unwrap()), 7);
    assert_eq!(count(&run("import m --cable-set basic_8_cables".split(' '), &read, &write, &list, &mut |_| {}).unwrap()), 8);
    let printed = run("import m --cable-set cross_8_cables --out o.json".split(' '), &read, &write, &list, &mut |_| {}).unwrap();
    assert!(printed.contains("(8 cables") && printed.contains("cable set \"cross_8_cables\" of 4"), "{printed}");
    let e = run("import m --cable-set nine".split(' '), &read, &write, &list, &mut |_| {}).unwrap_err();
    assert_eq!(e.field(), "--cable-set");
    assert!(e.to_string().contains("\"nine\"") && e.to_string().contains("basic_7_cables"), "{e}");
}

/// `plan --query A --query B … --json` prints one report per query, in order, each with its
/// `status` and `elapsed_ms`; the second query on q1-q2's slice reuses its atlas (`reused_charts`),
/// the one on another slice does not; each verdict is the one the query gets alone.
#[test]
fn plan_answers_several_queries_in_order_reusing_the_atlas() {
    let all = json("plan robocrane.json --query q1-q2 --query q3-q4 --query q5-q6 --json");
    let reports = all.as_array().expect("an array of reports");
    assert_eq!(reports.iter().map(|r| r["query"].as_str().unwrap()).collect::<Vec<_>>(), ["q1-q2", "q3-q4", "q5-q6"]);
    for r in reports {
        assert!(r["elapsed_ms"].as_f64().is_some_and(|ms| ms >= 0.0), "{r}");
        let alone = json(&format!("plan robocrane.json --query {} --json", r["query"].as_str().unwrap()));
        assert_eq!((&r["status"], alone["reused_charts"].as_u64()), (&alone["status"], Some(0)));
    }
    assert_eq!(reports[0]["reused_charts"], 0);
    assert_eq!(reports[1]["reused_charts"], reports[0]["charts"], "q3-q4 starts from q1-q2's atlas");
    assert_eq!(reports[2]["reused_charts"], 0, "q5-q6 is on another slice");
    let text = cli("plan robocrane.json --query q1-q2 --query q3-q4").unwrap();
    assert!(text.starts_with("plan q1-q2: found") && text.contains("plan q3-q4: found"), "{text}");
    let e = cli("plan robocrane.json --query q1-q2 --query q3-q4 --out x.json").unwrap_err();
    assert_eq!(e.field(), "--out");
    let e = cli("plan robocrane.json --query q1-q2 --query nope").unwrap_err();
    assert_eq!(e.field(), "query");
}

/// `--identify-angles false` plans with the angles as plain coordinates from the poses' written
/// angles: q3-q4 becomes paper 1's hard query (hundreds of charts, not one).
#[test]
fn plan_in_paper_coordinates() {
    let paper = json("plan robocrane.json --query q3-q4 --identify-angles false --json");
    let usual = json("plan robocrane.json --query q3-q4 --json");
    assert_eq!((&paper["status"], &usual["status"]), (&serde_json::json!("found"), &serde_json::json!("found")));
    assert_eq!(paper["params"]["identify_angles"], false);
    assert!(paper["charts"].as_u64().unwrap() > 100 && usual["charts"].as_u64().unwrap() < 5, "{} and {} charts", paper["charts"], usual["charts"]);
    assert_eq!(cli("plan robocrane.json --query q3-q4 --identify-angles maybe").unwrap_err().field(), "--identify-angles");
    let e = cli("plan robocrane.json --query q3-q4 --planner lattice --identify-angles false").unwrap_err();
    assert_eq!(e.field(), "--identify-angles");
}
