//! Multi-link robots on the command line (issue 11): joint coordinates wherever pose coordinates
//! go (`check --pose CONFIG`, `ray --vary alpha`, `lattice --axes alpha,beta`), the thesis'
//! Fig. 3.12 cross-section from the preset, an arm imported with its links' masses held by its
//! cables, and the commands that do not take a multi-link robot yet refusing it by name.

use cablenav::Error;
use cablenav_cli::{run, CliError};
use serde_json::Value;

const ARM: &str = include_str!("../../static/multilink/bmarm-x4-2.json");

fn cli(args: &[&str]) -> Result<String, CliError> {
    let read = |p: &str| if p == "arm.json" { Ok(ARM.to_string()) } else { Err(Error::new(p, "no such file")) };
    let write = |_: &str, _: &[u8]| Ok(());
    run(args.iter().copied(), &read, &write, &|_| Ok(vec![]), &mut |_| {})
}

fn json(args: &[&str]) -> Value {
    serde_json::from_str(&cli(args).unwrap_or_else(|e| panic!("{args:?}: {e}"))).unwrap()
}

const QUARTER: &str = "0.7853981633974483";
const MINUS_QUARTER: &str = "-0.7853981633974483";

#[test]
fn check_and_ray_take_joint_coordinates() {
    let check = json(&["check", "arm.json", "--pose", "fig312", "--json"]);
    assert_eq!(check["lengths"].as_array().unwrap().len(), 5);
    assert!(check["checks"].as_array().unwrap().iter().any(|c| c["constraint"] == "cable 4 - link Upper Arm"));

    // fig312 itself lies in the gap between the two regions (cables 2-3); "below" does not
    assert_eq!(check["violated"], serde_json::json!(["cables 2-3"]));
    let ray = json(&["ray", "arm.json", "--pose", "below", "--vary", "alpha", "--range", MINUS_QUARTER, QUARTER, "--json"]);
    assert_eq!(ray["vary"], "alpha");
    let feasible = ray["feasible"].as_array().unwrap();
    assert!(!feasible.is_empty());
    // the same ray by its generic name
    let by_q = json(&["ray", "arm.json", "--pose", "below", "--vary", "q1", "--range", MINUS_QUARTER, QUARTER, "--json"]);
    assert_eq!(by_q["feasible"], ray["feasible"]);
    let text = cli(&["ray", "arm.json", "--pose", "fig312", "--vary", "theta", "--range", "-0.5", "0.5"]).unwrap();
    assert!(text.contains("ray theta over [-0.5, 0.5] from pose fig312"), "{text}");
    // γ's own range is ±0.1745: a ray past it is computed, with a warning
    let past = json(&["ray", "arm.json", "--pose", "fig312", "--vary", "gamma", "--range", "-0.5", "0.5", "--json"]);
    assert!(past["warnings"].as_array().unwrap().iter().any(|w| w.as_str().unwrap().starts_with("gamma: [-0.5, 0.5] leaves the joint's range")), "{past}");
}

#[test]
fn a_slice_map_over_two_joint_coordinates() {
    let m = json(&["slice", "arm.json", "--pose", "fig312", "--axes", "alpha,beta", "--res", "40", "--range", MINUS_QUARTER, QUARTER, MINUS_QUARTER, QUARTER, "--json"]);
    assert_eq!(m["axes"], serde_json::json!(["alpha", "beta"]));
    assert_eq!(m["fixed"].as_array().unwrap().len(), 4);
    let classes = m["classes"].as_array().unwrap();
    assert_eq!(classes.len(), 1600);
    for class in ["feasible", "interference", "tension"] {
        assert!(classes.iter().any(|c| c == class), "no {class} cell");
    }
    // fig312 lies on the slice (α = β = 0 inside the square, γ and θ the fixed ones); initial not
    assert!(m["pose_components"].get("fig312").is_some() && m["pose_components"].get("below").is_some(), "{}", m["pose_components"]);
    assert!(m["pose_components"].get("initial").is_none(), "{}", m["pose_components"]);
    // the default range of angle axes is one turn
    let whole = json(&["slice", "arm.json", "--pose", "fig312", "--axes", "alpha,theta", "--res", "8", "--json"]);
    assert_eq!(whole["range"][1], serde_json::json!([-std::f64::consts::PI, std::f64::consts::PI]));
}

