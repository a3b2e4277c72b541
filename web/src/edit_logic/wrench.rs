//! Wrench edits: the ellipsoid as one radius, per-axis radii or a full matrix, a template, and a
//! wrench applied to a multi-link robot's link.

use serde_json::{json, Value};

use super::{get, number, remove, round12, set, Path};

/// How the wrench ellipsoid is edited: `radius` (one radius, E = I/r²), `radii` (one radius
/// per axis, E diagonal), `matrix` (the full 6×6 E) or `none` (format 4: the nominal wrench
/// alone, no ellipsoid around it).
pub fn ellipsoid_mode(doc: &Value) -> &'static str {
    let w = Path::of(&["wrench"]);
    if get(doc, &w.k("radius")).is_some() {
        return "radius";
    }
    if get(doc, &w.k("ellipsoid")).is_none() {
        return "none";
    }
    match ellipsoid_matrix(doc) {
        Some(e) if is_diagonal(&e) => "radii",
        _ => "matrix",
    }
}

fn ellipsoid_matrix(doc: &Value) -> Option<Vec<Vec<f64>>> {
    let rows = get(doc, &Path::of(&["wrench", "ellipsoid"]))?.as_array()?;
    rows.iter().map(|r| r.as_array()?.iter().map(Value::as_f64).collect()).collect()
}

fn is_diagonal(e: &[Vec<f64>]) -> bool {
    e.len() == 6 && e.iter().enumerate().all(|(i, r)| r.len() == 6 && r.iter().enumerate().all(|(j, x)| i == j || *x == 0.0))
}

/// The per-axis radii rᵢ = 1/√Eᵢᵢ of the ellipsoid (or of the ball), rounded to 12 digits;
/// `None` where the diagonal entry is not positive.
pub fn ellipsoid_radii(doc: &Value) -> [Option<f64>; 6] {
    let w = Path::of(&["wrench"]);
    if let Some(r) = get(doc, &w.k("radius")).and_then(Value::as_f64) {
        return [Some(r); 6];
    }
    let mut out = [None; 6];
    if let Some(e) = ellipsoid_matrix(doc) {
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = e.get(i).and_then(|r| r.get(i)).filter(|x| **x > 0.0).map(|x| round12(1.0 / x.sqrt()));
        }
    }
    out
}

/// Writes the ellipsoid as the diagonal E with Eᵢᵢ = 1/rᵢ² (replacing `radius`). A radius
/// that is not positive is written as Eᵢᵢ = 0 so that the core reports E not positive definite
/// at `wrench.ellipsoid`.
pub fn set_ellipsoid_radii(doc: &mut Value, radii: [f64; 6]) {
    let rows: Vec<Value> = (0..6)
        .map(|i| {
            Value::Array(
                (0..6)
                    .map(|j| {
                        let r = radii[i];
                        number(if i != j || r <= 0.0 { 0.0 } else { round12(1.0 / (r * r)) })
                    })
                    .collect(),
            )
        })
        .collect();
    remove(doc, &Path::of(&["wrench", "radius"]));
    set(doc, &Path::of(&["wrench", "ellipsoid"]), Value::Array(rows));
}

/// Switches the ellipsoid's editing mode, converting the current values: a ball becomes its
/// diagonal matrix; a matrix becomes one radius (the mean of the per-axis radii) only in
/// `radius` mode; `none` removes the ellipsoid (raising the file to format 4, which reads a
/// wrench section without one), and an ellipsoid comes back as radius 1.
pub fn set_ellipsoid_mode(doc: &mut Value, mode: &str) {
    let radii = ellipsoid_radii(doc).map(|r| r.unwrap_or(1.0));
    match mode {
        "none" => {
            remove(doc, &Path::of(&["wrench", "ellipsoid"]));
            remove(doc, &Path::of(&["wrench", "radius"]));
            super::timing::require_format(doc, super::timing::FORMAT_4);
        }
        "radius" => {
            let mean = round12(radii.iter().sum::<f64>() / 6.0);
            remove(doc, &Path::of(&["wrench", "ellipsoid"]));
            set(doc, &Path::of(&["wrench", "radius"]), number(mean));
        }
        "radii" => set_ellipsoid_radii(doc, radii),
        _ => {
            if get(doc, &Path::of(&["wrench", "ellipsoid"])).is_none() {
                set_ellipsoid_radii(doc, radii);
            }
        }
    }
}

