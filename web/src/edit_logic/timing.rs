//! Time and mass edits (scenario format 4, docs/dynamics.md): the platform's dynamics, the
//! winches' limits and trajectories' durations. A value written here raises the file's `format`
//! to `cablenav-scenario/4` where it was older, so that the core reads it.

use serde_json::{json, Value};

use super::{get, number, remove, set, Path};

/// The format a file needs for the fields of this module.
pub const FORMAT_4: &str = cablenav::scenario::FORMAT_4;

/// Raises the file's format to `format` (files of the older versions read the same).
pub fn require_format(doc: &mut Value, format: &str) {
    let version = cablenav::scenario::json::version;
    let older = doc.get("format").and_then(Value::as_str).and_then(version).zip(version(format)).is_some_and(|(v, least)| v < least);
    if older {
        set(doc, &Path::of(&["format"]), json!(format));
    }
}

/// Writes a format-4 number at `path` (`None`: removes it), raising the format when writing.
pub fn set_timed_number(doc: &mut Value, path: &Path, value: Option<f64>) {
    match value {
        Some(x) => {
            set(doc, path, number(x));
            require_format(doc, FORMAT_4);
        }
        None => {
            remove(doc, path);
        }
    }
}

/// Whether the robot has `robot.dynamics`.
pub fn has_dynamics(doc: &Value) -> bool {
    get(doc, &Path::of(&["robot", "dynamics"])).is_some()
}

/// Gives the platform a mass to start from: 1 kg, its centre of mass at the origin, the inertia
/// of a 1 kg cube 0.5 m wide (m·a²/6 on the diagonal), gravity down the world's z axis.
pub fn add_dynamics(doc: &mut Value) {
    let i = 0.5 * 0.5 / 6.0;
    set(
        doc,
        &Path::of(&["robot", "dynamics"]),
        json!({"mass": 1.0, "com": [0.0, 0.0, 0.0], "inertia": [[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]], "gravity": cablenav::scenario::STANDARD_GRAVITY}),
    );
    require_format(doc, FORMAT_4);
}

/// Removes the platform's mass (the robot is massless again: every load in the wrench set).
pub fn remove_dynamics(doc: &mut Value) {
    remove(doc, &Path::of(&["robot", "dynamics"]));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn timed_fields_raise_the_format_and_the_core_reads_them() {
        let mut doc = super::super::test_doc();
        assert_eq!(doc["format"], "cablenav-scenario/1");
        let duration = Path::of(&["trajectories"]).i(0).k("duration");
        set_timed_number(&mut doc, &duration, Some(2.5));
        assert_eq!(doc["format"], FORMAT_4);
        add_dynamics(&mut doc);
        set_timed_number(&mut doc, &Path::of(&["robot", "winch", "speed"]), Some(1.5));
        let s = cablenav::Scenario::from_json(&doc.to_string()).unwrap();
        assert_eq!(s.trajectories[0].duration, Some(2.5));
        assert_eq!(s.robot.dynamics.as_ref().map(|d| d.mass), Some(1.0));
        assert_eq!(s.robot.winch.speed, Some(1.5));
        let r = cablenav::verify::verify_trajectory(&s, &s.trajectories[0]).unwrap();
        assert_eq!(r.seconds.unwrap().duration, 2.5);
        // emptying a field removes it; a format already 4 stays
        set_timed_number(&mut doc, &duration, None);
        remove_dynamics(&mut doc);
        assert!(doc["trajectories"][0].get("duration").is_none() && !has_dynamics(&doc));
        assert_eq!(doc["format"], FORMAT_4);
        // a multi-link file (format 3) is raised too; the core then says what it does not take
        let mut arm: Value = serde_json::from_str(crate::presets::PRESETS[crate::presets::find("bmarm-x4-2").unwrap()].json).unwrap();
        add_dynamics(&mut arm);
        let e = cablenav::Scenario::from_json(&arm.to_string()).unwrap_err();
        assert_eq!(e.field, "robot.dynamics");
    }
}