#[test]
fn verify_takes_a_path_through_configurations() {
    let r = json(&["verify", "arm.json", "--json"]);
    assert_eq!(r["trajectory"], "across the gap");
    assert_eq!(r["infeasible"].as_array().unwrap().len(), 1);
    let sampled = json(&["verify", "arm.json", "--trajectory", "across the gap", "--pointwise", "0.01", "--json"]);
    assert_eq!(sampled["method"], "pointwise");
    let text = cli(&["verify", "arm.json"]).unwrap();
    assert!(text.contains("boundary t = 0.445314004: cables 2-3 → infeasible") && !text.contains("τ"), "{text}");
    let all = json(&["verify", "arm.json", "--all", "--json"]);
    assert_eq!(all.as_array().unwrap().len(), 1);
}

#[test]
fn the_fig_3_12_lattice_has_two_components() {
    let l = json(&["lattice", "arm.json", "--pose", "fig312", "--axes", "alpha,beta", "--range", MINUS_QUARTER, QUARTER, MINUS_QUARTER, QUARTER, "--steps", "10", "--json"]);
    assert_eq!(l["axes"], serde_json::json!(["alpha", "beta"]));
    assert_eq!(l["components"], 2);
    assert_eq!(l["feasible_points"], 77);
    let ray = &l["rays"][0];
    assert_eq!(ray["vary"], "alpha");
    assert!(ray["fixed"]["gamma"].as_f64().is_some_and(|g| (g + std::f64::consts::PI / 12.0).abs() < 1e-15), "{ray}");
}

fn input_error(args: &[&str]) -> Error {
    match cli(args) {
        Err(CliError::Input(e)) => e,
        other => panic!("{args:?}: expected an input error, got {other:?}"),
    }
}

#[test]
fn unknown_coordinates_and_unsupported_commands_say_why() {
    let e = input_error(&["ray", "arm.json", "--pose", "fig312", "--vary", "x", "--range", "0", "1"]);
    assert_eq!(e.field, "--vary");
    assert!(e.reason.contains("alpha, beta, gamma, theta"), "{e}");
    let e = input_error(&["lattice", "arm.json", "--pose", "fig312", "--axes", "alpha,omega", "--range", "0", "1", "0", "1", "--steps", "3"]);
    assert_eq!(e.field, "--axes");
    let e = input_error(&["check", "arm.json", "--pose", "upright"]);
    assert_eq!(e.field, "pose");
    assert!(e.reason.contains("no configuration named \"upright\"") && e.reason.contains("fig312"), "{e}");
    let e = input_error(&["envelope", "arm.json"]);
    assert_eq!(e.field, "envelope");
    let e = input_error(&["plan", "arm.json", "--query", "up"]);
    assert_eq!(e.field, "plan");
    assert!(e.reason.contains("multi-link"), "{e}");
    let e = input_error(&["slice", "arm.json", "--pose", "fig312", "--axes", "phi,theta", "--res", "8"]);
    assert_eq!(e.field, "--axes");
    assert!(e.reason.contains("\"phi\" is not a coordinate of this robot"), "{e}");
}

/// A CASPR model `name` in directory `m` (its bodies and cables files), imported by the CLI to
/// `out` and worked on by `body` with the CLI over those files (`cli`) and the imported JSON
/// (which `body` may rewrite).
fn with_model(name: &str, bodies: &str, cables: &str, out: &str, body: impl FnOnce(&dyn Fn(&str) -> String, &std::cell::RefCell<String>)) {
    let imported = std::cell::RefCell::new(String::new());
    let (bodies_file, cables_file) = (format!("{name}_bodies.xml"), format!("{name}_cables.xml"));
    let read = |p: &str| match p.strip_prefix("m/") {
        Some(f) if f == bodies_file => Ok(bodies.to_string()),
        Some(f) if f == cables_file => Ok(cables.to_string()),
        _ if p == out => Ok(imported.borrow().clone()),
        _ => Err(Error::new(p, "no such file")),
    };
    let list = |p: &str| if p == "m" { Ok(vec![bodies_file.clone(), cables_file.clone()]) } else { Ok(vec![]) };
    let write = |_: &str, bytes: &[u8]| {
        *imported.borrow_mut() = String::from_utf8_lossy(bytes).into_owned();
        Ok(())
    };
    let cli = |args: &str| run(args.split(' '), &read, &write, &list, &mut |_| {}).unwrap_or_else(|e| panic!("{args}: {e}"));
    body(&cli, &imported);
}