/// A wrench section to start from: a nominal force of 1 N along −z at the platform origin, and
/// a ball of radius 0.1 around it.
pub fn wrench_template() -> Value {
    json!({"nominal": [0, 0, -1, 0, 0, 0], "radius": 0.1, "point": [0, 0, 0], "point_frame": "platform"})
}

/// Applies a wrench to a multi-link robot's last link to start from: a force of 1 N along −z at
/// its joint (format 4: raises the file's format).
pub fn add_link_wrench(doc: &mut Value) {
    let Some(last) = super::link_names(doc).pop() else { return };
    set(doc, &Path::of(&["wrench"]), json!({"nominal": [0, 0, -1, 0, 0, 0], "link": last, "point": [0, 0, 0]}));
    super::require_format(doc, super::FORMAT_4);
}

#[cfg(test)]
mod tests {
    
    
    use super::*;
    use cablenav::Scenario;
    use serde_json::{json, Value};

    #[test]
    fn a_wrench_applied_to_the_arm_s_last_link_is_read_by_the_core() {
        let mut d: Value = serde_json::from_str(crate::presets::PRESETS[crate::presets::find("bmarm-x4-2").unwrap()].json).unwrap();
        add_link_wrench(&mut d);
        assert_eq!((d["format"].as_str(), d["wrench"]["link"].as_str()), (Some(super::super::FORMAT_4), Some("Lower Arm")));
        let s = Scenario::from_json(&d.to_string()).unwrap();
        let load = s.robot.chain.as_ref().unwrap().load.clone().unwrap();
        assert_eq!((load.link, load.nominal[2]), (1, -1.0));
        assert!(cablenav::conditions::for_scenario(&s).iter().any(|c| c.label() == "static feasibility"));
    }

    #[test]
    fn wrench_ellipsoid_modes() {
        let mut d: Value = serde_json::from_str(crate::presets::PRESETS[crate::presets::find("robocrane").unwrap()].json).unwrap();
        assert_eq!(ellipsoid_mode(&d), "radius");
        assert_eq!(ellipsoid_radii(&d), [Some(0.01); 6]);
        set_ellipsoid_mode(&mut d, "radii");
        assert_eq!(ellipsoid_mode(&d), "radii");
        assert_eq!(d["wrench"]["ellipsoid"][2][2], json!(10000));
        set_ellipsoid_radii(&mut d, [1.0, 2.0, 0.5, 1.0, 1.0, 4.0]);
        assert_eq!(ellipsoid_radii(&d), [Some(1.0), Some(2.0), Some(0.5), Some(1.0), Some(1.0), Some(4.0)]);
        let s = Scenario::from_json(&d.to_string()).unwrap();
        assert!((s.wrench.unwrap().ellipsoid[(1, 1)] - 0.25).abs() < 1e-15);
        // a zero radius is not SPD: the core says so at wrench.ellipsoid
        set_ellipsoid_radii(&mut d, [1.0, 0.0, 1.0, 1.0, 1.0, 1.0]);
        let e = Scenario::from_json(&d.to_string()).unwrap_err();
        assert_eq!(e.field, "wrench.ellipsoid");
        // an off-diagonal entry makes it a matrix
        set_ellipsoid_radii(&mut d, [1.0; 6]);
        d["wrench"]["ellipsoid"][0][1] = json!(0.5);
        d["wrench"]["ellipsoid"][1][0] = json!(0.5);
        assert_eq!(ellipsoid_mode(&d), "matrix");
        set_ellipsoid_mode(&mut d, "radius");
        assert_eq!(d["wrench"]["radius"], json!(1));
        assert!(d["wrench"].get("ellipsoid").is_none());
        // the nominal wrench alone: no ellipsoid, format 4, read by the core as a single wrench
        set_ellipsoid_mode(&mut d, "none");
        assert_eq!(ellipsoid_mode(&d), "none");
        assert_eq!(d["format"], json!(crate::edit_logic::timing::FORMAT_4));
        assert!(Scenario::from_json(&d.to_string()).unwrap().wrench.unwrap().is_single());
        set_ellipsoid_mode(&mut d, "radius");
        assert_eq!(d["wrench"]["radius"], json!(1));
        d["wrench"] = wrench_template();
        Scenario::from_json(&d.to_string()).unwrap();
    }
}
