//! The command line: JSON shapes, readable text, and one-line errors naming the option or field.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use cablenav::cli::run;
use cablenav::Error;

fn files(path: &str) -> cablenav::Result<String> {
    match path {
        "cdpr7.json" => Ok(include_str!("../static/scenarios/cdpr7.json").to_string()),
        "box.json" => Ok(include_str!("../static/scenarios/cdpr7-box.json").to_string()),
        "tree.json" => Ok(include_str!("../static/scenarios/cdpr7-tree.json").to_string()),
        "robocrane.json" => Ok(include_str!("../static/scenarios/robocrane.json").to_string()),
        "broken.json" => Ok("{\"format\": \"cablenav-scenario/1\", \"robot\": ".to_string()),
        other => Err(Error::new(other, "cannot read: no such file")),
    }
}

fn cli(args: &str) -> cablenav::Result<String> {
    let args: Vec<String> = args.split_whitespace().map(String::from).collect();
    run(&args, &files, &|_, _| Ok(()))
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
    let written = std::cell::RefCell::new(Vec::new());
    let args: Vec<String> = "slice robocrane.json --pose q1 --axes phi,theta --res 20 --png out.png".split(' ').map(String::from).collect();
    let text = run(&args, &files, &|path, bytes| {
        written.borrow_mut().push((path.to_string(), bytes.len()));
        Ok(())
    })
    .unwrap();
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

#[cfg(not(target_arch = "wasm32"))]
#[test]
fn binary_exits_non_zero_with_one_line_on_stderr() {
    use std::process::Command;
    let exe = env!("CARGO_BIN_EXE_cablenav");
    let out = Command::new(exe).args(["verify", "no/such/file.json"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("no/such/file.json"));
    let root = env!("CARGO_MANIFEST_DIR");
    let out = Command::new(exe).args(["verify", &format!("{root}/static/scenarios/cdpr7.json"), "--json"]).output().unwrap();
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["feasible"], serde_json::json!([[0.0, 1.0]]));
}