/// An arm imported from CASPR with its links' masses: the summary says so, and `check` and
/// `verify` hold its weight as a condition of their own (static feasibility, with its margin).
#[test]
fn an_imported_arm_holds_its_weight() {
    let bodies = include_str!("../../../shared/models/caspr/BMArm/BMArm_bodies.xml");
    let cables = include_str!("../../../shared/models/caspr/BMArm/BMArm_cables.xml");
    with_model("BMArm", bodies, cables, "arm.json", |cli, imported| {
        let printed = cli("import m --out arm.json");
        assert!(printed.contains("wrote arm.json: BMArm (6 cables, links' mass 1.1123952 kg)"), "{printed}");
        let check: Value = serde_json::from_str(&cli("check arm.json --pose initial --json")).unwrap();
        let statics = check["checks"].as_array().unwrap().iter().find(|c| c["constraint"] == "static feasibility").unwrap_or_else(|| panic!("{check}"));
        assert!(statics["distance"].as_f64().is_some_and(|d| d > 0.0), "{statics}");
        // CASPR's initial configuration holds the arm; turning the lower arm on to θ = −0.95 loses
        // the hold once, the condition named at the boundary
        let mut v: Value = serde_json::from_str(&imported.borrow()).unwrap();
        v["configurations"]["bent"] = v["configurations"]["initial"].clone();
        v["configurations"]["bent"]["theta"] = serde_json::json!(-0.95);
        v["trajectories"] = serde_json::json!([{"name": "bend", "through": ["initial", "bent"]}]);
        *imported.borrow_mut() = v.to_string();
        let r: Value = serde_json::from_str(&cli("verify arm.json --trajectory bend --json")).unwrap();
        let boundaries = r["boundaries"].as_array().unwrap();
        assert_eq!(boundaries.len(), 1, "{r}");
        assert_eq!((boundaries[0]["constraint"].as_str(), boundaries[0]["enters"].as_str()), (Some("static feasibility"), Some("infeasible")), "{r}");
        let t = boundaries[0]["t"].as_f64().unwrap();
        assert!(t > 0.5 && t < 0.9 && r["uncertain"].as_array().unwrap().is_empty(), "{r}");
    });
}

/// A model with routed cables (CAREX: two of its six cables run over the upper arm to the
/// forearm) imports as format 6 with its closure left out, and a ray of its shoulder finds where
/// it holds its weight, the boundaries named.
#[test]
fn a_routed_arm_imports_and_holds_its_weight_in_a_band() {
    let bodies = include_str!("../../../shared/models/caspr/CAREX/CAREX_bodies.xml");
    let cables = include_str!("../../../shared/models/caspr/CAREX/CAREX_cables.xml");
    with_model("CAREX", bodies, cables, "carex.json", |cli, imported| {
        let printed = cli("import m --out carex.json");
        assert!(printed.contains("(6 cables, links' mass 5 kg)") && printed.contains("robot.closure false") && printed.contains("wider than one turn"), "{printed}");
        let v: Value = serde_json::from_str(&imported.borrow()).unwrap();
        assert_eq!(v["format"], "cablenav-scenario/6");
        assert_eq!(v["robot"]["cables"][0]["via"][0]["link"], "Upper Arm");
        let r: Value = serde_json::from_str(&cli("ray carex.json --pose initial --vary alpha --range -0.3 0.3 --json")).unwrap();
        let feasible = r["feasible"].as_array().unwrap();
        assert_eq!(feasible.len(), 1, "{r}");
        let [lo, hi] = [0, 1].map(|k| feasible[0][k].as_f64().unwrap());
        assert!(lo > 0.0 && lo < hi && hi < 0.1 && r["uncertain"].as_array().unwrap().is_empty(), "{r}");
        let named: Vec<&str> = r["boundaries"].as_array().unwrap().iter().map(|b| b["constraint"].as_str().unwrap()).collect();
        assert_eq!(named, ["static feasibility", "static feasibility"], "{r}");
    });
}
